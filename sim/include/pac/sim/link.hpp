// One direction of the fieldbus between the PLC and the PA-CONTROL (to PAC or from PAC): the writer's
// process image (all modules, one consistent block, manual 2.3.3) reaches the reader after a latency
// plus a seeded jitter, in order, and the link can be faulted. Times are simulated (the caller's
// clock); nothing here reads a real clock.
//
//   Write(now, image): the image arrives at now + latency + jitter, jitter uniform in [0, jitter]
//       drawn from the seed, but never before the previous write's arrival (order is preserved).
//   Read(now): the newest image whose arrival time is <= now; zero bytes before the first arrival.
//   Every image has the link's size (8 bytes: the CMD module alone); another size: std::invalid_argument.
//
// Faults (SetFault):
//   kFrozen       the reader keeps seeing the image it would have read at the moment of the freeze;
//                 writes still travel and the reader sees the newest one once the fault is cleared.
//   kAllZero      the reader sees zero bytes; writes still travel (cleared: the newest arrival).
//   kDisconnected the reader sees zero bytes; images in flight are lost, writes are dropped, and
//                 after reconnection (SetFault(now, kNone)) the reader keeps seeing zeros until the
//                 first image written after the reconnection arrives.
//
// Tearing (LinkConfig::tearPercent, for buses without module consistency such as Interbus-S, 4.2.4):
//   a Read that finds a newly arrived image catches it, with that chance in percent, in the middle of
//   its update: each byte is the newest image's or the one that arrived just before it, drawn from the
//   seed (a generator of its own, so the jitter draws stay the same). The next read sees it whole.
// Writes must come in non-decreasing time, and so must reads and SetFault calls (a fault acts at the
// reader's side); std::invalid_argument otherwise.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>

#include "pac/sim/process_image.hpp"
#include "pac/sim/ring_buffer.hpp"
#include "pac/sim/rng.hpp"

namespace pac::sim {

enum class LinkFault { kNone, kFrozen, kAllZero, kDisconnected };

const char* ToString(LinkFault fault);

struct LinkConfig {
    std::chrono::nanoseconds latency{0};
    std::chrono::nanoseconds jitter{0};  // extra delay, uniform in [0, jitter]
    std::uint64_t seed = 1;
    int tearPercent = 0;  // 0..100: chance that the first read of a new image sees it torn
};

class Link {
public:
    // Negative latency or jitter, or an image size of 0: std::invalid_argument.
    explicit Link(LinkConfig config = {}, std::size_t imageBytes = 8);

    void Write(std::chrono::nanoseconds now, const ProcessImage& image);
    ProcessImage Read(std::chrono::nanoseconds now);
    std::size_t ImageBytes() const { return imageBytes_; }

    void SetFault(std::chrono::nanoseconds now, LinkFault fault);
    LinkFault Fault() const { return fault_; }
    bool Connected() const { return fault_ != LinkFault::kDisconnected; }

    // Take effect for later writes; order is still preserved.
    void SetLatency(std::chrono::nanoseconds latency);
    void SetJitter(std::chrono::nanoseconds jitter);
    void SetTearPercent(int percent);  // outside 0..100: std::invalid_argument
    const LinkConfig& Config() const { return config_; }

    // Arrival time of the newest image written so far (for tests of the ordering rule).
    std::chrono::nanoseconds LastArrival() const { return lastArrival_; }
    std::uint64_t WritesDropped() const { return writesDropped_; }
    std::uint64_t TornReads() const { return tornReads_; }  // reads that returned a torn image

private:
    struct InFlight {
        std::chrono::nanoseconds arrival{0};
        ProcessImage image;
    };

    void Deliver(std::chrono::nanoseconds now);  // moves arrived images to Delivered()
    ProcessImage ReadDelivered();                 // Delivered(), or torn on its first read
    void CheckReaderTime(std::chrono::nanoseconds now, const char* what);
    // The newest image arrived, and the one that arrived just before it: two slots in turn, so that an
    // arrival copies one image.
    ProcessImage& Delivered() { return delivered_[newest_]; }
    const ProcessImage& Delivered() const { return delivered_[newest_]; }
    const ProcessImage& BeforeDelivered() const { return delivered_[1 - newest_]; }

    LinkConfig config_;
    SplitMix64 rng_;
    SplitMix64 tearRng_;
    RingBuffer<InFlight> inFlight_;  // oldest first; allocates only while more are in flight than ever before
    std::size_t imageBytes_;
    ProcessImage delivered_[2];
    int newest_ = 0;                // Delivered() is delivered_[newest_]
    bool unread_ = false;           // Delivered() arrived after the last read
    ProcessImage frozen_;
    LinkFault fault_ = LinkFault::kNone;
    std::chrono::nanoseconds lastArrival_{std::chrono::nanoseconds::min()};
    std::chrono::nanoseconds lastWrite_{std::chrono::nanoseconds::min()};
    std::chrono::nanoseconds lastRead_{std::chrono::nanoseconds::min()};
    std::uint64_t writesDropped_ = 0;
    std::uint64_t tornReads_ = 0;
};

}  // namespace pac::sim
