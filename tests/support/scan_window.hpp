// The scans the protocol allows between something the PLC or the PA-CONTROL does and the first scan
// that can show its effect, derived from the bus timing alone (BusTiming): the PA-CONTROL's cycles fall
// on multiples of its cycle time (the rig runs the controller's cycle before a PLC scan at the same
// time), each direction delays an image by the latency plus up to the jitter, and a scan reads the
// newest image that has arrived. ScanWindow::min is without jitter, max with the whole jitter both
// ways; without jitter the window is one exact scan. Tests compare the FBs' results with these
// windows instead of scan numbers copied from a run.
#pragma once

#include <chrono>
#include <cstdint>
#include <ostream>

#include "bus_timing.hpp"

namespace pac::test {

struct ScanWindow {
    int min = 0;
    int max = 0;
    bool Contains(int scans) const { return scans >= min && scans <= max; }
    bool Contains(std::int64_t scans) const { return scans >= min && scans <= max; }
};

inline std::ostream& operator<<(std::ostream& out, const ScanWindow& w) {
    if (w.min == w.max) return out << w.min << " scans";
    return out << w.min << ".." << w.max << " scans";
}

class ProtocolWindow {
public:
    explicit ProtocolWindow(const BusTiming& timing) : t_(timing) {}

    // Something the PLC writes in the scan at `edge` (a command, a request bit, a Start): the
    // controller's first cycle that reads it acts on it, `extraCycles` more cycles pass transitional
    // statuses (30 before 31, 10 before 11, ...), and the reply of that cycle travels back.
    ScanWindow Request(std::chrono::nanoseconds edge, int extraCycles = 0) const {
        return {Scans(edge, true, extraCycles, Zero()), Scans(edge, true, extraCycles, t_.Jitter())};
    }
    // The fewest scans after the scan at `edge` that can show the answer to what it wrote.
    int Minimum(std::chrono::nanoseconds edge) const { return Request(edge).min; }

    // Something that happens to the controller between the scan at `after` and the next one (a system
    // error raised, an axis error): its next cycle notices it, and the reply of that cycle travels back.
    ScanWindow Event(std::chrono::nanoseconds after) const {
        return {Scans(after, false, 0, Zero()), Scans(after, false, 0, t_.Jitter())};
    }

    // A reply the controller writes at once at `after` (PowerCycle drops the reply to zero at once).
    ScanWindow ImmediateReply(std::chrono::nanoseconds after) const {
        return {Read(after, after, Zero()), Read(after, after, t_.Jitter())};
    }

    // An FB timer started in the edge scan runs out in the first scan at least `timeout` later.
    int TimeoutScans(std::chrono::nanoseconds timeout) const {
        return static_cast<int>((timeout + t_.PlcCycle() - std::chrono::nanoseconds(1)) / t_.PlcCycle());
    }

    // Enough scans for the controller to read what the PLC writes now, to pass a few one-cycle
    // transitional statuses (17 -> 18 -> 19, 16 -> 11) and for the PLC to read the answer: five
    // controller cycles and both directions with their whole jitter.
    int RoundTripScans() const {
        const std::chrono::nanoseconds way = t_.Latency() + t_.Jitter();
        return static_cast<int>((5 * t_.PacCycle() + 2 * way) / t_.PlcCycle()) + 2;
    }

    const BusTiming& Timing() const { return t_; }

private:
    static constexpr std::chrono::nanoseconds Zero() { return std::chrono::nanoseconds(0); }

    int Scans(std::chrono::nanoseconds from, bool throughTheBus, int extraCycles,
              std::chrono::nanoseconds jitter) const {
        const std::chrono::nanoseconds arrival = throughTheBus ? from + t_.Latency() + jitter : from;
        std::chrono::nanoseconds cycle = (arrival / t_.PacCycle()) * t_.PacCycle();
        while (cycle < arrival || cycle <= from) cycle += t_.PacCycle();
        return Read(from, cycle + extraCycles * t_.PacCycle(), jitter);
    }
    int Read(std::chrono::nanoseconds from, std::chrono::nanoseconds written, std::chrono::nanoseconds jitter) const {
        const std::chrono::nanoseconds arrival = written + t_.Latency() + jitter;
        std::chrono::nanoseconds scan = from + t_.PlcCycle();
        while (scan < arrival) scan += t_.PlcCycle();
        return static_cast<int>((scan - from) / t_.PlcCycle());
    }

    BusTiming t_;
};

}  // namespace pac::test
