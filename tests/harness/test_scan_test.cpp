// Cycle/RunUntil and the ScanTest fixture: RunUntil stops at the first scan where the predicate
// holds, runs no scan when it already holds, and fails with a clear message after maxScans.
#include <chrono>
#include <string>

#include <gtest/gtest.h>

#include "pac/scan_test.hpp"

using namespace std::chrono_literals;

namespace {

class RunUntilTest : public pac::ScanTest {
protected:
    void SetUp() override {
        task_.AddProgram([this] { ++programRuns; });
    }

    int programRuns = 0;
};

TEST_F(RunUntilTest, CycleRunsExactlyNScans) {
    Cycle(7);
    EXPECT_EQ(task_.ScanCount(), 7);
    EXPECT_EQ(programRuns, 7);
    EXPECT_EQ(clock_.Now(), 7ms);
}

TEST_F(RunUntilTest, CycleZeroRunsNothing) {
    Cycle(0);
    EXPECT_EQ(task_.ScanCount(), 0);
    EXPECT_EQ(clock_.Now(), 0ns);
}

TEST_F(RunUntilTest, StopsAtTheFirstScanWherePredicateHolds) {
    const auto result = RunUntil([this] { return programRuns == 5; }, 50, "five runs");
    ASSERT_TRUE(result);
    EXPECT_EQ(task_.ScanCount(), 5);
    EXPECT_EQ(std::string(result.message()), "five runs reached after 5 scans (scan 5, t = 5 ms)");
}

TEST_F(RunUntilTest, CountsScansFromWhereTheTaskStands) {
    Cycle(3);
    const auto result = RunUntil([this] { return programRuns >= 10; }, 50, "ten runs");
    ASSERT_TRUE(result);
    EXPECT_EQ(task_.ScanCount(), 10);
    EXPECT_EQ(std::string(result.message()), "ten runs reached after 7 scans (scan 10, t = 10 ms)");
}

TEST_F(RunUntilTest, ChecksThePredicateAfterTheScanNotBefore) {
    ASSERT_TRUE(RunUntil([this] { return programRuns == 1; }, 1));
    EXPECT_EQ(task_.ScanCount(), 1);
}

TEST_F(RunUntilTest, AlreadyTrueRunsNoScan) {
    const auto result = RunUntil([] { return true; }, 50, "ready");
    ASSERT_TRUE(result);
    EXPECT_EQ(task_.ScanCount(), 0);
    EXPECT_EQ(programRuns, 0);
    EXPECT_EQ(clock_.Now(), 0ns);
    EXPECT_EQ(std::string(result.message()), "ready already true, 0 scans run (scan 0, t = 0 ms)");
}

TEST_F(RunUntilTest, FailsAfterMaxScansWithMessage) {
    const auto result = RunUntil([] { return false; }, 25, "Done");
    EXPECT_FALSE(result);
    EXPECT_EQ(task_.ScanCount(), 25);
    EXPECT_EQ(std::string(result.message()), "Done not reached within 25 scans (scan 25, t = 25 ms)");
}

TEST_F(RunUntilTest, FailureReportsTheAbsoluteScanAndFractionalTime) {
    task_.SetCycleTime(500us);
    Cycle(4);
    const auto result = RunUntil([] { return false; }, 3, "Busy");
    EXPECT_FALSE(result);
    EXPECT_EQ(std::string(result.message()), "Busy not reached within 3 scans (scan 7, t = 3.5 ms)");
}

TEST_F(RunUntilTest, UnnamedConditionIsCalledCondition) {
    const auto result = RunUntil([] { return false; }, 2);
    EXPECT_FALSE(result);
    EXPECT_EQ(std::string(result.message()), "condition not reached within 2 scans (scan 2, t = 2 ms)");
}

TEST_F(RunUntilTest, ZeroMaxScansRunsNothingAndFails) {
    EXPECT_FALSE(RunUntil([] { return false; }, 0, "x"));
    EXPECT_EQ(task_.ScanCount(), 0);
}

TEST_F(RunUntilTest, EmptyPredicateFailsInsteadOfThrowing) {
    const auto result = RunUntil(nullptr, 5, "nothing");
    EXPECT_FALSE(result);
    EXPECT_EQ(task_.ScanCount(), 0);
}

TEST(RunUntilFree, WorksOnAnyTask) {
    pac::SimClock clock;
    pac::PlcTask task(clock, 2ms);
    pac::Cycle(task, 2);
    ASSERT_TRUE(pac::RunUntil(task, [&] { return clock.Now() >= 10ms; }, 10));
    EXPECT_EQ(task.ScanCount(), 5);
}

TEST(FormatMs, ExactMilliseconds) {
    EXPECT_EQ(pac::detail::FormatMs(0ns), "0 ms");
    EXPECT_EQ(pac::detail::FormatMs(1234ms), "1234 ms");
    EXPECT_EQ(pac::detail::FormatMs(2500us), "2.5 ms");
    EXPECT_EQ(pac::detail::FormatMs(1ns), "0.000001 ms");
    EXPECT_EQ(pac::detail::FormatMs(1ms + 10us), "1.01 ms");
}

}  // namespace
