// Verification of one face's mesh before tessellate_model accepts it (DESIGN.md,
// tessellation pipeline step 8), against measures of the exact trimmed face that
// do not come from the mesh or from the polygons it was meshed from:
//  area: the mesh's area against trimmed_area over the face's own trim curves
//    (TrimRegion, the integrator behind `trimkit check`);
//  boundary: points on each trim loop's 3D curve S(c(t)) against the mesh's
//    boundary edges, and each boundary vertex of the mesh against the loops' curves.
// Lengths in model units; T is the tessellation tolerance. Loops and coedges are
// numbered as in geom::Face, from 0.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "geom/face.h"
#include "mesh/mesh.h"
#include "tess/trim_polyline.h"
#include "tess/trim_region.h"

namespace trimkit::tess {

// Why a face's mesh was rejected.
enum class FaceDefect {
    kNone,
    kArea,          // the mesh's area is off the exact trimmed area by more than area_bound
    kLoopGap,       // a trim loop's curve lies farther than boundary_bound from the mesh boundary
    kBoundaryGap,   // a mesh boundary vertex lies farther than boundary_bound from every loop
    kNoBoundary,    // the mesh has triangles but no boundary edge to follow the loops
};

struct FaceVerification {
    FaceDefect defect = FaceDefect::kNone;
    bool passed() const { return defect == FaceDefect::kNone; }
    // "face 12: mesh area 1.504x the exact trimmed area (812.3 vs 540.1, allowed +/- 3.2)";
    // empty when passed.
    std::string reason;

    double area_mesh = 0.0;    // sum of the triangles' areas
    double area_exact = 0.0;   // trimmed_area over the face's trim curves (the fine one if measured)
    double area_bound = 0.0;   // allowed |area_mesh - area_exact| (verify_face.cpp derives it)
    double perimeter = 0.0;    // 3D length of the trim loops' curves
    // Largest distance from a sampled point of a trim loop's curve to the mesh boundary,
    // and the loop it lies on (-1 if none was sampled).
    double loop_gap = 0.0;
    int loop_gap_loop = -1;
    // Curve points off the mesh boundary that bound no area (a loop running back
    // along itself, a lobe repair_trim_loop drops as a sliver): not counted in loop_gap.
    int lobe_samples = 0;
    // Largest distance from a mesh boundary vertex to the trim loops' curves.
    double boundary_gap = 0.0;
    double boundary_bound = 0.0;  // allowed loop_gap and boundary_gap
    // Largest |xyz - S(uv)| of the meshed polygons' points: how far the mesh boundary
    // may sit off the surface by design (a shared edge's own points, within the file's
    // edge gap), added to both bounds.
    double edge_gap = 0.0;
};

// The exact area is measured twice at most: first coarsely, and when the mesh's area
// is off that by more than recheck_share of the bound, again as `trimkit check`
// measures it (measure_deviation's defaults), and the face is judged on that one. On
// the 29 IGES and 14 STEP files of ../shared/data/cad, at a tolerance of 1e-3 of the
// model, the coarse area is within 0.29 L·T of the fine one (L·T: the bound's main
// term, verify_face.cpp; 1.2 L·T with 4 cells or no sub-rows), so no mesh
// off by more than the bound passes the coarse filter; it costs a tenth of the fine
// one, which costs more than meshing the face.
struct VerifyFaceOptions {
    // Points per Bézier span of each trim curve: 32, or fewer (down to 4) on faces
    // whose trims have more than coarse_points / 32 spans, for coarse_points in all
    // (occ22470.igs has 1000 spans per face; the same figures, a fifth of the cost).
    TrimRegionOptions coarse_trim{32};
    int coarse_points = 1024;
    int coarse_cells = 5;               // trimmed_area grid cells per direction
    int coarse_levels = 1;              // trimmed_area sub-row levels of crossed rows
    TrimRegionOptions trim{};           // the fine measure: 256 points per span
    int area_cells = 24;
    int area_levels = 2;
    double recheck_share = 0.5;
};

// A point S(c(t)) of a trim curve.
struct CurveSample {
    double t = 0.0;
    Eigen::Vector3d xyz;
};

// What verify_face measures of the exact trimmed face alone, not of a mesh: the trim
// loops' curves sampled in 3D (refined to kChordShare of T, so it depends on T) and
// their length, and the exact trimmed area, coarse, and fine once a mesh needs it. A
// face meshed again (tessellate_model's area rounds) is verified against the same
// reference. Used by one thread at a time (the fine measures are filled in lazily).
struct FaceReference {
    double tolerance = 0.0;
    std::vector<std::vector<std::vector<CurveSample>>> samples;  // per loop, per coedge
    mesh::Mesh curves;           // the samples' chords, as degenerate triangles (a, b, b)
    double perimeter = 0.0;      // the chords' 3D length
    Eigen::AlignedBox3d extent;  // of the samples
    double area_coarse = 0.0;    // trimmed_area with the coarse options
    std::optional<double> area_fine;
    std::optional<TrimRegion> fine_region;  // with options.trim
};

// The reference of `face` at tolerance T (> 0 and finite, else geom::InvalidInput).
FaceReference face_reference(const geom::Face& face, double tolerance, const VerifyFaceOptions& options = {});

// Checks `face_mesh` against `reference` (face_reference of the same face and options).
FaceVerification verify_face(const geom::Face& face, FaceReference& reference, const mesh::Mesh& face_mesh,
                             const std::vector<TrimPolygon>& loops, int face_id,
                             const VerifyFaceOptions& options = {});

// Checks `face_mesh` (the mesh of `face` alone, with normals, as tessellate_face
// returns it and the face's weld leaves it) against the exact trimmed face. `loops`:
// the polygons it was meshed from, used only for the edge gap they carry by design.
// `tolerance` > 0 is T. `face_id` names the face in the reason. Throws
// geom::InvalidInput when the face has no trim loop with 3 or more points, or
// tolerance is not > 0.
FaceVerification verify_face(const geom::Face& face, const mesh::Mesh& face_mesh,
                             const std::vector<TrimPolygon>& loops, double tolerance, int face_id,
                             const VerifyFaceOptions& options = {});

}  // namespace trimkit::tess
