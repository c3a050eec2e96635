#include "diagram_reader.hpp"

#include <algorithm>

#include "scenario_keys.hpp"
#include "scenario_signals.hpp"

namespace pac::scenario {

namespace {

// Names of `known` signals, at least one.
std::vector<std::string> ReadSignals(const json::Json& list, const std::string& path, const std::vector<std::string>& known) {
    if (!list.is_array() || list.empty()) json::RefuseType(path, "an array of signal names", list);
    std::vector<std::string> names;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string elementPath = json::Element(path, i);
        const std::string name = json::String(list[i], elementPath);
        if (std::find(known.begin(), known.end(), name) == known.end()) {
            json::Refuse(elementPath, "unknown signal " + json::Quoted(name) +
                                          " (not among the signals this diagram shows: the scenario's modules record "
                                          "cmd.*, ctrl.*, axisK.*, docs/scenario.md)");
        }
        names.push_back(name);
    }
    return names;
}

}  // namespace

Diagram ReadDiagram(const json::Json& value, const std::string& path, std::size_t steps, const Modules& modules) {
    const json::Object object(value, path, keys::Of("diagram"), "a diagram");
    Diagram diagram;
    if (const json::Json* title = object.Find("title")) diagram.title = json::String(*title, object.PathOf("title"));
    diagram.lastStep = steps;
    if (const json::Json* range = object.Find("steps")) {
        const std::string rangePath = object.PathOf("steps");
        if (!range->is_array() || range->size() != 2) json::RefuseType(rangePath, "[first step, last step]", *range);
        const auto last = static_cast<std::int64_t>(steps);
        diagram.firstStep = static_cast<std::size_t>(json::Integer((*range)[0], json::Element(rangePath, 0), 1, last));
        diagram.lastStep = static_cast<std::size_t>(
            json::Integer((*range)[1], json::Element(rangePath, 1), static_cast<std::int64_t>(diagram.firstStep), last));
    }
    auto integer = [&object](const char* key, int max, int fallback) {
        const json::Json* v = object.Find(key);
        return v ? static_cast<int>(json::Integer(*v, object.PathOf(key), 0, max)) : fallback;
    };
    diagram.contextScans = integer("context_scans", 1000, diagram.contextScans);
    diagram.maxIdleScans = integer("max_idle_scans", 1000, diagram.maxIdleScans);
    diagram.hscale = integer("hscale", 10, diagram.hscale);
    if (diagram.hscale == 0) json::Refuse(object.PathOf("hscale"), "out of range: 0 is not in 1..10");
    const auto known = ScenarioSignals::Paths(modules);
    if (const json::Json* list = object.Find("signals")) diagram.signals = ReadSignals(*list, object.PathOf("signals"), known);
    if (const json::Json* list = object.Find("sampled")) {
        diagram.sampled = ReadSignals(*list, object.PathOf("sampled"), diagram.signals.empty() ? known : diagram.signals);
    }
    return diagram;
}

}  // namespace pac::scenario
