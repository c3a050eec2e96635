// ONLINE commands of manual 5.2.6: moves that end later (0A87, 0A89: RF = SF with BF = 0 at once,
// acknowledgement data following the axis position, BF = 1 at the target), 0A93, 0A94/0A95, 0A8D,
// 0A83, and their errors; a SEND toggle while a move is processing (docs/simulator.md). The axes have the
// default parameters: 1000 AE/s, ramps of 10000 AE/s^2 (100 ms, 50 AE to full speed).
#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

// A move of 100 AE from standstill is a triangle of 200 ms peaking at 1000 AE/s: the distance after t s.
double Triangle100(double t) { return t <= 0.1 ? 5000.0 * t * t : 100.0 - 5000.0 * (0.2 - t) * (0.2 - t); }

class OnlineCommands : public PacRig {
protected:
    void SetUp() override {
        GoOnline();                                          // 0 ms, SEND 1
        ASSERT_EQ(Tail(Send(code::kGetState)), "00 1F 20 00");  // 10 ms, SEND 0
    }
};

TEST_F(OnlineCommands, AbsoluteMoveReportsBf0ThenTheTravelThenBf1) {
    // 20 ms: 0A87 axis 1 to 100.0: 0.5, 2.0, 4.5, ... 50.0 (120 ms), ... 99.5, 100.0 at 220 ms.
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(100.0F)), "00 00 00 00 00 1F 80 00");
    for (int k = 1; k <= 19; ++k) {
        const float position = static_cast<float>(Triangle100(k / 100.0));
        EXPECT_EQ(Idle(), RealHex(position) + " 00 1F 80 00") << "cycle " << k;
    }
    EXPECT_EQ(Idle(), "42 C8 00 00 00 1F A0 00");  // 220 ms: at 100.0, BF = 1
    EXPECT_EQ(Idle(), "42 C8 00 00 00 1F A0 00");
    EXPECT_EQ(pac_.Counters().Count(code::kPosAxisAbsolute), 1U);
}

TEST_F(OnlineCommands, RelativeMoveFromTheCurrentPosition) {
    pac_.Axes().Motion(2).Place(now_, 100.0);
    // 0A89 axis 2 by -25.0: start 100.0 (42 C8 00 00); a triangle of 100 ms peaking at 500 AE/s after 12.5 AE.
    EXPECT_EQ(Send(code::kPosAxisRelative, 2, FloatToBits(-25.0F)), "42 C8 00 00 00 1F 80 00");
    EXPECT_EQ(Idle(), "42 C7 00 00 00 1F 80 00");  // 99.5
    EXPECT_EQ(Idle(), "42 C4 00 00 00 1F 80 00");  // 98.0
    EXPECT_EQ(Idle(), "42 BF 00 00 00 1F 80 00");  // 95.5
    EXPECT_EQ(Idle(), "42 B8 00 00 00 1F 80 00");  // 92.0
    EXPECT_EQ(Idle(), "42 AF 00 00 00 1F 80 00");  // 87.5: at the peak speed
    EXPECT_EQ(Idle(), "42 A6 00 00 00 1F 80 00");  // 83.0 = 75 + 5000 * 0.04^2
    EXPECT_EQ(Idle(), "42 9F 00 00 00 1F 80 00");  // 79.5
    EXPECT_EQ(Idle(), "42 9A 00 00 00 1F 80 00");  // 77.0
    EXPECT_EQ(Idle(), "42 97 00 00 00 1F 80 00");  // 75.5
    EXPECT_EQ(Idle(), "42 96 00 00 00 1F A0 00");  // 75.0, done
}

TEST_F(OnlineCommands, StopAxisEndsWhenTheAxisStandsStill) {
    // 0A94: start and end of processing at once (ack: start position 0.0).
    EXPECT_EQ(Send(code::kStartAxisAbsolute, 1, FloatToBits(1000.0F)), "00 00 00 00 00 1F A0 00");  // 20 ms
    for (int i = 0; i < 10; ++i) EXPECT_EQ(Idle(), "00 00 00 00 00 1F A0 00");                  // 30..120 ms
    // 130 ms, at full speed since 120 ms: 50 + 10 = 60.0. 0A93 brakes (1000 AE/s, 10000 AE/s^2: 100 ms,
    // 50 AE) with BF = 0.
    EXPECT_EQ(Send(code::kStopAxis, 1), "42 70 00 00 00 1F 00 00");  // 60.0
    // 140 ms: 60 + 1000*0.01 - 10000*0.01^2/2 = 69.5
    EXPECT_EQ(Idle(), "42 8B 00 00 00 1F 00 00");
    for (int i = 0; i < 8; ++i) Idle();  // 150..220 ms
    EXPECT_EQ(Idle(), "42 DC 00 00 00 1F 20 00");  // 230 ms: standing at 110.0, BF = 1
    EXPECT_EQ(Send(code::kGetStatusAxis, 1), "00 00 00 02 00 1F A0 00");
}

