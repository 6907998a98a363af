// Reading Open CASCADE's native .brep files into a geom::Model (BRepTools::Read),
// translated (and its faces healed by ShapeFix_Face) as STEP parts are (occt_shape.h). Only
// with TRIMKIT_WITH_OCCT; otherwise read_brep throws. Lengths are the file's own,
// taken as millimetres (the format stores no unit).
#pragma once

#include <string>

#include "geom/model.h"
#include "io/read_options.h"

namespace trimkit::io {

// Throws geom::ReadError ("FILE: reason") when OCCT cannot read the file or it
// holds no face that converts. Faces that fail are skipped with a warning.
// `options`: BRepTools::Read runs under an OCCT progress indicator (timeout, cancel,
// progress up to 0.5); the translation checks them between faces (ReadStopped).
geom::Model read_brep(const std::string& path, const ReadOptions& options = {});

}  // namespace trimkit::io
