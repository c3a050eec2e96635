// FB_PAC_Rs232Cmd where a reply comes late or the buffers are not the FB's alone (docs/fb/FB_PAC_Rs232Cmd.md,
// "A noisy line" and "The calling contract"), scan by scan against the simulated PA-CONTROL, on the bus
// timings and CHECK readings of the calling-contract suites:
// - a reply that arrives while the Timeout of its request runs out, with a driver in a faster task that holds
//   RxBuffer in one or two scans of every two or three: no request reaches the controller while its reply is
//   on the wire, and the read ends, Done only with its register's value;
// - a PLC restart at every scan from the edge of a read to the end of its reply: the fresh instance's read
//   ends Done with its own register's value, never the old instance's;
// - an edge that finds no room in TxBuffer (or no quiet line), the FB left out until a call some time later
//   that finds it: after Timeout no request goes out (16#8011, 16#8012), and Busy ends within the bound the
//   page states.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "free_commands.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/serial_rig.hpp"
#include "pac/sim/command_table.hpp"
#include "pac/sim/serial_port.hpp"
#include "pac/st_program.hpp"
#include "real_bits.hpp"
#include "rs232_case.hpp"

namespace test_rs232_late_reply_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using std::chrono::nanoseconds;
using pac::test::FreeCommand;
namespace code = pac::sim::code;

using LateCase = pac::test::Rs232Case;

std::string LateCaseName(const ::testing::TestParamInfo<LateCase>& info) {
    return pac::test::Rs232CaseName(info.param);
}

const FreeCommand kReadA{code::kGetIntReg, pac::test::kFreeReadRegisters, 0};
const FreeCommand kReadB{code::kGetIntReg, pac::test::kFreeReadRegisters + 1, 0};

// One FB_PAC_Rs232Cmd on a simulated PA-CONTROL's RS232 line, called in the scans `Calls` allows; every call
// checks that no request goes to the controller while one of its replies is still on the wire.
class LateReplyPlc {
public:
    LateReplyPlc(const LateCase& c, nanoseconds turnaround)
        : rig_(pac::test::Rs232RigTiming(c), pac::test::Rs232RigConfig(), pac::test::Rs232RigPort(c, turnaround)) {
        rig_.CallWhen(cmd_, [this] { return Calls(); }, [this] { After(); });
        for (int n = 0; n < 4; ++n) {
            rig_.Controller().Io().intRegisters.SetInt(pac::test::kFreeReadRegisters + n, pac::test::kFreeReadBase + n);
        }
    }

    // Idle calls long past QuietTime: the line is quiet before the first command.
    void LeadIn() { Scan(200ms); }
    void Scan(nanoseconds span) {
        const nanoseconds until = rig_.Now() + span;
        while (rig_.Now() < until) rig_.Scan();
    }
    // Edges `command` in the next scan and scans until the FB ends it (Execute held); the edge's time.
    nanoseconds Run(const FreeCommand& command, nanoseconds limit = 30s) {
        Edge(command);
        rig_.Scan();
        const nanoseconds edge = rig_.Now();
        while (rig_.Now() < edge + limit && !cmd_->DONE.value && !cmd_->ERROR.value) rig_.Scan();
        return edge;
    }
    void Edge(const FreeCommand& command) {
        cmd_->CODE.value = command.code;
        cmd_->PARAM.value = command.param;
        cmd_->DATA.value = command.data;
        cmd_->EXECUTE.value = TRUE;
        ledgerAtEdge_ = rig_.Controller().Serial().Commands().size();
    }
    // A PLC restart: a fresh instance with empty buffers on a controller that runs on.
    void Restart() { cmd_ = PAC_FB(FB_PAC_RS232CMD); }
    void LeaveOut(std::function<bool()> skipped) { skipped_ = std::move(skipped); }

    // How often the controller executed `command` since the last edge.
    int Executed(const FreeCommand& command) {
        const auto& ledger = rig_.Controller().Serial().Commands();
        int n = 0;
        for (std::size_t k = ledgerAtEdge_; k < ledger.size(); ++k) {
            const auto& t = ledger[k];
            if (t.error == 0 && FreeCommand{t.code, t.parameter, t.data} == command) ++n;
        }
        return n;
    }

