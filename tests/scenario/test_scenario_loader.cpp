// ScenarioLoader: what a scenario file may say, and the reason it gives, with the JSONPath, for
// everything it refuses: invalid JSON, duplicate / unknown / missing keys, wrong types, values out
// of range, unknown command, error and status names. It never crashes on any input.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "gvl_names.hpp"
#include "scenario_loader.hpp"

namespace {

using pac::scenario::CommandStep;
using pac::scenario::FaultKind;
using pac::scenario::FaultStep;
using pac::scenario::LinkSide;
using pac::scenario::Scenario;
using pac::scenario::ScenarioError;
using pac::scenario::ScenarioLoader;
using pac::scenario::WaitStep;

const pac::scenario::GvlNames& Names() {
    static const pac::scenario::GvlNames names;
    return names;
}

Scenario Load(const std::string& text) { return ScenarioLoader(Names()).FromText(text); }

// The refusal's full message ("$.steps[0].param: out of range: ..."), or "accepted".
std::string Refusal(const std::string& text) {
    try {
        Load(text);
    } catch (const ScenarioError& e) {
        return e.what();
    }
    return "accepted";
}

// A scenario whose only step is `step`.
std::string WithStep(const std::string& step) { return R"({"steps": [)" + step + "]}"; }

std::string ReadFile(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(ScenarioLoader, ReadsEveryField) {
    const Scenario s = Load(R"({
      "name": "all", "description": "every field",
      "timing": {"plc_cycle_ms": 2, "pac_cycle_ms": 7, "latency_cycles": 3, "jitter_ms": 4, "seed": 99, "boot_ms": 0},
      "controller": {"operating_status": "PAC_STATUS_ONLINE", "n_registers": {"3": -7, "1024": 2147483647},
                     "r_registers": {"1": 640.0}, "inputs": {"5": true, "6": false}},
      "steps": [
        {"command": "PAC_CMD_PUT_FLOAT_REG", "param": 2, "data": {"real": 10.0}, "timeout_ms": 200,
         "end_timeout_ms": 300, "note": "n", "expect": {"done": true, "ack_data": {"real": 10.0}}},
        {"command": "1906", "param": 65535, "data": 4294967295,
         "expect": {"error": true, "error_id": "PAC_ERR_N_REGISTER"}},
        {"command": "16#0906", "data": -2147483648, "expect": {"error_id": "16#8001"}},
        {"command": "7777", "expect": {"error_id": 19, "ack_data": 0}},
        {"fault": "power_cycle", "note": "off and on"},
        {"fault": "freeze_link", "link": "from_pac"},
        {"fault": "zero_link", "link": "to_pac"},
        {"fault": "thaw_link"},
        {"wait_ms": 15}
      ]})");
    EXPECT_EQ(s.name, "all");
    EXPECT_EQ(s.description, "every field");
    EXPECT_EQ(s.timing.plcCycleMs, 2);
    EXPECT_EQ(s.timing.pacCycleMs, 7);
    EXPECT_EQ(s.timing.latencyCycles, 3);
    EXPECT_EQ(s.timing.jitterMs, 4);
    EXPECT_EQ(s.timing.seed, 99u);
    EXPECT_EQ(s.timing.bootMs, 0);
    EXPECT_EQ(s.controller.operatingStatus, 31);
    EXPECT_EQ(s.controller.intRegisters.at(3), -7);
    EXPECT_EQ(s.controller.intRegisters.at(1024), 2147483647);
    EXPECT_EQ(s.controller.realRegisters.at(1), 640.0F);
    EXPECT_TRUE(s.controller.inputs.at(5));
    EXPECT_FALSE(s.controller.inputs.at(6));
    ASSERT_EQ(s.steps.size(), 9u);

    const auto& put = std::get<CommandStep>(s.steps[0].action);
    EXPECT_EQ(put.code, 0x0907);
    EXPECT_EQ(put.name, "PAC_CMD_PUT_FLOAT_REG");
    EXPECT_EQ(put.param, 2);
    EXPECT_EQ(put.data.bits, 0x41200000u);  // 10.0 (docs/manual_errata.md: not 43 20 00 00)
    EXPECT_TRUE(put.data.isReal);
    EXPECT_EQ(put.timeoutMs, 200);
    EXPECT_EQ(put.endTimeoutMs, 300);
    EXPECT_EQ(s.steps[0].note, "n");
    EXPECT_EQ(put.expect.done, true);
    EXPECT_FALSE(put.expect.error.has_value());
    EXPECT_EQ(put.expect.ackData->bits, 0x41200000u);

    const auto& get = std::get<CommandStep>(s.steps[1].action);
    EXPECT_EQ(get.code, 0x1906);
    EXPECT_EQ(get.name, "PAC_CMD_GET_INT_REG");  // named from GVL_PAC although written in hex
    EXPECT_EQ(get.param, 65535);
    EXPECT_EQ(get.data.bits, 0xFFFFFFFFu);
    EXPECT_EQ(get.expect.errorId, 38);

    const auto& put2 = std::get<CommandStep>(s.steps[2].action);
    EXPECT_EQ(put2.code, 0x0906);
    EXPECT_EQ(put2.data.bits, 0x80000000u);
    EXPECT_EQ(put2.expect.errorId, 0x8001);
    EXPECT_EQ(std::get<CommandStep>(s.steps[3].action).name, "");  // 7777 is no command of GVL_PAC

    EXPECT_EQ(std::get<FaultStep>(s.steps[4].action).kind, FaultKind::kPowerCycle);
    EXPECT_EQ(s.steps[4].note, "off and on");
    EXPECT_EQ(std::get<FaultStep>(s.steps[5].action).kind, FaultKind::kFreezeLink);
    EXPECT_EQ(std::get<FaultStep>(s.steps[5].action).link, LinkSide::kFromPac);
    EXPECT_EQ(std::get<FaultStep>(s.steps[6].action).link, LinkSide::kToPac);
    EXPECT_EQ(std::get<FaultStep>(s.steps[7].action).kind, FaultKind::kThawLink);
    EXPECT_EQ(std::get<FaultStep>(s.steps[7].action).link, LinkSide::kBoth);
    EXPECT_EQ(std::get<WaitStep>(s.steps[8].action).ms, 15);
}

TEST(ScenarioLoader, DefaultsForWhatIsLeftOut) {
    const Scenario s = Load(WithStep(R"({"command": "PAC_CMD_GET_STAT"})"));
    EXPECT_EQ(s.timing.plcCycleMs, 1);
    EXPECT_EQ(s.timing.pacCycleMs, 10);
    EXPECT_EQ(s.timing.latencyCycles, 0);
    EXPECT_EQ(s.timing.jitterMs, 0);
    EXPECT_EQ(s.timing.seed, 1u);
    EXPECT_EQ(s.timing.bootMs, 50);
    EXPECT_FALSE(s.controller.operatingStatus.has_value());
    const auto& command = std::get<CommandStep>(s.steps[0].action);
    EXPECT_EQ(command.code, 0x190B);
    EXPECT_EQ(command.param, 0);
    EXPECT_EQ(command.data.bits, 0u);
    EXPECT_EQ(command.timeoutMs, 1000);
    EXPECT_EQ(command.endTimeoutMs, 60000);
    EXPECT_TRUE(command.expect.Empty());
}

TEST(ScenarioLoader, IntegralNumbersMayBeWrittenWithAFraction) {
    const Scenario s = Load(R"({"timing": {"plc_cycle_ms": 2.0}, "steps": [{"wait_ms": 1e1}]})");
    EXPECT_EQ(s.timing.plcCycleMs, 2);
    EXPECT_EQ(std::get<WaitStep>(s.steps[0].action).ms, 10);
}

// "$schema" names the JSON Schema for editors (docs/scenario.md); the loader takes any string and reads
// nothing from it, and refuses another type as it would anywhere.
TEST(ScenarioLoader, AcceptsTheSchemaKeyOfEditors) {
    const Scenario scenario = Load(R"({"$schema": "../scenario.schema.json", "steps": [{"wait_ms": 1}]})");
    EXPECT_EQ(scenario.steps.size(), 1u);
    EXPECT_EQ(Refusal(R"({"$schema": 7, "steps": [{"wait_ms": 1}]})"),
              R"($["$schema"]: wrong type: expected a string, got the number 7)");
}

TEST(ScenarioLoader, RefusesInvalidJsonWithLineAndColumn) {
    EXPECT_EQ(Refusal("{\"steps\": [\n  {\"wait_ms\": 5},\n]}"),
              "not valid JSON: parse error at line 3, column 1: syntax error while parsing value - unexpected ']'; "
              "expected '[', '{', or a literal");
    EXPECT_EQ(Refusal(""),
              "not valid JSON: parse error at line 1, column 1: syntax error while parsing value - unexpected end of "
              "input; expected '[', '{', or a literal");
}

TEST(ScenarioLoader, RefusesADuplicateKey) {
    EXPECT_EQ(Refusal(R"({"steps": [{"wait_ms": 1}, {"command": "0906", "param": 1, "param": 2}]})"),
              R"($.steps[1].param: duplicate key "param")");
    EXPECT_EQ(Refusal(R"({"steps": [{"wait_ms": 1}], "steps": []})"), R"($.steps: duplicate key "steps")");
    EXPECT_EQ(Refusal(R"({"controller": {"n_registers": {"3": 1, "3": 2}}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.n_registers["3"]: duplicate key "3")");
}

TEST(ScenarioLoader, RefusesUnknownKeys) {
    EXPECT_EQ(Refusal(R"({"steps": [{"wait_ms": 1}], "step": 1})"),
              R"($.step: unknown key "step" (a scenario has "name", "description", "timing", "modules", "controller", )"
              R"("steps", "diagram" or "$schema"))");
    EXPECT_EQ(Refusal(R"({"timing": {"plc_cycle": 2}, "steps": [{"wait_ms": 1}]})"),
              R"($.timing.plc_cycle: unknown key "plc_cycle" (timing has "plc_cycle_ms", "pac_cycle_ms", )"
              R"("latency_cycles", "jitter_ms", "seed" or "boot_ms"))");
    EXPECT_EQ(Refusal(R"({"controller": {"n_register": {}}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.n_register: unknown key "n_register" (controller has "operating_status", )"
              R"("n_registers", "r_registers", "inputs", "system_parameters", "axes_referenced", "limit_switches" or )"
              R"("automatic_program"))");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "parm": 3})")),
              R"($.steps[0].parm: unknown key "parm" (a command step has "command", "param", "data", "timeout_ms", )"
              R"("end_timeout_ms", "expect" or "note"))");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "expect": {"ackdata": 3}})")),
              R"($.steps[0].expect.ackdata: unknown key "ackdata" (an expectation has "done", "error", "error_id" or )"
              R"("ack_data"))");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "data": {"float": 1.0}})")),
              R"($.steps[0].data.float: unknown key "float" (a REAL value has "real"))");
    EXPECT_EQ(Refusal(WithStep(R"({"fault": "power_cycle", "link": "to_pac"})")),
              R"($.steps[0].link: unknown key "link" (a power_cycle step has "fault" or "note"))");
    EXPECT_EQ(Refusal(WithStep(R"({"wait_ms": 5, "param": 1})")),
              R"($.steps[0].param: unknown key "param" (a wait step has "wait_ms" or "note"))");
    // Without any step kind, a misspelt key is the likelier mistake.
    EXPECT_EQ(Refusal(WithStep(R"({"comand": "0906"})")),
              R"($.steps[0].comand: unknown key "comand" (a step has "command", "param", "data", "timeout_ms", )"
              R"("end_timeout_ms", "expect", "note", "ctrl", "integer_mode", "axes", "automatic", "max_ms", "fault", )"
              R"("number", "input", "value", "link" or "wait_ms"))");
    EXPECT_EQ(Refusal(R"({"controller": {"inputs": {"I5": true}}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.inputs.I5: unknown key "I5" (the keys are input numbers 1..1024))");
}

