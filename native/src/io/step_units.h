// The units of a STEP file's geometry (ISO 10303-41 Sec. 19, measure_schema): the
// length and plane-angle units of its GLOBAL_UNIT_ASSIGNED_CONTEXT, as SI_UNIT with a
// prefix (.MILLI. .METRE.) or a CONVERSION_BASED_UNIT ('INCH', 'DEGREE') defined by a
// measure with unit. Read from the parsed file (io/step_part21.h).
#pragma once

#include <string>

#include "io/step_part21.h"

namespace trimkit::io {

struct StepUnits {
    double metres_per_length = 1e-3;  // one length unit of the file in metres
    double radians_per_angle = 1.0;   // one plane-angle unit of the file in radians
    std::string length_name = "mm";   // "mm", "m", "in", "cm", ... ("mm" when absent)
};

// The units every representation context of the file assigns. Throws
// UnsupportedStepEntity (step_geometry.h) when contexts disagree (one reading would
// scale some parts wrongly) or a unit is not understood; files without units get
// millimetres and radians (AP214's defaults in practice).
StepUnits step_units(const StepPart21& file);

}  // namespace trimkit::io
