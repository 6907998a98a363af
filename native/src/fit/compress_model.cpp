#include "fit/compress_model.h"

#include <cstdio>
#include <set>

#include "fit/coedge_edges.h"
#include "fit/coons_fill.h"
#include "fit/edge_faces.h"
#include "fit/extend_model.h"
#include "fit/surface_deviation.h"
#include "fit/g1_angle.h"
#include "fit/judge_g1.h"
#include "fit/refit_face.h"
#include "geom/error.h"
#include "geom/extend_closed_surface.h"
#include "geom/surface_projector.h"

namespace trimkit::fit {
namespace {

// Edge curves are fitted to this fraction of the face's tolerance, so the
// boundary's own error leaves room for the surface's.
constexpr double kEdgeTolerance = 0.1;
// Fraction of a closed direction's period the loops must span to make the face periodic.
constexpr double kPeriodicSpan = 0.99;

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

bool is_periodic(const geom::Face& f, double size) {
    std::set<int> seen;
    Eigen::AlignedBox2d uv;
    for (const geom::Loop& loop : f.loops)
        for (const geom::Coedge& c : loop.coedges) {
            if (c.edge >= 0 && !seen.insert(c.edge).second) return true;  // a seam
            uv.extend(c.curve.control_box());
        }
    const double tolerance = 1e-7 * std::max(size, 1e-300);
    const auto [u0, u1] = f.surface.domain_u();
    const auto [v0, v1] = f.surface.domain_v();
    if (geom::is_closed_surface(f.surface, 0, tolerance) && uv.sizes().x() >= kPeriodicSpan * (u1 - u0)) return true;
    if (geom::is_closed_surface(f.surface, 1, tolerance) && uv.sizes().y() >= kPeriodicSpan * (v1 - v0)) return true;
    return false;
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

// Numbers (doubles) a face's geometry costs stored: its surface and trim curves when
// kept; the 3D curves of the edges it adds when compressed (the rule is a few bytes).
template <int Dim>
std::size_t numbers(const geom::NurbsCurve<Dim>& c) {
    return c.knots().size() + c.points().size() * (Dim + (c.is_rational() ? 1 : 0));
}

std::size_t kept_numbers(const geom::Face& f) {
    const geom::NurbsSurface& s = f.surface;
    std::size_t n = s.knots_u().size() + s.knots_v().size() + s.points().size() * (s.is_rational() ? 4 : 3);
    for (const geom::Loop& loop : f.loops)
        for (const geom::Coedge& c : loop.coedges) n += numbers(c.curve);
    return n;
}

std::size_t added_numbers(const std::vector<geom::Edge>& before, const std::vector<geom::Edge>& after) {
    std::size_t n = 0;
    for (std::size_t e = 0; e < after.size(); ++e)
        if (after[e].curve && (e >= before.size() || !before[e].curve)) n += numbers(*after[e].curve);
    return n;
}

std::string figure(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}

// Tries the rules in order; returns true with `out` filled for the first within tolerance.
bool try_rules(const geom::Model& m, int face, FaceCompression& out) {
    const EdgeFaces uses = edge_faces(m);
    double best = 1e300;
    bool best_angle_failed = false;  // a fit was within the tolerance but failed G1 or the other direction
    const bool coons = coons_applicable(m.faces[face], m.edges);
    for (const int count : kTriedCounts)
        for (const int variant : {0, 1, 2}) {  // Coons (Sec. 3), then Sec. 4 with and without boundary curves
            if (variant == 0 && !coons) continue;
            FitRule rule = out.rule;
            rule.count_u = rule.count_v = count;
            rule.method = variant == 0 ? FitMethod::kCoons : FitMethod::kBoundaryG1;
            rule.boundary_curves = variant == 1;
            try {
                const RefitResult fit = refit_face(m, uses, face, rule);
                const FitError error = evaluate_fit(m.faces[face], m.edges, fit.surface);
                if (error.max() < best) best = error.max(), out.error = error;
                const double angle = g1_angle(m, uses, face, rule, fit.surface);
                if (error.max() <= out.tolerance && angle > kMaxG1Angle) {
                    out.reason = "G1 angle " + figure(angle) + " deg > " + figure(kMaxG1Angle);
                    best_angle_failed = true;
                    continue;
                }
                if (error.max() <= out.tolerance) {
                    // The other direction (what `trimkit check A B` measures too): the
                    // rebuilt face's grid onto the source surface.
                    rule.reversed = fitted_reversed(m.faces[face], fit.surface);
                    const SurfaceDeviation back = surface_deviation(extend_face(m, face, rule), m.faces[face].surface);
                    out.reverse_max = back.max;
                    if (!(back.max <= out.tolerance)) {
                        out.reason = "rebuilt face -> source " + figure(back.max) + " > tolerance " + figure(out.tolerance);
                        best_angle_failed = true;
                        continue;
                    }
                    out.g1_angle = angle;
                    rule.reversed = fitted_reversed(m.faces[face], fit.surface);
                    out.rule = rule;
                    out.error = error;
                    return true;
                }
            } catch (const std::exception& e) {
                out.reason = std::string("fit failed: ") + e.what();
            }
        }
    if (best < 1e300 && !best_angle_failed)
        out.reason = "max error " + figure(best) + " > tolerance " + figure(out.tolerance);
    return false;
}

}  // namespace

CompressedModel compress_model(const geom::Model& model, const CompressOptions& options,
                               std::vector<FaceCompression>* report) {
    CompressedModel result{model, std::vector<std::optional<FitRule>>(model.faces.size())};
    geom::Model& m = result.model;
    std::vector<bool> pinned(model.faces.size(), false);  // must keep its surface
    std::vector<FaceCompression> faces(model.faces.size());
    std::vector<bool> candidate(model.faces.size(), options.faces.empty());
    for (const int f : options.faces)
        if (f >= 0 && f < static_cast<int>(candidate.size())) candidate[f] = true;
    for (int f = 0; f < static_cast<int>(m.faces.size()); ++f) {
        FaceCompression& out = faces[f];
        const double size = boundary_diagonal(m.faces[f]);
        out.tolerance = options.tolerance > 0 ? options.tolerance : options.relative_tolerance * size;
        out.rule.tolerance = out.tolerance;
        if (!candidate[f]) { out.reason = "not selected"; continue; }
        if (pinned[f]) { out.reason = "G1 neighbour of a compressed face"; continue; }
        if (is_periodic(m.faces[f], size)) { out.reason = "periodic surface (Sec. 6), kept"; continue; }
        const geom::Face before = m.faces[f];
        const std::vector<geom::Edge> edges_before = m.edges;
        if (!add_coedge_edges(m, f, kEdgeTolerance * out.tolerance)) {
            out.reason = "a boundary curve cannot be fitted within the tolerance";
            continue;
        }
        const EdgeFaces uses = edge_faces(m);
        out.rule.g1 = judge_g1(m, uses, f);
        std::vector<int> g1_neighbours;
        for (std::size_t l = 0; l < out.rule.g1.size(); ++l)
            for (std::size_t c = 0; c < out.rule.g1[l].size(); ++c)
                if (out.rule.g1[l][c]) {
                    ++out.g1_edges;
                    g1_neighbours.push_back(neighbour_face(m, uses, f, static_cast<int>(l), static_cast<int>(c)));
                }
        bool blocked = false;
        for (const int n : g1_neighbours)
            if (result.rules[n]) blocked = true;
        if (blocked) {
            out.reason = "a G1 neighbour is compressed";
        } else if (!try_rules(m, f, out)) {
            // out.reason says why
        } else if (added_numbers(edges_before, m.edges) >= kept_numbers(before)) {
            out.reason = "its new edge curves (" + std::to_string(added_numbers(edges_before, m.edges)) +
                         " numbers) cost more than its surface and trim curves (" +
                         std::to_string(kept_numbers(before)) + ")";
        } else {
            out.compressed = true;
            result.rules[f] = out.rule;
            for (const int n : g1_neighbours) pinned[n] = true;
            continue;
        }
        m.faces[f] = before;  // kept: the face and the edges as they were
        m.edges = edges_before;
    }
    if (report) *report = std::move(faces);
    return result;
}

}  // namespace trimkit::fit
