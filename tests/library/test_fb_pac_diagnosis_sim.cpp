// FB_PAC_Diagnosis on the simulated PA-CONTROL (docs/fb/FB_PAC_Diagnosis.md), on several bus timings: it reads
// by command only what no cyclic module carries, at the poll rate; Enable FALSE sends nothing; a command error
// and a controller restart; the CMD channel shared with another command FB edged in the same scan, in both call
// orders; the diagnosis left out of scans at every point of its reads. The PLCopen Enable rules hold on
// FB_PAC_Diagnosis after every scan (diagnosis_plc.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "bus_timing.hpp"
#include "diagnosis_plc.hpp"
#include "pac/st_program.hpp"
#include "scan_window.hpp"

namespace test_fb_pac_diagnosis_sim {  // apart from the names of the other sources in its unity batch
namespace {

using pac::test::BusTiming;
using pac::test::DiagnosisLayout;
using pac::test::DiagnosisPlc;
using std::chrono::milliseconds;

constexpr std::uint16_t kGetError = 0x1909;       // cmd_get_error (5.2.4.16)
constexpr std::uint16_t kGetStatusAxis = 0x1910;  // cmd_get_status_axis (5.2.4.22)
constexpr std::uint16_t kGetIntReg = 0x1906;      // cmd_get_int_reg (5.2.4.12)

std::string Text(const STRING& s) { return std::string(reinterpret_cast<const char*>(s.body), s.len); }

std::vector<BusTiming> DiagnosisTimings() {
    std::vector<BusTiming> timings = pac::test::BusTimingGrid({1, 5}, {3, 10}, {0, 2});
    timings.push_back({2, 10, 2, 6000, 202});
    return timings;
}

// The longest one read takes from its edge to its final output, in ms: the protocol's window with the whole
// jitter, and a scan to spare on each side.
int CommandMs(const BusTiming& t) {
    const pac::test::ProtocolWindow window(t);
    int worst = 0;
    for (int phase = 0; phase < t.pacMs; phase += t.plcMs) {
        const int scans = window.Request(milliseconds(phase + 1000)).max;
        worst = std::max(worst, scans);
    }
    return (worst + 2) * t.plcMs;
}

class DiagnosisSim : public ::testing::TestWithParam<BusTiming> {};

TEST_P(DiagnosisSim, ModulesCarryEverythingSoNoCommandIsSent) {
    DiagnosisPlc plc(GetParam(), DiagnosisLayout{true, 2});
    // Enabled from the first scan, as a program does: through the boot and a restart too.
    plc.Diag()->AXES.value = 2;
    plc.Diag()->ENABLE.value = TRUE;
    plc.Boot();
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->VALID.value != 0; }, 20));
    EXPECT_EQ(plc.Diag()->OPSTATUS.value, 1);
    EXPECT_EQ(Text(plc.Diag()->OPSTATUSTEXT.value), "home position");
    EXPECT_EQ(Text(plc.Diag()->SYSTEMERRORTEXT.value), "no error");
    for (int k = 1; k <= 2; ++k) {
        EXPECT_EQ(plc.Entry(k).SOURCE, E_PAC_DIAGSOURCE__PAC_DIAGSRC_MODULE) << k;
        EXPECT_EQ(plc.Entry(k).STATUS, plc.Axis(k)->STATUSWORD.value) << k;
        EXPECT_FALSE(Text(plc.Entry(k).STATUSTEXT).empty()) << k;
        EXPECT_EQ(Text(plc.Entry(k).AXISERRORTEXT), "no error") << k;
    }
    EXPECT_EQ(plc.Entry(3).SOURCE, E_PAC_DIAGSOURCE__PAC_DIAGSRC_NONE);
    plc.ScanMs(300);
    EXPECT_EQ(plc.CountAll(), 0) << "a command although every value is in a cyclic module";

    // A system error: the CTRL interface carries its number (2.5.2), the CMD reply the flag and status 9.
    const auto count = plc.Diag()->CHANGECOUNT.value;
    plc.Controller().RaiseSystemError(529);
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->SYSTEMERRORNUMBER.value == 529; }, 100));
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->OPSTATUS.value == 9; }, 100));
    EXPECT_TRUE(plc.Diag()->SYSTEMERROR.value);
    EXPECT_EQ(Text(plc.Diag()->SYSTEMERRORTEXT.value),
              "system error of class 3 (ONLINE or AUTOMATIC): see the operating instructions");
    EXPECT_EQ(Text(plc.Diag()->OPSTATUSTEXT.value), "home position with system error");
    EXPECT_GT(plc.Diag()->CHANGECOUNT.value, count);
    EXPECT_TRUE(plc.Diag()->VALID.value);
    plc.Controller().PowerCycle(plc.Now());
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->ERROR.value != 0; }, 50));
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->VALID.value != 0; }, 300));
    plc.ScanMs(100);
    EXPECT_EQ(plc.CountAll(), 0);
}

