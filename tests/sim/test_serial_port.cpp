// The PA-CONTROL's RS232 port (docs/sim_serial.md): the CHECK it verifies, the sequence errors 16, 17, 18,
// the EOT poll, data type flags, the settings for the readings of chapter 3 the manual leaves open, and the
// baud-rate timing of the reply.
#include <gtest/gtest.h>

#include <chrono>

#include "pac/sim/image8.hpp"
#include "serial_fixture.hpp"

namespace pac::sim::testing {
namespace {

using namespace std::chrono_literals;
using rs232::CheckRule;
using rs232::Frame;

std::string Ack(const std::string& text) { return HexOf(Frame(text, CheckRule::kXorWithEtx)); }

// The default is the rule of the manual's master frames (3.4): the XOR of the text; "0" passes (3.1).
TEST(SerialPort, TakesTheXorOfTheTextAndZeroByDefault) {
    SerialRig rig;
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0906;7;0;-42", CheckRule::kXorText))), Ack("0;1;1;0;0;-42"));
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0906;8;0;43", 0))), Ack("0;1;1;0;0;43"));
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0906;9;0;44", CheckRule::kXorWithEtx))), Ack("16;0;1;0;0;0"));
    EXPECT_EQ(rig.Pac().Io().intRegisters.GetInt(9), 0);
    EXPECT_EQ(rig.Pac().Serial().Counters().checkErrors, 1u);
}

TEST(SerialPort, VerifiesTheXorWithEtxWhenSetSo) {
    SerialPortConfig port;
    port.verify = CheckVerification::kXorWithEtx;
    SerialRig rig(port);
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0906;7;0;-42", CheckRule::kXorWithEtx))), Ack("0;1;1;0;0;-42"));
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0906;9;0;44", CheckRule::kXorText))), Ack("16;0;1;0;0;0"));
}

TEST(SerialPort, VerifiesTheRuleItIsSetTo) {
    SerialPortConfig port;
    port.verify = CheckVerification::kXorText;
    port.acceptZeroCheck = false;
    SerialRig rig(port);
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0906;7;0;5", CheckRule::kXorText))), Ack("0;1;1;0;0;5"));
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0906;7;0;6", 0))), Ack("16;0;1;0;0;0"));
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0906;7;0;6", CheckRule::kXorWithEtx))), Ack("16;0;1;0;0;0"));
    EXPECT_EQ(rig.Pac().Io().intRegisters.GetInt(7), 5);
}

TEST(SerialPort, AnswersABadCheckWithSilenceWhenSetSo) {
    SerialPortConfig port;
    port.answerBadCheck = false;
    SerialRig rig(port);
    EXPECT_TRUE(rig.Exchange(Frame("0906;7;0;5", 99)).empty());
    EXPECT_EQ(HexOf(rig.Exchange({rs232::kEot})), Ack("16;0;1;0;0;0")) << "16 is the last reply";
}

// The reading that discards such a frame altogether: an EOT after it repeats the reply before it.
TEST(SerialPort, DiscardsABadCheckFrameWhenSetSo) {
    SerialPortConfig port;
    port.answerBadCheck = false;
    port.discardBadCheckFrame = true;
    SerialRig rig(port);
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0906;7;0;5", CheckRule::kXorText))), Ack("0;1;1;0;0;5"));
    EXPECT_TRUE(rig.Exchange(Frame("0909;0;0;0", 99)).empty());
    EXPECT_EQ(HexOf(rig.Exchange({rs232::kEot})), Ack("0;1;1;0;0;5"));
    EXPECT_EQ(rig.Pac().Serial().Counters().checkErrors, 1u);
    ASSERT_EQ(rig.Pac().Serial().Commands().size(), 1u) << "0909 was never carried out";
    EXPECT_EQ(rig.Pac().Serial().Commands()[0].code, 0x0906);
    EXPECT_EQ(rig.Pac().Serial().Commands()[0].data, 5u);
}

TEST(SerialPort, RepliesWithTheReplyCheckRule) {
    SerialPortConfig port;
    port.replyCheck = CheckRule::kZero;
    SerialRig rig(port);
    EXPECT_EQ(HexOf(rig.Exchange(Frame("190B;0;0;0", CheckRule::kXorText))), HexOf(Frame("0;1;1;0;0;1", 0)));
}

TEST(SerialPort, SequenceErrors) {
    SerialRig rig;
    // EOT before ETX: a wrong set-up (17).
    EXPECT_EQ(HexOf(rig.Exchange(Hex("01 02 31 39 30 42 04"))), Ack("17;0;1;0;0;0"));
    // Bytes that begin no frame, then EOT: a wrong beginning (18).
    EXPECT_EQ(HexOf(rig.Exchange(Hex("31 39 04"))), Ack("18;0;1;0;0;0"));
    // SOH not followed by STX (18).
    EXPECT_EQ(HexOf(rig.Exchange(Hex("01 31 04"))), Ack("18;0;1;0;0;0"));
    // Three fields instead of four, a code that is not hex, a data type other than 0 / 1 (17).
    EXPECT_EQ(HexOf(rig.Exchange(Frame("190B;0;0", CheckRule::kXorText))), Ack("17;0;1;0;0;0"));
    EXPECT_EQ(HexOf(rig.Exchange(Frame("19XB;0;0;0", CheckRule::kXorText))), Ack("17;0;1;0;0;0"));
    EXPECT_EQ(HexOf(rig.Exchange(Frame("190B;0;2;0", CheckRule::kXorText))), Ack("17;0;1;0;0;0"));
    // A fraction with data type 0 (17).
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0906;1;0;1.5", CheckRule::kXorText))), Ack("17;0;1;0;0;0"));
    EXPECT_EQ(rig.Pac().Serial().Counters().commands, 0u);
}

TEST(SerialPort, ACutOffFrameGivesWayToTheNextOne) {
    SerialRig rig;
    Bytes bytes = Hex("01 02 30 39 30 36 3B");  // cut off
    const Bytes next = Frame("0906;4;0;77", CheckRule::kXorText);
    bytes.insert(bytes.end(), next.begin(), next.end());
    EXPECT_EQ(HexOf(rig.Exchange(bytes)), Ack("0;1;1;0;0;77"));
    EXPECT_EQ(rig.Pac().Serial().Counters().replies, 1u) << "the cut frame is dropped without an answer";
}

TEST(SerialPort, NoiseBeforeAFrameIsSkipped) {
    SerialRig rig;
    Bytes bytes = Hex("7F 20 41");
    const Bytes frame = Frame("0906;4;0;78", CheckRule::kXorText);
    bytes.insert(bytes.end(), frame.begin(), frame.end());
    EXPECT_EQ(HexOf(rig.Exchange(bytes)), Ack("0;1;1;0;0;78"));
}

TEST(SerialPort, StxAloneBeginsAFrameOnlyWhenSohIsNotRequired) {
    SerialRig strict;
    EXPECT_EQ(HexOf(strict.Exchange(Frame("0906;4;0;5", rs232::Check("0906;4;0;5", CheckRule::kXorText), false))), Ack("18;0;1;0;0;0"));
    SerialPortConfig port;
    port.requireSoh = false;
    SerialRig lenient(port);
    EXPECT_EQ(HexOf(lenient.Exchange(Frame("0906;4;0;5", rs232::Check("0906;4;0;5", CheckRule::kXorText), false))), Ack("0;1;1;0;0;5"));
}

TEST(SerialPort, APollRepeatsTheLastReplyOrStaysSilentWhenSetSo) {
    SerialRig rig;
    EXPECT_EQ(HexOf(rig.Exchange({rs232::kEot})), Ack("0;1;1;0;0;0")) << "nothing carried out yet";
    rig.Pac().Io().intRegisters.SetInt(2, 5);
    rig.Exchange(Frame("1906;2;0;0", CheckRule::kXorText));
    EXPECT_EQ(HexOf(rig.Exchange({rs232::kEot})), Ack("0;1;1;0;0;5"));
    rig.Exchange(Frame("1906;2;0;0", 99));  // refused: 16
    EXPECT_EQ(HexOf(rig.Exchange({rs232::kEot})), Ack("16;0;1;0;0;0")) << "the last reply, not the last command";

    SerialPortConfig port;
    port.answerPollWhenIdle = false;
    SerialRig quiet(port);
    quiet.Exchange(Frame("1906;2;0;0", CheckRule::kXorText));
    EXPECT_TRUE(quiet.Exchange({rs232::kEot}).empty());
}

TEST(SerialPort, ModeCommandsAnswerAtOnceWhenNotHeld) {
    SerialPortConfig port;
    port.holdModeReplies = false;
    SerialRig rig(port);
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0603;0;0;0", CheckRule::kXorText))), Ack("0;0;30;0;0;0"));
    EXPECT_EQ(HexOf(rig.Exchange({rs232::kEot})), Ack("0;1;31;0;0;0"));
}

TEST(SerialPort, DataTypeFlagsAreConvertedOrRefused) {
    SerialRig rig;
    rig.Exchange(Frame("0907;3;0;5", CheckRule::kXorText));  // integer text for an R register
    EXPECT_EQ(rig.Pac().Io().realRegisters.GetReal(3), 5.0F);
    rig.Exchange(Frame("0906;3;1;7.9", CheckRule::kXorText));  // a REAL for an N register: toward zero
    EXPECT_EQ(rig.Pac().Io().intRegisters.GetInt(3), 7);

    SerialPortConfig port;
    port.refuseTypeMismatch = true;
    SerialRig strict(port);
    EXPECT_EQ(HexOf(strict.Exchange(Frame("0907;3;0;5", CheckRule::kXorText))), Ack("41;0;1;0;0;0"));
    EXPECT_EQ(HexOf(strict.Exchange(Frame("0906;3;1;7.9", CheckRule::kXorText))), Ack("41;0;1;0;0;0"));
    EXPECT_EQ(HexOf(strict.Exchange(Frame("0907;3;1;-2.5e1", CheckRule::kXorText))), Ack("0;1;1;0;1;-25.0000"));
}

// 5.2.6.22 / 5.2.6.23: both commands carry command data (an integer) over RS232 as over the fieldbus.
TEST(SerialPort, LimitSwitchMonitoringAndMoveConditionTakeTheirData) {
    SerialPortConfig port;
    port.verify = CheckVerification::kNone;  // the data, whatever the CHECK rule
    SerialRig rig(port);
    ASSERT_EQ(HexOf(rig.Exchange(Frame("0603;0;0;0", 0))), Ack("0;1;31;0;0;0"));
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0AA2;1;0;0", 0))), Ack("0;1;31;0;0;0"));
    EXPECT_FALSE(rig.Pac().Online().LimitSwitchMonitoring(1)) << "0: off";
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0AA2;1;0;1", 0))), Ack("0;1;31;0;0;0"));
    EXPECT_TRUE(rig.Pac().Online().LimitSwitchMonitoring(1)) << "1: on";
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0AA2;1;0;7", 0))), Ack("41;0;31;0;0;0")) << "neither off nor on";
    EXPECT_TRUE(rig.Pac().Online().LimitSwitchMonitoring(1));
    // Move axis 1 as long as flag 12 = 0: condition 0, element type 3, number 12 (16#0003000C).
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0AA3;1;0;196620", 0))), Ack("0;1;31;0;0;0"));
    const auto condition = rig.Pac().Online().PendingCondition(1);
    ASSERT_TRUE(condition.has_value());
    EXPECT_EQ(condition->type, ElementType::kFlag);
    EXPECT_EQ(condition->number, 12);
    EXPECT_FALSE(condition->level);
}

TEST(SerialPort, ASilentPortAnswersNothing) {
    SerialPortConfig port;
    port.answers = false;
    SerialRig rig(port);
    EXPECT_TRUE(rig.Exchange(Frame("0906;1;0;9", CheckRule::kXorText)).empty());
    EXPECT_EQ(rig.Pac().Io().intRegisters.GetInt(1), 9) << "it takes commands all the same";
}

TEST(SerialPort, CommandErrorsComeFromTheCommandProcessor) {
    SerialRig rig;
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0A87;1;1;10.0", CheckRule::kXorText))), Ack("20;0;1;0;0;0"));
    rig.Pac().InjectCommandError(38);
    EXPECT_EQ(HexOf(rig.Exchange(Frame("1906;1;0;0", CheckRule::kXorText))), Ack("38;0;1;0;0;0"));
    EXPECT_EQ(HexOf(rig.Exchange(Frame("1999;1;0;0", CheckRule::kXorText))), Ack("19;0;1;0;0;0"));
    rig.Pac().SetSystemError(123);
    EXPECT_EQ(HexOf(rig.Exchange(Frame("1909;0;0;0", CheckRule::kXorText))), Ack("0;1;1;123;0;123"));
}

TEST(SerialPort, BytesArriveDuringTheBootAreLost) {
    PaControlConfig config = SerialOnlyConfig();
    config.bootTime = 50ms;
    SerialRig rig({}, {}, config);
    EXPECT_TRUE(rig.Exchange(Frame("0906;1;0;9", CheckRule::kXorText), 3).empty());
    while (!rig.Pac().Booted()) rig.Step();
    EXPECT_EQ(HexOf(rig.Exchange(Frame("0906;1;0;9", CheckRule::kXorText))), Ack("0;1;1;0;0;9"));
}

// The reply leaves in the controller cycle that completes the request and takes one character time per
// byte: at 9600 baud with 7N1 (9 bits) 937.5 us, at 1200 baud 7.5 ms.
TEST(SerialPort, TheReplyTakesOneCharacterTimePerByte) {
    for (int baud : {1200, 9600, 19200}) {
        SerialFormat format;
        format.baud = baud;
        SerialRig rig({}, format);
        const std::chrono::nanoseconds character = format.CharacterTime();
        const Bytes request = Frame("190B;0;0;0", CheckRule::kXorText);
        const std::chrono::nanoseconds sent = rig.Now();
        rig.Line().toPac.Send(sent, request);
        const std::chrono::nanoseconds complete = sent + static_cast<int>(request.size()) * character;
        std::chrono::nanoseconds cycle = rig.Now();
        while (cycle < complete) {
            rig.Step();
            cycle = rig.Now();
        }
        const Bytes expected = Frame("0;1;1;0;0;1", CheckRule::kXorText);
        EXPECT_TRUE(rig.Line().fromPac.Receive(cycle).empty()) << baud;
        EXPECT_EQ(rig.Line().fromPac.LastEnd(), cycle + static_cast<int>(expected.size()) * character) << baud;
        EXPECT_EQ(rig.Line().fromPac.Receive(cycle + character), Bytes{rs232::kSoh}) << baud;
    }
}

}  // namespace
}  // namespace pac::sim::testing
