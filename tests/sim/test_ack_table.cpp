// Each row of the acknowledgement table of manual 2.4.2 / 4.2.3, seen by the PLC byte by byte:
//   SF != RF            not recognised yet
//   SF = RF, KF = 1     command error (error number)
//   SF = RF, KF = 0, BF = 0   recognised, not executed yet
//   SF = RF, KF = 0, BF = 1   recognised and executed
#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

class AckTable : public PacRig {};

TEST_F(AckTable, IdleAfterBootIsRf0Bf1InHomePosition) {
    EXPECT_EQ(Exchange(Image8{}), "00 00 00 00 00 01 20 00");
}

TEST_F(AckTable, SendToggleNotRecognisedYetUntilTheControllerCycles) {
    pac_.Io().intRegisters.SetInt(2, 7);
    pac_.Cycle(0ms);
    // The PLC toggles SEND at 5 ms; the controller's next cycle is at 10 ms.
    bus_.WriteToPac(5ms, CommandImage(0x1906, 2, 0, true));
    const ReplyFrame before = ReplyFrame::Decode(bus_.ReadFromPac(5ms).Cmd());
    EXPECT_FALSE(before.receiveFlag);  // SF = 1, RF = 0: not recognised yet
    EXPECT_EQ(ToHex(bus_.ReadFromPac(9ms)), "00 00 00 00 00 01 20 00");
    pac_.Cycle(10ms);
    EXPECT_EQ(ToHex(bus_.ReadFromPac(10ms)), "00 00 00 07 00 01 A0 00");
}

TEST_F(AckTable, CommandErrorSetsKfWithTheErrorNumber) {
    Exchange(Image8{});
    // 16#1234 is no command: error 19 = 16#13, RF = SF = 1, KF = 1, BF = 0.
    EXPECT_EQ(Send(0x1234, 0, 0), "00 00 00 00 00 01 C0 13");
    // SF = 0 this time: RF follows it.
    EXPECT_EQ(Send(0x1234, 0, 0), "00 00 00 00 00 01 40 13");
}

TEST_F(AckTable, RecognisedButNotExecutedYetWhileAnAxisMoves) {
    GoOnline();                                       // SEND 1
    EXPECT_EQ(Tail(Send(code::kGetState)), "00 1F 20 00");  // SEND 0
    // 0A87 axis 1 to 100.0 (SEND 1): start position 0.0, BF = 0.
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(100.0F)), "00 00 00 00 00 1F 80 00");
    EXPECT_EQ(Tail(Idle()), "00 1F 80 00");
}

TEST_F(AckTable, RecognisedAndExecuted) {
    pac_.Io().intRegisters.SetInt(2, 12345678);
    EXPECT_EQ(Send(code::kGetIntReg, 2), "00 BC 61 4E 00 01 A0 00");
    EXPECT_EQ(Send(code::kGetIntReg, 2), "00 BC 61 4E 00 01 20 00");
}

TEST_F(AckTable, NewDataWithoutASendToggleIsNotACommand) {
    pac_.Io().intRegisters.SetInt(5, 1);
    EXPECT_EQ(Send(code::kGetIntReg, 5), "00 00 00 01 00 01 A0 00");
    // Same SEND flag, other code and data: nothing happens, the reply stays.
    EXPECT_EQ(Exchange(CommandImage(code::kPutIntReg, 5, 99, true)), "00 00 00 01 00 01 A0 00");
    EXPECT_EQ(Idle(), "00 00 00 01 00 01 A0 00");
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(5), 1);
    EXPECT_EQ(pac_.Counters().recognized, 1U);
}

}  // namespace
}  // namespace pac::sim::testing
