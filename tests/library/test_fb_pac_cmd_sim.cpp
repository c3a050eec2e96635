// FB_PAC_Cmd against the simulated PA-CONTROL over the simulated bus: every combination of PLC
// cycle (1-10 ms), controller cycle (1-10 ms) and bus latency (0-3 PLC cycles each way). Each test
// checks the results, that the controller saw exactly the commands the PLC meant (no spurious or
// lost command), and that Done comes at the protocol minimum: the FB adds no scan of its own.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <string>

#include "bus_timing.hpp"
#include "command_plc.hpp"
#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"
#include "run_to_final.hpp"
#include "scan_window.hpp"

namespace test_fb_pac_cmd_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using std::chrono::nanoseconds;
using pac::test::BusTiming;
using pac::test::FinalOutcome;

// A PLC with one FB_PAC_Cmd on the CMD interface of a simulated PA-CONTROL.
class CmdRig {
public:
    explicit CmdRig(const BusTiming& timing, nanoseconds bootTime = 0ns) : plc_(timing, {}, bootTime) {
        plc_.Add("FB_PAC_Cmd", cmd_);
        plc_.Start();
    }

    // Runs one command to its end: Execute edge, wait for Done or Error, Execute back to FALSE.
    FinalOutcome Run(std::uint16_t code, std::uint16_t param, std::uint32_t data, int maxScans = 2000) {
        cmd_->CODE.value = code;
        cmd_->PARAM.value = param;
        cmd_->DATA.value = data;
        plc_.Begin(cmd_);
        const FinalOutcome outcome = plc_.Wait(cmd_, maxScans);
        ackData_ = cmd_->ACKDATA.value;
        plc_.Release(cmd_);
        return outcome;
    }

    // AckData in the scan that ended the last Run() (Execute falls in the scan after it).
    std::uint32_t AckData() const { return ackData_; }
    // The scans the protocol needs for the command of the last Run(): exact without jitter.
    pac::test::ScanWindow Window() const { return plc_.Window(); }

    void Settle(int scans) { plc_.Scan(scans); }
    // Past the cold start's first handshake, the parked read (190B), which the controller counts too.
    void SettlePastFirstHandshake() { plc_.ScanPastFirstHandshake(); }

    pac::FbInstance<FB_PAC_CMD>& Cmd() { return cmd_; }
    pac::sim::PaControl& Controller() { return plc_.Controller(); }
    pac::sim::Bus& Bus() { return plc_.Rig().Bus(); }
    nanoseconds Now() const { return plc_.Now(); }

private:
    pac::FbInstance<FB_PAC_CMD> cmd_ = PAC_FB(FB_PAC_CMD);  // before the PLC, which calls it
    pac::test::CommandPlc plc_;
    std::uint32_t ackData_ = 0;
};

// The commands the controller recognised, the parked read (190B) aside: the first handshake after a cold
// start, and what a restarted controller may take from the parked module, execute nothing.
std::uint64_t CommandsRecognised(const pac::sim::PaControl& pac) {
    return pac.Counters().recognized - pac.Counters().Count(0x190B);
}

class CmdTiming : public ::testing::TestWithParam<BusTiming> {};

TEST_P(CmdTiming, WriteThenReadRegisterAtTheProtocolMinimum) {
    CmdRig rig(GetParam());
    rig.SettlePastFirstHandshake();
    const FinalOutcome write = rig.Run(0x0906, 3, 333);
    ASSERT_TRUE(write.Done()) << "0906: " << write;
    EXPECT_TRUE(rig.Window().Contains(write.Scans())) << write << ", the protocol allows " << rig.Window();
    const FinalOutcome read = rig.Run(0x1906, 3, 0);
    EXPECT_TRUE(read.Done() && rig.Window().Contains(read.Scans())) << read << ", the protocol allows "
                                                                       << rig.Window();
    EXPECT_EQ(rig.AckData(), 333u);
    EXPECT_EQ(CommandsRecognised(rig.Controller()), 2u) << "exactly the two commands, nothing spurious";
}

