// Integer semantics of translated ST: wrap-around, division, conversions.
#include <gtest/gtest.h>

#include "pac/st_program.hpp"
#include "pac/fb_instance.hpp"

namespace {

TEST(ConformanceIntegers, OverflowWrapsInEveryType) {
    auto fb = PAC_FB(CONF_INTWRAP);
    fb();
    EXPECT_EQ(fb->SINTUP.value, -128);
    EXPECT_EQ(fb->INTUP.value, -32768);
    EXPECT_EQ(fb->DINTUP.value, INT32_MIN);
    EXPECT_EQ(fb->USINTDOWN.value, 255);
    EXPECT_EQ(fb->UINTUP.value, 0);
    EXPECT_EQ(fb->UDINTDOWN.value, 4294967295u);
    EXPECT_EQ(fb->INTNEG.value, -32768);
}

TEST(ConformanceIntegers, SubtractionWrapsInEveryType) {
    auto fb = PAC_FB(CONF_INTWRAPSUB);
    fb();
    EXPECT_EQ(fb->SINTDOWN.value, 127);
    EXPECT_EQ(fb->INTDOWN.value, 32767);
    EXPECT_EQ(fb->DINTDOWN.value, INT32_MAX);
    EXPECT_EQ(fb->USINTDOWN.value, 255);
    EXPECT_EQ(fb->UINTDOWN.value, 65534);
    EXPECT_EQ(fb->UDINTDOWN.value, 4294967294u);
    EXPECT_EQ(fb->UDINTUP.value, 6u);  // 5 - (2^32 - 1) modulo 2^32
}

TEST(ConformanceIntegers, MultiplicationWrapsInEveryType) {
    auto fb = PAC_FB(CONF_INTWRAPMUL);
    fb();
    EXPECT_EQ(fb->SINTMUL.value, -64);        // 192 - 256
    EXPECT_EQ(fb->INTMUL.value, 24464);       // 90000 - 65536
    EXPECT_EQ(fb->DINTMUL.value, 65536);      // 2^32 + 2^16 modulo 2^32
    EXPECT_EQ(fb->USINTMUL.value, 16);        // 272 - 256
    EXPECT_EQ(fb->UINTMUL.value, 1);          // (2^16 - 1)^2 = 2^32 - 2^17 + 1
    EXPECT_EQ(fb->UDINTMUL.value, 1u);        // (2^32 - 1)^2 = 2^64 - 2^33 + 1
    EXPECT_EQ(fb->INTNEGMUL.value, -32768);   // 32768 wraps to -32768
}

TEST(ConformanceIntegers, UnaryMinusOfTheMinimumWrapsToItself) {
    auto fb = PAC_FB(CONF_INTWRAPNEG);
    fb();
    EXPECT_EQ(fb->SINTNEG.value, -128);
    EXPECT_EQ(fb->INTNEG.value, -32768);
    EXPECT_EQ(fb->DINTNEG.value, INT32_MIN);
    fb->SINTIN.value = 127;
    fb->INTIN.value = -300;
    fb->DINTIN.value = 100000;
    fb();
    EXPECT_EQ(fb->SINTNEG.value, -127);
    EXPECT_EQ(fb->INTNEG.value, 300);
    EXPECT_EQ(fb->DINTNEG.value, -100000);
}

TEST(ConformanceIntegers, LiteralsAtTheLimitsOfEachType) {
    auto fb = PAC_FB(CONF_INTLIMITS);
    fb();
    EXPECT_EQ(fb->SINTLO.value, -128);
    EXPECT_EQ(fb->SINTHI.value, 127);
    EXPECT_EQ(fb->INTLO.value, -32768);
    EXPECT_EQ(fb->INTHI.value, 32767);
    EXPECT_EQ(fb->DINTLO.value, INT32_MIN);
    EXPECT_EQ(fb->DINTHI.value, INT32_MAX);
    EXPECT_EQ(fb->USINTHI.value, 255);
    EXPECT_EQ(fb->UINTHI.value, 65535);
    EXPECT_EQ(fb->UDINTHI.value, 4294967295u);
    EXPECT_EQ(fb->BYTEHI.value, 0xFF);
    EXPECT_EQ(fb->WORDHI.value, 0xFFFF);
    EXPECT_EQ(fb->DWORDHI.value, 0xFFFFFFFFu);
}

TEST(ConformanceIntegers, DivisionTruncatesTowardZero) {
    auto fb = PAC_FB(CONF_INTDIVTRUNC);
    fb();  // Num = -7, Den = 2
    EXPECT_EQ(fb->NEGPOS.value, -3);   // -7 / 2
    EXPECT_EQ(fb->POSNEG.value, -3);   // 7 / -2
    EXPECT_EQ(fb->NEGNEG.value, 3);    // -7 / -2
    EXPECT_EQ(fb->POSPOS.value, 3);    // 7 / 2
    EXPECT_EQ(fb->SINTQ.value, -1);    // -7 / 4
    EXPECT_EQ(fb->INTQ.value, 2333);   // -7000 / -3
    EXPECT_EQ(fb->UINTQ.value, 32767); // 65535 / 2
    EXPECT_EQ(fb->CONSTQ.value, -3);   // folded at translation: same rule
    fb->NUM.value = 9;
    fb->DEN.value = -4;
    fb();
    EXPECT_EQ(fb->NEGPOS.value, -2);   // 9 / -4
    EXPECT_EQ(fb->POSNEG.value, -2);   // -9 / 4
    EXPECT_EQ(fb->NEGNEG.value, 2);    // 9 / 4
    EXPECT_EQ(fb->POSPOS.value, 2);    // -9 / -4
    EXPECT_EQ(fb->SINTQ.value, 2);     // 9 / 4
    EXPECT_EQ(fb->INTQ.value, -3000);  // 9000 / -3
}

TEST(ConformanceIntegers, ModTakesTheSignOfTheDividend) {
    auto fb = PAC_FB(CONF_INTMODSIGN);
    fb();  // Num = -7, Den = 2
    EXPECT_EQ(fb->NEGPOS.value, -1);   // -7 MOD 2
    EXPECT_EQ(fb->POSNEG.value, 1);    // 7 MOD -2
    EXPECT_EQ(fb->NEGNEG.value, -1);   // -7 MOD -2
    EXPECT_EQ(fb->POSPOS.value, 1);    // 7 MOD 2
    EXPECT_EQ(fb->SINTM.value, -3);    // -7 MOD 4
    EXPECT_EQ(fb->INTM.value, -1);     // -7000 MOD -3
    EXPECT_EQ(fb->UDINTM.value, 5u);   // 4294967295 MOD 10
    EXPECT_EQ(fb->CONSTM.value, -1);   // folded at translation: same rule
    fb->NUM.value = 9;
    fb->DEN.value = -4;
    fb();
    EXPECT_EQ(fb->NEGPOS.value, 1);    // 9 MOD -4
    EXPECT_EQ(fb->POSNEG.value, -1);   // -9 MOD 4
    EXPECT_EQ(fb->NEGNEG.value, 1);    // 9 MOD 4
    EXPECT_EQ(fb->POSPOS.value, -1);   // -9 MOD -4
    EXPECT_EQ(fb->SINTM.value, 1);     // 9 MOD 4
    EXPECT_EQ(fb->INTM.value, 0);      // 9000 MOD -3
}

TEST(ConformanceIntegers, OperatorPrecedenceAndAssociativity) {
    auto fb = PAC_FB(CONF_INTPRECEDENCE);
    fb();  // Two = 2, Three = 3, Four = 4
    EXPECT_EQ(fb->MULFIRST.value, 14);
    EXPECT_EQ(fb->LEFTTORIGHT.value, -5);
    EXPECT_EQ(fb->DIVLEFT.value, 12);  // (100 / 4) / 2, not 100 / (4 / 2)
    EXPECT_EQ(fb->PARENS.value, 20);
    EXPECT_EQ(fb->NEGMUL.value, -5);   // (-2 * 3) + (4 MOD 3)
    EXPECT_TRUE(fb->CMPAFTERADD.value);
}

}  // namespace
