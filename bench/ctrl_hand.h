/* Benchmark only, not part of the library: what FB_PAC_Ctrl does per scan (st/modes/FB_PAC_Ctrl.st; manual
 * 2.5), written by hand in plain C without IEC wrappers, so that the benchmark can set what the translated FB
 * costs per scan next to it: the same pins and outputs, the status word decoded in every scan, the same
 * checks at the Execute edge, the same waits (the request's bit out until the status word shows the result,
 * CANCEL and RESET ERROR only after the controller has read their bit) and timeout, the whole CTRL module
 * written in every scan. bench_table checks scan by scan that both write the same module and give the same
 * outputs. */
#ifndef PAC_BENCH_CTRL_HAND_H
#define PAC_BENCH_CTRL_HAND_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* E_PAC_CtrlRequest's order. */
typedef enum {
    CTRL_HAND_NONE,
    CTRL_HAND_START_ONLINE,
    CTRL_HAND_START_AUTOMATIC,
    CTRL_HAND_STOP,
    CTRL_HAND_CANCEL,
    CTRL_HAND_RESET_ERROR
} CtrlHandRequest;

typedef enum { CTRL_HAND_IDLE, CTRL_HAND_WAIT, CTRL_HAND_DONE, CTRL_HAND_ERROR } CtrlHandState;

typedef struct {
    /* inputs */
    int execute;
    int request; /* CtrlHandRequest */
    int integerMode;
    int64_t timeoutNs; /* <= 0: 10 s */
    /* outputs */
    int done, busy, error;
    uint16_t errorId;
    int errorSource; /* E_PAC_ErrorSource: 0 none, 2 system, 3 library */
    int ready, batteryOk, systemError, automaticActive, automaticStopped, onlineActive, onlineStopped;
    int integerModeActive, modeChange;
    uint16_t systemErrorNumber;
    /* state */
    CtrlHandState state;
    int executeBefore, latched, systemErrorAtEdge;
    int64_t waitSince; /* the request's bit went out */
    unsigned readCalls;
} CtrlHand;

void CtrlHandInit(CtrlHand *c);
/* One scan at PLC time `nowNs` on the CTRL module's images: reads fromPac, writes toPac whole. */
void CtrlHandScan(CtrlHand *c, uint8_t toPac[8], const uint8_t fromPac[8], int64_t nowNs);

#ifdef __cplusplus
}
#endif

#endif