TEST_P(CmdTiming, CommandErrorThenGoodCommand) {
    CmdRig rig(GetParam());
    rig.SettlePastFirstHandshake();
    const FinalOutcome refused = rig.Run(0x1906, 60000, 0);
    EXPECT_TRUE(refused.Error() && rig.Window().Contains(refused.Scans())) << refused;
    EXPECT_EQ(rig.Controller().Counters().failed, 1u);
    const FinalOutcome write = rig.Run(0x0906, 5, 77);
    EXPECT_TRUE(write.Done()) << write;
    const FinalOutcome read = rig.Run(0x1906, 5, 0);
    ASSERT_TRUE(read.Done()) << read;
    EXPECT_EQ(rig.AckData(), 77u);
    EXPECT_EQ(CommandsRecognised(rig.Controller()), 3u);
    EXPECT_EQ(rig.Controller().Counters().executed, 3u) << "the parked read of the cold start, the write, the read";
}

TEST_P(CmdTiming, ErrorNumberIsThePacNumberUnchanged) {
    pac::test::GvlConstants gvl;
    CmdRig rig(GetParam());
    rig.SettlePastFirstHandshake();
    rig.Cmd()->CODE.value = 0x1906;
    rig.Cmd()->PARAM.value = 60000;
    rig.Cmd()->EXECUTE.value = TRUE;
    rig.Settle(200);
    ASSERT_TRUE(rig.Cmd()->ERROR.value);
    EXPECT_EQ(rig.Cmd()->ERRORID.value, gvl["PAC_ERR_N_REGISTER"]);
}

// PA-CONTROL cycle 7 ms besides the standard grid's: a cycle that is no multiple of any PLC cycle.
INSTANTIATE_TEST_SUITE_P(BusTimings, CmdTiming,
                         ::testing::ValuesIn(pac::test::BusTimingGrid({1, 2, 5, 10}, {1, 3, 7, 10}, {0, 1, 2, 3})),
                         pac::test::BusTimingName);

TEST(CmdOverSim, JitteredBusLosesAndDuplicatesNothing) {
    for (std::uint64_t seed : {11u, 12u, 13u, 14u, 15u}) {
        SCOPED_TRACE("jitter seed " + std::to_string(seed));
        CmdRig rig({2, 3, 1, 5000, seed});
        rig.SettlePastFirstHandshake();
        for (std::uint32_t n = 1; n <= 20; ++n) {
            const FinalOutcome write = rig.Run(0x0906, static_cast<std::uint16_t>(n), n * 1000);
            ASSERT_TRUE(write.Done() && rig.Window().Contains(write.Scans())) << "write " << n << ": " << write
                                                                                << ", allowed " << rig.Window();
            const FinalOutcome read = rig.Run(0x1906, static_cast<std::uint16_t>(n), 0);
            ASSERT_TRUE(read.Done() && rig.Window().Contains(read.Scans())) << "read " << n << ": " << read
                                                                              << ", allowed " << rig.Window();
            EXPECT_EQ(rig.AckData(), n * 1000) << "register " << n;
        }
        EXPECT_EQ(CommandsRecognised(rig.Controller()), 40u);
    }
}

TEST(CmdOverSim, ControllerBootingRefusesThenWorks) {
    pac::test::GvlConstants gvl;
    CmdRig rig({1, 10, 0}, 50ms);
    rig.Settle(5);  // still booting: status 0
    const FinalOutcome refused = rig.Run(0x1906, 1, 0);
    EXPECT_EQ(refused.Scans(), 0) << "refused in the edge scan: " << refused;
    EXPECT_EQ(refused.ErrorId(), gvl["PAC_LIB_ERR_NOT_READY"]);
    rig.Settle(60);
    const FinalOutcome write = rig.Run(0x0906, 1, 5);
    EXPECT_TRUE(write.Done()) << write;
    EXPECT_EQ(CommandsRecognised(rig.Controller()), 1u);
}

TEST(CmdOverSim, PowerCycleDuringCommandThenOneCleanCommand) {
    pac::test::GvlConstants gvl;
    CmdRig rig({1, 10, 1}, 30ms);
    rig.Settle(40);
    ASSERT_TRUE(rig.Run(0x0906, 1, 5).Done());  // SEND = 1 acknowledged
    const auto before = CommandsRecognised(rig.Controller());
    rig.Cmd()->CODE.value = 0x0906;
    rig.Cmd()->PARAM.value = 2;
    rig.Cmd()->DATA.value = 6;
    rig.Cmd()->EXECUTE.value = TRUE;
    rig.Settle(1);  // SEND toggles to 0
    rig.Controller().PowerCycle(rig.Now());
    rig.Settle(100);
    EXPECT_TRUE(rig.Cmd()->ERROR.value);
    EXPECT_EQ(rig.Cmd()->ERRORID.value, gvl["PAC_LIB_ERR_CONNECTION_LOST"]);
    rig.Cmd()->EXECUTE.value = FALSE;
    rig.Settle(1);
    const FinalOutcome read = rig.Run(0x1906, 1, 0);
    EXPECT_TRUE(read.Done()) << read;
    EXPECT_EQ(rig.AckData(), 5u) << "N registers are kept over a power cycle";
    EXPECT_EQ(CommandsRecognised(rig.Controller()), before + 1) << "the restart replayed nothing";
}

