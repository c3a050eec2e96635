// A PLC program with FB_PAC_Diagnosis (docs/fb/FB_PAC_Diagnosis.md) on a simulated PA-CONTROL: optionally
// FB_PAC_Ctrl on the CTRL module and an FB_PAC_Axis on each axis module (called first, as a program calls the
// cyclic FBs), then FB_PAC_Diagnosis and a second command FB (FB_PAC_Cmd) on the same CMD channel, in either
// order. The diagnosis FB gets each FB_PAC_Axis.Status and FB_PAC_Ctrl.SystemErrorNumber of the same scan, as
// a program wires them. After every scan: the PLCopen Enable rules on FB_PAC_Diagnosis, the PLCopen rules on
// the other FB. The commands the controller recognised are read from its exchange log.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rig_timing.hpp"
#include "bus_timing.hpp"
#include "pac/rig_trace.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/pac_rig.hpp"
#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/pa_control.hpp"
#include "pac/trace_dump.hpp"
#include "pac/trace_recorder.hpp"
#include "plcopen_enable_checker.hpp"
#include "plcopen_trace.hpp"
#include "plcopen_watch.hpp"

namespace pac::test {

struct DiagnosisLayout {
    bool ctrl = false;    // the CTRL module with FB_PAC_Ctrl; FB_PAC_Diagnosis.CtrlInterface follows it
    int axisModules = 0;  // axis modules with an FB_PAC_Axis each (needs ctrl)
    bool diagnosisFirst = true;  // FB_PAC_Diagnosis before the other command FB in every scan
};

// A command the controller recognised, with the time of the cycle that recognised it.
struct SeenCommand {
    std::chrono::nanoseconds time{0};
    std::uint16_t code = 0;
    std::uint16_t param = 0;
};

class DiagnosisPlc {
public:
    // The controller's boot at power-on and after a power cycle: status 0 and an all-zero reply meanwhile.
    static constexpr std::chrono::nanoseconds kBootTime = std::chrono::milliseconds(50);

    DiagnosisPlc(const BusTiming& timing, DiagnosisLayout layout, pac::sim::PaControlConfig config = {})
        : timing_(timing), layout_(layout),
          plc_(RigTimingOf(timing, kBootTime), WithWholeLog(config), {layout.ctrl, layout.axisModules}),
          rules_(timing.PlcCycle()), enableRules_("FB_PAC_Diagnosis") {
        if (layout.ctrl) plc_.CallCtrl(ctrl_);
        for (int k = 1; k <= layout.axisModules; ++k) {
            axes_.push_back(std::make_unique<FbInstance<FB_PAC_AXIS>>(PAC_FB(FB_PAC_AXIS)));
            plc_.CallAxis(Axis(k), k, [this, k] {
                Axis(k)->OPSTATUS.value = plc_.FromPac()[5];
                Axis(k)->MODECHANGE.value = ctrl_->MODECHANGE.value;
                Axis(k)->INTEGERMODE.value = ctrl_->INTEGERMODEACTIVE.value;
            });
        }
        auto wire = [this] {
            diag_->CTRLINTERFACE.value = layout_.ctrl;
            diag_->CTRLSYSTEMERRORNUMBER.value = ctrl_->SYSTEMERRORNUMBER.value;
            for (int k = 1; k <= layout_.axisModules; ++k) {
                diag_->AXISSTATUS.value.table[k - 1] = Axis(k)->STATUS.value;
            }
        };
        // The diagnosis as a program calls it, in the scans the test lets it (a CASE step, an IF branch).
        auto diagnosis = [this, wire](ST_PAC_CMDCHANNEL& channel) {
            if (!diagnosisCalled_) return;
            wire();
            diag_->CHANNEL.value = channel;
            diag_();
            channel = diag_->CHANNEL.value;
        };
        if (layout.diagnosisFirst) plc_.CallCmdProgram(diagnosis);
        plc_.Call(other_);
        if (!layout.diagnosisFirst) plc_.CallCmdProgram(diagnosis);
        plc_.Start();
        rules_.AddCommand("FB_PAC_Cmd (other)", other_);
        rules_.Attach(plc_.Task());
        plc_.Task().AddProgram([this] { enableRules_.Check(plc_.Task().ScanCount(), EnableOutputsOf(diag_)); });
        pac::TraceBusModules(trace_, plc_);
        TracePlcOpenPins(trace_, "other", other_);
        trace_.AddBool("diag.Enable", [this] { return diag_->ENABLE.value != 0; });
        trace_.AddBool("diag.Valid", [this] { return diag_->VALID.value != 0; });
        trace_.AddBool("diag.Busy", [this] { return diag_->BUSY.value != 0; });
        trace_.AddBool("diag.Error", [this] { return diag_->ERROR.value != 0; });
        trace_.AddBits("diag.ErrorID", 16, [this] { return diag_->ERRORID.value; });
        trace_.AddBits("diag.ChangeCount", 32, [this] { return diag_->CHANGECOUNT.value; });
        trace_.AttachTo(plc_.Task());
    }

