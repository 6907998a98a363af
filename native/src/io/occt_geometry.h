// Open CASCADE geometry translated straight into trimkit's exact kinds (compiled only
// with TRIMKIT_WITH_OCCT), as the IGES reader does for its entities: planes,
// cylinders, cones, spheres, tori, surfaces of revolution and of linear extrusion,
// Bézier and B-spline surfaces keep their shape exactly and their kind by name; the
// ParameterMap takes OCCT's (u, v) (angles in radians, lengths), in which the
// face's p-curves are written, to the NurbsSurface's parameters. Unbounded and
// periodic surfaces are built over `range`, the (u, v) box the face's trims cover,
// so a trim that runs across the seam (u in [-π/2, π/2] on a cylinder) stays whole.
#pragma once

#include <string>

#include <Eigen/Geometry>
#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>

#include "geom/nurbs_curve.h"
#include "geom/nurbs_surface.h"
#include "geom/parameter_map.h"

namespace trimkit::io {

struct TranslatedSurface {
    geom::NurbsSurface nurbs;
    std::string kind;       // Face::surface_kind: "plane", "cylinder", ..., "bspline"
    geom::ParameterMap map; // OCCT (u, v) -> nurbs (u, v)
};

// Thrown for a surface or curve kind without a direct translation (offset
// surfaces, offset curves, ...): the caller falls back to OCCT's own conversion.
struct UntranslatedKind : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// `s` in its own coordinates (the caller applies the face's location). Throws
// UntranslatedKind, geom::InvalidInput or Standard_Failure.
TranslatedSurface translate_surface(const Handle(Geom_Surface)& s, const Eigen::AlignedBox2d& range);

// The curve over [first, last] (its own parameter kept for B-splines and lines;
// the same trace and end points for conics). Throws Standard_Failure or
// geom::InvalidInput.
geom::NurbsCurve2d translate_curve(const Handle(Geom2d_Curve)& c, double first, double last);
geom::NurbsCurve3d translate_curve(const Handle(Geom_Curve)& c, double first, double last);

// The surface's own kind name, for faces converted by the fallback.
std::string surface_kind_name(const Handle(Geom_Surface)& s);

}  // namespace trimkit::io
