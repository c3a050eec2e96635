// A scenario: the timing of PLC, bus and PA-CONTROL, the Profibus modules, the controller's state
// before the first scan, and the steps to run one after the other (commands through FB_PAC_Cmd,
// mode requests through FB_PAC_Ctrl, axis jobs through FB_PAC_Axis, faults, waits). Plain data;
// ScenarioLoader builds it from a JSON file and refuses anything it cannot represent
// (docs/scenario.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace pac::scenario {

struct Timing {
    int plcCycleMs = 1;
    int pacCycleMs = 10;
    int latencyCycles = 0;  // bus latency each way, in PLC cycles
    int jitterMs = 0;       // extra delay of each image, uniform in [0, jitter], seeded
    std::uint64_t seed = 1;
    int bootMs = 50;  // the PA-CONTROL's boot after power-on: status 0, all-zero reply
};

// FB_PAC_Diagnosis on the CMD channel, after the other FBs, Enable TRUE from the first scan.
struct DiagnosisSetup {
    int axes = 0;      // FB_PAC_Diagnosis.Axes, 0..8
    int pollMs = 500;  // FB_PAC_Diagnosis.PollTime
};

// The Profibus modules besides the CMD interface (manual 2.3): the CTRL interface and 0..8 axis
// modules (which need the CTRL interface), and the diagnosis FB that watches them.
struct Modules {
    bool ctrl = false;
    int axes = 0;
    bool mcBlocks = false;  // the axis modules run FB_PAC_McAxis and the PLCopen MC_ blocks, not FB_PAC_Axis
    std::optional<DiagnosisSetup> diagnosis;
};

// Hardware limit switches of one axis, at machine positions (none fitted where empty).
struct LimitSwitches {
    std::optional<double> negative;
    std::optional<double> positive;
};

// The controller before the first scan. Registers and inputs not named keep the simulator's
// power-on values (0).
struct ControllerSetup {
    std::optional<std::uint8_t> operatingStatus;  // the status it boots into (default 1, home position)
    std::map<int, std::int32_t> intRegisters;     // N
    std::map<int, float> realRegisters;           // R
    std::map<int, bool> inputs;
    std::map<int, std::int32_t> systemParameters;  // 0700 values, e.g. 4: the external stop input
    bool axesReferenced = true;  // at power-on (an absolute measuring system); false: G25 first
    std::map<int, LimitSwitches> limitSwitches;  // per axis 1..8
    std::vector<std::string> automaticProgram;  // the stand-in AUTOMATIC program's lines ("R17 := R1 * 2")
};

// A DWORD as the scenario wrote it: an integer, or a REAL carried as its IEEE-754 bits.
struct DwordValue {
    std::uint32_t bits = 0;
    bool isReal = false;
};

// What a command step must end with; an empty optional is not checked.
struct Expectation {
    std::optional<bool> done;
    std::optional<bool> error;
    std::optional<std::uint16_t> errorId;
    std::optional<DwordValue> ackData;

    bool Empty() const { return !done && !error && !errorId && !ackData; }
};

// One command through FB_PAC_Cmd: Execute rises with these inputs and stays TRUE until Done or
// Error; it falls in the scan after.
struct CommandStep {
    std::uint16_t code = 0;
    std::string name;  // the command's PAC_CMD_ name in GVL_PAC, empty if it has none
    std::uint16_t param = 0;
    DwordValue data;
    int timeoutMs = 1000;      // FB_PAC_Cmd.Timeout
    int endTimeoutMs = 60000;  // FB_PAC_Cmd.EndTimeout
    Expectation expect;
};

// One request through FB_PAC_Ctrl on the CTRL interface, run like a command step. `request` is the
// E_PAC_CtrlRequest name (PAC_REQ_START_ONLINE, ...). IntegerMode keeps its value for later steps.
struct CtrlStep {
    std::string request;
    bool integerMode = false;
    int timeoutMs = 10000;  // FB_PAC_Ctrl.Timeout
    Expectation expect;     // done, error, error_id (no ack_data)
};

// What an axis must show at the end of its job (or, without a job, once Enabled has followed Enable).
struct AxisExpectation {
    std::optional<bool> done;
    std::optional<bool> error;
    std::optional<bool> aborted;  // CommandAborted
    std::optional<std::uint16_t> errorId;
    std::optional<bool> referenced;
    std::optional<double> position;  // ActualPosition, within positionTolerance
    double positionTolerance = 0.001;

