// FB_PAC_AutomaticModule and FB_PAC_Axis sharing the modules of the simulated PA-CONTROL (manual 2.3.1, 2.6,
// 2.7), scan by scan on every bus timing of the library's tests: FB_PAC_Ctrl starts AUTOMATIC, the stand-in
// AUTOMATIC program ("R17 := R1 * 2" ...) answers through FW / N / R 16+k, in both number formats and both byte
// layouts; FB_PAC_Axis stays off the module in AUTOMATIC and takes it back in HOME POSITION and ONLINE. In every
// controller cycle of AUTOMATIC (the controller's own log) the flags and registers the modules are copied into
// hold the values FB_PAC_AutomaticModule sends, or zeros: never an axis control word, dynamics or position. After
// every scan, once AUTOMATIC has ended, a module carries its axis FB's image whole, or zeros where no axis FB
// writes it: never flags, which HOME POSITION and ONLINE read as a control word.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "rig_timing.hpp"
#include "bus_timing.hpp"
#include "gvl_constants.hpp"
#include "log_follower.hpp"
#include "pac/fb_instance.hpp"
#include "pac/pac_rig.hpp"
#include "pac/sim/automatic_module.hpp"
#include "pac/sim/automatic_program.hpp"
#include "pac/sim/image8.hpp"
#include "pac/sim/pa_control.hpp"
#include "pac/st_program.hpp"
#include "run_to_final.hpp"

namespace test_fb_pac_automatic_module_sim {  // apart from the names of the other sources in its unity batch
namespace {

using std::chrono::milliseconds;
using std::chrono::nanoseconds;
using pac::sim::AutomaticLayout;
using pac::sim::AutomaticModuleData;
using pac::test::BusTiming;

const pac::test::GvlConstants kGvl;
const std::uint32_t kErrValueRange = kGvl["PAC_LIB_ERR_VALUE_RANGE"];
const std::uint32_t kErrWrongMode = kGvl["PAC_LIB_ERR_WRONG_MODE"];

constexpr std::size_t kOpStatusByte = 5;  // of the CMD reply (2.4.2)
constexpr int kExternalStopInput = 1;     // system parameter 4 (5.2.1.3), for ONLINE
constexpr int kModules = 2;

bool InAutomatic(std::uint8_t status) { return status >= 10 && status <= 19; }

// What the AUTOMATIC module FB of module k sends.
struct Sent {
    std::uint16_t flagWord = 0;
    std::int32_t n = 0;
    float r = 0.0f;
};

struct Options {
    BusTiming timing{1, 10, 0};
    AutomaticLayout layout = AutomaticLayout::kAxisWidths;  // the controller's: the widths printed in 2.6.1
    bool layoutWired = true;  // FALSE: FB_PAC_AutomaticModule.Layout keeps its default
    bool axisFbs = true;      // FALSE: no axis FB on the modules, FB_PAC_AutomaticModule is their only writer
    bool axisOwnsModuleWired = true;  // FB_PAC_AutomaticModule.AxisOwnsModule := FB_PAC_Axis.OwnsModule
    // TRUE: the FB called first on each module runs before FB_PAC_CmdInterface and sees the operating status of
    // the scan before; the status changes in the scan between the two FBs (module 1: the AUTOMATIC FB sees it
    // late, module 2: the axis FB).
    bool statusChangesBetween = false;
};

pac::sim::PaControlConfig ConfigFor(const Options& o) {
    pac::sim::PaControlConfig config;
    config.automaticModule.layout = o.layout;
    return config;
}

// The PLC: FB_PAC_Ctrl on the CTRL module, then on each module k FB_PAC_Axis and FB_PAC_AutomaticModule, wired
// as a PLC program wires them (operating status from byte 5 of the CMD reply, format and mode change from
// FB_PAC_Ctrl). The controller runs "R17 := R1 * 2", "M257 := M1", "N17 := N1 + 1", "FW18 := FW2",
// "R18 := R2 - 1", "N18 := N2 * 2".
class AutomaticRig {
public:
    explicit AutomaticRig(const Options& options)
        : options_(options),
          layout_{true, kModules},
          plc_(pac::test::RigTimingOf(options.timing), ConfigFor(options), layout_) {
        auto& pac = plc_.Controller();
        EXPECT_EQ(pac.SystemParameters().Set(pac::sim::sysparam::kStopInput, kExternalStopInput),
                  pac::sim::ParameterTable::SetResult::kOk);
        pac.Io().inputs.Set(kExternalStopInput, true);
        pac.SetAutomaticProgram(pac::sim::AutomaticProgram(
            {"R17 := R1 * 2", "M257 := M1", "N17 := N1 + 1", "FW18 := FW2", "R18 := R2 - 1", "N18 := N2 * 2"}));
        plc_.CallCtrl(ctrl_);
        for (int k = 1; k <= kModules; ++k) {
            axes_.push_back(std::make_unique<AxisFb>(PAC_FB(FB_PAC_AXIS)));
            autos_.push_back(std::make_unique<AutoFb>(PAC_FB(FB_PAC_AUTOMATICMODULE)));
            sent_.emplace_back();
        }
        for (int k = 1; k <= kModules; ++k) {
            // Module 1 has the AUTOMATIC FB first, module 2 the axis FB: neither may rely on the other's order.
            if (k != 1) CallAxisFb(k);
            plc_.CallAxis(Auto(k), k, [this, k] {
                Auto(k)->INTEGERMODE.value = ctrl_->INTEGERMODEACTIVE.value;
                Auto(k)->OPSTATUS.value = StatusFor(k, true);
                if (options_.layoutWired) {
                    Auto(k)->LAYOUT.value = options_.layout == AutomaticLayout::kShiftedWidths
                                                ? E_PAC_AUTOLAYOUT__PAC_AUTOLAYOUT_FW2_N4
                                                : E_PAC_AUTOLAYOUT__PAC_AUTOLAYOUT_FW4_N2;
                }
                if (options_.axisFbs && options_.axisOwnsModuleWired) {
                    Auto(k)->AXISOWNSMODULE.value = Axis(k)->OWNSMODULE.value;
                }
                const Sent& s = sent_[static_cast<std::size_t>(k - 1)];
                Auto(k)->FLAGWORD.value = s.flagWord;
                Auto(k)->INTREGISTER.value = s.n;
                Auto(k)->REALREGISTER.value = s.r;
            });
            if (k == 1) CallAxisFb(k);
            Axis(k)->ENABLE.value = TRUE;
        }
        plc_.Start();
        plc_.Task().AddProgram([this] {
            CheckControllerCycles();
            CheckHandOver();
            statusBefore_ = OpStatus();
        });
    }

