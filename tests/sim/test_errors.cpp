// Command errors of manual 6.5 by cause: unknown command (19), inadmissible in this mode (20),
// injected errors, and the counters of recognised commands.
#include <stdexcept>

#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

class CommandErrors : public PacRig {};

TEST_F(CommandErrors, UnknownCodesGiveError19) {
    // 16#0A99 and 16#1912 lie between commands of chapter 5; 16#7FFF and 16#0000 are no commands at all.
    EXPECT_EQ(Send(0x0A99, 1), "00 00 00 00 00 01 C0 13");
    EXPECT_EQ(Send(0x7FFF), "00 00 00 00 00 01 40 13");
    EXPECT_EQ(Send(0x0000, 1), "00 00 00 00 00 01 C0 13");
    EXPECT_EQ(Send(0x1912, 1), "00 00 00 00 00 01 40 13");
    EXPECT_EQ(pac_.Counters().failed, 4U);
    EXPECT_EQ(pac_.Counters().executed, 0U);
}

TEST_F(CommandErrors, EverySupportedCommandIsKnown) {
    for (const CommandInfo& info : SupportedCommands()) {
        const ReplyFrame reply = SendFrame(info.code, 1, 0);
        EXPECT_FALSE(reply.commandErrorFlag && reply.errorNumber == error::kUnknownCommand)
            << std::hex << info.code << " " << info.name;
        pac_.SetOperatingStatus(status::kHome);
    }
}

struct ModeCase {
    std::uint8_t status;
    std::uint16_t code;
};

TEST_F(CommandErrors, InadmissibleInThisModeGivesError20) {
    const ModeCase cases[] = {
        {status::kOnline, code::kSetSystemParameter},  {status::kAuto, code::kGetAxisParameter},
        {status::kManualPanel, code::kStartOnline},    {status::kAuto, code::kStartAuto},
        {status::kHome, code::kPosAxisAbsolute},       {status::kAuto, code::kPosAxisRelative},
        {status::kManualSerial, code::kStopAxis},      {status::kHome, code::kAbortAuto},
        {status::kOnline, code::kAbortAuto},           {status::kAuto, code::kAbortOnline},
        {status::kAuto, code::kResetError},            {status::kOnline, code::kResetError},
        {status::kManualPanel, code::kStop},           {status::kHome, code::kSetSpeedAxis},
    };
    for (const ModeCase& c : cases) {
        pac_.SetOperatingStatus(c.status);
        const ReplyFrame reply = SendFrame(c.code, 1, 0);
        EXPECT_TRUE(reply.commandErrorFlag) << std::hex << c.code << " in status " << std::dec << int(c.status);
        EXPECT_EQ(reply.errorNumber, error::kInadmissibleCommand) << std::hex << c.code;
        EXPECT_FALSE(reply.endOfProcessing);
        EXPECT_EQ(reply.receiveFlag, send_);
        EXPECT_EQ(pac_.OperatingStatus(), c.status);
    }
}

TEST_F(CommandErrors, InjectedErrorAnswersTheNextCommandOnly) {
    pac_.InjectCommandError(21);
    EXPECT_EQ(Send(code::kPutIntReg, 1, 9), "00 00 00 00 00 01 C0 15");
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(1), 0);  // not carried out
    EXPECT_EQ(Send(code::kPutIntReg, 1, 9), "00 00 00 09 00 01 20 00");
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(1), 9);
    pac_.InjectCommandError(0x1FFF);
    EXPECT_EQ(Send(code::kGetState), "00 00 00 00 00 01 DF FF");
    pac_.InjectCommandError(0);
    EXPECT_EQ(Send(code::kGetState), "00 00 00 00 00 01 40 00") << "KF = 1 without a number";
    EXPECT_EQ(pac_.Counters().failed, 3u);
    EXPECT_THROW(pac_.InjectCommandError(0x2000), std::invalid_argument);
}

TEST_F(CommandErrors, CountersCountRecognisedExecutedAndFailed) {
    Send(code::kGetState);
    Send(code::kGetState);
    Idle();  // no toggle: nothing counted
    Send(0x1234);
    EXPECT_EQ(pac_.Counters().recognized, 3U);
    EXPECT_EQ(pac_.Counters().executed, 2U);
    EXPECT_EQ(pac_.Counters().failed, 1U);
    EXPECT_EQ(pac_.Counters().Count(code::kGetState), 2U);
    EXPECT_EQ(pac_.Counters().Count(0x1234), 1U);
    EXPECT_EQ(pac_.Counters().Count(code::kPutIntReg), 0U);
}

TEST_F(CommandErrors, LogRecordsEveryCycle) {
    Idle();
    Send(code::kGetState);
    Idle();
    const auto& records = pac_.Log().Records();
    ASSERT_EQ(records.size(), 3U);
    EXPECT_EQ(records[1].time, 10ms);
    EXPECT_TRUE(records[1].newCommand);
    EXPECT_FALSE(records[2].newCommand);
    EXPECT_EQ(ToHex(records[1].toPac), "00 00 00 00 00 00 99 0B");
    EXPECT_EQ(ToHex(records[1].fromPac), "00 00 00 01 00 01 A0 00");
    EXPECT_EQ(pac_.Log().Format(),
              "        0 ms  to PAC 00 00 00 00 00 00 00 00  from PAC 00 00 00 00 00 01 20 00\n"
              "       10 ms  to PAC 00 00 00 00 00 00 99 0B  from PAC 00 00 00 01 00 01 A0 00  <- new command\n");
}

}  // namespace
}  // namespace pac::sim::testing
