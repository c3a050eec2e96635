// Reads the steps of the CTRL interface and the axis modules of a scenario (docs/scenario.md):
//   {"ctrl": "PAC_REQ_START_ONLINE", "integer_mode": false, "timeout_ms": 10000, "expect": {...}}
//   {"axes": [{"axis": 1, "enable": true, "command": "PAC_AX_HOME", "expect": {...}}, ...]}
//   {"automatic": [{"module": 1, "flag_word": 1, "n": 41, "r": 1.25, "expect": {"n": 42}}], "max_ms": 500}
// Requests, axis commands and conditions are the names a PLC programmer writes in ST (E_PAC_CtrlRequest,
// E_PAC_AxisCommand, E_PAC_MoveCondition), read from the enumerations themselves (pac::EnumNames).
// Every refusal is a ScenarioError naming the JSONPath and the reason, like the rest of the loader.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "json_fields.hpp"
#include "scenario.hpp"

namespace pac::scenario {

class ModuleStepReader {
public:
    using ErrorIdReader = std::function<std::uint16_t(const json::Json&, const std::string&)>;

    // `modules`: what the scenario configured (a step on a module it lacks is refused).
    ModuleStepReader(const Modules& modules, ErrorIdReader readErrorId)
        : modules_(modules), readErrorId_(std::move(readErrorId)) {}

    CtrlStep ReadCtrl(const json::Object& step) const;
    AxesStep ReadAxes(const json::Object& step) const;
    AutomaticStep ReadAutomatic(const json::Object& step) const;

private:
    AxisJob ReadJob(const json::Json& value, const std::string& path) const;
    AxisExpectation ReadAxisExpectation(const json::Json& value, const std::string& path) const;
    AutomaticValues ReadAutomaticValues(const json::Json& value, const std::string& path) const;

    const Modules& modules_;
    ErrorIdReader readErrorId_;
};

}  // namespace pac::scenario
