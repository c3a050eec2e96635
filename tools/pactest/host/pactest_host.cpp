#include "pactest_host.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "controller_setup.hpp"
#include "gvl_names.hpp"
#include "pac/pac_rig.hpp"
#include "pac/rig_trace.hpp"
#include "pac/trace_recorder.hpp"
#include "pac/vcd_writer.hpp"
#include "scenario_error.hpp"
#include "scenario_loader.hpp"

namespace pactest {

namespace {

using std::chrono::milliseconds;
using std::chrono::nanoseconds;

struct Failure {
    std::string file;
    int line = 0;
    std::int64_t scan = 0;
    nanoseconds time{0};
    std::string message;
    std::string callerModule;   // the executable, for addr2line
    std::uintptr_t callerOffset = 0;  // the caller's return address within it
};

// What one test did: the natives write it, Main reads it. One test per process, so one record.
struct TestRecord {
    std::uint64_t asserts = 0;
    bool finished = false;
    // A TcUnit suite (an FB that EXTENDS FB_TestSuite) is one test here: its TEST('name')s, in the order first
    // called, and those that called TEST_FINISHED(); the suite ends once every one has finished.
    nanoseconds now{0};  // the simulated clock in the running scan (F_GetSystemTime)
    int taskCycleMs = 0;  // the running task's cycle and the cycles it has run (TwinCAT_SystemInfoVarList)
    std::int64_t taskCycles = 0;
    std::vector<std::string> tcunitTests;
    std::vector<std::string> tcunitFinished;
    std::vector<std::string> tcunitOrdered;  // the TEST_ORDERED('name')s, in the order first called
    std::string tcunitCurrent;
    std::int64_t scan = 0;
    nanoseconds time{0};
    std::vector<Failure> failures;
};

// The record of the test that runs; the vocabulary's natives are C functions without a context pointer.
TestRecord* running = nullptr;
constexpr std::size_t kMaxFailures = 1000;  // an assert failing in every scan of a long test

struct Options {
    std::string scenario;
    std::string test;
    std::string result;
    std::string vcd;
    bool vcdAlways = false;  // --vcd-when always: the VCD of a passing test too (to choose fault times)
    int timeLimitMs = 10000;
};

Options ParseOptions(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (i + 1 >= argc) throw std::invalid_argument("option " + arg + " needs a value");
        const std::string value = argv[++i];
        if (arg == "--scenario") options.scenario = value;
        else if (arg == "--test") options.test = value;
        else if (arg == "--result") options.result = value;
        else if (arg == "--vcd") options.vcd = value;
        else if (arg == "--vcd-when" && (value == "failed" || value == "always")) options.vcdAlways = value == "always";
        else if (arg == "--time-limit-ms") options.timeLimitMs = std::stoi(value);
        else throw std::invalid_argument("unknown option " + arg);
    }
    if (options.scenario.empty() || options.test.empty() || options.result.empty()) {
        throw std::invalid_argument(
            "usage: host --scenario FILE --test NAME --result FILE [--vcd FILE [--vcd-when failed|always]] "
            "[--time-limit-ms N]");
    }
    return options;
}

std::string JsonString(const std::string& text) {
    std::string out = "\"";
    for (const unsigned char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c < 0x20) {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
            out += buffer;
        } else {
            out += static_cast<char>(c);
        }
    }
    return out + "\"";
}

double Ms(nanoseconds t) { return static_cast<double>(t.count()) / 1e6; }

void WriteResult(const std::string& path, const std::string& test, const TestRecord& record, bool timedOut,
                 std::int64_t scans, nanoseconds end) {
    std::ofstream out(path);
    out << "{\"test\": " << JsonString(test) << ", \"finished\": " << (record.finished ? "true" : "false")
        << ", \"timed_out\": " << (timedOut ? "true" : "false") << ", \"scans\": " << scans
        << ", \"time_ms\": " << Ms(end) << ", \"asserts\": " << record.asserts << ", \"failures\": [";
    for (std::size_t i = 0; i < record.failures.size(); ++i) {
        const Failure& f = record.failures[i];
        out << (i ? ", " : "") << "{\"file\": " << JsonString(f.file) << ", \"line\": " << f.line
            << ", \"scan\": " << f.scan << ", \"time_ms\": " << Ms(f.time)
            << ", \"message\": " << JsonString(f.message);
        if (!f.callerModule.empty()) {
            out << ", \"caller_module\": " << JsonString(f.callerModule) << ", \"caller_offset\": " << f.callerOffset;
        }
        out << "}";
    }
    out << "]}\n";
    if (!out) throw std::runtime_error("cannot write " + path);
}

