// The PLCopen state diagram of the MC_ blocks (docs/fb/MC_blocks.md, "State diagram") on the simulated
// PA-CONTROL: every motion block's Execute edge in every state, accepted or refused with the diagram's ErrorID;
// leaving states by MC_Stop and MC_Power; MC_ReadStatus showing exactly one state; eight axes at once.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "mc_test_steps.hpp"

namespace {

using namespace pac::test::mc;
using pac::test::BusTiming;
using pac::test::McBench;
using pac::test::McBlocks;

class McStateSim : public ::testing::TestWithParam<BusTiming> {};
INSTANTIATE_TEST_SUITE_P(BusTimings, McStateSim, ::testing::ValuesIn(McTimings()), pac::test::BusTimingName);

// ---- the state diagram, block by block and state by state ---------------------------------------------

// Brings axis 1 into `state` with blocks other than the one under test (moveB and stop2 are kept for that).
void Reach(McBench& bench, E_PAC_MCSTATE state) {
    McBlocks& b = bench.Blocks(1);
    if (state == kDisabled) {
        bench.GoOnline();
        return;
    }
    bench.PowerUp();
    if (state == kHoming) {
        SetMove(b.moveA, 300.0f, 1000.0f);
        Execute(bench, b.moveA);
        ASSERT_TRUE(bench.WaitFor([&] { return Final(b.moveA); }, 2000, "MoveAbsolute final"));
        Release(bench, b.moveA);
        Execute(bench, b.home);
        ASSERT_TRUE(bench.WaitFor([&] { return bench.Position(1) < 290.0f; }, 1000, "searching"));
    } else if (state == kDiscrete || state == kStopping) {
        StartLongMove(bench);
        if (state == kStopping) {
            Execute(bench, b.stop2);
            ASSERT_TRUE(bench.WaitFor([&] { return Final(b.stop2); }, 2000, "Stop final"));
        }
    } else if (state == kContinuous) {
        b.velocity->VELOCITY.value = 200.0f;
        Execute(bench, b.velocity);
        ASSERT_TRUE(bench.WaitFor([&] { return b.velocity->INVELOCITY.value != 0; }, 300, "InVelocity"));
    } else if (state == kErrorStop) {
        bench.Pac().Axes().SetDisturbance(1, bench.Now(), 5.0);
        ASSERT_TRUE(bench.WaitFor([&] { return bench.State(1) == kErrorStop; }, 300, "ErrorStop"));
    }
    ASSERT_EQ(bench.State(1), state);
}

// The block's Execute edge; its outputs in the edge scan. An instance that may have brought the axis into its
// state (it goes on meanwhile) gets a new edge.
pac::test::PlcOpenOutputs Try(McBench& bench, McBlock block) {
    McBlocks& b = bench.Blocks(1);
    if (block == McBlock::kMoveVelocity && b.velocity->EXECUTE.value) Release(bench, b.velocity);
    if (block == McBlock::kHome && b.home->EXECUTE.value) Release(bench, b.home);
    Arm(bench, block);
    bench.Scan();
    return OutputsOf(bench, block);
}

TEST_P(McStateSim, EveryBlockInEveryStateIsAcceptedOrRefusedAsTheDiagramSays) {
    for (const auto state : {kDisabled, kStandstill, kHoming, kDiscrete, kContinuous, kStopping, kErrorStop}) {
        for (const McBlock block : {McBlock::kMoveAbsolute, McBlock::kMoveRelative, McBlock::kMoveVelocity,
                                    McBlock::kHalt, McBlock::kHome, McBlock::kStop, McBlock::kReset}) {
            SCOPED_TRACE(std::string(Name(block)) + " in " + Name(state));
            McBench bench(GetParam(), 1);
            ASSERT_NO_FATAL_FAILURE(Reach(bench, state));
            const pac::test::PlcOpenOutputs out = Try(bench, block);
            const std::uint32_t expected = Refusal(state, block);
            if (expected != 0) {
                EXPECT_TRUE(out.error) << out;
                EXPECT_EQ(out.errorId, expected) << out;
                bench.Scan();
                EXPECT_EQ(bench.State(1), state) << "a refused block changes nothing";
            } else {
                EXPECT_TRUE(out.busy || out.done) << out;
            }
        }
    }
}

// Leaving each state: Stop from ContinuousMotion, MC_Power off from Homing and from Stopping.
TEST_P(McStateSim, StopEndsAContinuousMotionAndPowerOffDisablesFromHomingAndStopping) {
    {
        McBench bench(GetParam(), 1);
        ASSERT_NO_FATAL_FAILURE(Reach(bench, kContinuous));
        McBlocks& b = bench.Blocks(1);
        Execute(bench, b.stop);
        bench.Scan();
        EXPECT_TRUE(b.velocity->COMMANDABORTED.value);
        EXPECT_EQ(bench.State(1), kStopping);
        ASSERT_TRUE(EndsDone(bench, b.stop, 2000, "Stop"));
    }
    for (const auto state : {kHoming, kStopping}) {
        SCOPED_TRACE(std::string("from ") + Name(state));
        McBench bench(GetParam(), 1);
        ASSERT_NO_FATAL_FAILURE(Reach(bench, state));
        bench.Blocks(1).power->ENABLE.value = FALSE;
        ASSERT_TRUE(bench.WaitFor([&] { return bench.State(1) == kDisabled; }, 300, "Disabled"));
        if (state == kHoming) {
            ASSERT_TRUE(bench.WaitFor([&] { return Final(bench.Blocks(1).home); }, 300, "Home final"));
            EXPECT_TRUE(bench.Blocks(1).home->COMMANDABORTED.value);
        }
    }
}

// ---- MC_ReadStatus ----------------------------------------------------------------------------------------

TEST_P(McStateSim, ReadStatusShowsExactlyTheStateWhileEnabled) {
    McBench bench(GetParam(), 1);
    McBlocks& b = bench.Blocks(1);
    auto shown = [&] {
        const auto& s = b.status.Data();
        return int{s.ERRORSTOP.value} + int{s.DISABLED.value} + int{s.STOPPING.value} + int{s.HOMING.value} +
               int{s.STANDSTILL.value} + int{s.DISCRETEMOTION.value} + int{s.CONTINUOUSMOTION.value} +
               int{s.SYNCHRONIZEDMOTION.value};
    };
    bench.Scan();
    EXPECT_EQ(shown(), 0) << "nothing while Enable is FALSE";
    EXPECT_FALSE(b.status->VALID.value || b.status->BUSY.value);
    b.status->ENABLE.value = TRUE;
    bench.Scan();
    EXPECT_TRUE(b.status->VALID.value && b.status->BUSY.value && !b.status->ERROR.value);
    EXPECT_TRUE(b.status->DISABLED.value);
    EXPECT_EQ(shown(), 1);
    bench.PowerUp();
    ASSERT_NO_FATAL_FAILURE(StartLongMove(bench));
    Execute(bench, b.stop);
    bench.Scan();
    EXPECT_TRUE(b.status->STOPPING.value);
    EXPECT_EQ(shown(), 1);
    bench.Pac().Axes().SetDisturbance(1, bench.Now(), 5.0);
    ASSERT_TRUE(bench.WaitFor([&] { return b.status->ERRORSTOP.value != 0; }, 300, "ErrorStop"));
    EXPECT_EQ(shown(), 1);
}

// ---- eight axes ---------------------------------------------------------------------------------------------

TEST_P(McStateSim, EightAxesMoveAtOnceAndAnErrorStopsOnlyItsAxis) {
    McBench bench(GetParam(), 8);
    bench.PowerUp();
    for (int k = 1; k <= 8; ++k) {
        SetMove(bench.Blocks(k).moveA, 10.0f * static_cast<float>(k) + 100.0f, 1000.0f);
        bench.Blocks(k).moveA->EXECUTE.value = TRUE;
    }
    bench.Scan();
    ASSERT_TRUE(bench.WaitFor([&] { return bench.Ref(3).STATUS.ACTIVE != 0; }, 200, "axis 3 ACTIVE"));
    bench.Pac().Axes().SetBlocked(3, bench.Now(), true);
    ASSERT_TRUE(bench.WaitFor([&] {
        for (int k = 1; k <= 8; ++k) {
            if (!Final(bench.Blocks(k).moveA)) return false;
        }
        return true;
    }, 2000, "every move final"));
    bench.Scan();
    for (int k = 1; k <= 8; ++k) {
        SCOPED_TRACE("axis " + std::to_string(k));
        auto& move = bench.Blocks(k).moveA;
        if (k == 3) {
            EXPECT_EQ(move->ERRORID.value, kAxisError);
            EXPECT_EQ(bench.State(k), kErrorStop);
        } else {
            EXPECT_TRUE(move->DONE.value) << "ErrorID " << move->ERRORID.value;
            EXPECT_EQ(bench.Position(k), 10.0f * static_cast<float>(k) + 100.0f);
            EXPECT_EQ(bench.State(k), kStandstill);
        }
    }
}

}  // namespace
