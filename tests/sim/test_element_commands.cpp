// Element commands of manual 5.2.4 (inputs, outputs, flags, N and R registers) with the manual's
// own examples, and their range errors (6.5: 35 input, 36 output, 37 flag, 38 N, 39 R, 41 value).
#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

class ElementCommands : public PacRig {};

TEST_F(ElementCommands, Inputs) {
    pac_.Io().inputs.Set(13, true);
    EXPECT_EQ(Send(code::kGetSingleInput, 0x0D), "00 00 00 01 00 01 A0 00");  // 5.2.4.1
    EXPECT_EQ(Send(code::kGetSingleInput, 0x0C), "00 00 00 00 00 01 20 00");
    pac_.Io().inputs.SetWord(1, 0);
    for (int n : {1, 2, 9, 11, 12, 16}) pac_.Io().inputs.Set(n, true);
    EXPECT_EQ(Send(code::kGetInputWord, 0x0A), "00 00 8D 03 00 01 A0 00");  // 5.2.4.2: word of I10
    EXPECT_EQ(Send(code::kGetInputWord, 17), "00 00 00 00 00 01 20 00");
    pac_.Io().inputs.Set(1024, true);
    EXPECT_EQ(Send(code::kGetInputWord, 1009), "00 00 80 00 00 01 A0 00");
}

TEST_F(ElementCommands, Outputs) {
    EXPECT_EQ(Send(code::kPutSingleOutput, 0x0D, 1), "00 00 00 01 00 01 A0 00");  // 5.2.4.3
    EXPECT_TRUE(pac_.Io().outputs.Get(13));
    pac_.Io().outputs.Set(243, true);
    EXPECT_EQ(Send(code::kGetSingleOutput, 0xF3), "00 00 00 01 00 01 20 00");  // 5.2.4.4
    // 5.2.4.5: output word 2 (selected by O25) := 3E11: O17, O21, O26..O30.
    EXPECT_EQ(Send(code::kPutOutputWord, 0x19, 0x3E11), "00 00 3E 11 00 01 A0 00");
    for (int n = 17; n <= 32; ++n) {
        const bool expected = n == 17 || n == 21 || (n >= 26 && n <= 30);
        EXPECT_EQ(pac_.Io().outputs.Get(n), expected) << "O" << n;
    }
    // 5.2.4.6: output word 3 (O33) with O33, O35, ..., O47 set: 5555.
    for (int n = 33; n <= 47; n += 2) pac_.Io().outputs.Set(n, true);
    EXPECT_EQ(Send(code::kGetOutputWord, 0x21), "00 00 55 55 00 01 20 00");
    EXPECT_EQ(Send(code::kPutSingleOutput, 0x0D, 0), "00 00 00 00 00 01 A0 00");
    EXPECT_FALSE(pac_.Io().outputs.Get(13));
}

TEST_F(ElementCommands, SixteenBitDataIsTheLowWord) {
    // 2.4.1: a 16-bit command date sits in bytes 2..3; bytes 0..1 are not used.
    EXPECT_EQ(Send(code::kPutOutputWord, 1, 0xFFFF1234), "00 00 12 34 00 01 A0 00");
    EXPECT_EQ(Send(code::kGetOutputWord, 1), "00 00 12 34 00 01 20 00");
    EXPECT_EQ(Send(code::kPutSingleFlag, 1, 0xABCD0001), "00 00 00 01 00 01 A0 00");
}

TEST_F(ElementCommands, Flags) {
    EXPECT_EQ(Send(code::kPutSingleFlag, 0x0B, 1), "00 00 00 01 00 01 A0 00");  // 5.2.4.7: M11
    EXPECT_TRUE(pac_.Io().flags.Get(11));
    pac_.Io().flags.Set(243, true);
    EXPECT_EQ(Send(code::kGetSingleFlag, 0xF3), "00 00 00 01 00 01 20 00");  // 5.2.4.8
    // 5.2.4.9: flag word 2 (M17) := 45F2: M18, M21..M25, M27, M31.
    EXPECT_EQ(Send(code::kPutFlagWord, 0x11, 0x45F2), "00 00 45 F2 00 01 A0 00");
    for (int n = 17; n <= 32; ++n) {
        const bool expected = n == 18 || (n >= 21 && n <= 25) || n == 27 || n == 31;
        EXPECT_EQ(pac_.Io().flags.Get(n), expected) << "M" << n;
    }
    // 5.2.4.10: flag word 3 (M33) with M33..M36 and M41..M44: 0F0F.
    for (int n : {33, 34, 35, 36, 41, 42, 43, 44}) pac_.Io().flags.Set(n, true);
    EXPECT_EQ(Send(code::kGetFlagWord, 0x21), "00 00 0F 0F 00 01 20 00");
}

