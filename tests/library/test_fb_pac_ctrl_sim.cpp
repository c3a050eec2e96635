// FB_PAC_Ctrl (the library's ST, compiled to C) driving the simulated PA-CONTROL over the simulated bus,
// with the CMD and the CTRL module (ModuleLayout{true, 0}; manual 2.3.1, 2.5), scan by scan, on the bus
// timings of the FB_PAC_Cmd simulator tests: PLC cycle 1/2/5/10 ms x PA-CONTROL cycle 1/3/10 ms x
// latency 0..3 PLC cycles each way, and some jittered buses (the seed is in the test name and in every
// failure). Every scan runs the PLCopen checker on both FBs (plcopen_checker.hpp) and checks the control
// word on the wire (ControlWordRules); every Done, error and timeout is checked against the scan window
// the protocol allows (scan_window.hpp): an exact scan without jitter.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "rig_timing.hpp"
#include "bus_timing.hpp"
#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/scan_test.hpp"
#include "pac/st_program.hpp"
#include "pac/pac_rig.hpp"
#include "plcopen_checker.hpp"
#include "run_to_final.hpp"
#include "scan_window.hpp"

namespace test_fb_pac_ctrl_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using std::chrono::nanoseconds;
namespace sim = pac::sim;
using pac::test::BusTiming;
using pac::test::FinalOutcome;
using pac::test::ProtocolWindow;
using pac::test::ScanWindow;

const pac::test::GvlConstants kGvl;
const std::uint32_t kErrNotReady = kGvl["PAC_LIB_ERR_NOT_READY"];
const std::uint32_t kErrConnectionLost = kGvl["PAC_LIB_ERR_CONNECTION_LOST"];
const std::uint32_t kErrNotAllowed = kGvl["PAC_LIB_ERR_NOT_ALLOWED"];
const std::uint32_t kErrRequestTimeout = kGvl["PAC_LIB_ERR_REQUEST_TIMEOUT"];

using Request = E_PAC_CTRLREQUEST;
constexpr Request kStartOnline = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
constexpr Request kStartAutomatic = E_PAC_CTRLREQUEST__PAC_REQ_START_AUTOMATIC;
constexpr Request kStop = E_PAC_CTRLREQUEST__PAC_REQ_STOP;
constexpr Request kCancel = E_PAC_CTRLREQUEST__PAC_REQ_CANCEL;
constexpr Request kResetError = E_PAC_CTRLREQUEST__PAC_REQ_RESET_ERROR;

// Mode commands of the CMD interface (5.2.1, 5.2.5.1, 5.2.6.1).
constexpr std::uint16_t kCmdStop = 0x0600;
constexpr std::uint16_t kCmdStartAutomatic = 0x0602;
constexpr std::uint16_t kCmdStartOnline = 0x0603;
constexpr std::uint16_t kCmdCancelAutomatic = 0x0A41;
constexpr std::uint16_t kCmdCancelOnline = 0x0A81;

// The external stop input (system parameter 4, 5.2.1.3) the fixture wires: input 1.
constexpr std::uint32_t kStopInput = 1;

const char* Name(Request r) {
    switch (r) {
        case E_PAC_CTRLREQUEST__PAC_REQ_NONE: return "NONE";
        case kStartOnline: return "START_ONLINE";
        case kStartAutomatic: return "START_AUTOMATIC";
        case kStop: return "STOP";
        case kCancel: return "CANCEL";
        case kResetError: return "RESET_ERROR";
    }
    return "?";
}

// Low byte of the control word (2.5.1) as FB_PAC_Ctrl must write it: outside a request Error reset, Stop
// and Cancel at 1 and no start bit; during one, exactly the request's bit differs.
constexpr std::uint8_t kIdleByte = 0x07;
std::uint8_t RequestByte(Request r) {
    switch (r) {
        case kStartOnline: return 0x17;
        case kStartAutomatic: return 0x0F;
        case kStop: return 0x05;
        case kCancel: return 0x03;
        case kResetError: return 0x06;
        default: return kIdleByte;
    }
}

// The mode bit the CTRL status word shows for an operating status, written out from the project's
// decisions (docs/fb/FB_PAC_Ctrl.md) rather than taken from the simulator.
enum class Shown { kNoMode, kAutomaticActive, kAutomaticStopped, kOnlineActive, kOnlineStopped };

Shown ShownFor(int status) {
    switch (status) {
        case 11: case 12: case 13: case 16: case 17: case 18: return Shown::kAutomaticActive;
        case 15: case 19: return Shown::kAutomaticStopped;
        case 31: case 32: case 37: return Shown::kOnlineActive;
        case 35: case 39: return Shown::kOnlineStopped;
        default: return Shown::kNoMode;
    }
}

// ---------------------------------------------------------------------------------------------------
// The PLC

// The control word rules of 2.5.1 and docs/fb/FB_PAC_Ctrl.md, after every scan: never all zero, only
// bits 0..4 and 15, bit 15 = IntegerMode, idle (16#07) outside a request and exactly the request's bit
// during one, words 1..3 zero; and the controller never read an all-zero control word. Reports the
// first violations, with the bus timing and the scan.
class ControlWordRules {
public:
    explicit ControlWordRules(const BusTiming& timing) : timing_(timing) {}

    void Check(const FB_PAC_CTRL& c, Request latched, const sim::ProcessImage& toPac,
               const sim::ProcessImage& controllerRead, const pac::PlcTask& task) {
        const std::uint16_t word = ControlWord(toPac);
        Expect(word != 0, "all-zero control word on the wire", task);
        Expect((word & 0x8000U) == (c.INTEGERMODE.value ? 0x8000U : 0U), "bit 15 does not follow IntegerMode", task);
        const std::uint8_t expected = c.BUSY.value ? RequestByte(latched) : kIdleByte;
        Expect((word & 0x7FFFU) == expected,
               "control word 16#" + Hex(word) + ", expected low byte 16#" + Hex(expected), task);
        for (std::size_t i = 10; i < 16; ++i) Expect(toPac[i] == 0, "CTRL words 1..3 not zero", task);
        if (!controllerRead.AllZero()) {
            Expect(ControlWord(controllerRead) != 0, "the controller read an all-zero control word", task);
        }
    }

    // Word 0 of the CTRL module (PAC bytes 8, 9 of the image), big-endian.
    static std::uint16_t ControlWord(const sim::ProcessImage& image) {
        return static_cast<std::uint16_t>((image[8] << 8) | image[9]);
    }

private:
    void Expect(bool ok, const std::string& what, const pac::PlcTask& task) {
        if (ok || ++violations_ > 10) return;
        ADD_FAILURE() << what << " (" << Describe(timing_) << ", " << pac::detail::Position(task) << ")";
    }
    static std::string Hex(unsigned v) {
        std::ostringstream out;
        out << std::hex << std::uppercase << v;
        return out.str();
    }

    BusTiming timing_;
    int violations_ = 0;
};

// A PLC with FB_PAC_Cmd on the CMD module and FB_PAC_Ctrl on the CTRL module of a simulated
// PA-CONTROL, the external stop input wired and powered. After each of its FBs a hand-written "naive
// master" may zero the module (off unless a test turns it on). Scan() runs the PLCopen checker on both
// FBs after every scan, and ControlWordRules until a naive master has written.
// A bus timing and a reading of the CTRL status word the manual leaves open (docs/open_points.md): does a
// stopped mode keep its "active" bit? Every CtrlSim test runs on both.
struct CtrlSimCase : BusTiming {
    sim::StoppedModeBits stoppedModeBits = sim::StoppedModeBits::kStoppedAlone;
};

sim::PaControlConfig WithReading(sim::PaControlConfig config, sim::StoppedModeBits bits) {
    config.ctrlInterface.stoppedModeBits = bits;
    return config;
}

