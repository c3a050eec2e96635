// Commands per second through one CMD interface shared by N FB_PAC_Cmd that re-trigger as fast as a PLC
// program can (Execute falls for one scan after each final output), against the simulated PA-CONTROL, next
// to the protocol's bound: the same commands sent back to back, each acknowledged after the fewest scans
// the bus and the controller's cycle allow (PacPlcBench::ProtocolMinimumScans from the scan it was sent).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

#include "pac/fb_instance.hpp"
#include "pac/pac_plc_bench.hpp"
#include "pac/st_program.hpp"

namespace pac::bench {

struct Throughput {
    int commands = 0;
    double perSecond = 0.0;          // achieved
    double protocolPerSecond = 0.0;  // the bound for the same commands
    double Ratio() const { return protocolPerSecond > 0.0 ? perSecond / protocolPerSecond : 0.0; }
};

inline Throughput SharedInterfaceThroughput(const pac::PlcBenchTiming& timing, int fbs, int commands) {
    pac::PacPlcBench plc(timing);
    std::vector<pac::FbInstance<FB_PAC_CMD>> cmds;
    cmds.reserve(static_cast<std::size_t>(fbs));  // the bench keeps references
    for (int i = 0; i < fbs; ++i) {
        cmds.push_back(PAC_FB(FB_PAC_CMD));
        plc.Call(cmds.back());
    }
    plc.Start();
    plc.Scan(10 + 2 * timing.latencyCycles);
    for (int i = 0; i < fbs; ++i) {
        cmds[static_cast<std::size_t>(i)]->CODE.value = 0x0906;  // N(i + 1) := a count
        cmds[static_cast<std::size_t>(i)]->PARAM.value = static_cast<WORD>(i + 1);
        cmds[static_cast<std::size_t>(i)]->EXECUTE.value = TRUE;
    }
    Throughput result;
    std::chrono::nanoseconds minimum{0};
    std::chrono::nanoseconds firstSend{-1};
    std::chrono::nanoseconds lastDone{0};
    bool sendFlag = (plc.ToPac()[6] & 0x80) != 0;
    while (result.commands < commands) {
        plc.Scan();
        const bool flag = (plc.ToPac()[6] & 0x80) != 0;
        if (flag != sendFlag) {
            sendFlag = flag;
            if (firstSend.count() < 0) firstSend = plc.Now();
            minimum += timing.plcCycle * plc.ProtocolMinimumScans(plc.Now());
        }
        for (auto& cmd : cmds) {
            if (cmd->DONE.value || cmd->ERROR.value) {
                ++result.commands;
                lastDone = plc.Now();
                cmd->EXECUTE.value = FALSE;
                cmd->DATA.value = cmd->DATA.value + 1;
            } else if (!cmd->BUSY.value && !cmd->EXECUTE.value) {
                cmd->EXECUTE.value = TRUE;
            }
        }
    }
    const double seconds = std::chrono::duration<double>(lastDone - firstSend).count();
    result.perSecond = seconds > 0.0 ? result.commands / seconds : 0.0;
    const double bound = std::chrono::duration<double>(minimum).count();
    result.protocolPerSecond = bound > 0.0 ? result.commands / bound : 0.0;
    return result;
}

}  // namespace pac::bench
