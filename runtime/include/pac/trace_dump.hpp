// GoogleTest helper: writes what a test recorded as a VCD file to open in GTKWave, named after the
// test (<Suite>.<Test>.vcd, '/' of parameterised names as '_') in $PAC_TRACE_DIR, or else in "traces"
// under the working directory (ctest runs a suite in its build folder: build/tests/library/traces).
//
//   pac::TraceRecorder recorder;  ... signals, recorder.AttachTo(task) ...
//   pac::ScopedVcdDump dump(recorder.Recording());  // written if the test fails (always with PAC_TRACE_ALL set)
#pragma once

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "pac/trace.hpp"
#include "pac/vcd_writer.hpp"

namespace pac {

inline std::filesystem::path TraceDumpDir() {
    const char* dir = std::getenv("PAC_TRACE_DIR");
    return dir != nullptr && *dir != '\0' ? std::filesystem::path(dir) : std::filesystem::path("traces");
}

// Writes `trace` now as <dir>/<Suite>.<Test>[.<part>].vcd, says where on stdout and returns the path.
inline std::filesystem::path DumpVcd(const Trace& trace, const std::string& part = "") {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = test == nullptr ? "trace" : std::string(test->test_suite_name()) + "." + test->name();
    if (!part.empty() && name.find(part) == std::string::npos) name += "." + part;  // a parameter's name may hold it
    for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
    }
    const std::filesystem::path dir = TraceDumpDir();
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = dir / (name + ".vcd");
    std::ofstream out(path);
    WriteVcd(trace, out, {"pac", name});
    if (!out) ADD_FAILURE() << "could not write the trace " << path;
    std::cout << "[ TRACE    ] " << std::filesystem::absolute(path).string() << "\n";
    return path;
}

// Dumps the trace when it goes out of scope if the test has failed by then, or in any case when the
// environment variable PAC_TRACE_ALL is set. The trace must outlive it.
class ScopedVcdDump {
public:
    explicit ScopedVcdDump(const Trace& trace, std::string part = "") : trace_(trace), part_(std::move(part)) {}
    ScopedVcdDump(const ScopedVcdDump&) = delete;
    ScopedVcdDump& operator=(const ScopedVcdDump&) = delete;
    ~ScopedVcdDump() {
        if (::testing::Test::HasFailure() || std::getenv("PAC_TRACE_ALL") != nullptr) DumpVcd(trace_, part_);
    }

private:
    const Trace& trace_;
    std::string part_;
};

}  // namespace pac
