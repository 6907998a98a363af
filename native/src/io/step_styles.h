// Colours of a STEP file's faces (ISO 10303-46, presentation_appearance_schema):
// a STYLED_ITEM (or OVER_RIDING_STYLED_ITEM) gives its item — a face, a shell or a
// solid — a presentation style whose surface fill colour is a COLOUR_RGB or a
// DRAUGHTING_PRE_DEFINED_COLOUR. A face takes its own colour, else its body's.
#pragma once

#include <map>
#include <unordered_map>

#include "geom/model.h"
#include "io/step_part21.h"

namespace trimkit::io {

// Sets Face::color (indices into model.colors, equal colours sharing one entry) from
// the file's styled items. `faces`: Model::faces index by ADVANCED_FACE name; `bodies`:
// Model::bodies indices by solid or shell instance name. Styles that lead to no colour
// within a few references are ignored.
void apply_step_colors(const StepPart21& file, const std::unordered_map<long long, int>& faces,
                       const std::multimap<long long, int>& bodies, geom::Model& model);

}  // namespace trimkit::io
