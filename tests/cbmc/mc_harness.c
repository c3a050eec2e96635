/* Bounded model-checking harness of the MC blocks MC_Power, MC_Stop, MC_MoveAbsolute, MC_Halt and MC_Reset on
 * one axis run by FB_PAC_McAxis over FB_PAC_Axis (docs/fb/MC_blocks.md), on the C that pacst generates from st/,
 * for K scans (docs/verification.md). Free in every scan: the operating status, the controller's axis module
 * (bytes 0..7; the position bytes stay 0), ModeChange, MC_Power.Enable, whether each of the four blocks is
 * called (a CASE step or an IF branch leaves it out, its Execute then unchanged: the calling contract of
 * MC_blocks.md), their Execute, and the order in which they are called (as listed or the reverse, so every two
 * of them edged in one scan meet in either order; FB_PAC_McAxis last); per run IntegerMode, Timeout and
 * StopTimeout (1..TMAX ms). Free too a PLC restart: every block, FB_PAC_McAxis and the axis reference back to
 * their cold-start values. With -DCBMC__STUTTER=1 the scans in which the PLC only waits are compressed
 * (stutter_axis.h: after a still scan up to CBMC__STRETCH_MAX more in one step, S1 checked in the same run);
 * -DCBMC__TSLOW=<ms> lets Timeout be TSLOW .. TSLOW + TMAX - 1 ms as well (the slowest bus's take-over);
 * -DCBMC__ONLY_MOVE=1 keeps free only what the move's take-over on that bus needs (below); -DCBMC__STARTUP_SCANS=<n>
 * runs n start-up scans with fixed inputs before the first step (below).
 * The move's target and dynamics are constants (keeping floating point out of the proof). Properties "MC<n>",
 * P1..P4 for both blocks (plcopen_props.h), reachability checks "reach: ..." (which must FAIL), as in
 * cmd_harness.c. */
#include "harness.h"
#include "stutter_axis.h"

#ifndef CBMC__K
#define CBMC__K 4
#endif
#ifndef CBMC__TMAX
#define CBMC__TMAX 2
#endif
#ifndef CBMC__PLC_RESTARTS /* 0: no PLC restart (the counterexamples recorded before it was free replay so) */
#define CBMC__PLC_RESTARTS 1
#endif
/* 1: only what the slowest bus's move needs is free (a hand run, docs/verification.md): MC_Stop, MC_Halt and MC_Reset are never
 * called, MC_Power.Enable is TRUE, ModeChange and IntegerMode FALSE, Timeout only TSLOW .. TSLOW + TMAX - 1 ms;
 * MC_MoveAbsolute's calls and Execute, the operating status and the module's bytes stay free in every scan. */
#ifndef CBMC__ONLY_MOVE
#define CBMC__ONLY_MOVE 0
#endif
/* > 0: the run begins after that many start-up scans of the program, run before the first step with the inputs of a
 * PLC start before the controller's first reply (an all-zero module, operating status 0, MC_Power.Enable
 * CBMC__STARTUP_ENABLE, the four blocks not yet called): FB_PAC_AxisResetPulse's LowTimer has then run its update
 * time out, a limit no stretch may pass (docs/verification.md, "the move on the slowest bus in eight steps"). A PLC
 * restart within the run starts without them. 0: the first step is the PLC's first scan. */
#ifndef CBMC__STARTUP_SCANS
#define CBMC__STARTUP_SCANS 0
#endif
#ifndef CBMC__STARTUP_ENABLE
#define CBMC__STARTUP_ENABLE 0
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
/* The pins a run sets once. */
typedef struct {
    TIME timeout, stopTimeout;
    BOOL integerMode;
} RunPins;
/* A PLC cold start, the first and every restart: each instance from its init function and the run's pins (the
 * init functions again, not a copy of the first cold start kept aside: the same values without a second
 * instance of every FB for CBMC to write field by field). */
static void ColdStart(const RunPins *pins) {
    __pacst_init_ST_PAC_AXISREF(&ref);
    MC_POWER_init__(&power, FALSE);
    MC_STOP_init__(&stop, FALSE);
    MC_MOVEABSOLUTE_init__(&move, FALSE);
    MC_HALT_init__(&halt, FALSE);
    MC_RESET_init__(&reset, FALSE);
    FB_PAC_MCAXIS_init__(&mcAxis, FALSE);
    mcAxis.TIMEOUT.value = pins->timeout;
    mcAxis.STOPTIMEOUT.value = pins->stopTimeout;
    mcAxis.INTEGERMODE.value = pins->integerMode;
    mcAxis.MAXVELOCITY.value = 100.0f;
    mcAxis.MAXACCELERATION.value = 100.0f;
    move.POSITION.value = 10.5f;
    move.VELOCITY.value = 50.0f;
}

