// The FBs built on FB_PAC_Cmd (the element FBs, the command-set FBs) and FB_PAC_Ctrl in a PLC program as free as
// real ones (docs/fb/FB_PAC_Cmd.md and FB_PAC_Ctrl.md, "The calling contract"): FB_PAC_WriteIntReg,
// FB_PAC_ReadIntReg, FB_PAC_MoveAxisAbsolute, FB_PAC_MoveAxisRelative and FB_PAC_StopAxis (each with
// FreeInterface drawn per command), FB_PAC_ReadAxisValue and FB_PAC_SetLimitSwitchMonitoring on
// one CMD interface, in a call order drawn anew every scan, and FB_PAC_Ctrl on the CTRL module asking for ONLINE,
// a stop and a cancel now and then; each FB called or left out independently in every scan (runs of 1 to 6
// scans), edged when idle, Execute falling while Busy, a command FB now and then given up for good (the program
// calls a fresh instance from then on). The ledgers: the commands the simulated PA-CONTROL took on its CMD
// interface (its exchange log) and the operating status it showed after every scan. The property: an FB ends
// Done only if the controller took exactly its command (code, parameter, data) after this Execute edge, or for
// FB_PAC_Ctrl reached the requested status after it; a move only once its axis stands at the target (for 0A89:
// the controller's end report at its own acknowledged start plus the distance); a read ends with its
// register's or axis parameter's own value; Busy ends within
// the documented bound; the PLCopen rules hold on every call. FB_PAC_JogAxis on an axis of its own, its button
// (Traverse) pressed when the FB is not Busy and held up to past its MaxTime, its calls left out like the others':
// no start (0A90 / 0A91) and no keep-alive before the stop is taken by the controller later than a round trip after
// the call that saw the button released; Done only if the controller took the stop (0A9A) after the last start it
// took since the press, or took no start; Busy, Done and Error never together, Busy within its bound. Every
// random choice comes from the seed in the test's name.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "channel_case.hpp"
#include "free_caller.hpp"
#include "free_commands.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/pac_rig.hpp"
#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/command_table.hpp"
#include "pac/sim/operating_status.hpp"
#include "real_bits.hpp"
#include "rig_timing.hpp"

namespace test_cmd_fbs_free_program_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using pac::test::FreeCaller;
using pac::test::FreeCommand;
namespace code = pac::sim::code;
namespace status = pac::sim::status;

// The program's FBs; kJog (FB_PAC_JogAxis) has no Block of its own (PlaceJog).
enum class Kind { kWrite, kRead, kMove, kStop, kCtrl, kMoveRel, kValueRead, kMonitor, kJog };

// One FB of the program and what its present command asked for.
struct Block {
    Kind kind;
    std::unique_ptr<FreeCaller> caller;
    FreeCommand command;     // its CMD command (FreeInterface decides between the two codes of a move / stop)
    bool freeInterface = false;
    E_PAC_CTRLREQUEST request = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
    std::size_t ledgerAtEdge = 0;
    std::chrono::nanoseconds edgeTime{0};
    bool missed = false;
};

