/* ladderc runtime: IEC 61131-3 elementary types, standard function blocks, standard-function helpers,
 * the process image (%I/%Q/%M byte areas with byte-order-aware load/store) and the scan clock.
 *
 * C99, no undefined behaviour for any input: integer arithmetic wraps like the IEC type's width
 * (computed in unsigned arithmetic, converted back without implementation-defined casts), division and
 * modulo by zero give 0 and set LADDERC_ERR_DIV_ZERO in ladderc_errors, REAL to integer conversions
 * round to nearest with halves to even and saturate (NaN gives 0) and set LADDERC_ERR_RANGE when they
 * saturate; LREAL to REAL overflows to an infinity without an out-of-range cast.
 *
 * The generated program supplies ladderc_config.h (the target profile as macros) and the definitions of
 * the areas, the variable table, ladderc_program_init() and ladderc_program_scan().
 */
#ifndef LADDERC_RT_H
#define LADDERC_RT_H

#include <stdint.h>
#include <stddef.h>
#include <string.h>
#include <math.h>

#include "ladderc_config.h"

#ifndef LADDERC_I_SIZE
#error "ladderc_config.h must define LADDERC_I_SIZE"
#endif
/* The bytes flat addresses (`%IW3`) reach; the rest of an area holds the slots of hierarchical
   addresses (`%IX1.0.0`), which the watch table names. */
#ifndef LADDERC_PER_SIZE_IO
#define LADDERC_PER_SIZE_IO 0
#endif
#ifndef LADDERC_PER_SIZE_M
#define LADDERC_PER_SIZE_M 0
#endif
#ifndef LADDERC_I_FLAT_SIZE
#define LADDERC_I_FLAT_SIZE LADDERC_I_SIZE
#endif
#ifndef LADDERC_Q_FLAT_SIZE
#define LADDERC_Q_FLAT_SIZE LADDERC_Q_SIZE
#endif
#ifndef LADDERC_M_FLAT_SIZE
#define LADDERC_M_FLAT_SIZE LADDERC_M_SIZE
#endif
/* The nanoseconds of one unit of a number converted to or from TIME (the profile's
   `time_number_unit`: milliseconds by default, seconds under the OpenPLC profile). */
#ifndef LADDERC_TIME_UNIT_NS
#define LADDERC_TIME_UNIT_NS INT64_C(1000000)
#endif
/* Whether a real number converted to TIME is rounded to whole units first (1 under milliseconds:
   TIME is a count of milliseconds in CODESYS and TwinCAT, REAL_TO_TIME(1.5) is T#2ms; 0 under
   seconds, matiec's __real_to_time keeps the fraction). LTIME always keeps its nanoseconds. */
#ifndef LADDERC_REAL_TO_TIME_WHOLE_UNITS
#define LADDERC_REAL_TO_TIME_WHOLE_UNITS 1
#endif

/* ------------------------------------------------------------------ elementary types */
typedef uint8_t IEC_BOOL; /* always 0 or 1 */
typedef int8_t IEC_SINT;
typedef int16_t IEC_INT;
typedef int32_t IEC_DINT;
typedef int64_t IEC_LINT;
typedef uint8_t IEC_USINT;
typedef uint16_t IEC_UINT;
typedef uint32_t IEC_UDINT;
typedef uint64_t IEC_ULINT;
typedef uint8_t IEC_BYTE;
typedef uint16_t IEC_WORD;
typedef uint32_t IEC_DWORD;
typedef uint64_t IEC_LWORD;
typedef float IEC_REAL;
typedef double IEC_LREAL;
typedef int64_t IEC_TIME;  /* nanoseconds */
typedef int64_t IEC_LTIME; /* nanoseconds */
typedef int64_t IEC_DATE;  /* nanoseconds since 1970-01-01 (always a whole day) */
typedef int64_t IEC_TOD;   /* nanoseconds since midnight */
typedef int64_t IEC_DT;    /* nanoseconds since 1970-01-01T00:00:00 */
typedef int64_t IEC_LDATE; /* edition 3: as IEC_DATE */
typedef int64_t IEC_LTOD;  /* edition 3: as IEC_TOD */
typedef int64_t IEC_LDT;   /* edition 3: as IEC_DT */
typedef uint8_t IEC_CHAR;  /* edition 3: a STRING's character (ISO 8859-1 code) */
typedef uint16_t IEC_WCHAR; /* edition 3: a WSTRING's character (UCS-2 code) */

#define LADDERC_STRING_CAP 254
typedef struct {
    uint16_t len;
    char data[LADDERC_STRING_CAP + 1]; /* always NUL-terminated */
} IEC_STRING;
typedef struct {
    uint16_t len;
    uint16_t data[LADDERC_STRING_CAP + 1];
} IEC_WSTRING;

/* A reference (REF_TO, POINTER TO, REFERENCE TO), bounded: the variable it was made from (`base`, its
 * address, NULL for NULL; `size`, its bytes) and the byte offset `off` into it that pointer arithmetic and
 * indexing moved to (0 as made by REF/ADR). Every access through it goes through ladderc_deref, which
 * checks `off` against `size`, so no reference reaches outside the variable it was made from. */
typedef struct {
    unsigned char *base;
    uint32_t size;
    int32_t off;
} IEC_REF;

/* ------------------------------------------------------------------ runtime state */
#define LADDERC_ERR_DIV_ZERO 1u /* integer DIV or MOD by zero: result 0 */
#define LADDERC_ERR_RANGE 2u    /* REAL to integer conversion out of range or NaN, or a value outside a subrange stored into it: saturated */
#define LADDERC_ERR_BOUNDS 4u   /* array index out of its declared range: element 0 used instead */
#define LADDERC_ERR_STRING 8u   /* string truncated to its capacity */
#define LADDERC_ERR_STRPOS 16u  /* string function length or position out of range (ladderc_strings.c) */
#define LADDERC_ERR_MUX 32u     /* MUX selector K outside 0..n-1: IN0 selected */
#define LADDERC_ERR_NULL_REF 64u /* a NULL reference dereferenced: zero read, write dropped */
#define LADDERC_ERR_MEM 128u     /* MEMCPY/MEMMOVE/MEMSET/MEMCMP count beyond its variables: clipped */
#define LADDERC_ERR_POINTER 256u /* a pointer moved outside its variable dereferenced: zero read, write dropped */
#define LADDERC_ERR_CHAR_INDEX 512u /* s[i] of a STRING/WSTRING outside 1..LEN(s): NUL read, write dropped */

extern uint32_t ladderc_errors;  /* sticky error flags, LADDERC_ERR_* */
extern IEC_TIME ladderc_now;     /* the scan clock: nanoseconds since start, set before each cycle */
extern uint64_t ladderc_cycle;   /* the current cycle number, from 0 */
extern const char *ladderc_null_ref_site; /* where the first NULL reference was dereferenced */
extern const char *ladderc_mem_site;      /* where the first memory function count was clipped */
extern const char *ladderc_bounds_site;   /* where the first array index out of range was used */
extern int64_t ladderc_bounds_at[3];       /* that index, and the lower and upper bounds it missed */
extern const char *ladderc_pointer_site;  /* where the first pointer outside its variable was dereferenced */
extern const char *ladderc_char_index_site; /* where the first character index outside its string was used */
extern int64_t ladderc_char_index_at[3];    /* that index and the range it was outside then */

