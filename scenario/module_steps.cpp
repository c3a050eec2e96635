#include "module_steps.hpp"

#include <cmath>
#include <set>

#include "pac/enum_names.hpp"

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
        const json::Object expect(*value, path, {"done", "error", "error_id"}, "a ctrl expectation");
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
    const Json& list = step.Get("axes");
    const std::string path = step.PathOf("axes");
    if (modules_.axes == 0) {
        json::Refuse(path, "an axes step needs axis modules: set \"modules\": {\"ctrl\": true, \"axes\": 1..8}");
    }
    if (!list.is_array()) json::RefuseType(path, "an array of axis jobs", list);
    if (list.empty()) json::Refuse(path, "out of range: an axes step needs at least one axis");
    AxesStep axes;
    std::set<int> seen;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string jobPath = json::Element(path, i);
        axes.jobs.push_back(ReadJob(list[i], jobPath));
        if (!seen.insert(axes.jobs.back().axis).second) {
            json::Refuse(json::Child(jobPath, "axis"), "axis " + std::to_string(axes.jobs.back().axis) +
                                                           " appears twice in this step (one FB_PAC_Axis per axis)");
        }
    }
    return axes;
}

AxisJob ModuleStepReader::ReadJob(const Json& value, const std::string& path) const {
    const json::Object object(value, path,
                              {"axis", "enable", "command", "reset_error", "position", "velocity", "acceleration",
                               "condition", "timeout_ms", "max_ms", "expect"},
                              "an axis job");
    AxisJob job;
    job.axis = static_cast<int>(json::Integer(object.Get("axis"), object.PathOf("axis"), 1, modules_.axes));
    if (const Json* enable = object.Find("enable")) job.enable = json::Bool(*enable, object.PathOf("enable"));
    if (const Json* command = object.Find("command")) {
        job.command = Name(*command, object.PathOf("command"), pac::EnumNames(E_PAC_AXISCOMMAND__NAMES), "axis command");
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
    if (const Json* position = object.Find("position")) {
        job.position = json::Number(*position, object.PathOf("position"));
        if (!(std::fabs(job.position) <= 3.4028234663852886e38)) {
            json::Refuse(object.PathOf("position"), "out of range: " + position->dump() + " does not fit a REAL");
        }
    }
    if (const Json* v = object.Find("velocity")) job.velocity = static_cast<int>(json::Integer(*v, object.PathOf("velocity"), 0, 65535));
    if (const Json* a = object.Find("acceleration")) {
        job.acceleration = static_cast<int>(json::Integer(*a, object.PathOf("acceleration"), 0, 65535));
    }
    if (const Json* c = object.Find("condition")) {
        job.condition = Name(*c, object.PathOf("condition"), pac::EnumNames(E_PAC_MOVECONDITION__NAMES), "condition");
    }
    job.timeoutMs = json::Duration(object, "timeout_ms", job.timeoutMs);
    job.maxMs = json::Duration(object, "max_ms", job.maxMs);
    if (const Json* expect = object.Find("expect")) job.expect = ReadAxisExpectation(*expect, object.PathOf("expect"));
    return job;
}

AxisExpectation ModuleStepReader::ReadAxisExpectation(const Json& value, const std::string& path) const {
    const json::Object expect(value, path,
                              {"done", "error", "aborted", "error_id", "referenced", "position", "position_tolerance"},
                              "an axis expectation");
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
