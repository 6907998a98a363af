// Bound on how far a triangle whose vertices are points of S lies from S, from its
// (u,v) box, as kd_subdivision bounds its cells: for triangles that span cells
// (remove_crossings' triangles without a crossing).
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "geom/nurbs_surface.h"
#include "tess/bezier_patch.h"
#include "tess/revolution_error.h"
#include "tess/second_derivative_bound.h"
#include "tess/tessellation_options.h"

namespace trimkit::tess {

class TriangleBound {
public:
    // S and `shape` (revolution_shape of S, or null) must outlive the bound; `tolerance`: the bound callers aim at
    // (it only steers the split the cell bounds compute alongside).
    TriangleBound(const geom::NurbsSurface& S, const RevolutionShape* shape, ErrorMode mode, double tolerance);

    // For any triangle with vertices on S inside `box`:
    //  - the box in one Bezier patch: the cell bound of the patch's piece over it
    //    (revolution_error where it applies, else bilinear_error, which takes the
    //    piece's second-derivative bound where that is smaller);
    //  - across patches, where S is C^1 inside the box (is_c1_inside):
    //    block_error with the largest of the patches' second-derivative bounds;
    //  - else, or a box outside the patches, infinity.
    // Patches are converted once, on the first call.
    double operator()(Eigen::AlignedBox2d box);

private:
    void convert();
    // Patch k's second-derivative bound in the surface's parameters, computed once.
    const SecondDerivativeBound& patch_bound(long k);
    // Of the spans between `lines` (ascending sides, x within them): the one x starts
    // (x on a side: the span after it) and the one x ends (x on a side: the one before).
    static long first_span(const std::vector<double>& lines, double x);
    static long last_span(const std::vector<double>& lines, double x);

    const geom::NurbsSurface& S_;
    const RevolutionShape* shape_;
    ErrorMode mode_;
    double tolerance_;
    bool converted_ = false;
    std::vector<double> u_, v_;            // the patches' sides, ascending
    std::vector<BezierPatch> patches_;     // per (iu, iv): iu * (v_.size() - 1) + iv
    std::vector<SecondDerivativeBound> M_;  // per patch where has_M_
    std::vector<char> has_M_;
};

}  // namespace trimkit::tess
