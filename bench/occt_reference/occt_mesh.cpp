// occt_mesh: meshes IGES/STEP/.brep files with Open CASCADE's BRepMesh_IncrementalMesh, as
// a reference for `trimkit mesh --relative`. Per file: read with default reader settings
// (.brep: BRepTools::Read, then BRepTools::Clean so that triangulations stored in the file
// are not reused), D = diagonal of the tight bounding box (BRepBndLib::AddOptimal, no
// triangulation, no shape tolerances), then BRepMesh_IncrementalMesh(shape, r·D or T,
// absolute, 0.5 rad, parallel unless --threads 1).
// Prints one JSON object per file and line. Counts are per face occurrence (an instanced
// face counts once per placement); a face is failed when it has no triangles afterwards.
// read_seconds: wall time of the read and transfer; mesh_seconds: wall time of the mesher
// alone; mesh_cpu_seconds: CPU time of all threads.
// max_deflection: the largest Poly_Triangulation::Deflection(), which OCCT 7.6 sets by
// BRepLib::UpdateDeflection (distance of triangle centroids and inner edge midpoints to
// the surface at their interpolated (u,v)): OCCT's own estimate, not a true deviation.
// Usage: occt_mesh [-r R | --tolerance T] [--threads 1] [--obj OUT.obj] FILE...
//   R default 0.001; T: an absolute deflection in OCCT's units (mm); --threads 1: the
//   mesher's InParallel off; --obj (one FILE) writes the triangles in model space, per
//   face vertices not welded, each face's triangles after `g face_N` (N from 0 in
//   TopExp_Explorer order), reversed faces flipped.
// Exit status: 0 if every file meshed without failed faces, 1 otherwise, 2 on usage.

#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IGESControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

// A triangle is zero-area when twice its area is below this share of D²: the rounding
// of a cross product of coordinates of size D is ~1e-16·D², and no real triangle of a
// mesh at r >= 1e-4 comes near 1e-14·D².
constexpr double kZeroAreaRelative = 1e-14;
// OCCT's default angular deflection (radians), as in BRepMesh_IncrementalMesh's signature.
constexpr double kAngularDeflection = 0.5;

struct MeshStats {
  int faces = 0, faces_failed = 0, zero_area = 0;
  long triangles = 0, nodes = 0;
  double max_deflection = 0.0;
};

std::string lower_extension(const std::string& path) {
  std::string ext = path.substr(path.find_last_of('.') + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string base_name(const std::string& path) {
  return path.substr(path.find_last_of('/') + 1);
}

// `text` as a JSON string literal (file names and OCCT messages: quotes, backslashes,
// control characters).
std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
    else out += ' ';
  }
  return out + "\"";
}

// The shape of an IGES/STEP/.brep file with default reader settings; throws on failure.
TopoDS_Shape read_shape(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == "brep") {
    TopoDS_Shape shape;
    BRep_Builder builder;
    if (!BRepTools::Read(shape, path.c_str(), builder)) throw std::runtime_error("BRepTools::Read failed");
    if (shape.IsNull()) throw std::runtime_error("null shape");
    BRepTools::Clean(shape);
    return shape;
  }
  std::unique_ptr<XSControl_Reader> reader;
  if (ext == "igs" || ext == "iges") reader = std::make_unique<IGESControl_Reader>();
  else if (ext == "stp" || ext == "step") reader = std::make_unique<STEPControl_Reader>();
  else throw std::runtime_error("unknown extension '." + ext + "'");
  if (reader->ReadFile(path.c_str()) != IFSelect_RetDone) throw std::runtime_error("read failed");
  reader->TransferRoots();
  TopoDS_Shape shape = reader->OneShape();
  if (shape.IsNull()) throw std::runtime_error("null shape");
  return shape;
}

// Diagonal of `box` including its gap (0 for a void box).
double diagonal(const Bnd_Box& box) { return std::sqrt(box.SquareExtent()); }

// Counts the triangulation of every face occurrence of `shape` (D: bounding-box diagonal,
// for zero-area triangles); appends it to `obj` when not null.
MeshStats count_mesh(const TopoDS_Shape& shape, double D, std::FILE* obj) {
  MeshStats s;
  long obj_vertices = 0;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next(), ++s.faces) {
    const TopoDS_Face& face = TopoDS::Face(it.Current());
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(face, loc);
    if (mesh.IsNull() || mesh->NbTriangles() == 0) {
      ++s.faces_failed;
      continue;
    }
    s.triangles += mesh->NbTriangles();
    s.nodes += mesh->NbNodes();
    s.max_deflection = std::max(s.max_deflection, mesh->Deflection());
    const gp_Trsf& placement = loc.Transformation();
    std::vector<gp_Pnt> p(mesh->NbNodes() + 1);
    for (int i = 1; i <= mesh->NbNodes(); ++i) p[i] = mesh->Node(i).Transformed(placement);
    if (obj) {
      std::fprintf(obj, "g face_%d\n", s.faces);
      for (int i = 1; i <= mesh->NbNodes(); ++i)
        std::fprintf(obj, "v %.17g %.17g %.17g\n", p[i].X(), p[i].Y(), p[i].Z());
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int t = 1; t <= mesh->NbTriangles(); ++t) {
      int a, b, c;
      mesh->Triangle(t).Get(a, b, c);
      if (reversed) std::swap(b, c);
      const gp_Vec cross = gp_Vec(p[a], p[b]).Crossed(gp_Vec(p[a], p[c]));
      if (cross.Magnitude() <= kZeroAreaRelative * D * D) ++s.zero_area;
      if (obj) std::fprintf(obj, "f %ld %ld %ld\n", obj_vertices + a, obj_vertices + b, obj_vertices + c);
    }
    obj_vertices += mesh->NbNodes();
  }
  return s;
}

