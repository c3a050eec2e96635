/* Elementary IEC 61131-3 types, variable wrappers and the standard function blocks for the C code
 * that pacst generates. It reproduces the C interface of MATIEC's iec_std_lib.h that a harness sees
 * (type names, {value; flags} wrappers, TIME as seconds + nanoseconds, R_TRIG/F_TRIG/TON/TOF/TP with
 * MATIEC's member names), so that a harness compiles unchanged against either compiler's output.
 * Written for this project; see docs/translator.md. */
#ifndef PACST_IEC_H
#define PACST_IEC_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef uint8_t BOOL;
typedef int8_t SINT;
typedef int16_t INT;
typedef int32_t DINT;
typedef int64_t LINT;
typedef uint8_t USINT;
typedef uint16_t UINT;
typedef uint32_t UDINT;
typedef uint64_t ULINT;
typedef uint8_t BYTE;
typedef uint16_t WORD;
typedef uint32_t DWORD;
typedef uint64_t LWORD;
typedef float REAL;
typedef double LREAL;
/* MATIEC's IEC_TIMESPEC member for member (long, long): the C++ side of a MATIEC build reads and writes
 * TIME values that MATIEC's code uses, so the layout must be the same (checked, docs/translator.md). */
#if defined(PACST_CBMC_TIME32) && !defined(__CPROVER__)
#error "PACST_CBMC_TIME32 is the model checker's TIME: MATIEC's layout (long, long) everywhere else"
#endif
#ifdef PACST_CBMC_TIME32
/* The model checker's TIME (docs/verification.md, "TIME in 32 bits"): the same values in 32-bit fields, every sum
 * and difference checked for overflow there, so each proof's arithmetic is that of the 64-bit fields. */
typedef int32_t pacst_time_field;
#else
typedef long pacst_time_field;
#endif
typedef struct {
    pacst_time_field tv_sec;
    pacst_time_field tv_nsec;
} IEC_TIMESPEC;
typedef IEC_TIMESPEC TIME;
/* A STRING: a length and room for STR_MAX_LEN bytes. pacst's C holds 255 characters, TwinCAT's longest
 * string its string functions take (T_MaxString); the declarations of MATIEC's C (pacst declare) and every
 * file of a MATIEC build define PACST_MATIEC_STRING, for MATIEC's STRING of 126 (docs/translator.md). */
#ifdef PACST_MATIEC_STRING
#define STR_MAX_LEN 126
#else
#define STR_MAX_LEN 255
#endif
typedef struct {
    uint8_t len;
    uint8_t body[STR_MAX_LEN];
} STRING;
/* User mode: a WSTRING, TwinCAT's and CODESYS's wide string, holds UCS-2 code units, a WORD each, as they store
 * it: a length word and room for STR_MAX_LEN units (512 bytes, SIZEOF counting two a character as theirs). */
typedef struct {
    uint16_t len;
    uint16_t body[STR_MAX_LEN];
} WSTRING;

#ifndef TRUE
#define TRUE 1
#endif
#ifndef FALSE
#define FALSE 0
#endif

/* Flag bits of a variable wrapper, as MATIEC's accessor.h numbers them. A member whose flags carry
 * the force bit keeps its value: the generated code skips every write to it. */
#define __IEC_DEBUG_FLAG 0x01
#define __IEC_FORCE_FLAG 0x02
#define __IEC_RETAIN_FLAG 0x04
#define __IEC_OUTPUT_FLAG 0x08

#define __PACST_WRAPPER(type) typedef struct { type value; BYTE flags; } __IEC_##type##_t;
__PACST_WRAPPER(BOOL)
__PACST_WRAPPER(SINT)
__PACST_WRAPPER(INT)
__PACST_WRAPPER(DINT)
__PACST_WRAPPER(LINT)
__PACST_WRAPPER(USINT)
__PACST_WRAPPER(UINT)
__PACST_WRAPPER(UDINT)
__PACST_WRAPPER(ULINT)
__PACST_WRAPPER(BYTE)
__PACST_WRAPPER(WORD)
__PACST_WRAPPER(DWORD)
__PACST_WRAPPER(LWORD)
__PACST_WRAPPER(REAL)
__PACST_WRAPPER(LREAL)
__PACST_WRAPPER(TIME)
__PACST_WRAPPER(STRING)
__PACST_WRAPPER(WSTRING)

static inline STRING __pacst_string(const char *text, int len) {
    STRING s;
    int i;
    s.len = (uint8_t)len;
    for (i = 0; i < STR_MAX_LEN; i++) s.body[i] = (uint8_t)(i < len ? text[i] : 0);
    return s;
}
/* User mode: s[i], the unit at offset i of a string's characters (a STRING's byte, a WSTRING's WORD), as TwinCAT
 * and CODESYS read it (0 after the last character, their terminating NUL); written, the length is where the first
 * NUL is then. */
#define __PACST_STRING_UNIT(S, UNIT, LEN, get, set)                \
    static inline UNIT get(S s, long i) {                           \
        return (UNIT)(i < (long)s.len ? s.body[i] : 0);             \
    }                                                               \
    static inline S set(S s, long i, UNIT u) {                      \
        int n = 0;                                                  \
        s.body[i] = u;                                              \
        while (n < STR_MAX_LEN && s.body[n] != 0) n++;              \
        s.len = (LEN)n;                                             \
        return s;                                                   \
    }
__PACST_STRING_UNIT(STRING, BYTE, uint8_t, __pacst_str_byte, __pacst_str_setbyte)
__PACST_STRING_UNIT(WSTRING, WORD, uint16_t, __pacst_wstr_word, __pacst_wstr_setword)
static inline int __pacst_string_eq(STRING a, STRING b) {
    int i;
    if (a.len != b.len) return 0;
    for (i = 0; i < a.len; i++) {
        if (a.body[i] != b.body[i]) return 0;
    }
    return 1;
}
/* User mode: < > <= >= on strings: the first unit that differs decides, compared as an unsigned number (a STRING's
 * byte from 0 to 255, a character above 127 after every ASCII one; a WSTRING's code unit); where none differs the
 * shorter string comes first. Negative, 0 or positive, as memcmp. */
#define __PACST_UNITS_CMP(UNIT, NAME)                                                   \
    static inline int NAME(const UNIT *a, size_t n, const UNIT *b, size_t m) {         \
        size_t i, k = n < m ? n : m;                                                   \
        for (i = 0; i < k; i++) {                                                      \
            if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;                             \
        }                                                                              \
        return n < m ? -1 : n > m ? 1 : 0;                                             \
    }
__PACST_UNITS_CMP(uint8_t, __pacst_bytes_cmp)
__PACST_UNITS_CMP(uint16_t, __pacst_words_cmp)
static inline int __pacst_string_cmp(STRING a, STRING b) { return __pacst_bytes_cmp(a.body, a.len, b.body, b.len); }

/* The standard string functions of user programs (pacst --user), on a STRING's bytes (__pacst_str_) and on a
 * WSTRING's code units (__pacst_wstr_: Tc2_Standard's WLEN, WCONCAT, WLEFT, ...): positions count from 1, a result
 * keeps at most STR_MAX_LEN units, a position or length outside the string is clamped to it. */
