// FB_PAC_Ctrl scan by scan: against hand-written CTRL status images (manual 2.5.2) for the exact scan of
// every bit and output, and against a small fake controller that answers the control word per the
// project's CTRL decisions, for whole mode sequences. Every scan checks the control word rules (never all
// zero, the low-active bits at 1 and the start bits at 0 outside a request, one request bit at a time)
// and runs the PLCopen checker (plcopen_checker.hpp).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <deque>
#include <string>

#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/scan_test.hpp"
#include "pac/st_program.hpp"
#include "plcopen_checker.hpp"
#include "plcopen_pins.hpp"
#include "run_to_final.hpp"

namespace test_fb_pac_ctrl {  // apart from the names of the other sources in its unity batch
namespace {

using pac::test::OutputsOf;

using Image = std::array<std::uint8_t, 8>;

const pac::test::GvlConstants kGvl;
const std::uint32_t kErrNotReady = kGvl["PAC_LIB_ERR_NOT_READY"];
const std::uint32_t kErrConnectionLost = kGvl["PAC_LIB_ERR_CONNECTION_LOST"];
const std::uint32_t kErrNotAllowed = kGvl["PAC_LIB_ERR_NOT_ALLOWED"];
const std::uint32_t kErrRequestTimeout = kGvl["PAC_LIB_ERR_REQUEST_TIMEOUT"];
const std::uint32_t kErrNoCommand = kGvl["PAC_LIB_ERR_NO_COMMAND"];

// Status word bits, PA-CONTROL -> master (2.5.2).
constexpr std::uint16_t kReady = 0x0001;
constexpr std::uint16_t kBatteryOk = 0x0002;
constexpr std::uint16_t kSystemError = 0x0004;
constexpr std::uint16_t kAutomaticActive = 0x0100;
constexpr std::uint16_t kAutomaticStopped = 0x0200;
constexpr std::uint16_t kOnlineActive = 0x0400;
constexpr std::uint16_t kOnlineStopped = 0x0800;
constexpr std::uint16_t kIntegerFormat = 0x8000;
constexpr std::uint16_t kBooted = kReady | kBatteryOk;  // home position, no error

// Low byte of the control word, master -> PA-CONTROL (2.5.1), as the FB must write it.
constexpr std::uint8_t kIdle = 0x07;          // Error reset, Stop, Cancel inactive (1); no start
constexpr std::uint8_t kStartOnline = 0x17;   // bit 4
constexpr std::uint8_t kStartAutomatic = 0x0F;  // bit 3
constexpr std::uint8_t kStop = 0x05;          // bit 1 low
constexpr std::uint8_t kCancel = 0x03;        // bit 2 low
constexpr std::uint8_t kResetError = 0x06;    // bit 0 low

constexpr auto kNone = E_PAC_CTRLREQUEST__PAC_REQ_NONE;
constexpr auto kReqStartOnline = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
constexpr auto kReqStartAutomatic = E_PAC_CTRLREQUEST__PAC_REQ_START_AUTOMATIC;
constexpr auto kReqStop = E_PAC_CTRLREQUEST__PAC_REQ_STOP;
constexpr auto kReqCancel = E_PAC_CTRLREQUEST__PAC_REQ_CANCEL;
constexpr auto kReqResetError = E_PAC_CTRLREQUEST__PAC_REQ_RESET_ERROR;

const char* Name(E_PAC_CTRLREQUEST r) {
    switch (r) {
        case E_PAC_CTRLREQUEST__PAC_REQ_NONE: return "NONE";
        case E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE: return "START_ONLINE";
        case E_PAC_CTRLREQUEST__PAC_REQ_START_AUTOMATIC: return "START_AUTOMATIC";
        case E_PAC_CTRLREQUEST__PAC_REQ_STOP: return "STOP";
        case E_PAC_CTRLREQUEST__PAC_REQ_CANCEL: return "CANCEL";
        case E_PAC_CTRLREQUEST__PAC_REQ_RESET_ERROR: return "RESET_ERROR";
    }
    return "?";
}

// The CTRL module the PA-CONTROL sends: status word (word 0), system error number (word 2), big-endian.
Image StatusImage(std::uint16_t word, std::uint16_t errorNumber = 0) {
    return {static_cast<std::uint8_t>(word >> 8), static_cast<std::uint8_t>(word), 0, 0,
            static_cast<std::uint8_t>(errorNumber >> 8), static_cast<std::uint8_t>(errorNumber), 0, 0};
}

// A simulated PA-CONTROL's CTRL side, reduced to what FB_PAC_Ctrl needs (docs/fb/FB_PAC_Ctrl.md, the
// project's CTRL decisions): Stop and Cancel act as levels while 0, the start bits on their rising edge
// while Stop and Cancel are 1, Error reset on its falling edge. It reacts to the control word the PLC wrote
// delayScans scans earlier and passes one transitional status per scan (30 -> 31, 32 -> 35, ...).
class FakeController {
public:
    explicit FakeController(int delayScans, int opStatus = 1) : delay_(delayScans), status_(opStatus) {}

    void SetStandstillCycles(int n) { standstillCycles_ = n; }

    // A system error as the controller raises it in its current mode (ONLINE -> 37, AUTOMATIC -> 17).
    void RaiseSystemError(std::uint16_t number) {
        error_ = number;
        if (status_ == 1) status_ = 9;
        if (IsOnlineActive(status_)) status_ = 37;
        if (status_ == 35) status_ = 39;
        if (IsAutomaticActive(status_)) status_ = 17;
        if (status_ == 15) status_ = 19;
    }

    // One controller cycle, after the PLC scan that wrote toPac.
    void Step(const Image& toPac) {
        line_.push_back(static_cast<std::uint16_t>((toPac[0] << 8) | toPac[1]));
        Progress();
        if (static_cast<int>(line_.size()) > delay_) {
            Apply(line_.front());
            line_.pop_front();
        }
    }

