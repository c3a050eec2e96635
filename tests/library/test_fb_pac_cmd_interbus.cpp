// The Interbus-S complex example of manual 4.2.4 driven by FB_PAC_Cmd against the simulated
// PA-CONTROL, byte for byte, with the errata of docs/manual_errata.md corrected: replies to SEND = 0 end in 20 00,
// the third command writes N3, and 640.0 is 44 20 00 00. With FB_PAC_CmdInterface.TwoStepWrite the FB
// writes both of the example's rows, "command code & parameter" with the SEND flag unchanged and then
// "SEND flag toggle"; by default it writes the toggle row at once. Between commands the module is parked
// (190B, the SEND flag kept), where the example shows nothing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pac/fb_instance.hpp"
#include "pac/sim/image8.hpp"
#include "pac/st_program.hpp"
#include "pac/pac_rig.hpp"

namespace test_fb_pac_cmd_interbus {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;

struct Step {
    std::uint16_t code;
    std::uint16_t param;
    std::uint32_t data;
    std::string loaded;  // the example's "command code & parameter" row: SEND flag unchanged
    std::string toggle;  // its "SEND flag toggle" row
    std::string reply;   // the acknowledgement FB_PAC_Cmd reports Done on
};

class FbPacCmdInterbus : public ::testing::TestWithParam<bool> {};

TEST_P(FbPacCmdInterbus, ComplexExampleByteForByte) {
    const bool twoStep = GetParam();
    pac::PacRig plc({1ms, 10ms, 1});
    plc.Controller().Io().inputs.Set(5, true);
    plc.Controller().Io().intRegisters.SetInt(2, 12345678);
    plc.Controller().Io().realRegisters.SetReal(1, 640.0F);
    auto cmd = PAC_FB(FB_PAC_CMD);
    plc.Call(cmd);
    plc.CmdInterface()->TWOSTEPWRITE.value = twoStep;
    plc.Start();
    plc.Scan(1);
    const std::string idle = pac::sim::ToHex(plc.ToPac());
    EXPECT_TRUE(idle == "00 00 00 00 00 00 19 0B" || idle == "00 00 00 00 00 00 99 0B")
        << idle << ": idle is the parked read, never the all-zero image";
    plc.Scan(20);
    // The cold start's first handshake: the parked read toggled to SEND 1 and acknowledged, so the manual's
    // example follows with every SEND and RECEIVE flag the other way round.
    EXPECT_EQ(pac::sim::ToHex(plc.ToPac()), "00 00 00 00 00 00 99 0B");
    EXPECT_EQ(pac::sim::ToHex(plc.FromPac()), "00 00 00 01 00 01 A0 00") << "190B answered: status 1";

    const std::vector<Step> steps = {
        {0x1900, 5, 0, "00 00 00 00 00 05 99 00", "00 00 00 00 00 05 19 00", "00 00 00 01 00 01 20 00"},
        {0x1906, 2, 0, "00 00 00 00 00 02 19 06", "00 00 00 00 00 02 99 06", "00 BC 61 4E 00 01 A0 00"},
        {0x0906, 3, 333, "00 00 01 4D 00 03 89 06", "00 00 01 4D 00 03 09 06", "00 00 01 4D 00 01 20 00"},
        {0x1907, 1, 0, "00 00 00 00 00 01 19 07", "00 00 00 00 00 01 99 07", "44 20 00 00 00 01 A0 00"},
    };
    for (const Step& step : steps) {
        SCOPED_TRACE(step.toggle);
        cmd->CODE.value = step.code;
        cmd->PARAM.value = step.param;
        cmd->DATA.value = step.data;
        cmd->EXECUTE.value = TRUE;
        if (twoStep) {
            plc.Scan(1);
            EXPECT_EQ(pac::sim::ToHex(plc.ToPac()), step.loaded) << "code and parameter, the SEND flag unchanged";
        }
        plc.Scan(1);
        EXPECT_EQ(pac::sim::ToHex(plc.ToPac()), step.toggle);
        ASSERT_GT(plc.ScanUntil([&] { return cmd->DONE.value || cmd->ERROR.value; }, 100), 0);
        EXPECT_TRUE(cmd->DONE.value);
        EXPECT_EQ(pac::sim::ToHex(plc.FromPac()), step.reply);
        const bool send = step.toggle[18] >= '8';  // bit 15: the top bit of byte 6
        EXPECT_EQ(pac::sim::ToHex(plc.ToPac()), send ? "00 00 00 00 00 00 99 0B" : "00 00 00 00 00 00 19 0B")
            << "parked after its end, the SEND flag kept";
        cmd->EXECUTE.value = FALSE;
        plc.Scan(1);
    }
    EXPECT_EQ(plc.Controller().Io().intRegisters.GetInt(3), 333);
    EXPECT_EQ(plc.Controller().Counters().recognized, 5u) << "the parked read and the four commands";
}

INSTANTIATE_TEST_SUITE_P(WriteSteps, FbPacCmdInterbus, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "TwoStep" : "OneStep"; });

}  // namespace
}  // namespace test_fb_pac_cmd_interbus
