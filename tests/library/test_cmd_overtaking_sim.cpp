// Stops overtaking commands on one CMD interface against the simulated PA-CONTROL, scan by scan, on the bus
// timings of the library's tests, on every controller reading (controller_readings.hpp) and with the data
// written in one step or in two (FB_PAC_CmdInterface.TwoStepWrite, manual 4.2.4). The rule: an FB ends Done
// only for a command the controller took over and never with another FB's answer, a command that never
// went out ends 16#8016, a stop is never lost, and a stop whose acknowledgement is not seen keeps the
// interface until the controller shows it (issue 24, items 1 and 4; docs/fb/FB_PAC_Cmd.md).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <tuple>
#include <utility>

#include "bus_timing.hpp"
#include "controller_readings.hpp"
#include "gvl_constants.hpp"
#include "pac/iec_time.hpp"
#include "pac/sim/command_table.hpp"
#include "real_bits.hpp"
#include "shared_cmd_plc.hpp"

namespace test_cmd_overtaking_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using pac::test::SharedCmdPlc;
using pac::test::SharingCase;
namespace code = pac::sim::code;

const pac::test::GvlConstants kGvl;
const std::uint32_t kLibAckTimeout = kGvl["PAC_LIB_ERR_ACK_TIMEOUT"];
const std::uint32_t kLibEndTimeout = kGvl["PAC_LIB_ERR_END_TIMEOUT"];
const std::uint32_t kLibSuperseded = kGvl["PAC_LIB_ERR_SUPERSEDED"];
const std::uint32_t kLibOvertaken = kGvl["PAC_LIB_ERR_OVERTAKEN"];
const std::uint32_t kLibInterfaceBusy = kGvl["PAC_LIB_ERR_INTERFACE_BUSY"];

constexpr float kTarget = 400.0F;

std::uint32_t Bits(float value) { return pac::test::BitsOf(value); }

bool Final(pac::FbInstance<FB_PAC_CMD>& fb) { return fb->DONE.value || fb->ERROR.value; }

std::string WriteName(bool twoStep) { return twoStep ? "two-step write" : "one-step write"; }

// Scans until FB `i` shows a final output; false after maxScans.
bool ScanUntilFinal(SharedCmdPlc& plc, int i, int maxScans = 100000) {
    for (int scan = 0; scan < maxScans && !Final(plc.Fb(i)); ++scan) plc.Scan();
    return Final(plc.Fb(i));
}

// Every command the controller recognised from `from` on but the harmless 190B of a parked module, each at
// most once, and only the ones in `sent`.
void ExpectOnlySentCommandsOnce(SharedCmdPlc& plc, std::size_t from,
                                const std::set<std::tuple<std::uint16_t, std::uint16_t>>& sent) {
    std::set<std::tuple<std::uint16_t, std::uint16_t>> seen;
    const auto& commands = plc.CommandsSeen();
    for (std::size_t k = from; k < commands.size(); ++k) {
        const auto& c = commands[k];
        if (c.code == code::kGetState) continue;
        EXPECT_TRUE(sent.count({c.code, c.parameter}) == 1) << "command " << std::hex << c.code << " nobody sent";
        EXPECT_TRUE(seen.insert({c.code, c.parameter}).second) << "command " << std::hex << c.code << " twice";
    }
}

// Where an acknowledgement gets lost: the replies freeze (the controller took the command), or the module
// does (the controller does not read it). Freeze() freezes that link from now on and returns it.
std::string FreezeName(bool repliesFrozen) {
    return repliesFrozen ? ", the replies freeze" : ", the module freezes";
}
pac::sim::Link& Freeze(SharedCmdPlc& plc, bool repliesFrozen) {
    auto& link = repliesFrozen ? plc.Plc().Rig().Bus().FromPacLink() : plc.Plc().Rig().Bus().ToPacLink();
    link.SetFault(plc.Now(), pac::sim::LinkFault::kFrozen);
    return link;
}

