/* Bounded model-checking harness of the MC blocks MC_Power, MC_Stop and MC_MoveAbsolute on one axis run by
 * FB_PAC_McAxis over FB_PAC_Axis (docs/fb/MC_blocks.md), on the C that pacst generates from st/, for K scans
 * (docs/verification.md). Free in every scan: the operating status, the controller's axis module (bytes 0..7;
 * the position bytes stay 0), ModeChange, MC_Power.Enable, both blocks' Execute, and the order in which the
 * two blocks are called (FB_PAC_McAxis last); per run IntegerMode, Timeout and StopTimeout (1..TMAX ms).
 * The move's target and dynamics are constants (keeping floating point out of the proof). Properties "MC<n>",
 * P1..P4 for both blocks (plcopen_props.h), reachability checks "reach: ..." (which must FAIL), as in
 * cmd_harness.c. */
#include "harness.h"

#ifndef K
#define K 4
#endif
#ifndef TMAX
#define TMAX 2
#endif

/* The timeline of a counterexample (paccbmc): assigned at the end of every scan, tl_scan last. */
static unsigned long long tl_from_pac, tl_to_pac;
static int tl_op_status, tl_state;
static BOOL tl_enable, tl_stop_first, tl_s_execute, tl_s_busy, tl_s_done, tl_s_error, tl_m_execute, tl_m_busy,
    tl_m_done, tl_m_error, tl_m_aborted;
static WORD tl_s_errorid, tl_m_errorid;
static int tl_scan;

/* The axis reference is an in-out: copied into each block before its call and back after it. */
static ST_PAC_AXISREF ref;
static MC_POWER power;
static MC_STOP stop;
static MC_MOVEABSOLUTE move;
static FB_PAC_MCAXIS mcAxis;

static void CallStop(void) {
    stop.AXIS.value = ref;
    MC_STOP_body__(&stop);
    ref = stop.AXIS.value;
}
static void CallMove(void) {
    move.AXIS.value = ref;
    MC_MOVEABSOLUTE_body__(&move);
    ref = move.AXIS.value;
}