class CtrlSimPlc {
public:
    explicit CtrlSimPlc(const CtrlSimCase& c, sim::PaControlConfig config = {}, nanoseconds bootTime = 0ns)
        : CtrlSimPlc(static_cast<const BusTiming&>(c), WithReading(config, c.stoppedModeBits), bootTime) {}
    explicit CtrlSimPlc(const BusTiming& timing, sim::PaControlConfig config = {}, nanoseconds bootTime = 0ns)
        : timing_(timing),
          rig_(pac::test::RigTimingOf(timing, bootTime), config, sim::ModuleLayout{true, 0}),
          window_(timing),
          rules_(timing) {
        rig_.Call(cmd_);
        rig_.CallRaw8(sim::ModuleLayout::kCmdOffset, [this](const sim::Image8&, sim::Image8& out) {
            if (zeroCmdModule_) out = sim::Image8{};
        });
        rig_.CallCtrl(ctrl_);
        rig_.CallRaw8(sim::ModuleLayout::kCtrlOffset, [this](const sim::Image8&, sim::Image8& out) {
            if (zeroCtrlModule_) out = sim::Image8{};
        });
        rig_.Start();
        WireExternalStop(true);
    }

    // System parameter 4 = input 1 (5.2.1.3), with or without power.
    void WireExternalStop(bool powered) {
        EXPECT_EQ(Controller().SystemParameters().Set(4, kStopInput), sim::ParameterTable::SetResult::kOk);
        Controller().Io().inputs.Set(static_cast<int>(kStopInput), powered);
    }
    void UnwireExternalStop() {
        EXPECT_EQ(Controller().SystemParameters().Set(4, 0), sim::ParameterTable::SetResult::kOk);
    }

    void Scan(int n = 1) {
        for (int i = 0; i < n; ++i) {
            rig_.Scan();
            const std::int64_t scan = rig_.Task().ScanCount();
            const auto plcCycle = timing_.PlcCycle();
            ctrlRules_.Check(scan, ctrl_, pac::test::RequestBusyBoundOf(ctrl_, plcCycle));
            cmdRules_.Check(scan, cmd_, pac::test::CommandBusyBoundOf(cmd_, plcCycle));
            if (!naiveSeen_) {
                rules_.Check(ctrl_.Data(), latched_, rig_.ToPac(), Controller().LastToPacImage(), rig_.Task());
            }
        }
    }
    // Scans until `predicate` holds; the scans run, or -1 after maxScans.
    int ScanUntil(const std::function<bool()>& predicate, int maxScans) {
        for (int scans = 1; scans <= maxScans; ++scans) {
            Scan();
            if (predicate()) return scans;
        }
        return -1;
    }
    // One scan; its number.
    std::int64_t Step() {
        Scan();
        return rig_.Task().ScanCount();
    }
    // Until the FB shows Ready, then until the controller has read the idle control word and the FB
    // shows the controller's answer (the first control word after the boot is only the reference for
    // the edges).
    void Settle() {
        EXPECT_GE(ScanUntil([this] { return ctrl_->READY.value != 0; }, ScansFor(2s)), 0) << "never Ready";
        Scan(window_.RoundTripScans());
    }
    void Wait() { Scan(window_.RoundTripScans()); }

    // ---- FB_PAC_Ctrl ----
    // Execute rises: runs the edge scan.
    void Begin(Request r) {
        EXPECT_FALSE(ctrl_->EXECUTE.value || Busy()) << Name(r) << ": Execute still high or Busy";
        ctrl_->REQUEST.value = r;
        ctrl_->EXECUTE.value = TRUE;
        latched_ = r;
        Scan();
        edge_ = Now();
        edgeScan_ = rig_.Task().ScanCount();
    }
    // Scans until Done or Error, at most maxScans after the edge scan.
    FinalOutcome WaitEnd(int maxScans) {
        return pac::test::RunToFinal(ctrl_, edgeScan_, [this] { return Step(); }, maxScans);
    }
    // Execute falls: the final output clears in the scan that sees it (the PLCopen checker).
    void Release() {
        ctrl_->EXECUTE.value = FALSE;
        Scan();
    }
    // One request from edge to release, with one more scan while Execute is high (the final output
    // holds: the PLCopen checker).
    FinalOutcome Run(Request r, int maxScans = -1) {
        Begin(r);
        const FinalOutcome f = WaitEnd(maxScans < 0 ? ScansFor(3s) : maxScans);
        Scan();
        Release();
        return f;
    }
    // The window for Done of the request whose edge scan ran last.
    ScanWindow DoneWindow(int extraCycles) const { return window_.Request(edge_, extraCycles); }

    // A fresh FB_PAC_Ctrl instance: the first scan after a PLC restart with a new program.
    void RestartPlcProgram() {
        ctrl_ = PAC_FB(FB_PAC_CTRL);
        ctrlRules_.Restart();
        latched_ = E_PAC_CTRLREQUEST__PAC_REQ_NONE;
    }

    // ---- FB_PAC_Cmd ----
    FinalOutcome Command(std::uint16_t code) {
        cmd_->CODE.value = code;
        cmd_->PARAM.value = 0;
        cmd_->DATA.value = 0;
        cmd_->EXECUTE.value = TRUE;
        Scan();
        edge_ = Now();
        const FinalOutcome f = pac::test::RunToFinal(cmd_, rig_.Task().ScanCount(), [this] { return Step(); },
                                                     ScansFor(3s));
        cmdOpStatus_ = cmd_->OPSTATUS.value;
        ctrlAtCmdEnd_ = ctrl_.Data();
        cmd_->EXECUTE.value = FALSE;
        Scan();
        return f;
    }
    int CmdOpStatusAtEnd() const { return cmdOpStatus_; }
    const FB_PAC_CTRL& CtrlAtCmdEnd() const { return ctrlAtCmdEnd_; }

    // ---- naive masters (contrast) ----
    void ZeroCtrlModule(bool on) {
        zeroCtrlModule_ = on;
        naiveSeen_ = naiveSeen_ || on;
    }
    void ZeroCmdModule(bool on) {
        zeroCmdModule_ = on;
        naiveSeen_ = naiveSeen_ || on;
    }

    // ---- what the FB and the controller show ----
    // The controller's operating status and system error, and the FB's status outputs decoded from the
    // reply, agree with `status` and `errorNumber`. Call when both have settled.
    ::testing::AssertionResult Shows(int status, std::uint16_t errorNumber = 0) {
        std::ostringstream bad;
        if (Controller().OperatingStatus() != status) {
            bad << " controller status " << int{Controller().OperatingStatus()} << " (expected " << status << ")";
        }
        if (Controller().SystemError() != errorNumber) {
            bad << " controller system error " << Controller().SystemError() << " (expected " << errorNumber << ")";
        }
        const Shown shown = ShownFor(status);
        const bool cpuError = errorNumber >= 1 && errorNumber <= 99;
        auto pin = [&](const char* name, bool actual, bool expected) {
            if (actual != expected) bad << ' ' << name << '=' << actual;
        };
        pin("Ready", ctrl_->READY.value, !cpuError);
        pin("BatteryOk", ctrl_->BATTERYOK.value, true);
        pin("SystemError", ctrl_->SYSTEMERROR.value, errorNumber != 0);
        pin("AutomaticActive", ctrl_->AUTOMATICACTIVE.value, shown == Shown::kAutomaticActive);
        pin("AutomaticStopped", ctrl_->AUTOMATICSTOPPED.value, shown == Shown::kAutomaticStopped);
        pin("OnlineActive", ctrl_->ONLINEACTIVE.value, shown == Shown::kOnlineActive);
        pin("OnlineStopped", ctrl_->ONLINESTOPPED.value, shown == Shown::kOnlineStopped);
        pin("IntegerModeActive", ctrl_->INTEGERMODEACTIVE.value, Controller().IntegerFormat());
        if (ctrl_->SYSTEMERRORNUMBER.value != errorNumber) {
            bad << " SystemErrorNumber=" << ctrl_->SYSTEMERRORNUMBER.value;
        }
        if (bad.str().empty()) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "expected status " << status << " error " << errorNumber << ":"
                                             << bad.str();
    }
    ::testing::AssertionResult SettledAt(int status, std::uint16_t errorNumber = 0) {
        Wait();
        return Shows(status, errorNumber);
    }

    // The CTRL control word the PLC wrote in its last scan, and the one the controller read last.
    std::uint16_t WireControlWord() const { return ControlWordRules::ControlWord(rig_.ToPac()); }
    std::uint16_t ControlWordSeenByController() { return ControlWordRules::ControlWord(Controller().LastToPacImage()); }
    std::uint16_t IdleWord() { return static_cast<std::uint16_t>((ctrl_->INTEGERMODE.value ? 0x8000 : 0) | kIdleByte); }

