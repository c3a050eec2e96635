// pac_scenario's command line: exit code 0 when every expectation is met, 1 when one failed, 2 for a
// refused scenario (the reason on stderr) or bad usage. The process itself is run as well as RunCli,
// so the exit codes are the ones a shell or CI sees, and a copy of it runs away from the source and
// build trees, which it does not need.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.hpp"

namespace {

using pac::scenario::RunCli;

const std::string kDemo = std::string(PAC_SCENARIO_DIR) + "/demo.json";

// ctest runs tests in parallel processes: every file a test writes carries the test's name.
std::string TestName() { return testing::UnitTest::GetInstance()->current_test_info()->name(); }

std::string TempFile(const std::string& name, const std::string& text) {
    const std::string path = testing::TempDir() + "/" + TestName() + "-" + name;
    std::ofstream(path) << text;
    return path;
}

std::string ReadFile(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

struct Process {
    int exitCode = -1;
    std::string out;
    std::string err;
};

std::string Quoted(const std::string& word) { return "'" + word + "'"; }

// Runs `command` in a shell (words already quoted where needed) and keeps its output.
Process RunShell(const std::string& command) {
    const std::string out = testing::TempDir() + "/" + TestName() + ".out";
    const std::string err = testing::TempDir() + "/" + TestName() + ".err";
    const int status = std::system((command + " >" + Quoted(out) + " 2>" + Quoted(err)).c_str());
    Process result;
    if (status != -1 && WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    result.out = ReadFile(out);
    result.err = ReadFile(err);
    return result;
}

// Runs the pac_scenario binary with `args` (shell words, already quoted where needed).
Process RunBinary(const std::string& args) { return RunShell(Quoted(PAC_SCENARIO_BINARY) + " " + args); }

// A folder of the test's own holding a copy of the pac_scenario binary and of the demo.
std::string CopyBinaryAndDemo() {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(testing::TempDir()) / (TestName() + "-copy");
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy_file(PAC_SCENARIO_BINARY, dir / "pac_scenario");
    fs::copy_file(kDemo, dir / "demo.json");
    return dir.string();
}

bool IsWithin(const std::filesystem::path& path, const std::filesystem::path& folder) {
    const auto relative = std::filesystem::weakly_canonical(path).lexically_relative(std::filesystem::weakly_canonical(folder));
    return !relative.empty() && *relative.begin() != "..";
}

const std::string kDemoResult = "Result: 16 steps, 7 commands, 2 mode requests, 5 axis jobs: all expectations met";

struct Cli {
    explicit Cli(const std::vector<std::string>& args) { exitCode = RunCli(args, out, err); }
    int exitCode;
    std::ostringstream out;
    std::ostringstream err;
};

TEST(ScenarioCli, DemoExitsZero) {
    const Process run = RunBinary("'" + kDemo + "'");
    EXPECT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_EQ(run.err, "");
    EXPECT_NE(run.out.find(kDemoResult), std::string::npos) << run.out;
}

TEST(ScenarioCli, ACopyInAnotherFolderRunsTheDemo) {
    const std::string dir = CopyBinaryAndDemo();
    const Process run = RunShell("cd " + Quoted(dir) + " && ./pac_scenario demo.json");
    EXPECT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_EQ(run.err, "");
    EXPECT_NE(run.out.find(kDemoResult), std::string::npos) << run.out;
}

// The copy again, with the source and build trees hidden under empty file systems in a mount namespace
// of its own (unshare, where the kernel lets an unprivileged user have one): it reads no file there.
TEST(ScenarioCli, ACopyRunsWithTheSourceAndBuildTreesHidden) {
    const std::string dir = CopyBinaryAndDemo();
    std::string hidden = Quoted(PAC_SOURCE_DIR);
    if (!IsWithin(PAC_BINARY_DIR, PAC_SOURCE_DIR)) hidden += " " + Quoted(PAC_BINARY_DIR);
    if (IsWithin(dir, PAC_SOURCE_DIR) || IsWithin(dir, PAC_BINARY_DIR)) {
        GTEST_SKIP() << "the temporary folder " << dir << " lies in a tree the test hides";
    }
    // sh -c SCRIPT $0 TREE...: the trees are hidden, then SCRIPT's tail runs on $0.
    const auto inSandbox = [&](const std::string& tail, const std::string& zero) {
        return RunShell("unshare --user --map-root-user --mount sh -c "
                        "'for tree; do mount -t tmpfs tmpfs \"$tree\" || exit 99; done; " +
                        tail + "' " + Quoted(zero) + " " + hidden);
    };
    const Process probe = inSandbox("test ! -e \"$0\"", PAC_SCENARIO_BINARY);
    if (probe.exitCode != 0) GTEST_SKIP() << "no mount namespace to hide the trees in: " << probe.err;

    const Process run = inSandbox("cd \"$0\" && exec ./pac_scenario demo.json", dir);
    EXPECT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_EQ(run.err, "");
    EXPECT_NE(run.out.find(kDemoResult), std::string::npos) << run.out;
}

TEST(ScenarioCli, FailedExpectationExitsOne) {
    const std::string path = TempFile("failing.json", R"({"timing": {"boot_ms": 0}, "steps": [
        {"command": "PAC_CMD_GET_INT_REG", "param": 2000, "expect": {"done": true}}]})");
    const Process run = RunBinary("'" + path + "'");
    EXPECT_EQ(run.exitCode, 1) << run.out << run.err;
    EXPECT_NE(run.out.find("  => FAILED: Done is FALSE, expected TRUE\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("Result: 1 step, 1 command: 1 step FAILED (step 1)"), std::string::npos) << run.out;
    EXPECT_EQ(Cli({path}).exitCode, pac::scenario::kExitExpectationFailed);
}

TEST(ScenarioCli, InvalidScenarioExitsTwoWithTheReason) {
    const std::string path = TempFile("invalid.json", R"({"steps": [{"command": "0906", "param": 70000}]})");
    const Process run = RunBinary("'" + path + "'");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(run.err, "pac_scenario: invalid scenario " + path +
                           ": $.steps[0].param: out of range: 70000 is not in 0..65535\n");

    const Cli cli({TempFile("bad-name.json", R"({"steps": [{"command": "PAC_CMD_NOPE"}]})")});
    EXPECT_EQ(cli.exitCode, pac::scenario::kExitRefused);
    EXPECT_NE(cli.err.str().find(R"($.steps[0].command: unknown command name "PAC_CMD_NOPE")"), std::string::npos)
        << cli.err.str();
}

TEST(ScenarioCli, ASetupTheSimulatorRejectsExitsTwoBeforeAnyOutput) {
    const Cli cli({TempFile("bad-parameter.json",
                            R"({"controller": {"system_parameters": {"60000": 1}}, "steps": [{"wait_ms": 1}]})")});
    EXPECT_EQ(cli.exitCode, pac::scenario::kExitRefused);
    EXPECT_EQ(cli.out.str(), "");
    EXPECT_NE(cli.err.str().find(R"($.controller.system_parameters["60000"]: refused by the simulated PA-CONTROL)"),
              std::string::npos)
        << cli.err.str();
}

TEST(ScenarioCli, CheckOnlyValidates) {
    const Process run = RunBinary("--check '" + kDemo + "'");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.out, kDemo + ": valid scenario, 16 steps\n");
    EXPECT_EQ(Cli({"--check", TempFile("bad.json", "{")}).exitCode, pac::scenario::kExitRefused);
}

TEST(ScenarioCli, UsageErrorsExitTwo) {
    EXPECT_EQ(RunBinary("").exitCode, 2);
    const Cli none({});
    EXPECT_EQ(none.exitCode, pac::scenario::kExitRefused);
    EXPECT_NE(none.err.str().find("usage: pac_scenario [--check] [--vcd FILE] [--wavedrom FILE] SCENARIO.json"), std::string::npos);
    const Cli unknown({"--fast", kDemo});
    EXPECT_EQ(unknown.exitCode, pac::scenario::kExitRefused);
    EXPECT_NE(unknown.err.str().find("pac_scenario: unknown option --fast"), std::string::npos);
    // The names of GVL_PAC are compiled in: there is no other list to read.
    const Cli gvl({"--gvl", "GVL_PAC.st", kDemo});
    EXPECT_EQ(gvl.exitCode, pac::scenario::kExitRefused);
    EXPECT_NE(gvl.err.str().find("pac_scenario: unknown option --gvl"), std::string::npos);
    const Cli two({kDemo, kDemo});
    EXPECT_EQ(two.exitCode, pac::scenario::kExitRefused);
    EXPECT_NE(two.err.str().find("one scenario file at a time"), std::string::npos);
    const Cli help({"--help"});
    EXPECT_EQ(help.exitCode, pac::scenario::kExitOk);
    EXPECT_NE(help.out.str().find("exit codes: 0 all expectations met"), std::string::npos);
}

// --check takes several files (a folder's scenarios in one call): each is reported, the refused one does
// not stop the others, and the exit code is the worst.
TEST(ScenarioCli, CheckReportsEachOfSeveralFiles) {
    const std::string missing = testing::TempDir() + "/missing.json";
    const Cli check({"--check", missing, kDemo});
    EXPECT_EQ(check.exitCode, pac::scenario::kExitRefused);
    EXPECT_EQ(check.err.str(), "pac_scenario: invalid scenario " + missing + ": cannot read the file\n");
    EXPECT_EQ(check.out.str().rfind(std::string(kDemo) + ": valid scenario, ", 0), 0u) << check.out.str();
    const Cli both({"--check", kDemo, kDemo});
    EXPECT_EQ(both.exitCode, pac::scenario::kExitOk);
    const std::string out = both.out.str();
    EXPECT_NE(out.find(std::string(kDemo) + ": valid scenario, "), out.rfind(std::string(kDemo) + ": valid scenario, "));
}

TEST(ScenarioCli, AMissingScenarioFileExitsTwo) {
    const Cli scenario({testing::TempDir() + "/missing.json"});
    EXPECT_EQ(scenario.exitCode, pac::scenario::kExitRefused);
    EXPECT_EQ(scenario.err.str(),
              "pac_scenario: invalid scenario " + testing::TempDir() + "/missing.json: cannot read the file\n");
}

}  // namespace

namespace {

TEST(ScenarioCli, WritesTheTraceAndTheDiagramBesideTheTimeline) {
    const std::string vcd = TempFile("run.vcd", "");
    const std::string wave = TempFile("run.json", "");
    const std::string example = std::string(PAC_SCENARIO_DIR) + "/examples/cmd_ack.json";
    const Process run = RunBinary("--vcd " + Quoted(vcd) + " --wavedrom " + Quoted(wave) + " " + Quoted(example));
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("Result: 2 steps, 1 command: all expectations met"), std::string::npos) << run.out;
    const std::string trace = ReadFile(vcd);
    EXPECT_EQ(trace.rfind("$comment pac_scenario cmd_ack $end\n", 0), 0u) << trace.substr(0, 200);
    EXPECT_NE(trace.find("$var wire 1 ( Execute $end"), std::string::npos);
    const std::string diagram = ReadFile(wave);
    EXPECT_EQ(diagram.rfind("{\"signal\": [\n  {\"name\":\"t [ms]\"", 0), 0u) << diagram.substr(0, 200);
    EXPECT_NE(diagram.find("\"head\": {\"text\":\"FB_PAC_Cmd: a command and its acknowledgement"), std::string::npos);
}

// The trace runs to the scenario's last scan, not to its last change: a final wait in which nothing moves
// (the PA-CONTROL booted at 50 ms) still ends the waveform at the end of the wait.
TEST(ScenarioCli, TheTraceEndsAtTheLastScanNotAtTheLastChange) {
    const std::string vcd = TempFile("run.vcd", "");
    const std::string file = TempFile("idle.json", R"({"timing": {"plc_cycle_ms": 2}, "steps": [{"wait_ms": 200}]})");
    const Cli run({"--vcd", vcd, file});
    ASSERT_EQ(run.exitCode, pac::scenario::kExitOk) << run.err.str();
    const std::string trace = ReadFile(vcd);
    const auto stamp = trace.rfind("\n#");
    ASSERT_NE(stamp, std::string::npos) << trace;
    const long long lastNs = std::stoll(trace.substr(stamp + 2));
    // The wait scans for at least 200 ms in whole 2 ms cycles, its first scan one cycle in.
    EXPECT_GE(lastNs, 200'000'000LL) << trace.substr(stamp);
    EXPECT_LE(lastNs, 204'000'000LL) << trace.substr(stamp);
}

// --version names the library's version of st/library.json, compiled in: a copy of the binary away from
// the source tree prints it too, and exits 0 whatever follows.
TEST(ScenarioCli, VersionIsTheLibrarysFromItsMetadata) {
    const auto library = nlohmann::json::parse(ReadFile(std::string(PAC_SOURCE_DIR) + "/st/library.json"));
    const std::string expected = "pac_scenario (" + library.at("title").get<std::string>() + ") " +
                                 library.at("version").get<std::string>() + "\n";
    const Process copy = RunShell(Quoted(CopyBinaryAndDemo() + "/pac_scenario") + " --version");
    EXPECT_EQ(copy.exitCode, 0) << copy.err;
    EXPECT_EQ(copy.out, expected);
    EXPECT_EQ(copy.err, "");
    const Cli inProcess({"--version", "no-such-file.json"});
    EXPECT_EQ(inProcess.exitCode, pac::scenario::kExitOk);
    EXPECT_EQ(inProcess.out.str(), expected);
    EXPECT_NE(Cli({"--help"}).out.str().find("--version"), std::string::npos);
}

// START ONLINE without the external stop input: a warning on stderr before the run, naming the file and
// the step; the run goes on (the timeline shows the refusal) and --check warns too, exiting 0.
TEST(ScenarioCli, StartOnlineWithoutTheStopInputWarnsAndRunsOn) {
    const std::string file = TempFile("online.json", R"({"modules": {"ctrl": true}, "steps": [{"wait_ms": 60},
        {"ctrl": "PAC_REQ_START_ONLINE", "timeout_ms": 100}]})");
    const std::string warning = "pac_scenario: warning: " + file + ": step 2 ($.steps[1]): " +
                                "START ONLINE without an external stop input: system parameter 4 is 0";
    const Process run = RunBinary(Quoted(file));
    EXPECT_EQ(run.err.rfind(warning, 0), 0u) << run.err;
    EXPECT_EQ(run.exitCode, 0) << run.err;  // no expectation given: the timeout (16#8009) fails nothing
    EXPECT_NE(run.out.find("Result: 2 steps, 0 commands, 1 mode request"), std::string::npos) << run.out;
    const Cli check({"--check", file});
    EXPECT_EQ(check.exitCode, pac::scenario::kExitOk);
    EXPECT_EQ(check.err.str().rfind(warning, 0), 0u) << check.err.str();
}

