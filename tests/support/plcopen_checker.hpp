// The PLCopen output rules, checked after every scan of an FB (docs/fb/FB_PAC_Cmd.md "PLCopen rules",
// the same for every command FB of the library):
//   - Busy, Done, Error and CommandAborted exclude each other;
//   - ErrorID <> 0 exactly when Error;
//   - a final output (Done, Error, CommandAborted) holds, with its ErrorID, while the command input
//     that started the job stays TRUE, and clears in the scan that sees it FALSE; if that input was
//     already FALSE when the job ended, the output shows for exactly one scan;
//   - Busy never lasts longer than the FB's own bound (its Timeout / EndTimeout), where it has one.
// A job superseded by a new one (FB_PAC_Axis: a new Execute edge or a jog ends the running job with
// CommandAborted in the edge scan) shows its CommandAborted in that scan only; the new job owns the
// outputs from then on. A scan in which a command input rises may begin a new job, so the previous
// final output need not hold into it.
// Reports the first violations of each FB with the scan; a test fails if any scan broke a rule.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "plcopen_pins.hpp"

namespace pac::test {

// A TIME pin's limit in force: T#0S (or less) is the pin's default on every pin of the library.
inline std::chrono::nanoseconds TimeInForce(std::chrono::nanoseconds pin, std::chrono::nanoseconds pinDefault) {
    return pin <= std::chrono::nanoseconds(0) ? pinDefault : pin;
}

// Whole PLC cycles a TON of `t` needs to run out.
inline int ScansOf(std::chrono::nanoseconds t, std::chrono::nanoseconds plcCycle) {
    return static_cast<int>((t + plcCycle - std::chrono::nanoseconds(1)) / plcCycle);
}

// The longest FB_PAC_Cmd (and every FB built on it) stays Busy: Timeout for the wait for the interface,
// one scan for the SEND flag of a two-step write, Timeout again for the acknowledgement, then EndTimeout
// for END OF PROCESSING; each timer runs out in the first scan at least its time after it started.
inline std::optional<int> CommandBusyBound(std::chrono::nanoseconds timeout, std::chrono::nanoseconds endTimeout,
                                           std::chrono::nanoseconds plcCycle) {
    using std::chrono::seconds;
    const int ack = ScansOf(TimeInForce(timeout, seconds(1)), plcCycle);
    return ack + 1 + ack + ScansOf(TimeInForce(endTimeout, seconds(60)), plcCycle);
}

// FB_PAC_Ctrl: Timeout from the edge scan (T#0S: T#10S).
inline std::optional<int> RequestBusyBound(std::chrono::nanoseconds timeout, std::chrono::nanoseconds plcCycle) {
    return ScansOf(TimeInForce(timeout, std::chrono::seconds(10)), plcCycle);
}

template <class Fb>
std::optional<int> CommandBusyBoundOf(const Fb& fb, std::chrono::nanoseconds plcCycle) {
    return CommandBusyBound(TimeoutOf(fb), CommandEndTimeoutOf(fb), plcCycle);
}

template <class Fb>
std::optional<int> RequestBusyBoundOf(const Fb& fb, std::chrono::nanoseconds plcCycle) {
    return RequestBusyBound(TimeoutOf(fb), plcCycle);
}

class PlcOpenChecker {
public:
    explicit PlcOpenChecker(std::string name) : name_(std::move(name)) {}

    // After each scan: the command inputs as that scan saw them, the outputs it left, and the FB's
    // longest Busy in scans as its pins stand (nullopt: no bound).
    void Check(std::int64_t scan, const CommandInputs& in, const PlcOpenOutputs& out,
               std::optional<int> busyBound = std::nullopt) {
        const bool rose = in.RoseSince(in_);
        Expect(out.Shown() <= 1, scan, "Busy, Done, Error and CommandAborted at once", out);
        Expect(out.error == (out.errorId != 0), scan, "ErrorID <> 0 not exactly with Error", out);
        if (held_ && !rose) {
            if (in.Any()) {
                Expect(out == *held_, scan, "the final output did not hold while the command input stayed TRUE", out);
            } else {
                Expect(!out.Final() && out.errorId == 0, scan,
                       "the final output did not clear in the scan that saw the command input FALSE", out);
            }
        }
        if (oneScan_ && !rose) Expect(!out.Final(), scan, "the final output showed for more than one scan", out);
        Follow(in, out, rose);
        busyScans_ = out.busy ? busyScans_ + 1 : 0;
        if (busyBound) Expect(busyScans_ <= *busyBound, scan, "Busy longer than the FB's Timeout allows", out);
    }

    template <class Fb>
    void Check(std::int64_t scan, const Fb& fb, std::optional<int> busyBound = std::nullopt) {
        Check(scan, InputsOf(fb), OutputsOf(fb), busyBound);
    }

    // A fresh FB instance (a PLC restart with a new program): nothing carries over from the old one.
    void Restart() {
        in_ = {};
        held_.reset();
        oneScan_ = false;
        wasBusy_ = false;
        busyScans_ = 0;
    }

    int Violations() const { return violations_; }

private:
    // What the next scan must show: the final output held (held_), or gone (oneScan_).
    void Follow(const CommandInputs& in, const PlcOpenOutputs& out, bool rose) {
        const bool continued = held_ && out == *held_ && !rose;
        const bool superseded = out.aborted && rose && wasBusy_;
        held_.reset();
        oneScan_ = false;
        if (out.Final() && !continued && (superseded || !in.Any())) {
            oneScan_ = true;
        } else if (out.Final() && in.Any()) {
            held_ = out;
        }
        wasBusy_ = out.busy;
        in_ = in;
    }

    void Expect(bool ok, std::int64_t scan, const char* rule, const PlcOpenOutputs& out) {
        if (ok) return;
        if (++violations_ <= kReported) ADD_FAILURE() << name_ << ", scan " << scan << ": " << rule << " (" << out << ")";
    }

    static constexpr int kReported = 5;

    std::string name_;
    CommandInputs in_;
    std::optional<PlcOpenOutputs> held_;
    bool oneScan_ = false;
    bool wasBusy_ = false;
    int busyScans_ = 0;
    int violations_ = 0;
};

}  // namespace pac::test
