// Recovery of the shared CMD interface against the simulated PA-CONTROL, scan by scan, on the bus timings of
// the library's tests and on every controller reading (controller_readings.hpp): a controller restart while
// every FB is busy, or in Error with the inputs frozen, the two timers and what their ErrorIDs say about
// the command, the power-up reply, and T#0S (issue 10, defects 1, 3, 4 and 6; docs/fb/FB_PAC_Cmd.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "bus_timing.hpp"
#include "controller_readings.hpp"
#include "gvl_constants.hpp"
#include "pac/sim/command_table.hpp"
#include "pac/iec_time.hpp"
#include "real_bits.hpp"
#include "shared_cmd_plc.hpp"

namespace test_cmd_recovery_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using std::chrono::nanoseconds;
using pac::test::FinalOutcome;
using pac::test::SharedCmdPlc;
using pac::test::SharingCase;
namespace code = pac::sim::code;

const pac::test::GvlConstants kGvl;
const std::uint32_t kLibAckTimeout = kGvl["PAC_LIB_ERR_ACK_TIMEOUT"];
const std::uint32_t kLibEndTimeout = kGvl["PAC_LIB_ERR_END_TIMEOUT"];
const std::uint32_t kLibNotReady = kGvl["PAC_LIB_ERR_NOT_READY"];
const std::uint32_t kLibConnectionLost = kGvl["PAC_LIB_ERR_CONNECTION_LOST"];
const std::uint32_t kLibInterfaceBusy = kGvl["PAC_LIB_ERR_INTERFACE_BUSY"];

// Longer than the bus round trip plus a scan on every timing: a restart the PLC can see (status 0) before
// the controller reads commands again (docs/fb/FB_PAC_Cmd.md, "Restarts").
constexpr nanoseconds kBoot = 150ms;

std::uint32_t Bits(float value) { return pac::test::BitsOf(value); }

bool Final(pac::FbInstance<FB_PAC_CMD>& fb) { return fb->DONE.value || fb->ERROR.value; }

// Every command the controller recognised but the harmless 190B of a parked module, each at most once.
void ExpectNoCommandTwice(SharedCmdPlc& plc) {
    std::set<std::tuple<std::uint16_t, std::uint16_t, std::uint32_t>> seen;
    for (const auto& c : plc.CommandsSeen()) {
        if (c.code == code::kGetState) continue;
        EXPECT_TRUE(seen.insert({c.code, c.parameter, c.data}).second)
            << "command " << std::hex << c.code << " param " << std::dec << c.parameter << " data " << c.data
            << " executed twice";
    }
}

// The module is parked (190B, no data) in step with the controller's RECEIVE flag.
void ExpectParkedInStep(SharedCmdPlc& plc) {
    const auto module = pac::sim::CommandFrame::Decode(plc.Module());
    EXPECT_EQ(module.code, code::kGetState);
    EXPECT_EQ(module.data, 0u);
    const auto reply = pac::sim::ReplyFrame::Decode(plc.Controller().LastFromPacImage().Cmd());
    EXPECT_EQ(module.send, reply.receiveFlag) << "SEND = RECEIVE";
}

// FB `i` re-triggers its own write of N(20 + i) with a value no other command carries, as fast as a PLC
// program can: Execute falls for one scan after each final output.
class ReTrigger {
public:
    ReTrigger(SharedCmdPlc& plc, int fbs) : plc_(plc), released_(static_cast<std::size_t>(fbs), false),
                                              sequence_(static_cast<std::size_t>(fbs), 0),
                                              doneSince_(static_cast<std::size_t>(fbs), 0) {
        for (int i = 0; i < fbs; ++i) Next(i);
    }

