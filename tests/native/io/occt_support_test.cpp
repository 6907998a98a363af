// occt_guarded (io/occt_support.h): a memory fault inside OCCT becomes a Standard_Failure
// thrown from the innermost scope, and the caller's frames unwind normally (their
// destructors run), which is what lets read_step close its document after a fault in
// the parse or the transfer (issue 13). Built only with OCCT (tests/native/CMakeLists.txt).
#include <csignal>

#include <gtest/gtest.h>

#include "io/occt_support.h"

namespace trimkit::io {
namespace {

struct CountsDestruction {
    int* destroyed;
    ~CountsDestruction() { ++*destroyed; }
};

TEST(OcctGuarded, FaultInsideIsThrownAsStandardFailureAndTheCallerUnwinds) {
    OcctSignalGuard guard;
    int destroyed = 0;
    bool caught = false;
    try {
        CountsDestruction outer{&destroyed};
        occt_guarded([] { std::raise(SIGSEGV); });
        ADD_FAILURE() << "the fault did not leave the scope";
    } catch (const Standard_Failure& e) {
        caught = true;
        EXPECT_FALSE(failure_text(e).empty());
    }
    EXPECT_TRUE(caught);
    EXPECT_EQ(destroyed, 1) << "the caller's object was skipped by the jump";
}

TEST(OcctGuarded, InnermostScopeCatchesAndTheOuterOneStaysUsable) {
    OcctSignalGuard guard;
    int destroyed = 0;
    const int result = occt_guarded([&] {
        try {
            CountsDestruction middle{&destroyed};
            occt_guarded([] { std::raise(SIGSEGV); });
        } catch (const Standard_Failure&) {
            return 1;
        }
        return 0;
    });
    EXPECT_EQ(result, 1);
    EXPECT_EQ(destroyed, 1);
    EXPECT_EQ(occt_guarded([] { return 42; }), 42);  // no fault: the value passes through
}

}  // namespace
}  // namespace trimkit::io
