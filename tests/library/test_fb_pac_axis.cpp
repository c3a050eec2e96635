// FB_PAC_Axis scan by scan against a scripted axis module (tests/support/fake_axis_module.hpp) behind a
// bus of 0..3 scans latency each way: the control word bits and data bytes of every job in both number
// formats, take-over and Done at their exact scans, the stale CMD error rule under both controller
// behaviours, axis errors and their reset, Abort, Enable, link loss, a new job during a job, jog, G123,
// Timeout and the status outputs. Every scan of every test checks that the module never carries two
// traverse bits, never Start without exactly one (axis_control_rules.hpp), and runs the PLCopen checker
// (plcopen_checker.hpp).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <tuple>

#include "axis_control_rules.hpp"
#include "fake_axis_module.hpp"
#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/scan_test.hpp"
#include "pac/st_program.hpp"
#include "plcopen_checker.hpp"
#include "real_bits.hpp"
#include "run_to_final.hpp"
#include "scan_window.hpp"

namespace test_fb_pac_axis {  // apart from the names of the other sources in its unity batch
namespace {

using pac::test::AxisImage;
using pac::test::BitsOf;
using pac::test::CmdErrorStyle;
using pac::test::FakeAxisConfig;
using pac::test::FakeAxisModule;
using pac::test::ReadBe16;
using pac::test::ReadBe32;
using pac::test::ScanDelayLine;
namespace ctrl = pac::axis_control;
namespace status = pac::axis_status;

const pac::test::GvlConstants kGvl;
const std::uint32_t kErrAckTimeout = kGvl["PAC_LIB_ERR_ACK_TIMEOUT"];
const std::uint32_t kErrNotReady = kGvl["PAC_LIB_ERR_NOT_READY"];
const std::uint32_t kErrInterfaceBusy = kGvl["PAC_LIB_ERR_INTERFACE_BUSY"];
const std::uint32_t kErrAxisError = kGvl["PAC_LIB_ERR_AXIS_ERROR"];
const std::uint32_t kErrNotAllowed = kGvl["PAC_LIB_ERR_NOT_ALLOWED"];
const std::uint32_t kErrInvalidVelocity = kGvl["PAC_LIB_ERR_INVALID_VELOCITY"];
const std::uint32_t kErrInvalidAcceleration = kGvl["PAC_LIB_ERR_INVALID_ACCELERATION"];
const std::uint32_t kErrInvalidPosition = kGvl["PAC_LIB_ERR_INVALID_POSITION"];
const std::uint32_t kErrNoCommand = kGvl["PAC_LIB_ERR_NO_COMMAND"];
const std::uint32_t kErrNotOnline = kGvl["PAC_LIB_ERR_NOT_ONLINE"];
const std::uint32_t kNoReference = kGvl["PAC_ERR_NO_REFERENCE"];          // 43
const std::uint32_t kPositionRange = kGvl["PAC_ERR_POSITION_RANGE"];      // 65
const std::uint32_t kAxisOff = kGvl["PAC_ERR_AXIS_OFF"];                  // 55
const std::uint32_t kLimitSwitch = kGvl["PAC_ERR_LIMIT_SWITCH"];          // 64

constexpr int kTimeoutScans = 20;  // Timeout in the tests, at 1 ms per scan
// The PA-CONTROL's update time (2.3.4: < 10 ms in ONLINE), at 1 ms per scan: a level on the wire that long
// has been read by at least one controller cycle, so Start and the reset bit must have been 0 that long
// before the FB can be sure the PA-CONTROL has seen them 0 (and sees the next rise as an edge).
constexpr int kPacUpdateScans = 10;
// Before it has measured a take-over the FB assumes the longest one the library is made for: 3 scans of bus
// latency each way, a scan, and the update time (FB_PAC_Axis.md); Start must have been 0 that long plus the
// update time before the first Start after a restart.
constexpr int kAssumedTakeoverScans = 3 + 3 + 1 + kPacUpdateScans;
constexpr int kStartLowAfterRestartScans = kAssumedTakeoverScans + kPacUpdateScans;
constexpr BYTE kOnline = 31;  // operating status (2.4.2)

std::uint32_t TraverseBits(std::uint32_t control) { return control & ctrl::kTraverseBits; }

// How a job ended (absolute scan numbers of the task), and the scan that raised Start (-1: none).
struct Outcome : pac::test::FinalOutcome {
    std::int64_t startScan = -1;
};

// The PLC: FB_PAC_Axis on one axis module, the bus (a delay line each way, whole scans) and the fake
// axis, which runs one controller cycle per scan after the PLC program.
class FbPacAxis : public pac::ScanTest {
protected:
    FbPacAxis() {
        Configure({});
        fb_->OPSTATUS.value = kOnline;  // the fake axis module is always in ONLINE
        fb_->ENABLE.value = TRUE;
        fb_->TIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(kTimeoutScans));
        task_.AddProgram([this] { OneScan(); });
    }

    // Before the first scan only.
    void Configure(const FakeAxisConfig& config, int outLatency = 0, int inLatency = 0) {
        axis_ = std::make_unique<FakeAxisModule>(config);
        outLatency_ = outLatency;
        inLatency_ = inLatency;
        visible_ = axis_->Reply();
        atController_ = AxisImage{};
        out_ = std::make_unique<ScanDelayLine<AxisImage>>(outLatency, AxisImage{});
        in_ = std::make_unique<ScanDelayLine<AxisImage>>(inLatency, visible_);
        fb_->INTEGERMODE.value = config.integerFormat;
    }

    void OneScan() {
        AxisImage input = linkLost_ ? AxisImage{} : visible_;
        if (forcedReply_) input = *forcedReply_;
        for (int i = 0; i < 12; ++i) {
            fb_->FROMPAC.value.table[i] = input[i];
            fb_->TOPAC.value.table[i] = toPac_[i];
        }
        fb_();
        const bool startBefore = StartBit();
        for (int i = 0; i < 12; ++i) toPac_[i] = fb_->TOPAC.value.table[i];
        if (StartBit() && !startBefore) lastStartScan_ = task_.ScanCount();
        CheckInvariants();
        // A lost link carries nothing either way: the controller keeps the last module it received.
        if (!linkLost_) atController_ = out_->Push(toPac_);
        visible_ = in_->Push(axis_->Cycle(atController_));
    }

    void CheckInvariants() {
        const std::int64_t scan = task_.ScanCount();
        const char* broken = pac::test::AxisControlWordViolation(ControlWord(), ctrl::kTraverseBits, ctrl::kStart);
        EXPECT_EQ(broken, nullptr) << broken << " in scan " << scan;
        rules_.Check(scan, fb_);
    }

    // --- inputs -----------------------------------------------------------------------------------
    void SetJob(E_PAC_AXISCOMMAND command, float position = 0.0f, unsigned velocity = 1000,
                unsigned acceleration = 1000) {
        fb_->COMMAND.value = command;
        fb_->POSITION.value = position;
        fb_->VELOCITY.value = static_cast<UINT>(velocity);
        fb_->ACCELERATION.value = static_cast<UINT>(acceleration);
    }
    void Execute(bool on) { fb_->EXECUTE.value = on; }

    // Execute edge (the next scan sees it), then scans until a final output; Execute stays TRUE.
    Outcome StartAndWait(int maxScans = 300) {
        const std::int64_t startBefore = lastStartScan_;
        Execute(true);
        Cycle(1);
        Outcome o;
        static_cast<pac::test::FinalOutcome&>(o) = pac::test::RunToFinal(fb_, task_.ScanCount(), [this] {
            task_.Scan();
            return task_.ScanCount();
        }, maxScans);
        if (lastStartScan_ != startBefore) o.startScan = lastStartScan_;
        return o;
    }

    // A whole job as a PLC program runs it: edge, wait, Execute back to FALSE for one scan.
    // The final output clears in the scan that sees Execute FALSE: the PLCopen checker.
    Outcome Run(int maxScans = 300) {
        Outcome o = StartAndWait(maxScans);
        Execute(false);
        Cycle(1);
        return o;
    }

    // --- outputs and the module -------------------------------------------------------------------
    bool Done() const { return pac::test::OutputsOf(fb_).done; }
    bool Busy() const { return pac::test::OutputsOf(fb_).busy; }
    bool Error() const { return pac::test::OutputsOf(fb_).error; }
    bool Aborted() const { return pac::test::OutputsOf(fb_).aborted; }
    bool Final() const { return pac::test::IsFinal(fb_); }
    std::uint32_t ControlWord() const { return ReadBe32(toPac_, 0); }
    bool StartBit() const { return (ControlWord() & ctrl::kStart) != 0; }
    std::uint32_t Traverse() const { return TraverseBits(ControlWord()); }
    int RoundTrip() const { return outLatency_ + inLatency_ + 1; }  // scans from writing to seeing the answer
    // Long enough for the FB to count the axis as free after a (re)start: Start 0 for the assumed take-over
    // plus the update time.
    void Settle() { Cycle(RoundTrip() + 2 + kStartLowAfterRestartScans); }

