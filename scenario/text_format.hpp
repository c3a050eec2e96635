// How the scenario program writes numbers for PLC programmers: WORDs and DWORDs as IEC hex literals
// (16#0906, 16#0000014D), REALs in their shortest exact form (640.0, 0.1), error IDs as the manual
// and GVL_PAC write them (38, 16#8003), and the library's error texts (F_PAC_ErrorText).
#pragma once

#include <cstdint>
#include <string>

#include "scenario.hpp"

namespace pac::scenario {

std::string Hex4(std::uint16_t value);  // 16#0906
std::string Hex8(std::uint32_t value);  // 16#0000014D
std::string RealText(float value);      // 640.0, 0.1, -1.5E-07, NaN
// 333 (16#0000014D); as a REAL: 640.0 (16#44200000); negative DINTs also signed: -1 (16#FFFFFFFF).
std::string DwordText(std::uint32_t bits, bool asReal);
inline std::string DwordText(const DwordValue& value) { return DwordText(value.bits, value.isReal); }
// PA-CONTROL numbers in decimal (38), the library's codes (16#8000 and up) in hex (16#8003).
std::string ErrorIdText(std::uint16_t errorId);
// F_PAC_ErrorText of the library: "inadmissible N register".
std::string ErrorText(std::uint16_t errorId);
// A position field of an axis module (2.7.7, 2.7.8): IEEE REAL, or DINT x 1000 in integer format (2.5.3).
double PositionValue(std::uint32_t bits, bool integerMode);

}  // namespace pac::scenario
