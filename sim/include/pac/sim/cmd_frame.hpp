// The meaning of the CMD module's bytes in each direction (manual 2.4.1, 2.4.2, 4.2.2), decoded from
// and encoded into an Image8:
//   to PAC (CommandFrame): dword 0 (bytes 0..3) command data, word 2 command parameter,
//                          word 3 = SEND flag (bit 15) | command code (bits 14..0).
//   from PAC (ReplyFrame): dword 0 acknowledgement data, word 2 = FE (bit 15) | operating status
//                          (bits 7..0, decimal codes: ONLINE = 31 = 16#1F), word 3 = RF (bit 15) |
//                          KF (bit 14) | BF (bit 13) | command error number (bits 12..0).
// 16-bit command data and acknowledgement data sit in bytes 2..3, the low word of the dword.
#pragma once

#include <cstdint>

#include "pac/sim/image8.hpp"

namespace pac::sim {

struct CommandFrame {
    std::uint32_t data = 0;
    std::uint16_t parameter = 0;
    bool send = false;
    std::uint16_t code = 0;  // 15 bits; bit 15 of an encoded code is dropped

    static CommandFrame Decode(const Image8& image);
    Image8 Encode() const;
};

struct ReplyFrame {
    std::uint32_t ackData = 0;
    bool errorFlag = false;           // FE
    std::uint8_t operatingStatus = 0;
    bool receiveFlag = false;         // RF
    bool commandErrorFlag = false;    // KF
    bool endOfProcessing = false;     // BF
    std::uint16_t errorNumber = 0;    // 13 bits

    static ReplyFrame Decode(const Image8& image);
    Image8 Encode() const;
};

bool operator==(const CommandFrame& a, const CommandFrame& b);
bool operator==(const ReplyFrame& a, const ReplyFrame& b);

// Builds a to-PAC CMD image, as tests write them by hand: CommandImage(0x1906, 2, 0, true).
Image8 CommandImage(std::uint16_t code, std::uint16_t parameter, std::uint32_t data, bool send);

}  // namespace pac::sim
