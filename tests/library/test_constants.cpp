// The constant list GVL_PAC (for CODESYS/TwinCAT users) and F_PAC_ErrorText agree with each other and
// with the manual as corrected in docs/manual_errata.md.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "gvl_constants.hpp"
#include "pac/st_program.hpp"

namespace test_constants {  // apart from the names of the other sources in its unity batch
namespace {

std::string ErrorText(std::uint32_t number, E_PAC_ERRORSOURCE source = E_PAC_ERRORSOURCE__PAC_ERRSRC_NONE) {
    BOOL eno = 0;
    STRING s = F_PAC_ERRORTEXT(1, &eno, static_cast<WORD>(number), source);
    return std::string(reinterpret_cast<const char*>(s.body), s.len);
}

const pac::test::GvlConstants& Gvl() {
    static const pac::test::GvlConstants gvl;
    return gvl;
}

// The command error numbers of manual 6.5, read as docs/manual_errata.md corrects the table: 0x25 is 37, the second
// 0x1D is 0x1E (30), the second 0x2D is 0x2E (46), 0x2F is 47, and 0x31 is listed once.
std::vector<std::uint32_t> ManualErrorNumbers() {
    std::vector<std::uint32_t> numbers = {16, 17, 18, 19, 20, 21, 26, 27, 28, 29, 30, 31};
    for (std::uint32_t n = 32; n <= 59; ++n) numbers.push_back(n);  // 20..3B hex
    for (std::uint32_t n : {64u, 65u, 80u, 81u, 82u, 83u}) numbers.push_back(n);
    for (std::uint32_t n = 96; n <= 109; ++n) numbers.push_back(n);   // 60..6D hex
    for (std::uint32_t n = 250; n <= 262; ++n) numbers.push_back(n);  // FA..106 hex
    return numbers;
}

// The library's own codes, one per line of the FBs' error tables (docs/fb/*.md): 16#8001..16#8017, and from
// 16#8020 those of the modules and operating modes, from 16#8030 those of the MC_ blocks.
std::vector<std::uint32_t> LibraryErrorCodes() {
    std::vector<std::uint32_t> codes;
    for (std::uint32_t code = 0x8001; code <= 0x8017; ++code) codes.push_back(code);
    for (std::uint32_t code = 0x8020; code <= 0x8025; ++code) codes.push_back(code);
    for (std::uint32_t code = 0x8030; code <= 0x8039; ++code) codes.push_back(code);  // the MC_ blocks
    return codes;
}

std::map<std::uint32_t, std::vector<std::string>> ConstantsByValue(const std::string& prefix) {
    std::map<std::uint32_t, std::vector<std::string>> byValue;
    for (const auto& [name, value] : Gvl().All()) {
        if (name.rfind(prefix, 0) == 0) byValue[value].push_back(name);
    }
    return byValue;
}

// Every command code of chapter 5: the overview 5.1 checked against each description's header in 5.2, with
// the errata in docs/manual_errata.md (190E, not the overview's second 190D; 1934 / 1935 / 1937, not 934 / 935 / 0937).
std::vector<std::uint32_t> ManualCommandCodes() {
    return {0x0600, 0x0602, 0x0603,                                  // 5.2.1
            0x0700, 0x1700, 0x1701, 0x1702,                          // 5.2.2
            0x0800, 0x1800, 0x1801, 0x1802,                          // 5.2.3
            0x1900, 0x1901, 0x0902, 0x1902, 0x0903, 0x1903, 0x0904,  // 5.2.4
            0x1904, 0x0905, 0x1905, 0x0906, 0x1906, 0x0907, 0x1907, 0x0909, 0x1909, 0x190B, 0x190C,
            0x190D, 0x190E, 0x190F, 0x1910, 0x1911, 0x1913, 0x1914, 0x1915, 0x1920, 0x1921, 0x1934,
            0x1935, 0x1937,
            0x0A41,                                                  // 5.2.5
            0x0A81, 0x0A83, 0x0A84, 0x0A85, 0x0A86, 0x0A87, 0x0A89,  // 5.2.6
            0x0A8D, 0x0A8E, 0x0A90, 0x0A91, 0x0A92, 0x0A93, 0x0A94, 0x0A95, 0x0A96, 0x0A97, 0x0A98,
            0x0A9A, 0x0AA0, 0x0AA1, 0x0AA2, 0x0AA3};
}

TEST(GvlPac, EveryCommandOfChapter5HasOneNameAndNoNameIsOutsideIt) {
    const auto byValue = ConstantsByValue("PAC_CMD_");
    const std::vector<std::uint32_t> manual = ManualCommandCodes();
    for (std::uint32_t code : manual) {
        const auto it = byValue.find(code);
        ASSERT_NE(it, byValue.end()) << "no PAC_CMD_ constant for command 16#" << std::hex << code;
        EXPECT_EQ(it->second.size(), 1u) << "16#" << std::hex << code << " has several constants";
    }
    EXPECT_EQ(byValue.size(), manual.size()) << "a PAC_CMD_ constant that is no command of chapter 5";
}

TEST(GvlPac, EveryNumberOfTheManualsErrorTableHasOneConstant) {
    const auto byValue = ConstantsByValue("PAC_ERR_");
    for (std::uint32_t number : ManualErrorNumbers()) {
        const auto it = byValue.find(number);
        ASSERT_NE(it, byValue.end()) << "no PAC_ERR_ constant for error " << number << " of manual 6.5";
        EXPECT_EQ(it->second.size(), 1u) << "error " << number << " has several constants";
    }
}

TEST(GvlPac, EveryPacErrorConstantIsANumberOfTheManual) {
    const std::vector<std::uint32_t> manual = ManualErrorNumbers();
    std::set<std::uint32_t> known(manual.begin(), manual.end());
    known.insert(0);  // PAC_ERR_NONE: "no error", the table's first line
    for (const auto& [value, names] : ConstantsByValue("PAC_ERR_")) {
        EXPECT_EQ(known.count(value), 1u) << names.front() << " = " << value << " is not in manual 6.5";
    }
    EXPECT_EQ(Gvl()["PAC_ERR_NONE"], 0u);
}

TEST(GvlPac, EveryLibraryErrorCodeHasOneConstant) {
    const auto byValue = ConstantsByValue("PAC_LIB_ERR_");
    for (std::uint32_t code : LibraryErrorCodes()) {
        const auto it = byValue.find(code);
        ASSERT_NE(it, byValue.end()) << "no PAC_LIB_ERR_ constant for 16#" << std::hex << code;
        EXPECT_EQ(it->second.size(), 1u) << "16#" << std::hex << code << " has several constants";
    }
    EXPECT_EQ(byValue.size(), LibraryErrorCodes().size()) << "a library code outside the table";
}

TEST(GvlPac, EveryErrorNumberHasItsOwnText) {
    std::map<std::string, std::string> seen;
    for (const auto& [name, value] : Gvl().All()) {
        if (name.rfind("PAC_ERR_", 0) != 0 && name.rfind("PAC_LIB_ERR_", 0) != 0) continue;
        std::string text = ErrorText(value);
        EXPECT_NE(text, "unknown error number") << name;
        EXPECT_LE(text.size(), 80u) << name;
        EXPECT_TRUE(seen.emplace(text, name).second) << name << " has the same text as " << seen[text];
    }
}

TEST(GvlPac, NumbersOutsideTheTableAreUnknown) {
    for (std::uint32_t n : {1u, 15u, 22u, 25u, 60u, 63u, 66u, 84u, 110u, 249u, 263u, 0x1FFFu, 0x8000u, 0x8019u,
                            0x801Fu, 0x8026u, 0x802Fu, 0x803Au}) {
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
    EXPECT_EQ(Gvl()["PAC_STATUS_ONLINE"], 31u);  // decimal, 16#1F (docs/manual_errata.md)
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

// A system error number (FB_PAC_Ctrl's ErrorID with ErrorSource SYSTEM) is no command error of 6.5: its
// text names the class of 5.2.4.15 (1..99 CPU, 100..499 hardware, 500..999 ONLINE/AUTOMATIC) or the two
// numbers the manual names (E525 in 2.7.2, E560 in 5.2.6.21), never the 6.5 text of the same number.
TEST(ErrorText, SystemErrorNumbersGetTheirClassNotTheCommandErrorText) {
    constexpr auto kSystem = E_PAC_ERRORSOURCE__PAC_ERRSRC_SYSTEM;
    EXPECT_EQ(ErrorText(43), "no reference point");  // command error 43 (6.5)
    EXPECT_NE(ErrorText(43, kSystem), ErrorText(43));
    EXPECT_NE(ErrorText(43, kSystem).find("class 1 (CPU)"), std::string::npos);
    EXPECT_NE(ErrorText(99, kSystem).find("class 1"), std::string::npos);
    EXPECT_NE(ErrorText(100, kSystem).find("class 2 (hardware)"), std::string::npos);
    EXPECT_NE(ErrorText(499, kSystem).find("class 2"), std::string::npos);
    EXPECT_NE(ErrorText(500, kSystem).find("class 3"), std::string::npos);
    EXPECT_NE(ErrorText(999, kSystem).find("class 3"), std::string::npos);
    EXPECT_EQ(ErrorText(525, kSystem), "system error E525: no reference point");
    EXPECT_NE(ErrorText(560, kSystem).find("E560"), std::string::npos);
    EXPECT_EQ(ErrorText(1000, kSystem), "unknown error number");
    EXPECT_EQ(ErrorText(0, kSystem), "no error");
    // Library codes keep their texts whatever the source says.
    EXPECT_EQ(ErrorText(Gvl()["PAC_LIB_ERR_ACK_TIMEOUT"], kSystem), ErrorText(Gvl()["PAC_LIB_ERR_ACK_TIMEOUT"]));
    for (std::uint32_t n : {1u, 150u, 525u, 999u}) EXPECT_LE(ErrorText(n, kSystem).size(), 80u) << n;
}

TEST(ErrorSource, NoneWithoutErrorLibraryFrom16x8000OtherwiseWhatTheFbReports) {
    BOOL eno = 0;
    constexpr auto kCommand = E_PAC_ERRORSOURCE__PAC_ERRSRC_COMMAND;
    constexpr auto kSystem = E_PAC_ERRORSOURCE__PAC_ERRSRC_SYSTEM;
    EXPECT_EQ(F_PAC_ERRORSOURCE(1, &eno, 0, 0, kSystem), E_PAC_ERRORSOURCE__PAC_ERRSRC_NONE);
    EXPECT_EQ(F_PAC_ERRORSOURCE(1, &eno, 1, 0x8001, kSystem), E_PAC_ERRORSOURCE__PAC_ERRSRC_LIBRARY);
    EXPECT_EQ(F_PAC_ERRORSOURCE(1, &eno, 1, 0x7FFF, kSystem), kSystem);
    EXPECT_EQ(F_PAC_ERRORSOURCE(1, &eno, 1, 43, kCommand), kCommand);
}

}  // namespace
}  // namespace test_constants