class FreeCmdFbProgram {
public:
    explicit FreeCmdFbProgram(const pac::test::ChannelCase& c)
        : case_(c), layout_{true, 0}, rig_(pac::test::RigTimingOf(c.sharing.timing), ConfigOf(c), layout_), random_(c.seed) {
        for (Kind k : {Kind::kWrite, Kind::kRead, Kind::kMove, Kind::kStop, Kind::kCtrl, Kind::kMoveRel,
                       Kind::kValueRead, Kind::kMonitor}) {
            static const char* names[] = {"FB_PAC_WriteIntReg", "FB_PAC_ReadIntReg", "FB_PAC_MoveAxisAbsolute",
                                          "FB_PAC_StopAxis", "FB_PAC_Ctrl", "FB_PAC_MoveAxisRelative",
                                          "FB_PAC_ReadAxisValue", "FB_PAC_SetLimitSwitchMonitoring"};
            pac::test::FreeCallerOdds odds;
            odds.newCommand = k == Kind::kCtrl ? 400 : (k == Kind::kStop ? 60 : 6);
            odds.earlyFall = 200;
            odds.abandon = k == Kind::kCtrl ? 0 : 500;
            blocks_.push_back(std::make_unique<Block>());
            blocks_.back()->kind = k;
            blocks_.back()->caller = std::make_unique<FreeCaller>(names[static_cast<int>(k)], random_, odds, log_);
        }
        auto& pac = rig_.Controller();
        pac.SystemParameters().Set(pac::sim::sysparam::kStopInput, kExternalStopInput);
        pac.SystemParameters().Set(pac::sim::sysparam::kNumberOfAxes, kJogAxis);
        pac.Io().inputs.Set(kExternalStopInput, true);
        for (int n = 0; n < 4; ++n) {
            pac.Io().intRegisters.SetInt(pac::test::kFreeReadRegisters + n, pac::test::kFreeReadBase + n);
        }
        jog_.draw = [this](std::uint32_t n) { return std::uniform_int_distribution<std::uint32_t>(0, n - 1)(random_); };
        rig_.CmdInterface()->TWOSTEPWRITE.value = c.twoStepWrite ? TRUE : FALSE;
        rig_.CallImage([this](const pac::sim::ProcessImage& fromPac, pac::sim::ProcessImage& toPac) { CallCtrl(fromPac, toPac); });
        rig_.CallCmdProgram([this](ST_PAC_CMDCHANNEL& channel) { Program(channel); });
        rig_.Start();
        rig_.Task().AddProgram([this] {
            statusSeen_[rig_.Controller().OperatingStatus()] = rig_.Now();
            if (free_) WatchJog();
        });
    }

    // ONLINE through FB_PAC_Ctrl called in every scan, as a program starts.
    void Prepare() {
        ASSERT_GT(rig_.ScanUntil([this] { return ctrl_->READY.value != 0; }, 20000), 0) << "Ready";
        rig_.Scan(case_.sharing.timing.ScansFor(20ms));
        ctrl_->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
        ctrl_->EXECUTE.value = TRUE;
        ASSERT_GT(rig_.ScanUntil([this] { return ctrl_->DONE.value || ctrl_->ERROR.value; }, 20000), 0);
        ASSERT_TRUE(ctrl_->DONE.value) << "START_ONLINE: ErrorID 16#" << std::hex << ctrl_->ERRORID.value;
        ctrl_->EXECUTE.value = FALSE;
        rig_.Scan(case_.sharing.timing.ScansFor(30ms));
        free_ = true;
    }

    void Scan(int n) {
        for (int i = 0; i < n; ++i) {
            rig_.Scan();
            ++scans_;
        }
    }

    const std::vector<std::string>& Violations() const { return log_.Texts(); }
    int Dones(Kind k) const { return dones_[static_cast<int>(k)]; }
    int SkipsWhileBusy() const { return pac::test::SkipsWhileBusyOf(blocks_); }
    int EndedAfterSkip() const { return endedAfterSkip_; }
    int JogsStopped() const { return jog_.stopped; }
    int JogsReleasedEarly() const { return jog_.releasedEarly; }
    int JogStarts() const { return jog_.starts; }
    int JogSkipsWhileBusy() const { return jog_.skipsWhileBusy; }

private:
    static constexpr int kExternalStopInput = 7;
    static constexpr std::uint16_t kRelativeAxis = 3;
    static constexpr std::uint16_t kJogAxis = 4;  // FB_PAC_JogAxis's own
    static constexpr auto kJogMaxTime = 1s;
    static constexpr auto kJogTimeout = 3s;  // the start waits for an empty queue behind the moves of the others

    static pac::sim::PaControlConfig ConfigOf(const pac::test::ChannelCase& c) {
        pac::sim::PaControlConfig config = c.sharing.Config();
        config.logCapacity = 10000000;
        return config;
    }

    Block& B(Kind k) { return *blocks_[static_cast<std::size_t>(k)]; }

