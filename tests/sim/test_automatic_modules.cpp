// The modules in AUTOMATIC mode (manual 2.6): module k copied into FW k / N k / R k in every controller cycle
// and FW 16+k / N 16+k / R 16+k copied back, in both byte layouts of docs/open_points.md and both number
// formats (2.5.3); the stand-in AUTOMATIC program between the two copies; the modules as axis modules again
// once AUTOMATIC has ended, without flag data taken for a Start edge.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "pac/sim/automatic_module.hpp"
#include "pac/sim/automatic_program.hpp"
#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

namespace ac = axis_control;
namespace as = axis_status;

constexpr std::uint16_t kIdle = ctrl::kNoRequest;
constexpr std::uint16_t kCancelLow = static_cast<std::uint16_t>(ctrl::kNoRequest & ~ctrl::kCancel);
constexpr std::uint16_t kStopLow = static_cast<std::uint16_t>(ctrl::kNoRequest & ~ctrl::kStop);

std::string Hex(const Image12& module) {
    ProcessImage image(12);
    for (std::size_t i = 0; i < 12; ++i) image[i] = module[i];
    return ToHex(image);
}

PaControlConfig WithModules(AutomaticModuleConfig modules) {
    PaControlConfig config = QuickConfig();
    config.automaticModule = modules;
    return config;
}

// ---- the bytes ----------------------------------------------------------------------------------------

TEST(AutomaticModuleBytes, BothLayoutsBigEndian) {
    const AutomaticModuleData d{0x1234, -2, FloatToBits(10.0f)};  // 10.0 = 41 20 00 00 (docs/manual_errata.md)
    EXPECT_EQ(Hex(d.Encode(AutomaticLayout::kShiftedWidths)), "12 34 00 00 FF FF FF FE 41 20 00 00");
    EXPECT_EQ(Hex(d.Encode(AutomaticLayout::kAxisWidths)), "00 00 12 34 00 00 FF FE 41 20 00 00");
    for (AutomaticLayout layout : {AutomaticLayout::kShiftedWidths, AutomaticLayout::kAxisWidths}) {
        const AutomaticModuleData back = AutomaticModuleData::Decode(d.Encode(layout), layout);
        EXPECT_EQ(back.flagWord, d.flagWord);
        EXPECT_EQ(back.intRegister, d.intRegister);
        EXPECT_EQ(back.realBits, d.realBits);
    }
}

// 2.6.1 prints the widths 4, 2, 2, 4 (flag word, not used, N, R): a controller built with the default settings
// reads M1..M16 from bytes 2..3 and N as 16 bits from bytes 6..7.
TEST(AutomaticModuleBytes, TheDefaultIsTheWidthsAsPrinted) {
    EXPECT_EQ(AutomaticModuleConfig{}.layout, AutomaticLayout::kAxisWidths);
    EXPECT_EQ(PaControlConfig{}.automaticModule.layout, AutomaticLayout::kAxisWidths);
}

TEST(AutomaticModuleBytes, A16BitNKeepsItsLowBitsAndSignExtends) {
    const AutomaticModuleData d{0, 0x12345, 0};
    const Image12 module = d.Encode(AutomaticLayout::kAxisWidths);
    EXPECT_EQ(Hex(module), "00 00 00 00 00 00 23 45 00 00 00 00");
    EXPECT_EQ(AutomaticModuleData::Decode(module, AutomaticLayout::kAxisWidths).intRegister, 0x2345);
    const AutomaticModuleData negative{0, 0x8000, 0};
    EXPECT_EQ(AutomaticModuleData::Decode(negative.Encode(AutomaticLayout::kAxisWidths), AutomaticLayout::kAxisWidths)
                  .intRegister,
              -32768);
}

// ---- the program --------------------------------------------------------------------------------------

TEST(AutomaticProgramLines, RunInOrderWithEveryOperandKind) {
    Elements e{ElementCounts{}};
    e.realRegisters.SetReal(1, 1.25f);
    e.intRegisters.SetInt(1, 41);
    e.flags.Set(1, true);
    e.flags.SetWord(17, 0xBEEF);  // FW2
    const AutomaticProgram program({"R17 := R1 * 2", "M257 := M1", "N17 := N1 + 1", "FW18 := FW2", "R18 := N17 / 4",
                                    "N18 := R1 - 3", "M258 := N1"});
    EXPECT_EQ(program.Size(), 7u);
    program.Run(e);
    EXPECT_EQ(e.realRegisters.GetReal(17), 2.5f);
    EXPECT_TRUE(e.flags.Get(257));
    EXPECT_EQ(e.intRegisters.GetInt(17), 42);
    EXPECT_EQ(e.flags.Word(FirstFlagOf(18)), 0xBEEF);
    EXPECT_EQ(e.realRegisters.GetReal(18), 10.5f) << "a line sees what the lines before it wrote";
    EXPECT_EQ(e.intRegisters.GetInt(18), -2) << "-1.75 rounds to the nearest";
    EXPECT_TRUE(e.flags.Get(258)) << "a flag is 'not 0'";
}

