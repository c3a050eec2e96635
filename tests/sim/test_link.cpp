// Link and Bus: latency, seeded jitter with order preserved, frozen / all-zero / disconnected links.
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "pac/sim/bus.hpp"
#include "pac/sim/link.hpp"

namespace pac::sim {
namespace {

using namespace std::chrono_literals;

Image8 Numbered(std::uint32_t n) {
    Image8 image{};
    WriteDword(image, 4, n);
    return image;
}

std::uint32_t NumberOf(const Image8& image) { return ReadDword(image, 4); }

const Image8 kA = FromHex("AA 00 00 00 00 00 00 01");
const Image8 kB = FromHex("BB 00 00 00 00 00 00 02");
const Image8 kZero{};

TEST(Link, InitiallyAllZeroAndZeroLatencyDeliversAtOnce) {
    Link link;
    EXPECT_EQ(link.Read(0ns), kZero);
    link.Write(1ms, kA);
    EXPECT_EQ(link.Read(1ms), kA);
}

TEST(Link, LatencyDelaysArrival) {
    Link link(LinkConfig{3ms, 0ns, 1});
    link.Write(0ms, kA);
    link.Write(1ms, kB);
    EXPECT_EQ(link.Read(2ms), kZero);
    EXPECT_EQ(link.Read(2999us), kZero);
    EXPECT_EQ(link.Read(3ms), kA);
    EXPECT_EQ(link.Read(3999us), kA);
    EXPECT_EQ(link.Read(4ms), kB);
    EXPECT_EQ(link.Read(100ms), kB);
}

TEST(Link, JitterStaysWithinBoundsAndNeverReordersWrites) {
    const auto latency = 2ms;
    const auto jitter = 500us;
    Link link(LinkConfig{latency, jitter, 42});
    std::vector<std::chrono::nanoseconds> arrivals;
    auto previous = std::chrono::nanoseconds::min();
    int heldBack = 0;
    for (std::uint32_t i = 1; i <= 2000; ++i) {
        const auto now = std::chrono::microseconds(10 * i);
        link.Write(now, Numbered(i));
        const auto arrival = link.LastArrival();
        // Within [now + latency, now + latency + jitter] always: a write held back behind the
        // previous one arrives with it, and that one was inside its own (earlier) window.
        ASSERT_GE(arrival, now + latency) << "write " << i;
        ASSERT_LE(arrival, now + latency + jitter) << "write " << i;
        ASSERT_GE(arrival, previous) << "write " << i;
        if (arrival == previous) ++heldBack;
        previous = arrival;
        arrivals.push_back(arrival);
    }
    // Writes every 10 us with up to 500 us jitter: many draw an earlier arrival than the write
    // before them and are held back to it.
    EXPECT_GT(heldBack, 100);
    // The reader, sampling every 5 us, sees numbers that never go down.
    std::uint32_t seen = 0;
    for (auto t = 0us; t <= 25000us; t += 5us) {
        const std::uint32_t n = NumberOf(link.Read(t).Cmd());
        ASSERT_GE(n, seen) << "at " << t.count() << " us";
        seen = n;
    }
    EXPECT_EQ(seen, 2000U);
}

std::vector<std::int64_t> ArrivalsFor(std::uint64_t seed) {
    Link link(LinkConfig{1ms, 1ms, seed});
    std::vector<std::int64_t> out;
    for (int i = 0; i < 50; ++i) {
        link.Write(std::chrono::milliseconds(10 * i), Numbered(static_cast<std::uint32_t>(i)));
        out.push_back(link.LastArrival().count());
    }
    return out;
}

TEST(Link, JitterIsDeterministicPerSeed) {
    EXPECT_EQ(ArrivalsFor(7), ArrivalsFor(7));
    EXPECT_NE(ArrivalsFor(7), ArrivalsFor(8));
    // And it does vary: not every delay is the same.
    const auto a = ArrivalsFor(7);
    bool varies = false;
    for (std::size_t i = 1; i < a.size(); ++i) {
        if (a[i] - a[i - 1] != 10'000'000) varies = true;
    }
    EXPECT_TRUE(varies);
}

TEST(Link, FrozenReaderKeepsTheImageDeliveredBeforeTheFreeze) {
    Link link(LinkConfig{1ms, 0ns, 1});
    link.Write(0ms, kA);
    EXPECT_EQ(link.Read(1ms), kA);
    link.Write(2ms, kB);  // arrives at 3 ms
    link.SetFault(2ms, LinkFault::kFrozen);
    EXPECT_EQ(link.Read(3ms), kA);
    EXPECT_EQ(link.Read(50ms), kA);
    EXPECT_EQ(link.Fault(), LinkFault::kFrozen);
    link.SetFault(60ms, LinkFault::kNone);
    EXPECT_EQ(link.Read(60ms), kB);  // writes kept travelling during the freeze
}

TEST(Link, FreezeBeforeAnythingArrivedShowsZeros) {
    Link link(LinkConfig{5ms, 0ns, 1});
    link.Write(0ms, kA);
    link.SetFault(3ms, LinkFault::kFrozen);
    EXPECT_EQ(link.Read(10ms), kZero);
}

TEST(Link, AllZeroFaultShowsZerosThenTheNewestImage) {
    Link link;
    link.Write(0ms, kA);
    EXPECT_EQ(link.Read(0ms), kA);
    link.SetFault(1ms, LinkFault::kAllZero);
    EXPECT_EQ(link.Read(1ms), kZero);
    link.Write(2ms, kB);
    EXPECT_EQ(link.Read(3ms), kZero);
    link.SetFault(4ms, LinkFault::kNone);
    EXPECT_EQ(link.Read(4ms), kB);
}

TEST(Link, DisconnectLosesImagesInFlightAndDropsWrites) {
    Link link(LinkConfig{2ms, 0ns, 1});
    link.Write(0ms, kA);
    EXPECT_EQ(link.Read(2ms), kA);
    link.Write(3ms, kB);  // would arrive at 5 ms
    link.SetFault(4ms, LinkFault::kDisconnected);
    EXPECT_FALSE(link.Connected());
    EXPECT_EQ(link.Read(5ms), kZero);
    link.Write(6ms, kB);
    EXPECT_EQ(link.WritesDropped(), 1U);
    link.SetFault(10ms, LinkFault::kNone);
    EXPECT_TRUE(link.Connected());
    EXPECT_EQ(link.Read(20ms), kZero);  // nothing written since the reconnection
    link.Write(21ms, kA);
    EXPECT_EQ(link.Read(22ms), kZero);
    EXPECT_EQ(link.Read(23ms), kA);
}

TEST(Link, TimeMustNotRunBackwards) {
    Link link;
    link.Write(5ms, kA);
    EXPECT_THROW(link.Write(4ms, kB), std::invalid_argument);
    link.Read(5ms);
    EXPECT_THROW(link.Read(4ms), std::invalid_argument);
    EXPECT_THROW(link.SetFault(4ms, LinkFault::kFrozen), std::invalid_argument);
    EXPECT_THROW(Link(LinkConfig{-1ns, 0ns, 1}), std::invalid_argument);
    EXPECT_THROW(link.SetJitter(-1ns), std::invalid_argument);
}

TEST(Bus, CarriesEachDirectionWithItsOwnLatency) {
    BusConfig config;
    config.toPac.latency = 3ms;
    config.fromPac.latency = 1ms;
    Bus bus(config);
    bus.WriteToPac(0ms, kA);
    bus.WriteFromPac(0ms, kB);
    EXPECT_EQ(bus.ReadFromPac(1ms), kB);
    EXPECT_EQ(bus.ReadToPac(2ms), kZero);
    EXPECT_EQ(bus.ReadToPac(3ms), kA);
}

TEST(Bus, DisconnectAndReconnectBothDirections) {
    Bus bus;
    bus.WriteToPac(0ms, kA);
    bus.WriteFromPac(0ms, kB);
    bus.Disconnect(1ms);
    EXPECT_EQ(bus.ReadToPac(1ms), kZero);
    EXPECT_EQ(bus.ReadFromPac(1ms), kZero);
    bus.Reconnect(2ms);
    bus.WriteToPac(3ms, kA);
    EXPECT_EQ(bus.ReadToPac(3ms), kA);
    EXPECT_EQ(bus.ReadFromPac(3ms), kZero);
}

}  // namespace
}  // namespace pac::sim
