/* The PLCopen properties every harness checks of an FB with Execute, Busy, Done, Error and ErrorID after each
 * scan (docs/verification.md, P1..P4 and P8), with what the harness remembers of the scan before. */
#ifndef PAC_CBMC_PLCOPEN_PROPS_H
#define PAC_CBMC_PLCOPEN_PROPS_H

typedef struct {
    BOOL execute, busy, done, error;
    int busyScans;
    int bound;  /* the longest Busy in scans the FB's documentation allows */
} PlcOpenWatch;

/* Checks one scan's outputs; edge: Execute rose in this scan. Returns TRUE when the FB took an edge (a
 * job started: Busy or a final output from none). */
static BOOL CheckPlcOpen(PlcOpenWatch *w, BOOL execute, BOOL edge, BOOL busy, BOOL done, BOOL error, WORD errorId) {
    __CPROVER_assert((busy + done + error) <= 1, "P1 Busy, Done and Error mutually exclusive");
    __CPROVER_assert(!error || errorId != 0, "P2 Error implies ErrorID <> 0");
    __CPROVER_assert(!done || errorId == 0, "P2 Done implies ErrorID = 0");
    const BOOL was = w->busy || w->done || w->error;
    __CPROVER_assert(was || !(busy || done || error) || edge, "P3 no output without an Execute edge");
    __CPROVER_assert(!(w->done || w->error) || execute || !(done || error),
                     "P4 a final output clears in the scan that sees Execute FALSE");
    __CPROVER_assert(!(w->done && w->execute && execute) || done, "P4 Done holds while Execute stays TRUE");
    __CPROVER_assert(!(w->error && w->execute && execute) || error, "P4 Error holds while Execute stays TRUE");
    __CPROVER_assert(!w->busy || busy || done || error, "P4 a job that ends shows its final output");
    const BOOL took = edge && (busy || done || error) && !w->busy;
    w->busyScans = busy ? w->busyScans + 1 : 0;
    __CPROVER_assert(w->busyScans <= w->bound, "P8 Busy within the bound its timeouts set");
    w->execute = execute;
    w->busy = busy;
    w->done = done;
    w->error = error;
    return took;
}

#endif
