#include "scenario_runner.hpp"

#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <variant>
#include <vector>

#include "controller_setup.hpp"
#include "expectations.hpp"
#include "mc_axes.hpp"
#include "scenario_error.hpp"
#include "pac/enum_names.hpp"
#include "pac/fb_instance.hpp"
#include "pac/pac_rig.hpp"
#include "pac/st_program.hpp"

namespace pac::scenario {

namespace {

TIME ToTime(int ms) {
    TIME time{};
    time.tv_sec = ms / 1000;
    time.tv_nsec = (ms % 1000) * 1000000;
    return time;
}

// The C enumerator of an ST enum's value name; the loader has refused every other name.
template <class Enum, std::size_t N>
Enum Enumerator(const char* const (&names)[N], const std::string& name) {
    const auto value = pac::EnumNames(names).Find<Enum>(name);
    if (!value) throw std::logic_error("not an enumerator: " + name);
    return *value;
}

// One PLC with FB_PAC_Cmd on the CMD interface of one simulated PA-CONTROL, FB_PAC_Ctrl on its CTRL
// interface and FB_PAC_Axis on each axis module, run step by step.
class Session {
public:
    Session(const Scenario& scenario, RunObserver& observer, RemoteController* remote)
        : scenario_(scenario),
          observer_(observer),
          remote_(remote),
          axes_(static_cast<std::size_t>(scenario.modules.axes), PAC_FB(FB_PAC_AXIS)),
          automatic_(static_cast<std::size_t>(scenario.modules.axes), PAC_FB(FB_PAC_AUTOMATICMODULE)),
          plc_(RigTimingOf(scenario.timing), ControllerConfig(scenario.controller), Layout(scenario.modules)) {
        plc_.Call(cmd_);
        if (scenario.modules.ctrl) plc_.CallCtrl(ctrl_);
        if (scenario.modules.mcBlocks) {
            mc_ = std::make_unique<McAxes>(plc_, scenario.modules.axes, [this](FB_PAC_MCAXIS& fb) {
                fb.INTEGERMODE.value = ctrl_->INTEGERMODEACTIVE.value;
                fb.MODECHANGE.value = ctrl_->MODECHANGE.value;
                fb.OPSTATUS.value = cmd_->OPSTATUS.value;
            });
        }
        for (std::size_t k = 0; k < axes_.size(); ++k) {
            // As a PLC program wires them: each axis takes the format in force and the mode change from
            // FB_PAC_Ctrl, the operating status from FB_PAC_Cmd.
            if (!mc_) {
                plc_.CallAxis(axes_[k], static_cast<int>(k) + 1, [this, k] {
                    axes_[k]->INTEGERMODE.value = ctrl_->INTEGERMODEACTIVE.value;
                    axes_[k]->MODECHANGE.value = ctrl_->MODECHANGE.value;
                    axes_[k]->OPSTATUS.value = cmd_->OPSTATUS.value;
                });
            }
            // The same module in AUTOMATIC (2.6): each FB writes it only in its own modes; the AUTOMATIC FB, called
            // after the axis FB, clears it when AUTOMATIC ends unless the axis FB has taken it (AxisOwnsModule).
            plc_.CallAxis(automatic_[k], static_cast<int>(k) + 1, [this, k] {
                automatic_[k]->INTEGERMODE.value = ctrl_->INTEGERMODEACTIVE.value;
                automatic_[k]->OPSTATUS.value = cmd_->OPSTATUS.value;
                const bool axisOwns =
                    mc_ ? mc_->OwnsModule(static_cast<int>(k) + 1) : axes_[k]->OWNSMODULE.value != 0;
                automatic_[k]->AXISOWNSMODULE.value = axisOwns ? TRUE : FALSE;
            });
        }
        if (scenario.modules.diagnosis) CallDiagnosis(*scenario.modules.diagnosis);
        if (remote_) {
            plc_.ExchangeImagesWith(
                [this](std::chrono::nanoseconds now, pac::sim::ProcessImage& in) { remote_->ReadFromPac(now, in); },
                [this](std::chrono::nanoseconds now, const pac::sim::ProcessImage& out) { remote_->WriteToPac(now, out); });
        }
        plc_.Start();
        ApplyControllerSetup(plc_.Controller(), scenario.controller);
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
                } else if constexpr (std::is_same_v<Action, CtrlStep>) {
                    report.request = RunCtrl(action);
                    report.failures = CheckExpectation(action.expect, *report.request);
                } else if constexpr (std::is_same_v<Action, AxesStep>) {
                    report.axes = RunAxes(action);
                    for (std::size_t i = 0; i < action.jobs.size(); ++i) {
                        for (const auto& failure : CheckAxisExpectation(action.jobs[i], report.axes[i])) {
                            report.failures.push_back("axis " + std::to_string(action.jobs[i].axis) + ": " + failure);
                        }
                    }
                } else if constexpr (std::is_same_v<Action, AutomaticStep>) {
                    report.failures = RunAutomatic(action);
                } else if constexpr (std::is_same_v<Action, FaultStep>) {
                    if (remote_) {
                        remote_->InjectFault(action);
                    } else {
                        InjectFault(plc_, action);
                    }
                } else {
                    Wait(action);
                }
            },
            step.action);
        return report;
    }

    std::chrono::nanoseconds Now() const { return plc_.Now(); }

    // The CMD interface's history ring (FB_PAC_Cmd), oldest first; how many handshakes it has seen.
    std::vector<HandshakeRecord> History(std::uint32_t& handshakes) {
        const ST_PAC_CMDCHANNEL& channel = plc_.Channel();
        handshakes = static_cast<std::uint32_t>(channel.HISTORYCOUNT);
        constexpr std::uint32_t kRing = 16;
        const std::uint32_t kept = handshakes < kRing ? handshakes : kRing;
        std::vector<HandshakeRecord> history;
        for (std::uint32_t i = 0; i < kept; ++i) {
            const auto slot = (static_cast<std::uint32_t>(channel.HISTORYNEXT) + kRing - kept + i) % kRing;
            const ST_PAC_HANDSHAKE& h = channel.HISTORY.table[slot];
            history.push_back({static_cast<std::uint16_t>(h.CODE), static_cast<std::uint16_t>(h.PARAM),
                               static_cast<std::uint32_t>(h.DATA), static_cast<std::uint32_t>(h.ACKDATA),
                               static_cast<std::uint16_t>(h.ERRORID), static_cast<std::int32_t>(h.SCANSTOACK),
                               static_cast<std::int32_t>(h.SCANSTOEND)});
        }
        return history;
    }

