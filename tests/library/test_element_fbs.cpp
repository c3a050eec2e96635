// The element command FBs (st/cmd/FB_PAC_Read*/Write*/ResetError, docs/fb/element_commands.md)
// against the simulated PA-CONTROL over the simulated bus: the frames they send (manual 5.2.4, with
// the manual's own examples), that written values land in the controller and read values come from
// it (REAL registers bit for bit), command errors as the PA-CONTROL's numbers, the PLCopen output
// rules (the checker of plcopen_checker.hpp in every scan), the timing of FB_PAC_Cmd, and several FBs
// sharing one interface.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "bus_timing.hpp"
#include "command_plc.hpp"
#include "gvl_constants.hpp"
#include "pac/fb_instance.hpp"
#include "pac/sim/cmd_frame.hpp"
#include "pac/st_program.hpp"
#include "real_bits.hpp"
#include "run_to_final.hpp"

namespace test_element_fbs {  // apart from the names of the other sources in its unity batch
namespace {

using namespace std::chrono_literals;
using pac::sim::CommandFrame;
using pac::test::BusTiming;
using pac::test::FinalOutcome;

static_assert(sizeof(REAL) == sizeof(std::uint32_t) && std::numeric_limits<float>::is_iec559,
              "REAL must be an IEEE-754 single");

const pac::test::GvlConstants kGvl;

// 1 ms PLC cycle, 10 ms controller cycle, one PLC cycle of bus latency each way.
const BusTiming kTiming{1, 10, 1};

using pac::test::BitsOf;
using pac::test::FloatOf;

// One element FB alone on the CMD interface of a simulated PA-CONTROL.
template <class T>
class Single {
public:
    explicit Single(pac::FbInstance<T> fb, const BusTiming& timing = kTiming) : fb_(fb), plc_(timing) {
        plc_.Add("the FB", fb_);
        plc_.Start();
        plc_.ScanPastFirstHandshake();  // the controller has booted and answered the parked read
    }

    // One command: Execute edge, wait for Done or Error, Execute back to FALSE for one scan.
    FinalOutcome Run(int maxScans = 500) {
        plc_.Begin(fb_);
        sent_ = CommandFrame::Decode(plc_.Rig().ToPac().Cmd());
        const FinalOutcome out = plc_.Wait(fb_, maxScans);
        plc_.Release(fb_);
        return out;
    }

    pac::FbInstance<T>& Fb() { return fb_; }
    pac::test::CommandPlc& Plc() { return plc_; }
    pac::sim::PaControl& Pac() { return plc_.Controller(); }
    // The module as the FB wrote it in the Execute edge scan of the last Run().
    const CommandFrame& Sent() const { return sent_; }

private:
    pac::FbInstance<T> fb_;  // declared before the PLC, which calls it
    pac::test::CommandPlc plc_;
    CommandFrame sent_;
};

#define EXPECT_FRAME(single, expectedCode, expectedParam, expectedData)                   \
    do {                                                                                  \
        EXPECT_EQ((single).Sent().code, (expectedCode));                                  \
        EXPECT_EQ((single).Sent().parameter, (expectedParam));                            \
        EXPECT_EQ((single).Sent().data, (expectedData));                                  \
    } while (0)

// ---- Inputs ----

TEST(ElementFbs, ReadInputManualExample) {
    Single<FB_PAC_READINPUT> s(PAC_FB(FB_PAC_READINPUT));
    s.Pac().Io().inputs.Set(13, true);
    s.Fb()->NUMBER.value = 13;
    const FinalOutcome out = s.Run();
    ASSERT_TRUE(out.Done());
    EXPECT_FRAME(s, 0x1900, 0x000D, 0u);  // 5.2.4.1
    EXPECT_EQ(s.Fb()->VALUE.value, TRUE);
    s.Pac().Io().inputs.Set(13, false);
    ASSERT_TRUE(s.Run().Done());
    EXPECT_EQ(s.Fb()->VALUE.value, FALSE);
}

TEST(ElementFbs, ReadInputWordManualExample) {
    Single<FB_PAC_READINPUTWORD> s(PAC_FB(FB_PAC_READINPUTWORD));
    for (int n : {1, 2, 9, 11, 12, 16}) s.Pac().Io().inputs.Set(n, true);  // 5.2.4.2: 8D03
    s.Pac().Io().inputs.SetWord(17, 0x00FF);
    s.Fb()->NUMBER.value = 10;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x1901, 0x000A, 0u);
    EXPECT_EQ(s.Fb()->VALUE.value, 0x8D03);
    s.Fb()->NUMBER.value = 32;  // the last input of word 2
    ASSERT_TRUE(s.Run().Done());
    EXPECT_EQ(s.Fb()->VALUE.value, 0x00FF);
}

// ---- Outputs ----

TEST(ElementFbs, WriteOutputLandsInTheController) {
    Single<FB_PAC_WRITEOUTPUT> s(PAC_FB(FB_PAC_WRITEOUTPUT));
    s.Fb()->NUMBER.value = 13;
    s.Fb()->VALUE.value = TRUE;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x0902, 0x000D, 0x00000001u);  // 5.2.4.3: value 0 / 1 in bytes 2..3
    EXPECT_TRUE(s.Pac().Io().outputs.Get(13));
    EXPECT_FALSE(s.Pac().Io().outputs.Get(12));
    EXPECT_FALSE(s.Pac().Io().outputs.Get(14));
    s.Fb()->VALUE.value = FALSE;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_EQ(s.Sent().data, 0u);
    EXPECT_FALSE(s.Pac().Io().outputs.Get(13));
}