/* The loop guard. Every jump back in the generated code (the end of a WHILE, REPEAT or FOR pass, an IL
 * jump to an earlier label) passes LADDERC_LOOP_GUARD(file, start, end) with the source span of the
 * loop. `ladderc run` compiles with -DLADDERC_LOOP_LIMIT=N: the harness (ladderc_main.c) then counts the
 * jumps back of each scan and, past N, reports the span (`ladderc_loop_stuck`) and stops the run, as a
 * controller's watchdog stops a task whose cycle never ends. Without the definition (a build for a
 * controller) the guard is nothing. */
#ifdef LADDERC_LOOP_LIMIT
extern uint64_t ladderc_loop_steps; /* jumps back in the current scan, reset before each */
void ladderc_loop_stuck(unsigned file, unsigned long start, unsigned long end);
#define LADDERC_LOOP_GUARD(f, s, e) \
    do { \
        if (++ladderc_loop_steps > (uint64_t)(LADDERC_LOOP_LIMIT)) ladderc_loop_stuck((f), (s), (e)); \
    } while (0)
#else
#define LADDERC_LOOP_GUARD(f, s, e) ((void)0)
#endif

/* The process image (defined by the generated program, sizes from the target profile). */
extern uint8_t ladderc_I[LADDERC_I_SIZE];
extern uint8_t ladderc_Q[LADDERC_Q_SIZE];
extern uint8_t ladderc_M[LADDERC_M_SIZE];
/* The TM (temporary) area for parameter passing: a window of the %M area. */
#define LADDERC_TM (ladderc_M + LADDERC_TM_OFFSET)

/* ------------------------------------------------------------------ integer helpers (no UB) */
/* A value stored into a subrange variable (`n : UINT(1..4)`) from anything but a value of that
 * subrange: IEC 61131-3 makes a value outside the range an error; it is saturated to the nearer
 * bound and sets LADDERC_ERR_RANGE. */
static inline int64_t ladderc_subrange_i(int64_t v, int64_t lo, int64_t hi) {
    if (v < lo) { ladderc_errors |= LADDERC_ERR_RANGE; return lo; }
    if (v > hi) { ladderc_errors |= LADDERC_ERR_RANGE; return hi; }
    return v;
}
static inline uint64_t ladderc_subrange_u(uint64_t v, uint64_t lo, uint64_t hi) {
    if (v < lo) { ladderc_errors |= LADDERC_ERR_RANGE; return lo; }
    if (v > hi) { ladderc_errors |= LADDERC_ERR_RANGE; return hi; }
    return v;
}

static inline int8_t ladderc_wrap_i8(uint64_t u) {
    u &= 0xFFu;
    return u <= 0x7Fu ? (int8_t)u : (int8_t)((int)u - 256);
}
static inline int16_t ladderc_wrap_i16(uint64_t u) {
    u &= 0xFFFFu;
    return u <= 0x7FFFu ? (int16_t)u : (int16_t)((int32_t)u - 65536);
}
static inline int32_t ladderc_wrap_i32(uint64_t u) {
    u &= 0xFFFFFFFFu;
    return u <= 0x7FFFFFFFu ? (int32_t)u : (int32_t)((int64_t)u - 4294967296LL);
}
static inline int64_t ladderc_wrap_i64(uint64_t u) {
    return u <= (uint64_t)INT64_MAX ? (int64_t)u : -(int64_t)(~u) - 1;
}

#define LADDERC_ARITH_SIGNED(T, W)                                                                 \
    static inline T ladderc_add_##T(T a, T b) { return ladderc_wrap_##W((uint64_t)a + (uint64_t)b); } \
    static inline T ladderc_sub_##T(T a, T b) { return ladderc_wrap_##W((uint64_t)a - (uint64_t)b); } \
    static inline T ladderc_mul_##T(T a, T b) { return ladderc_wrap_##W((uint64_t)a * (uint64_t)b); } \
    static inline T ladderc_neg_##T(T a) { return ladderc_wrap_##W(0u - (uint64_t)a); }              \
    static inline T ladderc_div_##T(T a, T b) {                                                   \
        if (b == 0) { ladderc_errors |= LADDERC_ERR_DIV_ZERO; return 0; }                         \
        if (b == -1) return ladderc_neg_##T(a);                                                   \
        return (T)(a / b);                                                                        \
    }                                                                                             \
    static inline T ladderc_mod_##T(T a, T b) {                                                   \
        if (b == 0) { ladderc_errors |= LADDERC_ERR_DIV_ZERO; return 0; }                         \
        if (b == -1) return 0;                                                                    \
        return (T)(a % b);                                                                        \
    }
#define LADDERC_ARITH_UNSIGNED(T, MASK)                                                            \
    static inline T ladderc_add_##T(T a, T b) { return (T)(((uint64_t)a + (uint64_t)b) & MASK); }  \
    static inline T ladderc_sub_##T(T a, T b) { return (T)(((uint64_t)a - (uint64_t)b) & MASK); }  \
    static inline T ladderc_mul_##T(T a, T b) { return (T)(((uint64_t)a * (uint64_t)b) & MASK); }  \
    static inline T ladderc_neg_##T(T a) { return (T)((0u - (uint64_t)a) & MASK); }                \
    static inline T ladderc_div_##T(T a, T b) {                                                   \
        if (b == 0) { ladderc_errors |= LADDERC_ERR_DIV_ZERO; return 0; }                         \
        return (T)(a / b);                                                                        \
    }                                                                                             \
    static inline T ladderc_mod_##T(T a, T b) {                                                   \
        if (b == 0) { ladderc_errors |= LADDERC_ERR_DIV_ZERO; return 0; }                         \
        return (T)(a % b);                                                                        \
    }

LADDERC_ARITH_SIGNED(IEC_SINT, i8)
LADDERC_ARITH_SIGNED(IEC_INT, i16)
LADDERC_ARITH_SIGNED(IEC_DINT, i32)
LADDERC_ARITH_SIGNED(IEC_LINT, i64)
LADDERC_ARITH_UNSIGNED(IEC_USINT, 0xFFu)
LADDERC_ARITH_UNSIGNED(IEC_UINT, 0xFFFFu)
LADDERC_ARITH_UNSIGNED(IEC_UDINT, 0xFFFFFFFFu)
LADDERC_ARITH_UNSIGNED(IEC_ULINT, 0xFFFFFFFFFFFFFFFFu)

/* REAL arithmetic is plain IEEE 754; MOD on REAL is not IEC. ABS/EXPT etc. below. */
static inline IEC_REAL ladderc_div_IEC_REAL(IEC_REAL a, IEC_REAL b) { return a / b; }
static inline IEC_LREAL ladderc_div_IEC_LREAL(IEC_LREAL a, IEC_LREAL b) { return a / b; }