// A fault of the wiring file, at the time the scenario's wait steps before it add up to.
struct TimedFault {
    nanoseconds at;
    pac::scenario::FaultStep fault;
};

std::vector<TimedFault> Faults(const pac::scenario::Scenario& scenario) {
    std::vector<TimedFault> faults;
    nanoseconds at{0};
    for (const auto& step : scenario.steps) {
        if (const auto* wait = std::get_if<pac::scenario::WaitStep>(&step.action)) {
            at += milliseconds(wait->ms);
        } else if (const auto* fault = std::get_if<pac::scenario::FaultStep>(&step.action)) {
            faults.push_back({at, *fault});
        } else {
            throw pac::scenario::ScenarioError("$.steps", "a test's faults are wait_ms and fault steps only");
        }
    }
    return faults;
}

std::uint64_t ReadBits(const Signal& s) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, s.data, static_cast<std::size_t>(s.bytes));
    return bits;
}

void AddSignal(pac::TraceRecorder& recorder, const Signal& s) {
    switch (s.kind) {
        case Signal::Kind::kBool:
            recorder.AddBool(s.path, [s] { return *static_cast<const std::uint8_t*>(s.data) != 0; });
            return;
        case Signal::Kind::kReal:
            recorder.AddReal(s.path, [s] { return static_cast<double>(*static_cast<const float*>(s.data)); });
            return;
        case Signal::Kind::kLreal:
            recorder.AddReal(s.path, [s] { return *static_cast<const double*>(s.data); });
            return;
        case Signal::Kind::kTime:  // seconds and nanoseconds, as milliseconds
            recorder.AddReal(s.path, [s] {
                const long* t = static_cast<const long*>(s.data);
                return static_cast<double>(t[0]) * 1e3 + static_cast<double>(t[1]) / 1e6;
            });
            return;
        default:
            recorder.AddBits(s.path, s.bytes * 8, [s] { return ReadBits(s); });
    }
}

// Where each simulated axis really is (the bus modules are the rig's TraceBusModules).
void AddAxisPositions(pac::TraceRecorder& recorder, pac::PacRig& plc) {
    for (int k = 1; k <= plc.Layout().axisModules; ++k) {
        recorder.AddReal("sim.axis" + std::to_string(k) + ".Position",
                         [&plc, k] { return plc.Controller().Axes().Motion(k).Position(); });
    }
}

int Run(const Options& options, const Project& project) {
    const pac::scenario::GvlNames names;
    const auto scenario = pac::scenario::ScenarioLoader(names).FromFile(options.scenario);
    const Test* test = nullptr;
    for (const auto& t : project.tests) test = t.name == options.test ? &t : test;
    if (!test) throw std::invalid_argument("no test named " + options.test);
    const auto faults = Faults(scenario);

    TestRecord record;
    running = &record;
    pac::PacRig plc(pac::scenario::RigTimingOf(scenario.timing), pac::scenario::ControllerConfig(scenario.controller),
                    pac::scenario::Layout(scenario.modules));
    const int base = scenario.timing.plcCycleMs;
    project.init();
    plc.CallImage([&](const pac::sim::ProcessImage& fromPac, pac::sim::ProcessImage& toPac) {
        record.now = plc.Now();
        project.copyIn(fromPac.Data(), fromPac.Size());
        const std::int64_t scan = plc.Task().ScanCount();
        for (const Task& task : project.tasks) {
            if ((scan - 1) % (task.cycleMs / base) != 0) continue;
            record.taskCycleMs = task.cycleMs;
            record.taskCycles = (scan - 1) / (task.cycleMs / base) + 1;
            for (auto* program : task.programs) program();
            if (task.name == test->task && !record.finished) {
                record.scan = scan;
                record.time = plc.Now();
                test->body();
                record.tcunitCurrent.clear();
                if (!record.tcunitTests.empty() && record.tcunitFinished.size() == record.tcunitTests.size()) {
                    record.finished = true;
                }
            }
        }
        project.copyOut(&toPac[0], toPac.Size());
    });
    plc.Start();
    pac::scenario::ApplyControllerSetup(plc.Controller(), scenario.controller);

    pac::TraceRecorder recorder;
    const bool tracing = !options.vcd.empty();
    if (tracing) {
        for (const auto& signal : project.signals) AddSignal(recorder, signal);
        pac::TraceBusModules(recorder, plc);
        AddAxisPositions(recorder, plc);
    }
    const nanoseconds limit = milliseconds(options.timeLimitMs);
    bool timedOut = false;
    std::size_t next = 0;
    while (!record.finished) {
        while (next < faults.size() && faults[next].at <= plc.Now()) {
            pac::scenario::InjectFault(plc, faults[next++].fault);
        }
        if (plc.Now() >= limit) {
            timedOut = true;
            break;
        }
        plc.Scan();
        if (tracing) recorder.Sample(plc.Now());
    }
    running = nullptr;
    WriteResult(options.result, test->name, record, timedOut, plc.Task().ScanCount(), plc.Now());
    const bool passed = record.finished && record.failures.empty();
    if (tracing && (!passed || options.vcdAlways)) {
        std::ofstream vcd(options.vcd);
        pac::WriteVcd(recorder.Recording(), vcd, {"pactest", "pac-test: " + test->name});
    }
    return passed ? 0 : 1;
}

}  // namespace