static inline long __pacst_str_clamp(long v, long lo, long hi) { return v < lo ? lo : v > hi ? hi : v; }
#define __PACST_STRING_FUNCTIONS(S, LEN, P)                                                                    \
    static inline S __pacst_##P##_part(S s, long from, long count) {                                         \
        S r;                                                                                                   \
        from = __pacst_str_clamp(from, 0, s.len);                                                              \
        count = __pacst_str_clamp(count, 0, s.len - from);                                                     \
        memset(&r, 0, sizeof r);                                                                               \
        r.len = (LEN)count;                                                                                    \
        memcpy(r.body, s.body + from, (size_t)count * sizeof r.body[0]);                                       \
        return r;                                                                                              \
    }                                                                                                          \
    static inline S __pacst_##P##_concat(S a, S b) {                                                         \
        size_t n = b.len < STR_MAX_LEN - a.len ? b.len : (size_t)(STR_MAX_LEN - a.len);                        \
        memcpy(a.body + a.len, b.body, n * sizeof a.body[0]);                                                  \
        a.len = (LEN)(a.len + n);                                                                              \
        return a;                                                                                              \
    }                                                                                                          \
    static inline INT __pacst_##P##_len(S s) { return (INT)s.len; }                                         \
    static inline S __pacst_##P##_limit(S s, long n) { return __pacst_##P##_part(s, 0, n); }                 \
    static inline S __pacst_##P##_left(S s, long l) { return __pacst_##P##_part(s, 0, l); }                  \
    static inline S __pacst_##P##_right(S s, long l) {                                                       \
        l = __pacst_str_clamp(l, 0, s.len);                                                                    \
        return __pacst_##P##_part(s, s.len - l, l);                                                            \
    }                                                                                                          \
    static inline S __pacst_##P##_mid(S s, long l, long p) {                                                 \
        if (p < 1 || p > s.len) return __pacst_##P##_part(s, 0, 0);                                            \
        return __pacst_##P##_part(s, p - 1, l);                                                                \
    }                                                                                                          \
    static inline INT __pacst_##P##_find(S s, S what) {                                                      \
        long i;                                                                                                \
        if (what.len == 0) return 0;                                                                           \
        for (i = 0; i + what.len <= s.len; i++) {                                                              \
            if (memcmp(s.body + i, what.body, what.len * sizeof s.body[0]) == 0) return (INT)(i + 1);          \
        }                                                                                                      \
        return 0;                                                                                              \
    }                                                                                                          \
    static inline S __pacst_##P##_replace(S s, S with, long l, long p) {                                     \
        p = __pacst_str_clamp(p, 1, (long)s.len + 1);                                                          \
        l = __pacst_str_clamp(l, 0, (long)s.len - (p - 1));                                                    \
        return __pacst_##P##_concat(__pacst_##P##_concat(__pacst_##P##_part(s, 0, p - 1), with),               \
                                    __pacst_##P##_part(s, p - 1 + l, s.len));                                  \
    }                                                                                                          \
    static inline S __pacst_##P##_insert(S s, S with, long p) {                                              \
        p = __pacst_str_clamp(p, 0, s.len);                                                                    \
        return __pacst_##P##_concat(__pacst_##P##_concat(__pacst_##P##_part(s, 0, p), with),                   \
                                    __pacst_##P##_part(s, p, s.len));                                          \
    }                                                                                                          \
    static inline S __pacst_##P##_delete(S s, long l, long p) {                                              \
        S none;                                                                                                \
        memset(&none, 0, sizeof none);                                                                         \
        return __pacst_##P##_replace(s, none, l, p);                                                           \
    }
__PACST_STRING_FUNCTIONS(STRING, uint8_t, str)
__PACST_STRING_FUNCTIONS(WSTRING, uint16_t, wstr)
/* INT_TO_STRING and the other integer conversions to STRING: decimal, a '-' before a negative value (ULINT and
   LWORD: the magnitude u alone). */
static inline STRING __pacst_digits_to_string(unsigned long long u, int negative) {
    char digits[24];
    int n = 0, i;
    STRING s;
    do {
        digits[n++] = (char)('0' + u % 10U);
        u /= 10U;
    } while (u != 0U);
    if (negative) digits[n++] = '-';
    s.len = (uint8_t)n;
    for (i = 0; i < STR_MAX_LEN; i++) s.body[i] = (uint8_t)(i < n ? digits[n - 1 - i] : 0);
    return s;
}
static inline STRING __pacst_int_to_string(long long v) {
    return __pacst_digits_to_string(v < 0 ? 0ULL - (unsigned long long)v : (unsigned long long)v, v < 0);
}
/* User mode: STRING_TO_<integer> as TwinCAT's and CODESYS's help describe it: spaces skipped, a sign, digits with
 * '_' between them and a base (16#FF); text after the number ignored, text before it 0. The value wraps to 64 bits;
 * the caller cuts it to its type (STRING_TO_BYTE('500') is 244). */
static inline unsigned long long __pacst_string_to_bits(STRING s) {
    unsigned long long v = 0ULL, base = 10ULL;
    int i = 0, negative = 0, digits = 0;
    while (i < s.len && s.body[i] == ' ') i++;
    if (i < s.len && (s.body[i] == '+' || s.body[i] == '-')) negative = s.body[i++] == '-';
    for (; i < s.len; i++) {
        int c = s.body[i], d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10
                             : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
        if (c == '_' && digits > 0) continue;
        if (c == '#' && base == 10ULL && digits > 0 && (v == 2ULL || v == 8ULL || v == 16ULL)) {
            base = v;
            v = 0ULL;
            digits = 0;
            continue;
        }
        if (d < 0 || (unsigned long long)d >= base) break;
        v = v * base + (unsigned long long)d;
        digits++;
    }
    return negative ? 0ULL - v : v;
}
/* Whether the upper-case `word` stands at s[i], in any case. */
static inline int __pacst_string_word(STRING s, int i, const char *word) {
    int k;
    for (k = 0; word[k] != 0 && i + k < s.len; k++) {
        int c = s.body[i + k];
        if ((c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c) != word[k]) break;
    }
    return word[k] == 0;
}
/* STRING_TO_REAL and _LREAL: a REAL literal (digits with '_', a point, an exponent) after spaces and a sign; text
 * after it ignored, text before it 0, but "#INF" and "#NAN" / "#QNAN" in any case infinity and NaN. Only those
 * characters reach strtod, so its hex and "inf" forms never do. */