    pac::FbInstance<FB_PAC_RS232CMD>& Cmd() { return cmd_; }
    pac::SerialRig& Rig() { return rig_; }
    const std::vector<std::string>& Violations() const { return violations_; }
    // The last call's time, and whether it handed a request to the driver.
    nanoseconds LastCall() const { return lastCall_; }
    int Requests() const { return requests_; }
    // The first scan that saw a byte of the controller on the wire; negative: none yet.
    nanoseconds FirstReply() const { return firstReply_; }

private:
    bool Calls() {
        if (firstReply_ < 0ns && rig_.Line().fromPac.Carrying(rig_.Now())) firstReply_ = rig_.Now();
        return !skipped_ || !skipped_();
    }

    void After() {
        lastCall_ = rig_.Now();
        if (cmd_->TXBUFFER.value.COUNT == 0) return;
        ++requests_;
        if (rig_.Line().fromPac.Carrying(rig_.Now())) {
            violations_.push_back("a request at " + std::to_string(rig_.Now().count() / 1000) +
                                  " us while a reply of the controller is on the wire");
        }
    }

    pac::SerialRig rig_;
    pac::FbInstance<FB_PAC_RS232CMD> cmd_ = PAC_FB(FB_PAC_RS232CMD);
    std::function<bool()> skipped_;
    std::vector<std::string> violations_;
    std::size_t ledgerAtEdge_ = 0;
    nanoseconds lastCall_{0};
    int requests_ = 0;
    nanoseconds firstReply_{-1};
};

// The CheckRule that names the CHECK the case's controller verifies.
E_PAC_RS232CHECK ControllersRule(const LateCase& c) {
    return c.verify == pac::sim::CheckVerification::kXorText ? E_PAC_RS232CHECK__PAC_RS232_CHECK_XOR_TEXT
                                                              : E_PAC_RS232CHECK__PAC_RS232_CHECK_XOR_ETX;
}

// The skip tests' Timeout and EndTimeout, and the bound of Busy they give with the default Retries (3) and AUTO's
// probe: (3 + 1 + 1) x 3 x Timeout + EndTimeout (docs/fb/FB_PAC_Rs232Cmd.md, "A noisy line").
constexpr nanoseconds kSkipTimeout = 100ms;
constexpr nanoseconds kSkipEndTimeout = 1s;
constexpr nanoseconds kSkipBound = 5 * 3 * kSkipTimeout + kSkipEndTimeout;

const auto kTimings = ::testing::Values(LateCase{9600, 1, 10}, LateCase{38400, 2, 3},
                                        LateCase{19200, 5, 1, pac::sim::CheckVerification::kXorWithEtx, false});

// The controller answers a read late, so that its reply is on the wire when the request's Timeout (1 s) runs
// out; the driver holds RxBuffer in every other scan, or in two of every three. CheckRule is the controller's
// own rule: in AUTO a controller this slow keeps AUTO's probe and its repetitions in flight together. The
// sweep's turnarounds whose reply begins only after the Timeout's last scan are left out: that reply is a lost
// one, the request goes again on a quiet line, and a controller that slow answers every later request late as
// well (Timeout must cover a reply, the FB's page). The FB must not take a scan it could not read for a quiet
// one: it waits for the reply, takes it (the late reply of a failed request counts) and sends nothing while it
// comes in. A driver that holds the buffer that often must not stop the FB either.
class Rs232HeldRxBuffer : public ::testing::TestWithParam<LateCase> {};

TEST_P(Rs232HeldRxBuffer, NoRequestWhileALateReplyComesIn) {
    int failing = 0;
    int cases = 0;
    const auto controllersRule = ControllersRule(GetParam());
    // The driver's schedules: free in one scan of every `period`, from scan `phase` on.
    for (int period = 2; period <= 3; ++period) for (int phase = 0; phase < period; ++phase)
    for (nanoseconds turnaround = 900ms; turnaround <= 1000ms; turnaround += 500us) {
        ++cases;
        SCOPED_TRACE("controller turnaround " + std::to_string(turnaround.count() / 1000) + " us, free in scan " +
                     std::to_string(phase) + " of every " + std::to_string(period));
        LateReplyPlc plc(GetParam(), turnaround);
        plc.Cmd()->CHECKRULE.value = controllersRule;
        plc.Rig().HoldRxBuffer([&plc, period, phase] { return (plc.Rig().Task().ScanCount() + phase) % period != 0; });
        plc.LeadIn();
        const nanoseconds edge = plc.Run(kReadA);
        if (plc.FirstReply() > edge + 1s) {
            --cases;
            continue;
        }
        // The read ends, and Done only with its register's value.
        const bool final = plc.Cmd()->DONE.value || plc.Cmd()->ERROR.value;
        const bool rightValue = !plc.Cmd()->DONE.value || plc.Cmd()->ACKDATA.value == pac::test::FreeReadAnswer(kReadA);
        if (!plc.Violations().empty() || !final || !rightValue) ++failing;
        for (const std::string& v : plc.Violations()) ADD_FAILURE() << v;
        EXPECT_TRUE(final);
        EXPECT_TRUE(rightValue);
    }
    EXPECT_GT(cases, 3) << "too few replies straddle the Timeout";
    EXPECT_EQ(failing, 0) << failing << " of " << cases << " turnarounds failed";
}

