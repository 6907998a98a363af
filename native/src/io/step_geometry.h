// StepGeometry: the geometric entities of a STEP file (ISO 10303-42 geometric_model
// schema, as AP203/AP214/AP242 use it) translated into trimkit's exact NURBS, keeping
// the kind of surface the file named. Conventions: lengths in the file's own units
// (no scaling here), plane angles converted by the factor the caller gives; frames
// per ISO 10303-42 build_axes (Z = axis, X = ref_direction made orthogonal to Z,
// Y = Z × X); the STEP parameters of each surface (those its PCURVEs use) reach the
// NURBS's (u, v) through Surface::map. No topology: the caller gives the points
// (edge vertices, boundary samples) that locate pieces of unbounded curves and surfaces.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "geom/nurbs_curve.h"
#include "geom/nurbs_surface.h"
#include "geom/parameter_map.h"
#include "io/step_part21.h"

namespace trimkit::io {

// Thrown for an entity kind this layer does not translate (OFFSET_CURVE_3D, PCURVE as
// a 3D curve, HYPERBOLA, ...); the reader then falls back to OCCT.
struct UnsupportedStepEntity : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws UnsupportedStepEntity "FILE:LINE: #ID TYPE: why" for the instance `at` (TYPE:
// its record's type, or "(A B ...)" for a complex instance).
[[noreturn]] void unsupported_step_entity(const StepPart21& file, const StepInstance& at, const std::string& why);

// References followed from one entity (a TRIMMED_CURVE's basis, a SURFACE_CURVE's
// curve_3d, an OFFSET_SURFACE's basis, ...) nest at most this deep; deeper means a
// reference cycle in a broken file.
constexpr int kMaxStepGeometryNesting = 32;

// Unbounded surfaces and curves are built this much (relative to the extent of the
// boundary points in that parameter) beyond that extent, so trims near it stay inside
// and curved edges bulging between the samples are still covered.
constexpr double kStepBoundaryMargin = 0.02;

// A PCURVE mapped into a surface's NURBS (u, v) through a non-affine map is refitted
// within this share of the NURBS domain's larger side (as the OCCT reader's p-curves).
constexpr double kPcurveRefitShare = 1e-7;

// Holds no state beyond the file: its const methods may run on several threads.
class StepGeometry {
public:
    // `file` must outlive this object. plane_angle_to_radians: the file's plane-angle
    // unit in radians (1 for radians, π/180 for degrees), used for CONICAL_SURFACE's
    // semi_angle.
    explicit StepGeometry(const StepPart21& file, double plane_angle_to_radians = 1.0);
    StepGeometry(StepPart21&&, double = 1.0) = delete;  // would dangle

    // ---- Points, directions, placements -------------------------------------------

    // CARTESIAN_POINT (2D points get z = 0).
    Eigen::Vector3d point(long long id) const;
    // DIRECTION, normalised (2D: z = 0); a zero direction is a ReadError.
    Eigen::Vector3d direction(long long id) const;
    // VECTOR: orientation (normalised) × magnitude; magnitude must be > 0.
    Eigen::Vector3d vector(long long id) const;
    // The map from the local frame (e1, e2, e3 at 0) to the placement's (X, Y, Z at its
    // location): AXIS2_PLACEMENT_3D (axis default (0,0,1); ref_direction default per
    // ISO 10303-42 first_proj_axis: (1,0,0), or (0,1,0) when the axis is ±(1,0,0)),
    // AXIS2_PLACEMENT_2D (Z = (0,0,1)), AXIS1_PLACEMENT (Z = its axis, X the default).
    // A ref_direction parallel to the axis is a ReadError.
    Eigen::Affine3d placement(long long id) const;

    // ---- Curves ----------------------------------------------------------------

    // The parameter range of a curve that an edge uses, in the curve's own STEP
    // parameter as the file writes it (a conic's angle in the file's plane-angle
    // unit; a TRIMMED_CURVE's, SURFACE_CURVE's or SEAM_CURVE's that of its basis or
    // curve_3d): `start` at the edge's start vertex, `end` at its end vertex (end <
    // start when the edge runs against the curve). `period` > 0 for a closed curve
    // (its period; the range may run past the curve's end by less than one), else 0.
    // A SURFACE_CURVE's PCURVEs share this parameter (ISO 10303-42 4.4.x surface_curve).
    struct EdgeRange {
        double start = 0, end = 0, period = 0;
    };

    // The piece of curve `curve_id` that an EDGE_CURVE with vertex points `start` and
    // `end` and flag `same_sense` uses, returned running from start to end:
    //  - same_sense: the piece that follows the curve's own direction from start to end;
    //  - !same_sense: the piece that follows the curve's direction from end to start,
    //    returned reversed (so it still starts at `start`).
    //  - |start - end| <= tol on a closed curve (CIRCLE, ELLIPSE, a B-spline whose ends
    //    meet): the whole period starting at start, in that direction; on an open one
    //    (LINE, open B-spline) a ReadError.
    // The ends are the curve's points nearest the vertex points (not the vertex points
    // themselves). A bounded open curve whose vertices come in the other order than
    // same_sense says is still cut between them (start to end) rather than rejected.
    // Parameter: a LINE piece keeps the line's parameter (negated when it runs against
    // it), CIRCLE/ELLIPSE pieces the angle at their knots (geom::ArcParameterMap of
    // geom::circular_arc, increasing), B-spline pieces their parameter (reversed()
    // when traversed against it; a closed curve's piece across its ends is shifted
    // past the end).
    // Kinds: LINE, CIRCLE, ELLIPSE, POLYLINE (ISO's integer parameter),
    // B_SPLINE_CURVE_WITH_KNOTS, BEZIER_CURVE, QUASI_UNIFORM_CURVE, UNIFORM_CURVE, their
    // complex rational forms (RATIONAL_B_SPLINE_CURVE partial record), TRIMMED_CURVE
    // (its basis curve: the vertices choose the piece), SURFACE_CURVE, SEAM_CURVE,
    // INTERSECTION_CURVE (their curve_3d). UnsupportedStepEntity: PCURVE (not a 3D
    // curve), OFFSET_CURVE_3D, COMPOSITE_CURVE, HYPERBOLA, PARABOLA and other curves.
    // `range`, when given, receives the parameter range of the piece (EdgeRange).
    geom::NurbsCurve3d edge_curve(long long curve_id, const Eigen::Vector3d& start,
                                  const Eigen::Vector3d& end, bool same_sense, double tol,
                                  EdgeRange* range = nullptr) const;

    // The parameter-space curve of an edge on a surface: the PCURVE among the
    // associated_geometry of the SURFACE_CURVE or SEAM_CURVE `curve_id` whose
    // basis_surface is the instance `surface_id` (a SEAM_CURVE has two on it: the
    // first when `first_of_seam`, else the second), its DEFINITIONAL_REPRESENTATION's
    // first item cut to `range` and running from range.start to range.end, in the
    // surface's STEP parameters (s, t) as the file writes them (angles in its unit).
    // 2D kinds: those of edge_curve with 2D points and placements (LINE, CIRCLE,
    // ELLIPSE, POLYLINE, the B-spline and Bezier curves, rational too, TRIMMED_CURVE:
    // its basis). nullopt, never an exception, for anything else: no such PCURVE, a
    // kind not translated, a bounded 2D curve not covering the range (shifted by whole
    // periods of a closed edge curve), a malformed entity. The caller projects instead.
    std::optional<geom::NurbsCurve2d> edge_pcurve(long long curve_id, long long surface_id,
                                                  const EdgeRange& range, bool first_of_seam) const;

    // ---- Surfaces --------------------------------------------------------------

    struct Surface {
        geom::NurbsSurface nurbs;
        // Face::surface_kind: "plane", "cylinder", "cone", "sphere", "torus",
        // "revolution", "extrusion", "bspline", "bezier", "offset" (an offset of an
        // elementary surface); a RECTANGULAR_TRIMMED_SURFACE has its basis's kind.
        std::string kind;
        // STEP parameters (s, t) of the surface -> the NURBS's (u, v). Angles map
        // through ArcParameterMaps valid on one turn [θ0, θ1] (bring a PCURVE's angles
        // into it by whole turns first); SURFACE_OF_REVOLUTION swaps (angle, curve
        // parameter) into (curve parameter, angle).
        geom::ParameterMap map;
    };
    // The surface `id` over the part of it that the face's boundary covers; `boundary`
    // are 3D points sampled along every edge of the face, loop by loop in order
    // (consecutive points of one edge close together: their angles decide which arc
    // the boundary covers, see io/boundary_extent.h).
    //  - Bounded surfaces ignore `boundary`: B_SPLINE_SURFACE_WITH_KNOTS, BEZIER_SURFACE,
    //    QUASI_UNIFORM_SURFACE, UNIFORM_SURFACE and their rational complex forms.
    //  - PLANE, CYLINDRICAL_SURFACE, CONICAL_SURFACE, SURFACE_OF_LINEAR_EXTRUSION:
    //    lengths over the boundary's extent plus kStepBoundaryMargin (a cone's not past
    //    its apex; a cone going all the way round whose boundary lies at one height, a
    //    cap, reaches to its apex).
    //  - Angles (cylinder, cone, sphere and torus longitude, torus tube angle, angle
    //    of a revolution, a circular generatrix or directrix): the arc the boundary
    //    covers plus the margin, or a whole turn [0, 2π] (io/boundary_extent.h).
    //  - SPHERICAL_SURFACE: latitude over the boundary's plus the margin, up to the
    //    poles; a face going all the way round gets pole to pole (the boundary alone
    //    cannot tell a cap from a band, both are inside that).
    //  - TOROIDAL_SURFACE, DEGENERATE_TOROIDAL_SURFACE (tube angle limited to the
    //    selected outer or inner part); where R + r cos φ < 0 (a spindle torus, R < r)
    //    a point at longitude λ has θ = λ + π, and a TOROIDAL_SURFACE with R < r puts
    //    each point on the part whose tube it lies on.
    //  - The boundary alone cannot tell a face from its complement on a closed surface:
    //    a torus face bounded only by two parallels (no seam samples between them) is
    //    taken as the shorter tube arc.
    //  - SURFACE_OF_REVOLUTION, SURFACE_OF_LINEAR_EXTRUSION: a bounded swept curve
    //    whole; a LINE, CIRCLE or ELLIPSE over the part the boundary covers.
    //  - OFFSET_SURFACE of a plane, cylinder, cone, sphere or torus (another of the same
    //    kind, kind "offset"); of other surfaces UnsupportedStepEntity.
    //  - RECTANGULAR_TRIMMED_SURFACE: its basis surface sized by the boundary.
    // An unbounded surface with an empty boundary is a ReadError.
    Surface surface(long long id, const std::vector<Eigen::Vector3d>& boundary) const;

    // A curve in the STEP parameters (s, t) of `S` (an edge_pcurve) mapped into
    // S.nurbs's (u, v): the angular parameters (those whose axis map has an arc)
    // converted to radians and moved by whole turns to start in the arc's turn (past
    // its end a whole-turn arc continues periodically), then S.map.map_curve within
    // kPcurveRefitShare. nullopt when the map fails (never an exception).
    std::optional<geom::NurbsCurve2d> map_pcurve(const Surface& S, const geom::NurbsCurve2d& c) const;

private:
    const StepPart21& file_;
    double angle_factor_;
};

}  // namespace trimkit::io