static inline double __pacst_string_to_real(STRING s) {
    char text[STR_MAX_LEN + 1];
    int i = 0, n = 0, digits = 0;
    while (i < s.len && s.body[i] == ' ') i++;
    if (i < s.len && (s.body[i] == '+' || s.body[i] == '-')) text[n++] = (char)s.body[i++];
    if (__pacst_string_word(s, i, "#INF")) /* as LREAL_TO_FMTSTR writes them (FsCommon's F_GetInf reads them) */
        return n > 0 && text[0] == '-' ? -HUGE_VAL : HUGE_VAL;
    if (__pacst_string_word(s, i, "#NAN") || __pacst_string_word(s, i, "#QNAN")) return NAN;
    for (; i < s.len && ((s.body[i] >= '0' && s.body[i] <= '9') || (s.body[i] == '_' && digits)); i++)
        if (s.body[i] != '_') text[n++] = (char)s.body[i], digits++;
    if (i + 1 < s.len && s.body[i] == '.' && s.body[i + 1] >= '0' && s.body[i + 1] <= '9' && digits) {
        text[n++] = '.';
        for (i++; i < s.len && ((s.body[i] >= '0' && s.body[i] <= '9') || s.body[i] == '_'); i++)
            if (s.body[i] != '_') text[n++] = (char)s.body[i];
    }
    if (digits && i + 1 < s.len && (s.body[i] == 'e' || s.body[i] == 'E')) {
        int j = i + 1, m = n;
        text[m++] = 'e';
        if (s.body[j] == '+' || s.body[j] == '-') text[m++] = (char)s.body[j++];
        if (j < s.len && s.body[j] >= '0' && s.body[j] <= '9') {
            for (n = m; j < s.len && s.body[j] >= '0' && s.body[j] <= '9'; j++) text[n++] = (char)s.body[j];
        }
    }
    text[n] = 0;
    return digits ? strtod(text, NULL) : 0.0;
}
/* STRING_TO_BOOL: TRUE for "TRUE" in any case (after spaces) or a number not 0. */
static inline BOOL __pacst_string_to_bool(STRING s) {
    int i = 0;
    while (i < s.len && s.body[i] == ' ') i++;
    return __pacst_string_word(s, i, "TRUE") || __pacst_string_to_bits(s) != 0ULL;
}
/* User mode: REAL_TO_STRING (7 significant digits) and LREAL_TO_STRING (16), as TwinCAT writes them in TcUnit's
 * messages: trailing zeros dropped, a whole number with ".0" (-23.0); an exponent as C writes it (1e+20). */
static inline STRING __pacst_real_to_string(double v, int digits) {
    char text[40];
    int n = snprintf(text, sizeof text - 2, "%.*g", digits, v);
    if (isfinite(v) && strpbrk(text, ".e") == NULL) {
        text[n++] = '.';
        text[n++] = '0';
    }
    return __pacst_string(text, n);
}
/* User mode: a WSTRING's code units as LEN, CONCAT and = take a STRING's bytes above (s[i]: __PACST_STRING_UNIT).
 * A literal is its units; a unit past the room is dropped, as a STRING's byte is. */
static inline WSTRING __pacst_wstring(const uint16_t *units, int len) {
    WSTRING s;
    memset(&s, 0, sizeof s);
    s.len = (uint16_t)len;
    if (len > 0) memcpy(s.body, units, (size_t)len * sizeof s.body[0]);
    return s;
}
static inline int __pacst_wstring_eq(WSTRING a, WSTRING b) {
    return a.len == b.len && memcmp(a.body, b.body, (size_t)a.len * sizeof a.body[0]) == 0;
}
static inline int __pacst_wstring_cmp(WSTRING a, WSTRING b) { return __pacst_words_cmp(a.body, a.len, b.body, b.len); }
/* WSTRING_TO_STRING: a unit above 16#FF has no STRING character and is skipped, as Tc2_Utilities'
 * WSTRING_TO_STRING2 and WCHAR_TO_CHAR skip it; STRING_TO_WSTRING: each byte the unit of its number. */
static inline STRING __pacst_wstring_to_string(WSTRING w) {
    STRING s;
    int i, n = 0;
    memset(&s, 0, sizeof s);
    for (i = 0; i < w.len && i < STR_MAX_LEN; i++) {
        if (w.body[i] <= 0xFFu) s.body[n++] = (uint8_t)w.body[i];
    }
    s.len = (uint8_t)n;
    return s;
}
static inline WSTRING __pacst_string_to_wstring(STRING s) {
    WSTRING w;
    int i;
    memset(&w, 0, sizeof w);
    w.len = s.len;
    for (i = 0; i < s.len && i < STR_MAX_LEN; i++) w.body[i] = s.body[i];
    return w;
}

/* User mode: a STRING(n) or WSTRING(n) with n over STR_MAX_LEN is a C type of its own (pacst's LongStringType), its
 * n units and a NUL as TwinCAT lays it out; these read and write one by the address of its units and its n. _short:
 * its first STR_MAX_LEN units as a STRING (WSTRING), as the string functions' STRING(255) inputs take it; _of_short
 * and _copy: a STRING or another long string written into one, cut to its n; _eq and _eq_short compare the text,
 * _cmp and _cmp_short order it (CMP, __PACST_UNITS_CMP's). */
#define __PACST_LONG_STRING(S, UNIT, P, CMP)                                                                    \
    static inline size_t __pacst_##P##_units(const UNIT *body, size_t n) {                                   \
        size_t k = 0;                                                                                          \
        while (k < n && body[k] != 0) k++;                                                                     \
        return k;                                                                                              \
    }                                                                                                          \
    static inline S __pacst_##P##_short(const UNIT *body, size_t n) {                                        \
        S s;                                                                                                   \
        size_t k = __pacst_##P##_units(body, n);                                                               \
        if (k > STR_MAX_LEN) k = STR_MAX_LEN;                                                                  \
        memset(&s, 0, sizeof s);                                                                               \
        s.len = (UNIT)k;                                                                                       \
        memcpy(s.body, body, k * sizeof(UNIT));                                                                \
        return s;                                                                                              \
    }                                                                                                          \
    static inline UNIT *__pacst_##P##_of_short(UNIT *body, size_t n, S s) {                                  \
        size_t k = s.len < n ? s.len : n;                                                                      \
        memcpy(body, s.body, k * sizeof(UNIT));                                                                \
        memset(body + k, 0, (n + 1 - k) * sizeof(UNIT));                                                       \
        return body;                                                                                           \
    }                                                                                                          \
    static inline UNIT *__pacst_##P##_copy(UNIT *body, size_t n, const UNIT *from, size_t m) {               \
        size_t k = __pacst_##P##_units(from, m);                                                               \
        if (k > n) k = n;                                                                                      \
        memmove(body, from, k * sizeof(UNIT));                                                                 \
        memset(body + k, 0, (n + 1 - k) * sizeof(UNIT));                                                       \
        return body;                                                                                           \
    }                                                                                                          \
    static inline int __pacst_##P##_eq(const UNIT *a, size_t n, const UNIT *b, size_t m) {                   \
        size_t k = __pacst_##P##_units(a, n);                                                                  \
        return k == __pacst_##P##_units(b, m) && memcmp(a, b, k * sizeof(UNIT)) == 0;                          \
    }                                                                                                          \
    static inline int __pacst_##P##_eq_short(const UNIT *a, size_t n, S s) {                                 \
        size_t k = __pacst_##P##_units(a, n);                                                                  \
        return k == s.len && memcmp(a, s.body, k * sizeof(UNIT)) == 0;                                        \
    }                                                                                                          \
    static inline int __pacst_##P##_cmp(const UNIT *a, size_t n, const UNIT *b, size_t m) {                  \
        return CMP(a, __pacst_##P##_units(a, n), b, __pacst_##P##_units(b, m));                                \
    }                                                                                                          \
    static inline int __pacst_##P##_cmp_short(const UNIT *a, size_t n, S s) {                                \
        return CMP(a, __pacst_##P##_units(a, n), s.body, s.len);                                               \
    }
