// Every snippet in refuse/ must be refused by `pacst check` at the position and for the reason its
// first line names: (* expect-error: LINE:COL: words of the message *). Built a second time for
// refuse_user/ with PACST_REFUSE_USER: the snippets `pacst check --user` must refuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "translator_runner.hpp"

namespace {

namespace fs = std::filesystem;

struct Expectation {
    int line = 0;
    int col = 0;
    std::string words;
};

Expectation ReadExpectation(const fs::path& file) {
    std::ifstream in(file);
    std::string first;
    std::getline(in, first);
    static const std::regex pattern(R"(\(\*\s*expect-error:\s*(\d+):(\d+):\s*(.*?)\s*\*\))");
    std::smatch m;
    if (!std::regex_search(first, m, pattern)) {
        ADD_FAILURE() << file << ": first line must be (* expect-error: LINE:COL: words *)";
        return {};
    }
    return {std::stoi(m[1]), std::stoi(m[2]), m[3]};
}

std::vector<std::string> RefuseFiles() {
    std::vector<std::string> files;
    if (!fs::is_directory(PACST_REFUSE_DIR)) return files;  // HasEnoughSnippets reports it
    for (const auto& entry : fs::directory_iterator(PACST_REFUSE_DIR)) {
        if (entry.path().extension() == ".st") files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// What the translator printed for the snippets: under CTest, one `pacst check --separately` run over
// all of them (the fixture named in CMakeLists.txt, PACST_REFUSE_REPORT), because a translator start
// costs more than checking a snippet; run by hand, a translator run of the snippet's own.
std::string TranslatorOutput(const std::string& file) {
    if (const char* report = std::getenv("PACST_REFUSE_REPORT")) {
        std::ifstream in(report);
        if (!in) ADD_FAILURE() << "cannot read the translator's report " << report;
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }
#ifdef PACST_REFUSE_USER
    return pac::test::RunTranslator({"check", "--user", "--native", PACST_REFUSE_USER, file}).output;
#else
    return pac::test::RunTranslator({"check", file}).output;
#endif
}

std::vector<std::string> ErrorsOf(const std::string& file) {
    std::vector<std::string> errors;
    std::istringstream lines(TranslatorOutput(file));
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind(file + ":", 0) == 0) errors.push_back(line);
    }
    return errors;
}

class Refuse : public ::testing::TestWithParam<std::string> {};

TEST_P(Refuse, AtPositionWithReason) {
    const std::string file = GetParam();
    const Expectation want = ReadExpectation(file);
    const auto errors = ErrorsOf(file);
    ASSERT_FALSE(errors.empty()) << file << " was accepted, but must be refused: " << want.words;
    const std::string& first = errors.front();
    const std::string prefix = file + ":" + std::to_string(want.line) + ":" + std::to_string(want.col) + ": error: ";
    EXPECT_EQ(first.rfind(prefix, 0), 0u) << "expected the error at " << want.line << ":" << want.col
                                          << ", got: " << first;
    EXPECT_NE(first.find(want.words), std::string::npos) << "expected '" << want.words << "' in: " << first;
}

std::string NameOf(const ::testing::TestParamInfo<std::string>& info) {
    std::string stem = fs::path(info.param).stem().string();
    for (char& c : stem) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    }
    return stem;
}

#ifdef PACST_REFUSE_USER
INSTANTIATE_TEST_SUITE_P(UserSnippets, Refuse, ::testing::ValuesIn(RefuseFiles()), NameOf);

TEST(UserRefuseSuite, HasEnoughSnippets) {
    EXPECT_GE(RefuseFiles().size(), 10u);
}
#else
INSTANTIATE_TEST_SUITE_P(Snippets, Refuse, ::testing::ValuesIn(RefuseFiles()), NameOf);

TEST(RefuseSuite, HasEnoughSnippets) {
    EXPECT_GE(RefuseFiles().size(), 30u);
}
#endif

}  // namespace
