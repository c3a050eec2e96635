// FB_PAC_Rs232Cmd against hand-written bytes, scan by scan: the command frames of manual 3.4 byte for byte
// (with the errata of docs/manual_errata.md and docs/open_points.md), the manual's acknowledgements read back, the CHECKs
// it takes, a reply split over many scans, noise before STX, cut-off and damaged replies, the rules for
// sending again or polling, and the PLCopen rules on every scan.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <sstream>
#include <string>
#include <vector>

#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/scan_test.hpp"
#include "pac/serial_rig.hpp"
#include "pac/st_program.hpp"
#include "plcopen_checker.hpp"
#include "plcopen_pins.hpp"
#include "real_bits.hpp"

namespace test_fb_pac_rs232_cmd {  // apart from the names of the other sources in its unity batch
namespace {

using Bytes = std::vector<std::uint8_t>;
using pac::test::PlcOpenChecker;

const pac::test::GvlConstants kGvl;

Bytes Hex(const std::string& text) {
    Bytes bytes;
    std::istringstream in(text);
    std::string token;
    while (in >> token) bytes.push_back(static_cast<std::uint8_t>(std::stoul(token, nullptr, 16)));
    return bytes;
}

std::string HexOf(const Bytes& bytes) {
    std::string out;
    char buffer[4];
    for (std::uint8_t b : bytes) {
        std::snprintf(buffer, sizeof buffer, "%02X", b);
        if (!out.empty()) out += ' ';
        out += buffer;
    }
    return out;
}

// SOH STX text ETX check EOT with the XOR of the text and ETX.
Bytes Frame(const std::string& text, int check = -1) {
    unsigned sum = 3;
    for (char c : text) sum ^= static_cast<unsigned char>(c);
    Bytes bytes{1, 2};
    bytes.insert(bytes.end(), text.begin(), text.end());
    bytes.push_back(3);
    for (char c : std::to_string(check < 0 ? static_cast<int>(sum) : check)) bytes.push_back(static_cast<std::uint8_t>(c));
    bytes.push_back(4);
    return bytes;
}

// The XOR of the text, and with ETX.
int XorText(const std::string& text) {
    unsigned sum = 0;
    for (char c : text) sum ^= static_cast<unsigned char>(c);
    return static_cast<int>(sum);
}
int XorEtx(const std::string& text) { return XorText(text) ^ 3; }
// A command frame as AUTO writes it first: the XOR of the text (the rule of the manual's master frames).
Bytes Command(const std::string& text) { return Frame(text, XorText(text)); }

// The CHECK of a command frame the FB sent (the digits between ETX and EOT), -1 for anything else.
int CheckOf(const Bytes& frame) {
    if (frame.size() < 5 || frame.back() != 4) return -1;
    std::size_t etx = frame.size() - 2;
    while (etx > 0 && frame[etx] != 3) --etx;
    if (frame[etx] != 3) return -1;
    return std::stoi(std::string(frame.begin() + static_cast<std::ptrdiff_t>(etx) + 1, frame.end() - 1));
}

// One FB_PAC_Rs232Cmd whose receive buffer the test fills and whose transmit buffer it reads, scan by scan,
// with the PLCopen checker after every scan.
class Rs232Cmd : public pac::ScanTest {
protected:
    Rs232Cmd() : checker_("FB_PAC_Rs232Cmd") {
        task_.AddProgram([this] {
            while (!incoming_.empty() && perScan_-- != 0) {
                pac::com_ring::Put(fb_->RXBUFFER.value, incoming_.front());
                incoming_.pop_front();
            }
            perScan_ = bytesPerScan_;
            fb_();
            for (std::uint8_t b : pac::com_ring::TakeAll(fb_->TXBUFFER.value)) sent_.push_back(b);
            checker_.Check(task_.ScanCount(), fb_);
        });
        // The program has run idle for more than QuietTime since the PLC started: a fresh instance's first
        // request waits for that quiet line (an old instance's reply may still come in after a PLC restart).
        Cycle(60);
    }
    ~Rs232Cmd() override { EXPECT_EQ(checker_.Violations(), 0); }

