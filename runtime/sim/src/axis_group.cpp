// The axes of the simulated PA-CONTROL (see axis_group.hpp).
#include "pac/sim/axis_group.hpp"

#include <stdexcept>
#include <string>

namespace pac::sim {

AxisGroup::AxisGroup(int capacity, const std::vector<ParameterSpec>& axisParameters) {
    if (capacity < 0) throw std::invalid_argument("AxisGroup: capacity must be >= 0");
    for (int i = 0; i < capacity; ++i) {
        axes_.push_back(Axis{LinearAxis{}, ParameterTable(ParameterType::kReal32, axisParameters)});
    }
    ApplyParametersToAll();
}

LinearAxis& AxisGroup::Motion(int axis) { return At(axis).motion; }
const LinearAxis& AxisGroup::Motion(int axis) const { return At(axis).motion; }
ParameterTable& AxisGroup::Parameters(int axis) { return At(axis).parameters; }
const ParameterTable& AxisGroup::Parameters(int axis) const { return At(axis).parameters; }

void AxisGroup::ApplyParameters(int axis) {
    Axis& a = At(axis);
    if (auto speed = a.parameters.RealValue(axisparam::kTraverseSpeed); speed && *speed > 0.0F) {
        a.motion.SetSpeed(*speed);
    }
    if (auto accel = a.parameters.RealValue(axisparam::kAcceleration)) {
        a.motion.SetDeceleration(*accel);
    }
}

void AxisGroup::ApplyParametersToAll() {
    for (int axis = 1; axis <= Capacity(); ++axis) ApplyParameters(axis);
}

void AxisGroup::UpdateAll(std::chrono::nanoseconds now) {
    for (auto& a : axes_) a.motion.Update(now);
}

void AxisGroup::StopAll(std::chrono::nanoseconds now) {
    for (auto& a : axes_) a.motion.Stop(now);
}

void AxisGroup::HaltAll(std::chrono::nanoseconds now) {
    for (auto& a : axes_) a.motion.Halt(now);
}

bool AxisGroup::AnyMoving() const {
    for (const auto& a : axes_) {
        if (a.motion.Moving()) return true;
    }
    return false;
}

AxisGroup::Axis& AxisGroup::At(int axis) {
    if (!Contains(axis)) {
        throw std::out_of_range("AxisGroup: axis " + std::to_string(axis) + " outside 1.." +
                                std::to_string(Capacity()));
    }
    return axes_[static_cast<std::size_t>(axis - 1)];
}

const AxisGroup::Axis& AxisGroup::At(int axis) const {
    if (!Contains(axis)) {
        throw std::out_of_range("AxisGroup: axis " + std::to_string(axis) + " outside 1.." +
                                std::to_string(Capacity()));
    }
    return axes_[static_cast<std::size_t>(axis - 1)];
}

}  // namespace pac::sim
