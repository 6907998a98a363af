#include "fit/extend_model.h"

#include <string>

#include "fit/compress_model.h"
#include "fit/edge_faces.h"
#include "fit/refit_face.h"
#include "geom/error.h"
#include "geom/project_curve_adaptive.h"
#include "geom/surface_projector.h"

namespace trimkit::fit {

geom::Face extend_face(const geom::Model& model, int face, const FitRule& rule) {
    const EdgeFaces uses = edge_faces(model);
    geom::Face out = model.faces[face];
    out.surface = refit_face(model, uses, face, rule).surface;
    out.reversed = rule.reversed;
    out.surface_kind = "bspline";
    const geom::SurfaceProjector projector(out.surface);
    for (geom::Loop& loop : out.loops)
        for (geom::Coedge& c : loop.coedges) {
            const geom::NurbsCurve3d& edge = *model.edges[c.edge].curve;  // refit_face checked it exists
            const geom::NurbsCurve3d curve = c.edge_reversed ? edge.reversed() : edge;
            c.curve = geom::project_curve_adaptive(projector, curve, kParameterCurveTolerance * rule.tolerance);
        }
    return out;
}

geom::Model extend_model(const CompressedModel& compressed) {
    geom::Model model = compressed.model;
    if (compressed.rules.size() != model.faces.size())
        throw geom::InvalidInput("extend_model: " + std::to_string(compressed.rules.size()) + " rules for " +
                                 std::to_string(model.faces.size()) + " faces");
    const EdgeFaces uses = edge_faces(compressed.model);
    for (int f = 0; f < static_cast<int>(model.faces.size()); ++f) {
        if (!compressed.rules[f]) continue;
        const FitRule& rule = *compressed.rules[f];
        for (std::size_t l = 0; l < rule.g1.size(); ++l)
            for (std::size_t c = 0; c < rule.g1[l].size(); ++c) {
                if (!rule.g1[l][c]) continue;
                const int n = neighbour_face(compressed.model, uses, f, static_cast<int>(l), static_cast<int>(c));
                if (n < 0 || compressed.rules[n])
                    throw geom::InvalidInput("extend_model: face " + std::to_string(f) + " is G1 to face " +
                                             std::to_string(n) + ", which has no surface");
            }
        model.faces[f] = extend_face(compressed.model, f, rule);
    }
    return model;
}

}  // namespace trimkit::fit
