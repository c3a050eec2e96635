// The IEC TIME type of the generated code's C interface (pacst_iec.h, laid out as MATIEC's TIME), the
// declarations of the two C globals that interface requires, and conversions between TIME and std::chrono.
#pragma once

#include <chrono>
#include <cstdint>

#include "pacst_iec.h"  // declares __CURRENT_TIME and __DEBUG

namespace pac {

// Normalised like the generated code expects: tv_nsec in [0, 1e9), tv_sec carrying the sign.
inline TIME ToIecTime(std::chrono::nanoseconds t) {
    constexpr std::int64_t kNsPerSec = 1'000'000'000;
    std::int64_t sec = t.count() / kNsPerSec;
    std::int64_t nsec = t.count() % kNsPerSec;
    if (nsec < 0) {  // C++ division truncates toward zero
        nsec += kNsPerSec;
        --sec;
    }
    TIME out{};
    out.tv_sec = static_cast<decltype(out.tv_sec)>(sec);
    out.tv_nsec = static_cast<decltype(out.tv_nsec)>(nsec);
    return out;
}

inline std::chrono::nanoseconds FromIecTime(const TIME& t) {
    return std::chrono::seconds(t.tv_sec) + std::chrono::nanoseconds(t.tv_nsec);
}

}  // namespace pac
