// The controller's side of the SEND/RECEIVE handshake (see cmd_protocol.hpp).
#include "pac/sim/cmd_protocol.hpp"

namespace pac::sim {

void CmdProtocol::Reset() {
    receiveFlag_ = false;
    commandError_ = false;
    endOfProcessing_ = true;
    errorNumber_ = 0;
    ackData_ = 0;
}

void CmdProtocol::Acknowledge(bool send, const CommandResult& result) {
    receiveFlag_ = send;
    Update(result);
}

void CmdProtocol::Update(const CommandResult& result) {
    ackData_ = result.ackData;
    commandError_ = result.error != 0;
    errorNumber_ = result.error;
    endOfProcessing_ = !commandError_ && result.finished;
}

ReplyFrame CmdProtocol::Reply(std::uint8_t operatingStatus, bool errorFlag) const {
    ReplyFrame reply;
    reply.ackData = ackData_;
    reply.errorFlag = errorFlag;
    reply.operatingStatus = operatingStatus;
    reply.receiveFlag = receiveFlag_;
    reply.commandErrorFlag = commandError_;
    reply.endOfProcessing = endOfProcessing_;
    reply.errorNumber = errorNumber_;
    return reply;
}

}  // namespace pac::sim
