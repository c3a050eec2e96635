/* Bounded model-checking harness of FB_PAC_Rs232Cmd on its two ring buffers (manual 3.3, 3.3.1;
 * docs/fb/FB_PAC_Rs232Cmd.md), on the C that pacst generates from st/, for K scans (docs/verification.md),
 * against a protocol-faithful controller that keeps a ledger of the frames it executed and what it answered.
 * Free in every scan: the free space of TxBuffer (the driver sent any number of bytes, or none), both buffers'
 * Blocked, whether the request written in the scan reaches the controller or the line loses it, how many of the
 * controller's bytes on their way reach RxBuffer (0..BYTES_PER_SCAN) and whether the line drops the rest,
 * whether the FB is called (a CASE step or an IF branch leaves it out: the driver still moves bytes, the FB's
 * pins stay; with CBMC__LONG_SKIPS it is called in every step, after a free gap of scans left out), a PLC
 * restart (the FB and its rings back to their cold-start values; the controller runs on), and the programmer's
 * Execute and CheckRule; per run Timeout, EndTimeout, PollInterval, QuietTime (1..TMAX ms),
 * Retries (0 or 1) and the controller's reading of the CHECK; the command (Code, Param, Data) a constant of the
 * run. Properties "P<n>"/"R<n>"/"L<n>", reachability checks "reach: ..." (which must FAIL), as in cmd_harness.c. */
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
#ifndef CBMC__LONG_SKIPS /* 1: the FB called in every step, after 0 .. STRETCH_MAX scans it was left out of */
#define CBMC__LONG_SKIPS 0
#endif
#ifndef CBMC__STRETCH_MAX /* a power of 2 less 1 */
#define CBMC__STRETCH_MAX 15
#endif
#ifndef CBMC__BYTES_PER_SCAN /* bytes of the controller's that reach RxBuffer per scan at most: a whole reply */
#define CBMC__BYTES_PER_SCAN 18
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

/* The frames' texts as manual 3.3 composes them, written out here, independent of the FB's text functions: the
 * command's, also with PAR_1 in the leading-zero form the FB uses where a text's XOR would make its CHECK 0 or 3
 * (the same number: the controller executes the same command), and the probe's (the read 190B that goes first
 * in AUTO until a rule is confirmed, docs/fb/FB_PAC_Rs232Cmd.md). With another CBMC__CMD_CODE, define these. */
#ifndef CBMC__CMD_TEXT
#define CBMC__CMD_TEXT "0A87;1;1;12.5"
#define CBMC__CMD_TEXT_ZERO "0A87;01;1;12.5"
#define CBMC__CMD_LONG 1 /* acknowledged with BE 0 while it runs (a move), BE 1 on a later poll */
#endif
#define PROBE_TEXT "190B;0;0;0"
#ifndef CBMC__NOISE /* 1: the line may spoil one byte of the controller's per scan (any value) */
#define CBMC__NOISE 0
#endif

#define RING 300 /* T_PAC_ComBuffer: 300 bytes in Buffer[0..299] */

enum { REQ_POLL = 1, REQ_COMMAND, REQ_PROBE, REQ_OTHER }; /* a request as the controller reads it */
enum { TOOK_NOTHING, TOOK_COMMAND, TOOK_PROBE, TOOK_POLL, TOOK_REFUSED, TOOK_CHECK_16, TOOK_IGNORED, TOOK_LOST };

#define FRAME_MAX 19 /* the controller's longest acknowledgement: QUIT 16 or 20 and a CHECK of 3 digits */
#define LEDGER CBMC__K /* one request per scan at most (R1, R2) */

/* What the controller executed: which text, in which scan, and what it answered (STATUS, Q_PAR). */
typedef struct {
    int kind, scan, status, data;
} Entry;

/* A reply on its way: its bytes at fixed places (the formula then holds no write at a free index). */
typedef struct {
    unsigned char byte[FRAME_MAX];
    int length;
} Reply;

