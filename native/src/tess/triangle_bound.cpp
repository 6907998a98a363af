#include "tess/triangle_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tess/bilinear_error.h"
#include "tess/block_error.h"
#include "tess/derivative_bounds.h"

namespace trimkit::tess {
namespace {

// A box reaching beyond the patches by up to this share of their extent (trim points
// a hair outside the domain, within tessellate_face's margin) is clipped to them.
constexpr double kDomainSlack = 1e-8;

}  // namespace

TriangleBound::TriangleBound(const geom::NurbsSurface& S, const RevolutionShape* shape, ErrorMode mode,
                             double tolerance)
    : S_(S), shape_(shape), mode_(mode), tolerance_(tolerance) {}

void TriangleBound::convert() {
    converted_ = true;
    const std::vector<geom::NurbsSurface> beziers = S_.bezier_patches();
    for (const geom::NurbsSurface& b : beziers) {
        u_.insert(u_.end(), {b.domain_u().first, b.domain_u().second});
        v_.insert(v_.end(), {b.domain_v().first, b.domain_v().second});
    }
    for (auto* x : {&u_, &v_}) {
        std::sort(x->begin(), x->end());
        x->erase(std::unique(x->begin(), x->end()), x->end());
    }
    if (u_.size() < 2 || v_.size() < 2 || (u_.size() - 1) * (v_.size() - 1) != beziers.size()) {
        u_.clear(), v_.clear();  // not a grid of patches: no bound
        return;
    }
    patches_.resize(beziers.size());
    M_.resize(beziers.size());
    for (const geom::NurbsSurface& b : beziers) {
        const long iu = first_span(u_, b.domain_u().first), iv = first_span(v_, b.domain_v().first);
        const size_t k = static_cast<size_t>(iu) * (v_.size() - 1) + static_cast<size_t>(iv);
        patches_[k] = bezier_patch(b);
    }
    has_M_.assign(beziers.size(), 0);
}

long TriangleBound::first_span(const std::vector<double>& lines, double x) {
    const long i = std::upper_bound(lines.begin(), lines.end(), x) - lines.begin() - 1;
    return std::clamp(i, 0L, static_cast<long>(lines.size()) - 2);
}

long TriangleBound::last_span(const std::vector<double>& lines, double x) {
    const long i = std::lower_bound(lines.begin(), lines.end(), x) - lines.begin() - 1;
    return std::clamp(i, 0L, static_cast<long>(lines.size()) - 2);
}

const SecondDerivativeBound& TriangleBound::patch_bound(long k) {
    if (!has_M_[k]) {
        const BezierPatch& p = patches_[k];
        M_[k] = in_surface_parameters(second_derivative_bound(p), p.u1 - p.u0, p.v1 - p.v0);
        has_M_[k] = 1;
    }
    return M_[k];
}

double TriangleBound::operator()(Eigen::AlignedBox2d box) {
    constexpr double kNone = std::numeric_limits<double>::infinity();
    if (!converted_) convert();
    if (u_.empty()) return kNone;
    const Eigen::AlignedBox2d domain(Eigen::Vector2d(u_.front(), v_.front()), Eigen::Vector2d(u_.back(), v_.back()));
    const Eigen::Vector2d slack = kDomainSlack * domain.sizes();
    if (!domain.contains(Eigen::AlignedBox2d(box.min() + slack, box.max() - slack))) return kNone;
    box = box.intersection(domain);
    const long iu0 = first_span(u_, box.min().x()), iu1 = std::max(iu0, last_span(u_, box.max().x()));
    const long iv0 = first_span(v_, box.min().y()), iv1 = std::max(iv0, last_span(v_, box.max().y()));
    const long nv = static_cast<long>(v_.size()) - 1;
    if (iu0 == iu1 && iv0 == iv1) {
        const long k = iu0 * nv + iv0;
        const BezierPatch piece =
            restrict_patch(patches_[k], box.min().x(), box.max().x(), box.min().y(), box.max().y());
        if (shape_) {
            const double exact = revolution_error(*shape_, piece, tolerance_).bound;
            if (std::isfinite(exact)) return exact;
        }
        // The patch's own derivatives first: computed once, they spare most pieces theirs.
        const double coarse = block_error(patch_bound(k), box.sizes().x(), box.sizes().y()).bound;
        if (coarse <= tolerance_) return coarse;
        return std::min(coarse, bilinear_error(piece, mode_, tolerance_).bound);
    }
    if (!is_c1_inside(S_, box)) return kNone;
    SecondDerivativeBound M;
    for (long iu = iu0; iu <= iu1; ++iu)
        for (long iv = iv0; iv <= iv1; ++iv) {
            const SecondDerivativeBound& m = patch_bound(iu * nv + iv);
            M = {std::max(M.M_uu, m.M_uu), std::max(M.M_uv, m.M_uv), std::max(M.M_vv, m.M_vv)};
        }
    return block_error(M, box.sizes().x(), box.sizes().y()).bound;
}

}  // namespace trimkit::tess
