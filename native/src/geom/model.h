// Model: everything read from one CAD file. Lengths are in the file's units;
// `scale_to_metres` converts them. Bodies group faces into solids or shells;
// free faces belong to no body. Instances place bodies with a transform.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "geom/face.h"

namespace trimkit::geom {

struct Body {
    std::string name;
    std::vector<int> faces;  // indices into Model::faces
    bool closed = false;     // a solid (186/514 closed shell), not an open shell
};

struct Instance {
    int body = -1;                        // index into Model::bodies
    Eigen::Affine3d transform = Eigen::Affine3d::Identity();
    std::string name;
    // Names of the assemblies from the root down to the one holding this instance
    // (STEP's XCAF tree; empty for IGES subfigures and top-level parts).
    std::vector<std::string> path;
};

struct Color {
    std::array<double, 3> rgb{0.8, 0.8, 0.8};  // each in [0, 1]
    std::string name;
};

struct Model {
    std::string units = "mm";     // the file's unit name: "mm", "in", "m", ...
    double scale_to_metres = 1e-3;
    std::vector<Face> faces;
    std::vector<Edge> edges;
    std::vector<Body> bodies;
    std::vector<int> free_faces;  // faces in no body
    std::vector<Instance> instances;  // placements of bodies; empty: each body once, untransformed
    std::vector<Color> colors;
    std::vector<std::string> warnings;  // file-level warnings ("entity 140 at D123 unsupported")
    // Why each face of the file that the reader left out was left out (each also in
    // `warnings`): such a face is missing from every mesh, and `trimkit mesh --strict`
    // counts it as failed.
    std::vector<std::string> unread_faces;
};

// Records a face of the file that the reader leaves out, and why (Model::unread_faces
// and a warning).
inline void skip_face(Model& model, const std::string& reason) {
    model.warnings.push_back(reason);
    model.unread_faces.push_back(reason);
}

}  // namespace trimkit::geom
