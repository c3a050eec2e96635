// docs/testing.md, "Traces of a test": the recorder's calls, in a test that runs them.
#include "pac/fb_instance.hpp"
#include "pac/scan_test.hpp"
#include "pac/st_program.hpp"
// doc-example begin
#include "pac/trace_dump.hpp"
#include "pac/trace_recorder.hpp"
// doc-example end

class TraceExampleTest : public pac::ScanTest {};

TEST_F(TraceExampleTest, RecordsTheChosenSignals) {
    auto cmd = PAC_FB(FB_PAC_CMD);
    task_.AddProgram([&] { cmd(); });
    // doc-example begin
    pac::TraceRecorder trace;
    trace.AddBool("cmd.Execute", [&] { return cmd->EXECUTE.value != 0; });
    trace.AddBits("cmd.ErrorID", 16, [&] { return cmd->ERRORID.value; });
    trace.AddBits("cmd.FromPac", 64, [&] { /* the 8 bytes, PAC byte 0 first */ return std::uint64_t{0}; });
    trace.AttachTo(task_);                               // after the programs: it samples their outputs
    pac::ScopedVcdDump dump(trace.Recording());          // written if the test fails
    // doc-example end
    Cycle(3);
    EXPECT_EQ(trace.Recording().Signals().size(), 3u);
}
