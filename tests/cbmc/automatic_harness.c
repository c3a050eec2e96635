/* Bounded model-checking harness of FB_PAC_AutomaticModule on one 12-byte module in AUTOMATIC mode (manual
 * 2.6, 6.4), on the C that pacst generates from st/, for K scans (docs/verification.md). Free in every scan:
 * whether the FB is called (a CASE step or an IF branch leaves it out: nothing of it runs), a PLC restart (the
 * FB and the module back to their cold-start values), the operating status OpStatus (every value: a status 0
 * for a single scan, a controller restart), the controller's 12 module bytes, the programmer's FlagWord
 * and IntRegister (every value), RealRegister (five values: in range, beyond the integer format, infinite),
 * IntegerMode, Layout (both values), AxisOwnsModule, and another writer (an axis FB called before this one)
 * putting any 12 bytes on the module before the call. Properties "AM<n>", reachability checks "reach: ..."
 * (which must FAIL), as in cmd_harness.c. */
#include "harness.h"

#ifndef CBMC__K
#define CBMC__K 3
#endif

/* RealRegister's values and the R field each must give, IEEE REAL and DINT x 1000 (manual 2.5.3); 0 where
 * the format cannot carry the value (the FB then refuses it and keeps the last one that fitted). */
#define REALS 5
static const float reals[REALS] = {0.0f, 640.0f, -640.0f, 3.0e6f, __builtin_inff()};
static const unsigned realIeee[REALS] = {0u, 0x44200000u, 0xC4200000u, 0x4A371B00u, 0u};
static const unsigned realInt[REALS] = {0u, 640000u, 0xFFF63C00u, 0u, 0u};
static const BOOL realFitsIeee[REALS] = {1, 1, 1, 1, 0};
static const BOOL realFitsInt[REALS] = {1, 1, 1, 0, 0};

/* The timeline of a counterexample (paccbmc): assigned at the end of every scan, tl_scan last. */
static unsigned long long tl_from_pac, tl_to_pac;
static int tl_op_status, tl_layout, tl_real;
static unsigned tl_n_data, tl_r_data;
static BOOL tl_integer_mode, tl_axis_owns, tl_other_writer, tl_in_exchange, tl_error;
static WORD tl_errorid;
static int tl_scan;

static BOOL Automatic(BYTE status) { return status >= 10 && status <= 19; }
static unsigned Word(const BYTE *m, int i) { return ((unsigned)m[i] << 8) | m[i + 1]; }
static unsigned Dword(const BYTE *m, int i) { return (Word(m, i) << 16) | Word(m, i + 2); }
static BOOL SameImage(const BYTE *a, const BYTE *b) {
    BOOL same = TRUE;
    for (int i = 0; i < 12; ++i) same = same && a[i] == b[i];
    return same;
}
static unsigned RealBits(REAL r) { /* compared by its bits: a NaN received equals itself */
    union { REAL r; unsigned u; } v;
    v.r = r;
    return v.u;
}

