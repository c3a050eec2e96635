// FB_PAC_Rs232Cmd against the simulated PA-CONTROL's RS232 port, scan by scan, through a PLC serial driver
// that moves the bytes between the FB's ring buffers and the line: baud rates of 1200 to 38400 with PLC
// cycles of 1 to 10 ms, the exact scan of Done from the line's timing, long commands with EOT polls, every
// reading of chapter 3 the simulator can be set to, and a faulty line (dropped, corrupted, delayed bytes,
// noise) recovered. The PLCopen checker runs on every scan.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/serial_rig.hpp"
#include "pac/sim/rs232_frame.hpp"
#include "pac/st_program.hpp"
#include "plcopen_checker.hpp"
#include "plcopen_pins.hpp"
#include "real_bits.hpp"
#include "rs232_case.hpp"
#include "run_to_final.hpp"

namespace test_fb_pac_rs232_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using std::chrono::nanoseconds;
using pac::test::BitsOf;
using pac::test::FinalOutcome;

const pac::test::GvlConstants kGvl;

struct SerialTiming {
    int baud = 9600;
    int plcMs = 1;
    int pacMs = 10;
};

std::ostream& operator<<(std::ostream& out, const SerialTiming& t) {
    return out << t.baud << " baud, PLC " << t.plcMs << " ms, PA-CONTROL " << t.pacMs << " ms";
}

pac::sim::PaControlConfig OnlineReady() {
    pac::sim::PaControlConfig config;
    config.modes.requireExternalStop = false;
    return config;
}

// One FB_PAC_Rs232Cmd on the serial line of a simulated PA-CONTROL.
class SerialCmdPlc {
public:
    explicit SerialCmdPlc(const SerialTiming& t, pac::sim::SerialPortConfig port = {},
                          pac::sim::PaControlConfig config = OnlineReady())
        : rig_(Timing(t), config, port), checker_("FB_PAC_Rs232Cmd") {
        rig_.Call(cmd_);
        rig_.Task().AddProgram([this] { checker_.Check(rig_.Task().ScanCount(), cmd_, BusyBound()); });
    }
    ~SerialCmdPlc() { EXPECT_EQ(checker_.Violations(), 0); }

    FinalOutcome Run(std::uint16_t code, std::uint16_t param, std::uint32_t data = 0, int maxScans = 60000) {
        cmd_->CODE.value = code;
        cmd_->PARAM.value = param;
        cmd_->DATA.value = data;
        cmd_->EXECUTE.value = TRUE;
        rig_.Scan();
        edgeTime_ = rig_.Now();
        const FinalOutcome outcome = pac::test::RunToFinal(cmd_, rig_.Task().ScanCount(), [&] {
            rig_.Scan();
            return rig_.Task().ScanCount();
        }, maxScans);
        ackData_ = cmd_->ACKDATA.value;
        repeats_ = cmd_->REPEATS.value;
        cmd_->EXECUTE.value = FALSE;
        rig_.Scan();
        return outcome;
    }

    // The scans from the edge to the reply on a clean line: the request of `requestBytes` goes out at the
    // end of the edge scan, the controller's first cycle after its last byte answers with `replyBytes`,
    // and the first scan after the reply's last byte reads it.
    int ReplyScans(int requestBytes, int replyBytes) const {
        const nanoseconds character = rig_.Timing().format.CharacterTime();
        const nanoseconds pacCycle = rig_.Timing().pacCycle;
        const nanoseconds requestEnd = edgeTime_ + requestBytes * character;
        nanoseconds cycle = ((requestEnd + pacCycle - 1ns) / pacCycle) * pacCycle;
        const nanoseconds replyEnd = cycle + replyBytes * character;
        const nanoseconds plc = rig_.Timing().plcCycle;
        return static_cast<int>((replyEnd - edgeTime_ + plc - 1ns) / plc);
    }

    std::optional<int> BusyBound() const {
        // Every request: its Timeout, a scan, at most a QuietTime and Timeout of waiting for quiet and room;
        // Retries + 1 requests before the acknowledgement, then EndTimeout.
        const nanoseconds plc = rig_.Timing().plcCycle;
        auto scans = [&](nanoseconds t) { return static_cast<int>((t + plc - 1ns) / plc); };
        const int request = 3 * scans(pac::FromIecTime(cmd_->TIMEOUT.value)) + 3;
        return (cmd_->RETRIES.value + 1) * request + scans(pac::FromIecTime(cmd_->ENDTIMEOUT.value)) + 2;
    }

