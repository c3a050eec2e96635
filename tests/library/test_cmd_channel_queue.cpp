// FB_PAC_CmdInterface keeps the queue of a shared CMD interface moving past command FBs that gave up or that
// the program no longer calls, and follows a command whose FB is away to its end; FB_PAC_Cmd refuses to
// run without it. Hand-written replies, scan by scan, three FBs on one channel called in a fixed order.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/scan_test.hpp"
#include "pac/st_program.hpp"
#include "plcopen_checker.hpp"
#include "plcopen_pins.hpp"

namespace test_cmd_channel_queue {  // apart from the names of the other sources in its unity batch
namespace {

using pac::test::CommandBusyBoundOf;
using pac::test::OutputsOf;
using pac::test::PlcOpenChecker;

const pac::test::GvlConstants kGvl;

constexpr std::uint16_t kGetStat = 0x190B;  // what a parked module carries

class CmdChannelQueue : public pac::ScanTest {
protected:
    static constexpr int kFbs = 3;

    CmdChannelQueue() {
        interface_->CHANNEL.value.FIRSTREADDONE = TRUE;  // past the cold start's first handshake (FbPacCmdColdStart)
        task_.AddProgram([this] {
            ST_PAC_CMDCHANNEL& channel = interface_->CHANNEL.value;
            channel.FROMPAC.table[0] = channel.FROMPAC.table[1] = channel.FROMPAC.table[2] = 0;
            channel.FROMPAC.table[3] = channel.FROMPAC.table[4] = 0;
            channel.FROMPAC.table[5] = status_;  // operating status
            channel.FROMPAC.table[6] = static_cast<std::uint8_t>((rf_ ? 0x80 : 0) | (bf_ ? 0x20 : 0));
            channel.FROMPAC.table[7] = 0;
            if (callInterface_) interface_();
            for (int i = 0; i < kFbs; ++i) {
                if (!called_[i]) continue;
                fbs_[i]->CHANNEL.value = channel;
                fbs_[i]();
                channel = fbs_[i]->CHANNEL.value;
                checkers_[i].Check(task_.ScanCount(), fbs_[i], CommandBusyBoundOf(fbs_[i], kDefaultCycleTime));
            }
        });
    }

    void Request(int fb, std::uint16_t code, std::uint16_t param = 0) {
        fbs_[fb]->CODE.value = code;
        fbs_[fb]->PARAM.value = param;
        fbs_[fb]->EXECUTE.value = TRUE;
    }

    // The PA-CONTROL of the next scan's reply: RECEIVE := SEND of the module (the command is taken over),
    // END OF PROCESSING as `ended` says.
    void Acknowledge(bool ended) {
        rf_ = SendFlag();
        bf_ = ended;
    }

    const ST_PAC_CMDCHANNEL& Channel() { return interface_->CHANNEL.value; }
    bool SendFlag() { return (Channel().TOPAC.table[6] & 0x80) != 0; }
    std::uint16_t ModuleCode() { return static_cast<std::uint16_t>((Channel().TOPAC.table[6] & 0x7F) << 8 | Channel().TOPAC.table[7]); }
    std::uint16_t ModuleParam() { return static_cast<std::uint16_t>(Channel().TOPAC.table[4] << 8 | Channel().TOPAC.table[5]); }
    bool Busy(int fb) { return OutputsOf(fbs_[fb]).busy; }
    bool Done(int fb) { return OutputsOf(fbs_[fb]).done; }

