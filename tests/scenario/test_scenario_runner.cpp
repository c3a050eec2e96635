// ScenarioRunner and TimelinePrinter: the demo scenario and the link-fault example meet every
// expectation; a failed expectation is reported with what was seen; the controller setup, faults
// and waits act as described in docs/scenario.md; the timeline shows only scans with a change.
#include <gtest/gtest.h>

#include <cctype>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "../support/scan_window.hpp"
#include "gvl_names.hpp"
#include "scenario_loader.hpp"
#include "scenario_runner.hpp"
#include "timeline_printer.hpp"

namespace {

using pac::scenario::RunReport;
using pac::scenario::Scenario;
using pac::scenario::ScenarioLoader;
using pac::scenario::ScenarioRunner;

const pac::scenario::GvlNames& Names() {
    static const pac::scenario::GvlNames names;
    return names;
}

// Runs a scenario and keeps its timeline.
struct ScenarioRun {
    explicit ScenarioRun(const Scenario& s) : scenario(s) {
        pac::scenario::TimelinePrinter printer(timeline, Names());
        report = ScenarioRunner(scenario).Run(printer);
    }

    Scenario scenario;
    std::ostringstream timeline;
    RunReport report;
};

Scenario FromText(const std::string& text) { return ScenarioLoader(Names()).FromText(text); }
Scenario FromFile(const std::string& name) {
    return ScenarioLoader(Names()).FromFile(std::string(PAC_SCENARIO_DIR) + "/" + name);
}

pac::test::BusTiming BusOf(const Scenario& s) {
    return {s.timing.plcCycleMs, s.timing.pacCycleMs, s.timing.latencyCycles, 1000 * s.timing.jitterMs, s.timing.seed};
}

// The scan with number n runs at n PLC cycles: the task advances the clock, then scans.
std::chrono::nanoseconds TimeOfScan(const Scenario& s, std::int64_t scan) {
    return scan * std::chrono::milliseconds(s.timing.plcCycleMs);
}

// The scans from the edge scan of an axis job to the scan that shows ACTIVE fallen, for a move that
// takes `move` on the axis: the Start travels to the PA-CONTROL (latency), waits for its next cycle
// (less than one cycle), the axis moves, ACTIVE falls in the first cycle that finds it in position
// (less than one cycle), the reply travels back (latency) and the next scan reads it.
pac::test::ScanWindow MoveWindow(const pac::test::BusTiming& t, std::chrono::nanoseconds move) {
    const auto scans = [&t](std::chrono::nanoseconds d) {
        return static_cast<int>((d + t.PlcCycle() - std::chrono::nanoseconds(1)) / t.PlcCycle());
    };
    const std::chrono::nanoseconds fixed = move + 2 * t.Latency();
    return {scans(fixed), scans(fixed + 2 * (t.PacCycle() + t.Jitter()))};
}

// A point-to-point move of `distance` at `speed` with ramps of `acceleration` both ways (docs/sim_axis.md:
// the trapezoid, or a triangle where the distance is too short for the speed).
std::chrono::nanoseconds MoveTime(double distance, double speed, double acceleration) {
    const double seconds = distance * acceleration >= speed * speed ? distance / speed + speed / acceleration
                                                                    : 2 * std::sqrt(distance / acceleration);
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(seconds));
}

// The line the timeline prints for an axis outcome.
std::string AxisLine(const pac::scenario::AxisOutcome& o, const std::string& result) {
    std::ostringstream line;
    line << "=> axis " << o.axis << ": " << result << " in scan " << o.endScan << " ("
         << std::chrono::duration_cast<std::chrono::milliseconds>(o.endTime).count() << " ms), "
         << o.endScan - o.edgeScan << " scans after the step began";
    return line.str();
}

