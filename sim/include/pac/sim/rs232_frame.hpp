// The frames of the RS232 protocol (manual 3.3, 3.3.1) as bytes, with the errata of docs/manual_errata.md and the
// decisions of docs/sim_serial.md:
//   command:         SOH STX CMD ; PAR_1 ; TYP_PAR_2 ; PAR_2 ETX CHECK EOT
//   acknowledgement: SOH STX QUIT ; BE ; STATUS ; ERROR ; TYP_QUIT ; Q_PAR ETX CHECK EOT
//   poll:            EOT alone
// CHECK is a decimal number of 1 to 3 digits: the XOR of the text and ETX (the rule of the manual's
// acknowledgements), of the text alone, or 0 (3.1). Rs232Receiver is the controller's receiving side:
// it turns a byte stream into frames, polls and sequence errors.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pac::sim::rs232 {

constexpr std::uint8_t kSoh = 0x01;
constexpr std::uint8_t kStx = 0x02;
constexpr std::uint8_t kEtx = 0x03;
constexpr std::uint8_t kEot = 0x04;
constexpr std::size_t kMaxText = 64;

enum class CheckRule { kXorWithEtx, kXorText, kZero };

int Check(std::string_view text, CheckRule rule);
// SOH STX text ETX check EOT (without SOH when withSoh is false).
std::vector<std::uint8_t> Frame(std::string_view text, int check, bool withSoh = true);
std::vector<std::uint8_t> Frame(std::string_view text, CheckRule rule);

// The fields of a text split at ';'.
std::vector<std::string> Fields(std::string_view text);

// Decimal numbers as 3.1's itoa() / ftoa(): an optional sign and digits; with a fraction also a point
// with digits and an exponent. Leading zeros are fine ("0543", 5.2).
bool IsNumber(std::string_view s, bool allowFraction);
// The value of a number IsNumber accepted with a fraction allowed.
double NumberValue(std::string_view s);
// A REAL in fixed point with `decimals` decimals (3.4: 640.0000, 1255.000).
std::string FormatReal(float value, int decimals);

// What the commands of chapter 5 carry over RS232 (data type flags of 3.3).
bool TakesData(std::uint16_t code);          // PAR_2 is used (writes, moves, speeds)
bool DataIsReal(std::uint16_t code);         // ... as a floating-point number
bool AckIsReal(std::uint16_t code);          // Q_PAR is a floating-point number
bool AckIsPosition(std::uint16_t code);      // ... an axis position (3.4.3 writes 3 decimals)

struct Rs232Event {
    enum class Kind { kFrame, kPoll, kSequenceError };
    Kind kind = Kind::kPoll;
    std::string text;        // kFrame: between STX and ETX
    std::string check;       // kFrame: the CHECK digits
    std::uint16_t error = 0; // kSequenceError: 17 wrong sequence set-up, 18 wrong sequence beginning
};

// The controller's receiver (docs/sim_serial.md, "Receiving"):
//   outside a frame: SOH (or STX when SOH is not required) begins one; EOT is a poll, unless bytes that
//     began no frame came since the last frame or poll: then it ends a wrong beginning (18);
//   in a frame: a new SOH or STX drops the frame begun and begins another; EOT before ETX, any other
//     control symbol, more than 64 text bytes or more than 3 CHECK digits make it a wrong set-up (17),
//     reported at the EOT that ends it; EOT after ETX and 1..3 digits ends the frame.
class Rs232Receiver {
public:
    explicit Rs232Receiver(bool requireSoh = true) : requireSoh_(requireSoh) {}
    std::optional<Rs232Event> Feed(std::uint8_t byte);
    void Reset();

private:
    enum class Phase { kOutside, kAfterSoh, kText, kCheck, kBroken };
    bool requireSoh_;
    Phase phase_ = Phase::kOutside;
    bool garbage_ = false;
    std::string text_;
    std::string check_;
};

}  // namespace pac::sim::rs232
