// pac_scenario: runs a scenario file of commands, mode requests and axis jobs against the simulated
// PA-CONTROL and prints a scan-by-scan timeline of the library's FBs at work (docs/scenario.md).
#include <iostream>
#include <string>
#include <vector>

#include "cli.hpp"

int main(int argc, char** argv) {
    return pac::scenario::RunCli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