TEST(AutomaticProgramLines, RefusesWhatItCannotRead) {
    for (const char* bad : {"", "R17", "R17 = R1", "X1 := R1", "R0 := R1", "R1025 := R1", "FW65 := FW1",
                            "R17 := R1 % 2", "R17 := R1 * ", "R17 := R1 / 0", "R17 := R1 * 2 3", "R17 := 5"}) {
        EXPECT_THROW(AutomaticProgram({bad}), std::invalid_argument) << bad;
    }
}

// ---- the controller -----------------------------------------------------------------------------------

class AutomaticModules : public PacRig {
protected:
    explicit AutomaticModules(AutomaticModuleConfig modules = {})
        : PacRig(WithModules(modules), AxisBus(2)), layout_(modules.layout) {}

    void SetUp() override { Idle(); }  // the first CTRL control word: the reference for its edges

    // Home position to AUTOMATIC through the CTRL interface: 10, then 11.
    void Automatic(bool integer = false) {
        const std::uint16_t format = integer ? ctrl::kIntegerFormat : 0;
        Control(kIdle | ctrl::kStartAutomatic | format);
        ASSERT_EQ(pac_.OperatingStatus(), 10);
        Control(kIdle | format);
        ASSERT_EQ(pac_.OperatingStatus(), 11);
    }
    void Send(int k, const AutomaticModuleData& d) {
        axisToPac_[static_cast<std::size_t>(k - 1)] = AxisModuleCommand::Decode(d.Encode(layout_));
    }
    AutomaticModuleData Received(int k) const { return AutomaticModuleData::Decode(AxisModuleBytes(k), layout_); }

    AutomaticLayout layout_;
};

TEST_F(AutomaticModules, TheDefaultControllerReadsTheWidthsAsPrinted) {
    Automatic();
    // FW1 = 16#8001 in bytes 2..3, N1 = -300 (16#FED4) in bytes 6..7, R1 = 10.0.
    const Image12 module{0x00, 0x00, 0x80, 0x01, 0x00, 0x00, 0xFE, 0xD4, 0x41, 0x20, 0x00, 0x00};
    axisToPac_[0] = AxisModuleCommand::Decode(module);
    pac_.Io().intRegisters.SetInt(17, -2);
    pac_.Io().flags.SetWord(FirstFlagOf(17), 0x0102);
    Idle();
    EXPECT_EQ(pac_.Io().flags.Word(1), 0x8001);
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(1), -300);
    EXPECT_EQ(pac_.Io().realRegisters.GetReal(1), 10.0f);
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "00 00 01 02 00 00 FF FE 00 00 00 00");
}

class AutomaticModulesShifted : public AutomaticModules {
protected:
    AutomaticModulesShifted() : AutomaticModules({AutomaticLayout::kShiftedWidths, AutomaticExchange::kWholeMode}) {}
};

TEST_F(AutomaticModulesShifted, ModuleKIsCopiedIntoFwNRkAndBackFrom16PlusK) {
    Automatic();
    Send(1, {0x8001, 123456, FloatToBits(640.0f)});
    Send(2, {0x00F0, -7, FloatToBits(-0.5f)});
    pac_.Io().flags.SetWord(FirstFlagOf(17), 0xA5A5);  // M257..M272
    pac_.Io().intRegisters.SetInt(18, -99);
    pac_.Io().realRegisters.SetReal(17, 1255.0f);
    Idle();
    const Elements& e = pac_.Io();
    EXPECT_TRUE(e.flags.Get(1));
    EXPECT_TRUE(e.flags.Get(16));
    EXPECT_FALSE(e.flags.Get(2));
    EXPECT_EQ(e.flags.Word(17), 0x00F0) << "FW2 is M17..M32";
    EXPECT_EQ(e.intRegisters.GetInt(1), 123456);
    EXPECT_EQ(e.intRegisters.GetInt(2), -7);
    EXPECT_EQ(e.realRegisters.GetReal(1), 640.0f);
    EXPECT_EQ(e.realRegisters.GetReal(2), -0.5f);
    EXPECT_EQ(Received(1).flagWord, 0xA5A5);
    EXPECT_EQ(Received(2).intRegister, -99);
    EXPECT_EQ(BitsToFloat(Received(1).realBits), 1255.0f);
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "A5 A5 00 00 00 00 00 00 44 9C E0 00");
}

