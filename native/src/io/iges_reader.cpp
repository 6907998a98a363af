// IgesReader core: which entities are roots, translating them into the model,
// units, warnings, and deciding when a file as a whole is unreadable.
#include "io/iges_reader.h"

#include <algorithm>

#include "geom/error.h"

namespace trimkit::io {
namespace {

// Unsupported-entity warnings listed one by one per type before summarising.
constexpr int kWarningsPerType = 5;

const char* type_name(int type) {
    switch (type) {
        case 130: return "offset curve";
        case 140: return "offset surface";
        case 106: return "copious data";
        case 125: return "flash";
        case 132: return "connect point";
        case 134: return "node";
        case 136: return "finite element";
        case 150: case 152: case 154: case 156: case 158: case 160: case 162: case 164:
        case 168: return "CSG primitive";
        case 180: return "boolean tree";
        case 184: return "solid assembly";
        case 202: case 204: case 206: case 208: case 210: case 212: case 213: case 214:
        case 216: case 218: case 220: case 222: case 228: case 230: return "annotation";
        case 302: return "associativity definition";
        case 304: return "line font definition";
        case 310: return "text font definition";
        case 312: return "text display template";
        case 316: return "units data";
        case 320: return "network subfigure definition";
        case 404: return "drawing";
        case 410: return "view";
        case 412: return "rectangular array subfigure instance";
        case 414: return "circular array subfigure instance";
        case 416: return "external reference";
        case 418: return "nodal load/constraint";
        case 420: return "network subfigure instance";
        case 430: return "solid instance";
        default: return "unknown entity";
    }
}

bool makes_faces(int type) {
    switch (type) {
        case 108: case 114: case 118: case 120: case 122: case 128: case 140: case 143:
        case 144: case 186: case 190: case 192: case 194: case 196: case 198: case 510:
        case 514:
            return true;
        default:
            return false;
    }
}

}  // namespace

IgesReader::IgesReader(const IgesFile& file, ReadMonitor* monitor) : file_(file), monitor_(monitor) {}

IgesReader::Nesting::Nesting(IgesReader& r, int de) : r_(r) {
    if (++r_.depth_ > kMaxIgesNesting) {
        --r_.depth_;
        r_.fail(de, "entity references nested deeper than " + std::to_string(kMaxIgesNesting) +
                        " (a cycle?)");
    }
}

const IgesDirectoryEntry& IgesReader::entry_of(int de) const {
    const int i = file_.index_of(de);
    if (i < 0) throw geom::ReadError(file_.name(), 0, "pointer to D" + std::to_string(de) + ", which is not a directory entry");
    return file_.entry(i);
}

int IgesReader::line_of(int de) const {
    const int i = file_.index_of(de);
    return i < 0 ? 0 : file_.parameter_line(i);
}

void IgesReader::fail(int de, const std::string& reason) const {
    const int i = file_.index_of(de);
    const std::string who = i < 0 ? "D" + std::to_string(de)
                                   : "entity " + std::to_string(file_.entry(i).type) + " (D" +
                                         std::to_string(de) + ")";
    throw geom::ReadError(file_.name(), line_of(de), who + ": " + reason);
}

void IgesReader::warn(const std::string& message) { model_.warnings.push_back(message); }

void IgesReader::warn_unsupported(int de, const std::string& what) {
    const int type = entry_of(de).type;
    const int n = ++unsupported_count_[type];
    if (n > kWarningsPerType) return;
    warn("D" + std::to_string(de) + ": entity " + std::to_string(type) + " (" +
         (what.empty() ? type_name(type) : what) + ") not supported");
}

std::vector<int> IgesReader::references(int index) {
    const IgesDirectoryEntry& e = file_.entry(index);
    std::vector<int> out;
    IgesParameterCursor c(file_, index);
    auto ptr = [&] {
        const int p = c.integer_or("pointer", 0);
        if (p > 0) out.push_back(p);
    };
    auto list = [&] {
        const int n = c.count("count", 1);
        for (int i = 0; i < n; ++i) ptr();
    };
    switch (e.type) {
        case 102: list(); break;
        case 108: c.skip(4); ptr(); break;
        case 118: ptr(); ptr(); break;
        case 120: ptr(); ptr(); break;
        case 122: ptr(); break;
        case 140: c.skip(4); ptr(); break;
        case 141: {
            c.skip(2);
            ptr();
            const int n = c.count("count", 3);
            for (int i = 0; i < n; ++i) {
                ptr();
                c.skip(1);
                list();
            }
            break;
        }
        case 142: c.skip(1); ptr(); ptr(); ptr(); break;
        case 143: c.skip(1); ptr(); list(); break;
        case 144: {
            ptr();
            c.skip(1);
            const int n2 = c.count("count", 1);
            ptr();
            for (int i = 0; i < n2; ++i) ptr();
            break;
        }
        case 186: {
            ptr();
            c.skip(1);
            const int n = c.count("count", 2);
            for (int i = 0; i < n; ++i) {
                ptr();
                c.skip(1);
            }
            break;
        }
        case 308: c.skip(2); list(); break;
        case 402:
            if (e.form == 1 || e.form == 7 || e.form == 14 || e.form == 15) list();
            break;
        case 408: ptr(); break;
        case 504: {
            const int n = c.count("count", 5);
            for (int i = 0; i < n; ++i) {
                ptr();
                ptr();
                c.skip(1);
                ptr();
                c.skip(1);
            }
            break;
        }
        case 508: {
            const int n = c.count("count", 5);
            for (int i = 0; i < n; ++i) {
                c.skip(1);
                ptr();
                c.skip(2);
                const int k = c.count("count", 2);
                for (int j = 0; j < k; ++j) {
                    c.skip(1);
                    ptr();
                }
            }
            break;
        }
        case 510: {
            ptr();
            const int n = c.count("count", 1);
            c.skip(1);
            for (int i = 0; i < n; ++i) ptr();
            break;
        }
        case 514: {
            const int n = c.count("count", 2);
            for (int i = 0; i < n; ++i) {
                ptr();
                c.skip(1);
            }
            break;
        }
        default: break;
    }
    return out;
}

void IgesReader::build_reference_counts() {
    const int n = static_cast<int>(file_.entries().size());
    referenced_.assign(static_cast<std::size_t>(n), 0);
    for (int i = 0; i < n; ++i) {
        if (file_.entry(i).type <= 0) continue;
        std::vector<int> refs;
        try {
            refs = references(i);
        } catch (const geom::ReadError&) {
            continue;  // reported when (if) the entity itself is translated
        }
        for (int p : refs) {
            const int k = file_.index_of(p);
            if (k >= 0 && k != i) ++referenced_[k];
        }
    }
}

void IgesReader::set_units() {
    const IgesGlobal& g = file_.global();
    struct Unit {
        const char* name;
        double metres;
    };
    // IGES 5.3 Table 3, Global field 14.
    static const Unit units[] = {{"in", 0.0254}, {"mm", 1e-3}, {"", 0},      {"ft", 0.3048},
                                 {"mi", 1609.344}, {"m", 1.0},  {"km", 1000.0}, {"mil", 2.54e-5},
                                 {"um", 1e-6},   {"cm", 1e-2}, {"uin", 2.54e-8}};
    int flag = g.units_flag;
    if (flag == 3) {
        std::string n = g.units_name;
        std::transform(n.begin(), n.end(), n.begin(), [](unsigned char ch) { return std::toupper(ch); });
        static const std::pair<const char*, int> names[] = {
            {"IN", 1}, {"INCH", 1}, {"MM", 2}, {"FT", 4}, {"MI", 5}, {"M", 6}, {"KM", 7},
            {"MIL", 8}, {"UM", 9}, {"MICRON", 9}, {"CM", 10}, {"UIN", 11}};
        flag = 0;
        for (const auto& [key, f] : names)
            if (n == key) flag = f;
        if (flag == 0) {
            warn("Global field 15: unit name '" + g.units_name + "' not recognised; assuming mm");
            flag = 2;
        }
    }
    model_.units = units[flag - 1].name;
    model_.scale_to_metres = units[flag - 1].metres / g.model_scale;
}

geom::Model IgesReader::read() {
    for (const std::string& w : file_.warnings()) warn(w);
    set_units();
    build_reference_counts();

    const int n = static_cast<int>(file_.entries().size());
    int first_failure_line = 0;
    std::string first_failure;
    auto run = [&](int i) {
        const IgesDirectoryEntry& e = file_.entry(i);
        try {
            translate(e.sequence, Eigen::Affine3d::Identity(), 0);
        } catch (const geom::ReadError& err) {
            const std::string why = "D" + std::to_string(e.sequence) + ": entity " + std::to_string(e.type) +
                                    " skipped: " + err.reason() + " (line " + std::to_string(err.line()) + ")";
            const bool face_lost = makes_faces(e.type);
            if (face_lost)
                geom::skip_face(model_, why);
            else
                warn(why);
            if (first_failure.empty() && face_lost) {
                first_failure = err.reason();
                first_failure_line = err.line();
            }
        }
    };
    bool has_surfaces = false;
    for (int i = 0; i < n; ++i) {
        if (monitor_) {
            monitor_->check();
            monitor_->report(static_cast<double>(i) / n);
        }
        const IgesDirectoryEntry& e = file_.entry(i);
        if (e.type < 0) {
            warn("D" + std::to_string(e.sequence) + ": unreadable directory entry skipped");
            continue;
        }
        if (makes_faces(e.type)) has_surfaces = true;
        // Roots: independent entities nothing else points to. Subfigure
        // definitions (308) appear only through their instances.
        if (referenced_[i] > 0 || e.subordinate != 0 || e.type == 308) continue;
        run(i);
    }
    if (model_.faces.empty()) {
        // No root gave a face: take unreferenced face entities whatever their
        // status (files with every entity marked dependent exist).
        for (int i = 0; i < n; ++i) {
            const IgesDirectoryEntry& e = file_.entry(i);
            if (monitor_) monitor_->check();
            if (e.type > 0 && referenced_[i] == 0 && e.subordinate != 0 && makes_faces(e.type)) run(i);
        }
    }
    for (const auto& [type, count] : unsupported_count_) {
        if (count > kWarningsPerType)
            warn(std::to_string(count - kWarningsPerType) + " more entities of type " +
                 std::to_string(type) + " (" + type_name(type) + ") not supported");
    }
    if (model_.faces.empty() && has_surfaces) {
        throw geom::ReadError(file_.name(), first_failure_line,
                              first_failure.empty() ? "no face could be read from the file's surfaces"
                                                    : first_failure);
    }
    std::vector<char> in_body(model_.faces.size(), 0);
    for (const geom::Body& b : model_.bodies)
        for (int f : b.faces) in_body[static_cast<std::size_t>(f)] = 1;
    for (std::size_t f = 0; f < in_body.size(); ++f)
        if (!in_body[f]) model_.free_faces.push_back(static_cast<int>(f));
    return std::move(model_);
}

}  // namespace trimkit::io
