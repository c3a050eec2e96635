// The simulated servo axis (sim servo_axis.hpp, docs/sim_axis.md), driven call by call on simulated
// time: profiles at given times, per-mille dynamics, call-frequency independence, refusals, software limits
// and G29, limit switches, following error, tolerance window timing, homing modes 0/1/2, G26, enable modes,
// "displaced during OFF", configuration checks. Expected values are worked out in the comments.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "pac/sim/servo_axis.hpp"

namespace pac::sim {
namespace {

using std::chrono::nanoseconds;

constexpr double kNear = 1e-6;

nanoseconds Ms(double ms) { return nanoseconds(std::llround(ms * 1e6)); }

ServoAxisConfig ReferencedConfig() {
    ServoAxisConfig c;
    c.referenced = true;
    return c;
}

// Defaults: 1000 units/s, 10000 units/s^2 both ways: ramps of 0.1 s / 50 units; a 1000-unit move takes 1.1 s.
const Dynamics kFull = ServoAxisConfig{}.FullDynamics();

// ---- motion -------------------------------------------------------------------------------------------

TEST(ServoAxisMotion, AbsoluteMoveFollowsTheTrapezoid) {
    ServoAxis axis(ReferencedConfig());
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    EXPECT_TRUE(axis.Moving());
    EXPECT_TRUE(axis.JobActive());
    EXPECT_EQ(axis.Status(), AxisStatus::kMoving);
    axis.Update(Ms(50));
    EXPECT_NEAR(axis.Position(), 12.5, kNear);
    EXPECT_NEAR(axis.ActualSpeed(), 500.0, kNear);
    EXPECT_EQ(axis.Phase(), MotionPhase::kAccelerating);
    axis.Update(Ms(600));
    EXPECT_NEAR(axis.Position(), 550.0, kNear);
    EXPECT_EQ(axis.Phase(), MotionPhase::kConstantSpeed);
    axis.Update(Ms(1050));
    EXPECT_NEAR(axis.Position(), 987.5, kNear);
    EXPECT_EQ(axis.Phase(), MotionPhase::kDecelerating);
    axis.Update(Ms(1099));
    EXPECT_TRUE(axis.Moving());
    axis.Update(Ms(1100));
    EXPECT_EQ(axis.Position(), 1000.0);
    EXPECT_FALSE(axis.Moving());
    EXPECT_FALSE(axis.JobActive());
    EXPECT_TRUE(axis.InTolerance());
    EXPECT_EQ(axis.Status(), AxisStatus::kInPosition);
    EXPECT_EQ(axis.Target(), 1000.0);
    EXPECT_EQ(axis.ActualSpeed(), 0.0);
}

TEST(ServoAxisMotion, PerMilleScalesSpeedAndAcceleration) {
    const ServoAxisConfig config = ReferencedConfig();
    // 2.7.5 / 2.7.6: 500 per mille of 1000 units/s, 2000 per mille of 10000 units/s^2.
    const auto half = ScaledDynamics(config, 500, 2000);
    ASSERT_TRUE(half.has_value());
    EXPECT_EQ(half->speed, 500.0);
    EXPECT_EQ(half->acceleration, 20000.0);
    EXPECT_EQ(half->deceleration, 20000.0);
    EXPECT_FALSE(ScaledDynamics(config, 0, 1000).has_value());
    EXPECT_FALSE(ScaledDynamics(config, 1001, 1000).has_value());
    EXPECT_FALSE(ScaledDynamics(config, 1000, 0).has_value());
    EXPECT_FALSE(ScaledDynamics(config, 1000, 65536).has_value());
    EXPECT_EQ(ScaledDynamics(config, 1, 65535)->acceleration, 655350.0);

    ServoAxis axis(config);
    // Ramps of 0.025 s / 6.25 units, cruise 987.5 units at 500 = 1.975 s: 2.025 s in all.
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, *half), axis_error::kNone);
    axis.Update(Ms(1000));
    EXPECT_NEAR(axis.Position(), 6.25 + 500.0 * 0.975, kNear);
    axis.Update(Ms(2024));
    EXPECT_TRUE(axis.Moving());
    axis.Update(Ms(2025));
    EXPECT_FALSE(axis.Moving());
    EXPECT_EQ(axis.Position(), 1000.0);
}

TEST(ServoAxisMotion, SCurveMove) {
    ServoAxisConfig config = ReferencedConfig();
    config.rampType = RampType::kSCurve;
    ServoAxis axis(config);
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    axis.Update(Ms(25));  // x = 1/4 of the ramp: 100 * 2x^3/3, speed 1000 * 2x^2
    EXPECT_NEAR(axis.Position(), 100.0 * 2.0 / 3.0 / 64.0, kNear);
    EXPECT_NEAR(axis.Velocity(), 125.0, kNear);
    axis.Update(Ms(50));
    EXPECT_NEAR(axis.Position(), 100.0 / 12.0, kNear);
    axis.Update(Ms(100));
    EXPECT_NEAR(axis.Position(), 50.0, kNear);  // as the linear ramp
    axis.Update(Ms(1100));
    EXPECT_EQ(axis.Position(), 1000.0);
    EXPECT_EQ(axis.Status(), AxisStatus::kInPosition);
}

TEST(ServoAxisMotion, ShortMoveNeverReachesTheSetSpeed) {
    for (const RampType ramp : {RampType::kLinear, RampType::kSCurve}) {
        ServoAxisConfig config = ReferencedConfig();
        config.rampType = ramp;
        ServoAxis axis(config);
        ASSERT_EQ(axis.MoveRelative(Ms(0), 40.0, kFull), axis_error::kNone);
        // Peak sqrt(40 * 10000) = 632.46 units/s after 63.25 ms, at the target after 126.49 ms.
        double fastest = 0.0;
        for (int tenth = 1; tenth <= 1264; ++tenth) {
            axis.Update(Ms(tenth / 10.0));
            fastest = std::fmax(fastest, axis.ActualSpeed());
        }
        EXPECT_TRUE(axis.Moving());
        EXPECT_NEAR(fastest, std::sqrt(400000.0), 1.0) << static_cast<int>(ramp);  // sampled every 0.1 ms
        EXPECT_LT(fastest, std::sqrt(400000.0) + 1e-9);
        axis.Update(Ms(127));
        EXPECT_FALSE(axis.Moving());
        EXPECT_EQ(axis.Position(), 40.0);
    }
}