TEST(ScenarioLoader, RefusesMissingKeys) {
    EXPECT_EQ(Refusal(R"({"name": "x"})"), R"($: missing key "steps" (a scenario needs it))");
    EXPECT_EQ(Refusal(WithStep(R"({"note": "what?"})")),
              R"($.steps[0]: missing key: a step needs one of "command", "ctrl", "axes", "automatic", "fault" or "wait_ms")");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0907", "data": {}})")),
              R"($.steps[0].data: missing key "real" (a REAL value needs it))");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "wait_ms": 5})")),
              R"($.steps[0]: a step has exactly one of "command", "ctrl", "axes", "automatic", "fault" or "wait_ms", this one has "command" and )"
              R"("wait_ms")");
}

TEST(ScenarioLoader, RefusesWrongTypes) {
    EXPECT_EQ(Refusal("[]"), "$: wrong type: expected an object, got an array");
    EXPECT_EQ(Refusal(R"({"steps": {"wait_ms": 1}})"), "$.steps: wrong type: expected an array of steps, got an object");
    EXPECT_EQ(Refusal(R"({"steps": [5]})"), "$.steps[0]: wrong type: expected an object, got the number 5");
    EXPECT_EQ(Refusal(R"({"timing": {"plc_cycle_ms": "2"}, "steps": [{"wait_ms": 1}]})"),
              R"($.timing.plc_cycle_ms: wrong type: expected an integer, got a string "2")");
    EXPECT_EQ(Refusal(R"({"timing": [], "steps": [{"wait_ms": 1}]})"),
              "$.timing: wrong type: expected an object, got an array");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "param": 2.5})")),
              "$.steps[0].param: wrong type: expected an integer, got the number 2.5");
    EXPECT_EQ(Refusal(WithStep(R"({"command": 906})")),
              R"($.steps[0].command: wrong type: expected a command: 4 hex digits like "0906" or a GVL_PAC name like )"
              R"("PAC_CMD_PUT_INT_REG", got the number 906)");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "data": "333"})")),
              R"($.steps[0].data: wrong type: expected an integer or {"real": number}, got a string "333")");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "expect": {"done": 1}})")),
              "$.steps[0].expect.done: wrong type: expected true or false, got the number 1");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "expect": {"error_id": null}})")),
              "$.steps[0].expect.error_id: wrong type: expected an error number, \"16#8001\" or a PAC_ERR_ / "
              "PAC_LIB_ERR_ name, got null");
    EXPECT_EQ(Refusal(WithStep(R"({"wait_ms": 5, "note": 5})")),
              "$.steps[0].note: wrong type: expected a string, got the number 5");
    EXPECT_EQ(Refusal(R"({"controller": {"r_registers": {"1": "640.0"}}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.r_registers["1"]: wrong type: expected a number, got a string "640.0")");
    EXPECT_EQ(Refusal(R"({"controller": {"inputs": {"5": 1}}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.inputs["5"]: wrong type: expected true or false, got the number 1)");
}

TEST(ScenarioLoader, RefusesValuesOutOfRange) {
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "param": 70000})")),
              "$.steps[0].param: out of range: 70000 is not in 0..65535");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "param": -1})")),
              "$.steps[0].param: out of range: -1 is not in 0..65535");
    EXPECT_EQ(Refusal(R"({"timing": {"plc_cycle_ms": 0}, "steps": [{"wait_ms": 1}]})"),
              "$.timing.plc_cycle_ms: out of range: 0 is not in 1..1000");
    EXPECT_EQ(Refusal(R"({"timing": {"seed": -1}, "steps": [{"wait_ms": 1}]})"),
              "$.timing.seed: out of range: -1 is not in 0..18446744073709551615");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "data": 4294967296})")),
              "$.steps[0].data: out of range: 4294967296 is not in -2147483648..4294967295");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0907", "data": {"real": 1e39}})")),
              "$.steps[0].data.real: out of range: 1e+39 does not fit a REAL (at most 3.4028235e38)");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "timeout_ms": 0})")),
              "$.steps[0].timeout_ms: out of range: 0 is not in 1..3600000");
    EXPECT_EQ(Refusal(WithStep(R"({"wait_ms": 0})")), "$.steps[0].wait_ms: out of range: 0 is not in 1..3600000");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "expect": {"error_id": 65536}})")),
              "$.steps[0].expect.error_id: out of range: 65536 is not in 0..65535");
    EXPECT_EQ(Refusal(R"({"controller": {"n_registers": {"1025": 1}}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.n_registers["1025"]: out of range: N register 1025 is not in 1..1024)");
    EXPECT_EQ(Refusal(R"({"controller": {"n_registers": {"0": 1}}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.n_registers["0"]: out of range: N register 0 is not in 1..1024)");
    EXPECT_EQ(Refusal(R"({"controller": {"n_registers": {"3": 2147483648}}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.n_registers["3"]: out of range: 2147483648 is not in -2147483648..2147483647)");
    EXPECT_EQ(Refusal(R"({"controller": {"operating_status": 40}, "steps": [{"wait_ms": 1}]})"),
              "$.controller.operating_status: out of range: 40 is not an operating status of GVL_PAC");
    EXPECT_EQ(Refusal(R"({"steps": []})"), "$.steps: out of range: a scenario needs at least one step");
}

TEST(ScenarioLoader, RefusesUnknownNames) {
    EXPECT_EQ(Refusal(WithStep(R"({"command": "PAC_CMD_PUT_INT_REGISTER"})")),
              R"($.steps[0].command: unknown command name "PAC_CMD_PUT_INT_REGISTER" (a command is 4 hex digits like )"
              R"("0906" or a PAC_CMD_ constant of GVL_PAC))");
    // A name of GVL_PAC, but not a command's.
    EXPECT_EQ(Refusal(WithStep(R"({"command": "PAC_ERR_N_REGISTER"})")),
              R"($.steps[0].command: unknown command name "PAC_ERR_N_REGISTER" (a command is 4 hex digits like )"
              R"("0906" or a PAC_CMD_ constant of GVL_PAC))");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "906"})")),
              R"($.steps[0].command: unknown command name "906" (a command is 4 hex digits like "0906" or a )"
              R"(PAC_CMD_ constant of GVL_PAC))");
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "expect": {"error_id": "PAC_ERR_N_REG"}})")),
              R"($.steps[0].expect.error_id: unknown error name "PAC_ERR_N_REG" (not a PAC_ERR_ or PAC_LIB_ERR_ )"
              R"(constant of GVL_PAC, nor a number like "16#8001"))");
    EXPECT_EQ(Refusal(R"({"controller": {"operating_status": "PAC_STATUS_RUNNING"}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.operating_status: unknown status name "PAC_STATUS_RUNNING" (not a PAC_STATUS_ )"
              R"(constant of GVL_PAC))");
    EXPECT_EQ(Refusal(WithStep(R"({"fault": "unplug"})")),
              R"($.steps[0].fault: unknown fault "unplug" (a fault is "power_cycle", "freeze_link", "thaw_link", )"
              R"("zero_link", "system_error" or "set_input"))");
    EXPECT_EQ(Refusal(WithStep(R"({"fault": "system_error", "number": 1000})")),
              "$.steps[0].number: out of range: 1000 is not in 1..999");
    EXPECT_EQ(Refusal(WithStep(R"({"fault": "set_input", "input": 1})")),
              R"($.steps[0]: missing key "value" (a set_input step needs it))");
    EXPECT_EQ(Refusal(WithStep(R"({"fault": "freeze_link", "link": "up"})")),
              R"($.steps[0].link: unknown link "up" (a link is "to_pac", "from_pac" or "both"))");
}

