// Records the bus modules of a PacRig in a TraceRecorder, as every test on the rig can: each
// module as the PLC writes it (at the end of a scan) and as the scan read the PA-CONTROL's reply. 8-byte
// modules (CMD, CTRL) are one 64-bit value each, PAC byte 0 the most significant, so the hex digits read
// as the bytes do: cmd.ToPac, cmd.FromPac, ctrl.ToPac, ctrl.FromPac. A 12-byte axis module k is split at
// its fields (2.7.1, 2.7.2): axisK.Control, .Acceleration, .Speed, .TargetPositionRaw as sent,
// axisK.Status, .CmdErrorNumber, .AxisErrorNumber, .PositionRaw as received (positions as the bits on
// the wire: their format depends on the CTRL interface's integer mode).
#pragma once

#include "pac/pac_rig.hpp"
#include "pac/trace_recorder.hpp"

namespace pac {

// Adds the signals; attach the recorder to rig.Task() after rig.Start() so that a sample holds the
// images of the whole scan. The rig must outlive the recorder's sampling.
void TraceBusModules(TraceRecorder& recorder, const PacRig& rig);

}  // namespace pac
