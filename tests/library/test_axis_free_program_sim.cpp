// FB_PAC_Axis in a PLC program freer than the other axis suites' (docs/fb/FB_PAC_Axis.md, "Calling contract"):
// the program calls the FB or leaves it out in every scan (runs of 1 to 6 scans), at every point of a job
// (waiting for the axis to be free, Start on the wire waiting for the take-over, the job running, stopping),
// edges absolute and relative moves, G29 and reference runs with values no other job used, holds a jog input
// (JogPositive / JogNegative, its longest distance of its own) as it would hold Execute, lets Execute or the jog
// input fall while the job runs, aborts for a few scans now and then, and pulses ResetError and ChangeDynamics
// (with new values) now and then in the scans it calls the FB, and every 1,000 to 2,500 scans ends ONLINE
// (CANCEL, HOME POSITION for 20 to 60 ms, START ONLINE) with ResetError pressed in every other call until it sees
// ONLINE end. The simulated PA-CONTROL's ledger of the jobs its axis module took over on a Start edge
// (AxisModule::TakenJobs) is the record of what it executed. The property, in a PLC programmer's words: the FB
// ends Done only if the controller took exactly its job (the traverse bit, the position and the per-mille values)
// after this Execute (or jog input) edge, an absolute move Done stands at its target, and Busy ends within the
// bound the FB's page states; a change of dynamics the FB reports (DynamicsChanged) is in force on the controller
// a round trip later while it still runs that job, and the axis type changes its speed while traversing; bit 16
// (reset axis error) goes out only while the last status the FB was given is ONLINE. The PLCopen rules hold on
// every call. Every random choice comes from the seed in the test's name.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bus_timing.hpp"
#include "free_caller.hpp"
#include "gvl_constants.hpp"
#include "pac/axis_module_bits.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/pac_rig.hpp"
#include "pac/sim/axis_module.hpp"
#include "pac/sim/pa_control.hpp"
#include "plcopen_pins.hpp"
#include "real_bits.hpp"
#include "rig_timing.hpp"

namespace test_axis_free_program_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using pac::test::FreeCaller;

struct AxisFreeCase {
    pac::test::BusTiming timing;
    pac::sim::ActiveForJobs activeFor = pac::sim::ActiveForJobs::kEveryJob;
    pac::sim::CmdErrorRestart cmdErrorRestart = pac::sim::CmdErrorRestart::kSameCycle;
    std::uint64_t seed = 1;
};

std::string AxisFreeCaseName(const ::testing::TestParamInfo<AxisFreeCase>& info) {
    const ::testing::TestParamInfo<pac::test::BusTiming> timing(info.param.timing, info.index);
    return pac::test::BusTimingName(timing) +
           (info.param.activeFor == pac::sim::ActiveForJobs::kEveryJob ? "_ActiveEveryJob" : "_ActiveTraversing") +
           (info.param.cmdErrorRestart == pac::sim::CmdErrorRestart::kSameCycle ? "_ErrorSameCycle" : "_ErrorNextCycle") +
           "_Seed" + std::to_string(info.param.seed);
}

void PrintTo(const AxisFreeCase& c, std::ostream* out) {
    *out << pac::test::Describe(c.timing) << "; seed " << c.seed;
}

struct Job {
    E_PAC_AXISCOMMAND command = E_PAC_AXISCOMMAND__PAC_AX_NONE;
    float position = 0.0F;
    unsigned velocity = 1000;
    unsigned acceleration = 1000;
    int jog = 0;  // +1 / -1: a jog held by JogPositive / JogNegative instead of Execute; Position its longest distance
};

std::uint32_t TraverseBit(const Job& job) {
    namespace bit = pac::axis_control;
    if (job.jog != 0) return job.jog > 0 ? bit::kJogPositive : bit::kJogNegative;
    switch (job.command) {
        case E_PAC_AXISCOMMAND__PAC_AX_HOME: return bit::kHome;
        case E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE: return bit::kMoveAbsolute;
        case E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE: return bit::kMoveRelative;
        case E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION: return bit::kSetPosition;
        default: return bit::kClearOffset;
    }
}

bool IsMove(E_PAC_AXISCOMMAND c) {
    return c == E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE || c == E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE;
}

bool HasPosition(E_PAC_AXISCOMMAND c) { return IsMove(c) || c == E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION; }

bool IsMove(const Job& job) { return job.jog != 0 || IsMove(job.command); }
bool HasPosition(const Job& job) { return job.jog != 0 || HasPosition(job.command); }

class FreeAxisProgram {
public:
    explicit FreeAxisProgram(const AxisFreeCase& c)
        : case_(c),
          layout_{true, 1},
          rig_(pac::test::RigTimingOf(c.timing), ConfigOf(c), layout_),
          random_(c.seed),
          errorRandom_(c.seed + 1000),
          modeRandom_(c.seed + 2000),
          caller_("FB_PAC_Axis", random_, Odds(), log_) {
        auto& pac = rig_.Controller();
        EXPECT_EQ(pac.SystemParameters().Set(pac::sim::sysparam::kStopInput, kExternalStopInput),
                  pac::sim::ParameterTable::SetResult::kOk);
        pac.Io().inputs.Set(kExternalStopInput, true);
        rig_.CallCtrl(ctrl_);
        rig_.CallImage([this](const pac::sim::ProcessImage& fromPac, pac::sim::ProcessImage& toPac) {
            Program(fromPac, toPac);
        });
        rig_.Start();
        axis_->ENABLE.value = TRUE;
    }

