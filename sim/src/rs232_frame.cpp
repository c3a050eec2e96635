// RS232 frames, numbers and the controller's receiver (see rs232_frame.hpp and docs/sim_serial.md).
#include "pac/sim/rs232_frame.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace pac::sim::rs232 {

int Check(std::string_view text, CheckRule rule) {
    if (rule == CheckRule::kZero) return 0;
    unsigned sum = 0;
    for (char c : text) sum ^= static_cast<unsigned char>(c);
    if (rule == CheckRule::kXorWithEtx) sum ^= kEtx;
    return static_cast<int>(sum);
}

std::vector<std::uint8_t> Frame(std::string_view text, int check, bool withSoh) {
    std::vector<std::uint8_t> bytes;
    if (withSoh) bytes.push_back(kSoh);
    bytes.push_back(kStx);
    bytes.insert(bytes.end(), text.begin(), text.end());
    bytes.push_back(kEtx);
    for (char c : std::to_string(check)) bytes.push_back(static_cast<std::uint8_t>(c));
    bytes.push_back(kEot);
    return bytes;
}

std::vector<std::uint8_t> Frame(std::string_view text, CheckRule rule) { return Frame(text, Check(text, rule)); }

std::vector<std::string> Fields(std::string_view text) {
    std::vector<std::string> fields(1);
    for (char c : text) {
        if (c == ';') {
            fields.emplace_back();
        } else {
            fields.back().push_back(c);
        }
    }
    return fields;
}

bool IsNumber(std::string_view s, bool allowFraction) {
    std::size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    auto digits = [&] {
        const std::size_t start = i;
        while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
        return i - start;
    };
    if (digits() == 0) return false;
    if (allowFraction && i < s.size() && s[i] == '.') {
        ++i;
        if (digits() == 0) return false;
    }
    if (allowFraction && i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        const std::size_t n = digits();
        if (n == 0 || n > 3) return false;
    }
    return i == s.size();
}

double NumberValue(std::string_view s) { return std::strtod(std::string(s).c_str(), nullptr); }

std::string FormatReal(float value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, static_cast<double>(value));
    return buffer;
}

bool TakesData(std::uint16_t code) {
    switch (code) {
        case 0x0700: case 0x0800: case 0x0902: case 0x0903: case 0x0904: case 0x0905: case 0x0906: case 0x0907:
        case 0x0A86: case 0x0A87: case 0x0A89: case 0x0A8D: case 0x0A8E: case 0x0A90: case 0x0A91:
        case 0x0A94: case 0x0A95: case 0x0A96: case 0x0AA2: case 0x0AA3:
            return true;
        default:
            return false;
    }
}

bool DataIsReal(std::uint16_t code) {
    // 0AA2 (monitoring 0 / 1) and 0AA3 (the condition's bytes) carry an integer, 5.2.6.22 / 5.2.6.23.
    const bool integer = code == 0x0AA2 || code == 0x0AA3;
    return TakesData(code) && !integer && (code == 0x0800 || code == 0x0907 || code >= 0x0A00);
}

bool AckIsPosition(std::uint16_t code) {
    switch (code) {
        case 0x190C: case 0x190E: case 0x0A86: case 0x0A87: case 0x0A89: case 0x0A90: case 0x0A91: case 0x0A92:
        case 0x0A93: case 0x0A94: case 0x0A95: case 0x0A96: case 0x0A9A:
            return true;
        default:
            return false;
    }
}

bool AckIsReal(std::uint16_t code) {
    switch (code) {
        case 0x0800: case 0x1800: case 0x1801: case 0x1802: case 0x0907: case 0x1907: case 0x1937:
        case 0x190D: case 0x1913: case 0x1914: case 0x0A8D: case 0x0A8E:
            return true;
        default:
            return AckIsPosition(code);
    }
}

void Rs232Receiver::Reset() {
    phase_ = Phase::kOutside;
    garbage_ = false;
    text_.clear();
    check_.clear();
}

std::optional<Rs232Event> Rs232Receiver::Feed(std::uint8_t byte) {
    const bool begins = byte == kSoh || (byte == kStx && (!requireSoh_ || phase_ != Phase::kOutside));
    if (begins) {
        // A frame begun before is dropped without an answer: its sender has moved on to this one.
        phase_ = byte == kSoh ? Phase::kAfterSoh : Phase::kText;
        garbage_ = false;
        text_.clear();
        check_.clear();
        return std::nullopt;
    }
    switch (phase_) {
        case Phase::kOutside:
            if (byte != kEot) {
                garbage_ = true;
                return std::nullopt;
            }
            if (garbage_) {
                garbage_ = false;
                return Rs232Event{Rs232Event::Kind::kSequenceError, {}, {}, 18};
            }
            return Rs232Event{Rs232Event::Kind::kPoll, {}, {}, 0};
        case Phase::kAfterSoh:
            // SOH not followed by STX: a wrong beginning, answered at the EOT that ends it.
            phase_ = Phase::kOutside;
            if (byte == kEot) return Rs232Event{Rs232Event::Kind::kSequenceError, {}, {}, 18};
            garbage_ = true;
            return std::nullopt;
        case Phase::kText:
            if (byte == kEtx) {
                phase_ = Phase::kCheck;
            } else if (byte >= 0x20 && text_.size() < kMaxText) {
                text_.push_back(static_cast<char>(byte));
            } else if (byte == kEot) {
                phase_ = Phase::kOutside;
                return Rs232Event{Rs232Event::Kind::kSequenceError, {}, {}, 17};
            } else {
                phase_ = Phase::kBroken;
            }
            return std::nullopt;
        case Phase::kCheck:
            if (byte >= '0' && byte <= '9' && check_.size() < 3) {
                check_.push_back(static_cast<char>(byte));
                return std::nullopt;
            }
            if (byte == kEot && !check_.empty()) {
                phase_ = Phase::kOutside;
                return Rs232Event{Rs232Event::Kind::kFrame, text_, check_, 0};
            }
            if (byte == kEot) {
                phase_ = Phase::kOutside;
                return Rs232Event{Rs232Event::Kind::kSequenceError, {}, {}, 17};
            }
            phase_ = Phase::kBroken;
            return std::nullopt;
        case Phase::kBroken:
            if (byte == kEot) {
                phase_ = Phase::kOutside;
                return Rs232Event{Rs232Event::Kind::kSequenceError, {}, {}, 17};
            }
            return std::nullopt;
    }
    return std::nullopt;
}

}  // namespace pac::sim::rs232
