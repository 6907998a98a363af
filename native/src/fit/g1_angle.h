// The G1 check of a rebuilt face ([Muraki] Sec. 5, Fig. 15): the largest angle
// between its surface's normal and its neighbour's along every coedge a rule marks
// G1, at kG1CheckSamples points of each edge (both normals at the point's
// projection, compared up to sign). compress_model accepts a fit only when this
// is at most kMaxG1Angle.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "fit/edge_faces.h"
#include "fit/fit_rule.h"
#include "geom/model.h"

namespace trimkit::fit {

constexpr int kG1CheckSamples = 50;
constexpr double kMaxG1Angle = 0.5;  // degrees

// One sample of the check: the edge point, the rebuilt surface's unit normal at its
// projection, the neighbour's, and the angle between them (degrees, up to sign).
struct G1Sample {
    int loop = 0, coedge = 0;
    Eigen::Vector3d point, normal, neighbour_normal;
    double angle = 0;
};

// Every sample of the check, loop by loop, coedge by coedge (the paper's Fig. 15 draws
// these normals).
std::vector<G1Sample> g1_samples(const geom::Model& model, const EdgeFaces& uses, int face, const FitRule& rule,
                                 const geom::NurbsSurface& surface);

// Degrees, the largest angle of g1_samples; 0 when the rule marks no coedge G1.
double g1_angle(const geom::Model& model, const EdgeFaces& uses, int face, const FitRule& rule,
                const geom::NurbsSurface& surface);

}  // namespace trimkit::fit