/* The controller (manual 3.3, 3.3.1): it executes a frame whose CHECK it accepts and answers it with
 * SOH STX QUIT;BE;STATUS;ERROR;TYP_QUIT;Q_PAR ETX CHECK EOT; an EOT poll gets its last reply again, with BE 1
 * once the command ended (3.3.1: "another acknowledgement is requested"); before any reply, a poll gets none.
 * Its reading of the CHECK is free per run (the manual's examples agree with no single rule,
 * docs/open_points.md): the XOR of the text with or without ETX, "0" taken as not checked or not, a wrong CHECK
 * answered with QUIT 16 (6.5) or ignored, and the XOR of its own replies with or without ETX. A frame it
 * accepts it may refuse with a command error (20, 6.5: not carried out); the probe, a read, it always carries
 * out. STATUS and Q_PAR are free digits of each execution (the probe's Q_PAR is STATUS, as 190B reads it): two
 * executions answer differently. Two replies at most are on their way: a third is lost on the line whole. */
typedef struct {
    BOOL checkEtx, zeroUnchecked, ignoreBad, replyEtx;
    BOOL answered, running;
    int quit, be, status, data, entry; /* the last reply; entry: the ledger entry it answers, -1 none */
    Reply line[2];                     /* the replies on their way, line[0] first */
    int pending, outPos;               /* replies on their way; bytes of line[0] already on RxBuffer */
    Entry ledger[LEDGER];
    int entries;
} Controller;

static int TextXor(const char *text, int length) {
    int x = 0;
    for (int i = 0; i < length; ++i) x ^= (unsigned char)text[i];
    return x;
}

/* The controller's last reply as a frame: QUIT has one or two digits, CHECK one to three, so the frame has one
 * of six layouts, each written at fixed places. */
static void ReplyFrame(const Controller *c, Reply *r) {
    const int q = c->quit >= 10 ? 2 : 1, text = q + 10; /* QUIT ; BE ; STATUS ; 0 ; 0 ; Q_PAR */
    const unsigned char tens = (unsigned char)('0' + c->quit / 10), ones = (unsigned char)('0' + c->quit % 10);
    const unsigned char be = (unsigned char)('0' + c->be), status = (unsigned char)('0' + c->status);
    const unsigned char data = (unsigned char)('0' + c->data);
    const int check = (c->replyEtx ? 0x03 : 0) ^ (q == 2 ? tens : 0) ^ ones ^ ';' ^ be ^ ';' ^ status ^ ';' ^ '0' ^ ';'
                      ^ '0' ^ ';' ^ data;
    const int digits = check >= 100 ? 3 : check >= 10 ? 2 : 1;
    r->byte[0] = 0x01;
    r->byte[1] = 0x02;
    if (q == 2) {
        r->byte[2] = tens;
        r->byte[3] = ones;
    } else {
        r->byte[2] = ones;
    }
    const unsigned char rest[] = {';', be, ';', status, ';', '0', ';', '0', ';', data, 0x03};
    for (int i = 0; i < 11; ++i) {
        if (q == 2) r->byte[4 + i] = rest[i];
        else r->byte[3 + i] = rest[i];
    }
    const unsigned char d100 = (unsigned char)('0' + check / 100), d10 = (unsigned char)('0' + check / 10 % 10);
    const unsigned char d1 = (unsigned char)('0' + check % 10);
    for (int k = 1; k <= 2; ++k) { /* the text ends at 2 + text - 1; ETX at 2 + text; CHECK from 3 + text */
        if (q != k) continue;
        const int at = 3 + (k + 10);
        if (digits == 3) {
            r->byte[at] = d100;
            r->byte[at + 1] = d10;
            r->byte[at + 2] = d1;
            r->byte[at + 3] = 0x04;
        } else if (digits == 2) {
            r->byte[at] = d10;
            r->byte[at + 1] = d1;
            r->byte[at + 2] = 0x04;
        } else {
            r->byte[at] = d1;
            r->byte[at + 1] = 0x04;
        }
    }
    r->length = 4 + text + digits;
}

/* The controller's reply on the line: its last reply, as a frame, after the bytes still on their way. */
static void Answer(Controller *c) {
    Reply r;
    ReplyFrame(c, &r);
    if (c->pending == 0) {
        c->line[0] = r;
        c->outPos = 0;
        c->pending = 1;
    } else if (c->pending == 1) {
        c->line[1] = r;
        c->pending = 2;
    }
    c->answered = TRUE;
}