    void NewCommand(Block& b) {
        ++serial_;
        b.freeInterface = b.caller->Draw(2) == 0;
        const auto axis = static_cast<std::uint16_t>(1 + b.caller->Draw(2));
        switch (b.kind) {
            case Kind::kWrite:
                b.command = {code::kPutIntReg, static_cast<std::uint16_t>(1 + b.caller->Draw(4)), static_cast<std::uint32_t>(serial_)};
                break;
            case Kind::kRead:
                b.command = {code::kGetIntReg, static_cast<std::uint16_t>(pac::test::kFreeReadRegisters + b.caller->Draw(4)), 0};
                break;
            case Kind::kMove:
                b.command = {static_cast<std::uint16_t>(b.freeInterface ? 0x0A94 : code::kPosAxisAbsolute), axis,
                             pac::test::BitsOf(static_cast<float>(serial_ % 400) * 0.125F + 0.0625F)};
                break;
            case Kind::kMoveRel: {
                // Axis 3, which only FB_PAC_StopAxis shares with it (the checks of a Done read the axis), back
                // towards 25, a distance of its own.
                const bool down = rig_.Controller().Axes().Motion(kRelativeAxis).Position() > 25.0;
                const float distance = static_cast<float>(serial_ % 80) * 0.0625F + 0.03125F;
                b.command = {b.freeInterface ? code::kStartAxisRelative : code::kPosAxisRelative, kRelativeAxis,
                             pac::test::BitsOf(down ? -distance : distance)};
                break;
            }
            case Kind::kStop:
                b.command = {static_cast<std::uint16_t>(b.freeInterface ? 0x0A9A : code::kStopAxis),
                             static_cast<std::uint16_t>(1 + b.caller->Draw(3)), 0};
                break;
            case Kind::kValueRead:  // an end of the traverse range of axis 1..3 (axis parameters 8, 9)
                b.command = {b.caller->Draw(2) == 0 ? code::kGetTraverseAreaMin : code::kGetTraverseAreaMax,
                             static_cast<std::uint16_t>(1 + b.caller->Draw(3)), 0};
                break;
            case Kind::kMonitor:  // on, as ONLINE has it (5.2.6.22): every axis or one
                b.command = {0x0AA2, static_cast<std::uint16_t>(b.caller->Draw(4)), 1};
                break;
            case Kind::kJog:  // PlaceJog draws its own
                break;
            case Kind::kCtrl: {
                static const E_PAC_CTRLREQUEST requests[] = {E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE,
                                                             E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE,
                                                             E_PAC_CTRLREQUEST__PAC_REQ_STOP, E_PAC_CTRLREQUEST__PAC_REQ_CANCEL};
                b.request = requests[b.caller->Draw(4)];
                break;
            }
        }
    }

    // One FB's place in the program: the plan, its inputs, the call, the checks.
    template <class Fb>
    void Place(Block& b, pac::FbInstance<Fb>& fb, const std::function<void()>& setInputs, const std::function<void()>& call,
               const std::function<pac::FbInstance<Fb>()>& fresh) {
        const bool called = b.caller->Plan(scans_, rig_.Now());
        if (b.caller->Abandoned() && b.caller->Draw(30) == 0) {
            fb = fresh();
            b.caller->Replace();
            return;
        }
        if (b.caller->NewCommand()) NewCommand(b);
        if (!called) {
            b.missed = true;
            return;
        }
        setInputs();
        const auto ended = pac::test::CallFree(*b.caller, fb, BusyBound(b), call, [&] {
            b.ledgerAtEdge = Ledger().size();
            b.edgeTime = rig_.Now();
            b.missed = false;
        });
        if (ended == FreeCaller::Ended::kNo) return;
        if (b.missed) ++endedAfterSkip_;
        if (ended == FreeCaller::Ended::kDone) CheckDone(b);
    }

