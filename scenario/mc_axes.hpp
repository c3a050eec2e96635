// The axis modules of a scenario with "mc_blocks": per module the library's FB_PAC_McAxis and one instance of
// the PLCopen blocks an axes step drives (MC_Power for "enable", MC_Reset for "reset_error", and the job's
// MC_Home / MC_MoveAbsolute / MC_MoveRelative / MC_Halt / MC_Stop), all on the axis's ST_PAC_AxisRef, in
// place of FB_PAC_Axis (docs/scenario.md). Velocity and acceleration stay per mille in the scenario: the
// blocks get them in units of the simulator's axis parameters (1000 AE/s, 10000 AE/s2).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "POUS.h"

#include "pac/fb_instance.hpp"
#include "pac/pac_rig.hpp"
#include "scenario.hpp"
#include "scenario_runner.hpp"

namespace pac::scenario {

class McAxes {
public:
    // Registers on `plc`, module by module: FB_PAC_McAxis (`wire` sets its OpStatus, ModeChange, IntegerMode
    // before each call), then the blocks.
    McAxes(pac::PacRig& plc, int axes, std::function<void(FB_PAC_MCAXIS&)> wire);
    ~McAxes();
    McAxes(const McAxes&) = delete;
    McAxes& operator=(const McAxes&) = delete;

    void Begin(const AxisJob& job);  // Enable, and Execute of the job's block (or of MC_Reset)
    bool Finished(const AxisJob& job);
    void End(const AxisJob& job);  // Execute back to FALSE
    void Fill(AxisSample& sample);  // the pins of the block axis `sample.axis` ran last
    void Take(int axis, AxisOutcome& outcome);
    bool OwnsModule(int axis);  // FB_PAC_McAxis.OwnsModule as its last call left it

private:
    struct Axis;
    Axis& At(int axis);
    std::vector<std::unique_ptr<Axis>> axes_;
};

}  // namespace pac::scenario
