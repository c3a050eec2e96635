// The CTRL interface (manual 2.5) of the simulated PA-CONTROL, with hand-written control words on a bus
// that carries the CMD and the CTRL module: the status word of every operating status, the requests
// (low-active levels, start edges, error reset edge), requests ignored where they do not apply, the
// all-zero control word, the integer-format take-over, CTRL and CMD used together, and power cycles.
#include <string>

#include <gtest/gtest.h>

#include <utility>

#include "sim_fixture.hpp"

namespace pac::sim::testing {
namespace {

constexpr std::uint16_t Without(std::uint16_t bit) { return static_cast<std::uint16_t>(ctrl::kNoRequest & ~bit); }

constexpr std::uint16_t kIdle = ctrl::kNoRequest;                                      // 16#0007
constexpr std::uint16_t kStopLow = Without(ctrl::kStop);                               // 16#0005
constexpr std::uint16_t kCancelLow = Without(ctrl::kCancel);                           // 16#0003
constexpr std::uint16_t kResetLow = Without(ctrl::kErrorReset);                        // 16#0006
constexpr std::uint16_t kStartOnline = ctrl::kNoRequest | ctrl::kStartOnline;          // 16#0017
constexpr std::uint16_t kStartAutomatic = ctrl::kNoRequest | ctrl::kStartAutomatic;    // 16#000F
constexpr std::uint16_t kInteger = ctrl::kIntegerFormat;                               // 16#8000

// Status words (2.5.2) as numbers, so that a wrong bit constant cannot hide here.
constexpr std::uint16_t kHomeWord = 0x0003;  // ready, battery o.k.
constexpr std::uint16_t kAutoActiveWord = 0x0103;
constexpr std::uint16_t kAutoStoppedWord = 0x0203;
constexpr std::uint16_t kOnlineActiveWord = 0x0403;
constexpr std::uint16_t kOnlineStoppedWord = 0x0803;

class CtrlInterface : public PacRig {
protected:
    explicit CtrlInterface(PaControlConfig config = QuickConfig()) : PacRig(config, CtrlBus()) {}

    void SetUp() override {
        ASSERT_EQ(pac_.SystemParameters().Set(4, 1), ParameterTable::SetResult::kOk);
        pac_.Io().inputs.Set(1, true);
        Idle();  // the first control word after the boot: the reference for the edges
    }

