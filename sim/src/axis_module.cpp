// One axis module in ONLINE mode (see axis_module.hpp and docs/sim_axis_modules.md).
#include "pac/sim/axis_module.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "pac/sim/command_table.hpp"
#include "pac/sim/image8.hpp"

namespace pac::sim {

static_assert(AxisModule::kInadmissible == error::kInadmissibleCommand);

namespace {

using namespace axis_control;

bool Rising(std::uint32_t control, std::uint32_t last, std::uint32_t bit) {
    return (control & bit) != 0 && (last & bit) == 0;
}

bool SingleBit(std::uint32_t bits) { return bits != 0 && (bits & (bits - 1)) == 0; }

}  // namespace

// ---- the bytes ----------------------------------------------------------------------------------------

AxisModuleCommand AxisModuleCommand::Decode(const Image12& module) {
    AxisModuleCommand c;
    c.control = ReadDword(module, 0);
    c.accelerationPerMille = ReadWordAt(module, 4);
    c.speedPerMille = ReadWordAt(module, 6);
    c.position = ReadDword(module, 8);
    return c;
}

Image12 AxisModuleCommand::Encode() const {
    Image12 module{};
    WriteDword(module, 0, control);
    WriteWordAt(module, 4, accelerationPerMille);
    WriteWordAt(module, 6, speedPerMille);
    WriteDword(module, 8, position);
    return module;
}

AxisModuleReply AxisModuleReply::Decode(const Image12& module) {
    AxisModuleReply r;
    r.status = ReadDword(module, 0);
    r.cmdError = ReadWordAt(module, 4);
    r.axisError = ReadWordAt(module, 6);
    r.position = ReadDword(module, 8);
    return r;
}

Image12 AxisModuleReply::Encode() const {
    Image12 module{};
    EncodeInto(module);
    return module;
}

void AxisModuleReply::EncodeInto(Image12& module) const {
    WriteDword(module, 0, status);
    WriteWordAt(module, 4, cmdError);
    WriteWordAt(module, 6, axisError);
    WriteDword(module, 8, position);
}

std::uint32_t EncodeModulePosition(double position, bool integerFormat) {
    if (!integerFormat) return FloatToBits(static_cast<float>(position));
    const double scaled = std::round(position * 1000.0);
    constexpr double kMin = std::numeric_limits<std::int32_t>::min();
    constexpr double kMax = std::numeric_limits<std::int32_t>::max();
    if (std::isnan(scaled)) return 0;
    const double clamped = scaled < kMin ? kMin : (scaled > kMax ? kMax : scaled);
    return static_cast<std::uint32_t>(static_cast<std::int32_t>(clamped));
}

double DecodeModulePosition(std::uint32_t raw, bool integerFormat) {
    if (!integerFormat) return static_cast<double>(BitsToFloat(raw));
    return static_cast<double>(static_cast<std::int32_t>(raw)) / 1000.0;
}

// ---- the module ---------------------------------------------------------------------------------------

AxisModule::AxisModule(AxisModuleConfig config) : config_(config) {}

void TakenAxisJobLedger::Add(const TakenAxisJob& job) {
    if (jobs_.size() < kKept) {
        jobs_.push_back(job);
    } else {
        jobs_[count_ % kKept] = job;
    }
    ++count_;
}

const TakenAxisJob& TakenAxisJobLedger::operator[](std::size_t number) const {
    if (number < First() || number >= count_) {
        throw std::out_of_range("TakenAxisJobLedger: job " + std::to_string(number) + " is not kept (kept: " +
                                std::to_string(First()) + " to " + std::to_string(count_) + ")");
    }
    return jobs_[number % kKept];
}

void AxisModule::Reset() { *this = AxisModule(config_); }

void AxisModule::SetConditionInput(int input) {
    if (input < 1) throw std::invalid_argument("AxisModule::SetConditionInput: input must be >= 1");
    conditionInput_ = input;
}

Image12 AxisModule::Cycle(const Image12& toPac, ServoAxis& axis, const AxisModuleContext& context) {
    Serve(toPac, axis, context);
    return Reply(axis, context);
}

void AxisModule::Serve(const Image12& toPac, ServoAxis& axis, const AxisModuleContext& context) {
    const AxisModuleCommand command = AxisModuleCommand::Decode(toPac);
    const std::uint32_t control = command.control;
    axis.Update(context.now);
    if (pendingCmdError_ != 0) {  // kOneCycleClear: the refusal of the last cycle's Start edge
        cmdError_ = pendingCmdError_;
        pendingCmdError_ = 0;
    }
    // Each step is called only where its first test lets it act: in most cycles of most modules none does.
    if ((context.service != AxisModuleService::kReportOnly) != served_) FollowMode(axis, context);
    if (context.service != AxisModuleService::kReportOnly &&
        (((control & kDisableDrive) != 0) != axis.DriveDisabled() || ((control & kAxisOn) != 0) != axis.AxisOn() ||
         Rising(control, lastControl_, kResetAxisError))) {
        ApplyDrive(control, axis, context);
    }
    if (job_ != 0 && !jobComplete_) FollowJob(control, axis, context);
    if (config_.speedChange == SpeedChange::kWhileTraversing) FollowDynamics(command, axis, context);
    if (toContinue_) ContinueInterruptedTraverse(axis, context);
    // 2.7.4.8: ACTIVE falls at the earliest when the job is complete and Start is 0 again.
    if (active_ && jobComplete_ && (control & kStart) == 0) active_ = false;
    // 2.7.3.2: a job is recognised on the Start edge while none is processed; an edge during a job is lost.
    if (Rising(control, lastControl_, kStart) && !active_) StartEdge(command, axis, context);
    lastControl_ = control;
}

void AxisModule::FollowMode(ServoAxis& axis, const AxisModuleContext& context) {
    const bool online = context.service != AxisModuleService::kReportOnly;
    if (online && !served_) conditionInput_ = kDefaultConditionInput;  // 2.7.3.10: input 1 when ONLINE starts
    if (!online && served_) {
        // Outside ONLINE the axis is operational again, whatever Axis ON said (2.7.2, last note).
        const auto now = context.now;
        axis.SetDriveDisabled(now, false);
        axis.SetAxisOn(now, true);
        toContinue_ = false;  // the switch-on that continues a traverse is the axis-ON function in ONLINE
    }
    served_ = online;
}

void AxisModule::ApplyDrive(std::uint32_t control, ServoAxis& axis, const AxisModuleContext& context) {
    const auto now = context.now;
    // Levels: the axis follows bits 0 and 1 every cycle; switching off brakes a moving axis first.
    const bool disable = (control & kDisableDrive) != 0;
    if (axis.DriveDisabled() != disable) axis.SetDriveDisabled(now, disable);
    const bool on = (control & kAxisOn) != 0;
    if (!on && axis.AxisOn() && JobRunning() && job_ != kJogPositive && job_ != kJogNegative && job_ != kHome &&
        config_.interruptedTraverse == InterruptedTraverse::kContinuesAfterAxisOn) {
        toContinue_ = true;  // a move: its target is known; a reference run or jog is not continued here
    }
    if (axis.AxisOn() != on) axis.SetAxisOn(now, on);
    // Edge: an error raised between two cycles is always shown for at least one cycle, even with bit 16
    // held; a reset refused because the cause persists (ServoAxis::ResetAxisError) needs a new edge.
    if (Rising(control, lastControl_, kResetAxisError)) axis.ResetAxisError(now);
}

void AxisModule::FollowJob(std::uint32_t control, ServoAxis& axis, const AxisModuleContext& context) {
    if (job_ == 0 || jobComplete_) return;
    if (axis.JobActive() && !interrupted_ && !continued_) {
        if ((control & job_) == 0) {
            // 2.7.3 note: removing the traverse bit interrupts the job (the axis brakes, HALT).
            axis.Interrupt(context.now);
            interrupted_ = true;
        } else if (condition_ != Condition::kNone && !ConditionHolds(context)) {
            // 2.7.3.10 / 2.7.3.11: the input left the condition: the traverse ends, braking from here.
            axis.Interrupt(context.now);
            interrupted_ = true;
            stoppedByG123_ = true;
        }
    }
    if (!axis.JobActive()) jobComplete_ = true;
}

void AxisModule::StartEdge(const AxisModuleCommand& command, ServoAxis& axis, const AxisModuleContext& context) {
    const std::uint16_t refusal = TakeOver(command, axis, context);
    if (refusal == 0) {
        cmdError_ = 0;
        pendingCmdError_ = 0;
        // Taken over: ACTIVE in the same cycle, even for a job that is already complete, unless this
        // controller raises it for traversing tasks only.
        active_ = !(jobComplete_ && config_.activeFor == ActiveForJobs::kTraversingOnly);
        return;
    }
    if (refusal == axis_error::kNoReferencePoint && config_.noReference == NoReferenceAnswer::kSystemError525) {
        // 2.7.2 note: a system error instead of the command error; the Start clears an earlier CMD error.
        cmdError_ = 0;
        pendingCmdError_ = 0;
        axis.RaiseAxisError(context.now, kSystemErrorNoReference);
        return;
    }
    ShowCmdError(refusal);
}

void AxisModule::ShowCmdError(std::uint16_t number) {
    if (config_.cmdErrorRestart == CmdErrorRestart::kSameCycle) {
        cmdError_ = number;
    } else {
        cmdError_ = 0;
        pendingCmdError_ = number;
    }
}

std::uint16_t AxisModule::TakeOver(const AxisModuleCommand& command, ServoAxis& axis,
                                   const AxisModuleContext& context) {
    if (context.service != AxisModuleService::kJobs) return kInadmissible;
    const std::uint32_t control = command.control;
    const std::uint32_t traverse = control & kTraverseBits;
    if (!SingleBit(traverse)) return kInadmissible;  // none, or several traverse bits (2.7.2 notes)
    const bool whileOne = (control & kWhileInput1) != 0;
    const bool whileZero = (control & kWhileInput0) != 0;
    const Condition condition =
        whileOne ? Condition::kWhileOne : (whileZero ? Condition::kWhileZero : Condition::kNone);
    if (whileOne && whileZero) return kInadmissible;
    if (condition != Condition::kNone && traverse != kMoveAbsolute && traverse != kMoveRelative) return kInadmissible;

    const auto now = context.now;
    const double position = DecodeModulePosition(command.position, context.integerFormat);
    // Invalid per mille: dynamics the axis refuses with 41, in its own order of checks (after 46/55/56/42).
    const Dynamics dynamics = ScaledDynamics(axis.Config(), command.speedPerMille, command.accelerationPerMille)
                                  .value_or(Dynamics{0.0, 0.0, 0.0});
    const JobOptions options{(control & kDisableLimitSwitches) == 0};  // bit 17, taken over with Start

    std::uint16_t result = axis_error::kNone;
    switch (traverse) {
        case kHome: result = axis.Home(now); break;
        case kSetReferenced: result = axis.SetPositionReferenced(now, position); break;
        case kSetPosition: result = axis.ShiftPosition(now, position); break;
        case kMoveAbsolute: result = axis.MoveAbsolute(now, position, dynamics, options); break;
        case kMoveRelative: result = axis.MoveRelative(now, position, dynamics, options); break;
        case kJogPositive: result = axis.Jog(now, Direction::kPositive, std::fabs(position), dynamics, options); break;
        case kJogNegative: result = axis.Jog(now, Direction::kNegative, std::fabs(position), dynamics, options); break;
        case kClearOffset: result = axis.DeleteShift(now); break;
        case kClearDisplaced: result = axis.ResetDisplaced(now); break;
        case kMoveToMax: result = axis.MoveToMaxRange(now, dynamics, options); break;
        default: result = axis.MoveToMinRange(now, dynamics, options); break;  // kMoveToMin
    }
    if (result != axis_error::kNone) return result;

    job_ = traverse;
    taken_.Add({command, now});
    interrupted_ = false;
    continued_ = false;
    toContinue_ = false;
    target_ = axis.Target();
    dynamics_ = dynamics;
    speedPerMille_ = command.speedPerMille;
    accelerationPerMille_ = command.accelerationPerMille;
    condition_ = condition;
    if (condition != Condition::kNone) {
        stoppedByG123_ = false;  // bit 11 is about the last job with G123
        if (!ConditionHolds(context)) {
            // "It will not start at all and is thus terminated already": taken over and ended in this cycle.
            axis.EmergencyStop(now);
            interrupted_ = true;
            stoppedByG123_ = true;
        }
    }
    jobComplete_ = !axis.JobActive();
    return 0;
}

void AxisModule::FollowDynamics(const AxisModuleCommand& command, ServoAxis& axis, const AxisModuleContext& context) {
    if (config_.speedChange != SpeedChange::kWhileTraversing || !JobRunning() || interrupted_ || job_ == kHome) return;
    if (command.speedPerMille == speedPerMille_ && command.accelerationPerMille == accelerationPerMille_) return;
    speedPerMille_ = command.speedPerMille;
    accelerationPerMille_ = command.accelerationPerMille;
    // Values outside 1..1000 / 1..65535 are ignored: the move goes on as it was (no answer channel but the
    // CMD error, which belongs to Start commands, 2.7.4.14).
    const auto dynamics = ScaledDynamics(axis.Config(), speedPerMille_, accelerationPerMille_);
    if (dynamics && axis.ChangeDynamics(context.now, *dynamics)) dynamics_ = *dynamics;
}

void AxisModule::ContinueInterruptedTraverse(ServoAxis& axis, const AxisModuleContext& context) {
    if (!toContinue_ || axis.JobActive() || !axis.AxisOn()) return;
    if (context.service != AxisModuleService::kJobs || axis.Drive() != DriveState::kEnabled) return;
    toContinue_ = false;
    // The axis parameter "switch on traverse mode" continues the move to its target; a displaced axis is not
    // moved (2.7.4.12: the refusal leaves the job ended).
    if (axis.MoveAbsolute(context.now, target_, dynamics_, JobOptions{}) != axis_error::kNone) return;
    continued_ = true;
    interrupted_ = false;
    jobComplete_ = false;
    active_ = true;
}

bool AxisModule::ConditionHolds(const AxisModuleContext& context) const {
    const bool input = context.inputs != nullptr && context.inputs->Contains(conditionInput_) &&
                       context.inputs->Get(conditionInput_);
    return condition_ == Condition::kWhileOne ? input : !input;
}

Image12 AxisModule::Reply(const ServoAxis& axis, const AxisModuleContext& context) const {
    Image12 module{};
    ReplyInto(axis, context, module);
    return module;
}

// Into the caller's bytes: the controller's reply of every cycle builds no copy of its own.
void AxisModule::ReplyInto(const ServoAxis& axis, const AxisModuleContext& context, Image12& module) const {
    using namespace axis_status;
    const DriveState drive = axis.Drive();
    const ServoAxis::ActualSample actual = axis.SampleActual();
    std::uint32_t status = 0;
    if (drive == DriveState::kEnabled) status |= kDriveEnabled;
    if (drive == DriveState::kHalt || (drive == DriveState::kEnabled && axis.Interrupted())) status |= kHalt;
    if (!IsPowered(drive)) status |= kDriveDisabled;
    if (drive == DriveState::kSafe) status |= kSafe;
    if (drive == DriveState::kIdle) status |= kIdle;
    if (drive == DriveState::kDisabled) status |= kDisabled;
    if (axis.Fault()) status |= kFault | kAxisError;
    if (active_) status |= kActive;
    if (axis.Referenced()) status |= kReferenced;
    if (!actual.negativeLimitSwitch) status |= kNegativeLimitNotActuated;
    if (!actual.positiveLimitSwitch) status |= kPositiveLimitNotActuated;
    if (stoppedByG123_) status |= kStoppedByCondition;
    if (axis.DisplacedDuringOff()) status |= kDisplaced;
    if (axis.DisplacedDuringOff() || context.groupDisplaced) status |= kGroupDisplaced;
    if (cmdError_ != 0) status |= kCmdError;

    AxisModuleReply reply;
    reply.status = status;
    reply.cmdError = cmdError_;
    reply.axisError = axis.AxisError();
    reply.position = EncodeModulePosition(actual.position, context.integerFormat);
    reply.EncodeInto(module);
}

}  // namespace pac::sim