TEST_F(OnlineCommands, StopAxisOnAStandingAxisEndsAtOnce) {
    pac_.Axes().Motion(1).Place(now_, 10.0);
    EXPECT_EQ(Send(code::kStopAxis, 1), "41 20 00 00 00 1F A0 00");
}

TEST_F(OnlineCommands, SetSpeedWithinTheParameterLimits) {
    // 2000 AE/s (0A8D) with ramps of 100000 AE/s^2 (0A8E): 20 ms / 20 AE to full speed. Relative 100.0:
    // 5, 20, then 20 AE per 10 ms cycle (2000 AE/s): 40, 60, 80, then braking: 95, 100.
    EXPECT_EQ(Send(code::kSetSpeedAxis, 1, FloatToBits(2000.0F)), "44 FA 00 00 00 1F A0 00");
    EXPECT_EQ(Send(code::kSetAccelerationAxis, 1, FloatToBits(100000.0F)), "47 C3 50 00 00 1F 20 00");
    EXPECT_EQ(Send(code::kPosAxisRelative, 1, FloatToBits(100.0F)), "00 00 00 00 00 1F 80 00");
    EXPECT_EQ(Idle(), "40 A0 00 00 00 1F 80 00");  // 5.0
    EXPECT_EQ(Idle(), "41 A0 00 00 00 1F 80 00");  // 20.0
    EXPECT_EQ(Idle(), "42 20 00 00 00 1F 80 00");  // 40.0
    EXPECT_EQ(Idle(), "42 70 00 00 00 1F 80 00");  // 60.0
    EXPECT_EQ(Idle(), "42 A0 00 00 00 1F 80 00");  // 80.0
    EXPECT_EQ(Idle(), "42 BE 00 00 00 1F 80 00");  // 95.0
    EXPECT_EQ(Idle(), "42 C8 00 00 00 1F A0 00");  // 100.0: done
    // 60000 > max 50000, 0, NaN: error 41.
    EXPECT_EQ(Send(code::kSetSpeedAxis, 1, FloatToBits(60000.0F)), "00 00 00 00 00 1F 40 29");
    EXPECT_EQ(Send(code::kSetSpeedAxis, 1, 0), "00 00 00 00 00 1F C0 29");
    EXPECT_EQ(Send(code::kSetSpeedAxis, 1, 0x7FC00000), "00 00 00 00 00 1F 40 29");
    // Leaving ONLINE restores the parameters' speed and acceleration.
    Send(code::kAbortOnline);
    EXPECT_EQ(pac_.Axes().SessionDynamics(1).speed, 1000.0);
    EXPECT_EQ(pac_.Axes().SessionDynamics(1).acceleration, 10000.0);
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
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(25.0F)), "00 00 00 00 00 1F 80 00");  // 20 ms
    EXPECT_EQ(Idle(), "3F 00 00 00 00 1F 80 00");  // 30 ms: 0.5
    // 40 ms: 1906 N4. The reply is now 1906's; the axis carries on.
    EXPECT_EQ(Send(code::kGetIntReg, 4), "00 00 00 2C 00 1F 20 00");
    EXPECT_EQ(Idle(), "00 00 00 2C 00 1F 20 00");
    // A second move of the same axis meanwhile: error 42.
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(0.0F)), "00 00 00 00 00 1F C0 2A");
    for (int i = 0; i < 6; ++i) Idle();  // 70..120 ms: at 25.0 at 120 ms (a triangle of 100 ms)
    EXPECT_EQ(Send(code::kGetActualPos, 1), "41 C8 00 00 00 1F 20 00");
    EXPECT_EQ(Send(code::kGetStatusAxis, 1), "00 00 00 00 00 1F A0 00");
}

TEST_F(OnlineCommands, MoveToTheCurrentPositionEndsAtOnce) {
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, 0), "00 00 00 00 00 1F A0 00");
}

}  // namespace
}  // namespace pac::sim::testing
