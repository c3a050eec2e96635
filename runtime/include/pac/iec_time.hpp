// The IEC TIME type of the selected ST compiler's C interface (pacst's pacst_iec.h, or MATIEC's
// iec_types_all.h when PAC_ST_MATIEC is defined), the declarations of the two C globals that
// interface requires, and conversions between TIME and std::chrono.
#pragma once

#include <chrono>
#include <cstdint>

#ifdef PAC_ST_MATIEC
extern "C" {
#include "iec_types_all.h"
// MATIEC declares these in iec_std_lib.h, which carries the whole function library; the clock only
// needs the types, so the declarations are repeated here with the C linkage of the generated code.
extern TIME __CURRENT_TIME;
extern BOOL __DEBUG;
}
#else
#include "pacst_iec.h"  // declares __CURRENT_TIME and __DEBUG itself
#endif

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
    // The member types differ between interfaces (long/long here, int64/int32 in newer MATIEC).
    out.tv_sec = static_cast<decltype(out.tv_sec)>(sec);
    out.tv_nsec = static_cast<decltype(out.tv_nsec)>(nsec);
    return out;
}

inline std::chrono::nanoseconds FromIecTime(const TIME& t) {
    return std::chrono::seconds(t.tv_sec) + std::chrono::nanoseconds(t.tv_nsec);
}

}  // namespace pac
