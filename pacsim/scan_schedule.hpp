// When each scan of pac-sim-plc starts on the wall clock (docs/virtual_commissioning.md, "The library over
// Modbus"): the scan at PLC time `now` is due `now` after the schedule's start. A scan that starts more than a
// PLC cycle late (the process was not scheduled: a loaded machine) moves the schedule by its lateness, as a PLC
// halted and resumed keeps its cycle: the scans after it do not run back to back to catch up, which would run the
// PLC's clock faster than the controller's (a 60 ms wait over in a millisecond, a boot not yet ended).
#pragma once

#include <chrono>

namespace pac::pacsim {

class ScanSchedule {
public:
    using Clock = std::chrono::steady_clock;

    // When the scan at PLC time `now` is due; the first call starts the schedule, time 0 being one PLC cycle
    // before the first scan (the task advances its clock before each scan).
    Clock::time_point Due(std::chrono::nanoseconds now, Clock::time_point wallNow);
    // The scan at `now` started at `wallNow`: how late it is. Over a cycle late, later scans are due that much later.
    std::chrono::nanoseconds Started(std::chrono::nanoseconds now, Clock::time_point wallNow);

private:
    Clock::time_point start_;
    std::chrono::nanoseconds previous_{0};
    bool started_ = false;
};

}  // namespace pac::pacsim
