// The commands the simulated PA-CONTROL knows (manual 5.1, 5.2), with the operating modes each is
// valid in, and the command error numbers it answers with (6.5, with the corrections of docs/manual_errata.md:
// 16#25 is 37; the second 16#1D is 16#1E = 30; the second 16#2D is 16#2E = 46; 16#2F is 47).
#pragma once

#include <cstdint>
#include <vector>

#include "pac/sim/operating_status.hpp"

namespace pac::sim {

namespace code {
constexpr std::uint16_t kStop = 0x0600;
constexpr std::uint16_t kStartAuto = 0x0602;
constexpr std::uint16_t kStartOnline = 0x0603;
constexpr std::uint16_t kSetSystemParameter = 0x0700;
constexpr std::uint16_t kGetSystemParameter = 0x1700;
constexpr std::uint16_t kGetSystemParameterMax = 0x1701;
constexpr std::uint16_t kGetSystemParameterMin = 0x1702;
constexpr std::uint16_t kSetAxisParameter = 0x0800;
constexpr std::uint16_t kGetAxisParameter = 0x1800;
constexpr std::uint16_t kGetAxisParameterMax = 0x1801;
constexpr std::uint16_t kGetAxisParameterMin = 0x1802;
constexpr std::uint16_t kGetSingleInput = 0x1900;
constexpr std::uint16_t kGetInputWord = 0x1901;
constexpr std::uint16_t kPutSingleOutput = 0x0902;
constexpr std::uint16_t kGetSingleOutput = 0x1902;
constexpr std::uint16_t kPutOutputWord = 0x0903;
constexpr std::uint16_t kGetOutputWord = 0x1903;
constexpr std::uint16_t kPutSingleFlag = 0x0904;
constexpr std::uint16_t kGetSingleFlag = 0x1904;
constexpr std::uint16_t kPutFlagWord = 0x0905;
constexpr std::uint16_t kGetFlagWord = 0x1905;
constexpr std::uint16_t kPutIntReg = 0x0906;
constexpr std::uint16_t kGetIntReg = 0x1906;
constexpr std::uint16_t kPutFloatReg = 0x0907;
constexpr std::uint16_t kGetFloatReg = 0x1907;
constexpr std::uint16_t kResetError = 0x0909;
constexpr std::uint16_t kGetError = 0x1909;
constexpr std::uint16_t kGetState = 0x190B;
constexpr std::uint16_t kGetActualPos = 0x190C;
constexpr std::uint16_t kGetActualSpeed = 0x190D;
constexpr std::uint16_t kGetRotationControlPos = 0x190E;  // the overview repeats "190D" (docs/manual_errata.md)
constexpr std::uint16_t kGetMaxTowfault = 0x190F;         // overview only: 5.2.4.21 is missing
constexpr std::uint16_t kGetStatusAxis = 0x1910;
constexpr std::uint16_t kGetStatusAllAxis = 0x1911;
constexpr std::uint16_t kGetTraverseAreaMin = 0x1913;
constexpr std::uint16_t kGetTraverseAreaMax = 0x1914;
constexpr std::uint16_t kGetAxisFollowingError = 0x1915;
constexpr std::uint16_t kGetTemperature = 0x1920;
constexpr std::uint16_t kGetExtendedStatusAxis = 0x1921;
constexpr std::uint16_t kGetSystemFlag = 0x1934;  // the overview's "934"
constexpr std::uint16_t kGetSystemNReg = 0x1935;  // the overview's "935"
constexpr std::uint16_t kGetSystemRReg = 0x1937;  // the overview's "0937"
constexpr std::uint16_t kAbortAuto = 0x0A41;
constexpr std::uint16_t kAbortOnline = 0x0A81;
constexpr std::uint16_t kPutNoReference = 0x0A83;
constexpr std::uint16_t kPutStartReference = 0x0A84;
constexpr std::uint16_t kPutPositionNull = 0x0A85;
constexpr std::uint16_t kPutSetPosition = 0x0A86;
constexpr std::uint16_t kPosAxisAbsolute = 0x0A87;
constexpr std::uint16_t kPosAxisRelative = 0x0A89;
constexpr std::uint16_t kSetSpeedAxis = 0x0A8D;
constexpr std::uint16_t kSetAccelerationAxis = 0x0A8E;
constexpr std::uint16_t kStartManualAbsolute = 0x0A90;
constexpr std::uint16_t kStartManualRelative = 0x0A91;
constexpr std::uint16_t kControlMoveAxis = 0x0A92;
constexpr std::uint16_t kStopAxis = 0x0A93;
constexpr std::uint16_t kStartAxisAbsolute = 0x0A94;
constexpr std::uint16_t kStartAxisRelative = 0x0A95;
constexpr std::uint16_t kPutReferenceOnPosition = 0x0A96;
constexpr std::uint16_t kOnAxis = 0x0A97;
constexpr std::uint16_t kOffAxis = 0x0A98;
constexpr std::uint16_t kStopAxisMultiCmd = 0x0A9A;
constexpr std::uint16_t kSetMeasuringMode = 0x0AA0;
constexpr std::uint16_t kResetMeasuringMode = 0x0AA1;
constexpr std::uint16_t kPutLimitSwitchMonitoring = 0x0AA2;
constexpr std::uint16_t kPutConditionMoveAxis = 0x0AA3;
}  // namespace code

namespace error {
constexpr std::uint16_t kNone = 0;
constexpr std::uint16_t kUnknownCommand = 19;           // 16#13
constexpr std::uint16_t kInadmissibleCommand = 20;      // 16#14
constexpr std::uint16_t kNotExecutable = 21;            // 16#15
constexpr std::uint16_t kAxisNumberUnknown = 32;        // 16#20
constexpr std::uint16_t kAxisParameterUnknown = 33;     // 16#21
constexpr std::uint16_t kSystemParameterUnknown = 34;   // 16#22
constexpr std::uint16_t kInadmissibleInput = 35;        // 16#23
constexpr std::uint16_t kInadmissibleOutput = 36;       // 16#24
constexpr std::uint16_t kInadmissibleFlag = 37;         // 16#25 (the manual prints 36)
constexpr std::uint16_t kInadmissibleNRegister = 38;    // 16#26
constexpr std::uint16_t kInadmissibleRRegister = 39;    // 16#27
constexpr std::uint16_t kValueOutsideRange = 41;        // 16#29
constexpr std::uint16_t kAxisStillMoves = 42;           // 16#2A
constexpr std::uint16_t kNoReferencePoint = 43;         // 16#2B
constexpr std::uint16_t kExternalStopNotDefined = 44;   // 16#2C
constexpr std::uint16_t kAxisNotReady = 46;             // 16#2E (the manual prints a second 16#2D)
constexpr std::uint16_t kPositionOutsideRange = 65;     // 16#41
constexpr std::uint16_t kMeasuringModeNotAdmissible = 108;  // 16#6C: only with 0AA0 / 0AA1
}  // namespace error

struct CommandInfo {
    std::uint16_t code;
    const char* name;
    ModeSet validIn;
};

// nullptr for a code the simulator does not know (answered with error::kUnknownCommand).
const CommandInfo* FindCommand(std::uint16_t code);
const std::vector<CommandInfo>& SupportedCommands();

}  // namespace pac::sim