    // A PLC restart: a fresh FB (no CHECK rule confirmed, empty buffers) on a controller that keeps its
    // state and its last reply.
    void Restart() {
        cmd_ = PAC_FB(FB_PAC_RS232CMD);
        checker_.Restart();
    }

    pac::FbInstance<FB_PAC_RS232CMD>& Cmd() { return cmd_; }
    pac::SerialRig& Rig() { return rig_; }
    pac::sim::PaControl& Pac() { return rig_.Controller(); }
    // The time of the last Run's edge scan.
    nanoseconds EdgeTime() const { return edgeTime_; }
    std::uint32_t AckData() const { return ackData_; }
    int Repeats() const { return repeats_; }

private:
    static pac::SerialRigTiming Timing(const SerialTiming& t) {
        return pac::test::Rs232RigTiming(pac::test::Rs232Case{t.baud, t.plcMs, t.pacMs});
    }

    pac::FbInstance<FB_PAC_RS232CMD> cmd_ = PAC_FB(FB_PAC_RS232CMD);
    pac::SerialRig rig_;
    pac::test::PlcOpenChecker checker_;
    nanoseconds edgeTime_{0};
    std::uint32_t ackData_ = 0;
    int repeats_ = 0;
};

// The bytes of a command frame as AUTO first writes it (the XOR of the text), and of a reply as the
// simulator writes it by default (the XOR with ETX).
int RequestBytes(const std::string& text) {
    return static_cast<int>(pac::sim::rs232::Frame(text, pac::sim::rs232::CheckRule::kXorText).size());
}
int ReplyBytes(const std::string& text) {
    return static_cast<int>(pac::sim::rs232::Frame(text, pac::sim::rs232::CheckRule::kXorWithEtx).size());
}

class Rs232Timing : public ::testing::TestWithParam<SerialTiming> {};

TEST_P(Rs232Timing, WriteAndReadRegistersAtTheLinesPace) {
    SerialCmdPlc plc(GetParam());
    // Called idle for QuietTime since the PLC started: the fresh instance's first request goes at its edge.
    plc.Rig().Scan(50 / GetParam().plcMs + 1);
    const FinalOutcome write = plc.Run(0x0906, 3, static_cast<std::uint32_t>(-333));
    ASSERT_TRUE(write.Done()) << write;
    EXPECT_EQ(write.Scans(), plc.ReplyScans(RequestBytes("0906;3;0;-333"), ReplyBytes("0;1;1;0;0;-333")));
    EXPECT_EQ(plc.Pac().Io().intRegisters.GetInt(3), -333);

    const FinalOutcome read = plc.Run(0x1906, 3);
    ASSERT_TRUE(read.Done()) << read;
    EXPECT_EQ(read.Scans(), plc.ReplyScans(RequestBytes("1906;3;0;0"), ReplyBytes("0;1;1;0;0;-333")));
    EXPECT_EQ(plc.AckData(), static_cast<std::uint32_t>(-333));

    ASSERT_TRUE(plc.Run(0x0907, 1, BitsOf(640.5F)).Done());
    const FinalOutcome real = plc.Run(0x1907, 1);
    ASSERT_TRUE(real.Done()) << real;
    EXPECT_EQ(plc.AckData(), BitsOf(640.5F));
    EXPECT_TRUE(plc.Cmd()->ACKISREAL.value);
    EXPECT_EQ(plc.Pac().Serial().Counters().commands, 4u) << "each command exactly once";
    EXPECT_EQ(plc.Repeats(), 0);
}

TEST_P(Rs232Timing, StartOnlineAndMoveWithPolls) {
    SerialCmdPlc plc(GetParam());
    ASSERT_TRUE(plc.Run(0x0603, 0).Done());
    EXPECT_EQ(plc.Cmd()->OPSTATUS.value, 31);
    const FinalOutcome move = plc.Run(0x0A87, 1, BitsOf(100.0F));
    ASSERT_TRUE(move.Done()) << move;
    EXPECT_EQ(plc.AckData(), BitsOf(100.0F));
    EXPECT_EQ(plc.Pac().Axes().Motion(1).Position(), 100.0);
    EXPECT_GE(plc.Pac().Serial().Counters().polls, 1u);
    // 100 AE take 200 ms (docs/sim_axis.md): Done no earlier.
    EXPECT_GE(move.Scans() * GetParam().plcMs, 200);
}

