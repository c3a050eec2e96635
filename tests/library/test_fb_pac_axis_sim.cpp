// FB_PAC_Axis (the library's ST compiled to C) driving the axis modules of the simulated PA-CONTROL (manual
// 2.7) over the simulated bus, scan by scan: FB_PAC_Ctrl brings the controller to ONLINE (external stop:
// system parameter 4 = input 1), then the four sequences of 2.7.9, every command in both number formats,
// every error path and its recovery, Abort / Enable / link loss / a new job during a move, jog, G123 and eight
// axes at once, on every combination of PLC cycle (1, 2, 5, 10 ms), PA-CONTROL cycle (1, 3, 10 ms) and bus
// latency (0..3 PLC cycles each way), and on jittered buses (seeds printed). Every scan checks that the module
// never carries two traverse bits nor Start without exactly one (axis_control_rules.hpp) and runs the PLCopen
// checker on every FB (plcopen_checker.hpp); the controller's own log shows that every Start edge the FB sent
// was recognised (none arrived while the axis was ACTIVE) and no job was sent twice.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "axis_control_rules.hpp"
#include "rig_timing.hpp"
#include "bus_timing.hpp"
#include "gvl_constants.hpp"
#include "log_follower.hpp"
#include "pac/rig_trace.hpp"
#include "pac/fb_instance.hpp"
#include "pac/sim/axis_module.hpp"
#include "pac/sim/pa_control.hpp"
#include "pac/st_program.hpp"
#include "pac/pac_rig.hpp"
#include "pac/trace_dump.hpp"
#include "plcopen_pins.hpp"
#include "plcopen_trace.hpp"
#include "plcopen_watch.hpp"
#include "real_bits.hpp"
#include "run_to_final.hpp"
#include "scan_window.hpp"

namespace test_fb_pac_axis_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using std::chrono::milliseconds;
using std::chrono::nanoseconds;
namespace ac = pac::axis_control;
namespace as = pac::axis_status;
using pac::sim::ActiveForJobs;
using pac::sim::CmdErrorRestart;
using pac::sim::InterruptedTraverse;
using pac::sim::NoReferenceAnswer;
using pac::sim::EnableMode;
using pac::test::BusTiming;

const pac::test::GvlConstants kGvl;
const std::uint32_t kErrAxisError = kGvl["PAC_LIB_ERR_AXIS_ERROR"];
const std::uint32_t kErrNotReady = kGvl["PAC_LIB_ERR_NOT_READY"];
const std::uint32_t kErrStopTimeout = kGvl["PAC_LIB_ERR_STOP_TIMEOUT"];
constexpr std::uint32_t kE525 = pac::sim::AxisModule::kSystemErrorNoReference;
const std::uint32_t kNoReference = kGvl["PAC_ERR_NO_REFERENCE"];      // 43
const std::uint32_t kAxisOff = kGvl["PAC_ERR_AXIS_OFF"];              // 55
const std::uint32_t kAxisDisplaced = kGvl["PAC_ERR_AXIS_DISPLACED"];  // 56
const std::uint32_t kLimitSwitch = kGvl["PAC_ERR_LIMIT_SWITCH"];      // 64
const std::uint32_t kPositionRange = kGvl["PAC_ERR_POSITION_RANGE"];  // 65
const std::uint32_t kNotOnline = kGvl["PAC_LIB_ERR_NOT_ONLINE"];
constexpr std::uint16_t kFollowingError = pac::sim::axis_error::kFollowingError;  // 66, the simulator's number

constexpr auto kHome = E_PAC_AXISCOMMAND__PAC_AX_HOME;
constexpr auto kAbsolute = E_PAC_AXISCOMMAND__PAC_AX_MOVE_ABSOLUTE;
constexpr auto kRelative = E_PAC_AXISCOMMAND__PAC_AX_MOVE_RELATIVE;
constexpr auto kToMax = E_PAC_AXISCOMMAND__PAC_AX_MOVE_TO_MAX;
constexpr auto kToMin = E_PAC_AXISCOMMAND__PAC_AX_MOVE_TO_MIN;
constexpr auto kSetReferenced = E_PAC_AXISCOMMAND__PAC_AX_SET_REFERENCED;
constexpr auto kSetPosition = E_PAC_AXISCOMMAND__PAC_AX_SET_POSITION;
constexpr auto kClearOffset = E_PAC_AXISCOMMAND__PAC_AX_CLEAR_OFFSET;
constexpr auto kClearDisplaced = E_PAC_AXISCOMMAND__PAC_AX_CLEAR_DISPLACED;
constexpr auto kWhileInput1 = E_PAC_MOVECONDITION__PAC_COND_WHILE_INPUT_1;

// Status words as the simulator composes them (2.7.2; limit switch bits 9 / 10 are 1 while free).
constexpr std::uint32_t kFree = as::kNegativeLimitNotActuated | as::kPositiveLimitNotActuated;  // 0x600
constexpr std::uint32_t kOnUnreferenced = as::kDriveEnabled | kFree;                            // 0x601
constexpr std::uint32_t kOnReferenced = as::kDriveEnabled | as::kReferenced | kFree;            // 0x701
constexpr std::uint32_t kOnActive = kOnReferenced | as::kActive;                                 // 0x781
constexpr std::uint32_t kOn = ac::kAxisOn;

constexpr std::size_t kOpStatusByte = 5;  // of the CMD reply (2.4.2)
constexpr int kExternalStopInput = 1;  // system parameter 4 (5.2.1.3)
constexpr int kConditionInput = 5;     // G123 (input 1 is the external stop here)

// ---------------------------------------------------------------------------------------------------
// What one scan of one axis looked like: the control word the FB wrote, the status word it read and its
// final output. The trace of an axis merges consecutive equal scans, so a sequence of 2.7.9 reads the same
// on every bus timing; each step keeps the scan it began in.

struct AxisStep {
    std::uint32_t control = 0;
    std::uint32_t status = 0;
    char output = '-';  // PlcOpenOutputs::Letter()

    friend bool operator==(const AxisStep& a, const AxisStep& b) {
        return a.control == b.control && a.status == b.status && a.output == b.output;
    }
    friend bool operator!=(const AxisStep& a, const AxisStep& b) { return !(a == b); }
    friend std::ostream& operator<<(std::ostream& out, const AxisStep& s) {
        return out << "{CW " << std::hex << std::uppercase << std::setw(5) << std::setfill('0') << s.control
                   << ", SW " << std::setw(4) << s.status << std::dec << ", " << s.output << "}";
    }
};
using Steps = std::vector<AxisStep>;

std::string Show(const Steps& steps) {
    std::ostringstream out;
    for (const AxisStep& s : steps) out << "\n  " << s;
    return out.str();
}

class AxisTrace {
public:
    void Add(std::int64_t scan, const AxisStep& step) {
        if (!steps_.empty() && steps_.back() == step) return;
        steps_.push_back(step);
        scans_.push_back(scan);
    }
    // The step showing now; Since(mark) starts with it.
    std::size_t Mark() const { return steps_.empty() ? 0 : steps_.size() - 1; }
    Steps Since(std::size_t mark) const {
        return Steps(steps_.begin() + static_cast<std::ptrdiff_t>(mark), steps_.end());
    }
    // The scan the first step after `mark` matching `predicate` began in; -1 if none.
    std::int64_t ScanOf(std::size_t mark, const std::function<bool(const AxisStep&)>& predicate) const {
        for (std::size_t i = mark; i < steps_.size(); ++i) {
            if (predicate(steps_[i])) return scans_[i];
        }
        return -1;
    }

private:
    Steps steps_;
    std::vector<std::int64_t> scans_;
};

// The controller's side, from its exchange log: the Start edges it saw on each module, and those that came
// while the module showed ACTIVE (lost, 2.7.3.2). An all-zero image is no control word (4.2.5).
class ControllerView {
public:
    explicit ControllerView(const pac::sim::ModuleLayout& layout)
        : layout_(layout), last_(static_cast<std::size_t>(layout.axisModules) + 1) {}

    void Follow(const pac::sim::ExchangeLog& log) {
        follower_.ForEachNew(log, [this](const pac::sim::ExchangeRecord& r) {
            for (int k = 1; k <= layout_.axisModules; ++k) {
                Module& m = last_[static_cast<std::size_t>(k)];
                const std::size_t offset = layout_.AxisOffset(k);
                if (!r.toPac.AllZero()) {
                    const std::uint32_t control = pac::sim::ReadDword(r.toPac.Module12(offset), 0);
                    if ((control & ac::kStart) != 0 && (m.control & ac::kStart) == 0) {
                        ++m.edges;
                        if ((m.status & as::kActive) != 0) ++m.lostEdges;
                        m.jobs.push_back(pac::sim::AxisModuleCommand::Decode(r.toPac.Module12(offset)));
                    }
                    m.control = control;
                }
                m.status = pac::sim::ReadDword(r.fromPac.Module12(offset), 0);
            }
        });
    }
    int StartEdges(int k) const { return last_[static_cast<std::size_t>(k)].edges; }
    int LostEdges(int k) const { return last_[static_cast<std::size_t>(k)].lostEdges; }
    // The module as the PA-CONTROL read it in the cycle of each Start edge.
    const std::vector<pac::sim::AxisModuleCommand>& Jobs(int k) const {
        return last_[static_cast<std::size_t>(k)].jobs;
    }

private:
    struct Module {
        std::uint32_t control = 0;
        std::uint32_t status = 0;
        int edges = 0;
        int lostEdges = 0;
        std::vector<pac::sim::AxisModuleCommand> jobs;
    };
    pac::sim::ModuleLayout layout_;
    std::vector<Module> last_;
    pac::test::LogFollower follower_;
};

// ---------------------------------------------------------------------------------------------------
// The PLC: FB_PAC_Ctrl on the CTRL module and one FB_PAC_Axis per axis module of a simulated PA-CONTROL,
// each axis taking the format in force from FB_PAC_Ctrl as a PLC program wires them.

// A reading of the axis module the manual leaves open (docs/open_points.md): which jobs raise ACTIVE, and how a
// move of an unreferenced axis is refused.
struct AxisReading {
    ActiveForJobs activeFor = ActiveForJobs::kEveryJob;
    NoReferenceAnswer noReference = NoReferenceAnswer::kCmdError43;
    InterruptedTraverse interrupted = InterruptedTraverse::kEnds;

    bool ContinuesAfterAxisOn() const { return interrupted == InterruptedTraverse::kContinuesAfterAxisOn; }
    bool ActiveOnlyWhenTraversing() const { return activeFor == ActiveForJobs::kTraversingOnly; }
    bool E525() const { return noReference == NoReferenceAnswer::kSystemError525; }
};

struct RigOptions {
    BusTiming timing{1, 10, 0};
    AxisReading reading;
    int axes = 1;
    EnableMode enableMode = EnableMode::kHalt;
    bool referenced = true;  // at power-on
    CmdErrorRestart cmdErrorRestart = CmdErrorRestart::kSameCycle;
    pac::sim::SpeedChange speedChange = pac::sim::SpeedChange::kNotWhileTraversing;  // the axis type (2.7.6)
};

struct Job {
    E_PAC_AXISCOMMAND command = E_PAC_AXISCOMMAND__PAC_AX_NONE;
    float position = 0.0f;
    unsigned velocity = 1000;
    unsigned acceleration = 1000;
    E_PAC_MOVECONDITION condition = E_PAC_MOVECONDITION__PAC_COND_NONE;
};

