// Simulated PLC time: an integer nanosecond counter that moves only when a test advances it. Every
// change is written to the C global __CURRENT_TIME, which TON/TOF/TP read, so one SimClock at a
// time owns that global (a test fixture holds one; constructing it resets the global to 0).
#pragma once

#include <chrono>

namespace pac {

class SimClock {
public:
    SimClock();  // starts at 0

    // Copies would be two owners of the one global time.
    SimClock(const SimClock&) = delete;
    SimClock& operator=(const SimClock&) = delete;

    // dt must be >= 0 (std::invalid_argument otherwise): PLC time never runs backwards, and the
    // timers would misbehave if it did.
    void Advance(std::chrono::nanoseconds dt);
    std::chrono::nanoseconds Now() const;
    void Reset();  // back to 0

private:
    void Publish() const;

    std::chrono::nanoseconds now_{0};
};

}  // namespace pac
