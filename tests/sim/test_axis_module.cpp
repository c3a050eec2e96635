// The controller's side of one 12-byte axis module (sim axis_module.hpp, manual 2.7,
// docs/sim_axis_modules.md, docs/simulator.md "Axis modules (2.7)"), driven cycle by cycle: one Step() is one
// controller cycle of 10 ms with the PLC's 12 bytes, against a ServoAxis with the default parameters
// (1000 units/s, 10000 units/s^2: a 100-unit move is a triangle of 0.2 s peaking at 50 units). Expected
// positions are worked out in the comments.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pac/sim/axis_module.hpp"
#include "pac/sim/elements.hpp"
#include "pac/sim/process_image.hpp"
#include "pac/sim/servo_axis.hpp"

namespace pac::sim {
namespace {

using namespace std::chrono_literals;
namespace ac = axis_control;
namespace as = axis_status;

// Status words that recur: limit switches not actuated (bits 9 and 10 high, low-active).
constexpr std::uint32_t kSwitchesFree = as::kNegativeLimitNotActuated | as::kPositiveLimitNotActuated;
constexpr std::uint32_t kOnReferenced = as::kDriveEnabled | as::kReferenced | kSwitchesFree;  // 0x701
constexpr std::uint32_t kOnActive = kOnReferenced | as::kActive;                              // 0x781
constexpr std::uint32_t kOn = ac::kAxisOn;

std::string Hex(const Image12& module) {
    ProcessImage image(12);
    for (std::size_t i = 0; i < 12; ++i) image[i] = module[i];
    return ToHex(image);
}

Image12 Hex12(const std::string& text) {
    std::istringstream in(text);
    Image12 module{};
    for (auto& byte : module) {
        unsigned value = 0;
        in >> std::hex >> value;
        byte = static_cast<std::uint8_t>(value);
    }
    return module;
}

ServoAxisConfig Referenced() {
    ServoAxisConfig c;
    c.referenced = true;
    return c;
}

// Position of a triangle move of 100 units, s seconds after its start (a = 10000 units/s^2).
double Triangle100(double s) { return s <= 0.1 ? 5000.0 * s * s : 100.0 - 5000.0 * (0.2 - s) * (0.2 - s); }

// One row of a cycle-by-cycle sequence: what the PLC sends, what the reply must say.
struct Row {
    std::uint32_t control;
    std::uint32_t status;
    std::uint16_t cmdError;
    std::uint16_t axisError;
    double position;
};

class AxisModuleBench : public ::testing::Test {
protected:
    explicit AxisModuleBench(ServoAxisConfig config = Referenced(), AxisModuleConfig moduleConfig = {})
        : axis_(config), module_(moduleConfig) {
        toPac_.speedPerMille = 1000;
        toPac_.accelerationPerMille = 1000;
    }

    AxisModuleContext Context() const {
        AxisModuleContext c;
        c.now = now_;
        c.service = service_;
        c.integerFormat = integer_;
        c.inputs = &inputs_;
        c.groupDisplaced = groupDisplaced_;
        return c;
    }

    // One controller cycle with the PLC's current bytes; then time moves on by 10 ms.
    AxisModuleReply Step() {
        reply_ = module_.Cycle(toPac_.Encode(), axis_, Context());
        now_ += 10ms;
        return AxisModuleReply::Decode(reply_);
    }
    AxisModuleReply Step(std::uint32_t control) {
        toPac_.control = control;
        return Step();
    }
    AxisModuleReply Step(std::uint32_t control, double position) {
        toPac_.position = EncodeModulePosition(position, integer_);
        return Step(control);
    }
    // Steps with `control` until the reply's status has none of `bits` (at most `limit` cycles).
    AxisModuleReply StepUntilClear(std::uint32_t control, std::uint32_t bits, int limit = 2000) {
        AxisModuleReply r = Step(control);
        for (int i = 0; i < limit && (r.status & bits) != 0; ++i) r = Step(control);
        return r;
    }

    void Expect(const AxisModuleReply& r, const Row& row, const std::string& where) {
        EXPECT_EQ(r.status, row.status) << where << std::hex << ": status 0x" << r.status << " expected 0x"
                                        << row.status;
        EXPECT_EQ(r.cmdError, row.cmdError) << where;
        EXPECT_EQ(r.axisError, row.axisError) << where;
        EXPECT_EQ(r.position, EncodeModulePosition(row.position, integer_))
            << where << ": position " << DecodeModulePosition(r.position, integer_) << " expected " << row.position;
    }

    // Runs the rows, one cycle each.
    void Run(const std::vector<Row>& rows) {
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const auto t = std::chrono::duration_cast<std::chrono::milliseconds>(now_).count();
            Expect(Step(rows[i].control), rows[i], "row " + std::to_string(i) + " (t = " + std::to_string(t) + " ms)");
        }
    }

    ServoAxis axis_;
    AxisModule module_;
    AxisModuleCommand toPac_;
    BitBank inputs_{16};
    std::chrono::nanoseconds now_{0};
    AxisModuleService service_ = AxisModuleService::kJobs;
    bool integer_ = false;
    bool groupDisplaced_ = false;
    Image12 reply_{};
};

// ---- the bytes ----------------------------------------------------------------------------------------

TEST(AxisModuleBytes, FieldsAreBigEndianAtTheirOffsets) {
    const AxisModuleCommand c = AxisModuleCommand::Decode(Hex12("00 02 00 45 03 E8 01 F4 42 C8 00 00"));
    EXPECT_EQ(c.control, ac::kAxisOn | ac::kStart | ac::kMoveAbsolute | ac::kDisableLimitSwitches);
    EXPECT_EQ(c.accelerationPerMille, 1000);
    EXPECT_EQ(c.speedPerMille, 500);
    EXPECT_EQ(c.position, 0x42C80000u);
    EXPECT_EQ(Hex(c.Encode()), "00 02 00 45 03 E8 01 F4 42 C8 00 00");

    AxisModuleReply r;
    r.status = as::kAxisError | as::kCmdError | kOnReferenced;
    r.cmdError = 43;
    r.axisError = 64;
    r.position = 0xFFFF9E2Bu;
    EXPECT_EQ(Hex(r.Encode()), "00 00 C7 01 00 2B 00 40 FF FF 9E 2B");
    const AxisModuleReply back = AxisModuleReply::Decode(r.Encode());
    EXPECT_EQ(back.status, r.status);
    EXPECT_EQ(back.cmdError, 43);
    EXPECT_EQ(back.axisError, 64);
    EXPECT_EQ(back.position, r.position);
}

TEST(AxisModuleBytes, PositionsAsIeeeOrDintTimes1000) {
    // 2.5.3.2: 12345 -> 12.345, 25.045 -> 25045.
    EXPECT_EQ(DecodeModulePosition(12345, true), 12.345);
    EXPECT_EQ(EncodeModulePosition(25.045, true), 25045u);
    EXPECT_EQ(EncodeModulePosition(-25.045, true), 0xFFFF9E2Bu);
    EXPECT_EQ(DecodeModulePosition(0xFFFF9E2Bu, true), -25.045);
    EXPECT_EQ(EncodeModulePosition(0.0004, true), 0u);   // rounded to the nearest thousandth
    EXPECT_EQ(EncodeModulePosition(0.0006, true), 1u);
    EXPECT_EQ(EncodeModulePosition(-0.0006, true), 0xFFFFFFFFu);
    EXPECT_EQ(EncodeModulePosition(3e6, true), 0x7FFFFFFFu);  // beyond DINT: clamped
    EXPECT_EQ(EncodeModulePosition(-3e6, true), 0x80000000u);
    // IEEE (6.1): 100.0 = 42 C8 00 00, 12.345 = 41 45 85 1F.
    EXPECT_EQ(EncodeModulePosition(100.0, false), 0x42C80000u);
    EXPECT_EQ(EncodeModulePosition(12.345, false), 0x4145851Fu);
    EXPECT_EQ(DecodeModulePosition(0x42C80000u, false), 100.0);
}

class AxisModuleFormats : public AxisModuleBench {};

TEST_F(AxisModuleFormats, FloatMoveWithExactBytes) {
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 01 03 E8 03 E8 00 00 00 00"), axis_, Context())),
              "00 00 07 01 00 00 00 00 00 00 00 00");
    now_ += 10ms;
    // Absolute to 100.0 at 1000 per mille: taken over, ACTIVE in the same cycle.
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 45 03 E8 03 E8 42 C8 00 00"), axis_, Context())),
              "00 00 07 81 00 00 00 00 00 00 00 00");
    now_ += 10ms;
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 41 03 E8 03 E8 42 C8 00 00"), axis_, Context())),
              "00 00 07 81 00 00 00 00 3F 00 00 00");  // 0.5
    now_ += 200ms;
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 41 03 E8 03 E8 42 C8 00 00"), axis_, Context())),
              "00 00 07 01 00 00 00 00 42 C8 00 00");  // 100.0, ACTIVE fallen
}

