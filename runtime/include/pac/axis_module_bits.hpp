// The bits of the axis module's control and status words (manual 2.7.1 / 2.7.2), named as the library
// names the jobs (E_PAC_AxisCommand: PAC_AX_SET_POSITION is kSetPosition ...). The manual prints "G29"
// for both bits 4 and 5; by the order of 2.7.3.4 / 2.7.3.5 bit 4 is G26 and bit 5 G29 (docs/manual_errata.md).
// The simulated controller and the tests' scripted fake share these numbers and nothing else.
#pragma once

#include <cstdint>

namespace pac {

// Control word of the axis, PLC -> PA-CONTROL, bytes 0..3 (2.7.1). Bits 18..31 are reserve.
namespace axis_control {
constexpr std::uint32_t kAxisOn = 1U << 0;                 // Axis ON
constexpr std::uint32_t kDisableDrive = 1U << 1;           // Disable DRIVE (G140 / G141)
constexpr std::uint32_t kStart = 1U << 2;                  // Start command
constexpr std::uint32_t kHome = 1U << 3;                   // G25 (approach to reference point)
constexpr std::uint32_t kSetReferenced = 1U << 4;          // G26, set axis to position and reference
constexpr std::uint32_t kSetPosition = 1U << 5;            // G29, set axis to position
constexpr std::uint32_t kMoveAbsolute = 1U << 6;           // Absolute traversing (position)
constexpr std::uint32_t kMoveRelative = 1U << 7;           // Relative traversing (position)
constexpr std::uint32_t kWhileInput1 = 1U << 8;            // Traversing as long as input is "1" (G123 Ix..1)
constexpr std::uint32_t kWhileInput0 = 1U << 9;            // Traversing as long as input is "0" (G123 Ix..0)
constexpr std::uint32_t kJogPositive = 1U << 10;           // Traversing section in positive direction (jog)
constexpr std::uint32_t kJogNegative = 1U << 11;           // Traversing section in negative direction (jog)
constexpr std::uint32_t kClearOffset = 1U << 12;           // Delete G29 offset(s)
constexpr std::uint32_t kClearDisplaced = 1U << 13;        // Reset flag and group flag "axis was moved in OFF"
constexpr std::uint32_t kMoveToMax = 1U << 14;             // Traverse up to max. traverse range
constexpr std::uint32_t kMoveToMin = 1U << 15;             // Traverse up to min. traverse range
constexpr std::uint32_t kResetAxisError = 1U << 16;        // Reset axis error
constexpr std::uint32_t kDisableLimitSwitches = 1U << 17;  // Disable monitoring of limit switches G142

// The jobs: exactly one of these goes with a Start edge (2.7.2 notes: several at once are a CMD error).
constexpr std::uint32_t kTraverseBits = kHome | kSetReferenced | kSetPosition | kMoveAbsolute | kMoveRelative |
                                        kJogPositive | kJogNegative | kClearOffset | kClearDisplaced |
                                        kMoveToMax | kMoveToMin;
}  // namespace axis_control

// Status word of the axis, PA-CONTROL -> PLC, bytes 0..3 (2.7.2). Bits 16..31 are reserve.
namespace axis_status {
constexpr std::uint32_t kDriveEnabled = 1U << 0;               // DRIVE ENABLED
constexpr std::uint32_t kHalt = 1U << 1;                       // HALT
constexpr std::uint32_t kDriveDisabled = 1U << 2;              // DRIVE DISABLED
constexpr std::uint32_t kSafe = 1U << 3;                       // SAFE
constexpr std::uint32_t kIdle = 1U << 4;                       // IDLE
constexpr std::uint32_t kDisabled = 1U << 5;                   // DISABLED
constexpr std::uint32_t kFault = 1U << 6;                      // FAULT
constexpr std::uint32_t kActive = 1U << 7;                     // ACTIVE
constexpr std::uint32_t kReferenced = 1U << 8;                 // Axis is referenced
constexpr std::uint32_t kNegativeLimitNotActuated = 1U << 9;   // State of negative limit switch ("0": actuated)
constexpr std::uint32_t kPositiveLimitNotActuated = 1U << 10;  // State of positive limit switch ("0": actuated)
constexpr std::uint32_t kStoppedByCondition = 1U << 11;        // Axis has been stopped by G123 action
constexpr std::uint32_t kDisplaced = 1U << 12;                 // Displaced too much in DRIVE-DISABLED state
constexpr std::uint32_t kGroupDisplaced = 1U << 13;            // One axis of the group displaced while disabled
constexpr std::uint32_t kCmdError = 1U << 14;                  // CMD error
constexpr std::uint32_t kAxisError = 1U << 15;                 // Axis error
}  // namespace axis_status

}  // namespace pac
