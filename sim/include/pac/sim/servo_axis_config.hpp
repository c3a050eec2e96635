// Configuration of the simulated servo axis (docs/sim_axis.md): what the PA-CONTROL's axis parameters
// (manual 5.2.3) and the machine around the axis (switches, index pulses) give it, after the ANPOS2
// parameter list. Plain values with defaults; Validate() names the first field that is wrong.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>

#include "pac/sim/trajectory.hpp"

namespace pac::sim {

// What Axis ON = 0 does (manual 2.7.3.1; PA-CONTROL axis parameter 50 "enable mode for axes").
enum class EnableMode { kHalt, kIdle, kSafe };

// ANPOS2 parameter 25 (prsmode).
enum class HomingMode {
    kSwitch = 0,          // the home point is where the axis leaves the reference switch at creep speed
    kSwitchAndIndex = 1,  // ... the first index pulse after leaving the reference switch
    kLoadOnSwitch = 2,    // no movement: the next time the switch becomes actuated loads the position
};

struct ServoAxisConfig {
    // Dynamics: axis parameters 1 traverse speed, 2 reference speed, 4 creep speed, 6 acceleration (units/s,
    // units/s^2), 30 ramp type. The PA-CONTROL has one acceleration parameter; ANPOS2 separates
    // acceleration (15) and deceleration (16): the integrator sets both from parameter 6.
    double traverseSpeed = 1000.0;
    double referenceSpeed = 500.0;
    double creepSpeed = 100.0;
    double acceleration = 10000.0;
    double deceleration = 10000.0;
    RampType rampType = RampType::kLinear;

    // Software limits, axis parameters 8 / 9 (in the axis's coordinates; G29 shifts them).
    double minTraverseRange = 0.0;
    double maxTraverseRange = 10000.0;

    // The machine, in machine coordinates (= the axis's coordinates at power-on, before any G25 / G26 / G29).
    // A limit switch is actuated at its position and beyond; none configured = none fitted.
    std::optional<double> negativeLimitSwitch = -50.0;
    std::optional<double> positiveLimitSwitch = 10050.0;
    // The reference cam: actuated from the edge on, towards referenceCamSide (the edge belongs to the cam).
    double referenceSwitch = -20.0;
    Direction referenceCamSide = Direction::kNegative;
    // Index (zero) pulses of the encoder at indexOffset + k * indexPitch (homing mode 1).
    double indexPitch = 10.0;
    double indexOffset = 0.0;
    double startPosition = 0.0;  // where the axis stands at power-on

    // Homing (G25): mode, direction of the search (ANPOS2 26 prsdir), and the position the home point gets
    // (ANPOS2 5 prspos).
    HomingMode homingMode = HomingMode::kSwitch;
    Direction homingDirection = Direction::kNegative;
    double referencePosition = 0.0;

    // In position: within +-toleranceWindow of the target for toleranceDelay (ANPOS2 10 / 20). Following error
    // above followingErrorLimit -> axis error (ANPOS2 11; PA-CONTROL axis parameter 17 "maximum towfault");
    // infinity switches the monitoring off.
    double toleranceWindow = 0.01;
    std::chrono::nanoseconds toleranceDelay{0};
    double followingErrorLimit = 1.0;

    // Switching off: enable mode, and the "displaced during OFF" check (axis parameter "maximum position
    // displacement after axis-OFF", manual 2.7.4.12; off = the "switch on traverse mode" is not 4).
    EnableMode enableMode = EnableMode::kHalt;
    bool displacementMonitoring = true;
    double maxDisplacementOff = 1.0;

    bool referenced = false;  // at power-on (absolute measuring system, or the simulator's referencedAtPowerOn)

    // std::invalid_argument naming the field and the rule.
    void Validate() const;
    // Full traverse speed with the acceleration and deceleration parameters (per mille 1000 / 1000).
    Dynamics FullDynamics() const { return Dynamics{traverseSpeed, acceleration, deceleration}; }
};

// Axis module (manual 2.7.5 / 2.7.6): speed = speedPerMille x traverse speed / 1000 (1..1000), acceleration and
// deceleration = accelerationPerMille x their parameter / 1000 (1..65535; may exceed the parameter).
// nullopt outside those ranges.
std::optional<Dynamics> ScaledDynamics(const ServoAxisConfig& config, std::uint32_t speedPerMille,
                                       std::uint32_t accelerationPerMille);

}  // namespace pac::sim