// Lines of the timeline that show a scan: they start with the time column.
int ScanLines(const std::string& timeline) {
    std::istringstream lines(timeline);
    int n = 0;
    for (std::string line; std::getline(lines, line);) {
        const auto first = line.find_first_not_of(' ');
        if (first != std::string::npos && std::isdigit(static_cast<unsigned char>(line[first]))) ++n;
    }
    return n;
}

TEST(ScenarioRunner, DemoMeetsEveryExpectation) {
    const ScenarioRun run(FromFile("demo.json"));
    const std::string& out = run.timeline.str();
    EXPECT_TRUE(run.report.Passed()) << out;
    EXPECT_EQ(run.report.steps.size(), 16u);
    EXPECT_EQ(run.report.Commands(), 7u);
    EXPECT_EQ(run.report.Requests(), 2u);
    EXPECT_EQ(run.report.AxisJobs(), 5u);
    EXPECT_NE(out.find("Result: 16 steps, 7 commands, 2 mode requests, 5 axis jobs: all expectations met"), std::string::npos) << out;
    // N3 := 333 and its reply, byte for byte as in the corrected Interbus example of the manual (4.2.4) but for
    // the SEND flag: 0 here, since the cold start's parked read (190B) went out with SEND 1 before it; the
    // module is parked (190B, the SEND flag kept) in the scan that sees the reply.
    EXPECT_NE(out.find("| 00 00 01 4D 00 03 09 06 |"), std::string::npos) << out;
    EXPECT_NE(out.find("| 00 00 00 00 00 00 19 0B | 00 00 01 4D 00 01 20 00 |"), std::string::npos) << out;
    // R1 = 640.0 is 44 20 00 00 (docs/manual_errata.md), printed as a REAL because the step expects one.
    EXPECT_NE(out.find("| 44 20 00 00 00 01 20 00 |"), std::string::npos) << out;
    EXPECT_NE(out.find("AckData 640.0 (16#44200000): as expected"), std::string::npos) << out;
    EXPECT_NE(out.find("ErrorID 38 PAC_ERR_N_REGISTER \"inadmissible N register\""), std::string::npos) << out;
    // The power cycle: the reply drops to zero, the idle FB parks the module, the boot ends.
    EXPECT_NE(out.find("| 00 00 00 00 00 00 19 0B | 00 00 00 00 00 00 00 00 |"), std::string::npos) << out;
    // ONLINE through FB_PAC_Ctrl: Start ONLINE (bit 4) with Stop, Cancel and Error reset held at 1,
    // then the status word shows ONLINE active (bit 10); Cancel is bit 2 taken to 0.
    EXPECT_NE(out.find("| 00 17 00 00 00 00 00 00 | 00 03 00 00 00 00 00 00 | 16#0017 16#0003"), std::string::npos) << out;
    EXPECT_NE(out.find("| 00 07 00 00 00 00 00 00 | 04 03 00 00 00 00 00 00 | 16#0007 16#0403"), std::string::npos) << out;
    EXPECT_NE(out.find("| 00 03 00 00 00 00 00 00 | 04 03 00 00 00 00 00 00 | 16#0003 16#0403"), std::string::npos) << out;
    EXPECT_NE(out.find("AckData 31 (16#0000001F): as expected"), std::string::npos) << out;
    // Axis 1 before its reference run: Axis ON + Start + absolute (16#45) with 10.0, refused with
    // CMD error 43 (status bit 14); the reference run then ends Done although bit 14 was still set.
    EXPECT_NE(out.find("|    1 | 16#00000045 1000 1000     10.000 |"), std::string::npos) << out;
    EXPECT_NE(out.find("| 16#00004601     43     0      0.000 |"), std::string::npos) << out;
    // The refused move (step 10): CMD error 43 answers the Start edge in the PA-CONTROL's take-over cycle.
    const pac::test::BusTiming bus = BusOf(run.scenario);
    const pac::test::ProtocolWindow protocol(bus);
    ASSERT_EQ(run.report.steps[9].axes.size(), 1u);
    const auto& refused = run.report.steps[9].axes[0];
    const pac::test::ScanWindow answer = protocol.Request(TimeOfScan(run.scenario, refused.edgeScan));
    EXPECT_TRUE(answer.Contains(refused.endScan - refused.edgeScan))
        << refused.endScan - refused.edgeScan << " scans, the protocol allows " << answer;
    EXPECT_NE(out.find(AxisLine(refused, "Error") + "; ErrorID 43 PAC_ERR_NO_REFERENCE"), std::string::npos) << out;
    // Axis 1 to 50.0 at 500 per mille of the traverse speed (axis parameter 1: 1000 AE/s) with the full
    // acceleration (axis parameter 6: 10000 AE/s^2), from where the reference run left it (step 11).
    ASSERT_EQ(run.report.steps[10].axes.size(), 2u);
    ASSERT_EQ(run.report.steps[11].axes.size(), 2u);
    const auto& moved = run.report.steps[11].axes[0];
    const double distance = 50.0 - run.report.steps[10].axes[0].position;
    const pac::test::ScanWindow move = MoveWindow(bus, MoveTime(distance, 500.0, 10000.0));
    EXPECT_TRUE(move.Contains(moved.endScan - moved.edgeScan))
        << moved.endScan - moved.edgeScan << " scans, the move allows " << move;
    EXPECT_NE(out.find(AxisLine(moved, "Done") + "; position 50.000, referenced"), std::string::npos) << out;
    for (const auto& step : run.report.steps) {
        if (!step.outcome) continue;
        EXPECT_TRUE(step.outcome->finished);
        const pac::test::ScanWindow w = protocol.Request(step.outcome->edgeTime);
        EXPECT_TRUE(w.Contains(step.outcome->endScan - step.outcome->edgeScan))
            << "step " << step.index + 1 << ": " << step.outcome->endScan - step.outcome->edgeScan
            << " scans, the protocol allows " << w;
    }
}

