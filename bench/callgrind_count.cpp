#include "callgrind_count.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace pac::bench {

namespace {

std::string Quoted(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// The "totals:" (or "summary:") count of a callgrind dump; -1 if there is none.
double TotalOf(const std::string& dump) {
    std::ifstream in(dump);
    std::string line;
    double summary = -1;
    while (std::getline(in, line)) {
        if (line.rfind("totals:", 0) == 0) return std::strtod(line.c_str() + 7, nullptr);
        if (line.rfind("summary:", 0) == 0) summary = std::strtod(line.c_str() + 8, nullptr);
    }
    return summary;
}

}  // namespace

bool ValgrindAvailable() { return std::system("valgrind --version > /dev/null 2>&1") == 0; }

std::optional<CallgrindCount> CountInstructions(const std::string& self, const std::string& workload,
                                                const std::vector<std::string>& functions, int scans) {
    // The system's temporary folder ($TMPDIR or its default), not a path written into the source.
    std::string pattern = (std::filesystem::temp_directory_path() / "pac-bench-XXXXXX").string();
    char* dir = mkdtemp(pattern.data());
    if (dir == nullptr) return std::nullopt;
    const std::string out = std::string(dir) + "/callgrind.out";
    std::ostringstream command;
    command << "valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file=" << Quoted(out);
    for (const auto& f : functions) command << " --toggle-collect=" << Quoted(f);
    command << " " << Quoted(self) << " --workload " << Quoted(workload) << " --scans " << scans << " 2>/dev/null";
    FILE* pipe = popen(command.str().c_str(), "r");
    if (pipe == nullptr) return std::nullopt;
    CallgrindCount count;
    const int fields = std::fscanf(pipe, "scans %d jobs %ld", &count.scans, &count.jobs);
    const int status = pclose(pipe);
    // The dump the workload asked for after its measured scans is the first: <out>.1.
    const double total = TotalOf(out + ".1");
    std::remove((out + ".1").c_str());
    std::remove(out.c_str());
    rmdir(dir);
    if (fields != 2 || status != 0 || total < 0 || count.scans <= 0) return std::nullopt;
    count.instructionsPerScan = total / count.scans;
    return count;
}

}  // namespace pac::bench
