/* Runtime unit tests, compiled by tests/runtime.rs against ladderc_rt.c with warnings as errors and
 * sanitizers; EXPECT_BIG selects the byte-order expectations of the profile it was built with. */
#include "ladderc_rt.h"
#include <stdio.h>

uint8_t ladderc_I[LADDERC_I_SIZE];
uint8_t ladderc_Q[LADDERC_Q_SIZE];
uint8_t ladderc_M[LADDERC_M_SIZE];
const ladderc_var ladderc_vars[] = {{NULL, LADDERC_T_BOOL, NULL, NULL, 0, 0}};
const size_t ladderc_var_count = 0;
void ladderc_program_init(void) {}
void ladderc_program_scan(void) {}

static int failures = 0;
#define CHECK(cond)                                                                                \
    do {                                                                                          \
        if (!(cond)) {                                                                            \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);              \
            failures++;                                                                           \
        }                                                                                         \
    } while (0)

static void at(int64_t ms) { ladderc_now = ms * 1000000; }

static void arithmetic(void) {
    CHECK(ladderc_add_IEC_INT(32767, 1) == -32768);
    CHECK(ladderc_sub_IEC_INT(-32768, 1) == 32767);
    CHECK(ladderc_mul_IEC_INT(300, 300) == (IEC_INT)(90000 - 65536 * 1));
    CHECK(ladderc_mul_IEC_UINT(65535, 65535) == 1);
    CHECK(ladderc_add_IEC_SINT(127, 1) == -128);
    CHECK(ladderc_add_IEC_LINT(INT64_MAX, 1) == INT64_MIN);
    CHECK(ladderc_mul_IEC_LINT(INT64_MIN, -1) == INT64_MIN);
    CHECK(ladderc_neg_IEC_DINT(INT32_MIN) == INT32_MIN);
    CHECK(ladderc_div_IEC_DINT(INT32_MIN, -1) == INT32_MIN);
    CHECK(ladderc_mod_IEC_DINT(INT32_MIN, -1) == 0);
    CHECK(ladderc_div_IEC_INT(-7, 2) == -3); /* truncation toward zero */
    CHECK(ladderc_mod_IEC_INT(-7, 2) == -1);
    CHECK(ladderc_sub_IEC_USINT(0, 1) == 255);
    CHECK(ladderc_abs_IEC_INT(-32768) == -32768);
    CHECK(ladderc_abs_IEC_INT(-5) == 5);
    ladderc_errors = 0;
    CHECK(ladderc_div_IEC_INT(5, 0) == 0);
    CHECK(ladderc_errors & LADDERC_ERR_DIV_ZERO);
    ladderc_errors = 0;
    CHECK(ladderc_mod_IEC_UDINT(5, 0) == 0);
    CHECK(ladderc_errors == LADDERC_ERR_DIV_ZERO);
    ladderc_errors = 0;
}

static void shifts(void) {
    CHECK(ladderc_shl_IEC_BYTE(0x81, 1) == 0x02);
    CHECK(ladderc_shr_IEC_BYTE(0x81, 1) == 0x40);
    CHECK(ladderc_shl_IEC_WORD(1, 16) == 0);
    CHECK(ladderc_shl_IEC_WORD(1, 15) == 0x8000);
    CHECK(ladderc_shl_IEC_LWORD(1, 64) == 0);
    CHECK(ladderc_shl_IEC_LWORD(1, 63) == UINT64_C(0x8000000000000000));
    CHECK(ladderc_rol_IEC_BYTE(0x81, 1) == 0x03);
    CHECK(ladderc_ror_IEC_BYTE(0x81, 1) == 0xC0);
    CHECK(ladderc_rol_IEC_WORD(0x1234, 20) == ladderc_rol_IEC_WORD(0x1234, 4));
    CHECK(ladderc_ror_IEC_DWORD(1, -1) == 2); /* negative rotate count: the other direction */
    CHECK(ladderc_rol_IEC_LWORD(UINT64_C(0x8000000000000001), 1) == 3);
    CHECK(ladderc_shr_IEC_DWORD(0x80000000u, 31) == 1);
}

