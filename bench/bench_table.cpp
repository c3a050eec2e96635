// Benchmark (not a test): the one table of docs/benchmarks.md, printed as Markdown by
// `cmake --build build --target bench`: scan cost of the library's FBs (callgrind instructions) next to a
// hand-written C of the CMD handshake, the axis and the CTRL module, simulation throughput, scale to 32
// PA-CONTROLs, and scans from Execute to Done against the protocol minimum. `bench_table --workload W
// --scans N` runs one workload for callgrind; `bench_table --only throughput,scale` prints only those sections.
#include <sys/utsname.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "callgrind_count.hpp"
#include "latency.hpp"
#include "plant.hpp"
#include "workloads.hpp"

namespace {

using namespace pac::bench;
using std::chrono::milliseconds;

constexpr double kHandWrittenGoal = 1.5;        // FB_PAC_Cmd <= 1.5 x the hand-written C
constexpr double kThroughputGoal = 1000000.0;   // scans per CPU second, one plant
constexpr double kRealTimeGoal = 100.0;         // 32 plants at 1 ms
constexpr int kCostScans = 2000;
constexpr int kPlantScansPerRun = 200000;  // a few tenths of a CPU second per timed run

double CpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

std::string SelfPath() {
    char path[4096];
    const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
    if (n <= 0) throw std::runtime_error("cannot find this program's path");
    return std::string(path, static_cast<std::size_t>(n));
}

std::string CpuModel() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    }
    return "unknown CPU";
}

std::string LoadAverage() {
    double load[3] = {0, 0, 0};
    if (getloadavg(load, 3) != 3) return "unknown";
    char text[64];
    std::snprintf(text, sizeof text, "%.2f %.2f %.2f", load[0], load[1], load[2]);
    return text;
}

std::string Number(double value, int decimals = 0) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    // thousands separators for the integer part
    std::string s = text;
    std::size_t end = s.find('.');
    if (end == std::string::npos) end = s.size();
    for (std::ptrdiff_t i = static_cast<std::ptrdiff_t>(end) - 3; i > (s[0] == '-' ? 1 : 0); i -= 3) {
        s.insert(static_cast<std::size_t>(i), ",");
    }
    return s;
}

std::string Met(bool met) { return met ? "met" : "**not met**"; }

void PrintMachine() {
    utsname u{};
    uname(&u);
    std::printf("Machine: %s, %u cores, %s %s; load average at the start %s; compiler %s, %s build.\n\n",
                CpuModel().c_str(), std::thread::hardware_concurrency(), u.sysname, u.release, LoadAverage().c_str(),
                __VERSION__, PAC_BENCH_BUILD_TYPE);
}

// ---- scan cost ------------------------------------------------------------------------------------------

struct CostPair {
    std::optional<CallgrindCount> idle;
    std::optional<CallgrindCount> job;
};

CostPair Cost(const std::string& self, const std::string& prefix, const std::vector<std::string>& functions) {
    return {CountInstructions(self, prefix + "-idle", functions, kCostScans),
            CountInstructions(self, prefix + "-job", functions, kCostScans)};
}

std::string Cell(const std::optional<CallgrindCount>& c) { return c ? Number(c->instructionsPerScan) : "failed"; }

std::string Jobs(const std::optional<CallgrindCount>& c) { return c ? std::to_string(c->jobs) : "-"; }

