// The controller behind a faulty or slow bus: an all-zero to-PAC image is EMERGENCY STOP once
// communication was active (4.2.5); frozen links; disconnection; latency on each direction.
#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

class BusFaults : public PacRig {};

TEST_F(BusFaults, AllZeroBeforeCommunicationIsNoEmergencyStop) {
    EXPECT_EQ(Idle(), "00 00 00 00 00 01 20 00");
    EXPECT_EQ(Idle(), "00 00 00 00 00 01 20 00");
    EXPECT_FALSE(pac_.EmergencyStopActive());
    EXPECT_EQ(pac_.Counters().emergencyStops, 0U);
}

TEST_F(BusFaults, AllZeroToPacImageInOnlineIsAnEmergencyStop) {
    GoOnline();                                                                     // 0 ms, SEND 1
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(100.0F)), "00 00 00 00 00 1F 00 00");  // 10
    EXPECT_EQ(Idle(), "3F 00 00 00 00 1F 00 00");                                   // 20 ms: 0.5
    // 30 ms: the PLC writes 8 zero bytes. The axis halts without ramp (at 2.0), the move ends
    // (BF = 1, data = stop position), the status becomes ONLINE STOPPED with MALFUNCTION (39 =
    // 16#27). SEND = 0 in the zero image is no command; RF stays.
    EXPECT_EQ(Exchange(Image8{}), "40 00 00 00 00 27 20 00");
    EXPECT_TRUE(pac_.EmergencyStopActive());
    EXPECT_EQ(Idle(), "40 00 00 00 00 27 20 00");
    EXPECT_EQ(pac_.Counters().emergencyStops, 1U);
    EXPECT_DOUBLE_EQ(pac_.Axes().Motion(1).Position(), 2.0);
    EXPECT_EQ(pac_.Axes().Motion(1).Status(), AxisStatus::kStopped);
    // Back on the bus: moves are inadmissible in 39; 0A81 returns to home position.
    send_ = false;
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(5.0F)), "00 00 00 00 00 27 C0 14");
    EXPECT_FALSE(pac_.EmergencyStopActive());
    EXPECT_EQ(Send(code::kAbortOnline), "00 00 00 00 00 01 20 00");
}

TEST_F(BusFaults, AllZeroLinkFaultTowardsTheControllerIsAnEmergencyStop) {
    pac_.SetOperatingStatus(status::kAuto);
    EXPECT_EQ(Send(code::kGetState), "00 00 00 0B 00 0B A0 00");  // 0 ms
    bus_.ToPacLink().SetFault(now_, LinkFault::kAllZero);
    EXPECT_EQ(Idle(), "00 00 00 0B 00 13 A0 00");  // AUTOMATIC STOPPED with MALFUNCTION (19)
    EXPECT_TRUE(pac_.EmergencyStopActive());
    bus_.ToPacLink().SetFault(now_, LinkFault::kNone);
    EXPECT_EQ(Idle(), "00 00 00 0B 00 13 A0 00");
    EXPECT_FALSE(pac_.EmergencyStopActive());
}

TEST_F(BusFaults, EmergencyStopInHomePositionChangesNoStatus) {
    Send(code::kGetState);
    EXPECT_EQ(Exchange(Image8{}), "00 00 00 01 00 01 A0 00");
    EXPECT_TRUE(pac_.EmergencyStopActive());
}

TEST_F(BusFaults, FrozenLinkToPacHidesTheToggle) {
    pac_.Io().intRegisters.SetInt(1, 11);
    EXPECT_EQ(Send(code::kGetState), "00 00 00 01 00 01 A0 00");  // 0 ms
    bus_.ToPacLink().SetFault(now_, LinkFault::kFrozen);
    EXPECT_EQ(Send(code::kGetIntReg, 1), "00 00 00 01 00 01 A0 00");  // 10 ms: not seen
    EXPECT_EQ(Idle(), "00 00 00 01 00 01 A0 00");
    EXPECT_EQ(ToHex(pac_.LastToPacImage()), "00 00 00 00 00 00 99 0B");
    bus_.ToPacLink().SetFault(now_, LinkFault::kNone);
    EXPECT_EQ(Idle(), "00 00 00 0B 00 01 20 00");  // 30 ms: the toggle arrives
}

TEST_F(BusFaults, FrozenLinkFromPacHidesTheAcknowledgement) {
    EXPECT_EQ(Send(code::kGetState), "00 00 00 01 00 01 A0 00");
    bus_.FromPacLink().SetFault(now_, LinkFault::kFrozen);
    EXPECT_EQ(Send(code::kGetState), "00 00 00 01 00 01 A0 00");  // RF stays 1 for the PLC
    EXPECT_EQ(ToHex(pac_.LastFromPacImage()), "00 00 00 01 00 01 20 00");  // the controller did answer
    bus_.FromPacLink().SetFault(now_, LinkFault::kNone);
    EXPECT_EQ(Idle(), "00 00 00 01 00 01 20 00");
    EXPECT_EQ(pac_.Counters().recognized, 2U);
}

TEST_F(BusFaults, DisconnectionIsAnEmergencyStopAndNeedsANewWrite) {
    GoOnline();  // 0 ms
    bus_.Disconnect(now_);
    EXPECT_EQ(Idle(), "00 00 00 00 00 00 00 00");  // 10 ms: the PLC sees zeros
    EXPECT_TRUE(pac_.EmergencyStopActive());
    EXPECT_EQ(pac_.OperatingStatus(), 39);
    bus_.Reconnect(now_);
    EXPECT_EQ(Idle(), "00 00 00 00 00 27 A0 00");  // 20 ms: both sides write again
    EXPECT_FALSE(pac_.EmergencyStopActive());
}

TEST(BusLatency, RoundTripFollowsBothLatencies) {
    BusConfig busConfig;
    busConfig.toPac.latency = 3ms;
    busConfig.fromPac.latency = 4ms;
    Bus bus(busConfig);
    PaControl pac(bus, QuickConfig());
    pac.Io().intRegisters.SetInt(1, 1);
    // Controller cycles every 10 ms. Its 0 ms reply arrives at 4 ms. The PLC toggles SEND at
    // 8 ms: it arrives at 11 ms, so the 10 ms cycle misses it and the 20 ms cycle answers; that
    // reply arrives at 24 ms.
    pac.Cycle(0ms);
    EXPECT_EQ(ToHex(bus.ReadFromPac(3ms)), "00 00 00 00 00 00 00 00");
    EXPECT_EQ(ToHex(bus.ReadFromPac(4ms)), "00 00 00 00 00 01 20 00");
    bus.WriteToPac(8ms, CommandImage(code::kGetIntReg, 1, 0, true));
    pac.Cycle(10ms);
    EXPECT_EQ(pac.Counters().recognized, 0U);
    pac.Cycle(20ms);
    EXPECT_EQ(pac.Counters().recognized, 1U);
    EXPECT_EQ(ToHex(bus.ReadFromPac(23ms)), "00 00 00 00 00 01 20 00");
    EXPECT_EQ(ToHex(bus.ReadFromPac(24ms)), "00 00 00 01 00 01 A0 00");
}

}  // namespace
}  // namespace pac::sim::testing
