#include "timeline_printer.hpp"

#include <cstdio>
#include <string>
#include <type_traits>
#include <variant>

#include "pac/sim/cmd_frame.hpp"
#include "text_format.hpp"

namespace pac::scenario {

namespace {

// "60", "60.5": milliseconds, exact.
std::string MsNumber(std::chrono::nanoseconds t) {
    const auto ns = t.count();
    if (ns % 1000000 == 0) return std::to_string(ns / 1000000);
    char text[32];
    std::snprintf(text, sizeof text, "%.6f", static_cast<double>(ns) / 1e6);
    std::string number = text;
    number.erase(number.find_last_not_of('0') + 1);
    return number;
}

std::string Ms(std::chrono::nanoseconds t) { return MsNumber(t) + " ms"; }

bool SameInterface(const ScanSample& a, const ScanSample& b) {
    return a.toPac == b.toPac && a.fromPac == b.fromPac && a.execute == b.execute && a.busy == b.busy &&
           a.done == b.done && a.error == b.error && a.errorId == b.errorId && a.ackData == b.ackData;
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
    out_ << "  controller: " << (items.empty() ? "power-on state" : items) << "\n";
    out_ << "  one FB_PAC_Cmd on the CMD interface; a line for each scan in which the interface or the FB's outputs"
            " changed\n\n";
    PrintColumns();
}

void TimelinePrinter::PrintColumns() {
    out_ << "  t [ms]   scan | ToPac (PLC -> PAC)      | FromPac (PAC -> PLC)    | SEND RF KF BF Status |"
            " Execute Busy Done Error ErrorID AckData\n";
}

void TimelinePrinter::OnStepStart(std::size_t index, const Step& step, std::chrono::nanoseconds now) {
    out_ << "\nstep " << index + 1 << " at " << Ms(now) << ": ";
    std::visit(
        [this](const auto& action) {
            using Action = std::decay_t<decltype(action)>;
            if constexpr (std::is_same_v<Action, CommandStep>) {
                PrintCommand(action);
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
}

void TimelinePrinter::PrintCommand(const CommandStep& command) {
    out_ << (command.name.empty() ? "command" : command.name) << " (" << Hex4(command.code) << "), Param "
         << command.param;
    if (command.data.bits != 0 || command.data.isReal) out_ << ", Data " << DwordText(command.data);
    const CommandStep defaults;
    if (command.timeoutMs != defaults.timeoutMs) out_ << ", Timeout " << command.timeoutMs << " ms";
    if (command.endTimeoutMs != defaults.endTimeoutMs) out_ << ", EndTimeout " << command.endTimeoutMs << " ms";
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
            out_ << "zero " << LinkText(fault.link) << ": the reader sees 8 zero bytes";
            break;
        case FaultKind::kThawLink:
            out_ << "thaw " << LinkText(fault.link) << ": the newest image gets through again";
            break;
    }
}

void TimelinePrinter::OnScan(const ScanSample& s) {
    if (last_ && SameInterface(*last_, s)) return;
    last_ = s;
    const auto master = pac::sim::MasterFrame::Decode(s.toPac);
    const auto reply = pac::sim::ReplyFrame::Decode(s.fromPac);
    char line[256];
    std::snprintf(line, sizeof line, "%8s %6lld | %s | %s | %4d %2d %2d %2d %6d | %7d %4d %4d %5d %7s %s\n",
                  MsNumber(s.time).c_str(), static_cast<long long>(s.scan),
                  pac::sim::ToHex(s.toPac).c_str(), pac::sim::ToHex(s.fromPac).c_str(), master.send,
                  reply.receiveFlag, reply.commandErrorFlag, reply.endOfProcessing, reply.operatingStatus, s.execute,
                  s.busy, s.done, s.error, ErrorIdText(s.errorId).c_str(), Hex8(s.ackData).c_str());
    out_ << line;
}

void TimelinePrinter::OnStepEnd(const StepReport& report) {
    if (!report.outcome) return;
    const auto& command = std::get<CommandStep>(scenario_->steps[report.index].action);
    PrintOutcome(command, *report.outcome);
    if (command.expect.Empty() && report.Passed()) {
        out_ << " (nothing expected)\n";
    } else if (report.Passed()) {
        out_ << ": as expected\n";
    } else {
        out_ << "\n";
        for (const auto& failure : report.failures) out_ << "  => FAILED: " << failure << "\n";
    }
}

// "  => Done in scan 36 (72 ms), 3 scans after the Execute edge; AckData 333 (16#0000014D)"
void TimelinePrinter::PrintOutcome(const CommandStep& command, const CommandOutcome& outcome) {
    out_ << "  => ";
    const auto scans = outcome.endScan - outcome.edgeScan;
    if (!outcome.finished) {
        out_ << "no Done or Error within " << Plural(scans, "scan", "scans") << " of the Execute edge";
        return;
    }
    out_ << (outcome.done ? "Done" : "Error") << " in scan " << outcome.endScan << " (" << Ms(outcome.endTime)
         << "), " << Plural(scans, "scan", "scans") << " after the Execute edge";
    if (outcome.error) {
        const std::string name = names_.ErrorName(outcome.errorId);
        out_ << "; ErrorID " << ErrorIdText(outcome.errorId) << (name.empty() ? "" : " " + name) << " \""
             << ErrorText(outcome.errorId) << "\"";
    }
    const bool asReal = command.data.isReal || (command.expect.ackData && command.expect.ackData->isReal);
    out_ << "; AckData " << DwordText(outcome.ackData, asReal);
}

void TimelinePrinter::OnEnd(const RunReport& report) {
    const auto failed = report.FailedSteps();
    out_ << "\nResult: " << Plural(static_cast<long long>(report.steps.size()), "step", "steps") << ", "
         << Plural(static_cast<long long>(report.Commands()), "command", "commands") << ": ";
    if (failed.empty()) {
        out_ << "all expectations met\n";
        return;
    }
    out_ << Plural(static_cast<long long>(failed.size()), "step", "steps") << " FAILED (step";
    for (std::size_t i = 0; i < failed.size(); ++i) out_ << (i == 0 ? " " : ", ") << failed[i] + 1;
    out_ << ")\n";
}

}  // namespace pac::scenario
