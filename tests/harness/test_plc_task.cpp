// PlcTask: time advances by the cycle time before the programs run; programs run once per scan in
// registration order; the cycle time must be positive.
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "pac/iec_time.hpp"
#include "pac/plc_task.hpp"
#include "pac/sim_clock.hpp"

using namespace std::chrono_literals;

namespace {

TEST(PlcTask, RejectsNonPositiveCycleTime) {
    pac::SimClock clock;
    EXPECT_THROW(pac::PlcTask(clock, 0ns), std::invalid_argument);
    EXPECT_THROW(pac::PlcTask(clock, -1ms), std::invalid_argument);
}

TEST(PlcTask, SetCycleTimeRejectsNonPositiveAndKeepsTheOldOne) {
    pac::SimClock clock;
    pac::PlcTask task(clock, 2ms);
    EXPECT_THROW(task.SetCycleTime(0ns), std::invalid_argument);
    EXPECT_THROW(task.SetCycleTime(-5ms), std::invalid_argument);
    EXPECT_EQ(task.CycleTime(), 2ms);
}

TEST(PlcTask, RejectsEmptyProgram) {
    pac::SimClock clock;
    pac::PlcTask task(clock, 1ms);
    EXPECT_THROW(task.AddProgram(nullptr), std::invalid_argument);
}

TEST(PlcTask, NothingRunsBeforeTheFirstScan) {
    pac::SimClock clock;
    pac::PlcTask task(clock, 1ms);
    int runs = 0;
    task.AddProgram([&] { ++runs; });
    EXPECT_EQ(runs, 0);
    EXPECT_EQ(task.ScanCount(), 0);
    EXPECT_EQ(clock.Now(), 0ns);
}

TEST(PlcTask, TimeAdvancesBeforeProgramsRun) {
    pac::SimClock clock;
    pac::PlcTask task(clock, 1ms);
    std::vector<std::chrono::nanoseconds> seenGlobal;
    std::vector<std::chrono::nanoseconds> seenClock;
    task.AddProgram([&] {
        seenGlobal.push_back(pac::FromIecTime(__CURRENT_TIME));
        seenClock.push_back(clock.Now());
    });
    task.Scan();
    task.Scan();
    task.Scan();
    const std::vector<std::chrono::nanoseconds> expected{1ms, 2ms, 3ms};
    EXPECT_EQ(seenGlobal, expected);
    EXPECT_EQ(seenClock, expected);
}

TEST(PlcTask, ProgramsRunOncePerScanInRegistrationOrder) {
    pac::SimClock clock;
    pac::PlcTask task(clock, 1ms);
    std::vector<int> calls;
    task.AddProgram([&] { calls.push_back(1); });
    task.AddProgram([&] { calls.push_back(2); });
    task.AddProgram([&] { calls.push_back(3); });
    task.Scan();
    task.Scan();
    EXPECT_EQ(calls, (std::vector<int>{1, 2, 3, 1, 2, 3}));
}

TEST(PlcTask, ScanCountIsTheCurrentScanInsideAProgram) {
    pac::SimClock clock;
    pac::PlcTask task(clock, 1ms);
    std::vector<std::int64_t> seen;
    task.AddProgram([&] { seen.push_back(task.ScanCount()); });
    task.Scan();
    task.Scan();
    task.Scan();
    EXPECT_EQ(seen, (std::vector<std::int64_t>{1, 2, 3}));
    EXPECT_EQ(task.ScanCount(), 3);
}

TEST(PlcTask, NewCycleTimeAppliesFromTheNextScan) {
    pac::SimClock clock;
    pac::PlcTask task(clock, 1ms);
    task.Scan();
    task.SetCycleTime(5ms);
    EXPECT_EQ(task.CycleTime(), 5ms);
    EXPECT_EQ(clock.Now(), 1ms);
    task.Scan();
    EXPECT_EQ(clock.Now(), 6ms);
}

TEST(PlcTask, SubMillisecondCycle) {
    pac::SimClock clock;
    pac::PlcTask task(clock, 250us);
    for (int i = 0; i < 4000; ++i) {
        task.Scan();
    }
    EXPECT_EQ(clock.Now(), 1s);
    EXPECT_EQ(__CURRENT_TIME.tv_sec, 1);
    EXPECT_EQ(__CURRENT_TIME.tv_nsec, 0);
}

}  // namespace