TEST(ScenarioLoader, RefusesContradictoryExpectations) {
    EXPECT_EQ(Refusal(WithStep(R"({"command": "0906", "expect": {"done": true, "error": true}})")),
              "$.steps[0].expect: contradiction: done and error cannot both be true (FB_PAC_Cmd's outputs are exclusive)");
}

TEST(ScenarioLoader, FilesNameTheScenarioAndRefuseYaml) {
    const ScenarioLoader loader(Names());
    const Scenario demo = loader.FromFile(std::string(PAC_SCENARIO_DIR) + "/demo.json");
    EXPECT_EQ(demo.name, "demo");
    const std::string path = testing::TempDir() + "/ScenarioLoader-unnamed.json";
    std::ofstream(path) << R"({"steps": [{"wait_ms": 1}]})";
    EXPECT_EQ(loader.FromFile(path).name, "ScenarioLoader-unnamed.json");

    try {
        loader.FromFile(testing::TempDir() + "/scenario.yaml");
        FAIL() << "YAML accepted";
    } catch (const ScenarioError& e) {
        EXPECT_STREQ(e.what(), "YAML is not supported: write the scenario as JSON (docs/scenario.md)");
    }
    try {
        loader.FromFile(testing::TempDir() + "/no-such-scenario.json");
        FAIL() << "a missing file accepted";
    } catch (const ScenarioError& e) {
        EXPECT_STREQ(e.what(), "cannot read the file");
    }
}

