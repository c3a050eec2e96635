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
    : config_(config), rng_(config.seed), imageBytes_(imageBytes), delivered_(imageBytes), frozen_(imageBytes) {
    CheckDelay(config_.latency, "latency");
    CheckDelay(config_.jitter, "jitter");
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
    inFlight_.push_back(InFlight{arrival, image});
}

ProcessImage Link::Read(std::chrono::nanoseconds now) {
    CheckReaderTime(now, "Read");
    Deliver(now);
    switch (fault_) {
        case LinkFault::kNone: return delivered_;
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
        frozen_ = fault_ == LinkFault::kNone ? delivered_ : ProcessImage(imageBytes_);
    }
    if (fault == LinkFault::kDisconnected && fault_ != LinkFault::kDisconnected) {
        inFlight_.clear();
        delivered_ = ProcessImage(imageBytes_);
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

void Link::Deliver(std::chrono::nanoseconds now) {
    while (!inFlight_.empty() && inFlight_.front().arrival <= now) {
        delivered_ = inFlight_.front().image;
        inFlight_.pop_front();
    }
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
