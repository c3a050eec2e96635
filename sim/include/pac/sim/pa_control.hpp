// The simulated PA-CONTROL behind its Profibus-DP modules (manual 2.3): the 8-byte CMD interface (2.4,
// 4.2, chapter 5), and where the bus layout has them the CTRL interface (2.5) and the axis modules (2.7).
// It runs in its own cycle: each Cycle(now) reads the PLC's process image from the bus, steps the
// operating-mode machine, applies the CTRL control word, follows a command that is still processing,
// recognises a SEND flag change against the last acknowledged SEND (RF), carries out the command, serves
// the axis modules (AxisModule, one per axis) or in AUTOMATIC the flag/register modules (AutomaticModule)
// with the stand-in AUTOMATIC program (AutomaticProgram), and writes its reply image. docs/sim_controller.md and the
// pages it links list every decision where the manual is silent (power-up, operating modes, emergency
// stop, SEND toggles while processing, retention, axis modules).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "pac/sim/automatic_module.hpp"
#include "pac/sim/automatic_program.hpp"
#include "pac/sim/axis_module.hpp"
#include "pac/sim/bus.hpp"
#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/cmd_protocol.hpp"
#include "pac/sim/command_executor.hpp"
#include "pac/sim/controller_state.hpp"
#include "pac/sim/ctrl_interface.hpp"
#include "pac/sim/exchange_log.hpp"
#include "pac/sim/image8.hpp"
#include "pac/sim/mode_machine.hpp"
#include "pac/sim/process_image.hpp"
#include "pac/sim/serial_line.hpp"
#include "pac/sim/serial_port.hpp"

namespace pac::sim {

// What survives PowerCycle(). Parameters (system and axis) always survive; the system error number,
// system elements, axis motion and the operating status never do; inputs are the outside world's and
// stay as the test set them.
struct RetentionRule {
    bool intRegisters = true;   // N
    bool realRegisters = true;  // R
    bool flags = false;
    bool outputs = false;
};

struct PaControlConfig {
    std::chrono::nanoseconds bootTime{std::chrono::milliseconds(50)};  // status 0, all-zero reply
    std::chrono::nanoseconds homeCycle{std::chrono::milliseconds(10)};  // 2.3.4: home position
    std::chrono::nanoseconds activeCycle{std::chrono::milliseconds(10)};  // AUTOMATIC / ONLINE (< 10 ms)
    ElementCounts counts{};
    std::vector<ParameterSpec> systemParameters = DefaultSystemParameters();
    std::vector<ParameterSpec> axisParameters = DefaultAxisParameters();
    int axisCapacity = 16;  // axes held (>= the layout's axis modules); system parameter 2: addressable by CMD
    ServoAxisConfig axisMachine{};  // the machine around every axis (switches, homing, enable mode, ...)
    AxisModuleConfig axisModule{};  // how the axis modules show a CMD error at the next Start edge
    AutomaticModuleConfig automaticModule{};  // the byte layout of the modules in AUTOMATIC (2.6), when they copy
    RetentionRule retention{};
    bool referencedAtPowerOn = true;
    ModeMachineOptions modes{};  // external stop check, the AUTOMATIC stand-in's cycle counts
    CtrlInterfaceConfig ctrlInterface{};  // how a stopped mode shows in the CTRL status word
    OnlineCommandOptions online{};  // keep-alive, EP-only commands, readings of 5.2.6.23 (online_axes.hpp)
    CmdProtocolConfig cmd{};  // the manual's open points of the CMD handshake (docs/sim_cmd.md)
    std::size_t logCapacity = 10000;  // newest cycles kept in Log(); 0: no log
};

struct CommandCounters {
    std::uint64_t recognized = 0;  // SEND flag changes acted upon
    std::uint64_t executed = 0;    // ... of which without command error
    std::uint64_t failed = 0;      // ... of which with command error (KF = 1)
    std::uint64_t emergencyStops = 0;
    std::map<std::uint16_t, std::uint64_t> byCode;  // recognised, per command code