TEST(ScenarioCli, TraceOptionsWithoutAFileOrWithAFileItCannotWriteExitTwo) {
    const Cli missing({kDemo, "--vcd"});
    EXPECT_EQ(missing.exitCode, pac::scenario::kExitRefused);
    EXPECT_EQ(missing.err.str(), "pac_scenario: --vcd needs a file name\n");
    const Cli folder({"--wavedrom", testing::TempDir() + "/no-such-folder/x.json", kDemo});
    EXPECT_EQ(folder.exitCode, pac::scenario::kExitRefused);
    EXPECT_NE(folder.err.str().find("pac_scenario: cannot write " + testing::TempDir() + "/no-such-folder/x.json"),
              std::string::npos)
        << folder.err.str();
}

TEST(ScenarioCli, ADiagramOfStepsWithoutScansIsRefused) {
    const std::string file = TempFile("faults.json", R"({"steps": [{"wait_ms": 4}, {"fault": "power_cycle"}],
        "diagram": {"steps": [2, 2]}})");
    const Cli run({"--wavedrom", TempFile("out.json", ""), file});
    EXPECT_EQ(run.exitCode, pac::scenario::kExitRefused);
    EXPECT_NE(run.err.str().find("$.diagram.steps: steps 2..2 take no scan: nothing to draw"), std::string::npos)
        << run.err.str();
}

}  // namespace