    bool Empty() const { return !done && !error && !aborted && !errorId && !referenced && !position; }
};

// One axis of an axes step: Enable (a level that stays for later steps) and optionally a job through
// FB_PAC_Axis, or a reset of its axis error (ResetError until AxisError is seen FALSE). `command` and
// `condition` are the E_PAC_AxisCommand / E_PAC_MoveCondition names. With Modules::mcBlocks: MC_Power's
// Enable, the MC_ block named by `command`, MC_Reset (until it ends); no condition.
struct AxisJob {
    int axis = 1;  // the axis module, 1..Modules::axes
    std::optional<bool> enable;
    std::string command;  // empty: no job, only Enable (or the reset)
    bool resetError = false;
    double position = 0.0;
    int velocity = 1000;      // per mille
    int acceleration = 1000;  // per mille
    std::string condition = "PAC_COND_NONE";
    int timeoutMs = 1000;  // FB_PAC_Axis.Timeout (take-over)
    int maxMs = 60000;     // the longest the runner waits for the job to end
    AxisExpectation expect;

    bool HasJob() const { return !command.empty(); }
};

// The MC_ blocks an axes step may name as its "command" with Modules::mcBlocks.
const std::vector<std::string>& McCommandNames();

// Axis jobs that run at the same time: every Execute rises in the same scan and stays TRUE until
// every job has ended (Done, Error or CommandAborted); then all fall for one scan.
struct AxesStep {
    std::vector<AxisJob> jobs;
};

// What FB_PAC_AutomaticModule of one module must have received (an empty optional is not checked).
struct AutomaticExpectation {
    std::optional<std::uint16_t> flagWord;  // FW 16+k
    std::optional<std::int32_t> n;          // N 16+k
    std::optional<double> r;                // R 16+k, within rTolerance
    double rTolerance = 0.001;

    bool Empty() const { return !flagWord && !n && !r; }
};

// The values FB_PAC_AutomaticModule of module k sends (FW k, N k, R k: levels that stay for later steps).
struct AutomaticValues {
    int module = 1;  // 1..Modules::axes
    std::optional<std::uint16_t> flagWord;
    std::optional<std::int32_t> n;
    std::optional<double> r;
    AutomaticExpectation expect;
};

// The modules in AUTOMATIC mode (manual 2.6): the values go out from the step's first scan; the step ends in
// the first scan in which every module has received what it expects, or after maxMs.
struct AutomaticStep {
    std::vector<AutomaticValues> modules;
    int maxMs = 1000;
};

enum class FaultKind { kPowerCycle, kFreezeLink, kThawLink, kZeroLink, kSystemError, kSetInput };
enum class LinkSide { kToPac, kFromPac, kBoth };

// Acts between two scans, at the time of the last scan.
struct FaultStep {
    FaultKind kind = FaultKind::kPowerCycle;
    LinkSide link = LinkSide::kBoth;  // link faults only
    int number = 0;                   // kSystemError: the error number (1..999); kSetInput: the input
    bool value = false;               // kSetInput: the input's new state
};

// Scans for at least `ms`, in whole PLC cycles.
struct WaitStep {
    int ms = 0;
};

struct Step {
    std::variant<CommandStep, CtrlStep, AxesStep, AutomaticStep, FaultStep, WaitStep> action;
    std::string note;  // printed with the step
};

// What `pac_scenario --wavedrom` draws: a window of steps, the signals as lanes in this order, and how
// much of a stretch without change it keeps (docs/scenario.md#traces-and-diagrams).
struct Diagram {
    std::string title;
    std::size_t firstStep = 1;  // 1-based, as the timeline numbers steps
    std::size_t lastStep = 0;   // 0: the last step of the scenario
    int contextScans = 1;       // scans before the first step's first scan
    int maxIdleScans = 3;       // longer runs of scans in which only sampled lanes change become one gap
    int hscale = 3;             // WaveDrom's horizontal scale: room for the data lanes' text
    std::vector<std::string> signals;  // trace paths; empty: every signal
    std::vector<std::string> sampled;  // signals whose changes alone keep no scan (REALs never do)
};

struct Scenario {
    std::string name;
    std::string description;
    Timing timing;
    Modules modules;
    ControllerSetup controller;
    std::vector<Step> steps;
    Diagram diagram;
};

const char* ToString(FaultKind kind);  // "power_cycle", "freeze_link", ...
const char* ToString(LinkSide side);   // "to_pac", "from_pac", "both"

}  // namespace pac::scenario
