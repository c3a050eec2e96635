// Comparisons of translated ST on every elementary type (TIME in test_accept_time.cpp).
#include <gtest/gtest.h>

#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"

namespace {

TEST(ConformanceComparisons, SignedAndUnsignedIntegers) {
    auto fb = PAC_FB(CONF_COMPAREINTS);
    fb();
    EXPECT_EQ(fb->SINTLT.value, 1);   // -1 < 1
    EXPECT_EQ(fb->SINTGE.value, 0);
    EXPECT_EQ(fb->INTLE.value, 1);    // -300 <= 300
    EXPECT_EQ(fb->INTEQ.value, 1);
    EXPECT_EQ(fb->INTNE.value, 1);
    EXPECT_EQ(fb->DINTLT.value, 1);   // -2^31 < 2^31 - 1
    EXPECT_EQ(fb->DINTGT.value, 0);
    EXPECT_EQ(fb->USINTGT.value, 1);  // 255 > 1: no sign confusion
    EXPECT_EQ(fb->UINTGE.value, 1);   // 65535 >= 32768
    EXPECT_EQ(fb->UINTLE.value, 0);
    EXPECT_EQ(fb->UDINTGT.value, 1);  // 4000000000 > 1
    EXPECT_EQ(fb->UDINTEQ.value, 1);
    EXPECT_EQ(fb->LITLT.value, 0);    // -5 < -300 is FALSE
    fb->S1.value = 1;
    fb->I1.value = 300;
    fb->UI1.value = 32768;
    fb();
    EXPECT_EQ(fb->SINTLT.value, 0);
    EXPECT_EQ(fb->SINTGE.value, 1);
    EXPECT_EQ(fb->INTLE.value, 1);    // 300 <= 300
    EXPECT_EQ(fb->INTEQ.value, 0);
    EXPECT_EQ(fb->INTNE.value, 0);
    EXPECT_EQ(fb->UINTGE.value, 1);
    EXPECT_EQ(fb->UINTLE.value, 1);
    EXPECT_EQ(fb->LITLT.value, 1);
}

TEST(ConformanceComparisons, BitStringsRealsAndBools) {
    auto fb = PAC_FB(CONF_COMPAREOTHER);
    fb();
    EXPECT_EQ(fb->BYTEGT.value, 1);       // 16#FF > 16#01
    EXPECT_EQ(fb->WORDGT.value, 1);       // 16#8000 > 16#7FFF: bit strings are unsigned
    EXPECT_EQ(fb->WORDEQ.value, 1);
    EXPECT_EQ(fb->DWORDGE.value, 1);
    EXPECT_EQ(fb->DWORDNE.value, 1);
    EXPECT_EQ(fb->REALLT.value, 1);       // -0.5 < 0.25
    EXPECT_EQ(fb->REALGE.value, 0);
    EXPECT_EQ(fb->REALEQLIT.value, 1);
    EXPECT_EQ(fb->LREALEQLIT.value, 1);   // LREAL 0.1 = the literal 0.1 as LREAL
    EXPECT_EQ(fb->LREALNEREAL.value, 1);  // 0.1 <> 0.1 rounded to REAL and back
    EXPECT_EQ(fb->BOOLEQ.value, 0);
    EXPECT_EQ(fb->BOOLNE.value, 1);
    fb->B2.value = 1;
    fb->R1.value = 0.25f;
    fb->W2.value = 0x8000;
    fb();
    EXPECT_EQ(fb->BOOLEQ.value, 1);
    EXPECT_EQ(fb->BOOLNE.value, 0);
    EXPECT_EQ(fb->REALLT.value, 0);
    EXPECT_EQ(fb->REALGE.value, 1);
    EXPECT_EQ(fb->WORDGT.value, 0);
}

}  // namespace
