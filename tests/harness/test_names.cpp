// pac_names: GvlTable finds a constant by name only under the prefix asked for and a name by value in
// declaration order; EnumNames maps each value name of the library's enumerations to the C enumerator
// spelt alike, which the scenario program relies on when it turns a name into a pin value.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pac/enum_names.hpp"
#include "pac/gvl_table.hpp"
#include "pac/st_program.hpp"

namespace {

const PACST_CONSTANT kList[] = {
    {"PAC_CMD_STOP", "WORD", 0x0600},
    {"PAC_STATUS_HOME_POSITION", "BYTE", 1},
    {"PAC_ERR_FIRST", "WORD", 1},
    {"PAC_ERR_SECOND", "WORD", 1},
};

TEST(GvlTable, FindsANameOnlyUnderItsPrefix) {
    const pac::GvlTable table(kList);
    EXPECT_EQ(table.Size(), 4u);
    EXPECT_EQ(table.Find("PAC_CMD_STOP"), 0x0600);
    EXPECT_EQ(table.Find("PAC_CMD_STOP", "PAC_CMD_"), 0x0600);
    EXPECT_EQ(table.Find("PAC_CMD_STOP", "PAC_ERR_"), std::nullopt);
    EXPECT_EQ(table.Find("PAC_CMD_STO"), std::nullopt);
    EXPECT_EQ(table.Find("PAC_CMD_STOP_AXIS", "PAC_CMD_"), std::nullopt);
}

TEST(GvlTable, NamesAValueByTheFirstNameUnderThePrefix) {
    const pac::GvlTable table(kList);
    EXPECT_EQ(table.NameOf(1, "PAC_ERR_"), "PAC_ERR_FIRST");
    EXPECT_EQ(table.NameOf(1, "PAC_STATUS_"), "PAC_STATUS_HOME_POSITION");
    EXPECT_EQ(table.NameOf(0x0600, "PAC_ERR_"), "");
    EXPECT_EQ(table.NameOf(2, ""), "");
}

TEST(GvlTable, GvlPacIsTheLibrarysList) {
    const pac::GvlTable gvl = pac::GvlTable::GvlPac();
    EXPECT_EQ(gvl.Size(), static_cast<std::size_t>(GVL_PAC_COUNT));
    EXPECT_EQ(gvl.Find("PAC_CMD_PUT_INT_REG", "PAC_CMD_"), 0x0906);
    EXPECT_EQ(gvl.NameOf(0x8001, "PAC_LIB_ERR_"), "PAC_LIB_ERR_ACK_TIMEOUT");
}

TEST(EnumNames, EachNameIsTheEnumeratorSpeltAlike) {
    const pac::EnumNames requests(E_PAC_CTRLREQUEST__NAMES);
    EXPECT_EQ(requests.Count(), static_cast<std::size_t>(E_PAC_CTRLREQUEST__COUNT));
    EXPECT_EQ(requests.Find<E_PAC_CTRLREQUEST>("PAC_REQ_NONE"), E_PAC_CTRLREQUEST__PAC_REQ_NONE);
    EXPECT_EQ(requests.Find<E_PAC_CTRLREQUEST>("PAC_REQ_CANCEL"), E_PAC_CTRLREQUEST__PAC_REQ_CANCEL);
    EXPECT_EQ(requests.Find<E_PAC_CTRLREQUEST>("PAC_REQ_RESET_ERROR"), E_PAC_CTRLREQUEST__PAC_REQ_RESET_ERROR);

    const pac::EnumNames commands(E_PAC_AXISCOMMAND__NAMES);
    EXPECT_EQ(commands.Find<E_PAC_AXISCOMMAND>("PAC_AX_HOME"), E_PAC_AXISCOMMAND__PAC_AX_HOME);
    EXPECT_EQ(commands.Find<E_PAC_AXISCOMMAND>("PAC_AX_SET_POSITION"), E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION);
    EXPECT_EQ(commands.Find<E_PAC_AXISCOMMAND>("PAC_AX_CLEAR_DISPLACED"), E_PAC_AXISCOMMAND__PAC_AX_CLEAR_DISPLACED);

    const pac::EnumNames conditions(E_PAC_MOVECONDITION__NAMES);
    EXPECT_EQ(conditions.Find<E_PAC_MOVECONDITION>("PAC_COND_WHILE_INPUT_0"), E_PAC_MOVECONDITION__PAC_COND_WHILE_INPUT_0);
}

TEST(EnumNames, RefusesWhatTheEnumerationLacks) {
    const pac::EnumNames commands(E_PAC_AXISCOMMAND__NAMES);
    EXPECT_EQ(commands.Find<E_PAC_AXISCOMMAND>("HOME"), std::nullopt);
    EXPECT_EQ(commands.Find<E_PAC_AXISCOMMAND>("PAC_REQ_NONE"), std::nullopt);
    EXPECT_FALSE(commands.Contains("PAC_AX_HOME "));
    EXPECT_TRUE(commands.Contains("PAC_AX_MOVE_TO_MIN"));
    const std::vector<std::string> all = commands.All();
    ASSERT_EQ(all.size(), static_cast<std::size_t>(E_PAC_AXISCOMMAND__COUNT));
    EXPECT_EQ(all.front(), "PAC_AX_NONE");
}

}  // namespace
