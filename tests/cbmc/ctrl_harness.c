/* Bounded model-checking harness of FB_PAC_Ctrl on the CTRL interface (manual 2.5), on the C that pacst
 * generates from st/, for K scans (docs/verification.md). Free in every scan: whether the FB is called (a CASE
 * step or an IF branch leaves it out: its pins and its module then unchanged), the programmer's Execute,
 * Request (every value of E_PAC_CtrlRequest) and IntegerMode, a PLC restart (the FB and its module back to
 * their cold-start values), and the Timeout (1..TMAX ms) per run.
 * The controller, chosen per run: either all 8 bytes it sends free in every scan (whatever a controller, a
 * restart or a lost link may show), or a protocol-faithful one that reads the control word 0..LAG scans late,
 * changes its operating mode only for a request bit it reads where the manual lets it act on it (2.5.1; a
 * start on the bit's rising edge), keeps a ledger of the requests it executed, may raise a system error (a
 * running mode then stops), may restart (status word 0 for at least LAG + 2 scans, then home position) and
 * may show a single all-zero scan. Against it: CL1, Done only for a request the controller executed since
 * the FB's edge, or at the edge when the status word already showed the result; CL2, Done only while the
 * controller is where the request leaves it. Properties "P<n>"/"C<n>"/"CL<n>", reachability checks
 * "reach: ..." (which must FAIL), as in cmd_harness.c. */
#include "harness.h"

#ifndef CBMC__K
#define CBMC__K 6
#endif
#ifndef CBMC__TMAX
#define CBMC__TMAX 3
#endif
#ifndef CBMC__LAG
#define CBMC__LAG 1
#endif
#ifndef CBMC__PLC_RESTARTS /* 0: no PLC restart (to tell a path that needs one from one that does not) */
#define CBMC__PLC_RESTARTS 1
#endif

/* The timeline of a counterexample (paccbmc): assigned at the end of every scan, tl_scan last. */
static unsigned long long tl_from_pac, tl_to_pac;
static BOOL tl_called, tl_plc_restart, tl_execute;
static int tl_request, tl_mode, tl_ctrl_read;
static int tl_scan;

/* The control word's request bits (2.5.1): Error reset, Stop and Cancel low-active, the starts high-active. */
#define BIT_RESET 0x0001u
#define BIT_STOP 0x0002u
#define BIT_CANCEL 0x0004u
#define BIT_START_AUTOMATIC 0x0008u
#define BIT_START_ONLINE 0x0010u

/* The controller's operating mode as the CTRL status word shows it (2.5.2). */
enum { HOME, ONLINE_RUNS, ONLINE_STOPPED, AUTOMATIC_RUNS, AUTOMATIC_STOPPED };

/* The modules as the PLC left them after the last LAG + 1 scans: recent[j] after scan n - 1 - j. */
static BYTE recent[CBMC__LAG + 1][8];

typedef struct {
    int mode;
    BOOL starting;    /* a start taken: the one-cycle status (30, 10) without a mode bit may show first */
    BOOL systemError; /* a system error pending; its number is free, a CPU error (1..99) too */
    WORD errorNumber;
    int seen;         /* the scan whose module it read last */
    unsigned starts;  /* the start bits of that module: a start acts on its rising edge (FB_PAC_Ctrl.md) */
    int downSince;    /* restarting since this scan (0: running) */
    int ledger;       /* the requests it executed: the request, the scan before which it executed it */
    int ledgerRequest[CBMC__K + 1], ledgerScan[CBMC__K + 1];
} Controller;

static void Execute(Controller *c, int request, int n) {
    if (c->ledger <= CBMC__K) {
        c->ledgerRequest[c->ledger] = request;
        c->ledgerScan[c->ledger] = n;
        c->ledger++;
    }
}

/* One controller cycle before scan n: maybe restart, read a module (latency), act on its request bits, write
 * the status word. Returns in reply the 8 bytes the PLC reads in scan n. */
