// A cyclic PLC task scanned by hand (see plc_task.hpp).
#include "pac/plc_task.hpp"

#include <stdexcept>
#include <utility>

namespace pac {

namespace {

std::chrono::nanoseconds CheckedCycleTime(std::chrono::nanoseconds cycleTime) {
    // A zero cycle would freeze time, so a timer-driven RunUntil could never finish.
    if (cycleTime <= std::chrono::nanoseconds::zero()) {
        throw std::invalid_argument("PlcTask: cycle time must be > 0");
    }
    return cycleTime;
}

}  // namespace

PlcTask::PlcTask(SimClock& clock, std::chrono::nanoseconds cycleTime)
    : clock_(clock), cycleTime_(CheckedCycleTime(cycleTime)) {}

void PlcTask::AddProgram(std::function<void()> program) {
    if (!program) {
        throw std::invalid_argument("PlcTask::AddProgram: empty program");
    }
    programs_.push_back(std::move(program));
}

void PlcTask::Scan() {
    clock_.Advance(cycleTime_);
    ++scanCount_;
    for (const auto& program : programs_) {
        program();
    }
}

std::int64_t PlcTask::ScanCount() const { return scanCount_; }

std::chrono::nanoseconds PlcTask::CycleTime() const { return cycleTime_; }

void PlcTask::SetCycleTime(std::chrono::nanoseconds cycleTime) { cycleTime_ = CheckedCycleTime(cycleTime); }

const SimClock& PlcTask::Clock() const { return clock_; }

}  // namespace pac
