// Calls in translated ST: FUNCTIONs (formal, positional, outputs, in-outs, defaults, nesting) and
// nested FUNCTION_BLOCK instances (inputs, outputs, in-outs).
#include <gtest/gtest.h>

#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"
#include "matiec_deviations.hpp"

namespace {

TEST(ConformanceCalls, FormalAndPositionalFunctionCalls) {
    auto fb = PAC_FB(CONF_FUNCCALLSTYLES);
    fb();  // A = 1, B = 2, C = 3
    EXPECT_EQ(fb->POSITIONAL.value, 123);
    EXPECT_EQ(fb->FORMAL.value, 123);
    EXPECT_EQ(fb->FORMALREORDERED.value, 321);  // Ones := A, Hundreds := C, Tens := B
    EXPECT_EQ(fb->INEXPRESSION.value, 531);     // 2 * 321 - 111
    EXPECT_EQ(fb->ASCONDITION.value, 1);
    fb->A.value = 0;
    fb();
    EXPECT_EQ(fb->POSITIONAL.value, 23);
    EXPECT_EQ(fb->ASCONDITION.value, 0);
}

TEST(ConformanceCalls, FunctionOutputsAndPerCallLocals) {
    auto fb = PAC_FB(CONF_FUNCOUTPUTS);
    fb();  // Num = 17, Den = 5
    EXPECT_EQ(fb->OK.value, 1);  // the local VAR Calls starts at 100 in every call
    EXPECT_EQ(fb->QUOT.value, 3);
    EXPECT_EQ(fb->REM.value, 2);
    EXPECT_EQ(fb->ONLYQUOT.value, -3);
    EXPECT_EQ(fb->SECONDOK.value, 1);
    EXPECT_EQ(fb->VISITS.value, 6);  // the output starts at its initial value 5, not at the caller's 100
    EXPECT_EQ(fb->UNSET.value, -1);  // an output the FUNCTION leaves alone gives its initial value
    EXPECT_EQ(fb->WASSET.value, 0);
    fb();
    EXPECT_EQ(fb->VISITS.value, 6);
    fb->NUM.value = -17;
    fb();
    EXPECT_EQ(fb->WASSET.value, 1);
    EXPECT_EQ(fb->UNSET.value, 1);
    EXPECT_EQ(fb->QUOT.value, -3);
    EXPECT_EQ(fb->REM.value, -2);
    fb->DEN.value = 0;
    fb();
    EXPECT_EQ(fb->OK.value, 0);
    EXPECT_EQ(fb->QUOT.value, 0);
    EXPECT_EQ(fb->REM.value, 0);
}

TEST(ConformanceCalls, FunctionModifiesInOutArray) {
    auto fb = PAC_FB(CONF_FUNCINOUTARRAY);
    fb();  // Start = 100
    for (int i = 1; i <= 5; ++i) {
        EXPECT_EQ(fb->DATA.value.table[i - 1], 100 + i) << "Data[" << i << "]";
    }
    EXPECT_EQ(fb->LASTRETURNED.value, 105);
    fb();
    for (int i = 1; i <= 5; ++i) {
        EXPECT_EQ(fb->DATA.value.table[i - 1], 2 * (100 + i)) << "Data[" << i << "]";
    }
    EXPECT_EQ(fb->LASTRETURNED.value, 210);
}

TEST(ConformanceCalls, OmittedInputsTakeTheirInitialValues) {
    auto fb = PAC_FB(CONF_FUNCDEFAULTS);
    fb();  // X = 10
    EXPECT_EQ(fb->ALLDEFAULTS.value, 23);  // 10 * 3 - 7 + 0
    EXPECT_EQ(fb->GAINGIVEN.value, 43);    // 10 * 5 - 7
    EXPECT_EQ(fb->OFFSETGIVEN.value, 30);
    EXPECT_EQ(fb->DISABLED.value, 0);
    EXPECT_EQ(fb->NOINITGIVEN.value, 1023);
}

TEST(ConformanceCalls, FunctionCallingFunctionAndNestedCalls) {
    auto fb = PAC_FB(CONF_FUNCNESTED);
    fb();  // A = 3, B = 4
    EXPECT_EQ(fb->SUMSQ.value, 25);
    EXPECT_EQ(fb->NESTED.value, 49);   // (9 - 2)^2
    EXPECT_EQ(fb->WITHSTD.value, 23);  // MAX(9, 16) + ABS(9 - 16)
}

TEST(ConformanceCalls, StructsPassByValueAndOmittedStructTakesTypeDefaults) {
    auto fb = PAC_FB(CONF_FUNCSTRUCTINPUT);
    fb();
    EXPECT_EQ(fb->GIVEN.value, 4060);
    EXPECT_EQ(fb->SUMOUT.value.X, 40);
    EXPECT_EQ(fb->SUMOUT.value.Y, 60);
    EXPECT_EQ(fb->OMITTED.value, 1122);  // B = (X := 1, Y := 2) from the TYPE
    EXPECT_EQ(fb->UNCHANGED.value.X, 10);
    EXPECT_EQ(fb->UNCHANGED.value.Y, 20);
}

TEST(ConformanceCalls, NestedFunctionBlockInstances) {
    auto fb = PAC_FB(CONF_FBNESTED);
    fb();  // Stride = 5
    EXPECT_EQ(fb->FIRST.value, 5);
    EXPECT_EQ(fb->OUTVIAARROW.value, 5);
    EXPECT_EQ(fb->SECOND.value, 30);  // inputs written as AccB.Amount := 10, AccB.Gain := 3
    EXPECT_EQ(fb->SECONDCALLS.value, 1);
    fb();
    EXPECT_EQ(fb->FIRST.value, 10);  // each instance keeps its own state
    EXPECT_EQ(fb->SECOND.value, 60);
    EXPECT_EQ(fb->SECONDCALLS.value, 2);
    fb->CLEAR.value = 1;
    fb();
    EXPECT_EQ(fb->FIRST.value, 0);
    EXPECT_EQ(fb->OUTVIAARROW.value, 0);
    EXPECT_EQ(fb->SECOND.value, 0);
    EXPECT_EQ(fb->SECONDCALLS.value, 3);
}

TEST(ConformanceCalls, FunctionBlockInOutArrayAndStructChangeTheCallers) {
    auto fb = PAC_FB(CONF_FBINOUT);
    fb->VALUE.value = 7;
    fb();
    EXPECT_EQ(fb->SEENFIRST.value, 1000);  // the callee saw the caller's change made before the call
    const INT after1[] = {7, 1000, 0, 0};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(fb->QUEUE.value.table[i], after1[i]) << "Queue[" << i << "]";
    }
    EXPECT_EQ(fb->STATS.value.PUSHES, 1);
    EXPECT_EQ(fb->STATS.value.TAG, 9);
    fb->VALUE.value = 8;
    fb();
    EXPECT_EQ(fb->SEENFIRST.value, 1007);
    const INT after2[] = {8, 1007, 1000, 0};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(fb->QUEUE.value.table[i], after2[i]) << "Queue[" << i << "]";
    }
    EXPECT_EQ(fb->STATS.value.PUSHES, 2);
}

