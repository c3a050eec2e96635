// The readings of the CMD handshake the manual leaves open (docs/open_points.md), as settings of the
// simulated PA-CONTROL: what makes a new command, where RECEIVE starts after a restart, and END OF
// PROCESSING after power-on. The library's FBs must work on every one; sharing tests run on each, crossed
// with the bus timings (SharingCase), and name both in the test's name.
#pragma once

#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bus_timing.hpp"
#include "pac/sim/cmd_protocol.hpp"
#include "pac/sim/pa_control.hpp"

namespace pac::test {

using ControllerReading = pac::sim::CmdProtocolConfig;

// Every combination of the three settings.
inline std::vector<ControllerReading> AllControllerReadings() {
    using pac::sim::NewCommandRule;
    using pac::sim::ReceiveAfterRestart;
    std::vector<ControllerReading> all;
    for (NewCommandRule rule : {NewCommandRule::kSendDiffersFromReceive, NewCommandRule::kSendChanged}) {
        for (ReceiveAfterRestart start : {ReceiveAfterRestart::kZero, ReceiveAfterRestart::kLastSend}) {
            for (bool endAtPowerOn : {true, false}) all.push_back({rule, start, endAtPowerOn});
        }
    }
    return all;
}

// "SendChanged_RfLastSend_Bf0" for a GoogleTest name.
inline std::string ReadingName(const ControllerReading& r) {
    std::string name = r.newCommand == pac::sim::NewCommandRule::kSendChanged ? "SendChanged" : "SendNotRf";
    name += r.receiveAfterRestart == pac::sim::ReceiveAfterRestart::kLastSend ? "_RfLastSend" : "_Rf0";
    name += r.endOfProcessingAtPowerOn ? "_Bf1" : "_Bf0";
    return name;
}

// A std::string, not a stream, for the reason Describe(BusTiming) gives.
inline std::string Describe(const ControllerReading& r) {
    return std::string("new command on ") + pac::sim::ToString(r.newCommand) + ", " +
           pac::sim::ToString(r.receiveAfterRestart) + (r.endOfProcessingAtPowerOn ? ", BF 1" : ", BF 0") +
           " at power-on";
}

// One bus timing on one controller reading.
struct SharingCase {
    BusTiming timing;
    ControllerReading reading;

    pac::sim::PaControlConfig Config() const {
        pac::sim::PaControlConfig config;
        config.cmd = reading;
        return config;
    }
};

inline void PrintTo(const SharingCase& c, std::ostream* out) { *out << Describe(c.timing) << "; " << Describe(c.reading); }

inline std::string SharingCaseName(const ::testing::TestParamInfo<SharingCase>& info) {
    const ::testing::TestParamInfo<BusTiming> timing(info.param.timing, info.index);
    return BusTimingName(timing) + "_" + ReadingName(info.param.reading);
}

// Every timing of `timings` on every reading.
inline std::vector<SharingCase> OnEveryReading(const std::vector<BusTiming>& timings) {
    std::vector<SharingCase> cases;
    for (const BusTiming& t : timings) {
        for (const ControllerReading& r : AllControllerReadings()) cases.push_back({t, r});
    }
    return cases;
}

}  // namespace pac::test
