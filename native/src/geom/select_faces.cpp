#include "geom/select_faces.h"

#include <string>

#include "geom/error.h"

namespace trimkit::geom {

Model select_faces(const Model& model, const std::vector<int>& faces) {
    Model out;
    out.units = model.units;
    out.scale_to_metres = model.scale_to_metres;
    out.edges = model.edges;
    out.colors = model.colors;
    out.warnings = model.warnings;
    out.unread_faces = model.unread_faces;
    std::vector<char> taken(model.faces.size(), 0);
    for (int f : faces) {
        if (f < 0 || f >= static_cast<int>(model.faces.size()))
            throw InvalidInput("select_faces: face " + std::to_string(f) + " of " +
                               std::to_string(model.faces.size()));
        if (taken[f]) throw InvalidInput("select_faces: face " + std::to_string(f) + " listed twice");
        taken[f] = 1;
        out.free_faces.push_back(static_cast<int>(out.faces.size()));
        out.faces.push_back(model.faces[f]);
    }
    return out;
}

}  // namespace trimkit::geom
