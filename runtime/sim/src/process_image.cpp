// The process image and its module layout (see process_image.hpp).
#include "pac/sim/process_image.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pac::sim {

namespace {

void CheckFits(std::size_t offset, std::size_t length, std::size_t size, const char* what) {
    if (offset > size || length > size - offset) {
        throw std::out_of_range(std::string("ProcessImage::") + what + ": " + std::to_string(length) +
                                " bytes at offset " + std::to_string(offset) + " do not fit " +
                                std::to_string(size));
    }
}

void CheckModuleOffset(int byteOffset, int length) {
    if (byteOffset < 0 || byteOffset + length > 12) {
        throw std::out_of_range("Image12: offset " + std::to_string(byteOffset) + " out of range");
    }
}

}  // namespace

void ModuleLayout::Validate() const {
    if (axisModules < 0 || axisModules > kMaxAxisModules) {
        throw std::invalid_argument("ModuleLayout: " + std::to_string(axisModules) +
                                    " axis modules; a PA-CONTROL has 0 to 8");
    }
    if (axisModules > 0 && !ctrl) {
        throw std::invalid_argument(
            "ModuleLayout: axis modules are extensions 2..9 and need the CTRL module (extension 1)");
    }
}

std::size_t ModuleLayout::Bytes() const {
    return 8 + (ctrl ? 8 : 0) + 12 * static_cast<std::size_t>(std::max(axisModules, 0));
}

std::size_t ModuleLayout::AxisOffset(int module) const {
    if (module < 1 || module > axisModules) {
        throw std::out_of_range("ModuleLayout: axis module " + std::to_string(module) + " not configured");
    }
    return 16 + 12 * static_cast<std::size_t>(module - 1);
}

Image8 ProcessImage::Module8(std::size_t offset) const {
    CheckFits(offset, 8, bytes_.size(), "Module8");
    Image8 m{};
    std::copy_n(bytes_.begin() + static_cast<std::ptrdiff_t>(offset), 8, m.begin());
    return m;
}

void ProcessImage::SetModule8(std::size_t offset, const Image8& module) {
    CheckFits(offset, 8, bytes_.size(), "SetModule8");
    std::copy(module.begin(), module.end(), bytes_.begin() + static_cast<std::ptrdiff_t>(offset));
}

Image12 ProcessImage::Module12(std::size_t offset) const {
    CheckFits(offset, 12, bytes_.size(), "Module12");
    Image12 m{};
    std::copy_n(bytes_.begin() + static_cast<std::ptrdiff_t>(offset), 12, m.begin());
    return m;
}

void ProcessImage::SetModule12(std::size_t offset, const Image12& module) {
    CheckFits(offset, 12, bytes_.size(), "SetModule12");
    std::copy(module.begin(), module.end(), bytes_.begin() + static_cast<std::ptrdiff_t>(offset));
}

bool ProcessImage::AllZero() const {
    return std::all_of(bytes_.begin(), bytes_.end(), [](std::uint8_t b) { return b == 0; });
}

std::string ToHex(const ProcessImage& image) { return HexBytes(image.Bytes().data(), image.Size()); }

std::string ToHex(const ProcessImage& image, const ModuleLayout& layout) {
    const std::uint8_t* bytes = image.Bytes().data();
    std::string out = HexBytes(bytes, std::min<std::size_t>(8, image.Size()));
    std::size_t offset = 8;
    auto append = [&](std::size_t length) {
        if (offset + length > image.Size()) return;
        out += " | " + HexBytes(bytes + offset, length);
        offset += length;
    };
    if (layout.ctrl) append(8);
    for (int k = 0; k < layout.axisModules; ++k) append(12);
    return out;
}

std::ostream& operator<<(std::ostream& out, const ProcessImage& image) { return out << ToHex(image); }

std::uint32_t ReadDword(const Image12& m, int byteOffset) {
    CheckModuleOffset(byteOffset, 4);
    const auto k = static_cast<std::size_t>(byteOffset);
    return static_cast<std::uint32_t>(m[k]) << 24 | static_cast<std::uint32_t>(m[k + 1]) << 16 |
           static_cast<std::uint32_t>(m[k + 2]) << 8 | m[k + 3];
}

void WriteDword(Image12& m, int byteOffset, std::uint32_t value) {
    CheckModuleOffset(byteOffset, 4);
    const auto k = static_cast<std::size_t>(byteOffset);
    m[k] = static_cast<std::uint8_t>(value >> 24);
    m[k + 1] = static_cast<std::uint8_t>(value >> 16);
    m[k + 2] = static_cast<std::uint8_t>(value >> 8);
    m[k + 3] = static_cast<std::uint8_t>(value);
}

std::uint16_t ReadWordAt(const Image12& m, int byteOffset) {
    CheckModuleOffset(byteOffset, 2);
    const auto k = static_cast<std::size_t>(byteOffset);
    return static_cast<std::uint16_t>(m[k] << 8 | m[k + 1]);
}

void WriteWordAt(Image12& m, int byteOffset, std::uint16_t value) {
    CheckModuleOffset(byteOffset, 2);
    const auto k = static_cast<std::size_t>(byteOffset);
    m[k] = static_cast<std::uint8_t>(value >> 8);
    m[k + 1] = static_cast<std::uint8_t>(value);
}

}  // namespace pac::sim