// The CMD interface's handshake history (docs/fb/FB_PAC_Cmd.md) is in the report and printed at the end:
// one entry per command sent, in order, with what the FB saw of it.
TEST(ScenarioRunner, TheHandshakeHistoryShowsEveryCommandSent) {
    const ScenarioRun run(FromFile("demo.json"));
    std::vector<std::size_t> commands;
    for (const auto& step : run.report.steps) {
        if (step.outcome) commands.push_back(step.index);
    }
    ASSERT_EQ(run.report.handshakes, commands.size()) << "every command of the demo is sent";
    ASSERT_EQ(run.report.history.size(), commands.size());
    for (std::size_t i = 0; i < commands.size(); ++i) {
        SCOPED_TRACE("step " + std::to_string(commands[i] + 1));
        const auto& sent = std::get<pac::scenario::CommandStep>(run.scenario.steps[commands[i]].action);
        const auto& outcome = *run.report.steps[commands[i]].outcome;
        const auto& h = run.report.history[i];
        EXPECT_EQ(h.code, sent.code);
        EXPECT_EQ(h.param, sent.param);
        EXPECT_EQ(h.data, sent.data.bits);
        EXPECT_EQ(h.errorId, outcome.errorId);
        EXPECT_EQ(h.ackData, outcome.ackData);
        EXPECT_EQ(h.scansToEnd, outcome.endScan - outcome.edgeScan);
        EXPECT_GE(h.scansToAck, 1);
        EXPECT_LE(h.scansToAck, h.scansToEnd);
    }
    const std::string& out = run.timeline.str();
    const std::string heading = "CMD handshake history (Channel.History): the last " + std::to_string(commands.size()) +
                                " of " + std::to_string(commands.size());
    EXPECT_NE(out.find(heading), std::string::npos) << out;
    EXPECT_LT(out.find(heading), out.find("Result: ")) << "before the result line";
    EXPECT_NE(out.find("  16#0906      3  16#0000014D       0  16#0000014D"), std::string::npos) << out;
}

