// One simulated PA-CONTROL of pac-sim in real time: its bus and controller, run at the controller's own
// cycle (PacRunner) on the wall clock's time since pac-sim started, and the PLC's side of the bus as
// registers (RegisterMap). Its state is used under Lock() (Spec() and Map() never change): the simulation loop,
// each Modbus client thread and the RS232 bridge lock the controller, take the time inside the lock (so the
// controller sees its time run forward), run the cycles due and then read or write the images.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "pac/sim/bus.hpp"
#include "pac/sim/pa_control.hpp"
#include "pac/sim/pac_runner.hpp"
#include "pac/sim/process_image.hpp"
#include "pac/sim/serial_line.hpp"
#include "cmd_history.hpp"
#include "register_map.hpp"
#include "sim_config.hpp"

namespace pac::pacsim {

class SimulatedController {
public:
    // Applies the spec's timing, modules and controller settings as pac_scenario does (a ScenarioError names a
    // system parameter the simulator refuses).
    explicit SimulatedController(const ControllerSpec& spec);
    SimulatedController(const SimulatedController&) = delete;
    SimulatedController& operator=(const SimulatedController&) = delete;

    std::unique_lock<std::mutex> Lock() { return std::unique_lock<std::mutex>(mutex_); }

    // Runs every controller cycle due at `now` (non-decreasing) and reads the from-PAC image the bus delivers then.
    void CatchUp(std::chrono::nanoseconds now);
    std::chrono::nanoseconds NextCycleTime() const { return runner_.NextCycleTime(); }

    const ControllerSpec& Spec() const { return spec_; }
    const RegisterMap& Map() const { return map_; }
    // The PLC's images as registers: what it wrote last (to PAC) and what it reads (from PAC, as of the last CatchUp).
    std::vector<std::uint16_t> ToPacRegisters() const { return RegisterMap::ToRegisters(toPac_); }
    std::vector<std::uint16_t> FromPacRegisters() const { return RegisterMap::ToRegisters(fromPac_); }
    // Registers [first, first + values.size()) of the to-PAC image, sent on the bus at `now` as one image
    // (every module written by one request arrives together).
    void WriteToPac(std::chrono::nanoseconds now, int first, const std::vector<std::uint16_t>& values);

    // COM1 (manual chapter 3), with the spec's "rs232": bytes from the client onto the line at `now`, and the
    // controller's bytes that have come off the line by `now` (std::logic_error without "rs232").
    void SendSerial(std::chrono::nanoseconds now, const std::vector<std::uint8_t>& bytes);
    std::vector<std::uint8_t> ReceiveSerial(std::chrono::nanoseconds now);

    pac::sim::PaControl& Controller() { return pac_; }
    pac::sim::Bus& Bus() { return bus_; }
    // The CMD handshakes the controller has seen (pac-sim's live view), as of the last CatchUp.
    const CmdHistory& History() const { return history_; }

private:
    std::mutex mutex_;
    ControllerSpec spec_;
    RegisterMap map_;
    pac::sim::Bus bus_;
    std::unique_ptr<pac::sim::SerialLine> serialLine_;  // before pac_: the controller's port refers to it
    pac::sim::PaControl pac_;
    pac::sim::PacRunner runner_;
    pac::sim::ProcessImage toPac_;
    pac::sim::ProcessImage fromPac_;
    CmdHistory history_;
};

}  // namespace pac::pacsim
