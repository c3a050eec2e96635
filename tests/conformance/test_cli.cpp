// The translator's command line: refusals name file:line:col and leave nothing generated behind;
// builds rewrite only the files whose text changed; check mode writes nothing; order prints the declaration
// order.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "translator_runner.hpp"
#include "translator_scratch.hpp"

namespace {

namespace fs = std::filesystem;
using pac::test::RunTranslator;

class TranslatorCli : public pac::test::TranslatorScratch {};

const char* kTypes =
    "TYPE T_Pair : ARRAY[0..1] OF INT;\nEND_TYPE\n";
const char* kCounter =
    "FUNCTION_BLOCK FB_Counter\n"
    "VAR_OUTPUT Count : INT; END_VAR\n"
    "Count := Count + 1;\n"
    "END_FUNCTION_BLOCK\n";

TEST_F(TranslatorCli, BrokenFileNamesFileLineColumnAndLeavesNoOutput) {
    auto good = Write("FB_Counter.st", kCounter);
    ASSERT_EQ(RunTranslator({"build", "--out", Out(), good}).exitCode, 0);
    ASSERT_TRUE(Generated("POUS.h"));
    auto broken = Write("FB_Counter.st",
                        "FUNCTION_BLOCK FB_Counter\n"
                        "VAR_OUTPUT Count : INT; Wide : DINT; END_VAR\n"
                        "Wide := Count;\n"
                        "END_FUNCTION_BLOCK\n");
    auto result = RunTranslator({"build", "--out", Out(), "--stamp", Out() + "/pacst.stamp", broken});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(broken + ":3:9: error: type mismatch: INT where DINT is expected"),
              std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("INT_TO_DINT"), std::string::npos) << result.output;
    EXPECT_FALSE(Generated("POUS.h"));
    EXPECT_FALSE(Generated("FB_Counter.c"));
    EXPECT_FALSE(Generated("pacst.stamp"));
}

TEST_F(TranslatorCli, SyntaxErrorNamesItsPosition) {
    auto broken = Write("FB_Bad.st",
                        "FUNCTION_BLOCK FB_Bad\n"
                        "VAR Count : INT; END_VAR\n"
                        "Count := Count + ;\n"
                        "END_FUNCTION_BLOCK\n");
    auto result = RunTranslator({"build", "--out", Out(), broken});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(broken + ":3:18: error: syntax error"), std::string::npos) << result.output;
}

TEST_F(TranslatorCli, ReportsErrorsOfEveryPou) {
    auto broken = Write("Two.st",
                        "FUNCTION_BLOCK FB_One\nVAR a : INT; END_VAR\na := TRUE;\nEND_FUNCTION_BLOCK\n"
                        "FUNCTION_BLOCK FB_Two\nVAR b : BOOL; END_VAR\nb := 1;\nEND_FUNCTION_BLOCK\n");
    auto result = RunTranslator({"check", broken});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(broken + ":3:6: error:"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(broken + ":7:6: error:"), std::string::npos) << result.output;
}

TEST_F(TranslatorCli, CheckModeWritesNothing) {
    auto good = Write("FB_Counter.st", kCounter);
    auto result = RunTranslator({"check", good});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(result.output.empty()) << result.output;
    EXPECT_TRUE(fs::is_empty(dir_ / "out"));
}

TEST_F(TranslatorCli, RebuildRewritesOnlyWhatChanged) {
    auto types = Write("T_Pair.st", kTypes);
    auto counter = Write("FB_Counter.st", kCounter);
    auto first = RunTranslator({"build", "-v", "--out", Out(), types, counter});
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_NE(first.output.find("rewrote POUS.h, pacst_enum_names.h, pacst_iec.h, T_Pair.c, FB_Counter.c"), std::string::npos)
        << first.output;

    auto again = RunTranslator({"build", "-v", "--out", Out(), types, counter});
    EXPECT_NE(again.output.find("rewrote nothing"), std::string::npos) << again.output;

    // A new body with the same interface changes that file's C and nothing else.
    Write("FB_Counter.st",
          "FUNCTION_BLOCK FB_Counter\nVAR_OUTPUT Count : INT; END_VAR\nCount := Count + 2;\nEND_FUNCTION_BLOCK\n");
    auto touched = RunTranslator({"build", "-v", "--out", Out(), types, counter});
    EXPECT_NE(touched.output.find("rewrote FB_Counter.c\n"), std::string::npos) << touched.output;
}