// "diagnosis": FB_PAC_Diagnosis on the channel reads by command only what no module carries.
TEST(ScenarioRunner, DiagnosisExampleReadsTheAxesThenTheSystemError) {
    const ScenarioRun run(FromFile("examples/diag_poll.json"));
    ASSERT_TRUE(run.report.Passed()) << run.timeline.str();
    std::vector<int> axesRead(3, 0);
    int errorReads = 0;
    for (const auto& h : run.report.history) {
        if (h.code == 0x1910 && h.param >= 1 && h.param <= 2) {
            ++axesRead[h.param];
        } else if (h.code == 0x1909) {
            ++errorReads;
            EXPECT_EQ(h.ackData, 529u);
        } else {
            EXPECT_EQ(h.code, 0x1906) << "a command the scenario did not ask for";
        }
    }
    EXPECT_GE(axesRead[1], 1);
    EXPECT_GE(axesRead[2], 1);
    EXPECT_GE(errorReads, 1);
    EXPECT_NE(run.timeline.str().find("FB_PAC_Diagnosis on the CMD channel (Axes 2, PollTime 20 ms)"), std::string::npos)
        << run.timeline.str();
}

TEST(ScenarioRunner, DiagnosisWithEveryValueInAModuleSendsNoCommand) {
    const ScenarioRun run(FromText(R"({"modules": {"ctrl": true, "axes": 2, "diagnosis": {"axes": 2, "poll_ms": 5}},
        "steps": [{"wait_ms": 300}, {"fault": "system_error", "number": 529}, {"wait_ms": 100},
                  {"command": "PAC_CMD_GET_INT_REG", "param": 3, "expect": {"done": true}}]})"));
    ASSERT_TRUE(run.report.Passed()) << run.timeline.str();
    EXPECT_EQ(run.report.handshakes, 1u) << run.timeline.str();
}

TEST(ScenarioRunner, LinkFaultExampleMeetsEveryExpectation) {
    const ScenarioRun run(FromFile("examples/link_faults.json"));
    EXPECT_TRUE(run.report.Passed()) << run.timeline.str();
    EXPECT_EQ(run.report.Commands(), 5u);
}

TEST(ScenarioRunner, ModesExampleMeetsEveryExpectation) {
    const ScenarioRun run(FromFile("examples/modes.json"));
    const std::string& out = run.timeline.str();
    EXPECT_TRUE(run.report.Passed()) << out;
    EXPECT_EQ(run.report.Requests(), 10u);
    // The external stop input dropped: ONLINE stopped (bit 11) in the integer format (bit 15).
    EXPECT_NE(out.find("| 16#8007 16#8803        0 |"), std::string::npos) << out;
    // System error 600 (16#0258) in word 2 of the status module, with ONLINE stopped and bit 2.
    EXPECT_NE(out.find("| 88 07 00 00 02 58 00 00 | 16#0007 16#8807      600 |"), std::string::npos) << out;
    // Error reset: bit 0 taken to 0 (16#0006) until the system error bit clears.
    EXPECT_NE(out.find("| 00 06 00 00 00 00 00 00 | 80 07 00 00 00 96 00 00 | 16#0006 16#8007      150 |"),
              std::string::npos)
        << out;
}

