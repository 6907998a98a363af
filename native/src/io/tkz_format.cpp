#include "io/tkz_format.h"

#include <cmath>
#include <cstring>

#include "fit/extend_model.h"
#include "fit/fit_curve.h"
#include "geom/bspline_basis.h"
#include "geom/error.h"
#include "io/output_file.h"
#include "io/read_support.h"

namespace trimkit::io {
namespace {

constexpr char kMagic[4] = {'T', 'K', 'Z', '1'};
// Version 2 adds the notes section (warnings, source entities, assembly paths);
// version 1 files, which end after the colours, still read.
constexpr std::uint32_t kVersion = 2;

// ---- writing ----------------------------------------------------------------------

struct Writer {
    std::string out;
    void raw(const void* p, std::size_t n) { out.append(static_cast<const char*>(p), n); }
    void u8(std::uint8_t x) { raw(&x, 1); }
    void u32(std::uint32_t x) { for (int i = 0; i < 4; ++i) u8(static_cast<std::uint8_t>(x >> (8 * i))); }
    void i32(std::int32_t x) { u32(static_cast<std::uint32_t>(x)); }
    void f64(double x) {
        std::uint64_t bits;
        std::memcpy(&bits, &x, 8);
        for (int i = 0; i < 8; ++i) u8(static_cast<std::uint8_t>(bits >> (8 * i)));
    }
    void str(const std::string& s) {
        u32(static_cast<std::uint32_t>(s.size()));
        raw(s.data(), s.size());
    }
    void doubles(const std::vector<double>& v) { for (double x : v) f64(x); }
    template <int Dim>
    void curve(const geom::NurbsCurve<Dim>& c) {
        u8(static_cast<std::uint8_t>(c.degree()));
        u32(static_cast<std::uint32_t>(c.points().size()));
        u8(c.is_rational());
        doubles(c.knots());
        for (const auto& p : c.points()) for (int k = 0; k < Dim; ++k) f64(p[k]);
        if (c.is_rational()) doubles(c.weights());
    }
    void surface(const geom::NurbsSurface& s) {
        u8(static_cast<std::uint8_t>(s.degree_u()));
        u8(static_cast<std::uint8_t>(s.degree_v()));
        u32(static_cast<std::uint32_t>(s.count_u()));
        u32(static_cast<std::uint32_t>(s.count_v()));
        u8(s.is_rational());
        doubles(s.knots_u());
        doubles(s.knots_v());
        for (const auto& p : s.points()) for (int k = 0; k < 3; ++k) f64(p[k]);
        if (s.is_rational()) doubles(s.weights());
    }
    void point(const Eigen::Vector3d& p) { for (int k = 0; k < 3; ++k) f64(p[k]); }
};

void write_rule(Writer& w, const fit::FitRule& r) {
    w.u8(static_cast<std::uint8_t>(r.method));
    w.u8(static_cast<std::uint8_t>(r.degree_u));
    w.u8(static_cast<std::uint8_t>(r.degree_v));
    w.u8(static_cast<std::uint8_t>(r.count_u));
    w.u8(static_cast<std::uint8_t>(r.count_v));
    w.u8(static_cast<std::uint8_t>((r.boundary_curves ? 1 : 0) | (r.reversed ? 2 : 0)));
    w.f64(r.tolerance);
}

void write_face(Writer& w, const geom::Face& f, const std::optional<fit::FitRule>& rule) {
    w.u8(static_cast<std::uint8_t>((rule ? 1 : 0) | (f.reversed ? 2 : 0)));
    w.str(rule ? std::string() : f.surface_kind);
    w.str(f.name);
    w.i32(f.color);
    if (rule) write_rule(w, *rule);
    else w.surface(f.surface);
    w.u32(static_cast<std::uint32_t>(f.loops.size()));
    for (std::size_t l = 0; l < f.loops.size(); ++l) {
        const geom::Loop& loop = f.loops[l];
        w.u8(loop.outer);
        w.u32(static_cast<std::uint32_t>(loop.coedges.size()));
        for (std::size_t c = 0; c < loop.coedges.size(); ++c) {
            const geom::Coedge& e = loop.coedges[c];
            const bool g1 = rule && l < rule->g1.size() && c < rule->g1[l].size() && rule->g1[l][c];
            w.i32(e.edge);
            w.u8(static_cast<std::uint8_t>((e.edge_reversed ? 1 : 0) | (g1 ? 2 : 0)));
            if (!rule) w.curve(e.curve);
        }
    }
}

// ---- reading ----------------------------------------------------------------------

struct Reader {
    ByteCursor& c;
    const std::string& file;

