#include "workloads.hpp"

#include <chrono>
#include <cstring>
#include <cstdlib>
#include <functional>
#include <map>
#include <stdexcept>

#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#endif
#endif
#ifndef CALLGRIND_ZERO_STATS
#define CALLGRIND_ZERO_STATS
#define CALLGRIND_DUMP_STATS
#endif

#include "cmd_handshake.h"
#include "ctrl_hand.h"
#include "pac/iec_time.hpp"
#include "pac/pac_rig.hpp"
#include "pac/sim/automatic_program.hpp"
#include "plant.hpp"

namespace pac::bench {

namespace {

using std::chrono::milliseconds;

// The measured part of every workload: `scans` scans of `scan`, alone in the dump; `jobsDone` counts the
// jobs that ended with Done so far.
WorkloadResult Measure(const std::function<void()>& scan, int scans, const std::function<long()>& jobsDone) {
    const long before = jobsDone();
    CALLGRIND_ZERO_STATS;
    for (int i = 0; i < scans; ++i) scan();
    CALLGRIND_DUMP_STATS;
    return {scans, jobsDone() - before};
}

// The PLC program of a command job: Execute until a final output, then one scan low, then the next.
struct CommandInputs {
    bool execute = false;
    std::uint16_t code = 0;
    std::uint16_t param = 0;
    std::uint32_t data = 0;
    long started = 0;
    long done = 0;
};

void CycleCommand(CommandInputs& in, bool done, bool error) {
    if (in.execute && (done || error)) {
        in.execute = false;
        in.done += done ? 1 : 0;
    } else if (!in.execute) {
        in.execute = true;
        in.code = (in.started++ % 2 == 0) ? 0x0906 : 0x1906;  // write, then read back, N register 1
        in.param = 1;
        in.data = static_cast<std::uint32_t>(in.started);
    }
}

// The PLC program that sets a command's inputs before each call; null: no jobs.
using JobProgram = void (*)(CommandInputs& in, bool done, bool error);

// FB_PAC_Cmd on `plc`'s CMD interface (with the FB_PAC_CmdInterface the bench registers before it).
void CallLibrary(pac::PacRig& plc, pac::FbInstance<FB_PAC_CMD>& cmd, CommandInputs& in, JobProgram program) {
    plc.Call(cmd, [&cmd, &in, program] {
        if (program) program(in, cmd->DONE.value, cmd->ERROR.value);
        cmd->EXECUTE.value = in.execute;
        cmd->CODE.value = in.code;
        cmd->PARAM.value = in.param;
        cmd->DATA.value = in.data;
    });
}

// The hand-written C handshake on `plc`'s CMD module.
void CallHandWritten(pac::PacRig& plc, CmdHandshake& hs, CommandInputs& in, JobProgram program) {
    plc.CallRaw8(pac::sim::ModuleLayout::kCmdOffset,
                 [&plc, &hs, &in, program](const pac::sim::Image8& fromPac, pac::sim::Image8& toPac) {
                     if (program) program(in, hs.done != 0, hs.error != 0);
                     hs.execute = in.execute;
                     hs.code = in.code;
                     hs.param = in.param;
                     hs.data = in.data;
                     CmdHandshakeScan(&hs, toPac.data(), fromPac.data(), plc.Now().count());
                 });
}

WorkloadResult CmdWorkload(bool job, int scans) {
    pac::PacRig plc;
    auto cmd = PAC_FB(FB_PAC_CMD);
    CommandInputs in;
    CallLibrary(plc, cmd, in, job ? CycleCommand : nullptr);
    plc.Start();
    plc.Scan(20);
    return Measure([&] { plc.Scan(); }, scans, [&] { return in.done; });
}

WorkloadResult HandWrittenWorkload(bool job, int scans) {
    pac::PacRig plc;
    CmdHandshake hs;
    CmdHandshakeInit(&hs);
    CommandInputs in;
    CallHandWritten(plc, hs, in, job ? CycleCommand : nullptr);
    plc.Start();
    plc.Scan(20);
    return Measure([&] { plc.Scan(); }, scans, [&] { return in.done; });
}

// FB_PAC_Ctrl or its hand-written C (bench/ctrl_hand.c) alone on the CTRL module, the controller set up for
// ONLINE as in the plant: the same pins on either, so that one PLC program drives both.
class CtrlBench {
public:
    CtrlBench(const pac::RigTiming& timing, bool handWritten)
        : handWritten_(handWritten), plc_(timing, {}, pac::sim::ModuleLayout{true, 0}) {
        AllowOnline(plc_.Controller());
        if (handWritten_) {
            CtrlHandInit(&hand_);
            plc_.CallRaw8(pac::sim::ModuleLayout::kCtrlOffset,
                          [this](const pac::sim::Image8& fromPac, pac::sim::Image8& toPac) {
                              CtrlHandScan(&hand_, toPac.data(), fromPac.data(), plc_.Now().count());
                          });
        } else {
            plc_.CallCtrl(fb_);
        }
        plc_.Start();
    }