    void Start(std::uint16_t code, std::uint16_t param, std::uint32_t data = 0) {
        fb_->CODE.value = code;
        fb_->PARAM.value = param;
        fb_->DATA.value = data;
        fb_->EXECUTE.value = TRUE;
        Cycle(1);
    }
    // The bytes sent since the last call.
    Bytes Sent() {
        Bytes out;
        out.swap(sent_);
        return out;
    }
    void Reply(const Bytes& bytes) { incoming_.insert(incoming_.end(), bytes.begin(), bytes.end()); }
    bool Final() const { return pac::test::IsFinal(fb_); }
    // Answers with `reply`, which must end the command Done in the next scan, then releases Execute.
    void EndDone(const Bytes& reply) {
        Reply(reply);
        Cycle(1);
        EXPECT_TRUE(fb_->DONE.value) << "Done on the reply";
        fb_->EXECUTE.value = FALSE;
        Cycle(1);
    }
    void SetBytesPerScan(int n) { bytesPerScan_ = perScan_ = n; }
    // A PLC that has talked to the controller before: a read whose CHECK (55) no spoilt bit turns into "0"
    // is answered, so AUTO's rule, the XOR of the text, is confirmed and no probe goes before a command.
    void ConfirmRule() {
        Start(0x1906, 2000);
        EXPECT_EQ(HexOf(Sent()), HexOf(Command("1906;2000;0;0")));
        EndDone(Frame("0;1;1;0;0;0"));
    }