/* Shifts and rotates on bit strings: a shift by the width or more gives 0; a negative count gives the
 * value unchanged; rotates take the count modulo the width. */
#define LADDERC_SHIFTS(T, BITS)                                                                    \
    static inline T ladderc_shl_##T(T v, int64_t n) {                                             \
        if (n < 0) return v;                                                                      \
        return n >= BITS ? (T)0 : (T)(((uint64_t)v << n) & (T)~(T)0);                             \
    }                                                                                             \
    static inline T ladderc_shr_##T(T v, int64_t n) {                                             \
        if (n < 0) return v;                                                                      \
        return n >= BITS ? (T)0 : (T)((uint64_t)v >> n);                                          \
    }                                                                                             \
    static inline T ladderc_rol_##T(T v, int64_t n) {                                             \
        unsigned s = (unsigned)(((n % BITS) + BITS) % BITS);                                       \
        if (s == 0) return v;                                                                     \
        return (T)((((uint64_t)v << s) | ((uint64_t)v >> (BITS - s))) & (T)~(T)0);                \
    }                                                                                             \
    static inline T ladderc_ror_##T(T v, int64_t n) {                                             \
        unsigned s = (unsigned)(((n % BITS) + BITS) % BITS);                                       \
        if (s == 0) return v;                                                                     \
        return (T)((((uint64_t)v >> s) | ((uint64_t)v << (BITS - s))) & (T)~(T)0);                \
    }
LADDERC_SHIFTS(IEC_BYTE, 8)
LADDERC_SHIFTS(IEC_WORD, 16)
LADDERC_SHIFTS(IEC_DWORD, 32)
LADDERC_SHIFTS(IEC_LWORD, 64)

/* REAL -> integer (IEC 61131-3, IEC 60559): round to nearest, halves to even (2.5 -> 2, -2.5 -> -2,
 * 0.5 -> 0), independent of the C rounding mode; out of range saturates to the type's limit, NaN gives 0;
 * both flag LADDERC_ERR_RANGE. No out-of-range float-to-integer cast is ever executed. */
static inline double ladderc_round_half_even(double x) {
    double f = floor(x), d = x - f; /* exact for every double */
    if (d > 0.5 || (d == 0.5 && fmod(f, 2.0) != 0.0)) f += 1.0;
    return f;
}
static inline int64_t ladderc_real_to_int(double x, int64_t lo, int64_t hi) {
    double r, top = -(double)lo; /* 2^(n-1), exact: the first value above hi */
    if (x != x) { ladderc_errors |= LADDERC_ERR_RANGE; return 0; }
    r = ladderc_round_half_even(x);
    if (r < (double)lo) { ladderc_errors |= LADDERC_ERR_RANGE; return lo; }
    if (r >= top) { ladderc_errors |= LADDERC_ERR_RANGE; return hi; }
    return (int64_t)r;
}
static inline uint64_t ladderc_real_to_uint(double x, uint64_t hi) {
    double r, top = (double)hi + 1.0; /* 2^n (UINT64_MAX already rounds to 2^64) */
    if (x != x) { ladderc_errors |= LADDERC_ERR_RANGE; return 0; }
    r = ladderc_round_half_even(x);
    if (r < 0.0) { ladderc_errors |= LADDERC_ERR_RANGE; return 0; }
    if (r >= top) { ladderc_errors |= LADDERC_ERR_RANGE; return hi; }
    return (uint64_t)r;
}
/* LREAL -> REAL: rounded to nearest (IEC 60559); a finite value beyond REAL's range gives +-infinity, as
 * IEC 60559 does, and flags LADDERC_ERR_RANGE (no out-of-range cast is executed); NaN stays NaN. */
static inline float ladderc_lreal_to_real(double x) {
    const double fmax = 3.4028234663852886e38, edge = 3.4028235677973366e38; /* FLT_MAX, 2^128 - 2^103 */
    if (x > fmax || x < -fmax) {
        int neg = x < 0;
        double ax = neg ? -x : x;
        if (ax != (double)INFINITY) ladderc_errors |= LADDERC_ERR_RANGE;
        if (ax < edge) return neg ? -3.4028234663852886e38f : 3.4028234663852886e38f;
        return neg ? -INFINITY : INFINITY;
    }
    return (float)x;
}
/* REAL_TO_TIME, LREAL_TO_TIME: `units` is a number of the profile's unit (LADDERC_TIME_UNIT_NS);
   rounded to a whole number of units (halves to even) under LADDERC_REAL_TO_TIME_WHOLE_UNITS, else
   to the nanosecond; saturated (and flagged) outside the 64-bit range. */
static inline IEC_TIME ladderc_real_to_time(double units) {
#if LADDERC_REAL_TO_TIME_WHOLE_UNITS
    if (units == units) units = ladderc_round_half_even(units);
#endif
    return (IEC_TIME)ladderc_real_to_int(units * (double)LADDERC_TIME_UNIT_NS, INT64_MIN, INT64_MAX);
}
/* REAL_TO_TIME and friends: x is in milliseconds. */
static inline IEC_TIME ladderc_ms_to_time(double ms) { return (IEC_TIME)ladderc_real_to_int(ms * 1e6, INT64_MIN, INT64_MAX); }

/* The next due time of a cyclic task: the first multiple of `iv` after `due` that is later than `now`. */
static inline IEC_TIME ladderc_next_due(IEC_TIME due, IEC_TIME now, IEC_TIME iv) {
    IEC_LINT late = ladderc_sub_IEC_LINT(now, due);
    IEC_LINT steps = late < 0 ? 1 : ladderc_add_IEC_LINT(ladderc_div_IEC_LINT(late, iv), 1);
    return ladderc_add_IEC_LINT(due, ladderc_mul_IEC_LINT(steps, iv));
}

/* DT_TO_DATE / DT_TO_TOD: the day part and the time-of-day part (floor division, no overflow). */
#define LADDERC_NS_PER_DAY INT64_C(86400000000000)
static inline IEC_TOD ladderc_dt_to_tod(IEC_DT dt) {
    int64_t r = dt % LADDERC_NS_PER_DAY;
    return r < 0 ? r + LADDERC_NS_PER_DAY : r;
}
static inline IEC_DATE ladderc_dt_to_date(IEC_DT dt) { return ladderc_sub_IEC_LINT(dt, ladderc_dt_to_tod(dt)); }

/* BCD: invalid digits (> 9) give 0 and LADDERC_ERR_RANGE. */
/* Edition 3's IS_VALID_BCD: every 4-bit digit 0..9. */
static inline IEC_BOOL ladderc_is_valid_bcd(uint64_t bcd) {
    while (bcd) {
        if ((bcd & 0xFu) > 9) return 0;
        bcd >>= 4;
    }
    return 1;
}
static inline uint64_t ladderc_bcd_to_uint(uint64_t bcd) {
    uint64_t v = 0, mul = 1;
    while (bcd) {
        uint64_t d = bcd & 0xFu;
        if (d > 9) { ladderc_errors |= LADDERC_ERR_RANGE; return 0; }
        v += d * mul;
        mul *= 10;
        bcd >>= 4;
    }
    return v;
}
/* *_TO_BCD into a bit string of `bits` bits: a value with more than bits/4 decimal digits does not fit and
 * gives 0 with LADDERC_ERR_RANGE (like a negative input). */
