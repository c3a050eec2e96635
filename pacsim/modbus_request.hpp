// Which Modbus requests pac-sim serves and where they may reach (docs/virtual_commissioning.md, "Function codes
// and exceptions"), decided before libmodbus answers: libmodbus frames the request and builds the reply from a
// register table, this check keeps the table's holes and the read-only from-PAC image out of reach.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pac::pacsim {

// Modbus exception codes (Modbus Application Protocol 1.1b3, 7).
constexpr int kIllegalFunction = 0x01;
constexpr int kIllegalDataAddress = 0x02;
constexpr int kIllegalDataValue = 0x03;
constexpr int kGatewayPathUnavailable = 0x0A;

struct RequestCheck {
    int exception = 0;      // 0: serve it; else the exception code to answer with
    int writeFirst = 0;     // the to-PAC registers it writes, when writeCount > 0
    int writeCount = 0;
};

// `pdu` (function code first, `length` bytes) against a controller whose images have `imageRegisters`
// registers each: function codes 3 (holding registers 0..imageRegisters-1 and kFromPacHoldingBase..),
// 4 (input registers 0..imageRegisters-1), 6, 16 (holding registers 0..imageRegisters-1) and 23 (both);
// every other code: kIllegalFunction; a quantity out of the protocol's range or a byte count that does
// not match it: kIllegalDataValue; a register outside those ranges: kIllegalDataAddress.
RequestCheck CheckRequest(const std::uint8_t* pdu, std::size_t length, int imageRegisters);

}  // namespace pac::pacsim