INSTANTIATE_TEST_SUITE_P(Timings, Rs232HeldRxBuffer, kTimings, LateCaseName);

// The old instance edges a read of N100; the PLC restarts 0 to 60 ms later (the request on the wire, the
// controller's cycle, its reply coming in), and the fresh instance edges a read of N101 in its first call.
// The fresh read ends Done with N101's value, executed once after its edge: the old reply (QUIT 0, BE 1, the
// other register's value) names no command and must not pass for it.
class Rs232RestartLateReply : public ::testing::TestWithParam<LateCase> {};

TEST_P(Rs232RestartLateReply, AFreshInstanceNeverTakesTheOldInstancesReply) {
    int failing = 0;
    int cases = 0;
    const nanoseconds plcCycle = std::chrono::milliseconds(GetParam().plcMs);
    for (nanoseconds after = 0ms; after <= 60ms; after += plcCycle) {
        ++cases;
        SCOPED_TRACE("PLC restart " + std::to_string(after.count() / 1000000) + " ms after the old edge");
        LateReplyPlc plc(GetParam(), 0ns);
        plc.LeadIn();
        plc.Edge(kReadA);
        plc.Rig().Scan();
        plc.Scan(after);
        plc.Restart();
        plc.Run(kReadB);
        const int executed = plc.Executed(kReadB);
        const bool ok = plc.Cmd()->DONE.value && plc.Cmd()->ACKDATA.value == pac::test::FreeReadAnswer(kReadB) &&
                        executed == 1 && plc.Violations().empty();
        if (!ok) ++failing;
        EXPECT_TRUE(plc.Cmd()->DONE.value) << "ErrorID 16#" << std::hex << plc.Cmd()->ERRORID.value;
        EXPECT_EQ(plc.Cmd()->ACKDATA.value, pac::test::FreeReadAnswer(kReadB)) << "another command's answer";
        EXPECT_EQ(executed, 1);
        for (const std::string& v : plc.Violations()) ADD_FAILURE() << v;
    }
    EXPECT_EQ(failing, 0) << failing << " of " << cases << " restarts failed";
}

INSTANTIATE_TEST_SUITE_P(Timings, Rs232RestartLateReply, kTimings, LateCaseName);

// The driver holds TxBuffer from the edge on (a port still busy with another program's bytes), or RxBuffer
// (so the fresh instance cannot see the line quiet before its first request), and the program leaves the FB
// out from the scan after the edge until a call `late` after it, which finds the buffer free. Timeout (100 ms)
// bounds each wait on the clock: a call before it sends the read, which ends Done; a call after it ends
// 16#8011 (room) or 16#8012 (quiet line) with nothing sent, so Busy ends in the first call after the bound the
// page states, (Retries + 1) x 3 x Timeout + one request for AUTO's probe + EndTimeout, however long the FB
// was left out.
class Rs232SkipPastTimeout : public ::testing::TestWithParam<LateCase> {};

