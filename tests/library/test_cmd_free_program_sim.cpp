// FB_PAC_Cmd in a PLC program freer than the other suites' (docs/fb/FB_PAC_Cmd.md, "The calling contract"):
// three command FBs on one CMD interface, each called or skipped (runs of 1 to 6 scans, as a CASE step or an
// IF branch leaves it out) independently in every scan, in a call order drawn anew every scan, each sending
// any command (writes, reads, moves, stops of the moving axis), Execute held, dropped early or re-edged, and
// the controller's operating status blipping to 0. The simulated PA-CONTROL's exchange log is the ledger of
// what it executed. The property, in a PLC programmer's words: an FB ends Done only if the controller took
// exactly its command (code, parameter, data) after this Execute edge, and AckData is that command's own
// answer; no command is taken twice; Busy ends within the bound docs/fb/FB_PAC_Cmd.md states. Every random
// choice comes from a seed the test's name and its failures print.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "bus_timing.hpp"
#include "channel_case.hpp"
#include "controller_readings.hpp"
#include "free_commands.hpp"
#include "pac/fb_instance.hpp"
#include "pac/iec_time.hpp"
#include "pac/pac_rig.hpp"
#include "pac/sim/cmd_frame.hpp"
#include "pac/sim/command_table.hpp"
#include "rig_timing.hpp"

namespace test_cmd_free_program_sim {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
namespace code = pac::sim::code;

constexpr int kFbs = 3;

using FreeCase = pac::test::ChannelCase;
using Command = pac::test::FreeCommand;

// What the test program does with one FB: the command it asked for and since when.
struct Caller {
    bool execute = false;
    bool lowSeen = true;        // the FB was called idle with Execute FALSE since the last command: an edge can follow
    bool edgeSeen = false;      // the FB was called with Execute TRUE since it was set
    bool finalSeen = false;     // the FB showed Done or Error for the present Execute
    int skip = 0;               // scans still to leave it out
    int holdAfterFinal = 0;     // scans Execute stays TRUE after the final output
    Command command;
    std::size_t ledgerAtEdge = 0;  // commands the controller had taken before the FB saw the edge
    std::chrono::nanoseconds edgeTime{0};
};

class FreeCmdProgram {
public:
    explicit FreeCmdProgram(const FreeCase& c)
        : case_(c), rig_(pac::test::RigTimingOf(c.sharing.timing, 0ns), ConfigOf(c)), random_(c.seed) {
        for (int i = 0; i < kFbs; ++i) fbs_.push_back(PAC_FB(FB_PAC_CMD));
        rig_.CmdInterface()->TWOSTEPWRITE.value = c.twoStepWrite ? TRUE : FALSE;
        rig_.CallCmdProgram([this](ST_PAC_CMDCHANNEL& channel) { Program(channel); });
        rig_.Start();
        order_ = {0, 1, 2};
    }

    // The controller booted, its N registers set, ONLINE by FB 0 called in every scan.
    void Prepare() {
        for (int i = 0; i < 100000 && !rig_.Controller().Booted(); ++i) rig_.Scan();
        const auto& t = case_.sharing.timing;
        rig_.Scan(3 + 2 * t.latency + t.jitterUs / 1000 / t.plcMs);  // the PLC sees the booted controller
        PresetRegisters();
        ASSERT_TRUE(RunFixed(0, {0x0700, 4, 7})) << "system parameter 4 names the stop input 7";
        rig_.Controller().Io().inputs.Set(7, true);
        ASSERT_TRUE(RunFixed(0, {code::kStartOnline, 0, 0})) << "ONLINE";
        free_ = true;
    }

    void Scan() {
        if (blipLeft_ > 0 && --blipLeft_ == 0) rig_.Controller().SetOperatingStatus(31);
        if (blipLeft_ == 0 && Draw(400) == 0 && rig_.Controller().OperatingStatus() == 31) {
            rig_.Controller().SetOperatingStatus(0);  // the status reads 0 for one or two of its cycles
            blipLeft_ = 1 + static_cast<int>(Draw(2));
        }
        rig_.Scan();
        ++scans_;
    }

