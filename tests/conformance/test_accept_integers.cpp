// Integer semantics of translated ST: wrap-around, division, conversions.
#include <gtest/gtest.h>

#include "POUS.h"
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

}  // namespace
