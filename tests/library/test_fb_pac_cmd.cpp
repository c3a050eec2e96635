// FB_PAC_Cmd against hand-written PA-CONTROL replies, scan by scan: the handshake rules of manual
// 2.4.2 and the PLCopen output rules, each at the exact scan it must happen in; every scan of every
// test also runs the PLCopen checker (plcopen_checker.hpp).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>

#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/scan_test.hpp"
#include "pac/st_program.hpp"
#include "plcopen_checker.hpp"
#include "plcopen_pins.hpp"

namespace test_fb_pac_cmd {  // apart from the names of the other sources in its unity batch
namespace {

using pac::test::CommandBusyBoundOf;
using pac::test::OutputsOf;
using pac::test::PlcOpenChecker;

using Image = std::array<std::uint8_t, 8>;

// The library's error codes by the names PLC programmers use (st/gvl/GVL_PAC.st).
const pac::test::GvlConstants kGvl;
const std::uint32_t kErrAckTimeout = kGvl["PAC_LIB_ERR_ACK_TIMEOUT"];
const std::uint32_t kErrNotReady = kGvl["PAC_LIB_ERR_NOT_READY"];
const std::uint32_t kErrConnectionLost = kGvl["PAC_LIB_ERR_CONNECTION_LOST"];
const std::uint32_t kErrInvalidCode = kGvl["PAC_LIB_ERR_INVALID_CODE"];
const std::uint32_t kErrInterfaceBusy = kGvl["PAC_LIB_ERR_INTERFACE_BUSY"];
const std::uint32_t kErrSuperseded = kGvl["PAC_LIB_ERR_SUPERSEDED"];

// A reply of the PA-CONTROL (2.4.2): acknowledgement data, FE + operating status, RF KF BF + error number.
Image Reply(bool rf, bool kf, bool bf, std::uint16_t errorNumber = 0, std::uint8_t status = 1,
            std::uint32_t data = 0, bool fe = false) {
    std::uint16_t word3 = static_cast<std::uint16_t>((rf ? 0x8000 : 0) | (kf ? 0x4000 : 0) | (bf ? 0x2000 : 0) |
                                                     (errorNumber & 0x1FFF));
    return {static_cast<std::uint8_t>(data >> 24), static_cast<std::uint8_t>(data >> 16),
            static_cast<std::uint8_t>(data >> 8),  static_cast<std::uint8_t>(data),
            static_cast<std::uint8_t>(fe ? 0x80 : 0), status,
            static_cast<std::uint8_t>(word3 >> 8), static_cast<std::uint8_t>(word3)};
}

class FbPacCmd : public pac::ScanTest {
protected:
    FbPacCmd() {
        fromPac_ = Reply(false, false, true);
        interface_->CHANNEL.value.FIRSTREADDONE = TRUE;  // past the cold start's first handshake (FbPacCmdColdStart)
        // A PLC program: the module into the channel, FB_PAC_CmdInterface, the command FB, the module out.
        task_.AddProgram([this] {
            ST_PAC_CMDCHANNEL& channel = interface_->CHANNEL.value;
            for (int i = 0; i < 8; ++i) channel.FROMPAC.table[i] = fromPac_[i];
            interface_();
            cmd_->CHANNEL.value = channel;
            cmd_();
            channel = cmd_->CHANNEL.value;
            for (int i = 0; i < 8; ++i) toPac_[i] = channel.TOPAC.table[i];
            checker_.Check(task_.ScanCount(), cmd_, CommandBusyBoundOf(cmd_, kDefaultCycleTime));
        });
    }

    void Request(std::uint16_t code, std::uint16_t param, std::uint32_t data, bool execute = true) {
        cmd_->CODE.value = code;
        cmd_->PARAM.value = param;
        cmd_->DATA.value = data;
        cmd_->EXECUTE.value = execute;
    }

    bool SendFlag() const { return (toPac_[6] & 0x80) != 0; }
    bool Done() const { return OutputsOf(cmd_).done; }
    bool Busy() const { return OutputsOf(cmd_).busy; }
    bool Error() const { return OutputsOf(cmd_).error; }