    bool Done() const { return ctrl_->DONE.value != 0; }
    bool Busy() const { return ctrl_->BUSY.value != 0; }
    bool Error() const { return ctrl_->ERROR.value != 0; }
    bool Ended() const { return Done() || Error(); }
    std::uint32_t ErrorId() const { return ctrl_->ERRORID.value; }

    int ScansFor(nanoseconds t) const { return timing_.ScansFor(t); }
    pac::FbInstance<FB_PAC_CTRL>& Ctrl() { return ctrl_; }
    pac::FbInstance<FB_PAC_CMD>& Cmd() { return cmd_; }
    sim::PaControl& Controller() { return rig_.Controller(); }
    sim::Bus& Bus() { return rig_.Bus(); }
    nanoseconds Now() const { return rig_.Now(); }
    std::int64_t ScanCount() { return rig_.Task().ScanCount(); }
    nanoseconds Edge() const { return edge_; }
    const ProtocolWindow& Window() const { return window_; }
    const BusTiming& Timing() const { return timing_; }

private:
    BusTiming timing_;
    pac::PacRig rig_;
    ProtocolWindow window_;
    ControlWordRules rules_;
    pac::FbInstance<FB_PAC_CTRL> ctrl_ = PAC_FB(FB_PAC_CTRL);
    pac::FbInstance<FB_PAC_CMD> cmd_ = PAC_FB(FB_PAC_CMD);
    pac::test::PlcOpenChecker ctrlRules_{"FB_PAC_Ctrl"};
    pac::test::PlcOpenChecker cmdRules_{"FB_PAC_Cmd"};
    Request latched_ = E_PAC_CTRLREQUEST__PAC_REQ_NONE;
    nanoseconds edge_{0};
    std::int64_t edgeScan_ = 0;
    bool zeroCtrlModule_ = false;
    bool zeroCmdModule_ = false;
    bool naiveSeen_ = false;
    int cmdOpStatus_ = -1;
    FB_PAC_CTRL ctrlAtCmdEnd_{};
};

// A config whose AUTOMATIC stand-in takes the given controller cycles in 10, 13, 16 and 18.
sim::PaControlConfig Script(int started, int stopProgram, int startAfterStop, int malfunctionProgram) {
    sim::PaControlConfig config;
    config.modes.automatic = {started, stopProgram, startAfterStop, malfunctionProgram};
    return config;
}

// Axis 1 travels far at 1000 AE/s in ONLINE, with a braking deceleration (axis parameter 6) low enough
// that a stop (32) or a malfunction (37) lasts while the test looks at it. Set before START ONLINE,
// which takes the parameters over.
void SlowBraking(CtrlSimPlc& plc, float deceleration) {
    ASSERT_EQ(plc.Controller().Axes().Parameters(1).Set(6, sim::FloatToBits(deceleration)),
              sim::ParameterTable::SetResult::kOk);
}
// The test hook starts at full speed at once (no ramp up, so the braking time is speed / deceleration)
// towards the far end of the traverse range, braking at the session's deceleration.
void MoveAxis1(CtrlSimPlc& plc) {
    sim::AxisGroup& axes = plc.Controller().Axes();
    sim::Dynamics dynamics = axes.SessionDynamics(1);
    dynamics.speed = 1000.0;
    dynamics.acceleration = 1.0e12;
    sim::ServoAxis& axis = axes.Motion(1);
    ASSERT_EQ(axis.MoveAbsolute(plc.Now(), axis.MaxRange(), dynamics), 0u);
}

class CtrlSim : public ::testing::TestWithParam<CtrlSimCase> {
protected:
    void SetUp() override { RecordProperty("bus", pac::test::Describe(GetParam())); }
};

// CANCEL and RESET ERROR are Done on no mode bit, which a start's one-cycle status shows too: only once
// their bit has been out for the bus both ways and the controller's cycle (70 ms), then 7 more scans.
bool ShownAsHome(Request r) { return r == kCancel || r == kResetError; }
int ReadScans(const BusTiming& t) {
    return static_cast<int>((std::chrono::milliseconds(70) + t.PlcCycle() - std::chrono::nanoseconds(1)) / t.PlcCycle()) + 7;
}

// The window for Done of `r` whose edge scan ran last: `extraCycles` transitional controller cycles, for
// CANCEL and RESET ERROR not before their bit was read.
ScanWindow DoneWindowOf(const CtrlSimPlc& plc, Request r, int extraCycles) {
    ScanWindow w = plc.DoneWindow(extraCycles);
    if (ShownAsHome(r)) {
        w.min = std::max(w.min, ReadScans(plc.Timing()));
        w.max = std::max(w.max, ReadScans(plc.Timing()));
    }
    return w;
}

// Runs `r`: Done in the scan window of `extraCycles` transitional controller cycles.
::testing::AssertionResult DoneInWindow(CtrlSimPlc& plc, Request r, int extraCycles) {
    const FinalOutcome f = plc.Run(r);
    const ScanWindow w = DoneWindowOf(plc, r, extraCycles);
    if (f.Done() && w.Contains(f.Scans())) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << Name(r) << ": " << f << ", the protocol allows " << w;
}

// Runs CANCEL or RESET ERROR where the status word already shows its result: the bit goes out, Done exactly
// when it has been read.
::testing::AssertionResult DoneOnceRead(CtrlSimPlc& plc, Request r) {
    const FinalOutcome f = plc.Run(r);
    if (f.Done() && f.Scans() == ReadScans(plc.Timing())) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << Name(r) << ": " << f << ", expected Done " << ReadScans(plc.Timing())
                                         << " scans after the edge";
}

// Runs `r`: decided in the edge scan, Done at once (errorId 0) or the error `errorId`.
::testing::AssertionResult DecidedAtOnce(CtrlSimPlc& plc, Request r, std::uint32_t errorId) {
    const FinalOutcome f = plc.Run(r);
    if (f.Scans() == 0 && f.ErrorId() == errorId && f.Done() == (errorId == 0)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << Name(r) << ": " << f << ", expected in the edge scan "
                                         << (errorId == 0 ? std::string("Done") : "ErrorID " + std::to_string(errorId));
}

// ---------------------------------------------------------------------------------------------------
// Every transition through CTRL, Done at the first scan the protocol allows

TEST_P(CtrlSim, OnlineStartStopResumeCancel) {
    CtrlSimPlc plc(GetParam());
    plc.Settle();
    ASSERT_TRUE(plc.Shows(1));
    EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 1));  // 1 -> 30 (one cycle) -> 31
    EXPECT_TRUE(plc.SettledAt(31));
    EXPECT_TRUE(DoneInWindow(plc, kStop, 0));  // no axis moves: 31 -> 32 -> 35 within the cycle
    EXPECT_TRUE(plc.SettledAt(35));
    EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 0));  // resume: 35 -> 31
    EXPECT_TRUE(plc.SettledAt(31));
    EXPECT_TRUE(DoneInWindow(plc, kCancel, 0));
    EXPECT_TRUE(plc.SettledAt(1));
    plc.Scan(plc.ScansFor(500ms));
    EXPECT_TRUE(plc.Shows(1)) << "nothing more happens after the last request";
    EXPECT_EQ(plc.Controller().Counters().recognized - plc.Controller().Counters().Count(0x190B), 0u) << "no command on the CMD interface";
}

TEST_P(CtrlSim, AutomaticStartStopResumeCancel) {
    CtrlSimPlc plc(GetParam());
    plc.Settle();
    EXPECT_TRUE(DoneInWindow(plc, kStartAutomatic, 1));  // 1 -> 10 (startedCycles = 1) -> 11
    EXPECT_TRUE(plc.SettledAt(11));
    EXPECT_TRUE(DoneInWindow(plc, kStop, 1));  // 11 -> 12 -> 13 (stopProgramCycles = 1) -> 15
    EXPECT_TRUE(plc.SettledAt(15));
    EXPECT_TRUE(DoneInWindow(plc, kStartAutomatic, 0));  // resume: 15 -> 16, which shows AUTOMATIC active
    EXPECT_TRUE(plc.SettledAt(11)) << "16 -> 11 after startAfterStopCycles";
    EXPECT_TRUE(DoneInWindow(plc, kCancel, 0));
    EXPECT_TRUE(plc.SettledAt(1));
}

