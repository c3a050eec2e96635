// The PA-CONTROL's RS232 command port (see serial_port.hpp and docs/sim_serial.md).
#include "pac/sim/serial_port.hpp"

#include <cmath>
#include <cstdlib>

#include "pac/sim/image8.hpp"

namespace pac::sim {

namespace {

constexpr std::uint16_t kCheckError = 16;
constexpr std::uint16_t kSetUpError = 17;
constexpr std::uint16_t kBeginningError = 18;
constexpr std::uint16_t kValueOutsideRange = 41;

bool IsHexCode(const std::string& s) {
    if (s.size() != 4) return false;
    for (char c : s) {
        const bool hex = (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f');
        if (!hex) return false;
    }
    return true;
}

}  // namespace

SerialPort::SerialPort(SerialPortConfig config) : config_(config), receiver_(config.requireSoh) {}

void SerialPort::Reset() {
    receiver_ = rs232::Rs232Receiver(config_.requireSoh);
    pending_ = PendingCommand{};
    ack_ = Ack{};
    heldReply_ = false;
    endUnreported_ = false;
}

void SerialPort::Discard(std::chrono::nanoseconds now) {
    if (line_ != nullptr) line_->toPac.Receive(now);
}

void SerialPort::Cycle(std::chrono::nanoseconds now, CommandHost& host) {
    if (line_ == nullptr) return;
    if (pending_.Active()) {
        const CommandResult progress = host.Progress(pending_, now);
        ack_.data = progress.ackData;
        ack_.end = progress.finished;
        if (progress.finished) {
            pending_ = PendingCommand{};
            if (heldReply_) {
                heldReply_ = false;
                Send(ack_, now, host);
            }
        }
    }
    for (std::uint8_t byte : line_->toPac.Receive(now)) {
        const auto event = receiver_.Feed(byte);
        if (!event) continue;
        switch (event->kind) {
            case rs232::Rs232Event::Kind::kFrame: OnFrame(*event, now, host); break;
            case rs232::Rs232Event::Kind::kPoll: OnPoll(now, host); break;
            case rs232::Rs232Event::Kind::kSequenceError:
                // A broken frame (17) was a request: it ends what the port reported before. Bytes that began
                // no frame (18) may be noise before a poll and leave a processing command alone.
                OnError(event->error, event->error == kSetUpError, now, host);
                break;
        }
    }
}

bool SerialPort::CheckAccepted(const rs232::Rs232Event& frame) const {
    if (config_.verify == CheckVerification::kNone) return true;
    const int check = std::atoi(frame.check.c_str());
    if (check == 0 && config_.acceptZeroCheck) return true;
    const rs232::CheckRule rule = config_.verify == CheckVerification::kXorText ? rs232::CheckRule::kXorText
                                                                                 : rs232::CheckRule::kXorWithEtx;
    return check == rs232::Check(frame.text, rule);
}

std::uint16_t SerialPort::Decode(const std::string& text, CommandFrame& command) const {
    const std::vector<std::string> f = rs232::Fields(text);
    if (f.size() != 4 || !IsHexCode(f[0]) || !rs232::IsNumber(f[1], false) || (f[2] != "0" && f[2] != "1")) {
        return kSetUpError;
    }
    const bool typeReal = f[2] == "1";
    if (!rs232::IsNumber(f[3], typeReal)) return kSetUpError;
    command.code = static_cast<std::uint16_t>(std::strtoul(f[0].c_str(), nullptr, 16) & 0x7FFF);
    const double parameter = rs232::NumberValue(f[1]);
    if (parameter > 65535.0) return kSetUpError;
    command.parameter = static_cast<std::uint16_t>(parameter);
    command.data = 0;
    if (!rs232::TakesData(command.code)) return 0;
    const bool commandReal = rs232::DataIsReal(command.code);
    if (config_.refuseTypeMismatch && typeReal != commandReal) return kValueOutsideRange;
    const double value = rs232::NumberValue(f[3]);
    if (commandReal) {
        command.data = FloatToBits(static_cast<float>(value));
        return 0;
    }
    // An integer command takes a floating-point number as C converts it: toward zero.
    const double whole = std::trunc(value);
    if (whole < -2147483648.0 || whole > 2147483647.0) return kValueOutsideRange;
    command.data = static_cast<std::uint32_t>(static_cast<std::int32_t>(whole));
    return 0;
}

void SerialPort::OnFrame(const rs232::Rs232Event& frame, std::chrono::nanoseconds now, CommandHost& host) {
    ++counters_.frames;
    if (!CheckAccepted(frame)) {
        ++counters_.checkErrors;
        // A controller that discards such a frame silently has not seen a request at all.
        if (!config_.answerBadCheck && config_.discardBadCheckFrame) return;
        pending_ = PendingCommand{};
        heldReply_ = false;
        ack_ = Ack{0, kCheckError, false, 0};
        if (config_.answerBadCheck) Send(ack_, now, host);
        return;
    }
    if (config_.acceptZeroCheck && config_.verify != CheckVerification::kNone && std::atoi(frame.check.c_str()) == 0) {
        ++counters_.unchecked;  // "0" may be the XOR too: the controller cannot tell, nothing was verified
    }
    // Any frame is a new request: the command reported so far is no longer followed (as on the CMD
    // interface, docs/sim_cmd.md); its axis goes on.
    pending_ = PendingCommand{};
    heldReply_ = false;
    CommandFrame command;
    const std::uint16_t refused = Decode(frame.text, command);
    if (refused == kSetUpError) {
        OnError(kSetUpError, true, now, host);
        return;
    }
    if (refused != 0) {
        ack_ = Ack{command.code, refused, false, 0};
        Send(ack_, now, host);
        return;
    }
    ++counters_.commands;
    const CommandResult result = host.RunCommand(command, now, pending_);
    commands_.push_back(SerialCommand{command.code, command.parameter, command.data, result.error, now});
    ack_ = Ack{command.code, result.error, result.error == 0 && result.finished, result.ackData};
    if (config_.holdModeReplies && pending_.kind == PendingCommand::Kind::kModeChange) {
        heldReply_ = true;
        return;
    }
    Send(ack_, now, host);
}

void SerialPort::OnPoll(std::chrono::nanoseconds now, CommandHost& host) {
    ++counters_.polls;
    if (heldReply_) return;  // the held reply answers it
    // A command whose end the master has not been told yet is answered in any case (3.3.1: poll until BE = 1).
    if (pending_.Active() || endUnreported_ || config_.answerPollWhenIdle) Send(ack_, now, host);
}

void SerialPort::OnError(std::uint16_t error, bool clearsCommand, std::chrono::nanoseconds now, CommandHost& host) {
    ++counters_.sequenceErrors;
    const Ack reply{0, error, false, 0};
    if (clearsCommand || !pending_.Active()) {
        pending_ = PendingCommand{};
        heldReply_ = false;
        ack_ = reply;
    }
    if (config_.answerSequenceErrors) Send(reply, now, host);
}

std::string SerialPort::AckText(const Ack& ack, const CommandHost& host) const {
    const bool real = ack.quit == 0 && rs232::AckIsReal(ack.code);
    std::string value;
    if (real) {
        const int decimals = rs232::AckIsPosition(ack.code) ? config_.positionDecimals : config_.realDecimals;
        value = rs232::FormatReal(BitsToFloat(ack.data), decimals);
    } else {
        value = std::to_string(static_cast<std::int32_t>(ack.data));
    }
    return std::to_string(ack.quit) + ";" + (ack.end ? "1" : "0") + ";" + std::to_string(host.Status()) + ";" +
           std::to_string(host.SystemError()) + ";" + (real ? "1" : "0") + ";" + value;
}

void SerialPort::Send(const Ack& ack, std::chrono::nanoseconds now, const CommandHost& host) {
    if (!config_.answers) return;
    endUnreported_ = !ack.end && ack.quit == 0;
    const std::string text = AckText(ack, host);
    replies_.push_back(text);
    ++counters_.replies;
    line_->fromPac.Send(now + config_.turnaround, rs232::Frame(text, rs232::Check(text, config_.replyCheck)));
}

}  // namespace pac::sim