TEST(ElementFbs, ReadOutputManualExample) {
    Single<FB_PAC_READOUTPUT> s(PAC_FB(FB_PAC_READOUTPUT));
    s.Pac().Io().outputs.Set(243, true);
    s.Fb()->NUMBER.value = 243;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x1902, 0x00F3, 0u);  // 5.2.4.4
    EXPECT_EQ(s.Fb()->VALUE.value, TRUE);
    s.Fb()->NUMBER.value = 244;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_EQ(s.Fb()->VALUE.value, FALSE);
}

TEST(ElementFbs, WriteOutputWordManualExample) {
    Single<FB_PAC_WRITEOUTPUTWORD> s(PAC_FB(FB_PAC_WRITEOUTPUTWORD));
    s.Pac().Io().outputs.Set(16, true);  // word 1: untouched
    s.Fb()->NUMBER.value = 25;
    s.Fb()->VALUE.value = 0x3E11;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x0903, 0x0019, 0x00003E11u);  // 5.2.4.5
    const auto& outputs = s.Pac().Io().outputs;
    for (int n = 17; n <= 32; ++n) {
        const bool expected = n == 17 || n == 21 || (n >= 26 && n <= 30);
        EXPECT_EQ(outputs.Get(n), expected) << "output " << n;
    }
    EXPECT_TRUE(outputs.Get(16));
    EXPECT_FALSE(outputs.Get(33));
    s.Fb()->VALUE.value = 0xFFFF;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_EQ(s.Sent().data, 0x0000FFFFu) << "16-bit data in bytes 2..3, the high word 0";
    EXPECT_EQ(outputs.Word(17), 0xFFFF);
}

TEST(ElementFbs, ReadOutputWordManualExample) {
    Single<FB_PAC_READOUTPUTWORD> s(PAC_FB(FB_PAC_READOUTPUTWORD));
    s.Pac().Io().outputs.SetWord(33, 0x5555);
    s.Fb()->NUMBER.value = 33;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x1903, 0x0021, 0u);  // 5.2.4.6
    EXPECT_EQ(s.Fb()->VALUE.value, 0x5555);
}

// ---- Flags ----

TEST(ElementFbs, WriteFlagLandsInTheController) {
    Single<FB_PAC_WRITEFLAG> s(PAC_FB(FB_PAC_WRITEFLAG));
    s.Fb()->NUMBER.value = 11;
    s.Fb()->VALUE.value = TRUE;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x0904, 0x000B, 0x00000001u);  // 5.2.4.7
    EXPECT_TRUE(s.Pac().Io().flags.Get(11));
    s.Fb()->VALUE.value = FALSE;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FALSE(s.Pac().Io().flags.Get(11));
}

TEST(ElementFbs, ReadFlagManualExample) {
    Single<FB_PAC_READFLAG> s(PAC_FB(FB_PAC_READFLAG));
    s.Pac().Io().flags.Set(243, true);
    s.Fb()->NUMBER.value = 243;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x1904, 0x00F3, 0u);  // 5.2.4.8
    EXPECT_EQ(s.Fb()->VALUE.value, TRUE);
    s.Pac().Io().flags.Set(243, false);
    ASSERT_TRUE(s.Run().Done());
    EXPECT_EQ(s.Fb()->VALUE.value, FALSE);
}

TEST(ElementFbs, WriteFlagWordManualExample) {
    Single<FB_PAC_WRITEFLAGWORD> s(PAC_FB(FB_PAC_WRITEFLAGWORD));
    s.Fb()->NUMBER.value = 17;
    s.Fb()->VALUE.value = 0x45F2;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x0905, 0x0011, 0x000045F2u);  // 5.2.4.9
    const auto& flags = s.Pac().Io().flags;
    for (int n = 17; n <= 32; ++n) {
        const bool expected = n == 18 || (n >= 21 && n <= 25) || n == 27 || n == 31;
        EXPECT_EQ(flags.Get(n), expected) << "flag " << n;
    }
}

