// The axes of the simulated PA-CONTROL, numbered 1..Capacity(): each has its motion (ServoAxis), its
// parameter table (0800/1800), the machine around it (switches, homing, enable mode: everything of a
// ServoAxisConfig that is not an axis parameter) and the dynamics of the CMD moves of the ONLINE session
// (0A8D / 0A8E). How many are addressable over the CMD interface is system parameter 2, "Number of axes";
// the group holds Capacity() of them so that parameter can change.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "pac/sim/parameter_table.hpp"
#include "pac/sim/servo_axis.hpp"

namespace pac::sim {

class AxisGroup {
public:
    // Every axis gets `machine` (its parameter fields are overwritten by the axis parameters).
    AxisGroup(int capacity, const std::vector<ParameterSpec>& axisParameters, const ServoAxisConfig& machine = {});

    int Capacity() const { return capacity_; }
    bool Contains(int axis) const { return axis >= 1 && axis <= Capacity(); }

    // std::out_of_range outside 1..Capacity().
    ServoAxis& Motion(int axis) { return At(axis).motion; }
    const ServoAxis& Motion(int axis) const { return At(axis).motion; }
    // Motion(axis) for a loop whose bounds already keep axis within 1..Capacity(): no check.
    ServoAxis& MotionInRange(int axis) { return axes_[static_cast<std::size_t>(axis - 1)].motion; }
    const ServoAxis& MotionInRange(int axis) const { return axes_[static_cast<std::size_t>(axis - 1)].motion; }
    ParameterTable& Parameters(int axis) { return At(axis).parameters; }
    const ParameterTable& Parameters(int axis) const { return At(axis).parameters; }

    // The axis parameters on top of `machine`: 1 traverse speed, 2 reference speed, 4 creep speed, 6
    // acceleration (and deceleration), 8 / 9 traverse range, 30 ramp type (>= 0.5: S). A parameter the table
    // does not have leaves the machine's value.
    static ServoAxisConfig ConfigFrom(const ServoAxisConfig& machine, const ParameterTable& parameters);

    // The parameters to the axis, and the session dynamics back to them, as the ONLINE mode takes them over
    // when it starts or ends (5.2.6.8), and after 0800. Parameters that do not fit together (min. range above
    // max. range) leave the axis with its previous configuration: false.
    bool ApplyParameters(int axis);
    void ApplyParametersToAll();

    // CMD moves (0A87 ...) of the ONLINE session: speed (0A8D) and acceleration = deceleration (0A8E).
    const Dynamics& SessionDynamics(int axis) const;
    void SetSessionSpeed(int axis, double speed);
    void SetSessionAcceleration(int axis, double acceleration);

    // The machine around an axis (test hooks); the axis parameters are applied on top at once.
    const ServoAxisConfig& Machine(int axis) const;
    void SetMachine(int axis, const ServoAxisConfig& machine);  // std::invalid_argument if invalid
    // Hardware limit switches at these machine positions (nullopt: none fitted).
    void SetLimitSwitches(int axis, std::optional<double> negative, std::optional<double> positive);
    // The reference cam's edge (machine position) and the side the cam extends to.
    void SetReferenceSwitch(int axis, double edge, Direction camSide = Direction::kNegative);

    // Faults on one axis at `now` (test hooks; see ServoAxis).
    void SetBlocked(int axis, std::chrono::nanoseconds now, bool blocked);       // following error builds up
    void SetDisturbance(int axis, std::chrono::nanoseconds now, double offset);  // a load the servo cannot correct
    bool Displace(int axis, std::chrono::nanoseconds now, double delta);         // pushed while without current
    void RaiseAxisError(int axis, std::chrono::nanoseconds now, std::uint16_t number);

    // Power cycle: every axis stops at once where it stands, its axis error is reset, it is switched on with
    // the drive enabled, referenced as given, and the parameters apply (position and G29 shift stay).
    void Restart(std::chrono::nanoseconds now, bool referenced);

    void UpdateAll(std::chrono::nanoseconds now);
    // Whether one of axes 1..count is "displaced during OFF" (the axis modules' group, 2.7.4.13).
    bool AnyDisplacedDuringOff(int count) const;
    void StopAll(std::chrono::nanoseconds now);  // interrupt: braking with each job's deceleration
    void HaltAll(std::chrono::nanoseconds now);  // emergency stop: at once, without a ramp
    bool AnyMoving() const;

private:
    struct Axis {
        ServoAxis motion;
        ParameterTable parameters;
        ServoAxisConfig machine;
        Dynamics session;
    };
    // Inline: the controller looks axes up many times per cycle.
    Axis& At(int axis) {
        if (!Contains(axis)) ThrowOutside(axis);
        return axes_[static_cast<std::size_t>(axis - 1)];
    }
    const Axis& At(int axis) const {
        if (!Contains(axis)) ThrowOutside(axis);
        return axes_[static_cast<std::size_t>(axis - 1)];
    }
    [[noreturn]] void ThrowOutside(int axis) const;

    std::vector<Axis> axes_;
    int capacity_ = 0;  // axes_.size(), kept: the size of a vector of Axis takes a multiplication per lookup
};

}  // namespace pac::sim
