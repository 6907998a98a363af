#include "io/model_summary.h"

#include <set>
#include <sstream>

#include "geom/flatten_instances.h"
#include "io/json_writer.h"

namespace trimkit::io {

ModelSummary summarize(const geom::Model& as_read, const std::string& file) {
    const geom::Model model = geom::flatten_instances(as_read);
    ModelSummary s;
    s.instances = static_cast<int>(as_read.instances.size());
    s.file = file;
    s.units = model.units;
    s.scale_to_metres = model.scale_to_metres;
    s.faces = static_cast<int>(model.faces.size());
    std::set<int> used_edges;
    for (const geom::Face& face : model.faces) {
        ++s.surfaces[face.surface_kind];
        s.loops += static_cast<int>(face.loops.size());
        for (const geom::Loop& loop : face.loops) {
            s.coedges += static_cast<int>(loop.coedges.size());
            for (const geom::Coedge& coedge : loop.coedges)
                if (coedge.edge >= 0) used_edges.insert(coedge.edge);
        }
    }
    s.shared_edges = static_cast<int>(used_edges.size());
    s.bodies = static_cast<int>(model.bodies.size());
    for (const geom::Body& body : model.bodies) s.closed_bodies += body.closed ? 1 : 0;
    s.colors = static_cast<int>(model.colors.size());
    s.warnings = model.warnings;
    s.unread_faces = static_cast<int>(model.unread_faces.size());
    for (size_t i = 0; i < model.faces.size(); ++i)
        for (const std::string& w : model.faces[i].warnings)
            s.warnings.push_back("face " + std::to_string(i) + ": " + w);
    return s;
}

std::string to_json(const ModelSummary& s) {
    std::ostringstream out;
    out << "{\"file\": " << json_string(s.file) << ", \"units\": " << json_string(s.units)
        << ", \"scale_to_metres\": " << json_number(s.scale_to_metres)
        << ", \"faces\": " << s.faces << ", \"unread_faces\": " << s.unread_faces << ", \"surfaces\": {";
    const char* sep = "";
    for (const auto& [kind, count] : s.surfaces) {
        out << sep << json_string(kind) << ": " << count;
        sep = ", ";
    }
    out << "}, \"loops\": " << s.loops << ", \"coedges\": " << s.coedges
        << ", \"shared_edges\": " << s.shared_edges << ", \"bodies\": " << s.bodies
        << ", \"closed_bodies\": " << s.closed_bodies << ", \"instances\": " << s.instances
        << ", \"colors\": " << s.colors
        << ", \"warnings\": [";
    sep = "";
    for (const std::string& w : s.warnings) {
        out << sep << json_string(w);
        sep = ", ";
    }
    out << "]}";
    return out.str();
}

std::string to_text(const ModelSummary& s) {
    std::ostringstream out;
    out << "file:            " << s.file << "\n"
        << "units:           " << s.units << " (1 unit = " << s.scale_to_metres << " m)\n"
        << "faces:           " << s.faces
        << (s.unread_faces > 0 ? " (and " + std::to_string(s.unread_faces) + " the reader left out: see the warnings)"
                               : std::string())
        << "\n"
        << "surfaces:       ";
    for (const auto& [kind, count] : s.surfaces) out << " " << kind << " " << count;
    out << "\n"
        << "loops:           " << s.loops << "\n"
        << "coedges:         " << s.coedges << "\n"
        << "shared edges:    " << s.shared_edges << "\n"
        << "bodies:          " << s.bodies << " (" << s.closed_bodies << " closed)\n"
        << "instances:       " << s.instances << "\n"
        << "colours:         " << s.colors << "\n"
        << "warnings:        " << s.warnings.size() << "\n";
    for (const std::string& w : s.warnings) out << "  " << w << "\n";
    return out.str();
}

}  // namespace trimkit::io
