// The operating-mode machine (manual 2.4.2, 6.4, 5.2.1, 5.2.4.15, 5.2.5.1, 5.2.6.1) driven through the
// CMD interface: every transition of ONLINE and of the AUTOMATIC stand-in, the transitional statuses
// with BF = 0, system errors of each class, the external stop input, the emergency stop, statuses held
// by SetOperatingStatus(), a power cycle during a request, and each mode command in every status.
#include <set>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

// "31/1": the status and BF of a reply.
std::string Brief(const ReplyFrame& reply) {
    return std::to_string(reply.operatingStatus) + "/" + (reply.endOfProcessing ? "1" : "0");
}

class ModeMachineTest : public PacRig {
protected:
    explicit ModeMachineTest(PaControlConfig config = QuickConfig()) : PacRig(config) {}

    void SetUp() override {
        ASSERT_EQ(pac_.SystemParameters().Set(4, 1), ParameterTable::SetResult::kOk);
        pac_.Io().inputs.Set(1, true);
    }

    std::uint8_t Status() const { return pac_.OperatingStatus(); }
    std::string Cmd(std::uint16_t code) { return Brief(SendFrame(code)); }
    // `n` cycles without a new command: "status/BF" of each reply.
    std::string Trace(int n) {
        std::string out;
        for (int i = 0; i < n; ++i) out += (i == 0 ? "" : " ") + Brief(ReplyFrame::Decode(FromHex(Idle())));
        return out;
    }
    // `n` cycles: the status of each reply.
    std::string Statuses(int n) {
        std::string out;
        for (int i = 0; i < n; ++i) {
            out += (i == 0 ? "" : " ") + std::to_string(ReplyFrame::Decode(FromHex(Idle())).operatingStatus);
        }
        return out;
    }
    // Axis 1 travels at 1000 AE/s from the next cycle on (a ramp of 10 ms / 5 AE from the last cycle); a
    // stop brakes it with 10000 AE/s^2 in 100 ms (10 cycles, 50 AE).
    void MoveAxis1() {
        ServoAxis& axis = pac_.Axes().Motion(1);
        ASSERT_EQ(axis.MoveAbsolute(axis.Now(), 1000.0, Dynamics{1000.0, 100000.0, 10000.0}), 0);
    }
};

TEST_F(ModeMachineTest, OnlineStartStopResumeAndCancel) {
    EXPECT_EQ(Cmd(code::kStartOnline), "30/0");  // ONLINE started: one controller cycle
    EXPECT_EQ(Trace(2), "31/1 31/1");
    EXPECT_EQ(Send(code::kSetSpeedAxis, 1, FloatToBits(2000.0F)), "44 FA 00 00 00 1F 20 00");
    // No axis moves: STOP recognised (32) passes within the cycle, "stopped" (35) at once.
    EXPECT_EQ(Cmd(code::kStop), "35/1");
    // Resume (decision): 0603 in 35 goes straight back to 31; the session's speed stays.
    EXPECT_EQ(Cmd(code::kStartOnline), "31/1");
    EXPECT_EQ(pac_.Axes().SessionDynamics(1).speed, 2000.0);
    EXPECT_EQ(Cmd(code::kAbortOnline), "1/1");
    EXPECT_EQ(pac_.Axes().SessionDynamics(1).speed, 1000.0);
    EXPECT_EQ(pac_.Counters().failed, 0U);
}

TEST_F(ModeMachineTest, OnlineStopWaitsForTheAxesAndThe0600EndsWithIt) {
    GoOnline();
    MoveAxis1();
    EXPECT_EQ(Cmd(code::kStop), "32/0");
    EXPECT_EQ(Trace(10), "32/0 32/0 32/0 32/0 32/0 32/0 32/0 32/0 32/0 35/1");
    EXPECT_DOUBLE_EQ(pac_.Axes().Motion(1).Position(), 55.0);  // 5 AE of ramp, 50 AE of braking
}

class ScriptedAutomatic : public ModeMachineTest {
protected:
    static PaControlConfig Scripted() {
        PaControlConfig config = QuickConfig();
        config.modes.automatic = AutomaticScript{2, 3, 2, 4};
        return config;
    }
    ScriptedAutomatic() : ModeMachineTest(Scripted()) {}
};

