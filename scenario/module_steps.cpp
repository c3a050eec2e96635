#include "module_steps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>

#include "pac/enum_names.hpp"
#include "scenario_keys.hpp"

namespace pac::scenario {

namespace {

using json::Json;

using json::Quoted;

// One of `names`, refused with the list otherwise.
std::string Name(const Json& value, const std::string& path, const pac::EnumNames& names, const char* what) {
    const std::string text = json::String(value, path);
    if (!names.Contains(text)) {
        json::Refuse(path, "unknown " + std::string(what) + " " + Quoted(text) + " (one of " + json::ListKeys(names.All()) + ")");
    }
    return text;
}

// An MC_ block an axes step can run with "mc_blocks" (McCommandNames), refused with the list otherwise.
std::string McName(const Json& value, const std::string& path) {
    const std::string text = json::String(value, path);
    const auto& names = McCommandNames();
    if (std::find(names.begin(), names.end(), text) == names.end()) {
        json::Refuse(path, "unknown MC_ block " + Quoted(text) + " (one of " + json::ListKeys(names) + ")");
    }
    return text;
}

// A REAL: any finite number a REAL holds.
double RealValue(const Json& value, const std::string& path) {
    const double number = json::Number(value, path);
    if (!(std::fabs(number) <= 3.4028234663852886e38)) {
        json::Refuse(path, "out of range: " + value.dump() + " does not fit a REAL");
    }
    return number;
}

// The non-empty array `step.key` of a step on the modules, each element read by `read`, no module (`numberKey`,
// taken by `numberOf`) twice; `what` words the refusals.
struct ModuleListWords {
    const char* stepKind;  // "an axes step"
    const char* needs;     // "axis modules"
    const char* items;     // "axis jobs"
    const char* item;      // "axis"
    const char* twice;     // said after "appears twice in this step"
};

template <class Item, class Read, class NumberOf>
std::vector<Item> ReadModuleList(const json::Object& step, const char* key, const char* numberKey, int modules,
                                 const ModuleListWords& what, Read read, NumberOf numberOf) {
    const Json& list = step.Get(key);
    const std::string path = step.PathOf(key);
    if (modules == 0) {
        json::Refuse(path, std::string(what.stepKind) + " needs " + what.needs +
                               ": set \"modules\": {\"ctrl\": true, \"axes\": 1..8}");
    }
    if (!list.is_array()) json::RefuseType(path, std::string("an array of ") + what.items, list);
    if (list.empty()) json::Refuse(path, std::string("out of range: ") + what.stepKind + " needs at least one " + what.item);
    std::vector<Item> items;
    std::set<int> seen;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string itemPath = json::Element(path, i);
        items.push_back(read(list[i], itemPath));
        const int number = numberOf(items.back());
        if (!seen.insert(number).second) {
            json::Refuse(json::Child(itemPath, numberKey),
                         std::string(what.item) + " " + std::to_string(number) + " appears twice in this step" + what.twice);
        }
    }
    return items;
}

}  // namespace

CtrlStep ModuleStepReader::ReadCtrl(const json::Object& step) const {
    if (!modules_.ctrl) {
        json::Refuse(step.PathOf("ctrl"), "a ctrl step needs the CTRL interface: set \"modules\": {\"ctrl\": true}");
    }
    CtrlStep ctrl;
    ctrl.request = Name(step.Get("ctrl"), step.PathOf("ctrl"), pac::EnumNames(E_PAC_CTRLREQUEST__NAMES), "request");
    if (const Json* integer = step.Find("integer_mode")) ctrl.integerMode = json::Bool(*integer, step.PathOf("integer_mode"));
    ctrl.timeoutMs = json::Duration(step, "timeout_ms", ctrl.timeoutMs);
    if (const Json* value = step.Find("expect")) {
        const std::string path = step.PathOf("expect");
        const json::Object expect(*value, path, keys::Of("ctrlExpectation"), "a ctrl expectation");
        if (const Json* done = expect.Find("done")) ctrl.expect.done = json::Bool(*done, expect.PathOf("done"));
        if (const Json* error = expect.Find("error")) ctrl.expect.error = json::Bool(*error, expect.PathOf("error"));
        if (const Json* id = expect.Find("error_id")) ctrl.expect.errorId = readErrorId_(*id, expect.PathOf("error_id"));
        if (ctrl.expect.done.value_or(false) && ctrl.expect.error.value_or(false)) {
            json::Refuse(path, "contradiction: done and error cannot both be true (FB_PAC_Ctrl's outputs are exclusive)");
        }
    }
    return ctrl;
}

AxesStep ModuleStepReader::ReadAxes(const json::Object& step) const {
    AxesStep axes;
    axes.jobs = ReadModuleList<AxisJob>(
        step, "axes", "axis", modules_.axes,
        {"an axes step", "axis modules", "axis jobs", "axis", " (one FB_PAC_Axis per axis)"},
        [this](const Json& value, const std::string& path) { return ReadJob(value, path); },
        [](const AxisJob& job) { return job.axis; });
    return axes;
}