// Whether `condition` held in the scan the controller first recognised `code` with `param`: Check() after
// every scan.
class AtFirstSight {
public:
    AtFirstSight(std::uint16_t code, std::uint16_t param, std::function<bool()> condition)
        : code_(code), param_(param), condition_(std::move(condition)) {}
    void Check(SharedCmdPlc& plc) {
        if (!seen_ && plc.Seen(code_, param_) > 0) {
            seen_ = true;
            held_ = condition_();
        }
    }
    bool Held() const { return held_; }

private:
    std::uint16_t code_;
    std::uint16_t param_;
    std::function<bool()> condition_;
    bool seen_ = false;
    bool held_ = false;
};

// One PLC program, online, the axis standing, ready for two command FBs.
struct OnlinePlc {
    OnlinePlc(const SharingCase& c, bool twoStep, int fbs) : plc(c, fbs) {
        plc.Plc().Rig().CmdInterface()->TWOSTEPWRITE.value = twoStep ? TRUE : FALSE;
        plc.Boot();
        online = plc.GoOnline();
        plc.Scan(2);
        before = plc.CommandsSeen().size();
    }
    SharedCmdPlc plc;
    bool online = false;
    std::size_t before = 0;
};

class CmdOvertaking : public ::testing::TestWithParam<SharingCase> {};

// Item 1: a move of axis 1 and a stop of that axis on two FBs, the stop's edge 0..4 scans after the move's,
// the stop's FB called after or before the move's, with the data written in one step or two. Whatever the
// interleaving, the stop reaches the controller once and ends Done; the move ends Done only at its target
// after the controller took it, 16#8007 if the controller took it and the stop ended it, 16#8016 if it never
// went out.
TEST_P(CmdOvertaking, StopAndMoveEdgedTogetherEachEndOnTheirOwnCommand) {
    for (const bool twoStep : {false, true}) {
        for (const std::uint16_t stop : {code::kStopAxis, code::kStopAxisMultiCmd}) {
            for (const bool stopFirst : {false, true}) {
                for (int delay = 0; delay <= 4; ++delay) {
                    SCOPED_TRACE(WriteName(twoStep) + ", stop " + std::to_string(stop) +
                                 (stopFirst ? ", stop's FB called first" : ", move's FB called first") +
                                 ", stop edged " + std::to_string(delay) + " scans after the move");
                    OnlinePlc online(GetParam(), twoStep, 2);
                    SharedCmdPlc& plc = online.plc;
                    ASSERT_TRUE(online.online);
                    const int moveFb = stopFirst ? 1 : 0;
                    const int stopFb = stopFirst ? 0 : 1;
                    plc.Set(moveFb, code::kPosAxisAbsolute, 1, Bits(kTarget));
                    plc.Set(stopFb, stop, 1);
                    plc.Fb(stopFb)->TIMEOUT.value = pac::ToIecTime(5s);
                    plc.Fb(moveFb)->EXECUTE.value = TRUE;
                    plc.Scan(delay);
                    plc.Fb(stopFb)->EXECUTE.value = TRUE;
                    ASSERT_TRUE(ScanUntilFinal(plc, moveFb));
                    ASSERT_TRUE(ScanUntilFinal(plc, stopFb));
                    auto& move = plc.Fb(moveFb);
                    const int moveSeen = plc.Seen(code::kPosAxisAbsolute, 1);
                    EXPECT_EQ(plc.Seen(stop, 1), 1) << "a stop is never lost";
                    EXPECT_TRUE(plc.Fb(stopFb)->DONE.value) << "ErrorID " << std::hex << plc.Fb(stopFb)->ERRORID.value;
                    if (move->DONE.value) {
                        EXPECT_EQ(moveSeen, 1) << "Done for a move the controller never took";
                        EXPECT_EQ(move->ACKDATA.value, Bits(kTarget)) << "Done with another command's answer";
                    } else if (move->ERRORID.value == kLibSuperseded) {
                        EXPECT_EQ(moveSeen, 1) << "16#8007 says the controller took the move";
                    } else {
                        EXPECT_EQ(move->ERRORID.value, kLibOvertaken) << std::hex << move->ERRORID.value;
                        EXPECT_EQ(moveSeen, 0) << "16#8016 says the move never went out";
                    }
                    if (stop == code::kStopAxis) {  // 0A9A ends at once, 0A93 when the axis stands (5.2.6.13)
                        EXPECT_TRUE(move->DONE.value || !plc.Controller().Axes().Motion(1).JobActive())
                            << "the axis still runs a job no FB follows";
                    }
                    ExpectOnlySentCommandsOnce(plc, online.before,
                                               {{code::kPosAxisAbsolute, 1}, {stop, 1}});
                }
            }
        }
    }
}

