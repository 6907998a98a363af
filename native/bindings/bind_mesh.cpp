// Bindings for native/src/mesh: the output Mesh as numpy arrays (copies), and a
// Mesh built from arrays (validated) so Python can merge meshes before writing.
#include <optional>

#include <pybind11/stl.h>

#include "mesh/edge_map.h"
#include "mesh/mesh.h"
#include "mesh/weld_vertices.h"
#include "numpy_convert.h"

namespace trimkit::bindings {

namespace {

using UInt8Array = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>;
using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

// Mesh from arrays; optional arrays may be None. Throws ValueError for wrong
// shapes and for any violation of mesh::validate.
mesh::Mesh mesh_from_arrays(const DoubleArray& positions, const IntArray& triangles,
                            const std::optional<DoubleArray>& normals, const std::optional<DoubleArray>& uvs,
                            const std::optional<IntArray>& face_ids, const std::optional<IntArray>& edges,
                            const std::optional<UInt8Array>& edge_flags,
                            const std::optional<FloatArray>& face_colors) {
    mesh::Mesh m;
    rows_from_numpy(positions, 3, -1, "Mesh: positions", m.positions);
    const py::ssize_t V = positions.shape(0);
    rows_from_numpy(triangles, 3, -1, "Mesh: triangles", m.triangles);
    const py::ssize_t T = triangles.shape(0);
    if (normals) rows_from_numpy(*normals, 3, V, "Mesh: normals", m.normals);
    if (uvs) rows_from_numpy(*uvs, 2, V, "Mesh: uvs", m.uvs);
    if (face_ids) values_from_numpy(*face_ids, T, "Mesh: face_ids", m.face_ids);
    if (face_colors) rows_from_numpy(*face_colors, 3, -1, "Mesh: face_colors", m.face_colors);
    if (edges.has_value() != edge_flags.has_value())
        throw py::value_error("Mesh: edges and edge_flags go together");
    if (edges) {
        std::vector<std::array<std::int32_t, 2>> pairs;
        std::vector<std::uint8_t> flags;
        rows_from_numpy(*edges, 2, -1, "Mesh: edges", pairs);
        values_from_numpy(*edge_flags, edges->shape(0), "Mesh: edge_flags", flags);
        for (size_t k = 0; k < pairs.size(); ++k) m.edges.push_back({pairs[k][0], pairs[k][1], flags[k]});
    }
    mesh::validate(m);
    return m;
}

py::array_t<std::int32_t> edge_pairs(const mesh::Mesh& m) {
    std::vector<std::array<std::int32_t, 2>> pairs(m.edges.size());
    for (size_t k = 0; k < m.edges.size(); ++k) pairs[k] = {m.edges[k].v0, m.edges[k].v1};
    return rows_to_numpy<std::int32_t, 2>(pairs);
}

py::array_t<std::uint8_t> edge_flags(const mesh::Mesh& m) {
    std::vector<std::uint8_t> flags(m.edges.size());
    for (size_t k = 0; k < m.edges.size(); ++k) flags[k] = m.edges[k].flags;
    return to_numpy_1d<std::uint8_t>(flags);
}

// (edges (k, 2) uint32, corner_edges (3m,) uint32) for Blender's edge and loop arrays.
py::tuple edge_map_arrays(const IntArray& triangles, std::size_t vertex_count) {
    std::vector<std::array<std::int32_t, 3>> tris;
    rows_from_numpy(triangles, 3, -1, "edge_map: triangles", tris);
    mesh::EdgeMap map;
    {
        py::gil_scoped_release release;
        map = mesh::edge_map(tris, vertex_count);
    }
    return py::make_tuple(rows_to_numpy<std::uint32_t, 2>(map.edges), to_numpy_1d<std::uint32_t>(map.corner_edges));
}

}  // namespace

void bind_mesh(py::module_& m) {
    m.attr("EDGE_FACE_BOUNDARY") = static_cast<int>(mesh::kFaceBoundary);
    m.attr("EDGE_SHARP") = static_cast<int>(mesh::kSharp);

    py::class_<mesh::Mesh>(m, "Mesh",
                           "Triangle mesh as bulk arrays; every array property returns a numpy copy.")
        .def(py::init(&mesh_from_arrays), py::arg("positions"), py::arg("triangles"),
             py::arg("normals") = py::none(), py::arg("uvs") = py::none(), py::arg("face_ids") = py::none(),
             py::arg("edges") = py::none(), py::arg("edge_flags") = py::none(),
             py::arg("face_colors") = py::none(),
             "Mesh from (n,3) positions, (m,3) triangles and optional (n,3) normals, (n,2) uvs, "
             "(m,) face ids, (k,2) edges with (k,) flags, (c,3) face colours; validated.")
        .def_property_readonly("positions", [](const mesh::Mesh& s) { return rows_to_numpy<double, 3>(s.positions); },
                               "(n, 3) float64")
        .def_property_readonly("normals", [](const mesh::Mesh& s) { return rows_to_numpy<double, 3>(s.normals); },
                               "(n, 3) float64 unit normals from the exact surface, or (0, 3)")
        .def_property_readonly("uvs", [](const mesh::Mesh& s) { return rows_to_numpy<double, 2>(s.uvs); },
                               "(n, 2) float64 surface parameters, or (0, 2)")
        .def_property_readonly("triangles",
                               [](const mesh::Mesh& s) { return rows_to_numpy<std::int32_t, 3>(s.triangles); },
                               "(m, 3) int32, counter-clockwise seen from the normal side")
        .def_property_readonly("face_ids", [](const mesh::Mesh& s) { return to_numpy_1d<std::int32_t>(s.face_ids); },
                               "(m,) int32 CAD face (Model.faces index) per triangle, or (0,)")
        .def_property_readonly("edges", &edge_pairs, "(k, 2) int32 flagged edges (unordered pairs)")
        .def_property_readonly("edge_flags", &edge_flags,
                               "(k,) uint8 bits: EDGE_FACE_BOUNDARY, EDGE_SHARP")
        .def_property_readonly("face_colors",
                               [](const mesh::Mesh& s) { return rows_to_numpy<float, 3>(s.face_colors); },
                               "(c, 3) float32 rgb per face id, or (0, 3)")
        .def_property_readonly("vertex_count", &mesh::Mesh::vertex_count)
        .def_property_readonly("triangle_count", &mesh::Mesh::triangle_count);

    m.def("edge_map", &edge_map_arrays, py::arg("triangles"), py::arg("vertex_count"),
          "(edges, corner_edges): every undirected edge once as (k, 2) uint32 (smaller, larger), in "
          "order of first use, and for each triangle corner the edge to the next corner, (3m,) uint32.");
    m.def("surface_area", &mesh::surface_area, py::arg("mesh"), "Sum of the triangles' areas.");

    const mesh::WeldOptions weld;
    py::class_<mesh::WeldOptions>(m, "WeldOptions", "How weld_map merges vertices (tolerance in model units).")
        .def(py::init([](double tolerance, bool keep_split_normals, bool keep_split_uvs) {
                 mesh::WeldOptions o;
                 o.tolerance = tolerance;
                 o.keep_split_normals = keep_split_normals;
                 o.keep_split_uvs = keep_split_uvs;
                 return o;
             }),
             py::arg("tolerance") = weld.tolerance, py::arg("keep_split_normals") = weld.keep_split_normals,
             py::arg("keep_split_uvs") = weld.keep_split_uvs)
        .def_readwrite("tolerance", &mesh::WeldOptions::tolerance)
        .def_readwrite("keep_split_normals", &mesh::WeldOptions::keep_split_normals)
        .def_readwrite("keep_split_uvs", &mesh::WeldOptions::keep_split_uvs);
    py::class_<mesh::WeldResult>(m, "WeldResult")
        .def_property_readonly("vertex_map",
                               [](const mesh::WeldResult& r) { return to_numpy_1d<std::int32_t>(r.vertex_map); },
                               "(n,) int32 welded index of every input vertex")
        .def_readonly("vertex_count", &mesh::WeldResult::vertex_count);
    m.def("weld_map", &mesh::weld_map, py::arg("mesh"), py::arg("options"),
          py::call_guard<py::gil_scoped_release>(),
          "The welded index of every vertex, without changing the mesh (keep per-corner attributes "
          "by mapping only the corners' vertices). Welded vertices are numbered in order of their "
          "first input vertex.");
}

}  // namespace trimkit::bindings