    [[noreturn]] void fail(const std::string& reason) const { throw geom::ReadError(file, 0, reason); }
    // A count of items of at least `bytes_each` bytes, checked against what is left.
    std::uint32_t count(const char* what, std::size_t bytes_each) {
        const std::uint32_t n = c.u32(what);
        if (bytes_each > 0 && n > c.remaining() / bytes_each)
            fail(std::string(what) + " = " + std::to_string(n) + " but only " + std::to_string(c.remaining()) +
                 " bytes are left");
        return n;
    }
    std::string str(const char* what) {
        const std::uint32_t n = count(what, 1);
        std::string s(n, '\0');
        for (std::uint32_t i = 0; i < n; ++i) s[i] = static_cast<char>(c.u8(what));
        return s;
    }
    int degree(const char* what) {
        const int p = c.u8(what);
        if (p < 1 || p > geom::kMaxDegree)
            fail(std::string(what) + " = " + std::to_string(p) + "; expected 1 .. " + std::to_string(geom::kMaxDegree));
        return p;
    }
    std::vector<double> doubles(std::size_t n, const char* what) {
        if (n > c.remaining() / 8) fail(std::string("truncated: ") + what);
        std::vector<double> v(n);
        for (double& x : v) x = c.f64(what);
        return v;
    }
    Eigen::Vector3d point(const char* what) { return {c.f64(what), c.f64(what), c.f64(what)}; }
    template <int Dim>
    geom::NurbsCurve<Dim> curve(const char* what) {
        const int p = degree(what);
        const std::uint32_t n = count((std::string(what) + " point count").c_str(), 8 * Dim);
        const bool rational = c.u8(what) != 0;
        std::vector<double> U = doubles(std::size_t(n) + p + 1, what);
        std::vector<typename geom::NurbsCurve<Dim>::Point> P(n);
        for (auto& q : P) for (int k = 0; k < Dim; ++k) q[k] = c.f64(what);
        std::vector<double> w = rational ? doubles(n, what) : std::vector<double>();
        try {
            return geom::NurbsCurve<Dim>(p, std::move(U), std::move(P), std::move(w));
        } catch (const geom::InvalidInput& e) {
            fail(std::string(what) + ": " + e.what());
        }
    }
    geom::NurbsSurface surface() {
        const int pu = degree("surface degree u"), pv = degree("surface degree v");
        const std::uint32_t nu = count("surface count u", 8), nv = count("surface count v", 8);
        if (nv > 0 && nu > c.remaining() / 24 / nv) fail("surface has " + std::to_string(nu) + " x " + std::to_string(nv) + " points, more than the bytes left");
        const bool rational = c.u8("surface rational flag") != 0;
        std::vector<double> U = doubles(std::size_t(nu) + pu + 1, "surface knots u");
        std::vector<double> V = doubles(std::size_t(nv) + pv + 1, "surface knots v");
        std::vector<Eigen::Vector3d> P(std::size_t(nu) * nv);
        for (auto& q : P) q = point("surface points");
        std::vector<double> w = rational ? doubles(P.size(), "surface weights") : std::vector<double>();
        try {
            return geom::NurbsSurface(pu, pv, std::move(U), std::move(V), int(nu), int(nv), std::move(P), std::move(w));
        } catch (const geom::InvalidInput& e) {
            fail(std::string("surface: ") + e.what());
        }
    }
    fit::FitRule rule() {
        fit::FitRule r;
        const int method = c.u8("rule method");
        if (method != static_cast<int>(fit::FitMethod::kBoundaryG1) && method != static_cast<int>(fit::FitMethod::kCoons))
            fail("rule method " + std::to_string(method) + " unknown; expected 1 or 2");
        r.method = static_cast<fit::FitMethod>(method);
        r.degree_u = degree("rule degree u");
        r.degree_v = degree("rule degree v");
        r.count_u = c.u8("rule count u");
        r.count_v = c.u8("rule count v");
        if (r.count_u < r.degree_u + 1 || r.count_u > fit::kMaxFitControlPoints || r.count_v < r.degree_v + 1 ||
            r.count_v > fit::kMaxFitControlPoints)
            fail("rule control-point counts " + std::to_string(r.count_u) + " x " + std::to_string(r.count_v) +
                 "; expected degree + 1 .. " + std::to_string(fit::kMaxFitControlPoints));
        const int flags = c.u8("rule flags");
        r.boundary_curves = flags & 1;
        r.reversed = flags & 2;
        r.tolerance = c.f64("rule tolerance");
        if (!(r.tolerance > 0) || !std::isfinite(r.tolerance)) fail("rule tolerance " + geom::format_value(r.tolerance) + "; expected > 0");
        return r;
    }
};

void read_face(Reader& r, geom::Model& m, std::optional<fit::FitRule>& rule, std::size_t edge_count) {
    geom::Face f;
    const int flags = r.c.u8("face flags");
    f.reversed = flags & 2;
    f.surface_kind = r.str("surface kind");
    if (f.surface_kind.empty()) f.surface_kind = "bspline";
    f.name = r.str("face name");
    f.color = r.c.i32("face colour");
    if (flags & 1) rule = r.rule();
    else f.surface = r.surface();
    const std::uint32_t loops = r.count("loop count", 5);
    if (loops == 0) r.fail("face " + std::to_string(m.faces.size()) + " has no loop");
    for (std::uint32_t l = 0; l < loops; ++l) {
        geom::Loop loop;
        loop.outer = r.c.u8("loop outer flag") != 0;
        const std::uint32_t n = r.count("coedge count", 5);
        if (rule) rule->g1.emplace_back();
        for (std::uint32_t k = 0; k < n; ++k) {
            geom::Coedge e;
            e.edge = r.c.i32("coedge edge");
            if (e.edge < -1 || e.edge >= static_cast<std::int64_t>(edge_count))
                r.fail("face " + std::to_string(m.faces.size()) + " coedge edge " + std::to_string(e.edge) +
                       "; expected -1 .. " + std::to_string(edge_count - 1));
            const int bits = r.c.u8("coedge flags");
            e.edge_reversed = bits & 1;
            if (rule) {
                if (e.edge < 0) r.fail("compressed face " + std::to_string(m.faces.size()) + " has a coedge without an edge");
                rule->g1.back().push_back(bits & 2);
            } else {
                e.curve = r.curve<2>("coedge curve");
            }
            loop.coedges.push_back(std::move(e));
        }
        f.loops.push_back(std::move(loop));
    }
    m.faces.push_back(std::move(f));
}

std::vector<int> face_list(Reader& r, const char* what, std::size_t faces) {
    const std::uint32_t n = r.count(what, 4);
    std::vector<int> out(n);
    for (int& f : out) {
        f = r.c.i32(what);
        if (f < 0 || static_cast<std::size_t>(f) >= faces)
            r.fail(std::string(what) + " face " + std::to_string(f) + "; expected 0 .. " + std::to_string(faces) + " - 1");
    }
    return out;
}

void write_strings(Writer& w, const std::vector<std::string>& strings) {
    w.u32(static_cast<std::uint32_t>(strings.size()));
    for (const std::string& x : strings) w.str(x);
}

// What the reader noted, so that a model stored as .tkz (the Blender add-on) reports
// the same after a reload: the model's warnings, each face's source entity and
// warnings, each instance's assembly path.
void write_notes(Writer& w, const geom::Model& m) {
    write_strings(w, m.warnings);
    for (const geom::Face& f : m.faces) {
        w.i32(f.source_entity);
        write_strings(w, f.warnings);
    }
    for (const geom::Instance& i : m.instances) write_strings(w, i.path);
}

}  // namespace

std::string tkz_bytes(const fit::CompressedModel& cm) {
    const geom::Model& m = cm.model;
    Writer w;
    w.raw(kMagic, 4);
    w.u32(kVersion);
    w.str(m.units);
    w.f64(m.scale_to_metres);
    w.u32(static_cast<std::uint32_t>(m.edges.size()));
    for (const geom::Edge& e : m.edges) {
        w.u8(static_cast<std::uint8_t>((e.curve ? 1 : 0) | (e.start ? 2 : 0) | (e.end ? 4 : 0)));
        if (e.curve) w.curve(*e.curve);
        if (e.start) w.point(*e.start);
        if (e.end) w.point(*e.end);
    }
    w.u32(static_cast<std::uint32_t>(m.faces.size()));
    for (std::size_t f = 0; f < m.faces.size(); ++f)
        write_face(w, m.faces[f], f < cm.rules.size() ? cm.rules[f] : std::nullopt);
    w.u32(static_cast<std::uint32_t>(m.bodies.size()));
    for (const geom::Body& b : m.bodies) {
        w.str(b.name);
        w.u8(b.closed);
        w.u32(static_cast<std::uint32_t>(b.faces.size()));
        for (int f : b.faces) w.i32(f);
    }
    w.u32(static_cast<std::uint32_t>(m.free_faces.size()));
    for (int f : m.free_faces) w.i32(f);
    w.u32(static_cast<std::uint32_t>(m.instances.size()));
    for (const geom::Instance& i : m.instances) {
        w.i32(i.body);
        for (int r = 0; r < 3; ++r) for (int k = 0; k < 4; ++k) w.f64(i.transform.matrix()(r, k));
        w.str(i.name);
    }
    w.u32(static_cast<std::uint32_t>(m.colors.size()));
    for (const geom::Color& c : m.colors) {
        for (double x : c.rgb) w.f64(x);
        w.str(c.name);
    }
    write_notes(w, m);
    return w.out;
}

void write_tkz(const fit::CompressedModel& model, const std::string& path) {
    OutputFile out(path);
    out.write(tkz_bytes(model));
    out.commit();
}

void read_edges(Reader& r, geom::Model& m) {
    const std::uint32_t edges = r.count("edge count", 1);
    for (std::uint32_t k = 0; k < edges; ++k) {
        geom::Edge e;
        const int flags = r.c.u8("edge flags");
        if (flags & 1) e.curve = r.curve<3>("edge curve");
        if (flags & 2) e.start = r.point("edge start");
        if (flags & 4) e.end = r.point("edge end");
        m.edges.push_back(std::move(e));
    }
}

// Bodies, free faces, instances and colours, after the faces.
void read_structure(Reader& r, geom::Model& m) {
    const std::size_t faces = m.faces.size();
    const std::uint32_t bodies = r.count("body count", 9);
    for (std::uint32_t k = 0; k < bodies; ++k) {
        geom::Body b;
        b.name = r.str("body name");
        b.closed = r.c.u8("body closed flag") != 0;
        b.faces = face_list(r, "body", faces);
        m.bodies.push_back(std::move(b));
    }
    m.free_faces = face_list(r, "free faces", faces);
    const std::uint32_t instances = r.count("instance count", 104);
    for (std::uint32_t k = 0; k < instances; ++k) {
        geom::Instance i;
        i.body = r.c.i32("instance body");
        if (i.body < 0 || static_cast<std::uint32_t>(i.body) >= bodies) r.fail("instance body " + std::to_string(i.body) + " out of range");
        for (int row = 0; row < 3; ++row) for (int col = 0; col < 4; ++col) i.transform.matrix()(row, col) = r.c.f64("instance transform");
        i.name = r.str("instance name");
        m.instances.push_back(std::move(i));
    }
    const std::uint32_t colors = r.count("colour count", 28);
    for (std::uint32_t k = 0; k < colors; ++k) {
        geom::Color c;
        for (double& x : c.rgb) x = r.c.f64("colour");
        c.name = r.str("colour name");
        m.colors.push_back(std::move(c));
    }
    for (const geom::Face& f : m.faces)
        if (f.color < -1 || f.color >= static_cast<int>(colors)) r.fail("face colour " + std::to_string(f.color) + " out of range");
}

std::vector<std::string> read_strings(Reader& r, const char* what) {
    std::vector<std::string> out(r.count(what, 4));
    for (std::string& x : out) x = r.str(what);
    return out;
}

// The notes section of version 2 (write_notes).
void read_notes(Reader& r, geom::Model& m) {
    m.warnings = read_strings(r, "model warning");
    for (geom::Face& f : m.faces) {
        f.source_entity = r.c.i32("face source entity");
        f.warnings = read_strings(r, "face warning");
    }
    for (geom::Instance& i : m.instances) i.path = read_strings(r, "instance path");
}

fit::CompressedModel read_tkz_bytes(const std::string& bytes, const std::string& name) {
    ByteCursor cursor(bytes, 0, bytes.size(), name);
    Reader r{cursor, name};
    char magic[4];
    for (char& ch : magic) ch = static_cast<char>(cursor.u8("magic"));
    if (std::memcmp(magic, kMagic, 4) != 0) r.fail("not a .tkz file (no TKZ1 magic)");
    const std::uint32_t version = cursor.u32("version");
    if (version < 1 || version > kVersion)
        r.fail("version " + std::to_string(version) + "; this trimkit reads versions 1 and 2");
    fit::CompressedModel cm;
    geom::Model& m = cm.model;
    m.units = r.str("units");
    m.scale_to_metres = cursor.f64("scale to metres");
    read_edges(r, m);
    const std::uint32_t faces = r.count("face count", 14);
    for (std::uint32_t k = 0; k < faces; ++k) {
        cm.rules.emplace_back();
        read_face(r, m, cm.rules.back(), m.edges.size());
    }
    read_structure(r, m);
    if (version >= 2) read_notes(r, m);
    if (cursor.remaining() != 0) r.fail(std::to_string(cursor.remaining()) + " bytes after the end of the model");
    return cm;
}

fit::CompressedModel read_tkz(const std::string& path) {
    return read_tkz_bytes(read_file_bytes(path), path);
}

geom::Model read_tkz_model(const std::string& path, int* rebuilt) {
    const fit::CompressedModel compressed = read_tkz(path);
    if (rebuilt) {
        *rebuilt = 0;
        for (const auto& rule : compressed.rules) *rebuilt += rule.has_value();
    }
    try {
        return fit::extend_model(compressed);
    } catch (const geom::NumericalFailure& e) {
        // The file's edges and rules are what the fit ran on: a degenerate fit is bad input.
        throw geom::ReadError(path, 0, std::string("a face cannot be rebuilt: ") + e.what());
    } catch (const geom::InvalidInput& e) {
        throw geom::ReadError(path, 0, std::string("a face cannot be rebuilt: ") + e.what());
    }
}

}  // namespace trimkit::io
