// ONLINE commands of manual 5.2.6: moves that end later (0A87, 0A89: RF = SF with BF = 0 at once,
// acknowledgement data following the axis position, BF = 1 at the target), 0A93, 0A94/0A95, 0A8D,
// 0A83, and their errors; a SEND toggle while a move is processing (docs/simulator.md).
#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

class OnlineCommands : public PacBench {
protected:
    void SetUp() override {
        GoOnline();                                          // 0 ms, SEND 1
        ASSERT_EQ(Tail(Send(code::kGetState)), "00 1F 20 00");  // 10 ms, SEND 0
    }
};

TEST_F(OnlineCommands, AbsoluteMoveReportsBf0ThenTheTravelThenBf1) {
    // 20 ms: 0A87 axis 1 to 100.0 at 1000 AE/s; 10 AE per 10 ms cycle.
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(100.0F)), "00 00 00 00 00 1F 80 00");
    for (int k = 1; k <= 9; ++k) {
        const float position = 10.0F * static_cast<float>(k);
        EXPECT_EQ(Idle(), RealHex(position) + " 00 1F 80 00") << "cycle " << k;
    }
    EXPECT_EQ(Idle(), "42 C8 00 00 00 1F A0 00");  // 120 ms: at 100.0, BF = 1
    EXPECT_EQ(Idle(), "42 C8 00 00 00 1F A0 00");
    EXPECT_EQ(pac_.Counters().Count(code::kPosAxisAbsolute), 1U);
}

TEST_F(OnlineCommands, RelativeMoveFromTheCurrentPosition) {
    pac_.Axes().Motion(2).SetPosition(100.0);
    // 0A89 axis 2 by -30.0: start 100.0 (42 C8 00 00), then 90, 80, 70.
    EXPECT_EQ(Send(code::kPosAxisRelative, 2, FloatToBits(-30.0F)), "42 C8 00 00 00 1F 80 00");
    EXPECT_EQ(Idle(), "42 B4 00 00 00 1F 80 00");  // 90.0
    EXPECT_EQ(Idle(), "42 A0 00 00 00 1F 80 00");  // 80.0
    EXPECT_EQ(Idle(), "42 8C 00 00 00 1F A0 00");  // 70.0, done
}

TEST_F(OnlineCommands, StopAxisEndsWhenTheAxisStandsStill) {
    // 0A94: start and end of processing at once (ack: start position 0.0).
    EXPECT_EQ(Send(code::kStartAxisAbsolute, 1, FloatToBits(1000.0F)), "00 00 00 00 00 1F A0 00");  // 20 ms
    EXPECT_EQ(Idle(), "00 00 00 00 00 1F A0 00");                                                // 30 ms
    // 40 ms, at 20.0: 0A93 brakes (1000 AE/s, 10000 AE/s^2: 100 ms, 50 AE) with BF = 0.
    EXPECT_EQ(Send(code::kStopAxis, 1), "41 A0 00 00 00 1F 00 00");  // 20.0
    // 50 ms: 20 + 1000*0.01 - 10000*0.01^2/2 = 29.5
    EXPECT_EQ(Idle(), "41 EC 00 00 00 1F 00 00");
    for (int i = 0; i < 8; ++i) Idle();  // 60..130 ms
    EXPECT_EQ(Idle(), "42 8C 00 00 00 1F 20 00");  // 140 ms: standing at 70.0, BF = 1
    EXPECT_EQ(Send(code::kGetStatusAxis, 1), "00 00 00 02 00 1F A0 00");
}

TEST_F(OnlineCommands, StopAxisOnAStandingAxisEndsAtOnce) {
    pac_.Axes().Motion(1).SetPosition(10.0);
    EXPECT_EQ(Send(code::kStopAxis, 1), "41 20 00 00 00 1F A0 00");
}

