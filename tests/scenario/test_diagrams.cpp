// The timing diagrams of the documentation stay true: every docs/diagrams/<name>.json (WaveJSON) is
// exactly what scenario/examples/<name>.json draws now, every example with a "diagram" has its
// committed WaveJSON and SVG, and the diagrams show the handshakes the manual describes. When the
// library, the simulator or a scenario changes what a diagram shows, regenerate the diagrams with
// `cmake --build build --target diagrams`, look at them, and commit them with the change.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gvl_names.hpp"
#include "scenario_diagram.hpp"
#include "scenario_loader.hpp"
#include "scenario_runner.hpp"
#include "trace_observer.hpp"

namespace {

namespace fs = std::filesystem;
using pac::scenario::Scenario;

const fs::path kDiagrams = fs::path(PAC_SOURCE_DIR) / "docs" / "diagrams";
const fs::path kExamples = fs::path(PAC_SCENARIO_DIR) / "examples";

std::string ReadFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The WaveJSON the scenario draws now, and whether the run met its expectations.
std::string Draw(const fs::path& scenarioFile, bool& passed) {
    const pac::scenario::GvlNames names;
    const Scenario scenario = pac::scenario::ScenarioLoader(names).FromFile(scenarioFile.string());
    pac::scenario::TraceObserver trace(scenario.modules);
    passed = pac::scenario::ScenarioRunner(scenario).Run(trace).Passed();
    std::ostringstream out;
    pac::scenario::WriteScenarioDiagram(scenario, trace, out);
    return out.str();
}

std::vector<std::string> Lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<std::string> CommittedDiagrams() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(kDiagrams)) {
        if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    }
    return names;
}

TEST(Diagrams, EveryCommittedDiagramIsWhatItsScenarioDrawsNow) {
    const auto names = CommittedDiagrams();
    ASSERT_GE(names.size(), 8u) << "the CMD handshakes, the mode change and the four axis sequences of 2.7.9";
    for (const std::string& name : names) {
        SCOPED_TRACE(name);
        const fs::path scenario = kExamples / (name + ".json");
        ASSERT_TRUE(fs::exists(scenario)) << "docs/diagrams/" << name << ".json has no scenario " << scenario;
        bool passed = false;
        const auto now = Lines(Draw(scenario, passed));
        EXPECT_TRUE(passed) << scenario << " no longer meets its expectations";
        const auto committed = Lines(ReadFile(kDiagrams / (name + ".json")));
        std::size_t line = 0;
        while (line < now.size() && line < committed.size() && now[line] == committed[line]) ++line;
        EXPECT_TRUE(line == now.size() && line == committed.size())
            << "docs/diagrams/" << name << ".json differs from what its scenario draws now, first at line " << line + 1
            << ":\n  committed: " << (line < committed.size() ? committed[line] : "(end)")
            << "\n  now:       " << (line < now.size() ? now[line] : "(end)")
            << "\nregenerate with `cmake --build build --target diagrams`, look at the SVG, commit both";
        EXPECT_TRUE(fs::exists(kDiagrams / (name + ".svg"))) << "render it: cmake --build build --target diagrams";
    }
}

TEST(Diagrams, EveryExampleWithADiagramHasItCommitted) {
    for (const auto& entry : fs::directory_iterator(kExamples)) {
        const auto document = nlohmann::json::parse(ReadFile(entry.path()));
        if (!document.contains("diagram")) continue;
        const std::string name = entry.path().stem().string();
        EXPECT_TRUE(fs::exists(kDiagrams / (name + ".json")))
            << entry.path() << " has a diagram, docs/diagrams has none: cmake --build build --target diagrams";
    }
}

