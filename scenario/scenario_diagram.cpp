#include "scenario_diagram.hpp"

#include <algorithm>
#include <string>

#include "scenario_error.hpp"
#include "wavejson_writer.hpp"

namespace pac::scenario {

void WriteScenarioDiagram(const Scenario& scenario, const TraceObserver& trace, std::ostream& out) {
    const Diagram& d = scenario.diagram;
    const auto [first, end] = trace.StepSamples(d.firstStep, d.lastStep);
    if (first == end) {
        throw ScenarioError("$.diagram.steps", "steps " + std::to_string(d.firstStep) + ".." +
                                                   std::to_string(d.lastStep) + " take no scan: nothing to draw");
    }
    WaveJsonRequest request;
    request.title = d.title.empty() ? scenario.name : d.title;
    request.foot = "a column per PLC scan of " + std::to_string(scenario.timing.plcCycleMs) +
                   " ms; |: scans without a change left out";
    request.lanes = d.signals;
    if (request.lanes.empty()) {
        for (const auto& signal : trace.Recording().Signals()) request.lanes.push_back(signal.path);
    }
    request.sampled = d.sampled;
    request.begin = first - std::min(first, static_cast<std::size_t>(d.contextScans));
    request.end = end;
    request.maxIdleScans = d.maxIdleScans;
    request.hscale = d.hscale;
    WriteWaveJson(trace.Recording(), [&trace](const std::string& path) { return trace.Signals().FormatOf(path); },
                  request, out);
}

}  // namespace pac::scenario
