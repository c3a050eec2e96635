#include "gvl_names.hpp"

namespace pac::scenario {

namespace {

bool StartsWith(const std::string& text, const std::string& prefix) {
    return text.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace

GvlNames::GvlNames(const std::string& gvlFile) : file_(gvlFile), constants_(gvlFile) {}

std::optional<std::uint32_t> GvlNames::Find(const std::string& name, const std::string& prefix) const {
    if (!StartsWith(name, prefix)) return std::nullopt;
    const auto& all = constants_.All();
    const auto it = all.find(name);
    if (it == all.end()) return std::nullopt;
    return it->second;
}

std::string GvlNames::NameOf(std::uint32_t value, const std::string& prefix) const {
    for (const auto& [name, v] : constants_.All()) {
        if (v == value && StartsWith(name, prefix)) return name;
    }
    return "";
}

std::string GvlNames::ErrorName(std::uint16_t errorId) const {
    std::string name = NameOf(errorId, "PAC_ERR_");
    return name.empty() ? NameOf(errorId, "PAC_LIB_ERR_") : name;
}

std::optional<std::uint16_t> GvlNames::FindError(const std::string& name) const {
    auto value = Find(name, "PAC_ERR_");
    if (!value) value = Find(name, "PAC_LIB_ERR_");
    if (!value) return std::nullopt;
    return static_cast<std::uint16_t>(*value);
}

}  // namespace pac::scenario