// Every prefix of the demo and every one-byte change of it is either a scenario or a ScenarioError:
// nothing else escapes the loader.
TEST(ScenarioLoader, NeverCrashesOnDamagedFiles) {
    const std::string demo = ReadFile(std::string(PAC_SCENARIO_DIR) + "/demo.json");
    ASSERT_FALSE(demo.empty());
    int refused = 0;
    auto attempt = [&](const std::string& text) {
        try {
            Load(text);
        } catch (const ScenarioError&) {
            ++refused;
        }
    };
    for (std::size_t length = 0; length < demo.size(); ++length) attempt(demo.substr(0, length));
    const std::string replacements = "\"{}[],:0-9.eE \\ax";
    std::uint64_t state = 12345;
    for (int i = 0; i < 3000; ++i) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        std::string text = demo;
        text[(state >> 33) % text.size()] = replacements[(state >> 17) % replacements.size()];
        attempt(text);
    }
    EXPECT_GT(refused, static_cast<int>(demo.size()));
}

}  // namespace

TEST(ScenarioLoader, ReadsModulesCtrlAndAxesSteps) {
    const Scenario s = Load(R"({
      "modules": {"ctrl": true, "axes": 2},
      "controller": {"system_parameters": {"4": 1}},
      "steps": [
        {"ctrl": "PAC_REQ_START_ONLINE", "integer_mode": true, "timeout_ms": 500, "expect": {"done": true}},
        {"axes": [{"axis": 2, "enable": true},
                  {"axis": 1, "command": "PAC_AX_MOVE_RELATIVE", "position": -12.5, "velocity": 500,
                   "acceleration": 2000, "condition": "PAC_COND_WHILE_INPUT_0", "max_ms": 9000,
                   "expect": {"done": true, "position": -12.5, "position_tolerance": 0.01, "referenced": true}}]}
      ]})");
    EXPECT_TRUE(s.modules.ctrl);
    EXPECT_EQ(s.modules.axes, 2);
    EXPECT_EQ(s.controller.systemParameters.at(4), 1);
    const auto& ctrl = std::get<pac::scenario::CtrlStep>(s.steps[0].action);
    EXPECT_EQ(ctrl.request, "PAC_REQ_START_ONLINE");
    EXPECT_TRUE(ctrl.integerMode);
    EXPECT_EQ(ctrl.timeoutMs, 500);
    EXPECT_EQ(ctrl.expect.done, true);
    const auto& axes = std::get<pac::scenario::AxesStep>(s.steps[1].action);
    ASSERT_EQ(axes.jobs.size(), 2u);
    EXPECT_EQ(axes.jobs[0].axis, 2);
    EXPECT_EQ(axes.jobs[0].enable, true);
    EXPECT_FALSE(axes.jobs[0].HasJob());
    const auto& move = axes.jobs[1];
    EXPECT_EQ(move.command, "PAC_AX_MOVE_RELATIVE");
    EXPECT_FALSE(move.enable.has_value());
    EXPECT_DOUBLE_EQ(move.position, -12.5);
    EXPECT_EQ(move.velocity, 500);
    EXPECT_EQ(move.acceleration, 2000);
    EXPECT_EQ(move.condition, "PAC_COND_WHILE_INPUT_0");
    EXPECT_EQ(move.maxMs, 9000);
    EXPECT_EQ(move.expect.position, -12.5);
    EXPECT_DOUBLE_EQ(move.expect.positionTolerance, 0.01);
    EXPECT_EQ(move.expect.referenced, true);
}