    // ONLINE through FB_PAC_Ctrl, the axis FB called in every scan; then (`free`) the free program.
    void Prepare(bool free = true) {
        ASSERT_GT(rig_.ScanUntil([this] { return ctrl_->READY.value != 0; }, 20000), 0) << "Ready";
        Scan(case_.timing.ScansFor(20ms));
        ctrl_->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
        ctrl_->EXECUTE.value = TRUE;
        ASSERT_GT(rig_.ScanUntil([this] { return ctrl_->DONE.value || ctrl_->ERROR.value; }, 20000), 0);
        ASSERT_TRUE(ctrl_->DONE.value) << "START_ONLINE: ErrorID 16#" << std::hex << ctrl_->ERRORID.value;
        ctrl_->EXECUTE.value = FALSE;
        Scan(case_.timing.ScansFor(30ms));
        ASSERT_EQ(rig_.Controller().OperatingStatus(), 31);
        free_ = free;
    }

    // A named case: `job`, its calls from `from` to `from + length - 1` scans after the edge left out (Execute
    // falling in the first of them with `fall`); how it ended, once the FB was called idle again.
    FreeCaller::Ended RunScripted(const Job& job, int from, int length, bool fall) {
        scripted_ = true;
        scriptedJob_ = job;
        caller_.Script(from, length, fall);
        for (int i = 0; i < 100000 && !caller_.ScriptOver(); ++i) Scan();
        caller_.EndScript();
        scripted_ = false;
        return caller_.LastEnded();
    }

    // The program stops calling the FB `after` scans after the edge of `job`: the job runs to its end on the
    // controller without it (docs/fb/FB_PAC_Axis.md, "The FB never called again").
    void Abandon(const Job& job, int after) {
        scripted_ = true;
        scriptedJob_ = job;
        caller_.Script(after, 1000000, false);
    }
    pac::sim::PaControl& Controller() { return rig_.Controller(); }
    // ResetError TRUE in the next call only (a press of the program's reset key).
    void PressResetError() { pressReset_ = true; }
    std::chrono::nanoseconds Now() const { return rig_.Now(); }
    std::size_t JobsTaken() { return Ledger().size(); }
    // Outside the free program (Prepare(false)): the job the next calls carry, Execute, and whether the program
    // leaves the FB out of its scans.
    void Drive(const Job& job, bool execute) {
        job_ = job;
        axis_->EXECUTE.value = execute ? TRUE : FALSE;
    }
    void LeaveOut(bool out) { leftOut_ = out; }
    // The next call is given operating status 0 (a blip: the CMD reply not valid in that scan).
    void BlankOpStatus() { blankOpStatus_ = true; }
    // Outside the free program: Abort in the calls from now on.
    void HoldAbort(bool abort) { abortLeft_ = abort ? 1 : 0; }
    pac::FbInstance<FB_PAC_AXIS>& Axis() { return axis_; }
    // ACTIVE in the axis module the program read in its last scan, whether it called the FB or not.
    bool ActiveOnBus() const { return activeOnBus_; }
    std::uint32_t ControlOnBus() const {
        return pac::sim::ReadDword(rig_.ToPac().Module12(layout_.AxisOffset(1)), 0);
    }

    void Scan(int n = 1) {
        for (int i = 0; i < n; ++i) {
            blips_.BeforeScan(rig_.Controller(), random_, free_ && !scripted_);  // outside the named cases
            FollowMode();
            // An axis error now and then (1 in 200 scans, drawn apart from the program's choices) between jobs,
            // outside the named cases, once the last one is gone for the FB too and a pulse for it is over.
            if (free_ && !scripted_ && mode_ == Mode::kOnline && !faulted_ &&
                !rig_.Controller().Axes().Motion(1).Fault() && !axis_->AXISERROR.value && !axis_->BUSY.value &&
                rig_.Now() - clearedAt_ > PulseBound() &&
                std::uniform_int_distribution<int>(0, 199)(errorRandom_) == 0) {
                rig_.Controller().Axes().RaiseAxisError(1, rig_.Now(), pac::sim::axis_error::kFollowingError);
                raisedAt_ = rig_.Now();
                ++axisErrors_;
            }
            rig_.Scan();
            ++scans_;
        }
    }

    const std::vector<std::string>& Violations() const { return log_.Texts(); }
    int Dones() const { return dones_; }
    int DoneMoves() const { return doneMoves_; }
    int DoneJogs() const { return doneJogs_; }
    int Aborts() const { return aborts_; }
    int DynamicsChanges() const { return dynamicsChanges_; }
    int AxisErrorsReset() const { return resets_; }
    int AxisErrors() const { return axisErrors_; }
    int EndedAfterSkip() const { return endedAfterSkip_; }
    int OnlineEnds() const { return onlineEnds_; }
    int ResetsAtOnlineEnd() const { return resetsAtOnlineEnd_; }
    const FreeCaller& Caller() const { return caller_; }

private:
    // The controller's mode as the program drives it (FollowMode).
    enum class Mode { kOnline, kPressing, kCancelling, kHome, kStarting };
    static constexpr int kExternalStopInput = 1;
    static constexpr std::size_t kOpStatusByte = 5;  // of the CMD reply (2.4.2)

    static pac::test::FreeCallerOdds Odds() {
        pac::test::FreeCallerOdds odds;
        odds.newCommand = 8;
        odds.earlyFall = 200;
        return odds;
    }

    static pac::sim::PaControlConfig ConfigOf(const AxisFreeCase& c) {
        pac::sim::PaControlConfig config;
        config.axisModule.activeFor = c.activeFor;
        config.axisModule.cmdErrorRestart = c.cmdErrorRestart;
        config.axisModule.speedChange = pac::sim::SpeedChange::kWhileTraversing;  // DynamicsChangeable TRUE
        return config;
    }

