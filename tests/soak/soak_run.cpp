#include "soak_run.hpp"

#include <sstream>

#include "pac/iec_time.hpp"
#include "plcopen_pins.hpp"
#include "pac/sim/link.hpp"
#include "pac/sim/pa_control.hpp"

namespace pac::soak {

namespace {

using std::chrono::milliseconds;
using std::chrono::nanoseconds;
using std::chrono::microseconds;

constexpr auto kStartOnline = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
constexpr auto kCancel = E_PAC_CTRLREQUEST__PAC_REQ_CANCEL;
constexpr auto kResetError = E_PAC_CTRLREQUEST__PAC_REQ_RESET_ERROR;
constexpr auto kMoveRelative = E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE;
constexpr auto kClearDisplaced = E_PAC_AXISCOMMAND__PAC_AX_CLEAR_DISPLACED;
constexpr std::uint16_t kFollowingError = 66;  // the simulator's axis error for a servo that cannot follow
constexpr int kRegisters = 100;                 // the integer registers the commands write, 1..100

const char* const kFaultNames[kFaultKinds] = {"power cycle", "link loss",   "frozen inputs", "jitter",
                                              "command error", "axis error", "limit switch", "system error"};

}  // namespace

const char* FaultName(Fault fault) { return kFaultNames[static_cast<std::size_t>(fault)]; }

std::int64_t SoakCounts::Faults() const {
    std::int64_t all = 0;
    for (std::int64_t n : faults) all += n;
    return all;
}

RigTiming SoakTiming(std::uint64_t seed) {
    pac::sim::SplitMix64 rng(seed ^ 0x5EEDULL);
    const int plcMs[] = {1, 2, 5};
    const int pacMs[] = {1, 3, 10};
    RigTiming timing;
    timing.plcCycle = milliseconds(plcMs[rng.UniformUpTo(2)]);
    timing.pacCycle = milliseconds(pacMs[rng.UniformUpTo(2)]);
    timing.latencyCycles = static_cast<int>(rng.UniformUpTo(2));
    timing.jitter = microseconds(rng.UniformUpTo(1) * rng.UniformUpTo(static_cast<std::uint64_t>(timing.plcCycle / microseconds(1))));
    timing.seed = seed;
    // The simulated controller's own boot time: longer than any round trip here. A controller that booted
    // faster than the bus carries the PLC's next image would find the command it executed just before the
    // power cycle still on the bus, SEND unequal to its fresh RECEIVE 0, and execute it again: the
    // handshake of manual 2.4 cannot tell (docs/testing.md).
    timing.bootTime = pac::sim::PaControlConfig{}.bootTime;
    return timing;
}

SoakRun::SoakRun(std::uint64_t seed, std::int64_t scans)
    : seed_(seed), scans_(scans), rng_(seed), timing_(SoakTiming(seed)), plc_(timing_, report_) {
    plc_.Ctrl()->TIMEOUT.value = pac::ToIecTime(std::chrono::seconds(5));
    plc_.Axis()->ENABLE.value = TRUE;
}

std::int64_t SoakRun::Draw(std::int64_t low, std::int64_t high) {
    return low + static_cast<std::int64_t>(rng_.UniformUpTo(static_cast<std::uint64_t>(high - low)));
}

void SoakRun::ScanOnce() {
    plc_.Scan();
    counts_.scans = plc_.ScanCount();
}

template <class Predicate>
bool SoakRun::ScanUntil(Predicate done, std::int64_t deadline) {
    while (!done()) {
        if (plc_.ScanCount() >= deadline) return false;
        ScanOnce();
    }
    return true;
}

void SoakRun::Run() {
    // As a PLC program would: the first request once the controller shows Ready.
    Recover("at start");
    while (BudgetLeft()) RandomScan();
}

void SoakRun::RandomScan() {
    MaybeFault();
    RandomCommands();
    RandomRequest();
    RandomAxis();
    ScanOnce();
}

void SoakRun::StartCommand(int fb) {
    plc_.StartCommand(fb, static_cast<std::uint16_t>(Draw(1, kRegisters)), nextNumber_++);
    ++counts_.commands;
}

void SoakRun::RandomCommands() {
    for (int fb = 0; fb < SoakPlc::kCommandFbs; ++fb) {
        auto& cmd = plc_.Cmd(fb);
        int& hold = cmdHold_[static_cast<std::size_t>(fb)];
        if (plc_.CmdJob(fb).open) {
            if (Chance(300)) cmd->EXECUTE.value = FALSE;  // released early: the FB still ends the command
        } else if (cmd->EXECUTE.value != 0) {
            if (hold-- <= 0) cmd->EXECUTE.value = FALSE;
        } else if (Chance(40)) {
            StartCommand(fb);
            hold = static_cast<int>(Draw(0, 3));
        }
    }
}

void SoakRun::RandomRequest() {
    auto& ctrl = plc_.Ctrl();
    if (plc_.CtrlJob().open) return;
    if (ctrl->EXECUTE.value != 0) {
        if (ctrlHold_-- <= 0) ctrl->EXECUTE.value = FALSE;
    } else if (Chance(3000)) {
        const E_PAC_CTRLREQUEST requests[] = {kStartOnline,
                                              kStartOnline,
                                              kStartOnline,
                                              E_PAC_CTRLREQUEST__PAC_REQ_STOP,
                                              kCancel,
                                              kResetError,
                                              E_PAC_CTRLREQUEST__PAC_REQ_START_AUTOMATIC};
        plc_.StartRequest(requests[Draw(0, 6)]);
        ctrlHold_ = static_cast<int>(Draw(0, 3));
        ++counts_.requests;
    }
}

void SoakRun::RandomAxis() {
    auto& axis = plc_.Axis();
    if (axis->ENABLE.value != 0 ? Chance(20000) : Chance(300)) axis->ENABLE.value = axis->ENABLE.value != 0 ? FALSE : TRUE;
    if (abortScans_ > 0 && --abortScans_ == 0) axis->ABORT.value = FALSE;
    if (jogScans_ > 0 && --jogScans_ == 0) {
        axis->JOGPOSITIVE.value = FALSE;
        axis->JOGNEGATIVE.value = FALSE;
    }
    if (plc_.AxisJob().open) {
        if (abortScans_ == 0 && Chance(500)) {
            axis->ABORT.value = TRUE;
            abortScans_ = static_cast<int>(Draw(1, 5));
            ++counts_.aborts;
        }
        return;
    }
    if (axis->EXECUTE.value != 0) {
        if (axisHold_-- <= 0) axis->EXECUTE.value = FALSE;
        return;
    }
    if (jogScans_ > 0 || abortScans_ > 0 || !Chance(150)) return;
    const std::int64_t kind = Draw(0, 9);
    if (kind == 0) {  // a jog of up to 50 units, held for a while
        axis->POSITION.value = 50.0f;
        (Draw(0, 1) == 0 ? axis->JOGPOSITIVE : axis->JOGNEGATIVE).value = TRUE;
        jogScans_ = static_cast<int>(Draw(5, 300));
        ++counts_.jogs;
        return;
    }
    const std::int64_t limit = plc_.ScansFor(std::chrono::seconds(20));
    if (kind == 1) {
        plc_.StartAxisJob(E_PAC_AXISCOMMAND__PAC_AX_HOME, 0.0f, limit);
    } else if (kind == 2) {
        plc_.StartAxisJob(kClearDisplaced, 0.0f, limit);
    } else if (kind <= 5) {
        plc_.StartAxisJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, static_cast<float>(Draw(100, 900)), limit);
    } else {
        plc_.StartAxisJob(kMoveRelative, static_cast<float>(Draw(-100, 100)), limit);
    }
    axisHold_ = static_cast<int>(Draw(0, 3));
    ++counts_.axisJobs;
}

