// Carries out one CMD command on the controller state (manual 5.2) and says what to acknowledge:
// acknowledgement data, command error number, and whether processing has ended. Commands that end
// later (axis moves, axis stop, cmd_stop) leave a PendingCommand that Poll() follows cycle by cycle.
// The SEND/RECEIVE handshake is not its business (CmdProtocol).
#pragma once

#include <chrono>
#include <cstdint>

#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/controller_state.hpp"

namespace pac::sim {

struct CommandResult {
    std::uint32_t ackData = 0;
    std::uint16_t error = 0;  // command error number, 0: none
    bool finished = true;     // BF
};

struct PendingCommand {
    enum class Kind { kNone, kAxisMotion, kStopAll };
    Kind kind = Kind::kNone;
    int axis = 0;  // kAxisMotion
    bool Active() const { return kind != Kind::kNone; }
};

struct ExecutorOptions {
    // 5.2.1.3: ONLINE needs an external stop input (system parameter 4) that has power; otherwise
    // 0603 fails with error 44.
    bool requireExternalStop = true;
};

class CommandExecutor {
public:
    CommandExecutor(ControllerState& state, ExecutorOptions options) : state_(state), options_(options) {}

    // `pending` is set when the command ends later, and left alone otherwise.
    CommandResult Execute(const MasterFrame& command, std::chrono::nanoseconds now, PendingCommand& pending);

    // The acknowledgement of a command that is still processing, at `now` (axes already updated).
    CommandResult Poll(const PendingCommand& pending, std::chrono::nanoseconds now);

private:
    CommandResult ModeCommand(const MasterFrame& c, std::chrono::nanoseconds now, PendingCommand& pending);
    CommandResult SystemParameterCommand(const MasterFrame& c);
    CommandResult AxisParameterCommand(const MasterFrame& c);
    CommandResult ElementCommand(const MasterFrame& c);
    CommandResult StatusCommand(const MasterFrame& c);
    CommandResult SystemElementCommand(const MasterFrame& c);
    CommandResult OnlineCommand(const MasterFrame& c, std::chrono::nanoseconds now, PendingCommand& pending);
    CommandResult StartMove(const MasterFrame& c, std::chrono::nanoseconds now, bool relative, bool waitForEnd,
                            PendingCommand& pending);
    void LeaveToHome(std::chrono::nanoseconds now);

    ControllerState& state_;
    ExecutorOptions options_;
};

}  // namespace pac::sim
