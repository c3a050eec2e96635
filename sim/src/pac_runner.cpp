// The simulated controller's own cycle next to the PLC task (see pac_runner.hpp).
#include "pac/sim/pac_runner.hpp"

#include <stdexcept>

namespace pac::sim {

PacRunner::PacRunner(PaControl& pac, std::chrono::nanoseconds phase) : pac_(pac), next_(phase) {
    if (phase < std::chrono::nanoseconds::zero()) throw std::invalid_argument("PacRunner: phase must be >= 0");
}

void PacRunner::CatchUp(std::chrono::nanoseconds now) {
    while (next_ <= now) {
        pac_.Cycle(next_);
        ++cycles_;
        next_ += pac_.CycleTime();
    }
}

void PacRunner::AttachTo(pac::PlcTask& task) {
    task.AddProgram([this, &task] { CatchUp(task.Clock().Now()); });
}

}  // namespace pac::sim
