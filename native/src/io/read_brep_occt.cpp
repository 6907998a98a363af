// read_brep through Open CASCADE: BRepTools::Read, then the shared shape translation,
// which heals the faces whose wires do not close with ShapeFix_Face. Departure from a
// whole-shape ShapeFix_Shape first: it "fixes" a p-curve that misses its vertices by
// raising the edge's tolerance to the gap, which hides the gap from the face fix
// (tests: OcctModels.GappedAndMissingPcurvesAreHealedByShapeFix).
#include "io/read_brep.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Standard_ErrorHandler.hxx>
#include <TopoDS_Shape.hxx>

#include "geom/error.h"
#include "io/brep_counts.h"
#include "io/brep_input.h"
#include "io/occt_progress.h"
#include "io/occt_shape.h"
#include "io/occt_support.h"
#include "io/read_support.h"

namespace trimkit::io {
namespace {

// Blank lines allowed before the header line (files written by DBRep start with one).
constexpr int kMaxLeadingBlankLines = 16;

// Progress: BRepTools::Read up to this fraction, the translation after it.
constexpr double kReadShare = 0.5;

// std::cout sent to `to` while it lives: OCCT's .brep reader reports damage there
// ("Not a TShape table"), which would land in `trimkit ... --json` output.
class CoutTo {
public:
    explicit CoutTo(std::ostream& to) : saved_(std::cout.rdbuf(to.rdbuf())) {}
    ~CoutTo() { std::cout.rdbuf(saved_); }
    CoutTo(const CoutTo&) = delete;
    CoutTo& operator=(const CoutTo&) = delete;

private:
    std::streambuf* saved_;
};

// What OCCT printed, on one line.
std::string one_line(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\n' || c == '\r') c = ' ';
        if (c != ' ' || (!out.empty() && out.back() != ' ')) out += c;
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

// BRepTools::Read on a BrepInput, after check_brep_counts: a damaged file ends in a
// ReadError with its line, not in OCCT's reader spinning at its end (brep_input.h) or
// allocating what a damaged count asks (brep_counts.h). Returns what OCCT printed.
std::string read_shape(const std::string& path, TopoDS_Shape& shape, const BRep_Builder& builder,
                       const Message_ProgressRange& progress) {
    std::string content = read_file_bytes(path);
    check_brep_counts(content, path);
    BrepInput in(std::move(content));
    std::ostringstream printed;
    const CoutTo redirect(printed);
    try {
        occt_guarded([&] { BRepTools::Read(shape, in, builder, progress); });
    } catch (const BrepInputEnded& e) {
        throw geom::ReadError(path, 0, e.what());
    } catch (const Standard_Failure& e) {
        if (!in.past_end()) throw;
        throw geom::ReadError(path, 0, std::string(BrepInputEnded().what()) + ": " + failure_text(e));
    } catch (const std::ios_base::failure&) {
        throw geom::ReadError(path, in.line(),
                              in.past_end() ? BrepInputEnded().what()
                                             : "Open CASCADE's reader expects a number here (a damaged file?)");
    }
    // A shape read with values from past the end is not the file's.
    if (in.past_end()) throw geom::ReadError(path, 0, BrepInputEnded().what());
    return one_line(printed.str());
}

geom::Model read_brep_unguarded(const std::string& path, const ReadOptions& options) {
    ReadMonitor monitor(path, options);
    monitor.report(0.0);
    {
        std::ifstream probe(path);
        if (!probe) throw geom::ReadError(path, 0, "cannot open the file");
        std::string first;
        int line = 0;
        while (first.find_first_not_of(" \t\r") == std::string::npos && line < kMaxLeadingBlankLines &&
               std::getline(probe, first))
            ++line;
        const size_t start = first.find_first_not_of(" \t\r");
        if (start == std::string::npos || (first.compare(start, 19, "DBRep_DrawableShape") != 0 &&
                                           first.compare(start, 16, "CASCADE Topology") != 0))
            throw geom::ReadError(path, line, "not an Open CASCADE .brep file (expected 'DBRep_DrawableShape' "
                                              "or 'CASCADE Topology V1/V2')");
    }
    TopoDS_Shape shape;
    BRep_Builder builder;
    monitor.stage(0.0, kReadShare);
    Handle(OcctProgress) progress = new OcctProgress(monitor);
    // Its own signal-catching scope (occt_guarded): after a fault, the shape, the
    // progress indicator and the monitor are destroyed as after any exception.
    const std::string printed = read_shape(path, shape, builder, progress->Start());
    monitor.check();
    if (shape.IsNull())
        throw geom::ReadError(path, 0, "Open CASCADE cannot read this .brep file (BRepTools::Read failed" +
                                           (printed.empty() ? std::string() : ": " + printed) + ")");
    geom::Model model;
    if (!printed.empty()) model.warnings.push_back("Open CASCADE's reader: " + printed);
    model.units = "mm";
    model.scale_to_metres = 1e-3;
    int face_number = 0;
    const std::string stem = std::filesystem::path(path).stem().string();
    monitor.stage(kReadShare, 1.0);
    add_shape(model, shape, ShapeStyle{}, stem, face_number, &monitor);
    monitor.report(1.0);
    if (model.faces.empty())
        throw geom::ReadError(path, 0, face_number == 0 ? std::string("the .brep file has no faces")
                                                        : "no face of the .brep file converts (" +
                                                              model.warnings.back() + ")");
    return model;
}

}  // namespace

geom::Model read_brep(const std::string& path, const ReadOptions& options) {
    silence_occt_stdout();
    try {
        OcctSignalGuard guard;
        OCC_CATCH_SIGNALS
        return read_brep_unguarded(path, options);
    } catch (const Standard_Failure& e) {
        throw geom::ReadError(path, 0, "Open CASCADE failed (a damaged file?): " + failure_text(e));
    }
}

}  // namespace trimkit::io