    // A job with values no other job used: the ledger tells whose job the controller took.
    Job NextJob() {
        ++serial_;
        const float unique = static_cast<float>(serial_ % 64) * 0.0625F;
        Job job;
        job.velocity = 250 + caller_.Draw(751);
        job.acceleration = 500 + caller_.Draw(501);
        switch (caller_.Draw(12)) {
            case 0: case 1: case 2: case 3:
                job.command = E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE;
                job.position = 10.0F + static_cast<float>(caller_.Draw(60)) + unique;
                break;
            case 4: case 5:
                job.command = E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE;
                job.position = (caller_.Draw(2) == 0 ? -1.0F : 1.0F) * (2.0F + static_cast<float>(caller_.Draw(8)) + unique);
                break;
            case 6: case 7:
                job.command = E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION;
                job.position = 30.0F + static_cast<float>(caller_.Draw(20)) + unique;
                break;
            case 8:
                job.command = E_PAC_AXISCOMMAND__PAC_AX_CLEAR_OFFSET;
                break;
            case 10: case 11:
                job.jog = caller_.Draw(2) == 0 ? -1 : 1;
                job.position = 2.0F + static_cast<float>(caller_.Draw(8)) + unique;
                break;
            default:
                job.command = E_PAC_AXISCOMMAND__PAC_AX_HOME;
                break;
        }
        return job;
    }

    void Program(const pac::sim::ProcessImage& fromPac, pac::sim::ProcessImage& toPac) {
        if (free_) WatchAxisError();
        const std::uint32_t status = pac::sim::ReadDword(fromPac.Module12(layout_.AxisOffset(1)), 0);
        activeOnBus_ = (status & pac::axis_status::kActive) != 0;
        const bool called = !free_ || caller_.Plan(scans_, rig_.Now());
        if (free_ && caller_.NewCommand()) job_ = scripted_ ? scriptedJob_ : NextJob();
        if (free_ && !scripted_) {
            if (abortLeft_ > 0) {
                --abortLeft_;
            } else if (caller_.Draw(400) == 0) {
                abortLeft_ = 1 + static_cast<int>(caller_.Draw(4));  // Abort held for 1 to 4 scans of the program
                ++aborts_;
            }
        }
        if (!called) {
            missed_ = true;
            return;
        }
        // Pulses the program gives in some calls, whatever the job: an axis error reset, new dynamics.
        // Presses in every other call from the CANCEL until the FB sees ONLINE end: each edge after a pulse waits
        // for bit 16 to have been low for the update time, so one is mostly held back when ONLINE ends.
        const bool burst = burst_ && (burstCalls_++ % 2 == 0);
        const bool resetError = (free_ && !scripted_ && caller_.Draw(150) < 3) || (called && pressReset_) || burst;
        if (called) pressReset_ = false;
        const int knownBefore = fbKnown_;
        if (fromPac[kOpStatusByte] != 0) fbKnown_ = fromPac[kOpStatusByte];
        if (!Online(fbKnown_)) burst_ = false;
        // New dynamics only for a job on its way (a call that edges a job latches its pins as the job's), as a pulse:
        // FALSE in the call before.
        const bool changeDynamics = free_ && !scripted_ && axis_->BUSY.value && !axis_->CHANGEDYNAMICS.value &&
                                    caller_.Draw(100) < 3;
        const std::size_t offset = layout_.AxisOffset(1);
        CheckDynamicsChange();
        if (changeDynamics) {
            change_ = {250 + caller_.Draw(751), 500 + caller_.Draw(501)};
        } else if (abortLeft_ > 0) {
            change_.reset();  // the job stops: the change need not be in force
        }
        auto call = [&] {
            axis_->ABORT.value = abortLeft_ > 0 ? TRUE : FALSE;
            const bool held = axis_->EXECUTE.value != 0;
            axis_->EXECUTE.value = held && job_.jog == 0 ? TRUE : FALSE;
            axis_->JOGPOSITIVE.value = held && job_.jog > 0 ? TRUE : FALSE;
            axis_->JOGNEGATIVE.value = held && job_.jog < 0 ? TRUE : FALSE;
            axis_->RESETERROR.value = resetError ? TRUE : FALSE;
            axis_->CHANGEDYNAMICS.value = changeDynamics ? TRUE : FALSE;
            axis_->DYNAMICSCHANGEABLE.value = TRUE;
            axis_->COMMAND.value = job_.command;
            axis_->POSITION.value = job_.position;
            axis_->VELOCITY.value = static_cast<UINT>(changeDynamics ? change_->velocity : job_.velocity);
            axis_->ACCELERATION.value = static_cast<UINT>(changeDynamics ? change_->acceleration : job_.acceleration);
            axis_->INTEGERMODE.value = ctrl_->INTEGERMODEACTIVE.value;
            axis_->MODECHANGE.value = ctrl_->MODECHANGE.value;
            axis_->OPSTATUS.value = blankOpStatus_ ? 0 : fromPac[kOpStatusByte];
            blankOpStatus_ = false;
            for (std::size_t i = 0; i < 12; ++i) {
                axis_->FROMPAC.value.table[i] = fromPac[offset + i];
                axis_->TOPAC.value.table[i] = toPac[offset + i];
            }
            axis_();
            for (std::size_t i = 0; i < 12; ++i) toPac[offset + i] = axis_->TOPAC.value.table[i];
        };
        if (!free_) {
            if (!leftOut_) call();
            return;
        }
        const auto ended = pac::test::CallFree(caller_, axis_, BusyBound(), call, [this] {
            ledgerAtEdge_ = Ledger().size();
            missed_ = false;
            change_.reset();
        });
        CheckResetBit(toPac, knownBefore, resetError);
        if (resetError) {
            resetAskedAt_ = rig_.Now();
            // A pulse the FB gives: it sees the error, in ONLINE.
            if (axis_->AXISERROR.value && fromPac[kOpStatusByte] == 31 && !resetDue_) resetDue_ = rig_.Now();
        }
        if (changeDynamics && axis_->DYNAMICSCHANGED.value) {
            change_->at = rig_.Now();
            change_->jobs = Ledger().size();
            ++dynamicsChanges_;
        } else if (changeDynamics || !axis_->RUNNING.value) {
            change_.reset();  // refused, or the job no longer runs as the FB sees it
        }
        if (ended == FreeCaller::Ended::kNo) return;
        if (missed_) ++endedAfterSkip_;
        if (ended == FreeCaller::Ended::kDone) CheckDone();
    }

