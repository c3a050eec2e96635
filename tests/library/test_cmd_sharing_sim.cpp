// Several command FBs on one CMD interface against the simulated PA-CONTROL, scan by scan, on the bus
// timings of the library's tests and on every controller reading of the handshake (controller_readings.hpp):
// a command owns the interface until its end of processing, only the stops of what it runs overtake it,
// queued FBs are served in the order of their edges, and a freshly started FB leaves a command in flight
// alone (issue 10, defects 1 and 2; docs/fb/FB_PAC_Cmd.md).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bus_timing.hpp"
#include "controller_readings.hpp"
#include "gvl_constants.hpp"
#include "pac/sim/command_table.hpp"
#include "pac/iec_time.hpp"
#include "real_bits.hpp"
#include "shared_cmd_plc.hpp"

namespace test_cmd_sharing_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using pac::test::FinalOutcome;
using pac::test::SharedCmdPlc;
using pac::test::SharingCase;
namespace code = pac::sim::code;

const pac::test::GvlConstants kGvl;
const std::uint32_t kLibNoErrorNumber = kGvl["PAC_LIB_ERR_NO_ERROR_NUMBER"];
const std::uint32_t kLibSuperseded = kGvl["PAC_LIB_ERR_SUPERSEDED"];

std::uint32_t Bits(float value) { return pac::test::BitsOf(value); }

bool Final(pac::FbInstance<FB_PAC_CMD>& fb) { return fb->DONE.value || fb->ERROR.value; }

// Scans until every FB of `fbs` shows a final output; false after maxScans.
bool ScanUntilFinal(SharedCmdPlc& plc, const std::vector<int>& fbs, int maxScans,
                    const std::function<void()>& eachScan = {}) {
    for (int i = 0; i < maxScans; ++i) {
        bool all = true;
        for (int fb : fbs) all = all && Final(plc.Fb(fb));
        if (all) return true;
        plc.Scan();
        if (eachScan) eachScan();
    }
    return false;
}

class CmdSharing : public ::testing::TestWithParam<SharingCase> {};

// Defect 1: a move by 0A87 on one FB, a read of N5 on a second FB 20 scans later. The read waits, Busy,
// until the move's END OF PROCESSING, and only then reaches the controller; the move's FB follows its
// own command to Done.
TEST_P(CmdSharing, MoveOwnsTheInterfaceUntilItsEndOfProcessing) {
    SharedCmdPlc plc(GetParam(), 2);
    plc.Boot();
    ASSERT_TRUE(plc.GoOnline());
    plc.Controller().Io().intRegisters.SetInt(5, 4711);
    const int sentBefore = static_cast<int>(plc.CommandsSeen().size());

    plc.Set(0, code::kPosAxisAbsolute, 1, Bits(1000.0F));
    plc.Fb(0)->EXECUTE.value = TRUE;
    plc.Scan(20);
    ASSERT_TRUE(plc.Fb(0)->BUSY.value) << "the move runs for about a second";
    plc.Set(1, code::kGetIntReg, 5);
    plc.Fb(1)->TIMEOUT.value = pac::ToIecTime(5s);  // longer than the move
    plc.Fb(1)->EXECUTE.value = TRUE;
    bool moveDoneWhenReadSeen = false;
    bool readSeen = false;
    ASSERT_TRUE(ScanUntilFinal(plc, {0, 1}, 100000, [&] {
        if (!readSeen && plc.Seen(code::kGetIntReg, 5) > 0) {
            readSeen = true;
            moveDoneWhenReadSeen = plc.Fb(0)->DONE.value != 0;
        }
    }));
    EXPECT_TRUE(plc.Fb(0)->DONE.value) << "the move's FB followed its own command to its end: ErrorID "
                                        << plc.Fb(0)->ERRORID.value;
    EXPECT_EQ(plc.Fb(0)->ACKDATA.value, Bits(1000.0F)) << "the end position";
    ASSERT_TRUE(plc.Fb(1)->DONE.value) << "ErrorID " << plc.Fb(1)->ERRORID.value;
    EXPECT_EQ(plc.Fb(1)->ACKDATA.value, 4711u);
    EXPECT_TRUE(moveDoneWhenReadSeen) << "the read reached the controller while the move was processing";
    const auto seen = plc.CommandsSeen();
    ASSERT_EQ(seen.size(), static_cast<std::size_t>(sentBefore) + 2) << "the move and the read, nothing else";
    EXPECT_EQ(seen[seen.size() - 2].code, code::kPosAxisAbsolute);
    EXPECT_EQ(seen.back().code, code::kGetIntReg);
}

