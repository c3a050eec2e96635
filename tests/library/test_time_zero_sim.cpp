// T#0S on a TIME pin means the pin's default on every FB of the library (issue 10, defect 6): FB_PAC_Cmd's
// EndTimeout (T#60S) and FB_PAC_Ctrl's Timeout (T#10S) bound a wait that never ends, where T#0S once meant
// "no limit". The controller's answer is held back by a frozen input link, so only the FB's own bound ends
// the job. FB_PAC_Cmd's Timeout is covered in test_cmd_recovery_sim.cpp.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <vector>

#include "rig_timing.hpp"
#include "bus_timing.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/pac_rig.hpp"
#include "pac/st_program.hpp"
#include "plcopen_checker.hpp"
#include "real_bits.hpp"
#include "run_to_final.hpp"

namespace test_time_zero_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using std::chrono::nanoseconds;
using pac::test::BusTiming;

constexpr std::uint32_t kLibEndTimeout = 0x8002;
constexpr std::uint32_t kLibRequestTimeout = 0x8009;

std::vector<BusTiming> Timings() { return {{10, 10, 0}, {5, 3, 1}, {2, 1, 1, 1500, 606}}; }

// Scans of `plc` from now until `fb` shows a final output, at most `limit` of simulated time.
template <class Fb>
nanoseconds TimeToFinal(pac::PacRig& plc, pac::FbInstance<Fb>& fb, nanoseconds limit) {
    const nanoseconds start = plc.Now();
    plc.ScanUntil([&] { return pac::test::IsFinal(fb) || plc.Now() - start > limit; },
                  static_cast<int>(limit / plc.Timing().plcCycle) + 10);
    return plc.Now() - start;
}

// One command to its end: Execute edge, Done or Error, Execute back to FALSE for a scan.
bool RunCommand(pac::PacRig& plc, pac::FbInstance<FB_PAC_CMD>& cmd, std::uint16_t code, std::uint16_t param,
                std::uint32_t data) {
    cmd->CODE.value = code;
    cmd->PARAM.value = param;
    cmd->DATA.value = data;
    cmd->EXECUTE.value = TRUE;
    plc.ScanUntil([&] { return pac::test::IsFinal(cmd); }, 100000);
    const bool done = cmd->DONE.value != 0;
    cmd->EXECUTE.value = FALSE;
    plc.Scan();
    return done;
}

// Brings the controller to ONLINE as a PLC program gets there (5.2.1.3: the external stop input 7 powered, then
// 0603) and sends a long move (0A87) with `endTimeout`, until the controller acknowledged it; then freezes the
// controller's replies on their way to the PLC, so that END OF PROCESSING never shows.
void StartMoveWithoutEnd(pac::PacRig& plc, pac::FbInstance<FB_PAC_CMD>& cmd, const BusTiming& t,
                         nanoseconds endTimeout) {
    plc.Call(cmd);
    plc.Start();
    plc.Scan(5 + 2 * t.latency + 3);
    plc.Controller().Io().inputs.Set(7, true);
    ASSERT_TRUE(RunCommand(plc, cmd, 0x0700, 4, 7));
    ASSERT_TRUE(RunCommand(plc, cmd, 0x0603, 0, 0));
    plc.Scan(3 + 2 * t.latency);
    ASSERT_EQ(plc.Controller().OperatingStatus(), 31);
    cmd->CODE.value = 0x0A87;
    cmd->PARAM.value = 1;
    cmd->DATA.value = pac::test::BitsOf(5000.0F);
    cmd->ENDTIMEOUT.value = pac::ToIecTime(endTimeout);
    cmd->EXECUTE.value = TRUE;
    ASSERT_GT(plc.ScanUntil([&] { return cmd->ACKNOWLEDGED.value != 0; }, 10000), 0) << "the move runs";
    plc.Bus().FromPacLink().SetFault(plc.Now(), pac::sim::LinkFault::kFrozen);
}

// Each bus timing: a rig and an FB_PAC_Cmd with its move acknowledged and its end never to show, then `check`.
template <class Check>
void OnEveryTimingAfterAMoveWithoutEnd(nanoseconds endTimeout, Check check) {
    for (const BusTiming& t : Timings()) {
        SCOPED_TRACE(Describe(t));
        pac::PacRig plc(pac::test::RigTimingOf(t));
        auto cmd = PAC_FB(FB_PAC_CMD);
        StartMoveWithoutEnd(plc, cmd, t, endTimeout);
        if (::testing::Test::HasFatalFailure()) return;
        check(plc, cmd, t);
    }
}

TEST(TimeZero, CmdEndTimeoutZeroIsSixtySeconds) {
    OnEveryTimingAfterAMoveWithoutEnd(0s, [](pac::PacRig& plc, pac::FbInstance<FB_PAC_CMD>& cmd, const BusTiming& t) {
        const nanoseconds waited = TimeToFinal(plc, cmd, 70s);
        EXPECT_EQ(cmd->ERRORID.value, kLibEndTimeout);
        EXPECT_GE(waited, 59s);
        EXPECT_LE(waited, 60s + t.PlcCycle());
    });
}

// EndTimeout is taken when the command takes the interface: FB_PAC_CmdInterface bounds the wait of an FB left
// out with that value, so the FB called in every scan bounds it with the same, whatever the program writes to
// the pin afterwards.
TEST(TimeZero, CmdEndTimeoutIsTakenWithTheInterface) {
    OnEveryTimingAfterAMoveWithoutEnd(200ms, [](pac::PacRig& plc, pac::FbInstance<FB_PAC_CMD>& cmd,
                                                const BusTiming& t) {
        cmd->ENDTIMEOUT.value = pac::ToIecTime(5s);  // too late for this command: it took the interface
        const nanoseconds waited = TimeToFinal(plc, cmd, 10s);
        EXPECT_EQ(cmd->ERRORID.value, kLibEndTimeout);
        // The wait began in the scan that saw the acknowledgement, the scan before this one.
        EXPECT_LE(waited, 200ms + t.PlcCycle()) << waited.count() << " ns";
        EXPECT_GE(waited, 200ms - t.PlcCycle()) << waited.count() << " ns";
    });
}

TEST(TimeZero, CtrlTimeoutZeroIsTenSeconds) {
    for (const BusTiming& t : Timings()) {
        SCOPED_TRACE(Describe(t));
        pac::PacRig plc(pac::test::RigTimingOf(t), {}, pac::sim::ModuleLayout{true, 0});
        auto ctrl = PAC_FB(FB_PAC_CTRL);
        plc.CallCtrl(ctrl);
        plc.Start();
        ASSERT_EQ(plc.Controller().SystemParameters().Set(4, 1), pac::sim::ParameterTable::SetResult::kOk);
        plc.Controller().Io().inputs.Set(1, true);
        ASSERT_GT(plc.ScanUntil([&] { return ctrl->READY.value != 0; }, 10000), 0);
        plc.Scan(5 + 4 * t.latency);
        plc.Bus().FromPacLink().SetFault(plc.Now(), pac::sim::LinkFault::kFrozen);
        ctrl->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
        ctrl->TIMEOUT.value = pac::ToIecTime(0s);
        ctrl->EXECUTE.value = TRUE;
        plc.Scan();
        const nanoseconds waited = TimeToFinal(plc, ctrl, 20s) + t.PlcCycle();
        EXPECT_EQ(ctrl->ERRORID.value, kLibRequestTimeout);
        EXPECT_GE(waited, 10s);
        EXPECT_LE(waited, 10s + t.PlcCycle());
    }
}

}  // namespace
}  // namespace test_time_zero_sim
