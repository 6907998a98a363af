// FitRule: what a compressed face keeps instead of its surface, the "prediction
// function" of [Muraki] Sec. 2-3: the method and the parameters that, with the
// face's boundary edges and its G1 neighbours' surfaces, rebuild the surface
// (refit_face). Everything else is derived from the edges, so compression and
// extension compute the same surface from the same bytes.
#pragma once

#include <vector>

namespace trimkit::fit {

enum class FitMethod : int {
    kBoundaryG1 = 1,  // [Muraki] Sec. 4: boundary curves, tangent-plane samples, G1 rows
    kCoons = 2,       // [Muraki] Sec. 3's surface interpolation for four-sided faces (coons_fill)
};

struct FitRule {
    FitMethod method = FitMethod::kBoundaryG1;
    int degree_u = 3, degree_v = 3;
    int count_u = 4, count_v = 4;
    bool boundary_curves = true;  // fix the four boundary rows (Sec. 4.1) or leave them free
    double tolerance = 0;         // model units; the accuracy of the parameter curves rebuilt on extension
    bool reversed = false;        // the rebuilt face's normal is -(S_u x S_v) (Face::reversed)
    // Per loop, per coedge: G1 to the face across the coedge's edge (Sec. 4.1, Fig. 8 a).
    std::vector<std::vector<bool>> g1;
};

}  // namespace trimkit::fit