__PACST_LONG_STRING(STRING, uint8_t, lstr, __pacst_bytes_cmp)
__PACST_LONG_STRING(WSTRING, uint16_t, lwstr, __pacst_words_cmp)

/* The harness defines these two and advances __CURRENT_TIME before each scan. */
extern TIME __CURRENT_TIME;
extern BOOL __DEBUG;

/* Reports a run-time fault of the generated code (array index out of bounds) and aborts: in a test
 * run an out-of-bounds write must never corrupt the simulated PLC silently. Under a model checker
 * (CBMC, docs/verification.md) a fault is a failed property: CBMC takes abort() for the end of a path,
 * which would hide it. */
static inline void __pacst_fault(const char *where, const char *what, long value) {
#ifdef __CPROVER__
    __CPROVER_assert(0, "pacst run-time fault: array index out of bounds");
#endif
    fprintf(stderr, "%s: run-time error: %s (%ld)\n", where, what, value);
    abort();
}

/* Writes `val` to the part `path` (empty, .MEMBER or .table[i]) of a wrapped variable. Only a build that
 * defines PACST_FORCING skips the write when the variable's flags carry the force bit, as MATIEC's
 * __SET_VAR does: the test runtime forces nothing, and the flag's test in every ST assignment cost a load
 * and a branch each (docs/benchmarks.md). PACST_NO_FORCING, the older spelling of the default, wins. */
#if defined(PACST_FORCING) && !defined(PACST_NO_FORCING)
#define __PACST_SETP(var, path, val) \
    do { if (!((var).flags & __IEC_FORCE_FLAG)) (var).value path = (val); } while (0)
#else
#define __PACST_SETP(var, path, val) do { (var).value path = (val); } while (0)
#endif
#define __PACST_SET(var, val) __PACST_SETP(var, , val)

/* The body of an FB that one ST call of the program runs: inlined into that call where the compiler sees both
 * (the translated library compiled as one C unit), still defined for callers from C (its declaration in
 * POUS.h is not inline, so this is the external definition). Only where the compiler optimises: an unoptimised
 * build (the coverage build) keeps one copy of each body, whose counters are the lines' and branches' only
 * ones. The model checker gets the plain function. */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__OPTIMIZE__) && !defined(__CPROVER__)
#define PACST_INLINE_ONCE __attribute__((always_inline)) inline
#else
#define PACST_INLINE_ONCE
#endif

/* Offset of an array element; an index outside the declared bounds stops the run with its position. */
static inline long __pacst_index(long i, long low, long high, const char *where) {
    if (i < low || i > high) __pacst_fault(where, "array index out of bounds", i);
    return i - low;
}

/* Nanoseconds brought into 0..999,999,999, the same result for every input. A sum or a difference of two such
 * TIMEs is within one second of that range and needs one step; only a value further out needs the division.
 * Under a model checker (docs/verification.md) such a value is a failed property instead of a 64-bit divider in
 * the formula of every timer call, which cost most of the proofs 4 to 46 % of their CPU. */
static inline TIME __time_norm(pacst_time_field sec, pacst_time_field nsec) {
    const pacst_time_field second = 1000000000;
    TIME t;
    if (nsec >= 0 && nsec < second) {
        t.tv_sec = sec;
        t.tv_nsec = nsec;
    } else if (nsec < 0 && nsec > -second) {
        t.tv_sec = sec - 1;
        t.tv_nsec = nsec + second;
    } else if (nsec >= second && nsec - second < second) {
        t.tv_sec = sec + 1;
        t.tv_nsec = nsec - second;
    } else {
#ifdef __CPROVER__
        __CPROVER_assert(0, "pacst run-time fault: TIME nanoseconds more than one second out of range");
        __CPROVER_assume(0);
#endif
        t.tv_sec = sec + nsec / second;
        t.tv_nsec = nsec % second;
        if (t.tv_nsec < 0) { t.tv_nsec += second; t.tv_sec -= 1; }
    }
    return t;
}
static inline TIME __time_make(long sec, long nsec) {
#ifdef PACST_CBMC_TIME32
    __CPROVER_assert(sec >= INT32_MIN && sec <= INT32_MAX && nsec >= INT32_MIN && nsec <= INT32_MAX,
                     "pacst run-time fault: TIME beyond the model checker's 32-bit fields");
#endif
    return __time_norm((pacst_time_field)sec, (pacst_time_field)nsec);
}
static inline TIME __time_add(TIME a, TIME b) {
    return __time_norm((pacst_time_field)(a.tv_sec + b.tv_sec), (pacst_time_field)(a.tv_nsec + b.tv_nsec));
}
static inline TIME __time_sub(TIME a, TIME b) {
    return __time_norm((pacst_time_field)(a.tv_sec - b.tv_sec), (pacst_time_field)(a.tv_nsec - b.tv_nsec));
}
static inline int __time_cmp(TIME a, TIME b) {
    if (a.tv_sec != b.tv_sec) return a.tv_sec < b.tv_sec ? -1 : 1;
    if (a.tv_nsec != b.tv_nsec) return a.tv_nsec < b.tv_nsec ? -1 : 1;
    return 0;
}

/* Integer division and modulo as IEC defines them (truncation toward zero, MOD with the sign of the
 * dividend). A zero divisor gives 0 instead of a trap, and the one overflowing quotient (most negative
 * value / -1) wraps like every other overflow. */
#define __PACST_DIVMOD(T, W)                                                        \
    static inline T __div_##T(T a, T b) { return b == 0 ? (T)0 : (T)((W)a / (W)b); } \
    static inline T __mod_##T(T a, T b) { return b == 0 ? (T)0 : (T)((W)a % (W)b); }
__PACST_DIVMOD(SINT, int64_t)
__PACST_DIVMOD(INT, int64_t)
__PACST_DIVMOD(DINT, int64_t)
__PACST_DIVMOD(USINT, uint64_t)
__PACST_DIVMOD(UINT, uint64_t)
__PACST_DIVMOD(UDINT, uint64_t)
__PACST_DIVMOD(BYTE, uint64_t)
__PACST_DIVMOD(WORD, uint64_t)
__PACST_DIVMOD(DWORD, uint64_t)
__PACST_DIVMOD(ULINT, uint64_t)
__PACST_DIVMOD(LWORD, uint64_t)
/* LINT: the most negative value / -1 wraps (a 64-bit C division would trap). */
static inline LINT __div_LINT(LINT a, LINT b) {
    return b == 0 ? (LINT)0 : b == -1 ? (LINT)(0u - (uint64_t)a) : a / b;
}
static inline LINT __mod_LINT(LINT a, LINT b) { return (b == 0 || b == -1) ? (LINT)0 : a % b; }

