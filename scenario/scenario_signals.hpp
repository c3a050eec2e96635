// The signals of a scenario run, as a trace records them: the modules' bytes as they go out and come
// in, the protocol's flags decoded from them, the pins of the FB on each module, and each simulated
// axis's real position (docs/scenario.md#traces-and-diagrams). Scopes:
//   cmd                  ToPac, FromPac (PAC byte 0 first), SEND, RF, KF, BF, Status
//   cmd.FB_PAC_Cmd       Execute, Busy, Done, Error, ErrorID, AckData
//   ctrl                 ToPac, FromPac, Control, Status, SystemErrorNumber (with the CTRL interface)
//   ctrl.control         the control word's bits (2.5.1); ctrl.status: the status word's bits (2.5.2)
//   ctrl.FB_PAC_Ctrl     Execute, Busy, Done, Error, ErrorID
//   axisK                Control, Acceleration, Speed, TargetPosition as sent; Status, CmdErrorNumber,
//                        AxisErrorNumber, Position as received (2.7.1, 2.7.2)
//   axisK.control        the control word's bits; axisK.status: the status word's bits
//   axisK.FB_PAC_Axis    Enable, Execute, ResetError, Enabled, Busy, Done, Error, CommandAborted, ErrorID,
//                        ActualPosition
//   axisK.sim            Position: where the simulated axis is
#pragma once

#include <map>
#include <string>
#include <vector>

#include "pac/trace_recorder.hpp"
#include "scenario.hpp"
#include "scenario_runner.hpp"

namespace pac::scenario {

// How a diagram writes a signal's values.
enum class ValueFormat { kBit, kHex, kBytes, kDecimal, kErrorId, kReal };

class ScenarioSignals {
public:
    // Adds the signals of `modules` to `recorder`; both must outlive this object, which must not move
    // (the probes read the scan it is given).
    ScenarioSignals(const Modules& modules, TraceRecorder& recorder);
    ScenarioSignals(const ScenarioSignals&) = delete;
    ScenarioSignals& operator=(const ScenarioSignals&) = delete;

    // Samples the recorder with the values of `sample`.
    void Sample(const ScanSample& sample);

    ValueFormat FormatOf(const std::string& path) const;  // std::out_of_range for a path it did not add

    // The paths a scenario with `modules` records, in order (for the loader's checks of a diagram).
    static std::vector<std::string> Paths(const Modules& modules);

private:
    void AddCmd();
    void AddCtrl();
    void AddAxis(int axis);
    void AddDiagnosis();
    void Add(const std::string& path, ValueFormat format, int width, std::function<std::uint64_t(const ScanSample&)> read);
    void AddReal(const std::string& path, std::function<double(const ScanSample&)> read);

    TraceRecorder& recorder_;
    const ScanSample* current_ = nullptr;
    std::map<std::string, ValueFormat> formats_;
};

}  // namespace pac::scenario
