#include "scenario_loader.hpp"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "diagram_reader.hpp"
#include "json_fields.hpp"
#include "module_steps.hpp"
#include "scenario_keys.hpp"
#include "pac/sim/automatic_program.hpp"
#include "pac/sim/elements.hpp"
#include "pac/sim/image8.hpp"

namespace pac::scenario {

namespace {

using json::Json;


// "0906" or "16#0906" (4 hex digits); with anyWidthWithPrefix also "16#26" (1..3 digits after 16#).
std::optional<std::uint16_t> ParseHex(const std::string& text, bool anyWidthWithPrefix) {
    std::string digits = text;
    const bool prefixed = digits.rfind("16#", 0) == 0;
    if (prefixed) digits.erase(0, 3);
    const bool widthOk = digits.size() == 4 || (prefixed && anyWidthWithPrefix && !digits.empty() && digits.size() < 4);
    if (!widthOk) return std::nullopt;
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); })) {
        return std::nullopt;
    }
    return static_cast<std::uint16_t>(std::stoul(digits, nullptr, 16));
}

using json::Quoted;

class Reader {
public:
    explicit Reader(const GvlNames& names) : names_(names) {}

    Scenario ReadScenario(const Json& document) const {
        const json::Object top(document, "$", keys::Of("scenario"), "a scenario");
        if (const Json* schema = top.Find("$schema")) json::String(*schema, top.PathOf("$schema"));  // for editors
        Scenario scenario;
        if (const Json* name = top.Find("name")) scenario.name = json::String(*name, top.PathOf("name"));
        if (const Json* text = top.Find("description")) {
            scenario.description = json::String(*text, top.PathOf("description"));
        }
        if (const Json* timing = top.Find("timing")) scenario.timing = ReadTiming(*timing, top.PathOf("timing"));
        if (const Json* modules = top.Find("modules")) scenario.modules = ReadModules(*modules, top.PathOf("modules"));
        if (const Json* controller = top.Find("controller")) {
            scenario.controller = ReadController(*controller, top.PathOf("controller"));
        }
        const Json& steps = top.Get("steps");
        const std::string stepsPath = top.PathOf("steps");
        if (!steps.is_array()) json::RefuseType(stepsPath, "an array of steps", steps);
        if (steps.empty()) json::Refuse(stepsPath, "out of range: a scenario needs at least one step");
        const ModuleStepReader moduleSteps(scenario.modules, [this](const Json& value, const std::string& path) {
            return ReadErrorId(value, path);
        });
        for (std::size_t i = 0; i < steps.size(); ++i) {
            scenario.steps.push_back(ReadStep(steps[i], json::Element(stepsPath, i), moduleSteps));
        }
        scenario.diagram.lastStep = scenario.steps.size();
        if (const Json* diagram = top.Find("diagram")) {
            scenario.diagram = ReadDiagram(*diagram, top.PathOf("diagram"), scenario.steps.size(), scenario.modules);
        }
        return scenario;
    }

private:

    static Timing ReadTiming(const Json& value, const std::string& path) {
        const json::Object timing(value, path, keys::Of("timing"), "timing");
        Timing result;
        auto integer = [&](const char* key, int min, int max, int fallback) {
            const Json* v = timing.Find(key);
            return v ? static_cast<int>(json::Integer(*v, timing.PathOf(key), min, max)) : fallback;
        };
        result.plcCycleMs = integer("plc_cycle_ms", 1, 1000, result.plcCycleMs);
        result.pacCycleMs = integer("pac_cycle_ms", 1, 1000, result.pacCycleMs);
        result.latencyCycles = integer("latency_cycles", 0, 1000, result.latencyCycles);
        result.jitterMs = integer("jitter_ms", 0, 10000, result.jitterMs);
        result.bootMs = integer("boot_ms", 0, 600000, result.bootMs);
        if (const Json* seed = timing.Find("seed")) result.seed = json::Unsigned(*seed, timing.PathOf("seed"));
        return result;
    }

