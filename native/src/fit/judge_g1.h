// G1 judgement per shared edge ([Muraki] Sec. 4.1, Fig. 8 a): a coedge is G1 when
// the normals of its face and of the face across its edge coincide along the
// edge: at kG1JudgeSamples points of the edge curve, each projected on both
// surfaces, the angle between the normals (up to sign: files orient faces
// inconsistently) stays below kG1JudgeAngle.
#pragma once

#include <vector>

#include "fit/edge_faces.h"
#include "geom/model.h"

namespace trimkit::fit {

constexpr int kG1JudgeSamples = 9;
// 1 degree: CAD G1 joints agree to far less (file rounding), real creases differ by more.
constexpr double kG1JudgeAngle = 1.0 * 3.14159265358979323846 / 180.0;

// A face being rebuilt because its surface is damaged is judged more loosely: its
// normals are only roughly right, and real creases are far sharper than this.
constexpr double kRebuildG1JudgeAngle = 10.0 * 3.14159265358979323846 / 180.0;

// Per loop, per coedge of model.faces[face]; `angle` in radians.
std::vector<std::vector<bool>> judge_g1(const geom::Model& model, const EdgeFaces& uses, int face,
                                        double angle = kG1JudgeAngle);

}  // namespace trimkit::fit
