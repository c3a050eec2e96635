#include "modbus_request.hpp"

#include "register_map.hpp"

namespace pac::pacsim {

namespace {

// Protocol limits (Modbus Application Protocol 6.3, 6.4, 6.12, 6.17).
constexpr int kMaxRead = 125;
constexpr int kMaxWrite = 123;
constexpr int kMaxReadWriteWrite = 121;

int Word(const std::uint8_t* pdu, std::size_t at) { return pdu[at] << 8 | pdu[at + 1]; }

bool Inside(int first, int count, int base, int registers) { return first >= base && first + count <= base + registers; }

bool ReadableHolding(int first, int count, int registers) {
    return Inside(first, count, 0, registers) || Inside(first, count, kFromPacHoldingBase, registers);
}

RequestCheck Refuse(int exception) {
    RequestCheck check;
    check.exception = exception;
    return check;
}

}  // namespace

RequestCheck CheckRequest(const std::uint8_t* pdu, std::size_t length, int imageRegisters) {
    if (length < 1) return Refuse(kIllegalFunction);
    const int function = pdu[0];
    // The fixed part of each served request: function code, then its address and quantity fields.
    std::size_t fixed = 0;
    switch (function) {
        case 3: case 4: case 6: fixed = 5; break;
        case 16: fixed = 6; break;
        case 23: fixed = 10; break;
        default: return Refuse(kIllegalFunction);
    }
    if (length < fixed) return Refuse(kIllegalDataValue);
    const int address = Word(pdu, 1);
    if (function == 6) {
        if (!Inside(address, 1, 0, imageRegisters)) return Refuse(kIllegalDataAddress);
        return {0, address, 1};
    }
    const int count = Word(pdu, 3);
    if (function == 3 || function == 4) {
        if (count < 1 || count > kMaxRead) return Refuse(kIllegalDataValue);
        const bool inside = function == 3 ? ReadableHolding(address, count, imageRegisters)
                                          : Inside(address, count, 0, imageRegisters);
        return inside ? RequestCheck{} : Refuse(kIllegalDataAddress);
    }
    if (function == 16) {
        if (count < 1 || count > kMaxWrite || pdu[5] != 2 * count || length != fixed + 2 * static_cast<std::size_t>(count)) {
            return Refuse(kIllegalDataValue);
        }
        if (!Inside(address, count, 0, imageRegisters)) return Refuse(kIllegalDataAddress);
        return {0, address, count};
    }
    // 23: read address and quantity, write address and quantity, byte count, values.
    const int writeAddress = Word(pdu, 5);
    const int writeCount = Word(pdu, 7);
    if (count < 1 || count > kMaxRead || writeCount < 1 || writeCount > kMaxReadWriteWrite || pdu[9] != 2 * writeCount ||
        length != fixed + 2 * static_cast<std::size_t>(writeCount)) {
        return Refuse(kIllegalDataValue);
    }
    if (!ReadableHolding(address, count, imageRegisters) || !Inside(writeAddress, writeCount, 0, imageRegisters)) {
        return Refuse(kIllegalDataAddress);
    }
    return {0, writeAddress, writeCount};
}

}  // namespace pac::pacsim