// The library's CMD interface for one caller, FB_PAC_Axis and FB_PAC_Ctrl agree with their hand-written C on
// every scan, on timings that make the waits differ: a cost comparison of two programs that do different things would
// say nothing.
int PrintSideBySide() {
    int failures = 0;
    int timings = 0;
    for (int plcMs : {1, 2, 5}) {
        for (int pacMs : {1, 3, 10}) {
            for (int latency : {0, 2}) {
                pac::RigTiming timing;
                timing.plcCycle = milliseconds(plcMs);
                timing.pacCycle = milliseconds(pacMs);
                timing.latencyCycles = latency;
                timings++;
                for (const auto& [what, difference] :
                     {std::pair<const char*, std::string>{"the CMD FBs", CompareWithHandWritten(timing, kCostScans)},
                      {"FB_PAC_Axis", CompareAxisWithHandWritten(timing, kCostScans)},
                      {"FB_PAC_Ctrl", CompareCtrlWithHandWritten(timing, kCostScans)}}) {
                    if (difference.empty()) continue;
                    std::printf("The hand-written C and %s differ (PLC %d ms, controller %d ms, latency %d): %s.\n\n",
                                what, plcMs, pacMs, latency, difference.c_str());
                    failures++;
                }
            }
        }
    }
    if (failures == 0) {
        std::printf("Side by side on %d timings (PLC cycle 1, 2, 5 ms x controller cycle 1, 3, 10 ms x bus latency "
                    "0, 2 cycles), %d scans each: the hand-written C of the CMD interface, with writes, reads and a "
                    "refused code, writes the same CMD module and gives the same outputs and handshake history as "
                    "the FBs in every scan; the hand-written C of the axis, with absolute and relative moves, resets "
                    "of \"displaced\", a refused velocity, Abort, Axis OFF, DISABLE DRIVE, superseded jobs, ONLINE "
                    "stopped and started again and a lost link, writes the same axis module and gives the same outputs as FB_PAC_Axis in every scan; "
                    "the hand-written C of FB_PAC_Ctrl, with every request in turn (ONLINE, a STOP, a start from "
                    "stopped, CANCEL, RESET ERROR, AUTOMATIC, a STOP that does not apply, none), both number formats "
                    "and a lost link, writes the same CTRL module and gives the same outputs as the FB in every "
                    "scan.\n\n",
                    timings, kCostScans);
    }
    return failures;
}

int PrintScanCost(const std::string& self) {
    std::printf("### Scan cost\n\nInstructions per scan in the FBs' bodies (callgrind, their callees included), "
                "mean over %d scans: idle (no job) and during jobs (one after the other, Execute low for one "
                "scan between them). The CMD interface of a program with one command caller is "
                "FB_PAC_CmdInterface plus one FB_PAC_Cmd; the hand-written C (bench/cmd_handshake.c) does the same "
                "for one caller, without what only sharing needs (ids, tickets, the queue, the owner's "
                "keep-alive), in plain C without IEC wrappers; bench/axis_hand.c does what FB_PAC_Axis does for one "
                "axis, without jog, ChangeDynamics and ResetError, and bench/ctrl_hand.c what FB_PAC_Ctrl does. Each "
                "/ hand-written C is against its own. Not counted on either side: the bench copying the "
                "images in and out (the channel too, on MATIEC's C; on pacst's the FB works on it).\n\n", kCostScans);
    int failures = PrintSideBySide();
    if (!ValgrindAvailable()) {
        std::printf("valgrind not found: no scan cost (apt-get install valgrind).\n\n");
        return failures;
    }
    const CostPair both = Cost(self, "cmd", {measured::kCmd, measured::kCmdInterface});
    const CostPair cmd = Cost(self, "cmd", {measured::kCmd});
    const CostPair interface = Cost(self, "cmd", {measured::kCmdInterface});
    const CostPair hand = Cost(self, "c", {measured::kHandWritten});
    const CostPair ctrl = Cost(self, "ctrl", {measured::kCtrl});
    const CostPair ctrlHand = Cost(self, "ctrl-c", {measured::kCtrlHandWritten});
    const CostPair axis = Cost(self, "axis", {measured::kAxis});
    const CostPair axisHand = Cost(self, "axis-c", {measured::kAxisHandWritten});
    const CostPair automatic = Cost(self, "automatic", {measured::kAutomatic});
    std::printf("| function block | idle | during a job | the job | jobs done | / hand-written C (job) | goal |\n"
                "|---|---:|---:|---|---:|---:|---|\n");
    const auto ratioTo = [](const std::optional<CallgrindCount>& c, const std::optional<CallgrindCount>& by) {
        return c && by ? Number(c->instructionsPerScan / by->instructionsPerScan, 2) + "x" : std::string("-");
    };
    const auto ratio = [&](const std::optional<CallgrindCount>& c) { return ratioTo(c, hand.job); };
    std::string goal = "-";
    if (both.job && hand.job) {
        const double r = both.job->instructionsPerScan / hand.job->instructionsPerScan;
        goal = "<= " + Number(kHandWrittenGoal, 1) + "x: " + Met(r <= kHandWrittenGoal);
        if (both.job->jobs != hand.job->jobs) {
            std::printf("The hand-written handshake finished %ld jobs, the FBs %ld: they differ.\n\n",
                        hand.job->jobs, both.job->jobs);
            failures++;
        }
    }
    if (ctrl.job && ctrlHand.job && ctrl.job->jobs != ctrlHand.job->jobs) {
        std::printf("The hand-written CTRL finished %ld requests, FB_PAC_Ctrl %ld: they differ.\n\n", ctrlHand.job->jobs,
                    ctrl.job->jobs);
        failures++;
    }
    if (axis.job && axisHand.job && axis.job->jobs != axisHand.job->jobs) {
        std::printf("The hand-written axis finished %ld moves, FB_PAC_Axis %ld: they differ.\n\n", axisHand.job->jobs,
                    axis.job->jobs);
        failures++;
    }
    std::printf("| FB_PAC_CmdInterface + FB_PAC_Cmd (one caller) | %s | %s | write / read N1 | %s | %s | %s |\n",
                Cell(both.idle).c_str(), Cell(both.job).c_str(), Jobs(both.job).c_str(), ratio(both.job).c_str(),
                goal.c_str());
    std::printf("| of which FB_PAC_Cmd | %s | %s | | | %s | - |\n", Cell(cmd.idle).c_str(), Cell(cmd.job).c_str(),
                ratio(cmd.job).c_str());
    std::printf("| of which FB_PAC_CmdInterface | %s | %s | | | %s | - |\n", Cell(interface.idle).c_str(),
                Cell(interface.job).c_str(), ratio(interface.job).c_str());
    std::printf("| CMD interface by hand in C, one caller | %s | %s | write / read N1 | %s | 1.00x | - |\n",
                Cell(hand.idle).c_str(), Cell(hand.job).c_str(), Jobs(hand.job).c_str());
    std::printf("| FB_PAC_Ctrl | %s | %s | STOP / START ONLINE | %s | %s | - |\n", Cell(ctrl.idle).c_str(),
                Cell(ctrl.job).c_str(), Jobs(ctrl.job).c_str(), ratioTo(ctrl.job, ctrlHand.job).c_str());
    std::printf("| FB_PAC_Ctrl by hand in C | %s | %s | STOP / START ONLINE | %s | 1.00x | - |\n",
                Cell(ctrlHand.idle).c_str(), Cell(ctrlHand.job).c_str(), Jobs(ctrlHand.job).c_str());
    std::printf("| FB_PAC_Axis (one axis) | %s | %s | absolute moves 0 / 20 | %s | %s | - |\n",
                Cell(axis.idle).c_str(), Cell(axis.job).c_str(), Jobs(axis.job).c_str(),
                ratioTo(axis.job, axisHand.job).c_str());
    std::printf("| FB_PAC_Axis by hand in C, one axis | %s | %s | absolute moves 0 / 20 | %s | 1.00x | - |\n",
                Cell(axisHand.idle).c_str(), Cell(axisHand.job).c_str(), Jobs(axisHand.job).c_str());
    std::printf("| FB_PAC_AutomaticModule (one module) | %s | %s | HOME POSITION / AUTOMATIC, new N1 each scan, "
                "N17 back | %s | - | - |\n\n", Cell(automatic.idle).c_str(), Cell(automatic.job).c_str(),
                Jobs(automatic.job).c_str());
    return failures;
}

