// The FBs for the rest of chapter 5 (docs/commands.md) and the moves that keep the CMD interface free
// (docs/fb/axis_following.md), against the simulated PA-CONTROL over the simulated bus on the timings of
// the parameter and axis FBs: PLC cycle 1 and 5 ms, controller cycle 3 and 10 ms, latency 0 and 2 PLC
// cycles each way. Every FB sits on the one CMD interface, as in a PLC program; the PLCopen outputs of the
// Execute-driven FBs are checked in every scan (plcopen_checker.hpp).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <functional>

#include "bus_timing.hpp"
#include "command_plc.hpp"
#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/st_program.hpp"
#include "real_bits.hpp"
#include "run_to_final.hpp"

namespace test_command_set_fbs {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using std::chrono::nanoseconds;

const pac::test::GvlConstants kGvl;

using pac::test::BusTiming;
using pac::test::FinalOutcome;

std::uint32_t Bits(float value) { return pac::test::BitsOf(value); }

// A command error number (manual 6.5) the simulator answers a command with, to see it passed through unchanged.
constexpr std::uint16_t kInjectedErrorNumber = 21;
// The simulator's axis error for a servo that cannot follow.
constexpr std::uint16_t kFollowingErrorNumber = 66;

class CommandSetRig {
public:
    explicit CommandSetRig(const BusTiming& t, pac::sim::PaControlConfig config = {}) : plc_(t, config) {
        plc_.Add("WriteSystemParameter", writeSys);
        plc_.Add("ModeCommand", mode);
        plc_.Add("MoveAxisAbsolute", moveAbs);
        plc_.Add("MoveAxisRelative", moveRel);
        plc_.Add("StopAxis", stop);
        plc_.Add("ReadIntReg", readN);
        plc_.Add("ReadAxisStatus", readStatus);
        plc_.Add("SetAxisReference", reference);
        plc_.Add("SwitchAxis", switchAxis);
        plc_.Add("SetMeasuringMode", measuring);
        plc_.Add("SetLimitSwitchMonitoring", monitoring);
        plc_.Add("SetMoveCondition", condition);
        plc_.Add("ReadAxisValue", readValue);
        plc_.Add("ReadExtendedAxisStatus", readExtended);
        plc_.Rig().Call(jog);  // level-driven: no Execute for the PLCopen checker
        plc_.Start();
        for (int i = 0; i < 1000 && !Controller().Booted(); ++i) plc_.Scan();
        plc_.Scan(3 + 2 * t.latency);
    }

    template <class Fb>
    FinalOutcome Run(pac::FbInstance<Fb>& fb, int maxScans = 20000) { return plc_.Run(fb, maxScans); }
    template <class Fb>
    void Start(pac::FbInstance<Fb>& fb) { plc_.Begin(fb); }
    template <class Fb>
    FinalOutcome Wait(pac::FbInstance<Fb>& fb, int maxScans = 20000, const std::function<void()>& eachScan = {}) {
        return plc_.Wait(fb, maxScans, eachScan);
    }
    template <class Fb>
    void Release(pac::FbInstance<Fb>& fb) { plc_.Release(fb); }

    // ONLINE as 5.2.1.3 asks: system parameter 4 names the external stop input, it has power, then 0603.
    bool GoOnline() {
        writeSys->PARAMETERNUMBER.value = 4;
        writeSys->VALUE.value = 7;
        if (!Run(writeSys).Done()) return false;
        Controller().Io().inputs.Set(7, true);
        mode->COMMAND.value = E_PAC_MODECOMMAND__PAC_MODE_START_ONLINE;
        if (!Run(mode).Done()) return false;
        return Controller().OperatingStatus() == 31;
    }
    // Axis 1 to `position` by 0A94, followed by 1910 (FreeInterface).
    void AimFollowedMove(float position) {
        moveAbs->AXIS.value = 1;
        moveAbs->POSITION.value = position;
        moveAbs->FREEINTERFACE.value = TRUE;
    }
    // Axis 2 to `position` by 0A87, which holds the CMD interface to its end (5.2.6.6): other commands queue.
    void StartInterfaceHoldingMove(float position) {
        moveAbs->AXIS.value = 2;
        moveAbs->POSITION.value = position;
        moveAbs->FREEINTERFACE.value = FALSE;
        Start(moveAbs);
    }
    // Axis 1 toward `target` by 0A90, once Traverse rises.
    void AimJog(float target) {
        jog->AXIS.value = 1;
        jog->TARGET.value = target;
    }
    // Scans while `more` holds, at most `limit`.
    void ScanWhile(const std::function<bool()>& more, int limit = 20000) {
        for (int i = 0; i < limit && more(); ++i) plc_.Scan();
    }
    void Settle(int scans) { plc_.Scan(scans); }
    void SettleFor(nanoseconds t) { plc_.Scan(plc_.Timing().ScansFor(t)); }
    pac::sim::PaControl& Controller() { return plc_.Controller(); }
    pac::sim::ServoAxis& Motion(int axis) { return Controller().Axes().Motion(axis); }
    std::uint64_t Count(std::uint16_t code) { return Controller().Counters().Count(code); }
    // The code of the newest command the controller recognised.
    std::uint16_t LastCode() { return pac::sim::ReadWord(plc_.LastCommandSeen(), 3) & 0x7FFF; }
    std::uint32_t LastData() { return pac::sim::ReadDword(plc_.LastCommandSeen(), 0); }
    nanoseconds Now() const { return plc_.Now(); }

