// The PLCopen MC_ blocks (st/mc/MC_*.st, docs/fb/MC_blocks.md) on FB_PAC_McAxis over the simulated PA-CONTROL's
// axis modules, scan by scan on a spread of bus timings, block by block: MC_Power, the moves in user units, abort
// chains of several blocks on one axis, halt, stop, home, ErrorStop and MC_Reset, a lost link, and what the
// PA-CONTROL cannot do refused with its ErrorID. The PLCopen checker runs on every Execute block in every scan
// (mc_rig.hpp). The state diagram state by state: test_mc_state_diagram_sim.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "mc_test_steps.hpp"
#include "pac/axis_module_bits.hpp"

namespace test_mc_blocks_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace pac::test::mc;
using pac::test::BusTiming;
using pac::test::McRig;
using pac::test::McBlocks;

class McSim : public ::testing::TestWithParam<BusTiming> {};
INSTANTIATE_TEST_SUITE_P(BusTimings, McSim, ::testing::ValuesIn(McTimings()), pac::test::BusTimingName);

// ---- MC_Power and the states Disabled / Standstill ----------------------------------------------------------

TEST_P(McSim, PowerEnablesTheDriveAndLeavesDisabled) {
    McRig rig(GetParam(), 1);
    McBlocks& b = rig.Blocks(1);
    b.position->ENABLE.value = TRUE;
    b.axisError->ENABLE.value = TRUE;
    rig.GoOnline();
    EXPECT_FALSE(b.power->ERROR.value) << "no error while not enabled";
    EXPECT_FALSE(b.power->STATUS.value);
    EXPECT_EQ(rig.State(1), kDisabled);
    // Disabled refuses every motion block; MC_Reset has nothing to reset.
    SetMove(b.moveA, 10.0f);
    Execute(rig, b.moveA);
    EXPECT_EQ(b.moveA->ERRORID.value, kMcDisabled);
    Release(rig, b.moveA);
    Execute(rig, b.stop);
    EXPECT_EQ(b.stop->ERRORID.value, kMcDisabled);
    Release(rig, b.stop);
    Execute(rig, b.reset);
    EXPECT_TRUE(b.reset->DONE.value) << "Done in the edge scan";
    Release(rig, b.reset);

    b.power->ENABLE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return b.power->STATUS.value != 0; }, 100, "Status"));
    EXPECT_TRUE(b.power->VALID.value);
    EXPECT_TRUE(rig.Ref(1).STATUS.ENABLED);
    rig.Scan();
    EXPECT_EQ(rig.State(1), kStandstill);
    EXPECT_TRUE(b.position->VALID.value && b.position->BUSY.value && !b.position->ERROR.value);
    EXPECT_EQ(b.axisError->AXISERRORID.value, 0u);

    b.power->ENABLE.value = FALSE;
    ASSERT_TRUE(rig.WaitFor([&] { return b.power->STATUS.value == 0; }, 100, "Status off"));
    rig.Scan();
    EXPECT_EQ(rig.State(1), kDisabled);
}

// ---- the motion blocks -----------------------------------------------------------------------------------

TEST_P(McSim, MoveAbsoluteAndRelativeReachTheirTargetsInUserUnits) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    b.status->ENABLE.value = TRUE;
    b.position->ENABLE.value = TRUE;
    SetMove(b.moveA, 120.0f, 500.0f);
    b.moveA->ACCELERATION.value = 20000.0f;
    b.moveA->DECELERATION.value = 20000.0f;  // equal to Acceleration: one ramp, accepted
    Execute(rig, b.moveA);
    EXPECT_TRUE(b.moveA->BUSY.value && b.moveA->ACTIVE.value);
    rig.Scan();
    EXPECT_EQ(rig.State(1), kDiscrete);
    EXPECT_TRUE(b.status->DISCRETEMOTION.value && !b.status->STANDSTILL.value);
    ASSERT_TRUE(EndsDone(rig, b.moveA, 2000, "MoveAbsolute"));
    EXPECT_FALSE(b.moveA->ACTIVE.value);
    EXPECT_EQ(rig.Position(1), 120.0f);
    EXPECT_EQ(b.position->POSITION.value, 120.0f);
    // 500 AE/s of 1000 AE/s, 20000 AE/s2 of 10000 AE/s2: per mille in the module's fields (2.7.5, 2.7.6).
    EXPECT_EQ(rig.SentWord(1, 6), 500u);
    EXPECT_EQ(rig.SentWord(1, 4), 2000u);
    rig.Scan(3);
    EXPECT_TRUE(b.moveA->DONE.value) << "Done holds while Execute";
    EXPECT_EQ(rig.State(1), kStandstill);
    EXPECT_TRUE(b.status->STANDSTILL.value);
    Release(rig, b.moveA);
    EXPECT_FALSE(b.moveA->DONE.value);

    b.relative->POSITION.value = -20.0f;
    b.relative->VELOCITY.value = 250.0f;  // Acceleration 0.0: the axis parameter, 1000 per mille
    Execute(rig, b.relative);
    ASSERT_TRUE(EndsDone(rig, b.relative, 2000, "MoveRelative"));
    EXPECT_EQ(rig.Position(1), 100.0f);
    EXPECT_EQ(rig.SentWord(1, 6), 250u);
    EXPECT_EQ(rig.SentWord(1, 4), 1000u);
    // Execute already FALSE at the end: the final output shows for one scan only.
    b.relative->POSITION.value = 5.0f;
    Release(rig, b.relative);
    Execute(rig, b.relative);
    b.relative->EXECUTE.value = FALSE;
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.relative); }, 2000, "MoveRelative final"));
    rig.Scan();
    EXPECT_FALSE(Final(b.relative));
    EXPECT_EQ(rig.Position(1), 105.0f);
}