TEST_F(ScriptedAutomatic, StartStopResumeAndCancelFollowTheScript) {
    EXPECT_EQ(Cmd(code::kStartAuto), "10/0");  // AUTOMATIC started: 2 cycles
    EXPECT_EQ(Trace(2), "10/0 11/1");
    EXPECT_EQ(Trace(3), "11/1 11/1 11/1");  // the program runs until stopped
    MoveAxis1();
    // 5.2.1.1: 15 only once all axes stand and the STOP program (3 cycles) has finished.
    EXPECT_EQ(Cmd(code::kStop), "12/0");
    EXPECT_EQ(Trace(9), "12/0 12/0 12/0 12/0 12/0 12/0 12/0 12/0 12/0");
    EXPECT_EQ(Trace(4), "13/0 13/0 13/0 15/1");
    // 5.2.1.1: a repeated start continues the program: START-AFTER-STOP (2 cycles), then 11.
    EXPECT_EQ(Cmd(code::kStartAuto), "16/0");
    EXPECT_EQ(Trace(2), "16/0 11/1");
    EXPECT_EQ(Cmd(code::kAbortAuto), "1/1");
}

TEST_F(ScriptedAutomatic, MalfunctionStopsTheAxesThenRunsTheMalfunctionProgram) {
    Cmd(code::kStartAuto);
    EXPECT_EQ(Trace(2), "10/0 11/1");
    MoveAxis1();
    pac_.RaiseSystemError(600);
    // Noticed by the next cycle: 17 while the axis brakes (10 cycles), 18 for 4 cycles, then 19.
    EXPECT_EQ(Statuses(15), "17 17 17 17 17 17 17 17 17 17 18 18 18 18 19");
    EXPECT_EQ(Send(code::kGetError), "00 00 02 58 80 13 20 00");  // 600, FE
    EXPECT_EQ(Send(code::kStartAuto), "00 00 00 00 80 13 C0 15");  // error pending: 21
    EXPECT_EQ(Cmd(code::kStop), "19/1");                             // stopped already
    // 0A41: home; 600 is of class 3, cleared on returning home.
    EXPECT_EQ(Send(code::kAbortAuto), "00 00 00 00 00 01 A0 00");
}

TEST_F(ScriptedAutomatic, AMalfunctionDuringTheStopEndsThe0600AtTheMalfunctionStop) {
    Cmd(code::kStartAuto);
    Trace(2);
    MoveAxis1();
    EXPECT_EQ(Cmd(code::kStop), "12/0");
    EXPECT_EQ(Trace(2), "12/0 12/0");
    pac_.RaiseSystemError(700);
    EXPECT_EQ(Trace(8), "17/0 17/0 17/0 17/0 17/0 17/0 17/0 18/0");
    EXPECT_EQ(Trace(4), "18/0 18/0 18/0 19/1");
}

TEST_F(ModeMachineTest, SystemErrorOfClass3InOnline) {
    GoOnline();
    MoveAxis1();
    pac_.RaiseSystemError(512);
    EXPECT_EQ(Statuses(11), "37 37 37 37 37 37 37 37 37 37 39");
    EXPECT_EQ(pac_.Axes().Motion(1).Status(), AxisStatus::kStopped);
    EXPECT_EQ(Send(code::kGetError), "00 00 02 00 80 27 20 00");              // 512, FE, 39
    EXPECT_EQ(Send(code::kStartOnline), "00 00 00 00 80 27 C0 15");           // no resume: 21
    EXPECT_EQ(Send(code::kPosAxisAbsolute, 1, 0), "00 00 00 00 80 27 40 14");  // no moves: 20
    EXPECT_EQ(Cmd(code::kStop), "39/1");
    // 0A81: home position, 512 cleared (5.2.4.15, class 3).
    EXPECT_EQ(Send(code::kAbortOnline), "00 00 00 00 00 01 20 00");
    EXPECT_EQ(pac_.SystemError(), 0);
}

TEST_F(ModeMachineTest, SystemErrorOfClass2StaysInHomeUntilReset) {
    GoOnline();
    pac_.RaiseSystemError(150);
    EXPECT_EQ(Statuses(1), "39");  // nothing moves: 37 passes within the cycle
    EXPECT_EQ(Send(code::kAbortOnline), "00 00 00 00 80 09 20 00");  // home with system error (9)
    EXPECT_EQ(Send(code::kStartOnline), "00 00 00 00 80 09 C0 15");  // 21
    EXPECT_EQ(Send(code::kStartAuto), "00 00 00 00 80 09 40 15");
    EXPECT_EQ(Send(code::kResetError), "00 00 00 00 00 01 A0 00");   // 0909: 1, FE clear
    EXPECT_EQ(Cmd(code::kStartOnline), "30/0");
}