void SoakRun::MaybeFault() {
    if (faultActive_) {
        if (plc_.ScanCount() >= faultEnd_) {
            EndFault();
            if (Recover(std::string("after ") + FaultName(fault_))) ++counts_.recoveries;
        }
        return;
    }
    if (!Chance(4000)) return;
    auto& pac = plc_.Controller();
    auto& bus = plc_.Rig().Bus();
    const nanoseconds now = plc_.Now();
    fault_ = static_cast<Fault>(Draw(0, kFaultKinds - 1));
    faultActive_ = true;
    faultEnd_ = plc_.ScanCount() + plc_.ScansFor(milliseconds(Draw(20, 800)));
    ++counts_.faults[static_cast<std::size_t>(fault_)];
    switch (fault_) {
        case Fault::kPowerCycle:
            pac.PowerCycle(now);
            break;
        case Fault::kLinkLoss:
            bus.Disconnect(now);
            break;
        case Fault::kFrozenInputs:
            bus.FromPacLink().SetFault(now, pac::sim::LinkFault::kFrozen);
            break;
        case Fault::kJitter: {
            const nanoseconds jitter = microseconds(Draw(1, 3 * plc_.Cycle() / microseconds(1)));
            bus.ToPacLink().SetJitter(jitter);
            bus.FromPacLink().SetJitter(jitter);
            break;
        }
        case Fault::kCommandError:
            pac.InjectCommandError(static_cast<std::uint16_t>(Draw(1, 0x1FFF)));
            break;
        case Fault::kAxisError:
            pac.Axes().RaiseAxisError(1, now, kFollowingError);
            break;
        case Fault::kLimitSwitch: {
            const double position = pac.Axes().Motion(1).Position();
            pac.Axes().SetLimitSwitches(1, position - static_cast<double>(Draw(1, 30)),
                                        position + static_cast<double>(Draw(1, 30)));
            break;
        }
        case Fault::kSystemError:
            pac.RaiseSystemError(static_cast<std::uint16_t>(Draw(500, 999)));  // cleared by CANCEL (5.2.1)
            break;
    }
}