// Item 1, the same root cause between ordinary commands: two reads edged 0..2 scans apart, in either call
// order, one step or two; each FB ends Done with its own register's value.
TEST_P(CmdOvertaking, TwoCommandsEdgedTogetherEachEndWithItsOwnAnswer) {
    for (const bool twoStep : {false, true}) {
        for (const bool secondFirst : {false, true}) {
            for (int delay = 0; delay <= 2; ++delay) {
                SCOPED_TRACE(WriteName(twoStep) + (secondFirst ? ", FB 1 edged first" : ", FB 0 edged first") +
                             ", the other " + std::to_string(delay) + " scans later");
                OnlinePlc online(GetParam(), twoStep, 2);
                SharedCmdPlc& plc = online.plc;
                ASSERT_TRUE(online.online);
                plc.Controller().Io().intRegisters.SetInt(5, 55);
                plc.Controller().Io().intRegisters.SetInt(6, 66);
                plc.Set(0, code::kGetIntReg, 5);
                plc.Set(1, code::kGetIntReg, 6);
                const int first = secondFirst ? 1 : 0;
                plc.Fb(first)->EXECUTE.value = TRUE;
                plc.Scan(delay);
                plc.Fb(1 - first)->EXECUTE.value = TRUE;
                ASSERT_TRUE(ScanUntilFinal(plc, 0));
                ASSERT_TRUE(ScanUntilFinal(plc, 1));
                EXPECT_TRUE(plc.Fb(0)->DONE.value) << "ErrorID " << std::hex << plc.Fb(0)->ERRORID.value;
                EXPECT_TRUE(plc.Fb(1)->DONE.value) << "ErrorID " << std::hex << plc.Fb(1)->ERRORID.value;
                EXPECT_EQ(plc.Fb(0)->ACKDATA.value, 55u);
                EXPECT_EQ(plc.Fb(1)->ACKDATA.value, 66u);
                ExpectOnlySentCommandsOnce(plc, online.before, {{code::kGetIntReg, 5}, {code::kGetIntReg, 6}});
            }
        }
    }
}

