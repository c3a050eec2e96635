// The parameter, axis status and ONLINE axis command FBs (docs/fb/parameter_axis_commands.md) against
// the simulated PA-CONTROL over the simulated bus, on a few timings: PLC cycle 1 and 5 ms, controller
// cycle 3 and 10 ms, bus latency 0 and 2 PLC cycles each way. Every FB of the page sits on the one CMD
// interface, as in a PLC program; each test checks what lands in (or comes from) the controller, the
// PA-CONTROL's error numbers, and the PLCopen outputs in every scan (plcopen_checker.hpp).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "bus_timing.hpp"
#include "command_plc.hpp"
#include "pac/iec_time.hpp"
#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/st_program.hpp"
#include "real_bits.hpp"
#include "run_to_final.hpp"
#include "scan_window.hpp"

namespace test_parameter_axis_fbs {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using std::chrono::nanoseconds;

const pac::test::GvlConstants kGvl;

using pac::test::BusTiming;
using pac::test::FinalOutcome;

std::uint32_t Bits(float value) { return pac::test::BitsOf(value); }

// A PLC with every FB of the page on the CMD interface of one simulated PA-CONTROL, plus a plain
// FB_PAC_Cmd for the mode commands (0603) the page does not cover.
class AxisRig {
public:
    explicit AxisRig(const BusTiming& t, pac::sim::PaControlConfig config = {}, nanoseconds bootTime = 0ns)
        : plc_(t, config, bootTime) {
        plc_.Add("FB_PAC_Cmd", cmd);
        plc_.Add("WriteSystemParameter", writeSys);
        plc_.Add("ReadSystemParameter", readSys);
        plc_.Add("WriteAxisParameter", writeAxis);
        plc_.Add("ReadAxisParameter", readAxis);
        plc_.Add("ReadAxisPosition", readPos);
        plc_.Add("ReadAxisStatus", readStatus);
        plc_.Add("ReadAllAxesStatus", readAll);
        plc_.Add("MoveAxisAbsolute", moveAbs);
        plc_.Add("MoveAxisRelative", moveRel);
        plc_.Add("StopAxis", stop);
        plc_.Add("SetAxisSpeed", setSpeed);
        plc_.Add("SetAxisAcceleration", setAccel);
        plc_.Start();
        for (int i = 0; i < 1000 && !Controller().Booted(); ++i) plc_.Scan();
        plc_.Scan(3 + 2 * t.latency);
        plc_.ScanPastFirstHandshake();
    }

    // Execute edge, scans until Done, Error or CommandAborted, then Execute back to FALSE for one scan.
    template <class Fb>
    FinalOutcome Run(pac::FbInstance<Fb>& fb, int maxScans = 20000) {
        return plc_.Run(fb, maxScans);
    }
    // The scan that sees the Execute edge.
    template <class Fb>
    void Start(pac::FbInstance<Fb>& fb) {
        plc_.Begin(fb);
    }
    // Scans until `fb` shows its final output, counted from the last Start(); `eachScan` after each scan.
    template <class Fb>
    FinalOutcome Wait(pac::FbInstance<Fb>& fb, int maxScans = 20000, const std::function<void()>& eachScan = {}) {
        return plc_.Wait(fb, maxScans, eachScan);
    }
    template <class Fb>
    void Release(pac::FbInstance<Fb>& fb) {
        plc_.Release(fb);
    }

    // The scans the protocol needs for a command sent in the last Start()'s edge scan.
    pac::test::ScanWindow Window() const { return plc_.Window(); }

    // ONLINE the way a PLC gets there (5.2.1.3): system parameter 4 names the external stop input,
    // that input has power, then 0603.
    bool GoOnline() {
        writeSys->PARAMETERNUMBER.value = 4;
        writeSys->VALUE.value = 7;
        if (!Run(writeSys).Done()) return false;
        Controller().Io().inputs.Set(7, true);
        cmd->CODE.value = 0x0603;  // PAC_CMD_START_ONLINE
        cmd->PARAM.value = 0;
        cmd->DATA.value = 0;
        if (!Run(cmd).Done()) return false;
        Settle(2 * (plc_.Timing().latency + 1));
        return Controller().OperatingStatus() == 31 && cmd->OPSTATUS.value == 31;
    }

    void Settle(int scans) { plc_.Scan(scans); }
    // FB_PAC_CmdInterface.TwoStepWrite: the data a scan before the SEND flag (Interbus-S, 4.2.4).
    void SetTwoStepWrite(bool on) { plc_.Rig().CmdInterface()->TWOSTEPWRITE.value = on ? TRUE : FALSE; }
    pac::sim::PaControl& Controller() { return plc_.Controller(); }
    pac::sim::ServoAxis& Motion(int axis) { return Controller().Axes().Motion(axis); }
    const pac::sim::Dynamics& SessionDynamics(int axis) { return Controller().Axes().SessionDynamics(axis); }
    pac::sim::Image8 LastCommand() { return plc_.LastCommandSeen(); }
    nanoseconds Now() const { return plc_.Now(); }
    nanoseconds EdgeTime() const { return plc_.EdgeTime(); }

