// pacst's user-program mode on the command line: what needs several files (a name two global lists
// declare, files in any order), TwinCAT and PLCopen inputs, `pacst matiec`, --native only with --user.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
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

std::string ReadFile(const fs::path& path);

class TranslatorUserCli : public pac::test::TranslatorScratch {
protected:
    TranslatorUserCli() : TranslatorScratch("user_") {}
};

const char* kCounter = "FUNCTION_BLOCK FB_Counter\nVAR_OUTPUT N : INT; END_VAR\nN := N + 1;\nEND_FUNCTION_BLOCK\n";
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

TEST_F(TranslatorUserCli, PlainStFileMayLeaveOutItsPousEndKeyword) {
    // A TwinCAT or CODESYS programmer never types END_FUNCTION_BLOCK or END_PROGRAM: the editor keeps
    // them out, and so do the .st files such a programmer writes, one POU per file. User mode closes the
    // file's one POU at its end (as it does for a TwinCAT object); failures keep the file's lines.
    auto fb = Write("FB_Lamp.st", "// the lamp\nFUNCTION_BLOCK FB_Lamp\nVAR_INPUT On : BOOL; END_VAR\n"
                                  "VAR_OUTPUT N : INT; END_VAR\nIF On THEN\n  N := N + 1;\nEND_IF\n");
    auto main = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR Lamp : FB_Lamp; END_VAR\nLamp(On := TRUE);\n");
    auto result = RunTranslator({"build", "--user", "--out", Out(), fb, main});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    auto bad = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR Lamp : FB_Lamp; END_VAR\nLamp(On := TRUE)\nLamp(On := FALSE);\n");
    result = RunTranslator({"build", "--user", "--out", Out(), fb, bad});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(bad + ":4:1: error: syntax error"), std::string::npos) << result.output;
    // the other files are checked in the same run, but for what may need the file that could not be read
    auto other = Write("PRG_Other.st", "PROGRAM PRG_Other\nVAR N : INT; M : PRG_Gone; END_VAR\nN := 'text';\n"
                                       "N := Gone;\n");
    result = RunTranslator({"check", "--user", fb, bad, other});
    EXPECT_NE(result.output.find(bad + ":4:1: error: syntax error"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(other + ":3:6: error: type mismatch"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("undeclared"), std::string::npos) << result.output;
    result = RunTranslator({"build", "--out", Out(), fb, main});
    EXPECT_EQ(result.exitCode, 1) << "the library's subset keeps the IEC end keywords";
}

TEST_F(TranslatorUserCli, UseOfAGlobalListWithARefusedDeclarationSaysSo) {
    // One refused line of a global list must not read, further down, as a variable the list lacks; the lines
    // after it are declared (and refused each on its own).
    auto list = Write("GVL_Hmi.st", "VAR_GLOBAL\n  Speed : NoSuchType;\n  Message : STRING(80);\nEND_VAR\n");
    auto main = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR N : INT; END_VAR\nGVL_Hmi.Speed := 1;\n"
                                     "GVL_Hmi.Message := 'x';\nEND_PROGRAM\n");
    auto result = RunTranslator({"build", "--user", "--out", Out(), list, main});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(list + ":2:11: error:"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("has no variable"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(main + ":3:9: error: GVL_Hmi.Speed cannot be used: a declaration of the "
                                        "global variable list GVL_Hmi was refused (above)"),
              std::string::npos)
        << result.output;
    EXPECT_EQ(result.output.find(main + ":4:"), std::string::npos) << "Message is declared\n" << result.output;
    auto unqualified = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR N : INT; END_VAR\nSpeed := 1;\nEND_PROGRAM\n");
    result = RunTranslator({"build", "--user", "--out", Out(), list, unqualified});
    EXPECT_NE(result.output.find(unqualified + ":3:1: error: undeclared name 'Speed' (or one whose declaration in "
                                               "GVL_Hmi was refused, above)"),
              std::string::npos)
        << result.output;
}

TEST_F(TranslatorUserCli, QualifiedEnumerationValuesAndVariablesOfTheirNames) {
    // TwinCAT's new DUTs are {attribute 'qualified_only'}: programs write E_Step.HOMING, and a value may
    // have the name of a variable (the library's MC_ReadStatus has an output Homing), which shadows it.
    auto type = Write("E_Step.st", "{attribute 'qualified_only'}\nTYPE E_Step :\n(\n  IDLE,\n  HOMING,\n  FAULT\n);\n"
                                   "END_TYPE\n");
    auto fb = Write("FB_Status.st", "FUNCTION_BLOCK FB_Status\nVAR_OUTPUT Homing : BOOL; END_VAR\n"
                                    "Homing := NOT Homing;\nEND_FUNCTION_BLOCK\n");
    auto main = Write("PRG_Main.st",
                      "PROGRAM PRG_Main\nVAR Step : E_Step := E_Step.IDLE; Status : FB_Status; END_VAR\n"
                      "Status();\nCASE Step OF\n  E_Step.IDLE: Step := E_Step.HOMING;\n"
                      "  E_Step.HOMING, E_Step.FAULT:\n    IF Step <> E_Step.FAULT THEN Step := E_Step.FAULT; END_IF;\n"
                      "END_CASE;\nEND_PROGRAM\n");
    auto result = RunTranslator({"build", "--user", "--out", Out(), type, fb, main});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    // written alone, a value of a qualified_only type is refused, as TwinCAT refuses it; as a CASE label too, and
    // so is a constant of a qualified_only list (at the label, not at the file's first line)
    auto limits = Write("GVL_Limits.st", "{attribute 'qualified_only'}\nVAR_GLOBAL CONSTANT\n  MaxSteps : INT := 4;\n"
                                         "END_VAR\n");
    auto bare = Write("PRG_Bare.st", "PROGRAM PRG_Bare\nVAR Step : E_Step; N : INT; END_VAR\nStep := FAULT;\n"
                                     "CASE Step OF\n  IDLE: N := 1;\nEND_CASE\n"
                                     "CASE N OF\n  MaxSteps: N := 0;\nEND_CASE\n"
                                     "END_PROGRAM\n");
    result = RunTranslator({"build", "--user", "--out", Out(), type, fb, limits, bare});
    for (const auto& expected : {bare + ":3:9: error: 'FAULT' alone: the enumeration E_Step has {attribute "
                                        "'qualified_only'}, as in TwinCAT write E_Step.FAULT",
                                 bare + ":5:3: error: 'IDLE' alone: the enumeration E_Step has {attribute "
                                        "'qualified_only'}, as in TwinCAT write E_Step.IDLE",
                                 bare + ":8:3: error: 'MaxSteps' alone: the global list GVL_Limits has {attribute "
                                        "'qualified_only'}, as in TwinCAT write GVL_Limits.MaxSteps"}) {
        EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
    }
    auto wrong = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR Step : E_Step; END_VAR\nStep := E_Step.RUN;\n"
                                      "END_PROGRAM\n");
    result = RunTranslator({"build", "--user", "--out", Out(), type, fb, wrong});
    EXPECT_NE(result.output.find(wrong + ":3:16: error: E_Step has no value 'RUN'"), std::string::npos)
        << result.output;
    result = RunTranslator({"build", "--out", Out(), type, fb, main});
    EXPECT_EQ(result.exitCode, 1) << "the library's subset keeps values unqualified and distinct from names";
}

TEST_F(TranslatorUserCli, IntegersAndBoolsConvertToStringForMessages) {
    // HMI messages: CONCAT('trip ', UDINT_TO_STRING(Trips)); written in decimal by every tool.
    auto main = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR Text : STRING(80); N : INT := -5; Trips : UDINT;\n"
                                     "Ok : BOOL; W : WORD; END_VAR\n"
                                     "Text := CONCAT(INT_TO_STRING(N), UDINT_TO_STRING(Trips));\n"
                                     "Text := CONCAT(BOOL_TO_STRING(Ok), WORD_TO_STRING(W));\nEND_PROGRAM\n");
    auto result = RunTranslator({"build", "--user", "--out", Out(), main});
    EXPECT_EQ(result.exitCode, 0) << result.output;
}