/* Shifts and rotations of bit strings; a count outside 0..width-1 shifts every bit out. */
#define __PACST_SHIFT(T, BITS)                                                                          \
    static inline T __shl_##T(T v, long n) { return (n < 0 || n >= BITS) ? (T)0 : (T)((uint64_t)v << n); } \
    static inline T __shr_##T(T v, long n) { return (n < 0 || n >= BITS) ? (T)0 : (T)((uint64_t)v >> n); } \
    static inline T __rol_##T(T v, long n) {                                                             \
        n = ((n % BITS) + BITS) % BITS;                                                                  \
        return n == 0 ? v : (T)(((uint64_t)v << n) | ((uint64_t)v >> (BITS - n)));                      \
    }                                                                                                    \
    static inline T __ror_##T(T v, long n) { return __rol_##T(v, BITS - ((n % BITS) + BITS) % BITS); }
__PACST_SHIFT(BYTE, 8)
__PACST_SHIFT(WORD, 16)
__PACST_SHIFT(DWORD, 32)
__PACST_SHIFT(LWORD, 64)
/* SHR of a signed integer (user programs): the sign bit shifted in, as CODESYS describes SHR on signed types; a
 * count of the width or more leaves the sign bits alone (-1 or 0). The complement keeps the C shift unsigned. */
#define __PACST_SAR(T, W)                                                                                \
    static inline T __sar_##T(T v, long n) { return v < 0 ? (T)~__shr_##W((W)~v, n) : (T)__shr_##W((W)v, n); }
__PACST_SAR(SINT, BYTE)
__PACST_SAR(INT, WORD)
__PACST_SAR(DINT, DWORD)
__PACST_SAR(LINT, LWORD)

/* ABS for signed types (unsigned ones are their own ABS); MIN, MAX and LIMIT for every numeric and
 * bit-string type. */
#define __PACST_ABS(T) static inline T __abs_##T(T a) { return a < 0 ? (T)-a : a; }
__PACST_ABS(SINT)
__PACST_ABS(INT)
__PACST_ABS(DINT)
__PACST_ABS(LINT)
__PACST_ABS(REAL)
__PACST_ABS(LREAL)
#define __PACST_NUMERIC(T)                                                                   \
    static inline T __min_##T(T a, T b) { return b < a ? b : a; }                            \
    static inline T __max_##T(T a, T b) { return b > a ? b : a; }                            \
    static inline T __limit_##T(T mn, T in, T mx) { return in < mn ? mn : (in > mx ? mx : in); }
__PACST_NUMERIC(SINT)
__PACST_NUMERIC(INT)
__PACST_NUMERIC(DINT)
__PACST_NUMERIC(USINT)
__PACST_NUMERIC(UINT)
__PACST_NUMERIC(UDINT)
__PACST_NUMERIC(BYTE)
__PACST_NUMERIC(WORD)
__PACST_NUMERIC(DWORD)
__PACST_NUMERIC(LINT)
__PACST_NUMERIC(ULINT)
__PACST_NUMERIC(LWORD)
__PACST_NUMERIC(REAL)
__PACST_NUMERIC(LREAL)

/* REAL/LREAL to integer: round half to even (IEC); a negative value to an unsigned type gives 0;
 * NaN gives 0; a value beyond 64 bits saturates before it wraps to the target width. */
static inline int64_t __real_to_i64(double r) {
    double n;
    if (r != r) return 0;
    n = nearbyint(r);
    if (n >= 9223372036854775807.0) return INT64_MAX;
    if (n <= -9223372036854775808.0) return INT64_MIN;
    return (int64_t)n;
}
static inline uint64_t __real_to_u64(double r) {
    int64_t v = __real_to_i64(r);
    return v < 0 ? 0u : (uint64_t)v;
}

/* Standard function blocks with MATIEC's member names and timing: TON/TOF/TP read __CURRENT_TIME;
 * TON never sets Q in the call that sees IN rise, F_TRIG gives Q on its first call with CLK FALSE.
 * <FB>_body_lean__ is the body without the EN test and ENO write: the library's calls, whose EN no ST can reach. */
/* <FB>_body__: the EN test and ENO write of IEC 61131-3 around <FB>_body_lean__, for calls whose EN may be FALSE. */
#define __PACST_EN_BODY(FB)                                           \
    static inline void FB##_body__(FB *d) {                           \
        if (!d->EN.value) { d->ENO.value = FALSE; return; }           \
        d->ENO.value = TRUE;                                          \
        FB##_body_lean__(d);                                          \
    }
typedef struct {
    __IEC_BOOL_t EN, ENO, CLK, Q, M;
} R_TRIG;
typedef R_TRIG F_TRIG;
typedef struct {
    __IEC_BOOL_t EN, ENO, IN;
    __IEC_TIME_t PT;
    __IEC_BOOL_t Q;
    __IEC_TIME_t ET;
    __IEC_SINT_t STATE;
    __IEC_BOOL_t PREV_IN;
    __IEC_TIME_t CURRENT_TIME, START_TIME;
} TON;
typedef TON TOF;
typedef TON TP;

static inline void R_TRIG_init__(R_TRIG *d, BOOL retain) {
    (void)retain;
    d->EN.value = TRUE; d->ENO.value = TRUE; d->CLK.value = FALSE; d->Q.value = FALSE; d->M.value = FALSE;
}
static inline void F_TRIG_init__(F_TRIG *d, BOOL retain) { R_TRIG_init__(d, retain); }
static inline void R_TRIG_body_lean__(R_TRIG *d) {
    __PACST_SET(d->Q, d->CLK.value && !d->M.value);
    __PACST_SET(d->M, d->CLK.value);
}
__PACST_EN_BODY(R_TRIG)
static inline void F_TRIG_body_lean__(F_TRIG *d) {
    __PACST_SET(d->Q, !d->CLK.value && !d->M.value);
    __PACST_SET(d->M, !d->CLK.value);
}
__PACST_EN_BODY(F_TRIG)

static inline void TON_init__(TON *d, BOOL retain) {
    const TIME zero = {0, 0};
    (void)retain;
    d->EN.value = TRUE; d->ENO.value = TRUE; d->IN.value = FALSE; d->PT.value = zero;
    d->Q.value = FALSE; d->ET.value = zero; d->STATE.value = 0; d->PREV_IN.value = FALSE;
    d->CURRENT_TIME.value = zero; d->START_TIME.value = zero;
}
static inline void TOF_init__(TOF *d, BOOL retain) { TON_init__(d, retain); }
static inline void TP_init__(TP *d, BOOL retain) { TON_init__(d, retain); }

/* STATE: 0 idle, 1 timing, 2 elapsed (MATIEC's encoding). While timing, ET follows the time since the
 * start; once PT has passed, STATE becomes 2, ET stays at PT and the caller sets Q. */
static inline int __pacst_timer_elapsed(TON *d) {
    const TIME elapsed = __time_sub(d->CURRENT_TIME.value, d->START_TIME.value);
    if (__time_cmp(elapsed, d->PT.value) >= 0) {  /* START_TIME + PT <= CURRENT_TIME, one subtraction */
        __PACST_SET(d->STATE, 2);
        __PACST_SET(d->ET, d->PT.value);
        return 1;
    }
    __PACST_SET(d->ET, elapsed);
    return 0;
}

