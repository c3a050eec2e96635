#include "text_format.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "pac/sim/image8.hpp"
#include "pac/st_program.hpp"

namespace pac::scenario {

std::string Hex4(std::uint16_t value) {
    char text[16];
    std::snprintf(text, sizeof text, "16#%04X", static_cast<unsigned>(value));
    return text;
}

std::string Hex8(std::uint32_t value) {
    char text[16];
    std::snprintf(text, sizeof text, "16#%08lX", static_cast<unsigned long>(value));
    return text;
}

std::string RealText(float value) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "+Inf" : "-Inf";
    // The fewest significant digits that read back as the same float.
    char text[48];
    for (int digits = 1; digits <= 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*E", digits - 1, static_cast<double>(value));
        if (std::strtof(text, nullptr) == value) break;
    }
    const std::string scientific = text;  // "-6.4E+02"
    const auto e = scientific.find('E');
    const int exponent = std::atoi(scientific.c_str() + e + 1);
    const bool negative = scientific[0] == '-';
    std::string digits;
    for (std::size_t i = negative ? 1 : 0; i < e; ++i) {
        if (scientific[i] != '.') digits += scientific[i];
    }
    std::string result = negative ? "-" : "";
    if (exponent < -4 || exponent > 8) {
        result += digits.substr(0, 1) + "." + (digits.size() > 1 ? digits.substr(1) : "0") + "E" + std::to_string(exponent);
    } else if (exponent < 0) {
        result += "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
    } else {
        const auto point = static_cast<std::size_t>(exponent) + 1;
        if (digits.size() <= point) {
            result += digits + std::string(point - digits.size(), '0') + ".0";
        } else {
            result += digits.substr(0, point) + "." + digits.substr(point);
        }
    }
    return result;
}

std::string DwordText(std::uint32_t bits, bool asReal) {
    if (asReal) return RealText(pac::sim::BitsToFloat(bits)) + " (" + Hex8(bits) + ")";
    std::string text = std::to_string(bits);
    if (bits >= 0x80000000u) text += " = " + std::to_string(static_cast<std::int64_t>(bits) - 0x100000000LL);
    return text + " (" + Hex8(bits) + ")";
}

std::string ErrorIdText(std::uint16_t errorId) {
    return errorId >= 0x8000 ? Hex4(errorId) : std::to_string(errorId);
}

std::string ErrorText(std::uint16_t errorId) {
    BOOL eno = 0;
    const STRING text = F_PAC_ERRORTEXT(1, &eno, static_cast<WORD>(errorId), E_PAC_ERRORSOURCE__PAC_ERRSRC_NONE);
    return std::string(reinterpret_cast<const char*>(text.body), text.len);
}

double PositionValue(std::uint32_t bits, bool integerMode) {
    if (integerMode) return static_cast<double>(static_cast<std::int32_t>(bits)) / 1000.0;
    return static_cast<double>(pac::sim::BitsToFloat(bits));
}

}  // namespace pac::scenario