TEST_P(CtrlSim, DoneFollowsTheAutomaticScriptsTransitionalCycles) {
    CtrlSimPlc plc(GetParam(), Script(3, 4, 2, 1));
    plc.Settle();
    EXPECT_TRUE(DoneInWindow(plc, kStartAutomatic, 3));
    EXPECT_TRUE(plc.SettledAt(11));
    EXPECT_TRUE(DoneInWindow(plc, kStop, 4));
    EXPECT_TRUE(plc.SettledAt(15));
    EXPECT_TRUE(DoneInWindow(plc, kStartAutomatic, 0));
    EXPECT_TRUE(plc.SettledAt(11));
}

TEST_P(CtrlSim, StopWaitsForTheBrakingAxis) {
    CtrlSimPlc plc(GetParam());
    SlowBraking(plc, 4000.0F);  // 1000 AE/s: 250 ms of braking
    plc.Settle();
    ASSERT_TRUE(plc.Run(kStartOnline).Done());
    MoveAxis1(plc);
    plc.Begin(kStop);
    const nanoseconds edge = plc.Edge();
    const FinalOutcome f = plc.WaitEnd(plc.ScansFor(2s));
    ASSERT_TRUE(f.Done()) << f;
    EXPECT_GE(plc.Now() - edge, 250ms) << "Done before the axis stood";
    // The controller reads the stop within a cycle of its arrival, notices the axis standing within a
    // cycle, and the reply travels back and is read by the next scan.
    const BusTiming& t = GetParam();
    EXPECT_LE(plc.Now() - edge, 250ms + 2 * t.PacCycle() + 2 * (t.Latency() + t.Jitter()) + t.PlcCycle())
        << "Done later than braking plus the bus";
    EXPECT_FALSE(plc.Controller().Axes().AnyMoving());
    plc.Release();
    EXPECT_TRUE(plc.SettledAt(35));
}

// ---------------------------------------------------------------------------------------------------
// System error classes (5.2.4.15)

TEST_P(CtrlSim, Class2ErrorIsResetInHomePosition) {
    CtrlSimPlc plc(GetParam());
    plc.Settle();
    plc.Controller().RaiseSystemError(150);
    const ScanWindow shown = plc.Window().Event(plc.Now());
    const int scans = plc.ScanUntil([&] { return plc.Ctrl()->SYSTEMERROR.value != 0; }, 1000);
    EXPECT_TRUE(shown.Contains(scans)) << "SystemError after " << scans << ", expected " << shown;
    EXPECT_TRUE(plc.SettledAt(9, 150));
    EXPECT_TRUE(DecidedAtOnce(plc, kStartOnline, kErrNotAllowed));
    EXPECT_TRUE(DoneInWindow(plc, kResetError, 0));
    EXPECT_TRUE(plc.SettledAt(1));
    EXPECT_TRUE(DoneOnceRead(plc, kResetError));  // nothing left to reset
    EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 1));
}

TEST_P(CtrlSim, Class2ErrorInOnlineNeedsCancelThenReset) {
    CtrlSimPlc plc(GetParam());
    plc.Settle();
    ASSERT_TRUE(plc.Run(kStartOnline).Done());
    plc.Controller().RaiseSystemError(230);
    EXPECT_TRUE(plc.SettledAt(39, 230));
    EXPECT_TRUE(DecidedAtOnce(plc, kStartOnline, kErrNotAllowed));  // no resume with an error pending
    EXPECT_TRUE(DecidedAtOnce(plc, kResetError, kErrNotAllowed));  // not in home position
    EXPECT_TRUE(DecidedAtOnce(plc, kStop, 0));  // stopped already
    EXPECT_TRUE(DoneInWindow(plc, kCancel, 0));
    EXPECT_TRUE(plc.SettledAt(9, 230)) << "class 2 stays in home position";
    EXPECT_TRUE(DoneInWindow(plc, kResetError, 0));
    EXPECT_TRUE(plc.SettledAt(1));
    EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 1));
}

TEST_P(CtrlSim, Class3ErrorIsClearedOnReturningHome) {
    CtrlSimPlc plc(GetParam());
    plc.Settle();
    ASSERT_TRUE(plc.Run(kStartOnline).Done());
    plc.Controller().RaiseSystemError(600);
    EXPECT_TRUE(plc.SettledAt(39, 600));
    plc.Begin(kCancel);
    const FinalOutcome f = plc.WaitEnd(1000);
    EXPECT_TRUE(f.Done() && DoneWindowOf(plc, kCancel, 0).Contains(f.Scans())) << f;
    EXPECT_FALSE(plc.Ctrl()->SYSTEMERROR.value) << "cleared in the reply that shows home position";
    EXPECT_EQ(plc.Ctrl()->SYSTEMERRORNUMBER.value, 0);
    plc.Release();
    EXPECT_TRUE(plc.SettledAt(1));
    EXPECT_TRUE(DoneOnceRead(plc, kResetError));

    ASSERT_TRUE(plc.Run(kStartAutomatic).Done());
    plc.Controller().RaiseSystemError(700);
    EXPECT_TRUE(plc.SettledAt(19, 700));
    EXPECT_TRUE(DecidedAtOnce(plc, kStartAutomatic, kErrNotAllowed));
    EXPECT_TRUE(DoneInWindow(plc, kCancel, 0));
    EXPECT_TRUE(plc.SettledAt(1));
}

TEST_P(CtrlSim, Class1ErrorOnlyByPowerCycle) {
    CtrlSimPlc plc(GetParam(), {}, 50ms);
    plc.Settle();
    ASSERT_TRUE(plc.Run(kStartOnline).Done());
    plc.Controller().RaiseSystemError(42);
    EXPECT_TRUE(plc.SettledAt(39, 42));
    EXPECT_FALSE(plc.Ctrl()->READY.value);
    EXPECT_TRUE(DecidedAtOnce(plc, kResetError, kErrNotAllowed));  // only a power cycle clears a CPU error
    EXPECT_TRUE(DecidedAtOnce(plc, kStartOnline, kErrNotReady));
    // Stop and cancel stay possible: the controller is stopped already (39) and goes home (9).
    EXPECT_TRUE(DecidedAtOnce(plc, kStop, 0));
    EXPECT_TRUE(DoneInWindow(plc, kCancel, 0));
    EXPECT_TRUE(plc.SettledAt(9, 42));
    EXPECT_FALSE(plc.Ctrl()->READY.value);
    plc.Controller().PowerCycle(plc.Now());
    plc.Settle();
    EXPECT_TRUE(plc.Shows(1));
    EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 1));
    EXPECT_TRUE(plc.SettledAt(31));
}

// ---------------------------------------------------------------------------------------------------
// CTRL and CMD together

TEST_P(CtrlSim, CtrlStartsOnlineAndCmdStopsIt) {
    CtrlSimPlc plc(GetParam());
    plc.Settle();
    EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 1));
    const FinalOutcome stop = plc.Command(kCmdStop);
    ASSERT_TRUE(stop.Done()) << stop;
    EXPECT_EQ(plc.CmdOpStatusAtEnd(), 35);
    EXPECT_TRUE(plc.CtrlAtCmdEnd().ONLINESTOPPED.value) << "one consistent reply: OnlineStopped with 0600's Done";
    EXPECT_FALSE(plc.CtrlAtCmdEnd().ONLINEACTIVE.value);
    EXPECT_TRUE(plc.SettledAt(35));
    EXPECT_TRUE(DecidedAtOnce(plc, kStop, 0));  // stopped already: nothing to send
    EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 0));  // resume through CTRL
    EXPECT_TRUE(plc.SettledAt(31));
    ASSERT_TRUE(plc.Command(kCmdCancelOnline).Done());
    EXPECT_TRUE(plc.SettledAt(1));
    EXPECT_TRUE(DoneOnceRead(plc, kCancel));
    EXPECT_EQ(plc.Controller().Counters().recognized - plc.Controller().Counters().Count(0x190B), 2u);
}

