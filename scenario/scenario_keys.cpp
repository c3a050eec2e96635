#include "scenario_keys.hpp"

#include <algorithm>
#include <stdexcept>

namespace pac::scenario::keys {

const std::vector<ObjectKeys>& All() {
    static const std::vector<ObjectKeys> all = {
        // "$schema" names the JSON Schema for editors; the loader reads nothing from it.
        {"scenario", {"name", "description", "timing", "modules", "controller", "steps", "diagram", "$schema"}},
        {"timing", {"plc_cycle_ms", "pac_cycle_ms", "latency_cycles", "jitter_ms", "seed", "boot_ms"}},
        {"modules", {"ctrl", "axes", "mc_blocks", "diagnosis"}},
        {"diagnosis", {"axes", "poll_ms"}},
        {"controller",
         {"operating_status", "n_registers", "r_registers", "inputs", "system_parameters", "axes_referenced",
          "limit_switches", "automatic_program"}},
        {"limitSwitches", {"negative", "positive"}},
        {"real", {"real"}},
        {"commandStep", {"command", "param", "data", "timeout_ms", "end_timeout_ms", "expect", "note"}},
        {"expectation", {"done", "error", "error_id", "ack_data"}},
        {"ctrlStep", {"ctrl", "integer_mode", "timeout_ms", "expect", "note"}},
        {"ctrlExpectation", {"done", "error", "error_id"}},
        {"axesStep", {"axes", "note"}},
        {"axisJob",
         {"axis", "enable", "command", "reset_error", "position", "velocity", "acceleration", "condition",
          "timeout_ms", "max_ms", "expect"}},
        {"axisExpectation", {"done", "error", "aborted", "error_id", "referenced", "position", "position_tolerance"}},
        {"automaticStep", {"automatic", "max_ms", "note"}},
        {"automaticModule", {"module", "flag_word", "n", "r", "expect"}},
        {"automaticExpectation", {"flag_word", "n", "r", "r_tolerance"}},
        {"powerCycleStep", {"fault", "note"}},
        {"systemErrorStep", {"fault", "number", "note"}},
        {"setInputStep", {"fault", "input", "value", "note"}},
        {"linkFaultStep", {"fault", "link", "note"}},
        {"waitStep", {"wait_ms", "note"}},
        {"diagram", {"title", "steps", "signals", "sampled", "context_scans", "max_idle_scans", "hscale"}},
    };
    return all;
}

const std::vector<std::string>& Of(const std::string& definition) {
    for (const ObjectKeys& object : All()) {
        if (object.definition == definition) return object.keys;
    }
    throw std::out_of_range("scenario keys: no definition " + definition);
}

const std::vector<std::string>& StepDefinitions() {
    static const std::vector<std::string> steps = {"commandStep",    "ctrlStep",        "axesStep",
                                                   "automaticStep",  "powerCycleStep",  "systemErrorStep",
                                                   "setInputStep",   "linkFaultStep",   "waitStep"};
    return steps;
}

std::vector<std::string> AnyStep() {
    std::vector<std::string> all;
    for (const std::string& step : StepDefinitions()) {
        for (const std::string& key : Of(step)) {
            if (std::find(all.begin(), all.end(), key) == all.end()) all.push_back(key);
        }
    }
    return all;
}

}  // namespace pac::scenario::keys
