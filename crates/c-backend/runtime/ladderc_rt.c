/* ladderc runtime: standard function blocks, strings, and the value parsing/formatting the harness uses.
 * Input: the FB instance structs, the scan clock ladderc_now. Output: FB outputs per IEC 61131-3
 * (2nd/3rd edition semantics). Invariants: no undefined behaviour for any input value. */
#include "ladderc_rt.h"

#include <stdio.h>
#include <stdlib.h>
#include <ctype.h>
#include <errno.h>

uint32_t ladderc_errors = 0;
const char *ladderc_null_ref_site = "";
const char *ladderc_mem_site = "";
const char *ladderc_pointer_site = "";
const char *ladderc_char_index_site = "";
int64_t ladderc_char_index_at[3];
const char *ladderc_bounds_site = "";
int64_t ladderc_bounds_at[3];
IEC_TIME ladderc_now = 0;
uint64_t ladderc_cycle = 0;

/* ------------------------------------------------------------------ edge detection and bistables */
void ladderc_R_TRIG_init(ladderc_R_TRIG *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; }
void ladderc_R_TRIG_body(ladderc_R_TRIG *fb) {
    fb->Q = (IEC_BOOL)(fb->CLK && !fb->m);
    fb->m = fb->CLK ? 1u : 0u;
}
void ladderc_F_TRIG_init(ladderc_F_TRIG *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; }
void ladderc_F_TRIG_body(ladderc_F_TRIG *fb) {
    /* IEC: Q := NOT CLK AND NOT M; M := NOT CLK. */
    fb->Q = (IEC_BOOL)(!fb->CLK && !fb->m);
    fb->m = fb->CLK ? 0u : 1u;
}
void ladderc_SR_init(ladderc_SR *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; }
void ladderc_SR_body(ladderc_SR *fb) { fb->Q1 = (IEC_BOOL)(fb->S1 || (!fb->R && fb->Q1)); }
void ladderc_RS_init(ladderc_RS *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; }
void ladderc_RS_body(ladderc_RS *fb) { fb->Q1 = (IEC_BOOL)(!fb->R1 && (fb->S || fb->Q1)); }

/* ------------------------------------------------------------------ timers */
static IEC_TIME elapsed_since(IEC_TIME start) { return ladderc_sub_IEC_LINT(ladderc_now, start); }

/* TON, TOF, TP on TIME (S empty) and their edition-3 LTIME forms TON_LTIME ... (S _LTIME): the same
 * bodies on PT and ET of type T (both count nanoseconds here). */
#define LADDERC_TIMERS(S, T)                                                             \
void ladderc_TON##S##_init(ladderc_TON##S *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; } \
void ladderc_TON##S##_body(ladderc_TON##S *fb) {                                           \
    IEC_##T pt = fb->PT < 0 ? 0 : fb->PT;                                                \
    if (!fb->IN) {                                                                       \
        fb->Q = 0;                                                                       \
        fb->ET = 0;                                                                      \
        fb->running = 0;                                                                 \
        return;                                                                          \
    }                                                                                    \
    if (!fb->running) {                                                                  \
        fb->running = 1;                                                                 \
        fb->start = ladderc_now;                                                         \
    }                                                                                    \
    {                                                                                    \
        IEC_##T et = elapsed_since(fb->start);                                           \
        if (et >= pt) {                                                                  \
            fb->ET = pt;                                                                 \
            fb->Q = 1;                                                                   \
        } else {                                                                         \
            fb->ET = et;                                                                 \
            fb->Q = 0;                                                                   \
        }                                                                                \
    }                                                                                    \
}                                                                                        \
                                                                                         \
void ladderc_TOF##S##_init(ladderc_TOF##S *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; } \
void ladderc_TOF##S##_body(ladderc_TOF##S *fb) {                                           \
    IEC_##T pt = fb->PT < 0 ? 0 : fb->PT;                                                \
    if (fb->IN) {                                                                        \
        fb->Q = 1;                                                                       \
        fb->ET = 0;                                                                      \
        fb->running = 0;                                                                 \
        return;                                                                          \
    }                                                                                    \
    if (!fb->Q) return; /* idle: ET keeps its value (PT after a completed delay) */      \
    if (!fb->running) {                                                                  \
        fb->running = 1;                                                                 \
        fb->start = ladderc_now;                                                         \
    }                                                                                    \
    {                                                                                    \
        IEC_##T et = elapsed_since(fb->start);                                           \
        if (et >= pt) {                                                                  \
            fb->ET = pt;                                                                 \
            fb->Q = 0;                                                                   \
            fb->running = 0;                                                             \
        } else {                                                                         \
            fb->ET = et;                                                                 \
        }                                                                                \
    }                                                                                    \
}                                                                                        \
                                                                                         \
void ladderc_TP##S##_init(ladderc_TP##S *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; }   \
void ladderc_TP##S##_body(ladderc_TP##S *fb) {                                             \
    IEC_##T pt = fb->PT < 0 ? 0 : fb->PT;                                                \
    IEC_BOOL edge = (IEC_BOOL)(fb->IN && !fb->in_m);                                     \
    fb->in_m = fb->IN ? 1u : 0u;                                                         \
    /* The rising edge sets Q in this call whatever PT is (IEC 61131-3 ed. 3 Table 45's  \
     * diagram; CODESYS: "Rising edge starts the pulse timer and sets Q to TRUE"); the    \
     * pulse ends in a later call once ET reaches PT, so PT = T#0s gives a one-scan pulse \
     * (matiec's TP does the same: OpenPLC/Beremiz projects use it as a pulse former). */ \
    if (!fb->running && edge) {                                                          \
        fb->running = 1;                                                                 \
        fb->start = ladderc_now;                                                         \
        fb->Q = 1;                                                                       \
        fb->ET = 0;                                                                      \
    } else if (fb->running) {                                                            \
        IEC_##T et = elapsed_since(fb->start);                                           \
        if (et >= pt) {                                                                  \
            fb->running = 0;                                                             \
            fb->Q = 0;                                                                   \
            fb->ET = pt;                                                                 \
        } else {                                                                         \
            fb->Q = 1;                                                                   \
            fb->ET = et;                                                                 \
        }                                                                                \
    }                                                                                    \
    if (!fb->running && !fb->IN) fb->ET = 0;                                             \
}
LADDERC_TIMERS(, TIME)
LADDERC_TIMERS(_LTIME, LTIME)

