// The rest of the ONLINE commands of manual 5.2.6 on the simulated controller, cycle by cycle (10 ms per
// step): the keep-alive of a manual traverse (0A90..0A92), 0A9A, measuring mode, limit switch monitoring,
// move conditions, and the EP reads of 5.2.4 with the settings for the manual's open readings
// (docs/sim_cmd.md, docs/open_points.md). Default axes: 1000 AE/s, ramps of 10000 AE/s^2.
#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

// Acknowledged without a command error and with END OF PROCESSING, whatever the SEND / RECEIVE phase.
bool EndedWithoutError(const ReplyFrame& reply) { return reply.endOfProcessing && !reply.commandErrorFlag; }

PaControlConfig WithOnline(OnlineCommandOptions options) {
    PaControlConfig config = QuickConfig();
    config.online = options;
    return config;
}

class OnlineAxesBench : public PacRig {
protected:
    explicit OnlineAxesBench(PaControlConfig config = QuickConfig()) : PacRig(config) {}
    void SetUp() override { GoOnline(); }
    ServoAxis& Axis(int n) { return pac_.Axes().Motion(n); }
    void IdleFor(std::chrono::milliseconds t) {
        for (auto elapsed = 0ms; elapsed < t; elapsed += 10ms) Idle();
    }
};

TEST_F(OnlineAxesBench, ManualTraverseStopsWithoutItsKeepAliveAndGoesOnWithIt) {
    // 5.2.6.10: acknowledged at once with BF = 1 and the start position 0.0.
    EXPECT_TRUE(EndedWithoutError(SendFrame(code::kStartManualAbsolute, 1, FloatToBits(5000.0F))));
    IdleFor(900ms);
    EXPECT_TRUE(Axis(1).Moving()) << "within the second";
    IdleFor(200ms);  // the keep-alive ran out at 1 s: braking (100 ms)
    EXPECT_FALSE(Axis(1).Moving());
    EXPECT_EQ(Data(Send(code::kGetStatusAxis, 1)), "00 00 00 02") << "stopped";

    const double from = Axis(1).Position();
    ASSERT_TRUE(EndedWithoutError(SendFrame(code::kStartManualRelative, 1, FloatToBits(3000.0F))));
    for (int i = 0; i < 4; ++i) {
        IdleFor(500ms);
        const ReplyFrame alive = SendFrame(code::kControlMoveAxis, 1);
        EXPECT_TRUE(alive.endOfProcessing);
        EXPECT_EQ(alive.ackData, FloatToBits(static_cast<float>(Axis(1).Position()))) << "5.2.6.12: the position";
    }
    EXPECT_TRUE(Axis(1).Moving()) << "kept going for 2 s";
    EXPECT_GT(Axis(1).Position(), from + 1500.0);
}

TEST_F(OnlineAxesBench, StopMultiCmdEndsProcessingAtOnceWhileTheAxisBrakes) {
    ASSERT_TRUE(EndedWithoutError(SendFrame(code::kStartAxisAbsolute, 1, FloatToBits(1000.0F))));
    IdleFor(200ms);
    const ReplyFrame stop = SendFrame(code::kStopAxisMultiCmd, 1);
    EXPECT_TRUE(stop.endOfProcessing) << "5.2.6.19: immediately acknowledged with end of processing";
    EXPECT_FALSE(stop.commandErrorFlag);
    EXPECT_EQ(Data(Send(code::kGetStatusAxis, 1)), "00 00 00 01") << "still braking";
    IdleFor(150ms);
    EXPECT_EQ(Data(Send(code::kGetStatusAxis, 1)), "00 00 00 02");
}

TEST_F(OnlineAxesBench, MeasuringModeNeedsAStandingAxisAndBlocksMoves) {
    ASSERT_TRUE(EndedWithoutError(SendFrame(code::kStartAxisAbsolute, 1, FloatToBits(500.0F))));
    EXPECT_EQ(SendFrame(code::kSetMeasuringMode, 1).errorNumber, error::kAxisStillMoves);
    IdleFor(700ms);
    EXPECT_TRUE(EndedWithoutError(SendFrame(code::kSetMeasuringMode, 1)));
    EXPECT_EQ(Data(Send(code::kGetStatusAxis, 1)), "00 00 00 08");
    EXPECT_EQ(SendFrame(code::kStartAxisAbsolute, 1, FloatToBits(0.0F)).errorNumber, error::kAxisNotReady);
    EXPECT_EQ(SendFrame(code::kPutStartReference, 1).errorNumber, error::kAxisNotReady);
    EXPECT_TRUE(EndedWithoutError(SendFrame(code::kResetMeasuringMode, 1)));
    EXPECT_EQ(Data(Send(code::kGetStatusAxis, 1)), "00 00 00 00");
}

TEST_F(OnlineAxesBench, LimitSwitchMonitoringDataAndOnlineEntry) {
    EXPECT_EQ(SendFrame(code::kPutLimitSwitchMonitoring, 0, 2).errorNumber, error::kValueOutsideRange);
    EXPECT_EQ(SendFrame(code::kPutLimitSwitchMonitoring, 3, 0).errorNumber, error::kAxisNumberUnknown);
    ASSERT_FALSE(SendFrame(code::kPutLimitSwitchMonitoring, 0, 0).commandErrorFlag);
    EXPECT_FALSE(pac_.Online().LimitSwitchMonitoring(1));
    EXPECT_FALSE(pac_.Online().LimitSwitchMonitoring(2));
    // 5.2.6.22 note: entering ONLINE switches it on.
    Send(code::kAbortOnline);
    IdleFor(50ms);
    GoOnline();
    EXPECT_TRUE(pac_.Online().LimitSwitchMonitoring(1));
    EXPECT_TRUE(pac_.Online().LimitSwitchMonitoring(2));
}

