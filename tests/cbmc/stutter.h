/* The waiting scans of the CMD harness (-DCBMC__STUTTER=1, docs/verification.md, "the waiting scans"). A scan is
 * waiting when the reply, the calls, their order and the pins are those of the scan before and it passes no limit
 * (NoLimitPasses: no TON's Q changes, no scan count crosses its threshold); still when, besides, it changes
 * nothing of FB_PAC_CmdInterface, its channel and the command FBs but the counters of time and scans (TON's ET
 * and CURRENT_TIME, Channel.Scan, an FB's LastScan and the channel's OwnerScan, which follow Channel.Scan in a
 * scan the FB is called). S1: a waiting scan after a still one is still; each field one assertion, so that CBMC
 * names the field that breaks it. On S1 rests Stretch, which puts up to CBMC__STRETCH_MAX still scans in a step. */
#ifndef PAC_CBMC_STUTTER_H
#define PAC_CBMC_STUTTER_H

static BOOL SameTime(TIME a, TIME b) { return a.tv_sec == b.tv_sec && a.tv_nsec == b.tv_nsec; }

/* A TON's state but its clock (Q unchanged is the waiting scan's condition, NoTimerPasses). */
/* Each comparison either asserted (check) or folded into the result: one list of fields for both. */
#define STUTTER_CMP(cond, what)                                                                                    \
    do {                                                                                                           \
        if (check) __CPROVER_assert(cond, "S1 a waiting scan after a still one changes nothing but counters: " what); \
        same = same && (cond);                                                                                     \
    } while (0)
#define STUTTER_TON(a, b, what)                                                                                    \
    STUTTER_CMP((a).IN.value == (b).IN.value && SameTime((a).PT.value, (b).PT.value)                              \
                    && (a).STATE.value == (b).STATE.value && (a).PREV_IN.value == (b).PREV_IN.value                \
                    && SameTime((a).START_TIME.value, (b).START_TIME.value),                                       \
                what)
#define STUTTER_SAME(a, b, field) STUTTER_CMP((a).field == (b).field, #field)
#define STUTTER_SAMET(a, b, field) STUTTER_CMP(SameTime((a).field, (b).field), #field)

static BOOL TonQSame(const TON *a, const TON *b) { return a->Q.value == b->Q.value; }

/* No timer of the interface or of a command FB passes its limit in the scan: the waiting scan's condition. */
static BOOL NoTimerPasses(const FB_PAC_CMDINTERFACE *i0, const FB_PAC_CMDINTERFACE *i1, const FB_PAC_CMD *c0,
                          const FB_PAC_CMD *c1, int callers) {
    BOOL same = TonQSame(&i0->INFLIGHTCOMMAND.WATCHTIMER, &i1->INFLIGHTCOMMAND.WATCHTIMER)
                && TonQSame(&i0->KEEPINSTEP.STEPTIMER, &i1->KEEPINSTEP.STEPTIMER);
    for (int k = 0; k < callers; ++k)
        same = same && TonQSame(&c0[k].WAITTIMER, &c1[k].WAITTIMER) && TonQSame(&c0[k].ACKTIMER, &c1[k].ACKTIMER)
               && TonQSame(&c0[k].ENDTIMER, &c1[k].ENDTIMER);
    return same;
}