// In AUTOMATIC the axis module carries flags and registers (2.6): FB_PAC_Axis shows no status, and the axis is
// read by 1910 until the module is an axis module again.
TEST_P(DiagnosisSim, AnAxisModuleOutsideHomeAndOnlineIsReadByCommand) {
    const BusTiming& t = GetParam();
    DiagnosisPlc plc(t, DiagnosisLayout{true, 1});
    plc.Diag()->AXES.value = 1;
    plc.SetPollMs(10);
    plc.Diag()->ENABLE.value = TRUE;
    plc.Boot();
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->VALID.value != 0; }, 20));
    EXPECT_EQ(plc.Entry(1).SOURCE, E_PAC_DIAGSOURCE__PAC_DIAGSRC_MODULE);
    plc.Controller().SetOperatingStatus(15);  // AUTOMATIC, stopped
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Entry(1).SOURCE == E_PAC_DIAGSOURCE__PAC_DIAGSRC_COMMAND; },
                           20 + 2 * CommandMs(t)));
    EXPECT_EQ(Text(plc.Diag()->OPSTATUSTEXT.value), "AUTOMATIC, stopped");
    EXPECT_EQ(plc.Entry(1).AXISERRORNUMBER, 0);
    EXPECT_EQ(Text(plc.Entry(1).AXISERRORTEXT), "") << "no command reads the axis error number";
    EXPECT_GE(plc.Count(kGetStatusAxis, 1), 1);
    plc.Controller().SetOperatingStatus(1);
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Entry(1).SOURCE == E_PAC_DIAGSOURCE__PAC_DIAGSRC_MODULE; },
                           20 + 2 * CommandMs(t)));
    plc.ScanMs(CommandMs(t));  // the read on its way, if any
    const int reads = plc.CountAll();
    plc.ScanMs(200);
    EXPECT_EQ(plc.CountAll(), reads) << "1910 although the module carries the axis again";
}