TEST_P(CtrlSim, CmdStartsAndCtrlCancels) {
    CtrlSimPlc plc(GetParam());
    plc.Settle();
    const FinalOutcome start = plc.Command(kCmdStartOnline);
    ASSERT_TRUE(start.Done()) << start;
    EXPECT_EQ(plc.CmdOpStatusAtEnd(), 31);
    EXPECT_TRUE(plc.CtrlAtCmdEnd().ONLINEACTIVE.value);
    EXPECT_TRUE(DecidedAtOnce(plc, kStartOnline, 0));  // ONLINE active already
    EXPECT_TRUE(DoneInWindow(plc, kCancel, 0));
    EXPECT_TRUE(plc.SettledAt(1));

    ASSERT_TRUE(plc.Command(kCmdStartAutomatic).Done());
    EXPECT_TRUE(plc.SettledAt(11));
    EXPECT_TRUE(DoneInWindow(plc, kStop, 1));
    EXPECT_TRUE(plc.SettledAt(15));
    ASSERT_TRUE(plc.Command(kCmdStartAutomatic).Done());  // resume through CMD
    EXPECT_TRUE(plc.SettledAt(11));
    EXPECT_TRUE(DoneInWindow(plc, kCancel, 0));
    EXPECT_TRUE(plc.SettledAt(1));
    EXPECT_EQ(plc.Controller().Counters().Count(kCmdCancelOnline), 0u);
    EXPECT_EQ(plc.Controller().Counters().Count(kCmdCancelAutomatic), 0u);
}

// A cancel over CMD while a CTRL stop waits for the braking axis: the controller goes home, so the stop's
// result ("stopped") can no longer come; the stop request ends with 16#8008 in the scan that sees home
// position, the scan in which FB_PAC_Cmd sees its 0A81 done.
TEST_P(CtrlSim, CmdCancelWhileACtrlStopWaitsEndsTheStopAtOnce) {
    CtrlSimPlc plc(GetParam());
    SlowBraking(plc, 1000.0F);  // 1 s
    plc.Settle();
    ASSERT_TRUE(plc.Run(kStartOnline).Done());
    MoveAxis1(plc);
    plc.Ctrl()->TIMEOUT.value = pac::ToIecTime(400ms);
    plc.Begin(kStop);
    ASSERT_GT(plc.ScanUntil([&] { return plc.Controller().OperatingStatus() == 32; }, 1000), 0);
    plc.Cmd()->CODE.value = kCmdCancelOnline;
    plc.Cmd()->EXECUTE.value = TRUE;
    ASSERT_GT(plc.ScanUntil([&] { return plc.Ctrl()->ERROR.value != 0; }, 1000), 0);
    EXPECT_EQ(plc.Ctrl()->ERRORID.value, kErrNotAllowed);
    EXPECT_TRUE(plc.Cmd()->DONE.value) << "in the scan that shows home position";
    EXPECT_FALSE(plc.Ctrl()->ONLINESTOPPED.value);
    plc.Release();
    plc.Cmd()->EXECUTE.value = FALSE;
    EXPECT_TRUE(plc.SettledAt(1));
}

// The FB_PAC_Ctrl called in every scan holds Stop and Cancel at 1: modes driven over the CMD interface
// stay where the commands put them, scan after scan, and take the integer format from its bit 15.
TEST_P(CtrlSim, IdleCtrlModuleNeverDisturbsCmdDrivenModes) {
    CtrlSimPlc plc(GetParam());
    plc.Ctrl()->INTEGERMODE.value = TRUE;
    plc.Settle();
    const struct {
        std::uint16_t code;
        int status;
    } steps[] = {{kCmdStartOnline, 31}, {kCmdStop, 35},           {kCmdStartOnline, 31},
                 {kCmdCancelOnline, 1}, {kCmdStartAutomatic, 11}, {kCmdStop, 15},
                 {kCmdStartAutomatic, 11}, {kCmdCancelAutomatic, 1}};
    for (const auto& step : steps) {
        std::ostringstream code;
        code << "command " << std::hex << std::setw(4) << std::setfill('0') << step.code;
        SCOPED_TRACE(code.str());
        const FinalOutcome f = plc.Command(step.code);
        ASSERT_TRUE(f.Done()) << f;
        const int scans = plc.ScansFor(300ms);
        for (int i = 0; i < scans; ++i) {
            plc.Scan();
            ASSERT_EQ(plc.Controller().OperatingStatus(), step.status) << "scan " << i << " after the command";
        }
        EXPECT_TRUE(plc.Shows(step.status));
        EXPECT_TRUE(plc.Ctrl()->INTEGERMODEACTIVE.value) << "0603 / 0602 took CTRL bit 15 over";
    }
    EXPECT_EQ(plc.Controller().Counters().recognized - plc.Controller().Counters().Count(0x190B), 8u);
    EXPECT_EQ(plc.Controller().Counters().failed, 0u);
}

// Contrast: a CTRL module left at zero cancels a mode started over CMD (the low-active Cancel), so the
// test above could fail.
TEST_P(CtrlSim, ContrastAnAllZeroCtrlModuleCancelsACmdStart) {
    CtrlSimPlc plc(GetParam());
    plc.Settle();
    plc.ZeroCtrlModule(true);
    plc.Wait();
    const FinalOutcome f = plc.Command(kCmdStartOnline);
    ASSERT_TRUE(f.Done()) << f;
    EXPECT_EQ(plc.CmdOpStatusAtEnd(), 1) << "0603 ends in the status it settles on: home position";
    EXPECT_EQ(plc.Controller().OperatingStatus(), 1);
}

// ---------------------------------------------------------------------------------------------------
// Requests that do not apply: refused in the edge scan, nothing sent; and where the FB cannot know

enum class Outcome { kWaits, kDoneAtOnce, kNotAllowed, kNotReady };

struct StateCase {
    const char* name;
    sim::PaControlConfig config;
    std::function<void(CtrlSimPlc&)> reach;
    int status;
    std::uint16_t errorNumber;
    Outcome startOnline, startAutomatic, stop, cancel, resetError;
};

std::vector<StateCase> States() {
    const Outcome W = Outcome::kWaits, D = Outcome::kDoneAtOnce, N = Outcome::kNotAllowed, R = Outcome::kNotReady;
    auto run = [](std::initializer_list<Request> requests) {
        return [requests = std::vector<Request>(requests)](CtrlSimPlc& plc) {
            for (Request r : requests) ASSERT_TRUE(plc.Run(r).Done()) << Name(r);
        };
    };
    auto raise = [](std::vector<Request> requests, std::uint16_t number, bool moving) {
        return [requests, number, moving](CtrlSimPlc& plc) {
            for (Request r : requests) ASSERT_TRUE(plc.Run(r).Done()) << Name(r);
            if (moving) MoveAxis1(plc);
            plc.Controller().RaiseSystemError(number);
        };
    };
    sim::PaControlConfig longMalfunctionProgram = Script(1, 1, 1, 1'000'000);
    //                      START_ONL START_AUT STOP CANCEL RESET
    return {
        // CANCEL and RESET ERROR in home position put their bit out until the controller has read it
        // (DoneOnceRead, CancelAfterAPlcRestartWhileTheOldStartIsOnItsWayEndsInHomePosition).
        {"Home1", {}, run({}), 1, 0, W, W, N, W, W},
        {"Home9Class2", {}, raise({}, 150, false), 9, 150, N, N, N, W, W},
        {"Home9Cpu", {}, raise({}, 42, false), 9, 42, R, R, N, W, N},
        {"Automatic11", {}, run({kStartAutomatic}), 11, 0, N, D, W, W, N},
        {"AutomaticStopped15", {}, run({kStartAutomatic, kStop}), 15, 0, N, W, D, W, N},
        {"AutomaticMalfunction18", longMalfunctionProgram, raise({kStartAutomatic}, 600, false), 18, 600,
         N, N, W, W, N},
        {"AutomaticStoppedMalfunction19", {}, raise({kStartAutomatic}, 600, false), 19, 600, N, N, D, W, N},
        {"Online31", {}, run({kStartOnline}), 31, 0, D, N, W, W, N},
        {"OnlineStopped35", {}, run({kStartOnline, kStop}), 35, 0, W, N, D, W, N},
        {"OnlineMalfunction37", {}, raise({kStartOnline}, 600, true), 37, 600, N, N, W, W, N},
        {"OnlineStoppedMalfunction39", {}, raise({kStartOnline}, 600, false), 39, 600, N, N, D, W, N},
        {"OnlineCpuError39", {}, raise({kStartOnline}, 42, false), 39, 42, R, R, D, W, N},
    };
}

