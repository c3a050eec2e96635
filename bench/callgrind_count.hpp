// Benchmark (not a test): instructions counted by callgrind (valgrind) in a workload of this program, run
// again under valgrind in a child process.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace pac::bench {

struct CallgrindCount {
    double instructionsPerScan = 0;
    int scans = 0;
    long jobs = 0;  // jobs that ended with Done in the measured scans
};

// True when `valgrind` runs.
bool ValgrindAvailable();

// Runs `self --workload <workload> --scans <scans>` under callgrind, counting only inside `functions`
// (--toggle-collect; their callees included) and only in the measured scans; nullopt if it failed.
std::optional<CallgrindCount> CountInstructions(const std::string& self, const std::string& workload,
                                                const std::vector<std::string>& functions, int scans);

}  // namespace pac::bench