static inline uint64_t ladderc_uint_to_bcd(uint64_t v, unsigned bits) {
    uint64_t bcd = 0, limit = 1;
    unsigned shift = 0, k;
    for (k = 0; k < bits / 4; k++) limit *= 10u;
    if (v >= limit) { ladderc_errors |= LADDERC_ERR_RANGE; return 0; }
    while (v) {
        bcd |= (v % 10) << shift;
        v /= 10;
        shift += 4;
    }
    return bcd;
}

/* Standard functions that take any numeric type are emitted by the generator as these macros; every
 * argument is a plain C value (a local or a constant), so double evaluation is harmless. */
#define LADDERC_MAX(a, b) ((a) > (b) ? (a) : (b))
#define LADDERC_MIN(a, b) ((a) < (b) ? (a) : (b))
/* LIMIT is MIN(MAX(IN, MN), MX) (IEC 61131-3 ed. 2 Table 27, ed. 3 Table 32): MX when MN > MX */
#define LADDERC_LIMIT(mn, in, mx) LADDERC_MIN(LADDERC_MAX(in, mn), mx)
#define LADDERC_SEL(g, in0, in1) ((g) ? (in1) : (in0))

/* Comparisons and ordering as functions, so that comparing an unsigned value with a constant 0 never
 * trips -Wtype-limits in generated code. */
#define LADDERC_ORDERED(T)                                                                         \
    static inline IEC_BOOL ladderc_gt_##T(T a, T b) { return a > b; }                              \
    static inline IEC_BOOL ladderc_ge_##T(T a, T b) { return a >= b; }                            \
    static inline IEC_BOOL ladderc_eq_##T(T a, T b) { return a == b; }                            \
    static inline IEC_BOOL ladderc_ne_##T(T a, T b) { return a != b; }                            \
    static inline IEC_BOOL ladderc_le_##T(T a, T b) { return a <= b; }                            \
    static inline IEC_BOOL ladderc_lt_##T(T a, T b) { return a < b; }                              \
    static inline T ladderc_max_##T(T a, T b) { return a > b ? a : b; }                            \
    static inline T ladderc_min_##T(T a, T b) { return a < b ? a : b; }                            \
    static inline T ladderc_limit_##T(T mn, T in, T mx) { return ladderc_min_##T(ladderc_max_##T(in, mn), mx); }
LADDERC_ORDERED(IEC_SINT)
LADDERC_ORDERED(IEC_INT)
LADDERC_ORDERED(IEC_DINT)
LADDERC_ORDERED(IEC_LINT)
LADDERC_ORDERED(IEC_USINT)
LADDERC_ORDERED(IEC_UINT)
LADDERC_ORDERED(IEC_UDINT)
LADDERC_ORDERED(IEC_ULINT)
LADDERC_ORDERED(IEC_REAL)
LADDERC_ORDERED(IEC_LREAL)

/* ABS on signed integers wraps like the type (ABS of the most negative value is itself). */
static inline IEC_SINT ladderc_abs_IEC_SINT(IEC_SINT a) { return a < 0 ? ladderc_neg_IEC_SINT(a) : a; }
static inline IEC_INT ladderc_abs_IEC_INT(IEC_INT a) { return a < 0 ? ladderc_neg_IEC_INT(a) : a; }
static inline IEC_DINT ladderc_abs_IEC_DINT(IEC_DINT a) { return a < 0 ? ladderc_neg_IEC_DINT(a) : a; }
static inline IEC_LINT ladderc_abs_IEC_LINT(IEC_LINT a) { return a < 0 ? ladderc_neg_IEC_LINT(a) : a; }

/* The zero-based offset of index i in lo..hi; out of range gives 0 and sets LADDERC_ERR_BOUNDS,
 * keeping the site (the access as written, its POU and line), the index and the bounds of the first. */
static inline size_t ladderc_index(int64_t i, int64_t lo, int64_t hi, const char *site) {
    if (i < lo || i > hi) {
        if (!(ladderc_errors & LADDERC_ERR_BOUNDS)) {
            ladderc_bounds_site = site;
            ladderc_bounds_at[0] = i;
            ladderc_bounds_at[1] = lo;
            ladderc_bounds_at[2] = hi;
        }
        ladderc_errors |= LADDERC_ERR_BOUNDS;
        return 0;
    }
    return (size_t)((uint64_t)i - (uint64_t)lo);
}

/* Edition 3's `s[i]` of a STRING (a CHAR) or a WSTRING (a WCHAR), 1-based: the character's place.
 * An index outside 1..LEN(s) sets LADDERC_ERR_CHAR_INDEX (the first site and index kept) and gives a
 * scratch character, NUL each time it is handed out: a read gives NUL, a write is dropped. */
/* Whether 1 <= i <= len; otherwise sets LADDERC_ERR_CHAR_INDEX (the first site and index kept). */
static inline int ladderc_char_index_ok(int64_t i, size_t len, const char *site) {
    if (i >= 1 && i <= (int64_t)len) return 1;
    if (!(ladderc_errors & LADDERC_ERR_CHAR_INDEX)) {
        ladderc_char_index_site = site;
        ladderc_char_index_at[0] = i;
        ladderc_char_index_at[1] = 1;
        ladderc_char_index_at[2] = (int64_t)len;
    }
    ladderc_errors |= LADDERC_ERR_CHAR_INDEX;
    return 0;
}
/* CODESYS/TwinCAT `s[i]` of a STRING (a BYTE) or a WSTRING (a WORD): the code at offset i, 0 the
 * first, of the string's `cap + 1` places (its declared length and the terminating NUL). Reading at
 * LEN(s) or beyond gives 0 (ladderc keeps the places after the terminator NUL); writing 0 before
 * LEN(s) ends the string there, writing a code at LEN(s) appends it, elsewhere after the end it is
 * dropped (the string still ends at its first NUL). An offset outside 0..cap (a code other than 0
 * at cap itself: no room for the terminator) sets LADDERC_ERR_CHAR_INDEX and is a 0 read, a
 * dropped write. */
