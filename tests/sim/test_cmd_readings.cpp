// The readings of the CMD handshake the manual leaves open, as controller settings (CmdProtocolConfig,
// docs/sim_cmd.md "Readings of the handshake"): a command on SEND != RECEIVE or on a change of SEND, RECEIVE
// after a restart at 0 or at the last SEND seen, END OF PROCESSING after power-on.
#include <gtest/gtest.h>

#include <stdexcept>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

PaControlConfig Reading(NewCommandRule rule, ReceiveAfterRestart start, bool endAtPowerOn = true) {
    PaControlConfig config = BootingIn(20ms);
    config.cmd = {rule, start, endAtPowerOn};
    return config;
}

class Readings : public PacRig {
protected:
    explicit Readings(PaControlConfig config) : PacRig(config) {}

    // Steps until booted, the module parked with SEND = 0.
    void Boot() {
        for (int i = 0; i < 3; ++i) Exchange(CommandImage(code::kGetState, 0, 0, false));
        ASSERT_TRUE(pac_.Booted());
    }

    // A module holding 0906 N1 := 5 with SEND = 1 through a power cycle at `now_` and the boot.
    void RestartUnderSendOne() {
        Boot();
        send_ = false;
        Send(code::kGetState);  // RF = 1 = SEND
        pac_.PowerCycle(now_);
        for (int i = 0; i < 3; ++i) Exchange(CommandImage(code::kPutIntReg, 1, 5, true));
        ASSERT_TRUE(pac_.Booted());
    }
};

class LevelFromZero : public Readings {
protected:
    LevelFromZero() : Readings(Reading(NewCommandRule::kSendDiffersFromReceive, ReceiveAfterRestart::kZero)) {}
};
class ChangeFromZero : public Readings {
protected:
    ChangeFromZero() : Readings(Reading(NewCommandRule::kSendChanged, ReceiveAfterRestart::kZero)) {}
};
class LevelFromLastSend : public Readings {
protected:
    LevelFromLastSend() : Readings(Reading(NewCommandRule::kSendDiffersFromReceive, ReceiveAfterRestart::kLastSend)) {}
};
class ChangeFromLastSend : public Readings {
protected:
    ChangeFromLastSend() : Readings(Reading(NewCommandRule::kSendChanged, ReceiveAfterRestart::kLastSend)) {}
};
class EndZeroAtPowerOn : public Readings {
protected:
    EndZeroAtPowerOn()
        : Readings(Reading(NewCommandRule::kSendDiffersFromReceive, ReceiveAfterRestart::kZero, false)) {}
};

TEST_F(LevelFromZero, AModuleOutOfStepAfterARestartIsACommand) {
    RestartUnderSendOne();
    EXPECT_EQ(pac_.Io().intRegisters.GetInt(1), 5) << "SEND 1 against RECEIVE 0: the module ran again";
    EXPECT_EQ(pac_.Counters().Count(code::kPutIntReg), 1u);
}

TEST_F(ChangeFromZero, OnlyAChangeOfSendIsACommand) {
    RestartUnderSendOne();
    EXPECT_EQ(pac_.Counters().Count(code::kPutIntReg), 0u) << "no change since the boot: no command";
    EXPECT_EQ(Tail(Idle()), "00 01 20 00") << "RECEIVE 0 against SEND 1, nothing pending";
    EXPECT_EQ(Tail(Exchange(CommandImage(code::kGetState, 0, 0, false))), "00 01 20 00")
        << "SEND 1 -> 0 is a change, although SEND now equals RECEIVE";
    EXPECT_EQ(pac_.Counters().Count(code::kGetState), 2u);
    EXPECT_EQ(Exchange(CommandImage(code::kGetState, 0, 0, false)), Idle()) << "no change: nothing";
    EXPECT_EQ(pac_.Counters().Count(code::kGetState), 2u);
}

TEST_F(LevelFromLastSend, ReceiveStartsAtTheLastSendSeen) {
    RestartUnderSendOne();
    EXPECT_EQ(pac_.Counters().Count(code::kPutIntReg), 0u);
    EXPECT_EQ(Tail(Idle()), "00 01 A0 00") << "RECEIVE 1 = SEND: in step";
}

TEST_F(ChangeFromLastSend, TheFirstImageIsComparedWithTheLastSendSeen) {
    Boot();
    send_ = false;
    Send(code::kGetState);
    pac_.PowerCycle(now_);
    for (int i = 0; i < 3; ++i) Exchange(CommandImage(code::kPutIntReg, 1, 5, false));  // SEND fell meanwhile
    EXPECT_EQ(pac_.Counters().Count(code::kPutIntReg), 1u) << "SEND 1 before, 0 after the restart: a change";
}

TEST_F(EndZeroAtPowerOn, ReplyShowsNoEndAndNothingProcesses) {
    Boot();
    EXPECT_EQ(Tail(Idle()), "00 01 00 00") << "RECEIVE 0 = SEND, BF 0";
    EXPECT_FALSE(pac_.Processing());
    EXPECT_EQ(Tail(Send(code::kGetState)), "00 01 A0 00") << "a command ends normally";
}

TEST(TornLink, AFreshImageIsReadTornOnlyOnceAndTheSeedDecides) {
    auto run = [](std::uint64_t seed) {
        LinkConfig config{0ns, 0ns, seed, 100};
        Link link(config, 8);
        link.Write(0ms, ProcessImage(CommandImage(0x190B, 0, 0, false)));
        link.Read(1ms);  // zeros before it: maybe torn too
        const auto tornBefore = link.TornReads();
        const ProcessImage next(CommandImage(0x0906, 0x0303, 0x33333333, true));
        link.Write(2ms, next);
        const ProcessImage torn = link.Read(3ms);
        EXPECT_EQ(link.Read(4ms), next) << "whole at the next read";
        EXPECT_EQ(link.TornReads() - tornBefore, torn == next ? 0u : 1u);
        for (std::size_t i = 0; i < 8; ++i) {
            EXPECT_TRUE(torn[i] == next[i] || torn[i] == ProcessImage(CommandImage(0x190B, 0, 0, false))[i]) << i;
        }
        return torn;
    };
    EXPECT_EQ(run(7), run(7)) << "deterministic";
    int differing = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) differing += run(seed) != run(seed + 100) ? 1 : 0;
    EXPECT_GT(differing, 0) << "the seed decides which bytes are old";
    Link link;
    EXPECT_THROW(link.SetTearPercent(101), std::invalid_argument);
    EXPECT_THROW(link.SetTearPercent(-1), std::invalid_argument);
}

TEST(TornLink, TearingLeavesTheJitterDrawsAlone) {
    Link plain(LinkConfig{1ms, 5ms, 9, 0}, 8);
    Link torn(LinkConfig{1ms, 5ms, 9, 60}, 8);
    for (int i = 0; i < 50; ++i) {
        const ProcessImage image(CommandImage(0x0906, static_cast<std::uint16_t>(i), 0, i % 2 == 0));
        plain.Write(std::chrono::milliseconds(i), image);
        torn.Write(std::chrono::milliseconds(i), image);
        EXPECT_EQ(plain.LastArrival(), torn.LastArrival());
    }
}

}  // namespace
}  // namespace pac::sim::testing
