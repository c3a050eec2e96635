// The examples of manual 3.4 byte for byte, with the errata of docs/manual_errata.md: the
// acknowledgements exactly as printed (their CHECK is the XOR of the text and ETX, decimal), except the
// 0603 acknowledgement, whose printed CHECK 8 leaves ETX out. The master frames are sent as printed where
// the print is right, to the default controller, which verifies the XOR of the text (the rule four of them
// follow, none the XOR with ETX); 3.4.1 to one that verifies none, with its printed CHECK 7.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "pac/sim/image8.hpp"
#include "serial_fixture.hpp"

namespace pac::sim::testing {
namespace {

SerialPortConfig Verifying(CheckVerification verify) {
    SerialPortConfig port;
    port.verify = verify;
    return port;
}

TEST(SerialManualExamples, WriteIntegerRegisterN5With12345) {  // 3.4.1
    SerialRig rig(Verifying(CheckVerification::kNone));
    const Bytes reply = rig.Exchange(Hex("01 02 30 39 30 36 3B 35 3B 30 3B 31 32 33 34 35 03 37 04"));
    EXPECT_EQ(HexOf(reply), "01 02 30 3B 31 3B 31 3B 30 3B 30 3B 31 32 33 34 35 03 35 37 04");
    EXPECT_EQ(rig.Pac().Io().intRegisters.GetInt(5), 12345);
}

// Every master frame of 3.4 to a controller with the default settings: none is refused (16). The CHECK of
// four of the seven prints is the XOR of the text (1900, 0906;3, 1971 as printed; 0603 once its code is
// corrected), none the XOR with ETX; three print a CHECK that fits no rule and are sent with the XOR of the text.
// Errata (docs/manual_errata.md, "RS232"):
//   3.4.1 CHECK 7 fits no rule (XOR of the text 0, with ETX 3): sent with 0;
//   3.4.2 "read N2" prints the code 1960 for 1906, and its CHECK 6 fits no rule for either (XOR of the text 7,
//         with ETX 4: the two texts hold the same bytes): sent as 1906 with 7;
//   3.4.2 "read R1" prints 1971;3;0 for the table's 1907;1;1 (its CHECK 6 is the XOR of the printed text):
//         sent as 1907;1;1;0 with 4;
//   3.4.3 "start online" prints the code 0A03 for 0603 (its CHECK 14 is the XOR of "0603;0;0;0");
//   3.4.3 "move axis 2" CHECK 14 fits no rule (XOR of the text 95, with ETX 92): sent with 95.
// The acknowledgements as printed but for the one of 0603, whose printed CHECK 8 leaves ETX out (11).
TEST(SerialManualExamples, TheDefaultControllerTakesEveryPrintedFrameOf34) {
    SerialRig rig;
    rig.Pac().Io().inputs.Set(5, true);
    rig.Pac().Io().intRegisters.SetInt(2, 222);
    rig.Pac().Io().realRegisters.SetReal(1, 640.0F);
    struct Example {
        const char* section;
        const char* request;
        const char* reply;
    };
    const Example examples[] = {
        {"3.4.1 N5 := 12345", "01 02 30 39 30 36 3B 35 3B 30 3B 31 32 33 34 35 03 30 04",
         "01 02 30 3B 31 3B 31 3B 30 3B 30 3B 31 32 33 34 35 03 35 37 04"},
        {"3.4.2 input 5", "01 02 31 39 30 30 3B 35 3B 30 3B 30 03 36 04",
         "01 02 30 3B 31 3B 31 3B 30 3B 30 3B 31 03 35 37 04"},
        {"3.4.2 read N2", "01 02 31 39 30 36 3B 32 3B 30 3B 30 03 37 04",
         "01 02 30 3B 31 3B 31 3B 30 3B 30 3B 32 32 32 03 35 38 04"},
        {"3.4.2 N3 := 333", "01 02 30 39 30 36 3B 33 3B 30 3B 33 33 33 03 34 04",
         "01 02 30 3B 31 3B 31 3B 30 3B 30 3B 33 33 33 03 35 39 04"},
        {"3.4.2 read R1", "01 02 31 39 30 37 3B 31 3B 31 3B 30 03 34 04",
         "01 02 30 3B 31 3B 31 3B 30 3B 31 3B 36 34 30 2E 30 30 30 30 03 32 31 04"},
        {"3.4.3 start online", "01 02 30 36 30 33 3B 30 3B 30 3B 30 03 31 34 04",
         "01 02 30 3B 31 3B 33 31 3B 30 3B 30 3B 30 03 31 31 04"},
        {"3.4.3 move axis 2", "01 02 30 41 38 37 3B 32 3B 31 3B 35 35 35 32 2E 30 03 39 35 04",
         "01 02 30 3B 30 3B 33 31 3B 30 3B 31 3B 31 32 35 35 2E 30 30 30 03 33 38 04"},
    };
    for (const Example& e : examples) {
        if (std::string(e.section) == "3.4.3 move axis 2") rig.Pac().Axes().Motion(2).Place(rig.Now(), 1255.0);
        EXPECT_EQ(HexOf(rig.Exchange(Hex(e.request))), e.reply) << e.section;
    }
    EXPECT_EQ(rig.Pac().Serial().Counters().checkErrors, 0u);
    EXPECT_EQ(rig.Pac().Io().intRegisters.GetInt(5), 12345);
    EXPECT_EQ(rig.Pac().Io().intRegisters.GetInt(3), 333);
}

TEST(SerialManualExamples, ThePrintedCheckOf341FollowsNoRule) {
    // "7" is neither the XOR with ETX (3) nor without (0): a controller that verifies either refuses it (16).
    for (CheckVerification verify : {CheckVerification::kXorWithEtx, CheckVerification::kXorText}) {
        SerialRig rig(Verifying(verify));
        const Bytes reply = rig.Exchange(Hex("01 02 30 39 30 36 3B 35 3B 30 3B 31 32 33 34 35 03 37 04"));
        EXPECT_EQ(HexOf(reply), HexOf(rs232::Frame("16;0;1;0;0;0", rs232::CheckRule::kXorWithEtx)));
        EXPECT_EQ(rig.Pac().Io().intRegisters.GetInt(5), 0) << "a refused frame is not carried out";
    }
}

class ComplexExample1 : public ::testing::Test {  // 3.4.2
protected:
    ComplexExample1() {
        rig_.Pac().Io().inputs.Set(5, true);
        rig_.Pac().Io().intRegisters.SetInt(2, 222);
        rig_.Pac().Io().realRegisters.SetReal(1, 640.0F);
    }
    SerialRig rig_;
};

TEST_F(ComplexExample1, TheFourCommandsAndTheirAcknowledgements) {
    // Input 5, as printed.
    EXPECT_EQ(HexOf(rig_.Exchange(Hex("01 02 31 39 30 30 3B 35 3B 30 3B 30 03 36 04"))),
              "01 02 30 3B 31 3B 31 3B 30 3B 30 3B 31 03 35 37 04");
    // N2: the print sends 1960 (docs/manual_errata.md); 1906 with its CHECK.
    EXPECT_EQ(HexOf(rig_.Exchange(rs232::Frame("1906;2;0;0", rs232::CheckRule::kXorText))),
              "01 02 30 3B 31 3B 31 3B 30 3B 30 3B 32 32 32 03 35 38 04");
    // N3 := 333, as printed.
    EXPECT_EQ(HexOf(rig_.Exchange(Hex("01 02 30 39 30 36 3B 33 3B 30 3B 33 33 33 03 34 04"))),
              "01 02 30 3B 31 3B 31 3B 30 3B 30 3B 33 33 33 03 35 39 04");
    EXPECT_EQ(rig_.Pac().Io().intRegisters.GetInt(3), 333);
    // R1: the print sends 1971;3 and data type 0 where its table says 1 (docs/manual_errata.md).
    EXPECT_EQ(HexOf(rig_.Exchange(rs232::Frame("1907;1;1;0", rs232::CheckRule::kXorText))),
              "01 02 30 3B 31 3B 31 3B 30 3B 31 3B 36 34 30 2E 30 30 30 30 03 32 31 04");
}

TEST_F(ComplexExample1, AReadIgnoresTheDataTypeFlag) {
    // The printed frame of the R1 read carries data type 0 (and its CHECK is right for it): same answer.
    EXPECT_EQ(HexOf(rig_.Exchange(rs232::Frame("1907;1;0;0", rs232::CheckRule::kXorText))),
              "01 02 30 3B 31 3B 31 3B 30 3B 31 3B 36 34 30 2E 30 30 30 30 03 32 31 04");
}

TEST(SerialManualExamples, ComplexExample2StartOnlineMoveAndPoll) {  // 3.4.3
    SerialRig rig;
    // Start online: the print sends 0A03 (its CHECK 14 is that of 0603). The acknowledgement as printed but
    // for the CHECK: 11 (XOR with ETX, "31 31"), where the print has 8 (without ETX).
    const Bytes started = rig.Exchange(rs232::Frame("0603;0;0;0", rs232::CheckRule::kXorText));
    EXPECT_EQ(HexOf(started), "01 02 30 3B 31 3B 33 31 3B 30 3B 30 3B 30 03 31 31 04");

    // Move axis 2 to 5552.0 (the heading says 5520.0; the frame and the end position say 5552.0) from 1255.0;
    // the frame as printed but for its CHECK, 95 ("39 35") where the print has 14.
    rig.Pac().Axes().Motion(2).Place(rig.Now(), 1255.0);
    EXPECT_EQ(HexOf(rig.Exchange(Hex("01 02 30 41 38 37 3B 32 3B 31 3B 35 35 35 32 2E 30 03 39 35 04"))),
              "01 02 30 3B 30 3B 33 31 3B 30 3B 31 3B 31 32 35 35 2E 30 30 30 03 33 38 04");
    // Polls during the drive: BE 0 and a position between start and target that grows; then BE 1 at 5552.000.
    double last = 1255.0;
    for (int poll = 0; poll < 20; ++poll) {
        for (int i = 0; i < 20; ++i) rig.Step();  // 200 ms between polls
        const Bytes reply = rig.Exchange({rs232::kEot});
        ASSERT_FALSE(reply.empty());
        const std::string text(reply.begin() + 2, std::find(reply.begin(), reply.end(), rs232::kEtx));
        if (text.rfind("0;1;", 0) == 0) {
            EXPECT_EQ(HexOf(reply), "01 02 30 3B 31 3B 33 31 3B 30 3B 31 3B 35 35 35 32 2E 30 30 30 03 33 35 04");
            return;
        }
        ASSERT_EQ(text.substr(0, 11), "0;0;31;0;1;") << text;
        const double position = std::stod(text.substr(11));
        EXPECT_GT(position, last);
        EXPECT_LT(position, 5552.0);
        last = position;
    }
    FAIL() << "the move did not end within 20 polls";
}

}  // namespace
}  // namespace pac::sim::testing
