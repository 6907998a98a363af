// occt_check: measures a mesh of a CAD model against Open CASCADE's reading of the same
// file, independently of trimkit (issue 9's acceptance tool). The model is read with
// OCCT's default reader (STEPControl_Reader for .stp/.step, IGESControl_Reader for
// .igs/.iges, BRepTools::Read for .brep); its faces are taken flattened, one per
// occurrence with its location (an instanced face once per placement). The mesh (OBJ,
// PLY or STL) must be in model space with instances placed, in the file's length unit
// (mm for STEP and .brep, which OCCT's STEP reader also uses; for IGES OCCT converts to
// mm, and the mesh is scaled by the file's unit to match). All lengths printed are in the
// mesh's unit. One JSON line per mesh (several meshes of one model share the reference,
// built once):
//   faces            TopExp_Explorer(shape, TopAbs_FACE) count
//   area_occt        sum over faces of BRepGProp::SurfaceProperties (adaptive, relative
//                    precision 1e-9); area_mesh; area_ratio
//   mesh_to_surface  max/mean distance of mesh samples (a barycentric grid of each mesh
//                    triangle, --samples N subdivisions per side, plus its centroid) to the
//                    nearest trimmed OCCT face
//   surface_to_mesh  max/mean distance from points on the trimmed faces (nodes of a fine
//                    BRepMesh triangulation at --fine F times T, the exact surface at a
//                    barycentric grid of its (u,v) triangles, and points on the faces' edge
//                    curves) to the mesh's triangles
//   tolerance T      --tolerance T (absolute) or -r R (R times the diagonal of the tight
//                    box, BRepBndLib::AddOptimal as in occt_mesh); default -r 0.001
// How a distance to a trimmed face is found (mesh -> surface): a box tree over the fine
// triangulation gives the candidate faces (every face whose fine triangles come within
// the nearest one's distance plus twice the fine mesh's margin: its measured deviation,
// the fine deflection, a grid cell); on each, a Newton projection onto the exact surface
// (held inside the face's UV box) starts from the (u,v) of the nearest fine point. The
// foot counts if it is on the trimmed face (even-odd test against the face's (u,v)
// polygon of its pcurves; BRepClass_FaceClassifier where two rays disagree); if it is off
// the face, or within T of its edges, the distance to the face's edge curves (refined by
// Newton) is taken too. Every value is a distance to a point of the face, an upper bound;
// the 32 largest samples are refined within their triangle and re-measured with
// BRepExtrema_DistShapeShape, keeping the smaller. The 32 largest surface samples are
// likewise refined in (u,v) or along their edge. Faces BRepMesh cannot triangulate (no
// triangles, or an area more than 1% off) are sampled on a (u,v) grid instead.
// Usage: occt_check MODEL MESH [MESH ...] [-r R | --tolerance T] [--samples N] [--fine F] [--brute-force]
//   --brute-force also measures every mesh sample with BRepExtrema_DistShapeShape against
//   the compound of all faces and reports how the fast distances compare (a self-test).
//   Environment: OCCT_CHECK_DEBUG=1 prints per-face figures on stderr;
//   OCCT_CHECK_POINT=x,y,z traces the distance from that point (mesh units) and exits.
// Exit status: 0 if both maxima <= T and |area_ratio - 1| <= 0.002 for every mesh, 1
// otherwise, 2 on a usage or read error.

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GCPnts_TangentialDeflection.hxx>
#include <GProp_GProps.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_IGESModel.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Geom2d_Curve.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <queue>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

#include "mesh_file.h"
#include "triangle_bvh.h"

