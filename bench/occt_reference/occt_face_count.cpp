// occt_face_count: reads IGES/STEP files with Open CASCADE's default settings and prints
// what a user of OCCT gets. Faces are counted three ways: per occurrence (an instanced
// subfigure counts once per placement), unique (TopTools_IndexedMapOfShape: same TShape and
// same Location) and distinct TShapes (geometry shared by instances counts once).
// Also: shells and solids per occurrence, time for ReadFile + TransferRoots, transfer status
// and the number of fails/warnings OCCT recorded while loading and transferring.
// Usage: occt_face_count FILE...   (.igs/.iges -> IGESControl_Reader, .stp/.step -> STEP)
// Exit status: 0 if every file transferred to a non-null shape, 1 otherwise, 2 on usage.

#include <IGESControl_Reader.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <Standard_Version.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <unordered_set>

namespace {

// Sub-shapes of `type` in `shape`, counted once per occurrence (placement).
int count_occurrences(const TopoDS_Shape& shape, TopAbs_ShapeEnum type) {
  int n = 0;
  for (TopExp_Explorer it(shape, type); it.More(); it.Next()) ++n;
  return n;
}

// Sub-shapes of `type` in `shape`, counted once per distinct TShape + location.
int count_unique(const TopoDS_Shape& shape, TopAbs_ShapeEnum type) {
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, type, map);
  return map.Extent();
}

// Sub-shapes of `type` in `shape` with distinct TShapes, whatever their location.
int count_tshapes(const TopoDS_Shape& shape, TopAbs_ShapeEnum type) {
  std::unordered_set<const TopoDS_TShape*> seen;
  for (TopExp_Explorer it(shape, type); it.More(); it.Next())
    seen.insert(it.Current().TShape().get());
  return static_cast<int>(seen.size());
}

// "F/W": total fails and warnings in a check list.
std::string check_summary(const Interface_CheckIterator& checks) {
  int fails = 0, warnings = 0;
  for (checks.Start(); checks.More(); checks.Next()) {
    fails += checks.Value()->NbFails();
    warnings += checks.Value()->NbWarnings();
  }
  return std::to_string(fails) + "/" + std::to_string(warnings);
}

const char* status_name(IFSelect_ReturnStatus s) {
  switch (s) {
    case IFSelect_RetVoid: return "void";
    case IFSelect_RetDone: return "done";
    case IFSelect_RetError: return "error";
    case IFSelect_RetFail: return "fail";
    case IFSelect_RetStop: return "stop";
  }
  return "?";
}

std::string lower_extension(const std::string& path) {
  std::string ext = path.substr(path.find_last_of('.') + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string base_name(const std::string& path) {
  return path.substr(path.find_last_of('/') + 1);
}

// The reader parameters that shape IGES/STEP results; printed so the table says what
// "default settings" meant for this OCCT build. Valid once a reader has been constructed.
void print_settings() {
  for (const char* name : {"read.iges.bspline.continuity", "read.iges.onlyvisible",
                           "read.precision.mode", "read.maxprecision.mode",
                           "read.surfacecurve.mode", "read.step.product.mode",
                           "read.step.shape.repr", "read.step.assembly.level"})
    std::printf("# %s = %d\n", name, Interface_Static::IVal(name));
  for (const char* name : {"read.precision.val", "read.maxprecision.val",
                           "read.encoderegularity.angle"})
    std::printf("# %s = %g\n", name, Interface_Static::RVal(name));
}

// One result line for `path`; returns true if a non-null shape came out.
bool report(const std::string& path) {
  const std::string ext = lower_extension(path);
  std::unique_ptr<XSControl_Reader> reader;
  if (ext == "igs" || ext == "iges") reader = std::make_unique<IGESControl_Reader>();
  else if (ext == "stp" || ext == "step") reader = std::make_unique<STEPControl_Reader>();
  else {
    std::printf("%-34s unknown extension '.%s'\n", base_name(path).c_str(), ext.c_str());
    return false;
  }

  using Clock = std::chrono::steady_clock;
  std::string status;
  TopoDS_Shape shape;
  const auto start = Clock::now();
  auto stop = start;
  try {
    const IFSelect_ReturnStatus read = reader->ReadFile(path.c_str());
    const int roots = read == IFSelect_RetDone ? reader->NbRootsForTransfer() : 0;
    const int done = read == IFSelect_RetDone ? reader->TransferRoots() : 0;
    stop = Clock::now();
    if (read != IFSelect_RetDone) {
      status = std::string("read ") + status_name(read);
    } else {
      shape = reader->OneShape();
      const auto& transfer = reader->WS()->TransferReader()->TransientProcess();
      status = "roots " + std::to_string(done) + "/" + std::to_string(roots) +
               ", load F/W " + check_summary(reader->WS()->ModelCheckList()) +
               ", transfer F/W " + check_summary(transfer->CheckList(false));
      if (shape.IsNull()) status += ", null shape";
    }
  } catch (const Standard_Failure& e) {
    stop = Clock::now();
    status = std::string("exception: ") + e.GetMessageString();
  }
  const double ms = std::chrono::duration<double, std::milli>(stop - start).count();

  std::printf("%-34s %6d %6d %7d %6d %6d %8.1f  %s\n", base_name(path).c_str(),
              count_occurrences(shape, TopAbs_FACE), count_unique(shape, TopAbs_FACE),
              count_tshapes(shape, TopAbs_FACE),
              count_occurrences(shape, TopAbs_SHELL), count_occurrences(shape, TopAbs_SOLID),
              ms, status.c_str());
  std::fflush(stdout);
  return !shape.IsNull();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE.igs|FILE.stp...\n", argv[0]);
    return 2;
  }
  // OCCT's transfer messages go to stdout by default; keep stdout for the table.
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));

  { IGESControl_Reader iges; STEPControl_Reader step; }  // registers the read.* parameters
  std::printf("# OCCT %s, default reader settings\n", OCC_VERSION_COMPLETE);
  print_settings();
  std::printf("%-34s %6s %6s %7s %6s %6s %8s  %s\n", "# file", "faces", "unique", "tshapes",
              "shells", "solids", "ms", "status");

  bool all_ok = true;
  for (int i = 1; i < argc; ++i) all_ok = report(argv[i]) && all_ok;
  return all_ok ? 0 : 1;
}
