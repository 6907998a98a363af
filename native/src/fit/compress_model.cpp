#include "fit/compress_model.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <set>

#include "fit/coedge_edges.h"
#include "fit/coons_fill.h"
#include "fit/edge_faces.h"
#include "fit/extend_model.h"
#include "fit/surface_deviation.h"
#include "fit/g1_angle.h"
#include "fit/judge_g1.h"
#include "fit/periodic_face.h"
#include "fit/stored_numbers.h"
#include "fit/refit_face.h"
#include "geom/error.h"
#include "geom/surface_projector.h"

namespace trimkit::fit {
namespace {

// Edge curves are fitted to this fraction of the face's tolerance, so the
// boundary's own error leaves room for the surface's.
constexpr double kEdgeTolerance = 0.1;

// Box of the face's boundary on its surface (the loops' images), for the relative tolerance.
double boundary_diagonal(const geom::Face& f) {
    Eigen::AlignedBox3d box;
    for (const geom::Loop& loop : f.loops)
        for (const geom::Coedge& c : loop.coedges) {
            const auto [a, b] = c.curve.domain();
            for (int k = 0; k <= 16; ++k) {
                const Eigen::Vector2d uv = c.curve.evaluate(a + (b - a) * k / 16);
                box.extend(f.surface.evaluate(uv.x(), uv.y()));
            }
        }
    return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

// Whether S_u x S_v of the fitted surface points against the source face's normal.
bool fitted_reversed(const geom::Face& source, const geom::NurbsSurface& fitted) {
    const geom::Coedge& c = source.loops.front().coedges.front();
    const Eigen::Vector2d uv = c.curve.evaluate(c.curve.domain().first);
    const Eigen::Vector3d x = source.surface.evaluate(uv.x(), uv.y());
    Eigen::Vector3d n = source.surface.normal(uv.x(), uv.y());
    if (source.reversed) n = -n;
    const Eigen::Vector2d st = geom::SurfaceProjector(fitted).invert(x);
    return fitted.normal(st.x(), st.y()).dot(n) < 0;
}

std::string figure(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}

// Why an accepted-looking fit (error within the tolerance) is rejected, or "" when it
// is not: its G1 angle, or the rebuilt face against the source surface (the other
// direction of `trimkit check A B`). Sets rule.reversed, out.g1_angle, out.reverse_max.
std::string rejection(const geom::Model& m, const EdgeFaces& uses, int face, FitRule& rule,
                      const geom::NurbsSurface& surface, FaceCompression& out) {
    out.g1_angle = g1_angle(m, uses, face, rule, surface);
    if (out.g1_angle > kMaxG1Angle) return "G1 angle " + figure(out.g1_angle) + " deg > " + figure(kMaxG1Angle);
    rule.reversed = fitted_reversed(m.faces[face], surface);
    out.reverse_max = surface_deviation(extend_face(m, face, rule), m.faces[face].surface).max;
    if (!(out.reverse_max <= out.tolerance))
        return "rebuilt face -> source " + figure(out.reverse_max) + " > tolerance " + figure(out.tolerance);
    return "";
}

// The rules tried, smallest first: per count, Coons (Sec. 3, four-sided faces) and
// then Sec. 4 with and without the boundary curves.
std::vector<FitRule> candidate_rules(const geom::Model& m, int face, const FitRule& base) {
    std::vector<FitRule> rules;
    for (const int count : kTriedCounts)
        for (const int variant : {0, 1, 2}) {
            if (variant == 0 && !coons_applicable(m.faces[face], m.edges)) continue;
            FitRule rule = base;
            rule.count_u = rule.count_v = count;
            rule.method = variant == 0 ? FitMethod::kCoons : FitMethod::kBoundaryG1;
            rule.boundary_curves = variant == 1;
            rules.push_back(rule);
        }
    return rules;
}

// Tries the rules in order; true with `out` filled for the first one accepted. With
// `rebuild`, when none is, the first (fewest control points) that keeps G1 is taken:
// the fit never sees the face's own surface, and a damaged one is no guide to which
// rule is right.
bool try_rules(const geom::Model& m, int face, FaceCompression& out, bool rebuild) {
    const EdgeFaces uses = edge_faces(m);
    double best = 1e300;
    std::string rejected;  // why the last fit within the tolerance was not accepted
    std::optional<FaceCompression> fallback;  // rebuild: the first fit that keeps G1
    for (FitRule rule : candidate_rules(m, face, out.rule)) {
        try {
            const RefitResult fit = refit_face(m, uses, face, rule);
            const FitError error = evaluate_fit(m.faces[face], m.edges, fit.surface);
            if (error.max() < best) best = error.max(), out.error = error;
            if (rebuild && !fallback) {
                FaceCompression candidate = out;
                candidate.g1_angle = g1_angle(m, uses, face, rule, fit.surface);
                if (candidate.g1_angle <= kMaxG1Angle) {
                    rule.reversed = fitted_reversed(m.faces[face], fit.surface);
                    candidate.rule = rule;
                    candidate.error = error;
                    fallback = candidate;
                }
            }
            if (!(error.max() <= out.tolerance)) continue;
            rejected = rejection(m, uses, face, rule, fit.surface, out);
            if (!rejected.empty()) continue;
            out.rule = rule;
            out.error = error;
            return true;
        } catch (const std::exception& e) {
            out.reason = std::string("fit failed: ") + e.what();
        }
    }
    if (!rejected.empty()) out.reason = rejected;
    else if (best < 1e300) out.reason = "max error " + figure(best) + " > tolerance " + figure(out.tolerance);
    if (!fallback) return false;
    fallback->reason = "rebuilt beyond the tolerance: max error " + figure(fallback->error.max()) + " > " +
                       figure(out.tolerance);
    out = *fallback;
    return true;
}

// The faces across the coedges out.rule.g1 marks (counted in out.g1_edges).
std::vector<int> g1_neighbours(const geom::Model& m, int face, FaceCompression& out) {
    const EdgeFaces uses = edge_faces(m);
    std::vector<int> neighbours;
    for (std::size_t l = 0; l < out.rule.g1.size(); ++l)
        for (std::size_t c = 0; c < out.rule.g1[l].size(); ++c)
            if (out.rule.g1[l][c]) {
                ++out.g1_edges;
                neighbours.push_back(neighbour_face(m, uses, face, static_cast<int>(l), static_cast<int>(c)));
            }
    return neighbours;
}

// One face of compress_model: true when compressed (result and pinned updated);
// otherwise the face and the edges are left as they were.
bool compress_face(CompressedModel& result, int f, std::vector<bool>& pinned, FaceCompression& out, bool rebuild) {
    geom::Model& m = result.model;
    const geom::Face before = m.faces[f];
    const std::vector<geom::Edge> edges_before = m.edges;
    if (!add_coedge_edges(m, f, kEdgeTolerance * out.tolerance)) {
        out.reason = "a boundary curve cannot be fitted within the tolerance";
        return false;
    }
    const std::vector<int> neighbours = g1_neighbours(m, f, out);
    bool blocked = false;
    for (const int n : neighbours) blocked = blocked || result.rules[n].has_value();
    const std::size_t added = added_numbers(edges_before, m.edges), kept = kept_numbers(before);
    if (blocked) {
        out.reason = "a G1 neighbour is compressed";
    } else if (!try_rules(m, f, out, rebuild)) {
        // out.reason says why
    } else if (added >= kept && !rebuild) {
        out.reason = "its new edge curves (" + std::to_string(added) + " numbers) cost more than its surface and trim curves (" +
                     std::to_string(kept) + ")";
    } else {
        out.compressed = true;
        result.rules[f] = out.rule;
        for (const int n : neighbours) pinned[n] = true;
        return true;
    }
    m.faces[f] = before;
    m.edges = edges_before;
    return false;
}

}  // namespace

CompressedModel compress_model(const geom::Model& model, const CompressOptions& options,
                               std::vector<FaceCompression>* report) {
    CompressedModel result{model, std::vector<std::optional<FitRule>>(model.faces.size())};
    // G1 judged once on the model as read (the edges compression adds are unshared, so
    // never G1); faces with fewer G1 neighbours go first, since compressing a face pins
    // its G1 neighbours (a fillet between two faces waits for both).
    const EdgeFaces uses = edge_faces(model);
    std::vector<std::vector<std::vector<bool>>> g1(model.faces.size());
    std::vector<std::size_t> degree(model.faces.size(), 0);
    std::vector<bool> selected(model.faces.size(), options.faces.empty());
    for (const int f : options.faces)
        if (f >= 0 && f < static_cast<int>(selected.size())) selected[f] = true;
    for (int f = 0; f < static_cast<int>(model.faces.size()); ++f) {
        g1[f] = judge_g1(model, uses, f, options.rebuild && selected[f] ? kRebuildG1JudgeAngle : kG1JudgeAngle);
        std::set<int> neighbours;
        for (std::size_t l = 0; l < g1[f].size(); ++l)
            for (std::size_t c = 0; c < g1[f][l].size(); ++c)
                if (g1[f][l][c]) neighbours.insert(neighbour_face(model, uses, f, static_cast<int>(l), static_cast<int>(c)));
        degree[f] = neighbours.size();
    }
    std::vector<int> order(model.faces.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return degree[a] < degree[b]; });
    geom::Model& m = result.model;
    std::vector<bool> pinned(model.faces.size(), false);  // must keep its surface
    std::vector<FaceCompression> faces(model.faces.size());
    std::vector<bool> candidate(model.faces.size(), options.faces.empty());
    for (const int f : options.faces)
        if (f >= 0 && f < static_cast<int>(candidate.size())) candidate[f] = true;
    for (const int f : order) {
        FaceCompression& out = faces[f];
        const double size = boundary_diagonal(m.faces[f]);
        out.tolerance = options.tolerance > 0 ? options.tolerance : options.relative_tolerance * size;
        out.rule.tolerance = out.tolerance;
        out.rule.g1 = g1[f];
        if (!candidate[f]) out.reason = "not selected";
        else if (pinned[f]) out.reason = "G1 neighbour of a compressed face";
        else if (is_periodic_face(m.faces[f], size)) out.reason = "periodic surface (Sec. 6), kept";
        else compress_face(result, f, pinned, out, options.rebuild);
    }
    if (report) *report = std::move(faces);
    return result;
}

}  // namespace trimkit::fit
