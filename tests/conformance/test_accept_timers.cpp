// Standard function blocks used inside translated user FBs and driven scan by scan (1 ms cycle):
// R_TRIG, F_TRIG, TON, TOF, TP.
#include <gtest/gtest.h>

#include <chrono>
#include <vector>

#include "matiec_deviations.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/scan_test.hpp"
#include "pac/st_program.hpp"

using namespace std::chrono_literals;

namespace {

std::chrono::nanoseconds Ns(const TIME& t) { return pac::FromIecTime(t); }

// One scan per element of `inputs`: the program sets the input, calls the FB and records `output`.
template <class Fb, class In, class Out>
std::vector<int> RunScans(pac::PlcTask& task, pac::FbInstance<Fb>& fb, In in, Out out, const std::vector<int>& inputs) {
    std::vector<int> recorded;
    std::size_t next = 0;
    task.AddProgram([&] {
        in(fb, inputs.at(next++));
        fb();
        recorded.push_back(out(fb));
    });
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        task.Scan();
    }
    return recorded;
}

class ConformanceTimers : public pac::ScanTest {};

TEST_F(ConformanceTimers, RTrigPulsesOnRisingEdges) {
    auto fb = PAC_FB(CONF_STDRTRIG);
    const std::vector<int> q = RunScans(
        task_, fb, [](auto& f, int v) { f->SIGNAL.value = static_cast<BOOL>(v); },
        [](auto& f) { return static_cast<int>(f->PULSE.value); }, {1, 1, 0, 1, 0, 0, 1, 1});
    EXPECT_EQ(q, (std::vector<int>{1, 0, 0, 1, 0, 0, 1, 0}));
    EXPECT_EQ(fb->EDGES.value, 3);
}

TEST_F(ConformanceTimers, FTrigPulsesOnFallingEdgesAndOnTheFirstCall) {
    auto fb = PAC_FB(CONF_STDFTRIG);
    const std::vector<int> q = RunScans(
        task_, fb, [](auto& f, int v) { f->SIGNAL.value = static_cast<BOOL>(v); },
        [](auto& f) { return static_cast<int>(f->PULSE.value); }, {0, 0, 1, 1, 0, 1, 0});
    EXPECT_EQ(q, (std::vector<int>{1, 0, 0, 0, 1, 0, 1}));
    EXPECT_EQ(fb->EDGES.value, 3);
}

TEST_F(ConformanceTimers, TonDelaysAndNeverFiresInTheRisingScan) {
    auto fb = PAC_FB(CONF_STDTON);  // Delay = T#10MS
    task_.AddProgram([&] { fb(); });
    Cycle(3);
    EXPECT_EQ(fb->DONE.value, 0);
    fb->START.value = 1;
    Cycle(1);  // IN rises in this scan (t = 4 ms)
    EXPECT_EQ(fb->DONE.value, 0);
    EXPECT_EQ(fb->DONEZERO.value, 0) << "TON with PT = T#0S must not fire in the scan IN rises";
    Cycle(1);
    EXPECT_EQ(fb->DONEZERO.value, 1);
    EXPECT_EQ(Ns(fb->ELAPSED.value), 1ms);
    Cycle(3);
    EXPECT_EQ(Ns(fb->ELAPSED.value), 4ms);
    Cycle(5);  // 9 ms after the rise
    EXPECT_EQ(fb->DONE.value, 0);
    Cycle(1);  // 10 ms after the rise
    EXPECT_EQ(fb->DONE.value, 1);
    EXPECT_EQ(Ns(fb->ELAPSED.value), 10ms);
    Cycle(5);
    EXPECT_EQ(fb->DONE.value, 1);
    EXPECT_EQ(Ns(fb->ELAPSED.value), 10ms);  // ET stops at PT
    fb->START.value = 0;
    Cycle(1);
    EXPECT_EQ(fb->DONE.value, 0);
    EXPECT_EQ(fb->DONEZERO.value, 0);
    EXPECT_EQ(Ns(fb->ELAPSED.value), 0ms);
}

