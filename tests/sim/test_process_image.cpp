// The process image of the bus: module layout (manual 2.3), module access, and links that carry it.
#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>

#include "pac/sim/bus.hpp"
#include "pac/sim/link.hpp"
#include "pac/sim/process_image.hpp"

namespace pac::sim {
namespace {

using namespace std::chrono_literals;

TEST(ModuleLayout, SizesFollowTheExtensionsOfChapter2_3) {
    EXPECT_EQ((ModuleLayout{}).Bytes(), 8u);
    EXPECT_EQ((ModuleLayout{true, 0}).Bytes(), 16u);
    EXPECT_EQ((ModuleLayout{true, 8}).Bytes(), 112u);  // 2.3.3: "8, 16, ..., 112 bytes"
    EXPECT_EQ((ModuleLayout{true, 2}).AxisOffset(1), 16u);
    EXPECT_EQ((ModuleLayout{true, 2}).AxisOffset(2), 28u);
    EXPECT_THROW((ModuleLayout{true, 2}).AxisOffset(3), std::out_of_range);
    EXPECT_THROW((ModuleLayout{true, 2}).AxisOffset(0), std::out_of_range);
}

TEST(ModuleLayout, RejectsLayoutsNoPaControlHas) {
    EXPECT_THROW((ModuleLayout{false, 1}).Validate(), std::invalid_argument);  // axes need CTRL
    EXPECT_THROW((ModuleLayout{true, 9}).Validate(), std::invalid_argument);
    EXPECT_THROW((ModuleLayout{true, -1}).Validate(), std::invalid_argument);
    EXPECT_NO_THROW((ModuleLayout{true, 8}).Validate());
    EXPECT_THROW(Bus(BusConfig{{}, {}, ModuleLayout{false, 2}}), std::invalid_argument);
}

TEST(ProcessImage, ModulesSitAtTheirOffsets) {
    ProcessImage image(ModuleLayout{true, 1}.Bytes());
    image.SetModule8(ModuleLayout::kCtrlOffset, Image8{1, 2, 3, 4, 5, 6, 7, 8});
    Image12 axis{};
    WriteDword(axis, 0, 0x00000045u);
    WriteWordAt(axis, 6, 1000);
    WriteDword(axis, 8, FloatToBits(10.0f));
    image.SetModule12(16, axis);
    EXPECT_EQ(ToHex(image, ModuleLayout{true, 1}),
              "00 00 00 00 00 00 00 00 | 01 02 03 04 05 06 07 08 | 00 00 00 45 00 00 03 E8 41 20 00 00");
    EXPECT_EQ(ReadWordAt(image.Module12(16), 6), 1000);
    EXPECT_EQ(image.Module8(8)[7], 8);
    EXPECT_FALSE(image.AllZero());
    EXPECT_THROW(image.Module12(20), std::out_of_range);
    EXPECT_THROW(ReadDword(axis, 9), std::out_of_range);
}

TEST(ProcessImage, HoldsAtMostTheLargestLayout) {
    // 2.3.3: the largest image is 112 bytes (CMD, CTRL and 8 axis modules).
    EXPECT_NO_THROW(ProcessImage(ModuleLayout{true, 8}.Bytes()));
    EXPECT_THROW(ProcessImage(ModuleLayout{true, 8}.Bytes() + 1), std::invalid_argument);
    ProcessImage image(ModuleLayout{true, 0}.Bytes());
    EXPECT_THROW(image[16], std::out_of_range);
    EXPECT_THROW(image.Module8(12), std::out_of_range);
}

TEST(Link, CarriesTheWholeImageAsOneBlock) {
    Link link(LinkConfig{1ms, 0ns, 1}, 28);
    ProcessImage image(28);
    image[0] = 0x11;
    image[27] = 0x99;
    link.Write(0ms, image);
    EXPECT_TRUE(link.Read(0ms).AllZero());
    EXPECT_EQ(link.Read(1ms), image);
    EXPECT_THROW(link.Write(2ms, ProcessImage(8)), std::invalid_argument);
    link.SetFault(3ms, LinkFault::kAllZero);
    EXPECT_EQ(link.Read(3ms).Size(), 28u);
    EXPECT_TRUE(link.Read(3ms).AllZero());
}

}  // namespace
}  // namespace pac::sim
