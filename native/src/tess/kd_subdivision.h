// kd-tree subdivision of a surface into axis-aligned (u,v) cells whose bilinear
// error is within a tolerance [Balazs] Sec. 5.2, as the cell graph the trimming
// walks. The cells tile `box` without overlap. Each cell's boundary lists its
// corners and the corners of neighbouring cells that lie on its sides
// (T-junctions), counter-clockwise from (u0, v0), so triangulating every cell with
// all its boundary points gives a conforming mesh.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "geom/nurbs_surface.h"
#include "mesh/deadline.h"
#include "tess/revolution_error.h"
#include "tess/tessellation_options.h"
#include "tess/trim_polyline.h"

namespace trimkit::tess {

struct Cell {
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;  // u0 < u1, v0 < v1
};

struct CellGrid {
    Eigen::AlignedBox2d box;  // union of the cells
    std::vector<Cell> cells;
    // Per cell: boundary points counter-clockwise from (u0, v0), corners included.
    std::vector<std::vector<Eigen::Vector2d>> boundary;
};

// Upper bound on the cells of one face: a tolerance this fine for a face is almost
// certainly a unit mistake, and the memory would run out first.
constexpr std::size_t kMaxCells = 4'000'000;

// Splits each Bezier patch of `surface` that meets `box` (restricted to it) at the
// point of largest bilinear error until bilinear_error(.., mode).bound <= tolerance.
// Cells on the sides of the surface's domain are stretched to the sides of `box`
// where `box` reaches beyond the domain (trim loops a little outside it).
// Throws geom::InvalidInput for an empty or non-finite box or a tolerance <= 0,
// geom::NumericalFailure when a bound is not finite or more than kMaxCells are needed.
CellGrid kd_subdivision(const geom::NurbsSurface& surface, const Eigen::AlignedBox2d& box,
                        double tolerance, ErrorMode mode, const RevolutionShape* shape = nullptr);

// Trim-aware subdivision. A cell that no segment of `loops` meets (closed cell, with
// a margin of kTrimMeetMargin of the box) holds only vertices on S: its bound must
// be <= `tolerance`. A cell a segment meets also holds the crossings of its sides
// with the segments, which sit off S by up to s (1 - s) F / 2 (F >= sup |f''| for
// f(s) = S(a + s (b - a)), [Yang] eq. 10 with a linear curve; infinite across a C^0
// knot line): its bound must be <= min(tolerance, max(boundary_tolerance,
// total_tolerance - the largest offset of its own crossings)), so bound + offset <=
// total_tolerance when the trims keep their offsets <= total_tolerance -
// boundary_tolerance.
// Cells that no segment meets and that lie outside the loops (even-odd rule, as
// trim_cells decides) produce no triangles and are not subdivided at all.
// `loops`: closed polygons in (u,v); orientation does not matter here.
// With a `shape` (revolution_shape of the surface), cells are bounded by
// revolution_error instead (its exact distance bound, in both modes); a cell that
// bound does not cover falls back to bilinear_error.
// `deadline`: checked per kd node and per trim segment tested against a node; throws
// mesh::DeadlineExceeded once it has passed.
constexpr double kTrimMeetMargin = 1e-9;
CellGrid kd_subdivision(const geom::NurbsSurface& surface, const Eigen::AlignedBox2d& box,
                        double tolerance, double boundary_tolerance, double total_tolerance,
                        const std::vector<TrimPolygon>& loops, ErrorMode mode,
                        const RevolutionShape* shape = nullptr, mesh::Deadline* deadline = nullptr);

// The boundary points of every cell (CellGrid::boundary) for cells tiling a box.
std::vector<std::vector<Eigen::Vector2d>> cell_boundaries(const std::vector<Cell>& cells);

}  // namespace trimkit::tess
