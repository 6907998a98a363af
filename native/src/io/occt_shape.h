// A TopoDS_Shape translated into a geom::Model (compiled only with TRIMKIT_WITH_OCCT):
// each face occurrence becomes a geom::Face with its location applied, its surface
// and p-curves translated directly (occt_geometry.h), edges shared between the
// faces of one shape (same TShape and location), solids and shells as bodies.
// Faces whose wires do not close, or whose curves are missing, are healed with
// OCCT's ShapeFix_Face on a copy and translated again (a warning on the face says
// so); faces of kinds without a direct translation go through OCCT's own
// BRepBuilderAPI_NurbsConvert, one face at a time.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>

#include "geom/model.h"
#include "io/read_monitor.h"

namespace trimkit::io {

struct ShapeStyle {
    // Colour index into Model::colors of a face or a body's shape, -1 for none.
    std::function<int(const TopoDS_Shape&, geom::Model&)> color;
    // Name of a body's shape ("" for none).
    std::function<std::string(const TopoDS_Shape&)> name;
};

// Adds the faces of `part` to `model` (sewn first when they share no edges:
// occt_sewing.h; a warning says so) and its solids and shells (and, when none,
// one body of all its faces) as bodies named after `fallback_name` when the style
// gives none; returns the indices of the new bodies. Faces that cannot be
// translated are left out with a warning in Model::warnings naming them
// ("face 12 skipped: ..."), counting faces from `first_face_number`.
// monitor: checked before each face (ReadStopped propagates; it is not a skipped face).
std::vector<int> add_shape(geom::Model& model, const TopoDS_Shape& part, const ShapeStyle& style,
                           const std::string& fallback_name, int& face_number, ReadMonitor* monitor = nullptr);

}  // namespace trimkit::io