    using AxisFb = pac::FbInstance<FB_PAC_AXIS>;
    using AutoFb = pac::FbInstance<FB_PAC_AUTOMATICMODULE>;
    AxisFb& Axis(int k) { return *axes_.at(static_cast<std::size_t>(k - 1)); }
    AutoFb& Auto(int k) { return *autos_.at(static_cast<std::size_t>(k - 1)); }
    pac::FbInstance<FB_PAC_CTRL>& Ctrl() { return ctrl_; }
    pac::sim::PaControl& Pac() { return plc_.Controller(); }
    std::uint8_t OpStatus() const { return plc_.FromPac()[kOpStatusByte]; }
    // Set before a scan: what FB_PAC_AutomaticModule k sends from that scan on. Every value sent is one the
    // controller may hold in FW k / N k / R k from then on.
    void Send(int k, const Sent& s) {
        Try(k, s);
        allowed_.push_back({k, s});
    }
    // Values the FB must refuse: the controller may never hold them.
    void Try(int k, const Sent& s) { sent_[static_cast<std::size_t>(k - 1)] = s; }

    void Scan(int n = 1) { plc_.Scan(n); }
    int ScansFor(int ms) const { return options_.timing.ScansFor(milliseconds(ms)); }
    void ScanMs(int ms) { Scan(ScansFor(ms)); }
    ::testing::AssertionResult WaitFor(const std::function<bool()>& predicate, int ms, const std::string& what) {
        if (plc_.ScanUntil(predicate, ScansFor(ms)) > 0) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << what << " not within " << ms << " ms";
    }

