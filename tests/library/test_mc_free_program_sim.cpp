// The PLCopen MC_ blocks in a PLC program freer than the other MC suites' (docs/fb/MC_blocks.md, "Calling
// contract"): FB_PAC_McAxis called in every scan as the library asks, and two MC_MoveAbsolute, an
// MC_MoveRelative, MC_Home, MC_Halt, MC_Stop, MC_MoveVelocity, MC_Reset and MC_Power each called or left out
// independently in every scan (runs of 1 to 6 scans), edged when idle, Execute falling while Busy, a move block
// now and then given up for good (the program calls a fresh instance from then on), MC_Power's Enable falling
// for a while now and then, an axis error raised in the controller now and then. The simulated PA-CONTROL's
// ledger of the jobs its axis module took over on a Start edge (AxisModule::TakenJobs) is the record of what it
// executed; after every scan the test notes when the controller's drive was enabled, its axis stood still, ran
// at MC_MoveVelocity's velocity and had its axis error cleared. The property: a move or MC_Home ends Done only if
// the controller took exactly its job (traverse bit, position, speed) after this Execute edge, an absolute move
// Done stands at its target, MC_Stop and MC_Halt end Done only once the controller's axis stood still after
// their edge; MC_MoveVelocity shows InVelocity only for its own job taken over after its edge and while the
// controller's axis runs at its velocity (or brakes at the traverse range end, which the module does not
// announce), within a round trip; MC_Reset started in ErrorStop ends Done only once the controller cleared the
// axis error after its edge; MC_Power's Status only while the controller's drive is enabled (within a round
// trip), and Axis ON off on the controller a round trip after MC_Power saw Enable FALSE (in ONLINE); Busy ends
// within the bound MC_blocks.md states; the PLCopen rules hold on every call. The blocks run in the order McRig
// lists them or reversed; every random choice comes from the seed in the test's name.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "bus_timing.hpp"
#include "free_caller.hpp"
#include "mc_rig.hpp"
#include "mc_test_steps.hpp"
#include "pac/axis_module_bits.hpp"
#include "pac/sim/axis_module.hpp"
#include "real_bits.hpp"

namespace test_mc_free_program_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using pac::test::FreeCaller;
using pac::test::McRig;

struct McFreeCase {
    pac::test::BusTiming timing;
    pac::test::McCallOrder order = pac::test::McCallOrder::kAsListed;
    std::uint64_t seed = 1;
};

std::string McFreeCaseName(const ::testing::TestParamInfo<McFreeCase>& info) {
    const ::testing::TestParamInfo<pac::test::BusTiming> timing(info.param.timing, info.index);
    return pac::test::BusTimingName(timing) +
           (info.param.order == pac::test::McCallOrder::kAsListed ? "_AsListed" : "_Reversed") + "_Seed" +
           std::to_string(info.param.seed);
}

void PrintTo(const McFreeCase& c, std::ostream* out) { *out << pac::test::Describe(c.timing) << "; seed " << c.seed; }

enum class Kind { kAbsolute, kRelative, kHome, kHalt, kStop, kVelocity, kReset };

// One block of the program and what its present command asked for.
struct Block {
    Kind kind;
    std::unique_ptr<FreeCaller> caller;
    float position = 0.0F;
    float velocity = 0.0F;
    float acceleration = 0.0F;  // MC_MoveVelocity's
    std::size_t ledgerAtEdge = 0;
    bool errorStopAtEdge = false;  // MC_Reset's edge came in ErrorStop
    bool inVelocity = false;       // MC_MoveVelocity showed InVelocity for its present command
    std::chrono::nanoseconds edgeTime{0};
    bool missed = false;  // a scan without the call since the edge
    std::optional<float> scriptedPosition;  // a named case's command
};

