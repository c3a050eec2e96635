#include "cycle_stats.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>

namespace pac::pacsim {

void CycleStats::Add(std::chrono::nanoseconds lateness) {
    const auto us = std::chrono::duration_cast<std::chrono::microseconds>(lateness).count();
    const auto bucket = static_cast<std::size_t>(std::clamp<std::int64_t>(us / kBucketUs, 0, kBuckets - 1));
    ++buckets_[bucket];
    ++count_;
    max_ = std::max(max_, lateness);
}

std::chrono::microseconds CycleStats::Quantile(double q) const {
    if (count_ == 0) return std::chrono::microseconds(0);
    const auto rank = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(count_)));
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < kBuckets; ++i) {
        seen += buckets_[i];
        // The bucket's upper edge, but never above the largest value seen (which lies in the last bucket).
        if (seen >= rank) return std::min(std::chrono::microseconds((static_cast<std::int64_t>(i) + 1) * kBucketUs), Max());
    }
    return Max();
}

void CycleStats::Print(std::ostream& out, std::chrono::nanoseconds wall) const {
    timespec cpu{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu);
    const double cpuSeconds = static_cast<double>(cpu.tv_sec) + static_cast<double>(cpu.tv_nsec) * 1e-9;
    const double wallSeconds = std::chrono::duration<double>(wall).count();
    out << "cycles " << count_ << ", lateness p50 " << Quantile(0.5).count() << " us, p99 " << Quantile(0.99).count()
        << " us, max " << Max().count() << " us; CPU " << std::lround(100.0 * cpuSeconds / wallSeconds)
        << " % of one core over " << std::lround(wallSeconds) << " s";
}

}  // namespace pac::pacsim
