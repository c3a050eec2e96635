#include "cli.hpp"

#include <algorithm>
#include <exception>
#include <fstream>

#include "gvl_names.hpp"
#include "pac/vcd_writer.hpp"
#include "preconditions.hpp"
#include "scenario_loader.hpp"
#include "scenario_runner.hpp"
#include "timeline_printer.hpp"
#include "scenario_diagram.hpp"
#include "trace_observer.hpp"

namespace pac::scenario {

namespace {

constexpr const char* kProgram = "pac_scenario";

void Usage(std::ostream& out) {
    out << "usage: " << kProgram << " [--check] [--vcd FILE] [--wavedrom FILE] SCENARIO.json\n"
        << "       " << kProgram << " --check SCENARIO.json...\n"
        << "       " << kProgram << " --version\n"
        << "  Runs the scenario's commands, mode requests and axis jobs through FB_PAC_Cmd, FB_PAC_Ctrl and\n"
        << "  FB_PAC_Axis against the simulated PA-CONTROL and prints a scan-by-scan timeline of the\n"
        << "  modules' images and the FBs' pins (format: docs/scenario.md).\n"
        << "  --check          only check the scenario (or each of several), do not run it\n"
        << "  --vcd FILE       also write every signal of the run, scan by scan, as VCD (GTKWave)\n"
        << "  --wavedrom FILE  also write the scenario's \"diagram\" (steps, signals) as WaveJSON (WaveDrom)\n"
        << "  --version        print the library's version (st/library.json) and exit\n"
        << "exit codes: 0 all expectations met, 1 an expectation failed, 2 invalid scenario or usage,\n"
        << "            3 internal error\n";
}

struct Options {
    bool checkOnly = false;
    std::vector<std::string> scenarioFiles;
    std::string vcdFile;
    std::string waveFile;
};

// Writes the trace files the options ask for; false (with the reason on `err`) if one cannot be written.
bool WriteTraces(const Options& options, const Scenario& scenario, const TraceObserver& trace, std::ostream& err) {
    auto open = [&err](const std::string& name, std::ofstream& file) {
        file.open(name);
        if (!file) err << kProgram << ": cannot write " << name << "\n";
        return static_cast<bool>(file);
    };
    if (!options.vcdFile.empty()) {
        std::ofstream file;
        if (!open(options.vcdFile, file)) return false;
        pac::WriteVcd(trace.Recording(), file, {"pac", "pac_scenario " + scenario.name});
    }
    if (!options.waveFile.empty()) {
        std::ofstream file;
        if (!open(options.waveFile, file)) return false;
        WriteScenarioDiagram(scenario, trace, file);
    }
    return true;
}

// Reads `file` into `scenario` and prints the warnings of its unmet preconditions; kExitOk, or the exit
// code of the refusal (the reason on `err`).
int Load(const GvlNames& names, const std::string& file, Scenario& scenario, std::ostream& err) {
    try {
        scenario = ScenarioLoader(names).FromFile(file);
    } catch (const ScenarioError& e) {
        err << kProgram << ": invalid scenario " << file << ": " << e.what() << "\n";
        return kExitRefused;
    } catch (const std::exception& e) {
        err << kProgram << ": internal error while reading " << file << ": " << e.what() << "\n";
        return kExitInternalError;
    }
    // The run goes on: the warning says in advance why a request will be refused.
    for (const PreconditionWarning& warning : FindUnmetPreconditions(scenario)) {
        err << kProgram << ": warning: " << file << ": step " << warning.step + 1 << " ($.steps["
            << warning.step << "]): " << warning.message << "\n";
    }
    return kExitOk;
}

}  // namespace

int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    Options options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "-h" || arg == "--help") {
            Usage(out);
            return kExitOk;
        }
        if (arg == "--version") {
            out << kProgram << " (" << PAC_LIBRARY_TITLE << ") " << PAC_LIBRARY_VERSION << "\n";
            return kExitOk;
        }
        if (arg == "--check") {
            options.checkOnly = true;
        } else if (arg == "--vcd" || arg == "--wavedrom") {
            if (i + 1 >= args.size()) {
                err << kProgram << ": " << arg << " needs a file name\n";
                return kExitRefused;
            }
            (arg == "--vcd" ? options.vcdFile : options.waveFile) = args[++i];
        } else if (arg.size() > 1 && arg[0] == '-') {
            err << kProgram << ": unknown option " << arg << "\n";
            Usage(err);
            return kExitRefused;
        } else {
            options.scenarioFiles.push_back(arg);
        }
    }
    if (options.scenarioFiles.empty()) {
        Usage(err);
        return kExitRefused;
    }
    const GvlNames names;
    if (options.checkOnly) {
        // Each file checked on its own, all of them even after a refusal: the worst exit code counts.
        int worst = kExitOk;
        for (const std::string& file : options.scenarioFiles) {
            Scenario scenario;
            const int code = Load(names, file, scenario, err);
            if (code == kExitOk) {
                const auto steps = scenario.steps.size();
                out << file << ": valid scenario, " << steps << (steps == 1 ? " step\n" : " steps\n");
            }
            worst = std::max(worst, code);
        }
        return worst;
    }
    if (options.scenarioFiles.size() > 1) {
        err << kProgram << ": one scenario file at a time (got " << options.scenarioFiles[0] << " and "
            << options.scenarioFiles[1] << "); only --check takes several\n";
        return kExitRefused;
    }
    const std::string& scenarioFile = options.scenarioFiles[0];
    Scenario scenario;
    if (const int code = Load(names, scenarioFile, scenario, err); code != kExitOk) return code;
    try {
        TimelinePrinter printer(out, names);
        TraceObserver trace(scenario.modules);
        RunObservers observers({&printer, &trace});
        const RunReport report = ScenarioRunner(scenario).Run(observers);
        if (!WriteTraces(options, scenario, trace, err)) return kExitRefused;
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