// A limit switch of the controller setup stops the move on it with axis error 64; a reset_error job holds
// ResetError until the axis error bit is seen 0 (bit 16 in the control word meanwhile), and the axis can
// move away from the switch.
TEST(ScenarioRunner, LimitSwitchExampleStopsOnTheSwitchAndResetsTheAxisError) {
    const ScenarioRun run(FromFile("examples/axis_limit_switch.json"));
    const std::string& out = run.timeline.str();
    ASSERT_TRUE(run.report.Passed()) << out;
    const auto& stopped = run.report.steps[3].axes.at(0);
    EXPECT_TRUE(stopped.error);
    EXPECT_EQ(stopped.position, 30.0);
    const auto& reset = run.report.steps[4].axes.at(0);
    EXPECT_TRUE(reset.finished);
    EXPECT_FALSE(reset.hasJob) << "a reset is not an axis job";
    EXPECT_NE(out.find("controller: input 1 = 1, system parameter 4 = 1, axis 1 limit switches: negative at -50.000, positive at 30.000"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("axis 1: ResetError"), std::string::npos) << out;
    EXPECT_NE(out.find(AxisLine(reset, "axis error reset")), std::string::npos) << out;
    // While the reset runs: control word Axis ON + bit 16 (and the last job's target), status with FAULT and the
    // axis error bit, number 64.
    EXPECT_NE(out.find("16#00010001 1000 1000    100.000 | 16#00008343      0    64     30.000"), std::string::npos) << out;
    EXPECT_EQ(run.report.AxisJobs(), 2u);
}

// Two axes under the MC_ blocks: both moves end at their targets with the user-unit velocities as per mille on the
// wire (Start with the absolute / relative bit), MC_Home references axis 1, and a velocity the module cannot carry
// is refused in the scan its Execute rose.
TEST(ScenarioRunner, McBlocksExampleMovesTwoAxes) {
    const ScenarioRun run(FromFile("examples/mc_two_axes.json"));
    const std::string& out = run.timeline.str();
    ASSERT_TRUE(run.report.Passed()) << out;
    EXPECT_NE(out.find("FB_PAC_McAxis and the MC_ blocks on each axis module"), std::string::npos) << out;
    EXPECT_NE(out.find("|    1 | 16#00000045 1000  500    100.000 |"), std::string::npos) << out;
    EXPECT_NE(out.find("|    2 | 16#00000085 1000  250     30.000 |"), std::string::npos) << out;
    const auto& moves = run.report.steps[3].axes;
    EXPECT_EQ(moves.at(0).position, 100.0);
    EXPECT_EQ(moves.at(1).position, 30.0);
    EXPECT_TRUE(run.report.steps[4].axes.at(0).referenced);
    const auto& refused = run.report.steps[5].axes.at(0);
    EXPECT_EQ(refused.errorId, 0x800Bu);
    EXPECT_EQ(refused.endScan, refused.edgeScan) << "refused in the edge scan";
    EXPECT_EQ(run.report.AxisJobs(), 6u);
}

TEST(ScenarioRunner, AutomaticExampleMeetsEveryExpectation) {
    const ScenarioRun run(FromFile("examples/automatic.json"));
    const std::string& out = run.timeline.str();
    EXPECT_TRUE(run.report.Passed()) << out;
    EXPECT_EQ(run.report.Requests(), 5u);
    // R1 = 12.345 goes out as 12345 in the integer format; the program's R17 := R1 * 2 comes back as 24690.
    EXPECT_NE(out.find("| 16#0000         -5     12.345 | 16#0000         -4     24.690\n"), std::string::npos) << out;
}

TEST(ScenarioRunner, AnAutomaticExpectationNotMetSaysWhatWasReceived) {
    const ScenarioRun run(FromText(R"({"timing": {"boot_ms": 0}, "modules": {"ctrl": true, "axes": 1},
        "steps": [{"automatic": [{"module": 1, "n": 5, "expect": {"n": 6}}], "max_ms": 50}]})"));
    EXPECT_FALSE(run.report.Passed()) << "home position: nothing is exchanged";
    EXPECT_EQ(run.report.steps[0].failures, (std::vector<std::string>{"module 1: N 0, expected 6"}));
}

TEST(ScenarioRunner, RunsAreDeterministic) {
    const Scenario demo = FromFile("demo.json");
    const ScenarioRun first(demo);
    const ScenarioRun second(demo);
    EXPECT_EQ(first.timeline.str(), second.timeline.str());
}

TEST(ScenarioRunner, AFailedExpectationSaysWhatWasSeen) {
    const ScenarioRun run(FromText(R"({"timing": {"boot_ms": 0}, "steps": [
        {"command": "PAC_CMD_PUT_INT_REG", "param": 3, "data": 333, "expect": {"done": true}},
        {"command": "PAC_CMD_GET_INT_REG", "param": 3, "expect": {"done": true, "ack_data": 334}},
        {"command": "PAC_CMD_GET_INT_REG", "param": 2000, "expect": {"done": true, "error_id": 0}},
        {"command": "PAC_CMD_GET_FLOAT_REG", "param": 1, "expect": {"ack_data": {"real": 640.0}}}]})"));
    EXPECT_FALSE(run.report.Passed());
    EXPECT_EQ(run.report.FailedSteps(), (std::vector<std::size_t>{1, 2, 3}));
    EXPECT_EQ(run.report.steps[1].failures, (std::vector<std::string>{"AckData is 333 (16#0000014D), expected 334 (16#0000014E)"}));
    EXPECT_EQ(run.report.steps[2].failures,
              (std::vector<std::string>{"Done is FALSE, expected TRUE", "ErrorID is 38, expected 0"}));
    EXPECT_EQ(run.report.steps[3].failures,
              (std::vector<std::string>{"AckData is 0.0 (16#00000000), expected 640.0 (16#44200000)"}));
    const std::string& out = run.timeline.str();
    EXPECT_NE(out.find("  => FAILED: AckData is 333 (16#0000014D), expected 334 (16#0000014E)\n"), std::string::npos) << out;
    EXPECT_NE(out.find("Result: 4 steps, 4 commands: 3 steps FAILED (step 2, 3, 4)"), std::string::npos) << out;
}