TEST_F(TranslatorUserCli, TwoEnumerationsMayShareAValueNameWrittenQualified) {
    // qualified_only enumerations of one TwinCAT project often share names (E_Mode.IDLE, E_Step.IDLE).
    auto mode = Write("E_Mode.st", "TYPE E_Mode :\n(\n  IDLE,\n  MANUAL\n);\nEND_TYPE\n");
    auto step = Write("E_Step.st", "TYPE E_Step :\n(\n  IDLE,\n  RUN\n);\nEND_TYPE\n");
    auto main = Write("PRG_Main.st",
                      "PROGRAM PRG_Main\nVAR Mode : E_Mode := E_Mode.MANUAL; Step : E_Step; END_VAR\n"
                      "CASE Step OF\n  E_Step.IDLE: Step := E_Step.RUN;\n  E_Step.RUN: Mode := E_Mode.IDLE;\n"
                      "END_CASE;\nEND_PROGRAM\n");
    auto result = RunTranslator({"build", "--user", "--out", Out(), mode, step, main});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    auto bare = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR Step : E_Step; END_VAR\nStep := IDLE;\nEND_PROGRAM\n");
    result = RunTranslator({"build", "--user", "--out", Out(), mode, step, bare});
    EXPECT_NE(result.output.find(bare + ":3:9: error: 'IDLE' is a value of E_Mode and E_Step: qualify it "
                                        "(E_Mode.IDLE)"),
              std::string::npos)
        << result.output;
}

TEST_F(TranslatorUserCli, EveryRefusedDeclarationAndStatementIsReported) {
    // Eleven problems, one run: the declarations of a POU, a global list, a STRUCT and an FB's METHODs, then the
    // POU's statements, but those that use a variable whose declaration was refused (which cannot be told apart
    // from it).
    auto decls = Write("PRG_Decls.st", "PROGRAM PRG_Decls\nVAR\n  A : NoSuchType;\n  B : Tc2_MC2.MC_Power;\n"
                                       "  C : INT;\nEND_VAR\nC := 1;\nA := C;\nC := Nowhere;\nEND_PROGRAM\n");
    auto body = Write("PRG_Body.st", "PROGRAM PRG_Body\nVAR\n  C : INT;\n  D : REAL;\nEND_VAR\nC := D;\n"
                                     "IF C > 0 THEN\n  C := Nothing;\nEND_IF\nC := 2;\nEND_PROGRAM\n");
    auto list = Write("GVL_Two.st", "VAR_GLOBAL\n  E : NoSuchType;\n  F : INT := 'text';\nEND_VAR\n");
    auto type = Write("ST_Two.st", "TYPE ST_Two :\nSTRUCT\n  G : NoSuchType;\n  H : NoSuchType;\nEND_STRUCT\nEND_TYPE\n");
    auto fb = Write("FB_Two.st", "FUNCTION_BLOCK FB_Two\nEND_FUNCTION_BLOCK\nMETHOD M1 : NoSuchType\nEND_METHOD\n"
                                 "METHOD M2 : NoSuchType\nEND_METHOD\n");
    auto result = RunTranslator({"check", "--user", decls, body, list, type, fb});
    EXPECT_EQ(result.exitCode, 1);
    for (const auto& expected : {list + ":2:7: error: undeclared type 'NoSuchType'", list + ":3:14: error: ",
                                 type + ":3:7: error: undeclared type", type + ":4:7: error: undeclared type",
                                 fb + ":3:13: error: undeclared type", fb + ":5:13: error: undeclared type",
                                 decls + ":3:7: error: undeclared type 'NoSuchType'",
                                 decls + ":4:7: error: 'Tc2_MC2.MC_Power': pac-test does not provide the vendor library",
                                 body + ":6:6: error: type mismatch: REAL where INT is expected",
                                 body + ":8:8: error: undeclared name 'Nothing'",
                                 decls + ":9:6: error: undeclared name 'Nowhere'"}) {
        EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
    }
    EXPECT_EQ(result.output.find(decls + ":8:"), std::string::npos) << "A's use: A's refusal says it\n"
                                                                     << result.output;
}

TEST_F(TranslatorUserCli, RefusedDeclarationOfAnObjectOrientedFbHidesNoRefusalOfItsBody) {
    // An FB with METHODs, a base or an INTERFACE whose declarations were refused: the refusals of its body and of its
    // METHODs' declarations and bodies are reported in the same run too, but those that may owe to what is not
    // declared then (its METHODs, PROPERTYs, what it inherits, the variable refused).
    auto itf = Write("I_Run.st", "INTERFACE I_Run\nEND_INTERFACE\nMETHOD Run : BOOL\nEND_METHOD\n");
    auto base = Write("FB_Base.st", "FUNCTION_BLOCK FB_Base\nVAR Count : INT; END_VAR\nEND_FUNCTION_BLOCK\n");
    auto fb = Write("FB_Oo.st", R"(FUNCTION_BLOCK FB_Oo EXTENDS FB_Base IMPLEMENTS I_Run
VAR
  A : NoSuchType;
  C : INT;
  D : REAL;
END_VAR
C := D;
Run();
A := C;
C := MUX(0, 1, 2);
Count := C;
END_FUNCTION_BLOCK
METHOD Run : BOOL
VAR_INPUT
  P : NoSuchPin;
END_VAR
Run := TRUE;
END_METHOD
METHOD Step
VAR
  N : INT;
END_VAR
N := D;
N := A;
END_METHOD
)");
    auto result = RunTranslator({"check", "--user", itf, base, fb});
    EXPECT_EQ(result.exitCode, 1);
    // the FB's refused variable and its METHOD's pin; a statement of its body, twice, and of a METHOD's
    const std::vector<std::pair<int, std::string>> reported = {
        {3, "7: error: undeclared type 'NoSuchType'"}, {15, "7: error: undeclared type 'NoSuchPin'"},
        {7, "6: error: type mismatch: REAL where INT is expected"},
        {10, "6: error: standard function MUX is not supported by pacst"},
        {23, "6: error: type mismatch: REAL where INT is expected"}};
    for (const auto& [line, text] : reported) {
        auto where = fb + ":" + std::to_string(line) + ":" + text;
        EXPECT_NE(result.output.find(where), std::string::npos) << where << "\n" << result.output;
    }
    for (int line : {8, 9, 11, 24}) {  // not: its METHOD called, the variable refused (twice), the base's variable
        EXPECT_EQ(result.output.find(fb + ":" + std::to_string(line) + ":"), std::string::npos) << line << "\n"
                                                                                               << result.output;
    }
}

TEST_F(TranslatorUserCli, CallOfARefusedFunctionSaysSoAsAStatementToo) {
    // A FUNCTION whose declaration was refused is declared: a call of it, for its effect or in an expression,
    // points back at that refusal instead of calling the FUNCTION undeclared.
    auto function = Write("F_Bad.st", "FUNCTION F_Bad : INT\nVAR_INPUT X : NoSuchType; END_VAR\nF_Bad := 1;\n"
                                      "END_FUNCTION\n");
    auto main = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR N : INT; END_VAR\nF_Bad(X := 1);\nN := F_Bad(X := 2);\n"
                                     "END_PROGRAM\n");
    auto result = RunTranslator({"check", "--user", function, main});
    EXPECT_EQ(result.exitCode, 1);
    for (const auto& expected : {function + ":2:15: error: undeclared type 'NoSuchType'",
                                 main + ":3:1: error: FUNCTION F_Bad cannot be called: its declaration was refused",
                                 main + ":4:6: error: FUNCTION F_Bad cannot be called: its declaration was refused"}) {
        EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
    }
    EXPECT_EQ(result.output.find("undeclared function"), std::string::npos) << result.output;
}

TEST_F(TranslatorUserCli, UseOfAGlobalInstanceOfARefusedFbSaysSo) {
    // The CNC machine's MAIN calls `fbCNC();`, an instance its GVL declares of the refused FB_CNC: the call and a
    // read of its output point back at that refusal instead of calling the name undeclared.
    auto fb = Write("FB_Machine.st", "FUNCTION_BLOCK FB_Machine\nVAR_OUTPUT Busy : BOOL; END_VAR\n"
                                     "VAR X : NoSuchType; END_VAR\nBusy := TRUE;\nEND_FUNCTION_BLOCK\n");
    auto list = Write("GVL.st", "VAR_GLOBAL\n  Machine : FB_Machine;\nEND_VAR\n");
    auto main = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR Busy : BOOL; END_VAR\nMachine();\nBusy := Machine.Busy;\n"
                                     "END_PROGRAM\n");
    auto result = RunTranslator({"check", "--user", fb, list, main});
    EXPECT_EQ(result.exitCode, 1);
    const std::string why = "'Machine' of the global list GVL cannot be used: its function block's declaration was "
                            "refused (above)";
    for (const auto& expected : {main + ":3:1: error: " + why, main + ":4:9: error: " + why}) {
        EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
    }
    EXPECT_EQ(result.output.find("undeclared function"), std::string::npos) << result.output;
}

