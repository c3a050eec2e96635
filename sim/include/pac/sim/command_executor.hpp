// Carries out one CMD command on the controller state (manual 5.2) and says what to acknowledge:
// acknowledgement data, command error number, and whether processing has ended. Commands that end
// later (axis moves, reference run 0A84, axis stop, and the mode commands 0600 / 0602 / 0603 while the status is
// transitional) leave a PendingCommand that Poll() follows cycle by cycle. Mode changes are the
// ModeMachine's; the SEND/RECEIVE handshake is CmdProtocol's.
#pragma once

#include <chrono>
#include <cstdint>

#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/controller_state.hpp"
#include "pac/sim/mode_machine.hpp"

namespace pac::sim {

struct CommandResult {
    std::uint32_t ackData = 0;
    std::uint16_t error = 0;  // command error number, 0: none
    bool finished = true;     // BF
};

struct PendingCommand {
    enum class Kind { kNone, kAxisMotion, kModeChange };
    Kind kind = Kind::kNone;
    int axis = 0;  // kAxisMotion
    bool Active() const { return kind != Kind::kNone; }
};

class CommandExecutor {
public:
    CommandExecutor(ControllerState& state, ModeMachine& modes) : state_(state), modes_(modes) {}

    // `pending` is set when the command ends later, and left alone otherwise.
    CommandResult Execute(const CommandFrame& command, std::chrono::nanoseconds now, PendingCommand& pending);

    // The acknowledgement of a command that is still processing, at `now` (axes already updated).
    CommandResult Poll(const PendingCommand& pending, std::chrono::nanoseconds now);

private:
    CommandResult ModeCommand(const CommandFrame& c, std::chrono::nanoseconds now, PendingCommand& pending);
    CommandResult SystemParameterCommand(const CommandFrame& c);
    CommandResult AxisParameterCommand(const CommandFrame& c);
    CommandResult ElementCommand(const CommandFrame& c);
    CommandResult StatusCommand(const CommandFrame& c);
    CommandResult SystemElementCommand(const CommandFrame& c);
    CommandResult EpCommand(const CommandFrame& c);  // 190E, 190F, 1915, 1920: PA-CONTROL EP only
    std::uint32_t AxisStatusValue(int axis) const;   // 1910
    // command_executor_online.cpp: the ONLINE axis commands of 5.2.6.
    CommandResult OnlineCommand(const CommandFrame& c, std::chrono::nanoseconds now, PendingCommand& pending);
    CommandResult StartMove(const CommandFrame& c, std::chrono::nanoseconds now, bool relative, bool waitForEnd,
                            PendingCommand& pending);
    CommandResult ReferenceCommand(const CommandFrame& c, std::chrono::nanoseconds now, PendingCommand& pending);
    CommandResult StopCommand(const CommandFrame& c, std::chrono::nanoseconds now, PendingCommand& pending);
    CommandResult AxisSettingCommand(const CommandFrame& c, std::chrono::nanoseconds now);
    CommandResult ConditionCommand(const CommandFrame& c);

    ControllerState& state_;
    ModeMachine& modes_;
};

}  // namespace pac::sim
