// The whole Profibus-DP process image between the PLC and one PA-CONTROL, in either direction (manual
// 2.3): the 8-byte CMD module, then the optional 8-byte CTRL module, then 0..8 axis modules of 12 bytes.
// The bus carries it as one consistent block (2.3.3); PAC byte 0 of the CMD module is byte 0.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>

#include "pac/sim/image8.hpp"

namespace pac::sim {

using Image12 = std::array<std::uint8_t, 12>;

// Which modules a PA-CONTROL's Profibus extension has. Axis modules are extensions 2..9, after the CTRL
// module (extension 1), so they need it (docs/sim_bus.md).
struct ModuleLayout {
    static constexpr int kMaxAxisModules = 8;
    static constexpr std::size_t kCmdOffset = 0;
    static constexpr std::size_t kCtrlOffset = 8;
    static constexpr std::size_t kFirstAxisOffset = 16;  // axis module k at kFirstAxisOffset + 12 * (k - 1)

    bool ctrl = false;
    int axisModules = 0;

    // std::invalid_argument with the reason when the layout is impossible.
    void Validate() const;
    std::size_t Bytes() const;
    // Byte offset of axis module `module` (1..axisModules); std::out_of_range otherwise.
    std::size_t AxisOffset(int module) const {
        if (module < 1 || module > axisModules) ThrowNoAxisModule(module);
        return kFirstAxisOffset + 12 * static_cast<std::size_t>(module - 1);
    }

private:
    [[noreturn]] static void ThrowNoAxisModule(int module);
};

// Inline storage of the largest image (2.3.3: 8, 16, ..., 112 bytes): the simulator copies images several
// times per cycle, and a copy without the heap costs a fraction of one with it.
class ProcessImage {
public:
    static constexpr std::size_t kMaxBytes = 8 + 8 + 12 * ModuleLayout::kMaxAxisModules;

    // More than kMaxBytes: std::invalid_argument.
    explicit ProcessImage(std::size_t bytes = 8) : size_(CheckedSize(bytes)) {}
    // An image of the CMD module alone (implicit: where only the CMD interface is configured, the
    // 8-byte module is the whole image).
    ProcessImage(const Image8& cmd) : size_(cmd.size()) {  // NOLINT(google-explicit-constructor)
        std::copy(cmd.begin(), cmd.end(), bytes_.begin());
    }

    std::size_t Size() const { return size_; }
    const std::uint8_t* Data() const { return bytes_.data(); }
    // Size() bytes: for the simulator's loops over the axis modules, which check the size once per cycle.
    std::uint8_t* Data() { return bytes_.data(); }
    // Bytes at 0..Size()-1; another index: std::out_of_range.
    std::uint8_t& operator[](std::size_t i) { return bytes_[CheckedIndex(i)]; }
    std::uint8_t operator[](std::size_t i) const { return bytes_[CheckedIndex(i)]; }

    // The 8-byte module at `offset` (CMD at 0, CTRL at 8) and the 12-byte module at `offset`;
    // std::out_of_range when it does not fit.
    Image8 Module8(std::size_t offset) const { return Module<8>(offset, "Module8"); }
    void SetModule8(std::size_t offset, const Image8& module) { SetModule(offset, module, "SetModule8"); }
    Image12 Module12(std::size_t offset) const { return Module<12>(offset, "Module12"); }
    void SetModule12(std::size_t offset, const Image12& module) { SetModule(offset, module, "SetModule12"); }
    Image8 Cmd() const { return Module8(ModuleLayout::kCmdOffset); }

    bool AllZero() const;

    friend bool operator==(const ProcessImage& a, const ProcessImage& b) {
        return a.size_ == b.size_ && std::equal(a.bytes_.begin(), a.bytes_.begin() + Offset(a.size_), b.bytes_.begin());
    }
    friend bool operator!=(const ProcessImage& a, const ProcessImage& b) { return !(a == b); }

private:
    static std::size_t CheckedSize(std::size_t bytes) {
        if (bytes > kMaxBytes) ThrowSize(bytes);
        return bytes;
    }
    [[noreturn]] static void ThrowSize(std::size_t bytes);
    [[noreturn]] static void ThrowIndex(std::size_t i, std::size_t size);
    [[noreturn]] static void ThrowFit(std::size_t offset, std::size_t length, std::size_t size, const char* what);
    static std::ptrdiff_t Offset(std::size_t i) { return static_cast<std::ptrdiff_t>(i); }

