/* ladderc scan harness: runs the generated program for N scan cycles with a fixed cycle time.
 *
 *   prog [--cycles N] [--cycle-ms X] [--stimulus FILE] [--trace FILE|-] [--watch a,b,%QX0.1] [--list]
 *        [--progress FILE] [--trace-raw]
 *
 * Input: the stimulus CSV (`cycle,variable,value` rows; the values are written just before that cycle
 * runs; an optional `cycle,variable,value` header, blank lines and `#` comment lines are ignored; a
 * variable is named as the trace header names it, `"m.grid[1,0]"` or `m.grid[1,0]`, and so is each name
 * of --watch).
 * Output: the trace CSV (`cycle,time_ms,VAR...`, one row per cycle with the watched variables after it).
 * Progress (`--progress FILE`): about ten times a second of CPU time, the number of cycles done is written
 * at the start of FILE as 20 digits and a newline (the caller polls it for a progress bar); the clock is
 * read every 256 cycles only, so the run is not slowed measurably.
 * Cycle k runs with the scan clock at k * cycle time (cycle 0 at 0 ms); time_ms is that clock.
 * Exit status: 0 on success, 2 on bad usage or a bad stimulus row (with `file:line: message` on stderr).
 * Runtime error flags (division by zero, saturated conversions) are reported on stderr at the end.
 * Loop guard (compiled with -DLADDERC_LOOP_LIMIT=N, as `ladderc run` does): a scan that jumps back more
 * than N times never ends; the harness writes the trace so far, then `ladderc-loop-guard FILE START END
 * CYCLE N` on stderr, and exits with status 3. */
#include "ladderc_rt.h"

/* The default scan cycle (--cycle-ms); a program with motion defines it as its engine cycle. */
#ifndef LADDERC_DEFAULT_CYCLE_NS
#define LADDERC_DEFAULT_CYCLE_NS 10000000
#endif

#include <stdio.h>
#include <stdlib.h>
#include <ctype.h>
#include <errno.h>
#include <time.h>

typedef union {
    IEC_LINT i;
    IEC_ULINT u;
    IEC_LREAL d;
    IEC_STRING s;
    IEC_WSTRING w;
} any_value;

typedef struct {
    uint64_t cycle;
    ladderc_var var;
    any_value value;
} stimulus_row;

/* Heap blocks live in file-scope pointers so that early error exits leave nothing unreachable. */
static stimulus_row *rows;
static ladderc_var *watch;
static char *watch_copy;

static void usage(FILE *f) {
    fprintf(f,
            "usage: prog [--cycles N] [--cycle-ms X] [--stimulus FILE] [--trace FILE|-] [--watch a,b,%%QX0.1] "
            "[--list]\n"
            "  --cycles N       scan cycles to run (default 1)\n"
            "  --cycle-ms X     cycle time in milliseconds, may be fractional (default 10)\n"
            "  --stimulus FILE  CSV rows `cycle,variable,value` applied before that cycle\n"
            "  --trace FILE     CSV trace `cycle,time_ms,VAR...` after each cycle (default: standard output)\n"
            "  --watch LIST     comma-separated variables or addresses to trace, `m.grid[1,0]` one name (default: every variable but the compiler's own `__` ones)\n"
            "  --list           print the watchable variables with their types and exit\n"
            "  --progress FILE  write the number of cycles done into FILE, about ten times a second\n"
            "  --trace-raw      REAL/LREAL values of the trace as raw bits, for ladderc run to format\n");
}

/* The first `n` characters of `a` and `b` are equal, ignoring ASCII case. */
static int strncasecmp_portable(const char *a, const char *b, size_t n) {
    size_t i;
    for (i = 0; i < n; i++) {
        if (toupper((unsigned char)a[i]) != toupper((unsigned char)b[i])) return 1;
        if (!a[i]) return 0;
    }
    return 0;
}

static int ieq(const char *a, const char *b) {
    while (*a && *b) {
        if (toupper((unsigned char)*a) != toupper((unsigned char)*b)) return 0;
        a++;
        b++;
    }
    return *a == *b;
}

/* The part of a dotted name after its last dot (`Main.x` -> `x`). */
static const char *last_part(const char *s) {
    const char *p = s;
    for (; *s; s++) {
        if (*s == '.') p = s + 1;
    }
    return p;
}