    const pac::sim::TakenAxisJobLedger& Ledger() { return rig_.Controller().Module(1).TakenJobs(); }

    static bool Online(int status) { return status >= 30 && status <= 39; }

    // Every 1,000 to 2,500 scans of the free program (no axis error showing) ONLINE ends, whatever the job:
    // ResetError pressed in every other call from 4 scans before a CANCEL through FB_PAC_Ctrl until the FB sees it,
    // 20 to 60 ms in HOME POSITION, then START ONLINE again.
    void FollowMode() {
        if (!free_ || scripted_) return;
        const bool over = ctrl_->DONE.value || ctrl_->ERROR.value;
        switch (mode_) {
            case Mode::kOnline:
                if (++freeScans_ < nextOnlineEnd_ || faulted_ || axis_->AXISERROR.value) return;
                nextOnlineEnd_ += std::uniform_int_distribution<long>(1000, 2500)(modeRandom_);
                burst_ = true;
                burstCalls_ = 0;
                pressScans_ = 4;
                mode_ = Mode::kPressing;
                ++onlineEnds_;
                return;
            case Mode::kPressing:
                if (--pressScans_ == 0) Request(E_PAC_CTRLREQUEST__PAC_REQ_CANCEL, Mode::kCancelling);
                return;
            case Mode::kCancelling:
            case Mode::kStarting:
                if (retry_) {
                    retry_ = false;
                    ctrl_->EXECUTE.value = TRUE;
                    return;
                }
                if (!over) return;
                ctrl_->EXECUTE.value = FALSE;
                if (!ctrl_->DONE.value) {  // a status-0 blip ends or refuses it (16#8004, 16#8003): again
                    retry_ = true;
                    return;
                }
                homeUntil_ = rig_.Now() +
                             std::chrono::milliseconds(20 + std::uniform_int_distribution<int>(0, 40)(modeRandom_));
                mode_ = mode_ == Mode::kCancelling ? Mode::kHome : Mode::kOnline;
                return;
            case Mode::kHome:
                if (rig_.Now() >= homeUntil_) Request(E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE, Mode::kStarting);
                return;
        }
    }
    void Request(E_PAC_CTRLREQUEST request, Mode next) {
        ctrl_->REQUEST.value = request;
        ctrl_->EXECUTE.value = TRUE;
        mode_ = next;
    }

    // Bit 16 (reset axis error) only while the last status other than 0 the FB was given is ONLINE: outside it the
    // PA-CONTROL acts on no control word, and on the AUTOMATIC layout FW2_N4 bit 16 is flag M1 (issue 32, item 8).
    // Counted when ONLINE ends for the FB with the pulse on or an edge it saw in ONLINE not yet on the wire.
    void CheckResetBit(const pac::sim::ProcessImage& toPac, int knownBefore, bool resetError) {
        const std::size_t offset = layout_.AxisOffset(1);
        const bool onWire = (pac::sim::ReadDword(toPac.Module12(offset), 0) & pac::axis_control::kResetAxisError) != 0;
        if (onWire && !Online(fbKnown_)) {
            log_.Add(scans_, rig_.Now(), "bit 16 (reset axis error) on the wire in status " + std::to_string(fbKnown_));
        }
        if (Online(knownBefore) && !Online(fbKnown_) && (pulseOn_ || edgeWaiting_)) ++resetsAtOnlineEnd_;
        if (resetError && !lastReset_ && Online(fbKnown_)) edgeWaiting_ = true;
        if ((onWire && !pulseOn_) || !Online(fbKnown_)) edgeWaiting_ = false;
        pulseOn_ = onWire;
        lastReset_ = resetError;
    }

    // The controller's axis error: cleared only after a ResetError pulse of the program since it came, and within
    // the pulse's bound (Timeout, the update time, the longest skip, a round trip) after a pulse the FB gave in
    // ONLINE while it showed the error, unless the controller left ONLINE meanwhile (a blip ends the pulse).
    void WatchAxisError() {
        const bool fault = rig_.Controller().Axes().Motion(1).Fault();
        if (faulted_ && !fault) {
            ++resets_;
            clearedAt_ = rig_.Now();
            // A pulse asked for just before the error came may reach the controller after it.
            if (resetAskedAt_ < raisedAt_ - PulseBound()) log_.Add(scans_, rig_.Now(), "the controller cleared the axis error, but the program gave no ResetError since it came");
            resetDue_.reset();
        }
        faulted_ = fault;
        if (rig_.Controller().OperatingStatus() != 31 || !fault) resetDue_.reset();
        if (resetDue_ && rig_.Now() - *resetDue_ > 1s + PulseBound()) {
            log_.Add(scans_, rig_.Now(), "the axis error is still there " +
                                             std::to_string((rig_.Now() - *resetDue_) / std::chrono::milliseconds(1)) +
                                             " ms after a ResetError pulse in ONLINE");
            resetDue_.reset();
        }
    }

    // From a ResetError call to the pulse on the controller: the update time, the longest skip, a round trip.
    std::chrono::nanoseconds PulseBound() const { return 10ms + 7 * case_.timing.PlcCycle() + RoundTrip(); }