TEST(ElementFbs, ReadFlagWordManualExample) {
    Single<FB_PAC_READFLAGWORD> s(PAC_FB(FB_PAC_READFLAGWORD));
    for (int n : {33, 34, 35, 36, 41, 42, 43, 44}) s.Pac().Io().flags.Set(n, true);  // 5.2.4.10: 0F0F
    s.Fb()->NUMBER.value = 33;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x1905, 0x0021, 0u);
    EXPECT_EQ(s.Fb()->VALUE.value, 0x0F0F);
}

// ---- Integer registers ----

TEST(ElementFbs, WriteIntRegLandsInTheController) {
    Single<FB_PAC_WRITEINTREG> s(PAC_FB(FB_PAC_WRITEINTREG));
    s.Fb()->NUMBER.value = 97;
    s.Fb()->VALUE.value = 12589;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x0906, 0x0061, 0x0000312Du);  // 5.2.4.11
    EXPECT_EQ(s.Pac().Io().intRegisters.GetInt(97), 12589);
    for (std::int32_t v : {-1, std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max(), 0}) {
        s.Fb()->VALUE.value = v;
        ASSERT_TRUE(s.Run().Done()) << v;
        EXPECT_EQ(s.Pac().Io().intRegisters.GetInt(97), v);
    }
    s.Fb()->NUMBER.value = 1024;
    s.Fb()->VALUE.value = -5;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_EQ(s.Sent().data, 0xFFFFFFFBu) << "two's complement";
    EXPECT_EQ(s.Pac().Io().intRegisters.GetInt(1024), -5);
}

TEST(ElementFbs, ReadIntRegManualExample) {
    Single<FB_PAC_READINTREG> s(PAC_FB(FB_PAC_READINTREG));
    s.Pac().Io().intRegisters.SetInt(129, 88224);
    s.Fb()->NUMBER.value = 129;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x1906, 0x0081, 0u);  // 5.2.4.12
    EXPECT_EQ(s.Fb()->VALUE.value, 88224);
    for (std::int32_t v : {-1, std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()}) {
        s.Pac().Io().intRegisters.SetInt(129, v);
        ASSERT_TRUE(s.Run().Done()) << v;
        EXPECT_EQ(s.Fb()->VALUE.value, v);
    }
}

// ---- Real registers, bit for bit ----

const std::vector<float>& RealSamples() {
    static const std::vector<float> samples = {
        10.0F, 111.111F, -640.0F, 0.1F, 1.0F, -1.5F, 20480.0F, 16777215.0F, -1.0e20F, 3.0e-5F,
        std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(), std::numeric_limits<float>::min(),
        std::numeric_limits<float>::denorm_min(), -2.5e-39F, 0.0F,
    };
    return samples;
}

TEST(ElementFbs, WriteRealRegIsBitExact) {
    Single<FB_PAC_WRITEREALREG> s(PAC_FB(FB_PAC_WRITEREALREG));
    s.Fb()->NUMBER.value = 27;
    s.Fb()->VALUE.value = 10.0F;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x0907, 0x001B, 0x41200000u);  // 5.2.4.13
    for (float v : RealSamples()) {
        s.Fb()->VALUE.value = v;
        ASSERT_TRUE(s.Run().Done()) << v;
        EXPECT_EQ(s.Sent().data, BitsOf(v)) << v;
        EXPECT_EQ(s.Pac().Io().realRegisters.Get(27), BitsOf(v)) << v;
    }
}

TEST(ElementFbs, ReadRealRegIsBitExact) {
    Single<FB_PAC_READREALREG> s(PAC_FB(FB_PAC_READREALREG));
    s.Pac().Io().realRegisters.Set(37, 0x42DE38D5u);  // 5.2.4.14: 111.111
    s.Fb()->NUMBER.value = 37;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x1907, 0x0025, 0u);
    EXPECT_EQ(BitsOf(s.Fb()->VALUE.value), 0x42DE38D5u);
    EXPECT_FLOAT_EQ(s.Fb()->VALUE.value, 111.111F);
    for (float v : RealSamples()) {
        s.Pac().Io().realRegisters.SetReal(37, v);
        ASSERT_TRUE(s.Run().Done()) << v;
        EXPECT_EQ(BitsOf(s.Fb()->VALUE.value), BitsOf(v)) << v;
    }
}

// ---- Error and status ----

TEST(ElementFbs, ResetErrorResetsAResettableError) {
    Single<FB_PAC_RESETERROR> s(PAC_FB(FB_PAC_RESETERROR));
    s.Pac().SetSystemError(150);  // class 2: system error hardware
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x0909, 0x0000, 0u);  // 5.2.4.15
    EXPECT_EQ(s.Pac().SystemError(), 0);
    EXPECT_EQ(s.Fb()->ERRORNUMBER.value, 0);
}

