#include "tess/trim_area_loss.h"

namespace trimkit::tess {

double trim_area_loss(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c, const TrimPolyline& polyline,
                      bool region_left) {
    double loss = 0.0;
    const auto& p = polyline.points;
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
        // On this face's surface: a shared edge's own points may sit off it by the
        // file's edge gap, which is not the chord's.
        const Eigen::Vector3d a = S.evaluate(p[i].uv.x(), p[i].uv.y());
        const Eigen::Vector3d b = S.evaluate(p[i + 1].uv.x(), p[i + 1].uv.y());
        const Eigen::Vector3d chord = b - a;
        const double length = chord.norm();
        if (!(length > 0.0)) continue;
        const Eigen::Vector3d along = chord / length;
        double sagitta = 0.0, side = 0.0;
        for (double s : {0.25, 0.5, 0.75}) {
            const Eigen::Vector2d uv = c.evaluate(p[i].t + s * (p[i + 1].t - p[i].t));
            const geom::SurfaceDerivatives d = S.derivatives(uv.x(), uv.y());
            const Eigen::Vector3d normal = d.Su.cross(d.Sv);
            if (!(normal.norm() > 0.0)) continue;
            const Eigen::Vector3d n = normal.normalized();
            Eigen::Vector3d off = d.S - a;
            off -= off.dot(along) * along;
            // Only the bulge within the surface moves the region's boundary; the part
            // along the normal (a parallel circle of a cylinder bows straight out of the
            // surface's tangent plane) is the cells' sag, counted by cell_area_loss.
            off -= off.dot(n) * n;
            if (off.norm() <= sagitta) continue;
            sagitta = off.norm();
            side = n.dot(chord.cross(off));  // > 0: the curve runs left of the chord
        }
        if (side == 0.0) continue;
        const double segment = 2.0 / 3.0 * sagitta * length;
        // Bulging to the region's side, the curve leaves the strip between it and the
        // chord outside the face, and the mesh has it: a gain.
        loss += ((side > 0.0) == region_left ? -segment : segment);
    }
    return loss;
}

bool region_left_of(const TrimPolygon& loop, bool outer) {
    double area = 0.0;
    const auto& p = loop.points;
    for (std::size_t i = 0, n = p.size(); i < n; ++i)
        area += p[i].uv.x() * p[(i + 1) % n].uv.y() - p[(i + 1) % n].uv.x() * p[i].uv.y();
    return (area > 0.0) == outer;
}

}  // namespace trimkit::tess