    pac::FbInstance<FB_PAC_AXIS> fb_ = PAC_FB(FB_PAC_AXIS);
    pac::test::PlcOpenChecker rules_{"FB_PAC_Axis"};
    std::unique_ptr<FakeAxisModule> axis_;
    std::unique_ptr<ScanDelayLine<AxisImage>> out_;
    std::unique_ptr<ScanDelayLine<AxisImage>> in_;
    AxisImage toPac_{};
    AxisImage visible_{};
    AxisImage atController_{};
    std::optional<AxisImage> forcedReply_;
    bool linkLost_ = false;
    int outLatency_ = 0;
    int inLatency_ = 0;
    std::int64_t lastStartScan_ = -1;
};

// ---------------------------------------------------------------------------------------------------
// Every command: its traverse bit, and acceleration, speed and position bytes, in both number formats.

struct CommandCase {
    E_PAC_AXISCOMMAND command;
    std::uint32_t bit;
    bool needsReference;
    const char* name;
};

const CommandCase kCommands[] = {
    {E_PAC_AXISCOMMAND__PAC_AX_HOME, ctrl::kHome, false, "Home"},
    {E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, ctrl::kMoveAbsolute, true, "MoveAbsolute"},
    {E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE, ctrl::kMoveRelative, true, "MoveRelative"},
    {E_PAC_AXISCOMMAND__PAC_AX_MOVE_TO_MAX, ctrl::kMoveToMax, true, "MoveToMax"},
    {E_PAC_AXISCOMMAND__PAC_AX_MOVE_TO_MIN, ctrl::kMoveToMin, true, "MoveToMin"},
    {E_PAC_AXISCOMMAND__PAC_AX_SET_REFERENCED, ctrl::kSetReferenced, false, "SetReferenced"},
    {E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION, ctrl::kSetPosition, false, "SetPosition"},
    {E_PAC_AXISCOMMAND__PAC_AX_CLEAR_OFFSET, ctrl::kClearOffset, false, "ClearOffset"},
    {E_PAC_AXISCOMMAND__PAC_AX_CLEAR_DISPLACED, ctrl::kClearDisplaced, false, "ClearDisplaced"},
};

class FbPacAxisCommand : public FbPacAxis, public ::testing::WithParamInterface<std::tuple<CommandCase, bool>> {};

TEST_P(FbPacAxisCommand, BitAndDataBytesGoOutWithStartAndTheBitStaysUntilDone) {
    const auto [c, integer] = GetParam();
    FakeAxisConfig config;
    config.integerFormat = integer;
    Configure(config);
    Settle();
    SetJob(c.command, -12.5f, 250, 40000);
    Execute(true);
    Cycle(1);
    ASSERT_TRUE(StartBit()) << "the axis is free: Start goes out in the edge scan";
    const std::uint32_t position = integer ? static_cast<std::uint32_t>(-12500) : BitsOf(-12.5f);
    const AxisImage expected = {0, 0, static_cast<std::uint8_t>((ctrl::kStart | ctrl::kAxisOn | c.bit) >> 8),
                                static_cast<std::uint8_t>(ctrl::kStart | ctrl::kAxisOn | c.bit),
                                0x9C, 0x40, 0x00, 0xFA,
                                static_cast<std::uint8_t>(position >> 24), static_cast<std::uint8_t>(position >> 16),
                                static_cast<std::uint8_t>(position >> 8), static_cast<std::uint8_t>(position)};
    EXPECT_EQ(toPac_, expected) << c.name;
    EXPECT_TRUE(Busy());
    Cycle(1);  // the axis answers with ACTIVE: Start drops, the traverse bit stays
    EXPECT_FALSE(StartBit());
    EXPECT_EQ(Traverse(), c.bit);
    EXPECT_EQ(ReadBe32(toPac_, 8), position) << "data unchanged during the job";
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 50, "final output"));
    EXPECT_TRUE(Done()) << c.name;
    EXPECT_EQ(Traverse(), 0u) << "released in the Done scan";
    ASSERT_EQ(axis_->Jobs().size(), 1u);
    EXPECT_EQ(axis_->Jobs()[0].control, ctrl::kAxisOn | ctrl::kStart | c.bit);
    EXPECT_EQ(axis_->Jobs()[0].acceleration, 40000);
    EXPECT_EQ(axis_->Jobs()[0].speed, 250);
    EXPECT_EQ(axis_->Jobs()[0].position, position);
}

INSTANTIATE_TEST_SUITE_P(AllCommands, FbPacAxisCommand,
                         ::testing::Combine(::testing::ValuesIn(kCommands), ::testing::Bool()),
                         [](const auto& info) {
                             return std::string(std::get<0>(info.param).name) +
                                    (std::get<1>(info.param) ? "_Integer" : "_Ieee");
                         });

TEST_F(FbPacAxis, PositionBytesInBothFormatsExactly) {
    struct Case {
        float position;
        bool integer;
        std::uint32_t bytes;
    };
    const Case cases[] = {
        {12.345f, false, BitsOf(12.345f)},
        {640.0f, false, 0x44200000u},  // docs/manual_errata.md: the real bytes of 640.0
        {10.0f, false, 0x41200000u},
        {12.345f, true, 12345u},
        {25.045f, true, 25045u},
        {-25.045f, true, static_cast<std::uint32_t>(-25045)},
        {0.0f, true, 0u},
        {-0.0f, true, 0u},
        {2147483.5f, true, 2147483500u},                                 // the largest REAL that fits x1000
        {-2147483.5f, true, static_cast<std::uint32_t>(-2147483500)},    // and the smallest
        {1.0e30f, false, BitsOf(1.0e30f)},                               // fine as IEEE
    };
    Settle();
    for (const Case& c : cases) {
        fb_->INTEGERMODE.value = c.integer;
        SetJob(E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION, c.position);
        Execute(true);
        Cycle(1);
        ASSERT_TRUE(StartBit()) << c.position;
        EXPECT_EQ(ReadBe32(toPac_, 8), c.bytes) << c.position << (c.integer ? " integer" : " IEEE");
        ASSERT_TRUE(RunUntil([&] { return Final(); }, 20, "final output"));
        EXPECT_TRUE(Done());
        Execute(false);
        Cycle(2);
    }
}

TEST_F(FbPacAxis, PositionIsConvertedAtTheEdgeOnly) {
    Settle();
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 7.0f);
    axis_->SetReferenced(true);
    Execute(true);
    Cycle(1);
    fb_->POSITION.value = 99.0f;
    fb_->VELOCITY.value = 1;
    Cycle(2);
    EXPECT_EQ(ReadBe32(toPac_, 8), BitsOf(7.0f)) << "the latched job's data stay on the wire";
    EXPECT_EQ(ReadBe16(toPac_, 6), 1000);
}

// ---------------------------------------------------------------------------------------------------
// Invalid inputs: an error at the edge and nothing sent.

TEST_F(FbPacAxis, InvalidInputsAreRefusedAndNothingIsSent) {
    struct Case {
        const char* what;
        E_PAC_AXISCOMMAND command;
        float position;
        unsigned velocity;
        unsigned acceleration;
        bool integer;
        std::uint32_t errorId;
    };
    const float inf = std::numeric_limits<float>::infinity();
    const Case cases[] = {
        {"no command", E_PAC_AXISCOMMAND__PAC_AX_NONE, 1.0f, 1000, 1000, false, kErrNoCommand},
        {"velocity 0", E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 1.0f, 0, 1000, false, kErrInvalidVelocity},
        {"velocity 1001", E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 1.0f, 1001, 1000, false, kErrInvalidVelocity},
        {"velocity 65535", E_PAC_AXISCOMMAND__PAC_AX_HOME, 1.0f, 65535, 1000, false, kErrInvalidVelocity},
        {"acceleration 0", E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 1.0f, 500, 0, false, kErrInvalidAcceleration},
        {"NaN", E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, std::numeric_limits<float>::quiet_NaN(), 500, 500, false,
         kErrInvalidPosition},
        {"+inf", E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE, inf, 500, 500, false, kErrInvalidPosition},
        {"-inf", E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION, -inf, 500, 500, false, kErrInvalidPosition},
        {"NaN integer", E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, std::numeric_limits<float>::quiet_NaN(), 500, 500,
         true, kErrInvalidPosition},
        {"-inf integer", E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, -inf, 500, 500, true, kErrInvalidPosition},
        {"beyond DINT", E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 2147483.75f, 500, 500, true, kErrInvalidPosition},
        {"below DINT", E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, -2147483.75f, 500, 500, true, kErrInvalidPosition},
        {"far beyond DINT", E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 3.0e38f, 500, 500, true, kErrInvalidPosition},
        {"no command with bad data", E_PAC_AXISCOMMAND__PAC_AX_NONE, inf, 0, 0, false, kErrNoCommand},
    };
    Settle();
    const AxisImage idle = toPac_;
    for (const Case& c : cases) {
        fb_->INTEGERMODE.value = c.integer;
        SetJob(c.command, c.position, c.velocity, c.acceleration);
        Execute(true);
        Cycle(1);
        EXPECT_TRUE(Error()) << c.what << ": refused in the edge scan";
        EXPECT_EQ(fb_->ERRORID.value, c.errorId) << c.what;
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(toPac_, idle) << c.what << ": nothing written";
            EXPECT_TRUE(Error()) << c.what << ": held while Execute";
            Cycle(1);
        }
        Execute(false);
        Cycle(1);
        EXPECT_FALSE(Error());
    }
    EXPECT_TRUE(axis_->Jobs().empty());
}

