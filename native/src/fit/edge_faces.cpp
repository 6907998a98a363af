#include "fit/edge_faces.h"

namespace trimkit::fit {

EdgeFaces edge_faces(const geom::Model& model) {
    EdgeFaces uses(model.edges.size());
    for (int f = 0; f < static_cast<int>(model.faces.size()); ++f)
        for (const geom::Loop& loop : model.faces[f].loops)
            for (const geom::Coedge& c : loop.coedges)
                if (c.edge >= 0 && c.edge < static_cast<int>(uses.size())) uses[c.edge].push_back(f);
    return uses;
}

int neighbour_face(const geom::Model& model, const EdgeFaces& uses, int face, int loop, int coedge) {
    const int e = model.faces[face].loops[loop].coedges[coedge].edge;
    if (e < 0 || e >= static_cast<int>(uses.size()) || uses[e].size() != 2) return -1;
    const int other = uses[e][0] == face ? uses[e][1] : uses[e][0];
    return other == face ? -1 : other;
}

}  // namespace trimkit::fit