    // After each scan.
    void Step(bool retrigger) {
        for (int i = 0; i < static_cast<int>(released_.size()); ++i) {
            auto& fb = plc_.Fb(i);
            const auto k = static_cast<std::size_t>(i);
            if (released_[k]) {
                released_[k] = false;
                if (retrigger) Next(i);
            } else if (Final(fb)) {
                if (fb->DONE.value) ++doneSince_[k];
                errors_.insert(fb->ERROR.value ? fb->ERRORID.value : 0);
                fb->EXECUTE.value = FALSE;
                released_[k] = true;
            }
        }
    }
    void ResetDone() { std::fill(doneSince_.begin(), doneSince_.end(), 0); }
    int LeastDone() const { return *std::min_element(doneSince_.begin(), doneSince_.end()); }
    // The ErrorIDs seen (0 for Done).
    const std::set<std::uint32_t>& Outcomes() const { return errors_; }

private:
    void Next(int i) {
        const auto k = static_cast<std::size_t>(i);
        ++sequence_[k];
        plc_.Set(i, code::kPutIntReg, static_cast<std::uint16_t>(20 + i), static_cast<std::uint32_t>(i) * 100000u + sequence_[k]);
        plc_.Fb(i)->EXECUTE.value = TRUE;
    }

    SharedCmdPlc& plc_;
    std::vector<bool> released_;
    std::vector<std::uint32_t> sequence_;
    std::vector<int> doneSince_;
    std::set<std::uint32_t> errors_;
};

class CmdRecovery : public ::testing::TestWithParam<SharingCase> {};

// Defect 3: the controller restarts while every FB is busy (one command in flight, the others queued) and
// they go on re-triggering. Every FB ends each command (16#8004 sent, 16#8003 not sent, or Done), the
// module comes back in step without a command but the harmless 190B, no command runs twice, and every FB
// is served again after the boot.
TEST_P(CmdRecovery, RestartWhileEveryFbIsBusy) {
    const int fbs = 5;
    SharedCmdPlc plc(GetParam(), fbs, kBoot);
    plc.Boot();
    ReTrigger load(plc, fbs);
    for (int scan = 0; scan < 100000 && plc.Controller().Counters().recognized < 12; ++scan) {
        plc.Scan();
        load.Step(true);
    }
    plc.Controller().PowerCycle(plc.Now());
    load.ResetDone();
    for (int scan = 0; scan < 100000 && load.LeastDone() < 3; ++scan) {
        plc.Scan();
        load.Step(true);
    }
    EXPECT_GE(load.LeastDone(), 3) << "every FB is served again after the restart";
    for (std::uint32_t id : load.Outcomes()) {
        EXPECT_TRUE(id == 0 || id == kLibConnectionLost || id == kLibNotReady) << "ErrorID " << std::hex << id;
    }
    auto anyBusy = [&] {
        for (int i = 0; i < fbs; ++i) {
            if (plc.Fb(i)->BUSY.value) return true;
        }
        return false;
    };
    for (int scan = 0; scan < 100000 && anyBusy(); ++scan) {
        plc.Scan();
        load.Step(false);
    }
    plc.Scan(10 + 4 * plc.Timing().latency + plc.Timing().jitterUs / 500 / plc.Timing().plcMs);
    ExpectNoCommandTwice(plc);
    ExpectParkedInStep(plc);
}

