/* Bounded model-checking harness of FB_PAC_Rs232Cmd on its two ring buffers (manual 3.3, 3.3.1;
 * docs/fb/FB_PAC_Rs232Cmd.md), on the C that pacst generates from st/, for K scans (docs/verification.md).
 * Free in every scan: each byte the controller sends (any value, 0..BYTES_PER_SCAN of them, at most
 * REPLY_BYTES after each request), the free space of TxBuffer (the driver sent any number of bytes, or none),
 * both buffers' Blocked, whether the FB is called (a CASE step or an IF branch leaves it out: the driver still
 * moves bytes, the FB's pins stay), a PLC restart (the FB and its rings back to their cold-start values), and
 * the programmer's Execute and CheckRule; per run Timeout, EndTimeout, PollInterval,
 * QuietTime (1..TMAX ms) and Retries (0 or 1); the command (Code, Param, Data) a constant of the run. Properties
 * "P<n>"/"R<n>", reachability checks "reach: ..." (which must FAIL), as in cmd_harness.c. */
#include "harness.h"

#ifndef CBMC__K
#define CBMC__K 4
#endif
#ifndef CBMC__TMAX
#define CBMC__TMAX 2
#endif
#ifndef CBMC__PLC_RESTARTS /* 0: no PLC restart (CI: at K = 2 it fits in the second scan only, at a high cost) */
#define CBMC__PLC_RESTARTS 1
#endif
#ifndef CBMC__SKIPS /* 0: the FB called in every scan (CI: at K = 2 a scan left out leaves one call, at a high cost) */
#define CBMC__SKIPS 1
#endif
#ifndef CBMC__BYTES_PER_SCAN /* bytes the controller's side puts into RxBuffer per scan at most */
#define CBMC__BYTES_PER_SCAN 8
#endif
#ifndef CBMC__REPLY_BYTES /* bytes it sends after each request at most: an acknowledgement of up to 12 text bytes */
#define CBMC__REPLY_BYTES 16
#endif

/* The command, one per run: a constant, so that its text (the REAL's decimals above all) is computed once
 * rather than bit-blasted (the text functions have their own tests, docs/verification.md). By default an
 * absolute move of axis 1 to 12.5 (0A87: a REAL, a long command polled with EOT, not repeated blindly). */
#ifndef CBMC__CMD_CODE
#define CBMC__CMD_CODE 0x0A87
#endif
#ifndef CBMC__CMD_PARAM
#define CBMC__CMD_PARAM 1
#endif
#ifndef CBMC__CMD_DATA
#define CBMC__CMD_DATA 0x41480000u /* 12.5 */
#endif

#define RING 300 /* T_PAC_ComBuffer: 300 bytes in Buffer[0..299] */

/* i modulo RING for -RING <= i < 3 x RING, without a division: a % by 300 of a free value is a divider circuit
 * in the formula, in every scan and for every byte. */
static int Ring(int i) {
    return i < 0 ? i + RING : i >= 2 * RING ? i - 2 * RING : i >= RING ? i - RING : i;
}

/* The timeline of a counterexample (paccbmc): assigned at the end of every scan, tl_scan last. from_pac: the
 * bytes the controller's side put into RxBuffer in this scan; to_pac: the first 8 the FB wrote into TxBuffer. */
static unsigned long long tl_from_pac, tl_to_pac;
static BOOL tl_execute, tl_rx_blocked, tl_tx_blocked;
static WORD tl_code;
static int tl_rule, tl_received, tl_tx_free, tl_written, tl_state;
static BOOL tl_called, tl_plc_restart;
static int tl_scan;

/* The harness's own reading of the bytes received since the last request (manual 3.3.1: STX text ETX CHECK
 * EOT, bit 7 a parity bit), independent of FB_PAC_Rs232Receiver: whether a frame came, and one whose CHECK is
 * the XOR of its text (with or without ETX), or 0 where the command's rule is ZERO. */
typedef struct {
    int phase; /* 0 outside a frame, 1 text, 2 CHECK digits */
    unsigned char sum;
    int length, check, digits;
    BOOL frame;   /* a frame ended with EOT since the last request */
    BOOL checked; /* ... with a CHECK the command's rule accepts */
    BOOL damaged; /* a frame was cut off since the last request */
} Frames;

static void Receive(Frames *f, unsigned char byte, E_PAC_RS232CHECK rule) {
    const unsigned char s = byte & 0x7F;
    if (s == 0x02) {
        f->damaged = f->damaged || f->phase != 0;
        f->phase = 1;
        f->sum = 0;
        f->length = 0;
    } else if (s == 0x01) {
        f->damaged = f->damaged || f->phase != 0;
        f->phase = 0;
    } else if (f->phase == 1) {
        if (s == 0x03) {
            f->phase = 2;
            f->check = 0;
            f->digits = 0;
        } else if (s >= 0x20 && f->length < 64) {
            f->sum ^= s;
            ++f->length;
        } else {
            f->damaged = TRUE;
            f->phase = 0;
        }
    } else if (f->phase == 2) {
        if (s >= '0' && s <= '9' && f->digits < 3) {
            f->check = f->check * 10 + (s - '0');
            ++f->digits;
        } else if (s == 0x04 && f->digits > 0) {
            f->frame = TRUE;
            f->checked = f->checked || f->check == f->sum || f->check == (f->sum ^ 0x03)
                         || (f->check == 0 && rule == E_PAC_RS232CHECK__PAC_RS232_CHECK_ZERO);
            f->phase = 0;
        } else {
            f->damaged = TRUE;
            f->phase = 0;
        }
    }
}

