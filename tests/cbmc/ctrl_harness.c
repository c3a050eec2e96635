/* Bounded model-checking harness of FB_PAC_Ctrl on the CTRL interface (manual 2.5), on the C that pacst
 * generates from st/, for K scans (docs/verification.md). Free: all 8 bytes the controller sends in every
 * scan (status word, system error number: whatever a controller, a restart or a lost link may show), the
 * programmer's Execute, Request (every value of E_PAC_CtrlRequest) and IntegerMode in every scan, and the
 * Timeout (1..TMAX ms). Properties are __CPROVER_assert "P<n> ..." / "C<n> ...", reachability checks
 * "reach: ..." (which must FAIL), as in cmd_harness.c. */
#include "harness.h"

#ifndef CBMC__K
#define CBMC__K 6
#endif
#ifndef CBMC__TMAX
#define CBMC__TMAX 3
#endif

/* The timeline of a counterexample (paccbmc): assigned at the end of every scan, tl_scan last. */
static unsigned long long tl_from_pac, tl_to_pac;
static BOOL tl_execute;
static int tl_request;
static int tl_scan;

int main(void) {
    static FB_PAC_CTRL ctrl;
    PlcOpenWatch watch = {0};
    int reachDone = 0, reachLibError = 0, reachSystemError = 0, reachTimeout = 0;

    __CURRENT_TIME = __time_make(0, 0);
    FB_PAC_CTRL_init__(&ctrl, FALSE);
    const unsigned t = 1 + nondet_uchar() % CBMC__TMAX;
    ctrl.TIMEOUT.value = __time_make(0, (long)t * CYCLE_NS);
    watch.bound = (int)t; /* FB_PAC_Ctrl: Timeout from the edge scan (plcopen_checker.hpp, RequestBusyBound) */

    for (int n = 1; n <= CBMC__K; ++n) {
        __CURRENT_TIME = __time_make(0, (long)n * CYCLE_NS);
        for (int i = 0; i < 8; ++i) ctrl.FROMPAC.value.table[i] = nondet_uchar();
        const BOOL before = ctrl.EXECUTE.value;
        ctrl.EXECUTE.value = nondet_bool();
        const BOOL edge = ctrl.EXECUTE.value && !before;
        const unsigned char request = nondet_uchar() % 6;
        ctrl.REQUEST.value = (E_PAC_CTRLREQUEST)request;
        ctrl.INTEGERMODE.value = nondet_bool();
        FB_PAC_CTRL_body__(&ctrl);

        const BYTE *out = ctrl.TOPAC.value.table;
        tl_from_pac = Bytes8(ctrl.FROMPAC.value.table);
        tl_execute = ctrl.EXECUTE.value;
        tl_request = request;
        TimelineOutputs(ctrl.BUSY.value, ctrl.DONE.value, ctrl.ERROR.value, FALSE, ctrl.ERRORID.value);
        tl_to_pac = Bytes8(out);
        tl_scan = n;

        CheckPlcOpen(&watch, ctrl.EXECUTE.value, edge, ctrl.BUSY.value, ctrl.DONE.value, ctrl.ERROR.value, FALSE,
                     ctrl.ERRORID.value);
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
        if (ctrl.ERROR.value && ctrl.ERRORID.value >= 0x8000) reachLibError = 1;
        if (ctrl.ERROR.value && ctrl.ERRORID.value < 0x8000) reachSystemError = 1;
        if (ctrl.ERROR.value && ctrl.ERRORID.value == 0x8009) reachTimeout = 1;
    }
    __CPROVER_assert(!reachDone, "reach: Done");
    __CPROVER_assert(!reachLibError, "reach: Error with a library code");
    __CPROVER_assert(!reachSystemError, "reach: Error with the controller's system error number");
    __CPROVER_assert(!reachTimeout, "reach: the request's Timeout (16#8009)");
    return 0;
}
