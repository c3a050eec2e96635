// The servo axis's trajectory generator (sim trajectory.hpp, docs/sim_axis.md): trapezoid and S
// profiles at given times against hand-computed values, short moves that never reach full speed, braking,
// search runs, and the inverse "when does it reach x".
#include <gtest/gtest.h>

#include <cmath>

#include "pac/sim/trajectory.hpp"

namespace pac::sim {
namespace {

constexpr double kExact = 1e-9;

// 1000 units/s, 10000 units/s^2 both ways: ramps of 0.1 s and 50 units.
const Dynamics kFull{1000.0, 10000.0, 10000.0};

TEST(ServoTrajectory, TrapezoidPositionsSpeedsAndPhases) {
    const Trajectory t = Trajectory::PointToPoint(0.0, 1000.0, kFull, RampType::kLinear);
    EXPECT_NEAR(t.Duration(), 1.1, kExact);  // 0.1 up, 0.9 at 1000, 0.1 down
    EXPECT_EQ(t.PositionAt(0.0), 0.0);
    EXPECT_NEAR(t.PositionAt(0.05), 12.5, kExact);  // a t^2 / 2
    EXPECT_NEAR(t.VelocityAt(0.05), 500.0, kExact);
    EXPECT_NEAR(t.AccelerationAt(0.05), 10000.0, kExact);
    EXPECT_EQ(t.PhaseAt(0.05), MotionPhase::kAccelerating);
    EXPECT_NEAR(t.PositionAt(0.1), 50.0, kExact);
    EXPECT_NEAR(t.PositionAt(0.6), 550.0, kExact);
    EXPECT_NEAR(t.VelocityAt(0.6), 1000.0, kExact);
    EXPECT_EQ(t.PhaseAt(0.6), MotionPhase::kConstantSpeed);
    EXPECT_NEAR(t.PositionAt(1.05), 987.5, kExact);
    EXPECT_NEAR(t.VelocityAt(1.05), 500.0, kExact);
    EXPECT_NEAR(t.AccelerationAt(1.05), -10000.0, kExact);
    EXPECT_EQ(t.PhaseAt(1.05), MotionPhase::kDecelerating);
    EXPECT_EQ(t.PositionAt(1.1), 1000.0);
    EXPECT_EQ(t.PositionAt(5.0), 1000.0);
    EXPECT_EQ(t.VelocityAt(5.0), 0.0);
    EXPECT_EQ(t.PhaseAt(5.0), MotionPhase::kStandstill);
}

TEST(ServoTrajectory, NegativeMoveMirrorsThePositiveOne) {
    const Trajectory t = Trajectory::PointToPoint(100.0, -900.0, kFull, RampType::kLinear);
    EXPECT_EQ(t.Dir(), Direction::kNegative);
    EXPECT_NEAR(t.PositionAt(0.05), 87.5, kExact);
    EXPECT_NEAR(t.VelocityAt(0.6), -1000.0, kExact);
    EXPECT_NEAR(t.AccelerationAt(1.05), 10000.0, kExact);  // slowing a negative speed
    EXPECT_EQ(t.EndPosition(), -900.0);
}

TEST(ServoTrajectory, DifferentAccelerationAndDeceleration) {
    // Up 0.1 s / 50, down at 5000: 0.2 s / 100, cruise 850 units = 0.85 s.
    const Trajectory t = Trajectory::PointToPoint(0.0, 1000.0, Dynamics{1000.0, 10000.0, 5000.0}, RampType::kLinear);
    EXPECT_NEAR(t.Duration(), 1.15, kExact);
    EXPECT_NEAR(t.PositionAt(1.05), 975.0, kExact);  // 900 + 1000 * 0.1 - 5000 * 0.1^2 / 2
}

TEST(ServoTrajectory, ShortMoveTurnsBelowFullSpeed) {
    // 40 units cannot reach 1000 (that needs 100): peak p with p^2/a = 40, p = 632.455...
    const Trajectory t = Trajectory::PointToPoint(0.0, 40.0, kFull, RampType::kLinear);
    const double peak = std::sqrt(400000.0);
    EXPECT_NEAR(t.Duration(), 2.0 * peak / 10000.0, kExact);
    EXPECT_NEAR(t.PositionAt(t.Duration() / 2.0), 20.0, kExact);
    EXPECT_NEAR(t.VelocityAt(t.Duration() / 2.0), peak, 1e-6);
    double fastest = 0.0;
    for (int k = 0; k <= 1000; ++k) fastest = std::fmax(fastest, t.VelocityAt(t.Duration() * k / 1000.0));
    EXPECT_LE(fastest, peak + 1e-9);
    EXPECT_LT(fastest, 1000.0);
    EXPECT_EQ(t.PositionAt(t.Duration()), 40.0);
}

TEST(ServoTrajectory, SCurveKeepsTheLinearTimesAndRampDistances) {
    const Trajectory s = Trajectory::PointToPoint(0.0, 1000.0, kFull, RampType::kSCurve);
    EXPECT_NEAR(s.Duration(), 1.1, kExact);
    // Within the ramp (T = 0.1 s, 0 -> 1000): x = 0.25: speed 1000 * 2x^2 = 125, distance 100 * 2x^3/3.
    EXPECT_NEAR(s.VelocityAt(0.025), 125.0, kExact);
    EXPECT_NEAR(s.PositionAt(0.025), 100.0 * 2.0 * 0.015625 / 3.0, kExact);
    // Half-way: half the speed, a twelfth of v T, the peak acceleration 2a.
    EXPECT_NEAR(s.VelocityAt(0.05), 500.0, kExact);
    EXPECT_NEAR(s.PositionAt(0.05), 100.0 / 12.0, kExact);
    EXPECT_NEAR(s.AccelerationAt(0.05), 20000.0, kExact);
    // The acceleration starts and ends at 0; the ramp ends where the linear one does.
    EXPECT_NEAR(s.AccelerationAt(0.0), 0.0, kExact);
    EXPECT_NEAR(s.AccelerationAt(0.1), 0.0, kExact);
    EXPECT_NEAR(s.PositionAt(0.1), 50.0, kExact);
    EXPECT_NEAR(s.PositionAt(0.6), 550.0, kExact);
    // Braking mirrors it: 1.075 s is x = 0.75 of the down ramp, 25 units left over 0.025 s at 125 -> 0.
    EXPECT_NEAR(s.VelocityAt(1.075), 125.0, kExact);
    EXPECT_NEAR(s.PositionAt(1.075), 1000.0 - 100.0 * 2.0 * 0.015625 / 3.0, kExact);
    EXPECT_EQ(s.PositionAt(1.1), 1000.0);
}

TEST(ServoTrajectory, SCurveShortMoveMatchesTheLinearOne) {
    const Trajectory linear = Trajectory::PointToPoint(0.0, 40.0, kFull, RampType::kLinear);
    const Trajectory s = Trajectory::PointToPoint(0.0, 40.0, kFull, RampType::kSCurve);
    EXPECT_NEAR(s.Duration(), linear.Duration(), kExact);
    EXPECT_NEAR(s.PositionAt(s.Duration() / 2.0), 20.0, kExact);
    EXPECT_NEAR(s.VelocityAt(s.Duration() / 2.0), linear.VelocityAt(linear.Duration() / 2.0), 1e-6);
    // The S ramp starts softer: behind the linear one early in the ramp.
    EXPECT_LT(s.PositionAt(0.01), linear.PositionAt(0.01));
}

TEST(ServoTrajectory, BrakeAndRun) {
    const Trajectory brake = Trajectory::Brake(250.0, Direction::kPositive, 1000.0, 10000.0, RampType::kLinear);
    EXPECT_NEAR(brake.Duration(), 0.1, kExact);
    EXPECT_NEAR(brake.EndPosition(), 300.0, kExact);
    EXPECT_NEAR(brake.VelocityAt(0.0), 1000.0, kExact);
    EXPECT_NEAR(brake.PositionAt(0.05), 287.5, kExact);
    EXPECT_FALSE(Trajectory::Brake(5.0, Direction::kNegative, 0.0, 1.0, RampType::kLinear).Moves());

    const Trajectory run = Trajectory::Run(0.0, Direction::kNegative, 500.0, 10000.0, RampType::kLinear);
    EXPECT_TRUE(std::isinf(run.Duration()));
    EXPECT_NEAR(run.PositionAt(0.05), -12.5, kExact);
    EXPECT_NEAR(run.PositionAt(10.0), -12.5 - 500.0 * 9.95, 1e-6);
    EXPECT_NEAR(run.VelocityAt(1000.0), -500.0, kExact);
}

TEST(ServoTrajectory, TimeToReachInvertsThePosition) {
    const Trajectory t = Trajectory::PointToPoint(0.0, 1000.0, kFull, RampType::kLinear);
    EXPECT_NEAR(*t.TimeToReach(12.5), 0.05, kExact);
    EXPECT_NEAR(*t.TimeToReach(550.0), 0.6, kExact);
    EXPECT_NEAR(*t.TimeToReach(999.5), 1.09, kExact);
    EXPECT_NEAR(*t.TimeToReach(1000.0), 1.1, kExact);
    EXPECT_EQ(*t.TimeToReach(-3.0), 0.0);  // behind the start: already there
    EXPECT_FALSE(t.TimeToReach(1000.5).has_value());

    const Trajectory s = Trajectory::PointToPoint(0.0, 1000.0, kFull, RampType::kSCurve);
    EXPECT_NEAR(*s.TimeToReach(100.0 / 12.0), 0.05, kExact);

    const Trajectory run = Trajectory::Run(0.0, Direction::kNegative, 500.0, 10000.0, RampType::kLinear);
    EXPECT_NEAR(*run.TimeToReach(-20.0), 0.065, kExact);
    EXPECT_EQ(*run.TimeToReach(1.0), 0.0);  // behind a negative run

    EXPECT_EQ(*Trajectory::Hold(3.0).TimeToReach(3.0), 0.0);
    EXPECT_FALSE(Trajectory::Hold(3.0).TimeToReach(4.0).has_value());
}

TEST(ServoTrajectory, ZeroDistanceIsAHold) {
    const Trajectory t = Trajectory::PointToPoint(7.0, 7.0, kFull, RampType::kSCurve);
    EXPECT_FALSE(t.Moves());
    EXPECT_EQ(t.PositionAt(1.0), 7.0);
    EXPECT_EQ(t.Duration(), 0.0);
}

TEST(ServoTrajectory, DynamicsValidity) {
    EXPECT_TRUE(IsValid(kFull));
    EXPECT_FALSE(IsValid(Dynamics{0.0, 1.0, 1.0}));
    EXPECT_FALSE(IsValid(Dynamics{1.0, -1.0, 1.0}));
    EXPECT_FALSE(IsValid(Dynamics{1.0, 1.0, std::nan("")}));
    EXPECT_FALSE(IsValid(Dynamics{INFINITY, 1.0, 1.0}));
}

}  // namespace
}  // namespace pac::sim
