#include "command_ledger.hpp"

#include <sstream>

#include "pac/sim/image8.hpp"

namespace pac::soak {

void CommandLedger::Follow(const pac::sim::ExchangeLog& log, std::int64_t scan) {
    const auto& records = log.Records();
    // The records after the newest one already read, oldest first.
    auto first = records.end();
    while (first != records.begin() && (!followed_ || std::prev(first)->time > lastRecord_)) --first;
    for (auto it = first; it != records.end(); ++it) {
        if (it->newCommand) {
            const pac::sim::Image8 cmd = it->toPac.Cmd();
            Recognised(pac::sim::ReadWord(cmd, 3) & 0x7FFFU, pac::sim::ReadDword(cmd, 0), scan);
        }
    }
    if (!records.empty()) {
        followed_ = true;
        lastRecord_ = records.back().time;
    }
}

void CommandLedger::Recognised(std::uint16_t code, std::uint32_t data, std::int64_t scan) {
    if (code == kParkedCode) {
        ++parkedReads_;
        return;
    }
    ++executed_;
    std::ostringstream what;
    what << std::hex << std::uppercase << "the controller executed command 16#" << code << " with data 16#" << data;
    const auto entry = asked_.find(data);
    if (code != kAskedCode || entry == asked_.end()) {
        report_.Violation(scan, what.str() + ", which nobody asked for");
        return;
    }
    if (++entry->second.executed > 1) report_.Violation(scan, what.str() + " a second time");
}

void CommandLedger::Ended(std::uint32_t number, bool done, std::int64_t scan) {
    const auto entry = asked_.find(number);
    if (entry == asked_.end()) return;
    if (done && entry->second.executed != 1) {
        std::ostringstream what;
        what << "command number " << number << " ended with Done, but the controller executed it "
             << entry->second.executed << " times";
        report_.Violation(scan, what.str());
    }
}

}  // namespace pac::soak
