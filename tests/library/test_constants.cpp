// The constant list GVL_PAC (for CODESYS/TwinCAT users) and F_PAC_ErrorText agree with each other and
// with the manual as corrected by NOTES.md.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "gvl_constants.hpp"
#include "pac/st_program.hpp"

namespace {

std::string ErrorText(std::uint32_t number) {
    BOOL eno = 0;
    STRING s = F_PAC_ERRORTEXT(1, &eno, static_cast<WORD>(number));
    return std::string(reinterpret_cast<const char*>(s.body), s.len);
}

const pac::test::GvlConstants& Gvl() {
    static const pac::test::GvlConstants gvl;
    return gvl;
}

TEST(GvlPac, EveryErrorNumberHasItsOwnText) {
    std::map<std::string, std::string> seen;
    int errors = 0;
    for (const auto& [name, value] : Gvl().All()) {
        if (name.rfind("PAC_ERR_", 0) != 0 && name.rfind("PAC_LIB_ERR_", 0) != 0) continue;
        ++errors;
        std::string text = ErrorText(value);
        EXPECT_NE(text, "unknown error number") << name;
        EXPECT_LE(text.size(), 80u) << name;
        EXPECT_TRUE(seen.emplace(text, name).second) << name << " has the same text as " << seen[text];
    }
    EXPECT_EQ(errors, 88);
}

TEST(GvlPac, NumbersOutsideTheTableAreUnknown) {
    for (std::uint32_t n : {1u, 15u, 22u, 25u, 60u, 63u, 66u, 84u, 110u, 249u, 263u, 0x1FFFu, 0x8000u, 0x800Fu}) {
        EXPECT_EQ(ErrorText(n), "unknown error number") << n;
    }
}

TEST(GvlPac, ErrorTableErrataOfNotesAreApplied) {
    EXPECT_EQ(Gvl()["PAC_ERR_FLAG"], 37u);
    EXPECT_EQ(Gvl()["PAC_ERR_OUTPUT"], 36u);
    EXPECT_EQ(Gvl()["PAC_ERR_EPROM_DELETE"], 30u);
    EXPECT_EQ(Gvl()["PAC_ERR_AXIS_NOT_READY"], 46u);
    EXPECT_EQ(Gvl()["PAC_ERR_NOT_SERVOTEC"], 47u);
    EXPECT_EQ(Gvl()["PAC_ERR_NO_REFERENCE"], 43u);
    EXPECT_EQ(ErrorText(43), "no reference point");
    EXPECT_EQ(ErrorText(37), "inadmissible flag");
}

TEST(GvlPac, CommandCodesAndStatusesFollowTheNotes) {
    EXPECT_EQ(Gvl()["PAC_CMD_GET_ROTATION_CONTROL_POS"], 0x190Eu);
    EXPECT_EQ(Gvl()["PAC_CMD_GET_ACTUAL_SPEED"], 0x190Du);
    EXPECT_EQ(Gvl()["PAC_CMD_SEND_SYSTEM_FLAG"], 0x1934u);
    EXPECT_EQ(Gvl()["PAC_CMD_SEND_SYSTEM_N_REG"], 0x1935u);
    EXPECT_EQ(Gvl()["PAC_CMD_SEND_SYSTEM_R_REG"], 0x1937u);
    EXPECT_EQ(Gvl()["PAC_STATUS_ONLINE"], 31u);  // decimal, 16#1F (NOTES.md)
    EXPECT_EQ(Gvl()["PAC_STATUS_HOME_POSITION"], 1u);
}

TEST(GvlPac, LibraryCodesLieAboveEveryPacNumber) {
    for (const auto& [name, value] : Gvl().All()) {
        if (name.rfind("PAC_LIB_ERR_", 0) == 0) {
            EXPECT_GE(value, 0x8000u) << name;
        }
        if (name.rfind("PAC_ERR_", 0) == 0) {
            EXPECT_LE(value, 0x1FFFu) << name;
        }
    }
}

}  // namespace