TEST_F(TranslatorUserCli, MethodThroughAListsPointerToARefusedFbPointsAtTheRefusal) {
    // TcUnit's GVL_TcUnit.TestSuiteAddresses[i]^.AreAllTestsFinished() in an expression, when FB_TestSuite was
    // refused: the list's variable waits for the FB, so the call points back at the FB's refusal (it said "only plain
    // function names can be called", hiding the cause).
    auto fb = Write("FB_Suite.st", "FUNCTION_BLOCK FB_Suite\nVAR Count : NoSuchType; END_VAR\nEND_FUNCTION_BLOCK\n"
                                   "METHOD Finished : BOOL\nFinished := TRUE;\nEND_METHOD\n");
    auto list = Write("GVL_Suites.st", "{attribute 'qualified_only'}\nVAR_GLOBAL\n"
                                       "  Addresses : ARRAY [1..2] OF POINTER TO FB_Suite;\nEND_VAR\n");
    auto main = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR Done : BOOL; END_VAR\n"
                                     "Done := GVL_Suites.Addresses[1]^.Finished();\nEND_PROGRAM\n");
    auto result = RunTranslator({"check", "--user", fb, list, main});
    EXPECT_EQ(result.exitCode, 1);
    const auto expected = main + ":3:20: error: GVL_Suites.Addresses cannot be used: its type names FB_Suite, whose "
                                 "declaration was refused (above)";
    EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
    EXPECT_EQ(result.output.find("only plain function names"), std::string::npos) << result.output;
}

TEST_F(TranslatorUserCli, ARefusedResultTypeHidesNoRefusalOfThePins) {
    // FsCommon's I_PlcTaskInformation: a METHOD or PROPERTY of an INTERFACE whose type is a vendor's hid the refusals
    // of its pins and of the INTERFACE's later METHODs; every one is reported, in an FB's METHOD and a FUNCTION too.
    auto itf = Write("I_Thing.st", "INTERFACE I_Thing\nEND_INTERFACE\n\nMETHOD Get : NoSuchType\nVAR_INPUT\n"
                                   "  Index : NoSuchIndex;\nEND_VAR\nEND_METHOD\n\nMETHOD Put : BOOL\nVAR_INPUT\n"
                                   "  Item : NoSuchItem;\nEND_VAR\nEND_METHOD\n");
    auto fb = Write("FB_Thing.st", "FUNCTION_BLOCK FB_Thing\nVAR X : INT; END_VAR\nEND_FUNCTION_BLOCK\n\n"
                                   "METHOD Get : NoSuchType\nVAR_INPUT\n  Index : NoSuchIndex;\nEND_VAR\nEND_METHOD\n");
    auto function = Write("F_Thing.st", "FUNCTION F_Thing : NoSuchType\nVAR_INPUT\n  Index : NoSuchIndex;\nEND_VAR\n"
                                        "F_Thing := 1;\nEND_FUNCTION\n");
    auto result = RunTranslator({"check", "--user", itf, fb, function});
    EXPECT_EQ(result.exitCode, 1);
    for (const auto& expected : {itf + ":4:14: error: undeclared type 'NoSuchType'",
                                 itf + ":6:11: error: undeclared type 'NoSuchIndex'",
                                 itf + ":12:10: error: undeclared type 'NoSuchItem'",
                                 fb + ":5:14: error: undeclared type 'NoSuchType'",
                                 fb + ":7:11: error: undeclared type 'NoSuchIndex'",
                                 function + ":1:20: error: undeclared type 'NoSuchType'",
                                 function + ":3:11: error: undeclared type 'NoSuchIndex'"}) {
        EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
    }
    EXPECT_EQ(result.output.find("undeclared name 'F_Thing'"), std::string::npos) << result.output;
}

TEST_F(TranslatorUserCli, LibraryUnderItsNamespace) {
    // docs/import.md: the library referenced with the namespace PA_CONTROL; --namespace says which files hold it.
    fs::create_directories(dir_ / "lib");
    auto lib = Write("lib/FB_Lamp.st", "FUNCTION_BLOCK FB_Lamp\nVAR_INPUT On : BOOL; END_VAR\nVAR_OUTPUT Lit : BOOL; "
                                       "END_VAR\nLit := On;\nEND_FUNCTION_BLOCK\n");
    auto list = Write("lib/GVL_Lib.st", "VAR_GLOBAL CONSTANT\n  K_ON : BOOL := TRUE;\nEND_VAR\n");
    auto main = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR Lamp : PA_CONTROL.FB_Lamp; T : Tc2_Standard.TON; END_VAR\n"
                                     "Lamp(On := PA_CONTROL.GVL_Lib.K_ON);\nT(IN := Lamp.Lit, PT := T#1S);\nEND_PROGRAM\n");
    const std::string ns = "PA_CONTROL=" + fs::path(lib).parent_path().string();
    auto result = RunTranslator({"build", "--user", "--namespace", ns, "--out", Out(), lib, list, main});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    result = RunTranslator({"build", "--user", "--out", Out(), lib, list, main});
    EXPECT_EQ(result.exitCode, 1) << "without --namespace, PA_CONTROL is no namespace";
    EXPECT_NE(result.output.find(main + ":2:12: error: 'PA_CONTROL.FB_Lamp': 'PA_CONTROL' is no library namespace"),
              std::string::npos) << result.output;
    // A copy of the library's FB among the program's own shadows the library's, which no other file of it names:
    // the plain name means the copy, and PA_CONTROL.FB_Lamp says why it is not the library's.
    auto copy = Write("FB_Lamp.st", ReadFile(lib));
    result = RunTranslator({"check", "--user", "--namespace", ns, lib, list, copy, main});
    EXPECT_NE(result.output.find(main + ":2:12: error: 'PA_CONTROL.FB_Lamp': the program declares FB_Lamp too (" +
                                 copy + ":1), which TwinCAT and CODESYS keep apart from the library's"),
              std::string::npos) << result.output;
    auto matiec = Out() + "/program.st";
    result = RunTranslator({"matiec", "--namespace", ns, "--out", matiec, lib, list, main});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(main + ":2:12: error: the namespace in 'PA_CONTROL.FB_Lamp': TwinCAT / CODESYS "
                                        "dialect that MATIEC does not compile"),
              std::string::npos) << result.output;
}

TEST_F(TranslatorUserCli, AProgramsNameTakenFromItsLibraryIsOneClearError) {
    // The program declares FB_Counter and its library Lib does too, declared after the program's (it waits for the
    // library's Z_Count), and the library's PRG_Counting uses its own, so it is not left out as a shadowed one: the
    // refusal is at the program's copy, and Lib.FB_Counter says it was refused there, not that the library has no
    // FB_Counter, which it has.
    std::string theirs = kCounter;
    theirs.replace(theirs.find("INT;"), 3, "Z_Count");
    fs::create_directories(dir_ / "Lib");
    Write("Lib/FB_Counter.st", theirs);
    Write("Lib/Z_Count.st", "TYPE Z_Count : INT; END_TYPE\n");
    Write("Lib/PRG_Counting.st", "PROGRAM PRG_Counting\nVAR C : FB_Counter; END_VAR\nC();\nEND_PROGRAM\n");
    auto own = Write("FB_Counter.st", kCounter);
    auto main = Write("MAIN.st", "PROGRAM MAIN\nVAR Theirs : Lib.FB_Counter; END_VAR\nTheirs();\nEND_PROGRAM\n");
    auto result = RunTranslator({"check", "--user", "--library", "Lib=" + (dir_ / "Lib").string(), own, main});
    EXPECT_EQ(result.exitCode, 1);
    for (const auto& expected : {own + ":1:1: error: function block 'FB_Counter' is declared by the library Lib too",
                                 main + ":2:14: error: 'Lib.FB_Counter' cannot be used: its declaration was refused "
                                        "(above), as the program declares FB_Counter too (" + own + ":1): rename the "
                                        "program's"}) {
        EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
    }
    EXPECT_EQ(result.output.find("has no type or POU"), std::string::npos) << result.output;
}

