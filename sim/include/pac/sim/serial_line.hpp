// The RS232 line between the PLC's serial port and the PA-CONTROL's COM1 (manual 3.1, 3.2): two wires, one
// each way, that carry bytes at the baud rate of the line's format. A byte sent at t goes on the wire when
// the wire is free (at t or after the byte before it), takes one character time (start bit, data bits,
// parity, stop bits at the baud rate) and can be read from the end of its stop bit on. Times are the
// caller's simulated clock; nothing here reads a real clock.
//
// Faults, by the index of a byte on its wire (0 = the first byte ever sent on it), act when that byte is
// sent: DropByte (it takes its time on the wire but never arrives, as a byte with a framing error that a
// UART discards), CorruptByte (arrives XORed with a mask), DelayByte (a gap before it on the wire, which
// delays it and every byte after it). Noise(now, bytes) puts bytes on the wire that nobody sent; random
// drops and corruptions at a seeded rate come from SetRandomFaults. Bytes carry as many bits as the
// format's data bits (7 by default: the top bit is cleared).
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <vector>

#include "pac/sim/rng.hpp"

namespace pac::sim {

struct SerialFormat {
    int baud = 9600;      // 3.1: 9600 baud, 1 start bit, 7 data bits, 1 stop bit, no parity by default
    int dataBits = 7;
    bool parity = false;
    int stopBits = 1;

    int BitsPerCharacter() const { return 1 + dataBits + (parity ? 1 : 0) + stopBits; }
    // The time of one character on the wire, rounded up to whole nanoseconds.
    std::chrono::nanoseconds CharacterTime() const;
};

class SerialWire {
public:
    // baud > 0, dataBits 5..8, stopBits 1..2: std::invalid_argument otherwise.
    explicit SerialWire(SerialFormat format = {}, std::uint64_t seed = 1);

    // Sends in order; `now` must not decrease between calls (std::invalid_argument).
    void Send(std::chrono::nanoseconds now, const std::vector<std::uint8_t>& bytes);
    void Send(std::chrono::nanoseconds now, std::uint8_t byte) { Send(now, std::vector<std::uint8_t>{byte}); }
    // Every byte whose stop bit has ended by `now`, oldest first, taken off the wire.
    std::vector<std::uint8_t> Receive(std::chrono::nanoseconds now);
    // Nothing on its way (every byte sent has arrived or been dropped by `now`).
    bool Idle(std::chrono::nanoseconds now) const { return lastEnd_ <= now; }
    // A byte is on the wire at `now`: its start bit has begun and its stop bit has not ended (a byte sent for
    // later, such as a reply after the controller's turnaround, is not yet on it).
    bool Carrying(std::chrono::nanoseconds now) const;
    // When the last byte sent so far ends.
    std::chrono::nanoseconds LastEnd() const { return lastEnd_; }

    void DropByte(std::uint64_t index) { drops_[index] = true; }
    void CorruptByte(std::uint64_t index, std::uint8_t xorMask) { corruptions_[index] = xorMask; }
    void DelayByte(std::uint64_t index, std::chrono::nanoseconds gap) { delays_[index] = gap; }
    void Noise(std::chrono::nanoseconds now, const std::vector<std::uint8_t>& bytes);
    // Each later byte is dropped with probability dropRate and else corrupted (one random bit) with
    // probability corruptRate, drawn from the wire's seed. Rates in [0, 1], std::invalid_argument otherwise.
    void SetRandomFaults(double dropRate, double corruptRate);

    std::uint64_t BytesSent() const { return sent_; }
    std::uint64_t BytesDropped() const { return dropped_; }
    std::uint64_t BytesCorrupted() const { return corrupted_; }
    const SerialFormat& Format() const { return format_; }

private:
    struct OnWire {
        std::chrono::nanoseconds end;
        std::uint8_t byte;
        bool dropped;
    };
    void Put(std::chrono::nanoseconds now, std::uint8_t byte, bool scripted);
    bool Draw(double rate);

    SerialFormat format_;
    std::chrono::nanoseconds characterTime_;
    std::uint8_t mask_;
    SplitMix64 rng_;
    std::deque<OnWire> onWire_;
    std::chrono::nanoseconds lastEnd_{0};
    std::chrono::nanoseconds lastSend_{std::chrono::nanoseconds::min()};
    std::map<std::uint64_t, bool> drops_;
    std::map<std::uint64_t, std::uint8_t> corruptions_;
    std::map<std::uint64_t, std::chrono::nanoseconds> delays_;
    double dropRate_ = 0.0;
    double corruptRate_ = 0.0;
    std::uint64_t sent_ = 0;
    std::uint64_t dropped_ = 0;
    std::uint64_t corrupted_ = 0;
};

// Both wires of one line, in the library's directions: to PAC (PLC -> PA-CONTROL) and from PAC.
struct SerialLine {
    explicit SerialLine(SerialFormat format = {}, std::uint64_t seed = 1)
        : toPac(format, seed), fromPac(format, seed ^ 0x5A5A5A5AULL) {}
    SerialWire toPac;
    SerialWire fromPac;
};

}  // namespace pac::sim
