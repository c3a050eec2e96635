/* FB_PAC_Axis's scan for one axis by hand (see axis_hand.h). */
#include "axis_hand.h"

#include <math.h>
#include <string.h>

#include "hand_c.h"

/* E_PAC_AxisCommand, E_PAC_MoveCondition */
enum { CMD_NONE, CMD_HOME, CMD_MOVE_ABSOLUTE, CMD_MOVE_RELATIVE, CMD_MOVE_TO_MAX, CMD_MOVE_TO_MIN,
       CMD_SET_REFERENCED, CMD_SET_POSITION, CMD_CLEAR_OFFSET, CMD_CLEAR_DISPLACED };
enum { COND_NONE, COND_WHILE_INPUT_1 };
enum { STATUS_ONLINE = 31 };
/* status word bits (2.7.4) */
enum { ST_HALTED = 0x2, ST_ACTIVE = 0x80, ST_STOPPED_BY_CONDITION = 0x800, ST_CMD_ERROR = 0x4000,
       ST_AXIS_ERROR = 0x8000 };

#define MS 1000000LL
#define UPDATE_TIME (10 * MS) /* 2.3.4: the PA-CONTROL's update time in ONLINE */

void AxisHandInit(AxisHand *a) {
    memset(a, 0, sizeof *a);
    a->velocity = 1000;
    a->acceleration = 1000;
    a->timeoutNs = 1000 * MS;
    a->stopTimeoutNs = 10000 * MS;
}

static void Timer(AxisHandTimer *t, int in, int64_t pt, int64_t now) {
    if (t->state == 0 && !t->prevIn && in) {
        t->state = 1;
        t->q = 0;
        t->start = now;
    } else if (!in) {
        t->et = 0;
        t->q = 0;
        t->state = 0;
    } else if (t->state == 1) {
        if (now - t->start >= pt) {
            t->state = 2;
            t->et = pt;
            t->q = 1;
        } else {
            t->et = now - t->start;
        }
    }
    t->prevIn = in;
}

static void Restart(AxisHandTimer *t, int64_t now) {
    t->state = 1;
    t->q = 0;
    t->et = 0;
    t->start = now;
    t->prevIn = 1;
}

static void Reset(AxisHandTimer *t) {
    t->state = t->q = t->prevIn = 0;
    t->et = 0;
}

/* A position field (2.5.3): IEEE REAL (a NaN reads as 0) or DINT x 1000. */
static float DecodeReal(uint32_t bits, int integerMode) {
    float f;
    if (integerMode) return (float)((double)(int32_t)bits / 1000.0);
    if ((bits & 0x7F800000u) == 0x7F800000u && (bits & 0x7FFFFFu) != 0) return 0.0f;
    memcpy(&f, &bits, sizeof f);
    return f;
}

/* 0 if the value has no field: NaN, infinite, or beyond a DINT x 1000. */
static int EncodeReal(float value, int integerMode, uint32_t *bits) {
    uint32_t pattern;
    double scaled;
    *bits = 0;
    if (value != value) return 0;
    if (value == 0.0f) value = 0.0f; /* -0.0 as 0.0, as the library's conversion */
    memcpy(&pattern, &value, sizeof pattern);
    if ((pattern & 0x7F800000u) == 0x7F800000u) return 0;
    if (integerMode) {
        scaled = (double)value * 1000.0;
        if (scaled < -2147483648.0 || scaled > 2147483647.0) return 0;
        pattern = (uint32_t)(int32_t)nearbyint(scaled);
    }
    *bits = pattern;
    return 1;
}

static void Encode(AxisHand *a, AxisHandJob *j) {
    static const uint32_t kBits[] = {0, 0x8, 0x40, 0x80, 0x4000, 0x8000, 0x10, 0x20, 0x1000, 0x2000};
    const int c = a->command;
    j->command = c;
    j->bits = c >= 0 && c <= CMD_CLEAR_DISPLACED ? kBits[c] : 0;
    j->isMove =
        !(c == CMD_SET_REFERENCED || c == CMD_SET_POSITION || c == CMD_CLEAR_OFFSET || c == CMD_CLEAR_DISPLACED);
    j->hasCondition = (c == CMD_MOVE_ABSOLUTE || c == CMD_MOVE_RELATIVE) && a->condition != COND_NONE;
    if (j->hasCondition) j->bits |= a->condition == COND_WHILE_INPUT_1 ? 0x100 : 0x200;
    j->velocity = a->velocity;
    j->acceleration = a->acceleration;
    j->errorId = 0;
    if (!EncodeReal(a->position, a->integerMode, &j->position)) j->errorId = ERR_INVALID_POSITION;
    if (j->bits == 0) {
        j->errorId = ERR_NO_COMMAND;
    } else if (a->velocity == 0 || a->velocity > 1000) {
        j->errorId = ERR_INVALID_VELOCITY;
    } else if (a->acceleration == 0) {
        j->errorId = ERR_INVALID_ACCELERATION;
    }
}

