// FB_PAC_Cmd against the simulated PA-CONTROL over the simulated bus: every combination of PLC
// cycle (1-10 ms), controller cycle (1-10 ms) and bus latency (0-3 PLC cycles each way). Each test
// checks the results, that the controller saw exactly the commands the PLC meant (no spurious or
// lost command), and that Done comes at the protocol minimum: the FB adds no scan of its own.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <sstream>
#include <string>
#include <tuple>

#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"
#include "pac/pac_plc_bench.hpp"

namespace {

using namespace std::chrono_literals;
using std::chrono::milliseconds;
using std::chrono::nanoseconds;

struct Timing {
    int plcMs;
    int slaveMs;
    int latencyCycles;
};

// A PLC with one FB_PAC_Cmd on the CMD interface of a simulated PA-CONTROL.
class CmdBench {
public:
    CmdBench(Timing timing, nanoseconds jitter = 0ns, std::uint64_t seed = 1, nanoseconds bootTime = 0ns)
        : plc_({milliseconds(timing.plcMs), milliseconds(timing.slaveMs), timing.latencyCycles, jitter, seed,
                bootTime}) {
        plc_.Call(cmd_);
        plc_.Start();
    }

    // Runs one command to its end: Execute edge, wait for Done or Error, Execute back to FALSE.
    // Returns the scans from the edge to the final output (-1 if none came within maxScans).
    int Run(std::uint16_t code, std::uint16_t param, std::uint32_t data, int maxScans = 2000) {
        cmd_->CODE.value = code;
        cmd_->PARAM.value = param;
        cmd_->DATA.value = data;
        cmd_->EXECUTE.value = TRUE;
        plc_.Scan();
        edgeTime_ = plc_.Now();
        const int scans = plc_.ScanUntil([this] { return cmd_->DONE.value || cmd_->ERROR.value; }, maxScans);
        final_ = {cmd_->DONE.value != 0, cmd_->ERROR.value != 0, cmd_->ERRORID.value, cmd_->ACKDATA.value};
        cmd_->EXECUTE.value = FALSE;
        plc_.Scan();
        return scans;
    }

    // The outputs in the scan that ended the last Run() (Execute falls in the scan after it).
    struct Final {
        bool done = false;
        bool error = false;
        std::uint32_t errorId = 0;
        std::uint32_t ackData = 0;
    };
    const Final& Last() const { return final_; }

    int ProtocolMinimumScans() const { return plc_.ProtocolMinimumScans(edgeTime_); }

    void Settle(int scans) { plc_.Scan(scans); }