    static Modules ReadModules(const Json& value, const std::string& path) {
        const json::Object object(value, path, keys::Of("modules"), "modules");
        Modules modules;
        if (const Json* ctrl = object.Find("ctrl")) modules.ctrl = json::Bool(*ctrl, object.PathOf("ctrl"));
        if (const Json* axes = object.Find("axes")) {
            modules.axes = static_cast<int>(json::Integer(*axes, object.PathOf("axes"), 0, 8));
            if (modules.axes > 0 && !modules.ctrl) {
                json::Refuse(object.PathOf("axes"),
                             "axis modules need the CTRL interface (extensions 2..9 come after it): set \"ctrl\": true");
            }
        }
        if (const Json* mc = object.Find("mc_blocks")) {
            modules.mcBlocks = json::Bool(*mc, object.PathOf("mc_blocks"));
            if (modules.mcBlocks && modules.axes == 0) {
                json::Refuse(object.PathOf("mc_blocks"), "the MC_ blocks run on axis modules: set \"axes\" to 1..8");
            }
        }
        if (const Json* diagnosis = object.Find("diagnosis")) {
            modules.diagnosis = ReadDiagnosis(*diagnosis, object.PathOf("diagnosis"));
            if (modules.mcBlocks) {
                json::Refuse(object.PathOf("diagnosis"), "FB_PAC_Diagnosis takes FB_PAC_Axis's status: not with \"mc_blocks\"");
            }
        }
        return modules;
    }

    static DiagnosisSetup ReadDiagnosis(const Json& value, const std::string& path) {
        const json::Object object(value, path, keys::Of("diagnosis"), "diagnosis");
        DiagnosisSetup setup;
        if (const Json* axes = object.Find("axes")) {
            setup.axes = static_cast<int>(json::Integer(*axes, object.PathOf("axes"), 0, 8));
        }
        if (const Json* poll = object.Find("poll_ms")) {
            setup.pollMs = static_cast<int>(json::Integer(*poll, object.PathOf("poll_ms"), 1, 3600000));
        }
        return setup;
    }

