// Big-endian access to the 8-byte CMD module (see image8.hpp).
#include "pac/sim/image8.hpp"

#include <cstring>
#include <stdexcept>

namespace pac::sim {

namespace {

int HexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

namespace detail {

void ThrowImage8Offset(int offset, const char* what) {
    throw std::out_of_range(std::string(what) + ": offset " + std::to_string(offset) + " outside the 8-byte image");
}

}  // namespace detail

std::uint32_t FloatToBits(float value) {
    static_assert(sizeof(float) == 4, "IEEE single precision expected");
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

float BitsToFloat(std::uint32_t bits) {
    float value = 0.0F;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

std::string HexBytes(const std::uint8_t* bytes, std::size_t count) {
    static const char* const kDigits = "0123456789ABCDEF";
    std::string out;
    for (std::size_t i = 0; i < count; ++i) {
        if (i != 0) out += ' ';
        out += kDigits[bytes[i] >> 4];
        out += kDigits[bytes[i] & 0x0F];
    }
    return out;
}

std::string ToHex(const Image8& image) { return HexBytes(image.data(), image.size()); }

Image8 FromHex(const std::string& text) {
    Image8 image{};
    std::size_t pos = 0;
    for (std::size_t i = 0; i < image.size(); ++i) {
        if (i != 0 && pos < text.size() && text[pos] == ' ') ++pos;
        if (pos + 2 > text.size() || HexDigit(text[pos]) < 0 || HexDigit(text[pos + 1]) < 0) {
            throw std::invalid_argument("FromHex: expected 8 hex bytes in \"" + text + "\"");
        }
        image[i] = static_cast<std::uint8_t>(HexDigit(text[pos]) * 16 + HexDigit(text[pos + 1]));
        pos += 2;
    }
    if (pos != text.size()) {
        throw std::invalid_argument("FromHex: trailing characters in \"" + text + "\"");
    }
    return image;
}

bool IsAllZero(const Image8& image) {
    for (auto b : image) {
        if (b != 0) return false;
    }
    return true;
}

}  // namespace pac::sim
