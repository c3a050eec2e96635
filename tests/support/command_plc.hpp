// A PLC whose command FBs (FB_PAC_Cmd and the FBs built on it) share the CMD interface of a simulated
// PA-CONTROL on one bus timing: the PacRig, the PLCopen checker on every FB after every scan, and
// one command from its Execute edge to its final output, with the scan window the protocol allows for
// it. Add the FBs in the order the PLC program calls them, then Start(). The CMD module and each FB's
// PLCopen pins are traced scan by scan; a test that fails leaves the trace as a VCD file
// (pac/trace_dump.hpp: traces/<Suite>.<Test>.<bus timing>.vcd).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>

#include "rig_timing.hpp"
#include "bus_timing.hpp"
#include "pac/rig_trace.hpp"
#include "pac/fb_instance.hpp"
#include "pac/pac_rig.hpp"
#include "pac/trace_dump.hpp"
#include "pac/trace_recorder.hpp"
#include "plcopen_trace.hpp"
#include "plcopen_watch.hpp"
#include "run_to_final.hpp"
#include "scan_window.hpp"

namespace pac::test {

class CommandPlc {
public:
    explicit CommandPlc(const BusTiming& timing, pac::sim::PaControlConfig config = {},
                        std::chrono::nanoseconds bootTime = std::chrono::nanoseconds(0))
        : timing_(timing), rig_(RigTimingOf(timing, bootTime), config), window_(timing), rules_(timing.PlcCycle()) {
        pac::TraceBusModules(trace_, rig_);
    }

    template <class Fb>
    void Add(std::string name, pac::FbInstance<Fb>& fb) {
        rig_.Call(fb);
        TracePlcOpenPins(trace_, TraceScope(name), fb);
        rules_.AddCommand(std::move(name), fb);
    }
    void Start() {
        rig_.Start();
        rules_.Attach(rig_.Task());
        trace_.AttachTo(rig_.Task());
    }

    // The scan that sees the Execute edge.
    template <class Fb>
    void Begin(pac::FbInstance<Fb>& fb) {
        fb->EXECUTE.value = TRUE;
        Scan();
        edgeTime_ = rig_.Now();
        edgeScan_ = rig_.Task().ScanCount();
    }
    // Scans until `fb` shows its final output, counted from the last Begin(); `eachScan` after each scan.
    template <class Fb>
    FinalOutcome Wait(pac::FbInstance<Fb>& fb, int maxScans = 20000, const std::function<void()>& eachScan = {}) {
        return RunToFinal(fb, edgeScan_, [&] {
            Scan();
            if (eachScan) eachScan();
            return rig_.Task().ScanCount();
        }, maxScans);
    }
    // Execute falls for one scan.
    template <class Fb>
    void Release(pac::FbInstance<Fb>& fb) {
        fb->EXECUTE.value = FALSE;
        Scan();
    }
    // A whole command as a PLC program runs it: edge, wait, release.
    template <class Fb>
    FinalOutcome Run(pac::FbInstance<Fb>& fb, int maxScans = 20000) {
        Begin(fb);
        const FinalOutcome outcome = Wait(fb, maxScans);
        Release(fb);
        return outcome;
    }

    // The scans the protocol needs for a command sent in the last Begin()'s edge scan: the FBs add no
    // scan of their own (docs/fb/FB_PAC_Cmd.md, "Timing").
    ScanWindow Window() const { return window_.Request(edgeTime_); }
    const ProtocolWindow& Protocol() const { return window_; }
    const pac::Trace& Trace() const { return trace_.Recording(); }

    void Scan(int n = 1) { rig_.Scan(n); }
    // Scans until the channel's first handshake after the cold start, the parked read, is acknowledged:
    // from then on a command goes out in its edge scan (docs/fb/FB_PAC_Cmd.md, after a PLC cold start).
    void ScanPastFirstHandshake(int maxScans = 100000) {
        for (int i = 0; i < maxScans && !rig_.Channel().FIRSTREADDONE; ++i) rig_.Scan();
    }
    const BusTiming& Timing() const { return timing_; }
    PacRig& Rig() { return rig_; }
    pac::sim::PaControl& Controller() { return rig_.Controller(); }
    // The CMD module of the newest command the controller recognised (its exchange log): what was sent,
    // after the library has parked the module again.
    pac::sim::Image8 LastCommandSeen() {
        const auto& records = rig_.Controller().Log().Records();
        for (auto it = records.rbegin(); it != records.rend(); ++it) {
            if (it->newCommand) return it->toPac.Cmd();
        }
        return {};
    }
    std::chrono::nanoseconds Now() const { return rig_.Now(); }
    std::chrono::nanoseconds EdgeTime() const { return edgeTime_; }

private:
    BusTiming timing_;
    PacRig rig_;
    ProtocolWindow window_;
    PlcOpenWatch rules_;
    pac::TraceRecorder trace_;
    // After trace_ (written before it goes); one file per bus timing, as a test may try several.
    pac::ScopedVcdDump dump_{trace_.Recording(), BusTimingName(::testing::TestParamInfo<BusTiming>(timing_, 0))};
    std::chrono::nanoseconds edgeTime_{0};
    std::int64_t edgeScan_ = 0;
};

}  // namespace pac::test
