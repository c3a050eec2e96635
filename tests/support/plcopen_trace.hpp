// Records the PLCopen pins of a command FB in a trace, the same way for every FB of the library:
// <scope>.Execute, .Busy, .Done, .Error, .CommandAborted where the FB has it, .ErrorID.
#pragma once

#include <string>

#include "pac/trace_recorder.hpp"
#include "plcopen_pins.hpp"

namespace pac::test {

// `fb` must outlive the recorder's sampling.
template <class Fb>
void TracePlcOpenPins(pac::TraceRecorder& recorder, const std::string& scope, const pac::FbInstance<Fb>& fb) {
    recorder.AddBool(scope + ".Execute", [&fb] { return InputsOf(fb).execute; });
    recorder.AddBool(scope + ".Busy", [&fb] { return OutputsOf(fb).busy; });
    recorder.AddBool(scope + ".Done", [&fb] { return OutputsOf(fb).done; });
    recorder.AddBool(scope + ".Error", [&fb] { return OutputsOf(fb).error; });
    if constexpr (pins::HasCommandAborted<Fb>::value) {
        recorder.AddBool(scope + ".CommandAborted", [&fb] { return OutputsOf(fb).aborted; });
    }
    recorder.AddBits(scope + ".ErrorID", 16, [&fb] { return OutputsOf(fb).errorId; });
}

// A name as a trace scope: no blanks (VCD separates its words with them).
inline std::string TraceScope(std::string name) {
    for (char& c : name) {
        if (c == ' ' || c == '\t') c = '_';
    }
    return name;
}

}  // namespace pac::test