    // A round trip after DynamicsChanged, the controller runs the same job (no job taken since) with the new
    // values, unless it has ended it meanwhile.
    void CheckDynamicsChange() {
        if (!change_ || change_->jobs == 0 || rig_.Now() - change_->at <= RoundTrip()) return;
        const auto& module = rig_.Controller().Module(1);
        if (Ledger().size() == change_->jobs && module.JobRunning() &&
            (module.SpeedPerMille() != change_->velocity || module.AccelerationPerMille() != change_->acceleration)) {
            log_.Add(scans_, rig_.Now(), "DynamicsChanged to " + std::to_string(change_->velocity) + "/" +
                                             std::to_string(change_->acceleration) + " per mille, but the controller runs the job at " +
                                             std::to_string(module.SpeedPerMille()) + "/" + std::to_string(module.AccelerationPerMille()));
        }
        change_.reset();
    }

    std::chrono::nanoseconds RoundTrip() const {
        return 3 * case_.timing.PlcCycle() + 2 * case_.timing.PacCycle() + 2 * case_.timing.Latency() + 5ms;
    }

    void CheckDone() {
        const std::uint32_t bit = TraverseBit(job_);
        const bool taken = claims_.Claim(Ledger(), ledgerAtEdge_, [&](const pac::sim::AxisModuleCommand& taken) {
            if ((taken.control & pac::axis_control::kTraverseBits) != bit) return false;
            if (HasPosition(job_) && taken.position != pac::test::BitsOf(job_.position)) return false;
            return !IsMove(job_) ||
                   (taken.speedPerMille == job_.velocity && taken.accelerationPerMille == job_.acceleration);
        });
        if (taken) {
            ++dones_;
            if (job_.jog != 0) ++doneJogs_;
            if (job_.jog == 0 && job_.command == E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE) {
                ++doneMoves_;
                if (std::fabs(axis_->ACTUALPOSITION.value - job_.position) > 0.01F) {
                    log_.Add(scans_, rig_.Now(), "an absolute move to " + std::to_string(job_.position) +
                                                     " ended Done at " + std::to_string(axis_->ACTUALPOSITION.value));
                }
            }
            return;
        }
        std::ostringstream what;
        what << "Done for job " << job_.command << (job_.jog != 0 ? " (jog)" : "") << " (bit 16#" << std::hex << bit << std::dec << ", position "
             << job_.position << ", " << job_.velocity << "/" << job_.acceleration
             << " per mille), which the controller did not take over after the Execute edge";
        log_.Add(scans_, rig_.Now(), what.str());
    }

    // docs/fb/FB_PAC_Axis.md: Timeout for the axis to be free, the take-over bound, the job itself (a reference
    // run or a move of at most 80 units at a quarter of 1000 units/s), StopTimeout for a stop, and the longest
    // skip plus a round trip.
    std::chrono::nanoseconds BusyBound() const {
        return 1s + 1s + 2s + 10s + 7 * case_.timing.PlcCycle() + 2 * case_.timing.PacCycle() + 100ms;
    }

    AxisFreeCase case_;
    pac::sim::ModuleLayout layout_;
    pac::PacRig rig_;
    std::mt19937_64 random_;
    std::mt19937_64 errorRandom_;
    std::mt19937_64 modeRandom_;  // when ONLINE ends, how long HOME POSITION lasts
    pac::test::ViolationLog log_;
    FreeCaller caller_;
    pac::FbInstance<FB_PAC_CTRL> ctrl_ = PAC_FB(FB_PAC_CTRL);
    pac::FbInstance<FB_PAC_AXIS> axis_ = PAC_FB(FB_PAC_AXIS);
    bool free_ = false;
    bool leftOut_ = false;  // outside the free program: the FB is not called
    bool blankOpStatus_ = false;
    bool activeOnBus_ = false;
    pac::test::StatusBlips blips_;
    bool scripted_ = false;
    Job scriptedJob_;
    Job job_;
    int serial_ = 0;
    int abortLeft_ = 0;
    bool missed_ = false;  // a scan without the call since the edge
    long scans_ = 0;
    std::size_t ledgerAtEdge_ = 0;
    pac::test::AxisJobClaims claims_;
    int dones_ = 0;
    int doneMoves_ = 0;
    int doneJogs_ = 0;
    int aborts_ = 0;
    int endedAfterSkip_ = 0;
    // A change of dynamics the FB reported, until checked: the values, when, the ledger's size then (0: not yet).
    struct Change {
        unsigned velocity = 0;
        unsigned acceleration = 0;
        std::chrono::nanoseconds at{0};
        std::size_t jobs = 0;
    };
    std::optional<Change> change_;
    int dynamicsChanges_ = 0;
    bool pressReset_ = false;
    bool faulted_ = false;       // the controller's axis had an error at the last look
    std::chrono::nanoseconds raisedAt_{0};      // the last axis error raised
    std::chrono::nanoseconds clearedAt_{0};     // and cleared
    std::chrono::nanoseconds resetAskedAt_{0};  // the last call with ResetError
    std::optional<std::chrono::nanoseconds> resetDue_;  // a pulse the FB gave for the error it showed
    int axisErrors_ = 0;
    int resets_ = 0;
    Mode mode_ = Mode::kOnline;
    std::chrono::nanoseconds homeUntil_{0};
    long freeScans_ = 0;
    long nextOnlineEnd_ = 1000;
    int pressScans_ = 0;  // the presses begin these scans before the CANCEL
    bool retry_ = false;  // FB_PAC_Ctrl's request edged again in the next scan
    bool burst_ = false;
    unsigned burstCalls_ = 0;
    int fbKnown_ = 31;  // the last status other than 0 the FB was given in a call
    bool pulseOn_ = false;
    bool lastReset_ = false;   // ResetError in the last call
    bool edgeWaiting_ = false;  // an edge the FB saw in ONLINE, its pulse not yet on the wire
    int onlineEnds_ = 0;
    int resetsAtOnlineEnd_ = 0;
};

class AxisFreeProgram : public ::testing::TestWithParam<AxisFreeCase> {};