    pac::FbInstance<FB_PAC_CMDINTERFACE> interface_ = PAC_FB(FB_PAC_CMDINTERFACE);
    pac::FbInstance<FB_PAC_CMD> cmd_ = PAC_FB(FB_PAC_CMD);
    PlcOpenChecker checker_{"FB_PAC_Cmd"};
    Image fromPac_{};
    Image toPac_{};
};

TEST_F(FbPacCmd, IdleModuleIsNeverAllZero) {
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 0, 0x19, 0x0B}));
    EXPECT_FALSE(Busy());
    EXPECT_EQ(cmd_->OPSTATUS.value, 1);
}

TEST_F(FbPacCmd, EdgeWritesCommandAndToggledSendFlagInTheSameScan) {
    Cycle(2);
    Request(0x0906, 3, 333);
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0x00, 0x00, 0x01, 0x4D, 0x00, 0x03, 0x89, 0x06}));
    EXPECT_TRUE(Busy());
    EXPECT_FALSE(cmd_->ACKNOWLEDGED.value);
}

TEST_F(FbPacCmd, DoneInTheFirstScanThatShowsTheAcknowledgement) {
    Request(0x1906, 2, 0);
    Cycle(1);
    ASSERT_TRUE(SendFlag());
    Cycle(3);  // the controller has not answered yet
    EXPECT_TRUE(Busy());
    fromPac_ = Reply(true, false, true, 0, 1, 12345678);
    Cycle(1);
    EXPECT_TRUE(Done());
    EXPECT_TRUE(cmd_->ACKNOWLEDGED.value);
    EXPECT_EQ(cmd_->ACKDATA.value, 12345678u);
    EXPECT_EQ(cmd_->ERRORID.value, 0);
}

TEST_F(FbPacCmd, CommandErrorPassesThePacErrorNumberUnchanged) {
    Request(0x0A87, 1, 0x41200000);
    Cycle(1);
    fromPac_ = Reply(true, true, false, 43);
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(cmd_->ERRORID.value, 43);
    EXPECT_EQ(cmd_->ERRORSOURCE.value, E_PAC_ERRORSOURCE__PAC_ERRSRC_COMMAND);
    EXPECT_TRUE(cmd_->ACKNOWLEDGED.value);
}

TEST_F(FbPacCmd, LongCommandStaysBusyAcknowledgedUntilEndOfProcessing) {
    Request(0x0A87, 1, 0x41200000);
    Cycle(1);
    fromPac_ = Reply(true, false, false, 0, 31, 0x40000000);
    Cycle(1);
    EXPECT_TRUE(Busy());
    EXPECT_TRUE(cmd_->ACKNOWLEDGED.value);
    EXPECT_EQ(cmd_->ACKDATA.value, 0x40000000u);
    fromPac_ = Reply(true, false, false, 0, 31, 0x40A00000);
    Cycle(1);
    EXPECT_EQ(cmd_->ACKDATA.value, 0x40A00000u);  // follows the position
    fromPac_ = Reply(true, false, true, 0, 31, 0x41200000);
    Cycle(1);
    EXPECT_TRUE(Done());
    EXPECT_EQ(cmd_->ACKDATA.value, 0x41200000u);
}

TEST_F(FbPacCmd, LongCommandSupersededByAnotherCommandIsItsOwnError) {
    Request(0x0A87, 1, 0x41200000);
    Cycle(1);
    fromPac_ = Reply(true, false, false, 0, 31, 0x40000000);
    Cycle(1);
    ASSERT_TRUE(Busy());
    fromPac_ = Reply(false, false, true, 0, 31, 0x12345678);  // RECEIVE fell back: a newer command was served
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(cmd_->ERRORID.value, kErrSuperseded);
    EXPECT_EQ(cmd_->ACKDATA.value, 0x40000000u) << "the other command's data is not this command's";
}

TEST_F(FbPacCmd, NoAcknowledgementWithinTimeoutIsAnError) {
    cmd_->TIMEOUT.value = TIME{0, 10'000'000};
    Request(0x1906, 1, 0);
    Cycle(1);  // edge at t = 1 ms
    Cycle(9);
    EXPECT_TRUE(Busy()) << "t = 10 ms: 9 ms elapsed";
    Cycle(1);
    EXPECT_TRUE(Error()) << "t = 11 ms: 10 ms elapsed";
    EXPECT_EQ(cmd_->ERRORID.value, kErrAckTimeout);
}