TEST_F(FbPacAxis, BoundaryValuesAreAccepted) {
    Settle();
    fb_->INTEGERMODE.value = FALSE;
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION, 1.0f, 1, 65535);
    Outcome o = Run();
    EXPECT_TRUE(o.Done());
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION, 1.0f, 1000, 1);
    o = Run();
    EXPECT_TRUE(o.Done());
    ASSERT_EQ(axis_->Jobs().size(), 2u);
    EXPECT_EQ(axis_->Jobs()[0].speed, 1);
    EXPECT_EQ(axis_->Jobs()[0].acceleration, 65535);
    EXPECT_EQ(axis_->Jobs()[1].speed, 1000);
    EXPECT_EQ(axis_->Jobs()[1].acceleration, 1);
}

// ---------------------------------------------------------------------------------------------------
// Take-over and Done at their exact scans, on every latency.

class FbPacAxisLatency : public FbPacAxis, public ::testing::WithParamInterface<std::tuple<int, int>> {
protected:
    void SetUp() override {
        FakeAxisConfig config;
        config.moveCycles = 10;  // longer than the longest round trip, so the move decides when ACTIVE falls
        Configure(config, std::get<0>(GetParam()), std::get<1>(GetParam()));
        Settle();
    }
};

TEST_P(FbPacAxisLatency, InstantJobStartDropsAtTakeOverAndDoneWhenActiveFalls) {
    const int k = RoundTrip();
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION, 3.0f);
    Execute(true);
    Cycle(1);
    const std::int64_t s = task_.ScanCount();
    EXPECT_TRUE(StartBit()) << "scan " << s << ": Start with the edge";
    for (int i = 1; i < k; ++i) {
        Cycle(1);
        EXPECT_TRUE(StartBit()) << "no answer seen yet, scan s+" << i;
        EXPECT_TRUE(Busy());
    }
    Cycle(1);
    EXPECT_FALSE(StartBit()) << "ACTIVE seen at s+" << k << ": Start drops";
    EXPECT_EQ(Traverse(), ctrl::kSetPosition) << "the traverse bit stays";
    EXPECT_TRUE(Busy());
    EXPECT_TRUE(fb_->ACTIVE.value);
    for (int i = 1; i < k; ++i) {
        Cycle(1);
        EXPECT_TRUE(Busy()) << "ACTIVE still up, scan s+" << k + i;
    }
    Cycle(1);
    EXPECT_TRUE(Done()) << "ACTIVE fell, seen at s+" << 2 * k;
    EXPECT_EQ(Traverse(), 0u);
    EXPECT_FALSE(fb_->ACTIVE.value);
    EXPECT_EQ(axis_->Position(), 3.0f);
}

TEST_P(FbPacAxisLatency, MoveIsDoneInTheScanThatShowsActiveFallen) {
    axis_->SetReferenced(true);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 50.0f, 500, 500);
    const Outcome o = Run();
    ASSERT_TRUE(o.Done());
    EXPECT_EQ(o.startScan, o.edgeScan);
    // The controller takes over at s + out, moves 10 cycles; ACTIVE falls in the last (Start is long 0)
    // and the PLC sees it in + 1 scans later.
    EXPECT_EQ(o.finalScan, o.startScan + outLatency_ + 10 + inLatency_ + 1);
    EXPECT_EQ(axis_->Position(), 50.0f);
    EXPECT_EQ(BitsOf(fb_->ACTUALPOSITION.value), BitsOf(50.0f));
}

INSTANTIATE_TEST_SUITE_P(OutIn, FbPacAxisLatency, ::testing::Combine(::testing::Range(0, 4), ::testing::Range(0, 4)),
                         [](const auto& info) {
                             return "Out" + std::to_string(std::get<0>(info.param)) + "In" +
                                    std::to_string(std::get<1>(info.param));
                         });

TEST_F(FbPacAxis, StartWaitsForTheAssumedTakeOverAfterARestart) {
    // The PA-CONTROL may still see a Start from before a PLC restart, and an answer to it may still be on its
    // way: Start goes out once it has been 0 on the wire for the longest take-over the FB assumes before it
    // measured one, plus the update time, so the PA-CONTROL has seen it 0 and sees a new edge.
    fb_->TIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(100));  // longer than the wait
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_HOME);
    Execute(true);
    for (int i = 0; i < kStartLowAfterRestartScans; ++i) {
        Cycle(1);
        EXPECT_FALSE(StartBit()) << "scan " << task_.ScanCount();
        EXPECT_TRUE(Busy());
    }
    Cycle(1);
    EXPECT_TRUE(StartBit()) << "0 since the first scan, seen from the second: 27 ms at scan 28";
}

TEST_F(FbPacAxis, DoneShowsForExactlyOneScanWhenExecuteFellEarly) {
    Settle();
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_CLEAR_OFFSET);
    Execute(true);
    Cycle(1);
    Execute(false);
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 10, "final output"));
    EXPECT_TRUE(Done());
    Cycle(1);
    EXPECT_FALSE(Done());
    EXPECT_FALSE(Busy());
}

TEST_F(FbPacAxis, DoneHoldsWhileExecuteStaysTrue) {
    Settle();
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_CLEAR_DISPLACED);
    axis_->SetDisplaced(true);
    Outcome o = StartAndWait();
    ASSERT_TRUE(o.Done());
    Cycle(10);
    EXPECT_TRUE(Done());
    EXPECT_FALSE(fb_->DISPLACEDWHILEOFF.value);
    Execute(false);
    Cycle(1);
    EXPECT_FALSE(Done());
}

// ---------------------------------------------------------------------------------------------------
// CMD errors and the stale CMD error rule.

TEST_F(FbPacAxis, CmdError43EndsTheJobWithThePacNumber) {
    FakeAxisConfig config;
    config.referenced = false;
    config.cmdErrorStyle = CmdErrorStyle::kSameCycle;
    Configure(config);
    Settle();
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE, 5.0f);
    Execute(true);
    Cycle(1);
    ASSERT_TRUE(StartBit());
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(fb_->ERRORID.value, kNoReference);
    EXPECT_EQ(fb_->CMDERRORNUMBER.value, kNoReference);
    EXPECT_TRUE(fb_->CMDERROR.value);
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn) << "Start and traverse bit off in the error scan";
    Cycle(5);
    EXPECT_TRUE(Error()) << "held while Execute";
}

// A failed job (43), then a second one, on every latency, both CMD error behaviours and with the
// answer held back 0 or 2 controller cycles. The first job's error is measured (its bit rose from 0),
// so the rule knows the take-over time k.
class FbPacAxisStale : public FbPacAxis,
                       public ::testing::WithParamInterface<std::tuple<int, int, CmdErrorStyle, int>> {
protected:
    void SetUp() override {
        FakeAxisConfig config;
        config.referenced = false;
        config.cmdErrorStyle = Style();
        config.answerDelay = std::get<3>(GetParam());
        Configure(config, std::get<0>(GetParam()), std::get<1>(GetParam()));
        Settle();
        SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 10.0f);
        first_ = Run();
        ASSERT_TRUE(first_.Error());
        ASSERT_EQ(first_.ErrorId(), kNoReference);
        EXPECT_EQ(first_.startScan, first_.edgeScan);
        EXPECT_EQ(first_.finalScan, first_.startScan + K() + (SetsLate() ? 1 : 0));
    }

    CmdErrorStyle Style() const { return std::get<2>(GetParam()); }
    bool SetsLate() const { return Style() == CmdErrorStyle::kClearThenSet; }
    // Scans from raising Start to the answer: bus both ways, the controller cycle, the held-back answer.
    int K() const { return RoundTrip() + std::get<3>(GetParam()); }

    Outcome first_;
};

TEST_P(FbPacAxisStale, FailedThenGood) {
    axis_->SetReferenced(true);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 10.0f);
    const Outcome second = Run();
    EXPECT_TRUE(second.Done()) << "errorId " << second.ErrorId();
    ASSERT_EQ(axis_->Jobs().size(), 2u);
    EXPECT_EQ(axis_->Position(), 10.0f);
}

