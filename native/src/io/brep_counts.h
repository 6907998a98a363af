// The counts in a .brep text that size Open CASCADE's allocations as BRepTools::Read
// meets them (a B-spline's poles and knots, a triangulation's nodes and triangles, a
// polygon's nodes), checked against the file before OCCT reads it: every counted item
// takes at least one token of the file (a character and a blank), so a count above
// what the rest of the file can hold is damage,
// and trusting it asked for 24 GB (a triangulation of 2e9 triangles in CrankArm.brep).
// The sections are walked item by item in OCCT's text format (Curve2ds, Curves,
// Polygon3D, PolygonOnTriangulations, Surfaces, Triangulations); where an item is not
// one the walk knows (a type code, a flag or a degree out of range) the walk of that
// section stops and OCCT's reader decides. Damaged text past a known count is left to
// BrepInput (brep_input.h).
#pragma once

#include <string>

namespace trimkit::io {

// Degrees above this are not OCCT's (Geom_BSplineCurve::MaxDegree() is 25).
constexpr int kMaxBrepDegree = 25;
// Nesting of trimmed / offset / swept items the walk follows.
constexpr int kMaxBrepNesting = 16;

// Throws geom::ReadError(path, line of the count, ...) for a count the file cannot hold.
void check_brep_counts(const std::string& text, const std::string& path);

}  // namespace trimkit::io