TEST_P(DiagnosisSim, WithoutModulesItReadsTheAxesByCommandAtThePollRate) {
    const BusTiming& t = GetParam();
    DiagnosisPlc plc(t, DiagnosisLayout{});
    constexpr int kPollMs = 20;
    plc.Boot();
    plc.Diag()->AXES.value = 3;
    plc.SetPollMs(kPollMs);
    plc.Diag()->ENABLE.value = TRUE;
    // The first read at once, each next one PollTime after the previous one ended.
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->VALID.value != 0; }, 3 * CommandMs(t) + 2 * kPollMs + 5));
    for (int k = 1; k <= 3; ++k) EXPECT_EQ(plc.Count(kGetStatusAxis, k), 1) << k;
    for (int k = 1; k <= 2; ++k) {
        EXPECT_EQ(plc.Entry(k).SOURCE, E_PAC_DIAGSOURCE__PAC_DIAGSRC_COMMAND) << k;
        EXPECT_EQ(Text(plc.Entry(k).STATUSTEXT), "standing, in position") << k;
        EXPECT_EQ(plc.Entry(k).READERRORID, 0) << k;
    }
    // System parameter 2 gives the controller two axes: axis 3 is answered with command error 32, and that
    // answer is what the diagnosis shows for it.
    EXPECT_EQ(plc.Entry(3).SOURCE, E_PAC_DIAGSOURCE__PAC_DIAGSRC_NONE);
    EXPECT_EQ(plc.Entry(3).READERRORID, 32);
    EXPECT_EQ(Text(plc.Entry(3).STATUSTEXT), "");
    EXPECT_EQ(plc.Count(kGetError), 0) << "1909 without the PA-CONTROL error flag";

    const auto from = plc.Now();
    constexpr int kWindowMs = 1000;
    plc.ScanMs(kWindowMs);
    const int reads = plc.Count(kGetStatusAxis, -1, from);
    EXPECT_LE(reads, kWindowMs / kPollMs + 1) << "more reads than PollTime allows";
    EXPECT_GE(reads, kWindowMs / (kPollMs + CommandMs(t)) - 1) << "the reads do not keep up the poll rate";
    for (int k = 1; k <= 3; ++k) EXPECT_GE(plc.Count(kGetStatusAxis, k, from), reads / 3 - 1) << "axis " << k;
    EXPECT_EQ(plc.CountAll(from), reads) << "a command other than 1910";

    // The error flag set: 1909 joins the round; cleared: the number is 0 without a read.
    plc.Controller().SetSystemError(560);
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->SYSTEMERRORNUMBER.value == 560; }, 4 * (kPollMs + CommandMs(t))));
    EXPECT_EQ(Text(plc.Diag()->SYSTEMERRORTEXT.value), "system error E560: no encoder edge when leaving measuring mode");
    EXPECT_TRUE(plc.Diag()->VALID.value);
    plc.Controller().SetSystemError(0);
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->SYSTEMERRORNUMBER.value == 0; }, 100));
    plc.ScanMs(CommandMs(t));  // a 1909 on its way may still arrive
    const int gets = plc.Count(kGetError);
    plc.ScanMs(300);
    EXPECT_EQ(plc.Count(kGetError), gets) << "1909 without the error flag";
}

TEST_P(DiagnosisSim, EnableFalseSendsNothing) {
    const BusTiming& t = GetParam();
    DiagnosisPlc plc(t, DiagnosisLayout{});
    plc.Boot();
    plc.Diag()->AXES.value = 2;
    plc.SetPollMs(5);
    plc.Controller().SetSystemError(529);
    plc.ScanMs(300);
    EXPECT_EQ(plc.CountAll(), 0) << "a command before Enable";
    plc.Diag()->ENABLE.value = TRUE;
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->VALID.value != 0; }, 4 * (5 + CommandMs(t))));
    plc.Diag()->ENABLE.value = FALSE;
    plc.Scan();
    // At most the read on its way when Enable fell reaches the controller.
    const int before = plc.CountAll();
    plc.ScanMs(300);
    EXPECT_LE(plc.CountAll(), before + 1);
    const int after = plc.CountAll();
    plc.ScanMs(300);
    EXPECT_EQ(plc.CountAll(), after);
    EXPECT_FALSE(plc.Diag()->BUSY.value);
    // Enable again: Valid only once every value is read anew.
    plc.Diag()->ENABLE.value = TRUE;
    plc.Scan();
    EXPECT_FALSE(plc.Diag()->VALID.value);
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->VALID.value != 0; }, 4 * (5 + CommandMs(t))));
    EXPECT_GE(plc.CountAll(), after + 3);
}

