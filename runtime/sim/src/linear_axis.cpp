// Constant-speed axis with a braking stop (see linear_axis.hpp).
#include "pac/sim/linear_axis.hpp"

#include <cmath>
#include <stdexcept>

namespace pac::sim {

namespace {
constexpr double kNsPerSecond = 1e9;
}

void LinearAxis::Update(std::chrono::nanoseconds now) {
    if (now < now_) return;
    now_ = now;
    const double elapsedNs = static_cast<double>((now - segmentStart_).count());
    const double remaining = std::fabs(target_ - segmentPosition_);
    if (phase_ == Phase::kTravel) {
        const double distance = segmentSpeed_ * elapsedNs / kNsPerSecond;
        if (distance >= remaining) {
            position_ = target_;
            Rest(AxisStatus::kInPosition);
        } else {
            position_ = segmentPosition_ + direction_ * distance;
            actualSpeed_ = segmentSpeed_;
        }
    } else if (phase_ == Phase::kBrake) {
        const double dt = elapsedNs / kNsPerSecond;
        const double stopTime = segmentSpeed_ / deceleration_;
        const bool stopped = dt >= stopTime;
        const double distance = stopped ? segmentSpeed_ * segmentSpeed_ / (2.0 * deceleration_)
                                        : segmentSpeed_ * dt - deceleration_ * dt * dt / 2.0;
        if (distance >= remaining) {
            position_ = target_;
            Rest(AxisStatus::kInPosition);
        } else if (stopped) {
            position_ = segmentPosition_ + direction_ * distance;
            Rest(AxisStatus::kStopped);
        } else {
            position_ = segmentPosition_ + direction_ * distance;
            actualSpeed_ = segmentSpeed_ - deceleration_ * dt;
        }
    }
}

void LinearAxis::MoveTo(std::chrono::nanoseconds now, double target) {
    Update(now);
    target_ = target;
    if (target == position_) {
        Rest(AxisStatus::kInPosition);
        return;
    }
    phase_ = Phase::kTravel;
    segmentStart_ = now_;
    segmentPosition_ = position_;
    direction_ = target > position_ ? 1.0 : -1.0;
    segmentSpeed_ = speed_;
    actualSpeed_ = speed_;
}

void LinearAxis::Stop(std::chrono::nanoseconds now) {
    Update(now);
    if (phase_ != Phase::kTravel) return;  // standing, or braking already
    if (deceleration_ <= 0.0) {
        Rest(AxisStatus::kStopped);
        return;
    }
    phase_ = Phase::kBrake;
    segmentStart_ = now_;
    segmentPosition_ = position_;
    segmentSpeed_ = actualSpeed_;
}

void LinearAxis::Halt(std::chrono::nanoseconds now) {
    Update(now);
    if (Moving()) Rest(AxisStatus::kStopped);
}

void LinearAxis::SetSpeed(double unitsPerSecond) {
    if (!(unitsPerSecond > 0.0)) throw std::invalid_argument("LinearAxis::SetSpeed: speed must be > 0");
    speed_ = unitsPerSecond;
}

void LinearAxis::SetPosition(double position) {
    position_ = position;
    target_ = position;
    Rest(AxisStatus::kInPosition);
}

void LinearAxis::SetMalfunction(bool malfunction) {
    if (malfunction) {
        Rest(AxisStatus::kMalfunction);
    } else if (rest_ == AxisStatus::kMalfunction) {
        rest_ = AxisStatus::kStopped;
    }
}

void LinearAxis::Rest(AxisStatus status) {
    phase_ = Phase::kIdle;
    rest_ = status;
    actualSpeed_ = 0.0;
}

}  // namespace pac::sim