TEST(ScenarioRunner, ControllerSetupIsThereBeforeTheFirstScan) {
    const ScenarioRun run(FromText(R"({"timing": {"boot_ms": 0},
        "controller": {"operating_status": "PAC_STATUS_ONLINE", "n_registers": {"9": -2},
                       "r_registers": {"4": 0.1}, "inputs": {"17": true}},
        "steps": [
          {"command": "PAC_CMD_GET_STAT", "expect": {"done": true, "ack_data": 31}},
          {"command": "PAC_CMD_GET_INT_REG", "param": 9, "expect": {"ack_data": -2}},
          {"command": "PAC_CMD_GET_FLOAT_REG", "param": 4, "expect": {"ack_data": {"real": 0.1}}},
          {"command": "PAC_CMD_GET_SINGLE_INPUT", "param": 17, "expect": {"ack_data": 1}},
          {"command": "PAC_CMD_GET_INPUT_WORD", "param": 17, "expect": {"ack_data": 1}}]})"));
    EXPECT_TRUE(run.report.Passed()) << run.timeline.str();
    EXPECT_NE(run.timeline.str().find("controller: boots into status 31 PAC_STATUS_ONLINE, N9 = -2, R4 = 0.1 "
                                      "(16#3DCCCCCD), input 17 = 1"),
              std::string::npos)
        << run.timeline.str();
}

TEST(ScenarioRunner, TheFbRefusesWhatItMustRefuse) {
    const ScenarioRun run(FromText(R"({"steps": [
        {"command": "PAC_CMD_GET_STAT", "note": "still booting",
         "expect": {"error": true, "error_id": "PAC_LIB_ERR_NOT_READY"}},
        {"wait_ms": 60},
        {"command": "8906", "note": "bit 15 is the SEND flag", "expect": {"error": true, "error_id": "16#8005"}},
        {"command": "7777", "note": "no such command", "expect": {"error": true, "error_id": "PAC_ERR_UNKNOWN_COMMAND"}}
        ]})"));
    EXPECT_TRUE(run.report.Passed()) << run.timeline.str();
    // Refused at the edge: Error in the very scan in which Execute rose.
    EXPECT_EQ(run.report.steps[0].outcome->endScan, run.report.steps[0].outcome->edgeScan);
    EXPECT_EQ(run.report.steps[2].outcome->endScan, run.report.steps[2].outcome->edgeScan);
    EXPECT_NE(run.timeline.str().find("step 4 at 64 ms: command (16#7777), Param 0  -- no such command"),
              std::string::npos)
        << run.timeline.str();
}

