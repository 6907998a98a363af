// Bindings for native/src/io: reading models and their summaries.
#include <pybind11/stl.h>

#include <tuple>

#include "io/model_summary.h"
#include "io/read_iges.h"
#include "io/read_model.h"
#include "io/read_brep.h"
#include "io/read_step.h"
#include "io/write_glb.h"
#include "io/write_mesh.h"
#include "numpy_convert.h"

namespace trimkit::bindings {

namespace {

// IGES text held in memory (e.g. stored inside a .blend) read like a file.
geom::Model read_model_bytes(const py::bytes& data, const std::string& name) {
    std::string text = data;
    py::gil_scoped_release release;
    return io::read_iges_text(text, name);
}

// GlbNodes from (mesh index, 4x4 matrix, name) tuples.
std::vector<io::GlbNode> glb_nodes(const std::vector<std::tuple<int, DoubleArray, std::string>>& placements) {
    std::vector<io::GlbNode> nodes;
    for (const auto& [mesh, matrix, name] : placements) {
        if (matrix.ndim() != 2 || matrix.shape(0) != 4 || matrix.shape(1) != 4)
            throw py::value_error("write_glb_instances: each matrix must have shape (4, 4)");
        io::GlbNode node;
        node.mesh = mesh;
        node.name = name;
        const auto m = matrix.unchecked<2>();
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) node.matrix(r, c) = m(r, c);
        nodes.push_back(node);
    }
    return nodes;
}

}  // namespace

void bind_io(py::module_& m) {
    m.def("read_model", &io::read_model, py::arg("path"),
          py::call_guard<py::gil_scoped_release>(),
          "Read an IGES, STEP or .brep model (by extension); raises RuntimeError 'FILE:LINE: reason' for a bad file.");
    m.def("step_supported", &io::step_supported,
          "True when this build reads STEP files (built with Open CASCADE).");
    // Only with OCCT: the add-on shows its STEP import operator when read_step exists.
    if (io::step_supported())
        m.def("read_step", &io::read_step, py::arg("path"),
              py::call_guard<py::gil_scoped_release>(),
              "Read a STEP model through Open CASCADE; raises RuntimeError 'FILE: reason'.");
    if (io::step_supported())
        m.def("read_brep", &io::read_brep, py::arg("path"),
              py::call_guard<py::gil_scoped_release>(),
              "Read an Open CASCADE .brep model; raises RuntimeError 'FILE: reason'.");

    m.def("read_model_bytes", &read_model_bytes, py::arg("data"), py::arg("name"),
          "Read an IGES model from bytes; `name` is used in messages ('NAME:LINE: reason').");
    m.def("write_mesh", &io::write_mesh, py::arg("path"), py::arg("mesh"),
          py::call_guard<py::gil_scoped_release>(),
          "Write a Mesh as .obj, .ply, .stl or .glb (by extension).");
    m.def(
        "write_glb_instances",
        [](const std::string& path, const std::vector<mesh::Mesh>& meshes,
           const std::vector<std::tuple<int, DoubleArray, std::string>>& placements) {
            const std::vector<io::GlbNode> nodes = glb_nodes(placements);
            py::gil_scoped_release release;
            io::write_glb(path, meshes, nodes);
        },
        py::arg("path"), py::arg("meshes"), py::arg("placements"),
        "Write meshes once each to a .glb, placed by one node per (mesh index, 4x4 matrix, name).");

    py::class_<io::ModelSummary>(m, "ModelSummary")
        .def_readonly("file", &io::ModelSummary::file)
        .def_readonly("units", &io::ModelSummary::units)
        .def_readonly("scale_to_metres", &io::ModelSummary::scale_to_metres)
        .def_readonly("faces", &io::ModelSummary::faces)
        .def_readonly("surfaces", &io::ModelSummary::surfaces)
        .def_readonly("loops", &io::ModelSummary::loops)
        .def_readonly("coedges", &io::ModelSummary::coedges)
        .def_readonly("shared_edges", &io::ModelSummary::shared_edges)
        .def_readonly("bodies", &io::ModelSummary::bodies)
        .def_readonly("warnings", &io::ModelSummary::warnings);
    m.def("summarize", &io::summarize, py::arg("model"), py::arg("file") = std::string());
    m.def("to_json", py::overload_cast<const io::ModelSummary&>(&io::to_json), py::arg("summary"));
}

}  // namespace trimkit::bindings