    pac::FbInstance<FB_PAC_CMD>& Cmd() { return cmd_; }
    pac::sim::PaControl& Controller() { return plc_.Controller(); }
    pac::sim::Bus& Bus() { return plc_.Bus(); }
    nanoseconds Now() const { return plc_.Now(); }

private:
    pac::PacPlcBench plc_;
    pac::FbInstance<FB_PAC_CMD> cmd_ = PAC_FB(FB_PAC_CMD);
    nanoseconds edgeTime_{0};
    Final final_;
};

class CmdTiming : public ::testing::TestWithParam<std::tuple<int, int, int>> {
protected:
    Timing Param() const {
        return {std::get<0>(GetParam()), std::get<1>(GetParam()), std::get<2>(GetParam())};
    }
};

TEST_P(CmdTiming, WriteThenReadRegisterAtTheProtocolMinimum) {
    CmdBench bench(Param());
    bench.Settle(3);
    const int writeScans = bench.Run(0x0906, 3, 333);
    ASSERT_TRUE(bench.Last().done) << "0906 did not end with Done";
    EXPECT_EQ(writeScans, bench.ProtocolMinimumScans());
    const int readScans = bench.Run(0x1906, 3, 0);
    EXPECT_EQ(readScans, bench.ProtocolMinimumScans());
    EXPECT_EQ(bench.Last().ackData, 333u);
    EXPECT_EQ(bench.Controller().Counters().recognized, 2u) << "exactly the two commands, nothing spurious";
}

TEST_P(CmdTiming, CommandErrorThenGoodCommand) {
    pac::test::GvlConstants gvl;
    CmdBench bench(Param());
    bench.Settle(3);
    ASSERT_GT(bench.Run(0x1906, 60000, 0), 0);
    EXPECT_TRUE(bench.Last().error);
    EXPECT_EQ(bench.Controller().Counters().failed, 1u);
    ASSERT_GT(bench.Run(0x0906, 5, 77), 0);
    EXPECT_FALSE(bench.Last().error);
    ASSERT_GT(bench.Run(0x1906, 5, 0), 0);
    EXPECT_EQ(bench.Last().ackData, 77u);
    EXPECT_EQ(bench.Controller().Counters().recognized, 3u);
    EXPECT_EQ(bench.Controller().Counters().executed, 2u);
}

TEST_P(CmdTiming, ErrorNumberIsThePacNumberUnchanged) {
    pac::test::GvlConstants gvl;
    CmdBench bench(Param());
    bench.Settle(3);
    bench.Cmd()->CODE.value = 0x1906;
    bench.Cmd()->PARAM.value = 60000;
    bench.Cmd()->EXECUTE.value = TRUE;
    bench.Settle(200);
    ASSERT_TRUE(bench.Cmd()->ERROR.value);
    EXPECT_EQ(bench.Cmd()->ERRORID.value, gvl["PAC_ERR_N_REGISTER"]);
}

std::string TimingName(const ::testing::TestParamInfo<std::tuple<int, int, int>>& info) {
    std::ostringstream name;
    name << "Plc" << std::get<0>(info.param) << "ms_Pac" << std::get<1>(info.param) << "ms_Latency"
         << std::get<2>(info.param);
    return name.str();
}

INSTANTIATE_TEST_SUITE_P(AllTimings, CmdTiming,
                         ::testing::Combine(::testing::Values(1, 2, 5, 10), ::testing::Values(1, 3, 7, 10),
                                            ::testing::Values(0, 1, 2, 3)),
                         TimingName);

TEST(CmdOverSim, JitteredBusLosesAndDuplicatesNothing) {
    for (std::uint64_t seed : {11u, 12u, 13u, 14u, 15u}) {
        SCOPED_TRACE("jitter seed " + std::to_string(seed));
        CmdBench bench({2, 3, 1}, 5ms, seed);
        bench.Settle(3);
        for (std::uint32_t n = 1; n <= 20; ++n) {
            ASSERT_GT(bench.Run(0x0906, static_cast<std::uint16_t>(n), n * 1000), 0) << "write " << n;
            ASSERT_GT(bench.Run(0x1906, static_cast<std::uint16_t>(n), 0), 0) << "read " << n;
            EXPECT_EQ(bench.Last().ackData, n * 1000) << "register " << n;
        }
        EXPECT_EQ(bench.Controller().Counters().recognized, 40u);
    }
}

TEST(CmdOverSim, ControllerBootingRefusesThenWorks) {
    pac::test::GvlConstants gvl;
    CmdBench bench({1, 10, 0}, 0ns, 1, 50ms);
    bench.Settle(5);  // still booting: status 0
    ASSERT_GE(bench.Run(0x1906, 1, 0), 0);
    EXPECT_EQ(bench.Last().errorId, gvl["PAC_LIB_ERR_NOT_READY"]);
    bench.Settle(60);
    ASSERT_GT(bench.Run(0x0906, 1, 5), 0);
    EXPECT_TRUE(bench.Last().done);
    EXPECT_EQ(bench.Controller().Counters().recognized, 1u);
}

TEST(CmdOverSim, PowerCycleDuringCommandThenOneCleanCommand) {
    pac::test::GvlConstants gvl;
    CmdBench bench({1, 10, 1}, 0ns, 1, 30ms);
    bench.Settle(40);
    ASSERT_GT(bench.Run(0x0906, 1, 5), 0);  // SEND = 1 acknowledged
    const auto before = bench.Controller().Counters().recognized;
    bench.Cmd()->CODE.value = 0x0906;
    bench.Cmd()->PARAM.value = 2;
    bench.Cmd()->DATA.value = 6;
    bench.Cmd()->EXECUTE.value = TRUE;
    bench.Settle(1);  // SEND toggles to 0
    bench.Controller().PowerCycle(bench.Now());
    bench.Settle(100);
    EXPECT_TRUE(bench.Cmd()->ERROR.value);
    EXPECT_EQ(bench.Cmd()->ERRORID.value, gvl["PAC_LIB_ERR_CONNECTION_LOST"]);
    bench.Cmd()->EXECUTE.value = FALSE;
    bench.Settle(1);
    ASSERT_GT(bench.Run(0x1906, 1, 0), 0);
    EXPECT_TRUE(bench.Last().done);
    EXPECT_EQ(bench.Last().ackData, 5u) << "N registers are kept over a power cycle";
    EXPECT_EQ(bench.Controller().Counters().recognized, before + 1) << "the restart replayed nothing";
}

TEST(CmdOverSim, LinkLossAndReconnectionRepeatNoCommand) {
    CmdBench bench({1, 3, 1});
    bench.Settle(5);
    ASSERT_GT(bench.Run(0x0906, 1, 5), 0);  // SEND = 1 acknowledged; the module holds 0906 N1 := 5
    bench.Controller().Io().intRegisters.SetInt(1, 42);  // changed since by the PA-CONTROL's program
    bench.Bus().Disconnect(bench.Now());
    bench.Settle(50);
    bench.Bus().Reconnect(bench.Now());
    bench.Settle(50);
    EXPECT_EQ(bench.Controller().Counters().Count(0x0906), 1u) << "0906 was not repeated";
    EXPECT_EQ(bench.Controller().Io().intRegisters.GetInt(1), 42);
    ASSERT_GT(bench.Run(0x1906, 1, 0), 0);
    EXPECT_TRUE(bench.Last().done);
    EXPECT_EQ(bench.Last().ackData, 42u);
}

TEST(CmdOverSim, FrozenLinkTimesOutAndRecoversAfterThaw) {
    pac::test::GvlConstants gvl;
    CmdBench bench({1, 3, 0});
    bench.Settle(5);
    bench.Cmd()->TIMEOUT.value = TIME{0, 50'000'000};
    bench.Bus().FromPacLink().SetFault(bench.Now(), pac::sim::LinkFault::kFrozen);
    ASSERT_GT(bench.Run(0x0906, 1, 9), 0);
    EXPECT_EQ(bench.Last().errorId, gvl["PAC_LIB_ERR_ACK_TIMEOUT"]);
    bench.Bus().FromPacLink().SetFault(bench.Now(), pac::sim::LinkFault::kNone);
    bench.Settle(10);
    ASSERT_GT(bench.Run(0x1906, 1, 0), 0);
    EXPECT_TRUE(bench.Last().done);
    EXPECT_EQ(bench.Last().ackData, 9u) << "the command itself had reached the controller";
}

}  // namespace
