// Benchmark (not a test) of pac-sim, printed as Markdown by `cmake --build build --target bench_pacsim_run`
// (and by the target bench): the Modbus TCP round trip on loopback, writing the CMD module (function code 16)
// and reading the reply (function code 4), against pac-sim and against pymodbus's own server as the anchor, both
// with one libmodbus client; and how late the cycles of 32 controllers with 8 axis modules each at a 1 ms
// controller cycle run, with the CPU pac-sim takes (pac-sim --stats); and the library over Modbus: the demo
// scenario's steps through pac-sim-plc at a 10 ms PLC cycle, the scans from each Execute edge to the end against
// the same steps in the process.
//   pacsim_bench --pac-sim PATH --config TWO_AXES.json --python VENV_PYTHON --anchor anchor_server.py
//                --plc PAC_SIM_PLC --demo-config DEMO_CONTROLLER.json --scenario DEMO.json
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>
#include <netinet/in.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include <modbus/modbus.h>

extern char** environ;

namespace {

constexpr int kWarmUp = 200;
constexpr int kRoundTrips = 5000;
constexpr int kScaleSeconds = 5;
constexpr int kControllers = 32;

// Manual 2.5.1 / 2.5.2 (CTRL: register 4) and 2.7.1 / 2.7.2 (axis k: registers 8 + 6 (k - 1) ..).
constexpr std::uint16_t kCtrlNoRequest = 0x0007;
constexpr std::uint16_t kCtrlStartOnline = 0x0010;
constexpr std::uint16_t kCtrlOnlineActive = 1U << 10;
constexpr std::uint16_t kAxisOn = 1U << 0;
constexpr std::uint16_t kAxisStart = 1U << 2;
constexpr std::uint16_t kAxisAbsolute = 1U << 6;
constexpr std::uint16_t kAxisActive = 1U << 7;

// A program of its own with its standard output on a pipe, read line by line; terminated and reaped at the end.
class Child {
public:
    // quiet: its standard error goes to /dev/null (pymodbus's deprecation notices).
    explicit Child(const std::vector<std::string>& args, bool quiet = false) {
        int pipeFds[2];
        if (pipe(pipeFds) != 0) throw std::runtime_error("pipe");
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, pipeFds[1], STDOUT_FILENO);
        posix_spawn_file_actions_addclose(&actions, pipeFds[0]);
        if (quiet) posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
        std::vector<char*> argv;
        for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
        argv.push_back(nullptr);
        if (posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ) != 0) {
            throw std::runtime_error("cannot start " + args[0]);
        }
        posix_spawn_file_actions_destroy(&actions);
        close(pipeFds[1]);
        out_ = fdopen(pipeFds[0], "r");
    }
    ~Child() {
        Stop(SIGKILL);
        if (out_ != nullptr) fclose(out_);
    }
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;

    // The next line of its output; empty at its end.
    std::string Line() {
        char buffer[4096];
        return std::fgets(buffer, sizeof buffer, out_) != nullptr ? std::string(buffer) : std::string();
    }
    // The first line that matches `pattern`, its first group.
    std::string Await(const std::string& pattern) {
        const std::regex re(pattern);
        for (std::string line = Line(); !line.empty(); line = Line()) {
            std::smatch match;
            if (std::regex_search(line, match, re)) return match.size() > 1 ? match[1].str() : line;
        }
        throw std::runtime_error("the child ended before printing " + pattern);
    }
    void Stop(int sig) {
        if (pid_ <= 0) return;
        kill(pid_, sig);
        int status = 0;
        waitpid(pid_, &status, 0);
        pid_ = -1;
    }

private:
    pid_t pid_ = -1;
    FILE* out_ = nullptr;
};

int FreePort() {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
        getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
        throw std::runtime_error("no free port");
    }
    close(fd);
    return ntohs(address.sin_port);
}

