// The controller's side of the SEND/RECEIVE handshake (see cmd_protocol.hpp).
#include "pac/sim/cmd_protocol.hpp"

namespace pac::sim {

const char* ToString(NewCommandRule rule) {
    switch (rule) {
        case NewCommandRule::kSendDiffersFromReceive: return "SEND != RECEIVE";
        case NewCommandRule::kSendChanged: return "SEND changed";
    }
    return "?";
}

const char* ToString(ReceiveAfterRestart start) {
    switch (start) {
        case ReceiveAfterRestart::kZero: return "RECEIVE 0 after restart";
        case ReceiveAfterRestart::kLastSend: return "RECEIVE = last SEND after restart";
    }
    return "?";
}

void CmdProtocol::PowerOn() {
    receiveFlag_ = config_.receiveAfterRestart == ReceiveAfterRestart::kLastSend && lastSend_;
    commandError_ = false;
    endOfProcessing_ = config_.endOfProcessingAtPowerOn;
    errorNumber_ = 0;
    ackData_ = 0;
    answered_ = false;
    // A controller that kept the last SEND compares the first image with it; one that did not needs two
    // images to see a change.
    sendSeenSincePowerOn_ = config_.receiveAfterRestart == ReceiveAfterRestart::kLastSend;
}

bool CmdProtocol::Recognise(const CommandFrame& command) {
    bool isNew = false;
    switch (config_.newCommand) {
        case NewCommandRule::kSendDiffersFromReceive: isNew = command.send != receiveFlag_; break;
        case NewCommandRule::kSendChanged: isNew = sendSeenSincePowerOn_ && command.send != lastSend_; break;
    }
    lastSend_ = command.send;
    sendSeenSincePowerOn_ = true;
    return isNew;
}

void CmdProtocol::SeeAllZeroImage() {
    lastSend_ = false;
    sendSeenSincePowerOn_ = true;
}

void CmdProtocol::Acknowledge(bool send, const CommandResult& result) {
    receiveFlag_ = send;
    answered_ = true;
    Update(result);
}

void CmdProtocol::Update(const CommandResult& result) {
    ackData_ = result.ackData;
    commandError_ = result.error != 0;
    errorNumber_ = result.error;
    endOfProcessing_ = !commandError_ && result.finished;
}

void CmdProtocol::AcknowledgeCommandErrorWithoutNumber(bool send) {
    Acknowledge(send, CommandResult{});
    commandError_ = true;
    endOfProcessing_ = false;
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