static inline int ladderc_byte_index_ok(int64_t i, size_t cap, const char *site) {
    if (i >= 0 && i <= (int64_t)cap) return 1;
    if (!(ladderc_errors & LADDERC_ERR_CHAR_INDEX)) {
        ladderc_char_index_site = site;
        ladderc_char_index_at[0] = i;
        ladderc_char_index_at[1] = 0;
        ladderc_char_index_at[2] = (int64_t)cap;
    }
    ladderc_errors |= LADDERC_ERR_CHAR_INDEX;
    return 0;
}
#define LADDERC_STR_BYTE_FNS(NAME, STR, CODE)                                                        \
    static inline CODE NAME##_get(const STR *s, int64_t i, size_t cap, const char *site) {           \
        if (!ladderc_byte_index_ok(i, cap, site) || i >= (int64_t)s->len) return 0;                 \
        return (CODE)s->data[i];                                                                     \
    }                                                                                                \
    static inline void NAME##_set(STR *s, int64_t i, size_t cap, CODE v, const char *site) {         \
        if (!ladderc_byte_index_ok(i, v != 0 ? cap - 1 : cap, site)) return;                        \
        if (i < (int64_t)s->len) {                                                                   \
            s->data[i] = v;                                                                          \
            if (v == 0) s->len = (uint16_t)i;                                                        \
        } else if (i == (int64_t)s->len && v != 0) {                                                 \
            s->data[i] = v;                                                                          \
            s->len = (uint16_t)(i + 1);                                                              \
            s->data[i + 1] = 0;                                                                      \
        }                                                                                            \
    }
LADDERC_STR_BYTE_FNS(ladderc_str_byte, IEC_STRING, IEC_BYTE)
LADDERC_STR_BYTE_FNS(ladderc_wstr_word, IEC_WSTRING, IEC_WORD)
static inline IEC_CHAR *ladderc_char_at(IEC_STRING *s, int64_t i, const char *site) {
    static IEC_CHAR scratch;
    if (!ladderc_char_index_ok(i, s->len, site)) {
        scratch = 0;
        return &scratch;
    }
    return (IEC_CHAR *)&s->data[i - 1];
}
static inline IEC_WCHAR *ladderc_wchar_at(IEC_WSTRING *s, int64_t i, const char *site) {
    static IEC_WCHAR scratch;
    if (!ladderc_char_index_ok(i, s->len, site)) {
        scratch = 0;
        return &scratch;
    }
    return &s->data[i - 1];
}
/* CHAR_TO_STRING / WCHAR_TO_WSTRING: the one-character string; STRING_TO_CHAR / WSTRING_TO_WCHAR:
 * the first character (NUL of an empty string); WCHAR_TO_CHAR keeps a code up to 255, else '?'
 * (as WSTRING_TO_STRING does with a character a STRING cannot hold). */
static inline IEC_STRING ladderc_char_to_str(IEC_CHAR c) {
    IEC_STRING s;
    s.len = 1;
    s.data[0] = (char)c;
    s.data[1] = '\0';
    return s;
}
static inline IEC_WSTRING ladderc_wchar_to_wstr(IEC_WCHAR c) {
    IEC_WSTRING s;
    s.len = 1;
    s.data[0] = c;
    s.data[1] = 0;
    return s;
}
static inline IEC_CHAR ladderc_wchar_to_char(IEC_WCHAR c) {
    if (c > 0xFF) { ladderc_errors |= LADDERC_ERR_RANGE; return (IEC_CHAR)'?'; }
    return (IEC_CHAR)c;
}
static inline IEC_CHAR ladderc_str_first(IEC_STRING s) { return s.len ? (IEC_CHAR)s.data[0] : 0; }
static inline IEC_WCHAR ladderc_wstr_first(IEC_WSTRING s) { return s.len ? s.data[0] : 0; }

/* REF(x) / ADR(x): a reference to the `size` bytes at `base` (NULL for NULL). */
static inline IEC_REF ladderc_ref(void *base, size_t size) {
    IEC_REF r;
    r.base = (unsigned char *)base;
    r.size = (uint32_t)size;
    r.off = 0;
    return r;
}
/* ADR(a[i]): the element at `at` of the array `whole` of `size` bytes, as a reference into the whole
 * array (so that indexing and arithmetic may move it to the other elements). `at` lies in `whole`. */
static inline IEC_REF ladderc_ref_in(void *whole, size_t size, const void *at) {
    IEC_REF r = ladderc_ref(whole, size);
    r.off = (int32_t)((const unsigned char *)at - (const unsigned char *)whole);
    return r;
}
/* `r + bytes` (CODESYS/TwinCAT pointer arithmetic counts bytes): the offset moved, computed without
 * overflow and saturated far outside any variable (the data budget is far below 2^31 bytes). */
static inline IEC_REF ladderc_ref_add(IEC_REF r, int64_t bytes) {
    int64_t o = (int64_t)r.off;
    if (bytes > INT32_MAX || bytes < INT32_MIN) o = bytes > 0 ? INT32_MAX : INT32_MIN;
    else o += bytes;
    if (o > INT32_MAX) o = INT32_MAX;
    if (o < INT32_MIN) o = INT32_MIN;
    r.off = (int32_t)o;
    return r;
}
/* `r - bytes`. */
static inline IEC_REF ladderc_ref_sub(IEC_REF r, int64_t bytes) {
    return ladderc_ref_add(r, bytes == INT64_MIN ? INT64_MAX : -bytes);
}
/* `p[i]` of a POINTER TO T: `p` moved by i elements of `n` bytes (the i-th T after p^). */
static inline IEC_REF ladderc_ref_index(IEC_REF r, int64_t i, size_t n) {
    if (n != 0 && (i > INT32_MAX / (int64_t)n || i < INT32_MIN / (int64_t)n)) i = i > 0 ? INT32_MAX : INT32_MIN;
    else i *= (int64_t)n;
    return ladderc_ref_add(r, i);
}
/* The address a reference stands for, as an integer (NULL counts as address 0): what `=`, `<>`, `<`
 * ... compare. Computed in integers, so it is defined for any offset. */
static inline uintptr_t ladderc_ref_addr(IEC_REF r) {
    return (uintptr_t)r.base + (uintptr_t)(intptr_t)r.off;
}

/* The bytes a memory function (MEMCPY ...) given a pointer variable may reach: from where it points
 * to the end of the variable it was made from; 0 for NULL or a pointer moved outside it. */
static inline size_t ladderc_ref_room(IEC_REF r) {
    if (r.base == NULL || r.off < 0 || (uint32_t)r.off > r.size) return 0;
    return (size_t)(r.size - (uint32_t)r.off);
}
/* Where it points, for a memory function: a valid address even when its room is 0 (then no byte is
 * touched, the count is clipped to 0). */
static inline void *ladderc_ref_at(IEC_REF r) {
    static unsigned char nowhere[1];
    return ladderc_ref_room(r) != 0 ? (void *)(r.base + r.off) : (void *)nowhere;
}

/* A dereference `r^` (or `p[i]`, after ladderc_ref_index) of a reference: the address of the `n` bytes
 * (of alignment `align`) it refers to, or the zeroed scratch object `scratch` of `n` bytes (so a read
 * gives zero and a write is dropped) for NULL (LADDERC_ERR_NULL_REF) and for a reference moved outside
 * its variable or to a misaligned place (LADDERC_ERR_POINTER), with the place of the first of each
 * kept. No NULL pointer is dereferenced and no byte outside the variable is reached. */