    pac::FbInstance<FB_PAC_RS232CMD> fb_ = PAC_FB(FB_PAC_RS232CMD);
    PlcOpenChecker checker_;
    std::deque<std::uint8_t> incoming_;
    Bytes sent_;
    int bytesPerScan_ = -1;  // -1: all at once
    int perScan_ = -1;
};

// ---- the frames of 3.4 ----

TEST_F(Rs232Cmd, ManualFramesWhoseCheckIsTheXorOfTheText) {
    fb_->CHECKRULE.value = E_PAC_RS232CHECK__PAC_RS232_CHECK_XOR_TEXT;
    Start(0x1900, 5);  // 3.4.2, input 5, as printed
    EXPECT_EQ(HexOf(Sent()), "01 02 31 39 30 30 3B 35 3B 30 3B 30 03 36 04");
    Reply(Frame("0;1;1;0;0;1"));
    Cycle(1);
    EXPECT_TRUE(fb_->DONE.value);
    fb_->EXECUTE.value = FALSE;
    Cycle(1);
    Start(0x0906, 3, 333);  // 3.4.2, N3 := 333, as printed
    EXPECT_EQ(HexOf(Sent()), "01 02 30 39 30 36 3B 33 3B 30 3B 33 33 33 03 34 04");
}

TEST_F(Rs232Cmd, ManualFramesWithTheErrataApplied) {
    ConfirmRule();
    struct Case {
        std::uint16_t code, param;
        std::uint32_t data;
        const char* text;  // the frame's text, corrected
    };
    const Case cases[] = {
        {0x0906, 5, 12345, "0906;05;0;12345"},  // 3.4.1 (its CHECK 7 follows no rule; its XOR is 0: PAR_1 05)
        {0x1906, 2, 0, "1906;2;0;0"},                                      // printed 1960
        {0x1907, 1, 0, "1907;1;1;0"},                                      // printed 1971;3;0
        {0x0603, 0, 0, "0603;0;0;0"},                                      // printed 0A03
        {0x0A87, 2, pac::test::BitsOf(5552.0F), "0A87;2;1;5552.0"},      // as printed but for the CHECK
    };
    for (const Case& c : cases) {
        Start(c.code, c.param, c.data);
        EXPECT_EQ(HexOf(Sent()), HexOf(Command(c.text))) << c.text << ": the XOR of the text by default";
        fb_->EXECUTE.value = FALSE;
        Reply(Frame("0;1;1;0;0;0"));
        Cycle(3);
    }
}

TEST_F(Rs232Cmd, NumbersInTheirAsciiForm) {
    struct Case {
        std::uint16_t code, param;
        std::uint32_t data;
        const char* text;
    };
    const Case cases[] = {
        {0x0906, 65535, 0x80000000u, "0906;65535;0;-2147483648"},
        {0x0907, 1, pac::test::BitsOf(-0.5F), "0907;1;1;-0.5"},
        {0x0907, 1, pac::test::BitsOf(12.345F), "0907;1;1;12.345"},
        {0x0907, 1, pac::test::BitsOf(0.0001F), "0907;1;1;0.0001"},
        {0x0907, 1, pac::test::BitsOf(640.0F), "0907;1;1;640.0"},
        {0x0800, 0x0106, pac::test::BitsOf(10000.0F), "0800;262;1;10000.0"},
        {0x0903, 2, 0xFFFF, "0903;02;0;65535"},  // its XOR is 3, 0 under the XOR with ETX: PAR_1 02
        {0x190C, 1, 0, "190C;1;1;0"},
    };
    for (const Case& c : cases) {
        Start(c.code, c.param, c.data);
        EXPECT_EQ(HexOf(Sent()), HexOf(Command(c.text))) << c.text;
        fb_->EXECUTE.value = FALSE;
        Reply(Frame("0;1;1;0;0;0"));
        Cycle(3);
    }
}

TEST_F(Rs232Cmd, DataWithoutAnAsciiFormIsRefusedUnsent) {
    for (std::uint32_t bits : {0x7FC00000u, 0x7F800000u, pac::test::BitsOf(1.0E9F)}) {
        Start(0x0907, 1, bits);
        EXPECT_TRUE(fb_->ERROR.value);
        EXPECT_EQ(fb_->ERRORID.value, kGvl["PAC_LIB_ERR_SERIAL_DATA"]);
        EXPECT_TRUE(Sent().empty());
        fb_->EXECUTE.value = FALSE;
        Cycle(1);
    }
    Start(0x8906, 1, 0);
    EXPECT_EQ(fb_->ERRORID.value, kGvl["PAC_LIB_ERR_INVALID_CODE"]);
}

// ---- the acknowledgements of 3.4, as printed ----

TEST_F(Rs232Cmd, ReadsTheManualsAcknowledgements) {
    ConfirmRule();
    struct Case {
        const char* bytes;
        std::uint32_t data;
        bool real;
        std::uint8_t status;
    };
    const Case cases[] = {
        {"01 02 30 3B 31 3B 31 3B 30 3B 30 3B 31 32 33 34 35 03 35 37 04", 12345, false, 1},
        {"01 02 30 3B 31 3B 31 3B 30 3B 30 3B 32 32 32 03 35 38 04", 222, false, 1},
        {"01 02 30 3B 31 3B 31 3B 30 3B 31 3B 36 34 30 2E 30 30 30 30 03 32 31 04", 0x44200000, true, 1},
        // 0603: its CHECK 8 is the XOR without ETX; taken too.
        {"01 02 30 3B 31 3B 33 31 3B 30 3B 30 3B 30 03 38 04", 0, false, 31},
        {"01 02 30 3B 31 3B 33 31 3B 30 3B 31 3B 35 35 35 32 2E 30 30 30 03 33 35 04", 0x45AD8000, true, 31},
    };
    for (const Case& c : cases) {
        Start(0x1906, 1);
        Sent();
        Reply(Hex(c.bytes));
        Cycle(1);
        EXPECT_TRUE(fb_->DONE.value) << c.bytes;
        EXPECT_EQ(fb_->ACKDATA.value, c.data) << c.bytes;
        EXPECT_EQ(fb_->ACKISREAL.value != 0, c.real) << c.bytes;
        EXPECT_EQ(fb_->OPSTATUS.value, c.status) << c.bytes;
        fb_->EXECUTE.value = FALSE;
        Cycle(1);
    }
}

TEST_F(Rs232Cmd, FollowsALongCommandWithEotPollsUntilBe1) {  // 3.4.3
    ConfirmRule();
    fb_->POLLINTERVAL.value = pac::ToIecTime(std::chrono::milliseconds(5));
    Start(0x0A87, 2, pac::test::BitsOf(5552.0F));
    Sent();
    Reply(Hex("01 02 30 3B 30 3B 33 31 3B 30 3B 31 3B 31 32 35 35 2E 30 30 30 03 33 38 04"));
    Cycle(1);
    EXPECT_TRUE(fb_->BUSY.value && fb_->ACKNOWLEDGED.value);
    EXPECT_EQ(fb_->ACKDATA.value, pac::test::BitsOf(1255.0F));
    Cycle(4);
    EXPECT_TRUE(Sent().empty()) << "no poll before PollInterval";
    Cycle(1);
    EXPECT_EQ(HexOf(Sent()), "04");
    Reply(Hex("01 02 30 3B 30 3B 33 31 3B 30 3B 31 3B 31 35 31 36 2E 39 35 30 03 34 32 04"));
    Cycle(1);
    EXPECT_EQ(fb_->ACKDATA.value, pac::test::BitsOf(1516.95F));
    Cycle(5);
    EXPECT_EQ(HexOf(Sent()), "04");
    Reply(Hex("01 02 30 3B 31 3B 33 31 3B 30 3B 31 3B 35 35 35 32 2E 30 30 30 03 33 35 04"));
    Cycle(1);
    EXPECT_TRUE(fb_->DONE.value);
    EXPECT_EQ(fb_->ACKDATA.value, pac::test::BitsOf(5552.0F));
}

TEST_F(Rs232Cmd, AReplySplitOverManyScansAfterNoise) {
    SetBytesPerScan(1);
    Start(0x1906, 2);
    Sent();
    Reply(Hex("7F 20 33 03 04"));  // noise, including control symbols, before the frame
    Reply(Frame("0;1;1;0;0;222"));
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 50, "final output"));
    EXPECT_TRUE(fb_->DONE.value);
    EXPECT_EQ(fb_->ACKDATA.value, 222u);
    EXPECT_EQ(fb_->REPEATS.value, 0);
}

