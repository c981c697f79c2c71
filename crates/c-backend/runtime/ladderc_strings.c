/* ladderc runtime: the IEC 61131-3 character string functions (LEN, LEFT, RIGHT, MID, CONCAT, INSERT,
 * DELETE, REPLACE, FIND) on STRING (bytes) and WSTRING (UTF-16 code units).
 *
 * Input: string values (capacity LADDERC_STRING_CAP) and integer lengths/positions. Output: new string
 * values. Invariants: positions count from 1; every result is at most LADDERC_STRING_CAP units (a longer
 * one is truncated and sets LADDERC_ERR_STRING; the caller truncates further to the declared length when
 * it stores); an out-of-range length or position never reads or writes outside a buffer: it gives the
 * documented fallback result and sets LADDERC_ERR_STRPOS:
 *   LEFT/RIGHT  L < 0: ''                 L > LEN(IN): IN (no flag)
 *   MID         L < 0, P < 1 or P > LEN(IN) + 1: ''      L past the end: up to the end (no flag)
 *   INSERT      P < 0: inserted at the start; P > LEN(IN1): appended
 *   DELETE      L < 0, P < 1 or P > LEN(IN) + 1: IN unchanged    L past the end: up to the end
 *   REPLACE     L < 0, P < 1 or P > LEN(IN1) + 1: IN1 unchanged  L past the end: up to the end
 *   FIND        0 when IN2 does not occur in IN1 or IN2 is empty (no flag).
 * MAX, MIN and LIMIT order strings as the comparisons do (ladderc_string_cmp). */
#include "ladderc_rt.h"

/* Units [from, from + n) of `in`, clamped to its length. */
#define LADDERC_STR_FUNCS(P, S, U, SET, CMP)                                                             \
    static S P##_slice(const S *in, int64_t from, int64_t n) {                                     \
        S r;                                                                                        \
        memset(&r, 0, sizeof r);                                                                    \
        if (from < 0) from = 0;                                                                     \
        if (from > (int64_t)in->len) from = in->len;                                                \
        if (n < 0) n = 0;                                                                           \
        if (n > (int64_t)in->len - from) n = (int64_t)in->len - from;                               \
        SET(&r, in->data + from, (size_t)n, LADDERC_STRING_CAP);                                    \
        return r;                                                                                   \
    }                                                                                               \
    /* a[0, na) + b[0, nb) + a[sa, len a), truncated to the capacity */                            \
    static S P##_splice(const S *a, int64_t na, const S *b, int64_t nb, int64_t sa) {               \
        U buf[3 * LADDERC_STRING_CAP + 3];                                                          \
        size_t k = 0;                                                                               \
        S r;                                                                                        \
        memset(&r, 0, sizeof r);                                                                    \
        memcpy(buf, a->data, (size_t)na * sizeof(U));                                              \
        k += (size_t)na;                                                                            \
        memcpy(buf + k, b->data, (size_t)nb * sizeof(U));                                          \
        k += (size_t)nb;                                                                            \
        memcpy(buf + k, a->data + sa, (size_t)((int64_t)a->len - sa) * sizeof(U));                  \
        k += (size_t)((int64_t)a->len - sa);                                                        \
        SET(&r, buf, k, LADDERC_STRING_CAP);                                                        \
        return r;                                                                                   \
    }                                                                                               \
    IEC_INT P##_len(S in) { return (IEC_INT)in.len; }                                               \
    S P##_left(S in, int64_t l) {                                                                   \
        if (l < 0) { ladderc_errors |= LADDERC_ERR_STRPOS; l = 0; }                                 \
        return P##_slice(&in, 0, l);                                                                \
    }                                                                                               \
    S P##_right(S in, int64_t l) {                                                                  \
        if (l < 0) { ladderc_errors |= LADDERC_ERR_STRPOS; l = 0; }                                 \
        if (l > (int64_t)in.len) l = in.len;                                                        \
        return P##_slice(&in, (int64_t)in.len - l, l);                                              \
    }                                                                                               \
    S P##_mid(S in, int64_t l, int64_t p) {                                                         \
        if (l < 0 || p < 1 || p > (int64_t)in.len + 1) {                                            \
            ladderc_errors |= LADDERC_ERR_STRPOS;                                                   \
            return P##_slice(&in, 0, 0);                                                            \
        }                                                                                           \
        return P##_slice(&in, p - 1, l);                                                            \
    }                                                                                               \
    S P##_concat(S a, S b) { return P##_splice(&a, a.len, &b, b.len, a.len); }                      \
    S P##_insert(S a, S b, int64_t p) {                                                             \
        if (p < 0) { ladderc_errors |= LADDERC_ERR_STRPOS; p = 0; }                                 \
        if (p > (int64_t)a.len) { ladderc_errors |= LADDERC_ERR_STRPOS; p = a.len; }                \
        return P##_splice(&a, p, &b, b.len, p);                                                     \
    }                                                                                               \
    S P##_replace(S a, S b, int64_t l, int64_t p) {                                                 \
        int64_t end;                                                                                \
        if (l < 0 || p < 1 || p > (int64_t)a.len + 1) {                                             \
            ladderc_errors |= LADDERC_ERR_STRPOS;                                                   \
            return a;                                                                               \
        }                                                                                           \
        end = (l > (int64_t)a.len - (p - 1)) ? (int64_t)a.len : (p - 1) + l;                        \
        return P##_splice(&a, p - 1, &b, b.len, end);                                               \
    }                                                                                               \
    S P##_delete(S in, int64_t l, int64_t p) {                                                      \
        S none;                                                                                     \
        memset(&none, 0, sizeof none);                                                              \
        return P##_replace(in, none, l, p);                                                         \
    }                                                                                               \
    S P##_max(S a, S b) { return CMP(&a, &b) >= 0 ? a : b; }                                     \
    S P##_min(S a, S b) { return CMP(&a, &b) <= 0 ? a : b; }                                     \
    S P##_limit(S mn, S in, S mx) { return P##_min(P##_max(in, mn), mx); }                        \
    IEC_INT P##_find(S a, S b) {                                                                    \
        size_t i;                                                                                   \
        if (b.len == 0 || b.len > a.len) return 0;                                                  \
        for (i = 0; i + b.len <= a.len; i++)                                                        \
            if (memcmp(a.data + i, b.data, b.len * sizeof(U)) == 0) return (IEC_INT)(i + 1);        \
        return 0;                                                                                   \
    }