// How a job ended, the trace mark before its edge and the time of its edge scan.
struct Outcome : pac::test::FinalOutcome {
    std::size_t mark = 0;
    nanoseconds edgeTime{0};
};

pac::sim::PaControlConfig ConfigFor(const RigOptions& o) {
    pac::sim::PaControlConfig config;
    config.axisMachine.enableMode = o.enableMode;
    config.referencedAtPowerOn = o.referenced;
    config.axisModule.cmdErrorRestart = o.cmdErrorRestart;
    config.axisModule.activeFor = o.reading.activeFor;
    config.axisModule.noReference = o.reading.noReference;
    config.axisModule.interruptedTraverse = o.reading.interrupted;
    config.axisModule.speedChange = o.speedChange;
    return config;
}

class AxisSimRig {
public:
    explicit AxisSimRig(const RigOptions& options)
        : options_(options),
          layout_{true, options.axes},
          plc_(pac::test::RigTimingOf(options.timing), ConfigFor(options), layout_),
          view_(layout_) {
        auto& pac = plc_.Controller();
        EXPECT_EQ(pac.SystemParameters().Set(pac::sim::sysparam::kStopInput, kExternalStopInput),
                  pac::sim::ParameterTable::SetResult::kOk);
        pac.Io().inputs.Set(kExternalStopInput, true);
        for (int k = 0; k < options.axes; ++k) axes_.push_back(std::make_unique<AxisFb>(PAC_FB(FB_PAC_AXIS)));
        traces_.resize(static_cast<std::size_t>(options.axes));
        plc_.CallCtrl(ctrl_);
        for (int k = 1; k <= options.axes; ++k) {
            plc_.CallAxis(Fb(k), k, [this, k] {
                // As a PLC program wires them: the format in force and the mode change from FB_PAC_Ctrl, the
                // operating status from byte 5 of the CMD reply.
                Fb(k)->INTEGERMODE.value = ctrl_->INTEGERMODEACTIVE.value;
                Fb(k)->MODECHANGE.value = ctrl_->MODECHANGE.value;
                Fb(k)->OPSTATUS.value = plc_.FromPac()[kOpStatusByte];
            });
            Fb(k)->ENABLE.value = TRUE;
        }
        plc_.Start();
        plc_.Task().AddProgram([this] { Record(); });
        rules_.AddRequest("FB_PAC_Ctrl", ctrl_);
        for (int k = 1; k <= options.axes; ++k) rules_.AddJob("FB_PAC_Axis " + std::to_string(k), Fb(k));
        rules_.Attach(plc_.Task());
        // A failing test leaves the bus modules and the FBs' pins as a VCD file (pac/trace_dump.hpp).
        pac::TraceBusModules(recording_, plc_);
        pac::test::TracePlcOpenPins(recording_, "ctrl.FB_PAC_Ctrl", ctrl_);
        for (int k = 1; k <= options.axes; ++k) {
            pac::test::TracePlcOpenPins(recording_, "axis" + std::to_string(k) + ".FB_PAC_Axis", Fb(k));
        }
        recording_.AttachTo(plc_.Task());
    }

    // ONLINE through FB_PAC_Ctrl, with the integer format (2.5.3) taken over on the way; then long enough for
    // the axis FBs to treat the axes as free (more than the PA-CONTROL's longest update time, 2.3.4).
    void GoOnline(bool integer = false) {
        // As a PLC program would: the request once the controller shows Ready, not in the very first scans (the
        // first control word after the boot is only the reference for the CTRL edges, docs/simulator.md).
        ASSERT_GT(ScanUntil([this] { return ctrl_->READY.value != 0; }, 200), 0) << "Ready";
        ScanMs(20);
        ctrl_->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
        ctrl_->INTEGERMODE.value = integer ? TRUE : FALSE;
        ctrl_->EXECUTE.value = TRUE;
        const int scans = ScanUntil([this] { return ctrl_->DONE.value || ctrl_->ERROR.value; }, 500);
        ASSERT_GT(scans, 0) << "START_ONLINE ended";
        ASSERT_TRUE(ctrl_->DONE.value) << "START_ONLINE: ErrorID 16#" << std::hex << ctrl_->ERRORID.value;
        ctrl_->EXECUTE.value = FALSE;
        ASSERT_EQ(plc_.Controller().OperatingStatus(), 31);
        ASSERT_EQ(ctrl_->INTEGERMODEACTIVE.value != 0, integer);
        ASSERT_EQ(plc_.Controller().IntegerFormat(), integer);
        ScanMs(30);
    }

    using AxisFb = pac::FbInstance<FB_PAC_AXIS>;
    AxisFb& Fb(int k) { return *axes_.at(static_cast<std::size_t>(k - 1)); }
    pac::FbInstance<FB_PAC_CTRL>& Ctrl() { return ctrl_; }
    pac::sim::PaControl& Pac() { return plc_.Controller(); }
    pac::sim::ServoAxis& Motion(int k) { return plc_.Controller().Axes().Motion(k); }
    pac::PacRig& Plc() { return plc_; }
    nanoseconds Now() const { return plc_.Now(); }
    std::int64_t ScanCount() { return plc_.Task().ScanCount(); }
    const AxisTrace& Trace(int k) const { return traces_.at(static_cast<std::size_t>(k - 1)); }
    const ControllerView& View() const { return view_; }
    const RigOptions& Options() const { return options_; }

    std::uint32_t Control(int k) const {
        return pac::sim::ReadDword(plc_.ToPac().Module12(layout_.AxisOffset(k)), 0);
    }
    bool Final(int k) { return pac::test::IsFinal(Fb(k)); }

    void Scan(int n = 1) { plc_.Scan(n); }
    int ScansFor(int ms) const { return options_.timing.ScansFor(milliseconds(ms)); }
    void ScanMs(int ms) { Scan(ScansFor(ms)); }
    int ScanUntil(const std::function<bool()>& predicate, int maxScans) { return plc_.ScanUntil(predicate, maxScans); }
    // Scans until the predicate holds, at most `ms` of simulated time; false (with the reason) if it never did.
    ::testing::AssertionResult WaitFor(const std::function<bool()>& predicate, int ms, const std::string& what) {
        if (ScanUntil(predicate, ScansFor(ms)) > 0) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << what << " not within " << ms << " ms (scan " << ScanCount() << ")";
    }

    void SetJob(int k, const Job& job) {
        Fb(k)->COMMAND.value = job.command;
        Fb(k)->POSITION.value = job.position;
        Fb(k)->VELOCITY.value = static_cast<UINT>(job.velocity);
        Fb(k)->ACCELERATION.value = static_cast<UINT>(job.acceleration);
        Fb(k)->CONDITION.value = job.condition;
    }

    // Execute edge with `job` (the next scan sees it), then scans until a final output (Execute stays TRUE).
    Outcome StartAndWait(int k, const Job& job, int maxMs = 3000) {
        SetJob(k, job);
        Outcome o;
        o.mark = Trace(k).Mark();
        Fb(k)->EXECUTE.value = TRUE;
        Scan();
        o.edgeTime = Now();
        static_cast<pac::test::FinalOutcome&>(o) = pac::test::RunToFinal(Fb(k), ScanCount(), [this] {
            Scan();
            return ScanCount();
        }, ScansFor(maxMs));
        return o;
    }

    // A whole job as a PLC program runs it: edge, wait, Execute back to FALSE for one scan (in which the final
    // output clears: the PLCopen checker).
    Outcome Run(int k, const Job& job, int maxMs = 3000) {
        Outcome o = StartAndWait(k, job, maxMs);
        Fb(k)->EXECUTE.value = FALSE;
        Scan();
        return o;
    }

    float Position(int k) { return Fb(k)->ACTUALPOSITION.value; }

    // Every Start edge the FB sent was one job the PA-CONTROL recognised: `jobs` edges, none while ACTIVE.
    void ExpectJobsSeen(int k, int jobs) {
        EXPECT_EQ(view_.StartEdges(k), jobs) << "axis " << k << ": Start edges seen by the PA-CONTROL";
        EXPECT_EQ(view_.LostEdges(k), 0) << "axis " << k << ": Start edges that came while ACTIVE";
    }

private:
    void Record() {
        view_.Follow(plc_.Controller().Log());
        const std::int64_t scan = plc_.Task().ScanCount();
        for (int k = 1; k <= options_.axes; ++k) {
            const std::uint32_t control = Control(k);
            const char* broken = pac::test::AxisControlWordViolation(control, ac::kTraverseBits, ac::kStart);
            if (broken != nullptr && ++controlViolations_ <= 5) {
                ADD_FAILURE() << "axis " << k << ", scan " << scan << ": " << broken << " (control word 16#"
                              << std::hex << control << std::dec << ")";
            }
            const AxisStep step{control, Fb(k)->STATUSWORD.value, pac::test::OutputsOf(Fb(k)).Letter()};
            traces_[static_cast<std::size_t>(k - 1)].Add(scan, step);
        }
    }

    RigOptions options_;
    pac::sim::ModuleLayout layout_;
    pac::PacRig plc_;
    pac::FbInstance<FB_PAC_CTRL> ctrl_ = PAC_FB(FB_PAC_CTRL);
    std::vector<std::unique_ptr<AxisFb>> axes_;  // never moved: the PLC's programs hold references
    std::vector<AxisTrace> traces_;
    pac::test::PlcOpenWatch rules_{options_.timing.PlcCycle()};
    int controlViolations_ = 0;
    ControllerView view_;
    pac::TraceRecorder recording_;
    pac::ScopedVcdDump dump_{recording_.Recording(), pac::test::BusTimingName({options_.timing, 0})};
};

// Axis parameters 8 / 9 (traverse range) and the limit switches (machine positions) of axis k.
void SetRange(AxisSimRig& rig, int k, float min, float max) {
    auto& parameters = rig.Pac().Axes().Parameters(k);
    ASSERT_EQ(parameters.Set(pac::sim::axisparam::kMinTraverseArea, pac::test::BitsOf(min)),
              pac::sim::ParameterTable::SetResult::kOk);
    ASSERT_EQ(parameters.Set(pac::sim::axisparam::kMaxTraverseArea, pac::test::BitsOf(max)),
              pac::sim::ParameterTable::SetResult::kOk);
    ASSERT_TRUE(rig.Pac().Axes().ApplyParameters(k));
}

AxisStep S(std::uint32_t control, std::uint32_t status, char output) { return {control, status, output}; }

// ---------------------------------------------------------------------------------------------------
// Every timing of the FB_PAC_Cmd simulator tests: PLC cycle x PA-CONTROL cycle x latency.

struct AxisSimCase {
    BusTiming timing;
    AxisReading reading;
};

std::string Describe(const AxisReading& r) {
    return std::string(r.ActiveOnlyWhenTraversing() ? "ACTIVE for traversing jobs only" : "ACTIVE for every job") +
           (r.E525() ? ", unreferenced: E525" : ", unreferenced: CMD error 43") +
           (r.ContinuesAfterAxisOn() ? ", interrupted traverse continued after Axis ON" : "");
}

void PrintTo(const AxisSimCase& c, std::ostream* out) {
    *out << pac::test::Describe(c.timing) << "; " << Describe(c.reading);
}

std::string AxisSimCaseName(const ::testing::TestParamInfo<AxisSimCase>& info) {
    return pac::test::BusTimingName({info.param.timing, info.index});
}

std::vector<AxisSimCase> OnReading(const AxisReading& reading) {
    std::vector<AxisSimCase> cases;
    for (const BusTiming& t : pac::test::StandardBusTimings()) cases.push_back({t, reading});
    return cases;
}