    Image Reply() const {
        if (status_ == 0) return Image{};
        std::uint16_t word = kBatteryOk;
        if (!(error_ >= 1 && error_ <= 99)) word |= kReady;
        if (error_ != 0) word |= kSystemError;
        if (IsAutomaticActive(status_)) word |= kAutomaticActive;
        if (status_ == 15 || status_ == 19) word |= kAutomaticStopped;
        if (IsOnlineActive(status_)) word |= kOnlineActive;
        if (status_ == 35 || status_ == 39) word |= kOnlineStopped;
        if (integer_) word |= kIntegerFormat;
        return StatusImage(word, error_);
    }

    int OpStatus() const { return status_; }
    bool IntegerFormat() const { return integer_; }
    std::uint16_t ErrorNumber() const { return error_; }

private:
    static bool IsAutomaticActive(int s) {
        return s == 11 || s == 12 || s == 13 || s == 16 || s == 17 || s == 18;
    }
    static bool IsOnlineActive(int s) { return s == 31 || s == 32 || s == 37; }
    static bool InMode(int s) { return s >= 10 && s <= 39 && s != 20; }

    void Progress() {
        switch (status_) {
            case 30: status_ = 31; break;
            case 10: case 16: status_ = 11; break;
            case 12: status_ = 13; break;
            case 13: status_ = 15; break;
            case 17: status_ = 18; break;
            case 18: status_ = 19; break;
            case 37: status_ = 39; break;
            case 32:
                if (--standstill_ <= 0) status_ = 35;
                break;
            default: break;
        }
    }

    void Apply(std::uint16_t control) {
        const bool stopLow = (control & 0x02) == 0;
        const bool cancelLow = (control & 0x04) == 0;
        const bool onlineEdge = (control & 0x10) != 0 && (previous_ & 0x10) == 0;
        const bool automaticEdge = (control & 0x08) != 0 && (previous_ & 0x08) == 0;
        const bool resetFalls = (control & 0x01) == 0 && (previous_ & 0x01) != 0;
        previous_ = control;
        if (cancelLow) {
            if (InMode(status_)) {
                if (error_ >= 500) error_ = 0;  // class 3 is cleared on returning home
                status_ = error_ != 0 ? 9 : 1;
            }
        } else if (stopLow) {
            if (status_ == 31) {
                status_ = 32;
                standstill_ = standstillCycles_;
            }
            if (status_ == 11) status_ = 12;
        } else if (onlineEdge) {
            Start(control, 30, 35, 39, 31);
        } else if (automaticEdge) {
            Start(control, 10, 15, 19, 16);
        }
        if (resetFalls && (status_ == 1 || status_ == 9) && error_ >= 100 && error_ <= 499) {
            error_ = 0;
            status_ = 1;
        }
    }

    // From home position to "started", taking the integer format over (2.5.3); or a resume after a stop.
    void Start(std::uint16_t control, int started, int stopped, int stoppedWithMalfunction, int resumed) {
        if (error_ != 0) return;
        if (status_ == 1) {
            status_ = started;
            integer_ = (control & 0x8000) != 0;
        } else if (status_ == stopped || status_ == stoppedWithMalfunction) {
            status_ = resumed;
        }
    }

    int delay_;
    int status_;
    std::uint16_t error_ = 0;
    bool integer_ = false;
    std::uint16_t previous_ = 0x0007;
    int standstillCycles_ = 1;
    int standstill_ = 0;
    std::deque<std::uint16_t> line_;
};

class FbPacCtrl : public pac::ScanTest {
protected:
    FbPacCtrl() {
        fromPac_ = StatusImage(kBooted);
        task_.AddProgram([this] {
            for (int i = 0; i < 8; ++i) {
                ctrl_->FROMPAC.value.table[i] = fromPac_[i];
                ctrl_->TOPAC.value.table[i] = toPac_[i];
            }
            ctrl_();
            for (int i = 0; i < 8; ++i) toPac_[i] = ctrl_->TOPAC.value.table[i];
            rules_.Check(task_.ScanCount(), ctrl_, pac::test::RequestBusyBoundOf(ctrl_, kDefaultCycleTime));
            CheckControlWord();
        });
    }

    void Execute(E_PAC_CTRLREQUEST request, bool execute = true) {
        ctrl_->REQUEST.value = request;
        ctrl_->EXECUTE.value = execute;
    }
    void Release() { ctrl_->EXECUTE.value = FALSE; }
    void SetTimeout(int ms) {
        ctrl_->TIMEOUT.value.tv_sec = ms / 1000;
        ctrl_->TIMEOUT.value.tv_nsec = (ms % 1000) * 1'000'000;
    }

    std::uint8_t Control() const { return toPac_[1]; }
    bool Done() const { return OutputsOf(ctrl_).done; }
    bool Busy() const { return OutputsOf(ctrl_).busy; }
    bool Error() const { return OutputsOf(ctrl_).error; }
    std::uint32_t ErrorId() const { return OutputsOf(ctrl_).errorId; }

    // Manual 2.5.1 and the CTRL decisions: only bit 15 and bits 0..4 are ever set; outside a request the
    // low-active bits are 1 and the start bits 0; during one, exactly one bit differs from that.
    void CheckControlWord() {
        const std::string where = " in scan " + std::to_string(task_.ScanCount());
        EXPECT_FALSE(toPac_[0] == 0 && toPac_[1] == 0) << "all-zero control word" << where;
        EXPECT_EQ(toPac_[0], ctrl_->INTEGERMODE.value ? 0x80 : 0x00) << "bit 15 follows IntegerMode" << where;
        for (int i = 2; i < 8; ++i) EXPECT_EQ(toPac_[i], 0) << "word " << i / 2 << " is not used" << where;
        if (!Busy()) {
            EXPECT_EQ(Control(), kIdle) << "a request bit outside a request" << where;
        } else {
            const std::uint8_t c = Control();
            EXPECT_TRUE(c == kStartOnline || c == kStartAutomatic || c == kStop || c == kCancel || c == kResetError)
                << "control byte 0x" << std::hex << int{c} << std::dec << where;
        }
    }

