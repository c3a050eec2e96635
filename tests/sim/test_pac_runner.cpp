// PacRunner: the controller's own cycle (1..10 ms) next to a PlcTask, each controller cycle with
// its own timestamp, phase offsets, and the order at equal timestamps (controller first).
#include <chrono>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "pac/scan_test.hpp"
#include "pac/sim/pac_runner.hpp"
#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

PaControlConfig WithCycles(std::chrono::nanoseconds home, std::chrono::nanoseconds active) {
    PaControlConfig config = QuickConfig();
    config.homeCycle = home;
    config.activeCycle = active;
    return config;
}

std::vector<std::int64_t> CycleTimesUs(const PaControl& pac) {
    std::vector<std::int64_t> out;
    for (const auto& r : pac.Log().Records()) {
        out.push_back(std::chrono::duration_cast<std::chrono::microseconds>(r.time).count());
    }
    return out;
}

// The PLC program: reads the reply, toggles SEND with 1906 N1 in scan
// `toggleScan`, writes its image; records RF as seen in each scan.
struct PlcProgram {
    PlcProgram(Bus& b, const pac::PlcTask& t, std::int64_t toggle) : bus(b), task(t), toggleScan(toggle) {}

    Bus& bus;
    const pac::PlcTask& task;
    std::int64_t toggleScan;
    Image8 image{};
    std::vector<int> receiveFlags;  // per scan

    void operator()() {
        const auto now = task.Clock().Now();
        const ReplyFrame reply = ReplyFrame::Decode(bus.ReadFromPac(now).Cmd());
        receiveFlags.push_back(reply.receiveFlag ? 1 : 0);
        if (task.ScanCount() == toggleScan) image = CommandImage(code::kGetIntReg, 1, 0, true);
        bus.WriteToPac(now, image);
    }
    bool Acknowledged() const { return !receiveFlags.empty() && receiveFlags.back() == 1; }
};

class ControllerCycle : public pac::ScanTest, public ::testing::WithParamInterface<int> {};

TEST_P(ControllerCycle, EveryCycleRunsAtItsOwnTimestamp) {
    const auto cycle = std::chrono::milliseconds(GetParam());
    Bus bus;
    PaControl pac(bus, WithCycles(cycle, cycle));
    PacRunner runner(pac);
    runner.AttachTo(task_);
    Cycle(30);  // PLC at 1 ms: t = 1..30 ms
    std::vector<std::int64_t> expected;
    for (auto t = std::chrono::milliseconds(0); t <= 30ms; t += cycle) {
        expected.push_back(std::chrono::duration_cast<std::chrono::microseconds>(t).count());
    }
    EXPECT_EQ(CycleTimesUs(pac), expected);
    EXPECT_EQ(runner.CyclesRun(), static_cast<std::int64_t>(expected.size()));
    EXPECT_EQ(runner.NextCycleTime(), std::chrono::milliseconds(expected.size() * GetParam()));
}

TEST_P(ControllerCycle, AcknowledgementReachesThePlcAtTheNextControllerCycle) {
    const int c = GetParam();
    Bus bus;
    PaControl pac(bus, WithCycles(std::chrono::milliseconds(c), std::chrono::milliseconds(c)));
    pac.Io().intRegisters.SetInt(1, 3);
    PacRunner runner(pac);
    runner.AttachTo(task_);
    PlcProgram plc{bus, task_, 1};
    task_.AddProgram([&] { plc(); });
    // SEND toggles in the scan at 1 ms; the first controller cycle after it is at the smallest
    // multiple of c above 1 ms, and the PLC's scan at that time reads the reply.
    ASSERT_TRUE(RunUntil([&] { return plc.Acknowledged(); }, 20, "RF = 1"));
    const int expectedScan = c == 1 ? 2 : c;
    EXPECT_EQ(task_.ScanCount(), expectedScan);
    EXPECT_EQ(ToHex(bus.ReadFromPac(clock_.Now())), "00 00 00 03 00 01 A0 00");
}

INSTANTIATE_TEST_SUITE_P(OneToTenMs, ControllerCycle, ::testing::Values(1, 2, 3, 5, 7, 10));

class Runner : public pac::ScanTest {};

TEST_F(Runner, PlcCycleLongerThanTheControllerCycle) {
    task_.SetCycleTime(10ms);
    Bus bus;
    PaControl pac(bus, WithCycles(1ms, 1ms));
    PacRunner runner(pac);
    runner.AttachTo(task_);
    Cycle(1);  // t = 10 ms: controller cycles at 0, 1, ..., 10 ms
    EXPECT_EQ(CycleTimesUs(pac),
              (std::vector<std::int64_t>{0, 1000, 2000, 3000, 4000, 5000, 6000, 7000, 8000, 9000, 10000}));
}

TEST_F(Runner, PhaseOffset) {
    Bus bus;
    PaControl pac(bus, WithCycles(10ms, 10ms));
    PacRunner runner(pac, 3ms);
    runner.AttachTo(task_);
    Cycle(2);
    EXPECT_EQ(runner.CyclesRun(), 0);
    Cycle(23);  // t = 25 ms
    EXPECT_EQ(CycleTimesUs(pac), (std::vector<std::int64_t>{3000, 13000, 23000}));
    EXPECT_THROW(PacRunner(pac, -1ns), std::invalid_argument);
}

TEST_F(Runner, AtEqualTimestampsTheControllerRunsBeforeThePlc) {
    Bus bus;
    PaControl pac(bus, WithCycles(10ms, 10ms));
    PacRunner runner(pac);
    runner.AttachTo(task_);  // first program
    PlcProgram plc{bus, task_, 5};
    task_.AddProgram([&] { plc(); });
    Cycle(11);
    // Scans 1..11 (t = 1..11 ms): SEND toggles at 5 ms; the controller's 10 ms cycle sees it and
    // the PLC's 10 ms scan, running after it, reads RF = 1.
    EXPECT_EQ(plc.receiveFlags, (std::vector<int>{0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1}));
}

TEST_F(Runner, RegisteredAfterThePlcProgramTheReplyIsOneScanLater) {
    Bus bus;
    PaControl pac(bus, WithCycles(10ms, 10ms));
    PacRunner runner(pac);
    PlcProgram plc{bus, task_, 5};
    task_.AddProgram([&] { plc(); });
    runner.AttachTo(task_);  // after the PLC: the scan at 10 ms reads before the controller's cycle
    Cycle(11);
    EXPECT_EQ(plc.receiveFlags, (std::vector<int>{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1}));
}

TEST_F(Runner, CadenceFollowsTheModeCycleTime) {
    Bus bus;
    PaControl pac(bus, WithCycles(10ms, 2ms));
    pac.SystemParameters().Set(4, 1);
    pac.Io().inputs.Set(1, true);
    PacRunner runner(pac);
    runner.AttachTo(task_);
    task_.AddProgram([&] {
        if (task_.ScanCount() == 1) bus.WriteToPac(clock_.Now(), CommandImage(code::kStartOnline, 0, 0, true));
    });
    Cycle(16);
    // Home position: 0, 10 ms; the 10 ms cycle starts ONLINE, then every 2 ms.
    EXPECT_EQ(CycleTimesUs(pac), (std::vector<std::int64_t>{0, 10000, 12000, 14000, 16000}));
    EXPECT_EQ(pac.OperatingStatus(), 31);
}

}  // namespace
}  // namespace pac::sim::testing
