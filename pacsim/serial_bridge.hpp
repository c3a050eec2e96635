// COM1 of a simulated PA-CONTROL (manual chapter 3) as the raw byte stream of a TCP port, as ser2net carries a
// serial line (docs/virtual_commissioning.md, "RS232 over TCP"): the bytes a client sends go onto the simulated
// line at the line's speed, and the controller's answer comes back as it leaves the line. One client at a time,
// like the one peer of a serial line; another is closed at once. A thread of its own relays every millisecond.
#pragma once

#include <atomic>
#include <string>
#include <thread>

#include "simulated_controller.hpp"
#include "tcp_listener.hpp"
#include "wall_clock.hpp"

namespace pac::pacsim {

class SerialBridge {
public:
    // Listens on `address`:`port` (0: a free port); std::runtime_error naming them when it cannot.
    SerialBridge(SimulatedController& controller, const WallClock& clock, const std::string& address, int port);
    ~SerialBridge();
    SerialBridge(const SerialBridge&) = delete;
    SerialBridge& operator=(const SerialBridge&) = delete;

    int Port() const { return listener_.Port(); }
    void Start();
    void Stop();

private:
    void Run();
    // Moves the client's bytes onto the line and the line's bytes to the client; false when the client is gone.
    bool Relay(int client, bool readable);

    SimulatedController& controller_;
    const WallClock& clock_;
    TcpListener listener_;
    WakeEvent wake_;
    std::atomic<bool> stopping_{false};
    std::thread thread_;
};

}  // namespace pac::pacsim