// ---- throughput and scale -------------------------------------------------------------------------------

// Scans of all `plants` together per CPU second, best of three runs of `scans` scans.
double ScansPerCpuSecond(std::vector<std::unique_ptr<Plant>>& plants, int scans) {
    double best = 0;
    for (int run = 0; run < 3; ++run) {
        const double start = CpuSeconds();
        for (int i = 0; i < scans; ++i) {
            for (auto& plant : plants) plant->Scan();
        }
        const double rate = scans / (CpuSeconds() - start);
        best = rate > best ? rate : best;
    }
    return best;
}

void PrintThroughput(const std::string& self) {
    std::printf("### Simulation throughput\n\nOne PA-CONTROL with CMD, CTRL and 8 axis modules; FB_PAC_Cmd "
                "writes and reads a register without pause, every axis moves back and forth (bench/plant.hpp); "
                "PLC cycle 1 ms. Instructions per scan from callgrind (deterministic), scans per CPU second "
                "measured (best of 3).\n\n");
    std::printf("| PA-CONTROL cycle | instructions per scan | of which FBs | of which simulator | "
                "scans per CPU second | goal >= %s |\n|---|---:|---:|---:|---:|---|\n", Number(kThroughputGoal).c_str());
    const bool valgrind = ValgrindAvailable();
    for (int pacMs : {10, 1}) {
        const std::string workload = "plant-pac" + std::to_string(pacMs);
        std::string all = "-", fbs = "-", sim = "-";
        if (valgrind) {
            const auto total = CountInstructions(self, workload, {measured::kScan}, kCostScans);
            const auto fb = CountInstructions(
                self, workload, {measured::kCmdInterface, measured::kCmd, measured::kCtrl, measured::kAxis}, kCostScans);
            const auto simulator = CountInstructions(
                self, workload, {measured::kSimulator, measured::kBusRead, measured::kBusWrite}, kCostScans);
            all = Cell(total);
            if (total && fb) fbs = Cell(fb) + " (" + Number(100 * fb->instructionsPerScan / total->instructionsPerScan) + " %)";
            if (total && simulator) {
                sim = Cell(simulator) + " (" +
                      Number(100 * simulator->instructionsPerScan / total->instructionsPerScan) + " %)";
            }
        }
        auto plants = OnlinePlants(1, milliseconds(pacMs));
        const double rate = ScansPerCpuSecond(plants, kPlantScansPerRun);
        std::printf("| %d ms | %s | %s | %s | %s | %s |\n", pacMs, all.c_str(), fbs.c_str(), sim.c_str(),
                    Number(rate).c_str(), Met(rate >= kThroughputGoal).c_str());
    }
    std::printf("\n");
}

