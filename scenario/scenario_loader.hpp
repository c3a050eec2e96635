// Reads a scenario file (JSON, docs/scenario.md) into a Scenario, refusing anything it cannot
// represent with a ScenarioError that names the JSONPath and the reason: invalid JSON, a duplicate
// or unknown key, a missing key, a value of the wrong type or out of range, an unknown command,
// error or status name (names are GVL_PAC's).
#pragma once

#include <string>

#include "gvl_names.hpp"
#include "scenario.hpp"
#include "scenario_error.hpp"

namespace pac::scenario {

class ScenarioLoader {
public:
    explicit ScenarioLoader(const GvlNames& names) : names_(names) {}

    Scenario FromText(const std::string& jsonText) const;
    // Also refuses a file that cannot be read and a YAML file (.yaml, .yml).
    Scenario FromFile(const std::string& path) const;

private:
    const GvlNames& names_;
};

}  // namespace pac::scenario
