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

// Recursion without bound, as OCCT 7.6's STEP transfer does on some damaged assemblies
// (tests/fuzz/regressions/step/assembly_recursion_with_components.stp: exit 139 before).
// The frame keeps a buffer the compiler cannot drop, so the recursion is not a loop.
volatile int never = -1;  // a depth the recursion never reaches, unknown to the compiler

int recurse_forever(int depth) {
    if (depth == never) return 0;
    volatile char frame[512];
    frame[depth % sizeof frame] = static_cast<char>(depth);
    return recurse_forever(depth + 1) + frame[(depth + 1) % sizeof frame];
}

#if defined(__SANITIZE_ADDRESS__)
#define TRIMKIT_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TRIMKIT_UNDER_ASAN 1
#endif
#endif

TEST(OcctGuarded, StackOverflowInsideIsThrownAndTheProcessGoesOn) {
#if defined(TRIMKIT_UNDER_ASAN)
    GTEST_SKIP() << "AddressSanitizer reports the overflow itself";
#endif
    for (int round = 0; round < 2; ++round) {  // the handler is usable again afterwards
        OcctSignalGuard guard;
        bool caught = false;
        try {
            occt_guarded([] { return recurse_forever(0); });
        } catch (const Standard_Failure&) {
            caught = true;
        }
        EXPECT_TRUE(caught) << "round " << round;
    }
    stack_t now{};
    ASSERT_EQ(sigaltstack(nullptr, &now), 0);
    EXPECT_TRUE(now.ss_flags & SS_DISABLE) << "the guard's signal stack outlived it";
}

}  // namespace
}  // namespace trimkit::io
