// The RS232 line (docs/sim_serial.md): bytes one character time apart at the baud rate, in order, and the
// faults by byte index: dropped, corrupted, delayed; noise; seeded random faults.
#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>

#include "pac/sim/serial_line.hpp"

namespace pac::sim {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

TEST(SerialLine, CharacterTimeFollowsTheFormat) {
    EXPECT_EQ(SerialFormat{}.CharacterTime(), 937500ns);  // 9600 baud, 1 + 7 + 1 bits
    EXPECT_EQ((SerialFormat{19200, 8, true, 1}.CharacterTime()), 572917ns);  // 11 bits, rounded up
    EXPECT_EQ((SerialFormat{110, 8, false, 2}.CharacterTime()), 100000000ns);
    EXPECT_THROW(SerialWire(SerialFormat{0, 7, false, 1}), std::invalid_argument);
}

TEST(SerialLine, BytesArriveOneCharacterTimeApartAndInOrder) {
    SerialWire wire(SerialFormat{1200, 7, false, 1});  // 7.5 ms per character
    wire.Send(0ms, Bytes{1, 2, 3});
    EXPECT_TRUE(wire.Receive(7499us).empty());
    EXPECT_EQ(wire.Receive(7500us), Bytes{1});
    wire.Send(10ms, Bytes{4});  // queued behind the others: the wire is busy until 22.5 ms
    EXPECT_EQ(wire.Receive(22500us), (Bytes{2, 3}));
    EXPECT_FALSE(wire.Idle(22500us));
    EXPECT_EQ(wire.Receive(30ms), Bytes{4});
    EXPECT_TRUE(wire.Idle(30ms));
}

// A byte sent for later (a reply after the controller's turnaround) is on its way but not yet on the wire.
TEST(SerialLine, CarryingOnlyFromTheStartBitToTheStopBit) {
    SerialWire wire(SerialFormat{1200, 7, false, 1});  // 7.5 ms per character
    wire.Send(10ms, Bytes{1, 2});
    EXPECT_FALSE(wire.Carrying(5ms));
    EXPECT_FALSE(wire.Idle(5ms));
    EXPECT_TRUE(wire.Carrying(10ms));
    EXPECT_TRUE(wire.Carrying(24ms));
    EXPECT_FALSE(wire.Carrying(25ms));
    EXPECT_EQ(wire.Receive(25ms), (Bytes{1, 2}));
    EXPECT_FALSE(wire.Carrying(26ms));
}

TEST(SerialLine, SevenDataBitsClearTheTopBit) {
    SerialWire wire;
    wire.Send(0ms, Bytes{0xB1});
    EXPECT_EQ(wire.Receive(1s), Bytes{0x31});
}

TEST(SerialLine, ScriptedFaultsActOnTheBytesTheyName) {
    SerialWire wire(SerialFormat{9600, 8, false, 1});
    wire.DropByte(1);
    wire.CorruptByte(2, 0x10);
    wire.DelayByte(3, 5ms);
    wire.Send(0ms, Bytes{0x41, 0x42, 0x43, 0x44});
    const auto character = SerialFormat{9600, 8, false, 1}.CharacterTime();
    EXPECT_EQ(wire.Receive(3 * character), (Bytes{0x41, 0x53}));
    EXPECT_TRUE(wire.Receive(4 * character + 5ms - 1ns).empty());
    EXPECT_EQ(wire.Receive(4 * character + 5ms), Bytes{0x44});
    EXPECT_EQ(wire.BytesDropped(), 1u);
    EXPECT_EQ(wire.BytesCorrupted(), 1u);
}

TEST(SerialLine, NoiseTakesTheWireWithoutCountingAsSent) {
    SerialWire wire;
    wire.DropByte(0);
    wire.Noise(0ms, Bytes{0x7F});
    wire.Send(0ms, Bytes{0x41});
    EXPECT_EQ(wire.Receive(1s), Bytes{0x7F}) << "byte 0 is the first one sent, not the noise";
    EXPECT_EQ(wire.BytesSent(), 1u);
}

TEST(SerialLine, RandomFaultsFollowTheSeed) {
    auto run = [](std::uint64_t seed) {
        SerialWire wire(SerialFormat{}, seed);
        wire.SetRandomFaults(0.2, 0.2);
        wire.Send(0ms, Bytes(200, 0x41));
        return wire.Receive(1s);
    };
    EXPECT_EQ(run(7), run(7));
    const Bytes got = run(7);
    EXPECT_GT(got.size(), 120u);
    EXPECT_LT(got.size(), 190u);
    EXPECT_THROW(SerialWire().SetRandomFaults(1.5, 0), std::invalid_argument);
}

}  // namespace
}  // namespace pac::sim
