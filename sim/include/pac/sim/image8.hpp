// The 8-byte CMD module (manual 2.4, 4.2.2) as the bus carries it, and big-endian access at PAC byte
// offsets: word n is bytes 2n (high) and 2n+1 (low); a dword at byte offset k is bytes k..k+3, MSB
// first. Offsets outside the image throw std::out_of_range.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace pac::sim {

using Image8 = std::array<std::uint8_t, 8>;

namespace detail {
[[noreturn]] void ThrowImage8Offset(int offset, const char* what);
inline std::size_t Image8Field(int offset, int width, const char* what) {
    if (offset < 0 || offset + width > 8) ThrowImage8Offset(offset, what);
    return static_cast<std::size_t>(offset);
}
}  // namespace detail

// Inline: the simulator encodes and decodes the CMD module in every cycle, and a call per field cost more
// than the field.

// Word n (0..3) of the image.
inline std::uint16_t ReadWord(const Image8& image, int word) {
    const std::size_t k = detail::Image8Field(word * 2, 2, "ReadWord");
    return static_cast<std::uint16_t>((image[k] << 8) | image[k + 1]);
}
inline void WriteWord(Image8& image, int word, std::uint16_t value) {
    const std::size_t k = detail::Image8Field(word * 2, 2, "WriteWord");
    image[k] = static_cast<std::uint8_t>(value >> 8);
    image[k + 1] = static_cast<std::uint8_t>(value & 0xFF);
}

// Dword at PAC byte offset 0..4 (the CMD data dword is at 0).
inline std::uint32_t ReadDword(const Image8& image, int byteOffset) {
    const std::size_t k = detail::Image8Field(byteOffset, 4, "ReadDword");
    return static_cast<std::uint32_t>(image[k]) << 24 | static_cast<std::uint32_t>(image[k + 1]) << 16 |
           static_cast<std::uint32_t>(image[k + 2]) << 8 | image[k + 3];
}
inline void WriteDword(Image8& image, int byteOffset, std::uint32_t value) {
    const std::size_t k = detail::Image8Field(byteOffset, 4, "WriteDword");
    image[k] = static_cast<std::uint8_t>(value >> 24);
    image[k + 1] = static_cast<std::uint8_t>(value >> 16);
    image[k + 2] = static_cast<std::uint8_t>(value >> 8);
    image[k + 3] = static_cast<std::uint8_t>(value);
}

// IEEE-754 single precision, as the PA-CONTROL carries REAL values in a dword (manual 6.1).
std::uint32_t FloatToBits(float value);
float BitsToFloat(std::uint32_t bits);

// "00 00 00 01 00 01 A0 00": upper-case hex, one space between bytes, PAC byte 0 first.
std::string ToHex(const Image8& image);
// The same for any run of bytes.
std::string HexBytes(const std::uint8_t* bytes, std::size_t count);
// The reverse: 8 hex bytes, separated by single spaces or not at all; std::invalid_argument otherwise.
Image8 FromHex(const std::string& text);

bool IsAllZero(const Image8& image);

}  // namespace pac::sim
