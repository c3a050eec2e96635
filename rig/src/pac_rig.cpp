#include "pac/pac_rig.hpp"

namespace pac {

namespace {

pac::sim::BusConfig BusConfigFor(const RigTiming& t, const pac::sim::ModuleLayout& layout) {
    pac::sim::BusConfig config;
    config.layout = layout;
    const auto latency = t.plcCycle * t.latencyCycles;
    config.toPac = {latency, t.jitter, t.seed};
    config.fromPac = {latency, t.jitter, t.seed + 1};
    return config;
}

pac::sim::PaControlConfig WithTiming(pac::sim::PaControlConfig config, const RigTiming& t) {
    config.bootTime = t.bootTime;
    config.homeCycle = t.pacCycle;
    config.activeCycle = t.pacCycle;
    return config;
}

}  // namespace

PacRig::PacRig(RigTiming timing, pac::sim::PaControlConfig config, pac::sim::ModuleLayout layout)
    : timing_(timing),
      task_(clock_, timing.plcCycle),
      bus_(BusConfigFor(timing, layout)),
      pac_(bus_, WithTiming(config, timing)),
      runner_(pac_),
      toPac_(layout.Bytes()),
      fromPac_(layout.Bytes()) {
    runner_.AttachTo(task_);  // first: the controller's cycle runs before a scan at the same time
    task_.AddProgram([this] {
        if (remoteRead_) {
            remoteRead_(clock_.Now(), fromPac_);
        } else {
            fromPac_ = bus_.ReadFromPac(clock_.Now());
        }
    });
}

pac::FbInstance<FB_PAC_CMDINTERFACE>& PacRig::CmdInterface() {
    if (!cmdInterface_) cmdInterface_ = std::make_unique<pac::FbInstance<FB_PAC_CMDINTERFACE>>(PAC_FB(FB_PAC_CMDINTERFACE));
    return *cmdInterface_;
}

void PacRig::RegisterCmdInterface() {
    if (cmdInterfaceRegistered_) return;
    RequireModule(pac::sim::ModuleLayout::kCmdOffset, 8);
    cmdInterfaceRegistered_ = true;
    task_.AddProgram([this] {
        ST_PAC_CMDCHANNEL& channel = CmdInterface()->CHANNEL.value;
        // RequireModule checked the bounds once: a block copy, not 8 checked bytes.
        static_assert(sizeof channel.FROMPAC.table == 8 && sizeof channel.TOPAC.table == 8, "the CMD module");
        std::memcpy(channel.FROMPAC.table, fromPac_.Data() + pac::sim::ModuleLayout::kCmdOffset, 8);
        if (cmdInterfaceCalled_) CmdInterface()();
        CopyChannelToModule();
    });
}

void PacRig::CopyChannelToModule() {
    const ST_PAC_CMDCHANNEL& channel = CmdInterface()->CHANNEL.value;
    std::memcpy(toPac_.Data() + pac::sim::ModuleLayout::kCmdOffset, channel.TOPAC.table, 8);
}

void PacRig::CallCmdProgram(std::function<void(ST_PAC_CMDCHANNEL& channel)> program) {
    if (!program) throw std::invalid_argument("PacRig::CallCmdProgram: empty program");
    RegisterCmdInterface();
    task_.AddProgram([this, program] {
        program(CmdInterface()->CHANNEL.value);
        CopyChannelToModule();
    });
}

void PacRig::CallRaw8(std::size_t offset,
                           std::function<void(const pac::sim::Image8& fromPac, pac::sim::Image8& toPac)> program) {
    if (!program) throw std::invalid_argument("PacRig::CallRaw8: empty program");
    RequireModule(offset, 8);
    task_.AddProgram([this, offset, program] {
        pac::sim::Image8 out = toPac_.Module8(offset);
        program(fromPac_.Module8(offset), out);
        toPac_.SetModule8(offset, out);
    });
}

void PacRig::CallImage(
    std::function<void(const pac::sim::ProcessImage& fromPac, pac::sim::ProcessImage& toPac)> program) {
    if (!program) throw std::invalid_argument("PacRig::CallImage: empty program");
    task_.AddProgram([this, program] { program(fromPac_, toPac_); });
}

void PacRig::ExchangeImagesWith(ImageRead read, ImageWrite write) {
    if (!read || !write) throw std::invalid_argument("PacRig::ExchangeImagesWith: empty function");
    remoteRead_ = std::move(read);
    remoteWrite_ = std::move(write);
}

void PacRig::Start() {
    task_.AddProgram([this] {
        if (remoteWrite_) {
            remoteWrite_(clock_.Now(), toPac_);
        } else {
            bus_.WriteToPac(clock_.Now(), toPac_);
        }
    });
}

void PacRig::Scan(int n) {
    for (int i = 0; i < n; ++i) task_.Scan();
}

int PacRig::ScanUntil(const std::function<bool()>& predicate, int maxScans) {
    for (int scans = 1; scans <= maxScans; ++scans) {
        task_.Scan();
        if (predicate()) return scans;
    }
    return -1;
}

int PacRig::ProtocolMinimumScans(std::chrono::nanoseconds edgeTime) const {
    const auto latency = timing_.plcCycle * timing_.latencyCycles;
    const auto arrival = edgeTime + latency;
    auto pacTime = (arrival / timing_.pacCycle) * timing_.pacCycle;
    while (pacTime < arrival || pacTime <= edgeTime) pacTime += timing_.pacCycle;
    auto scanTime = edgeTime;
    while (scanTime < pacTime + latency) scanTime += timing_.plcCycle;
    return static_cast<int>((scanTime - edgeTime) / timing_.plcCycle);
}

void PacRig::RequireModule(std::size_t offset, std::size_t size) const {
    if (offset + size > toPac_.Size()) throw std::out_of_range("PacRig: module not in the bus layout");
}

}  // namespace pac