/* ------------------------------------------------------------------ counters */
void ladderc_CTU_init(ladderc_CTU *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; }
void ladderc_CTU_body(ladderc_CTU *fb) {
    IEC_BOOL edge = (IEC_BOOL)(fb->CU && !fb->cu_m);
    fb->cu_m = fb->CU ? 1u : 0u;
    if (fb->R) fb->CV = 0;
    else if (edge && fb->CV < INT16_MAX) fb->CV = (IEC_INT)(fb->CV + 1);
    fb->Q = (IEC_BOOL)(fb->CV >= fb->PV);
}
void ladderc_CTD_init(ladderc_CTD *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; }
void ladderc_CTD_body(ladderc_CTD *fb) {
    IEC_BOOL edge = (IEC_BOOL)(fb->CD && !fb->cd_m);
    fb->cd_m = fb->CD ? 1u : 0u;
    if (fb->LD) fb->CV = fb->PV;
    else if (edge && fb->CV > INT16_MIN) fb->CV = (IEC_INT)(fb->CV - 1);
    fb->Q = (IEC_BOOL)(fb->CV <= 0);
}
void ladderc_CTUD_init(ladderc_CTUD *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; }
void ladderc_CTUD_body(ladderc_CTUD *fb) {
    IEC_BOOL up = (IEC_BOOL)(fb->CU && !fb->cu_m);
    IEC_BOOL down = (IEC_BOOL)(fb->CD && !fb->cd_m);
    fb->cu_m = fb->CU ? 1u : 0u;
    fb->cd_m = fb->CD ? 1u : 0u;
    if (fb->R) fb->CV = 0;
    else if (fb->LD) fb->CV = fb->PV;
    else if (!(up && down)) {
        if (up && fb->CV < INT16_MAX) fb->CV = (IEC_INT)(fb->CV + 1);
        else if (down && fb->CV > INT16_MIN) fb->CV = (IEC_INT)(fb->CV - 1);
    }
    fb->QU = (IEC_BOOL)(fb->CV >= fb->PV);
    fb->QD = (IEC_BOOL)(fb->CV <= 0);
}
/* The typed counters: as above, saturating at the range of T (MIN..MAX). */
#define LADDERC_COUNTER_BODIES(T, MIN, MAX)                                                        \
    void ladderc_CTU_##T##_init(ladderc_CTU_##T *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; }               \
    void ladderc_CTU_##T##_body(ladderc_CTU_##T *fb) {                                             \
        IEC_BOOL edge = (IEC_BOOL)(fb->CU && !fb->cu_m);                                           \
        fb->cu_m = fb->CU ? 1u : 0u;                                                               \
        if (fb->R) fb->CV = 0;                                                                     \
        else if (edge && fb->CV < (MAX)) fb->CV = (IEC_##T)(fb->CV + 1);                           \
        fb->Q = (IEC_BOOL)(fb->CV >= fb->PV);                                                      \
    }                                                                                              \
    void ladderc_CTD_##T##_init(ladderc_CTD_##T *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; }               \
    void ladderc_CTD_##T##_body(ladderc_CTD_##T *fb) {                                             \
        IEC_BOOL edge = (IEC_BOOL)(fb->CD && !fb->cd_m);                                           \
        fb->cd_m = fb->CD ? 1u : 0u;                                                               \
        if (fb->LD) fb->CV = fb->PV;                                                               \
        else if (edge && fb->CV > (MIN)) fb->CV = (IEC_##T)(fb->CV - 1);                           \
        fb->Q = (IEC_BOOL)(fb->CV <= 0);                                                           \
    }                                                                                              \
    void ladderc_CTUD_##T##_init(ladderc_CTUD_##T *fb) { memset(fb, 0, sizeof *fb); fb->ENO = 1; }             \
    void ladderc_CTUD_##T##_body(ladderc_CTUD_##T *fb) {                                           \
        IEC_BOOL up = (IEC_BOOL)(fb->CU && !fb->cu_m);                                             \
        IEC_BOOL down = (IEC_BOOL)(fb->CD && !fb->cd_m);                                           \
        fb->cu_m = fb->CU ? 1u : 0u;                                                               \
        fb->cd_m = fb->CD ? 1u : 0u;                                                               \
        if (fb->R) fb->CV = 0;                                                                     \
        else if (fb->LD) fb->CV = fb->PV;                                                          \
        else if (!(up && down)) {                                                                  \
            if (up && fb->CV < (MAX)) fb->CV = (IEC_##T)(fb->CV + 1);                              \
            else if (down && fb->CV > (MIN)) fb->CV = (IEC_##T)(fb->CV - 1);                       \
        }                                                                                          \
        fb->QU = (IEC_BOOL)(fb->CV >= fb->PV);                                                     \
        fb->QD = (IEC_BOOL)(fb->CV <= 0);                                                          \
    }
LADDERC_COUNTER_BODIES(DINT, INT32_MIN, INT32_MAX)
LADDERC_COUNTER_BODIES(LINT, INT64_MIN, INT64_MAX)
LADDERC_COUNTER_BODIES(UDINT, 0u, UINT32_MAX)
LADDERC_COUNTER_BODIES(ULINT, 0u, UINT64_MAX)
/* Tc2_Standard / CODESYS Standard: CTD counts down "as long as CV is greater than 0" (Infosys). */
LADDERC_COUNTER_BODIES(WORD, 0u, UINT16_MAX)

/* ------------------------------------------------------------------ strings */
void ladderc_string_set(IEC_STRING *dst, const char *src, size_t len, unsigned cap) {
    if (cap > LADDERC_STRING_CAP) cap = LADDERC_STRING_CAP;
    if (len > cap) {
        len = cap;
        ladderc_errors |= LADDERC_ERR_STRING;
    }
    memmove(dst->data, src, len);
    dst->data[len] = '\0';
    dst->len = (uint16_t)len;
}
void ladderc_string_copy(IEC_STRING *dst, const IEC_STRING *src, unsigned cap) {
    ladderc_string_set(dst, src->data, src->len, cap);
}
int ladderc_string_cmp(const IEC_STRING *a, const IEC_STRING *b) {
    size_t n = a->len < b->len ? a->len : b->len;
    int c = memcmp(a->data, b->data, n);
    if (c != 0) return c < 0 ? -1 : 1;
    return a->len == b->len ? 0 : (a->len < b->len ? -1 : 1);
}
void ladderc_string_concat(IEC_STRING *dst, const IEC_STRING *a, const IEC_STRING *b, unsigned cap) {
    char buf[2 * LADDERC_STRING_CAP + 2];
    memcpy(buf, a->data, a->len);
    memcpy(buf + a->len, b->data, b->len);
    ladderc_string_set(dst, buf, (size_t)a->len + b->len, cap);
}
IEC_STRING ladderc_str_lit(const char *bytes, size_t len) {
    IEC_STRING s;
    memset(&s, 0, sizeof s);
    ladderc_string_set(&s, bytes, len, LADDERC_STRING_CAP);
    return s;
}
IEC_STRING ladderc_str_cap(IEC_STRING s, unsigned cap) {
    IEC_STRING r;
    memset(&r, 0, sizeof r);
    ladderc_string_set(&r, s.data, s.len, cap);
    return r;
}
int ladderc_str_cmpv(IEC_STRING a, IEC_STRING b) { return ladderc_string_cmp(&a, &b); }
IEC_WSTRING ladderc_wstr_lit(const uint16_t *units, size_t len) {
    IEC_WSTRING s;
    memset(&s, 0, sizeof s);
    ladderc_wstring_set(&s, units, len, LADDERC_STRING_CAP);
    return s;
}
IEC_WSTRING ladderc_wstr_cap(IEC_WSTRING s, unsigned cap) {
    IEC_WSTRING r;
    memset(&r, 0, sizeof r);
    ladderc_wstring_set(&r, s.data, s.len, cap);
    return r;
}
int ladderc_wstr_cmpv(IEC_WSTRING a, IEC_WSTRING b) { return ladderc_wstring_cmp(&a, &b); }

/* UTF-8 text to UTF-16 units; -1 on malformed UTF-8 or more than `cap` units. */
static int utf8_to_utf16(const char *t, size_t n, uint16_t *out, size_t cap, size_t *count) {
    size_t i = 0, k = 0;
    while (i < n) {
        unsigned char c = (unsigned char)t[i];
        uint32_t cp;
        int more, j;
        if (c < 0x80) { cp = c; more = 0; }
        else if ((c & 0xE0) == 0xC0) { cp = c & 0x1Fu; more = 1; }
        else if ((c & 0xF0) == 0xE0) { cp = c & 0x0Fu; more = 2; }
        else if ((c & 0xF8) == 0xF0) { cp = c & 0x07u; more = 3; }
        else return -1;
        for (j = 1; j <= more; j++) {
            unsigned char d;
            if (i + (size_t)j >= n) return -1;
            d = (unsigned char)t[i + (size_t)j];
            if ((d & 0xC0) != 0x80) return -1;
            cp = (cp << 6) | (d & 0x3Fu);
        }
        i += (size_t)more + 1;
        if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return -1;
        if (cp >= 0x10000) {
            if (k + 2 > cap) return -1;
            cp -= 0x10000;
            out[k++] = (uint16_t)(0xD800 + (cp >> 10));
            out[k++] = (uint16_t)(0xDC00 + (cp & 0x3FF));
        } else {
            if (k + 1 > cap) return -1;
            out[k++] = (uint16_t)cp;
        }
    }
    *count = k;
    return 0;
}
void ladderc_wstring_set(IEC_WSTRING *dst, const uint16_t *src, size_t len, unsigned cap) {
    if (cap > LADDERC_STRING_CAP) cap = LADDERC_STRING_CAP;
    if (len > cap) {
        len = cap;
        ladderc_errors |= LADDERC_ERR_STRING;
    }
    memmove(dst->data, src, len * sizeof(uint16_t));
    dst->data[len] = 0;
    dst->len = (uint16_t)len;
}
int ladderc_wstring_cmp(const IEC_WSTRING *a, const IEC_WSTRING *b) {
    size_t n = a->len < b->len ? a->len : b->len, i;
    for (i = 0; i < n; i++)
        if (a->data[i] != b->data[i]) return a->data[i] < b->data[i] ? -1 : 1;
    return a->len == b->len ? 0 : (a->len < b->len ? -1 : 1);
}

/* ------------------------------------------------------------------ values as text (harness) */
static const char *const type_names[] = {
    "BOOL", "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "BYTE", "WORD",
    "DWORD", "LWORD", "REAL", "LREAL", "TIME", "LTIME", "DATE", "TIME_OF_DAY", "DATE_AND_TIME", "STRING",
    "WSTRING", "LDATE", "LTIME_OF_DAY", "LDATE_AND_TIME", "CHAR", "WCHAR"};

const char *ladderc_type_name(ladderc_type t) {
    return (unsigned)t < sizeof type_names / sizeof type_names[0] ? type_names[t] : "?";
}

static int fail(char *err, size_t errlen, const char *msg, const char *text) {
    if (err && errlen) snprintf(err, errlen, "%s: `%s`", msg, text);
    return -1;
}

static int fail_type(char *err, size_t errlen, const char *msg, ladderc_type t, const char *text) {
    if (err && errlen) snprintf(err, errlen, "%s %s: `%s`", msg, ladderc_type_name(t), text);
    return -1;
}

static int ieq_prefix(const char *s, const char *prefix) {
    while (*prefix) {
        if (toupper((unsigned char)*s) != toupper((unsigned char)*prefix)) return 0;
        s++;
        prefix++;
    }
    return 1;
}

/* Skips `NAME#` when NAME is one of the given prefixes (case-insensitive). */
static const char *skip_prefix(const char *s, const char *const *prefixes) {
    for (; *prefixes; prefixes++) {
        size_t n = strlen(*prefixes);
        if (ieq_prefix(s, *prefixes) && s[n] == '#') return s + n + 1;
    }
    return s;
}

/* IEC integer literal: [+-] digits | 2#.. | 8#.. | 16#.., underscores between digits. */
static int parse_integer(const char *s, int *neg, uint64_t *mag) {
    unsigned base = 10;
    uint64_t v = 0;
    int digits = 0;
    *neg = 0;
    if (*s == '+' || *s == '-') {
        *neg = *s == '-';
        s++;
    }
    if (s[0] == '2' && s[1] == '#') { base = 2; s += 2; }
    else if (s[0] == '8' && s[1] == '#') { base = 8; s += 2; }
    else if (s[0] == '1' && s[1] == '6' && s[2] == '#') { base = 16; s += 3; }
    for (; *s; s++) {
        unsigned d;
        if (*s == '_' && digits) continue;
        if (*s >= '0' && *s <= '9') d = (unsigned)(*s - '0');
        else if (*s >= 'a' && *s <= 'f') d = (unsigned)(*s - 'a' + 10);
        else if (*s >= 'A' && *s <= 'F') d = (unsigned)(*s - 'A' + 10);
        else return -1;
        if (d >= base) return -1;
        if (v > (UINT64_MAX - d) / base) return -1;
        v = v * base + d;
        digits++;
    }
    if (!digits) return -1;
    *mag = v;
    return 0;
}

/* Duration `T#1h2m3s4ms5us6ns`, `TIME#-1.5s`, `LTIME#...`, `T#1d_2h`. */
int ladderc_parse_duration(const char *text, IEC_TIME *out) {
    static const char *const prefixes[] = {"LTIME", "TIME", "LT", "T", NULL};
    const char *s = skip_prefix(text, prefixes);
    double total = 0;
    int neg = 0, parts = 0;
    if (s == text) return -1;
    if (*s == '-' || *s == '+') {
        neg = *s == '-';
        s++;
    }
    while (*s) {
        char *end;
        double v, unit;
        if (*s == '_') { s++; continue; }
        if (!isdigit((unsigned char)*s)) return -1;
        errno = 0;
        v = strtod(s, &end);
        if (end == s || errno) return -1;
        s = end;
        if (ieq_prefix(s, "ms")) { unit = 1e6; s += 2; }
        else if (ieq_prefix(s, "us")) { unit = 1e3; s += 2; }
        else if (ieq_prefix(s, "ns")) { unit = 1; s += 2; }
        else if (ieq_prefix(s, "d")) { unit = 86400e9; s += 1; }
        else if (ieq_prefix(s, "h")) { unit = 3600e9; s += 1; }
        else if (ieq_prefix(s, "m")) { unit = 60e9; s += 1; }
        else if (ieq_prefix(s, "s")) { unit = 1e9; s += 1; }
        else return -1;
        total += v * unit;
        parts++;
    }
    if (!parts || total > 9.2e18) return -1;
    *out = (IEC_TIME)llround(neg ? -total : total);
    return 0;
}

/* Days since 1970-01-01 from a civil date (H. Hinnant's algorithm). */
static int64_t days_from_civil(int64_t y, unsigned m, unsigned d) {
    int64_t era;
    unsigned yoe, doy, doe;
    y -= m <= 2;
    era = (y >= 0 ? y : y - 399) / 400;
    yoe = (unsigned)(y - era * 400);
    doy = (153 * (m + (m > 2 ? (unsigned)-3 : 9)) + 2) / 5 + d - 1;
    doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + (int64_t)doe - 719468;
}
static void civil_from_days(int64_t z, int64_t *y, unsigned *m, unsigned *d) {
    int64_t era;
    unsigned doe, yoe, doy, mp;
    z += 719468;
    era = (z >= 0 ? z : z - 146096) / 146097;
    doe = (unsigned)(z - era * 146097);
    yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    *y = (int64_t)yoe + era * 400;
    doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    mp = (5 * doy + 2) / 153;
    *d = doy - (153 * mp + 2) / 5 + 1;
    *m = mp < 10 ? mp + 3 : mp - 9;
    *y += *m <= 2;
}

/* Days of a valid date (0 and *ok = 0 otherwise; DT must stay inside int64 nanoseconds). */
static int64_t date_days(int64_t y, int64_t m, int64_t d, int *ok) {
    static const unsigned mdays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    int leap;
    int64_t days;
    *ok = 0;
    if (y < 1677 || y > 2262 || m < 1 || m > 12 || d < 1) return 0;
    leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
    if (d > (int64_t)mdays[m - 1] + (m == 2 && leap)) return 0;
    days = days_from_civil(y, (unsigned)m, (unsigned)d);
    if (days < -106751 || days > 106750) return 0;
    *ok = 1;
    return days;
}
static int64_t tod_ns(int64_t h, int64_t mi, int64_t s, int64_t ms, int *ok) {
    *ok = h >= 0 && h <= 23 && mi >= 0 && mi <= 59 && s >= 0 && s <= 59 && ms >= 0 && ms <= 999;
    if (!*ok) return 0;
    return ((h * 60 + mi) * 60 + s) * 1000000000LL + ms * 1000000LL;
}
IEC_DATE ladderc_concat_date(int64_t year, int64_t month, int64_t day) {
    int ok;
    int64_t days = date_days(year, month, day, &ok);
    if (!ok) { ladderc_errors |= LADDERC_ERR_RANGE; return 0; }
    return days * LADDERC_NS_PER_DAY;
}
IEC_TOD ladderc_concat_tod(int64_t hour, int64_t minute, int64_t second, int64_t ms) {
    int ok;
    int64_t ns = tod_ns(hour, minute, second, ms, &ok);
    if (!ok) ladderc_errors |= LADDERC_ERR_RANGE;
    return ns;
}
IEC_DT ladderc_concat_dt(int64_t year, int64_t month, int64_t day, int64_t hour, int64_t minute, int64_t second,
                         int64_t ms) {
    int ok_d, ok_t;
    int64_t days = date_days(year, month, day, &ok_d), ns = tod_ns(hour, minute, second, ms, &ok_t);
    if (!ok_d || !ok_t) { ladderc_errors |= LADDERC_ERR_RANGE; return 0; }
    /* |days| <= 106751 and ns < one day: inside int64 */
    return days * LADDERC_NS_PER_DAY + ns;
}
IEC_INT ladderc_day_of_week(int64_t date) {
    int64_t days = date / LADDERC_NS_PER_DAY - (date % LADDERC_NS_PER_DAY < 0);
    int64_t w = (days + 4) % 7; /* 1970-01-01 was a Thursday */
    return (IEC_INT)(w < 0 ? w + 7 : w);
}

void ladderc_split(int64_t ns, IEC_LINT parts[7]) {
    int64_t days = ns / LADDERC_NS_PER_DAY - (ns % LADDERC_NS_PER_DAY < 0);
    int64_t rem = ns - days * LADDERC_NS_PER_DAY; /* 0 .. one day */
    int64_t y;
    unsigned m, d;
    civil_from_days(days, &y, &m, &d);
    parts[0] = y;
    parts[1] = (IEC_LINT)m;
    parts[2] = (IEC_LINT)d;
    parts[3] = rem / 3600000000000LL;
    parts[4] = rem / 60000000000LL % 60;
    parts[5] = rem / 1000000000LL % 60;
    parts[6] = rem / 1000000LL % 1000;
}

static int parse_date(const char **sp, int64_t *days) {
    int y, m, d, n = 0;
    if (sscanf(*sp, "%4d-%2d-%2d%n", &y, &m, &d, &n) != 3 || m < 1 || m > 12 || d < 1 || d > 31) return -1;
    *days = days_from_civil(y, (unsigned)m, (unsigned)d);
    *sp += n;
    return 0;
}
static int parse_tod(const char *s, IEC_TOD *out) {
    int h, mi, n = 0;
    double sec;
    char *end;
    if (sscanf(s, "%2d:%2d:%n", &h, &mi, &n) != 2 || !n || h > 23 || mi > 59 || h < 0 || mi < 0) return -1;
    sec = strtod(s + n, &end);
    if (end == s + n || *end || sec < 0 || sec >= 60) return -1;
    *out = (IEC_TOD)llround(((double)h * 3600 + mi * 60 + sec) * 1e9);
    return 0;
}

static int parse_unsigned_in(const char *s, uint64_t max, uint64_t *out) {
    int neg;
    uint64_t mag;
    if (parse_integer(s, &neg, &mag) || (neg && mag) || mag > max) return -1;
    *out = mag;
    return 0;
}
static int parse_signed_in(const char *s, int64_t min, int64_t max, int64_t *out) {
    int neg;
    uint64_t mag;
    if (parse_integer(s, &neg, &mag)) return -1;
    if (neg) {
        if (mag > (uint64_t)max + 1u || (min == 0 && mag)) return -1;
        *out = mag == (uint64_t)max + 1u ? min : -(int64_t)mag;
        if (*out < min) return -1;
    } else {
        if (mag > (uint64_t)max) return -1;
        *out = (int64_t)mag;
    }
    return 0;
}

int ladderc_parse_value(ladderc_type t, const char *text, void *out, char *err, size_t errlen) {
    static const char *const int_prefixes[] = {"SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT",
                                               "ULINT", "BYTE", "WORD", "DWORD", "LWORD", NULL};
    static const char *const real_prefixes[] = {"REAL", "LREAL", NULL};
    const char *s = text;
    int64_t sv = 0;
    uint64_t uv = 0;
    switch (t) {
    case LADDERC_T_BOOL: {
        static const char *const p[] = {"BOOL", NULL};
        s = skip_prefix(text, p);
        if (!strcmp(s, "1") || (ieq_prefix(s, "TRUE") && strlen(s) == 4)) *(IEC_BOOL *)out = 1;
        else if (!strcmp(s, "0") || (ieq_prefix(s, "FALSE") && strlen(s) == 5)) *(IEC_BOOL *)out = 0;
        else return fail(err, errlen, "expected TRUE, FALSE, 1 or 0 for a BOOL", text);
        return 0;
    }
#define SIGNED_CASE(TAG, CT, MIN, MAX)                                                             \
    case TAG:                                                                                     \
        if (parse_signed_in(skip_prefix(text, int_prefixes), MIN, MAX, &sv))                      \
            return fail_type(err, errlen, "expected an integer in the range of", TAG, text);      \
        *(CT *)out = (CT)sv;                                                                      \
        return 0;
#define UNSIGNED_CASE(TAG, CT, MAX)                                                                \
    case TAG:                                                                                     \
        if (parse_unsigned_in(skip_prefix(text, int_prefixes), MAX, &uv))                         \
            return fail_type(err, errlen, "expected an integer in the range of", TAG, text);      \
        *(CT *)out = (CT)uv;                                                                      \
        return 0;
        SIGNED_CASE(LADDERC_T_SINT, IEC_SINT, INT8_MIN, INT8_MAX)
        SIGNED_CASE(LADDERC_T_INT, IEC_INT, INT16_MIN, INT16_MAX)
        SIGNED_CASE(LADDERC_T_DINT, IEC_DINT, INT32_MIN, INT32_MAX)
        SIGNED_CASE(LADDERC_T_LINT, IEC_LINT, INT64_MIN, INT64_MAX)
        UNSIGNED_CASE(LADDERC_T_USINT, IEC_USINT, UINT8_MAX)
        UNSIGNED_CASE(LADDERC_T_UINT, IEC_UINT, UINT16_MAX)
        UNSIGNED_CASE(LADDERC_T_UDINT, IEC_UDINT, UINT32_MAX)
        UNSIGNED_CASE(LADDERC_T_ULINT, IEC_ULINT, UINT64_MAX)
        UNSIGNED_CASE(LADDERC_T_BYTE, IEC_BYTE, UINT8_MAX)
        UNSIGNED_CASE(LADDERC_T_WORD, IEC_WORD, UINT16_MAX)
        UNSIGNED_CASE(LADDERC_T_DWORD, IEC_DWORD, UINT32_MAX)
        UNSIGNED_CASE(LADDERC_T_LWORD, IEC_LWORD, UINT64_MAX)
#undef SIGNED_CASE
#undef UNSIGNED_CASE
    case LADDERC_T_REAL:
    case LADDERC_T_LREAL: {
        char *end;
        double d;
        s = skip_prefix(text, real_prefixes);
        errno = 0;
        d = strtod(s, &end);
        if (end == s || *end || isspace((unsigned char)*s))
            return fail(err, errlen, "expected a number for a REAL", text);
        if (t == LADDERC_T_REAL) *(IEC_REAL *)out = (IEC_REAL)d;
        else *(IEC_LREAL *)out = d;
        return 0;
    }
    case LADDERC_T_TIME:
    case LADDERC_T_LTIME:
        if (ladderc_parse_duration(text, (IEC_TIME *)out))
            return fail(err, errlen, "expected a duration like T#1s500ms", text);
        return 0;
    case LADDERC_T_DATE: {
        static const char *const p[] = {"DATE", "D", NULL};
        int64_t days;
        s = skip_prefix(text, p);
        if (s == text || parse_date(&s, &days) || *s)
            return fail(err, errlen, "expected a date like D#2024-01-31", text);
        *(IEC_DATE *)out = days * 86400 * (int64_t)1000000000;
        return 0;
    }
    case LADDERC_T_TOD: {
        static const char *const p[] = {"TIME_OF_DAY", "TOD", NULL};
        s = skip_prefix(text, p);
        if (s == text || parse_tod(s, (IEC_TOD *)out))
            return fail(err, errlen, "expected a time of day like TOD#12:30:00", text);
        return 0;
    }
    case LADDERC_T_DT: {
        static const char *const p[] = {"DATE_AND_TIME", "DT", NULL};
        int64_t days;
        IEC_TOD tod;
        s = skip_prefix(text, p);
        if (s == text || parse_date(&s, &days) || *s != '-' || parse_tod(s + 1, &tod))
            return fail(err, errlen, "expected a date and time like DT#2024-01-31-12:30:00", text);
        *(IEC_DT *)out = days * 86400 * (int64_t)1000000000 + tod;
        return 0;
    }
    case LADDERC_T_LDATE:
    case LADDERC_T_LTOD:
    case LADDERC_T_LDT: {
        /* edition 3's long forms: the short form's text under a long prefix (LDATE#, LD#, LTOD#,
         * LTIME_OF_DAY#, LDT#, LDATE_AND_TIME#) or a short one */
        static const char *const pd[] = {"LDATE", "LD", NULL};
        static const char *const pt[] = {"LTIME_OF_DAY", "LTOD", NULL};
        static const char *const pdt[] = {"LDATE_AND_TIME", "LDT", NULL};
        const char *shortp = t == LADDERC_T_LDATE ? "D#" : t == LADDERC_T_LTOD ? "TOD#" : "DT#";
        ladderc_type st = t == LADDERC_T_LDATE ? LADDERC_T_DATE : t == LADDERC_T_LTOD ? LADDERC_T_TOD : LADDERC_T_DT;
        char longer[96];
        size_t ns, nl;
        s = skip_prefix(text, t == LADDERC_T_LDATE ? pd : t == LADDERC_T_LTOD ? pt : pdt);
        if (s == text) return ladderc_parse_value(st, text, out, err, errlen);
        ns = strlen(shortp);
        nl = strlen(s);
        if (ns + nl >= sizeof longer)
            return fail(err, errlen, "expected a date or time of day", text);
        memcpy(longer, shortp, ns);
        memcpy(longer + ns, s, nl + 1);
        return ladderc_parse_value(st, longer, out, err, errlen);
    }
    case LADDERC_T_CHAR:
    case LADDERC_T_WCHAR: {
        /* edition 3's characters: `CHAR#'A'`, `'A'`, `A`, `WCHAR#"A"`, `"A"`; inside quotes the
         * IEC escapes `$$` `$'` `$"` `$L` `$N` `$P` `$R` `$T` and `$hh` (CHAR) / `$hhhh` (WCHAR) */
        static const char *const pc[] = {"CHAR", NULL};
        static const char *const pw[] = {"WCHAR", NULL};
        int wide = t == LADDERC_T_WCHAR;
        size_t len, count = 0;
        uint16_t units[4];
        uint32_t code;
        s = skip_prefix(text, wide ? pw : pc);
        len = strlen(s);
        if (len >= 3 && (s[0] == '\'' || s[0] == '"') && s[len - 1] == s[0] && s[1] == '$') {
            const char *e = s + 2;
            size_t n = len - 3, digits = wide ? 4 : 2, i;
            char c = (char)toupper((unsigned char)e[0]);
            if (n == 1 && (c == '$' || c == '\'' || c == '"')) code = (unsigned char)c;
            else if (n == 1 && (c == 'L' || c == 'N')) code = 0x0A;
            else if (n == 1 && c == 'P') code = 0x0C;
            else if (n == 1 && c == 'R') code = 0x0D;
            else if (n == 1 && c == 'T') code = 0x09;
            else if (n == digits) {
                code = 0;
                for (i = 0; i < n; i++) {
                    if (!isxdigit((unsigned char)e[i]))
                        return fail(err, errlen, "expected `$` and hexadecimal digits", text);
                    code = code * 16 + (uint32_t)(isdigit((unsigned char)e[i]) ? e[i] - '0' : toupper((unsigned char)e[i]) - 'A' + 10);
                }
            } else {
                return fail(err, errlen, wide ? "expected an escape `$$`, `$\"`, `$N` ... or `$hhhh`" : "expected an escape `$$`, `$'`, `$N` ... or `$hh`", text);
            }
        } else {
            if (len >= 2 && (s[0] == '\'' || s[0] == '"') && s[len - 1] == s[0]) {
                s++;
                len -= 2;
            }
            if (utf8_to_utf16(s, len, units, 4, &count) || count != 1)
                return fail(err, errlen, wide ? "expected one character for a WCHAR" : "expected one character for a CHAR", text);
            code = units[0];
        }
        if (wide) {
            *(IEC_WCHAR *)out = (IEC_WCHAR)code;
        } else {
            if (code > 0xFF)
                return fail(err, errlen, "a CHAR holds the characters U+0000-U+00FF; use a WCHAR", text);
            *(IEC_CHAR *)out = (IEC_CHAR)code;
        }
        return 0;
    }
    case LADDERC_T_STRING: {
        /* UTF-8 text; a STRING holds each character U+0000-U+00FF as one byte (ISO 8859-1) */
        size_t len = strlen(text), count = 0, i;
        uint16_t units[LADDERC_STRING_CAP];
        char bytes[LADDERC_STRING_CAP];
        if (len >= 2 && (text[0] == '\'' || text[0] == '"') && text[len - 1] == text[0]) {
            text++;
            len -= 2;
        }
        if (utf8_to_utf16(text, len, units, LADDERC_STRING_CAP, &count))
            return fail(err, errlen, "expected UTF-8 text of at most 254 characters", text);
        for (i = 0; i < count; i++) {
            if (units[i] > 0xFF)
                return fail(err, errlen,
                            "a STRING holds the characters U+0000-U+00FF, one byte each; use a WSTRING", text);
            bytes[i] = (char)units[i];
        }
        ladderc_string_set((IEC_STRING *)out, bytes, count, LADDERC_STRING_CAP);
        return 0;
    }
    case LADDERC_T_WSTRING: {
        size_t len = strlen(text), count = 0;
        uint16_t units[LADDERC_STRING_CAP];
        if (len >= 2 && (text[0] == '\'' || text[0] == '"') && text[len - 1] == text[0]) {
            text++;
            len -= 2;
        }
        if (utf8_to_utf16(text, len, units, LADDERC_STRING_CAP, &count))
            return fail(err, errlen, "expected UTF-8 text of at most 254 UTF-16 units", text);
        ladderc_wstring_set((IEC_WSTRING *)out, units, count, LADDERC_STRING_CAP);
        return 0;
    }
    }
    return fail(err, errlen, "unsupported type", text);
}

/* `%IX3.6`, `%QW2`, `%MD4`, `%I0.1` (no size letter: a bit). */
int ladderc_resolve_address(const char *text, ladderc_var *out, char *err, size_t errlen) {
    const char *s = text;
    uint8_t *area;
    uint32_t size, nbytes = 1, offset;
    unsigned long idx, bit = 0;
    int is_bit = 0;
    char *end;
    if (*s++ != '%') return fail(err, errlen, "not an address", text);
    switch (toupper((unsigned char)*s++)) {
    case 'I': area = ladderc_I; size = LADDERC_I_FLAT_SIZE; break;
    case 'Q': area = ladderc_Q; size = LADDERC_Q_FLAT_SIZE; break;
    case 'M': area = ladderc_M; size = LADDERC_M_FLAT_SIZE; break;
    default: return fail(err, errlen, "unknown area (expected %I, %Q or %M)", text);
    }
    switch (toupper((unsigned char)*s)) {
    case 'X': is_bit = 1; s++; break;
    case 'B': nbytes = 1; out->type = LADDERC_T_BYTE; s++; break;
    case 'W': nbytes = 2; out->type = LADDERC_T_WORD; s++; break;
    case 'D': nbytes = 4; out->type = LADDERC_T_DWORD; s++; break;
    case 'L': nbytes = 8; out->type = LADDERC_T_LWORD; s++; break;
    default: is_bit = 1; break;
    }
    if (!isdigit((unsigned char)*s)) return fail(err, errlen, "expected a number in the address", text);
    errno = 0;
    idx = strtoul(s, &end, 10);
    if (errno || idx > 0xFFFFFFFFul) return fail(err, errlen, "address out of range", text);
    s = end;
    if (is_bit) {
        if (*s == '.') {
            if (!isdigit((unsigned char)s[1])) return fail(err, errlen, "expected the bit number after `.`", text);
            bit = strtoul(s + 1, &end, 10);
            s = end;
            if (bit > 7) return fail(err, errlen, "bit number above 7", text);
        } else {
            /* `%IX13`: absolute bit 13 = byte 1, bit 5 */
            bit = idx % 8;
            idx /= 8;
        }
        out->type = LADDERC_T_BOOL;
    }
    if (*s) return fail(err, errlen, "unexpected text after the address", text);
    {
        /* per-size images (%I and %Q; %M too with LADDERC_PER_SIZE_M): X and B, W, D, L, each a
           quarter of the flat size; %M's TM window stays flat, in the first image */
        uint32_t image = 0;
        int per_size = area == ladderc_M ? LADDERC_PER_SIZE_M : LADDERC_PER_SIZE_IO;
        if (per_size) {
            size /= 4;
            image = is_bit || nbytes == 1 ? 0 : nbytes == 2 ? 1 : nbytes == 4 ? 2 : 3;
        }
        offset = (uint32_t)(LADDERC_ADDR_BYTE_OFFSET ? idx : idx * nbytes);
        if ((unsigned long)offset != (LADDERC_ADDR_BYTE_OFFSET ? idx : idx * nbytes) || offset >= size ||
            size - offset < nbytes)
            return fail(err, errlen, "address outside the area's size in the target profile", text);
        if (area == ladderc_M && offset >= LADDERC_TM_OFFSET && offset - LADDERC_TM_OFFSET + nbytes <= LADDERC_TM_SIZE)
            image = 0;
        offset += image * size;
    }
    out->name = text;
    out->ptr = NULL;
    out->area = area;
    out->offset = offset;
    out->bit = (uint8_t)bit;
    return 0;
}

unsigned ladderc_type_bytes(ladderc_type t) {
    switch (t) {
    case LADDERC_T_BOOL: case LADDERC_T_SINT: case LADDERC_T_USINT: case LADDERC_T_BYTE: case LADDERC_T_CHAR: return 1;
    case LADDERC_T_INT: case LADDERC_T_UINT: case LADDERC_T_WORD: case LADDERC_T_WCHAR: return 2;
    case LADDERC_T_DINT: case LADDERC_T_UDINT: case LADDERC_T_DWORD: case LADDERC_T_REAL: return 4;
    case LADDERC_T_STRING: return sizeof(IEC_STRING);
    case LADDERC_T_WSTRING: return sizeof(IEC_WSTRING);
    default: return 8;
    }
}

/* Reads a watchable variable into `out` (a value of its C type). */
void ladderc_read_var(const ladderc_var *v, void *out) {
    if (!v->area) {
        memcpy(out, v->ptr, ladderc_type_bytes(v->type));
        return;
    }
    if (v->type == LADDERC_T_BOOL) {
        *(IEC_BOOL *)out = ladderc_load_bit(v->area, v->offset, v->bit);
        return;
    }
    {
        unsigned n = ladderc_type_bytes(v->type);
        uint64_t raw = ladderc_load(v->area, v->offset, n);
        uint8_t u8 = (uint8_t)raw;
        uint16_t u16 = (uint16_t)raw;
        uint32_t u32 = (uint32_t)raw;
        switch (n) {
        case 1: memcpy(out, &u8, 1); break;
        case 2: memcpy(out, &u16, 2); break;
        case 4: memcpy(out, &u32, 4); break;
        default: memcpy(out, &raw, 8); break;
        }
    }
}

void ladderc_write_var(const ladderc_var *v, const void *in) {
    if (!v->area) {
        memcpy(v->ptr, in, ladderc_type_bytes(v->type));
        return;
    }
    if (v->type == LADDERC_T_BOOL) {
        ladderc_store_bit(v->area, v->offset, v->bit, *(const IEC_BOOL *)in);
        return;
    }
    {
        unsigned n = ladderc_type_bytes(v->type);
        uint8_t u8;
        uint16_t u16;
        uint32_t u32;
        uint64_t raw;
        switch (n) {
        case 1: memcpy(&u8, in, 1); raw = u8; break;
        case 2: memcpy(&u16, in, 2); raw = u16; break;
        case 4: memcpy(&u32, in, 4); raw = u32; break;
        default: memcpy(&raw, in, 8); break;
        }
        ladderc_store(v->area, v->offset, n, raw);
    }
}

static void format_duration(IEC_TIME ns, char *buf, size_t len) {
    const char *sign = ns < 0 ? "-" : "";
    uint64_t mag = ns < 0 ? (uint64_t)0 - (uint64_t)ns : (uint64_t)ns;
    if (mag % 1000000u == 0) snprintf(buf, len, "T#%s%llums", sign, (unsigned long long)(mag / 1000000u));
    else if (mag % 1000u == 0) snprintf(buf, len, "T#%s%lluus", sign, (unsigned long long)(mag / 1000u));
    else snprintf(buf, len, "T#%s%lluns", sign, (unsigned long long)mag);
}

static void format_clock(int64_t ns_of_day, char *buf, size_t len) {
    int64_t s = ns_of_day / 1000000000, frac = ns_of_day % 1000000000;
    if (frac == 0)
        snprintf(buf, len, "%02d:%02d:%02d", (int)(s / 3600), (int)(s / 60 % 60), (int)(s % 60));
    else {
        int n;
        n = snprintf(buf, len, "%02d:%02d:%02d.%09lld", (int)(s / 3600), (int)(s / 60 % 60), (int)(s % 60),
                     (long long)frac);
        while (n > 0 && (size_t)n < len && buf[n - 1] == '0') buf[--n] = '\0';
    }
}

static void format_datetime(const char *prefix, int64_t ns, int with_time, char *buf, size_t len) {
    /* floor division without overflow at the ends of the range */
    int64_t day = ns / 86400000000000LL, rem = ns % 86400000000000LL, y;
    unsigned m, d;
    char clock[32];
    if (rem < 0) {
        rem += 86400000000000LL;
        day -= 1;
    }
    civil_from_days(day, &y, &m, &d);
    if (!with_time) {
        snprintf(buf, len, "%s#%04lld-%02u-%02u", prefix, (long long)y, m, d);
        return;
    }
    format_clock(rem, clock, sizeof clock);
    snprintf(buf, len, "%s#%04lld-%02u-%02u-%s", prefix, (long long)y, m, d, clock);
}

/* The shortest %g rendering that reads back to the same value. */
static void format_real(double v, int is_float, char *buf, size_t len) {
    int p;
    for (p = is_float ? 6 : 15; p <= (is_float ? 9 : 17); p++) {
        snprintf(buf, len, "%.*g", p, v);
        if (is_float ? (float)strtod(buf, NULL) == (float)v : strtod(buf, NULL) == v) return;
    }
}

void ladderc_format_value(ladderc_type t, const void *value, char *buf, size_t len) {
    switch (t) {
    case LADDERC_T_BOOL: snprintf(buf, len, "%d", *(const IEC_BOOL *)value ? 1 : 0); break;
    case LADDERC_T_SINT: snprintf(buf, len, "%d", (int)*(const IEC_SINT *)value); break;
    case LADDERC_T_INT: snprintf(buf, len, "%d", (int)*(const IEC_INT *)value); break;
    case LADDERC_T_DINT: snprintf(buf, len, "%ld", (long)*(const IEC_DINT *)value); break;
    case LADDERC_T_LINT: snprintf(buf, len, "%lld", (long long)*(const IEC_LINT *)value); break;
    case LADDERC_T_USINT: case LADDERC_T_BYTE: snprintf(buf, len, "%u", (unsigned)*(const uint8_t *)value); break;
    case LADDERC_T_UINT: case LADDERC_T_WORD: snprintf(buf, len, "%u", (unsigned)*(const uint16_t *)value); break;
    case LADDERC_T_UDINT: case LADDERC_T_DWORD: snprintf(buf, len, "%lu", (unsigned long)*(const uint32_t *)value); break;
    case LADDERC_T_ULINT: case LADDERC_T_LWORD: snprintf(buf, len, "%llu", (unsigned long long)*(const uint64_t *)value); break;
    case LADDERC_T_REAL: format_real(*(const IEC_REAL *)value, 1, buf, len); break;
    case LADDERC_T_LREAL: format_real(*(const IEC_LREAL *)value, 0, buf, len); break;
    case LADDERC_T_TIME: case LADDERC_T_LTIME: format_duration(*(const IEC_TIME *)value, buf, len); break;
    case LADDERC_T_DATE: format_datetime("D", *(const IEC_DATE *)value, 0, buf, len); break;
    case LADDERC_T_DT: format_datetime("DT", *(const IEC_DT *)value, 1, buf, len); break;
    case LADDERC_T_LDATE: format_datetime("LDATE", *(const IEC_LDATE *)value, 0, buf, len); break;
    case LADDERC_T_LDT: format_datetime("LDT", *(const IEC_LDT *)value, 1, buf, len); break;
    case LADDERC_T_TOD:
    case LADDERC_T_LTOD: {
        char clock[32];
        int64_t ns = *(const IEC_TOD *)value;
        format_clock(ns < 0 ? 0 : ns, clock, sizeof clock);
        snprintf(buf, len, "%s#%s", t == LADDERC_T_TOD ? "TOD" : "LTOD", clock);
        break;
    }
    case LADDERC_T_CHAR:
    case LADDERC_T_WCHAR: {
        /* edition 3's literal form, `CHAR#'A'`, `WCHAR#"A"`: `$$`, `$'` (`$"`) and `$hh` (`$hhhh`)
         * for a control character (and a WCHAR's surrogate); the CSV field quoted (quotes doubled)
         * when it holds a `"` or a `,` */
        int wide = t == LADDERC_T_WCHAR;
        uint32_t cp = wide ? *(const IEC_WCHAR *)value : *(const IEC_CHAR *)value;
        char q = wide ? '"' : '\'';
        char body[16], lit[32];
        size_t o = 0, i, n;
        if (cp == '$' || cp == (uint32_t)q) snprintf(body, sizeof body, "$%c", (char)cp);
        else if (cp < 0x20 || (cp >= 0x7F && cp < 0xA0) || (cp >= 0xD800 && cp <= 0xDFFF))
            snprintf(body, sizeof body, wide ? "$%04X" : "$%02X", (unsigned)cp);
        else if (cp < 0x80) snprintf(body, sizeof body, "%c", (char)cp);
        else if (cp < 0x800) snprintf(body, sizeof body, "%c%c", (char)(0xC0 | (cp >> 6)), (char)(0x80 | (cp & 0x3F)));
        else
            snprintf(body, sizeof body, "%c%c%c", (char)(0xE0 | (cp >> 12)), (char)(0x80 | ((cp >> 6) & 0x3F)),
                     (char)(0x80 | (cp & 0x3F)));
        snprintf(lit, sizeof lit, "%s#%c%s%c", wide ? "WCHAR" : "CHAR", q, body, q);
        n = strlen(lit);
        if (!len) break;
        if (!strchr(lit, '"') && !strchr(lit, ',')) {
            snprintf(buf, len, "%s", lit);
            break;
        }
        if (len < 2 * n + 3) { buf[0] = '\0'; break; }
        buf[o++] = '"';
        for (i = 0; i < n; i++) {
            if (lit[i] == '"') buf[o++] = '"';
            buf[o++] = lit[i];
        }
        buf[o++] = '"';
        buf[o] = '\0';
        break;
    }
    case LADDERC_T_STRING: {
        /* CSV field: always quoted, quotes doubled; each byte is its ISO 8859-1 character, in UTF-8. */
        const IEC_STRING *s = (const IEC_STRING *)value;
        size_t o = 0, i;
        if (len < 3) { if (len) buf[0] = '\0'; break; }
        buf[o++] = '"';
        for (i = 0; i < s->len && o + 4 < len; i++) {
            unsigned char c = (unsigned char)s->data[i];
            if (c == '"') buf[o++] = '"';
            if (c < 0x80) buf[o++] = (char)c;
            else { buf[o++] = (char)(0xC0 | (c >> 6)); buf[o++] = (char)(0x80 | (c & 0x3F)); }
        }
        buf[o++] = '"';
        buf[o] = '\0';
        break;
    }
    case LADDERC_T_WSTRING: {
        /* UTF-8, quoted like STRING; an unpaired surrogate becomes U+FFFD */
        const IEC_WSTRING *s = (const IEC_WSTRING *)value;
        size_t o = 0, i;
        if (len < 3) { if (len) buf[0] = '\0'; break; }
        buf[o++] = '"';
        for (i = 0; i < s->len && o + 6 < len; i++) {
            uint32_t cp = s->data[i];
            if (cp >= 0xD800 && cp <= 0xDBFF && i + 1 < s->len && s->data[i + 1] >= 0xDC00 && s->data[i + 1] <= 0xDFFF) {
                cp = 0x10000 + ((cp - 0xD800) << 10) + (uint32_t)(s->data[i + 1] - 0xDC00);
                i++;
            } else if (cp >= 0xD800 && cp <= 0xDFFF) {
                cp = 0xFFFD;
            }
            if (cp == '"') { buf[o++] = '"'; buf[o++] = '"'; }
            else if (cp < 0x80) buf[o++] = (char)cp;
            else if (cp < 0x800) { buf[o++] = (char)(0xC0 | (cp >> 6)); buf[o++] = (char)(0x80 | (cp & 0x3F)); }
            else if (cp < 0x10000) {
                buf[o++] = (char)(0xE0 | (cp >> 12)); buf[o++] = (char)(0x80 | ((cp >> 6) & 0x3F));
                buf[o++] = (char)(0x80 | (cp & 0x3F));
            } else {
                buf[o++] = (char)(0xF0 | (cp >> 18)); buf[o++] = (char)(0x80 | ((cp >> 12) & 0x3F));
                buf[o++] = (char)(0x80 | ((cp >> 6) & 0x3F)); buf[o++] = (char)(0x80 | (cp & 0x3F));
            }
        }
        buf[o++] = '"';
        buf[o] = '\0';
        break;
    }
    default: snprintf(buf, len, "?"); break;
    }
}

/* ------------------------------------------------------------------ string conversions */
IEC_STRING ladderc_str_of(int type, const void *value) {
    char buf[2 * LADDERC_STRING_CAP + 16];
    if (type == LADDERC_T_BOOL) return *(const IEC_BOOL *)value ? ladderc_str_lit("TRUE", 4) : ladderc_str_lit("FALSE", 5);
    if (type == LADDERC_T_STRING) return *(const IEC_STRING *)value;
    if (type == LADDERC_T_CHAR) return ladderc_char_to_str(*(const IEC_CHAR *)value);
    if (type == LADDERC_T_WCHAR) return ladderc_char_to_str(ladderc_wchar_to_char(*(const IEC_WCHAR *)value));
    ladderc_format_value((ladderc_type)type, value, buf, sizeof buf);
    return ladderc_str_lit(buf, strlen(buf));
}

IEC_WSTRING ladderc_wstr_of_str(IEC_STRING s) {
    IEC_WSTRING w;
    uint16_t i, n = s.len > LADDERC_STRING_CAP ? LADDERC_STRING_CAP : s.len;
    for (i = 0; i < n; i++) w.data[i] = (uint16_t)(unsigned char)s.data[i]; /* ISO 8859-1 */
    w.data[n] = 0;
    w.len = n;
    return w;
}

IEC_STRING ladderc_str_of_wstr(IEC_WSTRING w) {
    IEC_STRING s;
    uint16_t i, o = 0, n = w.len > LADDERC_STRING_CAP ? LADDERC_STRING_CAP : w.len;
    for (i = 0; i < n; i++) {
        uint16_t u = w.data[i];
        if (u <= 0xFF) {
            s.data[o++] = (char)u;
            continue;
        }
        /* no single byte holds it: '?', and LADDERC_ERR_RANGE; a surrogate pair is one character */
        if (u >= 0xD800 && u <= 0xDBFF && i + 1 < n && w.data[i + 1] >= 0xDC00 && w.data[i + 1] <= 0xDFFF) i++;
        ladderc_errors |= LADDERC_ERR_RANGE;
        s.data[o++] = '?';
    }
    s.data[o] = '\0';
    s.len = o;
    return s;
}

/* The string's text without leading and trailing spaces, NUL-terminated, in buf. */
static const char *trimmed(IEC_STRING *s) {
    char *p = s->data, *e;
    s->data[s->len] = '\0';
    while (*p == ' ' || *p == '\t') p++;
    e = p + strlen(p);
    while (e > p && (e[-1] == ' ' || e[-1] == '\t')) *--e = '\0';
    return p;
}

int64_t ladderc_str_to_int(IEC_STRING s) {
    IEC_LINT v = 0;
    if (ladderc_parse_value(LADDERC_T_LINT, trimmed(&s), &v, NULL, 0)) { ladderc_errors |= LADDERC_ERR_RANGE; return 0; }
    return v;
}
uint64_t ladderc_str_to_uint(IEC_STRING s) {
    IEC_ULINT v = 0;
    if (ladderc_parse_value(LADDERC_T_ULINT, trimmed(&s), &v, NULL, 0)) { ladderc_errors |= LADDERC_ERR_RANGE; return 0; }
    return v;
}
double ladderc_str_to_real(IEC_STRING s) {
    IEC_LREAL v = 0;
    if (ladderc_parse_value(LADDERC_T_LREAL, trimmed(&s), &v, NULL, 0)) { ladderc_errors |= LADDERC_ERR_RANGE; return 0; }
    return v;
}
IEC_BOOL ladderc_str_to_bool(IEC_STRING s) {
    IEC_BOOL v = 0;
    if (ladderc_parse_value(LADDERC_T_BOOL, trimmed(&s), &v, NULL, 0)) { ladderc_errors |= LADDERC_ERR_RANGE; return 0; }
    return v;
}
IEC_TIME ladderc_str_to_time(IEC_STRING s) {
    IEC_TIME v = 0;
    if (ladderc_parse_value(LADDERC_T_TIME, trimmed(&s), &v, NULL, 0)) { ladderc_errors |= LADDERC_ERR_RANGE; return 0; }
    return v;
}
