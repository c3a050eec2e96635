// A recording of named signals, sample by sample (normally one sample per PLC scan): what a
// TraceRecorder took, what VcdWriter and the scenario program's WaveJSON writer read. Signals are
// bit vectors of 1..64 bits or REALs; each keeps only its changes, so a long run of scans in which
// little moves stays small. A name is "scope.name" ("cmd.Execute", "axis1.Status"): everything before
// the last dot is the scope, which may itself hold dots ("axis1.fb.Busy").
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pac {

enum class SignalKind { kBits, kReal };

struct SignalInfo {
    std::string path;  // "cmd.Execute"
    SignalKind kind = SignalKind::kBits;
    int width = 1;  // bits; 64 for a REAL

    std::string Scope() const;  // "cmd"; empty without a dot
    std::string Name() const;   // "Execute"
};

// A sample of one signal: `bits` for bit vectors, `real` for REALs (the other member is 0).
struct TraceValue {
    std::uint64_t bits = 0;
    double real = 0.0;

    bool operator==(const TraceValue& other) const { return bits == other.bits && real == other.real; }
    bool operator!=(const TraceValue& other) const { return !(*this == other); }
};

class Trace {
public:
    struct Change {
        std::size_t sample;
        TraceValue value;
    };

    // std::invalid_argument for an empty or duplicate path, a width outside 1..64, or a signal added
    // after the first sample (its earlier samples would be unknown).
    std::size_t AddSignal(SignalInfo info);

    // One sample of every signal, in the order they were added; times strictly increase
    // (std::invalid_argument otherwise, or for a wrong number of values).
    void Append(std::chrono::nanoseconds time, const std::vector<TraceValue>& values);

    const std::vector<SignalInfo>& Signals() const { return signals_; }
    std::size_t Find(const std::string& path) const;  // std::out_of_range if there is none
    std::size_t Samples() const { return times_.size(); }
    std::chrono::nanoseconds TimeOf(std::size_t sample) const { return times_.at(sample); }
    TraceValue ValueAt(std::size_t signal, std::size_t sample) const;
    // The first change is the value of sample 0.
    const std::vector<Change>& Changes(std::size_t signal) const { return changes_.at(signal); }

private:
    std::vector<SignalInfo> signals_;
    std::vector<std::chrono::nanoseconds> times_;
    std::vector<std::vector<Change>> changes_;
};

}  // namespace pac
