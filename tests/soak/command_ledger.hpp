// The ledger of the CMD interface: what the PLC program asked for against what the simulated PA-CONTROL
// executed, read from the controller's own exchange log. Every command the soak asks for carries a number
// of its own as its data, so the ledger can tell each one apart. It holds that
//   - every command the controller recognised was asked for, and at most once (nothing sent twice, nothing
//     sent that nobody asked for; the parked module's GET_STAT reads are counted apart, they change nothing);
//   - every command that ended with Done was recognised exactly once (nothing lost); one that ended with an
//     Error may or may not have arrived (16#8001: sent, outcome unknown), but never twice.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <string>

#include "pac/sim/exchange_log.hpp"
#include "soak_report.hpp"

namespace pac::soak {

class CommandLedger {
public:
    static constexpr std::uint16_t kAskedCode = 0x0906;  // PUT_INT_REG: the data is the command's number
    static constexpr std::uint16_t kParkedCode = 0x190B;  // GET_STAT, what a parked module carries

    explicit CommandLedger(SoakReport& report) : report_(report) {}

    // A new job: its number (the data it carries).
    void Asked(std::uint32_t number) { asked_[number] = Entry{}; }
    // The commands the controller recognised since the last call.
    void Follow(const pac::sim::ExchangeLog& log, std::int64_t scan);
    // The job `number` showed its final output: Done or not.
    void Ended(std::uint32_t number, bool done, std::int64_t scan);

    std::int64_t Executed() const { return executed_; }
    std::int64_t ParkedReads() const { return parkedReads_; }

private:
    struct Entry {
        int executed = 0;
    };

    void Recognised(std::uint16_t code, std::uint32_t data, std::int64_t scan);

    SoakReport& report_;
    std::map<std::uint32_t, Entry> asked_;
    bool followed_ = false;
    std::chrono::nanoseconds lastRecord_{0};
    std::int64_t executed_ = 0;
    std::int64_t parkedReads_ = 0;
};

}  // namespace pac::soak
