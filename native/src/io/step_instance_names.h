// Instance names of a STEP file (ISO 10303-21: "#N = ..."), checked before Open
// CASCADE parses it. Part 21 requires each name to be defined once; OCCT 7.6 reads a
// file that defines one twice and its transfer can then recurse without end (fuzz
// finding 9, tests/fuzz/regressions/step/assembly_recursion_with_components.stp:
// #44, #46 and #59 twice; with a 4 GB stack the recursion took 21.7 s and 5.7 GB, the
// same file with the duplicates left out reads at once). Caught only as a stack
// overflow, whose jump out of OCCT can leave a lock of malloc taken: the process
// then hangs instead (one replay in several hundred).
#pragma once

#include <istream>
#include <string>

namespace trimkit::io {

// Throws geom::ReadError naming `path` and the line of the second definition when an
// instance name is defined twice ("entity #44 is defined twice (first on line 44)").
// Names are read where a line starts with one ("#12 = ..."), as every writer puts its
// entities; other text is left to OCCT's parser.
void check_step_instance_names(std::istream& in, const std::string& path);

}  // namespace trimkit::io