TEST_F(AutomaticModules, RRegistersInTheIntegerFormatAreValueTimes1000) {
    Automatic(true);
    ASSERT_TRUE(pac_.IntegerFormat());
    Send(1, {0, 0, static_cast<std::uint32_t>(-12345)});
    pac_.Io().realRegisters.SetReal(17, 25.045f);
    Idle();
    EXPECT_FLOAT_EQ(pac_.Io().realRegisters.GetReal(1), -12.345f);
    EXPECT_EQ(static_cast<std::int32_t>(Received(1).realBits), 25045) << "2.5.3's example";
}

TEST_F(AutomaticModules, TheProgramRunsBetweenTheCopiesWhileItRuns) {
    pac_.SetAutomaticProgram(AutomaticProgram({"R17 := R1 * 2", "M257 := M1", "N17 := N1 + 1"}));
    Automatic();
    Send(1, {0x0001, 41, FloatToBits(1.5f)});
    Idle();
    EXPECT_EQ(BitsToFloat(Received(1).realBits), 3.0f) << "one controller cycle: in, program, out";
    EXPECT_EQ(Received(1).flagWord, 0x0001);
    EXPECT_EQ(Received(1).intRegister, 42);
    // Stopped (15): the copies go on, the program does not run.
    Control(kStopLow);
    Control(kIdle);
    while (pac_.OperatingStatus() != 15) Idle();
    Send(1, {0, 99, FloatToBits(7.0f)});
    Idle();
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(1), 99);
    EXPECT_EQ(Received(1).intRegister, 42) << "N17 is no longer computed";
}

TEST_F(AutomaticModules, OutsideAutomaticTheModulesAreAxisModules) {
    Send(1, {0xFFFF, 5, FloatToBits(2.0f)});
    Idle();
    EXPECT_EQ(pac_.OperatingStatus(), 1);
    EXPECT_EQ(pac_.Io().flags.Word(1), 0) << "home position copies nothing";
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(1), 0);
    EXPECT_NE(AxisReply(1).status & as::kDriveEnabled, 0u) << "the axis status, as in 2.7.2";
}

TEST_F(AutomaticModules, FlagDataAreNoStartEdgeWhenTheModuleIsAnAxisModuleAgain) {
    ASSERT_EQ(pac_.SystemParameters().Set(4, 1), ParameterTable::SetResult::kOk);  // ONLINE's external stop
    pac_.Io().inputs.Set(1, true);
    Automatic();
    // Flags whose bits read as Axis ON + Start + absolute traversing: the control word's bytes 2..3.
    AxisModuleCommand flags;
    flags.control = ac::kAxisOn | ac::kStart | ac::kMoveAbsolute;
    flags.speedPerMille = 1000;
    flags.accelerationPerMille = 1000;
    flags.position = FloatToBits(50.0f);
    axisToPac_[0] = flags;
    Idle();
    Control(kCancelLow);
    Control(kIdle);
    ASSERT_EQ(pac_.OperatingStatus(), 1);
    Control(kIdle | ctrl::kStartOnline);
    Control(kIdle);
    ASSERT_EQ(pac_.OperatingStatus(), 31);
    for (int i = 0; i < 10; ++i) {
        Idle();
        EXPECT_EQ(AxisReply(1).status & (as::kActive | as::kCmdError), 0u) << "cycle " << i << ": no job, no refusal";
    }
    EXPECT_EQ(AxisReply(1).cmdError, 0u);
    EXPECT_EQ(pac_.Axes().Motion(1).Position(), 0.0);
}

class AutomaticModulesOtherReadings : public AutomaticModules {
protected:
    AutomaticModulesOtherReadings()
        : AutomaticModules({AutomaticLayout::kAxisWidths, AutomaticExchange::kProgramRunning}) {}
};

TEST_F(AutomaticModulesOtherReadings, AxisWidthsAndCopiesOnlyWhileTheProgramRuns) {
    pac_.SetAutomaticProgram(AutomaticProgram({"N17 := N1 * 3"}));
    Automatic();
    Send(1, {0x4321, -300, 0});
    Idle();
    EXPECT_EQ(pac_.Io().flags.Word(1), 0x4321);
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(1), -300);
    EXPECT_EQ(Received(1).intRegister, -900);
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "00 00 00 00 00 00 FC 7C 00 00 00 00");
    Control(kStopLow);
    Control(kIdle);
    while (pac_.OperatingStatus() != 15) Idle();
    Send(1, {0, 5, 0});
    pac_.Io().intRegisters.SetInt(17, 1);
    Idle();
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(1), -300) << "no copy while the program is stopped";
    EXPECT_EQ(Received(1).intRegister, -900) << "the reply stays as last copied";
}

}  // namespace
}  // namespace pac::sim::testing
