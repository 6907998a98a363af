// Trimming of the kd-tree cell graph [Balazs] Sec. 6: the trim polygons are cut
// into the cells as directed edges, and each cell's kept region is walked as
// closed polygons (region on the left: outer rings counter-clockwise, holes
// clockwise). Cells untouched by trims are kept whole or dropped; a trim loop
// lying inside one cell becomes a polygon of its own (outer) or a hole of the
// cell polygon containing it (connected to that polygon by triangulate_polygon).
// Conventions: a cell is half-open, [u0,u1) x [v0,v1); a trim point on a cell side
// belongs to the cell above/right of it, so no point is on two cells at once.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "mesh/deadline.h"
#include "tess/kd_subdivision.h"
#include "tess/trim_polyline.h"

namespace trimkit::tess {

struct TrimmedVertex {
    Eigen::Vector2d uv;
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero();  // valid only when on_trim
    bool on_trim = false;  // trim vertex or crossing; grid vertices get S(uv) later
    // A trim chord's crossing with a cell side that remove_crossings may take (strictly
    // inside its chord, not a trim point, no keep_crossings at the chord's ends).
    bool crossing = false;
};

struct CellPolygon {
    std::vector<int> outer;               // counter-clockwise in (u,v)
    std::vector<std::vector<int>> holes;  // clockwise, each inside `outer`
    int cell = -1;                        // index into CellGrid::cells
    bool whole_cell = false;              // the untrimmed cell (convex)
};

struct TrimmedCells {
    // Vertices shared by all polygons; equal (u,v) means the same vertex.
    std::vector<TrimmedVertex> vertices;
    std::vector<CellPolygon> polygons;
    // Mesh edges along the trim loops (face boundary), each once.
    std::vector<std::array<int, 2>> trim_edges;
};

// The kept polygons of every cell of `grid` for trim `loops` (closed, outer loops
// counter-clockwise, holes clockwise, all inside grid.box). Crossing points of a
// trim segment with a cell side interpolate the segment's (u,v) and xyz linearly,
// so the face boundary stays on the trim polyline's 3D chords.
// `deadline`: checked per segment a cell tests; throws mesh::DeadlineExceeded.
TrimmedCells trim_cells(const CellGrid& grid, const std::vector<TrimPolygon>& loops,
                        mesh::Deadline* deadline = nullptr);

}  // namespace trimkit::tess