    pac::FbInstance<FB_PAC_CTRL> ctrl_ = PAC_FB(FB_PAC_CTRL);
    pac::test::PlcOpenChecker rules_{"FB_PAC_Ctrl"};
    Image fromPac_{};
    Image toPac_{};
};

// ---------------------------------------------------------------------------------------------------
// Control word without a request: the first scan and every scan after

TEST_F(FbPacCtrl, FirstScanOfAFreshInstanceWritesTheIdleControlWordEvenWithoutALink) {
    fromPac_ = Image{};  // PLC restart: the bus has not delivered the controller's status yet
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0x00, kIdle, 0, 0, 0, 0, 0, 0}));
    EXPECT_FALSE(Busy() || Done() || Error());
}

TEST_F(FbPacCtrl, FirstScanOverwritesAStaleOutputImageWhole) {
    toPac_ = Image{0xFF, 0xF8, 1, 2, 3, 4, 5, 6};  // Stop, Cancel, Error reset low, both starts high
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0x00, kIdle, 0, 0, 0, 0, 0, 0}));
}

TEST_F(FbPacCtrl, FirstScanWithIntegerModeSetsBit15Only) {
    ctrl_->INTEGERMODE.value = TRUE;
    Cycle(1);
    EXPECT_EQ(toPac_, (Image{0x80, kIdle, 0, 0, 0, 0, 0, 0}));
}

TEST_F(FbPacCtrl, IdleControlWordHoldsInEveryStatusWithoutExecute) {
    const std::uint16_t words[] = {0, kBooted, kBooted | kOnlineActive, kBooted | kAutomaticActive,
                                   kBooted | kSystemError | kOnlineStopped, 0xFFFF};
    for (std::uint16_t w : words) {
        fromPac_ = StatusImage(w, 600);
        Cycle(3);
        EXPECT_EQ(Control(), kIdle) << "status 0x" << std::hex << w;
    }
    EXPECT_FALSE(Busy() || Done() || Error());
}

TEST_F(FbPacCtrl, IntegerModeDrivesBit15InEveryScanAlsoDuringARequest) {
    const bool pattern[] = {false, true, true, false, true, false};
    for (bool mode : pattern) {
        ctrl_->INTEGERMODE.value = mode;
        Cycle(1);
        EXPECT_EQ(toPac_[0], mode ? 0x80 : 0x00);
        EXPECT_EQ(Control(), kIdle);
    }
    Execute(kReqStartOnline);
    for (bool mode : pattern) {
        ctrl_->INTEGERMODE.value = mode;
        Cycle(1);
        EXPECT_EQ(toPac_[0], mode ? 0x80 : 0x00);
        EXPECT_EQ(Control(), kStartOnline);
    }
}

TEST_F(FbPacCtrl, IntegerModeActiveShowsStatusBit15NotTheInput) {
    ctrl_->INTEGERMODE.value = TRUE;
    Cycle(1);
    EXPECT_FALSE(ctrl_->INTEGERMODEACTIVE.value) << "the controller has not taken the format over";
    ctrl_->INTEGERMODE.value = FALSE;
    fromPac_ = StatusImage(kBooted | kOnlineActive | kIntegerFormat);
    Cycle(1);
    EXPECT_TRUE(ctrl_->INTEGERMODEACTIVE.value) << "the format in force stays until the next start";
}

// ---------------------------------------------------------------------------------------------------
// Status decoding, every scan

TEST_F(FbPacCtrl, EveryStatusBitReachesItsOwnOutputAndNoOther) {
    struct Row {
        std::uint16_t bit;
        const char* pin;
    };
    const Row rows[] = {{kReady, "Ready"},
                        {kBatteryOk, "BatteryOk"},
                        {kSystemError, "SystemError"},
                        {kAutomaticActive, "AutomaticActive"},
                        {kAutomaticStopped, "AutomaticStopped"},
                        {kOnlineActive, "OnlineActive"},
                        {kOnlineStopped, "OnlineStopped"},
                        {kIntegerFormat, "IntegerModeActive"}};
    auto outputs = [this] {
        return std::array<bool, 8>{ctrl_->READY.value != 0,           ctrl_->BATTERYOK.value != 0,
                                   ctrl_->SYSTEMERROR.value != 0,     ctrl_->AUTOMATICACTIVE.value != 0,
                                   ctrl_->AUTOMATICSTOPPED.value != 0, ctrl_->ONLINEACTIVE.value != 0,
                                   ctrl_->ONLINESTOPPED.value != 0,   ctrl_->INTEGERMODEACTIVE.value != 0};
    };
    for (int k = 0; k < 8; ++k) {
        fromPac_ = StatusImage(rows[k].bit);
        Cycle(1);
        const auto out = outputs();
        for (int j = 0; j < 8; ++j) EXPECT_EQ(out[j], j == k) << rows[j].pin << " with only " << rows[k].pin << " set";
    }
    // The bits the manual leaves unassigned (3..7, 12..14) reach no output.
    fromPac_ = StatusImage(0x70F8);
    Cycle(1);
    for (bool b : outputs()) EXPECT_FALSE(b);
}

TEST_F(FbPacCtrl, SystemErrorNumberIsWord2BigEndianAndTheUnusedWordsAreIgnored) {
    fromPac_ = Image{0x00, 0x07, 0xAB, 0xCD, 0x02, 0x5D, 0xEF, 0x12};
    Cycle(1);
    EXPECT_EQ(ctrl_->SYSTEMERRORNUMBER.value, 0x025D);  // 605
    EXPECT_TRUE(ctrl_->SYSTEMERROR.value);
    EXPECT_TRUE(ctrl_->READY.value);
    EXPECT_FALSE(ctrl_->ONLINEACTIVE.value || ctrl_->AUTOMATICACTIVE.value);
    fromPac_ = StatusImage(kBooted, 0);
    Cycle(1);
    EXPECT_EQ(ctrl_->SYSTEMERRORNUMBER.value, 0);
}