/* What the controller does with a request the line brought it (in the scan the FB wrote it). */
static int Decide(Controller *c, int kind, BOOL zeroForm, int check, int n) {
    if (kind == REQ_POLL) {
        if (!c->answered) return TOOK_NOTHING;
        if (c->running && nondet_bool()) c->running = FALSE; /* the command ended since the last reply */
        if (c->entry >= 0) c->be = !c->running;
        return TOOK_POLL;
    }
    const int sum = kind == REQ_PROBE ? TextXor(PROBE_TEXT, sizeof PROBE_TEXT - 1)
                    : zeroForm         ? TextXor(CBMC__CMD_TEXT_ZERO, sizeof CBMC__CMD_TEXT_ZERO - 1)
                                       : TextXor(CBMC__CMD_TEXT, sizeof CBMC__CMD_TEXT - 1);
    c->status = nondet_uchar();
    __CPROVER_assume(c->status < 10);
    if (!(check == (c->checkEtx ? sum ^ 0x03 : sum) || (check == 0 && c->zeroUnchecked))) {
        if (c->ignoreBad) return TOOK_IGNORED;
        c->quit = 16, c->be = 1, c->data = 0, c->entry = -1;
        return TOOK_CHECK_16;
    }
    if (kind == REQ_COMMAND && nondet_bool()) {
        c->quit = 20, c->be = 1, c->data = 0, c->entry = -1;
        return TOOK_REFUSED;
    }
    c->quit = 0;
    c->running = kind == REQ_COMMAND && CBMC__CMD_LONG && nondet_bool();
    c->be = !c->running;
    c->data = nondet_uchar();
    __CPROVER_assume(c->data < 10);
    if (kind == REQ_PROBE) c->data = c->status;
    c->entry = c->entries;
    if (c->entries < LEDGER) {
        c->ledger[c->entries].kind = kind;
        c->ledger[c->entries].scan = n;
        c->ledger[c->entries].status = c->status;
        c->ledger[c->entries].data = c->data;
        ++c->entries;
    }
    return kind == REQ_PROBE ? TOOK_PROBE : TOOK_COMMAND;
}

/* The controller takes the request and answers it: one reply frame per call, whatever it decided. */
static int Take(Controller *c, int kind, BOOL zeroForm, int check, int n) {
    const int took = Decide(c, kind, zeroForm, check, n);
    if (took != TOOK_NOTHING && took != TOOK_IGNORED) Answer(c);
    return took;
}

/* i modulo RING for -RING <= i < 3 x RING, without a division: a % by 300 of a free value is a divider circuit
 * in the formula, in every scan and for every byte. */
static int Ring(int i) {
    return i < 0 ? i + RING : i >= 2 * RING ? i - 2 * RING : i >= RING ? i - RING : i;
}

/* Whether the bytes written at `at` are SOH STX text ETX: the frame of that text. */
static BOOL FrameOf(const T_PAC_COMBUFFER *tx, int at, int written, const char *text, int length) {
    if (written < length + 5) return FALSE;
    BOOL same = tx->BUFFER.table[Ring(at + 1)] == 0x02 && tx->BUFFER.table[Ring(at + 2 + length)] == 0x03;
    for (int i = 0; i < length; ++i) same = same && tx->BUFFER.table[Ring(at + 2 + i)] == (unsigned char)text[i];
    return same;
}

/* The timeline of a counterexample (paccbmc): assigned at the end of every scan, tl_scan last. from_pac: the
 * bytes the controller's side put into RxBuffer in this scan; to_pac: the first 8 the FB wrote into TxBuffer. */