TEST_P(McSim, ANewBlockAbortsTheRunningOneAlongAChain) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    // A -> B: B takes the axis, A shows CommandAborted and holds it while its Execute stays TRUE.
    SetMove(b.moveB, 300.0f, 1000.0f);
    Execute(rig, b.moveB);
    rig.Scan();
    EXPECT_TRUE(b.moveA->COMMANDABORTED.value);
    EXPECT_FALSE(b.moveA->BUSY.value || b.moveA->ACTIVE.value);
    EXPECT_TRUE(b.moveB->BUSY.value);
    // B -> MoveRelative in the next scans, -> MoveVelocity -> Halt: each aborts the one before.
    b.relative->POSITION.value = 50.0f;
    b.relative->VELOCITY.value = 1000.0f;
    Execute(rig, b.relative);
    rig.Scan();
    EXPECT_TRUE(b.moveB->COMMANDABORTED.value);
    b.velocity->VELOCITY.value = 500.0f;
    b.velocity->DIRECTION.value = E_PAC_MCDIRECTION__PAC_MC_POSITIVE;
    Execute(rig, b.velocity);
    rig.Scan();
    EXPECT_TRUE(b.relative->COMMANDABORTED.value);
    EXPECT_EQ(rig.State(1), kContinuous);
    ASSERT_TRUE(rig.WaitFor([&] { return b.velocity->INVELOCITY.value != 0; }, 300, "InVelocity"));
    EXPECT_TRUE(b.velocity->BUSY.value && b.velocity->ACTIVE.value);
    Execute(rig, b.halt);
    rig.Scan();
    EXPECT_TRUE(b.velocity->COMMANDABORTED.value);
    EXPECT_FALSE(b.velocity->INVELOCITY.value);
    EXPECT_EQ(rig.State(1), kDiscrete) << "a halt is a discrete motion";
    ASSERT_TRUE(EndsDone(rig, b.halt, 2000, "Halt"));
    EXPECT_FALSE(rig.Pac().Axes().Motion(1).Moving());
    EXPECT_EQ(rig.State(1), kStandstill);
    EXPECT_TRUE(b.moveA->COMMANDABORTED.value && b.moveB->COMMANDABORTED.value && b.relative->COMMANDABORTED.value)
        << "held while Execute";
    for (auto* fb : {&b.moveA, &b.moveB}) Release(rig, *fb);
    Release(rig, b.relative);
    Release(rig, b.velocity);
    Release(rig, b.halt);
    // The axis works on from where it stands.
    SetMove(b.moveA, 40.0f);
    Execute(rig, b.moveA);
    ASSERT_TRUE(EndsDone(rig, b.moveA, 20000, "MoveAbsolute"));
    EXPECT_EQ(rig.Position(1), 40.0f);
}

TEST_P(McSim, AHaltCanBeAbortedByAMoveAndAHaltAtStandstillIsDone) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    Execute(rig, b.halt);
    ASSERT_TRUE(EndsDone(rig, b.halt, 100, "Halt"));
    Release(rig, b.halt);
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    Execute(rig, b.halt);
    rig.Scan();
    EXPECT_TRUE(b.moveA->COMMANDABORTED.value);
    SetMove(b.moveB, 10.0f);
    Execute(rig, b.moveB);
    rig.Scan();
    EXPECT_TRUE(b.halt->COMMANDABORTED.value);
    ASSERT_TRUE(EndsDone(rig, b.moveB, 20000, "MoveAbsolute B"));
    EXPECT_EQ(rig.Position(1), 10.0f);
}

// The axis at full speed: from 1000 units/s at the axis parameter's 10000 units/s2 it brakes for 100 ms, and
// StopTimeout is 20 ms.
void StartMoveThatBrakesLongerThanStopTimeout(McRig& rig) {
    rig.Cyclic(1)->STOPTIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(20));
    rig.PowerUp();
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Pac().Axes().Motion(1).ActualSpeed() >= 900.0; }, 500, "speed"));
}

