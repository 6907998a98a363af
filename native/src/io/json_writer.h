// Minimal JSON output helpers: string escaping and number formatting that
// round-trips doubles. Only writing; trimkit reads no JSON here.
#pragma once

#include <string>

namespace trimkit::io {

// `s` as a quoted JSON string with ", \ and control characters escaped;
// bytes >= 0x80 pass through (the caller supplies UTF-8 or Latin-1 names).
std::string json_string(const std::string& s);

// Shortest text that reads back as the same double; non-finite values as null.
std::string json_number(double x);

}  // namespace trimkit::io