TEST_F(OnlineAxesBench, ConditionDataIsChecked) {
    // By significance: condition 1, type 4 (none), number 9.
    EXPECT_EQ(SendFrame(code::kPutConditionMoveAxis, 1, 0x01040009).errorNumber, error::kValueOutsideRange);
    EXPECT_EQ(SendFrame(code::kPutConditionMoveAxis, 1, 0x02010009).errorNumber, error::kValueOutsideRange);
    EXPECT_EQ(SendFrame(code::kPutConditionMoveAxis, 1, 0x01010000).errorNumber, error::kInadmissibleInput);
    EXPECT_EQ(SendFrame(code::kPutConditionMoveAxis, 1, 0x01030000 | 2000).errorNumber, error::kInadmissibleFlag);
    // Flag 12 = 0: the move runs while it stays 0, and stops when it is set.
    ASSERT_FALSE(SendFrame(code::kPutConditionMoveAxis, 1, 0x0003000C).commandErrorFlag);
    ASSERT_TRUE(pac_.Online().PendingCondition(1).has_value());
    ASSERT_FALSE(SendFrame(code::kStartAxisAbsolute, 1, FloatToBits(1000.0F)).commandErrorFlag);
    EXPECT_FALSE(pac_.Online().PendingCondition(1).has_value()) << "taken by this move";
    IdleFor(200ms);
    EXPECT_TRUE(Axis(1).Moving());
    pac_.Io().flags.Set(12, true);
    IdleFor(150ms);
    EXPECT_FALSE(Axis(1).Moving());
    EXPECT_LT(Axis(1).Position(), 400.0);
    EXPECT_EQ(Data(Send(code::kGetStatusAxis, 1)), "00 00 00 02");
}

class ProfibusConditionBench : public OnlineAxesBench {
protected:
    ProfibusConditionBench() : OnlineAxesBench(WithOnline({1s, true, true, ConditionLayout::kByProfibusByte, 40.0F})) {}
};

TEST_F(ProfibusConditionBench, ConditionInTheLowByteNumberInTheHighWord) {
    EXPECT_EQ(SendFrame(code::kPutConditionMoveAxis, 2, 0x00090101).errorNumber, error::kNone);
    ASSERT_TRUE(pac_.Online().PendingCondition(2).has_value());
    EXPECT_EQ(pac_.Online().PendingCondition(2)->number, 9);
    EXPECT_TRUE(pac_.Online().PendingCondition(2)->level);
    EXPECT_EQ(pac_.Online().PendingCondition(2)->type, ElementType::kInput);
}

TEST_F(OnlineAxesBench, ExtendedStatusOfTheManualsExample) {
    // 5.2.4.28: 0100 0104 = ready, positive limit switch actuated, negative not, malfunction. The simulator
    // counts an axis with an axis error as not ready, so the example's byte 0 comes with a drive fault only.
    pac_.Axes().SetLimitSwitches(2, -100.0, 0.0);
    EXPECT_EQ(Data(Send(code::kGetExtendedStatusAxis, 2)), "01 00 01 00");
    pac_.Axes().RaiseAxisError(2, now_, 46);
    EXPECT_EQ(Data(Send(code::kGetExtendedStatusAxis, 2)), "00 00 01 04");
}

TEST_F(OnlineAxesBench, ReferenceCommandsOfTheManualsExamples) {
    // 5.2.6.5: axis 2 to 200.00, acknowledged 4348 0000.
    EXPECT_EQ(Data(Send(code::kPutSetPosition, 2, FloatToBits(200.0F))), "43 48 00 00");
    EXPECT_EQ(Axis(2).Position(), 200.0);
    // 5.2.6.4: to zero.
    EXPECT_TRUE(EndedWithoutError(SendFrame(code::kPutPositionNull, 2)));
    EXPECT_EQ(Axis(2).Position(), 0.0);
    // 5.2.6.16: axis referenced at the current position, acknowledged with it (0.0).
    Axis(2).SetReferenced(false);
    const ReplyFrame referenced = SendFrame(code::kPutReferenceOnPosition, 2, 0);
    EXPECT_TRUE(EndedWithoutError(referenced));
    EXPECT_EQ(referenced.ackData, 0u);
    EXPECT_TRUE(Axis(2).Referenced());
    // 5.2.6.17 / 5.2.6.18.
    EXPECT_TRUE(EndedWithoutError(SendFrame(code::kOffAxis, 1)));
    EXPECT_FALSE(Axis(1).AxisOn());
    EXPECT_TRUE(EndedWithoutError(SendFrame(code::kOnAxis, 1)));
    EXPECT_TRUE(Axis(1).AxisOn());
}

class PlainController : public OnlineAxesBench {
protected:
    PlainController() : OnlineAxesBench(WithOnline({1s, false, true, ConditionLayout::kBySignificance, 40.0F})) {}
};

TEST_F(PlainController, EpReadsAreUnknownCommands) {
    for (std::uint16_t c : {code::kGetRotationControlPos, code::kGetMaxTowfault, code::kGetAxisFollowingError,
                            code::kGetTemperature}) {
        EXPECT_EQ(SendFrame(c, 1).errorNumber, error::kUnknownCommand) << std::hex << c;
    }
    EXPECT_FALSE(SendFrame(code::kGetExtendedStatusAxis, 1).commandErrorFlag) << "1921 is no EP command";
}

}  // namespace
}  // namespace pac::sim::testing
