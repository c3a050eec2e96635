#include "scan_schedule.hpp"

namespace pac::pacsim {

ScanSchedule::Clock::time_point ScanSchedule::Due(std::chrono::nanoseconds now, Clock::time_point wallNow) {
    if (!started_) {
        start_ = wallNow - now;  // the first scan is due at once
        started_ = true;
    }
    return start_ + now;
}

std::chrono::nanoseconds ScanSchedule::Started(std::chrono::nanoseconds now, Clock::time_point wallNow) {
    const std::chrono::nanoseconds late = wallNow - Due(now, wallNow);
    const std::chrono::nanoseconds cycle = now - previous_;
    previous_ = now;
    if (late > cycle) start_ += late;
    return late;
}

}  // namespace pac::pacsim