TEST(ElementFbs, ResetErrorReportsTheErrorThatStays) {
    Single<FB_PAC_RESETERROR> s(PAC_FB(FB_PAC_RESETERROR));
    s.Pac().SetSystemError(5);  // class 1: CPU error, power cycle only
    const FinalOutcome out = s.Run();
    ASSERT_TRUE(out.Error());
    EXPECT_EQ(out.ErrorId(), kGvl["PAC_ERR_NOT_EXECUTABLE"]);
    EXPECT_EQ(s.Fb()->ERRORNUMBER.value, 5) << "5.2.4.15: the error number again in the acknowledgement data";
    EXPECT_EQ(s.Pac().SystemError(), 5);
    s.Pac().SetSystemError(200);
    ASSERT_TRUE(s.Run().Done());
    EXPECT_EQ(s.Fb()->ERRORNUMBER.value, 0) << "cleared by the next final result";
}

TEST(ElementFbs, ResetErrorOutsideHomePositionIsInadmissible) {
    Single<FB_PAC_RESETERROR> s(PAC_FB(FB_PAC_RESETERROR));
    s.Pac().SetSystemError(150);
    s.Pac().SetOperatingStatus(static_cast<std::uint8_t>(kGvl["PAC_STATUS_ONLINE"]));
    const FinalOutcome out = s.Run();
    ASSERT_TRUE(out.Error());
    EXPECT_EQ(out.ErrorId(), kGvl["PAC_ERR_INADMISSIBLE_COMMAND"]);
    EXPECT_EQ(s.Fb()->ERRORNUMBER.value, 0);
    EXPECT_EQ(s.Pac().SystemError(), 150);
}

TEST(ElementFbs, ReadErrorManualExample) {
    Single<FB_PAC_READERROR> s(PAC_FB(FB_PAC_READERROR));
    s.Pac().SetSystemError(529);  // 5.2.4.16: 0211
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x1909, 0x0000, 0u);
    EXPECT_EQ(s.Fb()->ERRORNUMBER.value, 529);
    s.Pac().SetSystemError(0);
    ASSERT_TRUE(s.Run().Done());
    EXPECT_EQ(s.Fb()->ERRORNUMBER.value, 0);
}

TEST(ElementFbs, ReadStateGivesTheDecimalStatusCode) {
    Single<FB_PAC_READSTATE> s(PAC_FB(FB_PAC_READSTATE));
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x190B, 0x0000, 0u);  // 5.2.4.17
    EXPECT_EQ(s.Fb()->OPSTATUS.value, kGvl["PAC_STATUS_HOME_POSITION"]);
    for (const char* name : {"PAC_STATUS_ONLINE", "PAC_STATUS_AUTO_STARTED", "PAC_STATUS_ONLINE_STOPPED_MALFUNCTION"}) {
        s.Pac().SetOperatingStatus(static_cast<std::uint8_t>(kGvl[name]));
        ASSERT_TRUE(s.Run().Done()) << name;
        EXPECT_EQ(s.Fb()->OPSTATUS.value, kGvl[name]) << name;
    }
}

// ---- System elements ----

TEST(ElementFbs, ReadSystemFlag) {
    Single<FB_PAC_READSYSTEMFLAG> s(PAC_FB(FB_PAC_READSYSTEMFLAG));
    s.Pac().Io().systemFlags.Set(200, true);
    s.Fb()->NUMBER.value = 200;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x1934, 200, 0u);  // 5.2.4.29, code per docs/manual_errata.md
    EXPECT_EQ(s.Fb()->VALUE.value, TRUE);
    s.Fb()->NUMBER.value = 201;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_EQ(s.Fb()->VALUE.value, FALSE);
    s.Fb()->NUMBER.value = 51;  // SM51: axis 1 referenced (referenced at power on)
    ASSERT_TRUE(s.Run().Done());
    EXPECT_EQ(s.Fb()->VALUE.value, TRUE);
}

TEST(ElementFbs, ReadSystemIntReg) {
    Single<FB_PAC_READSYSTEMINTREG> s(PAC_FB(FB_PAC_READSYSTEMINTREG));
    s.Pac().Io().systemIntRegisters.SetInt(20, -7);
    s.Fb()->NUMBER.value = 20;
    ASSERT_TRUE(s.Run().Done());
    EXPECT_FRAME(s, 0x1935, 20, 0u);  // 5.2.4.30, code per docs/manual_errata.md
    EXPECT_EQ(s.Fb()->VALUE.value, -7);
    s.Pac().SetSystemError(529);
    s.Fb()->NUMBER.value = 10;  // SN10: the system error number
    ASSERT_TRUE(s.Run().Done());
    EXPECT_EQ(s.Fb()->VALUE.value, 529);
}