class FreeMcProgram {
public:
    // `named`: no random commands, no blips: the named cases script each command.
    explicit FreeMcProgram(const McFreeCase& c, bool named = false)
        : case_(c), named_(named), rig_(c.timing, 1, {}, c.order), random_(c.seed) {
        auto& b = rig_.Blocks(1);
        auto absolute = [] { return PAC_FB(MC_MOVEABSOLUTE); };
        Add(Kind::kAbsolute, "MC_MoveAbsolute A", b.moveA, absolute);
        Add(Kind::kAbsolute, "MC_MoveAbsolute B", b.moveB, absolute);
        Add(Kind::kRelative, "MC_MoveRelative", b.relative, [] { return PAC_FB(MC_MOVERELATIVE); });
        Add(Kind::kHome, "MC_Home", b.home, [] { return PAC_FB(MC_HOME); });
        Add(Kind::kHalt, "MC_Halt", b.halt, [] { return PAC_FB(MC_HALT); });
        Add(Kind::kStop, "MC_Stop", b.stop, [] { return PAC_FB(MC_STOP); });
        Add(Kind::kVelocity, "MC_MoveVelocity", b.velocity, [] { return PAC_FB(MC_MOVEVELOCITY); });
        velocity_ = blocks_.back().get();
        Add(Kind::kReset, "MC_Reset", b.reset, [] { return PAC_FB(MC_RESET); });
        rig_.Around(&b.power, [this] { return BeforePower(); }, [this] { AfterPower(); });
        // A range an MC_MoveVelocity crosses within the Busy bound; the other blocks' targets lie inside it.
        auto& parameters = rig_.Pac().Axes().Parameters(1);
        parameters.Set(pac::sim::axisparam::kMinTraverseArea, pac::test::BitsOf(0.0F));
        parameters.Set(pac::sim::axisparam::kMaxTraverseArea, pac::test::BitsOf(kRangeEnd));
        EXPECT_TRUE(rig_.Pac().Axes().ApplyParameters(1));
        rig_.Plc().Task().AddProgram([this] { Watch(); });
    }

    void Prepare() {
        rig_.PowerUp();
        free_ = true;
    }

    void Scan(int n) {
        for (int i = 0; i < n; ++i) {
            blips_.BeforeScan(rig_.Pac(), random_, free_ && !named_);  // outside the named cases
            auto& axis = rig_.Pac().Axes().Motion(1);
            if (free_ && !named_ && !axis.Fault() && std::uniform_int_distribution<int>(0, ScansFor(2s))(random_) == 0) {
                rig_.Pac().Axes().RaiseAxisError(1, rig_.Now(), pac::sim::axis_error::kFollowingError);
                ++axisErrors_;
            }
            rig_.Scan();
            ++scans_;
        }
    }

    // A named case for block `i` (in the order of the constructor: 0 MC_MoveAbsolute A ... 5 MC_Stop): its next
    // command goes to `position`, its calls from `from` to `from + length - 1` scans after the edge left out,
    // Execute falling in the first of them with `fall`.
    void Script(int i, float position, int from, int length, bool fall) {
        Block& b = *blocks_.at(static_cast<std::size_t>(i));
        b.scriptedPosition = position;
        b.caller->Script(from, length, fall);
    }
    // Scans until every scripted block was called idle again (at most `maxScans`); each one's scripts end.
    bool RunScripts(int maxScans) {
        auto over = [this] {
            for (const auto& b : blocks_) {
                if (b->scriptedPosition && !b->caller->ScriptOver()) return false;
            }
            return true;
        };
        for (int n = 0; n < maxScans && !over(); ++n) Scan(1);
        const bool ok = over();
        for (auto& b : blocks_) {
            if (b->scriptedPosition) b->caller->EndScript();
            b->scriptedPosition.reset();
        }
        return ok;
    }
    FreeCaller::Ended Ended(int i) const { return blocks_.at(static_cast<std::size_t>(i))->caller->LastEnded(); }

    const std::vector<std::string>& Violations() const { return log_.Texts(); }
    int Dones(Kind k) const { return dones_[static_cast<int>(k)]; }
    int SkipsWhileBusy() const { return pac::test::SkipsWhileBusyOf(blocks_); }
    int EndedAfterSkip() const { return endedAfterSkip_; }
    int Abandons() const { return abandons_; }
    int InVelocities() const { return inVelocities_; }
    int ResetsOfErrors() const { return resetsOfErrors_; }
    int PowerOffs() const { return powerOffs_; }
    int AxisErrors() const { return axisErrors_; }

private:
    // `fresh` makes the instance the program calls instead of one it gave up.
    template <class Fb, class Make>
    void Add(Kind kind, const std::string& name, pac::FbInstance<Fb>& fb, Make fresh) {
        pac::test::FreeCallerOdds odds;
        odds.newCommand = named_ ? 0 : (kind == Kind::kStop || kind == Kind::kHome ? 800
                                        : (kind == Kind::kHalt ? 400 : (kind == Kind::kVelocity ? 200 : 150)));
        if (kind == Kind::kReset) odds.newCommand = named_ ? 0 : 100;
        odds.earlyFall = named_ ? 0 : 150;
        odds.abandon = !named_ && (kind == Kind::kAbsolute || kind == Kind::kRelative) ? 400 : 0;
        blocks_.push_back(std::make_unique<Block>());
        Block& b = *blocks_.back();
        b.kind = kind;
        b.caller = std::make_unique<FreeCaller>(name, random_, odds, log_);
        rig_.Around(&fb, [this, &b, &fb, fresh] { return Before(b, fb, fresh); }, [this, &b, &fb] { After(b, fb); });
    }

