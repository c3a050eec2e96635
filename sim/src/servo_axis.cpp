// The simulated servo axis after ANPOS2 (see servo_axis.hpp and docs/sim_axis.md). Between two calls the
// axis runs from event to event: each event (profile end, limit switch, reference point, following error)
// is found from the profile at its own time, handled there, and the next one is searched from that state.
#include "pac/sim/servo_axis.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "pac/sim/command_table.hpp"

namespace pac::sim {

static_assert(axis_error::kValueOutsideRange == error::kValueOutsideRange);
static_assert(axis_error::kAxisStillMoves == error::kAxisStillMoves);
static_assert(axis_error::kNoReferencePoint == error::kNoReferencePoint);
static_assert(axis_error::kPositionOutsideRange == error::kPositionOutsideRange);

namespace {

using std::chrono::nanoseconds;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// More events than this within one call means a handler failed to change the state it reacted to.
constexpr int kMaxEventsPerCall = 10000;

double ToSeconds(nanoseconds d) { return static_cast<double>(d.count()) / 1e9; }

// `seconds` after `base`, to the nearest nanosecond; beyond the range of nanoseconds (an absurdly slow
// profile) the event is simply never due.
nanoseconds After(nanoseconds base, double seconds) {
    const double room = static_cast<double>((nanoseconds::max() - base).count()) / 2e9;
    if (!(seconds < room)) return nanoseconds::max();
    return base + nanoseconds(std::llround(seconds * 1e9));
}

}  // namespace

ServoAxis::ServoAxis(ServoAxisConfig config) : config_(config) {
    config_.Validate();
    CopyLimitSwitches();
    referenced_ = config_.referenced;
    offPosition_ = config_.startPosition;
    HoldAt(config_.startPosition);
}

void ServoAxis::CopyLimitSwitches() {
    hasNegativeLimit_ = config_.negativeLimitSwitch.has_value();
    hasPositiveLimit_ = config_.positiveLimitSwitch.has_value();
    negativeLimit_ = config_.negativeLimitSwitch.value_or(0.0);
    positiveLimit_ = config_.positiveLimitSwitch.value_or(0.0);
}

// ---- time and positions -------------------------------------------------------------------------------

double ServoAxis::Seconds() const { return ToSeconds(now_ - trajectoryStart_); }
double ServoAxis::EvaluateCommanded() const {
    const double commanded = trajectory_.PositionAt(Seconds());
    if (settled_ && settledAt_ == now_) {
        settledCommanded_ = commanded;
        settledCommandedKnown_ = true;
    }
    return commanded;
}
double ServoAxis::CommandedVelocity() const { return trajectory_.VelocityAt(Seconds()); }

double ServoAxis::Target() const { return std::isnan(target_) ? CommandedPosition() : target_ + offset_; }
double ServoAxis::Velocity() const { return blocked_ ? 0.0 : CommandedVelocity(); }
double ServoAxis::ActualSpeed() const { return std::fabs(Velocity()); }
double ServoAxis::FollowingError() const { return CommandedMachine() - ActualMachine(); }
// FollowingErrorSize() of a blocked or disturbed axis: neither, the actual position is the commanded one, and
// c - (c + 0) is 0 exactly.
double ServoAxis::DisturbedFollowingError() const { return std::fabs(FollowingError()); }
MotionPhase ServoAxis::Phase() const { return trajectory_.PhaseAt(Seconds()); }

bool ServoAxis::InTolerance() const { return windowSince_ && *windowSince_ + config_.toleranceDelay <= now_; }

AxisStatus ServoAxis::Status() const {
    if (axisError_ != 0) return AxisStatus::kMalfunction;
    if (JobActive() || Moving()) return AxisStatus::kMoving;
    return interrupted_ ? AxisStatus::kStopped : AxisStatus::kInPosition;
}

bool ServoAxis::ReferenceSwitch() const { return OnCam(ActualMachine()); }

bool ServoAxis::OnCam(double machinePosition) const {
    return config_.referenceCamSide == Direction::kNegative ? machinePosition <= config_.referenceSwitch
                                                            : machinePosition >= config_.referenceSwitch;
}

// ---- advancing time -----------------------------------------------------------------------------------

// Update() once its shortcuts are ruled out: a call to the time of the last one found nothing changed since
// (the simulator asks several times per cycle: the axis group, the axis module), and with no event due and
// nothing settling only the time moves on.
void ServoAxis::RunUntil(nanoseconds now) {
    settled_ = false;  // the events change the axis
    RunEventsUntil(now);
    now_ = now;
    Settle();
    Settled();
}

void ServoAxis::Advance(nanoseconds now) {
    Update(now);
    settled_ = false;  // the caller changes the axis now: the next Update() must look for events again
    eventKnown_ = false;
}

void ServoAxis::RunEventsUntil(nanoseconds until) {
    // The event searched at an earlier time of the same state is the one a search now would find: the
    // times come from the profile, and one is clamped to the search's time only when due at once, which
    // a search that found nothing due up to now_ rules out for the rest.
    for (int k = 0; k < kMaxEventsPerCall; ++k) {
        if (!eventKnown_) {
            nextEvent_ = NextEvent();
            eventKnown_ = !NextEventDependsOnPosition();
        }
        if (!nextEvent_ || nextEvent_->time > until) return;
        const Event event = *nextEvent_;
        eventKnown_ = false;  // handled: the state changes
        if (event.time > now_) now_ = event.time;
        Handle(event);
    }
    throw std::logic_error("ServoAxis: events do not settle");
}

bool ServoAxis::NextEventDependsOnPosition() const {
    // Entering the reference cam is searched only while off it (EntersCamAhead): a search that reads the
    // position is not kept.
    return captureArmed_ || (activity_ == Activity::kHoming && homingStep_ == HomingStep::kSearch);
}

std::optional<nanoseconds> ServoAxis::WhenCommandReaches(double commanded) const {
    const auto tau = trajectory_.TimeToReach(commanded);
    if (!tau) return std::nullopt;
    const nanoseconds at = After(trajectoryStart_, *tau);
    return at < now_ ? now_ : at;  // already there (a hook moved it): now
}

std::optional<nanoseconds> ServoAxis::WhenActualReaches(double actual) const {
    if (blocked_) return std::nullopt;  // the actual position does not move
    return WhenCommandReaches(actual - disturbance_);
}

bool ServoAxis::EntersCamAhead() const {
    const double actual = ActualMachine();
    if (blocked_ || OnCam(actual)) return false;
    // Off the cam, the edge lies towards the cam: moving that way enters it.
    return trajectory_.Dir() == config_.referenceCamSide;
}

std::optional<ServoAxis::Event> ServoAxis::NextEvent() const {
    if (!trajectory_.Moves()) return std::nullopt;
    std::optional<Event> best;
    // Considered in priority order: of two events at the same nanosecond the first one wins.
    const auto consider = [&best](std::optional<nanoseconds> at, EventKind kind, double position) {
        if (at && (!best || *at < best->time)) best = Event{*at, kind, position};
    };
    const double sign = Sign(trajectory_.Dir());
    if (blocked_ && IsPowered(drive_) && axisError_ == 0 && std::isfinite(config_.followingErrorLimit)) {
        consider(WhenCommandReaches(blockedAt_ + sign * config_.followingErrorLimit), EventKind::kFollowingError,
                 blockedAt_);
    }
    if (monitorLimitSwitches_) {
        const auto& limit = sign > 0.0 ? config_.positiveLimitSwitch : config_.negativeLimitSwitch;
        if (limit) consider(WhenActualReaches(*limit), EventKind::kLimitSwitch, *limit);
    }
    if (captureArmed_ && EntersCamAhead()) {
        consider(WhenActualReaches(config_.referenceSwitch), EventKind::kCapture, config_.referenceSwitch);
    }
    if (activity_ == Activity::kHoming) {
        if (homingStep_ == HomingStep::kSearch && EntersCamAhead()) {
            consider(WhenActualReaches(config_.referenceSwitch), EventKind::kHomingPoint, config_.referenceSwitch);
        } else if (homingStep_ == HomingStep::kCreep && !std::isnan(homingPoint_)) {
            consider(WhenActualReaches(homingPoint_), EventKind::kHomingPoint, homingPoint_);
        }
    }
    if (std::isfinite(trajectory_.Duration())) {
        consider(After(trajectoryStart_, trajectory_.Duration()), EventKind::kTrajectoryEnd,
                 trajectory_.EndPosition());
    }
    return best;
}

void ServoAxis::Handle(const Event& event) {
    switch (event.kind) {
        case EventKind::kFollowingError:
            // The controller takes the blocked actual position over as its command.
            Fail(axis_error::kFollowingError, event.position - disturbance_);
            break;
        case EventKind::kLimitSwitch:
            // Stopped at once, on the switch (no ramp: docs/sim_axis.md).
            Fail(axis_error::kLimitSwitchActuated, event.position - disturbance_);
            break;
        case EventKind::kCapture:
            LoadReference(event.position);
            captureArmed_ = false;
            break;
        case EventKind::kHomingPoint:
            if (homingStep_ == HomingStep::kSearch) {
                BrakeFromHere(config_.deceleration);
                homingStep_ = HomingStep::kSearchBrake;
            } else {
                LoadReference(event.position);
                BrakeFromHere(config_.deceleration);
                homingStep_ = HomingStep::kCreepBrake;
            }
            // Reached at a standstill (a run started right on the cam's edge): there is no ramp whose end
            // would close the step, so it closes now, or the run would stay ACTIVE for ever.
            if (!trajectory_.Moves()) MotionEnded();
            break;
        case EventKind::kTrajectoryEnd:
            HoldAt(trajectory_.EndPosition());
            MotionEnded();
            break;
    }
}

void ServoAxis::MotionEnded() {
    switch (activity_) {
        case Activity::kPositioning:
            activity_ = Activity::kSettling;
            break;
        case Activity::kBraking:
            EndJob(true);
            break;
        case Activity::kHoming:
            if (homingStep_ == HomingStep::kSearchBrake) {
                StartCreep();
            } else if (homingStep_ == HomingStep::kCreepBrake) {
                homingStep_ = HomingStep::kNone;
                activity_ = Activity::kSettling;
            }
            break;
        default:
            break;
    }
    ApplyDriveRequest();  // an Axis OFF / DISABLE DRIVE that waited for the standstill
}

void ServoAxis::Settle() {
    if (activity_ == Activity::kSettling && InTolerance()) activity_ = Activity::kNone;
}

// ---- motion -------------------------------------------------------------------------------------------

template <typename Change>
void ServoAxis::ChangeRegime(Change change) {
    // A stay inside the window that began earlier goes on if the axis is still inside after the change.
    std::optional<nanoseconds> before;
    if (windowSince_ && *windowSince_ <= now_) before = windowSince_;
    change();
    const auto entry = WindowEntry();
    windowSince_ = (entry && *entry == now_ && before) ? before : entry;
}

std::optional<nanoseconds> ServoAxis::WindowEntry() const {
    // Only where the profile comes to rest counts: passing through the window on the way is not "in position".
    if (std::isnan(target_) || !std::isfinite(trajectory_.EndPosition())) return std::nullopt;
    const double window = config_.toleranceWindow;
    if (blocked_) {
        if (std::fabs(blockedAt_ - target_) <= window) return now_;
        return std::nullopt;
    }
    // The commanded positions that put the actual one inside.
    const double low = target_ - disturbance_ - window;
    const double high = target_ - disturbance_ + window;
    const double end = trajectory_.EndPosition();
    if (end < low || end > high) return std::nullopt;
    const double commanded = CommandedMachine();
    if (commanded >= low && commanded <= high) return now_;
    return WhenCommandReaches(commanded < low ? low : high);
}

void ServoAxis::SetMotion(const Trajectory& trajectory, double target) {
    ChangeRegime([&] {
        trajectory_ = trajectory;
        trajectoryStart_ = now_;
        target_ = target;
    });
}

void ServoAxis::HoldAt(double commanded) { SetMotion(Trajectory::Hold(commanded), commanded); }

void ServoAxis::BrakeFromHere(double deceleration) {
    const Trajectory brake = Trajectory::Brake(CommandedMachine(), trajectory_.Dir(), std::fabs(CommandedVelocity()),
                                               deceleration, config_.rampType);
    SetMotion(brake, brake.EndPosition());
}

void ServoAxis::BrakeJob() {
    if (activity_ == Activity::kNone || activity_ == Activity::kBraking) return;
    if (!trajectory_.Moves()) {  // standing, not yet in position
        EndJob(true);
        return;
    }
    if (trajectory_.FinalRampAt(Seconds())) {
        // Already braking with the job's deceleration: a move ends at its target,
        // a homing run at the end of this ramp.
        if (activity_ == Activity::kHoming) {
            homingStep_ = HomingStep::kNone;
            activity_ = Activity::kBraking;
        }
        return;
    }
    homingStep_ = HomingStep::kNone;
    activity_ = Activity::kBraking;
    BrakeFromHere(jobDeceleration_);
    // A profile that had only just begun (an abort in the instant a reference run turns to creep) has no
    // speed to brake from: no ramp will end the job, so it ends here.
    if (!trajectory_.Moves()) MotionEnded();
}

void ServoAxis::EndJob(bool interrupted) {
    activity_ = Activity::kNone;
    homingStep_ = HomingStep::kNone;
    interrupted_ = interrupted;
}

void ServoAxis::Fail(std::uint16_t number, double commandedHold) {
    HoldAt(commandedHold);
    if (activity_ != Activity::kNone) EndJob(true);
    axisError_ = number;
    ApplyDriveRequest();
}

void ServoAxis::CheckFollowingError() {
    if (!IsPowered(drive_) || axisError_ != 0 || !std::isfinite(config_.followingErrorLimit)) return;
    if (std::fabs(FollowingError()) > config_.followingErrorLimit) {
        Fail(axis_error::kFollowingError, ActualMachine() - disturbance_);
    }
}

// ---- jobs ---------------------------------------------------------------------------------------------

std::uint16_t ServoAxis::MotionRefusal() const {
    if (axisError_ != 0) return axis_error::kAxisNotReady;
    if (drive_ != DriveState::kEnabled || WantedDrive() != DriveState::kEnabled) {
        return axis_error::kAxisNotSwitchedOn;
    }
    if (displaced_) return axis_error::kAxisDisplacedTooMuch;
    if (activity_ != Activity::kNone || trajectory_.Moves()) return axis_error::kAxisStillMoves;
    return axis_error::kNone;
}

bool ServoAxis::IntoActuatedLimitSwitch(Direction direction) const {
    return direction == Direction::kPositive ? PositiveLimitSwitch() : NegativeLimitSwitch();
}

std::uint16_t ServoAxis::StartMove(double target, const Dynamics& dynamics, JobOptions options, bool needsReference,
                                   bool checksRange) {
    if (const auto refusal = MotionRefusal()) return refusal;
    if (!std::isfinite(target) || !IsValid(dynamics)) return axis_error::kValueOutsideRange;
    if (needsReference && !referenced_) return axis_error::kNoReferencePoint;
    if (checksRange && (target < MinRange() || target > MaxRange())) return axis_error::kPositionOutsideRange;
    const double start = CommandedMachine();
    const double goal = target - offset_;
    if (goal != start && options.limitSwitchMonitoring &&
        IntoActuatedLimitSwitch(goal > start ? Direction::kPositive : Direction::kNegative)) {
        return axis_error::kLimitSwitchActuated;
    }
    interrupted_ = false;
    monitorLimitSwitches_ = options.limitSwitchMonitoring;
    jobDeceleration_ = dynamics.deceleration;
    activity_ = Activity::kPositioning;
    SetMotion(Trajectory::PointToPoint(start, goal, dynamics, config_.rampType), goal);
    if (!trajectory_.Moves()) activity_ = Activity::kSettling;  // already there
    RunEventsUntil(now_);
    Settle();
    return axis_error::kNone;
}

std::uint16_t ServoAxis::MoveAbsolute(nanoseconds now, double target, const Dynamics& dynamics, JobOptions options) {
    Advance(now);
    return StartMove(target, dynamics, options, true, true);
}

std::uint16_t ServoAxis::MoveRelative(nanoseconds now, double distance, const Dynamics& dynamics,
                                      JobOptions options) {
    Advance(now);
    return StartMove(CommandedPosition() + distance, dynamics, options, true, true);
}

std::uint16_t ServoAxis::MoveToMaxRange(nanoseconds now, const Dynamics& dynamics, JobOptions options) {
    Advance(now);
    return StartMove(MaxRange(), dynamics, options, true, true);
}

std::uint16_t ServoAxis::MoveToMinRange(nanoseconds now, const Dynamics& dynamics, JobOptions options) {
    Advance(now);
    return StartMove(MinRange(), dynamics, options, true, true);
}

std::uint16_t ServoAxis::Jog(nanoseconds now, Direction direction, double distance, const Dynamics& dynamics,
                             JobOptions options) {
    Advance(now);
    if (const auto refusal = MotionRefusal()) return refusal;
    if (!(distance >= 0.0) || !std::isfinite(distance)) return axis_error::kValueOutsideRange;
    return StartMove(CommandedPosition() + Sign(direction) * distance, dynamics, options, false, false);
}

std::uint16_t ServoAxis::Home(nanoseconds now) {
    Advance(now);
    if (const auto refusal = MotionRefusal()) return refusal;
    const bool onCam = ReferenceSwitch();
    if (config_.homingMode != HomingMode::kLoadOnSwitch) {
        const Direction first = onCam ? Opposite(config_.homingDirection) : config_.homingDirection;
        if (IntoActuatedLimitSwitch(first)) return axis_error::kLimitSwitchActuated;
    }
    referenced_ = false;  // ANPOS2: starting the search clears st_prsok
    interrupted_ = false;
    if (config_.homingMode == HomingMode::kLoadOnSwitch) {
        captureArmed_ = true;
        return axis_error::kNone;
    }
    captureArmed_ = false;
    monitorLimitSwitches_ = true;  // G25 cannot switch the monitoring off (2.7.3.17)
    jobDeceleration_ = config_.deceleration;
    activity_ = Activity::kHoming;
    if (onCam) {
        StartCreep();
    } else {
        StartSearch();
    }
    RunEventsUntil(now_);
    Settle();
    return axis_error::kNone;
}

void ServoAxis::StartSearch() {
    homingStep_ = HomingStep::kSearch;
    SetMotion(Trajectory::Run(CommandedMachine(), config_.homingDirection, config_.referenceSpeed,
                              config_.acceleration, config_.rampType),
              kNaN);
}

void ServoAxis::StartCreep() {
    // Off the cam at creep speed, against the search direction. If the edge is not ahead (a cam on the
    // other side than the search expects), the run finds no home point and ends at a limit switch.
    const Direction direction = Opposite(config_.homingDirection);
    const double edge = config_.referenceSwitch;
    homingPoint_ = kNaN;
    if ((edge - ActualMachine()) * Sign(direction) >= 0.0) {
        homingPoint_ = config_.homingMode == HomingMode::kSwitch ? edge : NextIndexPulse(edge, direction);
    }
    homingStep_ = HomingStep::kCreep;
    SetMotion(Trajectory::Run(CommandedMachine(), direction, config_.creepSpeed, config_.acceleration,
                              config_.rampType),
              kNaN);
}

double ServoAxis::NextIndexPulse(double from, Direction direction) const {
    // The first pulse strictly beyond `from` in `direction`.
    const double sign = Sign(direction);
    const double pitch = config_.indexPitch;
    const double k = (from - config_.indexOffset) / pitch;
    double pulse = config_.indexOffset + (sign > 0.0 ? std::floor(k) + 1.0 : std::ceil(k) - 1.0) * pitch;
    if ((pulse - from) * sign <= 0.0) pulse += sign * pitch;
    return pulse;
}

void ServoAxis::LoadReference(double machinePosition) {
    const double before = machinePosition + offset_;
    offset_ = config_.referencePosition - machinePosition;
    shift_ = 0.0;  // the reference run defines the coordinates afresh
    homingCorrection_ = config_.referencePosition - before;
    referenced_ = true;
}

std::uint16_t ServoAxis::SetPositionRefusal(double position) const {
    if (activity_ != Activity::kNone || trajectory_.Moves()) return axis_error::kAxisStillMoves;
    if (!std::isfinite(position)) return axis_error::kValueOutsideRange;
    return axis_error::kNone;
}

std::uint16_t ServoAxis::SetPositionReferenced(nanoseconds now, double position) {
    Advance(now);
    if (const auto refusal = SetPositionRefusal(position)) return refusal;
    offset_ = position - ActualMachine();
    referenced_ = true;
    interrupted_ = false;
    return axis_error::kNone;
}

std::uint16_t ServoAxis::ShiftPosition(nanoseconds now, double position) {
    Advance(now);
    if (const auto refusal = SetPositionRefusal(position)) return refusal;
    const double displacement = position - Position();
    offset_ += displacement;
    shift_ += displacement;
    interrupted_ = false;
    return axis_error::kNone;
}

std::uint16_t ServoAxis::DeleteShift(nanoseconds now) {
    Advance(now);
    if (const auto refusal = SetPositionRefusal(0.0)) return refusal;
    offset_ -= shift_;
    shift_ = 0.0;
    interrupted_ = false;
    return axis_error::kNone;
}

std::uint16_t ServoAxis::ResetDisplaced(nanoseconds now) {
    Advance(now);
    displaced_ = false;
    return axis_error::kNone;
}

bool ServoAxis::ChangeDynamics(nanoseconds now, const Dynamics& dynamics) {
    Advance(now);
    if (activity_ != Activity::kPositioning || !trajectory_.Moves() || !IsValid(dynamics)) return false;
    if (trajectory_.FinalRampAt(Seconds())) return false;
    const auto plan = Trajectory::FromSpeed(CommandedMachine(), target_, std::fabs(CommandedVelocity()), dynamics,
                                            config_.rampType);
    if (!plan) return false;
    jobDeceleration_ = dynamics.deceleration;
    SetMotion(*plan, target_);
    RunEventsUntil(now_);
    Settle();
    return true;
}

void ServoAxis::Interrupt(nanoseconds now) {
    Advance(now);
    BrakeJob();
    RunEventsUntil(now_);
    Settle();
}

void ServoAxis::EmergencyStop(nanoseconds now) {
    Advance(now);
    if (trajectory_.Moves()) HoldAt(CommandedMachine());
    if (activity_ != Activity::kNone) EndJob(true);
    ApplyDriveRequest();
    Settle();
}

bool ServoAxis::ResetAxisError(nanoseconds now) {
    Advance(now);
    if (axisError_ == 0) return true;
    if (IsPowered(drive_) && std::isfinite(config_.followingErrorLimit) &&
        std::fabs(FollowingError()) > config_.followingErrorLimit) {
        return false;
    }
    axisError_ = 0;
    return true;
}

// ---- drive --------------------------------------------------------------------------------------------

DriveState ServoAxis::WantedDrive() const {
    if (driveDisabled_) return DriveState::kDisabled;
    if (axisOn_) return DriveState::kEnabled;
    switch (config_.enableMode) {
        case EnableMode::kIdle: return DriveState::kIdle;
        case EnableMode::kSafe: return DriveState::kSafe;
        default: return DriveState::kHalt;
    }
}

void ServoAxis::ApplyDriveRequest() {
    const DriveState wanted = WantedDrive();
    if (wanted == drive_) return;
    if (trajectory_.Moves()) {  // only an enabled drive moves: brake, the new state follows at the standstill
        BrakeJob();
        return;
    }
    if (activity_ != Activity::kNone) EndJob(true);
    if (IsPowered(drive_) && !IsPowered(wanted)) offPosition_ = ActualMachine();
    if (!IsPowered(drive_) && IsPowered(wanted) && config_.displacementMonitoring &&
        std::fabs(ActualMachine() - offPosition_) > config_.maxDisplacementOff) {
        displaced_ = true;
    }
    drive_ = wanted;
    CheckFollowingError();
}

void ServoAxis::SetAxisOn(nanoseconds now, bool on) {
    Advance(now);
    axisOn_ = on;
    ApplyDriveRequest();
    RunEventsUntil(now_);
    Settle();
}

void ServoAxis::SetDriveDisabled(nanoseconds now, bool disabled) {
    Advance(now);
    driveDisabled_ = disabled;
    ApplyDriveRequest();
    RunEventsUntil(now_);
    Settle();
}

void ServoAxis::SetConfig(nanoseconds now, const ServoAxisConfig& config) {
    config.Validate();
    Advance(now);
    ChangeRegime([&] {
        config_ = config;
        CopyLimitSwitches();
    });
    ApplyDriveRequest();
    CheckFollowingError();
    RunEventsUntil(now_);
    Settle();
}

// ---- test hooks ---------------------------------------------------------------------------------------

void ServoAxis::SetDisturbance(nanoseconds now, double offset) {
    if (!std::isfinite(offset)) throw std::invalid_argument("ServoAxis::SetDisturbance: offset must be finite");
    Advance(now);
    ChangeRegime([&] { disturbance_ = offset; });
    CheckFollowingError();
    RunEventsUntil(now_);
    Settle();
}

void ServoAxis::SetBlocked(nanoseconds now, bool blocked) {
    Advance(now);
    if (blocked == blocked_) return;
    ChangeRegime([&] {
        if (blocked) blockedAt_ = ActualMachine();
        blocked_ = blocked;
    });
    CheckFollowingError();
    RunEventsUntil(now_);
    Settle();
}

bool ServoAxis::Displace(nanoseconds now, double delta) {
    if (!std::isfinite(delta)) throw std::invalid_argument("ServoAxis::Displace: delta must be finite");
    Advance(now);
    if (IsPowered(drive_) || blocked_) return false;
    const bool wasOnCam = ReferenceSwitch();
    HoldAt(CommandedMachine() + delta);  // without current the command follows the axis
    if (captureArmed_ && !wasOnCam && ReferenceSwitch()) {
        LoadReference(config_.referenceSwitch);
        captureArmed_ = false;
    }
    Settle();
    return true;
}

void ServoAxis::Place(nanoseconds now, double position) {
    if (!std::isfinite(position)) throw std::invalid_argument("ServoAxis::Place: position must be finite");
    Advance(now);
    if (activity_ != Activity::kNone) EndJob(false);
    interrupted_ = false;
    const double machine = position - offset_;
    if (blocked_) blockedAt_ = machine;
    HoldAt(machine - disturbance_);
    CheckFollowingError();
    Settle();
}

void ServoAxis::RaiseAxisError(nanoseconds now, std::uint16_t number) {
    if (number == 0) throw std::invalid_argument("ServoAxis::RaiseAxisError: number must not be 0");
    Advance(now);
    Fail(number, ActualMachine() - disturbance_);
    Settle();
}

}  // namespace pac::sim
