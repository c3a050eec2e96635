// System parameters (0700/1700/1701/1702, DINT values) or the parameters of one axis (0800/1800/
// 1801/1802, REAL values): each with a number, limits and a default. Values are kept as the 32-bit
// pattern the CMD interface carries; the table's type says how limits compare (signed integer or
// IEEE single; NaN is never within limits).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace pac::sim {

enum class ParameterType { kInt32, kReal32 };

struct ParameterSpec {
    std::uint16_t number = 0;
    std::uint32_t min = 0;  // bit patterns of the table's type
    std::uint32_t max = 0;
    std::uint32_t defaultValue = 0;
    // A string literal (or other text that outlives every table): the tables are copied with every
    // configuration and every axis, and a plain pointer copies without the heap.
    const char* name = "";
};

ParameterSpec IntParameter(std::uint16_t number, std::int32_t min, std::int32_t max, std::int32_t defaultValue,
                           const char* name);
ParameterSpec RealParameter(std::uint16_t number, float min, float max, float defaultValue, const char* name);

// The small default tables (docs/sim_cmd.md lists them): copies of tables built once per process.
std::vector<ParameterSpec> DefaultSystemParameters();
std::vector<ParameterSpec> DefaultAxisParameters();

namespace sysparam {
constexpr std::uint16_t kLanguage = 1;
constexpr std::uint16_t kNumberOfAxes = 2;
constexpr std::uint16_t kStartInput = 3;
constexpr std::uint16_t kStopInput = 4;
}  // namespace sysparam

namespace axisparam {
constexpr std::uint16_t kTraverseSpeed = 1;
constexpr std::uint16_t kReferenceSpeed = 2;
constexpr std::uint16_t kCreepSpeed = 4;
constexpr std::uint16_t kAcceleration = 6;
constexpr std::uint16_t kMinTraverseArea = 8;
constexpr std::uint16_t kMaxTraverseArea = 9;
constexpr std::uint16_t kRampType = 30;
}  // namespace axisparam

class ParameterTable {
public:
    enum class SetResult { kOk, kUnknown, kOutOfRange };

    // Duplicate numbers or a default outside its limits: std::invalid_argument.
    ParameterTable(ParameterType type, std::vector<ParameterSpec> specs);

    ParameterType Type() const { return type_; }
    bool Contains(std::uint16_t number) const { return Find(number) != nullptr; }
    std::optional<std::uint32_t> Value(std::uint16_t number) const;
    std::optional<std::uint32_t> Min(std::uint16_t number) const;
    std::optional<std::uint32_t> Max(std::uint16_t number) const;
    bool WithinLimits(std::uint16_t number, std::uint32_t value) const;  // false for unknown numbers

    SetResult Set(std::uint16_t number, std::uint32_t value);
    void ResetToDefaults();

    // Typed conveniences (the table's type is not checked: they reinterpret the pattern).
    std::optional<std::int32_t> IntValue(std::uint16_t number) const;
    std::optional<float> RealValue(std::uint16_t number) const;

private:
    struct Entry {
        ParameterSpec spec;
        std::uint32_t value;
    };
    const Entry* Find(std::uint16_t number) const;
    Entry* Find(std::uint16_t number);
    bool InRange(const ParameterSpec& spec, std::uint32_t value) const;

    ParameterType type_;
    std::vector<Entry> entries_;
};

}  // namespace pac::sim