TEST(ScenarioLoader, ReadsLimitSwitchesAndAxisErrorResets) {
    const Scenario s = Load(R"({"modules": {"ctrl": true, "axes": 2},
        "controller": {"limit_switches": {"2": {"positive": 30.0}, "1": {"negative": -5, "positive": 5}}},
        "steps": [{"axes": [{"axis": 2, "reset_error": true, "enable": true}]}]})");
    ASSERT_EQ(s.controller.limitSwitches.size(), 2u);
    EXPECT_FALSE(s.controller.limitSwitches.at(2).negative);
    EXPECT_EQ(s.controller.limitSwitches.at(2).positive, 30.0);
    EXPECT_EQ(s.controller.limitSwitches.at(1).negative, -5.0);
    const auto& job = std::get<pac::scenario::AxesStep>(s.steps[0].action).jobs[0];
    EXPECT_TRUE(job.resetError);
    EXPECT_FALSE(job.HasJob());
    const std::string axes = R"({"modules": {"ctrl": true, "axes": 1}, )";
    EXPECT_EQ(Refusal(axes + R"("controller": {"limit_switches": {"9": {"positive": 1}}}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.limit_switches["9"]: out of range: axis 9 is not in 1..8)");
    EXPECT_EQ(Refusal(axes + R"("controller": {"limit_switches": {"1": {}}}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.limit_switches["1"]: missing key: "negative", "positive" or both)");
    EXPECT_EQ(Refusal(axes + R"("controller": {"limit_switches": {"1": {"negative": 5, "positive": 5}}}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.limit_switches["1"]: contradiction: the negative switch must lie below the positive one)");
    EXPECT_EQ(Refusal(axes + R"("steps": [{"axes": [{"axis": 1, "command": "PAC_AX_HOME", "reset_error": true}]}]})"),
              "$.steps[0].axes[0].reset_error: contradiction: an axis has a command or resets its error, not both in one step");
}

TEST(ScenarioLoader, ReadsADiagramAndRefusesOneItCannotDraw) {
    const Scenario s = Load(R"({"steps": [{"wait_ms": 2}, {"command": "0906"}, {"wait_ms": 2}],
        "diagram": {"title": "t", "steps": [2, 3], "signals": ["cmd.SEND", "cmd.FromPac"], "sampled": ["cmd.FromPac"],
                    "context_scans": 0, "max_idle_scans": 5, "hscale": 2}})");
    EXPECT_EQ(s.diagram.title, "t");
    EXPECT_EQ(s.diagram.firstStep, 2u);
    EXPECT_EQ(s.diagram.lastStep, 3u);
    EXPECT_EQ(s.diagram.signals, (std::vector<std::string>{"cmd.SEND", "cmd.FromPac"}));
    EXPECT_EQ(s.diagram.sampled, (std::vector<std::string>{"cmd.FromPac"}));
    EXPECT_EQ(s.diagram.contextScans, 0);
    EXPECT_EQ(s.diagram.maxIdleScans, 5);
    EXPECT_EQ(s.diagram.hscale, 2);
    EXPECT_EQ(Load(R"({"steps": [{"wait_ms": 2}, {"wait_ms": 2}]})").diagram.lastStep, 2u) << "every step by default";
    const std::string steps = R"({"steps": [{"wait_ms": 2}, {"wait_ms": 2}], "diagram": )";
    EXPECT_EQ(Refusal(steps + R"({"steps": [2, 3]}})"), "$.diagram.steps[1]: out of range: 3 is not in 2..2");
    EXPECT_EQ(Refusal(steps + R"({"steps": [2, 1]}})"), "$.diagram.steps[1]: out of range: 1 is not in 2..2");
    EXPECT_EQ(Refusal(steps + R"({"steps": 2}})"), "$.diagram.steps: wrong type: expected [first step, last step], got the number 2");
    EXPECT_EQ(Refusal(steps + R"({"signals": ["ctrl.Status"]}})").rfind(R"($.diagram.signals[0]: unknown signal "ctrl.Status" ()", 0), 0u)
        << "the scenario has no CTRL interface";
    EXPECT_EQ(Refusal(steps + R"({"signals": ["cmd.SEND"], "sampled": ["cmd.RF"]}})").rfind(R"($.diagram.sampled[0]: unknown signal "cmd.RF" ()", 0), 0u)
        << "a sampled lane must be one of the diagram's";
    EXPECT_EQ(Refusal(steps + R"({"hscale": 0}})"), "$.diagram.hscale: out of range: 0 is not in 1..10");
    EXPECT_EQ(Refusal(steps + R"({"colour": 1}})").rfind(R"($.diagram.colour: unknown key "colour" ()", 0), 0u);
}

TEST(ScenarioLoader, RefusesModuleStepsItCannotRun) {
    EXPECT_EQ(Refusal(R"({"modules": {"axes": 1}, "steps": [{"wait_ms": 1}]})"),
              R"($.modules.axes: axis modules need the CTRL interface (extensions 2..9 come after it): set "ctrl": true)");
    EXPECT_EQ(Refusal(R"({"modules": {"ctrl": true, "axes": 9}, "steps": [{"wait_ms": 1}]})"),
              "$.modules.axes: out of range: 9 is not in 0..8");
    EXPECT_EQ(Refusal(WithStep(R"({"ctrl": "PAC_REQ_STOP"})")),
              R"($.steps[0].ctrl: a ctrl step needs the CTRL interface: set "modules": {"ctrl": true})");
    EXPECT_EQ(Refusal(WithStep(R"({"axes": [{"axis": 1, "enable": true}]})")),
              R"($.steps[0].axes: an axes step needs axis modules: set "modules": {"ctrl": true, "axes": 1..8})");
    const std::string modules = R"({"modules": {"ctrl": true, "axes": 2}, "steps": [)";
    EXPECT_EQ(Refusal(modules + R"({"ctrl": "START_ONLINE"}]})"),
              R"($.steps[0].ctrl: unknown request "START_ONLINE" (one of "PAC_REQ_NONE", "PAC_REQ_START_ONLINE", )"
              R"("PAC_REQ_START_AUTOMATIC", "PAC_REQ_STOP", "PAC_REQ_CANCEL" or "PAC_REQ_RESET_ERROR"))");
    EXPECT_EQ(Refusal(modules + R"({"ctrl": "PAC_REQ_STOP", "expect": {"ack_data": 1}}]})"),
              R"($.steps[0].expect.ack_data: unknown key "ack_data" (a ctrl expectation has "done", "error" or "error_id"))");
    EXPECT_EQ(Refusal(modules + R"({"axes": [{"axis": 3, "enable": true}]}]})"),
              "$.steps[0].axes[0].axis: out of range: 3 is not in 1..2");
    EXPECT_EQ(Refusal(modules + R"({"axes": [{"axis": 1}]}]})"),
              R"($.steps[0].axes[0]: missing key: an axis job needs "enable", "command" or "reset_error")");
    EXPECT_EQ(Refusal(modules + R"({"axes": [{"axis": 1, "enable": true}, {"axis": 1, "enable": false}]}]})"),
              "$.steps[0].axes[1].axis: axis 1 appears twice in this step (one FB_PAC_Axis per axis)");
    EXPECT_EQ(Refusal(modules + R"({"axes": []}]})"), "$.steps[0].axes: out of range: an axes step needs at least one axis");
    EXPECT_EQ(Refusal(modules + R"({"axes": [{"axis": 1, "command": "HOME"}]}]})").substr(0, 62),
              R"($.steps[0].axes[0].command: unknown axis command "HOME" (one o)");
    EXPECT_EQ(Refusal(modules + R"({"axes": [{"axis": 1, "command": "PAC_AX_HOME", "expect": {"done": true, "aborted": true}}]}]})"),
              "$.steps[0].axes[0].expect: contradiction: at most one of done, error and aborted can be true "
              "(FB_PAC_Axis's outputs are exclusive)");
}

// "mc_blocks": the axes steps name MC_ blocks, and only those the runner drives; no G123 condition.
TEST(ScenarioLoader, ReadsAndRefusesStepsOfTheMcBlocks) {
    const std::string mc = R"({"modules": {"ctrl": true, "axes": 2, "mc_blocks": true}, "steps": [)";
    const Scenario scenario = Load(mc + R"({"axes": [{"axis": 2, "command": "MC_MoveRelative", "position": 5.0}]}]})");
    EXPECT_TRUE(scenario.modules.mcBlocks);
    EXPECT_EQ(std::get<pac::scenario::AxesStep>(scenario.steps.at(0).action).jobs.at(0).command, "MC_MoveRelative");
    EXPECT_EQ(Refusal(R"({"modules": {"ctrl": true, "mc_blocks": true}, "steps": [{"wait_ms": 1}]})"),
              R"($.modules.mc_blocks: the MC_ blocks run on axis modules: set "axes" to 1..8)");
    EXPECT_EQ(Refusal(mc + R"({"axes": [{"axis": 1, "command": "PAC_AX_HOME"}]}]})"),
              R"($.steps[0].axes[0].command: unknown MC_ block "PAC_AX_HOME" (one of "MC_Home", "MC_MoveAbsolute", )"
              R"("MC_MoveRelative", "MC_Halt" or "MC_Stop"))");
    EXPECT_EQ(Refusal(mc + R"({"axes": [{"axis": 1, "command": "MC_MoveAbsolute", "condition": "PAC_COND_NONE"}]}]})"),
              "$.steps[0].axes[0].condition: the MC_ blocks have no G123 condition");
    const std::string plain = R"({"modules": {"ctrl": true, "axes": 1}, "steps": [)";
    EXPECT_EQ(Refusal(plain + R"({"axes": [{"axis": 1, "command": "MC_Home"}]}]})").substr(0, 65),
              R"($.steps[0].axes[0].command: unknown axis command "MC_Home" (one o)");
}

// "diagnosis": FB_PAC_Diagnosis's Axes and PollTime, defaults 0 and 500 ms; not with the MC_ blocks.
TEST(ScenarioLoader, ReadsAndRefusesTheDiagnosis) {
    const Scenario s = Load(R"({"modules": {"diagnosis": {"axes": 3, "poll_ms": 20}}, "steps": [{"wait_ms": 1}]})");
    ASSERT_TRUE(s.modules.diagnosis.has_value());
    EXPECT_EQ(s.modules.diagnosis->axes, 3);
    EXPECT_EQ(s.modules.diagnosis->pollMs, 20);
    const Scenario d = Load(R"({"modules": {"diagnosis": {}}, "steps": [{"wait_ms": 1}]})");
    EXPECT_EQ(d.modules.diagnosis->axes, 0);
    EXPECT_EQ(d.modules.diagnosis->pollMs, 500);
    EXPECT_FALSE(Load(R"({"steps": [{"wait_ms": 1}]})").modules.diagnosis.has_value());
    EXPECT_EQ(Refusal(R"({"modules": {"diagnosis": {"axes": 9}}, "steps": [{"wait_ms": 1}]})"),
              "$.modules.diagnosis.axes: out of range: 9 is not in 0..8");
    EXPECT_EQ(Refusal(R"({"modules": {"diagnosis": {"poll_ms": 0}}, "steps": [{"wait_ms": 1}]})"),
              "$.modules.diagnosis.poll_ms: out of range: 0 is not in 1..3600000");
    EXPECT_EQ(Refusal(R"({"modules": {"ctrl": true, "axes": 1, "mc_blocks": true, "diagnosis": {}}, )"
                      R"("steps": [{"wait_ms": 1}]})"),
              R"($.modules.diagnosis: FB_PAC_Diagnosis takes FB_PAC_Axis's status: not with "mc_blocks")");
}

TEST(ScenarioLoader, ReadsAutomaticStepsAndTheAutomaticProgram) {
    const Scenario s = Load(R"({
      "modules": {"ctrl": true, "axes": 2},
      "controller": {"automatic_program": ["R17 := R1 * 2", "M257 := M1"]},
      "steps": [
        {"automatic": [{"module": 2, "flag_word": 65535, "n": -7, "r": 1.5},
                       {"module": 1, "expect": {"flag_word": 1, "n": 42, "r": 2.5, "r_tolerance": 0.1}}],
         "max_ms": 300}
      ]})");
    EXPECT_EQ(s.controller.automaticProgram, (std::vector<std::string>{"R17 := R1 * 2", "M257 := M1"}));
    const auto& automatic = std::get<pac::scenario::AutomaticStep>(s.steps[0].action);
    EXPECT_EQ(automatic.maxMs, 300);
    ASSERT_EQ(automatic.modules.size(), 2u);
    const auto& sent = automatic.modules[0];
    EXPECT_EQ(sent.module, 2);
    EXPECT_EQ(sent.flagWord, 0xFFFF);
    EXPECT_EQ(sent.n, -7);
    EXPECT_EQ(sent.r, 1.5);
    EXPECT_TRUE(sent.expect.Empty());
    const auto& expected = automatic.modules[1];
    EXPECT_FALSE(expected.flagWord || expected.n || expected.r);
    EXPECT_EQ(expected.expect.flagWord, 1);
    EXPECT_EQ(expected.expect.n, 42);
    EXPECT_EQ(expected.expect.r, 2.5);
    EXPECT_DOUBLE_EQ(expected.expect.rTolerance, 0.1);
}

