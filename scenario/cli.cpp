#include "cli.hpp"

#include <exception>

#include "gvl_names.hpp"
#include "scenario_loader.hpp"
#include "scenario_runner.hpp"
#include "timeline_printer.hpp"

namespace pac::scenario {

namespace {

constexpr const char* kProgram = "pac_scenario";

void Usage(std::ostream& out) {
    out << "usage: " << kProgram << " [--check] SCENARIO.json\n"
        << "  Runs the scenario's commands, mode requests and axis jobs through FB_PAC_Cmd, FB_PAC_Ctrl and\n"
        << "  FB_PAC_Axis against the simulated PA-CONTROL and prints a scan-by-scan timeline of the\n"
        << "  modules' images and the FBs' pins (format: docs/scenario.md).\n"
        << "  --check  only check the scenario, do not run it\n"
        << "exit codes: 0 all expectations met, 1 an expectation failed, 2 invalid scenario or usage,\n"
        << "            3 internal error\n";
}

}  // namespace

int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    bool checkOnly = false;
    std::string scenarioFile;
    for (const std::string& arg : args) {
        if (arg == "-h" || arg == "--help") {
            Usage(out);
            return kExitOk;
        }
        if (arg == "--check") {
            checkOnly = true;
        } else if (arg.size() > 1 && arg[0] == '-') {
            err << kProgram << ": unknown option " << arg << "\n";
            Usage(err);
            return kExitRefused;
        } else if (scenarioFile.empty()) {
            scenarioFile = arg;
        } else {
            err << kProgram << ": one scenario file at a time (got " << scenarioFile << " and " << arg << ")\n";
            return kExitRefused;
        }
    }
    if (scenarioFile.empty()) {
        Usage(err);
        return kExitRefused;
    }

    const GvlNames names;
    Scenario scenario;
    try {
        scenario = ScenarioLoader(names).FromFile(scenarioFile);
    } catch (const ScenarioError& e) {
        err << kProgram << ": invalid scenario " << scenarioFile << ": " << e.what() << "\n";
        return kExitRefused;
    } catch (const std::exception& e) {
        err << kProgram << ": internal error while reading " << scenarioFile << ": " << e.what() << "\n";
        return kExitInternalError;
    }
    if (checkOnly) {
        const auto steps = scenario.steps.size();
        out << scenarioFile << ": valid scenario, " << steps << (steps == 1 ? " step\n" : " steps\n");
        return kExitOk;
    }
    try {
        TimelinePrinter printer(out, names);
        const RunReport report = ScenarioRunner(scenario).Run(printer);
        return report.Passed() ? kExitOk : kExitExpectationFailed;
    } catch (const ScenarioError& e) {
        err << kProgram << ": invalid scenario " << scenarioFile << ": " << e.what() << "\n";
        return kExitRefused;
    } catch (const std::exception& e) {
        err << kProgram << ": internal error: " << e.what() << "\n";
        return kExitInternalError;
    }
}

}  // namespace pac::scenario
