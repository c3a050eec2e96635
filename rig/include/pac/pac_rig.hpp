// A PLC wired to a simulated PA-CONTROL: simulated clock, PLC task, bus and controller running at its
// own cycle. Tests, benchmarks and the scenario program add their function blocks with Call(fb) (CMD
// module), CallCtrl(fb) (CTRL module) or CallAxis(fb, k) (axis module k), which copy the module's
// images in and out around the FB's body exactly as a PLC's I/O image would. Command FBs share the CMD
// interface through one ST_PAC_CmdChannel: before the first of them the rig calls an
// FB_PAC_CmdInterface on it in every scan, as a PLC program must. CallRaw8 adds a hand-written master
// program on an 8-byte module. The bus carries the modules of `layout` (default: the CMD module alone).
#pragma once

#include <chrono>
#include <cstdint>
#include <cstddef>
#include <cstring>
#include <functional>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "POUS.h"

#include "pac/fb_instance.hpp"
#include "pac/plc_task.hpp"
#include "pac/sim/bus.hpp"
#include "pac/sim/image8.hpp"
#include "pac/sim/pa_control.hpp"
#include "pac/sim/process_image.hpp"
#include "pac/sim/pac_runner.hpp"
#include "pac/sim_clock.hpp"

namespace pac {

struct RigTiming {
    std::chrono::nanoseconds plcCycle{std::chrono::milliseconds(1)};
    std::chrono::nanoseconds pacCycle{std::chrono::milliseconds(10)};
    int latencyCycles = 0;  // bus latency each way, in PLC cycles
    std::chrono::nanoseconds jitter{0};
    std::uint64_t seed = 1;
    std::chrono::nanoseconds bootTime{0};
};

class PacRig {
public:
    explicit PacRig(RigTiming timing = {}, pac::sim::PaControlConfig config = {},
                         pac::sim::ModuleLayout layout = {});

    // Registers `fb` as a program on the CMD interface: inputs set by the caller before a scan are
    // that scan's inputs. Call in the order the FBs should run; then call Start(). A command FB (one with
    // a Channel) runs on the rig's channel, after its FB_PAC_CmdInterface; an FB with ToPac/FromPac
    // (a hand-written master) on the module itself.
    template <class Fb>
    void Call(pac::FbInstance<Fb>& fb, std::function<void()> before = {}) {
        CallOnCmd(fb, std::move(before), 0);
    }

    // A program that calls the command FBs itself, as a PLC program with CASE steps and IF branches does:
    // any of them, in any order, or none in a scan. It gets the channel after FB_PAC_CmdInterface ran and
    // passes it to each FB it calls (FB_PAC_Cmd's VAR_IN_OUT); the module follows the channel.
    void CallCmdProgram(std::function<void(ST_PAC_CMDCHANNEL& channel)> program);

    // The FB_PAC_CmdInterface the command FBs' channel runs on (registered with the first of them).
    pac::FbInstance<FB_PAC_CMDINTERFACE>& CmdInterface();
    // The channel as the last program of the scan left it.
    const ST_PAC_CMDCHANNEL& Channel() { return CmdInterface()->CHANNEL.value; }
    // Whether the rig calls FB_PAC_CmdInterface in a scan (a test of what happens without it).
    void SetCmdInterfaceCalled(bool called) { cmdInterfaceCalled_ = called; }
    // The CTRL module (the layout must have it).
    template <class Fb>
    void CallCtrl(pac::FbInstance<Fb>& fb, std::function<void()> before = {}) {
        CallOnModule<8>(fb, pac::sim::ModuleLayout::kCtrlOffset, std::move(before));
    }
    // Axis module `module` (1..layout.axisModules).
    template <class Fb>
    void CallAxis(pac::FbInstance<Fb>& fb, int module, std::function<void()> before = {}) {
        CallOnModule<12>(fb, bus_.Layout().AxisOffset(module), std::move(before));
    }

    // A hand-written master program on the 8-byte module at `offset` (CMD or CTRL), run where it is
    // registered: it reads the module's input image and may rewrite the output image the FBs before it
    // left, e.g. a master that writes zeros where an FB holds low-active bits.
    void CallRaw8(std::size_t offset,
                  std::function<void(const pac::sim::Image8& fromPac, pac::sim::Image8& toPac)> program);

    // A program on the whole process image, for a PLC program that holds its own I/O images (pac-test's
    // host for a user's machine program, docs/user_tests.md): it reads the input image the scan read
    // and may rewrite the output image the programs before it left.
    void CallImage(std::function<void(const pac::sim::ProcessImage& fromPac, pac::sim::ProcessImage& toPac)> program);

