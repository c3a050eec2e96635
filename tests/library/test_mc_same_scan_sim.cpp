// Two MC_ blocks edged in the same scan, in both call orders (docs/fb/MC_blocks.md, "State diagram"): PLCopen
// changes the axis state when a command is issued, so the block called second is accepted or refused on the
// state the first one entered. Every pair of MC_Power (Enable falling), MC_Home, MC_MoveAbsolute,
// MC_MoveRelative, MC_MoveVelocity, MC_Halt, two MC_Stop and MC_Reset, from Standstill, Homing, DiscreteMotion,
// ContinuousMotion and Stopping (brought there by the A instances), on the MC suites' bus timings: the edge
// scan as the diagram says, the last accepted block runs to its end, a stop is never lost (Stopping refuses
// motion while its Execute is TRUE) and the axis is never left locked.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "mc_test_steps.hpp"

namespace test_mc_same_scan_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace pac::test::mc;
using pac::test::BusTiming;
using pac::test::McRig;
using pac::test::McBlocks;
using pac::test::McCallOrder;

class McSameScanSim : public ::testing::TestWithParam<BusTiming> {};
INSTANTIATE_TEST_SUITE_P(BusTimings, McSameScanSim, ::testing::ValuesIn(McTimings()), pac::test::BusTimingName);

const McBlock kPairBlocks[] = {McBlock::kPowerOff,     McBlock::kHome, McBlock::kMoveAbsolute,
                               McBlock::kMoveRelative, McBlock::kMoveVelocity, McBlock::kHalt,
                               McBlock::kStop,         McBlock::kStop2, McBlock::kReset};

// What the diagram makes of blocks edged in one scan in call order, from `state`.
struct Expectation {
    std::vector<std::uint32_t> refusals;  // per call, 0 accepted
    E_PAC_MCSTATE state;                  // at the end of the edge scan
    bool poweredOff = false;
    bool hasWinner = false;  // a motion block was accepted: the last one owns the axis
    McBlock winner = McBlock::kReset;
};

Expectation Expect(E_PAC_MCSTATE state, const std::vector<McBlock>& calls) {
    Expectation e{{}, state};
    for (const McBlock block : calls) {
        const std::uint32_t refusal = Refusal(e.state, block);
        e.refusals.push_back(refusal);
        if (refusal != 0) continue;
        e.state = Entered(e.state, block);
        if (block == McBlock::kPowerOff) {
            e.poweredOff = true;
        } else if (block != McBlock::kReset) {
            e.hasWinner = true;
            e.winner = block;
        }
    }
    return e;
}

// The axis is free again: every block released, MC_Power on, Standstill within 300 ms, and a new
// MC_MoveAbsolute A (MC_Home A on an axis left unreferenced) is accepted and ends Done. No MC_Stop is cycled.
void ExpectNotLocked(McRig& rig) {
    McBlocks& b = rig.Blocks(1);
    for (const McBlock block : kPairBlocks) Disarm(rig, block);
    for (auto* fb : {&b.moveA->EXECUTE, &b.homeA->EXECUTE, &b.velocityA->EXECUTE, &b.stopA->EXECUTE}) fb->value = FALSE;
    rig.Scan();
    ASSERT_TRUE(rig.WaitFor([&] { return rig.State(1) == kStandstill; }, 300, "Standstill"))
        << "state " << Name(rig.State(1));
    ASSERT_TRUE(rig.WaitFor([&] { return !rig.Pac().Axes().Motion(1).Moving(); }, 2000, "the axis stands"));
    if (!rig.Ref(1).STATUS.REFERENCED) {
        // An interrupted reference run leaves the axis unreferenced: the controller refuses moves (43).
        Execute(rig, b.homeA);
        EXPECT_TRUE(b.homeA->BUSY.value) << "refused in Standstill: " << pac::test::OutputsOf(b.homeA);
        ASSERT_TRUE(EndsDone(rig, b.homeA, 20000, "Home A after the pair"));
        return;
    }
    const float target = rig.Position(1) + 20.0f;
    SetMove(b.moveA, target);
    Execute(rig, b.moveA);
    EXPECT_TRUE(b.moveA->BUSY.value) << "refused in Standstill: " << pac::test::OutputsOf(b.moveA);
    ASSERT_TRUE(EndsDone(rig, b.moveA, 2000, "MoveAbsolute A after the pair"));
    EXPECT_EQ(rig.Position(1), target);
}