static BOOL StutterChannel(const ST_PAC_CMDCHANNEL *a, const ST_PAC_CMDCHANNEL *b, BOOL check) {
    BOOL same = TRUE;
    for (int i = 0; i < 8; ++i) STUTTER_CMP(a->TOPAC.table[i] == b->TOPAC.table[i], "Channel.ToPac");
    STUTTER_SAME(*a, *b, TWOSTEPWRITE);
    STUTTER_SAME(*a, *b, REPLYFREE);
    STUTTER_SAME(*a, *b, NEXTTICKET);
    STUTTER_SAME(*a, *b, SERVING);
    STUTTER_SAME(*a, *b, CANCELLED);
    STUTTER_SAME(*a, *b, NEXTID);
    STUTTER_SAME(*a, *b, INFLIGHT);
    STUTTER_SAME(*a, *b, INFLIGHTID);
    STUTTER_SAME(*a, *b, INFLIGHTCODE);
    STUTTER_SAME(*a, *b, INFLIGHTPARAM);
    STUTTER_SAME(*a, *b, INFLIGHTDATA);
    STUTTER_SAME(*a, *b, INFLIGHTNUMBER);
    STUTTER_SAMET(*a, *b, INFLIGHTTIMEOUT);
    STUTTER_SAMET(*a, *b, INFLIGHTENDTIMEOUT);
    STUTTER_SAME(*a, *b, INFLIGHTEDGESCAN);
    STUTTER_SAME(*a, *b, TOGGLEPENDING);
    STUTTER_SAME(*a, *b, INFLIGHTSEND);
    STUTTER_SAME(*a, *b, INFLIGHTSENDSCAN);
    STUTTER_SAME(*a, *b, INFLIGHTACKED);
    STUTTER_SAME(*a, *b, INFLIGHTACKDATA);
    STUTTER_SAME(*a, *b, INFLIGHTSCANSTOACK);
    STUTTER_SAME(*a, *b, HANDSHAKES);
    STUTTER_SAME(*a, *b, WITHDRAWN);
    STUTTER_SAME(*a, *b, WITHDRAWNERROR);
    STUTTER_SAME(*a, *b, RESYNCS);
    STUTTER_SAME(*a, *b, RESYNCSCAN);
    STUTTER_SAME(*a, *b, ROUNDTRIP);
    STUTTER_SAME(*a, *b, SETTLING);
    STUTTER_SAME(*a, *b, FIRSTREADSENT);
    STUTTER_SAME(*a, *b, FIRSTREADDONE);
    STUTTER_SAME(*a, *b, HISTORYNEXT);
    STUTTER_SAME(*a, *b, HISTORYCOUNT); /* F_PAC_RecordHandshake counts every entry it writes */
    /* OwnerScan follows Scan where the owner is called in the scan, else stays. */
    STUTTER_CMP(b->OWNERSCAN == a->OWNERSCAN || b->OWNERSCAN == b->SCAN, "OWNERSCAN (unchanged or this scan)");
    return same;
}

static BOOL StutterInterface(const FB_PAC_CMDINTERFACE *a, const FB_PAC_CMDINTERFACE *b, BOOL check) {
    BOOL same = TRUE;
    STUTTER_SAME(*a, *b, OPSTATUS.value);
    STUTTER_SAME(*a, *b, PACERROR.value);
    STUTTER_SAME(*a, *b, INFLIGHT.value);
    STUTTER_SAME(*a, *b, WAITING.value);
    STUTTER_SAME(*a, *b, RESYNCS.value);
    STUTTER_SAME(*a, *b, LASTSERVING.value);
    STUTTER_SAME(*a, *b, LASTOPSTATUS.value);
    STUTTER_SAME(*a, *b, INFLIGHTCOMMAND.OWNERAWAY.value);
    STUTTER_SAME(*a, *b, INFLIGHTCOMMAND.ENDS.value);
    STUTTER_SAME(*a, *b, INFLIGHTCOMMAND.OUTCOME.value);
    STUTTER_SAME(*a, *b, INFLIGHTCOMMAND.ENDSHOWN.value);
    STUTTER_SAME(*a, *b, INFLIGHTCOMMAND.RECORDED.value);
    STUTTER_SAME(*a, *b, INFLIGHTCOMMAND.WATCHNUMBER.value);
    STUTTER_SAME(*a, *b, INFLIGHTCOMMAND.WATCHACKED.value);
    STUTTER_SAME(*a, *b, INFLIGHTCOMMAND.WATCHING.value);
    STUTTER_TON(a->INFLIGHTCOMMAND.WATCHTIMER, b->INFLIGHTCOMMAND.WATCHTIMER, "InFlightCommand.WatchTimer");
    STUTTER_SAME(*a, *b, KEEPINSTEP.PARKED.value);
    STUTTER_SAME(*a, *b, KEEPINSTEP.READACKED.value);
    STUTTER_SAME(*a, *b, KEEPINSTEP.RETRYING.value);
    STUTTER_SAMET(*a, *b, KEEPINSTEP.STEPTIME.value);
    STUTTER_SAME(*a, *b, KEEPINSTEP.STEPSCAN.value);
    /* FirstToggleScan follows Scan while the status is 0 (a restarted controller answers no toggle from before) */
    STUTTER_CMP(b->KEEPINSTEP.FIRSTTOGGLESCAN.value == a->KEEPINSTEP.FIRSTTOGGLESCAN.value
                    || b->KEEPINSTEP.FIRSTTOGGLESCAN.value == b->CHANNEL.value.SCAN,
                "KeepInStep.FIRSTTOGGLESCAN (unchanged or this scan)");
    STUTTER_TON(a->KEEPINSTEP.STEPTIMER, b->KEEPINSTEP.STEPTIMER, "KeepInStep.StepTimer");
    return StutterChannel(&a->CHANNEL.value, &b->CHANNEL.value, check) && same;
}

