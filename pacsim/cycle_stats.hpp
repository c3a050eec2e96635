// pac-sim --stats: how late the controllers' cycles run on the wall clock, and the CPU the process used
// (docs/virtual_commissioning.md, "Figures"). A cycle's lateness is the wall time at which the loop ran it minus
// its own time; the figures are a histogram of 10 us buckets up to 1 s, so hours of cycles take no more memory.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <ostream>

namespace pac::pacsim {

class CycleStats {
public:
    void Add(std::chrono::nanoseconds lateness);
    std::uint64_t Cycles() const { return count_; }
    // The upper edge of the bucket that holds the fraction `q` (0..1] of the cycles, at most Max(); 0 without cycles.
    std::chrono::microseconds Quantile(double q) const;
    std::chrono::microseconds Max() const { return std::chrono::duration_cast<std::chrono::microseconds>(max_); }

    // "cycles N, lateness p50 A us, p99 B us, max C us; CPU D % of one core over E s"
    void Print(std::ostream& out, std::chrono::nanoseconds wall) const;

private:
    static constexpr std::int64_t kBucketUs = 10;
    static constexpr std::size_t kBuckets = 100000;  // 1 s; later cycles count in the last bucket
    std::array<std::uint64_t, kBuckets> buckets_{};
    std::uint64_t count_ = 0;
    std::chrono::nanoseconds max_{0};
};

}  // namespace pac::pacsim