class AxisSimTiming : public ::testing::TestWithParam<AxisSimCase> {
protected:
    RigOptions Options() const {
        RigOptions o;
        o.timing = GetParam().timing;
        o.reading = GetParam().reading;
        return o;
    }
    const AxisReading& Reading() const { return GetParam().reading; }
    // Every failure names the bus timing and the reading.
    void SetUp() override {
        std::ostringstream what;
        PrintTo(GetParam(), &what);
        trace_ = std::make_unique<::testing::ScopedTrace>(__FILE__, __LINE__, what.str());
    }
    void TearDown() override { trace_.reset(); }

private:
    std::unique_ptr<::testing::ScopedTrace> trace_;
};

// ---- the four sequences of 2.7.9 ----------------------------------------------------------------------

TEST_P(AxisSimTiming, AxisOnOff_2_7_9_1_InEveryEnableMode) {
    struct Mode {
        EnableMode mode;
        std::uint32_t off;  // the status word with Axis ON = 0
        const char* name;
    };
    const Mode modes[] = {
        {EnableMode::kHalt, as::kHalt | as::kReferenced | kFree, "HALT"},                            // 0x702
        {EnableMode::kIdle, as::kDriveDisabled | as::kIdle | as::kReferenced | kFree, "IDLE"},       // 0x714
        {EnableMode::kSafe, as::kDriveDisabled | as::kSafe | as::kReferenced | kFree, "SAFE"},       // 0x70C
    };
    constexpr std::uint32_t kDisabledStatus = as::kDriveDisabled | as::kDisabled | as::kReferenced | kFree;  // 0x724
    for (const Mode& m : modes) {
        SCOPED_TRACE(m.name);
        RigOptions o = Options();
        o.enableMode = m.mode;
        AxisSimRig rig(o);
        rig.GoOnline();
        auto& fb = rig.Fb(1);
        const std::size_t mark = rig.Trace(1).Mark();
        fb->ENABLE.value = FALSE;
        ASSERT_TRUE(rig.WaitFor([&] { return fb->STATUSWORD.value == m.off; }, 200, "Axis OFF"));
        EXPECT_FALSE(fb->ENABLED.value);
        EXPECT_EQ(fb->HALTED.value != 0, m.mode == EnableMode::kHalt);
        EXPECT_EQ(fb->IDLE.value != 0, m.mode == EnableMode::kIdle);
        EXPECT_EQ(fb->SAFE.value != 0, m.mode == EnableMode::kSafe);
        EXPECT_EQ(fb->DRIVEDISABLED.value != 0, m.mode != EnableMode::kHalt);
        rig.ScanMs(20);
        fb->ENABLE.value = TRUE;
        ASSERT_TRUE(rig.WaitFor([&] { return fb->ENABLED.value != 0; }, 200, "Axis ON"));
        rig.ScanMs(20);
        fb->DISABLEDRIVE.value = TRUE;
        ASSERT_TRUE(rig.WaitFor([&] { return fb->DISABLED.value != 0; }, 200, "DISABLED"));
        EXPECT_TRUE(fb->DRIVEDISABLED.value);
        rig.ScanMs(20);
        fb->DISABLEDRIVE.value = FALSE;
        ASSERT_TRUE(rig.WaitFor([&] { return fb->ENABLED.value != 0; }, 200, "Axis ON again"));
        rig.ScanMs(20);
        const Steps expected = {S(kOn, kOnReferenced, '-'),
                                S(0, kOnReferenced, '-'),
                                S(0, m.off, '-'),
                                S(kOn, m.off, '-'),
                                S(kOn, kOnReferenced, '-'),
                                S(kOn | ac::kDisableDrive, kOnReferenced, '-'),
                                S(kOn | ac::kDisableDrive, kDisabledStatus, '-'),
                                S(kOn, kDisabledStatus, '-'),
                                S(kOn, kOnReferenced, '-')};
        EXPECT_EQ(rig.Trace(1).Since(mark), expected) << Show(rig.Trace(1).Since(mark));
        rig.ExpectJobsSeen(1, 0);
    }
}

TEST_P(AxisSimTiming, Referencing_2_7_9_2) {
    RigOptions o = Options();
    o.referenced = false;
    AxisSimRig rig(o);
    rig.GoOnline();
    EXPECT_FALSE(rig.Fb(1)->REFERENCED.value);
    const Outcome home = rig.Run(1, {kHome});
    ASSERT_TRUE(home.Done()) << home;
    // G25 with the axis parameters: search negative to the cam edge (machine -20), creep back, load 0 there,
    // brake 0.5 AE past it (docs/sim_axis.md, homing mode 0).
    const Steps expected = {S(kOn, kOnUnreferenced, '-'),
                            S(kOn | ac::kStart | ac::kHome, kOnUnreferenced, 'B'),
                            S(kOn | ac::kHome, kOnUnreferenced | as::kActive, 'B'),
                            S(kOn | ac::kHome, kOnActive, 'B'),
                            S(kOn, kOnReferenced, 'D'),
                            S(kOn, kOnReferenced, '-')};
    EXPECT_EQ(rig.Trace(1).Since(home.mark), expected) << Show(rig.Trace(1).Since(home.mark));
    EXPECT_TRUE(rig.Fb(1)->REFERENCED.value);
    EXPECT_EQ(rig.Position(1), 0.5f);
    rig.ExpectJobsSeen(1, 1);
}

TEST_P(AxisSimTiming, RelativeTraversing_2_7_9_3_InBothFormats) {
    for (const bool integer : {false, true}) {
        SCOPED_TRACE(integer ? "integer format" : "IEEE format");
        AxisSimRig rig(Options());
        rig.GoOnline(integer);
        const Outcome move = rig.Run(1, {kRelative, 37.625f});
        ASSERT_TRUE(move.Done()) << move;
        const Steps expected = {S(kOn, kOnReferenced, '-'),
                                S(kOn | ac::kStart | ac::kMoveRelative, kOnReferenced, 'B'),
                                S(kOn | ac::kMoveRelative, kOnActive, 'B'),
                                S(kOn, kOnReferenced, 'D'),
                                S(kOn, kOnReferenced, '-')};
        EXPECT_EQ(rig.Trace(1).Since(move.mark), expected) << Show(rig.Trace(1).Since(move.mark));
        EXPECT_EQ(rig.Position(1), 37.625f);
        EXPECT_EQ(rig.Motion(1).Position(), 37.625);
        // The position bytes on the wire, in the format in force (2.5.3): 37.625 or 37625.
        const pac::sim::Image12 reply = rig.Plc().FromPac().Module12(16);
        EXPECT_EQ(pac::sim::ReadDword(reply, 8), integer ? 37625u : pac::test::BitsOf(37.625f));
        const pac::sim::Image12 sent = rig.Plc().ToPac().Module12(16);
        EXPECT_EQ(pac::sim::ReadDword(sent, 8), integer ? 37625u : pac::test::BitsOf(37.625f));
        rig.ExpectJobsSeen(1, 1);
    }
}

TEST_P(AxisSimTiming, RelativeTraversingWithLimitSwitchError_2_7_9_4) {
    AxisSimRig rig(Options());
    rig.Pac().Axes().SetLimitSwitches(1, -50.0, 60.0);
    rig.GoOnline();
    auto& fb = rig.Fb(1);
    // The move runs into the positive limit switch: the axis stops on it at once with axis error 64 (FAULT,
    // axis error bit, HALT, the switch bit 0); the job ends with 16#800A and the number in AxisErrorNumber.
    const Outcome move = rig.StartAndWait(1, {kRelative, 100.0f});
    ASSERT_TRUE(move.Error()) << move;
    EXPECT_EQ(move.ErrorId(), kErrAxisError);
    constexpr std::uint32_t kOnSwitch = as::kDriveEnabled | as::kHalt | as::kReferenced | as::kNegativeLimitNotActuated;
    constexpr std::uint32_t kFault = kOnSwitch | as::kFault | as::kAxisError;  // 0x8343
    const Steps expected = {S(kOn, kOnReferenced, '-'),
                            S(kOn | ac::kStart | ac::kMoveRelative, kOnReferenced, 'B'),
                            S(kOn | ac::kMoveRelative, kOnActive, 'B'),
                            S(kOn, kFault, 'E')};
    EXPECT_EQ(rig.Trace(1).Since(move.mark), expected) << Show(rig.Trace(1).Since(move.mark));
    EXPECT_TRUE(fb->AXISERROR.value);
    EXPECT_TRUE(fb->FAULT.value);
    EXPECT_EQ(fb->AXISERRORNUMBER.value, kLimitSwitch);
    EXPECT_TRUE(fb->POSITIVELIMITACTUATED.value);
    EXPECT_FALSE(fb->NEGATIVELIMITACTUATED.value);
    EXPECT_EQ(rig.Position(1), 60.0f) << "stopped on the switch";
    fb->EXECUTE.value = FALSE;
    rig.Scan();
    // A job while the axis error is pending: refused at the edge, nothing sent.
    Outcome refused = rig.Run(1, {kRelative, -10.0f});
    EXPECT_EQ(refused.ErrorId(), kErrAxisError);
    EXPECT_EQ(refused.finalScan, refused.edgeScan);
    // ResetError: bit 16 until the axis error bit is seen 0.
    std::size_t mark = rig.Trace(1).Mark();
    fb->RESETERROR.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return !fb->AXISERROR.value; }, 300, "axis error reset"));
    rig.ScanMs(20);
    fb->RESETERROR.value = FALSE;
    rig.Scan();
    const Steps reset = {S(kOn, kFault, '-'), S(kOn | ac::kResetAxisError, kFault, '-'), S(kOn, kOnSwitch, '-')};
    EXPECT_EQ(rig.Trace(1).Since(mark), reset) << Show(rig.Trace(1).Since(mark));
    EXPECT_EQ(fb->AXISERRORNUMBER.value, 0);
    // Further into the switch: refused (CMD error 64); away from it: moves.
    const Outcome further = rig.Run(1, {kRelative, 10.0f});
    ASSERT_TRUE(further.Error()) << further;
    EXPECT_EQ(further.ErrorId(), kLimitSwitch);
    const Steps refusal = {S(kOn, kOnSwitch, '-'),
                           S(kOn | ac::kStart | ac::kMoveRelative, kOnSwitch, 'B'),
                           S(kOn, kOnSwitch | as::kCmdError, 'E'),
                           S(kOn, kOnSwitch | as::kCmdError, '-')};
    EXPECT_EQ(rig.Trace(1).Since(further.mark), refusal) << Show(rig.Trace(1).Since(further.mark));
    EXPECT_TRUE(fb->CMDERROR.value);
    EXPECT_EQ(fb->CMDERRORNUMBER.value, kLimitSwitch);
    const Outcome away = rig.Run(1, {kRelative, -30.0f});
    ASSERT_TRUE(away.Done()) << away;
    EXPECT_EQ(rig.Position(1), 30.0f);
    EXPECT_FALSE(fb->POSITIVELIMITACTUATED.value);
    EXPECT_FALSE(fb->CMDERROR.value) << "cleared by the Start edge of the good job (2.7.4.14)";
    rig.ExpectJobsSeen(1, 3);
}

// ---- every command, both formats ------------------------------------------------------------------------

