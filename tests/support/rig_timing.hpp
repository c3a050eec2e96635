// A BusTiming as the timing of a PacRig (the PLC wired to the simulated PA-CONTROL).
#pragma once

#include <chrono>

#include "bus_timing.hpp"
#include "pac/pac_rig.hpp"

namespace pac::test {

inline RigTiming RigTimingOf(const BusTiming& t,
                                       std::chrono::nanoseconds bootTime = std::chrono::nanoseconds(0)) {
    RigTiming timing;
    timing.plcCycle = t.PlcCycle();
    timing.pacCycle = t.PacCycle();
    timing.latencyCycles = t.latency;
    timing.jitter = t.Jitter();
    timing.seed = t.seed;
    timing.bootTime = bootTime;
    return timing;
}

}  // namespace pac::test
