// A cyclic PLC task, scanned by hand: each Scan() advances the simulated clock by the cycle time and
// then runs every registered program once, in registration order (MATIEC/OpenPLC order: time moves
// before the scan, so a timer sees the new time in the very scan that follows the tick).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include "pac/sim_clock.hpp"

namespace pac {

class PlcTask {
public:
    // cycleTime must be > 0 (std::invalid_argument otherwise). The clock must outlive the task.
    PlcTask(SimClock& clock, std::chrono::nanoseconds cycleTime);

    // A program is one scan's work: copy inputs in, call the FB bodies, copy outputs out.
    // Register programs between scans, not from inside a program. An empty function throws
    // std::invalid_argument.
    void AddProgram(std::function<void()> program);

    void Scan();

    // Scans started so far; inside a program it is the number of the current scan (1 for the first).
    std::int64_t ScanCount() const;
    std::chrono::nanoseconds CycleTime() const;
    void SetCycleTime(std::chrono::nanoseconds cycleTime);  // same rule as the constructor
    const SimClock& Clock() const;

private:
    SimClock& clock_;
    std::chrono::nanoseconds cycleTime_;
    std::vector<std::function<void()>> programs_;
    std::int64_t scanCount_ = 0;
};

}  // namespace pac
