#include "pac/fb_instance.hpp"
#include "pac/scan_test.hpp"
#include "pac/st_program.hpp"

class CmdTimeoutTest : public pac::ScanTest {};

TEST_F(CmdTimeoutTest, NoAcknowledgementWithinTimeout) {
    auto interface = PAC_FB(FB_PAC_CMDINTERFACE);  // serves the CMD module; the command FBs share its Channel
    auto cmd = PAC_FB(FB_PAC_CMD);
    std::uint8_t reply[8] = {0, 0, 0, 0, 0, 1, 0x20, 0};  // status 1, RF 0, BF 1: nothing outstanding
    task_.AddProgram([&] {
        ST_PAC_CMDCHANNEL& channel = interface->CHANNEL.value;
        for (int i = 0; i < 8; ++i) channel.FROMPAC.table[i] = reply[i];  // the input image
        interface();
        cmd->CHANNEL.value = channel;  // a VAR_IN_OUT: copied in and back out around the call
        cmd();
        channel = cmd->CHANNEL.value;  // channel.TOPAC is the output image
        // A controller that answers only the parked read (190B), the interface's first handshake: RF := SEND.
        if ((channel.TOPAC.table[6] & 0x7F) == 0x19 && channel.TOPAC.table[7] == 0x0B) {
            reply[6] = static_cast<std::uint8_t>((channel.TOPAC.table[6] & 0x80) | 0x20);
        }
    });
    cmd->CODE.value = 0x1906;  // PAC_CMD_GET_INT_REG
    cmd->PARAM.value = 3;
    cmd->TIMEOUT.value = TIME{0, 5'000'000};  // T#5MS
    cmd->EXECUTE.value = TRUE;
    ASSERT_TRUE(RunUntil([&] { return cmd->ERROR.value != 0; }, 20, "Error"));
    EXPECT_EQ(cmd->ERRORID.value, 0x8001);  // PAC_LIB_ERR_ACK_TIMEOUT
    EXPECT_EQ(task_.ScanCount(), 7);  // edge in scan 1, sent in scan 2 after the parked read, Timeout at 7 ms
}