TEST(ServoAxisMotion, RelativeMoveAndTraverseRangeEnds) {
    ServoAxis axis(ReferencedConfig());
    axis.Place(Ms(0), 300.0);
    ASSERT_EQ(axis.MoveRelative(Ms(0), -100.0, kFull), axis_error::kNone);
    axis.Update(Ms(1000));
    EXPECT_EQ(axis.Position(), 200.0);
    ASSERT_EQ(axis.MoveToMinRange(Ms(1000), kFull), axis_error::kNone);
    axis.Update(Ms(2000));
    EXPECT_EQ(axis.Position(), 0.0);
    ASSERT_EQ(axis.MoveToMaxRange(Ms(2000), kFull), axis_error::kNone);
    EXPECT_EQ(axis.Target(), 10000.0);
    axis.Update(Ms(2000 + 10100));  // 0.1 + 9.9 + 0.1 s
    EXPECT_EQ(axis.Position(), 10000.0);
}

TEST(ServoAxisMotion, JogNeedsNeitherReferenceNorRange) {
    ServoAxis axis;  // not referenced
    EXPECT_EQ(axis.MoveAbsolute(Ms(0), 10.0, kFull), axis_error::kNoReferencePoint);
    // Down to -40: outside the range 0..10000, short of the limit switch at -50.
    ASSERT_EQ(axis.Jog(Ms(0), Direction::kNegative, 40.0, kFull), axis_error::kNone);
    axis.Update(Ms(500));
    EXPECT_EQ(axis.Position(), -40.0);
    EXPECT_EQ(axis.AxisError(), 0);
    EXPECT_EQ(axis.Jog(Ms(500), Direction::kPositive, -1.0, kFull), axis_error::kValueOutsideRange);
}

TEST(ServoAxisMotion, InterruptBrakesToAStandstillAndHalts) {
    ServoAxis axis(ReferencedConfig());
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    axis.Interrupt(Ms(300));  // at 250, 1000 units/s: 0.1 s and 50 units to stand
    EXPECT_TRUE(axis.Moving());
    EXPECT_FALSE(axis.Interrupted());
    axis.Update(Ms(350));
    EXPECT_NEAR(axis.Position(), 287.5, kNear);
    axis.Update(Ms(400));
    EXPECT_FALSE(axis.Moving());
    EXPECT_NEAR(axis.Position(), 300.0, kNear);
    EXPECT_TRUE(axis.Interrupted());
    EXPECT_FALSE(axis.JobActive());
    EXPECT_EQ(axis.Status(), AxisStatus::kStopped);
    EXPECT_NEAR(axis.Target(), 300.0, kNear);
    // The next job clears the HALT state.
    ASSERT_EQ(axis.MoveAbsolute(Ms(400), 400.0, kFull), axis_error::kNone);
    EXPECT_FALSE(axis.Interrupted());
}

TEST(ServoAxisMotion, InterruptOnTheFinalRampFinishesAtTheTarget) {
    ServoAxis axis(ReferencedConfig());
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    axis.Interrupt(Ms(1050));
    axis.Update(Ms(1100));
    EXPECT_EQ(axis.Position(), 1000.0);
    EXPECT_FALSE(axis.Interrupted());
    EXPECT_EQ(axis.Status(), AxisStatus::kInPosition);
}

TEST(ServoAxisMotion, EmergencyStopHaltsAtOnce) {
    ServoAxis axis(ReferencedConfig());
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    axis.EmergencyStop(Ms(300));
    EXPECT_FALSE(axis.Moving());
    EXPECT_NEAR(axis.Position(), 250.0, kNear);
    EXPECT_EQ(axis.Velocity(), 0.0);
    EXPECT_EQ(axis.Status(), AxisStatus::kStopped);
    axis.Update(Ms(1000));
    EXPECT_NEAR(axis.Position(), 250.0, kNear);
}

TEST(ServoAxisMotion, TimeNeverRunsBackwards) {
    ServoAxis axis(ReferencedConfig());
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    axis.Update(Ms(600));
    axis.Update(Ms(100));
    EXPECT_EQ(axis.Now(), Ms(600));
    EXPECT_NEAR(axis.Position(), 550.0, kNear);
}

TEST(ServoAxisMotion, NewConfigLeavesTheRunningProfileAlone) {
    ServoAxis axis(ReferencedConfig());
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    ServoAxisConfig slower = axis.Config();
    slower.traverseSpeed = 100.0;
    axis.SetConfig(Ms(300), slower);
    axis.Update(Ms(1100));
    EXPECT_EQ(axis.Position(), 1000.0);
    EXPECT_EQ(axis.Config().FullDynamics().speed, 100.0);
}

TEST(ServoAxisMotion, AbsurdlySlowMoveIsNeverDueEarly) {
    // Its end lies beyond the range of nanoseconds: it must not come due (or wrap round to now).
    ServoAxis axis(ReferencedConfig());
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, Dynamics{1e-12, 1e-12, 1e-12}), axis_error::kNone);
    axis.Update(Ms(1000));
    EXPECT_TRUE(axis.Moving());
    EXPECT_LT(axis.Position(), 1e-6);
}

// ---- call-frequency independence ----------------------------------------------------------------------

struct Snapshot {
    double position, commanded, velocity;
    AxisStatus status;
    std::uint16_t error;
    bool referenced, inTolerance, jobActive, positiveLimit;
    bool operator==(const Snapshot& o) const {
        return position == o.position && commanded == o.commanded && velocity == o.velocity && status == o.status &&
               error == o.error && referenced == o.referenced && inTolerance == o.inTolerance &&
               jobActive == o.jobActive && positiveLimit == o.positiveLimit;
    }
};

// A scenario with every kind of event (homing mode 1 with S ramps, a per-mille move, an interrupt, a limit
// switch, a tolerance delay), updated every `stepMs`, seen every 7 ms. Jobs fall on multiples of 7 ms.
std::vector<Snapshot> RunScenario(int stepMs) {
    ServoAxisConfig config;
    config.rampType = RampType::kSCurve;
    config.homingMode = HomingMode::kSwitchAndIndex;
    config.positiveLimitSwitch = 1500.0;
    config.toleranceWindow = 0.05;
    config.toleranceDelay = Ms(20);
    ServoAxis axis(config);
    const auto moveDynamics = *ScaledDynamics(config, 700, 1500);
    std::map<std::int64_t, std::function<void(nanoseconds)>> jobs = {
        {0, [&](nanoseconds t) { EXPECT_EQ(axis.Home(t), axis_error::kNone); }},
        {700, [&](nanoseconds t) { EXPECT_EQ(axis.MoveAbsolute(t, 1000.0, moveDynamics), axis_error::kNone); }},
        {1400, [&](nanoseconds t) { axis.Interrupt(t); }},
        {2100, [&](nanoseconds t) { EXPECT_EQ(axis.Jog(t, Direction::kPositive, 2000.0, kFull), 0); }},
        {4900, [&](nanoseconds t) { EXPECT_TRUE(axis.ResetAxisError(t)); }},
        {5600, [&](nanoseconds t) { EXPECT_EQ(axis.MoveAbsolute(t, 500.0, kFull), axis_error::kNone); }},
    };
    std::vector<Snapshot> seen;
    for (std::int64_t ms = 0; ms <= 7000; ms += stepMs) {
        const nanoseconds t = Ms(static_cast<double>(ms));
        axis.Update(t);
        if (auto job = jobs.find(ms); job != jobs.end()) job->second(t);
        if (ms % 7 == 0) {
            seen.push_back(Snapshot{axis.Position(), axis.CommandedPosition(), axis.Velocity(), axis.Status(),
                                    axis.AxisError(), axis.Referenced(), axis.InTolerance(), axis.JobActive(),
                                    axis.PositiveLimitSwitch()});
        }
    }
    return seen;
}