    // One FB_PAC_Ctrl request to Done, Execute back to FALSE for a scan.
    ::testing::AssertionResult Request(E_PAC_CTRLREQUEST request, bool integer = false) {
        ctrl_->REQUEST.value = request;
        ctrl_->INTEGERMODE.value = integer ? TRUE : FALSE;
        ctrl_->EXECUTE.value = TRUE;
        const bool ended = plc_.ScanUntil([this] { return ctrl_->DONE.value || ctrl_->ERROR.value; }, ScansFor(1000)) > 0;
        const bool done = ctrl_->DONE.value != 0;
        const unsigned id = ctrl_->ERRORID.value;
        ctrl_->EXECUTE.value = FALSE;
        Scan();
        if (ended && done) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "request " << request << (ended ? " failed, ErrorID " : " did not end ")
                                             << id;
    }
    // From power-on: Ready, then AUTOMATIC; then until every module FB exchanges.
    ::testing::AssertionResult StartAutomatic(bool integer = false) {
        if (!WaitFor([this] { return ctrl_->READY.value != 0; }, 200, "Ready")) return ::testing::AssertionFailure();
        ScanMs(20);
        auto result = Request(E_PAC_CTRLREQUEST__PAC_REQ_START_AUTOMATIC, integer);
        if (!result) return result;
        return WaitFor([this] { return Auto(1)->INEXCHANGE.value && Auto(kModules)->INEXCHANGE.value; }, 100,
                       "InExchange");
    }

    // The received values of module k once they equal the expected ones, within `ms`.
    ::testing::AssertionResult WaitReceived(int k, std::uint16_t fw, std::int32_t n, float r, int ms = 200) {
        auto& fb = Auto(k);
        if (plc_.ScanUntil([&] {
                return fb->RECEIVEDFLAGWORD.value == fw && fb->RECEIVEDINTREGISTER.value == n &&
                       std::fabs(fb->RECEIVEDREALREGISTER.value - r) <= 1e-3f;
            }, ScansFor(ms)) > 0) {
            return ::testing::AssertionSuccess();
        }
        std::ostringstream what;
        what << "module " << k << " received FW 16#" << std::hex << fb->RECEIVEDFLAGWORD.value << std::dec << ", N "
             << fb->RECEIVEDINTREGISTER.value << ", R " << fb->RECEIVEDREALREGISTER.value << "; expected 16#"
             << std::hex << fw << std::dec << ", " << n << ", " << r;
        return ::testing::AssertionFailure() << what.str();
    }

    int AutomaticCyclesChecked() const { return automaticCycles_; }
    int HandOversChecked() const { return handOvers_; }

private:
    // The status an FB of module k sees: that of the scan before if it is called before FB_PAC_CmdInterface.
    std::uint8_t StatusFor(int k, bool automaticFb) const {
        const bool calledFirst = (k == 1) == automaticFb;
        return options_.statusChangesBetween && calledFirst ? statusBefore_ : OpStatus();
    }

    void CallAxisFb(int k) {
        if (!options_.axisFbs) return;
        plc_.CallAxis(Axis(k), k, [this, k] {
            Axis(k)->INTEGERMODE.value = ctrl_->INTEGERMODEACTIVE.value;
            Axis(k)->MODECHANGE.value = ctrl_->MODECHANGE.value;
            Axis(k)->OPSTATUS.value = StatusFor(k, false);
            seenByAxis_[static_cast<std::size_t>(k - 1)] = Module(k);
        });
    }
    pac::sim::Image12 Module(int k) const { return plc_.ToPac().Module12(layout_.AxisOffset(k)); }

