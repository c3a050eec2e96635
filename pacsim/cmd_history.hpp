// The CMD handshakes a simulated PA-CONTROL has seen, for pac-sim's live view (docs/virtual_commissioning.md):
// a command is a change of the SEND flag in the CMD module the controller read (manual 2.4.1), answered once
// RF equals SEND with BF or KF (2.4.2). The newest kCapacity are kept.
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>

#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/image8.hpp"

namespace pac::pacsim {

struct CmdHandshake {
    std::chrono::nanoseconds time{0};  // the controller's cycle that read the new command
    pac::sim::CommandFrame command;
    bool answered = false;
    pac::sim::ReplyFrame reply;        // the first reply with RF = SEND and BF or KF, once answered
};

class CmdHistory {
public:
    static constexpr std::size_t kCapacity = 16;

    // The CMD module both ways as the controller read and answered it at `now` (after its cycles).
    void Follow(std::chrono::nanoseconds now, const pac::sim::Image8& toPac, const pac::sim::Image8& fromPac);
    const std::deque<CmdHandshake>& Handshakes() const { return handshakes_; }
    std::size_t Total() const { return total_; }  // handshakes seen since start

private:
    bool lastSend_ = false;  // the controller's to-PAC image is all zero at power-on
    std::deque<CmdHandshake> handshakes_;
    std::size_t total_ = 0;
};

}  // namespace pac::pacsim
