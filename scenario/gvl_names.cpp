#include "gvl_names.hpp"

namespace pac::scenario {

std::optional<std::uint32_t> GvlNames::Find(const std::string& name, const std::string& prefix) const {
    const auto value = table_.Find(name, prefix);
    if (!value) return std::nullopt;
    return static_cast<std::uint32_t>(*value);
}

std::string GvlNames::ErrorName(std::uint16_t errorId) const {
    std::string name = table_.NameOf(errorId, "PAC_ERR_");
    return name.empty() ? table_.NameOf(errorId, "PAC_LIB_ERR_") : name;
}

std::optional<std::uint16_t> GvlNames::FindError(const std::string& name) const {
    auto value = Find(name, "PAC_ERR_");
    if (!value) value = Find(name, "PAC_LIB_ERR_");
    if (!value) return std::nullopt;
    return static_cast<std::uint16_t>(*value);
}

}  // namespace pac::scenario
