// The PA-CONTROL's elements addressed by number (1-based, manual 5.2.4): inputs, outputs, flags and
// system flags as bit banks; integer registers (N), real registers (R, kept as IEEE bit patterns)
// and the system N and R registers as register banks.
#pragma once

#include <cstdint>
#include <vector>

namespace pac::sim {

// Numbered bits 1..count. Word access follows 5.2.4.2 / 6.3: element n is in word (n-1)/16, at bit
// (n-1)%16 (word 1 = elements 1..16, element 1 at bit 0). Elements past count read 0 and ignore
// writes in a word access. Single access to a number outside 1..count throws std::out_of_range.
class BitBank {
public:
    explicit BitBank(int count);  // count >= 0

    int Count() const { return static_cast<int>(bits_.size()); }
    bool Contains(int number) const { return number >= 1 && number <= Count(); }
    bool Get(int number) const;
    void Set(int number, bool value);
    std::uint16_t Word(int number) const;  // the word holding element `number`
    void SetWord(int number, std::uint16_t value);
    void Clear();

private:
    std::vector<bool> bits_;
};

// Numbered 32-bit cells 1..count (out of range: std::out_of_range).
class RegisterBank {
public:
    explicit RegisterBank(int count);

    int Count() const { return static_cast<int>(cells_.size()); }
    bool Contains(int number) const { return number >= 1 && number <= Count(); }
    std::uint32_t Get(int number) const;
    void Set(int number, std::uint32_t value);
    void Clear();

    // Typed views: N registers are DINT, R registers REAL.
    std::int32_t GetInt(int number) const { return static_cast<std::int32_t>(Get(number)); }
    void SetInt(int number, std::int32_t value) { Set(number, static_cast<std::uint32_t>(value)); }
    float GetReal(int number) const;
    void SetReal(int number, float value);

private:
    std::vector<std::uint32_t> cells_;
};

// How many of each. 5.2.4 gives 1..1024 (16#0001..16#0400) as the parameter range of the element
// commands; 6.2 names system elements up to SM246 / SN86 / SR86 without a total.
struct ElementCounts {
    int inputs = 1024;
    int outputs = 1024;
    int flags = 1024;
    int intRegisters = 1024;
    int realRegisters = 1024;
    int systemFlags = 256;
    int systemIntRegisters = 256;
    int systemRealRegisters = 256;
};

struct Elements {
    explicit Elements(const ElementCounts& counts);

    BitBank inputs;
    BitBank outputs;
    BitBank flags;
    RegisterBank intRegisters;   // N
    RegisterBank realRegisters;  // R
    BitBank systemFlags;         // SM
    RegisterBank systemIntRegisters;   // SN
    RegisterBank systemRealRegisters;  // SR
};

}  // namespace pac::sim
