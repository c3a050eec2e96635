// COM1 of a simulated PA-CONTROL (manual chapter 3) on a pseudo-terminal, as pac_sim --serial has it
// (docs/sim_serial.md): a terminal program or pyserial opens the printed path like a serial port. A thread of
// its own waits up to a millisecond for the client's bytes and relays both ways.
#pragma once

#include <atomic>
#include <string>
#include <thread>

#include "pseudo_terminal.hpp"
#include "serial_endpoint.hpp"

namespace pac::pacsim {

class PtySerialBridge final : public SerialEndpoint {
public:
    // `link`: a symbolic link to the terminal's path, or empty. std::runtime_error when the system refuses.
    PtySerialBridge(SimulatedController& controller, const WallClock& clock, const std::string& link);
    ~PtySerialBridge() override;
    PtySerialBridge(const PtySerialBridge&) = delete;
    PtySerialBridge& operator=(const PtySerialBridge&) = delete;

    void Start() override;
    void Stop() override;
    std::string Where() const override { return "pseudo-terminal " + terminal_.SlavePath(); }

private:
    SimulatedController& controller_;
    const WallClock& clock_;
    pac::sim::PseudoTerminal terminal_;
    std::atomic<bool> stopping_{false};
    std::thread thread_;
};

}  // namespace pac::pacsim
