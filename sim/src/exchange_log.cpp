// The simulated controller's cycle log (see exchange_log.hpp).
#include "pac/sim/exchange_log.hpp"

#include "pac/format_time.hpp"

#include <cstdint>
#include <iomanip>
#include <sstream>

namespace pac::sim {

std::string ExchangeLog::Format(bool changesOnly) const {
    std::ostringstream out;
    const ExchangeRecord* previous = nullptr;
    for (const auto& r : records_) {
        const bool same = previous != nullptr && previous->toPac == r.toPac && previous->fromPac == r.fromPac;
        previous = &r;
        if (changesOnly && same && !r.newCommand) continue;
        out << std::setw(12) << FormatTime(r.time) << "  to PAC " << ToHex(r.toPac) << "  from PAC "
            << ToHex(r.fromPac) << (r.newCommand ? "  <- new command" : "") << '\n';
    }
    return out.str();
}

std::string FormatTime(std::chrono::nanoseconds t) { return pac::FormatMs(t); }

}  // namespace pac::sim