TEST_P(AxisFreeProgram, DoneOnlyForTheJobTheControllerTookOver) {
    FreeAxisProgram program(GetParam());
    program.Prepare();
    ASSERT_FALSE(HasFatalFailure());
    program.Scan(5000);
    for (const std::string& v : program.Violations()) ADD_FAILURE() << v;
    // Reachability: skips while a job was on its way, jobs ended after a skip, moves Done, aborts.
    EXPECT_GT(program.Caller().SkipsWhileBusy(), 10);
    EXPECT_GT(program.EndedAfterSkip(), 3);
    EXPECT_GT(program.DoneMoves(), 2) << program.Dones() << " Done";
    EXPECT_GT(program.DoneJogs(), 0) << program.Dones() << " Done";
    EXPECT_GT(program.Aborts(), 0);
    EXPECT_GT(program.DynamicsChanges(), 0);
    EXPECT_GT(program.AxisErrorsReset(), 0) << program.AxisErrors() << " axis errors raised";
    EXPECT_GT(program.OnlineEnds(), 0);
    EXPECT_GT(program.ResetsAtOnlineEnd(), 0) << program.OnlineEnds() << " times ONLINE ended";
}

// The named cases: an absolute move, its calls left out for 1 to 6 scans from 1 to 14 scans after its edge
// (Start on the wire, the take-over, the move, its end), with Execute held or falling in the first scan left out.
// The move ends Done for its own job (the checks of the free program), for one call only if Execute fell.
class AxisSkippedCalls : public ::testing::TestWithParam<AxisFreeCase> {};

TEST_P(AxisSkippedCalls, AMoveEndsDoneForItsOwnJobWhateverScansItMisses) {
    FreeAxisProgram program(GetParam());
    program.Prepare();
    ASSERT_FALSE(HasFatalFailure());
    int serial = 0;
    for (const bool fall : {false, true}) {
        for (int length = 1; length <= 6; ++length) {
            for (int from = 1; from <= 14; ++from) {
                SCOPED_TRACE(std::to_string(length) + " scans left out from scan " + std::to_string(from) +
                             " after the edge" + (fall ? ", Execute falling in the first" : ""));
                ++serial;
                const Job job{E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, (serial % 2 ? 20.0F : 12.0F) + 0.0625F * (serial % 32)};
                EXPECT_EQ(program.RunScripted(job, from, length, fall), FreeCaller::Ended::kDone);
                if (HasFailure()) break;
            }
        }
    }
    for (const std::string& v : program.Violations()) ADD_FAILURE() << v;
}

// A jog released 1 to 8 scans after its edge (the input falling in the first call left out, 1 to 3 calls left
// out), before or after the controller took it over: Done only for a jog the controller took (the checks of the
// free program), CommandAborted for one it never ran. On the faster buses every release comes after the take-over;
// with a PA-CONTROL cycle of 10 ms the first ones come before it.
TEST_P(AxisSkippedCalls, AJogReleasedEarlyIsDoneOnlyIfTheControllerTookIt) {
    FreeAxisProgram program(GetParam());
    program.Prepare();
    ASSERT_FALSE(HasFatalFailure());
    for (int length = 1; length <= 3; ++length) {
        for (int from = 1; from <= 8; ++from) {
            SCOPED_TRACE("released " + std::to_string(from) + " scans after the edge, " + std::to_string(length) +
                         " calls left out");
            Job jog;
            jog.jog = from % 2 == 0 ? 1 : -1;
            jog.position = 3.0F + 0.0625F * static_cast<float>(from + 8 * length);
            const FreeCaller::Ended ended = program.RunScripted(jog, from, length, true);
            EXPECT_NE(ended, FreeCaller::Ended::kError);
        }
    }
    for (const std::string& v : program.Violations()) ADD_FAILURE() << v;
}

// The program stops calling the FB 1 to 6 scans after the edge of a move: the controller takes the job once and
// the axis arrives at its target.
TEST_P(AxisSkippedCalls, AMoveWhoseFbIsNeverCalledAgainRunsToItsEnd) {
    for (int after = 1; after <= 6; ++after) {
        SCOPED_TRACE("not called from scan " + std::to_string(after) + " after the edge");
        FreeAxisProgram program(GetParam());
        program.Prepare();
        ASSERT_FALSE(HasFatalFailure());
        const std::size_t before = program.JobsTaken();
        program.Abandon({E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 33.5F}, after);
        program.Scan(GetParam().timing.ScansFor(1s));
        EXPECT_EQ(program.JobsTaken(), before + 1);
        EXPECT_NEAR(program.Controller().Axes().Motion(1).Position(), 33.5, 0.01);
        for (const std::string& v : program.Violations()) ADD_FAILURE() << v;
    }
}

// ResetError pressed every 200 ms while the axis error's cause persists (a load the servo cannot correct: the
// controller refuses the reset), then the cause removed: the next press resets the error. The PA-CONTROL acts on
// the rising edge of bit 16, so each press must give one.
TEST_P(AxisSkippedCalls, AResetPressedAgainAfterTheCauseIsGoneClearsTheError) {
    FreeAxisProgram program(GetParam());
    program.Prepare(false);  // called in every scan, nothing but the presses
    ASSERT_FALSE(HasFatalFailure());
    auto& axes = program.Controller().Axes();
    axes.SetDisturbance(1, program.Now(), 5.0);  // following error beyond the limit: an axis error that stays
    program.Scan(GetParam().timing.ScansFor(100ms));
    ASSERT_TRUE(axes.Motion(1).Fault());
    auto press = [&] {
        program.PressResetError();
        program.Scan(GetParam().timing.ScansFor(200ms));
    };
    for (int i = 0; i < 5; ++i) press();
    EXPECT_TRUE(axes.Motion(1).Fault()) << "the cause persists";
    axes.SetDisturbance(1, program.Now(), 0.0);
    press();
    EXPECT_FALSE(axes.Motion(1).Fault()) << "the first press after the cause is gone";
}