TEST_P(CtrlSim, RequestsThatDoNotApplyAreDecidedInTheEdgeScanWithNothingSent) {
    bool integerMode = false;
    for (const StateCase& state : States()) {
        SCOPED_TRACE(state.name);
        CtrlSimPlc plc(GetParam(), state.config);
        if (state.status == 37) SlowBraking(plc, 1.0F);  // 37 lasts while the axis brakes: 1000 s
        integerMode = !integerMode;
        plc.Ctrl()->INTEGERMODE.value = integerMode;
        plc.Settle();
        state.reach(plc);
        ASSERT_TRUE(plc.SettledAt(state.status, state.errorNumber));
        const struct {
            Request request;
            Outcome expected;
        } rows[] = {{kStartOnline, state.startOnline},
                    {kStartAutomatic, state.startAutomatic},
                    {kStop, state.stop},
                    {kCancel, state.cancel},
                    {kResetError, state.resetError}};
        for (const auto& row : rows) {
            if (row.expected == Outcome::kWaits) continue;
            SCOPED_TRACE(Name(row.request));
            plc.Begin(row.request);
            EXPECT_TRUE(plc.Ended()) << "decided in the edge scan";
            EXPECT_EQ(plc.WireControlWord(), plc.IdleWord()) << "nothing sent";
            const std::uint32_t id = row.expected == Outcome::kDoneAtOnce   ? 0
                                     : row.expected == Outcome::kNotAllowed ? kErrNotAllowed
                                                                            : kErrNotReady;
            EXPECT_EQ(plc.ErrorId(), id);
            EXPECT_EQ(plc.Done(), id == 0);
            // Execute held: the result holds, the wire stays idle (ScanRules in every scan), and the
            // controller neither sees nor does anything.
            plc.Wait();
            EXPECT_EQ(plc.ErrorId(), id);
            EXPECT_EQ(plc.ControlWordSeenByController(), plc.IdleWord());
            plc.Release();
            EXPECT_TRUE(plc.Shows(state.status, state.errorNumber));
        }
        EXPECT_EQ(plc.Controller().Counters().recognized - plc.Controller().Counters().Count(0x190B), 0u);
    }
}

// The controller ignores a start without the external stop input (5.2.1.3): the CTRL interface has no
// error channel, so the FB can only wait: 16#8009 in the first scan Timeout after the edge.
TEST_P(CtrlSim, StartOnlineWithoutTheExternalStopInputTimesOut) {
    CtrlSimPlc plc(GetParam());
    plc.Ctrl()->TIMEOUT.value = pac::ToIecTime(95ms);
    const int timeoutScans = plc.Window().TimeoutScans(95ms);
    plc.UnwireExternalStop();
    plc.Settle();
    for (int attempt = 0; attempt < 2; ++attempt) {
        SCOPED_TRACE(attempt == 0 ? "system parameter 4 = 0" : "input defined, no power");
        const FinalOutcome f = plc.Run(kStartOnline);
        EXPECT_TRUE(f.Error()) << f;
        EXPECT_EQ(f.ErrorId(), kErrRequestTimeout);
        EXPECT_EQ(f.Scans(), timeoutScans) << "Timeout 95 ms at a " << GetParam().plcMs << " ms PLC cycle";
        EXPECT_TRUE(plc.SettledAt(1));
        plc.WireExternalStop(false);
    }
    // With power, a new edge: the controller has seen the start bit fall (Settle above and Wait below).
    plc.WireExternalStop(true);
    plc.Wait();
    plc.Ctrl()->TIMEOUT.value = pac::ToIecTime(10s);
    EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 1));
    EXPECT_TRUE(plc.SettledAt(31));
}

// The CTRL status word shows no mode bit in manual operation either: a start there runs into Timeout.
TEST_P(CtrlSim, StartInManualOperationTimesOut) {
    CtrlSimPlc plc(GetParam());
    plc.Settle();
    plc.Controller().SetOperatingStatus(2);
    plc.Wait();
    plc.Ctrl()->TIMEOUT.value = pac::ToIecTime(50ms);
    for (Request r : {kStartOnline, kStartAutomatic}) {
        const FinalOutcome f = plc.Run(r);
        EXPECT_EQ(f.ErrorId(), kErrRequestTimeout) << Name(r) << ": " << f;
        EXPECT_EQ(f.Scans(), plc.Window().TimeoutScans(50ms)) << Name(r);
        EXPECT_EQ(plc.Controller().OperatingStatus(), 2);
    }
    EXPECT_TRUE(DecidedAtOnce(plc, kStop, kErrNotAllowed));
    plc.Ctrl()->TIMEOUT.value = pac::ToIecTime(10s);  // longer than the read of CANCEL's bit
    EXPECT_TRUE(DoneOnceRead(plc, kCancel));
}

// A stop that takes longer than Timeout: 16#8009 at the exact scan, the stop bit released; the
// controller still ends the stop it has begun.
TEST_P(CtrlSim, StopSlowerThanTimeoutIsRequestTimeout) {
    CtrlSimPlc plc(GetParam());
    SlowBraking(plc, 2000.0F);  // 500 ms
    plc.Settle();
    ASSERT_TRUE(plc.Run(kStartOnline).Done());
    MoveAxis1(plc);
    plc.Ctrl()->TIMEOUT.value = pac::ToIecTime(100ms);
    const FinalOutcome f = plc.Run(kStop);
    EXPECT_EQ(f.ErrorId(), kErrRequestTimeout) << f;
    EXPECT_EQ(f.Scans(), plc.Window().TimeoutScans(100ms));
    plc.Scan(plc.ScansFor(500ms));
    EXPECT_TRUE(plc.SettledAt(35));
    EXPECT_TRUE(DecidedAtOnce(plc, kStop, 0));
}

TEST_P(CtrlSim, TimeoutZeroWaitsWithoutLimit) {
    CtrlSimPlc plc(GetParam());
    SlowBraking(plc, 1000.0F);  // 1 s, longer than every other wait here
    plc.Settle();
    ASSERT_TRUE(plc.Run(kStartOnline).Done());
    MoveAxis1(plc);
    plc.Ctrl()->TIMEOUT.value = pac::ToIecTime(0s);
    const FinalOutcome f = plc.Run(kStop);
    EXPECT_TRUE(f.Done()) << f;
    EXPECT_GE(f.Scans(), plc.ScansFor(1s) - 1);
    EXPECT_TRUE(plc.SettledAt(35));
}

// ---------------------------------------------------------------------------------------------------
// A system error during a request: ErrorID = the system error number

TEST_P(CtrlSim, SystemErrorBeforeTheStartArrivesIsTheRequestsError) {
    for (Request r : {kStartOnline, kStartAutomatic}) {
        SCOPED_TRACE(Name(r));
        CtrlSimPlc plc(GetParam());
        plc.Settle();
        plc.Begin(r);
        plc.Controller().RaiseSystemError(310);  // noticed before the start bit is looked at: 1 -> 9
        const ScanWindow shown = plc.Window().Event(plc.Edge());
        const FinalOutcome f = plc.WaitEnd(1000);
        EXPECT_TRUE(f.Error() && shown.Contains(f.Scans())) << f << ", the protocol allows " << shown;
        EXPECT_EQ(f.ErrorId(), 310u);
        EXPECT_EQ(plc.WireControlWord(), plc.IdleWord()) << "the start bit falls with the error";
        plc.Release();
        EXPECT_TRUE(plc.SettledAt(9, 310)) << "the start was refused";
    }
}

TEST_P(CtrlSim, SystemErrorWhileAutomaticStartsIsTheRequestsError) {
    CtrlSimPlc plc(GetParam(), Script(20, 1, 1, 1));
    plc.Settle();
    plc.Begin(kStartAutomatic);
    ASSERT_GT(plc.ScanUntil([&] { return plc.Controller().OperatingStatus() == 10; }, 1000), 0);
    plc.Controller().RaiseSystemError(555);
    const nanoseconds raised = plc.Now();
    const FinalOutcome f = plc.WaitEnd(1000);
    const ScanWindow shown = plc.Window().Event(raised);
    EXPECT_TRUE(f.Error()) << f;
    EXPECT_EQ(f.ErrorId(), 555u);
    const int sinceRaised = static_cast<int>((plc.Now() - raised) / GetParam().PlcCycle());
    EXPECT_TRUE(shown.Contains(sinceRaised)) << sinceRaised << " scans after the raise, expected " << shown;
    plc.Release();
    EXPECT_TRUE(plc.SettledAt(19, 555)) << "10 -> 17 -> 18 -> 19";
}

