// Sewing free coedges (tess/sew_free_coedges.h): two loose faces of one curved strip
// (IGES faces mode: no shared edges), parameterized differently along their common
// curve, get one shared edge and then one polyline for it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "geom/face.h"
#include "geom/model.h"
#include "tess/sew_free_coedges.h"
#include "tess/tessellate_model.h"

namespace trimkit::tess {
namespace {

// z = y^2 over x in [0, 1] (face 0: y = v) and x in [1, 2] (face 1: y = v^2, so its
// trim curve at x = 1 runs at another speed), face 1 lifted by `lift` in z. Both
// bounded by their natural loops; the common curve is x = 1, z = y^2.
geom::Model parabolic_strip(double lift) {
    geom::Model model;
    geom::Face a;
    a.surface = geom::NurbsSurface(1, 2, {0, 0, 1, 1}, {0, 0, 0, 1, 1, 1}, 2, 3,
                                   {{0, 0, 0}, {0, 0.5, 0}, {0, 1, 1}, {1, 0, 0}, {1, 0.5, 0}, {1, 1, 1}});
    // y = v^2 and z = v^4 in degree-4 Bernstein form: y_k = k(k-1)/12, z = (0,0,0,0,1).
    const double y[5] = {0, 0, 1.0 / 6.0, 0.5, 1};
    const double z[5] = {0, 0, 0, 0, 1};
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 2; ++i)
        for (int k = 0; k < 5; ++k) points.emplace_back(1.0 + i, y[k], z[k] + lift);
    geom::Face b;
    b.surface = geom::NurbsSurface(1, 4, {0, 0, 1, 1}, {0, 0, 0, 0, 0, 1, 1, 1, 1, 1}, 2, 5, points);
    for (geom::Face* face : {&a, &b}) {
        face->loops.push_back(geom::natural_boundary_loop(face->surface));
        model.faces.push_back(*face);
    }
    return model;
}

// The mesh's vertex positions on x = 1 of face `face`.
std::set<std::tuple<double, double, double>> common_curve_points(const mesh::Mesh& m, int face) {
    std::set<std::tuple<double, double, double>> points;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        if (m.face_ids[t] != face) continue;
        for (std::int32_t v : m.triangles[t]) {
            const Eigen::Vector3d& p = m.positions[v];
            if (std::abs(p.x() - 1.0) < 1e-12) points.insert({p.x(), p.y(), p.z()});
        }
    }
    return points;
}

TessellationOptions options_at(double tolerance) {
    TessellationOptions options;
    options.tolerance = tolerance;
    options.threads = 1;
    return options;
}

TEST(SewFreeCoedges, PairsTheCommonCurveOfTwoLooseFacesOnce) {
    geom::Model model = parabolic_strip(0.0);
    const SewingReport report = sew_free_coedges(model, 1e-3);
    EXPECT_EQ(report.pairs, 1);
    EXPECT_LT(report.max_gap, 1e-12);  // both traces are the parabola itself
    ASSERT_EQ(model.edges.size(), 1u);
    // Face 0's side u = 1 (its loop's second coedge) and face 1's side u = 0 (its fourth),
    // which runs the other way round.
    EXPECT_EQ(model.faces[0].loops[0].coedges[1].edge, 0);
    EXPECT_FALSE(model.faces[0].loops[0].coedges[1].edge_reversed);
    EXPECT_EQ(model.faces[1].loops[0].coedges[3].edge, 0);
    EXPECT_TRUE(model.faces[1].loops[0].coedges[3].edge_reversed);
    int shared = 0;
    for (const geom::Face& face : model.faces)
        for (const geom::Coedge& c : face.loops[0].coedges) shared += c.edge >= 0;
    EXPECT_EQ(shared, 2);
}

TEST(SewFreeCoedges, FacesFartherApartThanTheDistanceStayLoose) {
    geom::Model model = parabolic_strip(0.01);
    EXPECT_EQ(sew_free_coedges(model, 1e-3).pairs, 0);
    EXPECT_TRUE(model.edges.empty());
}

