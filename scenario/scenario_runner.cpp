#include "scenario_runner.hpp"

#include <type_traits>
#include <variant>

#include "expectations.hpp"
#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"
#include "pac_plc_bench.hpp"

namespace pac::scenario {

namespace {

using std::chrono::milliseconds;

TIME ToTime(int ms) {
    TIME time{};
    time.tv_sec = ms / 1000;
    time.tv_nsec = (ms % 1000) * 1000000;
    return time;
}

pac::test::PlcBenchTiming BenchTiming(const Timing& t) {
    return {milliseconds(t.plcCycleMs), milliseconds(t.pacCycleMs), t.latencyCycles, milliseconds(t.jitterMs),
            t.seed, milliseconds(t.bootMs)};
}

// One PLC with FB_PAC_Cmd on the CMD interface of one simulated PA-CONTROL, run step by step.
class Session {
public:
    Session(const Scenario& scenario, RunObserver& observer)
        : scenario_(scenario), observer_(observer), plc_(BenchTiming(scenario.timing)) {
        plc_.Call(cmd_);
        plc_.Start();
        SetUp(scenario.controller);
    }

    StepReport Run(std::size_t index, const Step& step) {
        StepReport report;
        report.index = index;
        std::visit(
            [&](const auto& action) {
                using Action = std::decay_t<decltype(action)>;
                if constexpr (std::is_same_v<Action, CommandStep>) {
                    report.outcome = RunCommand(action);
                    report.failures = CheckExpectation(action.expect, *report.outcome);
                } else if constexpr (std::is_same_v<Action, FaultStep>) {
                    Inject(action);
                } else {
                    Wait(action);
                }
            },
            step.action);
        return report;
    }

    std::chrono::nanoseconds Now() const { return plc_.Now(); }

private:
    void SetUp(const ControllerSetup& setup) {
        auto& pac = plc_.Controller();
        if (setup.operatingStatus) pac.SetOperatingStatus(*setup.operatingStatus);
        for (const auto& [number, value] : setup.intRegisters) pac.Io().intRegisters.SetInt(number, value);
        for (const auto& [number, value] : setup.realRegisters) pac.Io().realRegisters.SetReal(number, value);
        for (const auto& [number, value] : setup.inputs) pac.Io().inputs.Set(number, value);
    }

    bool Finished() { return cmd_->DONE.value || cmd_->ERROR.value; }

    void Scan() {
        plc_.Scan();
        ScanSample sample;
        sample.time = plc_.Now();
        sample.scan = plc_.Task().ScanCount();
        sample.toPac = plc_.ToPac().Cmd();
        sample.fromPac = plc_.FromPac().Cmd();
        sample.execute = cmd_->EXECUTE.value != 0;
        sample.busy = cmd_->BUSY.value != 0;
        sample.done = cmd_->DONE.value != 0;
        sample.error = cmd_->ERROR.value != 0;
        sample.errorId = static_cast<std::uint16_t>(cmd_->ERRORID.value);
        sample.ackData = static_cast<std::uint32_t>(cmd_->ACKDATA.value);
        observer_.OnScan(sample);
    }

    // The most scans a command may take before the runner gives up on it: the FB's own bounds
    // (Timeout, then EndTimeout), the bus both ways with its jitter, and a margin.
    std::int64_t MaxScans(const CommandStep& command) const {
        const Timing& t = scenario_.timing;
        const std::int64_t ms = static_cast<std::int64_t>(command.timeoutMs) + command.endTimeoutMs + 2LL * t.jitterMs +
                                2LL * t.pacCycleMs;
        return ms / t.plcCycleMs + 2LL * t.latencyCycles + 10;
    }

    CommandOutcome RunCommand(const CommandStep& command) {
        cmd_->CODE.value = command.code;
        cmd_->PARAM.value = command.param;
        cmd_->DATA.value = command.data.bits;
        cmd_->TIMEOUT.value = ToTime(command.timeoutMs);
        cmd_->ENDTIMEOUT.value = ToTime(command.endTimeoutMs);
        cmd_->EXECUTE.value = TRUE;
        CommandOutcome outcome;
        Scan();
        outcome.edgeScan = plc_.Task().ScanCount();
        outcome.edgeTime = plc_.Now();
        const std::int64_t maxScans = MaxScans(command);
        for (std::int64_t scans = 0; !Finished() && scans < maxScans; ++scans) Scan();
        outcome.finished = Finished();
        outcome.done = cmd_->DONE.value != 0;
        outcome.error = cmd_->ERROR.value != 0;
        outcome.errorId = static_cast<std::uint16_t>(cmd_->ERRORID.value);
        outcome.ackData = static_cast<std::uint32_t>(cmd_->ACKDATA.value);
        outcome.endScan = plc_.Task().ScanCount();
        outcome.endTime = plc_.Now();
        cmd_->EXECUTE.value = FALSE;  // PLCopen: Done / Error clear in the scan that sees Execute fall
        Scan();
        return outcome;
    }

    void Inject(const FaultStep& fault) {
        const auto now = plc_.Now();
        if (fault.kind == FaultKind::kPowerCycle) {
            plc_.Controller().PowerCycle(now);
            return;
        }
        pac::sim::LinkFault linkFault = pac::sim::LinkFault::kNone;
        if (fault.kind == FaultKind::kFreezeLink) linkFault = pac::sim::LinkFault::kFrozen;
        if (fault.kind == FaultKind::kZeroLink) linkFault = pac::sim::LinkFault::kAllZero;
        if (fault.link != LinkSide::kFromPac) plc_.Bus().ToSlave().SetFault(now, linkFault);
        if (fault.link != LinkSide::kToPac) plc_.Bus().ToMaster().SetFault(now, linkFault);
    }

    void Wait(const WaitStep& wait) {
        const int cycle = scenario_.timing.plcCycleMs;
        for (int scans = (wait.ms + cycle - 1) / cycle; scans > 0; --scans) Scan();
    }

    const Scenario& scenario_;
    RunObserver& observer_;
    pac::FbInstance<FB_PAC_CMD> cmd_ = PAC_FB(FB_PAC_CMD);  // before plc_, whose programs refer to it
    pac::test::PacPlcBench plc_;
};

}  // namespace

std::size_t RunReport::Commands() const {
    std::size_t commands = 0;
    for (const auto& step : steps) commands += step.outcome ? 1 : 0;
    return commands;
}

std::vector<std::size_t> RunReport::FailedSteps() const {
    std::vector<std::size_t> failed;
    for (const auto& step : steps) {
        if (!step.Passed()) failed.push_back(step.index);
    }
    return failed;
}

RunReport ScenarioRunner::Run(RunObserver& observer) const {
    observer.OnStart(scenario_);
    Session session(scenario_, observer);
    RunReport report;
    for (std::size_t i = 0; i < scenario_.steps.size(); ++i) {
        // Steps start between scans: at the time of the last scan (0 before the first).
        observer.OnStepStart(i, scenario_.steps[i], session.Now());
        report.steps.push_back(session.Run(i, scenario_.steps[i]));
        observer.OnStepEnd(report.steps.back());
    }
    observer.OnEnd(report);
    return report;
}

RunReport ScenarioRunner::Run() const {
    RunObserver silent;
    return Run(silent);
}

}  // namespace pac::scenario
