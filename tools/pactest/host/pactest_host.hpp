// pac-test's host: runs one test of a user's machine program scan by scan on the rig (PacRig) against
// the simulated PA-CONTROL, and writes its result (docs/user_tests.md). pac-test generates the part that
// knows the user's program (the Project: its tasks, tests, bus images and signals) and links it with
// this core; one process runs one test, so every test starts from a PLC and a controller at power-on.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pactest {

// A PLC task: its cycle and the programs it calls, in order.
struct Task {
    std::string name;
    int cycleMs = 1;
    std::vector<void (*)()> programs;
};

// A test FB: called after the programs of its task, in every scan of that task, until it finishes.
struct Test {
    std::string name;
    std::string task;
    void (*body)();
};

// A variable recorded in the VCD of a failing test: its path, C storage and kind.
struct Signal {
    enum class Kind { kBool, kUnsigned, kSigned, kReal, kLreal, kTime };
    std::string path;
    const void* data;
    Kind kind;
    int bytes;  // size of the integer types
};

// What pac-test generates from the symbol table and the wiring file.
struct Project {
    std::vector<Task> tasks;
    std::vector<Test> tests;
    void (*init)();  // the globals and the program instances, before the first scan
    // The bus images: the user's input variables from the bytes the scan read, the bytes to send from
    // the user's output variables; `bytes` is the layout's size.
    void (*copyIn)(const std::uint8_t* fromPac, std::size_t bytes);
    void (*copyOut)(std::uint8_t* toPac, std::size_t bytes);
    std::vector<Signal> signals;
};

// The assert record the vocabulary's native functions write to (pactest_natives.cpp). `caller`: the return
// address into the POU that called the POU of the assert, for an assert inside the vocabulary's own FBs
// (FB_AssertWithin): pac-test prints the line of the user's test that called it (addr2line).
void RecordAssert(const char* file, int line, bool passed, const std::string& message, const void* caller = nullptr);
void RecordFinished();
// the simulated clock since power-on in the running scan
std::chrono::nanoseconds Now();
// the running task's cycle and the cycles it has run, this one included (TwinCAT_SystemInfoVarList._TaskInfo)
std::chrono::milliseconds TaskCycle();
std::int64_t TaskCycles();
// TcUnit's TEST('name'): the asserts and TEST_FINISHED() that follow are that test's (one of a suite's tests)
void RecordTest(const std::string& name);
// TcUnit's TEST_FINISHED_NAMED('name')
void RecordTestFinished(const std::string& name);
// TcUnit's IS_TEST_FINISHED('name'): whether the running suite's test has finished
bool TestFinished(const std::string& name);
// TcUnit's TEST_ORDERED('name'): a test of the suite that runs once every ordered test called before it has
// finished; whether it runs now (it is then the current test, as after TEST('name'))
bool RecordTestOrdered(const std::string& name);

// `host --scenario FILE --test NAME --time-limit-ms N --result FILE [--vcd FILE] [--base-cycle-ms N]`
int Main(int argc, char** argv, const Project& project);

}  // namespace pactest
