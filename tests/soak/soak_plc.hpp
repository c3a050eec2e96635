// The PLC of the soak: FB_PAC_Ctrl on the CTRL module, two FB_PAC_Cmd sharing the CMD interface (the rig
// calls FB_PAC_CmdInterface before them) and FB_PAC_Axis on axis module 1 of a simulated PA-CONTROL, the axis
// taking the number format in force from FB_PAC_Ctrl as a PLC program wires them. After every scan: the
// PLCopen rules of every FB with its own Busy bound (plcopen_watch.hpp), the axis control word rule
// (axis_control_rules.hpp), the command ledger, and each open job's deadline.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "command_ledger.hpp"
#include "pac/fb_instance.hpp"
#include "pac/pac_rig.hpp"
#include "pac/st_program.hpp"
#include "plcopen_watch.hpp"
#include "soak_report.hpp"

namespace pac::soak {

// A job from its Execute edge to its final output, which must come within `limit` scans.
struct OpenJob {
    bool open = false;
    std::int64_t edgeScan = 0;
    std::int64_t limit = 0;
    std::uint32_t number = 0;  // the command's number (FB_PAC_Cmd jobs)
    // The FB was Busy when the edge came: a CommandAborted in the edge scan ends the job it supersedes.
    bool supersedes = false;
};

// PAC_SOAK_TRACE=<from>:<to> in the environment: the soak prints FB_PAC_Axis and its module, and FB_PAC_Ctrl,
// in every scan of that range, to see how a run came to a violation.
class TraceWindow {
public:
    TraceWindow();
    bool Covers(std::int64_t scan) const { return scan >= from_ && scan <= to_; }

private:
    std::int64_t from_ = 1;
    std::int64_t to_ = 0;
};

class SoakPlc {
public:
    static constexpr int kCommandFbs = 2;

    SoakPlc(const RigTiming& timing, SoakReport& report);
    SoakPlc(const SoakPlc&) = delete;
    SoakPlc& operator=(const SoakPlc&) = delete;

    void Scan();

    // Starts a job: sets Execute (the caller has set the job's inputs) and watches it from the next scan,
    // which sees the edge. A command FB's job carries `number` as its data.
    void StartCommand(int fb, std::uint16_t param, std::uint32_t number);
    void StartRequest(E_PAC_CTRLREQUEST request);
    void StartAxisJob(E_PAC_AXISCOMMAND command, float position, std::int64_t limitScans);

    pac::FbInstance<FB_PAC_CMD>& Cmd(int fb) { return cmd_[static_cast<std::size_t>(fb)]; }
    pac::FbInstance<FB_PAC_CTRL>& Ctrl() { return ctrl_; }
    pac::FbInstance<FB_PAC_AXIS>& Axis() { return axis_; }
    const OpenJob& CmdJob(int fb) const { return cmdJobs_[static_cast<std::size_t>(fb)]; }
    const OpenJob& CtrlJob() const { return ctrlJob_; }
    const OpenJob& AxisJob() const { return axisJob_; }

    PacRig& Rig() { return rig_; }
    pac::sim::PaControl& Controller() { return rig_.Controller(); }
    std::int64_t ScanCount() { return rig_.Task().ScanCount(); }
    std::chrono::nanoseconds Now() const { return rig_.Now(); }
    std::chrono::nanoseconds Cycle() const { return rig_.Timing().plcCycle; }
    std::int64_t ScansFor(std::chrono::nanoseconds t) const { return t / Cycle() + 1; }
    const CommandLedger& Ledger() const { return ledger_; }

private:
    void CheckAfterScan();
    void Trace(std::int64_t scan, std::uint32_t control);
    // Closes `job` when `fb` shows a final output; a violation when its limit passed first.
    template <class Fb>
    bool Follow(OpenJob& job, const pac::FbInstance<Fb>& fb, const char* name);

    SoakReport& report_;
    PacRig rig_;
    std::array<pac::FbInstance<FB_PAC_CMD>, kCommandFbs> cmd_{PAC_FB(FB_PAC_CMD), PAC_FB(FB_PAC_CMD)};
    pac::FbInstance<FB_PAC_CTRL> ctrl_ = PAC_FB(FB_PAC_CTRL);
    pac::FbInstance<FB_PAC_AXIS> axis_ = PAC_FB(FB_PAC_AXIS);
    pac::test::PlcOpenWatch watch_;
    TraceWindow trace_;
    CommandLedger ledger_;
    std::array<OpenJob, kCommandFbs> cmdJobs_{};
    OpenJob ctrlJob_;
    OpenJob axisJob_;
};

}  // namespace pac::soak
