// Parameter tables with limits (see parameter_table.hpp).
#include "pac/sim/parameter_table.hpp"

#include <stdexcept>
#include <string>

#include "pac/sim/image8.hpp"

namespace pac::sim {

ParameterSpec IntParameter(std::uint16_t number, std::int32_t min, std::int32_t max, std::int32_t defaultValue,
                           const char* name) {
    return ParameterSpec{number, static_cast<std::uint32_t>(min), static_cast<std::uint32_t>(max),
                         static_cast<std::uint32_t>(defaultValue), name};
}

ParameterSpec RealParameter(std::uint16_t number, float min, float max, float defaultValue, const char* name) {
    return ParameterSpec{number, FloatToBits(min), FloatToBits(max), FloatToBits(defaultValue), name};
}

namespace {

// The default tables are immutable: each is built once per process (a function-local static const) and
// every configuration gets a copy, one block of plain values.
std::vector<ParameterSpec> BuildSystemParameters() {
    // 5.2.2.1. Numbers 9..14 and 18 are "currently not used" and left out (error 34).
    return {
        IntParameter(1, 0, 3, 0, "Language"),
        IntParameter(2, 0, 4, 2, "Number of axes"),
        IntParameter(3, 0, 1024, 0, "Start input number"),
        IntParameter(4, 0, 1024, 0, "Stop input number"),
        IntParameter(5, 0, 1024, 0, "Manual release input number"),
        IntParameter(6, 0, 1024, 0, "Readiness output number"),
        IntParameter(7, 0, 1024, 0, "Malfunction output number"),
        IntParameter(8, 0, 1, 0, "Autostart"),
        IntParameter(15, 0, 1024, 0, "Teleservice activate input number"),
        IntParameter(16, 0, 1024, 0, "Teleservice contact output number"),
        IntParameter(17, 0, 126, 2, "Profibus DP address"),
        IntParameter(19, 0, 1, 0, "Profibus diagnosis active"),
        IntParameter(20, 0, 2, 0, "Basic operating mode"),
    };
}

std::vector<ParameterSpec> BuildAxisParameters() {
    // 5.2.3: a subset, units AE, AE/s, AE/s^2.
    return {
        RealParameter(1, 1.0F, 50000.0F, 1000.0F, "Traverse speed"),
        RealParameter(2, 1.0F, 50000.0F, 500.0F, "Reference speed"),
        RealParameter(3, 1.0F, 50000.0F, 500.0F, "Manual speed"),
        RealParameter(4, 1.0F, 50000.0F, 100.0F, "Creep speed"),
        RealParameter(5, 1.0F, 50000.0F, 100.0F, "Start-Stop speed"),
        RealParameter(6, 1.0F, 1000000.0F, 10000.0F, "Acceleration"),
        RealParameter(7, 0.001F, 1000000.0F, 1.0F, "Gear factor"),
        RealParameter(8, -1000000.0F, 1000000.0F, 0.0F, "Minimum traverse area"),
        RealParameter(9, -1000000.0F, 1000000.0F, 10000.0F, "Maximum traverse area"),
        RealParameter(24, 0.0F, 1.0F, 0.0F, "Direction of rotation"),
        RealParameter(30, 0.0F, 1.0F, 0.0F, "Ramp type"),
        RealParameter(31, 0.0F, 1.0F, 0.0F, "Invert shaft encoder direction"),
    };
}

}  // namespace

std::vector<ParameterSpec> DefaultSystemParameters() {
    static const std::vector<ParameterSpec> table = BuildSystemParameters();
    return table;
}

std::vector<ParameterSpec> DefaultAxisParameters() {
    static const std::vector<ParameterSpec> table = BuildAxisParameters();
    return table;
}

ParameterTable::ParameterTable(ParameterType type, std::vector<ParameterSpec> specs) : type_(type) {
    entries_.reserve(specs.size());
    for (auto& spec : specs) {
        if (Find(spec.number) != nullptr) {
            throw std::invalid_argument("ParameterTable: parameter " + std::to_string(spec.number) + " twice");
        }
        if (!InRange(spec, spec.defaultValue)) {
            throw std::invalid_argument("ParameterTable: default of parameter " + std::to_string(spec.number) +
                                        " outside its limits");
        }
        const std::uint32_t value = spec.defaultValue;
        entries_.push_back(Entry{spec, value});
    }
}

std::optional<std::uint32_t> ParameterTable::Value(std::uint16_t number) const {
    const Entry* e = Find(number);
    if (e == nullptr) return std::nullopt;
    return e->value;
}

std::optional<std::uint32_t> ParameterTable::Min(std::uint16_t number) const {
    const Entry* e = Find(number);
    if (e == nullptr) return std::nullopt;
    return e->spec.min;
}

std::optional<std::uint32_t> ParameterTable::Max(std::uint16_t number) const {
    const Entry* e = Find(number);
    if (e == nullptr) return std::nullopt;
    return e->spec.max;
}

bool ParameterTable::WithinLimits(std::uint16_t number, std::uint32_t value) const {
    const Entry* e = Find(number);
    return e != nullptr && InRange(e->spec, value);
}

ParameterTable::SetResult ParameterTable::Set(std::uint16_t number, std::uint32_t value) {
    Entry* e = Find(number);
    if (e == nullptr) return SetResult::kUnknown;
    if (!InRange(e->spec, value)) return SetResult::kOutOfRange;
    e->value = value;
    return SetResult::kOk;
}

void ParameterTable::ResetToDefaults() {
    for (auto& e : entries_) e.value = e.spec.defaultValue;
}

std::optional<std::int32_t> ParameterTable::IntValue(std::uint16_t number) const {
    auto v = Value(number);
    if (!v) return std::nullopt;
    return static_cast<std::int32_t>(*v);
}

std::optional<float> ParameterTable::RealValue(std::uint16_t number) const {
    auto v = Value(number);
    if (!v) return std::nullopt;
    return BitsToFloat(*v);
}

const ParameterTable::Entry* ParameterTable::Find(std::uint16_t number) const {
    for (const auto& e : entries_) {
        if (e.spec.number == number) return &e;
    }
    return nullptr;
}

ParameterTable::Entry* ParameterTable::Find(std::uint16_t number) {
    for (auto& e : entries_) {
        if (e.spec.number == number) return &e;
    }
    return nullptr;
}

bool ParameterTable::InRange(const ParameterSpec& spec, std::uint32_t value) const {
    if (type_ == ParameterType::kInt32) {
        const auto v = static_cast<std::int32_t>(value);
        return v >= static_cast<std::int32_t>(spec.min) && v <= static_cast<std::int32_t>(spec.max);
    }
    const float v = BitsToFloat(value);
    return v >= BitsToFloat(spec.min) && v <= BitsToFloat(spec.max);  // false for NaN
}

}  // namespace pac::sim
