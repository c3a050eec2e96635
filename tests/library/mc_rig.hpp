// A PLC program with the PLCopen MC_ blocks on the simulated PA-CONTROL: FB_PAC_Ctrl on the CTRL module brings
// the controller to ONLINE; per axis module an FB_PAC_McAxis (called first in every scan, as the library asks)
// and one instance of every MC_ block, all on the same ST_PAC_AxisRef. The axis reference is a variable of the
// PLC program: here it lives in FB_PAC_McAxis's in-out, and every block copies it in and back around its body,
// as MATIEC's C does with a VAR_IN_OUT. Every Execute block runs under the PLCopen checker in every scan.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rig_timing.hpp"
#include "bus_timing.hpp"
#include "pac/fb_instance.hpp"
#include "pac/pac_rig.hpp"
#include "pac/sim/pa_control.hpp"
#include "plcopen_checker.hpp"

namespace pac::test {

// The simulator's axis parameters (DefaultAxisParameters): traverse speed 1000 AE/s, acceleration 10000 AE/s2.
constexpr float kMaxVelocity = 1000.0f;
constexpr float kMaxAcceleration = 10000.0f;

// One instance of every MC_ block of one axis.
struct McBlocks {
    FbInstance<MC_POWER> power = PAC_FB(MC_POWER);
    FbInstance<MC_HOME> home = PAC_FB(MC_HOME);
    FbInstance<MC_MOVEABSOLUTE> moveA = PAC_FB(MC_MOVEABSOLUTE);  // two absolute moves: abort chains
    FbInstance<MC_MOVEABSOLUTE> moveB = PAC_FB(MC_MOVEABSOLUTE);
    FbInstance<MC_MOVERELATIVE> relative = PAC_FB(MC_MOVERELATIVE);
    FbInstance<MC_MOVEVELOCITY> velocity = PAC_FB(MC_MOVEVELOCITY);
    FbInstance<MC_HALT> halt = PAC_FB(MC_HALT);
    FbInstance<MC_STOP> stop = PAC_FB(MC_STOP);
    FbInstance<MC_STOP> stop2 = PAC_FB(MC_STOP);
    FbInstance<MC_RESET> reset = PAC_FB(MC_RESET);
    FbInstance<MC_READACTUALPOSITION> position = PAC_FB(MC_READACTUALPOSITION);
    FbInstance<MC_READSTATUS> status = PAC_FB(MC_READSTATUS);
    FbInstance<MC_READAXISERROR> axisError = PAC_FB(MC_READAXISERROR);
    // Instances that bring the axis into Homing, ContinuousMotion or Stopping before a test edges the ones above.
    FbInstance<MC_HOME> homeA = PAC_FB(MC_HOME);
    FbInstance<MC_MOVEVELOCITY> velocityA = PAC_FB(MC_MOVEVELOCITY);
    FbInstance<MC_STOP> stopA = PAC_FB(MC_STOP);
};

// MC_MoveVelocity has InVelocity where the others have Done: its PLCopen outputs with Done FALSE.
inline PlcOpenOutputs VelocityOutputsOf(const FbInstance<MC_MOVEVELOCITY>& fb) { return OutputsOf(fb); }

// The order the blocks of an axis are called in every scan: as McBlocks lists them (the A instances that bring
// the axis into a state first, then MC_Power ... MC_Reset), or the other way round, so that two blocks edged
// in one scan run in either order.
enum class McCallOrder { kAsListed, kReversed };

class McRig {
public:
    McRig(const BusTiming& timing, int axes, pac::sim::PaControlConfig config = {},
            McCallOrder order = McCallOrder::kAsListed)
        : timing_(timing), layout_{true, axes}, plc_(RigTimingOf(timing), std::move(config), layout_) {
        auto& pac = plc_.Controller();
        EXPECT_EQ(pac.SystemParameters().Set(pac::sim::sysparam::kStopInput, kExternalStopInput),
                  pac::sim::ParameterTable::SetResult::kOk);
        pac.Io().inputs.Set(kExternalStopInput, true);
        plc_.CallCtrl(ctrl_);
        for (int k = 1; k <= axes; ++k) {
            cyclic_.push_back(std::make_unique<FbInstance<FB_PAC_MCAXIS>>(PAC_FB(FB_PAC_MCAXIS)));
            blocks_.push_back(std::make_unique<McBlocks>());
            Cyclic(k)->MAXVELOCITY.value = kMaxVelocity;
            Cyclic(k)->MAXACCELERATION.value = kMaxAcceleration;
            plc_.CallAxis(Cyclic(k), k, [this, k] {
                Cyclic(k)->INTEGERMODE.value = ctrl_->INTEGERMODEACTIVE.value;
                Cyclic(k)->MODECHANGE.value = ctrl_->MODECHANGE.value;
                Cyclic(k)->OPSTATUS.value = plc_.FromPac()[kOpStatusByte];
            });
        }
        for (int k = 1; k <= axes; ++k) {
            McBlocks& b = Blocks(k);
            const std::string axis = "axis " + std::to_string(k) + " ";
            std::vector<std::function<void()>> calls = {
                [&] { CallBlock(b.homeA, k, axis + "MC_Home A"); },
                [&] { CallBlock(b.velocityA, k); },  // checked below
                [&] { CallBlock(b.stopA, k, axis + "MC_Stop A"); },
                [&] { CallBlock(b.power, k); },
                [&] { CallBlock(b.home, k, axis + "MC_Home"); },
                [&] { CallBlock(b.moveA, k, axis + "MC_MoveAbsolute A"); },
                [&] { CallBlock(b.moveB, k, axis + "MC_MoveAbsolute B"); },
                [&] { CallBlock(b.relative, k, axis + "MC_MoveRelative"); },
                [&] { CallBlock(b.velocity, k); },  // checked below
                [&] { CallBlock(b.halt, k, axis + "MC_Halt"); },
                [&] { CallBlock(b.stop, k, axis + "MC_Stop"); },
                [&] { CallBlock(b.stop2, k, axis + "MC_Stop 2"); },
                [&] { CallBlock(b.reset, k, axis + "MC_Reset"); },
            };
            if (order == McCallOrder::kReversed) std::reverse(calls.begin(), calls.end());
            for (auto& call : calls) call();
            CallBlock(b.position, k);
            CallBlock(b.status, k);
            CallBlock(b.axisError, k);
            CheckVelocityBlock(b.velocity, axis + "MC_MoveVelocity");
            CheckVelocityBlock(b.velocityA, axis + "MC_MoveVelocity A");
        }
        plc_.Start();
        plc_.Task().AddProgram([this] {
            for (auto& check : checks_) check(plc_.Task().ScanCount());
        });
    }