    pac::FbInstance<FB_PAC_WRITESYSTEMPARAMETER> writeSys = PAC_FB(FB_PAC_WRITESYSTEMPARAMETER);
    pac::FbInstance<FB_PAC_MODECOMMAND> mode = PAC_FB(FB_PAC_MODECOMMAND);
    pac::FbInstance<FB_PAC_MOVEAXISABSOLUTE> moveAbs = PAC_FB(FB_PAC_MOVEAXISABSOLUTE);
    pac::FbInstance<FB_PAC_MOVEAXISRELATIVE> moveRel = PAC_FB(FB_PAC_MOVEAXISRELATIVE);
    pac::FbInstance<FB_PAC_STOPAXIS> stop = PAC_FB(FB_PAC_STOPAXIS);
    pac::FbInstance<FB_PAC_READINTREG> readN = PAC_FB(FB_PAC_READINTREG);
    pac::FbInstance<FB_PAC_READAXISSTATUS> readStatus = PAC_FB(FB_PAC_READAXISSTATUS);
    pac::FbInstance<FB_PAC_SETAXISREFERENCE> reference = PAC_FB(FB_PAC_SETAXISREFERENCE);
    pac::FbInstance<FB_PAC_SWITCHAXIS> switchAxis = PAC_FB(FB_PAC_SWITCHAXIS);
    pac::FbInstance<FB_PAC_SETMEASURINGMODE> measuring = PAC_FB(FB_PAC_SETMEASURINGMODE);
    pac::FbInstance<FB_PAC_SETLIMITSWITCHMONITORING> monitoring = PAC_FB(FB_PAC_SETLIMITSWITCHMONITORING);
    pac::FbInstance<FB_PAC_SETMOVECONDITION> condition = PAC_FB(FB_PAC_SETMOVECONDITION);
    pac::FbInstance<FB_PAC_READAXISVALUE> readValue = PAC_FB(FB_PAC_READAXISVALUE);
    pac::FbInstance<FB_PAC_READEXTENDEDAXISSTATUS> readExtended = PAC_FB(FB_PAC_READEXTENDEDAXISSTATUS);
    pac::FbInstance<FB_PAC_JOGAXIS> jog = PAC_FB(FB_PAC_JOGAXIS);

private:
    pac::test::CommandPlc plc_;
};

class CommandSetFbs : public ::testing::TestWithParam<BusTiming> {};

// ---- 0A94 / 0A95 / 0A9A followed by 1910 (5.2.6.14, 5.2.6.15, 5.2.6.19; issue 10 defect 1) ----

// 5.2.6.14: 0A94 ends its processing at once, so a read may follow during the move; the FB reports Done only
// when 1910 says "in position" (5.2.4.22: 0), with the end position.
TEST_P(CommandSetFbs, FreeInterfaceMoveLetsAReadThroughAndIsDoneOnlyInPosition) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.Controller().Io().intRegisters.SetInt(5, -4711);
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 600.0F;  // about 0.7 s at 1000 AE/s
    rig.moveAbs->FREEINTERFACE.value = TRUE;
    rig.Start(rig.moveAbs);
    rig.ScanWhile([&] { return !rig.moveAbs->ACTIVE.value && rig.moveAbs->BUSY.value; });
    ASSERT_TRUE(rig.moveAbs->ACTIVE.value);
    EXPECT_EQ(rig.Count(0x0A94), 1u);
    EXPECT_EQ(rig.Count(0x0A87), 0u);

    rig.readN->NUMBER.value = 5;
    rig.Start(rig.readN);
    bool doneWhileMoving = true;
    FinalOutcome read = rig.Wait(rig.readN, 5000);
    doneWhileMoving = rig.Motion(1).Moving();
    rig.Release(rig.readN);
    ASSERT_TRUE(read.Done()) << read;
    EXPECT_EQ(rig.readN->VALUE.value, -4711);
    EXPECT_TRUE(doneWhileMoving) << "the read went through during the move";
    EXPECT_TRUE(rig.moveAbs->BUSY.value) << "the move is still followed";

    bool doneBeforeArrival = false;
    FinalOutcome move = rig.Wait(rig.moveAbs, 20000, [&] {
        if (rig.moveAbs->DONE.value && rig.Motion(1).Status() != pac::sim::AxisStatus::kInPosition) {
            doneBeforeArrival = true;
        }
    });
    ASSERT_TRUE(move.Done()) << move;
    EXPECT_FALSE(doneBeforeArrival);
    EXPECT_EQ(rig.Motion(1).Position(), 600.0);
    EXPECT_EQ(Bits(rig.moveAbs->ACTUALPOSITION.value), Bits(600.0F)) << "the end position, read by 190C";
    EXPECT_GE(rig.Count(0x1910), 2u);
    EXPECT_EQ(rig.LastCode(), 0x190C);
    rig.Release(rig.moveAbs);
    EXPECT_FALSE(rig.moveAbs->DONE.value);
}

TEST_P(CommandSetFbs, FreeInterfaceRelativeMoveSendsTheManualsCode) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.Motion(2).Place(rig.Now(), 100.0);
    rig.moveRel->AXIS.value = 2;
    rig.moveRel->DISTANCE.value = 10.0F;  // 5.2.6.15 example: by 10.0
    rig.moveRel->FREEINTERFACE.value = TRUE;
    FinalOutcome move = rig.Run(rig.moveRel);
    ASSERT_TRUE(move.Done()) << move;
    EXPECT_EQ(rig.Count(0x0A95), 1u);
    EXPECT_EQ(rig.Motion(2).Position(), 110.0);
    EXPECT_EQ(rig.moveRel->ACTUALPOSITION.value, 110.0F);
}

// A stop ends the job: CommandAborted, as for 0A87, because the controller no longer runs it. 0A9A with
// FreeInterface is Done when the axis stands.
TEST_P(CommandSetFbs, StopDuringAFollowedMoveAbortsItAndTheFreeStopIsDoneAtStandstill) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 2000.0F;
    rig.moveAbs->FREEINTERFACE.value = TRUE;
    rig.Start(rig.moveAbs);
    rig.ScanWhile([&] { return rig.Motion(1).Position() < 100.0; });
    rig.stop->AXIS.value = 1;
    rig.stop->FREEINTERFACE.value = TRUE;
    rig.Start(rig.stop);
    bool stopDoneWhileMoving = false;
    FinalOutcome stopped = rig.Wait(rig.stop, 20000, [&] {
        if (rig.stop->DONE.value && rig.Motion(1).Moving()) stopDoneWhileMoving = true;
    });
    ASSERT_TRUE(stopped.Done()) << stopped;
    EXPECT_FALSE(stopDoneWhileMoving);
    EXPECT_EQ(rig.Count(0x0A9A), 1u);
    EXPECT_EQ(rig.Count(0x0A93), 0u);
    EXPECT_EQ(Bits(rig.stop->ACTUALPOSITION.value), Bits(static_cast<float>(rig.Motion(1).Position())));
    FinalOutcome move = rig.Wait(rig.moveAbs, 20000);
    EXPECT_TRUE(move.Aborted()) << move;
    EXPECT_FALSE(move.Error());
    EXPECT_LT(rig.Motion(1).Position(), 2000.0);
}

TEST_P(CommandSetFbs, FollowedMoveNotInPositionWithinEndTimeoutIsTheLibrarysError) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 3000.0F;
    rig.moveAbs->FREEINTERFACE.value = TRUE;
    rig.moveAbs->ENDTIMEOUT.value = pac::ToIecTime(300ms);
    FinalOutcome move = rig.Run(rig.moveAbs);
    EXPECT_TRUE(move.Error()) << move;
    EXPECT_EQ(move.ErrorId(), kGvl["PAC_LIB_ERR_NOT_IN_POSITION"]);
    EXPECT_EQ(kGvl["PAC_LIB_ERR_NOT_IN_POSITION"], 0x8014u);
    EXPECT_TRUE(rig.Motion(1).Moving()) << "the library stops following, not the axis";
    // A refused start is the controller's number (43 without reference).
    rig.Motion(2).SetReferenced(false);
    rig.moveAbs->AXIS.value = 2;
    rig.moveAbs->POSITION.value = 10.0F;
    EXPECT_EQ(rig.Run(rig.moveAbs).ErrorId(), kGvl["PAC_ERR_NO_REFERENCE"]);
}