TEST_F(TranslatorUserCli, ALibrarysPouTheProgramShadowsIsLeftOut) {
    // TwinCAT and CODESYS keep a library's names apart from the program's: a test project's MAIN beside its library's
    // MAIN (TcDynCollections) is the one its plain name means. The library's, which no other file of the library
    // names, is left out of pacst's C, whose names are one set; Lib.MAIN says so at its use.
    fs::create_directories(dir_ / "Lib");
    Write("Lib/FB_Lamp.st", "FUNCTION_BLOCK FB_Lamp\nVAR_INPUT On : BOOL; END_VAR\nVAR_OUTPUT Lit : BOOL; END_VAR\n"
                            "Lit := On;\nEND_FUNCTION_BLOCK\n");
    Write("Lib/MAIN.st", "PROGRAM MAIN\nVAR Theirs : FB_Lamp; END_VAR\nTheirs(On := TRUE);\nEND_PROGRAM\n");
    auto main = Write("MAIN.st", "PROGRAM MAIN\nVAR Ours : Lib.FB_Lamp; Scans : INT; END_VAR\n"
                                 "Ours(On := Scans > 2);\nScans := Scans + 1;\nEND_PROGRAM\n");
    const std::string library = "Lib=" + (dir_ / "Lib").string();
    auto result = RunTranslator({"build", "--user", "--library", library, "--out", Out(), main});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const std::string c = ReadFile(Out() + "/MAIN.c");
    EXPECT_NE(c.find("SCANS"), std::string::npos) << "the program's MAIN\n" << c;
    EXPECT_EQ(c.find("THEIRS"), std::string::npos) << "not the library's\n" << c;
    EXPECT_NE(ReadFile(Out() + "/FB_Lamp.c").find("FB_LAMP_body__"), std::string::npos);
    auto other = Write("PRG_Other.st", "PROGRAM PRG_Other\nVAR Lit : BOOL; END_VAR\nLit := Lib.MAIN.Theirs.Lit;\n"
                                       "END_PROGRAM\n");
    result = RunTranslator({"check", "--user", "--library", library, main, other});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(other + ":3:12: error: 'Lib.MAIN': the program declares MAIN too (" + main +
                                 ":1), which TwinCAT and CODESYS keep apart from the library's; pac-test's C holds "
                                 "one declaration of each name and takes the program's: rename the program's to use "
                                 "the library's"),
              std::string::npos) << result.output;
}

TEST_F(TranslatorUserCli, PlcopenRefusalIsOneLineAtTheObject) {
    // A PLCopen object pacst cannot read is one line naming the XML file and the object's line, not a traceback.
    auto xml = Write("Project.xml", "<?xml version=\"1.0\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">\n"
                                    "<types><pous>\n<pou name=\"PLC_PRG\" pouType=\"program\"><body><LD/></body></pou>\n"
                                    "</pous></types></project>\n");
    for (const char* command : {"check", "build", "order"}) {
        std::vector<std::string> args = {command, "--user"};
        if (std::string(command) == "build") args.insert(args.end(), {"--out", Out()});
        args.push_back(xml);
        auto result = RunTranslator(args);
        EXPECT_EQ(result.exitCode, 1) << command;
        // the body's language named, and what to write instead
        EXPECT_NE(result.output.find(xml + ":4:1: error: cannot read the PLCopen project: PLC_PRG is implemented in "
                                           "LD: pacst reads ST only; write its body in ST, or leave the POU out of "
                                           "the program tested"),
                  std::string::npos) << command << ": " << result.output;
        EXPECT_EQ(result.output.find("Traceback"), std::string::npos) << command << ": " << result.output;
    }
}

TEST_F(TranslatorUserCli, PlcopenRefusalInABodyIsAtTheXmlLine) {
    // A refusal in the ST of a PLCopen object names the XML file and the line CODESYS shows, not the ST file
    // pacst writes from it (one in a declaration: the next test).
    auto xml = Write("Project.xml", "<?xml version=\"1.0\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">\n"
                                    "<types><pous>\n<pou name=\"FB_A\" pouType=\"functionBlock\">\n"
                                    "<interface><localVars><variable name=\"n\"><type><INT/></type></variable>"
                                    "</localVars></interface>\n"
                                    "<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">n := n + 1;\n"
                                    "n := Nope;</xhtml></ST></body>\n<addData><data name=\"http://www.3s-software.com/"
                                    "plcopenxml/method\" handleUnknown=\"implementation\">\n<Method name=\"Step\">"
                                    "<interface/>\n<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">n := 1;\n"
                                    "n := Nowhere;</xhtml></ST></body></Method></data></addData>\n"
                                    "</pou>\n</pous></types></project>\n");
    auto result = RunTranslator({"build", "--user", "--sources", Out() + "/plcopen", "--out", Out(), xml});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(xml + ":7:6: error: undeclared name 'Nope' (in FB_A)"), std::string::npos)
        << result.output;
    // in a METHOD's body too, at its line (a TcUnit test's asserts are in METHODs)
    EXPECT_NE(result.output.find(xml + ":11:6: error: undeclared name 'Nowhere' (in FB_A)"), std::string::npos)
        << result.output;
    EXPECT_EQ(result.output.find("FB_A.st"), std::string::npos) << result.output;
}

TEST_F(TranslatorUserCli, PlcopenRefusalInADeclarationIsAtTheVariablesLine) {
    // A refused variable of a PLCopen object, of a POU's interface or of a global list, is named at its
    // <variable> element's line, as CODESYS shows the declaration, not at the object's first line.
    auto xml = Write("Project.xml", R"(<?xml version="1.0"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
<types><pous>
<pou name="FB_A" pouType="functionBlock">
<interface>
<localVars>
<variable name="n"><type><INT/></type></variable>
<variable name="t"><type><derived name="NoSuchType"/></type></variable>
</localVars>
<outputVars>
<variable name="s"><type><string length="70000"/></type></variable>
</outputVars>
</interface>
<body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">n := n + 1;</xhtml></ST></body>
</pou>
</pous></types>
<instances><configurations><configuration name="Device"><resource name="Application">
<globalVars name="GVL">
<variable name="Ok"><type><BOOL/></type></variable>
<variable name="Bad"><type><derived name="NoSuchList"/></type></variable>
</globalVars>
</resource></configuration></configurations></instances>
</project>
)");
    auto result = RunTranslator({"build", "--user", "--sources", Out() + "/plcopen", "--out", Out(), xml});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(xml + ":8:"), std::string::npos) << "the variable t: " << result.output;
    EXPECT_NE(result.output.find("undeclared type 'NoSuchType' (in FB_A)"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(xml + ":11:"), std::string::npos) << "the output s: " << result.output;
    EXPECT_NE(result.output.find(xml + ":20:"), std::string::npos) << "the list's Bad: " << result.output;
    EXPECT_EQ(result.output.find(xml + ":4:"), std::string::npos) << "not the POU's line: " << result.output;
    EXPECT_EQ(result.output.find(xml + ":18:"), std::string::npos) << "not the list's line: " << result.output;
}

TEST_F(TranslatorUserCli, PlcopenMethodsAndActionsAreRead) {
    // CODESYS keeps a POU's METHODs in its addData, PLCopen its ACTIONs in <actions>: both are translated.
    auto xml = Write("Fb.xml",
        "<?xml version=\"1.0\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">\n<types><pous>\n"
        "<pou name=\"FB_Axis\" pouType=\"functionBlock\"><interface><localVars><variable name=\"Pos\"><type><REAL/>"
        "</type></variable></localVars></interface>\n"
        "<actions><action name=\"Home\"><body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">Pos := 0.0;</xhtml>"
        "</ST></body></action></actions>\n"
        "<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">Pos := Pos;</xhtml></ST></body>\n<addData>"
        "<data name=\"http://www.3s-software.com/plcopenxml/method\" handleUnknown=\"implementation\">\n"
        "<Method name=\"Move\"><interface><returnType><BOOL/></returnType><inputVars><variable name=\"Target\">"
        "<type><REAL/></type></variable></inputVars></interface>\n<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">"
        "Pos := Target;\nMove := TRUE;</xhtml></ST></body></Method>\n</data></addData></pou>\n"
        "<pou name=\"PRG_Main\" pouType=\"program\"><interface><localVars><variable name=\"Axis\"><type>"
        "<derived name=\"FB_Axis\"/></type></variable><variable name=\"Ok\"><type><BOOL/></type></variable>"
        "</localVars></interface>\n<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">Ok := Axis.Move(Target := 2.0);\n"
        "Axis.Home();</xhtml></ST></body></pou>\n</pous></types></project>\n");
    auto result = RunTranslator({"build", "--user", "--sources", Out() + "/plcopen", "--out", Out(), xml});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(ReadFile(Out() + "/plcopen/FB_Axis.st").find("METHOD Move : BOOL"), std::string::npos);
}

