/* The PLCopen properties every harness checks of an FB with Execute, Busy, Done, Error and ErrorID after each
 * scan (docs/verification.md, P1..P4 and P8), with what the harness remembers of the scan before. */
#ifndef PAC_CBMC_PLCOPEN_PROPS_H
#define PAC_CBMC_PLCOPEN_PROPS_H

typedef struct {
    BOOL execute, busy, done, error, aborted;
    BOOL replaced; /* a running job ended by a new edge in the scan before: that final output is shown once */
    int busyScans;
    int bound;  /* the longest Busy in scans the FB's documentation allows */
    BOOL edgeRestarts; /* an edge while Busy starts a new job (the MC blocks): Busy counts from the last edge */
} PlcOpenWatch;

/* Checks one scan's outputs; edge: Execute rose in this scan; aborted: CommandAborted (FALSE for an FB
 * without it), a final output like Done and Error. Returns TRUE when the FB took an edge (a job started:
 * Busy or a final output from none). */
static BOOL CheckPlcOpen(PlcOpenWatch *w, BOOL execute, BOOL edge, BOOL busy, BOOL done, BOOL error, BOOL aborted,
                         WORD errorId) {
    __CPROVER_assert((busy + done + error + aborted) <= 1,
                     "P1 Busy, Done, Error and CommandAborted mutually exclusive");
    __CPROVER_assert(!error || errorId != 0, "P2 Error implies ErrorID <> 0");
    __CPROVER_assert(!done || errorId == 0, "P2 Done implies ErrorID = 0");
    const BOOL was = w->busy || w->done || w->error || w->aborted;
    const BOOL now = busy || done || error || aborted;
    const BOOL final = done || error || aborted;
    __CPROVER_assert(was || !now || edge, "P3 no output without an Execute edge");
    /* A job that a new Execute edge replaced ends with its final output for one scan, and the new job owns
     * the outputs from the next scan on (FB_PAC_Axis.md, "A new Execute edge during a job"). */
    __CPROVER_assert(w->replaced || !(w->done || w->error || w->aborted) || execute || !final,
                     "P4 a final output clears in the scan that sees Execute FALSE");
    const BOOL held = w->execute && execute && !edge && !w->replaced;
    __CPROVER_assert(!(w->done && held) || done, "P4 Done holds while Execute stays TRUE");
    __CPROVER_assert(!(w->error && held) || error, "P4 Error holds while Execute stays TRUE");
    __CPROVER_assert(!(w->aborted && held) || aborted, "P4 CommandAborted holds while Execute stays TRUE");
    __CPROVER_assert(!w->busy || now, "P4 a job that ends shows its final output");
    const BOOL took = edge && now && !w->busy;
    w->replaced = w->busy && edge && final;
    w->busyScans = !busy ? 0 : (w->edgeRestarts && edge) ? 1 : w->busyScans + 1;
    __CPROVER_assert(w->busyScans <= w->bound, "P8 Busy within the bound its timeouts set");
    w->execute = execute;
    w->busy = busy;
    w->done = done;
    w->error = error;
    w->aborted = aborted;
    return took;
}

#endif
