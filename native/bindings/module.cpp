// PYBIND11_MODULE(_trimkit): one bind_<dir>() per native/src directory.
#include <pybind11/pybind11.h>

#include "geom/error.h"
#include "tess/tessellate_model.h"

namespace py = pybind11;

namespace trimkit::bindings {
void bind_fit(py::module_& m);
void bind_geom(py::module_& m);
void bind_io(py::module_& m);
void bind_mesh(py::module_& m);
void bind_tess(py::module_& m);
void bind_tbp(py::module_& m);
}  // namespace trimkit::bindings

PYBIND11_MODULE(_trimkit, m) {
    m.doc() = "trimkit: trimmed NURBS and triangular Bezier patch geometry";
    // InvalidInput derives from std::invalid_argument -> ValueError by default;
    // ReadError and NumericalFailure become subclasses of RuntimeError.
    py::register_exception<trimkit::geom::ReadError>(m, "ReadError", PyExc_RuntimeError);
    py::register_exception<trimkit::geom::NumericalFailure>(m, "NumericalFailure", PyExc_RuntimeError);
    py::register_exception<trimkit::tess::TessellationCancelled>(m, "TessellationCancelled", PyExc_RuntimeError);
    trimkit::bindings::bind_geom(m);
    trimkit::bindings::bind_mesh(m);
    trimkit::bindings::bind_tess(m);
    trimkit::bindings::bind_fit(m);
    trimkit::bindings::bind_io(m);
    trimkit::bindings::bind_tbp(m);
}