TEST(ScenarioLoader, RefusesAutomaticStepsItCannotRun) {
    EXPECT_EQ(Refusal(WithStep(R"({"automatic": [{"module": 1, "n": 1}]})")),
              R"($.steps[0].automatic: an automatic step needs modules: set "modules": {"ctrl": true, "axes": 1..8})");
    const std::string modules = R"({"modules": {"ctrl": true, "axes": 1}, "steps": [)";
    EXPECT_EQ(Refusal(modules + R"({"automatic": [{"module": 2, "n": 1}]}]})"),
              "$.steps[0].automatic[0].module: out of range: 2 is not in 1..1");
    EXPECT_EQ(Refusal(modules + R"({"automatic": [{"module": 1}]}]})"),
              R"($.steps[0].automatic[0]: missing key: a module needs "flag_word", "n", "r" or "expect")");
    EXPECT_EQ(Refusal(modules + R"({"automatic": [{"module": 1, "flag_word": 65536}]}]})"),
              "$.steps[0].automatic[0].flag_word: out of range: 65536 is not in 0..65535");
    EXPECT_EQ(Refusal(modules + R"({"automatic": [{"module": 1, "n": 1}, {"module": 1, "r": 1}]}]})"),
              "$.steps[0].automatic[1].module: module 1 appears twice in this step");
    EXPECT_EQ(Refusal(R"({"controller": {"automatic_program": ["R17 = R1"]}, "steps": [{"wait_ms": 1}]})"),
              R"($.controller.automatic_program[0]: AutomaticProgram: "R17 = R1": expected := at column 5)");
}
