// The PA-CONTROL's side of the CMD handshake (manual 2.4.2, 4.2.3): which SEND flag it acknowledged
// last (RF), and the KF / BF flags, error number and acknowledgement data of the newest command.
//   new command:        a SEND flag change (CmdProtocolConfig::newCommand says against what);
//   acknowledged:       RF := SEND, plus the command's result;
//   command error:      KF = 1, BF = 0 (recognised but not processed), error number set;
//   still processing:   KF = 0, BF = 0, until the command ends: BF = 1.
// After power-on: RF and BF per CmdProtocolConfig, KF = 0, error 0, data 0.
#pragma once

#include <cstdint>

#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/command_executor.hpp"

namespace pac::sim {

// What the controller compares the SEND flag with (docs/open_points.md: the manual leaves it open).
enum class NewCommandRule {
    kSendDiffersFromReceive,  // a command is pending while SEND != RF (a level)
    kSendChanged,             // only a change of SEND between two images it read is a command (2.4.2 wording)
};

// Where the controller's RECEIVE flag starts after power-on or a restart.
enum class ReceiveAfterRestart {
    kZero,      // RF = 0
    kLastSend,  // RF = the SEND flag of the last image it read before the restart (0 at the first power-on)
};

struct CmdProtocolConfig {
    NewCommandRule newCommand = NewCommandRule::kSendDiffersFromReceive;
    ReceiveAfterRestart receiveAfterRestart = ReceiveAfterRestart::kZero;
    // BF after power-on, before any command: 1 (nothing outstanding) or 0 (the flag's reset value; nothing
    // processes all the same).
    bool endOfProcessingAtPowerOn = true;
};

const char* ToString(NewCommandRule rule);
const char* ToString(ReceiveAfterRestart start);

class CmdProtocol {
public:
    explicit CmdProtocol(CmdProtocolConfig config = {}) : config_(config) { PowerOn(); }

    // The handshake state of a controller that has just booted.
    void PowerOn();
    // Whether `command`, the CMD module of a non-zero image read in a booted cycle, is a new command; it
    // also becomes the image the next one is compared with.
    bool Recognise(const CommandFrame& command);
    // An all-zero image read in a booted cycle: never a command (no communication, or EMERGENCY STOP), but
    // a SEND flag of 0 the next image is compared with.
    void SeeAllZeroImage();
    void Acknowledge(bool send, const CommandResult& result);  // RF := send, then the result
    void Update(const CommandResult& result);                  // progress of the processing command
    void AcknowledgeCommandErrorWithoutNumber(bool send);      // RF := send, KF = 1, error number 0
    bool Processing() const { return answered_ && !endOfProcessing_ && !commandError_; }
    bool ReceiveFlag() const { return receiveFlag_; }
    const CmdProtocolConfig& Config() const { return config_; }

    ReplyFrame Reply(std::uint8_t operatingStatus, bool errorFlag) const;

private:
    CmdProtocolConfig config_;
    bool receiveFlag_ = false;
    bool commandError_ = false;
    bool endOfProcessing_ = true;
    std::uint16_t errorNumber_ = 0;
    std::uint32_t ackData_ = 0;
    bool answered_ = false;  // a command was acknowledged since power-on (BF before that is no processing)
    // The SEND flag of the last image read, kept over restarts; whether one was read since power-on.
    bool lastSend_ = false;
    bool sendSeenSincePowerOn_ = false;
};

}  // namespace pac::sim
