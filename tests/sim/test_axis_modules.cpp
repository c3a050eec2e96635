// The simulated PA-CONTROL with axis modules (manual 2.7) in its bus layout (ModuleLayout{true, n}): the
// modules driven through the bus together with the CTRL and CMD modules, cycle by cycle. Eight axes at
// once with independent errors, CMD axis commands blocked, the four sequences of 2.7.9, STOP ONLINE,
// leaving ONLINE, the emergency stop, power cycles and the group flag. The axes have the default parameters
// (1000 AE/s, 10000 AE/s^2: a 100 AE move is a triangle of 200 ms); see docs/simulator.md "Axis modules".
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

namespace ac = axis_control;
namespace as = axis_status;

constexpr std::uint16_t kIdle = ctrl::kNoRequest;
constexpr std::uint16_t kStopLow = static_cast<std::uint16_t>(ctrl::kNoRequest & ~ctrl::kStop);
constexpr std::uint16_t kStartOnline = ctrl::kNoRequest | ctrl::kStartOnline;

constexpr std::uint32_t kOn = ac::kAxisOn;
constexpr std::uint32_t kSwitchesFree = as::kNegativeLimitNotActuated | as::kPositiveLimitNotActuated;
constexpr std::uint32_t kOnReferenced = as::kDriveEnabled | as::kReferenced | kSwitchesFree;  // 0x701
constexpr std::uint32_t kOnActive = kOnReferenced | as::kActive;                              // 0x781

double Triangle100(double s) { return s <= 0.1 ? 5000.0 * s * s : 100.0 - 5000.0 * (0.2 - s) * (0.2 - s); }

std::string Hex(const Image12& module) {
    ProcessImage image(12);
    for (std::size_t i = 0; i < 12; ++i) image[i] = module[i];
    return ToHex(image);
}

class AxisModules : public PacRig {
protected:
    explicit AxisModules(int n = 1, PaControlConfig config = QuickConfig()) : PacRig(config, AxisBus(n)) {}

    void SetUp() override {
        ASSERT_EQ(pac_.SystemParameters().Set(4, 1), ParameterTable::SetResult::kOk);  // external stop: input 1
        pac_.Io().inputs.Set(1, true);
        for (AxisModuleCommand& m : axisToPac_) {
            m.speedPerMille = 1000;
            m.accelerationPerMille = 1000;
        }
        Idle();  // 0 ms: the first CTRL control word after the boot, the reference for its edges
    }

    // ONLINE through the CTRL interface, bit 15 as `integer`: 30, then 31 (two cycles, 10 and 20 ms).
    void Online(bool integer = false) {
        const std::uint16_t format = integer ? ctrl::kIntegerFormat : 0;
        Control(kStartOnline | format);
        ASSERT_EQ(pac_.OperatingStatus(), 30);
        Control(kIdle | format);
        ASSERT_EQ(pac_.OperatingStatus(), 31);
    }

    void SetAxis(int axis, std::uint32_t control) { axisToPac_[static_cast<std::size_t>(axis - 1)].control = control; }
    void SetPosition(int axis, double position, bool integer = false) {
        axisToPac_[static_cast<std::size_t>(axis - 1)].position = EncodeModulePosition(position, integer);
    }
    // One cycle with axis `axis`'s control word set to `control`; the reply of that axis.
    AxisModuleReply Axis(int axis, std::uint32_t control) {
        SetAxis(axis, control);
        Idle();
        return AxisReply(axis);
    }
    double Position(int axis, bool integer = false) const {
        return DecodeModulePosition(AxisReply(axis).position, integer);
    }
    std::int64_t Ms() const { return std::chrono::duration_cast<std::chrono::milliseconds>(now_).count(); }
};

// ---- eight axes ---------------------------------------------------------------------------------------

class EightAxes : public AxisModules {
protected:
    EightAxes() : AxisModules(8) {}
};

