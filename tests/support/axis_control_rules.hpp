// The rule every axis module's control word keeps in every scan (manual 2.7.3, 2.7.4.14: two traverse
// bits, or Start without one, are CMD error 20): at most one traverse bit, and Start only with exactly
// one. The caller passes its bit masks, so the rule serves the scripted axis module and the simulated
// PA-CONTROL alike.
#pragma once

#include <bitset>
#include <cstdint>

namespace pac::test {

// nullptr if `control` keeps the rule, else what it breaks.
inline const char* AxisControlWordViolation(std::uint32_t control, std::uint32_t traverseBits, std::uint32_t start) {
    const auto traverse = std::bitset<32>(control & traverseBits).count();
    if (traverse > 1) return "two traverse bits";
    if ((control & start) != 0 && traverse != 1) return "Start without exactly one traverse bit";
    return nullptr;
}

}  // namespace pac::test
