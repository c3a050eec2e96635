// pacst's user-program mode on the command line: what needs two files (a name two global lists declare),
// the symbol table written only in user mode, --native only with --user.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "translator_runner.hpp"

namespace {

namespace fs = std::filesystem;
using pac::test::RunTranslator;

class TranslatorUserCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(PACST_SCRATCH_DIR) / ("user_" + std::string(::testing::UnitTest::GetInstance()
                                                                        ->current_test_info()->name()));
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

const char* kMain =
    "PROGRAM PRG_Main\n"
    "VAR N : INT; END_VAR\n"
    "N := Count;\n"
    "END_PROGRAM\n";

TEST_F(TranslatorUserCli, NameOfTwoGlobalListsMustBeQualified) {
    auto a = Write("GVL_A.st", "VAR_GLOBAL\n  Count : INT;\nEND_VAR\n");
    auto b = Write("GVL_B.st", "VAR_GLOBAL\n  Count : INT;\nEND_VAR\n");
    auto main = Write("PRG_Main.st", kMain);
    auto result = RunTranslator({"build", "--user", "--out", Out(), a, b, main});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(main + ":3:6: error: 'Count' is declared in the global lists GVL_A, GVL_B: "
                                        "qualify it (List.Name)"),
              std::string::npos)
        << result.output;
    EXPECT_FALSE(Generated("symbols.json"));
    auto qualified = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR N : INT; END_VAR\nN := GVL_B.Count;\nEND_PROGRAM\n");
    result = RunTranslator({"build", "--user", "--out", Out(), a, b, qualified});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(Generated("symbols.json"));
}

TEST_F(TranslatorUserCli, FilesMayComeInAnyOrder) {
    // TwinCAT and CODESYS keep no declaration order: user mode finds it (`pacst order`), and a POU may use
    // a global of any list.
    auto main = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR N : INT; Lamp : FB_Lamp; END_VAR\nN := Count;\n"
                                     "Point.X := N;\nLamp(On := TRUE);\nEND_PROGRAM\n");
    auto fb = Write("FB_Lamp.st", "FUNCTION_BLOCK FB_Lamp\nVAR_INPUT On : BOOL; END_VAR\nPoint.X := 1;\n"
                                  "END_FUNCTION_BLOCK\n");
    auto list = Write("GVL_A.st", "VAR_GLOBAL\n  Count : INT := 3;\n  Point : ST_Point;\nEND_VAR\n");
    auto type = Write("ST_Point.st", "TYPE ST_Point :\nSTRUCT\n  X : INT;\nEND_STRUCT;\nEND_TYPE\n");
    auto result = RunTranslator({"build", "--user", "--out", Out(), main, fb, list, type});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    result = RunTranslator({"build", "--out", Out(), main, fb, list, type});
    EXPECT_EQ(result.exitCode, 1) << "the library's subset keeps its declaration order (MATIEC)";
}

TEST_F(TranslatorUserCli, LibraryModeRefusesUserConstructsAndWritesNoSymbolTable) {
    auto list = Write("GVL_A.st", "VAR_GLOBAL\n  Count : INT;\nEND_VAR\n");
    auto main = Write("PRG_Main.st", kMain);
    auto result = RunTranslator({"build", "--out", Out(), list, main});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(list + ":1:1: error: VAR_GLOBAL is outside the subset"), std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find(main + ":1:1: error: PROGRAM is outside the library's subset"), std::string::npos)
        << result.output;
    auto fb = Write("FB_Counter.st", "FUNCTION_BLOCK FB_Counter\nVAR_OUTPUT N : INT; END_VAR\nN := N + 1;\nEND_FUNCTION_BLOCK\n");
    ASSERT_EQ(RunTranslator({"build", "--out", Out(), fb}).exitCode, 0);
    EXPECT_FALSE(Generated("symbols.json"));
    ASSERT_EQ(RunTranslator({"build", "--user", "--out", Out(), fb}).exitCode, 0);
    EXPECT_TRUE(Generated("symbols.json"));
}

TEST_F(TranslatorUserCli, NativeNeedsUserMode) {
    auto native = Write("Asserts.st", "FUNCTION AssertTrue\nVAR_INPUT C : BOOL; END_VAR\n;\nEND_FUNCTION\n");
    auto fb = Write("FB_Counter.st", "FUNCTION_BLOCK FB_Counter\nVAR_OUTPUT N : INT; END_VAR\nN := N + 1;\nEND_FUNCTION_BLOCK\n");
    auto result = RunTranslator({"build", "--native", native, "--out", Out(), fb});
    EXPECT_NE(result.exitCode, 0);
    EXPECT_NE(result.output.find("--native needs --user"), std::string::npos) << result.output;
    result = RunTranslator({"build", "--user", "--native", native, "--out", Out(), fb});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_FALSE(Generated("Asserts.c")) << "the host implements a native FUNCTION";
}

}  // namespace
