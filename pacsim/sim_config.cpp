#include "sim_config.hpp"

#include <fstream>
#include <set>
#include <sstream>
#include <utility>

#include "gvl_names.hpp"
#include "json_fields.hpp"
#include "scenario_error.hpp"
#include "scenario_loader.hpp"

namespace pac::pacsim {

namespace {

namespace json = pac::scenario::json;
using json::Json;
using pac::scenario::ScenarioError;

const std::vector<std::string> kTopKeys = {"$schema", "name", "description", "port", "controllers"};
const std::vector<std::string> kControllerKeys = {"name", "port", "unit_id", "rs232", "timing", "modules", "controller"};
const std::vector<std::string> kRs232Keys = {"port", "pty", "link", "baud"};
// The keys of a controller entry that are a scenario's own, read by the scenario loader.
const std::vector<std::string> kScenarioParts = {"timing", "modules", "controller"};

// The scenario loader reads the parts as a scenario of one wait step; its paths ($.controller...) are
// rewritten to the entry's ($.controllers[2].controller...).
void ReadScenarioParts(const Json& entry, std::size_t index, const pac::scenario::GvlNames& names, ControllerSpec& spec) {
    Json scenario = Json::object();
    for (const std::string& key : kScenarioParts) {
        if (entry.contains(key)) scenario[key] = entry.at(key);
    }
    scenario["steps"] = Json::array({Json{{"wait_ms", 1}}});
    try {
        const pac::scenario::Scenario parsed = pac::scenario::ScenarioLoader(names).FromText(scenario.dump());
        spec.timing = parsed.timing;
        spec.modules = parsed.modules;
        spec.controller = parsed.controller;
    } catch (const ScenarioError& e) {
        throw InController(e, index);
    }
}

ControllerSpec ReadController(const Json& value, const std::string& path, std::size_t index, int defaultPort,
                              const pac::scenario::GvlNames& names) {
    const json::Object entry(value, path, kControllerKeys, "a controller");
    ControllerSpec spec;
    spec.name = entry.Find("name") ? json::String(entry.Get("name"), entry.PathOf("name")) : "pac" + std::to_string(index + 1);
    if (spec.name.empty()) json::Refuse(entry.PathOf("name"), "out of range: a name cannot be empty");
    spec.port = entry.Find("port") ? static_cast<int>(json::Integer(entry.Get("port"), entry.PathOf("port"), 0, 65535))
                                   : defaultPort;
    spec.unitId = entry.Find("unit_id")
                      ? static_cast<int>(json::Integer(entry.Get("unit_id"), entry.PathOf("unit_id"), 1, 247))
                      : static_cast<int>(index) + 1;
    if (const Json* rs232 = entry.Find("rs232")) {
        const json::Object line(*rs232, entry.PathOf("rs232"), kRs232Keys, "the RS232 port");
        Rs232Spec serial;
        if (const Json* pty = line.Find("pty")) {
            serial.pty = json::Bool(*pty, line.PathOf("pty"));
            if (!serial.pty) json::Refuse(line.PathOf("pty"), "out of range: leave \"pty\" out for a TCP port");
            if (line.Has("port")) json::Refuse(line.Path(), "contradiction: a TCP \"port\" or a \"pty\", not both");
            if (const Json* link = line.Find("link")) serial.link = json::String(*link, line.PathOf("link"));
        } else {
            if (line.Has("link")) json::Refuse(line.PathOf("link"), "contradiction: a link names a pseudo-terminal: set \"pty\"");
            serial.port = static_cast<int>(json::Integer(line.Get("port"), line.PathOf("port"), 0, 65535));
        }
        if (const Json* baud = line.Find("baud")) {
            serial.baud = static_cast<int>(json::Integer(*baud, line.PathOf("baud"), 300, 115200));
        }
        spec.rs232 = serial;
    }
    ReadScenarioParts(value, index, names, spec);
    return spec;
}

}  // namespace

ScenarioError InController(const ScenarioError& error, std::size_t index) {
    const std::string path = json::Element("$.controllers", index);
    const std::string& inner = error.Path();
    return ScenarioError(inner.rfind("$", 0) == 0 ? path + inner.substr(1) : path, error.Reason());
}

SimConfig SimConfigLoader::FromText(const std::string& jsonText, int portOverride) {
    const Json document = json::Parse(jsonText);
    const json::Object top(document, "$", kTopKeys, "a pac-sim configuration");
    if (const Json* schema = top.Find("$schema")) json::String(*schema, top.PathOf("$schema"));  // for editors
    SimConfig config;
    if (const Json* name = top.Find("name")) config.name = json::String(*name, top.PathOf("name"));
    if (const Json* text = top.Find("description")) config.description = json::String(*text, top.PathOf("description"));
    int port = kDefaultPort;
    if (const Json* p = top.Find("port")) port = static_cast<int>(json::Integer(*p, top.PathOf("port"), 0, 65535));
    if (portOverride >= 0) port = portOverride;
    const Json& controllers = top.Get("controllers");
    const std::string listPath = top.PathOf("controllers");
    if (!controllers.is_array()) json::RefuseType(listPath, "an array of controllers", controllers);
    if (controllers.empty()) json::Refuse(listPath, "out of range: pac-sim needs at least one controller");
    const pac::scenario::GvlNames gvl;  // the PAC_STATUS_ names a controller's operating status may use
    std::set<std::pair<int, int>> addresses;
    std::set<int> serialPorts;
    std::set<std::string> names;
    for (std::size_t i = 0; i < controllers.size(); ++i) {
        const std::string path = json::Element(listPath, i);
        ControllerSpec spec = ReadController(controllers[i], path, i, port, gvl);
        if (!addresses.insert({spec.port, spec.unitId}).second) {
            json::Refuse(path, "contradiction: another controller has port " + std::to_string(spec.port) + " and unit id " +
                                   std::to_string(spec.unitId) + " (each needs a port or a unit id of its own)");
        }
        if (spec.rs232 && !spec.rs232->pty && spec.rs232->port != 0 &&
            (spec.rs232->port == spec.port || !serialPorts.insert(spec.rs232->port).second)) {
            json::Refuse(path + ".rs232.port", "contradiction: port " + std::to_string(spec.rs232->port) +
                                                   " is taken by Modbus or another RS232 port");
        }
        if (!names.insert(spec.name).second) {
            json::Refuse(path, "contradiction: another controller is named " + json::Quoted(spec.name));
        }
        config.controllers.push_back(std::move(spec));
    }
    return config;
}

SimConfig SimConfigLoader::FromFile(const std::string& path, int portOverride) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ScenarioError("", "cannot read the file");
    std::ostringstream text;
    text << in.rdbuf();
    return FromText(text.str(), portOverride);
}

}  // namespace pac::pacsim