TEST(ServoAxisDeterminism, SameResultsWithUpdatesEvery1And7Ms) {
    const auto every1 = RunScenario(1);
    const auto every7 = RunScenario(7);
    ASSERT_EQ(every1.size(), every7.size());
    for (std::size_t k = 0; k < every1.size(); ++k) {
        EXPECT_TRUE(every1[k] == every7[k]) << "at " << 7 * k << " ms: position " << every1[k].position << " vs "
                                            << every7[k].position;
    }
    // The scenario did what it is there for.
    bool referenced = false, limitError = false, moved = false;
    for (const auto& s : every7) {
        referenced = referenced || s.referenced;
        limitError = limitError || s.error == axis_error::kLimitSwitchActuated;
        moved = moved || s.velocity > 600.0;
    }
    EXPECT_TRUE(referenced);
    EXPECT_TRUE(limitError);
    EXPECT_TRUE(moved);
    EXPECT_NEAR(every7.back().position, 500.0, kNear);
    EXPECT_EQ(every7.back().status, AxisStatus::kInPosition);
}

// ---- refusals -----------------------------------------------------------------------------------------

TEST(ServoAxisRefusals, EachReasonWithItsNumber) {
    ServoAxis axis(ReferencedConfig());
    EXPECT_EQ(axis.MoveAbsolute(Ms(0), 10000.5, kFull), axis_error::kPositionOutsideRange);
    EXPECT_EQ(axis.MoveRelative(Ms(0), -1.0, kFull), axis_error::kPositionOutsideRange);
    EXPECT_EQ(axis.MoveAbsolute(Ms(0), std::nan(""), kFull), axis_error::kValueOutsideRange);
    EXPECT_EQ(axis.MoveAbsolute(Ms(0), 10.0, Dynamics{0.0, 1.0, 1.0}), axis_error::kValueOutsideRange);
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    EXPECT_EQ(axis.MoveAbsolute(Ms(10), 5.0, kFull), axis_error::kAxisStillMoves);
    EXPECT_EQ(axis.Home(Ms(10)), axis_error::kAxisStillMoves);
    EXPECT_EQ(axis.SetPositionReferenced(Ms(10), 0.0), axis_error::kAxisStillMoves);
    EXPECT_EQ(axis.ShiftPosition(Ms(10), 0.0), axis_error::kAxisStillMoves);
    EXPECT_EQ(axis.DeleteShift(Ms(10)), axis_error::kAxisStillMoves);
    EXPECT_EQ(axis.Target(), 1000.0);  // the refused jobs changed nothing
    axis.Update(Ms(1100));
    EXPECT_EQ(axis.Position(), 1000.0);

    axis.SetAxisOn(Ms(1100), false);
    EXPECT_EQ(axis.MoveAbsolute(Ms(1100), 5.0, kFull), axis_error::kAxisNotSwitchedOn);
    EXPECT_EQ(axis.Jog(Ms(1100), Direction::kPositive, 5.0, kFull), axis_error::kAxisNotSwitchedOn);
    EXPECT_EQ(axis.Home(Ms(1100)), axis_error::kAxisNotSwitchedOn);
    axis.RaiseAxisError(Ms(1100), 4711);
    EXPECT_EQ(axis.MoveAbsolute(Ms(1100), 5.0, kFull), axis_error::kAxisNotReady);  // 46 before 55
    EXPECT_TRUE(axis.ResetAxisError(Ms(1100)));
    axis.SetAxisOn(Ms(1100), true);
    EXPECT_EQ(axis.MoveAbsolute(Ms(1100), 5.0, kFull), axis_error::kNone);
}

TEST(ServoAxisRefusals, MalfunctionHookForTheCmdStatus) {
    ServoAxis axis(ReferencedConfig());
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    axis.RaiseAxisError(Ms(300), 4711);
    EXPECT_EQ(axis.Status(), AxisStatus::kMalfunction);
    EXPECT_EQ(axis.AxisError(), 4711);
    EXPECT_FALSE(axis.Moving());
    EXPECT_TRUE(axis.ResetAxisError(Ms(400)));
    EXPECT_EQ(axis.Status(), AxisStatus::kStopped);  // the job was cut short
    EXPECT_THROW(axis.RaiseAxisError(Ms(400), 0), std::invalid_argument);
}

// ---- software limits and coordinates ------------------------------------------------------------------

TEST(ServoAxisCoordinates, G29ShiftsPositionAndSoftwareLimits) {
    ServoAxis axis(ReferencedConfig());
    ASSERT_EQ(axis.ShiftPosition(Ms(0), 100.0), axis_error::kNone);
    EXPECT_NEAR(axis.Position(), 100.0, kNear);
    EXPECT_NEAR(axis.MinRange(), 100.0, kNear);
    EXPECT_NEAR(axis.MaxRange(), 10100.0, kNear);
    EXPECT_EQ(axis.MoveAbsolute(Ms(0), 50.0, kFull), axis_error::kPositionOutsideRange);
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1100.0, kFull), axis_error::kNone);
    axis.Update(Ms(1100));
    EXPECT_NEAR(axis.Position(), 1100.0, kNear);
    // A second G29 adds to the first; deleting removes both.
    ASSERT_EQ(axis.ShiftPosition(Ms(1100), 1250.0), axis_error::kNone);
    EXPECT_NEAR(axis.Shift(), 250.0, kNear);
    EXPECT_NEAR(axis.MaxRange(), 10250.0, kNear);
    ASSERT_EQ(axis.DeleteShift(Ms(1100)), axis_error::kNone);
    EXPECT_NEAR(axis.Position(), 1000.0, kNear);
    EXPECT_EQ(axis.MinRange(), 0.0);
    EXPECT_EQ(axis.MaxRange(), 10000.0);
    EXPECT_TRUE(axis.Referenced());
}