TEST(ElementFbs, ReadSystemRealRegIsBitExact) {
    Single<FB_PAC_READSYSTEMREALREG> s(PAC_FB(FB_PAC_READSYSTEMREALREG));
    s.Fb()->NUMBER.value = 5;
    for (float v : RealSamples()) {
        s.Pac().Io().systemRealRegisters.SetReal(5, v);
        ASSERT_TRUE(s.Run().Done()) << v;
        EXPECT_FRAME(s, 0x1937, 5, 0u);  // 5.2.4.31, code per docs/manual_errata.md
        EXPECT_EQ(BitsOf(s.Fb()->VALUE.value), BitsOf(v)) << v;
    }
}

// ---- Command errors: the PA-CONTROL's number unchanged ----

template <class T>
void ExpectNumberRefused(pac::FbInstance<T> fb, std::uint16_t number, const std::string& errorName) {
    SCOPED_TRACE(errorName + ", number " + std::to_string(number));
    Single<T> s(fb);
    s.Fb()->NUMBER.value = number;
    const FinalOutcome out = s.Run();
    EXPECT_TRUE(out.Error());
    EXPECT_FALSE(out.Done());
    EXPECT_EQ(out.ErrorId(), kGvl[errorName]);
    EXPECT_EQ(s.Pac().Counters().failed, 1u);
}

TEST(ElementFbs, NumbersOutOfRangeGiveThePacErrorNumber) {
    ExpectNumberRefused(PAC_FB(FB_PAC_READINPUT), 1025, "PAC_ERR_INPUT");
    ExpectNumberRefused(PAC_FB(FB_PAC_READINPUTWORD), 0, "PAC_ERR_INPUT");
    ExpectNumberRefused(PAC_FB(FB_PAC_WRITEOUTPUT), 1025, "PAC_ERR_OUTPUT");
    ExpectNumberRefused(PAC_FB(FB_PAC_READOUTPUT), 0, "PAC_ERR_OUTPUT");
    ExpectNumberRefused(PAC_FB(FB_PAC_WRITEOUTPUTWORD), 2000, "PAC_ERR_OUTPUT");
    ExpectNumberRefused(PAC_FB(FB_PAC_READOUTPUTWORD), 1025, "PAC_ERR_OUTPUT");
    ExpectNumberRefused(PAC_FB(FB_PAC_WRITEFLAG), 0, "PAC_ERR_FLAG");
    ExpectNumberRefused(PAC_FB(FB_PAC_READFLAG), 1025, "PAC_ERR_FLAG");
    ExpectNumberRefused(PAC_FB(FB_PAC_WRITEFLAGWORD), 1025, "PAC_ERR_FLAG");
    ExpectNumberRefused(PAC_FB(FB_PAC_READFLAGWORD), 0, "PAC_ERR_FLAG");
    ExpectNumberRefused(PAC_FB(FB_PAC_WRITEINTREG), 1025, "PAC_ERR_N_REGISTER");
    ExpectNumberRefused(PAC_FB(FB_PAC_READINTREG), 0, "PAC_ERR_N_REGISTER");
    ExpectNumberRefused(PAC_FB(FB_PAC_WRITEREALREG), 1025, "PAC_ERR_R_REGISTER");
    ExpectNumberRefused(PAC_FB(FB_PAC_READREALREG), 0, "PAC_ERR_R_REGISTER");
    ExpectNumberRefused(PAC_FB(FB_PAC_READSYSTEMFLAG), 257, "PAC_ERR_FLAG");
    ExpectNumberRefused(PAC_FB(FB_PAC_READSYSTEMINTREG), 0, "PAC_ERR_N_REGISTER");
    ExpectNumberRefused(PAC_FB(FB_PAC_READSYSTEMREALREG), 300, "PAC_ERR_R_REGISTER");
}

TEST(ElementFbs, LibraryErrorsPassThrough) {
    Single<FB_PAC_READINTREG> s(PAC_FB(FB_PAC_READINTREG));
    s.Fb()->NUMBER.value = 1;
    s.Fb()->TIMEOUT.value = TIME{0, 30'000'000};
    s.Plc().Rig().Bus().FromPacLink().SetFault(s.Plc().Now(), pac::sim::LinkFault::kFrozen);
    const FinalOutcome out = s.Run();
    ASSERT_TRUE(out.Error());
    EXPECT_EQ(out.ErrorId(), kGvl["PAC_LIB_ERR_ACK_TIMEOUT"]);
    EXPECT_EQ(out.Scans(), s.Plc().Protocol().TimeoutScans(30ms)) << "Timeout is the FB's own input, handed to FB_PAC_Cmd";
}

// ---- PLCopen output rules, once, on FB_PAC_ReadIntReg ----