static int Busy(AxisHandState s) { return s >= AXIS_HAND_WAIT_FREE && s <= AXIS_HAND_STOPPING; }

/* Who owns the module, and the module decoded where it, the format or the ownership changed (FB_PAC_AxisModule). */
static void Module(AxisHand *a, const uint8_t from[12], int *inOnline) {
    int sameHead, tailChanged;
    if (a->opStatus != 0) a->knownStatus = a->opStatus;
    *inOnline = a->knownStatus >= 30 && a->knownStatus <= 39;
    a->ownsModule = *inOnline || a->knownStatus == 1 || a->knownStatus == 9;
    sameHead = a->decoded && a->ownsModule == a->decodedOwnsModule && a->integerMode == a->decodedIntegerMode &&
               memcmp(from, a->decodedImage, 8) == 0;
    tailChanged = memcmp(from + 8, a->decodedImage + 8, 4) != 0;
    if (tailChanged && sameHead && a->ownsModule && a->status.statusWord != 0) {
        memcpy(a->decodedImage, from, 12);
        a->status.position = DecodeReal(HandGetDword(from + 8), a->integerMode);
        a->actualPosition = a->status.position;
    } else if (!sameHead || tailChanged) {
        a->decoded = 1;
        a->decodedOwnsModule = a->ownsModule;
        a->decodedIntegerMode = a->integerMode;
        memcpy(a->decodedImage, from, 12);
        memset(&a->status, 0, sizeof a->status);
        if (a->ownsModule) {
            const uint32_t raw = HandGetDword(from + 8);
            a->status.statusWord = HandGetDword(from);
            a->status.cmdErrorNumber = HandGetWord(from + 4);
            a->status.axisErrorNumber = HandGetWord(from + 6);
            a->status.valid = a->status.statusWord != 0 || a->status.cmdErrorNumber != 0 ||
                              a->status.axisErrorNumber != 0 || raw != 0;
            a->status.position = DecodeReal(raw, a->integerMode);
            if (a->status.valid) a->actualPosition = a->status.position;
        }
    }
}

/* The longest a take-over may take, and whether Start has been 0 long enough (FB_PAC_AxisTakeover). */
static int64_t Takeover(AxisHand *a, int startOnWire, int64_t now, int *startLow) {
    int64_t assumed;
    if (a->answered && a->answerTime > a->maxTakeover) a->maxTakeover = a->answerTime;
    a->measured |= a->answered;
    if (a->measured) {
        assumed = a->maxTakeover;
    } else {
        const int64_t scan = !a->scanned ? 0 : now - a->lastScanNs < 3600000 * MS ? now - a->lastScanNs : 3600000 * MS;
        if (scan > a->longestScan) a->longestScan = scan;
        a->scanned = 1;
        a->lastScanNs = now;
        assumed = 7 * a->longestScan + UPDATE_TIME;
    }
    if (startOnWire || !a->startLowTimer.q) Timer(&a->startLowTimer, !startOnWire, assumed + UPDATE_TIME, now);
    *startLow = a->startLowTimer.q;
    return assumed + assumed + UPDATE_TIME;
}

static void Fail(AxisHand *a, uint16_t errorId) {
    a->state = AXIS_HAND_ERROR;
    a->errorId = errorId;
}

static void Stop(AxisHand *a) {
    a->state = AXIS_HAND_STOPPING;
    Reset(&a->stepTimer);
}

