// The product structure of a STEP file (AP203 / AP214 / AP242, ISO 10303-41/-43/-44
// product and representation schemas, as the CAx-IF "Recommended Practices for STEP
// assembly structure" use it): which B-rep solids each part definition holds and where
// each occurrence of a part sits in the assembly tree. Conventions: transforms map a
// part's own coordinates to the root's, in the file's length units (the caller scales);
// occurrences come root first, components in file order; names as read_step_occt gives
// them (an occurrence: its NEXT_ASSEMBLY_USAGE_OCCURRENCE's name, else its id; an
// assembly at the root: its PRODUCT's name, else its id).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "geom/model.h"
#include "io/step_geometry.h"
#include "io/step_part21.h"

namespace trimkit::io {

// Assembly nesting followed at most (as read_step_occt; deeper means a hostile file).
constexpr int kMaxStepAssemblyDepth = 64;
// Assembly links (and placed solids) one file may make. Depth alone does not bound
// them: assemblies that each hold the one below twice make 2^depth occurrences.
constexpr std::size_t kMaxStepOccurrences = 200'000;

// One placed solid: a MANIFOLD_SOLID_BREP, BREP_WITH_VOIDS or SHELL_BASED_SURFACE_MODEL
// instance and where one occurrence of its part puts it.
struct StepOccurrence {
    long long solid = 0;                                        // the solid's instance name (#id)
    Eigen::Affine3d transform = Eigen::Affine3d::Identity();  // solid's coordinates -> root's
    std::string name;                                          // the occurrence's name
    std::vector<std::string> path;                             // assemblies from the root down
    std::string part;                                          // the part's PRODUCT name
};

// Whether the file places parts: it has a NEXT_ASSEMBLY_USAGE_OCCURRENCE, MAPPED_ITEM
// or ITEM_DEFINED_TRANSFORMATION. Files without them are read solid by solid.
bool step_has_assembly(const StepPart21& file);

// Every placed solid of the file, walked from each root PRODUCT_DEFINITION (one that is
// no component): PRODUCT_DEFINITION_SHAPE + SHAPE_DEFINITION_REPRESENTATION give its
// shape representations, SHAPE_REPRESENTATION_RELATIONSHIPs without transformation the
// representations holding its B-rep items, MAPPED_ITEMs sub-representations placed, and
// each NEXT_ASSEMBLY_USAGE_OCCURRENCE a component placed by its
// CONTEXT_DEPENDENT_SHAPE_REPRESENTATION. Throws geom::ReadError (file, line) for an
// assembly that contains itself, nests deeper than kMaxStepAssemblyDepth or makes more
// than kMaxStepOccurrences; UnsupportedStepEntity for anything this walk does not read
// (a transformation operator, a representation item of another kind, a solid outside
// the product structure), so that OCCT reads the file instead of a wrong model here.
std::vector<StepOccurrence> step_occurrences(const StepPart21& file, const StepGeometry& geometry);

// Model::instances for the occurrences, `bodies`: the Model::bodies index of each solid
// read (by its instance name; several for a SHELL_BASED_SURFACE_MODEL). A body without
// a name (or "NONE") takes its part's. No instances when they would only repeat the
// bodies (each body once, unmoved), as read_step_occt. Throws geom::ReadError naming
// `file_name` beyond kMaxStepOccurrences instances.
void place_step_occurrences(const std::vector<StepOccurrence>& occurrences,
                            const std::multimap<long long, int>& bodies, geom::Model& model,
                            const std::string& file_name);

}  // namespace trimkit::io