// The lines of the RS232 suites: 1200 to 38400 baud, PLC cycles of 1 to 10 ms, controller cycles of 1 to 10 ms.
const auto kLines = ::testing::Values(SerialTiming{1200, 1, 10}, SerialTiming{1200, 10, 10}, SerialTiming{9600, 1, 10},
                                      SerialTiming{9600, 2, 3}, SerialTiming{9600, 5, 10}, SerialTiming{19200, 1, 1},
                                      SerialTiming{19200, 10, 7}, SerialTiming{38400, 2, 10});

std::string LineName(const ::testing::TestParamInfo<SerialTiming>& info) {
    return std::to_string(info.param.baud) + "baud_plc" + std::to_string(info.param.plcMs) + "ms_pac" +
           std::to_string(info.param.pacMs) + "ms";
}

INSTANTIATE_TEST_SUITE_P(Lines, Rs232Timing, kLines, LineName);

// ---- the readings of chapter 3 (docs/open_points.md) ----

TEST(Rs232Readings, EveryCheckRuleTheControllerMayVerify) {
    struct Case {
        pac::sim::CheckVerification verify;
        bool acceptZero;
        bool answerBadCheck;
        int repeats;  // of the first command, in AUTO
    };
    const Case cases[] = {
        {pac::sim::CheckVerification::kXorText, true, true, 0},
        {pac::sim::CheckVerification::kXorWithEtx, false, true, 1},
        {pac::sim::CheckVerification::kXorWithEtx, true, false, 1},
        {pac::sim::CheckVerification::kNone, true, true, 0},
    };
    for (const Case& c : cases) {
        pac::sim::SerialPortConfig port;
        port.verify = c.verify;
        port.acceptZeroCheck = c.acceptZero;
        port.answerBadCheck = c.answerBadCheck;
        SerialCmdPlc plc({}, port);
        ASSERT_TRUE(plc.Run(0x0906, 1, 11).Done()) << static_cast<int>(c.verify);
        EXPECT_EQ(plc.Repeats(), c.repeats) << static_cast<int>(c.verify);
        ASSERT_TRUE(plc.Run(0x0906, 2, 22).Done());
        EXPECT_EQ(plc.Repeats(), 0) << "the rule that worked is kept";
        EXPECT_EQ(plc.Pac().Io().intRegisters.GetInt(2), 22);
    }
}

// The case on the default controller: the first two requests are lost in an outage (the probe: the
// CHECK of 1906;4 is 1, one spoilt bit from "0"). AUTO tries the other XOR on the silence, never "0"; so a
// request spoilt later (5552.0 -> 5553.0) is refused with 16 and sent again, never carried out.
TEST(Rs232Readings, AnOutageAtTheStartNeverLeavesTheLinkUnchecked) {
    SerialCmdPlc plc(SerialTiming{9600, 1, 10});
    plc.Cmd()->TIMEOUT.value = pac::ToIecTime(100ms);
    plc.Pac().Io().intRegisters.SetInt(4, 4444);
    pac::sim::SerialWire& toPac = plc.Rig().Line().toPac;
    const int request = RequestBytes("190B;0;0;0");
    ASSERT_EQ(request, static_cast<int>(pac::sim::rs232::Frame("190B;0;0;0", pac::sim::rs232::CheckRule::kXorWithEtx).size()));
    for (int i = 0; i < 2 * request; ++i) toPac.DropByte(toPac.BytesSent() + static_cast<std::uint64_t>(i));
    const FinalOutcome read = plc.Run(0x1906, 4);
    ASSERT_TRUE(read.Done()) << read;
    EXPECT_EQ(plc.AckData(), 4444u);
    EXPECT_EQ(plc.Repeats(), 2);

    toPac.CorruptByte(toPac.BytesSent() + 14, 0x01);  // the '2' of 5552.0 becomes '3'
    const FinalOutcome write = plc.Run(0x0907, 1, BitsOf(5552.0F));
    ASSERT_TRUE(write.Done()) << write;
    EXPECT_EQ(plc.Repeats(), 1);
    EXPECT_EQ(plc.Pac().Serial().Counters().checkErrors, 1u);
    EXPECT_EQ(plc.Pac().Io().realRegisters.GetReal(1), 5552.0F);
}

// What the default FB sends, the default controller takes: no command is refused on a clean line.
TEST(Rs232Readings, TheDefaultsAgree) {
    SerialCmdPlc plc(SerialTiming{9600, 1, 10});
    ASSERT_TRUE(plc.Run(0x0906, 3, 333).Done());
    EXPECT_EQ(plc.Repeats(), 0);
    ASSERT_TRUE(plc.Run(0x0907, 1, BitsOf(0.00004F)).Done());
    EXPECT_EQ(plc.Pac().Io().realRegisters.GetReal(1), 0.00004F) << "sent exactly";
    EXPECT_EQ(plc.Pac().Serial().Counters().checkErrors, 0u);
}

