/* Benchmark only, not part of the library: what FB_PAC_Axis does per scan for one axis module
 * (st/axis/FB_PAC_Axis.st and its parts; manual 2.7), written by hand in plain C without IEC wrappers, so
 * that the benchmark can set what the translated FB costs per scan next to it. The same pins and outputs,
 * the same module decoded only where it changed, the same admission of a job at its Execute edge, the
 * same control image written whole in every scan, the same Start/ACTIVE handshake (the wait for a free
 * axis that has seen Start 0, the take-over bound learnt from the answers, the stale CMD error rule, a
 * stop until ACTIVE falls) and the same waits and timeouts. What it leaves out: jog, ChangeDynamics and
 * ResetError (their pins stay FALSE on the FB in the comparison). bench_table checks scan by scan that
 * both write the same module and give the same outputs. */
#ifndef PAC_BENCH_AXIS_HAND_H
#define PAC_BENCH_AXIS_HAND_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* E_PAC_AxisState's order. */
typedef enum {
    AXIS_HAND_IDLE,
    AXIS_HAND_WAIT_FREE,
    AXIS_HAND_WAIT_TAKEOVER,
    AXIS_HAND_RUNNING,
    AXIS_HAND_STOPPING,
    AXIS_HAND_DONE,
    AXIS_HAND_ERROR,
    AXIS_HAND_ABORTED
} AxisHandState;

/* A job as its module carries it (ST_PAC_AxisJob without the jog's fields). */
typedef struct {
    int command; /* E_PAC_AxisCommand */
    int isMove, hasCondition;
    uint32_t bits;
    uint16_t acceleration, velocity;
    uint32_t position;
    uint16_t errorId;
} AxisHandJob;

/* The module decoded (ST_PAC_AxisStatus). */
typedef struct {
    uint32_t statusWord;
    uint16_t cmdErrorNumber, axisErrorNumber;
    float position;
    int valid;
} AxisHandStatus;

/* TON as the library's timers time: Q once IN has been TRUE for PT, ET up to PT. */
typedef struct {
    int state, prevIn, q;
    int64_t start, et;
} AxisHandTimer;

typedef struct {
    /* inputs */
    uint8_t opStatus;
    int modeChange, enable, execute;
    int command;   /* E_PAC_AxisCommand */
    int condition; /* E_PAC_MoveCondition */
    float position;
    uint16_t velocity, acceleration;
    int abort, disableDrive, disableLimitSwitches, integerMode;
    int64_t timeoutNs;     /* <= 0: 1 s */
    int64_t stopTimeoutNs; /* <= 0: 10 s */
    /* outputs; the status bits are read from status.statusWord */
    int done, busy, error, commandAborted, running, activeWithoutJob, ownsModule;
    uint16_t errorId;
    int errorSource; /* E_PAC_ErrorSource: 0 none, 1 command, 2 system, 3 library */
    AxisHandStatus status;
    float actualPosition; /* kept at the last valid value */
    /* the module */
    uint8_t knownStatus;
    int decoded, decodedIntegerMode, decodedOwnsModule;
    uint8_t decodedImage[12];
    /* the job */
    AxisHandState state;
    int executeBefore, enableBefore, requestPending, errorIsSystem;
    AxisHandJob next, job, sent;
    AxisHandState verdict; /* next's admission, taken once at its edge (FB_PAC_AxisRequest)... */
    uint16_t verdictErrorId; /* ...and why it may not start */
    /* the handshake */
    AxisHandTimer stepTimer;
    int activeSeen, mayStandStill, stopIsAbort, startRaised, takenOver, cmdErrorSeenClear, leftOnline;
    uint16_t staleCmdErrorNumber;
    int answered;
    int64_t answerTime;
    /* the take-over bound */
    int measured;
    int64_t maxTakeover, longestScan, lastScanNs;
    int scanned;
    AxisHandTimer startLowTimer;
} AxisHand;

void AxisHandInit(AxisHand *a);
/* One scan at PLC time `nowNs` on the axis module's images: reads fromPac, rewrites toPac while it owns it. */
void AxisHandScan(AxisHand *a, uint8_t toPac[12], const uint8_t fromPac[12], int64_t nowNs);

/* The single status outputs of FB_PAC_Axis from the status word (2.7.4): bit `bit` set. */
static inline int AxisHandBit(const AxisHand *a, int bit) { return (a->status.statusWord >> bit) & 1u; }

#ifdef __cplusplus
}
#endif

#endif
