// Bit-string and BOOL semantics of translated ST: logic operators, shifts and rotations, typed literals.
#include <gtest/gtest.h>

#include <cstdint>

#include "pac/fb_instance.hpp"
#include "pac/st_program.hpp"

namespace {

TEST(ConformanceBits, BoolOperatorsAndPrecedence) {
    auto fb = PAC_FB(CONF_BOOLLOGIC);
    for (int bits = 0; bits < 8; ++bits) {
        const bool a = (bits & 1) != 0;
        const bool b = (bits & 2) != 0;
        const bool c = (bits & 4) != 0;
        fb->A.value = a;
        fb->B.value = b;
        fb->C.value = c;
        fb();
        SCOPED_TRACE(testing::Message() << "A=" << a << " B=" << b << " C=" << c);
        EXPECT_EQ(fb->ANDAB.value, a && b);
        EXPECT_EQ(fb->ORAB.value, a || b);
        EXPECT_EQ(fb->XORAB.value, a != b);
        EXPECT_EQ(fb->NOTA.value, !a);
        EXPECT_EQ(fb->ORXOR.value, a || (b != c));    // XOR binds tighter than OR
        EXPECT_EQ(fb->XORAND.value, a != (b && c));   // AND binds tighter than XOR
        EXPECT_EQ(fb->NOTAND.value, !a && b);         // NOT binds tightest
    }
}

TEST(ConformanceBits, BitwiseOperatorsOnByteWordDword) {
    auto fb = PAC_FB(CONF_BITLOGIC);
    fb();
    EXPECT_EQ(fb->BYTEAND.value, 0x30);
    EXPECT_EQ(fb->BYTEOR.value, 0xFC);
    EXPECT_EQ(fb->BYTEXOR.value, 0xCC);
    EXPECT_EQ(fb->BYTENOT.value, 0x0F);
    EXPECT_EQ(fb->WORDAND.value, 0x0F00);
    EXPECT_EQ(fb->WORDOR.value, 0xFFF0);
    EXPECT_EQ(fb->WORDXOR.value, 0xF0F0);
    EXPECT_EQ(fb->WORDNOT.value, 0x00FF);
    EXPECT_EQ(fb->DWORDAND.value, 0x00FF0000u);
    EXPECT_EQ(fb->DWORDOR.value, 0xFFFFFF00u);
    EXPECT_EQ(fb->DWORDXOR.value, 0xFF00FF00u);
    EXPECT_EQ(fb->DWORDNOT.value, 0x0000FFFFu);
    EXPECT_EQ(fb->BYTEMASKED.value, 0xC1);  // (16#F0 AND NOT 16#3C) OR 16#01
    EXPECT_EQ(fb->WORDBITSET.value, 1);
    fb->W1.value = 0x7FFF;
    fb();
    EXPECT_EQ(fb->WORDBITSET.value, 0);
}

// The expected values of one shift snippet for V and N.
template <class T>
struct ShiftExpect {
    T shl1, shr1, rol1, ror1, shlN, shrN, rolN, rorN, shlOne, rolLit;
};

template <class Fb, class T>
void CheckShifts(Fb& fb, T v, const ShiftExpect<T>& e) {
    EXPECT_EQ(fb->SHL1.value, e.shl1);
    EXPECT_EQ(fb->SHR1.value, e.shr1);
    EXPECT_EQ(fb->ROL1.value, e.rol1);
    EXPECT_EQ(fb->ROR1.value, e.ror1);
    EXPECT_EQ(fb->SHLN.value, e.shlN);
    EXPECT_EQ(fb->SHRN.value, e.shrN);
    EXPECT_EQ(fb->ROLN.value, e.rolN);
    EXPECT_EQ(fb->RORN.value, e.rorN);
    EXPECT_EQ(fb->SHL0.value, v);
    EXPECT_EQ(fb->ROL0.value, v);
    EXPECT_EQ(fb->SHLONE.value, e.shlOne);
    EXPECT_EQ(fb->ROLLIT.value, e.rolLit);
}

TEST(ConformanceBits, ShiftsAndRotationsOnByte) {
    auto fb = PAC_FB(CONF_SHIFTBYTE);
    fb();  // V = 16#81, N = 7
    CheckShifts<decltype(fb), BYTE>(fb, 0x81, {0x02, 0x40, 0x03, 0xC0, 0x80, 0x01, 0xC0, 0x03, 0x80, 0xC0});
    fb->V.value = 0x12;
    fb->N.value = 4;
    fb();
    CheckShifts<decltype(fb), BYTE>(fb, 0x12, {0x24, 0x09, 0x24, 0x09, 0x20, 0x01, 0x21, 0x21, 0x10, 0x09});
}

TEST(ConformanceBits, ShiftsAndRotationsOnWord) {
    auto fb = PAC_FB(CONF_SHIFTWORD);
    fb();  // V = 16#8001, N = 15
    CheckShifts<decltype(fb), WORD>(fb, 0x8001,
                                    {0x0002, 0x4000, 0x0003, 0xC000, 0x8000, 0x0001, 0xC000, 0x0003, 0x8000, 0xC000});
    fb->V.value = 0x1234;
    fb->N.value = 4;
    fb();
    CheckShifts<decltype(fb), WORD>(fb, 0x1234,
                                    {0x2468, 0x091A, 0x2468, 0x091A, 0x2340, 0x0123, 0x2341, 0x4123, 0x0010, 0x091A});
}

TEST(ConformanceBits, ShiftsAndRotationsOnDword) {
    auto fb = PAC_FB(CONF_SHIFTDWORD);
    fb();  // V = 16#80000001, N = 31
    CheckShifts<decltype(fb), DWORD>(fb, 0x80000001u,
                                     {0x00000002u, 0x40000000u, 0x00000003u, 0xC0000000u, 0x80000000u, 0x00000001u,
                                      0xC0000000u, 0x00000003u, 0x80000000u, 0xC0000000u});
    fb->V.value = 0x12345678u;
    fb->N.value = 4;
    fb();
    CheckShifts<decltype(fb), DWORD>(fb, 0x12345678u,
                                     {0x2468ACF0u, 0x091A2B3Cu, 0x2468ACF0u, 0x091A2B3Cu, 0x23456780u, 0x01234567u,
                                      0x23456781u, 0x81234567u, 0x00000010u, 0x091A2B3Cu});
}

TEST(ConformanceBits, TypedAndBasedLiterals) {
    auto fb = PAC_FB(CONF_TYPEDLITERALS);
    fb();
    EXPECT_EQ(fb->WORDHEX.value, 0x8000);
    EXPECT_EQ(fb->INTNEG.value, -5);
    EXPECT_EQ(fb->BYTEBIN.value, 0xAA);
    EXPECT_EQ(fb->INTOCT.value, 15);
    EXPECT_EQ(fb->DWORDHEX.value, 0xDEADBEEFu);
    EXPECT_EQ(fb->DWORDZERO.value, 0u);
    EXPECT_EQ(fb->SINTTYPED.value, -128);
    EXPECT_EQ(fb->USINTTYPED.value, 255);
    EXPECT_EQ(fb->DINTDEC.value, 1000000);
    EXPECT_EQ(fb->UDINTHEX.value, 0xFFFFFFFFu);
    EXPECT_EQ(fb->BYTETYPEDBIN.value, 0xF0);
    EXPECT_EQ(fb->BOOLTYPED.value, 1);
    EXPECT_EQ(fb->DINTBIN.value, -4);
}

}  // namespace
