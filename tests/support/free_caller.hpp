// One Execute FB in a PLC program as free as real ones (the calling contracts of docs/fb/*.md): the program
// calls it or leaves it out in every scan (runs of 1 to 6 scans, as a CASE step or an IF branch leaves it
// out), edges a new command once the FB was called idle with Execute FALSE, lets Execute fall while the FB is
// Busy (seen at its next call), holds it a few scans after the final output, and may stop calling the FB for
// good. Every random choice comes from the generator the test seeds (and prints). After each call the PLCopen
// checker runs on the call's inputs and outputs (the FB sees its pins only when called), and the time since
// the Execute edge is checked against the FB's documented bound on Busy.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "pac/sim/pa_control.hpp"
#include "plcopen_checker.hpp"
#include "plcopen_pins.hpp"

namespace pac::test {

// How often, in one draw per scan, the program does each thing (1 in n).
struct FreeCallerOdds {
    std::uint32_t newCommand = 5;    // an idle FB gets a new command (0: only scripted ones)
    std::uint32_t skipRun = 6;       // a run of 1 to maxSkip scans without the call begins
    int maxSkip = 6;
    std::uint32_t earlyFall = 300;   // Execute falls while the FB is Busy
    std::uint32_t abandon = 0;       // the program stops calling a Busy FB for good (0: never)
};

// Violations of the free programs' properties, with the scan and time, the first few of a test.
class ViolationLog {
public:
    void Add(long scan, std::chrono::nanoseconds now, const std::string& what) {
        if (texts_.size() >= 5) return;
        std::ostringstream out;
        out << "scan " << scan << ", t=" << std::chrono::duration_cast<std::chrono::microseconds>(now).count() / 1000.0
            << " ms: " << what;
        texts_.push_back(out.str());
    }
    const std::vector<std::string>& Texts() const { return texts_; }

private:
    std::vector<std::string> texts_;
};

class FreeCaller {
public:
    enum class Ended { kNo, kDone, kError, kAborted };

    FreeCaller(std::string name, std::mt19937_64& random, FreeCallerOdds odds, ViolationLog& log)
        : name_(std::move(name)), random_(random), odds_(odds), log_(log), checker_(name_, [this](const std::string& v) {
              log_.Add(scan_, now_, v);
          }) {}
    FreeCaller(const FreeCaller&) = delete;  // its checker reports through `this`
    FreeCaller& operator=(const FreeCaller&) = delete;

    // The program's decisions for this scan, before the FB's place in it: true when it calls the FB. A new
    // command is asked for (Execute rises) only while the FB is idle; its edge is the next call.
    bool Plan(long scan, std::chrono::nanoseconds now) {
        scan_ = scan;
        now_ = now;
        newCommand_ = false;
        if (script_) return PlanScript();
        if (abandoned_) return false;
        if (!execute_) {
            if (lowSeen_ && odds_.newCommand != 0 && Draw(odds_.newCommand) == 0) {
                execute_ = true;
                lowSeen_ = false;
                edgeSeen_ = false;
                finalSeen_ = false;
                newCommand_ = true;
            }
        } else if (finalSeen_) {
            if (holdAfterFinal_-- <= 0) execute_ = false;
        } else if (edgeSeen_ && odds_.earlyFall != 0 && Draw(odds_.earlyFall) == 0) {
            execute_ = false;  // seen at the next call: the final output shows for that call only
        }
        if (edgeSeen_ && !finalSeen_ && odds_.abandon != 0 && Draw(odds_.abandon) == 0) {
            abandoned_ = true;
            ++abandons_;
            return false;
        }
        if (skip_ > 0) {
            --skip_;
            ++skips_;
            return false;
        }
        if (Draw(odds_.skipRun) == 0) {
            skip_ = static_cast<int>(Draw(static_cast<std::uint32_t>(odds_.maxSkip)));  // this scan and up to 5 more
            ++skips_;
            if (edgeSeen_ && !finalSeen_) ++skipsWhileBusy_;
            return false;
        }
        return true;
    }

    // A named case instead of random choices, for an idle FB: Execute rises in the next scan (the FB is called:
    // its edge), the calls `from` to `from + length - 1` scans after the edge are left out, and with `fall`
    // Execute falls in the first of them; every other scan calls the FB, and Execute falls in the scan after a
    // final output. ScriptOver() once the FB was called idle with Execute FALSE after it.
    void Script(int from, int length, bool fall) {
        script_ = true;
        scriptStarted_ = false;
        from_ = from;
        length_ = length;
        fall_ = fall;
        lastEnded_ = Ended::kNo;
    }
    bool ScriptOver() const { return script_ && scriptStarted_ && lowSeen_ && !execute_; }
    // How the scripted command ended (kNo: not yet).
    Ended LastEnded() const { return lastEnded_; }
    void EndScript() { script_ = false; }

    // The program's Execute for this scan's call.
    bool Execute() const { return execute_; }
    // A new command was asked for in this scan: latch its inputs now (they are the FB's at its edge).
    bool NewCommand() const { return newCommand_; }

    // Before the call: whether the call sees the Execute edge (returns true once per command).
    bool EdgeAtThisCall(const PlcOpenOutputs& before) {
        if (!execute_ || edgeSeen_ || before.busy || before.Final()) return false;
        edgeSeen_ = true;
        edgeTime_ = now_;
        return true;
    }

