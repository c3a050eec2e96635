#include "timeline_printer.hpp"

#include <cstdio>
#include <string>
#include <type_traits>
#include <variant>

#include "pac/format_time.hpp"
#include "pac/sim/automatic_module.hpp"
#include "pac/sim/cmd_frame.hpp"
#include "text_format.hpp"

namespace pac::scenario {

namespace {

using pac::FormatMs;
using pac::FormatMsNumber;

constexpr std::size_t kStatusByte = 5;  // the operating status in the CMD reply (2.4.2)

bool SameCmd(const ScanSample& a, const ScanSample& b) {
    return a.toPac == b.toPac && a.fromPac == b.fromPac && a.execute == b.execute && a.busy == b.busy &&
           a.done == b.done && a.error == b.error && a.errorId == b.errorId && a.ackData == b.ackData;
}

bool SameCtrl(const CtrlSample& a, const CtrlSample& b) {
    return a.toPac == b.toPac && a.fromPac == b.fromPac && a.execute == b.execute && a.busy == b.busy &&
           a.done == b.done && a.error == b.error && a.errorId == b.errorId;
}

bool SameAxis(const AxisSample& a, const AxisSample& b) {
    return a.toPac == b.toPac && a.fromPac == b.fromPac && a.enable == b.enable && a.execute == b.execute &&
           a.busy == b.busy && a.done == b.done && a.error == b.error && a.aborted == b.aborted &&
           a.errorId == b.errorId;
}

std::uint16_t Word(std::uint8_t high, std::uint8_t low) { return static_cast<std::uint16_t>(high << 8 | low); }

std::string PositionText(std::uint32_t bits, bool integerMode) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", PositionValue(bits, integerMode));
    return text;
}

std::string Plural(long long n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

const char* LinkText(LinkSide side) {
    switch (side) {
        case LinkSide::kToPac:
            return "the link PLC -> PA-CONTROL (ToPac)";
        case LinkSide::kFromPac:
            return "the link PA-CONTROL -> PLC (FromPac)";
        case LinkSide::kBoth:
            break;
    }
    return "both links (ToPac and FromPac)";
}

}  // namespace

void TimelinePrinter::OnStart(const Scenario& scenario) {
    scenario_ = &scenario;
    last_.reset();
    const Timing& t = scenario.timing;
    out_ << "PA-CONTROL scenario";
    if (!scenario.name.empty()) out_ << " \"" << scenario.name << "\"";
    if (!scenario.description.empty()) out_ << ": " << scenario.description;
    out_ << "\n  timing: PLC cycle " << t.plcCycleMs << " ms, PA-CONTROL cycle " << t.pacCycleMs
         << " ms, bus latency " << Plural(t.latencyCycles, "PLC cycle", "PLC cycles") << " each way";
    if (t.jitterMs > 0) {
        out_ << " + jitter up to " << t.jitterMs << " ms (seed " << t.seed << ")";
    } else {
        out_ << ", no jitter";
    }
    out_ << ", PA-CONTROL boots in " << t.bootMs << " ms\n";
    const ControllerSetup& setup = scenario.controller;
    std::string items;
    auto add = [&items](const std::string& item) { items += (items.empty() ? "" : ", ") + item; };
    if (setup.operatingStatus) {
        const std::string name = names_.StatusName(*setup.operatingStatus);
        add("boots into status " + std::to_string(*setup.operatingStatus) + (name.empty() ? "" : " " + name));
    }
    for (const auto& [n, value] : setup.intRegisters) add("N" + std::to_string(n) + " = " + std::to_string(value));
    for (const auto& [n, value] : setup.realRegisters) {
        add("R" + std::to_string(n) + " = " + DwordText(pac::sim::FloatToBits(value), true));
    }
    for (const auto& [n, value] : setup.inputs) add("input " + std::to_string(n) + " = " + (value ? "1" : "0"));
    for (const auto& [n, value] : setup.systemParameters) {
        add("system parameter " + std::to_string(n) + " = " + std::to_string(value));
    }
    if (scenario.modules.axes > 0 && !setup.axesReferenced) add("axes not referenced at power-on");
    for (const auto& [axis, switches] : setup.limitSwitches) {
        std::string where;
        char text[64];
        for (const auto& [side, position] : {std::pair{"negative", switches.negative}, std::pair{"positive", switches.positive}}) {
            if (!position) continue;
            std::snprintf(text, sizeof text, "%s%s at %.3f", where.empty() ? "" : ", ", side, *position);
            where += text;
        }
        add("axis " + std::to_string(axis) + " limit switches: " + where);
    }
    out_ << "  controller: " << (items.empty() ? "power-on state" : items) << "\n";
    const Modules& m = scenario.modules;
    out_ << "  modules: CMD";
    if (m.ctrl) out_ << ", CTRL";
    if (m.axes > 0) out_ << ", " << Plural(m.axes, "axis module", "axis modules");
    out_ << "; one FB_PAC_Cmd on the CMD interface";
    if (m.ctrl) out_ << ", FB_PAC_Ctrl on the CTRL interface";
    if (m.axes > 0 && m.mcBlocks) out_ << ", FB_PAC_McAxis and the MC_ blocks on each axis module";
    if (m.axes > 0 && !m.mcBlocks) out_ << ", an FB_PAC_Axis on each axis module";
    if (m.diagnosis) {
        out_ << ", FB_PAC_Diagnosis on the CMD channel (Axes " << m.diagnosis->axes << ", PollTime "
             << m.diagnosis->pollMs << " ms)";
    }
    out_ << "\n  a line for each scan in which the step's module or its FB's outputs changed\n\n";
    view_ = View::kCmd;
    viewAxes_.clear();
    PrintColumns();
}

bool TimelinePrinter::SetView(View view, std::vector<int> axes) {
    if (view == view_ && axes == viewAxes_) return false;
    view_ = view;
    viewAxes_ = std::move(axes);
    last_.reset();  // the first scan of a new view is always shown
    return true;
}

void TimelinePrinter::PrintColumns() {
    switch (view_) {
        case View::kCmd:
            out_ << "  t [ms]   scan | ToPac (PLC -> PAC)      | FromPac (PAC -> PLC)    | SEND RF KF BF Status |"
                    " Execute Busy Done Error ErrorID AckData\n";
            break;
        case View::kCtrl:
            out_ << "  t [ms]   scan | CTRL ToPac              | CTRL FromPac            | control status  SysErrNo |"
                    " Rdy Bat Err AuA AuS OnA OnS Int | Execute Busy Done Error ErrorID\n";
            break;
        case View::kAxes:
            out_ << "  t [ms]   scan | axis | control     acc  vel   position | status      CmdErr AxErr   position |"
                    " Enable Execute Busy Done Error Aborted ErrorID\n";
            break;
        case View::kAutomatic:
            out_ << "  t [ms]   scan | module | Status | FW k        N k        R k | FW 16+k   N 16+k     R 16+k"
                    "  (2.6, docs/open_points.md)\n";
            break;
    }
}

void TimelinePrinter::OnStepStart(std::size_t index, const Step& step, std::chrono::nanoseconds now) {
    const bool newView = std::visit(
        [this](const auto& action) {
            using Action = std::decay_t<decltype(action)>;
            if constexpr (std::is_same_v<Action, CommandStep>) {
                return SetView(View::kCmd, {});
            } else if constexpr (std::is_same_v<Action, CtrlStep>) {
                return SetView(View::kCtrl, {});
            } else if constexpr (std::is_same_v<Action, AxesStep>) {
                std::vector<int> axes;
                for (const auto& job : action.jobs) axes.push_back(job.axis);
                return SetView(View::kAxes, axes);
            } else if constexpr (std::is_same_v<Action, AutomaticStep>) {
                std::vector<int> modules;
                for (const auto& values : action.modules) modules.push_back(values.module);
                return SetView(View::kAutomatic, modules);
            } else {
                return false;
            }
        },
        step.action);
    out_ << "\nstep " << index + 1 << " at " << FormatMs(now) << ": ";
    std::visit(
        [this](const auto& action) {
            using Action = std::decay_t<decltype(action)>;
            if constexpr (std::is_same_v<Action, CommandStep>) {
                PrintCommand(action);
            } else if constexpr (std::is_same_v<Action, CtrlStep>) {
                PrintCtrl(action);
            } else if constexpr (std::is_same_v<Action, AxesStep>) {
                PrintAxes(action);
            } else if constexpr (std::is_same_v<Action, AutomaticStep>) {
                PrintAutomatic(action);
            } else if constexpr (std::is_same_v<Action, FaultStep>) {
                PrintFault(action);
            } else {
                const int cycle = scenario_->timing.plcCycleMs;
                out_ << "wait " << action.ms << " ms (" << Plural((action.ms + cycle - 1) / cycle, "scan", "scans") << ")";
            }
        },
        step.action);
    if (!step.note.empty()) out_ << "  -- " << step.note;
    out_ << "\n";
    if (newView) PrintColumns();
}

void TimelinePrinter::PrintCommand(const CommandStep& command) {
    out_ << (command.name.empty() ? "command" : command.name) << " (" << Hex4(command.code) << "), Param "
         << command.param;
    if (command.data.bits != 0 || command.data.isReal) out_ << ", Data " << DwordText(command.data);
    const CommandStep defaults;
    if (command.timeoutMs != defaults.timeoutMs) out_ << ", Timeout " << command.timeoutMs << " ms";
    if (command.endTimeoutMs != defaults.endTimeoutMs) out_ << ", EndTimeout " << command.endTimeoutMs << " ms";
}

void TimelinePrinter::PrintCtrl(const CtrlStep& step) {
    out_ << "FB_PAC_Ctrl " << step.request << ", IntegerMode " << (step.integerMode ? "TRUE" : "FALSE");
    if (step.timeoutMs != CtrlStep{}.timeoutMs) out_ << ", Timeout " << step.timeoutMs << " ms";
}

void TimelinePrinter::PrintAxes(const AxesStep& step) {
    for (std::size_t i = 0; i < step.jobs.size(); ++i) {
        const AxisJob& job = step.jobs[i];
        out_ << (i == 0 ? "" : "; ") << "axis " << job.axis << ":";
        if (job.enable) out_ << " Enable " << (*job.enable ? "TRUE" : "FALSE");
        if (job.resetError) out_ << (job.enable ? "," : "") << " ResetError";
        if (!job.HasJob()) continue;
        char position[32];
        std::snprintf(position, sizeof position, "%g", job.position);
        out_ << (job.enable ? "," : "") << " " << job.command << " Position " << position << ", Velocity "
             << job.velocity << ", Acceleration " << job.acceleration;
        if (job.condition != "PAC_COND_NONE") out_ << ", " << job.condition;
    }
}

void TimelinePrinter::PrintAutomatic(const AutomaticStep& step) {
    for (std::size_t i = 0; i < step.modules.size(); ++i) {
        const AutomaticValues& values = step.modules[i];
        out_ << (i == 0 ? "" : "; ") << "FB_PAC_AutomaticModule " << values.module << ":";
        if (!values.flagWord && !values.n && !values.r) out_ << " inputs unchanged";
        if (values.flagWord) out_ << " FlagWord " << Hex4(*values.flagWord);
        if (values.n) out_ << " IntRegister " << *values.n;
        if (values.r) {
            char r[32];
            std::snprintf(r, sizeof r, "%g", *values.r);
            out_ << " RealRegister " << r;
        }
    }
}

void TimelinePrinter::PrintFault(const FaultStep& fault) {
    switch (fault.kind) {
        case FaultKind::kPowerCycle:
            out_ << "power cycle: the PA-CONTROL drops off the bus and boots again (" << scenario_->timing.bootMs
                 << " ms)";
            break;
        case FaultKind::kFreezeLink:
            out_ << "freeze " << LinkText(fault.link) << ": the reader keeps seeing the last image";
            break;
        case FaultKind::kZeroLink:
            out_ << "zero " << LinkText(fault.link) << ": the reader sees zero bytes";
            break;
        case FaultKind::kThawLink:
            out_ << "thaw " << LinkText(fault.link) << ": the newest image gets through again";
            break;
        case FaultKind::kSystemError:
            out_ << "system error " << fault.number << " raised in the PA-CONTROL";
            break;
        case FaultKind::kSetInput:
            out_ << "input " << fault.number << " := " << (fault.value ? 1 : 0);
            break;
    }
}

bool TimelinePrinter::Changed(const ScanSample& s) const {
    if (!last_) return true;
    switch (view_) {
        case View::kCmd: return !SameCmd(*last_, s);
        case View::kCtrl: return !(last_->ctrl && s.ctrl && SameCtrl(*last_->ctrl, *s.ctrl));
        case View::kAxes:
        case View::kAutomatic:
            if (view_ == View::kAutomatic && last_->fromPac[kStatusByte] != s.fromPac[kStatusByte]) return true;
            for (int axis : viewAxes_) {
                const auto k = static_cast<std::size_t>(axis - 1);
                if (k >= s.axes.size() || k >= last_->axes.size() || !SameAxis(last_->axes[k], s.axes[k])) return true;
            }
            return false;
    }
    return true;
}

void TimelinePrinter::OnScan(const ScanSample& s) {
    if (!Changed(s)) return;
    last_ = s;
    switch (view_) {
        case View::kCmd: PrintCmdLine(s); break;
        case View::kCtrl: PrintCtrlLine(s); break;
        case View::kAxes:
            for (int axis : viewAxes_) {
                const auto k = static_cast<std::size_t>(axis - 1);
                if (k < s.axes.size()) PrintAxisLine(s, s.axes[k]);
            }
            break;
        case View::kAutomatic:
            for (int module : viewAxes_) {
                const auto k = static_cast<std::size_t>(module - 1);
                if (k < s.axes.size()) PrintAutomaticLine(s, s.axes[k]);
            }
            break;
    }
}

void TimelinePrinter::PrintCmdLine(const ScanSample& s) {
    const auto master = pac::sim::CommandFrame::Decode(s.toPac);
    const auto reply = pac::sim::ReplyFrame::Decode(s.fromPac);
    char line[256];
    std::snprintf(line, sizeof line, "%8s %6lld | %s | %s | %4d %2d %2d %2d %6d | %7d %4d %4d %5d %7s %s\n",
                  FormatMsNumber(s.time).c_str(), static_cast<long long>(s.scan),
                  pac::sim::ToHex(s.toPac).c_str(), pac::sim::ToHex(s.fromPac).c_str(), master.send,
                  reply.receiveFlag, reply.commandErrorFlag, reply.endOfProcessing, reply.operatingStatus, s.execute,
                  s.busy, s.done, s.error, ErrorIdText(s.errorId).c_str(), Hex8(s.ackData).c_str());
    out_ << line;
}

// Control word 2.5.1; status word and system error number 2.5.2 (docs/fb/FB_PAC_Ctrl.md).
void TimelinePrinter::PrintCtrlLine(const ScanSample& s) {
    if (!s.ctrl) return;
    const CtrlSample& c = *s.ctrl;
    const std::uint16_t control = Word(c.toPac[0], c.toPac[1]);
    const std::uint16_t status = Word(c.fromPac[0], c.fromPac[1]);
    auto bit = [status](int n) { return (status >> n) & 1; };
    char line[320];
    std::snprintf(line, sizeof line,
                  "%8s %6lld | %s | %s | %s %s %8u | %3d %3d %3d %3d %3d %3d %3d %3d | %7d %4d %4d %5d %7s\n",
                  FormatMsNumber(s.time).c_str(), static_cast<long long>(s.scan), pac::sim::ToHex(c.toPac).c_str(),
                  pac::sim::ToHex(c.fromPac).c_str(), Hex4(control).c_str(), Hex4(status).c_str(),
                  static_cast<unsigned>(Word(c.fromPac[4], c.fromPac[5])), bit(0), bit(1), bit(2), bit(8), bit(9),
                  bit(10), bit(11), bit(15), c.execute, c.busy, c.done, c.error, ErrorIdText(c.errorId).c_str());
    out_ << line;
}

// The module as the flag/register interface of AUTOMATIC mode, in the layout of the scenario's controller, the
// default: the widths printed in 2.6.1 (docs/open_points.md); outside AUTOMATIC the same bytes are the axis
// interface.
void TimelinePrinter::PrintAutomaticLine(const ScanSample& s, const AxisSample& m) {
    const pac::sim::AutomaticLayout layout = pac::sim::AutomaticModuleConfig{}.layout;
    const pac::sim::AutomaticModuleData sent = pac::sim::AutomaticModuleData::Decode(m.toPac, layout);
    const pac::sim::AutomaticModuleData received = pac::sim::AutomaticModuleData::Decode(m.fromPac, layout);
    char line[320];
    std::snprintf(line, sizeof line, "%8s %6lld | %6d | %6u | %s %10d %10s | %s %10d %10s\n",
                  FormatMsNumber(s.time).c_str(), static_cast<long long>(s.scan), m.axis,
                  static_cast<unsigned>(s.fromPac[kStatusByte]), Hex4(sent.flagWord).c_str(),
                  static_cast<int>(sent.intRegister), PositionText(sent.realBits, m.integerMode).c_str(),
                  Hex4(received.flagWord).c_str(), static_cast<int>(received.intRegister),
                  PositionText(received.realBits, m.integerMode).c_str());
    out_ << line;
}

// Module layout 2.7.1 / 2.7.2: control or status dword, acceleration / CMD error number, speed / axis
// error number, target / current position.
void TimelinePrinter::PrintAxisLine(const ScanSample& s, const AxisSample& a) {
    char line[320];
    std::snprintf(line, sizeof line,
                  "%8s %6lld | %4d | %s %4u %4u %10s | %s %6u %5u %10s | %6d %7d %4d %4d %5d %7d %7s\n",
                  FormatMsNumber(s.time).c_str(), static_cast<long long>(s.scan), a.axis,
                  Hex8(pac::sim::ReadDword(a.toPac, 0)).c_str(), static_cast<unsigned>(pac::sim::ReadWordAt(a.toPac, 4)),
                  static_cast<unsigned>(pac::sim::ReadWordAt(a.toPac, 6)),
                  PositionText(pac::sim::ReadDword(a.toPac, 8), a.integerMode).c_str(),
                  Hex8(pac::sim::ReadDword(a.fromPac, 0)).c_str(),
                  static_cast<unsigned>(pac::sim::ReadWordAt(a.fromPac, 4)),
                  static_cast<unsigned>(pac::sim::ReadWordAt(a.fromPac, 6)),
                  PositionText(pac::sim::ReadDword(a.fromPac, 8), a.integerMode).c_str(), a.enable, a.execute, a.busy,
                  a.done, a.error, a.aborted, ErrorIdText(a.errorId).c_str());
    out_ << line;
}

void TimelinePrinter::OnStepEnd(const StepReport& report) {
    const Step& step = scenario_->steps[report.index];
    if (report.outcome) {
        const auto& command = std::get<CommandStep>(step.action);
        const bool asReal = command.data.isReal || (command.expect.ackData && command.expect.ackData->isReal);
        PrintOutcome(*report.outcome, true, asReal);
        PrintVerdict(command.expect.Empty(), report);
    } else if (report.request) {
        PrintOutcome(*report.request, false, false);
        PrintVerdict(std::get<CtrlStep>(step.action).expect.Empty(), report);
    } else if (!report.axes.empty()) {
        const auto& axes = std::get<AxesStep>(step.action);
        bool nothing = true;
        for (std::size_t i = 0; i < axes.jobs.size(); ++i) {
            PrintAxisOutcome(axes.jobs[i], report.axes[i]);
            nothing = nothing && axes.jobs[i].expect.Empty();
        }
        out_ << "  => axes";
        PrintVerdict(nothing, report);
    }
}

void TimelinePrinter::PrintVerdict(bool expectedNothing, const StepReport& report) {
    if (expectedNothing && report.Passed()) {
        out_ << " (nothing expected)\n";
    } else if (report.Passed()) {
        out_ << ": as expected\n";
    } else {
        out_ << "\n";
        for (const auto& failure : report.failures) out_ << "  => FAILED: " << failure << "\n";
    }
}

// "  => Done in scan 36 (72 ms), 3 scans after the Execute edge; AckData 333 (16#0000014D)"
void TimelinePrinter::PrintOutcome(const CommandOutcome& outcome, bool showAckData, bool ackAsReal) {
    out_ << "  => ";
    const auto scans = outcome.endScan - outcome.edgeScan;
    if (!outcome.finished) {
        out_ << "no Done or Error within " << Plural(scans, "scan", "scans") << " of the Execute edge";
        return;
    }
    out_ << (outcome.done ? "Done" : "Error") << " in scan " << outcome.endScan << " (" << FormatMs(outcome.endTime)
         << "), " << Plural(scans, "scan", "scans") << " after the Execute edge";
    if (outcome.error) {
        const std::string name = names_.ErrorName(outcome.errorId);
        out_ << "; ErrorID " << ErrorIdText(outcome.errorId) << (name.empty() ? "" : " " + name) << " \""
             << ErrorText(outcome.errorId) << "\"";
    }
    if (showAckData) out_ << "; AckData " << DwordText(outcome.ackData, ackAsReal);
}

// "  => axis 1: Done in scan 80 (160 ms), 40 scans after the Execute edge; position 100.000, referenced"
void TimelinePrinter::PrintAxisOutcome(const AxisJob& job, const AxisOutcome& outcome) {
    out_ << "  => axis " << outcome.axis << ": ";
    const auto scans = outcome.endScan - outcome.edgeScan;
    if (!outcome.finished) {
        out_ << (job.HasJob()      ? "the job did not end"
                 : job.resetError ? "AxisError still set"
                                  : "Enabled did not follow Enable")
             << " within " << Plural(scans, "scan", "scans") << "\n";
        return;
    }
    if (job.HasJob()) {
        out_ << (outcome.done ? "Done" : outcome.error ? "Error" : "CommandAborted");
    } else if (job.resetError) {
        out_ << "axis error reset";
    } else {
        out_ << (outcome.enabled ? "Enabled" : "not Enabled");
    }
    out_ << " in scan " << outcome.endScan << " (" << FormatMs(outcome.endTime) << "), " << Plural(scans, "scan", "scans")
         << " after the step began";
    if (outcome.error) {
        const std::string name = names_.ErrorName(outcome.errorId);
        out_ << "; ErrorID " << ErrorIdText(outcome.errorId) << (name.empty() ? "" : " " + name);
    }
    char position[48];
    std::snprintf(position, sizeof position, "; position %.3f", outcome.position);
    out_ << position << (outcome.referenced ? ", referenced" : ", not referenced") << "\n";
}

// The CMD interface's last handshakes, as a PLC programmer reads Channel.History online.
void TimelinePrinter::PrintHistory(const RunReport& report) {
    if (report.history.empty()) return;
    out_ << "\nCMD handshake history (Channel.History): the last " << report.history.size() << " of "
         << report.handshakes << ", oldest first; scans from the Execute edge\n";
    out_ << "  Code      Param  Data         ErrorID  AckData      to ack  to end  command\n";
    for (const HandshakeRecord& h : report.history) {
        char line[256];
        std::snprintf(line, sizeof line, "  %s %6u  %s %7s  %s %6s %7d  %s\n", Hex4(h.code).c_str(),
                      static_cast<unsigned>(h.param), Hex8(h.data).c_str(), ErrorIdText(h.errorId).c_str(),
                      Hex8(h.ackData).c_str(), h.scansToAck < 0 ? "-" : std::to_string(h.scansToAck).c_str(),
                      static_cast<int>(h.scansToEnd), names_.CommandName(h.code).c_str());
        out_ << line;
    }
}

void TimelinePrinter::OnEnd(const RunReport& report) {
    PrintHistory(report);
    const auto failed = report.FailedSteps();
    out_ << "\nResult: " << Plural(static_cast<long long>(report.steps.size()), "step", "steps") << ", "
         << Plural(static_cast<long long>(report.Commands()), "command", "commands");
    if (report.Requests() > 0) out_ << ", " << Plural(static_cast<long long>(report.Requests()), "mode request", "mode requests");
    if (report.AxisJobs() > 0) out_ << ", " << Plural(static_cast<long long>(report.AxisJobs()), "axis job", "axis jobs");
    out_ << ": ";
    if (failed.empty()) {
        out_ << "all expectations met\n";
        return;
    }
    out_ << Plural(static_cast<long long>(failed.size()), "step", "steps") << " FAILED (step";
    for (std::size_t i = 0; i < failed.size(); ++i) out_ << (i == 0 ? " " : ", ") << failed[i] + 1;
    out_ << ")\n";
}

}  // namespace pac::scenario