TEST_F(FbPacCtrl, StatusFollowsEveryScanWhileARequestWaits) {
    Execute(kReqStartOnline);
    Cycle(1);
    ASSERT_TRUE(Busy());
    fromPac_ = StatusImage(kBatteryOk | kReady | kIntegerFormat, 0);
    Cycle(1);
    EXPECT_TRUE(ctrl_->INTEGERMODEACTIVE.value);
    fromPac_ = StatusImage(kReady, 0);
    Cycle(1);
    EXPECT_FALSE(ctrl_->BATTERYOK.value);
    EXPECT_FALSE(ctrl_->INTEGERMODEACTIVE.value);
    EXPECT_TRUE(Busy());
}

// ---------------------------------------------------------------------------------------------------
// Each request's bit: out in the edge scan, held until the status word shows the result, released in
// the scan that sees it, together with Done.

struct BitCase {
    const char* name;
    E_PAC_CTRLREQUEST request;
    std::uint16_t fromWord;
    std::uint16_t fromError;
    std::uint8_t control;
    std::uint16_t onTheWayWord;  // what the status shows before the result (transitional or unchanged)
    std::uint16_t onTheWayError;
    std::uint16_t resultWord;
    std::uint16_t resultError;
};

class FbPacCtrlBit : public FbPacCtrl, public ::testing::WithParamInterface<BitCase> {};

// CANCEL and RESET ERROR are Done on no mode bit only once their bit has been out for 70 ms (the bus both ways
// and the controller's cycle in home position) and 7 more scans: at a 1 ms scan, 77 scans after the edge.
constexpr int kReadScans = 77;
bool ShownAsHome(E_PAC_CTRLREQUEST r) { return r == kReqCancel || r == kReqResetError; }

