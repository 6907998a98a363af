// Bindings for native/src/fit and the .tkz / IGES writers of io ([Muraki]):
// compress_model (GIL released) with its per-face report, extend_model, the .tkz
// bytes both ways (the add-on stores them in a .blend), write_iges, model_deviation.
#include <pybind11/stl.h>

#include "fit/compress_model.h"
#include "fit/extend_model.h"
#include "fit/g1_angle.h"
#include "fit/model_deviation.h"
#include "io/tkz_format.h"
#include "io/write_iges.h"
#include "numpy_convert.h"

namespace trimkit::bindings {

namespace {

// (compressed model, per-face report) in one call, the GIL released while fitting.
std::pair<fit::CompressedModel, std::vector<fit::FaceCompression>> compress(const geom::Model& model,
                                                                           const fit::CompressOptions& options) {
    py::gil_scoped_release release;
    std::vector<fit::FaceCompression> report;
    fit::CompressedModel c = fit::compress_model(model, options, &report);
    return {std::move(c), std::move(report)};
}

py::bytes tkz_bytes(const fit::CompressedModel& c) { return py::bytes(io::tkz_bytes(c)); }

// The G1 check's samples of a compressed face against its rebuilt surface (in
// `extended`): (points, normals, neighbour normals) as (n, 3) arrays and the angles in
// degrees; empty when the face is kept or has no G1 coedge.
py::tuple g1_normals(const fit::CompressedModel& c, const geom::Model& extended, int face) {
    if (face < 0 || face >= static_cast<int>(c.model.faces.size()) || face >= static_cast<int>(extended.faces.size()))
        throw py::index_error("face " + std::to_string(face) + " out of range");
    std::vector<fit::G1Sample> samples;
    if (face < static_cast<int>(c.rules.size()) && c.rules[face]) {
        py::gil_scoped_release release;
        samples = fit::g1_samples(c.model, fit::edge_faces(c.model), face, *c.rules[face], extended.faces[face].surface);
    }
    std::vector<Eigen::Vector3d> points, normals, neighbour;
    std::vector<double> angles;
    for (const fit::G1Sample& s : samples) {
        points.push_back(s.point);
        normals.push_back(s.normal);
        neighbour.push_back(s.neighbour_normal);
        angles.push_back(s.angle);
    }
    return py::make_tuple(to_numpy<3>(points), to_numpy<3>(normals), to_numpy<3>(neighbour), angles);
}

// The model as a .tkz with every surface kept: lossless, it re-meshes as the source.
py::bytes model_tkz_bytes(const geom::Model& m) {
    return py::bytes(io::tkz_bytes({m, std::vector<std::optional<fit::FitRule>>(m.faces.size())}));
}

fit::CompressedModel read_tkz_bytes(const py::bytes& data, const std::string& name) {
    std::string bytes = data;
    py::gil_scoped_release release;
    return io::read_tkz_bytes(bytes, name);
}

}  // namespace

void bind_fit(py::module_& m) {
    py::class_<fit::CompressOptions>(m, "CompressOptions")
        .def(py::init<>())
        .def_readwrite("tolerance", &fit::CompressOptions::tolerance, "model units; 0: relative_tolerance of each face's box")
        .def_readwrite("relative_tolerance", &fit::CompressOptions::relative_tolerance)
        .def_readwrite("faces", &fit::CompressOptions::faces, "faces that may be compressed; empty: all")
        .def_readwrite("rebuild", &fit::CompressOptions::rebuild,
                       "rebuild the faces even beyond the tolerance of their own (damaged) surface");
    py::class_<fit::FaceCompression>(m, "FaceCompression")
        .def_readonly("compressed", &fit::FaceCompression::compressed)
        .def_readonly("reason", &fit::FaceCompression::reason)
        .def_readonly("tolerance", &fit::FaceCompression::tolerance)
        .def_readonly("g1_edges", &fit::FaceCompression::g1_edges)
        .def_readonly("g1_angle", &fit::FaceCompression::g1_angle)
        .def_property_readonly("max_error", [](const fit::FaceCompression& c) { return c.error.max(); })
        .def_property_readonly("avg_error", [](const fit::FaceCompression& c) { return c.error.surface_avg; });
    py::class_<fit::CompressedModel>(m, "CompressedModel")
        .def_readonly("model", &fit::CompressedModel::model)
        .def_property_readonly("compressed_faces", [](const fit::CompressedModel& c) {
            std::vector<int> faces;
            for (std::size_t f = 0; f < c.rules.size(); ++f)
                if (c.rules[f]) faces.push_back(static_cast<int>(f));
            return faces;
        });
    m.def("compress_model", &compress, py::arg("model"), py::arg("options") = fit::CompressOptions{},
          "Refit each face from its boundary edges with G1 (Muraki); returns (CompressedModel, [FaceCompression]).");
    m.def("extend_model", &fit::extend_model, py::arg("compressed"), py::call_guard<py::gil_scoped_release>(),
          "Rebuild the compressed faces' surfaces; returns a Model.");
    m.def("tkz_bytes", &tkz_bytes, py::arg("compressed"), "The .tkz file of a CompressedModel, as bytes.");
    m.def("g1_normals", &g1_normals, py::arg("compressed"), py::arg("extended"), py::arg("face"),
          "(points, normals, neighbour normals, angles in degrees) along a compressed face's G1 edges: "
          "the check compress_model makes ([Muraki] Fig. 15).");
    m.def("model_tkz_bytes", &model_tkz_bytes, py::arg("model"),
          "The model as .tkz bytes with every surface kept (lossless: it reads back as the same model).");
    m.def("read_tkz_bytes", &read_tkz_bytes, py::arg("data"), py::arg("name"),
          "Read .tkz bytes; raises RuntimeError 'NAME: reason' for a bad file.");
    m.def("write_iges", &io::write_iges, py::arg("model"), py::arg("path"), py::call_guard<py::gil_scoped_release>(),
          "Write a Model as IGES (144/142/102/128/126/110).");
    py::class_<fit::FaceDeviation>(m, "FaceDeviation")
        .def_readonly("a_to_b_max", &fit::FaceDeviation::a_to_b_max)
        .def_readonly("b_to_a_max", &fit::FaceDeviation::b_to_a_max)
        .def_property_readonly("max", &fit::FaceDeviation::max);
    m.def("model_deviation", &fit::model_deviation, py::arg("a"), py::arg("b"), py::call_guard<py::gil_scoped_release>(),
          "Two-sided surface deviation per face between two models with the same faces.");
}

}  // namespace trimkit::bindings