    void CallCtrl(const pac::sim::ProcessImage& fromPac, pac::sim::ProcessImage& toPac) {
        const std::size_t offset = pac::sim::ModuleLayout::kCtrlOffset;
        auto call = [&] {
            for (std::size_t i = 0; i < 8; ++i) {
                ctrl_->FROMPAC.value.table[i] = fromPac[offset + i];
                ctrl_->TOPAC.value.table[i] = toPac[offset + i];
            }
            ctrl_();
            for (std::size_t i = 0; i < 8; ++i) toPac[offset + i] = ctrl_->TOPAC.value.table[i];
        };
        if (!free_) {
            call();
            return;
        }
        Block& b = B(Kind::kCtrl);
        Place<FB_PAC_CTRL>(b, ctrl_, [&] { ctrl_->REQUEST.value = b.request; }, call, [] { return PAC_FB(FB_PAC_CTRL); });
    }

    void Program(ST_PAC_CMDCHANNEL& channel) {
        if (!free_) return;
        std::shuffle(order_.begin(), order_.end(), random_);
        for (Kind k : order_) {
            if (k == Kind::kJog) {
                PlaceJog(channel);
                continue;
            }
            Block& b = B(k);
            switch (k) {
                case Kind::kWrite:
                    Place<FB_PAC_WRITEINTREG>(b, write_, [&] {
                        write_->NUMBER.value = b.command.param;
                        write_->VALUE.value = static_cast<DINT>(b.command.data);
                    }, [&] { CallOn(channel, write_); }, [] { return PAC_FB(FB_PAC_WRITEINTREG); });
                    break;
                case Kind::kRead:
                    Place<FB_PAC_READINTREG>(b, read_, [&] { read_->NUMBER.value = b.command.param; },
                                             [&] { CallOn(channel, read_); }, [] { return PAC_FB(FB_PAC_READINTREG); });
                    break;
                case Kind::kMove:
                    Place<FB_PAC_MOVEAXISABSOLUTE>(b, move_, [&] {
                        move_->AXIS.value = static_cast<USINT>(b.command.param);
                        move_->POSITION.value = pac::test::FloatOf(b.command.data);
                        move_->FREEINTERFACE.value = b.freeInterface ? TRUE : FALSE;
                    }, [&] { CallOn(channel, move_); }, [] { return PAC_FB(FB_PAC_MOVEAXISABSOLUTE); });
                    break;
                case Kind::kMoveRel:
                    Place<FB_PAC_MOVEAXISRELATIVE>(b, moveRel_, [&] {
                        moveRel_->AXIS.value = static_cast<USINT>(b.command.param);
                        moveRel_->DISTANCE.value = pac::test::FloatOf(b.command.data);
                        moveRel_->FREEINTERFACE.value = b.freeInterface ? TRUE : FALSE;
                    }, [&] { CallOn(channel, moveRel_); }, [] { return PAC_FB(FB_PAC_MOVEAXISRELATIVE); });
                    break;
                case Kind::kValueRead:
                    Place<FB_PAC_READAXISVALUE>(b, value_, [&] {
                        value_->AXIS.value = static_cast<USINT>(b.command.param);
                        value_->KIND.value = b.command.code == code::kGetTraverseAreaMin
                                                 ? E_PAC_AXISVALUE__PAC_AXVAL_TRAVERSE_MIN
                                                 : E_PAC_AXISVALUE__PAC_AXVAL_TRAVERSE_MAX;
                    }, [&] { CallOn(channel, value_); }, [] { return PAC_FB(FB_PAC_READAXISVALUE); });
                    break;
                case Kind::kMonitor:
                    Place<FB_PAC_SETLIMITSWITCHMONITORING>(b, monitor_, [&] {
                        monitor_->AXIS.value = static_cast<USINT>(b.command.param);
                        monitor_->MONITOR.value = TRUE;
                    }, [&] { CallOn(channel, monitor_); }, [] { return PAC_FB(FB_PAC_SETLIMITSWITCHMONITORING); });
                    break;
                default:
                    Place<FB_PAC_STOPAXIS>(b, stop_, [&] {
                        stop_->AXIS.value = static_cast<USINT>(b.command.param);
                        stop_->FREEINTERFACE.value = b.freeInterface ? TRUE : FALSE;
                    }, [&] { CallOn(channel, stop_); }, [] { return PAC_FB(FB_PAC_STOPAXIS); });
                    break;
            }
        }
    }