static void conversions(void) {
    ladderc_errors = 0;
    CHECK(ladderc_real_to_int(2.5, INT16_MIN, INT16_MAX) == 2);
    CHECK(ladderc_real_to_int(-2.5, INT16_MIN, INT16_MAX) == -2);
    CHECK(ladderc_real_to_int(1.49, INT16_MIN, INT16_MAX) == 1);
    CHECK(ladderc_errors == 0);
    CHECK(ladderc_real_to_int(1e9, INT16_MIN, INT16_MAX) == INT16_MAX);
    CHECK(ladderc_errors & LADDERC_ERR_RANGE);
    CHECK(ladderc_real_to_int(0.0 / 0.0, INT16_MIN, INT16_MAX) == 0);
    CHECK(ladderc_real_to_int(-1e300, INT64_MIN, INT64_MAX) == INT64_MIN);
    CHECK(ladderc_real_to_uint(-3.0, UINT16_MAX) == 0);
    CHECK(ladderc_real_to_uint(1e300, UINT64_MAX) == UINT64_MAX);
    CHECK(ladderc_bcd_to_uint(0x1234) == 1234);
    CHECK(ladderc_uint_to_bcd(1234, 16) == 0x1234);
    ladderc_errors = 0;
    CHECK(ladderc_bcd_to_uint(0x1A) == 0);
    CHECK(ladderc_errors & LADDERC_ERR_RANGE);
    CHECK(ladderc_ms_to_time(1.5) == 1500000);
    CHECK(ladderc_dt_to_tod(-1) == LADDERC_NS_PER_DAY - 1);
    CHECK(ladderc_dt_to_date(LADDERC_NS_PER_DAY + 5) == LADDERC_NS_PER_DAY);
    CHECK(ladderc_index(5, 1, 10, "a[i] in P") == 4);
    ladderc_errors = 0;
    CHECK(ladderc_index(11, 1, 10, "a[i] in P") == 0);
    CHECK(ladderc_errors & LADDERC_ERR_BOUNDS);
    /* the first out-of-range index is the one reported */
    CHECK(ladderc_index(-3, 0, 4, "b[j] in Q") == 0);
    CHECK(strcmp(ladderc_bounds_site, "a[i] in P") == 0);
    CHECK(ladderc_bounds_at[0] == 11 && ladderc_bounds_at[1] == 1 && ladderc_bounds_at[2] == 10);
    CHECK(ladderc_next_due(0, 0, 20) == 20);
    CHECK(ladderc_next_due(20, 30, 20) == 40);
    CHECK(ladderc_next_due(20, 65, 20) == 80);
    ladderc_errors = 0;
}