// ONLINE started (30) lasts one controller cycle; the test can raise the error inside it only where a
// controller cycle is not shorter than a scan.
TEST_P(CtrlSim, SystemErrorWhileOnlineStartsIsTheRequestsError) {
    if (GetParam().pacMs < GetParam().plcMs) GTEST_SKIP() << "30 passes within one scan";
    CtrlSimPlc plc(GetParam());
    plc.Settle();
    plc.Begin(kStartOnline);
    ASSERT_GT(plc.ScanUntil([&] { return plc.Controller().OperatingStatus() == 30; }, 1000), 0);
    plc.Controller().RaiseSystemError(520);
    const nanoseconds raised = plc.Now();
    const FinalOutcome f = plc.WaitEnd(1000);
    EXPECT_TRUE(f.Error()) << f;
    EXPECT_EQ(f.ErrorId(), 520u);
    const int sinceRaised = static_cast<int>((plc.Now() - raised) / GetParam().PlcCycle());
    EXPECT_TRUE(plc.Window().Event(raised).Contains(sinceRaised)) << sinceRaised;
    plc.Release();
    EXPECT_TRUE(plc.SettledAt(39, 520)) << "30 -> 37 -> 39";
    EXPECT_TRUE(DoneInWindow(plc, kCancel, 0));
    EXPECT_TRUE(plc.SettledAt(1));
}

TEST_P(CtrlSim, SystemErrorWhileStoppingIsTheRequestsError) {
    {
        SCOPED_TRACE("ONLINE, axis braking (32)");
        CtrlSimPlc plc(GetParam());
        SlowBraking(plc, 2000.0F);
        plc.Settle();
        ASSERT_TRUE(plc.Run(kStartOnline).Done());
        MoveAxis1(plc);
        plc.Begin(kStop);
        ASSERT_GT(plc.ScanUntil([&] { return plc.Controller().OperatingStatus() == 32; }, 1000), 0);
        plc.Controller().RaiseSystemError(640);
        const nanoseconds raised = plc.Now();
        const FinalOutcome f = plc.WaitEnd(1000);
        EXPECT_EQ(f.ErrorId(), 640u) << f;
        const int sinceRaised = static_cast<int>((plc.Now() - raised) / GetParam().PlcCycle());
        EXPECT_TRUE(plc.Window().Event(raised).Contains(sinceRaised)) << sinceRaised;
        plc.Release();
        plc.Scan(plc.ScansFor(600ms));
        EXPECT_TRUE(plc.SettledAt(39, 640)) << "32 -> 37 -> 39 once the axis stands";
    }
    {
        SCOPED_TRACE("AUTOMATIC, stop program (13)");
        CtrlSimPlc plc(GetParam(), Script(1, 30, 1, 1));
        plc.Settle();
        ASSERT_TRUE(plc.Run(kStartAutomatic).Done());
        plc.Begin(kStop);
        ASSERT_GT(plc.ScanUntil([&] { return plc.Controller().OperatingStatus() == 13; }, 1000), 0);
        plc.Controller().RaiseSystemError(710);
        const FinalOutcome f = plc.WaitEnd(1000);
        EXPECT_EQ(f.ErrorId(), 710u) << f;
        plc.Release();
        EXPECT_TRUE(plc.SettledAt(19, 710)) << "13 -> 17 -> 18 -> 19";
    }
}

// ---------------------------------------------------------------------------------------------------
// Power cycle and link loss in the middle of a request

TEST_P(CtrlSim, PowerCycleDuringEachRequestIsConnectionLost) {
    struct Case {
        const char* name;
        std::vector<Request> before;
        std::uint16_t error;
        Request request;
    };
    const Case cases[] = {{"START_ONLINE", {}, 0, kStartOnline},
                          {"START_AUTOMATIC", {}, 0, kStartAutomatic},
                          {"STOP", {kStartOnline}, 0, kStop},
                          {"CANCEL", {kStartAutomatic}, 0, kCancel},
                          {"RESET_ERROR", {}, 150, kResetError}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        CtrlSimPlc plc(GetParam(), {}, 100ms);
        plc.Settle();
        for (Request r : c.before) ASSERT_TRUE(plc.Run(r).Done()) << Name(r);
        if (c.error != 0) plc.Controller().RaiseSystemError(c.error);
        plc.Wait();
        plc.Begin(c.request);
        ASSERT_TRUE(plc.Busy());
        plc.Controller().PowerCycle(plc.Now());
        const ScanWindow lost = plc.Window().ImmediateReply(plc.Now());
        const FinalOutcome f = plc.WaitEnd(1000);
        EXPECT_TRUE(f.Error() && lost.Contains(f.Scans())) << f << ", the protocol allows " << lost;
        EXPECT_EQ(f.ErrorId(), kErrConnectionLost);
        EXPECT_FALSE(plc.Ctrl()->READY.value);
        plc.Release();
        // While the controller boots, a request is refused at once; afterwards it works.
        EXPECT_TRUE(DecidedAtOnce(plc, kStartOnline, kErrNotReady));
        plc.Settle();
        EXPECT_TRUE(plc.Shows(1)) << "booted into home position, no error";
        EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 1));
    }
}

TEST_P(CtrlSim, PowerCycleWhileTheAxisBrakesForAStop) {
    CtrlSimPlc plc(GetParam(), {}, 100ms);
    SlowBraking(plc, 2000.0F);
    plc.Settle();
    ASSERT_TRUE(plc.Run(kStartOnline).Done());
    MoveAxis1(plc);
    plc.Begin(kStop);
    ASSERT_GT(plc.ScanUntil([&] { return plc.Controller().OperatingStatus() == 32; }, 1000), 0);
    plc.Scan(plc.ScansFor(100ms));
    ASSERT_TRUE(plc.Busy());
    plc.Controller().PowerCycle(plc.Now());
    const ScanWindow lost = plc.Window().ImmediateReply(plc.Now());
    const std::int64_t cycled = plc.ScanCount();
    const FinalOutcome f = plc.WaitEnd(1000);
    EXPECT_TRUE(f.Error() && lost.Contains(f.finalScan - cycled))
        << f << ", " << f.finalScan - cycled << " scans after the power cycle; the protocol allows " << lost;
    EXPECT_EQ(f.ErrorId(), kErrConnectionLost);
    plc.Release();
    plc.Settle();
    EXPECT_TRUE(plc.Shows(1));
}

// A pulled cable: the FB sees zeros (16#8004); the controller sees an all-zero master image, the
// emergency stop (4.2.5): ONLINE stopped with malfunction (39) but no system error, so START ONLINE
// resumes after the link is back.
TEST_P(CtrlSim, LinkLossDuringAStopThenResume) {
    CtrlSimPlc plc(GetParam());
    SlowBraking(plc, 2000.0F);
    plc.Settle();
    ASSERT_TRUE(plc.Run(kStartOnline).Done());
    MoveAxis1(plc);
    plc.Begin(kStop);
    plc.Bus().Disconnect(plc.Now());
    const FinalOutcome f = plc.WaitEnd(1000);
    EXPECT_EQ(f.ErrorId(), kErrConnectionLost) << f;
    plc.Release();
    plc.Scan(plc.ScansFor(100ms));
    plc.Bus().Reconnect(plc.Now());
    plc.Settle();
    EXPECT_TRUE(plc.Shows(39)) << "emergency stop";
    EXPECT_FALSE(plc.Controller().Axes().AnyMoving());
    EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 0));
    EXPECT_TRUE(plc.SettledAt(31));
}

// ---------------------------------------------------------------------------------------------------
// The first scan after a PLC restart

// A new PLC program: a fresh FB_PAC_Ctrl instance (with the other IntegerMode) takes over the CTRL module
// of a controller in ONLINE or AUTOMATIC. Its very first scan holds Stop and Cancel at 1: the controller
// stays where it is, scan after scan.
TEST_P(CtrlSim, FreshInstanceAfterAPlcRestartStopsAndCancelsNothing) {
    const struct {
        std::vector<Request> reach;
        int status;
    } cases[] = {{{kStartOnline}, 31}, {{kStartOnline, kStop}, 35}, {{kStartAutomatic}, 11},
                 {{kStartAutomatic, kStop}, 15}};
    for (const auto& c : cases) {
        SCOPED_TRACE("status " + std::to_string(c.status));
        CtrlSimPlc plc(GetParam());
        plc.Settle();
        for (Request r : c.reach) ASSERT_TRUE(plc.Run(r).Done()) << Name(r);
        ASSERT_TRUE(plc.SettledAt(c.status));
        plc.RestartPlcProgram();
        plc.Ctrl()->INTEGERMODE.value = TRUE;
        const int scans = std::max(plc.ScansFor(1s), 200);
        for (int i = 0; i < scans; ++i) {
            plc.Scan();
            ASSERT_EQ(plc.Controller().OperatingStatus(), c.status) << "scan " << i + 1 << " of the new program";
            ASSERT_EQ(plc.ControlWordSeenByController() & 0x7FFF, kIdleByte) << "scan " << i + 1;
        }
        EXPECT_TRUE(plc.Shows(c.status));
        EXPECT_FALSE(plc.Ctrl()->INTEGERMODEACTIVE.value) << "the format in force is the old one";
    }
}