TEST_F(ElementCommands, IntegerRegisters) {
    EXPECT_EQ(Send(code::kPutIntReg, 0x61, 0x0000312D), "00 00 31 2D 00 01 A0 00");  // N97 := 12589
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(97), 12589);
    pac_.Io().intRegisters.SetInt(129, 88224);
    EXPECT_EQ(Send(code::kGetIntReg, 0x81), "00 01 58 A0 00 01 20 00");  // 5.2.4.12
    EXPECT_EQ(Send(code::kPutIntReg, 1024, 0xFFFFFFFF), "FF FF FF FF 00 01 A0 00");
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(1024), -1);
}

TEST_F(ElementCommands, RealRegisters) {
    EXPECT_EQ(Send(code::kPutFloatReg, 0x1B, 0x41200000), "41 20 00 00 00 01 A0 00");  // R27 := 10.0
    EXPECT_EQ(pac_.Io().realRegisters.GetReal(27), 10.0F);
    pac_.Io().realRegisters.SetReal(37, 111.111F);
    EXPECT_EQ(Send(code::kGetFloatReg, 0x25), "42 DE 38 D5 00 01 20 00");  // 5.2.4.14
    // The register keeps any bit pattern, NaN included.
    EXPECT_EQ(Send(code::kPutFloatReg, 2, 0x7FC00001), "7F C0 00 01 00 01 A0 00");
    EXPECT_EQ(pac_.Io().realRegisters.Get(2), 0x7FC00001U);
}

TEST_F(ElementCommands, NumbersOutsideTheConfiguredCounts) {
    EXPECT_EQ(Send(code::kGetSingleInput, 0), "00 00 00 00 00 01 C0 23");     // 35
    EXPECT_EQ(Send(code::kGetInputWord, 1025), "00 00 00 00 00 01 40 23");    // 35
    EXPECT_EQ(Send(code::kPutSingleOutput, 1025, 1), "00 00 00 00 00 01 C0 24");  // 36
    EXPECT_EQ(Send(code::kGetOutputWord, 0), "00 00 00 00 00 01 40 24");      // 36
    EXPECT_EQ(Send(code::kPutSingleFlag, 0, 1), "00 00 00 00 00 01 C0 25");   // 37 (manual: 36)
    EXPECT_EQ(Send(code::kGetFlagWord, 2000), "00 00 00 00 00 01 40 25");     // 37
    EXPECT_EQ(Send(code::kGetIntReg, 1025), "00 00 00 00 00 01 C0 26");       // 38
    EXPECT_EQ(Send(code::kPutIntReg, 0, 5), "00 00 00 00 00 01 40 26");       // 38
    EXPECT_EQ(Send(code::kGetFloatReg, 0), "00 00 00 00 00 01 C0 27");        // 39
    EXPECT_EQ(Send(code::kPutFloatReg, 0xFFFF, 5), "00 00 00 00 00 01 40 27");  // 39
    EXPECT_EQ(pac_.Io().intRegisters.Count(), 1024);
}

TEST_F(ElementCommands, SingleBitValuesOtherThan0Or1AreOutOfRange) {
    EXPECT_EQ(Send(code::kPutSingleOutput, 1, 2), "00 00 00 00 00 01 C0 29");  // 41
    EXPECT_EQ(Send(code::kPutSingleFlag, 1, 0xFFFF), "00 00 00 00 00 01 40 29");
    EXPECT_FALSE(pac_.Io().outputs.Get(1));
    EXPECT_FALSE(pac_.Io().flags.Get(1));
}

TEST_F(ElementCommands, CountsAreConfigurable) {
    PaControlConfig config = QuickConfig();
    config.counts.intRegisters = 100;
    config.counts.inputs = 20;
    Bus bus;
    PaControl pac(bus, config);
    bus.WriteToPac(0ms, CommandImage(code::kGetIntReg, 101, 0, true));
    pac.Cycle(0ms);
    EXPECT_EQ(ToHex(bus.ReadFromPac(0ms)), "00 00 00 00 00 01 C0 26");
    // Input word 2 holds I17..I20 only; I20 is bit 3.
    pac.Io().inputs.Set(20, true);
    bus.WriteToPac(10ms, CommandImage(code::kGetInputWord, 17, 0, false));
    pac.Cycle(10ms);
    EXPECT_EQ(ToHex(bus.ReadFromPac(10ms)), "00 00 00 08 00 01 20 00");
}

TEST_F(ElementCommands, ValidInEveryMode) {
    pac_.Io().intRegisters.SetInt(1, 5);
    for (std::uint8_t s : {status::kHome, status::kManualPanel, status::kAuto, status::kOnline,
                           status::kOnlineStoppedMalfunction}) {
        pac_.SetOperatingStatus(s);
        const ReplyFrame reply = SendFrame(code::kGetIntReg, 1);
        EXPECT_FALSE(reply.commandErrorFlag) << "status " << int(s);
        EXPECT_EQ(reply.ackData, 5U);
        EXPECT_EQ(reply.operatingStatus, s);
    }
}

}  // namespace
}  // namespace pac::sim::testing