// Item 4: a reference run of axis 1 processes, a stop of the axis overtakes it and its acknowledgement is
// not seen within the stop's Timeout (16#8001): the replies freeze, or the controller does not yet read the
// module. The stop stays in the module until the controller shows it: it reaches the controller once, the
// reference run's FB never ends Done for a run that was stopped, and a read queued meanwhile goes out only
// once the axis stands.
TEST_P(CmdOvertaking, StopWhoseAcknowledgementIsLostKeepsTheInterface) {
    for (const bool twoStep : {false, true}) {
        for (const bool repliesFrozen : {true, false}) {
            SCOPED_TRACE(WriteName(twoStep) + FreezeName(repliesFrozen));
            OnlinePlc online(GetParam(), twoStep, 3);
            SharedCmdPlc& plc = online.plc;
            ASSERT_TRUE(online.online);
            auto& axes = plc.Controller().Axes();
            const auto& motion = axes.Motion(1);
            axes.SetReferenceSwitch(1, -400.0);
            axes.Motion(1).Place(plc.Now(), 0.0);
            plc.Controller().Io().intRegisters.SetInt(5, 55);
            plc.Set(0, code::kPutStartReference, 1);
            plc.Fb(0)->EXECUTE.value = TRUE;
            for (int scan = 0; scan < 100000 && !plc.Fb(0)->ACKNOWLEDGED.value; ++scan) plc.Scan();
            plc.Scan(2);
            ASSERT_TRUE(plc.Fb(0)->BUSY.value && motion.HomingActive()) << "the reference run processes";

            auto& link = Freeze(plc, repliesFrozen);
            plc.Set(1, code::kStopAxis, 1);
            plc.Fb(1)->TIMEOUT.value = pac::ToIecTime(30ms);
            plc.Fb(1)->EXECUTE.value = TRUE;
            plc.Set(2, code::kGetIntReg, 5);
            plc.Fb(2)->TIMEOUT.value = pac::ToIecTime(10s);
            plc.Fb(2)->EXECUTE.value = TRUE;
            ASSERT_TRUE(ScanUntilFinal(plc, 1));
            EXPECT_EQ(plc.Fb(1)->ERRORID.value, kLibAckTimeout) << "no acknowledgement seen within 30 ms";
            link.SetFault(plc.Now(), pac::sim::LinkFault::kNone);

            AtFirstSight readWhileAxisRan(code::kGetIntReg, 5, [&] { return motion.JobActive(); });
            for (int scan = 0; scan < 100000 && !(Final(plc.Fb(0)) && Final(plc.Fb(2))); ++scan) {
                plc.Scan();
                readWhileAxisRan.Check(plc);
            }
            ASSERT_TRUE(Final(plc.Fb(0)) && Final(plc.Fb(2)));
            EXPECT_EQ(plc.Seen(code::kStopAxis, 1), 1) << "a stop is never lost";
            EXPECT_FALSE(motion.HomingActive());
            if (plc.Fb(0)->DONE.value) {
                EXPECT_TRUE(motion.Referenced()) << "Done for a reference run that was stopped";
            } else {
                EXPECT_EQ(plc.Fb(0)->ERRORID.value, kLibSuperseded) << std::hex << plc.Fb(0)->ERRORID.value;
            }
            EXPECT_FALSE(readWhileAxisRan.Held()) << "the read went out while the axis still ran a job";
            EXPECT_TRUE(plc.Fb(2)->DONE.value) << "ErrorID " << std::hex << plc.Fb(2)->ERRORID.value;
            EXPECT_EQ(plc.Fb(2)->ACKDATA.value, 55u);
            ExpectOnlySentCommandsOnce(plc, online.before,
                                       {{code::kPutStartReference, 1}, {code::kStopAxis, 1}, {code::kGetIntReg, 5}});
        }
    }
}

// Low item: after 16#8002 (EndTimeout) the move still runs in the controller. The interface stays its until
// END OF PROCESSING: a read waits; a stop of the axis still goes out at once, ends the move, and the read
// follows once the axis stands.
TEST_P(CmdOvertaking, AfterEndTimeoutOnlyAStopReachesTheMovingAxis) {
    for (const bool twoStep : {false, true}) {
        SCOPED_TRACE(WriteName(twoStep));
        OnlinePlc online(GetParam(), twoStep, 3);
        SharedCmdPlc& plc = online.plc;
        ASSERT_TRUE(online.online);
        const auto& motion = plc.Controller().Axes().Motion(1);
        plc.Controller().Io().intRegisters.SetInt(5, 55);
        plc.Set(0, code::kPosAxisAbsolute, 1, Bits(kTarget));
        plc.Fb(0)->ENDTIMEOUT.value = pac::ToIecTime(100ms);
        plc.Fb(0)->EXECUTE.value = TRUE;
        ASSERT_TRUE(ScanUntilFinal(plc, 0));
        ASSERT_EQ(plc.Fb(0)->ERRORID.value, kLibEndTimeout);
        ASSERT_TRUE(motion.Moving());
        plc.Set(1, code::kGetIntReg, 5);
        plc.Fb(1)->TIMEOUT.value = pac::ToIecTime(10s);
        plc.Fb(1)->EXECUTE.value = TRUE;
        plc.Scan(10);
        EXPECT_EQ(plc.Seen(code::kGetIntReg, 5), 0) << "the read went out while the move was processing";
        plc.Set(2, code::kStopAxis, 1);
        plc.Fb(2)->EXECUTE.value = TRUE;
        AtFirstSight stopWhileMoving(code::kStopAxis, 1, [&] { return motion.Moving(); });
        AtFirstSight readWhileAxisRan(code::kGetIntReg, 5, [&] { return motion.JobActive(); });
        for (int scan = 0; scan < 100000 && !(Final(plc.Fb(1)) && Final(plc.Fb(2))); ++scan) {
            plc.Scan();
            stopWhileMoving.Check(plc);
            readWhileAxisRan.Check(plc);
        }
        EXPECT_TRUE(stopWhileMoving.Held()) << "the stop reached the moving axis";
        EXPECT_TRUE(plc.Fb(2)->DONE.value) << "ErrorID " << std::hex << plc.Fb(2)->ERRORID.value;
        EXPECT_LT(plc.Fb(2)->ACKDATA.value, Bits(kTarget)) << "stopped short of the target";
        EXPECT_FALSE(readWhileAxisRan.Held()) << "the read went out while the axis still ran a job";
        EXPECT_TRUE(plc.Fb(1)->DONE.value) << "ErrorID " << std::hex << plc.Fb(1)->ERRORID.value;
    }
}

