#include "tbp/tbp_solid.h"

#include "geom/error.h"

namespace trimkit::tbp {

void validate(const TbpSolid& solid) {
    if (solid.patches.empty()) throw geom::InvalidInput("TbpSolid: no patches");
    for (std::size_t p = 1; p < solid.patches.size(); ++p)
        if (solid.patches[p].degree() != solid.patches[0].degree())
            throw geom::InvalidInput("TbpSolid: patch " + std::to_string(p) + " has degree " +
                                     std::to_string(solid.patches[p].degree()) + ", patch 0 has " +
                                     std::to_string(solid.patches[0].degree()));
}

}  // namespace trimkit::tbp
