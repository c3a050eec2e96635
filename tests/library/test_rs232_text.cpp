// The text functions under FB_PAC_Rs232Cmd, called directly: numbers as the PA-CONTROL writes them in a
// frame (manual 3.1 itoa()/ftoa(), 3.3 fields separated by ";"), numbers as the library writes them, the
// commands with REAL data and the commands that may be sent twice, and the ComBuffer ring's limits.
// The FB's own tests reach these only with the values the simulator sends; here every form of 3.1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#include "pac/st_program.hpp"

namespace test_rs232_text {  // apart from the names of the other sources in its unity batch
namespace {

T_PAC_RS232TEXT TextOf(const std::string& s) {
    T_PAC_RS232TEXT text{};
    std::memcpy(text.table, s.data(), s.size() < 64 ? s.size() : 64);
    return text;
}

// A seeded xorshift32: the same numbers on every platform; each test prints its seed with a failure.
class XorShift {
public:
    explicit XorShift(std::uint32_t seed) : state_(seed) {}
    std::uint32_t Next() {
        state_ ^= state_ << 13;
        state_ ^= state_ >> 17;
        state_ ^= state_ << 5;
        return state_;
    }

private:
    std::uint32_t state_;
};

bool IsNumber(const std::string& s, bool allowFraction) {
    T_PAC_RS232TEXT text = TextOf(s);
    return F_PAC_RS232ISNUMBER(1, nullptr, 0, static_cast<INT>(s.size()), allowFraction, &text);
}

double ValueOf(const std::string& s) {
    T_PAC_RS232TEXT text = TextOf(s);
    return F_PAC_RS232NUMBERVALUE(1, nullptr, 0, static_cast<INT>(s.size()), &text);
}

// What F_PAC_Rs232AppendReal writes at index `start` of a text full of '#', or "-1" when it refuses.
std::string Real(float value, int start = 0) {
    T_PAC_RS232TEXT text{};
    std::memset(text.table, '#', sizeof text.table);
    const INT past = F_PAC_RS232APPENDREAL(1, nullptr, value, static_cast<INT>(start), &text);
    if (past < 0) return "-1";
    return std::string(reinterpret_cast<const char*>(text.table) + start, static_cast<std::size_t>(past - start));
}

TEST(Rs232Number, IntegersWithSignAndLeadingZeros) {
    for (const char* s : {"12", "-5", "+7", "0543", "0"}) EXPECT_TRUE(IsNumber(s, false)) << s;
    for (const char* s : {"", "-", "+", "1x", "1 2", "--1"}) EXPECT_FALSE(IsNumber(s, false)) << s;
    EXPECT_FALSE(IsNumber("1.5", false)) << "a point only where a fraction is allowed";
    EXPECT_FALSE(IsNumber("1E3", false)) << "an exponent only where a fraction is allowed";
}

TEST(Rs232Number, FractionsAndExponentsAsFtoaWritesThem) {
    for (const char* s : {"1.5", "-0.25", "5552.0", "1.5E3", "2e-12", "-7.125E+002", "3E1"}) {
        EXPECT_TRUE(IsNumber(s, true)) << s;
    }
    for (const char* s : {"1.", "1.2.3", "E5", "1E", "1E+", "1E1234", "1E2E3", "1.5E-", "1e3.5"}) {
        EXPECT_FALSE(IsNumber(s, true)) << s;
    }
}

TEST(Rs232Number, AFieldOutsideTheTextIsNoNumber) {
    T_PAC_RS232TEXT text = TextOf("123");
    EXPECT_FALSE(F_PAC_RS232ISNUMBER(1, nullptr, -1, 3, false, &text));
    EXPECT_FALSE(F_PAC_RS232ISNUMBER(1, nullptr, 0, 65, false, &text));
    EXPECT_FALSE(F_PAC_RS232ISNUMBER(1, nullptr, 2, 2, false, &text)) << "an empty field";
}

TEST(Rs232Number, ValuesAreTheNearestDoubles) {
    EXPECT_EQ(ValueOf("-12.5"), -12.5);
    EXPECT_EQ(ValueOf("+3"), 3.0);
    EXPECT_EQ(ValueOf("0.1"), 0.1);
    EXPECT_EQ(ValueOf("1.5E3"), 1500.0);
    EXPECT_EQ(ValueOf("25e-2"), 0.25);
    EXPECT_EQ(ValueOf("-7.125E+002"), -712.5);
    EXPECT_EQ(ValueOf("15E1"), 150.0);
    EXPECT_EQ(ValueOf("1E23"), 1e23) << "10^22 is exact, times 10 rounds once";
    EXPECT_DOUBLE_EQ(ValueOf("1E-30"), 1e-30) << "divided by 10^22, then by 10^8";
    EXPECT_EQ(ValueOf("123456789012345"), 123456789012345.0) << "15 significant digits";
    // A point or an exponent after the ninth significant digit: the digits gathered past the DINT go on in LREAL.
    EXPECT_EQ(ValueOf("1234567890.5"), 1234567890.5) << "a point after the tenth digit";
    EXPECT_EQ(ValueOf("-000123456789.25"), -123456789.25) << "leading zeros count for nothing";
    EXPECT_EQ(ValueOf("123456789.5E1"), 1234567895.0) << "decimals and an exponent past the ninth digit";
}

// A reply's text (3.3): Q_PAR error number; BE; status; system error; data type; data. Whatever does not
// have that form is refused as a whole, so a damaged reply can never pass for an acknowledgement.
bool Parse(const std::string& s, T_PAC_RS232REPLY& reply) {
    T_PAC_RS232TEXT text = TextOf(s);
    reply = T_PAC_RS232REPLY{};
    return F_PAC_RS232PARSEREPLY(1, nullptr, static_cast<INT>(s.size()), &text, &reply);
}

TEST(Rs232Reply, TheSixFieldsOfAnAcknowledgement) {
    T_PAC_RS232REPLY reply{};
    ASSERT_TRUE(Parse("0;1;31;0;1;1255.500", reply));
    EXPECT_EQ(reply.QUIT, 0);
    EXPECT_TRUE(reply.ENDOFPROCESSING);
    EXPECT_EQ(reply.STATUS, 31);
    EXPECT_TRUE(reply.ISREAL);
    EXPECT_EQ(reply.DATA, 0x449CF000u) << "1255.5 as IEEE single";
    ASSERT_TRUE(Parse("38;0;1;7;0;-2147483648", reply));
    EXPECT_EQ(reply.QUIT, 38);
    EXPECT_FALSE(reply.ENDOFPROCESSING);
    EXPECT_EQ(reply.PACERRORNUMBER, 7);
    EXPECT_EQ(reply.DATA, 0x80000000u);
}

TEST(Rs232Reply, AnyFieldOutOfItsFormRefusesTheWholeReply) {
    T_PAC_RS232REPLY reply{};
    for (const char* s : {"", "0;1;1;0;0", "0;1;1;0;0;5;", "0;1;1;0;0;5;6", "-1;1;1;0;0;5", "0;2;1;0;0;5",
                          "0;1;-1;0;0;5", "0;1;1;-3;0;5", "0;1;1;0;2;5", "0;1;1;0;0;1.5", "0;1;1;0;0;2147483648",
                          "0;1;1;0;1;1E39", "0;1;1;0;1;-1E39", "0.5;1;1;0;0;5", "0;x;1;0;0;5", "0;;1;0;0;5"}) {
        EXPECT_FALSE(Parse(s, reply)) << s;
    }
    EXPECT_FALSE(Parse(std::string(65, '1'), reply)) << "longer than a frame's text";
}

// The whole fields (QUIT, BE, STATUS, ERROR, TYP_QUIT, and Q_PAR with TYP_QUIT 0) as itoa() writes them (3.1):
// every DINT, with a sign and any number of leading zeros, and nothing outside the DINT range, also where the
// digits of a value past it are those of a value in it plus a multiple of 2^32.
TEST(Rs232Reply, WholeFieldsTakeTheDintRangeExactly) {
    T_PAC_RS232REPLY reply{};
    const struct {
        const char* qpar;
        std::int64_t value;
    } whole[] = {{"2147483647", 2147483647}, {"-2147483648", -2147483648LL}, {"+2147483647", 2147483647},
                 {"-0", 0}, {"+0", 0}, {"0000000000000000000000000000000000000042", 42},
                 {"-0002147483648", -2147483648LL}, {"214748364", 214748364}, {"-214748365", -214748365}};
    for (const auto& w : whole) {
        ASSERT_TRUE(Parse(std::string("0;1;1;0;0;") + w.qpar, reply)) << w.qpar;
        EXPECT_EQ(reply.DATA, static_cast<DWORD>(static_cast<std::int32_t>(w.value))) << w.qpar;
    }
    for (const char* qpar : {"2147483648", "-2147483649", "+2147483648", "4294967296", "4294967338", "-4294967338",
                             "21474836470", "99999999999999999999", "0000000000000000000000000000002147483648"}) {
        EXPECT_FALSE(Parse(std::string("0;1;1;0;0;") + qpar, reply)) << qpar;
    }
    ASSERT_TRUE(Parse("2147483647;1;0002147483647;2147483647;0;1", reply));
    EXPECT_EQ(reply.QUIT, 2147483647);
    EXPECT_EQ(reply.STATUS, 2147483647);
    EXPECT_EQ(reply.PACERRORNUMBER, 2147483647);
    // BE and TYP_QUIT are 0 or 1 in any spelling of the number; QUIT, STATUS and ERROR 0 to 2^31-1.
    for (const char* s : {"0;01;1;0;00;1", "0;-0;1;0;0;1", "-0;1;1;0;0;1", "0;+1;1;0;0;1", "0;1;1;0;+1;1.5",
                          "0;1;1;0;-0;1"}) {
        EXPECT_TRUE(Parse(s, reply)) << s;
    }
    for (const char* s : {"2147483648;1;1;0;0;1", "0;1;4294967297;0;0;1", "0;1;1;4294967296;0;1",
                          "0;4294967297;1;0;0;1", "0;1;1;0;4294967296;1", "0;-1;1;0;0;1"}) {
        EXPECT_FALSE(Parse(s, reply)) << s;
    }
}

// Seeded random DINTs of every magnitude, each written with a sign or none and 0 to 20 leading zeros, and
// random values just outside the range: the first come back exactly, the second are refused.
TEST(Rs232Reply, RandomWholeNumbersComeBackExactly) {
    const std::uint32_t seed = 20261207;
    XorShift random(seed);
    auto next = [&random] { return random.Next(); };
    T_PAC_RS232REPLY reply{};
    for (int i = 0; i < 20000; ++i) {
        const std::int64_t magnitude = (next() >> (next() % 32)) % 2147483649LL;
        const bool negative = (next() & 1U) != 0 || magnitude == 2147483648LL;
        const std::int64_t value = negative ? -magnitude : magnitude;
        const std::string zeros(next() % 21, '0');
        const char* sign = negative ? "-" : (next() & 1U) != 0 ? "+" : "";
        const std::string qpar = sign + zeros + std::to_string(magnitude);
        ASSERT_TRUE(Parse("0;1;1;0;0;" + qpar, reply)) << qpar << ", seed " << seed;
        ASSERT_EQ(reply.DATA, static_cast<DWORD>(static_cast<std::int32_t>(value))) << qpar << ", seed " << seed;
        const std::int64_t past = 1 + static_cast<std::int64_t>(next() % 1000000000U) * (1 + next() % 8);
        const std::int64_t outside = negative ? -2147483648LL - past : 2147483647LL + past;
        ASSERT_FALSE(Parse("0;1;1;0;0;" + std::to_string(outside), reply)) << outside << ", seed " << seed;
    }
}

// A REAL's Q_PAR (TYP_QUIT 1) as ftoa() may write it: every finite REAL written with nine significant digits,
// in fixed or exponent form, gives the REAL itself back (nine digits tell any two REALs apart), -0.0 the bits
// of 0.0 (F_PAC_RealToDword); digits past the ninth, leading zeros and a longer exponent change nothing.
TEST(Rs232Reply, RealQParGivesTheRealBack) {
    const std::uint32_t seed = 20261208;
    XorShift random(seed);
    auto next = [&random] { return random.Next(); };
    T_PAC_RS232REPLY reply{};
    auto bitsOf = [](float f) {
        std::uint32_t b;
        std::memcpy(&b, &f, sizeof b);
        return b;
    };
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const std::uint32_t bits = next();
        float value;
        std::memcpy(&value, &bits, sizeof value);
        if (!std::isfinite(value) || value == 0.0F) continue;
        char text[64];
        if (i % 2 == 0) {
            std::snprintf(text, sizeof text, "%.8e", static_cast<double>(value));
        } else {
            std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
        }
        const std::string s = std::string("0;1;1;0;1;") + text;
        if (s.size() > 64) continue;
        ASSERT_TRUE(Parse(s, reply)) << s << ", seed " << seed;
        ASSERT_EQ(reply.DATA, bitsOf(value)) << s << ", seed " << seed;
        ++checked;
    }
    EXPECT_GT(checked, 15000) << "seed " << seed;
    for (const char* qpar : {"-0.0", "0", "-0", "0.000", "0E0", "0000.0000"}) {
        ASSERT_TRUE(Parse(std::string("0;1;1;0;1;") + qpar, reply)) << qpar;
        EXPECT_EQ(reply.DATA, 0u) << qpar;
    }
    const struct {
        const char* qpar;
        float value;
    } same[] = {{"12.5", 12.5F}, {"0012.500000000000000000000000", 12.5F}, {"125E-1", 12.5F}, {"1.25e+001", 12.5F},
                {"1255.000", 1255.0F}, {"-2634.750", -2634.75F}, {"123456789012", 123456789012.0F},
                {"0.0000000000000000000000000000000000000000000014", 1.4e-45F}, {"1E-45", 1.4e-45F},
                {"3.40282346E38", 3.40282347e38F}, {"16777217", 16777216.0F}, {"-7.125E+002", -712.5F},
                {"123456789012345678901234567890", std::strtof("123456789012345678901234567890", nullptr)},
                {"0.000000000000000000000000000000000000011754944", std::strtof("1.1754944E-38", nullptr)}};
    for (const auto& x : same) {
        const std::string s = std::string("0;1;1;0;1;") + x.qpar;
        ASSERT_TRUE(Parse(s, reply)) << x.qpar;
        EXPECT_EQ(reply.DATA, bitsOf(x.value)) << x.qpar;
    }
    for (const char* qpar : {"3.5E38", "-3.5E38", "1E39", "1E999", "1.5.2", "1E", "1E1234", ".",
                             "1234567890123456789012345678901234567890"}) {
        EXPECT_FALSE(Parse(std::string("0;1;1;0;1;") + qpar, reply)) << qpar;
    }
}

// The fewest decimals (one at least, nine at most) whose number is the REAL itself: what the controller reads
// (3.1: ftoa, then a float) is what Data held.
TEST(Rs232Real, TheFewestDecimalsThatGiveTheRealBack) {
    EXPECT_EQ(Real(5552.0F), "5552.0");
    EXPECT_EQ(Real(12.345F), "12.345");
    EXPECT_EQ(Real(-0.5F), "-0.5");
    EXPECT_EQ(Real(2.75F), "2.75") << "2.75 rounds to 3: the integer part steps back";
    EXPECT_EQ(Real(0.0001F), "0.0001") << "leading zeros of the decimals";
    EXPECT_EQ(Real(10.05F), "10.05");
    EXPECT_EQ(Real(0.00004F), "0.00004") << "not 0.0";
    EXPECT_EQ(Real(0.99999F), "0.99999") << "not 1.0";
    EXPECT_EQ(Real(-0.00001F), "-0.00001");
    EXPECT_EQ(Real(12.34567F), "12.34567") << "not 12.3457";
    EXPECT_EQ(Real(0.1F), "0.1") << "0.1 is not exact in binary, but the nearest REAL to 0.1 is this one";
    EXPECT_EQ(Real(16777215.0F), "16777215.0");
    EXPECT_EQ(Real(-0.0F), "0.0");
}

// Seeded random REALs of every magnitude below 1.0E9: either the text gives the REAL back, or no text with at
// most nine decimals does and the REAL is refused.
TEST(Rs232Real, ExactOrRefusedForRandomReals) {
    const std::uint32_t seed = 20261202;
    XorShift random(seed);
    auto next = [&random] { return random.Next(); };
    int sent = 0;
    for (int i = 0; i < 20000; ++i) {
        // exponents 2^-40 .. 2^30, any mantissa and sign
        const std::uint32_t exponent = 127 - 40 + next() % 71;
        const std::uint32_t bits = (next() & 0x807FFFFFu) | (exponent << 23);
        float value;
        std::memcpy(&value, &bits, sizeof value);
        if (std::fabs(value) >= 1.0e9F) continue;
        const std::string text = Real(value);
        if (text != "-1") {
            ++sent;
            EXPECT_EQ(static_cast<float>(std::strtod(text.c_str(), nullptr)), value) << text << ", seed " << seed;
            continue;
        }
        for (int decimals = 1; decimals <= 9; ++decimals) {
            char buffer[64];
            std::snprintf(buffer, sizeof buffer, "%.*f", decimals, static_cast<double>(value));
            EXPECT_NE(static_cast<float>(std::strtod(buffer, nullptr)), value)
                << buffer << " would have carried it; seed " << seed;
        }
    }
    EXPECT_GT(sent, 5000) << "seed " << seed;
}

TEST(Rs232Real, ValuesWithoutThisFormOrThatDoNotFitAreRefused) {
    EXPECT_EQ(Real(std::numeric_limits<float>::quiet_NaN()), "-1");
    EXPECT_EQ(Real(std::numeric_limits<float>::infinity()), "-1");
    EXPECT_EQ(Real(-std::numeric_limits<float>::infinity()), "-1");
    EXPECT_EQ(Real(1.0e9F), "-1");
    EXPECT_EQ(Real(-1.0e9F), "-1");
    EXPECT_EQ(Real(1.234567E-7F), "-1") << "more than nine decimals";
    EXPECT_EQ(Real(12.5F, 61), "-1") << "12.5 needs 4 places, 61..64: one more than the text has";
    EXPECT_EQ(Real(1.5F, 61), "1.5") << "exactly fits";
    EXPECT_EQ(Real(123456.5F, 60), "-1") << "the integer part alone does not fit";
}

TEST(Rs232Dint, AllOfTheRangeAndNothingWrittenWhenItDoesNotFit) {
    T_PAC_RS232TEXT text{};
    INT past = F_PAC_RS232APPENDDINT(1, nullptr, std::numeric_limits<std::int32_t>::min(), 0, &text);
    EXPECT_EQ(std::string(reinterpret_cast<const char*>(text.table), static_cast<std::size_t>(past)), "-2147483648");
    text = TextOf("");
    EXPECT_EQ(F_PAC_RS232APPENDDINT(1, nullptr, 123456, 60, &text), -1);
    EXPECT_EQ(F_PAC_RS232APPENDDINT(1, nullptr, 5, -1, &text), -1);
    for (BYTE b : text.table) ASSERT_EQ(b, 0) << "the text is unchanged";
    EXPECT_EQ(F_PAC_RS232APPENDDINT(1, nullptr, -1234, 59, &text), 64) << "exactly fits";
}

TEST(Rs232Field, EndsAtTheSemicolonOrTheLength) {
    T_PAC_RS232TEXT text = TextOf("1;22;333");
    EXPECT_EQ(F_PAC_RS232FIELDEND(1, nullptr, 0, 8, &text), 1);
    EXPECT_EQ(F_PAC_RS232FIELDEND(1, nullptr, 2, 8, &text), 4);
    EXPECT_EQ(F_PAC_RS232FIELDEND(1, nullptr, 5, 8, &text), 8);
    EXPECT_EQ(F_PAC_RS232FIELDEND(1, nullptr, -3, 8, &text), 1) << "a start before the text starts at 0";
}

// Manual 3.3: the data type flag 1 for the commands whose data is a REAL (axis parameters, R registers,
// positions and speeds, the moves and their speeds and accelerations).
TEST(Rs232Commands, TheCommandsWithRealData) {
    for (std::uint16_t code : {0x0800, 0x1800, 0x1802, 0x0907, 0x1907, 0x1937, 0x190C, 0x1914, 0x0A86, 0x0A87,
                               0x0A89, 0x0A8E, 0x0A90, 0x0A93, 0x0A96, 0x0A9A}) {
        EXPECT_TRUE(F_PAC_RS232ISREAL(1, nullptr, code)) << std::hex << code;
    }
    for (std::uint16_t code : {0x0906, 0x1906, 0x0A84, 0x0A97, 0x0603, 0x1909}) {
        EXPECT_FALSE(F_PAC_RS232ISREAL(1, nullptr, code)) << std::hex << code;
    }
}

// Only a command whose second execution changes nothing may be sent again after a lost acknowledgement.
TEST(Rs232Commands, OnlyReadsAndAbsoluteWritesAreRepeatable) {
    for (std::uint16_t code : {0x1000, 0x1906, 0x1FFF, 0x0700, 0x0800, 0x0902, 0x0907, 0x0A8D, 0x0A8E}) {
        EXPECT_TRUE(F_PAC_RS232REPEATABLE(1, nullptr, code)) << std::hex << code;
    }
    for (std::uint16_t code : {0x0909, 0x0A87, 0x0A89, 0x0603, 0x0600, 0x2000}) {
        EXPECT_FALSE(F_PAC_RS232REPEATABLE(1, nullptr, code)) << std::hex << code;
    }
}

TEST(ComBuffer, AFullRingOrOneWithIndicesOutOfRangeTakesNothing) {
    T_PAC_COMBUFFER ring{};
    ring.FREEBYTE = 300;
    for (int i = 0; i < 300; ++i) ASSERT_TRUE(F_PAC_COMPUT(1, nullptr, static_cast<BYTE>(i), &ring)) << i;
    EXPECT_EQ(ring.FREEBYTE, 0);
    EXPECT_EQ(ring.WRIDX, 0) << "wrapped";
    EXPECT_FALSE(F_PAC_COMPUT(1, nullptr, 1, &ring)) << "full";
    EXPECT_EQ(ring.COUNT, 300);
    for (int i = 0; i < 300; ++i) ASSERT_EQ(F_PAC_COMGET(1, nullptr, &ring), i % 256) << i;
    EXPECT_EQ(F_PAC_COMGET(1, nullptr, &ring), -1) << "empty";
    EXPECT_EQ(ring.RDIDX, 0) << "wrapped";

    T_PAC_COMBUFFER broken{};
    broken.COUNT = 1;
    broken.RDIDX = 300;
    EXPECT_EQ(F_PAC_COMGET(1, nullptr, &broken), -1);
    broken.RDIDX = -1;
    EXPECT_EQ(F_PAC_COMGET(1, nullptr, &broken), -1);
    broken.RDIDX = 0;
    broken.COUNT = 301;
    EXPECT_EQ(F_PAC_COMGET(1, nullptr, &broken), -1);
    broken.COUNT = -1;
    EXPECT_FALSE(F_PAC_COMPUT(1, nullptr, 1, &broken));
    broken.COUNT = 0;
    broken.WRIDX = 300;
    EXPECT_FALSE(F_PAC_COMPUT(1, nullptr, 1, &broken));
    broken.WRIDX = -1;
    EXPECT_FALSE(F_PAC_COMPUT(1, nullptr, 1, &broken));
}

}  // namespace
}  // namespace test_rs232_text