TEST_F(EightAxes, MoveAtOnceWithIndependentErrors) {
    // Axis k moves relative 50 k. Axis 3's positive limit switch is at 125 (machine): reached 175 ms after
    // the start (100 ms ramp to 50, then 75 at 1000 AE/s). Axis 7 is blocked at 140 ms: following error.
    pac_.Axes().SetLimitSwitches(3, -50.0, 125.0);
    for (int k = 1; k <= 8; ++k) {
        SetAxis(k, kOn);
        SetPosition(k, 50.0 * k);
    }
    Online();  // 10, 20 ms
    for (int k = 1; k <= 8; ++k) SetAxis(k, kOn | ac::kMoveRelative | ac::kStart);
    Idle();  // 30 ms: all taken over in the same cycle
    for (int k = 1; k <= 8; ++k) {
        EXPECT_EQ(AxisReply(k).status, kOnActive) << "axis " << k;
        SetAxis(k, kOn | ac::kMoveRelative);
    }
    for (int i = 0; i < 10; ++i) Idle();  // 40..130 ms
    pac_.Axes().SetBlocked(7, now_, true);
    while (now_ < 210ms) Idle();  // ... 200 ms
    // 210 ms: axis 3 stands on its switch (since 205 ms) with axis error 64; the others move on.
    Idle();
    EXPECT_EQ(Hex(AxisModuleBytes(3)), "00 00 83 43 00 00 00 40 42 FA 00 00");  // FAULT, HALT, +switch; 125.0
    EXPECT_EQ(AxisReply(7).axisError, axis_error::kFollowingError);
    EXPECT_EQ(AxisReply(7).status & (as::kActive | as::kFault), as::kFault);
    for (int k : {4, 5, 6, 8}) EXPECT_EQ(AxisReply(k).status, kOnActive) << "axis " << k << " carries on";
    const double axis8 = Position(8);
    Idle();
    EXPECT_GT(Position(8), axis8);
    // Axis 8 (400 AE: 100 + 300 + 100 ms) is the last: in position at 530 ms.
    while (now_ < 530ms) Idle();
    EXPECT_EQ(AxisReply(8).status, kOnActive);
    Idle();  // 530 ms
    for (int k : {1, 2, 4, 5, 6, 8}) {
        EXPECT_EQ(AxisReply(k).status, kOnReferenced) << "axis " << k;
        EXPECT_EQ(Position(k), 50.0 * k) << "axis " << k;
        EXPECT_EQ(AxisReply(k).cmdError, 0);
    }
    EXPECT_EQ(Position(3), 125.0);
    EXPECT_LT(Position(7), 350.0);
    EXPECT_EQ(pac_.OperatingStatus(), 31);  // 2.7: an axis error is no system error
    EXPECT_EQ(pac_.SystemError(), 0);
    // Reset axis 3 (bit 16): only axis 3 changes; then it moves away from its switch.
    const std::string axis7 = Hex(AxisModuleBytes(7));
    EXPECT_EQ(Axis(3, kOn | ac::kResetAxisError).status, as::kDriveEnabled | as::kHalt | as::kReferenced |
                                                             as::kNegativeLimitNotActuated);
    EXPECT_EQ(Hex(AxisModuleBytes(7)), axis7);
    SetPosition(3, -25.0);
    EXPECT_EQ(Axis(3, kOn | ac::kMoveRelative | ac::kStart).cmdError, 0);
    while (AxisReply(3).status & as::kActive) Axis(3, kOn | ac::kMoveRelative);
    EXPECT_EQ(Position(3), 100.0);
}

TEST(AxisModulesConfig, EveryModuleNeedsAnAxis) {
    PaControlConfig config = QuickConfig();
    config.axisCapacity = 4;
    Bus bus(AxisBus(8));
    EXPECT_THROW(PaControl(bus, config), std::invalid_argument);
}

// ---- CMD axis commands ---------------------------------------------------------------------------------