static void timers(void) {
    ladderc_TOF tof;
    ladderc_TP tp;
    ladderc_TON ton;
    ladderc_TOF_init(&tof);
    tof.PT = 30000000;
    at(0); tof.IN = 1; ladderc_TOF_body(&tof); CHECK(tof.Q == 1 && tof.ET == 0);
    at(10); tof.IN = 0; ladderc_TOF_body(&tof); CHECK(tof.Q == 1 && tof.ET == 0);
    at(30); ladderc_TOF_body(&tof); CHECK(tof.Q == 1 && tof.ET == 20000000);
    at(40); ladderc_TOF_body(&tof); CHECK(tof.Q == 0 && tof.ET == 30000000);
    at(50); ladderc_TOF_body(&tof); CHECK(tof.Q == 0 && tof.ET == 30000000);
    at(60); tof.IN = 1; ladderc_TOF_body(&tof); CHECK(tof.Q == 1 && tof.ET == 0);

    ladderc_TP_init(&tp);
    tp.PT = 20000000;
    at(0); tp.IN = 1; ladderc_TP_body(&tp); CHECK(tp.Q == 1 && tp.ET == 0);
    at(10); tp.IN = 0; ladderc_TP_body(&tp); CHECK(tp.Q == 1 && tp.ET == 10000000); /* IN falling does not cut it */
    at(15); tp.IN = 1; ladderc_TP_body(&tp); CHECK(tp.Q == 1 && tp.ET == 15000000); /* no retrigger */
    at(20); ladderc_TP_body(&tp); CHECK(tp.Q == 0 && tp.ET == 20000000);
    at(30); ladderc_TP_body(&tp); CHECK(tp.Q == 0 && tp.ET == 20000000); /* IN still TRUE: ET holds */
    at(40); tp.IN = 0; ladderc_TP_body(&tp); CHECK(tp.Q == 0 && tp.ET == 0);
    at(50); tp.IN = 1; ladderc_TP_body(&tp); CHECK(tp.Q == 1 && tp.ET == 0);
    /* PT 0: the rising edge still gives Q for the call that sees it, cleared by the next call. */
    ladderc_TP_init(&tp);
    tp.PT = 0;
    at(0); tp.IN = 1; ladderc_TP_body(&tp); CHECK(tp.Q == 1 && tp.ET == 0);
    at(10); ladderc_TP_body(&tp); CHECK(tp.Q == 0 && tp.ET == 0);
    at(20); tp.IN = 0; ladderc_TP_body(&tp); CHECK(tp.Q == 0 && tp.ET == 0);
    at(30); tp.IN = 1; ladderc_TP_body(&tp); CHECK(tp.Q == 1 && tp.ET == 0);

    ladderc_TON_init(&ton);
    ton.PT = 0;
    at(0); ton.IN = 1; ladderc_TON_body(&ton); CHECK(ton.Q == 1); /* PT 0: immediately */
}

static void counters_and_bistables(void) {
    ladderc_CTD ctd;
    ladderc_CTUD ud;
    ladderc_SR sr;
    ladderc_RS rs;
    int k;
    ladderc_CTD_init(&ctd);
    ctd.PV = 2; ctd.LD = 1; ladderc_CTD_body(&ctd); CHECK(ctd.CV == 2 && !ctd.Q);
    ctd.LD = 0;
    for (k = 0; k < 3; k++) {
        ctd.CD = 1; ladderc_CTD_body(&ctd);
        ctd.CD = 0; ladderc_CTD_body(&ctd);
    }
    CHECK(ctd.CV == -1 && ctd.Q);

    ladderc_CTUD_init(&ud);
    ud.PV = 2;
    ud.CU = 1; ladderc_CTUD_body(&ud); CHECK(ud.CV == 1 && !ud.QU && !ud.QD);
    ud.CU = 0; ladderc_CTUD_body(&ud);
    ud.CU = 1; ladderc_CTUD_body(&ud); CHECK(ud.CV == 2 && ud.QU);
    ud.CU = 0; ud.CD = 1; ladderc_CTUD_body(&ud); CHECK(ud.CV == 1 && !ud.QU);
    ud.CU = 1; ud.CD = 0; ladderc_CTUD_body(&ud); CHECK(ud.CV == 2);
    ud.CU = 0; ladderc_CTUD_body(&ud);
    ud.CU = 1; ud.CD = 1; ladderc_CTUD_body(&ud); CHECK(ud.CV == 2); /* both edges: no change */
    ud.R = 1; ladderc_CTUD_body(&ud); CHECK(ud.CV == 0 && ud.QD);
    ud.R = 0; ud.LD = 1; ladderc_CTUD_body(&ud); CHECK(ud.CV == 2);

    ladderc_SR_init(&sr);
    sr.S1 = 1; sr.R = 1; ladderc_SR_body(&sr); CHECK(sr.Q1 == 1); /* set dominant */
    sr.S1 = 0; ladderc_SR_body(&sr); CHECK(sr.Q1 == 0);
    ladderc_RS_init(&rs);
    rs.S = 1; rs.R1 = 1; ladderc_RS_body(&rs); CHECK(rs.Q1 == 0); /* reset dominant */
    rs.R1 = 0; ladderc_RS_body(&rs); CHECK(rs.Q1 == 1);
    rs.S = 0; ladderc_RS_body(&rs); CHECK(rs.Q1 == 1);
}

