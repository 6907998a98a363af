// Bindings for native/src/tbp (and the .tbp format of native/src/io): TBP
// solids from and to numpy arrays and .tbp text, polygonization, hierarchies,
// point-in-solid, solid/solid intersection, trimming, solids from meshes.
// Containment crosses as int8 codes (TBP_OUTSIDE, TBP_INSIDE, TBP_BOUNDARY),
// Keep as the strings "outside" | "inside". Long work releases the GIL.
#include <pybind11/stl.h>

#include <cstdint>

#include "io/tbp_format.h"
#include "numpy_convert.h"
#include "tbp/from_mesh.h"
#include "tbp/intersect_patches.h"
#include "tbp/point_in_solid.h"
#include "tbp/polygonize.h"
#include "tbp/tbp_hierarchy.h"
#include "tbp/trim_patch.h"

// Hierarchies stay in C++ (they are large); Python holds them as one object.
PYBIND11_MAKE_OPAQUE(std::vector<trimkit::tbp::TbpHierarchy>)

namespace trimkit::bindings {

namespace {

using Hierarchies = std::vector<tbp::TbpHierarchy>;

// TbpSolid from a (p, (n+1)(n+2)/2, 3) array of control points (storage order of
// geom/bezier_triangle.h) and the degree n; validated (ValueError).
tbp::TbpSolid make_solid(const DoubleArray& points, int degree, const std::string& name) {
    if (degree < 1 || degree > geom::kMaxBezierTriangleDegree)
        throw py::value_error("TbpSolid: degree " + std::to_string(degree) + " is outside [1, " +
                              std::to_string(geom::kMaxBezierTriangleDegree) + "]");
    const auto groups = groups_from_numpy(points, geom::BezierTriangle::point_count(degree), "TbpSolid: points");
    tbp::TbpSolid solid;
    solid.name = name;
    for (const auto& g : groups) solid.patches.emplace_back(degree, g);
    tbp::validate(solid);
    return solid;
}

py::array_t<double> solid_points(const tbp::TbpSolid& s) {
    std::vector<std::vector<Eigen::Vector3d>> groups;
    for (const auto& p : s.patches) groups.push_back(p.points());
    return groups_to_numpy(groups, geom::BezierTriangle::point_count(std::max(1, s.degree())));
}

std::string keep_name(tbp::Keep keep) { return keep == tbp::Keep::kOutside ? "outside" : "inside"; }

tbp::Keep keep_from_name(const std::string& name) {
    if (name == "outside") return tbp::Keep::kOutside;
    if (name == "inside") return tbp::Keep::kInside;
    throw py::value_error("TrimOptions: keep = '" + name + "'; expected 'outside' or 'inside'");
}

// (n, 3) points -> (n,) int8 Containment codes.
py::array_t<std::int8_t> classify_points(const Hierarchies& solid, const DoubleArray& points) {
    const py::ssize_t n = expect_columns(points, 3, "point_in_solid(points)");
    py::array_t<std::int8_t> out(n);
    auto in = points.unchecked<2>();
    auto view = out.mutable_unchecked<1>();
    {
        py::gil_scoped_release release;
        for (py::ssize_t i = 0; i < n; ++i)
            view(i) = static_cast<std::int8_t>(tbp::point_in_solid(solid, Eigen::Vector3d(in(i, 0), in(i, 1), in(i, 2))));
    }
    return out;
}

// (mesh, [TrimResult per target patch]).
py::tuple trim_solid_parts(const tbp::TbpSolid& target, const tbp::TbpSolid& tool, const tbp::TrimOptions& options) {
    std::vector<tbp::TrimResult> parts;
    mesh::Mesh m;
    {
        py::gil_scoped_release release;
        m = tbp::trim_solid(target, tool, options, &parts);
    }
    return py::make_tuple(std::move(m), std::move(parts));
}

template <typename Points, typename Get>
py::array_t<double> point_rows(const Points& points, Get get) {
    std::vector<Eigen::Vector3d> rows;
    rows.reserve(points.size());
    for (const auto& p : points) rows.push_back(get(p));
    return rows_to_numpy<double, 3>(rows);
}

}  // namespace

void bind_tbp(py::module_& m) {
    m.attr("TBP_OUTSIDE") = static_cast<int>(tbp::Containment::kOutside);
    m.attr("TBP_INSIDE") = static_cast<int>(tbp::Containment::kInside);
    m.attr("TBP_BOUNDARY") = static_cast<int>(tbp::Containment::kBoundary);
    m.attr("TBP_WELD_RELATIVE_TOLERANCE") = tbp::kWeldRelativeTolerance;
    m.attr("TBP_MAX_POLYGONIZE_RATE") = tbp::kMaxPolygonizeRate;

    py::class_<tbp::TbpSolid>(m, "TbpSolid",
                              "A solid bounded by triangular Bezier patches of one degree, normals pointing out.")
        .def(py::init(&make_solid), py::arg("points"), py::arg("degree"), py::arg("name") = std::string(),
             "From a (p, (n+1)(n+2)/2, 3) array of control points b_ijk (i from n down to 0, within it "
             "j from n-i down to 0) and the degree n; ValueError for a wrong shape, degree or a NaN.")
        .def_readwrite("name", &tbp::TbpSolid::name)
        .def_property_readonly("degree", &tbp::TbpSolid::degree)
        .def_property_readonly("patch_count", [](const tbp::TbpSolid& s) { return s.patches.size(); })
        .def("__len__", [](const tbp::TbpSolid& s) { return s.patches.size(); })
        .def_property_readonly("points", &solid_points, "(p, (n+1)(n+2)/2, 3) float64 control points");

    m.def("read_tbp", &io::read_tbp, py::arg("path"), py::call_guard<py::gil_scoped_release>(),
          "Read a .tbp file; ReadError 'FILE:LINE: reason' for a bad one.");
    m.def("parse_tbp", &io::parse_tbp, py::arg("text"), py::arg("file"), py::call_guard<py::gil_scoped_release>(),
          "A TbpSolid from .tbp text (e.g. stored in a .blend); `file` names it in errors.");
    m.def("tbp_text", &io::tbp_text, py::arg("solid"), py::call_guard<py::gil_scoped_release>(),
          "The .tbp text of a solid (numbers round-trip exactly).");
    m.def("write_tbp", &io::write_tbp, py::arg("solid"), py::arg("path"), py::call_guard<py::gil_scoped_release>(),
          "Write a solid as a .tbp file.");

    const tbp::PolygonizeOptions poly;
    py::class_<tbp::PolygonizeOptions>(m, "PolygonizeOptions",
                                       "Hierarchy level L and lod K: (K+1)^L segments per patch edge.")
        .def(py::init([](int level, int lod, bool weld, bool keep_split_normals) {
                 tbp::PolygonizeOptions o;
                 o.level = level;
                 o.lod = lod;
                 o.weld = weld;
                 o.keep_split_normals = keep_split_normals;
                 return o;
             }),
             py::arg("level") = poly.level, py::arg("lod") = poly.lod, py::arg("weld") = poly.weld,
             py::arg("keep_split_normals") = poly.keep_split_normals)
        .def_readwrite("level", &tbp::PolygonizeOptions::level)
        .def_readwrite("lod", &tbp::PolygonizeOptions::lod)
        .def_readwrite("weld", &tbp::PolygonizeOptions::weld)
        .def_readwrite("keep_split_normals", &tbp::PolygonizeOptions::keep_split_normals);
    m.def("polygonize_rate", &tbp::polygonize_rate, py::arg("level"), py::arg("lod"),
          "(lod+1)^level; ValueError for negative values or a rate above TBP_MAX_POLYGONIZE_RATE.");
    m.def("polygonize", &tbp::polygonize, py::arg("solid"), py::arg("options") = tbp::PolygonizeOptions{},
          py::call_guard<py::gil_scoped_release>(),
          "Mesh of every patch at the same rate (face id = patch index), exact normals, uvs = (u, v); "
          "welded unless options.weld is False.");

    py::class_<Hierarchies>(m, "TbpHierarchies", "The LOD hierarchies of a solid's patches (held in C++).")
        .def("__len__", [](const Hierarchies& h) { return h.size(); })
        .def_property_readonly("levels", [](const Hierarchies& h) { return h.empty() ? 0 : h[0].levels(); })
        .def_property_readonly("lod", [](const Hierarchies& h) { return h.empty() ? 0 : h[0].lod(); })
        .def_property_readonly("leaves_per_patch",
                               [](const Hierarchies& h) { return h.empty() ? std::size_t{0} : h[0].leaves().size(); });
    m.def("build_hierarchies", &tbp::build_hierarchies, py::arg("solid"), py::arg("levels"), py::arg("lod"),
          py::call_guard<py::gil_scoped_release>(),
          "One hierarchy per patch: `levels` levels, each node split into (lod+1)^2 subpatches.");

    m.def("point_in_solid", &classify_points, py::arg("hierarchies"), py::arg("points"),
          "(n,) int8 codes TBP_OUTSIDE / TBP_INSIDE / TBP_BOUNDARY for (n, 3) points against a closed "
          "solid's hierarchies (its leaf-level polyhedron; exact for flat patches).");

    py::class_<tbp::IntersectionStats>(m, "IntersectionStats")
        .def_readonly("box_tests", &tbp::IntersectionStats::box_tests)
        .def_readonly("triangle_tests", &tbp::IntersectionStats::triangle_tests)
        .def_readonly("segments", &tbp::IntersectionStats::segments);
    py::class_<tbp::IntersectionComponent>(m, "IntersectionComponent")
        .def_readonly("closed", &tbp::IntersectionComponent::closed)
        .def_property_readonly("points", [](const tbp::IntersectionComponent& c) {
            return point_rows(c.points, [](const tbp::IntersectionPoint& p) { return p.position; });
        }, "(k, 3) float64 positions (a closed component's last point joins the first)")
        .def_property_readonly("uvw_a", [](const tbp::IntersectionComponent& c) {
            return point_rows(c.points, [](const tbp::IntersectionPoint& p) { return p.uvw_a; });
        }, "(k, 3) float64 parameters on the first patch")
        .def_property_readonly("uvw_b", [](const tbp::IntersectionComponent& c) {
            return point_rows(c.points, [](const tbp::IntersectionPoint& p) { return p.uvw_b; });
        }, "(k, 3) float64 parameters on the second patch");
    py::class_<tbp::PatchIntersection>(m, "PatchIntersection")
        .def_readonly("components", &tbp::PatchIntersection::components)
        .def_property_readonly("junctions",
                               [](const tbp::PatchIntersection& r) { return rows_to_numpy<double, 3>(r.junctions); },
                               "(j, 3) float64 points where three or more branches meet")
        .def_property_readonly("segment_count", [](const tbp::PatchIntersection& r) { return r.segments.size(); })
        .def_readonly("stats", &tbp::PatchIntersection::stats);
    m.def("intersect_solids", &tbp::intersect_solids, py::arg("a"), py::arg("b"), py::arg("use_hierarchy") = true,
          py::call_guard<py::gil_scoped_release>(),
          "Intersection curves of two solids' hierarchies as components (closed/open, Y junctions), with "
          "box and triangle test counts; use_hierarchy=False tests every leaf pair.");

    const tbp::TrimOptions trim;
    py::class_<tbp::TrimOptions>(m, "TrimOptions", "Hierarchy levels/lod of target and tool; keep 'outside' or 'inside'.")
        .def(py::init([](int levels, int lod, const std::string& keep) {
                 tbp::TrimOptions o;
                 o.levels = levels;
                 o.lod = lod;
                 o.keep = keep_from_name(keep);
                 return o;
             }),
             py::arg("levels") = trim.levels, py::arg("lod") = trim.lod, py::arg("keep") = keep_name(trim.keep))
        .def_readwrite("levels", &tbp::TrimOptions::levels)
        .def_readwrite("lod", &tbp::TrimOptions::lod)
        .def_property(
            "keep", [](const tbp::TrimOptions& o) { return keep_name(o.keep); },
            [](tbp::TrimOptions& o, const std::string& s) { o.keep = keep_from_name(s); });
    py::class_<tbp::PointInSolidStats>(m, "PointInSolidStats")
        .def_readonly("box_tests", &tbp::PointInSolidStats::box_tests)
        .def_readonly("triangle_tests", &tbp::PointInSolidStats::triangle_tests)
        .def_readonly("rejected_rays", &tbp::PointInSolidStats::rejected_rays);
    py::class_<tbp::TrimStats>(m, "TrimStats")
        .def_readonly("intersection", &tbp::TrimStats::intersection)
        .def_readonly("inclusion", &tbp::TrimStats::inclusion)
        .def_readonly("cut_leaves", &tbp::TrimStats::cut_leaves)
        .def_readonly("pieces", &tbp::TrimStats::pieces)
        .def_readonly("kept_leaves", &tbp::TrimStats::kept_leaves)
        .def_readonly("deleted_leaves", &tbp::TrimStats::deleted_leaves)
        .def_readonly("boundary_segments", &tbp::TrimStats::boundary_segments)
        .def_readonly("seconds", &tbp::TrimStats::seconds);
    py::class_<tbp::TrimBoundary>(m, "TrimBoundary", "A loop counter-clockwise around the kept region.")
        .def_property_readonly("uvw", [](const tbp::TrimBoundary& b) { return rows_to_numpy<double, 3>(b.uvw); },
                               "(k, 3) float64 root-domain parameters")
        .def_property_readonly("points", [](const tbp::TrimBoundary& b) { return rows_to_numpy<double, 3>(b.points); },
                               "(k, 3) float64 points on the patch")
        .def_property_readonly("on_cut", [](const tbp::TrimBoundary& b) { return to_numpy_1d<std::uint8_t>(b.on_cut); },
                               "(k,) uint8 per edge k -> k+1: 1 on a trimming curve, 0 on the patch's own boundary");
    py::class_<tbp::SubTbp>(m, "SubTbp", "An untrimmed hierarchy node of the result.")
        .def_readonly("level", &tbp::SubTbp::level)
        .def_readonly("index", &tbp::SubTbp::index)
        .def_property_readonly("domain", [](const tbp::SubTbp& s) { return rows_to_numpy<double, 3>(s.domain); },
                               "(3, 3) float64 barycentric corners in the root domain")
        .def_property_readonly("points", [](const tbp::SubTbp& s) { return to_numpy<3>(s.patch.points()); },
                               "(k, 3) float64 control points of the sub-TBP");
    py::class_<tbp::TrimResult>(m, "TrimResult")
        .def_readonly("mesh", &tbp::TrimResult::mesh)
        .def_readonly("boundaries", &tbp::TrimResult::boundaries)
        .def_readonly("untrimmed", &tbp::TrimResult::untrimmed)
        .def_readonly("curves", &tbp::TrimResult::curves)
        .def_readonly("stats", &tbp::TrimResult::stats);
    m.def("trim_solid", &trim_solid_parts, py::arg("target"), py::arg("tool"),
          py::arg("options") = tbp::TrimOptions{},
          "Every patch of `target` trimmed against the closed solid `tool`: (welded Mesh with face id = "
          "patch index, [TrimResult per patch]).");

    m.def("pn_triangles", &tbp::pn_triangles, py::arg("mesh"), py::arg("sharp_angle") = tbp::kNoSharpEdges,
          py::arg("sharp_edges") = tbp::VertexPairs{}, py::call_guard<py::gil_scoped_release>(),
          "Cubic PN-triangle solid of a closed triangle mesh (welded first); sides whose triangles meet at more "
          "than sharp_angle (radians), and sides whose vertices are a pair of sharp_edges ([(a, b)] indices "
          "into the mesh's positions: edges marked sharp), stay creases; ValueError for an invalid mesh or "
          "a sharp_edges index outside it.");
    py::class_<tbp::LoopConversion>(m, "LoopConversion")
        .def_readonly("solid", &tbp::LoopConversion::solid)
        .def_readonly("approximated", &tbp::LoopConversion::approximated)
        .def_readonly("max_error", &tbp::LoopConversion::max_error);
    m.def("loop_quartics", &tbp::loop_quartics, py::arg("cage"), py::call_guard<py::gil_scoped_release>(),
          "Quartic TBP solid of a closed cage's Loop limit surface (irregular patches approximated, error reported).");
}

}  // namespace trimkit::bindings