// An axis that brakes longer than StopTimeout ends MC_Halt with its own error, never Busy for ever.
TEST_P(McSim, AHaltLongerThanStopTimeoutEndsWithItsOwnError) {
    McRig rig(GetParam(), 1);
    McBlocks& b = rig.Blocks(1);
    ASSERT_NO_FATAL_FAILURE(StartMoveThatBrakesLongerThanStopTimeout(rig));
    Execute(rig, b.halt);
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.halt); }, 100, "Halt final"));
    EXPECT_TRUE(b.halt->ERROR.value);
    EXPECT_EQ(b.halt->ERRORID.value, kStopTimeout);
    EXPECT_TRUE(rig.Pac().Axes().Motion(1).Moving()) << "the axis still brakes";
    Release(rig, b.halt);
    ASSERT_TRUE(rig.WaitFor([&] { return !rig.Pac().Axes().Motion(1).Moving(); }, 500, "the axis stands"));
}

// A stop that fails keeps the axis in Stopping while its Execute stays TRUE (PLCopen MC_Stop: the axis stays in
// Stopping as long as Execute is TRUE; MC4 of docs/verification.md): an axis still braking after StopTimeout
// ends MC_Stop with 16#8022, and a move edged then is refused, not run on the braking axis. Once Execute
// falls the axis is not left locked: Standstill once it stands, and a move is accepted.
TEST_P(McSim, AStopThatFailsHoldsStoppingWhileExecuteAndReleasesAfterIt) {
    McRig rig(GetParam(), 1);
    McBlocks& b = rig.Blocks(1);
    ASSERT_NO_FATAL_FAILURE(StartMoveThatBrakesLongerThanStopTimeout(rig));
    Execute(rig, b.stop);
    ASSERT_TRUE(rig.WaitFor([&] { return b.stop->ERROR.value; }, 100, "Stop Error"));
    EXPECT_EQ(b.stop->ERRORID.value, kStopTimeout);
    ASSERT_TRUE(rig.Pac().Axes().Motion(1).Moving()) << "the axis still brakes";
    rig.Scan();
    EXPECT_EQ(rig.State(1), kStopping) << "a failed stop holds Stopping while its Execute is TRUE";
    SetMove(b.moveB, 10.0f);
    Execute(rig, b.moveB);
    EXPECT_EQ(b.moveB->ERRORID.value, kMcStopping) << "no move on an axis whose stop failed";
    Release(rig, b.moveB);
    EXPECT_TRUE(b.stop->ERROR.value) << "the stop's Error holds while its Execute is TRUE";
    Release(rig, b.stop);
    if (rig.Ref(1).STATUS.ACTIVE) {
        EXPECT_EQ(rig.State(1), kStopping) << "Stopping while the axis brakes";
    }
    ASSERT_TRUE(rig.WaitFor([&] { return !rig.Pac().Axes().Motion(1).Moving(); }, 500, "the axis stands"));
    // Standstill once the PLC sees ACTIVE fall: a round trip after the axis stands.
    ASSERT_TRUE(rig.WaitFor([&] { return rig.State(1) == kStandstill; }, 100, "not left locked once Execute is FALSE"));
    Execute(rig, b.moveB);
    ASSERT_TRUE(EndsDone(rig, b.moveB, 20000, "MoveAbsolute B"));
}

// MC_Stop whose Execute falls while the axis still brakes (PLCopen: Stopping until the stop is over): a move
// edged in any scan in which the axis still shows ACTIVE is refused, never run on the braking axis; and the
// stop ends with its own outcome, here 16#8022 for one scan, not CommandAborted by a move that came after its
// end. MC_MoveAbsolute B and MC_MoveRelative take turns, so that some block is edged in every scan.
TEST_P(McSim, AStopReleasedWhileBrakingHoldsStoppingUntilTheAxisStands) {
    McRig rig(GetParam(), 1);
    McBlocks& b = rig.Blocks(1);
    ASSERT_NO_FATAL_FAILURE(StartMoveThatBrakesLongerThanStopTimeout(rig));
    Execute(rig, b.stop);
    Release(rig, b.stop);
    SetMove(b.moveB, 10.0f);
    b.relative->POSITION.value = 10.0f;
    b.relative->VELOCITY.value = 500.0f;
    int stopFinals = 0;
    for (int i = 0; i < rig.ScansFor(500) && (rig.Ref(1).STATUS.ACTIVE || b.stop->BUSY.value); ++i) {
        b.moveB->EXECUTE.value = i % 2 == 0;
        b.relative->EXECUTE.value = i % 2 == 1;
        rig.Scan();
        const pac::test::PlcOpenOutputs edged =
            i % 2 == 0 ? pac::test::OutputsOf(b.moveB) : pac::test::OutputsOf(b.relative);
        if (rig.Ref(1).STATUS.ACTIVE) {
            EXPECT_EQ(edged.errorId, kMcStopping) << "a move edged while the stopped axis is ACTIVE, scan " << i;
        }
        if (Final(b.stop)) {
            ++stopFinals;
            EXPECT_TRUE(b.stop->ERROR.value) << pac::test::OutputsOf(b.stop);
            EXPECT_EQ(b.stop->ERRORID.value, kStopTimeout);
        }
    }
    EXPECT_EQ(stopFinals, 1) << "the stop's outcome shows for one scan";
    b.moveB->EXECUTE.value = FALSE;
    b.relative->EXECUTE.value = FALSE;
    ASSERT_TRUE(rig.WaitFor([&] { return !rig.Pac().Axes().Motion(1).Moving(); }, 500, "the axis stands"));
    ASSERT_TRUE(rig.WaitFor([&] { return rig.State(1) == kStandstill; }, 100, "Standstill"));
    Execute(rig, b.moveB);
    ASSERT_TRUE(EndsDone(rig, b.moveB, 20000, "MoveAbsolute B"));
}

