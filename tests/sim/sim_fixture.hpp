// A test rig for the simulated PA-CONTROL: a bus, a controller, and the PLC's side written by
// hand. Exchange() is one step of simulated time: the PLC writes its image, the controller runs
// one cycle, the PLC reads the reply; then time moves on by step_ (10 ms, the home-position cycle).
// With a CTRL module in the bus layout (CtrlBus()), the to-PAC image carries ctrlWord_ as the CTRL
// control word (default: no request, every low-active bit held at 1); with axis modules (AxisBus(n)),
// axisToPac_[k - 1] as the module of axis k.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "pac/sim/axis_module.hpp"
#include "pac/sim/bus.hpp"
#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/command_table.hpp"
#include "pac/sim/ctrl_interface.hpp"
#include "pac/sim/image8.hpp"
#include "pac/sim/pa_control.hpp"
#include "pac/sim/process_image.hpp"

namespace pac::sim::testing {

using namespace std::chrono_literals;

// A controller that boots in `bootTime` (status 0 and an all-zero reply until then).
inline PaControlConfig BootingIn(std::chrono::nanoseconds bootTime) {
    PaControlConfig config;
    config.bootTime = bootTime;
    return config;
}

// No boot delay, so the first cycle already answers in home position.
inline PaControlConfig QuickConfig() { return BootingIn(0ns); }

// A bus with the CMD and the CTRL module (16 bytes), no latency.
inline BusConfig CtrlBus() {
    BusConfig bus;
    bus.layout = ModuleLayout{true, 0};
    return bus;
}

// CMD, CTRL and `n` axis modules (2.3.2.3), no latency.
inline BusConfig AxisBus(int n) {
    BusConfig bus;
    bus.layout = ModuleLayout{true, n};
    return bus;
}

// "41 20 00 00" for 10.0F: the dword of a REAL as the reply carries it.
inline std::string RealHex(float value) {
    Image8 image{};
    WriteDword(image, 0, FloatToBits(value));
    return ToHex(image).substr(0, 11);
}

class PacRig : public ::testing::Test {
protected:
    explicit PacRig(PaControlConfig config = QuickConfig(), BusConfig bus = {})
        : bus_(bus), pac_(bus_, config), axisToPac_(static_cast<std::size_t>(bus.layout.axisModules)) {}

    // One step: PLC writes, controller cycles, PLC reads; returns the CMD reply as hex.
    std::string Exchange(const Image8& cmd) {
        cmd_ = cmd;
        ProcessImage image(bus_.Layout().Bytes());
        image.SetModule8(ModuleLayout::kCmdOffset, cmd);
        if (bus_.Layout().ctrl) {
            Image8 ctrl{};
            WriteWord(ctrl, 0, ctrlWord_);
            image.SetModule8(ModuleLayout::kCtrlOffset, ctrl);
        }
        for (int axis = 1; axis <= bus_.Layout().axisModules; ++axis) {
            image.SetModule12(bus_.Layout().AxisOffset(axis), axisToPac_[static_cast<std::size_t>(axis - 1)].Encode());
        }
        return ToHex(ExchangeImage(image).Cmd());
    }

    // One step with the whole to-PAC image as given (e.g. all zero).
    ProcessImage ExchangeImage(const ProcessImage& toPac) {
        bus_.WriteToPac(now_, toPac);
        pac_.Cycle(now_);
        reply_ = bus_.ReadFromPac(now_);
        now_ += step_;
        return reply_;
    }

    // A step with the to-PAC image unchanged.
    std::string Idle() { return Exchange(cmd_); }

    // Toggles SEND and sends a command; returns the reply of the cycle that saw it.
    std::string Send(std::uint16_t code, std::uint16_t parameter = 0, std::uint32_t data = 0) {
        send_ = !send_;
        return Exchange(CommandImage(code, parameter, data, send_));
    }
    ReplyFrame SendFrame(std::uint16_t code, std::uint16_t parameter = 0, std::uint32_t data = 0) {
        return ReplyFrame::Decode(FromHex(Send(code, parameter, data)));
    }

    // Stop input 1 defined and powered (5.2.1.3), then 0603: ONLINE started (30) with BF = 0.
    void StartOnline() {
        ASSERT_EQ(pac_.SystemParameters().Set(4, 1), ParameterTable::SetResult::kOk);
        pac_.Io().inputs.Set(1, true);
        const ReplyFrame reply = SendFrame(code::kStartOnline);
        ASSERT_FALSE(reply.commandErrorFlag) << "0603 failed with error " << reply.errorNumber;
        ASSERT_EQ(reply.operatingStatus, 30);
        ASSERT_FALSE(reply.endOfProcessing);
    }
    // StartOnline(), then one cycle later ONLINE (31) with BF = 1: two steps.
    void GoOnline() {
        StartOnline();
        const ReplyFrame reply = ReplyFrame::Decode(FromHex(Idle()));
        ASSERT_EQ(reply.operatingStatus, 31);
        ASSERT_TRUE(reply.endOfProcessing);
    }

    // The CTRL module of the last reply (CtrlBus() layout): status word, system error number.
    std::uint16_t StatusWord() const { return ReadWord(reply_.Module8(ModuleLayout::kCtrlOffset), 0); }
    std::uint16_t CtrlErrorNumber() const { return ReadWord(reply_.Module8(ModuleLayout::kCtrlOffset), 2); }
    std::string CtrlHex() const { return ToHex(reply_.Module8(ModuleLayout::kCtrlOffset)); }
    // The axis module of axis k in the last reply.
    Image12 AxisModuleBytes(int axis) const { return reply_.Module12(bus_.Layout().AxisOffset(axis)); }
    AxisModuleReply AxisReply(int axis) const { return AxisModuleReply::Decode(AxisModuleBytes(axis)); }
    // One step with this control word (held from then on); returns the status word.
    std::uint16_t Control(std::uint16_t word) {
        ctrlWord_ = word;
        Idle();
        return StatusWord();
    }

    // "... 00 1F A0 00": the reply's status and flag bytes as the PLC sees them.
    static std::string Tail(const std::string& replyHex) { return replyHex.substr(12); }
    static std::string Data(const std::string& replyHex) { return replyHex.substr(0, 11); }

    Bus bus_;
    PaControl pac_;
    std::chrono::nanoseconds now_{0};
    std::chrono::nanoseconds step_{10ms};
    bool send_ = false;
    Image8 cmd_{};  // the CMD module to PAC
    std::uint16_t ctrlWord_ = ctrl::kNoRequest;
    std::vector<AxisModuleCommand> axisToPac_;  // axis k's module at [k - 1]
    ProcessImage reply_;
};

}  // namespace pac::sim::testing