TEST_F(ModeMachineTest, SystemErrorOfClass1NeedsAPowerCycle) {
    pac_.RaiseSystemError(42);
    EXPECT_EQ(Statuses(1), "9");
    EXPECT_EQ(Send(code::kResetError), "00 00 00 2A 80 09 C0 15");  // 21, the number as data
    EXPECT_EQ(Send(code::kStartOnline), "00 00 00 00 80 09 40 15");
    pac_.PowerCycle(now_);
    EXPECT_EQ(pac_.SystemError(), 0);
    send_ = false;
    EXPECT_EQ(Exchange(CommandImage(code::kGetState, 0, 0, false)), "00 00 00 00 00 01 20 00");
}

TEST_F(ModeMachineTest, ErrorsRaisedInHomePositionShow9UntilReset) {
    pac_.RaiseSystemError(300);
    EXPECT_EQ(pac_.SystemError(), 0);  // noticed by the next cycle
    EXPECT_EQ(Idle(), "00 00 00 00 80 09 20 00");
    EXPECT_EQ(Send(code::kResetError), "00 00 00 00 00 01 A0 00");
    // Class 3 in home position (only a test can do that): shown, reset by 0909 too (decision).
    pac_.RaiseSystemError(999);
    EXPECT_EQ(Idle(), "00 00 00 00 80 09 A0 00");
    EXPECT_EQ(Send(code::kResetError), "00 00 00 00 00 01 20 00");
}

TEST_F(ModeMachineTest, TheMoreSevereErrorIsKept) {
    pac_.RaiseSystemError(512);
    pac_.RaiseSystemError(150);
    Idle();
    EXPECT_EQ(pac_.SystemError(), 150);  // class 2 replaces class 3
    pac_.RaiseSystemError(160);
    Idle();
    EXPECT_EQ(pac_.SystemError(), 160);  // same class: the newer one
    pac_.RaiseSystemError(512);
    Idle();
    EXPECT_EQ(pac_.SystemError(), 160);  // class 3 does not hide class 2
    pac_.RaiseSystemError(42);
    pac_.RaiseSystemError(150);
    Idle();
    EXPECT_EQ(pac_.SystemError(), 42);  // nothing hides a CPU error
    EXPECT_THROW(pac_.RaiseSystemError(0), std::invalid_argument);
    EXPECT_THROW(pac_.RaiseSystemError(1000), std::invalid_argument);
}

// A system error in every status, with no axis moving: where it leads one and two cycles later.
TEST_F(ModeMachineTest, SystemErrorInEveryStatus) {
    struct Case {
        std::uint8_t status;
        const char* statuses;  // after the next cycle and the one after
    };
    const Case cases[] = {
        {1, "9 9"},     {2, "2 2"},     {9, "9 9"},     {10, "18 19"},  {11, "18 19"},  {12, "18 19"},
        {13, "18 19"},  {15, "18 19"},  {16, "18 19"},  {17, "17 17"},  {18, "18 18"},  {19, "19 19"},
        {20, "20 20"},  {30, "39 39"},  {31, "39 39"},  {32, "39 39"},  {35, "39 39"},  {37, "37 37"},
        {39, "39 39"},
    };
    for (const Case& c : cases) {
        pac_.SetOperatingStatus(c.status);
        pac_.SetSystemError(0);
        pac_.RaiseSystemError(150);
        EXPECT_EQ(Statuses(2), c.statuses) << "status " << int(c.status);
        EXPECT_EQ(pac_.SystemError(), 150) << "status " << int(c.status);
    }
}

TEST(SystemErrorClasses, ByNumber) {
    EXPECT_EQ(ClassOfSystemError(0), SystemErrorClass::kNone);
    EXPECT_EQ(ClassOfSystemError(1), SystemErrorClass::kCpu);
    EXPECT_EQ(ClassOfSystemError(99), SystemErrorClass::kCpu);
    EXPECT_EQ(ClassOfSystemError(100), SystemErrorClass::kHardware);
    EXPECT_EQ(ClassOfSystemError(499), SystemErrorClass::kHardware);
    EXPECT_EQ(ClassOfSystemError(500), SystemErrorClass::kOperation);
    EXPECT_EQ(ClassOfSystemError(999), SystemErrorClass::kOperation);
    EXPECT_EQ(ClassOfSystemError(1000), SystemErrorClass::kHardware);
}

TEST(ModeMachineOptions, NegativeScriptCountsAreRefused) {
    PaControlConfig config = QuickConfig();
    config.modes.automatic.stopProgramCycles = -1;
    Bus bus;
    EXPECT_THROW(PaControl(bus, config), std::invalid_argument);
}