// The second refusal carries the number the bit already shows. The PA-CONTROL answers the Start edge in
// its take-over cycle (2.7.4.14), which the PLC sees K scans after raising Start: nothing the FB shows
// before that can be the second job's result. A controller that clears the bit in the take-over cycle
// and sets it in the next shows the refusal as the bit rising again, one scan later. One that clears and
// sets in one cycle shows the PLC no change at all: the FB may report the refusal any time from the
// answer on, and Timeout (which bounds every wait of FB_PAC_Axis) is the latest.
TEST_P(FbPacAxisStale, FailedThenFailedWithTheSameNumber) {
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 10.0f);
    const Outcome second = Run();
    ASSERT_TRUE(second.Error()) << second;
    EXPECT_EQ(second.ErrorId(), kNoReference);
    ASSERT_EQ(axis_->Jobs().size(), 2u) << "Start was 0 long enough for the PA-CONTROL to see a new edge";
    const std::int64_t answered = second.startScan + K();
    const pac::test::ScanWindow allowed =
        SetsLate() ? pac::test::ScanWindow{K() + 1, K() + 1} : pac::test::ScanWindow{K(), kTimeoutScans};
    EXPECT_TRUE(allowed.Contains(second.finalScan - second.startScan))
        << second << ", " << second.finalScan - second.startScan << " scans after Start (answer seen after "
        << answered - second.startScan << "); allowed " << allowed;
}

TEST_P(FbPacAxisStale, FailedThenFailedWithAnotherNumber) {
    axis_->SetReferenced(true);
    axis_->RefuseJobsWith(static_cast<std::uint16_t>(kPositionRange));
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 10.0f);
    const Outcome second = Run();
    ASSERT_TRUE(second.Error());
    EXPECT_EQ(second.ErrorId(), kPositionRange);
    EXPECT_EQ(second.finalScan, second.startScan + K() + (SetsLate() ? 1 : 0)) << "number changed";
}

TEST_P(FbPacAxisStale, FailedFailedGoodFailed) {
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 10.0f);
    Outcome o = Run();
    EXPECT_EQ(o.ErrorId(), kNoReference);
    axis_->SetReferenced(true);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE, 1.0f);
    o = Run();
    EXPECT_TRUE(o.Done());
    axis_->SetReferenced(false);
    o = Run();
    EXPECT_EQ(o.ErrorId(), kNoReference);
    EXPECT_EQ(o.finalScan, o.startScan + K() + (SetsLate() ? 1 : 0)) << "after a good job the bit was 0";
    EXPECT_EQ(axis_->Jobs().size(), 4u);
    EXPECT_EQ(axis_->Position(), 1.0f) << "only the relative move ran";
}

std::string StyleName(CmdErrorStyle s) { return s == CmdErrorStyle::kClearThenSet ? "ClearThenSet" : "SameCycle"; }

INSTANTIATE_TEST_SUITE_P(Timings, FbPacAxisStale,
                         ::testing::Combine(::testing::Range(0, 4), ::testing::Range(0, 4),
                                            ::testing::Values(CmdErrorStyle::kClearThenSet, CmdErrorStyle::kSameCycle),
                                            ::testing::Values(0, 2)),
                         [](const auto& info) {
                             return "Out" + std::to_string(std::get<0>(info.param)) + "In" +
                                    std::to_string(std::get<1>(info.param)) + StyleName(std::get<2>(info.param)) +
                                    "Held" + std::to_string(std::get<3>(info.param));
                         });

// A CMD error from before a PLC restart: nothing measured yet, so only a change of the bit or number
// or Timeout decides.
class FbPacAxisRestart : public FbPacAxis, public ::testing::WithParamInterface<CmdErrorStyle> {
protected:
    void SetUp() override {
        FakeAxisConfig config;
        config.cmdErrorStyle = GetParam();
        Configure(config, 1, 1);
        axis_->SetCmdError(static_cast<std::uint16_t>(kNoReference));
        Settle();
        ASSERT_TRUE(fb_->CMDERROR.value);
    }
};

TEST_P(FbPacAxisRestart, GoodJobIsDone) {
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 4.0f);
    const Outcome o = Run();
    EXPECT_TRUE(o.Done()) << o.ErrorId();
}

TEST_P(FbPacAxisRestart, FailingJobWithTheSameNumber) {
    axis_->SetReferenced(false);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 4.0f);
    const Outcome o = Run();
    ASSERT_TRUE(o.Error());
    EXPECT_EQ(o.ErrorId(), kNoReference);
    if (GetParam() == CmdErrorStyle::kClearThenSet) {
        EXPECT_EQ(o.finalScan, o.startScan + RoundTrip() + 1);
    } else {
        EXPECT_EQ(o.finalScan, o.startScan + kTimeoutScans) << "nothing measured, no change: Timeout decides";
    }
}

INSTANTIATE_TEST_SUITE_P(Styles, FbPacAxisRestart,
                         ::testing::Values(CmdErrorStyle::kClearThenSet, CmdErrorStyle::kSameCycle),
                         [](const auto& info) { return StyleName(info.param); });

// ---------------------------------------------------------------------------------------------------
// Timeout.

TEST_F(FbPacAxis, NoTakeOverWithinTimeout) {
    Settle();
    axis_->Mute(true);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_HOME);
    const Outcome o = StartAndWait();
    ASSERT_TRUE(o.Error());
    EXPECT_EQ(o.ErrorId(), kErrAckTimeout);
    EXPECT_EQ(o.finalScan, o.startScan + kTimeoutScans);
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn);
}

TEST_F(FbPacAxis, TimeoutWithAStaleCmdErrorReportsItsNumber) {
    axis_->SetCmdError(static_cast<std::uint16_t>(kPositionRange));
    Settle();
    axis_->Mute(true);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_HOME);
    const Outcome o = StartAndWait();
    ASSERT_TRUE(o.Error());
    EXPECT_EQ(o.ErrorId(), kPositionRange);
    EXPECT_EQ(o.finalScan, o.startScan + kTimeoutScans);
}

// ---------------------------------------------------------------------------------------------------
// Axis errors and ResetError.

TEST_F(FbPacAxis, AxisErrorDuringAMoveAndItsReset) {
    FakeAxisConfig config;
    config.moveCycles = 30;
    Configure(config, 1, 2);
    Settle();
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE, 100.0f);
    Execute(true);
    Cycle(8);
    ASSERT_TRUE(Busy());
    axis_->RaiseAxisError(static_cast<std::uint16_t>(kLimitSwitch));
    const std::int64_t raised = task_.ScanCount();
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 10, "final output"));
    EXPECT_EQ(task_.ScanCount(), raised + 1 + inLatency_ + 1) << "the first scan that can show the axis error";
    EXPECT_TRUE(Error());
    EXPECT_EQ(fb_->ERRORID.value, kErrAxisError);
    EXPECT_EQ(fb_->ERRORSOURCE.value, E_PAC_ERRORSOURCE__PAC_ERRSRC_LIBRARY) << "the axis error number has a pin of its own";
    EXPECT_EQ(fb_->AXISERRORNUMBER.value, kLimitSwitch);
    EXPECT_TRUE(fb_->AXISERROR.value);
    EXPECT_TRUE(fb_->FAULT.value);
    EXPECT_EQ(Traverse(), 0u);
    Execute(false);
    Cycle(2);

    // A job while the error is pending: refused at the edge, nothing sent.
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_HOME);
    Outcome o = Run();
    EXPECT_EQ(o.ErrorId(), kErrAxisError);
    EXPECT_EQ(o.finalScan, o.edgeScan);
    EXPECT_EQ(axis_->Jobs().size(), 1u);

    // ResetError: bit 16 from the edge until the axis error bit is seen 0: one round trip.
    fb_->RESETERROR.value = TRUE;
    Cycle(1);
    const std::int64_t r = task_.ScanCount();
    EXPECT_EQ(ControlWord() & ctrl::kResetAxisError, ctrl::kResetAxisError);
    ASSERT_TRUE(RunUntil([&] { return (ControlWord() & ctrl::kResetAxisError) == 0; }, 10, "reset bit off"));
    EXPECT_EQ(task_.ScanCount(), r + RoundTrip());
    EXPECT_FALSE(fb_->AXISERROR.value);
    EXPECT_EQ(fb_->AXISERRORNUMBER.value, 0);
    Cycle(5);
    EXPECT_EQ(ControlWord() & ctrl::kResetAxisError, 0u) << "a pulse, although ResetError stays TRUE";
    fb_->RESETERROR.value = FALSE;

    o = Run();
    EXPECT_TRUE(o.Done()) << "the axis moves again";
}

TEST_F(FbPacAxis, ResetPulseEndsAfterTimeoutWhileTheCauseRemains) {
    Settle();
    axis_->RaiseAxisError(static_cast<std::uint16_t>(kLimitSwitch), true);
    Cycle(3);
    fb_->RESETERROR.value = TRUE;
    Cycle(1);
    const std::int64_t r = task_.ScanCount();
    ASSERT_TRUE(RunUntil([&] { return (ControlWord() & ctrl::kResetAxisError) == 0; }, 40, "reset bit off"));
    EXPECT_EQ(task_.ScanCount(), r + kTimeoutScans);
    EXPECT_TRUE(fb_->AXISERROR.value);
    const std::int64_t off = task_.ScanCount();
    fb_->RESETERROR.value = FALSE;
    Cycle(1);
    axis_->ClearAxisErrorCause();
    fb_->RESETERROR.value = TRUE;
    Cycle(1);
    // A PA-CONTROL may act on the rising edge only: the new pulse waits until bit 16 has been 0 for the
    // update time (read back from the scan after it fell).
    EXPECT_EQ(ControlWord() & ctrl::kResetAxisError, 0u);
    ASSERT_TRUE(RunUntil([&] { return (ControlWord() & ctrl::kResetAxisError) != 0; }, 20, "reset bit on"));
    EXPECT_EQ(task_.ScanCount(), off + 1 + kPacUpdateScans);
    ASSERT_TRUE(RunUntil([&] { return !fb_->AXISERROR.value; }, 5, "axis error cleared"));
}

