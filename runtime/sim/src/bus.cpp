// The two directions of the fieldbus (see bus.hpp).
#include "pac/sim/bus.hpp"

namespace pac::sim {

namespace {

const ModuleLayout& Validated(const ModuleLayout& layout) {
    layout.Validate();
    return layout;
}

}  // namespace

Bus::Bus(BusConfig config)
    : layout_(Validated(config.layout)),
      toSlave_(config.toSlave, layout_.Bytes()),
      toMaster_(config.toMaster, layout_.Bytes()) {}

void Bus::Disconnect(std::chrono::nanoseconds now) {
    toSlave_.SetFault(now, LinkFault::kDisconnected);
    toMaster_.SetFault(now, LinkFault::kDisconnected);
}

void Bus::Reconnect(std::chrono::nanoseconds now) {
    toSlave_.SetFault(now, LinkFault::kNone);
    toMaster_.SetFault(now, LinkFault::kNone);
}

}  // namespace pac::sim
