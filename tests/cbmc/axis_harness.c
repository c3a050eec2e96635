/* Bounded model-checking harness of FB_PAC_Axis on its 12-byte axis module (manual 2.7), on the C that pacst
 * generates from st/, for K scans (docs/verification.md). Free in every scan: the operating status OpStatus,
 * the controller's status word and error numbers (module bytes 0..7; the position bytes 8..11 stay 0, which
 * keeps floating point out of the proof), ModeChange, and the programmer's Enable, Execute, Command (the jog
 * buttons only with -DCBMC__JOGS), Abort, ResetError, DisableDrive, DisableLimitSwitches, ChangeDynamics, Velocity and Acceleration
 * (a few values each, in and out of range); per run Position (two values), IntegerMode,
 * DynamicsChangeable, Timeout and StopTimeout (1..TMAX ms). Free too whether the FB is called in a scan (a CASE
 * step or an IF branch leaves it out: its pins and images then unchanged, and what it knows of the operating
 * status is what it saw when called; FB_PAC_Axis.md, "Calling contract"), and a PLC restart (the FB and its
 * module back to their cold-start values). With -DCBMC__LONG_SKIPS=1 a step the FB is left out of stands for up to
 * CBMC__STRETCH_MAX + 1 scans (nothing of it runs in them: the clock alone goes on); with -DCBMC__STUTTER=1 besides,
 * the scans in which the PLC only waits are compressed (stutter_axis.h: after a still scan up to CBMC__STRETCH_MAX
 * more in one step, S1 checked in the same run);
 * -DCBMC__TSLOW=<ms> lets Timeout be TSLOW .. TSLOW + TMAX - 1 ms as well, long enough for the take-over on the
 * slowest bus of the suites. Properties "P<n>"/"A<n>", reachability checks "reach: ..." (which must FAIL), as
 * in cmd_harness.c. */
#include "harness.h"
#include "stutter_axis.h"

#ifndef CBMC__K
#define CBMC__K 6
#endif
#ifndef CBMC__TMAX
#define CBMC__TMAX 2
#endif
#ifndef CBMC__PLC_RESTARTS /* 0: no PLC restart (the counterexamples recorded before it was free replay so) */
#define CBMC__PLC_RESTARTS 1
#endif
#ifndef CBMC__LONG_SKIPS /* a step left out stands for 1 .. STRETCH_MAX + 1 scans left out (STUTTER: too) */
#define CBMC__LONG_SKIPS CBMC__STUTTER
#endif

/* The traverse bits of the control word (2.7.1): 3..7 and 12..15 the jobs, 10 and 11 the jogs. */
#define TRAVERSE_BITS 0xFCF8u

/* The timeline of a counterexample (paccbmc): assigned at the end of every scan, tl_scan last. */
static unsigned long long tl_from_pac, tl_to_pac;
static int tl_op_status, tl_command;
static BOOL tl_enable, tl_execute, tl_jog_pos, tl_jog_neg, tl_abort;
static int tl_scan;

/* Still (stutter_axis.h): the FB after the call (at nowNs) is the FB before it (at beforeNs) but for counters. */
static FB_PAC_AXIS normalised;
static BOOL StillAxis(const FB_PAC_AXIS *before, const FB_PAC_AXIS *after, long long beforeNs, long long nowNs) {
    normalised = *after;
    const BOOL along = AxisCountersAlong(before, &normalised, beforeNs, nowNs);
    return along && SameWords(&normalised, before, sizeof normalised);
}

static BOOL Owns(BYTE status) { return status == 1 || status == 9 || (status >= 30 && status <= 39); }