int main(void) {
    PlcOpenWatch stopWatch = {0}, moveWatch = {0};
    stopWatch.bound = moveWatch.bound = 1000; /* no Busy bound for the MC blocks yet (docs/verification.md) */
    BOOL stopHeld = FALSE; /* the stop's edge was accepted and its Execute has stayed TRUE since */
    int reachStopDone = 0, reachHeld = 0, reachMoveBusy = 0, reachMoveAborted = 0, reachReleased = 0;

    __CURRENT_TIME = __time_make(0, 0);
    __pacst_init_ST_PAC_AXISREF(&ref);
    MC_POWER_init__(&power, FALSE);
    MC_STOP_init__(&stop, FALSE);
    MC_MOVEABSOLUTE_init__(&move, FALSE);
    FB_PAC_MCAXIS_init__(&mcAxis, FALSE);
    const unsigned t = 1 + nondet_uchar() % TMAX, st = 1 + nondet_uchar() % TMAX;
    mcAxis.TIMEOUT.value = __time_make(0, (long)t * CYCLE_NS);
    mcAxis.STOPTIMEOUT.value = __time_make(0, (long)st * CYCLE_NS);
    mcAxis.INTEGERMODE.value = nondet_bool();
    mcAxis.MAXVELOCITY.value = 100.0f;
    mcAxis.MAXACCELERATION.value = 100.0f;
    move.POSITION.value = 10.5f;
    move.VELOCITY.value = 50.0f;

    for (int n = 1; n <= K; ++n) {
        __CURRENT_TIME = __time_make(0, (long)n * CYCLE_NS);
        for (int i = 0; i < 8; ++i) mcAxis.FROMPAC.value.table[i] = nondet_uchar();
        for (int i = 8; i < 12; ++i) mcAxis.FROMPAC.value.table[i] = 0;
        mcAxis.OPSTATUS.value = nondet_uchar();
        mcAxis.MODECHANGE.value = nondet_bool();
        power.ENABLE.value = nondet_bool();
        const BOOL stopBefore = stop.EXECUTE.value, moveBefore = move.EXECUTE.value;
        stop.EXECUTE.value = nondet_bool();
        move.EXECUTE.value = nondet_bool();
        const BOOL stopEdge = stop.EXECUTE.value && !stopBefore, moveEdge = move.EXECUTE.value && !moveBefore;
        const BOOL stopFirst = nondet_bool();
        /* Held from an earlier scan: the stop's Execute is still TRUE in this one. */
        const BOOL heldBefore = stopHeld && stop.EXECUTE.value;

        power.AXIS.value = ref;
        MC_POWER_body__(&power);
        ref = power.AXIS.value;
        if (stopFirst) {
            CallStop();
            CallMove();
        } else {
            CallMove();
            CallStop();
        }
        mcAxis.AXIS.value = ref;
        FB_PAC_MCAXIS_body__(&mcAxis);
        ref = mcAxis.AXIS.value;

        tl_from_pac = Bytes8(mcAxis.FROMPAC.value.table);
        tl_op_status = mcAxis.OPSTATUS.value;
        tl_enable = power.ENABLE.value;
        tl_stop_first = stopFirst;
        tl_s_execute = stop.EXECUTE.value;
        tl_s_busy = stop.BUSY.value;
        tl_s_done = stop.DONE.value;
        tl_s_error = stop.ERROR.value;
        tl_s_errorid = stop.ERRORID.value;
        tl_m_execute = move.EXECUTE.value;
        tl_m_busy = move.BUSY.value;
        tl_m_done = move.DONE.value;
        tl_m_error = move.ERROR.value;
        tl_m_aborted = move.COMMANDABORTED.value;
        tl_m_errorid = move.ERRORID.value;
        tl_state = ref.STATE;
        tl_to_pac = Bytes8(mcAxis.TOPAC.value.table);
        tl_scan = n;

        /* P1..P4 for each block (plcopen_props.h): Busy, Done, Error and CommandAborted exclusive, Error with
         * an ErrorID, no output without an edge, the final outputs held while Execute stays TRUE. */
        CheckPlcOpen(&stopWatch, stop.EXECUTE.value, stopEdge, stop.BUSY.value, stop.DONE.value, stop.ERROR.value,
                     stop.COMMANDABORTED.value, stop.ERRORID.value);
        CheckPlcOpen(&moveWatch, move.EXECUTE.value, moveEdge, move.BUSY.value, move.DONE.value, move.ERROR.value,
                     move.COMMANDABORTED.value, move.ERRORID.value);
        __CPROVER_assert(!move.ACTIVE.value || move.BUSY.value, "MC2 Active only with Busy");
        __CPROVER_assert(!power.ERROR.value || power.ERRORID.value != 0, "MC3 MC_Power's Error implies ErrorID <> 0");

        /* MC4: a stop once accepted is never lost: while its Execute stays TRUE (and it has not failed with an
         * Error) the axis is in Stopping, or ErrorStop / Disabled, and no move is accepted. */
        if (stopEdge) stopHeld = stop.BUSY.value || stop.DONE.value;
        if (!stop.EXECUTE.value || stop.ERROR.value || stop.COMMANDABORTED.value) stopHeld = FALSE;
        const E_PAC_MCSTATE state = ref.STATE;
        __CPROVER_assert(!stopHeld || state == E_PAC_MCSTATE__PAC_MC_STOPPING
                             || state == E_PAC_MCSTATE__PAC_MC_ERROR_STOP || state == E_PAC_MCSTATE__PAC_MC_DISABLED,
                         "MC4 a held stop keeps the axis in Stopping");
        __CPROVER_assert(!(heldBefore && !stop.ERROR.value) || !(moveEdge && move.BUSY.value),
                         "MC4 no move accepted while a stop is held");
        /* MC5: once the stop's Execute is FALSE and the stop is over, the axis is not left in Stopping. */
        __CPROVER_assert(stop.EXECUTE.value || stop.BUSY.value || state != E_PAC_MCSTATE__PAC_MC_STOPPING,
                         "MC5 Stopping ends with the stop and its Execute");

        if (stop.DONE.value) reachStopDone = 1;
        if (stopHeld && heldBefore) reachHeld = 1;
        if (move.BUSY.value) reachMoveBusy = 1;
        if (move.COMMANDABORTED.value) reachMoveAborted = 1;
        if (!stop.EXECUTE.value && stopBefore && !stop.BUSY.value && state == E_PAC_MCSTATE__PAC_MC_STANDSTILL)
            reachReleased = 1;
    }
    __CPROVER_assert(!reachStopDone, "reach: MC_Stop Done");
    __CPROVER_assert(!reachHeld, "reach: a stop held over a scan");
    __CPROVER_assert(!reachMoveBusy, "reach: MC_MoveAbsolute Busy");
    __CPROVER_assert(!reachMoveAborted, "reach: MC_MoveAbsolute CommandAborted");
    __CPROVER_assert(!reachReleased, "reach: Standstill after the stop is released");
    return 0;
}