TEST_F(TranslatorUserCli, PlcopenApplicationObjectsAreRead) {
    // CODESYS exports an application's PROGRAMs, lists and DUTs (with their attributes) into the resource's
    // addData, an FB's EXTENDS and IMPLEMENTS into its interface's, a list's CONSTANT block into its
    // MixedAttrsVarList, an array's initial values as an arrayValue, a PROPERTY in the FB's addData: they are read.
    auto xml = Write("App.xml",
        "<?xml version=\"1.0\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">\n<types><pous/></types>\n"
        "<instances><configurations><configuration name=\"Device\"><resource name=\"Application\"><addData>\n"
        "<data name=\"http://www.3s-software.com/plcopenxml/datatype\" handleUnknown=\"implementation\">\n"
        "<dataType name=\"E_State\"><baseType><enum><values><value name=\"IDLE\" value=\"0\"/><value name=\"RUN\" "
        "value=\"10\"/></values></enum></baseType><addData><data name=\"http://www.3s-software.com/plcopenxml/"
        "attributes\" handleUnknown=\"implementation\"><Attributes><Attribute Name=\"qualified_only\" Value=\"\"/>"
        "</Attributes></data></addData></dataType>\n</data>\n"
        "<data name=\"http://www.3s-software.com/plcopenxml/pou\" handleUnknown=\"implementation\">\n"
        "<pou name=\"FB_Base\" pouType=\"functionBlock\"><interface><outputVars><variable name=\"N\"><type><INT/>"
        "</type></variable></outputVars></interface><body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">N := N + 1;"
        "</xhtml></ST></body><addData><data name=\"http://www.3s-software.com/plcopenxml/property\" "
        "handleUnknown=\"implementation\"><Property name=\"Doubled\"><interface><returnType><INT/></returnType>"
        "</interface><GetAccessor><interface/><body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">Doubled := 2 * N;"
        "</xhtml></ST></body></GetAccessor></Property></data></addData></pou>\n</data>\n"
        "<data name=\"http://www.3s-software.com/plcopenxml/pou\" handleUnknown=\"implementation\">\n"
        "<pou name=\"FB_Twice\" pouType=\"functionBlock\"><interface><addData><data name=\"http://www.3s-software.com/"
        "plcopenxml/pouinheritance\" handleUnknown=\"implementation\"><Inheritance><Extends>FB_Base</Extends>"
        "</Inheritance></data></addData></interface><body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">"
        "SUPER^();\nSUPER^();</xhtml></ST></body></pou>\n</data>\n"
        "<data name=\"http://www.3s-software.com/plcopenxml/pou\" handleUnknown=\"implementation\">\n"
        "<pou name=\"PLC_PRG\" pouType=\"program\"><interface><localVars><variable name=\"N\"><type><INT/></type>"
        "</variable><variable name=\"State\"><type><derived name=\"E_State\"/></type></variable>"
        "<variable name=\"Percent\"><type><subrangeSigned><range lower=\"0\" upper=\"100\"/><baseType><INT/></baseType>"
        "</subrangeSigned></type></variable>"
        "<variable name=\"Table\"><type><array><dimension lower=\"0\" upper=\"3\"/><baseType><INT/></baseType></array>"
        "</type><initialValue><arrayValue><value><simpleValue value=\"1\"/></value><value repetitionValue=\"3\">"
        "<simpleValue value=\"7\"/></value></arrayValue></initialValue></variable><variable name=\"Twice\">"
        "<type><derived name=\"FB_Twice\"/></type></variable></localVars></interface><body><ST>"
        "<xhtml xmlns=\"http://www.w3.org/1999/xhtml\">Twice();\nN := Twice.Doubled;\nState := E_State.RUN;\n"
        "CASE N OF\n  GVL.MaxCount: N := 0;\nEND_CASE</xhtml></ST></body></pou>\n</data>\n</addData>\n"
        // a list of a VAR_GLOBAL and a VAR_GLOBAL CONSTANT block: CODESYS keeps the blocks in MixedAttrsVarList
        "<globalVars name=\"GVL\"><variable name=\"Count\"><type><INT/></type></variable><variable name=\"MaxCount\">"
        "<type><INT/></type><initialValue><simpleValue value=\"5\"/></initialValue></variable><addData><data "
        "name=\"http://www.3s-software.com/plcopenxml/mixedattrsvarlist\" handleUnknown=\"implementation\">"
        "<MixedAttrsVarList><globalVars name=\"GVL\"><variable name=\"Count\"><type><INT/></type></variable>"
        "</globalVars><globalVars name=\"GVL\" constant=\"true\"><variable name=\"MaxCount\"><type><INT/></type>"
        "<initialValue><simpleValue value=\"5\"/></initialValue></variable></globalVars></MixedAttrsVarList></data>"
        "</addData></globalVars>\n</resource></configuration></configurations></instances>\n</project>\n");
    auto sources = Out() + "/plcopen";
    auto result = RunTranslator({"build", "--user", "--sources", sources, "--out", Out(), xml});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(fs::exists(sources + "/PLC_PRG.st")) << "the application's PROGRAM";
    EXPECT_NE(ReadFile(sources + "/E_State.st").find("{attribute 'qualified_only'}"), std::string::npos);
    EXPECT_NE(ReadFile(sources + "/FB_Twice.st").find("FUNCTION_BLOCK FB_Twice EXTENDS FB_Base"), std::string::npos);
    EXPECT_NE(ReadFile(sources + "/GVL.st").find("VAR_GLOBAL CONSTANT\n  MaxCount : INT := 5;"), std::string::npos);
    EXPECT_NE(ReadFile(sources + "/PLC_PRG.st").find("Table : ARRAY[0..3] OF INT := [1, 3(7)];"), std::string::npos);
    EXPECT_NE(ReadFile(sources + "/PLC_PRG.st").find("Percent : INT(0..100);"), std::string::npos);
}

TEST_F(TranslatorUserCli, PlcopenVariableLengthArrayIsRead) {
    // CODESYS exports a VAR_IN_OUT's ARRAY[*] OF T as a POINTER TO T among the inputs, the array's type and its list
    // kept in attributes: it is read back as the VAR_IN_OUT it was, in the list's order. One CODESYS wrote from a
    // VAR_INPUT, exported the same way, is read as a VAR_IN_OUT too (docs/open_points.md); one from another list is
    // refused at the variable's line, saying where pacst takes it.
    auto varlen = [](const char* name, const char* scope) {
        return std::string("<variable name=\"") + name + "\"><type><pointer><baseType><LREAL/></baseType></pointer></type>"
               "<addData><data name=\"http://www.3s-software.com/plcopenxml/attributes\" handleUnknown=\"implementation\">"
               "<Attributes><Attribute Name=\"variable_length_array_original_scope\" Value=\"" + scope + "\"/>"
               "<Attribute Name=\"variable_length_array\" Value=\"ARRAY[*] OF LREAL\"/><Attribute Name=\"Dimensions\" "
               "Value=\"1\"/></Attributes></data></addData></variable>\n";
    };
    auto function = [&](const char* name, const char* scope) {
        return std::string("<pou name=\"") + name + "\" pouType=\"function\"><interface><returnType><LREAL/></returnType>"
               "<inputVars><variable name=\"Scale\"><type><LREAL/></type></variable>\n" + varlen("Values", scope) +
               "</inputVars><localVars><variable name=\"i\"><type><DINT/></type></variable></localVars></interface>\n"
               "<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">FOR i := LOWER_BOUND(Values, 1) TO "
               "UPPER_BOUND(Values, 1) DO\n  " + name + " := " + name + " + Scale * Values[i];\nEND_FOR;</xhtml></ST></body></pou>\n";
    };
    const std::string head = "<?xml version=\"1.0\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">\n<types><pous>\n";
    // the program passes an array of its own to the VAR_IN_OUT, by position after the input before it
    const std::string program =
        "<pou name=\"PRG_Main\" pouType=\"program\"><interface><localVars><variable name=\"Data\"><type><array>"
        "<dimension lower=\"1\" upper=\"3\"/><baseType><LREAL/></baseType></array></type></variable><variable "
        "name=\"Total\"><type><LREAL/></type></variable></localVars></interface>\n<body><ST><xhtml "
        "xmlns=\"http://www.w3.org/1999/xhtml\">Total := F_Sum(2.0, Data);</xhtml></ST></body></pou>\n";
    auto sources = Out() + "/plcopen";
    auto xml = Write("Varlen.xml", head + function("F_Sum", "Inout") + program + "</pous></types></project>\n");
    auto result = RunTranslator({"build", "--user", "--sources", sources, "--out", Out(), xml});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(ReadFile(sources + "/F_Sum.st").find("VAR_INPUT\n  Scale : LREAL;\nEND_VAR\nVAR_IN_OUT\n  Values : "
                                                  "ARRAY[*] OF LREAL;\nEND_VAR\n"), std::string::npos)
        << ReadFile(sources + "/F_Sum.st");
    auto input = Write("Input.xml", head + function("F_Sum", "Input") + program + "</pous></types></project>\n");
    result = RunTranslator({"build", "--user", "--sources", sources, "--out", Out(), input});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(ReadFile(sources + "/F_Sum.st").find("END_VAR\nVAR_IN_OUT\n  Values : ARRAY[*] OF LREAL;\nEND_VAR\n"),
              std::string::npos) << ReadFile(sources + "/F_Sum.st");
    auto output = Write("Output.xml", head + function("F_Sum", "Output") + "</pous></types></project>\n");
    result = RunTranslator({"build", "--user", "--sources", sources, "--out", Out(), output});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(output + ":5:1: error: cannot read the PLCopen project: F_Sum: Values: an ARRAY[*] OF "
                                          "LREAL in the list CODESYS calls 'Output' is not read: pacst takes an "
                                          "ARRAY[*] in VAR_IN_OUT (or VAR_INPUT) only; declare it there"),
              std::string::npos) << result.output;
}

