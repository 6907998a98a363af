// STEP read by trimkit itself, without Open CASCADE: the Part 21 text parsed
// (io/step_part21.h), geometry translated to exact NURBS (io/step_geometry.h), and
// the B-rep topology of AP203/AP214/AP242 (MANIFOLD_SOLID_BREP, BREP_WITH_VOIDS,
// SHELL_BASED_SURFACE_MODEL; CLOSED_SHELL / OPEN_SHELL of ADVANCED_FACEs bounded by
// EDGE_LOOPs of ORIENTED_EDGEs on EDGE_CURVEs) built into a geom::Model: one Model
// edge per EDGE_CURVE, shared by the faces that use it; each face's loops from its
// edges' 3D curves projected onto its surface (io/face_loops.h, as IGES B-rep
// faces). Lengths in millimetres (as read_step through OCCT gives them).
// Assemblies (io/step_assembly.h): each part's solids become bodies once, each
// occurrence a Model::instances entry, named and pathed as read_step_occt does.
// Files this reader does not take on throw UnsupportedStepEntity: product structures
// step_assembly does not read, kinds step_geometry does not translate, units it does
// not understand. The caller then reads the file through OCCT.
#pragma once

#include <string>

#include "geom/model.h"
#include "io/read_monitor.h"

namespace trimkit::io {

// `text`: the whole file; `name` for messages. Throws geom::ReadError for a file that
// is not Part 21 or has no B-rep solid or shell, or an assembly that contains itself
// or places too many parts (step_assembly.h), UnsupportedStepEntity as above,
// ReadStopped from `monitor`.
geom::Model read_step_native(const std::string& text, const std::string& name, ReadMonitor& monitor);

}  // namespace trimkit::io