TEST_F(Rs232Cmd, ACommandErrorEndsWithItsNumber) {
    Start(0x1906, 2000);
    Sent();
    Reply(Frame("38;0;1;0;0;0"));
    Cycle(1);
    EXPECT_TRUE(fb_->ERROR.value);
    EXPECT_EQ(fb_->ERRORID.value, 38u);
    EXPECT_TRUE(fb_->ACKNOWLEDGED.value);
}

TEST_F(Rs232Cmd, ACheckErrorSendsTheFrameAgainWithTheOtherXorInAuto) {
    Start(0x1906, 2000);
    EXPECT_EQ(HexOf(Sent()), HexOf(Frame("1906;2000;0;0", XorText("1906;2000;0;0"))));
    Reply(Frame("16;0;1;0;0;0"));
    Cycle(1);
    EXPECT_EQ(HexOf(Sent()), HexOf(Frame("1906;2000;0;0", XorEtx("1906;2000;0;0")))) << "the XOR with ETX in the scan after";
    Reply(Frame("16;0;1;0;0;0"));
    Cycle(1);
    EXPECT_EQ(HexOf(Sent()), HexOf(Frame("1906;2000;0;0", XorText("1906;2000;0;0")))) << "then the XOR of the text again";
    Reply(Frame("16;0;1;0;0;0"));
    Cycle(1);
    EXPECT_EQ(HexOf(Sent()), HexOf(Frame("1906;2000;0;0", XorEtx("1906;2000;0;0"))));
    Reply(Frame("0;1;1;0;0;0"));
    Cycle(1);
    EXPECT_TRUE(fb_->DONE.value);
    EXPECT_EQ(fb_->REPEATS.value, 3);
    fb_->EXECUTE.value = FALSE;
    Cycle(1);
    Start(0x0906, 3, 333);
    EXPECT_EQ(HexOf(Sent()), HexOf(Frame("0906;3;0;333", XorEtx("0906;3;0;333")))) << "the rule that worked is kept";
}

TEST_F(Rs232Cmd, AFixedRuleIsNeverChangedAndTheRetriesAreBounded) {
    fb_->CHECKRULE.value = E_PAC_RS232CHECK__PAC_RS232_CHECK_XOR_ETX;
    fb_->RETRIES.value = 2;
    Start(0x1906, 2000);
    for (int attempt = 0; attempt < 3; ++attempt) {
        EXPECT_EQ(HexOf(Sent()), HexOf(Frame("1906;2000;0;0"))) << attempt;
        Reply(Frame("16;0;1;0;0;0"));
        Cycle(1);
    }
    EXPECT_TRUE(fb_->ERROR.value);
    EXPECT_EQ(fb_->ERRORID.value, 16u);
    EXPECT_EQ(fb_->REPEATS.value, 2);
}

// A frame whose CHECK would be 0 would read as "not checked" to a controller that takes "0": PAR_1 gets a
// leading zero instead (the same number), under every rule but ZERO.
TEST_F(Rs232Cmd, AFrameWhoseCheckWouldBeZeroGetsALeadingZero) {
    ASSERT_EQ(XorText("0906;5;0;12345"), 0);
    ASSERT_EQ(XorEtx("1906;6;0;0"), 0);
    struct Case {
        E_PAC_RS232CHECK rule;
        std::uint16_t code, param;
        std::uint32_t data;
        Bytes frame;
    };
    const Case cases[] = {
        {E_PAC_RS232CHECK__PAC_RS232_CHECK_XOR_TEXT, 0x0906, 5, 12345, Command("0906;05;0;12345")},
        {E_PAC_RS232CHECK__PAC_RS232_CHECK_XOR_ETX, 0x1906, 6, 0, Frame("1906;06;0;0")},
        {E_PAC_RS232CHECK__PAC_RS232_CHECK_ZERO, 0x0906, 5, 12345, Frame("0906;5;0;12345", 0)},
    };
    for (const Case& c : cases) {
        fb_->CHECKRULE.value = c.rule;
        Start(c.code, c.param, c.data);
        const Bytes sent = Sent();
        EXPECT_EQ(HexOf(sent), HexOf(c.frame));
        EXPECT_TRUE(c.rule == E_PAC_RS232CHECK__PAC_RS232_CHECK_ZERO || CheckOf(sent) == 48 || CheckOf(sent) == 51);
        EndDone(Frame("0;1;1;0;0;0"));
    }
}