// T#0S on PollInterval and EndTimeout means their defaults (20 ms, 60 s): the move is followed to its end, not
// cut off at once by an end time of zero, and the status is read every 20 ms, not in every scan.
TEST_P(CommandSetFbs, FollowedMoveWithZeroTimesUsesTheDefaults) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.AimFollowedMove(300.0F);
    rig.moveAbs->POLLINTERVAL.value = pac::ToIecTime(0ms);
    rig.moveAbs->ENDTIMEOUT.value = pac::ToIecTime(0ms);
    const nanoseconds start = rig.Now();
    FinalOutcome move = rig.Run(rig.moveAbs);
    ASSERT_TRUE(move.Done()) << move;
    EXPECT_EQ(rig.Motion(1).Position(), 300.0);
    const auto pauses = (rig.Now() - start) / 20ms;
    EXPECT_LE(rig.Count(0x1910), static_cast<std::uint64_t>(pauses) + 1u) << "at most one read per 20 ms pause";
}

// 5.2.4.22 read refused: the controller's number is the FB's ErrorID, and following stops there (no 190C).
TEST_P(CommandSetFbs, FollowedMoveStatusReadRefusedIsThatError) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.AimFollowedMove(600.0F);
    rig.Start(rig.moveAbs);
    rig.ScanWhile([&] { return !rig.moveAbs->ACTIVE.value && rig.moveAbs->BUSY.value; });
    ASSERT_TRUE(rig.moveAbs->ACTIVE.value);
    rig.Controller().InjectCommandError(kInjectedErrorNumber);  // the next command: the first 1910
    FinalOutcome move = rig.Wait(rig.moveAbs);
    EXPECT_TRUE(move.Error()) << move;
    EXPECT_EQ(move.ErrorId(), kInjectedErrorNumber);
    EXPECT_EQ(rig.LastCode(), 0x1910);
    const std::uint64_t reads = rig.Count(0x1910);
    rig.SettleFor(200ms);
    EXPECT_EQ(rig.Count(0x1910), reads) << "no read after the error";
    EXPECT_EQ(rig.Count(0x190C), 0u);
}

// 5.2.4.22 status 4 (standing with malfunction): the axis will not arrive; 16#800A, no position read.
TEST_P(CommandSetFbs, FollowedMoveEndsInTheLibrarysErrorOnAnAxisError) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.AimFollowedMove(2000.0F);
    rig.Start(rig.moveAbs);
    rig.ScanWhile([&] { return rig.Motion(1).Position() < 100.0; });
    rig.Controller().Axes().RaiseAxisError(1, rig.Now(), kFollowingErrorNumber);
    FinalOutcome move = rig.Wait(rig.moveAbs);
    EXPECT_TRUE(move.Error()) << move;
    EXPECT_EQ(move.ErrorId(), kGvl["PAC_LIB_ERR_AXIS_ERROR"]);
    EXPECT_EQ(kGvl["PAC_LIB_ERR_AXIS_ERROR"], 0x800Au);
    EXPECT_NE(rig.Motion(1).AxisError(), 0) << "the axis error that ended it";
    EXPECT_EQ(rig.Count(0x190C), 0u);
    EXPECT_LT(rig.Motion(1).Position(), 2000.0);
}

// The final 190C refused: the controller's number, not Done; the move is over, so nothing more is sent.
TEST_P(CommandSetFbs, FollowedMoveFinalPositionReadRefusedIsThatError) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.moveRel->AXIS.value = 1;
    rig.moveRel->DISTANCE.value = 0.0F;  // in position at once: the first 1910 says 0, the next command is 190C
    rig.moveRel->FREEINTERFACE.value = TRUE;
    rig.Start(rig.moveRel);
    rig.ScanWhile([&] { return rig.Count(0x1910) == 0 && rig.moveRel->BUSY.value; });
    ASSERT_EQ(rig.Count(0x1910), 1u);
    rig.Controller().InjectCommandError(kInjectedErrorNumber);
    FinalOutcome move = rig.Wait(rig.moveRel);
    EXPECT_TRUE(move.Error()) << move;
    EXPECT_EQ(move.ErrorId(), kInjectedErrorNumber);
    EXPECT_EQ(rig.LastCode(), 0x190C);
    EXPECT_EQ(rig.Count(0x1910), 1u);
    const std::uint64_t reads = rig.Count(0x190C);
    rig.SettleFor(200ms);
    EXPECT_EQ(rig.Count(0x190C), reads) << "no read after the error";
}

// ---- mode commands (5.2.1, 5.2.5.1, 5.2.6.1) ----

TEST_P(CommandSetFbs, ModeCommandsReachTheManualsStatuses) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    EXPECT_EQ(rig.mode->OPSTATUS.value, 31) << "5.2.1.3: 001F";
    rig.mode->COMMAND.value = E_PAC_MODECOMMAND__PAC_MODE_STOP;
    ASSERT_TRUE(rig.Run(rig.mode).Done());
    EXPECT_EQ(rig.mode->OPSTATUS.value, 35) << "5.2.1.1: online mode stopped";
    rig.mode->COMMAND.value = E_PAC_MODECOMMAND__PAC_MODE_ABORT_ONLINE;
    ASSERT_TRUE(rig.Run(rig.mode).Done());
    EXPECT_EQ(rig.LastCode(), 0x0A81);
    EXPECT_EQ(rig.mode->OPSTATUS.value, 1);
    rig.mode->COMMAND.value = E_PAC_MODECOMMAND__PAC_MODE_START_AUTO;
    ASSERT_TRUE(rig.Run(rig.mode).Done());
    EXPECT_EQ(rig.mode->OPSTATUS.value, 11) << "5.2.1.2: 000B";
    rig.mode->COMMAND.value = E_PAC_MODECOMMAND__PAC_MODE_STOP;
    ASSERT_TRUE(rig.Run(rig.mode).Done());
    EXPECT_EQ(rig.mode->OPSTATUS.value, 15) << "5.2.1.1 example: 000F";
    rig.mode->COMMAND.value = E_PAC_MODECOMMAND__PAC_MODE_ABORT_AUTO;
    ASSERT_TRUE(rig.Run(rig.mode).Done());
    EXPECT_EQ(rig.LastCode(), 0x0A41);
    EXPECT_EQ(rig.mode->OPSTATUS.value, 1);
    // 0600 in home position: 5.1.1 marks it for AUTOMATIC (and ONLINE) only.
    rig.mode->COMMAND.value = E_PAC_MODECOMMAND__PAC_MODE_STOP;
    EXPECT_EQ(rig.Run(rig.mode).ErrorId(), kGvl["PAC_ERR_INADMISSIBLE_COMMAND"]);
}

// ---- reference and scale (5.2.6.2..5.2.6.5, 5.2.6.16) ----

