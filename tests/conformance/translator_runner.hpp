// Runs the pacst command line from a test and captures what it prints and how it exits.
#pragma once

#include <string>
#include <vector>

namespace pac::test {

struct RunResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

// `arguments` are shell-quoted here; the translator command itself comes from the build.
RunResult RunTranslator(const std::vector<std::string>& arguments);

}  // namespace pac::test
