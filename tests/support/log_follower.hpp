// Reads a simulated controller's exchange log on from where the last call stopped, for a test that reads it
// after every scan: the records not read yet are found from the newest back, so a scan costs the records it
// added rather than the whole log (which holds every cycle of the test).
#pragma once

#include <chrono>

#include "pac/sim/exchange_log.hpp"

namespace pac::test {

class LogFollower {
public:
    // Calls `visit` with each record newer than the newest one read so far, oldest first. The log's times never
    // decrease (one record per controller cycle); a record of the same time as the last one read counts as read.
    template <class Visit>
    void ForEachNew(const pac::sim::ExchangeLog& log, Visit&& visit) {
        const auto& records = log.Records();
        auto it = records.end();
        while (it != records.begin() && (!seenAny_ || (it - 1)->time > lastTime_)) --it;
        for (; it != records.end(); ++it) {
            if (seenAny_ && it->time <= lastTime_) continue;
            seenAny_ = true;
            lastTime_ = it->time;
            visit(*it);
        }
    }

private:
    bool seenAny_ = false;
    std::chrono::nanoseconds lastTime_{0};
};

}  // namespace pac::test
