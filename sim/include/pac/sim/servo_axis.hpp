// A position-controlled servo axis for the simulated PA-CONTROL, modelled on the ANPOS2 positioning device
// (docs/sim_axis.md): ramped moves, software limits, limit and reference switches, homing modes 0/1/2,
// G26/G29, tolerance window, following-error monitoring, enable modes and "displaced during OFF". It knows
// nothing of the bus: the axis module (manual 2.7) and the CMD axis commands (5.2.6) are served on top.
// Simulated time only; everything that happens between two calls (a switch reached, a ramp ended) happens
// at its own computed time, so the results do not depend on how often Update() is called.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>

#include "pac/sim/axis_status.hpp"
#include "pac/sim/servo_axis_config.hpp"
#include "pac/sim/trajectory.hpp"

namespace pac::sim {

// Numbers the axis reports: refusals of a job (the axis module's CMD error number, 2.7.4.14) and axis errors
// (2.7.4.15). Values of the command error list (6.5, docs/manual_errata.md) where one fits.
namespace axis_error {
constexpr std::uint16_t kNone = 0;
constexpr std::uint16_t kValueOutsideRange = 41;     // 16#29: target not finite, dynamics not > 0
constexpr std::uint16_t kAxisStillMoves = 42;        // 16#2A: a job runs or the axis moves
constexpr std::uint16_t kNoReferencePoint = 43;      // 16#2B
constexpr std::uint16_t kAxisNotReady = 46;          // 16#2E: an axis error is pending
constexpr std::uint16_t kAxisNotSwitchedOn = 55;     // 16#37: Axis ON = 0 (HALT / IDLE / SAFE) or DRIVE disabled
constexpr std::uint16_t kAxisDisplacedTooMuch = 56;  // 16#38: "displaced during OFF" flag set
constexpr std::uint16_t kLimitSwitchActuated = 64;   // 16#40: refusal (start into an actuated switch), axis error
constexpr std::uint16_t kPositionOutsideRange = 65;  // 16#41: target outside the software limits
constexpr std::uint16_t kFollowingError = 66;        // axis error; not in 6.5: the simulator's choice (16#42)
}  // namespace axis_error

// The drive's state; status word bits 0..5 of the axis module derive from it (docs/sim_axis.md).
enum class DriveState {
    kEnabled,   // Axis ON, drive powered, position controlled: jobs run
    kHalt,      // Axis OFF, enable mode HALT: powered, holds its position
    kIdle,      // Axis OFF, enable mode IDLE: no current, brake applied
    kSafe,      // Axis OFF, enable mode SAFE: no current, safety function on
    kDisabled,  // DISABLE DRIVE (G140): no current, whatever Axis ON says
};
inline bool IsPowered(DriveState state) { return state == DriveState::kEnabled || state == DriveState::kHalt; }

// Per job (axis module control word bit 17, G142): limit switch monitoring. G25 always monitors.
struct JobOptions {
    bool limitSwitchMonitoring = true;
};

// Aligned to a cache line, so that the fields of every cycle (first in the object) share as few as possible.
class alignas(64) ServoAxis {
public:
    // std::invalid_argument from ServoAxisConfig::Validate(). The axis stands at config.startPosition, Axis ON,
    // drive enabled, referenced as config.referenced, at time 0.
    explicit ServoAxis(ServoAxisConfig config = {});

    // Brings the axis up to `now` (an earlier time is ignored: time never runs backwards). Every call below
    // does this first with its own `now`. Inline, the case of every cycle: no event due and nothing settling,
    // so that only the time moves on (the controller brings each of its axes here several times per cycle).
    void Update(std::chrono::nanoseconds now) {
        if (now < now_ || (settled_ && settledAt_ == now)) return;
        if (eventKnown_ && (!nextEvent_ || nextEvent_->time > now) && activity_ != Activity::kSettling) {
            now_ = now;
            Settled();
            return;
        }
        RunUntil(now);
    }

