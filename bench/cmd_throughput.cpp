// Benchmark (not a test): commands per second through the shared CMD interface with 1..8 command FBs,
// against the protocol's bound (cmd_throughput.hpp). A single FB pays its release and edge scans; with
// more, the FB whose turn it is sends in the scan of the previous command's end if the PLC calls it after
// the FB that ended, a scan later otherwise (once per round of the call order).
#include <cstdio>

#include "cmd_throughput.hpp"

int main() {
    using std::chrono::milliseconds;
    std::printf("%8s %8s %8s %4s %9s %12s %14s %7s\n", "PLC [ms]", "PAC [ms]", "latency", "FBs", "commands",
                "commands/s", "protocol [/s]", "ratio");
    for (int latency : {0, 1, 3}) {
        for (int plcMs : {1, 5, 10}) {
            for (int pacMs : {1, 10}) {
                for (int fbs : {1, 2, 4, 8}) {
                    pac::PlcBenchTiming timing;
                    timing.plcCycle = milliseconds(plcMs);
                    timing.pacCycle = milliseconds(pacMs);
                    timing.latencyCycles = latency;
                    const auto row = pac::bench::SharedInterfaceThroughput(timing, fbs, 400);
                    std::printf("%8d %8d %8d %4d %9d %12.1f %14.1f %6.1f%%\n", plcMs, pacMs, latency, fbs, row.commands,
                                row.perSecond, row.protocolPerSecond, 100.0 * row.Ratio());
                }
            }
        }
    }
    std::printf("\nlatency in PLC cycles each way; protocol: the same commands back to back, each acknowledged\n"
                "at the protocol minimum from the scan it was sent in.\n");
    return 0;
}
