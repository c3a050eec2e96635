// One case of the suites that run several command FBs on one CMD interface in a free PLC program: a bus
// timing on a controller reading (SharingCase), FB_PAC_CmdInterface's one- or two-step write, and for the
// seeded programs the seed of every random choice (0: none). The name and the printout say all three, so a
// failing case can be rerun alone.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bus_timing.hpp"
#include "controller_readings.hpp"

namespace pac::test {

struct ChannelCase {
    SharingCase sharing;
    bool twoStepWrite = false;
    std::uint64_t seed = 0;
};

inline std::string ChannelCaseName(const ::testing::TestParamInfo<ChannelCase>& info) {
    const ::testing::TestParamInfo<SharingCase> sharing(info.param.sharing, info.index);
    std::string name = SharingCaseName(sharing) + (info.param.twoStepWrite ? "_TwoStep" : "_OneStep");
    if (info.param.seed != 0) name += "_Seed" + std::to_string(info.param.seed);
    return name;
}

inline void PrintTo(const ChannelCase& c, std::ostream* out) {
    PrintTo(c.sharing, out);
    *out << (c.twoStepWrite ? "; two-step write" : "; one-step write");
    if (c.seed != 0) *out << "; seed " << c.seed;
}

// Every timing on every reading, with each write; numbered seeds from 1 when `seeded`.
inline std::vector<ChannelCase> ChannelCases(const std::vector<BusTiming>& timings, bool seeded) {
    std::vector<ChannelCase> cases;
    std::uint64_t seed = 1;
    for (const auto& sharing : OnEveryReading(timings)) {
        for (bool twoStep : {false, true}) cases.push_back({sharing, twoStep, seeded ? seed++ : 0});
    }
    return cases;
}

}  // namespace pac::test
