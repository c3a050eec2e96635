#include "fault_injector.hpp"

#include <stdexcept>

#include "controller_setup.hpp"
#include "pac/sim/servo_axis.hpp"

namespace pac::pacsim {

namespace {

int CheckedAxis(const SimulatedController& controller, const FaultRequest& fault) {
    const int axes = controller.Spec().modules.axes;
    if (fault.axis < 1 || fault.axis > axes) {
        throw std::invalid_argument(fault.kind + ": axis " + std::to_string(fault.axis) + " has no axis module (1.." +
                                    std::to_string(axes) + ")");
    }
    return fault.axis;
}

void SetLink(SimulatedController& controller, std::chrono::nanoseconds now, pac::sim::LinkFault fault) {
    controller.Bus().ToPacLink().SetFault(now, fault);
    controller.Bus().FromPacLink().SetFault(now, fault);
}

}  // namespace

const std::vector<std::string>& FaultKinds() {
    static const std::vector<std::string> kinds = {"link_loss",  "link_restore", "restart",
                                                   "power_cycle", "axis_error",  "limit_switch"};
    return kinds;
}

void InjectFault(SimulatedController& controller, std::chrono::nanoseconds now, const FaultRequest& fault) {
    pac::sim::PaControl& pac = controller.Controller();
    if (fault.kind == "link_loss") {
        SetLink(controller, now, pac::sim::LinkFault::kDisconnected);
    } else if (fault.kind == "link_restore") {
        SetLink(controller, now, pac::sim::LinkFault::kNone);
    } else if (fault.kind == "power_cycle") {
        pac.PowerCycle(now);
    } else if (fault.kind == "restart") {
        pac.PowerCycle(now);
        pac::scenario::ApplyControllerSetup(pac, controller.Spec().controller);
    } else if (fault.kind == "axis_error") {
        if (fault.number < 0 || fault.number > 0xFFFF) {
            throw std::invalid_argument("axis_error: number " + std::to_string(fault.number) + " is not 1..65535");
        }
        const auto number = fault.number == 0 ? pac::sim::axis_error::kFollowingError : static_cast<std::uint16_t>(fault.number);
        pac.Axes().RaiseAxisError(CheckedAxis(controller, fault), now, number);
    } else if (fault.kind == "limit_switch") {
        pac.Axes().RaiseAxisError(CheckedAxis(controller, fault), now, pac::sim::axis_error::kLimitSwitchActuated);
    } else {
        std::string known;
        for (const auto& kind : FaultKinds()) known += (known.empty() ? "" : ", ") + kind;
        throw std::invalid_argument("unknown fault \"" + fault.kind + "\" (known: " + known + ")");
    }
}

}  // namespace pac::pacsim