    template <class Fb>
    static void CallOn(ST_PAC_CMDCHANNEL& channel, pac::FbInstance<Fb>& fb) {
        fb->CHANNEL.value = channel;
        fb();
        channel = fb->CHANNEL.value;
    }

    const std::vector<FreeCommand>& Ledger() { return ledger_.Read(rig_.Controller().Log()); }

    void CheckDone(Block& b) {
        ++dones_[static_cast<int>(b.kind)];
        if (b.kind == Kind::kCtrl) {
            statusSeen_[rig_.Controller().OperatingStatus()] = rig_.Now();  // the watch runs at the end of the scan
            const std::uint8_t wanted = b.request == E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE
                                            ? status::kOnline
                                            : (b.request == E_PAC_CTRLREQUEST__PAC_REQ_STOP ? status::kOnlineStopped : status::kHome);
            const auto seen = statusSeen_.find(wanted);
            if (seen == statusSeen_.end() || seen->second < b.edgeTime) {
                log_.Add(scans_, rig_.Now(), "FB_PAC_Ctrl ended Done for request " + std::to_string(b.request) +
                                                 ", but the controller has not shown status " + std::to_string(wanted) +
                                                 " since its edge at " + std::to_string(b.edgeTime.count() / 1000) +
                                                 " us (last seen " +
                                                 (seen == statusSeen_.end() ? std::string("never") : std::to_string(seen->second.count() / 1000)) +
                                                 " us, now " + std::to_string(rig_.Controller().OperatingStatus()) + ")");
            }
            return;
        }
        Ledger();
        const long taken = ledger_.ClaimIndex(b.ledgerAtEdge, b.command);
        if (taken >= 0) {
            if (b.kind == Kind::kMoveRel && b.command.code == code::kPosAxisRelative) CheckRelativeEnd(b, taken);
            const double at = b.kind == Kind::kMove ? rig_.Controller().Axes().Motion(b.command.param).Position() : 0.0;
            if (b.kind == Kind::kMove && std::fabs(at - pac::test::FloatOf(b.command.data)) > 0.001) {
                log_.Add(scans_, rig_.Now(), "FB_PAC_MoveAxisAbsolute ended Done for " + pac::test::Describe(b.command) +
                                                 " with the axis at " + std::to_string(at) +
                                                 "; the controller took since its edge" + ledger_.DescribeFrom(b.ledgerAtEdge));
            }
            if (b.kind == Kind::kValueRead) CheckRangeValue(b);
            if (b.kind == Kind::kRead &&
                static_cast<std::uint32_t>(read_->VALUE.value) != pac::test::FreeReadAnswer(b.command)) {
                log_.Add(scans_, rig_.Now(), "FB_PAC_ReadIntReg ended Done for " + pac::test::Describe(b.command) +
                                                 " with Value " + std::to_string(read_->VALUE.value));
            }
            return;
        }
        log_.Add(scans_, rig_.Now(), b.caller->Name() + " ended Done for " + pac::test::Describe(b.command) +
                                         ", which the controller did not take after its Execute edge");
    }

    // A read of the traverse range ends with the axis parameter's own value (the program writes none).
    void CheckRangeValue(const Block& b) {
        const auto number = b.command.code == code::kGetTraverseAreaMin ? pac::sim::axisparam::kMinTraverseArea
                                                                        : pac::sim::axisparam::kMaxTraverseArea;
        const auto value = rig_.Controller().Axes().Parameters(b.command.param).RealValue(number);
        if (!value || *value != value_->VALUE.value) {
            log_.Add(scans_, rig_.Now(), "FB_PAC_ReadAxisValue ended Done for " + pac::test::Describe(b.command) +
                                             " with Value " + std::to_string(value_->VALUE.value));
        }
    }