TEST_P(McSim, StopHoldsStoppingWhileExecuteAndRefusesEveryMotion) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    Execute(rig, b.stop);
    EXPECT_TRUE(b.stop->BUSY.value);
    rig.Scan();
    EXPECT_TRUE(b.moveA->COMMANDABORTED.value);
    EXPECT_EQ(rig.State(1), kStopping);
    ASSERT_TRUE(EndsDone(rig, b.stop, 2000, "Stop"));
    EXPECT_FALSE(rig.Pac().Axes().Motion(1).Moving());
    rig.Scan(3);
    EXPECT_EQ(rig.State(1), kStopping) << "Stopping while MC_Stop's Execute is TRUE";
    SetMove(b.moveB, 10.0f);
    Execute(rig, b.moveB);
    EXPECT_EQ(b.moveB->ERRORID.value, kMcStopping);
    Release(rig, b.moveB);
    Execute(rig, b.halt);
    EXPECT_EQ(b.halt->ERRORID.value, kMcStopping);
    Release(rig, b.halt);
    Execute(rig, b.home);
    EXPECT_EQ(b.home->ERRORID.value, kMcStopping);
    Release(rig, b.home);
    // A second MC_Stop may come in Stopping and holds it from then on; the first keeps its Done.
    Execute(rig, b.stop2);
    ASSERT_TRUE(EndsDone(rig, b.stop2, 200, "Stop 2"));
    EXPECT_TRUE(b.stop->DONE.value);
    Release(rig, b.stop);
    rig.Scan(2);
    EXPECT_EQ(rig.State(1), kStopping) << "the second MC_Stop holds it now";
    Release(rig, b.stop2);
    rig.Scan();
    EXPECT_EQ(rig.State(1), kStandstill);
    Execute(rig, b.moveB);
    ASSERT_TRUE(EndsDone(rig, b.moveB, 20000, "MoveAbsolute B"));
}

// The request numbers are a UINT and wrap: after 65535 requests an MC_Stop posts under 0, the number every block
// that never posted still has. MC_Stop 2, never edged and called after it, must not take Stopping away.
TEST_P(McSim, AStopHoldsStoppingWhenTheRequestNumberWrapsToZero) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    rig.Ref(1).REQUESTSERIAL = 65534;  // as a program that has issued 65534 commands left it
    rig.Ref(1).JOBSERIAL = 65534;
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    Execute(rig, b.stop);
    ASSERT_EQ(rig.Ref(1).REQUESTSERIAL, 0u);
    EXPECT_EQ(rig.State(1), kStopping);
    ASSERT_TRUE(EndsDone(rig, b.stop, 2000, "Stop"));
    rig.Scan(3);
    EXPECT_EQ(rig.State(1), kStopping) << "Stopping while MC_Stop's Execute is TRUE";
    SetMove(b.moveB, 10.0f);
    Execute(rig, b.moveB);
    EXPECT_EQ(b.moveB->ERRORID.value, kMcStopping) << pac::test::OutputsOf(b.moveB);
    Release(rig, b.moveB);
    Release(rig, b.stop);
    EXPECT_EQ(rig.State(1), kStandstill);
    Execute(rig, b.moveB);
    ASSERT_TRUE(EndsDone(rig, b.moveB, 20000, "MoveAbsolute B"));
}

