// pac-sim's configuration file (JSON, pacsim/pacsim.schema.json, docs/virtual_commissioning.md): where it
// listens and one or more simulated PA-CONTROLs, each with the "timing", "modules" and "controller" of a
// scenario file (docs/scenario.md), read by the scenario loader itself so the two formats cannot part.
// A refusal is a ScenarioError naming the JSONPath in this file ($.controllers[1].controller.inputs["99"]).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scenario.hpp"
#include "scenario_error.hpp"

namespace pac::pacsim {

// COM1 (manual chapter 3) as the raw byte stream of a TCP port, as ser2net carries a serial line, or on a
// pseudo-terminal, as pac_sim --serial has it.
struct Rs232Spec {
    bool pty = false;  // a pseudo-terminal instead of a TCP port
    int port = 0;      // the TCP port; 0: a free port chosen at start
    std::string link;  // pty: a symbolic link to the terminal's path to make, or empty
    int baud = 9600;   // the line's speed: the bytes take their time on the simulated wire
};

struct ControllerSpec {
    std::string name;  // printed at start; default "pac1", "pac2", ...
    int port = 0;      // the TCP port it is served on (0: any free port, shared by every controller with 0)
    int unitId = 1;    // its Modbus unit id on that port, 1..247
    pac::scenario::Timing timing;
    pac::scenario::Modules modules;
    pac::scenario::ControllerSetup controller;
    std::optional<Rs232Spec> rs232;
};

struct SimConfig {
    std::string name;
    std::string description;
    std::vector<ControllerSpec> controllers;
};

constexpr int kDefaultPort = 5020;

// A refusal of the scenario loader or the simulator ($.controller.inputs) as the path of controller `index`
// ($.controllers[2].controller.inputs).
pac::scenario::ScenarioError InController(const pac::scenario::ScenarioError& error, std::size_t index);

class SimConfigLoader {
public:
    // `portOverride` >= 0 replaces the top-level "port" (pac-sim --port).
    static SimConfig FromText(const std::string& jsonText, int portOverride = -1);
    // Also refuses a file that cannot be read.
    static SimConfig FromFile(const std::string& path, int portOverride = -1);
};

}  // namespace pac::pacsim