TEST_P(CommandSetFbs, ReferenceCommandsSetTheFlagAndThePosition) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.reference->AXIS.value = 2;
    // 5.2.6.5 example: axis 2 to 200.00, data 4348 0000, acknowledged with the same value.
    rig.Motion(2).Place(rig.Now(), 50.0);
    rig.reference->COMMAND.value = E_PAC_REFERENCECOMMAND__PAC_REF_SET_POSITION;
    rig.reference->POSITION.value = 200.0F;
    ASSERT_TRUE(rig.Run(rig.reference).Done());
    EXPECT_EQ(rig.LastCode(), 0x0A86);
    EXPECT_EQ(rig.LastData(), 0x43480000u);
    EXPECT_EQ(rig.reference->ACTUALPOSITION.value, 200.0F);
    EXPECT_EQ(rig.Motion(2).Position(), 200.0);
    EXPECT_EQ(rig.Motion(2).MaxRange(), 10150.0) << "G29 moves the software limits with the scale";
    // 5.2.6.4: to zero (G26), software limits unchanged.
    rig.reference->COMMAND.value = E_PAC_REFERENCECOMMAND__PAC_REF_POSITION_ZERO;
    ASSERT_TRUE(rig.Run(rig.reference).Done());
    EXPECT_EQ(rig.LastCode(), 0x0A85);
    EXPECT_EQ(rig.Motion(2).Position(), 0.0);
    EXPECT_EQ(rig.Motion(2).MaxRange(), 10150.0);
    // 0A83 releases an unreferenced axis without moving it; 0A96 references it where it stands (example: 0.0).
    rig.Motion(2).SetReferenced(false);
    rig.reference->COMMAND.value = E_PAC_REFERENCECOMMAND__PAC_REF_RELEASE;
    ASSERT_TRUE(rig.Run(rig.reference).Done());
    EXPECT_TRUE(rig.Motion(2).Referenced());
    rig.Motion(2).SetReferenced(false);
    rig.reference->COMMAND.value = E_PAC_REFERENCECOMMAND__PAC_REF_AT_POSITION;
    rig.reference->POSITION.value = 12.5F;
    ASSERT_TRUE(rig.Run(rig.reference).Done());
    EXPECT_EQ(rig.LastCode(), 0x0A96);
    EXPECT_TRUE(rig.Motion(2).Referenced());
    EXPECT_EQ(rig.reference->ACTUALPOSITION.value, 12.5F) << "acknowledged with the current position";
    // Axis 3 is not configured: 32.
    rig.reference->AXIS.value = 3;
    EXPECT_EQ(rig.Run(rig.reference).ErrorId(), kGvl["PAC_ERR_AXIS_NUMBER"]);
}

// 5.2.6.3: the reference run sets the flag at its end; the FB is Busy until then.
TEST_P(CommandSetFbs, ReferenceRunIsBusyUntilTheFlagIsSet) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.Controller().Axes().SetReferenceSwitch(1, -20.0);
    rig.Motion(1).Place(rig.Now(), 0.0);
    rig.reference->AXIS.value = 1;
    rig.reference->COMMAND.value = E_PAC_REFERENCECOMMAND__PAC_REF_RUN;
    rig.Start(rig.reference);
    bool busyWhileHoming = false;
    FinalOutcome run = rig.Wait(rig.reference, 50000, [&] {
        if (rig.Motion(1).HomingActive() && rig.reference->BUSY.value) busyWhileHoming = true;
    });
    ASSERT_TRUE(run.Done()) << run;
    EXPECT_TRUE(busyWhileHoming);
    EXPECT_TRUE(rig.Motion(1).Referenced());
    EXPECT_FALSE(rig.Motion(1).HomingActive());
    EXPECT_EQ(rig.Count(0x0A84), 1u);
}

// ---- manual traverse (5.2.6.10..5.2.6.12) ----

// The axis keeps moving beyond one second only because 0A92 follows; Traverse falling stops it with 0A9A.
TEST_P(CommandSetFbs, ManualTraverseKeepsMovingWhileTraverseStaysTrue) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.jog->AXIS.value = 1;
    rig.jog->TARGET.value = 5000.0F;
    rig.jog->TRAVERSE.value = TRUE;
    rig.SettleFor(1500ms);
    EXPECT_TRUE(rig.jog->ACTIVE.value);
    EXPECT_TRUE(rig.Motion(1).Moving()) << "kept alive beyond the one second of 5.2.6.10";
    EXPECT_EQ(rig.Count(0x0A90), 1u);
    EXPECT_GE(rig.Count(0x0A92), 4u) << "every 250 ms";
    EXPECT_GT(rig.jog->ACTUALPOSITION.value, 500.0F) << "0A92 acknowledges the position";
    rig.jog->TRAVERSE.value = FALSE;
    rig.ScanWhile([&] { return rig.jog->BUSY.value; });
    EXPECT_TRUE(rig.jog->DONE.value);
    EXPECT_FALSE(rig.jog->ERROR.value);
    EXPECT_EQ(rig.Count(0x0A9A), 1u);
    rig.SettleFor(300ms);
    EXPECT_FALSE(rig.Motion(1).Moving());
    EXPECT_LT(rig.Motion(1).Position(), 5000.0);
    EXPECT_TRUE(rig.jog->DONE.value) << "held until the next rising edge";
}

TEST_P(CommandSetFbs, ManualTraverseEndsAtMaxTimeWithTheLibrarysError) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.jog->AXIS.value = 2;
    rig.jog->TARGET.value = 100.0F;
    rig.jog->RELATIVE.value = TRUE;  // 0A91: by 100
    rig.jog->MAXTIME.value = pac::ToIecTime(60ms);
    rig.jog->TRAVERSE.value = TRUE;
    rig.ScanWhile([&] { return !rig.jog->ERROR.value && !rig.jog->DONE.value; });
    EXPECT_TRUE(rig.jog->ERROR.value);
    EXPECT_EQ(rig.jog->ERRORID.value, kGvl["PAC_LIB_ERR_JOG_TIME_LIMIT"]);
    EXPECT_EQ(rig.Count(0x0A91), 1u);
    EXPECT_EQ(rig.Count(0x0A9A), 1u);
    rig.SettleFor(300ms);
    EXPECT_FALSE(rig.Motion(2).Moving());
}

// The jog key pressed and released while another command holds the interface (0A87 of axis 2, to its end): a
// queued command cannot be withdrawn, so the start waits for an empty queue and is never sent after the release.
// Nothing goes out, axis 1 never moves, the FB ends Done.
TEST_P(CommandSetFbs, ManualTraverseReleasedBeforeItsStartWentOutSendsNothing) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    const double start = rig.Motion(1).Position();
    rig.StartInterfaceHoldingMove(300.0F);
    rig.AimJog(5000.0F);
    rig.jog->TRAVERSE.value = TRUE;
    rig.SettleFor(50ms);
    EXPECT_TRUE(rig.jog->BUSY.value);
    EXPECT_FALSE(rig.jog->ACTIVE.value);
    rig.jog->TRAVERSE.value = FALSE;
    ASSERT_TRUE(rig.Wait(rig.moveAbs).Done());
    rig.Release(rig.moveAbs);
    rig.SettleFor(300ms);
    EXPECT_EQ(rig.Count(0x0A90), 0u) << "the start never went out";
    EXPECT_EQ(rig.Count(0x0A9A), 0u);
    EXPECT_FALSE(rig.jog->BUSY.value);
    EXPECT_TRUE(rig.jog->DONE.value);
    EXPECT_FALSE(rig.jog->ERROR.value);
    EXPECT_EQ(rig.Motion(1).Position(), start);
}

