// The fuzzer's input read as a stream of small decisions: every scan of a fuzz target takes the bytes it
// needs from the front. Past the end every read gives zero, so any input, even an empty one, is a whole
// run and the same input always makes the same run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace pac::fuzz {

class FuzzBytes {
public:
    FuzzBytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    bool Exhausted() const { return next_ >= size_; }

    std::uint8_t Byte() { return Exhausted() ? 0 : data_[next_++]; }
    bool Bit() { return (Byte() & 1U) != 0; }
    std::uint16_t Word() { return static_cast<std::uint16_t>((Byte() << 8) | Byte()); }
    std::uint32_t Dword() { return (static_cast<std::uint32_t>(Word()) << 16) | Word(); }
    // Any bit pattern, NaN and infinities included: the PLC program may hand the FB whatever it holds.
    float Real() {
        const std::uint32_t bits = Dword();
        float value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
    }
    // 0..limit-1 (limit > 0).
    unsigned Below(unsigned limit) { return Byte() % limit; }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t next_ = 0;
};

}  // namespace pac::fuzz