/* A variable of the table or a direct address; names compare case-insensitively. A hierarchical
   address (`%IX1.0.0`) is a table entry of its own; other addresses are decoded. An unknown name
   suggests a variable with the same last part (`Main.x` for the global `x`, or the reverse). */
static int resolve(const char *name, ladderc_var *out, char *err, size_t errlen) {
    size_t i;
    if (name[0] == '%') {
        for (i = 0; i < ladderc_var_count; i++) {
            if (ladderc_vars[i].name && ieq(ladderc_vars[i].name, name)) {
                *out = ladderc_vars[i];
                return 0;
            }
        }
        return ladderc_resolve_address(name, out, err, errlen);
    }
    for (i = 0; i < ladderc_var_count; i++) {
        if (ieq(ladderc_vars[i].name, name)) {
            *out = ladderc_vars[i];
            return 0;
        }
    }
    /* `P1.n` when two configurations (or resources) each have an instance `P1`: their variables
       are traced as `CfgA.P1.n` and `CfgB.P1.n`; the unqualified name is refused, listing them */
    if (strchr(name, '.')) {
        size_t nlen = strlen(name), found = 0, used;
        for (i = 0; i < ladderc_var_count; i++) {
            size_t len = strlen(ladderc_vars[i].name);
            if (len > nlen && ladderc_vars[i].name[len - nlen - 1] == '.' &&
                ieq(ladderc_vars[i].name + len - nlen, name))
                found++;
        }
        if (found > 1) {
            used = (size_t)snprintf(err, errlen, "`%s` is ambiguous: instances of one name in several configurations or resources are named by them:", name);
            for (i = 0; i < ladderc_var_count && used < errlen; i++) {
                size_t len = strlen(ladderc_vars[i].name);
                if (len > nlen && ladderc_vars[i].name[len - nlen - 1] == '.' &&
                    ieq(ladderc_vars[i].name + len - nlen, name))
                    used += (size_t)snprintf(err + used, errlen - used, " `%s`", ladderc_vars[i].name);
            }
            return -1;
        }
    }
    for (i = 0; i < ladderc_var_count; i++) {
        if (ieq(last_part(ladderc_vars[i].name), last_part(name))) {
            snprintf(err, errlen, "unknown variable `%s`: did you mean `%s`? (a run without --watch traces every variable; a built program lists them with --list)",
                     name, ladderc_vars[i].name);
            return -1;
        }
    }
    snprintf(err, errlen, "unknown variable `%s` (a run without --watch traces every variable; a built program lists them with --list)", name);
    return -1;
}

/* Whether `name` is an access path declared READ_ONLY (or a member of a structured one, `NAME.x`). */
static int read_only(const char *name) {
    size_t i, n;
    for (i = 0; i < ladderc_read_only_count; i++) {
        const char *r = ladderc_read_only[i];
        n = strlen(r);
        if (!strncasecmp_portable(name, r, n) && (name[n] == '\0' || name[n] == '.' || name[n] == '[')) return 1;
    }
    return 0;
}

/* A name the compiler made (a part of it starts with `__`, which no IEC identifier does): left out
 * of the default trace and of --list; --watch still finds it. */
static int hidden_name(const char *name) {
    const char *p = name;
    for (;;) {
        if (p[0] == '_' && p[1] == '_') return 1;
        p = strchr(p, '.');
        if (!p) return 0;
        p++;
    }
}

static char *trim(char *s) {
    char *e;
    while (*s && isspace((unsigned char)*s)) s++;
    e = s + strlen(s);
    while (e > s && isspace((unsigned char)e[-1])) *--e = '\0';
    return s;
}

static char *read_file(const char *path, size_t *len_out) {
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    size_t len = 0, cap = 0;
    if (!f) return NULL;
    for (;;) {
        size_t n;
        if (cap - len < 4096) {
            char *nb;
            cap = cap ? cap * 2 : 8192;
            nb = (char *)realloc(buf, cap + 1);
            if (!nb) {
                free(buf);
                fclose(f);
                return NULL;
            }
            buf = nb;
        }
        n = fread(buf + len, 1, cap - len, f);
        len += n;
        if (n == 0) break;
    }
    fclose(f);
    buf[len] = '\0';
    *len_out = len;
    return buf;
}