// The jog key held while another command keeps the interface longer than the jog's Timeout: the start is never
// queued (a queued command could not be withdrawn), and the jog ends with 16#8006, nothing sent.
TEST_P(CommandSetFbs, ManualTraverseWhoseStartFindsNoFreeInterfaceWithinTimeoutSendsNothing) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.StartInterfaceHoldingMove(300.0F);
    rig.AimJog(5000.0F);
    rig.jog->TIMEOUT.value = pac::ToIecTime(30ms);
    rig.jog->TRAVERSE.value = TRUE;
    rig.Settle(1);
    ASSERT_TRUE(rig.jog->BUSY.value);
    rig.ScanWhile([&] { return rig.jog->BUSY.value; });
    EXPECT_TRUE(rig.jog->ERROR.value);
    EXPECT_EQ(rig.jog->ERRORID.value, kGvl["PAC_LIB_ERR_INTERFACE_BUSY"]);
    EXPECT_TRUE(rig.moveAbs->BUSY.value) << "the move still holds the interface";
    rig.jog->TRAVERSE.value = FALSE;
    ASSERT_TRUE(rig.Wait(rig.moveAbs).Done());
    rig.Release(rig.moveAbs);
    rig.SettleFor(100ms);
    EXPECT_EQ(rig.Count(0x0A90), 0u) << "the start never went out";
}

// The jog key held while other callers keep the queue full of short commands (three reads, each edged again in
// the scan after its release, so that one waits while another is on its way; all called before the jog): the start
// goes out only into an empty queue (a queued start could not be withdrawn). Where this traffic leaves no such
// scan (every timing of this suite), the jog ends with 16#8006 in the first scan past Timeout from the press,
// nothing sent; where it does, the start goes out then. Either way Busy ends within its bound (docs/commands.md,
// "Manual traverse"). With the reads held back while the jog is Busy, as the page advises, the next press
// starts the axis once the reads queued before it have ended.
TEST_P(CommandSetFbs, ManualTraverseUnderQueueTrafficStartsOrEndsWithinTimeout) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.readN->NUMBER.value = 5;
    rig.readStatus->AXIS.value = 2;
    rig.readValue->AXIS.value = 2;
    rig.readValue->KIND.value = E_PAC_AXISVALUE__PAC_AXVAL_TRAVERSE_MAX;
    bool holdBack = false;  // the reads wait while the jog is Busy
    std::uint64_t reads = 0;
    auto poll = [&](auto& fb) {
        if (fb->EXECUTE.value && (fb->DONE.value || fb->ERROR.value)) {
            EXPECT_TRUE(fb->DONE.value) << "a read of the traffic: ErrorID 16#" << std::hex << fb->ERRORID.value;
            fb->EXECUTE.value = FALSE;
            ++reads;
        } else if (!fb->EXECUTE.value && !(holdBack && rig.jog->BUSY.value)) {
            fb->EXECUTE.value = TRUE;
        }
    };
    auto scan = [&] {
        poll(rig.readN);
        poll(rig.readStatus);
        poll(rig.readValue);
        rig.Settle(1);
    };
    for (int i = 0; i < GetParam().ScansFor(200ms); ++i) scan();
    constexpr auto kTimeout = 100ms;
    rig.AimJog(5000.0F);
    rig.jog->TIMEOUT.value = pac::ToIecTime(kTimeout);
    rig.jog->TRAVERSE.value = TRUE;
    const std::uint64_t readsBefore = reads;
    scan();
    const nanoseconds pressed = rig.Now();
    while (rig.jog->BUSY.value && !rig.jog->ACTIVE.value && rig.Count(0x0A90) == 0 &&
           rig.Now() - pressed <= kTimeout + GetParam().PlcCycle()) {
        scan();
    }
    if (rig.Count(0x0A90) == 0) {
        EXPECT_FALSE(rig.jog->BUSY.value) << "still Busy " << (rig.Now() - pressed) / 1ms << " ms after the press";
        EXPECT_TRUE(rig.jog->ERROR.value);
        EXPECT_EQ(rig.jog->ERRORID.value, kGvl["PAC_LIB_ERR_INTERFACE_BUSY"]);
        EXPECT_GE(rig.Now() - pressed, kTimeout) << "16#8006 before Timeout";
        EXPECT_GT(reads - readsBefore, 3u) << "the traffic went on meanwhile";
    }
    // Reachability: the traffic leaves no empty queue on a controller cycle of 10 ms.
    if (GetParam().pacMs == 10) {
        EXPECT_EQ(rig.Count(0x0A90), 0u) << "a start found an empty queue";
    }
    rig.jog->TRAVERSE.value = FALSE;
    scan();
    for (int i = 0; i < GetParam().ScansFor(2s) && rig.jog->BUSY.value; ++i) scan();
    EXPECT_FALSE(rig.jog->BUSY.value);
    // The remedy the page gives: the program holds its other callers back while the jog is Busy
    // (Execute := Poll AND NOT Jog.Busy). The reads already queued end, and the start goes out then.
    holdBack = true;
    const std::uint64_t starts = rig.Count(0x0A90);
    rig.jog->TRAVERSE.value = TRUE;
    scan();
    EXPECT_TRUE(rig.jog->BUSY.value);
    ASSERT_TRUE(rig.jog->ERRORID.value == 0) << "ErrorID 16#" << std::hex << rig.jog->ERRORID.value;
    const std::uint64_t readsAtPress = reads;
    for (int i = 0; i < GetParam().ScansFor(kTimeout) && !rig.jog->ACTIVE.value && !rig.jog->ERROR.value; ++i) scan();
    EXPECT_TRUE(rig.jog->ACTIVE.value) << "the start, behind the reads queued before the press";
    EXPECT_EQ(rig.Count(0x0A90), starts + 1);
    EXPECT_LE(reads - readsAtPress, 3u) << "only the reads queued at the press went before the start";
    rig.jog->TRAVERSE.value = FALSE;
    for (int i = 0; i < GetParam().ScansFor(2s) && rig.jog->BUSY.value; ++i) scan();
    EXPECT_TRUE(rig.jog->DONE.value);
}

// The jog key released in the scan after its start went out, before or with the start's acknowledgement: the
// stop 0A9A follows the start at once, and the axis stands.
TEST_P(CommandSetFbs, ManualTraverseReleasedWhileItsStartIsOnItsWayIsStoppedAtOnce) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.AimJog(5000.0F);
    rig.jog->TRAVERSE.value = TRUE;
    rig.Settle(1);
    ASSERT_TRUE(rig.jog->BUSY.value);
    rig.jog->TRAVERSE.value = FALSE;
    rig.ScanWhile([&] { return rig.jog->BUSY.value; });
    EXPECT_TRUE(rig.jog->DONE.value) << "ErrorID " << std::hex << rig.jog->ERRORID.value;
    EXPECT_EQ(rig.Count(0x0A90), 1u) << "the start went out";
    EXPECT_EQ(rig.Count(0x0A9A), 1u) << "and the stop after it";
    rig.SettleFor(300ms);
    EXPECT_FALSE(rig.Motion(1).Moving());
}