static inline void *ladderc_deref(IEC_REF r, size_t n, size_t align, void *scratch, const char *site) {
    if (r.base == NULL) {
        if (!(ladderc_errors & LADDERC_ERR_NULL_REF)) ladderc_null_ref_site = site;
        ladderc_errors |= LADDERC_ERR_NULL_REF;
    } else if (r.off >= 0 && (uint64_t)r.off + (uint64_t)n <= (uint64_t)r.size &&
               ((uintptr_t)(r.base + r.off)) % (align ? align : 1) == 0) {
        return r.base + r.off;
    } else {
        if (!(ladderc_errors & LADDERC_ERR_POINTER)) ladderc_pointer_site = site;
        ladderc_errors |= LADDERC_ERR_POINTER;
    }
    memset(scratch, 0, n);
    return scratch;
}

/* MEMCPY, MEMMOVE, MEMSET and MEMCMP (Tc2_System, CODESYS SysMem), bounded: `a_room` and `b_room`
 * are the bytes the variables behind the pointers hold from there on, and a count `n` beyond the
 * smaller is clipped to it, with LADDERC_ERR_MEM set and the place of the first one kept. Copies go
 * through memmove (a MEMCPY between overlapping parts of one variable is then well defined). The
 * copy and fill functions give 1, or 0 when the count was clipped (Tc2_System: 0 on failure);
 * MEMCMP gives 0 for equal bytes, -1 or 1 as the first differing byte (unsigned) compares. */
static inline size_t ladderc_mem_count(uint64_t n, size_t a_room, size_t b_room, const char *site) {
    size_t room = a_room < b_room ? a_room : b_room;
    if (n > (uint64_t)room) {
        if (!(ladderc_errors & LADDERC_ERR_MEM)) ladderc_mem_site = site;
        ladderc_errors |= LADDERC_ERR_MEM;
        return room;
    }
    return (size_t)n;
}
static inline IEC_UDINT ladderc_mem_move(void *dst, size_t d_room, const void *src, size_t s_room,
                                         uint64_t n, const char *site) {
    size_t k = ladderc_mem_count(n, d_room, s_room, site);
    if (k > 0) memmove(dst, src, k);
    return (uint64_t)k == n ? 1u : 0u;
}
static inline IEC_UDINT ladderc_mem_set(void *dst, size_t d_room, uint64_t fill, uint64_t n,
                                        const char *site) {
    size_t k = ladderc_mem_count(n, d_room, d_room, site);
    if (k > 0) memset(dst, (int)(fill & 0xFFu), k);
    return (uint64_t)k == n ? 1u : 0u;
}
static inline IEC_DINT ladderc_mem_cmp(const void *a, size_t a_room, const void *b, size_t b_room,
                                       uint64_t n, const char *site) {
    size_t k = ladderc_mem_count(n, a_room, b_room, site);
    int c = k > 0 ? memcmp(a, b, k) : 0;
    return c < 0 ? -1 : (c > 0 ? 1 : 0);
}

/* Edition 3 date functions: CONCAT_DATE(year, month, day), CONCAT_TOD(hour, minute, second, ms),
 * CONCAT_DT(the seven parts); a part out of its range (month 1..12, day 1..days of that month, hour 0..23,
 * minute and second 0..59, ms 0..999, a date outside 1677-09-22 .. 2262-04-10, where DT fits int64
 * nanoseconds) gives 0 and
 * sets LADDERC_ERR_RANGE. DAY_OF_WEEK: 0 Sunday ... 6 Saturday. */
IEC_DATE ladderc_concat_date(int64_t year, int64_t month, int64_t day);
IEC_TOD ladderc_concat_tod(int64_t hour, int64_t minute, int64_t second, int64_t ms);
IEC_DT ladderc_concat_dt(int64_t year, int64_t month, int64_t day, int64_t hour, int64_t minute, int64_t second,
                         int64_t ms);
IEC_INT ladderc_day_of_week(int64_t date);
/* Edition 3's SPLIT_DATE, SPLIT_TOD, SPLIT_LTOD, SPLIT_DT, SPLIT_LDT: the parts of a date, time of
 * day or date and time (nanoseconds since 1970-01-01, or since midnight): parts[0..6] are the year,
 * month, day, hour, minute, second and millisecond (a time of day is of 1970-01-01). */
void ladderc_split(int64_t ns, IEC_LINT parts[7]);

/* ------------------------------------------------------------------ strings */
void ladderc_string_set(IEC_STRING *dst, const char *src, size_t len, unsigned cap);
void ladderc_string_copy(IEC_STRING *dst, const IEC_STRING *src, unsigned cap);
int ladderc_string_cmp(const IEC_STRING *a, const IEC_STRING *b);
void ladderc_string_concat(IEC_STRING *dst, const IEC_STRING *a, const IEC_STRING *b, unsigned cap);
void ladderc_wstring_set(IEC_WSTRING *dst, const uint16_t *src, size_t len, unsigned cap);
int ladderc_wstring_cmp(const IEC_WSTRING *a, const IEC_WSTRING *b);
/* A string value from a literal (bytes, length), and value-based helpers for generated code. */
IEC_STRING ladderc_str_lit(const char *bytes, size_t len);
IEC_STRING ladderc_str_cap(IEC_STRING s, unsigned cap);
int ladderc_str_cmpv(IEC_STRING a, IEC_STRING b);
IEC_WSTRING ladderc_wstr_lit(const uint16_t *units, size_t len);
IEC_WSTRING ladderc_wstr_cap(IEC_WSTRING s, unsigned cap);
int ladderc_wstr_cmpv(IEC_WSTRING a, IEC_WSTRING b);
/* *_TO_STRING: the value's text as the trace prints it (BOOL TRUE/FALSE, T#..., shortest REAL). */
IEC_STRING ladderc_str_of(int type, const void *value);
/* A STRING holds single-byte characters, ISO 8859-1 (U+0000-U+00FF, one byte each; literals are
 * stored so and stimuli read so). STRING_TO_WSTRING: each byte becomes the character of its code.
 * WSTRING_TO_STRING: each character U+0000-U+00FF its byte; any other becomes '?' (a surrogate pair
 * one '?') and sets LADDERC_ERR_RANGE. *_TO_WSTRING and WSTRING_TO_* go through STRING. */
