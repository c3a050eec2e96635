// Records a scenario run as a trace (the signals of ScenarioSignals, one sample per scan) and where each
// step began, for `pac_scenario --vcd` and `--wavedrom`. RunObservers passes a run to several observers
// (the timeline and the trace).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "pac/trace_recorder.hpp"
#include "scenario_runner.hpp"
#include "scenario_signals.hpp"

namespace pac::scenario {

class TraceObserver : public RunObserver {
public:
    explicit TraceObserver(const Modules& modules) : signals_(modules, recorder_) {}

    void OnStepStart(std::size_t index, const Step& step, std::chrono::nanoseconds now) override;
    void OnScan(const ScanSample& sample) override { signals_.Sample(sample); }

    const Trace& Recording() const { return recorder_.Recording(); }
    const ScenarioSignals& Signals() const { return signals_; }
    // The samples of steps first..last (1-based, as the timeline numbers them): [begin, end). Empty when
    // those steps took no scan (faults).
    std::pair<std::size_t, std::size_t> StepSamples(std::size_t first, std::size_t last) const;

private:
    TraceRecorder recorder_;  // before signals_, which adds to it
    ScenarioSignals signals_;
    std::vector<std::size_t> stepStarts_;  // the first sample of each step
};

class RunObservers : public RunObserver {
public:
    explicit RunObservers(std::vector<RunObserver*> observers) : observers_(std::move(observers)) {}

    void OnStart(const Scenario& scenario) override;
    void OnStepStart(std::size_t index, const Step& step, std::chrono::nanoseconds now) override;
    void OnScan(const ScanSample& sample) override;
    void OnStepEnd(const StepReport& report) override;
    void OnEnd(const RunReport& report) override;

private:
    std::vector<RunObserver*> observers_;
};

}  // namespace pac::scenario
