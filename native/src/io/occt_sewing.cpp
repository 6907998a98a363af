#include "io/occt_sewing.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS.hxx>

#include "io/occt_support.h"

namespace trimkit::io {
namespace {

constexpr double kMinSewingTolerance = 1e-7;
constexpr double kMaxSewingShare = 1e-4;

bool has_solid(const TopoDS_Shape& shape) { return TopExp_Explorer(shape, TopAbs_SOLID).More(); }

int face_count(const TopoDS_Shape& shape) {
    int n = 0;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More() && n < 2; it.Next()) ++n;
    return n;
}

double sewing_tolerance(const TopoDS_Shape& part) {
    double largest = 0.0;
    for (TopExp_Explorer it(part, TopAbs_VERTEX); it.More(); it.Next())
        largest = std::max(largest, BRep_Tool::Tolerance(TopoDS::Vertex(it.Current())));
    Bnd_Box box;
    BRepBndLib::Add(part, box);
    const double size = box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
    return std::clamp(2.0 * largest, kMinSewingTolerance, std::max(kMinSewingTolerance, kMaxSewingShare * size));
}

}  // namespace

int count_free_edges(const TopoDS_Shape& shape) {
    TopTools_IndexedDataMapOfShapeListOfShape faces_of;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, faces_of);
    int free = 0;
    for (int i = 1; i <= faces_of.Extent(); ++i) {
        const TopoDS_Edge& edge = TopoDS::Edge(faces_of.FindKey(i));
        const TopTools_ListOfShape& faces = faces_of.FindFromIndex(i);
        // A seam is listed once for its face but bounds it twice.
        if (faces.Extent() == 1 && !BRep_Tool::Degenerated(edge) &&
            !BRep_Tool::IsClosed(edge, TopoDS::Face(faces.First())))
            ++free;
    }
    return free;
}

SewnShape sew_loose_faces(const TopoDS_Shape& part) {
    SewnShape out;
    out.shape = part;
    if (has_solid(part) || face_count(part) < 2) return out;
    out.free_edges_before = out.free_edges_after = count_free_edges(part);
    if (out.free_edges_before == 0) return out;
    BRepBuilderAPI_Sewing sewing(sewing_tolerance(part));
    TopoDS_Shape sewn;
    try {
        sewn = occt_guarded([&] {
            sewing.Add(part);
            sewing.Perform();
            return sewing.SewedShape();
        });
    } catch (const Standard_Failure&) {
        return out;  // the part as it was: its faces meet by position only
    }
    if (sewn.IsNull()) return out;
    const int after = count_free_edges(sewn);
    if (after >= out.free_edges_before) return out;
    for (TopExp_Explorer it(part, TopAbs_FACE); it.More(); it.Next())
        if (sewing.IsModifiedSubShape(it.Current()))
            out.original.Bind(sewing.ModifiedSubShape(it.Current()), it.Current());
    out.shape = sewn;
    out.free_edges_after = after;
    out.sewn = true;
    return out;
}

const TopoDS_Shape& original_face(const SewnShape& sewn, const TopoDS_Shape& face) {
    const TopoDS_Shape* found = sewn.original.Seek(face);
    return found ? *found : face;
}

}  // namespace trimkit::io
