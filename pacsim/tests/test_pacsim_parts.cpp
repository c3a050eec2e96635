// pac-sim's parts without a socket: which Modbus requests CheckRequest lets through and where (at every edge of
// the protocol's quantities and of the map), the register layout of the images, and a controller whose
// registers written at one time reach the simulated PA-CONTROL as one bus image; the live view's handshake history
// and its fault injection.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "cmd_history.hpp"
#include "fault_injector.hpp"
#include "modbus_request.hpp"
#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/image8.hpp"
#include "register_map.hpp"
#include "scan_schedule.hpp"
#include "sim_config.hpp"
#include "simulated_controller.hpp"

namespace {

using pac::pacsim::CheckRequest;
using pac::pacsim::kFromPacHoldingBase;
using pac::pacsim::RegisterMap;
using Bytes = std::vector<std::uint8_t>;

constexpr int kRegisters = 20;  // CMD, CTRL, two axis modules

void Put(Bytes& pdu, int word) {
    pdu.push_back(static_cast<std::uint8_t>(word >> 8));
    pdu.push_back(static_cast<std::uint8_t>(word));
}

Bytes Read(int function, int address, int count) {
    Bytes pdu{static_cast<std::uint8_t>(function)};
    Put(pdu, address);
    Put(pdu, count);
    return pdu;
}

Bytes WriteMultiple(int address, int count) {
    Bytes pdu = Read(16, address, count);
    pdu.push_back(static_cast<std::uint8_t>(2 * count));
    pdu.resize(pdu.size() + 2 * static_cast<std::size_t>(count));
    return pdu;
}

Bytes ReadWrite(int readAddress, int readCount, int writeAddress, int writeCount) {
    Bytes pdu = Read(23, readAddress, readCount);
    Put(pdu, writeAddress);
    Put(pdu, writeCount);
    pdu.push_back(static_cast<std::uint8_t>(2 * writeCount));
    pdu.resize(pdu.size() + 2 * static_cast<std::size_t>(writeCount));
    return pdu;
}

int Exception(const Bytes& pdu) { return CheckRequest(pdu.data(), pdu.size(), kRegisters).exception; }

TEST(CheckRequest, ServesTheFiveFunctionCodesAndNoOther) {
    EXPECT_EQ(Exception(Read(3, 0, 1)), 0);
    EXPECT_EQ(Exception(Read(4, 0, 1)), 0);
    EXPECT_EQ(Exception(Read(6, 0, 0)), 0);
    EXPECT_EQ(Exception(WriteMultiple(0, 1)), 0);
    EXPECT_EQ(Exception(ReadWrite(0, 1, 0, 1)), 0);
    for (int function : {0, 1, 2, 5, 7, 8, 15, 17, 22, 24, 43, 127, 128, 255}) {
        EXPECT_EQ(Exception(Read(function, 0, 1)), pac::pacsim::kIllegalFunction) << function;
    }
    EXPECT_EQ(CheckRequest(nullptr, 0, kRegisters).exception, pac::pacsim::kIllegalFunction);
}

TEST(CheckRequest, ReadsReachToPacAndFromPacAndNothingBetween) {
    EXPECT_EQ(Exception(Read(3, 0, kRegisters)), 0);
    EXPECT_EQ(Exception(Read(3, 0, kRegisters + 1)), pac::pacsim::kIllegalDataAddress);
    EXPECT_EQ(Exception(Read(3, kRegisters, 1)), pac::pacsim::kIllegalDataAddress);
    EXPECT_EQ(Exception(Read(3, kFromPacHoldingBase - 1, 1)), pac::pacsim::kIllegalDataAddress);
    EXPECT_EQ(Exception(Read(3, kFromPacHoldingBase, kRegisters)), 0);
    EXPECT_EQ(Exception(Read(3, kFromPacHoldingBase + kRegisters - 1, 2)), pac::pacsim::kIllegalDataAddress);
    EXPECT_EQ(Exception(Read(3, 0xFFFF, 125)), pac::pacsim::kIllegalDataAddress);
    EXPECT_EQ(Exception(Read(4, kRegisters - 1, 1)), 0);
    EXPECT_EQ(Exception(Read(4, kRegisters - 1, 2)), pac::pacsim::kIllegalDataAddress);
    EXPECT_EQ(Exception(Read(4, kFromPacHoldingBase, 1)), pac::pacsim::kIllegalDataAddress);
}

TEST(CheckRequest, WritesReachToPacOnly) {
    const auto single = CheckRequest(Read(6, kRegisters - 1, 7).data(), 5, kRegisters);
    EXPECT_EQ(single.exception, 0);
    EXPECT_EQ(single.writeFirst, kRegisters - 1);
    EXPECT_EQ(single.writeCount, 1);
    EXPECT_EQ(Exception(Read(6, kRegisters, 7)), pac::pacsim::kIllegalDataAddress);
    EXPECT_EQ(Exception(Read(6, kFromPacHoldingBase, 7)), pac::pacsim::kIllegalDataAddress);
    const Bytes whole = WriteMultiple(4, 16);
    const auto multiple = CheckRequest(whole.data(), whole.size(), kRegisters);
    EXPECT_EQ(multiple.exception, 0);
    EXPECT_EQ(multiple.writeFirst, 4);
    EXPECT_EQ(multiple.writeCount, 16);
    EXPECT_EQ(Exception(WriteMultiple(4, 17)), pac::pacsim::kIllegalDataAddress);
    EXPECT_EQ(Exception(WriteMultiple(kFromPacHoldingBase, 1)), pac::pacsim::kIllegalDataAddress);
    const Bytes both = ReadWrite(kFromPacHoldingBase, kRegisters, 8, 6);
    const auto readWrite = CheckRequest(both.data(), both.size(), kRegisters);
    EXPECT_EQ(readWrite.exception, 0);
    EXPECT_EQ(readWrite.writeFirst, 8);
    EXPECT_EQ(readWrite.writeCount, 6);
    EXPECT_EQ(Exception(ReadWrite(0, 1, kFromPacHoldingBase, 1)), pac::pacsim::kIllegalDataAddress);
    EXPECT_EQ(Exception(ReadWrite(kRegisters, 1, 0, 1)), pac::pacsim::kIllegalDataAddress);
}

TEST(CheckRequest, QuantitiesAtTheProtocolsEdges) {
    const int wide = 1024 + 200;  // a map wide enough that only the quantity decides
    auto exception = [wide](const Bytes& pdu) { return CheckRequest(pdu.data(), pdu.size(), wide).exception; };
    EXPECT_EQ(exception(Read(3, 0, 125)), 0);
    EXPECT_EQ(exception(Read(3, 0, 126)), pac::pacsim::kIllegalDataValue);
    EXPECT_EQ(exception(Read(4, 0, 0)), pac::pacsim::kIllegalDataValue);
    EXPECT_EQ(exception(WriteMultiple(0, 123)), 0);
    EXPECT_EQ(exception(WriteMultiple(0, 124)), pac::pacsim::kIllegalDataValue);
    EXPECT_EQ(exception(WriteMultiple(0, 0)), pac::pacsim::kIllegalDataValue);
    EXPECT_EQ(exception(ReadWrite(0, 125, 0, 121)), 0);
    EXPECT_EQ(exception(ReadWrite(0, 126, 0, 1)), pac::pacsim::kIllegalDataValue);
    EXPECT_EQ(exception(ReadWrite(0, 1, 0, 122)), pac::pacsim::kIllegalDataValue);
    // A byte count that does not match the quantity, and a frame shorter than its own fields.
    Bytes mismatch = WriteMultiple(0, 2);
    mismatch[5] = 3;
    EXPECT_EQ(exception(mismatch), pac::pacsim::kIllegalDataValue);
    Bytes shortValues = WriteMultiple(0, 2);
    shortValues.pop_back();
    EXPECT_EQ(exception(shortValues), pac::pacsim::kIllegalDataValue);
    EXPECT_EQ(exception(Bytes{3, 0, 0, 0}), pac::pacsim::kIllegalDataValue);
    EXPECT_EQ(exception(Bytes{23, 0, 0, 0, 1, 0, 0, 0, 1}), pac::pacsim::kIllegalDataValue);
}

TEST(RegisterMap, ModulesStartAtHalfTheirByteOffset) {
    const RegisterMap map(pac::sim::ModuleLayout{true, 8});
    ASSERT_EQ(map.Modules().size(), 10U);
    EXPECT_EQ(map.Registers(), 56);
    EXPECT_EQ(map.Modules()[1].name, "CTRL");
    EXPECT_EQ(map.Modules()[1].firstRegister, 4);
    EXPECT_EQ(map.Modules()[9].name, "AXIS 8");
    EXPECT_EQ(map.Modules()[9].firstRegister, 50);
    EXPECT_EQ(RegisterMap(pac::sim::ModuleLayout{}).Registers(), 4);
}

TEST(RegisterMap, ByteTwoNIsTheHighByteOfRegisterN) {
    pac::sim::ProcessImage image(16);
    RegisterMap::WriteRegisters(image, 1, {0x1234, 0xABCD});
    EXPECT_EQ(image[2], 0x12);
    EXPECT_EQ(image[3], 0x34);
    EXPECT_EQ(image[4], 0xAB);
    EXPECT_EQ(image[5], 0xCD);
    const auto registers = RegisterMap::ToRegisters(image);
    ASSERT_EQ(registers.size(), 8U);
    EXPECT_EQ(registers[1], 0x1234);
    EXPECT_EQ(registers[2], 0xABCD);
    EXPECT_THROW(RegisterMap::WriteRegisters(image, 7, {1, 2}), std::out_of_range);
}

TEST(SimulatedController, RegistersWrittenTogetherArriveAsOneImage) {
    const auto config = pac::pacsim::SimConfigLoader::FromText(
        R"({"controllers": [{"timing": {"pac_cycle_ms": 5, "boot_ms": 50}, "modules": {"ctrl": true, "axes": 1}}]})");
    pac::pacsim::SimulatedController controller(config.controllers.at(0));
    using std::chrono::milliseconds;
    controller.CatchUp(milliseconds(60));
    // Write N3 := 333 (0906, manual 5.2.4) as the four registers of the CMD module in one write, SEND toggled.
    controller.WriteToPac(milliseconds(60), 0, {0, 333, 3, 0x8000 | 0x0906});
    controller.CatchUp(milliseconds(80));
    EXPECT_EQ(controller.Controller().Io().intRegisters.GetInt(3), 333);
    const auto reply = controller.FromPacRegisters();
    EXPECT_EQ(reply[3] & 0xA000, 0xA000) << "RF = SEND, BF";
    EXPECT_EQ(reply[1], 333);
    EXPECT_EQ(controller.ToPacRegisters()[3], 0x8906);
}

TEST(SimConfigLoader, DefaultsAndThePortOverride) {
    const auto config = pac::pacsim::SimConfigLoader::FromText(R"({"controllers": [{}, {"port": 7000}]})", 0);
    ASSERT_EQ(config.controllers.size(), 2U);
    EXPECT_EQ(config.controllers[0].name, "pac1");
    EXPECT_EQ(config.controllers[0].port, 0);
    EXPECT_EQ(config.controllers[0].unitId, 1);
    EXPECT_EQ(config.controllers[1].name, "pac2");
    EXPECT_EQ(config.controllers[1].port, 7000);
    EXPECT_EQ(config.controllers[1].unitId, 2);
    EXPECT_FALSE(config.controllers[0].rs232);
    EXPECT_EQ(pac::pacsim::SimConfigLoader::FromText(R"({"controllers": [{}]})").controllers[0].port,
              pac::pacsim::kDefaultPort);
}

}  // namespace

