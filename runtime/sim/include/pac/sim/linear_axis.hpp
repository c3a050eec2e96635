// A deliberately simple axis for the CMD interface (a real axis model, after anpos2, comes later):
// it travels at constant speed to its target, and a stop brakes at a constant deceleration (or halts
// at once when the deceleration is <= 0). Positions follow from the start of each segment and the
// simulated time in nanoseconds, so 1000 AE/s for 10 ms is exactly 10 AE.
#pragma once

#include <chrono>
#include <cstdint>

namespace pac::sim {

// Values of cmd_get_status_axis (1910, manual 5.2.4.22).
enum class AxisStatus : std::uint16_t {
    kInPosition = 0,   // standing, in position
    kMoving = 1,
    kStopped = 2,      // standing still, was stopped
    kMalfunction = 4,  // standing still, with malfunction
};

class LinearAxis {
public:
    // Brings the position up to `now` (earlier times are ignored: time never runs backwards).
    void Update(std::chrono::nanoseconds now);

    void MoveTo(std::chrono::nanoseconds now, double target);  // at Speed(), from the current position
    void Stop(std::chrono::nanoseconds now);                   // brakes at Deceleration()
    void Halt(std::chrono::nanoseconds now);                   // stands still at once

    bool Moving() const { return phase_ != Phase::kIdle; }  // travelling or braking
    AxisStatus Status() const { return Moving() ? AxisStatus::kMoving : rest_; }
    double Position() const { return position_; }
    double Target() const { return target_; }
    double ActualSpeed() const { return actualSpeed_; }

    double Speed() const { return speed_; }
    void SetSpeed(double unitsPerSecond);  // > 0, std::invalid_argument otherwise; for later moves
    double Deceleration() const { return deceleration_; }
    void SetDeceleration(double unitsPerSecond2) { deceleration_ = unitsPerSecond2; }

    // Test hooks: place the axis (it stands still, in position), mark it faulty, (un)reference it.
    void SetPosition(double position);
    void SetMalfunction(bool malfunction);
    bool Referenced() const { return referenced_; }
    void SetReferenced(bool referenced) { referenced_ = referenced; }

private:
    enum class Phase { kIdle, kTravel, kBrake };

    void Rest(AxisStatus status);

    Phase phase_ = Phase::kIdle;
    AxisStatus rest_ = AxisStatus::kInPosition;
    double position_ = 0.0;
    double target_ = 0.0;
    double actualSpeed_ = 0.0;
    double speed_ = 1000.0;
    double deceleration_ = 10000.0;
    bool referenced_ = true;
    // The current segment: start time, start position, direction (+1/-1), start speed.
    std::chrono::nanoseconds segmentStart_{0};
    double segmentPosition_ = 0.0;
    double direction_ = 1.0;
    double segmentSpeed_ = 0.0;
    std::chrono::nanoseconds now_{0};
};

}  // namespace pac::sim
