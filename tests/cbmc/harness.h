/* What every CBMC harness of tests/cbmc shares (docs/verification.md): the clock the translated ST reads,
 * the free inputs (nondet_*: CBMC leaves a body-less function's result free; a replay returns the recorded
 * values, replay_inputs.c), the PLC cycle, the timeline helpers and the PLCopen properties. */
#ifndef PAC_CBMC_HARNESS_H
#define PAC_CBMC_HARNESS_H

#include "POUS.h"

#ifndef PAC_CBMC_REPLAY_SHIM_H /* a replay defines them once for all its harnesses (replay_inputs.c) */
TIME __CURRENT_TIME;
BOOL __DEBUG;
#endif

_Bool nondet_bool(void);
unsigned char nondet_uchar(void);
unsigned short nondet_ushort(void);
unsigned int nondet_uint(void);

#define CYCLE_NS 1000000L /* the PLC cycle: 1 ms, the fastest timing of the library suites */

/* A module's first 8 bytes as one number for the timeline, PAC byte 0 first (paccbmc prints them as bytes). */
static unsigned long long Bytes8(const BYTE *m) {
    unsigned long long v = 0;
    for (int i = 0; i < 8; ++i) v = (v << 8) | m[i];
    return v;
}

/* The timeline of a counterexample (paccbmc prints it scan by scan): each harness assigns its tl_* globals at
 * the end of every scan, tl_scan last; these are the columns of an FB's PLCopen outputs. */
static BOOL tl_busy, tl_done, tl_error, tl_aborted;
static WORD tl_errorid;
static void TimelineOutputs(BOOL busy, BOOL done, BOOL error, BOOL aborted, WORD errorId) {
    tl_busy = busy;
    tl_done = done;
    tl_error = error;
    tl_aborted = aborted;
    tl_errorid = errorId;
}

#include "plcopen_props.h"

#endif
