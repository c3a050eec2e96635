// The two directions of the fieldbus (see bus.hpp).
#include "pac/sim/bus.hpp"

namespace pac::sim {

Bus::Bus(BusConfig config) : toSlave_(config.toSlave), toMaster_(config.toMaster) {}

void Bus::Disconnect(std::chrono::nanoseconds now) {
    toSlave_.SetFault(now, LinkFault::kDisconnected);
    toMaster_.SetFault(now, LinkFault::kDisconnected);
}

void Bus::Reconnect(std::chrono::nanoseconds now) {
    toSlave_.SetFault(now, LinkFault::kNone);
    toMaster_.SetFault(now, LinkFault::kNone);
}

}  // namespace pac::sim