#define RESTART (CBMC__LAG + 2)
static void ControllerStep(Controller *c, int n, BYTE reply[8]) {
    if (c->downSince == 0 && nondet_bool()) c->downSince = n;
    if (c->downSince != 0) {
        for (int i = 0; i < 8; ++i) reply[i] = 0;
        if (n - c->downSince < RESTART || nondet_bool()) return;
        c->downSince = 0;
        c->mode = HOME;
        c->starting = FALSE;
        c->systemError = FALSE;
        c->seen = n - 1 - CBMC__LAG - 1; /* only modules the PLC wrote once it could see the restart */
        /* What it compares the first control word after booting with is not written: either reading. */
        c->starts = nondet_bool() ? 0u : (BIT_START_ONLINE | BIT_START_AUTOMATIC);
    }
    const int lag = (int)(nondet_uchar() % (CBMC__LAG + 1));
    if (n - 1 - lag > c->seen) {
        const BYTE *m = recent[lag];
        const unsigned word = ((unsigned)m[0] << 8) | m[1];
        const unsigned rising = word & ~c->starts & (BIT_START_ONLINE | BIT_START_AUTOMATIC);
        c->starts = word & (BIT_START_ONLINE | BIT_START_AUTOMATIC);
        c->seen = n - 1 - lag;
        /* One request per cycle, the safe ones first (an all-zero module asks for all three low-active ones). */
        if ((word & BIT_CANCEL) == 0 && c->mode != HOME) {
            Execute(c, E_PAC_CTRLREQUEST__PAC_REQ_CANCEL, n);
            c->mode = HOME;
            c->starting = FALSE;
        } else if ((word & BIT_STOP) == 0 && (c->mode == ONLINE_RUNS || c->mode == AUTOMATIC_RUNS)) {
            Execute(c, E_PAC_CTRLREQUEST__PAC_REQ_STOP, n);
            c->mode = c->mode == ONLINE_RUNS ? ONLINE_STOPPED : AUTOMATIC_STOPPED;
            c->starting = FALSE;
        } else if ((word & BIT_RESET) == 0 && c->mode == HOME && c->systemError
                   && !(c->errorNumber >= 1 && c->errorNumber <= 99)) {
            Execute(c, E_PAC_CTRLREQUEST__PAC_REQ_RESET_ERROR, n);
            c->systemError = FALSE;
        } else if ((rising & BIT_START_ONLINE) != 0 && !c->systemError
                   && (c->mode == HOME || c->mode == ONLINE_STOPPED)) {
            Execute(c, E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE, n);
            c->mode = ONLINE_RUNS;
            c->starting = TRUE;
        } else if ((rising & BIT_START_AUTOMATIC) != 0 && !c->systemError
                   && (c->mode == HOME || c->mode == AUTOMATIC_STOPPED)) {
            Execute(c, E_PAC_CTRLREQUEST__PAC_REQ_START_AUTOMATIC, n);
            c->mode = AUTOMATIC_RUNS;
            c->starting = TRUE;
        }
    }
    /* A malfunction at any time: a system error, which stops a running mode (ONLINE 37 -> 39, AUTOMATIC 17..19). */
    if (!c->systemError && nondet_bool()) {
        c->systemError = TRUE;
        c->errorNumber = nondet_ushort();
        c->starting = FALSE; /* 37 then 39, 17..19: the mode's bits show */
        if (c->mode == ONLINE_RUNS) c->mode = ONLINE_STOPPED;
        if (c->mode == AUTOMATIC_RUNS) c->mode = AUTOMATIC_STOPPED;
    }
    if (c->starting && nondet_bool()) c->starting = FALSE;
    const BOOL blip = nondet_bool(); /* a single scan of an all-zero image (a lost telegram) */
    unsigned word = 0x0001u | (nondet_bool() ? 0x0002u : 0) | (c->systemError ? 0x0004u : 0)
                    | (nondet_bool() ? 0x8000u : 0);
    if (!c->starting) {
        if (c->mode == ONLINE_RUNS) word |= 0x0400u;
        if (c->mode == ONLINE_STOPPED) word |= 0x0C00u;
        if (c->mode == AUTOMATIC_RUNS) word |= 0x0100u;
        if (c->mode == AUTOMATIC_STOPPED) word |= 0x0300u;
    }
    reply[0] = (BYTE)(word >> 8);
    reply[1] = (BYTE)word;
    reply[2] = reply[3] = reply[6] = reply[7] = 0;
    reply[4] = c->systemError ? (BYTE)(c->errorNumber >> 8) : 0;
    reply[5] = c->systemError ? (BYTE)c->errorNumber : 0;
    if (blip)
        for (int i = 0; i < 8; ++i) reply[i] = 0;
}

/* The mode a request leaves the controller in, when it is Done. */
static BOOL ShowsResult(const Controller *c, int request) {
    switch (request) {
    case E_PAC_CTRLREQUEST__PAC_REQ_START_ONLINE: return c->mode == ONLINE_RUNS && !c->starting && !c->systemError;
    case E_PAC_CTRLREQUEST__PAC_REQ_START_AUTOMATIC:
        return c->mode == AUTOMATIC_RUNS && !c->starting && !c->systemError;
    case E_PAC_CTRLREQUEST__PAC_REQ_STOP: return c->mode == ONLINE_STOPPED || c->mode == AUTOMATIC_STOPPED;
    case E_PAC_CTRLREQUEST__PAC_REQ_CANCEL: return c->mode == HOME;
    case E_PAC_CTRLREQUEST__PAC_REQ_RESET_ERROR: return c->mode == HOME && !c->systemError;
    default: return FALSE;
    }
}