/* Everything the harness runs, for the waiting scans (stutter_axis.h): the state before a scan's calls, and a
 * copy after them with the counters set to the state before's. */
typedef struct {
    ST_PAC_AXISREF ref;
    MC_POWER power;
#if !CBMC__ONLY_MOVE /* never called there: no scan writes them, so S1 has nothing to compare in them */
    MC_STOP stop;
    MC_HALT halt;
    MC_RESET reset;
#endif
    MC_MOVEABSOLUTE move;
    FB_PAC_MCAXIS mcAxis;
} McState;
/* What the program and the controller hand the blocks in a scan: a waiting scan's are those of the scan before. */
typedef struct {
    BYTE fromPac[8], opStatus;
    BOOL modeChange, enable, stopFirst, called[4], execute[4];
} Inputs;
static BOOL SameInputs(const Inputs *a, const Inputs *b) {
    BOOL same = a->opStatus == b->opStatus && a->modeChange == b->modeChange && a->enable == b->enable
                && a->stopFirst == b->stopFirst;
    for (int i = 0; i < 8; ++i) same = same && a->fromPac[i] == b->fromPac[i];
    for (int i = 0; i < 4; ++i) same = same && a->called[i] == b->called[i] && a->execute[i] == b->execute[i];
    return same;
}
#if CBMC__STUTTER /* declared only where compared: CBMC initialises every field of a global, a step each */
static McState before, normalised;
static void Snapshot(McState *s) {
    s->ref = ref;
    s->power = power;
#if !CBMC__ONLY_MOVE
    s->stop = stop;
    s->halt = halt;
    s->reset = reset;
#endif
    s->move = move;
    s->mcAxis = mcAxis;
}
/* Still: every instance after the scan (at nowNs) as before it (at beforeNs), but for the counters of the TONs
 * (FB_PAC_Axis's, FB_PAC_McAxis's HaltTimer, MC_Reset's ResetTimer) and the take-over's AnswerTime. */
static BOOL StillMc(long long beforeNs, long long nowNs) {
    Snapshot(&normalised);
    BOOL along = AxisCountersAlong(&before.mcAxis.MODULE, &normalised.mcAxis.MODULE, beforeNs, nowNs);
    along = TonCountersAlong(&before.mcAxis.HALTTIMER, &normalised.mcAxis.HALTTIMER, beforeNs, nowNs) && along;
#if !CBMC__ONLY_MOVE
    along = TonCountersAlong(&before.reset.RESETTIMER, &normalised.reset.RESETTIMER, beforeNs, nowNs) && along;
#endif
#ifdef __CPROVER__
    /* CBMC compares two structs with == (its C extension) member by member; word by word through a pointer each
     * word is a byte extraction from the whole state, the work growing with its square. */
    return along && normalised == before;
#else
    return along && SameWords(&normalised, &before, sizeof normalised);
#endif
}
static BOOL McNoLimitPasses(void) {
    return AxisNoLimitPasses(&before.mcAxis.MODULE, &mcAxis.MODULE)
           && before.mcAxis.HALTTIMER.Q.value == mcAxis.HALTTIMER.Q.value
#if !CBMC__ONLY_MOVE
           && before.reset.RESETTIMER.Q.value == reset.RESETTIMER.Q.value
#endif
        ;
}
#endif

/* A block's call as an ST program makes it: on the axis reference itself (VAR_IN_OUT) where pacst's C passes it by
 * reference; in, the body, out where it copies (MATIEC's C, in the replay of a MATIEC build). By reference the
 * blocks' own Axis members keep their initial values, out of the formula, also through a PLC restart. */
#ifdef PACST_BODY_REF
#define CALL_ON_REF(NAME, fb) NAME##_body_ref__(&(fb), &ref)
#else
#define CALL_ON_REF(NAME, fb)                                                                                      \
    do {                                                                                                           \
        (fb).AXIS.value = ref;                                                                                     \
        NAME##_body__(&(fb));                                                                                      \
        ref = (fb).AXIS.value;                                                                                     \
    } while (0)