TEST_F(AxisModules, CmdAxisCommandsAreBlocked) {
    Online();
    // 2.7 note: every axis command of 5.2.6 is refused with 20 (inadmissible command) ...
    for (std::uint16_t code : {code::kPosAxisAbsolute, code::kPosAxisRelative, code::kStartAxisAbsolute,
                               code::kStartAxisRelative, code::kStopAxis, code::kSetSpeedAxis,
                               code::kSetAccelerationAxis, code::kPutNoReference}) {
        const ReplyFrame reply = SendFrame(code, 1, FloatToBits(10.0F));
        EXPECT_TRUE(reply.commandErrorFlag) << std::hex << code;
        EXPECT_EQ(reply.errorNumber, error::kInadmissibleCommand) << std::hex << code;
    }
    EXPECT_FALSE(pac_.Axes().Motion(1).Moving());
    // ... reading the axis is not, nor are the mode commands.
    pac_.Axes().Motion(1).Place(now_, 12.0);
    EXPECT_EQ(Data(Send(code::kGetActualPos, 1)), "41 40 00 00");
    EXPECT_FALSE(SendFrame(code::kGetStatusAxis, 1).commandErrorFlag);
    EXPECT_EQ(SendFrame(code::kStop).operatingStatus, 35);
}

TEST(AxisModulesCmd, WithoutAxisModulesTheCmdMovesWork) {
    Bus bus;
    PaControlConfig config = QuickConfig();
    config.modes.requireExternalStop = false;
    PaControl pac(bus, config);
    bus.WriteToPac(0ms, CommandImage(code::kStartOnline, 0, 0, true));
    pac.Cycle(0ms);
    pac.Cycle(10ms);
    bus.WriteToPac(20ms, CommandImage(code::kStartAxisAbsolute, 1, FloatToBits(10.0F), false));
    pac.Cycle(20ms);
    EXPECT_FALSE(ReplyFrame::Decode(bus.ReadFromPac(20ms).Cmd()).commandErrorFlag);
    EXPECT_TRUE(pac.Axes().Motion(1).Moving());
}

// ---- the four sequences of 2.7.9 through the bus -------------------------------------------------------

// Axes whose enable mode is IDLE: Axis ON 0 takes the current off (2.7.3.1).
PaControlConfig IdleMachine() {
    PaControlConfig config = QuickConfig();
    config.axisMachine.enableMode = EnableMode::kIdle;
    return config;
}

class AxisModulesIdle : public AxisModules {
protected:
    AxisModulesIdle() : AxisModules(1, IdleMachine()) {}
};

TEST_F(AxisModulesIdle, AxisOnOff_2_7_9_1) {
    constexpr std::uint32_t kIdleStatus = as::kDriveDisabled | as::kIdle | as::kReferenced | kSwitchesFree;  // 0x714
    // Home position: the module reports, Axis ON 0 is not acted upon (the axis is operational).
    EXPECT_EQ(Axis(1, 0).status, kOnReferenced);
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "00 00 07 01 00 00 00 00 00 00 00 00");
    Control(kStartOnline);  // 30: ONLINE, Axis ON 0: off (IDLE) in this cycle
    EXPECT_EQ(AxisReply(1).status, kIdleStatus);
    Control(kIdle);  // 31
    EXPECT_EQ(Axis(1, kOn).status, kOnReferenced);
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "00 00 07 01 00 00 00 00 00 00 00 00");
    EXPECT_EQ(Axis(1, kOn).status, kOnReferenced);
    EXPECT_EQ(Axis(1, 0).status, kIdleStatus);
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "00 00 07 14 00 00 00 00 00 00 00 00");
    EXPECT_EQ(Axis(1, kOn | ac::kDisableDrive).status,
              as::kDriveDisabled | as::kDisabled | as::kReferenced | kSwitchesFree);
    EXPECT_EQ(Axis(1, kOn).status, kOnReferenced);
    EXPECT_EQ(Axis(1, 0).status, kIdleStatus);
    // Leaving ONLINE (0A81): operational again whatever Axis ON says (2.7.2, last note).
    EXPECT_EQ(SendFrame(code::kAbortOnline).operatingStatus, 1);
    EXPECT_EQ(AxisReply(1).status, kOnReferenced);
}