namespace {

using occt_reference::TriangleBvh;
using occt_reference::TrianglePoint;
using occt_reference::Vec3;

// The acceptance limits of issue 9 (same as bench/mesh_check_all.py).
constexpr double kAreaRatioLimit = 0.002;
// The fine reference triangulation's linear deflection, as a share of T, and its angle.
constexpr double kDefaultFine = 0.1;
constexpr double kFineAngle = 0.3;  // radians
// Subdivisions per side of each triangle's barycentric sample grid (both meshes).
constexpr int kDefaultSamples = 3;
// Each edge polygon interval (GCPnts_TangentialDeflection at the fine deflection and
// kFineAngle) is split into this many pieces for the edge samples.
constexpr int kEdgeSubdivisions = 4;
// A face's fine triangulation is used only when its area is within this share of the
// face's exact area (BRepGProp); otherwise the face is sampled on a (u,v) grid.
constexpr double kFineAreaMismatch = 0.01;
// The (u,v) grid (per side) of the midpoint rule that decides between BRepGProp and
// BRepMesh where their areas of a face differ by more than kFineAreaMismatch.
constexpr int kAreaGrid = 500;
// Grid fallback: about this many grid cells per face.
constexpr double kGridCells = 40000;
// How many of the largest samples of each direction are refined (and, mesh -> surface,
// re-measured with BRepExtrema_DistShapeShape).
constexpr int kRefined = 32;
// Newton iterations (surface and curve projections); convergence when the 3D step is
// below kNewtonStep times D.
constexpr int kNewtonIterations = 30;
constexpr double kNewtonStep = 1e-13;
// Relative precision of each face's area (BRepGProp::SurfaceProperties with adaptive
// integration). The default, fixed-order Gauss integration is 0.21% low on
// bug28366_fuselage.stp's B-spline faces: as much as the whole area criterion.
constexpr double kAreaPrecision = 1e-9;
// Points of the pcurve of a degenerate edge (which has no 3D polyline) in a face's
// (u,v) polygon.
constexpr int kDegenerateSamples = 64;
// Faces with an exact area below this share of D^2 are not checked for area mismatch.
constexpr double kTinyArea = 1e-12;

gp_Pnt to_pnt(Vec3 v) { return gp_Pnt(v.x, v.y, v.z); }
Vec3 to_vec(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Vec3 to_vec(const gp_Vec& p) { return {p.X(), p.Y(), p.Z()}; }

std::string lower_extension(const std::string& path) {
  std::string ext = path.substr(path.find_last_of('.') + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string base_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += static_cast<unsigned char>(c) >= 0x20 ? c : ' ';
  }
  return out + "\"";
}

std::string num(double x) {
  if (!std::isfinite(x)) return "null";
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

// A point with 17 significant digits (OCCT_CHECK_POINT retraces exactly that point).
std::string json_point(Vec3 p) {
  char b[96];
  std::snprintf(b, sizeof b, "[%.17g, %.17g, %.17g]", p.x, p.y, p.z);
  return b;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The shape of a CAD file with default reader settings, and the length of one unit of the
// file in OCCT's output unit (1 except for IGES files not in mm). Throws on failure.
struct Model {
  TopoDS_Shape shape;
  double unit = 1.0;
};
Model read_model(const std::string& path) {
  const std::string ext = lower_extension(path);
  Model model;
  if (ext == "brep") {
    BRep_Builder builder;
    if (!BRepTools::Read(model.shape, path.c_str(), builder)) throw std::runtime_error("BRepTools::Read failed");
  } else if (ext == "igs" || ext == "iges") {
    IGESControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw std::runtime_error("read failed");
    reader.TransferRoots();
    model.shape = reader.OneShape();
    // The file's unit and OCCT's output unit. The header says UnitValue() is in metres,
    // but OCCT 7.6.3 gives it in mm like CascadeUnit() (1 for an mm file, 25.4 for inches).
    const IGESData_GlobalSection& global = reader.IGESModel()->GlobalSection();
    model.unit = global.UnitValue() / global.CascadeUnit();
  } else if (ext == "stp" || ext == "step") {
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw std::runtime_error("read failed");
    reader.TransferRoots();
    model.shape = reader.OneShape();
  } else {
    throw std::runtime_error("unknown extension '." + ext + "' (expected .stp, .step, .igs, .iges, .brep)");
  }
  if (model.shape.IsNull()) throw std::runtime_error("null shape");
  if (!(model.unit > 0) || !std::isfinite(model.unit)) throw std::runtime_error("bad IGES unit");
  return model;
}

// ---------------------------------------------------------------------------------------
// The reference: OCCT's faces, their edges and a fine triangulation with (u,v).

// The trimmed domain of a face in (u,v) as segments of its pcurves (sampled densely), for
// an even-odd crossing test. Every edge occurrence counts (a seam's two pcurves,
// degenerate edges' pcurves), so the loops close in (u,v) without ordering them. A ray
// along u is tried first, then one along v: a ray is not trusted when it passes within a
// rounding distance of a segment's end (a point level with an iso-line edge or a vertex,
// where ends of neighbouring pcurves differ by rounding) or when its two directions
// disagree. Segments are binned in bands across each ray direction.
class UvPolygon {
 public:
  bool empty() const { return segments_.empty(); }
  void add(double u0, double v0, double u1, double v1) { segments_.push_back({u0, v0, u1, v1}); }
  void dump() const {
    for (const auto& s : segments_) std::fprintf(stderr, "  seg %.17g %.17g -> %.17g %.17g\n", s[0], s[1], s[2], s[3]);
  }
  void finish() {
    if (segments_.empty()) return;
    for (int axis = 0; axis < 2; ++axis) bins_[axis].build(segments_, axis);
  }
  // 1 inside, 0 outside, -1 when no ray can tell.
  int contains(double u, double v) const {
    for (int axis = 1; axis >= 0; --axis) {  // bands across v (a ray along u) first
      const int state = bins_[axis].parity(segments_, u, v, axis);
      if (state >= 0) return state;
    }
    return -1;
  }

 private:
  // Bands across coordinate `axis` (0: u, 1: v) for rays along the other one.
  struct Bins {
    double lo = 0, width = 1, eps = 0;
    std::vector<std::vector<int>> bands;

    int band(double x) const {
      return std::clamp(static_cast<int>((x - lo) / width), 0, static_cast<int>(bands.size()) - 1);
    }
    void build(const std::vector<std::array<double, 4>>& segments, int axis) {
      lo = std::numeric_limits<double>::infinity();
      double hi = -lo;
      for (const auto& s : segments) {
        lo = std::min({lo, s[axis], s[axis + 2]});
        hi = std::max({hi, s[axis], s[axis + 2]});
      }
      eps = 1e-9 * std::max(hi - lo, 1e-300);
      const int n = std::clamp(static_cast<int>(segments.size() / 4), 1, 4096);
      width = (hi - lo) / n;
      if (!(width > 0)) width = 1, lo -= 0.5;
      bands.assign(n, {});
      for (int k = 0; k < static_cast<int>(segments.size()); ++k) {
        const auto& s = segments[k];
        const int a = band(std::min(s[axis], s[axis + 2]) - eps), b = band(std::max(s[axis], s[axis + 2]) + eps);
        for (int i = a; i <= b; ++i) bands[i].push_back(k);
      }
    }
    // Parity of the crossings of the rays from (u, v) along the other axis; -1 if a ray
    // comes within eps of a segment's end or the two directions disagree.
    int parity(const std::vector<std::array<double, 4>>& segments, double u, double v, int axis) const {
      const double level = axis == 1 ? v : u, along = axis == 1 ? u : v;
      if (bands.empty() || level < lo - eps || level > lo + width * bands.size() + eps) return 0;
      int plus = 0, minus = 0;
      const int other = 1 - axis;
      for (const int k : bands[band(level)]) {
        const auto& s = segments[k];
        const double a = s[axis], b = s[axis + 2];
        if (std::abs(a - level) <= eps || std::abs(b - level) <= eps) {
          // Only a worry if the end is on the ray's line within the segment set's reach.
          return -1;
        }
        if ((a > level) != (b > level)) {
          const double x = s[other] + (level - a) * (s[other + 2] - s[other]) / (b - a);
          plus += x > along;
          minus += x <= along;
        }
      }
      return plus % 2 == minus % 2 ? plus % 2 : -1;
    }
  };
  std::vector<std::array<double, 4>> segments_;  // u0, v0, u1, v1
  Bins bins_[2];
};

struct EdgeData {
  TopoDS_Edge edge;
  std::unique_ptr<BRepAdaptor_Curve> curve;
  std::vector<double> t;  // parameters of the polyline (subdivided polygon)
  std::vector<Vec3> p;    // exact curve points at t
  int face = -1;          // the first face that uses the edge
};

struct FaceData {
  TopoDS_Face face;
  std::unique_ptr<BRepAdaptor_Surface> surface;  // null: the face has only a triangulation
  std::unique_ptr<BRepTopAdaptor_FClass2d> classifier;  // used where uv_polygon is not
  UvPolygon uv_polygon;
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;  // UV bounds (BRepTools::UVBounds)
  double area = 0;
  std::vector<int> edges;
  // The face's boundary as segments (degenerate triangles {a, b, b}) over boundary_points,
  // with the edge and parameters of each segment, and a tree over them.
  std::vector<Vec3> boundary_points;
  std::vector<std::array<int, 3>> boundary_segments;
  std::vector<std::array<double, 2>> segment_t;
  std::vector<int> segment_edge;
  std::unique_ptr<TriangleBvh> boundary;
  bool grid = false;       // sampled on a (u,v) grid (no usable fine triangulation)
  double grid_cell = 0;    // the grid's largest cell diagonal in 3D
  double deviation = 0;    // measured distance of the fine triangles from the surface
  double fine_area = 0;
  double brepmesh_area = 0;  // of BRepMesh's triangulation, before any grid fallback
};

struct FineMesh {
  std::vector<Vec3> points;
  std::vector<std::array<double, 2>> uv;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> face;  // per triangle
};

// Point on face f's surface at (u, v) (or, without a surface, not called).
Vec3 surface_point(const FaceData& f, double u, double v) { return to_vec(f.surface->Value(u, v)); }

// Newton projection of p onto f's surface from (u, v), bounded by the face's UV box: a
// variable at a bound whose gradient points out of the box is held there and the other
// one solved alone (projected Newton); damped (Levenberg-Marquardt) where the Hessian of
// |S - p|^2 is not positive definite. Returns the distance at the end and updates (u, v).
// D: the model's diagonal (for the convergence test).
double project_on_surface(const FaceData& f, Vec3 p, double& u, double& v, double D) {
  gp_Pnt P;
  gp_Vec Su, Sv, Suu, Svv, Suv;
  f.surface->D2(u, v, P, Su, Sv, Suu, Svv, Suv);
  Vec3 r = to_vec(P) - p;
  double fr = dot(r, r);
  double lambda = 0;
  for (int it = 0; it < kNewtonIterations; ++it) {
    const Vec3 su = to_vec(Su), sv = to_vec(Sv);
    const double gu = dot(su, r), gv = dot(sv, r);
    double a = dot(su, su) + dot(r, to_vec(Suu));
    double b = dot(su, sv) + dot(r, to_vec(Suv));
    double c = dot(sv, sv) + dot(r, to_vec(Svv));
    if (!(a > 0 && c > 0 && a * c - b * b > 0)) {  // Gauss-Newton part only, damped
      a = dot(su, su);
      b = dot(su, sv);
      c = dot(sv, sv);
      lambda = std::max(lambda, 1e-9 * (a + c) + 1e-300);
    }
    // Active bounds: at a bound with the descent direction (-g) pointing out.
    const bool hold_u = (u <= f.u0 && gu > 0) || (u >= f.u1 && gu < 0);
    const bool hold_v = (v <= f.v0 && gv > 0) || (v >= f.v1 && gv < 0);
    if (hold_u && hold_v) break;
    bool improved = false;
    for (int tries = 0; tries < 16; ++tries) {
      const double aa = a + lambda, cc = c + lambda;
      double du = 0, dv = 0;
      if (hold_u) {
        dv = cc > 0 ? -gv / cc : 0;
      } else if (hold_v) {
        du = aa > 0 ? -gu / aa : 0;
      } else {
        const double det = aa * cc - b * b;
        if (!(det > 0)) {
          lambda = std::max(4 * lambda, 1e-9 * (a + c) + 1e-300);
          continue;
        }
        du = -(cc * gu - b * gv) / det;
        dv = -(aa * gv - b * gu) / det;
      }
      const double nu = std::clamp(u + du, f.u0, f.u1), nv = std::clamp(v + dv, f.v0, f.v1);
      du = nu - u;
      dv = nv - v;
      gp_Pnt P2;
      gp_Vec Su2, Sv2, Suu2, Svv2, Suv2;
      f.surface->D2(nu, nv, P2, Su2, Sv2, Suu2, Svv2, Suv2);
      const Vec3 r2 = to_vec(P2) - p;
      const double f2 = dot(r2, r2);
      if (f2 <= fr) {
        const double step = norm(du * su + dv * sv);
        u = nu;
        v = nv;
        P = P2, Su = Su2, Sv = Sv2, Suu = Suu2, Svv = Svv2, Suv = Suv2;
        r = r2;
        const double gain = fr - f2;
        fr = f2;
        lambda *= 0.25;
        improved = step > kNewtonStep * D && gain > 1e-28 * D * D;
        break;
      }
      lambda = std::max(4 * lambda, 1e-6 * (a + c));
    }
    if (!improved) break;
  }
  return std::sqrt(fr);
}

// Newton projection of p onto edge curve e from parameter t (clamped to the edge's range).
double project_on_curve(const EdgeData& e, Vec3 p, double& t, double D) {
  const double t0 = e.curve->FirstParameter(), t1 = e.curve->LastParameter();
  gp_Pnt C;
  gp_Vec C1, C2;
  e.curve->D2(t, C, C1, C2);
  Vec3 r = to_vec(C) - p;
  double fr = dot(r, r);
  for (int it = 0; it < kNewtonIterations; ++it) {
    const double g = dot(to_vec(C1), r);
    double h = dot(to_vec(C1), to_vec(C1)) + dot(to_vec(C2), r);
    if (!(h > 0)) h = dot(to_vec(C1), to_vec(C1));
    if (!(h > 0)) break;
    double dt = -g / h;
    bool improved = false;
    for (int tries = 0; tries < 12; ++tries, dt *= 0.5) {
      const double nt = std::clamp(t + dt, t0, t1);
      gp_Pnt C_;
      gp_Vec C1_, C2_;
      e.curve->D2(nt, C_, C1_, C2_);
      const Vec3 r2 = to_vec(C_) - p;
      const double f2 = dot(r2, r2);
      if (f2 <= fr) {
        const double step = std::abs(nt - t) * norm(to_vec(C1));
        t = nt;
        C = C_, C1 = C1_, C2 = C2_;
        r = r2;
        improved = step > kNewtonStep * D && fr - f2 > 1e-28 * D * D;
        fr = f2;
        break;
      }
    }
    if (!improved) break;
  }
  return std::sqrt(fr);
}

class Reference {
 public:
  // near_boundary: within this 3D distance of a face's edges, the distance to a face is the
  // smaller of the foot's and the boundary's.
  Reference(const TopoDS_Shape& shape, double D, double fine_deflection, int samples, double near_boundary)
      : D_(D), fine_deflection_(fine_deflection), near_boundary_(near_boundary), samples_(samples) {
    collect_faces(shape);
    collect_edges();
    for (auto& f : faces_) build_boundary(*f);
    const auto start = std::chrono::steady_clock::now();
    mesh_fine(shape);
    fine_seconds = seconds_since(start);
  }

  int face_count() const { return static_cast<int>(faces_.size()); }
  double area() const {
    double a = 0;
    for (const auto& f : faces_) a += f->area;
    return a;
  }
  int grid_faces() const {
    int n = 0;
    for (const auto& f : faces_) n += f->grid;
    return n;
  }
  int mesh_only_faces() const {
    int n = 0;
    for (const auto& f : faces_) n += !f->surface;
    return n;
  }
  int empty_faces() const { return empty_faces_; }
  int area_replaced() const { return area_replaced_; }
  int area_uncertain() const { return area_uncertain_; }
  std::size_t fine_triangles() const { return fine_.triangles.size(); }
  double max_deviation() const {
    double m = 0;
    for (const auto& f : faces_) m = std::max(m, f->deviation);
    return m;
  }
  double fine_seconds = 0;

  // A point on an OCCT face (for surface -> mesh), where it came from, and how to move it.
  struct SurfaceSample {
    Vec3 point;
    int face = -1, edge = -1;  // edge >= 0: on that edge's curve at t (u)
    double u = 0, v = 0;
    double step = 0;  // parameter step of the local grid around it (for refinement)
  };

  // Calls visit(SurfaceSample) for every surface sample: each face's fine nodes (exact
  // surface points), the exact surface at a barycentric grid of each fine (u,v) triangle,
  // and the points of each edge polyline. Also sets each face's measured `deviation`.
  template <class Visit>
  void surface_samples(Visit&& visit_any) {
    const int m = samples_;
    for (std::size_t fi = 0; fi < faces_.size(); ++fi) {
      FaceData& f = *faces_[fi];
      // A grid face's cells may reach over its boundary: only points on the face count.
      const auto visit = [&](const SurfaceSample& sample) {
        if (!f.grid || contains(f, sample.u, sample.v)) visit_any(sample);
      };
      const auto [begin, end] = face_triangles_[fi];
      std::unordered_set<long long> seen_nodes, seen_sides;
      for (int t = begin; t < end; ++t) {
        const auto& tri = fine_.triangles[t];
        for (int k = 0; k < 3; ++k) {
          if (!seen_nodes.insert(tri[k]).second) continue;
          SurfaceSample s;
          s.point = fine_.points[tri[k]];
          s.face = static_cast<int>(fi);
          s.u = fine_.uv[tri[k]][0];
          s.v = fine_.uv[tri[k]][1];
          s.step = uv_size(tri) / m;
          visit(s);
        }
        for (int i = 0; i <= m; ++i) {
          for (int j = 0; i + j <= m; ++j) {
            const int k = m - i - j;
            const int zeros = (i == 0) + (j == 0) + (k == 0);
            if (zeros >= 2) continue;  // a corner
            if (zeros == 1) {          // on a side: once per side of the face's mesh
              const int a = k == 0 ? tri[0] : (i == 0 ? tri[1] : tri[0]);
              const int b = k == 0 ? tri[1] : (i == 0 ? tri[2] : tri[2]);
              const long long key = static_cast<long long>(std::min(a, b)) * 0x100000000LL + std::max(a, b);
              // Each side's points are generated at the first of its triangles (both
              // triangles give the same set of points).
              if (seen_sides.count(key)) continue;
            }
            const std::array<double, 3> w = {double(i) / m, double(j) / m, double(k) / m};
            visit(barycentric_sample(f, static_cast<int>(fi), tri, w, m));
          }
        }
        if (m % 3 != 0) visit(barycentric_sample(f, static_cast<int>(fi), tri, {1.0 / 3, 1.0 / 3, 1.0 / 3}, m));
        for (int k = 0; k < 3; ++k) {
          const int a = tri[k], b = tri[(k + 1) % 3];
          seen_sides.insert(static_cast<long long>(std::min(a, b)) * 0x100000000LL + std::max(a, b));
        }
      }
    }
    for (std::size_t ei = 0; ei < edges_.size(); ++ei) {
      const EdgeData& e = edges_[ei];
      const auto& visit = visit_any;
      for (std::size_t k = 0; k < e.p.size(); ++k) {
        SurfaceSample s;
        s.point = e.p[k];
        s.face = e.face;
        s.edge = static_cast<int>(ei);
        s.u = e.t[k];
        s.step = e.t.size() > 1 ? std::abs(e.t[std::min(k + 1, e.t.size() - 1)] - e.t[k > 0 ? k - 1 : 0]) / 2 : 0;
        visit(s);
      }
    }
  }

  // The sample moved to (u, v) (or edge parameter u); false if outside the face/edge.
  bool move_sample(const SurfaceSample& s, double u, double v, SurfaceSample& out) const {
    out = s;
    if (s.edge >= 0) {
      const EdgeData& e = edges_[s.edge];
      if (u < e.curve->FirstParameter() || u > e.curve->LastParameter()) return false;
      out.u = u;
      out.point = to_vec(e.curve->Value(u));
      return true;
    }
    const FaceData& f = *faces_[s.face];
    if (!f.surface || u < f.u0 || u > f.u1 || v < f.v0 || v > f.v1) return false;
    if (!contains(f, u, v)) return false;
    out.u = u;
    out.v = v;
    out.point = surface_point(f, u, v);
    return true;
  }

  // Distance from p to the nearest trimmed face (upper bound; see the file comment), and
  // that face. Needs surface_samples() to have run (it measures the margins).
  double distance_to_faces(Vec3 p, int& face) const {
    face = -1;
    if (!fine_bvh_) return std::numeric_limits<double>::infinity();
    const TriangleBvh::Hit nearest = fine_bvh_->nearest(p);
    struct Candidate {
      double fine_distance;
      int triangle;
      TrianglePoint on;
    };
    std::vector<std::pair<int, Candidate>> candidates;  // per face, its nearest fine point
    fine_bvh_->within(p, nearest.distance + 2 * margin_, [&](const TriangleBvh::Hit& h) {
      const int fi = fine_.face[h.triangle];
      auto it = std::find_if(candidates.begin(), candidates.end(), [fi](const auto& c) { return c.first == fi; });
      if (it == candidates.end()) candidates.push_back({fi, Candidate{h.distance, h.triangle, h.on}});
      else if (h.distance < it->second.fine_distance) it->second = Candidate{h.distance, h.triangle, h.on};
    });
    std::sort(candidates.begin(), candidates.end(),
              [](const auto& a, const auto& b) { return a.second.fine_distance < b.second.fine_distance; });
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [fi, c] : candidates) {
      const FaceData& f = *faces_[fi];
      if (verbose) std::fprintf(stderr, "candidate face %d fine %.9g margin %.4g\n", fi, c.fine_distance, face_margin(f));
      if (c.fine_distance - face_margin(f) >= best) continue;  // cannot be nearer
      const double d = distance_to_face(fi, p, c.triangle, c.on);
      if (verbose) std::fprintf(stderr, "  distance %.9g\n", d);
      if (d < best) {
        best = d;
        face = fi;
      }
    }
    return best;
  }

  // Faces whose fine triangles come within `radius` of p.
  std::vector<int> faces_near(Vec3 p, double radius) const {
    std::vector<int> out;
    if (!fine_bvh_) return out;
    fine_bvh_->within(p, radius, [&](const TriangleBvh::Hit& h) { out.push_back(fine_.face[h.triangle]); });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  // BRepExtrema_DistShapeShape from p to the faces near it (the exact re-measure).
  double exact_distance(Vec3 p, double fast, int& face) const {
    const TopoDS_Vertex vertex = BRepBuilderAPI_MakeVertex(to_pnt(p)).Vertex();
    double best = std::numeric_limits<double>::infinity();
    for (const int fi : faces_near(p, fast + 2 * margin_)) {
      BRepExtrema_DistShapeShape dist(vertex, faces_[fi]->face);
      if (dist.IsDone() && dist.Value() < best) {
        best = dist.Value();
        face = fi;
      }
    }
    return best;
  }

  // All faces as one compound (the brute-force reference).
  TopoDS_Compound compound() const {
    TopoDS_Compound c;
    BRep_Builder builder;
    builder.MakeCompound(c);
    for (const auto& f : faces_) builder.Add(c, f->face);
    return c;
  }
  bool verbose = false;
  void debug_probe(Vec3 p) const {
    const TopoDS_Vertex vertex = BRepBuilderAPI_MakeVertex(to_pnt(p)).Vertex();
    for (std::size_t fi = 0; fi < faces_.size(); ++fi) {
      BRepExtrema_DistShapeShape dist(vertex, faces_[fi]->face);
      if (!dist.IsDone() || dist.Value() > 1.0) continue;
      double fine = 1e300;
      for (int t = face_triangles_[fi].first; t < face_triangles_[fi].second; ++t) {
        const auto& tri = fine_.triangles[t];
        fine = std::min(fine, norm(p - occt_reference::closest_on_triangle(p, fine_.points[tri[0]], fine_.points[tri[1]], fine_.points[tri[2]]).point));
      }
      std::fprintf(stderr, "face %zu: exact %.9g fine %.9g\n", fi, dist.Value(), fine);
      if (std::getenv("OCCT_CHECK_DEBUG")) faces_[fi]->uv_polygon.dump();
    }
  }
  // Per-face figures on stderr (environment variable OCCT_CHECK_DEBUG set).
  void debug_faces() const {
    for (std::size_t fi = 0; fi < faces_.size(); ++fi) {
      const FaceData& f = *faces_[fi];
      std::fprintf(stderr, "face %zu: type %d area %.6g brepmesh_area %.6g fine_area %.6g deviation %.4g grid %d triangles %d edges %zu uv [%g,%g]x[%g,%g]\n",
                   fi, f.surface ? int(f.surface->GetType()) : -1, f.area, f.brepmesh_area, f.fine_area, f.deviation, int(f.grid),
                   face_triangles_[fi].second - face_triangles_[fi].first, f.edges.size(), f.u0, f.u1, f.v0, f.v1);
    }
  }
  void finish_margins() {
    margin_ = fine_deflection_;
    for (const auto& f : faces_) margin_ = std::max(margin_, face_margin(*f));
  }

 private:
  // How far the face may be from its fine triangles: their measured deviation (with a
  // safety factor), at least the fine deflection (the boundary chords), and for a grid
  // face one cell (the grid stops up to a cell short of the boundary).
  double face_margin(const FaceData& f) const {
    return std::max({fine_deflection_, 1.5 * f.deviation, f.grid_cell});
  }

  double uv_size(const std::array<int, 3>& tri) const {
    double s = 0;
    for (int k = 0; k < 3; ++k) {
      const auto& a = fine_.uv[tri[k]];
      const auto& b = fine_.uv[tri[(k + 1) % 3]];
      s = std::max(s, std::hypot(a[0] - b[0], a[1] - b[1]));
    }
    return s;
  }

  SurfaceSample barycentric_sample(FaceData& f, int fi, const std::array<int, 3>& tri,
                                   const std::array<double, 3>& w, int m) {
    SurfaceSample s;
    s.face = fi;
    const Vec3 flat = w[0] * fine_.points[tri[0]] + w[1] * fine_.points[tri[1]] + w[2] * fine_.points[tri[2]];
    s.u = w[0] * fine_.uv[tri[0]][0] + w[1] * fine_.uv[tri[1]][0] + w[2] * fine_.uv[tri[2]][0];
    s.v = w[0] * fine_.uv[tri[0]][1] + w[1] * fine_.uv[tri[1]][1] + w[2] * fine_.uv[tri[2]][1];
    s.step = uv_size(tri) / m;
    s.point = f.surface ? surface_point(f, s.u, s.v) : flat;
    if (f.surface && w[0] == w[1] && w[1] == w[2]) {  // the centroid: how far the fine mesh is
      double u = s.u, v = s.v;
      f.deviation = std::max(f.deviation, project_on_surface(f, flat, u, v, D_));
    }
    return s;
  }

  void collect_faces(const TopoDS_Shape& shape) {
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
      auto f = std::make_unique<FaceData>();
      f->face = TopoDS::Face(it.Current());
      GProp_GProps props;
      BRepGProp::SurfaceProperties(f->face, props, kAreaPrecision);
      f->area = std::abs(props.Mass());
      TopLoc_Location loc;
      if (!BRep_Tool::Surface(f->face, loc).IsNull()) {
        f->surface = std::make_unique<BRepAdaptor_Surface>(f->face, Standard_True);
        BRepTools::UVBounds(f->face, f->u0, f->u1, f->v0, f->v1);
        f->classifier = std::make_unique<BRepTopAdaptor_FClass2d>(f->face, Precision::PConfusion());
      }
      faces_.push_back(std::move(f));
    }
  }

  void collect_edges() {
    TopTools_IndexedMapOfShape edge_index;
    for (std::size_t fi = 0; fi < faces_.size(); ++fi) {
      FaceData& f = *faces_[fi];
      for (TopExp_Explorer it(f.face, TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
        if (BRep_Tool::Degenerated(edge)) continue;
        int index = edge_index.FindIndex(edge);
        if (index == 0) {
          index = edge_index.Add(edge);
          EdgeData e;
          e.edge = edge;
          e.face = static_cast<int>(fi);
          try {
            e.curve = std::make_unique<BRepAdaptor_Curve>(edge);
            sample_edge(e);
          } catch (const Standard_Failure&) {
            e.curve.reset();
            e.t.clear();
            e.p.clear();
          }
          edges_.push_back(std::move(e));
        }
        const int ei = index - 1;
        if (std::find(f.edges.begin(), f.edges.end(), ei) == f.edges.end()) f.edges.push_back(ei);
      }
    }
  }

  void sample_edge(EdgeData& e) {
    const GCPnts_TangentialDeflection polygon(*e.curve, kFineAngle, fine_deflection_, 4);
    std::vector<double> t;
    for (int k = 1; k <= polygon.NbPoints(); ++k) t.push_back(polygon.Parameter(k));
    if (t.size() < 2) t = {e.curve->FirstParameter(), e.curve->LastParameter()};
    for (std::size_t k = 0; k + 1 < t.size(); ++k)
      for (int s = 0; s < kEdgeSubdivisions; ++s) e.t.push_back(t[k] + (t[k + 1] - t[k]) * s / kEdgeSubdivisions);
    e.t.push_back(t.back());
    for (const double ti : e.t) e.p.push_back(to_vec(e.curve->Value(ti)));
  }

  void build_boundary(FaceData& f) {
    for (const int ei : f.edges) {
      const EdgeData& e = edges_[ei];
      if (e.p.size() < 2) continue;
      const int first = static_cast<int>(f.boundary_points.size());
      f.boundary_points.insert(f.boundary_points.end(), e.p.begin(), e.p.end());
      for (std::size_t k = 0; k + 1 < e.p.size(); ++k) {
        const int a = first + static_cast<int>(k);
        f.boundary_segments.push_back({a, a + 1, a + 1});
        f.segment_t.push_back({e.t[k], e.t[k + 1]});
        f.segment_edge.push_back(ei);
      }
    }
    f.boundary = std::make_unique<TriangleBvh>(f.boundary_points, f.boundary_segments);
    build_uv_polygon(f);
  }

  // f.uv_polygon from every edge occurrence's pcurve, at the parameters of the edge's 3D
  // polyline (degenerate edges: kDegenerateSamples even steps); left empty (FClass2d is
  // used) if a pcurve is missing.
  void build_uv_polygon(FaceData& f) {
    if (!f.surface) return;
    TopTools_IndexedMapOfShape edge_index;
    for (const int ei : f.edges) edge_index.Add(edges_[ei].edge);
    for (TopExp_Explorer it(f.face, TopAbs_EDGE); it.More(); it.Next()) {
      const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
      double first, last;
      const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, f.face, first, last);
      if (pcurve.IsNull()) {
        f.uv_polygon = UvPolygon();
        return;
      }
      std::vector<double> t;
      const int index = edge_index.FindIndex(edge);
      if (index > 0 && !BRep_Tool::Degenerated(edge)) t = edges_[f.edges[index - 1]].t;
      if (t.size() < 2)
        for (int k = 0; k <= kDegenerateSamples; ++k) t.push_back(first + (last - first) * k / kDegenerateSamples);
      gp_Pnt2d a = pcurve->Value(t[0]);
      for (std::size_t k = 1; k < t.size(); ++k) {
        const gp_Pnt2d b = pcurve->Value(t[k]);
        f.uv_polygon.add(a.X(), a.Y(), b.X(), b.Y());
        a = b;
      }
    }
    f.uv_polygon.finish();
  }

  // The fine triangulation: BRepMesh at the fine deflection (after removing any stored
  // triangulation), or a (u,v) grid where BRepMesh gives none or a wrong area.
  void mesh_fine(const TopoDS_Shape& shape) {
    BRepTools::Clean(shape);
    IMeshTools_Parameters params;
    params.Deflection = fine_deflection_;
    params.Angle = kFineAngle;
    params.Relative = Standard_False;
    params.InParallel = Standard_True;
    BRepMesh_IncrementalMesh mesher(shape, params);
    face_triangles_.resize(faces_.size());
    for (std::size_t fi = 0; fi < faces_.size(); ++fi) {
      FaceData& f = *faces_[fi];
      const int begin = static_cast<int>(fine_.triangles.size());
      TopLoc_Location loc;
      const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(f.face, loc);
      bool usable = !tri.IsNull() && tri->NbTriangles() > 0 && (tri->HasUVNodes() || !f.surface);
      if (usable) add_triangulation(f, static_cast<int>(fi), tri, loc);
      f.fine_area = f.brepmesh_area = area_of(begin);
      const bool checkable = f.surface && f.area > kTinyArea * D_ * D_;
      // Three opinions on the face's area where BRepGProp and BRepMesh's (u,v) domain
      // disagree: the third is a midpoint rule over a (u,v) grid classified by the
      // face's polygon. BRepMesh loses when the grid sides with BRepGProp (ec_turbine-A's
      // face 1: 2.4x the area); BRepGProp loses when the grid sides with BRepMesh
      // (PRO20358-X28.igs: BRepGProp 8045, BRepMesh and grid 8831, trimkit 8832).
      if (usable && checkable) {
        const double quadrature = uv_quadrature(f, begin);
        if (std::abs(quadrature / f.area - 1) > kFineAreaMismatch) {
          const double grid = grid_quadrature(f);
          if (std::abs(grid / f.area - 1) <= kFineAreaMismatch) {
            usable = false;
          } else if (std::abs(grid / quadrature - 1) <= kFineAreaMismatch) {
            f.area = quadrature;
            ++area_replaced_;
          } else {
            usable = false;
            ++area_uncertain_;
          }
        }
      }
      if (!usable) {
        truncate(begin);
        if (f.surface) {
          f.grid = true;
          add_grid(f, static_cast<int>(fi));
        } else {
          ++empty_faces_;
        }
        f.fine_area = area_of(begin);
      }
      if (tri.IsNull() && checkable) {  // no BRepMesh opinion: the grid checks BRepGProp
        const double grid = grid_quadrature(f);
        if (std::abs(grid / f.area - 1) > kFineAreaMismatch) ++area_uncertain_;
      }
      face_triangles_[fi] = {begin, static_cast<int>(fine_.triangles.size())};
    }
    fine_bvh_ = std::make_unique<TriangleBvh>(fine_.points, fine_.triangles);
  }

  // Area of the surface over the (u,v) triangles from `begin` on: |Su x Sv| integrated
  // with the 3-point rule exact for quadratics (Strang & Fix; points (2/3, 1/6, 1/6)).
  double uv_quadrature(const FaceData& f, int begin) const {
    double a = 0;
    for (std::size_t t = begin; t < fine_.triangles.size(); ++t) {
      const auto& tri = fine_.triangles[t];
      const auto &p = fine_.uv[tri[0]], &q = fine_.uv[tri[1]], &r = fine_.uv[tri[2]];
      const double uv_area = 0.5 * std::abs((q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1]));
      for (int k = 0; k < 3; ++k) {
        const double w0 = k == 0 ? 2.0 / 3 : 1.0 / 6, w1 = k == 1 ? 2.0 / 3 : 1.0 / 6, w2 = 1 - w0 - w1;
        gp_Pnt P;
        gp_Vec Su, Sv;
        f.surface->D1(w0 * p[0] + w1 * q[0] + w2 * r[0], w0 * p[1] + w1 * q[1] + w2 * r[1], P, Su, Sv);
        a += uv_area / 3 * Su.Crossed(Sv).Magnitude();
      }
    }
    return a;
  }

  // Area of the trimmed face by the midpoint rule on a kAreaGrid x kAreaGrid grid over
  // its UV box, cells counted whose centre the face's polygon contains.
  double grid_quadrature(const FaceData& f) const {
    const double du = (f.u1 - f.u0) / kAreaGrid, dv = (f.v1 - f.v0) / kAreaGrid;
    double a = 0;
    for (int j = 0; j < kAreaGrid; ++j)
      for (int i = 0; i < kAreaGrid; ++i) {
        const double u = f.u0 + (i + 0.5) * du, v = f.v0 + (j + 0.5) * dv;
        if (!contains(f, u, v)) continue;
        gp_Pnt P;
        gp_Vec Su, Sv;
        f.surface->D1(u, v, P, Su, Sv);
        a += Su.Crossed(Sv).Magnitude() * du * dv;
      }
    return a;
  }

  double area_of(int begin) const {
    double a = 0;
    for (std::size_t t = begin; t < fine_.triangles.size(); ++t) {
      const auto& tri = fine_.triangles[t];
      a += 0.5 * norm(cross(fine_.points[tri[1]] - fine_.points[tri[0]], fine_.points[tri[2]] - fine_.points[tri[0]]));
    }
    return a;
  }

  void truncate(int begin) {
    int first_point = static_cast<int>(fine_.points.size());
    for (std::size_t t = begin; t < fine_.triangles.size(); ++t)
      for (const int v : fine_.triangles[t]) first_point = std::min(first_point, v);
    fine_.triangles.resize(begin);
    fine_.face.resize(begin);
    fine_.points.resize(first_point);
    fine_.uv.resize(first_point);
  }

  void add_triangulation(const FaceData&, int fi, const Handle(Poly_Triangulation)& tri, const TopLoc_Location& loc) {
    const int base = static_cast<int>(fine_.points.size()) - 1;  // OCCT nodes count from 1
    const gp_Trsf& placement = loc.Transformation();
    for (int i = 1; i <= tri->NbNodes(); ++i) {
      fine_.points.push_back(to_vec(tri->Node(i).Transformed(placement)));
      const gp_Pnt2d uv = tri->HasUVNodes() ? tri->UVNode(i) : gp_Pnt2d(0, 0);
      fine_.uv.push_back({uv.X(), uv.Y()});
    }
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
      int a, b, c;
      tri->Triangle(t).Get(a, b, c);
      fine_.triangles.push_back({base + a, base + b, base + c});
      fine_.face.push_back(fi);
    }
  }

  // Grid fallback: an nu x nv grid over the UV bounds, spacing about equal in 3D; a cell
  // is kept (as two triangles) when a corner is inside the face.
  void add_grid(FaceData& f, int fi) {
    constexpr int kProbe = 16;
    double lu = 0, lv = 0;
    for (int i = 0; i <= 4; ++i) {
      double su = 0, sv = 0;
      Vec3 pu = surface_point(f, f.u0, f.v0 + (f.v1 - f.v0) * i / 4);
      Vec3 pv = surface_point(f, f.u0 + (f.u1 - f.u0) * i / 4, f.v0);
      for (int k = 1; k <= kProbe; ++k) {
        const Vec3 qu = surface_point(f, f.u0 + (f.u1 - f.u0) * k / kProbe, f.v0 + (f.v1 - f.v0) * i / 4);
        const Vec3 qv = surface_point(f, f.u0 + (f.u1 - f.u0) * i / 4, f.v0 + (f.v1 - f.v0) * k / kProbe);
        su += norm(qu - pu);
        sv += norm(qv - pv);
        pu = qu;
        pv = qv;
      }
      lu = std::max(lu, su);
      lv = std::max(lv, sv);
    }
    const double h = std::max(std::sqrt(std::max(lu * lv, 1e-300) / kGridCells), 1e-12 * D_);
    const int nu = std::clamp(static_cast<int>(std::ceil(lu / h)), 2, 2000);
    const int nv = std::clamp(static_cast<int>(std::ceil(lv / h)), 2, 2000);
    const int base = static_cast<int>(fine_.points.size());
    std::vector<char> inside((nu + 1) * (nv + 1));
    for (int j = 0; j <= nv; ++j) {
      for (int i = 0; i <= nu; ++i) {
        const double u = f.u0 + (f.u1 - f.u0) * i / nu, v = f.v0 + (f.v1 - f.v0) * j / nv;
        inside[j * (nu + 1) + i] = contains(f, u, v);
        fine_.points.push_back(surface_point(f, u, v));
        fine_.uv.push_back({u, v});
      }
    }
    for (int j = 0; j < nv; ++j) {
      for (int i = 0; i < nu; ++i) {
        const int a = j * (nu + 1) + i, b = a + 1, c = a + nu + 1, d = c + 1;
        // Cells with a corner on the face are kept, so that the grid reaches the face's
        // boundary within one cell (for finding candidate faces); samples are only taken
        // where they are on the face (surface_samples).
        if (!(inside[a] || inside[b] || inside[c] || inside[d])) continue;
        const Vec3 pa = fine_.points[base + a], pd = fine_.points[base + d];
        const Vec3 pb = fine_.points[base + b], pc = fine_.points[base + c];
        f.grid_cell = std::max({f.grid_cell, norm(pd - pa), norm(pc - pb)});
        fine_.triangles.push_back({base + a, base + b, base + d});
        fine_.triangles.push_back({base + a, base + d, base + c});
        fine_.face.push_back(fi);
        fine_.face.push_back(fi);
      }
    }
  }

  // Distance from p to face fi, starting from the nearest point `on` of its fine triangle.
  double distance_to_face(int fi, Vec3 p, int triangle, const TrianglePoint& on) const {
    const FaceData& f = *faces_[fi];
    if (!f.surface) return norm(p - on.point);  // the triangulation is the face
    const auto& tri = fine_.triangles[triangle];
    double u = 0, v = 0;
    for (int k = 0; k < 3; ++k) {
      u += on.weights[k] * fine_.uv[tri[k]][0];
      v += on.weights[k] * fine_.uv[tri[k]][1];
    }
    u = std::clamp(u, f.u0, f.u1);
    v = std::clamp(v, f.v0, f.v1);
    if (verbose) std::fprintf(stderr, "  start uv %.9g %.9g d %.9g\n", u, v, norm(p - surface_point(f, u, v)));
    const double d = project_on_surface(f, p, u, v, D_);
    bool near = false;
    const bool inside = contains(f, u, v, &near);
    if (verbose) {
      const BRepClass_FaceClassifier exact(f.face, gp_Pnt2d(u, v), Precision::PConfusion());
      const TopAbs_State fclass = f.classifier->Perform(gp_Pnt2d(u, v));
      std::fprintf(stderr, "  newton uv %.9g %.9g d %.9g inside %d (polygon %d, FClass2d %d, exact %d) near %d boundary %.9g\n",
                   u, v, d, int(inside), f.uv_polygon.contains(u, v), int(fclass), int(exact.State()), int(near),
                   distance_to_boundary(f, p));
    }
    // The foot of the perpendicular if it is on the face, else (or also, when the foot is
    // near the edges) the nearest boundary point. The start point S(u, v) is not used: its
    // fine triangle may reach outside the face by the fine mesh's boundary chord.
    if (inside && !near) return d;
    const double boundary = distance_to_boundary(f, p);
    return inside ? std::min(d, boundary) : boundary;
  }

  // Whether (u, v) is on the trimmed face: the face's (u,v) polygon (BRepTopAdaptor_FClass2d
  // where it has none). *near: the point is within the near-boundary distance of the
  // face's edges in 3D, where the caller also takes the boundary's distance.
  bool contains(const FaceData& f, double u, double v, bool* near = nullptr) const {
    bool inside;
    const int state = f.uv_polygon.empty() ? -1 : f.uv_polygon.contains(u, v);
    if (state >= 0) {
      inside = state == 1;
    } else if (f.uv_polygon.empty()) {
      const TopAbs_State fclass = f.classifier->Perform(gp_Pnt2d(u, v));
      inside = fclass == TopAbs_IN || fclass == TopAbs_ON;
    } else {  // the polygon cannot tell: OCCT's exact classifier
      const BRepClass_FaceClassifier exact(f.face, gp_Pnt2d(u, v), Precision::PConfusion());
      inside = exact.State() == TopAbs_IN || exact.State() == TopAbs_ON;
    }
    if (near && f.boundary && !f.boundary_segments.empty())
      *near = f.boundary->nearest(surface_point(f, u, v)).distance < near_boundary_;
    return inside;
  }

  double distance_to_boundary(const FaceData& f, Vec3 p) const {
    if (!f.boundary || f.boundary_segments.empty()) return std::numeric_limits<double>::infinity();
    const TriangleBvh::Hit h = f.boundary->nearest(p);
    const EdgeData& e = edges_[f.segment_edge[h.triangle]];
    const auto& st = f.segment_t[h.triangle];
    double t = h.on.weights[0] * st[0] + (h.on.weights[1] + h.on.weights[2]) * st[1];
    const double start = norm(p - to_vec(e.curve->Value(t)));
    return std::min(start, project_on_curve(e, p, t, D_));
  }

  double D_, fine_deflection_, near_boundary_;
  int samples_;
  std::vector<std::unique_ptr<FaceData>> faces_;
  std::vector<EdgeData> edges_;
  FineMesh fine_;
  std::vector<std::pair<int, int>> face_triangles_;
  std::unique_ptr<TriangleBvh> fine_bvh_;
  double margin_ = 0;
  int empty_faces_ = 0;
  int area_replaced_ = 0, area_uncertain_ = 0;
};

// ---------------------------------------------------------------------------------------
// Statistics of one direction: max, mean, and the largest samples kept for refinement.

template <class Sample>
struct Direction {
  double sum = 0, max = 0;
  std::size_t count = 0;
  struct Entry {
    double distance;
    Sample sample;
    bool operator>(const Entry& o) const { return distance > o.distance; }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> top;  // smallest on top

