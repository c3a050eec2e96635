// Every one of the 2^32 bit patterns through F_PAC_DwordToReal and back through F_PAC_RealToDword,
// on every core: each finite pattern except -0.0 (which encodes as 0, docs/ieee754.md) must come back
// unchanged. Too long for the test run (minutes), so a target of its own:
//   cmake --build build --target ieee_exhaustive_run
// Prints the patterns checked, the mismatches (the first few by value) and the time; exits 1 on any.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <thread>
#include <vector>

#include "pac/st_program.hpp"
#include "real_bits.hpp"

namespace {

bool IsFinitePattern(std::uint32_t b) { return (b & 0x7F800000u) != 0x7F800000u; }

struct Tally {
    std::atomic<std::uint64_t> checked{0};
    std::atomic<std::uint64_t> mismatches{0};
    std::mutex firstMutex;
    std::vector<std::uint32_t> first;  // the first mismatching patterns found, for the report
};

void Check(std::uint64_t begin, std::uint64_t end, Tally& tally) {
    std::uint64_t checked = 0;
    for (std::uint64_t i = begin; i < end; ++i) {
        const auto b = static_cast<std::uint32_t>(i);
        if (!IsFinitePattern(b) || b == 0x80000000u) continue;
        ++checked;
        const float r = F_PAC_DWORDTOREAL(1, nullptr, b);
        const std::uint32_t back = F_PAC_REALTODWORD(1, nullptr, pac::test::FloatOf(b));
        if (pac::test::BitsOf(r) != b || back != b) {
            tally.mismatches.fetch_add(1);
            std::lock_guard<std::mutex> lock(tally.firstMutex);
            if (tally.first.size() < 10) tally.first.push_back(b);
        }
    }
    tally.checked.fetch_add(checked);
}

}  // namespace

int main() {
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    const std::uint64_t total = 1ull << 32;
    const auto start = std::chrono::steady_clock::now();
    Tally tally;
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) {
        pool.emplace_back(Check, total * t / threads, total * (t + 1) / threads, std::ref(tally));
    }
    for (auto& thread : pool) thread.join();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("IEEE-754 round trip of every finite pattern but -0.0: %llu checked, %llu mismatches, "
                "%.1f s on %u threads\n",
                static_cast<unsigned long long>(tally.checked.load()),
                static_cast<unsigned long long>(tally.mismatches.load()), seconds, threads);
    std::sort(tally.first.begin(), tally.first.end());
    for (std::uint32_t b : tally.first) std::printf("  mismatch at 0x%08X\n", b);
    return tally.mismatches.load() == 0 ? 0 : 1;
}
