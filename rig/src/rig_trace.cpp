#include "pac/rig_trace.hpp"

#include <string>

namespace pac {

namespace {

std::uint64_t Bytes(const pac::sim::ProcessImage& image, std::size_t offset, std::size_t count) {
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < count; ++i) bits = bits << 8 | image[offset + i];
    return bits;
}

}  // namespace

void TraceBusModules(TraceRecorder& recorder, const PacRig& rig) {
    using pac::sim::ModuleLayout;
    const ModuleLayout& layout = rig.Layout();
    auto field = [&recorder, &rig](const std::string& path, bool toPac, std::size_t offset, std::size_t bytes) {
        recorder.AddBits(path, static_cast<int>(8 * bytes), [&rig, toPac, offset, bytes] {
            return Bytes(toPac ? rig.ToPac() : rig.FromPac(), offset, bytes);
        });
    };
    field("cmd.ToPac", true, ModuleLayout::kCmdOffset, 8);
    field("cmd.FromPac", false, ModuleLayout::kCmdOffset, 8);
    if (layout.ctrl) {
        field("ctrl.ToPac", true, ModuleLayout::kCtrlOffset, 8);
        field("ctrl.FromPac", false, ModuleLayout::kCtrlOffset, 8);
    }
    for (int k = 1; k <= layout.axisModules; ++k) {
        const std::string axis = "axis" + std::to_string(k) + ".";
        const std::size_t at = layout.AxisOffset(k);
        field(axis + "Control", true, at, 4);
        field(axis + "Acceleration", true, at + 4, 2);
        field(axis + "Speed", true, at + 6, 2);
        field(axis + "TargetPositionRaw", true, at + 8, 4);
        field(axis + "Status", false, at, 4);
        field(axis + "CmdErrorNumber", false, at + 4, 2);
        field(axis + "AxisErrorNumber", false, at + 6, 2);
        field(axis + "PositionRaw", false, at + 8, 4);
    }
}

}  // namespace pac
