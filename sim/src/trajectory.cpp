// Linear and S-shaped motion profiles (see trajectory.hpp).
#include "pac/sim/trajectory.hpp"

#include <cmath>
#include <limits>

namespace pac::sim {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Share of the speed change reached at x = tau / T of a ramp, its integral over x, and its slope.
double Share(RampType ramp, double x) {
    if (ramp == RampType::kLinear) return x;
    return x <= 0.5 ? 2.0 * x * x : 1.0 - 2.0 * (1.0 - x) * (1.0 - x);
}

double ShareIntegral(RampType ramp, double x) {
    if (ramp == RampType::kLinear) return x * x / 2.0;
    if (x <= 0.5) return 2.0 * x * x * x / 3.0;
    const double rest = 1.0 - x;
    return x - 0.5 + 2.0 * rest * rest * rest / 3.0;
}

double ShareSlope(RampType ramp, double x) {
    if (ramp == RampType::kLinear) return 1.0;
    return x <= 0.5 ? 4.0 * x : 4.0 * (1.0 - x);
}

}  // namespace

double Sign(Direction direction) { return direction == Direction::kPositive ? 1.0 : -1.0; }

Direction Opposite(Direction direction) {
    return direction == Direction::kPositive ? Direction::kNegative : Direction::kPositive;
}

bool IsValid(const Dynamics& d) {
    const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
    return positive(d.speed) && positive(d.acceleration) && positive(d.deceleration);
}

Trajectory Trajectory::Hold(double position) {
    Trajectory t;
    t.start_ = position;
    t.end_ = position;
    return t;
}

Trajectory Trajectory::PointToPoint(double start, double target, const Dynamics& dynamics, RampType ramp) {
    const double distance = std::fabs(target - start);
    if (!(distance > 0.0)) return Hold(target);
    Trajectory t;
    t.start_ = start;
    t.sign_ = target > start ? 1.0 : -1.0;
    t.ramp_ = ramp;
    const double a = dynamics.acceleration;
    const double d = dynamics.deceleration;
    const double v = dynamics.speed;
    const double up = v * v / (2.0 * a);
    const double down = v * v / (2.0 * d);
    if (up + down <= distance) {
        t.Append(v / a, 0.0, v);
        t.Append((distance - up - down) / v, v, v);
        t.Append(v / d, v, 0.0);
    } else {
        // Peak speed p with p^2/2a + p^2/2d = distance.
        const double peak = std::sqrt(2.0 * distance * a * d / (a + d));
        t.Append(peak / a, 0.0, peak);
        t.Append(peak / d, peak, 0.0);
    }
    t.distance_ = distance;  // exact, whatever the rounding of the segment sums
    t.end_ = target;
    return t;
}

std::optional<Trajectory> Trajectory::FromSpeed(double start, double target, double speed, const Dynamics& dynamics,
                                               RampType ramp) {
    const double distance = std::fabs(target - start);
    const double a = dynamics.acceleration;
    const double d = dynamics.deceleration;
    const double v = dynamics.speed;
    const double stop = speed * speed / (2.0 * d);
    if (!(speed > 0.0) || distance < stop) return std::nullopt;
    Trajectory t;
    t.start_ = start;
    t.sign_ = target > start ? 1.0 : -1.0;
    t.ramp_ = ramp;
    if (v < speed) {
        // Down to the new speed and, at the end, to standstill: together exactly the stop from `speed`.
        t.Append((speed - v) / d, speed, v);
        t.Append((distance - stop) / v, v, v);
        t.Append(v / d, v, 0.0);
    } else {
        const double up = (v * v - speed * speed) / (2.0 * a);
        const double down = v * v / (2.0 * d);
        if (up + down <= distance) {
            t.Append((v - speed) / a, speed, v);
            t.Append((distance - up - down) / v, v, v);
            t.Append(v / d, v, 0.0);
        } else {
            // Peak p with (p^2 - speed^2)/2a + p^2/2d = distance; p >= speed since distance >= stop.
            const double peak = std::sqrt((2.0 * a * d * distance + d * speed * speed) / (a + d));
            t.Append((peak - speed) / a, speed, peak);
            t.Append(peak / d, peak, 0.0);
        }
    }
    t.distance_ = distance;
    t.end_ = target;
    return t;
}

Trajectory Trajectory::Run(double start, Direction direction, double speed, double acceleration, RampType ramp) {
    Trajectory t;
    t.start_ = start;
    t.sign_ = Sign(direction);
    t.ramp_ = ramp;
    t.Append(speed / acceleration, 0.0, speed);
    t.Append(kInfinity, speed, speed);
    t.distance_ = kInfinity;
    t.end_ = t.sign_ * kInfinity;
    return t;
}