class AxisModulesUnreferenced : public AxisModules {
protected:
    static PaControlConfig Unreferenced() {
        PaControlConfig config = QuickConfig();
        config.referencedAtPowerOn = false;
        return config;
    }
    AxisModulesUnreferenced() : AxisModules(1, Unreferenced()) {}
};

TEST_F(AxisModulesUnreferenced, Referencing_2_7_9_2) {
    // G25 with axis parameters 2 (500 AE/s), 4 (100 AE/s) and 6 (10000 AE/s^2); the cam edge at -20 (machine)
    // extends negative. Started at 30 ms: the edge at 95 ms, braking to -32.5 at 145 ms, creep back, the
    // edge again at 275 ms (loaded: -20 becomes 0), braking 10 ms to 0.5 at 285 ms.
    constexpr std::uint32_t kOnFree = as::kDriveEnabled | kSwitchesFree;
    SetAxis(1, kOn);
    Online();  // 10, 20 ms
    EXPECT_EQ(AxisReply(1).status, kOnFree);
    EXPECT_EQ(Axis(1, kOn | ac::kHome | ac::kStart).status, kOnFree | as::kActive);  // 30 ms
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "00 00 06 81 00 00 00 00 00 00 00 00");
    SetAxis(1, kOn | ac::kHome);
    while (now_ < 280ms) {
        Idle();
        EXPECT_EQ(AxisReply(1).status, kOnFree | as::kActive) << Ms() << " ms";
        if (now_ == 90ms) {
            EXPECT_EQ(Position(1), -12.5);  // the cycle at 80 ms: 50 ms in, at 500 AE/s
        }
        if (now_ == 150ms) {
            EXPECT_EQ(Position(1), -32.375);  // 140 ms: braking, 5 ms before the standstill
        }
    }
    EXPECT_EQ(Position(1), -20.5);  // 270 ms
    Idle();                         // 280 ms: loaded at 275 ms, braking
    EXPECT_EQ(AxisReply(1).status, kOnReferenced | as::kActive);
    EXPECT_EQ(Position(1), 0.375);
    Idle();  // 290 ms: standing, complete; Start is 0: ACTIVE falls
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "00 00 07 01 00 00 00 00 3F 00 00 00");  // 0.5
    EXPECT_EQ(Axis(1, kOn).status, kOnReferenced);
}

TEST_F(AxisModules, RelativeTraversingInIntegerFormat_2_7_9_3) {
    SetAxis(1, kOn);
    SetPosition(1, 100.0, true);  // DINT 100000
    Online(true);                 // CTRL bit 15 taken over at the start of ONLINE
    EXPECT_TRUE(pac_.IntegerFormat());
    Axis(1, kOn | ac::kMoveRelative | ac::kStart);  // 30 ms
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "00 00 07 81 00 00 00 00 00 00 00 00");
    SetAxis(1, kOn | ac::kMoveRelative);
    for (int ms = 10; ms <= 190; ms += 10) {
        Idle();
        const auto expected = EncodeModulePosition(Triangle100(ms / 1000.0), true);
        EXPECT_EQ(AxisReply(1).status, kOnActive) << ms;
        EXPECT_EQ(AxisReply(1).position, expected) << ms << " ms into the move";
    }
    Idle();  // 230 ms: in position, Start 0: ACTIVE falls
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "00 00 07 01 00 00 00 00 00 01 86 A0");
    EXPECT_EQ(Axis(1, kOn).status, kOnReferenced);
}

TEST_F(AxisModules, RelativeTraversingWithLimitSwitchError_2_7_9_4) {
    pac_.Axes().SetLimitSwitches(1, -50.0, 155.0);
    SetAxis(1, kOn);
    SetPosition(1, 300.0);
    Online();
    Axis(1, kOn | ac::kMoveRelative | ac::kStart);  // 30 ms; the switch at 155 is reached at 235 ms
    SetAxis(1, kOn | ac::kMoveRelative);
    while (now_ < 240ms) {
        Idle();
        EXPECT_EQ(AxisReply(1).status, kOnActive) << Ms();
    }
    EXPECT_EQ(Position(1), 150.0);
    Idle();  // 240 ms
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "00 00 83 43 00 00 00 40 43 1B 00 00");  // FAULT, 64, at 155.0
    EXPECT_EQ(Axis(1, kOn).status & as::kAxisError, as::kAxisError);
    EXPECT_EQ(Axis(1, kOn | ac::kResetAxisError).axisError, 0);
    EXPECT_EQ(Axis(1, kOn | ac::kMoveRelative | ac::kStart).cmdError, axis_error::kLimitSwitchActuated);
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "00 00 43 03 00 40 00 00 43 1B 00 00");
}