TEST_F(FbPacCmd, FinalOutputHoldsWhileExecuteAndClearsWhenItFalls) {
    Request(0x1906, 1, 0);
    Cycle(1);
    fromPac_ = Reply(true, false, true);
    Cycle(5);
    EXPECT_TRUE(Done());
    cmd_->EXECUTE.value = FALSE;
    Cycle(1);
    EXPECT_FALSE(Done());
    EXPECT_FALSE(cmd_->ACKNOWLEDGED.value);
}

TEST_F(FbPacCmd, DoneShowsForExactlyOneScanWhenExecuteFellEarly) {
    Request(0x1906, 1, 0);
    Cycle(1);
    cmd_->EXECUTE.value = FALSE;
    Cycle(2);
    EXPECT_TRUE(Busy());
    fromPac_ = Reply(true, false, true);
    Cycle(1);
    EXPECT_TRUE(Done());
    Cycle(1);
    EXPECT_FALSE(Done());
    EXPECT_FALSE(Busy());
}

TEST_F(FbPacCmd, EdgeWhileBusyIsIgnored) {
    Request(0x1906, 1, 0);
    Cycle(1);
    cmd_->EXECUTE.value = FALSE;
    Cycle(1);
    Request(0x0906, 7, 99);
    Cycle(1);
    EXPECT_TRUE(SendFlag()) << "no second toggle";
    EXPECT_EQ(toPac_[7], 0x06) << "still the first command's code";
    EXPECT_EQ(toPac_[5], 1);
}

// A restarted PLC's module shows SEND = 0 while the controller last acknowledged SEND = 1. No FB owns a
// command, so FB_PAC_CmdInterface brings the module back in step without a command: the harmless 190B with
// SEND := RECEIVE, in one write on a bus with module consistency, then that read toggled and acknowledged, so
// that a controller comparing SEND with the image before has seen the flag the command toggles from. Nothing
// but that read can execute, and the queued command then goes with exactly one toggle.
TEST_F(FbPacCmd, AfterPlcRestartTheModuleIsResynchronisedWithoutACommand) {
    fromPac_ = Reply(true, false, true);  // the controller acknowledged SEND = 1 before the PLC restarted
    Request(0x1906, 1, 0);
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 0, 0x99, 0x0B})) << "parked, SEND follows RECEIVE: only 190B";
    EXPECT_TRUE(Busy());
    EXPECT_EQ(interface_->RESYNCS.value, 1u);
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 0, 0x19, 0x0B})) << "the parked read toggled";
    Cycle(2);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 0, 0x19, 0x0B})) << "no command before the read's acknowledgement";
    fromPac_ = Reply(false, false, true);
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 1, 0x99, 0x06})) << "one toggle: the queued command";
    fromPac_ = Reply(true, false, true, 0, 1, 5);
    Cycle(1);
    EXPECT_TRUE(Done());
    EXPECT_EQ(cmd_->ACKDATA.value, 5u);
    EXPECT_EQ(interface_->RESYNCS.value, 1u);
}

// Without module consistency (TwoStepWrite) the SEND flag never changes in the write that changes the data:
// first the parked module with the SEND flag it has, then SEND := RECEIVE, the read's toggle and its
// acknowledgement, then the command's data, then its toggle.
TEST_F(FbPacCmd, WithTwoStepWriteTheResyncWaitsAScanForTheParkedData) {
    interface_->TWOSTEPWRITE.value = TRUE;
    fromPac_ = Reply(true, false, true);
    Request(0x1906, 1, 0);
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 0, 0x19, 0x0B})) << "parked first, the SEND flag unchanged";
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 0, 0x99, 0x0B})) << "then SEND follows RECEIVE over it";
    EXPECT_EQ(interface_->RESYNCS.value, 1u);
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 0, 0x19, 0x0B})) << "the parked read toggled";
    fromPac_ = Reply(false, false, true);
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 1, 0x19, 0x06})) << "the command's data, the SEND flag unchanged";
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 1, 0x99, 0x06})) << "then its toggle";
}

