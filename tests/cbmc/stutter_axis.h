/* The waiting scans of FB_PAC_Axis (stutter_ton.h), for the axis harness and the MC harness, whose FB_PAC_McAxis
 * runs it: its TONs, the one limit it compares a TON's ET with, and the stretch (docs/verification.md, "the
 * waiting scans"). */
#ifndef PAC_CBMC_STUTTER_AXIS_H
#define PAC_CBMC_STUTTER_AXIS_H

#include "stutter_ton.h"

#ifndef CBMC__STUTTER /* the waiting scans compressed, S1 checked in the same run */
#define CBMC__STUTTER 0
#endif
#ifndef CBMC__STRETCH_MAX /* a stretch: 0..STRETCH_MAX more scans in one step (a power of 2 less 1) */
#define CBMC__STRETCH_MAX 15
#endif
#ifndef CBMC__TSLOW /* 0: Timeout 1 .. TMAX ms only; else TSLOW .. TSLOW + TMAX - 1 ms as well */
#define CBMC__TSLOW 0
#endif
/* The slowest bus of the suites (tests/support/bus_timing.hpp: a 1 ms PLC cycle, a 10 ms controller cycle, 3 scans
 * of latency each way): ACTIVE answers a Start up to 3 + 9 + 3 scans after the scan that wrote it, read in the
 * scan after: 16 ms. */
#define SLOW_TAKEOVER_MS 16

/* The FB's TONs (the S1 check fails on a TON left out here: its counters then differ). */
#define AXIS_TONS 5
static TON *AxisTons(FB_PAC_AXIS *a, int k) {
    switch (k) {
    case 0: return &a->HANDSHAKE.STEPTIMER;
    case 1: return &a->TAKEOVER.SCANTIMER;
    case 2: return &a->TAKEOVER.STARTLOWTIMER;
    case 3: return &a->RESETPULSE.PULSETIMER;
    default: return &a->RESETPULSE.LOWTIMER;
    }
}

/* The one limit besides the TONs' Q (FB_PAC_AxisHandshake: AnswerDue and the take-over without ACTIVE): the step
 * timer's ET reaching the take-over bound. */
static long long BoundNs(const FB_PAC_AXIS *a) { return Ns(a->HANDSHAKE.TAKEOVERBOUND.value); }
static BOOL Due(const FB_PAC_AXIS *a) { return Ns(a->HANDSHAKE.STEPTIMER.ET.value) >= BoundNs(a); }

/* after, a copy of the FB after a scan (at nowNs), with its counters set to before's (the FB after the scan
 * before, at beforeNs) where they moved as counters: the TONs' (TonCountersAlong) and the take-over's
 * AnswerTime, which follows the step timer's ET in every scan of WAIT_TAKEOVER and is read only with Answered
 * (FB_PAC_AxisTakeover). FALSE when a TON ran or restarted in one of the scans only. */
static BOOL AxisCountersAlong(const FB_PAC_AXIS *before, FB_PAC_AXIS *after, long long beforeNs, long long nowNs) {
    BOOL along = TRUE;
    for (int k = 0; k < AXIS_TONS; ++k)
        along = TonCountersAlong(AxisTons((FB_PAC_AXIS *)before, k), AxisTons(after, k), beforeNs, nowNs) && along;
    if (!before->HANDSHAKE.ANSWERED.value && !after->HANDSHAKE.ANSWERED.value && !before->TAKEOVER.ANSWERED.value
        && !after->TAKEOVER.ANSWERED.value) {
        after->HANDSHAKE.ANSWERTIME = before->HANDSHAKE.ANSWERTIME;
        after->TAKEOVER.ANSWERTIME = before->TAKEOVER.ANSWERTIME;
    }
    return along;
}

/* No limit passes in the scan: every TON's Q and the take-over bound's side as before. */
static BOOL AxisNoLimitPasses(FB_PAC_AXIS *before, FB_PAC_AXIS *after) {
    BOOL same = Due(before) == Due(after);
    for (int k = 0; k < AXIS_TONS; ++k) same = same && AxisTons(before, k)->Q.value == AxisTons(after, k)->Q.value;
    return same;
}

/* d more scans like the still one (at stillNs) in one step: each TON as TonStretch, the take-over bound's side
 * unchanged to the last of them. The stale AnswerTime is not read before it is written again (above). */
static void AxisStretch(FB_PAC_AXIS *a, unsigned d, long long stillNs) {
    const long long lastNs = stillNs + (long long)d * CYCLE_NS;
    __CPROVER_assume(TonSameSide(&a->HANDSHAKE.STEPTIMER, stillNs, lastNs, BoundNs(a)));
    for (int k = 0; k < AXIS_TONS; ++k) TonStretch(AxisTons(a, k), stillNs, lastNs);
}

#endif
