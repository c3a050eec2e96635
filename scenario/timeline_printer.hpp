// Prints a scenario run for PLC programmers: a header with the timing, the modules and the
// controller's setup, then one line per scan in which the module a step works on, or its FB's
// outputs, changed, a line when each step starts, its result, and a summary. Command steps show the
// CMD interface and FB_PAC_Cmd (ToPac and FromPac bytes, SEND / RF / KF / BF and the operating status
// decoded, Execute, Busy, Done, Error, ErrorID, AckData); ctrl steps the CTRL control and status
// words and FB_PAC_Ctrl; axes steps each of their axis modules and FB_PAC_Axis. Faults and waits keep
// the view of the step before them.
#pragma once

#include <optional>
#include <ostream>
#include <vector>

#include "gvl_names.hpp"
#include "scenario_runner.hpp"

namespace pac::scenario {

class TimelinePrinter : public RunObserver {
public:
    TimelinePrinter(std::ostream& out, const GvlNames& names) : out_(out), names_(names) {}

    void OnStart(const Scenario& scenario) override;
    void OnStepStart(std::size_t index, const Step& step, std::chrono::nanoseconds now) override;
    void OnScan(const ScanSample& sample) override;
    void OnStepEnd(const StepReport& report) override;
    void OnEnd(const RunReport& report) override;

private:
    enum class View { kCmd, kCtrl, kAxes, kAutomatic };

    bool SetView(View view, std::vector<int> axes);  // true if the view changed
    void PrintColumns();
    bool Changed(const ScanSample& sample) const;
    void PrintCmdLine(const ScanSample& s);
    void PrintCtrlLine(const ScanSample& s);
    void PrintAxisLine(const ScanSample& s, const AxisSample& axis);
    void PrintAutomaticLine(const ScanSample& s, const AxisSample& module);
    void PrintAutomatic(const AutomaticStep& step);
    void PrintCtrl(const CtrlStep& step);
    void PrintAxes(const AxesStep& step);
    void PrintCommand(const CommandStep& command);
    void PrintFault(const FaultStep& fault);
    void PrintOutcome(const CommandOutcome& outcome, bool showAckData, bool ackAsReal);
    void PrintAxisOutcome(const AxisJob& job, const AxisOutcome& outcome);
    void PrintVerdict(bool expectedNothing, const StepReport& report);
    void PrintHistory(const RunReport& report);  // the CMD interface's handshake history

    std::ostream& out_;
    const GvlNames& names_;
    const Scenario* scenario_ = nullptr;
    std::optional<ScanSample> last_;  // the last scan printed
    View view_ = View::kCmd;
    std::vector<int> viewAxes_;  // the axes (modules) shown in View::kAxes and View::kAutomatic
};

}  // namespace pac::scenario
