// The faults pac-sim's live view and its HTTP endpoint inject into a simulated PA-CONTROL
// (docs/virtual_commissioning.md, "Injecting faults"), at the controller's time `now`, under its lock:
//   link_loss     the Profibus link between gateway and controller is lost both ways: the PLC reads zeros, the
//                 controller sees zeros (its bus failure) until link_restore and the first image after it
//   link_restore  the link is back
//   restart       the controller restarts with the configuration's state (power off and on, then the registers,
//                 inputs, limit switches and system parameters of the file again, as when pac-sim started)
//   power_cycle   power off and on: battery-buffered data kept (docs/simulator.md)
//   axis_error    an axis error on `axis` (`number`, default 66 following error): the axis stops at once
//   limit_switch  `axis` runs onto a limit switch: axis error 64, the axis stops at once
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "simulated_controller.hpp"

namespace pac::pacsim {

struct FaultRequest {
    std::string kind;  // one of FaultKinds()
    int axis = 1;      // axis_error, limit_switch: 1..the controller's axis modules
    int number = 0;    // axis_error: its number, 1..65535; 0: 66
};

const std::vector<std::string>& FaultKinds();

// std::invalid_argument naming what is wrong (an unknown kind with the known ones, an axis without a module).
void InjectFault(SimulatedController& controller, std::chrono::nanoseconds now, const FaultRequest& fault);

}  // namespace pac::pacsim
