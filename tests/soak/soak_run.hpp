// A soak run: for a seed and a number of scans, random jobs (commands, mode requests, axis jobs, jogs,
// aborts) and random faults (controller power cycles, link loss, frozen inputs, jitter, command errors,
// axis errors, limit switches, system errors) against the simulated PA-CONTROL. After every fault the
// library must recover without a PLC restart: ONLINE again through FB_PAC_Ctrl, a command Done through
// FB_PAC_Cmd and an axis move Done through FB_PAC_Axis, all within kRecoveryTime. SoakPlc checks every scan.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <string>

#include "pac/sim/rng.hpp"
#include "soak_plc.hpp"
#include "soak_report.hpp"

namespace pac::soak {

enum class Fault { kPowerCycle, kLinkLoss, kFrozenInputs, kJitter, kCommandError, kAxisError, kLimitSwitch, kSystemError };
constexpr std::size_t kFaultKinds = 8;
const char* FaultName(Fault fault);

struct SoakCounts {
    std::int64_t scans = 0;
    std::int64_t commands = 0;
    std::int64_t requests = 0;
    std::int64_t axisJobs = 0;
    std::int64_t jogs = 0;
    std::int64_t aborts = 0;
    std::array<std::int64_t, kFaultKinds> faults{};
    std::int64_t recoveries = 0;

    std::int64_t Jobs() const { return commands + requests + axisJobs + jogs; }
    std::int64_t Faults() const;
};

// The bus timing a seed gives: PLC cycle, controller cycle, latency and jitter.
RigTiming SoakTiming(std::uint64_t seed);

class SoakRun {
public:
    SoakRun(std::uint64_t seed, std::int64_t scans);

    void Run();
    const SoakCounts& Counts() const { return counts_; }
    const SoakReport& Report() const { return report_; }
    const SoakPlc& Plc() const { return plc_; }
    std::string Summary() const;

private:
    static constexpr std::chrono::seconds kRecoveryTime{30};

    void RandomScan();
    void RandomCommands();
    void RandomRequest();
    void RandomAxis();
    void MaybeFault();
    void EndFault();
    // Brings the machine back as a PLC program would, without a restart; false (a violation) if it fails.
    bool Recover(const std::string& when);

    void StartCommand(int fb);
    bool RunCommand(int fb, std::int64_t deadline);
    bool RunRequest(E_PAC_CTRLREQUEST request, std::int64_t deadline);
    bool RunAxisJob(E_PAC_AXISCOMMAND command, float position, std::int64_t deadline);
    // Scans until `done` holds or the deadline passes; false then.
    template <class Predicate>
    bool ScanUntil(Predicate done, std::int64_t deadline);
    void ScanOnce();
    // The state a failed recovery stopped in, for its message.
    std::string Describe();
    void ScanFor(std::chrono::nanoseconds t);
    bool Chance(std::uint64_t oneIn) { return rng_.UniformUpTo(oneIn - 1) == 0; }
    std::int64_t Draw(std::int64_t low, std::int64_t high);
    bool BudgetLeft() { return plc_.ScanCount() < scans_; }

    std::uint64_t seed_;
    std::int64_t scans_;
    pac::sim::SplitMix64 rng_;
    RigTiming timing_;
    SoakReport report_;
    SoakPlc plc_;
    SoakCounts counts_;
    std::uint32_t nextNumber_ = 1;
    // A fault in force until faultEnd_ (scan), or none.
    bool faultActive_ = false;
    Fault fault_ = Fault::kPowerCycle;
    std::int64_t faultEnd_ = 0;
    // Scans to hold Execute / a jog / Abort before letting it fall.
    std::array<int, SoakPlc::kCommandFbs> cmdHold_{};
    int ctrlHold_ = 0;
    int axisHold_ = 0;
    int jogScans_ = 0;
    int abortScans_ = 0;
    std::string lastAxisOutcome_;  // the outputs that ended the last axis job of a recovery
};

}  // namespace pac::soak
