// The simulated controller's own cycle next to the PLC task (see slave_runner.hpp).
#include "pac/sim/slave_runner.hpp"

#include <stdexcept>

namespace pac::sim {

SlaveRunner::SlaveRunner(PaControl& pac, std::chrono::nanoseconds phase) : pac_(pac), next_(phase) {
    if (phase < std::chrono::nanoseconds::zero()) throw std::invalid_argument("SlaveRunner: phase must be >= 0");
}

void SlaveRunner::CatchUp(std::chrono::nanoseconds now) {
    while (next_ <= now) {
        pac_.Cycle(next_);
        ++cycles_;
        next_ += pac_.CycleTime();
    }
}

void SlaveRunner::AttachTo(pac::PlcTask& task) {
    task.AddProgram([this, &task] { CatchUp(task.Clock().Now()); });
}

}  // namespace pac::sim