static BOOL StutterCmd(const FB_PAC_CMD *a, const FB_PAC_CMD *b, UDINT scan, BOOL check) {
    BOOL same = TRUE;
    STUTTER_SAME(*a, *b, DONE.value);
    STUTTER_SAME(*a, *b, BUSY.value);
    STUTTER_SAME(*a, *b, ERROR.value);
    STUTTER_SAME(*a, *b, ERRORID.value);
    STUTTER_SAME(*a, *b, ERRORSOURCE.value);
    STUTTER_SAME(*a, *b, ACKDATA.value);
    STUTTER_SAME(*a, *b, ACKNOWLEDGED.value);
    STUTTER_SAME(*a, *b, OPSTATUS.value);
    STUTTER_SAME(*a, *b, PACERROR.value);
    STUTTER_SAME(*a, *b, LASTEXECUTE.value);
    STUTTER_SAME(*a, *b, EXECUTEEDGE.value);
    STUTTER_TON(a->WAITTIMER, b->WAITTIMER, "WaitTimer");
    STUTTER_TON(a->ACKTIMER, b->ACKTIMER, "AckTimer");
    STUTTER_TON(a->ENDTIMER, b->ENDTIMER, "EndTimer");
    STUTTER_SAME(*a, *b, STATE.value);
    STUTTER_SAMET(*a, *b, TIMEOUTINFORCE.value);
    STUTTER_SAMET(*a, *b, ENDTIMEOUTINFORCE.value);
    STUTTER_SAME(*a, *b, ID.value);
    STUTTER_SAME(*a, *b, TICKET.value);
    STUTTER_SAME(*a, *b, QUEUED.value);
    STUTTER_SAME(*a, *b, ISSTOP.value);
    STUTTER_SAME(*a, *b, CANSEND.value);
    STUTTER_SAME(*a, *b, MINE.value);
    STUTTER_SAME(*a, *b, SENT.value);
    STUTTER_SAME(*a, *b, TOGGLED.value);
    STUTTER_SAME(*a, *b, FINISHED.value);
    STUTTER_SAME(*a, *b, RECORDED.value);
    STUTTER_SAME(*a, *b, NUMBER.value);
    STUTTER_SAME(*a, *b, SENDFLAG.value);
    STUTTER_SAME(*a, *b, SENTCODE.value);
    STUTTER_SAME(*a, *b, SENTPARAM.value);
    STUTTER_SAME(*a, *b, SENTDATA.value);
    STUTTER_SAME(*a, *b, EDGESCAN.value);
    /* LastScan follows Channel.Scan in a scan the FB is called, else stays. */
    STUTTER_CMP(b->LASTSCAN.value == a->LASTSCAN.value || b->LASTSCAN.value == scan,
                "LASTSCAN (unchanged or this scan)");
    return same;
}

