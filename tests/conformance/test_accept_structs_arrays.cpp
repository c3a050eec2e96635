// Structured types of translated ST: structs, arrays with any lower bound, their combinations, enums.
#include <gtest/gtest.h>

#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"

namespace {

TEST(ConformanceStructsArrays, StructDefaultsNestingAndWholeAssignment) {
    auto fb = PAC_FB(CONF_STRUCTNESTED);
    // The TYPE's member defaults are in place before the first call, in nested structs too.
    EXPECT_EQ(fb->SEG.value.STARTPT.X, 3);
    EXPECT_EQ(fb->SEG.value.STARTPT.Y, -4);
    EXPECT_EQ(fb->SEG.value.ENDPT.X, 3);
    EXPECT_EQ(fb->SEG.value.ENDPT.Y, -4);
    EXPECT_EQ(fb->SEG.value.WIDTH, 1.5f);
    EXPECT_EQ(fb->SEG.value.VISIBLE, 1);
    EXPECT_EQ(fb->SEG.value.TAG, 0);
    fb->SHIFT.value = 10;
    fb();
    EXPECT_EQ(fb->SEG.value.ENDPT.X, 13);
    EXPECT_EQ(fb->SEG.value.STARTPT.Y, 100);
    EXPECT_EQ(fb->COPY.value.STARTPT.Y, -4);  // the copy was taken before the change
    EXPECT_EQ(fb->COPY.value.ENDPT.X, 13);
    EXPECT_EQ(fb->COPY.value.WIDTH, 1.5f);
    EXPECT_EQ(fb->COPY.value.VISIBLE, 1);
    EXPECT_EQ(fb->COPY.value.TAG, 0xBEEF);
    EXPECT_EQ(fb->PT.value.X, 13);
    EXPECT_EQ(fb->PT.value.Y, -4);
    EXPECT_EQ(fb->COPYINDEPENDENT.value, 1);
}

TEST(ConformanceStructsArrays, NonZeroAndNegativeLowerBounds) {
    auto fb = PAC_FB(CONF_ARRAYBOUNDS);
    fb();  // Idx = -2
    for (int i = 3; i <= 7; ++i) {
        EXPECT_EQ(fb->LOW.value.table[i - 3], i * 10) << "Low[" << i << "]";
    }
    EXPECT_EQ(fb->NEG.value.table[-2 - (-2)], -2000);
    EXPECT_EQ(fb->NEG.value.table[-1 - (-2)], -1);  // Neg[Idx + 1] := -1
    EXPECT_EQ(fb->NEG.value.table[0 - (-2)], 0);
    EXPECT_EQ(fb->NEG.value.table[1 - (-2)], 1000);
    EXPECT_EQ(fb->NEG.value.table[2 - (-2)], 2000);
    EXPECT_EQ(fb->ATIDX.value, -2000);
    EXPECT_EQ(fb->SUMLOW.value, 100);
    fb->IDX.value = 1;
    fb();
    EXPECT_EQ(fb->ATIDX.value, 1000);
    EXPECT_EQ(fb->NEG.value.table[-1 - (-2)], -1000);
    EXPECT_EQ(fb->NEG.value.table[2 - (-2)], -1);
}

TEST(ConformanceStructsArrays, ArrayOfStruct) {
    auto fb = PAC_FB(CONF_ARRAYOFSTRUCT);
    for (int i = 1; i <= 4; ++i) {
        EXPECT_EQ(fb->ITEMS.value.table[i - 1].ID, 7) << "each element gets the TYPE default";
    }
    fb();  // Pick = 2
    EXPECT_EQ(fb->ITEMS.value.table[2 - 1].ID, 42);
    EXPECT_EQ(fb->ITEMS.value.table[2 - 1].PRESENT, 1);
    EXPECT_EQ(fb->ITEMS.value.table[3 - 1].ID, 7);
    EXPECT_EQ(fb->ITEMS.value.table[3 - 1].WEIGHT, 1.5f);
    EXPECT_EQ(fb->ITEMS.value.table[3 - 1].PRESENT, 0);
    EXPECT_EQ(fb->TOTAL.value, 5.0f);
    EXPECT_EQ(fb->PICKED.value.ID, 42);
    EXPECT_EQ(fb->PICKED.value.WEIGHT, 1.0f);
    EXPECT_EQ(fb->PICKED.value.PRESENT, 1);
    EXPECT_EQ(fb->ITEMS.value.table[4 - 1].ID, 7);  // Items[4] := Items[1]
    EXPECT_EQ(fb->ITEMS.value.table[4 - 1].WEIGHT, 0.5f);
}

TEST(ConformanceStructsArrays, StructContainingAnArray) {
    auto fb = PAC_FB(CONF_STRUCTWITHARRAY);
    EXPECT_EQ(fb->REC.value.SCALE, 2.0);
    fb->NEWSAMPLE.value = 5;
    fb();
    EXPECT_EQ(fb->REC.value.COUNT, 1);
    EXPECT_EQ(fb->SNAPSHOT.value.SAMPLES.table[0], 5);  // the whole array was copied
    EXPECT_EQ(fb->REC.value.SAMPLES.table[0], 0);
    EXPECT_EQ(fb->SCALED.value, 10.0);
    fb->NEWSAMPLE.value = 7;
    fb();
    EXPECT_EQ(fb->REC.value.COUNT, 2);
    EXPECT_EQ(fb->REC.value.SAMPLES.table[1], 7);
    EXPECT_EQ(fb->SNAPSHOT.value.COUNT, 2);
    EXPECT_EQ(fb->SNAPSHOT.value.SAMPLES.table[0], 0);
    EXPECT_EQ(fb->SNAPSHOT.value.SAMPLES.table[1], 7);
    EXPECT_EQ(fb->SCALED.value, 0.0);
}

TEST(ConformanceStructsArrays, EnumDefaultAssignmentAndComparison) {
    auto fb = PAC_FB(CONF_ENUMBASIC);
    EXPECT_EQ(fb->COLOUR.value, E_CONFCOLOUR__CONF_COL_RED);  // the first value is the default
    EXPECT_EQ(fb->INITIAL.value, E_CONFCOLOUR__CONF_COL_BLUE);
    fb();
    EXPECT_EQ(fb->ISRED.value, 1);
    EXPECT_EQ(fb->NOTBLUE.value, 1);
    EXPECT_EQ(fb->SAMEASINITIAL.value, 0);
    fb->ADVANCE.value = 1;
    fb();
    EXPECT_EQ(fb->COLOUR.value, E_CONFCOLOUR__CONF_COL_GREEN);
    EXPECT_EQ(fb->ISRED.value, 0);
    EXPECT_EQ(fb->NOTBLUE.value, 1);
    fb();
    EXPECT_EQ(fb->COLOUR.value, E_CONFCOLOUR__CONF_COL_BLUE);
    EXPECT_EQ(fb->NOTBLUE.value, 0);
    EXPECT_EQ(fb->SAMEASINITIAL.value, 1);
    fb();
    EXPECT_EQ(fb->COLOUR.value, E_CONFCOLOUR__CONF_COL_RED);
    EXPECT_EQ(fb->ISRED.value, 1);
}

}  // namespace