// The jog key released while the next keep-alive waits behind another command (0A87 of axis 2): the stop takes
// no ticket and goes out as soon as the interface is free, before the queued keep-alive.
TEST_P(CommandSetFbs, ManualTraverseReleasedWhileAKeepAliveWaitsIsStoppedFirst) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.AimJog(5000.0F);
    rig.jog->TRAVERSE.value = TRUE;
    rig.ScanWhile([&] { return rig.Count(0x0A92) == 0; });
    const std::uint64_t alive = rig.Count(0x0A92);
    ASSERT_EQ(alive, 1u);
    rig.StartInterfaceHoldingMove(400.0F);
    rig.SettleFor(300ms);  // the next keep-alive is due 250 ms after the last one's acknowledgement
    ASSERT_TRUE(rig.moveAbs->BUSY.value) << "0A87 still holds the interface";
    ASSERT_EQ(rig.Count(0x0A92), alive) << "the keep-alive waits behind 0A87";
    rig.jog->TRAVERSE.value = FALSE;
    bool stopped = false;
    std::uint64_t aliveAtStop = 0;
    rig.ScanWhile([&] {
        if (!stopped && rig.Count(0x0A9A) > 0) {
            stopped = true;
            aliveAtStop = rig.Count(0x0A92);
        }
        return rig.jog->BUSY.value || rig.moveAbs->BUSY.value;
    });
    EXPECT_TRUE(stopped);
    EXPECT_EQ(aliveAtStop, alive) << "no keep-alive went out after the release before the stop";
    EXPECT_TRUE(rig.jog->DONE.value);
    rig.SettleFor(300ms);
    EXPECT_FALSE(rig.Motion(1).Moving());
}

// T#0S on KeepAliveInterval and MaxTime means their defaults (250 ms, 60 s): the traverse is kept alive at the
// default pace, not in every scan, and not ended at once.
TEST_P(CommandSetFbs, ManualTraverseWithZeroTimesUsesTheDefaults) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.AimJog(5000.0F);
    rig.jog->KEEPALIVEINTERVAL.value = pac::ToIecTime(0ms);
    rig.jog->MAXTIME.value = pac::ToIecTime(0ms);
    rig.jog->TRAVERSE.value = TRUE;
    rig.SettleFor(1500ms);
    EXPECT_TRUE(rig.jog->ACTIVE.value);
    EXPECT_FALSE(rig.jog->ERROR.value);
    EXPECT_TRUE(rig.Motion(1).Moving());
    EXPECT_GE(rig.Count(0x0A92), 4u) << "kept alive";
    EXPECT_LE(rig.Count(0x0A92), 6u) << "every 250 ms, not faster";
    EXPECT_EQ(rig.Count(0x0A9A), 0u);
    rig.jog->TRAVERSE.value = FALSE;
    rig.ScanWhile([&] { return rig.jog->BUSY.value; });
    EXPECT_TRUE(rig.jog->DONE.value);
}

// 0A90 refused: the controller's number, and nothing follows it (no keep-alive, no stop).
TEST_P(CommandSetFbs, ManualTraverseStartRefusedIsThatError) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.Controller().InjectCommandError(kInjectedErrorNumber);
    rig.AimJog(5000.0F);
    rig.jog->TRAVERSE.value = TRUE;
    rig.ScanWhile([&] { return !rig.jog->ERROR.value && !rig.jog->DONE.value; });
    EXPECT_TRUE(rig.jog->ERROR.value);
    EXPECT_EQ(rig.jog->ERRORID.value, kInjectedErrorNumber);
    EXPECT_FALSE(rig.jog->ACTIVE.value);
    EXPECT_FALSE(rig.jog->BUSY.value);
    rig.SettleFor(500ms);
    EXPECT_EQ(rig.Count(0x0A90), 1u);
    EXPECT_EQ(rig.Count(0x0A92), 0u);
    EXPECT_EQ(rig.Count(0x0A9A), 0u);
    EXPECT_FALSE(rig.Motion(1).Moving());
}

// 0A92 refused: the FB stops the axis with 0A9A at once rather than let it run out its second, and reports the
// keep-alive's number.
TEST_P(CommandSetFbs, ManualTraverseKeepAliveRefusedStopsTheAxisWithThatError) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.AimJog(5000.0F);
    rig.jog->TRAVERSE.value = TRUE;
    rig.ScanWhile([&] { return rig.Count(0x0A92) == 0; });
    rig.Controller().InjectCommandError(kInjectedErrorNumber);  // the next 0A92
    rig.ScanWhile([&] { return !rig.jog->ERROR.value && !rig.jog->DONE.value; });
    EXPECT_TRUE(rig.jog->ERROR.value);
    EXPECT_EQ(rig.jog->ERRORID.value, kInjectedErrorNumber);
    EXPECT_FALSE(rig.jog->ACTIVE.value);
    EXPECT_EQ(rig.Count(0x0A92), 2u);
    EXPECT_EQ(rig.Count(0x0A9A), 1u);
    EXPECT_TRUE(rig.jog->TRAVERSE.value) << "stopped by the FB, not by the program";
    rig.SettleFor(300ms);
    EXPECT_FALSE(rig.Motion(1).Moving());
    EXPECT_EQ(rig.Count(0x0A92), 2u) << "no keep-alive after the stop";
}

// 0A9A refused: the controller's number, not Done; no keep-alive follows, so the PA-CONTROL stops the axis
// within its second (5.2.6.10).
TEST_P(CommandSetFbs, ManualTraverseStopRefusedIsThatError) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.AimJog(5000.0F);
    rig.jog->KEEPALIVEINTERVAL.value = pac::ToIecTime(800ms);
    rig.jog->TRAVERSE.value = TRUE;
    rig.ScanWhile([&] { return !rig.jog->ACTIVE.value; });
    rig.SettleFor(100ms);
    ASSERT_EQ(rig.Count(0x0A92), 0u) << "in the pause: no command on its way";
    rig.Controller().InjectCommandError(kInjectedErrorNumber);  // the 0A9A
    rig.jog->TRAVERSE.value = FALSE;
    rig.ScanWhile([&] { return rig.jog->BUSY.value; });
    EXPECT_TRUE(rig.jog->ERROR.value);
    EXPECT_EQ(rig.jog->ERRORID.value, kInjectedErrorNumber);
    EXPECT_FALSE(rig.jog->DONE.value);
    EXPECT_EQ(rig.Count(0x0A9A), 1u);
    rig.SettleFor(1500ms);
    EXPECT_EQ(rig.Count(0x0A92), 0u);
    EXPECT_EQ(rig.Count(0x0A9A), 1u) << "no retry";
    EXPECT_FALSE(rig.Motion(1).Moving());
}

// ---- axis on/off, measuring mode, limit switch monitoring, move condition (5.2.6.17..5.2.6.23) ----

