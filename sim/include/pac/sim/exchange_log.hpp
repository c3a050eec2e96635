// What the simulated PA-CONTROL saw and answered, cycle by cycle: for timelines in test failures
// (Format()) and for tests that check when a reply appeared. Keeps the newest `capacity` records, in a
// RingBuffer: a cycle of the controller writes its record over the oldest one, without allocating.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

#include "pac/sim/process_image.hpp"
#include "pac/sim/ring_buffer.hpp"

namespace pac::sim {

struct ExchangeRecord {
    std::chrono::nanoseconds time{0};
    ProcessImage toPac;    // the image the cycle read from the bus
    ProcessImage fromPac;  // the reply it wrote
    bool newCommand = false;  // the cycle recognised a SEND flag change
};

class ExchangeLog {
public:
    // Records per allocation: a test's controller logs hundreds to thousands of cycles, so the log grows in
    // blocks of 64 (about 16 KB) rather than the ring's default 16.
    static constexpr std::size_t kChunk = 64;

    explicit ExchangeLog(std::size_t capacity) : capacity_(capacity), records_(capacity) {}

    void Add(const ExchangeRecord& record) { Add(record.time, record.toPac, record.fromPac, record.newCommand); }
    void Add(std::chrono::nanoseconds time, const ProcessImage& toPac, const ProcessImage& fromPac, bool newCommand) {
        if (capacity_ == 0) return;
        ExchangeRecord& record = records_.push_back();
        record.time = time;
        record.toPac = toPac;
        record.fromPac = fromPac;
        record.newCommand = newCommand;
    }
    void Clear() { records_.clear(); }
    // Oldest first; read as a std::deque (size(), [k], back(), iterators).
    const RingBuffer<ExchangeRecord, kChunk>& Records() const { return records_; }
    std::size_t Capacity() const { return capacity_; }

    // One line per record:
    //   "   40 ms  to PAC 00 00 00 00 00 05 99 00  from PAC 00 00 00 01 00 01 A0 00  <- new command".
    // With changesOnly, a record is left out when both images equal the previous record's.
    std::string Format(bool changesOnly = true) const;

private:
    std::size_t capacity_;
    RingBuffer<ExchangeRecord, kChunk> records_;
};

// "12 ms", "12.5 ms": exact.
std::string FormatTime(std::chrono::nanoseconds t);

}  // namespace pac::sim