    const std::vector<std::string>& Violations() const { return violations_; }
    int Dones() const { return dones_; }
    int Skips() const { return skips_; }
    int Reorders() const { return reorders_; }
    std::map<std::uint16_t, int> DoneCodes() const { return doneCodes_; }
    // "8001 x3, 8007 x12": the errors the FBs ended with.
    std::string Errors() const {
        std::ostringstream out;
        for (const auto& [id, n] : errors_) out << std::hex << std::uppercase << id << std::dec << " x" << n << ", ";
        return out.str();
    }

private:
    static pac::sim::PaControlConfig ConfigOf(const FreeCase& c) {
        pac::sim::PaControlConfig config = c.sharing.Config();
        config.logCapacity = 10000000;
        return config;
    }

    std::uint32_t Draw(std::uint32_t n) { return std::uniform_int_distribution<std::uint32_t>(0, n - 1)(random_); }

    void PresetRegisters() {
        for (int n = 0; n < 4; ++n) {
            rig_.Controller().Io().intRegisters.SetInt(pac::test::kFreeReadRegisters + n, pac::test::kFreeReadBase + n);
        }
    }

    bool RunFixed(int fb, const Command& command) {
        Caller& c = callers_[fb];
        c = Caller{};
        c.command = command;
        c.execute = true;
        for (int i = 0; i < 20000; ++i) {
            Scan();
            if (c.finalSeen) {
                const bool done = fbs_[fb]->DONE.value != 0;
                c.execute = false;
                Scan();
                c = Caller{};
                return done;
            }
        }
        return false;
    }

    void Program(ST_PAC_CMDCHANNEL& channel) {
        if (free_ && Draw(2) == 0) {
            std::shuffle(order_.begin(), order_.end(), random_);
            ++reorders_;
        }
        for (int i : order_) {
            Caller& c = callers_[i];
            if (free_) {
                Drive(i);
                if (c.skip > 0) {
                    --c.skip;
                    ++skips_;
                    continue;
                }
                if (Draw(6) == 0) {
                    c.skip = static_cast<int>(Draw(6));  // this scan and up to five more: 1 to 6 scans
                    ++skips_;
                    continue;
                }
            }
            Call(i, channel);
        }
    }

    // The program's decisions for FB i before its call: a new command, Execute dropped early or after the final.
    void Drive(int i) {
        Caller& c = callers_[i];
        if (!c.execute) {
            if (c.lowSeen && Draw(5) == 0) {
                c = Caller{};
                c.command = pac::test::NextFreeCommand(random_, serial_);
                c.execute = true;
                c.lowSeen = false;
            }
        } else if (c.finalSeen) {
            if (c.holdAfterFinal-- <= 0) c.execute = false;
        } else if (c.edgeSeen && Draw(300) == 0) {
            c.execute = false;  // Execute falls while Busy: the final output shows for one scan later
        }
    }

    void Call(int i, ST_PAC_CMDCHANNEL& channel) {
        Caller& c = callers_[i];
        auto& fb = fbs_[i];
        fb->CODE.value = c.command.code;
        fb->PARAM.value = c.command.param;
        fb->DATA.value = c.command.data;
        fb->EXECUTE.value = c.execute ? TRUE : FALSE;
        const bool wasFinal = fb->DONE.value || fb->ERROR.value;
        if (c.execute && !c.edgeSeen && !wasFinal && !fb->BUSY.value) {
            c.edgeSeen = true;
            c.ledgerAtEdge = LedgerSize();
            c.edgeTime = rig_.Now();
        }
        fb->CHANNEL.value = channel;
        fb();
        channel = fb->CHANNEL.value;
        if (!c.execute && !fb->BUSY.value && !fb->DONE.value && !fb->ERROR.value) c.lowSeen = true;
        if (!c.edgeSeen || c.finalSeen) return;
        CheckBusyBound(i);
        if (fb->DONE.value) {
            c.finalSeen = true;
            c.holdAfterFinal = static_cast<int>(Draw(4));
            CheckDone(i);
        } else if (fb->ERROR.value) {
            ++errors_[fb->ERRORID.value];
            c.finalSeen = true;
            c.holdAfterFinal = static_cast<int>(Draw(4));
        }
        if (c.finalSeen && !c.execute) c = Caller{};  // the one scan of a final output after Execute fell
    }