static inline void TON_body_lean__(TON *d) {
    const TIME zero = {0, 0};
    __PACST_SET(d->CURRENT_TIME, __CURRENT_TIME);
    if (d->STATE.value == 0 && !d->PREV_IN.value && d->IN.value) {
        __PACST_SET(d->STATE, 1);
        __PACST_SET(d->Q, FALSE);
        __PACST_SET(d->START_TIME, d->CURRENT_TIME.value);
    } else if (!d->IN.value) {
        __PACST_SET(d->ET, zero);
        __PACST_SET(d->Q, FALSE);
        __PACST_SET(d->STATE, 0);
    } else if (d->STATE.value == 1 && __pacst_timer_elapsed(d)) {
        __PACST_SET(d->Q, TRUE);
    }
    __PACST_SET(d->PREV_IN, d->IN.value);
}
__PACST_EN_BODY(TON)

static inline void TOF_body_lean__(TOF *d) {
    const TIME zero = {0, 0};
    __PACST_SET(d->CURRENT_TIME, __CURRENT_TIME);
    if (d->STATE.value == 0 && d->PREV_IN.value && !d->IN.value) {
        __PACST_SET(d->STATE, 1);
        __PACST_SET(d->START_TIME, d->CURRENT_TIME.value);
    } else if (d->IN.value) {
        __PACST_SET(d->ET, zero);
        __PACST_SET(d->STATE, 0);
    } else if (d->STATE.value == 1) {
        __pacst_timer_elapsed(d);
    }
    __PACST_SET(d->Q, d->IN.value || d->STATE.value == 1);
    __PACST_SET(d->PREV_IN, d->IN.value);
}
__PACST_EN_BODY(TOF)

static inline void TP_body_lean__(TP *d) {
    const TIME zero = {0, 0};
    __PACST_SET(d->CURRENT_TIME, __CURRENT_TIME);
    if (d->STATE.value == 0 && !d->PREV_IN.value && d->IN.value) {
        __PACST_SET(d->STATE, 1);
        __PACST_SET(d->Q, TRUE);
        __PACST_SET(d->START_TIME, d->CURRENT_TIME.value);
    } else if (d->STATE.value == 1 && __pacst_timer_elapsed(d)) {
        __PACST_SET(d->Q, FALSE);
    }
    if (d->STATE.value == 2 && !d->IN.value) {
        __PACST_SET(d->ET, zero);
        __PACST_SET(d->STATE, 0);
    }
    __PACST_SET(d->PREV_IN, d->IN.value);
}
__PACST_EN_BODY(TP)

/* User programs (pacst --user): TIME as milliseconds (TIME_TO_DINT, DINT_TO_TIME, as CODESYS and
 * TwinCAT count it), TIME * and / a number, TRUNC, and the counters and bistables with the pin names of
 * CODESYS's Standard and TwinCAT's Tc2_Standard. */
/* A pointer or reference read or written through (user mode): a null one stops the run at its ST line. */
static inline void *__pacst_ptr(void *p, const char *where) {
    if (p == NULL) __pacst_fault(where, "a null POINTER or an unset REFERENCE read or written through", 0);
    return p;
}
/* TwinCAT's __NEW and __DELETE (user mode): blocks of the C heap, at most PACST_HEAP_BYTES of them at once
 * (TwinCAT takes them from its router memory, whose size is configured): __NEW returns NULL when the program
 * holds that much already, as TwinCAT's returns 0 when the router memory is exhausted. The blocks are kept in
 * a list, so that __DELETE of a pointer __NEW did not return stops the run with its ST line. One list for
 * every C file of the program: weak definitions, which the linker merges. */
#ifndef __CPROVER__
#ifndef PACST_HEAP_BYTES
#define PACST_HEAP_BYTES (4UL * 1024UL * 1024UL)
#endif
typedef struct __pacst_block {
    struct __pacst_block *prev, *next;
    size_t size, unused; /* four words: the memory after the header keeps malloc's alignment */
} __pacst_block;
__attribute__((weak)) __pacst_block *__pacst_heap_blocks = NULL;
__attribute__((weak)) size_t __pacst_heap_used = 0;
static inline void *__pacst_new(size_t size, long long n) {
    __pacst_block *b;
    if (n < 1 || size == 0 || (unsigned long long)n > (PACST_HEAP_BYTES - __pacst_heap_used) / size) return NULL;
    b = (__pacst_block *)calloc(1, sizeof(__pacst_block) + (size_t)n * size);
    if (b == NULL) return NULL;
    b->size = (size_t)n * size;
    b->next = __pacst_heap_blocks;
    if (b->next != NULL) b->next->prev = b;
    __pacst_heap_blocks = b;
    __pacst_heap_used += b->size;
    return b + 1;
}
static inline __pacst_block *__pacst_heap_find(void *p, const char *where) {
    __pacst_block *b;
    for (b = __pacst_heap_blocks; b != NULL; b = b->next)
        if ((void *)(b + 1) == p) return b;
    __pacst_fault(where, "__DELETE of a pointer that __NEW did not return, or deleted already", 0);
    return NULL;
}
/* `p` when __NEW returned it (FB_exit is called on it before __DELETE frees it) */
static inline void *__pacst_heap_block(void *p, const char *where) {
    (void)__pacst_heap_find(p, where);
    return p;
}
static inline void __pacst_delete(void *p, const char *where) {
    __pacst_block *b = __pacst_heap_find(p, where);
    if (b->prev != NULL) b->prev->next = b->next; else __pacst_heap_blocks = b->next;
    if (b->next != NULL) b->next->prev = b->prev;
    __pacst_heap_used -= b->size;
    free(b);
}
/* Tc2_System's F_CheckMemoryArea (pac-test's vendor ST): 2 (Dynamic) for `n` bytes at `p` inside one block __NEW
 * returned, 0 (Unknown) for a null pointer or bytes reaching past such a block, else 1 (Static). */
static inline UDINT __pacst_memory_area(const void *p, size_t n) {
    const __pacst_block *b;
    if (p == NULL) return 0;
    for (b = __pacst_heap_blocks; b != NULL; b = b->next) {
        const char *start = (const char *)(b + 1), *at = (const char *)p;
        if (at >= start && at < start + b->size) return (size_t)(start + b->size - at) >= n ? 2 : 0;
    }
    return 1;
}
#endif
static inline DINT __pacst_memcmp(const void *a, const void *b, size_t n) {
    int c = memcmp(a, b, n);
    return c < 0 ? -1 : c > 0;
}
static inline int64_t __time_to_ms(TIME t) {
    return (int64_t)t.tv_sec * 1000 + (int64_t)(t.tv_nsec / 1000000);
}
static inline TIME __time_from_ms(int64_t ms) {
    return __time_make((long)(ms / 1000), (long)((ms % 1000) * 1000000));
}
/* LTIME (user programs) is a TIME here too, converted to and from nanoseconds as TwinCAT and CODESYS count
 * it: unsigned 64 bits (LTIME_TO_ULINT, ULINT_TO_LTIME). */
