// IgesReader: turns the entities of a parsed IgesFile into a geom::Model.
// Internal to read_iges; its members are spread over iges_reader.cpp (roots,
// model assembly), iges_curves.cpp, iges_surfaces.cpp, iges_topology.cpp and
// iges_structure.cpp. Conventions: entities are addressed by directory sequence
// number `de` (odd); every translator applies the entity's own 124 transform
// (chained 124s composed) and throws geom::ReadError naming the entity's line,
// which the caller turns into a warning ("D123: reason") or, for the whole
// file, into the reader's error.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "io/face_loops.h"
#include "geom/arc_parameter_map.h"
#include "geom/model.h"
#include "io/iges_file.h"
#include "io/iges_parameter_cursor.h"
#include "io/read_monitor.h"

namespace trimkit::io {

// Deepest chain of entity references followed (composite curves in composite
// curves, 124 chains, nested groups and subfigures). Real files nest a few
// levels; a cycle in a hostile file stops here instead of overflowing the stack.
constexpr int kMaxIgesNesting = 32;
// Most entity visits (translate calls) one file may cause: kMaxIgesVisitsPerEntry per
// directory entry, at least kMinIgesVisits. Depth alone does not bound the work: 30
// groups each holding the one below twice are 2^30 paths to one face
// (tests/fuzz/regressions/iges/group_fan_out.igs). Sound files visit each entity a few
// times (a subfigure definition's members once per instance inside another definition).
constexpr int kMaxIgesVisitsPerEntry = 16;
constexpr long long kMinIgesVisits = 4096;

// A surface entity converted to NURBS, with the map from the entity's native
// IGES parameters (s, t) (those of its parameter-space trim curves) to the
// NURBS parameters (u, v).
struct IgesSurface {
    geom::NurbsSurface nurbs;
    std::string kind;  // "bspline", "plane", "revolution", ... (Face::surface_kind)
    enum class Map {
        kNone,    // no usable native parameterisation: trims are projected
        kAffine,  // u = su*s + ou, v = sv*t + ov (after swapping s, t if `swap`)
        kAngleV,  // u = su*s + ou, v = angle.to_nurbs(t) (surface of revolution)
    };
    Map map = Map::kNone;
    bool swap = false;
    double su = 1, ou = 0, sv = 1, ov = 0;
    std::optional<geom::ArcParameterMap> angle;
    // kAngleV on a closed sweep (the NURBS closed in v): angles outside the
    // sweep map periodically (θ ± 2π k onto v ± period k), so a trim curve across
    // the seam keeps its shape past the domain (io/closed_surface_loops.h).
    bool periodic_angle = false;
    // u (after the affine map) is the angle of a circular-arc generatrix (120,
    // 140) or directrix (122): the NURBS parameter is angle_u->to_nurbs(θ), exact
    // only at the arc's knots. Parameter curves may give θ a whole turn off the
    // arc's range (IGES 5.3 Sec. 4.3 starts arcs in [0, 2π); OCCT's writer keeps
    // its own start, -0.09 say): θ is taken the turn nearest the arc.
    std::optional<geom::ArcParameterMap> angle_u;
};

// The weights of a 126/128 entity as NurbsCurve/NurbsSurface take them: empty
// (polynomial) when the entity's PROP3 says polynomial or when all weights are
// equal, which writers often emit with the rational flag set. [IGES] 4.23, 4.24.
std::vector<double> iges_weights(std::vector<double> w, bool polynomial_flag);

class IgesReader {
public:
    // monitor: checked (ReadStopped) and told the progress between root entities.
    explicit IgesReader(const IgesFile& file, ReadMonitor* monitor = nullptr);
    geom::Model read();

    // ---- shared helpers (iges_reader.cpp) ----
    const IgesFile& file() const { return file_; }
    // Entry of `de`; throws ReadError (from `from`'s viewpoint) if `de` is not an entry.
    const IgesDirectoryEntry& entry_of(int de) const;
    int line_of(int de) const;
    [[noreturn]] void fail(int de, const std::string& reason) const;
    void warn(const std::string& message);
    // Warning for an entity type this reader does not translate (capped per type).
    void warn_unsupported(int de, const std::string& what);

    // ---- structure (iges_structure.cpp) ----
    // The entity's own transform: its 124 composed with the 124s that one points to.
    Eigen::Affine3d transform_of(int de);
    // The matrix of a 124 entity itself (without its own chain).
    Eigen::Affine3d transform_matrix(int de);
    int color_of(int de);        // index into model_.colors or -1
    std::string name_of(int de, const std::vector<int>& properties);