TEST(Rs232Readings, EveryCheckRuleOfTheReplies) {
    for (auto rule : {pac::sim::rs232::CheckRule::kXorWithEtx, pac::sim::rs232::CheckRule::kXorText,
                      pac::sim::rs232::CheckRule::kZero}) {
        pac::sim::SerialPortConfig port;
        port.replyCheck = rule;
        SerialCmdPlc plc({}, port);
        if (rule == pac::sim::rs232::CheckRule::kZero) {
            // An unchecked reply counts only where the programmer chose no checksum.
            plc.Cmd()->CHECKRULE.value = E_PAC_RS232CHECK__PAC_RS232_CHECK_ZERO;
        }
        ASSERT_TRUE(plc.Run(0x190B, 0).Done());
        EXPECT_EQ(plc.AckData(), 1u);
    }
}

TEST(Rs232Readings, ModeRepliesAtOnceOrHeldAndPollsWhenIdleOrNot) {
    for (bool hold : {true, false}) {
        for (bool idlePolls : {true, false}) {
            pac::sim::SerialPortConfig port;
            port.holdModeReplies = hold;
            port.answerPollWhenIdle = idlePolls;
            port.requireSoh = !hold;
            port.refuseTypeMismatch = idlePolls;
            SerialCmdPlc plc({}, port);
            ASSERT_TRUE(plc.Run(0x0603, 0).Done()) << hold << idlePolls;
            EXPECT_EQ(plc.Cmd()->OPSTATUS.value, 31);
            ASSERT_TRUE(plc.Run(0x0A8D, 1, BitsOf(500.0F)).Done());
            const FinalOutcome move = plc.Run(0x0A89, 1, BitsOf(20.0F));
            ASSERT_TRUE(move.Done()) << hold << idlePolls << ": " << move;
            EXPECT_EQ(plc.Pac().Axes().Motion(1).Position(), 20.0);
        }
    }
}

TEST(Rs232Readings, ASilentControllerEndsInTimeout) {
    pac::sim::SerialPortConfig port;
    port.answers = false;
    SerialCmdPlc plc({}, port);
    plc.Cmd()->TIMEOUT.value = pac::ToIecTime(200ms);
    const FinalOutcome outcome = plc.Run(0x1906, 1);
    EXPECT_TRUE(outcome.Error());
    EXPECT_EQ(outcome.ErrorId(), kGvl["PAC_LIB_ERR_ACK_TIMEOUT"]);
    EXPECT_EQ(plc.Pac().Serial().Counters().frames, 4u) << "the frame and Retries = 3 more";
}

// ---- a command that must not run twice, and the CHECK rule not yet confirmed ----

// Every reading of the CHECK a controller may have (docs/sim_serial.md): which rule it verifies, whether it
// takes "0", and what it does with a frame whose CHECK it refuses (16; silence with 16 as its last reply;
// silence as if the frame never came, so an EOT repeats the reply before it).
struct CheckReading {
    std::string name;
    pac::sim::SerialPortConfig port;
};

std::vector<CheckReading> CheckReadings() {
    using pac::sim::CheckVerification;
    std::vector<CheckReading> readings;
    for (CheckVerification verify : {CheckVerification::kXorText, CheckVerification::kXorWithEtx}) {
        for (bool zero : {true, false}) {
            for (int bad = 0; bad < 3; ++bad) {
                pac::sim::SerialPortConfig port;
                port.verify = verify;
                port.acceptZeroCheck = zero;
                port.answerBadCheck = bad == 0;
                port.discardBadCheckFrame = bad == 2;
                readings.push_back({std::string(verify == CheckVerification::kXorText ? "xor-text" : "xor-etx") +
                                        (zero ? " or 0" : "") + (bad == 0 ? ", 16" : bad == 1 ? ", silent" : ", discards"),
                                    port});
            }
        }
    }
    pac::sim::SerialPortConfig none;
    none.verify = CheckVerification::kNone;
    readings.push_back({"no check", none});
    // The discarding controller with the other readings the suites use: mode replies at once, no answer
    // to a poll after BE = 1, STX alone.
    pac::sim::SerialPortConfig discards;
    discards.verify = CheckVerification::kXorWithEtx;
    discards.answerBadCheck = false;
    discards.discardBadCheckFrame = true;
    discards.holdModeReplies = false;
    discards.requireSoh = false;
    readings.push_back({"xor-etx or 0, discards, mode replies at once", discards});
    discards.holdModeReplies = true;
    discards.answerPollWhenIdle = false;
    readings.push_back({"xor-etx or 0, discards, no idle poll reply", discards});
    return readings;
}

