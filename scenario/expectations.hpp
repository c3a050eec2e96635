// Compares how a command ended with what the scenario expected of it.
#pragma once

#include <string>
#include <vector>

#include "scenario.hpp"
#include "scenario_runner.hpp"

namespace pac::scenario {

// One line per expectation not met ("AckData is 333 (16#0000014D), expected 334 (16#0000014E)");
// empty if all are met. A command that ended neither Done nor Error never meets its step.
std::vector<std::string> CheckExpectation(const Expectation& expect, const CommandOutcome& outcome);
// The same for one axis of an axes step; an axis whose part did not end never meets it.
std::vector<std::string> CheckAxisExpectation(const AxisJob& job, const AxisOutcome& outcome);

}  // namespace pac::scenario