TEST_F(OnlineCommands, SetSpeedWithinTheParameterLimits) {
    EXPECT_EQ(Send(code::kSetSpeedAxis, 1, FloatToBits(2000.0F)), "44 FA 00 00 00 1F A0 00");
    EXPECT_EQ(Send(code::kPosAxisRelative, 1, FloatToBits(40.0F)), "00 00 00 00 00 1F 00 00");
    EXPECT_EQ(Idle(), "41 A0 00 00 00 1F 00 00");  // 20.0 after 10 ms
    EXPECT_EQ(Idle(), "42 20 00 00 00 1F 20 00");  // 40.0: done
    // 60000 > max 50000, 0, NaN: error 41.
    EXPECT_EQ(Send(code::kSetSpeedAxis, 1, FloatToBits(60000.0F)), "00 00 00 00 00 1F C0 29");
    EXPECT_EQ(Send(code::kSetSpeedAxis, 1, 0), "00 00 00 00 00 1F 40 29");
    EXPECT_EQ(Send(code::kSetSpeedAxis, 1, 0x7FC00000), "00 00 00 00 00 1F C0 29");
    // Leaving ONLINE restores the parameter's speed.
    Send(code::kAbortOnline);
    EXPECT_EQ(pac_.Axes().Motion(1).Speed(), 1000.0);
}

TEST_F(OnlineCommands, MoveErrors) {
    // Axis 3 of 2, axis 0: error 32 = 16#20.
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 3, FloatToBits(1.0F)), "00 00 00 00 00 1F C0 20");
    EXPECT_EQ(Send(code::kStopAxis, 0), "00 00 00 00 00 1F 40 20");
    // Outside the traverse area 0..10000: error 65 = 16#41.
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(10000.5F)), "00 00 00 00 00 1F C0 41");
    EXPECT_EQ(Send(code::kPosAxisRelative, 1, FloatToBits(-1.0F)), "00 00 00 00 00 1F 40 41");
    // Not a number: error 41.
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, 0x7F800000), "00 00 00 00 00 1F C0 29");
    // Not referenced: error 43 = 16#2B, until 0A83 releases the axis.
    pac_.Axes().Motion(2).SetReferenced(false);
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 2, FloatToBits(5.0F)), "00 00 00 00 00 1F 40 2B");
    EXPECT_EQ(Send(code::kPutNoReference, 2), "00 00 00 00 00 1F A0 00");
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 2, FloatToBits(500.0F)), "00 00 00 00 00 1F 00 00");
    // Axis 2 still moves: error 42 = 16#2A.
    EXPECT_EQ(Send(code::kStartAxisAbsolute, 2, FloatToBits(9.0F)), "00 00 00 00 00 1F C0 2A");
    EXPECT_EQ(pac_.Counters().failed, 7U);
}

TEST_F(OnlineCommands, MovesOnlyInOnlineProper) {
    // ONLINE and stopped (35): error 20.
    pac_.SetOperatingStatus(status::kOnlineStopped);
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(5.0F)), "00 00 00 00 00 23 C0 14");
    EXPECT_EQ(Send(code::kStartAxisRelative, 1, FloatToBits(5.0F)), "00 00 00 00 00 23 40 14");
    // Home position: error 20.
    EXPECT_EQ(Send(code::kAbortOnline), "00 00 00 00 00 01 A0 00");
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(5.0F)), "00 00 00 00 00 01 40 14");
    EXPECT_EQ(Send(code::kStopAxis, 1), "00 00 00 00 00 01 C0 14");
}

TEST_F(OnlineCommands, SendToggleWhileAMoveIsProcessingTakesTheReplyOver) {
    pac_.Io().intRegisters.SetInt(4, 44);
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(50.0F)), "00 00 00 00 00 1F 80 00");  // 20 ms
    EXPECT_EQ(Idle(), "41 20 00 00 00 1F 80 00");  // 30 ms: 10.0
    // 40 ms: 1906 N4. The reply is now 1906's; the axis carries on.
    EXPECT_EQ(Send(code::kGetIntReg, 4), "00 00 00 2C 00 1F 20 00");
    EXPECT_EQ(Idle(), "00 00 00 2C 00 1F 20 00");
    // A second move of the same axis meanwhile: error 42.
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(0.0F)), "00 00 00 00 00 1F C0 2A");
    Idle();  // 70 ms: at 50.0
    EXPECT_EQ(Send(code::kGetActualPos, 1), "42 48 00 00 00 1F 20 00");
    EXPECT_EQ(Send(code::kGetStatusAxis, 1), "00 00 00 00 00 1F A0 00");
}

TEST_F(OnlineCommands, MoveToTheCurrentPositionEndsAtOnce) {
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, 0), "00 00 00 00 00 1F A0 00");
}

}  // namespace
}  // namespace pac::sim::testing
