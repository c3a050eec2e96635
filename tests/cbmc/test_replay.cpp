// Replays the counterexamples the model checker found (tests/cbmc/counterexamples/*.inputs, written by
// paccbmc) on the harness compiled natively against the same translated ST: an open defect's counterexample
// must still break its property (its status line says open), a fixed one's must hold (status fixed). With
// PAC_CBMC_REPLAY=<file> a counterexample just written into the build tree is replayed as well.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "replay_inputs.h"

extern "C" {
int pac_cbmc_cmd_one_main(void);
int pac_cbmc_cmd_one_restarts_main(void);
int pac_cbmc_cmd_two_main(void);
int pac_cbmc_cmd_two_no_plc_restart_main(void);
int pac_cbmc_cmd_one_short_timeout_main(void);
int pac_cbmc_cmd_one_lag2_main(void);
int pac_cbmc_cmd_one_short_timeout_lag2_main(void);
int pac_cbmc_ctrl_main(void);
int pac_cbmc_axis_main(void);
int pac_cbmc_axis_no_plc_restart_main(void);
int pac_cbmc_automatic_main(void);
int pac_cbmc_mc_main(void);
int pac_cbmc_mc_no_plc_restart_main(void);
int pac_cbmc_mc_slow_bus_main(void);
int pac_cbmc_rs232_main(void);
int pac_cbmc_rs232_no_gaps_main(void);
int pac_cbmc_rs232_restarts_main(void);
int pac_cbmc_rs232_deep_main(void);

// What the harness's asserts and assumes said during one replay.
static std::set<std::string> failedProperties;
static int brokenAssumptions = 0;
void pac_replay_assert(int holds, const char* property) {
    if (!holds) failedProperties.insert(property);
}
void pac_replay_assume(int holds) {
    if (!holds) ++brokenAssumptions;
}
}

namespace {

struct Counterexample {
    std::string file, harness, property, status;
    std::vector<unsigned long long> inputs;
};

Counterexample Read(const std::filesystem::path& path) {
    Counterexample c;
    c.file = path.filename().string();
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("# harness: ", 0) == 0) c.harness = line.substr(11);
        else if (line.rfind("# property: ", 0) == 0) c.property = line.substr(12);
        else if (line.rfind("# status: ", 0) == 0) c.status = line.substr(10);
        else if (!line.empty() && line[0] != '#') {
            std::istringstream values(line);
            unsigned long long v = 0;
            while (values >> v) c.inputs.push_back(v);
        }
    }
    return c;
}

void Replay(const Counterexample& c) {
    static const std::map<std::string, int (*)(void)> harnesses = {
        {"CmdInterface.OneCaller", pac_cbmc_cmd_one_main},
        {"CmdInterface.OneCallerRestarts", pac_cbmc_cmd_one_restarts_main},
        {"CmdInterface.TwoCallers", pac_cbmc_cmd_two_main},
        {"CmdInterface.TwoCallers.NoPlcRestart", pac_cbmc_cmd_two_no_plc_restart_main},
        {"CmdInterface.OneCallerShortTimeout", pac_cbmc_cmd_one_short_timeout_main},
        {"CmdInterface.OneCaller.Lag2", pac_cbmc_cmd_one_lag2_main},
        {"CmdInterface.OneCallerShortTimeout.Lag2", pac_cbmc_cmd_one_short_timeout_lag2_main},
        {"Ctrl", pac_cbmc_ctrl_main},
        {"Axis", pac_cbmc_axis_main},
        {"Axis.NoPlcRestart", pac_cbmc_axis_no_plc_restart_main},
        {"AutomaticModule", pac_cbmc_automatic_main},
        {"Mc", pac_cbmc_mc_main},
        {"Mc.NoPlcRestart", pac_cbmc_mc_no_plc_restart_main},
        {"McSlowBus", pac_cbmc_mc_slow_bus_main},
        {"Rs232Cmd", pac_cbmc_rs232_main},
        {"Rs232Cmd.NoGaps", pac_cbmc_rs232_no_gaps_main},
        {"Rs232Cmd.Restarts", pac_cbmc_rs232_restarts_main},
        {"Rs232Cmd.Deep", pac_cbmc_rs232_deep_main},
    };
    SCOPED_TRACE(c.file + " (" + c.harness + ", " + c.property + ", " + c.status + ")");
    const auto harness = harnesses.find(c.harness);
    ASSERT_NE(harness, harnesses.end()) << "no such harness";
    ASSERT_FALSE(c.property.empty());
    failedProperties.clear();
    brokenAssumptions = 0;
    const int used = pac_replay_run(harness->second, c.inputs.data(), static_cast<int>(c.inputs.size()));
    EXPECT_EQ(used, static_cast<int>(c.inputs.size())) << "the harness asked for fewer inputs than recorded";
    const bool failed = failedProperties.count(c.property) != 0;
    if (c.status == "open") {
        EXPECT_EQ(brokenAssumptions, 0) << "the replay left the counterexample's path";
        EXPECT_TRUE(failed) << "the open defect's counterexample no longer breaks its property: fixed? then "
                               "say '# status: fixed' and move the defect in docs/verification.md";
    } else {
        EXPECT_EQ(c.status, "fixed");
        EXPECT_FALSE(failed) << "the counterexample of a fixed defect breaks its property again";
    }
}

TEST(CbmcReplay, RecordedCounterexamples) {
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(PAC_CBMC_COUNTEREXAMPLES)) {
        if (entry.path().extension() != ".inputs") continue;
        Replay(Read(entry.path()));
        ++count;
    }
    EXPECT_GT(count, 0);
}

TEST(CbmcReplay, FromEnvironment) {
    const char* file = std::getenv("PAC_CBMC_REPLAY");
    if (file == nullptr) GTEST_SKIP() << "PAC_CBMC_REPLAY=<file.inputs> replays one counterexample";
    Replay(Read(file));
}

}  // namespace
