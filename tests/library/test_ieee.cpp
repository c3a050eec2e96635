// F_PAC_RealToDword / F_PAC_DwordToReal (st/fun/, docs/ieee754.md): the arithmetic IEEE-754 single
// conversions of manual 6.1, compared bit for bit with the C++ float's own representation.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "pac/st_program.hpp"
#include "real_bits.hpp"

namespace test_ieee {  // apart from the names of the other sources in its unity batch
namespace {

static_assert(sizeof(REAL) == sizeof(std::uint32_t) && std::numeric_limits<float>::is_iec559,
              "REAL must be an IEEE-754 single");

using pac::test::BitsOf;
using pac::test::FloatOf;

std::uint32_t ToDword(float value) { return F_PAC_REALTODWORD(1, nullptr, value); }
float ToReal(std::uint32_t bits) { return F_PAC_DWORDTOREAL(1, nullptr, bits); }

bool IsFinitePattern(std::uint32_t b) { return (b & 0x7F800000u) != 0x7F800000u; }

// Both directions for one finite value, bit for bit; -0.0 is the one documented exception.
::testing::AssertionResult BothWays(float x) {
    const std::uint32_t want = BitsOf(x);
    if (want == 0x80000000u) return ::testing::AssertionFailure() << "-0.0 is not bit-exact by design";
    const std::uint32_t got = ToDword(x);
    if (got != want) {
        return ::testing::AssertionFailure() << std::hexfloat << x << ": RealToDword gave 0x" << std::hex << got
                                             << ", expected 0x" << want;
    }
    const std::uint32_t back = BitsOf(ToReal(want));
    if (back != want) {
        return ::testing::AssertionFailure() << "DwordToReal(0x" << std::hex << want << ") gave the bits 0x" << back;
    }
    return ::testing::AssertionSuccess();
}

// ---------------------------------------------------------------- fixed values

TEST(Ieee754, EveryPowerOfTwoWithBothSigns) {
    for (int e = -149; e <= 127; ++e) {
        const float p = std::ldexp(1.0f, e);
        ASSERT_EQ(std::ilogb(p), e);
        EXPECT_TRUE(BothWays(p)) << "2^" << e;
        EXPECT_TRUE(BothWays(-p)) << "-2^" << e;
    }
}

TEST(Ieee754, NeighboursOfEveryPowerOfTwo) {
    const float inf = std::numeric_limits<float>::infinity();
    for (int e = -149; e <= 127; ++e) {
        const float p = std::ldexp(1.0f, e);
        for (float x : {std::nextafter(p, 0.0f), std::nextafter(p, inf)}) {
            if (x == 0.0f || std::isinf(x)) continue;
            EXPECT_TRUE(BothWays(x)) << "next to 2^" << e;
            EXPECT_TRUE(BothWays(-x)) << "next to -2^" << e;
        }
    }
}

TEST(Ieee754, RangeLimits) {
    using L = std::numeric_limits<float>;
    const float values[] = {
        L::max(),                          // 0x7F7FFFFF, largest finite
        L::min(),                          // 0x00800000, smallest normal
        L::denorm_min(),                   // 0x00000001, smallest subnormal
        FloatOf(0x007FFFFFu),              // largest subnormal
        FloatOf(0x00400000u),              // subnormal with only the top fraction bit
        FloatOf(0x00555555u),              // subnormal, alternating bits
        FloatOf(0x00800001u),              // smallest normal + 1 ulp
        FloatOf(0x3F800001u),              // 1 + 2^-23
        FloatOf(0x3FFFFFFFu),              // 2 - 2^-23
        FloatOf(0x7F7FFFFEu),              // below the largest finite
        16777216.0f, 16777215.0f, 0.1f, 1.0f / 3.0f,
    };
    for (float v : values) {
        EXPECT_TRUE(BothWays(v)) << std::hexfloat << v;
        EXPECT_TRUE(BothWays(-v)) << std::hexfloat << -v;
    }
}

TEST(Ieee754, EveryExponentFieldWithEdgeFractions) {
    const std::uint32_t fractions[] = {0x000000u, 0x000001u, 0x000002u, 0x000003u, 0x2AAAAAu, 0x400000u,
                                       0x555555u, 0x7FFFFEu, 0x7FFFFFu};
    for (std::uint32_t field = 0; field < 255; ++field) {
        for (std::uint32_t f : fractions) {
            for (std::uint32_t sign : {0u, 0x80000000u}) {
                const std::uint32_t b = sign | (field << 23) | f;
                if (b == 0x80000000u) continue;
                EXPECT_TRUE(BothWays(FloatOf(b))) << std::hex << "0x" << b;
            }
        }
    }
}

TEST(Ieee754, Zero) {
    EXPECT_EQ(ToDword(0.0f), 0x00000000u);
    EXPECT_EQ(BitsOf(ToReal(0x00000000u)), 0x00000000u);
}

// The manual's examples that are right (docs/manual_errata.md), as the bus carries them: byte 0 is the top byte.
TEST(Ieee754, ManualExamples) {
    struct Example { std::uint32_t bits; float value; };
    const Example examples[] = {
        {0x41200000u, 10.0f},  {0x43480000u, 200.0f},   {0x47435000u, 50000.0f},
        {0x45DAC000u, 7000.0f}, {0x461C4000u, 10000.0f}, {0x42DE38D5u, 111.111f},
    };
    for (const auto& ex : examples) {
        EXPECT_EQ(ToDword(ex.value), ex.bits) << ex.value;
        EXPECT_EQ(ToReal(ex.bits), ex.value) << std::hex << ex.bits;
    }
    EXPECT_NEAR(ToReal(0x42DE38D5u), 111.111, 1e-5);
}

// The manual's wrong examples (docs/manual_errata.md, the IEEE-754 table): the value it meant, with its real bytes,
// and what its printed bytes really decode to.
TEST(Ieee754, ManualErrataCorrected) {
    struct Example { std::uint32_t bits; float value; };
    const Example meant[] = {
        {0x3EB00000u, 0.34375f}, {0x44200000u, 640.0f},  {0x46A00000u, 20480.0f}, {0x459C4000u, 5000.0f},
        {0x458CA000u, 4500.0f},  {0x40160000u, 2.34375f}, {0x44202000u, 640.5f},
    };
    for (const auto& ex : meant) {
        EXPECT_EQ(ToDword(ex.value), ex.bits) << ex.value;
        EXPECT_EQ(ToReal(ex.bits), ex.value) << std::hex << ex.bits;
    }
    const Example printed[] = {
        {0x40160000u, 2.34375f}, {0x44202000u, 640.5f}, {0x44A80000u, 1344.0f}, {0x47A80000u, 86016.0f},
        {0x45480000u, 3200.0f},  {0x43200000u, 160.0f}, {0x42200000u, 40.0f},
    };
    for (const auto& ex : printed) EXPECT_EQ(ToReal(ex.bits), ex.value) << std::hex << ex.bits;
}

// ---------------------------------------------------------------- documented special values

TEST(Ieee754, NegativeZeroEncodesAsPositiveZero) {
    EXPECT_EQ(ToDword(-0.0f), 0x00000000u);
    // Decoding keeps the sign where the PLC has a signed zero (it has here).
    EXPECT_EQ(BitsOf(ToReal(0x80000000u)), 0x80000000u);
}

TEST(Ieee754, InfinitiesEncodeAsInfinityPatterns) {
    EXPECT_EQ(ToDword(std::numeric_limits<float>::infinity()), 0x7F800000u);
    EXPECT_EQ(ToDword(-std::numeric_limits<float>::infinity()), 0xFF800000u);
}

TEST(Ieee754, EveryNanEncodesAsTheCanonicalQuietNan) {
    for (std::uint32_t b : {0x7FC00000u, 0xFFC00000u, 0x7F800001u, 0xFF800001u, 0x7FFFFFFFu, 0xFFFFFFFFu,
                            0x7FA5A5A5u}) {
        ASSERT_TRUE(std::isnan(FloatOf(b)));
        EXPECT_EQ(ToDword(FloatOf(b)), 0x7FC00000u) << std::hex << b;
    }
    EXPECT_EQ(ToDword(std::numeric_limits<float>::quiet_NaN()), 0x7FC00000u);
}

TEST(Ieee754, InfinityPatternsSaturateToTheLargestFinite) {
    EXPECT_EQ(BitsOf(ToReal(0x7F800000u)), 0x7F7FFFFFu);
    EXPECT_EQ(BitsOf(ToReal(0xFF800000u)), 0xFF7FFFFFu);
    EXPECT_EQ(ToReal(0x7F800000u), 3.4028235E38f);
    EXPECT_EQ(ToReal(0xFF800000u), -3.4028235E38f);
}

TEST(Ieee754, NanPatternsDecodeAsPositiveZero) {
    for (std::uint32_t b : {0x7FC00000u, 0xFFC00000u, 0x7F800001u, 0xFF800001u, 0x7FFFFFFFu, 0xFFFFFFFFu}) {
        EXPECT_EQ(BitsOf(ToReal(b)), 0x00000000u) << std::hex << b;
    }
}

// ---------------------------------------------------------------- seeded random sweep

constexpr std::uint32_t kSweepSeed = 0x5EED1EEEu;
constexpr int kSweepCount = 1'000'000;

TEST(Ieee754, RandomBitPatternsDecodeAndRoundTrip) {
    RecordProperty("seed", std::to_string(kSweepSeed));
    SCOPED_TRACE("std::mt19937 seed " + std::to_string(kSweepSeed));
    std::mt19937 rng(kSweepSeed);
    int checked = 0, failures = 0;
    while (checked < kSweepCount && failures < 20) {
        const std::uint32_t b = static_cast<std::uint32_t>(rng());
        if (!IsFinitePattern(b) || b == 0x80000000u) continue;
        ++checked;
        const float r = ToReal(b);
        if (BitsOf(r) != b) {
            ADD_FAILURE() << std::hex << "DwordToReal(0x" << b << ") gave the bits 0x" << BitsOf(r);
            ++failures;
        }
        const std::uint32_t back = ToDword(r);
        if (back != b) {
            ADD_FAILURE() << std::hex << "RealToDword(DwordToReal(0x" << b << ")) = 0x" << back;
            ++failures;
        }
    }
    EXPECT_EQ(checked, kSweepCount);
}

TEST(Ieee754, RandomFloatsEncodeAndRoundTrip) {
    const std::uint32_t seed = kSweepSeed + 1;
    RecordProperty("seed", std::to_string(seed));
    SCOPED_TRACE("std::mt19937 seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    int checked = 0, failures = 0;
    while (checked < kSweepCount && failures < 20) {
        const float x = FloatOf(static_cast<std::uint32_t>(rng()));
        if (!std::isfinite(x) || BitsOf(x) == 0x80000000u) continue;
        ++checked;
        const std::uint32_t b = ToDword(x);
        if (b != BitsOf(x)) {
            ADD_FAILURE() << std::hexfloat << "RealToDword(" << x << ") = 0x" << std::hex << b << ", expected 0x"
                          << BitsOf(x);
            ++failures;
        }
        const float back = ToReal(b);
        if (BitsOf(back) != BitsOf(x)) {
            ADD_FAILURE() << std::hexfloat << "DwordToReal(RealToDword(" << x << ")) = " << back;
            ++failures;
        }
    }
    EXPECT_EQ(checked, kSweepCount);
}

// Every one of the 2^32 patterns, both ways, is the target ieee_exhaustive_run (rig/ieee_exhaustive.cpp;
// minutes on every core, so not a test); its last result is in docs/ieee754.md.

// ---------------------------------------------------------------- bounded work (code review as a test)

// The functions run in every PLC scan, so their work must not grow with the value (a subnormal would need
// 149 halvings one at a time). Both are straight-line code: no loop statement at all, and a fixed number of
// IF steps. Comments are stripped before the check.
std::string StSourceWithoutComments(const std::string& name) {
    std::string path = __FILE__;
    path = path.substr(0, path.rfind("/tests/library/")) + "/st/fun/" + name;
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << "cannot read " << path;
    std::stringstream text;
    text << in.rdbuf();
    return std::regex_replace(text.str(), std::regex(R"(\(\*[\s\S]*?\*\))"), " ");
}

TEST(Ieee754, NoLoopsScalingWithTheValue) {
    for (const char* name : {"F_PAC_RealToDword.st", "F_PAC_DwordToReal.st"}) {
        const std::string code = StSourceWithoutComments(name);
        ASSERT_FALSE(code.empty()) << name;
        const std::regex loop(R"(\b(WHILE|REPEAT|FOR|END_WHILE|END_REPEAT|END_FOR|EXIT|CONTINUE)\b)",
                              std::regex::icase);
        EXPECT_FALSE(std::regex_search(code, loop)) << name << " contains a loop";
        const std::regex call(R"(\bF_PAC_\w+\s*\()", std::regex::icase);
        EXPECT_FALSE(std::regex_search(code, call)) << name << " calls another library function";
        // At most 8 scaling steps on either side of one IF, each an IF of its own.
        const std::regex ifStatement(R"(\bIF\b)");
        const auto ifs =
            std::distance(std::sregex_iterator(code.begin(), code.end(), ifStatement), std::sregex_iterator());
        EXPECT_LE(ifs, 25) << name;
    }
}

}  // namespace
}  // namespace test_ieee
