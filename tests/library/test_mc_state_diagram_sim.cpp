// The PLCopen state diagram of the MC_ blocks (docs/fb/MC_blocks.md, "State diagram") on the simulated
// PA-CONTROL: every motion block's Execute edge in every state, accepted or refused with the diagram's ErrorID;
// leaving states by MC_Stop and MC_Power; MC_ReadStatus showing exactly one state; eight axes at once.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "mc_test_steps.hpp"

namespace test_mc_state_diagram_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace pac::test::mc;
using pac::test::BusTiming;
using pac::test::McRig;
using pac::test::McBlocks;

class McStateSim : public ::testing::TestWithParam<BusTiming> {};
INSTANTIATE_TEST_SUITE_P(BusTimings, McStateSim, ::testing::ValuesIn(McTimings()), pac::test::BusTimingName);

// ---- the state diagram, block by block and state by state ---------------------------------------------

// Brings axis 1 into `state` with blocks other than the one under test (moveB and stop2 are kept for that).
void Reach(McRig& rig, E_PAC_MCSTATE state) {
    McBlocks& b = rig.Blocks(1);
    if (state == kDisabled) {
        rig.GoOnline();
        return;
    }
    rig.PowerUp();
    if (state == kHoming) {
        SetMove(b.moveA, 300.0f, 1000.0f);
        Execute(rig, b.moveA);
        ASSERT_TRUE(rig.WaitFor([&] { return Final(b.moveA); }, 2000, "MoveAbsolute final"));
        Release(rig, b.moveA);
        Execute(rig, b.home);
        ASSERT_TRUE(rig.WaitFor([&] { return rig.Position(1) < 290.0f; }, 1000, "searching"));
    } else if (state == kDiscrete || state == kStopping) {
        StartLongMove(rig);
        if (state == kStopping) {
            Execute(rig, b.stop2);
            ASSERT_TRUE(rig.WaitFor([&] { return Final(b.stop2); }, 2000, "Stop final"));
        }
    } else if (state == kContinuous) {
        b.velocity->VELOCITY.value = 200.0f;
        Execute(rig, b.velocity);
        ASSERT_TRUE(rig.WaitFor([&] { return b.velocity->INVELOCITY.value != 0; }, 300, "InVelocity"));
    } else if (state == kErrorStop) {
        rig.Pac().Axes().SetDisturbance(1, rig.Now(), 5.0);
        ASSERT_TRUE(rig.WaitFor([&] { return rig.State(1) == kErrorStop; }, 300, "ErrorStop"));
    }
    ASSERT_EQ(rig.State(1), state);
}

// The block's Execute edge; its outputs in the edge scan. An instance that may have brought the axis into its
// state (it goes on meanwhile) gets a new edge.
pac::test::PlcOpenOutputs Try(McRig& rig, McBlock block) {
    McBlocks& b = rig.Blocks(1);
    if (block == McBlock::kMoveVelocity && b.velocity->EXECUTE.value) Release(rig, b.velocity);
    if (block == McBlock::kHome && b.home->EXECUTE.value) Release(rig, b.home);
    Arm(rig, block);
    rig.Scan();
    return OutputsOf(rig, block);
}

TEST_P(McStateSim, EveryBlockInEveryStateIsAcceptedOrRefusedAsTheDiagramSays) {
    for (const auto state : {kDisabled, kStandstill, kHoming, kDiscrete, kContinuous, kStopping, kErrorStop}) {
        for (const McBlock block : {McBlock::kMoveAbsolute, McBlock::kMoveRelative, McBlock::kMoveVelocity,
                                    McBlock::kHalt, McBlock::kHome, McBlock::kStop, McBlock::kReset}) {
            SCOPED_TRACE(std::string(Name(block)) + " in " + Name(state));
            McRig rig(GetParam(), 1);
            ASSERT_NO_FATAL_FAILURE(Reach(rig, state));
            const pac::test::PlcOpenOutputs out = Try(rig, block);
            const std::uint32_t expected = Refusal(state, block);
            if (expected != 0) {
                EXPECT_TRUE(out.error) << out;
                EXPECT_EQ(out.errorId, expected) << out;
                rig.Scan();
                EXPECT_EQ(rig.State(1), state) << "a refused block changes nothing";
            } else {
                EXPECT_TRUE(out.busy || out.done) << out;
            }
        }
    }
}

