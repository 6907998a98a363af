// Structure entities of IgesReader: 124 transformation matrices (chains
// composed), 314 colours and the standard colour numbers, 406 form 15 names,
// 402 groups, 308 subfigure definitions and 408 instances, and the per-entity
// dispatch. A 408 outside any definition becomes a Model::Instance of the body
// holding its definition, which is read once; 408s nested inside a definition are
// flattened into it (their faces copied into place).
#include <algorithm>
#include <cmath>
#include <set>

#include "geom/error.h"
#include "io/iges_reader.h"

namespace trimkit::io {

Eigen::Affine3d IgesReader::transform_matrix(int de) {
    const IgesDirectoryEntry& e = entry_of(de);
    if (e.type != 124) fail(de, "transform pointer refers to entity " + std::to_string(e.type) + ", expected 124");
    IgesParameterCursor c(file_, file_.index_of(de));
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) m(r, k) = c.real_or("R", r == k ? 1.0 : 0.0);
        m(r, 3) = c.real_or("T", 0.0);
    }
    if (!m.allFinite()) c.fail("transformation matrix has non-finite values");
    if (std::fabs(m.block<3, 3>(0, 0).determinant()) < 1e-300)
        c.fail("transformation matrix is singular");
    Eigen::Affine3d T;
    T.matrix() = m;
    return T;
}

Eigen::Affine3d IgesReader::transform_of(int de) {
    const IgesDirectoryEntry& e = entry_of(de);
    if (e.transform == 0) return Eigen::Affine3d::Identity();
    auto it = transform_cache_.find(e.transform);
    if (it != transform_cache_.end()) return it->second;
    // x_model = T_k ... T_2 T_1 x, T_1 the entity's 124, T_2 the one T_1 points to.
    Eigen::Affine3d T = Eigen::Affine3d::Identity();
    std::set<int> seen;
    int t = e.transform;
    while (t != 0) {
        if (t < 0 || file_.index_of(t) < 0)
            fail(de, "transform pointer " + std::to_string(t) + " is not a directory entry");
        if (!seen.insert(t).second || static_cast<int>(seen.size()) > kMaxIgesNesting)
            fail(de, "transformation matrices form a cycle or a chain longer than " +
                         std::to_string(kMaxIgesNesting));
        T = transform_matrix(t) * T;
        t = entry_of(t).transform;
    }
    transform_cache_.emplace(e.transform, T);
    return T;
}

