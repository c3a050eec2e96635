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
      toPac_(config.toPac, layout_.Bytes()),
      fromPac_(config.fromPac, layout_.Bytes()) {}

void Bus::Disconnect(std::chrono::nanoseconds now) {
    toPac_.SetFault(now, LinkFault::kDisconnected);
    fromPac_.SetFault(now, LinkFault::kDisconnected);
}

void Bus::Reconnect(std::chrono::nanoseconds now) {
    toPac_.SetFault(now, LinkFault::kNone);
    fromPac_.SetFault(now, LinkFault::kNone);
}

}  // namespace pac::sim
