// The test vocabulary's FUNCTIONs (tools/pactest/st), implemented by the host: pacst --user --native gives
// each call the ST file and line of the call (docs/user_tests.md#the-test-vocabulary). Their ST bodies are
// what a PLC runs; these record into the host's result instead.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>

#include "POUS.h"
#include "pactest_host.hpp"

namespace {

std::string Text(const STRING& s) {
    return std::string(reinterpret_cast<const char*>(s.body), s.len < STR_MAX_LEN ? s.len : STR_MAX_LEN);
}

// a WSTRING's UCS-2 code units as UTF-8, as the failure message is printed
std::string WideText(const WSTRING& s) {
    std::string text;
    for (int i = 0; i < s.len && i < STR_MAX_LEN; ++i) {
        const unsigned unit = s.body[i];
        if (unit < 0x80U) {
            text += static_cast<char>(unit);
        } else if (unit < 0x800U) {
            text += static_cast<char>(0xC0U | (unit >> 6U));
            text += static_cast<char>(0x80U | (unit & 0x3FU));
        } else {
            text += static_cast<char>(0xE0U | (unit >> 12U));
            text += static_cast<char>(0x80U | ((unit >> 6U) & 0x3FU));
            text += static_cast<char>(0x80U | (unit & 0x3FU));
        }
    }
    return text;
}

template <class T>
std::string Number(const char* format, T value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

std::string TimeText(const TIME& t) {
    const double ms = static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
    return Number("T#%gMS", ms);
}

// LTIME is unsigned, up to LTIME#213503D23H34M33S709MS551US615NS (2^64 - 1 ns): counted in 64 unsigned bits
std::string LongTimeText(const TIME& t) {
    const unsigned long long ns = static_cast<unsigned long long>(t.tv_sec) * 1000000000ULL +
                                  static_cast<unsigned long long>(t.tv_nsec);
    return Number("LTIME#%lluNS", ns);
}

// DATE and DATE_AND_TIME: seconds since 1970-01-01 (UTC); TIME_OF_DAY: milliseconds since midnight
std::string DateAndTimeText(UDINT seconds) {
    const std::time_t t = static_cast<std::time_t>(seconds);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buffer[40];
    std::strftime(buffer, sizeof buffer, "DT#%Y-%m-%d-%H:%M:%S", &tm);
    return buffer;
}

std::string DateText(UDINT seconds) {
    return "D#" + DateAndTimeText(seconds).substr(3, 10);
}

std::string TimeOfDayText(UDINT ms) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "TOD#%02u:%02u:%02u.%03u", ms / 3600000U, ms / 60000U % 60U, ms / 1000U % 60U,
                  ms % 1000U);
    return buffer;
}

BOOL Equals(const char* file, int line, bool passed, const std::string& expected, const std::string& actual,
            const STRING& message) {
    pactest::RecordAssert(file, line, passed, Text(message) + ": expected " + expected + ", got " + actual);
    return passed ? TRUE : FALSE;
}

void Ok(BOOL* eno) {
    if (eno) *eno = TRUE;
}

// TIME and LTIME: pacst's C keeps both as seconds and nanoseconds
bool operator==(const TIME& a, const TIME& b) {
    return a.tv_sec == b.tv_sec && a.tv_nsec == b.tv_nsec;
}

}  // namespace