TEST_P(CommandSetFbs, SwitchedOffAxisRefusesMovesUntilSwitchedOn) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.switchAxis->AXIS.value = 1;
    rig.switchAxis->SWITCHON.value = FALSE;
    ASSERT_TRUE(rig.Run(rig.switchAxis).Done());
    EXPECT_EQ(rig.LastCode(), 0x0A98);
    EXPECT_FALSE(rig.Motion(1).AxisOn());
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 10.0F;
    EXPECT_EQ(rig.Run(rig.moveAbs).ErrorId(), kGvl["PAC_ERR_AXIS_OFF"]);
    rig.switchAxis->SWITCHON.value = TRUE;
    ASSERT_TRUE(rig.Run(rig.switchAxis).Done());
    EXPECT_EQ(rig.LastCode(), 0x0A97);
    EXPECT_TRUE(rig.Motion(1).AxisOn());
    EXPECT_TRUE(rig.Run(rig.moveAbs).Done());
}

TEST_P(CommandSetFbs, MeasuringModeBlocksPositioningAndShowsInTheStatus) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.measuring->AXIS.value = 1;
    rig.measuring->ACTIVATE.value = TRUE;
    ASSERT_TRUE(rig.Run(rig.measuring).Done());
    EXPECT_EQ(rig.LastCode(), 0x0AA0);
    rig.readStatus->AXIS.value = 1;
    ASSERT_TRUE(rig.Run(rig.readStatus).Done());
    EXPECT_EQ(rig.readStatus->STATUS.value, 8) << "5.2.4.22: 8, axis in measuring mode";
    EXPECT_TRUE(rig.readStatus->MEASURINGMODE.value);
    rig.readExtended->AXIS.value = 1;
    ASSERT_TRUE(rig.Run(rig.readExtended).Done());
    EXPECT_TRUE(rig.readExtended->MEASURINGMODE.value);
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 10.0F;
    EXPECT_EQ(rig.Run(rig.moveAbs).ErrorId(), kGvl["PAC_ERR_AXIS_NOT_READY"]);
    rig.measuring->ACTIVATE.value = FALSE;
    ASSERT_TRUE(rig.Run(rig.measuring).Done());
    EXPECT_EQ(rig.LastCode(), 0x0AA1);
    EXPECT_TRUE(rig.Run(rig.moveAbs).Done());
    // 5.2.6.21: on an axis not in measuring mode, 0AA1 is only acknowledged.
    EXPECT_TRUE(rig.Run(rig.measuring).Done());
}

TEST_P(CommandSetFbs, LimitSwitchMonitoringForOneAxisOrAll) {
    CommandSetRig rig(GetParam());
    ASSERT_TRUE(rig.GoOnline());
    rig.monitoring->AXIS.value = 0;
    rig.monitoring->MONITOR.value = FALSE;
    ASSERT_TRUE(rig.Run(rig.monitoring).Done());
    EXPECT_EQ(rig.LastCode(), 0x0AA2);
    EXPECT_EQ(rig.LastData(), 0u);
    EXPECT_FALSE(rig.Controller().Online().LimitSwitchMonitoring(1));
    EXPECT_FALSE(rig.Controller().Online().LimitSwitchMonitoring(2));
    rig.monitoring->AXIS.value = 2;
    rig.monitoring->MONITOR.value = TRUE;
    ASSERT_TRUE(rig.Run(rig.monitoring).Done());
    EXPECT_EQ(rig.LastData(), 1u);
    EXPECT_FALSE(rig.Controller().Online().LimitSwitchMonitoring(1));
    EXPECT_TRUE(rig.Controller().Online().LimitSwitchMonitoring(2));
    // Into an actuated switch: refused (64) while monitored, allowed without monitoring.
    rig.Controller().Axes().SetLimitSwitches(1, -100.0, 0.0);
    rig.Controller().Axes().SetLimitSwitches(2, -100.0, 0.0);
    rig.moveAbs->POSITION.value = 20.0F;
    rig.moveAbs->AXIS.value = 2;
    EXPECT_EQ(rig.Run(rig.moveAbs).ErrorId(), kGvl["PAC_ERR_LIMIT_SWITCH"]);
    rig.moveAbs->AXIS.value = 1;
    EXPECT_TRUE(rig.Run(rig.moveAbs).Done());
}

// 5.2.6.23: the axis moves as long as the element keeps its value; switching over ends the movement, and
// the followed move reports CommandAborted (status 2: stopped), not Done. The element type is 1 input, 2 output,
// 3 flag, in byte "4" of the data: bits 23..16 by significance, 15..8 by Profibus byte.
struct ConditionElement {
    E_PAC_ELEMENTTYPE type;
    std::uint32_t typeBits;
    pac::sim::BitBank& (*bank)(pac::sim::Elements&);
};

const ConditionElement kConditionInput{E_PAC_ELEMENTTYPE__PAC_ELEMENT_INPUT, 1u,
                                       [](pac::sim::Elements& io) -> pac::sim::BitBank& { return io.inputs; }};
const ConditionElement kConditionOutput{E_PAC_ELEMENTTYPE__PAC_ELEMENT_OUTPUT, 2u,
                                        [](pac::sim::Elements& io) -> pac::sim::BitBank& { return io.outputs; }};
const ConditionElement kConditionFlag{E_PAC_ELEMENTTYPE__PAC_ELEMENT_FLAG, 3u,
                                      [](pac::sim::Elements& io) -> pac::sim::BitBank& { return io.flags; }};

void ConditionEndsTheMove(const BusTiming& timing, pac::sim::ConditionLayout layout, const ConditionElement& element) {
    pac::sim::PaControlConfig config;
    config.online.conditionLayout = layout;
    CommandSetRig rig(timing, config);
    ASSERT_TRUE(rig.GoOnline());
    pac::sim::BitBank& bank = element.bank(rig.Controller().Io());
    bank.Set(9, true);
    rig.condition->AXIS.value = 1;
    rig.condition->ELEMENT.value = element.type;
    rig.condition->NUMBER.value = 9;
    rig.condition->LEVEL.value = TRUE;
    rig.condition->PROFIBUSBYTEORDER.value = layout == pac::sim::ConditionLayout::kByProfibusByte;
    ASSERT_TRUE(rig.Run(rig.condition).Done());
    EXPECT_EQ(rig.LastCode(), 0x0AA3);
    const std::uint32_t expected = layout == pac::sim::ConditionLayout::kBySignificance
                                       ? 0x01000009u | element.typeBits << 16
                                       : 0x00090001u | element.typeBits << 8;
    EXPECT_EQ(rig.LastData(), expected);
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 2000.0F;
    rig.moveAbs->FREEINTERFACE.value = TRUE;
    rig.Start(rig.moveAbs);
    rig.ScanWhile([&] { return rig.Motion(1).Position() < 200.0; });
    bank.Set(9, false);
    FinalOutcome move = rig.Wait(rig.moveAbs);
    EXPECT_TRUE(move.Aborted()) << move;
    EXPECT_LT(rig.Motion(1).Position(), 500.0);
    EXPECT_FALSE(rig.Motion(1).Moving());
}

