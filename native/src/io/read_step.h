// Reading STEP (AP203/AP214/AP242) files into a geom::Model through Open CASCADE.
// Only available when trimkit is built with OCCT (CMake option TRIMKIT_WITH_OCCT);
// otherwise read_step throws and step_supported() is false. Every surface and
// pcurve is converted to a B-spline by OCCT (BRepBuilderAPI_NurbsConvert); faces are
// listed once per placement with the placement applied. Lengths are in millimetres
// (OCCT's default xstep.cad.unit): Model::units "mm", scale_to_metres 1e-3.
#pragma once

#include <string>

#include "geom/model.h"
#include "io/read_options.h"

namespace trimkit::io {

// Reads the file at `path`. Throws geom::ReadError ("FILE: reason") when OCCT
// cannot read the file, transfers no shape, or no face converts; or always when
// trimkit was built without OCCT. Faces that fail conversion are skipped with a
// message in Model::warnings ("face 12: ...").
// `options`: the transfer (with OCCT's shape healing) runs under an OCCT progress
// indicator whose UserBreak stops it on the timeout or the cancel flag; both are
// checked again after parsing and between faces (ReadStopped). Progress: parsing
// (no steps of its own) up to 0.3, the transfer up to 0.85, the translation to 1.
// options.step_reader chooses who reads (read_options.h); kAuto notes in
// Model::warnings why a file went to OCCT ("read through Open CASCADE: ...").
geom::Model read_step(const std::string& path, const ReadOptions& options = {});

// The file read by trimkit's own reader (io/read_step_native.h) under `options`' limits.
// Throws UnsupportedStepEntity (io/step_geometry.h) for files it does not take on.
geom::Model read_step_own(const std::string& path, const ReadOptions& options = {});

// The file read through Open CASCADE (with its healing); builds with OCCT only.
geom::Model read_step_occt(const std::string& path, const ReadOptions& options = {});

// True when this build of trimkit can read STEP (it was built with OCCT).
bool step_supported();

}  // namespace trimkit::io
