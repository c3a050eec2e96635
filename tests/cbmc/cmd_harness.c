/* Bounded model-checking harness of the CMD interface (manual 2.4): FB_PAC_CmdInterface with CALLERS
 * FB_PAC_Cmd on one channel, on the C that pacst generates from st/, for K scans (docs/verification.md).
 * Free: every byte the controller sends except the RECEIVE flag, which follows the protocol (below); the
 * programmer's Execute, Code, Param and Data in every scan the FB is called (SetPins); whether each FB is called
 * in a scan (a CASE step or an IF branch leaves it out: the calling contract of docs/fb/FB_PAC_Cmd.md); each
 * FB's Timeout and EndTimeout (a few ms); TwoStepWrite; the call order of the callers, anew in every scan; the
 * bus latency (the controller reads a module 0..LAG scans old, skipping any; with -DCBMC__FREE_TIMING=1 in any
 * later scan); the controller's reading of the handshake (a new command is SEND <> RECEIVE, or a SEND changed
 * since the last module it read) and its restart
 * (RECEIVE back to 0 or to the last SEND), a single all-zero scan while it runs on (-DCBMC__BLIPS=0 leaves it
 * out), and a PLC restart (the interface and the command FBs back to their cold-start values, the program's
 * pins too; -DCBMC__PLC_RESTARTS=0 leaves it out). With CALLERS = 2 the second FB sends any command too. The
 * controller keeps a ledger of the commands it took; P5 matches every Done with an entry of its own. The channel
 * starts past its first handshake (a program running since its cold start), so that the K scans go to commands;
 * a PLC restart starts a fresh channel, whose first handshake is then checked. With -DCBMC__STUTTER=1 the scans
 * in which the PLC only waits are compressed (stutter.h: after a still scan up to CBMC__STRETCH_MAX more in one
 * step, and S1, that this loses nothing, checked in the same run). A narrower program for a deeper run:
 * -DCBMC__READING fixes the controller's reading, -DCBMC__SECOND_FEW the second caller's Code to a short command
 * or a stop (Param and Data 0), -DCBMC__SECOND_ALWAYS calls it in every scan; -DCBMC__TWOSTEP and -DCBMC__TMAX
 * fix TwoStepWrite and the timeouts (docs/verification.md, "two callers on the slowest bus, narrowed").
 * Properties are __CPROVER_assert with a description "P<n> ..."; reachability checks are asserts that
 * describe themselves "reach: ..." and must FAIL (tests/cbmc/paccbmc.py checks both). */
#include "harness.h"
#include "stutter.h"

#ifndef CBMC__K
#define CBMC__K 10
#endif
#ifndef CBMC__CALLERS
#define CBMC__CALLERS 1
#endif
#ifndef CBMC__LAG
#define CBMC__LAG 1
#endif
#ifndef CBMC__TMAX
#define CBMC__TMAX 2 /* Timeout TMIN .. TMIN + TMAX - 1 ms, EndTimeout 1 .. TMAX ms */
#endif
#ifndef CBMC__TMIN
#define CBMC__TMIN (CBMC__LAG + 2) /* the round trip: the module out, LAG scans old at most, the reply back */
#endif
#ifndef CBMC__PLC_RESTARTS /* a PLC restart (every FB instance back to its cold-start values) at any scan */
#define CBMC__PLC_RESTARTS 1
#endif
#ifndef CBMC__BLIPS /* a single all-zero scan while the controller runs on */
#define CBMC__BLIPS 1
#endif
#ifndef CBMC__TWOSTEP /* TwoStepWrite: free (-1), or fixed to 0 or 1 (a run split in two does not pay) */
#define CBMC__TWOSTEP (-1)
#endif
#ifndef CBMC__FREE_TIMING /* the controller may leave any scan without a read: a controller cycle of any length */
#define CBMC__FREE_TIMING 0
#endif
#ifndef CBMC__STUTTER /* the waiting-scan lemma (stutter.h) checked in every scan, and a stretch after each */
#define CBMC__STUTTER 0
#endif
#ifndef CBMC__STRETCH_MAX /* a stretch: 0..STRETCH_MAX more waiting scans in one step (a power of 2 less 1) */
#define CBMC__STRETCH_MAX 15
#endif
#ifndef CBMC__READING /* the controller's reading of the handshake: free (-1), or fixed (0: SEND <> RECEIVE, 1: a
                        changed SEND) for a run that takes one reading per test */
