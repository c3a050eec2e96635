// Variables of translated ST: initial values, VAR CONSTANT, VAR_TEMP, EN/ENO and the force flag.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"

namespace {

TEST(ConformanceVariables, InitialValuesOfEveryElementaryType) {
    auto fb = PAC_FB(CONF_INITVALUES);
    // Set by _init__, before any call.
    EXPECT_EQ(fb->VBOOL.value, 1);
    EXPECT_EQ(fb->VBYTE.value, 0xAB);
    EXPECT_EQ(fb->VWORD.value, 0xABCD);
    EXPECT_EQ(fb->VDWORD.value, 0x12345678u);
    EXPECT_EQ(fb->VSINT.value, -100);
    EXPECT_EQ(fb->VINT.value, -30000);
    EXPECT_EQ(fb->VDINT.value, -2000000000);
    EXPECT_EQ(fb->VUSINT.value, 200);
    EXPECT_EQ(fb->VUINT.value, 60000);
    EXPECT_EQ(fb->VUDINT.value, 4000000000u);
    EXPECT_EQ(fb->VREAL.value, 1.5f);
    EXPECT_EQ(fb->VLREAL.value, -2.25);
    EXPECT_EQ(fb->VTIME.value.tv_sec, 2);
    EXPECT_EQ(fb->VTIME.value.tv_nsec, 0);
    EXPECT_EQ(fb->VENUM.value, E_CONFLEVEL__CONF_LVL_MID);
    EXPECT_EQ(fb->INDEFAULT.value, 42);
    fb();
    EXPECT_EQ(fb->VTIME.value.tv_sec, 3);
}

TEST(ConformanceVariables, DefaultsWithoutInitialValues) {
    // Garbage in every byte (0xA5 carries no force bit): _init__ must write every member.
    CONF_INITDEFAULTS fb;
    std::memset(static_cast<void*>(&fb), 0xA5, sizeof fb);
    CONF_INITDEFAULTS_init__(&fb, 0);
    EXPECT_EQ(fb.EN.value, 1);
    EXPECT_EQ(fb.VBOOL.value, 0);
    EXPECT_EQ(fb.VBYTE.value, 0);
    EXPECT_EQ(fb.VWORD.value, 0);
    EXPECT_EQ(fb.VDWORD.value, 0u);
    EXPECT_EQ(fb.VSINT.value, 0);
    EXPECT_EQ(fb.VINT.value, 0);
    EXPECT_EQ(fb.VDINT.value, 0);
    EXPECT_EQ(fb.VUSINT.value, 0);
    EXPECT_EQ(fb.VUINT.value, 0);
    EXPECT_EQ(fb.VUDINT.value, 0u);
    EXPECT_EQ(fb.VREAL.value, 0.0f);
    EXPECT_EQ(fb.VLREAL.value, 0.0);
    EXPECT_EQ(fb.VTIME.value.tv_sec, 0);
    EXPECT_EQ(fb.VTIME.value.tv_nsec, 0);
    EXPECT_EQ(fb.VENUM.value, E_CONFPHASE__CONF_PH_IDLE);
}

TEST(ConformanceVariables, VarConstantInExpressionsBoundsAndIndices) {
    auto fb = PAC_FB(CONF_VARCONSTANT);
    fb();
    EXPECT_EQ(fb->AREA.value, -36);
    EXPECT_EQ(fb->LAST.value, 5);
    EXPECT_EQ(fb->LABEL.value, 0xCAFE);
    EXPECT_EQ(fb->DELAY.value.tv_sec, 0);
    EXPECT_EQ(fb->DELAY.value.tv_nsec, 500000000);
    EXPECT_EQ(fb->RATIO.value, 1.5f);
}

TEST(ConformanceVariables, VarTempRestartsVarKeepsItsValue) {
    auto fb = PAC_FB(CONF_VARTEMP);
    fb();
    EXPECT_EQ(fb->TEMPOUT.value, 11);
    EXPECT_EQ(fb->TEMPZEROOUT.value, 1);
    EXPECT_EQ(fb->KEPTOUT.value, 11);
    fb();
    fb();
    EXPECT_EQ(fb->TEMPOUT.value, 11);
    EXPECT_EQ(fb->TEMPZEROOUT.value, 1);
    EXPECT_EQ(fb->KEPTOUT.value, 13);
}

TEST(ConformanceVariables, EnFalseSkipsTheBody) {
    auto fb = PAC_FB(CONF_ENENO);
    EXPECT_EQ(fb->EN.value, 1);  // _init__ enables the instance
    fb();
    EXPECT_EQ(fb->COUNT.value, 1);
    EXPECT_EQ(fb->ENO.value, 1);
    fb->EN.value = 0;
    fb();
    fb();
    EXPECT_EQ(fb->COUNT.value, 1);
    EXPECT_EQ(fb->ENO.value, 0);
    fb->EN.value = 1;
    fb();
    EXPECT_EQ(fb->COUNT.value, 2);
    EXPECT_EQ(fb->ENO.value, 1);
}

TEST(ConformanceVariables, ForcedMembersAreNotWritten) {
    auto fb = PAC_FB(CONF_FORCEFLAG);
    fb->FORCED.flags = 0x02;
    fb->FORCED.value = -5;
    fb->FORCEDPAIR.flags = 0x02;
    fb->FORCEDPAIR.value.A = 1;
    fb->FORCEDPAIR.value.B = 2;
    fb();  // Value = 7
    EXPECT_EQ(fb->PLAIN.value, 7);
    EXPECT_EQ(fb->FORCED.value, -5);
    EXPECT_EQ(fb->FORCEDPAIR.value.A, 1);  // member writes of a forced struct are skipped too
    EXPECT_EQ(fb->FORCEDPAIR.value.B, 2);
    EXPECT_EQ(fb->COPY.value, -5);  // reads see the forced value
    EXPECT_EQ(fb->HIDDEN.value, 7);
    fb->HIDDEN.flags = 0x02;
    fb->HIDDEN.value = 100;
    fb();
    EXPECT_EQ(fb->HIDDEN.value, 100);  // private variables can be forced as well
    fb->FORCED.flags = 0;
    fb->HIDDEN.flags = 0x01;  // other flag bits do not block writes
    fb();
    EXPECT_EQ(fb->FORCED.value, 7);
    EXPECT_EQ(fb->COPY.value, 7);
    EXPECT_EQ(fb->HIDDEN.value, 107);
}

}  // namespace

namespace {

std::string AsText(const STRING& s) { return std::string(reinterpret_cast<const char*>(s.body), s.len); }

TEST(ConformanceStrings, LiteralsEscapesAndComparisons) {
    auto fb = PAC_FB(CONF_STRINGBASIC);
    EXPECT_EQ(AsText(fb->TAB.value), "a\tb");
    EXPECT_EQ(AsText(fb->EMPTY.value), "");
    fb();
    EXPECT_EQ(AsText(fb->TEXT.value), "Good 'day' $1");
    EXPECT_TRUE(fb->SAME.value);
    EXPECT_FALSE(fb->DIFFERENT.value);
}

}  // namespace
