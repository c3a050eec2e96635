#include "live_view_state.hpp"

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "pac/axis_module_bits.hpp"
#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/command_table.hpp"
#include "pac/sim/operating_status.hpp"
#include "gvl_names.hpp"
#include "text_format.hpp"

namespace pac::pacsim {

namespace {

using nlohmann::json;

struct Bit {
    std::uint32_t mask;
    const char* name;
};

// The manual's names of the bits the library uses (2.5.1, 2.5.2, 2.7.1, 2.7.2); the others show in the hex word.
const std::vector<Bit> kCtrlRequestBits = {{1U << 4, "Start ONLINE"}, {1U << 3, "AUTOMATIC START"},
                                           {1U << 15, "integer format"}};
const std::vector<Bit> kCtrlStatusBits = {{1U << 0, "ready"},          {1U << 1, "battery o.k."},
                                          {1U << 2, "system error"},   {1U << 8, "AUTOMATIC active"},
                                          {1U << 9, "AUTOMATIC stopped"}, {1U << 10, "ONLINE active"},
                                          {1U << 11, "ONLINE stopped"}, {1U << 15, "integer format"}};
const std::vector<Bit> kAxisControlBits = {
    {axis_control::kAxisOn, "Axis ON"},           {axis_control::kDisableDrive, "Disable DRIVE"},
    {axis_control::kStart, "Start"},              {axis_control::kHome, "G25 reference"},
    {axis_control::kMoveAbsolute, "absolute"},    {axis_control::kMoveRelative, "relative"},
    {axis_control::kJogPositive, "jog +"},        {axis_control::kJogNegative, "jog -"},
    {axis_control::kResetAxisError, "reset axis error"}};
const std::vector<Bit> kAxisStatusBits = {
    {axis_status::kDriveEnabled, "DRIVE ENABLED"}, {axis_status::kHalt, "HALT"},
    {axis_status::kIdle, "IDLE"},                  {axis_status::kFault, "FAULT"},
    {axis_status::kActive, "ACTIVE"},              {axis_status::kReferenced, "referenced"},
    {axis_status::kCmdError, "CMD error"},         {axis_status::kAxisError, "axis error"}};

std::string Names(std::uint32_t word, const std::vector<Bit>& bits) {
    std::string text;
    for (const Bit& bit : bits) {
        if (word & bit.mask) text += (text.empty() ? "" : ", ") + std::string(bit.name);
    }
    return text.empty() ? "-" : text;
}

std::string HexBytes(const pac::sim::ProcessImage& image, std::size_t first, std::size_t count) {
    std::string text;
    char byte[4];
    for (std::size_t i = first; i < first + count; ++i) {
        std::snprintf(byte, sizeof byte, "%02X", image[i]);
        text += (text.empty() ? "" : " ") + std::string(byte);
    }
    return text;
}

std::uint16_t Word(const pac::sim::ProcessImage& image, std::size_t byte) {
    return static_cast<std::uint16_t>(image[byte] << 8 | image[byte + 1]);
}

std::uint32_t Dword(const pac::sim::ProcessImage& image, std::size_t byte) {
    return static_cast<std::uint32_t>(Word(image, byte)) << 16 | Word(image, byte + 2);
}

// The library's name of the command (GVL_PAC's PAC_CMD_...), else the simulator's.
std::string CommandName(std::uint16_t code) {
    static const pac::scenario::GvlNames names;
    const std::string gvl = names.CommandName(code);
    if (!gvl.empty()) return gvl;
    const pac::sim::CommandInfo* info = pac::sim::FindCommand(code);
    return info ? info->name : "unknown command";
}

std::string StatusText(std::uint8_t status) {
    return std::to_string(status) + " (" + pac::sim::ToString(pac::sim::ModeOf(status)) + ")";
}

using Fields = std::vector<std::pair<std::string, std::string>>;

json Direction(const pac::sim::ProcessImage& image, const ModuleRegisters& module, const Fields& fields) {
    json out = {{"hex", HexBytes(image, module.byte, module.bytes)}, {"fields", json::array()}};
    for (const auto& [name, value] : fields) out["fields"].push_back({name, value});
    return out;
}

// One module's bytes both ways and their fields; positions as REALs or integers x 1000 as the format in force.
json Module(const ModuleRegisters& module, const pac::sim::ProcessImage& to, const pac::sim::ProcessImage& from,
            bool integerFormat) {
    using pac::scenario::Hex4;
    using pac::scenario::Hex8;
    const std::size_t b = module.byte;
    Fields toFields;
    Fields fromFields;
    if (module.name == "CMD") {
        const auto command = pac::sim::CommandFrame::Decode(to.Module8(b));
        const auto reply = pac::sim::ReplyFrame::Decode(from.Module8(b));
        toFields = {{"command", Hex4(command.code) + " " + CommandName(command.code)},
                    {"parameter", std::to_string(command.parameter)},
                    {"data", pac::scenario::DwordText(command.data, false)},
                    {"SEND", command.send ? "1" : "0"}};
        fromFields = {{"operating status", StatusText(reply.operatingStatus)},
                      {"acknowledgement data", pac::scenario::DwordText(reply.ackData, false)},
                      {"RF", reply.receiveFlag ? "1" : "0"},
                      {"BF", reply.endOfProcessing ? "1" : "0"},
                      {"KF", reply.commandErrorFlag ? "1" : "0"},
                      {"command error number", std::to_string(reply.errorNumber)},
                      {"FE", reply.errorFlag ? "1" : "0"}};
    } else if (module.name == "CTRL") {
        const std::uint16_t control = Word(to, b);
        // Bits 0..2 are low active: 0 is the request.
        std::string requests = Names(control, kCtrlRequestBits);
        if (!(control & 1U)) requests += ", Error reset";
        if (!(control & 2U)) requests += ", Stop";
        if (!(control & 4U)) requests += ", Cancel";
        toFields = {{"control word", Hex4(control)}, {"requests", requests}};
        fromFields = {{"status word", Hex4(Word(from, b))},
                      {"status", Names(Word(from, b), kCtrlStatusBits)},
                      {"system error number", std::to_string(Word(from, b + 4))}};
    } else {
        const std::uint32_t control = Dword(to, b);
        const std::uint32_t status = Dword(from, b);
        toFields = {{"control word", Hex8(control)},
                    {"bits", Names(control, kAxisControlBits)},
                    {"acceleration", std::to_string(Word(to, b + 4)) + " per mille"},
                    {"speed", std::to_string(Word(to, b + 6)) + " per mille"},
                    {"target position", std::to_string(pac::scenario::PositionValue(Dword(to, b + 8), integerFormat))}};
        fromFields = {{"status word", Hex8(status)},
                      {"bits", Names(status, kAxisStatusBits)},
                      {"axis CMD error number", std::to_string(Word(from, b + 4))},
                      {"axis error number", std::to_string(Word(from, b + 6))},
                      {"current position",
                       std::to_string(pac::scenario::PositionValue(Dword(from, b + 8), integerFormat))}};
    }
    return {{"name", module.name},
            {"to_pac", Direction(to, module, toFields)},
            {"from_pac", Direction(from, module, fromFields)}};
}

const char* DriveText(pac::sim::DriveState drive) {
    switch (drive) {
        case pac::sim::DriveState::kEnabled: return "DRIVE ENABLED";
        case pac::sim::DriveState::kHalt: return "HALT";
        case pac::sim::DriveState::kIdle: return "IDLE";
        case pac::sim::DriveState::kSafe: return "SAFE";
        case pac::sim::DriveState::kDisabled: return "DISABLED";
    }
    return "?";
}

}  // namespace

json ControllerState(SimulatedController& controller, std::chrono::nanoseconds now) {
    pac::sim::PaControl& pac = controller.Controller();
    const pac::sim::ProcessImage& to = pac.LastToPacImage();
    const pac::sim::ProcessImage& from = pac.LastFromPacImage();
    const std::uint8_t status = pac::sim::ReplyFrame::Decode(from.Cmd()).operatingStatus;
    json state = {{"name", controller.Spec().name},
                  {"time_ms", static_cast<double>(now.count()) / 1e6},
                  {"operating_status", status},
                  {"mode", pac::sim::ToString(pac::sim::ModeOf(status))},
                  {"link", pac::sim::ToString(controller.Bus().ToPacLink().Fault())},
                  {"axes", json::array()},
                  {"handshakes", json::array()},
                  {"handshakes_total", controller.History().Total()},
                  {"modules", json::array()}};
    for (int axis = 1; axis <= controller.Spec().modules.axes; ++axis) {
        const pac::sim::ServoAxis& motion = pac.Axes().Motion(axis);
        state["axes"].push_back({{"axis", axis},
                                 {"position", motion.Position()},
                                 {"drive", DriveText(motion.Drive())},
                                 {"moving", motion.Moving()},
                                 {"referenced", motion.Referenced()},
                                 {"axis_error", motion.AxisError()},
                                 {"cmd_error", Word(from, pac.Layout().AxisOffset(axis) + 4)}});
    }
    for (const CmdHandshake& h : controller.History().Handshakes()) {
        json entry = {{"time_ms", static_cast<double>(h.time.count()) / 1e6},
                      {"code", pac::scenario::Hex4(h.command.code)},
                      {"meaning", CommandName(h.command.code)},
                      {"parameter", h.command.parameter},
                      {"data", h.command.data},
                      {"answered", h.answered}};
        if (h.answered) {
            entry["ack_data"] = h.reply.ackData;
            entry["command_error"] = h.reply.commandErrorFlag ? h.reply.errorNumber : 0;
        }
        state["handshakes"].push_back(entry);
    }
    for (const ModuleRegisters& module : controller.Map().Modules()) {
        state["modules"].push_back(Module(module, to, from, pac.IntegerFormat()));
    }
    return state;
}

}  // namespace pac::pacsim
