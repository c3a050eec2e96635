// The command line of pac_scenario, as a function so tests can run it in-process:
//   pac_scenario [--check] [--vcd FILE] [--wavedrom FILE] SCENARIO.json
//   pac_scenario --version   (the library's version of st/library.json, compiled in)
// Exit codes: 0 every expectation met (or --check: valid), 1 an expectation failed, 2 the scenario
// was refused (or bad usage), 3 an internal error.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace pac::scenario {

constexpr int kExitOk = 0;
constexpr int kExitExpectationFailed = 1;
constexpr int kExitRefused = 2;
constexpr int kExitInternalError = 3;

// `args` without the program name. The timeline goes to `out`, refusals and usage to `err`.
int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace pac::scenario