// ---- operating modes ----------------------------------------------------------------------------------

TEST_F(AxisModules, StopOnlineInterruptsTheJobWhichIsNotContinued) {
    SetAxis(1, kOn);
    SetPosition(1, 1000.0);
    Online();
    Axis(1, kOn | ac::kMoveAbsolute | ac::kStart);  // 30 ms
    SetAxis(1, kOn | ac::kMoveAbsolute);
    while (now_ < 330ms) Idle();
    // 330 ms, 300 ms into the move at 250.0: STOP (CTRL bit 1 low): 32 while the axis brakes 100 ms.
    Control(kStopLow);
    EXPECT_EQ(pac_.OperatingStatus(), 32);
    EXPECT_EQ(AxisReply(1).status, kOnActive);
    while (now_ < 430ms) {
        Control(kStopLow);
        EXPECT_EQ(AxisReply(1).status, kOnActive) << Ms();
    }
    Control(kStopLow);  // 430 ms: standing at 300, interrupted (HALT); ONLINE stopped
    EXPECT_EQ(pac_.OperatingStatus(), 35);
    EXPECT_EQ(AxisReply(1).status, kOnReferenced | as::kHalt);
    EXPECT_EQ(Position(1), 300.0);
    // No jobs while stopped: a Start edge gets CMD error 20.
    Axis(1, kOn);
    EXPECT_EQ(Axis(1, kOn | ac::kMoveAbsolute | ac::kStart).cmdError, AxisModule::kInadmissible);
    // Resume (a start edge in 35): the interrupted job is not continued; a new Start is needed.
    Axis(1, kOn | ac::kMoveAbsolute);
    Control(kStartOnline);
    EXPECT_EQ(pac_.OperatingStatus(), 31);
    for (int i = 0; i < 5; ++i) Control(kIdle);
    EXPECT_EQ(Position(1), 300.0);
    EXPECT_EQ(Axis(1, kOn | ac::kMoveAbsolute | ac::kStart).status, kOnActive);
    EXPECT_EQ(AxisReply(1).cmdError, 0);
}

TEST_F(AxisModules, LeavingOnlineHaltsAtOnceAndJobsAreRefusedOutside) {
    SetAxis(1, kOn);
    SetPosition(1, 1000.0);
    Online();
    Axis(1, kOn | ac::kMoveAbsolute | ac::kStart);  // 30 ms
    SetAxis(1, kOn | ac::kMoveAbsolute);
    while (now_ < 230ms) Idle();
    // 230 ms (200 ms in, at 150.0): 0A81: halted at once, no ramp; home position; the job is over.
    EXPECT_EQ(SendFrame(code::kAbortOnline).operatingStatus, 1);
    EXPECT_EQ(Position(1), 150.0);
    EXPECT_EQ(AxisReply(1).status, kOnReferenced | as::kHalt);
    EXPECT_FALSE(pac_.Axes().Motion(1).Moving());
    Axis(1, kOn);
    const AxisModuleReply r = Axis(1, kOn | ac::kMoveAbsolute | ac::kStart);
    EXPECT_EQ(r.status, kOnReferenced | as::kHalt | as::kCmdError);
    EXPECT_EQ(r.cmdError, AxisModule::kInadmissible);
    EXPECT_FALSE(pac_.Axes().Motion(1).Moving());
}