TEST_P(Rs232SkipPastTimeout, NoRequestAfterItsWaitRanOut) {
    constexpr nanoseconds kTimeout = kSkipTimeout;
    constexpr nanoseconds kBound = kSkipBound;
    const nanoseconds plcCycle = std::chrono::milliseconds(GetParam().plcMs);
    std::vector<nanoseconds> lates;
    for (nanoseconds late = 50ms; late <= 300ms; late += 10ms) {
        if (late != kTimeout) lates.push_back(late);
    }
    lates.push_back(kBound + plcCycle);
    lates.push_back(2 * kBound);
    int failing = 0;
    for (const bool quiet : {false, true}) for (const nanoseconds late : lates) {
        SCOPED_TRACE(std::string(quiet ? "RxBuffer" : "TxBuffer") + " held, first call after the edge " +
                     std::to_string(late.count() / 1000000) + " ms after it");
        const std::uint16_t ranOut = quiet ? 0x8012 : 0x8011;
        LateReplyPlc plc(GetParam(), 0ns);
        plc.Cmd()->TIMEOUT.value = pac::ToIecTime(kTimeout);
        plc.Cmd()->ENDTIMEOUT.value = pac::ToIecTime(kSkipEndTimeout);
        plc.LeadIn();
        nanoseconds edge = -1ns;  // the edge's scan holds the buffer too
        plc.LeaveOut([&] { return edge >= 0ns && plc.Rig().Now() > edge && plc.Rig().Now() < edge + late; });
        const auto held = [&] { return edge < 0ns || plc.Rig().Now() < edge + late; };
        if (quiet) {
            plc.Rig().HoldRxBuffer(held);
        } else {
            plc.Rig().HoldTxBuffer(held);
        }
        plc.Edge(kReadA);
        plc.Rig().Scan();
        edge = plc.Rig().Now();
        ASSERT_TRUE(plc.Cmd()->BUSY.value);
        while (plc.LastCall() < edge + late) plc.Rig().Scan();
        const bool sent = plc.Requests() > 0;
        const bool busyPastBound = plc.LastCall() >= edge + kBound && plc.Cmd()->BUSY.value;
        while (plc.Rig().Now() < edge + late + 10s && !plc.Cmd()->DONE.value && !plc.Cmd()->ERROR.value) {
            plc.Rig().Scan();
        }
        bool ok = !busyPastBound;
        if (late < kTimeout) {
            ok = ok && sent && plc.Cmd()->DONE.value && plc.Executed(kReadA) == 1;
            EXPECT_TRUE(plc.Cmd()->DONE.value) << "ErrorID 16#" << std::hex << plc.Cmd()->ERRORID.value;
        } else {
            ok = ok && !sent && plc.Cmd()->ERROR.value && plc.Cmd()->ERRORID.value == ranOut &&
                 plc.Executed(kReadA) == 0;
            EXPECT_FALSE(sent) << "a request went out after its wait had run out";
            EXPECT_TRUE(plc.Cmd()->ERROR.value);
            EXPECT_EQ(plc.Cmd()->ERRORID.value, ranOut);
            EXPECT_EQ(plc.Executed(kReadA), 0);
        }
        EXPECT_FALSE(busyPastBound) << "Busy in the first call after the bound";
        if (!ok) ++failing;
    }
    EXPECT_EQ(failing, 0) << failing << " of " << 2 * lates.size() << " skips failed";
}

INSTANTIATE_TEST_SUITE_P(Timings, Rs232SkipPastTimeout, kTimings, LateCaseName);

// The first request goes out, and the program leaves the FB out from the next scan until a call `late` after the edge,
// past the whole bound the page states ((Retries + 1) x 3 x Timeout + one request for AUTO's probe +
// EndTimeout). The answer came in meanwhile, and it would begin a new wait: a refused frame (the FB's CHECK rule
// is not the controller's: 16, send again), a reply the first call cannot read (the driver holds RxBuffer: a lost
// reply, send again), AUTO's probe answered (the move goes out next), or a move acknowledged with BE = 0 (EOT
// polls for BE = 1). The first call after the bound ends the command with the code of that wait (the refusal's
// QUIT, 16#8001 for no acknowledgement of the command, 16#8002) and sends nothing more, so Busy never outlasts the bound, however long the FB was left
// out.
enum class PastBound { kRefused, kUnread, kProbeAnswered, kLongCommand };

class Rs232SkipPastBound : public ::testing::TestWithParam<LateCase> {};