#endif
static BOOL stopCalled, moveCalled, haltCalled, resetCalled;
static void CallStop(void) {
    if (stopCalled) CALL_ON_REF(MC_STOP, stop);
}
static void CallMove(void) {
    if (moveCalled) CALL_ON_REF(MC_MOVEABSOLUTE, move);
}
static void CallHalt(void) {
    if (haltCalled) CALL_ON_REF(MC_HALT, halt);
}
static void CallReset(void) {
    if (resetCalled) CALL_ON_REF(MC_RESET, reset);
}
static void CallMcAxis(void) {
#ifdef PACST_BODY_REF
    FB_PAC_MCAXIS_body_ref__(&mcAxis, &ref, &mcAxis.TOPAC.value, &mcAxis.FROMPAC.value);
#else
    CALL_ON_REF(FB_PAC_MCAXIS, mcAxis);
#endif
}
/* The program's start-up scans (CBMC__STARTUP_SCANS), every input fixed: CBMC runs them as the PLC would, without a
 * choice to merge. The blocks' properties cannot break here: none of them is called, and MC_Power's MC3 is checked
 * from the first step on. */
static void StartupScans(void) {
    for (int s = 1; s <= CBMC__STARTUP_SCANS; ++s) {
        __CURRENT_TIME = __time_make(0, (long)s * CYCLE_NS);
        for (int i = 0; i < 12; ++i) mcAxis.FROMPAC.value.table[i] = 0;
        mcAxis.OPSTATUS.value = 0;
        mcAxis.MODECHANGE.value = FALSE;
        power.ENABLE.value = CBMC__STARTUP_ENABLE;
        CALL_ON_REF(MC_POWER, power);
        CallMcAxis();
    }
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
    unsigned t = 1 + nondet_uchar() % CBMC__TMAX;
    const unsigned st = 1 + nondet_uchar() % CBMC__TMAX;
    if (CBMC__TSLOW > 0 && (CBMC__ONLY_MOVE || nondet_bool())) t += CBMC__TSLOW - 1; /* the slowest bus's take-over */
    /* P8, the Busy bounds of MC_blocks.md: a halt or stop ends by StopTimeout after the scan FB_PAC_McAxis took
     * it (the scan of the edge here, the blocks called before it), shown one call later; MC_Reset by
     * 2 x Timeout after its edge scan. A move has no bound: it takes as long as the axis moves. */
    stopWatch.bound = haltWatch.bound = (int)st + 1;
    resetWatch.bound = 2 * (int)t + 1;
    moveWatch.bound = 1000;
    /* FB_PAC_McCommand posts every edge, also one while Busy: a new job, whose Busy counts from its edge. */
    stopWatch.edgeRestarts = haltWatch.edgeRestarts = resetWatch.edgeRestarts = moveWatch.edgeRestarts = TRUE;
    RunPins pins;
    pins.timeout = __time_make(0, (long)t * CYCLE_NS);
    pins.stopTimeout = __time_make(0, (long)st * CYCLE_NS);
    pins.integerMode = !CBMC__ONLY_MOVE && nondet_bool();
    ColdStart(&pins);
    StartupScans();
    const PlcOpenWatch stopWatch0 = stopWatch, moveWatch0 = moveWatch, haltWatch0 = haltWatch, resetWatch0 = resetWatch;
    /* The waiting scans (CBMC__STUTTER): the clock is CBMC__STARTUP_SCANS + n + stretched ms. */
    long stretched = 0;
    Inputs prevInputs;
    BOOL prevStill = FALSE;
    int reachSlowDone = 0;
    StutterReach stutterReach = {FALSE, FALSE};
    int moveSkipRun = 0;      /* scans in a row MC_MoveAbsolute has been left out while Busy */
    BOOL moveLongSkip = FALSE; /* a skip of two scans or more since its edge */
    long startMs = -1000, takeoverMs = 0; /* the clock when Start last rose, and when ACTIVE first showed since */
    BOOL activeSinceStart = FALSE;

    for (int n = 1; n <= CBMC__K; ++n) {
        __CURRENT_TIME = __time_make(0, (long)(CBMC__STARTUP_SCANS + n + stretched) * CYCLE_NS);
        BOOL restarted = FALSE;
        /* A PLC cold start: every instance back to its initial values; what the harness knows starts anew. */
        if (CBMC__PLC_RESTARTS && n > 1 && nondet_bool()) {
            ColdStart(&pins);
            stopWatch = stopWatch0;
            moveWatch = moveWatch0;
            haltWatch = haltWatch0;
            resetWatch = resetWatch0;
            stopHeld = lastWasStop = braking = FALSE;
            resetBusySeen = 0;
            moveSkipRun = 0;
            startMs = -1000;
            activeSinceStart = FALSE;
            restarted = TRUE;
            reachPlcRestart = 1;
        }
        for (int i = 0; i < 8; ++i) mcAxis.FROMPAC.value.table[i] = nondet_uchar();
        for (int i = 8; i < 12; ++i) mcAxis.FROMPAC.value.table[i] = 0;
        mcAxis.OPSTATUS.value = nondet_uchar();
        mcAxis.MODECHANGE.value = !CBMC__ONLY_MOVE && nondet_bool();
        power.ENABLE.value = CBMC__ONLY_MOVE || nondet_bool();
        const BOOL stopBefore = stop.EXECUTE.value, moveBefore = move.EXECUTE.value;
        const BOOL haltBefore = halt.EXECUTE.value, resetBefore = reset.EXECUTE.value;
        stopCalled = !CBMC__ONLY_MOVE && nondet_bool();
        moveCalled = nondet_bool();
        haltCalled = !CBMC__ONLY_MOVE && nondet_bool();
        resetCalled = !CBMC__ONLY_MOVE && nondet_bool();
        if ((!stopCalled && stop.BUSY.value) || (!moveCalled && move.BUSY.value) || (!haltCalled && halt.BUSY.value)
            || (!resetCalled && reset.BUSY.value))
            reachSkippedBusy = 1;
        if (stopCalled) stop.EXECUTE.value = nondet_bool();
        if (moveCalled) move.EXECUTE.value = nondet_bool();
        if (haltCalled) halt.EXECUTE.value = nondet_bool();
        if (resetCalled) reset.EXECUTE.value = nondet_bool();
        const BOOL stopEdge = stop.EXECUTE.value && !stopBefore, moveEdge = move.EXECUTE.value && !moveBefore;
        const BOOL haltEdge = halt.EXECUTE.value && !haltBefore, resetEdge = reset.EXECUTE.value && !resetBefore;
        const BOOL stopFirst = !CBMC__ONLY_MOVE && nondet_bool();
        moveSkipRun = (!moveCalled && move.BUSY.value) ? moveSkipRun + 1 : 0;
        if (moveEdge) moveLongSkip = FALSE;
        /* The waiting scan (stutter_axis.h): the inputs, the calls and their order those of the scan before. After
         * a still scan, d more like it go in one step before this one. */
        Inputs inputs;
        for (int i = 0; i < 8; ++i) inputs.fromPac[i] = mcAxis.FROMPAC.value.table[i];
        inputs.opStatus = mcAxis.OPSTATUS.value;
        inputs.modeChange = mcAxis.MODECHANGE.value;
        inputs.enable = power.ENABLE.value;
        inputs.stopFirst = stopFirst;
        inputs.called[0] = stopCalled;
        inputs.called[1] = moveCalled;
        inputs.called[2] = haltCalled;
        inputs.called[3] = resetCalled;
        inputs.execute[0] = stop.EXECUTE.value;
        inputs.execute[1] = move.EXECUTE.value;
        inputs.execute[2] = halt.EXECUTE.value;
        inputs.execute[3] = reset.EXECUTE.value;
        const BOOL waiting = CBMC__STUTTER && n > 1 && !restarted && SameInputs(&inputs, &prevInputs);
        prevInputs = inputs;
        if (CBMC__STUTTER && waiting && prevStill) {
            const unsigned d = nondet_uchar() & CBMC__STRETCH_MAX;
            const long long stillNs = (long long)(CBMC__STARTUP_SCANS + n - 1 + stretched) * CYCLE_NS;
            const long long lastNs = stillNs + (long long)d * CYCLE_NS;
            AxisStretch(&mcAxis.MODULE, d, stillNs);
            TonStretch(&mcAxis.HALTTIMER, stillNs, lastNs);
            TonStretch(&reset.RESETTIMER, stillNs, lastNs);
            /* P8 counts d more calls of each block called Busy in the still scan; a skip goes on through it. */
            if (stopCalled && stop.BUSY.value) stopWatch.busyScans += (int)d;
            if (moveCalled && move.BUSY.value) moveWatch.busyScans += (int)d;
            if (haltCalled && halt.BUSY.value) haltWatch.busyScans += (int)d;
            if (resetCalled && reset.BUSY.value) resetWatch.busyScans += (int)d;
            if (moveSkipRun > 0) moveSkipRun += (int)d;
            stretched += (long)d;
            __CURRENT_TIME = __time_make(0, (long)(CBMC__STARTUP_SCANS + n + stretched) * CYCLE_NS);
            if (d >= 2) stutterReach.stretch = TRUE;
        }
        if (moveSkipRun >= 2) moveLongSkip = TRUE;
#if CBMC__STUTTER
        Snapshot(&before);
#endif
        const BOOL startBefore = (mcAxis.TOPAC.value.table[3] & 0x04u) != 0;
        /* Held from an earlier scan: the stop's Execute is still TRUE in this one. */
        const BOOL heldBefore = stopHeld && stop.EXECUTE.value;

        CALL_ON_REF(MC_POWER, power);
        /* Stop, MoveAbsolute, Halt, Reset or the reverse: seven guarded calls hold both orders, where two whole
         * orders in an IF would have CBMC execute each block's body twice per scan. */
        if (!stopFirst) {
            CallReset();
            CallHalt();
            CallMove();
        }
        CallStop();
        if (stopFirst) {
            CallMove();
            CallHalt();
            CallReset();
        }
        CallMcAxis();
        const long nowMs = CBMC__STARTUP_SCANS + n + stretched;
#if CBMC__STUTTER
        {
            /* Still: a waiting scan that passed no limit and changed nothing but counters. S1: a waiting scan
             * after a still one (after a stretch too) is still, unless it passes a limit. */
            const long long nowNs = (long long)nowMs * CYCLE_NS;
            const BOOL noLimit = waiting && McNoLimitPasses();
            const BOOL still = noLimit && StillMc(nowNs - CYCLE_NS, nowNs);
            __CPROVER_assert(!(prevStill && noLimit) || still,
                             "S1 a waiting scan after a still one changes nothing but the TONs' counters");
            if (prevStill && noLimit) stutterReach.waiting = TRUE;
            prevStill = still;
        }
#endif
        /* The slowest bus's handshake: ACTIVE 16 ms or more after Start rose, MC_MoveAbsolute Done after it was
         * left out of two scans or more since its edge. */
        if ((mcAxis.TOPAC.value.table[3] & 0x04u) != 0 && !startBefore) {
            startMs = nowMs;
            activeSinceStart = FALSE;
        }
        if (!activeSinceStart && mcAxis.MODULE.ACTIVE.value) takeoverMs = nowMs;
        activeSinceStart = activeSinceStart || mcAxis.MODULE.ACTIVE.value;
        if (move.DONE.value && activeSinceStart && takeoverMs - startMs >= SLOW_TAKEOVER_MS && moveLongSkip)
            reachSlowDone = 1;

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
    __CPROVER_assert(!reachMoveBusy, "reach: MC_MoveAbsolute Busy");
    __CPROVER_assert(!reachMoveAborted, "reach: MC_MoveAbsolute CommandAborted");
    __CPROVER_assert(!reachSkippedBusy, "reach: a block left out of a scan while Busy");
#if !CBMC__ONLY_MOVE /* the blocks' own checks, where they are called */
    __CPROVER_assert(!reachStopDone, "reach: MC_Stop Done");
    __CPROVER_assert(!reachHeld, "reach: a stop held over a scan");
    __CPROVER_assert(!reachReleased, "reach: Standstill after the stop is released");
    __CPROVER_assert(!reachStopFailedHeld, "reach: a stop ended with Error held over a scan");
    __CPROVER_assert(!reachBrakingRefused, "reach: a move refused while a stopped axis shows ACTIVE");
    __CPROVER_assert(!reachHaltDone, "reach: MC_Halt Done");
    __CPROVER_assert(!reachResetDone, "reach: MC_Reset Done after Busy");
#else
    (void)reachStopDone;
    (void)reachHeld;
    (void)reachReleased;
    (void)reachStopFailedHeld;
    (void)reachBrakingRefused;
    (void)reachHaltDone;
    (void)reachResetDone;
#endif
#if CBMC__PLC_RESTARTS /* 0: the replay of counterexamples recorded before it, and the hand runs with STUTTER */
    __CPROVER_assert(!reachPlcRestart, "reach: a PLC restart");
#else
    (void)reachPlcRestart;
#endif
#if CBMC__STUTTER
    AssertStutterReached(&stutterReach);
    __CPROVER_assert(!reachSlowDone, "reach: MC_MoveAbsolute Done after a take-over 16 ms after Start, after a skip "
                                     "of two scans or more");
#else
    (void)stutterReach;
    (void)reachSlowDone;
#endif
    return 0;
}