// Round trips in microseconds, sorted: write the 4 registers of the CMD module, read the 4 of its reply.
std::vector<double> RoundTrips(int port) {
    modbus_t* ctx = modbus_new_tcp("127.0.0.1", port);
    if (ctx == nullptr || modbus_connect(ctx) != 0) throw std::runtime_error("cannot connect to port " + std::to_string(port));
    modbus_set_slave(ctx, 1);
    std::vector<double> times;
    std::uint16_t cmd[4] = {0, 0, 1, 0x1907};
    std::uint16_t reply[4];
    for (int i = 0; i < kWarmUp + kRoundTrips; ++i) {
        cmd[3] ^= 0x8000;  // the SEND flag toggles: a new command each time
        const auto start = std::chrono::steady_clock::now();
        if (modbus_write_registers(ctx, 0, 4, cmd) != 4 || modbus_read_input_registers(ctx, 0, 4, reply) != 4) {
            throw std::runtime_error(std::string("Modbus request failed: ") + modbus_strerror(errno));
        }
        const auto end = std::chrono::steady_clock::now();
        if (i >= kWarmUp) times.push_back(std::chrono::duration<double, std::micro>(end - start).count());
    }
    modbus_close(ctx);
    modbus_free(ctx);
    std::sort(times.begin(), times.end());
    return times;
}

// Switches every controller on `port` (unit ids 1..kControllers) to ONLINE with its 8 axes on, then moves every
// axis between 0.0 and 100.0 (absolute, full speed; Start falls once ACTIVE shows the job taken, the next job
// starts once ACTIVE fell) until pac-sim ends; the moves started.
long DriveAllAxes(int port) {
    modbus_t* ctx = modbus_new_tcp("127.0.0.1", port);
    if (ctx == nullptr || modbus_connect(ctx) != 0) throw std::runtime_error("cannot connect to port " + std::to_string(port));
    constexpr int kRegisters = 8 + 6 * 8;
    struct Axis {
        bool start = false;
        bool high = false;  // the target: 100.0, else 0.0
    };
    std::vector<std::vector<Axis>> axes(kControllers, std::vector<Axis>(8));
    long moves = 0;
    std::uint16_t in[kRegisters];
    std::uint16_t out[kRegisters - 8];
    const auto writeAxes = [&](int unit) {
        for (int k = 0; k < 8; ++k) {
            const Axis& axis = axes[static_cast<std::size_t>(unit - 1)][static_cast<std::size_t>(k)];
            const std::uint16_t target = axis.high ? 0x42C8 : 0x0000;  // 100.0 or 0.0 as a REAL, high word
            const std::uint16_t module[6] = {0, static_cast<std::uint16_t>(kAxisOn | kAxisAbsolute | (axis.start ? kAxisStart : 0)),
                                             1000, 1000, target, 0};
            std::copy(module, module + 6, out + 6 * k);
        }
        return modbus_write_registers(ctx, 8, kRegisters - 8, out) == kRegisters - 8;
    };
    for (int unit = 1; unit <= kControllers; ++unit) {
        modbus_set_slave(ctx, unit);
        const std::uint16_t online = kCtrlNoRequest | kCtrlStartOnline;
        std::uint16_t status = 0;
        for (int tries = 0; tries < 1000 && !(status & kCtrlOnlineActive); ++tries) {
            if (modbus_write_register(ctx, 4, online) != 1 || modbus_read_input_registers(ctx, 4, 1, &status) != 1) {
                throw std::runtime_error(std::string("ONLINE: ") + modbus_strerror(errno));
            }
        }
        if (!(status & kCtrlOnlineActive)) throw std::runtime_error("a controller did not start ONLINE");
        if (modbus_write_register(ctx, 4, kCtrlNoRequest) != 1 || !writeAxes(unit)) {
            throw std::runtime_error(std::string("Axis ON: ") + modbus_strerror(errno));
        }
    }
    for (bool running = true; running;) {
        for (int unit = 1; unit <= kControllers && running; ++unit) {
            modbus_set_slave(ctx, unit);
            running = modbus_read_input_registers(ctx, 0, kRegisters, in) == kRegisters;
            for (int k = 0; k < 8 && running; ++k) {
                Axis& axis = axes[static_cast<std::size_t>(unit - 1)][static_cast<std::size_t>(k)];
                const bool active = in[8 + 6 * k + 1] & kAxisActive;
                if (axis.start && active) {
                    axis.start = false;
                } else if (!axis.start && !active) {
                    axis.start = true;
                    axis.high = !axis.high;
                    ++moves;
                }
            }
            running = running && writeAxes(unit);
        }
    }
    modbus_close(ctx);
    modbus_free(ctx);
    return moves;
}

double Quantile(const std::vector<double>& sorted, double q) {
    return sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(q * static_cast<double>(sorted.size())))];
}

