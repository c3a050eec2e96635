/* Bounded model-checking harness of FB_PAC_Axis on its 12-byte axis module (manual 2.7), on the C that pacst
 * generates from st/, for K scans (docs/verification.md). Free in every scan: the operating status OpStatus,
 * the controller's status word and error numbers (module bytes 0..7; the position bytes 8..11 stay 0, which
 * keeps floating point out of the proof), ModeChange, and the programmer's Enable, Execute, Command (the jog
 * buttons only with -DCBMC__JOGS), Abort, ResetError, DisableDrive, DisableLimitSwitches, ChangeDynamics, Velocity and Acceleration
 * (a few values each, in and out of range); per run Position (two values), IntegerMode,
 * DynamicsChangeable, Timeout and StopTimeout (1..TMAX ms). Free too whether the FB is called in a scan (a CASE
 * step or an IF branch leaves it out: its pins and images then unchanged, and what it knows of the operating
 * status is what it saw when called; FB_PAC_Axis.md, "Calling contract"), and a PLC restart (the FB and its
 * module back to their cold-start values). Properties "P<n>"/"A<n>",
 * reachability checks "reach: ..." (which must FAIL), as in cmd_harness.c. */
#include "harness.h"

#ifndef CBMC__K
#define CBMC__K 6
#endif
#ifndef CBMC__TMAX
#define CBMC__TMAX 2
#endif
#ifndef CBMC__PLC_RESTARTS /* 0: no PLC restart (the counterexamples recorded before it was free replay so) */
#define CBMC__PLC_RESTARTS 1
#endif

/* The traverse bits of the control word (2.7.1): 3..7 and 12..15 the jobs, 10 and 11 the jogs. */
#define TRAVERSE_BITS 0xFCF8u

/* The timeline of a counterexample (paccbmc): assigned at the end of every scan, tl_scan last. */
static unsigned long long tl_from_pac, tl_to_pac;
static int tl_op_status, tl_command;
static BOOL tl_enable, tl_execute, tl_jog_pos, tl_jog_neg, tl_abort;
static int tl_scan;

static BOOL Owns(BYTE status) { return status == 1 || status == 9 || (status >= 30 && status <= 39); }

int main(void) {
    static FB_PAC_AXIS axis, fresh;
    PlcOpenWatch watch = {0};
    BYTE lastStatus = 0; /* the last operating status other than 0 */
    int reachDone = 0, reachLibError = 0, reachPacError = 0, reachAborted = 0;
    static const WORD velocities[] = {0, 500, 1000, 1001};
    static const WORD accelerations[] = {0, 1000};

    __CURRENT_TIME = __time_make(0, 0);
    FB_PAC_AXIS_init__(&fresh, FALSE);
    const unsigned t = 1 + nondet_uchar() % CBMC__TMAX, st = 1 + nondet_uchar() % CBMC__TMAX;
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
    int edgeScan = -1000;     /* the scan of the job's Execute edge, where its wait began */
    int reachTimedOutAfterSkip = 0;
    BOOL skippedSinceEdge = FALSE;

    for (int n = 1; n <= CBMC__K; ++n) {
        __CURRENT_TIME = __time_make(0, (long)n * CYCLE_NS);
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
            edgeScan = -1000;
            reachPlcRestart = 1;
        }
        if (!nondet_bool()) { /* left out of this scan: nothing of it runs, its module stays as it is */
            if (axis.BUSY.value) reachSkippedBusy = 1;
            if (axis.BUSY.value) skippedWhileBusy = TRUE;
            if (axis.BUSY.value) skippedSinceEdge = TRUE;
            tl_scan = n;
            continue;
        }
        for (int i = 0; i < 8; ++i) axis.FROMPAC.value.table[i] = nondet_uchar();
        for (int i = 8; i < 12; ++i) axis.FROMPAC.value.table[i] = 0;
        axis.OPSTATUS.value = nondet_uchar();
        if (axis.OPSTATUS.value != 0) lastStatus = axis.OPSTATUS.value;
        axis.MODECHANGE.value = nondet_bool();
        const BOOL before = axis.EXECUTE.value, jogPos = axis.JOGPOSITIVE.value, jogNeg = axis.JOGNEGATIVE.value;
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
        /* A job starts with an Execute edge or a jog button's edge. */
        const BOOL edge = (axis.EXECUTE.value && !before) || (axis.JOGPOSITIVE.value && !jogPos)
                          || (axis.JOGNEGATIVE.value && !jogNeg);
        const BOOL wasBusy = axis.BUSY.value, doneBefore = axis.DONE.value;
        BYTE module[12];
        for (int i = 0; i < 12; ++i) module[i] = axis.TOPAC.value.table[i];
        FB_PAC_AXIS_body__(&axis);

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
        if (axis.EXECUTE.value && !before) {
            edgeScan = n;
            skippedSinceEdge = FALSE;
        }
        __CPROVER_assert(!(startNow && !startBefore) || n - edgeScan < (int)t,
                         "A8 no Start once the job's Timeout since its edge ran out");
        if (axis.ERROR.value && axis.ERRORID.value == 0x8006 && skippedSinceEdge) reachTimedOutAfterSkip = 1;
        /* A7: never Done on silence outside ONLINE running: a job that saw no ACTIVE since its Start ends Done
         * only if no known status but 31 was seen since then. */
        if (startNow && !startBefore) {
            activeSinceStart = FALSE;
            leftSinceStart = FALSE;
        }
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
        __CPROVER_assert(!(axis.EXECUTE.value && !before) || wasBusy || axis.BUSY.value || axis.DONE.value
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
#if CBMC__K >= 6 /* edge, Start, ACTIVE, its fall, and a scan left out between */
    __CPROVER_assert(!reachDoneAfterSkip, "reach: Done after a scan left out while Busy");
#else
    (void)reachDoneAfterSkip;
#endif
    __CPROVER_assert(!reachTimedOutAfterSkip, "reach: 16#8006 for a job left out while it waited for the axis");
    __CPROVER_assert(!reachPlcRestart, "reach: a PLC restart"); /* CBMC__PLC_RESTARTS=0 is for the replay only */
    return 0;
}