TEST_P(DiagnosisSim, ACommandErrorTo1910IsThatAxisAnswerTo1909TheFbsError) {
    const BusTiming& t = GetParam();
    DiagnosisPlc plc(t, DiagnosisLayout{});
    plc.Boot();
    plc.Diag()->AXES.value = 1;
    plc.SetPollMs(10);
    plc.Diag()->ENABLE.value = TRUE;
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->VALID.value != 0; }, 2 * CommandMs(t)));
    plc.Controller().InjectCommandError(32);  // "axis number unknown" to the next 1910
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Entry(1).READERRORID == 32; }, 2 * (10 + CommandMs(t))));
    EXPECT_EQ(plc.Entry(1).SOURCE, E_PAC_DIAGSOURCE__PAC_DIAGSRC_NONE);
    EXPECT_TRUE(plc.Diag()->VALID.value) << "the axis's answer is known";
    EXPECT_FALSE(plc.Diag()->ERROR.value);
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Entry(1).READERRORID == 0; }, 2 * (10 + CommandMs(t))));
    EXPECT_EQ(plc.Entry(1).SOURCE, E_PAC_DIAGSOURCE__PAC_DIAGSRC_COMMAND);

    // Only 1909 wanted: its command error is the FB's, until the next read succeeds.
    plc.Diag()->AXES.value = 0;
    plc.Controller().SetSystemError(529);
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->SYSTEMERRORNUMBER.value == 529; }, 4 * (10 + CommandMs(t))));
    plc.Controller().InjectCommandError(21);
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->ERROR.value != 0; }, 2 * (10 + CommandMs(t))));
    EXPECT_EQ(plc.Diag()->ERRORID.value, 21);
    EXPECT_EQ(plc.Diag()->ERRORSOURCE.value, E_PAC_ERRORSOURCE__PAC_ERRSRC_COMMAND);
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->VALID.value != 0; }, 2 * (10 + CommandMs(t))));
    EXPECT_EQ(plc.Diag()->SYSTEMERRORNUMBER.value, 529);

    // Axes outside 0..8: an error, nothing read.
    plc.Diag()->AXES.value = 9;
    plc.Scan();
    EXPECT_TRUE(plc.Diag()->ERROR.value);
    EXPECT_EQ(plc.Diag()->ERRORID.value, 0x8024);  // PAC_LIB_ERR_DIAG_AXES
    plc.ScanMs(CommandMs(t));
    const int before = plc.CountAll();
    plc.ScanMs(200);
    EXPECT_EQ(plc.CountAll(), before);
}

// A read that failed on the interface (16#8001 behind a frozen link) is the FB's error until a read succeeds,
// or until nothing is left to read: then every value is known again without one.
TEST_P(DiagnosisSim, AFailedReadNoLongerWantedLeavesNoError) {
    const BusTiming& t = GetParam();
    DiagnosisPlc plc(t, DiagnosisLayout{});
    plc.Boot();
    plc.SetPollMs(10);
    plc.Diag()->TIMEOUT.value = TIME{0, 50'000'000};  // T#50MS
    plc.Controller().SetSystemError(529);
    plc.Diag()->ENABLE.value = TRUE;
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->SYSTEMERRORNUMBER.value == 529; }, 2 * CommandMs(t)));
    plc.Bench().Bus().FromPacLink().SetFault(plc.Now(), pac::sim::LinkFault::kFrozen);
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->ERROR.value != 0; }, 10 + 2 * 50 + CommandMs(t)));
    EXPECT_EQ(plc.Diag()->ERRORID.value, 0x8001);  // PAC_LIB_ERR_ACK_TIMEOUT
    EXPECT_FALSE(plc.Diag()->VALID.value);
    plc.Controller().SetSystemError(0);
    plc.Bench().Bus().FromPacLink().SetFault(plc.Now(), pac::sim::LinkFault::kNone);
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->VALID.value != 0; }, 200 + 2 * CommandMs(t)));
    EXPECT_FALSE(plc.Diag()->ERROR.value);
    EXPECT_EQ(plc.Diag()->SYSTEMERRORNUMBER.value, 0);
}

TEST_P(DiagnosisSim, AControllerRestartIsAnErrorThenEveryValueIsReadAgain) {
    const BusTiming& t = GetParam();
    DiagnosisPlc plc(t, DiagnosisLayout{});
    plc.Boot();
    plc.Diag()->AXES.value = 2;
    plc.SetPollMs(10);
    plc.Diag()->ENABLE.value = TRUE;
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->VALID.value != 0; }, 3 * (10 + CommandMs(t))));
    plc.ScanMs(37);  // somewhere in the round, maybe with a read on its way
    plc.Controller().PowerCycle(plc.Now());
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->OPSTATUS.value == 0; }, 10 + 2 * t.latency * t.plcMs + t.jitterUs / 1000));
    EXPECT_TRUE(plc.Diag()->ERROR.value);
    EXPECT_EQ(plc.Diag()->ERRORID.value, 0x8003);  // PAC_LIB_ERR_NOT_READY while status 0
    EXPECT_EQ(Text(plc.Diag()->OPSTATUSTEXT.value), "no communication via the bus (not initialized)");
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->OPSTATUS.value != 0; }, 200));
    const auto restart = plc.Now();
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->VALID.value != 0; }, 3 * (10 + CommandMs(t)) + 20));
    EXPECT_GE(plc.Count(kGetStatusAxis, 1, restart - milliseconds(20)), 1) << "Valid before axis 1 was read again";
    EXPECT_GE(plc.Count(kGetStatusAxis, 2, restart - milliseconds(20)), 1) << "Valid before axis 2 was read again";
    EXPECT_EQ(plc.Entry(1).SOURCE, E_PAC_DIAGSOURCE__PAC_DIAGSRC_COMMAND);
}