    template <class Fb, class Make>
    bool Before(Block& b, pac::FbInstance<Fb>& fb, const Make& fresh) {
        if (!free_) return true;
        const bool called = b.caller->Plan(scans_, rig_.Now());
        if (b.caller->Abandoned() && b.caller->Draw(50) == 0) {
            fb = fresh();  // the program calls another instance from now on
            b.caller->Replace();
            ++abandons_;
            return false;
        }
        if (b.caller->NewCommand()) NewCommand(b);
        if (!called) {
            b.missed = true;
            return false;
        }
        SetInputs(b, fb);
        fb->EXECUTE.value = b.caller->Execute() ? TRUE : FALSE;
        if (b.caller->EdgeAtThisCall(pac::test::OutputsOf(fb))) {
            b.ledgerAtEdge = Ledger().size();
            b.edgeTime = rig_.Now();
            b.missed = false;
            b.errorStopAtEdge = rig_.State(1) == E_PAC_MCSTATE__PAC_MC_ERROR_STOP;
            b.inVelocity = false;
        }
        return true;
    }

    template <class Fb>
    void After(Block& b, pac::FbInstance<Fb>& fb) {
        if (!free_) return;
        if constexpr (std::is_same_v<Fb, MC_MOVEVELOCITY>) {
            if (fb->INVELOCITY.value) CheckInVelocity(b);
        }
        const auto ended = b.caller->AfterCall(pac::test::InputsOf(fb), pac::test::OutputsOf(fb), BusyBound());
        if (ended == FreeCaller::Ended::kNo) return;
        if (b.missed) ++endedAfterSkip_;
        if (ended != FreeCaller::Ended::kDone) return;
        ++dones_[static_cast<int>(b.kind)];
        if (b.kind == Kind::kReset) {
            if (!b.errorStopAtEdge) return;  // nothing to reset: Done at once
            ++resetsOfErrors_;
            Watch();  // the controller as it stands in this scan
            if (clearedAt_ < b.edgeTime) {
                log_.Add(scans_, rig_.Now(), "MC_Reset ended Done, but the controller has not cleared the axis error since its edge");
            }
            return;
        }
        if (b.kind == Kind::kHalt || b.kind == Kind::kStop) {
            Watch();  // the axis as it stands in this scan (a block in Standstill is Done at its edge)
            if (stoodAt_ < b.edgeTime) {
                log_.Add(scans_, rig_.Now(), b.caller->Name() + " ended Done, but the axis has not stood still since its edge");
            }
            return;
        }
        CheckJob(b);
        if (b.kind == Kind::kAbsolute && std::fabs(rig_.Position(1) - b.position) > 0.01F) {
            log_.Add(scans_, rig_.Now(), b.caller->Name() + " ended Done at " + std::to_string(rig_.Position(1)) +
                                             ", its target " + std::to_string(b.position));
        }
    }

    void NewCommand(Block& b) {
        ++serial_;
        const float unique = static_cast<float>(serial_ % 64) * 0.0625F;
        b.velocity = static_cast<float>(250 + b.caller->Draw(751));  // whole units/s: per mille of 1000 units/s
        if (b.kind == Kind::kAbsolute) b.position = 10.0F + static_cast<float>(b.caller->Draw(60)) + unique;
        if (b.scriptedPosition) b.position = *b.scriptedPosition;
        if (b.kind == Kind::kRelative) {
            b.position = (b.caller->Draw(2) == 0 ? -1.0F : 1.0F) * (2.0F + static_cast<float>(b.caller->Draw(8)) + unique);
        }
        if (b.kind == Kind::kVelocity) {
            // Slow enough to cross the range within the Busy bound, a ramp of 0.01 to 0.2 s; towards the far end.
            b.velocity = static_cast<float>(10 + b.caller->Draw(31));
            b.acceleration = static_cast<float>(100 * (2 + b.caller->Draw(9)));
            b.position = rig_.Position(1) < kRangeEnd / 2.0F ? 1.0F : -1.0F;  // the direction
        }
    }