static void process_image(void) {
    ladderc_var v;
    char err[256];
    uint16_t w;
    memset(ladderc_M, 0, sizeof ladderc_M);
    ladderc_store(ladderc_M, 4, 2, 0x1234);
#if EXPECT_BIG
    CHECK(ladderc_M[4] == 0x12 && ladderc_M[5] == 0x34);
#else
    CHECK(ladderc_M[4] == 0x34 && ladderc_M[5] == 0x12);
#endif
    CHECK(ladderc_load(ladderc_M, 4, 2) == 0x1234);
    ladderc_store(ladderc_M, 8, 4, ladderc_real_to_bits(1.5f));
    CHECK(ladderc_bits_to_real((uint32_t)ladderc_load(ladderc_M, 8, 4)) == 1.5f);
    ladderc_store_bit(ladderc_Q, 3, 6, 1);
#if EXPECT_BIG
    CHECK(ladderc_Q[3] == 0x02); /* msb0: bit 6 is the second lowest */
#else
    CHECK(ladderc_Q[3] == 0x40);
#endif
    CHECK(ladderc_load_bit(ladderc_Q, 3, 6) == 1);
    ladderc_store_bit(ladderc_Q, 3, 6, 0);
    CHECK(ladderc_Q[3] == 0);
    /* addresses in the harness: %MW2 is the third word (element numbering) */
    CHECK(ladderc_resolve_address("%MW2", &v, err, sizeof err) == 0);
    CHECK(v.offset == 4 && v.type == LADDERC_T_WORD && v.area == ladderc_M);
    ladderc_read_var(&v, &w);
    CHECK(w == 0x1234);
    CHECK(ladderc_resolve_address("%ix3.6", &v, err, sizeof err) == 0);
    CHECK(v.offset == 3 && v.bit == 6 && v.type == LADDERC_T_BOOL);
    CHECK(ladderc_resolve_address("%IX13", &v, err, sizeof err) == 0); /* absolute bit 13 */
    CHECK(v.offset == 1 && v.bit == 5 && v.type == LADDERC_T_BOOL);
    CHECK(ladderc_resolve_address("%IX3.", &v, err, sizeof err) == -1);
    CHECK(ladderc_resolve_address("%IX3.8", &v, err, sizeof err) == -1);
    CHECK(ladderc_resolve_address("%QW100000", &v, err, sizeof err) == -1);
    CHECK(ladderc_resolve_address("%ZW1", &v, err, sizeof err) == -1);
    CHECK(ladderc_resolve_address("%QL1x", &v, err, sizeof err) == -1);
}