void SoakRun::EndFault() {
    auto& pac = plc_.Controller();
    auto& bus = plc_.Rig().Bus();
    const nanoseconds now = plc_.Now();
    faultActive_ = false;
    switch (fault_) {
        case Fault::kLinkLoss:
            bus.Reconnect(now);
            break;
        case Fault::kFrozenInputs:
            bus.FromPacLink().SetFault(now, pac::sim::LinkFault::kNone);
            break;
        case Fault::kJitter:
            bus.ToPacLink().SetJitter(timing_.jitter);
            bus.FromPacLink().SetJitter(timing_.jitter);
            break;
        case Fault::kLimitSwitch: {
            const pac::sim::ServoAxisConfig machine;  // the switches a machine has by default
            pac.Axes().SetLimitSwitches(1, machine.negativeLimitSwitch, machine.positiveLimitSwitch);
            break;
        }
        default:  // the others happened at once; what is left of them is the library's to recover from
            break;
    }
}

bool SoakRun::RunCommand(int fb, std::int64_t deadline) {
    auto& cmd = plc_.Cmd(fb);
    if (!ScanUntil([&] { return !plc_.CmdJob(fb).open; }, deadline)) return false;
    cmd->EXECUTE.value = FALSE;
    ScanOnce();
    StartCommand(fb);
    const bool ended = ScanUntil([&] { return !plc_.CmdJob(fb).open; }, deadline);
    const bool done = ended && cmd->DONE.value != 0;
    cmd->EXECUTE.value = FALSE;
    ScanOnce();
    return done;
}

bool SoakRun::RunRequest(E_PAC_CTRLREQUEST request, std::int64_t deadline) {
    auto& ctrl = plc_.Ctrl();
    if (!ScanUntil([&] { return !plc_.CtrlJob().open; }, deadline)) return false;
    ctrl->EXECUTE.value = FALSE;
    ScanOnce();
    plc_.StartRequest(request);
    ++counts_.requests;
    const bool ended = ScanUntil([&] { return !plc_.CtrlJob().open; }, deadline);
    const bool done = ended && ctrl->DONE.value != 0;
    ctrl->EXECUTE.value = FALSE;
    ScanOnce();
    return done;
}

bool SoakRun::RunAxisJob(E_PAC_AXISCOMMAND command, float position, std::int64_t deadline) {
    auto& axis = plc_.Axis();
    // A jog that was let go still stops (Busy without a job of the soak's), and an aborted reference run may
    // go on (ACTIVE): the FB waits Timeout for a free axis, a program waits for it before the next job.
    if (!ScanUntil([&] { return !plc_.AxisJob().open && axis->BUSY.value == 0 && axis->ACTIVE.value == 0; },
                   deadline)) {
        return false;
    }
    axis->EXECUTE.value = FALSE;
    ScanOnce();
    plc_.StartAxisJob(command, position, plc_.ScansFor(std::chrono::seconds(20)));
    ++counts_.axisJobs;
    const bool ended = ScanUntil([&] { return !plc_.AxisJob().open; }, deadline);
    const bool done = ended && axis->DONE.value != 0;
    std::ostringstream outcome;
    outcome << pac::test::OutputsOf(axis) << (ended ? "" : ", not ended");
    lastAxisOutcome_ = outcome.str();
    axis->EXECUTE.value = FALSE;
    ScanOnce();
    return done;
}

void SoakRun::ScanFor(nanoseconds t) {
    const std::int64_t end = plc_.ScanCount() + plc_.ScansFor(t);
    while (plc_.ScanCount() < end) ScanOnce();
}

