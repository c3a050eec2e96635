// Interbus-S gives no module consistency (chapter 4, against 2.3.3 for Profibus): the simulated bus can
// deliver a module torn, some bytes of the new image and some of the one before (Link tearPercent, seeded).
// With FB_PAC_CmdInterface.TwoStepWrite the data go out a scan before the SEND flag (4.2.4), so the
// controller never takes a torn command; written in one step it can (issue 10, defect 7).
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <tuple>
#include <vector>

#include "bus_timing.hpp"
#include "controller_readings.hpp"
#include "gvl_constants.hpp"
#include "pac/sim/command_table.hpp"
#include "shared_cmd_plc.hpp"

namespace test_cmd_torn_bus_sim {  // apart from the names of the other sources in its unity batch
namespace {

using pac::test::BusTiming;
using pac::test::SharedCmdPlc;
using pac::test::SharingCase;
namespace code = pac::sim::code;

constexpr int kTearPercent = 50;

using Frame = std::tuple<std::uint16_t, std::uint16_t, std::uint32_t>;

// Two FBs re-trigger writes whose every byte differs from the previous command's, `commands` in all, on
// a to-PAC link that tears; returns the commands the controller recognised that no FB sent.
struct TornRun {
    int commandsSent = 0;
    int tornCommands = 0;
    std::uint64_t tornReads = 0;
};

TornRun WriteThroughATornBus(const SharingCase& c, bool twoStep, int commands) {
    const int fbs = 2;
    SharedCmdPlc plc(c, fbs);
    plc.Plc().Rig().CmdInterface()->TWOSTEPWRITE.value = twoStep ? TRUE : FALSE;
    plc.Boot();
    plc.Plc().Rig().Bus().ToPacLink().SetTearPercent(kTearPercent);
    std::set<Frame> sent;
    std::vector<bool> released(fbs, false);
    TornRun run;
    auto next = [&](int i) {
        ++run.commandsSent;
        const auto n = static_cast<std::uint32_t>(run.commandsSent);
        const auto param = static_cast<std::uint16_t>(0x0101 * (n % 3 + 1));  // N257, N514, N771: both bytes differ
        const std::uint32_t data = 0x11111111u * (n % 15 + 1);
        plc.Set(i, code::kPutIntReg, param, data);
        sent.insert({code::kPutIntReg, param, data});
        plc.Fb(i)->EXECUTE.value = TRUE;
    };
    for (int i = 0; i < fbs; ++i) next(i);
    for (int scan = 0; scan < 200000; ++scan) {
        plc.Scan();
        bool busy = false;
        for (int i = 0; i < fbs; ++i) {
            auto& fb = plc.Fb(i);
            if (released[static_cast<std::size_t>(i)]) {
                released[static_cast<std::size_t>(i)] = false;
                if (run.commandsSent < commands) next(i);
            } else if (fb->DONE.value || fb->ERROR.value) {
                fb->EXECUTE.value = FALSE;
                released[static_cast<std::size_t>(i)] = true;
            }
            busy = busy || fb->BUSY.value || fb->EXECUTE.value;
        }
        if (!busy && run.commandsSent >= commands) break;
    }
    for (const auto& command : plc.CommandsSeen()) {
        if (command.code == code::kGetState && command.parameter == 0 && command.data == 0) continue;
        if (sent.count({command.code, command.parameter, command.data}) == 0) ++run.tornCommands;
    }
    run.tornReads = plc.Plc().Rig().Bus().ToPacLink().TornReads();
    return run;
}

class TornBus : public ::testing::TestWithParam<SharingCase> {};

TEST_P(TornBus, TwoStepWriteNeverSendsATornCommand) {
    const TornRun run = WriteThroughATornBus(GetParam(), true, 24);
    EXPECT_EQ(run.tornCommands, 0) << run.tornReads << " torn reads";
}

INSTANTIATE_TEST_SUITE_P(Readings, TornBus,
                         ::testing::ValuesIn(pac::test::OnEveryReading(pac::test::StandardAndJitteredBusTimings())),
                         pac::test::SharingCaseName);

// The same load written in one step: where the controller reads the module in the PLC cycle it changes in,
// a torn read toggles SEND over data of the image before. The test shows the two-step write is what keeps
// the Interbus data consistent, and that the torn bus really tears.
TEST(TornBusOneStep, OneStepWriteCanSendATornCommand) {
    for (const BusTiming& t : std::vector<BusTiming>{{5, 1, 0}, {10, 3, 1}, {2, 1, 1}, {10, 1, 2, 900, 77}}) {
        for (const auto& reading : pac::test::AllControllerReadings()) {
            SCOPED_TRACE(Describe(t) + "; " + pac::test::Describe(reading));
            const TornRun oneStep = WriteThroughATornBus({t, reading}, false, 40);
            EXPECT_GT(oneStep.tornCommands, 0) << oneStep.tornReads << " torn reads";
            const TornRun twoStep = WriteThroughATornBus({t, reading}, true, 40);
            EXPECT_EQ(twoStep.tornCommands, 0) << twoStep.tornReads << " torn reads";
            EXPECT_GT(twoStep.tornReads, 0u) << "the bus tore modules under the two-step write too";
        }
    }
}

}  // namespace
}  // namespace test_cmd_torn_bus_sim
