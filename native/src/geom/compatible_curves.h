// Compatible curves: two NURBS curves rewritten, without changing their shapes,
// with the same degree and the same knot vector on the domain [0, 1], as needed
// to build ruled and lofted surfaces between them ([PT] Sec. 8.4), and, when
// needed, with the same weights. Each curve is first mapped affinely onto [0, 1],
// so equal parameters mean equal fractions of the original domains.
#pragma once

#include <utility>

#include "geom/nurbs_curve.h"

namespace trimkit::geom {

// (a', b'): a and b reparameterised to [0, 1], the lower degree raised to the
// higher ([PT] A5.9, see elevate_degree) and the knots of each inserted into the
// other ([PT] A5.1; knots within kKnotTolerance are merged), so that
// a'.knots() == b'.knots() exactly and both are clamped.
template <int Dim>
std::pair<NurbsCurve<Dim>, NurbsCurve<Dim>> make_compatible(const NurbsCurve<Dim>& a,
                                                            const NurbsCurve<Dim>& b);

extern template std::pair<NurbsCurve<2>, NurbsCurve<2>> make_compatible(const NurbsCurve<2>&,
                                                                        const NurbsCurve<2>&);
extern template std::pair<NurbsCurve<3>, NurbsCurve<3>> make_compatible(const NurbsCurve<3>&,
                                                                        const NurbsCurve<3>&);

// (a', b'): compatible a and b (same degree p and knots, as from make_compatible)
// rewritten over one common denominator, so a'.weights() == b'.weights(): the
// numerators are multiplied by the other curve's weight function, A·W_b / (W_a·W_b).
// Then (1 - v) a'(u) + v b'(u) is an affine combination of homogeneous points,
// which ruled surfaces need for v to be the exact fraction along each ruling.
// Curves with equal weights (or both non-rational) are returned unchanged;
// otherwise the result has degree 2p and C0 knots of multiplicity 2p (exact, from
// products of Bézier segments; re-derived from the Bernstein product rule,
// [PT] Sec. 5.6 is the companion for decomposition).
template <int Dim>
std::pair<NurbsCurve<Dim>, NurbsCurve<Dim>> make_compatible_weights(const NurbsCurve<Dim>& a,
                                                                    const NurbsCurve<Dim>& b);

extern template std::pair<NurbsCurve<2>, NurbsCurve<2>> make_compatible_weights(
    const NurbsCurve<2>&, const NurbsCurve<2>&);
extern template std::pair<NurbsCurve<3>, NurbsCurve<3>> make_compatible_weights(
    const NurbsCurve<3>&, const NurbsCurve<3>&);

}  // namespace trimkit::geom
