// A simulated PA-CONTROL with COM1 on an RS232 line and nothing on the fieldbus, driven by hand: a test
// sends bytes on the to-PAC wire and runs the controller's cycles until the reply has arrived.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "pac/sim/bus.hpp"
#include "pac/sim/pa_control.hpp"
#include "pac/sim/rs232_frame.hpp"
#include "pac/sim/serial_line.hpp"
#include "pac/sim/serial_port.hpp"

namespace pac::sim::testing {

using Bytes = std::vector<std::uint8_t>;

// "01 02 30 39" -> bytes, as the manual prints them.
inline Bytes Hex(const std::string& text) {
    Bytes bytes;
    std::istringstream in(text);
    std::string token;
    while (in >> token) bytes.push_back(static_cast<std::uint8_t>(std::stoul(token, nullptr, 16)));
    return bytes;
}

inline std::string HexOf(const Bytes& bytes) {
    std::string out;
    char buffer[4];
    for (std::uint8_t b : bytes) {
        std::snprintf(buffer, sizeof buffer, "%02X", b);
        if (!out.empty()) out += ' ';
        out += buffer;
    }
    return out;
}

inline PaControlConfig SerialOnlyConfig() {
    PaControlConfig config;
    config.bootTime = std::chrono::nanoseconds(0);
    config.modes.requireExternalStop = false;  // 0603 without a stop input wired
    return config;
}

class SerialRig {
public:
    explicit SerialRig(SerialPortConfig port = {}, SerialFormat format = {}, PaControlConfig config = SerialOnlyConfig())
        : line_(format), pac_(bus_, config) {
        pac_.AttachSerial(line_, port);
        pac_.Cycle(now_);  // booted at 0
    }

    // Sends `request` now and runs controller cycles until a whole reply (up to EOT) has arrived, at most
    // `maxCycles`; returns what arrived (empty: no answer).
    Bytes Exchange(const Bytes& request, int maxCycles = 50) {
        line_.toPac.Send(now_, request);
        return AwaitReply(maxCycles);
    }
    Bytes AwaitReply(int maxCycles = 50) {
        Bytes reply;
        for (int i = 0; i < maxCycles; ++i) {
            Step();
            for (std::uint8_t b : line_.fromPac.Receive(now_)) reply.push_back(b);
            if (!reply.empty() && reply.back() == rs232::kEot && line_.fromPac.Idle(now_)) return reply;
        }
        return reply;
    }
    void Step() {
        now_ += pac_.CycleTime();
        pac_.Cycle(now_);
    }

    PaControl& Pac() { return pac_; }
    SerialLine& Line() { return line_; }
    std::chrono::nanoseconds Now() const { return now_; }

private:
    SerialLine line_;
    Bus bus_;
    PaControl pac_;
    std::chrono::nanoseconds now_{0};
};

}  // namespace pac::sim::testing