// A start bit the instance before a PLC restart put out can still reach the controller after the new
// instance's CANCEL edge (the bus latency): the controller takes the start and shows 30 or 10, which show no
// mode bit like home position. The CANCEL must not be Done before the controller has read its own bit, which
// cancels any mode started meanwhile: when it is Done, the controller is in home position and stays there.
TEST_P(CtrlSim, CancelAfterAPlcRestartWhileTheOldStartIsOnItsWayEndsInHomePosition) {
    for (Request start : {kStartOnline, kStartAutomatic}) {
        CtrlSimPlc probe(GetParam());
        const int roundTrip = probe.Window().RoundTripScans();
        for (int restartAfter = 0; restartAfter <= roundTrip; ++restartAfter) {
            SCOPED_TRACE(std::string(Name(start)) + ", PLC restart " + std::to_string(restartAfter) + " scans after its edge");
            CtrlSimPlc plc(GetParam());
            plc.Settle();
            plc.Begin(start);
            plc.Scan(restartAfter);
            plc.RestartPlcProgram();
            const FinalOutcome f = plc.Run(kCancel);
            ASSERT_TRUE(f.Done()) << f;
            EXPECT_TRUE(plc.SettledAt(1)) << "CANCEL Done, so the controller stays in home position";
        }
    }
}

// Contrast: a new program that leaves the CTRL module at zero (the CMD module carries FB_PAC_Cmd's
// idle 190B, so the image is not all zero) cancels ONLINE to home position at the first cycle that
// reads it; one that zeroes the whole image is the emergency stop (39).
TEST_P(CtrlSim, ContrastANaiveMasterWithAnAllZeroControlWordCancels) {
    {
        SCOPED_TRACE("CTRL module zero");
        CtrlSimPlc plc(GetParam());
        plc.Settle();
        ASSERT_TRUE(plc.Run(kStartOnline).Done());
        plc.Wait();
        plc.ZeroCtrlModule(true);
        plc.Scan();
        const ScanWindow w = plc.Window().Request(plc.Now(), 0);
        const int scans = plc.ScanUntil([&] { return !plc.Ctrl()->ONLINEACTIVE.value; }, 1000);
        EXPECT_TRUE(w.Contains(scans)) << scans << " scans, the protocol allows " << w;
        EXPECT_EQ(plc.Controller().OperatingStatus(), 1) << "cancelled";
    }
    {
        SCOPED_TRACE("whole image zero");
        CtrlSimPlc plc(GetParam());
        plc.Settle();
        ASSERT_TRUE(plc.Run(kStartOnline).Done());
        plc.Wait();
        plc.ZeroCtrlModule(true);
        plc.ZeroCmdModule(true);
        plc.Wait();
        EXPECT_EQ(plc.Controller().OperatingStatus(), 39) << "emergency stop, not a cancel";
        EXPECT_TRUE(plc.Controller().EmergencyStopActive());
    }
}

// The first start after the controller came up: it takes the first control word it reads as the
// reference for the edges (docs/simulator.md), so a start bit in that very word is not seen. Execute
// rising in the first scan that shows Ready works only where a controller cycle read one of the FB's
// idle words before the start bit arrived; elsewhere the FB waits until Timeout (16#8009, never stuck
// Busy). Waiting a controller cycle plus the bus both ways after Ready always works (every other test).
// A start raised as soon as Ready shows may be in the first control word the controller reads after its
// boot (where its cycle is longer than the PLC's). The simulator counts the bits as idle before that
// word, so the start is an edge and is served on every timing (docs/simulator.md).
TEST_P(CtrlSim, StartInTheFirstScansAfterPowerOnIsServed) {
    CtrlSimPlc plc(GetParam());
    plc.Ctrl()->TIMEOUT.value = pac::ToIecTime(200ms);
    ASSERT_GT(plc.ScanUntil([&] { return plc.Ctrl()->READY.value != 0; }, 1000), 0);
    plc.Begin(kStartOnline);
    const FinalOutcome f = plc.WaitEnd(plc.ScansFor(1s));
    EXPECT_TRUE(f.Done() && plc.DoneWindow(1).Contains(f.Scans())) << f << ", allowed " << plc.DoneWindow(1);
    plc.Release();
    plc.Wait();
    EXPECT_TRUE(plc.SettledAt(31));
}

// ---------------------------------------------------------------------------------------------------
// Integer format (2.5.3)

TEST_P(CtrlSim, IntegerModeIsTakenOverOnlyWhenEnteringFromHome) {
    CtrlSimPlc plc(GetParam());
    plc.Ctrl()->INTEGERMODE.value = TRUE;
    plc.Settle();
    EXPECT_FALSE(plc.Ctrl()->INTEGERMODEACTIVE.value) << "float after power-on";
    EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 1));
    EXPECT_TRUE(plc.Ctrl()->INTEGERMODEACTIVE.value);
    EXPECT_TRUE(plc.Controller().IntegerFormat());

    plc.Ctrl()->INTEGERMODE.value = FALSE;  // while ONLINE: no effect until the next entry from home
    plc.Scan(plc.ScansFor(200ms));
    EXPECT_TRUE(plc.Ctrl()->INTEGERMODEACTIVE.value);
    EXPECT_TRUE(DoneInWindow(plc, kStop, 0));
    EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 0));
    EXPECT_TRUE(plc.Ctrl()->INTEGERMODEACTIVE.value) << "a resume does not pass 30";
    EXPECT_TRUE(DoneInWindow(plc, kCancel, 0));
    EXPECT_TRUE(plc.SettledAt(1));
    EXPECT_TRUE(plc.Ctrl()->INTEGERMODEACTIVE.value) << "unchanged on returning home";
    EXPECT_TRUE(DoneInWindow(plc, kStartOnline, 1));
    EXPECT_FALSE(plc.Ctrl()->INTEGERMODEACTIVE.value) << "taken over at the next entry";

    EXPECT_TRUE(DoneInWindow(plc, kCancel, 0));
    plc.Ctrl()->INTEGERMODE.value = TRUE;
    EXPECT_TRUE(DoneInWindow(plc, kStartAutomatic, 1));
    EXPECT_TRUE(plc.Ctrl()->INTEGERMODEACTIVE.value);
    plc.Ctrl()->INTEGERMODE.value = FALSE;
    EXPECT_TRUE(DoneInWindow(plc, kStop, 1));
    EXPECT_TRUE(DoneInWindow(plc, kStartAutomatic, 0));
    EXPECT_TRUE(plc.SettledAt(11));
    EXPECT_TRUE(plc.Ctrl()->INTEGERMODEACTIVE.value);
}

std::vector<CtrlSimCase> CtrlSimCases(sim::StoppedModeBits bits) {
    std::vector<CtrlSimCase> cases;
    for (const BusTiming& t : pac::test::StandardAndJitteredBusTimings()) cases.push_back(CtrlSimCase{t, bits});
    return cases;
}

std::string CtrlSimCaseName(const ::testing::TestParamInfo<CtrlSimCase>& info) {
    return pac::test::BusTimingName(::testing::TestParamInfo<BusTiming>(info.param, info.index));
}

INSTANTIATE_TEST_SUITE_P(BusTimings, CtrlSim, ::testing::ValuesIn(CtrlSimCases(sim::StoppedModeBits::kStoppedAlone)),
                         CtrlSimCaseName);
INSTANTIATE_TEST_SUITE_P(StoppedShowsActive, CtrlSim,
                         ::testing::ValuesIn(CtrlSimCases(sim::StoppedModeBits::kStoppedAndActive)),
                         CtrlSimCaseName);

}  // namespace
}  // namespace test_fb_pac_ctrl_sim
