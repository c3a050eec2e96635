#include "plc_cli.hpp"

#include <cmath>
#include <cstdlib>
#include <exception>
#include <memory>
#include <sstream>

#include "gvl_names.hpp"
#include "modbus_remote_controller.hpp"
#include "register_map.hpp"
#include "scenario_error.hpp"
#include "scenario_loader.hpp"
#include "scenario_runner.hpp"
#include "controller_setup.hpp"

namespace pac::pacsim {

namespace {

using pac::scenario::RunReport;
using pac::scenario::StepReport;

constexpr const char* kProgram = "pac-sim-plc";

void Usage(std::ostream& out) {
    out << "usage: " << kProgram << " --port N [--address IPV4] [--unit ID] [--http N] [--plc-cycle-ms MS] [--compare]"
        << " SCENARIO.json\n"
        << "  Runs the scenario's steps with the library's FBs in a real-time scan loop against pac-sim over Modbus\n"
        << "  TCP (docs/virtual_commissioning.md). The pac-sim configuration must have the scenario's modules.\n"
        << "  --port N, --address IPV4, --unit ID  where pac-sim serves the controller (default 127.0.0.1, unit 1)\n"
        << "  --http N          pac-sim's --http port, for the scenario's power cycle\n"
        << "  --plc-cycle-ms MS the PLC cycle (default 10)\n"
        << "  --compare         run the steps in the process too and require the same ends\n";
}

// What a step ended with, as text: two runs ended the same when the texts are equal.
std::string Ending(const StepReport& step) {
    std::ostringstream text;
    if (step.outcome) {
        text << "done " << step.outcome->done << " error " << step.outcome->error << " id " << step.outcome->errorId
             << " ack " << step.outcome->ackData;
    }
    if (step.request) text << "done " << step.request->done << " error " << step.request->error << " id " << step.request->errorId;
    for (const auto& axis : step.axes) {
        text << "axis " << axis.axis << ": done " << axis.done << " error " << axis.error << " id " << axis.errorId
             << " enabled " << axis.enabled << " referenced " << axis.referenced << " position "
             << std::round(axis.position * 1000.0) / 1000.0 << "; ";
    }
    for (const auto& failure : step.failures) text << "FAILED " << failure << "; ";
    return text.str();
}

std::string Scans(const StepReport& step) {
    if (step.outcome) return std::to_string(step.outcome->endScan - step.outcome->edgeScan);
    if (step.request) return std::to_string(step.request->endScan - step.request->edgeScan);
    return "";
}

}  // namespace

int RunPlcCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    std::string file;
    std::string address = "127.0.0.1";
    int port = -1;
    int unit = 1;
    int http = 0;
    int cycleMs = 10;
    bool compare = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "-h" || arg == "--help") {
            Usage(out);
            return 0;
        }
        if (arg == "--compare") {
            compare = true;
        } else if (arg == "--address" && i + 1 < args.size()) {
            address = args[++i];
        } else if ((arg == "--port" || arg == "--unit" || arg == "--http" || arg == "--plc-cycle-ms") && i + 1 < args.size()) {
            char* rest = nullptr;
            const long value = std::strtol(args[++i].c_str(), &rest, 10);
            if (*rest != '\0' || value < 0 || value > 65535) {
                err << kProgram << ": " << arg << " needs a number 0..65535\n";
                return 2;
            }
            (arg == "--port" ? port : arg == "--unit" ? unit : arg == "--http" ? http : cycleMs) = static_cast<int>(value);
        } else if (!arg.empty() && arg[0] != '-' && file.empty()) {
            file = arg;
        } else {
            Usage(err);
            return 2;
        }
    }
    if (file.empty() || port < 0 || cycleMs < 1) {
        Usage(err);
        return 2;
    }
    const pac::scenario::GvlNames names;
    pac::scenario::Scenario scenario;
    try {
        scenario = pac::scenario::ScenarioLoader(names).FromFile(file);
    } catch (const pac::scenario::ScenarioError& e) {
        err << kProgram << ": invalid scenario " << file << ": " << e.what() << "\n";
        return 2;
    }
    scenario.timing.plcCycleMs = cycleMs;
    try {
        const int registers = RegisterMap(pac::scenario::Layout(scenario.modules)).Registers();
        // Two histograms of 800 kB: not on the stack.
        auto remote = std::make_unique<ModbusRemoteController>(address, port, unit, registers, http);
        const RunReport overModbus = pac::scenario::ScenarioRunner(scenario, remote.get()).Run();
        RunReport inProcess;
        if (compare) inProcess = pac::scenario::ScenarioRunner(scenario).Run();
        bool same = true;
        // A Markdown table: each step's end over Modbus and the scans from its Execute edge to its end.
        out << "| step | over Modbus | scans" << (compare ? " | in the process | scans |\n|---|---|---|---|---|\n"
                                                        : " |\n|---|---|---|\n");
        for (std::size_t i = 0; i < overModbus.steps.size(); ++i) {
            const StepReport& step = overModbus.steps[i];
            out << "| " << i + 1 << " " << scenario.steps[i].note.substr(0, 40) << " | " << Ending(step) << " | "
                << Scans(step);
            if (compare) {
                const StepReport& local = inProcess.steps[i];
                out << " | " << (Ending(local) == Ending(step) ? "the same" : Ending(local)) << " | " << Scans(local);
                same = same && Ending(local) == Ending(step);
            }
            out << " |\n";
        }
        const CycleStats& late = remote->ScanLateness();
        const CycleStats& trips = remote->RoundTrips();
        out << kProgram << ": PLC cycle " << cycleMs << " ms, " << late.Cycles() << " scans; scan start lateness p50 "
            << late.Quantile(0.5).count() << " us, p99 " << late.Quantile(0.99).count() << " us, max "
            << late.Max().count() << " us; Modbus read round trip p50 " << trips.Quantile(0.5).count() << " us, p99 "
            << trips.Quantile(0.99).count() << " us\n";
        const bool passed = overModbus.Passed() && (!compare || inProcess.Passed());
        out << kProgram << ": " << (passed ? "every step passed" : "a step failed")
            << (compare ? (same ? ", every step ended as in the process" : ", a step ended otherwise than in the process") : "")
            << "\n";
        return passed && same ? 0 : 1;
    } catch (const std::exception& e) {
        err << kProgram << ": " << e.what() << "\n";
        return 3;
    }
}

}  // namespace pac::pacsim