Trajectory Trajectory::Brake(double start, Direction direction, double speed, double deceleration, RampType ramp) {
    if (!(speed > 0.0)) return Hold(start);
    Trajectory t;
    t.start_ = start;
    t.sign_ = Sign(direction);
    t.ramp_ = ramp;
    t.Append(speed / deceleration, speed, 0.0);
    t.end_ = start + t.sign_ * t.distance_;
    return t;
}

void Trajectory::Append(double duration, double startSpeed, double endSpeed) {
    if (!(duration > 0.0)) return;
    segments_.at(segmentCount_++) = Segment{duration_, duration, startSpeed, endSpeed, distance_};
    duration_ += duration;
    distance_ += std::isinf(duration) ? kInfinity : (startSpeed + endSpeed) / 2.0 * duration;
}

inline double Trajectory::SegmentDistance(const Segment& s, double tau) const {
    if (s.startSpeed == s.endSpeed) return s.startSpeed * tau;
    return s.startSpeed * tau + (s.endSpeed - s.startSpeed) * s.duration * ShareIntegral(ramp_, tau / s.duration);
}

double Trajectory::SegmentSpeed(const Segment& s, double tau) const {
    if (s.startSpeed == s.endSpeed) return s.startSpeed;
    return s.startSpeed + (s.endSpeed - s.startSpeed) * Share(ramp_, tau / s.duration);
}

double Trajectory::SegmentAcceleration(const Segment& s, double tau) const {
    if (s.startSpeed == s.endSpeed) return 0.0;
    return (s.endSpeed - s.startSpeed) / s.duration * ShareSlope(ramp_, tau / s.duration);
}

const Trajectory::Segment* Trajectory::SegmentAt(double t) const {
    // The last one that has started: the start times grow from segment to segment.
    for (std::size_t i = segmentCount_; i > 0; --i) {
        if (segments_[i - 1].startTime <= t) return &segments_[i - 1];
    }
    return nullptr;
}

double Trajectory::PositionAt(double t) const {
    if (!Moves() || t <= 0.0) return start_;
    if (t >= duration_) return EndPosition();
    const Segment* s = SegmentAt(t);
    return start_ + sign_ * (s->startDistance + SegmentDistance(*s, t - s->startTime));
}

double Trajectory::VelocityAt(double t) const {
    if (!Moves() || t >= duration_) return 0.0;
    const Segment* s = SegmentAt(t < 0.0 ? 0.0 : t);
    return sign_ * SegmentSpeed(*s, (t < 0.0 ? 0.0 : t) - s->startTime);
}

double Trajectory::AccelerationAt(double t) const {
    if (!Moves() || t >= duration_) return 0.0;
    const Segment* s = SegmentAt(t < 0.0 ? 0.0 : t);
    return sign_ * SegmentAcceleration(*s, (t < 0.0 ? 0.0 : t) - s->startTime);
}

MotionPhase Trajectory::PhaseAt(double t) const {
    if (!Moves() || t >= duration_) return MotionPhase::kStandstill;
    const Segment* s = SegmentAt(t < 0.0 ? 0.0 : t);
    if (s->endSpeed > s->startSpeed) return MotionPhase::kAccelerating;
    if (s->endSpeed < s->startSpeed) return MotionPhase::kDecelerating;
    return MotionPhase::kConstantSpeed;
}

bool Trajectory::FinalRampAt(double t) const {
    if (!Moves() || t >= duration_) return false;
    const Segment* s = SegmentAt(t < 0.0 ? 0.0 : t);
    return s == &segments_[segmentCount_ - 1] && s->endSpeed == 0.0 && s->startSpeed > 0.0;
}

std::optional<double> Trajectory::TimeToReach(double position) const {
    if (!Moves()) {
        if (position == start_) return 0.0;
        return std::nullopt;
    }
    const double wanted = (position - start_) * sign_;
    if (wanted <= 0.0) return 0.0;
    if (wanted > distance_) return std::nullopt;
    if (wanted == distance_) return duration_;
    for (std::size_t i = 0; i < segmentCount_; ++i) {
        const Segment& s = segments_[i];
        const double end = i + 1 < segmentCount_ ? segments_[i + 1].startDistance : distance_;
        if (wanted > end) continue;
        const double rest = wanted - s.startDistance;
        if (s.startSpeed == s.endSpeed) {
            const double tau = rest / s.startSpeed;
            return s.startTime + (tau < s.duration ? tau : s.duration);
        }
        // Monotone within the ramp: bisect to the last representable step (deterministic, no tolerance).
        double lo = 0.0;
        double hi = s.duration;
        for (int k = 0; k < 200; ++k) {
            const double mid = lo + (hi - lo) / 2.0;
            if (mid <= lo || mid >= hi) break;
            if (SegmentDistance(s, mid) >= rest) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return s.startTime + hi;
    }
    return duration_;
}

}  // namespace pac::sim