    // After every scan, the module as it goes out. Where an axis FB writes the module it carries that FB's image
    // whole, in either call order. Where none does, once FB_PAC_AutomaticModule has seen a status that is neither
    // AUTOMATIC nor 0 it carries no flag data (all zero): in HOME POSITION and ONLINE the bytes are a control
    // word (2.7.1). An axis FB taking the module over after the AUTOMATIC FB in the same scan was given no flags.
    void CheckHandOver() {
        for (int k = 1; k <= kModules; ++k) {
            const auto i = static_cast<std::size_t>(k - 1);
            const std::uint8_t autoStatus = Auto(k)->OPSTATUS.value;
            if (InAutomatic(autoStatus)) autoLeft_[i] = false;
            if (autoStatus != 0 && !InAutomatic(autoStatus) && Auto(k)->INEXCHANGE.value == 0) {
                autoLeft_[i] = autoLeft_[i] || everExchanged_[i];
            }
            everExchanged_[i] = everExchanged_[i] || Auto(k)->INEXCHANGE.value != 0;
            // While both FBs see their own mode (the status changed between them), the one called later writes.
            const bool axisOwns =
                options_.axisFbs && Axis(k)->OWNSMODULE.value != 0 && Auto(k)->INEXCHANGE.value == 0;
            const pac::sim::Image12 module = Module(k);
            std::string what;
            if (axisOwns) {
                pac::sim::Image12 axisImage{};
                for (std::size_t b = 0; b < axisImage.size(); ++b) axisImage[b] = Axis(k)->TOPAC.value.table[b];
                if (module != axisImage) what = "is not the axis FB's image";
                // Module 1 calls the axis FB after the AUTOMATIC FB: in the scan it takes the module over, it must
                // find it cleared, not the flags (its own image only once it has written one).
                if (k == 1 && !axisOwnedBefore_[i] && !options_.statusChangesBetween && autoLeft_[i] &&
                    seenByAxis_[i] != pac::sim::Image12{}) {
                    what = "was handed to the axis FB with the flags in it";
                }
                ++handOvers_;
            } else if (autoLeft_[i] && module != pac::sim::Image12{}) {
                what = "still carries flag data outside AUTOMATIC";
            }
            axisOwnedBefore_[i] = axisOwns;
            if (!what.empty() && ++violations_ <= 5) {
                ADD_FAILURE() << "scan " << plc_.Task().ScanCount() << ", status " << int(OpStatus()) << ": module "
                              << k << " " << what << ": " << pac::sim::ToHex(plc_.ToPac(), layout_);
            }
        }
    }

    struct Allowed {
        int k;
        Sent sent;
    };

    // Every controller cycle that ended in an AUTOMATIC status copied module k into FW k / N k / R k: the bytes
    // must be zeros or what FB_PAC_AutomaticModule k was told to send (never an axis FB's).
    void CheckControllerCycles() {
        follower_.ForEachNew(plc_.Controller().Log(), [this](const pac::sim::ExchangeRecord& r) {
            const std::uint8_t status = r.fromPac[kOpStatusByte];
            if (!options_.axisFbs && status >= 30 && status <= 39) {
                // ONLINE acts on the module as a control word (2.7.1): with no axis FB it must be all zero.
                for (int k = 1; k <= kModules; ++k) {
                    if (r.toPac.Module12(layout_.AxisOffset(k)) != pac::sim::Image12{} && ++violations_ <= 5) {
                        ADD_FAILURE() << "ONLINE took module " << k << " as a control word at "
                                      << pac::sim::FormatTime(r.time) << ": " << pac::sim::ToHex(r.toPac, layout_);
                    }
                }
            }
            if (!InAutomatic(status) || r.toPac.AllZero()) return;
            ++automaticCycles_;
            for (int k = 1; k <= kModules; ++k) {
                const AutomaticModuleData d =
                    AutomaticModuleData::Decode(r.toPac.Module12(layout_.AxisOffset(k)), options_.layout);
                if (!Acceptable(k, d) && ++violations_ <= 5) {
                    ADD_FAILURE() << "module " << k << " copied into the flags and registers at "
                                  << pac::sim::FormatTime(r.time) << ": " << pac::sim::ToHex(r.toPac, layout_);
                }
            }
        });
    }
    bool Acceptable(int k, const AutomaticModuleData& d) {
        const bool integer = plc_.Controller().IntegerFormat();
        auto matches = [&](const Sent& s) {
            std::uint32_t bits = pac::sim::EncodeModulePosition(static_cast<double>(s.r), integer);
            const std::int32_t n = options_.layout == AutomaticLayout::kShiftedWidths
                                       ? s.n
                                       : static_cast<std::int16_t>(static_cast<std::uint16_t>(s.n));
            return d.flagWord == s.flagWord && d.intRegister == n && d.realBits == bits;
        };
        if (matches(Sent{})) return true;
        for (const Allowed& a : allowed_) {
            if (a.k == k && matches(a.sent)) return true;
        }
        return false;
    }

