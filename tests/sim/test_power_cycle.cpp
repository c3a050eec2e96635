// Power-up and power cycle: status 0 and an all-zero reply until the boot ends, then home position
// with RF = 0; what a PLC holding SEND = 1 causes; retention of registers and parameters.
#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

class PowerCycle : public PacRig {
protected:
    PowerCycle() : PacRig(BootingIn(30ms)) {}
};

TEST_F(PowerCycle, AllZeroUntilBootedAndCommandsWaitForTheBoot) {
    pac_.Io().intRegisters.SetInt(1, 5);
    // The PLC already toggles SEND at 0 ms: nothing happens while booting.
    EXPECT_EQ(Exchange(CommandImage(code::kGetIntReg, 1, 0, true)), "00 00 00 00 00 00 00 00");  // 0 ms
    EXPECT_FALSE(pac_.Booted());
    EXPECT_EQ(Idle(), "00 00 00 00 00 00 00 00");  // 10 ms
    EXPECT_EQ(Idle(), "00 00 00 00 00 00 00 00");  // 20 ms
    EXPECT_EQ(pac_.Counters().recognized, 0U);
    // 30 ms: booted, RF = 0 differs from SEND = 1: the command is recognised now.
    EXPECT_EQ(Idle(), "00 00 00 05 00 01 A0 00");
    EXPECT_TRUE(pac_.Booted());
    EXPECT_EQ(pac_.Counters().recognized, 1U);
}

TEST_F(PowerCycle, ResyncAfterAPowerCycle) {
    now_ = 30ms;
    pac_.Io().intRegisters.SetInt(1, 5);
    send_ = false;
    EXPECT_EQ(Send(code::kGetIntReg, 1), "00 00 00 05 00 01 A0 00");  // 30 ms: RF = 1
    // Power off and on at 40 ms: the PLC sees zeros at once (RF back to 0, status 0).
    pac_.PowerCycle(40ms);
    EXPECT_EQ(ToHex(bus_.ReadFromPac(40ms)), "00 00 00 00 00 00 00 00");
    EXPECT_EQ(pac_.OperatingStatus(), 0);
    // The PLC resynchronises while the status is 0: SEND := RF = 0 (what FB_PAC_Cmd does idle).
    send_ = false;
    EXPECT_EQ(Exchange(CommandImage(code::kGetIntReg, 1, 0, false)), "00 00 00 00 00 00 00 00");  // 40
    EXPECT_EQ(Idle(), "00 00 00 00 00 00 00 00");  // 50
    EXPECT_EQ(Idle(), "00 00 00 00 00 00 00 00");  // 60
    EXPECT_EQ(Idle(), "00 00 00 00 00 01 20 00");  // 70: booted, nothing outstanding
    EXPECT_EQ(pac_.Counters().recognized, 1U);     // nothing ran twice
    EXPECT_EQ(Send(code::kGetIntReg, 1), "00 00 00 05 00 01 A0 00");
}

TEST_F(PowerCycle, APlcHoldingSendRepeatsItsLastCommandAfterTheBoot) {
    now_ = 30ms;
    EXPECT_EQ(Send(code::kPutIntReg, 7, 1), "00 00 00 01 00 01 A0 00");  // N7 := 1, SEND 1
    pac_.Io().intRegisters.SetInt(7, 100);  // changed meanwhile
    pac_.PowerCycle(40ms);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(Idle(), "00 00 00 00 00 00 00 00");
    // 70 ms: booted with RF = 0; SEND = 1 counts as a new command: N7 := 1 again.
    EXPECT_EQ(Idle(), "00 00 00 01 00 01 A0 00");
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(7), 1);
    EXPECT_EQ(pac_.Counters().Count(code::kPutIntReg), 2U);
}