/* Start out, ACTIVE or a CMD error back, run, stop (FB_PAC_AxisHandshake). */
static void Handshake(AxisHand *a, const uint8_t from[12], int admitted, int stopRequest, int abortRequest,
                      int64_t bound, int startLow, int onlineLeft, int64_t timeout, int64_t stopTimeout, int64_t now) {
    const uint32_t sw = a->status.statusWord;
    const int active = (sw & ST_ACTIVE) != 0, cmdError = (sw & ST_CMD_ERROR) != 0;
    const int axisError = (sw & ST_AXIS_ERROR) != 0;
    a->activeSeen = (a->activeSeen || active) && a->ownsModule;
    a->takenOver |= a->startRaised && a->activeSeen;
    a->answered = 0;
    if (admitted) {
        Reset(&a->stepTimer);
        Timer(&a->stepTimer, 1, timeout, now);
        a->stopIsAbort = a->startRaised = a->takenOver = 0;
    }
    if (a->state == AXIS_HAND_WAIT_FREE) {
        Timer(&a->stepTimer, 1, timeout, now);
        if (axisError) {
            Fail(a, ERR_AXIS_ERROR);
        } else if (stopRequest) {
            Stop(a);
        } else if (onlineLeft) {
            Fail(a, ERR_NOT_ONLINE);
        } else if (a->stepTimer.q) {
            Fail(a, ERR_INTERFACE_BUSY);
        } else if (!active && (a->activeSeen || startLow)) {
            const uint32_t standsAt = HandGetDword(from + 8);
            const AxisHandJob *j = &a->job;
            a->sent = a->job;
            a->mayStandStill = !j->isMove || j->hasCondition || j->command == CMD_HOME ||
                               (j->command == CMD_MOVE_ABSOLUTE && j->position == standsAt) ||
                               (j->command == CMD_MOVE_RELATIVE && (j->position == 0 || j->position == 0x80000000u));
            a->staleCmdErrorNumber = a->status.cmdErrorNumber;
            a->cmdErrorSeenClear = !cmdError;
            a->activeSeen = 0;
            a->startRaised = 1;
            a->leftOnline = 0;
            Restart(&a->stepTimer, now);
            a->state = AXIS_HAND_WAIT_TAKEOVER;
        }
    } else if (a->state == AXIS_HAND_WAIT_TAKEOVER) {
        int isNew, due;
        Timer(&a->stepTimer, 1, timeout, now);
        a->leftOnline |= onlineLeft;
        a->cmdErrorSeenClear |= !cmdError;
        isNew = cmdError && (a->cmdErrorSeenClear || a->status.cmdErrorNumber != a->staleCmdErrorNumber);
        a->answered = isNew || active;
        a->answerTime = a->stepTimer.et;
        due = (a->measured || a->answered) && a->stepTimer.et >= bound;
        if (isNew || (cmdError && due)) {
            Fail(a, a->status.cmdErrorNumber);
        } else if (active) {
            a->state = AXIS_HAND_RUNNING;
        } else if (axisError) {
            Fail(a, ERR_AXIS_ERROR);
            if (a->status.axisErrorNumber != 0) {
                a->errorId = a->status.axisErrorNumber;
                a->errorIsSystem = 1;
            }
        } else if (stopRequest) {
            Stop(a);
        } else if ((a->mayStandStill || a->leftOnline) && !cmdError && a->stepTimer.et >= bound) {
            if (a->leftOnline) {
                Fail(a, ERR_NOT_ONLINE);
            } else {
                a->state = AXIS_HAND_DONE;
            }
        } else if (a->stepTimer.q) {
            Fail(a, cmdError ? a->status.cmdErrorNumber : ERR_ACK_TIMEOUT);
        }
        if (a->state == AXIS_HAND_ERROR && a->errorId == 0) a->errorId = ERR_NOT_ALLOWED;
    }
    if (a->state == AXIS_HAND_RUNNING) {
        if (axisError) {
            Fail(a, ERR_AXIS_ERROR);
        } else if (!active) {
            const int interrupted = a->job.isMove && (sw & ST_HALTED) &&
                                    !(a->job.hasCondition && (sw & ST_STOPPED_BY_CONDITION));
            a->state = interrupted ? AXIS_HAND_ABORTED : AXIS_HAND_DONE;
        } else if (stopRequest) {
            Stop(a);
        }
    }
    if (a->state == AXIS_HAND_STOPPING) {
        Timer(&a->stepTimer, 1, stopTimeout, now);
        a->stopIsAbort |= abortRequest;
        if (axisError) {
            Fail(a, ERR_AXIS_ERROR);
        } else if (!active && (a->activeSeen || startLow)) {
            a->state = a->stopIsAbort || !a->takenOver ? AXIS_HAND_ABORTED : AXIS_HAND_DONE;
        } else if (a->stepTimer.q) {
            Fail(a, ERR_STOP_TIMEOUT);
        }
    }
}

static void Fields(uint8_t to[12], uint32_t word, uint16_t acceleration, uint16_t velocity, uint32_t position) {
    HandPutDword(to, word);
    HandPutWord(to + 4, acceleration);
    HandPutWord(to + 6, velocity);
    HandPutDword(to + 8, position);
}