TEST_P(FbPacCtrlBit, AssertedFromTheEdgeUntilTheResultThenReleasedWithDone) {
    const BitCase& c = GetParam();
    fromPac_ = StatusImage(c.fromWord, c.fromError);
    Cycle(2);
    ASSERT_EQ(Control(), kIdle);
    Execute(c.request);
    Cycle(1);
    EXPECT_EQ(Control(), c.control) << "the bit goes out in the edge scan";
    EXPECT_TRUE(Busy());
    Cycle(3);
    EXPECT_EQ(Control(), c.control) << "held while the status is unchanged";
    fromPac_ = StatusImage(c.onTheWayWord, c.onTheWayError);
    Cycle(2);
    EXPECT_EQ(Control(), c.control) << "held on the way";
    EXPECT_TRUE(Busy());
    fromPac_ = StatusImage(c.resultWord, c.resultError);
    Cycle(1);
    if (ShownAsHome(c.request)) {
        // No mode bit is also a start's 10 or 30: Done once the bit was read, kReadScans after the edge.
        EXPECT_FALSE(Done()) << "not before the controller has read the bit";
        EXPECT_EQ(Control(), c.control);
        Cycle(kReadScans - 7);
        EXPECT_FALSE(Done());
        Cycle(1);
    }
    EXPECT_TRUE(Done()) << "Done in the first scan that shows the result";
    EXPECT_EQ(Control(), kIdle) << "released in that same scan";
    Cycle(3);
    EXPECT_TRUE(Done()) << "held while Execute stays TRUE";
    EXPECT_EQ(Control(), kIdle);
    Release();
    Cycle(1);
    EXPECT_FALSE(Done());
    EXPECT_EQ(ErrorId(), 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Requests, FbPacCtrlBit,
    ::testing::Values(
        // home 1 -> 30 (no mode bit) -> 31
        BitCase{"StartOnline", kReqStartOnline, kBooted, 0, kStartOnline, kBooted, 0, kBooted | kOnlineActive, 0},
        // 35 -> 31 (resume)
        BitCase{"StartOnlineResume", kReqStartOnline, kBooted | kOnlineStopped, 0, kStartOnline,
                kBooted | kOnlineStopped, 0, kBooted | kOnlineActive, 0},
        // home 1 -> 10 -> 11
        BitCase{"StartAutomatic", kReqStartAutomatic, kBooted, 0, kStartAutomatic, kBooted, 0,
                kBooted | kAutomaticActive, 0},
        // 15 -> 16 (shows AUTOMATIC active)
        BitCase{"StartAutomaticResume", kReqStartAutomatic, kBooted | kAutomaticStopped, 0, kStartAutomatic,
                kBooted | kAutomaticStopped, 0, kBooted | kAutomaticActive, 0},
        // 31 -> 32 (axes braking, still ONLINE active) -> 35
        BitCase{"StopOnline", kReqStop, kBooted | kOnlineActive, 0, kStop, kBooted | kOnlineActive, 0,
                kBooted | kOnlineStopped, 0},
        // 11 -> 12 -> 13 (stop program) -> 15
        BitCase{"StopAutomatic", kReqStop, kBooted | kAutomaticActive, 0, kStop, kBooted | kAutomaticActive, 0,
                kBooted | kAutomaticStopped, 0},
        BitCase{"CancelOnline", kReqCancel, kBooted | kOnlineActive, 0, kCancel, kBooted | kOnlineActive, 0,
                kBooted, 0},
        BitCase{"CancelAutomaticStoppedWithMalfunction", kReqCancel, kBooted | kSystemError | kAutomaticStopped,
                612, kCancel, kBooted | kSystemError | kAutomaticStopped, 612, kBooted, 0},
        // 9 -> 1: a class 2 error is cleared
        BitCase{"ResetError", kReqResetError, kBooted | kSystemError, 150, kResetError, kBooted | kSystemError, 150,
                kBooted, 0}),
    [](const ::testing::TestParamInfo<BitCase>& info) { return std::string(info.param.name); });

// ---------------------------------------------------------------------------------------------------
// Every request in every state: waits (bit out), Done at once, 16#8008 or 16#8003, decided in the edge scan

enum class Outcome { kWaits, kDoneAtOnce, kNotAllowed, kNotReady };

struct StateRow {
    const char* name;
    std::uint16_t word;
    std::uint16_t errorNumber;
    Outcome startOnline, startAutomatic, stop, cancel, resetError;
};

class FbPacCtrlState : public FbPacCtrl, public ::testing::WithParamInterface<StateRow> {};

TEST_P(FbPacCtrlState, EachRequestIsDecidedInTheEdgeScan) {
    const StateRow& row = GetParam();
    const struct {
        E_PAC_CTRLREQUEST request;
        Outcome expected;
        std::uint8_t bit;
    } requests[] = {{kReqStartOnline, row.startOnline, kStartOnline},
                    {kReqStartAutomatic, row.startAutomatic, kStartAutomatic},
                    {kReqStop, row.stop, kStop},
                    {kReqCancel, row.cancel, kCancel},
                    {kReqResetError, row.resetError, kResetError}};
    for (const auto& r : requests) {
        SCOPED_TRACE(Name(r.request));
        ctrl_ = PAC_FB(FB_PAC_CTRL);
        rules_.Restart();
        toPac_ = Image{};
        fromPac_ = StatusImage(row.word, row.errorNumber);
        Cycle(1);
        Execute(r.request);
        Cycle(1);
        switch (r.expected) {
            case Outcome::kWaits:
                EXPECT_TRUE(Busy());
                EXPECT_EQ(Control(), r.bit);
                break;
            case Outcome::kDoneAtOnce:
                EXPECT_TRUE(Done());
                EXPECT_EQ(Control(), kIdle) << "nothing to do: no bit";
                break;
            case Outcome::kNotAllowed:
                EXPECT_TRUE(Error());
                EXPECT_EQ(ErrorId(), kErrNotAllowed);
                EXPECT_EQ(Control(), kIdle) << "refused without touching the bits";
                break;
            case Outcome::kNotReady:
                EXPECT_TRUE(Error());
                EXPECT_EQ(ErrorId(), kErrNotReady);
                EXPECT_EQ(Control(), kIdle);
                break;
        }
        Cycle(2);  // the decision holds while Execute stays TRUE
        EXPECT_EQ(Busy(), r.expected == Outcome::kWaits);
        EXPECT_EQ(Done(), r.expected == Outcome::kDoneAtOnce);
    }
}

constexpr Outcome W = Outcome::kWaits;
constexpr Outcome D = Outcome::kDoneAtOnce;
constexpr Outcome N = Outcome::kNotAllowed;
constexpr Outcome R = Outcome::kNotReady;

// CANCEL and RESET ERROR where no mode bit shows put their bit out until the controller has read it: no mode
// bit is also a start's 10 or 30 (FbPacCtrl.CancelAndResetErrorInHomePositionAreDoneOnceTheirBitWasRead).
//                                                                       START_ONL START_AUT STOP CANCEL RESET
INSTANTIATE_TEST_SUITE_P(
    Statuses, FbPacCtrlState,
    ::testing::Values(
        StateRow{"Home1", kBooted, 0, W, W, N, W, W},
        StateRow{"Home9Class2Error", kBooted | kSystemError, 150, N, N, N, W, W},
        StateRow{"Home9CpuError", kBatteryOk | kSystemError, 5, R, R, N, W, N},
        StateRow{"LinkLost", 0, 0, R, R, R, R, R},
        StateRow{"BatteryLowHome1", kReady, 0, W, W, N, W, W},
        StateRow{"Started10Or30LooksLikeHome", kBooted, 0, W, W, N, W, W},
        StateRow{"Automatic11", kBooted | kAutomaticActive, 0, N, D, W, W, N},
        StateRow{"AutomaticStopped15", kBooted | kAutomaticStopped, 0, N, W, D, W, N},
        StateRow{"AutomaticMalfunction17", kBooted | kSystemError | kAutomaticActive, 600, N, N, W, W, N},
        StateRow{"AutomaticStoppedMalfunction19", kBooted | kSystemError | kAutomaticStopped, 600, N, N, D, W, N},
        StateRow{"Online31", kBooted | kOnlineActive, 0, D, N, W, W, N},
        StateRow{"Online31Integer", kBooted | kOnlineActive | kIntegerFormat, 0, D, N, W, W, N},
        StateRow{"OnlineStopped35", kBooted | kOnlineStopped, 0, W, N, D, W, N},
        StateRow{"OnlineMalfunction37", kBooted | kSystemError | kOnlineActive, 600, N, N, W, W, N},
        StateRow{"OnlineStoppedMalfunction39", kBooted | kSystemError | kOnlineStopped, 600, N, N, D, W, N}),
    [](const ::testing::TestParamInfo<StateRow>& info) { return std::string(info.param.name); });

TEST_F(FbPacCtrl, ExecuteWithoutARequestIsNoCommandEvenWithoutALink) {
    for (std::uint16_t word : {kBooted, std::uint16_t{0}}) {
        ctrl_ = PAC_FB(FB_PAC_CTRL);
        rules_.Restart();
        fromPac_ = StatusImage(word);
        Execute(kNone);
        Cycle(1);
        EXPECT_TRUE(Error());
        EXPECT_EQ(ErrorId(), kErrNoCommand);
        EXPECT_EQ(Control(), kIdle);
    }
}

// ---------------------------------------------------------------------------------------------------
// What ends a waiting request other than its result

TEST_F(FbPacCtrl, SystemErrorDuringStartOnlineIsTheErrorWithTheNumberUnchanged) {
    Execute(kReqStartOnline);
    Cycle(1);
    Cycle(1);  // 30: no mode bit yet
    fromPac_ = StatusImage(kBooted | kSystemError | kOnlineActive, 612);  // 37
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(ErrorId(), 612u);
    EXPECT_EQ(ctrl_->ERRORSOURCE.value, E_PAC_ERRORSOURCE__PAC_ERRSRC_SYSTEM) << "612 is E612, not 6.5's 612";
    EXPECT_EQ(Control(), kIdle) << "the start bit falls with the error";
}

TEST_F(FbPacCtrl, SystemErrorBitWithoutANumberIsNotAllowed) {
    Execute(kReqStartAutomatic);
    Cycle(1);
    fromPac_ = StatusImage(kBooted | kSystemError, 0);
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(ErrorId(), kErrNotAllowed);
    EXPECT_EQ(ctrl_->ERRORSOURCE.value, E_PAC_ERRORSOURCE__PAC_ERRSRC_LIBRARY);
    Release();
    Cycle(1);
    EXPECT_EQ(ctrl_->ERRORSOURCE.value, E_PAC_ERRORSOURCE__PAC_ERRSRC_NONE) << "clears with Error";
}

TEST_F(FbPacCtrl, SystemErrorDuringStopInAutomaticIsTheError) {
    fromPac_ = StatusImage(kBooted | kAutomaticActive);
    Execute(kReqStop);
    Cycle(2);
    ASSERT_TRUE(Busy());
    fromPac_ = StatusImage(kBooted | kSystemError | kAutomaticActive, 700);  // 17
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(ErrorId(), 700u);
}

TEST_F(FbPacCtrl, StopWhileAMalfunctionIsProcessedEndsDoneWhenStopped) {
    fromPac_ = StatusImage(kBooted | kSystemError | kOnlineActive, 600);  // 37: the error was there at the edge
    Execute(kReqStop);
    Cycle(2);
    EXPECT_TRUE(Busy());
    EXPECT_EQ(Control(), kStop);
    fromPac_ = StatusImage(kBooted | kSystemError | kOnlineStopped, 600);  // 39
    Cycle(1);
    EXPECT_TRUE(Done());
}

TEST_F(FbPacCtrl, StopEndsNotAllowedWhenTheModeIsLeftWhileItWaits) {
    fromPac_ = StatusImage(kBooted | kOnlineActive);  // 32: braking
    Execute(kReqStop);
    Cycle(2);
    ASSERT_TRUE(Busy());
    fromPac_ = StatusImage(kBooted);  // home: cancelled over the CMD interface (0A81)
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(ErrorId(), kErrNotAllowed);
    EXPECT_EQ(Control(), kIdle) << "the stop bit is released in the same scan";
}

TEST_F(FbPacCtrl, CancelEndsDoneInHomePositionWithAClass2ErrorLeft) {
    fromPac_ = StatusImage(kBooted | kSystemError | kOnlineStopped, 150);  // 39
    Execute(kReqCancel);
    Cycle(1);
    fromPac_ = StatusImage(kBooted | kSystemError, 150);  // 9
    Cycle(kReadScans);
    EXPECT_TRUE(Done());
    EXPECT_EQ(ctrl_->SYSTEMERRORNUMBER.value, 150);
}

// Home position already shown at the edge: it may be a start's 10 or 30 (a start bit of the instance before a
// PLC restart on its way). The bit goes out in the edge scan and stays out, Busy, until the controller has read
// it (a Cancel at 0 cancels whatever mode started meanwhile); Done in that scan, the bit released with it.
TEST_F(FbPacCtrl, CancelAndResetErrorInHomePositionAreDoneOnceTheirBitWasRead) {
    for (auto request : {kReqCancel, kReqResetError}) {
        SCOPED_TRACE(Name(request));
        ctrl_ = PAC_FB(FB_PAC_CTRL);
        rules_.Restart();
        fromPac_ = StatusImage(kBooted | kSystemError, 150);
        Cycle(1);
        Execute(request);
        Cycle(1);
        const std::uint8_t bit = request == kReqCancel ? kCancel : kResetError;
        EXPECT_EQ(Control(), bit) << "the bit goes out in the edge scan";
        if (request == kReqResetError) fromPac_ = StatusImage(kBooted);
        for (int i = 1; i < kReadScans; ++i) {
            Cycle(1);
            ASSERT_TRUE(Busy()) << "scan " << i << " after the edge";
            ASSERT_EQ(Control(), bit) << "scan " << i;
        }
        Cycle(1);
        EXPECT_TRUE(Done());
        EXPECT_EQ(Control(), kIdle);
        Release();
        Cycle(1);
    }
}

class FbPacCtrlLinkLost : public FbPacCtrl, public ::testing::WithParamInterface<BitCase> {};

TEST_P(FbPacCtrlLinkLost, AllZeroStatusWhileWaitingIsConnectionLost) {
    const BitCase& c = GetParam();
    fromPac_ = StatusImage(c.fromWord, c.fromError);
    Execute(c.request);
    Cycle(2);
    ASSERT_TRUE(Busy());
    fromPac_ = Image{};
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(ErrorId(), kErrConnectionLost);
    EXPECT_EQ(Control(), kIdle) << "released in the same scan";
    EXPECT_FALSE(ctrl_->READY.value);
}

INSTANTIATE_TEST_SUITE_P(
    Requests, FbPacCtrlLinkLost,
    ::testing::Values(BitCase{"StartOnline", kReqStartOnline, kBooted, 0, 0, 0, 0, 0, 0},
                      BitCase{"StartAutomatic", kReqStartAutomatic, kBooted, 0, 0, 0, 0, 0, 0},
                      BitCase{"Stop", kReqStop, kBooted | kOnlineActive, 0, 0, 0, 0, 0, 0},
                      BitCase{"Cancel", kReqCancel, kBooted | kAutomaticActive, 0, 0, 0, 0, 0, 0},
                      BitCase{"ResetError", kReqResetError, kBooted | kSystemError, 150, 0, 0, 0, 0, 0}),
    [](const ::testing::TestParamInfo<BitCase>& info) { return std::string(info.param.name); });

TEST_F(FbPacCtrl, NoResultWithinTimeoutIsRequestTimeout) {
    SetTimeout(10);
    Execute(kReqStartOnline);
    Cycle(1);  // edge at t = 1 ms
    Cycle(9);
    EXPECT_TRUE(Busy()) << "t = 10 ms: 9 ms elapsed";
    EXPECT_EQ(Control(), kStartOnline);
    Cycle(1);
    EXPECT_TRUE(Error()) << "t = 11 ms: 10 ms elapsed";
    EXPECT_EQ(ErrorId(), kErrRequestTimeout);
    EXPECT_EQ(Control(), kIdle);
}

TEST_F(FbPacCtrl, EachRequestGetsItsOwnTimeout) {
    SetTimeout(10);
    Execute(kReqStartOnline);
    Cycle(5);
    fromPac_ = StatusImage(kBooted | kOnlineActive);
    Cycle(1);
    ASSERT_TRUE(Done());
    Cycle(20);  // long after the first request's Timeout would have run out
    Release();
    Cycle(1);
    Execute(kReqStop);
    Cycle(1);  // edge
    Cycle(9);
    EXPECT_TRUE(Busy()) << "9 ms after this request's edge";
    Cycle(1);
    EXPECT_EQ(ErrorId(), kErrRequestTimeout);
}

TEST_F(FbPacCtrl, ResetErrorThatTheControllerCannotClearTimesOut) {
    SetTimeout(20);
    fromPac_ = StatusImage(kBooted | kSystemError, 320);  // e.g. a defective power pack: not resettable
    Execute(kReqResetError);
    ASSERT_TRUE(RunUntil([this] { return Error(); }, 30, "Error"));
    EXPECT_EQ(task_.ScanCount(), 21);
    EXPECT_EQ(ErrorId(), kErrRequestTimeout);
}

TEST_F(FbPacCtrl, DefaultTimeoutIsTenSecondsAndZeroIsTheDefault) {
    EXPECT_EQ(ctrl_->TIMEOUT.value.tv_sec, 10);
    EXPECT_EQ(ctrl_->TIMEOUT.value.tv_nsec, 0);
    SetTimeout(0);  // T#0S: the default T#10S, as on every TIME pin of the library
    fromPac_ = StatusImage(kBooted | kOnlineActive);
    Execute(kReqStop);
    Cycle(10000);  // the edge in the first scan, at 1 ms
    EXPECT_TRUE(Busy()) << "10 s of braking axes, less a millisecond";
    EXPECT_EQ(Control(), kStop);
    Cycle(1);
    EXPECT_TRUE(Error()) << "10 s after the edge";
    EXPECT_EQ(ErrorId(), kErrRequestTimeout);
}

// ---------------------------------------------------------------------------------------------------
// PLCopen Execute rules

TEST_F(FbPacCtrl, DoneShowsForExactlyOneScanWhenExecuteFellEarlyAndTheBitStaysOutUntilThen) {
    Execute(kReqStartOnline);
    Cycle(1);
    Release();
    Cycle(3);
    EXPECT_TRUE(Busy()) << "a request once started goes on";
    EXPECT_EQ(Control(), kStartOnline);
    fromPac_ = StatusImage(kBooted | kOnlineActive);
    Cycle(1);
    EXPECT_TRUE(Done());
    EXPECT_EQ(Control(), kIdle);
    Cycle(1);
    EXPECT_FALSE(Done());
    EXPECT_FALSE(Busy());
}

TEST_F(FbPacCtrl, ErrorShowsForExactlyOneScanWhenExecuteFellEarly) {
    SetTimeout(5);
    Execute(kReqStartOnline);
    Cycle(1);
    Release();
    Cycle(4);
    EXPECT_TRUE(Busy());
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(ErrorId(), kErrRequestTimeout);
    Cycle(1);
    EXPECT_FALSE(Error());
    EXPECT_EQ(ErrorId(), 0u);
}

TEST_F(FbPacCtrl, ImmediateResultClearsInTheScanThatSeesExecuteFalse) {
    fromPac_ = StatusImage(kBooted | kOnlineActive);
    Execute(kReqStartOnline);
    Cycle(1);
    ASSERT_TRUE(Done());
    Release();
    Cycle(1);
    EXPECT_FALSE(Done());
}

TEST_F(FbPacCtrl, NewRequestOnlyAfterExecuteWasLow) {
    fromPac_ = StatusImage(kBooted | kOnlineActive);
    Execute(kReqStartOnline);
    Cycle(1);
    ASSERT_TRUE(Done());
    Execute(kReqStop);  // Execute stays TRUE: no edge
    Cycle(5);
    EXPECT_TRUE(Done()) << "still the first request's result";
    EXPECT_EQ(Control(), kIdle) << "no stop without an edge";
    Release();
    Cycle(1);
    Execute(kReqStop);
    Cycle(1);
    EXPECT_TRUE(Busy());
    EXPECT_EQ(Control(), kStop);
}

TEST_F(FbPacCtrl, EdgeWhileBusyIsIgnored) {
    Execute(kReqStartOnline);
    Cycle(1);
    Release();
    Cycle(1);
    Execute(kReqCancel);
    Cycle(2);
    EXPECT_TRUE(Busy());
    EXPECT_EQ(Control(), kStartOnline) << "the running request goes on, no cancel";
    fromPac_ = StatusImage(kBooted | kOnlineActive);
    Cycle(1);
    EXPECT_TRUE(Done()) << "the start's Done; the edge seen while Busy is not remembered";
    Cycle(3);
    EXPECT_TRUE(Done());
    EXPECT_EQ(Control(), kIdle);
}

TEST_F(FbPacCtrl, RequestIsLatchedAtTheEdge) {
    Execute(kReqStartOnline);
    Cycle(1);
    ctrl_->REQUEST.value = kReqCancel;
    Cycle(2);
    EXPECT_EQ(Control(), kStartOnline);
}

// ---------------------------------------------------------------------------------------------------
// Against the fake controller: whole sequences, with the control word reaching it 0..3 scans late

class FbPacCtrlLoop : public FbPacCtrl, public ::testing::WithParamInterface<int> {
protected:
    FbPacCtrlLoop() : controller_(GetParam()) {
        fromPac_ = controller_.Reply();
        task_.AddProgram([this] {
            controller_.Step(toPac_);
            fromPac_ = controller_.Reply();
        });
    }

    // Runs one request from its edge to its final output, then releases Execute.
    pac::test::FinalOutcome Run(E_PAC_CTRLREQUEST request) {
        Release();
        Cycle(1);
        Execute(request);
        Cycle(1);
        const pac::test::FinalOutcome o = pac::test::RunToFinal(ctrl_, task_.ScanCount(), [this] {
            task_.Scan();
            return task_.ScanCount();
        }, 100);
        EXPECT_TRUE(o.Done()) << Name(request) << ": " << o;
        return o;
    }

    FakeController controller_;
};

TEST_P(FbPacCtrlLoop, MerelyCallingTheFbNeverStopsOrCancels) {
    for (int status : {31, 11, 35, 15}) {
        controller_ = FakeController(GetParam(), status);
        fromPac_ = controller_.Reply();
        ctrl_ = PAC_FB(FB_PAC_CTRL);  // a fresh instance: the first scan after a PLC restart
        rules_.Restart();
        toPac_ = Image{};
        Cycle(200);
        EXPECT_EQ(controller_.OpStatus(), status);
    }
}

TEST_P(FbPacCtrlLoop, SwitchToOnlineWithIntegerMode) {
    const int delay = GetParam();
    ctrl_->INTEGERMODE.value = TRUE;
    const pac::test::FinalOutcome o = Run(kReqStartOnline);
    ASSERT_TRUE(o.Done());
    // The fake acts on the bit in its cycle after scan edge + delay (30), passes 30 in its next cycle
    // (31), and the scan after that reads 31.
    EXPECT_EQ(o.Scans(), 2 + delay) << o;
    EXPECT_EQ(controller_.OpStatus(), 31);
    EXPECT_TRUE(controller_.IntegerFormat());
    EXPECT_TRUE(ctrl_->INTEGERMODEACTIVE.value);
    EXPECT_TRUE(ctrl_->ONLINEACTIVE.value);
}

TEST_P(FbPacCtrlLoop, OnlineAndAutomaticCycles) {
    controller_.SetStandstillCycles(5);
    ASSERT_TRUE(Run(kReqStartOnline).Done());
    EXPECT_EQ(controller_.OpStatus(), 31);
    ASSERT_TRUE(Run(kReqStop).Done());
    EXPECT_EQ(controller_.OpStatus(), 35);
    ASSERT_TRUE(Run(kReqStartOnline).Done());  // resume: a new rising edge of the start bit
    EXPECT_EQ(controller_.OpStatus(), 31);
    ASSERT_TRUE(Run(kReqCancel).Done());
    EXPECT_EQ(controller_.OpStatus(), 1);
    ASSERT_TRUE(Run(kReqStartAutomatic).Done());
    EXPECT_EQ(controller_.OpStatus(), 11);
    ASSERT_TRUE(Run(kReqStop).Done());
    EXPECT_EQ(controller_.OpStatus(), 15);
    ASSERT_TRUE(Run(kReqStartAutomatic).Done());  // resume through 16
    EXPECT_TRUE(controller_.OpStatus() == 16 || controller_.OpStatus() == 11) << controller_.OpStatus();
    ASSERT_TRUE(Run(kReqCancel).Done());
    EXPECT_EQ(controller_.OpStatus(), 1);
    Cycle(50);
    EXPECT_EQ(controller_.OpStatus(), 1) << "nothing more happens after the last request";
}

TEST_P(FbPacCtrlLoop, MalfunctionInOnlineThenCancelAndResetError) {
    ASSERT_TRUE(Run(kReqStartOnline).Done());
    controller_.RaiseSystemError(230);  // class 2: stays after returning home
    Cycle(3);
    EXPECT_EQ(controller_.OpStatus(), 39);
    EXPECT_TRUE(ctrl_->ONLINESTOPPED.value);
    EXPECT_EQ(ctrl_->SYSTEMERRORNUMBER.value, 230);
    Release();
    Cycle(1);
    Execute(kReqStartOnline);
    Cycle(1);
    EXPECT_EQ(ErrorId(), kErrNotAllowed) << "no resume with a system error pending";
    ASSERT_TRUE(Run(kReqCancel).Done());
    EXPECT_EQ(controller_.OpStatus(), 9);
    ASSERT_TRUE(Run(kReqResetError).Done());
    EXPECT_EQ(controller_.OpStatus(), 1);
    EXPECT_EQ(controller_.ErrorNumber(), 0);
    ASSERT_TRUE(Run(kReqStartOnline).Done());
    EXPECT_EQ(controller_.OpStatus(), 31);
}

TEST_P(FbPacCtrlLoop, SystemErrorWhileStoppingIsTheRequestsError) {
    controller_.SetStandstillCycles(20);
    ASSERT_TRUE(Run(kReqStartOnline).Done());
    Release();
    Cycle(1);
    Execute(kReqStop);
    Cycle(5 + GetParam());
    ASSERT_TRUE(Busy());
    ASSERT_EQ(controller_.OpStatus(), 32);
    controller_.RaiseSystemError(640);
    ASSERT_TRUE(RunUntil([this] { return Error(); }, 10, "Error"));
    EXPECT_EQ(ErrorId(), 640u);
}

TEST_P(FbPacCtrlLoop, IntegerFormatIsTakenOverOnlyWhenEnteringOnline) {
    ASSERT_TRUE(Run(kReqStartOnline).Done());
    EXPECT_FALSE(ctrl_->INTEGERMODEACTIVE.value);
    ASSERT_TRUE(Run(kReqStop).Done());
    ctrl_->INTEGERMODE.value = TRUE;  // too late for this ONLINE session
    ASSERT_TRUE(Run(kReqStartOnline).Done());
    EXPECT_FALSE(ctrl_->INTEGERMODEACTIVE.value) << "resuming from 35 does not pass 30";
    ASSERT_TRUE(Run(kReqCancel).Done());
    EXPECT_FALSE(ctrl_->INTEGERMODEACTIVE.value) << "unchanged on returning home";
    ASSERT_TRUE(Run(kReqStartOnline).Done());
    EXPECT_TRUE(ctrl_->INTEGERMODEACTIVE.value);
}

INSTANTIATE_TEST_SUITE_P(BusDelay, FbPacCtrlLoop, ::testing::Values(0, 1, 2, 3),
                         [](const ::testing::TestParamInfo<int>& info) {
                             return "Delay" + std::to_string(info.param) + "Scans";
                         });

}  // namespace
}  // namespace test_fb_pac_ctrl
