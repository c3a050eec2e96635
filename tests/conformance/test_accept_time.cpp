// TIME semantics of translated ST: literals, addition and subtraction, comparison.
#include <gtest/gtest.h>

#include "matiec_deviations.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/st_program.hpp"

namespace {

using pac::test::kTimeLiteralShortfall;

// The value of a TIME, sec + nsec. pacst keeps tv_nsec in [0, 1e9) with the sign in tv_sec; MATIEC gives
// a negative TIME a negative tv_nsec ({0, -250000000} for T#-250MS), so the tests compare values.
void ExpectTime(const TIME& t, long sec, long nsec) {
    const std::chrono::nanoseconds want = std::chrono::seconds(sec) + std::chrono::nanoseconds(nsec);
    const std::chrono::nanoseconds got = pac::FromIecTime(t);
    EXPECT_LE(got, want);
    EXPECT_GE(got, want - kTimeLiteralShortfall);
}

TEST(ConformanceTime, Literals) {
    auto fb = PAC_FB(CONF_TIMELITERALS);
    fb();
    {
        SCOPED_TRACE("T#1S500MS");
        ExpectTime(fb->SECMS.value, 1, 500000000);
    }
    {
        SCOPED_TRACE("T#1.5S");
        ExpectTime(fb->FRACSEC.value, 1, 500000000);
    }
    {
        SCOPED_TRACE("T#-250MS");
        ExpectTime(fb->NEGMS.value, -1, 750000000);
    }
    {
        SCOPED_TRACE("TIME#1D2H");
        ExpectTime(fb->DAYHOUR.value, 26 * 3600, 0);
    }
    {
        SCOPED_TRACE("T#0S");
        ExpectTime(fb->ZERO.value, 0, 0);
    }
    {
        SCOPED_TRACE("T#1M30S");
        ExpectTime(fb->MINSEC.value, 90, 0);
    }
    {
        SCOPED_TRACE("t#1h");
        ExpectTime(fb->HOUR.value, 3600, 0);
    }
    {
        SCOPED_TRACE("T#2.5MS");
        ExpectTime(fb->FRACMS.value, 0, 2500000);
    }
    {
        SCOPED_TRACE("T#1s_200ms");
        ExpectTime(fb->UNDERSCORED.value, 1, 200000000);
    }
}

TEST(ConformanceTime, AddSubtractCompare) {
    auto fb = PAC_FB(CONF_TIMEARITH);
    fb();  // A = 1.7 s, B = 0.8 s
    {
        SCOPED_TRACE("A + B");
        ExpectTime(fb->SUM.value, 2, 500000000);
    }
    {
        SCOPED_TRACE("A - B");
        ExpectTime(fb->DIFF.value, 0, 900000000);
    }
    {
        SCOPED_TRACE("B - A");
        ExpectTime(fb->NEGDIFF.value, -1, 100000000);  // -0.9 s
    }
    {
        SCOPED_TRACE("A + B + 1 d - 23 h 59 min 59 s");
        ExpectTime(fb->CHAIN.value, 3, 500000000);
    }
    EXPECT_EQ(fb->SUMISTWOANDHALF.value, 1);
    EXPECT_EQ(fb->NEGISNEGATIVE.value, 1);
    EXPECT_EQ(fb->CHAINGTSUM.value, 1);
    fb->A.value = {0, 0};
    fb->B.value = {0, 1};  // 1 ns
    fb();
    ExpectTime(fb->NEGDIFF.value, 0, 1);
    ExpectTime(fb->DIFF.value, -1, 999999999);
    EXPECT_EQ(fb->NEGISNEGATIVE.value, 0);
    EXPECT_EQ(fb->SUMISTWOANDHALF.value, 0);
}

TEST(ConformanceTime, Comparisons) {
    auto fb = PAC_FB(CONF_COMPAREOTHER);
    fb();  // T1 = 1 s, T2 = 999 ms
    EXPECT_EQ(fb->TIMEGT.value, 1);
    EXPECT_EQ(fb->TIMELT.value, 0);
    EXPECT_EQ(fb->TIMELE.value, 1);
    EXPECT_EQ(fb->TIMEGE.value, 0);
    EXPECT_EQ(fb->TIMEEQ.value, 1);
    EXPECT_EQ(fb->TIMENE.value, 1);
    EXPECT_EQ(fb->TIMENEGLT.value, 1);
    fb->T2.value = {1, 0};
    fb();
    EXPECT_EQ(fb->TIMEGT.value, 0);
    EXPECT_EQ(fb->TIMELT.value, 0);
    EXPECT_EQ(fb->TIMEGE.value, 1);
    EXPECT_EQ(fb->TIMENE.value, 0);
    fb->T1.value = {-1, 500000000};  // -0.5 s
    fb();
    EXPECT_EQ(fb->TIMEGT.value, 0);
    EXPECT_EQ(fb->TIMELT.value, 1);
    EXPECT_EQ(fb->TIMELE.value, 1);
    EXPECT_EQ(fb->TIMEEQ.value, 0);
}

}  // namespace
