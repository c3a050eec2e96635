// Modbus TCP in front of the simulated PA-CONTROLs, as a Profibus-DP-to-Modbus-TCP gateway shows its slaves
// (docs/virtual_commissioning.md): one listening socket per port of the configuration, each controller reached
// by its unit id on its port. libmodbus frames every request and answers it from the controller's registers
// (RegisterMap); CheckRequest decides first what may be served. Each client has a thread of its own, so a
// client that stalls in the middle of a frame holds up nobody else; a frame libmodbus cannot read, a client
// that does not take its replies or one beyond the connection limit is disconnected, and the others carry on.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <modbus/modbus.h>

#include "simulated_controller.hpp"
#include "tcp_listener.hpp"
#include "wall_clock.hpp"

namespace pac::pacsim {

struct GatewayCounters {
    std::uint64_t connections = 0;          // accepted and served
    std::uint64_t connectionsRefused = 0;   // beyond kMaxClients: closed at once
    std::uint64_t requests = 0;             // frames libmodbus read
    std::uint64_t exceptions = 0;           // ... answered with a Modbus exception
    std::uint64_t dropped = 0;              // connections closed on a frame or a reply that failed
};

class ModbusGateway {
public:
    static constexpr int kMaxClients = 32;

    // Listens on `address` (IPv4) on each port the controllers name; port 0: a free port chosen by the system,
    // one for every controller configured with 0. std::runtime_error naming address and port when it cannot.
    ModbusGateway(std::vector<std::unique_ptr<SimulatedController>>& controllers, const WallClock& clock,
                  std::string address);
    ~ModbusGateway();
    ModbusGateway(const ModbusGateway&) = delete;
    ModbusGateway& operator=(const ModbusGateway&) = delete;

    // The port controller `index` is served on (the one bound, for port 0).
    int PortOf(std::size_t index) const;
    const std::string& Address() const { return address_; }

    void Start();  // accepts clients from now on, on a thread of its own
    void Stop();   // closes every connection and listening socket; joins the threads
    GatewayCounters Counters() const;

private:
    struct Listener;
    struct Client;
    class Tables;

    void AcceptLoop();
    void Accept(Listener& listener);
    void Serve(Client& client);
    // Answers one request libmodbus has read (an exception, or the reply from the controller's registers and
    // the write applied); false when the reply could not be sent.
    bool Answer(modbus_t* ctx, const std::uint8_t* query, int length, const Listener& listener);
    void Reap(bool all);

    std::vector<std::unique_ptr<SimulatedController>>& controllers_;
    const WallClock& clock_;
    std::string address_;
    std::vector<std::unique_ptr<Listener>> listeners_;
    std::unique_ptr<Tables> tables_;
    WakeEvent wake_;  // Stop() wakes every poll
    std::thread acceptor_;
    std::mutex clientsMutex_;
    std::vector<std::unique_ptr<Client>> clients_;
    std::atomic<bool> stopping_{false};
    std::atomic<std::uint64_t> connections_{0}, refused_{0}, requests_{0}, exceptions_{0}, dropped_{0};
};

}  // namespace pac::pacsim
