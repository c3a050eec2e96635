/* The CMD handshake of one caller by hand (see cmd_handshake.h). */
#include "cmd_handshake.h"

#include <string.h>

#include "hand_c.h"

enum { GET_STAT = 0x190B };

void CmdHandshakeInit(CmdHandshake *hs) {
    memset(hs, 0, sizeof *hs);
    hs->timeoutNs = 1000000000LL;
    hs->endTimeoutNs = 60000000000LL;
}

static void Fail(CmdHandshake *hs, uint16_t errorId) {
    hs->error = 1;
    hs->errorId = errorId;
    hs->state = CMD_HS_ERROR;
}

static void Write(uint8_t toPac[8], uint32_t data, uint16_t param, uint16_t codeAndFlag) {
    HandPutDword(toPac, data);
    HandPutWord(toPac + 4, param);
    HandPutWord(toPac + 6, codeAndFlag);
}

static void Park(uint8_t toPac[8], int sendFlag) { Write(toPac, 0, 0, (uint16_t)(GET_STAT | (sendFlag ? 0x8000 : 0))); }

static int IsLong(uint16_t code) {
    return code == 0x0602 || code == 0x0603 || code == 0x0A41 || code == 0x0A81 || code == 0x0A84 ||
           code == 0x0A87 || code == 0x0A89 || code == 0x0A93;
}

/* TON's timing: Q once the wait has lasted its limit. */
static int Elapsed(int64_t since, int64_t nowNs, int64_t limitNs) { return nowNs - since >= limitNs; }

static void Record(CmdHandshake *hs) {
    CmdHsEntry *e = &hs->history[hs->historyNext];
    e->code = hs->sentCode;
    e->param = hs->sentParam;
    e->data = hs->sentData;
    e->ackData = hs->ackData;
    e->errorId = hs->errorId;
    e->scansToAck = hs->scansToAck;
    e->scansToEnd = (int32_t)(hs->scan - hs->edgeScan);
    hs->historyNext = (hs->historyNext + 1) % 16;
    hs->historyCount++;
}

/* The acknowledgement or the reply of a running command: Done, a command error or still processing. */
static void FollowReply(CmdHandshake *hs, uint16_t reply, uint32_t replyData) {
    hs->ackData = replyData;
    if (reply & 0x4000) {
        Fail(hs, reply & 0x1FFF);
    } else if (reply & 0x2000) {
        hs->done = 1;
        hs->state = CMD_HS_DONE;
    }
}