// Defect 1, the stops: 0A93 of the moving axis overtakes the queue and the move; a read queued before it
// waits for the stop's end, and a stop of another axis overtakes nothing that is processing.
TEST_P(CmdSharing, OnlyAStopOfTheMovingAxisOvertakesTheMove) {
    SharedCmdPlc plc(GetParam(), 4);
    plc.Boot();
    ASSERT_TRUE(plc.GoOnline());
    plc.Controller().Io().intRegisters.SetInt(5, 55);
    const auto& motion = plc.Controller().Axes().Motion(1);

    plc.Set(0, code::kPosAxisAbsolute, 1, Bits(1000.0F));
    plc.Fb(0)->EXECUTE.value = TRUE;
    plc.Scan(20);
    plc.Set(1, code::kGetIntReg, 5);
    plc.Fb(1)->TIMEOUT.value = pac::ToIecTime(5s);
    plc.Fb(1)->EXECUTE.value = TRUE;
    plc.Set(2, code::kStopAxis, 2);  // axis 2 stands: its stop must not overtake the move of axis 1
    plc.Fb(2)->TIMEOUT.value = pac::ToIecTime(5s);
    plc.Fb(2)->EXECUTE.value = TRUE;
    plc.Scan(5);
    plc.Set(3, code::kStopAxis, 1);
    plc.Fb(3)->EXECUTE.value = TRUE;
    bool movingWhenStopSeen = false;
    bool stopSeen = false;
    bool otherStopBeforeStopEnded = false;
    bool readBeforeStopEnded = false;
    ASSERT_TRUE(ScanUntilFinal(plc, {0, 1, 2, 3}, 100000, [&] {
        if (!stopSeen && plc.Seen(code::kStopAxis, 1) > 0) {
            stopSeen = true;
            movingWhenStopSeen = motion.Moving();
        }
        if (plc.Seen(code::kStopAxis, 2) > 0 && !plc.Fb(3)->DONE.value) otherStopBeforeStopEnded = true;
        if (plc.Seen(code::kGetIntReg, 5) > 0 && !plc.Fb(3)->DONE.value) readBeforeStopEnded = true;
    }));
    EXPECT_TRUE(movingWhenStopSeen) << "the stop reached the controller while the axis moved";
    EXPECT_EQ(plc.Fb(0)->ERRORID.value, kLibSuperseded) << "the move was stopped: 16#8007, CommandAborted";
    EXPECT_TRUE(plc.Fb(3)->DONE.value) << "ErrorID " << plc.Fb(3)->ERRORID.value;
    EXPECT_LT(plc.Fb(3)->ACKDATA.value, Bits(1000.0F)) << "stopped short of the target";
    EXPECT_FALSE(otherStopBeforeStopEnded) << "a stop of axis 2 went out while axis 1 was moving or braking";
    EXPECT_TRUE(plc.Fb(2)->DONE.value) << "ErrorID " << plc.Fb(2)->ERRORID.value;
    EXPECT_FALSE(readBeforeStopEnded) << "the read went out while the stop was processing";
    EXPECT_TRUE(plc.Fb(1)->DONE.value) << "ErrorID " << plc.Fb(1)->ERRORID.value;
    EXPECT_EQ(plc.Fb(1)->ACKDATA.value, 55u);
    EXPECT_EQ(plc.Seen(code::kStopAxis, 1), 1);
    EXPECT_EQ(plc.Seen(code::kGetIntReg, 5), 1);
}

// Defect 2: FBs that re-trigger as fast as a PLC program can (Execute falls for one scan after each final
// output) are served in the order of their edges: round robin, each at least once every N commands, every
// value written once and in order.
TEST_P(CmdSharing, ReTriggeringFbsAreServedInTheOrderOfTheirEdges) {
    for (int fbs : {4, 8}) {
        SCOPED_TRACE(std::to_string(fbs) + " FBs");
        SharedCmdPlc plc(GetParam(), fbs);
        plc.Boot();
        const std::size_t before = plc.CommandsSeen().size();
        std::vector<std::uint32_t> written(static_cast<std::size_t>(fbs), 0);
        std::vector<bool> released(static_cast<std::size_t>(fbs), false);
        const int rounds = 4;
        auto retrigger = [&] {
            for (int i = 0; i < fbs; ++i) {
                auto& fb = plc.Fb(i);
                auto& count = written[static_cast<std::size_t>(i)];
                if (released[static_cast<std::size_t>(i)]) {
                    released[static_cast<std::size_t>(i)] = false;
                    if (count < static_cast<std::uint32_t>(rounds)) {
                        plc.Set(i, code::kPutIntReg, static_cast<std::uint16_t>(100 + i), count + 1);
                        fb->EXECUTE.value = TRUE;
                    }
                } else if (Final(fb)) {
                    ASSERT_TRUE(fb->DONE.value) << "FB " << i << ": ErrorID " << fb->ERRORID.value;
                    ++count;
                    fb->EXECUTE.value = FALSE;
                    released[static_cast<std::size_t>(i)] = true;
                }
            }
        };
        for (int i = 0; i < fbs; ++i) {
            plc.Set(i, code::kPutIntReg, static_cast<std::uint16_t>(100 + i), 1);
            plc.Fb(i)->EXECUTE.value = TRUE;
        }
        for (int scan = 0; scan < 100000; ++scan) {
            plc.Scan();
            retrigger();
            bool all = true;
            for (auto count : written) all = all && count == static_cast<std::uint32_t>(rounds);
            if (all) break;
        }
        const auto seen = plc.CommandsSeen();
        ASSERT_EQ(seen.size() - before, static_cast<std::size_t>(fbs * rounds)) << "every command once";
        for (std::size_t k = 0; k < seen.size() - before; ++k) {
            const auto& c = seen[before + k];
            const int fb = static_cast<int>(k % static_cast<std::size_t>(fbs));
            EXPECT_EQ(c.parameter, 100 + fb) << "command " << k << ": round robin in the order of the edges";
            EXPECT_EQ(c.data, k / static_cast<std::size_t>(fbs) + 1) << "command " << k << ": the values in order";
        }
    }
}

