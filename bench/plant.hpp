// Benchmark (not a test): one PA-CONTROL with its CMD, CTRL and axis modules on a pac::PacRig, the
// library's FB_PAC_Cmd, FB_PAC_Ctrl and one FB_PAC_Axis per axis module on them, and an application program
// that runs in the scans like a PLC program: it brings the controller to ONLINE through FB_PAC_Ctrl, then
// keeps the FBs busy: FB_PAC_Cmd writes and reads a register over and over, each axis moves back and forth
// between two absolute targets, each job ending with Execute low for one scan. Plants share nothing, so many
// of them can run side by side, scan for scan.
#pragma once

#include <chrono>
#include <memory>
#include <vector>

#include "axis_hand.h"
#include "pac/fb_instance.hpp"
#include "pac/pac_rig.hpp"
#include "pac/st_program.hpp"

namespace pac::bench {

struct PlantOptions {
    int axes = 8;  // 0..8 axis modules
    std::chrono::nanoseconds plcCycle{std::chrono::milliseconds(1)};
    std::chrono::nanoseconds pacCycle{std::chrono::milliseconds(10)};
    int latencyCycles = 0;  // bus latency each way, in PLC cycles
    bool commands = true;  // FB_PAC_Cmd sends one command after the other
    bool moves = true;     // every axis moves back and forth
    bool handWrittenAxes = false;  // the axes driven by the hand-written C (bench/axis_hand.c), not FB_PAC_Axis
};

class Plant {
public:
    explicit Plant(const PlantOptions& options);
    Plant(const Plant&) = delete;
    Plant& operator=(const Plant&) = delete;

    // Scans until the application program has brought the controller to ONLINE and started its commands
    // and moves. std::runtime_error if ONLINE is not reached within a simulated second.
    void GoOnline();
    bool Online() const { return phase_ == Phase::kRunning; }
    // One scan; std::runtime_error if FB_PAC_Ctrl refused ONLINE.
    void Scan(int n = 1) { plc_.Scan(n); }
    int ScanUntil(const std::function<bool()>& predicate, int maxScans) { return plc_.ScanUntil(predicate, maxScans); }

    // Stops or resumes the application program's new commands and moves (a running job ends normally).
    void SetCommands(bool on) { commands_ = on; }
    void SetMoves(bool on) { moves_ = on; }

    pac::FbInstance<FB_PAC_CMD>& Cmd() { return cmd_; }
    pac::FbInstance<FB_PAC_CTRL>& Ctrl() { return ctrl_; }
    pac::FbInstance<FB_PAC_AXIS>& Axis(int k) { return *axes_.at(static_cast<std::size_t>(k - 1)); }
    // With handWrittenAxes: the hand-written C of axis module k.
    AxisHand& HandAxis(int k) { return *handAxes_.at(static_cast<std::size_t>(k - 1)); }
    pac::PacRig& Plc() { return plc_; }
    // Jobs that ended with Done since construction: commands and axis moves.
    long CommandsDone() const { return commandsDone_; }
    long MovesDone() const { return movesDone_; }

private:
    enum class Phase { kBoot, kSettle, kRequest, kSettleOnline, kRunning };

    void CtrlProgram();
    void NextCommand();
    void NextMove(int k);
    void NextHandMove(int k);
    int ScansFor(std::chrono::milliseconds time) const;

    PlantOptions options_;
    pac::PacRig plc_;
    pac::FbInstance<FB_PAC_CMD> cmd_ = PAC_FB(FB_PAC_CMD);
    pac::FbInstance<FB_PAC_CTRL> ctrl_ = PAC_FB(FB_PAC_CTRL);
    std::vector<std::unique_ptr<pac::FbInstance<FB_PAC_AXIS>>> axes_;
    std::vector<std::unique_ptr<AxisHand>> handAxes_;
    Phase phase_ = Phase::kBoot;
    int phaseScans_ = 0;  // scans left in a settle phase
    bool commands_ = false;
    bool moves_ = false;
    long commandsDone_ = 0;
    long movesDone_ = 0;
};

// The controller's set-up for ONLINE as the plant has it: system parameter 4 names an external stop input
// (5.2.1.3), and that input is high. std::runtime_error if the simulator refuses it.
void AllowOnline(pac::sim::PaControl& pac);

// `count` plants with a controller cycle of `pacCycle` brought to ONLINE scan for scan, as in one runtime,
// then 200 scans more so that every axis is under way. std::runtime_error if one does not reach ONLINE.
std::vector<std::unique_ptr<Plant>> OnlinePlants(int count, std::chrono::nanoseconds pacCycle);

}  // namespace pac::bench
