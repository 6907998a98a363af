// Two-sided deviation between a mesh and the exact trimmed faces of a model, the
// measure behind `trimkit check`. Lengths in model units; the mesh is in model
// space (instances not applied); face ids index Model::faces.
//  mesh -> surface: a barycentric grid on every triangle; each sample's distance
//    to the surface of its face (by face id, else the face nearest its triangle's
//    centroid), by Newton projection (SurfaceProjector / foot_point). With uvs and
//    face ids also |P - S(interpolated uv)|, an upper bound.
//  surface -> mesh: a (u,v) grid inside every trimmed face plus its trim polygon
//    points, evaluated in 3D, each against the nearest triangle (TriangleBvh).
//  area of the mesh against the exact trimmed area (trimmed_area), and open edges
//    after welding exactly coincident vertices.
// Projections are onto the untrimmed surface of the face, so a mesh point beyond a
// trim that still lies on the surface's extension counts as on the surface.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "geom/model.h"
#include "mesh/mesh.h"
#include "tess/trim_region.h"

namespace trimkit::tess {

struct DeviationOptions {
    // Subdivisions of each triangle edge: (n+1)(n+2)/2 samples per triangle. The
    // surface grid's spacing is the face's median shortest triangle edge / n.
    int samples = 4;
    int threads = 0;                   // 0 = all cores
    int max_face_samples = 250000;     // surface grid points per face at most
    int area_cells = 24;               // trimmed_area grid cells per direction
    int area_levels = 2;               // trimmed_area sub-row levels of crossed rows
    TrimRegionOptions trim;
};

struct DeviationLocation {
    int face = -1;  // Model::faces index
    Eigen::Vector3d point = Eigen::Vector3d::Zero();  // the sample (model space)
};

struct DirectionDeviation {
    double max = 0.0;
    double mean = 0.0;
    std::size_t samples = 0;
    DeviationLocation worst;
};

struct DeviationReport {
    DirectionDeviation mesh_to_surface;
    // Largest |P - S(interpolated uv)| (>= the projected distance); NaN when the
    // mesh lacks uvs or face ids.
    double mesh_to_surface_max_uv = std::numeric_limits<double>::quiet_NaN();
    DirectionDeviation surface_to_mesh;
    double area_mesh = 0.0;
    double area_exact = 0.0;
    double area_ratio = 0.0;    // area_mesh / area_exact (NaN if area_exact is 0)
    std::size_t open_edges = 0; // boundary edges after welding coincident vertices
    int faces = 0;              // faces in the model
    std::size_t triangles = 0;
    // Per model face: max mesh->surface distance of its triangles (NaN if none),
    // max surface->mesh distance of its samples, and its exact area.
    std::vector<double> face_mesh_to_surface;
    std::vector<double> face_surface_to_mesh;
    std::vector<double> face_area_exact;
    std::vector<std::string> warnings;  // faces that could not be sampled, and why
};

// Throws geom::InvalidInput for an invalid mesh (mesh::validate), a mesh without
// triangles, a face id >= the model's face count, or options out of range
// (samples < 1, threads < 0, max_face_samples < 4, area_cells < 1, area_levels < 0).
DeviationReport measure_deviation(const geom::Model& model, const mesh::Mesh& mesh,
                                  const DeviationOptions& options = {});

}  // namespace trimkit::tess
