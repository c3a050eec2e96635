// User programs (`pacst --user`): the plant of user/ (PROGRAMs over two global lists, located and
// inline-array variables, VAR_EXTERNAL, STRINGs) run scan by scan as a host runs it, the standard string
// functions, the ST file and line a native assert is given, and symbols.json against the C it describes.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "POUS.h"

namespace {

struct AssertCall {
    std::string function;
    std::string file;
    int line = 0;
    bool passed = false;
    std::string message;
};

std::vector<AssertCall> g_calls;  // the native asserts' record; cleared by every test's SetUp

std::string Text(const STRING& s) { return std::string(reinterpret_cast<const char*>(s.body), s.len); }

void Record(const char* function, const char* file, int line, bool passed, const STRING& message) {
    g_calls.push_back({function, file, line, passed, Text(message)});
}

}  // namespace

// The native FUNCTIONs of user/native/TestAsserts.st: pacst passes each call's position first.
extern "C" {
void ASSERTEQUALS_INT(const char* file, int line, BOOL, BOOL*, INT expected, INT actual, STRING message) {
    Record("AssertEquals_INT", file, line, expected == actual, message);
}
void ASSERTEQUALS_STRING(const char* file, int line, BOOL, BOOL*, STRING expected, STRING actual, STRING message) {
    Record("AssertEquals_STRING", file, line, Text(expected) == Text(actual), message);
}
BOOL ASSERTTRUE(const char* file, int line, BOOL, BOOL*, BOOL condition, STRING message) {
    Record("AssertTrue", file, line, condition != 0, message);
    return condition;
}
}

