#include "mesh/deadline.h"

#include <gtest/gtest.h>

#include <limits>
#include <thread>

namespace trimkit::mesh {
namespace {

TEST(Deadline, DefaultZeroAndInfiniteNeverExpire) {
    for (Deadline d : {Deadline(), Deadline(0.0), Deadline(-1.0), Deadline(std::numeric_limits<double>::infinity())}) {
        EXPECT_FALSE(d.limited());
        EXPECT_FALSE(d.expired());
        for (unsigned i = 0; i < 4 * Deadline::kCheckStride; ++i) d.check("loop");
        d.check_now("loop");
    }
}

TEST(Deadline, CheckThrowsNamingTheStageOnceItHasPassed) {
    Deadline d(1e-3);
    EXPECT_TRUE(d.limited());
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    EXPECT_TRUE(d.expired());
    try {
        d.check_now("trim loop repair");
        FAIL() << "no throw";
    } catch (const DeadlineExceeded& e) {
        EXPECT_EQ(e.stage(), "trim loop repair");
        EXPECT_GE(e.elapsed(), 1e-3);
        EXPECT_EQ(e.limit(), 1e-3);
        EXPECT_NE(std::string(e.what()).find("in trim loop repair (limit 0.001 s)"), std::string::npos) << e.what();
    }
    // check() reads the clock once per stride: it throws within one stride of calls.
    unsigned calls = 0;
    EXPECT_THROW(
        {
            for (; calls <= Deadline::kCheckStride; ++calls) d.check("kd subdivision");
        },
        DeadlineExceeded);
    EXPECT_LE(calls, Deadline::kCheckStride);
}

}  // namespace
}  // namespace trimkit::mesh