// ---- AUTO settles only on a rule a correct acknowledgement confirmed, and never on "0" ----

TEST_F(Rs232Cmd, AutoStartsWithTheRuleOfTheManualsFrames) {
    Start(0x1900, 5);  // 3.4.2, input 5: the print's CHECK 6 is the XOR of the text
    EXPECT_EQ(HexOf(Sent()), "01 02 31 39 30 30 3B 35 3B 30 3B 30 03 36 04");
}

TEST_F(Rs232Cmd, AutoNeverSendsZeroOnItsOwn) {
    // The XOR of this text is 0: its frame goes with PAR_1 05 and both XORs of that (48, 51) in turn, never 0.
    const std::string text = "1906;5;0;0";
    ASSERT_EQ(XorText(text), 0);
    fb_->RETRIES.value = 5;
    Start(0x1906, 5);
    std::vector<int> checks;
    for (int attempt = 0; attempt < 6; ++attempt) {
        const Bytes sent = Sent();
        EXPECT_TRUE(HexOf(sent) == HexOf(Command("1906;05;0;0")) || HexOf(sent) == HexOf(Frame("1906;05;0;0")))
            << HexOf(sent);
        checks.push_back(CheckOf(sent));
        Reply(Frame("16;0;1;0;0;0"));
        Cycle(1);
    }
    EXPECT_NE(std::find(checks.begin(), checks.end(), 48), checks.end()) << "both XORs tried";
    EXPECT_NE(std::find(checks.begin(), checks.end(), 51), checks.end()) << "both XORs tried";
    EXPECT_TRUE(fb_->ERROR.value);
    EXPECT_EQ(fb_->ERRORID.value, 16u);
}

// Before a rule is confirmed a command that must not run twice waits for the probe: a controller that ignores
// the probe's CHECK is never polled with EOT (it would repeat a reply from before), and the command's frame
// goes out once, with the rule the probe's reply confirmed, in the scan after that reply.
TEST_F(Rs232Cmd, ACommandThatMustNotRunTwiceWaitsForTheProbe) {
    fb_->TIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(100));
    Start(0x0603, 0);
    EXPECT_EQ(HexOf(Sent()), HexOf(Command("190B;0;0;0"))) << "the probe, with the XOR of the text";
    ASSERT_TRUE(RunUntil([&] { return !sent_.empty(); }, 400, "the probe again"));
    EXPECT_EQ(HexOf(Sent()), HexOf(Frame("190B;0;0;0"))) << "silence: the probe with the XOR with ETX, no EOT";
    Reply(Frame("0;1;1;0;0;1"));
    Cycle(1);
    EXPECT_TRUE(fb_->BUSY.value && !fb_->ACKNOWLEDGED.value) << "the probe's reply is not the command's";
    EXPECT_EQ(HexOf(Sent()), HexOf(Frame("0603;0;0;0"))) << "the command, with the rule confirmed";
    EndDone(Frame("0;1;31;0;0;0"));
    EXPECT_EQ(fb_->REPEATS.value, 1);
    Start(0x0909, 0);
    EXPECT_EQ(HexOf(Sent()), HexOf(Frame("0909;0;0;0"))) << "no probe once a rule is confirmed";
}

// The case: a short outage while the first command runs. Silence before any acknowledgement may mean
// a controller that ignores a wrong CHECK, so AUTO tries the other XOR; it never goes on to "0", and the rule
// the first acknowledgement confirms is the one kept.
TEST_F(Rs232Cmd, AnOutageBeforeTheFirstReplyNeverSettlesOnZero) {
    fb_->TIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(100));
    Start(0x0906, 3, static_cast<std::uint32_t>(-333));
    const std::string text = "0906;3;0;-333";
    std::vector<int> checks{CheckOf(Sent())};
    for (int outage = 0; outage < 2; ++outage) {
        ASSERT_TRUE(RunUntil([&] { return !sent_.empty(); }, 400, "the frame again"));
        checks.push_back(CheckOf(Sent()));
    }
    EndDone(Frame("0;1;1;0;0;-333"));  // the line is back: the third frame is answered
    for (int check : checks) EXPECT_TRUE(check == XorText(text) || check == XorEtx(text)) << "CHECK " << check;
    Start(0x1906, 3);
    EXPECT_EQ(CheckOf(Sent()), checks.back() == XorText(text) ? XorText("1906;3;0;0") : XorEtx("1906;3;0;0"))
        << "the rule of the frame that was acknowledged";
}