#define CBMC__READING (-1)
#endif
#ifndef CBMC__SECOND_FEW /* the second caller's Code from a short command and a stop only, Param and Data 0 */
#define CBMC__SECOND_FEW 0
#endif
#ifndef CBMC__SECOND_ALWAYS /* the second caller called in every scan (its skips are the runs without this) */
#define CBMC__SECOND_ALWAYS 0
#endif

#define PARKED_CODE 0x190B
#define SUPERSEDED 0x8007

/* The modules as the PLC left them after the last LAG + 2 scans: recent[j] after scan n - 1 - j. */
static BYTE recent[CBMC__LAG + 2][8];

/* The timeline of a counterexample (paccbmc prints it scan by scan): assigned at the end of every scan,
 * tl_scan last. A caller's pins are tl_a_* and tl_b_*. */
static unsigned long long tl_from_pac, tl_to_pac;
static int tl_ctrl_read, tl_ctrl_took;
static BOOL tl_plc_restart;
static BOOL tl_a_execute, tl_a_busy, tl_a_done, tl_a_error;
static WORD tl_a_code, tl_a_errorid;
#if CBMC__CALLERS > 1
static BOOL tl_b_execute, tl_b_busy, tl_b_done, tl_b_error;
static WORD tl_b_code, tl_b_errorid;
#endif
static int tl_scan;


/* The controller: only its RECEIVE flag follows the protocol; everything else it says is free. */
typedef struct {
    BOOL receive;
    int seen;             /* the scan whose module it read last */
    BOOL lastSend;        /* the SEND flag of that module */
    BOOL bySendChange;    /* its reading: a new command is a changed SEND (else SEND <> RECEIVE) */
    int takenScan;        /* the scan it took its last command in (0: none) */
    int taken;            /* commands taken that were not the parked read */
    int ledger;           /* entries in the ledger below: every command it took, the parked read too */
    int ledgerScan[CBMC__K + 1];
    WORD ledgerCode[CBMC__K + 1], ledgerParam[CBMC__K + 1];
    DWORD ledgerData[CBMC__K + 1];
    BOOL ledgerClaimed[CBMC__K + 1]; /* an FB ended Done for it */
    BOOL processingLong;  /* it acknowledged a long command and has not ended it */
    int downSince;        /* restarting since this scan (0: running) */
    BOOL restarted;       /* it restarted and has taken no command since */
    BOOL lastStop;        /* the last command it took was a stop, */
    BOOL lastStopSend;    /* with this SEND flag, */
    WORD lastStopCode, lastStopParam; /* code, parameter */
    DWORD lastStopData;   /* and data */
    int retakenStops;     /* stops it took again from the same module after a restart (P7) */
    BOOL blip;            /* the PLC read an all-zero image in the scan before (a lost telegram) */
} Controller;

static WORD Word(const BYTE *m, int i) { return (WORD)((m[i] << 8) | m[i + 1]); }
static DWORD Dword(const BYTE *m) {
    return ((DWORD)m[0] << 24) | ((DWORD)m[1] << 16) | ((DWORD)m[2] << 8) | (DWORD)m[3];
}
static BOOL IsStop(WORD code) { return code == 0x0600 || code == 0x0A93 || code == 0x0A9A; }
static BOOL IsLong(WORD code) {
    return F_PAC_ISLONGCOMMAND(TRUE, NULL, code);
}

/* One controller cycle before scan n: read a module (latency), take a command, write the reply.
 * A restart shows status 0 and RECEIVE 0 for at least RESTART scans, and the controller then reads no module
 * written before the PLC parked it (a real restart lasts far longer than a bus round trip). */
