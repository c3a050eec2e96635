// The benchmark table's workloads (bench/workloads.hpp) without valgrind: a workload that finishes no job,
// or a hand-written C handshake that no longer does what the FBs do, would print the cost of another
// program than the one its row names (as when the bench's axes once stood still for want of an input).
#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <string>

#include "latency.hpp"
#include "workloads.hpp"

namespace {

using std::chrono::milliseconds;

// The scans each workload runs here; the table measures 2000 (docs/benchmarks.md).
constexpr int kScans = 2000;

TEST(BenchWorkloads, EveryJobWorkloadFinishesJobs) {
    // At a 1 ms PLC cycle a command, a mode request or an automatic-module job ends within tens of scans and
    // an axis move within hundreds, so 2000 scans hold several of each.
    for (const char* name : {"cmd-job", "c-job", "ctrl-job", "ctrl-c-job", "axis-job", "axis-c-job", "automatic-job",
                             "plant-pac1", "plant-pac10"}) {
        const pac::bench::WorkloadResult result = pac::bench::RunWorkload(name, kScans);
        EXPECT_EQ(result.scans, kScans) << name;
        EXPECT_GE(result.jobs, 2) << name;
    }
}

TEST(BenchWorkloads, IdleWorkloadsFinishNoJob) {
    for (const char* name :
         {"cmd-idle", "c-idle", "ctrl-idle", "ctrl-c-idle", "axis-idle", "axis-c-idle", "automatic-idle"}) {
        const pac::bench::WorkloadResult result = pac::bench::RunWorkload(name, kScans);
        EXPECT_EQ(result.scans, kScans) << name;
        EXPECT_EQ(result.jobs, 0) << name;
    }
}

TEST(BenchWorkloads, AnUnknownWorkloadIsRefused) {
    EXPECT_THROW(pac::bench::RunWorkload("no-such-workload", 1), std::invalid_argument);
    EXPECT_THROW(pac::bench::RunWorkload("plants-0", 1), std::invalid_argument);
    EXPECT_THROW(pac::bench::RunWorkload("plants-2-pac0", 1), std::invalid_argument);
    EXPECT_THROW(pac::bench::RunWorkload("plants-2x", 1), std::invalid_argument);
}

// The scale rows' instruction counts divide by every plant's scans: N plants for `cycles` PLC cycles are
// N x cycles scans, and every plant finishes jobs (a 10 ms controller cycle: an axis move within hundreds).
TEST(BenchWorkloads, PlantsWorkloadCountsEveryPlantsScans) {
    const pac::bench::WorkloadResult one = pac::bench::RunWorkload("plants-1", kScans);
    const pac::bench::WorkloadResult three = pac::bench::RunWorkload("plants-3", kScans);
    EXPECT_EQ(one.scans, kScans);
    EXPECT_EQ(three.scans, 3 * kScans);
    EXPECT_GE(one.jobs, 2);
    EXPECT_EQ(three.jobs, 3 * one.jobs) << "the plants share nothing: each does what one alone does";
    // The same at the 1 ms controller cycle of the scale goal.
    const pac::bench::WorkloadResult fast = pac::bench::RunWorkload("plants-3-pac1", kScans);
    EXPECT_EQ(fast.scans, 3 * kScans);
    EXPECT_GE(fast.jobs, 3 * one.jobs) << "a 1 ms controller cycle answers sooner: no fewer jobs in as many scans";
}

// `compare` (one of the side-by-side checks of workloads.hpp) finds no difference on timings where the waits
// differ: PLC cycle 1 and 5 ms x controller cycle 1 and 10 ms x bus latency 0 and 2 cycles.
void ExpectAgreementOnEveryTiming(std::string (*compare)(const pac::RigTiming&, int)) {
    for (int plcMs : {1, 5}) {
        for (int pacMs : {1, 10}) {
            for (int latency : {0, 2}) {
                pac::RigTiming timing;
                timing.plcCycle = milliseconds(plcMs);
                timing.pacCycle = milliseconds(pacMs);
                timing.latencyCycles = latency;
                EXPECT_EQ(compare(timing, kScans), "")
                    << "PLC " << plcMs << " ms, controller " << pacMs << " ms, latency " << latency;
            }
        }
    }
}

// The scan-cost ratio compares the library's CMD interface with the hand-written C only if both write the
// same module and give the same outputs in every scan: on timings where the waits differ.
TEST(BenchWorkloads, HandWrittenCAgreesWithTheFbsOnEveryScan) {
    ExpectAgreementOnEveryTiming(pac::bench::CompareWithHandWritten);
}

// The same for FB_PAC_Axis and its hand-written C, through moves, aborts, Axis OFF, refused and superseded
// jobs, ONLINE stopped and started again and a lost link.
TEST(BenchWorkloads, HandWrittenAxisAgreesWithTheFbOnEveryScan) {
    ExpectAgreementOnEveryTiming(pac::bench::CompareAxisWithHandWritten);
}

// The same for FB_PAC_Ctrl and its hand-written C, through every request, both number formats and a lost link.
TEST(BenchWorkloads, HandWrittenCtrlAgreesWithTheFbOnEveryScan) {
    ExpectAgreementOnEveryTiming(pac::bench::CompareCtrlWithHandWritten);
}

// The latency table compares each job with the protocol minimum of its own round trip: a job that also waits
// for the CMD interface's first handshake after the PLC cold start (the parked read) would count as late.
// The slowest timings, where that handshake lasts longest: a 1 ms PLC cycle, a 10 ms controller cycle.
TEST(BenchWorkloads, LatencyJobsStartPastTheFirstHandshake) {
    for (int latency : {0, 3}) {
        pac::RigTiming timing;
        timing.plcCycle = milliseconds(1);
        timing.pacCycle = milliseconds(10);
        timing.latencyCycles = latency;
        EXPECT_EQ(pac::bench::MeasureCmd(timing, 4).aboveMinimum, 0) << "latency " << latency;
        EXPECT_EQ(pac::bench::MeasureShared(timing, 2, 2).aboveMinimum, 0) << "latency " << latency;
    }
}

}  // namespace
