// The PA-CONTROL's COM1 as an online command port (manual 3): it reads the bytes the RS232 line brings,
// puts frames together (rs232::Rs232Receiver), has the controller's command processor carry each command
// out, the same one as behind the CMD interface, and answers with an acknowledgement frame; an EOT poll
// asks for the acknowledgement again. Where chapter 3 can be read two ways the port can behave either way
// (SerialPortConfig); docs/sim_serial.md lists each point, and docs/open_points.md the library's decisions.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/command_executor.hpp"
#include "pac/sim/rs232_frame.hpp"
#include "pac/sim/serial_line.hpp"

namespace pac::sim {

// The controller's side of a command: PaControl runs it on the same executor, counters and injected
// errors as a command of the CMD interface.
class CommandHost {
public:
    virtual ~CommandHost() = default;
    virtual CommandResult RunCommand(const CommandFrame& command, std::chrono::nanoseconds now,
                                     PendingCommand& pending) = 0;
    virtual CommandResult Progress(const PendingCommand& pending, std::chrono::nanoseconds now) = 0;
    virtual std::uint8_t Status() const = 0;
    virtual std::uint16_t SystemError() const = 0;
};

// Which CHECK of a command frame the controller takes as right (3.1, 3.3; docs/manual_errata.md). The
// default is the rule of the manual's master frames: four of the seven in 3.4 carry the XOR of the text
// (one once its misprinted code is corrected), none the XOR with ETX.
enum class CheckVerification { kXorWithEtx, kXorText, kNone };

struct SerialPortConfig {
    CheckVerification verify = CheckVerification::kXorText;
    bool acceptZeroCheck = true;        // 3.1: the XOR sum "can be replaced by the value 0"
    rs232::CheckRule replyCheck = rs232::CheckRule::kXorWithEtx;
    bool answerBadCheck = true;         // 16 "sum of digits error"; false: no answer
    bool discardBadCheckFrame = false;  // with answerBadCheck false: the frame is dropped as if never sent, so an
                                        // EOT repeats the reply before it; false: 16 becomes the last reply
    bool answerSequenceErrors = true;   // 17 / 18 "wrong sequence"; false: no answer
    bool requireSoh = true;             // false: STX alone begins a frame
    bool answerPollWhenIdle = true;     // EOT after the master has seen BE = 1: the last reply again; false: none
    bool holdModeReplies = true;        // 0600 / 0602 / 0603: answer once the status has settled (3.4.3)
    bool refuseTypeMismatch = false;    // TYP_PAR_2 that does not suit the command: 41; false: converted
    int realDecimals = 4;               // Q_PAR of a REAL (3.4.2: 640.0000)
    int positionDecimals = 3;           // Q_PAR of an axis position (3.4.3: 1255.000)
    std::chrono::nanoseconds turnaround{0};  // from the end of a request to the first byte of its reply
    bool answers = true;                // false: a port that takes commands but never answers
};

// A command the port handed to the command processor: what the controller carried out (error 0) or
// refused with a command error, and when.
struct SerialCommand {
    std::uint16_t code = 0;
    std::uint16_t parameter = 0;
    std::uint32_t data = 0;
    std::uint16_t error = 0;
    std::chrono::nanoseconds at{0};
};

struct SerialCounters {
    std::uint64_t frames = 0;          // complete frames received
    std::uint64_t commands = 0;        // ... carried out
    std::uint64_t polls = 0;
    std::uint64_t checkErrors = 0;     // 16
    std::uint64_t unchecked = 0;       // ... taken with a CHECK of "0" (acceptZeroCheck): unverified
    std::uint64_t sequenceErrors = 0;  // 17, 18
    std::uint64_t replies = 0;
};

class SerialPort {
public:
    explicit SerialPort(SerialPortConfig config = {});

    void Connect(SerialLine& line) { line_ = &line; }
    bool Connected() const { return line_ != nullptr; }

    // One controller cycle of a booted controller: the bytes arrived by `now`, a command still processing.
    void Cycle(std::chrono::nanoseconds now, CommandHost& host);
    // A controller that is not booted: whatever arrives is lost.
    void Discard(std::chrono::nanoseconds now);
    // Power cycle: no frame begun, no command, no reply to repeat.
    void Reset();

    const SerialPortConfig& Config() const { return config_; }
    const SerialCounters& Counters() const { return counters_; }
    // The texts of every reply sent (between STX and ETX), oldest first.
    const std::vector<std::string>& Replies() const { return replies_; }
    // Every command handed to the command processor, oldest first.
    const std::vector<SerialCommand>& Commands() const { return commands_; }

private:
    struct Ack {
        std::uint16_t code = 0;
        std::uint16_t quit = 0;
        bool end = true;
        std::uint32_t data = 0;
    };

    void OnFrame(const rs232::Rs232Event& frame, std::chrono::nanoseconds now, CommandHost& host);
    void OnPoll(std::chrono::nanoseconds now, CommandHost& host);
    void OnError(std::uint16_t error, bool clearsCommand, std::chrono::nanoseconds now, CommandHost& host);
    bool CheckAccepted(const rs232::Rs232Event& frame) const;
    // The command of a frame's text; 0 and the command's fields set, or 17 / 41.
    std::uint16_t Decode(const std::string& text, CommandFrame& command) const;
    std::string AckText(const Ack& ack, const CommandHost& host) const;
    void Send(const Ack& ack, std::chrono::nanoseconds now, const CommandHost& host);

    SerialPortConfig config_;
    SerialLine* line_ = nullptr;
    rs232::Rs232Receiver receiver_;
    PendingCommand pending_;
    Ack ack_;               // the last reply, or the processing command's acknowledgement
    bool heldReply_ = false;
    bool endUnreported_ = false;  // the last reply said BE = 0
    SerialCounters counters_;
    std::vector<std::string> replies_;
    std::vector<SerialCommand> commands_;
};

}  // namespace pac::sim