TEST(ServoAxisCoordinates, G29KeepsTheReferenceState) {
    ServoAxis axis;
    ASSERT_EQ(axis.ShiftPosition(Ms(0), 5.0), axis_error::kNone);
    EXPECT_FALSE(axis.Referenced());
}

TEST(ServoAxisCoordinates, G26SetsPositionAndReferenceButNotTheLimits) {
    ServoAxisConfig config;
    config.positiveLimitSwitch = 1200.0;
    ServoAxis axis(config);
    ASSERT_EQ(axis.SetPositionReferenced(Ms(0), 500.0), axis_error::kNone);
    EXPECT_TRUE(axis.Referenced());
    EXPECT_NEAR(axis.Position(), 500.0, kNear);
    EXPECT_EQ(axis.MinRange(), 0.0);
    EXPECT_EQ(axis.MaxRange(), 10000.0);
    // The switch is a machine part: 1200 from the start point, i.e. at 1700 now.
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 2000.0, kFull), axis_error::kNone);
    axis.Update(Ms(3000));
    EXPECT_EQ(axis.AxisError(), axis_error::kLimitSwitchActuated);
    EXPECT_NEAR(axis.Position(), 1700.0, kNear);
    // G26 works while switched off too.
    axis.SetAxisOn(Ms(3000), false);
    EXPECT_EQ(axis.SetPositionReferenced(Ms(3000), 0.0), axis_error::kNone);
    EXPECT_NEAR(axis.Position(), 0.0, kNear);
}

// ---- limit switches -----------------------------------------------------------------------------------

TEST(ServoAxisLimits, ReachingALimitSwitchStopsAtOnceWithAxisError64) {
    ServoAxisConfig config = ReferencedConfig();
    config.positiveLimitSwitch = 1200.0;
    ServoAxis axis(config);
    ASSERT_EQ(axis.Jog(Ms(0), Direction::kPositive, 2000.0, kFull), axis_error::kNone);
    axis.Update(Ms(1249));  // 50 + 1000 * 1.149
    EXPECT_TRUE(axis.Moving());
    EXPECT_NEAR(axis.Position(), 1199.0, kNear);
    EXPECT_FALSE(axis.PositiveLimitSwitch());
    axis.Update(Ms(1260));  // reached at 1250 ms: 50 + 1000 * 1.15
    EXPECT_FALSE(axis.Moving());
    EXPECT_EQ(axis.Position(), 1200.0);
    EXPECT_EQ(axis.Velocity(), 0.0);
    EXPECT_TRUE(axis.PositiveLimitSwitch());
    EXPECT_FALSE(axis.NegativeLimitSwitch());
    EXPECT_EQ(axis.AxisError(), axis_error::kLimitSwitchActuated);
    EXPECT_TRUE(axis.Fault());
    EXPECT_FALSE(axis.JobActive());
    EXPECT_EQ(axis.Status(), AxisStatus::kMalfunction);

    EXPECT_EQ(axis.MoveAbsolute(Ms(1300), 100.0, kFull), axis_error::kAxisNotReady);
    ASSERT_TRUE(axis.ResetAxisError(Ms(1300)));
    // Further into the switch: refused; away from it: allowed, and the switch releases.
    EXPECT_EQ(axis.Jog(Ms(1300), Direction::kPositive, 10.0, kFull), axis_error::kLimitSwitchActuated);
    EXPECT_EQ(axis.AxisError(), 0);
    ASSERT_EQ(axis.MoveAbsolute(Ms(1300), 1000.0, kFull), axis_error::kNone);
    axis.Update(Ms(2000));
    EXPECT_FALSE(axis.PositiveLimitSwitch());
    EXPECT_EQ(axis.Position(), 1000.0);
}

TEST(ServoAxisLimits, NegativeSwitchStopsAnUnreferencedJog) {
    ServoAxis axis;  // negative limit switch at -50
    ASSERT_EQ(axis.Jog(Ms(0), Direction::kNegative, 500.0, kFull), axis_error::kNone);
    axis.Update(Ms(1000));
    EXPECT_EQ(axis.Position(), -50.0);
    EXPECT_TRUE(axis.NegativeLimitSwitch());
    EXPECT_EQ(axis.AxisError(), axis_error::kLimitSwitchActuated);
}

TEST(ServoAxisLimits, MonitoringOffPerJobPassesTheSwitch) {
    ServoAxisConfig config = ReferencedConfig();
    config.positiveLimitSwitch = 1200.0;
    ServoAxis axis(config);
    ASSERT_EQ(axis.Jog(Ms(0), Direction::kPositive, 2000.0, kFull, JobOptions{false}), axis_error::kNone);
    axis.Update(Ms(2100));
    EXPECT_EQ(axis.Position(), 2000.0);
    EXPECT_EQ(axis.AxisError(), 0);
    EXPECT_TRUE(axis.PositiveLimitSwitch());  // reported all the same
    // The next job monitors again (the flag is taken over per Start, 2.7.3.17).
    EXPECT_EQ(axis.Jog(Ms(2100), Direction::kPositive, 1.0, kFull), axis_error::kLimitSwitchActuated);
    EXPECT_EQ(axis.Jog(Ms(2100), Direction::kPositive, 1.0, kFull, JobOptions{false}), axis_error::kNone);
}

// The axis keeps the next event it found while nothing changes it (docs/sim_axis.md, "The model"): a switch
// placed in the path of a move that has already run for many cycles must still stop it.
TEST(ServoAxisLimits, ASwitchPlacedAheadDuringAMoveStopsIt) {
    ServoAxis axis(ReferencedConfig());
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    for (int ms = 1; ms <= 500; ++ms) axis.Update(Ms(ms));  // at 450 units, no switch on the way
    ServoAxisConfig withSwitch = axis.Config();
    withSwitch.positiveLimitSwitch = 700.0;
    axis.SetConfig(Ms(500), withSwitch);
    for (int ms = 501; ms <= 1200; ++ms) axis.Update(Ms(ms));
    EXPECT_EQ(axis.Position(), 700.0);  // reached at 750 ms: 50 + 1000 * 0.7
    EXPECT_FALSE(axis.Moving());
    EXPECT_EQ(axis.AxisError(), axis_error::kLimitSwitchActuated);
}

// ---- following error ----------------------------------------------------------------------------------