TEST_F(ConformanceTimers, TonRestartsWhenInDropsBeforePt) {
    auto fb = PAC_FB(CONF_STDTON);
    task_.AddProgram([&] { fb(); });
    fb->START.value = 1;
    Cycle(6);
    fb->START.value = 0;
    Cycle(1);
    fb->START.value = 1;
    Cycle(10);  // the rise plus 9 ms
    EXPECT_EQ(fb->DONE.value, 0);
    Cycle(1);
    EXPECT_EQ(fb->DONE.value, 1);
}

TEST_F(ConformanceTimers, TofHoldsQForPtAfterInFalls) {
    auto fb = PAC_FB(CONF_STDTOF);  // PT = T#5MS
    task_.AddProgram([&] { fb(); });
    Cycle(2);
    EXPECT_EQ(fb->HOLD.value, 0);
    fb->RUN.value = 1;
    Cycle(1);
    EXPECT_EQ(fb->HOLD.value, 1);  // Q follows IN up at once
    Cycle(3);
    fb->RUN.value = 0;
    Cycle(1);  // IN falls in this scan
    EXPECT_EQ(fb->HOLD.value, 1);
    Cycle(2);
    EXPECT_EQ(Ns(fb->ELAPSED.value), 2ms);
    Cycle(2);  // 4 ms after the fall
    EXPECT_EQ(fb->HOLD.value, 1);
    Cycle(1);  // 5 ms after the fall
    EXPECT_EQ(fb->HOLD.value, 0);
    EXPECT_EQ(Ns(fb->ELAPSED.value), 5ms);
    // A new rise during the delay cancels it.
    fb->RUN.value = 1;
    Cycle(1);
    fb->RUN.value = 0;
    Cycle(3);
    fb->RUN.value = 1;
    Cycle(1);
    EXPECT_EQ(fb->HOLD.value, 1);
    EXPECT_EQ(Ns(fb->ELAPSED.value), 0ms);
    Cycle(10);
    EXPECT_EQ(fb->HOLD.value, 1);
}

TEST_F(ConformanceTimers, TpGivesOnePulseOfPtThatEdgesCannotRetrigger) {
    auto fb = PAC_FB(CONF_STDTP);  // PT = T#4MS
    const std::vector<int> q = RunScans(
        task_, fb, [](auto& f, int v) { f->TRIGGER.value = static_cast<BOOL>(v); },
        [](auto& f) { return static_cast<int>(f->PULSE.value); }, {1, 0, 1, 0, 0, 0, 1, 1, 1, 1, 1, 1, 0});
    // Pulse of 4 scans from each rise that finds the timer idle; the rise in scan 3 changes nothing,
    // and IN held TRUE does not lengthen the second pulse.
    EXPECT_EQ(q, (std::vector<int>{1, 1, 1, 1, 0, 0, 1, 1, 1, 1, 0, 0, 0}));
}

TEST_F(ConformanceTimers, TpElapsedTime) {
    auto fb = PAC_FB(CONF_STDTP);
    task_.AddProgram([&] { fb(); });
    fb->TRIGGER.value = 1;
    Cycle(3);
    EXPECT_EQ(fb->PULSE.value, 1);
    EXPECT_EQ(Ns(fb->ELAPSED.value), 2ms);
    Cycle(2);
    EXPECT_EQ(fb->PULSE.value, 0);
    EXPECT_LE(Ns(fb->ELAPSED.value), 4ms);  // ET stays at PT (T#4MS) while IN is TRUE
    EXPECT_GE(Ns(fb->ELAPSED.value), 4ms - pac::test::kTimeLiteralShortfall);
    fb->TRIGGER.value = 0;
    Cycle(1);
    EXPECT_EQ(Ns(fb->ELAPSED.value), 0ms);
}

}  // namespace