    // Keys of a register or input table: element numbers 1..count.
    template <class Value, class ReadValue>
    static std::map<int, Value> ReadNumbered(const Json& value, const std::string& path, int count, const char* what,
                                             ReadValue readValue) {
        json::RequireObject(value, path);
        std::map<int, Value> result;
        for (const auto& item : value.items()) {
            const std::string& key = item.key();
            const std::string itemPath = json::Child(path, key);
            const bool digits = !key.empty() && key.size() <= 9 &&
                                std::all_of(key.begin(), key.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
            if (!digits) {
                json::Refuse(itemPath, "unknown key " + Quoted(key) + " (the keys are " + what + " numbers 1.." +
                                           std::to_string(count) + ")");
            }
            const int number = std::stoi(key);
            if (number < 1 || number > count) {
                json::Refuse(itemPath, "out of range: " + std::string(what) + " " + key + " is not in 1.." + std::to_string(count));
            }
            result[number] = readValue(item.value(), itemPath);
        }
        return result;
    }

    ControllerSetup ReadController(const Json& value, const std::string& path) const {
        const json::Object controller(value, path, keys::Of("controller"), "controller");
        const pac::sim::ElementCounts counts;
        ControllerSetup setup;
        if (const Json* status = controller.Find("operating_status")) {
            setup.operatingStatus = ReadStatus(*status, controller.PathOf("operating_status"));
        }
        if (const Json* n = controller.Find("n_registers")) {
            setup.intRegisters = ReadNumbered<std::int32_t>(
                *n, controller.PathOf("n_registers"), counts.intRegisters, "N register",
                [](const Json& v, const std::string& p) {
                    return static_cast<std::int32_t>(json::Integer(v, p, INT32_MIN, INT32_MAX));
                });
        }
        if (const Json* r = controller.Find("r_registers")) {
            setup.realRegisters = ReadNumbered<float>(*r, controller.PathOf("r_registers"), counts.realRegisters,
                                                      "R register", [](const Json& v, const std::string& p) { return Real(v, p); });
        }
        if (const Json* inputs = controller.Find("inputs")) {
            setup.inputs = ReadNumbered<bool>(*inputs, controller.PathOf("inputs"), counts.inputs, "input",
                                              [](const Json& v, const std::string& p) { return json::Bool(v, p); });
        }
        if (const Json* referenced = controller.Find("axes_referenced")) {
            setup.axesReferenced = json::Bool(*referenced, controller.PathOf("axes_referenced"));
        }
        if (const Json* switches = controller.Find("limit_switches")) {
            setup.limitSwitches = ReadNumbered<LimitSwitches>(*switches, controller.PathOf("limit_switches"), 8, "axis",
                                                              ReadLimitSwitches);
        }
        if (const Json* program = controller.Find("automatic_program")) {
            setup.automaticProgram = ReadProgram(*program, controller.PathOf("automatic_program"));
        }
        if (const Json* parameters = controller.Find("system_parameters")) {
            // The simulator's table knows which numbers exist and their limits; the runner reports a refusal.
            setup.systemParameters = ReadNumbered<std::int32_t>(
                *parameters, controller.PathOf("system_parameters"), 65535, "system parameter",
                [](const Json& v, const std::string& p) {
                    return static_cast<std::int32_t>(json::Integer(v, p, INT32_MIN, INT32_MAX));
                });
        }
        return setup;
    }

    // {"negative": -50.0, "positive": 60.0}: machine positions of the switches, at least one of them.
    static LimitSwitches ReadLimitSwitches(const Json& value, const std::string& path) {
        const json::Object object(value, path, keys::Of("limitSwitches"), "the limit switches of an axis");
        LimitSwitches switches;
        if (const Json* v = object.Find("negative")) switches.negative = json::Number(*v, object.PathOf("negative"));
        if (const Json* v = object.Find("positive")) switches.positive = json::Number(*v, object.PathOf("positive"));
        if (!switches.negative && !switches.positive) json::Refuse(path, "missing key: \"negative\", \"positive\" or both");
        if (switches.negative && switches.positive && !(*switches.negative < *switches.positive)) {
            json::Refuse(path, "contradiction: the negative switch must lie below the positive one");
        }
        return switches;
    }

    // The stand-in AUTOMATIC program: an array of lines the simulator reads (pac/sim/automatic_program.hpp).
    static std::vector<std::string> ReadProgram(const Json& value, const std::string& path) {
        if (!value.is_array()) json::RefuseType(path, "an array of program lines", value);
        std::vector<std::string> lines;
        for (std::size_t i = 0; i < value.size(); ++i) {
            const std::string linePath = json::Element(path, i);
            lines.push_back(json::String(value[i], linePath));
            try {
                pac::sim::AutomaticProgram({lines.back()});
            } catch (const std::invalid_argument& e) {
                json::Refuse(linePath, e.what());
            }
        }
        return lines;
    }

    std::uint8_t ReadStatus(const Json& value, const std::string& path) const {
        if (value.is_string()) {
            const std::string name = value.get<std::string>();
            const auto status = names_.Find(name, "PAC_STATUS_");
            if (!status) json::Refuse(path, "unknown status name " + Quoted(name) + " (not a PAC_STATUS_ constant of GVL_PAC)");
            return static_cast<std::uint8_t>(*status);
        }
        if (!value.is_number()) json::RefuseType(path, "an operating status (a number or a PAC_STATUS_ name)", value);
        const auto status = static_cast<std::uint8_t>(json::Integer(value, path, 0, 255));
        if (names_.StatusName(status).empty()) {
            json::Refuse(path, "out of range: " + std::to_string(status) + " is not an operating status of GVL_PAC");
        }
        return status;
    }

    // A REAL: any finite number a single-precision float can hold.
    static float Real(const Json& value, const std::string& path) {
        const double number = json::Number(value, path);
        if (!(std::fabs(number) <= FLT_MAX)) {
            json::Refuse(path, "out of range: " + value.dump() + " does not fit a REAL (at most 3.4028235e38)");
        }
        return static_cast<float>(number);
    }

    // A DWORD: an integer -2147483648..4294967295 (DINT or UDINT) or {"real": number}.
    static DwordValue ReadDword(const Json& value, const std::string& path) {
        DwordValue result;
        if (value.is_object()) {
            const json::Object real(value, path, keys::Of("real"), "a REAL value");
            result.bits = pac::sim::FloatToBits(Real(real.Get("real"), real.PathOf("real")));
            result.isReal = true;
            return result;
        }
        if (!value.is_number()) json::RefuseType(path, "an integer or {\"real\": number}", value);
        result.bits = static_cast<std::uint32_t>(json::Integer(value, path, INT32_MIN, UINT32_MAX));
        return result;
    }

    std::uint16_t ReadCode(const Json& value, const std::string& path, std::string& name) const {
        const std::string what = "a command: 4 hex digits like \"0906\" or a GVL_PAC name like \"PAC_CMD_PUT_INT_REG\"";
        if (!value.is_string()) json::RefuseType(path, what, value);
        const std::string text = value.get<std::string>();
        if (const auto code = ParseHex(text, false)) {
            name = names_.CommandName(*code);
            return *code;
        }
        const auto code = names_.Find(text, "PAC_CMD_");
        if (!code) {
            json::Refuse(path, "unknown command name " + Quoted(text) +
                                   " (a command is 4 hex digits like \"0906\" or a PAC_CMD_ constant of GVL_PAC)");
        }
        name = text;
        return static_cast<std::uint16_t>(*code);
    }

    std::uint16_t ReadErrorId(const Json& value, const std::string& path) const {
        if (value.is_number()) return static_cast<std::uint16_t>(json::Integer(value, path, 0, 0xFFFF));
        if (!value.is_string()) {
            json::RefuseType(path, "an error number, \"16#8001\" or a PAC_ERR_ / PAC_LIB_ERR_ name", value);
        }
        const std::string text = value.get<std::string>();
        if (const auto number = ParseHex(text, true); number && text.rfind("16#", 0) == 0) return *number;
        const auto number = names_.FindError(text);
        if (!number) {
            json::Refuse(path, "unknown error name " + Quoted(text) +
                                   " (not a PAC_ERR_ or PAC_LIB_ERR_ constant of GVL_PAC, nor a number like \"16#8001\")");
        }
        return *number;
    }

    Expectation ReadExpectation(const Json& value, const std::string& path) const {
        const json::Object expect(value, path, keys::Of("expectation"), "an expectation");
        Expectation result;
        if (const Json* done = expect.Find("done")) result.done = json::Bool(*done, expect.PathOf("done"));
        if (const Json* error = expect.Find("error")) result.error = json::Bool(*error, expect.PathOf("error"));
        if (const Json* id = expect.Find("error_id")) result.errorId = ReadErrorId(*id, expect.PathOf("error_id"));
        if (const Json* ack = expect.Find("ack_data")) result.ackData = ReadDword(*ack, expect.PathOf("ack_data"));
        if (result.done.value_or(false) && result.error.value_or(false)) {
            json::Refuse(path, "contradiction: done and error cannot both be true (FB_PAC_Cmd's outputs are exclusive)");
        }
        return result;
    }

    Step ReadStep(const Json& value, const std::string& path, const ModuleStepReader& moduleSteps) const {
        static const std::vector<std::string> kinds = {"command", "ctrl", "axes", "automatic", "fault", "wait_ms"};
        json::RequireObject(value, path);
        std::vector<std::string> present;
        for (const auto& kind : kinds) {
            if (value.contains(kind)) present.push_back(kind);
        }
        if (present.size() > 1) {
            json::Refuse(path, "a step has exactly one of " + json::ListKeys(kinds) + ", this one has " +
                                   json::ListKeys(present, "and"));
        }
        if (present.empty()) {
            json::Object(value, path, keys::AnyStep(), "a step");  // an unknown key is the likelier mistake: report it
            json::Refuse(path, "missing key: a step needs one of " + json::ListKeys(kinds));
        }
        Step step;
        if (present[0] == "command") {
            const json::Object object(value, path, keys::Of("commandStep"), "a command step");
            step.action = ReadCommand(object);
            step.note = ReadNote(object);
        } else if (present[0] == "ctrl") {
            const json::Object object(value, path, keys::Of("ctrlStep"), "a ctrl step");
            step.action = moduleSteps.ReadCtrl(object);
            step.note = ReadNote(object);
        } else if (present[0] == "axes") {
            const json::Object object(value, path, keys::Of("axesStep"), "an axes step");
            step.action = moduleSteps.ReadAxes(object);
            step.note = ReadNote(object);
        } else if (present[0] == "automatic") {
            const json::Object object(value, path, keys::Of("automaticStep"), "an automatic step");
            step.action = moduleSteps.ReadAutomatic(object);
            step.note = ReadNote(object);
        } else if (present[0] == "fault") {
            step.action = ReadFault(value, path, step.note);
        } else {
            const json::Object object(value, path, keys::Of("waitStep"), "a wait step");
            step.action = WaitStep{json::Duration(object, "wait_ms", 0)};
            step.note = ReadNote(object);
        }
        return step;
    }

    static std::string ReadNote(const json::Object& object) {
        const Json* note = object.Find("note");
        return note ? json::String(*note, object.PathOf("note")) : "";
    }

    CommandStep ReadCommand(const json::Object& object) const {
        CommandStep command;
        command.code = ReadCode(object.Get("command"), object.PathOf("command"), command.name);
        if (const Json* param = object.Find("param")) {
            command.param = static_cast<std::uint16_t>(json::Integer(*param, object.PathOf("param"), 0, 0xFFFF));
        }
        if (const Json* data = object.Find("data")) command.data = ReadDword(*data, object.PathOf("data"));
        command.timeoutMs = json::Duration(object, "timeout_ms", command.timeoutMs);
        command.endTimeoutMs = json::Duration(object, "end_timeout_ms", command.endTimeoutMs);
        if (const Json* expect = object.Find("expect")) command.expect = ReadExpectation(*expect, object.PathOf("expect"));
        return command;
    }

    static FaultStep ReadFault(const Json& value, const std::string& path, std::string& note) {
        static const std::vector<std::pair<std::string, FaultKind>> faults = {{"power_cycle", FaultKind::kPowerCycle},
                                                                              {"freeze_link", FaultKind::kFreezeLink},
                                                                              {"thaw_link", FaultKind::kThawLink},
                                                                              {"zero_link", FaultKind::kZeroLink},
                                                                              {"system_error", FaultKind::kSystemError},
                                                                              {"set_input", FaultKind::kSetInput}};
        static const std::vector<std::pair<std::string, LinkSide>> sides = {
            {"to_pac", LinkSide::kToPac}, {"from_pac", LinkSide::kFromPac}, {"both", LinkSide::kBoth}};
        const std::string faultPath = json::Child(path, "fault");
        const std::string name = json::String(value.at("fault"), faultPath);
        const auto fault = std::find_if(faults.begin(), faults.end(), [&](const auto& f) { return f.first == name; });
        if (fault == faults.end()) {
            json::Refuse(faultPath, "unknown fault " + Quoted(name) +
                                        " (a fault is \"power_cycle\", \"freeze_link\", \"thaw_link\", \"zero_link\", "
                                        "\"system_error\" or \"set_input\")");
        }
        FaultStep step;
        step.kind = fault->second;
        if (step.kind == FaultKind::kPowerCycle) {
            const json::Object object(value, path, keys::Of("powerCycleStep"), "a power_cycle step");
            note = ReadNote(object);
            return step;
        }
        if (step.kind == FaultKind::kSystemError) {
            // 5.2.4.15: 1..99 CPU errors, 100..499 hardware, 500..999 errors of the ONLINE / AUTOMATIC mode.
            const json::Object object(value, path, keys::Of("systemErrorStep"), "a system_error step");
            note = ReadNote(object);
            step.number = static_cast<int>(json::Integer(object.Get("number"), object.PathOf("number"), 1, 999));
            return step;
        }
        if (step.kind == FaultKind::kSetInput) {
            const json::Object object(value, path, keys::Of("setInputStep"), "a set_input step");
            note = ReadNote(object);
            step.number = static_cast<int>(
                json::Integer(object.Get("input"), object.PathOf("input"), 1, pac::sim::ElementCounts{}.inputs));
            step.value = json::Bool(object.Get("value"), object.PathOf("value"));
            return step;
        }
        const json::Object object(value, path, keys::Of("linkFaultStep"), "a link fault step");
        note = ReadNote(object);
        if (const Json* link = object.Find("link")) {
            const std::string side = json::String(*link, object.PathOf("link"));
            const auto it = std::find_if(sides.begin(), sides.end(), [&](const auto& s) { return s.first == side; });
            if (it == sides.end()) {
                json::Refuse(object.PathOf("link"),
                             "unknown link " + Quoted(side) + " (a link is \"to_pac\", \"from_pac\" or \"both\")");
            }
            step.link = it->second;
        }
        return step;
    }

    const GvlNames& names_;
};

bool EndsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

Scenario ScenarioLoader::FromText(const std::string& jsonText) const {
    return Reader(names_).ReadScenario(json::Parse(jsonText));
}

Scenario ScenarioLoader::FromFile(const std::string& path) const {
    std::string lower = path;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (EndsWith(lower, ".yaml") || EndsWith(lower, ".yml")) {
        throw ScenarioError("", "YAML is not supported: write the scenario as JSON (docs/scenario.md)");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ScenarioError("", "cannot read the file");
    std::ostringstream text;
    text << in.rdbuf();
    Scenario scenario = FromText(text.str());
    if (scenario.name.empty()) {
        const auto slash = path.find_last_of('/');
        scenario.name = path.substr(slash == std::string::npos ? 0 : slash + 1);
    }
    return scenario;
}

}  // namespace pac::scenario
