#include "serial_endpoint.hpp"

namespace pac::pacsim {

std::vector<std::uint8_t> RelaySerial(SimulatedController& controller, const WallClock& clock,
                                      const std::vector<std::uint8_t>& received) {
    const auto lock = controller.Lock();
    const auto now = clock.Now();
    controller.CatchUp(now);
    if (!received.empty()) controller.SendSerial(now, received);
    return controller.ReceiveSerial(now);
}

}  // namespace pac::pacsim
