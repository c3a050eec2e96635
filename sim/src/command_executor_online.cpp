// The ONLINE axis commands of manual 5.2.6 on the simulated controller (see command_executor.hpp, and
// docs/sim_cmd.md for what the simulator decides where the manual is silent).
#include <cmath>
#include <cstdint>

#include "command_replies.hpp"
#include "pac/sim/command_executor.hpp"
#include "pac/sim/command_table.hpp"

namespace pac::sim {

using reply::Ack;
using reply::Fail;
using reply::LowWord;
using reply::Real;

namespace {

bool Runs(const ServoAxis& motion) { return motion.JobActive() || motion.Moving(); }

}  // namespace

CommandResult CommandExecutor::OnlineCommand(const CommandFrame& c, std::chrono::nanoseconds now,
                                             PendingCommand& pending) {
    switch (c.code) {
        case code::kPosAxisAbsolute: return StartMove(c, now, false, true, pending);
        case code::kPosAxisRelative: return StartMove(c, now, true, true, pending);
        case code::kStartAxisAbsolute:
        case code::kStartManualAbsolute: return StartMove(c, now, false, false, pending);
        case code::kStartAxisRelative:
        case code::kStartManualRelative: return StartMove(c, now, true, false, pending);
        case code::kPutLimitSwitchMonitoring:
        case code::kPutConditionMoveAxis: return ConditionCommand(c);
        default: break;
    }
    const int axis = c.parameter;
    if (!state_.AxisAddressable(axis)) return Fail(error::kAxisNumberUnknown);
    ServoAxis& motion = state_.axes.Motion(axis);
    switch (c.code) {
        case code::kPutNoReference:
            motion.SetReferenced(true);
            return Ack(0);
        case code::kPutStartReference:
        case code::kPutPositionNull:
        case code::kPutSetPosition:
        case code::kPutReferenceOnPosition: return ReferenceCommand(c, now, pending);
        case code::kStopAxis:
        case code::kStopAxisMultiCmd: return StopCommand(c, now, pending);
        case code::kControlMoveAxis:
            // 5.2.6.12: keeps a manual traverse going; acknowledged at once with the position.
            if (state_.online.ManualTraverse(axis)) state_.online.KeepAlive(axis, now);
            return Ack(Real(motion.Position()));
        default: return AxisSettingCommand(c, now);
    }
}

CommandResult CommandExecutor::ReferenceCommand(const CommandFrame& c, std::chrono::nanoseconds now,
                                                PendingCommand& pending) {
    const int axis = c.parameter;
    ServoAxis& motion = state_.axes.Motion(axis);
    const float value = BitsToFloat(c.data);
    switch (c.code) {
        case code::kPutStartReference: {
            // 5.2.6.3: the reference run (G25) ends processing when the reference flag is set.
            if (state_.online.MeasuringMode(axis)) return Fail(error::kAxisNotReady);
            const std::uint16_t refusal = motion.Home(now);
            if (refusal != 0) return Fail(refusal);
            const bool finished = !Runs(motion);
            if (!finished) pending = PendingCommand{PendingCommand::Kind::kAxisMotion, axis};
            return CommandResult{0, error::kNone, finished};
        }
        case code::kPutPositionNull: {
            // 5.2.6.4 (G26): the position becomes 0, the software limits stay where they are.
            const std::uint16_t refusal = motion.SetPositionReferenced(now, 0.0);
            return refusal == 0 ? Ack(0) : Fail(refusal);
        }
        case code::kPutSetPosition: {
            // 5.2.6.5 (G29): the software limits move with the scale; the data is acknowledged.
            if (!std::isfinite(value)) return Fail(error::kValueOutsideRange);
            const std::uint16_t refusal = motion.ShiftPosition(now, value);
            return refusal == 0 ? Ack(c.data) : Fail(refusal);
        }
        default: {
            // 5.2.6.16: referenced at the current position, which becomes the command data.
            if (!std::isfinite(value)) return Fail(error::kValueOutsideRange);
            const std::uint16_t refusal = motion.SetPositionReferenced(now, value);
            return refusal == 0 ? Ack(Real(motion.Position())) : Fail(refusal);
        }
    }
}

CommandResult CommandExecutor::StopCommand(const CommandFrame& c, std::chrono::nanoseconds now,
                                           PendingCommand& pending) {
    const int axis = c.parameter;
    ServoAxis& motion = state_.axes.Motion(axis);
    motion.Interrupt(now);
    state_.online.EndManualTraverse(axis);
    // 5.2.6.13: 0A93 ends processing once the axis stands; 5.2.6.19: 0A9A at once, with the position.
    const bool finished = c.code == code::kStopAxisMultiCmd || !motion.Moving();
    if (!finished) pending = PendingCommand{PendingCommand::Kind::kAxisMotion, axis};
    return CommandResult{Real(motion.Position()), error::kNone, finished};
}

CommandResult CommandExecutor::AxisSettingCommand(const CommandFrame& c, std::chrono::nanoseconds now) {
    const int axis = c.parameter;
    ServoAxis& motion = state_.axes.Motion(axis);
    switch (c.code) {
        case code::kSetSpeedAxis:
        case code::kSetAccelerationAxis: {
            // 5.2.6.8 / 5.2.6.9: only within the limits of the traverse speed / acceleration parameter.
            const bool isSpeed = c.code == code::kSetSpeedAxis;
            const std::uint16_t parameter = isSpeed ? axisparam::kTraverseSpeed : axisparam::kAcceleration;
            const float value = BitsToFloat(c.data);
            const ParameterTable& parameters = state_.axes.Parameters(axis);
            if (!(value > 0.0F) || !std::isfinite(value) ||
                (parameters.Contains(parameter) && !parameters.WithinLimits(parameter, c.data))) {
                return Fail(error::kValueOutsideRange);
            }
            if (isSpeed) {
                state_.axes.SetSessionSpeed(axis, value);
            } else {
                state_.axes.SetSessionAcceleration(axis, value);  // one parameter for both ramps
            }
            return Ack(c.data);
        }
        case code::kOnAxis:
        case code::kOffAxis:
            // 5.2.6.17 / 5.2.6.18: switching off while moving brakes first (ServoAxis::SetAxisOn).
            motion.SetAxisOn(now, c.code == code::kOnAxis);
            return Ack(0);
        case code::kSetMeasuringMode:
            // 5.2.6.20: only with the axis standing still; positioning is blocked until 0AA1.
            if (Runs(motion)) return Fail(error::kAxisStillMoves);
            state_.online.SetMeasuringMode(axis, true);
            return Ack(0);
        case code::kResetMeasuringMode:
            // 5.2.6.21: on an axis not in measuring mode, only acknowledged.
            state_.online.SetMeasuringMode(axis, false);
            return Ack(0);
        default: return Fail(error::kUnknownCommand);
    }
}

CommandResult CommandExecutor::ConditionCommand(const CommandFrame& c) {
    // 5.2.6.22 / 5.2.6.23: parameter 0 = every axis.
    const int axis = c.parameter;
    if (axis != 0 && !state_.AxisAddressable(axis)) return Fail(error::kAxisNumberUnknown);
    const int first = axis == 0 ? 1 : axis;
    const int last = axis == 0 ? state_.NumberOfAxes() : axis;
    if (c.code == code::kPutLimitSwitchMonitoring) {
        const std::uint16_t on = LowWord(c.data);
        if (on > 1 || (c.data >> 16) != 0) return Fail(error::kValueOutsideRange);
        for (int a = first; a <= last; ++a) state_.online.SetLimitSwitchMonitoring(a, on == 1);
        return Ack(0);
    }
    std::uint32_t level = 0;
    std::uint32_t type = 0;
    std::uint32_t number = 0;
    if (state_.online.Options().conditionLayout == ConditionLayout::kBySignificance) {
        level = c.data >> 24;
        type = (c.data >> 16) & 0xFF;
        number = c.data & 0xFFFF;
    } else {
        number = c.data >> 16;
        type = (c.data >> 8) & 0xFF;
        level = c.data & 0xFF;
    }
    if (level > 1 || type < 1 || type > 3) return Fail(error::kValueOutsideRange);
    const Elements& e = state_.elements;
    const int n = static_cast<int>(number);
    switch (static_cast<ElementType>(type)) {
        case ElementType::kInput:
            if (!e.inputs.Contains(n)) return Fail(error::kInadmissibleInput);
            break;
        case ElementType::kOutput:
            if (!e.outputs.Contains(n)) return Fail(error::kInadmissibleOutput);
            break;
        default:
            if (!e.flags.Contains(n)) return Fail(error::kInadmissibleFlag);
            break;
    }
    const MoveCondition condition{static_cast<ElementType>(type), n, level == 1};
    for (int a = first; a <= last; ++a) state_.online.SetCondition(a, condition);
    return Ack(0);
}

CommandResult CommandExecutor::StartMove(const CommandFrame& c, std::chrono::nanoseconds now, bool relative,
                                         bool waitForEnd, PendingCommand& pending) {
    // Axes move in ONLINE proper (31), not while stopping, stopped or with malfunction.
    if (state_.operatingStatus != status::kOnline) return Fail(error::kInadmissibleCommand);
    const int axis = c.parameter;
    if (!state_.AxisAddressable(axis)) return Fail(error::kAxisNumberUnknown);
    const float value = BitsToFloat(c.data);
    if (!std::isfinite(value)) return Fail(error::kValueOutsideRange);
    // 5.2.6.20: "positioning commands are blocked" in measuring mode; the simulator answers 46 (not ready).
    if (state_.online.MeasuringMode(axis)) return Fail(error::kAxisNotReady);
    ServoAxis& motion = state_.axes.Motion(axis);
    const double start = motion.Position();
    // The axis checks the rest (46 axis error, 55 not switched on, 56 displaced, 42 still moves, 43 no
    // reference, 65 outside the traverse range, 64 into an actuated limit switch while monitored) with the
    // session dynamics.
    const Dynamics& dynamics = state_.axes.SessionDynamics(axis);
    const JobOptions options{state_.online.LimitSwitchMonitoring(axis)};
    const std::uint16_t refusal = relative ? motion.MoveRelative(now, value, dynamics, options)
                                           : motion.MoveAbsolute(now, value, dynamics, options);
    if (refusal != 0) return Fail(refusal);
    state_.online.ArmConditionOfMove(axis);
    if (c.code == code::kStartManualAbsolute || c.code == code::kStartManualRelative) {
        state_.online.KeepAlive(axis, now);  // 5.2.6.10: stands unless 0A92 follows within the keep-alive
    } else {
        state_.online.EndManualTraverse(axis);
    }
    // 5.2.6.6: the acknowledgement data is the start position; 0A94/0A95 and 0A90/0A91 end processing at once.
    const bool finished = !waitForEnd || !Runs(motion);
    if (!finished) pending = PendingCommand{PendingCommand::Kind::kAxisMotion, axis};
    return CommandResult{Real(start), error::kNone, finished};
}

}  // namespace pac::sim