// The calling contract (docs/fb/FB_PAC_Diagnosis.md): the diagnosis left out for 1 to 6 scans, from 0 to 11 scans
// into a stretch of back-to-back reads (PollTime T#1MS), so at every point of a read's handshake, while another FB
// reads N3 again and again on the same channel (4242, which is no axis status). What the diagnosis shows is its
// own 1910s' answer ("standing, in position"), never the other command's; it stays Valid without Error; it sends
// 1910 of axes 1 and 2 only, and the other FB's reads end Done with their own value.
TEST_P(DiagnosisSim, LeftOutOfScansItShowsOnlyItsOwnReads) {
    const BusTiming& t = GetParam();
    DiagnosisPlc plc(t, DiagnosisLayout{});
    plc.Boot();
    plc.Controller().Io().intRegisters.SetInt(3, 4242);
    plc.Diag()->AXES.value = 2;
    plc.SetPollMs(1);
    plc.Diag()->ENABLE.value = TRUE;
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Diag()->VALID.value != 0; }, 3 * CommandMs(t) + 10));
    plc.Other()->CODE.value = kGetIntReg;
    plc.Other()->PARAM.value = 3;
    int otherDone = 0;
    auto scan = [&] {
        auto& other = plc.Other();
        if (other->EXECUTE.value && (other->DONE.value || other->ERROR.value)) {
            EXPECT_TRUE(other->DONE.value) << "N3: ErrorID 16#" << std::hex << other->ERRORID.value;
            EXPECT_EQ(other->ACKDATA.value, 4242u) << "N3's own value";
            other->EXECUTE.value = FALSE;
            ++otherDone;
        } else {
            other->EXECUTE.value = TRUE;
        }
        plc.Scan();
    };
    const int readsBefore = plc.Count(kGetStatusAxis);
    for (int skip = 1; skip <= 6; ++skip) {
        for (int offset = 0; offset <= 11; ++offset) {
            SCOPED_TRACE(std::to_string(skip) + " scans left out from scan " + std::to_string(offset));
            for (int n = 0; n < 12 + skip; ++n) {
                plc.CallDiagnosis(n < offset || n >= offset + skip);
                scan();
            }
            plc.CallDiagnosis(true);
            scan();
            for (int k = 1; k <= 2; ++k) {
                EXPECT_EQ(Text(plc.Entry(k).STATUSTEXT), "standing, in position") << "axis " << k;
                EXPECT_EQ(plc.Entry(k).READERRORID, 0) << "axis " << k;
            }
            EXPECT_TRUE(plc.Diag()->VALID.value);
            ASSERT_FALSE(plc.Diag()->ERROR.value) << "ErrorID 16#" << std::hex << plc.Diag()->ERRORID.value;
        }
    }
    EXPECT_GT(plc.Count(kGetStatusAxis) - readsBefore, 20) << "the diagnosis kept reading";
    EXPECT_GT(otherDone, 20);
    EXPECT_EQ(plc.Count(kGetStatusAxis, 1) + plc.Count(kGetStatusAxis, 2), plc.Count(kGetStatusAxis));
    EXPECT_EQ(plc.CountAll(), plc.Count(kGetStatusAxis) + plc.Count(kGetIntReg, 3)) << "a command of neither FB";
}

