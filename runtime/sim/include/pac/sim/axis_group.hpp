// The axes of the simulated PA-CONTROL, numbered 1..Capacity(): each has its motion (LinearAxis) and
// its parameter table (0800/1800). How many are addressable is system parameter 2, "Number of axes";
// the group holds Capacity() of them so that parameter can change.
#pragma once

#include <chrono>
#include <vector>

#include "pac/sim/linear_axis.hpp"
#include "pac/sim/parameter_table.hpp"

namespace pac::sim {

class AxisGroup {
public:
    AxisGroup(int capacity, const std::vector<ParameterSpec>& axisParameters);

    int Capacity() const { return static_cast<int>(axes_.size()); }
    bool Contains(int axis) const { return axis >= 1 && axis <= Capacity(); }

    // std::out_of_range outside 1..Capacity().
    LinearAxis& Motion(int axis);
    const LinearAxis& Motion(int axis) const;
    ParameterTable& Parameters(int axis);
    const ParameterTable& Parameters(int axis) const;

    // Speed (parameter 1) and braking deceleration (parameter 6) of the motion from the parameters,
    // as the ONLINE mode takes them over when it starts or ends (5.2.6.8).
    void ApplyParameters(int axis);
    void ApplyParametersToAll();

    void UpdateAll(std::chrono::nanoseconds now);
    void StopAll(std::chrono::nanoseconds now);  // braking
    void HaltAll(std::chrono::nanoseconds now);  // at once
    bool AnyMoving() const;

private:
    struct Axis {
        LinearAxis motion;
        ParameterTable parameters;
    };
    Axis& At(int axis);
    const Axis& At(int axis) const;

    std::vector<Axis> axes_;
};

}  // namespace pac::sim