TEST_F(TranslatorUserCli, PlcopenExportWithTheLibraryTakesTheLibraryGiven) {
    // CODESYS's export "into an application" carries the referenced library's objects: where it holds most of a
    // library given under its namespace, they are left out with one warning, not refused one by one.
    fs::create_directories(dir_ / "lib");
    auto lamp = Write("lib/FB_Lamp.st", "FUNCTION_BLOCK FB_Lamp\nVAR_INPUT On : BOOL; END_VAR\nVAR_OUTPUT Lit : BOOL; "
                                        "END_VAR\nLit := On;\nEND_FUNCTION_BLOCK\n");
    auto list = Write("lib/GVL_Lib.st", "VAR_GLOBAL CONSTANT\n  K_ON : BOOL := TRUE;\nEND_VAR\n");
    const std::string st = "<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">";
    auto xml = Write("App.xml",
        "<?xml version=\"1.0\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">\n<types><dataTypes/><pous>\n"
        "<pou name=\"FB_Lamp\" pouType=\"functionBlock\"><interface><inputVars><variable name=\"On\"><type><BOOL/>"
        "</type></variable></inputVars><outputVars><variable name=\"Lit\"><type><BOOL/></type></variable></outputVars>"
        "</interface>" + st + "Lit := On;</xhtml></ST></body></pou>\n"
        "<pou name=\"PLC_PRG\" pouType=\"program\"><interface><localVars><variable name=\"Lamp\"><type>"
        "<derived name=\"PA_CONTROL.FB_Lamp\"/></type></variable></localVars></interface>" + st +
        "Lamp(On := PA_CONTROL.GVL_Lib.K_ON);</xhtml></ST></body></pou>\n</pous></types>\n</project>\n");
    const std::string ns = "PA_CONTROL=" + fs::path(lamp).parent_path().string();
    auto result = RunTranslator({"build", "--user", "--namespace", ns, "--sources", Out() + "/plcopen", "--out", Out(),
                                 lamp, list, xml});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("pacst: warning: " + xml + ": the export holds 1 of the 2 objects of the library "
                                 "PA_CONTROL (FB_Lamp)"), std::string::npos) << result.output;
}

TEST_F(TranslatorUserCli, PlcopenObjectsNotReadAreRefusedAtTheirLines) {
    // A part of an object the reader does not translate (an INTERFACE's PROPERTY, whose form no export has shown)
    // is refused at its element, not dropped; so is a global list it cannot read, at the list's element: both in
    // one run.
    auto xml = Write("App.xml",
        "<?xml version=\"1.0\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">\n<types><pous/></types>\n"
        "<instances><configurations><configuration name=\"Device\"><resource name=\"Application\">\n"
        "<globalVars name=\"GVL\">\n<variable name=\"P\"><type><struct><variable name=\"A\"><type><INT/></type>"
        "</variable></struct></type>"
        "</variable></globalVars>\n</resource></configuration></configurations></instances>\n<addData>\n"
        "<data name=\"http://www.3s-software.com/plcopenxml/interface\" handleUnknown=\"implementation\">\n"
        "<Interface name=\"I_Run\">\n<Properties/></Interface></data></addData>\n</project>\n");
    auto result = RunTranslator({"check", "--user", xml});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(xml + ":5:1: error: cannot read the PLCopen project: GVL: type element <struct> "
                                        "has no ST form in this reader"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(xml + ":11:1: error: cannot read the PLCopen project: I_Run: <Properties> of an INTERFACE "
                                        "is not read from PLCopen XML"), std::string::npos) << result.output;
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
    auto fb = Write("FB_Counter.st", kCounter);
    ASSERT_EQ(RunTranslator({"build", "--out", Out(), fb}).exitCode, 0);
    EXPECT_FALSE(Generated("symbols.json"));
    ASSERT_EQ(RunTranslator({"build", "--user", "--out", Out(), fb}).exitCode, 0);
    EXPECT_TRUE(Generated("symbols.json"));
}

TEST_F(TranslatorUserCli, NativeNeedsUserMode) {
    auto native = Write("Asserts.st", "FUNCTION AssertTrue\nVAR_INPUT C : BOOL; END_VAR\n;\nEND_FUNCTION\n");
    auto fb = Write("FB_Counter.st", kCounter);
    auto result = RunTranslator({"build", "--native", native, "--out", Out(), fb});
    EXPECT_NE(result.exitCode, 0);
    EXPECT_NE(result.output.find("need --user"), std::string::npos) << result.output;
    result = RunTranslator({"build", "--user", "--native", native, "--out", Out(), fb});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_FALSE(Generated("Asserts.c")) << "the host implements a native FUNCTION";
}

TEST_F(TranslatorUserCli, LibraryConstantListIsAGlobalListOfUserPrograms) {
    // As the library's GVL_PAC: checked against the POUs' own copies (--gvl) and read by the user's PROGRAM.
    auto list = Write("GVL_K.st", "VAR_GLOBAL CONSTANT\n  K_STOP : WORD := WORD#16#0600;\nEND_VAR\n");
    auto fb = Write("FB_Lib.st", "FUNCTION_BLOCK FB_Lib\nVAR_OUTPUT W : WORD; END_VAR\n"
                                 "VAR CONSTANT K_STOP : WORD := WORD#16#0600; END_VAR\nW := K_STOP;\n"
                                 "END_FUNCTION_BLOCK\n");
    auto main = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR A : WORD; B : WORD; END_VAR\nA := K_STOP;\n"
                                     "B := GVL_K.K_STOP;\nEND_PROGRAM\n");
    auto result = RunTranslator({"build", "--user", "--gvl", list, "--out", Out(), list, fb, main});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(Generated("GVL_K.h")) << "the constants table";
    EXPECT_TRUE(Generated("GVL_K.c")) << "the list's globals";
}

