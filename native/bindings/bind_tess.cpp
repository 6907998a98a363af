// Bindings for native/src/tess: options, tessellate_model (GIL released) and its
// result. Enumerations cross as strings: mode "guaranteed" | "approximate",
// trim_method "bezier3d" | "yang" | "param".
#include <memory>

#include <pybind11/stl.h>

#include "geom/error.h"
#include "geom/select_faces.h"
#include "tess/corner_attributes.h"
#include "tess/measure_deviation.h"
#include "tess/tessellate_model.h"
#include "cancel_flag.h"
#include "numpy_convert.h"

namespace trimkit::bindings {

namespace {

std::string mode_name(tess::ErrorMode mode) {
    return mode == tess::ErrorMode::kGuaranteed ? "guaranteed" : "approximate";
}

tess::ErrorMode mode_from_name(const std::string& name) {
    if (name == "guaranteed") return tess::ErrorMode::kGuaranteed;
    if (name == "approximate") return tess::ErrorMode::kApproximate;
    throw py::value_error("TessellationOptions: mode = '" + name + "'; expected 'guaranteed' or 'approximate'");
}

std::string method_name(tess::TrimMethod method) {
    switch (method) {
        case tess::TrimMethod::kBezier3d: return "bezier3d";
        case tess::TrimMethod::kYang: return "yang";
        case tess::TrimMethod::kParam: return "param";
    }
    return "bezier3d";
}

tess::TrimMethod method_from_name(const std::string& name) {
    if (name == "bezier3d") return tess::TrimMethod::kBezier3d;
    if (name == "yang") return tess::TrimMethod::kYang;
    if (name == "param") return tess::TrimMethod::kParam;
    throw py::value_error("TessellationOptions: trim_method = '" + name + "'; expected 'bezier3d', 'yang' or 'param'");
}

tess::TessellationOptions make_options(double tolerance, double angle, const std::string& mode,
                                       const std::string& trim_method, int threads, double face_timeout,
                                       bool area_per_body) {
    tess::TessellationOptions options;
    options.tolerance = tolerance;
    options.angle = angle;
    options.mode = mode_from_name(mode);
    options.trim_method = method_from_name(trim_method);
    options.threads = threads;
    options.face_timeout = face_timeout;
    options.area_per_body = area_per_body;
    return options;
}

// A Python callable (or None) as TessellationOptions::progress. Copies share the
// callable (no GIL needed to copy them in worker threads); each call takes the GIL;
// an exception from the callable is printed as unraisable and the tessellation goes on.
std::function<void(double)> progress_function(const py::object& callable) {
    if (callable.is_none()) return {};
    const auto held = std::make_shared<py::object>(callable);
    return [held](double fraction) {
        py::gil_scoped_acquire gil;
        try {
            (*held)(fraction);
        } catch (py::error_already_set& e) {
            e.discard_as_unraisable("trimkit tessellation progress callback");
        }
    };
}

// measure_deviation over `faces` of the model only (all when empty): the mesh's face
// ids name model faces and are renumbered into the selection.
tess::DeviationReport deviation_of_faces(const geom::Model& model, const mesh::Mesh& mesh,
                                         const std::vector<int>& faces, int samples) {
    tess::DeviationOptions options;
    options.samples = samples;
    if (faces.empty()) return tess::measure_deviation(model, mesh, options);
    const geom::Model part = geom::select_faces(model, faces);
    std::vector<int> position(model.faces.size(), -1);
    for (std::size_t k = 0; k < faces.size(); ++k) position[faces[k]] = static_cast<int>(k);
    mesh::Mesh renumbered = mesh;
    for (auto& id : renumbered.face_ids) {
        if (id < 0 || id >= static_cast<int>(position.size()) || position[id] < 0)
            throw geom::InvalidInput("measure_deviation: the mesh has face id " + std::to_string(id) +
                                     ", which is not among the faces measured");
        id = position[id];
    }
    return tess::measure_deviation(part, renumbered, options);
}

// (m, 3, 2) corner uvs and (m, 3, 3) corner normals.
py::tuple corner_attributes(const geom::Model& model, const mesh::Mesh& mesh) {
    tess::CornerAttributes corners;
    {
        py::gil_scoped_release release;
        corners = tess::corner_attributes(model, mesh);
    }
    const auto T = static_cast<py::ssize_t>(mesh.triangle_count());
    return py::make_tuple(rows_to_numpy<double, 2>(corners.uvs).reshape({T, py::ssize_t{3}, py::ssize_t{2}}),
                          rows_to_numpy<double, 3>(corners.normals).reshape({T, py::ssize_t{3}, py::ssize_t{3}}));
}

}  // namespace

void bind_tess(py::module_& m) {
    const tess::TessellationOptions defaults;
    py::class_<tess::TessellationOptions>(m, "TessellationOptions",
                                          "What the tessellator is asked for; tolerance in model units, "
                                          "angle in radians. Checked by tessellate_model (ValueError).")
        .def(py::init(&make_options), py::arg("tolerance") = defaults.tolerance,
             py::arg("angle") = defaults.angle, py::arg("mode") = mode_name(defaults.mode),
             py::arg("trim_method") = method_name(defaults.trim_method), py::arg("threads") = defaults.threads,
             py::arg("face_timeout") = defaults.face_timeout, py::arg("area_per_body") = defaults.area_per_body)
        .def_readwrite("tolerance", &tess::TessellationOptions::tolerance)
        .def_readwrite("angle", &tess::TessellationOptions::angle)
        .def_property(
            "mode", [](const tess::TessellationOptions& o) { return mode_name(o.mode); },
            [](tess::TessellationOptions& o, const std::string& s) { o.mode = mode_from_name(s); })
        .def_property(
            "trim_method", [](const tess::TessellationOptions& o) { return method_name(o.trim_method); },
            [](tess::TessellationOptions& o, const std::string& s) { o.trim_method = method_from_name(s); })
        .def_readwrite("threads", &tess::TessellationOptions::threads)
        .def_readwrite("face_timeout", &tess::TessellationOptions::face_timeout,
                       "seconds one face may take; a face that takes longer fails with defect 'timeout' "
                       "(0 = no limit)")
        .def_readwrite("area_per_body", &tess::TessellationOptions::area_per_body,
                       "the area budget per body (each body an object of its own); else one for the model")
        .def_property(
            "cancel", [](const tess::TessellationOptions&) { return py::none(); },
            py::cpp_function(
                [](tess::TessellationOptions& o, CancelFlag* flag) { o.cancel = flag ? &flag->value : nullptr; },
                py::keep_alive<1, 2>()),
            "a CancelFlag (write-only): once set, tessellate_model stops and raises TessellationCancelled")
        .def_property(
            "progress", [](const tess::TessellationOptions&) { return py::none(); },
            [](tess::TessellationOptions& o, const py::object& f) { o.progress = progress_function(f); },
            "callable(fraction of faces meshed) or None (write-only); called with the GIL from worker threads");

    py::class_<tess::FailedFace>(m, "FailedFace",
                                 "A face left out of the mesh; figures NaN unless its mesh was made and rejected.")
        .def_readonly("face", &tess::FailedFace::face)
        .def_readonly("reason", &tess::FailedFace::reason)
        .def_readonly("defect", &tess::FailedFace::defect,
                      "'area', 'trim_loop', 'boundary', 'no_boundary' (the check that failed), "
                      "'timeout' (stopped by face_timeout) or 'error'")
        .def_readonly("area_mesh", &tess::FailedFace::area_mesh)
        .def_readonly("area_exact", &tess::FailedFace::area_exact)
        .def_readonly("area_bound", &tess::FailedFace::area_bound, "allowed |area_mesh - area_exact|")
        .def_readonly("boundary_gap", &tess::FailedFace::boundary_gap,
                      "largest distance between the trim loops' 3D curves and the mesh boundary")
        .def_readonly("boundary_bound", &tess::FailedFace::boundary_bound)
        .def_readonly("seconds", &tess::FailedFace::seconds, "wall time spent on the face (all its attempts)");

    py::class_<tess::TessellationTimings>(m, "TessellationTimings")
        .def_readonly("trim", &tess::TessellationTimings::trim)
        .def_readonly("surface", &tess::TessellationTimings::surface)
        .def_readonly("triangulate", &tess::TessellationTimings::triangulate)
        .def_readonly("weld", &tess::TessellationTimings::weld)
        .def_readonly("verify", &tess::TessellationTimings::verify);

    py::class_<tess::TessellationResult>(m, "TessellationResult")
        .def_readonly("mesh", &tess::TessellationResult::mesh)
        .def_readonly("faces", &tess::TessellationResult::faces)
        .def_readonly("faces_meshed", &tess::TessellationResult::faces_meshed)
        .def_readonly("failed_faces", &tess::TessellationResult::failed_faces)
        .def_readonly("open_edges", &tess::TessellationResult::open_edges)
        .def_readonly("tolerance", &tess::TessellationResult::tolerance)
        .def_readonly("seconds", &tess::TessellationResult::seconds)
        .def_readonly("warnings", &tess::TessellationResult::warnings);

    m.def("tessellate_model", &tess::tessellate_model, py::arg("model"),
          py::arg("options") = tess::TessellationOptions{}, py::call_guard<py::gil_scoped_release>(),
          "Mesh every face of the model (faces that fail are listed in failed_faces). "
          "ValueError for invalid options.");
    py::class_<tess::DeviationReport>(m, "DeviationReport",
                                      "Two-sided deviation of a mesh from the exact trimmed faces (model units).")
        .def_property_readonly("mesh_to_surface", [](const tess::DeviationReport& r) { return r.mesh_to_surface.max; })
        .def_property_readonly("surface_to_mesh", [](const tess::DeviationReport& r) { return r.surface_to_mesh.max; })
        .def_readonly("area_mesh", &tess::DeviationReport::area_mesh)
        .def_readonly("area_exact", &tess::DeviationReport::area_exact)
        .def_readonly("area_ratio", &tess::DeviationReport::area_ratio)
        .def_readonly("open_edges", &tess::DeviationReport::open_edges)
        .def_readonly("face_mesh_to_surface", &tess::DeviationReport::face_mesh_to_surface,
                      "per measured face (in the order of `faces`): max mesh -> surface distance, NaN without triangles")
        .def_readonly("face_surface_to_mesh", &tess::DeviationReport::face_surface_to_mesh)
        .def_readonly("face_area_exact", &tess::DeviationReport::face_area_exact,
                      "per measured face: its exact trimmed area (model units squared)")
        .def_readonly("warnings", &tess::DeviationReport::warnings);
    m.def("measure_deviation", &deviation_of_faces, py::arg("model"), py::arg("mesh"),
          py::arg("faces") = std::vector<int>{}, py::arg("samples") = 4, py::call_guard<py::gil_scoped_release>(),
          "What `trimkit check` measures, over the listed model faces (all when empty); the mesh's "
          "face ids must be among them. ValueError for an invalid mesh or face list.");
    m.def("corner_attributes", &corner_attributes, py::arg("model"), py::arg("mesh"),
          "Per-corner (u,v) in each triangle's own face, (m, 3, 2), and unit normals, (m, 3, 3).");
    m.def("model_diagonal", &tess::model_diagonal, py::arg("model"), py::arg("threads") = 0,
          py::call_guard<py::gil_scoped_release>(),
          "Diagonal of the trimmed faces' bounding box: what a relative tolerance is a fraction of "
          "(faces sampled on `threads` threads, 0: all cores; the same result on any).");
}

}  // namespace trimkit::bindings
