// The standard function blocks of pacst_iec.h (R_TRIG, F_TRIG, TON, TOF, TP) driven scan by scan
// through PlcTask with a 1 ms cycle, checked against IEC 61131-3 and MATIEC's timing.
#include <chrono>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "pac/iec_time.hpp"
#include "pac/scan_test.hpp"
#include "pacst_iec.h"

using namespace std::chrono_literals;

namespace {

double Millis(const TIME& t) { return std::chrono::duration<double, std::milli>(pac::FromIecTime(t)).count(); }

// ---- Edge detectors: CLK comes from a per-scan sequence, Q is recorded after each body call. ----

template <typename Trig>
class TrigTest : public pac::ScanTest {
protected:
    // Runs one scan per element of clk and returns Q of each scan.
    std::vector<int> Run(void (*body)(Trig*), const std::vector<int>& clk) {
        std::vector<int> q;
        task_.AddProgram([&] {
            trig.CLK.value = static_cast<BOOL>(clk.at(static_cast<std::size_t>(task_.ScanCount() - 1)));
            body(&trig);
            q.push_back(trig.Q.value);
        });
        Cycle(static_cast<int>(clk.size()));
        return q;
    }

    Trig trig{};  // zeroed: _init__ does not clear the flags
};

using RTrigTest = TrigTest<R_TRIG>;
using FTrigTest = TrigTest<F_TRIG>;

TEST_F(RTrigTest, QForExactlyOneScanPerRisingEdge) {
    R_TRIG_init__(&trig, 0);
    const std::vector<int> q = Run(R_TRIG_body__, {0, 1, 1, 1, 0, 0, 1, 0, 1, 1});
    EXPECT_EQ(q, (std::vector<int>{0, 1, 0, 0, 0, 0, 1, 0, 1, 0}));
}

TEST_F(RTrigTest, ClkTrueOnTheFirstCallIsAnEdge) {
    R_TRIG_init__(&trig, 0);
    EXPECT_EQ(Run(R_TRIG_body__, {1, 1, 1}), (std::vector<int>{1, 0, 0}));
}

TEST_F(FTrigTest, QOnTheFirstCallWithClkFalseAndOnFallingEdges) {
    F_TRIG_init__(&trig, 0);
    const std::vector<int> q = Run(F_TRIG_body__, {0, 0, 1, 1, 0, 0, 1, 0, 0});
    EXPECT_EQ(q, (std::vector<int>{1, 0, 0, 0, 1, 0, 0, 1, 0}));
}

TEST_F(FTrigTest, ClkTrueOnTheFirstCallGivesNoPulse) {
    F_TRIG_init__(&trig, 0);
    EXPECT_EQ(Run(F_TRIG_body__, {1, 1, 0}), (std::vector<int>{0, 0, 1}));
}

// ---- Timers: the test sets `in` between scans; one program copies it in and calls the body. ----

class TimerTest : public pac::ScanTest {
protected:
    void Start(void (*init)(TON*, BOOL), void (*body)(TON*), std::chrono::nanoseconds pt) {
        init(&timer, 0);
        timer.PT.value = pac::ToIecTime(pt);
        task_.AddProgram([this, body] {
            timer.IN.value = in;
            body(&timer);
        });
    }

    // Sets IN, runs one scan, returns that scan's number.
    std::int64_t ScanWithIn(bool value) {
        in = value;
        Cycle(1);
        return task_.ScanCount();
    }

