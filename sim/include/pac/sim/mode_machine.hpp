// The operating-mode machine of the simulated PA-CONTROL (manual 2.4.2, 6.4, 5.2.1, 5.2.4.15, 5.2.5.1,
// 5.2.6.1): home position, ONLINE and a scripted stand-in for the AUTOMATIC program, with the system
// error classes. The CMD commands (CommandExecutor) and the CTRL interface (CtrlInterface) both ask it
// for a mode change; it alone writes the operating status, the system error number and the integer
// format in force. The transition table and every decision are in docs/sim_modes.md.
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

#include "pac/sim/controller_state.hpp"

namespace pac::sim {

// The error categories of 5.2.4.15, by number.
enum class SystemErrorClass : std::uint8_t {
    kNone = 0,       // 0
    kCpu = 1,        // 1..99: only a power cycle clears it
    kHardware = 2,   // 100..499 (and 1000..65535, which the manual does not classify): reset in home
    kOperation = 3,  // 500..999: cleared when ONLINE / AUTOMATIC return to home position
};
SystemErrorClass ClassOfSystemError(std::uint16_t number);

// How many controller cycles each step of the stand-in AUTOMATIC program takes (>= 0; 0: passed
// within the cycle that enters it). The program itself runs in 11 until it is stopped or cancelled.
struct AutomaticScript {
    int startedCycles = 1;             // 10 AUTOMATIC started -> 11
    int stopProgramCycles = 1;         // 13 STOP program -> 15
    int startAfterStopCycles = 1;      // 16 START-AFTER-STOP program -> 11
    int malfunctionProgramCycles = 1;  // 18 MALFUNCTION program -> 19
};

struct ModeMachineOptions {
    // 5.2.1.3: ONLINE needs an external stop input (system parameter 4) that has power.
    bool requireExternalStop = true;
    AutomaticScript automatic{};
};

// Why a request was not carried out. The CMD interface answers with a command error, the CTRL
// interface ignores the request.
enum class ModeRequestResult : std::uint8_t {
    kAccepted = 0,
    kNotInThisStatus,     // CMD error 20
    kSystemErrorPending,  // CMD error 21 (a start while a system error is pending)
    kNoExternalStop,      // CMD error 44
    kCpuError,            // CMD error 21 with the number as data (an error reset of class 1)
};

class ModeMachine {
public:
    // std::invalid_argument for a negative cycle count in options.automatic.
    ModeMachine(ControllerState& state, ModeMachineOptions options);

    std::uint8_t Status() const { return state_.operatingStatus; }
    std::uint16_t SystemError() const { return state_.systemError; }
    bool IntegerFormat() const { return state_.integerFormat; }
    // Booted and no CPU error (2.5.2 "Control ready").
    bool Ready() const;
    // A status the machine leaves by itself (10, 12, 13, 16, 17, 18, 30, 32, 37): a mode command
    // of the CMD interface ends (BF = 1) when the status is no longer transitional.
    bool Transitional() const;
    // Set by SetOperatingStatus() until the machine is moved by a request or an event.
    bool Held() const { return held_; }

    // ---- requests (CMD and CTRL alike) ----
    ModeRequestResult StartOnline(std::chrono::nanoseconds now);     // 0603, CTRL bit 4
    ModeRequestResult StartAutomatic(std::chrono::nanoseconds now);  // 0602, CTRL bit 3
    ModeRequestResult Stop(std::chrono::nanoseconds now);            // 0600, CTRL bit 1 low
    ModeRequestResult Cancel(std::chrono::nanoseconds now);          // 0A81 / 0A41, CTRL bit 2 low
    ModeRequestResult ResetError();                                  // 0909, CTRL bit 0 falling
    // The CTRL control word's bit 15, taken over when ONLINE or AUTOMATIC is entered from home.
    void SetRequestedIntegerFormat(bool integer) { integerRequested_ = integer; }

    // ---- the controller's cycle ----
    // Once per cycle, axes brought to `now`: system errors raised since the last cycle, the
    // external stop input in ONLINE, and the transitional statuses whose step is over.
    void Step(std::chrono::nanoseconds now);
    // 4.2.5: axes halt at once; ONLINE -> 39, AUTOMATIC -> 19; home and manual keep their status.
    void EmergencyStop(std::chrono::nanoseconds now);
    void PowerOff();  // status 0, no system error, float format, nothing pending
    void Boot();      // status 1, or the status set before the boot (held)

    // ---- test hooks ----
    // Noticed by the next Step(): the controller's reaction to a system error of the number's
    // class (1..999, std::invalid_argument otherwise).
    void RaiseSystemError(std::uint16_t number);
    // The status as is, held: no transition by itself until a request or an event moves it.
    void Force(std::uint8_t status);

private:
    void Enter(std::uint8_t status);
    void EnterHome();
    void BeginStop(std::chrono::nanoseconds now);
    void ApplySystemError(std::uint16_t number, std::chrono::nanoseconds now);
    void Advance();
    bool ExternalStopPowered() const;
    bool CycleCountReached(int cycles) const { return cyclesInStatus_ >= cycles; }

    ControllerState& state_;
    ModeMachineOptions options_;
    bool held_ = false;
    int cyclesInStatus_ = 0;
    bool integerRequested_ = false;
    std::vector<std::uint16_t> raised_;
};

}  // namespace pac::sim