/* A request's verdict at its edge (F_PAC_AxisAdmission). */
static AxisHandState Admission(const AxisHand *a, const AxisHandJob *job, uint16_t *errorId) {
    *errorId = 0;
    if (a->opStatus == 0 || (a->ownsModule && !a->status.valid)) {
        *errorId = ERR_NOT_READY;
    } else if (!a->ownsModule || a->modeChange) {
        *errorId = ERR_WRONG_MODE;
    } else if (a->opStatus != STATUS_ONLINE) {
        *errorId = ERR_NOT_ONLINE;
    } else if (a->abort) {
        return AXIS_HAND_ABORTED;
    } else if (job->errorId != 0) {
        *errorId = job->errorId;
    } else if (a->status.statusWord & ST_AXIS_ERROR) {
        *errorId = ERR_AXIS_ERROR;
    } else {
        return AXIS_HAND_WAIT_FREE;
    }
    return AXIS_HAND_ERROR;
}

void AxisHandScan(AxisHand *a, uint8_t toPac[12], const uint8_t fromPac[12], int64_t nowNs) {
    const int64_t timeout = a->timeoutNs > 0 ? a->timeoutNs : 1000 * MS;
    const int64_t stopTimeout = a->stopTimeoutNs > 0 ? a->stopTimeoutNs : 10000 * MS;
    const int edge = a->execute && !a->executeBefore;
    const int abortRequest = a->abort || (a->enableBefore && !a->enable);
    int inOnline, startLow, superseded = 0, accepted = 0;
    int64_t bound;
    Module(a, fromPac, &inOnline);
    bound = Takeover(a, (toPac[3] & 0x04) != 0, nowNs, &startLow);
    a->executeBefore = a->execute;
    a->enableBefore = a->enable;

    if (edge) {
        /* Admitted once, at its edge, on this scan's status; its wait counts from here. A running job ends,
         * CommandAborted for one scan, and the new one takes the outputs over in the next. */
        Encode(a, &a->next);
        a->verdict = Admission(a, &a->next, &a->verdictErrorId);
        accepted = a->verdict == AXIS_HAND_WAIT_FREE;
        a->requestPending = 1;
        superseded = Busy(a->state);
        if (superseded) a->state = AXIS_HAND_ABORTED;
    }
    if (!Busy(a->state) && a->state != AXIS_HAND_IDLE && !superseded && (!a->execute || a->requestPending)) {
        a->state = AXIS_HAND_IDLE;
        a->errorId = 0;
    }
    if (a->state == AXIS_HAND_IDLE && a->requestPending) {
        a->requestPending = 0;
        a->job = a->next;
        a->errorIsSystem = 0;
        a->state = a->verdict;
        a->errorId = a->verdictErrorId;
    }
    if ((!a->status.valid || a->modeChange) && Busy(a->state)) a->state = AXIS_HAND_ABORTED;
    Handshake(a, fromPac, accepted, abortRequest, abortRequest, bound, startLow,
              a->opStatus != 0 && a->opStatus != STATUS_ONLINE, timeout, stopTimeout, nowNs);

    a->busy = Busy(a->state);
    a->activeWithoutJob = (a->status.statusWord & ST_ACTIVE) && !a->busy && !a->requestPending;
    a->running = a->state == AXIS_HAND_RUNNING;
    a->done = a->state == AXIS_HAND_DONE;
    a->error = a->state == AXIS_HAND_ERROR;
    a->commandAborted = a->state == AXIS_HAND_ABORTED;
    if (a->ownsModule) {
        uint32_t word = (uint32_t)(a->enable != 0) | (uint32_t)(a->disableDrive != 0) << 1 |
                        (uint32_t)(a->disableLimitSwitches && inOnline) << 17;
        if (a->state == AXIS_HAND_WAIT_TAKEOVER) word |= 0x4 | a->sent.bits;
        if (a->state == AXIS_HAND_RUNNING) word |= a->sent.bits;
        if (a->modeChange) {
            memset(toPac, 0, 12);
        } else if (inOnline || a->busy) {
            Fields(toPac, word, a->sent.acceleration, a->sent.velocity, a->sent.position);
        } else {
            Fields(toPac, word, 0, 0, 0);
        }
    }
    a->errorSource = !a->error ? SOURCE_NONE
                     : a->errorId >= 0x8000 ? SOURCE_LIBRARY
                     : a->errorIsSystem ? SOURCE_SYSTEM
                                        : SOURCE_COMMAND;
}
