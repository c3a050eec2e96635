// Image8 helpers and the CMD frame layout of manual 2.4.1 / 2.4.2 (big-endian words at PAC bytes).
#include <stdexcept>

#include <gtest/gtest.h>

#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/image8.hpp"

namespace pac::sim {
namespace {

TEST(Image8, WordsAndDwordsAreBigEndianAtPacByteOffsets) {
    const Image8 image = FromHex("01 02 03 04 05 06 07 08");
    EXPECT_EQ(ReadWord(image, 0), 0x0102);
    EXPECT_EQ(ReadWord(image, 1), 0x0304);
    EXPECT_EQ(ReadWord(image, 2), 0x0506);
    EXPECT_EQ(ReadWord(image, 3), 0x0708);
    EXPECT_EQ(ReadDword(image, 0), 0x01020304U);
    EXPECT_EQ(ReadDword(image, 4), 0x05060708U);
    EXPECT_EQ(ReadDword(image, 2), 0x03040506U);
}

TEST(Image8, WritesTouchOnlyTheirBytes) {
    Image8 image = FromHex("11 11 11 11 11 11 11 11");
    WriteWord(image, 2, 0xABCD);
    EXPECT_EQ(ToHex(image), "11 11 11 11 AB CD 11 11");
    WriteDword(image, 0, 0x00BC614E);
    EXPECT_EQ(ToHex(image), "00 BC 61 4E AB CD 11 11");
    WriteWord(image, 3, 0x8000);
    EXPECT_EQ(ToHex(image), "00 BC 61 4E AB CD 80 00");
}

TEST(Image8, OffsetsOutsideTheImageThrow) {
    Image8 image{};
    EXPECT_THROW(ReadWord(image, 4), std::out_of_range);
    EXPECT_THROW(ReadWord(image, -1), std::out_of_range);
    EXPECT_THROW(ReadDword(image, 5), std::out_of_range);
    EXPECT_THROW(WriteWord(image, 4, 1), std::out_of_range);
    EXPECT_THROW(WriteDword(image, 6, 1), std::out_of_range);
}

TEST(Image8, HexRoundTripAndBadInput) {
    EXPECT_EQ(ToHex(FromHex("00 bc 61 4e 00 01 20 00")), "00 BC 61 4E 00 01 20 00");
    EXPECT_EQ(ToHex(FromHex("44200000000120FF")), "44 20 00 00 00 01 20 FF");
    EXPECT_THROW(FromHex("00 00 00"), std::invalid_argument);
    EXPECT_THROW(FromHex("00 00 00 00 00 00 00 0G"), std::invalid_argument);
    EXPECT_THROW(FromHex("00 00 00 00 00 00 00 00 00"), std::invalid_argument);
    EXPECT_TRUE(IsAllZero(FromHex("00 00 00 00 00 00 00 00")));
    EXPECT_FALSE(IsAllZero(FromHex("00 00 00 00 00 00 00 01")));
}

// The IEEE values of the manual, checked against docs/manual_errata.md (several printed patterns are wrong).
TEST(Image8, RealBitPatterns) {
    EXPECT_EQ(FloatToBits(10.0F), 0x41200000U);
    EXPECT_EQ(FloatToBits(200.0F), 0x43480000U);
    EXPECT_EQ(FloatToBits(640.0F), 0x44200000U);  // the manual prints 44 20 20 00
    EXPECT_EQ(BitsToFloat(0x44202000U), 640.5F);
    EXPECT_EQ(BitsToFloat(0x40160000U), 2.34375F);  // printed as 0.34375
    EXPECT_EQ(FloatToBits(0.34375F), 0x3EB00000U);
    EXPECT_EQ(FloatToBits(20480.0F), 0x46A00000U);
    EXPECT_EQ(FloatToBits(5000.0F), 0x459C4000U);
    EXPECT_EQ(FloatToBits(50000.0F), 0x47435000U);
    EXPECT_EQ(FloatToBits(7000.0F), 0x45DAC000U);
    EXPECT_EQ(FloatToBits(10000.0F), 0x461C4000U);
    EXPECT_EQ(FloatToBits(111.111F), 0x42DE38D5U);
}

TEST(CmdFrame, CommandImageLayout) {
    // 2.4.1: data dword at bytes 0..3, parameter word 2, SEND bit 15 and code in word 3.
    EXPECT_EQ(ToHex(CommandImage(0x1900, 5, 0, false)), "00 00 00 00 00 05 19 00");
    EXPECT_EQ(ToHex(CommandImage(0x1900, 5, 0, true)), "00 00 00 00 00 05 99 00");
    EXPECT_EQ(ToHex(CommandImage(0x0906, 3, 333, true)), "00 00 01 4D 00 03 89 06");
    const CommandFrame frame = CommandFrame::Decode(FromHex("44 20 00 00 01 02 8A 87"));
    EXPECT_EQ(frame.data, 0x44200000U);
    EXPECT_EQ(frame.parameter, 0x0102);
    EXPECT_TRUE(frame.send);
    EXPECT_EQ(frame.code, 0x0A87);
    EXPECT_EQ(ToHex(frame.Encode()), "44 20 00 00 01 02 8A 87");
}

TEST(CmdFrame, ReplyImageLayout) {
    // 2.4.2: word 2 = FE bit 15 + status bits 7..0; word 3 = RF 15, KF 14, BF 13, error 12..0.
    ReplyFrame reply;
    reply.ackData = 1;
    reply.operatingStatus = 1;
    reply.receiveFlag = true;
    reply.endOfProcessing = true;
    EXPECT_EQ(ToHex(reply.Encode()), "00 00 00 01 00 01 A0 00");
    reply.receiveFlag = false;
    EXPECT_EQ(ToHex(reply.Encode()), "00 00 00 01 00 01 20 00");
    reply.errorFlag = true;
    reply.operatingStatus = 31;
    reply.endOfProcessing = false;
    reply.commandErrorFlag = true;
    reply.errorNumber = 0x1FFF;
    EXPECT_EQ(ToHex(reply.Encode()), "00 00 00 01 80 1F 5F FF");
    const ReplyFrame decoded = ReplyFrame::Decode(FromHex("00 00 00 01 80 1F 5F FF"));
    EXPECT_TRUE(decoded == reply);
    EXPECT_EQ(decoded.errorNumber, 0x1FFF);
    EXPECT_FALSE(decoded.receiveFlag);
}

}  // namespace
}  // namespace pac::sim