TEST_P(AxisSimTiming, EveryCommandInBothFormats) {
    for (const bool integer : {false, true}) {
        SCOPED_TRACE(integer ? "integer format" : "IEEE format");
        RigOptions o = Options();
        o.referenced = false;
        AxisSimRig rig(o);
        SetRange(rig, 1, -50.0f, 150.0f);
        rig.Pac().Axes().SetLimitSwitches(1, -80.0, 180.0);
        rig.GoOnline(integer);
        auto& fb = rig.Fb(1);
        auto run = [&](const Job& job) {
            const Outcome outcome = rig.Run(1, job);
            EXPECT_TRUE(outcome.Done()) << "command " << job.command << " " << job.position << ": " << outcome;
            return outcome;
        };
        run({kHome});
        EXPECT_TRUE(fb->REFERENCED.value);
        EXPECT_EQ(rig.Position(1), 0.5f);
        run({kAbsolute, 100.0f, 800, 2000});
        EXPECT_EQ(rig.Position(1), 100.0f);
        // The job as the PA-CONTROL took it over with the Start edge: data, bit and Start in one image (2.3.3).
        ASSERT_EQ(rig.View().Jobs(1).size(), 2u);
        const pac::sim::AxisModuleCommand job = rig.View().Jobs(1).back();
        EXPECT_EQ(job.control, kOn | ac::kStart | ac::kMoveAbsolute);
        EXPECT_EQ(job.speedPerMille, 800);
        EXPECT_EQ(job.accelerationPerMille, 2000);
        EXPECT_EQ(job.position, integer ? 100000u : pac::test::BitsOf(100.0f));
        run({kRelative, -20.5f, 500, 500});
        EXPECT_EQ(rig.Position(1), 79.5f);
        run({kToMax});
        EXPECT_EQ(rig.Position(1), 150.0f) << "axis parameter 9";
        run({kToMin, 0.0f, 1000, 3000});
        EXPECT_EQ(rig.Position(1), -50.0f) << "axis parameter 8";
        run({kAbsolute, 100.0f});
        // G29: the position becomes 125.25 and the software limits move with it (2.7.3.5): -24.75..175.25.
        run({kSetPosition, 125.25f});
        EXPECT_EQ(rig.View().Jobs(1).back().position, integer ? 125250u : pac::test::BitsOf(125.25f));
        EXPECT_EQ(rig.Position(1), 125.25f);
        EXPECT_EQ(rig.Motion(1).MaxRange(), 175.25);
        EXPECT_TRUE(fb->REFERENCED.value) << "G29 leaves the reference as it is";
        run({kToMax});
        EXPECT_EQ(rig.Position(1), 175.25f) << "the maximum shifted by G29";
        Outcome outside = rig.Run(1, {kAbsolute, 180.0f});
        EXPECT_EQ(outside.ErrorId(), kPositionRange) << outside;
        run({kAbsolute, -24.75f});
        EXPECT_EQ(rig.Position(1), -24.75f) << "the minimum shifted by G29";
        // Delete the G29 offsets: position and limits back by 25.25.
        run({kClearOffset});
        EXPECT_EQ(rig.Position(1), -50.0f);
        EXPECT_EQ(rig.Motion(1).MaxRange(), 150.0);
        outside = rig.Run(1, {kAbsolute, 160.0f});
        EXPECT_EQ(outside.ErrorId(), kPositionRange) << outside;
        run({kAbsolute, 100.0f});
        // G26: position 10, referenced, the limits as they are (2.7.3.4).
        run({kSetReferenced, 10.0f});
        EXPECT_EQ(rig.Position(1), 10.0f);
        EXPECT_EQ(rig.Motion(1).MinRange(), -50.0);
        run({kToMin});
        EXPECT_EQ(rig.Position(1), -50.0f);
        run({kClearDisplaced});
        EXPECT_EQ(rig.Position(1), -50.0f);
        EXPECT_EQ(rig.Motion(1).Position(), -50.0);
        rig.ExpectJobsSeen(1, 16);
    }
}

TEST_P(AxisSimTiming, DisplacedWhileOffAndClearDisplaced) {
    RigOptions o = Options();
    o.enableMode = EnableMode::kIdle;
    AxisSimRig rig(o);
    rig.GoOnline();
    auto& fb = rig.Fb(1);
    fb->ENABLE.value = FALSE;
    ASSERT_TRUE(rig.WaitFor([&] { return fb->IDLE.value != 0; }, 200, "IDLE"));
    ASSERT_TRUE(rig.Pac().Axes().Displace(1, rig.Now(), 5.0));
    fb->ENABLE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return fb->ENABLED.value != 0; }, 200, "Axis ON"));
    EXPECT_TRUE(fb->DISPLACEDWHILEOFF.value);
    EXPECT_TRUE(fb->GROUPDISPLACEDWHILEOFF.value);
    EXPECT_EQ(rig.Position(1), 5.0f) << "the displaced position is taken over";
    const Outcome refused = rig.Run(1, {kRelative, 1.0f});
    EXPECT_EQ(refused.ErrorId(), kAxisDisplaced) << refused;
    const Outcome clear = rig.Run(1, {kClearDisplaced});
    EXPECT_TRUE(clear.Done()) << clear;
    EXPECT_FALSE(fb->DISPLACEDWHILEOFF.value);
    EXPECT_FALSE(fb->GROUPDISPLACEDWHILEOFF.value);
    const Outcome move = rig.Run(1, {kRelative, 1.0f});
    EXPECT_TRUE(move.Done()) << move;
    EXPECT_EQ(rig.Position(1), 6.0f);
    rig.ExpectJobsSeen(1, 3);
}

// ---- CMD errors, both restart styles --------------------------------------------------------------------

TEST_P(AxisSimTiming, CmdErrorsAndRecoveryOnBothRestartStyles) {
    for (const CmdErrorRestart style : {CmdErrorRestart::kSameCycle, CmdErrorRestart::kOneCycleClear}) {
        SCOPED_TRACE(style == CmdErrorRestart::kSameCycle ? "kSameCycle" : "kOneCycleClear");
        RigOptions o = Options();
        o.referenced = false;
        o.cmdErrorRestart = style;
        AxisSimRig rig(o);
        rig.GoOnline();
        auto& fb = rig.Fb(1);
        auto expectError = [&](const Job& job, std::uint32_t number) {
            const Outcome outcome = rig.Run(1, job);
            EXPECT_TRUE(outcome.Error()) << outcome;
            EXPECT_EQ(outcome.ErrorId(), number) << outcome;
            EXPECT_EQ(fb->CMDERRORNUMBER.value, number);
            EXPECT_TRUE(fb->CMDERROR.value);
        };
        auto expectDone = [&](const Job& job) {
            const Outcome outcome = rig.Run(1, job);
            EXPECT_TRUE(outcome.Done()) << outcome;
        };
        // Unreferenced: CMD error 43, or system error E525 as an axis error (the 2.7.2 note), whose number the FB
        // passes through unchanged; ResetError clears the axis error for the next job.
        auto expectNoReference = [&] {
            if (!Reading().E525()) return expectError({kAbsolute, 10.0f}, kNoReference);
            const Outcome outcome = rig.StartAndWait(1, {kAbsolute, 10.0f});
            EXPECT_TRUE(outcome.Error()) << outcome;
            EXPECT_EQ(outcome.ErrorId(), kE525) << outcome;
            EXPECT_EQ(fb->ERRORSOURCE.value, E_PAC_ERRORSOURCE__PAC_ERRSRC_SYSTEM);
            EXPECT_EQ(fb->AXISERRORNUMBER.value, kE525);
            EXPECT_FALSE(fb->CMDERROR.value);
            fb->EXECUTE.value = FALSE;
            fb->RESETERROR.value = TRUE;
            ASSERT_TRUE(rig.WaitFor([&] { return !fb->AXISERROR.value; }, 300, "E525 reset"));
            fb->RESETERROR.value = FALSE;
            rig.Scan();
        };
        // 43 twice in a row with the same number, then good: G26, which the stale 43 must not fail.
        expectNoReference();
        expectNoReference();
        EXPECT_EQ(rig.Position(1), 0.0f);
        expectDone({kSetReferenced, 0.0f});
        EXPECT_FALSE(fb->CMDERROR.value);
        expectDone({kAbsolute, 10.0f});
        EXPECT_EQ(rig.Position(1), 10.0f);
        // 55: the job goes out with Axis ON 0 and the PA-CONTROL refuses it; twice, then good.
        fb->ENABLE.value = FALSE;
        rig.ScanMs(30);
        expectError({kRelative, 5.0f}, kAxisOff);
        expectError({kRelative, 5.0f}, kAxisOff);
        fb->ENABLE.value = TRUE;
        rig.ScanMs(30);
        // 65 after 55 (another number), twice, then a good one after the same failed job.
        expectError({kAbsolute, 20000.0f}, kPositionRange);
        expectError({kAbsolute, 20000.0f}, kPositionRange);
        expectDone({kRelative, 5.0f});
        EXPECT_EQ(rig.Position(1), 15.0f);
        // Failed, good, failed with the same number: the good job cleared the bit in between.
        expectError({kAbsolute, -1.0f}, kPositionRange);
        expectDone({kAbsolute, 12.0f});
        expectError({kAbsolute, -1.0f}, kPositionRange);
        EXPECT_EQ(rig.Position(1), 12.0f);
        rig.ExpectJobsSeen(1, 12);
    }
}

// ---- axis errors and ResetError -------------------------------------------------------------------------

TEST_P(AxisSimTiming, FollowingErrorOfABlockedAxisAndItsReset) {
    AxisSimRig rig(Options());
    rig.GoOnline();
    auto& fb = rig.Fb(1);
    const Outcome start = rig.StartAndWait(1, {kAbsolute, 200.0f}, 60);
    ASSERT_FALSE(start.Done() || start.Error() || start.Aborted()) << start;
    ASSERT_TRUE(rig.WaitFor([&] { return fb->ACTIVE.value != 0; }, 200, "ACTIVE"));
    rig.Pac().Axes().SetBlocked(1, rig.Now(), true);
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 300, "final output"));
    EXPECT_TRUE(fb->ERROR.value);
    EXPECT_EQ(fb->ERRORID.value, kErrAxisError);
    EXPECT_EQ(fb->AXISERRORNUMBER.value, kFollowingError);
    EXPECT_TRUE(fb->FAULT.value);
    EXPECT_EQ(rig.Control(1), kOn) << "Start and the traverse bit off";
    fb->EXECUTE.value = FALSE;
    rig.Scan();
    rig.Pac().Axes().SetBlocked(1, rig.Now(), false);
    fb->RESETERROR.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return !fb->AXISERROR.value && (rig.Control(1) & ac::kResetAxisError) == 0; },
                              300, "reset"));
    fb->RESETERROR.value = FALSE;
    const float stoppedAt = rig.Position(1);
    EXPECT_LT(stoppedAt, 200.0f);
    const Outcome move = rig.Run(1, {kAbsolute, 200.0f});
    EXPECT_TRUE(move.Done()) << move;
    EXPECT_EQ(rig.Position(1), 200.0f);
    rig.ExpectJobsSeen(1, 2);
}