/* What the program and the controller hand the FB in a scan: a waiting scan's are those of the scan before. */
typedef struct {
    BYTE fromPac[8], opStatus;
    BOOL modeChange, enable, execute, jogPositive, jogNegative, abort, resetError, disableDrive, disableLimitSwitches,
        changeDynamics;
    E_PAC_AXISCOMMAND command;
    UINT velocity, acceleration;
} Inputs;
static Inputs InputsOf(const FB_PAC_AXIS *a) {
    Inputs in;
    for (int i = 0; i < 8; ++i) in.fromPac[i] = a->FROMPAC.value.table[i];
    in.opStatus = a->OPSTATUS.value;
    in.modeChange = a->MODECHANGE.value;
    in.enable = a->ENABLE.value;
    in.execute = a->EXECUTE.value;
    in.jogPositive = a->JOGPOSITIVE.value;
    in.jogNegative = a->JOGNEGATIVE.value;
    in.abort = a->ABORT.value;
    in.resetError = a->RESETERROR.value;
    in.disableDrive = a->DISABLEDRIVE.value;
    in.disableLimitSwitches = a->DISABLELIMITSWITCHES.value;
    in.changeDynamics = a->CHANGEDYNAMICS.value;
    in.command = a->COMMAND.value;
    in.velocity = a->VELOCITY.value;
    in.acceleration = a->ACCELERATION.value;
    return in;
}
static BOOL SameInputs(const Inputs *a, const Inputs *b) {
    BOOL same = a->opStatus == b->opStatus && a->modeChange == b->modeChange && a->enable == b->enable
                && a->execute == b->execute && a->jogPositive == b->jogPositive && a->jogNegative == b->jogNegative
                && a->abort == b->abort && a->resetError == b->resetError
                && a->disableDrive == b->disableDrive && a->disableLimitSwitches == b->disableLimitSwitches
                && a->changeDynamics == b->changeDynamics && a->command == b->command && a->velocity == b->velocity
                && a->acceleration == b->acceleration;
    for (int i = 0; i < 8; ++i) same = same && a->fromPac[i] == b->fromPac[i];
    return same;
}

