// Prints a scenario run for PLC programmers: a header with the timing and the controller's setup,
// then one line per scan in which the CMD interface or FB_PAC_Cmd's outputs changed (time, scan,
// ToPac and FromPac bytes, SEND / RF / KF / BF and the operating status decoded, Execute, Busy, Done,
// Error, ErrorID, AckData), a line when each step starts, its result, and a summary.
#pragma once

#include <optional>
#include <ostream>

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
    void PrintColumns();
    void PrintCommand(const CommandStep& command);
    void PrintFault(const FaultStep& fault);
    void PrintOutcome(const CommandStep& command, const CommandOutcome& outcome);

    std::ostream& out_;
    const GvlNames& names_;
    const Scenario* scenario_ = nullptr;
    std::optional<ScanSample> last_;  // the last scan printed
};

}  // namespace pac::scenario