std::string ReadFile(const fs::path& path) {
    std::ifstream in(path);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string TcObject(const std::string& element, const std::string& name, const std::string& declaration,
                     const std::string& body) {
    std::string text = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\r\n"
                       "<TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4024.12\">\r\n"
                       "  <" + element + " Name=\"" + name + "\" Id=\"{0}\">\r\n"
                       "    <Declaration><![CDATA[" + declaration + "]]></Declaration>\r\n";
    if (!body.empty()) {
        text += "    <Implementation>\r\n      <ST><![CDATA[" + body + "]]></ST>\r\n    </Implementation>\r\n";
    }
    return text + "  </" + element + ">\r\n</TcPlcObject>\r\n";
}

const char* kTcMainDeclaration = "PROGRAM MAIN\r\nVAR\r\n  Count : INT; // TwinCAT's comments\r\nEND_VAR\r\n";

TEST_F(TranslatorUserCli, TwinCatFilesAreReadWithTheirOwnLinesAndColumns) {
    fs::create_directories(dir_ / "POUs");
    fs::create_directories(dir_ / "GVLs");
    fs::create_directories(dir_ / "DUTs");
    auto list = Write("GVLs/GVL_Io.TcGVL",
                      TcObject("GVL", "GVL_Io", "{attribute 'qualified_only'}\r\nVAR_GLOBAL\r\n"
                                                "  MaxCount : INT := 3;\r\n  Where : ST_Point;\r\nEND_VAR\r\n", ""));
    // TwinCAT writes END_STRUCT without ';'.
    Write("DUTs/ST_Point.TcDUT", TcObject("DUT", "ST_Point", "TYPE ST_Point :\r\nSTRUCT\r\n  X : INT;\r\nEND_STRUCT\r\n"
                                                            "END_TYPE\r\n", ""));
    // Line 11 of the file (the body's CDATA opens on line 10), column 12: the undeclared name.
    auto main = Write("POUs/MAIN.TcPOU", TcObject("POU", "MAIN", kTcMainDeclaration,
                                                  "IF Count < GVL_Io.MaxCount THEN\r\n  Count := Nope;\r\nEND_IF"));
    auto result = RunTranslator({"build", "--user", "--line-directives", "--out", Out(), list, main});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(main + ":11:12: error: undeclared name 'Nope'"), std::string::npos) << result.output;

    main = Write("POUs/MAIN.TcPOU", TcObject("POU", "MAIN", kTcMainDeclaration,
                                             "IF Count < GVL_Io.MaxCount THEN\r\n  Count := Count + 1;\r\nEND_IF\r\n"
                                             "GVL_Io.Where.X := Count;"));
    auto project = Write("Plant.plcproj",
                         "<?xml version=\"1.0\" encoding=\"utf-8\"?>\r\n"
                         "<Project xmlns=\"http://schemas.microsoft.com/developer/msbuild/2003\">\r\n  <ItemGroup>\r\n"
                         "    <Compile Include=\"POUs\\MAIN.TcPOU\"><SubType>Code</SubType></Compile>\r\n"
                         "    <Compile Include=\"GVLs\\GVL_Io.TcGVL\"><SubType>Code</SubType></Compile>\r\n"
                         "    <Compile Include=\"DUTs\\ST_Point.TcDUT\"><SubType>Code</SubType></Compile>\r\n"
                         "    <None Include=\"PlcTask.TcTTO\"><SubType>Code</SubType></None>\r\n"
                         "  </ItemGroup>\r\n</Project>\r\n");
    result = RunTranslator({"build", "--user", "--line-directives", "--out", Out(), project});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::ifstream c(dir_ / "out" / "MAIN.c");
    std::string text((std::istreambuf_iterator<char>(c)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("#line 10 \"" + fs::absolute(main).string() + "\""), std::string::npos) << text;
    EXPECT_TRUE(Generated("GVL_Io.c"));
    EXPECT_NE(ReadFile(dir_ / "out" / "POUS.h").find("} ST_POINT;"), std::string::npos) << "the .TcDUT's STRUCT";
}

TEST_F(TranslatorUserCli, TwinCatMethodsAreReadAtTheirLines) {
    // A .TcPOU's <Method> and <Action> elements: translated, their errors at the line in the TwinCAT file.
    auto fb = Write("FB_A.TcPOU",
                    "<?xml version=\"1.0\"?>\n<TcPlcObject>\n  <POU Name=\"FB_A\">\n"
                    "    <Declaration><![CDATA[FUNCTION_BLOCK FB_A\nVAR N : INT; END_VAR\n]]></Declaration>\n"
                    "    <Implementation><ST><![CDATA[Reset();]]></ST></Implementation>\n"
                    "    <Method Name=\"Reset\">\n      <Declaration><![CDATA[METHOD Reset\n]]></Declaration>\n"
                    "      <Implementation>\n        <ST><![CDATA[N := 0;\nCount();]]></ST>\n      </Implementation>\n"
                    "    </Method>\n    <Action Name=\"Count\">\n      <Implementation>\n"
                    "        <ST><![CDATA[N := N + 1;]]></ST>\n      </Implementation>\n    </Action>\n"
                    "  </POU>\n</TcPlcObject>\n");
    auto result = RunTranslator({"build", "--user", "--out", Out(), fb});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    auto bad = Write("FB_A.TcPOU", ReadFile(fb).replace(ReadFile(fb).find("Count();"), 8, "Cont(); "));
    result = RunTranslator({"check", "--user", bad});
    EXPECT_NE(result.output.find(bad + ":13:1: error: undeclared function, METHOD, ACTION or function block instance 'Cont'"), std::string::npos) << result.output;
}

TEST_F(TranslatorUserCli, TwinCatPropertyWithALongHeadingOnTheLineOfItsGet) {
    // FsCommon's P_GetSystemInformation: the declaration's CDATA closes on the PROPERTY's line, and the heading pacst
    // writes for the Get (PROPERTY Name.Get : Type) is longer than the <Get ...> tag: it takes the blanks before the
    // tag too, after the END_PROPERTY of the declaration.
    const std::string getTag = "      <Get Name=\"Get\" Id=\"{520417e0-26ec-0961-2c1d-de4d1180fee7}\">\n";
    auto fb = Write("FB_Info.TcPOU",
                    "<?xml version=\"1.0\"?>\n<TcPlcObject>\n  <POU Name=\"FB_Info\">\n"
                    "    <Declaration><![CDATA[FUNCTION_BLOCK FB_Info\nVAR N : UDINT; END_VAR\n]]></Declaration>\n"
                    "    <Implementation><ST><![CDATA[N := N + 1;]]></ST></Implementation>\n"
                    "    <Property Name=\"ProcessorArchitecture\" Id=\"{6b336d92-e78b-0b30-0721-8bc6141fb57c}\">\n"
                    "      <Declaration><![CDATA[PROPERTY ProcessorArchitecture : E_ProcessorArchitecture]]></Declaration>\n" +
                        getTag +
                    "        <Declaration><![CDATA[VAR\nEND_VAR\n]]></Declaration>\n"
                    "        <Implementation>\n"
                    "          <ST><![CDATA[ProcessorArchitecture := UDINT_TO_BYTE(N);]]></ST>\n"
                    "        </Implementation>\n      </Get>\n    </Property>\n  </POU>\n</TcPlcObject>\n");
    auto type = Write("E_ProcessorArchitecture.st", "TYPE E_ProcessorArchitecture : (X86, ARM) BYTE;\nEND_TYPE\n");
    auto result = RunTranslator({"build", "--user", "--out", Out(), type, fb});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    auto bad = Write("FB_Info.TcPOU", ReadFile(fb).replace(ReadFile(fb).find("UDINT_TO_BYTE(N)"), 16, "UDINT_TO_BYTE(M)"));
    result = RunTranslator({"check", "--user", type, bad});
    EXPECT_NE(result.output.find(bad + ":15:63: error: undeclared name 'M'"), std::string::npos) << result.output;
}

TEST_F(TranslatorUserCli, TwinCatTransitionsAndOtherLanguagesAreRefused) {
    auto method = Write("FB_A.TcPOU",
                        "<?xml version=\"1.0\"?>\n<TcPlcObject>\n  <POU Name=\"FB_A\">\n"
                        "    <Declaration><![CDATA[FUNCTION_BLOCK FB_A\n]]></Declaration>\n"
                        "    <Implementation><ST><![CDATA[;]]></ST></Implementation>\n"
                        "    <Transition Name=\"Ready\">\n    </Transition>\n  </POU>\n</TcPlcObject>\n");
    auto result = RunTranslator({"check", "--user", method});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(method + ":7:1: error: TRANSITION Ready of FB_A is outside pacst's user programs"),
              std::string::npos)
        << result.output;
    auto ladder = Write("FB_B.TcPOU",
                        "<?xml version=\"1.0\"?>\n<TcPlcObject>\n  <POU Name=\"FB_B\">\n"
                        "    <Declaration><![CDATA[FUNCTION_BLOCK FB_B\n]]></Declaration>\n"
                        "    <Implementation>\n      <LD></LD>\n    </Implementation>\n  </POU>\n</TcPlcObject>\n");
    result = RunTranslator({"check", "--user", ladder});
    EXPECT_NE(result.output.find(ladder + ":7:1: error: FB_B is implemented in LD: pacst reads ST only"),
              std::string::npos)
        << result.output;
    // TwinCAT keeps LD, FBD and IL as a network list: the refusal says which languages, and what to do
    auto network = Write("FB_C.TcPOU",
                         "<?xml version=\"1.0\"?>\n<TcPlcObject>\n  <POU Name=\"FB_C\">\n"
                         "    <Declaration><![CDATA[FUNCTION_BLOCK FB_C\n]]></Declaration>\n"
                         "    <Implementation>\n      <NWL></NWL>\n    </Implementation>\n  </POU>\n</TcPlcObject>\n");
    result = RunTranslator({"check", "--user", network});
    EXPECT_NE(result.output.find(network + ":7:1: error: FB_C is implemented in a network list (LD, FBD or IL): "
                                           "pacst reads ST only; write its body in ST, or leave the POU out of the "
                                           "program tested"),
              std::string::npos)
        << result.output;
}

TEST_F(TranslatorUserCli, PlcopenProjectIsReadIntoStFiles) {
    auto project = Write("plant.xml", R"(<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <types><dataTypes/><pous>
    <pou name="PRG_Main" pouType="program">
      <interface><localVars><variable name="Count"><type><INT/></type></variable></localVars></interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">IF GVL_Io.Start THEN
  Count := Count + 1;
END_IF;</xhtml></ST></body>
    </pou>
  </pous></types>
  <addData><data name="http://www.3s-software.com/plcopenxml/globalvars" handleUnknown="implementation">
    <globalVars name="GVL_Io">
      <variable name="Start" address="%IX0.1"><type><BOOL/></type></variable>
      <variable name="Image" address="%IB2"><type>
        <array><dimension lower="0" upper="3"/><baseType><BYTE/></baseType></array>
      </type></variable>
    </globalVars>
  </data></addData>
</project>
)");
    auto sources = (dir_ / "sources").string();
    auto result = RunTranslator({"build", "--user", "--sources", sources, "--out", Out(), project});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(fs::exists(dir_ / "sources" / "PRG_Main.st"));
    EXPECT_TRUE(fs::exists(dir_ / "sources" / "GVL_Io.st"));
    std::ifstream symbols(dir_ / "out" / "symbols.json");
    std::string text((std::istreambuf_iterator<char>(symbols)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\"path\": \"GVL_Io.Image\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"address\": \"%IB2\""), std::string::npos) << text;
}