TEST_F(FbPacAxis, ResetWithoutAnAxisErrorIsOneScan) {
    Settle();
    fb_->RESETERROR.value = TRUE;
    Cycle(1);
    EXPECT_NE(ControlWord() & ctrl::kResetAxisError, 0u);
    Cycle(1);
    EXPECT_EQ(ControlWord() & ctrl::kResetAxisError, 0u);
    EXPECT_EQ(axis_->ResetCycles(), 1);
}

// An axis error ends a job in whatever wait it is (docs/fb/FB_PAC_Axis.md, "Axis error"): while it waits for
// the axis to be free, before the take-over, and while it stops after Abort; Abort in those waits ends it with
// CommandAborted. A CMD error with number 0 is reported as 16#8008, so that Error never comes with ErrorID 0.

// An axis error that comes before the take-over is the controller's answer to the Start (E525 "no reference
// point", 2.7.2 note): the job ends with its number unchanged, as a system error number.
TEST_F(FbPacAxis, AxisErrorBeforeTheTakeOverIsAnErrorWithItsNumber) {
    Settle();
    axis_->Mute(true);  // the Start edge gets no answer
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_HOME);
    Execute(true);
    Cycle(3);
    ASSERT_TRUE(Busy());
    ASSERT_TRUE(StartBit());
    axis_->RaiseAxisError(static_cast<std::uint16_t>(kLimitSwitch));
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 10, "final output"));
    EXPECT_TRUE(Error());
    EXPECT_EQ(fb_->ERRORID.value, kLimitSwitch);
    EXPECT_EQ(fb_->ERRORSOURCE.value, E_PAC_ERRORSOURCE__PAC_ERRSRC_SYSTEM);
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn) << "Start and the traverse bit off";
}

TEST_F(FbPacAxis, AbortBeforeTheTakeOverIsCommandAbortedWhenStartHasBeenLowLongEnough) {
    Settle();
    axis_->Mute(true);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_HOME);
    Execute(true);
    Cycle(3);
    ASSERT_TRUE(StartBit());
    fb_->ABORT.value = TRUE;
    Cycle(1);
    const std::int64_t a = task_.ScanCount();
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn) << "Start and the traverse bit off in the Abort scan";
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 40, "final output"));
    EXPECT_TRUE(Aborted());
    // Nothing was taken over, so nothing was measured: Start must have been 0 on the wire for the assumed
    // take-over plus the update time before the axis counts as free (read back from the scan after the Abort
    // scan): a late answer to the Start is visible by then.
    EXPECT_EQ(task_.ScanCount(), a + 1 + kStartLowAfterRestartScans);
}

TEST_F(FbPacAxis, CmdErrorWithNumberZeroIsReportedAsNotAllowed) {
    Settle();
    axis_->Mute(true);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_HOME);
    Execute(true);
    Cycle(2);
    AxisImage reply = visible_;
    pac::test::WriteBe32(reply, 0, ReadBe32(reply, 0) | status::kCmdError);
    pac::test::WriteBe16(reply, 4, 0);
    forcedReply_ = reply;
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 10, "final output"));
    EXPECT_TRUE(Error());
    EXPECT_EQ(fb_->ERRORID.value, kErrNotAllowed);
}

TEST_F(FbPacAxis, AnyByteOfTheModuleMakesItAReply) {
    // A live axis shows a drive state in bits 0..5; a module that is all zero is no reply (link lost), but
    // one with any field set comes from the PA-CONTROL, odd as it is.
    Settle();
    for (int field : {4, 6, 8}) {
        AxisImage reply{};
        if (field == 8) {
            pac::test::WriteBe32(reply, 8, BitsOf(1.5f));
        } else {
            pac::test::WriteBe16(reply, field, 7);
        }
        forcedReply_ = reply;
        Cycle(1);
        EXPECT_TRUE(fb_->STATUSVALID.value) << "byte " << field;
        forcedReply_ = AxisImage{};
        Cycle(1);
        EXPECT_FALSE(fb_->STATUSVALID.value);
    }
}

// ---------------------------------------------------------------------------------------------------
// Abort, Enable, link loss, a new job during a job.

class FbPacAxisLongMove : public FbPacAxis {
protected:
    void SetUp() override {
        FakeAxisConfig config;
        config.moveCycles = 40;
        config.brakeCycles = 3;
        Configure(config);
        Settle();
        SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 400.0f, 800, 800);
        Execute(true);
        Cycle(10);
        ASSERT_TRUE(Busy());
        ASSERT_TRUE(axis_->IsMoving());
    }
};

TEST_F(FbPacAxisLongMove, AbortInterruptsAndEndsWhenTheAxisIsFree) {
    fb_->ABORT.value = TRUE;
    Cycle(1);
    const std::int64_t a = task_.ScanCount();
    EXPECT_EQ(Traverse(), 0u) << "the traverse bit goes off in the Abort scan";
    EXPECT_TRUE(Busy());
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 20, "final output"));
    EXPECT_TRUE(Aborted());
    EXPECT_EQ(task_.ScanCount(), a + 3) << "the axis stands in cycle a + 2 (3 braking cycles), seen at a + 3";
    EXPECT_TRUE(fb_->HALTED.value);
    EXPECT_FALSE(fb_->ACTIVE.value);
    EXPECT_LT(axis_->Position(), 400.0f);
    Cycle(3);
    EXPECT_TRUE(Aborted()) << "held while Execute";
    // A job while Abort is held: aborted at once, nothing sent.
    Execute(false);
    Cycle(1);
    const Outcome o = Run();
    EXPECT_TRUE(o.Aborted());
    EXPECT_EQ(o.finalScan, o.edgeScan);
    EXPECT_EQ(axis_->Jobs().size(), 1u);
    fb_->ABORT.value = FALSE;
    EXPECT_TRUE(Run().Done());
}

// A stop ends when ACTIVE has fallen, not after Timeout: the axis may brake for longer.
TEST_F(FbPacAxisLongMove, AbortEndsWhenActiveFallsEvenAfterTimeout) {
    axis_->HoldActive(true);
    fb_->ABORT.value = TRUE;
    Cycle(1);
    Cycle(2 * kTimeoutScans);
    EXPECT_TRUE(Busy()) << "ACTIVE still set: the stop goes on";
    axis_->HoldActive(false);
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 10, "final output"));
    EXPECT_TRUE(Aborted());
    EXPECT_FALSE(fb_->ACTIVE.value);
}

// An axis that stays ACTIVE is an error of its own after StopTimeout, never Busy for ever.
TEST_F(FbPacAxisLongMove, StopTimeoutEndsAStopWhileActiveStaysUp) {
    constexpr int kStopTimeoutScans = 50;
    fb_->STOPTIMEOUT.value = pac::ToIecTime(std::chrono::milliseconds(kStopTimeoutScans));
    axis_->HoldActive(true);
    fb_->ABORT.value = TRUE;
    Cycle(1);
    const std::int64_t a = task_.ScanCount();
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 2 * kStopTimeoutScans, "final output"));
    EXPECT_TRUE(Error());
    EXPECT_EQ(fb_->ERRORID.value, kGvl["PAC_LIB_ERR_STOP_TIMEOUT"]);
    EXPECT_EQ(task_.ScanCount(), a + kStopTimeoutScans);
    EXPECT_TRUE(fb_->ACTIVE.value) << "Active tells the truth";
    // The next job waits for the axis to be free, bounded by Timeout.
    fb_->ABORT.value = FALSE;
    Execute(false);
    Cycle(1);
    const Outcome o = Run();
    ASSERT_TRUE(o.Error());
    EXPECT_EQ(o.ErrorId(), kErrInterfaceBusy);
    EXPECT_EQ(o.startScan, -1) << "no Start while the axis is ACTIVE";
    EXPECT_EQ(o.finalScan, o.edgeScan + kTimeoutScans);
    EXPECT_EQ(axis_->Jobs().size(), 1u);
}

TEST_F(FbPacAxisLongMove, EnableFallingInterruptsTheJob) {
    fb_->ENABLE.value = FALSE;
    Cycle(1);
    EXPECT_EQ(ControlWord(), 0u) << "Axis ON and the traverse bit off";
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 20, "final output"));
    EXPECT_TRUE(Aborted());
    EXPECT_FALSE(fb_->ENABLED.value);
    EXPECT_TRUE(fb_->IDLE.value);
}

