/* Bounded model-checking harness of the MC blocks MC_Power, MC_Stop, MC_MoveAbsolute, MC_Halt and MC_Reset on
 * one axis run by FB_PAC_McAxis over FB_PAC_Axis (docs/fb/MC_blocks.md), on the C that pacst generates from st/,
 * for K scans (docs/verification.md). Free in every scan: the operating status, the controller's axis module
 * (bytes 0..7; the position bytes stay 0), ModeChange, MC_Power.Enable, whether each of the four blocks is
 * called (a CASE step or an IF branch leaves it out, its Execute then unchanged: the calling contract of
 * MC_blocks.md), their Execute, and the order in which they are called (as listed or the reverse, so every two
 * of them edged in one scan meet in either order; FB_PAC_McAxis last); per run IntegerMode, Timeout and
 * StopTimeout (1..TMAX ms). Free too a PLC restart: every block, FB_PAC_McAxis and the axis reference back to
 * their cold-start values.
 * The move's target and dynamics are constants (keeping floating point out of the proof). Properties "MC<n>",
 * P1..P4 for both blocks (plcopen_props.h), reachability checks "reach: ..." (which must FAIL), as in
 * cmd_harness.c. */
#include "harness.h"

#ifndef CBMC__K
#define CBMC__K 4
#endif
#ifndef CBMC__TMAX
#define CBMC__TMAX 2
#endif
#ifndef CBMC__PLC_RESTARTS /* 0: no PLC restart (the counterexamples recorded before it was free replay so) */
#define CBMC__PLC_RESTARTS 1
#endif

/* The timeline of a counterexample (paccbmc): assigned at the end of every scan, tl_scan last. */
static unsigned long long tl_from_pac, tl_to_pac;
static int tl_op_status, tl_state;
static BOOL tl_enable, tl_stop_first, tl_s_execute, tl_s_busy, tl_s_done, tl_s_error, tl_m_execute, tl_m_busy,
    tl_m_done, tl_m_error, tl_m_aborted, tl_h_execute, tl_h_busy, tl_h_done, tl_h_error, tl_h_aborted, tl_r_execute,
    tl_r_busy, tl_r_done, tl_r_error;
static WORD tl_s_errorid, tl_m_errorid, tl_h_errorid;
static int tl_scan;

/* The axis reference is an in-out: copied into each block before its call and back after it. */
static ST_PAC_AXISREF ref;
static MC_POWER power;
static MC_STOP stop;
static MC_MOVEABSOLUTE move;
static MC_HALT halt;
static MC_RESET reset;
static FB_PAC_MCAXIS mcAxis;
/* The cold-start values, for a PLC restart. */
static ST_PAC_AXISREF refFresh;
static MC_POWER powerFresh;
static MC_STOP stopFresh;
static MC_MOVEABSOLUTE moveFresh;
static MC_HALT haltFresh;
static MC_RESET resetFresh;
static FB_PAC_MCAXIS mcAxisFresh;

static BOOL stopCalled;
static void CallStop(void) {
    if (!stopCalled) return;
    stop.AXIS.value = ref;
    MC_STOP_body__(&stop);
    ref = stop.AXIS.value;
}
static BOOL moveCalled;
static void CallMove(void) {
    if (!moveCalled) return;
    move.AXIS.value = ref;
    MC_MOVEABSOLUTE_body__(&move);
    ref = move.AXIS.value;
}
static BOOL haltCalled;
static void CallHalt(void) {
    if (!haltCalled) return;
    halt.AXIS.value = ref;
    MC_HALT_body__(&halt);
    ref = halt.AXIS.value;
}
static BOOL resetCalled;
static void CallReset(void) {
    if (!resetCalled) return;
    reset.AXIS.value = ref;
    MC_RESET_body__(&reset);
    ref = reset.AXIS.value;
}