void Row(const char* what, const std::vector<double>& times) {
    std::printf("| %s | %.0f us | %.0f us | %.0f us | %zu |\n", what, Quantile(times, 0.5), Quantile(times, 0.99),
                times.back(), times.size());
}

std::string Option(int argc, char** argv, const std::string& name) {
    for (int i = 1; i + 1 < argc; ++i) {
        if (argv[i] == name) return argv[i + 1];
    }
    throw std::runtime_error("missing " + name);
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::string pacSim = Option(argc, argv, "--pac-sim");
        std::printf("### pac-sim\n\nOne libmodbus client on loopback; a round trip writes the CMD module (function code "
                    "16, 4 registers) and reads the reply (function code 4, 4 registers); %d round trips after %d.\n\n",
                    kRoundTrips, kWarmUp);
        std::printf("| Modbus TCP round trip | p50 | p99 | max | round trips |\n|---|---|---|---|---|\n");
        {
            Child sim({pacSim, "--port", "0", Option(argc, argv, "--config")});
            const int port = std::stoi(sim.Await(R"(Modbus TCP 127\.0\.0\.1:(\d+) )"));
            sim.Await("running");
            Row("pac-sim (libmodbus), one controller with CMD, CTRL and 2 axis modules", RoundTrips(port));
            sim.Stop(SIGINT);
        }
        {
            const int port = FreePort();
            Child anchor({Option(argc, argv, "--python"), Option(argc, argv, "--anchor"), std::to_string(port)}, true);
            anchor.Await("ready");
            Row("the anchor: pymodbus 3.16.1's own server (asyncio)", RoundTrips(port));
        }
        const std::string config = "pacsim_bench_32x8.json";
        {
            std::ofstream out(config);
            out << "{\"port\": 0, \"controllers\": [";
            for (int i = 1; i <= kControllers; ++i) {
                out << (i > 1 ? ", " : "") << "{\"unit_id\": " << i
                    << ", \"timing\": {\"pac_cycle_ms\": 1}, \"modules\": {\"ctrl\": true, \"axes\": 8}"
                    << ", \"controller\": {\"inputs\": {\"1\": true}, \"system_parameters\": {\"4\": 1}}}";
            }
            out << "]}\n";
        }
        for (const bool moving : {false, true}) {
            Child scale({pacSim, "--seconds", std::to_string(kScaleSeconds), "--stats", config});
            const int port = std::stoi(scale.Await(R"(Modbus TCP 127\.0\.0\.1:(\d+) )"));
            scale.Await("running");
            std::string load = "no client: the axes stand";
            if (moving) {
                const auto moves = DriveAllAxes(port);
                load = "one libmodbus client switches each controller to ONLINE and its 8 axes on, then moves every "
                       "axis back and forth between 0 and 100 (" + std::to_string(moves) + " moves started), reading "
                       "and writing each controller's modules in turn";
            }
            const std::string stats = scale.Await(R"(pac-sim: (cycles .*))");
            std::printf("\n%d controllers with CTRL and 8 axis modules each, 1 ms controller cycle, %d s, %s: %s\n",
                        kControllers, kScaleSeconds, load.c_str(), stats.substr(0, stats.find_last_not_of('\n') + 1).c_str());
        }
        std::remove(config.c_str());

        std::printf("\nThe library over Modbus TCP: the demo scenario's steps with the library's FBs in pac-sim-plc's "
                    "real-time scan loop (10 ms PLC cycle) against pac-sim, and in the process on the simulated bus "
                    "(the same PLC cycle, the scenario's bus latency of 1 cycle each way):\n\n");
        Child demo({pacSim, "--port", "0", "--http", "0", Option(argc, argv, "--demo-config")});
        const std::string port = demo.Await(R"(Modbus TCP 127\.0\.0\.1:(\d+) )");
        const std::string http = demo.Await(R"(live view http://127\.0\.0\.1:(\d+)/)");
        demo.Await("running");
        Child plc({Option(argc, argv, "--plc"), "--port", port, "--http", http, "--plc-cycle-ms", "10", "--compare",
                   Option(argc, argv, "--scenario")});
        for (std::string line = plc.Line(); !line.empty(); line = plc.Line()) std::printf("%s", line.c_str());
        demo.Stop(SIGINT);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pacsim_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