TEST(ModeMachineScript, ZeroCycleStepsPassWithinTheCycle) {
    PaControlConfig config = QuickConfig();
    config.modes.automatic = AutomaticScript{0, 0, 0, 0};
    Bus bus;
    PaControl pac(bus, config);
    bus.WriteToPac(0ms, CommandImage(code::kStartAuto, 0, 0, true));
    pac.Cycle(0ms);
    EXPECT_EQ(ToHex(bus.ReadFromPac(0ms)), "00 00 00 00 00 0B A0 00");  // 10 not shown
    bus.WriteToPac(10ms, CommandImage(code::kStop, 0, 0, false));
    pac.Cycle(10ms);
    EXPECT_EQ(ToHex(bus.ReadFromPac(10ms)), "00 00 00 00 00 0F 20 00");  // 12, 13 not shown
}

TEST_F(ModeMachineTest, DroppingTheExternalStopInputStopsOnline) {
    GoOnline();
    MoveAxis1();
    pac_.Io().inputs.Set(1, false);
    EXPECT_EQ(Statuses(11), "32 32 32 32 32 32 32 32 32 32 35");
    EXPECT_EQ(pac_.SystemError(), 0);  // a stop, not a malfunction
    // No resume without power on the input (44), then with it.
    EXPECT_EQ(Send(code::kStartOnline), "00 00 00 00 00 23 40 2C");
    pac_.Io().inputs.Set(1, true);
    EXPECT_EQ(Cmd(code::kStartOnline), "31/1");
}

TEST_F(ModeMachineTest, DroppingTheExternalStopInputWhileOnlineStarts) {
    StartOnline();
    pac_.Io().inputs.Set(1, false);
    EXPECT_EQ(Trace(1), "35/1");  // 30 -> stop: the 0603 ends with the status it settled on
}

TEST_F(ModeMachineTest, AutomaticDoesNotWatchTheExternalStopInput) {
    Cmd(code::kStartAuto);
    pac_.Io().inputs.Set(1, false);
    EXPECT_EQ(Statuses(3), "11 11 11");
    // An undefined input (system parameter 4 = 0) refuses 0603 with 44 as well.
    Cmd(code::kAbortAuto);
    ASSERT_EQ(pac_.SystemParameters().Set(4, 0), ParameterTable::SetResult::kOk);
    pac_.Io().inputs.Set(1, true);
    EXPECT_EQ(Send(code::kStartOnline), "00 00 00 00 00 01 C0 2C");
}

TEST(ModeMachineWithoutExternalStop, OnlineNeedsNoInput) {
    PaControlConfig config = QuickConfig();
    config.modes.requireExternalStop = false;
    Bus bus;
    PaControl pac(bus, config);
    bus.WriteToPac(0ms, CommandImage(code::kStartOnline, 0, 0, true));
    for (int k = 0; k < 5; ++k) pac.Cycle(10ms * k);
    EXPECT_EQ(pac.OperatingStatus(), 31);
}

TEST_F(ModeMachineTest, EmergencyStopThenResume) {
    Cmd(code::kStartAuto);
    EXPECT_EQ(Trace(1), "11/1");
    // All-zero to-PAC image: 19 at once, no system error; a repeated start resumes.
    EXPECT_EQ(Exchange(Image8{}), "00 00 00 00 00 13 A0 00");
    EXPECT_EQ(Cmd(code::kStartAuto), "16/0");
    EXPECT_EQ(Trace(1), "11/1");
    EXPECT_EQ(Cmd(code::kAbortAuto), "1/1");
    GoOnline();
    EXPECT_EQ(Exchange(Image8{}), "00 00 00 00 00 27 20 00");
    EXPECT_EQ(Cmd(code::kStartOnline), "31/1");
}

TEST_F(ModeMachineTest, AStatusSetByTheTestIsHeldUntilSomethingMovesIt) {
    pac_.SetOperatingStatus(status::kAutoStarted);
    EXPECT_EQ(Statuses(4), "10 10 10 10");
    EXPECT_EQ(Cmd(code::kStop), "13/0");
    EXPECT_EQ(Trace(1), "15/1");
    // Held ONLINE without power on the external stop input: no reaction until a request.
    pac_.Io().inputs.Set(1, false);
    pac_.SetOperatingStatus(status::kOnline);
    EXPECT_EQ(Statuses(3), "31 31 31");
    EXPECT_TRUE(pac_.Modes().Held());
    EXPECT_EQ(Cmd(code::kStop), "35/1");
    EXPECT_FALSE(pac_.Modes().Held());
    // A system error moves a held status too.
    pac_.SetOperatingStatus(status::kOnline);
    pac_.RaiseSystemError(510);
    EXPECT_EQ(Statuses(1), "39");
}

