// Bindings for native/src/io: reading models and their summaries.
#include <atomic>
#include <functional>
#include <string>

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <tuple>

#include "io/model_summary.h"
#include "io/read_iges.h"
#include "io/read_model.h"
#include "io/read_brep.h"
#include "io/read_step.h"
#include "io/write_glb.h"
#include "io/write_mesh.h"
#include "cancel_flag.h"
#include "numpy_convert.h"

namespace trimkit::bindings {

namespace {

using Reader = std::function<geom::Model(const io::ReadOptions&)>;

// Runs `reader` with the GIL released. `progress` (a callable taking the fraction,
// or None) is called with the GIL taken; an exception from it cancels the read and
// is raised as RuntimeError once the reader has returned.
geom::Model read_with(const Reader& reader, const std::string& path, double read_timeout,
                      const py::object& progress, CancelFlag* cancel) {
    io::ReadOptions options;
    options.timeout = read_timeout;
    CancelFlag local;
    CancelFlag& flag = cancel ? *cancel : local;
    options.cancel = &flag.value;
    std::string callback_error;
    if (!progress.is_none()) {
        options.progress = [&](double fraction) {
            py::gil_scoped_acquire gil;
            if (!callback_error.empty()) return;
            try {
                progress(fraction);
            } catch (py::error_already_set& e) {
                callback_error = e.what();
                flag.value = true;
            }
        };
    }
    geom::Model model;
    try {
        py::gil_scoped_release release;
        model = reader(options);
    } catch (const io::ReadStopped&) {
        if (callback_error.empty()) throw;
    }
    if (!callback_error.empty()) throw std::runtime_error(path + ": the progress callback raised: " + callback_error);
    return model;
}

template <geom::Model (*reader)(const std::string&, const io::ReadOptions&)>
geom::Model read_file(const std::string& path, double read_timeout, const py::object& progress, CancelFlag* cancel) {
    return read_with([&](const io::ReadOptions& options) { return reader(path, options); }, path, read_timeout,
                     progress, cancel);
}

// IGES text held in memory (e.g. stored inside a .blend) read like a file.
geom::Model read_model_bytes(const py::bytes& data, const std::string& name, double read_timeout,
                             const py::object& progress, CancelFlag* cancel) {
    const std::string text = data;
    return read_with([&](const io::ReadOptions& options) { return io::read_iges_text(text, name, options); }, name,
                     read_timeout, progress, cancel);
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
    py::register_exception<io::ReadStopped>(m, "ReadStopped", m.attr("ReadError"));
    py::class_<CancelFlag>(m, "CancelFlag", "Set it (from any thread) to stop a read at its next check.")
        .def(py::init<>())
        .def("set", [](CancelFlag& f) { f.value = true; })
        .def("clear", [](CancelFlag& f) { f.value = false; })
        .def("is_set", [](const CancelFlag& f) { return f.value.load(); });
    m.attr("DEFAULT_READ_TIMEOUT") = io::kDefaultReadTimeout;
    // Docstrings outlive bind_io (pybind11 keeps the pointers).
    static const std::string limits =
        " read_timeout: seconds (0 = no limit); progress: callable(fraction in [0, 1]) or None, called with "
        "the GIL from the reading thread; cancel: a CancelFlag. A read stopped by either raises ReadStopped "
        "(a ReadError, RuntimeError): 'FILE: reading stopped after N s (read timeout)' or "
        "'FILE: reading cancelled after N s'. The GIL is released while reading.";
    static std::string model_doc, step_doc, brep_doc;
    m.def("read_model", &read_file<&io::read_model>, py::arg("path"),
          py::arg("read_timeout") = io::kDefaultReadTimeout, py::arg("progress") = py::none(),
          py::arg("cancel") = nullptr,
          (model_doc = "Read an IGES, STEP or .brep model (by extension); raises RuntimeError 'FILE:LINE: reason' "
                       "for a bad file." + limits).c_str());
    m.def("step_supported", &io::step_supported,
          "True when this build reads STEP files (built with Open CASCADE).");
    // Only with OCCT: the add-on shows its STEP import operator when read_step exists.
    if (io::step_supported())
        m.def("read_step", &read_file<&io::read_step>, py::arg("path"),
              py::arg("read_timeout") = io::kDefaultReadTimeout, py::arg("progress") = py::none(),
              py::arg("cancel") = nullptr,
              (step_doc = "Read a STEP model through Open CASCADE; raises RuntimeError 'FILE: reason'." + limits)
                  .c_str());
    if (io::step_supported())
        m.def("read_brep", &read_file<&io::read_brep>, py::arg("path"),
              py::arg("read_timeout") = io::kDefaultReadTimeout, py::arg("progress") = py::none(),
              py::arg("cancel") = nullptr,
              (brep_doc = "Read an Open CASCADE .brep model; raises RuntimeError 'FILE: reason'." + limits).c_str());

    static std::string bytes_doc;
    m.def("read_model_bytes", &read_model_bytes, py::arg("data"), py::arg("name"),
          py::arg("read_timeout") = io::kDefaultReadTimeout, py::arg("progress") = py::none(),
          py::arg("cancel") = nullptr,
          (bytes_doc = "Read an IGES model from bytes; `name` is used in messages ('NAME:LINE: reason')." + limits)
              .c_str());
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
        .def_readonly("unread_faces", &io::ModelSummary::unread_faces)
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
