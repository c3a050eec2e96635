// What the MC_ block tests share (test_mc_blocks_sim.cpp, test_mc_state_diagram_sim.cpp): the library codes
// and states by name, the bus timings, and the steps a PLC program takes with a block.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bus_timing.hpp"
#include "gvl_constants.hpp"
#include "mc_bench.hpp"
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
::testing::AssertionResult EndsDone(McBench& bench, pac::FbInstance<Fb>& fb, int ms, const std::string& what) {
    ::testing::AssertionResult final = bench.WaitFor([&] { return Final(fb); }, ms, what + " final");
    if (!final) return final;
    if (fb->DONE.value) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << what << " ended without Done, ErrorID " << fb->ERRORID.value;
}

// Execute rises; the next scan sees it.
template <class Fb>
void Execute(McBench& bench, pac::FbInstance<Fb>& fb) {
    fb->EXECUTE.value = TRUE;
    bench.Scan();
}

// Execute back to FALSE for a scan, as a program does after a final output.
template <class Fb>
void Release(McBench& bench, pac::FbInstance<Fb>& fb) {
    fb->EXECUTE.value = FALSE;
    bench.Scan();
}

inline void SetMove(pac::FbInstance<MC_MOVEABSOLUTE>& fb, float position, float velocity = 500.0f) {
    fb->POSITION.value = position;
    fb->VELOCITY.value = velocity;
}

// Axis 1 moving towards 5000 at 1000 AE/s under MC_MoveAbsolute A, taken over by the controller.
inline void StartLongMove(McBench& bench) {
    auto& a = bench.Blocks(1).moveA;
    SetMove(a, 5000.0f, 1000.0f);
    Execute(bench, a);
    ASSERT_TRUE(a->BUSY.value && a->ACTIVE.value);
    ASSERT_TRUE(bench.WaitFor([&] { return bench.Ref(1).STATUS.ACTIVE != 0; }, 200, "ACTIVE"));
    EXPECT_EQ(bench.State(1), kDiscrete);
}

}  // namespace pac::test::mc