class ReadIntRegRules : public ::testing::Test {
protected:
    // Each scan: the outputs are FB_PAC_Cmd's and Value changes only in a scan that shows Done (the
    // PLCopen rules: Single's checker).
    void ScanAndCheck(int n = 1) {
        for (int i = 0; i < n; ++i) {
            const DINT before = fb()->VALUE.value;
            s_.Plc().Scan();
            auto& f = s_.Fb().Data();
            EXPECT_EQ(f.DONE.value, f.CMD.DONE.value);
            EXPECT_EQ(f.BUSY.value, f.CMD.BUSY.value);
            EXPECT_EQ(f.ERROR.value, f.CMD.ERROR.value);
            EXPECT_EQ(f.ERRORID.value, f.CMD.ERRORID.value);
            if (!f.DONE.value) {
                EXPECT_EQ(f.VALUE.value, before) << "Value changes only with Done";
            }
        }
    }

    int ScanUntilFinal(int maxScans = 200) {
        for (int scans = 1; scans <= maxScans; ++scans) {
            ScanAndCheck();
            if (fb()->DONE.value || fb()->ERROR.value) return scans;
        }
        return -1;
    }

    pac::FbInstance<FB_PAC_READINTREG>& fb() { return s_.Fb(); }
    pac::sim::RegisterBank& N() { return s_.Pac().Io().intRegisters; }

    Single<FB_PAC_READINTREG> s_{PAC_FB(FB_PAC_READINTREG)};
};

TEST_F(ReadIntRegRules, DoneHoldsWhileExecuteAndValueHoldsAfter) {
    N().SetInt(4, 5);
    fb()->NUMBER.value = 4;
    fb()->EXECUTE.value = TRUE;
    ScanAndCheck();
    EXPECT_TRUE(fb()->BUSY.value) << "Busy in the edge scan";
    ASSERT_GT(ScanUntilFinal(), 0);
    EXPECT_TRUE(fb()->DONE.value);
    EXPECT_EQ(fb()->VALUE.value, 5);
    N().SetInt(4, 6);
    ScanAndCheck(20);
    EXPECT_TRUE(fb()->DONE.value) << "Done holds while Execute stays TRUE";
    EXPECT_EQ(fb()->VALUE.value, 5) << "no new command without a new edge";
    fb()->EXECUTE.value = FALSE;
    ScanAndCheck();
    EXPECT_FALSE(fb()->DONE.value);
    EXPECT_FALSE(fb()->BUSY.value);
    EXPECT_EQ(fb()->VALUE.value, 5) << "Value holds after Done";

    // The next read: Value keeps the old value while Busy.
    N().SetInt(4, 7);
    fb()->EXECUTE.value = TRUE;
    ASSERT_GT(ScanUntilFinal(), 0);
    EXPECT_EQ(fb()->VALUE.value, 7);
    fb()->EXECUTE.value = FALSE;
    ScanAndCheck();
}

TEST_F(ReadIntRegRules, ExecuteFallingWhileBusyShowsDoneForOneScan) {
    N().SetInt(4, 9);
    fb()->NUMBER.value = 4;
    fb()->EXECUTE.value = TRUE;
    ScanAndCheck();
    fb()->EXECUTE.value = FALSE;
    int doneScans = 0;
    for (int i = 0; i < 100; ++i) {
        ScanAndCheck();
        if (fb()->DONE.value) ++doneScans;
    }
    EXPECT_EQ(doneScans, 1);
    EXPECT_EQ(fb()->VALUE.value, 9);
}

TEST_F(ReadIntRegRules, ErrorHoldsWhileExecuteAndKeepsValue) {
    N().SetInt(4, 3);
    fb()->NUMBER.value = 4;
    ASSERT_TRUE(s_.Run().Done());
    ASSERT_EQ(fb()->VALUE.value, 3);
    fb()->NUMBER.value = 1025;
    fb()->EXECUTE.value = TRUE;
    ASSERT_GT(ScanUntilFinal(), 0);
    EXPECT_TRUE(fb()->ERROR.value);
    EXPECT_EQ(fb()->ERRORID.value, kGvl["PAC_ERR_N_REGISTER"]);
    ScanAndCheck(10);
    EXPECT_TRUE(fb()->ERROR.value) << "Error holds while Execute stays TRUE";
    EXPECT_EQ(fb()->VALUE.value, 3) << "an error keeps the last value read";
    fb()->EXECUTE.value = FALSE;
    ScanAndCheck();
    EXPECT_FALSE(fb()->ERROR.value);
    EXPECT_EQ(fb()->ERRORID.value, 0);
    EXPECT_EQ(fb()->VALUE.value, 3);
}

