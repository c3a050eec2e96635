// A PLC and a simulated PA-CONTROL on an RS232 line (see serial_rig.hpp).
#include "pac/serial_rig.hpp"

#include <utility>

namespace pac {

namespace {

pac::sim::PaControlConfig WithTiming(pac::sim::PaControlConfig config, const SerialRigTiming& timing) {
    config.bootTime = timing.bootTime;
    config.homeCycle = timing.pacCycle;
    config.activeCycle = timing.pacCycle;
    return config;
}

}  // namespace

SerialRig::SerialRig(SerialRigTiming timing, pac::sim::PaControlConfig config,
                               pac::sim::SerialPortConfig port)
    : timing_(timing),
      task_(clock_, timing.plcCycle),
      bus_(pac::sim::BusConfig{}),
      pac_(bus_, WithTiming(std::move(config), timing)),
      runner_(pac_, timing.pacPhase),
      line_(timing.format, timing.seed) {
    pac_.AttachSerial(line_, port);
    // First: at equal timestamps the controller's cycle runs before the PLC's scan (pac_runner.hpp).
    runner_.AttachTo(task_);
}

void SerialRig::Scan(int n) {
    for (int i = 0; i < n; ++i) task_.Scan();
}

int SerialRig::ScanUntil(const std::function<bool()>& predicate, int maxScans) {
    for (int scans = 1; scans <= maxScans; ++scans) {
        task_.Scan();
        if (predicate()) return scans;
    }
    return -1;
}

}  // namespace pac