    Options options_;
    pac::sim::ModuleLayout layout_;
    pac::PacRig plc_;
    pac::FbInstance<FB_PAC_CTRL> ctrl_ = PAC_FB(FB_PAC_CTRL);
    std::vector<std::unique_ptr<AxisFb>> axes_;  // never moved: the PLC's programs hold references
    std::vector<std::unique_ptr<AutoFb>> autos_;
    std::vector<Sent> sent_;
    std::vector<Allowed> allowed_;
    pac::test::LogFollower follower_;
    int automaticCycles_ = 0;
    int violations_ = 0;
    std::uint8_t statusBefore_ = 0;
    std::array<pac::sim::Image12, kModules> seenByAxis_{};  // the module as the axis FB was given it this scan
    std::array<bool, kModules> axisOwnedBefore_{};
    std::array<bool, kModules> everExchanged_{};
    std::array<bool, kModules> autoLeft_{};  // the AUTOMATIC FB exchanged, then saw neither AUTOMATIC nor 0
    int handOvers_ = 0;
};

class AutomaticSim : public ::testing::TestWithParam<BusTiming> {
protected:
    Options OptionsFor(AutomaticLayout layout = AutomaticLayout::kAxisWidths) const {
        Options o;
        o.timing = GetParam();
        o.layout = layout;
        return o;
    }
    void SetUp() override {
        trace_ = std::make_unique<::testing::ScopedTrace>(__FILE__, __LINE__, pac::test::Describe(GetParam()));
    }
    void TearDown() override { trace_.reset(); }

private:
    std::unique_ptr<::testing::ScopedTrace> trace_;
};

TEST_P(AutomaticSim, RoundTripThroughTheRunningProgramInBothFormatsAndLayouts) {
    for (const int variant : {0, 1, 2, 3}) {
        const bool integer = (variant & 1) != 0;
        const AutomaticLayout layout = variant < 2 ? AutomaticLayout::kAxisWidths : AutomaticLayout::kShiftedWidths;
        SCOPED_TRACE(integer ? "integer format" : "float format");
        SCOPED_TRACE(layout == AutomaticLayout::kAxisWidths ? "the printed layout" : "the other layout");
        AutomaticRig rig(OptionsFor(layout));
        rig.Send(1, {0x0001, 41, 1.25f});
        rig.Send(2, {0xBEEF, -300, 640.0f});
        ASSERT_TRUE(rig.StartAutomatic(integer));
        EXPECT_EQ(rig.Pac().IntegerFormat(), integer);
        ASSERT_TRUE(rig.WaitReceived(1, 0x0001, 42, 2.5f));
        ASSERT_TRUE(rig.WaitReceived(2, 0xBEEF, -600, 639.0f));
        const auto& io = rig.Pac().Io();
        EXPECT_EQ(io.flags.Word(1), 0x0001);
        EXPECT_EQ(io.intRegisters.GetInt(2), -300);
        EXPECT_EQ(io.realRegisters.GetReal(1), 1.25f);
        // A new value goes through the program and back.
        rig.Send(1, {0x0000, -5, -12.345f});
        ASSERT_TRUE(rig.WaitReceived(1, 0x0000, -4, -24.69f));
        EXPECT_FALSE(rig.Auto(1)->ERROR.value);
        EXPECT_GT(rig.AutomaticCyclesChecked(), 0);
    }
}

TEST_P(AutomaticSim, TheAxisFbStaysOffTheModuleAndRefusesJobsInAutomatic) {
    AutomaticRig rig(OptionsFor());
    rig.Send(1, {0x00FF, 7, 3.0f});
    ASSERT_TRUE(rig.StartAutomatic());
    auto& axis = rig.Axis(1);
    EXPECT_FALSE(axis->OWNSMODULE.value);
    EXPECT_FALSE(axis->STATUSVALID.value) << "flags are no axis status";
    EXPECT_FALSE(axis->ACTIVE.value);
    axis->COMMAND.value = E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE;
    axis->POSITION.value = 100.0f;
    axis->EXECUTE.value = TRUE;
    rig.Scan();
    EXPECT_TRUE(axis->ERROR.value) << "refused in the edge scan";
    EXPECT_EQ(axis->ERRORID.value, kErrWrongMode);
    axis->EXECUTE.value = FALSE;
    axis->JOGPOSITIVE.value = TRUE;
    axis->RESETERROR.value = TRUE;
    rig.ScanMs(50);
    EXPECT_TRUE(axis->ERROR.value) << "a jog too";
    EXPECT_EQ(axis->ERRORID.value, kErrWrongMode);
    ASSERT_TRUE(rig.WaitReceived(1, 0x0001, 8, 6.0f)) << "FW17 is M257 := M1 alone";
    EXPECT_EQ(rig.Pac().Io().intRegisters.GetInt(1), 7);
}

TEST_P(AutomaticSim, ModeChangesInAndOutKeepEachModuleToItsOwner) {
    AutomaticRig rig(OptionsFor());
    rig.Send(1, {0x1234, 1000, 50.0f});
    rig.Send(2, {0x0000, 0, 0.0f});
    ASSERT_TRUE(rig.StartAutomatic());
    ASSERT_TRUE(rig.WaitReceived(1, 0x0000, 1001, 100.0f));
    // Out: home position, ONLINE, a job on the axis FB; the AUTOMATIC FBs leave the modules.
    ASSERT_TRUE(rig.Request(E_PAC_CTRLREQUEST__PAC_REQ_CANCEL));
    EXPECT_FALSE(rig.Auto(1)->INEXCHANGE.value);
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Axis(1)->OWNSMODULE.value != 0; }, 100, "axis FB owns"));
    rig.ScanMs(30);
    ASSERT_TRUE(rig.Request(E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE));
    rig.ScanMs(30);
    auto& axis = rig.Axis(1);
    EXPECT_TRUE(axis->STATUSVALID.value);
    EXPECT_EQ(rig.Pac().Module(1).CmdError(), 0u) << "no flag data taken for a job";
    const double before = rig.Pac().Axes().Motion(1).Position();
    axis->COMMAND.value = E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE;
    axis->POSITION.value = 10.0f;
    axis->EXECUTE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return pac::test::IsFinal(axis); }, 2000, "the job's end"));
    EXPECT_TRUE(axis->DONE.value) << "ErrorID 16#" << std::hex << axis->ERRORID.value;
    EXPECT_NEAR(rig.Pac().Axes().Motion(1).Position(), before + 10.0, 1e-3);
    axis->EXECUTE.value = FALSE;
    rig.Scan();
    // In again: the axis FB's module holds dynamics and a position, none of which may reach the flags.
    ASSERT_TRUE(rig.Request(E_PAC_CTRLREQUEST__PAC_REQ_CANCEL));
    rig.ScanMs(30);
    rig.Send(1, {0x0F0F, -1, -1.0f});
    ASSERT_TRUE(rig.Request(E_PAC_CTRLREQUEST__PAC_REQ_START_AUTOMATIC));
    ASSERT_TRUE(rig.WaitReceived(1, 0x0001, 0, -2.0f));
    EXPECT_FALSE(axis->OWNSMODULE.value);
    EXPECT_GT(rig.AutomaticCyclesChecked(), 0);
}