TEST_P(AxisSimTiming, DisturbanceKeepsTheAxisErrorUntilItsCauseIsGone) {
    AxisSimRig rig(Options());
    rig.GoOnline();
    auto& fb = rig.Fb(1);
    rig.Pac().Axes().SetDisturbance(1, rig.Now(), 5.0);
    ASSERT_TRUE(rig.WaitFor([&] { return fb->AXISERROR.value != 0; }, 200, "axis error"));
    EXPECT_EQ(fb->AXISERRORNUMBER.value, kFollowingError);
    // The reset is refused while the cause persists: the pulse ends after Timeout, the error stays.
    fb->RESETERROR.value = TRUE;
    rig.Scan();
    ASSERT_NE(rig.Control(1) & ac::kResetAxisError, 0u);
    ASSERT_TRUE(rig.WaitFor([&] { return (rig.Control(1) & ac::kResetAxisError) == 0; }, 1500, "pulse ended"));
    EXPECT_TRUE(fb->AXISERROR.value);
    fb->RESETERROR.value = FALSE;
    rig.Scan();
    const Outcome refused = rig.Run(1, {kRelative, 1.0f});
    EXPECT_EQ(refused.ErrorId(), kErrAxisError) << refused;
    EXPECT_EQ(refused.finalScan, refused.edgeScan) << "refused at the edge, nothing sent";
    rig.Pac().Axes().SetDisturbance(1, rig.Now(), 0.0);
    fb->RESETERROR.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return !fb->AXISERROR.value; }, 300, "axis error reset"));
    fb->RESETERROR.value = FALSE;
    const Outcome move = rig.Run(1, {kRelative, 1.0f});
    EXPECT_TRUE(move.Done()) << move;
    EXPECT_EQ(rig.Position(1), 1.0f);
    rig.ExpectJobsSeen(1, 1);
}

// ResetError when ONLINE ends (issue 32, item 8): outside ONLINE the PA-CONTROL acts on no control word (2.7.2
// notes), and on the AUTOMATIC layout FW2_N4 bit 16 is flag M1. An axis error whose cause stays keeps the pulse
// on; the program CANCELs ONLINE and, with `pressAgain`, presses ResetError again in the scan the controller
// leaves ONLINE: the FB, still seeing ONLINE, drops the running pulse and holds the new one back for the update
// time (10 ms). From the first call that sees a status outside ONLINE, bit 16 never goes out, neither the
// running pulse nor the edge held back; nor once ONLINE is back.
void ResetPulseWhenOnlineEnds(AxisSimRig& rig, bool pressAgain, bool& heldBackWhenSeen) {
    auto& fb = rig.Fb(1);
    auto& ctrl = rig.Ctrl();
    rig.Pac().Axes().SetDisturbance(1, rig.Now(), 5.0);
    ASSERT_TRUE(rig.WaitFor([&] { return fb->AXISERROR.value != 0; }, 200, "axis error"));
    fb->RESETERROR.value = TRUE;
    rig.Scan();
    ASSERT_NE(rig.Control(1) & ac::kResetAxisError, 0u) << "the pulse, the cause persisting";
    fb->RESETERROR.value = FALSE;
    rig.Scan();
    ctrl->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_CANCEL;
    ctrl->EXECUTE.value = TRUE;
    auto online = [](int status) { return status >= 30 && status <= 39; };
    int known = 31;  // the last status other than 0 the FB was given
    std::optional<std::int64_t> pressScan;
    bool seen = false;
    for (int i = 0; i < rig.ScansFor(300); ++i) {
        if (pressAgain && !pressScan && !online(rig.Pac().OperatingStatus())) {
            fb->RESETERROR.value = TRUE;
            pressScan = rig.ScanCount() + 1;
        }
        rig.Scan();
        if (fb->OPSTATUS.value != 0) known = fb->OPSTATUS.value;
        if (!online(known) && !seen) {
            seen = true;
            // The edge was seen in ONLINE (a scan before this one) and its 10 ms of bit 16 low had not passed: it
            // was held back when ONLINE ended.
            const std::int64_t since = pressScan ? rig.ScanCount() - *pressScan : 0;
            heldBackWhenSeen = since > 0 && since * rig.Options().timing.plcMs < 10;
        }
        if (!online(known)) {
            ASSERT_EQ(rig.Control(1) & ac::kResetAxisError, 0u)
                << "bit 16 on the wire in status " << known << ", scan " << rig.ScanCount();
        }
    }
    ASSERT_TRUE(seen) << "ONLINE cancelled";
    ASSERT_TRUE(ctrl->DONE.value) << "CANCEL: ErrorID 16#" << std::hex << ctrl->ERRORID.value;
    ctrl->EXECUTE.value = FALSE;
    rig.Scan();
    ctrl->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
    ctrl->EXECUTE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return ctrl->DONE.value || ctrl->ERROR.value; }, 500, "ONLINE again"));
    ctrl->EXECUTE.value = FALSE;
    for (int i = 0; i < rig.ScansFor(100); ++i) {
        rig.Scan();
        ASSERT_EQ(rig.Control(1) & ac::kResetAxisError, 0u) << "an old edge or pulse, ONLINE again, scan " << i;
    }
}

TEST_P(AxisSimTiming, NoResetPulseOnTheWireOnceOnlineEnded) {
    const BusTiming& t = GetParam().timing;
    for (const bool pressAgain : {false, true}) {
        SCOPED_TRACE(pressAgain ? "pressed again as ONLINE ends" : "the pulse running as ONLINE ends");
        AxisSimRig rig(Options());
        rig.GoOnline();
        bool heldBack = false;
        ResetPulseWhenOnlineEnds(rig, pressAgain, heldBack);
        if (HasFatalFailure()) return;
        // Reachability: the press comes in the scan after the controller's change, which reaches the FB `latency`
        // scans after the change; from a latency of 2 the FB sees the press in ONLINE, and within the update time
        // the new status, so the edge is held back then.
        if (pressAgain && t.latency >= 2 && (t.latency - 1) * t.plcMs <= 5) {
            EXPECT_TRUE(heldBack);
        }
    }
}

// ---- interruptions: Abort, Enable, link, a new job -----------------------------------------------------

// A long move under way (0 -> 400, 1000 AE/s), taken over and running.
void StartLongMove(AxisSimRig& rig, Outcome& started) {
    started = rig.StartAndWait(1, {kAbsolute, 400.0f}, 150);
    ASSERT_FALSE(started.Done() || started.Error() || started.Aborted()) << started;
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Position(1) > 20.0f; }, 300, "moving"));
    ASSERT_TRUE(rig.Fb(1)->ACTIVE.value);
}

TEST_P(AxisSimTiming, AbortMidMoveThenANewJob) {
    AxisSimRig rig(Options());
    rig.GoOnline();
    auto& fb = rig.Fb(1);
    Outcome started;
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig, started));
    fb->ABORT.value = TRUE;
    rig.Scan();
    EXPECT_EQ(rig.Control(1), kOn) << "the traverse bit goes off in the Abort scan";
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 500, "final output"));
    EXPECT_TRUE(fb->COMMANDABORTED.value);
    EXPECT_TRUE(fb->HALTED.value) << "the axis stands: HALT";
    EXPECT_FALSE(fb->ACTIVE.value);
    EXPECT_FALSE(rig.Motion(1).Moving());
    const float stoppedAt = rig.Position(1);
    EXPECT_LT(stoppedAt, 400.0f);
    EXPECT_EQ(stoppedAt, static_cast<float>(rig.Motion(1).Position()));
    fb->ABORT.value = FALSE;
    fb->EXECUTE.value = FALSE;
    rig.Scan();
    const Outcome next = rig.Run(1, {kRelative, -10.0f});
    EXPECT_TRUE(next.Done()) << next;
    EXPECT_NEAR(rig.Position(1), stoppedAt - 10.0f, 1e-3);
    EXPECT_FALSE(fb->HALTED.value);
    rig.ExpectJobsSeen(1, 2);
}

// A stop lasts as long as the axis brakes: with 50 per mille of the axis parameter acceleration (500 units/s²)
// from 600 units/s the axis brakes for 1.2 s, longer than Timeout (1 s). The job ends when ACTIVE has fallen,
// and StopTimeout shorter than the braking ends it with its own error while the axis still moves.
TEST_P(AxisSimTiming, StopEndsWhenActiveFallsAndStopTimeoutBoundsIt) {
    for (const bool bounded : {false, true}) {
        SCOPED_TRACE(bounded ? "StopTimeout 500 ms" : "StopTimeout default");
        AxisSimRig rig(Options());
        rig.GoOnline();
        auto& fb = rig.Fb(1);
        if (bounded) fb->STOPTIMEOUT.value = pac::ToIecTime(milliseconds(500));
        const Outcome started = rig.StartAndWait(1, {kAbsolute, 5000.0f, 1000, 50}, 100);
        ASSERT_FALSE(started.Done() || started.Error() || started.Aborted()) << started;
        ASSERT_TRUE(rig.WaitFor([&] { return rig.Motion(1).ActualSpeed() >= 600.0; }, 1500, "600 units/s"));
        fb->ABORT.value = TRUE;
        const nanoseconds abortAt = rig.Now();
        ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 3000, "final output"));
        if (bounded) {
            EXPECT_TRUE(fb->ERROR.value);
            EXPECT_EQ(fb->ERRORID.value, kErrStopTimeout);
            EXPECT_TRUE(fb->ACTIVE.value) << "the axis still brakes";
            EXPECT_TRUE(rig.Motion(1).Moving());
            ASSERT_TRUE(rig.WaitFor([&] { return !fb->ACTIVE.value; }, 1500, "the axis stands"));
        } else {
            EXPECT_TRUE(fb->COMMANDABORTED.value);
            EXPECT_GT(rig.Now() - abortAt, milliseconds(1000)) << "longer than Timeout";
            EXPECT_FALSE(fb->ACTIVE.value);
            EXPECT_FALSE(rig.Motion(1).Moving());
        }
        fb->ABORT.value = FALSE;
        fb->EXECUTE.value = FALSE;
        rig.Scan();
        const Outcome next = rig.Run(1, {kRelative, -10.0f});
        EXPECT_TRUE(next.Done()) << next;
        rig.ExpectJobsSeen(1, 2);
    }
}

// 2.7.6: a new speed while a move runs, on an axis type that takes it (the move arrives ten times sooner), and
// refused with 16#8023 where the FB is told the axis type cannot, or no move runs (the move unchanged).
TEST_P(AxisSimTiming, SpeedChangeDuringAMoveWhereTheAxisTypeAllowsIt) {
    const auto kNoChange = kGvl["PAC_LIB_ERR_NO_DYNAMICS_CHANGE"];
    for (const bool changeable : {true, false}) {
        SCOPED_TRACE(changeable ? "axis type with speed change" : "axis type without");
        RigOptions o = Options();
        o.speedChange = changeable ? pac::sim::SpeedChange::kWhileTraversing : pac::sim::SpeedChange::kNotWhileTraversing;
        AxisSimRig rig(o);
        rig.GoOnline();
        auto& fb = rig.Fb(1);
        fb->DYNAMICSCHANGEABLE.value = changeable ? TRUE : FALSE;
        fb->VELOCITY.value = 500;
        fb->CHANGEDYNAMICS.value = TRUE;
        rig.Scan();
        EXPECT_TRUE(fb->CHANGEREFUSED.value) << "no move runs";
        EXPECT_EQ(fb->CHANGEERRORID.value, kNoChange);
        fb->CHANGEDYNAMICS.value = FALSE;
        rig.Scan();
        EXPECT_FALSE(fb->CHANGEREFUSED.value);
        const Outcome started = rig.StartAndWait(1, {kAbsolute, 300.0f, 100, 1000}, 100);
        ASSERT_FALSE(started.Done() || started.Error() || started.Aborted()) << started;
        ASSERT_TRUE(rig.WaitFor([&] { return rig.Position(1) > 10.0f; }, 300, "moving at 100 units/s"));
        const nanoseconds changeAt = rig.Now();
        fb->VELOCITY.value = 0;
        fb->CHANGEDYNAMICS.value = TRUE;
        rig.Scan();
        fb->CHANGEDYNAMICS.value = FALSE;
        if (changeable) {
            EXPECT_EQ(fb->CHANGEERRORID.value, kGvl["PAC_LIB_ERR_INVALID_VELOCITY"]);
            rig.Scan();
            fb->VELOCITY.value = 1000;
            fb->ACCELERATION.value = 0;
            fb->CHANGEDYNAMICS.value = TRUE;
            rig.Scan();
            EXPECT_EQ(fb->CHANGEERRORID.value, kGvl["PAC_LIB_ERR_INVALID_ACCELERATION"]);
            fb->CHANGEDYNAMICS.value = FALSE;
            rig.Scan();
            fb->ACCELERATION.value = 1000;
            fb->CHANGEDYNAMICS.value = TRUE;
            rig.Scan();
            EXPECT_TRUE(fb->DYNAMICSCHANGED.value);
            EXPECT_FALSE(fb->CHANGEREFUSED.value);
            EXPECT_EQ(rig.Control(1), kOn | ac::kMoveAbsolute) << "the job's bits as they were, no Start";
        } else {
            EXPECT_EQ(fb->CHANGEERRORID.value, kNoChange) << "the FB knows the axis type cannot";
        }
        ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 4000, "final output"));
        EXPECT_TRUE(fb->DONE.value);
        EXPECT_EQ(rig.Position(1), 300.0f);
        const auto took = rig.Now() - changeAt;
        if (changeable) {
            EXPECT_LT(took, milliseconds(500)) << "about 290 units at 1000 units/s";
        } else {
            EXPECT_GT(took, milliseconds(2500)) << "about 290 units at 100 units/s";
        }
        fb->CHANGEDYNAMICS.value = FALSE;
        fb->EXECUTE.value = FALSE;
        rig.Scan();
        EXPECT_FALSE(fb->DYNAMICSCHANGED.value);
        rig.ExpectJobsSeen(1, 1);
    }
}

