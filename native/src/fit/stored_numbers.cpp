#include "fit/stored_numbers.h"

namespace trimkit::fit {
namespace {

// Numbers (doubles) a face's geometry costs stored: its surface and trim curves when
// kept; the 3D curves of the edges it adds when compressed (the rule is a few bytes).
template <int Dim>
std::size_t curve_numbers(const geom::NurbsCurve<Dim>& c) {
    return c.knots().size() + c.points().size() * (Dim + (c.is_rational() ? 1 : 0));
}

}  // namespace

std::size_t kept_numbers(const geom::Face& f) {
    const geom::NurbsSurface& s = f.surface;
    std::size_t n = s.knots_u().size() + s.knots_v().size() + s.points().size() * (s.is_rational() ? 4 : 3);
    for (const geom::Loop& loop : f.loops)
        for (const geom::Coedge& c : loop.coedges) n += curve_numbers(c.curve);
    return n;
}

std::size_t added_numbers(const std::vector<geom::Edge>& before, const std::vector<geom::Edge>& after) {
    std::size_t n = 0;
    for (std::size_t e = 0; e < after.size(); ++e)
        if (after[e].curve && (e >= before.size() || !before[e].curve)) n += curve_numbers(*after[e].curve);
    return n;
}

}  // namespace trimkit::fit
