// Runs a Scenario against the simulated PA-CONTROL: one FB_PAC_Cmd of the library on the CMD
// interface of a PLC task (pac::PacRig: simulated clock, bus with latency and jitter, the
// controller at its own cycle), one FB_PAC_Ctrl on the CTRL interface and one FB_PAC_Axis on each
// axis module where the scenario has them. Commands, requests and axis jobs raise Execute and hold
// it until the job ends, then drop it for one scan; faults act between two scans; waits scan. An
// observer sees every scan and step.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pac/sim/image8.hpp"
#include "pac/sim/process_image.hpp"
#include "scenario.hpp"

namespace pac::scenario {

// The CTRL interface and FB_PAC_Ctrl after one scan.
struct CtrlSample {
    pac::sim::Image8 toPac{};
    pac::sim::Image8 fromPac{};
    bool execute = false;
    bool busy = false;
    bool done = false;
    bool error = false;
    std::uint16_t errorId = 0;
};

// One axis module and its FB_PAC_Axis after one scan.
struct AxisSample {
    int axis = 1;
    pac::sim::Image12 toPac{};
    pac::sim::Image12 fromPac{};
    bool enable = false;
    bool execute = false;
    bool busy = false;
    bool done = false;
    bool error = false;
    bool aborted = false;
    std::uint16_t errorId = 0;
    bool enabled = false;
    bool resetError = false;
    float actualPosition = 0.0F;
    bool integerMode = false;  // how the module's positions are coded
    double simPosition = 0.0;  // where the simulated axis really is (axis coordinates)
};

// FB_PAC_Diagnosis after one scan.
struct DiagSample {
    bool valid = false;
    bool busy = false;
    bool error = false;
    std::uint16_t errorId = 0;
    std::uint8_t opStatus = 0;
    std::uint16_t systemErrorNumber = 0;
    std::uint32_t changeCount = 0;
    std::uint32_t historyCount = 0;
};

// The modules and their FBs after one scan.
struct ScanSample {
    std::chrono::nanoseconds time{0};
    std::int64_t scan = 0;
    pac::sim::Image8 toPac{};    // the PLC's module as it goes out at the end of the scan
    pac::sim::Image8 fromPac{};  // the PA-CONTROL's reply as the scan read it
    bool execute = false;
    bool busy = false;
    bool done = false;
    bool error = false;
    std::uint16_t errorId = 0;
    std::uint32_t ackData = 0;
    std::optional<CtrlSample> ctrl;  // where the scenario has the CTRL interface
    std::vector<AxisSample> axes;    // one per axis module
    std::optional<DiagSample> diag;  // where the scenario has FB_PAC_Diagnosis
};

// How one command ended.
struct CommandOutcome {
    bool finished = false;  // Done or Error came within the runner's bound (Timeout + EndTimeout + margin)
    bool done = false;
    bool error = false;
    std::uint16_t errorId = 0;
    std::uint32_t ackData = 0;
    std::int64_t edgeScan = 0;  // the scan in which Execute rose
    std::int64_t endScan = 0;   // the scan that showed Done or Error (the last one tried if !finished)
    std::chrono::nanoseconds edgeTime{0};
    std::chrono::nanoseconds endTime{0};
};

// How one axis of an axes step ended: its job's final outputs, or, without a job, Enabled following
// Enable.
struct AxisOutcome {
    int axis = 1;
    bool hasJob = false;
    bool finished = false;  // the job ended (Done, Error, CommandAborted), or Enabled = Enable, within max_ms
    bool done = false;
    bool error = false;
    bool aborted = false;
    std::uint16_t errorId = 0;
    bool enabled = false;
    bool referenced = false;
    double position = 0.0;
    std::int64_t edgeScan = 0;
    std::int64_t endScan = 0;
    std::chrono::nanoseconds endTime{0};
};

struct StepReport {
    std::size_t index = 0;                  // into Scenario::steps
    std::optional<CommandOutcome> outcome;  // command steps
    std::optional<CommandOutcome> request;  // ctrl steps (AckData unused)
    std::vector<AxisOutcome> axes;          // axes steps
    std::vector<std::string> failures;      // expectations not met
    bool Passed() const { return failures.empty(); }
};

// One handshake of the CMD interface's history (ST_PAC_Handshake, docs/fb/FB_PAC_Cmd.md).
struct HandshakeRecord {
    std::uint16_t code = 0;
    std::uint16_t param = 0;
    std::uint32_t data = 0;
    std::uint32_t ackData = 0;
    std::uint16_t errorId = 0;  // 0 after Done
    std::int32_t scansToAck = -1;  // from the Execute edge; -1: never acknowledged
    std::int32_t scansToEnd = 0;   // from the Execute edge to the final output
};

struct RunReport {
    std::vector<StepReport> steps;
    std::vector<HandshakeRecord> history;  // the channel's last 16 handshakes at the end, oldest first
    std::uint32_t handshakes = 0;          // handshakes recorded in the whole run

    std::size_t Commands() const;   // command steps run
    std::size_t Requests() const;   // ctrl steps run
    std::size_t AxisJobs() const;   // axis jobs run (an axis that only changed Enable is not one)
    std::vector<std::size_t> FailedSteps() const;  // indices into Scenario::steps
    bool Passed() const { return FailedSteps().empty(); }
};

class RunObserver {
public:
    virtual ~RunObserver() = default;
    virtual void OnStart(const Scenario& /*scenario*/) {}
    virtual void OnStepStart(std::size_t /*index*/, const Step& /*step*/, std::chrono::nanoseconds /*now*/) {}
    virtual void OnScan(const ScanSample& /*sample*/) {}
    virtual void OnStepEnd(const StepReport& /*report*/) {}
    virtual void OnEnd(const RunReport& /*report*/) {}
};

// A PA-CONTROL outside the process (pac-sim over Modbus TCP, docs/virtual_commissioning.md): the PLC's process
// image goes through it at the start and the end of each scan, and the scenario's faults act on it.
class RemoteController {
public:
    virtual ~RemoteController() = default;
    virtual void ReadFromPac(std::chrono::nanoseconds now, pac::sim::ProcessImage& fromPac) = 0;
    virtual void WriteToPac(std::chrono::nanoseconds now, const pac::sim::ProcessImage& toPac) = 0;
    virtual void InjectFault(const FaultStep& fault) = 0;
};

class ScenarioRunner {
public:
    // With `remote`, the FBs drive that controller instead of the simulated one in the process (whose state,
    // AxisSample::simPosition, then tells nothing).
    explicit ScenarioRunner(const Scenario& scenario, RemoteController* remote = nullptr)
        : scenario_(scenario), remote_(remote) {}

    // Each call runs on a fresh PLC and PA-CONTROL, from time 0. A controller setup the simulator
    // rejects (a system parameter it does not have, a value outside its limits) is a ScenarioError,
    // thrown before the observer hears of the run.
    RunReport Run(RunObserver& observer) const;
    RunReport Run() const;

private:
    const Scenario& scenario_;
    RemoteController* remote_;
};

}  // namespace pac::scenario
