// The names of GVL_PAC (st/gvl/GVL_PAC.st) in both directions, for the scenario program: a scenario
// may write PAC_CMD_PUT_INT_REG, PAC_ERR_N_REGISTER or PAC_STATUS_ONLINE, and the timeline prints
// the names back. The list is compiled in (pac::GvlTable), so it is the very list PLC programmers
// import and the program needs no file beside the scenario.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "pac/gvl_table.hpp"

namespace pac::scenario {

class GvlNames {
public:
    // The value of `name` if it is in the list and starts with `prefix` ("PAC_CMD_", ...).
    std::optional<std::uint32_t> Find(const std::string& name, const std::string& prefix) const;

    std::string CommandName(std::uint16_t code) const { return table_.NameOf(code, "PAC_CMD_"); }
    std::string StatusName(std::uint8_t status) const { return table_.NameOf(status, "PAC_STATUS_"); }
    // PAC_ERR_ (the PA-CONTROL's numbers) or PAC_LIB_ERR_ (the library's own codes).
    std::string ErrorName(std::uint16_t errorId) const;
    std::optional<std::uint16_t> FindError(const std::string& name) const;

private:
    pac::GvlTable table_ = pac::GvlTable::GvlPac();
};

}  // namespace pac::scenario
