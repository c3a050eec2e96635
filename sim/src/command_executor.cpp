// The commands of manual chapter 5 on the simulated controller (see command_executor.hpp and
// docs/sim_cmd.md for what the simulator decides where the manual is silent).
#include "pac/sim/command_executor.hpp"

#include <cmath>

#include "pac/sim/command_table.hpp"
#include "command_replies.hpp"

namespace pac::sim {

using reply::Ack;
using reply::Bit;
using reply::Fail;
using reply::LowWord;
using reply::Real;

CommandResult CommandExecutor::Execute(const CommandFrame& c, std::chrono::nanoseconds now,
                                       PendingCommand& pending) {
    const CommandInfo* info = FindCommand(c.code);
    if (info == nullptr) return Fail(error::kUnknownCommand);
    if (!info->validIn.Contains(state_.CurrentMode())) return Fail(error::kInadmissibleCommand);

    switch (c.code) {
        case code::kStop:
        case code::kStartAuto:
        case code::kStartOnline:
        case code::kAbortAuto:
        case code::kAbortOnline:
            return ModeCommand(c, now, pending);
        case code::kSetSystemParameter:
        case code::kGetSystemParameter:
        case code::kGetSystemParameterMax:
        case code::kGetSystemParameterMin:
            return SystemParameterCommand(c);
        case code::kSetAxisParameter:
        case code::kGetAxisParameter:
        case code::kGetAxisParameterMax:
        case code::kGetAxisParameterMin:
            return AxisParameterCommand(c);
        case code::kResetError:
        case code::kGetError:
        case code::kGetState:
        case code::kGetActualPos:
        case code::kGetActualSpeed:
        case code::kGetStatusAxis:
        case code::kGetStatusAllAxis:
        case code::kGetTraverseAreaMin:
        case code::kGetTraverseAreaMax:
        case code::kGetExtendedStatusAxis:
            return StatusCommand(c);
        case code::kGetRotationControlPos:
        case code::kGetMaxTowfault:
        case code::kGetAxisFollowingError:
        case code::kGetTemperature:
            return EpCommand(c);
        case code::kGetSystemFlag:
        case code::kGetSystemNReg:
        case code::kGetSystemRReg:
            return SystemElementCommand(c);
        case code::kPutNoReference:
        case code::kPutStartReference:
        case code::kPutPositionNull:
        case code::kPutSetPosition:
        case code::kPosAxisAbsolute:
        case code::kPosAxisRelative:
        case code::kSetSpeedAxis:
        case code::kSetAccelerationAxis:
        case code::kStartManualAbsolute:
        case code::kStartManualRelative:
        case code::kControlMoveAxis:
        case code::kStopAxis:
        case code::kStartAxisAbsolute:
        case code::kStartAxisRelative:
        case code::kPutReferenceOnPosition:
        case code::kOnAxis:
        case code::kOffAxis:
        case code::kStopAxisMultiCmd:
        case code::kSetMeasuringMode:
        case code::kResetMeasuringMode:
        case code::kPutLimitSwitchMonitoring:
        case code::kPutConditionMoveAxis:
            // 2.7 note: with axis modules configured, the axes move only through them.
            if (state_.axisModules > 0) return Fail(error::kInadmissibleCommand);
            return OnlineCommand(c, now, pending);
        default:
            return ElementCommand(c);
    }
}

CommandResult CommandExecutor::Poll(const PendingCommand& pending, std::chrono::nanoseconds /*now*/) {
    switch (pending.kind) {
        case PendingCommand::Kind::kAxisMotion: {
            // A move ends in position (the tolerance window of the axis), a stop once the axis stands.
            const ServoAxis& axis = state_.axes.Motion(pending.axis);
            return CommandResult{Real(axis.Position()), error::kNone, !axis.JobActive() && !axis.Moving()};
        }
        case PendingCommand::Kind::kModeChange:
            // Ends when the status settles, whatever it settles on (a stop may turn into a
            // malfunction, a start may be cancelled through the CTRL interface).
            return CommandResult{0, error::kNone, !modes_.Transitional()};
        case PendingCommand::Kind::kNone:
            break;
    }
    return Ack(0);
}

CommandResult CommandExecutor::ModeCommand(const CommandFrame& c, std::chrono::nanoseconds now,
                                           PendingCommand& pending) {
    ModeRequestResult result = ModeRequestResult::kNotInThisStatus;
    switch (c.code) {
        case code::kStop: result = modes_.Stop(now); break;
        case code::kStartAuto: result = modes_.StartAutomatic(now); break;
        case code::kStartOnline: result = modes_.StartOnline(now); break;
        case code::kAbortAuto:
        case code::kAbortOnline: result = modes_.Cancel(now); break;
        default: return Fail(error::kUnknownCommand);
    }
    switch (result) {
        case ModeRequestResult::kAccepted: break;
        case ModeRequestResult::kSystemErrorPending: return Fail(error::kNotExecutable);
        case ModeRequestResult::kNoExternalStop: return Fail(error::kExternalStopNotDefined);
        default: return Fail(error::kInadmissibleCommand);
    }
    // 5.2.1: the acknowledgement shows the status the command leads to (11, 15, 31, 35), so the
    // command is processing while the status is transitional (10, 12, 13, 16, 30, 32).
    if (modes_.Transitional()) pending = PendingCommand{PendingCommand::Kind::kModeChange, 0};
    return CommandResult{0, error::kNone, !modes_.Transitional()};
}

CommandResult CommandExecutor::SystemParameterCommand(const CommandFrame& c) {
    ParameterTable& table = state_.systemParameters;
    const std::uint16_t number = c.parameter;
    if (!table.Contains(number)) return Fail(error::kSystemParameterUnknown);
    switch (c.code) {
        case code::kSetSystemParameter:
            if (table.Set(number, c.data) != ParameterTable::SetResult::kOk) return Fail(error::kValueOutsideRange);
            return Ack(c.data);
        case code::kGetSystemParameter: return Ack(*table.Value(number));
        case code::kGetSystemParameterMax: return Ack(*table.Max(number));
        default: return Ack(*table.Min(number));
    }
}

CommandResult CommandExecutor::AxisParameterCommand(const CommandFrame& c) {
    // 5.2.3: parameter high byte = axis, low byte = axis parameter number.
    const int axis = c.parameter >> 8;
    const std::uint16_t number = c.parameter & 0xFF;
    if (!state_.AxisAddressable(axis)) return Fail(error::kAxisNumberUnknown);
    ParameterTable& table = state_.axes.Parameters(axis);
    if (!table.Contains(number)) return Fail(error::kAxisParameterUnknown);
    switch (c.code) {
        case code::kSetAxisParameter:
            if (table.Set(number, c.data) != ParameterTable::SetResult::kOk) return Fail(error::kValueOutsideRange);
            state_.axes.ApplyParameters(axis);
            return Ack(c.data);
        case code::kGetAxisParameter: return Ack(*table.Value(number));
        case code::kGetAxisParameterMax: return Ack(*table.Max(number));
        default: return Ack(*table.Min(number));
    }
}

CommandResult CommandExecutor::ElementCommand(const CommandFrame& c) {
    Elements& e = state_.elements;
    const int n = c.parameter;
    const std::uint16_t value16 = LowWord(c.data);
    switch (c.code) {
        case code::kGetSingleInput:
            return e.inputs.Contains(n) ? Ack(Bit(e.inputs.Get(n))) : Fail(error::kInadmissibleInput);
        case code::kGetInputWord:
            return e.inputs.Contains(n) ? Ack(e.inputs.Word(n)) : Fail(error::kInadmissibleInput);
        case code::kPutSingleOutput:
            if (!e.outputs.Contains(n)) return Fail(error::kInadmissibleOutput);
            if (value16 > 1) return Fail(error::kValueOutsideRange);
            e.outputs.Set(n, value16 != 0);
            return Ack(value16);
        case code::kGetSingleOutput:
            return e.outputs.Contains(n) ? Ack(Bit(e.outputs.Get(n))) : Fail(error::kInadmissibleOutput);
        case code::kPutOutputWord:
            if (!e.outputs.Contains(n)) return Fail(error::kInadmissibleOutput);
            e.outputs.SetWord(n, value16);
            return Ack(value16);
        case code::kGetOutputWord:
            return e.outputs.Contains(n) ? Ack(e.outputs.Word(n)) : Fail(error::kInadmissibleOutput);
        case code::kPutSingleFlag:
            if (!e.flags.Contains(n)) return Fail(error::kInadmissibleFlag);
            if (value16 > 1) return Fail(error::kValueOutsideRange);
            e.flags.Set(n, value16 != 0);
            return Ack(value16);
        case code::kGetSingleFlag:
            return e.flags.Contains(n) ? Ack(Bit(e.flags.Get(n))) : Fail(error::kInadmissibleFlag);
        case code::kPutFlagWord:
            if (!e.flags.Contains(n)) return Fail(error::kInadmissibleFlag);
            e.flags.SetWord(n, value16);
            return Ack(value16);
        case code::kGetFlagWord:
            return e.flags.Contains(n) ? Ack(e.flags.Word(n)) : Fail(error::kInadmissibleFlag);
        case code::kPutIntReg:
            if (!e.intRegisters.Contains(n)) return Fail(error::kInadmissibleNRegister);
            e.intRegisters.Set(n, c.data);
            return Ack(c.data);
        case code::kGetIntReg:
            return e.intRegisters.Contains(n) ? Ack(e.intRegisters.Get(n)) : Fail(error::kInadmissibleNRegister);
        case code::kPutFloatReg:
            if (!e.realRegisters.Contains(n)) return Fail(error::kInadmissibleRRegister);
            e.realRegisters.Set(n, c.data);
            return Ack(c.data);
        case code::kGetFloatReg:
            return e.realRegisters.Contains(n) ? Ack(e.realRegisters.Get(n)) : Fail(error::kInadmissibleRRegister);
        default:
            return Fail(error::kUnknownCommand);
    }
}

CommandResult CommandExecutor::StatusCommand(const CommandFrame& c) {
    switch (c.code) {
        case code::kResetError:
            // 5.2.4.15: CPU errors (1..99) need a power cycle: "command not executable", and the
            // error number again in the acknowledgement data.
            switch (modes_.ResetError()) {
                case ModeRequestResult::kAccepted: return Ack(0);
                case ModeRequestResult::kCpuError: return Fail(error::kNotExecutable, state_.systemError);
                default: return Fail(error::kInadmissibleCommand);
            }
        case code::kGetError: return Ack(state_.systemError);
        case code::kGetState: return Ack(state_.operatingStatus);
        case code::kGetStatusAllAxis: {
            std::uint32_t bits = 0;
            for (int axis = 1; axis <= state_.NumberOfAxes() && axis <= 16; ++axis) {
                if (state_.axes.Motion(axis).Moving()) bits |= 1U << (axis - 1);
            }
            return Ack(bits);
        }
        default: break;
    }
    const int axis = c.parameter;
    if (!state_.AxisAddressable(axis)) return Fail(error::kAxisNumberUnknown);
    const ServoAxis& motion = state_.axes.Motion(axis);
    const ParameterTable& parameters = state_.axes.Parameters(axis);
    switch (c.code) {
        case code::kGetActualPos: return Ack(Real(motion.Position()));
        case code::kGetActualSpeed: return Ack(Real(motion.ActualSpeed()));
        case code::kGetStatusAxis: return Ack(AxisStatusValue(axis));
        case code::kGetExtendedStatusAxis: {
            // 5.2.4.28, byte 0 (bits 31..24) first: power pack ready, positive and negative limit switch
            // not actuated (1 each), the axis status of 1910 (example 0100 0104: ready, positive switch
            // actuated, negative not, malfunction).
            const bool ready = IsPowered(motion.Drive()) && !motion.Fault();
            return Ack(Bit(ready) << 24 | Bit(!motion.PositiveLimitSwitch()) << 16 |
                       Bit(!motion.NegativeLimitSwitch()) << 8 | AxisStatusValue(axis));
        }
        case code::kGetTraverseAreaMin:
        case code::kGetTraverseAreaMax: {
            const auto number = c.code == code::kGetTraverseAreaMin ? axisparam::kMinTraverseArea
                                                                   : axisparam::kMaxTraverseArea;
            const auto value = parameters.Value(number);
            return value ? Ack(*value) : Fail(error::kAxisParameterUnknown);
        }
        default: return Fail(error::kUnknownCommand);
    }
}

CommandResult CommandExecutor::EpCommand(const CommandFrame& c) {
    const OnlineCommandOptions& options = state_.online.Options();
    if (!options.epCommands) return Fail(error::kUnknownCommand);
    const int axis = c.parameter;
    if (!state_.AxisAddressable(axis)) return Fail(error::kAxisNumberUnknown);
    const ServoAxis& motion = state_.axes.Motion(axis);
    double value = 0.0;
    switch (c.code) {
        // 5.2.4.20: a 32-bit real; the simulated encoder follows the axis exactly.
        case code::kGetRotationControlPos: return Ack(Real(motion.Position()));
        case code::kGetMaxTowfault: value = state_.online.MaxFollowingError(axis); break;
        case code::kGetAxisFollowingError: value = motion.FollowingError(); break;
        default: value = options.temperature; break;
    }
    // 5.2.4.26 / 5.2.4.27: "0000 - FFFF" in the header, IEEE REAL bytes in the examples (a setting).
    if (options.epValuesAsReal) return Ack(Real(value));
    return Ack(static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(value))));
}

