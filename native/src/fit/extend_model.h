// Extension ([Muraki] Sec. 3, Fig. 4): the surfaces of compressed faces rebuilt
// from their boundary edges and rules (refit_face, with the same inputs as at
// compression, so the same surface), and their parameter curves made by
// projecting the 3D edges onto it (geom::project_curve_adaptive). Faces that kept
// their surface are returned unchanged.
#pragma once

#include "fit/fit_rule.h"
#include "geom/model.h"

namespace trimkit::fit {

// Precision of the rebuilt parameter curves, as a fraction of the rule's tolerance.
constexpr double kParameterCurveTolerance = 0.05;

// Throws geom::InvalidInput if a rule's G1 neighbour is itself compressed or a
// coedge has no 3D edge; geom::NumericalFailure if a fit is degenerate.
struct CompressedModel;
geom::Model extend_model(const CompressedModel& compressed);

// One face: its rebuilt surface, loops with projected parameter curves and orientation.
geom::Face extend_face(const geom::Model& model, int face, const FitRule& rule);

}  // namespace trimkit::fit