  void add(double d, const Sample& s) {
    sum += d;
    ++count;
    max = std::max(max, d);
    if (static_cast<int>(top.size()) < kRefined) top.push({d, s});
    else if (d > top.top().distance) {
      top.pop();
      top.push({d, s});
    }
  }
  // The kept samples, largest first.
  std::vector<Entry> largest() {
    std::vector<Entry> out;
    while (!top.empty()) {
      out.push_back(top.top());
      top.pop();
    }
    std::reverse(out.begin(), out.end());
    return out;
  }
  double mean() const { return count ? sum / count : 0; }
};

struct MeshSample {
  Vec3 point;
  int triangle = -1;
  std::array<double, 3> w{};
};

// Open edges of the mesh (vertices merged by exact position): sides used an odd number
// of times.
std::size_t open_edges(const occt_reference::MeshFile& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      if (a != b) ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::size_t n = 0;
  for (const auto& [side, count] : uses) n += count % 2;
  return n;
}

struct Options {
  std::string model;
  std::vector<std::string> meshes;
  double relative = 0.001, absolute = 0;  // absolute > 0 wins
  int samples = kDefaultSamples;
  double fine = kDefaultFine;
  bool brute_force = false;  // also re-measure every mesh sample with BRepExtrema (slow)
};

// What every mesh of one model is measured against: the model, its tolerance and the
// reference (built once, so that several meshes of one file cost one fine mesh).
struct Setup {
  Model model;
  double read_seconds = 0;
  double D = 0, T = 0;  // OCCT units
  std::unique_ptr<Reference> ref;
};

std::string json_start(const Options& opt, const std::string& mesh) {
  return "{\"file\": " + json_string(base_name(opt.model)) + ", \"mesh\": " + json_string(base_name(mesh));
}

// Prints {"file", "mesh", "error"} for each mesh.
int report_error(const Options& opt, const std::string& message) {
  for (const std::string& mesh : opt.meshes)
    std::printf("%s, \"error\": %s}\n", json_start(opt, mesh).c_str(), json_string(message).c_str());
  return 2;
}

// Reads `path` and scales it to OCCT units; throws on a read error or an empty mesh.
occt_reference::MeshFile read_scaled_mesh(const std::string& path, double s) {
  occt_reference::MeshFile mesh = occt_reference::read_mesh_file(path);
  if (mesh.triangles.empty()) throw std::runtime_error(path + ": no triangles");
  for (Vec3& p : mesh.points) p = s * p;
  return mesh;
}

int measure(const Options& opt, Setup& setup, const std::string& mesh_path, const occt_reference::MeshFile& mesh,
            std::chrono::steady_clock::time_point start);

int run(const Options& opt) {
  const auto start = std::chrono::steady_clock::now();
  Setup setup;
  try {
    setup.model = read_model(opt.model);
  } catch (const Standard_Failure& e) {
    return report_error(opt, std::string("OCCT: ") + e.GetMessageString());
  } catch (const std::exception& e) {
    return report_error(opt, e.what());
  }
  setup.read_seconds = seconds_since(start);
  const double s = setup.model.unit;  // OCCT length of one mesh unit
  Bnd_Box box;
  BRepBndLib::AddOptimal(setup.model.shape, box, Standard_False, Standard_False);
  setup.D = std::sqrt(box.SquareExtent());
  setup.T = opt.absolute > 0 ? opt.absolute * s : opt.relative * setup.D;
  setup.ref = std::make_unique<Reference>(setup.model.shape, setup.D, opt.fine * setup.T, opt.samples, setup.T);
  int status = 0;
  for (const std::string& path : opt.meshes) {
    const auto mesh_start = std::chrono::steady_clock::now();
    occt_reference::MeshFile mesh;
    try {
      mesh = read_scaled_mesh(path, s);
    } catch (const std::exception& e) {
      std::printf("%s, \"error\": %s}\n", json_start(opt, path).c_str(), json_string(e.what()).c_str());
      status = 2;
      continue;
    }
    // The first mesh's seconds include the read and the reference; the others' only their own.
    status = std::max(status, measure(opt, setup, path, mesh, path == opt.meshes.front() ? start : mesh_start));
    std::fflush(stdout);
  }
  return status;
}

// One JSON line for `mesh` against the setup's reference; 0 if it passes, 1 if not.
int measure(const Options& opt, Setup& setup, const std::string& mesh_path, const occt_reference::MeshFile& mesh,
            std::chrono::steady_clock::time_point start) {
  std::string json = json_start(opt, mesh_path);
  Reference& ref = *setup.ref;
  const double s = setup.model.unit, D = setup.D, T = setup.T, read_seconds = setup.read_seconds;

  // Surface -> mesh.
  const auto s2m_start = std::chrono::steady_clock::now();
  const TriangleBvh mesh_bvh(mesh.points, mesh.triangles);
  Direction<Reference::SurfaceSample> s2m;
  ref.surface_samples([&](const Reference::SurfaceSample& sample) {
    s2m.add(mesh_bvh.nearest(sample.point).distance, sample);
  });
  ref.finish_margins();
  if (std::getenv("OCCT_CHECK_DEBUG")) ref.debug_faces();
  if (const char* probe = std::getenv("OCCT_CHECK_POINT")) {
    Vec3 p;
    std::sscanf(probe, "%lf,%lf,%lf", &p.x, &p.y, &p.z);
    p = s * p;
    ref.verbose = true;
    int face;
    const double fast = ref.distance_to_faces(p, face);
    ref.verbose = false;
    int exact_face = -1;
    const double exact = ref.exact_distance(p, fast, exact_face);
    std::fprintf(stderr, "probe: fast %.9g (face %d), exact %.9g (face %d)\n", fast, face, exact, exact_face);
    ref.debug_probe(p);
    BRepExtrema_DistShapeShape all(BRepBuilderAPI_MakeVertex(to_pnt(p)).Vertex(), ref.compound());
    if (all.IsDone()) {
      std::fprintf(stderr, "whole shape: %.9g at %g %g %g\n", all.Value(), all.PointOnShape2(1).X(), all.PointOnShape2(1).Y(), all.PointOnShape2(1).Z());
    }
    return 0;
  }
  double s2m_max = 0;
  Reference::SurfaceSample s2m_worst;
  {
    // Refine each kept sample by a pattern search in its face's (u,v) (or its edge's t).
    for (const auto& entry : s2m.largest()) {
      Reference::SurfaceSample best = entry.sample;
      double best_d = entry.distance;
      double h = best.step;
      for (int round = 0; round < 40 && h > 0; ++round) {
        bool moved = false;
        for (int du = -1; du <= 1; ++du)
          for (int dv = -1; dv <= 1; ++dv) {
            if ((du == 0 && dv == 0) || (best.edge >= 0 && dv != 0)) continue;
            Reference::SurfaceSample trial;
            if (!ref.move_sample(best, best.u + du * h, best.v + dv * h, trial)) continue;
            const double d = mesh_bvh.nearest(trial.point).distance;
            if (d > best_d) {
              best_d = d;
              best = trial;
              moved = true;
            }
          }
        if (!moved) h *= 0.5;
        if (h < entry.sample.step / 256) break;
      }
      if (best_d > s2m_max) {
        s2m_max = best_d;
        s2m_worst = best;
      }
    }
  }
  const double s2m_seconds = seconds_since(s2m_start);

  // Mesh -> surface: a barycentric grid of each triangle plus its centroid; vertices and
  // side points once (by vertex and side).
  const auto m2s_start = std::chrono::steady_clock::now();
  Direction<MeshSample> m2s;
  const TopoDS_Compound all_faces = ref.compound();
  // --brute-force: BRepExtrema_DistShapeShape from every sample to the whole shape.
  double brute_max = 0, brute_over = 0, brute_under = 0;
  std::size_t brute_differ = 0;
  Vec3 brute_under_point, brute_over_point;
  {
    const int n = opt.samples;
    std::vector<char> vertex_done(mesh.points.size(), 0);
    std::unordered_set<long long> side_done;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      const auto sample = [&](std::array<double, 3> w) {
        MeshSample ms;
        ms.triangle = static_cast<int>(t);
        ms.w = w;
        ms.point = w[0] * mesh.points[tri[0]] + w[1] * mesh.points[tri[1]] + w[2] * mesh.points[tri[2]];
        int face;
        const double fast = ref.distance_to_faces(ms.point, face);
        m2s.add(fast, ms);
        if (opt.brute_force) {
          BRepExtrema_DistShapeShape dist(BRepBuilderAPI_MakeVertex(to_pnt(ms.point)).Vertex(), all_faces);
          const double exact = dist.IsDone() ? dist.Value() : fast;
          brute_max = std::max(brute_max, exact);
          if (fast - exact > brute_over) {
            brute_over = fast - exact;
            brute_over_point = ms.point;
          }
          if (exact - fast > brute_under) {
            brute_under = exact - fast;
            brute_under_point = ms.point;
          }
          brute_differ += std::abs(fast - exact) > 1e-6 * T;
        }
      };
      bool side_new[3];
      for (int k = 0; k < 3; ++k) {
        const int a = tri[k], b = tri[(k + 1) % 3];
        side_new[k] = side_done.insert(static_cast<long long>(std::min(a, b)) * 0x100000000LL + std::max(a, b)).second;
      }
      for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
          const int k = n - i - j;
          const std::array<double, 3> w = {double(i) / n, double(j) / n, double(k) / n};
          const int zeros = (i == 0) + (j == 0) + (k == 0);
          if (zeros == 2) {
            const int v = tri[i == n ? 0 : j == n ? 1 : 2];
            if (vertex_done[v]) continue;
            vertex_done[v] = 1;
          } else if (zeros == 1) {
            const int side = k == 0 ? 0 : (i == 0 ? 1 : 2);  // sides 01, 12, 20
            if (!side_new[side]) continue;
          }
          sample(w);
        }
      if (n % 3 != 0) sample({1.0 / 3, 1.0 / 3, 1.0 / 3});
    }
  }
  // Refine the largest in their triangle (pattern search on the barycentric weights),
  // then re-measure with BRepExtrema_DistShapeShape.
  double m2s_max = 0, fast_minus_exact = 0;
  int m2s_face = -1, exact_checks = 0;
  Vec3 m2s_point;
  {
    const auto largest = m2s.largest();
    // Samples not kept are no farther than the smallest kept one (fast distances are upper
    // bounds), so that bounds the maximum from below whatever the re-measure finds.
    if (!largest.empty()) m2s_max = largest.back().distance;
    for (const auto& entry : largest) {
      MeshSample best = entry.sample;
      double best_d = entry.distance;
      const auto& tri = mesh.triangles[best.triangle];
      double h = 0.5 / opt.samples;
      for (int round = 0; round < 40 && h > 1.0 / (512.0 * opt.samples); ++round) {
        bool moved = false;
        for (int d1 = -1; d1 <= 1; ++d1)
          for (int d2 = -1; d2 <= 1; ++d2) {
            if (d1 == 0 && d2 == 0) continue;
            std::array<double, 3> w = best.w;
            w[1] += d1 * h;
            w[2] += d2 * h;
            w[0] = 1 - w[1] - w[2];
            if (w[0] < 0 || w[1] < 0 || w[2] < 0) continue;
            const Vec3 p = w[0] * mesh.points[tri[0]] + w[1] * mesh.points[tri[1]] + w[2] * mesh.points[tri[2]];
            int face;
            const double d = ref.distance_to_faces(p, face);
            if (d > best_d) {
              best_d = d;
              best.w = w;
              best.point = p;
              moved = true;
            }
          }
        if (!moved) h *= 0.5;
      }
      int fast_face = -1, exact_face = -1;
      const double fast = ref.distance_to_faces(best.point, fast_face);
      const double exact = ref.exact_distance(best.point, fast, exact_face);
      ++exact_checks;
      // Both are distances to points of the faces (upper bounds): the smaller is kept.
      // BRepExtrema misses feet beyond the first period of a periodic face whose domain
      // spans more (the bottle's thread faces: u in [0.12, 12.45]), so it is not trusted
      // over the fast value.
      const double d = std::min(exact, fast);
      if (std::isfinite(exact)) fast_minus_exact = std::max(fast_minus_exact, fast - exact);
      if (d > m2s_max || m2s_face < 0) {
        m2s_max = std::max(m2s_max, d);
        m2s_face = exact < fast ? exact_face : fast_face;
        m2s_point = best.point;
      }
    }
  }
  const double m2s_seconds = seconds_since(m2s_start);

