// The value names of one of the library's enumerations, from the table pacst writes for each
// (pacst_enum_names.h: E_PAC_AXISCOMMAND__NAMES), so C++ code reads and prints the names of the ST
// itself: EnumNames(E_PAC_AXISCOMMAND__NAMES).Find<E_PAC_AXISCOMMAND>("PAC_AX_HOME").
// A name's position is its C enumerator's value: the portable ST subset has no explicit enum values,
// and pacst writes the enumerators in declaration order.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pacst_enum_names.h"

namespace pac {

class EnumNames {
public:
    template <std::size_t N>
    explicit EnumNames(const char* const (&names)[N]) : names_(names), count_(N) {}

    std::size_t Count() const { return count_; }
    // Every name, in declaration order.
    std::vector<std::string> All() const { return std::vector<std::string>(names_, names_ + count_); }

    // The enumerator named `name`, or nothing.
    template <class Enum>
    std::optional<Enum> Find(std::string_view name) const {
        for (std::size_t i = 0; i < count_; ++i) {
            if (name == names_[i]) return static_cast<Enum>(i);
        }
        return std::nullopt;
    }

    bool Contains(std::string_view name) const { return Find<std::size_t>(name).has_value(); }

private:
    const char* const* names_;
    std::size_t count_;
};

}  // namespace pac