#define RESTART (CBMC__LAG + 2)
static void ControllerStep(Controller *c, int n, BOOL twoStep, BYTE reply[8]) {
    if (c->downSince == 0 && nondet_bool()) {
        c->downSince = n;
        c->receive = nondet_bool() ? c->lastSend : FALSE; /* where RECEIVE starts again: 0 or the last SEND */
        c->processingLong = FALSE;
        c->restarted = TRUE;
    }
    if (c->downSince != 0) {
        c->blip = FALSE;
        if (n - c->downSince < RESTART || nondet_bool()) {
            for (int i = 0; i < 8; ++i) reply[i] = 0;
            return;
        }
        /* It reads no module the PLC wrote before it could see the restart and park the module (the data in
         * the scan after the first status 0, the flag a scan later with TwoStepWrite), and under either reading
         * it starts from its RECEIVE: a SEND equal to it is no new command. */
        c->seen = n - 1 - CBMC__LAG - 1;
        if (c->seen < c->downSince + 1) c->seen = c->downSince + 1;
        c->lastSend = c->receive;
        c->downSince = 0;
    }
    /* The module it reads: 0..LAG scans old, never older than the last one it read. With CBMC__FREE_TIMING it
     * may read none in this scan although a newer one is due: its cycle is then free, not at most LAG + 1 scans
     * (docs/verification.md, "the slowest bus"). */
    const int lag = (int)(nondet_uchar() % (CBMC__LAG + 1));
    if (n - 1 - lag > c->seen && (!CBMC__FREE_TIMING || nondet_bool())) {
        BYTE module[8];
        /* Without module consistency the data may still be those of the module before the flag's. */
        const BOOL torn = twoStep && nondet_bool();
        for (int i = 0; i < 8; ++i) module[i] = (torn && i < 6) ? recent[lag + 1][i] : recent[lag][i];
        const WORD word = Word(module, 6);
        const BOOL send = (word & 0x8000) != 0;
        const BOOL isNew = c->bySendChange ? send != c->lastSend : send != c->receive;
        c->lastSend = send;
        c->seen = n - 1 - lag;
        if (isNew) {
            const WORD code = word & 0x7FFF;
            /* The parked read; read torn, its parameter and data are the module's before (a fresh interface
             * after a PLC restart parks data and flag in one write): still a read without effect. */
            const BOOL parked = code == PARKED_CODE && ((Dword(module) == 0 && Word(module, 4) == 0) || torn);
            /* P6: nothing but a stop of what runs reaches a controller that processes a long command. */
            __CPROVER_assert(!c->processingLong || parked || IsStop(code),
                             "P6 only a stop or the parked read while a command is processing");
            c->receive = send;
            c->takenScan = n;
            if (c->ledger <= CBMC__K) {
                c->ledgerScan[c->ledger] = n;
                c->ledgerCode[c->ledger] = code;
                c->ledgerParam[c->ledger] = Word(module, 4);
                c->ledgerData[c->ledger] = Dword(module);
                c->ledgerClaimed[c->ledger] = FALSE;
                c->ledger++;
            }
            /* A stop stays on the module through any status 0, never withdrawn (docs/fb/FB_PAC_Cmd.md): a
             * controller that took it, restarted before the PLC saw the acknowledgement and starts RECEIVE at 0
             * takes it again from the same module. The library sent it once; a stop makes nothing move (and a
             * controller back from a restart is in HOME POSITION): P7 counts it apart. */
            const BOOL retaken = c->restarted && c->lastStop && IsStop(code) && code == c->lastStopCode
                                 && Word(module, 4) == c->lastStopParam && Dword(module) == c->lastStopData
                                 && send == c->lastStopSend;
            c->restarted = FALSE;
            c->lastStop = IsStop(code);
            c->lastStopSend = send;
            c->lastStopCode = code;
            c->lastStopParam = Word(module, 4);
            c->lastStopData = Dword(module);
            if (retaken) c->retakenStops++;
            if (!parked && !retaken) c->taken++;
            c->processingLong = IsLong(code);
        }
    }
    /* The reply: data, error number, END OF PROCESSING, COMMAND ERROR, status and PAC error free. */
    const BYTE flags = nondet_uchar() & 0x60;
    if (flags != 0) c->processingLong = FALSE;
    for (int i = 0; i < 5; ++i) reply[i] = nondet_uchar();
    reply[5] = nondet_uchar();
    __CPROVER_assume(reply[5] != 0);
    reply[6] = (BYTE)((c->receive ? 0x80 : 0) | flags | (nondet_uchar() & 0x1F));
    reply[7] = nondet_uchar();
    /* A single scan of an all-zero image while the controller runs on (a lost telegram: status 0 for one
     * scan, RECEIVE 0 with it), never two in a row: longer is a restart. */
    c->blip = CBMC__BLIPS && !c->blip && nondet_bool();
    if (c->blip)
        for (int i = 0; i < 8; ++i) reply[i] = 0;
}

