#include "mc_axes.hpp"

#include <chrono>
#include <type_traits>

#include "pac/iec_time.hpp"

namespace pac::scenario {

namespace {

constexpr float kMaxVelocity = 1000.0F;       // the simulator's axis parameter 1, AE/s
constexpr float kMaxAcceleration = 10000.0F;  // axis parameter 6, AE/s2

// The PLCopen output pins every Execute block has, read alike.
struct BlockPins {
    bool execute = false;
    bool busy = false;
    bool done = false;
    bool error = false;
    bool aborted = false;
    std::uint16_t errorId = 0;
};

template <class Fb>
BlockPins PinsOf(const pac::FbInstance<Fb>& fb) {
    BlockPins p;
    p.execute = fb->EXECUTE.value != 0;
    p.busy = fb->BUSY.value != 0;
    p.done = fb->DONE.value != 0;
    p.error = fb->ERROR.value != 0;
    if constexpr (!std::is_same_v<Fb, MC_RESET>) p.aborted = fb->COMMANDABORTED.value != 0;
    p.errorId = static_cast<std::uint16_t>(fb->ERRORID.value);
    return p;
}

}  // namespace

struct McAxes::Axis {
    pac::FbInstance<FB_PAC_MCAXIS> cyclic = PAC_FB(FB_PAC_MCAXIS);
    pac::FbInstance<MC_POWER> power = PAC_FB(MC_POWER);
    pac::FbInstance<MC_HOME> home = PAC_FB(MC_HOME);
    pac::FbInstance<MC_MOVEABSOLUTE> absolute = PAC_FB(MC_MOVEABSOLUTE);
    pac::FbInstance<MC_MOVERELATIVE> relative = PAC_FB(MC_MOVERELATIVE);
    pac::FbInstance<MC_HALT> halt = PAC_FB(MC_HALT);
    pac::FbInstance<MC_STOP> stop = PAC_FB(MC_STOP);
    pac::FbInstance<MC_RESET> reset = PAC_FB(MC_RESET);
    std::string last = "MC_Power";  // the block whose pins the samples show

    ST_PAC_AXISREF& Ref() { return cyclic->AXIS.value; }

    template <class Fb>
    void Call(pac::PacRig& plc, pac::FbInstance<Fb>& fb) {
        plc.Task().AddProgram([this, &fb] {
            fb->AXIS.value = Ref();
            fb();
            Ref() = fb->AXIS.value;
        });
    }

    BlockPins Pins() const {
        if (last == "MC_Home") return PinsOf(home);
        if (last == "MC_MoveAbsolute") return PinsOf(absolute);
        if (last == "MC_MoveRelative") return PinsOf(relative);
        if (last == "MC_Halt") return PinsOf(halt);
        if (last == "MC_Stop") return PinsOf(stop);
        if (last == "MC_Reset") return PinsOf(reset);
        return {};
    }

    void SetExecute(const std::string& block, bool on) {
        const BOOL value = on ? TRUE : FALSE;
        if (block == "MC_Home") home->EXECUTE.value = value;
        if (block == "MC_MoveAbsolute") absolute->EXECUTE.value = value;
        if (block == "MC_MoveRelative") relative->EXECUTE.value = value;
        if (block == "MC_Halt") halt->EXECUTE.value = value;
        if (block == "MC_Stop") stop->EXECUTE.value = value;
        if (block == "MC_Reset") reset->EXECUTE.value = value;
    }
};

McAxes::McAxes(pac::PacRig& plc, int axes, std::function<void(FB_PAC_MCAXIS&)> wire) {
    for (int k = 1; k <= axes; ++k) axes_.push_back(std::make_unique<Axis>());
    for (int k = 1; k <= axes; ++k) {
        Axis& a = At(k);
        a.cyclic->MAXVELOCITY.value = kMaxVelocity;
        a.cyclic->MAXACCELERATION.value = kMaxAcceleration;
        plc.CallAxis(a.cyclic, k, [&a, wire] { wire(a.cyclic.Data()); });
        a.Call(plc, a.power);
        a.Call(plc, a.home);
        a.Call(plc, a.absolute);
        a.Call(plc, a.relative);
        a.Call(plc, a.halt);
        a.Call(plc, a.stop);
        a.Call(plc, a.reset);
    }
}

McAxes::~McAxes() = default;

McAxes::Axis& McAxes::At(int axis) { return *axes_.at(static_cast<std::size_t>(axis - 1)); }

bool McAxes::OwnsModule(int axis) { return At(axis).cyclic->OWNSMODULE.value != 0; }

void McAxes::Begin(const AxisJob& job) {
    Axis& a = At(job.axis);
    if (job.enable) a.power->ENABLE.value = *job.enable ? TRUE : FALSE;
    const std::string block = job.resetError ? "MC_Reset" : job.command;
    if (block.empty()) return;
    const auto position = static_cast<float>(job.position);
    const float velocity = static_cast<float>(job.velocity) * kMaxVelocity / 1000.0F;
    const float acceleration = static_cast<float>(job.acceleration) * kMaxAcceleration / 1000.0F;
    a.home->POSITION.value = 0.0F;
    a.absolute->POSITION.value = position;
    a.absolute->VELOCITY.value = velocity;
    a.absolute->ACCELERATION.value = acceleration;
    a.relative->POSITION.value = position;
    a.relative->VELOCITY.value = velocity;
    a.relative->ACCELERATION.value = acceleration;
    a.cyclic->TIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(job.timeoutMs));
    a.last = block;
    a.SetExecute(block, true);
}

bool McAxes::Finished(const AxisJob& job) {
    Axis& a = At(job.axis);
    if (job.HasJob() || job.resetError) {
        const BlockPins p = a.Pins();
        return p.done || p.error || p.aborted;
    }
    return (a.power->STATUS.value != 0) == job.enable.value_or(false);
}

void McAxes::End(const AxisJob& job) { At(job.axis).SetExecute(job.resetError ? "MC_Reset" : job.command, false); }

void McAxes::Fill(AxisSample& sample) {
    Axis& a = At(sample.axis);
    const BlockPins p = a.Pins();
    sample.enable = a.power->ENABLE.value != 0;
    sample.execute = p.execute && a.last != "MC_Reset";
    sample.busy = p.busy;
    sample.done = p.done;
    sample.error = p.error;
    sample.aborted = p.aborted;
    sample.errorId = p.errorId;
    sample.enabled = a.power->STATUS.value != 0;
    sample.resetError = a.reset->EXECUTE.value != 0;
    sample.actualPosition = a.Ref().ACTUALPOSITION;
    sample.integerMode = a.cyclic->INTEGERMODE.value != 0;
}

void McAxes::Take(int axis, AxisOutcome& outcome) {
    Axis& a = At(axis);
    const BlockPins p = a.Pins();
    outcome.done = p.done;
    outcome.error = p.error;
    outcome.aborted = p.aborted;
    outcome.errorId = p.errorId;
    outcome.enabled = a.power->STATUS.value != 0;
    outcome.referenced = a.Ref().STATUS.REFERENCED != 0;
    outcome.position = a.Ref().ACTUALPOSITION;
}

}  // namespace pac::scenario
