#include "tess/measure_deviation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>

#include "geom/error.h"
#include "geom/surface_projector.h"
#include "mesh/open_edges.h"
#include "mesh/parallel_for.h"
#include "mesh/weld_vertices.h"
#include "tess/foot_point.h"
#include "tess/surface_evaluator.h"
#include "tess/triangle_bvh.h"

namespace trimkit::tess {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Triangles per mesh->surface work item: large enough to amortise scheduling,
// small enough to balance two to dozens of threads.
constexpr int kTriangleChunk = 256;
// A projected distance above this fraction of the triangle's longest edge is
// checked again from the projector's grid: a chord's sagitta is edge²/(8R), so
// a faithful mesh stays far below it unless R is under ~12 edges.
constexpr double kSuspectDistance = 0.01;
// Starts per direction of the retry of a suspect projection.
constexpr int kRetryGrid = 4;
// A foot point within this fraction of the domain of a boundary may be clamped
// there (a seam of a closed surface, a pole): such projections are retried.
constexpr double kBoundaryZone = 1e-6;
// Isolines and points per isoline used to estimate a face's 3D extent in u and v.
constexpr int kExtentLines = 5, kExtentPoints = 17;


// Running max / sum / count of one direction over a part of the work.
struct Accumulator {
    double max = 0.0, sum = 0.0;
    std::size_t count = 0;
    DeviationLocation worst;

    void add(double d, int face, const Eigen::Vector3d& p) {
        if (count == 0 || d > max) {
            max = d;
            worst = {face, p};
        }
        sum += d;
        ++count;
    }
    void merge(const Accumulator& o) {
        if (o.count == 0) return;
        if (count == 0 || o.max > max) {
            max = o.max;
            worst = o.worst;
        }
        sum += o.sum;
        count += o.count;
    }
    DirectionDeviation result() const {
        DirectionDeviation d;
        d.max = max;
        d.mean = count > 0 ? sum / static_cast<double>(count) : 0.0;
        d.samples = count;
        d.worst = worst;
        return d;
    }
};

double median(std::vector<double> x) {
    if (x.empty()) return kNaN;
    auto mid = x.begin() + x.size() / 2;
    std::nth_element(x.begin(), mid, x.end());
    return *mid;
}

// Longest polyline length of kExtentLines isolines in u (along_u) or v over the box.
double isoline_length(const geom::NurbsSurface& s, const Eigen::AlignedBox2d& box, bool along_u) {
    double longest = 0.0;
    for (int l = 0; l < kExtentLines; ++l) {
        const double c = along_u ? box.min().y() + box.sizes().y() * l / (kExtentLines - 1)
                                 : box.min().x() + box.sizes().x() * l / (kExtentLines - 1);
        double length = 0.0;
        Eigen::Vector3d prev;
        for (int k = 0; k < kExtentPoints; ++k) {
            const double t = along_u ? box.min().x() + box.sizes().x() * k / (kExtentPoints - 1)
                                     : box.min().y() + box.sizes().y() * k / (kExtentPoints - 1);
            const Eigen::Vector3d p = along_u ? s.evaluate(t, c) : s.evaluate(c, t);
            if (k > 0) length += (p - prev).norm();
            prev = p;
        }
        longest = std::max(longest, length);
    }
    return longest;
}

void validate(const geom::Model& model, const mesh::Mesh& mesh, const DeviationOptions& o) {
    if (o.samples < 1) throw geom::InvalidInput("DeviationOptions: samples = " + std::to_string(o.samples) + "; expected >= 1");
    if (o.threads < 0) throw geom::InvalidInput("DeviationOptions: threads = " + std::to_string(o.threads) + "; expected >= 0");
    if (o.max_face_samples < 4)
        throw geom::InvalidInput("DeviationOptions: max_face_samples = " + std::to_string(o.max_face_samples) + "; expected >= 4");
    if (o.area_cells < 1 || o.area_levels < 0)
        throw geom::InvalidInput("DeviationOptions: area_cells = " + std::to_string(o.area_cells) + ", area_levels = " +
                                 std::to_string(o.area_levels) + "; expected >= 1 and >= 0");
    mesh::validate(mesh);
    if (mesh.triangles.empty()) throw geom::InvalidInput("measure_deviation: the mesh has no triangles");
    for (std::size_t t = 0; t < mesh.face_ids.size(); ++t)
        if (mesh.face_ids[t] >= static_cast<std::int32_t>(model.faces.size()))
            throw geom::InvalidInput("measure_deviation: face_ids[" + std::to_string(t) + "] = " +
                                     std::to_string(mesh.face_ids[t]) + "; the model has " +
                                     std::to_string(model.faces.size()) + " faces");
}

}  // namespace