IEC_WSTRING ladderc_wstr_of_str(IEC_STRING s);
IEC_STRING ladderc_str_of_wstr(IEC_WSTRING w);
/* STRING_TO_*: text after trimming spaces; a malformed text gives 0 (FALSE) and LADDERC_ERR_RANGE. */
int64_t ladderc_str_to_int(IEC_STRING s);
uint64_t ladderc_str_to_uint(IEC_STRING s);
double ladderc_str_to_real(IEC_STRING s);
IEC_BOOL ladderc_str_to_bool(IEC_STRING s);
IEC_TIME ladderc_str_to_time(IEC_STRING s);
/* The standard string functions (ladderc_strings.c), value-based; lengths and positions as int64_t. */
#define LADDERC_STR_DECLS(P, S)                                                                       \
    IEC_INT P##_len(S in);                                                                          \
    S P##_left(S in, int64_t l);                                                                    \
    S P##_right(S in, int64_t l);                                                                   \
    S P##_mid(S in, int64_t l, int64_t p);                                                          \
    S P##_concat(S a, S b);                                                                         \
    S P##_insert(S a, S b, int64_t p);                                                              \
    S P##_delete(S in, int64_t l, int64_t p);                                                       \
    S P##_replace(S a, S b, int64_t l, int64_t p);                                                  \
    S P##_max(S a, S b);                                                                            \
    S P##_min(S a, S b);                                                                            \
    S P##_limit(S mn, S in, S mx);                                                                  \
    IEC_INT P##_find(S a, S b);
LADDERC_STR_DECLS(ladderc_str, IEC_STRING)
LADDERC_STR_DECLS(ladderc_wstr, IEC_WSTRING)
IEC_DATE ladderc_str_to_date(IEC_STRING s);
IEC_TOD ladderc_str_to_tod(IEC_STRING s);
IEC_DT ladderc_str_to_dt(IEC_STRING s);
IEC_LDATE ladderc_str_to_ldate(IEC_STRING s);
IEC_LTOD ladderc_str_to_ltod(IEC_STRING s);
IEC_LDT ladderc_str_to_ldt(IEC_STRING s);

/* ------------------------------------------------------------------ process image access */
/* Byte order from the profile: LADDERC_BIG_ENDIAN is 0 (little) or 1 (big). Loads and stores go byte by
 * byte, never through an unaligned pointer cast. Offsets are checked by the generator (E2xxx), so they
 * are always inside the area. */
static inline uint64_t ladderc_load(const uint8_t *area, uint32_t offset, unsigned nbytes) {
    uint64_t v = 0;
    unsigned i;
    for (i = 0; i < nbytes; i++) {
        unsigned idx = LADDERC_BIG_ENDIAN ? i : nbytes - 1 - i;
        v = (v << 8) | area[offset + idx];
    }
    return v;
}
static inline void ladderc_store(uint8_t *area, uint32_t offset, unsigned nbytes, uint64_t v) {
    unsigned i;
    for (i = 0; i < nbytes; i++) {
        unsigned idx = LADDERC_BIG_ENDIAN ? nbytes - 1 - i : i;
        area[offset + idx] = (uint8_t)(v & 0xFFu);
        v >>= 8;
    }
}
/* Bit `bit` of byte `offset` (bit 0 is the least significant unless LADDERC_BIT_MSB0). */
#if LADDERC_BIT_MSB0
#define LADDERC_BITMASK(bit) ((uint8_t)(0x80u >> (bit)))
#else
#define LADDERC_BITMASK(bit) ((uint8_t)(1u << (bit)))
#endif
static inline IEC_BOOL ladderc_load_bit(const uint8_t *area, uint32_t offset, unsigned bit) {
    return (area[offset] & LADDERC_BITMASK(bit)) ? 1u : 0u;
}
static inline void ladderc_store_bit(uint8_t *area, uint32_t offset, unsigned bit, IEC_BOOL v) {
    if (v) area[offset] = (uint8_t)(area[offset] | LADDERC_BITMASK(bit));
    else area[offset] = (uint8_t)(area[offset] & (uint8_t)~LADDERC_BITMASK(bit));
}
static inline float ladderc_bits_to_real(uint32_t u) { float f; memcpy(&f, &u, sizeof f); return f; }
/* Edition 3's endianness conversions of the n low bytes of v (n = 1, 2, 4 or 8), on any host:
 * ladderc_to_endian gives the n-byte value whose bytes in memory are v's, most significant first
 * (big) or least significant first; ladderc_from_endian reads the bytes of v's memory so. */
static inline uint64_t ladderc_to_endian(uint64_t v, unsigned n, int big) {
    unsigned char b[8] = {0};
    unsigned i;
    uint16_t r2;
    uint32_t r4;
    uint64_t r8;
    for (i = 0; i < n && i < 8; i++) b[i] = (unsigned char)(v >> (8 * (big ? n - 1 - i : i)));
    switch (n) {
    case 1: return b[0];
    case 2: memcpy(&r2, b, 2); return r2;
    case 4: memcpy(&r4, b, 4); return r4;
    default: memcpy(&r8, b, 8); return r8;
    }
}
static inline uint64_t ladderc_from_endian(uint64_t v, unsigned n, int big) {
    unsigned char b[8] = {0};
    unsigned i;
    uint16_t v2 = (uint16_t)v;
    uint32_t v4 = (uint32_t)v;
    uint64_t r = 0;
    switch (n) {
    case 1: b[0] = (unsigned char)v; break;
    case 2: memcpy(b, &v2, 2); break;
    case 4: memcpy(b, &v4, 4); break;
    default: memcpy(b, &v, 8); break;
    }
    for (i = 0; i < n && i < 8; i++) r |= (uint64_t)b[i] << (8 * (big ? n - 1 - i : i));
    return r;
}
static inline uint32_t ladderc_real_to_bits(float f) { uint32_t u; memcpy(&u, &f, sizeof u); return u; }
static inline double ladderc_bits_to_lreal(uint64_t u) { double f; memcpy(&f, &u, sizeof f); return f; }
static inline uint64_t ladderc_lreal_to_bits(double f) { uint64_t u; memcpy(&u, &f, sizeof u); return u; }

/* ------------------------------------------------------------------ standard function blocks */
/* Field names are the IEC parameter names; hidden state is lower-case. Each FB has _init (the IEC
 * initial values, all zero, and ENO TRUE) and _body (one execution with the current inputs). ENO is
 * the ENO of the instance's last call, stored by the generated call (FALSE when its EN was FALSE and
 * the body did not run). Timers read ladderc_now. */
