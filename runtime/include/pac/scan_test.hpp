// GoogleTest helpers for tests that run a PLC task over many scans: Cycle() runs a fixed number of
// scans, RunUntil() runs scans until a condition holds but never more than a bound, so a test that
// waits for a Done bit fails with a message instead of hanging. ScanTest is a fixture holding a clock
// and a 1 ms task, so a test reads ASSERT_TRUE(RunUntil([&] { return fb.DONE.value; }, 50, "Done")).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <sstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "pac/format_time.hpp"
#include "pac/plc_task.hpp"
#include "pac/sim_clock.hpp"

namespace pac {

namespace detail {

using pac::FormatMs;

// Where the task stands, for messages: absolute scan number and simulated time.
inline std::string Position(const PlcTask& task) {
    return "scan " + std::to_string(task.ScanCount()) + ", t = " + FormatMs(task.Clock().Now());
}

}  // namespace detail

inline void Cycle(PlcTask& task, int n) {
    if (n < 0) {
        ADD_FAILURE() << "Cycle: negative scan count " << n;
        return;
    }
    for (int i = 0; i < n; ++i) {
        task.Scan();
    }
}

// The predicate is checked before the first scan (true already: no scan runs) and after each scan.
inline ::testing::AssertionResult RunUntil(PlcTask& task, std::function<bool()> predicate, int maxScans,
                                           const std::string& what = "") {
    const std::string name = what.empty() ? "condition" : what;
    if (!predicate) {
        return ::testing::AssertionFailure() << "RunUntil(" << name << "): empty predicate";
    }
    if (predicate()) {
        return ::testing::AssertionSuccess()
               << name << " already true, 0 scans run (" << detail::Position(task) << ")";
    }
    for (int scans = 1; scans <= maxScans; ++scans) {
        task.Scan();
        if (predicate()) {
            return ::testing::AssertionSuccess()
                   << name << " reached after " << scans << " scans (" << detail::Position(task) << ")";
        }
    }
    return ::testing::AssertionFailure()
           << name << " not reached within " << maxScans << " scans (" << detail::Position(task) << ")";
}

// Fixture base: each test gets a fresh clock at 0 (which also resets __CURRENT_TIME) and a task.
class ScanTest : public ::testing::Test {
protected:
    static constexpr std::chrono::nanoseconds kDefaultCycleTime = std::chrono::milliseconds(1);

    explicit ScanTest(std::chrono::nanoseconds cycleTime = kDefaultCycleTime) : task_(clock_, cycleTime) {}

    void Cycle(int n) { pac::Cycle(task_, n); }

    ::testing::AssertionResult RunUntil(std::function<bool()> predicate, int maxScans,
                                        const std::string& what = "") {
        return pac::RunUntil(task_, std::move(predicate), maxScans, what);
    }

    SimClock clock_;
    PlcTask task_;
};

}  // namespace pac