class ModeMachineBooting : public ModeMachineTest {
protected:
    ModeMachineBooting() : ModeMachineTest(BootingIn(30ms)) {}
};

TEST_F(ModeMachineBooting, PowerCycleDuringAStartDropsIt) {
    now_ = 30ms;
    Idle();
    StartOnline();                                   // 40 ms: 30, BF = 0, SEND 1
    pac_.PowerCycle(now_);                           // 50 ms
    send_ = false;                                   // the PLC resynchronises
    EXPECT_EQ(Exchange(CommandImage(code::kGetState, 0, 0, false)), "00 00 00 00 00 00 00 00");
    EXPECT_EQ(Idle(), "00 00 00 00 00 00 00 00");
    EXPECT_EQ(Idle(), "00 00 00 00 00 00 00 00");
    EXPECT_EQ(Idle(), "00 00 00 00 00 01 20 00");  // 80 ms: home position, nothing outstanding
    EXPECT_EQ(Statuses(2), "1 1");
    EXPECT_EQ(pac_.Counters().Count(code::kStartOnline), 1U);
}

TEST_F(ModeMachineBooting, ErrorsRaisedWhileBootingAreNoticedByTheFirstCycle) {
    pac_.RaiseSystemError(200);
    EXPECT_EQ(Idle(), "00 00 00 00 00 00 00 00");
    now_ = 30ms;
    EXPECT_EQ(Idle(), "00 00 00 00 80 09 20 00");
    // A power cycle forgets errors raised before it, not those raised after it.
    pac_.RaiseSystemError(300);
    pac_.PowerCycle(now_);
    pac_.RaiseSystemError(400);
    now_ += 30ms;
    Idle();
    EXPECT_EQ(pac_.SystemError(), 400);
}

TEST_F(ModeMachineBooting, PowerCycleDuringTheAutomaticStopProgram) {
    now_ = 30ms;
    Idle();
    Cmd(code::kStartAuto);
    Trace(1);
    EXPECT_EQ(Cmd(code::kStop), "13/0");
    pac_.PowerCycle(now_);
    send_ = false;
    Exchange(CommandImage(code::kGetState, 0, 0, false));
    now_ += 30ms;
    EXPECT_EQ(Statuses(3), "1 1 1");
}

// Each mode command in every status (5.1.1 with 5.2.1 and the decisions of docs/simulator.md):
// accepted, or refused with its error number and nothing changed.
TEST_F(ModeMachineTest, EachModeCommandInEveryStatus) {
    const std::uint8_t statuses[] = {1, 2, 9, 10, 11, 12, 13, 15, 16, 17, 18, 19, 20, 30, 31, 32, 35, 37, 39};
    const std::set<int> automatic = {10, 11, 12, 13, 15, 16, 17, 18, 19};
    const std::set<int> online = {30, 31, 32, 35, 37, 39};
    struct Rule {
        std::uint16_t code;
        std::set<int> accepted;
        std::set<int> notExecutable;  // 21: a system error is pending (status 9 carries one)
    };
    std::set<int> stop = automatic;
    stop.insert(online.begin(), online.end());
    const Rule rules[] = {
        {code::kStop, stop, {}},
        {code::kStartAuto, {1, 15, 19}, {9}},
        {code::kStartOnline, {1, 35, 39}, {9}},
        {code::kAbortAuto, automatic, {}},
        {code::kAbortOnline, online, {}},
        {code::kResetError, {1, 9}, {}},
    };
    for (const Rule& rule : rules) {
        for (std::uint8_t s : statuses) {
            pac_.SetOperatingStatus(s);
            pac_.SetSystemError(s == 9 ? 150 : 0);
            const ReplyFrame reply = SendFrame(rule.code);
            const std::string what = "code " + std::to_string(rule.code) + " in status " + std::to_string(s);
            if (rule.accepted.count(s) != 0) {
                EXPECT_FALSE(reply.commandErrorFlag) << what << ": error " << reply.errorNumber;
            } else {
                const std::uint16_t expected = rule.notExecutable.count(s) != 0 ? 21 : 20;
                EXPECT_TRUE(reply.commandErrorFlag) << what;
                EXPECT_EQ(reply.errorNumber, expected) << what;
                EXPECT_EQ(reply.operatingStatus, s) << what;
                EXPECT_EQ(pac_.SystemError(), s == 9 ? 150 : 0) << what;
            }
        }
    }
}

}  // namespace
}  // namespace pac::sim::testing