TEST(ServoAxisFollowingError, BlockedAxisFaultsWhenTheLagReachesTheLimit) {
    ServoAxis axis(ReferencedConfig());  // limit 1.0
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    axis.SetBlocked(Ms(300), true);  // at 250, the command goes on at 1000 units/s
    axis.Update(Ms(300.9));
    EXPECT_EQ(axis.AxisError(), 0);
    EXPECT_NEAR(axis.Position(), 250.0, kNear);
    EXPECT_NEAR(axis.FollowingError(), 0.9, kNear);
    EXPECT_EQ(axis.ActualSpeed(), 0.0);
    axis.Update(Ms(350));  // the command reached 251 at 301 ms
    EXPECT_EQ(axis.AxisError(), axis_error::kFollowingError);
    EXPECT_FALSE(axis.Moving());
    EXPECT_NEAR(axis.Position(), 250.0, kNear);
    EXPECT_NEAR(axis.CommandedPosition(), 250.0, kNear);  // the actual position taken over
    EXPECT_EQ(axis.FollowingError(), 0.0);
    EXPECT_EQ(axis.Status(), AxisStatus::kMalfunction);
    ASSERT_TRUE(axis.ResetAxisError(Ms(350)));
    // Still blocked: the next move faults after 1 unit (a t^2/2 = 1: 14.14 ms).
    ASSERT_EQ(axis.MoveRelative(Ms(350), 100.0, kFull), axis_error::kNone);
    axis.Update(Ms(364));
    EXPECT_EQ(axis.AxisError(), 0);
    axis.Update(Ms(365));
    EXPECT_EQ(axis.AxisError(), axis_error::kFollowingError);
    axis.SetBlocked(Ms(400), false);
    ASSERT_TRUE(axis.ResetAxisError(Ms(400)));
    ASSERT_EQ(axis.MoveRelative(Ms(400), 100.0, kFull), axis_error::kNone);
    axis.Update(Ms(1000));
    EXPECT_NEAR(axis.Position(), 350.0, kNear);
    EXPECT_EQ(axis.AxisError(), 0);
}

TEST(ServoAxisFollowingError, DisturbanceBelowTheLimitKeepsTheAxisOutOfPosition) {
    ServoAxisConfig config = ReferencedConfig();
    config.toleranceWindow = 0.1;
    ServoAxis axis(config);
    axis.SetDisturbance(Ms(0), 0.5);
    EXPECT_EQ(axis.AxisError(), 0);
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 100.0, kFull), axis_error::kNone);  // 0.2 s, no cruise
    axis.Update(Ms(200));
    EXPECT_FALSE(axis.Moving());
    EXPECT_NEAR(axis.Position(), 100.5, kNear);
    EXPECT_NEAR(axis.FollowingError(), -0.5, kNear);
    EXPECT_FALSE(axis.InTolerance());
    EXPECT_TRUE(axis.JobActive());  // not yet in position
    EXPECT_EQ(axis.Status(), AxisStatus::kMoving);
    axis.SetDisturbance(Ms(300), 0.05);
    EXPECT_TRUE(axis.InTolerance());
    EXPECT_FALSE(axis.JobActive());
    EXPECT_EQ(axis.Status(), AxisStatus::kInPosition);
}

TEST(ServoAxisFollowingError, DisturbanceAboveTheLimitFaultsUntilItIsGone) {
    ServoAxis axis(ReferencedConfig());
    axis.SetDisturbance(Ms(0), -1.5);
    EXPECT_EQ(axis.AxisError(), axis_error::kFollowingError);
    EXPECT_FALSE(axis.ResetAxisError(Ms(10)));
    EXPECT_EQ(axis.AxisError(), axis_error::kFollowingError);
    axis.SetDisturbance(Ms(20), 0.0);
    EXPECT_TRUE(axis.ResetAxisError(Ms(20)));
    EXPECT_EQ(axis.AxisError(), 0);
}

TEST(ServoAxisFollowingError, NotMonitoredWithoutCurrent) {
    ServoAxisConfig config = ReferencedConfig();
    config.enableMode = EnableMode::kIdle;
    ServoAxis axis(config);
    axis.SetAxisOn(Ms(0), false);
    axis.SetDisturbance(Ms(0), 3.0);
    EXPECT_EQ(axis.AxisError(), 0);
    axis.SetAxisOn(Ms(10), true);  // the loop closes: the lag is checked
    EXPECT_EQ(axis.AxisError(), axis_error::kFollowingError);
}

// ---- tolerance window ---------------------------------------------------------------------------------

TEST(ServoAxisTolerance, InPositionAfterTheDelayInsideTheWindow) {
    ServoAxisConfig config = ReferencedConfig();
    config.toleranceWindow = 0.5;
    config.toleranceDelay = Ms(20);
    ServoAxis axis(config);
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    // Inside from 999.5 on: 0.5 = d t^2/2 before the end, t = 10 ms: at 1090 ms; in position at 1110 ms.
    axis.Update(Ms(1100));
    EXPECT_FALSE(axis.Moving());
    EXPECT_FALSE(axis.InTolerance());
    EXPECT_TRUE(axis.JobActive());
    EXPECT_EQ(axis.Status(), AxisStatus::kMoving);
    axis.Update(Ms(1110) - nanoseconds(1));
    EXPECT_FALSE(axis.InTolerance());
    axis.Update(Ms(1110));
    EXPECT_TRUE(axis.InTolerance());
    EXPECT_FALSE(axis.JobActive());
    EXPECT_EQ(axis.Status(), AxisStatus::kInPosition);
    // Leaving the window restarts the delay; a change that stays inside does not.
    axis.SetDisturbance(Ms(1200), 0.6);
    EXPECT_FALSE(axis.InTolerance());
    axis.SetDisturbance(Ms(1300), 0.2);
    axis.Update(Ms(1319));
    EXPECT_FALSE(axis.InTolerance());
    axis.Update(Ms(1320));
    EXPECT_TRUE(axis.InTolerance());
    axis.SetDisturbance(Ms(1400), -0.3);
    EXPECT_TRUE(axis.InTolerance());
}

TEST(ServoAxisTolerance, WithoutDelayTheJobEndsWithTheProfile) {
    ServoAxis axis(ReferencedConfig());
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 100.0, kFull), axis_error::kNone);
    axis.Update(Ms(199));
    EXPECT_TRUE(axis.JobActive());
    axis.Update(Ms(200));
    EXPECT_FALSE(axis.JobActive());
    EXPECT_TRUE(axis.InTolerance());
}

// ---- homing -------------------------------------------------------------------------------------------

