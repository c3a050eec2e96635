// Benchmark (not a test): scans from FB_PAC_Cmd's Execute edge to Done against the simulated
// PA-CONTROL, for every bus latency and a range of PLC and controller cycles, next to the protocol
// minimum. Equal columns mean the FB adds no scan of its own.
#include <cstdio>

#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"
#include "pac/pac_plc_bench.hpp"

namespace {

struct Row {
    int commands = 0;
    int scansMin = 1 << 30;
    int scansMax = 0;
    int aboveMinimum = 0;
};

Row Measure(const pac::PlcBenchTiming& timing, int commands) {
    pac::PacPlcBench plc(timing);
    auto cmd = PAC_FB(FB_PAC_CMD);
    plc.Call(cmd);
    plc.Start();
    plc.Scan(3);
    Row row;
    for (int i = 0; i < commands; ++i) {
        cmd->CODE.value = (i % 2 == 0) ? 0x0906 : 0x1906;  // write, then read back, N register 1
        cmd->PARAM.value = 1;
        cmd->DATA.value = static_cast<DWORD>(i);
        cmd->EXECUTE.value = TRUE;
        plc.Scan();
        const auto edge = plc.Now();
        const int scans = plc.ScanUntil([&] { return cmd->DONE.value || cmd->ERROR.value; }, 10000);
        const int minimum = plc.ProtocolMinimumScans(edge);
        row.commands++;
        row.scansMin = scans < row.scansMin ? scans : row.scansMin;
        row.scansMax = scans > row.scansMax ? scans : row.scansMax;
        if (scans != minimum || !cmd->DONE.value) row.aboveMinimum++;
        cmd->EXECUTE.value = FALSE;
        plc.Scan(1 + i % 3);  // vary the phase against the controller's cycle
    }
    return row;
}

}  // namespace

int main() {
    using std::chrono::milliseconds;
    std::printf("%8s %8s %8s %9s %10s %10s %16s\n", "PLC [ms]", "PAC [ms]", "latency", "commands",
                "scans min", "scans max", "not at minimum");
    int failures = 0;
    for (int latency = 0; latency <= 3; ++latency) {
        for (int plcMs : {1, 2, 5, 10}) {
            for (int pacMs : {1, 3, 10}) {
                pac::PlcBenchTiming timing;
                timing.plcCycle = milliseconds(plcMs);
                timing.pacCycle = milliseconds(pacMs);
                timing.latencyCycles = latency;
                const Row row = Measure(timing, 200);
                failures += row.aboveMinimum;
                std::printf("%8d %8d %8d %9d %10d %10d %16d\n", plcMs, pacMs, latency, row.commands, row.scansMin,
                            row.scansMax, row.aboveMinimum);
            }
        }
    }
    std::printf("\nlatency in PLC cycles each way; 'not at minimum': commands whose Done came later than the\n"
                "protocol allows (or not at all). Total: %d\n", failures);
    return failures == 0 ? 0 : 1;
}