int main(void) {
    static FB_PAC_AUTOMATICMODULE fb, fresh;
    BOOL holding = FALSE;  /* the FB wrote the module in AUTOMATIC and no status outside it (and 0) came since */
    BYTE written[12] = {0}; /* what the FB wrote last in AUTOMATIC */
    long keptN = 0;         /* the last IntRegister that fitted: N k */
    int keptR = 0;          /* the last RealRegister that fitted (index into reals; the FB starts at 0.0) */
    int reachExchange = 0, reachRange = 0, reachClear = 0, reachLeftAlone = 0;
    int reachSkipped = 0, reachPlcRestart = 0, reachBlip = 0;
    BOOL zeroAfterAutomatic = FALSE; /* the last call saw status 0 after one in AUTOMATIC */

    __CURRENT_TIME = __time_make(0, 0);
    FB_PAC_AUTOMATICMODULE_init__(&fresh, FALSE);
    fb = fresh;

    for (int n = 1; n <= CBMC__K; ++n) {
        __CURRENT_TIME = __time_make(0, (long)n * CYCLE_NS);
        /* A PLC cold start: the FB instance and the module image back to their initial values. */
        if (n > 1 && nondet_bool()) {
            fb = fresh;
            holding = FALSE;
            for (int i = 0; i < 12; ++i) written[i] = 0;
            keptN = 0;
            keptR = 0;
            zeroAfterAutomatic = FALSE;
            reachPlcRestart = 1;
        }
        if (!nondet_bool()) { /* left out of this scan: nothing of it runs, its module stays as it is */
            if (holding) reachSkipped = 1;
            tl_scan = n;
            continue;
        }
        const BYTE status = nondet_uchar();
        fb.OPSTATUS.value = status;
        for (int i = 0; i < 12; ++i) fb.FROMPAC.value.table[i] = nondet_uchar();
        fb.FLAGWORD.value = (WORD)(((unsigned)nondet_uchar() << 8) | nondet_uchar());
        const unsigned nBits = ((unsigned)nondet_uchar() << 24) | ((unsigned)nondet_uchar() << 16)
                               | ((unsigned)nondet_uchar() << 8) | nondet_uchar();
        fb.INTREGISTER.value = (DINT)nBits;
        const int real = nondet_uchar() % REALS;
        fb.REALREGISTER.value = reals[real];
        const BOOL integerMode = nondet_bool();
        fb.INTEGERMODE.value = integerMode;
        const BOOL wide = nondet_bool(); /* PAC_AUTOLAYOUT_FW2_N4: N in 32 bits */
        fb.LAYOUT.value = wide ? E_PAC_AUTOLAYOUT__PAC_AUTOLAYOUT_FW2_N4 : E_PAC_AUTOLAYOUT__PAC_AUTOLAYOUT_FW4_N2;
        const BOOL axisOwns = nondet_bool();
        fb.AXISOWNSMODULE.value = axisOwns;
        /* Another writer on the same module, called before this FB (an axis FB): any bytes. */
        const BOOL other = nondet_bool();
        if (other)
            for (int i = 0; i < 12; ++i) fb.TOPAC.value.table[i] = nondet_uchar();
        BYTE before[12];
        for (int i = 0; i < 12; ++i) before[i] = fb.TOPAC.value.table[i];
        const WORD flagsBefore = fb.RECEIVEDFLAGWORD.value;
        const DINT intBefore = fb.RECEIVEDINTREGISTER.value;
        const unsigned realBefore = RealBits(fb.RECEIVEDREALREGISTER.value);
        const BOOL own = SameImage(before, written);
        const BOOL firstAfter = holding && status != 0 && !Automatic(status);

        FB_PAC_AUTOMATICMODULE_body__(&fb);

        const BYTE *out = fb.TOPAC.value.table;
        static const BYTE zeros[12] = {0};
        const BOOL same = SameImage(out, before), zero = SameImage(out, zeros);
        tl_op_status = status;
        tl_from_pac = Bytes8(fb.FROMPAC.value.table);
        tl_layout = wide;
        tl_integer_mode = integerMode;
        tl_axis_owns = axisOwns;
        tl_other_writer = other;
        tl_n_data = nBits;
        tl_real = real;
        tl_in_exchange = fb.INEXCHANGE.value;
        tl_error = fb.ERROR.value;
        tl_errorid = fb.ERRORID.value;
        tl_to_pac = Bytes8(out);
        tl_r_data = Dword(out, 8);
        tl_scan = n;

        /* AM1: the module is the FB's in the AUTOMATIC statuses 10..19 only (manual 2.6, 6.4); outside them it
         * changes it at most once, to all zero, in the first scan after AUTOMATIC (AM2). */
        __CPROVER_assert(Automatic(status) || same || (firstAfter && zero),
                         "AM1 the module written only in AUTOMATIC statuses (and cleared once after)");
        /* AM2: in the first scan after AUTOMATIC the module is all zero, unless an axis FB owns it or the bytes
         * are no longer the FB's own: then it is left as it was. */
        __CPROVER_assert(!firstAfter || axisOwns || !own || zero,
                         "AM2 the FB's own bytes cleared in the first scan after AUTOMATIC");
        __CPROVER_assert(!firstAfter || !(axisOwns || !own) || same,
                         "AM2 a module an axis FB owns (or other bytes) left alone after AUTOMATIC");
        /* AM3: status 0 (a lost link) changes nothing: the module and the received values stay. */
        __CPROVER_assert(status != 0 || same, "AM3 status 0 leaves the module as it was");
        __CPROVER_assert(Automatic(status)
                             || (fb.RECEIVEDFLAGWORD.value == flagsBefore && fb.RECEIVEDINTREGISTER.value == intBefore
                                 && RealBits(fb.RECEIVEDREALREGISTER.value) == realBefore),
                         "AM6 the received values change only in AUTOMATIC");
        __CPROVER_assert(fb.INEXCHANGE.value == Automatic(status), "AM6 InExchange exactly in AUTOMATIC statuses");

        /* AM4: a value its field cannot carry sets Error with 16#8020, and the field carries the last value that
         * fitted, or 0 where the layout or format in force cannot carry that either: never a cut value. */
        const long nValue = (long)(DINT)nBits;
        const BOOL fitsN = wide || (nValue >= -32768 && nValue <= 32767);
        const BOOL fitsR = integerMode ? realFitsInt[real] : realFitsIeee[real];
        if (Automatic(status)) {
            if (fitsN) keptN = nValue;
            if (fitsR) keptR = real;
            __CPROVER_assert(fb.ERROR.value == (!fitsN || !fitsR),
                             "AM4 Error exactly when a value does not fit its field");
            __CPROVER_assert(!fb.ERROR.value || fb.ERRORID.value == 0x8020, "AM4 a value out of range is 16#8020");
            const unsigned nField = wide ? Dword(out, 4) : Word(out, 6);
            const unsigned nExpected =
                wide ? (unsigned)keptN : (keptN >= -32768 && keptN <= 32767 ? (unsigned)keptN & 0xFFFFu : 0u);
            __CPROVER_assert(nField == nExpected && (wide || Word(out, 4) == 0),
                             "AM4 the N field carries the last value that fitted, never a cut one");
            const unsigned rExpected = integerMode ? realInt[keptR] : realIeee[keptR];
            __CPROVER_assert(Dword(out, 8) == rExpected,
                             "AM4 the R field carries the last value that fitted, in the format in force");
            const unsigned flagField = wide ? Word(out, 0) : Word(out, 2);
            __CPROVER_assert(flagField == fb.FLAGWORD.value && (wide ? Word(out, 2) : Word(out, 0)) == 0,
                             "AM4 the flag word in its field, the unused bytes 0");
            /* The reply, in the layout in force (2.6.2). */
            const BYTE *in = fb.FROMPAC.value.table;
            __CPROVER_assert(fb.RECEIVEDFLAGWORD.value == (wide ? Word(in, 0) : Word(in, 2))
                                 && fb.RECEIVEDINTREGISTER.value
                                        == (wide ? (DINT)Dword(in, 4) : (DINT)(short)Word(in, 6)),
                             "AM6 the received flags and N as the reply carries them");
        } else {
            __CPROVER_assert(!fb.ERROR.value, "AM6 no Error outside AUTOMATIC");
        }
        /* AM5: Error always with an ErrorID, and the library as its source. */
        __CPROVER_assert(!fb.ERROR.value || fb.ERRORID.value != 0, "AM5 Error implies ErrorID <> 0");
        __CPROVER_assert(fb.ERROR.value || fb.ERRORID.value == 0, "AM5 no ErrorID without Error");
        __CPROVER_assert(fb.ERRORSOURCE.value
                             == (fb.ERROR.value ? E_PAC_ERRORSOURCE__PAC_ERRSRC_LIBRARY : E_PAC_ERRORSOURCE__PAC_ERRSRC_NONE),
                         "AM5 ErrorSource LIBRARY with Error, NONE without");

        if (fb.INEXCHANGE.value) reachExchange = 1;
        if (fb.ERROR.value) reachRange = 1;
        if (firstAfter && zero && !same) reachClear = 1;
        if (firstAfter && same && !zero) reachLeftAlone = 1;
        if (zeroAfterAutomatic && Automatic(status) && fb.INEXCHANGE.value) reachBlip = 1;
        if (status == 0) zeroAfterAutomatic = zeroAfterAutomatic || holding;
        else zeroAfterAutomatic = FALSE;

        /* What the FB holds for the next scan. */
        if (Automatic(status)) {
            holding = TRUE;
            for (int i = 0; i < 12; ++i) written[i] = out[i];
        } else if (status != 0) {
            holding = FALSE;
        }
    }
    __CPROVER_assert(!reachExchange, "reach: in exchange");
    __CPROVER_assert(!reachRange, "reach: Error for a value out of range");
    __CPROVER_assert(!reachClear, "reach: the module cleared after AUTOMATIC");
    __CPROVER_assert(!reachLeftAlone, "reach: a hand-over after AUTOMATIC left alone");
    __CPROVER_assert(!reachSkipped, "reach: the FB left out of a scan in AUTOMATIC");
    __CPROVER_assert(!reachPlcRestart, "reach: a PLC restart");
    __CPROVER_assert(!reachBlip, "reach: AUTOMATIC again after a single scan of status 0");
    return 0;
}