    void Set(bool execute, int request, bool integerMode, std::chrono::nanoseconds timeout) {
        if (handWritten_) {
            hand_.execute = execute;
            hand_.request = request;
            hand_.integerMode = integerMode;
            hand_.timeoutNs = timeout.count();
        } else {
            fb_->EXECUTE.value = execute;
            fb_->REQUEST.value = static_cast<E_PAC_CTRLREQUEST>(request);
            fb_->INTEGERMODE.value = integerMode;
            fb_->TIMEOUT.value = pac::ToIecTime(timeout);
        }
    }
    bool Execute() const { return handWritten_ ? hand_.execute != 0 : fb_->EXECUTE.value != 0; }
    bool Done() const { return handWritten_ ? hand_.done != 0 : fb_->DONE.value != 0; }
    bool Error() const { return handWritten_ ? hand_.error != 0 : fb_->ERROR.value != 0; }
    bool Ready() const { return handWritten_ ? hand_.ready != 0 : fb_->READY.value != 0; }
    void Scan() { plc_.Scan(); }
    pac::PacRig& Plc() { return plc_; }
    const CtrlHand& Hand() const { return hand_; }
    pac::FbInstance<FB_PAC_CTRL>& Fb() { return fb_; }

    // Scans until Ready, 20 ms more (the first control word is only the reference for the edges), then
    // START ONLINE until it is Done and one scan with Execute low. std::runtime_error if ONLINE is not reached.
    void GoOnline() {
        const std::chrono::nanoseconds ten = std::chrono::seconds(10);
        if (plc_.ScanUntil([this] { return Ready(); }, 2000) < 0) throw std::runtime_error("CtrlBench: not Ready");
        plc_.Scan(static_cast<int>(milliseconds(20) / plc_.Timing().plcCycle) + 1);
        Set(true, E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE, false, ten);
        if (plc_.ScanUntil([this] { return Done() || Error(); }, 2000) < 0 || !Done()) {
            throw std::runtime_error("CtrlBench: ONLINE not reached");
        }
        Set(false, E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE, false, ten);
        plc_.Scan();
    }

private:
    bool handWritten_;
    pac::PacRig plc_;
    pac::FbInstance<FB_PAC_CTRL> fb_ = PAC_FB(FB_PAC_CTRL);
    CtrlHand hand_{};
};

WorkloadResult CtrlWorkload(bool job, bool handWritten, int scans) {
    CtrlBench bench({}, handWritten);
    bench.GoOnline();
    bool online = true;
    long done = 0;
    return Measure([&] {
        if (job) {
            // STOP ONLINE and START ONLINE in turn, each held until its final output, then one scan low.
            if (bench.Execute() && (bench.Done() || bench.Error())) {
                done += bench.Done() ? 1 : 0;
                bench.Set(false, online ? E_PAC_CTRLREQUEST__PAC_REQ_STOP : E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE,
                          false, std::chrono::seconds(10));
                online = !online;
            } else if (!bench.Execute()) {
                bench.Set(true, online ? E_PAC_CTRLREQUEST__PAC_REQ_STOP : E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE,
                          false, std::chrono::seconds(10));
            }
        }
        bench.Scan();
    }, scans, [&] { return done; });
}

WorkloadResult AxisWorkload(bool job, bool handWritten, int scans) {
    PlantOptions options;
    options.axes = 1;
    options.commands = false;
    options.moves = job;
    options.handWrittenAxes = handWritten;
    Plant plant(options);
    plant.GoOnline();
    return Measure([&] { plant.Scan(); }, scans, [&] { return plant.MovesDone(); });
}

// FB_PAC_AutomaticModule on module 1 after power-on: "idle" in HOME POSITION, where it leaves the module
// alone; "job" in AUTOMATIC, where it sends a new N1 in every scan and the controller's stand-in program
// answers N17 := N1 + 1 (and R17, FW18 from R1, FW2). A job is an answer that came back.
WorkloadResult AutomaticWorkload(bool exchange, int scans) {
    constexpr std::size_t kOpStatusByte = 5;  // of the CMD reply (2.4.2)
    pac::PacRig plc({}, {}, pac::sim::ModuleLayout{true, 1});
    plc.Controller().SetAutomaticProgram(
        pac::sim::AutomaticProgram({"N17 := N1 + 1", "R17 := R1 * 2", "FW18 := FW2"}));
    auto ctrl = PAC_FB(FB_PAC_CTRL);
    auto module = PAC_FB(FB_PAC_AUTOMATICMODULE);
    std::int32_t sent = 0;
    long answers = 0;
    plc.CallCtrl(ctrl);
    plc.CallAxis(module, 1, [&] {
        module->OPSTATUS.value = plc.FromPac()[kOpStatusByte];
        module->INTEGERMODE.value = ctrl->INTEGERMODEACTIVE.value;
        module->INTREGISTER.value = ++sent % 30000;
        module->REALREGISTER.value = static_cast<float>(sent % 1000) * 0.5f;
        module->FLAGWORD.value = static_cast<std::uint16_t>(sent);
    });
    plc.Start();
    if (plc.ScanUntil([&] { return ctrl->READY.value != 0; }, 2000) < 0) {
        throw std::runtime_error("AutomaticWorkload: the controller is not Ready");
    }
    plc.Scan(20);
    if (exchange) {
        ctrl->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_START_AUTOMATIC;
        ctrl->EXECUTE.value = TRUE;
        if (plc.ScanUntil([&] { return ctrl->DONE.value || ctrl->ERROR.value; }, 2000) < 0 || !ctrl->DONE.value ||
            plc.ScanUntil([&] { return module->INEXCHANGE.value != 0; }, 200) < 0) {
            throw std::runtime_error("AutomaticWorkload: AUTOMATIC not reached");
        }
        ctrl->EXECUTE.value = FALSE;
    }
    std::int32_t last = module->RECEIVEDINTREGISTER.value;
    return Measure([&] {
        plc.Scan();
        if (module->RECEIVEDINTREGISTER.value != last) {
            last = module->RECEIVEDINTREGISTER.value;
            ++answers;
        }
    }, scans, [&] { return answers; });
}

WorkloadResult PlantWorkload(milliseconds pacCycle, int scans) {
    PlantOptions options;
    options.pacCycle = pacCycle;
    Plant plant(options);
    plant.GoOnline();
    plant.Scan(200);  // every axis under way
    return Measure([&] { plant.Scan(); }, scans, [&] { return plant.MovesDone() + plant.CommandsDone(); });
}

// `count` plants at a controller cycle of `pacCycle` scanned one after the other in each PLC cycle, as the
// scale rows run them: `cycles` PLC cycles measured, each plant's scan one scan of the result (the cost per
// controller and scan).
WorkloadResult PlantsWorkload(int count, milliseconds pacCycle, int cycles) {
    auto plants = OnlinePlants(count, pacCycle);
    const auto jobs = [&plants] {
        long done = 0;
        for (const auto& plant : plants) done += plant->MovesDone() + plant->CommandsDone();
        return done;
    };
    WorkloadResult result = Measure([&] {
        for (auto& plant : plants) plant->Scan();
    }, cycles, jobs);
    result.scans *= count;
    return result;
}

// The jobs of the side-by-side check: write and read back N register 1, and a code with the SEND flag set,
// which both refuse without sending.
void CycleCheckedCommand(CommandInputs& in, bool done, bool error) {
    if (in.execute && (done || error)) {
        in.execute = false;
    } else if (!in.execute) {
        static const std::uint16_t kCodes[] = {0x0906, 0x1906, 0x8906};
        in.execute = true;
        in.code = kCodes[in.started++ % 3];
        in.param = 1;
        in.data = static_cast<std::uint32_t>(in.started * 7);
    }
}

// What the side-by-side check of the axis adds to the plant's moves back and forth, by scan: relative moves
// (by 0 from 20 back: a job that may stand still), resets of "displaced", a refused velocity, Abort, Enable
// falling (Axis OFF), DISABLE DRIVE and a new Execute edge while a job is busy (the running job superseded).
struct AxisInputs {
    int command;
    std::uint16_t velocity;
    bool abort;
    bool enable;
    bool disableDrive;
    bool dropExecute;
};

AxisInputs CheckedAxisInputs(int scan, bool busy) {
    static const int kCommands[] = {E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE,
                                    E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE, E_PAC_AXISCOMMAND__PAC_AX_CLEAR_DISPLACED};
    AxisInputs in{};
    in.command = kCommands[(scan / 250) % 4];
    in.velocity = (scan / 150) % 9 == 4 ? 0 : 1000;
    in.abort = scan % 250 >= 100 && scan % 250 < 103;
    in.enable = !(scan % 900 >= 500 && scan % 900 < 504);
    in.disableDrive = scan % 1000 >= 700 && scan % 1000 < 706;
    in.dropExecute = scan % 400 == 200 && busy;
    return in;
}

// A lost link in the last 100 of `scans` scans, for 30 scans: whatever runs then ends as the FBs end it
// (late, so that the runs before it are not cut short by what the controller does after it).
void PullCableNearTheEnd(pac::PacRig& plc, int scan, int scans) {
    if (scan == scans - 100) plc.Bus().Disconnect(plc.Now());
    if (scan == scans - 70) plc.Bus().Reconnect(plc.Now());
}

// STOP ONLINE 380 scans before the end of `scans`, START ONLINE 80 scans later, each request's Execute low
// once it is final: a move that runs then ends with HALT, and jobs are refused until ONLINE runs again.
void StopAndRestartOnline(Plant& plant, int scan, int scans) {
    auto& ctrl = plant.Ctrl();
    if (ctrl->EXECUTE.value && (ctrl->DONE.value || ctrl->ERROR.value)) ctrl->EXECUTE.value = FALSE;
    if (scan == scans - 380 || scan == scans - 300) {
        ctrl->REQUEST.value =
            scan == scans - 380 ? E_PAC_CTRLREQUEST__PAC_REQ_STOP : E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
        ctrl->EXECUTE.value = TRUE;
    }
}

// The first difference between FB_PAC_Axis and the hand-written C in a scan; empty if none.
std::string AxisDifference(Plant& library, Plant& hand) {
    auto& fb = library.Axis(1);
    const AxisHand& a = hand.HandAxis(1);
    const std::size_t offset = library.Plc().Layout().AxisOffset(1);
    if (std::memcmp(library.Plc().ToPac().Data() + offset, hand.Plc().ToPac().Data() + offset, 12) != 0) {
        return "the module differs";
    }
    const bool bits[] = {fb->ENABLED.value != 0, fb->HALTED.value != 0, fb->DRIVEDISABLED.value != 0,
                         fb->SAFE.value != 0, fb->IDLE.value != 0, fb->DISABLED.value != 0, fb->FAULT.value != 0,
                         fb->ACTIVE.value != 0, fb->REFERENCED.value != 0};
    for (int bit = 0; bit < 9; ++bit) {
        if (bits[bit] != (AxisHandBit(&a, bit) != 0)) return "status bit " + std::to_string(bit) + " differs";
    }
    const bool valid = a.status.valid != 0;
    const bool same =
        (fb->DONE.value != 0) == (a.done != 0) && (fb->BUSY.value != 0) == (a.busy != 0) &&
        (fb->ERROR.value != 0) == (a.error != 0) && (fb->COMMANDABORTED.value != 0) == (a.commandAborted != 0) &&
        fb->ERRORID.value == a.errorId && static_cast<int>(fb->ERRORSOURCE.value) == a.errorSource &&
        (fb->STATUSVALID.value != 0) == valid && (fb->RUNNING.value != 0) == (a.running != 0) &&
        (fb->ACTIVEWITHOUTJOB.value != 0) == (a.activeWithoutJob != 0) &&
        (fb->OWNSMODULE.value != 0) == (a.ownsModule != 0) &&
        (fb->NEGATIVELIMITACTUATED.value != 0) == (valid && !AxisHandBit(&a, 9)) &&
        (fb->POSITIVELIMITACTUATED.value != 0) == (valid && !AxisHandBit(&a, 10)) &&
        (fb->STOPPEDBYCONDITION.value != 0) == (AxisHandBit(&a, 11) != 0) &&
        (fb->DISPLACEDWHILEOFF.value != 0) == (AxisHandBit(&a, 12) != 0) &&
        (fb->GROUPDISPLACEDWHILEOFF.value != 0) == (AxisHandBit(&a, 13) != 0) &&
        (fb->CMDERROR.value != 0) == (AxisHandBit(&a, 14) != 0) &&
        (fb->AXISERROR.value != 0) == (AxisHandBit(&a, 15) != 0) &&
        fb->STATUSWORD.value == a.status.statusWord && fb->CMDERRORNUMBER.value == a.status.cmdErrorNumber &&
        fb->AXISERRORNUMBER.value == a.status.axisErrorNumber && fb->ACTUALPOSITION.value == a.actualPosition &&
        fb->STATUS.value.POSITION == a.status.position && fb->STATUS.value.STATUSWORD == a.status.statusWord;
    return same ? "" : "an output differs";
}

}  // namespace

std::string CompareAxisWithHandWritten(const pac::RigTiming& timing, int scans) {
    PlantOptions options;
    options.axes = 1;
    options.commands = false;
    options.plcCycle = timing.plcCycle;
    options.pacCycle = timing.pacCycle;
    options.latencyCycles = timing.latencyCycles;
    Plant library(options);
    options.handWrittenAxes = true;
    Plant hand(options);
    library.GoOnline();
    hand.GoOnline();
    long events = 0;
    for (int scan = 1; scan <= scans; ++scan) {
        auto& fb = library.Axis(1);
        AxisHand& a = hand.HandAxis(1);
        const AxisInputs in = CheckedAxisInputs(scan, fb->BUSY.value != 0);
        fb->COMMAND.value = static_cast<E_PAC_AXISCOMMAND>(in.command);
        fb->VELOCITY.value = in.velocity;
        fb->ABORT.value = in.abort;
        fb->ENABLE.value = in.enable;
        fb->DISABLEDRIVE.value = in.disableDrive;
        // A dropped Execute stays low for this scan: the plant's program raises it again in the next.
        library.SetMoves(!in.dropExecute);
        hand.SetMoves(!in.dropExecute);
        if (in.dropExecute) fb->EXECUTE.value = FALSE;
        a.command = in.command;
        a.velocity = in.velocity;
        a.abort = in.abort;
        a.enable = in.enable;
        a.disableDrive = in.disableDrive;
        if (in.dropExecute) a.execute = 0;
        for (Plant* plant : {&library, &hand}) {
            StopAndRestartOnline(*plant, scan, scans);
            PullCableNearTheEnd(plant->Plc(), scan, scans);
        }
        library.Scan();
        hand.Scan();
        const std::string difference = AxisDifference(library, hand);
        if (!difference.empty()) return "scan " + std::to_string(scan) + ": " + difference;
        events += (fb->COMMANDABORTED.value || fb->ERROR.value) ? 1 : 0;
    }
    if (library.MovesDone() < 3 || events < 3) {
        return "fewer than three moves Done or three ends other than Done in " + std::to_string(scans) + " scans";
    }
    return "";
}

std::string CompareCtrlWithHandWritten(const pac::RigTiming& timing, int scans) {
    // Every request from the states it meets in this order: ONLINE and back, a start from "stopped", CANCEL,
    // RESET ERROR, AUTOMATIC, a STOP that does not apply in home position, no request; the number format
    // switched at every second request; a short Timeout, so that a request that hangs ends within the run.
    static const int kRequests[] = {
        E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE, E_PAC_CTRLREQUEST__PAC_REQ_STOP,
        E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE, E_PAC_CTRLREQUEST__PAC_REQ_STOP,
        E_PAC_CTRLREQUEST__PAC_REQ_CANCEL,       E_PAC_CTRLREQUEST__PAC_REQ_RESET_ERROR,
        E_PAC_CTRLREQUEST__PAC_REQ_START_AUTOMATIC, E_PAC_CTRLREQUEST__PAC_REQ_CANCEL,
        E_PAC_CTRLREQUEST__PAC_REQ_STOP,         E_PAC_CTRLREQUEST__PAC_REQ_NONE};
    constexpr int kCount = sizeof kRequests / sizeof kRequests[0];
    CtrlBench library(timing, false);
    CtrlBench hand(timing, true);
    int started = 0;
    long done = 0;
    long errors = 0;
    for (int scan = 1; scan <= scans; ++scan) {
        // One program for both, on the library's outputs: the check below keeps the two the same.
        const bool integerMode = (started / 2) % 2 == 1;
        if (library.Execute() && (library.Done() || library.Error())) {
            done += library.Done() ? 1 : 0;
            errors += library.Error() ? 1 : 0;
            for (CtrlBench* bench : {&library, &hand}) bench->Set(false, kRequests[0], integerMode, milliseconds(300));
        } else if (!library.Execute() && library.Ready()) {
            const int request = kRequests[started++ % kCount];
            for (CtrlBench* bench : {&library, &hand}) bench->Set(true, request, integerMode, milliseconds(300));
        }
        for (CtrlBench* bench : {&library, &hand}) PullCableNearTheEnd(bench->Plc(), scan, scans);
        library.Scan();
        hand.Scan();
        auto& fb = library.Fb();
        const CtrlHand& c = hand.Hand();
        const auto offset = pac::sim::ModuleLayout::kCtrlOffset;
        if (library.Plc().ToPac().Module8(offset) != hand.Plc().ToPac().Module8(offset)) {
            return "scan " + std::to_string(scan) + ": the module differs";
        }
        const bool same =
            (fb->DONE.value != 0) == (c.done != 0) && (fb->BUSY.value != 0) == (c.busy != 0) &&
            (fb->ERROR.value != 0) == (c.error != 0) && fb->ERRORID.value == c.errorId &&
            static_cast<int>(fb->ERRORSOURCE.value) == c.errorSource && (fb->READY.value != 0) == (c.ready != 0) &&
            (fb->BATTERYOK.value != 0) == (c.batteryOk != 0) && (fb->SYSTEMERROR.value != 0) == (c.systemError != 0) &&
            (fb->AUTOMATICACTIVE.value != 0) == (c.automaticActive != 0) &&
            (fb->AUTOMATICSTOPPED.value != 0) == (c.automaticStopped != 0) &&
            (fb->ONLINEACTIVE.value != 0) == (c.onlineActive != 0) &&
            (fb->ONLINESTOPPED.value != 0) == (c.onlineStopped != 0) &&
            (fb->INTEGERMODEACTIVE.value != 0) == (c.integerModeActive != 0) &&
            fb->SYSTEMERRORNUMBER.value == c.systemErrorNumber && (fb->MODECHANGE.value != 0) == (c.modeChange != 0);
        if (!same) return "scan " + std::to_string(scan) + ": an output differs";
    }
    if (started < kCount || done < 3 || errors < 2) {
        return "fewer than every request, three Done and two errors in " + std::to_string(scans) + " scans";
    }
    return "";
}

std::string CompareWithHandWritten(const pac::RigTiming& timing, int scans) {
    pac::PacRig library(timing);
    auto cmd = PAC_FB(FB_PAC_CMD);
    CommandInputs libraryIn;
    CallLibrary(library, cmd, libraryIn, CycleCheckedCommand);
    // The hand-written handshake knows no PLC cold start: the library's channel starts past its first
    // handshake, the parked read (docs/fb/FB_PAC_Cmd.md, "After a PLC cold start").
    library.CmdInterface()->CHANNEL.value.FIRSTREADDONE = TRUE;
    library.Start();
    pac::PacRig hand(timing);
    CmdHandshake hs;
    CmdHandshakeInit(&hs);
    CommandInputs handIn;
    CallHandWritten(hand, hs, handIn, CycleCheckedCommand);
    hand.Start();
    for (int scan = 1; scan <= scans; ++scan) {
        library.Scan();
        hand.Scan();
        const auto& channel = library.Channel();
        const bool same = library.ToPac().Cmd() == hand.ToPac().Cmd() && (cmd->DONE.value != 0) == (hs.done != 0) &&
                          (cmd->BUSY.value != 0) == (hs.busy != 0) && (cmd->ERROR.value != 0) == (hs.error != 0) &&
                          cmd->ERRORID.value == hs.errorId && static_cast<int>(cmd->ERRORSOURCE.value) == hs.errorSource &&
                          cmd->ACKDATA.value == hs.ackData && (cmd->ACKNOWLEDGED.value != 0) == (hs.acknowledged != 0) &&
                          channel.HISTORYCOUNT == hs.historyCount;
        if (!same) return "scan " + std::to_string(scan) + ": the module or an output differs";
        if (hs.historyCount > 0) {
            const auto& a = channel.HISTORY.table[(channel.HISTORYNEXT + 15) % 16];
            const auto& b = hs.history[(hs.historyNext + 15) % 16];
            if (a.CODE != b.code || a.PARAM != b.param || a.DATA != b.data || a.ACKDATA != b.ackData ||
                a.ERRORID != b.errorId || a.SCANSTOACK != b.scansToAck || a.SCANSTOEND != b.scansToEnd) {
                return "scan " + std::to_string(scan) + ": the handshake history differs";
            }
        }
    }
    if (libraryIn.started < 3) return "fewer than three jobs in " + std::to_string(scans) + " scans";
    return "";
}

WorkloadResult RunWorkload(const std::string& name, int scans) {
    static const std::map<std::string, std::function<WorkloadResult(int)>> workloads = {
        {"cmd-idle", [](int n) { return CmdWorkload(false, n); }},
        {"cmd-job", [](int n) { return CmdWorkload(true, n); }},
        {"c-idle", [](int n) { return HandWrittenWorkload(false, n); }},
        {"c-job", [](int n) { return HandWrittenWorkload(true, n); }},
        {"ctrl-idle", [](int n) { return CtrlWorkload(false, false, n); }},
        {"ctrl-job", [](int n) { return CtrlWorkload(true, false, n); }},
        {"ctrl-c-idle", [](int n) { return CtrlWorkload(false, true, n); }},
        {"ctrl-c-job", [](int n) { return CtrlWorkload(true, true, n); }},
        {"axis-idle", [](int n) { return AxisWorkload(false, false, n); }},
        {"axis-job", [](int n) { return AxisWorkload(true, false, n); }},
        {"axis-c-idle", [](int n) { return AxisWorkload(false, true, n); }},
        {"axis-c-job", [](int n) { return AxisWorkload(true, true, n); }},
        {"automatic-idle", [](int n) { return AutomaticWorkload(false, n); }},
        {"automatic-job", [](int n) { return AutomaticWorkload(true, n); }},
        {"plant-pac1", [](int n) { return PlantWorkload(milliseconds(1), n); }},
        {"plant-pac10", [](int n) { return PlantWorkload(milliseconds(10), n); }},
    };
    const std::string plants = "plants-";
    if (name.rfind(plants, 0) == 0) {
        // "plants-N" at the default controller cycle of 10 ms, "plants-N-pacM" at M ms.
        char* rest = nullptr;
        const long count = std::strtol(name.c_str() + plants.size(), &rest, 10);
        long pacMs = 10;
        if (std::string(rest).rfind("-pac", 0) == 0) pacMs = std::strtol(rest + 4, &rest, 10);
        if (count >= 1 && pacMs >= 1 && *rest == '\0') {
            return PlantsWorkload(static_cast<int>(count), milliseconds(pacMs), scans);
        }
    }
    auto it = workloads.find(name);
    if (it == workloads.end()) throw std::invalid_argument("no workload '" + name + "'");
    return it->second(scans);
}

}  // namespace pac::bench