// One FB online, the module at SEND 1, and the controller restarted at once (boot time 0: it is back before
// the PLC may have seen its status 0), RECEIVE where the reading puts it.
struct RestartRun {
    explicit RestartRun(const SharingCase& c, bool twoStep) : online(c, twoStep, 1) {
        SharedCmdPlc& plc = online.plc;
        if (!online.online) return;
        if (!pac::sim::CommandFrame::Decode(plc.Module()).send) {  // an odd number of commands: SEND 1
            plc.Set(0, code::kGetIntReg, 5);
            ready = plc.Run(0).Done();
            plc.Fb(0)->EXECUTE.value = FALSE;
            plc.Scan();
        } else {
            ready = true;
        }
        before = plc.CommandsSeen().size();
        plc.Controller().PowerCycle(plc.Now());
    }
    OnlinePlc online;
    bool ready = false;
    std::size_t before = 0;
};

// The scan (counted from the restart, 1 = the first scan after it) in which FB_PAC_CmdInterface brings the
// module back in step with the controller ready (status not 0); 0 if none within `maxScans`, -1 if the
// run could not be prepared.
int ResyncScanAfterRestart(const SharingCase& c, bool twoStep, int maxScans) {
    RestartRun run(c, twoStep);
    SharedCmdPlc& plc = run.online.plc;
    if (!run.ready) return -1;
    for (int scan = 1; scan <= maxScans; ++scan) {
        const auto resyncs = plc.Channel().RESYNCS;
        plc.Scan();
        if (plc.Channel().RESYNCS != resyncs && plc.Plc().Rig().CmdInterface()->OPSTATUS.value != 0) return scan;
    }
    return 0;
}

