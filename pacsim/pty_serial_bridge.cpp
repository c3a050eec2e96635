#include "pty_serial_bridge.hpp"

#include <cstdint>
#include <vector>

namespace pac::pacsim {

namespace {

constexpr int kRelayPeriodMs = 1;  // as pac_sim --serial

}  // namespace

PtySerialBridge::PtySerialBridge(SimulatedController& controller, const WallClock& clock, const std::string& link)
    : controller_(controller), clock_(clock), terminal_(link) {}

PtySerialBridge::~PtySerialBridge() { Stop(); }

void PtySerialBridge::Start() {
    thread_ = std::thread([this] {
        while (!stopping_) {
            const std::vector<std::uint8_t> reply = RelaySerial(controller_, clock_, terminal_.Read(kRelayPeriodMs));
            if (!reply.empty()) terminal_.Write(reply);
        }
    });
}

void PtySerialBridge::Stop() {
    stopping_ = true;  // the thread looks at it at least every kRelayPeriodMs
    if (thread_.joinable()) thread_.join();
}

}  // namespace pac::pacsim
