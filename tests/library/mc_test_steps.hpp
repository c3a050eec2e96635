// What the MC_ block tests share (test_mc_blocks_sim.cpp, test_mc_state_diagram_sim.cpp): the library codes
// and states by name, the bus timings, and the steps a PLC program takes with a block.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bus_timing.hpp"
#include "gvl_constants.hpp"
#include "mc_rig.hpp"
#include "pac/sim/servo_axis.hpp"

namespace pac::test::mc {

inline const pac::test::GvlConstants kGvl;
inline const std::uint32_t kNotReady = kGvl["PAC_LIB_ERR_NOT_READY"];
inline const std::uint32_t kAxisError = kGvl["PAC_LIB_ERR_AXIS_ERROR"];
inline const std::uint32_t kInvalidVelocity = kGvl["PAC_LIB_ERR_INVALID_VELOCITY"];
inline const std::uint32_t kInvalidAcceleration = kGvl["PAC_LIB_ERR_INVALID_ACCELERATION"];
inline const std::uint32_t kInvalidPosition = kGvl["PAC_LIB_ERR_INVALID_POSITION"];
inline const std::uint32_t kMcDisabled = kGvl["PAC_LIB_ERR_MC_DISABLED"];
inline const std::uint32_t kMcErrorStop = kGvl["PAC_LIB_ERR_MC_ERROR_STOP"];
inline const std::uint32_t kMcStopping = kGvl["PAC_LIB_ERR_MC_STOPPING"];
inline const std::uint32_t kMcState = kGvl["PAC_LIB_ERR_MC_STATE"];
inline const std::uint32_t kMcBufferMode = kGvl["PAC_LIB_ERR_MC_BUFFER_MODE"];
inline const std::uint32_t kMcJerk = kGvl["PAC_LIB_ERR_MC_JERK"];
inline const std::uint32_t kMcDeceleration = kGvl["PAC_LIB_ERR_MC_DECELERATION"];
inline const std::uint32_t kMcDirection = kGvl["PAC_LIB_ERR_MC_DIRECTION"];
inline const std::uint32_t kMcHomePosition = kGvl["PAC_LIB_ERR_MC_HOME_POSITION"];
inline const std::uint32_t kMcRangeEnd = kGvl["PAC_LIB_ERR_MC_RANGE_END"];
inline const std::uint32_t kStopTimeout = kGvl["PAC_LIB_ERR_STOP_TIMEOUT"];
inline const std::uint32_t kNotOnline = kGvl["PAC_LIB_ERR_NOT_ONLINE"];
inline constexpr std::uint16_t kFollowingError = pac::sim::axis_error::kFollowingError;  // the simulator's number

inline constexpr auto kDisabled = E_PAC_MCSTATE__PAC_MC_DISABLED;
inline constexpr auto kStandstill = E_PAC_MCSTATE__PAC_MC_STANDSTILL;
inline constexpr auto kHoming = E_PAC_MCSTATE__PAC_MC_HOMING;
inline constexpr auto kDiscrete = E_PAC_MCSTATE__PAC_MC_DISCRETE_MOTION;
inline constexpr auto kContinuous = E_PAC_MCSTATE__PAC_MC_CONTINUOUS_MOTION;
inline constexpr auto kStopping = E_PAC_MCSTATE__PAC_MC_STOPPING;
inline constexpr auto kErrorStop = E_PAC_MCSTATE__PAC_MC_ERROR_STOP;

// A few timings of the standard grid, the slowest PLC against the fastest controller and back, and a jittered
// bus: the blocks add a scan between a request and FB_PAC_Axis, whatever the bus does.
inline std::vector<BusTiming> McTimings() {
    return {{1, 10, 0}, {2, 3, 1}, {5, 1, 3}, {10, 10, 2}, {1, 3, 1, 2500, 101}};
}


template <class Fb>
bool Final(const pac::FbInstance<Fb>& fb) {
    return pac::test::IsFinal(fb);
}

// MC_MoveVelocity never ends with Done.
inline bool Final(const pac::FbInstance<MC_MOVEVELOCITY>& fb) { return fb->ERROR.value || fb->COMMANDABORTED.value; }

// Scans until `fb` is final, at most `ms` of simulated time, and succeeds only if it ended with Done: the
// failure names the ErrorID it ended with instead.
template <class Fb>
::testing::AssertionResult EndsDone(McRig& rig, pac::FbInstance<Fb>& fb, int ms, const std::string& what) {
    ::testing::AssertionResult final = rig.WaitFor([&] { return Final(fb); }, ms, what + " final");
    if (!final) return final;
    if (fb->DONE.value) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << what << " ended without Done, ErrorID " << fb->ERRORID.value;
}

// Execute rises; the next scan sees it.
template <class Fb>
void Execute(McRig& rig, pac::FbInstance<Fb>& fb) {
    fb->EXECUTE.value = TRUE;
    rig.Scan();
}

// Execute back to FALSE for a scan, as a program does after a final output.
template <class Fb>
void Release(McRig& rig, pac::FbInstance<Fb>& fb) {
    fb->EXECUTE.value = FALSE;
    rig.Scan();
}

inline void SetMove(pac::FbInstance<MC_MOVEABSOLUTE>& fb, float position, float velocity = 500.0f) {
    fb->POSITION.value = position;
    fb->VELOCITY.value = velocity;
}

inline const char* Name(E_PAC_MCSTATE state) {
    switch (state) {
        case kDisabled: return "Disabled";
        case kStandstill: return "Standstill";
        case kHoming: return "Homing";
        case kDiscrete: return "DiscreteMotion";
        case kContinuous: return "ContinuousMotion";
        case kStopping: return "Stopping";
        case kErrorStop: return "ErrorStop";
    }
    return "?";
}

// The blocks of axis 1 a test edges by name, in the order McRig calls them (McCallOrder::kAsListed): moveB is
// the MC_MoveAbsolute edged (moveA and the other A instances bring the axis into a state), MC_Power's edge is
// Enable falling.
enum class McBlock { kPowerOff, kHome, kMoveAbsolute, kMoveRelative, kMoveVelocity, kHalt, kStop, kStop2, kReset };

inline const char* Name(McBlock block) {
    switch (block) {
        case McBlock::kPowerOff: return "MC_Power off";
        case McBlock::kHome: return "MC_Home";
        case McBlock::kMoveAbsolute: return "MC_MoveAbsolute";
        case McBlock::kMoveRelative: return "MC_MoveRelative";
        case McBlock::kMoveVelocity: return "MC_MoveVelocity";
        case McBlock::kHalt: return "MC_Halt";
        case McBlock::kStop: return "MC_Stop";
        case McBlock::kStop2: return "MC_Stop 2";
        case McBlock::kReset: return "MC_Reset";
    }
    return "?";
}

inline bool IsStop(McBlock block) { return block == McBlock::kStop || block == McBlock::kStop2; }

// docs/fb/MC_blocks.md, "State diagram": 0 = accepted (Busy, or Done at once), else the ErrorID of the refusal.
inline std::uint32_t Refusal(E_PAC_MCSTATE state, McBlock block) {
    if (block == McBlock::kReset || block == McBlock::kPowerOff) return 0;
    if (state == kErrorStop) return kMcErrorStop;
    if (state == kDisabled) return kMcDisabled;
    if (IsStop(block)) return 0;
    if (state == kStopping) return kMcStopping;
    if (state == kHoming) return kMcState;
    if (block == McBlock::kHome && state != kStandstill) return kMcState;
    return 0;
}

// The state an accepted block puts the axis in, in the call that issues it (PLCopen: at once).
inline E_PAC_MCSTATE Entered(E_PAC_MCSTATE state, McBlock block) {
    switch (block) {
        case McBlock::kPowerOff: return state == kErrorStop ? kErrorStop : kDisabled;
        case McBlock::kHome: return kHoming;
        case McBlock::kMoveAbsolute:
        case McBlock::kMoveRelative:
        case McBlock::kHalt: return kDiscrete;
        case McBlock::kMoveVelocity: return kContinuous;
        case McBlock::kStop:
        case McBlock::kStop2: return kStopping;
        case McBlock::kReset: return state;
    }
    return state;
}

// The block's inputs for its edge, without a scan: MC_MoveAbsolute B to 10, MC_MoveRelative by 10 (both at
// 500 AE/s), MC_MoveVelocity at 100 AE/s to the max. traverse range, MC_Power's Enable FALSE, else Execute.
inline void Arm(McRig& rig, McBlock block) {
    McBlocks& b = rig.Blocks(1);
    switch (block) {
        case McBlock::kPowerOff: b.power->ENABLE.value = FALSE; return;
        case McBlock::kHome: b.home->EXECUTE.value = TRUE; return;
        case McBlock::kMoveAbsolute:
            SetMove(b.moveB, 10.0f);
            b.moveB->EXECUTE.value = TRUE;
            return;
        case McBlock::kMoveRelative:
            b.relative->POSITION.value = 10.0f;
            b.relative->VELOCITY.value = 500.0f;
            b.relative->EXECUTE.value = TRUE;
            return;
        case McBlock::kMoveVelocity:
            b.velocity->VELOCITY.value = 100.0f;
            b.velocity->DIRECTION.value = E_PAC_MCDIRECTION__PAC_MC_POSITIVE;
            b.velocity->EXECUTE.value = TRUE;
            return;
        case McBlock::kHalt: b.halt->EXECUTE.value = TRUE; return;
        case McBlock::kStop: b.stop->EXECUTE.value = TRUE; return;
        case McBlock::kStop2: b.stop2->EXECUTE.value = TRUE; return;
        case McBlock::kReset: b.reset->EXECUTE.value = TRUE; return;
    }
}

// Execute (MC_Power: Enable) back to where a program leaves it between commands, without a scan.
inline void Disarm(McRig& rig, McBlock block) {
    McBlocks& b = rig.Blocks(1);
    switch (block) {
        case McBlock::kPowerOff: b.power->ENABLE.value = TRUE; return;
        case McBlock::kHome: b.home->EXECUTE.value = FALSE; return;
        case McBlock::kMoveAbsolute: b.moveB->EXECUTE.value = FALSE; return;
        case McBlock::kMoveRelative: b.relative->EXECUTE.value = FALSE; return;
        case McBlock::kMoveVelocity: b.velocity->EXECUTE.value = FALSE; return;
        case McBlock::kHalt: b.halt->EXECUTE.value = FALSE; return;
        case McBlock::kStop: b.stop->EXECUTE.value = FALSE; return;
        case McBlock::kStop2: b.stop2->EXECUTE.value = FALSE; return;
        case McBlock::kReset: b.reset->EXECUTE.value = FALSE; return;
    }
}

// The block's PLCopen outputs; MC_MoveVelocity's Done is FALSE (it has InVelocity), MC_Power shows none.
inline pac::test::PlcOpenOutputs OutputsOf(McRig& rig, McBlock block) {
    McBlocks& b = rig.Blocks(1);
    switch (block) {
        case McBlock::kPowerOff: return {};
        case McBlock::kHome: return pac::test::OutputsOf(b.home);
        case McBlock::kMoveAbsolute: return pac::test::OutputsOf(b.moveB);
        case McBlock::kMoveRelative: return pac::test::OutputsOf(b.relative);
        case McBlock::kMoveVelocity: return pac::test::VelocityOutputsOf(b.velocity);
        case McBlock::kHalt: return pac::test::OutputsOf(b.halt);
        case McBlock::kStop: return pac::test::OutputsOf(b.stop);
        case McBlock::kStop2: return pac::test::OutputsOf(b.stop2);
        case McBlock::kReset: return pac::test::OutputsOf(b.reset);
    }
    return {};
}

// Axis 1 moving towards 5000 at 1000 AE/s under MC_MoveAbsolute A, taken over by the controller.
inline void StartLongMove(McRig& rig) {
    auto& a = rig.Blocks(1).moveA;
    SetMove(a, 5000.0f, 1000.0f);
    Execute(rig, a);
    ASSERT_TRUE(a->BUSY.value && a->ACTIVE.value);
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Ref(1).STATUS.ACTIVE != 0; }, 200, "ACTIVE"));
    EXPECT_EQ(rig.State(1), kDiscrete);
}

}  // namespace pac::test::mc