// How often the controller carried out exactly this command (without a command error) since entry `from`
// of its ledger, and how often anything else that is not a read.
struct Executions {
    int exact = 0;
    int other = 0;
};

Executions ExecutionsOf(const pac::sim::SerialPort& port, std::size_t from, std::uint16_t code, std::uint16_t param,
                        std::uint32_t data) {
    Executions e;
    const auto& commands = port.Commands();
    for (std::size_t i = from; i < commands.size(); ++i) {
        const pac::sim::SerialCommand& c = commands[i];
        if (c.error != 0) continue;
        if (c.code == code && c.parameter == param && (c.data == data || !pac::sim::rs232::TakesData(code))) {
            ++e.exact;
        } else if (c.code < 0x1000 || c.code > 0x1FFF) {
            ++e.other;
        }
    }
    return e;
}

struct OnceCommand {
    std::uint16_t code;
    std::uint16_t param;
    std::uint32_t data;
};

// After a PLC restart no CHECK rule is confirmed. The controller still holds its last reply (QUIT 0, BE 1). A
// command that must not run twice (0603, 0909, 0A89) and one that may (0906) are each carried out exactly once
// and Done on every reading; a controller that discards a frame with the other rule's CHECK and answers the
// EOT after it with that old reply must not end the new command Done.
TEST(Rs232Readings, AfterAPlcRestartEachCommandRunsExactlyOnce) {
    const OnceCommand commands[] = {
        {0x0603, 0, 0}, {0x0909, 0, 0}, {0x0A89, 1, BitsOf(20.0F)}, {0x0906, 5, 555}};
    for (const CheckReading& reading : CheckReadings()) {
        for (const OnceCommand& c : commands) {
            SCOPED_TRACE(reading.name + ", command " + std::to_string(c.code));
            SerialCmdPlc plc(SerialTiming{9600, 1, 10}, reading.port);
            plc.Cmd()->TIMEOUT.value = pac::ToIecTime(100ms);
            if (c.code == 0x0A89) {
                ASSERT_TRUE(plc.Run(0x0603, 0).Done());
                ASSERT_TRUE(plc.Run(0x0A8D, 1, BitsOf(500.0F)).Done());
            } else {
                ASSERT_TRUE(plc.Run(0x1906, 4).Done());
            }
            plc.Restart();
            plc.Cmd()->TIMEOUT.value = pac::ToIecTime(100ms);
            const std::size_t before = plc.Pac().Serial().Commands().size();
            const FinalOutcome outcome = plc.Run(c.code, c.param, c.data);
            const Executions runs = ExecutionsOf(plc.Pac().Serial(), before, c.code, c.param, c.data);
            EXPECT_EQ(runs.exact, 1) << outcome;
            EXPECT_EQ(runs.other, 0);
            EXPECT_TRUE(outcome.Done()) << outcome;
            if (c.code == 0x0603) {
                EXPECT_EQ(plc.Pac().OperatingStatus(), 31);
            } else if (c.code == 0x0A89) {
                EXPECT_EQ(plc.Pac().Axes().Motion(1).Position(), 20.0);
            } else if (c.code == 0x0906) {
                EXPECT_EQ(plc.AckData(), 555u);
            }
        }
    }
}

