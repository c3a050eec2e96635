// A fixture for tests that run the translator's command line: a scratch folder of the test's own, files
// written into it, and the output folder a build writes to.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

namespace pac::test {

class TranslatorScratch : public ::testing::Test {
protected:
    // `prefix` keeps apart the folders of two suites whose tests share a name.
    explicit TranslatorScratch(std::string prefix = "") : prefix_(std::move(prefix)) {}

    void SetUp() override {
        dir_ = std::filesystem::path(PACST_SCRATCH_DIR) /
               (prefix_ + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_ / "out");
    }

    std::string Write(const std::string& name, const std::string& text) {
        std::filesystem::path p = dir_ / name;
        std::ofstream(p) << text;
        return p.string();
    }

    std::string Out() const { return (dir_ / "out").string(); }
    bool Generated(const std::string& name) const { return std::filesystem::exists(dir_ / "out" / name); }

    std::filesystem::path dir_;

private:
    std::string prefix_;
};

}  // namespace pac::test
