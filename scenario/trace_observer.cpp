#include "trace_observer.hpp"

#include <stdexcept>

namespace pac::scenario {

void TraceObserver::OnStepStart(std::size_t index, const Step& /*step*/, std::chrono::nanoseconds /*now*/) {
    if (index != stepStarts_.size()) throw std::logic_error("TraceObserver: steps out of order");
    stepStarts_.push_back(Recording().Samples());
}

std::pair<std::size_t, std::size_t> TraceObserver::StepSamples(std::size_t first, std::size_t last) const {
    if (first < 1 || last < first || last > stepStarts_.size()) throw std::out_of_range("TraceObserver: no such steps");
    const std::size_t end = last < stepStarts_.size() ? stepStarts_[last] : Recording().Samples();
    return {stepStarts_[first - 1], end};
}

void RunObservers::OnStart(const Scenario& scenario) {
    for (RunObserver* o : observers_) o->OnStart(scenario);
}

void RunObservers::OnStepStart(std::size_t index, const Step& step, std::chrono::nanoseconds now) {
    for (RunObserver* o : observers_) o->OnStepStart(index, step, now);
}

void RunObservers::OnScan(const ScanSample& sample) {
    for (RunObserver* o : observers_) o->OnScan(sample);
}

void RunObservers::OnStepEnd(const StepReport& report) {
    for (RunObserver* o : observers_) o->OnStepEnd(report);
}

void RunObservers::OnEnd(const RunReport& report) {
    for (RunObserver* o : observers_) o->OnEnd(report);
}

}  // namespace pac::scenario
