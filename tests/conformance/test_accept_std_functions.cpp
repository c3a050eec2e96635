// Standard functions in translated ST: ABS, MIN, MAX, LIMIT, SEL.
#include <gtest/gtest.h>

#include <cstdint>

#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"

namespace {

TEST(ConformanceStdFunctions, AbsMinMax) {
    auto fb = PAC_FB(CONF_STDABSMINMAX);
    fb();
    EXPECT_EQ(fb->ABSINT.value, 7);
    EXPECT_EQ(fb->ABSDINT.value, 2147483647);
    EXPECT_EQ(fb->ABSREAL.value, 2.5f);
    EXPECT_EQ(fb->ABSLREAL.value, 0.125);
    EXPECT_EQ(fb->ABSPOS.value, 3);
    EXPECT_EQ(fb->MININT.value, -7);
    EXPECT_EQ(fb->MAXINT.value, 3);
    EXPECT_EQ(fb->MINUDINT.value, 5u);
    EXPECT_EQ(fb->MAXUDINT.value, 4000000000u);  // unsigned order
    EXPECT_EQ(fb->MINREAL.value, -2.5f);
    EXPECT_EQ(fb->MAXLIT.value, -7);
    EXPECT_EQ(fb->MAXWORD.value, 0x8000);
    EXPECT_EQ(fb->MINFORMAL.value, -7);
    fb->I.value = -32768;  // ABS of the minimum overflows and wraps
    fb->R.value = 3.0f;
    fb();
    EXPECT_EQ(fb->ABSINT.value, -32768);
    EXPECT_EQ(fb->ABSREAL.value, 3.0f);
    EXPECT_EQ(fb->MINREAL.value, 0.0f);
}

TEST(ConformanceStdFunctions, LimitAndSel) {
    auto fb = PAC_FB(CONF_STDLIMITSEL);
    fb->X.value = -20;
    fb->R.value = -0.5f;
    fb->G.value = 0;
    fb();
    EXPECT_EQ(fb->CLAMPED.value, -10);
    EXPECT_EQ(fb->CLAMPEDREAL.value, 0.0f);
    EXPECT_EQ(fb->CLAMPEDFORMAL.value, 0);
    EXPECT_EQ(fb->SELECTED.value, -20);  // G = FALSE: IN0
    EXPECT_EQ(fb->SELECTEDTIME.value.tv_sec, 1);
    EXPECT_EQ(fb->SELECTEDFORMAL.value, -0.5f);
    fb->X.value = 150;
    fb->R.value = 2.0f;
    fb->G.value = 1;
    fb();
    EXPECT_EQ(fb->CLAMPED.value, 10);
    EXPECT_EQ(fb->CLAMPEDREAL.value, 1.0f);
    EXPECT_EQ(fb->CLAMPEDFORMAL.value, 100);
    EXPECT_EQ(fb->SELECTED.value, 42);  // G = TRUE: IN1
    EXPECT_EQ(fb->SELECTEDTIME.value.tv_sec, 2);
    EXPECT_EQ(fb->SELECTEDFORMAL.value, -2.0f);
    fb->X.value = 5;
    fb->R.value = 0.25f;
    fb();
    EXPECT_EQ(fb->CLAMPED.value, 5);
    EXPECT_EQ(fb->CLAMPEDREAL.value, 0.25f);
    EXPECT_EQ(fb->CLAMPEDFORMAL.value, 5);
}

}  // namespace
