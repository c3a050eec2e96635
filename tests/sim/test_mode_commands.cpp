// Mode commands of manual 5.2.1 / 5.2.5 / 5.2.6.1: 0600, 0602, 0603, 0A41, 0A81 on the CMD interface
// (the whole mode machine: test_mode_machine.cpp).
#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

class ModeCommands : public PacRig {};

TEST_F(ModeCommands, StartOnlineNeedsAPoweredExternalStopInput) {
    // No stop input defined (system parameter 4 = 0): error 44 = 16#2C.
    EXPECT_EQ(Send(code::kStartOnline), "00 00 00 00 00 01 C0 2C");
    // Defined as input 3, but without power.
    ASSERT_EQ(pac_.SystemParameters().Set(4, 3), ParameterTable::SetResult::kOk);
    EXPECT_EQ(Send(code::kStartOnline), "00 00 00 00 00 01 40 2C");
    pac_.Io().inputs.Set(3, true);
    // ONLINE started (30 = 16#1E) for one controller cycle, BF = 0; then ONLINE (31 = 16#1F), BF = 1.
    EXPECT_EQ(Send(code::kStartOnline), "00 00 00 00 00 1E 80 00");
    EXPECT_EQ(Idle(), "00 00 00 00 00 1F A0 00");
    EXPECT_EQ(pac_.OperatingStatus(), 31);
}

TEST_F(ModeCommands, StartOnlineWithoutTheExternalStopCheck) {
    PaControlConfig config = QuickConfig();
    config.modes.requireExternalStop = false;
    Bus bus;
    PaControl pac(bus, config);
    bus.WriteToPac(0ms, CommandImage(code::kStartOnline, 0, 0, true));
    pac.Cycle(0ms);
    EXPECT_EQ(ToHex(bus.ReadFromPac(0ms)), "00 00 00 00 00 1E 80 00");
    pac.Cycle(10ms);
    EXPECT_EQ(ToHex(bus.ReadFromPac(10ms)), "00 00 00 00 00 1F A0 00");
}

TEST_F(ModeCommands, StartAutoAndStopIt) {
    // AUTOMATIC started (10) for one cycle with BF = 0, then AUTOMATIC (11) and BF = 1.
    EXPECT_EQ(Send(code::kStartAuto), "00 00 00 00 00 0A 80 00");
    EXPECT_EQ(Idle(), "00 00 00 00 00 0B A0 00");
    // No axis moves, so STOP recognised (12) passes at once: the STOP program (13) runs one cycle
    // with BF = 0, then "stopped" (15) and BF = 1.
    EXPECT_EQ(Send(code::kStop), "00 00 00 00 00 0D 00 00");
    EXPECT_EQ(Idle(), "00 00 00 00 00 0F 20 00");
    EXPECT_EQ(Send(code::kAbortAuto), "00 00 00 00 00 01 A0 00");
}

TEST_F(ModeCommands, StopInOnlineWaitsForTheAxesToStandStill) {
    GoOnline();                                                                   // 0, 10 ms, SEND 1
    EXPECT_EQ(Send(code::kStartAxisAbsolute, 1, FloatToBits(1000.0F)),           // 20 ms, SEND 0
              "00 00 00 00 00 1F 20 00");  // 0A94: start position 0.0, BF at once
    for (int i = 0; i < 10; ++i) Idle();  // 30..120 ms: the ramp of 100 ms to 1000 AE/s, at 50.0
    // 130 ms, at 60.0: 0600, ONLINE STOP recognised (32 = 16#20), BF = 0. Braking from 1000 AE/s at
    // 10000 AE/s^2 takes 100 ms and 50 AE.
    EXPECT_EQ(Send(code::kStop), "00 00 00 00 00 20 80 00");
    for (int cycle = 14; cycle <= 22; ++cycle) {
        EXPECT_EQ(Idle(), "00 00 00 00 00 20 80 00") << "cycle at " << cycle * 10 << " ms";
    }
    // 230 ms: the axis stands at 110.0: ONLINE and STOPPED (35 = 16#23), BF = 1.
    EXPECT_EQ(Idle(), "00 00 00 00 00 23 A0 00");
    EXPECT_EQ(Send(code::kGetActualPos, 1), "42 DC 00 00 00 23 20 00");  // 110.0
    EXPECT_EQ(Send(code::kGetStatusAxis, 1), "00 00 00 02 00 23 A0 00");  // standing, was stopped
}

TEST_F(ModeCommands, AbortOnlineReturnsToHomePosition) {
    GoOnline();
    EXPECT_EQ(Send(code::kAbortOnline), "00 00 00 00 00 01 20 00");
    EXPECT_EQ(pac_.OperatingStatus(), 1);
}

TEST_F(ModeCommands, ModeCommandsOutsideTheirModesAreInadmissible) {
    // 0600 in home position, 0A41 in home position, 0A81 in home position: error 20 = 16#14.
    EXPECT_EQ(Send(code::kStop), "00 00 00 00 00 01 C0 14");
    EXPECT_EQ(Send(code::kAbortAuto), "00 00 00 00 00 01 40 14");
    EXPECT_EQ(Send(code::kAbortOnline), "00 00 00 00 00 01 C0 14");
    GoOnline();  // SEND 0
    EXPECT_EQ(Send(code::kStartOnline), "00 00 00 00 00 1F C0 14");
    EXPECT_EQ(Send(code::kStartAuto), "00 00 00 00 00 1F 40 14");
    EXPECT_EQ(Send(code::kAbortAuto), "00 00 00 00 00 1F C0 14");
}

}  // namespace
}  // namespace pac::sim::testing
