/* The waiting scans of a harness whose FBs count nothing but time, and that only through TONs (-DCBMC__STUTTER=1:
 * the axis harness; docs/verification.md, "the waiting scans"). As in stutter.h, a scan is waiting when its inputs,
 * and whether the FB is called, are those of the scan before and it passes no limit; still when, besides, it
 * changes nothing of the FB but its TONs' counters. Here the FB is compared whole, word by word, after those
 * counters are set to the scan before's (StillFb): a field added to the FB is compared without a list to keep.
 * A TON's counters are CURRENT_TIME and ET in a scan that runs it as the scan before did, and START_TIME when it
 * is restarted in both (a TON that measures the scan time). S1 (in the harness): a waiting scan after a still
 * one is still. On S1 rests TonStretch, which puts up to CBMC__STRETCH_MAX still scans in a step. */
#ifndef PAC_CBMC_STUTTER_TON_H
#define PAC_CBMC_STUTTER_TON_H

#include "stutter.h" /* Ns, TonBelowLimit */

/* A TON run (its CURRENT_TIME the scan's clock) and restarted (timing since this scan) in a scan. */
static BOOL TonRan(const TON *t, long long nowNs) { return Ns(t->CURRENT_TIME.value) == nowNs; }
static BOOL TonRestarted(const TON *t, long long nowNs) {
    return TonRan(t, nowNs) && t->STATE.value == 1 && Ns(t->START_TIME.value) == nowNs;
}

/* b the TON after the scan before (at beforeNs), a after this scan (at nowNs), in a copy of the FB: a's counters
 * set to b's where they moved as counters. FALSE when the TON ran or restarted in one of the scans only: a real
 * change, which the stretch's counters (TonStretch) could not follow. */
static BOOL TonCountersAlong(const TON *b, TON *a, long long beforeNs, long long nowNs) {
    const BOOL ranB = TonRan(b, beforeNs), ranA = TonRan(a, nowNs);
    const BOOL restartedB = TonRestarted(b, beforeNs), restartedA = TonRestarted(a, nowNs);
    if (ranB && ranA) {
        a->CURRENT_TIME = b->CURRENT_TIME;
        a->ET = b->ET; /* CURRENT_TIME - START_TIME while timing, PT or 0 else: compared through those */
    }
    if (restartedB && restartedA) a->START_TIME = b->START_TIME;
    return ranB == ranA && restartedB == restartedA;
}

/* The FB and its copy after the counters were set, 64 bits at a time (the structs' sizes are multiples of 8). */
static BOOL SameWords(const void *a, const void *b, unsigned long bytes) {
    const unsigned long long *p = (const unsigned long long *)a, *q = (const unsigned long long *)b;
    unsigned long long diff = 0;
    for (unsigned long i = 0; i < bytes / 8; ++i) diff |= p[i] ^ q[i];
    return diff == 0;
}

/* A limit a TON may pass besides its Q: ET reaching boundNs (a comparison in the FB). In a scan (check): the
 * same side before and after; in a stretch: the same side at the still scan (stillNs) and at the stretch's last
 * scan (lastNs), for a TON timing that the still scan ran. */
static BOOL TonSameSide(const TON *t, long long stillNs, long long lastNs, long long boundNs) {
    const long long start = Ns(t->START_TIME.value);
    return t->STATE.value != 1 || !TonRan(t, stillNs) || ((stillNs - start >= boundNs) == (lastNs - start >= boundNs));
}

/* A stretch for one TON: d scans like the still scan (at stillNs) up to lastNs. One the still scan did not run is
 * not run in them either (S1: a TON runs in a still scan's successor as in the still scan); one it ran stays
 * below its PT (no limit passes: assumed), runs to lastNs, restarted in each if it was restarted in the still
 * scan. Its fields are then those of the d scans run one by one. */
static void TonStretch(TON *t, long long stillNs, long long lastNs) {
    if (!TonRan(t, stillNs)) return;
    if (TonRestarted(t, stillNs)) t->START_TIME.value = __time_make(0, lastNs);
    __CPROVER_assume(TonBelowLimit(t, stillNs, lastNs));
    t->CURRENT_TIME.value = __time_make(0, lastNs);
    if (t->STATE.value == 1) t->ET.value = __time_make(0, lastNs - Ns(t->START_TIME.value));
}

/* The waiting scans' reachability checks (S1 is not vacuous, a stretch is taken), for -DCBMC__STUTTER=1 runs. */
typedef struct {
    BOOL waiting; /* S1 was asserted: a waiting scan after a still one */
    BOOL stretch; /* a stretch of two scans or more was taken */
} StutterReach;
static void AssertStutterReached(const StutterReach *r) {
    __CPROVER_assert(!r->waiting, "reach: a waiting scan after a still one");
    __CPROVER_assert(!r->stretch, "reach: a stretch of two waiting scans or more in one step");
}

#endif