TEST_P(McSim, HomeOnlyFromStandstillAndNothingButStopWhileHoming) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    b.home->POSITION.value = 1.0f;
    Execute(rig, b.home);
    EXPECT_EQ(b.home->ERRORID.value, kMcHomePosition) << "the reference point is the axis parameter's";
    Release(rig, b.home);
    b.home->POSITION.value = 0.0f;
    // From a motion state MC_Home is refused and the motion goes on.
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    Execute(rig, b.home);
    EXPECT_EQ(b.home->ERRORID.value, kMcState);
    EXPECT_TRUE(b.moveA->BUSY.value) << "a refused block aborts nothing";
    Release(rig, b.home);
    Execute(rig, b.halt);
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.halt); }, 2000, "Halt final"));
    Release(rig, b.halt);
    Release(rig, b.moveA);
    // Homing: the reference run G25 (the simulator's cam at -20).
    Execute(rig, b.home);
    rig.Scan();
    EXPECT_EQ(rig.State(1), kHoming);
    SetMove(b.moveB, 10.0f);
    Execute(rig, b.moveB);
    EXPECT_EQ(b.moveB->ERRORID.value, kMcState);
    Release(rig, b.moveB);
    Execute(rig, b.halt);
    EXPECT_EQ(b.halt->ERRORID.value, kMcState);
    Release(rig, b.halt);
    ASSERT_TRUE(EndsDone(rig, b.home, 20000, "Home"));
    EXPECT_TRUE(rig.Ref(1).STATUS.REFERENCED);
    EXPECT_EQ(rig.State(1), kStandstill);
    Release(rig, b.home);
    // MC_Stop ends a reference run, here in its search for the cam (from 300 towards -20 at 500 AE/s).
    SetMove(b.moveA, 300.0f, 1000.0f);
    Execute(rig, b.moveA);
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.moveA); }, 2000, "MoveAbsolute final"));
    Release(rig, b.moveA);
    Execute(rig, b.home);
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Position(1) < 250.0f; }, 1000, "searching"));
    Execute(rig, b.stop);
    rig.Scan();
    EXPECT_TRUE(b.home->COMMANDABORTED.value);
    ASSERT_TRUE(EndsDone(rig, b.stop, 2000, "Stop"));
    EXPECT_GT(rig.Position(1), 0.0f) << "stopped before the cam";
}

// ONLINE stopped (STOP ONLINE, status 35): the PA-CONTROL runs no axis job (2.7), so MC_Home and a move end
// with 16#8025, nothing sent, never Done with the axis unreferenced or not moved; after START ONLINE they run.
TEST_P(McSim, NoJobRunsWhileOnlineIsStopped) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    auto& ctrl = rig.Ctrl();
    ctrl->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_STOP;
    ctrl->EXECUTE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return ctrl->DONE.value != 0; }, 500, "ONLINE stopped"));
    ctrl->EXECUTE.value = FALSE;
    rig.Scan();
    ASSERT_EQ(rig.Pac().OperatingStatus(), 35);
    ASSERT_EQ(rig.Pac().Module(1).CmdError(), 0u);
    Execute(rig, b.home);
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.home); }, 2000, "Home final"));
    EXPECT_TRUE(b.home->ERROR.value) << pac::test::OutputsOf(b.home);
    EXPECT_EQ(b.home->ERRORID.value, kNotOnline);
    Release(rig, b.home);
    SetMove(b.moveB, 10.0f);
    Execute(rig, b.moveB);
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.moveB); }, 2000, "MoveAbsolute final"));
    EXPECT_EQ(b.moveB->ERRORID.value, kNotOnline) << pac::test::OutputsOf(b.moveB);
    Release(rig, b.moveB);
    // The simulator answers a Start outside running ONLINE with CMD error 20: none came.
    EXPECT_EQ(rig.Pac().Module(1).CmdError(), 0u) << "no Start reached the controller";
    ctrl->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
    ctrl->EXECUTE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return ctrl->DONE.value != 0; }, 500, "ONLINE again"));
    ctrl->EXECUTE.value = FALSE;
    Execute(rig, b.moveB);
    ASSERT_TRUE(EndsDone(rig, b.moveB, 20000, "MoveAbsolute B"));
}

// MC_Stop in the scan after MC_Home: the traverse bit of the reference run may fall in the controller cycle
// that takes it over, before the axis has any speed; the stop still ends and the axis stands, not ACTIVE.
TEST_P(McSim, AStopRightAfterHomeEndsWithTheAxisStanding) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    Execute(rig, b.home);
    rig.Scan();
    Execute(rig, b.stop);
    ASSERT_TRUE(EndsDone(rig, b.stop, 2000, "Stop"));
    EXPECT_TRUE(b.home->COMMANDABORTED.value);
    EXPECT_FALSE(rig.Ref(1).STATUS.ACTIVE);
    EXPECT_FALSE(rig.Pac().Axes().Motion(1).Moving());
    Release(rig, b.stop);
    rig.Scan();
    EXPECT_EQ(rig.State(1), kStandstill);
}

