// Compression of a model's faces ([Muraki] Sec. 2-3, Fig. 3): each face's surface
// is refitted from its boundary edges (refit_face) and the fit judged as in
// Sec. 4.4 (evaluate_fit); a face whose maximum error is within the tolerance
// keeps only its FitRule, the others keep their surface; a fit along G1 edges must
// also keep the normals within kMaxG1Angle there (g1_angle), and the rebuilt face
// (extend_face) must lie within the tolerance of the source surface too. A face is
// compressed only if every G1 neighbour still has its surface (extension rebuilds
// from neighbours' surfaces), and once it is, its G1 neighbours keep theirs; faces
// with fewer G1 neighbours are tried first. Periodic faces (a seam edge used twice,
// or a closed surface whose loops span its period) keep their surface: Sec. 6 says
// the method cannot build their reference planes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fit/evaluate_fit.h"
#include "fit/fit_rule.h"
#include "geom/model.h"

namespace trimkit::fit {

struct CompressOptions {
    double tolerance = 0;              // model units; 0: relative_tolerance of each face's box
    double relative_tolerance = 0.01;  // the paper's 1 % (Sec. 4.4)
    std::vector<int> faces;            // the faces that may be compressed; empty: all
    // Rebuild the faces even when no fit is within the tolerance (the first rule that
    // keeps G1 is taken, its reason says so; their G1 is judged within
    // kRebuildG1JudgeAngle) and whatever they
    // cost stored: `object.trimkit_rebuild_faces`, for faces whose own surface is
    // damaged or failed to mesh (their error is measured against that surface).
    bool rebuild = false;
};

struct FaceCompression {
    bool compressed = false;
    std::string reason;   // why the surface was kept ("periodic", "max error 0.3 > 0.1", ...)
    FitError error;       // of the best rule tried (zero when none was)
    double tolerance = 0;
    FitRule rule;         // the rule used (or the last tried)
    int g1_edges = 0;     // coedges judged G1
    double g1_angle = 0;  // degrees, the accepted fit's g1_angle (<= kMaxG1Angle)
    double reverse_max = 0;  // rebuilt face's grid -> source surface (surface_deviation), <= tolerance
};

// The model with every compressed face's coedges on 3D edges (new edges fitted
// where the file had none), and per face its rule, or none when the surface is kept.
struct CompressedModel {
    geom::Model model;
    std::vector<std::optional<FitRule>> rules;
};

// Control-point counts tried per direction, smallest first (degree 3).
constexpr int kTriedCounts[] = {4, 6, 9, 13, 18};

CompressedModel compress_model(const geom::Model& model, const CompressOptions& options,
                               std::vector<FaceCompression>* report = nullptr);

}  // namespace trimkit::fit