/* What the harness knows of one caller's job, for the properties. */
typedef struct {
    PlcOpenWatch plcopen;
    int edges;      /* Execute edges that the FB took (Busy or a final output followed) */
    int edgeScan;   /* the scan of the job's edge */
    WORD code, param;
    DWORD data;
} Watch;

/* The programmer's pins, in every scan the FB is called. Code comes from one representative of each class the
 * FBs tell apart (a short command, the parked read's own code, a long move, each stop, a code with bit 15 set),
 * for either caller. Param and Data take two values each: enough to tell two commands apart. */
static const WORD codes[] = {0x1906, 0x190B, 0x0A87, 0x0600, 0x0A93, 0x0A9A, 0x9906};
/* With CBMC__SECOND_FEW the second caller's (few): a short command or a stop, Param and Data 0, what it needs to
 * end Done on a command of its own and to supersede the first caller's (16#8007) beside the first one's handshake. */
static void SetPins(FB_PAC_CMD *fb, BOOL few) {
    fb->EXECUTE.value = nondet_bool();
#if CBMC__SECOND_FEW
    if (few) {
        fb->CODE.value = nondet_bool() ? 0x0600 : 0x1906;
        fb->PARAM.value = FALSE;
        fb->DATA.value = FALSE;
        return;
    }
#else
    (void)few;
#endif
    const unsigned char pick = nondet_uchar();
    fb->CODE.value = codes[pick % (sizeof codes / sizeof codes[0])];
    fb->PARAM.value = nondet_bool();
    fb->DATA.value = nondet_bool();
}

static void Check(const FB_PAC_CMD *fb, Watch *w, Controller *c, int n, BOOL edge) {
    const BOOL wasDone = w->plcopen.done;
    if (CheckPlcOpen(&w->plcopen, fb->EXECUTE.value, edge, fb->BUSY.value, fb->DONE.value, fb->ERROR.value, FALSE,
                     fb->ERRORID.value)) {
        w->edges++;
        w->edgeScan = n;
        w->code = fb->CODE.value;
        w->param = fb->PARAM.value;
        w->data = fb->DATA.value;
    }
    if (fb->DONE.value && !wasDone) {
        /* An entry of the ledger taken after the edge, with the command's code, parameter and data, that no
         * other Done claimed. */
        int match = -1;
        for (int k = 0; k <= CBMC__K; ++k) {
            if (match < 0 && k < c->ledger && !c->ledgerClaimed[k] && c->ledgerScan[k] > w->edgeScan
                && c->ledgerCode[k] == w->code && c->ledgerParam[k] == w->param && c->ledgerData[k] == w->data) {
                match = k;
            }
        }
        __CPROVER_assert(match >= 0, "P5 Done only for a command the controller took after the edge, once");
        if (match >= 0) c->ledgerClaimed[match] = TRUE;
    }
}

/* A command FB's call as an ST program makes it: on the channel itself (VAR_IN_OUT) where pacst's C passes it
 * by reference; in, the body, out where it copies (MATIEC's C, in the replay of a MATIEC build). */
static void CallCmd(FB_PAC_CMD *fb, FB_PAC_CMDINTERFACE *iface) {
#ifdef PACST_BODY_REF
    FB_PAC_CMD_body_ref__(fb, &iface->CHANNEL.value);
#else
    fb->CHANNEL.value = iface->CHANNEL.value;
    FB_PAC_CMD_body__(fb);
    iface->CHANNEL.value = fb->CHANNEL.value;
#endif
}

