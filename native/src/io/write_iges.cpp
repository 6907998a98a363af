#include "io/write_iges.h"

#include <cstdio>
#include <filesystem>

#include "geom/error.h"
#include "io/output_file.h"

namespace trimkit::io {
namespace {

std::string real(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17G", x);
    std::string s = buf;
    if (s.find_first_of(".EN") == std::string::npos) s += ".";
    return s;
}

std::string hollerith(const std::string& s) { return std::to_string(s.size()) + "H" + s; }

// Entities in directory order; each has its parameter tokens (without delimiters).
struct Entity {
    int type = 0, form = 0;
    bool subordinate = true;
    std::vector<std::string> params;
};

class IgesBuilder {
public:
    int add(Entity e) {
        entities_.push_back(std::move(e));
        return 2 * static_cast<int>(entities_.size()) - 1;  // its D sequence number
    }
    template <int Dim>
    int curve(const geom::NurbsCurve<Dim>& c);
    int surface(const geom::NurbsSurface& s);
    int composite(const std::vector<int>& pieces);
    std::string text(const geom::Model& m, const std::string& name) const;

private:
    std::vector<Entity> entities_;
};

template <int Dim>
int IgesBuilder::curve(const geom::NurbsCurve<Dim>& c) {
    const auto point = [](const typename geom::NurbsCurve<Dim>::Point& p, int k) { return k < Dim ? p[k] : 0.0; };
    if (c.degree() == 1 && c.points().size() == 2 && !c.is_rational()) {
        Entity line{110, 0, true, {"110"}};
        for (const auto& p : c.points())
            for (int k = 0; k < 3; ++k) line.params.push_back(real(point(p, k)));
        return add(line);
    }
    const int K = static_cast<int>(c.points().size()) - 1;
    Entity e{126, 0, true, {"126", std::to_string(K), std::to_string(c.degree()), Dim == 2 ? "1" : "0", "0",
                            c.is_rational() ? "0" : "1", "0"}};
    for (double u : c.knots()) e.params.push_back(real(u));
    for (int i = 0; i <= K; ++i) e.params.push_back(real(c.weights().empty() ? 1.0 : c.weights()[i]));
    for (const auto& p : c.points())
        for (int k = 0; k < 3; ++k) e.params.push_back(real(point(p, k)));
    e.params.push_back(real(c.domain().first));
    e.params.push_back(real(c.domain().second));
    for (const char* n : {"0.", "0.", "1."}) e.params.push_back(n);
    return add(e);
}

int IgesBuilder::surface(const geom::NurbsSurface& s) {
    Entity e{128, 0, true, {"128", std::to_string(s.count_u() - 1), std::to_string(s.count_v() - 1),
                            std::to_string(s.degree_u()), std::to_string(s.degree_v()), "0", "0",
                            s.is_rational() ? "0" : "1", "0", "0"}};
    for (double u : s.knots_u()) e.params.push_back(real(u));
    for (double v : s.knots_v()) e.params.push_back(real(v));
    // [IGES] 4.24: weights and points with the first (u) index varying fastest.
    for (int j = 0; j < s.count_v(); ++j)
        for (int i = 0; i < s.count_u(); ++i) e.params.push_back(real(s.weight(i, j)));
    for (int j = 0; j < s.count_v(); ++j)
        for (int i = 0; i < s.count_u(); ++i)
            for (int k = 0; k < 3; ++k) e.params.push_back(real(s.point(i, j)[k]));
    for (double x : {s.domain_u().first, s.domain_u().second, s.domain_v().first, s.domain_v().second})
        e.params.push_back(real(x));
    return add(e);
}

int IgesBuilder::composite(const std::vector<int>& pieces) {
    Entity e{102, 0, true, {"102", std::to_string(pieces.size())}};
    for (int d : pieces) e.params.push_back(std::to_string(d));
    return add(e);
}

std::string field8(const std::string& s) { return std::string(s.size() < 8 ? 8 - s.size() : 0, ' ') + s; }

std::string record(const std::string& data, char section, int seq) {
    std::string line = data.substr(0, 72);
    line.resize(72, ' ');
    char buf[16];
    std::snprintf(buf, sizeof buf, "%c%7d", section, seq);
    return line + buf + "\n";
}

// Free-format parameters packed into 64 columns without splitting a token.
std::vector<std::string> parameter_lines(const std::vector<std::string>& params) {
    std::vector<std::string> lines(1);
    for (std::size_t k = 0; k < params.size(); ++k) {
        const std::string token = params[k] + (k + 1 < params.size() ? "," : ";");
        if (lines.back().size() + token.size() > 64 && !lines.back().empty()) lines.emplace_back();
        lines.back() += token;  // a token longer than 64 (never: 17-digit reals) would overflow
    }
    return lines;
}

std::pair<int, std::string> units_of(const geom::Model& m) {
    if (m.units == "in") return {1, "INCH"};
    if (m.units == "mm") return {2, "MM"};
    if (m.units == "ft") return {4, "FT"};
    if (m.units == "m") return {6, "M"};
    if (m.units == "cm") return {10, "CM"};
    if (m.units == "um") return {9, "UM"};
    return {2, "MM"};
}

std::string IgesBuilder::text(const geom::Model& m, const std::string& name) const {
    std::string out;
    out += record("trimkit IGES writer", 'S', 1);
    const auto [flag, unit] = units_of(m);
    const std::vector<std::string> global = {
        "1H,", "1H;", hollerith("trimkit"), hollerith(name), hollerith("trimkit"), hollerith("trimkit 0.1"), "32", "38",
        "6", "308", "15", hollerith("trimkit"), "1.", std::to_string(flag), hollerith(unit), "1", "0.01",
        hollerith("20260101.000000"), "1E-09", "0.", hollerith("trimkit"), hollerith("trimkit"), "11", "0",
        hollerith("20260101.000000")};  // [IGES] Table 3: 25 fields, the last change date last
    std::string gtext;
    for (std::size_t k = 0; k < global.size(); ++k) gtext += global[k] + (k + 1 < global.size() ? "," : ";");
    int g = 0;
    for (std::size_t i = 0; i < gtext.size(); i += 72) out += record(gtext.substr(i, 72), 'G', ++g);
    std::string directory, parameters;
    int p = 0;
    for (std::size_t i = 0; i < entities_.size(); ++i) {
        const Entity& e = entities_[i];
        const int de = 2 * static_cast<int>(i) + 1;
        const std::vector<std::string> lines = parameter_lines(e.params);
        const int first = p + 1;
        for (const std::string& l : lines) {
            std::string data = l;
            data.resize(64, ' ');
            parameters += record(data + field8(std::to_string(de)), 'P', ++p);
        }
        const std::string type = field8(std::to_string(e.type));
        directory += record(type + field8(std::to_string(first)) + field8("0") + field8("0") + field8("0") +
                                field8("0") + field8("0") + field8("0") + (e.subordinate ? "00010000" : "00000000"),
                            'D', de);
        directory += record(type + field8("0") + field8("0") + field8(std::to_string(lines.size())) +
                                field8(std::to_string(e.form)) + field8("") + field8("") + field8("") + field8("0"),
                            'D', de + 1);
    }
    out += directory + parameters;
    char t[80];
    std::snprintf(t, sizeof t, "S%7dG%7dD%7dP%7d", 1, g, static_cast<int>(2 * entities_.size()), p);
    return out + record(t, 'T', 1);
}

// A free face: 144 on its 128, one 142 per loop (parameter and model curves as 102s).
void trimmed_face(IgesBuilder& b, const geom::Model& m, const geom::Face& face) {
    const int surface = b.surface(face.surface);
    std::vector<int> boundaries;
    int outer = -1;
    for (const geom::Loop& loop : face.loops) {
        std::vector<int> params, models;
        bool all_models = true;
        for (const geom::Coedge& c : loop.coedges) {
            params.push_back(b.curve(c.curve));
            const bool has = c.edge >= 0 && c.edge < static_cast<int>(m.edges.size()) && m.edges[c.edge].curve;
            if (!has) { all_models = false; continue; }
            const geom::NurbsCurve3d& e = *m.edges[c.edge].curve;
            models.push_back(b.curve(c.edge_reversed ? e.reversed() : e));
        }
        const int pc = b.composite(params);
        const int mc = all_models ? b.composite(models) : 0;
        const int de = b.add({142, 0, true, {"142", "0", std::to_string(surface), std::to_string(pc), std::to_string(mc), "1"}});
        if (loop.outer && outer < 0) outer = de;
        else boundaries.push_back(de);
    }
    if (outer < 0 && !boundaries.empty()) outer = boundaries.front(), boundaries.erase(boundaries.begin());
    Entity trimmed{144, 0, false, {"144", std::to_string(surface), "1", std::to_string(boundaries.size()), std::to_string(outer)}};
    for (int d : boundaries) trimmed.params.push_back(std::to_string(d));
    b.add(trimmed);
}

// Every coedge of the body's faces on an edge with a 3D curve: it can be a B-rep.
bool has_topology(const geom::Model& m, const geom::Body& body) {
    for (int f : body.faces)
        for (const geom::Loop& loop : m.faces[f].loops)
            for (const geom::Coedge& c : loop.coedges)
                if (c.edge < 0 || c.edge >= static_cast<int>(m.edges.size()) || !m.edges[c.edge].curve) return false;
    return !body.faces.empty();
}

// One body as [IGES] 4.140-4.150: a 502 vertex list (two per edge: its curve's ends),
// a 504 edge list of the body's edges, per face a 510 of 508 loops
// (each edge with its parameter curve), a 514 shell, and a 186 solid when closed.
// has_topology(m, body) must hold.
void brep_body(IgesBuilder& b, const geom::Model& m, const geom::Body& body) {
    std::vector<int> edges(m.edges.size(), 0);  // model edge -> 1-based index in the 504, 0: not in the body
    for (int f : body.faces)
        for (const geom::Loop& loop : m.faces[f].loops)
            for (const geom::Coedge& c : loop.coedges) edges[c.edge] = -1;
    std::vector<int> curves;
    Entity vertices{502, 1, true, {"502", "0"}};
    int count = 0;
    for (std::size_t e = 0; e < m.edges.size(); ++e) {
        if (edges[e] == 0) continue;
        edges[e] = ++count;
        curves.push_back(b.curve(*m.edges[e].curve));
        for (const Eigen::Vector3d& p : {m.edges[e].curve->points().front(), m.edges[e].curve->points().back()})
            for (int k = 0; k < 3; ++k) vertices.params.push_back(real(p[k]));
    }
    vertices.params[1] = std::to_string(2 * count);
    const int vl = b.add(vertices);
    Entity list{504, 1, true, {"504", std::to_string(count)}};
    for (int k = 0; k < count; ++k)
        for (const int x : {curves[k], vl, 2 * k + 1, vl, 2 * k + 2}) list.params.push_back(std::to_string(x));
    const int el = b.add(list);
    Entity shell{514, body.closed ? 1 : 2, body.closed, {"514", std::to_string(body.faces.size())}};
    for (int f : body.faces) {
        const geom::Face& face = m.faces[f];
        const int surface = b.surface(face.surface);
        std::vector<const geom::Loop*> loops;  // the outer loop first (510's outer flag 1)
        for (const geom::Loop& loop : face.loops) if (loop.outer) loops.insert(loops.begin(), &loop); else loops.push_back(&loop);
        Entity f510{510, 1, true, {"510", std::to_string(surface), std::to_string(loops.size()), "1"}};
        for (const geom::Loop* loop : loops) {
            Entity l508{508, 1, true, {"508", std::to_string(loop->coedges.size())}};
            for (const geom::Coedge& c : loop->coedges)
                for (const std::string& x : {std::string("0"), std::to_string(el), std::to_string(edges[c.edge]),
                                             std::string(c.edge_reversed ? "0" : "1"), std::string("1"), std::string("0"),
                                             std::to_string(b.curve(c.curve))})
                    l508.params.push_back(x);
            f510.params.push_back(std::to_string(b.add(l508)));
        }
        shell.params.push_back(std::to_string(b.add(f510)));
        shell.params.push_back(face.reversed ? "0" : "1");
    }
    const int s514 = b.add(shell);
    if (body.closed) b.add({186, 0, false, {"186", std::to_string(s514), "1", "0"}});
}

}  // namespace

// Our reader (and OCCT's) numbers faces in the order of the root entities and of
// each shell's faces; writing entities in face order keeps a model's face indices
// (what `check A B` pairs) when each B-rep body is one run of consecutive faces.
bool consecutive(const geom::Body& body) {
    for (std::size_t k = 0; k < body.faces.size(); ++k)
        if (body.faces[k] != body.faces[0] + static_cast<int>(k)) return false;
    return true;
}

std::string iges_text(const geom::Model& m, const std::string& file_name) {
    IgesBuilder b;
    std::vector<int> brep_start(m.faces.size(), -1);  // body written as B-rep from this face
    std::vector<bool> in_brep(m.faces.size(), false);
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
        const geom::Body& body = m.bodies[i];
        if (!has_topology(m, body) || !consecutive(body)) continue;
        brep_start[body.faces.front()] = static_cast<int>(i);
        for (int f : body.faces) in_brep[f] = true;
    }
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        if (brep_start[f] >= 0) brep_body(b, m, m.bodies[brep_start[f]]);
        else if (!in_brep[f]) trimmed_face(b, m, m.faces[f]);
    }
    return b.text(m, file_name);
}

void write_iges(const geom::Model& model, const std::string& path) {
    OutputFile out(path);
    out.write(iges_text(model, std::filesystem::path(path).filename().string()));
    out.commit();
}

}  // namespace trimkit::io