    // The process image exchanged with a PA-CONTROL outside the process instead of the simulated one (pac-sim
    // over Modbus TCP, docs/virtual_commissioning.md): `read` fills the input image at the start of each scan,
    // `write` takes the output image at its end, each with the scan's time. Call before Start(); the simulated
    // controller then only idles.
    using ImageRead = std::function<void(std::chrono::nanoseconds now, pac::sim::ProcessImage& fromPac)>;
    using ImageWrite = std::function<void(std::chrono::nanoseconds now, const pac::sim::ProcessImage& toPac)>;
    void ExchangeImagesWith(ImageRead read, ImageWrite write);

    // After the FBs: the master's image goes out on the bus at the end of each scan.
    void Start();

    void Scan(int n = 1);

    // Scans until `predicate` holds; returns the scans run, or -1 after maxScans.
    int ScanUntil(const std::function<bool()>& predicate, int maxScans);

    // The fewest scans after a scan at `edgeTime` that can show the PA-CONTROL's answer to a module
    // written in it: the image reaches the controller after the latency, the controller's next cycle
    // answers (its cycle at the very time of that scan has already run), the answer travels back and
    // the next scan reads it. Jitter is not counted.
    int ProtocolMinimumScans(std::chrono::nanoseconds edgeTime) const;

    pac::sim::PaControl& Controller() { return pac_; }
    pac::sim::Bus& Bus() { return bus_; }
    pac::PlcTask& Task() { return task_; }
    std::chrono::nanoseconds Now() const { return clock_.Now(); }
    const pac::sim::ProcessImage& ToPac() const { return toPac_; }
    const pac::sim::ProcessImage& FromPac() const { return fromPac_; }
    const RigTiming& Timing() const { return timing_; }
    const pac::sim::ModuleLayout& Layout() const { return bus_.Layout(); }

private:
    // A command FB on the channel, as an ST call passes it (pacst's C: the body works on the channel itself);
    // MATIEC's C: the channel into the FB's member, the body, the channel back. The module follows the channel.
    template <class Fb>
    auto CallOnCmd(pac::FbInstance<Fb>& fb, std::function<void()> before, int) -> decltype(fb->CHANNEL, void()) {
        RegisterCmdInterface();
        task_.AddProgram([this, &fb, before] {
            if (before) before();
            ST_PAC_CMDCHANNEL& channel = CmdInterface()->CHANNEL.value;
            RunOnChannel(fb, channel, 0);
            CopyChannelToModule();
        });
    }
#ifdef PACST_BODY_REF
    template <class Fb>
    static auto RunOnChannel(pac::FbInstance<Fb>& fb, ST_PAC_CMDCHANNEL& channel, int)
        -> decltype(pacst::BodyRef(&fb.Data(), &channel), void()) {
        pacst::BodyRef(&fb.Data(), &channel);
    }
#endif
    template <class Fb>
    static void RunOnChannel(pac::FbInstance<Fb>& fb, ST_PAC_CMDCHANNEL& channel, long) {
        fb->CHANNEL.value = channel;
        fb();
        channel = fb->CHANNEL.value;
    }
    template <class Fb>
    void CallOnCmd(pac::FbInstance<Fb>& fb, std::function<void()> before, long) {
        CallOnModule<8>(fb, pac::sim::ModuleLayout::kCmdOffset, std::move(before));
    }
    void RegisterCmdInterface();
    void CopyChannelToModule();

    template <std::size_t N, class Fb>
    void CallOnModule(pac::FbInstance<Fb>& fb, std::size_t offset, std::function<void()> before) {
        RequireModule(offset, N);
        static_assert(sizeof fb->TOPAC.value.table == N && sizeof fb->FROMPAC.value.table == N,
                      "the FB's images are the module's bytes");
        // RequireModule checked the bounds once: the copies are plain byte blocks (they cost more than a
        // small FB's body when done byte by byte with a bounds check each).
        task_.AddProgram([this, &fb, offset, before] {
            if (before) before();
            std::memcpy(fb->FROMPAC.value.table, fromPac_.Data() + offset, N);
            std::memcpy(fb->TOPAC.value.table, toPac_.Data() + offset, N);
            fb();
            std::memcpy(&toPac_[offset], fb->TOPAC.value.table, N);
        });
    }

    // std::out_of_range unless the bus layout has `size` bytes at `offset`.
    void RequireModule(std::size_t offset, std::size_t size) const;

    RigTiming timing_;
    pac::SimClock clock_;
    pac::PlcTask task_;
    pac::sim::Bus bus_;
    pac::sim::PaControl pac_;
    pac::sim::PacRunner runner_;
    pac::sim::ProcessImage toPac_;
    pac::sim::ProcessImage fromPac_;
    std::unique_ptr<pac::FbInstance<FB_PAC_CMDINTERFACE>> cmdInterface_;
    bool cmdInterfaceRegistered_ = false;
    bool cmdInterfaceCalled_ = true;
    ImageRead remoteRead_;
    ImageWrite remoteWrite_;
};

}  // namespace pac