#if CBMC__CALLERS > 1
/* Two command FBs trade places: their whole state, pins and all (the free call order below). */
static void SwapCallers(FB_PAC_CMD *a, FB_PAC_CMD *b) {
    const FB_PAC_CMD t = *a;
    *a = *b;
    *b = t;
}
#endif

int main(void) {
    static FB_PAC_CMDINTERFACE iface, ifaceFresh;
    static FB_PAC_CMD cmd[CBMC__CALLERS], cmdFresh[CBMC__CALLERS];
    static Watch watch[CBMC__CALLERS];
    Controller ctrl = {0};
    BYTE reply[8] = {0, 0, 0, 0, 0, 1, 0x20, 0}; /* home position, nothing outstanding */
    const BOOL twoStep = CBMC__TWOSTEP < 0 ? nondet_bool() : CBMC__TWOSTEP != 0;
    int reachLibError = 0, reachPacError = 0, reachDone = 0, reachSuperseded = 0;
    int reachSkippedBusy = 0, reachReversed = 0, reachSecondDone = 0, reachDoneAfterSkip = 0, reachPlcRestart = 0;
    int reachInOrder = 0, reachOrderSwapped = 0;
    BOOL prevBoth = FALSE; /* both callers called in the scan before */
    int reachBlipBusy = 0, reachWaiting = 0, reachStretch = 0;
    long stretched = 0; /* scans the stretches added: the clock is n + stretched ms */
    long edgeMs[CBMC__CALLERS];   /* the clock at a caller's last Execute edge */
    int skipRun[CBMC__CALLERS];   /* scans in a row it has been left out while Busy, stretches counted */
    BOOL longSkip[CBMC__CALLERS]; /* left out two scans or more in a row since its edge */
    int reachSlowDone = 0;
    BOOL skippedWhileBusy[CBMC__CALLERS];
    /* The scan before, for the waiting scan (stutter.h). */
    static FB_PAC_CMDINTERFACE ifaceBefore;
    static FB_PAC_CMD cmdBefore[CBMC__CALLERS];
    BYTE prevReply[8] = {0};
    BOOL prevCalled[CBMC__CALLERS], prevReversed = FALSE, prevStill = FALSE;
    for (int i = 0; i < CBMC__CALLERS; ++i) {
        prevCalled[i] = FALSE;
        edgeMs[i] = 0;
        skipRun[i] = 0;
        longSkip[i] = FALSE;
    }

    ctrl.bySendChange = CBMC__READING < 0 ? nondet_bool() : CBMC__READING != 0;
    __CURRENT_TIME = __time_make(0, 0);
    FB_PAC_CMDINTERFACE_init__(&ifaceFresh, FALSE);
    ifaceFresh.TWOSTEPWRITE.value = twoStep;
    iface = ifaceFresh;
    /* The program has run since its cold start: its channel is past the first handshake (the parked read, in
     * step with the controller's RECEIVE 0). A PLC restart below starts a fresh channel (ifaceFresh). */
    iface.CHANNEL.value.FIRSTREADDONE = TRUE;
    for (int i = 0; i < CBMC__CALLERS; ++i) {
        const Watch none = {0};
        watch[i] = none; /* a replay runs the harness more than once in one process */
        skippedWhileBusy[i] = FALSE;
        FB_PAC_CMD_init__(&cmdFresh[i], FALSE);
        /* Timeout at least the bus round trip (TMIN); a shorter one (D1, docs/verification.md) is checked
         * with -DCBMC__TMIN=1. */
        const unsigned t = CBMC__TMIN + nondet_uchar() % CBMC__TMAX, e = 1 + nondet_uchar() % CBMC__TMAX;
        cmdFresh[i].TIMEOUT.value = __time_make(0, (long)t * CYCLE_NS);
        cmdFresh[i].ENDTIMEOUT.value = __time_make(0, (long)e * CYCLE_NS);
        cmd[i] = cmdFresh[i];
        watch[i].plcopen.bound = (int)(t + 1 + t + e); /* Timeout + two-step + Timeout + EndTimeout */
    }
    for (int j = 0; j < CBMC__LAG + 2; ++j) {
        for (int i = 0; i < 8; ++i) recent[j][i] = 0;
    }

    for (int n = 1; n <= CBMC__K; ++n) {
        __CURRENT_TIME = __time_make(0, (long)(n + stretched) * CYCLE_NS);
        if (n > 1) ControllerStep(&ctrl, n, twoStep, reply);
        /* A PLC cold start: every FB instance and the program's pins back to their initial values. What the
         * controller took before stays in its ledger (P7 counts the edges of the instances before too). */
        const BOOL plcRestart = CBMC__PLC_RESTARTS && n > 1 && nondet_bool();
        if (plcRestart) {
            iface = ifaceFresh;
            for (int i = 0; i < CBMC__CALLERS; ++i) {
                cmd[i] = cmdFresh[i];
                const int bound = watch[i].plcopen.bound;
                const PlcOpenWatch none = {0};
                watch[i].plcopen = none;
                watch[i].plcopen.bound = bound;
                skippedWhileBusy[i] = FALSE;
            }
            reachPlcRestart = 1;
        }
        BOOL edge[CBMC__CALLERS], called[CBMC__CALLERS];
        /* The waiting scan (stutter.h): the reply, the calls, their order and the pins those of the scan before. */
        BOOL waiting = CBMC__STUTTER && n > 1 && !plcRestart;
        for (int i = 0; i < 8; ++i) waiting = waiting && reply[i] == prevReply[i];
        for (int i = 0; i < CBMC__CALLERS; ++i) {
            /* A caller left out of a scan keeps its pins: a program assigns them in the call it does not make. */
            called[i] = (CBMC__SECOND_ALWAYS && i == 1) || nondet_bool();
            const BOOL before = cmd[i].EXECUTE.value;
            const WORD codeBefore = cmd[i].CODE.value, paramBefore = cmd[i].PARAM.value;
            const DWORD dataBefore = cmd[i].DATA.value;
            if (called[i]) SetPins(&cmd[i], CBMC__SECOND_FEW && i == 1);
            waiting = waiting && called[i] == prevCalled[i] && cmd[i].EXECUTE.value == before
                      && cmd[i].CODE.value == codeBefore && cmd[i].PARAM.value == paramBefore
                      && cmd[i].DATA.value == dataBefore;
            prevCalled[i] = called[i];
            edge[i] = cmd[i].EXECUTE.value && !before;
            if (!called[i] && cmd[i].BUSY.value) {
                skippedWhileBusy[i] = TRUE;
                reachSkippedBusy = 1;
            }
            if (edge[i]) {
                edgeMs[i] = n + stretched;
                longSkip[i] = FALSE;
            }
            skipRun[i] = (!called[i] && cmd[i].BUSY.value) ? skipRun[i] + 1 : 0;
        }
        for (int i = 0; i < 8; ++i) iface.CHANNEL.value.FROMPAC.table[i] = reply[i];
        for (int i = 0; i < CBMC__CALLERS; ++i)
            if (ctrl.blip && called[i] && cmd[i].BUSY.value) reachBlipBusy = 1;
        /* A stretch (stutter.h): after a still scan, d more scans like it in one step, before this one. */
        if (CBMC__STUTTER && prevStill && waiting) {
            const unsigned d = nondet_uchar() & CBMC__STRETCH_MAX;
            Stretch(&iface, cmd, called, CBMC__CALLERS, d, (long long)(n - 1 + stretched) * CYCLE_NS);
            for (int i = 0; i < CBMC__CALLERS; ++i) {
                if (called[i] && cmd[i].BUSY.value) watch[i].plcopen.busyScans += (int)d; /* P8 counts its calls */
                if (skipRun[i] > 0) skipRun[i] += (int)d; /* a skip goes on through the stretch */
            }
            stretched += (long)d;
            __CURRENT_TIME = __time_make(0, (long)(n + stretched) * CYCLE_NS);
            if (d >= 2) reachStretch = 1;
        }
        if (CBMC__STUTTER) {
            ifaceBefore = iface;
            for (int i = 0; i < CBMC__CALLERS; ++i) cmdBefore[i] = cmd[i];
            for (int i = 0; i < 8; ++i) prevReply[i] = reply[i];
        }
        FB_PAC_CMDINTERFACE_body__(&iface);
        /* The call order anew in every scan. Each call with a constant index: a pointer to cmd[symbolic] would
         * split every access in the body. */
        const BOOL reversed = CBMC__CALLERS > 1 && nondet_bool();
        /* Both orders, each with both callers called, and the order changed from one such scan to the next: the
         * order is free in every scan, not chosen once per run. */
        const BOOL both = CBMC__CALLERS > 1 && called[0] && called[CBMC__CALLERS - 1];
        if (both && reversed) reachReversed = 1;
        if (both && !reversed) reachInOrder = 1;
        if (both && prevBoth && reversed != prevReversed) reachOrderSwapped = 1;
        prevBoth = both;
        waiting = waiting && reversed == prevReversed;
        prevReversed = reversed;
#if CBMC__CALLERS > 2
#error "the free call order is written for one or two callers"
#endif
#if CBMC__CALLERS > 1
        /* Two calls, not three (the second before the first, the first, the second after it): in the reversed
         * order the two instances trade places (an FB's body reads nothing but its instance and the channel)
         * for the two calls in the fixed order, and trade back. A swap is one choice per field, cheaper than a
         * third body to execute symbolically (docs/verification.md, "two callers on the slowest bus"). */
        const BOOL firstSlot = reversed ? called[1] : called[0], secondSlot = reversed ? called[0] : called[1];
        if (reversed) SwapCallers(&cmd[0], &cmd[1]);
        if (firstSlot) CallCmd(&cmd[0], &iface);
        if (secondSlot) CallCmd(&cmd[1], &iface);
        if (reversed) SwapCallers(&cmd[0], &cmd[1]);
#else
        if (called[0]) CallCmd(&cmd[0], &iface);
#endif
        if (CBMC__STUTTER) {
            /* Still: a waiting scan that passed no limit and changed nothing but counters. S1: a waiting scan
             * after a still one (after a stretch too) is still, unless it passes a limit. */
            const BOOL noLimit = waiting && NoLimitPasses(&ifaceBefore, &iface, cmdBefore, cmd, CBMC__CALLERS);
            const BOOL check = prevStill && noLimit;
            BOOL still = StutterInterface(&ifaceBefore, &iface, check);
            for (int i = 0; i < CBMC__CALLERS; ++i)
                still = StutterCmd(&cmdBefore[i], &cmd[i], iface.CHANNEL.value.SCAN, check) && still;
            if (check) reachWaiting = 1;
            prevStill = noLimit && still;
        }
        for (int j = CBMC__LAG + 1; j > 0; --j) {
            for (int i = 0; i < 8; ++i) recent[j][i] = recent[j - 1][i];
        }
        for (int i = 0; i < 8; ++i) recent[0][i] = iface.CHANNEL.value.TOPAC.table[i];
        int edges = 0;
        for (int i = 0; i < CBMC__CALLERS; ++i) {
            if (cmd[i].DONE.value) reachDone = 1;
            if (cmd[i].DONE.value && skippedWhileBusy[i]) reachDoneAfterSkip = 1;
            if (skipRun[i] >= 2) longSkip[i] = TRUE;
            /* The slowest bus of the suites: its reply behind a module up to 15 scans old, so 16 ms or more
             * from the edge to Done, with a skip of two scans or more since the edge. */
            if (cmd[i].DONE.value && longSkip[i] && n + stretched - edgeMs[i] >= 16) reachSlowDone = 1;
            /* The second caller's ordinary command: the code latched at its edge, not the pin as changed since. */
            if (i == 1 && cmd[i].DONE.value && !IsStop(watch[i].code)) reachSecondDone = 1;
            if (cmd[i].ERROR.value && cmd[i].ERRORID.value >= 0x8000) reachLibError = 1;
            if (cmd[i].ERROR.value && cmd[i].ERRORID.value < 0x8000) reachPacError = 1;
            if (cmd[i].ERROR.value && cmd[i].ERRORID.value == SUPERSEDED) reachSuperseded = 1;
        }
        tl_from_pac = Bytes8(reply);
        tl_ctrl_read = ctrl.seen;
        tl_ctrl_took = ctrl.takenScan;
        tl_plc_restart = plcRestart;
        tl_a_execute = cmd[0].EXECUTE.value;
        tl_a_code = cmd[0].CODE.value;
        tl_a_busy = cmd[0].BUSY.value;
        tl_a_done = cmd[0].DONE.value;
        tl_a_error = cmd[0].ERROR.value;
        tl_a_errorid = cmd[0].ERRORID.value;
#if CBMC__CALLERS > 1
        tl_b_execute = cmd[1].EXECUTE.value;
        tl_b_code = cmd[1].CODE.value;
        tl_b_busy = cmd[1].BUSY.value;
        tl_b_done = cmd[1].DONE.value;
        tl_b_error = cmd[1].ERROR.value;
        tl_b_errorid = cmd[1].ERRORID.value;
#endif
        tl_to_pac = Bytes8(recent[0]);
        tl_scan = n;
        for (int i = 0; i < CBMC__CALLERS; ++i) {
            if (called[i]) Check(&cmd[i], &watch[i], &ctrl, n, edge[i]);
            edges += watch[i].edges;
        }
        /* P7: a toggle is one new command; the parked read aside, none goes out without an edge (a stop the
         * controller took again after its restart aside, above). */
        __CPROVER_assert(ctrl.taken <= edges, "P7 no command sent without an Execute edge");
    }
    __CPROVER_assert(!reachDone, "reach: Done");
    __CPROVER_assert(!reachLibError, "reach: Error with a library code");
    __CPROVER_assert(!reachPacError, "reach: Error with a controller code");
    __CPROVER_assert(iface.RESYNCS.value == 0, "reach: a resynchronisation");
    __CPROVER_assert(!reachSkippedBusy, "reach: a caller left out of a scan while Busy");
    __CPROVER_assert(!reachDoneAfterSkip, "reach: Done after a scan left out while Busy");
#if CBMC__BLIPS
    __CPROVER_assert(!reachBlipBusy, "reach: a single all-zero scan while a caller is Busy");
    /* P7's exception is reached: its acknowledgement lost in an all-zero scan, then the restart. */
    __CPROVER_assert(ctrl.retakenStops == 0, "reach: a stop taken again by a controller back from a restart");
#else
    (void)reachBlipBusy;
#endif
#if CBMC__STUTTER
    __CPROVER_assert(!reachWaiting, "reach: a waiting scan after a still one");
    __CPROVER_assert(!reachStretch, "reach: a stretch of two waiting scans or more in one step");
    __CPROVER_assert(!reachSlowDone, "reach: Done 16 ms or more after its edge, after a skip of two scans or more");
#else
    (void)reachSlowDone;
    (void)reachWaiting;
    (void)reachStretch;
#endif
#if CBMC__PLC_RESTARTS
    __CPROVER_assert(!reachPlcRestart, "reach: a PLC restart");
#else
    (void)reachPlcRestart;
#endif
#if CBMC__CALLERS > 1
    __CPROVER_assert(!reachSuperseded, "reach: a command superseded by a stop (16#8007)");
    __CPROVER_assert(!reachReversed, "reach: both callers called, the second first");
    __CPROVER_assert(!reachInOrder, "reach: both callers called, the first first");
    __CPROVER_assert(!reachOrderSwapped, "reach: the call order swapped between two scans that call both");
    __CPROVER_assert(!reachSecondDone, "reach: the second caller Done with a command other than a stop");
#else
    (void)reachSuperseded;
    (void)reachReversed;
    (void)reachInOrder;
    (void)reachOrderSwapped;
    (void)prevBoth;
    (void)reachSecondDone;
#endif
    return 0;
}
