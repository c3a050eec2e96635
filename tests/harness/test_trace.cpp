// Traces: a Trace keeps each signal's changes and answers the value of any sample; a TraceRecorder on a
// PlcTask samples the outputs of every scan at the scan's time; WriteVcd writes IEEE 1364 VCD (header,
// nested scopes, $dumpvars, then only the changes); DumpVcd / ScopedVcdDump write a test's trace.
// tests/scenario/vcd_readback.py reads pac_scenario's VCD back with an independent reader (pyvcd).
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "pac/plc_task.hpp"
#include "pac/sim_clock.hpp"
#include "pac/trace.hpp"
#include "pac/trace_dump.hpp"
#include "pac/trace_recorder.hpp"
#include "pac/vcd_writer.hpp"

using namespace std::chrono_literals;

namespace {

pac::TraceValue Bits(std::uint64_t bits) { return {bits, 0.0}; }

TEST(Trace, KeepsOnlyChangesAndAnswersEverySample) {
    pac::Trace trace;
    const auto flag = trace.AddSignal({"cmd.Busy", pac::SignalKind::kBits, 1});
    const auto word = trace.AddSignal({"cmd.Word", pac::SignalKind::kBits, 16});
    trace.Append(1ms, {Bits(0), Bits(0x1234)});
    trace.Append(2ms, {Bits(1), Bits(0x1234)});
    trace.Append(3ms, {Bits(1), Bits(0x1234)});
    trace.Append(4ms, {Bits(0), Bits(0xABCD)});
    ASSERT_EQ(trace.Samples(), 4u);
    EXPECT_EQ(trace.Changes(flag).size(), 3u);  // samples 0, 1, 3
    EXPECT_EQ(trace.Changes(word).size(), 2u);  // samples 0, 3
    const std::uint64_t busy[] = {0, 1, 1, 0};
    for (std::size_t s = 0; s < 4; ++s) EXPECT_EQ(trace.ValueAt(flag, s).bits, busy[s]) << s;
    EXPECT_EQ(trace.ValueAt(word, 2).bits, 0x1234u);
    EXPECT_EQ(trace.ValueAt(word, 3).bits, 0xABCDu);
    EXPECT_EQ(trace.TimeOf(3), 4ms);
    EXPECT_EQ(trace.Find("cmd.Word"), word);
    EXPECT_EQ(trace.Signals()[word].Scope(), "cmd");
    EXPECT_EQ(trace.Signals()[word].Name(), "Word");
}

TEST(Trace, CutsValuesToTheSignalsWidth) {
    pac::Trace trace;
    trace.AddSignal({"b", pac::SignalKind::kBits, 8});
    trace.Append(1ms, {Bits(0x1FF)});
    EXPECT_EQ(trace.ValueAt(0, 0).bits, 0xFFu);
}

TEST(Trace, RefusesWhatItCouldNotRecordFaithfully) {
    pac::Trace trace;
    EXPECT_THROW(trace.AddSignal({"", pac::SignalKind::kBits, 1}), std::invalid_argument);
    EXPECT_THROW(trace.AddSignal({"scope.", pac::SignalKind::kBits, 1}), std::invalid_argument);
    EXPECT_THROW(trace.AddSignal({"FB one.Busy", pac::SignalKind::kBits, 1}), std::invalid_argument);
    EXPECT_THROW(trace.AddSignal({"wide", pac::SignalKind::kBits, 65}), std::invalid_argument);
    EXPECT_THROW(trace.AddSignal({"none", pac::SignalKind::kBits, 0}), std::invalid_argument);
    trace.AddSignal({"a", pac::SignalKind::kBits, 1});
    EXPECT_THROW(trace.AddSignal({"a", pac::SignalKind::kBits, 1}), std::invalid_argument);
    EXPECT_THROW(trace.Append(1ms, {}), std::invalid_argument);
    trace.Append(2ms, {Bits(1)});
    EXPECT_THROW(trace.Append(2ms, {Bits(0)}), std::invalid_argument) << "times must increase";
    EXPECT_THROW(trace.AddSignal({"late", pac::SignalKind::kBits, 1}), std::invalid_argument);
    EXPECT_THROW(trace.Find("missing"), std::out_of_range);
    EXPECT_THROW(trace.ValueAt(0, 1), std::out_of_range);
}

TEST(TraceRecorder, SamplesTheOutputsOfEveryScanAtItsTime) {
    pac::SimClock clock;
    pac::PlcTask task(clock, 2ms);
    int counter = 0;
    task.AddProgram([&] { ++counter; });
    pac::TraceRecorder recorder;
    recorder.AddBits("counter", 8, [&] { return static_cast<std::uint64_t>(counter); });
    recorder.AddBool("odd", [&] { return counter % 2 == 1; });
    recorder.AddReal("half", [&] { return counter / 2.0; });
    recorder.AttachTo(task);
    for (int i = 0; i < 3; ++i) task.Scan();
    const pac::Trace& trace = recorder.Recording();
    ASSERT_EQ(trace.Samples(), 3u);
    for (std::size_t s = 0; s < 3; ++s) {
        EXPECT_EQ(trace.TimeOf(s), (s + 1) * 2ms);
        EXPECT_EQ(trace.ValueAt(0, s).bits, s + 1) << "the counter after the scan's program ran";
        EXPECT_EQ(trace.ValueAt(1, s).bits, (s + 1) % 2);
        EXPECT_EQ(trace.ValueAt(2, s).real, (s + 1) / 2.0);
    }
    EXPECT_THROW(recorder.AddBool("late", [] { return true; }), std::invalid_argument);
    EXPECT_THROW(recorder.AddBool("empty", nullptr), std::invalid_argument);
}

TEST(WriteVcd, WritesHeaderScopesDumpvarsAndThenOnlyTheChanges) {
    pac::Trace trace;
    trace.AddSignal({"cmd.Execute", pac::SignalKind::kBits, 1});
    trace.AddSignal({"cmd.ToPac", pac::SignalKind::kBits, 16});
    trace.AddSignal({"axis1.fb.Position", pac::SignalKind::kReal, 64});
    trace.AddSignal({"cmd.Done", pac::SignalKind::kBits, 1});
    trace.Append(2ms, {Bits(0), Bits(0x1906), {0, 0.0}, Bits(0)});
    trace.Append(4ms, {Bits(1), Bits(0x9906), {0, 0.0}, Bits(0)});
    trace.Append(6ms, {Bits(1), Bits(0x9906), {0, 0.0}, Bits(0)});  // nothing changes: no time stamp
    trace.Append(8ms, {Bits(1), Bits(0x9906), {0, 12.5}, Bits(1)});
    std::ostringstream vcd;
    pac::WriteVcd(trace, vcd, {"pac", "a test"});
    const std::string expected =
        "$comment a test $end\n"
        "$version PA-CONTROL PLC library trace (pac::WriteVcd) $end\n"
        "$timescale 1 ns $end\n"
        "$scope module pac $end\n"
        "$scope module cmd $end\n"
        "$var wire 1 ! Execute $end\n"
        "$var wire 16 \" ToPac $end\n"
        "$var wire 1 $ Done $end\n"
        "$upscope $end\n"
        "$scope module axis1 $end\n"
        "$scope module fb $end\n"
        "$var real 64 # Position $end\n"
        "$upscope $end\n"
        "$upscope $end\n"
        "$upscope $end\n"
        "$enddefinitions $end\n"
        "#2000000\n"
        "$dumpvars\n"
        "0!\n"
        "b1100100000110 \"\n"
        "r0 #\n"
        "0$\n"
        "$end\n"
        "#4000000\n"
        "1!\n"
        "b1001100100000110 \"\n"
        "#8000000\n"
        "r12.5 #\n"
        "1$\n";
    EXPECT_EQ(vcd.str(), expected);
}

// A viewer ends the waveform at the last time stamp: scans after the last change must still show.
TEST(WriteVcd, EndsAtTheLastSampleAlsoWhenNothingChangedInIt) {
    pac::Trace trace;
    trace.AddSignal({"cmd.Execute", pac::SignalKind::kBits, 1});
    trace.Append(2ms, {Bits(0)});
    trace.Append(4ms, {Bits(1)});
    trace.Append(6ms, {Bits(1)});
    trace.Append(8ms, {Bits(1)});
    std::ostringstream vcd;
    pac::WriteVcd(trace, vcd);
    const std::string text = vcd.str();
    const std::string changes = text.substr(text.find("$enddefinitions $end\n"));
    EXPECT_EQ(changes, "$enddefinitions $end\n#2000000\n$dumpvars\n0!\n$end\n#4000000\n1!\n#8000000\n");
}

TEST(WriteVcd, GivesEverySignalItsOwnIdentifierBeyondOneCharacter) {
    pac::Trace trace;
    for (int i = 0; i < 200; ++i) trace.AddSignal({"s" + std::to_string(i), pac::SignalKind::kBits, 1});
    std::ostringstream vcd;
    pac::WriteVcd(trace, vcd);
    std::istringstream lines(vcd.str());
    std::set<std::string> codes;
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("$var ", 0) != 0) continue;
        std::istringstream words(line);
        std::string var, type, width, code;
        words >> var >> type >> width >> code;
        for (char c : code) EXPECT_TRUE(c >= '!' && c <= '~') << line;
        EXPECT_TRUE(codes.insert(code).second) << "identifier used twice: " << line;
    }
    EXPECT_EQ(codes.size(), 200u);
}