// The live view's handshake history (pacsim/cmd_history.hpp): a command is a SEND change, answered by the first
// reply with RF = SEND and BF or KF; an earlier reply with RF still the old SEND does not answer it.
TEST(CmdHistory, ACommandIsASendChangeAnsweredByRfEqualToSend) {
    using pac::sim::CommandImage;
    using pac::sim::ReplyFrame;
    pac::pacsim::CmdHistory history;
    const auto reply = [](bool rf, bool bf, bool kf, std::uint32_t ack) {
        ReplyFrame frame;
        frame.receiveFlag = rf;
        frame.endOfProcessing = bf;
        frame.commandErrorFlag = kf;
        frame.ackData = ack;
        frame.operatingStatus = 1;
        return frame.Encode();
    };
    history.Follow(std::chrono::milliseconds(5), CommandImage(0x1907, 1, 0, false), reply(false, true, false, 0));
    EXPECT_TRUE(history.Handshakes().empty());  // SEND as at power-on: no command
    history.Follow(std::chrono::milliseconds(10), CommandImage(0x1907, 1, 0, true), reply(false, true, false, 0));
    ASSERT_EQ(history.Handshakes().size(), 1U);
    EXPECT_FALSE(history.Handshakes().back().answered);  // RF is still the old SEND
    history.Follow(std::chrono::milliseconds(15), CommandImage(0x1907, 1, 0, true), reply(true, true, false, 640));
    EXPECT_TRUE(history.Handshakes().back().answered);
    EXPECT_EQ(history.Handshakes().back().reply.ackData, 640U);
    EXPECT_EQ(history.Handshakes().back().command.code, 0x1907);
    // A refused command: KF answers it; the next one toggles SEND back.
    history.Follow(std::chrono::milliseconds(20), CommandImage(0x1906, 2000, 0, false), reply(true, true, false, 640));
    EXPECT_FALSE(history.Handshakes().back().answered);
    history.Follow(std::chrono::milliseconds(25), CommandImage(0x1906, 2000, 0, false), reply(false, false, true, 0));
    EXPECT_TRUE(history.Handshakes().back().answered);
    EXPECT_TRUE(history.Handshakes().back().reply.commandErrorFlag);
    // The newest 16 are kept; the total counts them all.
    for (int i = 0; i < 20; ++i) {
        history.Follow(std::chrono::milliseconds(30 + i), CommandImage(0x1906, static_cast<std::uint16_t>(i), 0, i % 2 == 0),
                       reply(false, false, false, 0));
    }
    EXPECT_EQ(history.Handshakes().size(), pac::pacsim::CmdHistory::kCapacity);
    EXPECT_EQ(history.Total(), 22U);
    EXPECT_EQ(history.Handshakes().back().command.parameter, 19);
}