TEST_F(AxisModuleFormats, IntegerMoveWithExactBytes) {
    integer_ = true;
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 01 03 E8 03 E8 00 00 00 00"), axis_, Context())),
              "00 00 07 01 00 00 00 00 00 00 00 00");
    now_ += 10ms;
    // Absolute to 100000 / 1000 = 100.0.
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 45 03 E8 03 E8 00 01 86 A0"), axis_, Context())),
              "00 00 07 81 00 00 00 00 00 00 00 00");
    now_ += 10ms;
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 41 03 E8 03 E8 00 01 86 A0"), axis_, Context())),
              "00 00 07 81 00 00 00 00 00 00 01 F4");  // 0.5 -> 500
    now_ += 100ms;
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 41 03 E8 03 E8 00 01 86 A0"), axis_, Context())),
              "00 00 07 81 00 00 00 00 00 00 E8 6C");  // 110 ms after the start: 59.5 -> 59500
    now_ += 100ms;
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 41 03 E8 03 E8 00 01 86 A0"), axis_, Context())),
              "00 00 07 01 00 00 00 00 00 01 86 A0");
}

TEST_F(AxisModuleFormats, SetPositionBytesInBothFormats) {
    // G26 (bit 4) to -25.045: DINT FF FF 9E 2B; then G26 to 12.345 as IEEE 41 45 85 1F.
    integer_ = true;
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 15 00 00 00 00 FF FF 9E 2B"), axis_, Context())),
              "00 00 07 81 00 00 00 00 FF FF 9E 2B");
    now_ += 10ms;
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 01 00 00 00 00 FF FF 9E 2B"), axis_, Context())),
              "00 00 07 01 00 00 00 00 FF FF 9E 2B");
    now_ += 10ms;
    integer_ = false;
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 15 00 00 00 00 41 45 85 1F"), axis_, Context())),
              "00 00 07 81 00 00 00 00 41 45 85 1F");
    now_ += 10ms;
    integer_ = true;  // the same position in the other format: 12.345 -> 12345 = 00 00 30 39
    EXPECT_EQ(Hex(module_.Cycle(Hex12("00 00 00 01 00 00 00 00 00 00 00 00"), axis_, Context())),
              "00 00 07 01 00 00 00 00 00 00 30 39");
}

// ---- the four sequences of 2.7.9 ----------------------------------------------------------------------

class AxisModuleSequences : public AxisModuleBench {};

TEST_F(AxisModuleSequences, AxisOnOffWithEnableModeHalt_2_7_9_1) {
    Run({
        {0, as::kHalt | as::kReferenced | kSwitchesFree, 0, 0, 0.0},  // Axis ON 0: switched off in cycle 1
        {kOn, kOnReferenced, 0, 0, 0.0},                              // DRIVE ENABLED in the same cycle
        {kOn, kOnReferenced, 0, 0, 0.0},
        {0, as::kHalt | as::kReferenced | kSwitchesFree, 0, 0, 0.0},  // HALT: powered, holds its position
        {kOn, kOnReferenced, 0, 0, 0.0},
    });
}

class AxisModuleIdle : public AxisModuleBench {
protected:
    static ServoAxisConfig Idle() {
        ServoAxisConfig c = Referenced();
        c.enableMode = EnableMode::kIdle;
        return c;
    }
    AxisModuleIdle() : AxisModuleBench(Idle()) {}
};

TEST_F(AxisModuleIdle, AxisOnOffWithEnableModeIdleAndDisableDrive_2_7_9_1) {
    constexpr std::uint32_t kIdle = as::kDriveDisabled | as::kIdle | as::kReferenced | kSwitchesFree;  // 0x714
    constexpr std::uint32_t kDisabled = as::kDriveDisabled | as::kDisabled | as::kReferenced | kSwitchesFree;
    Run({
        {0, kIdle, 0, 0, 0.0},
        {kOn, kOnReferenced, 0, 0, 0.0},
        {0, kIdle, 0, 0, 0.0},
        {kOn | ac::kDisableDrive, kDisabled, 0, 0, 0.0},  // DISABLE DRIVE wins over Axis ON
        {ac::kDisableDrive, kDisabled, 0, 0, 0.0},
        {kOn, kOnReferenced, 0, 0, 0.0},
    });
}

TEST(AxisModuleSafe, AxisOffWithEnableModeSafe) {
    ServoAxisConfig config = Referenced();
    config.enableMode = EnableMode::kSafe;
    ServoAxis axis(config);
    AxisModule module;
    AxisModuleContext context;
    context.service = AxisModuleService::kJobs;
    const auto r = AxisModuleReply::Decode(module.Cycle(AxisModuleCommand{}.Encode(), axis, context));
    EXPECT_EQ(r.status, as::kDriveDisabled | as::kSafe | as::kReferenced | kSwitchesFree);  // 0x70C
}

class AxisModuleUnreferenced : public AxisModuleBench {
protected:
    AxisModuleUnreferenced() : AxisModuleBench(ServoAxisConfig{}) {}
};