    // Jobs (a Start edge of the axis module, or a CMD move). 0 = taken over, else the refusal number
    // (axis_error); a refused job changes nothing. Checked in this order: 46 axis error pending, 55 not
    // switched on, 56 displaced during OFF, 42 still moving (or a job still active), 41 invalid target or
    // dynamics, 43 not referenced, 65 target outside the software limits, 64 moving into an actuated limit
    // switch (monitoring on). Positions are in the axis's coordinates.
    [[nodiscard]] std::uint16_t MoveAbsolute(std::chrono::nanoseconds now, double target, const Dynamics& dynamics,
                                             JobOptions options = {});
    // From the commanded position (= the actual one unless a disturbance is injected).
    [[nodiscard]] std::uint16_t MoveRelative(std::chrono::nanoseconds now, double distance, const Dynamics& dynamics,
                                             JobOptions options = {});
    [[nodiscard]] std::uint16_t MoveToMaxRange(std::chrono::nanoseconds now, const Dynamics& dynamics,
                                               JobOptions options = {});
    [[nodiscard]] std::uint16_t MoveToMinRange(std::chrono::nanoseconds now, const Dynamics& dynamics,
                                               JobOptions options = {});
    // Control word bits 10 / 11: up to `distance` (>= 0) in `direction`, without reference and range check.
    [[nodiscard]] std::uint16_t Jog(std::chrono::nanoseconds now, Direction direction, double distance,
                                    const Dynamics& dynamics, JobOptions options = {});
    // G25 with the configured homing mode, reference / creep speed, acceleration and deceleration (2.7.5 note).
    // Clears Referenced() at once; mode 2 does not move, it arms the switch and the job ends at once.
    [[nodiscard]] std::uint16_t Home(std::chrono::nanoseconds now);
    // G26: the actual position becomes `position`, referenced; software limits unchanged. Refused (42) while
    // a job runs; allowed while switched off.
    [[nodiscard]] std::uint16_t SetPositionReferenced(std::chrono::nanoseconds now, double position);
    // G29: the actual position becomes `position`; the software limits move by the same displacement.
    [[nodiscard]] std::uint16_t ShiftPosition(std::chrono::nanoseconds now, double position);
    // Delete G29 offset(s): position and software limits back by the sum of the G29 displacements.
    [[nodiscard]] std::uint16_t DeleteShift(std::chrono::nanoseconds now);
    // Reset "displaced during OFF" (control word bit 13). Always accepted.
    [[nodiscard]] std::uint16_t ResetDisplaced(std::chrono::nanoseconds now);

    // 2.7.6: new speed and ramps for the move under way (axis types that allow it), on to the same target from
    // the commanded position and speed. False, the move going on as planned, when no move runs, it is on its
    // final ramp or braking, or it could no longer stop at its target with the new deceleration.
    bool ChangeDynamics(std::chrono::nanoseconds now, const Dynamics& dynamics);
    // Interrupt (traverse bit removed, CMD stop): brake with the job's deceleration; the job ends interrupted
    // (HALT) once standing. A move already on its final deceleration ramp finishes at its target instead.
    void Interrupt(std::chrono::nanoseconds now);
    // Emergency stop: the commanded motion ends at once, without a ramp (ANPOS2 EMRG); the job ends interrupted.
    void EmergencyStop(std::chrono::nanoseconds now);
    // Control word bit 16. False (error kept) while its cause persists (a following error still too large).
    bool ResetAxisError(std::chrono::nanoseconds now);
    // Control word bits 0 and 1. Switching off while moving brakes first (job interrupted); the enable
    // mode's state follows once standing. Switching on from a state without current checks the displacement.
    void SetAxisOn(std::chrono::nanoseconds now, bool on);
    void SetDriveDisabled(std::chrono::nanoseconds now, bool disabled);
    // New parameters (validated; std::invalid_argument). A running profile keeps its plan; later jobs, limits
    // and monitoring use the new values. startPosition and referenced are used by the constructor only.
    void SetConfig(std::chrono::nanoseconds now, const ServoAxisConfig& config);
    void SetReferenced(bool referenced) { referenced_ = referenced; }  // 0A83, test hook