TEST_P(AxisSimTiming, EnableFallingMidMoveThenANewJob) {
    AxisSimRig rig(Options());
    rig.GoOnline();
    auto& fb = rig.Fb(1);
    Outcome started;
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig, started));
    fb->ENABLE.value = FALSE;
    rig.Scan();
    EXPECT_EQ(rig.Control(1), 0u) << "Axis ON and the traverse bit off";
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 500, "final output"));
    EXPECT_TRUE(fb->COMMANDABORTED.value);
    EXPECT_TRUE(fb->HALTED.value);
    EXPECT_FALSE(fb->ENABLED.value);
    EXPECT_FALSE(rig.Motion(1).Moving());
    const float stoppedAt = rig.Position(1);
    fb->EXECUTE.value = FALSE;
    fb->ENABLE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return fb->ENABLED.value != 0; }, 200, "Axis ON"));
    if (Reading().ContinuesAfterAxisOn()) {
        // The controller continues the aborted move by itself (2.7.2 note): the FB shows it, without a job.
        ASSERT_TRUE(rig.WaitFor([&] { return fb->ACTIVEWITHOUTJOB.value != 0; }, 200, "ActiveWithoutJob"));
        EXPECT_FALSE(fb->BUSY.value);
        EXPECT_EQ(rig.Control(1), kOn) << "nothing sent for it";
        ASSERT_TRUE(rig.WaitFor([&] { return !fb->ACTIVE.value; }, 1000, "the continued move's end"));
        EXPECT_FALSE(fb->ACTIVEWITHOUTJOB.value);
        EXPECT_EQ(rig.Position(1), 400.0f) << "at the aborted job's target";
    } else {
        rig.ScanMs(100);
        EXPECT_FALSE(fb->ACTIVEWITHOUTJOB.value);
        EXPECT_EQ(rig.Position(1), stoppedAt) << "the aborted move stays ended";
    }
    const Outcome next = rig.Run(1, {kAbsolute, 50.0f});
    EXPECT_TRUE(next.Done()) << next;
    EXPECT_EQ(rig.Position(1), 50.0f);
    EXPECT_NE(stoppedAt, 50.0f);
    rig.ExpectJobsSeen(1, 2);
}

TEST_P(AxisSimTiming, AllZeroLinkOnThePlcSideMidMove) {
    for (const auto fault : {pac::sim::LinkFault::kAllZero, pac::sim::LinkFault::kDisconnected}) {
        SCOPED_TRACE(fault == pac::sim::LinkFault::kAllZero ? "kAllZero" : "kDisconnected");
        AxisSimRig rig(Options());
        rig.GoOnline();
        auto& fb = rig.Fb(1);
        Outcome started;
        ASSERT_NO_FATAL_FAILURE(StartLongMove(rig, started));
        rig.Plc().Bus().FromPacLink().SetFault(rig.Now(), fault);
        ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 200, "final output"));
        EXPECT_TRUE(fb->COMMANDABORTED.value) << "an all-zero module aborts the job at once";
        EXPECT_FALSE(fb->STATUSVALID.value);
        EXPECT_EQ(rig.Control(1), kOn) << "Start and the traverse bit off";
        // The PA-CONTROL still gets the module: it sees the traverse bit go and stops the axis (HALT).
        rig.ScanMs(300);
        EXPECT_FALSE(rig.Motion(1).Moving());
        EXPECT_TRUE(rig.Motion(1).Interrupted());
        EXPECT_EQ(rig.Pac().OperatingStatus(), 31) << "the controller saw no all-zero image";
        fb->EXECUTE.value = FALSE;
        rig.Scan();
        const Outcome whileLost = rig.Run(1, {kRelative, 5.0f});
        EXPECT_EQ(whileLost.ErrorId(), kErrNotReady) << whileLost;
        rig.Plc().Bus().FromPacLink().SetFault(rig.Now(), pac::sim::LinkFault::kNone);
        ASSERT_TRUE(rig.WaitFor([&] { return fb->STATUSVALID.value != 0; }, 200, "link back"));
        EXPECT_TRUE(fb->HALTED.value);
        const float stoppedAt = rig.Position(1);
        EXPECT_EQ(stoppedAt, static_cast<float>(rig.Motion(1).Position()));
        const Outcome next = rig.Run(1, {kRelative, 5.0f});
        EXPECT_TRUE(next.Done()) << next;
        EXPECT_NEAR(rig.Position(1), stoppedAt + 5.0f, 1e-3);
        rig.ExpectJobsSeen(1, 2);
    }
}

TEST_P(AxisSimTiming, NewExecuteEdgeMidMoveAbortsTheOldJobAndRunsTheNewOne) {
    AxisSimRig rig(Options());
    rig.GoOnline();
    auto& fb = rig.Fb(1);
    Outcome started;
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig, started));
    fb->EXECUTE.value = FALSE;
    rig.Scan();
    EXPECT_TRUE(fb->BUSY.value);
    rig.SetJob(1, {kRelative, -30.0f, 500, 1000});
    fb->EXECUTE.value = TRUE;
    rig.Scan();
    EXPECT_TRUE(fb->COMMANDABORTED.value) << "the old job, in the edge scan";
    EXPECT_EQ(rig.Control(1) & ac::kTraverseBits, 0u) << "its traverse bit goes off";
    rig.Scan();
    EXPECT_FALSE(fb->COMMANDABORTED.value) << "for exactly one scan";
    EXPECT_TRUE(fb->BUSY.value) << "the new job owns the outputs";
    // The old move brakes from full speed (50 AE); the new one starts once the axis is free, from where it stands.
    ASSERT_TRUE(rig.WaitFor([&] { return (rig.Control(1) & ac::kStart) != 0; }, 500, "Start of the new job"));
    EXPECT_EQ(rig.Control(1), kOn | ac::kStart | ac::kMoveRelative);
    EXPECT_FALSE(rig.Motion(1).Moving());
    const double stoppedAt = rig.Motion(1).Position();
    EXPECT_GT(stoppedAt, 20.0 + 49.0) << "braked from full speed";
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 1500, "final output"));
    EXPECT_TRUE(fb->DONE.value) << "ErrorID 16#" << std::hex << fb->ERRORID.value;
    EXPECT_NEAR(rig.Position(1), stoppedAt - 30.0, 1e-3);
    fb->EXECUTE.value = FALSE;
    rig.Scan();
    rig.ExpectJobsSeen(1, 2);
}

TEST_P(AxisSimTiming, StopOnlineMidMoveIsCommandAbortedAndJobsWaitForTheResume) {
    AxisSimRig rig(Options());
    rig.GoOnline();
    auto& fb = rig.Fb(1);
    auto& ctrl = rig.Ctrl();
    Outcome started;
    ASSERT_NO_FATAL_FAILURE(StartLongMove(rig, started));
    // STOP ONLINE (CTRL): the PA-CONTROL brakes every axis and interrupts its job; the move ends with HALT, which
    // FB_PAC_Axis reports as CommandAborted (interrupted from outside).
    ctrl->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_STOP;
    ctrl->EXECUTE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 500, "final output"));
    EXPECT_TRUE(fb->COMMANDABORTED.value);
    EXPECT_TRUE(fb->HALTED.value);
    EXPECT_FALSE(rig.Motion(1).Moving());
    ASSERT_TRUE(rig.WaitFor([&] { return ctrl->DONE.value != 0; }, 500, "ONLINE stopped"));
    EXPECT_TRUE(ctrl->ONLINESTOPPED.value);
    ctrl->EXECUTE.value = FALSE;
    fb->EXECUTE.value = FALSE;
    rig.Scan();
    // No jobs while ONLINE is stopped (2.7): refused at the edge, nothing sent.
    const Outcome whileStopped = rig.Run(1, {kRelative, 5.0f});
    EXPECT_EQ(whileStopped.ErrorId(), kNotOnline) << whileStopped;
    // The resume does not continue the interrupted job; a new one runs.
    ctrl->REQUEST.value = E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE;
    ctrl->EXECUTE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return ctrl->DONE.value != 0; }, 500, "ONLINE again"));
    ctrl->EXECUTE.value = FALSE;
    const float stoppedAt = rig.Position(1);
    EXPECT_LT(stoppedAt, 400.0f);
    const Outcome next = rig.Run(1, {kRelative, 5.0f});
    EXPECT_TRUE(next.Done()) << next;
    EXPECT_NEAR(rig.Position(1), stoppedAt + 5.0f, 1e-3);
    rig.ExpectJobsSeen(1, 2);
}

// HOME POSITION after the boot: the FB writes the module (Axis ON for the start of ONLINE), but the PA-CONTROL
// acts on no control word there (2.7.2 notes). A G29 and a reference run are refused in their edge scan with
// 16#8025 and no Start reaches the controller; once ONLINE, the same G29 runs.
TEST_P(AxisSimTiming, JobsInHomePositionAreRefusedWithNothingSent) {
    AxisSimRig rig(Options());
    ASSERT_GT(rig.ScanUntil([&] { return rig.Ctrl()->READY.value != 0; }, 200), 0) << "Ready";
    rig.ScanMs(30);
    ASSERT_EQ(rig.Pac().OperatingStatus(), 1);
    for (const auto command : {kSetPosition, kHome}) {
        const Outcome o = rig.Run(1, {command, 100.0f});
        EXPECT_TRUE(o.Error()) << o;
        EXPECT_EQ(o.ErrorId(), kNotOnline) << o;
        EXPECT_EQ(o.Scans(), 0) << "refused in the edge scan";
    }
    rig.ScanMs(30);
    rig.ExpectJobsSeen(1, 0);
    rig.GoOnline();
    const Outcome online = rig.Run(1, {kSetPosition, 100.0f});
    EXPECT_TRUE(online.Done()) << online;
    EXPECT_NEAR(rig.Position(1), 100.0f, 1e-3);
    rig.ExpectJobsSeen(1, 1);
}