    TON timer{};  // TOF and TP are the same struct
    bool in = false;
};

TEST_F(TimerTest, TonQFirstTrueExactlyPtAfterInRises) {
    Start(TON_init__, TON_body__, 10ms);
    Cycle(4);
    const std::int64_t k = ScanWithIn(true);
    EXPECT_FALSE(timer.Q.value) << "Q in the scan that sees IN rise";
    ASSERT_TRUE(RunUntil([this] { return timer.Q.value != 0; }, 50, "TON.Q"));
    EXPECT_EQ(task_.ScanCount(), k + 10);
}

TEST_F(TimerTest, TonEtGrowsByTheCycleAndStopsAtPt) {
    Start(TON_init__, TON_body__, 10ms);
    Cycle(2);
    ScanWithIn(true);
    EXPECT_DOUBLE_EQ(Millis(timer.ET.value), 0.0);
    for (int j = 1; j <= 20; ++j) {
        Cycle(1);
        EXPECT_DOUBLE_EQ(Millis(timer.ET.value), j < 10 ? j : 10.0) << j << " scans after the edge";
        EXPECT_EQ(timer.Q.value != 0, j >= 10) << j << " scans after the edge";
    }
}

TEST_F(TimerTest, TonWithZeroPtStillWaitsOneScan) {
    Start(TON_init__, TON_body__, 0ns);
    Cycle(3);
    ScanWithIn(true);
    EXPECT_FALSE(timer.Q.value);
    Cycle(1);
    EXPECT_TRUE(timer.Q.value);
}

TEST_F(TimerTest, TonInFallingResetsQAndEt) {
    Start(TON_init__, TON_body__, 10ms);
    ScanWithIn(true);
    ASSERT_TRUE(RunUntil([this] { return timer.Q.value != 0; }, 50, "TON.Q"));
    ScanWithIn(false);
    EXPECT_FALSE(timer.Q.value);
    EXPECT_DOUBLE_EQ(Millis(timer.ET.value), 0.0);
}

TEST_F(TimerTest, TonInterruptedInRestartsTheFullDelay) {
    Start(TON_init__, TON_body__, 10ms);
    ScanWithIn(true);
    Cycle(5);
    ScanWithIn(false);
    EXPECT_DOUBLE_EQ(Millis(timer.ET.value), 0.0);
    const std::int64_t k = ScanWithIn(true);
    ASSERT_TRUE(RunUntil([this] { return timer.Q.value != 0; }, 50, "TON.Q"));
    EXPECT_EQ(task_.ScanCount(), k + 10);
}

TEST_F(TimerTest, TofQFollowsInUpAtOnce) {
    Start(TOF_init__, TOF_body__, 10ms);
    Cycle(3);
    EXPECT_FALSE(timer.Q.value) << "no off-delay before IN was ever TRUE";
    ScanWithIn(true);
    EXPECT_TRUE(timer.Q.value);
}

TEST_F(TimerTest, TofQStaysTruePtAfterInFalls) {
    Start(TOF_init__, TOF_body__, 10ms);
    ScanWithIn(true);
    Cycle(3);
    const std::int64_t f = ScanWithIn(false);
    EXPECT_TRUE(timer.Q.value);
    ASSERT_TRUE(RunUntil([this] { return timer.Q.value == 0; }, 50, "TOF.Q off"));
    EXPECT_EQ(task_.ScanCount(), f + 10);
    EXPECT_DOUBLE_EQ(Millis(timer.ET.value), 10.0);
}

TEST_F(TimerTest, TofInReturningDuringTheDelayKeepsQAndRestartsTheDelay) {
    Start(TOF_init__, TOF_body__, 10ms);
    ScanWithIn(true);
    ScanWithIn(false);
    Cycle(5);
    ScanWithIn(true);
    EXPECT_TRUE(timer.Q.value);
    EXPECT_DOUBLE_EQ(Millis(timer.ET.value), 0.0);
    const std::int64_t f = ScanWithIn(false);
    ASSERT_TRUE(RunUntil([this] { return timer.Q.value == 0; }, 50, "TOF.Q off"));
    EXPECT_EQ(task_.ScanCount(), f + 10);
}

TEST_F(TimerTest, TpPulseLastsExactlyPt) {
    Start(TP_init__, TP_body__, 10ms);
    Cycle(2);
    const std::int64_t k = ScanWithIn(true);
    EXPECT_TRUE(timer.Q.value) << "Q in the scan that sees IN rise";
    ASSERT_TRUE(RunUntil([this] { return timer.Q.value == 0; }, 50, "TP.Q off"));
    EXPECT_EQ(task_.ScanCount(), k + 10);
    EXPECT_DOUBLE_EQ(Millis(timer.ET.value), 10.0);
}

TEST_F(TimerTest, TpIsNotRetriggerableWhileRunning) {
    Start(TP_init__, TP_body__, 10ms);
    const std::int64_t k = ScanWithIn(true);
    Cycle(2);
    ScanWithIn(false);  // IN drops and rises again during the pulse
    Cycle(1);
    ScanWithIn(true);
    EXPECT_TRUE(timer.Q.value);
    ASSERT_TRUE(RunUntil([this] { return timer.Q.value == 0; }, 50, "TP.Q off"));
    EXPECT_EQ(task_.ScanCount(), k + 10) << "the second edge must not extend the pulse";
    Cycle(20);  // IN still TRUE: that edge during the pulse must not start another one
    EXPECT_FALSE(timer.Q.value);
    EXPECT_DOUBLE_EQ(Millis(timer.ET.value), 10.0);
}

TEST_F(TimerTest, TpRestartsOnlyAfterInFellAfterThePulse) {
    Start(TP_init__, TP_body__, 10ms);
    ScanWithIn(true);
    Cycle(15);
    EXPECT_FALSE(timer.Q.value);
    ScanWithIn(false);
    EXPECT_FALSE(timer.Q.value);
    EXPECT_DOUBLE_EQ(Millis(timer.ET.value), 0.0);
    const std::int64_t k = ScanWithIn(true);
    EXPECT_TRUE(timer.Q.value);
    ASSERT_TRUE(RunUntil([this] { return timer.Q.value == 0; }, 50, "TP.Q off"));
    EXPECT_EQ(task_.ScanCount(), k + 10);
}

TEST_F(TimerTest, TpInFallingDuringThePulseAllowsAnEdgeRightAfterIt) {
    Start(TP_init__, TP_body__, 10ms);
    const std::int64_t k = ScanWithIn(true);
    ScanWithIn(false);
    ASSERT_TRUE(RunUntil([this] { return timer.Q.value == 0; }, 50, "TP.Q off"));
    EXPECT_EQ(task_.ScanCount(), k + 10);
    const std::int64_t k2 = ScanWithIn(true);
    EXPECT_TRUE(timer.Q.value);
    ASSERT_TRUE(RunUntil([this] { return timer.Q.value == 0; }, 50, "TP.Q off"));
    EXPECT_EQ(task_.ScanCount(), k2 + 10);
}

}  // namespace