TEST_F(AxisModuleUnreferenced, Referencing_2_7_9_2) {
    // G25 from 0, mode 0, cam edge at -20 extending negative, search negative at 500 units/s, creep 100 units/s,
    // 10000 units/s^2. Started at 10 ms: search ramp 50 ms / 12.5 units, the edge at 75 ms, braking 50 ms /
    // 12.5 units to -32.5 at 125 ms, creep ramp 10 ms / 0.5 units, the edge again at 255 ms: reference loaded
    // there (-20 becomes 0), braking 10 ms / 0.5 units to 0.5 at 265 ms.
    constexpr std::uint32_t kOnFree = as::kDriveEnabled | kSwitchesFree;
    constexpr std::uint32_t kHoming = kOnFree | as::kActive;
    constexpr std::uint32_t kG25 = kOn | ac::kHome;
    Run({
        {kOn, kOnFree, 0, 0, 0.0},
        {kG25 | ac::kStart, kHoming, 0, 0, 0.0},  // taken over: ACTIVE; not referenced (it never was)
        {kG25, kHoming, 0, 0, -0.5},              // search ramp: 5000 s^2
        {kG25, kHoming, 0, 0, -2.0},
        {kG25, kHoming, 0, 0, -4.5},
        {kG25, kHoming, 0, 0, -8.0},
        {kG25, kHoming, 0, 0, -12.5},    // 60 ms: at 500 units/s
        {kG25, kHoming, 0, 0, -17.5},    // 70 ms
        {kG25, kHoming, 0, 0, -22.375},  // 80 ms: on the cam since 75 ms, braking: -20 - (2.5 - 0.125)
        {kG25, kHoming, 0, 0, -26.375},  // -20 - (7.5 - 1.125)
        {kG25, kHoming, 0, 0, -29.375},
        {kG25, kHoming, 0, 0, -31.375},
        {kG25, kHoming, 0, 0, -32.375},  // 120 ms
        {kG25, kHoming, 0, 0, -32.375},  // 130 ms: creep ramp 5 ms after the standstill at 125 ms
        {kG25, kHoming, 0, 0, -31.5},    // 140 ms: -32.5 + 0.5 + 0.5
        {kG25, kHoming, 0, 0, -30.5},
        {kG25, kHoming, 0, 0, -29.5},
        {kG25, kHoming, 0, 0, -28.5},
        {kG25, kHoming, 0, 0, -27.5},
        {kG25, kHoming, 0, 0, -26.5},  // 190 ms
        {kG25, kHoming, 0, 0, -25.5},
        {kG25, kHoming, 0, 0, -24.5},
        {kG25, kHoming, 0, 0, -23.5},
        {kG25, kHoming, 0, 0, -22.5},
        {kG25, kHoming, 0, 0, -21.5},
        {kG25, kHoming, 0, 0, -20.5},                             // 250 ms
        {kG25, kHoming | as::kReferenced, 0, 0, 0.375},           // 260 ms: loaded at 255 ms, braking
        {kG25, kOnFree | as::kReferenced, 0, 0, 0.5},             // 270 ms: complete, Start 0: ACTIVE falls
        {kOn, kOnFree | as::kReferenced, 0, 0, 0.5},              // the PLC takes G25 away
    });
}

// 2.7.9.3 in both formats: relative +100 started at 10 ms; the triangle ends at 210 ms.
std::vector<Row> RelativeTraversing() {
    constexpr std::uint32_t kRel = kOn | ac::kMoveRelative;
    std::vector<Row> rows;
    rows.push_back({kOn, kOnReferenced, 0, 0, 0.0});
    rows.push_back({kRel | ac::kStart, kOnActive, 0, 0, 0.0});
    for (int ms = 10; ms <= 190; ms += 10) rows.push_back({kRel, kOnActive, 0, 0, Triangle100(ms / 1000.0)});
    rows.push_back({kRel, kOnReferenced, 0, 0, 100.0});  // 210 ms: in position and Start 0: ACTIVE falls
    rows.push_back({kOn, kOnReferenced, 0, 0, 100.0});   // the PLC takes the traverse bit away
    return rows;
}

TEST_F(AxisModuleSequences, RelativeTraversingFloat_2_7_9_3) {
    toPac_.position = EncodeModulePosition(100.0, false);
    Run(RelativeTraversing());
}

TEST_F(AxisModuleSequences, RelativeTraversingInteger_2_7_9_3) {
    integer_ = true;
    toPac_.position = 100000;
    Run(RelativeTraversing());
}

// The readings the manual leaves open (docs/open_points.md), as module settings.
class AxisModuleActiveForTraversingOnly : public AxisModuleBench {
protected:
    AxisModuleActiveForTraversingOnly()
        : AxisModuleBench(Referenced(), AxisModuleConfig{CmdErrorRestart::kSameCycle, ActiveForJobs::kTraversingOnly}) {}
};

TEST_F(AxisModuleActiveForTraversingOnly, JobsThatDoNotTraverseNeverShowActiveButTraversesDo) {
    // G29 to 5: carried out in the take-over cycle, no ACTIVE; a refused move before it left CMD error 65, which
    // the G29's Start clears (2.7.4.14).
    toPac_.position = EncodeModulePosition(20000.0, integer_);  // beyond the traverse range: 65
    Run({
        {kOn, kOnReferenced, 0, 0, 0.0},
        {kOn | ac::kMoveAbsolute | ac::kStart, kOnReferenced | as::kCmdError, 65, 0, 0.0},
        {kOn, kOnReferenced | as::kCmdError, 65, 0, 0.0},
    });
    toPac_.position = EncodeModulePosition(5.0, integer_);
    Run({
        {kOn | ac::kSetPosition | ac::kStart, kOnReferenced, 0, 0, 5.0},
        {kOn | ac::kSetPosition, kOnReferenced, 0, 0, 5.0},
        {kOn, kOnReferenced, 0, 0, 5.0},
    });
    // A move does: ACTIVE from its take-over until it is complete and Start is 0.
    toPac_.position = EncodeModulePosition(105.0, integer_);
    EXPECT_EQ(Step(kOn | ac::kMoveAbsolute | ac::kStart).status, kOnActive);
    const AxisModuleReply end = StepUntilClear(kOn | ac::kMoveAbsolute, as::kActive);
    EXPECT_EQ(DecodeModulePosition(end.position, integer_), 105.0);
}

class AxisModuleContinuesAfterAxisOn : public AxisModuleBench {
protected:
    AxisModuleContinuesAfterAxisOn()
        : AxisModuleBench(Referenced(), AxisModuleConfig{CmdErrorRestart::kSameCycle, ActiveForJobs::kEveryJob,
                                                         NoReferenceAnswer::kCmdError43,
                                                         InterruptedTraverse::kContinuesAfterAxisOn}) {}
};

TEST_F(AxisModuleContinuesAfterAxisOn, MoveInterruptedByAxisOffGoesOnToItsTargetAfterAxisOn) {
    toPac_.position = EncodeModulePosition(105.0, integer_);
    Step(kOn);
    EXPECT_EQ(Step(kOn | ac::kMoveAbsolute | ac::kStart).status, kOnActive);
    for (int i = 0; i < 5; ++i) Step(kOn | ac::kMoveAbsolute);
    // Axis ON 0 and the traverse bit removed together, as FB_PAC_Axis does when Enable falls.
    const AxisModuleReply stopped = StepUntilClear(0, as::kActive);
    const double stoppedAt = DecodeModulePosition(stopped.position, integer_);
    EXPECT_LT(stoppedAt, 105.0);
    EXPECT_EQ(Step(0).status & as::kActive, 0u) << "nothing runs while the axis is off";
    // Axis ON again, no traverse bit, no Start: the controller continues by itself.
    EXPECT_EQ(Step(kOn).status & as::kActive, as::kActive);
    const AxisModuleReply end = StepUntilClear(kOn, as::kActive);
    EXPECT_EQ(DecodeModulePosition(end.position, integer_), 105.0);
    EXPECT_EQ(Step(kOn).status & as::kActive, 0u) << "continued once";
}

TEST_F(AxisModuleSequences, MoveInterruptedByAxisOffStaysEndedByDefault) {
    toPac_.position = EncodeModulePosition(105.0, integer_);
    Step(kOn);
    Step(kOn | ac::kMoveAbsolute | ac::kStart);
    for (int i = 0; i < 5; ++i) Step(kOn | ac::kMoveAbsolute);
    const AxisModuleReply stopped = StepUntilClear(0, as::kActive);
    for (int i = 0; i < 20; ++i) {
        const AxisModuleReply r = Step(kOn);
        EXPECT_EQ(r.status & as::kActive, 0u);
        EXPECT_EQ(r.position, stopped.position);
    }
}