/* Cuts the next variable name off the comma-separated text at `p`, in place, as the trace header
 * writes names: a field in double quotes may hold commas (`"m.grid[1,0]"`, `""` is one quote, RFC 4180);
 * an unquoted field's commas inside `[...]` belong to it (`m.grid[1,0]`, IEC 61131-3's subscript list).
 * Blanks around the name and inside a subscript list are dropped (`grid[1, 0]` is `grid[1,0]`).
 * `*name` gets the name; returns the text after the comma that ends it, or NULL when the name ends the
 * text (`*fault` then says whether a quote was left open). */
static char *next_name(char *p, char **name, const char **fault) {
    char *r = p, *w = p, *rest = NULL;
    int quoted = 0, depth = 0;
    *fault = NULL;
    while (*r && isspace((unsigned char)*r)) r++;
    *name = w;
    if (*r == '"') {
        quoted = 1;
        r++;
    }
    for (; *r; r++) {
        if (quoted == 1 && *r == '"') {
            if (r[1] != '"') {
                quoted = 2;
                r++;
                break;
            }
            r++;
        } else if (*r == '[') {
            depth++;
        } else if (*r == ']' && depth > 0) {
            depth--;
        } else if (*r == ',' && depth == 0 && !quoted) {
            break;
        }
        if (depth > 0 && isspace((unsigned char)*r)) continue;
        *w++ = *r;
    }
    if (quoted == 1) *fault = "a quoted name has no closing `\"`";
    if (quoted == 2) {
        while (*r && isspace((unsigned char)*r)) r++;
        if (*r && *r != ',') *fault = "text after a quoted name (write `\"name\",` or the name without quotes)";
    }
    if (*r == ',') rest = r + 1;
    while (w > *name && isspace((unsigned char)w[-1])) w--;
    *w = '\0';
    return rest;
}

/* Parses the stimulus file into rows sorted by cycle (file order within a cycle). Returns -1 on error. */
static int load_stimulus(const char *path, stimulus_row **rows_out, size_t *count_out) {
    size_t len, count = 0, cap = 0, lineno = 0;
    char *text = read_file(path, &len), *line, *next;
    stimulus_row *rows = NULL;
    char err[512];
    if (!text) {
        fprintf(stderr, "%s: cannot read the stimulus file: %s\n", path, strerror(errno));
        return -1;
    }
    if (len >= 3 && (unsigned char)text[0] == 0xEF && (unsigned char)text[1] == 0xBB && (unsigned char)text[2] == 0xBF)
        memmove(text, text + 3, len - 2);
    for (line = text; line; line = next) {
        char *c1, *c2, *cycle_s, *name, *value, *end;
        const char *fault = NULL;
        unsigned long long cycle;
        stimulus_row row;
        next = strchr(line, '\n');
        if (next) *next++ = '\0';
        lineno++;
        if (strlen(line) && line[strlen(line) - 1] == '\r') line[strlen(line) - 1] = '\0';
        if (*trim(line) == '\0' || *trim(line) == '#') continue;
        c1 = strchr(line, ',');
        /* the name as the trace header writes it (quoted, or with a subscript list `grid[1,0]`);
           the value is the rest of the line */
        c2 = c1 ? next_name(c1 + 1, &name, &fault) : NULL;
        if (fault) {
            fprintf(stderr, "%s:%lu: %s\n", path, (unsigned long)lineno, fault);
            goto bad;
        }
        if (!c2) {
            fprintf(stderr, "%s:%lu: expected `cycle,variable,value`\n", path, (unsigned long)lineno);
            goto bad;
        }
        *c1 = '\0';
        cycle_s = trim(line);
        value = trim(c2);
        if (ieq(cycle_s, "cycle") && ieq(name, "variable")) continue; /* header */
        errno = 0;
        cycle = strtoull(cycle_s, &end, 10);
        if (!*cycle_s || *end || errno || cycle_s[0] == '-') {
            fprintf(stderr, "%s:%lu: the cycle `%s` is not a non-negative integer\n", path, (unsigned long)lineno,
                    cycle_s);
            goto bad;
        }
        memset(&row, 0, sizeof row);
        row.cycle = cycle;
        if (resolve(name, &row.var, err, sizeof err)) {
            fprintf(stderr, "%s:%lu: %s\n", path, (unsigned long)lineno, err);
            goto bad;
        }
        if (read_only(name)) {
            fprintf(stderr, "%s:%lu: `%s` is a READ_ONLY access path: it cannot be written (declare it READ_WRITE in VAR_ACCESS)\n",
                    path, (unsigned long)lineno, name);
            goto bad;
        }
        if (ladderc_parse_value(row.var.type, value, &row.value, err, sizeof err)) {
            fprintf(stderr, "%s:%lu: %s (variable `%s` is %s)\n", path, (unsigned long)lineno, err, name,
                    ladderc_type_name(row.var.type));
            goto bad;
        }
        if (count == cap) {
            stimulus_row *nr;
            cap = cap ? cap * 2 : 16;
            nr = (stimulus_row *)realloc(rows, cap * sizeof *rows);
            if (!nr) {
                fprintf(stderr, "%s: out of memory\n", path);
                goto bad;
            }
            rows = nr;
        }
        rows[count++] = row;
    }
    free(text);
    /* Rows apply in cycle order, file order within a cycle: a stable insertion sort, skipped when the
     * file is already ordered (the usual case), so loading stays linear. */
    {
        size_t i;
        int sorted = 1;
        for (i = 1; i < count; i++)
            if (rows[i].cycle < rows[i - 1].cycle) sorted = 0;
        if (!sorted) {
            for (i = 1; i < count; i++) {
                stimulus_row r = rows[i];
                size_t j = i;
                while (j > 0 && rows[j - 1].cycle > r.cycle) {
                    rows[j] = rows[j - 1];
                    j--;
                }
                rows[j] = r;
            }
        }
    }
    *rows_out = rows;
    *count_out = count;
    return 0;
bad:
    free(text);
    free(rows);
    return -1;
}

