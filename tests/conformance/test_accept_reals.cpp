// REAL and LREAL semantics of translated ST: literal rounding checked bit by bit, single and double
// precision arithmetic.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "matiec_deviations.hpp"
#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"

namespace {

std::uint32_t Bits(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

std::uint64_t Bits(double d) {
    std::uint64_t u;
    std::memcpy(&u, &d, sizeof u);
    return u;
}

TEST(ConformanceReals, RealLiteralsRoundToTheNearestSingle) {
    auto fb = PAC_FB(CONF_REALLITERALS);
    fb();
    EXPECT_EQ(Bits(fb->POINTONE.value), 0x3DCCCCCDu);       // 0.1 rounds up in the last bit
    EXPECT_EQ(Bits(fb->TWOPOW24PLUS1.value), 0x4B800000u);  // 16777217 is a tie: to even, 2^24
    EXPECT_EQ(Bits(fb->TWOPOW24PLUS3.value), 0x4B800002u);  // 16777219 is a tie: to even, 16777220
    EXPECT_EQ(Bits(fb->FLTMAX.value), 0x7F7FFFFFu);         // 3.4028235E38 is the largest finite single
    EXPECT_EQ(Bits(fb->SUBNORMAL.value), 0x00000001u);      // 1.0E-45 -> 2^-149, the smallest subnormal
    EXPECT_EQ(Bits(fb->SUBNORMAL2.value), 0x00000002u);     // 2.5E-45 -> 2 * 2^-149
    EXPECT_EQ(Bits(fb->SMALLESTNORMAL.value), 0x00800000u); // 2^-126
    EXPECT_EQ(Bits(fb->NEGTHIRD.value), 0xBEAAAAABu);
    EXPECT_EQ(Bits(fb->EXPLITERAL.value), 0x44BB8000u);     // 1500.0
    EXPECT_EQ(Bits(fb->LPOINTONE.value), 0x3FB999999999999Au);
    EXPECT_EQ(fb->LTWOPOW24PLUS1.value, 16777217.0);        // exact in LREAL
    EXPECT_EQ(Bits(fb->TYPEDREAL.value), 0x3DCCCCCDu);
}

TEST(ConformanceReals, RealArithmeticIsSinglePrecision) {
    auto fb = PAC_FB(CONF_REALARITH);
    fb();
    volatile float a = 0.1f;
    volatile float b = 0.2f;
    EXPECT_EQ(Bits(fb->SUM.value), Bits(static_cast<float>(a + b)));
    EXPECT_EQ(Bits(fb->SUM.value), 0x3E99999Au);
    EXPECT_EQ(Bits(fb->DIFF.value), Bits(static_cast<float>(a - b)));
    EXPECT_EQ(Bits(fb->PROD.value), Bits(static_cast<float>(a * b)));
    EXPECT_EQ(fb->QUOT.value, 0.5f);  // 0.2f is exactly twice 0.1f
    volatile float one = 1.0f;
    volatile float three = 3.0f;
    EXPECT_EQ(Bits(fb->THIRD.value), Bits(static_cast<float>(one / three)));
    EXPECT_EQ(Bits(fb->THIRD.value), 0x3EAAAAABu);
    EXPECT_EQ(fb->NEG.value, -0.1f);
    EXPECT_EQ(fb->BIGPLUSONE.value, 16777216.0f);  // 2^24 + 1 is not a single
    // (A + B) * 10.0 - 3.0: MATIEC's REAL literals are C double constants, so it computes the part after
    // A + B in double precision and rounds once at the assignment; pacst rounds after every operation.
    const float mixed = pac::test::kMatiecBackend
                            ? static_cast<float>(static_cast<double>(static_cast<float>(a + b)) * 10.0 - 3.0)
                            : static_cast<float>(static_cast<float>(static_cast<float>(a + b) * 10.0f) - 3.0f);
    EXPECT_EQ(Bits(fb->MIXED.value), Bits(mixed));
}

TEST(ConformanceReals, LrealArithmeticIsDoublePrecision) {
    auto fb = PAC_FB(CONF_LREALARITH);
    fb();
    EXPECT_EQ(fb->SUM.value, 0.30000000000000004);
    EXPECT_EQ(Bits(fb->SUM.value), 0x3FD3333333333334u);
    EXPECT_EQ(fb->SUMISPOINTTHREE.value, 0);
    EXPECT_EQ(fb->DIFF.value, -0.1);
    EXPECT_EQ(fb->PROD.value, 0.020000000000000004);
    volatile double third = 1.0 / 3.0;
    EXPECT_EQ(fb->QUOT.value, third);  // 0.1 * 30.0 rounds to exactly 3.0
    EXPECT_EQ(fb->NEG.value, -0.1);
    EXPECT_EQ(fb->BIGPLUSONE.value, 16777217.0);
    EXPECT_EQ(fb->ABSNEG.value, 0.1);
}

}  // namespace