// Defaults: cam from -20 downwards, search negative at 500, creep at 100, 10000 units/s^2, home point = 0.
TEST(ServoAxisHoming, Mode0SearchesTheCamThenCreepsOffIt) {
    ServoAxis axis;
    ASSERT_EQ(axis.Home(Ms(0)), axis_error::kNone);
    EXPECT_TRUE(axis.HomingActive());
    EXPECT_FALSE(axis.Referenced());
    axis.Update(Ms(60));  // 12.5 after the 50 ms ramp, then 500 units/s: -17.5
    EXPECT_NEAR(axis.Position(), -17.5, kNear);
    EXPECT_NEAR(axis.Velocity(), -500.0, kNear);
    EXPECT_FALSE(axis.ReferenceSwitch());
    // Cam at 65 ms; braking 50 ms / 12.5 units: standing at -32.5 at 115 ms, then creeping back.
    axis.Update(Ms(115));
    EXPECT_NEAR(axis.Position(), -32.5, kNear);
    EXPECT_TRUE(axis.ReferenceSwitch());
    axis.Update(Ms(200));  // 0.5 after the 10 ms ramp, then 100 units/s: -32.5 + 8
    EXPECT_NEAR(axis.Position(), -24.5, kNear);
    EXPECT_NEAR(axis.Velocity(), 100.0, kNear);
    EXPECT_FALSE(axis.Referenced());
    // Off the cam at -20 at 245 ms: that point becomes 0.
    axis.Update(Ms(245));
    EXPECT_TRUE(axis.Referenced());
    EXPECT_NEAR(axis.Position(), 0.0, kNear);
    EXPECT_TRUE(axis.HomingActive());
    axis.Update(Ms(255));  // braked from 100 in 10 ms / 0.5 units
    EXPECT_FALSE(axis.HomingActive());
    EXPECT_FALSE(axis.JobActive());
    EXPECT_NEAR(axis.Position(), 0.5, kNear);
    EXPECT_FALSE(axis.ReferenceSwitch());
    EXPECT_NEAR(axis.LastHomingCorrection(), 20.0, kNear);
    EXPECT_EQ(axis.Status(), AxisStatus::kInPosition);
}

TEST(ServoAxisHoming, Mode0StartingOnTheCamOnlyCreeps) {
    ServoAxisConfig config;
    config.startPosition = -30.0;
    ServoAxis axis(config);
    ASSERT_TRUE(axis.ReferenceSwitch());
    ASSERT_EQ(axis.Home(Ms(0)), axis_error::kNone);
    axis.Update(Ms(50));
    EXPECT_NEAR(axis.Velocity(), 100.0, kNear);  // creep speed at once, towards the edge
    axis.Update(Ms(104));
    EXPECT_FALSE(axis.Referenced());
    axis.Update(Ms(105));  // 0.5 + 100 * 0.095 = 10 units: at -20
    EXPECT_TRUE(axis.Referenced());
    axis.Update(Ms(200));
    EXPECT_NEAR(axis.Position(), 0.5, kNear);
    EXPECT_FALSE(axis.JobActive());
}

// Standing right on the cam's edge (where an aborted run can leave the axis), the creep's home point is
// where it stands: reached before the axis moves, it must still end the run, referenced there.
TEST(ServoAxisHoming, Mode0StartingOnTheCamEdgeEndsAtOnce) {
    ServoAxisConfig config;
    config.startPosition = config.referenceSwitch;
    ServoAxis axis(config);
    ASSERT_TRUE(axis.ReferenceSwitch());
    ASSERT_EQ(axis.Home(Ms(0)), axis_error::kNone);
    axis.Update(Ms(1));
    EXPECT_TRUE(axis.Referenced());
    EXPECT_FALSE(axis.HomingActive());
    EXPECT_FALSE(axis.JobActive());
    EXPECT_NEAR(axis.Position(), config.referencePosition, kNear);
    EXPECT_EQ(axis.Status(), AxisStatus::kInPosition);
}

TEST(ServoAxisHoming, Mode1LoadsAtTheFirstIndexPulseOffTheCam) {
    ServoAxisConfig config;
    config.homingMode = HomingMode::kSwitchAndIndex;
    config.indexPitch = 8.0;  // pulses at ..., -24, -16, -8, ...
    ServoAxis axis(config);
    ASSERT_EQ(axis.Home(Ms(0)), axis_error::kNone);
    axis.Update(Ms(250));  // off the cam at 245 ms, still no pulse
    EXPECT_FALSE(axis.Referenced());
    EXPECT_FALSE(axis.ReferenceSwitch());
    // From -32.5: 0.5 + 100 * (t - 0.01) = 16.5 at t = 170 ms after 115 ms: the pulse at -16 at 285 ms.
    axis.Update(Ms(284));
    EXPECT_FALSE(axis.Referenced());
    axis.Update(Ms(285));
    EXPECT_TRUE(axis.Referenced());
    EXPECT_NEAR(axis.Position(), 0.0, kNear);
    axis.Update(Ms(300));
    EXPECT_NEAR(axis.Position(), 0.5, kNear);
    EXPECT_NEAR(axis.LastHomingCorrection(), 16.0, kNear);
    EXPECT_FALSE(axis.HomingActive());
}

TEST(ServoAxisHoming, Mode2LoadsWhenAJogReachesTheSwitch) {
    ServoAxisConfig config;
    config.homingMode = HomingMode::kLoadOnSwitch;
    config.negativeLimitSwitch = -100.0;
    ServoAxis axis(config);
    ASSERT_EQ(axis.Home(Ms(0)), axis_error::kNone);
    EXPECT_FALSE(axis.JobActive());  // no movement: the job ends at once
    EXPECT_FALSE(axis.Moving());
    EXPECT_TRUE(axis.HomingArmed());
    EXPECT_FALSE(axis.Referenced());
    ASSERT_EQ(axis.Jog(Ms(0), Direction::kNegative, 50.0, kFull), axis_error::kNone);
    axis.Update(Ms(63));  // a t^2/2 = 20 at 63.25 ms
    EXPECT_FALSE(axis.Referenced());
    axis.Update(Ms(64));
    EXPECT_TRUE(axis.Referenced());
    EXPECT_FALSE(axis.HomingArmed());
    axis.Update(Ms(500));
    EXPECT_NEAR(axis.Position(), -30.0, kNear);  // stood at -50, the cam edge -20 is 0
}

