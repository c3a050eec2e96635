#include "pac/gvl_table.hpp"

namespace pac {

namespace {

bool StartsWith(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

}  // namespace

std::optional<long long> GvlTable::Find(std::string_view name, std::string_view prefix) const {
    if (!StartsWith(name, prefix)) return std::nullopt;
    for (const PACST_CONSTANT& constant : *this) {
        if (name == constant.name) return constant.value;
    }
    return std::nullopt;
}

std::string GvlTable::NameOf(long long value, std::string_view prefix) const {
    for (const PACST_CONSTANT& constant : *this) {
        if (constant.value == value && StartsWith(constant.name, prefix)) return constant.name;
    }
    return "";
}

}  // namespace pac
