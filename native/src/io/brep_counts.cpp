#include "io/brep_counts.h"

#include <algorithm>
#include <cstdlib>
#include <string_view>

#include "geom/error.h"

namespace trimkit::io {
namespace {

// Stops the walk of a section: an item the walk does not know.
struct UnknownItem {};

bool blank(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f'; }

class Walk {
public:
    Walk(const std::string& text, const std::string& path) : text_(text), path_(path) {
        version3_ = text.substr(0, 512).find("CASCADE Topology V3") != std::string::npos;
    }

    void run() {
        section("Curve2ds", "Curves", [&] { curve(2, 0); });
        section("Curves", "Polygon3D", [&] { curve(3, 0); });
        section("Polygon3D", "PolygonOnTriangulations", [&] { polygon3d(); });
        section("PolygonOnTriangulations", "Surfaces", [&] { polygon_on_triangulation(); });
        section("Surfaces", "Triangulations", [&] { surface(0); });
        section("Triangulations", "TShapes", [&] { triangulation(); });
    }

private:
    // Where the next token starts (the end of the text when none is left).
    std::size_t next_start() {
        while (pos_ < text_.size() && blank(text_[pos_])) ++pos_;
        return pos_;
    }
    // The next token, without taking it.
    std::string_view peek() {
        const std::size_t start = next_start();
        std::size_t end = start;
        while (end < text_.size() && !blank(text_[end])) ++end;
        return std::string_view(text_).substr(start, end - start);
    }
    void take() {
        const std::string_view t = peek();
        if (t.empty()) throw UnknownItem{};
        pos_ += t.size();
    }
    // Tokens that can follow: each takes a character and a blank but the last.
    double left() const { return 0.5 * double(text_.size() - pos_ + 1); }

    long integer() {
        const std::string word(peek());
        char* end = nullptr;
        const long value = std::strtol(word.c_str(), &end, 10);
        if (word.empty() || *end != '\0') throw UnknownItem{};
        take();
        return value;
    }
    long flag() {
        const long f = integer();
        if (f != 0 && f != 1) throw UnknownItem{};
        return f;
    }
    long degree() {
        const long d = integer();
        if (d < 0 || d > kMaxBrepDegree) throw UnknownItem{};
        return d;
    }
    // A count of items, each `tokens_each` tokens or more: at most what is left.
    long count(double tokens_each = 1.0) {
        const std::size_t where = next_start();
        const long n = integer();
        if (n < 0 || double(n) * tokens_each > left())
            throw geom::ReadError(path_, line_of(where),
                                  "count " + std::to_string(n) + " in the " + std::string(section_) +
                                      " section does not fit the rest of the file (a damaged file?)");
        return n;
    }
    void skip(double tokens) {
        if (tokens > left()) throw UnknownItem{};
        for (auto n = static_cast<std::size_t>(tokens); n > 0; --n) take();
    }
    int line_of(std::size_t offset) const {
        return 1 + static_cast<int>(std::count(text_.begin(), text_.begin() + offset, '\n'));
    }

    template <class Item>
    void section(const char* name, const char* next, const Item& item) {
        while (!peek().empty() && peek() != name) take();
        if (peek().empty()) return;
        section_ = name;
        take();
        const std::size_t header = pos_;
        try {
            const long n = count();
            for (long k = 0; k < n; ++k) item();
            if (peek() == next) return;
        } catch (const UnknownItem&) {
        }
        pos_ = header;  // the next section is searched from here
    }

    // GeomTools_Curve2dSet / GeomTools_CurveSet items (dim 2 or 3).
    void curve(int dim, int depth) {
        if (depth > kMaxBrepNesting) throw UnknownItem{};
        const long type = integer();
        static const int fixed2[] = {0, 4, 7, 8, 7, 8}, fixed3[] = {0, 6, 13, 14, 13, 14};
        if (type >= 1 && type <= 5) return skip(dim == 2 ? fixed2[type] : fixed3[type]);
        switch (type) {
        case 6: {  // Bezier: rational, degree, poles (with weights)
            const long rational = flag(), d = degree();
            return skip(double(d + 1) * (dim + rational));
        }
        case 7: {  // B-spline: rational, periodic, degree, poles, knots (value, multiplicity)
            const long rational = flag();
            flag();
            degree();
            const long poles = count(dim + rational), knots = count(2.0);
            return skip(double(poles) * (dim + rational) + 2.0 * knots);
        }
        case 8:  // trimmed: first, last, basis
            skip(2);
            return curve(dim, depth + 1);
        case 9:  // offset: distance (and direction in 3D), basis
            skip(dim == 2 ? 1 : 4);
            return curve(dim, depth + 1);
        default:
            throw UnknownItem{};
        }
    }

    // GeomTools_SurfaceSet items.
    void surface(int depth) {
        if (depth > kMaxBrepNesting) throw UnknownItem{};
        const long type = integer();
        static const int fixed[] = {0, 12, 13, 14, 13, 14};
        if (type >= 1 && type <= 5) return skip(fixed[type]);
        switch (type) {
        case 6:  // linear extrusion: direction, basis curve
            skip(3);
            return curve(3, depth + 1);
        case 7:  // revolution: location, direction, basis curve
            skip(6);
            return curve(3, depth + 1);
        case 8: {  // Bezier: u, v rational, degrees, poles (with weights)
            const long rational = std::max(flag(), flag()), du = degree(), dv = degree();
            return skip(double(du + 1) * (dv + 1) * (3 + rational));
        }
        case 9: {  // B-spline
            const long rational = std::max(flag(), flag());
            flag();
            flag();
            degree();
            degree();
            const long nu = count(), nv = count(double(nu) * (3 + rational));
            const long ku = count(2.0), kv = count(2.0);
            return skip(double(nu) * nv * (3 + rational) + 2.0 * (ku + kv));
        }
        case 10:  // rectangular trimmed: u1 u2 v1 v2, basis
            skip(4);
            return surface(depth + 1);
        case 11:  // offset: distance, basis
            skip(1);
            return surface(depth + 1);
        default:
            throw UnknownItem{};
        }
    }

    void polygon3d() {  // nodes, parameters flag, deflection, points (, parameters)
        const long nodes = count(3.0);
        const long parameters = flag();
        skip(1 + 3.0 * nodes + (parameters ? nodes : 0));
    }

    void polygon_on_triangulation() {  // nodes, node indices, "p", deflection, flag (, parameters)
        const long nodes = count();
        skip(double(nodes));
        if (peek() != "p") throw UnknownItem{};
        skip(2);
        if (flag()) skip(double(nodes));
    }

    void triangulation() {  // nodes, triangles, uv flag (, normals flag), deflection, arrays
        const long nodes = count(3.0), triangles = count(3.0);
        const long uv = flag(), normals = version3_ ? flag() : 0;
        skip(1 + 3.0 * nodes + (uv ? 2.0 * nodes : 0) + 3.0 * triangles + (normals ? 3.0 * nodes : 0));
    }

    const std::string& text_;
    const std::string& path_;
    std::size_t pos_ = 0;  // offset of the walk
    bool version3_ = false;
    std::string_view section_;
};

}  // namespace

void check_brep_counts(const std::string& text, const std::string& path) {
    Walk(text, path).run();
}

}  // namespace trimkit::io