namespace {

class UserProgram : public ::testing::Test {
protected:
    void SetUp() override {
        g_calls.clear();
        GVL_PLANT__init__();
        GVL_HMI__init__();
    }
};

TEST_F(UserProgram, GlobalsStartFromTheirInitialValues) {
    EXPECT_EQ(GVL_PLANT__SETPOINT.value, 1000);
    EXPECT_EQ(Text(GVL_PLANT__BANNER.value), "ready");
    EXPECT_EQ(GVL_PLANT__MODE.value, E_USERMODE__UM_IDLE);
    EXPECT_EQ(GVL_PLANT__RECIPE.value.SPEED, 50);  // the STRUCT's member default
    EXPECT_EQ(Text(GVL_PLANT__RECIPE.value.TAGS.table[1]), "");
    EXPECT_EQ(GVL_HMI__CYCLES.value, -1);
    EXPECT_EQ(GVL_PLANT__MAX_CYCLES.value, 3u);
    EXPECT_EQ(Text(GVL_PLANT__GREETING.value), "hello");
    for (int i = 0; i < 8; ++i) EXPECT_EQ(GVL_PLANT__CMDIN.value.table[i], 0) << i;
}

TEST_F(UserProgram, StepChainRunsOverTheGlobalsScanByScan) {
    PRG_USERMAIN prg{};  // zero-filled, flags included, as the runtime creates every instance
    PRG_USERMAIN_init__(&prg, FALSE);
    EXPECT_TRUE(prg.ENABLE.value);  // VAR_INPUT's initial value
    // The host copies the input image in before each scan.
    GVL_PLANT__CMDIN.value.table[0] = 0x05;
    GVL_PLANT__CMDIN.value.table[7] = 0x42;
    GVL_PLANT__PRESSURE.value = 7;
    PRG_USERMAIN_body__(&prg);
    EXPECT_EQ(prg.STEPNO.value, 0) << "no start edge yet";
    GVL_HMI__START.value = TRUE;
    PRG_USERMAIN_body__(&prg);
    EXPECT_EQ(prg.STEPNO.value, 1);
    EXPECT_EQ(GVL_PLANT__MODE.value, E_USERMODE__UM_RUN);
    for (unsigned count = 1; count <= 3; ++count) {
        PRG_USERMAIN_body__(&prg);
        EXPECT_EQ(GVL_PLANT__CYCLES.value, count);
        EXPECT_EQ(prg.LAMP.COUNT.value, count);
        EXPECT_EQ(prg.TOTALS.value.table[count - 1], 7 * 1000) << "Totals[" << count << "] (1-based)";
        EXPECT_EQ(prg.SCRATCH.value, count) << "the PROGRAM's located %MB4";
    }
    EXPECT_EQ(GVL_PLANT__CMDOUT.value.table[0], 0x85);
    EXPECT_EQ(GVL_PLANT__CMDOUT.value.table[7], 0x42);
    EXPECT_EQ(prg.STEPNO.value, 2);
    EXPECT_EQ(GVL_PLANT__MODE.value, E_USERMODE__UM_DONE);
    EXPECT_FALSE(GVL_PLANT__LAMPOUT.value) << "switched off through VAR_EXTERNAL in the last step";
    EXPECT_EQ(Text(GVL_PLANT__BANNER.value), "hello world,") << "a STRING(12) keeps its first 12 characters";
    PRG_USERMAIN_body__(&prg);
    EXPECT_EQ(GVL_HMI__CYCLES.value, 0) << "GVL_Hmi.Cycles, not GVL_Plant.Cycles";
    EXPECT_EQ(GVL_PLANT__CYCLES.value, 3u);
}

TEST_F(UserProgram, StandardStringFunctions) {
    PRG_USERSTRINGS prg{};
    PRG_USERSTRINGS_init__(&prg, FALSE);
    PRG_USERSTRINGS_body__(&prg);
    EXPECT_EQ(prg.LENGTH.value, 14);
    EXPECT_EQ(Text(prg.JOINED.value), "pick\tand place!");
    EXPECT_EQ(Text(prg.JOINED3.value), "abc");
    EXPECT_EQ(Text(prg.LEFT3.value), "pic");
    EXPECT_EQ(Text(prg.RIGHT2.value), "ce");
    EXPECT_EQ(Text(prg.MIDDLE.value), "and") << "MID(IN, L := 3, P := 6): positions count from 1";
    EXPECT_EQ(Text(prg.MIDOUTSIDE.value), "");
    EXPECT_EQ(prg.FOUND.value, 10);
    EXPECT_EQ(prg.NOTFOUND.value, 0);
    EXPECT_EQ(Text(prg.INSERTED.value), "pickX\tand place");
    EXPECT_EQ(Text(prg.DELETED.value), "pick place");
    EXPECT_EQ(Text(prg.REPLACED.value), "pick\tand drop");
    EXPECT_EQ(Text(prg.CUT.value), "pick");
    EXPECT_TRUE(prg.SAME.value);
    EXPECT_TRUE(prg.DIFFERS.value);
    EXPECT_EQ(Text(prg.PIN.value), "pic") << "an FB's STRING(3) input keeps 3 characters";
    EXPECT_EQ(Text(prg.OUT2.value), "pi") << "an output assigned with => to a STRING(2) keeps 2";
}

// The line of the first occurrence of `marker` in the ST file `name` of user/ (1-based).
int StLine(const std::string& name, const std::string& marker) {
    std::ifstream in(std::string(PAC_USER_ST_DIR) + "/" + name);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (line.find(marker) != std::string::npos) return number;
    }
    ADD_FAILURE() << marker << " not in " << name;
    return -1;
}

