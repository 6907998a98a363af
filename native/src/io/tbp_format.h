// The .tbp file format: a TBP solid as JSON,
//   {"tbp": 1, "degree": n, "patches": [[[x,y,z], ...], ...], "name": "optional"}
// each patch (n+1)(n+2)/2 control points b_ijk ordered with i from n down to 0
// and, within, j from n-i down to 0 (geom/bezier_triangle.h). Unknown members
// are ignored. Errors are geom::ReadError "FILE:LINE: what is wrong".
#pragma once

#include <string>

#include "tbp/tbp_solid.h"

namespace trimkit::io {

// .tbp files larger than this are refused before parsing (a million cubic
// patches in JSON take about 300 MiB).
constexpr std::size_t kMaxTbpFileBytes = std::size_t(512) << 20;

// Parses .tbp text; `file` names it in errors. Throws geom::ReadError for
// malformed JSON, a missing or wrong "tbp" version, a degree outside [1, 20],
// a patch with the wrong number of points, a point that is not three finite
// numbers, or no patches.
tbp::TbpSolid parse_tbp(const std::string& text, const std::string& file);

// Reads a .tbp file (ReadError if it cannot be read or is larger than kMaxTbpFileBytes).
tbp::TbpSolid read_tbp(const std::string& path);

// The .tbp text of `solid` (numbers round-trip exactly), one patch per line.
std::string tbp_text(const tbp::TbpSolid& solid);

// Writes `solid` to `path`; throws std::runtime_error if the file cannot be written.
void write_tbp(const tbp::TbpSolid& solid, const std::string& path);

}  // namespace trimkit::io
