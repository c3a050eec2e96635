/* Benchmark only, not part of the library: the CMD handshake of FB_PAC_Cmd (st/fb/FB_PAC_Cmd.st, manual
 * 2.4 and 4.2) written by hand in plain C, as a programmer would write it without IEC wrappers, so that
 * the benchmark can set what the translated FB costs per scan next to it. Same pins, same states, same
 * timeouts and the same writes to the module, scan by scan. */
#ifndef PAC_BENCH_CMD_HANDSHAKE_H
#define PAC_BENCH_CMD_HANDSHAKE_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { CMD_HS_IDLE, CMD_HS_WAIT_FREE, CMD_HS_WAIT_ACK, CMD_HS_WAIT_END, CMD_HS_DONE, CMD_HS_ERROR } CmdHsState;

typedef struct {
    /* inputs */
    int execute;
    uint16_t code;
    uint16_t param;
    uint32_t data;
    int64_t timeoutNs;
    int64_t endTimeoutNs;
    /* outputs */
    int done, busy, error, acknowledged, pacError;
    uint16_t errorId;
    uint32_t ackData;
    uint8_t opStatus;
    /* state */
    CmdHsState state;
    int executeBefore;
    int sendFlag;
    uint16_t sentCode, sentParam;
    uint32_t sentData;
    int64_t waitSince; /* start of the acknowledgement wait (WAIT_FREE and WAIT_ACK) */
    int64_t endSince;  /* start of the END OF PROCESSING wait */
} CmdHandshake;

void CmdHandshakeInit(CmdHandshake *hs);
/* One scan at PLC time `nowNs` on the module images: reads fromPac, may rewrite toPac. */
void CmdHandshakeScan(CmdHandshake *hs, uint8_t toPac[8], const uint8_t fromPac[8], int64_t nowNs);

#ifdef __cplusplus
}
#endif

#endif