// A move runs at full speed; a new Execute edge with another job (`next`, with `timeout`) ends it: CommandAborted
// in the edge scan, and the new job waits for the braking axis. `taken`: the controller's ledger size before the edge.
// `blankAtEdge`: operating status 0 in the edge scan; `abortAtEdge`: Abort TRUE in the edge scan only.
void SupersedeARunningMove(FreeAxisProgram& program, const AxisFreeCase& c, const Job& next,
                           std::chrono::nanoseconds timeout, std::size_t& taken, bool blankAtEdge = false,
                           bool abortAtEdge = false) {
    auto& axis = program.Axis();
    const Job first{E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 70.0F};
    program.Drive(first, true);
    for (int n = 0; n < 20000 && !axis->RUNNING.value && !pac::test::IsFinal(axis); ++n) program.Scan();
    ASSERT_TRUE(axis->RUNNING.value) << "the first move runs";
    program.Scan(c.timing.ScansFor(10ms));
    program.Drive(first, false);
    program.Scan();
    axis->TIMEOUT.value = pac::ToIecTime(timeout);
    taken = program.JobsTaken();
    program.Drive(next, true);
    if (blankAtEdge) program.BlankOpStatus();
    program.HoldAbort(abortAtEdge);
    program.Scan();
    program.HoldAbort(false);
    ASSERT_TRUE(axis->COMMANDABORTED.value && program.ActiveOnBus()) << "the first move, in the edge scan";
}

// The job ended with `errorId` in the last call, nothing of it taken by the controller after its edge.
void ExpectEndedUnsent(FreeAxisProgram& program, const AxisFreeCase& c, const Job& next, std::size_t taken,
                       const char* errorId) {
    auto& axis = program.Axis();
    EXPECT_TRUE(axis->ERROR.value) << "Busy " << int{axis->BUSY.value} << ", Done " << int{axis->DONE.value};
    EXPECT_EQ(axis->ERRORID.value, pac::test::GvlConstants{}[errorId]) << "Start not sent";
    program.Drive(next, false);
    program.Scan(c.timing.ScansFor(50ms));
    EXPECT_EQ(program.JobsTaken(), taken) << "the controller took the job over";
}

// D22: the calling contract (docs/fb/FB_PAC_Axis.md, "Calling contract": the waits run on the clock, a wait that
// ran out meanwhile ends the job in the next call, 16#8006 before Start). The new job of SupersedeARunningMove, with
// Timeout 20 ms: the program leaves the FB out from the call after its admission (D24, `fromEdge`: from the call
// after its edge, as its Timeout counts from the edge) until the Timeout has run out and the bus shows the axis
// free (ACTIVE 0), and `extra` scans more. Called again, the job ends 16#8006 and the controller's ledger holds no
// job taken over after its edge.
void LeaveOutAJobWaitingForTheAxisPastItsTimeout(FreeAxisProgram& program, const AxisFreeCase& c, int extra,
                                                 bool fromEdge) {
    auto& axis = program.Axis();
    const auto timeout = 20ms;
    const Job next{E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 40.0F + 0.0625F * static_cast<float>(extra)};
    std::size_t taken = 0;
    SupersedeARunningMove(program, c, next, timeout, taken);
    ASSERT_FALSE(::testing::Test::HasFatalFailure());
    auto waitFrom = program.Now();
    if (!fromEdge) {
        program.Scan();
        ASSERT_TRUE(axis->BUSY.value && program.ActiveOnBus() &&
                    (program.ControlOnBus() & pac::axis_control::kStart) == 0)
            << "the new job waits for the braking axis";
        waitFrom = program.Now();
    }
    program.LeaveOut(true);
    for (int n = 0; n < 20000 && (program.ActiveOnBus() || program.Now() - waitFrom <= timeout); ++n) program.Scan();
    program.Scan(extra);
    program.LeaveOut(false);
    program.Scan();
    ExpectEndedUnsent(program, c, next, taken, "PAC_LIB_ERR_INTERFACE_BUSY");
}

void LeaveOutPastTimeoutCases(const AxisFreeCase& c, bool fromEdge) {
    for (int extra = 0; extra <= 3; ++extra) {
        SCOPED_TRACE("called again " + std::to_string(extra) + " scans after its Timeout and the axis free");
        FreeAxisProgram program(c);
        program.Prepare(false);  // the case decides every call
        ASSERT_FALSE(::testing::Test::HasFatalFailure());
        LeaveOutAJobWaitingForTheAxisPastItsTimeout(program, c, extra, fromEdge);
    }
}

// D22 on each bus timing, called again 0 to 3 scans after the Timeout and the axis free. Before the fix Start went
// out in that call: 16 of the 16 cases failed, on pacst's C and on MATIEC's C alike.
TEST_P(AxisSkippedCalls, AJobLeftOutWhileItWaitsForTheAxisPastItsTimeoutIsNeverStarted) {
    LeaveOutPastTimeoutCases(GetParam(), false);
}

// D24: the same for the FB left out from the call after the edge. Before the fix the job was admitted in the first
// call after the skip and its wait began there, so Start went out.
TEST_P(AxisSkippedCalls, ASupersedingJobLeftOutPastItsTimeoutSinceItsEdgeIsNeverStarted) {
    LeaveOutPastTimeoutCases(GetParam(), true);
}