int main(void) {
    PlcOpenWatch stopWatch = {0}, moveWatch = {0}, haltWatch = {0}, resetWatch = {0};
    BOOL stopHeld = FALSE; /* the stop's edge was accepted and its Execute has stayed TRUE since */
    BOOL lastWasStop = FALSE; /* the last request accepted was the stop's */
    BOOL braking = FALSE;     /* after the last scan: lastWasStop, and the axis showed ACTIVE */
    int reachBrakingRefused = 0;
    int reachStopDone = 0, reachHeld = 0, reachMoveBusy = 0, reachMoveAborted = 0, reachReleased = 0;
    int reachHaltDone = 0, reachResetDone = 0, reachStopFailedHeld = 0, resetBusySeen = 0, reachSkippedBusy = 0;
    int reachPlcRestart = 0;

    __CURRENT_TIME = __time_make(0, 0);
    __pacst_init_ST_PAC_AXISREF(&ref);
    MC_POWER_init__(&power, FALSE);
    MC_STOP_init__(&stop, FALSE);
    MC_MOVEABSOLUTE_init__(&move, FALSE);
    MC_HALT_init__(&halt, FALSE);
    MC_RESET_init__(&reset, FALSE);
    FB_PAC_MCAXIS_init__(&mcAxis, FALSE);
    const unsigned t = 1 + nondet_uchar() % CBMC__TMAX, st = 1 + nondet_uchar() % CBMC__TMAX;
    /* P8, the Busy bounds of MC_blocks.md: a halt or stop ends by StopTimeout after the scan FB_PAC_McAxis took
     * it (the scan of the edge here, the blocks called before it), shown one call later; MC_Reset by
     * 2 x Timeout after its edge scan. A move has no bound: it takes as long as the axis moves. */
    stopWatch.bound = haltWatch.bound = (int)st + 1;
    resetWatch.bound = 2 * (int)t + 1;
    moveWatch.bound = 1000;
    /* FB_PAC_McCommand posts every edge, also one while Busy: a new job, whose Busy counts from its edge. */
    stopWatch.edgeRestarts = haltWatch.edgeRestarts = resetWatch.edgeRestarts = moveWatch.edgeRestarts = TRUE;
    mcAxis.TIMEOUT.value = __time_make(0, (long)t * CYCLE_NS);
    mcAxis.STOPTIMEOUT.value = __time_make(0, (long)st * CYCLE_NS);
    mcAxis.INTEGERMODE.value = nondet_bool();
    mcAxis.MAXVELOCITY.value = 100.0f;
    mcAxis.MAXACCELERATION.value = 100.0f;
    move.POSITION.value = 10.5f;
    move.VELOCITY.value = 50.0f;
    refFresh = ref;
    powerFresh = power;
    stopFresh = stop;
    moveFresh = move;
    haltFresh = halt;
    resetFresh = reset;
    mcAxisFresh = mcAxis;
    const PlcOpenWatch stopWatch0 = stopWatch, moveWatch0 = moveWatch, haltWatch0 = haltWatch, resetWatch0 = resetWatch;

    for (int n = 1; n <= CBMC__K; ++n) {
        __CURRENT_TIME = __time_make(0, (long)n * CYCLE_NS);
        /* A PLC cold start: every instance back to its initial values; what the harness knows starts anew. */
        if (CBMC__PLC_RESTARTS && n > 1 && nondet_bool()) {
            ref = refFresh;
            power = powerFresh;
            stop = stopFresh;
            move = moveFresh;
            halt = haltFresh;
            reset = resetFresh;
            mcAxis = mcAxisFresh;
            stopWatch = stopWatch0;
            moveWatch = moveWatch0;
            haltWatch = haltWatch0;
            resetWatch = resetWatch0;
            stopHeld = lastWasStop = braking = FALSE;
            resetBusySeen = 0;
            reachPlcRestart = 1;
        }
        for (int i = 0; i < 8; ++i) mcAxis.FROMPAC.value.table[i] = nondet_uchar();
        for (int i = 8; i < 12; ++i) mcAxis.FROMPAC.value.table[i] = 0;
        mcAxis.OPSTATUS.value = nondet_uchar();
        mcAxis.MODECHANGE.value = nondet_bool();
        power.ENABLE.value = nondet_bool();
        const BOOL stopBefore = stop.EXECUTE.value, moveBefore = move.EXECUTE.value;
        const BOOL haltBefore = halt.EXECUTE.value, resetBefore = reset.EXECUTE.value;
        stopCalled = nondet_bool();
        moveCalled = nondet_bool();
        haltCalled = nondet_bool();
        resetCalled = nondet_bool();
        if ((!stopCalled && stop.BUSY.value) || (!moveCalled && move.BUSY.value) || (!haltCalled && halt.BUSY.value)
            || (!resetCalled && reset.BUSY.value))
            reachSkippedBusy = 1;
        if (stopCalled) stop.EXECUTE.value = nondet_bool();
        if (moveCalled) move.EXECUTE.value = nondet_bool();
        if (haltCalled) halt.EXECUTE.value = nondet_bool();
        if (resetCalled) reset.EXECUTE.value = nondet_bool();
        const BOOL stopEdge = stop.EXECUTE.value && !stopBefore, moveEdge = move.EXECUTE.value && !moveBefore;
        const BOOL haltEdge = halt.EXECUTE.value && !haltBefore, resetEdge = reset.EXECUTE.value && !resetBefore;
        const BOOL stopFirst = nondet_bool();
        /* Held from an earlier scan: the stop's Execute is still TRUE in this one. */
        const BOOL heldBefore = stopHeld && stop.EXECUTE.value;

        power.AXIS.value = ref;
        MC_POWER_body__(&power);
        ref = power.AXIS.value;
        if (stopFirst) {
            CallStop();
            CallMove();
            CallHalt();
            CallReset();
        } else {
            CallReset();
            CallHalt();
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
        tl_h_execute = halt.EXECUTE.value;
        tl_h_busy = halt.BUSY.value;
        tl_h_done = halt.DONE.value;
        tl_h_error = halt.ERROR.value;
        tl_h_aborted = halt.COMMANDABORTED.value;
        tl_h_errorid = halt.ERRORID.value;
        tl_r_execute = reset.EXECUTE.value;
        tl_r_busy = reset.BUSY.value;
        tl_r_done = reset.DONE.value;
        tl_r_error = reset.ERROR.value;
        tl_state = ref.STATE;
        tl_to_pac = Bytes8(mcAxis.TOPAC.value.table);
        tl_scan = n;

        /* P1..P4 and P8 for each block (plcopen_props.h): Busy, Done, Error and CommandAborted exclusive, Error
         * with an ErrorID, no output without an edge, the final outputs held while Execute stays TRUE, Busy
         * within its bound. */
        if (stopCalled)
            CheckPlcOpen(&stopWatch, stop.EXECUTE.value, stopEdge, stop.BUSY.value, stop.DONE.value,
                         stop.ERROR.value, stop.COMMANDABORTED.value, stop.ERRORID.value);
        if (moveCalled)
            CheckPlcOpen(&moveWatch, move.EXECUTE.value, moveEdge, move.BUSY.value, move.DONE.value,
                         move.ERROR.value, move.COMMANDABORTED.value, move.ERRORID.value);
        if (haltCalled)
            CheckPlcOpen(&haltWatch, halt.EXECUTE.value, haltEdge, halt.BUSY.value, halt.DONE.value,
                         halt.ERROR.value, halt.COMMANDABORTED.value, halt.ERRORID.value);
        if (resetCalled)
            CheckPlcOpen(&resetWatch, reset.EXECUTE.value, resetEdge, reset.BUSY.value, reset.DONE.value,
                         reset.ERROR.value, FALSE, reset.ERRORID.value);
        __CPROVER_assert(!move.ACTIVE.value || move.BUSY.value, "MC2 Active only with Busy");
        __CPROVER_assert(!halt.ACTIVE.value || halt.BUSY.value, "MC2 MC_Halt's Active only with Busy");
        __CPROVER_assert(!power.ERROR.value || power.ERRORID.value != 0, "MC3 MC_Power's Error implies ErrorID <> 0");

        /* MC4: a stop once accepted is never lost: while its Execute stays TRUE (whether it ended Done or with
         * Error) the axis is in Stopping, or ErrorStop / Disabled, and no move or halt is accepted. */
        if (stopEdge) stopHeld = stop.BUSY.value || stop.DONE.value;
        if (!stop.EXECUTE.value || stop.COMMANDABORTED.value) stopHeld = FALSE;
        const E_PAC_MCSTATE state = ref.STATE;
        __CPROVER_assert(!stopHeld || state == E_PAC_MCSTATE__PAC_MC_STOPPING
                             || state == E_PAC_MCSTATE__PAC_MC_ERROR_STOP || state == E_PAC_MCSTATE__PAC_MC_DISABLED,
                         "MC4 a held stop keeps the axis in Stopping");
        __CPROVER_assert(!heldBefore || (!(moveEdge && move.BUSY.value) && !(haltEdge && halt.BUSY.value)),
                         "MC4 no move accepted while a stop is held");
        /* MC5: once the stop's Execute is FALSE, the stop is over and the axis shows no ACTIVE, the axis is not
         * left in Stopping. */
        __CPROVER_assert(stop.EXECUTE.value || stop.BUSY.value || ref.STATUS.ACTIVE
                             || state != E_PAC_MCSTATE__PAC_MC_STOPPING,
                         "MC5 Stopping ends with the stop, its Execute and ACTIVE");
        /* MC6: a stop is not undone by letting it go early: after an accepted stop, as long as the axis the blocks
         * see shows ACTIVE, no move or halt is accepted, whether the stop's Execute is TRUE or not, and the
         * stop ends with its own outcome, never CommandAborted (there is no other MC_Stop here). */
        __CPROVER_assert(!braking || (!(moveEdge && move.BUSY.value) && !(haltEdge && halt.BUSY.value)),
                         "MC6 no move accepted while a stopped axis still shows ACTIVE");
        __CPROVER_assert(!stop.COMMANDABORTED.value, "MC6 MC_Stop ends with its own outcome");
        if (braking && moveEdge && move.ERROR.value) reachBrakingRefused = 1;
        if (stopEdge && (stop.BUSY.value || stop.DONE.value)) lastWasStop = TRUE;
        if ((moveEdge && move.BUSY.value) || (haltEdge && halt.BUSY.value)) lastWasStop = FALSE;
        braking = lastWasStop && ref.STATUS.ACTIVE;

        if (stop.DONE.value) reachStopDone = 1;
        if (stopHeld && heldBefore) reachHeld = 1;
        if (move.BUSY.value) reachMoveBusy = 1;
        if (move.COMMANDABORTED.value) reachMoveAborted = 1;
        if (!stop.EXECUTE.value && stopBefore && !stop.BUSY.value && state == E_PAC_MCSTATE__PAC_MC_STANDSTILL)
            reachReleased = 1;
        if (stopHeld && heldBefore && stop.ERROR.value) reachStopFailedHeld = 1;
        if (halt.DONE.value) reachHaltDone = 1;
        if (reset.DONE.value && resetBusySeen) reachResetDone = 1;
        if (reset.BUSY.value) resetBusySeen = 1;
    }
    __CPROVER_assert(!reachStopDone, "reach: MC_Stop Done");
    __CPROVER_assert(!reachHeld, "reach: a stop held over a scan");
    __CPROVER_assert(!reachMoveBusy, "reach: MC_MoveAbsolute Busy");
    __CPROVER_assert(!reachMoveAborted, "reach: MC_MoveAbsolute CommandAborted");
    __CPROVER_assert(!reachReleased, "reach: Standstill after the stop is released");
    __CPROVER_assert(!reachStopFailedHeld, "reach: a stop ended with Error held over a scan");
    __CPROVER_assert(!reachBrakingRefused, "reach: a move refused while a stopped axis shows ACTIVE");
    __CPROVER_assert(!reachHaltDone, "reach: MC_Halt Done");
    __CPROVER_assert(!reachResetDone, "reach: MC_Reset Done after Busy");
    __CPROVER_assert(!reachSkippedBusy, "reach: a block left out of a scan while Busy");
    __CPROVER_assert(!reachPlcRestart, "reach: a PLC restart"); /* CBMC__PLC_RESTARTS=0 is for the replay only */
    return 0;
}
