// What MATIEC (iec2c 6bb2c33, the reference compiler) computes differently from IEC 61131-3 and from
// pacst, measured by the conformance suite on the matiec preset (docs/translator.md, "Where MATIEC
// differs"). The tests expect pacst's exact results and, on the MATIEC backend, these deviations and
// nothing looser. The library keeps clear of all of them.
#pragma once

#include <chrono>

namespace pac::test {

#ifdef PAC_ST_MATIEC
constexpr bool kMatiecBackend = true;
#else
constexpr bool kMatiecBackend = false;
#endif

// MATIEC converts a TIME literal through a double of seconds and truncates to whole nanoseconds, so a
// literal whose milliseconds are no binary fraction comes out short: T#4MS is 3 999 999 ns there.
constexpr std::chrono::nanoseconds kTimeLiteralShortfall{kMatiecBackend ? 1 : 0};

}  // namespace pac::test