TEST(ScenarioRunner, WaitsScanWholePlcCyclesAndPrintOnlyChanges) {
    const ScenarioRun run(FromText(R"({"timing": {"plc_cycle_ms": 4, "boot_ms": 10}, "steps": [{"wait_ms": 401}]})"));
    EXPECT_TRUE(run.report.Passed());
    const std::string& out = run.timeline.str();
    EXPECT_NE(out.find("wait 401 ms (101 scans)"), std::string::npos) << out;
    // The first scan (booting: zeros), the scan that sees the boot's reply and toggles the cold start's parked
    // read (190B, SEND 1), and the scan that sees its acknowledgement; nothing changes after.
    EXPECT_EQ(ScanLines(out), 3) << out;
    // The boot ends at 10 ms; the PA-CONTROL's first cycle from then (10 ms cycles, the default) writes
    // its reply, which the first scan from then on reads (4 ms cycles, no latency): scan 3 at 12 ms.
    const Scenario& s = run.scenario;
    const int firstReply = (s.timing.bootMs + s.timing.pacCycleMs - 1) / s.timing.pacCycleMs * s.timing.pacCycleMs +
                           s.timing.latencyCycles * s.timing.plcCycleMs;
    const int scan = (firstReply + s.timing.plcCycleMs - 1) / s.timing.plcCycleMs;
    std::ostringstream line;
    line << std::setw(8) << scan * s.timing.plcCycleMs << std::setw(7) << scan
         << " | 00 00 00 00 00 00 99 0B | 00 00 00 00 00 01 20 00 |";
    EXPECT_NE(out.find(line.str()), std::string::npos) << line.str() << "\n" << out;
}

TEST(ScenarioRunner, LinkFaultsActOnTheirDirection) {
    // ToPac zeroed: the PA-CONTROL sees an all-zero module (EMERGENCY STOP) and no command; the FB
    // times out (16#8001: sent, outcome unknown). FB_PAC_CmdInterface then parks the module and brings
    // SEND back to RECEIVE, so when the link thaws the timed-out command is withdrawn, not carried out
    // late: N5 stays 0.
    const ScenarioRun run(FromText(R"({"timing": {"boot_ms": 0}, "steps": [
        {"wait_ms": 20},
        {"fault": "zero_link", "link": "to_pac"},
        {"command": "PAC_CMD_PUT_INT_REG", "param": 5, "data": 55, "timeout_ms": 30,
         "expect": {"error": true, "error_id": "PAC_LIB_ERR_ACK_TIMEOUT"}},
        {"fault": "thaw_link", "link": "to_pac"},
        {"wait_ms": 30},
        {"command": "PAC_CMD_GET_INT_REG", "param": 5, "expect": {"done": true, "ack_data": 0}}]})"));
    EXPECT_TRUE(run.report.Passed()) << run.timeline.str();
}

TEST(ScenarioRunner, JitteredBusStillMeetsTheDemo) {
    Scenario demo = FromFile("demo.json");
    for (std::uint64_t seed : {3u, 4u, 5u}) {
        demo.timing.jitterMs = 3;
        demo.timing.seed = seed;
        const ScenarioRun run(demo);
        EXPECT_TRUE(run.report.Passed()) << "seed " << seed << "\n" << run.timeline.str();
        EXPECT_NE(run.timeline.str().find("+ jitter up to 3 ms (seed " + std::to_string(seed) + ")"), std::string::npos);
    }
}