TEST(ServoAxisHoming, Mode2LoadsWhenTheAxisIsPushedOntoTheSwitch) {
    ServoAxisConfig config;
    config.homingMode = HomingMode::kLoadOnSwitch;
    config.enableMode = EnableMode::kIdle;
    ServoAxis axis(config);
    ASSERT_EQ(axis.Home(Ms(0)), axis_error::kNone);
    axis.SetAxisOn(Ms(0), false);
    ASSERT_TRUE(axis.Displace(Ms(10), -25.0));
    EXPECT_TRUE(axis.Referenced());
    EXPECT_NEAR(axis.Position(), -5.0, kNear);
}

TEST(ServoAxisHoming, NoCamOnTheSearchSideEndsAtTheLimitSwitch) {
    ServoAxisConfig config;
    config.homingDirection = Direction::kPositive;  // the cam is on the negative side
    config.positiveLimitSwitch = 300.0;
    ServoAxis axis(config);
    ASSERT_EQ(axis.Home(Ms(0)), axis_error::kNone);
    axis.Update(Ms(624));
    EXPECT_TRUE(axis.HomingActive());
    axis.Update(Ms(625));  // 12.5 + 500 * 0.575
    EXPECT_EQ(axis.AxisError(), axis_error::kLimitSwitchActuated);
    EXPECT_EQ(axis.Position(), 300.0);
    EXPECT_FALSE(axis.HomingActive());
    EXPECT_FALSE(axis.Referenced());
}

TEST(ServoAxisHoming, RefusedIntoAnActuatedLimitSwitch) {
    ServoAxisConfig config;
    config.startPosition = -60.0;  // on the negative limit switch (-50)
    config.referenceSwitch = 100.0;
    config.referenceCamSide = Direction::kPositive;  // off the cam: the search goes negative first
    ServoAxis axis(config);
    EXPECT_EQ(axis.Home(Ms(0)), axis_error::kLimitSwitchActuated);
    EXPECT_FALSE(axis.Moving());
}

TEST(ServoAxisHoming, InterruptAbortsTheReferenceRun) {
    ServoAxis axis(ReferencedConfig());
    ASSERT_EQ(axis.Home(Ms(0)), axis_error::kNone);
    EXPECT_FALSE(axis.Referenced());
    axis.Interrupt(Ms(40));
    axis.Update(Ms(200));
    EXPECT_FALSE(axis.Moving());
    EXPECT_FALSE(axis.HomingActive());
    EXPECT_FALSE(axis.Referenced());
    EXPECT_EQ(axis.Status(), AxisStatus::kStopped);
}

// An interrupt in the very instant a profile begins finds no speed to brake from; the job must end all the
// same. From -19.5 the search enters the cam at 10 ms (0.5 units at 10000 units/s^2, 100 units/s) and
// brakes 10 ms / 0.5 units: standing at -20.5 at 20 ms, where the creep starts.
TEST(ServoAxisHoming, InterruptAsAProfileBeginsStillEndsTheRun) {
    for (const double interruptMs : {0.0, 20.0}) {
        ServoAxisConfig config;
        config.startPosition = -19.5;
        ServoAxis axis(config);
        ASSERT_EQ(axis.Home(Ms(0)), axis_error::kNone);
        axis.Interrupt(Ms(interruptMs));
        axis.Update(Ms(interruptMs + 1.0));
        EXPECT_FALSE(axis.HomingActive()) << interruptMs;
        EXPECT_FALSE(axis.JobActive()) << interruptMs;
        EXPECT_EQ(axis.Status(), AxisStatus::kStopped) << interruptMs;
    }
}

TEST(ServoAxisHoming, ReferenceRunDropsTheG29Shift) {
    ServoAxis axis;
    ASSERT_EQ(axis.ShiftPosition(Ms(0), 40.0), axis_error::kNone);
    ASSERT_EQ(axis.Home(Ms(0)), axis_error::kNone);
    axis.Update(Ms(300));
    EXPECT_TRUE(axis.Referenced());
    EXPECT_EQ(axis.Shift(), 0.0);
    EXPECT_EQ(axis.MinRange(), 0.0);
    EXPECT_NEAR(axis.LastHomingCorrection(), -20.0, kNear);  // the edge read 20 before (-20 + 40)
}

TEST(ServoAxisHoming, SpeedsComeFromTheParametersWithSCurves) {
    ServoAxisConfig config;
    config.rampType = RampType::kSCurve;
    config.referenceSpeed = 200.0;
    ServoAxis axis(config);
    ASSERT_EQ(axis.Home(Ms(0)), axis_error::kNone);
    axis.Update(Ms(50));
    EXPECT_NEAR(axis.Velocity(), -200.0, kNear);
    axis.Update(Ms(2000));
    EXPECT_TRUE(axis.Referenced());
    EXPECT_FALSE(axis.JobActive());
    EXPECT_NEAR(axis.Position(), 0.5, kNear);  // the creep brake: the same distance as linear
}

// ---- drive states -------------------------------------------------------------------------------------

TEST(ServoAxisDrive, HaltModeHoldsThePosition) {
    ServoAxis axis(ReferencedConfig());  // enable mode HALT
    axis.SetAxisOn(Ms(0), false);
    EXPECT_EQ(axis.Drive(), DriveState::kHalt);
    EXPECT_TRUE(IsPowered(axis.Drive()));
    EXPECT_FALSE(axis.Displace(Ms(0), 5.0));
    EXPECT_EQ(axis.MoveAbsolute(Ms(0), 10.0, kFull), axis_error::kAxisNotSwitchedOn);
    axis.SetAxisOn(Ms(10), true);
    EXPECT_EQ(axis.Drive(), DriveState::kEnabled);
    EXPECT_FALSE(axis.DisplacedDuringOff());
    EXPECT_EQ(axis.MoveAbsolute(Ms(10), 10.0, kFull), axis_error::kNone);
}

TEST(ServoAxisDrive, SwitchingOffWhileMovingBrakesThenIdles) {
    ServoAxisConfig config = ReferencedConfig();
    config.enableMode = EnableMode::kIdle;
    ServoAxis axis(config);
    ASSERT_EQ(axis.MoveAbsolute(Ms(0), 1000.0, kFull), axis_error::kNone);
    axis.SetAxisOn(Ms(300), false);
    axis.Update(Ms(350));
    EXPECT_TRUE(axis.Moving());
    EXPECT_EQ(axis.Drive(), DriveState::kEnabled);  // still braking under control
    axis.Update(Ms(400));
    EXPECT_FALSE(axis.Moving());
    EXPECT_EQ(axis.Drive(), DriveState::kIdle);
    EXPECT_FALSE(IsPowered(axis.Drive()));
    EXPECT_NEAR(axis.Position(), 300.0, kNear);
    EXPECT_TRUE(axis.Interrupted());
    EXPECT_EQ(axis.Status(), AxisStatus::kStopped);
}

