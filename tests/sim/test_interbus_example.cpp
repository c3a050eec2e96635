// The Interbus-S complex example of manual 4.2.4, byte for byte, with its errata corrected
// (docs/manual_errata.md): the replies for SEND = 0 end in 20 00 (RF 0, BF 1), not 02 00; the third command
// writes N3 (its parameter is 3), not N2; R1 holds 640.0 = 44 20 00 00 (44 20 20 00 is 640.5).
// The controller runs one cycle per row; each first row of a pair loads code and parameter with the
// SEND flag unchanged, which must not be taken as a command.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

class InterbusExample : public PacRig {
protected:
    InterbusExample() : PacRig(BootingIn(20ms)) {}
};

struct Row {
    const char* action;
    const char* toPac;
    const char* fromPac;
};

TEST_F(InterbusExample, CorrectedTableByteForByte) {
    pac_.Io().inputs.Set(5, true);
    pac_.Io().intRegisters.SetInt(2, 12345678);
    pac_.Io().realRegisters.SetReal(1, 640.0F);

    const std::vector<Row> rows = {
        {"before the boot ends (0 ms)", "00 00 00 00 00 00 00 00", "00 00 00 00 00 00 00 00"},
        {"before the boot ends (10 ms)", "00 00 00 00 00 00 00 00", "00 00 00 00 00 00 00 00"},
        {"booted: home position, nothing outstanding", "00 00 00 00 00 00 00 00", "00 00 00 00 00 01 20 00"},
        {"1900 input 5: code and parameter", "00 00 00 00 00 05 19 00", "00 00 00 00 00 01 20 00"},
        {"1900 input 5: SEND toggle", "00 00 00 00 00 05 99 00", "00 00 00 01 00 01 A0 00"},
        {"1906 N2: code and parameter", "00 00 00 00 00 02 99 06", "00 00 00 01 00 01 A0 00"},
        {"1906 N2: SEND toggle", "00 00 00 00 00 02 19 06", "00 BC 61 4E 00 01 20 00"},
        {"0906 N3 := 333: code and parameter", "00 00 01 4D 00 03 09 06", "00 BC 61 4E 00 01 20 00"},
        {"0906 N3 := 333: SEND toggle", "00 00 01 4D 00 03 89 06", "00 00 01 4D 00 01 A0 00"},
        {"1907 R1: code and parameter", "00 00 00 00 00 01 99 07", "00 00 01 4D 00 01 A0 00"},
        {"1907 R1: SEND toggle", "00 00 00 00 00 01 19 07", "44 20 00 00 00 01 20 00"},
        {"nothing new", "00 00 00 00 00 01 19 07", "44 20 00 00 00 01 20 00"},
    };
    for (const Row& row : rows) {
        EXPECT_EQ(Exchange(FromHex(row.toPac)), row.fromPac) << row.action << "\n" << pac_.Log().Format();
    }
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(3), 333);
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(2), 12345678);
    EXPECT_EQ(pac_.Counters().recognized, 4U);
    EXPECT_EQ(pac_.Counters().executed, 4U);
}

}  // namespace
}  // namespace pac::sim::testing
