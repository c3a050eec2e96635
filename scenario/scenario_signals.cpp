#include "scenario_signals.hpp"

#include <cstddef>
#include <utility>

#include "pac/axis_module_bits.hpp"
#include "pac/sim/cmd_frame.hpp"
#include "text_format.hpp"

namespace pac::scenario {

namespace {

struct NamedBit {
    const char* name;
    std::uint32_t mask;
};

// Control word of an axis (2.7.1), named as in the manual's list.
const NamedBit kAxisControlBits[] = {
    {"AxisON", axis_control::kAxisOn},           {"DisableDrive", axis_control::kDisableDrive},
    {"Start", axis_control::kStart},             {"G25", axis_control::kHome},
    {"G26", axis_control::kSetReferenced},       {"G29", axis_control::kSetPosition},
    {"Absolute", axis_control::kMoveAbsolute},   {"Relative", axis_control::kMoveRelative},
    {"WhileInput1", axis_control::kWhileInput1}, {"WhileInput0", axis_control::kWhileInput0},
    {"JogPlus", axis_control::kJogPositive},     {"JogMinus", axis_control::kJogNegative},
    {"DeleteG29", axis_control::kClearOffset},   {"ResetDisplaced", axis_control::kClearDisplaced},
    {"ToMaxRange", axis_control::kMoveToMax},    {"ToMinRange", axis_control::kMoveToMin},
    {"ResetAxisError", axis_control::kResetAxisError}, {"NoLimitSwitches", axis_control::kDisableLimitSwitches},
};

// Status word of an axis (2.7.2); the drive states in capitals as 2.7.4 writes them.
const NamedBit kAxisStatusBits[] = {
    {"DRIVE_ENABLED", axis_status::kDriveEnabled},   {"HALT", axis_status::kHalt},
    {"DRIVE_DISABLED", axis_status::kDriveDisabled}, {"SAFE", axis_status::kSafe},
    {"IDLE", axis_status::kIdle},                    {"DISABLED", axis_status::kDisabled},
    {"FAULT", axis_status::kFault},                  {"ACTIVE", axis_status::kActive},
    {"Referenced", axis_status::kReferenced},        {"NegLimitFree", axis_status::kNegativeLimitNotActuated},
    {"PosLimitFree", axis_status::kPositiveLimitNotActuated}, {"StoppedByG123", axis_status::kStoppedByCondition},
    {"Displaced", axis_status::kDisplaced},          {"GroupDisplaced", axis_status::kGroupDisplaced},
    {"CmdError", axis_status::kCmdError},            {"AxisError", axis_status::kAxisError},
};

// The CTRL interface's control word (2.5.1; bits 0..2 low-active) and status word (2.5.2), named as
// FB_PAC_Ctrl's pins name them.
const NamedBit kCtrlControlBits[] = {{"ErrorReset_n", 1U << 0}, {"Stop_n", 1U << 1},        {"Cancel_n", 1U << 2},
                                     {"StartAutomatic", 1U << 3}, {"StartOnline", 1U << 4}, {"IntegerMode", 1U << 15}};
const NamedBit kCtrlStatusBits[] = {{"Ready", 1U << 0},           {"BatteryOk", 1U << 1},
                                    {"SystemError", 1U << 2},     {"AutomaticActive", 1U << 8},
                                    {"AutomaticStopped", 1U << 9}, {"OnlineActive", 1U << 10},
                                    {"OnlineStopped", 1U << 11},  {"IntegerModeActive", 1U << 15}};

// The module as one 64-bit value, PAC byte 0 the most significant: the hex digits read as the bytes do.
std::uint64_t Bytes(const pac::sim::Image8& image) {
    std::uint64_t bits = 0;
    for (std::uint8_t byte : image) bits = bits << 8 | byte;
    return bits;
}

std::uint16_t Word(const pac::sim::Image8& image, int byte) {
    return static_cast<std::uint16_t>(image[static_cast<std::size_t>(byte)] << 8 | image[static_cast<std::size_t>(byte) + 1]);
}

const AxisSample& AxisOf(const ScanSample& s, int axis) { return s.axes.at(static_cast<std::size_t>(axis - 1)); }

const CtrlSample& CtrlOf(const ScanSample& s) { return s.ctrl.value(); }

}  // namespace

ScenarioSignals::ScenarioSignals(const Modules& modules, TraceRecorder& recorder) : recorder_(recorder) {
    AddCmd();
    if (modules.ctrl) AddCtrl();
    for (int axis = 1; axis <= modules.axes; ++axis) AddAxis(axis);
    if (modules.diagnosis) AddDiagnosis();
}

void ScenarioSignals::AddDiagnosis() {
    using pac::sim::CommandFrame;
    // The command the CMD module carries: the diagnosis's 1909 / 1910 are told from the others by it.
    Add("cmd.Code", ValueFormat::kHex, 16, [](const ScanSample& s) { return CommandFrame::Decode(s.toPac).code; });
    const std::string fb = "diag.FB_PAC_Diagnosis.";
    const auto d = [](const ScanSample& s) -> const DiagSample& { return s.diag.value(); };
    Add(fb + "Valid", ValueFormat::kBit, 1, [d](const ScanSample& s) { return d(s).valid; });
    Add(fb + "Busy", ValueFormat::kBit, 1, [d](const ScanSample& s) { return d(s).busy; });
    Add(fb + "Error", ValueFormat::kBit, 1, [d](const ScanSample& s) { return d(s).error; });
    Add(fb + "ErrorID", ValueFormat::kErrorId, 16, [d](const ScanSample& s) { return d(s).errorId; });
    Add(fb + "OpStatus", ValueFormat::kDecimal, 8, [d](const ScanSample& s) { return d(s).opStatus; });
    Add(fb + "SystemErrorNumber", ValueFormat::kDecimal, 16, [d](const ScanSample& s) { return d(s).systemErrorNumber; });
    Add(fb + "ChangeCount", ValueFormat::kDecimal, 32, [d](const ScanSample& s) { return d(s).changeCount; });
    Add(fb + "HistoryCount", ValueFormat::kDecimal, 32, [d](const ScanSample& s) { return d(s).historyCount; });
}

void ScenarioSignals::Add(const std::string& path, ValueFormat format, int width,
                          std::function<std::uint64_t(const ScanSample&)> read) {
    formats_[path] = format;
    recorder_.AddBits(path, width, [this, read = std::move(read)] { return read(*current_); });
}

void ScenarioSignals::AddReal(const std::string& path, std::function<double(const ScanSample&)> read) {
    formats_[path] = ValueFormat::kReal;
    recorder_.AddReal(path, [this, read = std::move(read)] { return read(*current_); });
}

void ScenarioSignals::AddCmd() {
    using pac::sim::CommandFrame;
    using pac::sim::ReplyFrame;
    Add("cmd.ToPac", ValueFormat::kBytes, 64, [](const ScanSample& s) { return Bytes(s.toPac); });
    Add("cmd.SEND", ValueFormat::kBit, 1, [](const ScanSample& s) { return CommandFrame::Decode(s.toPac).send; });
    Add("cmd.FromPac", ValueFormat::kBytes, 64, [](const ScanSample& s) { return Bytes(s.fromPac); });
    Add("cmd.RF", ValueFormat::kBit, 1, [](const ScanSample& s) { return ReplyFrame::Decode(s.fromPac).receiveFlag; });
    Add("cmd.KF", ValueFormat::kBit, 1, [](const ScanSample& s) { return ReplyFrame::Decode(s.fromPac).commandErrorFlag; });
    Add("cmd.BF", ValueFormat::kBit, 1, [](const ScanSample& s) { return ReplyFrame::Decode(s.fromPac).endOfProcessing; });
    Add("cmd.Status", ValueFormat::kDecimal, 8, [](const ScanSample& s) { return ReplyFrame::Decode(s.fromPac).operatingStatus; });
    const std::string fb = "cmd.FB_PAC_Cmd.";
    Add(fb + "Execute", ValueFormat::kBit, 1, [](const ScanSample& s) { return s.execute; });
    Add(fb + "Busy", ValueFormat::kBit, 1, [](const ScanSample& s) { return s.busy; });
    Add(fb + "Done", ValueFormat::kBit, 1, [](const ScanSample& s) { return s.done; });
    Add(fb + "Error", ValueFormat::kBit, 1, [](const ScanSample& s) { return s.error; });
    Add(fb + "ErrorID", ValueFormat::kErrorId, 16, [](const ScanSample& s) { return s.errorId; });
    Add(fb + "AckData", ValueFormat::kHex, 32, [](const ScanSample& s) { return s.ackData; });
}

void ScenarioSignals::AddCtrl() {
    Add("ctrl.ToPac", ValueFormat::kBytes, 64, [](const ScanSample& s) { return Bytes(CtrlOf(s).toPac); });
    Add("ctrl.FromPac", ValueFormat::kBytes, 64, [](const ScanSample& s) { return Bytes(CtrlOf(s).fromPac); });
    Add("ctrl.Control", ValueFormat::kHex, 16, [](const ScanSample& s) { return Word(CtrlOf(s).toPac, 0); });
    Add("ctrl.Status", ValueFormat::kHex, 16, [](const ScanSample& s) { return Word(CtrlOf(s).fromPac, 0); });
    Add("ctrl.SystemErrorNumber", ValueFormat::kDecimal, 16, [](const ScanSample& s) { return Word(CtrlOf(s).fromPac, 4); });
    for (const NamedBit& bit : kCtrlControlBits) {
        Add(std::string("ctrl.control.") + bit.name, ValueFormat::kBit, 1,
            [mask = bit.mask](const ScanSample& s) { return (Word(CtrlOf(s).toPac, 0) & mask) != 0; });
    }
    for (const NamedBit& bit : kCtrlStatusBits) {
        Add(std::string("ctrl.status.") + bit.name, ValueFormat::kBit, 1,
            [mask = bit.mask](const ScanSample& s) { return (Word(CtrlOf(s).fromPac, 0) & mask) != 0; });
    }
    const std::string fb = "ctrl.FB_PAC_Ctrl.";
    Add(fb + "Execute", ValueFormat::kBit, 1, [](const ScanSample& s) { return CtrlOf(s).execute; });
    Add(fb + "Busy", ValueFormat::kBit, 1, [](const ScanSample& s) { return CtrlOf(s).busy; });
    Add(fb + "Done", ValueFormat::kBit, 1, [](const ScanSample& s) { return CtrlOf(s).done; });
    Add(fb + "Error", ValueFormat::kBit, 1, [](const ScanSample& s) { return CtrlOf(s).error; });
    Add(fb + "ErrorID", ValueFormat::kErrorId, 16, [](const ScanSample& s) { return CtrlOf(s).errorId; });
}

void ScenarioSignals::AddAxis(int axis) {
    using pac::sim::ReadDword;
    using pac::sim::ReadWordAt;
    const std::string scope = "axis" + std::to_string(axis);
    auto sent = [axis](int byte, int width) {
        return [axis, byte, width](const ScanSample& s) -> std::uint64_t {
            const auto& module = AxisOf(s, axis).toPac;
            return width == 32 ? ReadDword(module, byte) : ReadWordAt(module, byte);
        };
    };
    auto received = [axis](int byte, int width) {
        return [axis, byte, width](const ScanSample& s) -> std::uint64_t {
            const auto& module = AxisOf(s, axis).fromPac;
            return width == 32 ? ReadDword(module, byte) : ReadWordAt(module, byte);
        };
    };
    Add(scope + ".Control", ValueFormat::kHex, 32, sent(0, 32));
    Add(scope + ".Acceleration", ValueFormat::kDecimal, 16, sent(4, 16));
    Add(scope + ".Speed", ValueFormat::kDecimal, 16, sent(6, 16));
    AddReal(scope + ".TargetPosition", [axis](const ScanSample& s) {
        const AxisSample& a = AxisOf(s, axis);
        return PositionValue(ReadDword(a.toPac, 8), a.integerMode);
    });
    Add(scope + ".Status", ValueFormat::kHex, 32, received(0, 32));
    Add(scope + ".CmdErrorNumber", ValueFormat::kDecimal, 16, received(4, 16));
    Add(scope + ".AxisErrorNumber", ValueFormat::kDecimal, 16, received(6, 16));
    AddReal(scope + ".Position", [axis](const ScanSample& s) {
        const AxisSample& a = AxisOf(s, axis);
        return PositionValue(ReadDword(a.fromPac, 8), a.integerMode);
    });
    for (const NamedBit& bit : kAxisControlBits) {
        Add(scope + ".control." + bit.name, ValueFormat::kBit, 1,
            [axis, mask = bit.mask](const ScanSample& s) { return (ReadDword(AxisOf(s, axis).toPac, 0) & mask) != 0; });
    }
    for (const NamedBit& bit : kAxisStatusBits) {
        Add(scope + ".status." + bit.name, ValueFormat::kBit, 1,
            [axis, mask = bit.mask](const ScanSample& s) { return (ReadDword(AxisOf(s, axis).fromPac, 0) & mask) != 0; });
    }
    const std::string fb = scope + ".FB_PAC_Axis.";
    Add(fb + "Enable", ValueFormat::kBit, 1, [axis](const ScanSample& s) { return AxisOf(s, axis).enable; });
    Add(fb + "Execute", ValueFormat::kBit, 1, [axis](const ScanSample& s) { return AxisOf(s, axis).execute; });
    Add(fb + "ResetError", ValueFormat::kBit, 1, [axis](const ScanSample& s) { return AxisOf(s, axis).resetError; });
    Add(fb + "Enabled", ValueFormat::kBit, 1, [axis](const ScanSample& s) { return AxisOf(s, axis).enabled; });
    Add(fb + "Busy", ValueFormat::kBit, 1, [axis](const ScanSample& s) { return AxisOf(s, axis).busy; });
    Add(fb + "Done", ValueFormat::kBit, 1, [axis](const ScanSample& s) { return AxisOf(s, axis).done; });
    Add(fb + "Error", ValueFormat::kBit, 1, [axis](const ScanSample& s) { return AxisOf(s, axis).error; });
    Add(fb + "CommandAborted", ValueFormat::kBit, 1, [axis](const ScanSample& s) { return AxisOf(s, axis).aborted; });
    Add(fb + "ErrorID", ValueFormat::kErrorId, 16, [axis](const ScanSample& s) { return AxisOf(s, axis).errorId; });
    AddReal(fb + "ActualPosition", [axis](const ScanSample& s) { return AxisOf(s, axis).actualPosition; });
    AddReal(scope + ".sim.Position", [axis](const ScanSample& s) { return AxisOf(s, axis).simPosition; });
}

void ScenarioSignals::Sample(const ScanSample& sample) {
    current_ = &sample;
    recorder_.Sample(sample.time);
    current_ = nullptr;
}

ValueFormat ScenarioSignals::FormatOf(const std::string& path) const { return formats_.at(path); }

std::vector<std::string> ScenarioSignals::Paths(const Modules& modules) {
    TraceRecorder recorder;
    const ScenarioSignals signals(modules, recorder);
    std::vector<std::string> paths;
    for (const auto& signal : recorder.Recording().Signals()) paths.push_back(signal.path);
    return paths;
}

}  // namespace pac::scenario
