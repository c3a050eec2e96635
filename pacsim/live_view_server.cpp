#include "live_view_server.hpp"

#include <chrono>
#include <stdexcept>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "fault_injector.hpp"
#include "live_view_page.hpp"
#include "live_view_state.hpp"

namespace pac::pacsim {

namespace {

using nlohmann::json;

void Reply(httplib::Response& response, int status, const json& body) {
    response.status = status;
    response.set_content(body.dump(), "application/json");
}

}  // namespace

LiveViewServer::LiveViewServer(std::vector<std::unique_ptr<SimulatedController>>& controllers, const WallClock& clock,
                               const std::string& address, int port)
    : controllers_(controllers), clock_(clock), server_(std::make_unique<httplib::Server>()) {
    const bool bound = port == 0 ? (port_ = server_->bind_to_any_port(address)) > 0
                                 : (port_ = port, server_->bind_to_port(address, port));
    if (!bound) {
        throw std::runtime_error("live view: cannot listen on " + address + ":" + std::to_string(port));
    }
    Route();
}

LiveViewServer::~LiveViewServer() { Stop(); }

void LiveViewServer::Route() {
    server_->Get("/", [](const httplib::Request&, httplib::Response& response) {
        response.set_content(LiveViewPage(), "text/html; charset=utf-8");
    });
    server_->Get("/api/state", [this](const httplib::Request&, httplib::Response& response) {
        json state = {{"controllers", json::array()}};
        for (auto& controller : controllers_) {
            const auto lock = controller->Lock();
            state["controllers"].push_back(ControllerState(*controller, clock_.Now()));
        }
        Reply(response, 200, state);
    });
    server_->Get("/api/faults", [](const httplib::Request&, httplib::Response& response) {
        Reply(response, 200, {{"faults", FaultKinds()}});
    });
    server_->Post("/api/fault", [this](const httplib::Request& request, httplib::Response& response) {
        const json body = json::parse(request.body, nullptr, false);
        if (!body.is_object() || !body.contains("fault") || !body["fault"].is_string()) {
            Reply(response, 400, {{"error", "a JSON object with \"fault\" (a string) is needed"}});
            return;
        }
        FaultRequest fault;
        fault.kind = body["fault"].get<std::string>();
        std::string name = controllers_.front()->Spec().name;
        try {
            if (body.contains("controller")) name = body.at("controller").get<std::string>();
            if (body.contains("axis")) fault.axis = body.at("axis").get<int>();
            if (body.contains("number")) fault.number = body.at("number").get<int>();
        } catch (const json::exception&) {
            Reply(response, 400, {{"error", "\"controller\" is a name, \"axis\" and \"number\" integers"}});
            return;
        }
        for (auto& controller : controllers_) {
            if (controller->Spec().name != name) continue;
            try {
                const auto lock = controller->Lock();
                const auto now = clock_.Now();
                controller->CatchUp(now);  // the fault acts at now, after the cycles due
                InjectFault(*controller, now, fault);
                Reply(response, 200, {{"controller", name}, {"fault", fault.kind}, {"time_ms", now.count() / 1e6}});
            } catch (const std::invalid_argument& e) {
                Reply(response, 400, {{"error", e.what()}});
            }
            return;
        }
        Reply(response, 404, {{"error", "no controller named \"" + name + "\""}});
    });
}

void LiveViewServer::Start() {
    thread_ = std::thread([this] { server_->listen_after_bind(); });
    // stop() acts only on a running server: wait for it, so a Stop() right after Start() is not lost.
    while (!server_->is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

void LiveViewServer::Stop() {
    if (!thread_.joinable()) return;
    server_->stop();
    thread_.join();
}

}  // namespace pac::pacsim