// ---- jog -------------------------------------------------------------------------------------------------

TEST_P(AxisSimTiming, JogMovesWhileHeldAndAtMostItsDistance) {
    RigOptions o = Options();
    o.referenced = false;  // a jog needs no reference
    AxisSimRig rig(o);
    rig.Pac().Axes().SetLimitSwitches(1, -500.0, 500.0);
    rig.GoOnline();
    auto& fb = rig.Fb(1);
    rig.SetJob(1, {E_PAC_AXISCOMMAND__PAC_AX_NONE, 150.0f, 500, 1000});
    // Positive, held for 60 ms more once it moves, then released: the axis brakes and stands; Done for one scan.
    fb->JOGPOSITIVE.value = TRUE;
    rig.Scan();
    ASSERT_TRUE(fb->BUSY.value);
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Position(1) > 0.0f; }, 200, "jogging"));
    rig.ScanMs(60);
    EXPECT_TRUE(fb->BUSY.value);
    EXPECT_EQ(rig.Control(1) & ac::kTraverseBits, ac::kJogPositive);
    const float held = rig.Position(1);
    fb->JOGPOSITIVE.value = FALSE;
    rig.Scan();
    EXPECT_EQ(rig.Control(1), kOn) << "released: the bit goes";
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 300, "final output"));
    EXPECT_TRUE(fb->DONE.value);
    rig.Scan();
    EXPECT_FALSE(fb->DONE.value) << "one scan: the jog input is FALSE";
    const float released = rig.Position(1);
    EXPECT_GT(released, held);
    EXPECT_LT(released, 150.0f) << "released before its distance";
    EXPECT_FALSE(rig.Motion(1).Moving());
    EXPECT_FALSE(fb->REFERENCED.value);
    // Negative, held to its distance: stops after 150, Done held while the input is held.
    fb->JOGNEGATIVE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 1500, "final output"));
    EXPECT_TRUE(fb->DONE.value);
    EXPECT_NEAR(rig.Position(1), released - 150.0f, 1e-3) << "at most Position";
    rig.ScanMs(50);
    EXPECT_TRUE(fb->DONE.value);
    EXPECT_EQ(rig.Control(1), kOn) << "no second jog while held";
    fb->JOGNEGATIVE.value = FALSE;
    rig.Scan();
    EXPECT_FALSE(fb->DONE.value);
    rig.ExpectJobsSeen(1, 2);
}

// ---- G123 ------------------------------------------------------------------------------------------------

TEST_P(AxisSimTiming, G123StopsTheMoveWhenTheInputDrops) {
    AxisSimRig rig(Options());
    rig.GoOnline();
    auto& fb = rig.Fb(1);
    rig.Pac().SetConditionInput(1, kConditionInput);  // after ONLINE started (it sets input 1)
    rig.Pac().Io().inputs.Set(kConditionInput, true);
    const Outcome started = rig.StartAndWait(1, {kAbsolute, 300.0f, 1000, 1000, kWhileInput1}, 100);
    ASSERT_FALSE(started.Done() || started.Error() || started.Aborted()) << started;
    EXPECT_EQ(rig.Trace(1).Since(started.mark).at(1).control,
              kOn | ac::kStart | ac::kMoveAbsolute | ac::kWhileInput1);
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Position(1) > 50.0f; }, 300, "moving"));
    rig.Pac().Io().inputs.Set(kConditionInput, false);
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 500, "final output"));
    EXPECT_TRUE(fb->DONE.value) << "its own condition ended it (FB_PAC_Axis.md): Done";
    EXPECT_TRUE(fb->STOPPEDBYCONDITION.value);
    EXPECT_TRUE(fb->HALTED.value);
    EXPECT_LT(rig.Position(1), 300.0f);
    EXPECT_FALSE(rig.Motion(1).Moving());
    fb->EXECUTE.value = FALSE;
    rig.Scan();
    // The condition does not hold at the start: taken over and ended at once, without a move.
    const float standing = rig.Position(1);
    const Outcome notMet = rig.Run(1, {kRelative, 10.0f, 1000, 1000, kWhileInput1});
    EXPECT_TRUE(notMet.Done()) << notMet;
    EXPECT_EQ(rig.Position(1), standing);
    EXPECT_TRUE(fb->STOPPEDBYCONDITION.value);
    // The condition holds: the move ends at its target, and its take-over cleared bit 11.
    rig.Pac().Io().inputs.Set(kConditionInput, true);
    const Outcome met = rig.Run(1, {kRelative, 10.0f, 1000, 1000, kWhileInput1});
    EXPECT_TRUE(met.Done()) << met;
    EXPECT_NEAR(rig.Position(1), standing + 10.0f, 1e-3);
    EXPECT_FALSE(fb->STOPPEDBYCONDITION.value);
    EXPECT_FALSE(fb->HALTED.value);
    rig.ExpectJobsSeen(1, 3);
}

// A reference run in the homing mode that loads the reference the next time the switch is actuated, without
// moving: complete in its take-over cycle, so on a controller that shows ACTIVE for traversing tasks only it
// has no ACTIVE either, and is Done all the same.
TEST_P(AxisSimTiming, ReferenceRunThatLoadsOnTheSwitchWithoutMoving) {
    RigOptions o = Options();
    o.referenced = false;
    AxisSimRig rig(o);
    rig.GoOnline();
    pac::sim::ServoAxisConfig config = rig.Motion(1).Config();
    config.homingMode = pac::sim::HomingMode::kLoadOnSwitch;
    rig.Motion(1).SetConfig(rig.Now(), config);
    const Outcome home = rig.Run(1, {kHome});
    EXPECT_TRUE(home.Done()) << home;
    EXPECT_EQ(rig.Position(1), 0.0f) << "no move";
    EXPECT_TRUE(rig.Motion(1).HomingArmed());
    rig.ExpectJobsSeen(1, 1);
}

// ---- the FB adds no scan: an instant job at the protocol minimum ---------------------------------------

TEST_P(AxisSimTiming, InstantJobAtTheProtocolMinimum) {
    AxisSimRig rig(Options());
    rig.GoOnline();
    auto& fb = rig.Fb(1);
    rig.SetJob(1, {kSetPosition, 3.0f});
    fb->EXECUTE.value = TRUE;
    rig.Scan();
    const std::int64_t edge = rig.ScanCount();
    ASSERT_EQ(rig.Control(1), kOn | ac::kStart | ac::kSetPosition) << "the axis is free: Start in the edge scan";
    const pac::test::ProtocolWindow window(rig.Options().timing);
    if (Reading().ActiveOnlyWhenTraversing()) {
        // No ACTIVE ever: Done once the controller's answer would have been visible, never before.
        const int answer = window.Request(rig.Now()).max;
        ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 300, "final output"));
        EXPECT_TRUE(fb->DONE.value);
        EXPECT_GE(rig.ScanCount(), edge + answer) << "not before the controller's answer could arrive";
        EXPECT_EQ(rig.Control(1), kOn) << "Start and the traverse bit off with Done";
        EXPECT_EQ(rig.Position(1), 3.0f);
        fb->EXECUTE.value = FALSE;
        rig.Scan();
        rig.ExpectJobsSeen(1, 1);
        return;
    }
    const int takeOver = window.Minimum(rig.Now());
    ASSERT_TRUE(rig.WaitFor([&] { return (rig.Control(1) & ac::kStart) == 0; }, 300, "Start dropped"));
    EXPECT_EQ(rig.ScanCount(), edge + takeOver) << "Start drops in the scan that sees ACTIVE";
    EXPECT_TRUE(fb->ACTIVE.value);
    EXPECT_EQ(rig.Control(1), kOn | ac::kSetPosition) << "the traverse bit stays";
    const std::int64_t drop = rig.ScanCount();
    const int release = window.Minimum(rig.Now());
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 300, "final output"));
    EXPECT_TRUE(fb->DONE.value);
    EXPECT_EQ(rig.ScanCount(), drop + release) << "Done in the scan that sees ACTIVE fall";
    EXPECT_EQ(rig.Control(1), kOn);
    EXPECT_EQ(rig.Position(1), 3.0f);
    fb->EXECUTE.value = FALSE;
    rig.Scan();
    rig.ExpectJobsSeen(1, 1);
}

// ---- eight axes at once ----------------------------------------------------------------------------------

TEST_P(AxisSimTiming, EightAxesAtOnceWithIndependentErrors) {
    RigOptions o = Options();
    o.axes = 8;
    AxisSimRig rig(o);
    rig.Pac().Axes().SetLimitSwitches(3, -50.0, 45.0);
    rig.GoOnline();
    for (int k = 1; k <= 8; ++k) {
        rig.SetJob(k, {kRelative, 20.0f * static_cast<float>(k)});
        rig.Fb(k)->EXECUTE.value = TRUE;
    }
    rig.Scan();
    for (int k = 1; k <= 8; ++k) {
        EXPECT_EQ(rig.Control(k), kOn | ac::kStart | ac::kMoveRelative) << "axis " << k << ": Start in the edge scan";
    }
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Fb(6)->ACTIVE.value != 0 && rig.Position(6) > 10.0f; }, 300,
                              "axis 6 moving"));
    rig.Pac().Axes().SetBlocked(6, rig.Now(), true);
    auto allFinal = [&] {
        for (int k = 1; k <= 8; ++k) {
            if (!rig.Final(k)) return false;
        }
        return true;
    };
    ASSERT_TRUE(rig.WaitFor(allFinal, 1500, "every axis's final output"));
    for (int k = 1; k <= 8; ++k) {
        SCOPED_TRACE("axis " + std::to_string(k));
        auto& fb = rig.Fb(k);
        if (k == 3 || k == 6) {
            EXPECT_TRUE(fb->ERROR.value);
            EXPECT_EQ(fb->ERRORID.value, kErrAxisError);
            EXPECT_EQ(fb->AXISERRORNUMBER.value, k == 3 ? kLimitSwitch : kFollowingError);
        } else {
            EXPECT_TRUE(fb->DONE.value);
            EXPECT_FALSE(fb->AXISERROR.value);
            EXPECT_EQ(rig.Position(k), 20.0f * static_cast<float>(k));
        }
    }
    EXPECT_EQ(rig.Position(3), 45.0f);
    EXPECT_LT(rig.Position(6), 120.0f);
    EXPECT_EQ(rig.Pac().OperatingStatus(), 31) << "an axis error is no system error (2.7)";
    for (int k = 1; k <= 8; ++k) rig.Fb(k)->EXECUTE.value = FALSE;
    rig.Scan();
    // Reset both; each moves again, the others stay where they are.
    rig.Pac().Axes().SetBlocked(6, rig.Now(), false);
    rig.Fb(3)->RESETERROR.value = TRUE;
    rig.Fb(6)->RESETERROR.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return !rig.Fb(3)->AXISERROR.value && !rig.Fb(6)->AXISERROR.value; }, 300,
                              "both reset"));
    rig.Fb(3)->RESETERROR.value = FALSE;
    rig.Fb(6)->RESETERROR.value = FALSE;
    rig.SetJob(3, {kRelative, -20.0f});
    rig.SetJob(6, {kAbsolute, 120.0f});
    rig.Fb(3)->EXECUTE.value = TRUE;
    rig.Fb(6)->EXECUTE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(3) && rig.Final(6); }, 1000, "final outputs"));
    EXPECT_TRUE(rig.Fb(3)->DONE.value);
    EXPECT_TRUE(rig.Fb(6)->DONE.value);
    EXPECT_EQ(rig.Position(3), 25.0f);
    EXPECT_EQ(rig.Position(6), 120.0f);
    for (int k = 1; k <= 8; ++k) {
        if (k != 3 && k != 6) {
            EXPECT_EQ(rig.Position(k), 20.0f * static_cast<float>(k));
        }
        rig.ExpectJobsSeen(k, k == 3 || k == 6 ? 2 : 1);
    }
}