// Zeros from the PA-CONTROL read as operating status 0: the FB sends nothing until they are gone.
TEST(ScenarioRunner, ZeroedRepliesHoldBackCommandsUntilThawed) {
    const ScenarioRun run(FromText(R"({"timing": {"plc_cycle_ms": 1, "pac_cycle_ms": 10, "latency_cycles": 3, "boot_ms": 0},
        "steps": [
          {"wait_ms": 5},
          {"fault": "zero_link", "link": "from_pac"},
          {"command": "PAC_CMD_GET_STAT", "expect": {"error": true, "error_id": "PAC_LIB_ERR_NOT_READY"}},
          {"fault": "thaw_link"},
          {"wait_ms": 5},
          {"command": "PAC_CMD_GET_STAT", "expect": {"done": true, "ack_data": 1}}]})"));
    EXPECT_TRUE(run.report.Passed()) << run.timeline.str();
}

}  // namespace

TEST(ScenarioRunner, ACtrlRequestTheControllerIgnoresEndsInTheFbsTimeout) {
    // No external stop input (system parameter 4 is 0): the PA-CONTROL ignores Start ONLINE on the
    // CTRL interface, which has no error channel, so FB_PAC_Ctrl ends with 16#8009 after Timeout.
    const ScenarioRun run(FromText(R"({"timing": {"boot_ms": 0, "plc_cycle_ms": 2}, "modules": {"ctrl": true},
      "steps": [{"ctrl": "PAC_REQ_START_ONLINE", "timeout_ms": 100,
                 "expect": {"error": true, "error_id": "PAC_LIB_ERR_REQUEST_TIMEOUT"}},
                {"ctrl": "PAC_REQ_STOP", "expect": {"error": true, "error_id": "PAC_LIB_ERR_NOT_ALLOWED"}}]})"));
    const std::string& out = run.timeline.str();
    EXPECT_TRUE(run.report.Passed()) << out;
    ASSERT_TRUE(run.report.steps[0].request.has_value());
    const auto& timeout = *run.report.steps[0].request;
    // Timeout 100 ms: the TON's Q shows in the first scan at least 100 ms after the edge's.
    const int timeoutScans = pac::test::ProtocolWindow(BusOf(run.scenario)).TimeoutScans(std::chrono::milliseconds(100));
    EXPECT_EQ(timeout.endScan - timeout.edgeScan, timeoutScans) << out;
    EXPECT_EQ(run.report.steps[1].request->endScan, run.report.steps[1].request->edgeScan) << "refused in the edge scan";
    EXPECT_NE(out.find("ErrorID 16#8009 PAC_LIB_ERR_REQUEST_TIMEOUT"), std::string::npos) << out;
}

TEST(ScenarioRunner, AnAxisExpectationNotMetSaysWhatWasSeen) {
    const ScenarioRun run(FromText(R"({"timing": {"boot_ms": 0}, "modules": {"ctrl": true, "axes": 1},
      "controller": {"inputs": {"1": true}, "system_parameters": {"4": 1}},
      "steps": [{"ctrl": "PAC_REQ_START_ONLINE", "expect": {"done": true}},
                {"axes": [{"axis": 1, "enable": true, "command": "PAC_AX_MOVE_RELATIVE", "position": 5.0,
                           "expect": {"done": true, "position": 5.5, "referenced": false}}]}]})"));
    const std::string& out = run.timeline.str();
    EXPECT_FALSE(run.report.Passed()) << out;
    EXPECT_EQ(run.report.FailedSteps(), std::vector<std::size_t>{1}) << out;
    EXPECT_NE(out.find("  => FAILED: axis 1: Referenced is TRUE, expected FALSE\n"), std::string::npos) << out;
    EXPECT_NE(out.find("  => FAILED: axis 1: ActualPosition is 5.0000, expected 5.5000 +- 0.001\n"), std::string::npos)
        << out;
}