    // 0A89 (5.2.6.7): its acknowledgement carries the start position, its END OF PROCESSING report the position
    // where the traverse ended; the move was executed only if that is the start plus the distance.
    void CheckRelativeEnd(const Block& b, long taken) {
        const auto end = pac::test::MoveReports(rig_.Controller().Log(), ledger_.RecordOf(static_cast<std::size_t>(taken)));
        const float distance = pac::test::FloatOf(b.command.data);
        std::string why;
        if (!end.acknowledged) {
            why = "no acknowledgement without a command error";
        } else if (!end.ended) {
            why = "no END OF PROCESSING before the next command";
        } else {
            const float target = end.start + distance;
            if (std::fabs(end.end - target) > 0.001F + std::fabs(target) * 1.0E-6F) {
                why = "its end report at " + std::to_string(end.end) + ", started at " + std::to_string(end.start);
            }
        }
        if (!why.empty()) {
            log_.Add(scans_, rig_.Now(), "FB_PAC_MoveAxisRelative ended Done for " + pac::test::Describe(b.command) +
                                             " (distance " + std::to_string(distance) + ") with " + why);
        }
    }

    // FB_PAC_JogAxis's button and the program's call: the button pressed (1 in 20 scans) in ONLINE while the FB is
    // not Busy, held up to 0.4 s, or (1 in 4) 0.8 to 1.2 s past MaxTime (1 s), from the call that saw it; calls
    // left out in runs of 1 to 6 scans.
    void PlaceJog(ST_PAC_CMDCHANNEL& channel) {
        JogButton& j = jog_;
        // An operator jogs in ONLINE (the interface's OpStatus); the FB_PAC_Ctrl requests may end it meanwhile.
        const bool online = rig_.CmdInterface()->OPSTATUS.value == status::kOnline;
        if (!j.pressed && online && !jogFb_->BUSY.value && j.draw(20) == 0) {
            j.pressed = true;
            j.edgeSeen = false;
            j.holdFor = std::chrono::milliseconds(j.draw(4) == 0 ? 800 + j.draw(400) : j.draw(400));
            j.relative = j.draw(2) == 0;
            const bool up = rig_.Controller().Axes().Motion(kJogAxis).Position() < 5000.0;
            j.target = j.relative ? (up ? 1000.0F : -1000.0F) : (up ? 9000.0F : 1000.0F);
        } else if (j.pressed && j.edgeSeen && rig_.Now() - j.pressedAt >= j.holdFor) {
            j.pressed = false;
        }
        if (j.skip > 0 || j.draw(6) == 0) {
            j.skip = j.skip > 0 ? j.skip - 1 : static_cast<int>(j.draw(6));
            if (jogFb_->BUSY.value) ++j.skipsWhileBusy;
            return;
        }
        jogFb_->TRAVERSE.value = j.pressed ? TRUE : FALSE;
        jogFb_->AXIS.value = kJogAxis;
        jogFb_->TARGET.value = j.target;
        jogFb_->RELATIVE.value = j.relative ? TRUE : FALSE;
        jogFb_->MAXTIME.value = pac::ToIecTime(kJogMaxTime);
        jogFb_->TIMEOUT.value = pac::ToIecTime(kJogTimeout);
        if (j.pressed && !j.edgeSeen && !jogFb_->BUSY.value) {
            j.edgeSeen = true;
            j.releaseSeen = false;
            j.pressedAt = rig_.Now();
            j.ledgerAtEdge = Ledger().size();
        }
        if (!j.pressed && j.edgeSeen && !j.releaseSeen) {
            j.releaseSeen = true;
            j.releasedAt = rig_.Now();
        }
        const bool doneBefore = jogFb_->DONE.value != 0;
        CallOn(channel, jogFb_);
        const bool busy = jogFb_->BUSY.value != 0;
        const bool done = jogFb_->DONE.value != 0;
        if (int{busy} + int{done} + int{jogFb_->ERROR.value != 0} > 1 || (jogFb_->ACTIVE.value && !busy)) {
            log_.Add(scans_, rig_.Now(), "FB_PAC_JogAxis shows Busy, Done, Error or Active together");
        }
        // docs/commands.md, "Manual traverse": MaxTime, the waits for the interface and the acknowledgements of the start and the stop.
        if (busy && rig_.Now() - j.pressedAt > kJogMaxTime + 4 * kJogTimeout + 7 * case_.sharing.timing.PlcCycle() + 100ms) {
            log_.Add(scans_, rig_.Now(), "FB_PAC_JogAxis still Busy " +
                                             std::to_string((rig_.Now() - j.pressedAt) / std::chrono::milliseconds(1)) +
                                             " ms after the press");
        }
        if (done && !doneBefore) CheckJogDone();
    }

