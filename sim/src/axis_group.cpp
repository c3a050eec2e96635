// The axes of the simulated PA-CONTROL (see axis_group.hpp).
#include "pac/sim/axis_group.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace pac::sim {

namespace {

// The value of a REAL parameter, if the table has it.
std::optional<double> Real(const ParameterTable& parameters, std::uint16_t number) {
    if (const auto value = parameters.RealValue(number)) return static_cast<double>(*value);
    return std::nullopt;
}

}  // namespace

AxisGroup::AxisGroup(int capacity, const std::vector<ParameterSpec>& axisParameters, const ServoAxisConfig& machine) {
    if (capacity < 0) throw std::invalid_argument("AxisGroup: capacity must be >= 0");
    machine.Validate();
    if (capacity == 0) return;
    // Every axis starts alike: the first is built (its table checked, its configuration worked out) and the
    // others are copies of it.
    ParameterTable parameters(ParameterType::kReal32, axisParameters);
    ServoAxisConfig config = ConfigFrom(machine, parameters);
    try {
        config.Validate();
    } catch (const std::invalid_argument&) {
        config = machine;  // default parameters that do not fit together: the machine's own values
    }
    axes_.assign(static_cast<std::size_t>(capacity),
                 Axis{ServoAxis(config), std::move(parameters), machine, config.FullDynamics()});
    capacity_ = capacity;
}

ServoAxisConfig AxisGroup::ConfigFrom(const ServoAxisConfig& machine, const ParameterTable& parameters) {
    ServoAxisConfig c = machine;
    c.traverseSpeed = Real(parameters, axisparam::kTraverseSpeed).value_or(c.traverseSpeed);
    c.referenceSpeed = Real(parameters, axisparam::kReferenceSpeed).value_or(c.referenceSpeed);
    c.creepSpeed = Real(parameters, axisparam::kCreepSpeed).value_or(c.creepSpeed);
    if (const auto acceleration = Real(parameters, axisparam::kAcceleration)) {
        c.acceleration = *acceleration;  // the PA-CONTROL has one acceleration parameter for both ramps
        c.deceleration = *acceleration;
    }
    c.minTraverseRange = Real(parameters, axisparam::kMinTraverseArea).value_or(c.minTraverseRange);
    c.maxTraverseRange = Real(parameters, axisparam::kMaxTraverseArea).value_or(c.maxTraverseRange);
    if (const auto ramp = Real(parameters, axisparam::kRampType)) {
        c.rampType = *ramp >= 0.5 ? RampType::kSCurve : RampType::kLinear;
    }
    return c;
}

bool AxisGroup::ApplyParameters(int axis) {
    Axis& a = At(axis);
    const ServoAxisConfig config = ConfigFrom(a.machine, a.parameters);
    try {
        config.Validate();
    } catch (const std::invalid_argument&) {
        return false;
    }
    a.motion.SetConfig(a.motion.Now(), config);
    a.session = config.FullDynamics();
    return true;
}

void AxisGroup::ApplyParametersToAll() {
    for (int axis = 1; axis <= Capacity(); ++axis) ApplyParameters(axis);
}

const Dynamics& AxisGroup::SessionDynamics(int axis) const { return At(axis).session; }

void AxisGroup::SetSessionSpeed(int axis, double speed) {
    if (!(speed > 0.0)) throw std::invalid_argument("AxisGroup::SetSessionSpeed: speed must be > 0");
    At(axis).session.speed = speed;
}

void AxisGroup::SetSessionAcceleration(int axis, double acceleration) {
    if (!(acceleration > 0.0)) {
        throw std::invalid_argument("AxisGroup::SetSessionAcceleration: acceleration must be > 0");
    }
    Dynamics& d = At(axis).session;
    d.acceleration = acceleration;
    d.deceleration = acceleration;
}

const ServoAxisConfig& AxisGroup::Machine(int axis) const { return At(axis).machine; }

void AxisGroup::SetMachine(int axis, const ServoAxisConfig& machine) {
    Axis& a = At(axis);
    const ServoAxisConfig config = ConfigFrom(machine, a.parameters);
    config.Validate();
    a.machine = machine;
    a.motion.SetConfig(a.motion.Now(), config);
}

void AxisGroup::SetLimitSwitches(int axis, std::optional<double> negative, std::optional<double> positive) {
    ServoAxisConfig machine = Machine(axis);
    machine.negativeLimitSwitch = negative;
    machine.positiveLimitSwitch = positive;
    SetMachine(axis, machine);
}

void AxisGroup::SetReferenceSwitch(int axis, double edge, Direction camSide) {
    ServoAxisConfig machine = Machine(axis);
    machine.referenceSwitch = edge;
    machine.referenceCamSide = camSide;
    SetMachine(axis, machine);
}

void AxisGroup::SetBlocked(int axis, std::chrono::nanoseconds now, bool blocked) {
    Motion(axis).SetBlocked(now, blocked);
}

void AxisGroup::SetDisturbance(int axis, std::chrono::nanoseconds now, double offset) {
    Motion(axis).SetDisturbance(now, offset);
}

bool AxisGroup::Displace(int axis, std::chrono::nanoseconds now, double delta) {
    return Motion(axis).Displace(now, delta);
}

void AxisGroup::RaiseAxisError(int axis, std::chrono::nanoseconds now, std::uint16_t number) {
    Motion(axis).RaiseAxisError(now, number);
}

void AxisGroup::Restart(std::chrono::nanoseconds now, bool referenced) {
    for (auto& a : axes_) {
        a.motion.EmergencyStop(now);
        a.motion.ResetAxisError(now);
        a.motion.SetDriveDisabled(now, false);
        a.motion.SetAxisOn(now, true);
        a.motion.SetReferenced(referenced);
    }
    ApplyParametersToAll();
}

void AxisGroup::UpdateAll(std::chrono::nanoseconds now) {
    for (auto& a : axes_) a.motion.Update(now);
}

bool AxisGroup::AnyDisplacedDuringOff(int count) const {
    const auto n = static_cast<std::size_t>(count <= 0 ? 0 : (count < Capacity() ? count : Capacity()));
    for (std::size_t k = 0; k < n; ++k) {
        if (axes_[k].motion.DisplacedDuringOff()) return true;
    }
    return false;
}

void AxisGroup::StopAll(std::chrono::nanoseconds now) {
    for (auto& a : axes_) a.motion.Interrupt(now);
}

void AxisGroup::HaltAll(std::chrono::nanoseconds now) {
    for (auto& a : axes_) a.motion.EmergencyStop(now);
}

bool AxisGroup::AnyMoving() const {
    for (const auto& a : axes_) {
        if (a.motion.Moving()) return true;
    }
    return false;
}

void AxisGroup::ThrowOutside(int axis) const {
    throw std::out_of_range("AxisGroup: axis " + std::to_string(axis) + " outside 1.." + std::to_string(Capacity()));
}

}  // namespace pac::sim