bool SoakRun::Recover(const std::string& when) {
    const std::int64_t deadline = plc_.ScanCount() + plc_.ScansFor(kRecoveryTime);
    auto& ctrl = plc_.Ctrl();
    auto& axis = plc_.Axis();
    // What a PLC program does after a fault: let go of everything, then bring the machine back.
    axis->ABORT.value = FALSE;
    axis->JOGPOSITIVE.value = FALSE;
    axis->JOGNEGATIVE.value = FALSE;
    axis->ENABLE.value = TRUE;
    abortScans_ = 0;
    jogScans_ = 0;
    auto fail = [&](const std::string& step) {
        report_.Violation(plc_.ScanCount(), "no recovery " + when + ": " + step + " (" + Describe() + ")");
        return false;
    };

    // A mode request made before the fault ended may still run: a STOP that lands after ONLINE was confirmed
    // would stop the recovery's own moves (20, not ONLINE). It ends first; the recovery goes from where it left.
    if (!ScanUntil([&] { return !plc_.CtrlJob().open; }, deadline)) return fail("FB_PAC_Ctrl's request never ended");
    ctrl->EXECUTE.value = FALSE;
    if (!ScanUntil([&] { return ctrl->READY.value != 0; }, deadline)) return fail("the PA-CONTROL never showed Ready");
    ScanFor(milliseconds(20));  // the first control word after a boot is only the reference for the CTRL edges
    // ONLINE runs and no system error: ONLINE's bit also shows while a malfunction is braking (status 37).
    auto online = [&] { return ctrl->ONLINEACTIVE.value != 0 && ctrl->SYSTEMERROR.value == 0; };
    for (int attempt = 0; attempt < 3 && !online(); ++attempt) {
        if (ctrl->ONLINESTOPPED.value != 0 || ctrl->AUTOMATICACTIVE.value != 0 || ctrl->AUTOMATICSTOPPED.value != 0 ||
            ctrl->SYSTEMERROR.value != 0) {
            RunRequest(kCancel, deadline);
        }
        if (ctrl->SYSTEMERROR.value != 0) RunRequest(kResetError, deadline);
        RunRequest(kStartOnline, deadline);
    }
    if (!online()) return fail("FB_PAC_Ctrl could not bring ONLINE back");

    bool commandDone = false;
    for (int attempt = 0; attempt < 3 && !commandDone; ++attempt) commandDone = RunCommand(0, deadline);
    if (!commandDone) return fail("no command Done through FB_PAC_Cmd");

    bool moved = false;
    for (int attempt = 0; attempt < 3 && !moved; ++attempt) {
        if (axis->AXISERROR.value != 0 || axis->CMDERROR.value != 0) {
            axis->RESETERROR.value = TRUE;
            ScanFor(milliseconds(30));
            axis->RESETERROR.value = FALSE;
            ScanOnce();
        }
        if (axis->DISPLACEDWHILEOFF.value != 0) RunAxisJob(kClearDisplaced, 0.0f, deadline);
        // A reference run that was aborted leaves the axis unreferenced: moves wait for a new one (43).
        if (axis->REFERENCED.value == 0) RunAxisJob(E_PAC_AXISCOMMAND__PAC_AX_HOME, 0.0f, deadline);
        moved = RunAxisJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 500.0f, deadline);
    }
    if (!moved) return fail("no axis move Done through FB_PAC_Axis, the last one: " + lastAxisOutcome_);
    return true;
}

std::string SoakRun::Describe() {
    std::ostringstream out;
    auto& cmd = plc_.Cmd(0);
    auto& axis = plc_.Axis();
    out << std::hex << std::uppercase << "PA-CONTROL status " << std::dec << int{plc_.Controller().OperatingStatus()}
        << std::hex << ", FB_PAC_Cmd ErrorID 16#" << cmd->ERRORID.value << ", FB_PAC_Axis ErrorID 16#"
        << axis->ERRORID.value << " status word 16#" << axis->STATUSWORD.value << " CMD error "
        << std::dec << axis->CMDERRORNUMBER.value << " axis error " << axis->AXISERRORNUMBER.value;
    return out.str();
}

std::string SoakRun::Summary() const {
    std::ostringstream out;
    out << "soak: seed " << seed_ << ", PLC " << timing_.plcCycle / milliseconds(1) << " ms, PA-CONTROL "
        << timing_.pacCycle / milliseconds(1) << " ms, latency " << timing_.latencyCycles << ", jitter "
        << timing_.jitter / microseconds(1) << " us; scans " << counts_.scans << ", jobs " << counts_.Jobs()
        << " (commands " << counts_.commands << ", mode requests " << counts_.requests << ", axis jobs "
        << counts_.axisJobs << ", jogs " << counts_.jogs << ", aborts " << counts_.aborts << "), faults "
        << counts_.Faults() << " (";
    for (std::size_t i = 0; i < kFaultKinds; ++i) out << (i == 0 ? "" : ", ") << kFaultNames[i] << " " << counts_.faults[i];
    out << "), recovered " << counts_.recoveries << ", commands executed " << plc_.Ledger().Executed()
        << ", violations " << report_.Violations();
    return out.str();
}

}  // namespace pac::soak
