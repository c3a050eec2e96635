// System and axis parameter commands of manual 5.2.2 / 5.2.3 (0700, 1700..1702, 0800, 1800..1802):
// home position only, limits, unknown numbers.
#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

class ParameterCommands : public PacRig {};

TEST_F(ParameterCommands, SetAndGetSystemParameters) {
    // 5.2.2.1: input 1 as start input (parameter 3): the acknowledgement echoes the value.
    EXPECT_EQ(Send(code::kSetSystemParameter, 3, 1), "00 00 00 01 00 01 A0 00");
    EXPECT_EQ(Send(code::kGetSystemParameter, 3), "00 00 00 01 00 01 20 00");
    EXPECT_EQ(Send(code::kSetSystemParameter, 1, 3), "00 00 00 03 00 01 A0 00");  // language 3
    EXPECT_EQ(Send(code::kGetSystemParameter, 1), "00 00 00 03 00 01 20 00");
    // 1701 / 1702 parameter 2: at most 4 axes, at least 0 (the manual's examples).
    EXPECT_EQ(Send(code::kGetSystemParameterMax, 2), "00 00 00 04 00 01 A0 00");
    EXPECT_EQ(Send(code::kGetSystemParameterMin, 2), "00 00 00 00 00 01 20 00");
    EXPECT_EQ(pac_.SystemParameters().IntValue(3), 1);
}

TEST_F(ParameterCommands, SystemParameterErrors) {
    // Parameter 9 is "currently not used", 99 does not exist: error 34 = 16#22.
    EXPECT_EQ(Send(code::kSetSystemParameter, 9, 0), "00 00 00 00 00 01 C0 22");
    EXPECT_EQ(Send(code::kGetSystemParameter, 99), "00 00 00 00 00 01 40 22");
    EXPECT_EQ(Send(code::kGetSystemParameterMax, 0), "00 00 00 00 00 01 C0 22");
    // 5 axes > max 4, and -1 < min 0: error 41 = 16#29; the value stays.
    EXPECT_EQ(Send(code::kSetSystemParameter, 2, 5), "00 00 00 00 00 01 40 29");
    EXPECT_EQ(Send(code::kSetSystemParameter, 2, 0xFFFFFFFF), "00 00 00 00 00 01 C0 29");
    EXPECT_EQ(Send(code::kGetSystemParameter, 2), "00 00 00 02 00 01 20 00");
}

TEST_F(ParameterCommands, SetAndGetAxisParameters) {
    // 5.2.3: acceleration 200.0 for axis 3, parameter 16#0306 (needs 3 axes configured).
    EXPECT_EQ(Send(code::kSetSystemParameter, 2, 4), "00 00 00 04 00 01 A0 00");
    EXPECT_EQ(Send(code::kSetAxisParameter, 0x0306, 0x43480000), "43 48 00 00 00 01 20 00");
    EXPECT_EQ(Send(code::kGetAxisParameter, 0x0306), "43 48 00 00 00 01 A0 00");
    // Shaft encoder direction of axis 2 (16#021F): 0.0.
    EXPECT_EQ(Send(code::kGetAxisParameter, 0x021F), "00 00 00 00 00 01 20 00");
    // Maximum traverse speed of axis 3 (16#0301): 50000.0 = 47 43 50 00.
    EXPECT_EQ(Send(code::kGetAxisParameterMax, 0x0301), "47 43 50 00 00 01 A0 00");
    // Minimum acceleration of axis 4 (16#0406): 1.0 in the default table.
    EXPECT_EQ(Send(code::kGetAxisParameterMin, 0x0406), "3F 80 00 00 00 01 20 00");
    EXPECT_EQ(pac_.Axes().Parameters(3).RealValue(6), 200.0F);
    // The axis takes it over for both ramps, and so do the CMD moves of an ONLINE session.
    EXPECT_EQ(pac_.Axes().Motion(3).Config().acceleration, 200.0);
    EXPECT_EQ(pac_.Axes().Motion(3).Config().deceleration, 200.0);
    EXPECT_EQ(pac_.Axes().SessionDynamics(3).deceleration, 200.0);
}

TEST_F(ParameterCommands, AxisParameterErrors) {
    // Axis 3 with 2 axes configured, and axis 0: error 32 = 16#20.
    EXPECT_EQ(Send(code::kGetAxisParameter, 0x0301), "00 00 00 00 00 01 C0 20");
    EXPECT_EQ(Send(code::kSetAxisParameter, 0x0001, 0x41200000), "00 00 00 00 00 01 40 20");
    // Axis parameter 16#40 does not exist: error 33 = 16#21.
    EXPECT_EQ(Send(code::kGetAxisParameter, 0x0140), "00 00 00 00 00 01 C0 21");
    // Traverse speed 60000.0 > 50000.0, and NaN: error 41 = 16#29.
    EXPECT_EQ(Send(code::kSetAxisParameter, 0x0101, FloatToBits(60000.0F)), "00 00 00 00 00 01 40 29");
    EXPECT_EQ(Send(code::kSetAxisParameter, 0x0101, 0x7FC00000), "00 00 00 00 00 01 C0 29");
    EXPECT_EQ(Send(code::kGetAxisParameter, 0x0101), "44 7A 00 00 00 01 20 00");  // still 1000.0
}

TEST_F(ParameterCommands, OnlyInHomePosition) {
    GoOnline();  // SEND 1
    EXPECT_EQ(Send(code::kGetSystemParameter, 1), "00 00 00 00 00 1F 40 14");
    EXPECT_EQ(Send(code::kSetAxisParameter, 0x0101, FloatToBits(10.0F)), "00 00 00 00 00 1F C0 14");
    pac_.SetOperatingStatus(status::kAuto);
    EXPECT_EQ(Send(code::kGetAxisParameterMin, 0x0101), "00 00 00 00 00 0B 40 14");
    pac_.SetOperatingStatus(status::kManualPanel);
    EXPECT_EQ(Send(code::kGetSystemParameterMax, 1), "00 00 00 00 00 02 C0 14");
    pac_.SetOperatingStatus(status::kHomeWithSystemError);
    EXPECT_EQ(Send(code::kGetSystemParameterMax, 1), "00 00 00 03 00 09 20 00");
}

}  // namespace
}  // namespace pac::sim::testing
