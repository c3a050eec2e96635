// COM1 of a simulated PA-CONTROL (manual chapter 3) as the raw byte stream of a TCP port, as ser2net carries a
// serial line (docs/virtual_commissioning.md, "RS232 over TCP"): the bytes a client sends go onto the simulated
// line at the line's speed, and the controller's answer comes back as it leaves the line. One client at a time,
// like the one peer of a serial line; another is closed at once. A thread of its own relays every millisecond.
#pragma once

#include <atomic>
#include <string>
#include <thread>

#include "serial_endpoint.hpp"
#include "simulated_controller.hpp"
#include "tcp_listener.hpp"
#include "wall_clock.hpp"

namespace pac::pacsim {

class TcpSerialBridge final : public SerialEndpoint {
public:
    // Listens on `address`:`port` (0: a free port); std::runtime_error naming them when it cannot.
    TcpSerialBridge(SimulatedController& controller, const WallClock& clock, const std::string& address, int port);
    ~TcpSerialBridge() override;
    TcpSerialBridge(const TcpSerialBridge&) = delete;
    TcpSerialBridge& operator=(const TcpSerialBridge&) = delete;

    int Port() const { return listener_.Port(); }
    void Start() override;
    void Stop() override;
    std::string Where() const override;

private:
    void Run();
    // Moves the client's bytes onto the line and the line's bytes to the client; false when the client is gone.
    bool Relay(int client, bool readable);

    SimulatedController& controller_;
    const WallClock& clock_;
    std::string address_;
    TcpListener listener_;
    WakeEvent wake_;
    std::atomic<bool> stopping_{false};
    std::thread thread_;
};

}  // namespace pac::pacsim
