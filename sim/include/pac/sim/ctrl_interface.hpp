// The controller's side of the 8-byte CTRL module (manual 2.5): decodes the PLC's control word into
// requests to the ModeMachine and encodes the status word. Word 0 of each direction is the control /
// status word (big-endian, bytes 0-1 of the module); from the controller, word 2 is the system error
// number; every other word is 0 (words 1..3 to PAC are ignored).
// Control word: Stop (bit 1) and Cancel (bit 2) are low-active levels; the start bits (3, 4) act on
// their rising edge while Stop and Cancel are inactive (1); Error reset (bit 0, low-active) acts on
// its falling edge 1 -> 0. A request the controller cannot serve is ignored: the CTRL interface has no
// error channel. Before the first control word after a boot the bits count as idle (docs/sim_modes.md).
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>

#include "pac/sim/image8.hpp"
#include "pac/sim/mode_machine.hpp"

namespace pac::sim {

namespace ctrl {
// Control word, to PAC (2.5.1).
constexpr std::uint16_t kErrorReset = 1U << 0;  // low-active
constexpr std::uint16_t kStop = 1U << 1;        // low-active
constexpr std::uint16_t kCancel = 1U << 2;      // low-active
constexpr std::uint16_t kStartAutomatic = 1U << 3;
constexpr std::uint16_t kStartOnline = 1U << 4;
constexpr std::uint16_t kIntegerFormat = 1U << 15;
constexpr std::uint16_t kNoRequest = kErrorReset | kStop | kCancel;  // what a PLC holds outside a request

// Status word, from PAC (2.5.2).
constexpr std::uint16_t kReady = 1U << 0;
constexpr std::uint16_t kBatteryOk = 1U << 1;
constexpr std::uint16_t kSystemError = 1U << 2;
constexpr std::uint16_t kAutomaticActive = 1U << 8;
constexpr std::uint16_t kAutomaticStopped = 1U << 9;
constexpr std::uint16_t kOnlineActive = 1U << 10;
constexpr std::uint16_t kOnlineStopped = 1U << 11;
constexpr std::uint16_t kIntegerInForce = 1U << 15;

// The mode bits (8..11) of an operating status: AUTOMATIC active 11, 12, 13, 16, 17, 18; AUTOMATIC
// stopped 15, 19; ONLINE active 31, 32, 37; ONLINE stopped 35, 39; none otherwise (10 and 30 are
// transitional, home and manual have no mode bit).
std::uint16_t ModeBits(std::uint8_t operatingStatus);
}  // namespace ctrl

// How a stopped mode shows in the status word (2.5.2 lists "ONLINE stopped" and "ONLINE active" as two bits
// without saying whether a stopped ONLINE is still "active"; docs/open_points.md). Likewise AUTOMATIC.
enum class StoppedModeBits {
    kStoppedAlone,      // 35, 39: "ONLINE stopped" only; 15, 19: "AUTOMATIC stopped" only (default)
    kStoppedAndActive,  // the mode's "active" bit stays set while it is stopped
};

struct CtrlInterfaceConfig {
    StoppedModeBits stoppedModeBits = StoppedModeBits::kStoppedAlone;
};

class CtrlInterface {
public:
    CtrlInterface(ModeMachine& modes, const ControllerState& state, CtrlInterfaceConfig config = {})
        : modes_(modes), state_(state), config_(config) {}

    // One controller cycle with the PLC's CTRL module (not called for an all-zero to-PAC image,
    // which is an emergency stop, not a control word).
    void Apply(const Image8& module, std::chrono::nanoseconds now);
    // Power off: the next control word is a new reference for the edges.
    void Reset() { previous_.reset(); }

    std::uint16_t StatusWord() const;
    Image8 Reply() const;  // status word, 0, system error number, 0

private:
    ModeMachine& modes_;
    const ControllerState& state_;  // battery
    CtrlInterfaceConfig config_;
    std::optional<std::uint16_t> previous_;
};

}  // namespace pac::sim