TEST_F(FbPacAxisLongMove, LinkLostAbortsTheJobAtOnce) {
    linkLost_ = true;
    Cycle(1);
    EXPECT_TRUE(Aborted()) << "an all-zero link aborts the job like Abort (issue: Enable falling, an all-zero "
                              "link or another Execute edge abort it the same way)";
    EXPECT_FALSE(Error());
    EXPECT_EQ(fb_->ERRORID.value, 0u);
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn) << "Start and traverse bit off";
    EXPECT_FALSE(fb_->STATUSVALID.value);
    EXPECT_FALSE(fb_->NEGATIVELIMITACTUATED.value) << "no status, no limit switch";
    EXPECT_FALSE(fb_->POSITIVELIMITACTUATED.value);
    EXPECT_GT(fb_->ACTUALPOSITION.value, 0.0f) << "the last position is kept";
    Execute(false);
    Cycle(1);
    const Outcome o = Run();
    EXPECT_EQ(o.ErrorId(), kErrNotReady) << "no job while the link is lost";
    EXPECT_EQ(o.finalScan, o.edgeScan);
    linkLost_ = false;
    Cycle(3);
    EXPECT_TRUE(fb_->STATUSVALID.value);
    EXPECT_FALSE(axis_->IsMoving()) << "the controller saw the traverse bit go";
    EXPECT_TRUE(Run().Done());
}

TEST_F(FbPacAxisLongMove, NewExecuteAbortsTheJobAndStartsTheNewOneWhenTheAxisIsFree) {
    Execute(false);
    Cycle(1);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE, -5.0f, 300, 300);
    Execute(true);
    Cycle(1);
    const std::int64_t e = task_.ScanCount();
    EXPECT_TRUE(Aborted()) << "the old job: CommandAborted in the edge scan";
    EXPECT_FALSE(Busy());
    EXPECT_EQ(Traverse(), 0u) << "its traverse bit off";
    Cycle(1);
    EXPECT_FALSE(Aborted()) << "for one scan";
    EXPECT_TRUE(Busy()) << "the new job";
    EXPECT_FALSE(StartBit()) << "not while ACTIVE";
    ASSERT_TRUE(RunUntil([&] { return StartBit(); }, 20, "Start of the new job"));
    EXPECT_EQ(task_.ScanCount(), e + 3) << "the scan that sees ACTIVE fallen";
    EXPECT_EQ(Traverse(), ctrl::kMoveRelative);
    EXPECT_EQ(ReadBe16(toPac_, 6), 300);
    const float stoppedAt = axis_->Position();
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 60, "final output"));
    EXPECT_TRUE(Done());
    ASSERT_EQ(axis_->Jobs().size(), 2u);
    EXPECT_EQ(axis_->Jobs()[1].control, ctrl::kAxisOn | ctrl::kStart | ctrl::kMoveRelative);
    EXPECT_EQ(axis_->Position(), stoppedAt - 5.0f);
}

// A new job waits while ACTIVE of the one it superseded stays up.
TEST_F(FbPacAxisLongMove, AxisErrorWhileTheNextJobWaitsForTheAxisIsAnError) {
    axis_->HoldActive(true);
    Execute(false);
    Cycle(1);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_HOME);
    Execute(true);
    Cycle(1);
    ASSERT_TRUE(Aborted()) << "the move, in the edge scan";
    Cycle(3);
    ASSERT_TRUE(Busy());
    ASSERT_FALSE(StartBit()) << "waiting for ACTIVE to fall";
    axis_->RaiseAxisError(static_cast<std::uint16_t>(kLimitSwitch));
    const std::int64_t raised = task_.ScanCount();
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 10, "final output"));
    EXPECT_EQ(task_.ScanCount(), raised + 1 + inLatency_ + 1) << "the first scan that can show the axis error";
    EXPECT_TRUE(Error());
    EXPECT_EQ(fb_->ERRORID.value, kErrAxisError);
    EXPECT_EQ(axis_->Jobs().size(), 1u) << "the new job never went out";
}

TEST_F(FbPacAxisLongMove, AbortWhileTheNextJobWaitsIsCommandAbortedOnceTheAxisIsFree) {
    axis_->HoldActive(true);
    Execute(false);
    Cycle(1);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_HOME);
    Execute(true);
    Cycle(3);
    ASSERT_TRUE(Busy());
    fb_->ABORT.value = TRUE;
    Cycle(3);
    EXPECT_TRUE(Busy()) << "it ends when the axis is free, or after Timeout";
    axis_->HoldActive(false);
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 10, "final output"));
    EXPECT_TRUE(Aborted());
    EXPECT_FALSE(StartBit());
    EXPECT_EQ(axis_->Jobs().size(), 1u) << "the new job never went out";
}

TEST_F(FbPacAxisLongMove, AxisErrorWhileStoppingIsAnError) {
    axis_->HoldActive(true);  // the stop takes as long as the test needs
    fb_->ABORT.value = TRUE;
    Cycle(2);
    ASSERT_TRUE(Busy());
    axis_->RaiseAxisError(static_cast<std::uint16_t>(kLimitSwitch));
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 10, "final output"));
    EXPECT_TRUE(Error()) << "not CommandAborted: the axis reports an error";
    EXPECT_EQ(fb_->ERRORID.value, kErrAxisError);
}

TEST_F(FbPacAxisLongMove, InterruptionFromOutsideIsCommandAborted) {
    axis_->InterruptFromOutside();
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 20, "final output"));
    EXPECT_TRUE(Aborted()) << "ACTIVE fell with HALT: not at the target";
    EXPECT_TRUE(fb_->HALTED.value);
}

// ---------------------------------------------------------------------------------------------------
// Jog.

class FbPacAxisJog : public FbPacAxis {
protected:
    void SetUp() override {
        FakeAxisConfig config;
        config.moveCycles = 20;
        config.referenced = false;
        Configure(config);
        Settle();
        fb_->POSITION.value = 200.0f;  // the longest distance
        fb_->VELOCITY.value = 100;
        fb_->ACCELERATION.value = 50;
    }
};

TEST_F(FbPacAxisJog, JogPositiveWhileHeldStopsWhenReleased) {
    fb_->JOGPOSITIVE.value = TRUE;
    Cycle(1);
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn | ctrl::kStart | ctrl::kJogPositive) << "no reference needed";
    EXPECT_EQ(ReadBe32(toPac_, 8), BitsOf(200.0f));
    EXPECT_EQ(ReadBe16(toPac_, 6), 100);
    EXPECT_EQ(ReadBe16(toPac_, 4), 50);
    EXPECT_TRUE(Busy());
    Cycle(1);
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn | ctrl::kJogPositive) << "taken over: Start off, the bit stays";
    Cycle(5);
    EXPECT_TRUE(Busy());
    fb_->JOGPOSITIVE.value = FALSE;
    Cycle(1);
    const std::int64_t r = task_.ScanCount();
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn) << "released: the bit goes";
    EXPECT_TRUE(Busy());
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 10, "final output"));
    EXPECT_TRUE(Done());
    EXPECT_EQ(task_.ScanCount(), r + 2) << "2 braking cycles from r, seen the scan after";
    Cycle(1);
    EXPECT_FALSE(Done()) << "one scan: the jog input is FALSE";
    EXPECT_GT(axis_->Position(), 0.0f);
    EXPECT_LT(axis_->Position(), 200.0f);
}

TEST_F(FbPacAxisJog, JogNegativeToItsDistanceHoldsDoneWhileHeld) {
    fb_->JOGNEGATIVE.value = TRUE;
    Cycle(1);
    EXPECT_EQ(Traverse(), ctrl::kJogNegative);
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 40, "final output"));
    EXPECT_TRUE(Done());
    EXPECT_EQ(Traverse(), 0u);
    EXPECT_EQ(axis_->Position(), -200.0f);
    Cycle(5);
    EXPECT_TRUE(Done()) << "held while JogNegative";
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn) << "no second jog while held";
    fb_->JOGNEGATIVE.value = FALSE;
    Cycle(1);
    EXPECT_FALSE(Done());
    EXPECT_EQ(axis_->Jobs().size(), 1u);
}

TEST_F(FbPacAxisJog, JogErrorIsReportedWhileHeld) {
    fb_->ENABLE.value = FALSE;
    Cycle(2);
    fb_->JOGPOSITIVE.value = TRUE;
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 10, "final output"));
    EXPECT_TRUE(Error());
    EXPECT_EQ(fb_->ERRORID.value, kAxisOff);
    Cycle(5);
    EXPECT_TRUE(Error());
    fb_->JOGPOSITIVE.value = FALSE;
    Cycle(1);
    EXPECT_FALSE(Error());
}

TEST_F(FbPacAxisJog, InvalidJogDataIsRefusedWhileHeld) {
    fb_->VELOCITY.value = 0;
    fb_->JOGNEGATIVE.value = TRUE;
    Cycle(1);
    EXPECT_TRUE(Error());
    EXPECT_EQ(fb_->ERRORID.value, kErrInvalidVelocity);
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn);
    Cycle(3);
    EXPECT_TRUE(Error());
    fb_->JOGNEGATIVE.value = FALSE;
    Cycle(1);
    EXPECT_FALSE(Error());
    EXPECT_TRUE(axis_->Jobs().empty());
}

