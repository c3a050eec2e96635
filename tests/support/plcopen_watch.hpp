// Runs the PLCopen checker (plcopen_checker.hpp) on every FB of a PLC task after every scan, each FB
// with its own bound for Busy: a test adds its FBs by kind and attaches the watch to the task once the
// FBs' programs are registered, so the check runs after all of them.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pac/fb_instance.hpp"
#include "pac/plc_task.hpp"
#include "plcopen_checker.hpp"

namespace pac::test {

class PlcOpenWatch {
public:
    explicit PlcOpenWatch(std::chrono::nanoseconds plcCycle, ViolationReporter report = ReportAsTestFailure)
        : plcCycle_(plcCycle), report_(std::move(report)) {}
    PlcOpenWatch(const PlcOpenWatch&) = delete;
    PlcOpenWatch& operator=(const PlcOpenWatch&) = delete;

    // FB_PAC_Cmd and the FBs built on it: Busy at most Timeout + EndTimeout.
    template <class Fb>
    void AddCommand(std::string name, const pac::FbInstance<Fb>& fb) {
        Add(std::move(name), fb, [this, &fb] { return CommandBusyBoundOf(fb, plcCycle_); });
    }
    // FB_PAC_Ctrl: Busy at most Timeout.
    template <class Fb>
    void AddRequest(std::string name, const pac::FbInstance<Fb>& fb) {
        Add(std::move(name), fb, [this, &fb] { return RequestBusyBoundOf(fb, plcCycle_); });
    }
    // FB_PAC_Axis: a move has no bound of its own.
    template <class Fb>
    void AddJob(std::string name, const pac::FbInstance<Fb>& fb) {
        Add(std::move(name), fb, [] { return std::optional<int>(); });
    }

    // Registers the check as the task's next program: call after the FBs' programs.
    void Attach(pac::PlcTask& task) {
        task.AddProgram([this, &task] {
            for (const auto& check : checks_) check(task.ScanCount());
        });
    }

private:
    template <class Fb, class Bound>
    void Add(std::string name, const pac::FbInstance<Fb>& fb, Bound bound) {
        auto checker = std::make_shared<PlcOpenChecker>(std::move(name), report_);
        // The bound matters only in a Busy scan (a scan without Busy counts 0 Busy scans, within every
        // bound), so it is worked out only then: the watch runs after every scan of every test.
        checks_.push_back([checker, &fb, bound](std::int64_t scan) {
            const PlcOpenOutputs out = OutputsOf(fb);
            checker->Check(scan, InputsOf(fb), out, out.busy ? bound() : std::nullopt);
        });
    }

    std::chrono::nanoseconds plcCycle_;
    ViolationReporter report_;
    std::vector<std::function<void(std::int64_t)>> checks_;
};

}  // namespace pac::test