// A reply with status 0 says nothing of RECEIVE (a restarting controller and a lost telegram look alike): the
// module stays parked under its SEND flag, and SEND follows RECEIVE once the controller shows it ready.
TEST_F(FbPacCmd, SendFlagFollowsReceiveFlagWhileTheControllerRestarts) {
    fromPac_ = Reply(false, false, true);
    Request(0x0906, 1, 7);
    Cycle(1);
    fromPac_ = Reply(true, false, true);
    Cycle(1);
    ASSERT_TRUE(Done());
    ASSERT_TRUE(SendFlag());
    cmd_->EXECUTE.value = FALSE;
    fromPac_ = Reply(false, false, false, 0, 0);  // restarting: status 0, RECEIVE back to 0
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 0, 0x99, 0x0B})) << "parked under its SEND flag: harmless 190B";
    EXPECT_EQ(interface_->RESYNCS.value, 0u) << "no resynchronisation on a status-0 reply";
    fromPac_ = Reply(false, false, true);  // booted
    Request(0x1906, 2, 0);
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 0, 0x19, 0x0B})) << "SEND := RECEIVE over the parked module";
    EXPECT_EQ(interface_->RESYNCS.value, 1u);
    EXPECT_TRUE(Busy());
    Cycle(1);
    EXPECT_FALSE(SendFlag()) << "a reply within a round trip (1 scan here) of the resync is not trusted";
    Cycle(1);
    EXPECT_TRUE(SendFlag()) << "then the next command is one clean toggle";
}

// A command still processing (RECEIVE = SEND, END OF PROCESSING 0, a code that acknowledges before its
// end) holds the interface: a new command waits its Timeout and ends 16#8006, never sent.
TEST_F(FbPacCmd, InterfaceThatNeverFreesIsAnErrorAfterTimeoutNeverSent) {
    cmd_->TIMEOUT.value = TIME{0, 5'000'000};
    Request(0x0A87, 1, 0x41200000);
    Cycle(1);
    fromPac_ = Reply(true, false, false, 0, 31);  // the move is acknowledged and runs
    Cycle(1);
    ASSERT_TRUE(Busy());
    ASSERT_TRUE(cmd_->ACKNOWLEDGED.value);
    // The program's next command on the same interface, while the move runs.
    pac::FbInstance<FB_PAC_CMD> read = PAC_FB(FB_PAC_CMD);
    read->TIMEOUT.value = TIME{0, 5'000'000};
    read->CODE.value = 0x1906;
    read->PARAM.value = 2;
    read->EXECUTE.value = TRUE;
    ST_PAC_CMDCHANNEL& channel = interface_->CHANNEL.value;
    int scans = 0;
    while (!read->ERROR.value && !read->DONE.value && scans < 20) {
        ++scans;
        Cycle(1);
        read->CHANNEL.value = channel;
        read();
        channel = read->CHANNEL.value;
        for (int i = 0; i < 8; ++i) toPac_[i] = channel.TOPAC.table[i];
        EXPECT_EQ(toPac_[7], 0x87) << "scan " << scans << ": the move's module stays, nothing else is sent";
    }
    EXPECT_TRUE(read->ERROR.value);
    EXPECT_EQ(read->ERRORID.value, kErrInterfaceBusy);
    EXPECT_EQ(scans, 6) << "Timeout 5 ms at 1 ms scans, counted from the edge";
    EXPECT_TRUE(Busy()) << "the move goes on";
}

TEST_F(FbPacCmd, ControllerRestartDuringCommandIsAnErrorNotAnAcknowledgement) {
    Request(0x1906, 1, 0);
    Cycle(1);  // SEND toggles to 1
    ASSERT_TRUE(SendFlag());
    fromPac_ = Reply(true, false, true);
    Cycle(1);
    ASSERT_TRUE(Done());
    Request(0x1906, 2, 0, false);
    Cycle(1);
    Request(0x1906, 2, 0);
    Cycle(1);  // SEND toggles to 0
    ASSERT_FALSE(SendFlag());
    fromPac_ = Reply(false, false, false, 0, 0);  // rebooting: status 0, RF = 0 = SEND
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(cmd_->ERRORID.value, kErrConnectionLost);
}

