// The CTRL module on the controller's side (see ctrl_interface.hpp and docs/sim_modes.md).
#include "pac/sim/ctrl_interface.hpp"

namespace pac::sim {

namespace ctrl {

std::uint16_t ModeBits(std::uint8_t s) {
    switch (s) {
        case status::kAuto:
        case status::kAutoStopRecognized:
        case status::kAutoStopProgram:
        case status::kAutoStartAfterStop:
        case status::kAutoMalfunctionRecognized:
        case status::kAutoMalfunctionProgram:
            return kAutomaticActive;
        case status::kAutoStopped:
        case status::kAutoStoppedMalfunction:
            return kAutomaticStopped;
        case status::kOnline:
        case status::kOnlineStopRecognized:
        case status::kOnlineMalfunctionRecognized:
            return kOnlineActive;
        case status::kOnlineStopped:
        case status::kOnlineStoppedMalfunction:
            return kOnlineStopped;
        default:
            return 0;
    }
}

}  // namespace ctrl

void CtrlInterface::Apply(const Image8& module, std::chrono::nanoseconds now) {
    const std::uint16_t word = ReadWord(module, 0);
    // Before the first word after a boot the bits count as idle (starts 0, the low-active bits 1): a
    // PLC whose very first image carries a request is served (docs/sim_modes.md).
    const std::uint16_t before = previous_.value_or(ctrl::kNoRequest);
    previous_ = word;
    auto rose = [&](std::uint16_t bit) { return (word & bit) != 0 && (before & bit) == 0; };
    auto fell = [&](std::uint16_t bit) { return (word & bit) == 0 && (before & bit) != 0; };
    const bool stopLow = (word & ctrl::kStop) == 0;
    const bool cancelLow = (word & ctrl::kCancel) == 0;

    modes_.SetRequestedIntegerFormat((word & ctrl::kIntegerFormat) != 0);
    // Levels first: Cancel is the stronger of the two, and a start is refused while either is low.
    // Results are dropped on purpose: a request that does not apply is ignored.
    if (cancelLow) (void)modes_.Cancel(now);
    if (stopLow) (void)modes_.Stop(now);
    if (!stopLow && !cancelLow) {
        if (rose(ctrl::kStartOnline)) (void)modes_.StartOnline(now);
        if (rose(ctrl::kStartAutomatic)) (void)modes_.StartAutomatic(now);
    }
    if (fell(ctrl::kErrorReset)) (void)modes_.ResetError();
}

std::uint16_t CtrlInterface::StatusWord() const {
    std::uint16_t word = ctrl::ModeBits(modes_.Status());
    if (config_.stoppedModeBits == StoppedModeBits::kStoppedAndActive) {
        if ((word & ctrl::kOnlineStopped) != 0) word |= ctrl::kOnlineActive;
        if ((word & ctrl::kAutomaticStopped) != 0) word |= ctrl::kAutomaticActive;
    }
    if (modes_.Ready()) word |= ctrl::kReady;
    if (state_.batteryOk && modes_.Status() != status::kNotInitialized) word |= ctrl::kBatteryOk;
    if (modes_.SystemError() != 0) word |= ctrl::kSystemError;
    if (modes_.IntegerFormat()) word |= ctrl::kIntegerInForce;
    return word;
}

Image8 CtrlInterface::Reply() const {
    Image8 module{};
    WriteWord(module, 0, StatusWord());
    WriteWord(module, 2, modes_.SystemError());
    return module;
}

}  // namespace pac::sim
