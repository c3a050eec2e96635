// Reads the named constants of st/gvl/GVL_PAC.st, so that tests speak of PAC_LIB_ERR_ACK_TIMEOUT
// rather than 16#8001 and the constant list that CODESYS and TwinCAT users import is itself tested.
// The scenario program (scenario/) reads command, status and error names through it too.
#pragma once

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <map>
#include <regex>
#include <stdexcept>
#include <string>

namespace pac::test {

class GvlConstants {
public:
    explicit GvlConstants(const std::string& path = PAC_GVL_FILE) {
        std::ifstream in(path);
        if (!in) throw std::runtime_error("cannot read " + path);
        static const std::regex line(R"(^\s*(\w+)\s*:\s*(WORD|BYTE)\s*:=\s*(16#)?([0-9A-Fa-f_]+)\s*;)");
        std::string text;
        while (std::getline(in, text)) {
            std::smatch m;
            if (!std::regex_search(text, m, line)) continue;
            std::string digits = m[4];
            digits.erase(std::remove(digits.begin(), digits.end(), '_'), digits.end());
            values_[m[1]] = static_cast<std::uint32_t>(std::stoul(digits, nullptr, m[3].matched ? 16 : 10));
        }
    }

    std::uint32_t operator[](const std::string& name) const {
        auto it = values_.find(name);
        if (it == values_.end()) throw std::out_of_range(name + " is not in GVL_PAC");
        return it->second;
    }

    const std::map<std::string, std::uint32_t>& All() const { return values_; }

private:
    std::map<std::string, std::uint32_t> values_;
};

}  // namespace pac::test
