// Motion profiles of the simulated servo axis (docs/sim_axis.md), after the ANPOS2 trajectory generator:
// linear (trapezoidal) or S-shaped ramps. A profile runs in one direction only, so its position is monotone
// and "when does it reach x" has one answer. Positions follow from the profile's start and the time since
// then (never from summed steps), so they do not depend on how often anyone evaluates them.
#pragma once

#include <array>
#include <cstddef>
#include <optional>

namespace pac::sim {

// ANPOS2 parameter 14 / PA-CONTROL axis parameter 30 "ramp type": 0 linear, 1 S-shaped.
enum class RampType { kLinear = 0, kSCurve = 1 };

enum class Direction { kPositive, kNegative };
double Sign(Direction direction);  // +1 / -1
Direction Opposite(Direction direction);

// Speed and ramps of one job, in units/s and units/s^2 (all > 0 and finite to be valid).
struct Dynamics {
    double speed = 0.0;
    double acceleration = 0.0;
    double deceleration = 0.0;
};
bool IsValid(const Dynamics& dynamics);

// ANPOS2 states st_acc / st_vconst / st_dec, or standing (st_still).
enum class MotionPhase { kStandstill, kAccelerating, kConstantSpeed, kDecelerating };

// A ramp from speed v0 to v1 takes |v1 - v0| / a for both ramp types (ANPOS2 defines its ramps by the time
// from 0 to full speed). The S ramp lets the acceleration rise and fall linearly (constant jerk, peak 2 a);
// since its speed curve is point-symmetric, it covers the same distance as the linear ramp. Planning, short
// moves and total times are therefore the same for both types; only the shape inside a ramp differs.
class Trajectory {
public:
    Trajectory() = default;  // standing at 0

    static Trajectory Hold(double position);
    // From standstill at `start` to standstill at `target`: accelerate, cruise at `dynamics.speed`, decelerate.
    // A move too short to reach that speed turns at the highest speed it can reach (no cruise).
    static Trajectory PointToPoint(double start, double target, const Dynamics& dynamics, RampType ramp);
    // From `speed` (>= 0, towards `target`) at `start` to standstill at `target` with new dynamics: a ramp to
    // dynamics.speed (or the highest speed the distance allows), cruise, decelerate. nullopt when the distance
    // is shorter than braking from `speed` with dynamics.deceleration takes (a speed change too late, 2.7.6).
    static std::optional<Trajectory> FromSpeed(double start, double target, double speed, const Dynamics& dynamics,
                                               RampType ramp);
    // From standstill, up to `speed`, then on at that speed without end (a search run).
    static Trajectory Run(double start, Direction direction, double speed, double acceleration, RampType ramp);
    // From `speed` (>= 0) in `direction` down to standstill.
    static Trajectory Brake(double start, Direction direction, double speed, double deceleration, RampType ramp);

    // t in seconds since the start of the profile; before it the start, after the end the end.
    double PositionAt(double t) const;
    double VelocityAt(double t) const;      // signed
    double AccelerationAt(double t) const;  // signed (the sign of the velocity change)
    MotionPhase PhaseAt(double t) const;
    bool FinalRampAt(double t) const;  // on the last ramp, down to standstill (not a ramp to a lower speed)

    bool Moves() const { return segmentCount_ != 0; }
    Direction Dir() const { return sign_ > 0.0 ? Direction::kPositive : Direction::kNegative; }
    double StartPosition() const { return start_; }
    double Duration() const { return duration_; }        // infinity for Run
    double EndPosition() const { return end_; }           // +-infinity for Run
    // The first time (s) at which the profile is at `position` or beyond it in its direction: 0 if it starts
    // there or beyond, nullopt if it never gets there.
    std::optional<double> TimeToReach(double position) const;

private:
    // Speed from startSpeed to endSpeed over duration (infinite for the cruise of Run, which keeps its speed).
    struct Segment {
        double startTime;
        double duration;
        double startSpeed;
        double endSpeed;
        double startDistance;
    };
    double SegmentDistance(const Segment& s, double tau) const;
    double SegmentSpeed(const Segment& s, double tau) const;
    double SegmentAcceleration(const Segment& s, double tau) const;
    const Segment* SegmentAt(double t) const;
    void Append(double duration, double startSpeed, double endSpeed);

    // What PositionAt() reads in every cycle first, before the segments, so that it shares their cache lines.
    double start_ = 0.0;
    double sign_ = 1.0;
    double duration_ = 0.0;
    std::size_t segmentCount_ = 0;
    RampType ramp_ = RampType::kLinear;
    double end_ = 0.0;
    double distance_ = 0.0;  // along the direction; infinity for Run
    // A profile has at most three segments (ramp, cruise, ramp): held inline, so that a new or copied profile
    // (every job, every stop) needs no allocation.
    static constexpr std::size_t kMaxSegments = 3;
    std::array<Segment, kMaxSegments> segments_{};
};

}  // namespace pac::sim