// Sides of the mesh on x = 1 that only one triangle has (by position).
int open_sides_on_common_curve(const mesh::Mesh& m) {
    std::map<std::pair<std::tuple<double, double, double>, std::tuple<double, double, double>>, int> uses;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d& p = m.positions[t[k]];
            const Eigen::Vector3d& q = m.positions[t[(k + 1) % 3]];
            if (std::abs(p.x() - 1.0) > 1e-12 || std::abs(q.x() - 1.0) > 1e-12) continue;
            auto a = std::make_tuple(p.x(), p.y(), p.z()), b = std::make_tuple(q.x(), q.y(), q.z());
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    return static_cast<int>(std::count_if(uses.begin(), uses.end(), [](const auto& u) { return u.second == 1; }));
}

// Meshed, the two faces take one polyline for the curve: face 0's own points, with
// the points where either face's cells cross it, and not face 1's own polyline,
// which differs (it runs along the curve at another speed). Without sewing the join
// puts the union of both polylines on the curve.
TEST(SewFreeCoedges, SewnFacesShareTheFirstFacesPolyline) {
    const TessellationOptions options = options_at(1e-3);
    const geom::Model model = parabolic_strip(0.0);
    geom::Model first_alone = model, second_alone = model;
    first_alone.faces.pop_back();
    second_alone.faces.erase(second_alone.faces.begin());
    const auto own_first = common_curve_points(tessellate_model(first_alone, options).mesh, 0);
    const auto own_second = common_curve_points(tessellate_model(second_alone, options).mesh, 0);
    std::set<std::tuple<double, double, double>> both = own_first;
    both.insert(own_second.begin(), own_second.end());
    ASSERT_GE(own_first.size(), 3u);
    ASSERT_GT(both.size(), own_first.size());

    const TessellationResult r = tessellate_model(model, options);
    EXPECT_EQ(r.faces_meshed, 2);
    EXPECT_EQ(open_sides_on_common_curve(r.mesh), 0);
    const auto sewn = common_curve_points(r.mesh, 0);
    EXPECT_EQ(common_curve_points(r.mesh, 1), sewn);
    EXPECT_TRUE(std::includes(sewn.begin(), sewn.end(), own_first.begin(), own_first.end()));
    EXPECT_LT(sewn.size(), both.size()) << own_first.size() << " " << own_second.size();
}

// Distance from p to the cylinder over the parabola z = y^2 + lift (along x): the
// nearest point of the curve in the (y, z) plane, by a fine scan and bisection-free
// refinement of the parameter.
double distance_to_parabola(const Eigen::Vector3d& p, double lift) {
    const auto d2 = [&](double s) { return std::pow(p.y() - s, 2) + std::pow(p.z() - s * s - lift, 2); };
    double best = p.y(), step = 0.01;
    for (double s = p.y() - 0.1; s <= p.y() + 0.1; s += 1e-4)
        if (d2(s) < d2(best)) best = s;
    for (int it = 0; it < 60; ++it, step *= 0.5)
        for (double s : {best - step, best + step})
            if (d2(s) < d2(best)) best = s;
    return std::sqrt(d2(best));
}

// Sewn faces apart by less than the sewing distance meet midway: the shared
// polyline's points (its ends, vertices of the unshared sides, aside) are half the
// gap from each face, not on the first and the whole gap off the second. (Points
// the cells add on its chords lie on the chords, off both.)
TEST(SewFreeCoedges, SewnFacesApartMeetMidway) {
    const TessellationOptions options = options_at(1e-2);
    const double lift = 0.15 * options.tolerance;  // within the sewing distance, 0.2 T
    const TessellationResult r = tessellate_model(parabolic_strip(lift), options);
    EXPECT_EQ(r.faces_meshed, 2);
    int midway = 0, on_first = 0;
    for (const auto& [x, y, z] : common_curve_points(r.mesh, 1)) {
        if (y <= 0.0 || y >= 1.0) continue;
        const Eigen::Vector3d p(x, y, z);
        const double d0 = distance_to_parabola(p, 0.0), d1 = distance_to_parabola(p, lift);
        // The faces' gap along the normal is lift / sqrt(1 + 4 y^2): half of it each way.
        const double half_gap = 0.5 * lift / std::sqrt(1.0 + 4.0 * y * y);
        midway += std::abs(d0 - half_gap) < 0.02 * half_gap && std::abs(d1 - half_gap) < 0.02 * half_gap;
        on_first += d0 < 1e-3 * lift;
    }
    EXPECT_GE(midway, 3);
    EXPECT_EQ(on_first, 0);
}