// D24 with the FB called in every scan: a first run with the default Timeout measures the time from the edge to the
// call that raised the new job's Start; with that Timeout the job's wait, counted from its edge, runs out in that
// call: 16#8006, never Start.
TEST_P(AxisSkippedCalls, ASupersedingJobCalledInEveryScanNeverStartsPastItsTimeoutSinceItsEdge) {
    const Job next{E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 40.0F};
    std::chrono::nanoseconds wait{1s};
    for (bool measure : {true, false}) {
        SCOPED_TRACE(measure ? "measuring the wait" : "Timeout as long as the wait");
        FreeAxisProgram program(GetParam());
        program.Prepare(false);
        ASSERT_FALSE(HasFatalFailure());
        auto& axis = program.Axis();
        std::size_t taken = 0;
        SupersedeARunningMove(program, GetParam(), next, wait, taken);
        ASSERT_FALSE(HasFatalFailure());
        const auto edgeAt = program.Now();
        program.Scan();  // the new job's first call: CommandAborted of the edge scan is over
        for (int n = 0; n < 20000 && !pac::test::IsFinal(axis) &&
                        (program.ControlOnBus() & pac::axis_control::kStart) == 0; ++n) {
            program.Scan();
        }
        if (measure) {
            ASSERT_NE(program.ControlOnBus() & pac::axis_control::kStart, 0U) << "Start after the braking";
            wait = program.Now() - edgeAt;
        } else {
            ExpectEndedUnsent(program, GetParam(), next, taken, "PAC_LIB_ERR_INTERFACE_BUSY");
        }
    }
}

// D24: operating status 0 in the scan of an edge that supersedes a running job ends the new job 16#8003 in the next
// call, as at a fresh edge, whatever status that call sees; nothing is sent.
TEST_P(AxisSkippedCalls, ASupersedingEdgeInAStatusZeroScanEndsNotReady) {
    FreeAxisProgram program(GetParam());
    program.Prepare(false);
    ASSERT_FALSE(HasFatalFailure());
    const Job next{E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 40.0F};
    std::size_t taken = 0;
    SupersedeARunningMove(program, GetParam(), next, 1s, taken, true);
    ASSERT_FALSE(HasFatalFailure());
    program.Scan();
    ExpectEndedUnsent(program, GetParam(), next, taken, "PAC_LIB_ERR_NOT_READY");
}

// One admission at every edge (docs/fb/FB_PAC_Axis.md, "Calling contract"): Abort TRUE in the scan of an edge that
// supersedes a running job refuses the new job as it refuses a job edged on an idle axis ("while TRUE ... none
// starts"), whatever Abort is in the calls after. Abort FALSE from the next call on, the FB left out for 0 to 3
// scans after the edge: in every call while Execute stays TRUE (the braking, a round trip, 50 ms more) the new job
// shows CommandAborted and never Busy, and the controller takes no job after the edge; Execute falling, the output
// ends in the next call. Before the fix the next call admitted the job and Start went out after the braking.
TEST_P(AxisSkippedCalls, ASupersedingEdgeWithAbortInForceNeverStartsItsJob) {
    for (int skip = 0; skip <= 3; ++skip) {
        SCOPED_TRACE("left out for " + std::to_string(skip) + " scans after the edge");
        FreeAxisProgram program(GetParam());
        program.Prepare(false);
        ASSERT_FALSE(HasFatalFailure());
        auto& axis = program.Axis();
        const Job next{E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 40.0F + 0.0625F * static_cast<float>(skip)};
        std::size_t taken = 0;
        SupersedeARunningMove(program, GetParam(), next, 1s, taken, false, true);
        ASSERT_FALSE(HasFatalFailure());
        program.LeaveOut(true);
        program.Scan(skip);
        program.LeaveOut(false);
        int calls = 0;
        for (int n = 0; n < 20000 && (program.ActiveOnBus() || calls < GetParam().timing.ScansFor(50ms)); ++n) {
            program.Scan();
            ++calls;
            EXPECT_TRUE(axis->COMMANDABORTED.value && !axis->BUSY.value && !axis->DONE.value && !axis->ERROR.value)
                << "call " << calls << " after the skip: Busy " << int{axis->BUSY.value} << ", Error "
                << int{axis->ERROR.value} << " (16#" << std::hex << axis->ERRORID.value << ")";
            if (HasFailure()) break;
        }
        program.Scan(GetParam().timing.ScansFor(50ms));
        EXPECT_EQ(program.JobsTaken(), taken) << "the controller took the refused job over";
        program.Drive(next, false);
        program.Scan();
        EXPECT_FALSE(axis->COMMANDABORTED.value || axis->BUSY.value) << "Execute fell";
    }
}

INSTANTIATE_TEST_SUITE_P(Timings, AxisSkippedCalls,
                         ::testing::Values(AxisFreeCase{{1, 10, 0}}, AxisFreeCase{{2, 3, 1}},
                                           AxisFreeCase{{5, 1, 3}, pac::sim::ActiveForJobs::kTraversingOnly},
                                           AxisFreeCase{{2, 1, 1, 1500, 606}, pac::sim::ActiveForJobs::kEveryJob,
                                                        pac::sim::CmdErrorRestart::kOneCycleClear}),
                         AxisFreeCaseName);

std::vector<AxisFreeCase> AxisFreeCases() {
    std::vector<AxisFreeCase> cases;
    std::uint64_t seed = 1;
    const std::vector<pac::test::BusTiming> timings = {{1, 10, 0}, {1, 3, 1}, {2, 10, 2}, {5, 1, 3},
                                                       {10, 3, 0}, {2, 1, 1, 1500, 606}};
    for (const auto& t : timings) {
        for (auto active : {pac::sim::ActiveForJobs::kEveryJob, pac::sim::ActiveForJobs::kTraversingOnly}) {
            for (auto restart : {pac::sim::CmdErrorRestart::kSameCycle, pac::sim::CmdErrorRestart::kOneCycleClear}) {
                cases.push_back({t, active, restart, seed++});
            }
        }
    }
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Readings, AxisFreeProgram, ::testing::ValuesIn(AxisFreeCases()), AxisFreeCaseName);

}  // namespace
}  // namespace test_axis_free_program_sim
