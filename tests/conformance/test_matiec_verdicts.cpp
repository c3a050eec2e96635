// pacst against real MATIEC's measured verdicts (matiec_verdicts/ beside this file, README there): every
// snippet iec2c rejects, pacst refuses with file:line:col and a reason; every snippet iec2c accepts,
// pacst accepts too or refuses for a reason on record in stricter_than_matiec.tsv. With the matiec
// preset (IEC2C set) the same corpus is run through iec2c, which must still give each recorded verdict.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "translator_runner.hpp"

namespace {

namespace fs = std::filesystem;

struct Verdict {
    bool accepted = false;
    std::string message;  // MATIEC's first message
};

// Tab-separated rows after a header line: name, then columns.
std::vector<std::vector<std::string>> ReadTsv(const fs::path& path) {
    std::ifstream in(path);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        std::vector<std::string> cells;
        std::istringstream fields(line);
        std::string cell;
        while (std::getline(fields, cell, '\t')) cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

class MatiecVerdicts : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        const fs::path dir = PAC_MATIEC_VERDICTS_DIR;
        for (const auto& row : ReadTsv(dir / "verdicts.tsv")) {
            if (row.size() < 2) continue;
            verdicts_[row[0]] = {row[1] == "accepted", row.size() > 2 ? row[2] : ""};
        }
        for (const auto& row : ReadTsv(PAC_STRICTER_LIST)) {
            if (row.size() >= 3) stricter_[row[0]] = row[1];
        }
        // One translator run for the whole corpus: each snippet is a program of its own.
        std::vector<std::string> args = {"check", "--separately", "--cache", PACST_CACHE};
        for (const auto& [name, verdict] : verdicts_) args.push_back((dir / "snippets" / name).string());
        const auto result = pac::test::RunTranslator(args);
        // Refusals are `<dir>/snippets/<name>.st:line:col: error: ...`.
        const std::string prefix = (dir / "snippets").string() + "/";
        std::istringstream lines(result.output);
        std::string line;
        while (std::getline(lines, line)) {
            const std::size_t end = line.find(".st:", prefix.size());
            if (line.rfind(prefix, 0) != 0 || end == std::string::npos) continue;
            refusals_[line.substr(prefix.size(), end + 3 - prefix.size())].push_back(line);
        }
    }

    static std::map<std::string, Verdict> verdicts_;
    static std::map<std::string, std::string> stricter_;  // snippet -> words of pacst's refusal
    static std::map<std::string, std::vector<std::string>> refusals_;
};

std::map<std::string, Verdict> MatiecVerdicts::verdicts_;
std::map<std::string, std::string> MatiecVerdicts::stricter_;
std::map<std::string, std::vector<std::string>> MatiecVerdicts::refusals_;

TEST_F(MatiecVerdicts, CorpusIsThere) {
    // A missing or unreadable corpus would make every other test here pass vacuously.
    EXPECT_GE(verdicts_.size(), 100u) << "cannot read " << PAC_MATIEC_VERDICTS_DIR;
    int rejected = 0;
    for (const auto& [name, v] : verdicts_) rejected += v.accepted ? 0 : 1;
    EXPECT_GE(rejected, 30);
}

TEST_F(MatiecVerdicts, EverySnippetMatiecRejectsIsRefusedWithPosition) {
    for (const auto& [name, v] : verdicts_) {
        if (v.accepted) continue;
        auto it = refusals_.find(name);
        if (it == refusals_.end()) {
            ADD_FAILURE() << name << ": MATIEC rejects it (" << v.message << "), pacst accepted it";
            continue;
        }
        // file:line:col: error: reason
        const std::string& first = it->second.front();
        const std::size_t at = first.find(".st:");
        int line = 0;
        int col = 0;
        char colon = 0;
        std::istringstream pos(first.substr(at + 4));
        pos >> line >> colon >> col;
        EXPECT_GT(line, 0) << first;
        EXPECT_GT(col, 0) << first;
        EXPECT_NE(first.find(": error: "), std::string::npos) << first;
    }
}

TEST_F(MatiecVerdicts, EverySnippetMatiecAcceptsIsAcceptedOrStricterOnRecord) {
    for (const auto& [name, v] : verdicts_) {
        if (!v.accepted) continue;
        auto refused = refusals_.find(name);
        auto listed = stricter_.find(name);
        if (refused == refusals_.end()) {
            EXPECT_EQ(listed, stricter_.end())
                << name << " is listed in stricter_than_matiec.tsv but pacst accepts it: remove the line";
            continue;
        }
        if (listed == stricter_.end()) {
            ADD_FAILURE() << name << ": MATIEC accepts it, pacst refuses it without a reason on record in "
                          << "stricter_than_matiec.tsv: " << refused->second.front();
            continue;
        }
        EXPECT_NE(refused->second.front().find(listed->second), std::string::npos)
            << name << ": expected the recorded reason '" << listed->second << "' in: " << refused->second.front();
    }
}

TEST_F(MatiecVerdicts, EveryRecordedStricterSnippetIsInTheCorpus) {
    for (const auto& [name, words] : stricter_) {
        auto it = verdicts_.find(name);
        ASSERT_NE(it, verdicts_.end()) << name << " is in stricter_than_matiec.tsv but not in the corpus";
        EXPECT_TRUE(it->second.accepted) << name << " is rejected by MATIEC: it is no stricter choice";
    }
}

#ifdef PAC_IEC2C
// Real MATIEC on every snippet: the recorded verdicts still hold for the iec2c this build uses.
TEST_F(MatiecVerdicts, Iec2cStillGivesEveryRecordedVerdict) {
    const fs::path dir = PAC_MATIEC_VERDICTS_DIR;
    const fs::path out = fs::path(PAC_VERDICT_SCRATCH_DIR);
    fs::create_directories(out);
    for (const auto& [name, v] : verdicts_) {
        const std::string command = std::string("'") + PAC_IEC2C + "' -I '" + PAC_MATIEC_LIB + "' -T '" +
                                    out.string() + "' '" + (dir / "snippets" / name).string() +
                                    "' >/dev/null 2>&1";
        const bool accepted = std::system(command.c_str()) == 0;
        EXPECT_EQ(accepted, v.accepted) << name << ": iec2c " << (accepted ? "accepts" : "rejects")
                                        << " it, the corpus says " << (v.accepted ? "accepted" : "rejected");
    }
}
#endif

}  // namespace
