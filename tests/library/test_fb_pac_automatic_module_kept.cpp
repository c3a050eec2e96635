// FB_PAC_AutomaticModule on its own, scan by scan: what its fields carry when an input does not fit them after
// the layout or the number format changed (Layout, IntegerMode = FB_PAC_Ctrl.IntegerModeActive, which follows a
// format change of the controller). The field keeps the last value that fitted, in the layout and format in
// force: never the other layout's value cut to 16 bits, never the other format's bits (manual 2.5.3: the same
// 32 bits are 640.0 as REAL and 1 142 947 840 / 1000 as DINT x 1000). One that the layout or format in force
// cannot carry either goes out as 0, with Error. The fuzz target found both (docs/testing.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/sim/automatic_module.hpp"
#include "pac/st_program.hpp"
#include "real_bits.hpp"

namespace test_fb_pac_automatic_module_kept {  // apart from the names of the other sources in its unity batch
namespace {

using pac::sim::AutomaticLayout;
using pac::sim::AutomaticModuleData;

const pac::test::GvlConstants kGvl;
const std::uint32_t kErrValueRange = kGvl["PAC_LIB_ERR_VALUE_RANGE"];
constexpr std::uint8_t kAutomaticRunning = 11;  // operating status: AUTOMATIC, program running (6.4)

class KeptFields : public ::testing::Test {
protected:
    KeptFields() { fb_->OPSTATUS.value = kAutomaticRunning; }

    // One scan with these inputs; the module as the simulated controller reads it in `layout`.
    AutomaticModuleData Scan(E_PAC_AUTOLAYOUT layout, bool integerMode, std::int32_t n, float r) {
        fb_->LAYOUT.value = layout;
        fb_->INTEGERMODE.value = integerMode ? TRUE : FALSE;
        fb_->INTREGISTER.value = n;
        fb_->REALREGISTER.value = r;
        fb_();
        pac::sim::Image12 module{};
        for (std::size_t i = 0; i < module.size(); ++i) module[i] = fb_->TOPAC.value.table[i];
        return AutomaticModuleData::Decode(module, layout == E_PAC_AUTOLAYOUT__PAC_AUTOLAYOUT_FW2_N4
                                                       ? AutomaticLayout::kShiftedWidths
                                                       : AutomaticLayout::kAxisWidths);
    }
    void ExpectRefused() {
        EXPECT_TRUE(fb_->ERROR.value);
        EXPECT_EQ(fb_->ERRORID.value, kErrValueRange);
    }

    pac::FbInstance<FB_PAC_AUTOMATICMODULE> fb_ = PAC_FB(FB_PAC_AUTOMATICMODULE);
};

constexpr auto kFw2N4 = E_PAC_AUTOLAYOUT__PAC_AUTOLAYOUT_FW2_N4;
constexpr auto kFw4N2 = E_PAC_AUTOLAYOUT__PAC_AUTOLAYOUT_FW4_N2;

TEST_F(KeptFields, AnNTheNewLayoutCannotCarryGoesOutAsZeroNotCut) {
    EXPECT_EQ(Scan(kFw2N4, false, 100000, 0.0f).intRegister, 100000);
    EXPECT_FALSE(fb_->ERROR.value);
    // 100000 is 16#186A0: cut to 16 bits it would be 16#86A0, -31072, a value nobody asked for.
    EXPECT_EQ(Scan(kFw4N2, false, 100000, 0.0f).intRegister, 0);
    ExpectRefused();
    EXPECT_EQ(Scan(kFw4N2, false, 1234, 0.0f).intRegister, 1234);
    EXPECT_FALSE(fb_->ERROR.value);
    // One the new layout can carry stays as it was.
    EXPECT_EQ(Scan(kFw4N2, false, 40000, 0.0f).intRegister, 1234);
    ExpectRefused();
}

TEST_F(KeptFields, AnRKeptAcrossAFormatChangeGoesOutInTheFormatInForce) {
    EXPECT_EQ(Scan(kFw2N4, false, 0, 640.0f).realBits, pac::test::BitsOf(640.0f));
    // Now DINT x 1000 with a value that cannot be sent: the kept 640.0 goes out as 640000, not as 16#44200000.
    EXPECT_EQ(static_cast<std::int32_t>(Scan(kFw2N4, true, 0, std::nanf("")).realBits), 640000);
    ExpectRefused();
    // And back: the REAL's own bits again.
    EXPECT_EQ(Scan(kFw2N4, false, 0, INFINITY).realBits, pac::test::BitsOf(640.0f));
    ExpectRefused();
}

TEST_F(KeptFields, AnRTheNewFormatCannotCarryGoesOutAsZero) {
    // 3.0e6 is a REAL, but 3.0e9 is beyond DINT: in the integer format it cannot be sent at all.
    EXPECT_EQ(Scan(kFw2N4, false, 0, 3.0e6f).realBits, pac::test::BitsOf(3.0e6f));
    EXPECT_EQ(Scan(kFw2N4, true, 0, 3.0e6f).realBits, 0U);
    ExpectRefused();
    // It is still the last value that fitted: the REAL format carries it again.
    EXPECT_EQ(Scan(kFw2N4, false, 0, std::nanf("")).realBits, pac::test::BitsOf(3.0e6f));
    ExpectRefused();
    EXPECT_EQ(Scan(kFw2N4, true, 0, 1.5f).realBits, 1500U);
    EXPECT_FALSE(fb_->ERROR.value);
}

}  // namespace
}  // namespace test_fb_pac_automatic_module_kept