class AxisModuleSpeedChange : public AxisModuleBench {
protected:
    explicit AxisModuleSpeedChange(SpeedChange change = SpeedChange::kWhileTraversing)
        : AxisModuleBench(Referenced(), AxisModuleConfig{CmdErrorRestart::kSameCycle, ActiveForJobs::kEveryJob,
                                                         NoReferenceAnswer::kCmdError43, InterruptedTraverse::kEnds,
                                                         change}) {}
    // A move to 1000 at 100 per mille (100 units/s); at 0.2 s the speed field goes to 1000 per mille. Returns the
    // cycles from the change to the end of the job.
    int MoveWithSpeedChange() {
        toPac_.position = EncodeModulePosition(1000.0, integer_);
        toPac_.speedPerMille = 100;
        Step(kOn);
        Step(kOn | ac::kMoveAbsolute | ac::kStart);
        for (int i = 0; i < 20; ++i) Step(kOn | ac::kMoveAbsolute);
        EXPECT_NEAR(axis_.ActualSpeed(), 100.0, 1e-6);
        toPac_.speedPerMille = 1000;
        int cycles = 0;
        while ((Step(kOn | ac::kMoveAbsolute).status & as::kActive) != 0 && cycles < 2000) ++cycles;
        EXPECT_EQ(axis_.Position(), 1000.0) << "at the same target";
        return cycles;
    }
};

TEST_F(AxisModuleSpeedChange, NewSpeedDuringAMoveAppliesWhereTheAxisTypeAllowsIt) {
    // 980 units left at 100 units/s: ramp 0.09 s to 1000 units/s, about 0.98 s in all, against 9.8 s.
    EXPECT_LT(MoveWithSpeedChange(), 110);
}

class AxisModuleNoSpeedChange : public AxisModuleSpeedChange {
protected:
    AxisModuleNoSpeedChange() : AxisModuleSpeedChange(SpeedChange::kNotWhileTraversing) {}
};

TEST_F(AxisModuleNoSpeedChange, NewSpeedDuringAMoveIsIgnoredByOtherAxisTypes) {
    EXPECT_GT(MoveWithSpeedChange(), 970);
}

class AxisModuleNoReferenceE525 : public AxisModuleBench {
protected:
    AxisModuleNoReferenceE525()
        : AxisModuleBench(ServoAxisConfig{}, AxisModuleConfig{CmdErrorRestart::kSameCycle, ActiveForJobs::kEveryJob,
                                                              NoReferenceAnswer::kSystemError525}) {}
};

TEST_F(AxisModuleNoReferenceE525, MoveOfAnUnreferencedAxisIsSystemErrorE525UntilReset) {
    toPac_.position = EncodeModulePosition(10.0, integer_);
    Step(kOn);
    const AxisModuleReply refused = Step(kOn | ac::kMoveAbsolute | ac::kStart);
    EXPECT_EQ(refused.cmdError, 0) << "no CMD error";
    EXPECT_EQ(refused.axisError, AxisModule::kSystemErrorNoReference);
    EXPECT_EQ(refused.status & (as::kActive | as::kCmdError | as::kAxisError), as::kAxisError);
    EXPECT_EQ(Step(kOn).axisError, AxisModule::kSystemErrorNoReference) << "kept until reset";
    const AxisModuleReply reset = Step(kOn | ac::kResetAxisError);
    EXPECT_EQ(reset.axisError, 0);
    EXPECT_EQ(reset.status & as::kAxisError, 0u);
}

class AxisModuleLimitSwitch : public AxisModuleBench {
protected:
    static ServoAxisConfig Config() {
        ServoAxisConfig c = Referenced();
        c.positiveLimitSwitch = 155.0;
        return c;
    }
    AxisModuleLimitSwitch() : AxisModuleBench(Config()) {}
};

TEST_F(AxisModuleLimitSwitch, RelativeTraversingWithLimitSwitchError_2_7_9_4) {
    // Relative +300 from 0 at 10 ms: ramp to 1000 units/s in 100 ms (50 units), then 1000 units/s; the switch
    // at 155 is reached 205 ms after the start (215 ms): stop there at once, axis error 64.
    constexpr std::uint32_t kRel = kOn | ac::kMoveRelative;
    constexpr std::uint32_t kFaultHalt = as::kDriveEnabled | as::kHalt | as::kFault | as::kReferenced |
                                         as::kNegativeLimitNotActuated | as::kAxisError;  // positive switch actuated
    constexpr std::uint32_t kOnSwitch = as::kDriveEnabled | as::kHalt | as::kReferenced | as::kNegativeLimitNotActuated;
    toPac_.position = EncodeModulePosition(300.0, false);
    std::vector<Row> rows{{kOn, kOnReferenced, 0, 0, 0.0}, {kRel | ac::kStart, kOnActive, 0, 0, 0.0}};
    for (int ms = 10; ms <= 200; ms += 10) {
        const double s = ms / 1000.0;
        rows.push_back({kRel, kOnActive, 0, 0, s <= 0.1 ? 5000.0 * s * s : 50.0 + 1000.0 * (s - 0.1)});
    }
    rows.push_back({kRel, kFaultHalt, 0, 64, 155.0});  // 220 ms: on the switch, FAULT; Start 0: ACTIVE falls
    rows.push_back({kOn, kFaultHalt, 0, 64, 155.0});   // traverse bit taken away
    rows.push_back({kOn | ac::kResetAxisError, kOnSwitch, 0, 0, 155.0});  // reset: the switch stays actuated
    rows.push_back({kOn, kOnSwitch, 0, 0, 155.0});
    Run(rows);
    // Further into the switch: refused with 64 (CMD error), away from it: taken over.
    Run({{kRel | ac::kStart, kOnSwitch | as::kCmdError, 64, 0, 155.0},
         {kRel, kOnSwitch | as::kCmdError, 64, 0, 155.0},
         {kOn, kOnSwitch | as::kCmdError, 64, 0, 155.0}});
    toPac_.position = EncodeModulePosition(-100.0, false);
    Run({{kRel | ac::kStart, as::kDriveEnabled | as::kActive | as::kReferenced | as::kNegativeLimitNotActuated, 0, 0, 155.0},
         {kRel, kOnActive, 0, 0, 154.5}});  // off the switch again
}

// ---- handshake ----------------------------------------------------------------------------------------

class AxisModuleHandshake : public AxisModuleBench {};

TEST_F(AxisModuleHandshake, ActiveStaysWhileStartIsHeldAfterTheJob) {
    toPac_.position = EncodeModulePosition(100.0, false);
    constexpr std::uint32_t kRel = kOn | ac::kMoveRelative;
    Step(kOn);
    EXPECT_EQ(Step(kRel | ac::kStart).status, kOnActive);
    for (int i = 0; i < 25; ++i) EXPECT_EQ(Step(kRel | ac::kStart).status, kOnActive) << i;  // done at 210 ms
    EXPECT_FALSE(module_.JobRunning());
    EXPECT_EQ(axis_.Position(), 100.0);
    EXPECT_EQ(Step(kRel).status, kOnReferenced);  // falls with Start
}

TEST_F(AxisModuleHandshake, InstantJobsShowActiveUntilStartFalls) {
    toPac_.position = EncodeModulePosition(7.0, false);
    Step(kOn);
    auto r = Step(kOn | ac::kSetPosition | ac::kStart);  // G29 to 7.0: done in this cycle
    EXPECT_EQ(r.status, kOnActive);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 7.0);
    EXPECT_FALSE(module_.JobRunning());
    EXPECT_EQ(Step(kOn | ac::kSetPosition | ac::kStart).status, kOnActive);
    EXPECT_EQ(Step(kOn | ac::kSetPosition).status, kOnReferenced);
}