TEST_P(AutomaticSim, ThePrintedLayoutWithModeChangeAndItsRangeOfN) {
    AutomaticRig rig(OptionsFor(AutomaticLayout::kAxisWidths));
    // Axis ON would be M1 and M2 in this layout: FB_PAC_Ctrl.ModeChange clears the axis modules before it.
    rig.Send(1, {0x8001, -32768, 0.5f});
    rig.Send(2, {0x8000, 300, 0.0f});
    ASSERT_TRUE(rig.StartAutomatic());
    ASSERT_TRUE(rig.WaitReceived(1, 0x0001, -32767, 1.0f));
    ASSERT_TRUE(rig.WaitReceived(2, 0x8000, 600, -1.0f));
    rig.Scan();
    auto& fb = rig.Auto(1);
    // N beyond 16 bits: refused, the last value stays on the wire.
    rig.Try(1, {0x8001, 40000, 0.5f});
    rig.Scan();
    EXPECT_TRUE(fb->ERROR.value);
    EXPECT_EQ(fb->ERRORID.value, kErrValueRange);
    rig.ScanMs(30);
    EXPECT_EQ(rig.Pac().Io().intRegisters.GetInt(1), -32768);
}

TEST_P(AutomaticSim, AnRRegisterTheFieldCannotCarryIsRefused) {
    AutomaticRig rig(OptionsFor());
    rig.Send(1, {0, 0, 2.0f});
    ASSERT_TRUE(rig.StartAutomatic(true));
    ASSERT_TRUE(rig.WaitReceived(1, 0, 1, 4.0f));
    auto& fb = rig.Auto(1);
    for (const float bad : {3.0e6f, -3.0e6f, std::nanf(""), INFINITY}) {
        rig.Try(1, {0, 0, bad});
        rig.Scan();
        EXPECT_TRUE(fb->ERROR.value) << bad;
        EXPECT_EQ(fb->ERRORID.value, kErrValueRange) << bad;
    }
    rig.ScanMs(30);
    EXPECT_EQ(rig.Pac().Io().realRegisters.GetReal(1), 2.0f) << "the last value that fitted stays";
}