static int parse_cycle_ms(const char *s, int64_t *ns) {
    char *end;
    double ms;
    errno = 0;
    ms = strtod(s, &end);
    if (end == s || *end || errno || !(ms > 0) || ms > 1e9) return -1;
    *ns = (int64_t)llround(ms * 1e6);
    return *ns > 0 ? 0 : -1;
}

/* Rewrites the progress file with the number of cycles done (fixed width: a reader never sees a mix). */
static void report_progress(FILE *f, unsigned long long done) {
    if (!f) return;
    rewind(f);
    fprintf(f, "%020llu\n", done);
    fflush(f);
}

/* ------------------------------------------------------------------ the trace writer
 * Rows go into one buffer that is written with fwrite when it fills (no per-value stdio call, no allocation
 * per cycle). Each column keeps the raw bytes and the text of its last value: an unchanged value (most of a
 * trace: inputs, flags, resting axes) is copied, not formatted again. With --trace-raw (ladderc run uses
 * it), a REAL or LREAL value is written as a marker byte and its raw bits, which ladderc turns into the same
 * text with the ryu formatter: TRACE_F64 + 8 bytes, TRACE_F32 + 4 bytes (host byte order), TRACE_ESC + a
 * byte of text that would read as a marker, TRACE_EOR for the end of a row, TRACE_SAME for a float equal to
 * the one of its column in the row before. Without it the trace is CSV. */
#define TRACE_F64 1
#define TRACE_F32 2
#define TRACE_ESC 3
#define TRACE_EOR 4
#define TRACE_SAME 5
#define TRACE_CACHE 32

typedef struct {
    unsigned bytes;          /* of the value, as ladderc_read_var writes it */
    int scalar;              /* at most 8 bytes, compared as `last` */
    int cached;              /* last/text hold the previous row's value */
    unsigned char text_len;
    uint64_t last;
    char text[TRACE_CACHE];
} trace_column;

static trace_column *columns;
static FILE *trace_file;
static int trace_raw;
static size_t trace_len;
static char trace_buf[1 << 16];
/* one field's text at most, escaped: the buffer is flushed when less than this is left */
#define TRACE_FIELD_MAX (2 * (4 * (LADDERC_STRING_CAP + 1) + 16) + 16)

static void trace_flush(void) {
    if (trace_len) fwrite(trace_buf, 1, trace_len, trace_file);
    trace_len = 0;
}

static void trace_room(void) {
    if (trace_len + TRACE_FIELD_MAX > sizeof trace_buf) trace_flush();
}

static void trace_put(const char *text, size_t n) {
    memcpy(trace_buf + trace_len, text, n);
    trace_len += n;
}