TEST_F(AxisModuleHandshake, StartEdgeDuringAJobIsLost) {
    toPac_.position = EncodeModulePosition(1000.0, false);
    constexpr std::uint32_t kAbs = kOn | ac::kMoveAbsolute;
    Step(kOn);
    EXPECT_EQ(Step(kAbs | ac::kStart).status, kOnActive);
    Step(kAbs);
    // A new edge with two traverse bits while the job runs: not recognised, so no CMD error 20 either.
    auto r = Step(kAbs | ac::kMoveRelative | ac::kStart);
    EXPECT_EQ(r.status, kOnActive);
    EXPECT_EQ(r.cmdError, 0);
    r = StepUntilClear(kAbs | ac::kMoveRelative, as::kActive);
    EXPECT_EQ(r.status, kOnReferenced);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 1000.0);
    toPac_.position = EncodeModulePosition(0.0, false);
    EXPECT_EQ(Step(kAbs | ac::kStart).status, kOnActive);  // now an edge (Start was 0 in the last cycle)
}

TEST_F(AxisModuleHandshake, StartHeldFromOutsideOnlineIsNoEdge) {
    service_ = AxisModuleService::kReportOnly;
    toPac_.position = EncodeModulePosition(100.0, false);
    constexpr std::uint32_t kRel = kOn | ac::kMoveRelative | ac::kStart;
    auto r = Step(kRel);  // an edge outside ONLINE: CMD error 20
    EXPECT_EQ(r.cmdError, AxisModule::kInadmissible);
    service_ = AxisModuleService::kJobs;
    r = Step(kRel);
    EXPECT_EQ(r.status, kOnReferenced | as::kCmdError);  // no edge: nothing taken over
    EXPECT_EQ(Step(kOn).status, kOnReferenced | as::kCmdError);
    r = Step(kRel);
    EXPECT_EQ(r.status, kOnActive);
    EXPECT_EQ(r.cmdError, 0);
}

TEST_F(AxisModuleHandshake, TraverseBitsMustBeExactlyOne) {
    Step(kOn);
    auto r = Step(kOn | ac::kStart);  // Start without a traverse bit (2.7.4.14 example)
    EXPECT_EQ(r.status, kOnReferenced | as::kCmdError);
    EXPECT_EQ(r.cmdError, 20);
    Step(kOn);
    r = Step(kOn | ac::kMoveAbsolute | ac::kMoveRelative | ac::kStart);  // two traverse bits (2.7.2 notes)
    EXPECT_EQ(r.cmdError, 20);
    EXPECT_FALSE(axis_.JobActive());
    Step(kOn);
    r = Step(kOn | ac::kMoveToMax | ac::kMoveToMin | ac::kStart);
    EXPECT_EQ(r.cmdError, 20);
    Step(kOn);
    r = Step(kOn | ac::kHome | ac::kWhileInput1 | ac::kStart);  // G123 only with absolute / relative
    EXPECT_EQ(r.cmdError, 20);
    Step(kOn);
    r = Step(kOn | ac::kMoveAbsolute | ac::kWhileInput1 | ac::kWhileInput0 | ac::kStart);  // both conditions
    EXPECT_EQ(r.cmdError, 20);
    EXPECT_FALSE(axis_.JobActive());
    Step(kOn);
    r = Step(kOn | ac::kMoveAbsolute | ac::kStart | (1U << 20));  // reserve bits are ignored
    EXPECT_EQ(r.status, kOnActive);
    EXPECT_EQ(r.cmdError, 0);
}

TEST_F(AxisModuleHandshake, PerMilleOutsideItsRangeIs41) {
    Step(kOn);
    toPac_.position = EncodeModulePosition(100.0, false);
    for (const auto& [speed, acceleration] : std::vector<std::pair<int, int>>{{0, 1000}, {1001, 1000}, {1000, 0}}) {
        toPac_.speedPerMille = static_cast<std::uint16_t>(speed);
        toPac_.accelerationPerMille = static_cast<std::uint16_t>(acceleration);
        const auto r = Step(kOn | ac::kMoveAbsolute | ac::kStart);
        EXPECT_EQ(r.cmdError, axis_error::kValueOutsideRange) << speed << " / " << acceleration;
        EXPECT_EQ(r.status & as::kActive, 0u);
        Step(kOn);
    }
    // The axis's own order: not switched on (55) comes before 41.
    toPac_.speedPerMille = 0;
    Step(0);
    EXPECT_EQ(Step(ac::kMoveAbsolute | ac::kStart).cmdError, axis_error::kAxisNotSwitchedOn);
    // Jobs that do not move ignore the per-mille fields (G26), and so does G25 (parameters only, 2.7.5 note).
    Step(kOn);
    EXPECT_EQ(Step(kOn | ac::kSetReferenced | ac::kStart).status, kOnActive);
    Step(kOn | ac::kSetReferenced);
    EXPECT_EQ(Step(kOn | ac::kHome | ac::kStart).cmdError, 0);
}

TEST_F(AxisModuleHandshake, PerMilleScalesTheMove) {
    // 500 per mille of 1000 units/s, 2000 per mille of 10000 units/s^2: ramps of 25 ms / 6.25 units;
    // 100 ms after the start: 6.25 + 500 * 0.075 = 43.75; done 25 + 175 + 25 = 225 ms after the start (235 ms).
    toPac_.speedPerMille = 500;
    toPac_.accelerationPerMille = 2000;
    Step(kOn);
    Step(kOn | ac::kMoveRelative | ac::kStart, 100.0);
    for (int i = 0; i < 9; ++i) Step(kOn | ac::kMoveRelative);
    EXPECT_EQ(DecodeModulePosition(Step(kOn | ac::kMoveRelative).position, false), 43.75f);
    for (int i = 0; i < 11; ++i) EXPECT_TRUE(Step(kOn | ac::kMoveRelative).status & as::kActive) << i;  // to 220 ms
    EXPECT_TRUE(Step(kOn | ac::kMoveRelative).status & as::kActive);   // 230 ms: 5 ms to go
    const auto r = Step(kOn | ac::kMoveRelative);                      // 240 ms
    EXPECT_EQ(r.status, kOnReferenced);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 100.0);
}

// ---- CMD error persistence ----------------------------------------------------------------------------

TEST_F(AxisModuleUnreferenced, CmdErrorStaysUntilTheNextStartEdgeSameCycleRestart) {
    constexpr std::uint32_t kOnFree = as::kDriveEnabled | kSwitchesFree;
    toPac_.position = EncodeModulePosition(50.0, false);
    Run({
        {kOn, kOnFree, 0, 0, 0.0},
        {kOn | ac::kMoveAbsolute | ac::kStart, kOnFree | as::kCmdError, 43, 0, 0.0},  // no reference point
        {kOn | ac::kMoveAbsolute, kOnFree | as::kCmdError, 43, 0, 0.0},
        {kOn, kOnFree | as::kCmdError, 43, 0, 0.0},
        {kOn, kOnFree | as::kCmdError, 43, 0, 0.0},
        // Refused again: the flag never falls; the number is the new job's (two traverse bits: 20).
        {kOn | ac::kMoveAbsolute | ac::kMoveRelative | ac::kStart, kOnFree | as::kCmdError, 20, 0, 0.0},
        {kOn, kOnFree | as::kCmdError, 20, 0, 0.0},
        // The same refusal once more: flag and number unchanged throughout (the FB's stale-error case).
        {kOn | ac::kMoveAbsolute | ac::kStart, kOnFree | as::kCmdError, 43, 0, 0.0},
        {kOn, kOnFree | as::kCmdError, 43, 0, 0.0},
        {kOn | ac::kMoveAbsolute | ac::kStart, kOnFree | as::kCmdError, 43, 0, 0.0},
        {kOn, kOnFree | as::kCmdError, 43, 0, 0.0},
        // A job taken over clears flag and number in the cycle that shows ACTIVE.
        {kOn | ac::kSetReferenced | ac::kStart, kOnActive, 0, 0, 50.0},
        {kOn, kOnReferenced, 0, 0, 50.0},
    });
}

class AxisModuleGapRestart : public AxisModuleBench {
protected:
    AxisModuleGapRestart() : AxisModuleBench(ServoAxisConfig{}, AxisModuleConfig{CmdErrorRestart::kOneCycleClear}) {}
};