// Manual 2.6.1 / 2.6.2 print the widths 4, 2, 2, 4: on a controller that follows the print, the FB with its
// Layout left alone puts M1..M16 where the controller reads them and reads a negative N17 as negative.
TEST_P(AutomaticSim, TheDefaultLayoutIsTheOnePrinted) {
    Options o = OptionsFor(AutomaticLayout::kAxisWidths);
    o.layoutWired = false;
    AutomaticRig rig(o);
    rig.Send(1, {0x8001, -300, 1.5f});
    ASSERT_TRUE(rig.StartAutomatic());
    ASSERT_TRUE(rig.WaitReceived(1, 0x0001, -299, 3.0f)) << "FW17 = M257 := M1, N17 := N1 + 1, R17 := R1 * 2";
    const auto& io = rig.Pac().Io();
    EXPECT_EQ(io.flags.Word(1), 0x8001) << "M1 and M16";
    EXPECT_EQ(io.intRegisters.GetInt(1), -300);
    EXPECT_EQ(rig.Auto(1)->LAYOUT.value, E_PAC_AUTOLAYOUT__PAC_AUTOLAYOUT_FW4_N2);
}

// Out of AUTOMATIC with no axis FB on the modules: in HOME POSITION and ONLINE the bytes are a control word
// (2.7.1), so the flags FB_PAC_AutomaticModule left there would read, on the printed layout, as Axis ON, Start and
// absolute traversing to R1 (bytes 2..3 and 8..11), on the other as "reset axis error" (bit 16) with N as the
// dynamics. It clears its module in the scan that sees the status leave AUTOMATIC.
TEST_P(AutomaticSim, LeavingAutomaticClearsTheFlagsWhenNoAxisFbTakesTheModule) {
    for (const AutomaticLayout layout : {AutomaticLayout::kAxisWidths, AutomaticLayout::kShiftedWidths}) {
        SCOPED_TRACE(layout == AutomaticLayout::kAxisWidths ? "the printed layout" : "the other layout");
        Options o = OptionsFor(layout);
        o.axisFbs = false;
        AutomaticRig rig(o);
        rig.Send(1, {0x0045, 500, 50.0f});
        rig.Send(2, {0x0005, 7, 1.0f});
        ASSERT_TRUE(rig.StartAutomatic());
        ASSERT_TRUE(rig.WaitReceived(1, 0x0001, 501, 100.0f));
        const double before = rig.Pac().Axes().Motion(1).Position();
        ASSERT_TRUE(rig.Request(E_PAC_CTRLREQUEST__PAC_REQ_CANCEL));
        EXPECT_FALSE(rig.Auto(1)->INEXCHANGE.value);
        rig.ScanMs(30);
        ASSERT_TRUE(rig.Request(E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE));
        rig.ScanMs(100);
        EXPECT_EQ(rig.Pac().Module(1).CmdError(), 0u) << "no flag data taken for a job";
        EXPECT_EQ(rig.Pac().Axes().Motion(1).Position(), before);
        EXPECT_EQ(rig.Auto(1)->RECEIVEDINTREGISTER.value, 501) << "the received values hold outside AUTOMATIC";
    }
}

