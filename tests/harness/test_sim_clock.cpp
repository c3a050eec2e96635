// SimClock: integer nanosecond time, mirrored into __CURRENT_TIME with tv_nsec in [0, 1e9).
#include <chrono>
#include <stdexcept>

#include <gtest/gtest.h>

#include "pac/iec_time.hpp"
#include "pac/sim_clock.hpp"

using namespace std::chrono_literals;

namespace {

void ExpectCurrentTime(long sec, long nsec) {
    EXPECT_EQ(__CURRENT_TIME.tv_sec, sec);
    EXPECT_EQ(__CURRENT_TIME.tv_nsec, nsec);
}

TEST(SimClock, StartsAtZeroAndResetsTheGlobal) {
    __CURRENT_TIME = pac::ToIecTime(5s + 7ns);  // left over from an earlier test
    pac::SimClock clock;
    EXPECT_EQ(clock.Now(), 0ns);
    ExpectCurrentTime(0, 0);
}

TEST(SimClock, AdvanceAccumulatesAndPublishes) {
    pac::SimClock clock;
    clock.Advance(1500ms);
    EXPECT_EQ(clock.Now(), 1500ms);
    ExpectCurrentTime(1, 500'000'000);
    clock.Advance(250us);
    EXPECT_EQ(clock.Now(), 1'500'250'000ns);
    ExpectCurrentTime(1, 500'250'000);
}

TEST(SimClock, CarriesNanosecondsIntoSecondsExactly) {
    pac::SimClock clock;
    clock.Advance(999'999'999ns);
    ExpectCurrentTime(0, 999'999'999);
    clock.Advance(1ns);
    ExpectCurrentTime(1, 0);
    clock.Advance(2s + 999'999'999ns);
    ExpectCurrentTime(3, 999'999'999);
}

TEST(SimClock, StaysNormalisedOverManyThreeMillisecondSteps) {
    pac::SimClock clock;
    for (int step = 1; step <= 1000; ++step) {  // 3 s: crosses several second boundaries off-grid
        clock.Advance(3ms);
        ASSERT_EQ(clock.Now(), step * 3ms);
        ASSERT_GE(__CURRENT_TIME.tv_nsec, 0) << "step " << step;
        ASSERT_LT(__CURRENT_TIME.tv_nsec, 1'000'000'000) << "step " << step;
        ASSERT_EQ(pac::FromIecTime(__CURRENT_TIME), clock.Now()) << "step " << step;
    }
    ExpectCurrentTime(3, 0);
}

TEST(SimClock, FirstThreeMillisecondStepPastOneSecond) {
    pac::SimClock clock;
    for (int step = 0; step < 334; ++step) {
        clock.Advance(3ms);
    }
    ExpectCurrentTime(1, 2'000'000);  // 334 * 3 ms = 1.002 s
}

TEST(SimClock, ZeroStepIsAllowed) {
    pac::SimClock clock;
    clock.Advance(5ms);
    clock.Advance(0ns);
    EXPECT_EQ(clock.Now(), 5ms);
}

TEST(SimClock, NegativeStepThrowsAndKeepsTime) {
    pac::SimClock clock;
    clock.Advance(5ms);
    EXPECT_THROW(clock.Advance(-1ns), std::invalid_argument);
    EXPECT_EQ(clock.Now(), 5ms);
    ExpectCurrentTime(0, 5'000'000);
}

TEST(SimClock, OverflowThrowsAndKeepsTime) {
    pac::SimClock clock;
    clock.Advance(std::chrono::nanoseconds::max() - 1ns);
    EXPECT_THROW(clock.Advance(2ns), std::overflow_error);
    EXPECT_EQ(clock.Now(), std::chrono::nanoseconds::max() - 1ns);
}

TEST(SimClock, ResetReturnsToZero) {
    pac::SimClock clock;
    clock.Advance(42s);
    clock.Reset();
    EXPECT_EQ(clock.Now(), 0ns);
    ExpectCurrentTime(0, 0);
}

TEST(IecTime, ConversionNormalisesNegativeDurations) {
    const TIME t = pac::ToIecTime(-1ns);
    EXPECT_EQ(t.tv_sec, -1);
    EXPECT_EQ(t.tv_nsec, 999'999'999);
    EXPECT_EQ(pac::FromIecTime(t), -1ns);
    EXPECT_EQ(pac::FromIecTime(pac::ToIecTime(-2500ms)), -2500ms);
}

}  // namespace