    std::uint64_t Count(std::uint16_t code) const;
};

class PaControl {
public:
    // Powered on at time 0: the boot ends at config.bootTime. Bad times: std::invalid_argument.
    // The modules served are the bus's layout (Bus::Layout()).
    explicit PaControl(Bus& bus, PaControlConfig config = {});
    PaControl(const PaControl&) = delete;  // its serial port's host refers to it
    PaControl& operator=(const PaControl&) = delete;

    // One controller cycle at `now` (non-decreasing, std::invalid_argument otherwise).
    void Cycle(std::chrono::nanoseconds now);
    // The cycle time in the current mode: homeCycle, or activeCycle in AUTOMATIC and ONLINE.
    std::chrono::nanoseconds CycleTime() const;

    bool Booted() const { return booted_; }
    std::uint8_t OperatingStatus() const { return state_.operatingStatus; }
    std::uint16_t SystemError() const { return state_.systemError; }
    bool IntegerFormat() const { return state_.integerFormat; }  // 2.5.3: the format in force
    bool BatteryOk() const { return state_.batteryOk; }
    // The CTRL status word as the controller writes it (also without a CTRL module in the layout).
    std::uint16_t CtrlStatusWord() const { return ctrl_.StatusWord(); }
    const ModeMachine& Modes() const { return modes_; }
    bool EmergencyStopActive() const { return emergencyStop_; }
    bool Processing() const { return booted_ && protocol_.Processing(); }
    const ProcessImage& LastFromPacImage() const { return lastFromPac_; }
    const ProcessImage& LastToPacImage() const { return lastToPac_; }
    const ModuleLayout& Layout() const { return layout_; }

    // ---- test hooks ----
    // Power off and on at `now`: the reply is all zero (status 0, RF 0) at once and until the boot
    // ends at now + bootTime; then status 1 and the power-on handshake state. Retention: RetentionRule.
    void PowerCycle(std::chrono::nanoseconds now);
    // Takes effect in the next reply. Set before the boot ends, it is the status the controller boots
    // into. The status is held: the mode machine makes no transition out of it by itself (no timed
    // step, no external stop check) until a request, a system error or an emergency stop moves it.
    void SetOperatingStatus(std::uint8_t status) { modes_.Force(status); }
    // The PA-CONTROL error number of 1909 / SN10 as is; FE (word 2 bit 15) is set while it is not 0.
    // The status does not change: RaiseSystemError() is the controller's reaction to an error.
    void SetSystemError(std::uint16_t number) { state_.systemError = number; }
    // A system error of the number's class (5.2.4.15; 1..999, std::invalid_argument otherwise),
    // noticed by the next cycle: home -> 9; ONLINE -> 37 -> 39; AUTOMATIC -> 17 -> 18 -> 19.
    void RaiseSystemError(std::uint16_t number) { modes_.RaiseSystemError(number); }
    // 2.5.2 status word bit 1 (true at construction; survives power cycles).
    void SetBatteryOk(bool ok) { state_.batteryOk = ok; }
    // The next recognised command is not carried out but answered with KF = 1 and this number
    // (0..16#1FFF, std::invalid_argument otherwise; 0: KF = 1 without a number, which the manual does not
    // rule out). One shot; a power cycle drops it.
    void InjectCommandError(std::uint16_t errorNumber);

    // The axis module of axis `axis` (1..Layout().axisModules; std::out_of_range otherwise).
    AxisModule& Module(int axis);
    const AxisModule& Module(int axis) const;
    // COM1 as an online command port (chapter 3, docs/sim_serial.md) on `line`, whose to-PAC wire it reads and
    // whose from-PAC wire it answers on; commands go to the same processor as those of the CMD interface.
    // The line must outlive the controller. Attaching again replaces the port.
    void AttachSerial(SerialLine& line, SerialPortConfig config = {});
    const SerialPort& Serial() const { return serial_; }

    // The stand-in AUTOMATIC program (automatic_program.hpp): run once per cycle in status 11, after the
    // modules were copied into FW k / N k / R k and before FW 16+k / N 16+k / R 16+k are copied back.
    void SetAutomaticProgram(AutomaticProgram program) { automaticProgram_ = std::move(program); }