  double area_mesh = 0;
  for (const auto& tri : mesh.triangles)
    area_mesh += 0.5 * norm(cross(mesh.points[tri[1]] - mesh.points[tri[0]], mesh.points[tri[2]] - mesh.points[tri[0]]));
  const double area_occt = ref.area();
  const double area_ratio = area_mesh / area_occt;
  const bool pass = m2s_max <= T && s2m_max <= T && std::abs(area_ratio - 1) <= kAreaRatioLimit;

  const double L = 1 / s, A = L * L;  // back to mesh units
  json += ", \"faces\": " + std::to_string(ref.face_count());
  json += ", \"unit\": " + num(s) + ", \"diagonal\": " + num(D * L) + ", \"tolerance\": " + num(T * L);
  json += opt.absolute > 0 ? ", \"tolerance_relative\": null" : ", \"tolerance_relative\": " + num(opt.relative);
  json += ", \"area_occt\": " + num(area_occt * A) + ", \"area_mesh\": " + num(area_mesh * A) +
          ", \"area_ratio\": " + num(area_ratio);
  json += ", \"mesh_to_surface\": {\"max\": " + num(m2s_max * L) + ", \"max_T\": " + num(m2s_max / T) +
          ", \"mean\": " + num(m2s.mean() * L) + ", \"mean_T\": " + num(m2s.mean() / T) +
          ", \"samples\": " + std::to_string(m2s.count) + ", \"unrefined_max_T\": " + num(m2s.max / T) +
          ", \"exact_checks\": " + std::to_string(exact_checks) +
          ", \"fast_minus_exact_T\": " + num(fast_minus_exact / T) + ", \"worst\": {\"face\": " +
          std::to_string(m2s_face) + ", \"point\": " + json_point(L * m2s_point) + "}}";
  json += ", \"surface_to_mesh\": {\"max\": " + num(s2m_max * L) + ", \"max_T\": " + num(s2m_max / T) +
          ", \"mean\": " + num(s2m.mean() * L) + ", \"mean_T\": " + num(s2m.mean() / T) +
          ", \"samples\": " + std::to_string(s2m.count) + ", \"unrefined_max_T\": " + num(s2m.max / T) +
          ", \"worst\": {\"face\": " + std::to_string(s2m_worst.face) + ", \"edge\": " +
          (s2m_worst.edge >= 0 ? "true" : "false") + ", \"point\": " + json_point(L * s2m_worst.point) + "}}";
  json += ", \"mesh_triangles\": " + std::to_string(mesh.triangles.size()) +
          ", \"mesh_vertices\": " + std::to_string(mesh.points.size()) +
          ", \"open_edges\": " + std::to_string(open_edges(mesh));
  json += ", \"reference\": {\"fine_deflection\": " + num(opt.fine * T * L) +
          ", \"fine_triangles\": " + std::to_string(ref.fine_triangles()) +
          ", \"fine_max_deviation\": " + num(ref.max_deviation() * L) +
          ", \"grid_faces\": " + std::to_string(ref.grid_faces()) +
          ", \"mesh_only_faces\": " + std::to_string(ref.mesh_only_faces()) +
          ", \"unsampled_faces\": " + std::to_string(ref.empty_faces()) +
          ", \"area_from_quadrature\": " + std::to_string(ref.area_replaced()) +
          ", \"area_uncertain\": " + std::to_string(ref.area_uncertain()) + "}";
  if (opt.brute_force)
    json += ", \"brute_force\": {\"max_T\": " + num(brute_max / T) + ", \"fast_over_T\": " + num(brute_over / T) +
            ", \"fast_under_T\": " + num(brute_under / T) + ", \"under_point\": " + json_point(L * brute_under_point) +
            ", \"over_point\": " + json_point(L * brute_over_point) +
            ", \"differ\": " + std::to_string(brute_differ) + "}";
  json += ", \"pass\": " + std::string(pass ? "true" : "false");
  json += ", \"seconds\": {\"read\": " + num(read_seconds) + ", \"fine_mesh\": " + num(ref.fine_seconds) +
          ", \"surface_to_mesh\": " + num(s2m_seconds) + ", \"mesh_to_surface\": " + num(m2s_seconds) +
          ", \"total\": " + num(seconds_since(start)) + "}}";
  std::printf("%s\n", json.c_str());
  return pass ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  std::vector<std::string> positional;
  bool bad = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "-r" && has_value) opt.relative = std::atof(argv[++i]);
    else if (a == "--tolerance" && has_value) opt.absolute = std::atof(argv[++i]);
    else if (a == "--samples" && has_value) opt.samples = std::atoi(argv[++i]);
    else if (a == "--fine" && has_value) opt.fine = std::atof(argv[++i]);
    else if (a == "--brute-force") opt.brute_force = true;
    else if (!a.empty() && a[0] == '-') bad = true;
    else positional.push_back(a);
  }
  if (bad || positional.size() < 2 || !(opt.relative > 0) || opt.absolute < 0 || opt.samples < 1 ||
      opt.samples > 64 || !(opt.fine > 0 && opt.fine <= 1)) {
    std::fprintf(stderr,
                 "usage: %s MODEL MESH [MESH ...] [-r R | --tolerance T] [--samples N] [--fine F] [--brute-force]\n"
                 "  MODEL: .stp .step .igs .iges .brep; MESH: .obj .ply .stl in the model's units\n"
                 "  (several meshes: one JSON line each, measured against one reference)\n"
                 "  T absolute (mesh units), R relative to the tight box diagonal (default 0.001);\n"
                 "  N barycentric subdivisions per triangle side (default %d, 1..64);\n"
                 "  F reference mesh deflection as a share of T (default %g, (0, 1])\n",
                 argv[0], kDefaultSamples, kDefaultFine);
    return 2;
  }
  opt.model = positional[0];
  opt.meshes.assign(positional.begin() + 1, positional.end());
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  try {
    return run(opt);
  } catch (const Standard_Failure& e) {
    std::printf("{\"file\": %s, \"error\": %s}\n", json_string(base_name(opt.model)).c_str(),
                json_string(std::string("OCCT: ") + e.GetMessageString()).c_str());
  } catch (const std::exception& e) {
    std::printf("{\"file\": %s, \"error\": %s}\n", json_string(base_name(opt.model)).c_str(),
                json_string(e.what()).c_str());
  }
  return 2;
}
