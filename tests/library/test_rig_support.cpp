// The test rig of tests/support itself: the protocol windows against timings worked out by hand, the
// PLCopen checker against scan sequences that break each rule (it must report them) and sequences that
// keep them (it must stay silent), and RunToFinal's count and bound. A rig that cannot fail would
// let every library test pass.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <sstream>
#include <vector>

#include "bus_timing.hpp"
#include "plcopen_checker.hpp"
#include "plcopen_enable_checker.hpp"
#include "plcopen_pins.hpp"
#include "run_to_final.hpp"
#include "scan_window.hpp"

namespace test_rig_support {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using pac::test::BusTiming;
using pac::test::CommandInputs;
using pac::test::EnableOutputs;
using pac::test::PlcOpenEnableChecker;
using pac::test::PlcOpenChecker;
using pac::test::PlcOpenOutputs;
using pac::test::ProtocolWindow;
using pac::test::ScanWindow;

// ---- protocol windows ------------------------------------------------------------------------------

void ExpectWindow(const ScanWindow& w, int min, int max) {
    EXPECT_EQ(w.min, min);
    EXPECT_EQ(w.max, max);
}

TEST(ProtocolWindow, RequestWaitsForTheNextControllerCycleAndTheBusBothWays) {
    // Edge scan at 1 ms, 1 ms latency: there at 2 ms, the cycle at 10 ms answers, back at 11 ms, read by
    // the scan at 11 ms: 10 scans.
    ExpectWindow(ProtocolWindow({1, 10, 1}).Request(1ms), 10, 10);
    // Two transitional cycles more: 30 ms, back at 31 ms.
    ExpectWindow(ProtocolWindow({1, 10, 1}).Request(1ms, 2), 30, 30);
}

TEST(ProtocolWindow, TheCycleAtTheEdgeScansOwnTimeHasRunAlready) {
    // Edge scan at 10 ms, no latency: the cycle at 10 ms ran before that scan, so the one at 20 ms answers.
    ExpectWindow(ProtocolWindow({1, 10, 0}).Request(10ms), 10, 10);
}

TEST(ProtocolWindow, JitterWidensTheWindowByBothDirections) {
    // PLC 2 ms, controller 3 ms, 1 cycle latency, 1.5 ms jitter, edge scan at 2 ms. Without jitter: there
    // at 4 ms, cycle at 6 ms, back at 8 ms: 3 scans. With the whole jitter: there at 5.5 ms, cycle at 6 ms,
    // back at 9.5 ms, read at 10 ms: 4 scans.
    ExpectWindow(ProtocolWindow({2, 3, 1, 1500}).Request(2ms), 3, 4);
}

TEST(ProtocolWindow, EventsAndImmediateRepliesSkipTheWayOut) {
    // Raised after the scan at 1 ms: the cycle at 10 ms notices it, back at 11 ms.
    ExpectWindow(ProtocolWindow({1, 10, 1}).Event(1ms), 10, 10);
    // Written at once at 5 ms, 2 ms latency: read by the scan at 7 ms.
    ExpectWindow(ProtocolWindow({1, 10, 2}).ImmediateReply(5ms), 2, 2);
}

TEST(ProtocolWindow, TimeoutRunsOutInTheFirstScanAtLeastThatLate) {
    EXPECT_EQ(ProtocolWindow({2, 10, 0}).TimeoutScans(100ms), 50);
    EXPECT_EQ(ProtocolWindow({2, 10, 0}).TimeoutScans(95ms), 48);
    EXPECT_EQ(ProtocolWindow({10, 10, 0}).TimeoutScans(1ms), 1);
}

TEST(BusTiming, NamesItselfForGoogleTestAndInMessages) {
    const BusTiming jittered{2, 10, 1, 2500, 101};
    EXPECT_EQ(pac::test::BusTimingName({jittered, 0}), "Plc2ms_Pac10ms_Latency1_Jitter2500us_Seed101");
    EXPECT_EQ(pac::test::BusTimingName({BusTiming{5, 3, 0}, 0}), "Plc5ms_Pac3ms_Latency0");
    EXPECT_EQ(pac::test::Describe(jittered), "PLC 2 ms, PA-CONTROL 10 ms, latency 1 PLC cycles, jitter 2500 us, seed 101");
    EXPECT_EQ(pac::test::StandardBusTimings().size(), 48u);
}

// ---- the PLCopen checker ---------------------------------------------------------------------------

PlcOpenOutputs Busy() { return {true, false, false, false, 0}; }
PlcOpenOutputs Done() { return {false, true, false, false, 0}; }
PlcOpenOutputs Error(std::uint32_t id) { return {false, false, true, false, id}; }
PlcOpenOutputs Aborted() { return {false, false, false, true, 0}; }
PlcOpenOutputs Idle() { return {}; }
CommandInputs Execute(bool on) { return {on, false, false}; }

struct ScanOf {
    CommandInputs in;
    PlcOpenOutputs out;
};

// Feeds the scans to a fresh checker; the number of rules it reported broken.
int Violations(const std::vector<ScanOf>& scans, std::optional<int> busyBound = std::nullopt) {
    PlcOpenChecker checker("test FB");
    std::int64_t scan = 0;
    for (const ScanOf& s : scans) checker.Check(++scan, s.in, s.out, busyBound);
    return checker.Violations();
}

// ---- the Enable rules ---------------------------------------------------------------------------------

// Runs the Enable checker over scans of {Enable, Valid, Busy, Error, ErrorID}.
void EnableViolations(const std::vector<EnableOutputs>& scans) {
    PlcOpenEnableChecker checker("FB");
    std::int64_t scan = 0;
    for (const auto& o : scans) checker.Check(++scan, o);
}

TEST(PlcOpenEnableChecker, KeptRulesAreSilent) {
    EnableViolations({{false, false, false, false, 0}, {true, false, true, false, 0}, {true, true, true, false, 0},
                      {true, false, false, true, 0x8003}, {true, true, true, false, 0}, {false, false, false, false, 0}});
}

TEST(PlcOpenEnableChecker, ReportsEachBrokenRule) {
    EXPECT_NONFATAL_FAILURE(EnableViolations({{true, true, false, true, 0x8003}}), "Valid and Error at once");
    EXPECT_NONFATAL_FAILURE(EnableViolations({{true, false, true, true, 0x8003}}), "Busy and Error at once");
    EXPECT_NONFATAL_FAILURE(EnableViolations({{true, false, false, true, 0}}), "ErrorID <> 0 not exactly with Error");
    EXPECT_NONFATAL_FAILURE(EnableViolations({{true, true, true, false, 5}}), "ErrorID <> 0 not exactly with Error");
    EXPECT_NONFATAL_FAILURE(EnableViolations({{false, true, false, false, 0}}), "a scan that saw Enable FALSE");
    EXPECT_NONFATAL_FAILURE(EnableViolations({{false, false, true, false, 0}}), "a scan that saw Enable FALSE");
}

TEST(PlcOpenChecker, KeptRulesAreSilent) {
    EXPECT_EQ(Violations({{Execute(true), Busy()},
                          {Execute(true), Busy()},
                          {Execute(true), Done()},
                          {Execute(true), Done()},
                          {Execute(false), Idle()},
                          {Execute(true), Error(43)},
                          {Execute(true), Error(43)},
                          {Execute(false), Idle()},
                          {Execute(true), Busy()},
                          {Execute(false), Busy()},
                          {Execute(false), Done()},
                          {Execute(false), Idle()}},
                         3),
              0);
}

TEST(PlcOpenChecker, ASupersededJobShowsCommandAbortedForTheEdgeScanOnly) {
    EXPECT_EQ(Violations({{Execute(true), Busy()},
                          {Execute(false), Busy()},
                          {Execute(true), Aborted()},
                          {Execute(true), Busy()},
                          {Execute(true), Done()}}),
              0);
    // A jog (level input) ended by an Execute edge.
    EXPECT_EQ(Violations({{{false, true, false}, Busy()}, {{true, true, false}, Aborted()}, {{true, true, false}, Busy()}}),
              0);
}

TEST(PlcOpenChecker, TheInputThatStartedTheJobGovernsItsFinalOutput) {
    const CommandInputs executeAndJog{true, true, false};
    const CommandInputs jogOnly{false, true, false};
    const CommandInputs bothJogs{false, true, true};
    // Execute and a jog rose together: Execute's job; its Error clears with Execute although the jog stays.
    EXPECT_EQ(Violations({{executeAndJog, Error(0x800E)}, {jogOnly, Idle()}}), 0);
    EXPECT_NONFATAL_FAILURE(Violations({{executeAndJog, Error(0x800E)}, {jogOnly, Error(0x800E)}}),
                            "did not clear");
    // A jog edge beside a held output: either input may own it, so it may hold on the jog alone...
    EXPECT_EQ(Violations({{Execute(true), Error(0x800B)}, {executeAndJog, Error(0x800B)}, {jogOnly, Error(0x800B)}}), 0);
    // ...but it must clear once neither is TRUE.
    EXPECT_NONFATAL_FAILURE(
        Violations({{Execute(true), Error(0x800B)}, {bothJogs, Error(0x800B)}, {Execute(false), Error(0x800B)}}),
        "did not clear");
    // A jog edge while the other jog still stops is ignored: that jog's Done shows for one scan.
    const CommandInputs jogNegative{false, false, true};
    EXPECT_EQ(Violations({{jogNegative, Busy()}, {jogOnly, Busy()}, {jogOnly, Done()}, {jogOnly, Idle()}}), 0);
    // A superseded job's CommandAborted, then the new job's own, held while Execute stays TRUE.
    EXPECT_EQ(Violations({{jogOnly, Busy()}, {executeAndJog, Aborted()}, {executeAndJog, Aborted()},
                          {executeAndJog, Aborted()}}),
              0);
}

TEST(PlcOpenChecker, ReportsOutputsAtOnce) {
    EXPECT_NONFATAL_FAILURE(Violations({{Execute(true), {true, true, false, false, 0}}}), "at once");
}

TEST(PlcOpenChecker, ReportsErrorIdWithoutError) {
    EXPECT_NONFATAL_FAILURE(Violations({{Execute(true), Error(0)}}), "ErrorID <> 0 not exactly with Error");
    EXPECT_NONFATAL_FAILURE(Violations({{Execute(true), {false, true, false, false, 5}}}),
                            "ErrorID <> 0 not exactly with Error");
}

TEST(PlcOpenChecker, ReportsAFinalOutputThatDoesNotHold) {
    EXPECT_NONFATAL_FAILURE(Violations({{Execute(true), Done()}, {Execute(true), Idle()}}), "did not hold");
    EXPECT_NONFATAL_FAILURE(Violations({{Execute(true), Error(43)}, {Execute(true), Error(44)}}), "did not hold");
}

TEST(PlcOpenChecker, ReportsAFinalOutputThatDoesNotClear) {
    EXPECT_NONFATAL_FAILURE(Violations({{Execute(true), Done()}, {Execute(false), Done()}}), "did not clear");
}

TEST(PlcOpenChecker, ReportsAnEarlyReleasedJobsOutputShownTwice) {
    EXPECT_NONFATAL_FAILURE(
        Violations({{Execute(true), Busy()}, {Execute(false), Busy()}, {Execute(false), Done()}, {Execute(false), Done()}}),
        "more than one scan");
}

TEST(PlcOpenChecker, ReportsBusyBeyondTheBound) {
    EXPECT_NONFATAL_FAILURE(Violations({{Execute(true), Busy()}, {Execute(true), Busy()}, {Execute(true), Busy()}}, 2),
                            "Busy longer");
}

TEST(PlcOpenChecker, BusyBoundsFollowTheFbsTimeouts) {
    EXPECT_EQ(pac::test::CommandBusyBound(1s, 60s, 1ms), 1000 + 1 + 1000 + 60000) << "wait, SEND flag, ack, end";
    EXPECT_EQ(pac::test::CommandBusyBound(0s, 0s, 1ms), 1000 + 1 + 1000 + 60000) << "T#0S: the defaults";
    EXPECT_EQ(pac::test::RequestBusyBound(95ms, 2ms), 48);
    EXPECT_EQ(pac::test::RequestBusyBound(0s, 2ms), 5000) << "T#0S: T#10S";
}

// ---- typed pins and RunToFinal ---------------------------------------------------------------------

template <class T>
struct Pin {
    T value{};
};

// The pins of a command FB as the generated C code lays them out, without CommandAborted.
struct FakeCommandFb {
    Pin<std::uint8_t> EXECUTE, BUSY, DONE, ERROR;
    Pin<std::uint16_t> ERRORID;
};

struct FakeJobFb : FakeCommandFb {
    Pin<std::uint8_t> COMMANDABORTED, JOGPOSITIVE, JOGNEGATIVE;
};

TEST(PlcOpenPins, ReadEveryFbTheSameWay) {
    FakeCommandFb cmd;
    cmd.ERROR.value = 1;
    cmd.ERRORID.value = 0x8001;
    EXPECT_EQ(pac::test::OutputsOf(cmd), Error(0x8001));
    FakeJobFb job;
    job.COMMANDABORTED.value = 1;
    job.JOGNEGATIVE.value = 1;
    EXPECT_EQ(pac::test::OutputsOf(job), Aborted());
    EXPECT_TRUE(pac::test::InputsOf(job).Any());
    EXPECT_FALSE(pac::test::InputsOf(cmd).Any());
    std::ostringstream text;
    text << Error(0x8001);
    EXPECT_EQ(text.str(), "Error, ErrorID 16#8001");
}

TEST(RunToFinal, CountsScansFromTheEdgeScanAndStopsAtTheBound) {
    FakeCommandFb fb;
    fb.BUSY.value = 1;
    std::int64_t scan = 7;  // the edge scan
    auto doneInScan = [&](std::int64_t at) {
        return [&fb, &scan, at] {
            ++scan;
            if (scan == at) {
                fb.BUSY.value = 0;
                fb.DONE.value = 1;
            }
            return scan;
        };
    };
    const pac::test::FinalOutcome done = pac::test::RunToFinal(fb, 7, doneInScan(10), 5);
    EXPECT_TRUE(done.Done());
    EXPECT_EQ(done.Scans(), 3);
    fb.DONE.value = 0;
    fb.BUSY.value = 1;
    scan = 7;
    const pac::test::FinalOutcome late = pac::test::RunToFinal(fb, 7, doneInScan(20), 5);
    EXPECT_FALSE(late.Ended());
    EXPECT_EQ(late.Scans(), -1);
    EXPECT_EQ(scan, 12) << "five scans, no more";
}

}  // namespace
}  // namespace test_rig_support