static inline uint64_t __time_to_ns(TIME t) {
    return (uint64_t)t.tv_sec * 1000000000u + (uint64_t)t.tv_nsec;
}
static inline TIME __time_from_ns(uint64_t ns) {
    return __time_make((long)(ns / 1000000000u), (long)(ns % 1000000000u));
}
/* User mode: TIME_TO_STRING and LTIME_TO_STRING as TwinCAT writes them (T#1h30m5s, LTIME#1s2us44ns: the units
 * that are not 0, T#0ms for 0), and the date types' literals (D#2002-08-18, DT#1998-02-13-14:20:00,
 * TOD#14:01:05.123 with the milliseconds when there are any). */
static inline STRING __pacst_text(const char *text) {
    return __pacst_string(text, (int)strlen(text));
}
static inline STRING __pacst_time_to_string(TIME t, int nanoseconds) {
    static const char *const units[] = {"d", "h", "m", "s", "ms", "us", "ns"};
    const uint64_t per[] = {86400000000000ull, 3600000000000ull, 60000000000ull, 1000000000ull, 1000000ull,
                            1000ull, 1ull};
    char text[96];
    int n = snprintf(text, sizeof text, "%s", nanoseconds ? "LTIME#" : "T#"), u, any = 0;
    uint64_t ns = nanoseconds ? __time_to_ns(t) : (uint64_t)(uint32_t)__time_to_ms(t) * 1000000ull;
    for (u = 0; u < (nanoseconds ? 7 : 5); u++) {
        if (ns / per[u] == 0) continue;
        n += snprintf(text + n, sizeof text - (size_t)n, "%llu%s", (unsigned long long)(ns / per[u]), units[u]);
        ns %= per[u];
        any = 1;
    }
    if (!any) snprintf(text + n, sizeof text - (size_t)n, "0%s", nanoseconds ? "ns" : "ms");
    return __pacst_text(text);
}
static inline UDINT __pacst_dt_to_date(UDINT dt) {
    return dt - dt % 86400u;
}
/* kind: 0 DATE, 1 TIME_OF_DAY, 2 DATE_AND_TIME; a DATE or DT counts seconds since 1970, a TOD milliseconds. */
static inline STRING __pacst_date_to_string(uint32_t v, int kind) {
    char text[48];
    if (kind == 1) {
        unsigned ms = v % 1000u, s = v / 1000u;
        int n = snprintf(text, sizeof text, "TOD#%02u:%02u:%02u", s / 3600u, s / 60u % 60u, s % 60u);
        if (ms != 0u) snprintf(text + n, sizeof text - (size_t)n, ".%03u", ms);
    } else {
        /* the Gregorian date of a day count since 1970-01-01, in eras of 400 years from 0000-03-01 */
        long z = (long)(v / 86400u) + 719468L, era = z / 146097L, doe = z - era * 146097L;
        long yoe = (doe - doe / 1460L + doe / 36524L - doe / 146096L) / 365L;
        long doy = doe - (365L * yoe + yoe / 4L - yoe / 100L), mp = (5L * doy + 2L) / 153L;
        long day = doy - (153L * mp + 2L) / 5L + 1L, month = mp < 10L ? mp + 3L : mp - 9L;
        long year = yoe + era * 400L + (month <= 2L);
        unsigned s = v % 86400u;
        if (kind == 0)
            snprintf(text, sizeof text, "D#%04ld-%02ld-%02ld", year, month, day);
        else
            snprintf(text, sizeof text, "DT#%04ld-%02ld-%02ld-%02u:%02u:%02u", year, month, day, s / 3600u,
                     s / 60u % 60u, s % 60u);
    }
    return __pacst_text(text);
}
/* User mode: STRING_TO_TIME and _LTIME read a duration literal as TwinCAT's help writes it: after spaces, T#, TIME#,
 * LT# or LTIME# in any case, then numbers with the units d h m s ms us ns ('_' between digits, a fraction:
 * T#1.5s); text that is no such literal gives 0, as text before a number does. Nanoseconds. */
static inline uint64_t __pacst_string_to_ns(STRING s) {
    static const char *const prefixes[] = {"LTIME#", "TIME#", "LT#", "T#"};
    static const char *const units[] = {"MS", "US", "NS", "D", "H", "M", "S"};  /* MS before M */
    static const uint64_t per[] = {1000000ull, 1000ull, 1ull, 86400000000000ull, 3600000000000ull, 60000000000ull,
                                   1000000000ull};
    uint64_t ns = 0u;
    int i = 0, p = 0, u;
    while (i < s.len && s.body[i] == ' ') i++;
    while (p < 4 && !__pacst_string_word(s, i, prefixes[p])) p++;
    if (p == 4) return 0u;
    for (i += (int)strlen(prefixes[p]); i < s.len;) {
        uint64_t whole = 0u;
        double fraction = 0.0, scale = 0.1;
        int digits = 0;
        for (; i < s.len && ((s.body[i] >= '0' && s.body[i] <= '9') || (s.body[i] == '_' && digits)); i++)
            if (s.body[i] != '_') whole = whole * 10u + (uint64_t)(s.body[i] - '0'), digits++;
        if (!digits) break;
        if (i + 1 < s.len && s.body[i] == '.' && s.body[i + 1] >= '0' && s.body[i + 1] <= '9')
            for (i++; i < s.len && s.body[i] >= '0' && s.body[i] <= '9'; i++, scale /= 10.0)
                fraction += (double)(s.body[i] - '0') * scale;
        for (u = 0; u < 7 && !__pacst_string_word(s, i, units[u]); u++) {}
        if (u == 7) break;
        i += (int)strlen(units[u]);
        ns += whole * per[u] + (uint64_t)(fraction * (double)per[u] + 0.5);
    }
    return ns;
}
/* The number of days from 1970-01-01 to the Gregorian date y-m-d (the inverse of __pacst_date_to_string's). */
static inline long __pacst_days_from_civil(long y, long m, long d) {
    long era, yoe, doy, doe;
    y -= m <= 2L;
    era = (y >= 0L ? y : y - 399L) / 400L;
    yoe = y - era * 400L;
    doy = (153L * (m > 2L ? m - 3L : m + 9L) + 2L) / 5L + d - 1L;
    doe = yoe * 365L + yoe / 4L - yoe / 100L + doy;
    return era * 146097L + doe - 719468L;
}
/* STRING_TO_DATE, _TOD and _DT read the literal of the type (kind 0 D# or DATE#, 1 TOD# or TIME_OF_DAY#, 2 DT# or
 * DATE_AND_TIME#, in any case) after spaces, as __pacst_date_to_string writes it (seconds may be left out, a
 * fraction of a second is kept by TOD only); text that is no such literal gives 0. */