int main(void) {
    static FB_PAC_RS232CMD cmd, fresh;
    PlcOpenWatch watch = {0};
    Frames frames = {0};
    E_PAC_RS232CHECK rule = E_PAC_RS232CHECK__PAC_RS232_CHECK_AUTO; /* CheckRule at the last edge */
    int requests = 0, lastRequest = 0, lastByte = -1000, sinceRequest = 0;
    BOOL quietSeen = FALSE; /* the line was quiet for QuietTime at some scan since the last request */
    int reachDone = 0, reachLibError = 0, reachPacError = 0, reachRepeat = 0, reachSkippedBusy = 0;
    int reachPlcRestart = 0;

    __CURRENT_TIME = __time_make(0, 0);
    FB_PAC_RS232CMD_init__(&fresh, FALSE);
    const int t = 1 + nondet_uchar() % CBMC__TMAX, e = 1 + nondet_uchar() % CBMC__TMAX, q = 1 + nondet_uchar() % CBMC__TMAX;
    fresh.TIMEOUT.value = __time_make(0, (long)t * CYCLE_NS);
    fresh.ENDTIMEOUT.value = __time_make(0, (long)e * CYCLE_NS);
    fresh.POLLINTERVAL.value = __time_make(0, (long)(1 + nondet_uchar() % CBMC__TMAX) * CYCLE_NS);
    fresh.QUIETTIME.value = __time_make(0, (long)q * CYCLE_NS);
    fresh.RETRIES.value = nondet_bool();
    /* Busy: per request at most Timeout for a quiet line, Timeout for room in TxBuffer and Timeout for the
     * reply, Retries + 1 requests before the acknowledgement, then EndTimeout (FB_PAC_Rs232Cmd.md, "A noisy
     * line"). */
    watch.bound = (fresh.RETRIES.value + 1) * 3 * t + e;
    fresh.TXBUFFER.value.WRIDX = RING - 10; /* the first command frame wraps round the ring's end */
    cmd = fresh;
    T_PAC_COMBUFFER *tx = &cmd.TXBUFFER.value, *rx = &cmd.RXBUFFER.value;

    for (int n = 1; n <= CBMC__K; ++n) {
        __CURRENT_TIME = __time_make(0, (long)n * CYCLE_NS);
        /* A PLC cold start: the FB instance and its rings back to their initial values; what the controller
         * still sends for a request of the instance before goes into the new RxBuffer. The request history of
         * R2 starts anew (the new instance cannot know of the old request). */
        const BOOL plcRestart = CBMC__PLC_RESTARTS && n > 1 && nondet_bool();
        if (plcRestart) {
            cmd = fresh;
            const PlcOpenWatch none = {0};
            const int bound = watch.bound;
            watch = none;
            watch.bound = bound;
            rule = E_PAC_RS232CHECK__PAC_RS232_CHECK_AUTO;
            requests = 0;
            quietSeen = FALSE;
            frames = (Frames){0};
            reachPlcRestart = 1;
        }
        /* TxBuffer: the driver sent any number of the bytes, or the line is stuck: any free space. */
        const int held = nondet_ushort();
        __CPROVER_assume(held <= RING);
        tx->COUNT = (INT)held;
        tx->FREEBYTE = (INT)(RING - held);
        tx->RDIDX = (INT)Ring(tx->WRIDX + RING - held);
        tx->BLOCKED = nondet_bool();
        /* RxBuffer: the controller's bytes, any values. */
        rx->BLOCKED = nondet_bool();
        int received = nondet_uchar();
        __CPROVER_assume(received <= CBMC__BYTES_PER_SCAN);
        if (received > CBMC__REPLY_BYTES - sinceRequest) received = CBMC__REPLY_BYTES - sinceRequest;
        unsigned long long fromPac = 0;
        for (int i = 0; i < CBMC__BYTES_PER_SCAN && i < received; ++i) {
            const unsigned char byte = nondet_uchar();
            if (i < 8) fromPac |= (unsigned long long)byte << (8 * (7 - i));
            Receive(&frames, byte, rule);
            if (rx->COUNT < RING) {
                rx->BUFFER.table[rx->WRIDX] = byte;
                rx->WRIDX = (INT)Ring(rx->WRIDX + 1);
                ++rx->COUNT;
                rx->FREEBYTE = (INT)(RING - rx->COUNT);
            }
        }
        sinceRequest += received;
        if (received > 0) lastByte = n;
        if (n - lastByte >= q) quietSeen = TRUE;

        const BOOL called = CBMC__SKIPS ? nondet_bool() : 1;
        const BOOL before = cmd.EXECUTE.value;
        if (called) {
            cmd.EXECUTE.value = nondet_bool();
            cmd.CODE.value = CBMC__CMD_CODE;
            cmd.PARAM.value = CBMC__CMD_PARAM;
            cmd.DATA.value = CBMC__CMD_DATA;
            cmd.CHECKRULE.value = (E_PAC_RS232CHECK)(nondet_uchar() % 4);
        } else if (cmd.BUSY.value) {
            reachSkippedBusy = 1;
        }
        const BOOL edge = called && cmd.EXECUTE.value && !before;
        if (edge && !cmd.BUSY.value) rule = cmd.CHECKRULE.value;
        const BOOL doneBefore = cmd.DONE.value;
        const int count0 = tx->COUNT, wrIdx0 = tx->WRIDX;
        const BOOL txBlocked = tx->BLOCKED;
        if (called) FB_PAC_RS232CMD_body__(&cmd);

        const int written = tx->COUNT - count0;
        unsigned long long toPac = 0;
        for (int i = 0; i < 8 && i < written; ++i)
            toPac |= (unsigned long long)tx->BUFFER.table[Ring(wrIdx0 + i)] << (8 * (7 - i));
        tl_from_pac = fromPac;
        tl_received = received;
        tl_rx_blocked = rx->BLOCKED;
        tl_tx_free = RING - count0;
        tl_tx_blocked = txBlocked;
        tl_execute = cmd.EXECUTE.value;
        tl_code = cmd.CODE.value;
        tl_rule = cmd.CHECKRULE.value;
        TimelineOutputs(cmd.BUSY.value, cmd.DONE.value, cmd.ERROR.value, FALSE, cmd.ERRORID.value);
        tl_written = written;
        tl_to_pac = toPac;
        tl_state = cmd.STATE.value;
        tl_called = called;
        tl_plc_restart = plcRestart;
        tl_scan = n;

        /* P1..P4, P8 (plcopen_props.h); P8 counts the scans, not the calls. */
        if (!called && watch.busy) watch.busyScans++;
        if (called)
            CheckPlcOpen(&watch, cmd.EXECUTE.value, edge, cmd.BUSY.value, cmd.DONE.value, cmd.ERROR.value, FALSE,
                     cmd.ERRORID.value);
        /* R1: a request goes into TxBuffer whole (a command frame SOH .. EOT, or an EOT poll), only into its
         * free space, never into a buffer the driver holds. */
        const unsigned char first = tx->BUFFER.table[Ring(wrIdx0)];
        const unsigned char last = tx->BUFFER.table[Ring(wrIdx0 + written - 1)];
        __CPROVER_assert(written >= 0 && written <= RING - count0, "R1 nothing written past TxBuffer's free space");
        __CPROVER_assert(tx->WRIDX == Ring(wrIdx0 + written) && tx->FREEBYTE == RING - tx->COUNT,
                         "R1 TxBuffer's indices follow the bytes written");
        __CPROVER_assert(written == 0 || (!txBlocked && last == 0x04 && (written == 1 || first == 0x01)),
                         "R1 a whole request or nothing, never into a held buffer");
        /* R2: one request at a time: a request goes out only when the one before it is over: its reply came
         * (a frame with a good CHECK), or it is lost (Timeout since it, or a cut-off frame) and the line has
         * been quiet for QuietTime since it was sent. */
        if (written > 0) {
            __CPROVER_assert(requests == 0 || frames.checked
                                 || ((frames.damaged || frames.frame || n - lastRequest >= t) && quietSeen),
                             "R2 no request while the one before it awaits its reply");
            ++requests;
            lastRequest = n;
            sinceRequest = 0;
            quietSeen = FALSE;
            frames = (Frames){0};
        }
        /* R3: Done only after a reply that checks: since the last request a frame came whose CHECK the
         * command's rule accepts; a serial link is never left unchecked. */
        __CPROVER_assert(!cmd.DONE.value || doneBefore || frames.checked,
                         "R3 Done only after an acknowledgement whose CHECK holds");

        if (cmd.DONE.value) reachDone = 1;
        if (cmd.ERROR.value && cmd.ERRORID.value >= 0x8000) reachLibError = 1;
        if (cmd.ERROR.value && cmd.ERRORID.value < 0x8000) reachPacError = 1;
        if (cmd.REPEATS.value > 0) reachRepeat = 1;
    }
    __CPROVER_assert(!reachDone, "reach: Done");
    __CPROVER_assert(!reachLibError, "reach: Error with a library code");
    __CPROVER_assert(!reachPacError, "reach: Error with the controller's QUIT");
    __CPROVER_assert(!reachRepeat, "reach: a request sent again");
#if CBMC__SKIPS
    __CPROVER_assert(!reachSkippedBusy, "reach: the FB left out of a scan while Busy");
#endif
#if CBMC__PLC_RESTARTS
    __CPROVER_assert(!reachPlcRestart, "reach: a PLC restart");
#else
    (void)reachPlcRestart;
#endif
    return 0;
}
