// TbpPatch and TbpSolid: a solid bounded by triangular Bezier patches ([Garcia]
// Sec. 2). A patch is a geom::BezierTriangle (degree n, (n+1)(n+2)/2 control
// points, order b_n00 ... b_00n as in geom/bezier_triangle.h). A solid is a
// closed set of patches of one degree, oriented so that every patch's normal
// (db/du x db/dv) points out of the solid; neighbouring patches share their
// boundary curves (same edge control points, traversed in opposite directions).
#pragma once

#include <string>
#include <vector>

#include "geom/bezier_triangle.h"

namespace trimkit::tbp {

using TbpPatch = geom::BezierTriangle;

struct TbpSolid {
    std::string name;               // optional, from the file
    std::vector<TbpPatch> patches;  // all of one degree

    int degree() const { return patches.empty() ? 0 : patches.front().degree(); }
};

// Throws geom::InvalidInput unless the solid has at least one patch and all
// patches have the same degree ("TbpSolid: patch 3 has degree 2, patch 0 has 3").
void validate(const TbpSolid& solid);

}  // namespace trimkit::tbp
