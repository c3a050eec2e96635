// The whole Profibus-DP process image between the PLC and one PA-CONTROL, in either direction (manual
// 2.3): the 8-byte CMD module, then the optional 8-byte CTRL module, then 0..8 axis modules of 12 bytes.
// The bus carries it as one consistent block (2.3.3); PAC byte 0 of the CMD module is byte 0.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "pac/sim/image8.hpp"

namespace pac::sim {

using Image12 = std::array<std::uint8_t, 12>;

// Which modules a PA-CONTROL's Profibus extension has. Axis modules are extensions 2..9, after the CTRL
// module (extension 1), so they need it (docs/sim_bus.md).
struct ModuleLayout {
    static constexpr int kMaxAxisModules = 8;
    static constexpr std::size_t kCmdOffset = 0;
    static constexpr std::size_t kCtrlOffset = 8;

    bool ctrl = false;
    int axisModules = 0;

    // std::invalid_argument with the reason when the layout is impossible.
    void Validate() const;
    std::size_t Bytes() const;
    // Byte offset of axis module `module` (1..axisModules); std::out_of_range otherwise.
    std::size_t AxisOffset(int module) const;
};

class ProcessImage {
public:
    explicit ProcessImage(std::size_t bytes = 8) : bytes_(bytes, 0) {}
    // An image of the CMD module alone (implicit: where only the CMD interface is configured, the
    // 8-byte module is the whole image).
    ProcessImage(const Image8& cmd) : bytes_(cmd.begin(), cmd.end()) {}  // NOLINT(google-explicit-constructor)

    std::size_t Size() const { return bytes_.size(); }
    const std::vector<std::uint8_t>& Bytes() const { return bytes_; }
    std::uint8_t& operator[](std::size_t i) { return bytes_.at(i); }
    std::uint8_t operator[](std::size_t i) const { return bytes_.at(i); }

    // The 8-byte module at `offset` (CMD at 0, CTRL at 8) and the 12-byte module at `offset`;
    // std::out_of_range when it does not fit.
    Image8 Module8(std::size_t offset) const;
    void SetModule8(std::size_t offset, const Image8& module);
    Image12 Module12(std::size_t offset) const;
    void SetModule12(std::size_t offset, const Image12& module);
    Image8 Cmd() const { return Module8(ModuleLayout::kCmdOffset); }

    bool AllZero() const;

    friend bool operator==(const ProcessImage& a, const ProcessImage& b) { return a.bytes_ == b.bytes_; }
    friend bool operator!=(const ProcessImage& a, const ProcessImage& b) { return !(a == b); }

private:
    std::vector<std::uint8_t> bytes_;
};

// Upper-case hex, one space between bytes, modules separated by " | " when `layout` is given.
std::string ToHex(const ProcessImage& image);
std::string ToHex(const ProcessImage& image, const ModuleLayout& layout);
std::ostream& operator<<(std::ostream& out, const ProcessImage& image);

// Big-endian fields of a 12-byte module (2.7.1/2.7.2): dword at byte 0 or 8, word at byte 4 or 6.
std::uint32_t ReadDword(const Image12& module, int byteOffset);
void WriteDword(Image12& module, int byteOffset, std::uint32_t value);
std::uint16_t ReadWordAt(const Image12& module, int byteOffset);
void WriteWordAt(Image12& module, int byteOffset, std::uint16_t value);

}  // namespace pac::sim