// Execute released while the command runs: Done shows for one scan. A program that raises Execute again in
// the very next scan asks for a new command and must get it, not the old Done (the soak's ledger found the
// edge swallowed: Done for a command never sent).
TEST(CmdOverSim, AnEdgeRightAfterAOneScanDoneSendsTheNextCommand) {
    CmdRig rig({1, 3, 1});
    rig.Settle(5);
    auto& cmd = rig.Cmd();
    cmd->CODE.value = 0x0906;
    cmd->PARAM.value = 1;
    cmd->DATA.value = 7;
    cmd->EXECUTE.value = TRUE;
    rig.Settle(1);
    cmd->EXECUTE.value = FALSE;
    for (int i = 0; i < 200 && !cmd->DONE.value; ++i) rig.Settle(1);
    ASSERT_TRUE(cmd->DONE.value) << "the first command's one-scan Done";
    cmd->DATA.value = 8;
    cmd->EXECUTE.value = TRUE;
    rig.Settle(1);
    EXPECT_FALSE(cmd->DONE.value) << "the first command's Done answered the new edge";
    EXPECT_TRUE(cmd->BUSY.value);
    for (int i = 0; i < 200 && !pac::test::IsFinal(cmd); ++i) rig.Settle(1);
    EXPECT_TRUE(cmd->DONE.value);
    EXPECT_EQ(rig.Controller().Counters().Count(0x0906), 2u);
    EXPECT_EQ(rig.Controller().Io().intRegisters.GetInt(1), 8);
}

TEST(CmdOverSim, LinkLossAndReconnectionRepeatNoCommand) {
    CmdRig rig({1, 3, 1});
    rig.Settle(5);
    ASSERT_TRUE(rig.Run(0x0906, 1, 5).Done());  // SEND = 1 acknowledged; the module holds 0906 N1 := 5
    rig.Controller().Io().intRegisters.SetInt(1, 42);  // changed since by the PA-CONTROL's program
    rig.Bus().Disconnect(rig.Now());
    rig.Settle(50);
    rig.Bus().Reconnect(rig.Now());
    rig.Settle(50);
    EXPECT_EQ(rig.Controller().Counters().Count(0x0906), 1u) << "0906 was not repeated";
    EXPECT_EQ(rig.Controller().Io().intRegisters.GetInt(1), 42);
    const FinalOutcome read = rig.Run(0x1906, 1, 0);
    EXPECT_TRUE(read.Done()) << read;
    EXPECT_EQ(rig.AckData(), 42u);
}

TEST(CmdOverSim, FrozenLinkTimesOutAndRecoversAfterThaw) {
    pac::test::GvlConstants gvl;
    const BusTiming timing{1, 3, 0};
    CmdRig rig(timing);
    rig.Settle(5);
    rig.Cmd()->TIMEOUT.value = TIME{0, 50'000'000};
    rig.Bus().FromPacLink().SetFault(rig.Now(), pac::sim::LinkFault::kFrozen);
    const FinalOutcome frozen = rig.Run(0x0906, 1, 9);
    EXPECT_EQ(frozen.ErrorId(), gvl["PAC_LIB_ERR_ACK_TIMEOUT"]) << frozen;
    EXPECT_EQ(frozen.Scans(), pac::test::ProtocolWindow(timing).TimeoutScans(50ms)) << "Timeout from the edge scan";
    rig.Bus().FromPacLink().SetFault(rig.Now(), pac::sim::LinkFault::kNone);
    rig.Settle(10);
    const FinalOutcome read = rig.Run(0x1906, 1, 0);
    EXPECT_TRUE(read.Done()) << read;
    EXPECT_EQ(rig.AckData(), 9u) << "the command itself had reached the controller";
}

}  // namespace
}  // namespace test_fb_pac_cmd_sim
