// The simulated PA-CONTROL's cycle (see pa_control.hpp and docs/sim_controller.md).
#include "pac/sim/pa_control.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

namespace pac::sim {

namespace {

const PaControlConfig& CheckedConfig(const PaControlConfig& config) {
    if (config.bootTime < std::chrono::nanoseconds::zero()) {
        throw std::invalid_argument("PaControl: boot time must be >= 0");
    }
    if (config.homeCycle <= std::chrono::nanoseconds::zero() ||
        config.activeCycle <= std::chrono::nanoseconds::zero()) {
        throw std::invalid_argument("PaControl: cycle times must be > 0");
    }
    return config;
}

int CheckedAxisModules(const ModuleLayout& layout, const PaControlConfig& config) {
    if (config.axisCapacity < layout.axisModules) {
        throw std::invalid_argument("PaControl: " + std::to_string(layout.axisModules) +
                                    " axis modules need an axis capacity of at least as many axes");
    }
    return layout.axisModules;
}

}  // namespace

std::uint64_t CommandCounters::Count(std::uint16_t code) const {
    auto it = byCode.find(code);
    return it == byCode.end() ? 0 : it->second;
}

PaControl::PaControl(Bus& bus, PaControlConfig config)
    : bus_(bus),
      layout_(bus.Layout()),
      config_(CheckedConfig(config)),
      state_(config_.counts, config_.systemParameters, config_.axisCapacity, config_.axisParameters,
             config_.axisMachine, config_.online),
      modes_(state_, config_.modes),
      executor_(state_, modes_),
      ctrl_(modes_, state_, config_.ctrlInterface),
      protocol_(config_.cmd),
      log_(config_.logCapacity),
      automaticModule_(config_.automaticModule),
      bootEnd_(config_.bootTime),
      imageBytes_(layout_.Bytes()),
      lastFromPac_(imageBytes_),
      lastToPac_(imageBytes_) {
    state_.axisModules = CheckedAxisModules(layout_, config_);
    modules_.assign(static_cast<std::size_t>(state_.axisModules), AxisModule(config_.axisModule));
    automaticReplies_.assign(modules_.size(), Image12{});
    for (int axis = 1; axis <= state_.axes.Capacity(); ++axis) {
        state_.axes.Motion(axis).SetReferenced(config_.referencedAtPowerOn);
    }
}

AxisModule& PaControl::Module(int axis) {
    if (axis < 1 || axis > static_cast<int>(modules_.size())) {
        throw std::out_of_range("PaControl: no axis module for axis " + std::to_string(axis));
    }
    return modules_[static_cast<std::size_t>(axis - 1)];
}

const AxisModule& PaControl::Module(int axis) const {
    if (axis < 1 || axis > static_cast<int>(modules_.size())) {
        throw std::out_of_range("PaControl: no axis module for axis " + std::to_string(axis));
    }
    return modules_[static_cast<std::size_t>(axis - 1)];
}

std::chrono::nanoseconds PaControl::CycleTime() const {
    const Mode mode = state_.CurrentMode();
    return booted_ && (mode == Mode::kAutomatic || mode == Mode::kOnline) ? config_.activeCycle
                                                                          : config_.homeCycle;
}

void PaControl::Cycle(std::chrono::nanoseconds now) {
    CheckTime(now, "Cycle");
    lastToPac_ = bus_.ReadToPac(now);
    const ProcessImage& toPac = lastToPac_;  // the cycle's record keeps it as read
    bool newCommand = false;

    if (!booted_) {
        if (now < bootEnd_) {
            serial_.Discard(now);
            WriteReply(now, ProcessImage(layout_.Bytes()));
            log_.Add(now, toPac, lastFromPac_, false);
            return;
        }
        Boot();
    }

    state_.axes.UpdateAll(now);
    state_.online.Supervise(now, state_.axes, state_.elements, state_.CurrentMode() == Mode::kOnline);
    const bool allZero = toPac.AllZero();
    if (allZero && communicationActive_ && !emergencyStop_) EmergencyStop(now);
    modes_.Step(now);
    // An all-zero image is no control word (all requests low-active would cancel): it is the
    // emergency stop above, or no communication yet.
    if (layout_.ctrl && !allZero) ctrl_.Apply(toPac.Module8(ModuleLayout::kCtrlOffset), now);

    if (pending_.Active()) {
        const CommandResult progress = executor_.Poll(pending_, now);
        protocol_.Update(progress);
        if (progress.finished) pending_ = PendingCommand{};
    }

    if (!allZero) {
        communicationActive_ = true;
        emergencyStop_ = false;
        const CommandFrame command = CommandFrame::Decode(toPac.Cmd());
        if (protocol_.Recognise(command)) {
            newCommand = true;
            Execute(command, now);
        }
        // Last, so that a mode change by CTRL or CMD in this cycle applies to the axis modules at once. Like
        // the CTRL module, they take no control word from an all-zero image (the emergency stop has halted
        // the axes); they report all the same.
        ServeModules(toPac, now);
    } else {
        protocol_.SeeAllZeroImage();
    }
    // COM1 needs no fieldbus: an RS232-only controller sees an all-zero image all the time.
    serial_.Cycle(now, serialHost_);

    ComposeReply(now, lastFromPac_);
    bus_.WriteFromPac(now, lastFromPac_);
    log_.Add(now, toPac, lastFromPac_, newCommand);
}

AxisModuleContext PaControl::ModuleContext(std::chrono::nanoseconds now) const {
    AxisModuleContext context;
    context.now = now;
    // Jobs in ONLINE proper; Axis ON, DISABLE DRIVE and reset axis error in every ONLINE status.
    if (state_.operatingStatus == status::kOnline) {
        context.service = AxisModuleService::kJobs;
    } else if (state_.CurrentMode() == Mode::kOnline) {
        context.service = AxisModuleService::kControl;
    }
    context.integerFormat = state_.integerFormat;
    context.inputs = &state_.elements.inputs;
    return context;
}

bool PaControl::AutomaticExchangeNow() const {
    if (state_.CurrentMode() != Mode::kAutomatic) return false;
    return config_.automaticModule.exchange == AutomaticExchange::kWholeMode ||
           state_.operatingStatus == status::kAuto;
}

void PaControl::ServeModules(const ProcessImage& toPac, std::chrono::nanoseconds now) {
    if (state_.CurrentMode() != Mode::kAutomatic) {
        ServeAxisModules(toPac, now);
        return;
    }
    // 2.6: the same bytes are flags and registers now. The axis modules only follow the control word, so that
    // flag data are no Start edge when HOME POSITION returns (docs/sim_axis_modules.md).
    for (int k = 1; k <= state_.axisModules; ++k) {
        const Image12 module = toPac.Module12(layout_.AxisOffset(k));
        Module(k).Follow(module);
        if (AutomaticExchangeNow()) automaticModule_.CopyIn(k, module, state_.elements, state_.integerFormat);
    }
    if (state_.operatingStatus == status::kAuto) automaticProgram_.Run(state_.elements);
    if (!AutomaticExchangeNow()) return;
    for (int k = 1; k <= state_.axisModules; ++k) {
        automaticReplies_[static_cast<std::size_t>(k - 1)] =
            automaticModule_.CopyOut(k, state_.elements, state_.integerFormat);
    }
}

void PaControl::ServeAxisModules(const ProcessImage& toPac, std::chrono::nanoseconds now) {
    const AxisModuleContext context = ModuleContext(now);
    // modules_ holds axisModules modules, axis k at k - 1, no more than the axes (the constructor); the image
    // has the layout's size (checked once here): the bytes are copied as blocks, without a check per module.
    const std::uint8_t* bytes = AxisModuleBytes(toPac);
    Image12 module;
    for (int axis = 1; axis <= state_.axisModules; ++axis, bytes += module.size()) {
        std::memcpy(module.data(), bytes, module.size());
        modules_[static_cast<std::size_t>(axis - 1)].Serve(module, state_.axes.MotionInRange(axis), context);
    }
}

const std::uint8_t* PaControl::AxisModuleBytes(const ProcessImage& image) const {
    if (image.Size() != imageBytes_) {
        throw std::logic_error("PaControl: an image of " + std::to_string(image.Size()) + " bytes, the layout has " +
                               std::to_string(imageBytes_));
    }
    return image.Data() + ModuleLayout::kFirstAxisOffset;
}

void PaControl::PowerCycle(std::chrono::nanoseconds now) {
    CheckTime(now, "PowerCycle");
    booted_ = false;
    bootEnd_ = now + config_.bootTime;

    state_.axes.Restart(now, config_.referencedAtPowerOn);
    state_.online.Reset();
    for (AxisModule& module : modules_) module.Reset();
    automaticReplies_.assign(modules_.size(), Image12{});
    Elements& e = state_.elements;
    if (!config_.retention.intRegisters) e.intRegisters.Clear();
    if (!config_.retention.realRegisters) e.realRegisters.Clear();
    if (!config_.retention.flags) e.flags.Clear();
    if (!config_.retention.outputs) e.outputs.Clear();
    e.systemFlags.Clear();
    e.systemIntRegisters.Clear();
    e.systemRealRegisters.Clear();
    modes_.PowerOff();
    ctrl_.Reset();

    protocol_.PowerOn();
    pending_ = PendingCommand{};
    serial_.Reset();
    injectedError_.reset();
    communicationActive_ = false;
    emergencyStop_ = false;
    WriteReply(now, ProcessImage(layout_.Bytes()));  // the controller drops off the bus at once
}

void PaControl::InjectCommandError(std::uint16_t errorNumber) {
    if (errorNumber > 0x1FFF) {
        throw std::invalid_argument("PaControl::InjectCommandError: error number must be 0..8191");
    }
    injectedError_ = errorNumber;
}

void PaControl::CheckTime(std::chrono::nanoseconds now, const char* what) {
    if (lastTime_ && now < *lastTime_) {
        throw std::invalid_argument(std::string("PaControl::") + what + ": time runs backwards (" +
                                    FormatTime(now) + " after " + FormatTime(*lastTime_) + ")");
    }
    lastTime_ = now;
}

void PaControl::Boot() {
    booted_ = true;
    modes_.Boot();
    protocol_.PowerOn();
}

void PaControl::EmergencyStop(std::chrono::nanoseconds now) {
    // 4.2.5: an all-zero to-PAC image after communication was active means EMERGENCY STOP.
    emergencyStop_ = true;
    ++counters_.emergencyStops;
    modes_.EmergencyStop(now);
}

void PaControl::Execute(const CommandFrame& command, std::chrono::nanoseconds now) {
    // A new command takes the CMD reply over; an earlier one still processing is no longer reported
    // (its axis carries on: 1910 / 190C show it).
    pending_ = PendingCommand{};
    const bool errorWithoutNumber = injectedError_ == std::uint16_t{0};
    const CommandResult result = RunCommand(command, now, pending_);
    if (errorWithoutNumber) {
        protocol_.AcknowledgeCommandErrorWithoutNumber(command.send);
    } else {
        protocol_.Acknowledge(command.send, result);
    }
}

CommandResult PaControl::RunCommand(const CommandFrame& command, std::chrono::nanoseconds now, PendingCommand& pending) {
    ++counters_.recognized;
    ++counters_.byCode[command.code];
    CommandResult result;
    bool refused = true;
    if (injectedError_) {
        result = CommandResult{0, *injectedError_, true};
        injectedError_.reset();
    } else {
        result = executor_.Execute(command, now, pending);
        refused = result.error != 0;
    }
    if (!refused) {
        ++counters_.executed;
    } else {
        ++counters_.failed;
        pending = PendingCommand{};
    }
    return result;
}

void PaControl::AttachSerial(SerialLine& line, SerialPortConfig config) {
    serial_ = SerialPort(config);
    serial_.Connect(line);
}

void PaControl::ComposeReply(std::chrono::nanoseconds now, ProcessImage& reply) const {
    // Every byte is written below (CMD, CTRL where the layout has it, each axis module; axis modules need
    // CTRL): the image is only made the layout's size, not cleared first.
    if (reply.Size() != imageBytes_) reply = ProcessImage(imageBytes_);
    reply.SetModule8(ModuleLayout::kCmdOffset, protocol_.Reply(state_.operatingStatus, state_.systemError != 0).Encode());
    if (layout_.ctrl) reply.SetModule8(ModuleLayout::kCtrlOffset, ctrl_.Reply());
    const bool automatic = state_.CurrentMode() == Mode::kAutomatic;
    AxisModuleContext context = ModuleContext(now);
    // 2.7.4.13: the group is every axis with a module. Only the reply's status word reads it, and serving the
    // control words may change it: it is searched here, once per cycle, and only where a module replies.
    if (!automatic) context.groupDisplaced = state_.axes.AnyDisplacedDuringOff(state_.axisModules);
    Image12 module;
    std::uint8_t* bytes = reply.Data() + ModuleLayout::kFirstAxisOffset;  // the reply has the layout's size (above)
    for (int axis = 1; axis <= state_.axisModules; ++axis, bytes += module.size()) {
        const auto k = static_cast<std::size_t>(axis - 1);
        if (automatic) {
            module = automaticReplies_[k];
        } else {
            modules_[k].ReplyInto(state_.axes.MotionInRange(axis), context, module);
        }
        std::memcpy(bytes, module.data(), module.size());
    }
}

void PaControl::WriteReply(std::chrono::nanoseconds now, const ProcessImage& reply) {
    lastFromPac_ = reply;
    bus_.WriteFromPac(now, reply);
}

}  // namespace pac::sim
