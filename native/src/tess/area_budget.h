// The area a mesh may lose against its exact faces, shared out over the faces. A
// mesh within the tolerance T is smaller than its curved faces (its chords cut
// inside them: trim_area_loss.h, cell_area_loss.h), by about e / 3R of a face of
// radius R whose chords deviate by e, so a thin part whose cells spend all of T
// loses more of its area than the 0.2 % a check allows (issue 9), although every
// point is within T. The model gets a budget, a share of its area (or each part,
// geom::Body, of its own, when each is handed out as an object: area_groups); a
// group over budget has its faces that lose most for their area meshed again with
// finer trims and cells, until it is within it. A face's loss falls about
// linearly with its trims' or cells' tolerance t, while their points grow as
// 1/sqrt(t) (chords of curves, cells curved one way) to 1/t (cells curved both
// ways): the trims or cells that lose most per point they have buy the most area
// per added triangle, and are tightened first.
#pragma once

#include <vector>

#include "geom/model.h"

namespace trimkit::tess {

struct FaceArea {
    double area = 0.0;       // the face mesh's area
    double trim_loss = 0.0;  // signed area its trim chords lose (trim_area_loss.h)
    double cell_loss = 0.0;  // signed area its triangles lose inside the trims (cell_area_loss.h)
    int triangles = 0;       // the face mesh's triangles
    int boundary_edges = 0;  // and its face-boundary edges (the trims' points)
};

// Per face, the share of their tolerance its trims and its cells get (each in (0, 1]).
struct FaceScales {
    std::vector<double> trim, cell;
};

// The faces of each part of `model`: one group per body, and one for faces in no
// body (all faces when the model has no bodies).
std::vector<std::vector<int>> part_groups(const geom::Model& model);

// The groups of faces that get a budget each: with per_body the parts (part_groups),
// else one group of all the model's faces.
std::vector<std::vector<int>> area_groups(const geom::Model& model, bool per_body);

// |Loss| over area of the group whose area is furthest off, lost or gained (0 when none is).
double worst_loss_share(const std::vector<std::vector<int>>& groups, const std::vector<FaceArea>& faces);

// Lowers the scales of faces in groups losing (or gaining) more than `share` of their
// area, so that the group's predicted |loss| (linear in each scale) is `margin` x share of its
// area at the fewest added points (a face's trims and its cells apart, each by at
// most a factor 4 per call, none below min_scale). Returns the groups tightened
// (indices into groups).
std::vector<int> tighten_to_area_budget(const std::vector<std::vector<int>>& groups,
                                        const std::vector<FaceArea>& faces, double share, double margin,
                                        double min_scale, FaceScales& scales);

}  // namespace trimkit::tess
