#include "cmd_history.hpp"

namespace pac::pacsim {

void CmdHistory::Follow(std::chrono::nanoseconds now, const pac::sim::Image8& toPac, const pac::sim::Image8& fromPac) {
    const auto command = pac::sim::CommandFrame::Decode(toPac);
    if (command.send != lastSend_) {
        lastSend_ = command.send;
        if (handshakes_.size() == kCapacity) handshakes_.pop_front();
        handshakes_.push_back({now, command, false, {}});
        ++total_;
    }
    if (handshakes_.empty() || handshakes_.back().answered) return;
    const auto reply = pac::sim::ReplyFrame::Decode(fromPac);
    CmdHandshake& last = handshakes_.back();
    if (reply.receiveFlag == last.command.send && (reply.endOfProcessing || reply.commandErrorFlag)) {
        last.answered = true;
        last.reply = reply;
    }
}

}  // namespace pac::pacsim