// Every single-bit flip of every byte the FB sends for command `c`, each on a fresh FB (no rule confirmed):
// the command is never carried out as another command or value, never twice, and it is Done only if it ran
// exactly once, with its own answer. The next command on the same FB then runs as usual. Returns the flips.
int FlipEveryBitOfTheRequests(const pac::sim::SerialPortConfig& port, const OnceCommand& c) {
    // The clean run: the bytes the FB sends, and the command's own answer.
    std::uint64_t sent = 0;
    std::uint32_t ack = 0;
    {
        SerialCmdPlc plc(SerialTiming{9600, 1, 10}, port);
        plc.Cmd()->TIMEOUT.value = pac::ToIecTime(100ms);
        EXPECT_TRUE(plc.Run(c.code, c.param, c.data).Done());
        sent = plc.Rig().Line().toPac.BytesSent();
        ack = plc.AckData();
    }
    int flips = 0;
    for (std::uint64_t byte = 0; byte < sent; ++byte) {
        for (int bit = 0; bit < 7; ++bit) {
            SCOPED_TRACE("byte " + std::to_string(byte) + ", bit " + std::to_string(bit));
            ++flips;
            SerialCmdPlc plc(SerialTiming{9600, 1, 10}, port);
            plc.Cmd()->TIMEOUT.value = pac::ToIecTime(100ms);
            plc.Rig().Line().toPac.CorruptByte(byte, static_cast<std::uint8_t>(1U << bit));
            const FinalOutcome outcome = plc.Run(c.code, c.param, c.data);
            EXPECT_TRUE(outcome.Ended()) << outcome;
            const Executions runs = ExecutionsOf(plc.Pac().Serial(), 0, c.code, c.param, c.data);
            EXPECT_EQ(runs.other, 0) << outcome;
            EXPECT_LE(runs.exact, 1) << outcome;
            if (outcome.Done()) {
                EXPECT_EQ(runs.exact, 1) << outcome;
                EXPECT_EQ(plc.AckData(), ack);
            }
            const std::size_t before = plc.Pac().Serial().Commands().size();
            const FinalOutcome next = plc.Run(0x0906, 9, 99);
            EXPECT_TRUE(next.Done()) << next;
            EXPECT_EQ(ExecutionsOf(plc.Pac().Serial(), before, 0x0906, 9, 99).exact, 1);
            if (::testing::Test::HasFailure()) return flips;  // the first flip that breaks it is the one to read
        }
    }
    return flips;
}

// The flips against a controller that verifies one XOR and also takes "0" as "not checked" (answering 16 to
// a CHECK it refuses): the XOR with ETX (the FB's first rule is the other one) and the XOR of the text (the
// simulator's default). Deterministic: the flips are enumerated, no random choice.
TEST(Rs232BitFlips, NoFlipOfARequestEndsDoneWithoutItsCommandRunOnce) {
    const OnceCommand commands[] = {
        {0x0906, 5, 12345},  // its text XORs to 0: under the XOR of the text its CHECK would read "0"
        {0x0603, 0, 0},
        {0x0909, 0, 0},
        {0x0907, 1, BitsOf(5552.0F)},
        {0x1906, 4, 0},  // CHECK 1 or 2: one flipped bit makes it "0", which the controller takes unchecked
    };
    int flips = 0;
    for (pac::sim::CheckVerification verify :
         {pac::sim::CheckVerification::kXorWithEtx, pac::sim::CheckVerification::kXorText}) {
        pac::sim::SerialPortConfig port;
        port.verify = verify;
        port.acceptZeroCheck = true;
        for (const OnceCommand& c : commands) {
            SCOPED_TRACE(std::string(verify == pac::sim::CheckVerification::kXorText ? "xor-text" : "xor-etx") +
                         " or 0, command " + std::to_string(c.code));
            flips += FlipEveryBitOfTheRequests(port, c);
            ASSERT_FALSE(HasFailure());
        }
    }
    RecordProperty("flips", flips);
    EXPECT_GT(flips, 2 * 5 * 20 * 7) << "every byte of every request flipped";
}

// ---- a controller slower than Timeout ----

// Issue 32, item 5, with a controller slower than Timeout: its reply begins 1.2 or 1.6 times Timeout after the
// request, after Timeout and before twice Timeout (the latest the FB can tell from a lost request). In AUTO,
// before a rule is confirmed, the reply to AUTO's probe, or the last reply repeated for an EOT, comes while the
// FB has given the request up and may already have switched rules or sent its next request. Whatever comes in,
// no command runs twice, none ends Done on a reply that is not its own (Done only a turnaround or more after
// the controller first carried it out, once since its edge unless it may run twice, with its own answer), and
// each ends within the bound the page states (the PLCopen checker, in every scan), in Error with a documented
// code where it cannot complete. Each run: a read on a fresh FB, a PLC restart (no rule confirmed, the
// controller keeps the read's reply to repeat), the command, and a write; on every CHECK reading whose refusal
// AUTO meets (16, silence, discard).
class Rs232SlowController : public ::testing::TestWithParam<SerialTiming> {};

