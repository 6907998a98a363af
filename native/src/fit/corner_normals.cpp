#include "fit/corner_normals.h"

namespace trimkit::fit {
namespace {

// The samples of one loop: [first, last] in `samples`.
void loop_normals(const std::vector<BoundarySample>& s, std::size_t first, std::size_t last, const Eigen::Vector3d& up,
                  std::vector<std::optional<Eigen::Vector3d>>& out) {
    const std::size_t n = last - first + 1;
    std::vector<double> at(n + 1, 0.0);  // boundary length from the loop's first sample
    for (std::size_t i = 1; i <= n; ++i) at[i] = at[i - 1] + (s[first + i % n].x - s[first + i - 1].x).norm();
    const double total = at[n];
    std::vector<std::size_t> corners;
    std::vector<Eigen::Vector3d> normals;
    std::size_t previous_start = last;  // the last coedge's first sample, for the incoming tangent
    for (std::size_t i = first; i <= last; ++i)
        if (i == first || s[i].coedge != s[i - 1].coedge) previous_start = i;
    for (std::size_t i = first; i <= last; ++i) {
        if (i != first && s[i].coedge == s[i - 1].coedge) continue;
        const Eigen::Vector3d t_in = s[previous_start].end_tangent;
        previous_start = i;
        Eigen::Vector3d c = t_in.cross(s[i].tangent);
        if (!(c.norm() >= kCornerSine)) continue;
        c.normalize();
        corners.push_back(i - first);
        normals.push_back(c.dot(up) < 0 ? Eigen::Vector3d(-c) : c);
    }
    if (corners.empty()) return;
    const std::size_t m = corners.size();
    for (std::size_t k = 0; k < n; ++k) {
        // The corners before and after k along the loop (cyclically).
        std::size_t b = m - 1;
        for (std::size_t j = 0; j < m; ++j)
            if (corners[j] <= k) b = j;
        const std::size_t a = (b + 1) % m;
        double from = at[corners[b]], to = at[corners[a]], here = at[k];
        if (to <= from) to += total;
        if (here < from) here += total;
        const double w = to > from ? (here - from) / (to - from) : 0.0;
        const Eigen::Vector3d v = (1 - w) * normals[b] + w * normals[a];
        if (v.norm() > 1e-9) out[first + k] = v.normalized();
    }
}

}  // namespace

std::vector<std::optional<Eigen::Vector3d>> corner_normals(const std::vector<BoundarySample>& samples,
                                                           const Eigen::Vector3d& up) {
    std::vector<std::optional<Eigen::Vector3d>> out(samples.size());
    std::size_t first = 0;
    for (std::size_t i = 0; i < samples.size(); ++i)
        if (i + 1 == samples.size() || samples[i + 1].loop != samples[i].loop) {
            loop_normals(samples, first, i, up, out);
            first = i + 1;
        }
    return out;
}

}  // namespace trimkit::fit