TEST_F(Rs232Cmd, AConfirmedRuleIsKeptThroughCheckErrors) {
    Start(0x1906, 2);
    const Bytes first = Sent();
    EndDone(Frame("0;1;1;0;0;222"));
    Start(0x1906, 2);
    for (int attempt = 0; attempt < 3; ++attempt) {
        EXPECT_EQ(HexOf(Sent()), HexOf(first)) << "attempt " << attempt << ": a spoilt byte changes no rule";
        Reply(Frame("16;0;1;0;0;0"));
        Cycle(1);
    }
    EXPECT_EQ(HexOf(Sent()), HexOf(first));
    Reply(Frame("0;1;1;0;0;222"));
    Cycle(1);
    EXPECT_TRUE(fb_->DONE.value);
    EXPECT_EQ(fb_->REPEATS.value, 3);
}

// A reply that comes after Timeout, while the FB waits for the line to fall quiet, acknowledges the frame
// sent before the silence: its rule is the one confirmed, not the one AUTO had moved on to meanwhile.
TEST_F(Rs232Cmd, ALateReplyConfirmsTheRuleOfTheFrameItAnswers) {
    fb_->TIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(20));
    Start(0x1906, 2);
    const int sentCheck = CheckOf(Sent());
    Reply(Hex("55"));  // a byte just after the request: the line is not quiet for QuietTime when Timeout ends
    Cycle(30);
    ASSERT_TRUE(Sent().empty()) << "waiting for a quiet line";
    EndDone(Frame("0;1;1;0;0;222"));
    Start(0x1906, 2);
    EXPECT_EQ(CheckOf(Sent()), sentCheck);
}

TEST_F(Rs232Cmd, AReplyWithCheckZeroCountsOnlyWhenTheProgrammerChoseZero) {
    Start(0x1906, 2);
    Sent();
    Reply(Frame("0;1;1;0;0;222", 0));
    Cycle(1);
    EXPECT_FALSE(fb_->ACKNOWLEDGED.value) << "an unchecked reply in AUTO";
    ASSERT_TRUE(RunUntil([&] { return !sent_.empty(); }, 200, "the frame again"));
    Sent();
    EndDone(Frame("0;1;1;0;0;222"));
    fb_->CHECKRULE.value = E_PAC_RS232CHECK__PAC_RS232_CHECK_ZERO;
    Start(0x1906, 2);
    EXPECT_EQ(CheckOf(Sent()), 0);
    Reply(Frame("0;1;1;0;0;222", 0));
    Cycle(1);
    EXPECT_TRUE(fb_->DONE.value);
}

// ---- REALs are sent exactly or not at all ----

TEST_F(Rs232Cmd, ARealIsSentExactlyOrRefused) {
    Start(0x0907, 1, pac::test::BitsOf(0.00004F));
    EXPECT_EQ(HexOf(Sent()), HexOf(Command("0907;1;1;0.00004")));
    fb_->EXECUTE.value = FALSE;
    Reply(Frame("0;1;1;0;1;0.0000"));
    Cycle(3);
    Start(0x0907, 1, pac::test::BitsOf(1.234567E-7F));  // needs more than 9 decimals
    EXPECT_TRUE(fb_->ERROR.value);
    EXPECT_EQ(fb_->ERRORID.value, kGvl["PAC_LIB_ERR_SERIAL_DATA"]);
    EXPECT_TRUE(Sent().empty());
}

// 5.2.6.13 sends 0A93 with the data 0; 3.3: "if a data field has no function, enter a 0".
TEST_F(Rs232Cmd, ACommandWithoutDataSendsZero) {
    ConfirmRule();
    Start(0x0A93, 4);
    EXPECT_EQ(HexOf(Sent()), HexOf(Command("0A93;4;1;0")));
}