TEST_F(AxisModuleGapRestart, CmdErrorShowsClearedForOneCycleBeforeTheRefusal) {
    constexpr std::uint32_t kOnFree = as::kDriveEnabled | kSwitchesFree;
    toPac_.position = EncodeModulePosition(50.0, false);
    Run({
        {kOn, kOnFree, 0, 0, 0.0},
        {kOn | ac::kMoveAbsolute | ac::kStart, kOnFree, 0, 0, 0.0},  // edge cycle: nothing shown yet
        {kOn | ac::kMoveAbsolute, kOnFree | as::kCmdError, 43, 0, 0.0},
        {kOn, kOnFree | as::kCmdError, 43, 0, 0.0},
        {kOn | ac::kMoveAbsolute | ac::kStart, kOnFree, 0, 0, 0.0},  // cleared for one cycle ...
        {kOn | ac::kMoveAbsolute | ac::kStart, kOnFree | as::kCmdError, 43, 0, 0.0},  // ... and set again
        {kOn, kOnFree | as::kCmdError, 43, 0, 0.0},
        {kOn | ac::kStart, kOnFree, 0, 0, 0.0},
        {kOn, kOnFree | as::kCmdError, 20, 0, 0.0},  // Start fell meanwhile: shown all the same
        {kOn, kOnFree | as::kCmdError, 20, 0, 0.0},
        {kOn | ac::kSetReferenced | ac::kStart, kOnActive, 0, 0, 50.0},  // take-over: same cycle
        {kOn, kOnReferenced, 0, 0, 50.0},
    });
}

// ---- interrupts ---------------------------------------------------------------------------------------

TEST_F(AxisModuleHandshake, RemovingTheTraverseBitInterrupts) {
    // Absolute to 1000 started at 10 ms; at 310 ms (300 ms in: 250 units, 1000 units/s) the PLC takes
    // bit 6 away: braking 100 ms / 50 units to 300, standing at 410 ms with HALT.
    constexpr std::uint32_t kAbs = kOn | ac::kMoveAbsolute;
    toPac_.position = EncodeModulePosition(1000.0, false);
    Step(kOn);
    Step(kAbs | ac::kStart);
    for (int i = 0; i < 28; ++i) Step(kAbs);
    EXPECT_EQ(DecodeModulePosition(Step(kAbs).position, false), 240.0f);  // 300 ms
    std::vector<Row> rows;
    rows.push_back({kOn, kOnActive, 0, 0, 250.0});  // 310 ms: the interrupt starts here
    for (int ms = 10; ms < 100; ms += 10) {
        const double s = ms / 1000.0;
        rows.push_back({kOn, kOnActive, 0, 0, 250.0 + 1000.0 * s - 5000.0 * s * s});
    }
    rows.push_back({kOn, kOnReferenced | as::kHalt, 0, 0, 300.0});  // 410 ms: stands, interrupted: HALT
    rows.push_back({kOn, kOnReferenced | as::kHalt, 0, 0, 300.0});
    Run(rows);
    EXPECT_EQ(axis_.Status(), AxisStatus::kStopped);
    // The next job clears HALT.
    EXPECT_EQ(Step(kAbs | ac::kStart, 0.0).status, kOnActive);
}

TEST_F(AxisModuleHandshake, AxisOnFallingMidMoveEndsTheJob) {
    // As above, but Axis ON falls at 310 ms: the axis brakes under control (still DRIVE ENABLED), then HALT
    // (enable mode HALT). The job is not continued when Axis ON returns (docs: "switch on traverse mode").
    constexpr std::uint32_t kAbs = kOn | ac::kMoveAbsolute;
    toPac_.position = EncodeModulePosition(1000.0, false);
    Step(kOn);
    Step(kAbs | ac::kStart);
    for (int i = 0; i < 29; ++i) Step(kAbs);
    auto r = Step(ac::kMoveAbsolute);  // 310 ms
    EXPECT_EQ(r.status, kOnActive);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 250.0f);
    for (int i = 0; i < 9; ++i) EXPECT_EQ(Step(ac::kMoveAbsolute).status, kOnActive) << i;
    r = Step(ac::kMoveAbsolute);  // 410 ms
    EXPECT_EQ(r.status, as::kHalt | as::kReferenced | kSwitchesFree);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 300.0f);
    r = Step(kAbs);
    EXPECT_EQ(r.status, kOnReferenced | as::kHalt);  // on again, the interrupted job shows as HALT
    for (int i = 0; i < 5; ++i) r = Step(kAbs);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 300.0f);
    EXPECT_FALSE(axis_.Moving());
}

TEST_F(AxisModuleHandshake, AxisErrorDuringAJobEndsIt) {
    // A blocked axis: following error 66 once the command is 1.0 ahead; the axis stops, the job ends.
    constexpr std::uint32_t kAbs = kOn | ac::kMoveAbsolute;
    toPac_.position = EncodeModulePosition(1000.0, false);
    Step(kOn);
    Step(kAbs | ac::kStart);
    for (int i = 0; i < 20; ++i) Step(kAbs);
    axis_.SetBlocked(now_, true);  // at 220 ms; 1.0 behind at 221 ms
    EXPECT_EQ(Step(kAbs).status, kOnActive);
    const auto r = Step(kAbs);
    EXPECT_EQ(r.status, kOnReferenced | as::kHalt | as::kFault | as::kAxisError);
    EXPECT_EQ(r.axisError, axis_error::kFollowingError);
    EXPECT_FALSE(module_.JobRunning());
}

// ---- reset axis error ---------------------------------------------------------------------------------

TEST_F(AxisModuleHandshake, ResetAxisErrorActsOnItsRisingEdge) {
    constexpr std::uint32_t kFaulty = kOnReferenced | as::kFault | as::kAxisError;
    Step(kOn);
    axis_.RaiseAxisError(now_, 500);
    auto r = Step(kOn);
    EXPECT_EQ(r.status, kFaulty);
    EXPECT_EQ(r.axisError, 500);
    EXPECT_EQ(Step(kOn | ac::kResetAxisError).status, kOnReferenced);
    // Held: a new error is shown and stays; only the next edge clears it.
    axis_.RaiseAxisError(now_, 501);
    EXPECT_EQ(Step(kOn | ac::kResetAxisError).axisError, 501);
    EXPECT_EQ(Step(kOn | ac::kResetAxisError).axisError, 501);
    EXPECT_EQ(Step(kOn).axisError, 501);
    r = Step(kOn | ac::kResetAxisError);
    EXPECT_EQ(r.status, kOnReferenced);
    EXPECT_EQ(r.axisError, 0);
}

TEST_F(AxisModuleHandshake, ResetRefusedWhileTheCauseLastsNeedsANewEdge) {
    Step(kOn);
    axis_.SetDisturbance(now_, 2.0);  // following error above the limit of 1.0: 66 at once
    EXPECT_EQ(Step(kOn).axisError, axis_error::kFollowingError);
    EXPECT_EQ(Step(kOn | ac::kResetAxisError).axisError, axis_error::kFollowingError);
    axis_.SetDisturbance(now_, 0.0);
    EXPECT_EQ(Step(kOn | ac::kResetAxisError).axisError, axis_error::kFollowingError);  // no edge
    Step(kOn);
    EXPECT_EQ(Step(kOn | ac::kResetAxisError).axisError, 0);
}

// ---- outside ONLINE -----------------------------------------------------------------------------------

