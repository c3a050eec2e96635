// Reads a scenario's "diagram" object, what `pac_scenario --wavedrom` draws (docs/scenario.md):
//   {"title": "...", "steps": [2, 3], "signals": ["cmd.FB_PAC_Cmd.Execute", ...], "sampled": [...],
//    "context_scans": 1, "max_idle_scans": 3, "hscale": 3}
// Steps are numbered from 1 as the timeline numbers them; signals are the paths the scenario records
// for its modules (ScenarioSignals). Refusals are ScenarioErrors with the JSONPath, as in the loader.
#pragma once

#include <cstddef>
#include <string>

#include "json_fields.hpp"
#include "scenario.hpp"

namespace pac::scenario {

Diagram ReadDiagram(const json::Json& value, const std::string& path, std::size_t steps, const Modules& modules);

}  // namespace pac::scenario
