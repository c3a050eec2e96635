// The operating-mode machine (see mode_machine.hpp and docs/sim_modes.md).
#include "pac/sim/mode_machine.hpp"

#include <stdexcept>

namespace pac::sim {

namespace {

bool IsHome(std::uint8_t s) { return s == status::kHome || s == status::kHomeWithSystemError; }
bool OnlineRunning(std::uint8_t s) { return s == status::kOnlineStarted || s == status::kOnline; }
bool AutomaticRunning(std::uint8_t s) {
    return s == status::kAutoStarted || s == status::kAuto || s == status::kAutoStartAfterStop;
}

// A newer error replaces the one held unless the one held is of a more severe class: a CPU error,
// which only a power cycle clears, must not be hidden by a later operating error.
int Severity(SystemErrorClass c) {
    switch (c) {
        case SystemErrorClass::kCpu: return 3;
        case SystemErrorClass::kHardware: return 2;
        case SystemErrorClass::kOperation: return 1;
        case SystemErrorClass::kNone: break;
    }
    return 0;
}

const AutomaticScript& CheckedScript(const AutomaticScript& script) {
    if (script.startedCycles < 0 || script.stopProgramCycles < 0 || script.startAfterStopCycles < 0 ||
        script.malfunctionProgramCycles < 0) {
        throw std::invalid_argument("ModeMachine: the AUTOMATIC script's cycle counts must be >= 0");
    }
    return script;
}

}  // namespace

SystemErrorClass ClassOfSystemError(std::uint16_t number) {
    if (number == 0) return SystemErrorClass::kNone;
    if (number <= 99) return SystemErrorClass::kCpu;
    if (number >= 500 && number <= 999) return SystemErrorClass::kOperation;
    return SystemErrorClass::kHardware;
}

ModeMachine::ModeMachine(ControllerState& state, ModeMachineOptions options)
    : state_(state), options_(options) {
    CheckedScript(options_.automatic);
}

bool ModeMachine::Ready() const {
    return Status() != status::kNotInitialized && ClassOfSystemError(SystemError()) != SystemErrorClass::kCpu;
}

bool ModeMachine::Transitional() const {
    switch (Status()) {
        case status::kAutoStarted:
        case status::kAutoStopRecognized:
        case status::kAutoStopProgram:
        case status::kAutoStartAfterStop:
        case status::kAutoMalfunctionRecognized:
        case status::kAutoMalfunctionProgram:
        case status::kOnlineStarted:
        case status::kOnlineStopRecognized:
        case status::kOnlineMalfunctionRecognized:
            return true;
        default:
            return false;
    }
}

ModeRequestResult ModeMachine::StartOnline(std::chrono::nanoseconds /*now*/) {
    const std::uint8_t s = Status();
    const bool resume = s == status::kOnlineStopped || s == status::kOnlineStoppedMalfunction;
    if (!IsHome(s) && !resume) return ModeRequestResult::kNotInThisStatus;
    if (SystemError() != 0) return ModeRequestResult::kSystemErrorPending;
    if (options_.requireExternalStop && !ExternalStopPowered()) return ModeRequestResult::kNoExternalStop;
    if (resume) {
        Enter(status::kOnline);  // the ONLINE session goes on: speeds and format stay
    } else {
        state_.axes.ApplyParametersToAll();
        state_.integerFormat = integerRequested_;  // 2.5.3: taken over on entering ONLINE
        Enter(status::kOnlineStarted);
    }
    Advance();
    return ModeRequestResult::kAccepted;
}

ModeRequestResult ModeMachine::StartAutomatic(std::chrono::nanoseconds /*now*/) {
    const std::uint8_t s = Status();
    const bool resume = s == status::kAutoStopped || s == status::kAutoStoppedMalfunction;
    if (!IsHome(s) && !resume) return ModeRequestResult::kNotInThisStatus;
    if (SystemError() != 0) return ModeRequestResult::kSystemErrorPending;
    if (resume) {
        Enter(status::kAutoStartAfterStop);  // 5.2.1.1: continued from the stopped place
    } else {
        state_.integerFormat = integerRequested_;  // 2.5.3: taken over on entering AUTOMATIC
        Enter(status::kAutoStarted);
    }
    Advance();
    return ModeRequestResult::kAccepted;
}

ModeRequestResult ModeMachine::Stop(std::chrono::nanoseconds now) {
    const std::uint8_t s = Status();
    if (OnlineRunning(s) || AutomaticRunning(s)) {
        BeginStop(now);
        return ModeRequestResult::kAccepted;
    }
    switch (s) {
        case status::kAutoStopRecognized:
        case status::kAutoStopProgram:
        case status::kAutoStopped:
        case status::kAutoMalfunctionRecognized:
        case status::kAutoMalfunctionProgram:
        case status::kAutoStoppedMalfunction:
        case status::kOnlineStopRecognized:
        case status::kOnlineStopped:
        case status::kOnlineMalfunctionRecognized:
        case status::kOnlineStoppedMalfunction:
            // Stopping or stopped already: nothing more to do, but the machine goes on by itself.
            held_ = false;
            Advance();
            return ModeRequestResult::kAccepted;
        default:
            return ModeRequestResult::kNotInThisStatus;
    }
}

ModeRequestResult ModeMachine::Cancel(std::chrono::nanoseconds now) {
    const Mode mode = ModeOf(Status());
    if (mode != Mode::kOnline && mode != Mode::kAutomatic) return ModeRequestResult::kNotInThisStatus;
    // 5.2.5.1 / 5.2.6.1: positioning stopped, the current position taken over; ONLINE speed
    // changes end (5.2.6.8).
    state_.axes.HaltAll(now);
    state_.axes.ApplyParametersToAll();
    EnterHome();
    return ModeRequestResult::kAccepted;
}

ModeRequestResult ModeMachine::ResetError() {
    if (!IsHome(Status())) return ModeRequestResult::kNotInThisStatus;
    if (ClassOfSystemError(SystemError()) == SystemErrorClass::kCpu) return ModeRequestResult::kCpuError;
    state_.systemError = 0;
    Enter(status::kHome);
    return ModeRequestResult::kAccepted;
}

void ModeMachine::Step(std::chrono::nanoseconds now) {
    if (!held_) ++cyclesInStatus_;
    for (std::uint16_t number : raised_) ApplySystemError(number, now);
    raised_.clear();
    if (held_) return;
    if (options_.requireExternalStop && OnlineRunning(Status()) && !ExternalStopPowered()) {
        BeginStop(now);  // the external stop acts like a stop (decision, docs/sim_modes.md)
    }
    Advance();
}

void ModeMachine::EmergencyStop(std::chrono::nanoseconds now) {
    state_.axes.HaltAll(now);
    switch (ModeOf(Status())) {
        case Mode::kOnline: Enter(status::kOnlineStoppedMalfunction); break;
        case Mode::kAutomatic: Enter(status::kAutoStoppedMalfunction); break;
        default: break;
    }
}

void ModeMachine::PowerOff() {
    state_.operatingStatus = status::kNotInitialized;
    state_.systemError = 0;
    state_.integerFormat = false;
    integerRequested_ = false;
    held_ = false;
    cyclesInStatus_ = 0;
    raised_.clear();
}

void ModeMachine::Boot() {
    // PowerOff() cleared the error number; one set by SetSystemError() meanwhile stays as it is.
    if (Status() == status::kNotInitialized) Enter(status::kHome);
}

void ModeMachine::RaiseSystemError(std::uint16_t number) {
    if (number == 0 || number > 999) {
        throw std::invalid_argument("ModeMachine::RaiseSystemError: number must be 1..999 (the classes of 5.2.4.15)");
    }
    raised_.push_back(number);
}

void ModeMachine::Force(std::uint8_t s) {
    state_.operatingStatus = s;
    held_ = true;
    cyclesInStatus_ = 0;
}

void ModeMachine::Enter(std::uint8_t s) {
    state_.operatingStatus = s;
    held_ = false;
    cyclesInStatus_ = 0;
}

void ModeMachine::EnterHome() {
    // 5.2.4.15: errors 500..999 are reset on returning to home position; others stay (status 9).
    if (ClassOfSystemError(SystemError()) == SystemErrorClass::kOperation) state_.systemError = 0;
    Enter(SystemError() != 0 ? status::kHomeWithSystemError : status::kHome);
}

void ModeMachine::BeginStop(std::chrono::nanoseconds now) {
    // 5.2.1.1: running positionings are stopped (braking); "stopped" once all axes stand.
    state_.axes.StopAll(now);
    Enter(ModeOf(Status()) == Mode::kOnline ? status::kOnlineStopRecognized : status::kAutoStopRecognized);
    Advance();
}

void ModeMachine::ApplySystemError(std::uint16_t number, std::chrono::nanoseconds now) {
    if (Severity(ClassOfSystemError(number)) >= Severity(ClassOfSystemError(SystemError()))) {
        state_.systemError = number;
    }
    const std::uint8_t s = Status();
    if (IsHome(s)) {
        Enter(status::kHomeWithSystemError);
    } else if (OnlineRunning(s) || s == status::kOnlineStopRecognized || s == status::kOnlineStopped) {
        state_.axes.StopAll(now);
        Enter(status::kOnlineMalfunctionRecognized);
    } else if (ModeOf(s) == Mode::kAutomatic && s != status::kAutoMalfunctionRecognized &&
               s != status::kAutoMalfunctionProgram && s != status::kAutoStoppedMalfunction) {
        state_.axes.StopAll(now);
        Enter(status::kAutoMalfunctionRecognized);
    }
    // Malfunction statuses already, manual mode: the number alone changes.
}

void ModeMachine::Advance() {
    const AutomaticScript& script = options_.automatic;
    // Each pass leaves one status for the next; the chain ends in a status that stays (11, 15, 19,
    // 31, 35, 39) or in one still waiting, so a few passes always suffice.
    for (int pass = 0; pass < 8; ++pass) {
        switch (Status()) {
            case status::kAutoStarted:
                if (!CycleCountReached(script.startedCycles)) return;
                Enter(status::kAuto);
                break;
            case status::kAutoStopRecognized:
                if (state_.axes.AnyMoving()) return;
                Enter(status::kAutoStopProgram);
                break;
            case status::kAutoStopProgram:
                if (!CycleCountReached(script.stopProgramCycles)) return;
                Enter(status::kAutoStopped);
                break;
            case status::kAutoStartAfterStop:
                if (!CycleCountReached(script.startAfterStopCycles)) return;
                Enter(status::kAuto);
                break;
            case status::kAutoMalfunctionRecognized:
                if (state_.axes.AnyMoving()) return;
                Enter(status::kAutoMalfunctionProgram);
                break;
            case status::kAutoMalfunctionProgram:
                if (!CycleCountReached(script.malfunctionProgramCycles)) return;
                Enter(status::kAutoStoppedMalfunction);
                break;
            case status::kOnlineStarted:
                if (!CycleCountReached(1)) return;
                Enter(status::kOnline);
                break;
            case status::kOnlineStopRecognized:
                if (state_.axes.AnyMoving()) return;
                Enter(status::kOnlineStopped);
                break;
            case status::kOnlineMalfunctionRecognized:
                if (state_.axes.AnyMoving()) return;
                Enter(status::kOnlineStoppedMalfunction);
                break;
            default:
                return;
        }
    }
}

bool ModeMachine::ExternalStopPowered() const {
    const auto input = state_.systemParameters.IntValue(sysparam::kStopInput).value_or(0);
    const BitBank& inputs = state_.elements.inputs;
    return input != 0 && inputs.Contains(static_cast<int>(input)) && inputs.Get(static_cast<int>(input));
}

}  // namespace pac::sim
