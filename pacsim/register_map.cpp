#include "register_map.hpp"

#include <stdexcept>

namespace pac::pacsim {

RegisterMap::RegisterMap(const pac::sim::ModuleLayout& layout) : registers_(static_cast<int>(layout.Bytes() / 2)) {
    auto add = [this](std::string name, std::size_t byte, std::size_t bytes) {
        modules_.push_back({std::move(name), byte, bytes, static_cast<int>(byte / 2), static_cast<int>(bytes / 2)});
    };
    add("CMD", pac::sim::ModuleLayout::kCmdOffset, 8);
    if (layout.ctrl) add("CTRL", pac::sim::ModuleLayout::kCtrlOffset, 8);
    for (int k = 1; k <= layout.axisModules; ++k) add("AXIS " + std::to_string(k), layout.AxisOffset(k), 12);
}

std::vector<std::uint16_t> RegisterMap::ToRegisters(const pac::sim::ProcessImage& image) {
    std::vector<std::uint16_t> registers(image.Size() / 2);
    for (std::size_t n = 0; n < registers.size(); ++n) {
        registers[n] = static_cast<std::uint16_t>(image[2 * n] << 8 | image[2 * n + 1]);
    }
    return registers;
}

void RegisterMap::WriteRegisters(pac::sim::ProcessImage& image, int first, const std::vector<std::uint16_t>& values) {
    const std::size_t end = static_cast<std::size_t>(first) + values.size();
    if (first < 0 || 2 * end > image.Size()) throw std::out_of_range("RegisterMap: registers outside the image");
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::size_t byte = 2 * (static_cast<std::size_t>(first) + i);
        image[byte] = static_cast<std::uint8_t>(values[i] >> 8);
        image[byte + 1] = static_cast<std::uint8_t>(values[i] & 0xFF);
    }
}

void RegisterMap::Print(std::ostream& out) const {
    out << "| module | PAC bytes | to PAC: holding registers | from PAC: input registers | from PAC: holding registers |\n"
        << "|---|---|---|---|---|\n";
    for (const ModuleRegisters& m : modules_) {
        const int last = m.firstRegister + m.registers - 1;
        out << "| " << m.name << " | " << m.byte << ".." << m.byte + m.bytes - 1 << " | " << m.firstRegister << ".."
            << last << " | " << m.firstRegister << ".." << last << " | " << kFromPacHoldingBase + m.firstRegister
            << ".." << kFromPacHoldingBase + last << " |\n";
    }
}

}  // namespace pac::pacsim