// D3 (docs/verification.md): the controller restarts unseen and comes back out of step with the module; a
// 0600 edged in the scan FB_PAC_CmdInterface resynchronises, or in the scans after it, must not toggle in
// the resync's module write (the controller would never see the parked module in step, take the parked
// read or nothing, and answer with the RECEIVE the stop expects). Whatever the scan: the stop reaches the
// controller exactly once and ends Done (or with the restarted controller's refusal), never Done without
// the controller having taken it.
TEST_P(CmdOvertaking, StopEdgedInTheResyncScanIsNeverLost) {
    int scenarios = 0;
    for (const bool twoStep : {false, true}) {
        const int resync = ResyncScanAfterRestart(GetParam(), twoStep, 200);
        ASSERT_GE(resync, 0) << WriteName(twoStep) << ": not online";
        if (resync == 0) continue;  // this reading and timing never leave the module out of step with status
        ++scenarios;
        for (int offset = 0; offset <= 2; ++offset) {
            SCOPED_TRACE(WriteName(twoStep) + ", resync in scan " + std::to_string(resync) + " after the restart, "
                         "0600 edged " + std::to_string(offset) + " scans after it");
            RestartRun run(GetParam(), twoStep);
            SharedCmdPlc& plc = run.online.plc;
            ASSERT_TRUE(run.ready);
            plc.Scan(resync - 1);
            const auto resyncs = plc.Channel().RESYNCS;
            plc.Scan(offset);
            plc.Set(0, code::kStop, 0);
            plc.Fb(0)->TIMEOUT.value = pac::ToIecTime(5s);
            plc.Fb(0)->EXECUTE.value = TRUE;
            if (offset == 0) {
                plc.Scan();
                ASSERT_NE(plc.Channel().RESYNCS, resyncs) << "the 0600 was edged in the resync scan";
            }
            ASSERT_TRUE(ScanUntilFinal(plc, 0));
            // Done, or the restarted controller's own refusal (a command error number, below 16#8000).
            const auto& stop = plc.Fb(0);
            EXPECT_TRUE(stop->DONE.value || stop->ERRORID.value < 0x8000u) << "ErrorID " << std::hex << stop->ERRORID.value;
            EXPECT_EQ(plc.Seen(code::kStop, 0), 1) << "a stop is never lost (Done: "
                                                   << static_cast<int>(plc.Fb(0)->DONE.value) << ")";
            ExpectOnlySentCommandsOnce(plc, run.before, {{code::kStop, 0}});
        }
    }
    // A status-0 reply resynchronises nothing (it says nothing of RECEIVE): the module stays parked with SEND 1.
    // A controller that takes SEND <> RECEIVE for a new command takes that read when it is back; one that
    // takes a changed SEND starts from RECEIVE 0 = its last SEND and shows RECEIVE 0 with a status, so the
    // interface resynchronises with the controller ready. There the scenario must arise, or this test could
    // not fail.
    const auto& reading = GetParam().reading;
    if (GetParam().timing.plcMs == 1 && GetParam().timing.pacMs == 10 && GetParam().timing.latency == 3 &&
        GetParam().timing.jitterUs == 0 &&
        reading.newCommand == pac::sim::NewCommandRule::kSendChanged &&
        reading.receiveAfterRestart == pac::sim::ReceiveAfterRestart::kZero) {
        EXPECT_GT(scenarios, 0) << "no resync with the controller ready after the restart";
    }
}

// D1 (docs/verification.md): a Timeout shorter than the bus round trip, before the channel measured any.
// A write ends 16#8001 before its acknowledgement can arrive; the acknowledgement comes late, the interface
// resynchronises, and a read or a stop edged 0..12 scans after the 16#8001 must end Done only for a
// command the controller took, with its own answer.
TEST_P(CmdOvertaking, CommandAfterATimeoutBelowTheRoundTripEndsOnItsOwnCommand) {
    const auto& t = GetParam().timing;
    for (const bool twoStep : {false, true}) {
        for (const std::uint16_t next : {code::kGetIntReg, code::kStop}) {
            for (int delay = 0; delay <= 12; ++delay) {
                SCOPED_TRACE(WriteName(twoStep) + ", then " + (next == code::kStop ? std::string("0600") : std::string("1906")) + " edged " + std::to_string(delay) +
                             " scans after the 16#8001");
                // No command acknowledged before: the channel has measured no round trip yet.
                SharedCmdPlc plc(GetParam(), 2);
                plc.Plc().Rig().CmdInterface()->TWOSTEPWRITE.value = twoStep ? TRUE : FALSE;
                plc.Boot();
                plc.Controller().Io().intRegisters.SetInt(5, 55);
                plc.Set(0, code::kPutIntReg, 9, 99);
                plc.Fb(0)->TIMEOUT.value = pac::ToIecTime(t.PlcCycle());  // one scan: below every round trip
                plc.Fb(0)->EXECUTE.value = TRUE;
                ASSERT_TRUE(ScanUntilFinal(plc, 0));
                if (plc.Fb(0)->ERRORID.value != kLibAckTimeout) continue;  // acknowledged within a scan
                plc.Scan(delay);
                plc.Set(1, next, next == code::kStop ? 0 : 5);
                plc.Fb(1)->TIMEOUT.value = pac::ToIecTime(5s);
                plc.Fb(1)->EXECUTE.value = TRUE;
                ASSERT_TRUE(ScanUntilFinal(plc, 1));
                const std::uint16_t param = next == code::kStop ? 0 : 5;
                if (plc.Fb(1)->DONE.value) {
                    EXPECT_EQ(plc.Seen(next, param), 1) << "Done for a command the controller never took";
                    if (next == code::kGetIntReg) {
                        EXPECT_EQ(plc.Fb(1)->ACKDATA.value, 55u);
                    }
                }
                EXPECT_LE(plc.Seen(next, param), 1);
            }
        }
    }
}