// ---- the take-over bound (FB_PAC_Axis.md, "Stale CMD error") ---------------------------------------------

// PLC 1 ms, PA-CONTROL 10 ms, no latency: a take-over takes 1 to 10 ms, depending on where the Start falls in
// the controller's cycle. The first job is refused (43) 1 ms after its Start; the next one, with the 43 still
// showing, is taken over 8 ms after its Start. Counting the unchanged 43 as the new job's refusal after twice the
// longest measured take-over (2 ms) reported Error 43 for a good job the controller had not even seen yet; the
// bound now adds the controller's longest update time (2.3.4).
TEST(AxisSimTakeOverBound, GoodJobAfterARefusalMayTakeLongerThanTwiceTheFirstTakeOver) {
    RigOptions o;
    o.timing = {1, 10, 0};
    o.referenced = false;
    AxisSimRig rig(o);
    rig.GoOnline();
    // The edge in the scan 1 ms before a controller cycle.
    ASSERT_GT(rig.ScanUntil([&] { return rig.Now() % 10ms == 8ms; }, 20), 0);
    const Outcome refused = rig.Run(1, {kAbsolute, 10.0f});
    ASSERT_TRUE(refused.Error()) << refused;
    EXPECT_EQ(refused.ErrorId(), kNoReference);
    const pac::test::ScanWindow answer = pac::test::ProtocolWindow(o.timing).Request(refused.edgeTime);
    EXPECT_EQ(answer.max, 1) << "the edge scan lies 1 ms before a controller cycle";
    EXPECT_TRUE(answer.Contains(refused.Scans())) << refused << ", the protocol allows " << answer;
    const Outcome good = rig.Run(1, {kSetReferenced, 0.0f});
    EXPECT_TRUE(good.Done()) << good;
    const auto isStart = [](const AxisStep& step) { return (step.control & ac::kStart) != 0; };
    const auto isActive = [](const AxisStep& step) { return (step.status & as::kActive) != 0; };
    const std::int64_t start = rig.Trace(1).ScanOf(good.mark, isStart);
    const std::int64_t takeOver = rig.Trace(1).ScanOf(good.mark, isActive);
    ASSERT_GT(start, 0);
    EXPECT_GT(takeOver - start, 2) << "longer than twice the first take-over";
    EXPECT_TRUE(rig.Fb(1)->REFERENCED.value);
    const Outcome move = rig.Run(1, {kAbsolute, 10.0f});
    EXPECT_TRUE(move.Done()) << move;
    EXPECT_EQ(rig.Position(1), 10.0f);
    rig.ExpectJobsSeen(1, 3);
}

// ---- Start low long enough before a take-over was measured -----------------------------------------------

// The first job after a PLC start is aborted in the scan after its Start: nothing measured yet. On the slow
// timings of the grid the controller's answer to that Start (ACTIVE, then its fall) comes long after 10 ms; had
// the FB counted the axis free after Start had been low for the update time, the next Start would reach the
// controller while it still processes the old job (the edge lost, 2.7.3.2) and the old job's ACTIVE would pass
// for the new job's take-over.
class AxisSimSlowStart : public ::testing::TestWithParam<BusTiming> {};

TEST_P(AxisSimSlowStart, LateActiveOfAnAbortedFirstJobIsNotTheNextJobsTakeOver) {
    RigOptions o;
    o.timing = GetParam();
    AxisSimRig rig(o);
    rig.GoOnline();
    auto& fb = rig.Fb(1);
    rig.SetJob(1, {kAbsolute, 400.0f});
    fb->EXECUTE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return (rig.Control(1) & ac::kStart) != 0; }, 100, "Start"));
    fb->ABORT.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 1000, "the first job aborted"));
    EXPECT_TRUE(fb->COMMANDABORTED.value);
    fb->ABORT.value = FALSE;
    fb->EXECUTE.value = FALSE;
    rig.Scan();
    const Outcome next = rig.Run(1, {kAbsolute, 50.0f});
    EXPECT_TRUE(next.Done()) << next;
    EXPECT_EQ(rig.Position(1), 50.0f) << "the second job ran";
    rig.ExpectJobsSeen(1, 2);
}

INSTANTIATE_TEST_SUITE_P(SlowBuses, AxisSimSlowStart,
                         ::testing::ValuesIn(pac::test::BusTimingGrid({5, 10}, {3, 10}, {2, 3})),
                         pac::test::BusTimingName);

// ---- jittered buses --------------------------------------------------------------------------------------

// Two axes through a session of jobs, refusals, interruptions and an axis error, on a bus whose every image is
// delayed by the latency plus a seeded uniform draw from [0, jitter] (never overtaking the one before).
void MixedSession(AxisSimRig& rig, bool integer) {
    rig.Pac().Axes().SetLimitSwitches(2, -50.0, 40.0);
    rig.GoOnline(integer);
    auto& one = rig.Fb(1);
    auto& two = rig.Fb(2);
    auto expect = [&](int k, const Job& job, char result, std::uint32_t errorId = 0) {
        const Outcome o = rig.Run(k, job);
        if (result == 'D') {
            EXPECT_TRUE(o.Done()) << "axis " << k << ": " << o;
        } else {
            EXPECT_TRUE(o.Error()) << "axis " << k << ": " << o;
            EXPECT_EQ(o.ErrorId(), errorId) << "axis " << k << ": " << o;
        }
    };
    // Axis 2 references while axis 1 is refused twice with the same number, then referenced and moved.
    rig.SetJob(2, {kHome});
    two->EXECUTE.value = TRUE;
    expect(1, {kAbsolute, 10.0f}, 'E', kNoReference);
    expect(1, {kAbsolute, 10.0f}, 'E', kNoReference);
    expect(1, {kSetReferenced, 0.0f}, 'D');
    expect(1, {kAbsolute, 10.0f}, 'D');
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(2); }, 1000, "axis 2 referenced"));
    EXPECT_TRUE(two->DONE.value);
    two->EXECUTE.value = FALSE;
    expect(1, {kAbsolute, 20000.0f}, 'E', kPositionRange);
    expect(1, {kAbsolute, 20000.0f}, 'E', kPositionRange);
    expect(1, {kRelative, 5.0f}, 'D');
    EXPECT_EQ(rig.Position(1), 15.0f);
    // Axis 2 runs into its limit switch (machine 40 = 60 after homing) while axis 1 is aborted mid-move.
    rig.SetJob(2, {kRelative, 100.0f});
    two->EXECUTE.value = TRUE;
    const Outcome longMove = rig.StartAndWait(1, {kAbsolute, 300.0f}, 100);
    EXPECT_FALSE(longMove.Done() || longMove.Error() || longMove.Aborted()) << longMove;
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Position(1) > 40.0f; }, 300, "axis 1 moving"));
    one->ABORT.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 500, "axis 1 aborted"));
    EXPECT_TRUE(one->COMMANDABORTED.value);
    one->ABORT.value = FALSE;
    one->EXECUTE.value = FALSE;
    rig.Scan();
    expect(1, {kRelative, -5.0f}, 'D');
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(2); }, 1000, "axis 2 on its switch"));
    EXPECT_EQ(two->ERRORID.value, kErrAxisError);
    EXPECT_EQ(two->AXISERRORNUMBER.value, kLimitSwitch);
    two->EXECUTE.value = FALSE;
    two->RESETERROR.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return !two->AXISERROR.value; }, 300, "axis 2 reset"));
    two->RESETERROR.value = FALSE;
    expect(2, {kRelative, -10.0f}, 'D');
    EXPECT_EQ(rig.Position(2), 50.0f);
    // A new job while axis 1 moves: the old one aborted, the new one done.
    const Outcome back = rig.StartAndWait(1, {kAbsolute, 10.0f}, 50);
    EXPECT_FALSE(back.Done() || back.Error() || back.Aborted()) << back;
    ASSERT_TRUE(rig.WaitFor([&] { return one->ACTIVE.value != 0; }, 300, "axis 1 moving back"));
    one->EXECUTE.value = FALSE;
    rig.Scan();
    rig.SetJob(1, {kRelative, 2.0f});
    one->EXECUTE.value = TRUE;
    rig.Scan();
    EXPECT_TRUE(one->COMMANDABORTED.value);
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 1000, "the new job"));
    EXPECT_TRUE(one->DONE.value);
    one->EXECUTE.value = FALSE;
    // A short jog.
    rig.Scan();
    one->JOGNEGATIVE.value = TRUE;
    ASSERT_TRUE(rig.WaitFor([&] { return one->ACTIVE.value != 0; }, 300, "jogging"));
    one->JOGNEGATIVE.value = FALSE;
    ASSERT_TRUE(rig.WaitFor([&] { return rig.Final(1); }, 300, "jog ended"));
    EXPECT_TRUE(one->DONE.value);
    rig.Scan();
    rig.ExpectJobsSeen(1, 12);
    rig.ExpectJobsSeen(2, 3);
}

class AxisSimJitter : public ::testing::TestWithParam<BusTiming> {};

TEST_P(AxisSimJitter, MixedSession) {
    RigOptions o;
    o.timing = GetParam();
    o.axes = 2;
    o.referenced = false;
    AxisSimRig rig(o);
    MixedSession(rig, GetParam().seed % 2 == 0);
}

// The jitter comes from the bus alone, not from what FB_PAC_Axis's take-over bound assumes (FB_PAC_Axis.md:
// a shortest take-over of at least twice the jitter plus one scan): one and four PLC cycles on every timing of
// the standard grid, latency 0 included, so most of these buses lie outside that assumption; and the jittered
// buses of the other suites.
std::vector<BusTiming> JitteredSessions() {
    std::vector<BusTiming> all = pac::test::JitteredBusTimings();
    std::uint64_t seed = 1;
    for (const BusTiming& t : pac::test::StandardBusTimings()) {
        for (int cycles : {1, 4}) all.push_back({t.plcMs, t.pacMs, t.latency, 1000 * t.plcMs * cycles, seed++});
    }
    return all;
}

INSTANTIATE_TEST_SUITE_P(JitteredBuses, AxisSimJitter, ::testing::ValuesIn(JitteredSessions()),
                         pac::test::BusTimingName);

INSTANTIATE_TEST_SUITE_P(BusTimings, AxisSimTiming, ::testing::ValuesIn(OnReading({})), AxisSimCaseName);
INSTANTIATE_TEST_SUITE_P(ActiveWhenTraversing, AxisSimTiming,
                         ::testing::ValuesIn(OnReading({ActiveForJobs::kTraversingOnly})), AxisSimCaseName);
INSTANTIATE_TEST_SUITE_P(ContinuedAfterAxisOn, AxisSimTiming,
                         ::testing::ValuesIn(OnReading({ActiveForJobs::kEveryJob, NoReferenceAnswer::kCmdError43,
                                                        InterruptedTraverse::kContinuesAfterAxisOn})),
                         AxisSimCaseName);
INSTANTIATE_TEST_SUITE_P(NoReferenceE525, AxisSimTiming,
                         ::testing::ValuesIn(OnReading({ActiveForJobs::kEveryJob, NoReferenceAnswer::kSystemError525})),
                         AxisSimCaseName);

}  // namespace
}  // namespace test_fb_pac_axis_sim
