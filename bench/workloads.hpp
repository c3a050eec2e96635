// Benchmark (not a test): the workloads whose instructions callgrind counts. Each sets its PLC up, then
// runs `scans` measured scans between CALLGRIND_ZERO_STATS and CALLGRIND_DUMP_STATS, so that the dump holds
// the measured scans only; under callgrind's --toggle-collect=<function> it holds that function's cost.
#pragma once

#include <string>
#include <vector>

#include "pac/pac_rig.hpp"

namespace pac::bench {

struct Workload {
    std::string name;
    std::vector<std::string> functions;  // what --toggle-collect counts (callgrind's demangled names)
};

// The functions a workload's rows are measured on.
namespace measured {
// The rig runs a command FB on its channel (pacst's C: the body on the channel itself; MATIEC's: through the member).
#ifdef PACST_BODY_REF
inline const char* const kCmd = "FB_PAC_CMD_body_ref__";
#else
inline const char* const kCmd = "FB_PAC_CMD_body__";
#endif
inline const char* const kCmdInterface = "FB_PAC_CMDINTERFACE_body__";
inline const char* const kHandWritten = "CmdHandshakeScan";
inline const char* const kAxisHandWritten = "AxisHandScan";
inline const char* const kCtrl = "FB_PAC_CTRL_body__";
inline const char* const kCtrlHandWritten = "CtrlHandScan";
inline const char* const kAxis = "FB_PAC_AXIS_body__";
inline const char* const kAutomatic = "FB_PAC_AUTOMATICMODULE_body__";
inline const char* const kScan = "pac::PlcTask::Scan()";
inline const char* const kSimulator = "pac::sim::PaControl::Cycle*";
inline const char* const kBusRead = "pac::sim::Bus::ReadFromPac*";
inline const char* const kBusWrite = "pac::sim::Bus::WriteToPac*";
}  // namespace measured

struct WorkloadResult {
    int scans = 0;  // measured
    long jobs = 0;  // jobs that ended with Done in the measured scans
};

// Runs workload `name` ("cmd-idle", "cmd-job", "c-idle", "c-job", "ctrl-idle", "ctrl-job", "ctrl-c-idle",
// "ctrl-c-job" (the hand-written C of FB_PAC_Ctrl), "axis-idle", "axis-job", "axis-c-idle", "axis-c-job" (the
// hand-written C of the axis), "automatic-idle", "automatic-job", "plant-pac1", "plant-pac10") with `scans`
// measured scans;
// "plants-N": N plants at a 10 ms controller cycle, `scans` PLC cycles of N scans each (the scale rows);
// "plants-N-pacM": the same at a controller cycle of M ms.
// std::invalid_argument for another name.
WorkloadResult RunWorkload(const std::string& name, int scans);

// FB_PAC_CmdInterface with FB_PAC_Cmd and the hand-written C handshake side by side on two benches of the
// same timing, the same jobs (writes, reads and a refused code) for `scans` scans: the first scan where
// the CMD module or an output differs, described; empty if they agree on every scan.
std::string CompareWithHandWritten(const pac::RigTiming& timing, int scans);

// FB_PAC_Axis and the hand-written C of one axis (bench/axis_hand.c) in two plants of the same timing, with
// the same moves, aborts, Axis OFF, refused and superseded jobs, ONLINE stopped and started again and a lost
// link for `scans` scans after ONLINE:
// the first scan where the axis module or an output differs, described; empty if they agree on every scan.
std::string CompareAxisWithHandWritten(const pac::RigTiming& timing, int scans);

// FB_PAC_Ctrl and its hand-written C (bench/ctrl_hand.c) on two benches of the same timing, with every request
// in turn and a lost link for `scans` scans: the first scan where the CTRL module or an output differs,
// described; empty if they agree on every scan.
std::string CompareCtrlWithHandWritten(const pac::RigTiming& timing, int scans);

}  // namespace pac::bench