    std::size_t CheckedIndex(std::size_t i) const {
        if (i >= size_) ThrowIndex(i, size_);
        return i;
    }
    void CheckFits(std::size_t offset, std::size_t length, const char* what) const {
        if (offset > size_ || length > size_ - offset) ThrowFit(offset, length, size_, what);
    }
    template <std::size_t N>
    std::array<std::uint8_t, N> Module(std::size_t offset, const char* what) const {
        CheckFits(offset, N, what);
        std::array<std::uint8_t, N> m{};
        std::copy_n(bytes_.begin() + Offset(offset), N, m.begin());
        return m;
    }
    template <std::size_t N>
    void SetModule(std::size_t offset, const std::array<std::uint8_t, N>& module, const char* what) {
        CheckFits(offset, N, what);
        std::copy(module.begin(), module.end(), bytes_.begin() + Offset(offset));
    }

    std::array<std::uint8_t, kMaxBytes> bytes_{};
    std::size_t size_;
};

// Upper-case hex, one space between bytes, modules separated by " | " when `layout` is given.
std::string ToHex(const ProcessImage& image);
std::string ToHex(const ProcessImage& image, const ModuleLayout& layout);
std::ostream& operator<<(std::ostream& out, const ProcessImage& image);

// Big-endian fields of a 12-byte module (2.7.1/2.7.2): dword at byte 0 or 8, word at byte 4 or 6; a field
// outside the module: std::out_of_range. Inline: the simulator reads and writes them for every axis in every
// cycle.
namespace detail {
[[noreturn]] void ThrowModuleOffset(int byteOffset);
inline std::size_t ModuleField(int byteOffset, int length) {
    if (byteOffset < 0 || byteOffset + length > 12) ThrowModuleOffset(byteOffset);
    return static_cast<std::size_t>(byteOffset);
}
}  // namespace detail

inline std::uint32_t ReadDword(const Image12& m, int byteOffset) {
    const std::size_t k = detail::ModuleField(byteOffset, 4);
    return static_cast<std::uint32_t>(m[k]) << 24 | static_cast<std::uint32_t>(m[k + 1]) << 16 |
           static_cast<std::uint32_t>(m[k + 2]) << 8 | m[k + 3];
}

inline void WriteDword(Image12& m, int byteOffset, std::uint32_t value) {
    const std::size_t k = detail::ModuleField(byteOffset, 4);
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    // One store of the swapped value: byte by byte, g++ assembles the bytes in a register, a shift each.
    const std::uint32_t big = __builtin_bswap32(value);
    std::memcpy(m.data() + k, &big, sizeof big);
#else
    m[k] = static_cast<std::uint8_t>(value >> 24);
    m[k + 1] = static_cast<std::uint8_t>(value >> 16);
    m[k + 2] = static_cast<std::uint8_t>(value >> 8);
    m[k + 3] = static_cast<std::uint8_t>(value);
#endif
}

inline std::uint16_t ReadWordAt(const Image12& m, int byteOffset) {
    const std::size_t k = detail::ModuleField(byteOffset, 2);
    return static_cast<std::uint16_t>(m[k] << 8 | m[k + 1]);
}

inline void WriteWordAt(Image12& m, int byteOffset, std::uint16_t value) {
    const std::size_t k = detail::ModuleField(byteOffset, 2);
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    const std::uint16_t big = __builtin_bswap16(value);
    std::memcpy(m.data() + k, &big, sizeof big);
#else
    m[k] = static_cast<std::uint8_t>(value >> 8);
    m[k + 1] = static_cast<std::uint8_t>(value);
#endif
}

}  // namespace pac::sim