    // Done: the controller took a stop of the axis after the last start it took since the press, or no start.
    void CheckJogDone() {
        const auto& ledger = Ledger();
        long lastStart = -1;
        long lastStop = -1;
        for (std::size_t k = jog_.ledgerAtEdge; k < ledger.size(); ++k) {
            if (ledger[k].param != kJogAxis) continue;
            if (IsJogStart(ledger[k])) lastStart = static_cast<long>(k);
            if (ledger[k].code == 0x0A9A) lastStop = static_cast<long>(k);
        }
        if (lastStart < 0) {
            ++jog_.releasedEarly;
        } else if (lastStop > lastStart) {
            ++jog_.stopped;
        } else {
            log_.Add(scans_, rig_.Now(), "FB_PAC_JogAxis ended Done, but the controller took no stop after its start" +
                                             ledger_.DescribeFrom(jog_.ledgerAtEdge));
        }
    }

    static bool IsJogStart(const FreeCommand& c) { return c.code == 0x0A90 || c.code == 0x0A91; }

    // After every scan: what the controller took since the last scan, against the jog button's release.
    void WatchJog() {
        const auto& ledger = Ledger();
        const auto late = jog_.releasedAt + 3 * case_.sharing.timing.PlcCycle() + 2 * case_.sharing.timing.PacCycle() +
                          2 * case_.sharing.timing.Latency() + 5ms;
        for (; jog_.ledgerSeen < ledger.size(); ++jog_.ledgerSeen) {
            const FreeCommand& c = ledger[jog_.ledgerSeen];
            if (c.param == kJogAxis && IsJogStart(c)) ++jog_.starts;
            if (c.param != kJogAxis || !jog_.releaseSeen) continue;
            const auto at = rig_.Controller().Log().Records()[ledger_.RecordOf(jog_.ledgerSeen)].time;
            if (c.code == 0x0A9A) jog_.stopTaken = true;
            const bool keepAlive = c.code == 0x0A92 && !jog_.stopTaken;
            if (at > late && (IsJogStart(c) || keepAlive)) {
                log_.Add(scans_, rig_.Now(), "the controller took " + pac::test::Describe(c) + " " +
                                                 std::to_string((at - jog_.releasedAt) / std::chrono::microseconds(1)) +
                                                 " us after FB_PAC_JogAxis saw the button released");
            }
        }
        if (!jog_.releaseSeen) jog_.stopTaken = false;
    }

    // FB_PAC_Cmd.md: the waits for the interface and the acknowledgement (Timeout each), END OF PROCESSING
    // (EndTimeout; FreeInterface: a status read every PollInterval until in position); FB_PAC_Ctrl.md: its
    // Timeout. Plus the longest skip and a round trip.
    std::chrono::nanoseconds BusyBound(const Block& b) const {
        const auto slack = 7 * case_.sharing.timing.PlcCycle() + 100ms;
        return (b.kind == Kind::kCtrl ? 10s : 1s + 1s + 60s) + slack;
    }