INSTANTIATE_TEST_SUITE_P(BusTimings, DiagnosisSim, ::testing::ValuesIn(DiagnosisTimings()),
                         pac::test::BusTimingName);

// Two FBs on one channel: FB_PAC_Diagnosis polling as fast as it may (PollTime T#1MS) and an FB_PAC_Cmd whose
// Execute rises in the scan Enable rises, in either call order. The other command never waits for more than
// the one read ahead of it, and each FB sends only its own commands.
class DiagnosisSharing : public ::testing::TestWithParam<std::tuple<BusTiming, bool>> {};

TEST_P(DiagnosisSharing, AnotherCommandWaitsAtMostOneRead) {
    const auto& [t, diagnosisFirst] = GetParam();
    DiagnosisPlc plc(t, DiagnosisLayout{false, 0, diagnosisFirst});
    plc.Boot();
    plc.Diag()->AXES.value = 2;
    plc.SetPollMs(1);
    plc.Other()->CODE.value = kGetIntReg;
    plc.Other()->PARAM.value = 3;
    const int bound = 2 * CommandMs(t) / t.plcMs + 2;  // one read ahead, then its own
    for (int round = 0; round < 20; ++round) {
        if (round == 0) plc.Diag()->ENABLE.value = TRUE;  // the same scan as the first Execute edge
        plc.Other()->EXECUTE.value = TRUE;
        int scans = 0;
        while (!plc.Other()->DONE.value && !plc.Other()->ERROR.value && scans < 10 * bound) {
            plc.Scan();
            ++scans;
        }
        ASSERT_TRUE(plc.Other()->DONE.value) << "round " << round << ", ErrorID 16#" << std::hex
                                             << plc.Other()->ERRORID.value;
        EXPECT_LE(scans, bound) << "round " << round;
        plc.Other()->EXECUTE.value = FALSE;
        plc.Scan(1 + round % 3);
    }
    EXPECT_TRUE(plc.Diag()->VALID.value);
    EXPECT_EQ(plc.Count(kGetIntReg, 3), 20);
    EXPECT_GE(plc.Count(kGetStatusAxis), 10) << "the diagnosis did not get its turns";
    EXPECT_EQ(plc.CountAll(), 20 + plc.Count(kGetStatusAxis));

    // The CMD history: every command of both FBs, newest first, as the controller recognised them.
    plc.Diag()->AXES.value = 0;  // nothing left to read; the FB still shows the history
    plc.ScanMs(CommandMs(t));    // the read on its way ends
    plc.Other()->PARAM.value = 7;
    plc.Other()->EXECUTE.value = TRUE;
    ASSERT_TRUE(plc.WaitMs([&] { return plc.Other()->DONE.value != 0; }, 2 * CommandMs(t)));
    plc.Other()->EXECUTE.value = FALSE;
    plc.Scan();
    const auto& seen = plc.Seen();
    ASSERT_GE(seen.size(), 16u);
    EXPECT_EQ(plc.Diag()->HISTORYCOUNT.value, seen.size());
    const auto& history = plc.Diag()->HISTORY.value.table;
    EXPECT_EQ(history[0].CODE, kGetIntReg);
    EXPECT_EQ(history[0].PARAM, 7);
    EXPECT_EQ(history[0].ERRORID, 0);
    for (std::size_t i = 0; i < 16; ++i) {
        const auto& c = seen[seen.size() - 1 - i];
        EXPECT_EQ(history[i].CODE, c.code) << "entry " << i;
        EXPECT_EQ(history[i].PARAM, c.param) << "entry " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(BusTimings, DiagnosisSharing,
                         ::testing::Combine(::testing::ValuesIn(DiagnosisTimings()), ::testing::Bool()),
                         [](const ::testing::TestParamInfo<std::tuple<BusTiming, bool>>& info) {
                             const ::testing::TestParamInfo<BusTiming> timing(std::get<0>(info.param), info.index);
                             return pac::test::BusTimingName(timing) +
                                    (std::get<1>(info.param) ? "_DiagnosisFirst" : "_DiagnosisSecond");
                         });

}  // namespace
}  // namespace test_fb_pac_diagnosis_sim