void PrintScale() {
    std::printf("### Scale\n\nPA-CONTROLs as above (CMD, CTRL, 8 axes moving) in one process on one core, scanned one "
                "after the other in each 1 ms PLC cycle, at the goal's controller cycle of 1 ms and at the default "
                "of 10 ms. Multiple of real time: simulated seconds per CPU second.\n\n");
    std::printf("| PA-CONTROL cycle | PA-CONTROLs | PLC cycles per CPU second | multiple of real time | CPU per "
                "controller and scan | vs. 1 controller | goal >= %sx at 32, 1 ms |\n|---|---:|---:|---:|---:|---:|---|\n",
                Number(kRealTimeGoal).c_str());
    for (int pacMs : {1, 10}) {
        double single = 0;
        for (int count : {1, 2, 4, 8, 16, 32}) {
            auto plants = OnlinePlants(count, milliseconds(pacMs));
            const double cycles = ScansPerCpuSecond(plants, kPlantScansPerRun / count);
            const double perController = 1e6 / (cycles * count);  // microseconds
            if (count == 1) single = perController;
            const double realTime = cycles / 1000.0;
            std::string goal;
            if (count == 32) goal = pacMs == 1 ? Met(realTime >= kRealTimeGoal) : "-";
            std::printf("| %d ms | %d | %s | %sx | %s us | %sx | %s |\n", pacMs, count, Number(cycles).c_str(),
                        Number(realTime, 1).c_str(), Number(perController, 2).c_str(),
                        Number(perController / single, 2).c_str(), goal.c_str());
        }
    }
    std::printf("\n");
}

// ---- latency --------------------------------------------------------------------------------------------

template <class Measure>
LatencyRow OverTimings(int latency, const Measure& measure) {
    LatencyRow all;
    for (int plcMs : {1, 2, 5, 10}) {
        for (int pacMs : {1, 3, 10}) {
            pac::RigTiming timing;
            timing.plcCycle = milliseconds(plcMs);
            timing.pacCycle = milliseconds(pacMs);
            timing.latencyCycles = latency;
            all.Merge(measure(timing));
        }
    }
    return all;
}

void PrintLatencyRow(const std::string& what, int latency, const LatencyRow& row) {
    std::printf("| %s | %d | %d | %d..%d | %d..%d | %d |\n", what.c_str(), latency, row.commands, row.scansMin,
                row.scansMax, row.minimumMin, row.minimumMax, row.aboveMinimum);
}