TEST_F(TranslatorUserCli, MatiecSourceHasTheConfigurationTasksAndExternals) {
    auto a = Write("GVL_A.st", "VAR_GLOBAL\n  Count : INT;\n  Image AT %IB0 : ARRAY [0..3] OF BYTE;\nEND_VAR\n");
    auto b = Write("GVL_B.st", "VAR_GLOBAL\n  Count : INT := 7;\nEND_VAR\n");
    auto main = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR N : INT; Flag AT %MX0.1 : BOOL; END_VAR\n"
                                     "N := GVL_B.Count + GVL_A.Count;\nImage[1] := BYTE#2;\nEND_PROGRAM\n");
    auto tasks = Write("tasks.json", R"({"PRG_Main": {"task": "Fast", "interval": "T#5MS", "priority": 3}})");
    auto out = (dir_ / "out" / "user.st").string();
    auto result = RunTranslator({"matiec", "--tasks", tasks, "--out", out, main, b, a});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const std::string st = ReadFile(out);
    for (const char* want : {
             "VAR\n  N : INT;\nEND_VAR\nVAR\n  Flag AT %MX0.1 : BOOL;\nEND_VAR\n",  // located: a block of its own
             "VAR_EXTERNAL\n  GVL_B_Count : INT;\n  GVL_A_Count : INT;\n  Image : T_PacArray_BYTE_0_3;\nEND_VAR\n",
             "N := GVL_B_Count + GVL_A_Count;\nImage[1] := BYTE#2;\nEND_PROGRAM",  // qualifiers spelled MATIEC's way
             "TYPE T_PacArray_BYTE_0_3 : ARRAY [0..3] OF BYTE;\nEND_TYPE",
             "CONFIGURATION PacConfig\n  VAR_GLOBAL\n",
             "    GVL_B_Count : INT := 7;\n",
             "    Image AT %IB0 : T_PacArray_BYTE_0_3;\n",
             "  RESOURCE PacResource ON PLC\n    TASK Fast(INTERVAL := T#5MS, PRIORITY := 3);\n"
             "    PROGRAM Inst_PRG_Main WITH Fast : PRG_Main;\n  END_RESOURCE\nEND_CONFIGURATION\n"}) {
        EXPECT_NE(st.find(want), std::string::npos) << "missing:\n" << want << "\nin:\n" << st;
    }
}

// A native FUNCTION (the host's C, as pac-test's asserts) goes to MATIEC as its interface, a local variable where
// it has none (MATIEC parses no FUNCTION without a variable block); --line-map says where each body came from.
TEST_F(TranslatorUserCli, MatiecWritesNativesAsInterfacesAndMapsTheBodies) {
    auto check = Write("F_Check.st", "FUNCTION F_Check : BOOL\nVAR_INPUT\n  C : BOOL;\nEND_VAR\nF_Check := C;\n"
                                     "END_FUNCTION\n");
    auto done = Write("F_Done.st", "FUNCTION F_Done : BOOL\nF_Done := TRUE;\nEND_FUNCTION\n");
    auto main = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR N : INT; END_VAR\nN := N + 1;\nF_Check(C := N > 2);\n"
                                     "F_Done();\nEND_PROGRAM\n");
    auto out = (dir_ / "out" / "user.st").string();
    auto map = (dir_ / "out" / "lines.json").string();
    auto result = RunTranslator({"matiec", "--out", out, "--line-map", map, "--native", check, "--native", done, main});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const std::string st = ReadFile(out);
    for (const char* want : {
             "FUNCTION F_Check : BOOL\nVAR_INPUT\n  C : BOOL;\nEND_VAR\nF_Check := F_Check;\nEND_FUNCTION",
             "FUNCTION F_Done : BOOL\nVAR\n  PacUnused : BOOL;\nEND_VAR\nF_Done := F_Done;\nEND_FUNCTION",
             "N := N + 1;\nF_Check(C := N > 2);\nF_Done();\nEND_PROGRAM"}) {
        EXPECT_NE(st.find(want), std::string::npos) << "missing:\n" << want << "\nin:\n" << st;
    }
    // PRG_Main's body starts at its line 3; the map gives the line of user.st where that line is
    const auto at = st.find("N := N + 1;");
    ASSERT_NE(at, std::string::npos) << st;
    const auto line = 1 + std::count(st.begin(), st.begin() + static_cast<std::ptrdiff_t>(at), '\n');
    const std::string entry = "[\n" + std::to_string(line) + ",\n\"" + main + "\",\n3\n]";
    EXPECT_NE(ReadFile(map).find(entry), std::string::npos) << entry << "\nin:\n" << ReadFile(map);
}

TEST_F(TranslatorUserCli, MatiecRefusesAFunctionThatReadsGlobals) {
    auto list = Write("GVL_A.st", "VAR_GLOBAL\n  Factor : INT := 3;\nEND_VAR\n");
    auto scale = Write("F_Scale.st", "FUNCTION F_Scale : INT\nVAR_INPUT Raw : INT; END_VAR\nF_Scale := Raw * Factor;\n"
                                     "END_FUNCTION\n");
    auto result = RunTranslator({"check", "--user", list, scale});
    EXPECT_EQ(result.exitCode, 0) << "pacst itself accepts it (CODESYS and TwinCAT do): " << result.output;
    result = RunTranslator({"matiec", "--out", (dir_ / "out" / "user.st").string(), list, scale});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(scale + ":1:1: error: FUNCTION F_Scale uses global variables: MATIEC's FUNCTIONs "
                                         "have no VAR_EXTERNAL"),
              std::string::npos)
        << result.output;
}

TEST_F(TranslatorUserCli, LibraryOfTheProgramsOwnFromPlcopen) {
    // A library of the program's own given as a PLCopen XML project (--library NAME=PATH): its objects written to
    // the --sources folder's NAME/ and held by the namespace NAME; a refusal in it named at the XML file's line.
    const std::string lamp =
        "<?xml version=\"1.0\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">\n<types><pous>\n"
        "<pou name=\"FB_Blink\" pouType=\"functionBlock\">\n<interface><outputVars><variable name=\"Lit\"><type><BOOL/>"
        "</type></variable></outputVars></interface>\n"
        "<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">Lit := NOT Lit;\nLit := BODY;</xhtml></ST></body>\n"
        "</pou>\n</pous></types></project>\n";
    auto main = Write("PRG_Main.st", "PROGRAM PRG_Main\nVAR\n  Blink : Lamps.FB_Blink;\n  On : BOOL;\nEND_VAR\n"
                                     "Blink();\nOn := Blink.Lit;\nEND_PROGRAM\n");
    auto xml = Write("Lamps.xml", std::string(lamp).replace(lamp.find("\nLit := BODY;"), 13, ""));
    const std::string sources = Out() + "/plcopen";
    auto result = RunTranslator({"build", "--user", "--library", "Lamps=" + xml, "--sources", sources, "--out", Out(),
                                 main});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(fs::exists(sources + "/Lamps/FB_Blink.st"));
    result = RunTranslator({"check", "--user", main});
    EXPECT_NE(result.output.find(main + ":3:11: error: 'Lamps.FB_Blink': 'Lamps' is no library namespace"),
              std::string::npos) << result.output;
    auto broken = Write("Broken.xml", lamp);
    result = RunTranslator({"check", "--user", "--library", "Lamps=" + broken, "--sources", sources, main});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(broken + ":7:8: error: undeclared name 'BODY' (in FB_Blink)"), std::string::npos)
        << result.output;
    result = RunTranslator({"check", "--user", "--library", "Lamps=" + xml, "--library", "LAMPS=" + broken, main});
    EXPECT_NE(result.output.find("pacst: --library LAMPS: the namespace LAMPS is given twice, also by --library Lamps"),
              std::string::npos) << result.output;
    result = RunTranslator({"check", "--library", "Lamps=" + xml, main});
    EXPECT_NE(result.output.find("need --user"), std::string::npos) << result.output;
}

}  // namespace