AxisJob ModuleStepReader::ReadJob(const Json& value, const std::string& path) const {
    const json::Object object(value, path, keys::Of("axisJob"), "an axis job");
    AxisJob job;
    job.axis = static_cast<int>(json::Integer(object.Get("axis"), object.PathOf("axis"), 1, modules_.axes));
    if (const Json* enable = object.Find("enable")) job.enable = json::Bool(*enable, object.PathOf("enable"));
    if (const Json* command = object.Find("command")) {
        job.command = modules_.mcBlocks ? McName(*command, object.PathOf("command"))
                                        : Name(*command, object.PathOf("command"),
                                               pac::EnumNames(E_PAC_AXISCOMMAND__NAMES), "axis command");
    }
    if (const Json* reset = object.Find("reset_error")) {
        job.resetError = json::Bool(*reset, object.PathOf("reset_error"));
        if (job.resetError && job.HasJob()) {
            json::Refuse(object.PathOf("reset_error"), "contradiction: an axis has a command or resets its error, not both in one step");
        }
    }
    if (!job.enable && !job.HasJob() && !job.resetError) {
        json::Refuse(path, "missing key: an axis job needs \"enable\", \"command\" or \"reset_error\"");
    }
    // The FB's own input checks (Velocity 1..1000, Acceleration not 0, a finite Position) are the
    // FB's to show: a scenario may send what the FB must refuse, within the pins' types.
    if (const Json* position = object.Find("position")) job.position = RealValue(*position, object.PathOf("position"));
    if (const Json* v = object.Find("velocity")) job.velocity = static_cast<int>(json::Integer(*v, object.PathOf("velocity"), 0, 65535));
    if (const Json* a = object.Find("acceleration")) {
        job.acceleration = static_cast<int>(json::Integer(*a, object.PathOf("acceleration"), 0, 65535));
    }
    if (const Json* c = object.Find("condition")) {
        if (modules_.mcBlocks) json::Refuse(object.PathOf("condition"), "the MC_ blocks have no G123 condition");
        job.condition = Name(*c, object.PathOf("condition"), pac::EnumNames(E_PAC_MOVECONDITION__NAMES), "condition");
    }
    job.timeoutMs = json::Duration(object, "timeout_ms", job.timeoutMs);
    job.maxMs = json::Duration(object, "max_ms", job.maxMs);
    if (const Json* expect = object.Find("expect")) job.expect = ReadAxisExpectation(*expect, object.PathOf("expect"));
    return job;
}

AutomaticStep ModuleStepReader::ReadAutomatic(const json::Object& step) const {
    AutomaticStep automatic;
    automatic.modules = ReadModuleList<AutomaticValues>(
        step, "automatic", "module", modules_.axes, {"an automatic step", "modules", "module values", "module", ""},
        [this](const Json& value, const std::string& path) { return ReadAutomaticValues(value, path); },
        [](const AutomaticValues& values) { return values.module; });
    automatic.maxMs = json::Duration(step, "max_ms", automatic.maxMs);
    return automatic;
}

AutomaticValues ModuleStepReader::ReadAutomaticValues(const Json& value, const std::string& path) const {
    const json::Object object(value, path, keys::Of("automaticModule"), "the values of a module");
    AutomaticValues values;
    values.module = static_cast<int>(json::Integer(object.Get("module"), object.PathOf("module"), 1, modules_.axes));
    auto read = [](const json::Object& from, AutomaticExpectation& target) {
        if (const Json* v = from.Find("flag_word")) {
            target.flagWord = static_cast<std::uint16_t>(json::Integer(*v, from.PathOf("flag_word"), 0, 65535));
        }
        if (const Json* v = from.Find("n")) {
            target.n = static_cast<std::int32_t>(json::Integer(*v, from.PathOf("n"), INT32_MIN, INT32_MAX));
        }
        if (const Json* v = from.Find("r")) target.r = RealValue(*v, from.PathOf("r"));
    };
    AutomaticExpectation sent;
    read(object, sent);
    values.flagWord = sent.flagWord;
    values.n = sent.n;
    values.r = sent.r;
    if (const Json* expect = object.Find("expect")) {
        const std::string expectPath = object.PathOf("expect");
        const json::Object e(*expect, expectPath, keys::Of("automaticExpectation"), "an automatic expectation");
        read(e, values.expect);
        if (const Json* v = e.Find("r_tolerance")) {
            values.expect.rTolerance = json::Number(*v, e.PathOf("r_tolerance"));
            if (!(values.expect.rTolerance >= 0.0)) json::Refuse(e.PathOf("r_tolerance"), "out of range: must be >= 0");
        }
    }
    if (!values.flagWord && !values.n && !values.r && values.expect.Empty()) {
        json::Refuse(path, "missing key: a module needs \"flag_word\", \"n\", \"r\" or \"expect\"");
    }
    return values;
}

AxisExpectation ModuleStepReader::ReadAxisExpectation(const Json& value, const std::string& path) const {
    const json::Object expect(value, path, keys::Of("axisExpectation"), "an axis expectation");
    AxisExpectation result;
    if (const Json* v = expect.Find("done")) result.done = json::Bool(*v, expect.PathOf("done"));
    if (const Json* v = expect.Find("error")) result.error = json::Bool(*v, expect.PathOf("error"));
    if (const Json* v = expect.Find("aborted")) result.aborted = json::Bool(*v, expect.PathOf("aborted"));
    if (const Json* v = expect.Find("error_id")) result.errorId = readErrorId_(*v, expect.PathOf("error_id"));
    if (const Json* v = expect.Find("referenced")) result.referenced = json::Bool(*v, expect.PathOf("referenced"));
    if (const Json* v = expect.Find("position")) result.position = json::Number(*v, expect.PathOf("position"));
    if (const Json* v = expect.Find("position_tolerance")) {
        result.positionTolerance = json::Number(*v, expect.PathOf("position_tolerance"));
        if (!(result.positionTolerance >= 0.0)) json::Refuse(expect.PathOf("position_tolerance"), "out of range: must be >= 0");
    }
    const int finals = result.done.value_or(false) + result.error.value_or(false) + result.aborted.value_or(false);
    if (finals > 1) {
        json::Refuse(path, "contradiction: at most one of done, error and aborted can be true (FB_PAC_Axis's outputs are exclusive)");
    }
    return result;
}

}  // namespace pac::scenario