TEST_F(AxisModuleHandshake, OutsideOnlineTheStatusIsReportedAndNothingActs) {
    service_ = AxisModuleService::kReportOnly;
    axis_.Place(now_, 12.0);
    auto r = Step(0);  // Axis ON 0 is not acted upon: the axis stays enabled
    EXPECT_EQ(r.status, kOnReferenced);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 12.0);
    axis_.RaiseAxisError(now_, 500);
    r = Step(ac::kResetAxisError);  // not acted upon either
    EXPECT_EQ(r.axisError, 500);
    r = Step(ac::kMoveRelative | ac::kStart, 10.0);  // Start: not taken over, CMD error 20
    EXPECT_EQ(r.status, kOnReferenced | as::kFault | as::kAxisError | as::kCmdError);
    EXPECT_EQ(r.cmdError, 20);
    EXPECT_FALSE(axis_.JobActive());
}

TEST_F(AxisModuleHandshake, OnlineNotRunningControlsTheDriveButTakesNoJobs) {
    service_ = AxisModuleService::kControl;  // e.g. ONLINE stopped (35)
    EXPECT_EQ(Step(0).status, as::kHalt | as::kReferenced | kSwitchesFree);
    EXPECT_EQ(Step(kOn).status, kOnReferenced);
    const auto r = Step(kOn | ac::kMoveRelative | ac::kStart, 10.0);
    EXPECT_EQ(r.cmdError, 20);
    EXPECT_FALSE(axis_.JobActive());
    axis_.RaiseAxisError(now_, 500);
    Step(kOn);
    EXPECT_EQ(Step(kOn | ac::kResetAxisError).axisError, 0);
}

TEST_F(AxisModuleHandshake, LeavingOnlineSwitchesTheAxisOnAgain) {
    EXPECT_EQ(Step(0).status, as::kHalt | as::kReferenced | kSwitchesFree);
    service_ = AxisModuleService::kReportOnly;
    EXPECT_EQ(Step(0).status, kOnReferenced);  // 2.7.2 last note: operational after ONLINE
    service_ = AxisModuleService::kJobs;
    EXPECT_EQ(Step(0).status, as::kHalt | as::kReferenced | kSwitchesFree);  // ONLINE again: off again
}

// ---- G123 ---------------------------------------------------------------------------------------------

TEST_F(AxisModuleHandshake, G123StopsWhenTheInputLeavesTheCondition) {
    // Absolute to 1000 while input 1 = 1; at 310 ms the input drops: braking to 300 as with an interrupt.
    constexpr std::uint32_t kJob = kOn | ac::kMoveAbsolute | ac::kWhileInput1;
    inputs_.Set(1, true);
    toPac_.position = EncodeModulePosition(1000.0, false);
    Step(kOn);
    EXPECT_EQ(Step(kJob | ac::kStart).status, kOnActive);
    for (int i = 0; i < 29; ++i) EXPECT_EQ(Step(kJob).status, kOnActive) << i;
    inputs_.Set(1, false);
    auto r = Step(kJob);  // 310 ms
    EXPECT_EQ(r.status, kOnActive | as::kStoppedByCondition);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 250.0f);
    r = StepUntilClear(kJob, as::kActive);
    EXPECT_EQ(r.status, kOnReferenced | as::kHalt | as::kStoppedByCondition);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 300.0f);
    EXPECT_EQ(now_, 420ms);  // the cycle at 410 ms showed ACTIVE fallen
    // Bit 11 describes the last job with G123: a job without G123 leaves it ...
    r = Step(kOn | ac::kMoveRelative | ac::kStart, 10.0);
    EXPECT_EQ(r.status, kOnActive | as::kStoppedByCondition);
    r = StepUntilClear(kOn | ac::kMoveRelative, as::kActive);
    EXPECT_EQ(r.status & as::kStoppedByCondition, as::kStoppedByCondition);
    // ... the next G123 job clears it, and finishing normally does not set it.
    inputs_.Set(1, true);
    r = Step(kJob | ac::kStart, 320.0);
    EXPECT_EQ(r.status, kOnActive);
    r = StepUntilClear(kJob, as::kActive);
    EXPECT_EQ(r.status, kOnReferenced);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 320.0f);
}

TEST_F(AxisModuleHandshake, G123NotStartedWhenTheConditionIsNotMet) {
    // While input 1 = 1, but it is 0: taken over (ACTIVE) and terminated in the same cycle without moving.
    constexpr std::uint32_t kJob = kOn | ac::kMoveRelative | ac::kWhileInput1;
    Step(kOn);
    auto r = Step(kJob | ac::kStart, 100.0);
    EXPECT_EQ(r.status, kOnActive | as::kHalt | as::kStoppedByCondition);
    EXPECT_EQ(r.cmdError, 0);
    EXPECT_FALSE(module_.JobRunning());
    r = Step(kJob);
    EXPECT_EQ(r.status, kOnReferenced | as::kHalt | as::kStoppedByCondition);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 0.0f);
    EXPECT_FALSE(axis_.Moving());
}

TEST_F(AxisModuleHandshake, G123WhileInputZeroOnAnotherInput) {
    constexpr std::uint32_t kJob = kOn | ac::kMoveRelative | ac::kWhileInput0;
    Step(kOn);
    module_.SetConditionInput(5);
    inputs_.Set(1, true);  // input 1 no longer matters
    Step(kJob | ac::kStart, 100.0);
    for (int i = 0; i < 5; ++i) EXPECT_EQ(Step(kJob).status, kOnActive);
    inputs_.Set(5, true);
    EXPECT_EQ(Step(kJob).status, kOnActive | as::kStoppedByCondition);  // 70 ms: braking from 18
    const auto r = StepUntilClear(kJob, as::kActive);
    EXPECT_EQ(r.status, kOnReferenced | as::kHalt | as::kStoppedByCondition);
    EXPECT_LT(DecodeModulePosition(r.position, false), 100.0);
    // An input the controller does not have reads 0.
    module_.SetConditionInput(999);
    EXPECT_EQ(Step(kJob | ac::kStart, 10.0).status & as::kStoppedByCondition, 0u);
    EXPECT_THROW(module_.SetConditionInput(0), std::invalid_argument);
}

TEST_F(AxisModuleHandshake, ConditionInputIsBackTo1WhenOnlineStarts) {
    module_.SetConditionInput(7);
    Step(kOn);  // the first ONLINE cycle: ONLINE starts
    EXPECT_EQ(module_.ConditionInput(), 1);
    module_.SetConditionInput(7);
    Step(kOn);
    EXPECT_EQ(module_.ConditionInput(), 7);
    service_ = AxisModuleService::kReportOnly;
    Step(kOn);
    EXPECT_EQ(module_.ConditionInput(), 7);
    service_ = AxisModuleService::kJobs;
    Step(kOn);
    EXPECT_EQ(module_.ConditionInput(), 1);
}

// ---- the other jobs -----------------------------------------------------------------------------------

TEST_F(AxisModuleUnreferenced, JogWithoutReferenceByTheMagnitudeOfPosition) {
    constexpr std::uint32_t kOnFree = as::kDriveEnabled | kSwitchesFree;
    Step(kOn);
    EXPECT_EQ(Step(kOn | ac::kMoveAbsolute | ac::kStart, 30.0).cmdError, axis_error::kNoReferencePoint);
    Step(kOn);
    auto r = Step(kOn | ac::kJogPositive | ac::kStart, -30.0);  // bit 10: +30, the sign is ignored
    EXPECT_EQ(r.status, kOnFree | as::kActive);
    r = StepUntilClear(kOn | ac::kJogPositive, as::kActive);
    EXPECT_EQ(r.status, kOnFree);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 30.0f);
    Step(kOn);
    Step(kOn | ac::kJogNegative | ac::kStart, 45.0);  // bit 11: to -15, below the min. range 0 (no check)
    r = StepUntilClear(kOn | ac::kJogNegative, as::kActive);
    EXPECT_EQ(DecodeModulePosition(r.position, false), -15.0f);
    EXPECT_EQ(r.cmdError, 0);
}

