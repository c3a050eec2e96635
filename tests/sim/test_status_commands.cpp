// Status commands of manual 5.2.4.15..5.2.4.31: 0909, 1909, 190B, 190C, 190D, 1910, 1911, 1913,
// 1914, and the system elements 1934 / 1935 / 1937 (6.2).
#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

class StatusCommands : public PacRig {};

TEST_F(StatusCommands, ErrorNumberSetsFeAndResetClearsIt) {
    EXPECT_EQ(Idle(), "00 00 00 00 00 01 20 00");
    pac_.SetSystemError(529);
    EXPECT_EQ(Idle(), "00 00 00 00 80 01 20 00");  // FE = word 2 bit 15
    EXPECT_EQ(Send(code::kGetError), "00 00 02 11 80 01 A0 00");  // 5.2.4.16: 529 = 16#0211
    EXPECT_EQ(Send(code::kResetError), "00 00 00 00 00 01 20 00");  // 5.2.4.15
    EXPECT_EQ(pac_.SystemError(), 0);
    EXPECT_EQ(Send(code::kGetError), "00 00 00 00 00 01 A0 00");
}

TEST_F(StatusCommands, CpuErrorsCannotBeResetByCommand) {
    pac_.SetSystemError(42);  // class 1 (1..99): power off/on only
    // Error 21 = 16#15, and the error number again in the acknowledgement data.
    EXPECT_EQ(Send(code::kResetError), "00 00 00 2A 80 01 C0 15");
    EXPECT_EQ(pac_.SystemError(), 42);
}

TEST_F(StatusCommands, ResetErrorOnlyInHomePosition) {
    pac_.SetSystemError(300);
    pac_.SetOperatingStatus(status::kAuto);
    EXPECT_EQ(Send(code::kResetError), "00 00 00 00 80 0B C0 14");
    EXPECT_EQ(pac_.SystemError(), 300);
    EXPECT_EQ(Send(code::kGetError), "00 00 01 2C 80 0B 20 00");  // 1909 in every mode
}

TEST_F(StatusCommands, GetStateGivesTheDecimalStatusCode) {
    EXPECT_EQ(Send(code::kGetState), "00 00 00 01 00 01 A0 00");
    GoOnline();  // SEND 0
    EXPECT_EQ(Send(code::kGetState), "00 00 00 1F 00 1F A0 00");  // 31, not 16#31
    pac_.SetOperatingStatus(status::kAutoStarted);
    EXPECT_EQ(Send(code::kGetState), "00 00 00 0A 00 0A 20 00");
}

TEST_F(StatusCommands, AxisPositionSpeedAndStatus) {
    pac_.Axes().Motion(2).Place(now_, 5000.0);
    EXPECT_EQ(Send(code::kGetActualPos, 2), "45 9C 40 00 00 01 A0 00");  // 5000.0 (not 45 48 00 00)
    EXPECT_EQ(Send(code::kGetStatusAxis, 2), "00 00 00 00 00 01 20 00");  // standing, in position
    EXPECT_EQ(Send(code::kGetActualSpeed, 2), "00 00 00 00 00 01 A0 00");
    EXPECT_EQ(Send(code::kGetTraverseAreaMin, 2), "00 00 00 00 00 01 20 00");  // 0.0
    EXPECT_EQ(Send(code::kGetTraverseAreaMax, 2), "46 1C 40 00 00 01 A0 00");  // 10000.0
    // Axis 3 with 2 axes configured, axis 0: error 32 = 16#20.
    EXPECT_EQ(Send(code::kGetActualPos, 3), "00 00 00 00 00 01 40 20");
    EXPECT_EQ(Send(code::kGetStatusAxis, 0), "00 00 00 00 00 01 C0 20");
    EXPECT_EQ(Send(code::kGetTraverseAreaMax, 17), "00 00 00 00 00 01 40 20");
}

TEST_F(StatusCommands, AxisStatusWhileMovingAndAfterAStop) {
    GoOnline();                                                       // 0 ms, SEND 1
    // Ramps of 10000 AE/s^2 (axis parameter 6): 10000 t AE/s and 5000 t^2 AE after t s.
    Send(code::kStartAxisRelative, 2, FloatToBits(100.0F));          // 10 ms, SEND 0
    EXPECT_EQ(Send(code::kGetStatusAxis, 2), "00 00 00 01 00 1F A0 00");     // 20 ms: moving
    EXPECT_EQ(Send(code::kGetStatusAllAxis), "00 00 00 02 00 1F 20 00");     // bit 1 = axis 2
    EXPECT_EQ(Send(code::kGetActualSpeed, 2), "43 96 00 00 00 1F A0 00");    // 40 ms: 300.0 AE/s
    EXPECT_EQ(Send(code::kGetActualPos, 2), "41 00 00 00 00 1F 20 00");      // 50 ms: 8.0
    pac_.Axes().Motion(2).EmergencyStop(now_);
    EXPECT_EQ(Send(code::kGetStatusAxis, 2), "00 00 00 02 00 1F A0 00");     // was stopped
    EXPECT_EQ(Send(code::kGetStatusAllAxis), "00 00 00 00 00 1F 20 00");
    pac_.Axes().RaiseAxisError(1, now_, 500);
    EXPECT_EQ(Send(code::kGetStatusAxis, 1), "00 00 00 04 00 1F A0 00");     // malfunction
}

TEST_F(StatusCommands, SystemElements) {
    // SN10 = system error number; SM51.. = axis referenced; SN71.. = axis status; SR71.. = target.
    pac_.SetSystemError(512);
    EXPECT_EQ(Send(code::kGetSystemNReg, 10), "00 00 02 00 80 01 A0 00");
    pac_.SetSystemError(0);
    EXPECT_EQ(Send(code::kGetSystemFlag, 51), "00 00 00 01 00 01 20 00");
    pac_.Axes().Motion(1).SetReferenced(false);
    EXPECT_EQ(Send(code::kGetSystemFlag, 51), "00 00 00 00 00 01 A0 00");
    pac_.Axes().RaiseAxisError(2, now_, 500);
    EXPECT_EQ(Send(code::kGetSystemNReg, 72), "00 00 00 04 00 01 20 00");
    EXPECT_EQ(Send(code::kGetSystemFlag, 232), "00 00 00 01 00 01 A0 00");
    pac_.Axes().Motion(2).Place(now_, 200.0);
    EXPECT_EQ(Send(code::kGetSystemRReg, 72), "43 48 00 00 00 01 20 00");
    // Plain storage elsewhere.
    pac_.Io().systemFlags.Set(5, true);
    pac_.Io().systemIntRegisters.SetInt(20, -2);
    pac_.Io().systemRealRegisters.SetReal(1, 10.0F);
    EXPECT_EQ(Send(code::kGetSystemFlag, 5), "00 00 00 01 00 01 A0 00");
    EXPECT_EQ(Send(code::kGetSystemNReg, 20), "FF FF FF FE 00 01 20 00");
    EXPECT_EQ(Send(code::kGetSystemRReg, 1), "41 20 00 00 00 01 A0 00");
    // Outside the counts (256 each by default).
    EXPECT_EQ(Send(code::kGetSystemFlag, 257), "00 00 00 00 00 01 40 25");
    EXPECT_EQ(Send(code::kGetSystemNReg, 0), "00 00 00 00 00 01 C0 26");
    EXPECT_EQ(Send(code::kGetSystemRReg, 300), "00 00 00 00 00 01 40 27");
}

}  // namespace
}  // namespace pac::sim::testing