extern "C" {

BOOL ASSERTTRUE(const char* file__, int line__, BOOL EN, BOOL* __ENO, BOOL CONDITION, STRING MESSAGE) {
    (void)EN;
    Ok(__ENO);
    // FB_AssertWithin fails through here, with its own message; the frame above its body is the user's test
    // (frame pointers kept), whose line pac-test prints.
    const bool wait = std::strstr(file__, "FB_AssertWithin") != nullptr;
    pactest::RecordAssert(file__, line__, CONDITION != 0, Text(MESSAGE) + (wait ? "" : ": expected TRUE, got FALSE"),
                          __builtin_return_address(1));
    return CONDITION;
}

BOOL ASSERTFALSE(const char* file__, int line__, BOOL EN, BOOL* __ENO, BOOL CONDITION, STRING MESSAGE) {
    (void)EN;
    Ok(__ENO);
    pactest::RecordAssert(file__, line__, CONDITION == 0, Text(MESSAGE) + ": expected FALSE, got TRUE");
    return CONDITION ? FALSE : TRUE;
}

#define PACTEST_EQUALS(NAME, TYPE, FORMAT, CAST)                                                              \
    BOOL NAME(const char* file__, int line__, BOOL EN, BOOL* __ENO, TYPE EXPECTED, TYPE ACTUAL, STRING MESSAGE) { \
        (void)EN;                                                                                             \
        Ok(__ENO);                                                                                            \
        return Equals(file__, line__, EXPECTED == ACTUAL, Number(FORMAT, CAST(EXPECTED)),                     \
                      Number(FORMAT, CAST(ACTUAL)), MESSAGE);                                                 \
    }

PACTEST_EQUALS(ASSERTEQUALS_BOOL, BOOL, "%s", [](BOOL b) { return b ? "TRUE" : "FALSE"; })
PACTEST_EQUALS(ASSERTEQUALS_INT, INT, "%d", static_cast<int>)
PACTEST_EQUALS(ASSERTEQUALS_DINT, DINT, "%ld", static_cast<long>)
PACTEST_EQUALS(ASSERTEQUALS_UINT, UINT, "%u", static_cast<unsigned>)
PACTEST_EQUALS(ASSERTEQUALS_SINT, SINT, "%d", static_cast<int>)
PACTEST_EQUALS(ASSERTEQUALS_USINT, USINT, "%u", static_cast<unsigned>)
PACTEST_EQUALS(ASSERTEQUALS_UDINT, UDINT, "%lu", static_cast<unsigned long>)
PACTEST_EQUALS(ASSERTEQUALS_BYTE, BYTE, "16#%02X", static_cast<unsigned>)
PACTEST_EQUALS(ASSERTEQUALS_WORD, WORD, "16#%04X", static_cast<unsigned>)
PACTEST_EQUALS(ASSERTEQUALS_DWORD, DWORD, "16#%08lX", static_cast<unsigned long>)
// TcUnit's asserts beyond the vocabulary's (tools/pactest/tcunit): the 64-bit types, the dates, WSTRING
PACTEST_EQUALS(ASSERTEQUALS_LINT, LINT, "%lld", static_cast<long long>)
PACTEST_EQUALS(ASSERTEQUALS_ULINT, ULINT, "%llu", static_cast<unsigned long long>)
PACTEST_EQUALS(ASSERTEQUALS_LWORD, LWORD, "16#%016llX", static_cast<unsigned long long>)

#define PACTEST_EQUALS_TEXT(NAME, TYPE, TEXT)                                                                 \
    BOOL NAME(const char* file__, int line__, BOOL EN, BOOL* __ENO, TYPE EXPECTED, TYPE ACTUAL, STRING MESSAGE) { \
        (void)EN;                                                                                             \
        Ok(__ENO);                                                                                            \
        return Equals(file__, line__, EXPECTED == ACTUAL, TEXT(EXPECTED), TEXT(ACTUAL), MESSAGE);             \
    }

PACTEST_EQUALS_TEXT(ASSERTEQUALS_DATE, UDINT, DateText)
PACTEST_EQUALS_TEXT(ASSERTEQUALS_DATE_AND_TIME, UDINT, DateAndTimeText)
PACTEST_EQUALS_TEXT(ASSERTEQUALS_TIME_OF_DAY, UDINT, TimeOfDayText)

PACTEST_EQUALS_TEXT(ASSERTEQUALS_TIME, TIME, TimeText)
PACTEST_EQUALS_TEXT(ASSERTEQUALS_LTIME, TIME, LongTimeText)

BOOL ASSERTEQUALS_WSTRING(const char* file__, int line__, BOOL EN, BOOL* __ENO, WSTRING EXPECTED, WSTRING ACTUAL,
                          STRING MESSAGE) {
    (void)EN;
    Ok(__ENO);
    return Equals(file__, line__, __pacst_wstring_eq(EXPECTED, ACTUAL) != 0, "\"" + WideText(EXPECTED) + "\"",
                  "\"" + WideText(ACTUAL) + "\"", MESSAGE);
}

BOOL IS_TEST_FINISHED(const char*, int, BOOL, BOOL* __ENO, STRING TESTNAME) {
    Ok(__ENO);
    return pactest::TestFinished(Text(TESTNAME)) ? TRUE : FALSE;
}

BOOL ASSERTEQUALS_STRING(const char* file__, int line__, BOOL EN, BOOL* __ENO, STRING EXPECTED, STRING ACTUAL,
                         STRING MESSAGE) {
    (void)EN;
    Ok(__ENO);
    return Equals(file__, line__, Text(EXPECTED) == Text(ACTUAL), "'" + Text(EXPECTED) + "'",
                  "'" + Text(ACTUAL) + "'", MESSAGE);
}

BOOL ASSERTEQUALS_REAL(const char* file__, int line__, BOOL EN, BOOL* __ENO, REAL EXPECTED, REAL ACTUAL, REAL DELTA,
                       STRING MESSAGE) {
    (void)EN;
    Ok(__ENO);
    const bool passed = std::fabs(ACTUAL - EXPECTED) <= DELTA;
    return Equals(file__, line__, passed, Number("%g", EXPECTED) + " +/- " + Number("%g", DELTA),
                  Number("%g", ACTUAL), MESSAGE);
}

BOOL ASSERTEQUALS_LREAL(const char* file__, int line__, BOOL EN, BOOL* __ENO, LREAL EXPECTED, LREAL ACTUAL,
                        LREAL DELTA, STRING MESSAGE) {
    (void)EN;
    Ok(__ENO);
    const bool passed = std::fabs(ACTUAL - EXPECTED) <= DELTA;
    return Equals(file__, line__, passed, Number("%.15g", EXPECTED) + " +/- " + Number("%g", DELTA),
                  Number("%.15g", ACTUAL), MESSAGE);
}

BOOL TEST_FINISHED(const char* file__, int line__, BOOL EN, BOOL* __ENO) {
    (void)file__;
    (void)line__;
    (void)EN;
    Ok(__ENO);
    pactest::RecordFinished();
    return TRUE;
}

// Tc2_System's F_GetSystemTime: 100 ns since 1 January 1601 (UTC); the simulated clock starts at power-on at
// 1 January 2026 00:00 UTC (tools/pactest/vendor/Tc2_System/F_GetSystemTime.st).
ULINT F_GETSYSTEMTIME(const char*, int, BOOL, BOOL* __ENO) {
    Ok(__ENO);
    // 1601 to 1970: 11644473600 s; 1970 to 2026: 1767225600 s; in 100 ns
    constexpr ULINT k1601To2026 = 134116992000000000ULL;
    return k1601To2026 + static_cast<ULINT>(pactest::Now().count() / 100);
}

// TwinCAT_SystemInfoVarList._TaskInfo (tools/pactest/vendor/Tc2_System/PacTestTaskInfo.st): the running task's
// cycle in 100 ns and the cycles it has run
UDINT PACTESTTASKCYCLETIME(const char*, int, BOOL, BOOL* __ENO) {
    Ok(__ENO);
    return static_cast<UDINT>(pactest::TaskCycle().count() * 10000);
}

UDINT PACTESTTASKCYCLES(const char*, int, BOOL, BOOL* __ENO) {
    Ok(__ENO);
    return static_cast<UDINT>(pactest::TaskCycles());
}

BOOL TEST(const char*, int, BOOL, BOOL* __ENO, STRING TESTNAME) {
    Ok(__ENO);
    pactest::RecordTest(Text(TESTNAME));
    return TRUE;
}

BOOL TEST_ORDERED(const char*, int, BOOL, BOOL* __ENO, STRING TESTNAME) {
    Ok(__ENO);
    return pactest::RecordTestOrdered(Text(TESTNAME)) ? TRUE : FALSE;
}

BOOL TEST_FINISHED_NAMED(const char*, int, BOOL, BOOL* __ENO, STRING TESTNAME) {
    Ok(__ENO);
    pactest::RecordTestFinished(Text(TESTNAME));
    return TRUE;
}

BOOL PACTESTRECORD(const char* file__, int line__, BOOL EN, BOOL* __ENO, BOOL PASSED, STRING MESSAGE) {
    (void)EN;
    Ok(__ENO);
    // TcUnit's AssertArrayEquals_ (ST) record through here: the frame above theirs is the user's test, whose
    // line pac-test prints (a call from the user's own code is printed at its own line)
    pactest::RecordAssert(file__, line__, PASSED != 0, Text(MESSAGE), __builtin_return_address(1));
    return PASSED;
}

}  // extern "C"
