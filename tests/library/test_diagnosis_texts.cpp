// The texts FB_PAC_Diagnosis shows: F_PAC_OpStatusText for every operating status of manual 6.4 (GVL_PAC's
// PAC_STATUS_ constants), F_PAC_AxisStatusText for each bit of the axis status word (2.7.4) and each code of
// cmd_get_status_axis 1910 (5.2.4.22).
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>

#include "gvl_constants.hpp"
#include "pac/st_program.hpp"

namespace test_diagnosis_texts {  // apart from the names of the other sources in its unity batch
namespace {

std::string Text(const STRING& s) { return std::string(reinterpret_cast<const char*>(s.body), s.len); }

std::string OpStatusText(std::uint32_t status) {
    BOOL eno = 0;
    return Text(F_PAC_OPSTATUSTEXT(1, &eno, static_cast<BYTE>(status)));
}

std::string AxisText(E_PAC_DIAGSOURCE source, std::uint32_t status) {
    BOOL eno = 0;
    return Text(F_PAC_AXISSTATUSTEXT(1, &eno, source, static_cast<DWORD>(status)));
}

constexpr E_PAC_DIAGSOURCE kModule = E_PAC_DIAGSOURCE__PAC_DIAGSRC_MODULE;
constexpr E_PAC_DIAGSOURCE kCommand = E_PAC_DIAGSOURCE__PAC_DIAGSRC_COMMAND;

TEST(DiagnosisTexts, EveryOperatingStatusOfTheManualHasItsOwnText) {
    const pac::test::GvlConstants gvl;
    std::set<std::string> seen;
    int statuses = 0;
    for (const auto& [name, value] : gvl.All()) {
        if (name.rfind("PAC_STATUS_", 0) != 0) continue;
        ++statuses;
        const std::string text = OpStatusText(value);
        EXPECT_NE(text, "unknown operating status") << name;
        EXPECT_LE(text.size(), 60u) << name;
        EXPECT_TRUE(seen.insert(text).second) << name << ": " << text << " twice";
    }
    EXPECT_EQ(statuses, 21);  // 0 of 2.4.2 and the twenty of 6.4
    EXPECT_EQ(OpStatusText(31), "ONLINE");
    EXPECT_EQ(OpStatusText(9), "home position with system error");
    for (std::uint32_t unknown : {4u, 14u, 21u, 33u, 40u, 255u}) {
        EXPECT_EQ(OpStatusText(unknown), "unknown operating status") << unknown;
    }
}

TEST(DiagnosisTexts, AxisModuleStatusNamesTheMostTellingState) {
    // One bit at a time (2.7.2): each state has a text of its own.
    std::set<std::string> seen;
    for (std::uint32_t bit : {0x1u, 0x2u, 0x4u, 0x8u, 0x10u, 0x20u, 0x40u, 0x80u, 0x1000u, 0x4000u, 0x8000u}) {
        const std::string text = AxisText(kModule, bit);
        EXPECT_LE(text.size(), 60u) << bit;
        EXPECT_TRUE(seen.insert(text).second) << "16#" << std::hex << bit << ": " << text << " twice";
    }
    EXPECT_EQ(AxisText(kModule, 0x101), "DRIVE ENABLED, referenced");
    EXPECT_EQ(AxisText(kModule, 0x1), "DRIVE ENABLED, not referenced");
    EXPECT_EQ(AxisText(kModule, 0x2000), AxisText(kModule, 0x1000));  // the group's displacement as the axis's
    EXPECT_EQ(AxisText(kModule, 0), "no drive state");
    // An error outranks a running job, a job the drive state.
    EXPECT_EQ(AxisText(kModule, 0x8000 | 0x40 | 0x80 | 0x1), AxisText(kModule, 0x8000));
    EXPECT_EQ(AxisText(kModule, 0x40 | 0x80 | 0x1), AxisText(kModule, 0x40));
    EXPECT_EQ(AxisText(kModule, 0x80 | 0x101), AxisText(kModule, 0x80));
    EXPECT_EQ(AxisText(E_PAC_DIAGSOURCE__PAC_DIAGSRC_NONE, 0x80), "");
}

TEST(DiagnosisTexts, Command1910CodesHaveTheManualsWords) {
    EXPECT_EQ(AxisText(kCommand, 0), "standing, in position");
    EXPECT_EQ(AxisText(kCommand, 1), "moving");
    EXPECT_EQ(AxisText(kCommand, 2), "standing still, was stopped");
    EXPECT_EQ(AxisText(kCommand, 4), "standing still with malfunction");
    EXPECT_EQ(AxisText(kCommand, 8), "in measuring mode");
    EXPECT_EQ(AxisText(kCommand, 4 | 1), "standing still with malfunction");
}

}  // namespace
}  // namespace test_diagnosis_texts