// The plane z = 0 over [x0, x1] x [y0, y1] (S(u, v) = (u, v, 0)).
geom::NurbsSurface plane(double x0, double x1, double y0, double y1) {
    return geom::NurbsSurface(1, 1, {x0, x0, x1, x1}, {y0, y0, y1, y1}, 2, 2,
                              {{x0, y0, 0}, {x0, y1, 0}, {x1, y0, 0}, {x1, y1, 0}});
}

// A T-vertex the file left unsplit: face 0 spans [0, 2] x [0, 1]; faces 1 and 2 sit
// on its top side, [0, 1] x [1, 2] and [1, 2] x [1, 2]. Face 0's top side is one
// coedge, which faces 1 and 2 meet in two.
TEST(SewFreeCoedges, SplitsACurveWhereAnotherFacesTraceEndsOnIt) {
    geom::Model model;
    for (const auto& [x0, x1, y0, y1] : {std::array<double, 4>{0, 2, 0, 1}, {0, 1, 1, 2}, {1, 2, 1, 2}}) {
        geom::Face face;
        face.surface = plane(x0, x1, y0, y1);
        face.loops.push_back(geom::natural_boundary_loop(face.surface));
        model.faces.push_back(face);
    }
    const SewingReport report = sew_free_coedges(model, 1e-3);
    EXPECT_EQ(report.splits, 1);
    EXPECT_EQ(model.faces[0].loops[0].coedges.size(), 5u);
    // Face 0's two top pieces with faces 1 and 2, and the side x = 1 between 1 and 2.
    EXPECT_EQ(report.pairs, 3);
    const TessellationResult r = tessellate_model(model, options_at(1e-3));
    EXPECT_EQ(r.faces_meshed, 3);
    // Open: only the outline of the L-shaped union, 2 + 2 + 2 + 1 + 1 + 1 + 1 sides long at least.
    std::map<std::pair<std::tuple<double, double, double>, std::tuple<double, double, double>>, int> uses;
    for (const auto& t : r.mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d& p = r.mesh.positions[t[k]];
            const Eigen::Vector3d& q = r.mesh.positions[t[(k + 1) % 3]];
            auto a = std::make_tuple(p.x(), p.y(), p.z()), b = std::make_tuple(q.x(), q.y(), q.z());
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    for (const auto& [side, count] : uses) {
        if (count != 1) continue;
        const double y0 = std::get<1>(side.first), y1 = std::get<1>(side.second);
        const double x0 = std::get<0>(side.first), x1 = std::get<0>(side.second);
        const bool inner = (y0 == 1.0 && y1 == 1.0) || (x0 == 1.0 && x1 == 1.0 && y0 > 1.0 && y1 > 1.0);
        EXPECT_FALSE(inner) << "open side (" << x0 << ", " << y0 << ") - (" << x1 << ", " << y1 << ")";
    }
}

// Loose faces of a brick wall (rows of unit-high bricks, every other row shifted by a
// half brick, so each row's joints end on the next row's brick sides): the sewing
// splits and pairs the same coedges whatever the number of threads.
TEST(SewFreeCoedges, SameSewingOnAnyNumberOfThreads) {
    geom::Model wall;
    for (int row = 0; row < 4; ++row)
        for (int brick = 0; brick < 4; ++brick) {
            const double x0 = brick * 2.0 - (row % 2 ? 1.0 : 0.0);
            geom::Face face;
            face.surface = plane(x0, x0 + 2.0, row, row + 1.0);
            face.loops.push_back(geom::natural_boundary_loop(face.surface));
            wall.faces.push_back(face);
        }
    geom::Model one = wall, two = wall;
    const SewingReport a = sew_free_coedges(one, 1e-3, 1), b = sew_free_coedges(two, 1e-3, 2);
    // Derived: the rows overlap on [0, 7] (row 0 spans [0, 8], row 1 [-1, 7]), cut at every
    // integer there into 7 unit pieces on each side; each row has 3 joints between its
    // bricks: 3 x 7 + 4 x 3 pairs (the end pieces [-1, 0] and [7, 8] have no partner).
    EXPECT_EQ(a.pairs, 33);
    EXPECT_EQ(b.pairs, a.pairs);
    EXPECT_EQ(b.splits, a.splits);
    ASSERT_EQ(one.edges.size(), two.edges.size());
    for (std::size_t f = 0; f < one.faces.size(); ++f) {
        const auto& x = one.faces[f].loops[0].coedges;
        const auto& y = two.faces[f].loops[0].coedges;
        ASSERT_EQ(x.size(), y.size()) << "face " << f;
        for (std::size_t c = 0; c < x.size(); ++c) {
            EXPECT_EQ(x[c].edge, y[c].edge) << "face " << f << ", coedge " << c;
            EXPECT_EQ(x[c].edge_reversed, y[c].edge_reversed);
        }
    }
}

// The unit circle as a rational quadratic NURBS in (u, v) starting at angle `start`,
// counter-clockwise or clockwise.
geom::NurbsCurve2d unit_circle(double start, bool counter_clockwise) {
    std::vector<Eigen::Vector2d> points;
    std::vector<double> weights;
    for (int k = 0; k <= 8; ++k) {
        const double angle = start + (counter_clockwise ? 1.0 : -1.0) * k * M_PI / 4.0;
        const double r = k % 2 == 0 ? 1.0 : std::sqrt(2.0);
        points.emplace_back(r * std::cos(angle), r * std::sin(angle));
        weights.push_back(k % 2 == 0 ? 1.0 : std::sqrt(0.5));
    }
    return geom::NurbsCurve2d(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, points, weights);
}

// A hole and the disk that fills it, each bounded by one closed curve, the hole's
// starting at angle 0 and the disk's at 90 degrees: each is split at the other's
// start, and the two arcs pair.
TEST(SewFreeCoedges, ClosedCurvesStartingApartAreSplitAndPaired) {
    geom::Model model;
    geom::Face square;
    square.surface = plane(-2, 2, -2, 2);
    square.loops.push_back(geom::natural_boundary_loop(square.surface));
    square.loops.push_back(geom::Loop{{geom::Coedge{unit_circle(0.0, false), -1, false}}, false});
    geom::Face disk;
    disk.surface = plane(-1, 1, -1, 1);
    disk.loops.push_back(geom::Loop{{geom::Coedge{unit_circle(M_PI / 2.0, true), -1, false}}, true});
    model.faces = {square, disk};
    const SewingReport report = sew_free_coedges(model, 1e-3);
    EXPECT_EQ(report.splits, 2);
    EXPECT_EQ(report.pairs, 2);
    EXPECT_LT(report.max_gap, 1e-9);
    const TessellationResult r = tessellate_model(model, options_at(1e-3));
    EXPECT_EQ(r.faces_meshed, 2);
    // Open: the square's outline only, none on the circle.
    int open_on_circle = 0;
    std::map<std::pair<std::tuple<double, double, double>, std::tuple<double, double, double>>, int> uses;
    for (const auto& t : r.mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d& p = r.mesh.positions[t[k]];
            const Eigen::Vector3d& q = r.mesh.positions[t[(k + 1) % 3]];
            auto a = std::make_tuple(p.x(), p.y(), p.z()), b = std::make_tuple(q.x(), q.y(), q.z());
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    for (const auto& [side, count] : uses) {
        const double ra = std::hypot(std::get<0>(side.first), std::get<1>(side.first));
        const double rb = std::hypot(std::get<0>(side.second), std::get<1>(side.second));
        open_on_circle += count == 1 && std::abs(ra - 1.0) < 1e-9 && std::abs(rb - 1.0) < 1e-9;
    }
    EXPECT_EQ(open_on_circle, 0);
}

}  // namespace
}  // namespace trimkit::tess
