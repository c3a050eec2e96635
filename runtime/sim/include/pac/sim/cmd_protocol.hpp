// The PA-CONTROL's side of the CMD handshake (manual 2.4.2, 4.2.3): which SEND flag it acknowledged
// last (RF), and the KF / BF flags, error number and acknowledgement data of the newest command.
//   new command:        SEND differs from RF (a toggle, 0->1 or 1->0);
//   acknowledged:       RF := SEND, plus the command's result;
//   command error:      KF = 1, BF = 0 (recognised but not processed), error number set;
//   still processing:   KF = 0, BF = 0, until the command ends: BF = 1.
// After power-on: RF = 0, KF = 0, BF = 1, error 0, data 0 (nothing outstanding).
#pragma once

#include <cstdint>

#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/command_executor.hpp"

namespace pac::sim {

class CmdProtocol {
public:
    CmdProtocol() { Reset(); }

    void Reset();
    bool IsNewCommand(const CommandFrame& command) const { return command.send != receiveFlag_; }
    void Acknowledge(bool send, const CommandResult& result);  // RF := send, then the result
    void Update(const CommandResult& result);                  // progress of the processing command
    bool Processing() const { return !endOfProcessing_ && !commandError_; }
    bool ReceiveFlag() const { return receiveFlag_; }

    ReplyFrame Reply(std::uint8_t operatingStatus, bool errorFlag) const;

private:
    bool receiveFlag_ = false;
    bool commandError_ = false;
    bool endOfProcessing_ = true;
    std::uint16_t errorNumber_ = 0;
    std::uint32_t ackData_ = 0;
};

}  // namespace pac::sim