    template <class Fb>
    void SetInputs(const Block& b, pac::FbInstance<Fb>& fb) {
        if constexpr (std::is_same_v<Fb, MC_MOVEABSOLUTE> || std::is_same_v<Fb, MC_MOVERELATIVE>) {
            fb->POSITION.value = b.position;
            fb->VELOCITY.value = b.velocity;
        }
        if constexpr (std::is_same_v<Fb, MC_MOVEVELOCITY>) {
            fb->VELOCITY.value = b.velocity;
            fb->ACCELERATION.value = b.acceleration;
            fb->DIRECTION.value = b.position > 0.0F ? E_PAC_MCDIRECTION__PAC_MC_POSITIVE : E_PAC_MCDIRECTION__PAC_MC_NEGATIVE;
        }
    }

    // InVelocity: the controller took this block's job after its edge, and its axis ran at the velocity (or
    // braked at the range end) within the last round trip.
    void CheckInVelocity(Block& b) {
        namespace bit = pac::axis_control;
        if (!b.inVelocity) {
            ++inVelocities_;
            b.inVelocity = true;
            const std::uint32_t traverse = b.position > 0.0F ? bit::kMoveToMax : bit::kMoveToMin;
            const bool taken = claims_.Claim(Ledger(), b.ledgerAtEdge, [&](const pac::sim::AxisModuleCommand& taken) {
                return (taken.control & bit::kTraverseBits) == traverse &&
                       taken.speedPerMille == static_cast<std::uint16_t>(b.velocity) &&
                       taken.accelerationPerMille == static_cast<std::uint16_t>(b.acceleration / 10.0F);
            });
            if (!taken) {
                log_.Add(scans_, rig_.Now(), "MC_MoveVelocity showed InVelocity for a job the controller did not take over after its edge");
            }
        }
        Watch();  // the controller as it stands in this scan
        if (atSpeedAt_ < b.edgeTime || rig_.Now() - atSpeedAt_ > RoundTrip()) {
            std::ostringstream what;
            what << "MC_MoveVelocity showed InVelocity for " << b.velocity * b.position << " units/s, but the controller's axis runs at "
                 << rig_.Pac().Axes().Motion(1).Velocity() << " units/s and ran at it last "
                 << (rig_.Now() - atSpeedAt_) / std::chrono::microseconds(1) << " us ago";
            log_.Add(scans_, rig_.Now(), what.str());
        }
    }

    // MC_Power: called or left out (1 in 6), Enable falling for 50 to 300 ms about every 2 s.
    bool BeforePower() {
        if (!free_) return true;
        auto& power = rig_.Blocks(1).power;
        if (powerOffLeft_ > 0) {
            --powerOffLeft_;
        } else if (!named_ && std::uniform_int_distribution<int>(0, ScansFor(2s))(random_) == 0) {
            powerOffLeft_ = ScansFor(std::chrono::milliseconds(50 + std::uniform_int_distribution<int>(0, 250)(random_)));
            ++powerOffs_;
        }
        if (std::uniform_int_distribution<int>(0, 5)(random_) == 0) return false;
        power->ENABLE.value = powerOffLeft_ > 0 ? FALSE : TRUE;
        return true;
    }

    void AfterPower() {
        if (!free_) return;
        auto& power = rig_.Blocks(1).power;
        if (power->ENABLE.value) {
            offSeenAt_.reset();
        } else if (!offSeenAt_) {
            offSeenAt_ = rig_.Now();
        }
        Watch();  // the controller as it stands in this scan
        if (power->STATUS.value && rig_.Now() - enabledAt_ > RoundTrip()) {
            log_.Add(scans_, rig_.Now(), "MC_Power shows Status, but the controller's drive has not been enabled for " +
                                             std::to_string((rig_.Now() - enabledAt_) / std::chrono::milliseconds(1)) + " ms");
        }
    }

    const pac::sim::TakenAxisJobLedger& Ledger() { return rig_.Pac().Module(1).TakenJobs(); }