// An MC_MoveVelocity that owns the axis reaches InVelocity and is halted by MC_Halt.
void ExpectInVelocityThenHalt(McRig& rig, pac::FbInstance<MC_MOVEVELOCITY>& velocity) {
    McBlocks& b = rig.Blocks(1);
    ASSERT_TRUE(rig.WaitFor([&] { return velocity->INVELOCITY.value != 0; }, 300, "InVelocity"));
    if (b.halt->EXECUTE.value) Release(rig, b.halt);
    Execute(rig, b.halt);
    ASSERT_TRUE(EndsDone(rig, b.halt, 2000, "Halt of MoveVelocity"));
}

// A stop is done and its Execute stays TRUE: the axis stands in Stopping and a new move is refused (16#8032).
void ExpectStoppingHeld(McRig& rig) {
    McBlocks& b = rig.Blocks(1);
    EXPECT_FALSE(rig.Pac().Axes().Motion(1).Moving()) << "the stop is done: the axis stands";
    rig.Scan(3);
    EXPECT_EQ(rig.State(1), kStopping) << "Stopping while MC_Stop's Execute is TRUE";
    SetMove(b.moveA, rig.Position(1) + 5.0f);
    if (b.moveA->EXECUTE.value) Release(rig, b.moveA);
    Execute(rig, b.moveA);
    EXPECT_EQ(b.moveA->ERRORID.value, kMcStopping) << pac::test::OutputsOf(b.moveA);
    Release(rig, b.moveA);
}

// The last accepted block runs to its end: Done, MC_MoveVelocity InVelocity (then halted); a stop holds
// Stopping while its Execute stays TRUE.
void ExpectWinnerEnds(McRig& rig, McBlock winner) {
    if (winner == McBlock::kMoveVelocity) {
        ExpectInVelocityThenHalt(rig, rig.Blocks(1).velocity);
        return;
    }
    const std::string name = Name(winner);
    ASSERT_TRUE(rig.WaitFor([&] { return OutputsOf(rig, winner).Final(); }, 20000, name + " final"));
    const pac::test::PlcOpenOutputs out = OutputsOf(rig, winner);
    ASSERT_TRUE(out.done) << Name(winner) << " owns the axis: " << out;
    if (IsStop(winner)) ExpectStoppingHeld(rig);
}

// From Standstill into `from` with the A instances, outside the pair: MC_MoveAbsolute A towards 5000 at
// 1000 AE/s, MC_Home A searching from 300, MC_MoveVelocity A at 200 AE/s, MC_Stop A done on A's move.
void Reach(McRig& rig, E_PAC_MCSTATE from) {
    McBlocks& b = rig.Blocks(1);
    if (from == kDiscrete || from == kStopping) {
        ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
    }
    if (from == kStopping) {
        Execute(rig, b.stopA);
        ASSERT_TRUE(EndsDone(rig, b.stopA, 2000, "Stop A"));
    } else if (from == kHoming) {
        SetMove(b.moveA, 300.0f, 1000.0f);
        Execute(rig, b.moveA);
        ASSERT_TRUE(EndsDone(rig, b.moveA, 2000, "MoveAbsolute A to 300"));
        Release(rig, b.moveA);
        Execute(rig, b.homeA);
        ASSERT_TRUE(rig.WaitFor([&] { return rig.Position(1) < 290.0f; }, 1000, "searching"));
    } else if (from == kContinuous) {
        b.velocityA->VELOCITY.value = 200.0f;
        Execute(rig, b.velocityA);
        ASSERT_TRUE(rig.WaitFor([&] { return b.velocityA->INVELOCITY.value != 0; }, 300, "InVelocity A"));
    }
    ASSERT_EQ(rig.State(1), from);
}