// Waiting for the interface is waiting for the controller too: status 0 there (a restart, a lost link) ends the
// wait at once instead of after Timeout, as "not ready": the command never went out.
TEST_F(FbPacCmd, ControllerRestartWhileWaitingForTheInterfaceIsAnError) {
    fromPac_ = Reply(true, false, false);  // RECEIVE 1, the module's SEND 0: not free until it is in step again
    Request(0x1906, 1, 0);
    Cycle(1);  // the interface brings SEND to RECEIVE over the parked module; the command still waits
    ASSERT_TRUE(Busy());
    ASSERT_EQ((toPac_[6] & 0x7F) << 8 | toPac_[7], 0x190B) << "the command waits: not on the module yet";
    fromPac_ = Reply(false, false, false, 0, 0);
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(cmd_->ERRORID.value, kErrNotReady);
    EXPECT_EQ((toPac_[6] & 0x7F) << 8 | toPac_[7], 0x190B) << "nothing was sent: the module stays parked";
}

// The parked module follows RECEIVE whichever value the controller last showed, once it shows it ready: a
// reply with status 0 that still carries RECEIVE 1 (the link, not the controller, is gone) changes nothing.
TEST_F(FbPacCmd, ParkedModuleTakesASetReceiveFlagToo) {
    Cycle(1);
    ASSERT_FALSE(SendFlag());
    fromPac_ = Reply(true, false, false, 0, 0);
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 0, 0x19, 0x0B})) << "status 0: parked under its SEND flag";
    fromPac_ = Reply(true, false, true);
    Request(0x1906, 2, 0);
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0, 0, 0, 0, 0, 0, 0x99, 0x0B})) << "SEND := RECEIVE = 1, harmless 190B";
    Cycle(1);
    EXPECT_FALSE(SendFlag()) << "the next command is one clean toggle, from 1 to 0";
}

// A long command refused after its acknowledgement (the move cannot be carried out): KF with the number.
TEST_F(FbPacCmd, CommandErrorAfterTheAcknowledgementOfALongCommand) {
    Request(0x0A87, 1, 0x41200000);
    Cycle(1);
    fromPac_ = Reply(true, false, false, 0, 31, 0x40000000);
    Cycle(1);
    ASSERT_TRUE(Busy());
    ASSERT_TRUE(cmd_->ACKNOWLEDGED.value);
    fromPac_ = Reply(true, true, false, 64, 31, 0x40400000);
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(cmd_->ERRORID.value, 64);
    EXPECT_EQ(cmd_->ERRORSOURCE.value, E_PAC_ERRORSOURCE__PAC_ERRSRC_COMMAND);
    EXPECT_EQ(cmd_->ACKDATA.value, 0x40400000u) << "where the move stopped";
}

