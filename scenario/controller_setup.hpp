// The simulated PLC and PA-CONTROL a scenario describes, for every program that runs on the rig with a
// scenario's settings: the scenario runner, and pac-test's host of a user's machine program
// (docs/user_tests.md), which reads its wiring file's "timing", "controller" and faults through the
// scenario loader.
#pragma once

#include "pac/pac_rig.hpp"
#include "scenario.hpp"

namespace pac::scenario {

// The rig's timing of a scenario's "timing".
pac::RigTiming RigTimingOf(const Timing& timing);
// The bus modules of a scenario's "modules".
pac::sim::ModuleLayout Layout(const Modules& modules);
// The controller settings that must be known when the PA-CONTROL is made.
pac::sim::PaControlConfig ControllerConfig(const ControllerSetup& setup);
// The rest of "controller", applied before the first scan: operating status, registers, inputs, limit
// switches, system parameters (a ScenarioError names the parameter the simulator refuses), the
// AUTOMATIC program.
void ApplyControllerSetup(pac::sim::PaControl& pac, const ControllerSetup& setup);
// A fault step, between two scans, at the time of the last scan.
void InjectFault(pac::PacRig& plc, const FaultStep& fault);

}  // namespace pac::scenario