TEST_P(Rs232SlowController, NoCommandRunsTwiceOrEndsDoneOnAnotherRequestsReply) {
    // Timeout covers a request and its reply at the line's pace, as the page asks; the controller takes longer.
    const nanoseconds timeout = GetParam().baud < 9600 ? 600ms : 100ms;
    const OnceCommand commands[] = {{0x0603, 0, 0}, {0x0909, 0, 0}, {0x0906, 5, 555}, {0x1906, 4, 0}};
    int runs = 0;
    int failing = 0;
    int done = 0;
    for (const CheckReading& reading : CheckReadings()) {
        if (reading.port.verify == pac::sim::CheckVerification::kNone || !reading.port.acceptZeroCheck) continue;
        for (const int tenths : {12, 16}) for (const OnceCommand& c : commands) {
            const nanoseconds turnaround = timeout * tenths / 10;
            SCOPED_TRACE(reading.name + ", turnaround " + std::to_string(turnaround.count() / 1000000) +
                         " ms, command " + std::to_string(c.code));
            pac::sim::SerialPortConfig port = reading.port;
            port.turnaround = turnaround;
            SerialCmdPlc plc(GetParam(), port);
            plc.Pac().Io().intRegisters.SetInt(4, 4444);
            const nanoseconds plcCycle = std::chrono::milliseconds(GetParam().plcMs);
            bool ok = true;
            // One command on the FB: ends, runs at most once, and Done only on its own reply.
            const auto run = [&](const OnceCommand& cmd, std::optional<std::uint32_t> answer) {
                ++runs;
                plc.Cmd()->TIMEOUT.value = pac::ToIecTime(timeout);
                plc.Cmd()->ENDTIMEOUT.value = pac::ToIecTime(2s);
                const std::size_t before = plc.Pac().Serial().Commands().size();
                const FinalOutcome outcome = plc.Run(cmd.code, cmd.param, cmd.data);
                const Executions runsOf = ExecutionsOf(plc.Pac().Serial(), before, cmd.code, cmd.param, cmd.data);
                const nanoseconds final = plc.EdgeTime() + outcome.Scans() * plcCycle;
                nanoseconds executed = -1ns;  // the first time the controller carried it out
                for (std::size_t i = before; i < plc.Pac().Serial().Commands().size() && executed < 0ns; ++i) {
                    const pac::sim::SerialCommand& x = plc.Pac().Serial().Commands()[i];
                    if (x.error == 0 && x.code == cmd.code && x.parameter == cmd.param) executed = x.at;
                }
                const bool repeatable = cmd.code >= 0x1000 || cmd.code == 0x0906;  // F_PAC_Rs232Repeatable
                const bool documented = outcome.ErrorId() != 0 &&
                                        (outcome.ErrorId() < 0x8000 || outcome.ErrorId() == 0x8001 ||
                                         outcome.ErrorId() == 0x8002 || outcome.ErrorId() == 0x8011 ||
                                         outcome.ErrorId() == 0x8012);
                const bool once = runsOf.other == 0 && (repeatable || runsOf.exact <= 1);
                const bool own = !outcome.Done() ||
                                 (runsOf.exact >= 1 && executed >= 0ns && final >= executed + turnaround &&
                                  (!answer || plc.AckData() == *answer) && (repeatable || runsOf.exact == 1));
                EXPECT_TRUE(outcome.Ended()) << outcome;
                EXPECT_TRUE(outcome.Done() || documented) << outcome;
                EXPECT_TRUE(once) << outcome << ": carried out " << runsOf.exact << " times, " << runsOf.other
                                  << " other commands";
                EXPECT_TRUE(own) << outcome << ": carried out " << runsOf.exact << " times, first at "
                                 << executed.count() / 1000 << " us; Done at " << final.count() / 1000
                                 << " us with AckData " << plc.AckData();
                if (outcome.Done()) ++done;
                ok = ok && outcome.Ended() && (outcome.Done() || documented) && once && own;
            };
            run({0x1906, 4, 0}, 4444u);
            plc.Restart();
            run(c, c.code == 0x1906 ? std::optional<std::uint32_t>(4444u)
                   : c.code == 0x0906 ? std::optional<std::uint32_t>(c.data) : std::nullopt);
            run({0x0906, 9, 99}, 99u);
            if (!ok) ++failing;
        }
    }
    EXPECT_EQ(failing, 0) << failing << " of " << runs / 3 << " runs failed";
    EXPECT_GT(done, runs / 3) << "most commands complete on a controller within twice Timeout";
    RecordProperty("done", done);
}

INSTANTIATE_TEST_SUITE_P(Lines, Rs232SlowController, kLines, LineName);

// ---- a faulty line ----