// Leaving each state: Stop from ContinuousMotion, MC_Power off from Homing and from Stopping.
TEST_P(McStateSim, StopEndsAContinuousMotionAndPowerOffDisablesFromHomingAndStopping) {
    {
        McRig rig(GetParam(), 1);
        ASSERT_NO_FATAL_FAILURE(Reach(rig, kContinuous));
        McBlocks& b = rig.Blocks(1);
        Execute(rig, b.stop);
        rig.Scan();
        EXPECT_TRUE(b.velocity->COMMANDABORTED.value);
        EXPECT_EQ(rig.State(1), kStopping);
        ASSERT_TRUE(EndsDone(rig, b.stop, 2000, "Stop"));
    }
    for (const auto state : {kHoming, kStopping}) {
        SCOPED_TRACE(std::string("from ") + Name(state));
        McRig rig(GetParam(), 1);
        ASSERT_NO_FATAL_FAILURE(Reach(rig, state));
        rig.Blocks(1).power->ENABLE.value = FALSE;
        ASSERT_TRUE(rig.WaitFor([&] { return rig.State(1) == kDisabled; }, 300, "Disabled"));
        if (state == kHoming) {
            ASSERT_TRUE(rig.WaitFor([&] { return Final(rig.Blocks(1).home); }, 300, "Home final"));
            EXPECT_TRUE(rig.Blocks(1).home->COMMANDABORTED.value);
        }
    }
}

// ---- MC_ReadStatus ----------------------------------------------------------------------------------------

TEST_P(McStateSim, ReadStatusShowsExactlyTheStateWhileEnabled) {
    McRig rig(GetParam(), 1);
    McBlocks& b = rig.Blocks(1);
    auto shown = [&] {
        const auto& s = b.status.Data();
        return int{s.ERRORSTOP.value} + int{s.DISABLED.value} + int{s.STOPPING.value} + int{s.HOMING.value} +
               int{s.STANDSTILL.value} + int{s.DISCRETEMOTION.value} + int{s.CONTINUOUSMOTION.value} +
               int{s.SYNCHRONIZEDMOTION.value};
    };
    rig.Scan();
    EXPECT_EQ(shown(), 0) << "nothing while Enable is FALSE";
    EXPECT_FALSE(b.status->VALID.value || b.status->BUSY.value);
    b.status->ENABLE.value = TRUE;
    rig.Scan();
    EXPECT_TRUE(b.status->VALID.value && b.status->BUSY.value && !b.status->ERROR.value);
    EXPECT_TRUE(b.status->DISABLED.value);
    EXPECT_EQ(shown(), 1);
    rig.PowerUp();
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    Execute(rig, b.stop);
    rig.Scan();
    EXPECT_TRUE(b.status->STOPPING.value);
    EXPECT_EQ(shown(), 1);
    rig.Pac().Axes().SetDisturbance(1, rig.Now(), 5.0);
    ASSERT_TRUE(rig.WaitFor([&] { return b.status->ERRORSTOP.value != 0; }, 300, "ErrorStop"));
    EXPECT_EQ(shown(), 1);
}

// ---- eight axes ---------------------------------------------------------------------------------------------

TEST_P(McStateSim, EightAxesMoveAtOnceAndAnErrorStopsOnlyItsAxis) {
    McRig rig(GetParam(), 8);
    rig.PowerUp();
    for (int k = 1; k <= 8; ++k) {
        SetMove(rig.Blocks(k).moveA, 10.0f * static_cast<float>(k) + 100.0f, 1000.0f);
        rig.Blocks(k).moveA->EXECUTE.value = TRUE;
    }
    rig.Scan();
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Ref(3).STATUS.ACTIVE != 0; }, 200, "axis 3 ACTIVE"));
    rig.Pac().Axes().SetBlocked(3, rig.Now(), true);
    ASSERT_TRUE(rig.WaitFor([&] {
        for (int k = 1; k <= 8; ++k) {
            if (!Final(rig.Blocks(k).moveA)) return false;
        }
        return true;
    }, 2000, "every move final"));
    rig.Scan();
    for (int k = 1; k <= 8; ++k) {
        SCOPED_TRACE("axis " + std::to_string(k));
        auto& move = rig.Blocks(k).moveA;
        if (k == 3) {
            EXPECT_EQ(move->ERRORID.value, kAxisError);
            EXPECT_EQ(rig.State(k), kErrorStop);
        } else {
            EXPECT_TRUE(move->DONE.value) << "ErrorID " << move->ERRORID.value;
            EXPECT_EQ(rig.Position(k), 10.0f * static_cast<float>(k) + 100.0f);
            EXPECT_EQ(rig.State(k), kStandstill);
        }
    }
}

}  // namespace
}  // namespace test_mc_state_diagram_sim
