// The PLCopen output rules, checked after every scan of an FB (docs/fb/FB_PAC_Cmd.md "PLCopen rules",
// the same for every command FB of the library):
//   - Busy, Done, Error and CommandAborted exclude each other;
//   - ErrorID <> 0 exactly when Error;
//   - a final output (Done, Error, CommandAborted) holds, with its ErrorID, while the command input
//     that started the job stays TRUE, and clears in the scan that sees it FALSE; if that input was
//     already FALSE when the job ended, the output shows for exactly one scan (Execute starts the job
//     when it rises together with a jog input; where a jog input rose and the output stayed the same,
//     either input may be the job's: the output may hold while one of them stays TRUE);
//   - Busy never lasts longer than the FB's own bound (its Timeout / EndTimeout), where it has one.
// A job superseded by a new one (FB_PAC_Axis: a new Execute edge or a jog ends the running job with
// CommandAborted in the edge scan) shows its CommandAborted in that scan; the new job owns the outputs
// from the next scan on (which may show its own CommandAborted, e.g. an Execute edge as Enable falls). A scan in which a command input rises may begin a new job, so the previous
// final output need not hold into it.
// Reports the first violations of each FB with the scan: by default as a GoogleTest failure, or to a
// reporter of the caller's (the fuzz targets and the soak program run outside GoogleTest).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <sstream>
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

// Receives one violation, described with the FB, the scan, the rule and the outputs.
using ViolationReporter = std::function<void(const std::string&)>;

inline void ReportAsTestFailure(const std::string& violation) { ADD_FAILURE() << violation; }

class PlcOpenChecker {
public:
    explicit PlcOpenChecker(std::string name, ViolationReporter report = ReportAsTestFailure)
        : name_(std::move(name)), report_(std::move(report)) {}

    // After each scan: the command inputs as that scan saw them, the outputs it left, and the FB's
    // longest Busy in scans as its pins stand (nullopt: no bound).
    void Check(std::int64_t scan, const CommandInputs& in, const PlcOpenOutputs& out,
               std::optional<int> busyBound = std::nullopt) {
        const unsigned rising = in.RoseMaskSince(in_);
        const bool rose = rising != 0;
        if (rose) NewJob(rising, out);
        Expect(out.Shown() <= 1, scan, "Busy, Done, Error and CommandAborted at once", out);
        Expect(out.error == (out.errorId != 0), scan, "ErrorID <> 0 not exactly with Error", out);
        if (held_ && !rose) {
            const unsigned holding = in.Mask() & starters_;
            if (holding == starters_) {
                Expect(out == *held_, scan, "the final output did not hold while the command input stayed TRUE", out);
            } else if (holding == 0) {
                Expect(!out.Final() && out.errorId == 0, scan,
                       "the final output did not clear in the scan that saw the command input FALSE", out);
            } else {
                Expect(out == *held_ || (!out.Final() && out.errorId == 0), scan,
                       "the final output neither held nor cleared", out);
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
        starters_ = CommandInputs::kExecute;
        held_.reset();
        oneScan_ = false;
        wasBusy_ = false;
        afterSupersede_ = false;
        busyScans_ = 0;
    }

    int Violations() const { return violations_; }

private:
    // The inputs that may have started the job in a scan where `rising` rose. An Execute edge always
    // begins a new job (it ends a jog). A jog edge while a job runs or stops is ignored, and one that leaves the
    // final output unchanged may have begun nothing (both jog inputs TRUE) or a new job that ended alike:
    // either input may govern the job's final output.
    void NewJob(unsigned rising, const PlcOpenOutputs& out) {
        if ((rising & CommandInputs::kExecute) != 0) {
            starters_ = CommandInputs::kExecute;
        } else if (wasBusy_ || afterSupersede_ || (held_ && out == *held_)) {
            starters_ |= rising;
        } else {
            starters_ = rising;
        }
    }

    // What the next scan must show: the final output held (held_), or gone (oneScan_).
    void Follow(const CommandInputs& in, const PlcOpenOutputs& out, bool rose) {
        const bool continued = held_ && out == *held_ && !rose;
        const bool superseded = out.aborted && rose && wasBusy_;
        if (continued) starters_ &= in.Mask();  // held: the job's input is one of those still TRUE
        const bool starterHeld = (in.Mask() & starters_) != 0;
        held_.reset();
        oneScan_ = false;
        afterSupersede_ = superseded;
        if (superseded) {
            // The next scan is the new job's: it may show that job's own final output already.
        } else if (out.Final() && !continued && !starterHeld) {
            oneScan_ = true;
        } else if (out.Final() && starterHeld) {
            held_ = out;
        }
        wasBusy_ = out.busy;
        in_ = in;
    }

    void Expect(bool ok, std::int64_t scan, const char* rule, const PlcOpenOutputs& out) {
        if (ok) return;
        if (++violations_ > kReported) return;
        std::ostringstream text;
        text << name_ << ", scan " << scan << ": " << rule << " (" << out << ")";
        report_(text.str());
    }

    static constexpr int kReported = 5;

    std::string name_;
    ViolationReporter report_;
    CommandInputs in_;
    unsigned starters_ = CommandInputs::kExecute;  // the inputs that may have started the current job
    std::optional<PlcOpenOutputs> held_;
    bool oneScan_ = false;
    bool wasBusy_ = false;
    bool afterSupersede_ = false;  // the last scan ended a job for a new one
    int busyScans_ = 0;
    int violations_ = 0;
};

}  // namespace pac::test
