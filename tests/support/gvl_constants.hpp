// The named constants of st/gvl/GVL_PAC.st, so that tests speak of PAC_LIB_ERR_ACK_TIMEOUT rather
// than 16#8001 and the constant list that CODESYS and TwinCAT users import is itself tested. The
// values are pacst's reading of the list, compiled in (pac::GvlTable); a name not in the list throws.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>

#include "pac/gvl_table.hpp"

namespace pac::test {

class GvlConstants {
public:
    GvlConstants() {
        for (const PACST_CONSTANT& constant : pac::GvlTable::GvlPac()) {
            values_[constant.name] = static_cast<std::uint32_t>(constant.value);
        }
    }

    std::uint32_t operator[](const std::string& name) const {
        auto it = values_.find(name);
        if (it == values_.end()) throw std::out_of_range(name + " is not in GVL_PAC");
        return it->second;
    }

    // By name, in alphabetical order.
    const std::map<std::string, std::uint32_t>& All() const { return values_; }

private:
    std::map<std::string, std::uint32_t> values_;
};

}  // namespace pac::test
