// One direction of the simulated fieldbus (see link.hpp).
#include "pac/sim/link.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pac::sim {

namespace {

void CheckDelay(std::chrono::nanoseconds value, const char* what) {
    if (value < std::chrono::nanoseconds::zero()) {
        throw std::invalid_argument(std::string("Link: negative ") + what);
    }
}

void CheckTearPercent(int percent) {
    if (percent < 0 || percent > 100) throw std::invalid_argument("Link: tear percent outside 0..100");
}

// Its own stream: a torn link draws the same jitter as an intact one.
constexpr std::uint64_t kTearSeedSalt = 0x7EA5'0F1A'2B3C'4D5EULL;

}  // namespace

const char* ToString(LinkFault fault) {
    switch (fault) {
        case LinkFault::kNone: return "none";
        case LinkFault::kFrozen: return "frozen";
        case LinkFault::kAllZero: return "all-zero";
        case LinkFault::kDisconnected: return "disconnected";
    }
    return "?";
}

Link::Link(LinkConfig config, std::size_t imageBytes)
    : config_(config),
      rng_(config.seed),
      tearRng_(config.seed ^ kTearSeedSalt),
      imageBytes_(imageBytes),
      delivered_{ProcessImage(imageBytes), ProcessImage(imageBytes)},
      frozen_(imageBytes) {
    CheckDelay(config_.latency, "latency");
    CheckDelay(config_.jitter, "jitter");
    CheckTearPercent(config_.tearPercent);
    if (imageBytes == 0) throw std::invalid_argument("Link: image size 0");
}

void Link::Write(std::chrono::nanoseconds now, const ProcessImage& image) {
    if (image.Size() != imageBytes_) {
        throw std::invalid_argument("Link::Write: a " + std::to_string(image.Size()) + "-byte image on a " +
                                    std::to_string(imageBytes_) + "-byte link");
    }
    if (now < lastWrite_) {
        throw std::invalid_argument("Link::Write: time runs backwards (" + std::to_string(now.count()) +
                                    " ns after " + std::to_string(lastWrite_.count()) + " ns)");
    }
    lastWrite_ = now;
    if (fault_ == LinkFault::kDisconnected) {
        ++writesDropped_;
        return;
    }
    const auto extra = std::chrono::nanoseconds(
        static_cast<std::int64_t>(rng_.UniformUpTo(static_cast<std::uint64_t>(config_.jitter.count()))));
    const auto arrival = std::max(now + config_.latency + extra, lastArrival_);
    lastArrival_ = arrival;
    InFlight& slot = inFlight_.push_back();
    slot.arrival = arrival;
    slot.image = image;
}

ProcessImage Link::Read(std::chrono::nanoseconds now) {
    CheckReaderTime(now, "Read");
    Deliver(now);
    switch (fault_) {
        case LinkFault::kNone: return ReadDelivered();
        case LinkFault::kFrozen: return frozen_;
        case LinkFault::kAllZero:
        case LinkFault::kDisconnected: return ProcessImage(imageBytes_);
    }
    return ProcessImage(imageBytes_);
}

void Link::SetFault(std::chrono::nanoseconds now, LinkFault fault) {
    CheckReaderTime(now, "SetFault");
    Deliver(now);
    if (fault == LinkFault::kFrozen && fault_ != LinkFault::kFrozen) {
        // What the reader would see now (zeros if the link was down or zeroed until this moment).
        frozen_ = fault_ == LinkFault::kNone ? Delivered() : ProcessImage(imageBytes_);
    }
    if (fault == LinkFault::kDisconnected && fault_ != LinkFault::kDisconnected) {
        inFlight_.clear();
        Delivered() = ProcessImage(imageBytes_);
    }
    fault_ = fault;
}

void Link::SetLatency(std::chrono::nanoseconds latency) {
    CheckDelay(latency, "latency");
    config_.latency = latency;
}

void Link::SetJitter(std::chrono::nanoseconds jitter) {
    CheckDelay(jitter, "jitter");
    config_.jitter = jitter;
}

void Link::SetTearPercent(int percent) {
    CheckTearPercent(percent);
    config_.tearPercent = percent;
}

void Link::Deliver(std::chrono::nanoseconds now) {
    while (!inFlight_.empty() && inFlight_.front().arrival <= now) {
        newest_ = 1 - newest_;  // the newest so far becomes the one before
        Delivered() = inFlight_.front().image;
        unread_ = true;
        inFlight_.pop_front();
    }
}

ProcessImage Link::ReadDelivered() {
    const bool fresh = unread_;
    unread_ = false;
    const ProcessImage& delivered = Delivered();
    if (!fresh || config_.tearPercent == 0 || delivered == BeforeDelivered()) return delivered;
    if (tearRng_.UniformUpTo(99) >= static_cast<std::uint64_t>(config_.tearPercent)) return delivered;
    ProcessImage torn = delivered;
    for (std::size_t i = 0; i < imageBytes_; ++i) {
        if ((tearRng_.Next() & 1U) != 0) torn[i] = BeforeDelivered()[i];
    }
    if (torn != delivered) ++tornReads_;
    return torn;
}

void Link::CheckReaderTime(std::chrono::nanoseconds now, const char* what) {
    if (now < lastRead_) {
        throw std::invalid_argument(std::string("Link::") + what + ": time runs backwards (" +
                                    std::to_string(now.count()) + " ns after " +
                                    std::to_string(lastRead_.count()) + " ns)");
    }
    lastRead_ = now;
}

}  // namespace pac::sim