TEST(ServoAxisDrive, SafeModeAndDisableDrive) {
    ServoAxisConfig config = ReferencedConfig();
    config.enableMode = EnableMode::kSafe;
    ServoAxis axis(config);
    axis.SetAxisOn(Ms(0), false);
    EXPECT_EQ(axis.Drive(), DriveState::kSafe);
    axis.SetAxisOn(Ms(0), true);
    // DISABLE DRIVE wins over Axis ON.
    axis.SetDriveDisabled(Ms(0), true);
    EXPECT_EQ(axis.Drive(), DriveState::kDisabled);
    EXPECT_TRUE(axis.AxisOn());
    EXPECT_EQ(axis.MoveAbsolute(Ms(0), 10.0, kFull), axis_error::kAxisNotSwitchedOn);
    axis.SetDriveDisabled(Ms(0), false);
    EXPECT_EQ(axis.Drive(), DriveState::kEnabled);
    EXPECT_EQ(axis.MoveAbsolute(Ms(0), 10.0, kFull), axis_error::kNone);
}

TEST(ServoAxisDrive, DisplacedDuringOffBeyondTheMaximum) {
    ServoAxisConfig config = ReferencedConfig();
    config.enableMode = EnableMode::kIdle;  // max displacement 1.0
    ServoAxis axis(config);
    axis.SetAxisOn(Ms(0), false);
    ASSERT_TRUE(axis.Displace(Ms(0), 0.5));
    axis.SetAxisOn(Ms(10), true);
    EXPECT_FALSE(axis.DisplacedDuringOff());
    EXPECT_NEAR(axis.Position(), 0.5, kNear);  // the position is taken over, not corrected

    axis.SetAxisOn(Ms(20), false);
    ASSERT_TRUE(axis.Displace(Ms(20), 0.8));
    ASSERT_TRUE(axis.Displace(Ms(30), 0.8));  // 1.6 from where it was switched off
    axis.SetAxisOn(Ms(40), true);
    EXPECT_TRUE(axis.DisplacedDuringOff());
    EXPECT_NEAR(axis.Position(), 2.1, kNear);
    EXPECT_EQ(axis.MoveAbsolute(Ms(40), 10.0, kFull), axis_error::kAxisDisplacedTooMuch);
    EXPECT_EQ(axis.Home(Ms(40)), axis_error::kAxisDisplacedTooMuch);
    EXPECT_EQ(axis.ResetDisplaced(Ms(40)), axis_error::kNone);
    EXPECT_FALSE(axis.DisplacedDuringOff());
    EXPECT_EQ(axis.MoveAbsolute(Ms(40), 10.0, kFull), axis_error::kNone);
}

TEST(ServoAxisDrive, DisableDriveCountsAsOffForTheDisplacement) {
    ServoAxis axis(ReferencedConfig());
    axis.SetDriveDisabled(Ms(0), true);
    ASSERT_TRUE(axis.Displace(Ms(0), 3.0));
    axis.SetDriveDisabled(Ms(10), false);
    EXPECT_TRUE(axis.DisplacedDuringOff());
}

TEST(ServoAxisDrive, DisplacementMonitoringCanBeOff) {
    ServoAxisConfig config = ReferencedConfig();
    config.enableMode = EnableMode::kIdle;
    config.displacementMonitoring = false;
    ServoAxis axis(config);
    axis.SetAxisOn(Ms(0), false);
    ASSERT_TRUE(axis.Displace(Ms(0), 30.0));
    axis.SetAxisOn(Ms(10), true);
    EXPECT_FALSE(axis.DisplacedDuringOff());
    EXPECT_NEAR(axis.Position(), 30.0, kNear);
}

// ---- configuration ------------------------------------------------------------------------------------

void ExpectRejected(const std::function<void(ServoAxisConfig&)>& spoil, const std::string& field) {
    ServoAxisConfig config;
    spoil(config);
    try {
        ServoAxis axis(config);
        ADD_FAILURE() << field << ": accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
}

TEST(ServoAxisConfigCheck, RejectsWhatCannotWork) {
    ExpectRejected([](auto& c) { c.traverseSpeed = 0.0; }, "traverseSpeed");
    ExpectRejected([](auto& c) { c.creepSpeed = std::nan(""); }, "creepSpeed");
    ExpectRejected([](auto& c) { c.deceleration = -1.0; }, "deceleration");
    ExpectRejected([](auto& c) { c.minTraverseRange = 20000.0; }, "minTraverseRange");
    ExpectRejected([](auto& c) { c.negativeLimitSwitch = 20000.0; }, "negativeLimitSwitch");
    ExpectRejected([](auto& c) { c.indexPitch = 0.0; }, "indexPitch");
    ExpectRejected([](auto& c) { c.toleranceWindow = -0.1; }, "toleranceWindow");
    ExpectRejected([](auto& c) { c.toleranceDelay = Ms(-1); }, "toleranceDelay");
    ExpectRejected([](auto& c) { c.followingErrorLimit = 0.0; }, "followingErrorLimit");
    ExpectRejected([](auto& c) { c.homingMode = static_cast<HomingMode>(3); }, "homingMode");
    ExpectRejected([](auto& c) { c.maxDisplacementOff = INFINITY; }, "maxDisplacementOff");
    EXPECT_NO_THROW(ServoAxis{ServoAxisConfig{}});
}

TEST(ServoAxisConfigCheck, NoLimitSwitchesAndNoFollowingErrorMonitoring) {
    ServoAxisConfig config;
    config.negativeLimitSwitch.reset();
    config.followingErrorLimit = INFINITY;
    ServoAxis axis(config);
    ASSERT_EQ(axis.Jog(Ms(0), Direction::kNegative, 500.0, kFull), axis_error::kNone);
    axis.SetDisturbance(Ms(10), 100.0);
    axis.Update(Ms(1000));
    EXPECT_NEAR(axis.Position(), -400.0, kNear);
    EXPECT_EQ(axis.AxisError(), 0);
    EXPECT_FALSE(axis.NegativeLimitSwitch());
}

TEST(ServoAxisConfigCheck, RejectedNewConfigKeepsTheOldOne) {
    ServoAxis axis;
    ServoAxisConfig bad = axis.Config();
    bad.acceleration = 0.0;
    EXPECT_THROW(axis.SetConfig(Ms(0), bad), std::invalid_argument);
    EXPECT_EQ(axis.Config().acceleration, 10000.0);
}

}  // namespace
}  // namespace pac::sim
