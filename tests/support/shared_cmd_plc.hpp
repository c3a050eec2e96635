// A PLC program with several FB_PAC_Cmd on the one CMD interface of a simulated PA-CONTROL (docs/fb/
// FB_PAC_Cmd.md, "One interface, many FBs"), on one bus timing and one controller reading: the FBs in call
// order, the PLCopen checker on each after every scan, the commands the controller recognised (its
// exchange log), and the way to ONLINE a PLC program takes.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "command_plc.hpp"
#include "controller_readings.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/sim/cmd_frame.hpp"
#include "pac/st_program.hpp"

namespace pac::test {

class SharedCmdPlc {
public:
    // `fbs` FB_PAC_Cmd called in the order 0, 1, ...; `unwatched` more after them that the PLCopen checker
    // leaves alone (a test re-initialises them, as a PLC does at an online change or a restart).
    SharedCmdPlc(const SharingCase& c, int fbs, std::chrono::nanoseconds bootTime = std::chrono::nanoseconds(0),
                 int unwatched = 0)
        : plc_(c.timing, ConfigOf(c), bootTime) {
        fbs_.reserve(static_cast<std::size_t>(fbs + unwatched));  // plc_ keeps references: never reallocated
        for (int i = 0; i < fbs + unwatched; ++i) {
            fbs_.push_back(PAC_FB(FB_PAC_CMD));
            if (i < fbs) {
                plc_.Add("FB_PAC_Cmd #" + std::to_string(i), fbs_.back());
            } else {
                plc_.Rig().Call(fbs_.back());
            }
        }
        plc_.Start();
    }

    // Scans until the controller has booted and the PLC sees it, plus a round trip.
    void Boot() {
        for (int i = 0; i < 100000 && !Controller().Booted(); ++i) plc_.Scan();
        plc_.Scan(3 + 2 * plc_.Timing().latency + plc_.Timing().jitterUs / 1000 / plc_.Timing().plcMs);
        plc_.ScanPastFirstHandshake();
    }

    pac::FbInstance<FB_PAC_CMD>& Fb(int i) { return fbs_.at(static_cast<std::size_t>(i)); }
    int Fbs() const { return static_cast<int>(fbs_.size()); }

    // Latches a command into FB `i` (Execute unchanged).
    void Set(int i, std::uint16_t code, std::uint16_t param, std::uint32_t data = 0) {
        Fb(i)->CODE.value = code;
        Fb(i)->PARAM.value = param;
        Fb(i)->DATA.value = data;
    }
    FinalOutcome Run(int i, int maxScans = 200000) { return plc_.Run(Fb(i), maxScans); }

    // ONLINE as a PLC program gets there (5.2.1.3), through FB 0: system parameter 4 names the external
    // stop input 7, which has power, then 0603.
    bool GoOnline() {
        Set(0, 0x0700, 4, 7);
        if (!Run(0).Done()) return false;
        Controller().Io().inputs.Set(7, true);
        Set(0, 0x0603, 0, 0);
        if (!Run(0).Done()) return false;
        Scan(2 * (plc_.Timing().latency + 1));
        return Controller().OperatingStatus() == 31;
    }

    // The commands the controller recognised, oldest first (from its exchange log, read on from where the
    // last call stopped).
    const std::vector<pac::sim::CommandFrame>& CommandsSeen() {
        const auto& records = Controller().Log().Records();
        for (; logRead_ < records.size(); ++logRead_) {
            if (records[logRead_].newCommand) {
                seen_.push_back(pac::sim::CommandFrame::Decode(records[logRead_].toPac.Cmd()));
            }
        }
        return seen_;
    }
    // How often the controller recognised `code` with `param`.
    int Seen(std::uint16_t code, std::uint16_t param) {
        int n = 0;
        for (const auto& c : CommandsSeen()) n += c.code == code && c.parameter == param ? 1 : 0;
        return n;
    }

    void Scan(int n = 1) { plc_.Scan(n); }
    CommandPlc& Plc() { return plc_; }
    pac::sim::PaControl& Controller() { return plc_.Controller(); }
    const ST_PAC_CMDCHANNEL& Channel() { return plc_.Rig().Channel(); }
    pac::sim::Image8 Module() { return plc_.Rig().ToPac().Cmd(); }
    std::chrono::nanoseconds Now() const { return plc_.Now(); }
    const BusTiming& Timing() const { return plc_.Timing(); }

private:
    static pac::sim::PaControlConfig ConfigOf(const SharingCase& c) {
        pac::sim::PaControlConfig config = c.Config();
        config.logCapacity = 10000000;  // the whole test, never dropped: CommandsSeen() reads every command
        return config;
    }

    std::vector<pac::FbInstance<FB_PAC_CMD>> fbs_;  // before plc_, whose programs call them
    CommandPlc plc_;
    std::vector<pac::sim::CommandFrame> seen_;
    std::size_t logRead_ = 0;
};

}  // namespace pac::test