class Rs232Faults : public ::testing::Test {
protected:
    Rs232Faults() : plc_(SerialTiming{9600, 1, 10}) { plc_.Pac().Io().intRegisters.SetInt(4, 4444); }
    // A PLC that has talked to the controller before: the CHECK rule is confirmed (AUTO).
    void SetUp() override { ExpectRead(0); }
    pac::sim::SerialWire& ToPac() { return plc_.Rig().Line().toPac; }
    pac::sim::SerialWire& FromPac() { return plc_.Rig().Line().fromPac; }
    void ExpectRead(int repeats) {
        const FinalOutcome read = plc_.Run(0x1906, 4);
        ASSERT_TRUE(read.Done()) << read;
        EXPECT_EQ(plc_.AckData(), 4444u);
        EXPECT_EQ(plc_.Repeats(), repeats);
    }
    SerialCmdPlc plc_;
};

TEST_F(Rs232Faults, ADroppedByteOfTheRequest) {
    ToPac().DropByte(ToPac().BytesSent() + 5);  // the frame never completes: no answer, Timeout, again
    ExpectRead(1);
}

TEST_F(Rs232Faults, ADroppedEotOfTheRequest) {
    ToPac().DropByte(ToPac().BytesSent() + RequestBytes("1906;4;0;0") - 1);
    ExpectRead(1);
}

TEST_F(Rs232Faults, ACorruptedByteOfTheRequestIsRefusedWith16) {
    ToPac().CorruptByte(ToPac().BytesSent() + 4, 0x01);
    ExpectRead(1);
    EXPECT_EQ(plc_.Pac().Serial().Counters().checkErrors, 1u);
}

TEST_F(Rs232Faults, ADroppedOrCorruptedByteOfTheReply) {
    FromPac().DropByte(FromPac().BytesSent() + 3);
    ExpectRead(1);
    FromPac().CorruptByte(FromPac().BytesSent() + 6, 0x02);
    ExpectRead(1);
    FromPac().DropByte(FromPac().BytesSent());  // SOH: STX alone still begins the frame
    ExpectRead(0);
}

TEST_F(Rs232Faults, ADelayedReplyLongerThanTimeout) {
    plc_.Cmd()->TIMEOUT.value = pac::ToIecTime(100ms);
    FromPac().DelayByte(FromPac().BytesSent() + 10, 120ms);  // a gap in the middle of the reply
    ExpectRead(1);
    EXPECT_EQ(plc_.Pac().Io().intRegisters.GetInt(4), 4444);
}

TEST_F(Rs232Faults, NoiseBeforeTheReply) {
    plc_.Rig().Task().AddProgram([this] {
        if (plc_.Rig().Task().ScanCount() == 3) FromPac().Noise(plc_.Rig().Now(), {0x7F, 0x03, 0x30, 0x04, 0x55});
    });
    ExpectRead(0);
}

TEST_F(Rs232Faults, ARelativeMoveWhoseReplyIsLostRunsOnce) {
    ASSERT_TRUE(plc_.Run(0x0603, 0).Done());
    FromPac().DropByte(FromPac().BytesSent() + 4);
    const FinalOutcome move = plc_.Run(0x0A89, 1, BitsOf(30.0F));
    ASSERT_TRUE(move.Done()) << move;
    EXPECT_EQ(plc_.Pac().Axes().Motion(1).Position(), 30.0) << "polled, not sent twice";
    EXPECT_EQ(plc_.Pac().Counters().Count(0x0A89), 1u);
}

TEST_F(Rs232Faults, RandomDropsAndCorruptionsOnBothWires) {
    ToPac().SetRandomFaults(0.002, 0.002);
    FromPac().SetRandomFaults(0.002, 0.002);
    for (int n = 1; n <= 40; ++n) {
        const FinalOutcome write = plc_.Run(0x0906, static_cast<std::uint16_t>(n), static_cast<std::uint32_t>(n * 7));
        ASSERT_TRUE(write.Done()) << n << ": " << write;
        const FinalOutcome read = plc_.Run(0x1906, static_cast<std::uint16_t>(n));
        ASSERT_TRUE(read.Done()) << n << ": " << read;
        EXPECT_EQ(plc_.AckData(), static_cast<std::uint32_t>(n * 7)) << n;
    }
    EXPECT_GT(ToPac().BytesDropped() + ToPac().BytesCorrupted() + FromPac().BytesDropped() +
                  FromPac().BytesCorrupted(), 0u) << "the line did misbehave";
}

}  // namespace
}  // namespace test_fb_pac_rs232_sim
