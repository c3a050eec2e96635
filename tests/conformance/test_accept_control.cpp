// Control statements of translated ST: IF, CASE, WHILE, REPEAT, EXIT, CONTINUE, RETURN (FOR is refused:
// MATIEC miscompiles it).
#include <gtest/gtest.h>

#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"

namespace {

TEST(ConformanceControl, IfElsifElse) {
    struct Case {
        INT x, branch, noElse, nested;
    };
    const Case cases[] = {
        {-5, -1, 7, 0}, {0, 0, 7, 1}, {3, 1, 7, 1}, {4, 1, 7, 2}, {10, 2, 7, 2}, {101, 2, 8, 2},
    };
    auto fb = PAC_FB(CONF_IFELSIF);
    for (const Case& c : cases) {
        fb->X.value = c.x;
        fb();
        EXPECT_EQ(fb->BRANCH.value, c.branch) << "X = " << c.x;
        EXPECT_EQ(fb->NOELSE.value, c.noElse) << "X = " << c.x;
        EXPECT_EQ(fb->NESTED.value, c.nested) << "X = " << c.x;
    }
}

TEST(ConformanceControl, CaseOnIntWithListsRangesNegativesAndElse) {
    struct Case {
        INT selector, result;
    };
    const Case cases[] = {
        {1, 10},   {2, 20},   {3, 20},   {5, 20},   {4, 99},   {6, 30},   {9, 30},   {12, 30},     {10, 99},
        {13, 99},  {-5, 40},  {-3, 40},  {-2, 40},  {-1, 99},  {-6, 99},  {-10, 50}, {-7, 50},     {-8, 99},
        {-32768, 60}, {32767, 70}, {0, 99},
    };
    auto fb = PAC_FB(CONF_CASEINT);
    for (const Case& c : cases) {
        fb->SELECTOR.value = c.selector;
        fb();
        EXPECT_EQ(fb->RESULT.value, c.result) << "CASE " << c.selector;
    }
}

TEST(ConformanceControl, CaseOnDintWithoutElseChangesNothing) {
    auto fb = PAC_FB(CONF_CASEDINT);
    fb->SELECTOR.value = 5;
    fb();
    EXPECT_EQ(fb->RESULT.value, -1);  // no label matches, no ELSE: the initial value stays
    EXPECT_EQ(fb->HITS.value, 100);   // 10 goes to the ELSE of the second CASE
    struct Step {
        DINT selector, result, hits;
    };
    const Step steps[] = {
        {0, 3, 101},
        {100000, 1, 111},
        {150000, 1, 211},          // 300000: ELSE
        {-1000000, 2, 311},
        {-999999, 2, 411},         // first CASE: no match, Result keeps 2
        {2147483647, 3, 511},      // * 2 wraps to -2: ELSE
        {-2147483647 - 1, 2, 512}, // * 2 wraps to 0
    };
    for (const Step& s : steps) {
        fb->SELECTOR.value = s.selector;
        fb();
        EXPECT_EQ(fb->RESULT.value, s.result) << "CASE " << s.selector;
        EXPECT_EQ(fb->HITS.value, s.hits) << "CASE " << s.selector;
    }
}

TEST(ConformanceControl, CaseOnEnum) {
    struct Case {
        E_CONFMODE mode;
        INT speed;
        E_CONFMODE next;
    };
    const Case cases[] = {
        {E_CONFMODE__CONF_MODE_OFF, 0, E_CONFMODE__CONF_MODE_MANUAL},
        {E_CONFMODE__CONF_MODE_MANUAL, 10, E_CONFMODE__CONF_MODE_AUTO},
        {E_CONFMODE__CONF_MODE_SERVICE, 10, E_CONFMODE__CONF_MODE_AUTO},
        {E_CONFMODE__CONF_MODE_AUTO, 100, E_CONFMODE__CONF_MODE_OFF},
        {E_CONFMODE__CONF_MODE_FAULT, -1, E_CONFMODE__CONF_MODE_FAULT},
    };
    auto fb = PAC_FB(CONF_CASEENUM);
    for (const Case& c : cases) {
        fb->MODE.value = c.mode;
        fb();
        EXPECT_EQ(fb->SPEED.value, c.speed) << "mode " << static_cast<int>(c.mode);
        EXPECT_EQ(fb->NEXT.value, c.next) << "mode " << static_cast<int>(c.mode);
    }
}

TEST(ConformanceControl, WhileWithExit) {
    auto fb = PAC_FB(CONF_WHILEEXIT);
    fb();  // MaxCount = 10, StopAt = 100
    EXPECT_EQ(fb->COUNT.value, 10);
    EXPECT_EQ(fb->SUM.value, 55);
    EXPECT_EQ(fb->NEVERRAN.value, 1);  // WHILE FALSE never runs its body
    fb->STOPAT.value = 4;
    fb();
    EXPECT_EQ(fb->COUNT.value, 4);
    EXPECT_EQ(fb->SUM.value, 6);  // 1 + 2 + 3: EXIT skips the rest of the pass
    fb->MAXCOUNT.value = -5;
    fb();
    EXPECT_EQ(fb->COUNT.value, 0);
    EXPECT_EQ(fb->SUM.value, 0);
}

TEST(ConformanceControl, RepeatWithContinueAndExit) {
    auto fb = PAC_FB(CONF_REPEATLOOP);
    fb();  // MaxCount = 10, StopAt = 100
    EXPECT_EQ(fb->COUNT.value, 10);
    EXPECT_EQ(fb->PASSES.value, 10);  // CONTINUE goes to UNTIL, which ends the loop at 10
    EXPECT_EQ(fb->ODDSUM.value, 25);  // 1 + 3 + 5 + 7 + 9
    EXPECT_EQ(fb->ONCEPASSES.value, 1);
    fb->MAXCOUNT.value = 0;
    fb();
    EXPECT_EQ(fb->COUNT.value, 1);  // the body runs once before UNTIL is tested
    EXPECT_EQ(fb->PASSES.value, 1);
    EXPECT_EQ(fb->ODDSUM.value, 1);
    fb->MAXCOUNT.value = 10;
    fb->STOPAT.value = 5;
    fb();
    EXPECT_EQ(fb->COUNT.value, 5);
    EXPECT_EQ(fb->PASSES.value, 5);
    EXPECT_EQ(fb->ODDSUM.value, 4);  // 1 + 3: EXIT at 5 before adding it
}

TEST(ConformanceControl, ExitLeavesOnlyTheInnerLoop) {
    auto fb = PAC_FB(CONF_NESTEDEXIT);
    fb();
    EXPECT_EQ(fb->OUTER.value, 4);
    EXPECT_EQ(fb->INNER.value, 4);
    EXPECT_EQ(fb->TOTAL.value, 10);      // 1 + 2 + 3 + 4
    EXPECT_EQ(fb->NESTEDTOTAL.value, 306);  // (1 + 2 + 3) inner passes + 3 * 100 outer passes
}

TEST(ConformanceControl, ReturnInFunctionBlockAndFunction) {
    auto fb = PAC_FB(CONF_RETURNEARLY);
    fb->X.value = 3;
    fb();
    EXPECT_EQ(fb->FROMFUNCTION.value, 6);
    EXPECT_EQ(fb->BEFORE.value, 3);
    EXPECT_EQ(fb->LOOPRETURN.value, 3);  // RETURN from inside the loop
    EXPECT_EQ(fb->AFTER.value, 0);       // never reached
    fb->X.value = -2;
    fb();
    EXPECT_EQ(fb->FROMFUNCTION.value, 0);  // the FUNCTION returned the result assigned before RETURN
    EXPECT_EQ(fb->BEFORE.value, -2);
    EXPECT_EQ(fb->LOOPRETURN.value, 10);
    EXPECT_EQ(fb->AFTER.value, 0);
    fb->X.value = 20;
    fb();
    EXPECT_EQ(fb->FROMFUNCTION.value, 40);
    EXPECT_EQ(fb->AFTER.value, 20);
    fb->X.value = 5;
    fb();
    EXPECT_EQ(fb->BEFORE.value, 5);
    EXPECT_EQ(fb->LOOPRETURN.value, 5);
    EXPECT_EQ(fb->AFTER.value, 20);  // unchanged: the body returned first
}

}  // namespace
