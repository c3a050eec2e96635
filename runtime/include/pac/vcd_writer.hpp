// Writes a Trace as a Value Change Dump (IEEE 1364, chapter 18), the format GTKWave and every HDL
// waveform viewer open. Scopes become nested modules under one top module; bit vectors are `wire`s,
// REALs `real`s; times are the samples' simulated times in nanoseconds (`$timescale 1 ns`). The file
// depends on nothing but the trace, so equal runs give equal files. The last sample always has a time
// stamp (alone when nothing changed in it), so a viewer shows the trace to its end.
#pragma once

#include <ostream>
#include <string>

#include "pac/trace.hpp"

namespace pac {

struct VcdOptions {
    std::string top = "pac";  // the module that holds every scope
    std::string comment;      // written as $comment when not empty (what the run was)
};

void WriteVcd(const Trace& trace, std::ostream& out, const VcdOptions& options = {});

}  // namespace pac
