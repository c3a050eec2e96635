// pac_soak: the library against the simulated PA-CONTROL for a number of scans, with random jobs and faults
// drawn from a seed (soak_run.hpp). Prints the seed first, so any run can be repeated, then a summary line;
// exit code 0 without violations, 1 with, 2 for a bad command line.
//   pac_soak --seed 1 --scans 100000
//   pac_soak --seed random --scans 10000000
#include <cstdint>
#include <cstring>
#include <iostream>
#include <random>
#include <string>

#include "soak_run.hpp"

namespace {

int Usage() {
    std::cerr << "usage: pac_soak --seed <number|random> --scans <number>\n";
    return 2;
}

bool ParseNumber(const char* text, std::uint64_t& value) {
    try {
        std::size_t used = 0;
        value = std::stoull(text, &used, 10);
        return used == std::strlen(text);
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::uint64_t seed = 1;
    std::uint64_t scans = 100000;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (i + 1 >= argc) return Usage();
        const char* value = argv[++i];
        if (arg == "--seed" && std::strcmp(value, "random") == 0) {
            seed = (static_cast<std::uint64_t>(std::random_device{}()) << 32) | std::random_device{}();
        } else if (arg == "--seed") {
            if (!ParseNumber(value, seed)) return Usage();
        } else if (arg == "--scans") {
            if (!ParseNumber(value, scans) || scans == 0) return Usage();
        } else {
            return Usage();
        }
    }
    std::cout << "pac_soak --seed " << seed << " --scans " << scans << std::endl;
    pac::soak::SoakRun run(seed, static_cast<std::int64_t>(scans));
    run.Run();
    run.Report().Print(std::cout);
    std::cout << run.Summary() << std::endl;
    return run.Report().Violations() == 0 ? 0 : 1;
}
