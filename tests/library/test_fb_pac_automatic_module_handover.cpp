// FB_PAC_AutomaticModule on its own, scan by scan: what it leaves on its module when AUTOMATIC ends (manual 2.6,
// 2.7.1: outside AUTOMATIC the same bytes are an axis control word). It clears its own image once, in the first
// scan whose status is neither AUTOMATIC nor 0; it leaves bytes another writer put there, and bytes an axis FB
// called before it wrote (AxisOwnsModule), even when they equal its own; status 0 (a lost link) ends nothing.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>

#include "pac/fb_instance.hpp"
#include "pac/sim/automatic_module.hpp"
#include "pac/st_program.hpp"

namespace test_fb_pac_automatic_module_handover {  // apart from the names of the other sources in its unity batch
namespace {

using pac::sim::Image12;

constexpr std::uint8_t kAutomaticRunning = 11;  // operating statuses (6.4)
constexpr std::uint8_t kHome = 1;
constexpr std::uint8_t kOnline = 31;
constexpr std::uint8_t kManual = 20;

class HandOver : public ::testing::Test {
protected:
    HandOver() {
        fb_->FLAGWORD.value = 0x0045;  // M1, M3, M7: Axis ON, Start, absolute traversing in bytes 2..3
        fb_->INTREGISTER.value = 500;
        fb_->REALREGISTER.value = 50.0f;
        fb_->LAYOUT.value = E_PAC_AUTOLAYOUT__PAC_AUTOLAYOUT_FW4_N2;
    }

    // One scan with `status`; the module as the FB left it.
    Image12 Scan(std::uint8_t status, bool axisOwnsModule = false) {
        fb_->OPSTATUS.value = status;
        fb_->AXISOWNSMODULE.value = axisOwnsModule ? TRUE : FALSE;
        fb_();
        return Module();
    }
    Image12 Module() {
        Image12 module{};
        for (std::size_t i = 0; i < module.size(); ++i) module[i] = fb_->TOPAC.value.table[i];
        return module;
    }
    void Put(const Image12& module) {
        for (std::size_t i = 0; i < module.size(); ++i) fb_->TOPAC.value.table[i] = module[i];
    }

    // The flags as the FB sends them on the layout printed in 2.6.1.
    const Image12 kFlags{0x00, 0x00, 0x00, 0x45, 0x00, 0x00, 0x01, 0xF4, 0x42, 0x48, 0x00, 0x00};
    pac::FbInstance<FB_PAC_AUTOMATICMODULE> fb_ = PAC_FB(FB_PAC_AUTOMATICMODULE);
};

TEST_F(HandOver, TheFirstStatusOutsideAutomaticClearsTheModuleOnce) {
    for (const std::uint8_t next : {kHome, kOnline, kManual}) {
        SCOPED_TRACE(static_cast<int>(next));
        ASSERT_EQ(Scan(kAutomaticRunning), kFlags);
        EXPECT_EQ(Scan(next), Image12{});
        EXPECT_FALSE(fb_->INEXCHANGE.value);
        // Cleared once: what another writer puts there later stays.
        const Image12 other{0, 0, 0, 0x01};
        Put(other);
        EXPECT_EQ(Scan(next), other);
    }
}

TEST_F(HandOver, ALostLinkEndsNothing) {
    ASSERT_EQ(Scan(kAutomaticRunning), kFlags);
    EXPECT_EQ(Scan(0), kFlags) << "status 0: AUTOMATIC may still run";
    EXPECT_EQ(Scan(0), kFlags);
    EXPECT_EQ(Scan(kHome), Image12{}) << "the first status known after it";
}

TEST_F(HandOver, AnAxisFbCalledBeforeItKeepsItsImage) {
    ASSERT_EQ(Scan(kAutomaticRunning), kFlags);
    // Bytes other than its own: an axis FB (or the program) wrote them in this scan.
    const Image12 axisImage{0, 0, 0, 0x03};
    Put(axisImage);
    EXPECT_EQ(Scan(kHome), axisImage);
    // Bytes equal to its own: only AxisOwnsModule tells them apart.
    ASSERT_EQ(Scan(kAutomaticRunning), kFlags);
    EXPECT_EQ(Scan(kHome, true), kFlags);
}

TEST_F(HandOver, NothingToClearWhenItNeverWrote) {
    const Image12 axisImage{0, 0, 0, 0x01};
    Put(axisImage);
    EXPECT_EQ(Scan(kHome), axisImage);
    EXPECT_EQ(Scan(kOnline), axisImage);
}

// Left out of the scans in which AUTOMATIC ends (docs/fb/FB_PAC_AutomaticModule.md, "The calling contract"): the
// module keeps the flags until the FB's next call, whatever statuses passed meanwhile; that call clears it if its
// status is outside AUTOMATIC (and not 0), writes the flags again if AUTOMATIC is back, and leaves an image an
// axis FB put there meanwhile.
TEST_F(HandOver, LeftOutWhenAutomaticEndsItClearsTheModuleInItsNextCall) {
    for (const std::uint8_t next : {kHome, kOnline}) {
        SCOPED_TRACE(static_cast<int>(next));
        ASSERT_EQ(Scan(kAutomaticRunning), kFlags);
        // Not called while the status goes 11, 0, `next`: nothing changes the module.
        EXPECT_EQ(Module(), kFlags);
        EXPECT_EQ(Scan(next), Image12{}) << "its next call";
        EXPECT_EQ(Scan(next), Image12{});
        ASSERT_EQ(Scan(kAutomaticRunning), kFlags);
        // AUTOMATIC ended and came back while it was not called: the flags again, nothing cleared.
        EXPECT_EQ(Scan(kAutomaticRunning), kFlags);
        // An axis FB took the module while it was not called.
        const Image12 axisImage{0, 0, 0, 0x03};
        Put(axisImage);
        EXPECT_EQ(Scan(next), axisImage);
        ASSERT_EQ(Scan(kAutomaticRunning), kFlags);
        EXPECT_EQ(Scan(next, true), kFlags) << "AxisOwnsModule: the axis FB's equal image";
        ASSERT_EQ(Scan(kAutomaticRunning), kFlags);
        EXPECT_EQ(Scan(0), kFlags) << "called again while the link is lost: AUTOMATIC may still run";
        EXPECT_EQ(Scan(next), Image12{});
    }
}

}  // namespace
}  // namespace test_fb_pac_automatic_module_handover