TEST(ConformanceCalls, FunctionBlockInOutIsTheCallersVariable) {
    auto fb = PAC_FB(CONF_FBINOUTREFERENCE);
    fb->AMOUNT.value = 3;
    fb->OUTER.value.TOTAL = 100;
    fb();
    EXPECT_EQ(fb->SEENBETWEEN.value, 3);  // the inner FB's write, seen by the FB that passed the in-out on
    EXPECT_EQ(fb->LEDGER.value.TOTAL, 33);
    EXPECT_EQ(fb->LEDGER.value.WRITES, 2);
    EXPECT_EQ(fb->OUTER.value.TOTAL, 111);  // passed on two levels down from the C caller's member
    EXPECT_EQ(fb->OUTER.value.WRITES, 2);
    EXPECT_EQ(fb->APART.value, 1);
    EXPECT_EQ(fb->OTHER.value, 10);
    // One variable to both in-outs: written through both; MATIEC copies each back, the last one wins.
    EXPECT_EQ(fb->SHARED.value, pac::test::kMatiecBackend ? 10 : 11);
    fb();
    EXPECT_EQ(fb->SEENBETWEEN.value, 36);
    EXPECT_EQ(fb->LEDGER.value.TOTAL, 66);
    EXPECT_EQ(fb->OUTER.value.TOTAL, 122);
    EXPECT_EQ(fb->SHARED.value, pac::test::kMatiecBackend ? 20 : 22);
}

}  // namespace