TEST_P(CommandSetFbs, MoveConditionEndsTheMoveBySignificanceLayout) {
    ConditionEndsTheMove(GetParam(), pac::sim::ConditionLayout::kBySignificance, kConditionInput);
}

TEST_P(CommandSetFbs, MoveConditionEndsTheMoveByProfibusByteLayout) {
    ConditionEndsTheMove(GetParam(), pac::sim::ConditionLayout::kByProfibusByte, kConditionInput);
}

TEST_P(CommandSetFbs, MoveConditionOnAnOutputEndsTheMove) {
    ConditionEndsTheMove(GetParam(), pac::sim::ConditionLayout::kBySignificance, kConditionOutput);
}

TEST_P(CommandSetFbs, MoveConditionOnAFlagEndsTheMove) {
    ConditionEndsTheMove(GetParam(), pac::sim::ConditionLayout::kByProfibusByte, kConditionFlag);
}

// ---- axis values and the extended status (5.2.4.19..5.2.4.28) ----

TEST_P(CommandSetFbs, AxisValuesAreDecoded) {
    CommandSetRig rig(GetParam());
    rig.readValue->AXIS.value = 1;
    rig.readValue->KIND.value = E_PAC_AXISVALUE__PAC_AXVAL_TRAVERSE_MAX;
    ASSERT_TRUE(rig.Run(rig.readValue).Done());
    EXPECT_EQ(rig.LastCode(), 0x1914);
    EXPECT_EQ(rig.readValue->VALUE.value, 10000.0F) << "axis parameter 9";
    rig.readValue->KIND.value = E_PAC_AXISVALUE__PAC_AXVAL_TRAVERSE_MIN;
    ASSERT_TRUE(rig.Run(rig.readValue).Done());
    EXPECT_EQ(rig.LastCode(), 0x1913);
    EXPECT_EQ(rig.readValue->VALUE.value, 0.0F);
    rig.readValue->KIND.value = E_PAC_AXISVALUE__PAC_AXVAL_TEMPERATURE;
    ASSERT_TRUE(rig.Run(rig.readValue).Done());
    EXPECT_EQ(rig.LastCode(), 0x1920);
    EXPECT_EQ(rig.readValue->VALUE.value, 40.0F);
    EXPECT_EQ(rig.readValue->RAWVALUE.value, 0x42200000u) << "5.2.4.27 example bytes (docs/manual_errata.md: 40.0)";
    rig.Motion(1).Place(rig.Now(), 321.5);
    rig.readValue->KIND.value = E_PAC_AXISVALUE__PAC_AXVAL_ENCODER_POSITION;
    ASSERT_TRUE(rig.Run(rig.readValue).Done());
    EXPECT_EQ(rig.LastCode(), 0x190E);
    EXPECT_EQ(rig.readValue->VALUE.value, 321.5F);
    ASSERT_TRUE(rig.GoOnline());
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 2000.0F;
    rig.moveAbs->FREEINTERFACE.value = TRUE;
    rig.Start(rig.moveAbs);
    rig.SettleFor(400ms);
    rig.readValue->KIND.value = E_PAC_AXISVALUE__PAC_AXVAL_SPEED;
    ASSERT_TRUE(rig.Run(rig.readValue).Done());
    EXPECT_EQ(rig.LastCode(), 0x190D);
    EXPECT_EQ(rig.readValue->VALUE.value, 1000.0F) << "the traverse speed of axis parameter 1";
}

// 1915 / 1920 on the other reading of the header ("0000 - FFFF"): the FB takes a value with an upper word
// of 0 as a 16-bit integer. Without the EP commands the controller answers 19.
TEST_P(CommandSetFbs, EpValuesAsIntegersAndControllersWithoutThem) {
    pac::sim::PaControlConfig config;
    config.online.epValuesAsReal = false;
    config.online.temperature = 37.0F;
    CommandSetRig rig(GetParam(), config);
    rig.readValue->AXIS.value = 2;
    rig.readValue->KIND.value = E_PAC_AXISVALUE__PAC_AXVAL_TEMPERATURE;
    ASSERT_TRUE(rig.Run(rig.readValue).Done());
    EXPECT_EQ(rig.readValue->RAWVALUE.value, 37u);
    EXPECT_EQ(rig.readValue->VALUE.value, 37.0F);
    rig.readValue->KIND.value = E_PAC_AXISVALUE__PAC_AXVAL_FOLLOWING_ERROR;
    ASSERT_TRUE(rig.Run(rig.readValue).Done());
    EXPECT_EQ(rig.LastCode(), 0x1915);
    EXPECT_EQ(rig.readValue->VALUE.value, 0.0F);

    pac::sim::PaControlConfig plain;
    plain.online.epCommands = false;
    CommandSetRig other(GetParam(), plain);
    other.readValue->AXIS.value = 1;
    other.readValue->KIND.value = E_PAC_AXISVALUE__PAC_AXVAL_MAX_FOLLOWING_ERROR;
    EXPECT_EQ(other.Run(other.readValue).ErrorId(), kGvl["PAC_ERR_UNKNOWN_COMMAND"]);
    EXPECT_EQ(other.LastCode(), 0x190F);
}

TEST_P(CommandSetFbs, ExtendedStatusDecodesReadinessSwitchesAndStatus) {
    CommandSetRig rig(GetParam());
    rig.readExtended->AXIS.value = 2;
    ASSERT_TRUE(rig.Run(rig.readExtended).Done());
    EXPECT_EQ(rig.LastCode(), 0x1921);
    EXPECT_EQ(rig.readExtended->RAWSTATUS.value, 0x01010100u) << "ready, no switch actuated, in position";
    EXPECT_TRUE(rig.readExtended->POWERREADY.value);
    EXPECT_FALSE(rig.readExtended->POSITIVELIMITSWITCH.value);
    EXPECT_FALSE(rig.readExtended->NEGATIVELIMITSWITCH.value);
    EXPECT_TRUE(rig.readExtended->INPOSITION.value);
    // 5.2.4.28 example 0100 0104: ready, positive switch actuated, negative not, malfunction.
    rig.Controller().Axes().SetLimitSwitches(2, -100.0, 0.0);
    rig.Controller().Axes().RaiseAxisError(2, rig.Now(), 46);
    ASSERT_TRUE(rig.Run(rig.readExtended).Done());
    EXPECT_TRUE(rig.readExtended->POSITIVELIMITSWITCH.value);
    EXPECT_FALSE(rig.readExtended->NEGATIVELIMITSWITCH.value);
    EXPECT_TRUE(rig.readExtended->MALFUNCTION.value);
    EXPECT_EQ(rig.readExtended->STATUS.value, 4);
    EXPECT_EQ(rig.readExtended->RAWSTATUS.value & 0x00FFFFFFu, 0x00000104u);
}

INSTANTIATE_TEST_SUITE_P(BusTimings, CommandSetFbs, ::testing::ValuesIn(pac::test::BusTimingGrid({1, 5}, {3, 10}, {0, 2})),
                         pac::test::BusTimingName);

}  // namespace
}  // namespace test_command_set_fbs