std::uint32_t CommandExecutor::AxisStatusValue(int axis) const {
    // 5.2.4.22: 8 for an axis in measuring mode (it stands: moves are refused), else the axis's own status.
    if (state_.online.MeasuringMode(axis)) return 8;
    return static_cast<std::uint32_t>(state_.axes.Motion(axis).Status());
}

CommandResult CommandExecutor::SystemElementCommand(const CommandFrame& c) {
    // 6.2: a few system elements follow the controller's state; the rest are plain storage.
    const int n = c.parameter;
    const AxisGroup& axes = state_.axes;
    Elements& e = state_.elements;
    switch (c.code) {
        case code::kGetSystemFlag:
            if (!e.systemFlags.Contains(n)) return Fail(error::kInadmissibleFlag);
            if (n >= 51 && n <= 66 && axes.Contains(n - 50)) return Ack(Bit(axes.Motion(n - 50).Referenced()));
            if (n >= 91 && n <= 106 && axes.Contains(n - 90)) return Ack(Bit(axes.Motion(n - 90).Moving()));
            if (n >= 231 && n <= 246 && axes.Contains(n - 230)) {
                return Ack(Bit(axes.Motion(n - 230).Status() == AxisStatus::kMalfunction));
            }
            return Ack(Bit(e.systemFlags.Get(n)));
        case code::kGetSystemNReg:
            if (!e.systemIntRegisters.Contains(n)) return Fail(error::kInadmissibleNRegister);
            if (n == 10) return Ack(state_.systemError);
            if (n >= 71 && n <= 86 && axes.Contains(n - 70)) {
                return Ack(static_cast<std::uint32_t>(axes.Motion(n - 70).Status()));
            }
            return Ack(e.systemIntRegisters.Get(n));
        default:
            if (!e.systemRealRegisters.Contains(n)) return Fail(error::kInadmissibleRRegister);
            if (n >= 71 && n <= 86 && axes.Contains(n - 70)) return Ack(Real(axes.Motion(n - 70).Target()));
            return Ack(e.systemRealRegisters.Get(n));
    }
}

}  // namespace pac::sim
