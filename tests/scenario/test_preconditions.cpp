// FindUnmetPreconditions: START ONLINE (a ctrl request or 0603) without the powered external stop input
// of system parameter 4 (manual 5.2.1.3) is seen before the run, following the steps that change it
// (set_input, 0700 on parameter 4); a step that expects the refusal is left alone. The warning names
// the step and says what the simulated PA-CONTROL will do, and the run, which the warning does not stop,
// shows exactly that refusal.
#include <gtest/gtest.h>

#include <string>

#include "gvl_names.hpp"
#include "preconditions.hpp"
#include "scenario_loader.hpp"
#include "scenario_runner.hpp"

namespace {

using pac::scenario::FindUnmetPreconditions;
using pac::scenario::PreconditionWarning;

pac::scenario::Scenario Load(const std::string& text) {
    static const pac::scenario::GvlNames names;
    return pac::scenario::ScenarioLoader(names).FromText(text);
}

std::vector<PreconditionWarning> Warnings(const std::string& controller, const std::string& steps) {
    return FindUnmetPreconditions(Load(R"({"modules": {"ctrl": true}, "controller": {)" + controller +
                                       R"(}, "steps": [{"wait_ms": 60}, )" + steps + "]}"));
}

const std::string kStartCtrl = R"({"ctrl": "PAC_REQ_START_ONLINE"})";
const std::string kStartCmd = R"({"command": "PAC_CMD_START_ONLINE"})";

TEST(Preconditions, StartOnlineWithoutAStopInputIsSeenOnEitherInterface) {
    for (const std::string& start : {kStartCtrl, kStartCmd}) {
        const auto warnings = Warnings("", start);
        ASSERT_EQ(warnings.size(), 1u) << start;
        EXPECT_EQ(warnings[0].step, 1u);
        EXPECT_NE(warnings[0].message.find("system parameter 4 is 0"), std::string::npos) << warnings[0].message;
        EXPECT_NE(warnings[0].message.find("5.2.1.3"), std::string::npos);
    }
}

TEST(Preconditions, AStopInputWithoutPowerIsSeenAndNamed) {
    const auto unpowered = Warnings(R"("system_parameters": {"4": 7})", kStartCtrl);
    ASSERT_EQ(unpowered.size(), 1u);
    EXPECT_NE(unpowered[0].message.find("external stop input 7 (system parameter 4) has no power"), std::string::npos)
        << unpowered[0].message;
    EXPECT_EQ(Warnings(R"("system_parameters": {"4": 7}, "inputs": {"7": false})", kStartCmd).size(), 1u);
    EXPECT_EQ(Warnings(R"("system_parameters": {"4": 7}, "inputs": {"6": true})", kStartCmd).size(), 1u);
}

TEST(Preconditions, APoweredStopInputIsNoWarning) {
    EXPECT_TRUE(Warnings(R"("system_parameters": {"4": 7}, "inputs": {"7": true})", kStartCtrl).empty());
    EXPECT_TRUE(Warnings(R"("system_parameters": {"4": 7}, "inputs": {"7": true})", kStartCmd).empty());
}

TEST(Preconditions, StepsBeforeTheStartChangeWhatItSees) {
    const std::string defineByCommand = R"({"command": "PAC_CMD_SET_SYSTEM_PARAMETER", "param": 4, "data": 3}, )";
    const std::string power = R"({"fault": "set_input", "input": 3, "value": true}, )";
    const std::string dropPower = R"({"fault": "set_input", "input": 3, "value": false}, )";
    EXPECT_TRUE(Warnings("", defineByCommand + power + kStartCtrl).empty());
    EXPECT_EQ(Warnings("", power + kStartCtrl).size(), 1u);            // powered, but not the stop input yet
    EXPECT_EQ(Warnings("", defineByCommand + kStartCtrl).size(), 1u);  // defined, without power
    const auto later = Warnings(R"("system_parameters": {"4": 3}, "inputs": {"3": true})",
                                kStartCtrl + ", " + dropPower + kStartCmd);
    ASSERT_EQ(later.size(), 1u);
    EXPECT_EQ(later[0].step, 3u);  // the second start, after the input lost power
    // A 0700 the scenario expects to be refused does not define the input.
    const std::string refusedDefinition = R"({"command": "0700", "param": 4, "data": 3, "expect": {"error": true}}, )";
    EXPECT_EQ(Warnings("", refusedDefinition + power + kStartCtrl).size(), 1u);
}

TEST(Preconditions, AStartThatExpectsTheRefusalIsLeftAlone) {
    EXPECT_TRUE(Warnings("", R"({"ctrl": "PAC_REQ_START_ONLINE", "expect": {"error": true}})").empty());
    EXPECT_TRUE(Warnings("", R"({"command": "0603", "expect": {"error_id": 44}})").empty());
    EXPECT_EQ(Warnings("", R"({"command": "0603", "expect": {"done": true}})").size(), 1u);
}

// The warning tells the truth: the run it does not stop refuses the start as it says (0603: error 44).
TEST(Preconditions, TheRunRefusesTheStartTheWarningNamed) {
    const auto scenario = Load(R"({"steps": [{"wait_ms": 60}, {"command": "0603", "expect": {"done": true}}]})");
    ASSERT_EQ(FindUnmetPreconditions(scenario).size(), 1u);
    pac::scenario::RunObserver quiet;
    const auto report = pac::scenario::ScenarioRunner(scenario).Run(quiet);
    ASSERT_EQ(report.steps.size(), 2u);
    ASSERT_TRUE(report.steps[1].outcome.has_value());
    EXPECT_TRUE(report.steps[1].outcome->error);
    EXPECT_EQ(report.steps[1].outcome->errorId, 44);  // manual 6.5: no external stop for ONLINE
    EXPECT_FALSE(report.Passed());
}

}  // namespace
