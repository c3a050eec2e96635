// Samples chosen signals into a Trace (see trace_recorder.hpp).
#include "pac/trace_recorder.hpp"

#include <stdexcept>
#include <utility>

namespace pac {

void TraceRecorder::Add(SignalInfo info, Probe probe) {
    trace_.AddSignal(std::move(info));
    probes_.push_back(std::move(probe));
}

void TraceRecorder::AddBool(const std::string& path, std::function<bool()> probe) {
    if (!probe) throw std::invalid_argument("TraceRecorder: empty probe for " + path);
    Add({path, SignalKind::kBits, 1}, [probe = std::move(probe)] { return TraceValue{probe() ? 1U : 0U, 0.0}; });
}

void TraceRecorder::AddBits(const std::string& path, int width, std::function<std::uint64_t()> probe) {
    if (!probe) throw std::invalid_argument("TraceRecorder: empty probe for " + path);
    Add({path, SignalKind::kBits, width}, [probe = std::move(probe)] { return TraceValue{probe(), 0.0}; });
}

void TraceRecorder::AddReal(const std::string& path, std::function<double()> probe) {
    if (!probe) throw std::invalid_argument("TraceRecorder: empty probe for " + path);
    Add({path, SignalKind::kReal, 64}, [probe = std::move(probe)] { return TraceValue{0, probe()}; });
}

void TraceRecorder::Sample(std::chrono::nanoseconds time) {
    sample_.clear();
    for (const auto& probe : probes_) sample_.push_back(probe());
    trace_.Append(time, sample_);
}

void TraceRecorder::AttachTo(PlcTask& task) {
    task.AddProgram([this, &task] { Sample(task.Clock().Now()); });
}

}  // namespace pac
