/* Benchmark only, not part of the library: what FB_PAC_CmdInterface and one FB_PAC_Cmd do for a program
 * with a single command caller (st/cmd/FB_PAC_CmdInterface.st, st/cmd/FB_PAC_Cmd.st; manual 2.4), written
 * by hand in plain C without IEC wrappers, so that the benchmark can set what the translated FBs cost per
 * scan next to it. Same pins, the same waits and timeouts, the same module written scan by scan (parked
 * with 190B between commands, brought back in step with RECEIVE), the same handshake history. What it
 * leaves out is what only a shared interface needs: ids, tickets, the queue and the owner's keep-alive.
 * bench_table checks scan by scan that both write the same module and give the same outputs. */
#ifndef PAC_BENCH_CMD_HANDSHAKE_H
#define PAC_BENCH_CMD_HANDSHAKE_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { CMD_HS_IDLE, CMD_HS_WAIT_FREE, CMD_HS_WAIT_ACK, CMD_HS_WAIT_END, CMD_HS_DONE, CMD_HS_ERROR } CmdHsState;

/* One finished handshake, as ST_PAC_Handshake. */
typedef struct {
    uint16_t code, param;
    uint32_t data, ackData;
    uint16_t errorId;
    int32_t scansToAck, scansToEnd;
} CmdHsEntry;

typedef struct {
    /* inputs */
    int execute;
    uint16_t code;
    uint16_t param;
    uint32_t data;
    int64_t timeoutNs;    /* <= 0: 1 s */
    int64_t endTimeoutNs; /* <= 0: 60 s */
    /* outputs */
    int done, busy, error, acknowledged, pacError;
    uint16_t errorId;
    int errorSource; /* E_PAC_ErrorSource: 0 none, 1 command, 3 library */
    uint32_t ackData;
    uint8_t opStatus;
    /* state */
    CmdHsState state;
    int executeBefore;
    int sendFlag;
    int sent;
    uint16_t sentCode, sentParam, lastSentCode;
    uint32_t sentData;
    uint32_t scan, edgeScan;
    int32_t scansToAck;
    int64_t waitSince; /* start of the current wait: interface, acknowledgement or END OF PROCESSING */
    CmdHsEntry history[16];
    int historyNext;
    uint32_t historyCount;
} CmdHandshake;

void CmdHandshakeInit(CmdHandshake *hs);
/* One scan at PLC time `nowNs` on the module images: reads fromPac, may rewrite toPac. */
void CmdHandshakeScan(CmdHandshake *hs, uint8_t toPac[8], const uint8_t fromPac[8], int64_t nowNs);

#ifdef __cplusplus
}
#endif

#endif