    pac::FbInstance<FB_PAC_CMDINTERFACE> interface_ = PAC_FB(FB_PAC_CMDINTERFACE);
    std::array<pac::FbInstance<FB_PAC_CMD>, kFbs> fbs_{PAC_FB(FB_PAC_CMD), PAC_FB(FB_PAC_CMD), PAC_FB(FB_PAC_CMD)};
    std::array<PlcOpenChecker, kFbs> checkers_{PlcOpenChecker("A"), PlcOpenChecker("B"), PlcOpenChecker("C")};
    std::array<bool, kFbs> called_{true, true, true};
    bool callInterface_ = true;
    bool rf_ = false;
    bool bf_ = true;
    std::uint8_t status_ = 1;  // ready (HOME POSITION)
};

// Without FB_PAC_CmdInterface nobody keeps the module in step or the queue moving: a command FB whose channel
// shows no new scan stops at once with 16#8010 instead of waiting its Timeout for nothing.
TEST_F(CmdChannelQueue, ACommandWithoutTheInterfaceCalledIsAnError) {
    rf_ = true;  // the module (SEND 0) is out of step: the command must wait
    Request(0, 0x1906, 1);
    Cycle(1);
    ASSERT_TRUE(Busy(0));
    callInterface_ = false;
    Cycle(1);
    EXPECT_TRUE(OutputsOf(fbs_[0]).error);
    EXPECT_EQ(fbs_[0]->ERRORID.value, kGvl["PAC_LIB_ERR_NO_INTERFACE"]);
}

// C's long command holds the interface (acknowledged, END OF PROCESSING 0) while A and B queue behind it. A
// gives up (its Timeout of 1 ms) before its turn: it ends with "never sent", the interface passes over its
// ticket, and B's command is the next on the module once C has ended.
TEST_F(CmdChannelQueue, ATicketThatGaveUpBeforeItsTurnIsPassedOver) {
    Request(2, 0x0A87, 3);
    Cycle(1);
    ASSERT_EQ(ModuleCode(), 0x0A87);
    Acknowledge(false);
    fbs_[0]->TIMEOUT.value = TIME{0, 1'000'000};
    Request(0, 0x1906, 1);
    Request(1, 0x1906, 2);
    Cycle(3);  // A's wait runs out while C processes
    ASSERT_TRUE(OutputsOf(fbs_[0]).error);
    EXPECT_EQ(fbs_[0]->ERRORID.value, kGvl["PAC_LIB_ERR_INTERFACE_BUSY"]) << "A: never sent";
    EXPECT_TRUE(Busy(1) && Busy(2));
    EXPECT_EQ(ModuleCode(), 0x0A87) << "nothing overtakes C's move";
    Acknowledge(true);  // C ends
    bool sentB = false;
    for (int scan = 0; scan < 4 && !sentB; ++scan) {
        Cycle(1);
        EXPECT_FALSE(ModuleCode() == 0x1906 && ModuleParam() == 1) << "A's command never goes out";
        sentB = ModuleCode() == 0x1906 && ModuleParam() == 2;
    }
    EXPECT_TRUE(sentB) << "B's command follows C's end within two scans of the parked module";
    EXPECT_TRUE(Done(2));
}

// A and B queue behind C's long command; then the program stops calling A. Once C has ended, A's ticket stays
// unclaimed for one whole free scan and is passed over: B goes, and A's command never does.
TEST_F(CmdChannelQueue, ATicketWhoseFbIsNoLongerCalledIsPassedOverAfterAScan) {
    Request(2, 0x0A87, 3);
    Cycle(1);
    Acknowledge(false);
    Request(0, 0x1906, 1);
    Request(1, 0x1906, 2);
    Cycle(2);
    EXPECT_EQ(interface_->WAITING.value, 2) << "A and B queue behind the move";
    called_[0] = false;
    Acknowledge(true);  // C ends
    int freeScansWithNothingSent = 0;
    bool sentB = false;
    for (int scan = 0; scan < 6 && !sentB; ++scan) {
        Cycle(1);
        EXPECT_FALSE(ModuleCode() == 0x1906 && ModuleParam() == 1) << "A's command never goes out";
        sentB = ModuleCode() == 0x1906 && ModuleParam() == 2;
        if (!sentB && ModuleCode() == kGetStat) ++freeScansWithNothingSent;
    }
    ASSERT_TRUE(sentB) << "B's command goes once A's ticket is passed over";
    EXPECT_GE(freeScansWithNothingSent, 1) << "A's turn is held for a whole free scan before it is passed over";
    EXPECT_EQ(interface_->WAITING.value, 1) << "B, counted by the interface before it took its turn";
    Cycle(1);
    EXPECT_EQ(interface_->WAITING.value, 0);
    // Called again, A queues anew behind B (its Timeout still counting from its edge) and goes after B's end.
    Acknowledge(true);
    called_[0] = true;
    bool sentA = false;
    for (int scan = 0; scan < 6 && !sentA; ++scan) {
        Cycle(1);
        sentA = ModuleCode() == 0x1906 && ModuleParam() == 1;
    }
    ASSERT_TRUE(sentA) << "A's command goes once it is called again";
    Acknowledge(true);
    Cycle(1);
    EXPECT_TRUE(Done(0)) << "A: " << OutputsOf(fbs_[0]);
}

// The calling contract's first case (docs/fb/FB_PAC_Cmd.md): A queues behind C's long command, and the program
// leaves A out until its Timeout (5 ms) has run out. Called again with the interface free, A ends with 16#8006
// and its command never goes out: its Timeout counts from the Execute edge, not from the call that finds a turn.
TEST_F(CmdChannelQueue, AnFbLeftOutBeforeItsTurnPastItsTimeoutEndsNeverSent) {
    Request(2, 0x0A87, 3);
    Cycle(1);
    Acknowledge(false);
    fbs_[0]->TIMEOUT.value = TIME{0, 5'000'000};
    Request(0, 0x1906, 1);
    Cycle(1);
    ASSERT_TRUE(Busy(0));
    called_[0] = false;
    Cycle(2);
    Acknowledge(true);  // C ends; A's ticket is passed over while A is away
    Cycle(10);
    ASSERT_EQ(ModuleCode(), kGetStat) << "the interface is free";
    called_[0] = true;
    for (int scan = 0; scan < 3; ++scan) {
        Cycle(1);
        EXPECT_FALSE(ModuleCode() == 0x1906 && ModuleParam() == 1) << "A's command goes out after its Timeout";
    }
    EXPECT_TRUE(OutputsOf(fbs_[0]).error) << "A: " << OutputsOf(fbs_[0]);
    EXPECT_EQ(fbs_[0]->ERRORID.value, kGvl["PAC_LIB_ERR_INTERFACE_BUSY"]) << "A: never sent";
}

// The calling contract (docs/fb/FB_PAC_Cmd.md): A's read goes out, and while the program leaves A out its Execute
// falls and rises again, with a new parameter. That is no edge for A: called again, it ends Done for the read it
// sent, the new parameter never goes out, and its Done holds while Execute stays TRUE.
TEST_F(CmdChannelQueue, AnExecuteThatFallsAndRisesWhileTheFbIsLeftOutIsNoEdge) {
    Request(0, 0x1906, 1);
    Cycle(1);
    ASSERT_EQ(ModuleParam(), 1);
    called_[0] = false;
    fbs_[0]->EXECUTE.value = FALSE;
    Cycle(1);
    fbs_[0]->EXECUTE.value = TRUE;
    fbs_[0]->PARAM.value = 5;
    Acknowledge(true);
    Cycle(2);
    called_[0] = true;
    for (int scan = 0; scan < 4; ++scan) {
        Cycle(1);
        EXPECT_TRUE(Done(0)) << "scan " << scan << ", A: " << OutputsOf(fbs_[0]);
        EXPECT_FALSE(ModuleCode() == 0x1906 && ModuleParam() == 5) << "a second command went out";
    }
    fbs_[0]->EXECUTE.value = FALSE;
    Cycle(1);
    EXPECT_FALSE(Done(0)) << "Done clears in the scan that sees Execute FALSE";
}

// A's move is acknowledged and runs; then the program stops calling A (a CASE step left). The interface follows
// the move to its end in A's absence: the module keeps the move, B waits while the reply shows it processing,
// B goes in the scan that shows its end, and A, called again after B's command ended too, finds its own outcome
// (Done, the end position) by its handshake number, not B's answer (issue 32, item 1).
TEST_F(CmdChannelQueue, ACommandWhoseFbIsNoLongerCalledIsFollowedToItsEndOfProcessing) {
    Request(0, 0x0A87, 1);
    Cycle(1);
    ASSERT_EQ(ModuleCode(), 0x0A87);
    Acknowledge(false);
    Cycle(1);
    ASSERT_TRUE(fbs_[0]->ACKNOWLEDGED.value);
    Request(1, 0x1906, 2);
    called_[0] = false;
    Cycle(7);
    EXPECT_TRUE(interface_->INFLIGHT.value) << "still A's move, A away or not";
    EXPECT_EQ(ModuleCode(), 0x0A87) << "the module keeps the move";
    EXPECT_TRUE(Busy(1)) << "B waits while the move runs";
    bf_ = true;  // the move ends
    Cycle(1);
    EXPECT_EQ(ModuleCode(), 0x1906) << "B goes in the scan that shows the move's end";
    EXPECT_EQ(ModuleParam(), 2);
    Acknowledge(true);
    Cycle(1);
    EXPECT_TRUE(Done(1));
    called_[0] = true;
    Cycle(1);
    EXPECT_TRUE(Done(0)) << "A: " << OutputsOf(fbs_[0]);
    EXPECT_TRUE(fbs_[0]->ACKNOWLEDGED.value);
}

// The program leaves A out after its move was acknowledged, and the move's END OF PROCESSING never comes: the
// interface waits no longer than A's EndTimeout, records 16#8002 for A and frees the interface; A, called again,
// ends with it.
TEST_F(CmdChannelQueue, AnAbsentFbsCommandIsWaitedForNoLongerThanItsEndTimeout) {
    fbs_[0]->ENDTIMEOUT.value = TIME{0, 3'000'000};
    Request(0, 0x0A87, 1);
    Cycle(1);
    Acknowledge(false);
    Cycle(1);
    ASSERT_TRUE(fbs_[0]->ACKNOWLEDGED.value);
    called_[0] = false;
    Cycle(3);
    EXPECT_TRUE(interface_->INFLIGHT.value) << "within EndTimeout of A's last call";
    Cycle(5);
    EXPECT_FALSE(interface_->INFLIGHT.value) << "freed after EndTimeout";
    called_[0] = true;
    Cycle(1);
    ASSERT_TRUE(OutputsOf(fbs_[0]).error) << "A: " << OutputsOf(fbs_[0]);
    EXPECT_EQ(fbs_[0]->ERRORID.value, kGvl["PAC_LIB_ERR_END_TIMEOUT"]);
}

// The program leaves A out after its read went out, and no acknowledgement comes: after A's Timeout the interface
// records 16#8001 for A and holds the interface as after A's own 16#8001 (the read parked under the same SEND
// flag), until the reply shows that flag; A, called again, ends with 16#8001.
TEST_F(CmdChannelQueue, AnAbsentFbsUnacknowledgedCommandIsHeldAfterItsTimeout) {
    fbs_[0]->TIMEOUT.value = TIME{0, 3'000'000};
    Request(0, 0x1906, 7);
    Cycle(1);
    ASSERT_EQ(ModuleCode(), 0x1906);
    const bool send = SendFlag();
    called_[0] = false;
    Cycle(8);
    EXPECT_TRUE(interface_->INFLIGHT.value) << "held for the late acknowledgement";
    EXPECT_EQ(ModuleCode(), kGetStat) << "the read parked over it";
    EXPECT_EQ(SendFlag(), send) << "under the same SEND flag";
    called_[0] = true;
    Cycle(1);
    ASSERT_TRUE(OutputsOf(fbs_[0]).error) << "A: " << OutputsOf(fbs_[0]);
    EXPECT_EQ(fbs_[0]->ERRORID.value, kGvl["PAC_LIB_ERR_ACK_TIMEOUT"]);
    Acknowledge(true);
    Cycle(1);
    EXPECT_FALSE(interface_->INFLIGHT.value) << "the acknowledgement frees it";
}

// A controller whose PLC cycle equals its own, with no bus latency: in the reply of the next scan it takes
// over a toggled module (RECEIVE := SEND), a move or a stop processes for three scans, anything else ends at
// once. It records the code of every command it took over.
class CmdChannelOvertaking : public CmdChannelQueue {
protected:
    CmdChannelOvertaking() { status_ = 31; }  // ONLINE: where moves run and stops may overtake them (5.2.6)

