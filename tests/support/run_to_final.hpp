// Runs a job to its final state: after the scan that saw the Execute edge, scans until the FB shows
// Done, Error or CommandAborted, never more than a bound, and reports the outputs of that scan and
// where it came (FinalOutcome). A job that shows nothing within the bound is reported as such rather
// than hanging the test.
#pragma once

#include <cstdint>
#include <ostream>

#include "plcopen_pins.hpp"

namespace pac::test {

struct FinalOutcome {
    PlcOpenOutputs outputs;     // in the scan that showed the final output, or the last one run
    std::int64_t edgeScan = -1;   // the scan that saw the Execute edge
    std::int64_t finalScan = -1;  // the scan that showed the final output; -1: none within the bound

    bool Ended() const { return finalScan >= 0; }
    bool Done() const { return outputs.done; }
    bool Error() const { return outputs.error; }
    bool Aborted() const { return outputs.aborted; }
    std::uint32_t ErrorId() const { return outputs.errorId; }
    // Scans from the edge scan to the final output (0: in the edge scan itself); -1 without one.
    int Scans() const { return Ended() ? static_cast<int>(finalScan - edgeScan) : -1; }
};

inline std::ostream& operator<<(std::ostream& out, const FinalOutcome& o) {
    if (!o.Ended()) return out << "no final output within the bound (" << o.outputs << ")";
    return out << o.outputs << " after " << o.Scans() << " scans (edge scan " << o.edgeScan << ", final scan "
               << o.finalScan << ")";
}

// `scan` runs one scan and returns its number; the edge scan `edgeScan` has run already. At most
// `maxScans` more scans.
template <class Fb, class ScanFn>
FinalOutcome RunToFinal(const Fb& fb, std::int64_t edgeScan, ScanFn&& scan, int maxScans) {
    FinalOutcome o;
    o.edgeScan = edgeScan;
    std::int64_t now = edgeScan;
    for (int i = 0; i < maxScans && !IsFinal(fb); ++i) now = scan();
    o.outputs = OutputsOf(fb);
    if (o.outputs.Final()) o.finalScan = now;
    return o;
}

}  // namespace pac::test