    // G123 (2.7.3.10): the input the axis module of `axis` watches from now on; back to 1 when ONLINE starts.
    void SetConditionInput(int axis, int input) { Module(axis).SetConditionInput(input); }

    Elements& Io() { return state_.elements; }  // inputs to set, outputs/flags/registers to read
    const Elements& Io() const { return state_.elements; }
    ParameterTable& SystemParameters() { return state_.systemParameters; }
    AxisGroup& Axes() { return state_.axes; }
    const AxisGroup& Axes() const { return state_.axes; }
    const OnlineAxes& Online() const { return state_.online; }  // measuring mode, monitoring, conditions
    ControllerState& State() { return state_; }

    const CommandCounters& Counters() const { return counters_; }
    const ExchangeLog& Log() const { return log_; }
    ExchangeLog& Log() { return log_; }
    const PaControlConfig& Config() const { return config_; }

private:
    // The serial port's way to the command processor.
    class SerialHost final : public CommandHost {
    public:
        explicit SerialHost(PaControl& pac) : pac_(pac) {}
        CommandResult RunCommand(const CommandFrame& command, std::chrono::nanoseconds now,
                                 PendingCommand& pending) override {
            return pac_.RunCommand(command, now, pending);
        }
        CommandResult Progress(const PendingCommand& pending, std::chrono::nanoseconds now) override {
            return pac_.executor_.Poll(pending, now);
        }
        std::uint8_t Status() const override { return pac_.state_.operatingStatus; }
        std::uint16_t SystemError() const override { return pac_.state_.systemError; }

    private:
        PaControl& pac_;
    };

    // Carries a command out for either interface: counters, the injected error, the executor.
    CommandResult RunCommand(const CommandFrame& command, std::chrono::nanoseconds now, PendingCommand& pending);
    void CheckTime(std::chrono::nanoseconds now, const char* what);
    void Boot();
    void EmergencyStop(std::chrono::nanoseconds now);
    void Execute(const CommandFrame& command, std::chrono::nanoseconds now);
    void WriteReply(std::chrono::nanoseconds now, const ProcessImage& reply);
    void ServeModules(const ProcessImage& toPac, std::chrono::nanoseconds now);
    void ServeAxisModules(const ProcessImage& toPac, std::chrono::nanoseconds now);
    bool AutomaticExchangeNow() const;
    // The cycle's context for serving the modules; the reply adds the group's displacement.
    AxisModuleContext ModuleContext(std::chrono::nanoseconds now) const;
    void ComposeReply(std::chrono::nanoseconds now, ProcessImage& reply) const;
    // The first axis module's byte in `image`; std::logic_error unless the image has the layout's size.
    const std::uint8_t* AxisModuleBytes(const ProcessImage& image) const;

    Bus& bus_;
    ModuleLayout layout_;
    PaControlConfig config_;
    ControllerState state_;
    ModeMachine modes_;
    CommandExecutor executor_;
    CtrlInterface ctrl_;
    CmdProtocol protocol_;
    PendingCommand pending_;
    ExchangeLog log_;
    CommandCounters counters_;
    std::optional<std::uint16_t> injectedError_;
    std::vector<AxisModule> modules_;  // module k serves axis k
    AutomaticModule automaticModule_;
    AutomaticProgram automaticProgram_;
    std::vector<Image12> automaticReplies_;  // the last copy of FW / N / R 16+k per module
    SerialPort serial_;
    SerialHost serialHost_{*this};

    bool booted_ = false;
    std::chrono::nanoseconds bootEnd_{0};
    bool communicationActive_ = false;  // a non-zero to-PAC image was seen since power-on
    bool emergencyStop_ = false;
    std::optional<std::chrono::nanoseconds> lastTime_;
    std::size_t imageBytes_;  // layout_.Bytes(), the size of every image of a cycle
    ProcessImage lastFromPac_;
    ProcessImage lastToPac_;
};

}  // namespace pac::sim