int IgesReader::color_of(int de) {
    const IgesDirectoryEntry& e = entry_of(de);
    const int key = e.color;
    if (key == 0) return -1;
    auto it = color_cache_.find(key);
    if (it != color_cache_.end()) return it->second;
    geom::Color color;
    int result = -1;
    if (key > 0 && key <= 8) {
        // IGES 5.3 Table 4: the standard colour numbers.
        static const char* names[] = {"black", "red", "green", "blue", "yellow", "magenta", "cyan", "white"};
        static const double rgb[][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                        {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
        color.rgb = {rgb[key - 1][0], rgb[key - 1][1], rgb[key - 1][2]};
        color.name = names[key - 1];
        result = static_cast<int>(model_.colors.size());
        model_.colors.push_back(color);
    } else if (key < 0 && file_.index_of(-key) >= 0 && entry_of(-key).type == 314) {
        try {
            IgesParameterCursor c(file_, file_.index_of(-key));
            for (double& x : color.rgb) x = std::clamp(c.real_or("colour component", 0) / 100.0, 0.0, 1.0);
            if (c.remaining() > 0) color.name = c.string_or("colour name", "");
            result = static_cast<int>(model_.colors.size());
            model_.colors.push_back(color);
        } catch (const geom::ReadError& err) {
            warn("D" + std::to_string(-key) + ": colour skipped: " + err.reason());
        }
    } else {
        warn("D" + std::to_string(de) + ": colour number " + std::to_string(key) +
             " is neither 0-8 nor a pointer to a 314 colour");
    }
    color_cache_.emplace(key, result);
    return result;
}

std::string IgesReader::name_of(int de, const std::vector<int>& properties) {
    for (int p : properties) {
        const IgesDirectoryEntry& e = entry_of(p);
        if (e.type != 406 || e.form != 15) continue;
        try {
            IgesParameterCursor c(file_, file_.index_of(p));
            c.integer_or("property count", 1);
            std::string name = c.string_or("name", "");
            if (!name.empty()) return name;
        } catch (const geom::ReadError&) {
        }
    }
    const IgesDirectoryEntry& e = entry_of(de);
    if (e.label.empty()) return {};
    return e.label;
}

int IgesReader::definition_body(int def, int depth) {
    const auto cached = definition_body_.find(def);
    if (cached != definition_body_.end()) return cached->second;
    definition_body_.emplace(def, -1);  // a definition placing itself reads as empty
    const std::size_t bodies_before = model_.bodies.size();
    ++in_definition_;
    std::vector<int> faces;
    try {
        faces = translate(def, Eigen::Affine3d::Identity(), depth);
    } catch (...) {
        --in_definition_;
        throw;
    }
    --in_definition_;
    if (faces.empty()) return -1;
    geom::Body body;
    body.closed = model_.bodies.size() > bodies_before;
    for (std::size_t b = bodies_before; b < model_.bodies.size(); ++b) body.closed = body.closed && model_.bodies[b].closed;
    if (model_.bodies.size() == bodies_before + 1) body.name = model_.bodies.back().name;
    model_.bodies.resize(bodies_before);
    IgesParameterCursor c(file_, file_.index_of(def));
    c.integer_or("depth", 0);
    const std::string name = c.string_or("name", "");
    if (!name.empty()) body.name = name;
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    body.faces = std::move(faces);
    model_.bodies.push_back(std::move(body));
    const int index = static_cast<int>(model_.bodies.size()) - 1;
    definition_body_[def] = index;
    return index;
}

std::vector<int> IgesReader::translate(int de, const Eigen::Affine3d& placement, int depth) {
    if (depth > kMaxIgesNesting)
        fail(de, "groups or subfigures nested deeper than " + std::to_string(kMaxIgesNesting));
    const long long max_visits =
        std::max(kMinIgesVisits, kMaxIgesVisitsPerEntry * static_cast<long long>(file_.entries().size()));
    if (++visits_ > max_visits)
        fail(de, "groups or subfigures reach their members more than " + std::to_string(max_visits) +
                     " times (the same entities held many times over)");
    if (monitor_) monitor_->check();
    const IgesDirectoryEntry& e = entry_of(de);
    const int type = e.type;
    std::vector<int> faces;
    switch (type) {
        case 144: case 143: case 510:
        case 128: case 114: case 118: case 120: case 122: case 140:
        case 108: case 190: case 192: case 194: case 196: case 198:
            return read_face_entity(de, placement);
        case 186: case 514: {
            int b = read_body(de, placement);
            return model_.bodies[b].faces;
        }
        case 402: {
            // Groups (forms 1, 7, 14, 15): N members. Other forms relate
            // entities without defining geometry and are ignored.
            if (e.form != 1 && e.form != 7 && e.form != 14 && e.form != 15) return faces;
            IgesParameterCursor c(file_, file_.index_of(de));
            const int n = c.count("member count", 1);
            std::vector<int> members;
            for (int i = 0; i < n; ++i) members.push_back(c.pointer("member"));
            for (int m : members) {
                if (m == 0) continue;
                try {
                    std::vector<int> f = translate(m, placement, depth + 1);
                    faces.insert(faces.end(), f.begin(), f.end());
                } catch (const geom::ReadError& err) {
                    warn("D" + std::to_string(m) + ": skipped: " + err.reason() + " (line " +
                         std::to_string(err.line()) + ")");
                }
            }
            return faces;
        }
        case 408: {
            IgesParameterCursor c(file_, file_.index_of(de));
            const int def = c.pointer("subfigure definition");
            const Eigen::Vector3d x = c.point("translation");
            const double s = c.real_or("scale", 1.0);
            if (def == 0 || entry_of(def).type != 308)
                c.fail("subfigure instance does not point to a 308 subfigure definition");
            if (!(s > 0) || !std::isfinite(s)) c.fail("subfigure scale " + geom::format_value(s) + " is not positive");
            Eigen::Affine3d local = Eigen::Affine3d::Identity();
            local.translate(x);
            local.scale(s);
            const Eigen::Affine3d inner = placement * transform_of(de) * local;
            if (in_definition_ > 0) return translate(def, inner, depth + 1);
            const int body = definition_body(def, depth + 1);
            if (body >= 0) model_.instances.push_back({body, inner, name_of(de, c.property_pointers())});
            return faces;
        }
        case 308: {
            IgesParameterCursor c(file_, file_.index_of(de));
            c.integer_or("depth", 0);
            c.string_or("name", "");
            const int n = c.count("entity count", 1);
            std::vector<int> members;
            for (int i = 0; i < n; ++i) members.push_back(c.pointer("member"));
            const Eigen::Affine3d inner = placement * transform_of(de);
            for (int m : members) {
                if (m == 0) continue;
                try {
                    std::vector<int> f = translate(m, inner, depth + 1);
                    faces.insert(faces.end(), f.begin(), f.end());
                } catch (const geom::ReadError& err) {
                    warn("D" + std::to_string(m) + ": skipped: " + err.reason() + " (line " +
                         std::to_string(err.line()) + ")");
                }
            }
            return faces;
        }
        // Entities without faces of their own: curves, points, directions,
        // transforms, properties, colours and B-rep parts read via their owners.
        case 100: case 102: case 104: case 106: case 110: case 112: case 116: case 123:
        case 124: case 126: case 141: case 142: case 314: case 406: case 502: case 504:
        case 508: case 0:
            return faces;
        case 130:
            warn_unsupported(de, "offset curve");
            return faces;
        default:
            warn_unsupported(de, "");
            return faces;
    }
}

}  // namespace trimkit::io