LADDERC_STR_FUNCS(ladderc_str, IEC_STRING, char, ladderc_string_set, ladderc_string_cmp)
LADDERC_STR_FUNCS(ladderc_wstr, IEC_WSTRING, uint16_t, ladderc_wstring_set, ladderc_wstring_cmp)

/* STRING_TO_DATE, STRING_TO_TOD, STRING_TO_DT: the IEC literal text (`D#2024-01-31`, `TOD#12:30:00`,
 * `DT#2024-01-31-12:30:00`, long prefixes too), or the same without its prefix, spaces around ignored; a
 * malformed text gives 0 (1970-01-01, midnight) and LADDERC_ERR_RANGE, as the other STRING_TO_*. */
static int64_t ladderc_str_to_datetime(IEC_STRING s, ladderc_type t, const char *prefix) {
    char buf[LADDERC_STRING_CAP + 8];
    size_t b = 0, e = s.len;
    int64_t v = 0;
    while (b < e && (s.data[b] == ' ' || s.data[b] == '\t')) b++;
    while (e > b && (s.data[e - 1] == ' ' || s.data[e - 1] == '\t')) e--;
    memcpy(buf, s.data + b, e - b);
    buf[e - b] = '\0';
    if (ladderc_parse_value(t, buf, &v, NULL, 0) == 0) return v;
    memmove(buf + strlen(prefix), buf, e - b + 1);
    memcpy(buf, prefix, strlen(prefix));
    if (ladderc_parse_value(t, buf, &v, NULL, 0) == 0) return v;
    ladderc_errors |= LADDERC_ERR_RANGE;
    return 0;
}
IEC_DATE ladderc_str_to_date(IEC_STRING s) { return ladderc_str_to_datetime(s, LADDERC_T_DATE, "D#"); }
IEC_TOD ladderc_str_to_tod(IEC_STRING s) { return ladderc_str_to_datetime(s, LADDERC_T_TOD, "TOD#"); }
IEC_DT ladderc_str_to_dt(IEC_STRING s) { return ladderc_str_to_datetime(s, LADDERC_T_DT, "DT#"); }
IEC_LDATE ladderc_str_to_ldate(IEC_STRING s) { return ladderc_str_to_datetime(s, LADDERC_T_LDATE, "LDATE#"); }
IEC_LTOD ladderc_str_to_ltod(IEC_STRING s) { return ladderc_str_to_datetime(s, LADDERC_T_LTOD, "LTOD#"); }
IEC_LDT ladderc_str_to_ldt(IEC_STRING s) { return ladderc_str_to_datetime(s, LADDERC_T_LDT, "LDT#"); }
