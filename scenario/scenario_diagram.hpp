// The scenario's "diagram" of a recorded run as WaveJSON: the steps it names (with its context scans
// before them), its signals (every recorded one if it names none), its sampled lanes and scale. What
// `pac_scenario --wavedrom` writes and what the committed diagrams of docs/diagrams are checked against.
#pragma once

#include <ostream>

#include "scenario.hpp"
#include "trace_observer.hpp"

namespace pac::scenario {

// ScenarioError when the diagram's steps took no scan (faults only).
void WriteScenarioDiagram(const Scenario& scenario, const TraceObserver& trace, std::ostream& out);

}  // namespace pac::scenario