TEST_F(ReadIntRegRules, EdgeWhileBusyIsIgnored) {
    N().SetInt(4, 11);
    fb()->NUMBER.value = 4;
    const auto before = s_.Pac().Counters().Count(0x1906);
    fb()->EXECUTE.value = TRUE;
    ScanAndCheck();
    fb()->EXECUTE.value = FALSE;
    ScanAndCheck();
    fb()->EXECUTE.value = TRUE;  // a second edge while the first command runs
    ASSERT_TRUE(fb()->BUSY.value);
    ASSERT_GT(ScanUntilFinal(), 0);
    EXPECT_TRUE(fb()->DONE.value);
    ScanAndCheck(50);
    EXPECT_EQ(s_.Pac().Counters().Count(0x1906), before + 1) << "one command only";
}

// ---- Timing: FB_PAC_Cmd's, plus nothing ----

TEST(ElementFbs, SameScansAsFbPacCmd) {
    const BusTiming timings[] = {{1, 10, 1}, {1, 1, 0}, {2, 3, 2}, {5, 7, 1}, {10, 1, 3}};
    for (const BusTiming& t : timings) {
        SCOPED_TRACE(pac::test::Describe(t));
        Single<FB_PAC_CMD> cmd(PAC_FB(FB_PAC_CMD), t);
        cmd.Pac().Io().intRegisters.SetInt(3, 42);
        cmd.Fb()->CODE.value = 0x1906;
        cmd.Fb()->PARAM.value = 3;
        Single<FB_PAC_READINTREG> read(PAC_FB(FB_PAC_READINTREG), t);
        read.Pac().Io().intRegisters.SetInt(3, 42);
        read.Fb()->NUMBER.value = 3;
        Single<FB_PAC_WRITEREALREG> write(PAC_FB(FB_PAC_WRITEREALREG), t);
        write.Fb()->NUMBER.value = 3;
        write.Fb()->VALUE.value = 2.5F;
        for (int i = 0; i < 3; ++i) {
            const FinalOutcome c = cmd.Run();
            const FinalOutcome r = read.Run();
            const FinalOutcome w = write.Run();
            ASSERT_TRUE(c.Done() && r.Done() && w.Done());
            EXPECT_TRUE(cmd.Plc().Window().Contains(c.Scans())) << c << ", the protocol allows " << cmd.Plc().Window();
            EXPECT_TRUE(read.Plc().Window().Contains(r.Scans())) << r << ", the protocol allows " << read.Plc().Window();
            EXPECT_TRUE(write.Plc().Window().Contains(w.Scans())) << w << ", the protocol allows " << write.Plc().Window();
            EXPECT_EQ(r.Scans(), c.Scans());
            EXPECT_EQ(w.Scans(), c.Scans());
            EXPECT_EQ(read.Fb()->VALUE.value, 42);
        }
    }
}

// ---- Several FBs on one interface, all started in the same scan ----

