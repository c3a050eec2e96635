// What every fuzz target shares: a PLC (a simulated clock and a task whose cycle the input picks), the
// length of one run, the short times the inputs give the FBs' Timeout pins, and what a broken invariant
// does: it prints the rule and aborts, so libFuzzer keeps the input as a crash and the corpus replay under
// ctest fails on it.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_bytes.hpp"
#include "pac/iec_time.hpp"
#include "pac/plc_task.hpp"
#include "pac/sim_clock.hpp"
#include "plcopen_checker.hpp"

namespace pac::fuzz {

[[noreturn]] inline void Violation(const std::string& what) {
    std::fprintf(stderr, "invariant broken: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

// PAC_FUZZ_TRACE=1 in the environment: the targets print every scan, to see how an input broke a rule.
inline bool TraceWanted() { return std::getenv("PAC_FUZZ_TRACE") != nullptr; }

inline pac::test::ViolationReporter AbortOnViolation() {
    return [](const std::string& violation) { Violation(violation); };
}

// Scans driven by the input; longer inputs are cut (libFuzzer's -max_len keeps them short anyway).
constexpr int kMaxInputScans = 3000;
// After the input, scans go on (every read of the input gives zero: inputs low, controller bytes held)
// while an FB is Busy, at most this long: longer than the longest bound the inputs can give an FB
// (FB_PAC_Cmd: Timeout T#0S means T#1S, plus EndTimeout up to 255 ms), so an FB that would stay Busy past
// its own bound is caught.
constexpr std::chrono::milliseconds kSettleTime{1500};

// A Timeout pin's value: mostly short (1..255 ms) so that timeouts happen within a run, sometimes
// T#0S (the FB's default or "no limit", as the pin documents).
inline TIME ShortTime(FuzzBytes& in) {
    return pac::ToIecTime(std::chrono::milliseconds(in.Byte()));
}

// The scans every input of this process ran, for the fuzz figures in scans and not only in inputs. A count
// that outlives the runs because libFuzzer calls the target once per input and ends the process itself;
// printed when the process exits normally (a timed fuzz run, a corpus replay).
class ScanTally {
public:
    static void Add(std::int64_t scans) {
        static const bool printAtExit = std::atexit(Print) == 0;
        (void)printAtExit;
        Total() += scans;
    }

private:
    static std::int64_t& Total() {
        static std::int64_t total = 0;
        return total;
    }
    static void Print() { std::fprintf(stderr, "scans run: %lld\n", static_cast<long long>(Total())); }
};

// The PLC: one task at a cycle of 1..16 ms taken from the input.
class FuzzPlc {
public:
    explicit FuzzPlc(FuzzBytes& in) : task_(clock_, std::chrono::milliseconds(1 + in.Below(16))) {}

    pac::PlcTask& Task() { return task_; }
    std::chrono::nanoseconds Cycle() const { return task_.CycleTime(); }

    // Scans the task (whose program reads each scan's decisions from the input) for the input, then while
    // `busy` holds, at most kSettleTime.
    template <class BusyFn>
    void Run(FuzzBytes& in, BusyFn&& busy) {
        for (int i = 0; i < kMaxInputScans && !in.Exhausted(); ++i) task_.Scan();
        const auto settleScans = kSettleTime / task_.CycleTime() + 1;
        for (std::int64_t i = 0; i < settleScans && busy(); ++i) task_.Scan();
        ScanTally::Add(task_.ScanCount());
    }

private:
    pac::SimClock clock_;
    pac::PlcTask task_;
};

// A target's LLVMFuzzerTestOneInput: one FuzzRun, constructed on the input, run once.
template <class FuzzRun>
int RunOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzBytes in(data, size);
    FuzzRun run(in);
    run.Run();
    return 0;
}

}  // namespace pac::fuzz
