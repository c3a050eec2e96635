// The RS232 line's timing and faults (see serial_line.hpp).
#include "pac/sim/serial_line.hpp"

#include <stdexcept>

namespace pac::sim {

std::chrono::nanoseconds SerialFormat::CharacterTime() const {
    const std::int64_t bits = BitsPerCharacter();
    return std::chrono::nanoseconds((bits * 1000000000LL + baud - 1) / baud);
}

SerialWire::SerialWire(SerialFormat format, std::uint64_t seed)
    : format_(format), characterTime_(0), mask_(0), rng_(seed) {
    if (format.baud <= 0 || format.dataBits < 5 || format.dataBits > 8 || format.stopBits < 1 || format.stopBits > 2) {
        throw std::invalid_argument("SerialWire: baud > 0, 5..8 data bits and 1..2 stop bits");
    }
    characterTime_ = format.CharacterTime();
    mask_ = static_cast<std::uint8_t>((1U << format.dataBits) - 1U);
}

void SerialWire::Send(std::chrono::nanoseconds now, const std::vector<std::uint8_t>& bytes) {
    if (now < lastSend_) throw std::invalid_argument("SerialWire::Send: time runs backwards");
    lastSend_ = now;
    for (std::uint8_t byte : bytes) Put(now, byte, true);
}

void SerialWire::Noise(std::chrono::nanoseconds now, const std::vector<std::uint8_t>& bytes) {
    if (now < lastSend_) throw std::invalid_argument("SerialWire::Noise: time runs backwards");
    lastSend_ = now;
    for (std::uint8_t byte : bytes) Put(now, byte, false);
}

void SerialWire::Put(std::chrono::nanoseconds now, std::uint8_t byte, bool scripted) {
    std::chrono::nanoseconds start = now > lastEnd_ ? now : lastEnd_;
    OnWire b{start, static_cast<std::uint8_t>(byte & mask_), false};
    if (scripted) {
        // Noise is not counted: the scripted faults name the bytes someone sent.
        const std::uint64_t index = sent_++;
        if (auto d = delays_.find(index); d != delays_.end()) start += d->second;
        if (drops_.count(index) != 0) b.dropped = true;
        if (auto c = corruptions_.find(index); c != corruptions_.end()) {
            b.byte = static_cast<std::uint8_t>((b.byte ^ c->second) & mask_);
            ++corrupted_;
        }
        if (!b.dropped && Draw(dropRate_)) {
            b.dropped = true;
        } else if (!b.dropped && Draw(corruptRate_)) {
            b.byte = static_cast<std::uint8_t>((b.byte ^ (1U << rng_.UniformUpTo(format_.dataBits - 1))) & mask_);
            ++corrupted_;
        }
        if (b.dropped) ++dropped_;
    }
    b.end = start + characterTime_;
    lastEnd_ = b.end;
    onWire_.push_back(b);
}

bool SerialWire::Draw(double rate) {
    if (rate <= 0.0) return false;
    constexpr std::uint64_t kScale = 1000000;
    return rng_.UniformUpTo(kScale - 1) < static_cast<std::uint64_t>(rate * kScale);
}

void SerialWire::SetRandomFaults(double dropRate, double corruptRate) {
    if (dropRate < 0.0 || dropRate > 1.0 || corruptRate < 0.0 || corruptRate > 1.0) {
        throw std::invalid_argument("SerialWire::SetRandomFaults: rates in [0, 1]");
    }
    dropRate_ = dropRate;
    corruptRate_ = corruptRate;
}

std::vector<std::uint8_t> SerialWire::Receive(std::chrono::nanoseconds now) {
    std::vector<std::uint8_t> arrived;
    while (!onWire_.empty() && onWire_.front().end <= now) {
        if (!onWire_.front().dropped) arrived.push_back(onWire_.front().byte);
        onWire_.pop_front();
    }
    return arrived;
}

bool SerialWire::Carrying(std::chrono::nanoseconds now) const {
    for (const OnWire& b : onWire_) {
        if (b.end > now) return b.end - characterTime_ <= now;
    }
    return false;
}

}  // namespace pac::sim
