// Bindings for native/src/io: reading models and their summaries.
#include <pybind11/stl.h>

#include "io/model_summary.h"
#include "io/read_model.h"
#include "numpy_convert.h"

namespace trimkit::bindings {

void bind_io(py::module_& m) {
    m.def("read_model", &io::read_model, py::arg("path"),
          py::call_guard<py::gil_scoped_release>(),
          "Read an IGES model; raises RuntimeError 'FILE:LINE: reason' for a bad file.");

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