int main(void) {
    static FB_PAC_CTRL ctrl, fresh;
    PlcOpenWatch watch = {0};
    Controller pac = {0};
    BYTE reply[8] = {0, 0x03, 0, 0, 0, 0, 0, 0}; /* home position, ready, battery ok */
    int edgeScan = 0, latched = 0;
    BOOL underWay = FALSE; /* at the edge the controller had taken this very request and not shown its result yet */
    int reachDone = 0, reachLibError = 0, reachSystemError = 0, reachTimeout = 0, reachExecutedDone = 0;
    int reachSkippedBusy = 0, reachDoneAfterSkip = 0, reachPlcRestart = 0, reachCtrlRestart = 0, reachBlipError = 0;
    BOOL skippedWhileBusy = FALSE;

    const BOOL faithful = nondet_bool(); /* the protocol-faithful controller, or free bytes */
    __CURRENT_TIME = __time_make(0, 0);
    FB_PAC_CTRL_init__(&fresh, FALSE);
    const unsigned t = 1 + nondet_uchar() % CBMC__TMAX;
    fresh.TIMEOUT.value = __time_make(0, (long)t * CYCLE_NS);
    ctrl = fresh;
    watch.bound = (int)t; /* FB_PAC_Ctrl: Timeout from the edge scan (plcopen_checker.hpp, RequestBusyBound) */
    for (int j = 0; j <= CBMC__LAG; ++j)
        for (int i = 0; i < 8; ++i) recent[j][i] = 0;

    for (int n = 1; n <= CBMC__K; ++n) {
        __CURRENT_TIME = __time_make(0, (long)n * CYCLE_NS);
        if (n > 1) {
            if (faithful) {
                const int wasDown = pac.downSince;
                ControllerStep(&pac, n, reply);
                if (wasDown == 0 && pac.downSince != 0) reachCtrlRestart = 1;
            } else {
                for (int i = 0; i < 8; ++i) reply[i] = nondet_uchar();
            }
        }
        /* A PLC cold start: the FB instance and the module image back to their initial values, the program's
         * Execute FALSE; the controller sees the zero image (Stop, Cancel and Error reset at once, 2.5.1). */
        const BOOL plcRestart = CBMC__PLC_RESTARTS && n > 1 && nondet_bool();
        if (plcRestart) {
            ctrl = fresh;
            const PlcOpenWatch none = {0};
            watch = none;
            watch.bound = (int)t;
            skippedWhileBusy = FALSE;
            reachPlcRestart = 1;
        }
        const BOOL called = nondet_bool();
        const BOOL before = ctrl.EXECUTE.value;
        int request = 0;
        if (called) {
            ctrl.EXECUTE.value = nondet_bool();
            request = nondet_uchar() % 6;
            ctrl.REQUEST.value = (E_PAC_CTRLREQUEST)request;
            ctrl.INTEGERMODE.value = nondet_bool();
            for (int i = 0; i < 8; ++i) ctrl.FROMPAC.value.table[i] = reply[i];
            FB_PAC_CTRL_body__(&ctrl);
        } else if (ctrl.BUSY.value) {
            skippedWhileBusy = TRUE;
            reachSkippedBusy = 1;
        }
        const BOOL edge = called && ctrl.EXECUTE.value && !before;

        const BYTE *out = ctrl.TOPAC.value.table;
        for (int j = CBMC__LAG; j > 0; --j)
            for (int i = 0; i < 8; ++i) recent[j][i] = recent[j - 1][i];
        for (int i = 0; i < 8; ++i) recent[0][i] = out[i];
        tl_from_pac = Bytes8(reply);
        tl_called = called;
        tl_plc_restart = plcRestart;
        tl_execute = ctrl.EXECUTE.value;
        tl_request = request;
        tl_mode = faithful ? pac.mode : -1;
        tl_ctrl_read = pac.seen;
        TimelineOutputs(ctrl.BUSY.value, ctrl.DONE.value, ctrl.ERROR.value, FALSE, ctrl.ERRORID.value);
        tl_to_pac = Bytes8(out);
        tl_scan = n;

        if (!called) {
            /* P8 counts the scans, not the calls: Busy ends in the first call after its bound. */
            if (watch.busy) watch.busyScans++;
            continue;
        }
        const BOOL wasDone = watch.done;
        if (CheckPlcOpen(&watch, ctrl.EXECUTE.value, edge, ctrl.BUSY.value, ctrl.DONE.value, ctrl.ERROR.value, FALSE,
                         ctrl.ERRORID.value)) {
            edgeScan = n;
            latched = request;
            underWay = faithful && pac.starting && pac.ledger > 0 && pac.ledgerRequest[pac.ledger - 1] == request;
        }
        /* CL1: Done only for the request the controller executed in the cycle whose image the edge scan read or
         * later, or in the edge scan itself when the status word already showed the request's result; and the
         * controller is where the request leaves it. The CTRL bits are levels without a handshake: the
         * controller acts on the bit it reads, whichever scan's module carried it. A start it took before the
         * edge (an instance before a PLC restart, or a request that timed out) and shows no mode bit for yet is
         * that same request under way: its result is the one asked for. */
        if (faithful && ctrl.DONE.value && !wasDone) {
            BOOL executed = FALSE;
            for (int k = 0; k <= CBMC__K; ++k)
                executed = executed
                           || (k < pac.ledger && pac.ledgerRequest[k] == latched && pac.ledgerScan[k] >= edgeScan);
            __CPROVER_assert(executed || underWay || n == edgeScan,
                             "CL1 Done only for the request the controller executed after the edge");
            /* CL2: and the controller is where the request leaves it, not in a start's one-cycle status (30, 10),
             * which shows no mode bit like home position. */
            __CPROVER_assert(ShowsResult(&pac, latched),
                             "CL2 Done only while the controller is where the request leaves it");
            if (executed && n > edgeScan) reachExecutedDone = 1;
        }
        /* C1: the control word (bytes 0..1; 2..7 unused) carries at most one request: Error reset, Stop and
         * Cancel are low-active, the two starts high-active; and none at all unless a request waits. */
        const WORD word = (WORD)((out[0] << 8) | out[1]);
        const int requests = ((word & 0x0001) == 0) + ((word & 0x0002) == 0) + ((word & 0x0004) == 0)
                             + ((word & 0x0008) != 0) + ((word & 0x0010) != 0);
        __CPROVER_assert(requests <= 1, "C1 at most one CTRL request bit on the wire");
        __CPROVER_assert(ctrl.BUSY.value || requests == 0, "C1 no request bit without a request waiting");
        __CPROVER_assert((word & 0x7FE0) == 0 && out[2] == 0 && out[3] == 0 && out[4] == 0 && out[5] == 0
                             && out[6] == 0 && out[7] == 0,
                         "C2 nothing but the control word's bits 0..4 and 15 on the wire");
        __CPROVER_assert(((word & 0x8000) != 0) == (ctrl.INTEGERMODE.value != 0), "C2 bit 15 is IntegerMode");

        if (ctrl.DONE.value) reachDone = 1;
        if (ctrl.DONE.value && skippedWhileBusy) reachDoneAfterSkip = 1;
        if (!ctrl.BUSY.value) skippedWhileBusy = FALSE;
        if (ctrl.ERROR.value && ctrl.ERRORID.value >= 0x8000) reachLibError = 1;
        if (ctrl.ERROR.value && ctrl.ERRORID.value < 0x8000) reachSystemError = 1;
        if (ctrl.ERROR.value && ctrl.ERRORID.value == 0x8009) reachTimeout = 1;
        if (faithful && ctrl.ERROR.value && ctrl.ERRORID.value == 0x8004 && pac.downSince == 0) reachBlipError = 1;
    }
    __CPROVER_assert(!reachDone, "reach: Done");
    __CPROVER_assert(!reachLibError, "reach: Error with a library code");
    __CPROVER_assert(!reachSystemError, "reach: Error with the controller's system error number");
    __CPROVER_assert(!reachTimeout, "reach: the request's Timeout (16#8009)");
    __CPROVER_assert(!reachExecutedDone, "reach: Done for a request the controller executed");
    __CPROVER_assert(!reachSkippedBusy, "reach: the FB left out of a scan while Busy");
    __CPROVER_assert(!reachDoneAfterSkip, "reach: Done after a scan left out while Busy");
    __CPROVER_assert(!reachPlcRestart, "reach: a PLC restart");
    __CPROVER_assert(!reachCtrlRestart, "reach: a controller restart");
    __CPROVER_assert(!reachBlipError, "reach: a single all-zero scan ends a request (16#8004)");
    return 0;
}
