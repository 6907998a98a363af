// TessellationOptions: what a caller asks of the trimmed-NURBS tessellator.
// `tolerance` is absolute, in model units: every mesh point lies within it of the
// exact trimmed surface (mode kGuaranteed). It is split between the trim curves
// and the surface (kTrimToleranceShare), because a triangle touching the trim
// boundary carries both errors. `angle` is in radians.
#pragma once

#include "tess/trim_polyline.h"

namespace trimkit::tess {

enum class ErrorMode {
    kGuaranteed,   // conservative bilinear bound on control points [Balazs] Sec. 5.2
    kApproximate,  // the same bound with surface samples instead of control points
};

struct TessellationOptions {
    double tolerance = 0.01;          // absolute, model units; > 0 and finite
    double angle = 0.5235987755982988;  // 30 degrees: sharp-edge flag threshold, radians
    ErrorMode mode = ErrorMode::kGuaranteed;
    TrimMethod trim_method = TrimMethod::kBezier3d;
    int threads = 0;                  // 0 = all cores
};

// Share of the tolerance given to the trim polylines; the surface subdivision gets
// the rest. A boundary triangle's error is at most the sum of both (the trim
// crossing points lie on the trim chords, within the trim share of S(u,v)).
constexpr double kTrimToleranceShare = 0.25;

// Throws geom::InvalidInput naming the field unless tolerance > 0 and finite,
// angle in [0, pi] and threads >= 0.
void validate(const TessellationOptions& options);

inline double trim_tolerance(const TessellationOptions& options) {
    return kTrimToleranceShare * options.tolerance;
}
inline double surface_tolerance(const TessellationOptions& options) {
    return (1.0 - kTrimToleranceShare) * options.tolerance;
}

}  // namespace trimkit::tess
