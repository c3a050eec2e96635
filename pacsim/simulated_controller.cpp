#include "simulated_controller.hpp"

#include <stdexcept>

#include "controller_setup.hpp"

namespace pac::pacsim {

namespace {

using std::chrono::milliseconds;

pac::sim::BusConfig BusConfigOf(const ControllerSpec& spec) {
    // The scenario's bus timing: a latency of whole PLC cycles each way, a seeded jitter.
    pac::sim::BusConfig config;
    config.layout = pac::scenario::Layout(spec.modules);
    const auto latency = milliseconds(spec.timing.plcCycleMs) * spec.timing.latencyCycles;
    config.toPac = {latency, milliseconds(spec.timing.jitterMs), spec.timing.seed};
    config.fromPac = {latency, milliseconds(spec.timing.jitterMs), spec.timing.seed + 1};
    return config;
}

pac::sim::PaControlConfig ControllerConfigOf(const ControllerSpec& spec) {
    pac::sim::PaControlConfig config = pac::scenario::ControllerConfig(spec.controller);
    config.bootTime = milliseconds(spec.timing.bootMs);
    config.homeCycle = milliseconds(spec.timing.pacCycleMs);
    config.activeCycle = milliseconds(spec.timing.pacCycleMs);
    config.logCapacity = 0;  // it runs for hours: nothing reads the exchange log
    return config;
}

}  // namespace

SimulatedController::SimulatedController(const ControllerSpec& spec)
    : spec_(spec),
      map_(pac::scenario::Layout(spec.modules)),
      bus_(BusConfigOf(spec)),
      pac_(bus_, ControllerConfigOf(spec)),
      runner_(pac_),
      toPac_(bus_.Layout().Bytes()),
      fromPac_(bus_.Layout().Bytes()) {
    pac::scenario::ApplyControllerSetup(pac_, spec.controller);
    if (spec.rs232) {
        pac::sim::SerialFormat format;
        format.baud = spec.rs232->baud;
        serialLine_ = std::make_unique<pac::sim::SerialLine>(format);
        pac_.AttachSerial(*serialLine_);  // the port's defaults: pac_sim --serial's (docs/sim_serial.md)
    }
}

void SimulatedController::SendSerial(std::chrono::nanoseconds now, const std::vector<std::uint8_t>& bytes) {
    if (!serialLine_) throw std::logic_error("SimulatedController: no RS232 port configured");
    serialLine_->toPac.Send(now, bytes);
}

std::vector<std::uint8_t> SimulatedController::ReceiveSerial(std::chrono::nanoseconds now) {
    if (!serialLine_) throw std::logic_error("SimulatedController: no RS232 port configured");
    return serialLine_->fromPac.Receive(now);
}

void SimulatedController::CatchUp(std::chrono::nanoseconds now) {
    runner_.CatchUp(now);
    fromPac_ = bus_.ReadFromPac(now);
    history_.Follow(now, pac_.LastToPacImage().Cmd(), pac_.LastFromPacImage().Cmd());
}

void SimulatedController::WriteToPac(std::chrono::nanoseconds now, int first, const std::vector<std::uint16_t>& values) {
    RegisterMap::WriteRegisters(toPac_, first, values);
    bus_.WriteToPac(now, toPac_);
}

}  // namespace pac::pacsim
