// The bus timings the library's tests run on: the PLC's cycle, the PA-CONTROL's cycle, the bus latency
// each way in PLC cycles, and a seeded jitter on top of the latency. One value names itself in test
// output (Describe, PrintTo) and in GoogleTest parameter names (BusTimingName), so a failing case says
// which timing it ran on and can be rerun alone.
#pragma once

#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace pac::test {

struct BusTiming {
    int plcMs = 1;
    int pacMs = 10;
    int latency = 0;    // PLC cycles, each way
    int jitterUs = 0;   // each image is delayed by the latency plus a seeded draw from [0, jitter]
    std::uint64_t seed = 1;

    std::chrono::nanoseconds PlcCycle() const { return std::chrono::milliseconds(plcMs); }
    std::chrono::nanoseconds PacCycle() const { return std::chrono::milliseconds(pacMs); }
    std::chrono::nanoseconds Latency() const { return PlcCycle() * latency; }
    std::chrono::nanoseconds Jitter() const { return std::chrono::microseconds(jitterUs); }
    // Scans that cover at least `t` of simulated time.
    int ScansFor(std::chrono::nanoseconds t) const { return static_cast<int>(t / PlcCycle()) + 1; }
};

// Built with std::string rather than an ostringstream: GoogleTest prints every case's parameter when it
// registers the tests, thousands of times per process start, where a stream's set-up costs most.
inline std::string Describe(const BusTiming& t) {
    std::string out = "PLC " + std::to_string(t.plcMs) + " ms, PA-CONTROL " + std::to_string(t.pacMs) +
                      " ms, latency " + std::to_string(t.latency) + " PLC cycles";
    if (t.jitterUs != 0) out += ", jitter " + std::to_string(t.jitterUs) + " us, seed " + std::to_string(t.seed);
    return out;
}

inline std::ostream& operator<<(std::ostream& out, const BusTiming& t) { return out << Describe(t); }

// GoogleTest prints a parameter with this instead of its bytes.
inline void PrintTo(const BusTiming& t, std::ostream* out) { *out << Describe(t); }

// "Plc2ms_Pac10ms_Latency1", with "_Jitter2500us_Seed101" for a jittered bus.
inline std::string BusTimingName(const ::testing::TestParamInfo<BusTiming>& info) {
    const BusTiming& t = info.param;
    std::string name = "Plc" + std::to_string(t.plcMs) + "ms_Pac" + std::to_string(t.pacMs) + "ms_Latency" +
                       std::to_string(t.latency);
    if (t.jitterUs != 0) name += "_Jitter" + std::to_string(t.jitterUs) + "us_Seed" + std::to_string(t.seed);
    return name;
}

// Every combination of the given PLC cycles, PA-CONTROL cycles and latencies, without jitter.
inline std::vector<BusTiming> BusTimingGrid(std::initializer_list<int> plcMs, std::initializer_list<int> pacMs,
                                            std::initializer_list<int> latencies) {
    std::vector<BusTiming> grid;
    for (int plc : plcMs) {
        for (int pac : pacMs) {
            for (int latency : latencies) grid.push_back({plc, pac, latency});
        }
    }
    return grid;
}

// The grid most suites repeat every case on: PLC cycle 1, 2, 5, 10 ms x PA-CONTROL cycle 1, 3, 10 ms x
// latency 0..3 PLC cycles each way.
inline std::vector<BusTiming> StandardBusTimings() { return BusTimingGrid({1, 2, 5, 10}, {1, 3, 10}, {0, 1, 2, 3}); }

// Jittered buses: the jitter ranges from a fraction of a PLC cycle to nearly a PA-CONTROL cycle and is
// not matched to the latency. The seeds are fixed here, so every run is the same; the seed is part of
// the test's name.
inline std::vector<BusTiming> JitteredBusTimings() {
    return {{1, 3, 1, 2500, 101}, {2, 10, 2, 6000, 202}, {5, 1, 3, 4000, 303},
            {10, 3, 0, 9000, 404}, {1, 10, 0, 700, 505},  {2, 1, 1, 1500, 606}};
}

inline std::vector<BusTiming> StandardAndJitteredBusTimings() {
    std::vector<BusTiming> all = StandardBusTimings();
    for (const BusTiming& t : JitteredBusTimings()) all.push_back(t);
    return all;
}

}  // namespace pac::test
