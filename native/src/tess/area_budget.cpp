#include "tess/area_budget.h"

#include <algorithm>
#include <cmath>

namespace trimkit::tess {
namespace {

// A face's cells tightened get at least this fraction of their scale per round.
constexpr double kTightenStep = 0.25;

struct GroupArea {
    double area = 0.0, loss = 0.0;
};

GroupArea group_area(const std::vector<int>& group, const std::vector<FaceArea>& faces) {
    GroupArea sum;
    for (int f : group) {
        sum.area += faces[f].area;
        sum.loss += faces[f].trim_loss + faces[f].cell_loss;
    }
    return sum;
}

// A face's trims or its cells: the area they lose, their points (boundary edges or
// triangles), how the points grow as the scale falls (as scale^-growth), and their scale.
// A cell lever also caps the face's trim scale (`trims`): the triangles along a trim
// span between its points, so cells finer than the trims leave the boundary strip
// as coarse as before (a cylinder between two circles loses what its circles' chords
// give it, whatever its cells).
struct Lever {
    double loss = 0.0;
    double points = 1.0;
    double growth = 1.0;
    double least_factor = 1.0;  // the least factor in one round
    double* scale = nullptr;
    double* trims = nullptr;
};

// Trim points grow as 1/sqrt(t) (chords of a curve); cell triangles as 1/sqrt(t) to
// 1/t (curved one way or both): taken as 1/t, so the trims are preferred. Trims are
// few, so they may fall further in one round.
constexpr double kTrimGrowth = 0.5, kCellGrowth = 1.0;
constexpr double kTrimStep = 1.0 / 16.0;

// The factor (<= 1, >= lever.least_factor) lever gets at multiplier lambda: the
// cheapest way to lose less, sum points k^-growth least for sum loss k fixed, gives
// points growth k^(-growth-1) = lambda loss (a Lagrange multiplier).
double lever_factor(const Lever& lever, double lambda) {
    const double k = std::pow(lever.points * lever.growth / (lambda * lever.loss), 1.0 / (lever.growth + 1.0));
    return std::clamp(k, lever.least_factor, 1.0);
}

// Tightens the levers of one group so that their predicted loss (linear in the
// scale) reaches target_loss at the fewest added points; no lever below
// its least factor in one round, nor below min_scale. True if any scale changed.
// A group that gains area (its chords cut into its holes: a plate with many holes) is
// tightened like one that loses, with the signs turned: `sign` is -1 then.
bool tighten_group(const std::vector<int>& group, const std::vector<FaceArea>& faces, double target_loss,
                   double min_scale, FaceScales& scales) {
    const double signed_loss = group_area(group, faces).loss;
    const double sign = signed_loss < 0.0 ? -1.0 : 1.0;
    const double loss = sign * signed_loss;
    std::vector<Lever> levers;
    double lever_loss = 0.0;
    for (int f : group) {
        const FaceArea& face = faces[f];
        if (sign * face.trim_loss > 0.0 && scales.trim[f] > min_scale)
            levers.push_back({sign * face.trim_loss, std::max(1.0, 1.0 * face.boundary_edges), kTrimGrowth,
                              kTrimStep, &scales.trim[f], nullptr});
        if (sign * face.cell_loss > 0.0 && scales.cell[f] > min_scale)
            levers.push_back({sign * face.cell_loss, std::max(1.0, 1.0 * face.triangles), kCellGrowth, kTightenStep,
                              &scales.cell[f], &scales.trim[f]});
    }
    for (const Lever& lever : levers) lever_loss += lever.loss;
    if (levers.empty() || loss <= target_loss) return false;
    const double fixed_loss = loss - lever_loss;  // what the levers cannot change
    const auto predicted = [&](double lambda) {
        double sum = fixed_loss;
        for (const Lever& lever : levers) sum += lever.loss * lever_factor(lever, lambda);
        return sum;
    };
    // predicted falls as lambda grows: bisect on log(lambda) for predicted = target.
    double low = 1e-30, high = 1e30;
    if (predicted(high) > target_loss) low = high;
    for (int i = 0; i < 200 && high / low > 1.0 + 1e-9; ++i) {
        const double mid = std::sqrt(low * high);
        (predicted(mid) > target_loss ? low : high) = mid;
    }
    bool changed = false;
    for (const Lever& lever : levers) {
        const double k = lever_factor(lever, high);
        if (k >= 1.0) continue;
        *lever.scale = std::max(min_scale, k * *lever.scale);
        changed = true;
    }
    for (const Lever& lever : levers)
        if (lever.trims) *lever.trims = std::min(*lever.trims, *lever.scale);
    return changed;
}

}  // namespace

std::vector<std::vector<int>> part_groups(const geom::Model& model) {
    std::vector<std::vector<int>> groups;
    std::vector<char> in_body(model.faces.size(), 0);
    for (const geom::Body& body : model.bodies) {
        std::vector<int> group;
        for (int f : body.faces)
            if (f >= 0 && f < static_cast<int>(model.faces.size()) && !in_body[f]) {
                in_body[f] = 1;
                group.push_back(f);
            }
        if (!group.empty()) groups.push_back(std::move(group));
    }
    std::vector<int> rest;
    for (size_t f = 0; f < model.faces.size(); ++f)
        if (!in_body[f]) rest.push_back(static_cast<int>(f));
    if (!rest.empty()) groups.push_back(std::move(rest));
    return groups;
}

std::vector<std::vector<int>> area_groups(const geom::Model& model, bool per_body) {
    if (per_body) return part_groups(model);
    if (model.faces.empty()) return {};
    std::vector<int> all(model.faces.size());
    for (size_t f = 0; f < all.size(); ++f) all[f] = static_cast<int>(f);
    return {all};
}

double worst_loss_share(const std::vector<std::vector<int>>& groups, const std::vector<FaceArea>& faces) {
    double worst = 0.0;
    for (const auto& group : groups) {
        const GroupArea sum = group_area(group, faces);
        if (sum.area > 0.0) worst = std::max(worst, std::abs(sum.loss) / sum.area);
    }
    return worst;
}

std::vector<int> tighten_to_area_budget(const std::vector<std::vector<int>>& groups,
                                        const std::vector<FaceArea>& faces, double share, double margin,
                                        double min_scale, FaceScales& scales) {
    std::vector<int> tightened;
    for (size_t g = 0; g < groups.size(); ++g) {
        const GroupArea sum = group_area(groups[g], faces);
        if (!(sum.area > 0.0) || std::abs(sum.loss) <= share * sum.area) continue;
        if (tighten_group(groups[g], faces, margin * share * sum.area, min_scale, scales))
            tightened.push_back(static_cast<int>(g));
    }
    return tightened;
}

}  // namespace trimkit::tess