// Reads, meshes and prints one JSON line for `path` (deflection T if T > 0, else r·D);
// true if every face got triangles.
bool report(const std::string& path, double r, double T, bool parallel, const char* obj_path) {
  std::string json = "{\"file\": " + json_string(base_name(path));
  char buffer[1024];
  if (T > 0) std::snprintf(buffer, sizeof buffer, ", \"tolerance_relative\": null");
  else std::snprintf(buffer, sizeof buffer, ", \"tolerance_relative\": %g", r);
  json += buffer;
  bool ok = false;
  try {
    const auto read_start = std::chrono::steady_clock::now();
    const TopoDS_Shape shape = read_shape(path);
    const double read_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - read_start).count();
    Bnd_Box tight, loose;
    BRepBndLib::AddOptimal(shape, tight, Standard_False, Standard_False);
    BRepBndLib::Add(shape, loose, Standard_False);
    const double D = diagonal(tight);
    const double deflection = T > 0 ? T : r * D;

    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    const BRepMesh_IncrementalMesh mesher(shape, deflection, Standard_False, kAngularDeflection,
                                          parallel ? Standard_True : Standard_False);
    const double cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::FILE* obj = obj_path ? std::fopen(obj_path, "w") : nullptr;
    if (obj_path && !obj) throw std::runtime_error(std::string("cannot write ") + obj_path);
    if (obj) std::fprintf(obj, "# occt_mesh %s r=%g tolerance=%.17g\n", base_name(path).c_str(), r, deflection);
    const MeshStats s = count_mesh(shape, D, obj);
    if (obj) std::fclose(obj);
    std::snprintf(buffer, sizeof buffer,
                  ", \"tolerance\": %.6g, \"diagonal\": %.9g, \"diagonal_add\": %.9g, "
                  "\"faces\": %d, \"faces_failed\": %d, \"triangles\": %ld, \"nodes\": %ld, "
                  "\"zero_area_triangles\": %d, \"max_deflection\": %.6g, \"status_flags\": %d, "
                  "\"read_seconds\": %.4f, \"mesh_seconds\": %.4f, \"mesh_cpu_seconds\": %.4f, "
                  "\"parallel\": %s}",
                  deflection, D, diagonal(loose), s.faces, s.faces_failed, s.triangles, s.nodes,
                  s.zero_area, s.max_deflection, mesher.GetStatusFlags(), read_seconds, seconds, cpu_seconds,
                  parallel ? "true" : "false");
    json += buffer;
    ok = s.faces_failed == 0;
  } catch (const Standard_Failure& e) {
    json += ", \"error\": " + json_string(std::string("OCCT: ") + e.GetMessageString()) + "}";
  } catch (const std::exception& e) {
    json += ", \"error\": " + json_string(e.what()) + "}";
  }
  std::printf("%s\n", json.c_str());
  std::fflush(stdout);
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  double r = 0.001, T = 0;
  bool parallel = true;
  const char* obj = nullptr;
  int first = 1;
  bool bad = false;
  for (; first + 1 < argc && argv[first][0] == '-'; first += 2) {
    if (std::strcmp(argv[first], "-r") == 0) r = std::atof(argv[first + 1]);
    else if (std::strcmp(argv[first], "--tolerance") == 0) T = std::atof(argv[first + 1]);
    else if (std::strcmp(argv[first], "--threads") == 0) parallel = std::atoi(argv[first + 1]) != 1;
    else if (std::strcmp(argv[first], "--obj") == 0) obj = argv[first + 1];
    else {
      bad = true;
      break;
    }
  }
  if (bad || first >= argc || !(r > 0.0) || T < 0 || (obj && argc - first != 1) || argv[first][0] == '-') {
    std::fprintf(stderr,
                 "usage: %s [-r R | --tolerance T] [--threads 1] [--obj OUT.obj] FILE...  "
                 "(R, T > 0; --obj: one FILE)\n",
                 argv[0]);
    return 2;
  }
  // OCCT's reader messages go to stdout by default; keep stdout for the JSON lines.
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));

  bool all_ok = true;
  for (int i = first; i < argc; ++i) all_ok = report(argv[i], r, T, parallel, obj) && all_ok;
  return all_ok ? 0 : 1;
}
