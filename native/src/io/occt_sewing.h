// Sewing a part whose faces do not share their edges (compiled only with
// TRIMKIT_WITH_OCCT). Some writers give every face of a shell edges and vertices of
// its own (Spatial's SHELL_BASED_SURFACE_MODEL of FACE_SURFACEs); OCCT's transfer
// then heals the shell into one shell per face, and the faces' meshes meet only by
// position, each part a body of its own. OCCT's BRepBuilderAPI_Sewing (the
// maintained tool for this) gives them shared edges again, so the faces are meshed
// along one polyline per edge and a closed shell is a closed body.
#pragma once

#include <TopTools_DataMapOfShapeShape.hxx>
#include <TopoDS_Shape.hxx>

namespace trimkit::io {

struct SewnShape {
    TopoDS_Shape shape;                    // the part, sewn or as it was
    TopTools_DataMapOfShapeShape original;  // sewn face -> the part's face it replaces
    int free_edges_before = 0;             // edges one face bounds (not degenerate, not seams)
    int free_edges_after = 0;
    bool sewn = false;
};

// Edges of `shape` that bound one face once (not degenerate, not a seam).
int count_free_edges(const TopoDS_Shape& shape);

// `part` sewn when it has no solid, at least two faces and free edges; the sewing
// tolerance is twice the part's largest vertex tolerance (the writer's own precision),
// at least 1e-7 and at most 1e-4 of the part's size. Otherwise, or when OCCT fails
// while sewing, `part` itself.
SewnShape sew_loose_faces(const TopoDS_Shape& part);

// The part's face that `face` (a face of SewnShape::shape) stands for.
const TopoDS_Shape& original_face(const SewnShape& sewn, const TopoDS_Shape& face);

}  // namespace trimkit::io
