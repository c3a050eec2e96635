/* The CMD handshake by hand (see cmd_handshake.h). The library's error codes, 16#8001..16#8007. */
#include "cmd_handshake.h"

#include <string.h>

enum {
    ERR_ACK_TIMEOUT = 0x8001,
    ERR_END_TIMEOUT = 0x8002,
    ERR_NOT_READY = 0x8003,
    ERR_CONNECTION_LOST = 0x8004,
    ERR_INVALID_CODE = 0x8005,
    ERR_INTERFACE_BUSY = 0x8006,
    ERR_SUPERSEDED = 0x8007
};

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

static void ParkOrKeepAlive(uint8_t toPac[8], int receive, uint8_t opStatus) {
    static const uint8_t zero[8];
    if (opStatus == 0 && ((toPac[6] & 0x80) != 0) != receive) {
        memset(toPac, 0, 6);
        toPac[6] = receive ? 0x99 : 0x19;
        toPac[7] = 0x0B;
    }
    if (memcmp(toPac, zero, 8) == 0) {
        toPac[6] = 0x19;
        toPac[7] = 0x0B;
    }
}

static void Send(CmdHandshake *hs, uint8_t toPac[8], int receive) {
    hs->sendFlag = !receive;
    toPac[0] = (uint8_t)(hs->sentData >> 24);
    toPac[1] = (uint8_t)(hs->sentData >> 16);
    toPac[2] = (uint8_t)(hs->sentData >> 8);
    toPac[3] = (uint8_t)hs->sentData;
    toPac[4] = (uint8_t)(hs->sentParam >> 8);
    toPac[5] = (uint8_t)hs->sentParam;
    toPac[6] = (uint8_t)((hs->sentCode >> 8) | (hs->sendFlag ? 0x80 : 0));
    toPac[7] = (uint8_t)hs->sentCode;
    hs->state = CMD_HS_WAIT_ACK;
}

/* TON's timing: Q only from the scan after the one that started the wait. */
static int Elapsed(int64_t since, int64_t nowNs, int64_t limitNs) { return nowNs > since && nowNs - since >= limitNs; }

void CmdHandshakeScan(CmdHandshake *hs, uint8_t toPac[8], const uint8_t fromPac[8], int64_t nowNs) {
    const uint16_t reply = (uint16_t)((fromPac[6] << 8) | fromPac[7]);
    const int receive = (reply & 0x8000) != 0;
    const int cmdError = (reply & 0x4000) != 0;
    const int end = (reply & 0x2000) != 0;
    const uint32_t replyData = ((uint32_t)fromPac[0] << 24) | ((uint32_t)fromPac[1] << 16) |
                               ((uint32_t)fromPac[2] << 8) | fromPac[3];
    const int edge = hs->execute && !hs->executeBefore;
    hs->executeBefore = hs->execute;
    hs->opStatus = fromPac[5];
    hs->pacError = (fromPac[4] & 0x80) != 0;

    if ((hs->state == CMD_HS_DONE || hs->state == CMD_HS_ERROR) && !hs->execute) {
        hs->state = CMD_HS_IDLE;
        hs->done = hs->error = hs->acknowledged = 0;
        hs->errorId = 0;
    }
    if (hs->state == CMD_HS_IDLE) {
        ParkOrKeepAlive(toPac, receive, hs->opStatus);
        if (edge) {
            hs->acknowledged = 0;
            hs->ackData = 0;
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
    }
    switch (hs->state) {
        case CMD_HS_WAIT_FREE:
            if (hs->opStatus == 0) {
                Fail(hs, ERR_CONNECTION_LOST);
            } else if (((toPac[6] & 0x80) != 0) == receive) {
                Send(hs, toPac, receive);
            } else if (Elapsed(hs->waitSince, nowNs, hs->timeoutNs)) {
                Fail(hs, ERR_INTERFACE_BUSY);
            }
            break;
        case CMD_HS_WAIT_ACK:
            if (hs->opStatus == 0) {
                Fail(hs, ERR_CONNECTION_LOST);
            } else if (receive == hs->sendFlag) {
                hs->acknowledged = 1;
                hs->ackData = replyData;
                if (cmdError) {
                    Fail(hs, reply & 0x1FFF);
                } else if (end) {
                    hs->done = 1;
                    hs->state = CMD_HS_DONE;
                } else {
                    hs->endSince = nowNs;
                    hs->state = CMD_HS_WAIT_END;
                }
            } else if (Elapsed(hs->waitSince, nowNs, hs->timeoutNs)) {
                Fail(hs, ERR_ACK_TIMEOUT);
            }
            break;
        case CMD_HS_WAIT_END:
            if (hs->opStatus == 0) {
                Fail(hs, ERR_CONNECTION_LOST);
            } else if (receive != hs->sendFlag) {
                Fail(hs, ERR_SUPERSEDED);
            } else {
                hs->ackData = replyData;
                if (cmdError) {
                    Fail(hs, reply & 0x1FFF);
                } else if (end) {
                    hs->done = 1;
                    hs->state = CMD_HS_DONE;
                } else if (hs->endTimeoutNs > 0 && Elapsed(hs->endSince, nowNs, hs->endTimeoutNs)) {
                    Fail(hs, ERR_END_TIMEOUT);
                }
            }
            break;
        default:
            break;
    }
    hs->busy = hs->state == CMD_HS_WAIT_FREE || hs->state == CMD_HS_WAIT_ACK || hs->state == CMD_HS_WAIT_END;
}
