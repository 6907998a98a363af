// CancelFlag: the `_trimkit.CancelFlag` object Python sets (from any thread, or from a
// progress callback) to stop a read or a tessellation at its next check; the native
// side sees the atomic. Bound once, in bind_io.cpp.
#pragma once

#include <atomic>

namespace trimkit::bindings {

struct CancelFlag {
    std::atomic<bool> value{false};
};

}  // namespace trimkit::bindings