    // ONLINE through FB_PAC_Ctrl; then long enough for the axis FBs to treat the axes as free (2.3.4).
    void GoOnline() {
        ASSERT_TRUE(WaitFor([this] { return ctrl_->READY.value != 0; }, 200, "Ready"));
        ScanMs(20);
        ctrl_->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
        ctrl_->EXECUTE.value = TRUE;
        ASSERT_TRUE(WaitFor([this] { return ctrl_->DONE.value || ctrl_->ERROR.value; }, 500, "START_ONLINE"));
        ASSERT_TRUE(ctrl_->DONE.value) << "START_ONLINE: ErrorID 16#" << std::hex << ctrl_->ERRORID.value;
        ctrl_->EXECUTE.value = FALSE;
        ScanMs(30);
    }

    // GoOnline, MC_Power on every axis, until every axis is in Standstill.
    void PowerUp() {
        GoOnline();
        for (int k = 1; k <= Axes(); ++k) Blocks(k).power->ENABLE.value = TRUE;
        for (int k = 1; k <= Axes(); ++k) {
            ASSERT_TRUE(WaitFor([this, k] { return State(k) == E_PAC_MCSTATE__PAC_MC_STANDSTILL; }, 200, "Standstill"));
        }
    }

    int Axes() const { return layout_.axisModules; }
    FbInstance<FB_PAC_MCAXIS>& Cyclic(int k) { return *cyclic_.at(static_cast<std::size_t>(k - 1)); }
    McBlocks& Blocks(int k) { return *blocks_.at(static_cast<std::size_t>(k - 1)); }
    ST_PAC_AXISREF& Ref(int k) { return Cyclic(k)->AXIS.value; }
    E_PAC_MCSTATE State(int k) { return Ref(k).STATE; }
    float Position(int k) { return Ref(k).ACTUALPOSITION; }
    FbInstance<FB_PAC_CTRL>& Ctrl() { return ctrl_; }
    pac::sim::PaControl& Pac() { return plc_.Controller(); }
    PacRig& Plc() { return plc_; }
    std::chrono::nanoseconds Now() const { return plc_.Now(); }
    std::int64_t ScanCount() { return plc_.Task().ScanCount(); }
    // A 16-bit field of the axis module the PLC sends (bytes 4..5 acceleration, 6..7 speed; big-endian).
    unsigned SentWord(int k, std::size_t byte) const {
        const auto module = plc_.ToPac().Module12(layout_.AxisOffset(k));
        return static_cast<unsigned>(module[byte] << 8 | module[byte + 1]);
    }