// Out of AUTOMATIC with an axis FB on each module, called after the AUTOMATIC FB on module 1 and before it on
// module 2, also with the status changing between the two: each axis FB's image goes out whole from the scan it
// takes the module (the clearing never overwrites it), and on module 1 the axis FB finds the module cleared. With
// AxisOwnsModule wired the flags sent are, byte for byte, the axis FB's HOME image with Axis ON on the printed
// layout (FW 1, N 0, R 0.0): only that input tells the two apart. Without it, other flags (M1, M3, M7).
TEST_P(AutomaticSim, TheAxisFbsTakeTheModulesBackInBothCallOrders) {
    for (const int variant : {0, 1, 2}) {
        const bool between = variant == 1;
        const bool wired = variant != 2;
        SCOPED_TRACE(between ? "the status changes between the two FBs" : "both FBs see the same status");
        SCOPED_TRACE(wired ? "AxisOwnsModule wired" : "AxisOwnsModule not wired");
        Options o = OptionsFor(AutomaticLayout::kAxisWidths);
        o.statusChangesBetween = between;
        o.axisOwnsModuleWired = wired;
        AutomaticRig rig(o);
        const std::uint16_t flags = wired ? 0x0001 : 0x0045;
        rig.Send(1, {flags, 0, 0.0f});
        rig.Send(2, {flags, 0, 0.0f});
        ASSERT_TRUE(rig.StartAutomatic());
        ASSERT_TRUE(rig.WaitReceived(1, 0x0001, 1, 0.0f));
        ASSERT_TRUE(rig.WaitReceived(2, flags, 0, -1.0f));
        const int before = rig.HandOversChecked();
        ASSERT_TRUE(rig.Request(E_PAC_CTRLREQUEST__PAC_REQ_CANCEL));
        ASSERT_TRUE(rig.WaitFor([&] { return rig.Axis(1)->OWNSMODULE.value && rig.Axis(2)->OWNSMODULE.value; },
                                  100, "axis FBs own"));
        rig.ScanMs(30);
        ASSERT_TRUE(rig.Request(E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE));
        for (int k = 1; k <= kModules; ++k) {
            auto& axis = rig.Axis(k);
            const double start = rig.Pac().Axes().Motion(k).Position();
            axis->COMMAND.value = E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE;
            axis->POSITION.value = 5.0f;
            axis->EXECUTE.value = TRUE;
            ASSERT_TRUE(rig.WaitFor([&] { return pac::test::IsFinal(axis); }, 2000, "the job's end"));
            EXPECT_TRUE(axis->DONE.value) << "axis " << k << ": ErrorID 16#" << std::hex << axis->ERRORID.value;
            EXPECT_NEAR(rig.Pac().Axes().Motion(k).Position(), start + 5.0, 1e-3);
            axis->EXECUTE.value = FALSE;
            rig.Scan();
        }
        EXPECT_GT(rig.HandOversChecked(), before);
    }
}

INSTANTIATE_TEST_SUITE_P(BusTimings, AutomaticSim, ::testing::ValuesIn(pac::test::StandardAndJitteredBusTimings()),
                         pac::test::BusTimingName);

}  // namespace
}  // namespace test_fb_pac_automatic_module_sim