TEST_P(McSim, AnAxisErrorMeansErrorStopUntilMcResetSeesItGone) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    b.axisError->ENABLE.value = TRUE;
    Execute(rig, b.reset);
    EXPECT_TRUE(b.reset->DONE.value) << "nothing to reset in Standstill";
    Release(rig, b.reset);
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    rig.Pac().Axes().SetDisturbance(1, rig.Now(), 5.0);
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.moveA); }, 300, "MoveAbsolute final"));
    EXPECT_TRUE(b.moveA->ERROR.value);
    EXPECT_EQ(b.moveA->ERRORID.value, kAxisError);
    rig.Scan();
    EXPECT_EQ(rig.State(1), kErrorStop);
    EXPECT_EQ(b.axisError->AXISERRORID.value, kFollowingError);
    Release(rig, b.moveA);
    // ErrorStop refuses everything but MC_Reset, MC_Power off included.
    SetMove(b.moveB, 10.0f);
    Execute(rig, b.moveB);
    EXPECT_EQ(b.moveB->ERRORID.value, kMcErrorStop);
    Release(rig, b.moveB);
    Execute(rig, b.stop);
    EXPECT_EQ(b.stop->ERRORID.value, kMcErrorStop);
    Release(rig, b.stop);
    b.power->ENABLE.value = FALSE;
    rig.ScanMs(50);
    EXPECT_EQ(rig.State(1), kErrorStop);
    // The cause persists: the pulse ends after Timeout, MC_Reset fails with the axis error.
    Execute(rig, b.reset);
    EXPECT_TRUE(b.reset->BUSY.value);
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.reset); }, 2500, "Reset final"));
    EXPECT_TRUE(b.reset->ERROR.value);
    EXPECT_EQ(b.reset->ERRORID.value, kAxisError);
    EXPECT_EQ(rig.State(1), kErrorStop);
    Release(rig, b.reset);
    rig.Pac().Axes().SetDisturbance(1, rig.Now(), 0.0);
    Execute(rig, b.reset);
    ASSERT_TRUE(EndsDone(rig, b.reset, 500, "Reset"));
    EXPECT_EQ(rig.State(1), kDisabled) << "MC_Power is off";
    Release(rig, b.reset);
    b.power->ENABLE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return rig.State(1) == kStandstill; }, 200, "Standstill"));
}

TEST_P(McSim, AnAxisErrorDuringAHaltOrAStopFailsIt) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    Execute(rig, b.halt);
    rig.Pac().Axes().SetDisturbance(1, rig.Now(), 5.0);
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.halt); }, 300, "Halt final"));
    EXPECT_TRUE(b.halt->ERROR.value);
    EXPECT_EQ(b.halt->ERRORID.value, kAxisError);
}

TEST_P(McSim, PowerOffAbortsTheMoveAndALostLinkFailsAHalt) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    b.power->ENABLE.value = FALSE;
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.moveA); }, 2000, "MoveAbsolute final"));
    EXPECT_TRUE(b.moveA->COMMANDABORTED.value);
    ASSERT_TRUE(rig.WaitFor([&] { return rig.State(1) == kDisabled; }, 100, "Disabled"));
    Release(rig, b.moveA);
    b.power->ENABLE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return rig.State(1) == kStandstill; }, 200, "Standstill"));
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    Execute(rig, b.halt);
    b.position->ENABLE.value = TRUE;
    b.axisError->ENABLE.value = TRUE;
    rig.Plc().Bus().FromPacLink().SetFault(rig.Now(), pac::sim::LinkFault::kAllZero);
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.halt); }, 300, "Halt final"));
    EXPECT_TRUE(b.halt->ERROR.value);
    EXPECT_EQ(b.halt->ERRORID.value, kNotReady);
    rig.Scan();
    EXPECT_EQ(rig.State(1), kDisabled) << "no module status";
    // No axis status: MC_Power and the read blocks show Error, their outputs are not valid.
    EXPECT_TRUE(b.power->ERROR.value && !b.power->VALID.value);
    EXPECT_EQ(b.power->ERRORID.value, kNotReady);
    EXPECT_TRUE(b.position->ERROR.value && !b.position->VALID.value && !b.position->BUSY.value);
    EXPECT_EQ(b.position->ERRORID.value, kNotReady);
    EXPECT_TRUE(b.axisError->ERROR.value && !b.axisError->VALID.value);
    EXPECT_EQ(b.axisError->ERRORID.value, kNotReady);
    rig.Plc().Bus().FromPacLink().SetFault(rig.Now(), pac::sim::LinkFault::kNone);
    ASSERT_TRUE(rig.WaitFor([&] { return rig.State(1) == kStandstill; }, 200, "Standstill again"));
    EXPECT_TRUE(b.power->VALID.value && b.position->VALID.value && b.axisError->VALID.value);
}