TEST_F(TranslatorCli, DeclarationAfterUseIsRefused) {
    auto user = Write("FB_User.st",
                      "FUNCTION_BLOCK FB_User\nVAR p : T_Pair; END_VAR\np[0] := 1;\nEND_FUNCTION_BLOCK\n");
    auto types = Write("T_Pair.st", kTypes);
    auto result = RunTranslator({"check", user, types});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(user + ":2:9: error: type 'T_Pair' is used before its declaration"),
              std::string::npos)
        << result.output;
}

// Reads a generated C file the way the compiler does: each line with the file and line it is attributed to
// (#line directives followed), and the text with the directives left out.
struct LocatedC {
    std::vector<std::pair<std::string, int>> where;  // per line of `code`
    std::vector<std::string> code;
};

LocatedC ReadLocated(const fs::path& path) {
    LocatedC result;
    std::ifstream in(path);
    std::string file = path.string();
    int next = 1;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("#line ", 0) == 0) {
            const auto quote = line.find('"');
            next = std::stoi(line.substr(6, quote - 6));
            file = line.substr(quote + 1, line.size() - quote - 2);
            continue;
        }
        result.where.emplace_back(file, next++);
        result.code.push_back(line);
    }
    return result;
}

TEST_F(TranslatorCli, LineDirectivesPutEachStatementOnItsStLineAndChangeNothingElse) {
    auto source = Write("FB_Lines.st",
                        "FUNCTION_BLOCK FB_Lines\n"                       // 1
                        "VAR_INPUT Go : BOOL; END_VAR\n"                  // 2
                        "VAR_OUTPUT Count : INT; END_VAR\n"               // 3
                        "IF Go THEN\n"                                    // 4
                        "  Count := Count + 1;\n"                         // 5
                        "  (* not a statement *)\n"                       // 6
                        "ELSIF Count > 10 THEN\n"                         // 7
                        "  Count := 0;\n"                                 // 8
                        "END_IF;\n"                                       // 9
                        "CASE Count OF\n"                                 // 10
                        "  3:\n"                                          // 11
                        "    Count := 4;\n"                               // 12
                        "END_CASE;\n"                                     // 13
                        "END_FUNCTION_BLOCK\n");
    const std::string plain = (dir_ / "plain").string();
    ASSERT_EQ(RunTranslator({"build", "--out", plain, source}).exitCode, 0);
    auto result = RunTranslator({"build", "--line-directives", "--out", Out(), source});
    ASSERT_EQ(result.exitCode, 0) << result.output;

    const LocatedC with = ReadLocated(dir_ / "out" / "FB_Lines.c");
    EXPECT_EQ(with.code, ReadLocated(fs::path(plain) / "FB_Lines.c").code) << "only #line lines may be added";
    auto stLineOf = [&](const std::string& code) {
        for (std::size_t i = 0; i < with.code.size(); ++i) {
            if (with.code[i].find(code) != std::string::npos) {
                EXPECT_EQ(with.where[i].first, fs::absolute(source).string()) << code;
                return with.where[i].second;
            }
        }
        ADD_FAILURE() << "no line with " << code;
        return 0;
    };
    EXPECT_EQ(stLineOf("if (data__->GO.value)"), 4);
    EXPECT_EQ(stLineOf("data__->COUNT.value + ((INT)1LL)"), 5);
    EXPECT_EQ(stLineOf("} else if ("), 7);
    EXPECT_EQ(stLineOf("COUNT, , ((INT)0LL)"), 8);
    EXPECT_EQ(stLineOf("__case1 == 3"), 11);
    EXPECT_EQ(stLineOf("COUNT, , ((INT)4LL)"), 12);
    // After the body the generated file has its own lines again: the exit is not an ST line.
    for (std::size_t i = 0; i < with.code.size(); ++i) {
        if (with.code[i] == "__end:") {
            EXPECT_EQ(with.where[i].first, fs::absolute(dir_ / "out" / "FB_Lines.c").string());
            std::ifstream in(dir_ / "out" / "FB_Lines.c");
            int number = 0;
            for (std::string line; std::getline(in, line) && line != "__end:";) ++number;
            EXPECT_EQ(with.where[i].second, number + 1);
        }
    }
}