// Defect 3: every FB holds an Error (Execute stays TRUE) while the controller restarts, and the master has
// frozen the inputs meanwhile, so no FB sees the restart. When the inputs thaw the module is out of step;
// FB_PAC_CmdInterface brings it back without a command, and each FB's next command runs exactly once.
TEST_P(CmdRecovery, RestartUnseenBehindFrozenInputsWhileEveryFbHoldsAnError) {
    const int fbs = 4;
    SharedCmdPlc plc(GetParam(), fbs, kBoot);
    plc.Boot();
    for (int i = 0; i < fbs; ++i) {
        plc.Set(i, code::kGetIntReg, static_cast<std::uint16_t>(60000 + i));  // no such register: command error 38
        plc.Fb(i)->EXECUTE.value = TRUE;
    }
    for (int scan = 0; scan < 100000; ++scan) {
        bool all = true;
        for (int i = 0; i < fbs; ++i) all = all && plc.Fb(i)->ERROR.value;
        if (all) break;
        plc.Scan();
    }
    // An odd number of commands so far: SEND = 1, which a controller restarting with RECEIVE 0 disagrees with.
    plc.Set(0, code::kGetIntReg, 1);
    plc.Fb(0)->EXECUTE.value = FALSE;
    plc.Scan();
    plc.Fb(0)->EXECUTE.value = TRUE;
    for (int scan = 0; scan < 100000 && !Final(plc.Fb(0)); ++scan) plc.Scan();
    ASSERT_TRUE(plc.Fb(0)->DONE.value);
    const auto before = plc.CommandsSeen().size();

    plc.Plc().Rig().Bus().FromPacLink().SetFault(plc.Now(), pac::sim::LinkFault::kFrozen);
    plc.Scan(3);
    plc.Controller().PowerCycle(plc.Now());
    plc.Plc().Rig().ScanUntil([&] { return plc.Controller().Booted(); }, 100000);
    plc.Scan(20);
    plc.Plc().Rig().Bus().FromPacLink().SetFault(plc.Now(), pac::sim::LinkFault::kNone);
    plc.Scan(10 + 4 * plc.Timing().latency + plc.Timing().jitterUs / 500 / plc.Timing().plcMs);
    for (std::size_t k = before; k < plc.CommandsSeen().size(); ++k) {
        EXPECT_EQ(plc.CommandsSeen()[k].code, code::kGetState) << "only the parked module's read while nobody sent";
    }
    ExpectParkedInStep(plc);

    for (int i = 0; i < fbs; ++i) {
        plc.Fb(i)->EXECUTE.value = FALSE;
        plc.Set(i, code::kPutIntReg, static_cast<std::uint16_t>(30 + i), 77u + static_cast<std::uint32_t>(i));
    }
    plc.Scan();
    for (int i = 0; i < fbs; ++i) plc.Fb(i)->EXECUTE.value = TRUE;
    for (int scan = 0; scan < 100000; ++scan) {
        bool all = true;
        for (int i = 0; i < fbs; ++i) all = all && Final(plc.Fb(i));
        if (all) break;
        plc.Scan();
    }
    for (int i = 0; i < fbs; ++i) {
        EXPECT_TRUE(plc.Fb(i)->DONE.value) << "FB " << i << ": ErrorID " << std::hex << plc.Fb(i)->ERRORID.value;
        EXPECT_EQ(plc.Controller().Io().intRegisters.GetInt(30 + i), 77 + i);
        EXPECT_EQ(plc.Seen(code::kPutIntReg, static_cast<std::uint16_t>(30 + i)), 1) << "FB " << i;
    }
    ExpectNoCommandTwice(plc);
}

// Defect 1 at power-up: the controller's first reply may show RECEIVE = SEND with END OF PROCESSING 0
// although nothing runs; once the cold start's parked read is acknowledged (D8), the first command goes out
// in its edge scan and ends at the protocol minimum.
TEST_P(CmdRecovery, FirstCommandAfterPowerUpGoesAtOnce) {
    SharedCmdPlc plc(GetParam(), 1, kBoot);
    plc.Plc().Rig().ScanUntil([&] { return plc.Fb(0)->OPSTATUS.value != 0; }, 100000);
    plc.Plc().ScanPastFirstHandshake();
    plc.Controller().Io().intRegisters.SetInt(2, 22);
    plc.Set(0, code::kGetIntReg, 2);
    const FinalOutcome read = plc.Run(0);
    ASSERT_TRUE(read.Done()) << read;
    EXPECT_EQ(plc.Fb(0)->ACKDATA.value, 22u);
    EXPECT_TRUE(plc.Plc().Window().Contains(read.Scans())) << read << ", the protocol allows " << plc.Plc().Window();
}

