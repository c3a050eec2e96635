#include "cli.hpp"

#include <exception>
#include <optional>

#include "gvl_names.hpp"
#include "scenario_loader.hpp"
#include "scenario_runner.hpp"
#include "timeline_printer.hpp"

namespace pac::scenario {

namespace {

constexpr const char* kProgram = "pac_scenario";

void Usage(std::ostream& out) {
    out << "usage: " << kProgram << " [--check] [--gvl FILE] SCENARIO.json\n"
        << "  Runs the scenario's commands through FB_PAC_Cmd against the simulated PA-CONTROL and prints\n"
        << "  a scan-by-scan timeline of the handshake (format: docs/scenario.md).\n"
        << "  --check     only check the scenario, do not run it\n"
        << "  --gvl FILE  read command, status and error names from FILE (default " << PAC_GVL_FILE << ")\n"
        << "exit codes: 0 all expectations met, 1 an expectation failed, 2 invalid scenario or usage,\n"
        << "            3 internal error\n";
}

}  // namespace

int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    bool checkOnly = false;
    std::string gvlFile = PAC_GVL_FILE;
    std::string scenarioFile;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "-h" || arg == "--help") {
            Usage(out);
            return kExitOk;
        }
        if (arg == "--check") {
            checkOnly = true;
        } else if (arg == "--gvl" && i + 1 < args.size()) {
            gvlFile = args[++i];
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

    std::optional<GvlNames> names;
    try {
        names.emplace(gvlFile);
    } catch (const std::exception& e) {
        err << kProgram << ": " << e.what() << " (the names of GVL_PAC)\n";
        return kExitRefused;
    }
    Scenario scenario;
    try {
        scenario = ScenarioLoader(*names).FromFile(scenarioFile);
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
        TimelinePrinter printer(out, *names);
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
