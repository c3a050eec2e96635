// The fieldbus between the PLC and one PA-CONTROL: two Links, to PAC (PLC -> PA-CONTROL) and from PAC
// (PA-CONTROL -> PLC), each with its own latency, jitter, seed and fault.
#pragma once

#include <chrono>

#include "pac/sim/link.hpp"

namespace pac::sim {

struct BusConfig {
    LinkConfig toPac{std::chrono::nanoseconds(0), std::chrono::nanoseconds(0), 1};
    LinkConfig fromPac{std::chrono::nanoseconds(0), std::chrono::nanoseconds(0), 2};
    ModuleLayout layout{};  // the process image both directions carry: ModuleLayout::Bytes()
};

class Bus {
public:
    explicit Bus(BusConfig config = {});  // an invalid layout: std::invalid_argument
    const ModuleLayout& Layout() const { return layout_; }

    // The PLC's side: its output image goes to the controller, its input image is the controller's reply.
    void WriteToPac(std::chrono::nanoseconds now, const ProcessImage& image) { toPac_.Write(now, image); }
    ProcessImage ReadFromPac(std::chrono::nanoseconds now) { return fromPac_.Read(now); }

    // The controller's side.
    void WriteFromPac(std::chrono::nanoseconds now, const ProcessImage& image) { fromPac_.Write(now, image); }
    ProcessImage ReadToPac(std::chrono::nanoseconds now) { return toPac_.Read(now); }

    Link& ToPacLink() { return toPac_; }
    Link& FromPacLink() { return fromPac_; }
    const Link& ToPacLink() const { return toPac_; }
    const Link& FromPacLink() const { return fromPac_; }

    // Both directions at once (a pulled cable): see Link for what each reader sees.
    void Disconnect(std::chrono::nanoseconds now);
    void Reconnect(std::chrono::nanoseconds now);

private:
    ModuleLayout layout_;
    Link toPac_;
    Link fromPac_;
};

}  // namespace pac::sim
