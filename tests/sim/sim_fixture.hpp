// A test bench for the simulated PA-CONTROL: a bus, a controller, and the master's side written by
// hand. Exchange() is one step of simulated time: the master writes its image, the controller runs
// one cycle, the master reads the reply; then time moves on by step_ (10 ms, the home-position cycle).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "pac/sim/bus.hpp"
#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/command_table.hpp"
#include "pac/sim/image8.hpp"
#include "pac/sim/pa_control.hpp"

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

// "41 20 00 00" for 10.0F: the dword of a REAL as the reply carries it.
inline std::string RealHex(float value) {
    Image8 image{};
    WriteDword(image, 0, FloatToBits(value));
    return ToHex(image).substr(0, 11);
}

class PacBench : public ::testing::Test {
protected:
    explicit PacBench(PaControlConfig config = QuickConfig(), BusConfig bus = {})
        : bus_(bus), pac_(bus_, config) {}

    // One step: master writes, controller cycles, master reads; returns the reply as hex.
    std::string Exchange(const Image8& master) {
        master_ = master;
        bus_.MasterWrite(now_, master);
        pac_.Cycle(now_);
        const Image8 reply = bus_.MasterRead(now_).Cmd();
        now_ += step_;
        return ToHex(reply);
    }

    // A step with the master image unchanged.
    std::string Idle() { return Exchange(master_); }

    // Toggles SEND and sends a command; returns the reply of the cycle that saw it.
    std::string Send(std::uint16_t code, std::uint16_t parameter = 0, std::uint32_t data = 0) {
        send_ = !send_;
        return Exchange(MasterImage(code, parameter, data, send_));
    }
    ReplyFrame SendFrame(std::uint16_t code, std::uint16_t parameter = 0, std::uint32_t data = 0) {
        return ReplyFrame::Decode(FromHex(Send(code, parameter, data)));
    }

    // Stop input 1 defined and powered (5.2.1.3), then 0603: status 31.
    void GoOnline() {
        ASSERT_EQ(pac_.SystemParameters().Set(4, 1), ParameterTable::SetResult::kOk);
        pac_.Io().inputs.Set(1, true);
        const ReplyFrame reply = SendFrame(code::kStartOnline);
        ASSERT_FALSE(reply.commandErrorFlag) << "0603 failed with error " << reply.errorNumber;
        ASSERT_EQ(reply.operatingStatus, 31);
    }

    // "... 00 1F A0 00": the reply's status and flag bytes as the master sees them.
    static std::string Tail(const std::string& replyHex) { return replyHex.substr(12); }
    static std::string Data(const std::string& replyHex) { return replyHex.substr(0, 11); }

    Bus bus_;
    PaControl pac_;
    std::chrono::nanoseconds now_{0};
    std::chrono::nanoseconds step_{10ms};
    bool send_ = false;
    Image8 master_{};
};

}  // namespace pac::sim::testing