// Fault injection (pacsim/fault_injector.hpp): each kind acts on the controller; a bad request names what is wrong.
TEST(FaultInjector, EachFaultActsAndBadRequestsAreRefused) {
    pac::pacsim::SimConfig config = pac::pacsim::SimConfigLoader::FromText(
        R"({"controllers": [{"timing": {"pac_cycle_ms": 5, "boot_ms": 50}, "modules": {"ctrl": true, "axes": 2}}]})");
    pac::pacsim::SimulatedController controller(config.controllers[0]);
    using std::chrono::milliseconds;
    controller.CatchUp(milliseconds(100));
    pac::pacsim::InjectFault(controller, milliseconds(100), {"axis_error", 2, 70});
    EXPECT_EQ(controller.Controller().Axes().Motion(2).AxisError(), 70);
    pac::pacsim::InjectFault(controller, milliseconds(100), {"limit_switch", 1, 0});
    EXPECT_EQ(controller.Controller().Axes().Motion(1).AxisError(), 64);
    pac::pacsim::InjectFault(controller, milliseconds(100), {"link_loss", 1, 0});
    EXPECT_EQ(controller.Bus().FromPacLink().Fault(), pac::sim::LinkFault::kDisconnected);
    pac::pacsim::InjectFault(controller, milliseconds(100), {"link_restore", 1, 0});
    EXPECT_EQ(controller.Bus().ToPacLink().Fault(), pac::sim::LinkFault::kNone);
    pac::pacsim::InjectFault(controller, milliseconds(100), {"power_cycle", 1, 0});
    EXPECT_FALSE(controller.Controller().Booted());
    // A restart brings back the configuration's state; a power cycle would keep the battery-buffered registers.
    pac::pacsim::SimConfig withRegister = pac::pacsim::SimConfigLoader::FromText(
        R"({"controllers": [{"modules": {"ctrl": true, "axes": 1}, "controller": {"r_registers": {"1": 640.0}}}]})");
    pac::pacsim::SimulatedController restarted(withRegister.controllers[0]);
    restarted.Controller().Io().realRegisters.SetReal(1, 5.0F);
    pac::pacsim::InjectFault(restarted, milliseconds(100), {"restart", 1, 0});
    EXPECT_EQ(restarted.Controller().Io().realRegisters.GetReal(1), 640.0F);
    EXPECT_FALSE(restarted.Controller().Booted());
    try {
        pac::pacsim::InjectFault(controller, milliseconds(100), {"meltdown", 1, 0});
        FAIL() << "an unknown fault was taken";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("limit_switch"), std::string::npos) << e.what();
    }
    EXPECT_THROW(pac::pacsim::InjectFault(controller, milliseconds(100), {"axis_error", 3, 0}), std::invalid_argument);
    EXPECT_THROW(pac::pacsim::InjectFault(controller, milliseconds(100), {"axis_error", 1, 70000}), std::invalid_argument);
}