    void CheckJob(const Block& b) {
        namespace bit = pac::axis_control;
        const std::uint32_t traverse =
            b.kind == Kind::kAbsolute ? bit::kMoveAbsolute : (b.kind == Kind::kRelative ? bit::kMoveRelative : bit::kHome);
        const bool taken = claims_.Claim(Ledger(), b.ledgerAtEdge, [&](const pac::sim::AxisModuleCommand& taken) {
            if ((taken.control & bit::kTraverseBits) != traverse) return false;
            return b.kind == Kind::kHome || (taken.position == pac::test::BitsOf(b.position) &&
                                             taken.speedPerMille == static_cast<std::uint16_t>(b.velocity));
        });
        if (taken) return;
        std::ostringstream what;
        what << b.caller->Name() << " ended Done for position " << b.position << " at " << b.velocity
             << " units/s, which the controller did not take over after its Execute edge";
        log_.Add(scans_, rig_.Now(), what.str());
    }

    // After every scan: when the controller's axis last stood still (no job, not moving), was on, ran at
    // MC_MoveVelocity's velocity (or braked at the range end) and had its axis error cleared.
    void Watch() {
        const auto& axis = rig_.Pac().Axes().Motion(1);
        if (!rig_.Pac().Module(1).Active() && !axis.Moving()) stoodAt_ = rig_.Now();
        if (axis.Drive() == pac::sim::DriveState::kEnabled) enabledAt_ = rig_.Now();  // status bit 0 DRIVE ENABLED
        if (faulted_ && !axis.Fault()) clearedAt_ = rig_.Now();
        faulted_ = axis.Fault();
        const Block& v = *velocity_;
        const double wanted = static_cast<double>(v.velocity * v.position);
        const bool braking = axis.Phase() == pac::sim::MotionPhase::kDecelerating &&
                             (std::fabs(axis.Target()) < 0.01 || std::fabs(axis.Target() - kRangeEnd) < 0.01);
        if (braking || (axis.Moving() && std::fabs(axis.Velocity() - wanted) <= 1.0E-3 * std::fabs(wanted))) {
            atSpeedAt_ = rig_.Now();
        }
        // Outside ONLINE the controller runs the axis whatever Axis ON says (2.7.2): the bound starts in ONLINE.
        if (offSeenAt_ && rig_.Pac().OperatingStatus() != 31) offSeenAt_ = rig_.Now();
        if (offSeenAt_ && rig_.Now() - *offSeenAt_ > RoundTrip() && axis.AxisOn()) {
            log_.Add(scans_, rig_.Now(), "the controller's axis is still on " +
                                             std::to_string((rig_.Now() - *offSeenAt_) / std::chrono::milliseconds(1)) +
                                             " ms after MC_Power saw Enable FALSE");
            offSeenAt_.reset();
        }
    }

    int ScansFor(std::chrono::nanoseconds t) const { return case_.timing.ScansFor(t); }

    // From a PLC call to the controller acting on its outputs and back to the PLC's inputs: two PLC cycles,
    // two controller cycles, the bus latency each way and the jitter.
    std::chrono::nanoseconds RoundTrip() const {
        return 3 * case_.timing.PlcCycle() + 2 * case_.timing.PacCycle() + 2 * case_.timing.Latency() + 5ms;
    }

    // MC_blocks.md: the axis to be free and the take-over (Timeout each), the job (a reference run, or a move of
    // at most 80 units at a quarter of 1000 units/s), StopTimeout, the longest skip and a round trip.
    std::chrono::nanoseconds BusyBound() const {
        return 1s + 1s + 2s + 10s + 7 * case_.timing.PlcCycle() + 2 * case_.timing.PacCycle() + 100ms;
    }

    static constexpr float kRangeEnd = 100.0F;

    McFreeCase case_;
    bool named_;
    McRig rig_;
    std::mt19937_64 random_;
    pac::test::ViolationLog log_;
    std::vector<std::unique_ptr<Block>> blocks_;
    bool free_ = false;
    pac::test::StatusBlips blips_;
    long scans_ = 0;
    int serial_ = 0;
    pac::test::AxisJobClaims claims_;
    std::chrono::nanoseconds stoodAt_{0};
    const Block* velocity_ = nullptr;  // MC_MoveVelocity's
    std::chrono::nanoseconds enabledAt_{0};
    std::chrono::nanoseconds clearedAt_{0};
    std::chrono::nanoseconds atSpeedAt_{0};
    std::optional<std::chrono::nanoseconds> offSeenAt_;
    bool faulted_ = false;
    int powerOffLeft_ = 0;
    int dones_[7] = {};
    int inVelocities_ = 0;
    int resetsOfErrors_ = 0;
    int powerOffs_ = 0;
    int axisErrors_ = 0;
    int endedAfterSkip_ = 0;
    int abandons_ = 0;
};

