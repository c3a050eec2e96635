// pac-sim's live view (docs/virtual_commissioning.md, "The live view"): an HTTP server (cpp-httplib, Debian's
// libcpp-httplib-dev) on its own threads that serves the page (web/live_view.html), the controllers' state as
// JSON for it (GET /api/state, polled by the page 20 times a second) and fault injection (POST /api/fault, the
// page's buttons and any HTTP client). Every request locks the controllers it reads or changes, one at a time.
#pragma once

#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "simulated_controller.hpp"
#include "wall_clock.hpp"

namespace httplib {
class Server;
}

namespace pac::pacsim {

class LiveViewServer {
public:
    // Listens on `address`:`port` (0: a free port); std::runtime_error naming both when it cannot.
    LiveViewServer(std::vector<std::unique_ptr<SimulatedController>>& controllers, const WallClock& clock,
                   const std::string& address, int port);
    ~LiveViewServer();
    LiveViewServer(const LiveViewServer&) = delete;
    LiveViewServer& operator=(const LiveViewServer&) = delete;

    int Port() const { return port_; }
    void Start();  // serves from now on
    void Stop();   // stops serving; joins the thread

private:
    void Route();

    std::vector<std::unique_ptr<SimulatedController>>& controllers_;
    const WallClock& clock_;
    std::unique_ptr<httplib::Server> server_;
    int port_ = 0;
    std::thread thread_;
};

}  // namespace pac::pacsim