typedef struct { IEC_BOOL CLK, Q, m; IEC_BOOL ENO; } ladderc_R_TRIG;
typedef struct { IEC_BOOL CLK, Q, m; IEC_BOOL ENO; } ladderc_F_TRIG;
typedef struct { IEC_BOOL S1, R, Q1; IEC_BOOL ENO; } ladderc_SR;
typedef struct { IEC_BOOL S, R1, Q1; IEC_BOOL ENO; } ladderc_RS;
typedef struct { IEC_BOOL IN; IEC_TIME PT; IEC_BOOL Q; IEC_TIME ET; IEC_BOOL running; IEC_TIME start; IEC_BOOL ENO; } ladderc_TON;
typedef struct { IEC_BOOL IN; IEC_TIME PT; IEC_BOOL Q; IEC_TIME ET; IEC_BOOL running; IEC_TIME start; IEC_BOOL ENO; } ladderc_TOF;
typedef struct { IEC_BOOL IN; IEC_TIME PT; IEC_BOOL Q; IEC_TIME ET; IEC_BOOL running; IEC_TIME start; IEC_BOOL in_m; IEC_BOOL ENO; } ladderc_TP;
/* Edition 3's LTIME timers TON_LTIME, TOF_LTIME, TP_LTIME (CODESYS's and TwinCAT's LTON, LTOF, LTP). */
typedef struct { IEC_BOOL IN; IEC_LTIME PT; IEC_BOOL Q; IEC_LTIME ET; IEC_BOOL running; IEC_LTIME start; IEC_BOOL ENO; } ladderc_TON_LTIME;
typedef struct { IEC_BOOL IN; IEC_LTIME PT; IEC_BOOL Q; IEC_LTIME ET; IEC_BOOL running; IEC_LTIME start; IEC_BOOL ENO; } ladderc_TOF_LTIME;
typedef struct { IEC_BOOL IN; IEC_LTIME PT; IEC_BOOL Q; IEC_LTIME ET; IEC_BOOL running; IEC_LTIME start; IEC_BOOL in_m; IEC_BOOL ENO; } ladderc_TP_LTIME;
typedef struct { IEC_BOOL CU, R; IEC_INT PV; IEC_BOOL Q; IEC_INT CV; IEC_BOOL cu_m; IEC_BOOL ENO; } ladderc_CTU;
typedef struct { IEC_BOOL CD, LD; IEC_INT PV; IEC_BOOL Q; IEC_INT CV; IEC_BOOL cd_m; IEC_BOOL ENO; } ladderc_CTD;
typedef struct { IEC_BOOL CU, CD, R, LD; IEC_INT PV; IEC_BOOL QU, QD; IEC_INT CV; IEC_BOOL cu_m, cd_m; IEC_BOOL ENO; } ladderc_CTUD;
/* The typed counters CTU_DINT ... CTUD_ULINT: the same FBs on PV and CV of type T. */
#define LADDERC_COUNTER_TYPES(T)                                                                   \
    typedef struct { IEC_BOOL CU, R; IEC_##T PV; IEC_BOOL Q; IEC_##T CV; IEC_BOOL cu_m; IEC_BOOL ENO; } ladderc_CTU_##T; \
    typedef struct { IEC_BOOL CD, LD; IEC_##T PV; IEC_BOOL Q; IEC_##T CV; IEC_BOOL cd_m; IEC_BOOL ENO; } ladderc_CTD_##T; \
    typedef struct {                                                                               \
        IEC_BOOL CU, CD, R, LD; IEC_##T PV; IEC_BOOL QU, QD; IEC_##T CV; IEC_BOOL cu_m, cd_m;     \
        IEC_BOOL ENO;                                                                              \
    } ladderc_CTUD_##T;
LADDERC_COUNTER_TYPES(DINT)
LADDERC_COUNTER_TYPES(LINT)
LADDERC_COUNTER_TYPES(UDINT)
LADDERC_COUNTER_TYPES(ULINT)
/* CODESYS's Standard and TwinCAT's Tc2_Standard CTU, CTD, CTUD: PV and CV of type WORD. */
LADDERC_COUNTER_TYPES(WORD)

#define LADDERC_FB_DECL(N)                                                                         \
    void ladderc_##N##_init(ladderc_##N *fb);                                                     \
    void ladderc_##N##_body(ladderc_##N *fb);
LADDERC_FB_DECL(R_TRIG)
LADDERC_FB_DECL(F_TRIG)
LADDERC_FB_DECL(SR)
LADDERC_FB_DECL(RS)
LADDERC_FB_DECL(TON)
LADDERC_FB_DECL(TOF)
LADDERC_FB_DECL(TP)
LADDERC_FB_DECL(TON_LTIME)
LADDERC_FB_DECL(TOF_LTIME)
LADDERC_FB_DECL(TP_LTIME)
LADDERC_FB_DECL(CTU)
LADDERC_FB_DECL(CTD)
LADDERC_FB_DECL(CTUD)
LADDERC_FB_DECL(CTU_DINT)
LADDERC_FB_DECL(CTD_DINT)
LADDERC_FB_DECL(CTUD_DINT)
LADDERC_FB_DECL(CTU_LINT)
LADDERC_FB_DECL(CTD_LINT)
LADDERC_FB_DECL(CTUD_LINT)
LADDERC_FB_DECL(CTU_UDINT)
LADDERC_FB_DECL(CTD_UDINT)
LADDERC_FB_DECL(CTUD_UDINT)
LADDERC_FB_DECL(CTU_ULINT)
LADDERC_FB_DECL(CTD_ULINT)
LADDERC_FB_DECL(CTUD_ULINT)
LADDERC_FB_DECL(CTU_WORD)
LADDERC_FB_DECL(CTD_WORD)
LADDERC_FB_DECL(CTUD_WORD)

/* ------------------------------------------------------------------ the harness contract */
typedef enum {
    LADDERC_T_BOOL, LADDERC_T_SINT, LADDERC_T_INT, LADDERC_T_DINT, LADDERC_T_LINT,
    LADDERC_T_USINT, LADDERC_T_UINT, LADDERC_T_UDINT, LADDERC_T_ULINT,
    LADDERC_T_BYTE, LADDERC_T_WORD, LADDERC_T_DWORD, LADDERC_T_LWORD,
    LADDERC_T_REAL, LADDERC_T_LREAL, LADDERC_T_TIME, LADDERC_T_LTIME,
    LADDERC_T_DATE, LADDERC_T_TOD, LADDERC_T_DT, LADDERC_T_STRING, LADDERC_T_WSTRING,
    LADDERC_T_LDATE, LADDERC_T_LTOD, LADDERC_T_LDT, LADDERC_T_CHAR, LADDERC_T_WCHAR
} ladderc_type;

/* A watchable variable: either in memory (ptr) or located in an area (area != NULL: offset, bit). */
typedef struct {
    const char *name; /* `main.count`, `inst.count`, `%QX0.1` */
    ladderc_type type;
    void *ptr;
    uint8_t *area;
    uint32_t offset;
    uint8_t bit;
} ladderc_var;

extern const ladderc_var ladderc_vars[];
extern const size_t ladderc_var_count;
/* The access names declared READ_ONLY in VAR_ACCESS (NULL-terminated): a stimulus may not write them. */
extern const char *const ladderc_read_only[];
extern const size_t ladderc_read_only_count;
void ladderc_program_init(void);
void ladderc_program_scan(void);

/* Harness helpers (ladderc_rt.c), also usable by tests. Return 0 on success, -1 with a message in err. */
int ladderc_parse_value(ladderc_type t, const char *text, void *out, char *err, size_t errlen);
int ladderc_resolve_address(const char *text, ladderc_var *out, char *err, size_t errlen);
void ladderc_read_var(const ladderc_var *v, void *out);
void ladderc_write_var(const ladderc_var *v, const void *in);
void ladderc_format_value(ladderc_type t, const void *value, char *buf, size_t len);
unsigned ladderc_type_bytes(ladderc_type t);
int ladderc_parse_duration(const char *text, IEC_TIME *out);
const char *ladderc_type_name(ladderc_type t);

#endif
