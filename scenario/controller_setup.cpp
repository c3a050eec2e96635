#include "controller_setup.hpp"

#include <string>

#include "scenario_error.hpp"

namespace pac::scenario {

using std::chrono::milliseconds;

pac::RigTiming RigTimingOf(const Timing& t) {
    return {milliseconds(t.plcCycleMs), milliseconds(t.pacCycleMs), t.latencyCycles, milliseconds(t.jitterMs),
            t.seed, milliseconds(t.bootMs)};
}

pac::sim::ModuleLayout Layout(const Modules& modules) { return pac::sim::ModuleLayout{modules.ctrl, modules.axes}; }

pac::sim::PaControlConfig ControllerConfig(const ControllerSetup& setup) {
    pac::sim::PaControlConfig config;
    config.referencedAtPowerOn = setup.axesReferenced;
    return config;
}

void ApplyControllerSetup(pac::sim::PaControl& pac, const ControllerSetup& setup) {
    if (setup.operatingStatus) pac.SetOperatingStatus(*setup.operatingStatus);
    pac.SetAutomaticProgram(pac::sim::AutomaticProgram(setup.automaticProgram));
    for (const auto& [number, value] : setup.intRegisters) pac.Io().intRegisters.SetInt(number, value);
    for (const auto& [number, value] : setup.realRegisters) pac.Io().realRegisters.SetReal(number, value);
    for (const auto& [number, value] : setup.inputs) pac.Io().inputs.Set(number, value);
    for (const auto& [axis, switches] : setup.limitSwitches) {
        pac.Axes().SetLimitSwitches(axis, switches.negative, switches.positive);
    }
    for (const auto& [number, value] : setup.systemParameters) {
        if (pac.SystemParameters().Set(number, value) != pac::sim::ParameterTable::SetResult::kOk) {
            throw ScenarioError("$.controller.system_parameters[\"" + std::to_string(number) + "\"]",
                                "refused by the simulated PA-CONTROL: no such system parameter, or " +
                                    std::to_string(value) + " is outside its limits");
        }
    }
}

void InjectFault(pac::PacRig& plc, const FaultStep& fault) {
    const auto now = plc.Now();
    switch (fault.kind) {
        case FaultKind::kPowerCycle:
            plc.Controller().PowerCycle(now);
            return;
        case FaultKind::kSystemError:
            plc.Controller().RaiseSystemError(static_cast<std::uint16_t>(fault.number));
            return;
        case FaultKind::kSetInput:
            plc.Controller().Io().inputs.Set(fault.number, fault.value);
            return;
        default:
            break;
    }
    pac::sim::LinkFault linkFault = pac::sim::LinkFault::kNone;
    if (fault.kind == FaultKind::kFreezeLink) linkFault = pac::sim::LinkFault::kFrozen;
    if (fault.kind == FaultKind::kZeroLink) linkFault = pac::sim::LinkFault::kAllZero;
    if (fault.link != LinkSide::kFromPac) plc.Bus().ToPacLink().SetFault(now, linkFault);
    if (fault.link != LinkSide::kToPac) plc.Bus().FromPacLink().SetFault(now, linkFault);
}

}  // namespace pac::scenario