/* The limits a stretch of waiting scans must not pass (the waiting scan's condition, scan by scan): a running
 * TON's Q, the owner counted away (FB_PAC_CmdInFlight: two scans without its call), the settling round trip
 * after a resynchronisation (FB_PAC_CmdInterface, FB_PAC_CmdResync), the scans an unclaimed ticket waits. */
static long long Ns(TIME t) { return (long long)t.tv_sec * 1000000000LL + t.tv_nsec; }
/* A TON timing (STATE 1) that the still scan ran (its CURRENT_TIME that scan's, stillNs) runs in each scan of
 * the stretch too, so it must still be below PT at the stretch's last scan (lastNs); one the still scan did
 * not run is not run in the stretch either (the same inputs, the same state). */
static BOOL TonBelowLimit(const TON *t, long long stillNs, long long lastNs) {
    return t->STATE.value != 1 || Ns(t->CURRENT_TIME.value) != stillNs
           || lastNs - Ns(t->START_TIME.value) < Ns(t->PT.value);
}
static BOOL OwnerAway(const ST_PAC_CMDCHANNEL *c) { return c->SCAN - c->OWNERSCAN >= 2; }
static BOOL Settling(const ST_PAC_CMDCHANNEL *c) { return c->SCAN - c->RESYNCSCAN <= c->ROUNDTRIP; }
static BOOL NoLimitPasses(const FB_PAC_CMDINTERFACE *i0, const FB_PAC_CMDINTERFACE *i1, const FB_PAC_CMD *c0,
                          const FB_PAC_CMD *c1, int callers) {
    return NoTimerPasses(i0, i1, c0, c1, callers) && i0->UNCLAIMEDSCANS.value == i1->UNCLAIMEDSCANS.value
           && OwnerAway(&i0->CHANNEL.value) == OwnerAway(&i1->CHANNEL.value)
           && Settling(&i0->CHANNEL.value) == Settling(&i1->CHANNEL.value);
}

/* A stretch: d more scans like the still scan just run (same inputs), in one step before the next waiting scan
 * (docs/verification.md, "the waiting scans"): the clock and Channel.Scan advance by d, a caller called in the
 * still scan keeps LastScan = Scan (the harness counts d more Busy calls for P8), the owner called in it keeps
 * OwnerScan = Scan (one not called stays away), a FirstToggleScan set in it (status 0) keeps = Scan; and no
 * limit passes within the stretch: each TON the still scan ran below its PT at the stretch's last scan,
 * OwnerAway and Settling as before. stillNs: the still scan's clock. By S1 each of those d scans changes nothing
 * else. */
static void Stretch(FB_PAC_CMDINTERFACE *iface, FB_PAC_CMD *cmd, const BOOL *called, int callers, unsigned d,
                    long long stillNs) {
    const long long lastNs = stillNs + (long long)d * CYCLE_NS;
    ST_PAC_CMDCHANNEL *c = &iface->CHANNEL.value;
    const BOOL away = OwnerAway(c), settling = Settling(c);
    if (c->OWNERSCAN == c->SCAN) c->OWNERSCAN += d;
    if (iface->KEEPINSTEP.FIRSTTOGGLESCAN.value == c->SCAN) iface->KEEPINSTEP.FIRSTTOGGLESCAN.value += d;
    c->SCAN += d;
    __CPROVER_assume(OwnerAway(c) == away && Settling(c) == settling);
    __CPROVER_assume(TonBelowLimit(&iface->INFLIGHTCOMMAND.WATCHTIMER, stillNs, lastNs)
                     && TonBelowLimit(&iface->KEEPINSTEP.STEPTIMER, stillNs, lastNs));
    for (int k = 0; k < callers; ++k) {
        if (!called[k]) continue; /* its timers run on, read again in its next call: a real event, not passed here */
        cmd[k].LASTSCAN.value += d;
        __CPROVER_assume(TonBelowLimit(&cmd[k].WAITTIMER, stillNs, lastNs)
                         && TonBelowLimit(&cmd[k].ACKTIMER, stillNs, lastNs)
                         && TonBelowLimit(&cmd[k].ENDTIMER, stillNs, lastNs));
    }
}

#endif