static void values(void) {
    char err[256], buf[600];
    IEC_INT i;
    IEC_BOOL b;
    IEC_TIME t;
    IEC_REAL r;
    IEC_UINT u;
    IEC_DT dt;
    IEC_STRING s;
    CHECK(ladderc_parse_value(LADDERC_T_INT, "-32768", &i, err, sizeof err) == 0 && i == -32768);
    CHECK(ladderc_parse_value(LADDERC_T_INT, "32768", &i, err, sizeof err) == -1);
    CHECK(ladderc_parse_value(LADDERC_T_INT, "INT#16#7F_FF", &i, err, sizeof err) == 0 && i == 32767);
    CHECK(ladderc_parse_value(LADDERC_T_UINT, "-1", &u, err, sizeof err) == -1);
    CHECK(ladderc_parse_value(LADDERC_T_UINT, "2#1010", &u, err, sizeof err) == 0 && u == 10);
    CHECK(ladderc_parse_value(LADDERC_T_INT, "12abc", &i, err, sizeof err) == -1);
    CHECK(ladderc_parse_value(LADDERC_T_INT, "", &i, err, sizeof err) == -1);
    CHECK(ladderc_parse_value(LADDERC_T_BOOL, "true", &b, err, sizeof err) == 0 && b == 1);
    CHECK(ladderc_parse_value(LADDERC_T_BOOL, "FALSE", &b, err, sizeof err) == 0 && b == 0);
    CHECK(ladderc_parse_value(LADDERC_T_BOOL, "2", &b, err, sizeof err) == -1);
    CHECK(ladderc_parse_value(LADDERC_T_BOOL, "TRUEX", &b, err, sizeof err) == -1);
    CHECK(ladderc_parse_value(LADDERC_T_TIME, "T#1h2m3s4ms", &t, err, sizeof err) == 0 &&
          t == ((INT64_C(3600) + 120 + 3) * 1000 + 4) * 1000000);
    CHECK(ladderc_parse_value(LADDERC_T_TIME, "TIME#-1.5s", &t, err, sizeof err) == 0 && t == -1500000000);
    CHECK(ladderc_parse_value(LADDERC_T_TIME, "t#1d_2h", &t, err, sizeof err) == 0 &&
          t == INT64_C(26) * 3600 * 1000000000);
    CHECK(ladderc_parse_value(LADDERC_T_TIME, "150", &t, err, sizeof err) == -1);
    CHECK(ladderc_parse_value(LADDERC_T_TIME, "T#5x", &t, err, sizeof err) == -1);
    CHECK(ladderc_parse_value(LADDERC_T_REAL, "2.5e1", &r, err, sizeof err) == 0 && r == 25.0f);
    CHECK(ladderc_parse_value(LADDERC_T_REAL, "abc", &r, err, sizeof err) == -1);
    CHECK(ladderc_parse_value(LADDERC_T_DT, "DT#2001-04-09-11:36:15.20", &dt, err, sizeof err) == 0);
    ladderc_format_value(LADDERC_T_DT, &dt, buf, sizeof buf);
    CHECK(strcmp(buf, "DT#2001-04-09-11:36:15.2") == 0);
    CHECK(ladderc_parse_value(LADDERC_T_STRING, "'a,b'", &s, err, sizeof err) == 0 && s.len == 3);
    ladderc_format_value(LADDERC_T_STRING, &s, buf, sizeof buf);
    CHECK(strcmp(buf, "\"a,b\"") == 0);
    t = 1500000;
    ladderc_format_value(LADDERC_T_TIME, &t, buf, sizeof buf);
    CHECK(strcmp(buf, "T#1500us") == 0);
    t = -30000000;
    ladderc_format_value(LADDERC_T_TIME, &t, buf, sizeof buf);
    CHECK(strcmp(buf, "T#-30ms") == 0);
    r = 0.1f;
    ladderc_format_value(LADDERC_T_REAL, &r, buf, sizeof buf);
    CHECK(strcmp(buf, "0.1") == 0);
    {
        IEC_WSTRING w;
        static const uint16_t abc[] = {0x61, 0xE9, 0xD83D, 0xDE00};
        CHECK(ladderc_parse_value(LADDERC_T_WSTRING, "\"a\xC3\xA9\xF0\x9F\x98\x80\"", &w, err, sizeof err) == 0);
        CHECK(w.len == 4 && ladderc_wstr_cmpv(w, ladderc_wstr_lit(abc, 4)) == 0);
        ladderc_format_value(LADDERC_T_WSTRING, &w, buf, sizeof buf);
        CHECK(strcmp(buf, "\"a\xC3\xA9\xF0\x9F\x98\x80\"") == 0);
        CHECK(ladderc_parse_value(LADDERC_T_WSTRING, "\xC3", &w, err, sizeof err) == -1);
        CHECK(ladderc_parse_value(LADDERC_T_WSTRING, "\xED\xA0\x80", &w, err, sizeof err) == -1); /* surrogate */
        CHECK(ladderc_wstr_cap(ladderc_wstr_lit(abc, 4), 2).len == 2);
    }
    s = ladderc_str_lit("abc", 3);
    CHECK(ladderc_str_cmpv(s, ladderc_str_lit("abd", 3)) < 0);
    CHECK(ladderc_str_cap(s, 2).len == 2);
}

int main(void) {
    arithmetic();
    shifts();
    conversions();
    timers();
    counters_and_bistables();
    process_image();
    values();
    if (failures) {
        fprintf(stderr, "%d runtime check(s) failed\n", failures);
        return 1;
    }
    printf("runtime ok\n");
    return 0;
}