TEST_P(McSim, MoveVelocityRunsToTheRangeEndAndThatEndsItWithAnError) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    b.status->ENABLE.value = TRUE;
    SetMove(b.moveA, 30.0f, 1000.0f);
    Execute(rig, b.moveA);
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.moveA); }, 2000, "MoveAbsolute final"));
    Release(rig, b.moveA);
    // To the min. traverse range (axis parameter 8: 0.0) at 300 AE/s.
    b.velocity->VELOCITY.value = 300.0f;
    b.velocity->DIRECTION.value = E_PAC_MCDIRECTION__PAC_MC_NEGATIVE;
    Execute(rig, b.velocity);
    rig.Scan();
    EXPECT_EQ(rig.State(1), kContinuous);
    EXPECT_TRUE(b.status->CONTINUOUSMOTION.value);
    EXPECT_EQ(rig.SentWord(1, 6), 300u);
    ASSERT_TRUE(rig.WaitFor([&] { return Final(b.velocity); }, 2000, "MoveVelocity final"));
    EXPECT_TRUE(b.velocity->ERROR.value);
    EXPECT_EQ(b.velocity->ERRORID.value, kMcRangeEnd);
    EXPECT_EQ(rig.Position(1), 0.0f);
    rig.Scan();
    EXPECT_EQ(rig.State(1), kStandstill);
}

// InVelocity means the commanded velocity is reached (PLCopen). From standstill at 40 units/s with 100 units/s2
// the ramp takes 0.4 s: in every scan that shows InVelocity the controller's axis runs at 40 units/s.
TEST_P(McSim, InVelocityOnlyOnceTheAxisRunsAtTheVelocity) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    b.velocity->VELOCITY.value = 40.0f;
    b.velocity->ACCELERATION.value = 100.0f;
    b.velocity->DIRECTION.value = E_PAC_MCDIRECTION__PAC_MC_POSITIVE;
    Execute(rig, b.velocity);
    int early = 0;
    ASSERT_TRUE(rig.WaitFor([&] {
        const double speed = rig.Pac().Axes().Motion(1).Velocity();
        if (b.velocity->INVELOCITY.value && std::fabs(speed - 40.0) > 0.04 && early++ == 0) {
            ADD_FAILURE() << "InVelocity with the controller's axis at " << speed << " units/s (scan " << rig.ScanCount() << ")";
        }
        return b.velocity->INVELOCITY.value != 0;
    }, 1500, "InVelocity"));
    EXPECT_NEAR(rig.Pac().Axes().Motion(1).Velocity(), 40.0, 0.04);
}

// InVelocity only for the block's own job: MC_MoveVelocity edged 1 to 8 scans after an MC_MoveAbsolute, whose
// Start may still be on the wire when the velocity job is posted (the ACTIVE that follows is the move's), shows
// InVelocity only once the controller took the velocity job over (its ledger of the jobs taken on a Start).
TEST_P(McSim, InVelocityOnlyForTheBlocksOwnJob) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    const auto& taken = rig.Pac().Module(1).TakenJobs();
    for (int after = 1; after <= 8; ++after) {
        SCOPED_TRACE("MC_MoveVelocity " + std::to_string(after) + " scans after the move");
        SetMove(b.moveA, rig.Position(1) < 50.0f ? 90.0f : 10.0f, 1000.0f);
        Execute(rig, b.moveA);
        rig.Scan(after - 1);
        b.velocity->VELOCITY.value = 20.0f;
        b.velocity->DIRECTION.value = rig.Position(1) < 50.0f ? E_PAC_MCDIRECTION__PAC_MC_POSITIVE : E_PAC_MCDIRECTION__PAC_MC_NEGATIVE;
        const std::size_t before = taken.size();
        Execute(rig, b.velocity);
        ASSERT_TRUE(rig.WaitFor([&] {
            constexpr std::uint32_t kVelocityBits = pac::axis_control::kMoveToMax | pac::axis_control::kMoveToMin;
            bool own = false;
            for (std::size_t k = before; k < taken.size(); ++k) {
                own = own || (taken[k].command.control & kVelocityBits) != 0;
            }
            if (b.velocity->INVELOCITY.value && !own) {
                ADD_FAILURE() << "InVelocity before the controller took the velocity job (scan " << rig.ScanCount() << ")";
                return true;
            }
            return b.velocity->INVELOCITY.value != 0;
        }, 1000, "InVelocity"));
        Release(rig, b.moveA);
        Execute(rig, b.halt);
        ASSERT_TRUE(EndsDone(rig, b.halt, 2000, "Halt"));
        Release(rig, b.velocity);
        Release(rig, b.halt);
        if (HasFailure()) break;
    }
}

// ---- what the PA-CONTROL cannot do, and values outside what the module carries ----------------------------

