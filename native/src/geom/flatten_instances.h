// A model with its instances applied: every instance's body copied into place
// (surfaces, edges and vertices transformed; trim curves in (u,v) unchanged), for
// consumers that want all geometry in model space (trimkit mesh, check, info).
#pragma once

#include "geom/model.h"

namespace trimkit::geom {

// Without instances the model is returned unchanged. Otherwise the faces of bodies
// no instance names, and the free faces, come first in their order; then each
// instance's copy of its body's faces, one new body per instance (named after the
// instance, or the body). Edges of copied faces are copied per instance.
Model flatten_instances(Model model);

}  // namespace trimkit::geom