    // A PLC program's own decisions around a block's call (a CASE step, an IF branch): `before` says whether
    // the program calls it in this scan (and sets its inputs), `after` sees what the call left. The rig's
    // PLCopen checker leaves such a block to the program. Blocks without one are called in every scan.
    void Around(const void* block, std::function<bool()> before, std::function<void()> after) {
        around_[block] = {std::move(before), std::move(after)};
    }

    void Scan(int n = 1) { plc_.Scan(n); }
    int ScansFor(int ms) const { return timing_.ScansFor(std::chrono::milliseconds(ms)); }
    void ScanMs(int ms) { Scan(ScansFor(ms)); }
    ::testing::AssertionResult WaitFor(const std::function<bool()>& predicate, int ms, const std::string& what) {
        if (plc_.ScanUntil(predicate, ScansFor(ms)) > 0) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << what << " not within " << ms << " ms (scan " << ScanCount() << ")";
    }

private:
    static constexpr std::size_t kOpStatusByte = 5;  // of the CMD reply (2.4.2)
    static constexpr int kExternalStopInput = 1;     // system parameter 4 (5.2.1.3)

    // The block on the axis reference of axis k.
    template <class Fb>
    void CallBlock(FbInstance<Fb>& fb, int k) {
        plc_.Task().AddProgram([this, &fb, k] {
            const auto around = around_.find(&fb);
            if (around != around_.end() && !around->second.before()) return;
            fb->AXIS.value = Ref(k);
            fb();
            Ref(k) = fb->AXIS.value;
            if (around != around_.end() && around->second.after) around->second.after();
        });
    }

    // An Execute block, under the PLCopen checker.
    template <class Fb>
    void CallBlock(FbInstance<Fb>& fb, int k, const std::string& checked) {
        CallBlock(fb, k);
        auto checker = std::make_shared<PlcOpenChecker>(checked);
        checks_.push_back([this, checker, &fb](std::int64_t scan) {
            if (around_.count(&fb) == 0) checker->Check(scan, fb);
        });
    }

    // MC_MoveVelocity, checked with Done FALSE.
    void CheckVelocityBlock(FbInstance<MC_MOVEVELOCITY>& fb, const std::string& name) {
        auto checker = std::make_shared<PlcOpenChecker>(name);
        checks_.push_back([this, checker, &fb](std::int64_t scan) {
            if (around_.count(&fb) == 0) checker->Check(scan, InputsOf(fb), OutputsOf(fb));
        });
    }

    BusTiming timing_;
    pac::sim::ModuleLayout layout_;
    PacRig plc_;
    FbInstance<FB_PAC_CTRL> ctrl_ = PAC_FB(FB_PAC_CTRL);
    std::vector<std::unique_ptr<FbInstance<FB_PAC_MCAXIS>>> cyclic_;
    std::vector<std::unique_ptr<McBlocks>> blocks_;
    std::vector<std::function<void(std::int64_t)>> checks_;
    struct AroundCall {
        std::function<bool()> before;
        std::function<void()> after;
    };
    std::map<const void*, AroundCall> around_;
};

}  // namespace pac::test