    // ---- curves (iges_curves.cpp) ----
    // The model-space curve of a curve entity (102 gives its pieces in order),
    // own transform applied. Cached.
    const std::vector<geom::NurbsCurve3d>& curve(int de);
    // A parameter-space curve: the entity read as a curve and z dropped.
    std::vector<geom::NurbsCurve2d> parameter_curve(int de);
    // The parameter curves `des` (0 entries skipped) joined in order; empty, with a
    // warning added to `warnings`, if any of them cannot be read.
    std::vector<geom::NurbsCurve2d> parameter_curves(const std::vector<int>& des,
                                                     std::vector<std::string>* warnings);
    static bool is_curve_type(int type);

    // ---- surfaces (iges_surfaces.cpp) ----
    static bool is_surface_type(int type);
    // `hint` sizes unbounded surfaces; without it they cannot be built.
    IgesSurface surface(int de, const BoundaryHint* hint = nullptr);
    // Distance (model units) below which a surface's boundary rows count as one
    // (closed direction): 1e-7 of its size, or the file's resolution (Global field
    // 19) when larger, capped at 1e-4 of its size.
    double closure_tolerance(const geom::NurbsSurface& s) const;
    // A 2D curve in the surface's native parameters mapped into NURBS (u, v);
    // nullopt when the surface has no usable map.
    std::optional<geom::NurbsCurve2d> map_to_nurbs(const IgesSurface& s,
                                                   const geom::NurbsCurve2d& c) const;
    // face_loops.h's context for faces on `s` (which must outlive it): closure
    // tolerance, the file's resolution and map_to_nurbs.
    FaceLoopsContext face_loops_context(const IgesSurface& s) const;

    // ---- topology (iges_topology.cpp) ----
    // Faces of a 144 / 143 / 510-with-surface / bare surface entity, placed by
    // `placement` (applied after the entities' own transforms). Appends to the
    // model and returns the face indices added.
    std::vector<int> read_face_entity(int de, const Eigen::Affine3d& placement);
    // A 510 face of a B-rep shell; `reversed` from the shell's orientation flags.
    int read_brep_face(int de, const Eigen::Affine3d& placement, bool reversed);
    // Entry `index` (1-based) of 504 edge list `list`: made into Model::edges
    // (one per curve piece, placed) on first use within the current body.
    // Returns the first edge index and the pieces in the body's local space.
    std::pair<int, const std::vector<geom::NurbsCurve3d>*> brep_edge(
        int list, int index, const Eigen::Affine3d& placement);
    // A 186 or 514 as a body; returns the body index.
    int read_body(int de, const Eigen::Affine3d& placement);

    // ---- structure: groups and instances (iges_structure.cpp) ----
    // Translates a root or member entity of any kind, placed by `placement`.
    // Returns the faces added (for bodies and groups: all their faces).
    std::vector<int> translate(int de, const Eigen::Affine3d& placement, int depth);
    // The body holding a 308 subfigure definition's faces in the definition's own
    // coordinates, read on first use (bodies read inside it are merged into it).
    int definition_body(int def, int depth);

    // RAII depth guard against deep or cyclic references.
    class Nesting {
    public:
        Nesting(IgesReader& r, int de);
        ~Nesting() { --r_.depth_; }
        Nesting(const Nesting&) = delete;
        Nesting& operator=(const Nesting&) = delete;
    private:
        IgesReader& r_;
    };

    geom::Model& model() { return model_; }

private:
    std::vector<int> references(int index);
    void build_reference_counts();
    void set_units();

    const IgesFile& file_;
    ReadMonitor* monitor_ = nullptr;
    geom::Model model_;
    int depth_ = 0;
    long long visits_ = 0;  // translate calls so far (kMaxIgesVisitsPerEntry)
    std::map<int, std::vector<geom::NurbsCurve3d>> curve_cache_;
    std::map<int, Eigen::Affine3d> transform_cache_;
    std::map<int, int> color_cache_;
    std::map<int, int> definition_body_;  // 308 sequence number -> body index
    int in_definition_ = 0;               // > 0 while reading a 308's members
    std::map<int, int> unsupported_count_;
    std::vector<int> referenced_;  // per entry index: how many entities point to it
public:
    // 504 edge list entries already made into Model::edges for the current
    // placement: (504 de, 1-based index) -> edge index.
    std::map<std::pair<int, int>, int> edge_index_;
    std::map<std::pair<int, int>, int> edge_curve_;  // same key -> curve entity
    // Box of the faces' control points read so far.
    Eigen::AlignedBox3d seen_box_;
};

}  // namespace trimkit::io
