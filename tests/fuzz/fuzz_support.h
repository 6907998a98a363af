// Shared pieces of the libFuzzer harnesses (tests/fuzz/fuzz_*.cpp). Each harness
// feeds one input to one reader (and the first steps after it) and accepts only
// the errors that mean "bad input": geom::ReadError and geom::InvalidInput, which
// the CLI reports as `trimkit: FILE:LINE: reason`, exit 2. Anything else escaping
// (NumericalFailure, std::runtime_error, a bad_alloc) is what the CLI would call an
// internal error, so it aborts and libFuzzer records the input as a crash.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

#include "geom/error.h"

namespace trimkit::fuzz {

// The input name every harness passes to the readers (it appears in their messages).
inline const std::string kInputName = "fuzz-input";

inline std::string input_text(const std::uint8_t* data, std::size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

// The input written to this process's scratch file `name` (for readers that only read
// files, as OCCT's do): in $TMPDIR (tests/fuzz/run points it at /dev/shm), else /tmp.
inline std::string scratch_file(const std::uint8_t* data, std::size_t size, const std::string& name) {
    static const std::string prefix = [] {
        const char* dir = std::getenv("TMPDIR");
        return std::string(dir && *dir ? dir : "/tmp") + "/trimkit-fuzz-" + std::to_string(getpid()) + "-";
    }();
    const std::string path = prefix + name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) std::abort();  // the harness's own failure, not the input's
    return path;
}

// Runs `f`; returns normally when it ends or throws a bad-input error.
template <class F>
void expect_bad_input_at_most(F&& f) {
    try {
        f();
    } catch (const geom::ReadError&) {
    } catch (const geom::InvalidInput&) {
    }
}

}  // namespace trimkit::fuzz
