// read_brep for builds without Open CASCADE (TRIMKIT_WITH_OCCT off): always refuses.
#include "io/read_brep.h"

#include "geom/error.h"

namespace trimkit::io {

geom::Model read_brep(const std::string& path, const ReadOptions&) {
    throw geom::ReadError(path, 0, ".brep import needs trimkit built with Open CASCADE");
}

}  // namespace trimkit::io
