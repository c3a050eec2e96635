// Simulated times as test messages, logs and timelines print them: "12", "12.5", "0.000001"
// milliseconds, exact to the nanosecond (cycle times below 1 ms are common), no trailing zeros.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace pac {

inline std::string FormatMsNumber(std::chrono::nanoseconds t) {
    constexpr std::int64_t kNsPerMs = 1'000'000;
    const std::int64_t ns = t.count();
    const std::uint64_t magnitude = ns < 0 ? 0 - static_cast<std::uint64_t>(ns) : static_cast<std::uint64_t>(ns);
    std::string text = (ns < 0 ? "-" : "") + std::to_string(magnitude / kNsPerMs);
    if (const std::uint64_t frac = magnitude % kNsPerMs; frac != 0) {
        std::string digits = std::to_string(frac);
        digits.insert(0, 6 - digits.size(), '0');
        digits.erase(digits.find_last_not_of('0') + 1);
        text += '.' + digits;
    }
    return text;
}

inline std::string FormatMs(std::chrono::nanoseconds t) { return FormatMsNumber(t) + " ms"; }

}  // namespace pac
