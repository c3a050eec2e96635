// The IEEE-754 bit pattern of a C++ float and back, by plain reinterpretation: the reference the
// library's arithmetic conversions and the bus images are checked against.
#pragma once

#include <cstdint>
#include <cstring>

namespace pac::test {

inline std::uint32_t BitsOf(float f) {
    std::uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

inline float FloatOf(std::uint32_t b) {
    float f;
    std::memcpy(&f, &b, sizeof f);
    return f;
}

}  // namespace pac::test
