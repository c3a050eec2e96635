// Preconditions the simulated PA-CONTROL will check and a scenario file does not meet, found before the
// run so the author reads the cause rather than a refused request: START ONLINE (a ctrl step
// PAC_REQ_START_ONLINE or command 0603) without the powered external stop input of system parameter 4
// (manual 5.2.1.3). The steps are followed in order: set_input faults and 0700 commands on parameter 4
// change what a later start sees. A step that expects an error is left alone (it shows the refusal).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "scenario.hpp"

namespace pac::scenario {

struct PreconditionWarning {
    std::size_t step = 0;  // 0-based, as the JSONPath counts ($.steps[step])
    std::string message;
};

std::vector<PreconditionWarning> FindUnmetPreconditions(const Scenario& scenario);

}  // namespace pac::scenario
