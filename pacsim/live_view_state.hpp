// What pac-sim's live view shows of one simulated PA-CONTROL (GET /api/state, docs/virtual_commissioning.md,
// "The live view"): its operating status and mode, each axis (position, drive state, errors), the CMD handshakes
// it has seen with each command's name, and every module's bytes both ways with their fields named as the
// manual's sections 2.4, 2.5 and 2.7 name them. Built under the controller's lock.
#pragma once

#include <chrono>

#include <nlohmann/json.hpp>

#include "simulated_controller.hpp"

namespace pac::pacsim {

nlohmann::json ControllerState(SimulatedController& controller, std::chrono::nanoseconds now);

}  // namespace pac::pacsim
