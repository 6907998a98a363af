// ModelSummary: the counts `trimkit info` prints for a Model (faces, surface
// kinds, loops, coedges, shared edges, bodies, warnings), as a struct and as JSON.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "geom/model.h"

namespace trimkit::io {

struct ModelSummary {
    std::string file;
    std::string units;
    double scale_to_metres = 1.0;
    int faces = 0;
    int unread_faces = 0;  // faces of the file the reader left out (Model::unread_faces)
    std::map<std::string, int> surfaces;  // face count by surface_kind
    int loops = 0;
    int coedges = 0;
    int shared_edges = 0;  // edges used by at least one coedge
    int bodies = 0;
    int closed_bodies = 0;
    int instances = 0;     // placements of bodies in the file (subfigures); 0 without
    int colors = 0;
    std::vector<std::string> warnings;  // model warnings, then "face N: ..." ones
};

// Counts are of the model with its instances applied (every placed face), so they
// agree with what `trimkit mesh` meshes; `instances` tells how many placements.
ModelSummary summarize(const geom::Model& model, const std::string& file);

// One JSON object with the keys of ModelSummary (`file`, `units`,
// `scale_to_metres`, `faces`, `surfaces`, `loops`, `coedges`, `shared_edges`,
// `bodies`, `closed_bodies`, `instances`, `colors`, `warnings`).
std::string to_json(const ModelSummary& summary);

// The same for a person: one "key: value" line per field, warnings indented.
std::string to_text(const ModelSummary& summary);

}  // namespace trimkit::io