static unsigned long long tl_from_pac, tl_to_pac;
static BOOL tl_execute, tl_rx_blocked, tl_tx_blocked;
static WORD tl_code;
static int tl_rule, tl_received, tl_tx_free, tl_written, tl_state;
static BOOL tl_called, tl_plc_restart;
static int tl_ctrl_took, tl_ledger, tl_answer; /* TOOK_*; ledger entries; the last reply: QUIT BE STATUS Q_PAR */
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
    Controller ctrl = {0};
    PlcOpenWatch watch = {0};
    Frames frames = {0};
    E_PAC_RS232CHECK rule = E_PAC_RS232CHECK__PAC_RS232_CHECK_AUTO; /* CheckRule at the last edge */
    int requests = 0, lastRequest = 0, lastByte = -1000, edgeScan = 0;
    BOOL quietSeen = FALSE; /* the line was quiet for QuietTime at some scan since the last request */
    BOOL polled = FALSE;    /* the reply the FB is waiting for answers an EOT poll */
    int reachDone = 0, reachLibError = 0, reachPacError = 0, reachRepeat = 0, reachSkippedBusy = 0;
    int reachPlcRestart = 0, reachDoneExecuted = 0, reachDoneAfterPoll = 0;

    ctrl.checkEtx = nondet_bool();
    ctrl.zeroUnchecked = nondet_bool();
    ctrl.ignoreBad = nondet_bool();
    ctrl.replyEtx = nondet_bool();
    ctrl.entry = -1;
    __CURRENT_TIME = __time_make(0, 0);
    FB_PAC_RS232CMD_init__(&fresh, FALSE);
    const int t = 1 + nondet_uchar() % CBMC__TMAX, e = 1 + nondet_uchar() % CBMC__TMAX, q = 1 + nondet_uchar() % CBMC__TMAX;
    fresh.TIMEOUT.value = __time_make(0, (long)t * CYCLE_NS);
    fresh.ENDTIMEOUT.value = __time_make(0, (long)e * CYCLE_NS);
    fresh.POLLINTERVAL.value = __time_make(0, (long)(1 + nondet_uchar() % CBMC__TMAX) * CYCLE_NS);
    fresh.QUIETTIME.value = __time_make(0, (long)q * CYCLE_NS);
    fresh.RETRIES.value = nondet_bool();
    /* Busy: per request at most Timeout for a quiet line, Timeout for room in TxBuffer and Timeout for the
     * reply, Retries + 1 requests before the acknowledgement (one more for AUTO's probe), then EndTimeout,
     * however long the FB was left out (FB_PAC_Rs232Cmd.md, "A noisy line"); set again at each edge for its
     * CheckRule. */
    watch.bound = (fresh.RETRIES.value + 2) * 3 * t + e;
    fresh.TXBUFFER.value.WRIDX = RING - 10; /* the first command frame wraps round the ring's end */
    cmd = fresh;
    T_PAC_COMBUFFER *tx = &cmd.TXBUFFER.value, *rx = &cmd.RXBUFFER.value;
    /* The program has called the FB idle on a quiet line since the PLC started, longer than any QuietTime: a
     * fresh instance lets the line fall quiet for QuietTime from its first call before its first request (D10),
     * and at K = 2 a first call with the edge would leave no scan for the reply. The instance after a PLC
     * restart below is not called before its scan. */
    FB_PAC_RS232CMD_body__(&cmd);

    /* The scans left out (CBMC__LONG_SKIPS): each step calls the FB after a gap of 0 to STRETCH_MAX scans it was
     * left out of, in which nothing of it runs and the clock goes on; step n is scan s = n + the gaps so far, the
     * clock s + TMAX ms. The bytes of a step arrive in its own scan, after the gap (the FB, left out, would read
     * them in this call all the same). Where the FB is called in some steps only (CBMC__SKIPS), its whole
     * instance is merged after each call under a free condition, the rings' arrays too: this costs several times
     * more than the gaps (docs/verification.md). */
    int stretched = 0;
    BOOL skippedReply = FALSE; /* since the last request: a gap of two scans or more while Busy */
    int reachSkippedReply = 0;
    for (int n = 1; n <= CBMC__K; ++n) {
        const int gap = CBMC__LONG_SKIPS ? (int)(nondet_uchar() & CBMC__STRETCH_MAX) : 0;
        stretched += gap;
        const int s = n + stretched;
        if (gap > 0 && s - 1 - lastByte >= q) quietSeen = TRUE; /* the line quiet until the gap's end */
        if (gap > 0 && cmd.BUSY.value) {
            reachSkippedBusy = 1;
            watch.busyScans += gap; /* P8 counts the scans, not the calls */
        }
        if (gap >= 2 && cmd.BUSY.value && requests > 0) skippedReply = TRUE;
        __CURRENT_TIME = __time_make(0, (long)(s + CBMC__TMAX) * CYCLE_NS);
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
        /* TxBuffer: the driver sent any number of the bytes, or the line is stuck: any free space. The FB keeps
         * no index of it from one call to the next and writes at WrIdx whatever it is, so the place of its
         * bytes in the ring matters to it only where they wrap round the ring's end (F_PAC_ComPut): the driver
         * here leaves WrIdx RING - 10 in every scan, where a frame wraps and a poll does not, and the harness
         * reads the request at places it knows, not at free ones. */
        const int held = nondet_ushort();
        __CPROVER_assume(held <= RING);
        tx->WRIDX = RING - 10;
        tx->COUNT = (INT)held;
        tx->FREEBYTE = (INT)(RING - held);
        tx->RDIDX = (INT)Ring(tx->WRIDX + RING - held);
        tx->BLOCKED = nondet_bool();
        /* RxBuffer: the controller's bytes on their way, any number of them in this scan; the line may drop
         * the rest (a cut-off reply) or, with NOISE, spoil one of them. */
        rx->BLOCKED = nondet_bool();
        int received = nondet_uchar();
        __CPROVER_assume(received <= CBMC__BYTES_PER_SCAN);
        const int length0 = ctrl.line[0].length;
        const int waiting =
            ctrl.pending == 0 ? 0 : length0 - ctrl.outPos + (ctrl.pending == 2 ? ctrl.line[1].length : 0);
#if CBMC__NOISE
        const int spoilt = nondet_uchar();
        const unsigned char noise = nondet_uchar();
#endif
        unsigned long long fromPac = 0;
        if (waiting == 0) { /* a known 0 where no reply is on its way: no byte to deliver in the formula */
            received = 0;
        } else {
            if (received > waiting) received = waiting;
            for (int i = 0; i < CBMC__BYTES_PER_SCAN && i < received; ++i) {
                const int at = ctrl.outPos + i;
                unsigned char byte = at < length0 ? ctrl.line[0].byte[at] : ctrl.line[1].byte[at - length0];
#if CBMC__NOISE
                if (i == spoilt) byte = noise;
#endif
                if (i < 8) fromPac |= (unsigned long long)byte << (8 * (7 - i));
                Receive(&frames, byte, rule);
                if (rx->COUNT < RING) {
                    rx->BUFFER.table[rx->WRIDX] = byte;
                    rx->WRIDX = (INT)Ring(rx->WRIDX + 1);
                    ++rx->COUNT;
                    rx->FREEBYTE = (INT)(RING - rx->COUNT);
                }
            }
            /* The replies delivered whole leave the line; the line may drop the rest. */
            ctrl.outPos += received;
            for (int k = 0; k < 2; ++k) {
                if (ctrl.pending > 0 && ctrl.outPos >= ctrl.line[0].length) {
                    ctrl.outPos -= ctrl.line[0].length;
                    ctrl.line[0] = ctrl.line[1];
                    --ctrl.pending;
                }
            }
            if (ctrl.pending > 0 && nondet_bool()) ctrl.pending = ctrl.outPos = 0;
            if (received > 0) lastByte = s;
        }
        if (s - lastByte >= q) quietSeen = TRUE;

        const BOOL called = CBMC__SKIPS && !CBMC__LONG_SKIPS ? nondet_bool() : 1;
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
        if (edge && !cmd.BUSY.value) {
            rule = cmd.CHECKRULE.value;
            edgeScan = s; /* the FB takes this edge: L1 counts the executions from this scan on */
            watch.bound = (cmd.RETRIES.value + 1 + (rule == E_PAC_RS232CHECK__PAC_RS232_CHECK_AUTO)) * 3 * t + e;
        }
        const BOOL doneBefore = cmd.DONE.value;
        const int count0 = tx->COUNT, wrIdx0 = tx->WRIDX;
        const BOOL txBlocked = tx->BLOCKED;
        if (called) FB_PAC_RS232CMD_body__(&cmd);

        const int written = tx->COUNT - count0;
        unsigned long long toPac = 0;
        for (int i = 0; i < 8 && i < written; ++i)
            toPac |= (unsigned long long)tx->BUFFER.table[Ring(wrIdx0 + i)] << (8 * (7 - i));

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
        int took = TOOK_NOTHING;
        if (written > 0) {
            __CPROVER_assert(requests == 0 || frames.checked
                                 || ((frames.damaged || frames.frame || s - lastRequest >= t) && quietSeen),
                             "R2 no request while the one before it awaits its reply");
            ++requests;
            lastRequest = s;
            skippedReply = FALSE;
            quietSeen = FALSE;
            frames = (Frames){0};
            /* R4: a frame carries the command's text or the probe's, nothing else (the controller would run it). */
            const int lengthCmd = sizeof CBMC__CMD_TEXT - 1, lengthZero = sizeof CBMC__CMD_TEXT_ZERO - 1;
            const int lengthProbe = sizeof PROBE_TEXT - 1;
            const BOOL zeroForm = FrameOf(tx, wrIdx0, written, CBMC__CMD_TEXT_ZERO, lengthZero);
            const BOOL command = FrameOf(tx, wrIdx0, written, CBMC__CMD_TEXT, lengthCmd) || zeroForm;
            const int kind = written == 1 ? REQ_POLL
                             : command    ? REQ_COMMAND
                             : FrameOf(tx, wrIdx0, written, PROBE_TEXT, lengthProbe) ? REQ_PROBE
                                                                                     : REQ_OTHER;
            __CPROVER_assert(kind != REQ_OTHER, "R4 a frame carries the command's text or the probe's");
            /* The CHECK digits between ETX and EOT (R1: the last byte is EOT). */
            const int textLength = kind == REQ_PROBE ? lengthProbe : zeroForm ? lengthZero : lengthCmd;
            int check = 0;
            for (int i = 0; i < 3; ++i)
                if (kind != REQ_POLL && 3 + textLength + i < written - 1)
                    check = check * 10 + (tx->BUFFER.table[Ring(wrIdx0 + 3 + textLength + i)] - '0');
            /* The line brings the request to the controller in this scan, or loses it. */
            polled = kind == REQ_POLL;
            took = nondet_bool() ? TOOK_LOST : Take(&ctrl, kind, zeroForm, check, s);
        }
        /* R3: Done only after a reply that checks: since the last request a frame came whose CHECK the
         * command's rule accepts; a serial link is never left unchecked. */
        __CPROVER_assert(!cmd.DONE.value || doneBefore || frames.checked,
                         "R3 Done only after an acknowledgement whose CHECK holds");
        /* L1, L2 (issue: Done means executed): at the rising Done the controller's ledger holds exactly one
         * execution of the command's text since the FB took its edge, and the FB's outputs are that
         * execution's answer (STATUS, Q_PAR; ERROR 0, TYP_QUIT 0). */
        if (cmd.DONE.value && !doneBefore) {
            int runs = 0;
            BOOL own = FALSE;
            for (int i = 0; i < LEDGER; ++i) {
                const Entry *x = &ctrl.ledger[i];
                if (i < ctrl.entries && x->kind == REQ_COMMAND && x->scan >= edgeScan) {
                    ++runs;
                    own = cmd.ACKDATA.value == (DWORD)x->data && cmd.OPSTATUS.value == (BYTE)x->status
                          && !cmd.ACKISREAL.value && !cmd.PACERROR.value;
                }
            }
            __CPROVER_assert(runs == 1,
                             "L1 Done only if the controller executed the command's text once since the edge");
            __CPROVER_assert(runs != 1 || own, "L2 Done carries the answer of the command's own execution");
            if (runs == 1 && own) reachDoneExecuted = 1;
            if (runs == 1 && own && skippedReply) reachSkippedReply = 1;
            if (polled) reachDoneAfterPoll = 1;
        }

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
        tl_ctrl_took = took;
        tl_ledger = ctrl.entries;
        tl_answer = ctrl.quit * 1000 + ctrl.be * 100 + ctrl.status * 10 + ctrl.data;
        tl_scan = n;

        if (cmd.DONE.value) reachDone = 1;
        if (cmd.ERROR.value && cmd.ERRORID.value >= 0x8000) reachLibError = 1;
        if (cmd.ERROR.value && cmd.ERRORID.value < 0x8000) reachPacError = 1;
        if (cmd.REPEATS.value > 0) reachRepeat = 1;
    }
    __CPROVER_assert(!reachDone, "reach: Done");
    __CPROVER_assert(!reachDoneExecuted, "reach: Done on the command the controller executed, with its answer");
    __CPROVER_assert(!reachLibError, "reach: Error with a library code");
    __CPROVER_assert(!reachPacError, "reach: Error with the controller's QUIT");
    __CPROVER_assert(!reachRepeat, "reach: a request sent again");
#if CBMC__K >= 4
    __CPROVER_assert(!reachDoneAfterPoll, "reach: Done on the answer to an EOT poll");
#else
    (void)reachDoneAfterPoll;
#endif
#if CBMC__SKIPS || CBMC__LONG_SKIPS
    __CPROVER_assert(!reachSkippedBusy, "reach: the FB left out of a scan while Busy");
#endif
#if CBMC__LONG_SKIPS
    __CPROVER_assert(!reachSkippedReply, "reach: Done with the command's own answer after the FB was left out of two "
                                         "scans or more while the reply came in");
#else
    (void)reachSkippedReply;
#endif
#if CBMC__PLC_RESTARTS
    __CPROVER_assert(!reachPlcRestart, "reach: a PLC restart");
#else
    (void)reachPlcRestart;
#endif
    return 0;
}