TEST_F(PowerCycle, RetentionRule) {
    now_ = 30ms;
    Idle();
    GoOnline();
    pac_.Io().intRegisters.SetInt(3, 33);
    pac_.Io().realRegisters.SetReal(3, 3.5F);
    pac_.Io().flags.Set(3, true);
    pac_.Io().outputs.Set(3, true);
    pac_.Io().systemIntRegisters.SetInt(3, 3);
    ASSERT_EQ(pac_.SystemParameters().Set(1, 2), ParameterTable::SetResult::kOk);
    ASSERT_EQ(pac_.Axes().Parameters(1).Set(1, FloatToBits(300.0F)), ParameterTable::SetResult::kOk);
    pac_.SetSystemError(42);
    pac_.Axes().Motion(1).SetReferenced(false);

    pac_.PowerCycle(now_);
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(3), 33);
    EXPECT_EQ(pac_.Io().realRegisters.GetReal(3), 3.5F);
    EXPECT_FALSE(pac_.Io().flags.Get(3));
    EXPECT_FALSE(pac_.Io().outputs.Get(3));
    EXPECT_TRUE(pac_.Io().inputs.Get(1));  // the outside world's
    EXPECT_EQ(pac_.Io().systemIntRegisters.GetInt(3), 0);
    EXPECT_EQ(pac_.SystemParameters().IntValue(1), 2);
    EXPECT_EQ(pac_.Axes().Parameters(1).RealValue(1), 300.0F);
    EXPECT_EQ(pac_.Axes().Motion(1).Config().traverseSpeed, 300.0);
    EXPECT_EQ(pac_.Axes().SessionDynamics(1).speed, 300.0);
    EXPECT_EQ(pac_.SystemError(), 0);
    EXPECT_TRUE(pac_.Axes().Motion(1).Referenced());
    EXPECT_EQ(pac_.OperatingStatus(), 0);
}

TEST_F(PowerCycle, RetentionIsConfigurable) {
    PaControlConfig config = QuickConfig();
    config.retention.intRegisters = false;
    config.retention.flags = true;
    config.referencedAtPowerOn = false;
    Bus bus;
    PaControl pac(bus, config);
    pac.Io().intRegisters.SetInt(1, 1);
    pac.Io().flags.Set(1, true);
    pac.PowerCycle(0ms);
    EXPECT_EQ(pac.Io().intRegisters.GetInt(1), 0);
    EXPECT_TRUE(pac.Io().flags.Get(1));
    EXPECT_FALSE(pac.Axes().Motion(1).Referenced());
}

TEST_F(PowerCycle, PowerCycleDuringAMoveStopsTheAxisAndDropsTheCommand) {
    now_ = 30ms;
    GoOnline();                                                                     // 30, 40 ms, SEND 1
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, FloatToBits(100.0F)), "00 00 00 00 00 1F 00 00");  // 50
    Idle();                                                                         // 60 ms: 0.5
    pac_.PowerCycle(65ms);  // 15 ms into the ramp of 10000 AE/s^2: 5000 * 0.015^2 = 1.125
    EXPECT_FALSE(pac_.Axes().Motion(1).Moving());
    EXPECT_DOUBLE_EQ(pac_.Axes().Motion(1).Position(), 1.125);
    for (int i = 0; i < 3; ++i) Idle();                                              // 70..90 ms
    // 100 ms: booted in home position; the PLC's SEND (0) equals RF (0): nothing outstanding.
    EXPECT_EQ(Idle(), "00 00 00 00 00 01 20 00");
}

TEST_F(PowerCycle, SetStatusBeforeTheBootIsTheStatusItBootsInto) {
    pac_.SetOperatingStatus(status::kOnline);
    EXPECT_EQ(Idle(), "00 00 00 00 00 00 00 00");
    now_ = 30ms;
    EXPECT_EQ(Idle(), "00 00 00 00 00 1F 20 00");
}

TEST_F(PowerCycle, TimeMustNotRunBackwards) {
    pac_.Cycle(20ms);
    EXPECT_THROW(pac_.Cycle(10ms), std::invalid_argument);
    EXPECT_THROW(pac_.PowerCycle(10ms), std::invalid_argument);
}

}  // namespace
}  // namespace pac::sim::testing