// D1, the hold: a write whose acknowledgement is not seen within its Timeout (16#8001: the replies freeze,
// or the controller does not read the module) holds the interface until the reply shows its SEND flag. A
// read edged meanwhile is never sent (16#8006); a read edged once the link is back ends Done with its own
// answer. With the one-step write a controller that never read the write takes the read parked under its
// SEND flag instead, never the write later.
TEST_P(CmdOvertaking, WriteWhoseAcknowledgementIsLostHoldsTheInterfaceUntilItShows) {
    for (const bool twoStep : {false, true}) {
        for (const bool repliesFrozen : {true, false}) {
            SCOPED_TRACE(WriteName(twoStep) + FreezeName(repliesFrozen));
            OnlinePlc online(GetParam(), twoStep, 3);
            SharedCmdPlc& plc = online.plc;
            ASSERT_TRUE(online.online);
            plc.Controller().Io().intRegisters.SetInt(5, 55);
            auto& link = Freeze(plc, repliesFrozen);
            plc.Set(0, code::kPutIntReg, 9, 99);
            plc.Fb(0)->TIMEOUT.value = pac::ToIecTime(30ms);
            plc.Fb(0)->EXECUTE.value = TRUE;
            ASSERT_TRUE(ScanUntilFinal(plc, 0));
            EXPECT_EQ(plc.Fb(0)->ERRORID.value, kLibAckTimeout) << "no acknowledgement seen within 30 ms";
            plc.Set(1, code::kGetIntReg, 5);
            plc.Fb(1)->TIMEOUT.value = pac::ToIecTime(30ms);
            plc.Fb(1)->EXECUTE.value = TRUE;
            ASSERT_TRUE(ScanUntilFinal(plc, 1));
            EXPECT_EQ(plc.Fb(1)->ERRORID.value, kLibInterfaceBusy) << "sent into an interface out of step";
            link.SetFault(plc.Now(), pac::sim::LinkFault::kNone);

            plc.Set(2, code::kGetIntReg, 6);
            plc.Controller().Io().intRegisters.SetInt(6, 66);
            plc.Fb(2)->TIMEOUT.value = pac::ToIecTime(10s);
            plc.Fb(2)->EXECUTE.value = TRUE;
            ASSERT_TRUE(ScanUntilFinal(plc, 2));
            EXPECT_TRUE(plc.Fb(2)->DONE.value) << "ErrorID " << std::hex << plc.Fb(2)->ERRORID.value;
            EXPECT_EQ(plc.Fb(2)->ACKDATA.value, 66u);
            EXPECT_EQ(plc.Seen(code::kGetIntReg, 6), 1);
            EXPECT_EQ(plc.Seen(code::kGetIntReg, 5), 0) << "a command that ended 16#8006 was sent";
            if (repliesFrozen || twoStep) {
                EXPECT_EQ(plc.Seen(code::kPutIntReg, 9), 1) << "the controller read the write before the freeze";
            } else {
                EXPECT_EQ(plc.Seen(code::kPutIntReg, 9), 0) << "the write went out after its FB gave it up";
            }
            ExpectOnlySentCommandsOnce(plc, online.before,
                                       {{code::kPutIntReg, 9}, {code::kGetIntReg, 6}});
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Readings, CmdOvertaking,
                         ::testing::ValuesIn(pac::test::OnEveryReading(pac::test::StandardAndJitteredBusTimings())),
                         pac::test::SharingCaseName);

}  // namespace
}  // namespace test_cmd_overtaking_sim
