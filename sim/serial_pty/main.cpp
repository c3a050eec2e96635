// pac_sim --serial: the simulated PA-CONTROL with its COM1 (manual 3) on a pseudo-terminal, in real time, so a
// real client talks to it over a serial port (docs/sim_serial.md, "pac_sim --serial"). It prints the port's
// path on the first line of its output and runs until it is terminated, --seconds have passed or (with
// --until-stdin-closes) its standard input ends.
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <poll.h>
#include <string>
#include <unistd.h>
#include <vector>

#include "pac/sim/bus.hpp"
#include "pac/sim/pa_control.hpp"
#include "pac/sim/pac_runner.hpp"
#include "pac/sim/serial_line.hpp"
#include "pac/sim/serial_port.hpp"
#include "pseudo_terminal.hpp"

namespace {

volatile std::sig_atomic_t stopRequested = 0;
void OnSignal(int) { stopRequested = 1; }

struct Options {
    bool serial = false;
    std::string link;
    int baud = 9600;
    double seconds = 0.0;  // 0: no limit
    bool exampleSetup = false;
    pac::sim::SerialPortConfig port;
    bool requireStopInput = false;
    bool untilStdinCloses = false;
};

constexpr const char* kUsage =
    "usage: pac_sim --serial [--link PATH] [--baud N] [--seconds S] [--example-setup]\n"
    "               [--check xor-etx|xor-text|none] [--no-zero-check] [--reply-check xor-etx|xor-text|zero]\n"
    "               [--silent-on-bad-check] [--discard-bad-check] [--no-idle-poll-reply] [--require-stop-input]\n"
    "               [--until-stdin-closes]\n"
    "Prints the pseudo-terminal's path, then serves RS232 frames of manual chapter 3 on it in real time.\n"
    "--example-setup: input 5 = 1, N2 = 222, R1 = 640.0 (the setup of manual 3.4.2).\n"
    "Defaults: --check xor-text (the manual's master frames), --reply-check xor-etx (its acknowledgements).\n";

bool Parse(int argc, char** argv, Options& o) {
    std::vector<std::string> args(argv + 1, argv + argc);
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::string { return i + 1 < args.size() ? args[++i] : std::string(); };
        if (a == "--serial") {
            o.serial = true;
        } else if (a == "--link") {
            o.link = value();
        } else if (a == "--baud") {
            o.baud = std::atoi(value().c_str());
        } else if (a == "--seconds") {
            o.seconds = std::atof(value().c_str());
        } else if (a == "--example-setup") {
            o.exampleSetup = true;
        } else if (a == "--check") {
            const std::string v = value();
            if (v == "xor-etx") o.port.verify = pac::sim::CheckVerification::kXorWithEtx;
            else if (v == "xor-text") o.port.verify = pac::sim::CheckVerification::kXorText;
            else if (v == "none") o.port.verify = pac::sim::CheckVerification::kNone;
            else return false;
        } else if (a == "--no-zero-check") {
            o.port.acceptZeroCheck = false;
        } else if (a == "--reply-check") {
            const std::string v = value();
            if (v == "xor-etx") o.port.replyCheck = pac::sim::rs232::CheckRule::kXorWithEtx;
            else if (v == "xor-text") o.port.replyCheck = pac::sim::rs232::CheckRule::kXorText;
            else if (v == "zero") o.port.replyCheck = pac::sim::rs232::CheckRule::kZero;
            else return false;
        } else if (a == "--silent-on-bad-check") {
            o.port.answerBadCheck = false;
        } else if (a == "--discard-bad-check") {
            o.port.answerBadCheck = false;
            o.port.discardBadCheckFrame = true;
        } else if (a == "--no-idle-poll-reply") {
            o.port.answerPollWhenIdle = false;
        } else if (a == "--until-stdin-closes") {
            o.untilStdinCloses = true;
        } else if (a == "--require-stop-input") {
            o.requireStopInput = true;
        } else {
            return false;
        }
    }
    return o.serial && o.baud > 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    if (!Parse(argc, argv, options)) {
        std::cerr << kUsage;
        return 2;
    }
    std::signal(SIGTERM, OnSignal);
    std::signal(SIGINT, OnSignal);
    try {
        pac::sim::PaControlConfig config;
        config.modes.requireExternalStop = options.requireStopInput;
        pac::sim::Bus bus;
        pac::sim::PaControl pac(bus, config);
        pac::sim::SerialFormat format;
        format.baud = options.baud;
        pac::sim::SerialLine line(format);
        pac.AttachSerial(line, options.port);
        if (options.exampleSetup) {
            pac.Io().inputs.Set(5, true);
            pac.Io().intRegisters.SetInt(2, 222);
            pac.Io().realRegisters.SetReal(1, 640.0F);
        }
        pac::sim::PacRunner runner(pac);
        pac::sim::PseudoTerminal pty(options.link);
        std::cout << pty.SlavePath() << std::endl;

        const auto start = std::chrono::steady_clock::now();
        while (stopRequested == 0) {
            // Wait up to 1 ms for the client's bytes; they are on the wire from the moment they were read.
            const std::vector<std::uint8_t> received = pty.Read(1);
            const auto now = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start);
            if (options.seconds > 0.0 && now.count() > options.seconds * 1e9) break;
            if (options.untilStdinCloses) {
                pollfd in{STDIN_FILENO, POLLIN, 0};
                char c;
                if (poll(&in, 1, 0) > 0 && read(STDIN_FILENO, &c, 1) <= 0) break;
            }
            if (!received.empty()) line.toPac.Send(now, received);
            runner.CatchUp(now);
            const std::vector<std::uint8_t> reply = line.fromPac.Receive(now);
            if (!reply.empty()) pty.Write(reply);
        }
    } catch (const std::exception& e) {
        std::cerr << "pac_sim: " << e.what() << "\n";
        return 3;
    }
    return 0;
}