TEST_F(AxisModules, EmergencyStopHaltsAtOnceAndTheModulesStillReport) {
    SetAxis(1, kOn);
    SetPosition(1, 1000.0);
    Online();
    Axis(1, kOn | ac::kMoveAbsolute | ac::kStart);  // 30 ms
    SetAxis(1, kOn | ac::kMoveAbsolute);
    while (now_ < 230ms) Idle();
    ExchangeImage(ProcessImage(bus_.Layout().Bytes()));  // 230 ms: all zero (4.2.5)
    EXPECT_TRUE(pac_.EmergencyStopActive());
    EXPECT_EQ(pac_.OperatingStatus(), 39);
    // HALT at 150.0 (no ramp). The zero image is no control word, so ACTIVE waits for the PLC's Start 0.
    EXPECT_EQ(Hex(AxisModuleBytes(1)), "00 00 07 83 00 00 00 00 43 16 00 00");
    // The PLC is back (Start 0): ACTIVE falls, Axis ON stays; no jobs in 39.
    EXPECT_EQ(Axis(1, kOn).status, kOnReferenced | as::kHalt);
    EXPECT_FALSE(pac_.EmergencyStopActive());
    EXPECT_EQ(Axis(1, kOn | ac::kMoveAbsolute | ac::kStart).cmdError, AxisModule::kInadmissible);
}

TEST_F(AxisModules, PowerCycleForgetsTheCmdError) {
    EXPECT_EQ(Axis(1, kOn | ac::kStart).cmdError, AxisModule::kInadmissible);  // home position: 20
    EXPECT_EQ(Axis(1, kOn).cmdError, AxisModule::kInadmissible);
    pac_.PowerCycle(now_);
    now_ += 60ms;
    Axis(1, kOn);
    EXPECT_EQ(pac_.OperatingStatus(), 1);
    EXPECT_EQ(AxisReply(1).cmdError, 0);
    EXPECT_EQ(AxisReply(1).status, kOnReferenced);
}

// ---- group flag and G123 -------------------------------------------------------------------------------

class TwoIdleAxes : public AxisModules {
protected:
    TwoIdleAxes() : AxisModules(2, IdleMachine()) {}
};

TEST_F(TwoIdleAxes, AnAxisDisplacedDuringOffShowsInTheWholeGroup) {
    SetAxis(1, kOn);
    Online();
    EXPECT_EQ(AxisReply(2).status & as::kIdle, as::kIdle);
    ASSERT_TRUE(pac_.Axes().Displace(2, now_, 5.0));
    SetAxis(2, kOn);
    Idle();
    EXPECT_EQ(AxisReply(2).status, kOnReferenced | as::kDisplaced | as::kGroupDisplaced);
    EXPECT_EQ(AxisReply(1).status, kOnReferenced | as::kGroupDisplaced);
    Axis(2, kOn | ac::kClearDisplaced | ac::kStart);
    EXPECT_EQ(AxisReply(2).status, kOnActive);
    EXPECT_EQ(AxisReply(1).status, kOnReferenced);
}

TEST_F(AxisModules, G123OnTheInputSetForTheAxis) {
    SetAxis(1, kOn);
    SetPosition(1, 1000.0);
    Online();
    pac_.SetConditionInput(1, 5);
    pac_.Io().inputs.Set(5, true);
    Axis(1, kOn | ac::kMoveAbsolute | ac::kWhileInput1 | ac::kStart);  // 30 ms
    SetAxis(1, kOn | ac::kMoveAbsolute | ac::kWhileInput1);
    while (now_ < 230ms) Idle();
    pac_.Io().inputs.Set(5, false);
    Idle();  // 230 ms: at 150.0, braking from 1000 AE/s: 100 ms, 50 AE
    EXPECT_EQ(AxisReply(1).status, kOnActive | as::kStoppedByCondition);
    while (AxisReply(1).status & as::kActive) Idle();
    EXPECT_EQ(Ms(), 340);  // ACTIVE fell in the cycle at 330 ms
    EXPECT_EQ(AxisReply(1).status, kOnReferenced | as::kHalt | as::kStoppedByCondition);
    EXPECT_EQ(Position(1), 200.0);
    EXPECT_THROW(pac_.SetConditionInput(2, 1), std::out_of_range);
}

}  // namespace
}  // namespace pac::sim::testing
