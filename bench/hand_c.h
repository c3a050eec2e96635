/* Benchmark only: what the bench's hand-written C shares: the library's own error codes (as in GVL_PAC),
 * E_PAC_ErrorSource, and the modules' fields, high byte first. */
#ifndef PAC_BENCH_HAND_C_H
#define PAC_BENCH_HAND_C_H

#include <stdint.h>

enum {
    ERR_ACK_TIMEOUT = 0x8001,
    ERR_END_TIMEOUT = 0x8002,
    ERR_NOT_READY = 0x8003,
    ERR_CONNECTION_LOST = 0x8004,
    ERR_INVALID_CODE = 0x8005,
    ERR_INTERFACE_BUSY = 0x8006,
    ERR_SUPERSEDED = 0x8007,
    ERR_NOT_ALLOWED = 0x8008,
    ERR_REQUEST_TIMEOUT = 0x8009,
    ERR_AXIS_ERROR = 0x800A,
    ERR_INVALID_VELOCITY = 0x800B,
    ERR_INVALID_ACCELERATION = 0x800C,
    ERR_INVALID_POSITION = 0x800D,
    ERR_NO_COMMAND = 0x800E,
    ERR_NO_ERROR_NUMBER = 0x800F,
    ERR_WRONG_MODE = 0x8021,
    ERR_STOP_TIMEOUT = 0x8022,
    ERR_NOT_ONLINE = 0x8025
};
enum { SOURCE_NONE, SOURCE_COMMAND, SOURCE_SYSTEM, SOURCE_LIBRARY };

static inline void HandPutWord(uint8_t *b, uint16_t v) {
    b[0] = (uint8_t)(v >> 8);
    b[1] = (uint8_t)v;
}

static inline void HandPutDword(uint8_t *b, uint32_t v) {
    HandPutWord(b, (uint16_t)(v >> 16));
    HandPutWord(b + 2, (uint16_t)v);
}

static inline uint16_t HandGetWord(const uint8_t *b) { return (uint16_t)((b[0] << 8) | b[1]); }

static inline uint32_t HandGetDword(const uint8_t *b) { return ((uint32_t)HandGetWord(b) << 16) | HandGetWord(b + 2); }

#endif
