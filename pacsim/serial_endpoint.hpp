// Where a simulated PA-CONTROL's COM1 (manual chapter 3) meets its client: a TCP port (TcpSerialBridge) or a
// pseudo-terminal (PtySerialBridge), each relaying on a thread of its own. RelaySerial is the step both take.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "simulated_controller.hpp"
#include "wall_clock.hpp"

namespace pac::pacsim {

class SerialEndpoint {
public:
    virtual ~SerialEndpoint() = default;
    virtual void Start() = 0;
    virtual void Stop() = 0;
    // "raw TCP 127.0.0.1:5021", "pseudo-terminal /dev/pts/4": printed at start.
    virtual std::string Where() const = 0;
};

// Under the controller's lock at the present time: its cycles due, `received` onto the line, and the bytes the
// controller's answer has put through the line by now.
std::vector<std::uint8_t> RelaySerial(SimulatedController& controller, const WallClock& clock,
                                      const std::vector<std::uint8_t>& received);

}  // namespace pac::pacsim
