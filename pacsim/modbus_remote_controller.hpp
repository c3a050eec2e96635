// The PLC side of the closed loop (pac-sim-plc, docs/virtual_commissioning.md, "The library over Modbus"): the
// scenario runner's process image goes through a Modbus TCP client (libmodbus) to pac-sim, as a soft PLC's
// Modbus master exchanges it, and the scan runs on the wall clock: each scan starts at its own time
// (ScanSchedule: scan n at n PLC cycles after the first, unless a stall moved the schedule), reads the input
// registers (function code 4), and writes the holding registers (function code 16) at its end. The scenario's
// power cycle goes to pac-sim's fault endpoint (POST /api/fault).
#pragma once

#include <chrono>
#include <string>

#include <modbus/modbus.h>

#include "cycle_stats.hpp"
#include "scan_schedule.hpp"
#include "scenario_runner.hpp"

namespace pac::pacsim {

class ModbusRemoteController final : public pac::scenario::RemoteController {
public:
    // `registers`: one direction's image (RegisterMap::Registers()); `httpPort` pac-sim's --http, 0: none (then a
    // fault step is an error). std::runtime_error when the connection cannot be made.
    ModbusRemoteController(const std::string& address, int port, int unitId, int registers, int httpPort);
    ~ModbusRemoteController() override;
    ModbusRemoteController(const ModbusRemoteController&) = delete;
    ModbusRemoteController& operator=(const ModbusRemoteController&) = delete;

    void ReadFromPac(std::chrono::nanoseconds now, pac::sim::ProcessImage& fromPac) override;
    void WriteToPac(std::chrono::nanoseconds now, const pac::sim::ProcessImage& toPac) override;
    void InjectFault(const pac::scenario::FaultStep& fault) override;

    // How late each scan started on the wall clock (the loop's jitter), and the round trips.
    const CycleStats& ScanLateness() const { return lateness_; }
    const CycleStats& RoundTrips() const { return roundTrips_; }

private:
    std::string address_;
    int httpPort_;
    int registers_;
    modbus_t* ctx_ = nullptr;
    ScanSchedule schedule_;
    CycleStats lateness_;
    CycleStats roundTrips_;
};

}  // namespace pac::pacsim