    pac::test::ChannelCase case_;
    pac::sim::ModuleLayout layout_;
    pac::PacRig rig_;
    std::mt19937_64 random_;
    pac::test::ViolationLog log_;
    std::vector<std::unique_ptr<Block>> blocks_;
    std::vector<Kind> order_ = {Kind::kWrite,   Kind::kRead,      Kind::kMove,    Kind::kStop,
                                Kind::kMoveRel, Kind::kValueRead, Kind::kMonitor, Kind::kJog};
    pac::FbInstance<FB_PAC_CTRL> ctrl_ = PAC_FB(FB_PAC_CTRL);
    pac::FbInstance<FB_PAC_WRITEINTREG> write_ = PAC_FB(FB_PAC_WRITEINTREG);
    pac::FbInstance<FB_PAC_READINTREG> read_ = PAC_FB(FB_PAC_READINTREG);
    pac::FbInstance<FB_PAC_MOVEAXISABSOLUTE> move_ = PAC_FB(FB_PAC_MOVEAXISABSOLUTE);
    pac::FbInstance<FB_PAC_STOPAXIS> stop_ = PAC_FB(FB_PAC_STOPAXIS);
    pac::FbInstance<FB_PAC_MOVEAXISRELATIVE> moveRel_ = PAC_FB(FB_PAC_MOVEAXISRELATIVE);
    pac::FbInstance<FB_PAC_READAXISVALUE> value_ = PAC_FB(FB_PAC_READAXISVALUE);
    pac::FbInstance<FB_PAC_SETLIMITSWITCHMONITORING> monitor_ = PAC_FB(FB_PAC_SETLIMITSWITCHMONITORING);
    pac::FbInstance<FB_PAC_JOGAXIS> jogFb_ = PAC_FB(FB_PAC_JOGAXIS);
    // FB_PAC_JogAxis's button and what the test saw of it.
    struct JogButton {
        std::function<std::uint32_t(std::uint32_t)> draw;
        bool pressed = false;
        bool edgeSeen = false;     // a call saw the press (the FB's edge)
        bool releaseSeen = false;  // a call saw the button released after it
        bool stopTaken = false;    // the controller took 0A9A for the axis since the release
        bool relative = false;
        float target = 0.0F;
        std::chrono::nanoseconds holdFor{0};
        std::chrono::nanoseconds pressedAt{0};
        std::chrono::nanoseconds releasedAt{0};
        std::size_t ledgerAtEdge = 0;
        std::size_t ledgerSeen = 0;
        int skip = 0;
        int skipsWhileBusy = 0;
        int stopped = 0;
        int releasedEarly = 0;
        int starts = 0;  // 0A90 / 0A91 the controller took
    } jog_;
    bool free_ = false;
    long scans_ = 0;
    int serial_ = 0;
    pac::test::CmdLedger ledger_;
    std::map<std::uint8_t, std::chrono::nanoseconds> statusSeen_;
    int dones_[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    int endedAfterSkip_ = 0;
};

class CmdFbsFreeProgram : public ::testing::TestWithParam<pac::test::ChannelCase> {};

TEST_P(CmdFbsFreeProgram, DoneOnlyForTheCommandTheControllerTook) {
    FreeCmdFbProgram program(GetParam());
    program.Prepare();
    ASSERT_FALSE(HasFatalFailure());
    program.Scan(std::max(GetParam().sharing.timing.ScansFor(8s), 4800));
    for (const std::string& v : program.Violations()) ADD_FAILURE() << v;
    EXPECT_GT(program.SkipsWhileBusy(), 20);
    EXPECT_GT(program.EndedAfterSkip(), 5);
    for (Kind k :
         {Kind::kWrite, Kind::kRead, Kind::kMove, Kind::kCtrl, Kind::kMoveRel, Kind::kValueRead, Kind::kMonitor}) {
        EXPECT_GT(program.Dones(k), 0) << "kind " << static_cast<int>(k);
    }
    // The jog's start waits for an empty queue, which the others' commands leave rarely: a start or a release
    // before it in every case.
    EXPECT_GT(program.JogStarts() + program.JogsReleasedEarly(), 0);
    EXPECT_GT(program.JogSkipsWhileBusy(), 3);
}

std::vector<pac::test::ChannelCase> CmdFbsFreeCases() {
    return pac::test::ChannelCases({{1, 10, 0}, {2, 3, 1}, {5, 1, 3}, {2, 3, 1, 1500, 606}}, true);
}

INSTANTIATE_TEST_SUITE_P(Readings, CmdFbsFreeProgram, ::testing::ValuesIn(CmdFbsFreeCases()), pac::test::ChannelCaseName);

}  // namespace
}  // namespace test_cmd_fbs_free_program_sim