/* Text of any length that may hold marker bytes (names, strings): escaped in raw mode. */
static void trace_put_text(const char *text, size_t n) {
    size_t i;
    for (i = 0; i < n; i++) {
        unsigned char c = (unsigned char)text[i];
        if (trace_len + 2 > sizeof trace_buf) trace_flush();
        if (trace_raw && c >= TRACE_F64 && c <= TRACE_SAME) trace_buf[trace_len++] = TRACE_ESC;
        trace_buf[trace_len++] = (char)c;
    }
}

/* A column name; CSV-quoted when it holds a comma or a quote (`main.grid[0,1]`, a 2-D array element). */
static void trace_put_name(const char *name) {
    size_t i, n = strlen(name);
    if (!strpbrk(name, ",\"")) {
        trace_put_text(name, n);
        return;
    }
    trace_put_text("\"", 1);
    for (i = 0; i < n; i++) {
        if (name[i] == '"') trace_put_text("\"", 1);
        trace_put_text(name + i, 1);
    }
    trace_put_text("\"", 1);
}

static void trace_u64(unsigned long long v) {
    char d[24];
    int n = 0;
    do {
        d[n++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    while (n) trace_buf[trace_len++] = d[--n];
}

static void trace_end_row(void) {
    if (trace_raw) trace_buf[trace_len++] = TRACE_EOR;
    else trace_buf[trace_len++] = '\n';
}

/* time_ms of a row: the scan clock in milliseconds, without trailing zeros in the fraction. */
static void trace_time_ms(int64_t ns) {
    if (ns < 0) {
        trace_buf[trace_len++] = '-';
        ns = -ns;
    }
    trace_u64((unsigned long long)(ns / 1000000));
    if (ns % 1000000) {
        char frac[8];
        int n = 6, k;
        int64_t f = ns % 1000000;
        for (k = 5; k >= 0; k--) {
            frac[k] = (char)('0' + f % 10);
            f /= 10;
        }
        while (frac[n - 1] == '0') n--;
        trace_buf[trace_len++] = '.';
        trace_put(frac, (size_t)n);
    }
}

/* The value of a column of at most 8 bytes, as bits. */
static uint64_t trace_bits(const ladderc_var *var, unsigned bytes) {
    uint64_t bits = 0;
    uint8_t u8;
    uint16_t u16;
    uint32_t u32;
    any_value v;
    const void *p = var->ptr;
    if (var->area) {
        ladderc_read_var(var, &v);
        p = &v;
    }
    switch (bytes) {
    case 1: memcpy(&u8, p, 1); bits = u8; break;
    case 2: memcpy(&u16, p, 2); bits = u16; break;
    case 4: memcpy(&u32, p, 4); bits = u32; break;
    default: memcpy(&bits, p, 8); break;
    }
    return bits;
}

/* One watched value, after its comma. */
static void trace_value(const ladderc_var *var, trace_column *c, char *text, size_t text_cap) {
    any_value v;
    size_t n;
    if (c->scalar) {
        uint64_t bits = trace_bits(var, c->bytes);
        int same = c->cached && bits == c->last;
        if (trace_raw && (var->type == LADDERC_T_LREAL || var->type == LADDERC_T_REAL)) {
            if (same) {
                trace_buf[trace_len++] = TRACE_SAME;
                return;
            }
            trace_buf[trace_len++] = var->type == LADDERC_T_LREAL ? TRACE_F64 : TRACE_F32;
            if (c->bytes == 8) trace_put((const char *)&bits, 8);
            else {
                uint32_t single = (uint32_t)bits;
                trace_put((const char *)&single, 4);
            }
            c->cached = 1;
            c->last = bits;
            return;
        }
        if (same) {
            /* the buffer has room for TRACE_CACHE bytes more than a field: a fixed-size copy */
            memcpy(trace_buf + trace_len, c->text, TRACE_CACHE);
            trace_len += c->text_len;
            return;
        }
        c->last = bits;
    }
    ladderc_read_var(var, &v);
    ladderc_format_value(var->type, &v, text, text_cap);
    n = strlen(text);
    trace_put_text(text, n);
    /* strings are formatted every row */
    c->cached = c->scalar && n < TRACE_CACHE;
    if (c->cached) {
        memcpy(c->text, text, n);
        c->text_len = (unsigned char)n;
    }
}

#ifdef LADDERC_LOOP_LIMIT
uint64_t ladderc_loop_steps;

void ladderc_loop_stuck(unsigned file, unsigned long start, unsigned long end) {
    trace_flush();
    fflush(stdout);
    fprintf(stderr, "ladderc-loop-guard %u %lu %lu %llu %llu\n", file, start, end,
            (unsigned long long)ladderc_cycle, (unsigned long long)(LADDERC_LOOP_LIMIT));
    fflush(stderr);
    exit(3);
}
#endif

int main(int argc, char **argv) {
    unsigned long long cycles = 1;
    int64_t cycle_ns = LADDERC_DEFAULT_CYCLE_NS;
    const char *stimulus_path = NULL, *trace_path = NULL, *watch_list = NULL, *progress_path = NULL;
    FILE *progress = NULL;
    clock_t last_report = 0;
    int list = 0, i;
    size_t row_count = 0, next_row = 0, watch_count = 0, w;
    FILE *trace = stdout;
    char err[512];
    static char value_text[4 * (LADDERC_STRING_CAP + 1) + 16];

    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(a, "--list")) {
            list = 1;
            continue;
        } else if (!strcmp(a, "--trace-raw")) {
            trace_raw = 1;
            continue;
        }
        if (!v) {
            fprintf(stderr, "error: `%s` needs a value (or is unknown)\n", a);
            usage(stderr);
            return 2;
        }
        if (!strcmp(a, "--cycles")) {
            char *end;
            errno = 0;
            cycles = strtoull(v, &end, 10);
            if (!*v || *end || errno || v[0] == '-') {
                fprintf(stderr, "error: --cycles expects a non-negative integer, got `%s`\n", v);
                return 2;
            }
        } else if (!strcmp(a, "--cycle-ms")) {
            if (parse_cycle_ms(v, &cycle_ns)) {
                fprintf(stderr, "error: --cycle-ms expects a positive number of milliseconds, got `%s`\n", v);
                return 2;
            }
        } else if (!strcmp(a, "--stimulus")) stimulus_path = v;
        else if (!strcmp(a, "--trace")) trace_path = v;

        else if (!strcmp(a, "--watch")) watch_list = v;
        else if (!strcmp(a, "--progress")) progress_path = v;
        else {
            fprintf(stderr, "error: unknown option `%s`\n", a);
            usage(stderr);
            return 2;
        }
        i++;
    }

    if (list) {
        size_t k;
        for (k = 0; k < ladderc_var_count; k++)
            if (!hidden_name(ladderc_vars[k].name))
                printf("%s : %s\n", ladderc_vars[k].name, ladderc_type_name(ladderc_vars[k].type));
        return 0;
    }

    if (watch_list) {
        char *copy = (char *)malloc(strlen(watch_list) + 1), *tok, *save;
        watch_copy = copy;
        size_t n = 1;
        const char *p;
        for (p = watch_list; *p; p++) n += *p == ',';
        watch = (ladderc_var *)calloc(n, sizeof *watch);
        if (!copy || !watch) return 2;
        strcpy(copy, watch_list);
        for (tok = copy; tok; tok = save) {
            char *name;
            const char *fault;
            /* names as the trace header writes them: `m.grid[1,0]` is one name */
            save = next_name(tok, &name, &fault);
            if (fault) {
                fprintf(stderr, "error: --watch: %s\n", fault);
                return 2;
            }
            if (!*name) continue;
            if (resolve(name, &watch[watch_count], err, sizeof err)) {
                fprintf(stderr, "error: --watch: %s\n", err);
                return 2;
            }
            /* the header shows the name as the user wrote it; `name` lives in watch_copy */
            watch[watch_count].name = name;
            watch_count++;
        }
    } else {
        watch = (ladderc_var *)calloc(ladderc_var_count + 1, sizeof *watch);
        if (!watch) return 2;
        watch_count = 0;
        for (w = 0; w < ladderc_var_count; w++)
            if (!hidden_name(ladderc_vars[w].name)) watch[watch_count++] = ladderc_vars[w];
    }

    if (stimulus_path && load_stimulus(stimulus_path, &rows, &row_count)) return 2;

    if (progress_path) {
        progress = fopen(progress_path, "w");
        if (!progress) {
            fprintf(stderr, "%s: cannot write the progress file: %s\n", progress_path, strerror(errno));
            return 2;
        }
        report_progress(progress, 0);
        last_report = clock();
    }

    if (trace_path && strcmp(trace_path, "-")) {
        trace = fopen(trace_path, "w");
        if (!trace) {
            fprintf(stderr, "%s: cannot write the trace file: %s\n", trace_path, strerror(errno));
            if (progress) fclose(progress);
            return 2;
        }
    }

    columns = (trace_column *)calloc(watch_count + 1, sizeof *columns);
    if (!columns) return 2;
    for (w = 0; w < watch_count; w++) {
        columns[w].bytes = ladderc_type_bytes(watch[w].type);
        columns[w].scalar = columns[w].bytes <= 8;
    }
    trace_file = trace;
    trace_put("cycle,time_ms", 13);
    for (w = 0; w < watch_count; w++) {
        trace_room();
        trace_buf[trace_len++] = ',';
        trace_put_name(watch[w].name);
    }
    trace_end_row();

    ladderc_now = 0;
    ladderc_program_init();
    {
        unsigned long long k;
        for (k = 0; k < cycles; k++) {
            ladderc_cycle = k;
            ladderc_now = (IEC_TIME)(k * (uint64_t)cycle_ns);
            while (next_row < row_count && rows[next_row].cycle < k) next_row++;
            while (next_row < row_count && rows[next_row].cycle == k) {
                ladderc_write_var(&rows[next_row].var, &rows[next_row].value);
                next_row++;
            }
#ifdef LADDERC_LOOP_LIMIT
            ladderc_loop_steps = 0;
#endif
            ladderc_program_scan();
            trace_room();
            trace_u64(k);
            trace_buf[trace_len++] = ',';
            trace_time_ms(ladderc_now);
            for (w = 0; w < watch_count; w++) {
                trace_room();
                trace_buf[trace_len++] = ',';
                trace_value(&watch[w], &columns[w], value_text, sizeof value_text);
            }
            trace_end_row();
            if (progress && (k & 255) == 255) {
                clock_t now = clock();
                if (now - last_report >= CLOCKS_PER_SEC / 10) {
                    report_progress(progress, k + 1);
                    last_report = now;
                }
            }
        }
    }
    trace_flush();
    if (progress) {
        report_progress(progress, cycles);
        fclose(progress);
    }
    if (trace != stdout) fclose(trace);
    else fflush(stdout);
    free(rows);
    free(watch);
    free(watch_copy);
    free(columns);
    if (ladderc_errors & LADDERC_ERR_DIV_ZERO) fprintf(stderr, "runtime: integer division by zero (result 0)\n");
    if (ladderc_errors & LADDERC_ERR_RANGE) fprintf(stderr, "runtime: conversion out of range or value outside a subrange (saturated)\n");
    if (ladderc_errors & LADDERC_ERR_BOUNDS)
        fprintf(stderr, "runtime: array index out of range (first: %s, index %lld outside %lld..%lld; the first element used)\n",
                ladderc_bounds_site, (long long)ladderc_bounds_at[0], (long long)ladderc_bounds_at[1], (long long)ladderc_bounds_at[2]);
    if (ladderc_errors & LADDERC_ERR_STRING) fprintf(stderr, "runtime: string truncated\n");
    if (ladderc_errors & LADDERC_ERR_STRPOS) fprintf(stderr, "runtime: string length or position out of range\n");
    if (ladderc_errors & LADDERC_ERR_MUX) fprintf(stderr, "runtime: MUX selector K out of range (IN0 selected)\n");
    if (ladderc_errors & LADDERC_ERR_NULL_REF) fprintf(stderr, "runtime: NULL reference dereferenced (first: %s; zero read, write dropped)\n", ladderc_null_ref_site);
    if (ladderc_errors & LADDERC_ERR_MEM) fprintf(stderr, "runtime: memory function count beyond its variables (first: %s; clipped to their size)\n", ladderc_mem_site);
    if (ladderc_errors & LADDERC_ERR_POINTER) fprintf(stderr, "runtime: pointer outside its variable dereferenced (first: %s; zero read, write dropped)\n", ladderc_pointer_site);
    if (ladderc_errors & LADDERC_ERR_CHAR_INDEX)
        fprintf(stderr, "runtime: string index out of range (first: %s, index %lld outside %lld..%lld; NUL read, write dropped)\n",
                ladderc_char_index_site, (long long)ladderc_char_index_at[0], (long long)ladderc_char_index_at[1],
                (long long)ladderc_char_index_at[2]);
    return 0;
}