class McFreeProgram : public ::testing::TestWithParam<McFreeCase> {};

TEST_P(McFreeProgram, DoneOnlyForTheJobTheControllerTookOver) {
    FreeMcProgram program(GetParam());
    program.Prepare();
    ASSERT_FALSE(HasFatalFailure());
    program.Scan(std::max(GetParam().timing.ScansFor(8s), 3000));
    for (const std::string& v : program.Violations()) ADD_FAILURE() << v;
    EXPECT_GT(program.SkipsWhileBusy(), 20);
    EXPECT_GT(program.EndedAfterSkip(), 5);
    EXPECT_GT(program.Dones(Kind::kAbsolute), 2);
    EXPECT_GT(program.Dones(Kind::kRelative) + program.Dones(Kind::kHome) + program.Dones(Kind::kHalt) +
                  program.Dones(Kind::kStop),
              3);
    EXPECT_GT(program.InVelocities(), 0);
    EXPECT_GT(program.ResetsOfErrors(), 0) << program.AxisErrors() << " axis errors";
    EXPECT_GT(program.PowerOffs(), 0);
}

// The named cases. MC_MoveAbsolute: its calls left out for 1 to 6 scans from 1 to 14 scans after its edge, with
// Execute held or falling in the first scan left out: Done for its own job. MC_Stop edged while it moves, its
// calls left out likewise: the stop ends Done once the axis stands, the move CommandAborted.
class McSkippedCalls : public ::testing::TestWithParam<McFreeCase> {};

TEST_P(McSkippedCalls, AMoveAndAStopEndForThemselvesWhateverScansTheyMiss) {
    FreeMcProgram program(GetParam(), true);
    program.Prepare();
    ASSERT_FALSE(HasFatalFailure());
    constexpr int kMoveA = 0;
    constexpr int kStop = 5;
    int serial = 0;
    const int maxScans = GetParam().timing.ScansFor(3s);
    for (const bool fall : {false, true}) {
        for (int length = 1; length <= 6; ++length) {
            for (int from = 1; from <= 14; ++from) {
                SCOPED_TRACE(std::to_string(length) + " scans left out from scan " + std::to_string(from) +
                             " after the edge" + (fall ? ", Execute falling in the first" : ""));
                ++serial;
                program.Script(kMoveA, (serial % 2 ? 20.0F : 12.0F) + 0.0625F * static_cast<float>(serial % 32), from,
                               length, fall);
                ASSERT_TRUE(program.RunScripts(maxScans));
                EXPECT_EQ(program.Ended(kMoveA), FreeCaller::Ended::kDone) << "the move";
                if (from > 6) continue;
                program.Script(kMoveA, serial % 2 ? 70.0F : 5.0F, 1000000, 0, false);
                program.Scan(GetParam().timing.ScansFor(20ms));
                program.Script(kStop, 0.0F, from, length, fall);
                ASSERT_TRUE(program.RunScripts(maxScans));
                EXPECT_EQ(program.Ended(kStop), FreeCaller::Ended::kDone) << "the stop";
                EXPECT_EQ(program.Ended(kMoveA), FreeCaller::Ended::kAborted) << "the move it stopped";
                if (HasFailure()) break;
            }
        }
    }
    for (const std::string& v : program.Violations()) ADD_FAILURE() << v;
}

INSTANTIATE_TEST_SUITE_P(Timings, McSkippedCalls,
                         ::testing::Values(McFreeCase{{1, 10, 0}}, McFreeCase{{5, 1, 3}, pac::test::McCallOrder::kReversed},
                                           McFreeCase{{1, 3, 1, 2500, 101}}),
                         McFreeCaseName);

std::vector<McFreeCase> McFreeCases() {
    std::vector<McFreeCase> cases;
    std::uint64_t seed = 1;
    for (const auto& t : pac::test::mc::McTimings()) {
        for (auto order : {pac::test::McCallOrder::kAsListed, pac::test::McCallOrder::kReversed}) {
            cases.push_back({t, order, seed++});
        }
    }
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Timings, McFreeProgram, ::testing::ValuesIn(McFreeCases()), McFreeCaseName);

}  // namespace
}  // namespace test_mc_free_program_sim