bool EndsWith(const std::string& text, const std::string& tail) {
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

TEST_F(UserProgram, NativeAssertIsGivenTheStFileAndLineOfItsCall) {
#ifndef PAC_USER_LINE_DIRECTIVES
    GTEST_SKIP() << "built without #line directives (PAC_ST_LINE_DIRECTIVES=OFF): calls name the C file";
#endif
    PRG_USERASSERTS prg{};
    PRG_USERASSERTS_init__(&prg, FALSE);
    for (int scan = 0; scan < 3; ++scan) PRG_USERASSERTS_body__(&prg);
    const int equalsInt = StLine("PRG_UserAsserts.st", "AssertEquals_INT(");
    const int equalsString = StLine("PRG_UserAsserts.st", "AssertEquals_STRING(");
    const int isTrue = StLine("PRG_UserAsserts.st", "AssertTrue(");
    struct Want {
        const char* function;
        int line;
        bool passed;
        const char* message;
    };
    const std::vector<Want> want = {
        {"AssertEquals_INT", equalsInt, true, "first scan"},
        {"AssertTrue", isTrue, true, "at most two scans"},
        {"AssertEquals_INT", equalsInt, false, "first scan"},
        {"AssertEquals_STRING", equalsString, true, "banner after scan two"},
        {"AssertTrue", isTrue, true, "at most two scans"},
        {"AssertEquals_INT", equalsInt, false, "first scan"},
        {"AssertEquals_STRING", equalsString, true, "banner after scan two"},
        {"AssertTrue", isTrue, false, "at most two scans"},
    };
    ASSERT_EQ(g_calls.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) {
        SCOPED_TRACE("call " + std::to_string(i));
        EXPECT_EQ(g_calls[i].function, want[i].function);
        EXPECT_TRUE(EndsWith(g_calls[i].file, "/user/PRG_UserAsserts.st")) << g_calls[i].file;
        EXPECT_EQ(g_calls[i].line, want[i].line);
        EXPECT_EQ(g_calls[i].passed, want[i].passed);
        EXPECT_EQ(g_calls[i].message, want[i].message);
    }
}

nlohmann::json Symbols() {
    std::ifstream in(PAC_USER_SYMBOLS);
    EXPECT_TRUE(in.good()) << PAC_USER_SYMBOLS;
    return nlohmann::json::parse(in);
}

const nlohmann::json& ByKey(const nlohmann::json& list, const char* key, const std::string& value) {
    for (const auto& entry : list) {
        if (entry.at(key) == value) return entry;
    }
    static const nlohmann::json none;
    ADD_FAILURE() << "no entry with " << key << " = " << value;
    return none;
}

struct CGlobal {
    const void* address;
    size_t size;
};

TEST_F(UserProgram, SymbolTableNamesEveryGlobalWithItsCVariableTypeAndAddress) {
    // Every global of the two lists, as the C code has it: the table must list exactly these.
#define PAC_GLOBAL(sym) {#sym, {&sym, sizeof(sym.value)}}
    const std::map<std::string, CGlobal> c = {
        PAC_GLOBAL(GVL_PLANT__CMDIN),   PAC_GLOBAL(GVL_PLANT__CMDOUT),    PAC_GLOBAL(GVL_PLANT__STARTBUTTON),
        PAC_GLOBAL(GVL_PLANT__LAMPOUT), PAC_GLOBAL(GVL_PLANT__PRESSURE),  PAC_GLOBAL(GVL_PLANT__SETPOINT),
        PAC_GLOBAL(GVL_PLANT__MODE),    PAC_GLOBAL(GVL_PLANT__RECIPE),    PAC_GLOBAL(GVL_PLANT__BANNER),
        PAC_GLOBAL(GVL_PLANT__CYCLES),  PAC_GLOBAL(GVL_PLANT__MAX_CYCLES), PAC_GLOBAL(GVL_PLANT__GREETING),
        PAC_GLOBAL(GVL_HMI__START),     PAC_GLOBAL(GVL_HMI__CYCLES),
    };
#undef PAC_GLOBAL
    const auto symbols = Symbols();
    EXPECT_EQ(symbols.at("format"), 1);
    std::map<std::string, std::string> listed;  // c_name -> path
    for (const auto& g : symbols.at("globals")) listed[g.at("c_name")] = g.at("path");
    ASSERT_EQ(listed.size(), c.size());
    for (const auto& [name, global] : c) EXPECT_EQ(listed.count(name), 1u) << name;
    for (const auto& g : symbols.at("globals")) {
        const auto& type = g.at("type");
        if (type.at("kind") == "elementary") {
            EXPECT_EQ(type.at("size").get<size_t>(), c.at(g.at("c_name")).size) << g.at("path");
        }
    }

    const auto& cmdIn = ByKey(symbols.at("globals"), "path", "GVL_Plant.CmdIn");
    EXPECT_EQ(cmdIn.at("c_name"), "GVL_PLANT__CMDIN");
    EXPECT_EQ(cmdIn.at("list"), "GVL_Plant");
    EXPECT_EQ(cmdIn.at("location").at("address"), "%IB0");
    EXPECT_EQ(cmdIn.at("location").at("area"), "I");
    EXPECT_EQ(cmdIn.at("location").at("size"), "B");
    EXPECT_EQ(cmdIn.at("type").at("kind"), "array");
    EXPECT_EQ(cmdIn.at("type").at("low"), 0);
    EXPECT_EQ(cmdIn.at("type").at("high"), 7);
    EXPECT_EQ(cmdIn.at("type").at("element").at("name"), "BYTE");
    EXPECT_EQ(cmdIn.at("type").at("element_size").get<size_t>(), sizeof(GVL_PLANT__CMDIN.value.table[0]));
    EXPECT_EQ(cmdIn.at("type").at("c_type"), "__ARRAY_OF_BYTE_8");
    const auto& start = ByKey(symbols.at("globals"), "path", "GVL_Plant.StartButton");
    EXPECT_EQ(start.at("location").at("numbers"), nlohmann::json({8, 2}));
    const auto& setpoint = ByKey(symbols.at("globals"), "path", "GVL_Plant.Setpoint");
    EXPECT_EQ(setpoint.at("initial"), "1000");
    EXPECT_EQ(setpoint.at("location").at("bits"), 32);
    const auto& banner = ByKey(symbols.at("globals"), "path", "GVL_Plant.Banner");
    EXPECT_EQ(banner.at("string_length"), 12);
    EXPECT_TRUE(ByKey(symbols.at("globals"), "path", "GVL_Plant.MAX_CYCLES").at("constant").get<bool>());
    const auto& lists = symbols.at("global_lists");
    EXPECT_EQ(ByKey(lists, "name", "GVL_Plant").at("init"), "GVL_PLANT__init__");
}

TEST_F(UserProgram, SymbolTableDescribesProgramsFunctionBlocksAndTypes) {
    const auto symbols = Symbols();
    const auto& main = ByKey(symbols.at("programs"), "name", "PRG_UserMain");
    EXPECT_EQ(main.at("c_type"), "PRG_USERMAIN");
    EXPECT_EQ(main.at("init"), "PRG_USERMAIN_init__");
    EXPECT_EQ(main.at("body"), "PRG_USERMAIN_body__");
    const auto& step = ByKey(main.at("variables"), "path", "PRG_UserMain.StepNo");
    EXPECT_EQ(step.at("c_name"), "STEPNO");
    EXPECT_EQ(step.at("direction"), "output");
    EXPECT_EQ(ByKey(main.at("variables"), "name", "Enable").at("initial"), "TRUE");
    EXPECT_EQ(ByKey(main.at("variables"), "name", "Scratch").at("location").at("address"), "%MB4");
    const auto& totals = ByKey(main.at("variables"), "name", "Totals");
    EXPECT_EQ(totals.at("type").at("low"), 1);
    EXPECT_EQ(ByKey(main.at("variables"), "name", "Lamp").at("type").at("name"), "FB_UserLamp");
    EXPECT_EQ(ByKey(main.at("variables"), "name", "Scaled").at("direction"), "temp");

    const auto& lamp = ByKey(symbols.at("function_blocks"), "name", "FB_UserLamp");
    EXPECT_EQ(lamp.at("c_type"), "FB_USERLAMP");
    EXPECT_EQ(ByKey(lamp.at("variables"), "name", "Enable").at("direction"), "input");
    EXPECT_EQ(ByKey(lamp.at("variables"), "name", "Count").at("direction"), "output");
    EXPECT_EQ(ByKey(lamp.at("externals"), "name", "LampOut").at("global"), "GVL_Plant.LampOut");
    const auto& feedback = ByKey(lamp.at("variables"), "name", "Feedback").at("location");
    EXPECT_EQ(feedback.at("address"), "%I*");
    EXPECT_EQ(feedback.at("area"), "I");
    EXPECT_TRUE(feedback.at("numbers").empty());
    EXPECT_EQ(ByKey(symbols.at("function_blocks"), "name", "TON").at("standard"), true);

    const auto& assertInt = ByKey(symbols.at("functions"), "name", "AssertEquals_INT");
    EXPECT_TRUE(assertInt.at("native").get<bool>());
    EXPECT_TRUE(assertInt.at("returns").is_null());
    EXPECT_FALSE(ByKey(symbols.at("functions"), "name", "F_UserScale").at("native").get<bool>());

    const auto& mode = ByKey(symbols.at("types"), "name", "E_UserMode");
    EXPECT_EQ(mode.at("values").at(2).at("name"), "UM_DONE");
    EXPECT_EQ(mode.at("values").at(2).at("value"), E_USERMODE__UM_DONE);
    const auto& recipe = ByKey(symbols.at("types"), "name", "ST_UserRecipe");
    EXPECT_EQ(ByKey(recipe.at("members"), "name", "Speed").at("c_name"), "SPEED");
}

}  // namespace
