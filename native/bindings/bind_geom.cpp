// Bindings for native/src/geom: the data model read-only, surface evaluation on
// parameter arrays, and the two model-to-model functions (placing instances,
// picking faces) a caller needs to mesh an assembly part by part.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "geom/flatten_instances.h"
#include "geom/model.h"
#include "geom/select_faces.h"
#include "numpy_convert.h"

namespace trimkit::bindings {

namespace {

// (n, 2) parameters -> (n, 3) points.
py::array_t<double> evaluate_surface(const geom::NurbsSurface& surface, const DoubleArray& uv) {
    const py::ssize_t n = expect_columns(uv, 2, "NurbsSurface.evaluate(uv)");
    py::array_t<double> out({n, py::ssize_t{3}});
    auto in = uv.unchecked<2>();
    auto view = out.mutable_unchecked<2>();
    {
        py::gil_scoped_release release;
        for (py::ssize_t i = 0; i < n; ++i) {
            const Eigen::Vector3d p = surface.evaluate(in(i, 0), in(i, 1));
            for (int k = 0; k < 3; ++k) view(i, k) = p[k];
        }
    }
    return out;
}

}  // namespace

void bind_geom(py::module_& m) {
    py::class_<geom::NurbsSurface>(m, "NurbsSurface")
        .def_property_readonly("degree_u", &geom::NurbsSurface::degree_u)
        .def_property_readonly("degree_v", &geom::NurbsSurface::degree_v)
        .def_property_readonly("count_u", &geom::NurbsSurface::count_u)
        .def_property_readonly("count_v", &geom::NurbsSurface::count_v)
        .def_property_readonly("is_rational", &geom::NurbsSurface::is_rational)
        .def_property_readonly("domain_u", &geom::NurbsSurface::domain_u)
        .def_property_readonly("domain_v", &geom::NurbsSurface::domain_v)
        .def_property_readonly("points", [](const geom::NurbsSurface& s) { return to_numpy<3>(s.points()); })
        .def("evaluate", &evaluate_surface, py::arg("uv"),
             "Points S(u, v) for an (n, 2) array of parameters, as an (n, 3) array.");

    py::class_<geom::Loop>(m, "Loop")
        .def_readonly("outer", &geom::Loop::outer)
        .def_property_readonly("coedge_count", [](const geom::Loop& l) { return l.coedges.size(); });

    py::class_<geom::Face>(m, "Face")
        .def_readonly("surface", &geom::Face::surface)
        .def_readonly("loops", &geom::Face::loops)
        .def_readonly("reversed", &geom::Face::reversed)
        .def_readonly("surface_kind", &geom::Face::surface_kind)
        .def_readonly("name", &geom::Face::name)
        .def_readonly("color", &geom::Face::color)
        .def_readonly("warnings", &geom::Face::warnings);

    py::class_<geom::Body>(m, "Body")
        .def_readonly("name", &geom::Body::name)
        .def_readonly("faces", &geom::Body::faces)
        .def_readonly("closed", &geom::Body::closed);

    py::class_<geom::Instance>(m, "Instance")
        .def_readonly("body", &geom::Instance::body)
        .def_property_readonly(
            "matrix", [](const geom::Instance& i) -> Eigen::Matrix4d { return i.transform.matrix(); },
            "(4, 4) float64: the body's coordinates to the model's (file units), column vectors.")
        .def_readonly("name", &geom::Instance::name)
        .def_readonly("path", &geom::Instance::path,
                      "Assembly names from the root down to the one holding the instance (STEP).");

    py::class_<geom::Color>(m, "Color")
        .def_readonly("rgb", &geom::Color::rgb)
        .def_readonly("name", &geom::Color::name);

    py::class_<geom::Model>(m, "Model")
        .def_readonly("units", &geom::Model::units)
        .def_readonly("scale_to_metres", &geom::Model::scale_to_metres)
        .def_readonly("faces", &geom::Model::faces)
        .def_readonly("bodies", &geom::Model::bodies)
        .def_readonly("instances", &geom::Model::instances)
        .def_readonly("colors", &geom::Model::colors)
        .def_readonly("warnings", &geom::Model::warnings)
        .def_readonly("unread_faces", &geom::Model::unread_faces,
                      "why each face the reader left out was left out (each also in warnings)");

    m.def("flatten_instances", &geom::flatten_instances, py::arg("model"), py::call_guard<py::gil_scoped_release>(),
          "The model with every instance's body copied into place (what `trimkit mesh` meshes): faces in no "
          "instanced body first, then each instance's copy; unchanged without instances.");
    m.def("select_faces", &geom::select_faces, py::arg("model"), py::arg("faces"),
          py::call_guard<py::gil_scoped_release>(),
          "A model of the listed faces only, in that order, all free (bodies and instances dropped; edges keep "
          "their indices). ValueError for an index out of range or repeated.");
}

}  // namespace trimkit::bindings