DeviationReport measure_deviation(const geom::Model& model, const mesh::Mesh& mesh,
                                  const DeviationOptions& options) {
    validate(model, mesh, options);
    const int threads = mesh::resolve_threads(options.threads);
    const int nf = static_cast<int>(model.faces.size());
    const int nt = static_cast<int>(mesh.triangles.size());
    const int n = options.samples;
    DeviationReport report;
    report.faces = nf;
    report.triangles = mesh.triangles.size();
    report.face_mesh_to_surface.assign(nf, kNaN);
    report.face_surface_to_mesh.assign(nf, kNaN);
    report.face_area_exact.assign(nf, 0.0);

    // ---- Per face: trim region, exact area, projector ----
    std::vector<std::unique_ptr<TrimRegion>> regions(nf);
    std::vector<std::unique_ptr<geom::SurfaceProjector>> projectors(nf);
    std::vector<std::string> face_warning(nf);
    mesh::parallel_for(nf, threads, [&](int f) {
        const geom::Face& face = model.faces[f];
        try {
            regions[f] = std::make_unique<TrimRegion>(face, options.trim);
            report.face_area_exact[f] = trimmed_area(face.surface, *regions[f], options.area_cells, options.area_levels);
            projectors[f] = std::make_unique<geom::SurfaceProjector>(face.surface);
        } catch (const geom::InvalidInput& e) {
            regions[f].reset();
            face_warning[f] = "face " + std::to_string(f) + ": " + e.what();
        } catch (const geom::NumericalFailure& e) {
            regions[f].reset();
            face_warning[f] = "face " + std::to_string(f) + ": " + e.what();
        }
    });
    for (const auto& w : face_warning)
        if (!w.empty()) report.warnings.push_back(w);

    // Median shortest triangle edge, per face (with face ids) and overall.
    std::vector<double> shortest(nt);
    for (int t = 0; t < nt; ++t) {
        const auto& tri = mesh.triangles[t];
        double e = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 3; ++k) {
            const double l = (mesh.positions[tri[k]] - mesh.positions[tri[(k + 1) % 3]]).norm();
            if (l > 0) e = std::min(e, l);
        }
        shortest[t] = e;
    }
    std::vector<double> finite_shortest;
    for (double e : shortest)
        if (std::isfinite(e)) finite_shortest.push_back(e);
    const double global_edge = median(finite_shortest);
    std::vector<double> face_edge(nf, global_edge);
    if (mesh.has_face_ids()) {
        std::vector<std::vector<double>> per(nf);
        for (int t = 0; t < nt; ++t)
            if (std::isfinite(shortest[t])) per[mesh.face_ids[t]].push_back(shortest[t]);
        for (int f = 0; f < nf; ++f)
            if (!per[f].empty()) face_edge[f] = median(std::move(per[f]));
    }

    // ---- Surface -> mesh ----
    const TriangleBvh bvh(mesh);
    std::vector<Accumulator> s2m(nf);
    mesh::parallel_for(nf, threads, [&](int f) {
        if (!regions[f]) return;
        const TrimRegion& region = *regions[f];
        const geom::NurbsSurface& s = model.faces[f].surface;
        const Eigen::AlignedBox2d& box = region.box();
        Accumulator acc;
        SurfaceEvaluator eval(s);
        Eigen::Vector3d S, Su, Sv;
        const auto sample = [&](double u, double v) {
            eval.evaluate(u, v, S, Su, Sv);
            const TriangleBvh::Hit hit = bvh.closest(S);
            acc.add(hit.distance, f, S);
        };
        double h = face_edge[f] / n;
        if (!(h > 0) || !std::isfinite(h)) h = std::max(box.sizes().maxCoeff(), 1e-300);
        double nu = std::ceil(isoline_length(s, box, true) / h) + 1;
        double nv = std::ceil(isoline_length(s, box, false) / h) + 1;
        const double budget = 0.75 * options.max_face_samples;  // a quarter for the trim polygons
        if (nu * nv > budget) {
            const double shrink = std::sqrt(budget / (nu * nv));
            nu = std::max(2.0, std::floor(nu * shrink));
            nv = std::max(2.0, std::floor(nv * shrink));
        }
        const int iu = std::max(2, static_cast<int>(nu)), iv = std::max(2, static_cast<int>(nv));
        std::vector<double> us(iu);
        for (int i = 0; i < iu; ++i) us[i] = box.min().x() + box.sizes().x() * i / (iu - 1);
        for (int j = 0; j < iv; ++j) {
            const double v = box.min().y() + box.sizes().y() * j / (iv - 1);
            const std::vector<double> x = region.crossings(v);
            // Walk the sorted crossings along the row: inside between x[2k] and x[2k+1].
            std::size_t c = 0;
            for (double u : us) {
                while (c < x.size() && x[c] <= u) ++c;
                if (c % 2 == 1) sample(u, v);
            }
        }
        std::size_t points = 0;
        for (const auto& loop : region.loops()) points += loop.size();
        const std::size_t stride = std::max<std::size_t>(1, points / (options.max_face_samples / 4 + 1) + 1);
        std::size_t k = 0;
        for (const auto& loop : region.loops())
            for (const auto& uv : loop)
                if (k++ % stride == 0) sample(uv.x(), uv.y());
        s2m[f] = acc;
    });

    // ---- Mesh -> surface ----
    const int chunks = (nt + kTriangleChunk - 1) / kTriangleChunk;
    std::vector<Accumulator> m2s(chunks);
    std::vector<double> chunk_uv_max(chunks, 0.0);
    std::vector<std::vector<std::pair<int, double>>> chunk_face_max(chunks);
    std::vector<Eigen::AlignedBox3d> face_box(nf);
    for (int f = 0; f < nf; ++f) face_box[f] = model.faces[f].surface.control_box();
    const bool use_uvs = mesh.has_face_ids() && mesh.has_uvs();
    // A projection that may have stalled (a start across a seam, Newton stuck at a
    // pole, which is a stationary point of |S - x|): the projector's grid start and
    // kRetryGrid² starts spread over the domain; the least distance wins.
    const auto retry = [&](int f, const Eigen::Vector3d& x, const Eigen::Vector2d& uv, double d) {
        const geom::NurbsSurface& s = model.faces[f].surface;
        const auto [u0, u1] = s.domain_u();
        const auto [v0, v1] = s.domain_v();
        std::vector<Eigen::Vector2d> starts;
        if (projectors[f]) {
            starts.push_back(projectors[f]->invert(x, &uv));
            starts.push_back(projectors[f]->invert(x));
            // Across a seam: Newton from the other side of the domain.
            if (projectors[f]->closed_u()) starts.push_back(foot_point(s, x, {u0 + u1 - uv.x(), uv.y()}));
            if (projectors[f]->closed_v()) starts.push_back(foot_point(s, x, {uv.x(), v0 + v1 - uv.y()}));
        }
        for (int i = 0; i < kRetryGrid; ++i)
            for (int j = 0; j < kRetryGrid; ++j)
                starts.push_back(foot_point(s, x, {u0 + (u1 - u0) * (i + 0.5) / kRetryGrid,
                                                   v0 + (v1 - v0) * (j + 0.5) / kRetryGrid}));
        for (const auto& q : starts) d = std::min(d, (s.evaluate(q.x(), q.y()) - x).norm());
        return d;
    };
    // On a closed surface a triangle whose corners lie on both sides of the seam
    // (a welded seam vertex keeps one side's uv) is unwrapped by one period before
    // its (u,v) is interpolated, and the result wrapped back into the domain.
    const auto unwrapped_uvs = [&](int f, const std::array<std::int32_t, 3>& tri) {
        std::array<Eigen::Vector2d, 3> q{mesh.uvs[tri[0]], mesh.uvs[tri[1]], mesh.uvs[tri[2]]};
        if (!projectors[f]) return q;
        const geom::NurbsSurface& s = model.faces[f].surface;
        const std::array<std::pair<double, double>, 2> dom{s.domain_u(), s.domain_v()};
        const std::array<bool, 2> closed{projectors[f]->closed_u(), projectors[f]->closed_v()};
        for (int k = 0; k < 2; ++k) {
            if (!closed[k]) continue;
            const double period = dom[k].second - dom[k].first;
            const double lo = std::min({q[0][k], q[1][k], q[2][k]}), hi = std::max({q[0][k], q[1][k], q[2][k]});
            if (hi - lo <= 0.5 * period) continue;
            for (auto& p : q)
                if (p[k] < dom[k].first + 0.5 * period) p[k] += period;
        }
        return q;
    };
    const auto wrap = [&](int f, Eigen::Vector2d uv) {
        const geom::NurbsSurface& s = model.faces[f].surface;
        const auto [u0, u1] = s.domain_u();
        const auto [v0, v1] = s.domain_v();
        if (uv.x() > u1) uv.x() -= u1 - u0;
        if (uv.y() > v1) uv.y() -= v1 - v0;
        return uv;
    };
    const auto on_boundary = [&](int f, const Eigen::Vector2d& uv) {
        const geom::NurbsSurface& s = model.faces[f].surface;
        const auto [u0, u1] = s.domain_u();
        const auto [v0, v1] = s.domain_v();
        const double zu = kBoundaryZone * (u1 - u0), zv = kBoundaryZone * (v1 - v0);
        return uv.x() - u0 < zu || u1 - uv.x() < zu || uv.y() - v0 < zv || v1 - uv.y() < zv;
    };
    mesh::parallel_for(chunks, threads, [&](int chunk) {
        Accumulator acc;
        double uv_max = 0.0;
        std::vector<std::pair<int, double>> face_max;
        const int t_end = std::min(nt, (chunk + 1) * kTriangleChunk);
        for (int t = chunk * kTriangleChunk; t < t_end; ++t) {
            const auto& tri = mesh.triangles[t];
            const Eigen::Vector3d& A = mesh.positions[tri[0]];
            const Eigen::Vector3d& B = mesh.positions[tri[1]];
            const Eigen::Vector3d& C = mesh.positions[tri[2]];
            int f = mesh.has_face_ids() ? mesh.face_ids[t] : -1;
            std::optional<Eigen::Vector2d> near;
            if (f < 0) {
                // The face whose surface is nearest the centroid; boxes bound the search.
                const Eigen::Vector3d g = (A + B + C) / 3.0;
                std::vector<std::pair<double, int>> order;
                for (int k = 0; k < nf; ++k)
                    if (projectors[k]) order.emplace_back(std::sqrt(face_box[k].squaredExteriorDistance(g)), k);
                std::sort(order.begin(), order.end());
                double best = std::numeric_limits<double>::infinity();
                for (const auto& [box_distance, k] : order) {
                    if (box_distance > best) break;
                    const Eigen::Vector2d uv = projectors[k]->invert(g);
                    const double d = (model.faces[k].surface.evaluate(uv.x(), uv.y()) - g).norm();
                    if (d < best) {
                        best = d;
                        f = k;
                        near = uv;
                    }
                }
                if (f < 0) continue;  // no face could be sampled
            }
            const geom::NurbsSurface& s = model.faces[f].surface;
            const double longest = std::max({(A - B).norm(), (B - C).norm(), (C - A).norm()});
            std::array<Eigen::Vector2d, 3> tri_uv;
            if (use_uvs) tri_uv = unwrapped_uvs(f, tri);
            double tri_max = 0.0;
            for (int a = 0; a <= n; ++a)
                for (int b = 0; a + b <= n; ++b) {
                    const double l0 = double(a) / n, l1 = double(b) / n, l2 = 1.0 - l0 - l1;
                    const Eigen::Vector3d x = l0 * A + l1 * B + l2 * C;
                    double d;
                    if (use_uvs) {
                        const Eigen::Vector2d uv = wrap(f, l0 * tri_uv[0] + l1 * tri_uv[1] + l2 * tri_uv[2]);
                        const double d_uv = (s.evaluate(uv.x(), uv.y()) - x).norm();
                        const Eigen::Vector2d foot = foot_point(s, x, uv);
                        d = std::min(d_uv, (s.evaluate(foot.x(), foot.y()) - x).norm());
                        uv_max = std::max(uv_max, d_uv);
                        if (d > kSuspectDistance * longest || on_boundary(f, foot)) d = retry(f, x, foot, d);
                    } else if (projectors[f]) {
                        const Eigen::Vector2d* start = near ? &*near : nullptr;
                        const Eigen::Vector2d uv = projectors[f]->invert(x, start);
                        d = (s.evaluate(uv.x(), uv.y()) - x).norm();
                        near = uv;
                        if (d > kSuspectDistance * longest) d = retry(f, x, uv, d);
                        // Other faces whose box is nearer than this distance may hold a closer point.
                        if (!mesh.has_face_ids())
                            for (int k = 0; k < nf; ++k)
                                if (k != f && projectors[k] && face_box[k].squaredExteriorDistance(x) < d * d) {
                                    const Eigen::Vector2d q = projectors[k]->invert(x);
                                    d = std::min(d, (model.faces[k].surface.evaluate(q.x(), q.y()) - x).norm());
                                }
                    } else {
                        continue;
                    }
                    acc.add(d, f, x);
                    tri_max = std::max(tri_max, d);
                }
            face_max.emplace_back(f, tri_max);
        }
        m2s[chunk] = acc;
        chunk_uv_max[chunk] = uv_max;
        chunk_face_max[chunk] = std::move(face_max);
    });

    // ---- Merge in a fixed order, so the report does not depend on the thread count ----
    Accumulator total_m2s, total_s2m;
    double uv_max = 0.0;
    for (int c = 0; c < chunks; ++c) {
        total_m2s.merge(m2s[c]);
        uv_max = std::max(uv_max, chunk_uv_max[c]);
        for (const auto& [f, d] : chunk_face_max[c])
            report.face_mesh_to_surface[f] = std::isnan(report.face_mesh_to_surface[f])
                                                 ? d : std::max(report.face_mesh_to_surface[f], d);
    }
    for (int f = 0; f < nf; ++f) {
        total_s2m.merge(s2m[f]);
        if (s2m[f].count > 0) report.face_surface_to_mesh[f] = s2m[f].max;
    }
    report.mesh_to_surface = total_m2s.result();
    report.surface_to_mesh = total_s2m.result();
    if (use_uvs) report.mesh_to_surface_max_uv = uv_max;

    // ---- Area and open edges ----
    report.area_mesh = mesh::surface_area(mesh);
    for (double a : report.face_area_exact) report.area_exact += a;
    report.area_ratio = report.area_exact > 0 ? report.area_mesh / report.area_exact : kNaN;
    mesh::Mesh welded = mesh;
    mesh::WeldOptions weld;
    weld.tolerance = 0.0;
    mesh::weld_vertices(welded, weld);
    report.open_edges = mesh::count_open_edges(welded);
    return report;
}

}  // namespace trimkit::tess