    // Scans until the controller has booted and the PLC sees it, plus a round trip.
    void Boot() {
        for (int i = 0; i < 100000 && !Controller().Booted(); ++i) Scan();
        Scan(3 + 2 * timing_.latency + timing_.jitterUs / 1000 / timing_.plcMs);
        // Past the cold start's first handshake on the CMD interface (the parked read).
        for (int i = 0; i < 100000 && !plc_.Channel().FIRSTREADDONE; ++i) Scan();
    }

    // Scans for `ms` of PLC time.
    void ScanMs(int ms) { Scan(timing_.ScansFor(std::chrono::milliseconds(ms))); }
    // Scans until `predicate` holds, at most `ms` of PLC time.
    bool WaitMs(const std::function<bool()>& predicate, int ms) {
        return predicate() || plc_.ScanUntil(predicate, timing_.ScansFor(std::chrono::milliseconds(ms))) > 0;
    }

    // The commands the controller recognised so far, oldest first.
    const std::vector<SeenCommand>& Seen() {
        const auto& records = Controller().Log().Records();
        for (; logRead_ < records.size(); ++logRead_) {
            const auto& r = records[logRead_];
            if (!r.newCommand) continue;
            const auto frame = pac::sim::CommandFrame::Decode(r.toPac.Cmd());
            // The parked read (190B without data) executes nothing: the first handshake after a cold start.
            if (frame.code == 0x190B && frame.parameter == 0 && frame.data == 0) continue;
            seen_.push_back({r.time, frame.code, frame.parameter});
        }
        return seen_;
    }
    // How many of them had `code` (and `param`, unless negative) since `from`.
    int Count(std::uint16_t code, int param = -1, std::chrono::nanoseconds from = std::chrono::nanoseconds(0)) {
        int n = 0;
        for (const auto& c : Seen()) {
            n += c.time >= from && c.code == code && (param < 0 || c.param == param) ? 1 : 0;
        }
        return n;
    }
    int CountAll(std::chrono::nanoseconds from = std::chrono::nanoseconds(0)) {
        int n = 0;
        for (const auto& c : Seen()) n += c.time >= from ? 1 : 0;
        return n;
    }

    // Whether the program calls FB_PAC_Diagnosis in the next scans (TRUE from the start).
    void CallDiagnosis(bool called) { diagnosisCalled_ = called; }
    void SetPollMs(int ms) { diag_->POLLTIME.value = TIME{ms / 1000, (ms % 1000) * 1'000'000L}; }

    void Scan(int n = 1) { plc_.Scan(n); }
    FbInstance<FB_PAC_DIAGNOSIS>& Diag() { return diag_; }
    FbInstance<FB_PAC_CMD>& Other() { return other_; }
    FbInstance<FB_PAC_CTRL>& Ctrl() { return ctrl_; }
    FbInstance<FB_PAC_AXIS>& Axis(int k) { return *axes_.at(static_cast<std::size_t>(k - 1)); }
    const ST_PAC_DIAGAXIS& Entry(int k) { return diag_->AXIS.value.table[k - 1]; }
    pac::sim::PaControl& Controller() { return plc_.Controller(); }
    PacRig& Bench() { return plc_; }
    std::chrono::nanoseconds Now() const { return plc_.Now(); }
    const BusTiming& Timing() const { return timing_; }

private:
    static pac::sim::PaControlConfig WithWholeLog(pac::sim::PaControlConfig config) {
        config.logCapacity = 10000000;  // the whole test: Seen() reads every command
        return config;
    }

    BusTiming timing_;
    DiagnosisLayout layout_;
    FbInstance<FB_PAC_CTRL> ctrl_ = PAC_FB(FB_PAC_CTRL);
    FbInstance<FB_PAC_DIAGNOSIS> diag_ = PAC_FB(FB_PAC_DIAGNOSIS);
    bool diagnosisCalled_ = true;
    FbInstance<FB_PAC_CMD> other_ = PAC_FB(FB_PAC_CMD);
    std::vector<std::unique_ptr<FbInstance<FB_PAC_AXIS>>> axes_;  // before plc_, whose programs call them
    PacRig plc_;
    PlcOpenWatch rules_;
    PlcOpenEnableChecker enableRules_;
    pac::TraceRecorder trace_;
    pac::ScopedVcdDump dump_{trace_.Recording(), BusTimingName(::testing::TestParamInfo<BusTiming>(timing_, 0))};
    std::vector<SeenCommand> seen_;
    std::size_t logRead_ = 0;
};

}  // namespace pac::test