    // Queries, as of the last Update().
    std::chrono::nanoseconds Now() const { return now_; }
    // Inline, as the other queries the axis module's reply makes of every axis in every cycle.
    double Position() const { return ActualMachine() + offset_; }  // actual position, axis coordinates
    double CommandedPosition() const { return CommandedMachine() + offset_; }  // ANPOS2 posvirt
    double Target() const;              // the job's target (after a stop: where it stopped)
    double Velocity() const;            // actual, signed
    double ActualSpeed() const;         // |Velocity()|
    double FollowingError() const;      // commanded - actual
    // |FollowingError()|, without evaluating the profile where it is 0 (inline: supervised every cycle).
    double FollowingErrorSize() const { return !blocked_ && disturbance_ == 0.0 ? 0.0 : DisturbedFollowingError(); }
    MotionPhase Phase() const;
    bool Moving() const { return trajectory_.Moves(); }  // the trajectory generator runs (ANPOS2 st_still = 0)
    bool JobActive() const { return activity_ != Activity::kNone; }  // moving, homing, or not yet in position
    bool InTolerance() const;           // ANPOS2 st_toll
    // The last job was interrupted and the axis stands (status HALT).
    bool Interrupted() const { return interrupted_ && !Moving(); }
    bool HomingActive() const { return activity_ == Activity::kHoming; }
    bool HomingArmed() const { return captureArmed_; }  // mode 2 waits for the switch
    double LastHomingCorrection() const { return homingCorrection_; }  // ANPOS2 deltaprspos
    bool Referenced() const { return referenced_; }
    std::uint16_t AxisError() const { return axisError_; }
    bool Fault() const { return axisError_ != 0; }
    AxisStatus Status() const;          // 1910: malfunction, moving (job active), stopped, in position
    DriveState Drive() const { return drive_; }
    bool AxisOn() const { return axisOn_; }
    bool DriveDisabled() const { return driveDisabled_; }
    bool DisplacedDuringOff() const { return displaced_; }
    // Actuated = true (the axis module reports them low-active, 2.7.4.9 / 2.7.4.10).
    bool NegativeLimitSwitch() const {
        return config_.negativeLimitSwitch && ActualMachine() <= *config_.negativeLimitSwitch;
    }
    bool PositiveLimitSwitch() const {
        return config_.positiveLimitSwitch && ActualMachine() >= *config_.positiveLimitSwitch;
    }
    bool ReferenceSwitch() const;
    // Position(), NegativeLimitSwitch() and PositiveLimitSwitch() from one evaluation of the actual position:
    // the axis module's reply asks for the three of every axis in every cycle.
    struct ActualSample {
        double position;
        bool negativeLimitSwitch;
        bool positiveLimitSwitch;
    };
    ActualSample SampleActual() const {
        const double machine = ActualMachine();
        return {machine + offset_, hasNegativeLimit_ && machine <= negativeLimit_,
                hasPositiveLimit_ && machine >= positiveLimit_};
    }
    double MinRange() const { return config_.minTraverseRange + shift_; }  // with the G29 shift
    double MaxRange() const { return config_.maxTraverseRange + shift_; }
    double Shift() const { return shift_; }                                  // sum of the G29 displacements
    const ServoAxisConfig& Config() const { return config_; }

    // Test hooks. Each brings the axis to `now` first.
    // Actual = commanded + offset while the axis is not blocked (a load the servo cannot correct).
    void SetDisturbance(std::chrono::nanoseconds now, double offset);
    // A blocked axis keeps its actual position while the commanded one moves on.
    void SetBlocked(std::chrono::nanoseconds now, bool blocked);
    // Pushes an axis without current (IDLE / SAFE / DISABLED) by `delta`; false (ignored) while powered or blocked.
    bool Displace(std::chrono::nanoseconds now, double delta);
    // Puts the axis at `position` (axis coordinates), standing, in position, no job.
    void Place(std::chrono::nanoseconds now, double position);
    // An axis error with this number (not 0): the axis stops at once.
    void RaiseAxisError(std::chrono::nanoseconds now, std::uint16_t number);

private:
    enum class Activity : std::uint8_t { kNone, kPositioning, kSettling, kBraking, kHoming };  // one byte: see now_
    enum class HomingStep { kNone, kSearch, kSearchBrake, kCreep, kCreepBrake };
    enum class EventKind { kFollowingError, kLimitSwitch, kCapture, kHomingPoint, kTrajectoryEnd };
    struct Event {
        std::chrono::nanoseconds time;
        EventKind kind;
        double position;  // machine position of the actual axis where it happens
    };

    // Machine coordinates: commanded and actual position, and the time base of the running profile.
    double Seconds() const;
    // Settled at now_, the profile and the time stay as they are until the next change: the many queries of a
    // cycle (position, limit switches, following error) evaluate it once.
    double CommandedMachine() const {
        if (settledCommandedKnown_ && settled_ && settledAt_ == now_) return settledCommanded_;
        return EvaluateCommanded();
    }
    double EvaluateCommanded() const;
    double ActualMachine() const { return blocked_ ? blockedAt_ : CommandedMachine() + disturbance_; }
    double CommandedVelocity() const;

    std::uint16_t MotionRefusal() const;
    std::uint16_t StartMove(double target, const Dynamics& dynamics, JobOptions options, bool needsReference,
                            bool checksRange);
    std::uint16_t SetPositionRefusal(double position) const;
    bool IntoActuatedLimitSwitch(Direction direction) const;

