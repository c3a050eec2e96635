// A window of a trace as WaveJSON, the input of WaveDrom (wavedrom.com; rendered to SVG by wavedrom-cli):
// one column per scan, the first lane the scan's time, then the chosen signals in the given order,
// grouped by scope where neighbours share one. Bits are waves, everything else data lanes with the
// value written as a PLC programmer reads it (bytes in hex, error IDs as the manual writes them).
// A run of more than maxIdleScans scans in which only sampled lanes change (REALs, and the lanes the
// request names, such as a position carried in bytes) becomes one gap column ('|'), so a wait or a move
// does not drown the handshake around it; sampled lanes show their value in the scans kept.
#pragma once

#include <cstddef>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "pac/trace.hpp"
#include "scenario_signals.hpp"

namespace pac::scenario {

struct WaveJsonRequest {
    std::string title;
    std::string foot;
    std::vector<std::string> lanes;    // trace paths
    std::vector<std::string> sampled;  // lanes that keep no scan by changing (REALs never do)
    std::size_t begin = 0;           // the window's samples [begin, end)
    std::size_t end = 0;
    int maxIdleScans = 3;
    int hscale = 3;
};

// std::out_of_range for a lane the trace does not have or a window outside it, std::invalid_argument
// for an empty window.
void WriteWaveJson(const Trace& trace, const std::function<ValueFormat(const std::string&)>& formatOf,
                   const WaveJsonRequest& request, std::ostream& out);

}  // namespace pac::scenario