void CmdHandshakeScan(CmdHandshake *hs, uint8_t toPac[8], const uint8_t fromPac[8], int64_t nowNs) {
    const uint16_t reply = HandGetWord(fromPac + 6);
    const int receive = (reply & 0x8000) != 0;
    const uint32_t replyData = HandGetDword(fromPac);
    const int64_t timeout = hs->timeoutNs > 0 ? hs->timeoutNs : 1000000000LL;
    const int64_t endTimeout = hs->endTimeoutNs > 0 ? hs->endTimeoutNs : 60000000000LL;
    const int edge = hs->execute && !hs->executeBefore;
    const int wasBusy = hs->busy;
    int moduleSend = (toPac[6] & 0x80) != 0;
    int replyFree;
    hs->executeBefore = hs->execute;
    hs->scan++;
    hs->opStatus = fromPac[5];
    hs->pacError = (fromPac[4] & 0x80) != 0;
    replyFree = moduleSend == receive && hs->opStatus != 0 &&
                ((reply & 0x6000) != 0 || !(IsLong(hs->lastSentCode) || IsLong((uint16_t)(((toPac[6] << 8) | toPac[7]) & 0x7FFF))));

    /* Between commands (none sent and unfinished) the module is parked and follows RECEIVE. */
    if (!(hs->busy && hs->sent)) {
        static const uint8_t parked[6];
        if (toPac[6] != (moduleSend ? 0x99 : 0x19) || toPac[7] != 0x0B || memcmp(toPac, parked, 6) != 0) {
            Park(toPac, moduleSend);
        } else if (moduleSend != receive) {
            Park(toPac, receive);
        }
    }

    if ((hs->state == CMD_HS_DONE || hs->state == CMD_HS_ERROR) && !hs->execute) {
        hs->state = CMD_HS_IDLE;
        hs->done = hs->error = hs->acknowledged = 0;
        hs->errorId = 0;
    }
    if (hs->state == CMD_HS_IDLE && edge) {
        hs->acknowledged = 0;
        hs->ackData = 0;
        hs->sent = 0;
        hs->scansToAck = -1;
        hs->edgeScan = hs->scan;
        if (hs->code & 0x8000) {
            Fail(hs, ERR_INVALID_CODE);
        } else if (hs->opStatus == 0) {
            Fail(hs, ERR_NOT_READY);
        } else {
            hs->sentCode = hs->code;
            hs->sentParam = hs->param;
            hs->sentData = hs->data;
            hs->waitSince = nowNs;
            hs->state = CMD_HS_WAIT_FREE;
        }
    }
    switch (hs->state) {
        case CMD_HS_WAIT_FREE:
            if (hs->opStatus == 0) {
                Fail(hs, ERR_NOT_READY);
            } else if (replyFree) {
                hs->sendFlag = !receive;
                hs->lastSentCode = hs->sentCode;
                Write(toPac, hs->sentData, hs->sentParam, (uint16_t)(hs->sentCode | (hs->sendFlag ? 0x8000 : 0)));
                hs->sent = 1;
                hs->waitSince = nowNs;
                hs->state = CMD_HS_WAIT_ACK;
            } else if (Elapsed(hs->waitSince, nowNs, timeout)) {
                Fail(hs, ERR_INTERFACE_BUSY);
            }
            break;
        case CMD_HS_WAIT_ACK:
            if (hs->opStatus == 0) {
                Fail(hs, ERR_CONNECTION_LOST);
            } else if (receive == hs->sendFlag) {
                hs->acknowledged = 1;
                hs->scansToAck = (int32_t)(hs->scan - hs->edgeScan);
                FollowReply(hs, reply, replyData);
                if (hs->state == CMD_HS_WAIT_ACK) {
                    hs->waitSince = nowNs;
                    hs->state = CMD_HS_WAIT_END;
                }
            } else if (Elapsed(hs->waitSince, nowNs, timeout)) {
                Fail(hs, ERR_ACK_TIMEOUT);
            }
            break;
        case CMD_HS_WAIT_END:
            if (hs->opStatus == 0) {
                Fail(hs, ERR_CONNECTION_LOST);
            } else if (receive != hs->sendFlag) {
                Fail(hs, ERR_SUPERSEDED);
            } else {
                FollowReply(hs, reply, replyData);
                if (hs->state == CMD_HS_WAIT_END && Elapsed(hs->waitSince, nowNs, endTimeout)) {
                    Fail(hs, ERR_END_TIMEOUT);
                }
            }
            break;
        default:
            break;
    }
    if (hs->state == CMD_HS_ERROR && hs->errorId == 0) hs->errorId = ERR_NO_ERROR_NUMBER;
    if ((hs->state == CMD_HS_DONE || hs->state == CMD_HS_ERROR) && wasBusy) {
        moduleSend = (toPac[6] & 0x80) != 0;
        if (hs->sent && moduleSend == receive) Park(toPac, receive);
        if (hs->sent) Record(hs);
    }
    hs->busy = hs->state == CMD_HS_WAIT_FREE || hs->state == CMD_HS_WAIT_ACK || hs->state == CMD_HS_WAIT_END;
    hs->errorSource = !hs->error ? SOURCE_NONE : hs->errorId >= 0x8000 ? SOURCE_LIBRARY : SOURCE_COMMAND;
}