TEST(ElementFbs, SeveralFbsShareOneInterfaceInTheSameScan) {
    auto writeN = PAC_FB(FB_PAC_WRITEINTREG);
    auto writeR = PAC_FB(FB_PAC_WRITEREALREG);
    auto writeO = PAC_FB(FB_PAC_WRITEOUTPUT);
    auto writeMW = PAC_FB(FB_PAC_WRITEFLAGWORD);
    auto readN = PAC_FB(FB_PAC_READINTREG);
    auto readN2 = PAC_FB(FB_PAC_READINTREG);
    auto readR = PAC_FB(FB_PAC_READREALREG);
    auto readO = PAC_FB(FB_PAC_READOUTPUT);
    auto readM = PAC_FB(FB_PAC_READFLAG);
    auto readI = PAC_FB(FB_PAC_READINPUT);
    auto readState = PAC_FB(FB_PAC_READSTATE);
    auto cmd = PAC_FB(FB_PAC_CMD);
    pac::test::CommandPlc plc(kTiming);
    // Called in this order every scan: the writes come before the reads of the same elements.
    plc.Add("FB_PAC_WriteIntReg", writeN);
    plc.Add("FB_PAC_WriteRealReg", writeR);
    plc.Add("FB_PAC_WriteOutput", writeO);
    plc.Add("FB_PAC_WriteFlagWord", writeMW);
    plc.Add("FB_PAC_ReadIntReg N5", readN);
    plc.Add("FB_PAC_ReadIntReg N6", readN2);
    plc.Add("FB_PAC_ReadRealReg", readR);
    plc.Add("FB_PAC_ReadOutput", readO);
    plc.Add("FB_PAC_ReadFlag", readM);
    plc.Add("FB_PAC_ReadInput", readI);
    plc.Add("FB_PAC_ReadState", readState);
    plc.Add("FB_PAC_Cmd", cmd);
    plc.Start();
    plc.ScanPastFirstHandshake();

    auto& io = plc.Controller().Io();
    io.inputs.Set(3, true);
    io.intRegisters.SetInt(6, 606);
    writeN->NUMBER.value = 5;
    writeN->VALUE.value = -123456;
    writeR->NUMBER.value = 6;
    writeR->VALUE.value = 2.5F;
    writeO->NUMBER.value = 7;
    writeO->VALUE.value = TRUE;
    writeMW->NUMBER.value = 20;  // word 2: M17..M32
    writeMW->VALUE.value = 0x0008;  // M20
    readN->NUMBER.value = 5;
    readN2->NUMBER.value = 6;
    readR->NUMBER.value = 6;
    readO->NUMBER.value = 7;
    readM->NUMBER.value = 20;
    readI->NUMBER.value = 3;
    cmd->CODE.value = 0x0906;
    cmd->PARAM.value = 8;
    cmd->DATA.value = 888;

    const auto recognizedBefore = plc.Controller().Counters().recognized;
    const auto logBefore = plc.Controller().Log().Records().size();  // the cold start's parked read before
    writeN->EXECUTE.value = writeR->EXECUTE.value = writeO->EXECUTE.value = writeMW->EXECUTE.value = TRUE;
    readN->EXECUTE.value = readN2->EXECUTE.value = readR->EXECUTE.value = readO->EXECUTE.value = TRUE;
    readM->EXECUTE.value = readI->EXECUTE.value = readState->EXECUTE.value = cmd->EXECUTE.value = TRUE;
    plc.Scan();
    // Inputs latched at the edge: a change while the FB waits for the interface is not sent.
    EXPECT_TRUE(writeR->BUSY.value);
    writeR->VALUE.value = 99.0F;
    writeN->VALUE.value = 1;

    const auto allDone = [&] {
        return writeN->DONE.value && writeR->DONE.value && writeO->DONE.value && writeMW->DONE.value &&
               readN->DONE.value && readN2->DONE.value && readR->DONE.value && readO->DONE.value &&
               readM->DONE.value && readI->DONE.value && readState->DONE.value && cmd->DONE.value;
    };
    const auto anyError = [&] {
        return writeN->ERROR.value || writeR->ERROR.value || writeO->ERROR.value || writeMW->ERROR.value ||
               readN->ERROR.value || readN2->ERROR.value || readR->ERROR.value || readO->ERROR.value ||
               readM->ERROR.value || readI->ERROR.value || readState->ERROR.value || cmd->ERROR.value;
    };
    ASSERT_GT(plc.Rig().ScanUntil([&] { return allDone() || anyError(); }, 1000), 0);
    ASSERT_FALSE(anyError());
    ASSERT_TRUE(allDone());

    EXPECT_EQ(plc.Controller().Counters().recognized, recognizedBefore + 12) << "one command per FB, no more";
    EXPECT_EQ(plc.Controller().Counters().failed, 0u);
    EXPECT_EQ(io.intRegisters.GetInt(5), -123456);
    EXPECT_EQ(io.realRegisters.Get(6), BitsOf(2.5F));
    EXPECT_TRUE(io.outputs.Get(7));
    EXPECT_EQ(io.flags.Word(17), 0x0008);
    EXPECT_EQ(io.intRegisters.GetInt(8), 888);
    EXPECT_EQ(readN->VALUE.value, -123456);
    EXPECT_EQ(readN2->VALUE.value, 606);
    EXPECT_EQ(BitsOf(readR->VALUE.value), BitsOf(2.5F));
    EXPECT_EQ(readO->VALUE.value, TRUE);
    EXPECT_EQ(readM->VALUE.value, TRUE);
    EXPECT_EQ(readI->VALUE.value, TRUE);
    EXPECT_EQ(readState->OPSTATUS.value, kGvl["PAC_STATUS_HOME_POSITION"]);

    // The controller saw them one after the other, in call order, each with the data of its edge.
    std::vector<CommandFrame> commands;
    const auto& records = plc.Controller().Log().Records();
    for (std::size_t k = logBefore; k < records.size(); ++k) {
        if (records[k].newCommand) commands.push_back(CommandFrame::Decode(records[k].toPac.Cmd()));
    }
    const std::vector<std::uint16_t> expectedCodes = {0x0906, 0x0907, 0x0902, 0x0905, 0x1906, 0x1906,
                                                      0x1907, 0x1902, 0x1904, 0x1900, 0x190B, 0x0906};
    ASSERT_EQ(commands.size(), expectedCodes.size());
    for (std::size_t i = 0; i < commands.size(); ++i) EXPECT_EQ(commands[i].code, expectedCodes[i]) << i;
    EXPECT_EQ(commands[0].data, static_cast<std::uint32_t>(-123456));
    EXPECT_EQ(FloatOf(commands[1].data), 2.5F);
}

}  // namespace
}  // namespace test_element_fbs