TEST_F(FbPacAxisJog, BothJogInputsMoveNothing) {
    fb_->JOGPOSITIVE.value = TRUE;
    fb_->JOGNEGATIVE.value = TRUE;
    Cycle(3);
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn);
    EXPECT_FALSE(Busy());
    fb_->JOGNEGATIVE.value = FALSE;
    Cycle(3);
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn) << "a jog starts on its own edge only";
}

TEST_F(FbPacAxisJog, ExecuteDuringAJogEndsTheJog) {
    fb_->JOGPOSITIVE.value = TRUE;
    Cycle(4);
    ASSERT_TRUE(Busy());
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION, 0.0f);
    Execute(true);
    Cycle(1);
    EXPECT_TRUE(Aborted()) << "the jog ends";
    EXPECT_EQ(Traverse(), 0u);
    Cycle(1);
    EXPECT_TRUE(Busy()) << "the job owns the outputs";
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 20, "final output"));
    EXPECT_TRUE(Done()) << "the job ran";
    EXPECT_EQ(axis_->Jobs().size(), 2u);
    EXPECT_EQ(axis_->Position(), 0.0f);
    Cycle(3);
    EXPECT_EQ(axis_->Jobs().size(), 2u) << "the jog input still held starts nothing";
}

TEST_F(FbPacAxisJog, JogIgnoredWhileAJobRuns) {
    axis_->SetReferenced(true);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 30.0f);
    Execute(true);
    Cycle(3);
    fb_->JOGNEGATIVE.value = TRUE;
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 40, "final output"));
    EXPECT_TRUE(Done());
    EXPECT_EQ(axis_->Jobs().size(), 1u);
}

// ---------------------------------------------------------------------------------------------------
// G123, Axis ON, DisableDrive, DisableLimitSwitches.

TEST_F(FbPacAxis, ConditionBitsGoWithAbsoluteAndRelativeMovesOnly) {
    struct Case {
        E_PAC_AXISCOMMAND command;
        E_PAC_MOVECONDITION condition;
        std::uint32_t bits;
    };
    const Case cases[] = {
        {E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, E_PAC_MOVECONDITION__PAC_COND_WHILE_INPUT_1,
         ctrl::kMoveAbsolute | ctrl::kWhileInput1},
        {E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, E_PAC_MOVECONDITION__PAC_COND_WHILE_INPUT_0,
         ctrl::kMoveAbsolute | ctrl::kWhileInput0},
        {E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE, E_PAC_MOVECONDITION__PAC_COND_WHILE_INPUT_1,
         ctrl::kMoveRelative | ctrl::kWhileInput1},
        {E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE, E_PAC_MOVECONDITION__PAC_COND_WHILE_INPUT_0,
         ctrl::kMoveRelative | ctrl::kWhileInput0},
        {E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE, E_PAC_MOVECONDITION__PAC_COND_NONE, ctrl::kMoveRelative},
        {E_PAC_AXISCOMMAND__PAC_AX_HOME, E_PAC_MOVECONDITION__PAC_COND_WHILE_INPUT_1, ctrl::kHome},
        {E_PAC_AXISCOMMAND__PAC_AX_MOVE_TO_MAX, E_PAC_MOVECONDITION__PAC_COND_WHILE_INPUT_0, ctrl::kMoveToMax},
        {E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION, E_PAC_MOVECONDITION__PAC_COND_WHILE_INPUT_1, ctrl::kSetPosition},
    };
    Settle();
    for (const Case& c : cases) {
        SetJob(c.command, 1.0f);
        fb_->CONDITION.value = c.condition;
        Execute(true);
        Cycle(1);
        EXPECT_EQ(ControlWord(), ctrl::kAxisOn | ctrl::kStart | c.bits);
        Cycle(1);
        EXPECT_EQ(ControlWord(), ctrl::kAxisOn | c.bits) << "the G123 bits stay with the traverse bit";
        ASSERT_TRUE(RunUntil([&] { return Final(); }, 20, "final output"));
        EXPECT_TRUE(Done());
        Execute(false);
        Cycle(2);
    }
}

// An absolute move with G123's condition "while input 1", six scans under way.
class FbPacAxisConditionMove : public FbPacAxis {
protected:
    void StartMoveWhileInput1() {
        FakeAxisConfig config;
        config.moveCycles = 30;
        Configure(config);
        Settle();
        SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE, 300.0f);
        fb_->CONDITION.value = E_PAC_MOVECONDITION__PAC_COND_WHILE_INPUT_1;
        Execute(true);
        Cycle(6);
    }
};

TEST_F(FbPacAxisConditionMove, MoveEndedByItsConditionIsDone) {
    StartMoveWhileInput1();
    axis_->StopByCondition();
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 20, "final output"));
    EXPECT_TRUE(Done());
    EXPECT_TRUE(fb_->STOPPEDBYCONDITION.value);
    EXPECT_TRUE(fb_->HALTED.value);
}

// A G123 move that HALT ends without its condition (STOP ONLINE...) was interrupted: not Done.
TEST_F(FbPacAxisConditionMove, ConditionMoveInterruptedFromOutsideIsCommandAborted) {
    StartMoveWhileInput1();
    axis_->InterruptFromOutside();
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 20, "final output"));
    EXPECT_TRUE(Aborted());
    EXPECT_FALSE(fb_->STOPPEDBYCONDITION.value);
    EXPECT_TRUE(fb_->HALTED.value);
}

TEST_F(FbPacAxis, LevelBitsFollowTheirInputsEveryScan) {
    Settle();
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn);
    fb_->DISABLEDRIVE.value = TRUE;
    Cycle(1);
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn | ctrl::kDisableDrive);
    fb_->DISABLEDRIVE.value = FALSE;
    fb_->ENABLE.value = FALSE;
    Cycle(1);
    EXPECT_EQ(ControlWord(), 0u);
    fb_->ENABLE.value = TRUE;
    fb_->DISABLELIMITSWITCHES.value = TRUE;
    Cycle(3);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE, 2.0f);
    Execute(true);
    Cycle(1);
    EXPECT_EQ(ControlWord(), ctrl::kAxisOn | ctrl::kStart | ctrl::kMoveRelative | ctrl::kDisableLimitSwitches);
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 20, "final output"));
    ASSERT_EQ(axis_->Jobs().size(), 1u);
    EXPECT_NE(axis_->Jobs()[0].control & ctrl::kDisableLimitSwitches, 0u) << "taken over with Start";
}

// ---------------------------------------------------------------------------------------------------
// Status outputs.

TEST_F(FbPacAxis, EveryStatusBitHasItsOutputLimitSwitchesLowActive) {
    auto outputs = [&] {
        const auto& f = fb_.Data();
        return std::array<bool, 16>{f.ENABLED.value != 0,  f.HALTED.value != 0,     f.DRIVEDISABLED.value != 0,
                                    f.SAFE.value != 0,     f.IDLE.value != 0,       f.DISABLED.value != 0,
                                    f.FAULT.value != 0,    f.ACTIVE.value != 0,     f.REFERENCED.value != 0,
                                    f.NEGATIVELIMITACTUATED.value != 0, f.POSITIVELIMITACTUATED.value != 0,
                                    f.STOPPEDBYCONDITION.value != 0, f.DISPLACEDWHILEOFF.value != 0,
                                    f.GROUPDISPLACEDWHILEOFF.value != 0, f.CMDERROR.value != 0,
                                    f.AXISERROR.value != 0};
    };
    const std::uint32_t limitsFree = status::kNegativeLimitNotActuated | status::kPositiveLimitNotActuated;
    for (int bit = 0; bit < 16; ++bit) {
        const std::uint32_t word = limitsFree ^ (1u << bit);  // bits 9 and 10: 0 means actuated
        AxisImage reply{};
        pac::test::WriteBe32(reply, 0, word);
        forcedReply_ = reply;
        Cycle(1);
        const auto out = outputs();
        for (int i = 0; i < 16; ++i) EXPECT_EQ(out[i], i == bit) << "status bit " << bit << ", output " << i;
        EXPECT_EQ(fb_->STATUSWORD.value, word);
        EXPECT_TRUE(fb_->STATUSVALID.value);
    }
}

TEST_F(FbPacAxis, LimitSwitchesFromTheAxis) {
    axis_->SetLimitSwitches(true, false);
    Settle();
    EXPECT_TRUE(fb_->NEGATIVELIMITACTUATED.value);
    EXPECT_FALSE(fb_->POSITIVELIMITACTUATED.value);
    EXPECT_EQ(fb_->STATUSWORD.value & (status::kNegativeLimitNotActuated | status::kPositiveLimitNotActuated),
              status::kPositiveLimitNotActuated);
    axis_->SetLimitSwitches(false, true);
    Settle();
    EXPECT_FALSE(fb_->NEGATIVELIMITACTUATED.value);
    EXPECT_TRUE(fb_->POSITIVELIMITACTUATED.value);
}

