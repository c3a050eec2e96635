// One case of the RS232 suites that call FB_PAC_Rs232Cmd on a SerialRig: the line's baud rate, the PLC's and
// the controller's cycles, the CHECK the controller verifies and whether it takes "0" as no CHECK; and the rig
// set up for it (the controller starts ONLINE without an external stop wired).
#pragma once

#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>

#include "pac/serial_rig.hpp"
#include "pac/sim/serial_port.hpp"

namespace pac::test {

struct Rs232Case {
    int baud = 9600;
    int plcMs = 1;
    int pacMs = 10;
    pac::sim::CheckVerification verify = pac::sim::CheckVerification::kXorText;
    bool acceptZeroCheck = true;
    std::uint64_t seed = 1;
};

// "9600Baud_Plc1ms_Pac10ms_XorText_ZeroAccepted": the case in a test's name (without its seed).
inline std::string Rs232CaseName(const Rs232Case& c) {
    return std::to_string(c.baud) + "Baud_Plc" + std::to_string(c.plcMs) + "ms_Pac" + std::to_string(c.pacMs) + "ms" +
           (c.verify == pac::sim::CheckVerification::kXorText ? "_XorText" : "_XorWithEtx") +
           (c.acceptZeroCheck ? "_ZeroAccepted" : "_ZeroRefused");
}

inline void PrintTo(const Rs232Case& c, std::ostream* out) {
    *out << c.baud << " baud, PLC " << c.plcMs << " ms, PA-CONTROL " << c.pacMs << " ms, seed " << c.seed;
}

inline pac::SerialRigTiming Rs232RigTiming(const Rs232Case& c) {
    pac::SerialRigTiming timing;
    timing.plcCycle = std::chrono::milliseconds(c.plcMs);
    timing.pacCycle = std::chrono::milliseconds(c.pacMs);
    timing.format.baud = c.baud;
    return timing;
}

inline pac::sim::PaControlConfig Rs232RigConfig() {
    pac::sim::PaControlConfig config;
    config.modes.requireExternalStop = false;
    return config;
}

// `turnaround`: from the end of a request to the first byte of its reply.
inline pac::sim::SerialPortConfig Rs232RigPort(const Rs232Case& c,
                                               std::chrono::nanoseconds turnaround = std::chrono::nanoseconds(0)) {
    pac::sim::SerialPortConfig port;
    port.verify = c.verify;
    port.acceptZeroCheck = c.acceptZeroCheck;
    port.turnaround = turnaround;
    return port;
}

}  // namespace pac::test