    std::uint8_t Status() const { return pac_.OperatingStatus(); }
    // Axis 1 travels at 1000 AE/s from the next cycle on (a ramp of 10 ms / 5 AE from the last cycle); a
    // stop brakes it with 10000 AE/s^2 in 100 ms (10 cycles, 50 AE).
    void MoveAxis1() {
        ServoAxis& axis = pac_.Axes().Motion(1);
        ASSERT_EQ(axis.MoveAbsolute(axis.Now(), 1000.0, Dynamics{1000.0, 100000.0, 10000.0}), 0);
    }
    std::string ReplyHex() const { return ToHex(reply_); }
};

TEST_F(CtrlInterface, StatusWordOfEveryStatus) {
    struct Case {
        std::uint8_t status;
        std::uint16_t word;
    };
    const Case cases[] = {
        {1, 0x0003},  {2, 0x0003},  {3, 0x0003},  {9, 0x0003},  {10, 0x0003}, {11, 0x0103}, {12, 0x0103},
        {13, 0x0103}, {14, 0x0003}, {15, 0x0203}, {16, 0x0103}, {17, 0x0103}, {18, 0x0103}, {19, 0x0203},
        {20, 0x0003}, {30, 0x0003}, {31, 0x0403}, {32, 0x0403}, {33, 0x0003}, {35, 0x0803}, {37, 0x0403},
        {39, 0x0803},
    };
    for (const Case& c : cases) {
        pac_.SetOperatingStatus(c.status);
        EXPECT_EQ(Control(kIdle), c.word) << "status " << int(c.status);
        EXPECT_EQ(Status(), c.status);
    }
}

class CtrlInterfaceStoppedAndActive : public CtrlInterface {
protected:
    static PaControlConfig Config() {
        PaControlConfig config = QuickConfig();
        config.ctrlInterface.stoppedModeBits = StoppedModeBits::kStoppedAndActive;
        return config;
    }
    CtrlInterfaceStoppedAndActive() : CtrlInterface(Config()) {}
};

// The other reading of 2.5.2 (docs/open_points.md): a stopped mode keeps its "active" bit.
TEST_F(CtrlInterfaceStoppedAndActive, StoppedModesAlsoShowActive) {
    const std::pair<std::uint8_t, std::uint16_t> cases[] = {{11, 0x0103}, {15, 0x0303}, {19, 0x0303},
                                                           {31, 0x0403}, {35, 0x0C03}, {39, 0x0C03}, {1, 0x0003}};
    for (const auto& [status, word] : cases) {
        pac_.SetOperatingStatus(status);
        EXPECT_EQ(Control(kIdle), word) << "status " << int(status);
    }
}

TEST_F(CtrlInterface, StatusWordFlagsAndErrorNumber) {
    Idle();
    EXPECT_EQ(CtrlHex(), "00 03 00 00 00 00 00 00");
    // System error: bit 2 and the number in word 2 (the number of 1909).
    pac_.SetOperatingStatus(status::kOnlineStoppedMalfunction);
    pac_.SetSystemError(529);
    Idle();
    EXPECT_EQ(CtrlHex(), "08 07 00 00 02 11 00 00");
    EXPECT_EQ(CtrlErrorNumber(), 529);
    // A CPU error (1..99): not ready.
    pac_.SetOperatingStatus(status::kHomeWithSystemError);
    pac_.SetSystemError(42);
    Idle();
    EXPECT_EQ(CtrlHex(), "00 06 00 00 00 2A 00 00");
    pac_.SetSystemError(100);
    EXPECT_EQ(Control(kIdle), 0x0007);
    // Battery.
    pac_.SetBatteryOk(false);
    EXPECT_EQ(Control(kIdle), 0x0005);
    pac_.SetBatteryOk(true);
    EXPECT_EQ(Control(kIdle), 0x0007);
    EXPECT_EQ(pac_.CtrlStatusWord(), 0x0007);
    // The CMD module beside it is unchanged: FE and the status.
    EXPECT_EQ(ReplyHex(), "00 00 00 00 80 09 20 00 00 07 00 00 00 64 00 00");
}

class CtrlInterfaceBooting : public CtrlInterface {
protected:
    CtrlInterfaceBooting() : CtrlInterface(BootingIn(30ms)) {}
    void SetUp() override {
        ASSERT_EQ(pac_.SystemParameters().Set(4, 1), ParameterTable::SetResult::kOk);
        pac_.Io().inputs.Set(1, true);
    }
    static std::string Zeros() { return "00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00"; }
};

TEST_F(CtrlInterfaceBooting, WhileBootingTheWholeReplyIsZeroAndTheBatteryStaysAcrossAPowerCycle) {
    pac_.SetBatteryOk(false);
    for (int i = 0; i < 3; ++i) {
        Control(kIdle);
        EXPECT_EQ(ReplyHex(), Zeros()) << i;
    }
    EXPECT_EQ(Control(kIdle), 0x0001);  // 30 ms: booted, ready, battery not o.k.
    pac_.PowerCycle(now_);
    EXPECT_EQ(ToHex(bus_.ReadFromPac(now_)), Zeros());
    now_ += 30ms;
    EXPECT_EQ(Control(kIdle), 0x0001);
}

TEST_F(CtrlInterfaceBooting, PowerCycleInTheMiddleOfAStartRequest) {
    now_ = 30ms;
    EXPECT_EQ(Control(kIdle), kHomeWord);
    EXPECT_EQ(Control(kStartOnline), kHomeWord);  // 40 ms: ONLINE started (30), no mode bit yet
    EXPECT_EQ(Status(), 30);
    pac_.PowerCycle(now_);  // 50 ms; the PLC keeps the start bit high
    for (int i = 0; i < 3; ++i) {
        Idle();
        EXPECT_EQ(ReplyHex(), Zeros());
    }
    // 80 ms: booted. Before the first word after the boot the bits count as idle, so the start bit the
    // PLC still holds is a rising edge: ONLINE starts again (docs/sim_modes.md).
    EXPECT_EQ(Idle(), "00 00 00 00 00 1E 20 00");
    EXPECT_EQ(Status(), 30);
    EXPECT_EQ(Control(kStartOnline), kHomeWord | ctrl::kOnlineActive);
    EXPECT_EQ(Status(), 31);
}

TEST_F(CtrlInterfaceBooting, AStartBitInTheFirstWordAfterTheBootIsAnEdge) {
    // The PLC's request is out before the controller has seen any control word of it.
    ctrlWord_ = kStartOnline;
    for (int i = 0; i < 3; ++i) {  // 0, 10, 20 ms: booting
        Idle();
        EXPECT_EQ(ReplyHex(), Zeros());
    }
    EXPECT_EQ(Idle(), "00 00 00 00 00 1E 20 00");  // 30 ms: booted, and the first word starts ONLINE
    EXPECT_EQ(Idle(), "00 00 00 00 00 1F 20 00");
    EXPECT_EQ(StatusWord(), kHomeWord | ctrl::kOnlineActive);
}

TEST_F(CtrlInterfaceBooting, PowerCycleInTheMiddleOfAStop) {
    now_ = 30ms;
    Control(kIdle);
    Control(kStartOnline);
    EXPECT_EQ(Control(kIdle), kOnlineActiveWord);
    MoveAxis1();
    EXPECT_EQ(Control(kStopLow), kOnlineActiveWord);  // 32 while the axis brakes
    EXPECT_EQ(Status(), 32);
    pac_.PowerCycle(now_);
    now_ += 30ms;
    EXPECT_EQ(Control(kStopLow), kHomeWord);  // booted in home; a low stop does nothing there
    EXPECT_FALSE(pac_.Axes().Motion(1).Moving());
    EXPECT_FALSE(pac_.IntegerFormat());
}

TEST_F(CtrlInterface, OnlineStartStopResumeCancel) {
    EXPECT_EQ(Control(kStartOnline), kHomeWord);  // 30: transitional, no mode bit
    EXPECT_EQ(Status(), 30);
    EXPECT_EQ(Control(kStartOnline), kOnlineActiveWord);  // 31 after one controller cycle
    EXPECT_EQ(Control(kIdle), kOnlineActiveWord);
    MoveAxis1();
    // Stop low: 32 while the axis brakes (still ONLINE active), then 35 ONLINE stopped.
    for (int k = 0; k < 10; ++k) EXPECT_EQ(Control(kStopLow), kOnlineActiveWord) << k;
    EXPECT_EQ(Status(), 32);
    EXPECT_EQ(Control(kStopLow), kOnlineStoppedWord);
    EXPECT_EQ(Status(), 35);
    EXPECT_EQ(Control(kIdle), kOnlineStoppedWord);
    // Resume (decision): a start edge in 35 goes back to 31 at once.
    EXPECT_EQ(Control(kStartOnline), kOnlineActiveWord);
    EXPECT_EQ(Status(), 31);
    // Cancel low: home position (0A81's path): axes halted.
    MoveAxis1();
    EXPECT_EQ(Control(kCancelLow), kHomeWord);
    EXPECT_EQ(Status(), 1);
    EXPECT_FALSE(pac_.Axes().Motion(1).Moving());
    EXPECT_EQ(Control(kIdle), kHomeWord);
}

TEST_F(CtrlInterface, AutomaticStartStopResumeCancel) {
    EXPECT_EQ(Control(kStartAutomatic), kHomeWord);  // 10: transitional
    EXPECT_EQ(Status(), 10);
    EXPECT_EQ(Control(kStartAutomatic), kAutoActiveWord);  // 11
    EXPECT_EQ(Control(kIdle), kAutoActiveWord);
    EXPECT_EQ(Control(kStopLow), kAutoActiveWord);  // 12 passes at once, 13 STOP program
    EXPECT_EQ(Status(), 13);
    EXPECT_EQ(Control(kStopLow), kAutoStoppedWord);  // 15
    EXPECT_EQ(Control(kIdle), kAutoStoppedWord);
    EXPECT_EQ(Control(kStartAutomatic), kAutoActiveWord);  // 16 START-AFTER-STOP (5.2.1.1)
    EXPECT_EQ(Status(), 16);
    EXPECT_EQ(Control(kIdle), kAutoActiveWord);
    EXPECT_EQ(Status(), 11);
    EXPECT_EQ(Control(kCancelLow), kHomeWord);  // 0A41's path
    EXPECT_EQ(Status(), 1);
}

TEST_F(CtrlInterface, StartsAreIgnoredWhileStopOrCancelIsLowAndTheEdgeIsUsedUp) {
    EXPECT_EQ(Control(Without(ctrl::kStop) | ctrl::kStartOnline), kHomeWord);
    EXPECT_EQ(Control(kStartOnline), kHomeWord);  // stop released: the start bit did not rise now
    EXPECT_EQ(Status(), 1);
    Control(kIdle);
    EXPECT_EQ(Control(Without(ctrl::kCancel) | ctrl::kStartAutomatic), kHomeWord);
    EXPECT_EQ(Status(), 1);
    Control(kIdle);
    Control(kStartAutomatic);
    EXPECT_EQ(Status(), 10);
}

TEST_F(CtrlInterface, BothStartBitsRisingTogetherStartOnline) {
    Control(kIdle | ctrl::kStartOnline | ctrl::kStartAutomatic);
    EXPECT_EQ(Status(), 30);
}

TEST_F(CtrlInterface, StartOnlineNeedsThePoweredExternalStopInput) {
    pac_.Io().inputs.Set(1, false);
    EXPECT_EQ(Control(kStartOnline), kHomeWord);
    EXPECT_EQ(Status(), 1);
    pac_.Io().inputs.Set(1, true);
    Control(kIdle);
    Control(kStartOnline);
    EXPECT_EQ(Control(kIdle), kOnlineActiveWord);
    // Dropping it acts like a stop; no resume without it.
    pac_.Io().inputs.Set(1, false);
    EXPECT_EQ(Control(kIdle), kOnlineStoppedWord);
    EXPECT_EQ(Control(kStartOnline), kOnlineStoppedWord);
    pac_.Io().inputs.Set(1, true);
    Control(kIdle);
    EXPECT_EQ(Control(kStartOnline), kOnlineActiveWord);
}

// Each CTRL request in every status: where it does not apply, it is ignored (the status stays).
TEST_F(CtrlInterface, EachRequestInEveryStatus) {
    struct Case {
        std::uint8_t status;
        std::uint8_t startOnline, startAutomatic, stop, cancel;
    };
    // Status 9 carries error 150. No axis moves and the script steps take one cycle each, so a stop
    // shows the STOP program (13) in AUTOMATIC and "stopped" (35) in ONLINE.
    const Case cases[] = {
        {1, 30, 10, 1, 1},      {2, 2, 2, 2, 2},        {9, 9, 9, 9, 9},        {10, 10, 10, 13, 1},
        {11, 11, 11, 13, 1},    {12, 12, 12, 13, 1},    {13, 13, 13, 13, 1},    {15, 15, 16, 15, 1},
        {16, 16, 16, 13, 1},    {17, 17, 17, 18, 1},    {18, 18, 18, 18, 1},    {19, 19, 16, 19, 1},
        {20, 20, 20, 20, 20},   {30, 30, 30, 35, 1},    {31, 31, 31, 35, 1},    {32, 32, 32, 35, 1},
        {35, 31, 35, 35, 1},    {37, 37, 37, 39, 1},    {39, 31, 39, 39, 1},
    };
    struct Request {
        const char* name;
        std::uint16_t word;
        std::uint8_t Case::*expected;
    };
    const Request requests[] = {
        {"start online", kStartOnline, &Case::startOnline},
        {"start automatic", kStartAutomatic, &Case::startAutomatic},
        {"stop", kStopLow, &Case::stop},
        {"cancel", kCancelLow, &Case::cancel},
    };
    for (const Request& r : requests) {
        for (const Case& c : cases) {
            pac_.SetOperatingStatus(c.status);
            pac_.SetSystemError(c.status == 9 ? 150 : 0);
            Control(kIdle);
            Control(r.word);
            EXPECT_EQ(Status(), c.*r.expected) << r.name << " in status " << int(c.status);
            EXPECT_EQ(pac_.SystemError(), c.status == 9 ? 150 : 0) << r.name << " in status " << int(c.status);
        }
    }
}

TEST_F(CtrlInterface, ErrorResetActsOnTheFallingEdgeInHomePositionOnly) {
    const std::uint8_t statuses[] = {1, 2, 9, 11, 15, 19, 31, 35, 39};
    for (std::uint8_t s : statuses) {
        pac_.SetOperatingStatus(s);
        pac_.SetSystemError(150);
        Control(kIdle);
        Control(kResetLow);
        const bool home = s == 1 || s == 9;
        EXPECT_EQ(pac_.SystemError(), home ? 0 : 150) << "status " << int(s);
        EXPECT_EQ(Status(), home ? 1 : s) << "status " << int(s);
    }
}

TEST_F(CtrlInterface, ErrorResetByClass) {
    // Class 2 raised in ONLINE: 39; reset ignored there; cancel: 9; reset: 1.
    Control(kStartOnline);
    Control(kIdle);
    pac_.RaiseSystemError(150);
    EXPECT_EQ(Control(kIdle), kOnlineStoppedWord | ctrl::kSystemError);
    EXPECT_EQ(CtrlErrorNumber(), 150);
    EXPECT_EQ(Control(kResetLow), kOnlineStoppedWord | ctrl::kSystemError);
    EXPECT_EQ(Control(kCancelLow), kHomeWord | ctrl::kSystemError);
    EXPECT_EQ(Status(), 9);
    EXPECT_EQ(Control(kIdle), kHomeWord | ctrl::kSystemError);
    EXPECT_EQ(Control(kResetLow), kHomeWord);
    EXPECT_EQ(Status(), 1);
    // Held low: one edge, one reset; a new error needs a new edge.
    pac_.RaiseSystemError(160);
    EXPECT_EQ(Control(kResetLow), kHomeWord | ctrl::kSystemError);
    EXPECT_EQ(Control(kIdle), kHomeWord | ctrl::kSystemError);
    EXPECT_EQ(Control(kResetLow), kHomeWord);
    // Class 3 raised in AUTOMATIC: cleared by the cancel itself.
    Control(kStartAutomatic);
    Control(kIdle);
    pac_.RaiseSystemError(530);
    EXPECT_EQ(Control(kIdle), kAutoActiveWord | ctrl::kSystemError);  // 18 MALFUNCTION program
    EXPECT_EQ(Control(kIdle), kAutoStoppedWord | ctrl::kSystemError);  // 19
    EXPECT_EQ(Control(kStartAutomatic), kAutoStoppedWord | ctrl::kSystemError);  // no resume
    EXPECT_EQ(Control(kCancelLow), kHomeWord);
    EXPECT_EQ(pac_.SystemError(), 0);
    // Class 1: not ready; no reset, no start; a power cycle clears it.
    Control(kIdle);
    pac_.RaiseSystemError(7);
    EXPECT_EQ(Control(kIdle), 0x0006);
    EXPECT_EQ(Control(kResetLow), 0x0006);
    Control(kIdle);
    EXPECT_EQ(Control(kStartOnline), 0x0006);
    EXPECT_EQ(Status(), 9);
    pac_.PowerCycle(now_);
    EXPECT_EQ(Control(kIdle), kHomeWord);
}

// The controller's real behaviour that FB_PAC_Ctrl must avoid: the low-active bits of a control word
// left at 0 (while the PLC still talks on the CMD interface) stop and cancel.
TEST_F(CtrlInterface, AnAllZeroControlWordCancels) {
    GoOnline();
    EXPECT_EQ(StatusWord(), kOnlineActiveWord);
    EXPECT_EQ(Control(0x0000), kHomeWord);
    EXPECT_EQ(Status(), 1);
    // 0603 with the control word at 0: ONLINE started, then cancelled in the next cycle; the 0603
    // ends there (BF = 1) with home position.
    EXPECT_EQ(Send(code::kStartOnline), "00 00 00 00 00 1E 00 00");
    EXPECT_EQ(Idle(), "00 00 00 00 00 01 20 00");
    // The same for 0602.
    EXPECT_EQ(Send(code::kStartAuto), "00 00 00 00 00 0A 80 00");
    EXPECT_EQ(Idle(), "00 00 00 00 00 01 A0 00");
}

TEST_F(CtrlInterface, AControlWordWithOnlyStopLowStops) {
    GoOnline();
    EXPECT_EQ(Control(0x0005), kOnlineStoppedWord);
    Control(kIdle);
    Control(kStartOnline);
    EXPECT_EQ(Control(Without(ctrl::kStop | ctrl::kErrorReset)), kOnlineStoppedWord);
}

TEST_F(CtrlInterface, AnAllZeroToPacImageIsAnEmergencyStopNotACancel) {
    Control(kStartOnline);
    EXPECT_EQ(Control(kIdle), kOnlineActiveWord);
    ExchangeImage(ProcessImage(16));
    EXPECT_TRUE(pac_.EmergencyStopActive());
    EXPECT_EQ(StatusWord(), kOnlineStoppedWord);  // 39, no system error
    EXPECT_EQ(Status(), 39);
    EXPECT_EQ(Control(kIdle), kOnlineStoppedWord);
    EXPECT_EQ(Control(kStartOnline), kOnlineActiveWord);  // resume
}

TEST_F(CtrlInterface, WordsOneToThreeToPacAreIgnored) {
    Control(kStartOnline);
    Control(kIdle);
    ProcessImage image(16);
    const Image8 module = FromHex("00 07 FF FF FF FF FF FF");
    image.SetModule8(ModuleLayout::kCtrlOffset, module);
    for (int i = 0; i < 3; ++i) ExchangeImage(image);
    EXPECT_EQ(Status(), 31);
    EXPECT_EQ(StatusWord(), kOnlineActiveWord);
    EXPECT_EQ(CtrlHex(), "04 03 00 00 00 00 00 00");
}

TEST_F(CtrlInterface, IntegerFormatIsTakenOverOnEnteringOnlineOrAutomatic) {
    EXPECT_EQ(Control(kIdle | kInteger), kHomeWord);  // float in force after power-on
    EXPECT_EQ(Control(kStartOnline | kInteger), kHomeWord | ctrl::kIntegerInForce);  // 30: taken over
    EXPECT_TRUE(pac_.IntegerFormat());
    EXPECT_EQ(Control(kIdle), kOnlineActiveWord | ctrl::kIntegerInForce);  // bit 15 dropped: no change
    EXPECT_EQ(Control(kStopLow), kOnlineStoppedWord | ctrl::kIntegerInForce);
    EXPECT_EQ(Control(kStartOnline), kOnlineActiveWord | ctrl::kIntegerInForce);  // resume: no take-over
    EXPECT_EQ(Control(kCancelLow), kHomeWord | ctrl::kIntegerInForce);  // unchanged on returning home
    EXPECT_EQ(Control(kIdle), kHomeWord | ctrl::kIntegerInForce);
    EXPECT_EQ(Control(kStartAutomatic), kHomeWord);  // 10: float taken over
    EXPECT_EQ(Control(kIdle | kInteger), kAutoActiveWord);
    EXPECT_EQ(Control(kStopLow | kInteger), kAutoActiveWord);
    EXPECT_EQ(Control(kIdle | kInteger), kAutoStoppedWord);
    EXPECT_EQ(Control(kStartAutomatic | kInteger), kAutoActiveWord);  // 16: resume, still float
    EXPECT_EQ(Control(kCancelLow | kInteger), kHomeWord);
    // A CMD start takes the CTRL bit over too.
    ctrlWord_ = kIdle | kInteger;
    EXPECT_EQ(Send(code::kStartOnline), "00 00 00 00 00 1E 80 00");
    EXPECT_EQ(StatusWord(), kHomeWord | ctrl::kIntegerInForce);
    Send(code::kGetState);  // SEND back to 0, so the boot does not repeat the 0603
    // After a power cycle: float again, though the PLC still asks for integers.
    pac_.PowerCycle(now_);
    EXPECT_EQ(Control(kIdle | kInteger), kHomeWord);
    EXPECT_FALSE(pac_.IntegerFormat());
}

TEST(CtrlIntegerFormat, WithoutACtrlModuleTheFormatIsFloat) {
    PaControlConfig config = QuickConfig();
    config.modes.requireExternalStop = false;
    Bus bus;
    PaControl pac(bus, config);
    bus.WriteToPac(0ms, CommandImage(code::kStartOnline, 0, 0, true));
    pac.Cycle(0ms);
    pac.Cycle(10ms);
    EXPECT_EQ(pac.OperatingStatus(), 31);
    EXPECT_FALSE(pac.IntegerFormat());
    EXPECT_EQ(pac.CtrlStatusWord(), kOnlineActiveWord);
    EXPECT_EQ(bus.ReadFromPac(10ms).Size(), 8U);
}

// Both interfaces on the one mode machine: start via CTRL, stop via 0600 and cancel via 0A81 while the
// CTRL bits stay inactive; start via 0602, stop via CTRL, cancel via 0A41.
TEST_F(CtrlInterface, CtrlAndCmdTogether) {
    Control(kStartOnline);
    EXPECT_EQ(Control(kIdle), kOnlineActiveWord);
    MoveAxis1();
    EXPECT_EQ(Send(code::kStop), "00 00 00 00 00 20 80 00");  // 32, BF = 0
    EXPECT_EQ(StatusWord(), kOnlineActiveWord);
    for (int k = 0; k < 9; ++k) Idle();
    EXPECT_EQ(Idle(), "00 00 00 00 00 23 A0 00");  // 35, BF = 1
    EXPECT_EQ(StatusWord(), kOnlineStoppedWord);
    EXPECT_EQ(Control(kStartOnline), kOnlineActiveWord);  // resumed through CTRL
    EXPECT_EQ(Control(kIdle), kOnlineActiveWord);
    EXPECT_EQ(Send(code::kAbortOnline), "00 00 00 00 00 01 20 00");
    EXPECT_EQ(StatusWord(), kHomeWord);

    EXPECT_EQ(Send(code::kStartAuto), "00 00 00 00 00 0A 80 00");
    EXPECT_EQ(Idle(), "00 00 00 00 00 0B A0 00");
    EXPECT_EQ(StatusWord(), kAutoActiveWord);
    EXPECT_EQ(Control(kStopLow), kAutoActiveWord);  // 13
    EXPECT_EQ(Control(kIdle), kAutoStoppedWord);    // 15
    // 0602 resumes what CTRL stopped; then 0A41.
    EXPECT_EQ(Send(code::kStartAuto), "00 00 00 00 00 10 00 00");  // 16, BF = 0
    EXPECT_EQ(Idle(), "00 00 00 00 00 0B 20 00");
    EXPECT_EQ(Send(code::kAbortAuto), "00 00 00 00 00 01 A0 00");
    EXPECT_EQ(StatusWord(), kHomeWord);
}

TEST_F(CtrlInterface, ACtrlCancelEndsAPendingCmdStart) {
    EXPECT_EQ(Send(code::kStartOnline), "00 00 00 00 00 1E 80 00");  // 30, BF = 0
    ctrlWord_ = kCancelLow;
    EXPECT_EQ(Idle(), "00 00 00 00 00 01 A0 00");  // 31 then cancelled: BF = 1 in home position
}

TEST_F(CtrlInterface, ASystemErrorRaisedDuringACtrlStopEndsInTheMalfunctionStop) {
    Control(kStartOnline);
    Control(kIdle);
    MoveAxis1();
    EXPECT_EQ(Control(kStopLow), kOnlineActiveWord);  // 32
    pac_.RaiseSystemError(520);
    EXPECT_EQ(Control(kStopLow), kOnlineActiveWord | ctrl::kSystemError);  // 37
    EXPECT_EQ(Status(), 37);
    for (int k = 0; k < 8; ++k) Control(kStopLow);
    EXPECT_EQ(Control(kStopLow), kOnlineStoppedWord | ctrl::kSystemError);  // 39
    EXPECT_EQ(Control(kStartOnline), kOnlineStoppedWord | ctrl::kSystemError);
    EXPECT_EQ(Control(kCancelLow), kHomeWord);  // class 3 cleared
}

}  // namespace
}  // namespace pac::sim::testing
