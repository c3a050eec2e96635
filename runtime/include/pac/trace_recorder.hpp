// Takes a sample of chosen signals, each read by a probe the caller gives (an FB pin, a byte of the bus
// image, a decoded flag, the simulated axis position), into a Trace. Attached to a PlcTask it samples
// after every scan, once the programs registered before it have run: the outputs of that scan.
//
//   pac::TraceRecorder recorder;
//   recorder.AddBool("cmd.Execute", [&] { return cmd->EXECUTE.value != 0; });
//   recorder.AddBits("cmd.ErrorID", 16, [&] { return cmd->ERRORID.value; });
//   recorder.AttachTo(task);  // after the programs whose results it should see
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "pac/plc_task.hpp"
#include "pac/trace.hpp"

namespace pac {

class TraceRecorder {
public:
    // Signals are added before the first sample (std::invalid_argument otherwise, and for an empty probe).
    void AddBool(const std::string& path, std::function<bool()> probe);
    void AddBits(const std::string& path, int width, std::function<std::uint64_t()> probe);
    void AddReal(const std::string& path, std::function<double()> probe);

    // Reads every probe; `time` must be later than the previous sample's.
    void Sample(std::chrono::nanoseconds time);
    // Samples at the end of every scan of `task`, which must outlive this recorder's use.
    void AttachTo(PlcTask& task);

    const Trace& Recording() const { return trace_; }

private:
    using Probe = std::function<TraceValue()>;
    void Add(SignalInfo info, Probe probe);

    Trace trace_;
    std::vector<Probe> probes_;
    std::vector<TraceValue> sample_;  // reused by every Sample: a scan allocates nothing
};

}  // namespace pac