// No ST of the library's subset names an instance's EN or ENO, so EN stays the TRUE _init__ gives it: the calls of
// the standard FBs skip the EN test and the ENO write. In user mode (memory functions, pointers) the full form stays;
// the C interface keeps both members and `<FB>_body__` with its test.
std::string ReadAll(const fs::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST_F(TranslatorCli, StandardFbCallsSkipTheEnTestNoStCanMakeFalse) {
    const char* body =
        "FUNCTION_BLOCK FB_Pulse\n"
        "VAR_INPUT Go : BOOL; END_VAR\n"
        "VAR_OUTPUT Done : BOOL; END_VAR\n"
        "VAR Delay : TON; Edge : R_TRIG; END_VAR\n"
        "Delay(IN := Go, PT := T#2MS);\n"
        "Edge(CLK := Delay.Q);\n"
        "Done := Edge.Q;\n";
    auto source = Write("FB_Pulse.st", std::string(body) + "END_FUNCTION_BLOCK\n");
    auto result = RunTranslator({"build", "--out", Out(), source});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const std::string lean = ReadAll(dir_ / "out" / "FB_Pulse.c");
    EXPECT_NE(lean.find("TON_body_lean__(&data__->DELAY);"), std::string::npos) << lean;
    EXPECT_NE(lean.find("R_TRIG_body_lean__(&data__->EDGE);"), std::string::npos) << lean;
    const std::string header = ReadAll(dir_ / "out" / "pacst_iec.h");
    // TON_body__, which C callers use, still tests EN around the lean body.
    EXPECT_NE(header.find("static inline void FB##_body__(FB *d) {"), std::string::npos);
    EXPECT_NE(header.find("if (!d->EN.value) { d->ENO.value = FALSE; return; }"), std::string::npos);
    EXPECT_NE(header.find("__PACST_EN_BODY(TON)"), std::string::npos);
    EXPECT_NE(header.find("__IEC_BOOL_t EN, ENO, IN;"), std::string::npos);

    // The premise: a call's EN or ENO, and the members, are refused in the library's subset.
    for (const char* use : {"Delay(EN := FALSE, IN := Go, PT := T#2MS);\n", "Edge(CLK := Go, ENO => Done);\n",
                            "Done := Delay.ENO;\n", "Delay.EN := FALSE;\n"}) {
        auto changed = Write("FB_Pulse.st", std::string(body) + use + "END_FUNCTION_BLOCK\n");
        EXPECT_EQ(RunTranslator({"check", changed}).exitCode, 1) << use;
    }

    // User mode keeps the EN test: there memory functions could reach EN.
    auto user = Write("FB_Pulse.st", std::string(body) + "END_FUNCTION_BLOCK\n");
    const std::string userOut = (dir_ / "user").string();
    result = RunTranslator({"build", "--user", "--out", userOut, user});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const std::string full = ReadAll(fs::path(userOut) / "FB_Pulse.c");
    EXPECT_NE(full.find("TON_body__(&data__->DELAY);"), std::string::npos) << full;
    EXPECT_EQ(full.find("_body_lean__"), std::string::npos) << full;
}

// --gvl: the global constant list is checked, POU constants named like its constants must repeat them
// unchanged, and a build writes the list as a name/type/value table.
const char* kList =
    "VAR_GLOBAL CONSTANT\n"
    "  K_CODE : WORD := 16#0A93;\n"
    "  K_LIMIT : INT := -5;\n"
    "END_VAR\n";

std::string UserOf(const std::string& value) {
    return "FUNCTION_BLOCK FB_User\nVAR_OUTPUT Code : WORD; END_VAR\nVAR CONSTANT\n  K_CODE : WORD := " + value +
           ";\nEND_VAR\nCode := K_CODE;\nEND_FUNCTION_BLOCK\n";
}

TEST_F(TranslatorCli, ConstantRepeatedFromTheListBuildsAndTheListBecomesATable) {
    auto list = Write("GVL_Probe.st", kList);
    auto user = Write("FB_User.st", UserOf("WORD#2707"));  // the same value in another spelling
    auto result = RunTranslator({"build", "--out", Out(), "--gvl", list, user});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::ifstream table(dir_ / "out" / "GVL_Probe.h");
    std::string text((std::istreambuf_iterator<char>(table)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("{\"K_CODE\", \"WORD\", 2707LL}"), std::string::npos) << text;
    EXPECT_NE(text.find("{\"K_LIMIT\", \"INT\", -5LL}"), std::string::npos) << text;
}

TEST_F(TranslatorCli, ConstantThatDiffersFromTheListIsRefused) {
    auto list = Write("GVL_Probe.st", kList);
    auto user = Write("FB_User.st", UserOf("16#0A94"));
    auto result = RunTranslator({"build", "--out", Out(), "--gvl", list, user});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(user + ":4:3: error: constant K_CODE differs from GVL_Probe.st:2 (WORD#16#0A93)"),
              std::string::npos)
        << result.output;
    EXPECT_FALSE(Generated("GVL_Probe.h"));
    auto retyped = Write("FB_User.st", "FUNCTION_BLOCK FB_User\nVAR_OUTPUT L : DINT; END_VAR\nVAR CONSTANT\n"
                                       "  K_LIMIT : DINT := -5;\nEND_VAR\nL := K_LIMIT;\nEND_FUNCTION_BLOCK\n");
    result = RunTranslator({"check", "--gvl", list, retyped});
    EXPECT_NE(result.output.find(retyped + ":4:3: error: constant K_LIMIT is DINT here but INT in GVL_Probe.st:3"),
              std::string::npos)
        << result.output;
}

TEST_F(TranslatorCli, ListOutsideItsRulesIsRefused) {
    auto user = Write("FB_Counter.st", kCounter);
    const std::pair<const char*, const char*> cases[] = {
        {"VAR_GLOBAL\n  K : WORD := 1;\nEND_VAR\n", ":1:1: error: VAR_GLOBAL without CONSTANT"},
        {"VAR_GLOBAL CONSTANT\n  K : REAL := 1.5;\nEND_VAR\n", ":2:7: error: global constant of type REAL"},
        {"VAR_GLOBAL CONSTANT\n  K : BYTE := 256;\nEND_VAR\n", ":2:15: error: 256 does not fit BYTE"},
        {"VAR_GLOBAL CONSTANT\n  K : WORD := 1;\n  k : WORD := 2;\nEND_VAR\n",
         ":3:3: error: constant 'k' is declared twice"},
        {"VAR_GLOBAL CONSTANT\n  K : WORD;\nEND_VAR\n", ":2:3: error: a global constant needs a value"},
    };
    for (const auto& [text, words] : cases) {
        auto list = Write("GVL_Probe.st", text);
        auto result = RunTranslator({"check", "--gvl", list, user});
        EXPECT_EQ(result.exitCode, 1) << text;
        EXPECT_NE(result.output.find(list + words), std::string::npos) << text << result.output;
    }
}

// `pacst order`: the declaration order CMake gives MATIEC and pacst (st/CMakeLists.txt), from the files alone.
std::string Lines(const std::vector<std::string>& lines) {
    std::string text;
    for (const auto& line : lines) text += line + "\n";
    return text;
}

TEST_F(TranslatorCli, OrderPutsTypesEnumerationsAndCalleesBeforeTheirUsers) {
    // Named so that the file names' order is wrong: only the uses can put them right.
    auto caller = Write("A_Caller.st",
                        "FUNCTION_BLOCK A_Caller\nVAR_OUTPUT IsOn : BOOL; END_VAR\nVAR Callee : Z_Callee; END_VAR\n"
                        "Callee();\nIsOn := Callee.Mode = MODE_ON;\nEND_FUNCTION_BLOCK\n");
    auto values = Write("B_Values.st",  // names only enumeration values, not their type
                        "FUNCTION_BLOCK B_Values\nVAR_OUTPUT Same : BOOL; END_VAR\nSame := MODE_ON = MODE_OFF;\n"
                        "END_FUNCTION_BLOCK\n");
    auto callee = Write("Z_Callee.st",
                        "FUNCTION_BLOCK Z_Callee\nVAR_INPUT Pair : T_Pair; END_VAR\nVAR_OUTPUT Mode : E_Mode; END_VAR\n"
                        "Mode := MODE_ON;\nEND_FUNCTION_BLOCK\n");
    auto pair = Write("T_Pair.st", kTypes);
    auto mode = Write("E_Mode.st", "TYPE E_Mode : (MODE_OFF, MODE_ON);\nEND_TYPE\n");
    auto result = RunTranslator({"order", caller, values, callee, pair, mode});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(result.output, Lines({mode, values, pair, callee, caller}));
    // The order is one the translator accepts; the given one is not.
    EXPECT_EQ(RunTranslator({"check", mode, values, pair, callee, caller}).exitCode, 0);
    EXPECT_EQ(RunTranslator({"check", caller, values, callee, pair, mode}).exitCode, 1);
}

TEST_F(TranslatorCli, OrderBreaksTiesByFileNameWhateverTheFoldersAndTheGivenOrder) {
    fs::create_directories(dir_ / "a");
    fs::create_directories(dir_ / "b");
    auto two = Write("a/FB_Two.st", "FUNCTION_BLOCK FB_Two\nVAR_OUTPUT X : INT; END_VAR\nX := 2;\nEND_FUNCTION_BLOCK\n");
    auto one = Write("b/FB_One.st", "FUNCTION_BLOCK FB_One\nVAR_OUTPUT X : INT; END_VAR\nX := 1;\nEND_FUNCTION_BLOCK\n");
    auto counter = Write("FB_Counter.st", kCounter);
    const auto expected = Lines({counter, one, two});
    EXPECT_EQ(RunTranslator({"order", two, one, counter}).output, expected);
    EXPECT_EQ(RunTranslator({"order", one, counter, two}).output, expected);
}

TEST_F(TranslatorCli, OrderRefusesACycleNamingItsFiles) {
    auto ping = Write("FB_Ping.st", "FUNCTION_BLOCK FB_Ping\nVAR Other : FB_Pong; END_VAR\nOther();\nEND_FUNCTION_BLOCK\n");
    auto pong = Write("FB_Pong.st", "FUNCTION_BLOCK FB_Pong\nVAR Other : FB_Ping; END_VAR\nOther();\nEND_FUNCTION_BLOCK\n");
    auto counter = Write("FB_Counter.st", kCounter);
    auto result = RunTranslator({"order", counter, pong, ping});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(ping + ":1:1: error: declaration cycle"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("FB_Ping.st (uses FB_Pong) -> FB_Pong.st (uses FB_Ping) -> FB_Ping.st"),
              std::string::npos)
        << result.output;
    EXPECT_EQ(result.output.find(counter), std::string::npos) << "no order printed: " << result.output;
}

}  // namespace