TEST_P(McSim, WhatThePaControlCannotDoIsRefusedAndAbortsNothing) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    auto refusedB = [&](auto setup, std::uint32_t expected, const char* what) {
        SetMove(b.moveB, 10.0f);
        b.moveB->ACCELERATION.value = 0.0f;
        b.moveB->DECELERATION.value = 0.0f;
        b.moveB->JERK.value = 0.0f;
        b.moveB->BUFFERMODE.value = E_PAC_MCBUFFERMODE__PAC_MC_ABORTING;
        setup();
        Execute(rig, b.moveB);
        EXPECT_TRUE(b.moveB->ERROR.value) << what;
        EXPECT_EQ(b.moveB->ERRORID.value, expected) << what;
        Release(rig, b.moveB);
        EXPECT_TRUE(b.moveA->BUSY.value) << what << ": the running move goes on";
    };
    refusedB([&] { b.moveB->BUFFERMODE.value = E_PAC_MCBUFFERMODE__PAC_MC_BUFFERED; }, kMcBufferMode, "Buffered");
    refusedB([&] { b.moveB->BUFFERMODE.value = E_PAC_MCBUFFERMODE__PAC_MC_BLENDING_LOW; }, kMcBufferMode, "Blending");
    refusedB([&] { b.moveB->JERK.value = 1000.0f; }, kMcJerk, "Jerk");
    refusedB([&] { b.moveB->DECELERATION.value = 5000.0f; }, kMcDeceleration, "Deceleration apart");
    refusedB([&] {
        b.moveB->ACCELERATION.value = 5000.0f;
        b.moveB->DECELERATION.value = 6000.0f;
    }, kMcDeceleration, "Deceleration apart from Acceleration");
    refusedB([&] { b.moveB->VELOCITY.value = 0.0f; }, kInvalidVelocity, "Velocity 0");
    refusedB([&] { b.moveB->VELOCITY.value = 0.4f; }, kInvalidVelocity, "below half a per mille");
    refusedB([&] { b.moveB->VELOCITY.value = 1000.6f; }, kInvalidVelocity, "above the traverse speed");
    refusedB([&] { b.moveB->VELOCITY.value = NAN; }, kInvalidVelocity, "NaN");
    refusedB([&] { b.moveB->ACCELERATION.value = -1.0f; }, kInvalidAcceleration, "negative acceleration");
    refusedB([&] { b.moveB->ACCELERATION.value = 700000.0f; }, kInvalidAcceleration, "beyond 65535 per mille");
    refusedB([&] { b.moveB->POSITION.value = NAN; }, kInvalidPosition, "Position NaN");
    refusedB([&] { b.moveB->POSITION.value = INFINITY; }, kInvalidPosition, "Position infinite");
    b.velocity->VELOCITY.value = 100.0f;
    b.velocity->DIRECTION.value = E_PAC_MCDIRECTION__PAC_MC_SHORTEST_WAY;
    Execute(rig, b.velocity);
    EXPECT_EQ(b.velocity->ERRORID.value, kMcDirection);
    Release(rig, b.velocity);
    b.velocity->DIRECTION.value = E_PAC_MCDIRECTION__PAC_MC_CURRENT;
    Execute(rig, b.velocity);
    EXPECT_EQ(b.velocity->ERRORID.value, kMcDirection);
    Release(rig, b.velocity);
    b.halt->DECELERATION.value = 100.0f;
    Execute(rig, b.halt);
    EXPECT_EQ(b.halt->ERRORID.value, kMcDeceleration) << "a halt brakes on the running job's ramp";
    Release(rig, b.halt);
    b.halt->DECELERATION.value = 0.0f;
    b.halt->BUFFERMODE.value = E_PAC_MCBUFFERMODE__PAC_MC_BLENDING_NEXT;
    Execute(rig, b.halt);
    EXPECT_EQ(b.halt->ERRORID.value, kMcBufferMode);
    Release(rig, b.halt);
    b.stop->JERK.value = 1.0f;
    Execute(rig, b.stop);
    EXPECT_EQ(b.stop->ERRORID.value, kMcJerk);
    Release(rig, b.stop);
    b.home->BUFFERMODE.value = E_PAC_MCBUFFERMODE__PAC_MC_BUFFERED;
    Execute(rig, b.home);
    EXPECT_EQ(b.home->ERRORID.value, kMcBufferMode);
    Release(rig, b.home);
    EXPECT_TRUE(b.moveA->BUSY.value);
    EXPECT_EQ(rig.State(1), kDiscrete);
}

TEST_P(McSim, WithoutTheAxisParametersNoVelocityFits) {
    McRig rig(GetParam(), 1);
    rig.PowerUp();
    McBlocks& b = rig.Blocks(1);
    rig.Cyclic(1)->MAXVELOCITY.value = 0.0f;
    rig.Scan();
    SetMove(b.moveA, 10.0f);
    Execute(rig, b.moveA);
    EXPECT_EQ(b.moveA->ERRORID.value, kInvalidVelocity);
}

}  // namespace
}  // namespace test_mc_blocks_sim
