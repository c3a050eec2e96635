// A small seeded generator (SplitMix64) with its own uniform draw, so a seed gives the same sequence
// on every standard library (std::uniform_int_distribution is implementation-defined).
#pragma once

#include <cstdint>

namespace pac::sim {

class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

    std::uint64_t Next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }

    // Uniform in [0, max], both ends included (rejection sampling, no modulo bias).
    std::uint64_t UniformUpTo(std::uint64_t max) {
        if (max == UINT64_MAX) return Next();
        if (max == 0) {  // a link without jitter draws in every write: the same step, without the divisions
            Next();
            return 0;
        }
        const std::uint64_t range = max + 1;
        const std::uint64_t limit = UINT64_MAX - (UINT64_MAX % range + 1) % range;
        std::uint64_t draw = Next();
        while (draw > limit) draw = Next();
        return draw % range;
    }

private:
    std::uint64_t state_;
};

}  // namespace pac::sim