namespace {

bool Contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

void RecordAssert(const char* file, int line, bool passed, const std::string& message, const void* caller) {
    if (!running) return;
    const std::string& test = running->tcunitCurrent;
    if (!test.empty() && Contains(running->tcunitFinished, test)) return;  // TcUnit: a finished test's asserts
    ++running->asserts;
    if (passed || running->failures.size() >= kMaxFailures) return;
    Failure failure{file, line, running->scan, running->time, test.empty() ? message : test + ": " + message, {}, 0};
    Dl_info info{};
    if (caller && dladdr(caller, &info) && info.dli_fname) {
        failure.callerModule = info.dli_fname;
        failure.callerOffset =
            reinterpret_cast<std::uintptr_t>(caller) - reinterpret_cast<std::uintptr_t>(info.dli_fbase);
    }
    running->failures.push_back(failure);
}

void RecordFinished() {
    if (!running) return;
    if (running->tcunitCurrent.empty()) {
        running->finished = true;
    } else {
        RecordTestFinished(running->tcunitCurrent);
    }
}

std::chrono::nanoseconds Now() {
    return running ? running->now : std::chrono::nanoseconds{0};
}

std::chrono::milliseconds TaskCycle() {
    return std::chrono::milliseconds(running ? running->taskCycleMs : 0);
}

std::int64_t TaskCycles() {
    return running ? running->taskCycles : 0;
}

void RecordTest(const std::string& name) {
    if (!running) return;
    running->tcunitCurrent = name;
    if (!Contains(running->tcunitTests, name)) running->tcunitTests.push_back(name);
}

bool RecordTestOrdered(const std::string& name) {
    if (!running) return false;
    if (!Contains(running->tcunitTests, name)) running->tcunitTests.push_back(name);  // the suite waits for it
    if (!Contains(running->tcunitOrdered, name)) running->tcunitOrdered.push_back(name);
    for (const std::string& before : running->tcunitOrdered) {
        if (before == name) break;
        if (!Contains(running->tcunitFinished, before)) return false;
    }
    if (Contains(running->tcunitFinished, name)) return false;
    running->tcunitCurrent = name;
    return true;
}

void RecordTestFinished(const std::string& name) {
    if (running && Contains(running->tcunitTests, name) && !Contains(running->tcunitFinished, name)) {
        running->tcunitFinished.push_back(name);
    }
}

bool TestFinished(const std::string& name) {
    return running && Contains(running->tcunitFinished, name);
}

int Main(int argc, char** argv, const Project& project) {
    try {
        return Run(ParseOptions(argc, argv), project);
    } catch (const pac::scenario::ScenarioError& e) {
        std::cerr << e.Path() << ": " << e.Reason() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "pac-test host: " << e.what() << "\n";
        return 3;
    }
}

}  // namespace pactest