// EndTimeout T#0S means the pin's default, 60 s (docs/fb/FB_PAC_Cmd.md): neither no wait nor an unbounded one.
TEST_F(FbPacCmd, EndTimeoutZeroMeansTheDefaultOfSixtySeconds) {
    const std::uint32_t kErrEndTimeout = kGvl["PAC_LIB_ERR_END_TIMEOUT"];
    cmd_->ENDTIMEOUT.value = TIME{0, 0};
    cmd_->TIMEOUT.value = TIME{0, 5'000'000};
    Request(0x0A87, 1, 0x41200000);
    Cycle(1);
    fromPac_ = Reply(true, false, false, 0, 31, 0x40000000);
    Cycle(1);
    ASSERT_TRUE(cmd_->ACKNOWLEDGED.value);
    Cycle(59'990);  // 1 ms scans: just under 60 s after the acknowledgement
    EXPECT_TRUE(Busy()) << "still waiting for END OF PROCESSING";
    EXPECT_FALSE(Error());
    Cycle(20);
    EXPECT_TRUE(Error()) << "60 s after the acknowledgement";
    EXPECT_EQ(cmd_->ERRORID.value, kErrEndTimeout);
}

// Timeout T#0S means the pin's default, 1 s, like EndTimeout: a command never waits without limit.
TEST_F(FbPacCmd, TimeoutZeroMeansTheDefaultOfOneSecond) {
    cmd_->TIMEOUT.value = TIME{0, 0};
    Request(0x1906, 1, 0);
    Cycle(1);  // edge and toggle at t = 1 ms; the controller never answers
    Cycle(999);
    EXPECT_TRUE(Busy()) << "t = 1000 ms: 999 ms elapsed";
    Cycle(1);
    EXPECT_TRUE(Error()) << "t = 1001 ms: 1 s elapsed";
    EXPECT_EQ(cmd_->ERRORID.value, kErrAckTimeout);
}

// COMMAND ERROR with error number 0 (a controller that sets KF without a number): Error never comes with
// ErrorID 0, so the library's 16#800F stands in (docs/fb/FB_PAC_Cmd.md).
TEST_F(FbPacCmd, CommandErrorWithoutANumberIsTheLibrarysCode) {
    Request(0x1906, 1, 0);
    Cycle(1);
    fromPac_ = Reply(true, true, false, 0);
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(cmd_->ERRORID.value, kGvl["PAC_LIB_ERR_NO_ERROR_NUMBER"]);
}

// The two-step write of Interbus-S (4.2.4): data in one scan, the SEND toggle in the next. A controller that
// restarts between the two scans gets no toggle: the command never went out, so it is "not ready".
TEST_F(FbPacCmd, TwoStepWriteSendsNoToggleToAControllerThatRestartedInBetween) {
    interface_->TWOSTEPWRITE.value = TRUE;
    Cycle(1);
    Request(0x0906, 3, 333);
    Cycle(1);
    ASSERT_EQ(toPac_, (Image{0x00, 0x00, 0x01, 0x4D, 0x00, 0x03, 0x09, 0x06})) << "the data, SEND unchanged";
    fromPac_ = Reply(false, false, false, 0, 0);
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(cmd_->ERRORID.value, kErrNotReady);
    EXPECT_FALSE(SendFlag()) << "no toggle";
}

// FB ids on the channel skip 0 when they wrap (0 is "no FB": an idle channel's InFlightId).
TEST_F(FbPacCmd, FbIdsSkipZeroWhenTheyWrap) {
    interface_->CHANNEL.value.NEXTID = 0xFFFF;
    Request(0x1906, 1, 0);
    Cycle(1);
    ASSERT_TRUE(Busy());
    EXPECT_EQ(interface_->CHANNEL.value.INFLIGHTID, 1);
    EXPECT_EQ(interface_->CHANNEL.value.NEXTID, 1);
}

// The history index is kept in 0..15 even when a program wrote something else into the channel: the
// handshake goes to entry 0 instead of outside the array.
TEST_F(FbPacCmd, HistoryIndexOutOfRangeStartsOverAtTheFirstEntry) {
    interface_->CHANNEL.value.HISTORYNEXT = 16;
    Request(0x0906, 3, 333);
    Cycle(1);
    fromPac_ = Reply(true, false, true, 0, 1, 333);
    Cycle(1);
    ASSERT_TRUE(Done());
    const ST_PAC_CMDCHANNEL& channel = interface_->CHANNEL.value;
    EXPECT_EQ(channel.HISTORY.table[0].CODE, 0x0906);
    EXPECT_EQ(channel.HISTORY.table[0].ACKDATA, 333u);
    EXPECT_EQ(channel.HISTORYNEXT, 1);
    EXPECT_EQ(channel.HISTORYCOUNT, 1u);
}

TEST_F(FbPacCmd, ControllerNotReadyRefusesTheCommandAndSendsNothing) {
    fromPac_ = Reply(false, false, false, 0, 0);
    Cycle(1);
    Request(0x1906, 1, 0);
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(cmd_->ERRORID.value, kErrNotReady);
    EXPECT_FALSE(SendFlag());
}

TEST_F(FbPacCmd, CodeWithBit15IsRefusedAndNothingIsSent) {
    Request(0x9906, 1, 0);
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(cmd_->ERRORID.value, kErrInvalidCode);
    EXPECT_FALSE(SendFlag());
    EXPECT_EQ(toPac_[7], 0x0B);
}

TEST_F(FbPacCmd, GoodCommandAfterCommandError) {
    Request(0x1906, 99, 0);
    Cycle(1);
    fromPac_ = Reply(true, true, false, 4);
    Cycle(1);
    ASSERT_TRUE(Error());
    cmd_->EXECUTE.value = FALSE;
    Cycle(1);
    EXPECT_FALSE(Error());
    EXPECT_EQ(cmd_->ERRORID.value, 0);
    Request(0x1906, 2, 0);
    Cycle(1);
    EXPECT_FALSE(SendFlag());
    fromPac_ = Reply(false, false, true, 0, 1, 7);
    Cycle(1);
    EXPECT_TRUE(Done());
    EXPECT_EQ(cmd_->ACKDATA.value, 7u);
}

// Two command FBs on one CMD interface: the second waits until the first is acknowledged.
class TwoFbPacCmd : public pac::ScanTest {
protected:
    TwoFbPacCmd() {
        interface_->CHANNEL.value.FIRSTREADDONE = TRUE;  // past the cold start's first handshake (FbPacCmdColdStart)
        task_.AddProgram([this] {
            ST_PAC_CMDCHANNEL& channel = interface_->CHANNEL.value;
            for (int i = 0; i < 8; ++i) channel.FROMPAC.table[i] = fromPac_[i];
            interface_();
            Call(first_);
            Call(second_);
            for (int i = 0; i < 8; ++i) toPac_[i] = channel.TOPAC.table[i];
            firstRules_.Check(task_.ScanCount(), first_, CommandBusyBoundOf(first_, kDefaultCycleTime));
            secondRules_.Check(task_.ScanCount(), second_, CommandBusyBoundOf(second_, kDefaultCycleTime));
        });
    }

    void Call(pac::FbInstance<FB_PAC_CMD>& fb) {
        fb->CHANNEL.value = interface_->CHANNEL.value;
        fb();
        interface_->CHANNEL.value = fb->CHANNEL.value;
    }

    pac::FbInstance<FB_PAC_CMDINTERFACE> interface_ = PAC_FB(FB_PAC_CMDINTERFACE);
    pac::FbInstance<FB_PAC_CMD> first_ = PAC_FB(FB_PAC_CMD);
    pac::FbInstance<FB_PAC_CMD> second_ = PAC_FB(FB_PAC_CMD);
    PlcOpenChecker firstRules_{"first FB_PAC_Cmd"};
    PlcOpenChecker secondRules_{"second FB_PAC_Cmd"};
    Image fromPac_ = Reply(false, false, true);
    Image toPac_{};
};

TEST_F(TwoFbPacCmd, SecondCommandWaitsForTheFirstAcknowledgement) {
    first_->CODE.value = 0x0906;
    first_->PARAM.value = 3;
    first_->DATA.value = 333;
    first_->EXECUTE.value = TRUE;
    second_->CODE.value = 0x1906;
    second_->PARAM.value = 2;
    second_->EXECUTE.value = TRUE;
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0x00, 0x00, 0x01, 0x4D, 0x00, 0x03, 0x89, 0x06})) << "the first command alone";
    EXPECT_TRUE(first_->BUSY.value);
    EXPECT_TRUE(second_->BUSY.value);
    fromPac_ = Reply(true, false, true, 0, 1, 333);
    Cycle(1);
    EXPECT_TRUE(first_->DONE.value);
    EXPECT_EQ(first_->ACKDATA.value, 333u);
    EXPECT_EQ(toPac_, (Image{0x00, 0x00, 0x00, 0x00, 0x00, 0x02, 0x19, 0x06})) << "second sent in the same scan";
    EXPECT_FALSE(second_->ACKNOWLEDGED.value) << "the first one's acknowledgement is not the second's";
    fromPac_ = Reply(false, false, true, 0, 1, 12345678);
    Cycle(1);
    EXPECT_TRUE(second_->DONE.value);
    EXPECT_EQ(second_->ACKDATA.value, 12345678u);
}

}  // namespace
}  // namespace test_fb_pac_cmd
