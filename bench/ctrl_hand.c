/* FB_PAC_Ctrl's scan by hand (see ctrl_hand.h). */
#include "ctrl_hand.h"

#include <string.h>

#include "hand_c.h"

/* control word bits (2.5.1); Stop, Cancel and Error reset are low-active */
enum { BIT_ERROR_RESET = 0x1, BIT_STOP = 0x2, BIT_CANCEL = 0x4, BIT_START_AUTOMATIC = 0x8, BIT_START_ONLINE = 0x10,
       BIT_INTEGER_MODE = 0x8000 };
/* The controller reads a bit within its cycle in home position (2.3.4) after it arrived: the bit and its answer
 * each take at most 3 scans or 30 ms, whichever is longer. */
#define READ_TIME_NS 70000000LL
#define LATENCY_CALLS 7u

void CtrlHandInit(CtrlHand *c) {
    memset(c, 0, sizeof *c);
    c->timeoutNs = 10000000000LL;
}

static void Fail(CtrlHand *c, uint16_t errorId) {
    c->error = 1;
    c->errorId = errorId;
    c->state = CTRL_HAND_ERROR;
}

void CtrlHandScan(CtrlHand *c, uint8_t toPac[8], const uint8_t fromPac[8], int64_t nowNs) {
    const uint16_t status = HandGetWord(fromPac);
    const int64_t timeout = c->timeoutNs > 0 ? c->timeoutNs : 10000000000LL;
    const int edge = c->execute && !c->executeBefore;
    const int noModeShown = (status & 0x0F00) == 0;
    int reached = 0, applicable = 0, watchSystemError = 0, shownAsHome, cpuError;
    uint16_t word = BIT_ERROR_RESET | BIT_STOP | BIT_CANCEL;
    c->executeBefore = c->execute;
    c->ready = status & 0x1;
    c->batteryOk = (status & 0x2) != 0;
    c->systemError = (status & 0x4) != 0;
    c->automaticStopped = (status & 0x200) != 0;
    c->automaticActive = (status & 0x100) && !c->automaticStopped;
    c->onlineStopped = (status & 0x800) != 0;
    c->onlineActive = (status & 0x400) && !c->onlineStopped;
    c->integerModeActive = (status & 0x8000) != 0;
    c->systemErrorNumber = HandGetWord(fromPac + 4);
    cpuError = c->systemErrorNumber >= 1 && c->systemErrorNumber <= 99; /* class 1: only a power cycle clears it */

    if ((c->state == CTRL_HAND_DONE || c->state == CTRL_HAND_ERROR) && (!c->execute || edge)) {
        c->state = CTRL_HAND_IDLE;
        c->done = c->error = 0;
        c->errorId = 0;
    }
    if (c->state == CTRL_HAND_IDLE && edge) {
        c->latched = c->request;
        c->systemErrorAtEdge = c->systemError;
    }
    switch (c->latched) {
        case CTRL_HAND_START_ONLINE:
            reached = c->onlineActive && !c->systemError;
            applicable = !c->systemError && (noModeShown || c->onlineStopped);
            watchSystemError = 1;
            break;
        case CTRL_HAND_START_AUTOMATIC:
            reached = c->automaticActive && !c->systemError;
            applicable = !c->systemError && (noModeShown || c->automaticStopped);
            watchSystemError = 1;
            break;
        case CTRL_HAND_STOP:
            reached = c->onlineStopped || c->automaticStopped;
            applicable = c->onlineActive || c->automaticActive;
            watchSystemError = 1;
            break;
        case CTRL_HAND_CANCEL:
            reached = noModeShown;
            applicable = 1;
            break;
        case CTRL_HAND_RESET_ERROR:
            reached = noModeShown && !c->systemError;
            applicable = noModeShown;
            break;
        default:
            break;
    }
    shownAsHome = c->latched == CTRL_HAND_CANCEL || c->latched == CTRL_HAND_RESET_ERROR;

    if (c->state == CTRL_HAND_IDLE && edge) {
        if (c->latched == CTRL_HAND_NONE) {
            Fail(c, ERR_NO_COMMAND);
        } else if (c->latched == CTRL_HAND_RESET_ERROR && cpuError) {
            Fail(c, ERR_NOT_ALLOWED);
        } else if (!c->ready && (status == 0 || c->latched == CTRL_HAND_START_ONLINE ||
                                 c->latched == CTRL_HAND_START_AUTOMATIC)) {
            Fail(c, ERR_NOT_READY);
        } else if (reached && !shownAsHome) {
            c->done = 1;
            c->state = CTRL_HAND_DONE;
        } else if (!applicable) {
            Fail(c, ERR_NOT_ALLOWED);
        } else {
            c->waitSince = nowNs;
            c->readCalls = 0;
            c->state = CTRL_HAND_WAIT;
        }
    }
    if (c->state == CTRL_HAND_WAIT) {
        if (nowNs - c->waitSince >= READ_TIME_NS && c->readCalls <= LATENCY_CALLS) c->readCalls++;
        if (status == 0) {
            Fail(c, ERR_CONNECTION_LOST);
        } else if (watchSystemError && c->systemError && !c->systemErrorAtEdge) {
            Fail(c, c->systemErrorNumber != 0 ? c->systemErrorNumber : ERR_NOT_ALLOWED);
        } else if (c->latched == CTRL_HAND_STOP && noModeShown) {
            Fail(c, ERR_NOT_ALLOWED);
        } else if (reached && (c->readCalls > LATENCY_CALLS || !shownAsHome)) {
            c->done = 1;
            c->state = CTRL_HAND_DONE;
        } else if (nowNs - c->waitSince >= timeout) {
            Fail(c, ERR_REQUEST_TIMEOUT);
        }
    }
    c->busy = c->state == CTRL_HAND_WAIT;
    c->modeChange = c->busy && c->latched == CTRL_HAND_START_AUTOMATIC;
    if (c->busy) {
        switch (c->latched) {
            case CTRL_HAND_START_ONLINE: word |= BIT_START_ONLINE; break;
            case CTRL_HAND_START_AUTOMATIC: word |= BIT_START_AUTOMATIC; break;
            case CTRL_HAND_STOP: word &= (uint16_t)~BIT_STOP; break;
            case CTRL_HAND_CANCEL: word &= (uint16_t)~BIT_CANCEL; break;
            case CTRL_HAND_RESET_ERROR: word &= (uint16_t)~BIT_ERROR_RESET; break;
            default: break;
        }
    }
    if (c->integerMode) word |= BIT_INTEGER_MODE;
    HandPutWord(toPac, word);
    memset(toPac + 2, 0, 6);
    c->errorSource = !c->error ? SOURCE_NONE : c->errorId >= 0x8000 ? SOURCE_LIBRARY : SOURCE_SYSTEM;
}
