// The translator's command line: refusals name file:line:col and leave nothing generated behind;
// builds rewrite only the files whose text changed; check mode writes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "translator_runner.hpp"

namespace {

namespace fs = std::filesystem;
using pac::test::RunTranslator;

class TranslatorCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(PACST_SCRATCH_DIR) / ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "out");
    }

    std::string Write(const std::string& name, const std::string& text) {
        fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p.string();
    }

    std::string Out() const { return (dir_ / "out").string(); }
    bool Generated(const std::string& name) const { return fs::exists(dir_ / "out" / name); }

    fs::path dir_;
};

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

}  // namespace
