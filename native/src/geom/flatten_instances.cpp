#include "geom/flatten_instances.h"

#include <map>

namespace trimkit::geom {
namespace {

// Appends `face` (of `from`) to `to`, placed by T; its edges are copied once per
// call site through `edge_copy` (old index -> new index).
void append_face(const Model& from, const Face& face, const Eigen::Affine3d& T, Model& to,
                 std::map<int, int>& edge_copy) {
    Face copy = face;
    copy.surface = face.surface.transformed(T);
    for (Loop& loop : copy.loops)
        for (Coedge& coedge : loop.coedges) {
            if (coedge.edge < 0 || coedge.edge >= static_cast<int>(from.edges.size())) continue;
            auto it = edge_copy.find(coedge.edge);
            if (it == edge_copy.end()) {
                Edge e = from.edges[coedge.edge];
                if (e.curve) e.curve = e.curve->transformed(T);
                if (e.start) e.start = T * *e.start;
                if (e.end) e.end = T * *e.end;
                it = edge_copy.emplace(coedge.edge, static_cast<int>(to.edges.size())).first;
                to.edges.push_back(std::move(e));
            }
            coedge.edge = it->second;
        }
    to.faces.push_back(std::move(copy));
}

}  // namespace

Model flatten_instances(Model model) {
    if (model.instances.empty()) return model;
    std::vector<char> instanced(model.bodies.size(), 0);
    for (const Instance& instance : model.instances)
        if (instance.body >= 0 && instance.body < static_cast<int>(model.bodies.size())) instanced[instance.body] = 1;
    std::vector<char> in_instanced(model.faces.size(), 0);
    for (std::size_t b = 0; b < model.bodies.size(); ++b)
        if (instanced[b])
            for (int f : model.bodies[b].faces) in_instanced[f] = 1;

    Model flat;
    flat.units = model.units;
    flat.scale_to_metres = model.scale_to_metres;
    flat.colors = model.colors;
    flat.warnings = model.warnings;
    flat.unread_faces = model.unread_faces;
    // Faces in place, each edge kept once.
    std::map<int, int> kept_edges;
    std::vector<int> new_index(model.faces.size(), -1);
    for (std::size_t f = 0; f < model.faces.size(); ++f) {
        if (in_instanced[f]) continue;
        new_index[f] = static_cast<int>(flat.faces.size());
        append_face(model, model.faces[f], Eigen::Affine3d::Identity(), flat, kept_edges);
    }
    for (std::size_t b = 0; b < model.bodies.size(); ++b) {
        if (instanced[b]) continue;
        Body body = model.bodies[b];
        for (int& f : body.faces) f = new_index[f];
        flat.bodies.push_back(std::move(body));
    }
    for (const Instance& instance : model.instances) {
        if (instance.body < 0 || instance.body >= static_cast<int>(model.bodies.size())) continue;
        const Body& source = model.bodies[instance.body];
        Body body;
        body.name = instance.name.empty() ? source.name : instance.name;
        body.closed = source.closed;
        std::map<int, int> edges;  // shared edges stay shared within the copy
        for (int f : source.faces) {
            body.faces.push_back(static_cast<int>(flat.faces.size()));
            append_face(model, model.faces[f], instance.transform, flat, edges);
        }
        flat.bodies.push_back(std::move(body));
    }
    std::vector<char> in_body(flat.faces.size(), 0);
    for (const Body& b : flat.bodies)
        for (int f : b.faces) in_body[f] = 1;
    for (std::size_t f = 0; f < flat.faces.size(); ++f)
        if (!in_body[f]) flat.free_faces.push_back(static_cast<int>(f));
    return flat;
}

}  // namespace trimkit::geom
