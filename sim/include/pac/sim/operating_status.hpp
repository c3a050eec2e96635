// Operating statuses of the PA-CONTROL (manual 2.4.2 and 6.4). The status byte holds these DECIMAL
// codes (ONLINE = 31 = 16#1F; docs/manual_errata.md). Mode groups the codes the way the validity tables of 5.1 do.
#pragma once

#include <cstdint>
#include <initializer_list>

namespace pac::sim {

namespace status {
constexpr std::uint8_t kNotInitialized = 0;  // no communication possible (before boot)
constexpr std::uint8_t kHome = 1;
constexpr std::uint8_t kManualPanel = 2;
constexpr std::uint8_t kManualPanelMoving = 3;
constexpr std::uint8_t kHomeWithSystemError = 9;
constexpr std::uint8_t kAutoStarted = 10;
constexpr std::uint8_t kAuto = 11;
constexpr std::uint8_t kAutoStopRecognized = 12;
constexpr std::uint8_t kAutoStopProgram = 13;
constexpr std::uint8_t kAutoStopped = 15;
constexpr std::uint8_t kAutoStartAfterStop = 16;
constexpr std::uint8_t kAutoMalfunctionRecognized = 17;
constexpr std::uint8_t kAutoMalfunctionProgram = 18;
constexpr std::uint8_t kAutoStoppedMalfunction = 19;
constexpr std::uint8_t kManualSerial = 20;
constexpr std::uint8_t kOnlineStarted = 30;
constexpr std::uint8_t kOnline = 31;
constexpr std::uint8_t kOnlineStopRecognized = 32;
constexpr std::uint8_t kOnlineStopped = 35;
constexpr std::uint8_t kOnlineMalfunctionRecognized = 37;
constexpr std::uint8_t kOnlineStoppedMalfunction = 39;
}  // namespace status

// The columns of the validity tables in 5.1.
enum class Mode : std::uint8_t {
    kNotReady = 0,   // status 0 and codes above 39
    kHome = 1,       // 1, 9
    kManual = 2,     // 2..8, 20..29
    kAutomatic = 4,  // 10..19
    kOnline = 8,     // 30..39
};

Mode ModeOf(std::uint8_t operatingStatus);
const char* ToString(Mode mode);

// A set of modes, for the validity of a command.
class ModeSet {
public:
    constexpr ModeSet() = default;
    constexpr ModeSet(std::initializer_list<Mode> modes) {
        for (Mode m : modes) bits_ |= static_cast<std::uint8_t>(m);
    }
    static constexpr ModeSet All() { return ModeSet{Mode::kHome, Mode::kManual, Mode::kAutomatic, Mode::kOnline}; }
    constexpr bool Contains(Mode mode) const { return (bits_ & static_cast<std::uint8_t>(mode)) != 0; }

private:
    std::uint8_t bits_ = 0;
};

}  // namespace pac::sim