    pac::FbInstance<FB_PAC_CMD> cmd = PAC_FB(FB_PAC_CMD);
    pac::FbInstance<FB_PAC_WRITESYSTEMPARAMETER> writeSys = PAC_FB(FB_PAC_WRITESYSTEMPARAMETER);
    pac::FbInstance<FB_PAC_READSYSTEMPARAMETER> readSys = PAC_FB(FB_PAC_READSYSTEMPARAMETER);
    pac::FbInstance<FB_PAC_WRITEAXISPARAMETER> writeAxis = PAC_FB(FB_PAC_WRITEAXISPARAMETER);
    pac::FbInstance<FB_PAC_READAXISPARAMETER> readAxis = PAC_FB(FB_PAC_READAXISPARAMETER);
    pac::FbInstance<FB_PAC_READAXISPOSITION> readPos = PAC_FB(FB_PAC_READAXISPOSITION);
    pac::FbInstance<FB_PAC_READAXISSTATUS> readStatus = PAC_FB(FB_PAC_READAXISSTATUS);
    pac::FbInstance<FB_PAC_READALLAXESSTATUS> readAll = PAC_FB(FB_PAC_READALLAXESSTATUS);
    pac::FbInstance<FB_PAC_MOVEAXISABSOLUTE> moveAbs = PAC_FB(FB_PAC_MOVEAXISABSOLUTE);
    pac::FbInstance<FB_PAC_MOVEAXISRELATIVE> moveRel = PAC_FB(FB_PAC_MOVEAXISRELATIVE);
    pac::FbInstance<FB_PAC_STOPAXIS> stop = PAC_FB(FB_PAC_STOPAXIS);
    pac::FbInstance<FB_PAC_SETAXISSPEED> setSpeed = PAC_FB(FB_PAC_SETAXISSPEED);
    pac::FbInstance<FB_PAC_SETAXISACCELERATION> setAccel = PAC_FB(FB_PAC_SETAXISACCELERATION);

private:
    pac::test::CommandPlc plc_;
};

// The command in the master's CMD module: data, parameter, code without the SEND flag.
struct SentCommand {
    std::uint32_t data;
    std::uint16_t param;
    std::uint16_t code;
};

SentCommand Sent(const pac::sim::Image8& toPac) {
    return {pac::sim::ReadDword(toPac, 0), pac::sim::ReadWord(toPac, 2),
            static_cast<std::uint16_t>(pac::sim::ReadWord(toPac, 3) & 0x7FFF)};
}

// System parameter 21 is not in the manual's list ("not used"): the test configuration adds it with the
// full DINT range of 5.2.2.1, for signed values.
pac::sim::PaControlConfig WithWideSystemParameter() {
    pac::sim::PaControlConfig config;
    config.systemParameters.push_back(
        pac::sim::IntParameter(21, -2147483647, 2147483647, 0, "test: full DINT range"));
    return config;
}

class ParameterAxisFbs : public ::testing::TestWithParam<BusTiming> {
protected:
    const BusTiming& Param() const { return GetParam(); }
};

// ---- system parameters (5.2.2) ----

TEST_P(ParameterAxisFbs, SystemParameterLandsInTheControllerAndReadsBack) {
    AxisRig rig(Param());
    // 5.2.2.1 example: input 1 as the start input, 0700 parameter 3 data 1.
    rig.writeSys->PARAMETERNUMBER.value = 3;
    rig.writeSys->VALUE.value = 1;
    FinalOutcome write = rig.Run(rig.writeSys);
    ASSERT_TRUE(write.Done());
    EXPECT_TRUE(rig.Window().Contains(write.Scans())) << write << ", the protocol allows " << rig.Window() << "the FB adds no scan to FB_PAC_Cmd";
    EXPECT_EQ(rig.Controller().SystemParameters().IntValue(3), 1);
    const SentCommand sent = Sent(rig.LastCommand());
    EXPECT_EQ(sent.code, 0x0700);
    EXPECT_EQ(sent.param, 3);
    EXPECT_EQ(sent.data, 1u);

    rig.writeSys->VALUE.value = 1000;
    ASSERT_TRUE(rig.Run(rig.writeSys).Done());
    EXPECT_EQ(rig.Controller().SystemParameters().IntValue(3), 1000);

    rig.readSys->PARAMETERNUMBER.value = 3;
    rig.readSys->KIND.value = E_PAC_PARAMETERLIMIT__PAC_PARAM_VALUE;
    FinalOutcome read = rig.Run(rig.readSys);
    ASSERT_TRUE(read.Done());
    EXPECT_TRUE(rig.Window().Contains(read.Scans())) << read << ", the protocol allows " << rig.Window();
    EXPECT_EQ(rig.readSys->VALUE.value, 1000) << "the value holds after Execute fell";
    EXPECT_EQ(Sent(rig.LastCommand()).code, 0x1700);

    // 5.2.2.2 example: language 3 (French).
    rig.Controller().SystemParameters().Set(1, 3);
    rig.readSys->PARAMETERNUMBER.value = 1;
    ASSERT_TRUE(rig.Run(rig.readSys).Done());
    EXPECT_EQ(rig.readSys->VALUE.value, 3);
}

TEST_P(ParameterAxisFbs, SystemParameterLimitsSelectTheCommand) {
    AxisRig rig(Param());
    // 5.2.2.3 / 5.2.2.4 examples: at most 4 axes, at least 0.
    rig.readSys->PARAMETERNUMBER.value = 2;
    rig.readSys->KIND.value = E_PAC_PARAMETERLIMIT__PAC_PARAM_MAX;
    ASSERT_TRUE(rig.Run(rig.readSys).Done());
    EXPECT_EQ(Sent(rig.LastCommand()).code, 0x1701);
    EXPECT_EQ(rig.readSys->VALUE.value, 4);
    rig.readSys->KIND.value = E_PAC_PARAMETERLIMIT__PAC_PARAM_MIN;
    ASSERT_TRUE(rig.Run(rig.readSys).Done());
    EXPECT_EQ(Sent(rig.LastCommand()).code, 0x1702);
    EXPECT_EQ(rig.readSys->VALUE.value, 0);
    rig.readSys->KIND.value = E_PAC_PARAMETERLIMIT__PAC_PARAM_VALUE;
    ASSERT_TRUE(rig.Run(rig.readSys).Done());
    EXPECT_EQ(Sent(rig.LastCommand()).code, 0x1700);
    EXPECT_EQ(rig.readSys->VALUE.value, 2);
}

TEST_P(ParameterAxisFbs, SignedSystemParameterValuesRoundTrip) {
    AxisRig rig(Param(), WithWideSystemParameter());
    for (std::int32_t value : {-1, -2147483647, 2147483647, -123456789, 0}) {
        SCOPED_TRACE("value " + std::to_string(value));
        rig.writeSys->PARAMETERNUMBER.value = 21;
        rig.writeSys->VALUE.value = value;
        ASSERT_TRUE(rig.Run(rig.writeSys).Done());
        EXPECT_EQ(rig.Controller().SystemParameters().IntValue(21), value);
        EXPECT_EQ(Sent(rig.LastCommand()).data, static_cast<std::uint32_t>(value));
        rig.readSys->PARAMETERNUMBER.value = 21;
        rig.readSys->KIND.value = E_PAC_PARAMETERLIMIT__PAC_PARAM_VALUE;
        ASSERT_TRUE(rig.Run(rig.readSys).Done());
        EXPECT_EQ(rig.readSys->VALUE.value, value);
    }
    rig.readSys->KIND.value = E_PAC_PARAMETERLIMIT__PAC_PARAM_MIN;
    ASSERT_TRUE(rig.Run(rig.readSys).Done());
    EXPECT_EQ(rig.readSys->VALUE.value, -2147483647);
}

TEST_P(ParameterAxisFbs, SystemParameterErrorsAreThePacNumbers) {
    AxisRig rig(Param());
    // Number of axes: 0..4.
    rig.writeSys->PARAMETERNUMBER.value = 2;
    rig.writeSys->VALUE.value = 5;
    FinalOutcome outcome = rig.Run(rig.writeSys);
    EXPECT_TRUE(outcome.Error());
    EXPECT_EQ(outcome.ErrorId(), kGvl["PAC_ERR_VALUE_RANGE"]);
    EXPECT_EQ(rig.Controller().SystemParameters().IntValue(2), 2) << "unchanged";
    rig.writeSys->VALUE.value = -1;
    EXPECT_EQ(rig.Run(rig.writeSys).ErrorId(), kGvl["PAC_ERR_VALUE_RANGE"]);
    // 9 is "currently not used".
    rig.writeSys->PARAMETERNUMBER.value = 9;
    rig.writeSys->VALUE.value = 0;
    EXPECT_EQ(rig.Run(rig.writeSys).ErrorId(), kGvl["PAC_ERR_SYSTEM_PARAMETER"]);
    rig.readSys->PARAMETERNUMBER.value = 9;
    rig.readSys->VALUE.value = 77;
    outcome = rig.Run(rig.readSys);
    EXPECT_TRUE(outcome.Error());
    EXPECT_EQ(outcome.ErrorId(), kGvl["PAC_ERR_SYSTEM_PARAMETER"]);
    EXPECT_EQ(rig.readSys->VALUE.value, 77) << "Value changes only with Done";
    rig.readSys->PARAMETERNUMBER.value = 65535;
    EXPECT_EQ(rig.Run(rig.readSys).ErrorId(), kGvl["PAC_ERR_SYSTEM_PARAMETER"]);
    EXPECT_EQ(Sent(rig.LastCommand()).param, 65535);
    // A good command after the errors.
    rig.readSys->PARAMETERNUMBER.value = 2;
    ASSERT_TRUE(rig.Run(rig.readSys).Done());
    EXPECT_EQ(rig.readSys->VALUE.value, 2);
}

// ---- axis parameters (5.2.3) ----

TEST_P(ParameterAxisFbs, AxisParameterTheManualsExample) {
    AxisRig rig(Param());
    rig.writeSys->PARAMETERNUMBER.value = 2;  // three axes, so that axis 3 exists
    rig.writeSys->VALUE.value = 3;
    ASSERT_TRUE(rig.Run(rig.writeSys).Done());
    // 5.2.3 example: acceleration 200 for axis 3: parameter 0306, data 43 48 00 00.
    rig.writeAxis->AXIS.value = 3;
    rig.writeAxis->PARAMETERNUMBER.value = 6;
    rig.writeAxis->VALUE.value = 200.0F;
    FinalOutcome write = rig.Run(rig.writeAxis);
    ASSERT_TRUE(write.Done());
    EXPECT_TRUE(rig.Window().Contains(write.Scans())) << write << ", the protocol allows " << rig.Window();
    SentCommand sent = Sent(rig.LastCommand());
    EXPECT_EQ(sent.code, 0x0800);
    EXPECT_EQ(sent.param, 0x0306);
    EXPECT_EQ(sent.data, 0x43480000u);
    EXPECT_EQ(rig.Controller().Axes().Parameters(3).Value(6), 0x43480000u);
    EXPECT_EQ(rig.Controller().Axes().Parameters(2).Value(6), pac::sim::FloatToBits(10000.0F)) << "axis 2 untouched";
    // 5.2.3.2 example: the maximum traverse speed of axis 3, parameter 0301: 47 43 50 00 = 50000.0.
    rig.readAxis->AXIS.value = 3;
    rig.readAxis->PARAMETERNUMBER.value = 1;
    rig.readAxis->KIND.value = E_PAC_PARAMETERLIMIT__PAC_PARAM_MAX;
    ASSERT_TRUE(rig.Run(rig.readAxis).Done());
    sent = Sent(rig.LastCommand());
    EXPECT_EQ(sent.code, 0x1801);
    EXPECT_EQ(sent.param, 0x0301);
    EXPECT_EQ(Bits(rig.readAxis->VALUE.value), 0x47435000u);
    // 5.2.3.1 example: is the encoder of axis 2 inverted (parameter 021F)? 0.0: no.
    rig.readAxis->AXIS.value = 2;
    rig.readAxis->PARAMETERNUMBER.value = 31;
    rig.readAxis->KIND.value = E_PAC_PARAMETERLIMIT__PAC_PARAM_VALUE;
    ASSERT_TRUE(rig.Run(rig.readAxis).Done());
    sent = Sent(rig.LastCommand());
    EXPECT_EQ(sent.code, 0x1800);
    EXPECT_EQ(sent.param, 0x021F);
    EXPECT_EQ(Bits(rig.readAxis->VALUE.value), 0u);
    // The minimum acceleration (1802) of the simulator's table: 1.0.
    rig.readAxis->AXIS.value = 3;
    rig.readAxis->PARAMETERNUMBER.value = 6;
    rig.readAxis->KIND.value = E_PAC_PARAMETERLIMIT__PAC_PARAM_MIN;
    ASSERT_TRUE(rig.Run(rig.readAxis).Done());
    EXPECT_EQ(Sent(rig.LastCommand()).code, 0x1802);
    EXPECT_EQ(rig.readAxis->VALUE.value, 1.0F);
}

TEST_P(ParameterAxisFbs, AxisParameterRealValuesAreBitExact) {
    AxisRig rig(Param());
    // Axis parameter 8 (minimum traverse area) allows -1e6..1e6: normal, smallest normal, subnormal,
    // values with all 24 mantissa bits, the ends of the range.
    const std::vector<float> values = {-123.456F, 0.1F, 3.14159274F, std::numeric_limits<float>::min(),
                                       1.0e-40F, 999999.9375F, -999999.9375F, 1.0e6F, 16777215.0F / 32.0F, 0.0F};
    for (float value : values) {
        std::ostringstream trace;
        trace << "value " << value << " (bits " << std::hex << Bits(value) << ")";
        SCOPED_TRACE(trace.str());
        rig.writeAxis->AXIS.value = 1;
        rig.writeAxis->PARAMETERNUMBER.value = 8;
        rig.writeAxis->VALUE.value = value;
        ASSERT_TRUE(rig.Run(rig.writeAxis).Done());
        EXPECT_EQ(Sent(rig.LastCommand()).data, Bits(value));
        EXPECT_EQ(rig.Controller().Axes().Parameters(1).Value(8), Bits(value));
        rig.readAxis->AXIS.value = 1;
        rig.readAxis->PARAMETERNUMBER.value = 8;
        rig.readAxis->KIND.value = E_PAC_PARAMETERLIMIT__PAC_PARAM_VALUE;
        ASSERT_TRUE(rig.Run(rig.readAxis).Done());
        EXPECT_EQ(Bits(rig.readAxis->VALUE.value), Bits(value));
    }
}

TEST_P(ParameterAxisFbs, AxisParameterErrorsAreThePacNumbers) {
    AxisRig rig(Param());
    auto write = [&](int axis, int number, float value) {
        rig.writeAxis->AXIS.value = static_cast<USINT>(axis);
        rig.writeAxis->PARAMETERNUMBER.value = static_cast<USINT>(number);
        rig.writeAxis->VALUE.value = value;
        return rig.Run(rig.writeAxis);
    };
    // Traverse speed 1..50000.
    FinalOutcome outcome = write(1, 1, 0.5F);
    EXPECT_TRUE(outcome.Error());
    EXPECT_EQ(outcome.ErrorId(), kGvl["PAC_ERR_VALUE_RANGE"]);
    EXPECT_EQ(write(1, 1, 50000.5F).ErrorId(), kGvl["PAC_ERR_VALUE_RANGE"]);
    EXPECT_EQ(write(1, 1, std::numeric_limits<float>::quiet_NaN()).ErrorId(), kGvl["PAC_ERR_VALUE_RANGE"]);
    EXPECT_EQ(Sent(rig.LastCommand()).data, 0x7FC00000u) << "NaN goes out as the one quiet NaN";
    EXPECT_EQ(write(1, 1, std::numeric_limits<float>::infinity()).ErrorId(), kGvl["PAC_ERR_VALUE_RANGE"]);
    EXPECT_EQ(rig.Controller().Axes().Parameters(1).Value(1), pac::sim::FloatToBits(1000.0F)) << "unchanged";
    // Two axes are configured (system parameter 2); axis 0 does not exist.
    EXPECT_EQ(write(3, 1, 100.0F).ErrorId(), kGvl["PAC_ERR_AXIS_NUMBER"]);
    EXPECT_EQ(write(0, 1, 100.0F).ErrorId(), kGvl["PAC_ERR_AXIS_NUMBER"]);
    EXPECT_EQ(write(255, 1, 100.0F).ErrorId(), kGvl["PAC_ERR_AXIS_NUMBER"]);
    EXPECT_EQ(Sent(rig.LastCommand()).param, 0xFF01);
    // Parameter 10 (motor phase current) is not in the simulator's table.
    EXPECT_EQ(write(1, 10, 1.0F).ErrorId(), kGvl["PAC_ERR_AXIS_PARAMETER"]);
    rig.readAxis->AXIS.value = 2;
    rig.readAxis->PARAMETERNUMBER.value = 0;
    rig.readAxis->KIND.value = E_PAC_PARAMETERLIMIT__PAC_PARAM_MAX;
    EXPECT_EQ(rig.Run(rig.readAxis).ErrorId(), kGvl["PAC_ERR_AXIS_PARAMETER"]);
    rig.readAxis->AXIS.value = 9;
    EXPECT_EQ(rig.Run(rig.readAxis).ErrorId(), kGvl["PAC_ERR_AXIS_NUMBER"]);
    // Within the limits.
    outcome = write(2, 1, 50000.0F);
    EXPECT_TRUE(outcome.Done());
    EXPECT_EQ(rig.Controller().Axes().Parameters(2).RealValue(1), 50000.0F);
}

TEST_P(ParameterAxisFbs, ParameterCommandsAreRefusedOutsideHomePosition) {
    AxisRig rig(Param());
    ASSERT_TRUE(rig.GoOnline());
    const std::uint32_t inadmissible = kGvl["PAC_ERR_INADMISSIBLE_COMMAND"];
    rig.writeSys->PARAMETERNUMBER.value = 3;
    rig.writeSys->VALUE.value = 5;
    EXPECT_EQ(rig.Run(rig.writeSys).ErrorId(), inadmissible);
    EXPECT_EQ(rig.Controller().SystemParameters().IntValue(3), 0);
    rig.readSys->PARAMETERNUMBER.value = 2;
    EXPECT_EQ(rig.Run(rig.readSys).ErrorId(), inadmissible);
    rig.writeAxis->AXIS.value = 1;
    rig.writeAxis->PARAMETERNUMBER.value = 1;
    rig.writeAxis->VALUE.value = 2000.0F;
    EXPECT_EQ(rig.Run(rig.writeAxis).ErrorId(), inadmissible);
    EXPECT_EQ(rig.Controller().Axes().Parameters(1).RealValue(1), 1000.0F);
    rig.readAxis->AXIS.value = 1;
    rig.readAxis->PARAMETERNUMBER.value = 1;
    EXPECT_EQ(rig.Run(rig.readAxis).ErrorId(), inadmissible);
    // AUTOMATIC too.
    rig.Controller().SetOperatingStatus(11);
    rig.Settle(2 * (Param().latency + 1) + Param().pacMs);
    EXPECT_EQ(rig.Run(rig.writeAxis).ErrorId(), inadmissible);
    EXPECT_EQ(rig.Run(rig.readSys).ErrorId(), inadmissible);
}

// ---- axis position and status (5.2.4.18, 5.2.4.22, 5.2.4.23) ----

TEST_P(ParameterAxisFbs, AxisPositionIsBitExact) {
    AxisRig rig(Param());
    for (float position : {-1234.5678F, 0.1F, 5000.0F, 1.0e-40F}) {
        rig.Motion(2).Place(rig.Now(), static_cast<double>(position));
        rig.readPos->AXIS.value = 2;
        FinalOutcome outcome = rig.Run(rig.readPos);
        ASSERT_TRUE(outcome.Done());
        EXPECT_TRUE(rig.Window().Contains(outcome.Scans())) << outcome << ", the protocol allows " << rig.Window();
        const SentCommand sent = Sent(rig.LastCommand());
        EXPECT_EQ(sent.code, 0x190C);
        EXPECT_EQ(sent.param, 2);
        EXPECT_EQ(Bits(rig.readPos->POSITION.value), Bits(position));
    }
    rig.readPos->AXIS.value = 3;
    EXPECT_EQ(rig.Run(rig.readPos).ErrorId(), kGvl["PAC_ERR_AXIS_NUMBER"]);
}

TEST_P(ParameterAxisFbs, AxisStatusDecodesTheManualsValues) {
    AxisRig rig(Param());
    rig.readStatus->AXIS.value = 1;
    ASSERT_TRUE(rig.Run(rig.readStatus).Done());
    EXPECT_EQ(Sent(rig.LastCommand()).code, 0x1910);
    EXPECT_EQ(rig.readStatus->STATUS.value, 0);
    EXPECT_TRUE(rig.readStatus->INPOSITION.value);
    EXPECT_FALSE(rig.readStatus->MOVING.value || rig.readStatus->STOPPED.value ||
                 rig.readStatus->MALFUNCTION.value || rig.readStatus->MEASURINGMODE.value);

    rig.Motion(2).RaiseAxisError(rig.Now(), 500);
    rig.readStatus->AXIS.value = 2;
    ASSERT_TRUE(rig.Run(rig.readStatus).Done());
    EXPECT_EQ(Sent(rig.LastCommand()).param, 2);
    EXPECT_EQ(rig.readStatus->STATUS.value, 4);
    EXPECT_TRUE(rig.readStatus->MALFUNCTION.value);
    EXPECT_FALSE(rig.readStatus->INPOSITION.value || rig.readStatus->MOVING.value ||
                 rig.readStatus->STOPPED.value);

    rig.readStatus->AXIS.value = 17;
    FinalOutcome outcome = rig.Run(rig.readStatus);
    EXPECT_TRUE(outcome.Error());
    EXPECT_EQ(outcome.ErrorId(), kGvl["PAC_ERR_AXIS_NUMBER"]);
}

// ---- ONLINE axis commands (5.2.6) ----

TEST_P(ParameterAxisFbs, AbsoluteMoveStaysBusyWithThePositionFollowingAndEndsDoneAtTheTarget) {
    AxisRig rig(Param());
    ASSERT_TRUE(rig.GoOnline());
    const float target = 123.456F;  // 1000 AE/s (axis parameter 1), ramps of 100 ms: about 223 ms
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = target;
    rig.Start(rig.moveAbs);
    const auto edge = rig.EdgeTime();
    float last = 0.0F;
    bool sawBetween = false;
    bool sawActive = false;
    bool monotonic = true;
    bool busyWhileMoving = true;
    FinalOutcome outcome = rig.Wait(rig.moveAbs, 5000, [&] {
        const auto& fb = rig.moveAbs.Data();
        if (fb.DONE.value) return;
        if (rig.Motion(1).Moving() && !fb.BUSY.value) busyWhileMoving = false;
        if (fb.ACTIVE.value) {
            sawActive = true;
            if (fb.ACTUALPOSITION.value < last) monotonic = false;
            last = fb.ACTUALPOSITION.value;
            if (last > 0.0F && last < target) sawBetween = true;
        }
    });
    ASSERT_TRUE(outcome.Done()) << "error " << outcome.ErrorId();
    EXPECT_TRUE(sawActive);
    EXPECT_TRUE(sawBetween) << "ActualPosition followed the axis";
    EXPECT_TRUE(monotonic);
    EXPECT_TRUE(busyWhileMoving);
    EXPECT_GE(rig.Now() - edge, 123ms) << "Done only at end of processing";
    EXPECT_FALSE(rig.moveAbs->ACTIVE.value);
    EXPECT_EQ(Bits(rig.moveAbs->ACTUALPOSITION.value), Bits(target));
    EXPECT_EQ(Bits(static_cast<float>(rig.Motion(1).Position())), Bits(target));
    const SentCommand sent = Sent(rig.LastCommand());
    EXPECT_EQ(sent.code, 0x0A87);
    EXPECT_EQ(sent.param, 1);
    EXPECT_EQ(sent.data, Bits(target));
    rig.Release(rig.moveAbs);
    EXPECT_FALSE(rig.moveAbs->DONE.value);
    EXPECT_EQ(Bits(rig.moveAbs->ACTUALPOSITION.value), Bits(target)) << "kept after Execute fell";
    EXPECT_EQ(rig.Controller().Counters().Count(0x0A87), 1u);

    rig.readPos->AXIS.value = 1;
    ASSERT_TRUE(rig.Run(rig.readPos).Done());
    EXPECT_EQ(Bits(rig.readPos->POSITION.value), Bits(target));
    rig.readStatus->AXIS.value = 1;
    ASSERT_TRUE(rig.Run(rig.readStatus).Done());
    EXPECT_TRUE(rig.readStatus->INPOSITION.value);
}

TEST_P(ParameterAxisFbs, RelativeMoveFromTheCurrentPosition) {
    AxisRig rig(Param());
    ASSERT_TRUE(rig.GoOnline());
    rig.Motion(2).Place(rig.Now(), 100.0);
    rig.moveRel->AXIS.value = 2;
    rig.moveRel->DISTANCE.value = -30.5F;
    float first = -1.0F;
    rig.Start(rig.moveRel);
    bool decreasing = true;
    float last = 1000.0F;
    SentCommand move{};
    FinalOutcome outcome = rig.Wait(rig.moveRel, 5000, [&] {
        const auto& fb = rig.moveRel.Data();
        if (!fb.ACTIVE.value) return;
        move = Sent(rig.LastCommand());
        if (first < 0.0F) first = fb.ACTUALPOSITION.value;
        if (fb.ACTUALPOSITION.value > last) decreasing = false;
        last = fb.ACTUALPOSITION.value;
    });
    ASSERT_TRUE(outcome.Done()) << "error " << outcome.ErrorId();
    if (Param().plcMs <= Param().pacMs) {
        EXPECT_EQ(first, 100.0F) << "the acknowledgement carries the start position";
    } else {
        // A PLC slower than the controller can miss the acknowledging reply itself.
        EXPECT_LE(first, 100.0F);
        EXPECT_GT(first, 69.5F);
    }
    EXPECT_TRUE(decreasing);
    EXPECT_EQ(rig.moveRel->ACTUALPOSITION.value, 69.5F);
    EXPECT_EQ(move.code, 0x0A89);
    EXPECT_EQ(move.data, Bits(-30.5F));
    // After END OF PROCESSING the status read (1910) told "in position", then 190C read where the axis stands.
    EXPECT_EQ(Sent(rig.LastCommand()).code, 0x190C);
    rig.Release(rig.moveRel);
    EXPECT_EQ(rig.Motion(2).Position(), 69.5);
}

// A stop of the mode (the external stop input losing its power, 5.2.1.3) ends a 0A89 short: the PA-CONTROL sets
// END OF PROCESSING at the stop position (5.2.6.7), the axis status reads 2 (stopped): CommandAborted, not Done.
TEST_P(ParameterAxisFbs, RelativeMoveThatAModeStopCutsShortIsCommandAborted) {
    AxisRig rig(Param());
    ASSERT_TRUE(rig.GoOnline());
    rig.Motion(2).Place(rig.Now(), 100.0);
    rig.moveRel->AXIS.value = 2;
    rig.moveRel->DISTANCE.value = 300.0F;
    rig.Start(rig.moveRel);
    bool stopped = false;
    const FinalOutcome outcome = rig.Wait(rig.moveRel, 20000, [&] {
        if (!stopped && rig.Motion(2).Position() > 150.0) {
            rig.Controller().Io().inputs.Set(7, false);
            stopped = true;
        }
    });
    ASSERT_TRUE(stopped) << "the move never passed 150";
    EXPECT_TRUE(outcome.Aborted()) << "Done " << outcome.Done() << ", error " << outcome.ErrorId();
    EXPECT_LT(rig.moveRel->ACTUALPOSITION.value, 399.0F);
    EXPECT_NEAR(rig.moveRel->ACTUALPOSITION.value, rig.Motion(2).Position(), 0.001);
    rig.Release(rig.moveRel);
}

TEST_P(ParameterAxisFbs, MoveErrorsAreTheManualsNumbers) {
    AxisRig rig(Param());
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 50.0F;
    // Home position: moves need ONLINE.
    EXPECT_EQ(rig.Run(rig.moveAbs).ErrorId(), kGvl["PAC_ERR_INADMISSIBLE_COMMAND"]);
    ASSERT_TRUE(rig.GoOnline());
    // Without reference: 43.
    rig.Motion(1).SetReferenced(false);
    bool active = false;
    rig.Start(rig.moveAbs);
    FinalOutcome outcome = rig.Wait(rig.moveAbs, 5000, [&] { active = active || rig.moveAbs->ACTIVE.value; });
    rig.Release(rig.moveAbs);
    EXPECT_TRUE(outcome.Error());
    EXPECT_EQ(outcome.ErrorId(), kGvl["PAC_ERR_NO_REFERENCE"]);
    EXPECT_FALSE(active);
    EXPECT_EQ(rig.moveAbs->ACTUALPOSITION.value, 0.0F) << "a command error carries no position";
    rig.Motion(1).SetReferenced(true);
    // Outside the traverse area (axis parameters 8..9: 0..10000): 65.
    rig.moveAbs->POSITION.value = 10000.5F;
    EXPECT_EQ(rig.Run(rig.moveAbs).ErrorId(), kGvl["PAC_ERR_POSITION_RANGE"]);
    rig.moveRel->AXIS.value = 1;
    rig.moveRel->DISTANCE.value = -0.25F;
    EXPECT_EQ(rig.Run(rig.moveRel).ErrorId(), kGvl["PAC_ERR_POSITION_RANGE"]);
    // Axis 3 is not configured: 32. A target that is no number: 41.
    rig.moveAbs->AXIS.value = 3;
    rig.moveAbs->POSITION.value = 50.0F;
    EXPECT_EQ(rig.Run(rig.moveAbs).ErrorId(), kGvl["PAC_ERR_AXIS_NUMBER"]);
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(rig.Run(rig.moveAbs).ErrorId(), kGvl["PAC_ERR_VALUE_RANGE"]);
    EXPECT_FALSE(rig.Motion(1).Moving());
    EXPECT_EQ(rig.Controller().Counters().executed - rig.Controller().Counters().Count(0x190B), 2u) << "only 0700 and 0603";
    // The axis did not move; a good move afterwards.
    rig.moveAbs->POSITION.value = 10000.0F;
    rig.moveAbs->ENDTIMEOUT.value = pac::ToIecTime(20s);
    EXPECT_TRUE(rig.Run(rig.moveAbs).Done());
}

TEST_P(ParameterAxisFbs, StopAxisStopsAMoveAndTheMoveShowsCommandAborted) {
    AxisRig rig(Param());
    ASSERT_TRUE(rig.GoOnline());
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 1000.0F;  // one second at 1000 AE/s
    rig.Start(rig.moveAbs);
    ASSERT_FALSE(rig.Wait(rig.moveAbs, 100).Ended()) << "the move ended too early";
    int guard = 0;
    while (rig.moveAbs->ACTUALPOSITION.value < 50.0F && guard++ < 1000) rig.Settle(1);
    ASSERT_TRUE(rig.moveAbs->ACTIVE.value);

    rig.stop->AXIS.value = 1;
    rig.Start(rig.stop);
    bool moveErrored = false;
    bool moveAborted = false;
    bool stopBusyWhileBraking = true;
    bool brakingSeen = false;
    float stopLast = 0.0F;
    bool stopMonotonic = true;
    FinalOutcome stopped = rig.Wait(rig.stop, 5000, [&] {
        moveErrored = moveErrored || rig.moveAbs->ERROR.value;
        moveAborted = moveAborted || rig.moveAbs->COMMANDABORTED.value;
        if (rig.stop->DONE.value) return;
        if (rig.Motion(1).Moving() && !rig.stop->BUSY.value) stopBusyWhileBraking = false;
        if (rig.stop->BUSY.value && rig.stop->ACTUALPOSITION.value > 0.0F) {
            brakingSeen = true;
            if (rig.stop->ACTUALPOSITION.value < stopLast) stopMonotonic = false;
            stopLast = rig.stop->ACTUALPOSITION.value;
        }
    });
    ASSERT_TRUE(stopped.Done()) << "error " << stopped.ErrorId();
    EXPECT_TRUE(brakingSeen) << "0A93 reports the position while braking";
    EXPECT_TRUE(stopMonotonic);
    EXPECT_TRUE(stopBusyWhileBraking);
    EXPECT_FALSE(rig.Motion(1).Moving());
    const float stopPosition = static_cast<float>(rig.Motion(1).Position());
    EXPECT_LT(stopPosition, 1000.0F);
    EXPECT_EQ(Bits(rig.stop->ACTUALPOSITION.value), Bits(stopPosition));
    EXPECT_EQ(Sent(rig.LastCommand()).code, 0x0A93);
    EXPECT_EQ(Sent(rig.LastCommand()).param, 1);
    EXPECT_TRUE(moveAborted);
    EXPECT_FALSE(moveErrored);
    EXPECT_TRUE(rig.moveAbs->COMMANDABORTED.value) << "held while Execute stays TRUE";
    EXPECT_FALSE(rig.moveAbs->BUSY.value || rig.moveAbs->DONE.value || rig.moveAbs->ACTIVE.value);
    EXPECT_EQ(rig.moveAbs->ERRORID.value, 0);
    rig.Release(rig.stop);
    rig.Release(rig.moveAbs);
    EXPECT_FALSE(rig.moveAbs->COMMANDABORTED.value);

    rig.readStatus->AXIS.value = 1;
    ASSERT_TRUE(rig.Run(rig.readStatus).Done());
    EXPECT_EQ(rig.readStatus->STATUS.value, 2);
    EXPECT_TRUE(rig.readStatus->STOPPED.value);
    EXPECT_FALSE(rig.readStatus->INPOSITION.value);
    rig.readPos->AXIS.value = 1;
    ASSERT_TRUE(rig.Run(rig.readPos).Done());
    EXPECT_EQ(Bits(rig.readPos->POSITION.value), Bits(stopPosition));

    // 0A93 on a standing axis: Done at once, with its position.
    FinalOutcome again = rig.Run(rig.stop);
    EXPECT_TRUE(again.Done());
    EXPECT_EQ(Bits(rig.stop->ACTUALPOSITION.value), Bits(stopPosition));
}

// 5.2.6.6: 0A87 is reported complete only with its end of processing, and another command must not
// follow before it (0A94 is the command for that). A read asked for during the move waits (Busy) until
// the move has ended, then goes out; the move FB follows its own command to the end: Done, not aborted.
TEST_P(ParameterAxisFbs, ACommandDuringAMoveWaitsForItsEndOfProcessing) {
    AxisRig rig(Param());
    ASSERT_TRUE(rig.GoOnline());
    rig.moveAbs->AXIS.value = 2;
    rig.moveAbs->POSITION.value = 300.0F;
    rig.Start(rig.moveAbs);
    int guard = 0;
    while (!rig.moveAbs->ACTIVE.value && guard++ < 1000) rig.Settle(1);
    ASSERT_TRUE(rig.moveAbs->ACTIVE.value);
    const std::uint64_t recognisedBefore = rig.Controller().Counters().recognized;
    rig.readAll->TIMEOUT.value = pac::ToIecTime(std::chrono::seconds(30));
    rig.readAll->EXECUTE.value = TRUE;
    bool sawMovingWhileReadWaits = false;
    guard = 0;
    while (!rig.moveAbs->DONE.value && !rig.moveAbs->ERROR.value && !rig.moveAbs->COMMANDABORTED.value &&
           guard++ < 20000) {
        rig.Settle(1);
        ASSERT_EQ(rig.Controller().Counters().recognized, recognisedBefore) << "nothing else during the move";
        EXPECT_TRUE(rig.readAll->BUSY.value);
        sawMovingWhileReadWaits = sawMovingWhileReadWaits || rig.Motion(2).Moving();
    }
    EXPECT_TRUE(sawMovingWhileReadWaits);
    ASSERT_TRUE(rig.moveAbs->DONE.value) << "the move FB follows its command to its end";
    EXPECT_EQ(rig.Motion(2).Position(), 300.0);
    guard = 0;
    while (!rig.readAll->DONE.value && !rig.readAll->ERROR.value && guard++ < 1000) rig.Settle(1);
    ASSERT_TRUE(rig.readAll->DONE.value);
    EXPECT_EQ(Sent(rig.LastCommand()).code, 0x1911);
    EXPECT_EQ(rig.readAll->MOVINGAXES.value, 0) << "asked during the move, read after its end";
    EXPECT_EQ(rig.Controller().Counters().recognized, recognisedBefore + 1);
}

TEST_P(ParameterAxisFbs, SetAxisSpeedChangesTheTraverseSpeed) {
    AxisRig rig(Param());
    ASSERT_TRUE(rig.GoOnline());
    rig.setSpeed->AXIS.value = 1;
    rig.setSpeed->SPEED.value = 2000.0F;
    FinalOutcome outcome = rig.Run(rig.setSpeed);
    ASSERT_TRUE(outcome.Done());
    const SentCommand sent = Sent(rig.LastCommand());
    EXPECT_EQ(sent.code, 0x0A8D);
    EXPECT_EQ(sent.param, 1);
    EXPECT_EQ(sent.data, 0x44FA0000u);
    EXPECT_EQ(rig.SessionDynamics(1).speed, 2000.0);
    // Limits of axis parameter 1 (1..50000), and > 0.
    rig.setSpeed->SPEED.value = 50001.0F;
    EXPECT_EQ(rig.Run(rig.setSpeed).ErrorId(), kGvl["PAC_ERR_VALUE_RANGE"]);
    rig.setSpeed->SPEED.value = 0.0F;
    EXPECT_EQ(rig.Run(rig.setSpeed).ErrorId(), kGvl["PAC_ERR_VALUE_RANGE"]);
    rig.setSpeed->AXIS.value = 3;
    rig.setSpeed->SPEED.value = 100.0F;
    EXPECT_EQ(rig.Run(rig.setSpeed).ErrorId(), kGvl["PAC_ERR_AXIS_NUMBER"]);
    EXPECT_EQ(rig.SessionDynamics(1).speed, 2000.0);
    // 2000 AE at 2000 AE/s with ramps of 10000 AE/s^2 (200 ms, 200 AE each): 1.2 s, not 2.1 s as at 1000 AE/s.
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 2000.0F;
    rig.Start(rig.moveAbs);
    const auto edge = rig.EdgeTime();
    ASSERT_TRUE(rig.Wait(rig.moveAbs).Done());
    EXPECT_GE(rig.Now() - edge, 1200ms);
    EXPECT_LT(rig.Now() - edge, 1260ms);
    rig.Release(rig.moveAbs);
    // Home position: refused.
    rig.cmd->CODE.value = 0x0A81;  // PAC_CMD_ABORT_ONLINE
    ASSERT_TRUE(rig.Run(rig.cmd).Done());
    rig.setSpeed->AXIS.value = 1;
    EXPECT_EQ(rig.Run(rig.setSpeed).ErrorId(), kGvl["PAC_ERR_INADMISSIBLE_COMMAND"]);
}

TEST_P(ParameterAxisFbs, SetAxisAccelerationSendsTheManualsCommand) {
    AxisRig rig(Param());
    ASSERT_TRUE(rig.GoOnline());
    // 5.2.6.9 example: acceleration 10 for axis 3: 0A8E, parameter 3, data 41 20 00 00.
    rig.setAccel->AXIS.value = 3;
    rig.setAccel->ACCELERATION.value = 10.0F;
    FinalOutcome outcome = rig.Run(rig.setAccel);
    const SentCommand sent = Sent(rig.LastCommand());
    EXPECT_EQ(sent.code, 0x0A8E);
    EXPECT_EQ(sent.param, 3);
    EXPECT_EQ(sent.data, 0x41200000u);
    EXPECT_EQ(rig.Controller().Counters().Count(0x0A8E), 1u);
    // The simulated controller is configured with fewer axes than the manual's example uses.
    EXPECT_EQ(outcome.ErrorId(), kGvl["PAC_ERR_AXIS_NUMBER"]);
    rig.setAccel->AXIS.value = 1;
    outcome = rig.Run(rig.setAccel);
    ASSERT_TRUE(outcome.Done()) << "ErrorID " << outcome.ErrorId();
    EXPECT_EQ(rig.SessionDynamics(1).acceleration, 10.0);  // one value for both ramps of the CMD moves
    EXPECT_EQ(rig.SessionDynamics(1).deceleration, 10.0);
    // Below the acceleration parameter's minimum (1.0): value outside range.
    rig.setAccel->ACCELERATION.value = 0.5F;
    EXPECT_EQ(rig.Run(rig.setAccel).ErrorId(), kGvl["PAC_ERR_VALUE_RANGE"]);
}

TEST_P(ParameterAxisFbs, MoveLongerThanEndTimeoutIsALibraryError) {
    AxisRig rig(Param());
    ASSERT_TRUE(rig.GoOnline());
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 1000.0F;
    rig.moveAbs->ENDTIMEOUT.value = pac::ToIecTime(200ms);
    FinalOutcome outcome = rig.Run(rig.moveAbs);
    EXPECT_TRUE(outcome.Error());
    EXPECT_FALSE(outcome.Aborted());
    EXPECT_EQ(outcome.ErrorId(), kGvl["PAC_LIB_ERR_END_TIMEOUT"]);
    EXPECT_TRUE(rig.Motion(1).Moving()) << "the library stops waiting, not the axis";
    rig.stop->AXIS.value = 1;
    FinalOutcome stopped = rig.Run(rig.stop);
    EXPECT_TRUE(stopped.Done());
}

TEST_P(ParameterAxisFbs, ExecuteFallingDuringAMoveShowsDoneForOneScan) {
    AxisRig rig(Param());
    ASSERT_TRUE(rig.GoOnline());
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 30.0F;
    rig.Start(rig.moveAbs);
    rig.Release(rig.moveAbs);
    int doneScans = 0;
    int guard = 0;
    while ((rig.moveAbs->BUSY.value || doneScans == 0) && guard++ < 2000) {
        rig.Settle(1);
        if (rig.moveAbs->DONE.value) ++doneScans;
    }
    rig.Settle(3);
    EXPECT_EQ(doneScans, 1);
    EXPECT_FALSE(rig.moveAbs->DONE.value);
    EXPECT_EQ(rig.moveAbs->ACTUALPOSITION.value, 30.0F);
    EXPECT_EQ(rig.Motion(1).Position(), 30.0);
}

INSTANTIATE_TEST_SUITE_P(BusTimings, ParameterAxisFbs,
                         ::testing::ValuesIn(pac::test::BusTimingGrid({1, 5}, {3, 10}, {0, 2})),
                         pac::test::BusTimingName);

// Starts the move `fb` of `axis` and scans until the controller has taken it over and the axis moves.
template <class Fb>
void StartTakenOverMove(AxisRig& rig, pac::FbInstance<Fb>& fb, int axis) {
    rig.Start(fb);
    int guard = 0;
    while (!fb->ACTIVE.value && guard++ < 1000) rig.Settle(1);
    ASSERT_TRUE(fb->ACTIVE.value);
    ASSERT_TRUE(rig.Motion(axis).Moving());
}

// PLCopen's CommandAborted for the long commands other than the absolute move (which the timing grid above
// covers). A command owns the CMD interface until its end of processing; only a stop of what it runs may
// overtake it (F_PAC_IsStopOver), and the PA-CONTROL then reports the stop alone: the move FB is aborted.
TEST(ParameterAxisFbsOverSim, RelativeMoveOvertakenByTheStopOfItsAxisIsCommandAborted) {
    AxisRig rig({1, 3, 1});
    ASSERT_TRUE(rig.GoOnline());
    rig.moveRel->AXIS.value = 2;
    rig.moveRel->DISTANCE.value = 300.0F;
    ASSERT_NO_FATAL_FAILURE(StartTakenOverMove(rig, rig.moveRel, 2));
    rig.stop->AXIS.value = 2;
    ASSERT_TRUE(rig.Run(rig.stop).Done());
    EXPECT_TRUE(rig.moveRel->COMMANDABORTED.value);
    EXPECT_FALSE(rig.moveRel->ERROR.value);
    EXPECT_EQ(rig.moveRel->ERRORID.value, 0) << "CommandAborted carries no ErrorID";
    EXPECT_FALSE(rig.Motion(2).Moving()) << "the stop ended the move";
    EXPECT_LT(rig.Motion(2).Position(), 300.0);
    rig.Release(rig.moveRel);
    EXPECT_FALSE(rig.moveRel->COMMANDABORTED.value);
}

// cmd_abort_online 0A81 (5.2.6.1): "positioning is stopped", ONLINE ends. Like the other stops it overtakes a
// running move (F_PAC_IsStopCommand, F_PAC_IsStopOver): it goes out while the move processes, not after
// Timeout with 16#8006, the axis stops short of its target and the move FB is aborted, not Done.
TEST_P(ParameterAxisFbs, AbortOnlineOvertakesARunningMove) {
    AxisRig rig(Param());
    ASSERT_TRUE(rig.GoOnline());
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 3000.0F;
    ASSERT_NO_FATAL_FAILURE(StartTakenOverMove(rig, rig.moveAbs, 1));
    rig.cmd->CODE.value = 0x0A81;  // PAC_CMD_ABORT_ONLINE
    rig.cmd->PARAM.value = 0;
    rig.cmd->DATA.value = 0;
    rig.cmd->TIMEOUT.value = pac::ToIecTime(200ms);
    const FinalOutcome aborted = rig.Run(rig.cmd);
    EXPECT_TRUE(aborted.Done()) << aborted;
    EXPECT_EQ(rig.Controller().OperatingStatus(), 1) << "HOME POSITION";
    rig.Settle(200);
    EXPECT_FALSE(rig.Motion(1).Moving());
    EXPECT_LT(rig.Motion(1).Position(), 3000.0);
    EXPECT_TRUE(rig.moveAbs->COMMANDABORTED.value) << "stopped short of its target";
    EXPECT_FALSE(rig.moveAbs->DONE.value || rig.moveAbs->ERROR.value);
}

// A move and the stop of its axis edged in one scan, the move's FB called first, with the two-step write:
// the stop takes the interface between the move's data and its toggle, the move never goes out, and its
// FB shows CommandAborted (16#8016 inside), never Done with the stop's answer (issue 24, item 1).
TEST(ParameterAxisFbsOverSim, MoveOvertakenByTheStopOfItsAxisBeforeItWentOutIsCommandAborted) {
    AxisRig rig({1, 1, 0});
    rig.SetTwoStepWrite(true);
    ASSERT_TRUE(rig.GoOnline());
    const double start = rig.Motion(1).Position();
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 300.0F;
    rig.stop->AXIS.value = 1;
    rig.moveAbs->EXECUTE.value = TRUE;
    rig.Start(rig.stop);
    const FinalOutcome stopped = rig.Wait(rig.stop);
    EXPECT_TRUE(stopped.Done()) << stopped;
    rig.Settle(5);
    EXPECT_TRUE(rig.moveAbs->COMMANDABORTED.value);
    EXPECT_FALSE(rig.moveAbs->DONE.value || rig.moveAbs->ERROR.value);
    EXPECT_EQ(rig.Motion(1).Position(), start) << "the move never reached the controller";
}

// The axis stop is itself overtaken by cmd_stop (0600, which may overtake anything): CommandAborted.
TEST(ParameterAxisFbsOverSim, StopOvertakenByCmdStopWhileTheAxisBrakesIsCommandAborted) {
    AxisRig rig({1, 3, 1});
    ASSERT_TRUE(rig.GoOnline());
    rig.setAccel->AXIS.value = 1;
    rig.setAccel->ACCELERATION.value = 50.0F;  // AE/s^2 both ways: braking takes a while
    ASSERT_TRUE(rig.Run(rig.setAccel).Done());
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 1000.0F;
    rig.Start(rig.moveAbs);
    rig.Settle(400);
    rig.stop->AXIS.value = 1;
    rig.Start(rig.stop);
    int guard = 0;
    while (!(rig.stop->BUSY.value && rig.stop->ACTUALPOSITION.value > 0.0F) && guard++ < 1000) rig.Settle(1);
    ASSERT_TRUE(rig.stop->BUSY.value) << "acknowledged, braking";
    ASSERT_TRUE(rig.Motion(1).Moving());
    rig.cmd->CODE.value = 0x0600;
    rig.cmd->PARAM.value = 0;
    rig.cmd->DATA.value = 0;
    ASSERT_TRUE(rig.Run(rig.cmd).Done());
    EXPECT_TRUE(rig.stop->COMMANDABORTED.value);
    EXPECT_FALSE(rig.stop->ERROR.value);
    EXPECT_EQ(rig.stop->ERRORID.value, 0);
}

// A stop the PA-CONTROL refuses is its error, with its number; the position output keeps its value.
TEST(ParameterAxisFbsOverSim, StopOfAnAxisTheControllerDoesNotHaveIsItsError) {
    AxisRig rig({1, 3, 1});
    ASSERT_TRUE(rig.GoOnline());
    rig.stop->AXIS.value = 3;  // the simulated controller has fewer axes
    const FinalOutcome outcome = rig.Run(rig.stop);
    ASSERT_TRUE(outcome.Error());
    EXPECT_FALSE(outcome.Aborted());
    EXPECT_EQ(outcome.ErrorId(), kGvl["PAC_ERR_AXIS_NUMBER"]);
    EXPECT_EQ(rig.stop->ACTUALPOSITION.value, 0.0F);
}

// A lost link during a move is an Error, not CommandAborted: the reply shows status 0.
TEST(ParameterAxisFbsOverSim, PowerCycleDuringAMoveIsAnErrorNotCommandAborted) {
    AxisRig rig({1, 3, 1}, {}, 30ms);
    ASSERT_TRUE(rig.GoOnline());
    rig.moveAbs->AXIS.value = 1;
    rig.moveAbs->POSITION.value = 500.0F;
    rig.Start(rig.moveAbs);
    int guard = 0;
    while (!rig.moveAbs->ACTIVE.value && guard++ < 1000) rig.Settle(1);
    ASSERT_TRUE(rig.moveAbs->ACTIVE.value);
    rig.Controller().PowerCycle(rig.Now());
    FinalOutcome outcome = rig.Wait(rig.moveAbs, 1000);
    EXPECT_TRUE(outcome.Error());
    EXPECT_FALSE(outcome.Aborted());
    EXPECT_EQ(outcome.ErrorId(), kGvl["PAC_LIB_ERR_CONNECTION_LOST"]);
}

}  // namespace
}  // namespace test_parameter_axis_fbs
