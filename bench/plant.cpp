#include "plant.hpp"

#include <stdexcept>
#include <string>

#include "pac/sim/parameter_table.hpp"

namespace pac::bench {

namespace {

constexpr int kExternalStopInput = 1;  // system parameter 4 (5.2.1.3): ONLINE needs its input high
constexpr WORD kReadIntReg = 0x1906;   // cmd_get_int_reg (5.2.4.12)
constexpr float kTargetA = 0.0F;
constexpr float kTargetB = 20.0F;

pac::RigTiming TimingOf(const PlantOptions& o) {
    pac::RigTiming timing;
    timing.plcCycle = o.plcCycle;
    timing.pacCycle = o.pacCycle;
    timing.latencyCycles = o.latencyCycles;
    return timing;
}

// The other of the two targets: the one farther from where the axis is.
float NextTarget(float actualPosition) { return actualPosition < (kTargetA + kTargetB) / 2 ? kTargetB : kTargetA; }

template <class Fb>
bool Final(const pac::FbInstance<Fb>& fb) {
    return fb->DONE.value || fb->ERROR.value;
}

}  // namespace

Plant::Plant(const PlantOptions& options)
    : options_(options), plc_(TimingOf(options), {}, pac::sim::ModuleLayout{true, options.axes}) {
    AllowOnline(plc_.Controller());
    plc_.Call(cmd_, [this] { NextCommand(); });
    plc_.CallCtrl(ctrl_, [this] { CtrlProgram(); });
    for (int k = 1; k <= options.axes && options.handWrittenAxes; ++k) {
        handAxes_.push_back(std::make_unique<AxisHand>());
        AxisHandInit(&HandAxis(k));
        HandAxis(k).enable = 1;
        HandAxis(k).command = E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE;
        const std::size_t offset = plc_.Layout().AxisOffset(k);
        plc_.CallImage([this, k, offset](const pac::sim::ProcessImage& fromPac, pac::sim::ProcessImage& toPac) {
            NextHandMove(k);
            AxisHandScan(&HandAxis(k), toPac.Data() + offset, fromPac.Data() + offset, plc_.Now().count());
        });
    }
    for (int k = 1; k <= options.axes && !options.handWrittenAxes; ++k) {
        axes_.push_back(std::make_unique<pac::FbInstance<FB_PAC_AXIS>>(PAC_FB(FB_PAC_AXIS)));
        Axis(k)->ENABLE.value = TRUE;
        Axis(k)->COMMAND.value = E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE;
        plc_.CallAxis(Axis(k), k, [this, k] { NextMove(k); });
    }
    plc_.Start();
}

int Plant::ScansFor(std::chrono::milliseconds time) const {
    return static_cast<int>(std::chrono::nanoseconds(time) / options_.plcCycle);
}

void Plant::GoOnline() {
    if (ScanUntil([this] { return Online(); }, ScansFor(std::chrono::milliseconds(1000))) < 0) {
        throw std::runtime_error("Plant: ONLINE not reached within a second");
    }
}

// As a PLC program does it: the request once the controller shows Ready and a little later (the first
// control word is only the reference for the CTRL edges), the FBs' jobs once ONLINE has lasted longer than
// the controller's update time (2.3.4).
void Plant::CtrlProgram() {
    switch (phase_) {
        case Phase::kBoot:
            if (ctrl_->READY.value) {
                phase_ = Phase::kSettle;
                phaseScans_ = ScansFor(std::chrono::milliseconds(20));
            }
            break;
        case Phase::kSettle:
            if (--phaseScans_ <= 0) {
                ctrl_->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
                ctrl_->EXECUTE.value = TRUE;
                phase_ = Phase::kRequest;
            }
            break;
        case Phase::kRequest:
            if (ctrl_->ERROR.value) throw std::runtime_error("Plant: START_ONLINE ended with an error");
            if (ctrl_->DONE.value) {
                ctrl_->EXECUTE.value = FALSE;
                phase_ = Phase::kSettleOnline;
                phaseScans_ = ScansFor(std::chrono::milliseconds(30));
            }
            break;
        case Phase::kSettleOnline:
            if (--phaseScans_ <= 0) {
                commands_ = options_.commands;
                moves_ = options_.moves;
                phase_ = Phase::kRunning;
            }
            break;
        case Phase::kRunning:
            break;
    }
}

void Plant::NextCommand() {
    if (cmd_->EXECUTE.value) {
        if (!Final(cmd_)) return;
        commandsDone_ += cmd_->DONE.value ? 1 : 0;
        cmd_->EXECUTE.value = FALSE;  // one scan low: the final output clears
    } else if (commands_) {
        cmd_->CODE.value = kReadIntReg;
        cmd_->PARAM.value = 1;
        cmd_->EXECUTE.value = TRUE;
    }
}

void Plant::NextMove(int k) {
    auto& axis = Axis(k);
    // As a PLC program wires FB_PAC_Axis: the operating status from the CMD reply (without it the FB
    // leaves the module alone and no axis moves) and FB_PAC_Ctrl's ModeChange.
    axis->OPSTATUS.value = plc_.CmdInterface()->OPSTATUS.value;
    axis->MODECHANGE.value = ctrl_->MODECHANGE.value;
    if (axis->EXECUTE.value) {
        if (!Final(axis) && !axis->COMMANDABORTED.value) return;
        movesDone_ += axis->DONE.value ? 1 : 0;
        axis->EXECUTE.value = FALSE;
    } else if (moves_) {
        axis->POSITION.value = NextTarget(axis->ACTUALPOSITION.value);
        axis->EXECUTE.value = TRUE;
    }
}

void Plant::NextHandMove(int k) {
    AxisHand& axis = HandAxis(k);
    axis.opStatus = plc_.CmdInterface()->OPSTATUS.value;
    axis.modeChange = ctrl_->MODECHANGE.value;
    // The same program as NextMove's, on the hand-written C's pins.
    if (axis.execute) {
        if (!axis.done && !axis.error && !axis.commandAborted) return;
        movesDone_ += axis.done ? 1 : 0;
        axis.execute = 0;
    } else if (moves_) {
        axis.position = NextTarget(axis.actualPosition);
        axis.execute = 1;
    }
}

void AllowOnline(pac::sim::PaControl& pac) {
    if (pac.SystemParameters().Set(pac::sim::sysparam::kStopInput, kExternalStopInput) !=
        pac::sim::ParameterTable::SetResult::kOk) {
        throw std::runtime_error("the simulator refuses the external stop input");
    }
    pac.Io().inputs.Set(kExternalStopInput, true);
}

std::vector<std::unique_ptr<Plant>> OnlinePlants(int count, std::chrono::nanoseconds pacCycle) {
    std::vector<std::unique_ptr<Plant>> plants;
    PlantOptions options;
    options.pacCycle = pacCycle;
    for (int i = 0; i < count; ++i) plants.push_back(std::make_unique<Plant>(options));
    for (int scan = 0; scan < 1000; ++scan) {
        bool all = true;
        for (auto& plant : plants) {
            plant->Scan();
            all = all && plant->Online();
        }
        if (all) break;
    }
    for (auto& plant : plants) {
        if (!plant->Online()) throw std::runtime_error("a plant did not reach ONLINE");
    }
    for (int scan = 0; scan < 200; ++scan) {
        for (auto& plant : plants) plant->Scan();
    }
    return plants;
}

}  // namespace pac::bench
