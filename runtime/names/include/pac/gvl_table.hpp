// The named constants of a global constant list, as pacst writes them next to the library's C
// (<LIST>.h: {name, type, value} in declaration order), read by name or by value. GvlTable::GvlPac()
// is st/gvl/GVL_PAC.st, the list CODESYS and TwinCAT users import, compiled into the program: C++
// code speaks of PAC_LIB_ERR_ACK_TIMEOUT rather than 16#8001 and needs no source tree at run time.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "GVL_PAC.h"

namespace pac {

class GvlTable {
public:
    template <std::size_t N>
    explicit GvlTable(const PACST_CONSTANT (&constants)[N]) : begin_(constants), end_(constants + N) {}

    static GvlTable GvlPac() { return GvlTable(GVL_PAC); }

    const PACST_CONSTANT* begin() const { return begin_; }
    const PACST_CONSTANT* end() const { return end_; }
    std::size_t Size() const { return static_cast<std::size_t>(end_ - begin_); }

    // The value of `name` if the list has it and it starts with `prefix` ("PAC_CMD_", ...).
    std::optional<long long> Find(std::string_view name, std::string_view prefix = {}) const;

    // The first name in declaration order with this value and prefix; "" if none.
    std::string NameOf(long long value, std::string_view prefix) const;

private:
    const PACST_CONSTANT* begin_;
    const PACST_CONSTANT* end_;
};

}  // namespace pac
