#include "geom/curve_box.h"

#include <vector>

#include "geom/error.h"
#include "geom/homogeneous_bezier.h"

namespace trimkit::geom {
namespace {

constexpr int kMaxSplitDepth = 30;

struct Piece {
    std::vector<Eigen::Vector3d> H;  // homogeneous control points (w u, w v, w)
    int depth = 0;
};

Eigen::AlignedBox2d hull_box(const std::vector<Eigen::Vector3d>& H) {
    Eigen::AlignedBox2d box;
    for (const Eigen::Vector3d& h : H) box.extend(project(h));
    return box;
}

bool within(const Eigen::AlignedBox2d& inner, const Eigen::AlignedBox2d& outer, double tolerance) {
    return (inner.min() - outer.min()).minCoeff() >= -tolerance && (outer.max() - inner.max()).minCoeff() >= -tolerance;
}

}  // namespace

Eigen::AlignedBox2d curve_box(const NurbsCurve2d& c, double tolerance) {
    std::vector<Piece> todo;
    Eigen::AlignedBox2d box;
    for (const NurbsCurve2d& segment : c.bezier_segments()) {
        Piece piece;
        for (std::size_t i = 0; i < segment.points().size(); ++i) {
            const double w = segment.weights()[i];
            piece.H.emplace_back(w * segment.points()[i].x(), w * segment.points()[i].y(), w);
        }
        box.extend(project(piece.H.front())).extend(project(piece.H.back()));
        todo.push_back(std::move(piece));
    }
    while (!todo.empty()) {
        Piece piece = std::move(todo.back());
        todo.pop_back();
        for (const Eigen::Vector3d& h : piece.H)
            if (!(h.z() > 0.0)) throw InvalidInput("curve_box: a weight <= 0 (" + format_value(h.z()) + ")");
        const Eigen::AlignedBox2d hull = hull_box(piece.H);
        if (piece.depth >= kMaxSplitDepth) {
            box.extend(hull);
            continue;
        }
        if (within(hull, box, tolerance)) continue;
        Piece left{{}, piece.depth + 1}, right{{}, piece.depth + 1};
        split_bezier(piece.H, 0.5, &left.H, &right.H);
        box.extend(project(left.H.back()));
        todo.push_back(std::move(left));
        todo.push_back(std::move(right));
    }
    return box;
}

}  // namespace trimkit::geom
