// Operating status codes and their modes (see operating_status.hpp).
#include "pac/sim/operating_status.hpp"

namespace pac::sim {

Mode ModeOf(std::uint8_t s) {
    if (s == status::kHome || s == status::kHomeWithSystemError) return Mode::kHome;
    if ((s >= 2 && s <= 8) || (s >= 20 && s <= 29)) return Mode::kManual;
    if (s >= 10 && s <= 19) return Mode::kAutomatic;
    if (s >= 30 && s <= 39) return Mode::kOnline;
    return Mode::kNotReady;
}

const char* ToString(Mode mode) {
    switch (mode) {
        case Mode::kNotReady: return "not ready";
        case Mode::kHome: return "home position";
        case Mode::kManual: return "manual";
        case Mode::kAutomatic: return "automatic";
        case Mode::kOnline: return "online";
    }
    return "?";
}

}  // namespace pac::sim
