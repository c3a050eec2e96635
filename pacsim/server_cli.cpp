#include "server_cli.hpp"

#include <arpa/inet.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <memory>

#include "controller_setup.hpp"
#include "cycle_stats.hpp"
#include "live_view_server.hpp"
#include "modbus_gateway.hpp"
#include "register_map.hpp"
#include "scenario_error.hpp"
#include "pty_serial_bridge.hpp"
#include "serial_endpoint.hpp"
#include "tcp_serial_bridge.hpp"
#include "sim_config.hpp"
#include "simulated_controller.hpp"
#include "wall_clock.hpp"

namespace pac::pacsim {

namespace {

constexpr const char* kProgram = "pac-sim";
// The longest the loop sleeps, so --seconds ends on time whatever the controllers' cycles.
constexpr std::chrono::milliseconds kMaxSleep{50};

void Usage(std::ostream& out) {
    out << "usage: " << kProgram << " [--port N] [--http N] [--address IPV4] [--seconds S] [--stats] CONFIG.json\n"
        << "       " << kProgram << " --check CONFIG.json | --print-map CONFIG.json | --version | --help\n"
        << "  Runs the simulated PA-CONTROLs of CONFIG.json in real time, each at its own controller cycle, and\n"
        << "  serves their Profibus modules as Modbus TCP registers, as a Profibus-to-Modbus gateway would\n"
        << "  (docs/virtual_commissioning.md). Ctrl-C (SIGINT) or SIGTERM stops it.\n"
        << "  --port N        the port of every controller that names none (default: the file's \"port\", else "
        << kDefaultPort << ";\n"
        << "                  0: a free port, printed at start)\n"
        << "  --http N        serve the live view and the fault endpoint on HTTP port N (0: a free port)\n"
        << "  --address IPV4  the address to listen on (default 127.0.0.1: this machine only)\n"
        << "  --seconds S     stop after S seconds\n"
        << "  --stats         at the stop, also print how late the controllers' cycles ran and the CPU used\n"
        << "  --check         only check the configuration\n"
        << "  --print-map     print each controller's register map (Markdown) and exit\n"
        << "  --version       print the library's version (st/library.json) and exit\n"
        << "exit codes: 0 stopped by a signal or --seconds, 2 invalid configuration or usage, 3 cannot listen\n";
}

struct Options {
    std::string config;
    int port = -1;
    int http = -1;  // the live view's port; -1: none
    std::string address = "127.0.0.1";
    double seconds = 0.0;
    bool check = false;
    bool printMap = false;
    bool stats = false;
};

std::string Modules(const RegisterMap& map) {
    std::string text;
    for (const ModuleRegisters& module : map.Modules()) text += (text.empty() ? "" : ", ") + module.name;
    return text;
}

// Runs every controller's cycles due now (the lateness of the first into `stats`); the time of the next one due.
std::chrono::nanoseconds CatchUp(std::vector<std::unique_ptr<SimulatedController>>& controllers, const WallClock& clock,
                                 CycleStats& stats) {
    auto next = std::chrono::nanoseconds::max();
    for (auto& controller : controllers) {
        const auto lock = controller->Lock();
        const auto now = clock.Now();
        if (controller->NextCycleTime() <= now) stats.Add(now - controller->NextCycleTime());
        controller->CatchUp(now);
        next = std::min(next, controller->NextCycleTime());
    }
    return next;
}

// Runs the controllers' cycles on time until SIGINT or SIGTERM (its number) or `seconds` (0; 0: no limit).
int RunUntilStopped(std::vector<std::unique_ptr<SimulatedController>>& controllers, const WallClock& clock,
                    double seconds, CycleStats& stats) {
    sigset_t stop;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    const auto end = seconds > 0.0 ? std::chrono::nanoseconds(static_cast<std::int64_t>(seconds * 1e9))
                                   : std::chrono::nanoseconds::max();
    while (true) {
        const auto next = CatchUp(controllers, clock, stats);
        const auto now = clock.Now();
        if (now >= end) return 0;
        const auto wait = std::clamp(std::min(next, end) - now, std::chrono::nanoseconds(0),
                                     std::chrono::nanoseconds(kMaxSleep));
        const timespec timeout{static_cast<std::time_t>(wait.count() / 1000000000),
                               static_cast<long>(wait.count() % 1000000000)};
        const int signal = sigtimedwait(&stop, nullptr, &timeout);
        if (signal > 0) return signal;
    }
}

int Run(const Options& options, const SimConfig& config, std::ostream& out) {
    std::vector<std::unique_ptr<SimulatedController>> controllers;
    for (const ControllerSpec& spec : config.controllers) controllers.push_back(std::make_unique<SimulatedController>(spec));
    const WallClock clock;  // time 0: every controller powers on now
    ModbusGateway gateway(controllers, clock, options.address);
    std::vector<std::unique_ptr<SerialEndpoint>> bridges(controllers.size());
    for (std::size_t i = 0; i < controllers.size(); ++i) {
        if (const auto& rs232 = controllers[i]->Spec().rs232) {
            if (rs232->pty) {
                bridges[i] = std::make_unique<PtySerialBridge>(*controllers[i], clock, rs232->link);
            } else {
                bridges[i] = std::make_unique<TcpSerialBridge>(*controllers[i], clock, options.address, rs232->port);
            }
        }
    }
    std::unique_ptr<LiveViewServer> view;
    if (options.http >= 0) view = std::make_unique<LiveViewServer>(controllers, clock, options.address, options.http);
    gateway.Start();
    if (view) view->Start();
    for (auto& bridge : bridges) {
        if (bridge) bridge->Start();
    }
    for (std::size_t i = 0; i < controllers.size(); ++i) {
        const ControllerSpec& spec = controllers[i]->Spec();
        const RegisterMap& map = controllers[i]->Map();
        out << spec.name << ": Modbus TCP " << gateway.Address() << ":" << gateway.PortOf(i) << " unit id " << spec.unitId
            << ": " << Modules(map) << " (registers 0.." << map.Registers() - 1 << ", from PAC also holding registers "
            << kFromPacHoldingBase << ".." << kFromPacHoldingBase + map.Registers() - 1 << ")\n";
        if (bridges[i]) {
            out << spec.name << ": RS232 (COM1) " << bridges[i]->Where() << ", " << spec.rs232->baud << " baud\n";
        }
    }
    if (view) out << kProgram << ": live view http://" << options.address << ":" << view->Port() << "/\n";
    out << kProgram << ": running; Ctrl-C stops" << std::endl;

    auto stats = std::make_unique<CycleStats>();  // 800 kB of buckets: not on the stack
    const int signal = RunUntilStopped(controllers, clock, options.seconds, *stats);
    if (view) view->Stop();
    gateway.Stop();
    for (auto& bridge : bridges) {
        if (bridge) bridge->Stop();
    }
    const GatewayCounters counters = gateway.Counters();
    out << kProgram << ": stopped" << (signal > 0 ? " by a signal" : "") << " after " << clock.Now().count() / 1000000
        << " ms: " << counters.connections << " connections (" << counters.connectionsRefused << " refused, "
        << counters.dropped << " dropped), " << counters.requests << " requests, " << counters.exceptions
        << " exceptions" << std::endl;
    if (options.stats) {
        out << kProgram << ": ";
        stats->Print(out, clock.Now());
        out << std::endl;
    }
    return kExitOk;
}

}  // namespace

int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    Options options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        auto value = [&]() -> const std::string* { return i + 1 < args.size() ? &args[++i] : nullptr; };
        if (arg == "-h" || arg == "--help") {
            Usage(out);
            return kExitOk;
        }
        if (arg == "--version") {
            out << kProgram << " (" << PAC_LIBRARY_TITLE << ") " << PAC_LIBRARY_VERSION << "\n";
            return kExitOk;
        }
        if (arg == "--check") {
            options.check = true;
        } else if (arg == "--stats") {
            options.stats = true;
        } else if (arg == "--print-map") {
            options.printMap = true;
        } else if (arg == "--port" || arg == "--http" || arg == "--address" || arg == "--seconds") {
            const std::string* v = value();
            char* rest = nullptr;
            const double number = v ? std::strtod(v->c_str(), &rest) : 0.0;
            const bool isNumber = v && !v->empty() && *rest == '\0';
            in_addr ip{};
            if (arg == "--address" && v && inet_pton(AF_INET, v->c_str(), &ip) == 1) {
                options.address = *v;
            } else if (arg == "--http" && isNumber && number >= 0 && number <= 65535 && number == static_cast<int>(number)) {
                options.http = static_cast<int>(number);
            } else if (arg == "--port" && isNumber && number >= 0 && number <= 65535 && number == static_cast<int>(number)) {
                options.port = static_cast<int>(number);
            } else if (arg == "--seconds" && isNumber && number > 0) {
                options.seconds = number;
            } else {
                const char* needs = arg == "--address" ? "an IPv4 address"
                                    : arg == "--port" || arg == "--http" ? "a port 0..65535"
                                                       : "a number of seconds above 0";
                err << kProgram << ": " << arg << " needs " << needs << "\n";
                return kExitInvalid;
            }
        } else if (!arg.empty() && arg[0] == '-') {
            err << kProgram << ": unknown option " << arg << "\n";
            Usage(err);
            return kExitInvalid;
        } else if (options.config.empty()) {
            options.config = arg;
        } else {
            err << kProgram << ": one configuration file only (" << options.config << ", " << arg << ")\n";
            return kExitInvalid;
        }
    }
    if (options.config.empty()) {
        Usage(err);
        return kExitInvalid;
    }
    SimConfig config;
    try {
        config = SimConfigLoader::FromFile(options.config, options.port);
        // The settings only the simulator can judge (a system parameter's limits) are refused by making them.
        for (std::size_t i = 0; i < config.controllers.size(); ++i) {
            try {
                SimulatedController check(config.controllers[i]);
            } catch (const pac::scenario::ScenarioError& e) {
                throw InController(e, i);
            }
        }
    } catch (const pac::scenario::ScenarioError& e) {
        err << kProgram << ": " << options.config << ": " << e.what() << "\n";
        return kExitInvalid;
    }
    if (options.check) {
        out << options.config << ": " << config.controllers.size() << " controller(s), valid\n";
        return kExitOk;
    }
    if (options.printMap) {
        for (const ControllerSpec& spec : config.controllers) {
            out << spec.name << " (port " << spec.port << ", unit id " << spec.unitId << "):\n\n";
            RegisterMap(pac::scenario::Layout(spec.modules)).Print(out);
            out << "\n";
        }
        return kExitOk;
    }
    try {
        return Run(options, config, out);
    } catch (const std::exception& e) {
        err << kProgram << ": " << e.what() << "\n";
        return kExitFailed;
    }
}

}  // namespace pac::pacsim