private:
    // FB_PAC_Diagnosis after the other FBs, on the same channel: this scan's axis statuses and system error
    // number, as a PLC program wires them.
    void CallDiagnosis(const DiagnosisSetup& setup) {
        diag_->ENABLE.value = TRUE;
        diag_->AXES.value = static_cast<INT>(setup.axes);
        diag_->POLLTIME.value = ToTime(setup.pollMs);
        diag_->CTRLINTERFACE.value = scenario_.modules.ctrl ? TRUE : FALSE;
        plc_.Call(diag_, [this] {
            diag_->CTRLSYSTEMERRORNUMBER.value = ctrl_->SYSTEMERRORNUMBER.value;
            for (std::size_t k = 0; k < axes_.size(); ++k) diag_->AXISSTATUS.value.table[k] = axes_[k]->STATUS.value;
        });
    }

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
        if (scenario_.modules.ctrl) {
            CtrlSample ctrl;
            ctrl.toPac = plc_.ToPac().Module8(pac::sim::ModuleLayout::kCtrlOffset);
            ctrl.fromPac = plc_.FromPac().Module8(pac::sim::ModuleLayout::kCtrlOffset);
            ctrl.execute = ctrl_->EXECUTE.value != 0;
            ctrl.busy = ctrl_->BUSY.value != 0;
            ctrl.done = ctrl_->DONE.value != 0;
            ctrl.error = ctrl_->ERROR.value != 0;
            ctrl.errorId = static_cast<std::uint16_t>(ctrl_->ERRORID.value);
            sample.ctrl = ctrl;
        }
        const auto layout = Layout(scenario_.modules);
        for (std::size_t k = 0; k < axes_.size(); ++k) {
            auto& fb = axes_[k];
            AxisSample axis;
            axis.axis = static_cast<int>(k) + 1;
            axis.toPac = plc_.ToPac().Module12(layout.AxisOffset(axis.axis));
            axis.fromPac = plc_.FromPac().Module12(layout.AxisOffset(axis.axis));
            axis.enable = fb->ENABLE.value != 0;
            axis.execute = fb->EXECUTE.value != 0;
            axis.busy = fb->BUSY.value != 0;
            axis.done = fb->DONE.value != 0;
            axis.error = fb->ERROR.value != 0;
            axis.aborted = fb->COMMANDABORTED.value != 0;
            axis.errorId = static_cast<std::uint16_t>(fb->ERRORID.value);
            axis.enabled = fb->ENABLED.value != 0;
            axis.resetError = fb->RESETERROR.value != 0;
            axis.actualPosition = fb->ACTUALPOSITION.value;
            axis.integerMode = fb->INTEGERMODE.value != 0;
            if (mc_) mc_->Fill(axis);
            axis.simPosition = plc_.Controller().Axes().Motion(axis.axis).Position();
            sample.axes.push_back(axis);
        }
        if (scenario_.modules.diagnosis) {
            DiagSample diag;
            diag.valid = diag_->VALID.value != 0;
            diag.busy = diag_->BUSY.value != 0;
            diag.error = diag_->ERROR.value != 0;
            diag.errorId = static_cast<std::uint16_t>(diag_->ERRORID.value);
            diag.opStatus = static_cast<std::uint8_t>(diag_->OPSTATUS.value);
            diag.systemErrorNumber = static_cast<std::uint16_t>(diag_->SYSTEMERRORNUMBER.value);
            diag.changeCount = static_cast<std::uint32_t>(diag_->CHANGECOUNT.value);
            diag.historyCount = static_cast<std::uint32_t>(diag_->HISTORYCOUNT.value);
            sample.diag = diag;
        }
        observer_.OnScan(sample);
    }

    // The most scans a job whose FB bounds its own waits by `fbLimitMs` may take before the runner gives
    // up on it: that bound, the bus both ways with its jitter, and a margin.
    std::int64_t MaxScans(std::int64_t fbLimitMs) const {
        const Timing& t = scenario_.timing;
        const std::int64_t ms = fbLimitMs + 2LL * t.jitterMs + 2LL * t.pacCycleMs;
        return ms / t.plcCycleMs + 2LL * t.latencyCycles + 10;
    }

    CommandOutcome RunCommand(const CommandStep& command) {
        cmd_->CODE.value = command.code;
        cmd_->PARAM.value = command.param;
        cmd_->DATA.value = command.data.bits;
        cmd_->TIMEOUT.value = ToTime(command.timeoutMs);
        cmd_->ENDTIMEOUT.value = ToTime(command.endTimeoutMs);
        return RunToFinalOutput(cmd_, MaxScans(static_cast<std::int64_t>(command.timeoutMs) + command.endTimeoutMs),
                                [this](CommandOutcome& outcome) {
                                    outcome.ackData = static_cast<std::uint32_t>(cmd_->ACKDATA.value);
                                });
    }

    CommandOutcome RunCtrl(const CtrlStep& step) {
        ctrl_->REQUEST.value = Enumerator<E_PAC_CTRLREQUEST>(E_PAC_CTRLREQUEST__NAMES, step.request);
        ctrl_->INTEGERMODE.value = step.integerMode ? TRUE : FALSE;
        ctrl_->TIMEOUT.value = ToTime(step.timeoutMs);
        return RunToFinalOutput(ctrl_, MaxScans(step.timeoutMs), [](CommandOutcome&) {});
    }

    // Raises Execute, scans until Done or Error (at most maxScans), takes the outputs of that scan,
    // then drops Execute for one scan (PLCopen: Done / Error clear in the scan that sees it fall).
    template <class Fb, class TakeMore>
    CommandOutcome RunToFinalOutput(pac::FbInstance<Fb>& fb, std::int64_t maxScans, TakeMore takeMore) {
        fb->EXECUTE.value = TRUE;
        CommandOutcome outcome;
        Scan();
        outcome.edgeScan = plc_.Task().ScanCount();
        outcome.edgeTime = plc_.Now();
        auto finished = [&fb] { return fb->DONE.value || fb->ERROR.value; };
        for (std::int64_t scans = 0; !finished() && scans < maxScans; ++scans) Scan();
        outcome.finished = finished();
        outcome.done = fb->DONE.value != 0;
        outcome.error = fb->ERROR.value != 0;
        outcome.errorId = static_cast<std::uint16_t>(fb->ERRORID.value);
        takeMore(outcome);
        outcome.endScan = plc_.Task().ScanCount();
        outcome.endTime = plc_.Now();
        fb->EXECUTE.value = FALSE;
        Scan();
        return outcome;
    }

    // An axis has ended its part of the step: its job's final output, its axis error reset, or Enabled
    // following Enable.
    bool AxisFinished(const AxisJob& job) {
        if (mc_) return mc_->Finished(job);
        auto& fb = axes_[static_cast<std::size_t>(job.axis - 1)];
        if (job.HasJob()) return fb->DONE.value || fb->ERROR.value || fb->COMMANDABORTED.value;
        if (job.resetError) return !fb->AXISERROR.value;
        return (fb->ENABLED.value != 0) == job.enable.value_or(false);
    }

    std::vector<AxisOutcome> RunAxes(const AxesStep& step) {
        for (const auto& job : step.jobs) {
            if (mc_) {
                mc_->Begin(job);
                continue;
            }
            auto& fb = axes_[static_cast<std::size_t>(job.axis - 1)];
            if (job.enable) fb->ENABLE.value = *job.enable ? TRUE : FALSE;
            if (job.resetError) fb->RESETERROR.value = TRUE;
            if (!job.HasJob()) continue;
            fb->COMMAND.value = Enumerator<E_PAC_AXISCOMMAND>(E_PAC_AXISCOMMAND__NAMES, job.command);
            fb->POSITION.value = static_cast<float>(job.position);
            fb->VELOCITY.value = static_cast<UINT>(job.velocity);
            fb->ACCELERATION.value = static_cast<UINT>(job.acceleration);
            fb->CONDITION.value = Enumerator<E_PAC_MOVECONDITION>(E_PAC_MOVECONDITION__NAMES, job.condition);
            fb->TIMEOUT.value = ToTime(job.timeoutMs);
            fb->EXECUTE.value = TRUE;
        }
        Scan();
        const std::int64_t edgeScan = plc_.Task().ScanCount();
        std::vector<AxisOutcome> outcomes(step.jobs.size());
        std::vector<std::int64_t> limits;
        for (std::size_t i = 0; i < step.jobs.size(); ++i) {
            outcomes[i].axis = step.jobs[i].axis;
            outcomes[i].hasJob = step.jobs[i].HasJob();
            outcomes[i].edgeScan = edgeScan;
            limits.push_back(edgeScan + step.jobs[i].maxMs / scenario_.timing.plcCycleMs + 1);
        }
        // Every axis's outputs are taken in the scan its part ends; the step ends when all have.
        for (;;) {
            bool open = false;
            for (std::size_t i = 0; i < step.jobs.size(); ++i) {
                AxisOutcome& outcome = outcomes[i];
                if (outcome.endScan != 0) continue;
                const bool ended = AxisFinished(step.jobs[i]);
                if (ended || plc_.Task().ScanCount() >= limits[i]) {
                    Take(step.jobs[i].axis, ended, outcome);
                } else {
                    open = true;
                }
            }
            if (!open) break;
            Scan();
        }
        for (const auto& job : step.jobs) {
            if (mc_) mc_->End(job);
            auto& fb = axes_[static_cast<std::size_t>(job.axis - 1)];
            fb->EXECUTE.value = FALSE;
            fb->RESETERROR.value = FALSE;
        }
        Scan();
        return outcomes;
    }

    void Take(int axis, bool finished, AxisOutcome& outcome) {
        auto& fb = axes_[static_cast<std::size_t>(axis - 1)];
        outcome.finished = finished;
        outcome.done = fb->DONE.value != 0;
        outcome.error = fb->ERROR.value != 0;
        outcome.aborted = fb->COMMANDABORTED.value != 0;
        outcome.errorId = static_cast<std::uint16_t>(fb->ERRORID.value);
        outcome.enabled = fb->ENABLED.value != 0;
        outcome.referenced = fb->REFERENCED.value != 0;
        outcome.position = fb->ACTUALPOSITION.value;
        if (mc_) mc_->Take(axis, outcome);
        outcome.endScan = plc_.Task().ScanCount();
        outcome.endTime = plc_.Now();
    }

    // What module k's FB_PAC_AutomaticModule has received, against what it should have.
    std::vector<std::string> AutomaticMismatches(const AutomaticValues& values) {
        const auto& fb = automatic_[static_cast<std::size_t>(values.module - 1)];
        const AutomaticExpectation& e = values.expect;
        std::vector<std::string> failures;
        const std::string module = "module " + std::to_string(values.module) + ": ";
        if (e.flagWord && fb->RECEIVEDFLAGWORD.value != *e.flagWord) {
            failures.push_back(module + "flag word " + std::to_string(fb->RECEIVEDFLAGWORD.value) + ", expected " +
                               std::to_string(*e.flagWord));
        }
        if (e.n && fb->RECEIVEDINTREGISTER.value != *e.n) {
            failures.push_back(module + "N " + std::to_string(fb->RECEIVEDINTREGISTER.value) + ", expected " +
                               std::to_string(*e.n));
        }
        if (e.r && !(std::fabs(fb->RECEIVEDREALREGISTER.value - *e.r) <= e.rTolerance)) {
            failures.push_back(module + "R " + std::to_string(fb->RECEIVEDREALREGISTER.value) + ", expected " +
                               std::to_string(*e.r));
        }
        return failures;
    }

    std::vector<std::string> RunAutomatic(const AutomaticStep& step) {
        for (const auto& values : step.modules) {
            auto& fb = automatic_[static_cast<std::size_t>(values.module - 1)];
            if (values.flagWord) fb->FLAGWORD.value = *values.flagWord;
            if (values.n) fb->INTREGISTER.value = *values.n;
            if (values.r) fb->REALREGISTER.value = static_cast<float>(*values.r);
        }
        auto mismatches = [this, &step] {
            std::vector<std::string> all;
            for (const auto& values : step.modules) {
                for (auto& failure : AutomaticMismatches(values)) all.push_back(std::move(failure));
            }
            return all;
        };
        Scan();
        const std::int64_t limit = plc_.Task().ScanCount() + step.maxMs / scenario_.timing.plcCycleMs + 1;
        while (!mismatches().empty() && plc_.Task().ScanCount() < limit) Scan();
        return mismatches();
    }

    void Wait(const WaitStep& wait) {
        const int cycle = scenario_.timing.plcCycleMs;
        for (int scans = (wait.ms + cycle - 1) / cycle; scans > 0; --scans) Scan();
    }

    const Scenario& scenario_;
    RunObserver& observer_;
    RemoteController* remote_;
    // The FBs come before plc_, whose programs refer to them.
    pac::FbInstance<FB_PAC_CMD> cmd_ = PAC_FB(FB_PAC_CMD);
    pac::FbInstance<FB_PAC_CTRL> ctrl_ = PAC_FB(FB_PAC_CTRL);
    std::vector<pac::FbInstance<FB_PAC_AXIS>> axes_;  // never resized: plc_ holds references
    std::vector<pac::FbInstance<FB_PAC_AUTOMATICMODULE>> automatic_;  // on the same modules; never resized
    std::unique_ptr<McAxes> mc_;  // with Modules::mcBlocks, in place of axes_ (made once plc_ is)
    pac::FbInstance<FB_PAC_DIAGNOSIS> diag_ = PAC_FB(FB_PAC_DIAGNOSIS);  // with Modules::diagnosis
    pac::PacRig plc_;
};

}  // namespace