// The outputs of the A instance that brought the axis into `from`; none from Standstill.
pac::test::PlcOpenOutputs ReacherOutputs(McRig& rig, E_PAC_MCSTATE from) {
    McBlocks& b = rig.Blocks(1);
    if (from == kDiscrete) return pac::test::OutputsOf(b.moveA);
    if (from == kHoming) return pac::test::OutputsOf(b.homeA);
    if (from == kContinuous) return pac::test::VelocityOutputsOf(b.velocityA);
    if (from == kStopping) return pac::test::OutputsOf(b.stopA);
    return {};
}

// Nothing of the pair took the axis: the A instance runs on to its end (MC_MoveVelocity A: halted), MC_Stop A
// holds Stopping.
void ExpectReacherRunsOn(McRig& rig, E_PAC_MCSTATE from) {
    McBlocks& b = rig.Blocks(1);
    if (from == kDiscrete) {
        ASSERT_TRUE(EndsDone(rig, b.moveA, 20000, "MoveAbsolute A, nothing having aborted it"));
    } else if (from == kHoming) {
        ASSERT_TRUE(EndsDone(rig, b.homeA, 20000, "Home A, nothing having aborted it"));
    } else if (from == kContinuous) {
        ExpectInVelocityThenHalt(rig, b.velocityA);
    } else if (from == kStopping) {
        ExpectStoppingHeld(rig);
    }
}

void RunPair(const BusTiming& timing, E_PAC_MCSTATE from, McBlock first, McBlock second, McCallOrder order) {
    McRig rig(timing, 1, {}, order);
    ASSERT_NO_FATAL_FAILURE(rig.PowerUp());
    McBlocks& b = rig.Blocks(1);
    ASSERT_NO_FATAL_FAILURE(Reach(rig, from));
    const std::vector<McBlock> calls = {first, second};
    const Expectation e = Expect(from, calls);
    Arm(rig, first);
    Arm(rig, second);
    rig.Scan();
    for (std::size_t i = 0; i < calls.size(); ++i) {
        if (calls[i] == McBlock::kPowerOff) continue;
        const pac::test::PlcOpenOutputs out = OutputsOf(rig, calls[i]);
        if (e.refusals[i] != 0) {
            EXPECT_TRUE(out.error && out.errorId == e.refusals[i])
                << Name(calls[i]) << " refused with 16#" << std::hex << e.refusals[i] << " expected: " << out;
        } else {
            const bool doneAtOnce = calls[i] == McBlock::kReset && out.done;  // nothing to reset
            EXPECT_TRUE(out.busy || doneAtOnce) << Name(calls[i]) << " accepted: " << out;
        }
    }
    EXPECT_EQ(rig.State(1), e.state) << "the state at the end of the edge scan: " << Name(rig.State(1))
                                       << " instead of " << Name(e.state);
    rig.Scan();
    // Every block accepted before the last one is aborted by it (PLCopen Aborting), and so is the A instance.
    for (std::size_t i = 0; i < calls.size(); ++i) {
        if (e.refusals[i] != 0 || calls[i] == McBlock::kReset || calls[i] == McBlock::kPowerOff) continue;
        if (e.hasWinner && calls[i] == e.winner) continue;
        EXPECT_TRUE(OutputsOf(rig, calls[i]).aborted) << Name(calls[i]) << ": " << OutputsOf(rig, calls[i]);
    }
    // The A instance loses the axis: CommandAborted; MC_Stop A was done before and keeps its Done.
    const auto expectReacherEnded = [&] {
        if (from == kStandstill) return;
        const pac::test::PlcOpenOutputs reacher = ReacherOutputs(rig, from);
        EXPECT_TRUE(from == kStopping ? reacher.done : reacher.aborted) << "the A instance: " << reacher;
    };
    if (e.hasWinner) expectReacherEnded();
    if (e.poweredOff) {
        // Power off ends whatever ran once the drive reports it off.
        ASSERT_TRUE(rig.WaitFor([&] {
            for (const McBlock block : calls) {
                if (OutputsOf(rig, block).busy) return false;
            }
            return !ReacherOutputs(rig, from).busy;
        }, 2000, "every block ends"));
        EXPECT_EQ(rig.State(1), kDisabled);
        // The drive reports itself off before MC_Power switches it on again: until then DRIVE ENABLED is the
        // old reading, and the state would show Standstill for the bus's round trip.
        ASSERT_TRUE(rig.WaitFor([&] { return !b.power->STATUS.value; }, 300, "MC_Power.Status FALSE"));
        expectReacherEnded();
        // A job not yet started is aborted, never sent to an axis being switched off; a halt or stop is over
        // once the axis stands.
        for (std::size_t i = 0; i < calls.size(); ++i) {
            if (e.refusals[i] != 0 || calls[i] == McBlock::kReset || calls[i] == McBlock::kPowerOff) continue;
            const pac::test::PlcOpenOutputs out = OutputsOf(rig, calls[i]);
            const bool halts = calls[i] == McBlock::kHalt || IsStop(calls[i]);
            EXPECT_TRUE(halts ? out.done : out.aborted) << Name(calls[i]) << " with MC_Power off: " << out;
        }
    } else if (e.hasWinner) {
        ExpectWinnerEnds(rig, e.winner);  // and then whether the axis is free, whatever happened
    } else {
        ExpectReacherRunsOn(rig, from);
    }
    ExpectNotLocked(rig);
}