    void ControllerCycle(int n) {
        for (int i = 0; i < n; ++i) {
            Cycle(1);
            if (SendFlag() != rf_) {
                taken_.push_back(ModuleCode());
                const bool long_ = ModuleCode() == 0x0A84 || ModuleCode() == 0x0A87 || ModuleCode() == 0x0A93;
                Acknowledge(!long_);
                processing_ = long_ ? 3 : 0;
            } else if (processing_ > 0 && --processing_ == 0) {
                bf_ = true;
            }
        }
    }
    std::vector<std::uint16_t> taken_;
    int processing_ = 0;
};

// Issue 24, item 1: a move on A and a stop of its axis on B get their edges in one scan, A called first,
// with the two-step write. B overtakes A between A's data and A's toggle; only B's command may carry the
// toggle, and A, whose SEND flag never went out, ends 16#8016, never Done with the stop's answer.
TEST_F(CmdChannelOvertaking, AStopOvertakingAMoveBeforeItsToggleLeavesTheMoveNeverSent) {
    interface_->TWOSTEPWRITE.value = TRUE;
    ControllerCycle(2);
    Request(0, 0x0A87, 1);
    Request(1, 0x0A93, 1);
    ControllerCycle(10);
    EXPECT_EQ(taken_, std::vector<std::uint16_t>{0x0A93}) << "the controller took the stop alone";
    ASSERT_TRUE(OutputsOf(fbs_[0]).error) << "A: " << OutputsOf(fbs_[0]);
    EXPECT_EQ(fbs_[0]->ERRORID.value, kGvl["PAC_LIB_ERR_OVERTAKEN"]);
    EXPECT_FALSE(fbs_[0]->ACKNOWLEDGED.value);
    EXPECT_TRUE(Done(1)) << "B: " << OutputsOf(fbs_[1]);
}

// The same with B called first and its edge one scan after A's: FB_PAC_CmdInterface toggles A's move at the
// start of that scan, so B finds the move on its way and waits for its acknowledgement, then stops it. The stop
// is never lost, the controller takes each command once, and A ends with the stop's verdict over its move
// (16#8007), never Done with the stop's answer.
TEST_F(CmdChannelOvertaking, AStopCalledFirstAfterAMovesDataStopsTheMoveAndIsNeverLost) {
    interface_->TWOSTEPWRITE.value = TRUE;
    ControllerCycle(2);
    Request(1, 0x0A87, 1);
    ControllerCycle(1);
    Request(0, 0x0A93, 1);
    ControllerCycle(12);
    EXPECT_EQ(taken_, (std::vector<std::uint16_t>{0x0A87, 0x0A93})) << "the move, then its stop";
    EXPECT_TRUE(Done(0)) << "B: " << OutputsOf(fbs_[0]);
    ASSERT_TRUE(OutputsOf(fbs_[1]).error) << "A: " << OutputsOf(fbs_[1]);
    EXPECT_EQ(fbs_[1]->ERRORID.value, kGvl["PAC_LIB_ERR_SUPERSEDED"]);
}

// A stop is sent, and before its acknowledgement the program stops calling its FB. The interface does not
// park over it after the whole scan without a call, as it does for other commands: the stop stays in the
// module until the reply shows it taken over, and B's read follows its end.
TEST_F(CmdChannelQueue, AStopWhoseFbIsNoLongerCalledIsNeverWithdrawn) {
    Request(0, 0x0A93, 1);
    Cycle(1);
    ASSERT_EQ(ModuleCode(), 0x0A93);
    const bool stopSend = SendFlag();
    ASSERT_NE(stopSend, rf_);
    called_[0] = false;
    Request(1, 0x1906, 2);
    for (int scan = 0; scan < 5; ++scan) {
        Cycle(1);
        EXPECT_EQ(ModuleCode(), 0x0A93) << "scan " << scan << ": the stop is never withdrawn";
        EXPECT_EQ(SendFlag(), stopSend);
        EXPECT_TRUE(interface_->INFLIGHT.value);
    }
    Acknowledge(true);  // the controller takes the stop over; the axis stood already
    Cycle(1);
    EXPECT_EQ(ModuleCode(), 0x1906) << "B goes in the scan that shows the stop's end";
    EXPECT_EQ(ModuleParam(), 2);
}

// Issue 32, item 7: a stop goes out, and the next reply shows operating status 0 for one scan, before the
// controller read the stop. The stop's FB ends 16#8004 (whether the controller took it is unknown), but the
// stop stays in the module under its SEND flag: a controller that was only briefly not ready takes it when it
// reads the module, and nothing is parked over it meanwhile.
TEST_F(CmdChannelQueue, AStatusZeroBlipNeverWithdrawsAStop) {
    status_ = 31;  // ONLINE: where the move runs and the stop of its axis may overtake it
    Request(0, 0x0A87, 1);
    Cycle(1);
    Acknowledge(false);
    Cycle(1);
    Request(1, 0x0A93, 1);
    Cycle(1);
    ASSERT_EQ(ModuleCode(), 0x0A93);
    const bool stopSend = SendFlag();
    ASSERT_NE(stopSend, rf_);
    status_ = 0;
    Cycle(1);
    status_ = 31;
    EXPECT_TRUE(OutputsOf(fbs_[1]).error) << "B: " << OutputsOf(fbs_[1]);
    EXPECT_EQ(fbs_[1]->ERRORID.value, kGvl["PAC_LIB_ERR_CONNECTION_LOST"]);
    for (int scan = 0; scan < 5; ++scan) {
        Cycle(1);
        EXPECT_EQ(ModuleCode(), 0x0A93) << "scan " << scan << ": the stop is never withdrawn";
        EXPECT_EQ(SendFlag(), stopSend);
    }
    Acknowledge(true);  // the controller reads the module: it takes the stop
    Cycle(2);
    EXPECT_EQ(ModuleCode(), kGetStat) << "parked once the stop is taken and ended";
}

// Issue 24, item 4: A's reference run processes, B's stop of the axis overtakes it and no acknowledgement
// comes within B's Timeout (16#8001). The stop stays in the module and the interface stays held: C's read
// does not go out, nor is a read parked over the stop, until the reply shows the stop taken over and ended.
TEST_F(CmdChannelQueue, AStopWhoseAcknowledgementIsLostHoldsTheInterfaceUntilTheReplyShowsIt) {
    status_ = 31;  // ONLINE: where the reference run runs and the stop of its axis may overtake it
    Request(0, 0x0A84, 1);
    Cycle(1);
    Acknowledge(false);
    Cycle(1);
    ASSERT_TRUE(fbs_[0]->ACKNOWLEDGED.value && Busy(0)) << "the reference run processes";
    fbs_[1]->TIMEOUT.value = TIME{0, 1'000'000};
    Request(1, 0x0A93, 1);
    Cycle(1);
    ASSERT_EQ(ModuleCode(), 0x0A93);
    const bool stopSend = SendFlag();
    ASSERT_NE(stopSend, rf_);
    Request(2, 0x1906, 5);
    Cycle(3);
    ASSERT_TRUE(OutputsOf(fbs_[1]).error);
    EXPECT_EQ(fbs_[1]->ERRORID.value, kGvl["PAC_LIB_ERR_ACK_TIMEOUT"]);
    for (int scan = 0; scan < 10; ++scan) {
        Cycle(1);
        EXPECT_EQ(ModuleCode(), 0x0A93) << "scan " << scan << ": the stop is never withdrawn";
        EXPECT_EQ(SendFlag(), stopSend);
        EXPECT_TRUE(interface_->INFLIGHT.value);
    }
    EXPECT_TRUE(Busy(2)) << "C waits";
    Acknowledge(false);  // the controller takes the stop over: the axis brakes
    Cycle(1);
    EXPECT_EQ(fbs_[0]->ERRORID.value, kGvl["PAC_LIB_ERR_SUPERSEDED"]) << "the reference run was stopped";
    Cycle(5);
    EXPECT_NE(ModuleCode(), 0x1906) << "C waits while the stop processes";
    bf_ = true;  // the axis stands
    Cycle(1);
    EXPECT_EQ(ModuleCode(), 0x1906);
    EXPECT_EQ(ModuleParam(), 5);
}

}  // namespace
}  // namespace test_cmd_channel_queue