int main(void) {
    static FB_PAC_AXIS axis, fresh;
    PlcOpenWatch watch = {0};
    BYTE lastStatus = 0; /* the last operating status other than 0 */
    int reachDone = 0, reachLibError = 0, reachPacError = 0, reachAborted = 0;
    static const WORD velocities[] = {0, 500, 1000, 1001};
    static const WORD accelerations[] = {0, 1000};

    __CURRENT_TIME = __time_make(0, 0);
    FB_PAC_AXIS_init__(&fresh, FALSE);
    unsigned t = 1 + nondet_uchar() % CBMC__TMAX;
    const unsigned st = 1 + nondet_uchar() % CBMC__TMAX;
    if (CBMC__TSLOW > 0 && nondet_bool()) t += CBMC__TSLOW - 1; /* the slowest bus's take-over fits */
    fresh.TIMEOUT.value = __time_make(0, (long)t * CYCLE_NS);
    fresh.STOPTIMEOUT.value = __time_make(0, (long)st * CYCLE_NS);
    fresh.POSITION.value = nondet_bool() ? 10.5f : 0.0f;
    fresh.INTEGERMODE.value = nondet_bool();
    fresh.DYNAMICSCHANGEABLE.value = nondet_bool();
    axis = fresh;
    watch.bound = 1000; /* a move takes as long as the axis moves: no Busy bound of its own (A4, A5 instead) */
    int abortScans = 0;        /* Busy scans since Abort rose during a job, Abort TRUE since */
    int waitScans = 0;         /* Busy scans of the job without ACTIVE since its edge (before the take-over) */
    BOOL takenOver = FALSE;    /* the job saw ACTIVE */
    int reachAbortEnded = 0;
    BOOL activeSinceStart = FALSE; /* ACTIVE seen since Start last rose on the wire */
    BOOL leftSinceStart = FALSE;   /* a known status other than ONLINE running (31) seen since then */
    int reachRefusedNotOnline = 0, reachSkippedBusy = 0, reachPlcRestart = 0, reachDoneAfterSkip = 0;
    BOOL skippedWhileBusy = FALSE;
    long edgeMs = -1000;      /* the clock at the job's Execute edge, where its wait began */
    int reachTimedOutAfterSkip = 0;
    BOOL skippedSinceEdge = FALSE;
    /* The waiting scans and the scans left out (CBMC__LONG_SKIPS, CBMC__STUTTER): the clock is n + stretched ms. */
    long stretched = 0;
    static FB_PAC_AXIS before;    /* the FB before this scan's call */
    Inputs prevInputs = InputsOf(&axis); /* the inputs of the last scan the FB was called in */
    BOOL prevCalled = FALSE, prevStill = FALSE;
    int skipRun = 0;              /* scans in a row the FB has been left out while Busy */
    BOOL longSkip = FALSE;        /* a skip of two scans or more since the job's edge */
    long startMs = -1000;         /* the clock when Start last rose on the wire */
    long takeoverMs = 0;          /* ... and when the FB first saw ACTIVE since */
    int reachLongSkip = 0, reachSlowDone = 0;
    StutterReach stutterReach = {FALSE, FALSE};

    for (int n = 1; n <= CBMC__K; ++n) {
        __CURRENT_TIME = __time_make(0, (long)(n + stretched) * CYCLE_NS);
        /* A PLC cold start: the FB instance and its module back to their initial values; what the harness knows
         * of the job starts anew. */
        if (CBMC__PLC_RESTARTS && n > 1 && nondet_bool()) {
            axis = fresh;
            const PlcOpenWatch none = {0};
            watch = none;
            watch.bound = 1000;
            lastStatus = 0;
            abortScans = waitScans = 0;
            takenOver = activeSinceStart = leftSinceStart = FALSE;
            skippedWhileBusy = FALSE;
            edgeMs = -1000;
            startMs = -1000;
            prevCalled = prevStill = FALSE;
            skipRun = 0;
            reachPlcRestart = 1;
        }
        if (!nondet_bool()) { /* left out of this scan: nothing of it runs, its module stays as it is */
            if (axis.BUSY.value) reachSkippedBusy = 1;
            if (axis.BUSY.value) skippedWhileBusy = TRUE;
            if (axis.BUSY.value) skippedSinceEdge = TRUE;
            /* With CBMC__LONG_SKIPS up to STRETCH_MAX more scans left out in this step: nothing runs in them. */
            const unsigned d = CBMC__LONG_SKIPS ? (nondet_uchar() & CBMC__STRETCH_MAX) : 0;
            stretched += (long)d;
            skipRun = axis.BUSY.value ? skipRun + 1 + (int)d : 0;
            if (skipRun >= 2) longSkip = TRUE;
            if (skipRun >= 2) reachLongSkip = 1;
            prevCalled = prevStill = FALSE;
            tl_scan = n;
            continue;
        }
        skipRun = 0;
        for (int i = 0; i < 8; ++i) axis.FROMPAC.value.table[i] = nondet_uchar();
        for (int i = 8; i < 12; ++i) axis.FROMPAC.value.table[i] = 0;
        axis.OPSTATUS.value = nondet_uchar();
        if (axis.OPSTATUS.value != 0) lastStatus = axis.OPSTATUS.value;
        axis.MODECHANGE.value = nondet_bool();
        const BOOL executeBefore = axis.EXECUTE.value, jogPos = axis.JOGPOSITIVE.value, jogNeg = axis.JOGNEGATIVE.value;
        axis.ENABLE.value = nondet_bool();
        axis.EXECUTE.value = nondet_bool();
        const unsigned char command = nondet_uchar() % 10;
        axis.COMMAND.value = (E_PAC_AXISCOMMAND)command;
#ifdef CBMC__JOGS /* the jogs are jobs without Execute: P3/P4 for them are not stated yet (docs/verification.md) */
        axis.JOGPOSITIVE.value = nondet_bool();
        axis.JOGNEGATIVE.value = nondet_bool();
#endif
        axis.ABORT.value = nondet_bool();
        axis.RESETERROR.value = nondet_bool();
        axis.DISABLEDRIVE.value = nondet_bool();
        axis.DISABLELIMITSWITCHES.value = nondet_bool();
        axis.CHANGEDYNAMICS.value = nondet_bool();
        axis.VELOCITY.value = velocities[nondet_uchar() % 4];
        axis.ACCELERATION.value = accelerations[nondet_uchar() % 2];
        /* The waiting scan (stutter_ton.h): called as in the scan before, with its inputs. After a still scan, d
         * more like it go in one step before this one. */
        const Inputs inputs = InputsOf(&axis);
        const BOOL waiting = CBMC__STUTTER && n > 1 && prevCalled && SameInputs(&inputs, &prevInputs);
        prevInputs = inputs;
        prevCalled = TRUE;
        if (CBMC__STUTTER && waiting && prevStill) {
            const unsigned d = nondet_uchar() & CBMC__STRETCH_MAX;
            AxisStretch(&axis, d, (long long)(n - 1 + stretched) * CYCLE_NS);
            /* The properties count d more calls, as the still scan did (A4, A5, P8). */
            if (axis.BUSY.value) watch.busyScans += (int)d;
            if (axis.ABORT.value && axis.BUSY.value) abortScans += (int)d;
            if (axis.BUSY.value && !takenOver) waitScans += (int)d;
            stretched += (long)d;
            __CURRENT_TIME = __time_make(0, (long)(n + stretched) * CYCLE_NS);
            if (d >= 2) stutterReach.stretch = TRUE;
        }
        if (CBMC__STUTTER) before = axis;
        /* A job starts with an Execute edge or a jog button's edge. */
        const BOOL edge = (axis.EXECUTE.value && !executeBefore) || (axis.JOGPOSITIVE.value && !jogPos)
                          || (axis.JOGNEGATIVE.value && !jogNeg);
        const BOOL wasBusy = axis.BUSY.value, doneBefore = axis.DONE.value;
        BYTE module[12];
        for (int i = 0; i < 12; ++i) module[i] = axis.TOPAC.value.table[i];
        FB_PAC_AXIS_body__(&axis);
        if (CBMC__STUTTER) {
            /* Still: a waiting scan that passed no limit and changed nothing but counters. S1: a waiting scan
             * after a still one (after a stretch too) is still, unless it passes a limit. */
            const long long nowNs = (long long)(n + stretched) * CYCLE_NS;
            const BOOL noLimit = waiting && AxisNoLimitPasses(&before, &axis);
            const BOOL still = noLimit && StillAxis(&before, &axis, nowNs - CYCLE_NS, nowNs);
            __CPROVER_assert(!(prevStill && noLimit) || still,
                             "S1 a waiting scan after a still one changes nothing but the TONs' counters");
            if (prevStill && noLimit) stutterReach.waiting = TRUE;
            prevStill = still;
        }
        const long nowMs = n + stretched;

        const BYTE *out = axis.TOPAC.value.table;
        tl_from_pac = Bytes8(axis.FROMPAC.value.table);
        tl_op_status = axis.OPSTATUS.value;
        tl_enable = axis.ENABLE.value;
        tl_execute = axis.EXECUTE.value;
        tl_command = command;
        tl_jog_pos = axis.JOGPOSITIVE.value;
        tl_jog_neg = axis.JOGNEGATIVE.value;
        tl_abort = axis.ABORT.value;
        TimelineOutputs(axis.BUSY.value, axis.DONE.value, axis.ERROR.value, axis.COMMANDABORTED.value,
                        axis.ERRORID.value);
        tl_to_pac = Bytes8(out);
        tl_scan = n;

        CheckPlcOpen(&watch, axis.EXECUTE.value || axis.JOGPOSITIVE.value || axis.JOGNEGATIVE.value, edge,
                     axis.BUSY.value, axis.DONE.value, axis.ERROR.value, axis.COMMANDABORTED.value,
                     axis.ERRORID.value);
        /* A1: the module is the FB's in HOME POSITION and ONLINE only; in any other status it is untouched. */
        BOOL same = TRUE;
        for (int i = 0; i < 12; ++i) same = same && out[i] == module[i];
        __CPROVER_assert(Owns(lastStatus) || same, "A1 the axis module written only in HOME POSITION and ONLINE");
        /* A6: a job only where the controller runs it (2.7: ONLINE): Start rises on the wire only while the last
         * known operating status is 31, ONLINE running. */
        const BOOL startBefore = (module[3] & 0x04u) != 0, startNow = (out[3] & 0x04u) != 0;
        __CPROVER_assert(!(startNow && !startBefore) || lastStatus == 31, "A6 Start rises only in ONLINE running");
        /* A8: no Start after Timeout: the wait for the axis counts Timeout from the job's Execute edge, also for
         * an edge that supersedes a running job (admitted in the next call, D24), and a call that finds it run out
         * (also the first call after the FB was left out past it) ends the job with 16#8006, never raises Start
         * (FB_PAC_Axis.md, "Calling contract"; D22). */
        if (axis.EXECUTE.value && !executeBefore) {
            edgeMs = nowMs;
            skippedSinceEdge = FALSE;
            longSkip = FALSE;
        }
        __CPROVER_assert(!(startNow && !startBefore) || nowMs - edgeMs < (long)t,
                         "A8 no Start once the job's Timeout since its edge ran out");
        if (axis.ERROR.value && axis.ERRORID.value == 0x8006 && skippedSinceEdge) reachTimedOutAfterSkip = 1;
        /* A7: never Done on silence outside ONLINE running: a job that saw no ACTIVE since its Start ends Done
         * only if no known status but 31 was seen since then. */
        if (startNow && !startBefore) {
            activeSinceStart = FALSE;
            leftSinceStart = FALSE;
            startMs = nowMs;
        }
        if (!activeSinceStart && axis.ACTIVE.value) takeoverMs = nowMs;
        activeSinceStart = activeSinceStart || axis.ACTIVE.value;
        leftSinceStart = leftSinceStart || (axis.OPSTATUS.value != 0 && axis.OPSTATUS.value != 31);
        __CPROVER_assert(!(axis.DONE.value && !doneBefore) || activeSinceStart || !leftSinceStart,
                         "A7 Done without ACTIVE only if ONLINE ran since the Start");
        if (axis.ERROR.value && axis.ERRORID.value == 0x8025) reachRefusedNotOnline = 1;
        /* A2: one job at a time: at most one traverse bit in the control word (bytes 0..3). */
        const unsigned word = ((unsigned)out[0] << 24) | ((unsigned)out[1] << 16) | ((unsigned)out[2] << 8) | out[3];
        const unsigned traverse = word & TRAVERSE_BITS;
        __CPROVER_assert((traverse & (traverse - 1u)) == 0, "A2 at most one traverse bit on the wire");
        /* A3: a stop is never lost: while Abort is TRUE no traverse bit is on the wire (the axis brakes,
         * 2.7.3), and the FB is not left locked: every Execute edge the FB sees while not Busy is taken (Busy,
         * or a final output in that scan). */
        __CPROVER_assert(!axis.ABORT.value || !Owns(lastStatus) || traverse == 0,
                         "A3 no traverse bit while Abort is TRUE");
        __CPROVER_assert(!(axis.EXECUTE.value && !executeBefore) || wasBusy || axis.BUSY.value || axis.DONE.value
                             || axis.ERROR.value || axis.COMMANDABORTED.value,
                         "A3 an Execute edge is never left without an output");
        /* A4: a stop ends: Busy lasts at most StopTimeout + 1 scans once Abort is TRUE (16#8022 after
         * StopTimeout, FB_PAC_Axis.md, "A stop ends when ACTIVE has fallen"). */
        abortScans = (axis.ABORT.value && axis.BUSY.value) ? abortScans + 1 : 0;
        __CPROVER_assert(abortScans <= (int)st + 1, "A4 Busy within StopTimeout + 1 scan once Abort is TRUE");
        if (wasBusy && !axis.BUSY.value && axis.ABORT.value) reachAbortEnded = 1;
        /* A5: before the take-over a job waits Timeout at most for the axis to be free (16#8006) and Timeout
         * for ACTIVE (16#8001): Busy without ACTIVE since the edge at most 2 x Timeout + 2 scans. */
        if (edge || !axis.BUSY.value) {
            waitScans = 0;
            takenOver = FALSE;
        }
        takenOver = takenOver || axis.ACTIVE.value;
        waitScans = (axis.BUSY.value && !takenOver) ? waitScans + 1 : 0;
        __CPROVER_assert(waitScans <= 2 * (int)t + 2, "A5 Busy before the take-over within 2 x Timeout + 2 scans");

        if (axis.DONE.value) reachDone = 1;
        if (axis.DONE.value && skippedWhileBusy) reachDoneAfterSkip = 1;
        /* The slowest bus's handshake: ACTIVE seen 16 ms or more after Start rose, Done, a skip of two scans or
         * more since the edge. */
        if (axis.DONE.value && !doneBefore && activeSinceStart && takeoverMs - startMs >= SLOW_TAKEOVER_MS && longSkip)
            reachSlowDone = 1;
        if (!axis.BUSY.value) skippedWhileBusy = FALSE;
        if (axis.ERROR.value && axis.ERRORID.value >= 0x8000) reachLibError = 1;
        if (axis.ERROR.value && axis.ERRORID.value < 0x8000) reachPacError = 1;
        if (axis.COMMANDABORTED.value) reachAborted = 1;
    }
    __CPROVER_assert(!reachDone, "reach: Done");
    __CPROVER_assert(!reachLibError, "reach: Error with a library code");
    __CPROVER_assert(!reachPacError, "reach: Error with the controller's CMD error number");
    __CPROVER_assert(!reachAborted, "reach: CommandAborted");
    __CPROVER_assert(!reachAbortEnded, "reach: a job ended by Abort");
    __CPROVER_assert(!reachRefusedNotOnline, "reach: a job refused outside ONLINE running (16#8025)");
    __CPROVER_assert(!reachSkippedBusy, "reach: the FB left out of a scan while Busy");
#if CBMC__K >= 6 || CBMC__LONG_SKIPS /* edge, Start, ACTIVE, its fall, a scan left out between (or a long skip) */
    __CPROVER_assert(!reachDoneAfterSkip, "reach: Done after a scan left out while Busy");
#else
    (void)reachDoneAfterSkip;
#endif
#if CBMC__PLC_RESTARTS /* 0: the replay of counterexamples recorded before it, and the hand runs with STUTTER */
    __CPROVER_assert(!reachPlcRestart, "reach: a PLC restart");
#else
    (void)reachPlcRestart;
#endif
    __CPROVER_assert(!reachTimedOutAfterSkip, "reach: 16#8006 for a job left out while it waited for the axis");
#if CBMC__STUTTER
    AssertStutterReached(&stutterReach);
#else
    (void)stutterReach;
#endif
#if CBMC__LONG_SKIPS
    __CPROVER_assert(!reachLongSkip, "reach: the FB left out of two scans or more in a row while Busy");
    __CPROVER_assert(!reachSlowDone,
                     "reach: Done after a take-over 16 ms after Start, after a skip of two scans or more");
#else
    (void)reachLongSkip;
    (void)reachSlowDone;
#endif
    return 0;
}
