// Reading STEP (AP203/AP214/AP242) files into a geom::Model through Open CASCADE.
// Only available when trimkit is built with OCCT (CMake option TRIMKIT_WITH_OCCT);
// otherwise read_step throws and step_supported() is false. Every surface and
// pcurve is converted to a B-spline by OCCT (BRepBuilderAPI_NurbsConvert); faces are
// listed once per placement with the placement applied. Lengths are in millimetres
// (OCCT's default xstep.cad.unit): Model::units "mm", scale_to_metres 1e-3.
#pragma once

#include <string>

#include "geom/model.h"

namespace trimkit::io {

// Reads the file at `path`. Throws geom::ReadError ("FILE: reason") when OCCT
// cannot read the file, transfers no shape, or no face converts; or always when
// trimkit was built without OCCT. Faces that fail conversion are skipped with a
// message in Model::warnings ("face 12: ...").
geom::Model read_step(const std::string& path);

// True when this build of trimkit can read STEP (it was built with OCCT).
bool step_supported();

}  // namespace trimkit::io