    // The commands the controller took (a SEND flag change it recognised), oldest first.
    std::size_t LedgerSize() {
        const std::size_t before = ledger_.Size();
        const auto& commands = ledger_.Read(rig_.Controller().Log());
        for (std::size_t k = before; k < commands.size(); ++k) {
            const Command& t = commands[k];
            if ((t.code == code::kPutIntReg || t.code == code::kPosAxisAbsolute) &&
                ++taken_[std::make_tuple(t.code, t.param, t.data)] > 1) {
                Violation("the controller took " + pac::test::Describe(t) + " twice");
            }
        }
        return commands.size();
    }

    void CheckDone(int i) {
        Caller& c = callers_[i];
        const auto& fb = fbs_[i];
        LedgerSize();
        if (!ledger_.Claim(c.ledgerAtEdge, c.command)) {
            Violation("FB " + std::to_string(i) + " ended Done for " + pac::test::Describe(c.command) +
                      ", which the controller did not take after its Execute edge");
            return;
        }
        ++dones_;
        ++doneCodes_[c.command.code];
        if (pac::test::IsFreeRead(c.command) && fb->ACKDATA.value != pac::test::FreeReadAnswer(c.command)) {
            Violation("FB " + std::to_string(i) + " ended Done for " + pac::test::Describe(c.command) + " with AckData " +
                      std::to_string(fb->ACKDATA.value) + ", another command's answer");
        }
    }

    // Busy ends within the two waits for the interface and the acknowledgement (Timeout each) and the wait for
    // END OF PROCESSING (EndTimeout), measured in time, however few of the scans called the FB; plus the longest
    // skip and a round trip.
    void CheckBusyBound(int i) {
        const auto bound = 1s + 1s + 60s + 6 * case_.sharing.timing.PlcCycle() + 100ms;
        if (fbs_[i]->BUSY.value && rig_.Now() - callers_[i].edgeTime > bound) {
            Violation("FB " + std::to_string(i) + " still Busy with " + pac::test::Describe(callers_[i].command));
        }
    }

    void Violation(const std::string& what) {
        if (violations_.size() < 5) {
            std::ostringstream out;
            out << "scan " << scans_ << ", t=" << pac::sim::FormatTime(rig_.Now()) << ": " << what;
            violations_.push_back(out.str());
        }
    }

    FreeCase case_;
    pac::PacRig rig_;
    std::mt19937_64 random_;
    std::vector<pac::FbInstance<FB_PAC_CMD>> fbs_;
    Caller callers_[kFbs];
    std::vector<int> order_;
    bool free_ = false;
    int blipLeft_ = 0;
    int serial_ = 0;
    long scans_ = 0;
    int dones_ = 0;
    int skips_ = 0;
    int reorders_ = 0;
    std::map<std::uint16_t, int> doneCodes_;
    std::map<std::uint32_t, int> errors_;
    pac::test::CmdLedger ledger_;
    std::map<std::tuple<std::uint16_t, std::uint16_t, std::uint32_t>, int> taken_;
    std::vector<std::string> violations_;
};

class CmdFreeProgram : public ::testing::TestWithParam<FreeCase> {};

TEST_P(CmdFreeProgram, DoneOnlyForTheCommandTheControllerTook) {
    FreeCmdProgram program(GetParam());
    program.Prepare();
    ASSERT_FALSE(HasFatalFailure());
    for (int i = 0; i < 6000; ++i) program.Scan();
    for (const std::string& v : program.Violations()) ADD_FAILURE() << v;
    // Reachability: the program did skip, reorder, and end commands of every kind Done.
    EXPECT_GT(program.Skips(), 100);
    EXPECT_GT(program.Reorders(), 100);
    const auto codes = program.DoneCodes();
    for (std::uint16_t c : {code::kPutIntReg, code::kGetIntReg, code::kPosAxisAbsolute}) {
        EXPECT_GT(codes.count(c) ? codes.at(c) : 0, 0) << "no " << std::hex << c << " ended Done; " << std::dec
                                                        << program.Dones() << " Done, errors " << program.Errors();
    }
}

std::vector<FreeCase> FreeCases() {
    return pac::test::ChannelCases({{1, 10, 0}, {1, 3, 1}, {2, 10, 2}, {5, 1, 3}, {10, 3, 0}, {1, 1, 0}, {2, 3, 1, 1500, 606}},
                                   true);
}

INSTANTIATE_TEST_SUITE_P(Readings, CmdFreeProgram, ::testing::ValuesIn(FreeCases()), pac::test::ChannelCaseName);

}  // namespace
}  // namespace test_cmd_free_program_sim
