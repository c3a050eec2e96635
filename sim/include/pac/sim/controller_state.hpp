// Everything the simulated PA-CONTROL knows, apart from the CMD handshake: operating status, system
// error number, format in force, battery, elements, system parameters, axes and what the ONLINE commands
// keep per axis. PaControl owns one;
// CommandExecutor works on it; ModeMachine alone changes the status, error number and format.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "pac/sim/axis_group.hpp"
#include "pac/sim/elements.hpp"
#include "pac/sim/online_axes.hpp"
#include "pac/sim/operating_status.hpp"
#include "pac/sim/parameter_table.hpp"

namespace pac::sim {

struct ControllerState {
    ControllerState(const ElementCounts& counts, const std::vector<ParameterSpec>& systemSpecs, int axisCapacity,
                    const std::vector<ParameterSpec>& axisSpecs, const ServoAxisConfig& axisMachine = {},
                    const OnlineCommandOptions& onlineOptions = {})
        : elements(counts),
          systemParameters(ParameterType::kInt32, systemSpecs),
          axes(axisCapacity, axisSpecs, axisMachine),
          online(axisCapacity, onlineOptions) {}

    // Addressable axes: system parameter 2 ("Number of axes"), within 0..axes.Capacity().
    int NumberOfAxes() const {
        const auto n = systemParameters.IntValue(sysparam::kNumberOfAxes).value_or(0);
        return std::clamp(static_cast<int>(n), 0, axes.Capacity());
    }
    bool AxisAddressable(int axis) const { return axis >= 1 && axis <= NumberOfAxes(); }
    Mode CurrentMode() const { return ModeOf(operatingStatus); }

    std::uint8_t operatingStatus = status::kNotInitialized;
    std::uint16_t systemError = 0;  // PA-CONTROL error number (1909); FE = systemError != 0
    bool integerFormat = false;     // 2.5.3: axis positions and R registers as integers x1000
    bool batteryOk = true;          // 2.5.2 status word bit 1
    int axisModules = 0;            // axis modules in the bus layout: CMD axis commands blocked (2.7 note)
    Elements elements;
    ParameterTable systemParameters;
    AxisGroup axes;
    OnlineAxes online;  // what the ONLINE commands keep per axis beside its motion
};

}  // namespace pac::sim