// A damaged reply: a read is sent again, a command that must not run twice is asked for its
// acknowledgement with EOT; either only once the line has been quiet for QuietTime.
TEST_F(Rs232Cmd, ADamagedReplyToAReadSendsItAgainOnceTheLineIsQuiet) {
    Start(0x1906, 2);
    Sent();
    Bytes damaged = Frame("0;1;1;0;0;222");
    damaged[13] = '3';  // the CHECK no longer fits
    Reply(damaged);
    Cycle(1);
    EXPECT_TRUE(fb_->BUSY.value);
    ASSERT_TRUE(RunUntil([&] { return !sent_.empty(); }, 100, "the frame again"));
    EXPECT_EQ(HexOf(Sent()), HexOf(Command("1906;2;0;0")));
    EXPECT_GE(task_.ScanCount(), 2 + 50) << "QuietTime T#50MS after the last byte";
    Reply(Frame("0;1;1;0;0;222"));
    Cycle(1);
    EXPECT_TRUE(fb_->DONE.value);
    EXPECT_EQ(fb_->REPEATS.value, 1);
}

TEST_F(Rs232Cmd, AFrameCutOffByTheNextIsDroppedForIt) {
    ConfirmRule();
    Start(0x0A89, 1, pac::test::BitsOf(10.0F));
    Sent();
    Bytes cut = Frame("0;0;31;0;1;0.000");
    cut.resize(8);
    Reply(cut);
    Reply(Frame("0;0;31;0;1;2.500"));  // a new STX cuts it off; the whole frame after it is the reply
    Cycle(1);
    EXPECT_TRUE(fb_->ACKNOWLEDGED.value) << "the first whole frame counts";
    EXPECT_EQ(fb_->ACKDATA.value, pac::test::BitsOf(2.5F));
    EXPECT_EQ(fb_->REPEATS.value, 0);
}

TEST_F(Rs232Cmd, ALostReplyToARelativeMoveIsAskedForWithEot) {
    ConfirmRule();
    Start(0x0A89, 1, pac::test::BitsOf(10.0F));
    Sent();
    Reply(Hex("01 02 30 3B 30 3B"));  // then nothing
    ASSERT_TRUE(RunUntil([&] { return !sent_.empty(); }, 2000, "a request again"));
    EXPECT_EQ(HexOf(Sent()), "04") << "an EOT poll, not the move again";
    Reply(Frame("0;1;31;0;1;10.000"));
    Cycle(1);
    EXPECT_TRUE(fb_->DONE.value);
}

TEST_F(Rs232Cmd, ASilentControllerEndsInTimeoutAfterTheRetries) {
    fb_->TIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(100));
    fb_->RETRIES.value = 2;
    const auto before = task_.ScanCount();
    Start(0x1906, 2);
    int frames = 0;
    ASSERT_TRUE(RunUntil([&] {
        for (std::uint8_t b : Sent()) frames += b == 0x01 ? 1 : 0;
        return Final();
    }, 2000, "final output"));
    EXPECT_TRUE(fb_->ERROR.value);
    EXPECT_EQ(fb_->ERRORID.value, kGvl["PAC_LIB_ERR_ACK_TIMEOUT"]);
    EXPECT_EQ(frames, 3) << "the frame and two retries";
    // Each attempt waits Timeout for its reply; a request without a byte of reply then Timeout more for a
    // late one (a controller slower than Timeout) before the next goes, in the scan after; the last ends at
    // once.
    EXPECT_EQ(task_.ScanCount() - before, 3 * (100 + 1) + 2 * 100);
}

TEST_F(Rs232Cmd, NoiseThatNeverStopsEndsTheCommand) {
    fb_->TIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(100));
    Start(0x1906, 2);
    Sent();
    SetBytesPerScan(1);
    Reply(Bytes(2000, 0x55));
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 1000, "final output"));
    EXPECT_EQ(fb_->ERRORID.value, kGvl["PAC_LIB_ERR_SERIAL_REPLY"]);
}

TEST_F(Rs232Cmd, AFullTransmitBufferEndsInItsError) {
    fb_->TIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(20));
    fb_->TXBUFFER.value.BLOCKED = TRUE;  // a driver that never lets go of the buffer
    Start(0x1906, 2);
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 100, "final output"));
    EXPECT_EQ(fb_->ERRORID.value, kGvl["PAC_LIB_ERR_SERIAL_BUFFER"]);
}

TEST_F(Rs232Cmd, StaleBytesNeverPassForTheReply) {
    ConfirmRule();  // not a fresh instance: that one waits for a quiet line before its first request
    Reply(Frame("0;1;1;0;0;999"));  // a reply nobody waits for
    Cycle(2);
    Start(0x1906, 2);
    Cycle(5);
    EXPECT_TRUE(fb_->BUSY.value);
    Reply(Frame("0;1;1;0;0;222"));
    Cycle(1);
    EXPECT_EQ(fb_->ACKDATA.value, 222u);
}