// Defect 1 after a restart: the last command was a long one (a move, ended); the restarted controller's
// RECEIVE = SEND with END OF PROCESSING 0 is not that move still processing.
TEST_P(CmdRecovery, AfterARestartTheEndedMoveHoldsNothing) {
    SharedCmdPlc plc(GetParam(), 1, kBoot);
    plc.Boot();
    ASSERT_TRUE(plc.GoOnline());
    for (float target : {100.0F, 200.0F}) {  // an even number of commands since: SEND = 0 as RECEIVE starts
        plc.Set(0, code::kPosAxisAbsolute, 1, Bits(target));
        ASSERT_TRUE(plc.Run(0).Done());
    }
    plc.Controller().PowerCycle(plc.Now());
    plc.Plc().Rig().ScanUntil([&] { return plc.Fb(0)->OPSTATUS.value == 0; }, 100000);
    plc.Plc().Rig().ScanUntil([&] { return plc.Fb(0)->OPSTATUS.value != 0; }, 100000);
    plc.Controller().Io().intRegisters.SetInt(2, 23);
    plc.Set(0, code::kGetIntReg, 2);
    const FinalOutcome read = plc.Run(0);
    ASSERT_TRUE(read.Done()) << read;
    EXPECT_EQ(plc.Fb(0)->ACKDATA.value, 23u);
}

// Defect 1: a move whose FB gave up at EndTimeout (16#8002) still processes in the controller, so the
// interface stays its until END OF PROCESSING; a read queued meanwhile goes out after it.
TEST_P(CmdRecovery, MoveAfterEndTimeoutHoldsTheInterfaceUntilItsEnd) {
    SharedCmdPlc plc(GetParam(), 2);
    plc.Boot();
    ASSERT_TRUE(plc.GoOnline());
    plc.Set(0, code::kPosAxisAbsolute, 1, Bits(600.0F));
    plc.Fb(0)->ENDTIMEOUT.value = pac::ToIecTime(100ms);
    const FinalOutcome move = plc.Run(0);
    ASSERT_EQ(move.ErrorId(), kLibEndTimeout) << move;
    ASSERT_TRUE(plc.Controller().Axes().Motion(1).Moving());
    plc.Controller().Io().intRegisters.SetInt(5, 5);
    plc.Set(1, code::kGetIntReg, 5);
    plc.Fb(1)->TIMEOUT.value = pac::ToIecTime(5s);
    plc.Fb(1)->EXECUTE.value = TRUE;
    const auto& motion = plc.Controller().Axes().Motion(1);
    bool readSeen = false;
    bool readWhileMoving = false;
    for (int scan = 0; scan < 100000 && !Final(plc.Fb(1)); ++scan) {
        plc.Scan();
        if (!readSeen && plc.Seen(code::kGetIntReg, 5) > 0) {
            readSeen = true;
            readWhileMoving = motion.JobActive();
        }
    }
    EXPECT_FALSE(readWhileMoving) << "the read went out while the move was processing";
    EXPECT_TRUE(plc.Fb(1)->DONE.value) << "ErrorID " << std::hex << plc.Fb(1)->ERRORID.value;
    EXPECT_EQ(plc.Fb(1)->ACKDATA.value, 5u);
}

// The scans from FB 1's edge to the scan it sends, behind a move of FB 0 started in the same scan; then
// FB 1's outcome with the given Timeout.
struct QueuedRead {
    int waitScans = 0;
    FinalOutcome outcome;
};

QueuedRead ReadBehindAMove(const SharingCase& c, nanoseconds timeout) {
    SharedCmdPlc plc(c, 2);
    plc.Boot();
    QueuedRead result;
    if (!plc.GoOnline()) return result;
    plc.Set(0, code::kPosAxisAbsolute, 1, Bits(300.0F));
    plc.Set(1, code::kGetIntReg, 5);
    plc.Fb(1)->TIMEOUT.value = pac::ToIecTime(timeout);
    plc.Fb(0)->EXECUTE.value = TRUE;
    plc.Plc().Begin(plc.Fb(1));
    const auto edge = plc.Plc().Rig().Task().ScanCount();
    result.outcome = plc.Plc().Wait(plc.Fb(1), 100000, [&] {
        if (result.waitScans == 0 && plc.Fb(0)->DONE.value) {
            result.waitScans = static_cast<int>(plc.Plc().Rig().Task().ScanCount() - edge);
        }
    });
    return result;
}

