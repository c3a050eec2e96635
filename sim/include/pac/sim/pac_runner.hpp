// Runs a PaControl at its own cycle next to a pac::PlcTask. The controller's cycles fall at
// phase, phase + c1, phase + c1 + c2, ... where each c is PaControl::CycleTime() after the cycle
// before it (so a mode change changes the cadence). CatchUp(now) runs, in order, every cycle whose
// time is <= now, each with its own timestamp.
//
// AttachTo(task) registers CatchUp(task time) as a program of the task; register it FIRST, before
// the PLC program: at equal timestamps the controller's cycle then runs before the PLC's scan, so
// the scan at t reads the reply the controller wrote at t (with zero latency), and the controller
// at t sees to-PAC images written up to the scan before.
#pragma once

#include <chrono>
#include <cstdint>

#include "pac/plc_task.hpp"
#include "pac/sim/pa_control.hpp"

namespace pac::sim {

class PacRunner {
public:
    // phase >= 0 (std::invalid_argument otherwise): the time of the first cycle.
    explicit PacRunner(PaControl& pac, std::chrono::nanoseconds phase = std::chrono::nanoseconds(0));

    void CatchUp(std::chrono::nanoseconds now);
    void AttachTo(pac::PlcTask& task);

    std::chrono::nanoseconds NextCycleTime() const { return next_; }
    std::int64_t CyclesRun() const { return cycles_; }

private:
    PaControl& pac_;
    std::chrono::nanoseconds next_;
    std::int64_t cycles_ = 0;
};

}  // namespace pac::sim
