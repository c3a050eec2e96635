#include "modbus_remote_controller.hpp"

#include <cerrno>
#include <stdexcept>
#include <thread>
#include <vector>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "register_map.hpp"

namespace pac::pacsim {

namespace {

std::runtime_error ModbusError(const std::string& what) {
    return std::runtime_error("Modbus TCP: " + what + ": " + modbus_strerror(errno));
}

}  // namespace

ModbusRemoteController::ModbusRemoteController(const std::string& address, int port, int unitId, int registers,
                                               int httpPort)
    : address_(address), httpPort_(httpPort), registers_(registers), ctx_(modbus_new_tcp(address.c_str(), port)) {
    if (!ctx_) throw ModbusError("cannot make a client for " + address);
    modbus_set_slave(ctx_, unitId);
    modbus_set_response_timeout(ctx_, 1, 0);
    if (modbus_connect(ctx_) != 0) {
        modbus_free(ctx_);
        throw ModbusError("cannot connect to " + address + ":" + std::to_string(port));
    }
}

ModbusRemoteController::~ModbusRemoteController() {
    modbus_close(ctx_);
    modbus_free(ctx_);
}

void ModbusRemoteController::ReadFromPac(std::chrono::nanoseconds now, pac::sim::ProcessImage& fromPac) {
    std::this_thread::sleep_until(schedule_.Due(now, std::chrono::steady_clock::now()));
    lateness_.Add(schedule_.Started(now, std::chrono::steady_clock::now()));
    std::vector<std::uint16_t> values(static_cast<std::size_t>(registers_));
    const auto sent = std::chrono::steady_clock::now();
    if (modbus_read_input_registers(ctx_, 0, registers_, values.data()) != registers_) throw ModbusError("read");
    roundTrips_.Add(std::chrono::steady_clock::now() - sent);
    pac::sim::ProcessImage image(fromPac.Size());
    RegisterMap::WriteRegisters(image, 0, values);
    fromPac = image;
}

void ModbusRemoteController::WriteToPac(std::chrono::nanoseconds /*now*/, const pac::sim::ProcessImage& toPac) {
    const std::vector<std::uint16_t> values = RegisterMap::ToRegisters(toPac);
    if (modbus_write_registers(ctx_, 0, registers_, values.data()) != registers_) throw ModbusError("write");
}

void ModbusRemoteController::InjectFault(const pac::scenario::FaultStep& fault) {
    if (fault.kind != pac::scenario::FaultKind::kPowerCycle || httpPort_ == 0) {
        throw std::runtime_error(std::string("fault ") + pac::scenario::ToString(fault.kind) +
                                 ": over Modbus only power_cycle, through pac-sim's --http port");
    }
    httplib::Client client(address_, httpPort_);
    const auto result = client.Post("/api/fault", nlohmann::json{{"fault", "power_cycle"}}.dump(), "application/json");
    if (!result || result->status != 200) {
        throw std::runtime_error("pac-sim's fault endpoint did not take power_cycle" +
                                 (result ? ": " + result->body : std::string()));
    }
}

}  // namespace pac::pacsim