// A long command whose end never comes: EndTimeout counts from the first acknowledgement through the polls.
TEST_F(Rs232Cmd, ALongCommandThatNeverEndsEndsInEndTimeout) {
    ConfirmRule();
    fb_->POLLINTERVAL.value = pac::ToIecTime(std::chrono::milliseconds(5));
    fb_->ENDTIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(40));
    Start(0x0A87, 2, pac::test::BitsOf(5552.0F));
    Sent();
    Reply(Frame("0;0;31;0;1;1255.000"));
    Cycle(1);
    ASSERT_TRUE(fb_->BUSY.value && fb_->ACKNOWLEDGED.value);
    const auto acknowledged = task_.ScanCount();
    int polls = 0;
    ASSERT_TRUE(RunUntil([&] {
        if (!Sent().empty()) {
            ++polls;
            Reply(Frame("0;0;31;0;1;1300.000"));  // still moving
        }
        return Final();
    }, 200, "final output"));
    EXPECT_TRUE(fb_->ERROR.value);
    EXPECT_EQ(fb_->ERRORID.value, kGvl["PAC_LIB_ERR_END_TIMEOUT"]);
    EXPECT_EQ(task_.ScanCount() - acknowledged, 40) << "EndTimeout after the acknowledgement, at 1 ms scans";
    EXPECT_GE(polls, 5) << "polled every PollInterval meanwhile";
}

// After a command that failed on a silent line, bytes still arrive (its late, spoilt reply). The next command
// waits until the line has been quiet for QuietTime, so none of them can pass for its reply; and since the
// failed request had no byte of reply within its Timeout, for the new command's Timeout as well (a controller
// slower than Timeout may still be answering it).
TEST_F(Rs232Cmd, AfterAFailedCommandTheNextWaitsForAQuietLine) {
    fb_->TIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(20));
    fb_->RETRIES.value = 0;
    Start(0x1906, 2);
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 100, "final output"));
    ASSERT_EQ(fb_->ERRORID.value, kGvl["PAC_LIB_ERR_ACK_TIMEOUT"]);
    fb_->EXECUTE.value = FALSE;
    fb_->TIMEOUT.value = pac::ToIecTime(std::chrono::seconds(1));  // longer than the noise lasts
    Cycle(1);
    Sent();
    SetBytesPerScan(1);
    Reply(Bytes(30, 0x55));
    Start(0x1906, 3);
    const std::int64_t edge = task_.ScanCount();
    EXPECT_TRUE(Sent().empty()) << "not into a busy line";
    std::int64_t lastByte = task_.ScanCount();
    int scans = 0;
    while (sent_.empty() && scans++ < 1100) {
        const bool arriving = !incoming_.empty();
        Cycle(1);
        if (arriving) lastByte = task_.ScanCount();
    }
    ASSERT_FALSE(sent_.empty());
    const Bytes frame = Sent();
    ASSERT_GE(frame.size(), 12u);
    EXPECT_EQ(std::string(frame.begin() + 2, frame.begin() + 12), "1906;3;0;0") << "the new command (its CHECK rule: AUTO's)";
    EXPECT_GE(task_.ScanCount() - lastByte, 50) << "QuietTime T#50MS after the last byte, at 1 ms scans";
    EXPECT_EQ(task_.ScanCount() - edge, 1000) << "Timeout T#1S after the edge";
}

// A noise burst that looks like the start of a frame spoils the first reply; the controller's reply after it
// is still taken while the FB waits for the line to fall quiet, and a relative move is not asked for again.
TEST_F(Rs232Cmd, AReplyAfterANoiseBurstIsTakenWhileTheLineFallsQuiet) {
    ConfirmRule();
    Start(0x0A89, 1, pac::test::BitsOf(10.0F));
    Sent();
    Reply(Hex("02 41 02 42 03 33 41"));  // STX, text, STX again, text, ETX, then a letter among the CHECK digits
    Cycle(1);
    ASSERT_TRUE(fb_->BUSY.value);
    ASSERT_FALSE(fb_->ACKNOWLEDGED.value);
    Cycle(3);
    Reply(Frame("0;1;31;0;1;10.000"));
    Cycle(1);
    EXPECT_TRUE(fb_->DONE.value);
    EXPECT_EQ(fb_->ACKDATA.value, pac::test::BitsOf(10.0F));
    EXPECT_TRUE(Sent().empty()) << "neither the move again nor a poll";
}

}  // namespace
}  // namespace test_fb_pac_rs232_cmd
