// The fieldbus between one master (the PLC) and one PA-CONTROL: two Links, master -> slave and
// slave -> master, each with its own latency, jitter, seed and fault.
#pragma once

#include <chrono>

#include "pac/sim/link.hpp"

namespace pac::sim {

struct BusConfig {
    LinkConfig toSlave{std::chrono::nanoseconds(0), std::chrono::nanoseconds(0), 1};
    LinkConfig toMaster{std::chrono::nanoseconds(0), std::chrono::nanoseconds(0), 2};
    ModuleLayout layout{};  // the process image both directions carry: ModuleLayout::Bytes()
};

class Bus {
public:
    explicit Bus(BusConfig config = {});  // an invalid layout: std::invalid_argument
    const ModuleLayout& Layout() const { return layout_; }

    // The master's side: its output image goes to the slave, its input image is the slave's reply.
    void MasterWrite(std::chrono::nanoseconds now, const ProcessImage& image) { toSlave_.Write(now, image); }
    ProcessImage MasterRead(std::chrono::nanoseconds now) { return toMaster_.Read(now); }

    // The slave's side.
    void SlaveWrite(std::chrono::nanoseconds now, const ProcessImage& image) { toMaster_.Write(now, image); }
    ProcessImage SlaveRead(std::chrono::nanoseconds now) { return toSlave_.Read(now); }

    Link& ToSlave() { return toSlave_; }
    Link& ToMaster() { return toMaster_; }
    const Link& ToSlave() const { return toSlave_; }
    const Link& ToMaster() const { return toMaster_; }

    // Both directions at once (a pulled cable): see Link for what each reader sees.
    void Disconnect(std::chrono::nanoseconds now);
    void Reconnect(std::chrono::nanoseconds now);

private:
    ModuleLayout layout_;
    Link toSlave_;
    Link toMaster_;
};

}  // namespace pac::sim
