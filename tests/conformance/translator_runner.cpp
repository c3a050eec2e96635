#include "translator_runner.hpp"

#include <sys/wait.h>

#include <cstdio>
#include <stdexcept>

namespace pac::test {

namespace {
std::string Quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) {
        if (c == '\'') {
            out += "'\\''";
        } else {
            out += c;
        }
    }
    return out + "'";
}
}  // namespace

RunResult RunTranslator(const std::vector<std::string>& arguments) {
    std::string command = PACST_SHELL_COMMAND;
    for (const auto& a : arguments) command += " " + Quote(a);
    command += " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) throw std::runtime_error("cannot start: " + command);
    RunResult result;
    char buffer[4096];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
    int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

}  // namespace pac::test
