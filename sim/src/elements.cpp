// Numbered bits and registers of the PA-CONTROL (see elements.hpp).
#include "pac/sim/elements.hpp"

#include <stdexcept>
#include <string>

#include "pac/sim/image8.hpp"

namespace pac::sim {

namespace {

int CheckedCount(int count) {
    if (count < 0) throw std::invalid_argument("element count must be >= 0");
    return count;
}

[[noreturn]] void OutOfRange(const char* what, int number, int count) {
    throw std::out_of_range(std::string(what) + ": number " + std::to_string(number) + " outside 1.." +
                            std::to_string(count));
}

}  // namespace

BitBank::BitBank(int count) : bits_(static_cast<std::size_t>(CheckedCount(count)), false) {}

bool BitBank::Get(int number) const {
    if (!Contains(number)) OutOfRange("BitBank::Get", number, Count());
    return bits_[static_cast<std::size_t>(number - 1)];
}

void BitBank::Set(int number, bool value) {
    if (!Contains(number)) OutOfRange("BitBank::Set", number, Count());
    bits_[static_cast<std::size_t>(number - 1)] = value;
}

std::uint16_t BitBank::Word(int number) const {
    if (!Contains(number)) OutOfRange("BitBank::Word", number, Count());
    const int first = (number - 1) / 16 * 16 + 1;
    std::uint16_t word = 0;
    for (int bit = 0; bit < 16 && first + bit <= Count(); ++bit) {
        if (bits_[static_cast<std::size_t>(first + bit - 1)]) word |= static_cast<std::uint16_t>(1U << bit);
    }
    return word;
}

void BitBank::SetWord(int number, std::uint16_t value) {
    if (!Contains(number)) OutOfRange("BitBank::SetWord", number, Count());
    const int first = (number - 1) / 16 * 16 + 1;
    for (int bit = 0; bit < 16 && first + bit <= Count(); ++bit) {
        bits_[static_cast<std::size_t>(first + bit - 1)] = ((value >> bit) & 1U) != 0;
    }
}

void BitBank::Clear() { bits_.assign(bits_.size(), false); }

RegisterBank::RegisterBank(int count) : cells_(static_cast<std::size_t>(CheckedCount(count)), 0) {}

std::uint32_t RegisterBank::Get(int number) const {
    if (!Contains(number)) OutOfRange("RegisterBank::Get", number, Count());
    return cells_[static_cast<std::size_t>(number - 1)];
}

void RegisterBank::Set(int number, std::uint32_t value) {
    if (!Contains(number)) OutOfRange("RegisterBank::Set", number, Count());
    cells_[static_cast<std::size_t>(number - 1)] = value;
}

void RegisterBank::Clear() { cells_.assign(cells_.size(), 0); }

float RegisterBank::GetReal(int number) const { return BitsToFloat(Get(number)); }

void RegisterBank::SetReal(int number, float value) { Set(number, FloatToBits(value)); }

Elements::Elements(const ElementCounts& counts)
    : inputs(counts.inputs),
      outputs(counts.outputs),
      flags(counts.flags),
      intRegisters(counts.intRegisters),
      realRegisters(counts.realRegisters),
      systemFlags(counts.systemFlags),
      systemIntRegisters(counts.systemIntRegisters),
      systemRealRegisters(counts.systemRealRegisters) {}

}  // namespace pac::sim