TEST_P(McSameScanSim, EveryPairOfBlocksEdgedInOneScanFollowsTheDiagramInBothCallOrders) {
    for (const auto from : {kStandstill, kHoming, kDiscrete, kContinuous, kStopping}) {
        for (std::size_t i = 0; i < std::size(kPairBlocks); ++i) {
            for (std::size_t j = i + 1; j < std::size(kPairBlocks); ++j) {
                // kPairBlocks lists the blocks in McRig's call order: reversed, the later one is called first.
                for (const auto order : {McCallOrder::kAsListed, McCallOrder::kReversed}) {
                    const bool asListed = order == McCallOrder::kAsListed;
                    const McBlock first = asListed ? kPairBlocks[i] : kPairBlocks[j];
                    const McBlock second = asListed ? kPairBlocks[j] : kPairBlocks[i];
                    SCOPED_TRACE(std::string("from ") + Name(from) + ": " + Name(first) + ", then " + Name(second) +
                                 " in the same scan");
                    RunPair(GetParam(), from, first, second, order);
                }
            }
        }
    }
}

// The scan in which the MC_Stop holding Stopping sees its Execute FALSE (its stop done) leaves Stopping: a move
// edged in that scan is accepted when called after MC_Stop, refused with 16#8032 when called before it (the
// axis was still Stopping then); either way the axis is free afterwards.
TEST_P(McSameScanSim, ReleasingAStopFreesTheAxisForTheBlocksCalledAfterIt) {
    for (const auto order : {McCallOrder::kAsListed, McCallOrder::kReversed}) {
        SCOPED_TRACE(order == McCallOrder::kAsListed ? "MC_MoveAbsolute before MC_Stop" : "MC_Stop first");
        McRig rig(GetParam(), 1, {}, order);
        ASSERT_NO_FATAL_FAILURE(rig.PowerUp());
        McBlocks& b = rig.Blocks(1);
        ASSERT_NO_FATAL_FAILURE(StartLongMove(rig));
        Execute(rig, b.stop);
        ASSERT_TRUE(EndsDone(rig, b.stop, 2000, "Stop"));
        rig.Scan(2);
        ASSERT_EQ(rig.State(1), kStopping);
        b.stop->EXECUTE.value = FALSE;
        Arm(rig, McBlock::kMoveAbsolute);
        rig.Scan();
        const pac::test::PlcOpenOutputs out = OutputsOf(rig, McBlock::kMoveAbsolute);
        if (order == McCallOrder::kReversed) {
            EXPECT_TRUE(out.busy) << out;
            EXPECT_EQ(rig.State(1), kDiscrete);
            ASSERT_TRUE(EndsDone(rig, b.moveB, 2000, "MoveAbsolute B"));
        } else {
            EXPECT_TRUE(out.error && out.errorId == kMcStopping) << out;
            EXPECT_EQ(rig.State(1), kStandstill);
        }
        ExpectNotLocked(rig);
    }
}

}  // namespace
}  // namespace test_mc_same_scan_sim