TEST_P(Rs232SkipPastBound, TheFirstCallAfterTheBoundBeginsNoNewWait) {
    constexpr nanoseconds kTimeout = kSkipTimeout;
    constexpr nanoseconds kEndTimeout = kSkipEndTimeout;
    constexpr nanoseconds kBound = kSkipBound;
    const nanoseconds plcCycle = std::chrono::milliseconds(GetParam().plcMs);
    const FreeCommand move{code::kPosAxisAbsolute, 1, pac::test::BitsOf(12.5F)};
    const auto controllersRule = ControllersRule(GetParam());
    const auto otherRule = controllersRule == E_PAC_RS232CHECK__PAC_RS232_CHECK_XOR_TEXT
                               ? E_PAC_RS232CHECK__PAC_RS232_CHECK_XOR_ETX
                               : E_PAC_RS232CHECK__PAC_RS232_CHECK_XOR_TEXT;
    int failing = 0;
    int cases = 0;
    for (const PastBound kind : {PastBound::kRefused, PastBound::kUnread, PastBound::kProbeAnswered,
                                 PastBound::kLongCommand})
    for (const nanoseconds late : {kBound + plcCycle, 2 * kBound}) {
        ++cases;
        const char* names[] = {"a refused frame", "a reply held from the first call", "AUTO's probe answered or refused",
                               "a move acknowledged with BE = 0"};
        SCOPED_TRACE(std::string(names[static_cast<int>(kind)]) + ", first call after the edge " +
                     std::to_string(late.count() / 1000000) + " ms after it");
        LateReplyPlc plc(GetParam(), 0ns);
        // ONLINE first (the move runs only there), by an instance whose rule is then confirmed; AUTO's probe
        // goes out before a move only from a fresh instance, which lets the line fall quiet before it.
        plc.LeadIn();
        plc.Run({code::kStartOnline, 0, 0});
        ASSERT_TRUE(plc.Cmd()->DONE.value) << "0603: ErrorID 16#" << std::hex << plc.Cmd()->ERRORID.value;
        plc.Cmd()->EXECUTE.value = FALSE;
        plc.LeadIn();
        if (kind == PastBound::kProbeAnswered) plc.Restart();
        plc.Cmd()->TIMEOUT.value = pac::ToIecTime(kTimeout);
        plc.Cmd()->ENDTIMEOUT.value = pac::ToIecTime(kEndTimeout);
        plc.Cmd()->CHECKRULE.value = kind == PastBound::kRefused         ? otherRule
                                     : kind == PastBound::kProbeAnswered ? E_PAC_RS232CHECK__PAC_RS232_CHECK_AUTO
                                                                         : controllersRule;
        const FreeCommand command = kind == PastBound::kLongCommand || kind == PastBound::kProbeAnswered ? move : kReadA;
        std::uint16_t code = 0x8001;
        if (kind == PastBound::kRefused) code = 16;
        if (kind == PastBound::kLongCommand) code = 0x8002;
        // Left out from the scan after the first request until `late` after the edge.
        nanoseconds edge = -1ns;
        const int beforeTheEdge = plc.Requests();
        plc.LeaveOut([&] { return edge >= 0ns && plc.Requests() > beforeTheEdge && plc.Rig().Now() < edge + late; });
        if (kind == PastBound::kUnread) {
            plc.Rig().HoldRxBuffer([&] {
                return edge >= 0ns && plc.Rig().Now() >= edge + late && plc.Rig().Now() < edge + late + plcCycle;
            });
        }
        plc.Edge(command);
        plc.Rig().Scan();
        edge = plc.Rig().Now();
        while (plc.Requests() == beforeTheEdge && plc.Rig().Now() < edge + kTimeout) plc.Rig().Scan();
        const int sentBeforeTheSkip = plc.Requests() - beforeTheEdge;
        const int before = plc.Requests();
        while (plc.LastCall() < edge + late) plc.Rig().Scan();
        const bool busyPastBound = plc.Cmd()->BUSY.value;
        while (plc.Rig().Now() < edge + late + 10s && !plc.Cmd()->DONE.value && !plc.Cmd()->ERROR.value) {
            plc.Rig().Scan();
        }
        const int sentAfter = plc.Requests() - before;
        const int executed = plc.Executed(command);
        // The read whose reply was held ran once; the refused frame and the move behind the probe never reached
        // the controller.
        const int executedOnce = kind == PastBound::kLongCommand || kind == PastBound::kUnread ? 1 : 0;
        // AUTO's probe goes out with the rule tried first: the controller takes it (the move would be next) or
        // refuses it with 16 (the probe would go again with the other rule).
        const std::uint16_t id = plc.Cmd()->ERRORID.value;
        const bool codeOk = id == code || (kind == PastBound::kProbeAnswered && id == 16);
        const bool ok = sentBeforeTheSkip == 1 && sentAfter == 0 && !busyPastBound && plc.Cmd()->ERROR.value &&
                        codeOk && executed == executedOnce;
        if (!ok) ++failing;
        EXPECT_EQ(sentBeforeTheSkip, 1) << "the first request goes out before the skip";
        EXPECT_EQ(sentAfter, 0) << "a request went out after the bound";
        EXPECT_FALSE(busyPastBound) << "Busy in the first call after the bound";
        EXPECT_TRUE(plc.Cmd()->ERROR.value);
        EXPECT_TRUE(codeOk) << std::hex << "ErrorID 16#" << id << ", expected 16#" << code;
        EXPECT_EQ(executed, executedOnce);
    }
    EXPECT_EQ(failing, 0) << failing << " of " << cases << " skips failed";
}

INSTANTIATE_TEST_SUITE_P(Timings, Rs232SkipPastBound, kTimings, LateCaseName);

}  // namespace
}  // namespace test_rs232_late_reply_sim