// The lanes of a committed diagram by name, for the checks of what it shows.
struct Lanes {
    explicit Lanes(const std::string& name) {
        const auto document = nlohmann::json::parse(ReadFile(kDiagrams / (name + ".json")));
        for (const auto& row : document.at("signal")) {
            if (row.is_object()) {
                waves[row.at("name").get<std::string>()] = row.at("wave").get<std::string>();
                continue;
            }
            for (std::size_t i = 1; i < row.size(); ++i) {
                waves[row[i].at("name").get<std::string>()] = row[i].at("wave").get<std::string>();
            }
        }
    }
    // The first column after `after` in which `lane` becomes `level` ('0' or '1'), -1 if none; the first
    // column counts as becoming its level.
    int Becomes(const std::string& lane, char level, int after = -1) const {
        const std::string& wave = waves.at(lane);
        char previous = 'x';
        for (std::size_t i = 0; i < wave.size(); ++i) {
            const char current = (wave[i] == '0' || wave[i] == '1') ? wave[i] : previous;
            if (static_cast<int>(i) > after && current == level && previous != level) return static_cast<int>(i);
            previous = current;
        }
        return -1;
    }
    std::map<std::string, std::string> waves;
};

// The level SEND toggles to in column `edge` ('1' or '0'; which one depends on the handshakes before, the cold
// start's parked read among them).
char Toggled(const Lanes& lanes, int edge) { return lanes.Becomes("SEND", '1', edge - 1) == edge ? '1' : '0'; }

// The handshake as the manual and docs/fb/FB_PAC_Cmd.md give it: SEND toggles with Execute's edge, the
// acknowledgement (RF = SEND) comes later, Done in the scan that sees it.
TEST(Diagrams, TheCommandDiagramShowsTheHandshakeInItsOrder) {
    const Lanes ack("cmd_ack");
    const int edge = ack.Becomes("Execute", '1');
    ASSERT_GT(edge, 0) << "the diagram starts before the edge";
    const char sent = Toggled(ack, edge);
    EXPECT_EQ(ack.Becomes("SEND", sent, edge - 1), edge) << "SEND toggles in the edge scan";
    EXPECT_EQ(ack.Becomes("Busy", '1'), edge);
    const int acknowledged = ack.Becomes("RF", sent, edge);
    EXPECT_GT(acknowledged, edge) << "the acknowledgement needs the bus and a controller cycle";
    EXPECT_EQ(ack.Becomes("Done", '1'), acknowledged);
    EXPECT_EQ(ack.Becomes("Busy", '0', edge), acknowledged);

    const Lanes error("cmd_error");
    EXPECT_EQ(error.Becomes("KF", '1'), error.Becomes("Error", '1'));
    EXPECT_EQ(error.Becomes("Done", '1'), -1);

    // A long command: acknowledged with BF 0 first (RF follows SEND), Done only when BF returns to 1.
    const Lanes move("cmd_move");
    const int taken = move.Becomes("BF", '0');
    ASSERT_GT(taken, 0);
    const int moveEdge = move.Becomes("Execute", '1');
    EXPECT_EQ(move.Becomes("RF", Toggled(move, moveEdge), moveEdge), taken);
    EXPECT_EQ(move.Becomes("Done", '1'), move.Becomes("BF", '1', taken));
}

// 2.7.3.2 / 2.7.4.8: Start until ACTIVE answers, ACTIVE falls after the job, Done in that scan.
TEST(Diagrams, TheAxisDiagramsShowStartAndActive) {
    for (const char* name : {"axis_reference", "axis_traverse"}) {
        SCOPED_TRACE(name);
        const Lanes lanes(name);
        const int start = lanes.Becomes("Start", '1');
        const int active = lanes.Becomes("ACTIVE", '1');
        ASSERT_GT(start, 0);
        EXPECT_GT(active, start);
        EXPECT_EQ(lanes.Becomes("Start", '0', start), active) << "Start drops in the scan that sees ACTIVE";
        const int end = lanes.Becomes("ACTIVE", '0', active);
        EXPECT_GT(end, active);
        EXPECT_EQ(lanes.Becomes("Done", '1'), end);
    }
    const Lanes limit("axis_limit_switch");
    EXPECT_EQ(limit.Becomes("AxisError", '1'), limit.Becomes("Error", '1'));
    EXPECT_GT(limit.Becomes("ResetAxisError", '1'), limit.Becomes("AxisError", '1'));
    EXPECT_EQ(limit.Becomes("ResetAxisError", '0', limit.Becomes("ResetAxisError", '1')), limit.Becomes("AxisError", '0', 0))
        << "the reset bit stays until the axis error bit is seen 0";
}

}  // namespace
