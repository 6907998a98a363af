// TrimPolyline: a trim curve (coedge) or a whole trim loop approximated for
// tessellation. Each vertex carries its (u,v) in the face's domain and the 3D
// position the mesh must use for it, so that two faces sharing an edge put their
// boundary vertices at identical 3D points (watertight after welding).
// Guarantee: the 3D polyline through `xyz` is within the trim tolerance of the
// exact curve on the surface, S(c(t)), and stays so when the surface grid adds
// points on its segments (Yang eq. 9-11; Balazs Sec. 5.1).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace trimkit::tess {

struct PolylinePoint {
    Eigen::Vector2d uv;   // in the face's (u,v) domain
    Eigen::Vector3d xyz;  // mesh position (equals S(uv) except on shared edges, where it
                          // is the edge's own point, within the file's edge gap of S(uv))
    double t = 0.0;       // parameter on the coedge's 2D curve
    // The chords to and from this point keep their cell crossings (remove_crossings.h):
    // set where the join welds the face's boundary to another face's by position, and
    // the crossings are points to meet (tessellate_model.cpp, keep_crossings).
    bool keep_crossings = false;
};

// One coedge approximated: points in traversal order, first and last included.
struct TrimPolyline {
    std::vector<PolylinePoint> points;
    int edge = -1;  // Model::edges index when shared, -1 otherwise
};

// A closed trim loop: the coedges' polylines joined, with the duplicate joint
// points removed; the closing segment runs from back() to front().
struct TrimPolygon {
    std::vector<PolylinePoint> points;
    bool outer = false;
};

enum class TrimMethod {
    kBezier3d,  // 3D Bezier lift + line-distance bound + simplification [Balazs] Sec. 4, 5.1
    kYang,      // step length dt = sqrt(eps / (M1 + M2)) [Yang] eq. 9-11
    kParam,     // naive parameter-space chord bound, baseline only (no 3D guarantee)
};

}  // namespace trimkit::tess
