#include "soak_plc.hpp"

#include <cstdlib>
#include <iostream>

#include "axis_control_rules.hpp"
#include "pac/axis_module_bits.hpp"
#include "pac/iec_time.hpp"
#include "pac/sim/parameter_table.hpp"
#include "pac/sim/process_image.hpp"
#include "plcopen_checker.hpp"

namespace pac::soak {

namespace {

constexpr int kExternalStopInput = 1;  // system parameter 4: START ONLINE needs one (5.2.1.3)

pac::sim::ModuleLayout SoakLayout() {
    pac::sim::ModuleLayout layout;
    layout.ctrl = true;
    layout.axisModules = 1;
    return layout;
}

}  // namespace

TraceWindow::TraceWindow() {
    const char* range = std::getenv("PAC_SOAK_TRACE");
    if (range == nullptr) return;
    char* colon = nullptr;
    from_ = std::strtoll(range, &colon, 10);
    to_ = *colon == ':' ? std::strtoll(colon + 1, nullptr, 10) : from_;
}

SoakPlc::SoakPlc(const RigTiming& timing, SoakReport& report)
    : report_(report),
      rig_(timing, pac::sim::PaControlConfig{}, SoakLayout()),
      watch_(timing.plcCycle, [this](const std::string& violation) { report_.Violation(ScanCount(), violation); }),
      ledger_(report) {
    auto& pac = rig_.Controller();
    pac.SystemParameters().Set(pac::sim::sysparam::kStopInput, kExternalStopInput);
    pac.Io().inputs.Set(kExternalStopInput, true);

    rig_.CallCtrl(ctrl_);
    for (auto& cmd : cmd_) rig_.Call(cmd);
    rig_.CallAxis(axis_, 1, [this] {
        axis_->INTEGERMODE.value = ctrl_->INTEGERMODEACTIVE.value;
        axis_->MODECHANGE.value = ctrl_->MODECHANGE.value;
        axis_->OPSTATUS.value = rig_.CmdInterface()->OPSTATUS.value;  // byte 5 of the CMD reply
    });
    rig_.Start();
    watch_.AddRequest("FB_PAC_Ctrl", ctrl_);
    watch_.AddCommand("FB_PAC_Cmd 1", cmd_[0]);
    watch_.AddCommand("FB_PAC_Cmd 2", cmd_[1]);
    watch_.AddJob("FB_PAC_Axis", axis_);
    watch_.Attach(rig_.Task());
    rig_.Task().AddProgram([this] { CheckAfterScan(); });
}

void SoakPlc::Scan() { rig_.Scan(); }

void SoakPlc::StartCommand(int fb, std::uint16_t param, std::uint32_t number) {
    auto& cmd = Cmd(fb);
    cmd->CODE.value = CommandLedger::kAskedCode;
    cmd->PARAM.value = param;
    cmd->DATA.value = number;
    cmd->EXECUTE.value = TRUE;
    ledger_.Asked(number);
    const auto bound = pac::test::CommandBusyBoundOf(cmd, Cycle());
    cmdJobs_[static_cast<std::size_t>(fb)] = OpenJob{true, ScanCount() + 1, bound.value_or(0) + 1, number};
}

void SoakPlc::StartRequest(E_PAC_CTRLREQUEST request) {
    ctrl_->REQUEST.value = request;
    ctrl_->EXECUTE.value = TRUE;
    const auto bound = pac::test::RequestBusyBoundOf(ctrl_, Cycle());
    ctrlJob_ = OpenJob{true, ScanCount() + 1, bound.value_or(0) + 1, 0};
}

void SoakPlc::StartAxisJob(E_PAC_AXISCOMMAND command, float position, std::int64_t limitScans) {
    axis_->COMMAND.value = command;
    axis_->POSITION.value = position;
    axis_->EXECUTE.value = TRUE;
    axisJob_ = OpenJob{true, ScanCount() + 1, limitScans, 0, axis_->BUSY.value != 0};
}

void SoakPlc::CheckAfterScan() {
    const std::int64_t scan = ScanCount();
    ledger_.Follow(rig_.Controller().Log(), scan);
    const std::uint32_t control =
        pac::sim::ReadDword(rig_.ToPac().Module12(rig_.Bus().Layout().AxisOffset(1)), 0);
    if (trace_.Covers(scan)) Trace(scan, control);
    if (const char* broken =
            pac::test::AxisControlWordViolation(control, pac::axis_control::kTraverseBits, pac::axis_control::kStart)) {
        report_.Violation(scan, std::string("FB_PAC_Axis control word: ") + broken);
    }
    for (std::size_t i = 0; i < cmd_.size(); ++i) {
        if (Follow(cmdJobs_[i], cmd_[i], "FB_PAC_Cmd")) ledger_.Ended(cmdJobs_[i].number, cmd_[i]->DONE.value != 0, scan);
    }
    Follow(ctrlJob_, ctrl_, "FB_PAC_Ctrl");
    Follow(axisJob_, axis_, "FB_PAC_Axis");
}

void SoakPlc::Trace(std::int64_t scan, std::uint32_t control) {
    const FB_PAC_AXIS& axis = axis_.Data();
    std::cout << "scan " << scan << " status " << int{rig_.Controller().OperatingStatus()} << " axis E"
              << int{axis.EXECUTE.value} << " cmd " << axis.COMMAND.value << " pos " << axis.POSITION.value << " A"
              << int{axis.ABORT.value} << " en" << int{axis.ENABLE.value} << " jog" << int{axis.JOGPOSITIVE.value}
              << int{axis.JOGNEGATIVE.value} << " state " << axis.STATE.value << " " << pac::test::OutputsOf(axis_)
              << std::hex << " control 16#" << control << " status 16#" << axis.STATUSWORD.value << std::dec
              << " actual " << axis.ACTUALPOSITION.value << " | ctrl E" << int{ctrl_->EXECUTE.value} << " request "
              << ctrl_->REQUEST.value << " state " << ctrl_->STATE.value << " " << pac::test::OutputsOf(ctrl_) << "\n";
}

template <class Fb>
bool SoakPlc::Follow(OpenJob& job, const pac::FbInstance<Fb>& fb, const char* name) {
    const std::int64_t scan = ScanCount();
    if (!job.open || scan < job.edgeScan) return false;
    const auto out = pac::test::OutputsOf(fb);
    if (out.Final() && !(job.supersedes && scan == job.edgeScan && out.aborted)) {
        job.open = false;
        return true;
    }
    if (scan - job.edgeScan >= job.limit) {
        report_.Violation(scan, std::string(name) + ": Execute of scan " + std::to_string(job.edgeScan) +
                                    " did not end within " + std::to_string(job.limit) + " scans");
        job.open = false;
    }
    return false;
}

}  // namespace pac::soak