TEST_F(FbPacAxis, NumbersAndActualPositionInBothFormats) {
    AxisImage reply{};
    pac::test::WriteBe32(reply, 0, status::kDriveEnabled | status::kCmdError | status::kAxisError);
    pac::test::WriteBe16(reply, 4, 0x1234);
    pac::test::WriteBe16(reply, 6, 999);
    pac::test::WriteBe32(reply, 8, static_cast<std::uint32_t>(-25045));
    forcedReply_ = reply;
    fb_->INTEGERMODE.value = TRUE;
    Cycle(1);
    EXPECT_EQ(fb_->CMDERRORNUMBER.value, 0x1234);
    EXPECT_EQ(fb_->AXISERRORNUMBER.value, 999);
    EXPECT_EQ(BitsOf(fb_->ACTUALPOSITION.value), BitsOf(-25.045f));
    pac::test::WriteBe32(reply, 8, 2147483647u);
    forcedReply_ = reply;
    Cycle(1);
    EXPECT_EQ(BitsOf(fb_->ACTUALPOSITION.value), BitsOf(2147483.647f));
    fb_->INTEGERMODE.value = FALSE;
    pac::test::WriteBe32(reply, 8, 0x44200000u);
    forcedReply_ = reply;
    Cycle(1);
    EXPECT_EQ(fb_->ACTUALPOSITION.value, 640.0f);
    pac::test::WriteBe32(reply, 8, 0x7FC00000u);  // NaN from the wire: decoded to 0.0, never a NaN REAL
    forcedReply_ = reply;
    Cycle(1);
    EXPECT_EQ(fb_->ACTUALPOSITION.value, 0.0f);
}

// The FB decodes the module only when something it depends on changed: a new number format with the same
// bytes on the wire is such a change.
TEST_F(FbPacAxis, ActualPositionFollowsTheFormatWhileTheImageStays) {
    AxisImage reply{};
    pac::test::WriteBe32(reply, 0, status::kDriveEnabled);
    pac::test::WriteBe32(reply, 8, 0x44200000u);  // IEEE 640.0, or 1142947840 / 1000 as DINT x 1000
    forcedReply_ = reply;
    fb_->INTEGERMODE.value = TRUE;
    Cycle(2);
    EXPECT_NEAR(fb_->ACTUALPOSITION.value, 1142947.84, 0.2);
    fb_->INTEGERMODE.value = FALSE;
    Cycle(1);
    EXPECT_EQ(fb_->ACTUALPOSITION.value, 640.0f);
    fb_->INTEGERMODE.value = TRUE;
    Cycle(1);
    EXPECT_NEAR(fb_->ACTUALPOSITION.value, 1142947.84, 0.2);
}

// ---------------------------------------------------------------------------------------------------
// Jobs only where the PA-CONTROL runs them (2.7: "The axes can only be controlled in the ONLINE mode"; 2.7.2
// notes). The fake axis module answers every Start as an ONLINE controller would, whatever OpStatus says: a
// job admitted in HOME POSITION or a stopped ONLINE would end Done here, with nothing run on a real one.

// Every status the FB writes the module in, but running ONLINE: the job and the jog are refused in their edge
// scan with 16#8025, Start never rises, the controller receives no job.
TEST_F(FbPacAxis, JobsAndJogsOutsideRunningOnlineAreRefusedWithNothingSent) {
    for (const BYTE opStatus : {BYTE{1}, BYTE{9}, BYTE{30}, BYTE{32}, BYTE{35}, BYTE{37}, BYTE{39}}) {
        SCOPED_TRACE("operating status " + std::to_string(opStatus));
        fb_->OPSTATUS.value = opStatus;
        Settle();
        const std::size_t jobsBefore = axis_->Jobs().size();
        SetJob(E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION, 100.0f);
        const Outcome o = Run();
        EXPECT_TRUE(o.Error()) << o;
        EXPECT_EQ(o.ErrorId(), kErrNotOnline) << o;
        EXPECT_EQ(o.Scans(), 0) << "refused in the edge scan";
        EXPECT_EQ(o.startScan, -1) << "no Start";
        fb_->JOGPOSITIVE.value = TRUE;
        Cycle(1);
        EXPECT_TRUE(Error());
        EXPECT_EQ(fb_->ERRORID.value, kErrNotOnline);
        EXPECT_FALSE(StartBit());
        fb_->JOGPOSITIVE.value = FALSE;
        Cycle(1);
        EXPECT_EQ(axis_->Jobs().size(), jobsBefore) << "no job reached the controller";
    }
}

// ONLINE ends (STOP ONLINE: 35) while Start is up and the controller has not answered it. A job that may be
// complete without ACTIVE (G29) would be Done after the take-over bound on silence; outside running ONLINE
// silence says nothing: the job ends with 16#8025, never Done.
TEST_F(FbPacAxis, SilenceAfterOnlineEndedIsNoSignThatAJobRan) {
    Settle();
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION, 10.0f);
    ASSERT_TRUE(Run().Done()) << "a first job measures the take-over";
    Cycle(kPacUpdateScans);
    axis_->Mute(true);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION, 100.0f);
    Execute(true);
    Cycle(1);
    ASSERT_TRUE(StartBit());
    fb_->OPSTATUS.value = 35;
    ASSERT_TRUE(RunUntil([&] { return Final(); }, 3 * kTimeoutScans, "final output"));
    EXPECT_FALSE(Done()) << "the controller never answered";
    EXPECT_TRUE(Error());
    EXPECT_EQ(fb_->ERRORID.value, kErrNotOnline);
    EXPECT_FALSE(StartBit());
}

// A job waiting for the axis (the move it superseded still brakes) when ONLINE ends: its Start never goes out.
TEST_F(FbPacAxisLongMove, JobWaitingForTheAxisWhenOnlineEndsSendsNothing) {
    const std::size_t jobsBefore = axis_->Jobs().size();
    Execute(false);
    Cycle(1);
    SetJob(E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION, 100.0f);
    Execute(true);
    Cycle(1);
    ASSERT_TRUE(Aborted()) << "the move it supersedes, for one scan";
    Cycle(1);
    ASSERT_TRUE(Busy()) << "waits for the braking axis";
    ASSERT_TRUE(axis_->IsMoving());
    fb_->OPSTATUS.value = 35;
    ASSERT_TRUE(RunUntil([&] { return Final() || StartBit(); }, 3 * kTimeoutScans, "final output"));
    EXPECT_FALSE(StartBit());
    EXPECT_TRUE(Error());
    EXPECT_EQ(fb_->ERRORID.value, kErrNotOnline);
    Cycle(kTimeoutScans);
    EXPECT_EQ(axis_->Jobs().size(), jobsBefore);
}

// ResetError in HOME POSITION: the PA-CONTROL acts on no control word there (2.7.2 notes), and on the AUTOMATIC
// layout PAC_AUTOLAYOUT_FW2_N4 bit 16 is flag M1. An edge held back in ONLINE (bit 16 was not 0 for the update
// time yet) never goes out once ONLINE has ended, nor when ONLINE comes back; a pulse running when ONLINE
// ends stops in that scan.
TEST_F(FbPacAxis, ResetPulseNeverOnTheWireOutsideOnline) {
    Settle();
    axis_->RaiseAxisError(static_cast<std::uint16_t>(kLimitSwitch));
    Cycle(3);
    fb_->RESETERROR.value = TRUE;
    Cycle(1);
    ASSERT_NE(ControlWord() & ctrl::kResetAxisError, 0u);
    ASSERT_TRUE(RunUntil([&] { return (ControlWord() & ctrl::kResetAxisError) == 0; }, 10, "pulse over"));
    fb_->RESETERROR.value = FALSE;
    Cycle(1);
    fb_->RESETERROR.value = TRUE;  // within the update time: held back
    Cycle(1);
    ASSERT_EQ(ControlWord() & ctrl::kResetAxisError, 0u);
    fb_->OPSTATUS.value = 1;
    for (int i = 0; i < 3 * kPacUpdateScans; ++i) {
        Cycle(1);
        ASSERT_EQ(ControlWord() & ctrl::kResetAxisError, 0u) << "HOME POSITION, scan " << i;
    }
    fb_->OPSTATUS.value = kOnline;
    for (int i = 0; i < 3 * kPacUpdateScans; ++i) {
        Cycle(1);
        ASSERT_EQ(ControlWord() & ctrl::kResetAxisError, 0u) << "the old edge, ONLINE again, scan " << i;
    }
    // A pulse that runs (the cause persists) when ONLINE ends.
    axis_->RaiseAxisError(static_cast<std::uint16_t>(kLimitSwitch), true);
    fb_->RESETERROR.value = FALSE;
    Cycle(1);
    fb_->RESETERROR.value = TRUE;
    Cycle(1);
    ASSERT_NE(ControlWord() & ctrl::kResetAxisError, 0u);
    fb_->OPSTATUS.value = 1;
    for (int i = 0; i < kTimeoutScans; ++i) {
        Cycle(1);
        ASSERT_EQ(ControlWord() & ctrl::kResetAxisError, 0u) << "HOME POSITION, scan " << i;
    }
}

}  // namespace
}  // namespace test_fb_pac_axis