    // Update() where an event may be due or the axis settles.
    void RunUntil(std::chrono::nanoseconds now);
    // Update() is done at now_: nothing changes the axis until the next call that changes it.
    void Settled() {
        settled_ = true;
        settledAt_ = now_;
        settledCommandedKnown_ = false;
    }
    double DisturbedFollowingError() const;
    // Update(), for the calls that change the axis after it: every one of them comes through here.
    void Advance(std::chrono::nanoseconds now);
    void RunEventsUntil(std::chrono::nanoseconds until);
    std::optional<Event> NextEvent() const;
    bool NextEventDependsOnPosition() const;
    std::optional<std::chrono::nanoseconds> WhenCommandReaches(double commanded) const;
    std::optional<std::chrono::nanoseconds> WhenActualReaches(double actual) const;
    bool EntersCamAhead() const;
    void Handle(const Event& event);
    void MotionEnded();

    void SetMotion(const Trajectory& trajectory, double target);
    void HoldAt(double commanded);
    void BrakeFromHere(double deceleration);
    void BrakeJob();
    void EndJob(bool interrupted);
    void Fail(std::uint16_t number, double commandedHold);
    void CheckFollowingError();
    void Settle();

    void StartSearch();
    void StartCreep();
    void LoadReference(double machinePosition);
    double NextIndexPulse(double from, Direction direction) const;
    bool OnCam(double machinePosition) const;

    DriveState WantedDrive() const;
    void ApplyDriveRequest();
    void CopyLimitSwitches();  // after every change of config_

    template <typename Change>
    void ChangeRegime(Change change);
    std::optional<std::chrono::nanoseconds> WindowEntry() const;

    // First, in one or two cache lines, what every cycle reads of each of the controller's 16 axes (Update(),
    // the ONLINE supervision's following error, the group's displaced flag): the other fields of an axis
    // without a job stay out of the cache.
    std::chrono::nanoseconds now_{0};
    // The time of the last Update() after which nothing changed: a new Update() to it has nothing to do.
    std::chrono::nanoseconds settledAt_{0};
    // NextEvent() as last searched, while nothing has changed the axis since (eventKnown_): the times it
    // finds follow from the profile and the settings alone, so a later search would find the same event
    // (RunEventsUntil). Every change comes through Advance() or Handle(), which forget it.
    std::optional<Event> nextEvent_;
    Activity activity_ = Activity::kNone;
    bool settled_ = false;
    bool eventKnown_ = false;
    mutable bool settledCommandedKnown_ = false;  // settledCommanded_ is CommandedMachine() at settledAt_
    bool blocked_ = false;    // injected: the actual position stays at blockedAt_
    bool displaced_ = false;  // "displaced during OFF"
    double disturbance_ = 0.0;  // injected: actual = commanded + disturbance_
    mutable double settledCommanded_ = 0.0;
    // Next, what every cycle reads of an axis with a module (its cycle and its reply).
    double offset_ = 0.0;  // axis position = machine position + offset_
    std::chrono::nanoseconds trajectoryStart_{0};  // the time base of trajectory_
    DriveState drive_ = DriveState::kEnabled;
    std::uint16_t axisError_ = 0;
    bool axisOn_ = true;
    bool driveDisabled_ = false;
    bool interrupted_ = false;
    bool referenced_ = false;
    // config_'s limit switches, copied by CopyLimitSwitches(): every cycle's reply reads them, config_ is lines away.
    bool hasNegativeLimit_ = false;
    bool hasPositiveLimit_ = false;
    double negativeLimit_ = 0.0;
    double positiveLimit_ = 0.0;

    // Motion: the running profile (machine coordinates), its start (above), the job's target (NaN: none yet).
    Trajectory trajectory_;
    double target_ = 0.0;
    HomingStep homingStep_ = HomingStep::kNone;
    double homingPoint_ = 0.0;  // machine position the creep run loads the reference at (NaN: none ahead)
    double jobDeceleration_ = 0.0;
    bool monitorLimitSwitches_ = true;
    // Start of the current stay inside the tolerance window (possibly still ahead), if there is one.
    std::optional<std::chrono::nanoseconds> windowSince_;

    ServoAxisConfig config_;
    double offPosition_ = 0.0;  // actual machine position when the current went off (drive state above)
    double blockedAt_ = 0.0;    // the actual position of a blocked axis

    // Coordinates: axis position = machine position + offset_ (above); shift_ is the G29 part of it.
    double shift_ = 0.0;
    bool captureArmed_ = false;
    double homingCorrection_ = 0.0;
};

}  // namespace pac::sim