std::size_t RunReport::Commands() const {
    std::size_t commands = 0;
    for (const auto& step : steps) commands += step.outcome ? 1 : 0;
    return commands;
}

std::size_t RunReport::Requests() const {
    std::size_t requests = 0;
    for (const auto& step : steps) requests += step.request ? 1 : 0;
    return requests;
}

std::size_t RunReport::AxisJobs() const {
    std::size_t jobs = 0;
    for (const auto& step : steps) {
        for (const auto& axis : step.axes) jobs += axis.hasJob ? 1 : 0;
    }
    return jobs;
}

std::vector<std::size_t> RunReport::FailedSteps() const {
    std::vector<std::size_t> failed;
    for (const auto& step : steps) {
        if (!step.Passed()) failed.push_back(step.index);
    }
    return failed;
}

RunReport ScenarioRunner::Run(RunObserver& observer) const {
    Session session(scenario_, observer, remote_);  // refuses a controller setup the simulator rejects, before any output
    observer.OnStart(scenario_);
    RunReport report;
    for (std::size_t i = 0; i < scenario_.steps.size(); ++i) {
        // Steps start between scans: at the time of the last scan (0 before the first).
        observer.OnStepStart(i, scenario_.steps[i], session.Now());
        report.steps.push_back(session.Run(i, scenario_.steps[i]));
        observer.OnStepEnd(report.steps.back());
    }
    report.history = session.History(report.handshakes);
    observer.OnEnd(report);
    return report;
}

RunReport ScenarioRunner::Run() const {
    RunObserver silent;
    return Run(silent);
}

}  // namespace pac::scenario