// Defect 3: a freshly started or re-initialised FB (an online change, a restart of that FB) never parks
// or resynchronises the module while another FB's command is in flight; the fresh FB's own command waits.
TEST_P(CmdSharing, FreshFbLeavesTheCommandInFlightAlone) {
    SharedCmdPlc plc(GetParam(), 1, 0ns, 2);
    plc.Boot();
    ASSERT_TRUE(plc.GoOnline());
    plc.Controller().Io().intRegisters.SetInt(5, 9);
    plc.Set(0, code::kPosAxisAbsolute, 1, Bits(800.0F));
    plc.Fb(0)->EXECUTE.value = TRUE;
    plc.Scan(1);
    const pac::sim::Image8 move = plc.Module();
    ASSERT_GT(plc.Plc().Rig().ScanUntil([&] { return plc.Fb(0)->ACKNOWLEDGED.value != 0; }, 10000), 0);
    plc.Scan(3);
    ASSERT_TRUE(plc.Fb(0)->BUSY.value) << "the move is processing";
    plc.Fb(1) = PAC_FB(FB_PAC_CMD);  // re-initialised, idle
    plc.Fb(2) = PAC_FB(FB_PAC_CMD);  // re-initialised, and its first call has an Execute edge
    plc.Set(2, code::kGetIntReg, 5);
    plc.Fb(2)->TIMEOUT.value = pac::ToIecTime(5s);
    plc.Fb(2)->EXECUTE.value = TRUE;
    int scans = 0;
    while (scans < 100000) {
        plc.Scan();
        ++scans;
        if (Final(plc.Fb(0))) break;  // the move's FB parks the module in the scan of its end
        ASSERT_EQ(pac::sim::ToHex(plc.Module()), pac::sim::ToHex(move)) << "scan " << scans << " of the move";
    }
    EXPECT_TRUE(plc.Fb(0)->DONE.value) << "ErrorID " << plc.Fb(0)->ERRORID.value;
    ASSERT_TRUE(ScanUntilFinal(plc, {2}, 100000));
    EXPECT_TRUE(plc.Fb(2)->DONE.value) << "ErrorID " << plc.Fb(2)->ERRORID.value;
    EXPECT_EQ(plc.Fb(2)->ACKDATA.value, 9u);
    EXPECT_EQ(plc.Seen(code::kPosAxisAbsolute, 1), 1);
}

// Defect 5: COMMAND ERROR with error number 0 is an Error with ErrorID 16#800F, never ErrorID 0; the
// interface works on.
TEST_P(CmdSharing, CommandErrorWithoutNumberIsLibraryError800F) {
    SharedCmdPlc plc(GetParam(), 1);
    plc.Boot();
    plc.Controller().InjectCommandError(0);
    plc.Set(0, code::kGetIntReg, 1);
    const FinalOutcome refused = plc.Run(0);
    ASSERT_TRUE(refused.Error()) << refused;
    EXPECT_EQ(refused.ErrorId(), kLibNoErrorNumber);
    plc.Controller().Io().intRegisters.SetInt(1, 3);
    const FinalOutcome read = plc.Run(0);
    EXPECT_TRUE(read.Done()) << read;
    EXPECT_EQ(plc.Fb(0)->ACKDATA.value, 3u);
    EXPECT_EQ(plc.Controller().Counters().recognized - plc.Controller().Counters().Count(0x190B), 2u);
}

INSTANTIATE_TEST_SUITE_P(Readings, CmdSharing,
                         ::testing::ValuesIn(pac::test::OnEveryReading(pac::test::StandardAndJitteredBusTimings())),
                         pac::test::SharingCaseName);

}  // namespace
}  // namespace test_cmd_sharing_sim