    // After the call: the PLCopen rules on what the call saw and left; what ended in it for this command.
    Ended AfterCall(const CommandInputs& in, const PlcOpenOutputs& out, std::chrono::nanoseconds busyBound) {
        checker_.Check(scan_, in, out);
        if (!in.execute && !out.busy && !out.Final()) lowSeen_ = true;
        if (!edgeSeen_ || finalSeen_) return Ended::kNo;
        if (out.busy && now_ - edgeTime_ > busyBound) {
            log_.Add(scan_, now_, name_ + " still Busy " + std::to_string((now_ - edgeTime_) / std::chrono::milliseconds(1)) +
                                      " ms after its edge");
        }
        if (!out.Final()) return Ended::kNo;
        finalSeen_ = true;
        holdAfterFinal_ = script_ ? 0 : static_cast<int>(Draw(4));
        lastEnded_ = out.done ? Ended::kDone : (out.error ? Ended::kError : Ended::kAborted);
        return lastEnded_;
    }

    // The program calls a fresh instance in place of the abandoned one: it starts idle.
    void Replace() {
        abandoned_ = false;
        execute_ = false;
        lowSeen_ = true;
        edgeSeen_ = false;
        finalSeen_ = false;
        skip_ = 0;
        checker_.Restart();
    }

    bool Abandoned() const { return abandoned_; }
    std::chrono::nanoseconds EdgeTime() const { return edgeTime_; }
    int Skips() const { return skips_; }
    int SkipsWhileBusy() const { return skipsWhileBusy_; }
    int Abandons() const { return abandons_; }
    const std::string& Name() const { return name_; }
    std::uint32_t Draw(std::uint32_t n) { return std::uniform_int_distribution<std::uint32_t>(0, n - 1)(random_); }

private:
    bool PlanScript() {
        if (!scriptStarted_) {
            scriptStarted_ = true;
            execute_ = true;
            lowSeen_ = false;
            edgeSeen_ = false;
            finalSeen_ = false;
            newCommand_ = true;
            sinceEdge_ = 0;
            return true;
        }
        ++sinceEdge_;
        if (finalSeen_) execute_ = false;
        const bool away = sinceEdge_ >= from_ && sinceEdge_ < from_ + length_;
        if (fall_ && sinceEdge_ == from_) execute_ = false;
        if (away) {
            ++skips_;
            if (!finalSeen_) ++skipsWhileBusy_;
        }
        return !away;
    }

    std::string name_;
    std::mt19937_64& random_;
    FreeCallerOdds odds_;
    ViolationLog& log_;
    long scan_ = 0;
    std::chrono::nanoseconds now_{0};
    bool execute_ = false;
    bool lowSeen_ = true;    // called idle with Execute FALSE since the last command: the next rise is an edge
    bool edgeSeen_ = false;  // the present command's edge was seen by a call
    bool finalSeen_ = false;
    bool newCommand_ = false;
    bool abandoned_ = false;
    int skip_ = 0;
    int holdAfterFinal_ = 0;
    std::chrono::nanoseconds edgeTime_{0};
    int skips_ = 0;
    int skipsWhileBusy_ = 0;
    int abandons_ = 0;
    bool script_ = false;
    bool scriptStarted_ = false;
    int from_ = 0;
    int length_ = 0;
    bool fall_ = false;
    long sinceEdge_ = 0;
    Ended lastEnded_ = Ended::kNo;
    PlcOpenChecker checker_;
};

// Now and then the controller's operating status reads 0 for one or two scans (a status-0 blip), then 31 again.
class StatusBlips {
public:
    // Before a scan: ends a blip, or begins one (1 in `odds`) while `allowed` and the status is 31.
    void BeforeScan(pac::sim::PaControl& pac, std::mt19937_64& random, bool allowed, int odds = 800) {
        if (left_ > 0 && --left_ == 0) pac.SetOperatingStatus(31);
        if (!allowed || left_ != 0 || pac.OperatingStatus() != 31) return;
        if (std::uniform_int_distribution<int>(0, odds - 1)(random) == 0) {
            pac.SetOperatingStatus(0);
            left_ = 1 + std::uniform_int_distribution<int>(0, 1)(random);
            ++count_;
        }
    }
    int Count() const { return count_; }

private:
    int left_ = 0;
    int count_ = 0;
};

// The jobs an axis module took over on a Start edge (AxisModule::TakenJobs), each claimed by one FB's Done.
class AxisJobClaims {
public:
    // Claims the first unclaimed job from index `from` on that `matches`; false if there is none.
    // The ledger must still keep job `from` (std::out_of_range otherwise: the test ran too many jobs between).
    bool Claim(const pac::sim::TakenAxisJobLedger& jobs, std::size_t from,
               const std::function<bool(const pac::sim::AxisModuleCommand&)>& matches) {
        claimed_.resize(jobs.size(), false);
        for (std::size_t k = from; k < jobs.size(); ++k) {
            if (claimed_[k] || !matches(jobs[k].command)) continue;
            claimed_[k] = true;
            return true;
        }
        return false;
    }

private:
    std::vector<bool> claimed_;
};

// The runs left out while Busy, over the blocks of a program (each with a `caller`).
template <class Blocks>
int SkipsWhileBusyOf(const Blocks& blocks) {
    int n = 0;
    for (const auto& b : blocks) n += b->caller->SkipsWhileBusy();
    return n;
}

// Calls `fb` as the program does in this scan (FreeCaller::Plan said so): the Execute in, the command latched by
// `latch` (the program's inputs of a new command), the body by `call`, then the rules.
template <class Fb>
FreeCaller::Ended CallFree(FreeCaller& caller, Fb& fb, std::chrono::nanoseconds busyBound, const std::function<void()>& call,
                           const std::function<void()>& atEdge) {
    fb->EXECUTE.value = caller.Execute() ? TRUE : FALSE;
    if (caller.EdgeAtThisCall(OutputsOf(fb)) && atEdge) atEdge();
    call();
    return caller.AfterCall(InputsOf(fb), OutputsOf(fb), busyBound);
}

}  // namespace pac::test
