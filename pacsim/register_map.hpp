// The Modbus register map of one simulated PA-CONTROL behind a Profibus-to-Modbus gateway
// (docs/virtual_commissioning.md, "The register map"). The process image of each direction is laid out in
// registers of two bytes, PAC byte 2n in the high byte of register n, so a big-endian word of a module lands
// in one register as it is and a dword in two, high word first:
//   holding registers 0..          the PLC-to-controller image (to PAC): CMD, CTRL, axis modules; read and write
//   input registers 0..            the controller-to-PLC image (from PAC), the same offsets; read only
//   holding registers 1024..       the controller-to-PLC image again, for masters that read holding registers only
#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "pac/sim/process_image.hpp"

namespace pac::pacsim {

// Where the from-PAC image starts among the holding registers.
constexpr int kFromPacHoldingBase = 1024;

// One module of the layout and its registers (the same numbers in both directions).
struct ModuleRegisters {
    std::string name;    // "CMD", "CTRL", "AXIS 1" .. "AXIS 8"
    std::size_t byte;    // its first byte in the process image
    std::size_t bytes;   // 8 or 12
    int firstRegister;   // byte / 2
    int registers;       // bytes / 2
};

class RegisterMap {
public:
    explicit RegisterMap(const pac::sim::ModuleLayout& layout);

    const std::vector<ModuleRegisters>& Modules() const { return modules_; }
    // Registers of one direction's image: the layout's bytes / 2 (4 for the CMD module alone, up to 56).
    int Registers() const { return registers_; }

    // The image as registers (PAC byte 2n high, 2n + 1 low) and back.
    static std::vector<std::uint16_t> ToRegisters(const pac::sim::ProcessImage& image);
    // Registers [first, first + values.size()) of `image` replaced; the range must lie inside it.
    static void WriteRegisters(pac::sim::ProcessImage& image, int first, const std::vector<std::uint16_t>& values);

    // The table of docs/virtual_commissioning.md for this layout (pac-sim --print-map): one row per module.
    void Print(std::ostream& out) const;

private:
    std::vector<ModuleRegisters> modules_;
    int registers_;
};

}  // namespace pac::pacsim