class TraceDump : public ::testing::Test {
protected:
    void SetUp() override {
        // One folder per test: ctest runs the cases of a suite in parallel processes.
        dir_ = std::filesystem::path(::testing::TempDir()) /
               ("pac_trace_dump." + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::remove_all(dir_);
        setenv("PAC_TRACE_DIR", dir_.c_str(), 1);
        unsetenv("PAC_TRACE_ALL");
        trace_.AddSignal({"x", pac::SignalKind::kBits, 1});
        trace_.Append(1ms, {Bits(1)});
    }
    void TearDown() override { unsetenv("PAC_TRACE_DIR"); }

    std::filesystem::path dir_;
    pac::Trace trace_;
};

TEST_F(TraceDump, WritesTheTestsTraceNamedAfterIt) {
    const auto path = pac::DumpVcd(trace_, "part");
    EXPECT_EQ(path, dir_ / "TraceDump.WritesTheTestsTraceNamedAfterIt.part.vcd");
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_NE(text.str().find("$var wire 1 ! x $end"), std::string::npos) << text.str();
}

TEST_F(TraceDump, ScopedDumpWritesNothingForAPassingTestUnlessAsked) {
    { pac::ScopedVcdDump dump(trace_); }
    EXPECT_FALSE(std::filesystem::exists(dir_));
    setenv("PAC_TRACE_ALL", "1", 1);
    { pac::ScopedVcdDump dump(trace_); }
    unsetenv("PAC_TRACE_ALL");
    EXPECT_TRUE(std::filesystem::exists(dir_ / "TraceDump.ScopedDumpWritesNothingForAPassingTestUnlessAsked.vcd"));
}

}  // namespace