// Defect 4: the wait for the interface and the wait for the acknowledgement are timed apart. A read that
// waited most of its Timeout behind a move is still acknowledged normally: Done, not 16#8001.
TEST_P(CmdRecovery, LongWaitForTheInterfaceLeavesTheAcknowledgementItsTimeout) {
    const auto plcCycle = GetParam().timing.PlcCycle();
    const QueuedRead measured = ReadBehindAMove(GetParam(), 10s);
    ASSERT_TRUE(measured.outcome.Done()) << measured.outcome;
    ASSERT_GT(measured.waitScans, 0);
    // Expires half a PLC cycle after the scan the read is sent in.
    const nanoseconds timeout = plcCycle * measured.waitScans + plcCycle / 2;
    const QueuedRead tight = ReadBehindAMove(GetParam(), timeout);
    EXPECT_EQ(tight.waitScans, measured.waitScans) << "the same run";
    EXPECT_TRUE(tight.outcome.Done()) << tight.outcome << " with Timeout " << timeout.count() << " ns";
}

// Defect 4: which ErrorID means what. 16#8006: the interface never became free, the command never reached
// the controller. 16#8001: sent, no acknowledgement seen, outcome unknown (here: executed).
TEST_P(CmdRecovery, ErrorIdsSayWhetherTheCommandWasSent) {
    const QueuedRead tooShort = ReadBehindAMove(GetParam(), 20ms);
    EXPECT_EQ(tooShort.outcome.ErrorId(), kLibInterfaceBusy) << tooShort.outcome;

    SharedCmdPlc plc(GetParam(), 2);
    plc.Boot();
    ASSERT_TRUE(plc.GoOnline());
    plc.Set(0, code::kPosAxisAbsolute, 1, Bits(300.0F));
    plc.Set(1, code::kGetIntReg, 5);
    plc.Fb(1)->TIMEOUT.value = pac::ToIecTime(20ms);
    plc.Fb(0)->EXECUTE.value = TRUE;
    plc.Fb(1)->EXECUTE.value = TRUE;
    for (int scan = 0; scan < 100000 && !Final(plc.Fb(1)); ++scan) plc.Scan();
    EXPECT_EQ(plc.Fb(1)->ERRORID.value, kLibInterfaceBusy);
    for (int scan = 0; scan < 100000 && !Final(plc.Fb(0)); ++scan) plc.Scan();
    plc.Scan(5);
    EXPECT_EQ(plc.Seen(code::kGetIntReg, 5), 0) << "16#8006: never sent";

    plc.Fb(1)->EXECUTE.value = FALSE;
    plc.Scan();
    plc.Plc().Rig().Bus().FromPacLink().SetFault(plc.Now(), pac::sim::LinkFault::kFrozen);
    plc.Set(1, code::kPutIntReg, 6, 66);
    plc.Fb(1)->TIMEOUT.value = pac::ToIecTime(100ms);
    const FinalOutcome unknown = plc.Run(1);
    EXPECT_EQ(unknown.ErrorId(), kLibAckTimeout) << unknown;
    EXPECT_EQ(plc.Seen(code::kPutIntReg, 6), 1) << "16#8001: sent, and here executed";
    plc.Plc().Rig().Bus().FromPacLink().SetFault(plc.Now(), pac::sim::LinkFault::kNone);
    plc.Set(1, code::kGetIntReg, 6);
    const FinalOutcome read = plc.Run(1);
    EXPECT_TRUE(read.Done()) << read;
    EXPECT_EQ(plc.Fb(1)->ACKDATA.value, 66u);
    EXPECT_EQ(plc.Seen(code::kPutIntReg, 6), 1) << "never repeated";
}

// Defect 6: T#0S is the default on FB_PAC_Cmd.Timeout: a read behind a move of some 0.4 s is Done (T#1S),
// where "fail at once" would end it 16#8006 in its edge scan.
TEST_P(CmdRecovery, TimeoutZeroIsTheDefaultSecond) {
    const QueuedRead zero = ReadBehindAMove(GetParam(), 0s);
    EXPECT_TRUE(zero.outcome.Done()) << zero.outcome;
    EXPECT_GT(zero.waitScans, 1);
}

INSTANTIATE_TEST_SUITE_P(Readings, CmdRecovery,
                         ::testing::ValuesIn(pac::test::OnEveryReading(pac::test::StandardAndJitteredBusTimings())),
                         pac::test::SharingCaseName);

}  // namespace
}  // namespace test_cmd_recovery_sim