int PrintLatency() {
    std::printf("### Latency\n\nScans from the Execute edge to Done against the protocol minimum (the image "
                "reaches the controller after the bus latency, its next cycle answers, the answer travels back, "
                "the next scan reads it), on every PLC cycle (1, 2, 5, 10 ms) x controller cycle (1, 3, 10 ms) "
                "for each bus latency. Shared interface: FB_PAC_WriteIntReg and FB_PAC_ReadIntReg in turn on "
                "the one CMD interface, all started in the same scan; Done of the last one against the protocol "
                "minima of the commands one after the other. Each run starts past the CMD interface's first "
                "handshake after the PLC cold start (the parked read, acknowledged before any command may go "
                "out).\n\n");
    std::printf("| FBs | bus latency [PLC cycles] | jobs | scans | protocol minimum | later than the minimum |\n"
                "|---|---:|---:|---:|---:|---:|\n");
    int late = 0;
    for (int latency = 0; latency <= 3; ++latency) {
        const LatencyRow row = OverTimings(latency, [](const pac::RigTiming& t) { return MeasureCmd(t, 200); });
        late += row.aboveMinimum;
        PrintLatencyRow("FB_PAC_Cmd", latency, row);
    }
    for (int fbs : {2, 4, 8}) {
        for (int latency : {0, 2}) {
            const LatencyRow row =
                OverTimings(latency, [fbs](const pac::RigTiming& t) { return MeasureShared(t, fbs, 20); });
            late += row.aboveMinimum;
            PrintLatencyRow(std::to_string(fbs) + " element FBs, shared", latency, row);
        }
    }
    std::printf("\n");
    return late;
}

// The shared interface's capacity: commands per second through one CMD interface as more FBs share it.
int PrintSharedRate() {
    constexpr int kScans = 20000;
    std::printf("#### Shared interface: commands per second\n\nElement FBs (FB_PAC_WriteIntReg and "
                "FB_PAC_ReadIntReg in turn) on one CMD interface, each sending its next command as soon as its "
                "last one is final (Execute low for one scan), %d scans at a PLC cycle of 1 ms, bus latency 0. "
                "Commands Done per simulated second, all FBs together, against the protocol's bound (the same "
                "commands back to back, each acknowledged at the protocol minimum from the scan it was sent in), "
                "and the fewest and most any one FB got (the queue serves them in turn). One FB alone pays its "
                "release and edge scans; with several, the FB whose turn it is sends a scan later when the PLC "
                "calls it before the FB that ended.\n\n", kScans);
    std::printf("| FBs | controller cycle | commands per second | of the protocol's bound | vs. one FB | "
                "Done per FB (fewest..most) | errors |\n|---:|---:|---:|---:|---:|---|---:|\n");
    int errors = 0;
    for (int pacMs : {1, 3, 10}) {
        double single = 0;
        for (int fbs : {1, 2, 4, 8}) {
            pac::RigTiming timing;
            timing.pacCycle = milliseconds(pacMs);
            const SharedRate rate = MeasureSharedRate(timing, fbs, kScans);
            if (fbs == 1) single = rate.commandsPerSecond;
            errors += static_cast<int>(rate.errors);
            const double ofBound = rate.protocolPerSecond > 0 ? 100.0 * rate.commandsPerSecond / rate.protocolPerSecond : 0;
            std::printf("| %d | %d ms | %s | %s %% | %sx | %ld..%ld | %ld |\n", fbs, pacMs,
                        Number(rate.commandsPerSecond).c_str(), Number(ofBound).c_str(),
                        Number(rate.commandsPerSecond / single, 2).c_str(), rate.fewestPerFb, rate.mostPerFb,
                        rate.errors);
        }
    }
    std::printf("\n");
    return errors;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        if (argc == 5 && std::string(argv[1]) == "--workload" && std::string(argv[3]) == "--scans") {
            const WorkloadResult r = RunWorkload(argv[2], std::atoi(argv[4]));
            std::printf("scans %d jobs %ld\n", r.scans, r.jobs);
            return 0;
        }
        // `--only throughput,scale` prints only the sections named (scan-cost, throughput, scale, latency):
        // the throughput and scale rows take a minute, the whole table much longer.
        std::string only;
        if (argc == 3 && std::string(argv[1]) == "--only") {
            only = "," + std::string(argv[2]) + ",";
        } else if (argc != 1) {
            std::fprintf(stderr, "usage: bench_table [--only SECTION,...] | --workload W --scans N\n");
            return 2;
        }
        const auto wanted = [&only](const char* section) {
            return only.empty() || only.find("," + std::string(section) + ",") != std::string::npos;
        };
        const std::string self = SelfPath();
        PrintMachine();
        int failures = 0;
        if (wanted("scan-cost")) failures += PrintScanCost(self);
        if (wanted("throughput")) PrintThroughput(self);
        if (wanted("scale")) PrintScale();
        if (wanted("latency")) failures += PrintLatency() + PrintSharedRate();
        std::printf("Load average at the end: %s\n", LoadAverage().c_str());
        return failures == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_table: %s\n", e.what());
        return 2;
    }
}