static inline UDINT __pacst_string_to_date(STRING s, int kind) {
    static const char *const prefixes[3][2] = {{"DATE#", "D#"}, {"TIME_OF_DAY#", "TOD#"},
                                               {"DATE_AND_TIME#", "DT#"}};
    long part[6] = {0L, 0L, 0L, 0L, 0L, 0L};
    double fraction = 0.0, scale = 0.1;
    int i = 0, p = 0, n = 0, first = kind == 1 ? 3 : 0, last = kind == 0 ? 3 : 6;
    while (i < s.len && s.body[i] == ' ') i++;
    while (p < 2 && !__pacst_string_word(s, i, prefixes[kind][p])) p++;
    if (p == 2) return 0u;
    for (i += (int)strlen(prefixes[kind][p]), n = first; n < last; n++) {
        int digits = 0;
        for (; i < s.len && s.body[i] >= '0' && s.body[i] <= '9'; i++, digits++)
            part[n] = part[n] * 10L + (long)(s.body[i] - '0');
        if (!digits) return 0u;
        if (i >= s.len || s.body[i] != (n <= 2 ? '-' : ':') || n == last - 1) break;
        i++;
    }
    if (n < last - 1 && !(n >= 4 && n == last - 2)) return 0u;  /* a date needs all three, a time hours and minutes */
    if (i + 1 < s.len && s.body[i] == '.' && n == 5)
        for (i++; i < s.len && s.body[i] >= '0' && s.body[i] <= '9'; i++, scale /= 10.0)
            fraction += (double)(s.body[i] - '0') * scale;
    if (kind == 1)
        return (UDINT)((part[3] * 3600L + part[4] * 60L + part[5]) * 1000L + (long)(fraction * 1000.0 + 0.5));
    return (UDINT)(__pacst_days_from_civil(part[0], part[1], part[2]) * 86400L + part[3] * 3600L + part[4] * 60L
                   + part[5]);
}
static inline TIME __time_scale(TIME t, double factor) {
    double ns = ((double)t.tv_sec * 1e9 + (double)t.tv_nsec) * factor;
    int64_t n = (int64_t)ns;
    return __time_make((long)(n / 1000000000), (long)(n % 1000000000));
}
static inline int64_t __trunc_i64(double r) {
    if (r != r) return 0;
    if (r >= 9223372036854775807.0) return INT64_MAX;
    if (r <= -9223372036854775808.0) return INT64_MIN;
    return (int64_t)r;
}

typedef struct {
    __IEC_BOOL_t EN, ENO, CU, RESET;
    __IEC_WORD_t PV;
    __IEC_BOOL_t Q;
    __IEC_WORD_t CV;
    __IEC_BOOL_t MU;
} CTU;
static inline void CTU_init__(CTU *d, BOOL retain) {
    (void)retain;
    d->EN.value = TRUE; d->ENO.value = TRUE;
    d->CU.value = FALSE; d->RESET.value = FALSE; d->PV.value = 0; d->Q.value = FALSE; d->CV.value = 0;
    d->MU.value = FALSE;
}
static inline void CTU_body_lean__(CTU *d) {
    if (d->RESET.value) {
        __PACST_SET(d->CV, 0);
    } else if (d->CU.value && !d->MU.value && d->CV.value < 0xFFFF) {
        __PACST_SET(d->CV, (WORD)(d->CV.value + 1));
    }
    __PACST_SET(d->Q, d->CV.value >= d->PV.value);
    __PACST_SET(d->MU, d->CU.value);
}
__PACST_EN_BODY(CTU)
typedef struct {
    __IEC_BOOL_t EN, ENO, CD, LOAD;
    __IEC_WORD_t PV;
    __IEC_BOOL_t Q;
    __IEC_WORD_t CV;
    __IEC_BOOL_t MD;
} CTD;
static inline void CTD_init__(CTD *d, BOOL retain) {
    (void)retain;
    d->EN.value = TRUE; d->ENO.value = TRUE;
    d->CD.value = FALSE; d->LOAD.value = FALSE; d->PV.value = 0; d->Q.value = FALSE; d->CV.value = 0;
    d->MD.value = FALSE;
}
static inline void CTD_body_lean__(CTD *d) {
    if (d->LOAD.value) {
        __PACST_SET(d->CV, d->PV.value);
    } else if (d->CD.value && !d->MD.value && d->CV.value > 0) {
        __PACST_SET(d->CV, (WORD)(d->CV.value - 1));
    }
    __PACST_SET(d->Q, d->CV.value == 0);
    __PACST_SET(d->MD, d->CD.value);
}
__PACST_EN_BODY(CTD)
typedef struct {
    __IEC_BOOL_t EN, ENO, CU, CD, RESET, LOAD;
    __IEC_WORD_t PV;
    __IEC_BOOL_t QU, QD;
    __IEC_WORD_t CV;
    __IEC_BOOL_t MU, MD;
} CTUD;
static inline void CTUD_init__(CTUD *d, BOOL retain) {
    (void)retain;
    d->EN.value = TRUE; d->ENO.value = TRUE;
    d->CU.value = FALSE; d->CD.value = FALSE; d->RESET.value = FALSE; d->LOAD.value = FALSE; d->PV.value = 0;
    d->QU.value = FALSE; d->QD.value = FALSE; d->CV.value = 0; d->MU.value = FALSE; d->MD.value = FALSE;
}
static inline void CTUD_body_lean__(CTUD *d) {
    if (d->RESET.value) {
        __PACST_SET(d->CV, 0);
    } else if (d->LOAD.value) {
        __PACST_SET(d->CV, d->PV.value);
    } else {
        if (d->CU.value && !d->MU.value && d->CV.value < 0xFFFF) __PACST_SET(d->CV, (WORD)(d->CV.value + 1));
        if (d->CD.value && !d->MD.value && d->CV.value > 0) __PACST_SET(d->CV, (WORD)(d->CV.value - 1));
    }
    __PACST_SET(d->QU, d->CV.value >= d->PV.value);
    __PACST_SET(d->QD, d->CV.value == 0);
    __PACST_SET(d->MU, d->CU.value);
    __PACST_SET(d->MD, d->CD.value);
}
__PACST_EN_BODY(CTUD)
typedef struct {
    __IEC_BOOL_t EN, ENO, SET1, RESET, Q1;
} SR;
static inline void SR_init__(SR *d, BOOL retain) {
    (void)retain;
    d->EN.value = TRUE; d->ENO.value = TRUE; d->SET1.value = FALSE; d->RESET.value = FALSE; d->Q1.value = FALSE;
}
static inline void SR_body_lean__(SR *d) {
    __PACST_SET(d->Q1, d->SET1.value || (!d->RESET.value && d->Q1.value));
}
__PACST_EN_BODY(SR)
typedef struct {
    __IEC_BOOL_t EN, ENO, SET, RESET1, Q1;
} RS;
static inline void RS_init__(RS *d, BOOL retain) {
    (void)retain;
    d->EN.value = TRUE; d->ENO.value = TRUE; d->SET.value = FALSE; d->RESET1.value = FALSE; d->Q1.value = FALSE;
}
static inline void RS_body_lean__(RS *d) {
    __PACST_SET(d->Q1, !d->RESET1.value && (d->SET.value || d->Q1.value));
}
__PACST_EN_BODY(RS)

#ifdef __cplusplus
}
#endif

#endif /* PACST_IEC_H */
