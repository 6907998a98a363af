// TessellationOptions: what a caller asks of the trimmed-NURBS tessellator.
// `tolerance` is absolute, in model units: every mesh point lies within it of the
// exact trimmed surface (mode kGuaranteed). Near the trim boundary it is shared
// between the trim curves and the surface (kTrimToleranceShare), because a triangle
// touching the trim boundary carries both errors. `angle` is in radians;
// `face_timeout` in seconds of wall time.
#pragma once

#include <atomic>
#include <functional>

#include "tess/trim_polyline.h"

namespace trimkit::tess {

enum class ErrorMode {
    kGuaranteed,   // conservative bilinear bound on control points [Balazs] Sec. 5.2
    kApproximate,  // the same bound with surface samples instead of control points
};

// Default TessellationOptions::face_timeout, seconds: whole shared CAD files mesh in
// about a second (Motor-c.brep 0.4 s on one thread); a hostile face (a star-shaped trim
// loop crossing itself 720 000 times spends 14 s in its loop repair alone, bench/FUZZ.md)
// grows with the square of its crossings.
constexpr double kDefaultFaceTimeout = 30.0;

struct TessellationOptions {
    double tolerance = 0.01;          // absolute, model units; > 0 and finite
    double angle = 0.5235987755982988;  // 30 degrees: sharp-edge flag threshold, radians
    ErrorMode mode = ErrorMode::kGuaranteed;
    TrimMethod trim_method = TrimMethod::kBezier3d;
    int threads = 0;                  // 0 = all cores
    // Wall time one face may take (all its attempts: trims, loop repair, kd-tree,
    // trimming, triangulation, verification); a face that takes longer is stopped at
    // the next check and reported in failed_faces with defect "timeout". 0 = no limit.
    double face_timeout = kDefaultFaceTimeout;
    // The area budget (area_budget.h) per body, for callers that hand each body out as
    // an object of its own (Blender's split by body); else one budget for the whole
    // model, as one mesh file (a bearing's balls, T = 5 % of their radius, then lose
    // what T allows them while the bearing stays within the budget).
    bool area_per_body = false;
    // Set from any thread to stop the tessellation: faces stop at their next check and
    // tessellate_model throws TessellationCancelled. nullptr: not cancellable.
    const std::atomic<bool>* cancel = nullptr;
    // Called with the fraction of the model's faces meshed (first pass), from the
    // worker threads one at a time; empty: none.
    std::function<void(double)> progress{};
};

// How the tolerance T is shared (kGuaranteed). A triangle's point at barycentric
// weights λ_k of vertices (uv_k, x_k) deviates from S at the interpolated (u,v) by at
// most Σ λ_k |x_k - S(uv_k)| + the cell's bound ([Balazs] Sec. 5.2: the bound holds
// for any triangle with vertices on S in the cell; re-derived). Only trim vertices
// sit off S: the crossings, on the 3D chords of the trim polylines. So:
//  - trims: approximate_trim_curve with trim_tolerance = kTrimToleranceShare·T;
//  - cells that a trim meets: bound <= max(surface_tolerance, T - the offset bound
//    of their own crossings) (kd_subdivision; the offset bound is computed from the
//    chords, so cells take what the trims leave), and <= interior_tolerance;
//  - cells no trim meets (only vertices on S): bound <= interior_tolerance.
// tessellate_model meshes each face to (1 - kWeldShare) T with these shares and
// joins the faces by moving boundary points by at most kWeldShare T.
constexpr double kTrimToleranceShare = 0.5;
// Joining the faces by position (snap_boundary_vertices, close_t_junctions) moves
// mesh points by up to kWeldShare T, so that share is kept back from the faces, and
// a point the join moves stays within T. (Snapping within T on top of meshes that
// spend T put hammer.iges 1.29 T off at 0.016 of its diagonal.)
constexpr double kWeldShare = 0.1;
// Cells could take all that the trims leave (T away from the trims); they take this
// share because the area a mesh loses against a curved surface grows with the chord
// error (about e / 3R on a tube of radius R): with cells at 0.8 T bug22869_Spring's
// thin wire loses 0.18 % of its area, at 0.85 T 0.21 %, beyond the 0.2 % the
// acceptance allows.
constexpr double kInteriorToleranceShare = 0.8;

// Throws geom::InvalidInput naming the field unless tolerance > 0 and finite,
// angle in [0, pi], threads >= 0 and face_timeout >= 0 (not NaN).
void validate(const TessellationOptions& options);

// The tolerance tessellate_model meshes each face to.
inline double face_tolerance(const TessellationOptions& options) {
    return (1.0 - kWeldShare) * options.tolerance;
}
// The tolerance approximate_trim_curve gets.
inline double trim_tolerance(const TessellationOptions& options) {
    return kTrimToleranceShare * options.tolerance;
}
// The least bound of cells that a trim meets (kd_subdivision's boundary_tolerance).
inline double surface_tolerance(const TessellationOptions& options) {
    return (1.0 - kTrimToleranceShare) * options.tolerance;
}
// The bound of cells that no trim meets.
inline double interior_tolerance(const TessellationOptions& options) {
    return kInteriorToleranceShare * options.tolerance;
}

}  // namespace trimkit::tess