TEST_F(AxisModuleHandshake, JogIsInterruptedByRemovingItsBit) {
    Step(kOn);
    Step(kOn | ac::kJogPositive | ac::kStart, 1000.0);
    for (int i = 0; i < 20; ++i) Step(kOn | ac::kJogPositive);
    const auto r = StepUntilClear(kOn, as::kActive);
    EXPECT_EQ(r.status, kOnReferenced | as::kHalt);
    EXPECT_LT(DecodeModulePosition(r.position, false), 1000.0);
}

class AxisModuleRange : public AxisModuleBench {
protected:
    static ServoAxisConfig Config() {
        ServoAxisConfig c = Referenced();
        c.minTraverseRange = -40.0;
        c.maxTraverseRange = 100.0;
        return c;
    }
    AxisModuleRange() : AxisModuleBench(Config()) {}
};

TEST_F(AxisModuleRange, ToMaxAndMinTraverseRangeAndTheRangeCheck) {
    Step(kOn);
    EXPECT_EQ(Step(kOn | ac::kMoveToMax | ac::kStart, -999.0).status, kOnActive);  // position field unused
    auto r = StepUntilClear(kOn | ac::kMoveToMax, as::kActive);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 100.0f);
    Step(kOn | ac::kMoveToMin | ac::kStart);
    r = StepUntilClear(kOn | ac::kMoveToMin, as::kActive);
    EXPECT_EQ(DecodeModulePosition(r.position, false), -40.0f);
    Step(kOn);
    r = Step(kOn | ac::kMoveAbsolute | ac::kStart, 101.0);
    EXPECT_EQ(r.cmdError, axis_error::kPositionOutsideRange);
}

TEST_F(AxisModuleRange, G29ShiftsAndDeleteOffsetsRestores) {
    Step(kOn);
    auto r = Step(kOn | ac::kSetPosition | ac::kStart, 500.0);  // G29: 0 becomes 500, the range 460..600
    EXPECT_EQ(r.status, kOnActive);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 500.0f);
    EXPECT_EQ(axis_.MaxRange(), 600.0);
    Step(kOn);
    Step(kOn | ac::kMoveAbsolute | ac::kStart, 590.0);
    r = StepUntilClear(kOn | ac::kMoveAbsolute, as::kActive);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 590.0f);
    r = Step(kOn | ac::kClearOffset | ac::kStart);
    EXPECT_EQ(r.status, kOnActive);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 90.0f);
    EXPECT_EQ(axis_.MaxRange(), 100.0);
}

TEST_F(AxisModuleHandshake, LimitSwitchMonitoringOffIsTakenOverWithStart) {
    // Bit 17 with the Start edge: the move passes the switch at 155 (machine), which then reads actuated.
    axis_.SetConfig(now_, [] {
        ServoAxisConfig c = Referenced();
        c.positiveLimitSwitch = 155.0;
        return c;
    }());
    Step(kOn);
    Step(kOn | ac::kMoveRelative | ac::kDisableLimitSwitches | ac::kStart, 300.0);
    const auto r = StepUntilClear(kOn | ac::kMoveRelative, as::kActive);  // bit 17 dropped: no effect any more
    EXPECT_EQ(r.status, as::kDriveEnabled | as::kReferenced | as::kNegativeLimitNotActuated);
    EXPECT_EQ(r.axisError, 0);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 300.0f);
}

TEST_F(AxisModuleHandshake, LimitSwitchBitsAreLowActive) {
    axis_.Place(now_, -60.0);  // beyond the negative switch at -50
    auto r = Step(kOn);
    EXPECT_EQ(r.status, as::kDriveEnabled | as::kReferenced | as::kPositiveLimitNotActuated);
    axis_.Place(now_, 10060.0);
    r = Step(kOn);
    EXPECT_EQ(r.status, as::kDriveEnabled | as::kReferenced | as::kNegativeLimitNotActuated);
}

TEST_F(AxisModuleIdle, DisplacedDuringOffBlocksMovesUntilReset) {
    constexpr std::uint32_t kDisplacedBits = as::kDisplaced | as::kGroupDisplaced;
    Step(0);  // IDLE
    ASSERT_TRUE(axis_.Displace(now_, 5.0));
    auto r = Step(kOn);
    EXPECT_EQ(r.status, kOnReferenced | kDisplacedBits);
    r = Step(kOn | ac::kMoveRelative | ac::kStart, 10.0);
    EXPECT_EQ(r.cmdError, axis_error::kAxisDisplacedTooMuch);
    Step(kOn);
    r = Step(kOn | ac::kClearDisplaced | ac::kStart);  // bit 13: instant job
    EXPECT_EQ(r.status, kOnActive);
    EXPECT_EQ(r.cmdError, 0);
    EXPECT_EQ(DecodeModulePosition(r.position, false), 5.0f);
    // The group flag alone comes from the integrator.
    groupDisplaced_ = true;
    EXPECT_EQ(Step(kOn).status, kOnReferenced | as::kGroupDisplaced);
}

TEST_F(AxisModuleHandshake, ResetReturnsToThePowerOnState) {
    Step(kOn);
    Step(kOn | ac::kStart);
    module_.SetConditionInput(3);
    EXPECT_EQ(module_.CmdError(), 20);
    module_.Reset();
    EXPECT_EQ(module_.CmdError(), 0);
    EXPECT_EQ(module_.ConditionInput(), 1);
    EXPECT_FALSE(module_.Active());
    EXPECT_EQ(Step(kOn | ac::kStart).cmdError, 20);  // Start held through Reset: an edge from power-on 0
}

// ---- the ledger of the jobs taken over ---------------------------------------------------------------

// A simulation that runs for hours takes jobs without end: the ledger keeps the last kKept, numbered from
// power-on, and says so for an older one instead of growing.
TEST(TakenAxisJobLedger, KeepsTheLastJobsByTheirNumberFromPowerOn) {
    TakenAxisJobLedger ledger;
    const std::size_t total = TakenAxisJobLedger::kKept * 2 + 5;
    for (std::size_t n = 0; n < total; ++n) {
        TakenAxisJob job;
        job.command.position = static_cast<std::uint32_t>(n);
        ledger.Add(job);
        ASSERT_EQ(ledger.size(), n + 1);
        ASSERT_EQ(ledger[n].command.position, n) << "the job just taken";
    }
    EXPECT_EQ(ledger.First(), total - TakenAxisJobLedger::kKept);
    for (std::size_t n = ledger.First(); n < total; ++n) EXPECT_EQ(ledger[n].command.position, n) << n;
    EXPECT_THROW(ledger[ledger.First() - 1], std::out_of_range) << "no longer kept";
    EXPECT_THROW(ledger[total], std::out_of_range) << "not yet taken";
}

// The module enters each job it takes over on a Start edge, with the bytes it carried.
TEST_F(AxisModuleSequences, EachJobTakenOverIsInTheLedger) {
    for (int k = 1; k <= 3; ++k) {
        Step(kOn | ac::kSetPosition | ac::kStart, 5.0 * k);
        Step(kOn);
    }
    const TakenAxisJobLedger& taken = module_.TakenJobs();
    ASSERT_EQ(taken.size(), 3u);
    EXPECT_EQ(taken.First(), 0u);
    for (std::size_t n = 0; n < 3; ++n) {
        EXPECT_EQ(taken[n].command.position, EncodeModulePosition(5.0 * static_cast<double>(n + 1), integer_)) << n;
        EXPECT_EQ(taken[n].command.control & ac::kTraverseBits, ac::kSetPosition) << n;
    }
}

}  // namespace
}  // namespace pac::sim
