// The process image and its module layout (see process_image.hpp).
#include "pac/sim/process_image.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pac::sim {

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

void ModuleLayout::ThrowNoAxisModule(int module) {
    throw std::out_of_range("ModuleLayout: axis module " + std::to_string(module) + " not configured");
}

void ProcessImage::ThrowSize(std::size_t bytes) {
    throw std::invalid_argument("ProcessImage: " + std::to_string(bytes) + " bytes; a PA-CONTROL's image has " +
                                "at most " + std::to_string(kMaxBytes));
}

void ProcessImage::ThrowIndex(std::size_t i, std::size_t size) {
    throw std::out_of_range("ProcessImage: byte " + std::to_string(i) + " of " + std::to_string(size));
}

void ProcessImage::ThrowFit(std::size_t offset, std::size_t length, std::size_t size, const char* what) {
    throw std::out_of_range(std::string("ProcessImage::") + what + ": " + std::to_string(length) +
                            " bytes at offset " + std::to_string(offset) + " do not fit " + std::to_string(size));
}

bool ProcessImage::AllZero() const {
    return std::all_of(bytes_.begin(), bytes_.begin() + Offset(size_), [](std::uint8_t b) { return b == 0; });
}

std::string ToHex(const ProcessImage& image) { return HexBytes(image.Data(), image.Size()); }

std::string ToHex(const ProcessImage& image, const ModuleLayout& layout) {
    const std::uint8_t* bytes = image.Data();
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

namespace detail {

void ThrowModuleOffset(int byteOffset) {
    throw std::out_of_range("Image12: offset " + std::to_string(byteOffset) + " out of range");
}

}  // namespace detail

}  // namespace pac::sim