// pac-sim-plc's scans on the wall clock at a 10 ms PLC cycle: a stall of 1.5 s (a loaded machine) must not be
// caught up by scans back to back, which would run the PLC's clock faster than pac-sim's (ClosedLoopTest's wait
// of 60 ms for the boot after a power cycle ended before the boot, and the command got 16#8003).
TEST(ScanSchedule, AScanMoreThanACycleLateMovesTheScheduleInsteadOfABurst) {
    using namespace std::chrono_literals;
    pac::pacsim::ScanSchedule schedule;
    const auto t0 = pac::pacsim::ScanSchedule::Clock::time_point{} + 100s;
    EXPECT_EQ(schedule.Due(10ms, t0), t0);  // the first scan at once
    EXPECT_EQ(schedule.Started(10ms, t0), 0ms);
    EXPECT_EQ(schedule.Due(20ms, t0 + 1ms), t0 + 10ms);
    EXPECT_EQ(schedule.Started(20ms, t0 + 1510ms), 1500ms);
    EXPECT_EQ(schedule.Due(30ms, t0 + 1511ms), t0 + 1520ms);  // a cycle after the late scan, not at once
    // Late by less than a cycle (jitter): the schedule stays, the next scan catches up.
    EXPECT_EQ(schedule.Started(30ms, t0 + 1525ms), 5ms);
    EXPECT_EQ(schedule.Due(40ms, t0 + 1526ms), t0 + 1530ms);
}
