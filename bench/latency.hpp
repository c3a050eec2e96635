// Benchmark (not a test): scans from Execute to Done against the protocol minimum, for FB_PAC_Cmd alone
// and for several command FBs started in the same scan on the one CMD interface they share.
#pragma once

#include <chrono>

#include "pac/pac_rig.hpp"

namespace pac::bench {

struct LatencyRow {
    int commands = 0;       // jobs measured
    int scansMin = 1 << 30;  // from the Execute edge to the (last) Done
    int scansMax = 0;
    int minimumMin = 1 << 30;  // the protocol minimum of the same jobs
    int minimumMax = 0;
    int aboveMinimum = 0;  // jobs whose Done came later than the protocol allows, or never

    void Add(int scans, int minimum, bool done);
    void Merge(const LatencyRow& other);
};

// FB_PAC_Cmd: `commands` commands one after the other on `timing`, the Execute edge at varying phases
// against the controller's cycle.
LatencyRow MeasureCmd(const pac::RigTiming& timing, int commands);

// `fbs` element FBs (FB_PAC_WriteIntReg and FB_PAC_ReadIntReg in turn) on one CMD interface, all started
// in the same scan, `rounds` times: scans until the last one is Done, against the sum of the protocol
// minima of the commands one after the other (each goes out in the scan that shows the one before it done).
LatencyRow MeasureShared(const pac::RigTiming& timing, int fbs, int rounds);

// Commands per simulated second through one CMD interface shared by `fbs` element FBs (FB_PAC_WriteIntReg
// and FB_PAC_ReadIntReg in turn), each sending its next command as soon as its last one is final (Execute
// low for one scan between), over `scans` scans, next to the protocol's bound for the same commands.
struct SharedRate {
    double commandsPerSecond = 0;  // all FBs together, Done only
    double protocolPerSecond = 0;  // the same commands back to back, each at the protocol minimum
    long fewestPerFb = 0;          // Done of the FB served least and most: the queue's fairness
    long mostPerFb = 0;
    long errors = 0;
};
SharedRate MeasureSharedRate(const pac::RigTiming& timing, int fbs, int scans);

}  // namespace pac::bench
