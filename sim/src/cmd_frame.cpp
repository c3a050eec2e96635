// Encoding and decoding of the CMD module in both directions (see cmd_frame.hpp).
#include "pac/sim/cmd_frame.hpp"

namespace pac::sim {

namespace {
constexpr std::uint16_t kBit15 = 0x8000;
constexpr std::uint16_t kBit14 = 0x4000;
constexpr std::uint16_t kBit13 = 0x2000;
constexpr std::uint16_t kErrorNumberMask = 0x1FFF;
constexpr std::uint16_t kCodeMask = 0x7FFF;
}  // namespace

CommandFrame CommandFrame::Decode(const Image8& image) {
    CommandFrame frame;
    frame.data = ReadDword(image, 0);
    frame.parameter = ReadWord(image, 2);
    const std::uint16_t word3 = ReadWord(image, 3);
    frame.send = (word3 & kBit15) != 0;
    frame.code = word3 & kCodeMask;
    return frame;
}

Image8 CommandFrame::Encode() const {
    Image8 image{};
    WriteDword(image, 0, data);
    WriteWord(image, 2, parameter);
    WriteWord(image, 3, static_cast<std::uint16_t>((send ? kBit15 : 0) | (code & kCodeMask)));
    return image;
}

ReplyFrame ReplyFrame::Decode(const Image8& image) {
    ReplyFrame frame;
    frame.ackData = ReadDword(image, 0);
    const std::uint16_t word2 = ReadWord(image, 2);
    frame.errorFlag = (word2 & kBit15) != 0;
    frame.operatingStatus = static_cast<std::uint8_t>(word2 & 0xFF);
    const std::uint16_t word3 = ReadWord(image, 3);
    frame.receiveFlag = (word3 & kBit15) != 0;
    frame.commandErrorFlag = (word3 & kBit14) != 0;
    frame.endOfProcessing = (word3 & kBit13) != 0;
    frame.errorNumber = word3 & kErrorNumberMask;
    return frame;
}

Image8 ReplyFrame::Encode() const {
    Image8 image{};
    WriteDword(image, 0, ackData);
    WriteWord(image, 2, static_cast<std::uint16_t>((errorFlag ? kBit15 : 0) | operatingStatus));
    WriteWord(image, 3,
              static_cast<std::uint16_t>((receiveFlag ? kBit15 : 0) | (commandErrorFlag ? kBit14 : 0) |
                                         (endOfProcessing ? kBit13 : 0) | (errorNumber & kErrorNumberMask)));
    return image;
}

bool operator==(const CommandFrame& a, const CommandFrame& b) {
    return a.data == b.data && a.parameter == b.parameter && a.send == b.send && a.code == b.code;
}

bool operator==(const ReplyFrame& a, const ReplyFrame& b) {
    return a.ackData == b.ackData && a.errorFlag == b.errorFlag && a.operatingStatus == b.operatingStatus &&
           a.receiveFlag == b.receiveFlag && a.commandErrorFlag == b.commandErrorFlag &&
           a.endOfProcessing == b.endOfProcessing && a.errorNumber == b.errorNumber;
}

Image8 CommandImage(std::uint16_t code, std::uint16_t parameter, std::uint32_t data, bool send) {
    CommandFrame frame;
    frame.code = code;
    frame.parameter = parameter;
    frame.data = data;
    frame.send = send;
    return frame.Encode();
}

}  // namespace pac::sim
