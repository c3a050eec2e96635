// Simulated PLC time, mirrored into __CURRENT_TIME (see sim_clock.hpp).
#include "pac/sim_clock.hpp"

#include <stdexcept>

#include "pac/iec_time.hpp"

namespace pac {

SimClock::SimClock() { Publish(); }

void SimClock::Advance(std::chrono::nanoseconds dt) {
    if (dt < std::chrono::nanoseconds::zero()) {
        throw std::invalid_argument("SimClock::Advance: negative time step");
    }
    // Signed overflow would be undefined behaviour; it takes 292 simulated years to get here.
    if (dt > std::chrono::nanoseconds::max() - now_) {
        throw std::overflow_error("SimClock::Advance: simulated time overflows int64 nanoseconds");
    }
    now_ += dt;
    Publish();
}

std::chrono::nanoseconds SimClock::Now() const { return now_; }

void SimClock::Reset() {
    now_ = std::chrono::nanoseconds::zero();
    Publish();
}

void SimClock::Publish() const { __CURRENT_TIME = ToIecTime(now_); }

}  // namespace pac
