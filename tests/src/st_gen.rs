//! Seeded generator of random valid IEC 61131-3 Structured Text projects, for the differential run
//! against matiec (the ST sibling of [`crate::il_gen`]).
//!
//! Input: a seed (`u64`). Output: the text of one `.st` file whose first line is
//! `(* matiec-diff: cycles=N seed=S *)`: a TYPE block (an enumeration, a subrange, a structure),
//! user FUNCTIONs (VAR_INPUT, VAR_OUTPUT, an early RETURN), a FUNCTION_BLOCK (VAR_INPUT, VAR_OUTPUT,
//! VAR_IN_OUT, standard blocks inside), one PROGRAM and a CONFIGURATION whose one task runs it every
//! 10 ms. The body uses expressions with precedence and parentheses (arithmetic, comparison,
//! AND/OR/XOR/NOT/&, `**` on REAL), IF/ELSIF/ELSE, CASE with lists, ranges and ELSE (on integers and on
//! the enumeration), FOR with positive and negative BY, WHILE and REPEAT with bounded iterations, EXIT,
//! formal and informal function calls, `=>` outputs, the standard blocks (TON, TOF, TP, CTU, CTD, CTUD,
//! R_TRIG, F_TRIG, SR, RS) and functions (conversions, SEL, MUX, MAX, MIN, LIMIT, ABS, SQRT,
//! SHL/SHR/ROL/ROR, extensible ADD/MUL/MAX/MIN/CONCAT), arrays of integers and of structures, TIME,
//! STRING (LEN, CONCAT, LEFT, RIGHT, MID, FIND), typed and untyped literals. Its typed statements (about
//! a third) add USINT, UINT, UDINT, ULINT, INT, LINT, BYTE, WORD, DWORD, LWORD and LREAL arithmetic, bit
//! operations and conversions between all of them, a 2-D array with a negative lower bound and an array
//! from -3, whole-structure assignment, STRING INSERT/DELETE/REPLACE/MID and comparison, TIME + TIME,
//! TIME - TIME, TIME * INT and TIME / INT, a block `mix_fb` whose VAR_IN_OUT comes before its outputs
//! (called informally and formally with `=>`, its outputs read as `mx0.q` in expressions), a function
//! `sumto` with two outputs and a RETURN inside a FOR, and a FOR nested in a FOR with an EXIT of the
//! inner loop. The program counts its scans (`tick`) and derives its inputs from the count, so edges,
//! timers and counters fire.
//!
//! Invariants: the same seed gives the same text. Nothing is generated whose result the standard leaves
//! open or that the two compilers are known to settle differently (`KNOWN` of `matiec_diff.rs`): every
//! integer expression is DINT and tracked as an interval (an operation whose interval could leave
//! ±2**30 is not generated), every stored value is brought back into its variable's range with LIMIT;
//! divisors are non-zero literals, shift counts are literals below the width, MUX selectors and array
//! indices are within range, timers have a fixed PT > 0, counters never count past PV or below 0 (their
//! count inputs are gated by CV), strings keep 4 to 12 characters (LEFT/RIGHT/MID within them), FOR
//! loops have literal bounds whose distance is a multiple of BY and their control variable is set
//! again after the loop (its value after a loop is implementation-dependent), WHILE and REPEAT are
//! bounded by a counter the body does not write, a REAL expression is one operation deep (`**` and SQRT
//! only of a variable, at the top: matiec keeps REAL intermediates in C double, `KNOWN`
//! real_intermediate_precision), CTUD's reset and load inputs stay FALSE, timers keep one PT per
//! program, FIND looks for text that cannot start inside a partial match (`KNOWN` find_overlap), a
//! CASE has at least one element. In the typed statements every integer value is tracked as an
//! interval within its type (a conversion's argument is first brought within the target's range with
//! LIMIT or a bit mask), 64-bit literals are typed (`KNOWN` lint_compare_literal), REPLACE's IN2 is as
//! long as L (`KNOWN` strings_edges), TIME values stay whole milliseconds below 1 s with literals
//! matiec holds exactly and divisors that divide them exactly (`KNOWN` time_literals, time_ops), and a
//! function with `=>` outputs is never called inside an expression (iec2c's C then calls an inline
//! helper it never defines, a link error).
//!
//! Not generated because iec2c (IEC 61131-3 ed. 2) refuses them: enumerations with explicit values
//! (ed. 3; ladderc runs them), arrays of FB instances (ladderc runs them), FB instances in structures.

use crate::il_gen::Rng;
use std::fmt::Write as _;

/// the largest magnitude an intermediate DINT value may reach
const SAFE: i64 = 1 << 30;

/// The generator's state: the seed's random sequence and what the program declares.
struct Gen {
    rng: Rng,
    /// user functions: name (each takes `a`, `b` : DINT, gives DINT and `flag` : BOOL)
    funcs: Vec<String>,
    /// instances of the user block `acc_fb`
    blocks: usize,
    /// nesting depth of statements
    depth: usize,
    /// inside a loop (EXIT allowed)
    in_loop: bool,
    /// loop counters in use (not to be written by a body)
    loops: usize,
    /// PT (ms) of ton0, tof0, tp0: fixed for the program (a PT that changes while a timer runs is
    /// `KNOWN` timers_pt)
    pts: [i64; 3],
}

/// DINT variables of the program, each kept in -1000..=1000.
const DVARS: &[&str] = &["d0", "d1", "d2", "d3"];
/// INT variables, kept in -1000..=1000.
const NVARS: &[&str] = &["n0", "n1"];
/// BOOL variables.
const BVARS: &[&str] = &["b0", "b1", "b2", "b3", "b4"];
/// REAL variables, kept in -1000.0..=1000.0.
const RVARS: &[&str] = &["r0", "r1"];
/// The enumeration's values.
const COLORS: &[&str] = &["Red", "Green", "Blue", "Amber"];

/// A random valid ST project for `seed` (see the module header).
pub fn generate(seed: u64) -> String {
    let mut g = Gen {
        rng: Rng::new(seed),
        funcs: Vec::new(),
        blocks: 0,
        depth: 0,
        in_loop: false,
        loops: 0,
        pts: [0; 3],
    };
    g.project(seed)
}

impl Gen {
    fn project(&mut self, seed: u64) -> String {
        let cycles = 40 + self.rng.below(41);
        for pt in &mut self.pts {
            *pt = self.rng.range(1, 6) * 10;
        }
        let mut out = String::new();
        let _ = writeln!(
            out,
            "(* matiec-diff: cycles={cycles} seed={seed}. Generated by ladderc-tests' st_gen (random valid ST). *)"
        );
        out.push_str(
            "TYPE\n  Color : (Red, Green, Blue, Amber);\n  Level : INT (0..10);\n  Pt : STRUCT\n    x : DINT;\n    y : INT;\n    lit : BOOL;\n  END_STRUCT;\nEND_TYPE\n\n",
        );
        let nf = 1 + self.rng.below(2);
        for k in 0..nf {
            out.push_str(&self.function(k));
        }
        out.push_str(&self.block());
        out.push_str(&self.sumto_and_mix());
        self.blocks = 1 + self.rng.below(2);
        out.push_str(&self.program());
        out.push_str("CONFIGURATION cfg\n  RESOURCE res ON PLC\n    TASK tsk (INTERVAL := T#10ms, PRIORITY := 0);\n    PROGRAM inst WITH tsk : prog;\n  END_RESOURCE\nEND_CONFIGURATION\n");
        out
    }

    /// `FUNCTION fK : DINT` of `a`, `b` (each within -1000..=1000) with output `flag`.
    fn function(&mut self, k: usize) -> String {
        let name = format!("f{k}");
        let mut s = String::new();
        let _ = writeln!(
            s,
            "FUNCTION {name} : DINT\n  VAR_INPUT\n    a : DINT;\n    b : DINT;\n  END_VAR\n  VAR_OUTPUT\n    flag : BOOL;\n  END_VAR\n  VAR\n    t : DINT;\n  END_VAR"
        );
        let leaves: &[&str] = &["a", "b", "t"];
        let e1 = self.int_expr_over(leaves, 2);
        let c = self.cmp_over(leaves);
        let e2 = self.int_expr_over(leaves, 2);
        let _ = writeln!(s, "  t := LIMIT(-1000, {}, 1000);", e1.0);
        let _ = writeln!(s, "  flag := {c};");
        let _ = writeln!(
            s,
            "  IF flag THEN\n    {name} := t;\n    RETURN;\n  END_IF;\n  {name} := LIMIT(-1000, {}, 1000);\nEND_FUNCTION\n",
            e2.0
        );
        self.funcs.push(name);
        s
    }

    /// `FUNCTION_BLOCK acc_fb`: an edge-triggered accumulator with a gated counter and an in-out total.
    fn block(&mut self) -> String {
        let step_mod = self.rng.range(50, 400);
        let pv = self.rng.range(2, 5);
        format!(
            "FUNCTION_BLOCK acc_fb\n  VAR_INPUT\n    go : BOOL;\n    inc : DINT;\n  END_VAR\n  VAR_OUTPUT\n    q : BOOL;\n    acc : DINT;\n  END_VAR\n  VAR_IN_OUT\n    total : DINT;\n  END_VAR\n  VAR\n    edge : R_TRIG;\n    cnt : CTU;\n  END_VAR\n  edge(CLK := go);\n  IF edge.Q THEN\n    acc := (acc + inc) MOD {step_mod};\n  END_IF;\n  cnt(CU := go AND cnt.CV < {pv}, R := NOT go AND cnt.Q, PV := {pv});\n  q := cnt.Q;\n  total := LIMIT(-1000, total + acc, 1000);\nEND_FUNCTION_BLOCK\n\n"
        )
    }

    /// `FUNCTION sumto` (two outputs, RETURN inside a FOR) and `FUNCTION_BLOCK mix_fb` (inputs, an
    /// in-out LINT, outputs, declared in that order for the informal call)
    fn sumto_and_mix(&mut self) -> String {
        let by = self.rng.range(1, 3);
        let off = self.rng.range(0, 300);
        let thr = self.rng.range(-500, 500);
        format!(
            "FUNCTION sumto : DINT\n  VAR_INPUT\n    lim : DINT;\n    delta : DINT;\n  END_VAR\n  VAR_OUTPUT\n    count : DINT;\n    over : BOOL;\n  END_VAR\n  VAR\n    n : DINT;\n  END_VAR\n  sumto := 0;\n  count := 0;\n  over := FALSE;\n  FOR n := 1 TO 19 BY {by} DO\n    sumto := sumto + delta;\n    count := count + 1;\n    IF sumto > lim THEN\n      over := TRUE;\n      RETURN;\n    END_IF;\n  END_FOR;\nEND_FUNCTION\n\n\
             FUNCTION_BLOCK mix_fb\n  VAR_INPUT\n    en0 : BOOL;\n    k : UINT;\n  END_VAR\n  VAR_IN_OUT\n    io : LINT;\n  END_VAR\n  VAR_OUTPUT\n    q : BOOL;\n    cnt : UDINT;\n  END_VAR\n  IF en0 THEN\n    io := LIMIT(LINT#-10000000, io + UINT_TO_LINT(k) - LINT#{off}, LINT#10000000);\n    cnt := (cnt + 1) MOD 1000;\n  END_IF;\n  q := io > LINT#{thr};\nEND_FUNCTION_BLOCK\n\n"
        )
    }

    fn program(&mut self) -> String {
        let mut s = String::from("PROGRAM prog\n  VAR\n    tick : DINT;\n");
        for v in DVARS {
            let init = self.rng.range(-50, 50);
            let _ = writeln!(s, "    {v} : DINT := {init};");
        }
        for v in NVARS {
            let _ = writeln!(s, "    {v} : INT;");
        }
        for v in BVARS {
            let _ = writeln!(s, "    {v} : BOOL;");
        }
        for v in RVARS {
            let _ = writeln!(s, "    {v} : REAL := 1.5;");
        }
        s.push_str(
            "    u0 : UINT;\n    w0 : WORD := 16#00F1;\n    col : Color := Green;\n    lvl : Level;\n    arr : ARRAY[0..7] OF DINT;\n    pts : ARRAY[1..3] OF Pt;\n    txt : STRING := 'ladder';\n    tlen : INT;\n    tpos : INT;\n    t0 : TIME;\n    t1 : TIME;\n    i : DINT;\n    j : INT;\n    k : INT;\n    ton0 : TON;\n    tof0 : TOF;\n    tp0 : TP;\n    ctu0 : CTU;\n    ctd0 : CTD;\n    ctud0 : CTUD;\n    rt0 : R_TRIG;\n    ft0 : F_TRIG;\n    sr0 : SR;\n    rs0 : RS;\n",
        );
        for b in 0..self.blocks {
            let _ = writeln!(s, "    fb{b} : acc_fb;");
        }
        let _ = writeln!(
            s,
            "    us0 : USINT := {};\n    ud0 : UDINT := {};\n    ul0 : ULINT := {};\n    li0 : LINT := {};\n    li1 : LINT := {};\n    by0 : BYTE := 16#{:02X};\n    dw0 : DWORD := 16#{:08X};\n    lw0 : LWORD := 16#{:016X};\n    lr0 : LREAL := {}.75;\n    lr1 : LREAL := -{}.5;",
            self.rng.range(0, 200),
            self.rng.range(0, 100_000),
            self.rng.range(0, 10_000_000),
            self.rng.range(-10_000_000, 10_000_000),
            self.rng.range(-1000, 1000),
            self.rng.range(0, 255),
            self.rng.range(0, 0xFFFF_FFFF),
            self.rng.range(0, i64::MAX - 1),
            self.rng.range(0, 99),
            self.rng.range(0, 99),
        );
        s.push_str("    sum_m2 : DINT;\n    sum_arr : DINT;\n    sum_lb : UDINT;\n    sum_pts : DINT;\n    any_lit : BOOL;\n");
        s.push_str("    m2 : ARRAY[-2..1, 1..3] OF INT;\n    lb : ARRAY[-3..2] OF UDINT;\n    p0 : Pt;\n    s2 : STRING := 'abcdefgh';\n    t2 : TIME;\n    i2 : DINT;\n    mx0 : mix_fb;\n    mx1 : mix_fb;\n");
        s.push_str("  END_VAR\n  tick := tick + 1;\n");
        // inputs from the scan count
        for v in &BVARS[..3] {
            let p = self.rng.range(2, 7);
            let ph = self.rng.range(0, p - 1);
            let _ = writeln!(s, "  {v} := ((tick + {ph}) / {p}) MOD 2 = 0;");
        }
        let n = 10 + self.rng.below(10);
        for _ in 0..n {
            self.depth = 1;
            let st = self.statement();
            s.push_str(&st);
        }
        // matiec's trace has no array or structure elements: their sums are compared instead
        let m2: Vec<String> = (-2..=1)
            .flat_map(|i| (1..=3).map(move |j| format!("INT_TO_DINT(m2[{i}, {j}])")))
            .collect();
        let arr: Vec<String> = (0..8).map(|i| format!("arr[{i}]")).collect();
        let lb: Vec<String> = (-3..=2).map(|i| format!("lb[{i}]")).collect();
        let _ = writeln!(
            s,
            "  sum_m2 := {};\n  sum_arr := {};\n  sum_lb := {};\n  sum_pts := pts[1].x + pts[2].x + pts[3].x + INT_TO_DINT(pts[1].y + pts[2].y + pts[3].y) + p0.x + INT_TO_DINT(p0.y);\n  any_lit := pts[1].lit OR pts[2].lit XOR pts[3].lit OR p0.lit;",
            m2.join(" + "),
            arr.join(" + "),
            lb.join(" + ")
        );
        s.push_str("END_PROGRAM\n\n");
        s
    }

    fn ind(&self) -> String {
        "  ".repeat(self.depth)
    }

    /// One statement (with nested ones up to depth 3).
    fn statement(&mut self) -> String {
        if self.rng.chance(30) {
            return self.typed_stmt();
        }
        let ind = self.ind();
        let nested = self.depth < 3;
        let choice = self.rng.below(if nested { 22 } else { 14 });
        match choice {
            0 | 1 => {
                let v = *self.rng.pick(DVARS);
                let e = self.int_expr(3);
                if self.rng.chance(30) {
                    format!("{ind}{v} := ({}) MOD {};\n", e.0, self.rng.range(7, 1000))
                } else {
                    format!("{ind}{v} := LIMIT(-1000, {}, 1000);\n", e.0)
                }
            }
            2 => {
                let v = *self.rng.pick(NVARS);
                let e = self.int_expr(2);
                format!("{ind}{v} := DINT_TO_INT(LIMIT(-1000, {}, 1000));\n", e.0)
            }
            3 => {
                let v = *self.rng.pick(&BVARS[3..]);
                let e = self.bool_expr(3);
                format!("{ind}{v} := {e};\n")
            }
            4 => {
                let v = *self.rng.pick(RVARS);
                let w = *self.rng.pick(RVARS);
                match self.rng.below(4) {
                    0 => format!("{ind}{v} := LIMIT(-1000.0, (ABS({w}) * 0.25) ** 2.0, 1000.0);\n"),
                    1 => format!("{ind}{v} := SQRT(ABS({w}));\n"),
                    _ => {
                        let e = self.real_expr(1);
                        format!("{ind}{v} := LIMIT(-1000.0, {}, 1000.0);\n", e.0)
                    }
                }
            }
            5 => self.std_block(),
            6 => self.user_call(),
            7 => self.string_stmt(),
            8 => self.bits_stmt(),
            9 => {
                // array of DINT, array of structures, subrange, enumeration
                match self.rng.below(4) {
                    0 => {
                        let idx = self.index(0, 7);
                        let e = self.int_expr(2);
                        format!("{ind}arr[{idx}] := LIMIT(-1000, {}, 1000);\n", e.0)
                    }
                    1 => {
                        let idx = self.index(1, 3);
                        let e = self.int_expr(2);
                        let b = self.bool_expr(2);
                        format!(
                            "{ind}pts[{idx}].x := LIMIT(-1000, {}, 1000);\n{ind}pts[{idx}].y := DINT_TO_INT(LIMIT(-100, pts[{idx}].x / 3, 100));\n{ind}pts[{idx}].lit := {b};\n",
                            e.0
                        )
                    }
                    2 => {
                        let e = self.int_expr(2);
                        format!("{ind}lvl := DINT_TO_INT(LIMIT(0, {}, 10));\n", e.0)
                    }
                    _ => {
                        let c = *self.rng.pick(COLORS);
                        let b = self.bool_expr(2);
                        let c2 = *self.rng.pick(COLORS);
                        format!("{ind}IF {b} THEN\n{ind}  col := {c};\n{ind}ELSE\n{ind}  col := {c2};\n{ind}END_IF;\n")
                    }
                }
            }
            10 => {
                let u = self.int_expr(2);
                format!("{ind}u0 := DINT_TO_UINT(LIMIT(0, {}, 1000));\n", u.0)
            }
            11 => {
                let b = self.bool_expr(2);
                format!("{ind}t1 := SEL({b}, T#15ms, t0 + T#5ms);\n")
            }
            12 | 13 => {
                if self.in_loop && self.rng.chance(50) {
                    let b = self.bool_expr(2);
                    format!("{ind}IF {b} THEN\n{ind}  EXIT;\n{ind}END_IF;\n")
                } else {
                    let v = *self.rng.pick(DVARS);
                    let e = self.int_expr(2);
                    format!("{ind}{v} := LIMIT(-1000, {}, 1000);\n", e.0)
                }
            }
            14 | 15 => self.if_stmt(),
            16 | 17 => self.case_stmt(),
            18 => self.for_stmt(),
            19 => self.while_stmt(),
            20 => self.repeat_stmt(),
            _ => self.case_enum(),
        }
    }

    fn block_of(&mut self, n: usize) -> String {
        self.depth += 1;
        let mut s = String::new();
        for _ in 0..n {
            s.push_str(&self.statement());
        }
        self.depth -= 1;
        s
    }

    fn if_stmt(&mut self) -> String {
        let ind = self.ind();
        let c = self.bool_expr(3);
        let n = 1 + self.rng.below(2);
        let mut s = format!("{ind}IF {c} THEN\n{}", self.block_of(n));
        for _ in 0..self.rng.below(3) {
            let c = self.bool_expr(2);
            let body = self.block_of(1);
            let _ = write!(s, "{ind}ELSIF {c} THEN\n{body}");
        }
        if self.rng.chance(60) {
            let body = self.block_of(1);
            let _ = write!(s, "{ind}ELSE\n{body}");
        }
        let _ = writeln!(s, "{ind}END_IF;");
        s
    }

    fn case_stmt(&mut self) -> String {
        let ind = self.ind();
        let m = self.rng.range(6, 12);
        let sel = self.int_expr(2);
        let mut s = format!("{ind}CASE ABS(({}) MOD {m}) OF\n", sel.0);
        let mut next = 0;
        let mut emitted = false;
        while next < m {
            let len = self.rng.range(1, 3).min(m - next);
            let label = match (len, self.rng.below(2)) {
                (1, _) => format!("{next}"),
                (_, 0) => format!("{}..{}", next, next + len - 1),
                _ => (next..next + len)
                    .map(|v| v.to_string())
                    .collect::<Vec<_>>()
                    .join(", "),
            };
            next += len;
            // at least one case element (IEC 61131-3's grammar; matiec refuses a CASE without)
            if self.rng.chance(25) && (emitted || next < m) {
                continue; // left to ELSE
            }
            emitted = true;
            let body = self.block_of(1);
            let _ = write!(s, "{ind}  {label}:\n{body}");
        }
        if self.rng.chance(70) {
            let body = self.block_of(1);
            let _ = write!(s, "{ind}ELSE\n{body}");
        }
        let _ = writeln!(s, "{ind}END_CASE;");
        s
    }

    fn case_enum(&mut self) -> String {
        let ind = self.ind();
        let mut s = format!("{ind}CASE col OF\n");
        let a = self.block_of(1);
        let b = self.block_of(1);
        let next = *self.rng.pick(COLORS);
        let _ = write!(
            s,
            "{ind}  Red:\n{a}{ind}  Green, Blue:\n{b}{ind}    col := {next};\n{ind}ELSE\n{ind}  col := Red;\n{ind}END_CASE;\n"
        );
        s
    }

    fn loop_body(&mut self, n: usize) -> String {
        let saved = self.in_loop;
        self.in_loop = true;
        self.loops += 1;
        let body = self.block_of(n);
        self.loops -= 1;
        self.in_loop = saved;
        body
    }

    fn for_stmt(&mut self) -> String {
        if self.loops > 0 {
            return self.if_stmt();
        }
        let ind = self.ind();
        let by = *self.rng.pick(&[1i64, 2, 3, -1, -2]);
        let steps = self.rng.range(1, 7 / by.abs());
        let (from, to) = if by > 0 {
            let from = self.rng.range(0, 7 - steps * by);
            (from, from + steps * by)
        } else {
            let from = self.rng.range(steps * -by, 7);
            (from, from + steps * by)
        };
        let e = self.int_expr(2);
        let body = self.loop_body(1);
        let by_text = if by == 1 && self.rng.chance(50) {
            String::new()
        } else {
            format!(" BY {by}")
        };
        format!(
            "{ind}FOR i := {from} TO {to}{by_text} DO\n{ind}  arr[i] := LIMIT(-1000, arr[i] + ({}), 1000);\n{body}{ind}END_FOR;\n{ind}i := 0;\n",
            e.0
        )
    }

    fn while_stmt(&mut self) -> String {
        if self.loops > 0 {
            return self.case_stmt();
        }
        let ind = self.ind();
        let n = self.rng.range(1, 5);
        let c = self.bool_expr(2);
        let body = self.loop_body(1);
        format!(
            "{ind}j := 0;\n{ind}WHILE j < {n} AND ({c}) DO\n{ind}  j := j + 1;\n{body}{ind}END_WHILE;\n"
        )
    }

    fn repeat_stmt(&mut self) -> String {
        if self.loops > 0 {
            return self.if_stmt();
        }
        let ind = self.ind();
        let n = self.rng.range(1, 5);
        let body = self.loop_body(1);
        let c = self.bool_expr(1);
        format!(
            "{ind}k := 0;\n{ind}REPEAT\n{ind}  k := k + 1;\n{body}{ind}UNTIL k >= {n} OR ({c})\n{ind}END_REPEAT;\n"
        )
    }

    fn std_block(&mut self) -> String {
        let ind = self.ind();
        let b = self.bool_expr(2);
        let dst = *self.rng.pick(&BVARS[3..]);
        match self.rng.below(10) {
            0 => {
                let pt = self.pts[0];
                format!("{ind}ton0(IN := {b}, PT := T#{pt}ms);\n{ind}{dst} := ton0.Q;\n{ind}t0 := ton0.ET;\n")
            }
            1 => {
                let pt = self.pts[1];
                format!("{ind}tof0(IN := {b}, PT := T#{pt}ms, Q => {dst}, ET => t0);\n")
            }
            2 => {
                let pt = self.pts[2];
                format!(
                    "{ind}tp0(IN := {b}, PT := T#{pt}ms);\n{ind}{dst} := tp0.Q AND t0 < T#1s;\n"
                )
            }
            3 => {
                let pv = self.rng.range(2, 6);
                let r = self.bool_expr(1);
                format!("{ind}ctu0(CU := ({b}) AND ctu0.CV < {pv}, R := {r}, PV := {pv});\n{ind}{dst} := ctu0.Q;\n")
            }
            4 => {
                let pv = self.rng.range(2, 6);
                format!("{ind}ctd0(CD := ({b}) AND ctd0.CV > 0, LD := ctd0.CV <= 0, PV := {pv});\n{ind}{dst} := ctd0.Q;\n")
            }
            5 => {
                let pv = self.rng.range(2, 6);
                let d = self.bool_expr(1);
                format!("{ind}ctud0(CU := ({b}) AND ctud0.CV < {pv}, CD := ({d}) AND ctud0.CV > 0, R := FALSE, LD := FALSE, PV := {pv});\n{ind}{dst} := ctud0.QU OR ctud0.QD;\n")
            }
            6 => format!("{ind}rt0(CLK := {b});\n{ind}{dst} := rt0.Q;\n"),
            7 => format!("{ind}ft0({b});\n{ind}{dst} := ft0.Q;\n"),
            8 => {
                let r = self.bool_expr(1);
                format!("{ind}sr0(S1 := {b}, R := {r}, Q1 => {dst});\n")
            }
            _ => {
                let r = self.bool_expr(1);
                format!("{ind}rs0(S := {b}, R1 := {r});\n{ind}{dst} := rs0.Q1;\n")
            }
        }
    }

    fn user_call(&mut self) -> String {
        let ind = self.ind();
        let dst = *self.rng.pick(DVARS);
        if self.rng.chance(50) {
            let f = self.rng.pick(&self.funcs).clone();
            let a = self.int_expr(2);
            let b = self.int_expr(2);
            let a = format!("LIMIT(-1000, {}, 1000)", a.0);
            let b = format!("LIMIT(-1000, {}, 1000)", b.0);
            if self.rng.chance(50) {
                format!("{ind}{dst} := {f}({a}, {b});\n")
            } else {
                let flag = *self.rng.pick(&BVARS[3..]);
                format!("{ind}{dst} := {f}(a := {a}, b := {b}, flag => {flag});\n")
            }
        } else {
            let inst = self.rng.below(self.blocks);
            let go = self.bool_expr(2);
            let step = self.int_expr(2);
            let total = *self.rng.pick(DVARS);
            let q = *self.rng.pick(&BVARS[3..]);
            if self.rng.chance(50) {
                format!("{ind}fb{inst}(go := {go}, inc := LIMIT(-1000, {}, 1000), total := {total}, q => {q});\n", step.0)
            } else {
                format!("{ind}fb{inst}(inc := LIMIT(0, {}, 500), go := {go}, total := {total});\n{ind}{q} := fb{inst}.q;\n{ind}{dst} := fb{inst}.acc;\n", step.0)
            }
        }
    }

    /// Strings keep 4..=12 characters: every assignment's result length is within that whatever the
    /// old length (4..=12) was.
    fn string_stmt(&mut self) -> String {
        let ind = self.ind();
        let lit = *self.rng.pick(&["'ab'", "'xyz'", "'Q'", "'st'", "''"]);
        let l = self.rng.range(1, 4);
        match self.rng.below(5) {
            // 4..=8 + 0..=3 chars
            0 => format!("{ind}txt := CONCAT(LEFT(txt, {l}), {lit}, RIGHT(txt, 3));\n"),
            1 => {
                let p = self.rng.range(1, 4 - l + 1);
                format!("{ind}txt := CONCAT(MID(txt, {l}, {p}), 'abc', {lit});\n")
            }
            2 => {
                let part = *self.rng.pick(&["'d'", "'xy'", "'b'", "'z'"]); // no overlap (KNOWN find_overlap)
                format!("{ind}tlen := LEN(txt);\n{ind}tpos := FIND(txt, {part});\n")
            }
            3 => {
                let b = self.bool_expr(2);
                format!(
                    "{ind}IF {b} AND txt <> 'ladder' THEN\n{ind}  txt := 'ladder';\n{ind}END_IF;\n"
                )
            }
            _ => format!(
                "{ind}{} := txt > {lit} OR LEN(txt) >= 8;\n",
                self.rng.pick(&BVARS[3..])
            ),
        }
    }

    fn bits_stmt(&mut self) -> String {
        let ind = self.ind();
        let n = self.rng.range(0, 15);
        let e = self.int_expr(2);
        let op = *self.rng.pick(&["SHL", "SHR", "ROL", "ROR"]);
        let logic = *self.rng.pick(&["AND", "OR", "XOR"]);
        let lit = *self.rng.pick(&["16#0F0F", "2#1010", "WORD#255", "8#777"]);
        format!(
            "{ind}w0 := {op}(w0, {n}) {logic} DINT_TO_WORD(LIMIT(0, {}, 65535)) OR {lit};\n{ind}IF w0 = 0 THEN\n{ind}  w0 := NOT w0;\n{ind}END_IF;\n",
            e.0
        )
    }

    /// an index within lo..=hi: a literal, `i` where in range, or a MOD of the scan count
    fn index(&mut self, lo: i64, hi: i64) -> String {
        if self.rng.chance(40) {
            self.rng.range(lo, hi).to_string()
        } else {
            format!("{lo} + tick MOD {}", hi - lo + 1)
        }
    }

    /// leaves of an integer expression in the program: text and interval
    fn int_leaf(&mut self) -> (String, i64, i64) {
        match self.rng.below(14) {
            0..=3 => ((*self.rng.pick(DVARS)).to_string(), -1000, 1000),
            12 => ("UDINT_TO_DINT(mx0.cnt)".into(), 0, 999),
            13 => {
                let (t, lo, hi) = self.conversion(Ty::Dint);
                (t, lo as i64, hi as i64)
            }
            4 => (
                format!("INT_TO_DINT({})", self.rng.pick(NVARS)),
                -1000,
                1000,
            ),
            5 => ("tick".into(), 0, 100),
            6 => {
                let v = self.rng.range(-20, 20);
                if v < 0 {
                    (format!("({v})"), v, v)
                } else if self.rng.chance(30) {
                    (format!("DINT#{v}"), v, v)
                } else {
                    (v.to_string(), v, v)
                }
            }
            7 => {
                let idx = self.index(0, 7);
                (format!("arr[{idx}]"), -1000, 1000)
            }
            8 => {
                let idx = self.index(1, 3);
                (format!("pts[{idx}].x"), -1000, 1000)
            }
            9 => {
                let c = *self
                    .rng
                    .pick(&["ctu0.CV", "ctd0.CV", "ctud0.CV", "lvl", "tlen", "tpos"]);
                (format!("INT_TO_DINT({c})"), 0, 20)
            }
            10 => ("UINT_TO_DINT(u0)".into(), 0, 1000),
            _ => ("REAL_TO_DINT(r0)".into(), -1000, 1000),
        }
    }

    fn int_expr(&mut self, depth: usize) -> (String, i64, i64) {
        self.int_expr_in(depth, None)
    }

    fn int_expr_over(&mut self, leaves: &[&str], depth: usize) -> (String, i64, i64) {
        self.int_expr_in(depth, Some(leaves))
    }

    fn int_expr_in(&mut self, depth: usize, leaves: Option<&[&str]>) -> (String, i64, i64) {
        let leaf = |g: &mut Gen| match leaves {
            Some(l) if g.rng.chance(80) => ((*g.rng.pick(l)).to_string(), -1000, 1000),
            Some(_) => {
                let v = g.rng.range(1, 9);
                (v.to_string(), v, v)
            }
            None => g.int_leaf(),
        };
        if depth == 0 || self.rng.chance(25) {
            return leaf(self);
        }
        let a = self.int_expr_in(depth - 1, leaves);
        let r = match self.rng.below(12) {
            0..=2 => {
                let b = self.int_expr_in(depth - 1, leaves);
                let op = *self.rng.pick(&["+", "-"]);
                let (lo, hi) = if op == "+" {
                    (a.1 + b.1, a.2 + b.2)
                } else {
                    (a.1 - b.2, a.2 - b.1)
                };
                (format!("{} {op} {}", a.0, paren(&b.0)), lo, hi)
            }
            3 | 4 => {
                let b = self.int_expr_in(depth - 1, leaves);
                let c = [a.1 * b.1, a.1 * b.2, a.2 * b.1, a.2 * b.2];
                (
                    format!("{} * {}", paren(&a.0), paren(&b.0)),
                    *c.iter().min().unwrap(),
                    *c.iter().max().unwrap(),
                )
            }
            5 => {
                let d = *self.rng.pick(&[2i64, 3, 7, -4, 10]);
                let lit = if d < 0 {
                    format!("({d})")
                } else {
                    d.to_string()
                };
                let (x, y) = (a.1 / d, a.2 / d);
                (format!("{} / {lit}", paren(&a.0)), x.min(y), x.max(y))
            }
            6 => {
                let m = self.rng.range(2, 50);
                (format!("{} MOD {m}", paren(&a.0)), -(m - 1), m - 1)
            }
            7 => (format!("ABS({})", a.0), 0, a.1.abs().max(a.2.abs())),
            8 => {
                let b = self.int_expr_in(depth - 1, leaves);
                let c = self.int_expr_in(0, leaves);
                let f = *self.rng.pick(&["MAX", "MIN"]);
                (
                    format!("{f}({}, {}, {})", a.0, b.0, c.0),
                    a.1.min(b.1).min(c.1),
                    a.2.max(b.2).max(c.2),
                )
            }
            9 => {
                let b = self.int_expr_in(depth - 1, leaves);
                if leaves.is_some() {
                    (
                        format!("SEL(a > b, {}, {})", a.0, b.0),
                        a.1.min(b.1),
                        a.2.max(b.2),
                    )
                } else {
                    let c = self.bool_expr(1);
                    (
                        format!("SEL({c}, {}, {})", a.0, b.0),
                        a.1.min(b.1),
                        a.2.max(b.2),
                    )
                }
            }
            10 if leaves.is_none() => {
                let b = self.int_expr_in(depth - 1, leaves);
                let c = self.int_expr_in(depth - 1, leaves);
                (
                    format!("MUX(tick MOD 3, {}, {}, {})", a.0, b.0, c.0),
                    a.1.min(b.1).min(c.1),
                    a.2.max(b.2).max(c.2),
                )
            }
            10 => (format!("-{}", paren(&a.0)), -a.2, -a.1),
            _ => {
                let b = self.int_expr_in(0, leaves);
                let c = self.int_expr_in(0, leaves);
                (
                    format!("ADD({}, {}, {})", a.0, b.0, c.0),
                    a.1 + b.1 + c.1,
                    a.2 + b.2 + c.2,
                )
            }
        };
        if r.1 < -SAFE || r.2 > SAFE {
            a
        } else {
            r
        }
    }

    fn cmp_over(&mut self, leaves: &[&str]) -> String {
        let a = self.int_expr_over(leaves, 1);
        let b = self.int_expr_over(leaves, 1);
        let op = *self.rng.pick(&["<", "<=", "=", "<>", ">", ">="]);
        format!("{} {op} {}", a.0, b.0)
    }

    fn bool_expr(&mut self, depth: usize) -> String {
        if depth == 0 || self.rng.chance(20) {
            return match self.rng.below(9) {
                0..=3 => (*self.rng.pick(BVARS)).to_string(),
                4 => self
                    .rng
                    .pick(&[
                        "ton0.Q", "tof0.Q", "tp0.Q", "rt0.Q", "ft0.Q", "sr0.Q1", "rs0.Q1",
                        "ctu0.Q", "ctd0.Q", "mx0.q", "fb0.q",
                    ])
                    .to_string(),
                5 => format!("col = {}", self.rng.pick(COLORS)),
                6 => format!("pts[{}].lit", self.rng.range(1, 3)),
                7 => format!("t0 >= T#{}ms", self.rng.range(0, 5) * 10),
                _ => (*self.rng.pick(&["TRUE", "FALSE", "BOOL#1"])).to_string(),
            };
        }
        match self.rng.below(9) {
            0..=2 => {
                let a = self.int_expr(1);
                let b = self.int_expr(1);
                let op = *self.rng.pick(&["<", "<=", "=", "<>", ">", ">="]);
                format!("{} {op} {}", a.0, b.0)
            }
            3 => {
                let a = self.real_expr(1);
                let op = *self.rng.pick(&["<", ">"]);
                format!("{} {op} {}", a.0, self.rng.pick(RVARS))
            }
            4 => format!("NOT {}", bparen(&self.bool_expr(depth - 1))),
            _ => {
                let a = self.bool_expr(depth - 1);
                let b = self.bool_expr(depth - 1);
                let op = *self.rng.pick(&["AND", "OR", "XOR", "&"]);
                if self.rng.chance(50) {
                    format!("({a}) {op} ({b})")
                } else {
                    format!("{} {op} {}", bparen(&a), bparen(&b))
                }
            }
        }
    }

    /// a REAL expression and its interval (values are exact small multiples of 1/4 where possible)
    fn real_expr(&mut self, depth: usize) -> (String, f64, f64) {
        if depth == 0 || self.rng.chance(25) {
            return match self.rng.below(5) {
                0 | 1 => ((*self.rng.pick(RVARS)).to_string(), -1000.0, 1000.0),
                2 => {
                    let v = *self.rng.pick(&["0.5", "2.0", "1.25", "REAL#4.0", "-3.5"]);
                    let x: f64 = v.trim_start_matches("REAL#").parse().unwrap();
                    (
                        if x < 0.0 {
                            format!("({v})")
                        } else {
                            v.to_string()
                        },
                        x,
                        x,
                    )
                }
                _ => {
                    let e = self.int_expr(1);
                    (format!("DINT_TO_REAL({})", e.0), e.1 as f64, e.2 as f64)
                }
            };
        }
        let a = self.real_expr(depth - 1);
        let r = match self.rng.below(4) {
            0 | 1 => {
                let b = self.real_expr(depth - 1);
                let op = *self.rng.pick(&["+", "-"]);
                let (lo, hi) = if op == "+" {
                    (a.1 + b.1, a.2 + b.2)
                } else {
                    (a.1 - b.2, a.2 - b.1)
                };
                (format!("{} {op} {}", a.0, paren(&b.0)), lo, hi)
            }
            2 => {
                let k = *self.rng.pick(&[0.5, 0.25, 2.0]);
                (format!("{} * {k:?}", paren(&a.0)), a.1 * k, a.2 * k)
            }
            _ => (format!("ABS({})", a.0), 0.0, a.1.abs().max(a.2.abs())),
        };
        if r.1 < -1.0e7 || r.2 > 1.0e7 {
            a
        } else {
            r
        }
    }
}

/// The elementary types of the typed statements (the DINT world above keeps its own intervals).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Ty {
    Usint,
    Uint,
    Udint,
    Ulint,
    Int,
    Dint,
    Lint,
    Byte,
    Word,
    Dword,
    Lword,
    Real,
    Lreal,
}

/// The program's variables of the typed statements: name and type (each keeps [`Ty::keep`]).
const TYPED: &[(&str, Ty)] = &[
    ("us0", Ty::Usint),
    ("u0", Ty::Uint),
    ("ud0", Ty::Udint),
    ("ul0", Ty::Ulint),
    ("n0", Ty::Int),
    ("n1", Ty::Int),
    ("d0", Ty::Dint),
    ("d1", Ty::Dint),
    ("li0", Ty::Lint),
    ("li1", Ty::Lint),
    ("by0", Ty::Byte),
    ("w0", Ty::Word),
    ("dw0", Ty::Dword),
    ("lw0", Ty::Lword),
    ("r0", Ty::Real),
    ("lr0", Ty::Lreal),
    ("lr1", Ty::Lreal),
];

/// Durations (ms) whose literal matiec holds exactly (`KNOWN` time_literals: T#1ms is 1 ns short).
const EXACT_MS: &[i64] = &[3, 5, 6, 7, 10, 15, 20, 25, 30, 40, 50, 60, 100, 120];

impl Ty {
    fn name(self) -> &'static str {
        match self {
            Ty::Usint => "USINT",
            Ty::Uint => "UINT",
            Ty::Udint => "UDINT",
            Ty::Ulint => "ULINT",
            Ty::Int => "INT",
            Ty::Dint => "DINT",
            Ty::Lint => "LINT",
            Ty::Byte => "BYTE",
            Ty::Word => "WORD",
            Ty::Dword => "DWORD",
            Ty::Lword => "LWORD",
            Ty::Real => "REAL",
            Ty::Lreal => "LREAL",
        }
    }
    fn is_bits(self) -> bool {
        matches!(self, Ty::Byte | Ty::Word | Ty::Dword | Ty::Lword)
    }
    fn is_real(self) -> bool {
        matches!(self, Ty::Real | Ty::Lreal)
    }
    fn width(self) -> u32 {
        match self {
            Ty::Usint | Ty::Byte => 8,
            Ty::Uint | Ty::Int | Ty::Word => 16,
            Ty::Udint | Ty::Dint | Ty::Dword | Ty::Real => 32,
            _ => 64,
        }
    }
    /// the values the type holds (bit strings as unsigned; reals where every integer is exact)
    fn bounds(self) -> (i128, i128) {
        match self {
            Ty::Int => (-32768, 32767),
            Ty::Dint => (-(1 << 31), (1 << 31) - 1),
            Ty::Lint => (-(1 << 63), (1 << 63) - 1),
            Ty::Real | Ty::Lreal => (-10_000_000, 10_000_000),
            _ => (0, (1i128 << self.width()) - 1),
        }
    }
    /// the range a variable of the type keeps
    fn keep(self) -> (i128, i128) {
        match self {
            Ty::Usint => (0, 200),
            Ty::Uint => (0, 1000),
            Ty::Udint => (0, 100_000),
            Ty::Ulint => (0, 10_000_000),
            Ty::Int | Ty::Dint | Ty::Real | Ty::Lreal => (-1000, 1000),
            Ty::Lint => (-10_000_000, 10_000_000),
            _ => self.bounds(),
        }
    }
    fn wide(self) -> bool {
        self.width() == 64
    }
}

/// a typed expression: text and interval (bit strings: the full range of their width)
type TExpr = (String, i128, i128);

impl Gen {
    /// One statement of the typed world: arithmetic, bit operations and conversions between USINT ..
    /// LWORD and LREAL, 2-D arrays and arrays with non-zero lower bounds, whole-structure assignment,
    /// STRING INSERT/DELETE/REPLACE and comparison, TIME arithmetic, the in-out block `mix_fb` called
    /// formally and informally, the two-output function `sumto`, nested FOR with EXIT.
    fn typed_stmt(&mut self) -> String {
        let ind = self.ind();
        match self.rng.below(14) {
            0..=3 => {
                let (v, ty) = *self.rng.pick(TYPED);
                self.store(&ind, v, ty)
            }
            4 => {
                let ty = *self.rng.pick(&[Ty::Int, Ty::Udint]);
                let e = self.texpr(ty, 2);
                let (lo, hi) = ty.keep();
                let target = if ty == Ty::Int {
                    format!("m2[{}, {}]", self.index(-2, 1), self.index(1, 3))
                } else {
                    format!("lb[{}]", self.index(-3, 2))
                };
                format!(
                    "{ind}{target} := LIMIT({}, {}, {});\n",
                    self.lit(ty, lo),
                    e.0,
                    self.lit(ty, hi)
                )
            }
            5 => {
                let (_, ty) = *self.rng.pick(TYPED);
                let d = if ty == Ty::Real { 0 } else { 1 };
                let a = self.texpr(ty, d);
                let b = self.texpr(ty, d);
                let op = if ty.is_bits() {
                    *self.rng.pick(&["=", "<>"])
                } else {
                    *self.rng.pick(&["<", "<=", "=", "<>", ">", ">="])
                };
                let dst = *self.rng.pick(&BVARS[3..]);
                format!("{ind}{dst} := {} {op} {};\n", paren(&a.0), paren(&b.0))
            }
            6 => {
                let a = self.index(1, 3);
                let b = self.index(1, 3);
                match self.rng.below(3) {
                    0 => format!("{ind}pts[{a}] := pts[{b}];\n"),
                    1 => format!("{ind}p0 := pts[{a}];\n"),
                    _ => format!(
                        "{ind}p0.x := LIMIT(-1000, p0.x + tick, 1000);\n{ind}pts[{a}] := p0;\n"
                    ),
                }
            }
            7 => self.string_edit(),
            8 => self.time_stmt(),
            9 | 10 => self.mix_call(),
            11 => {
                let dst = *self.rng.pick(DVARS);
                let lim = self.int_expr(2);
                let step = self.int_expr(1);
                let over = *self.rng.pick(&BVARS[3..]);
                format!(
                    "{ind}{dst} := sumto(lim := LIMIT(-1000, {}, 1000), delta := LIMIT(-1000, {}, 1000), count => d3, over => {over});\n{ind}{dst} := LIMIT(-1000, {dst}, 1000);\n",
                    lim.0, step.0
                )
            }
            12 if self.loops == 0 && self.depth < 3 => self.nested_for(),
            _ => {
                let ty = *self.rng.pick(&[Ty::Byte, Ty::Word, Ty::Dword, Ty::Lword]);
                let v = TYPED.iter().find(|(_, t)| *t == ty).unwrap().0;
                self.store(&ind, v, ty)
            }
        }
    }

    /// `v := e` brought back into `ty`'s kept range
    fn store(&mut self, ind: &str, v: &str, ty: Ty) -> String {
        let e = self.texpr(ty, 3);
        if ty.is_bits() {
            return format!("{ind}{v} := {};\n", e.0);
        }
        let (lo, hi) = ty.keep();
        if e.1 >= lo && e.2 <= hi && self.rng.chance(50) {
            return format!("{ind}{v} := {};\n", e.0);
        }
        format!(
            "{ind}{v} := LIMIT({}, {}, {});\n",
            self.lit(ty, lo),
            e.0,
            self.lit(ty, hi)
        )
    }

    /// a literal of `ty` (typed where an untyped one would meet a 64-bit operand, `KNOWN`
    /// lint_compare_literal)
    fn lit(&mut self, ty: Ty, v: i128) -> String {
        if ty.is_real() {
            let t = format!("{}.0", v.abs());
            let t = if ty.wide() || self.rng.chance(50) {
                format!("{}#{}{t}", ty.name(), if v < 0 { "-" } else { "" })
            } else if v < 0 {
                format!("-{t}")
            } else {
                t
            };
            return if v < 0 { format!("({t})") } else { t };
        }
        if ty.is_bits() {
            return format!("{}#16#{v:X}", ty.name());
        }
        let t = if ty.wide() || self.rng.chance(40) {
            format!("{}#{v}", ty.name())
        } else {
            v.to_string()
        };
        if v < 0 {
            format!("({t})")
        } else {
            t
        }
    }

    fn texpr(&mut self, ty: Ty, depth: usize) -> TExpr {
        // REAL one operation deep (`KNOWN` real_intermediate_precision)
        let depth = if ty == Ty::Real { depth.min(1) } else { depth };
        if ty.is_bits() {
            return self.bits_expr(ty, depth);
        }
        if depth == 0 || self.rng.chance(25) {
            return self.tleaf(ty);
        }
        let a = self.texpr(ty, depth - 1);
        let r = match self.rng.below(9) {
            0..=2 => {
                let b = self.texpr(ty, depth - 1);
                let op = *self.rng.pick(&["+", "-"]);
                let (lo, hi) = if op == "+" {
                    (a.1 + b.1, a.2 + b.2)
                } else {
                    (a.1 - b.2, a.2 - b.1)
                };
                (format!("{} {op} {}", a.0, paren(&b.0)), lo, hi)
            }
            3 => {
                let b = self.texpr(ty, depth - 1);
                let c = [
                    a.1.saturating_mul(b.1),
                    a.1.saturating_mul(b.2),
                    a.2.saturating_mul(b.1),
                    a.2.saturating_mul(b.2),
                ];
                let (lo, hi) = (*c.iter().min().unwrap(), *c.iter().max().unwrap());
                (format!("{} * {}", paren(&a.0), paren(&b.0)), lo, hi)
            }
            4 if ty.is_real() => {
                let k = *self.rng.pick(&["0.5", "0.25", "2.0", "4.0"]);
                (
                    format!("{} / {k}", paren(&a.0)),
                    a.1.min(a.1 * 4),
                    a.2.max(a.2 * 4),
                )
            }
            4 => {
                let d = self.rng.range(2, 9) as i128;
                let l = self.lit(ty, d);
                (format!("{} / {l}", paren(&a.0)), a.1 / d, a.2 / d)
            }
            5 if ty.is_real() => {
                let w = *self.rng.pick(&["lr0", "lr1"]);
                if ty == Ty::Real {
                    (
                        format!("SQRT(ABS({}))", self.rng.pick(&["r0", "r1"])),
                        0,
                        32,
                    )
                } else {
                    (format!("SQRT(ABS({w}))"), 0, 32)
                }
            }
            5 => {
                let m = self.rng.range(3, 60) as i128;
                let l = self.lit(ty, m);
                let lo = if a.1 < 0 { -(m - 1) } else { 0 };
                let hi = if a.2 > 0 { m - 1 } else { 0 };
                (format!("{} MOD {l}", paren(&a.0)), lo, hi)
            }
            6 if ty.bounds().0 < 0 => (format!("ABS({})", a.0), 0, a.1.abs().max(a.2.abs())),
            7 => {
                let b = self.texpr(ty, depth - 1);
                let f = *self.rng.pick(&["MAX", "MIN"]);
                (format!("{f}({}, {})", a.0, b.0), a.1.min(b.1), a.2.max(b.2))
            }
            _ => {
                let b = self.texpr(ty, depth - 1);
                let c = self.bool_expr(1);
                (
                    format!("SEL({c}, {}, {})", a.0, b.0),
                    a.1.min(b.1),
                    a.2.max(b.2),
                )
            }
        };
        let (lo, hi) = ty.bounds();
        if r.1 < lo || r.2 > hi {
            a
        } else {
            r
        }
    }

    /// a leaf of type `ty`: a variable, a literal, a conversion from another type
    fn tleaf(&mut self, ty: Ty) -> TExpr {
        let (klo, khi) = ty.keep();
        match self.rng.below(8) {
            0..=2 => {
                let own: Vec<&str> = TYPED
                    .iter()
                    .filter(|(_, t)| *t == ty)
                    .map(|(n, _)| *n)
                    .collect();
                ((*self.rng.pick(&own)).to_string(), klo, khi)
            }
            3 => {
                let v = if klo < 0 {
                    self.rng.range(-50, 50)
                } else {
                    self.rng.range(0, 50)
                } as i128;
                let quarter = ty.is_real() && self.rng.chance(50);
                if quarter {
                    let t = format!("{}.25", v.abs());
                    let t = if v < 0 { format!("(-{t})") } else { t };
                    return (t, v.min(0) - 1, v.max(0) + 1);
                }
                (self.lit(ty, v), v, v)
            }
            4 if ty == Ty::Int => {
                let i = self.index(-2, 1);
                let j = self.index(1, 3);
                (format!("m2[{i}, {j}]"), klo, khi)
            }
            4 if ty == Ty::Udint => (format!("lb[{}]", self.index(-3, 2)), klo, khi),
            4 if ty == Ty::Udint || ty == Ty::Uint => ("UDINT_TO_UINT(mx0.cnt)".into(), 0, 999),
            _ => self.conversion(ty),
        }
    }

    /// `SRC_TO_ty(...)` of another variable, its argument kept where `ty` holds it
    fn conversion(&mut self, ty: Ty) -> TExpr {
        let (src, sty) = *self.rng.pick(TYPED);
        let (blo, bhi) = ty.bounds();
        let (slo, shi) = sty.keep();
        if sty == ty {
            return (src.to_string(), slo, shi);
        }
        let f = format!("{}_TO_{}", sty.name(), ty.name());
        if sty.is_bits() {
            let w = sty.width();
            let mut k = w;
            while (1i128 << k) - 1 > bhi {
                k -= 1;
            }
            let m = (1i128 << k) - 1;
            if k == w {
                return (format!("{f}({src})"), 0, m);
            }
            return (format!("{f}({src} AND {})", self.lit(sty, m)), 0, m);
        }
        let (lo, hi) = (slo.max(blo), shi.min(bhi));
        if lo == slo && hi == shi {
            return (format!("{f}({src})"), lo, hi);
        }
        let (a, b) = (self.lit(sty, lo), self.lit(sty, hi));
        (format!("{f}(LIMIT({a}, {src}, {b}))"), lo, hi)
    }

    /// a bit-string expression of `ty`
    fn bits_expr(&mut self, ty: Ty, depth: usize) -> TExpr {
        let full = ty.bounds();
        if depth == 0 || self.rng.chance(25) {
            let t = match self.rng.below(5) {
                0 | 1 => TYPED.iter().find(|(_, t)| *t == ty).unwrap().0.to_string(),
                2 => {
                    let v = (self.rng.range(0, i64::MAX - 1) as i128) & full.1;
                    self.lit(ty, v)
                }
                _ => {
                    // from an unsigned integer that fits, or from another bit string (narrowing keeps
                    // the low bits)
                    let src: &[(&str, Ty)] = &[
                        ("us0", Ty::Usint),
                        ("u0", Ty::Uint),
                        ("ud0", Ty::Udint),
                        ("ul0", Ty::Ulint),
                        ("by0", Ty::Byte),
                        ("w0", Ty::Word),
                        ("dw0", Ty::Dword),
                        ("lw0", Ty::Lword),
                    ];
                    let (s, sty) = *self.rng.pick(src);
                    if sty == ty {
                        s.to_string()
                    } else if !sty.is_bits() && sty.keep().1 > full.1 {
                        format!(
                            "{}_TO_{}({s} MOD {})",
                            sty.name(),
                            ty.name(),
                            self.lit(sty, 200)
                        )
                    } else {
                        format!("{}_TO_{}({s})", sty.name(), ty.name())
                    }
                }
            };
            return (t, full.0, full.1);
        }
        let a = self.bits_expr(ty, depth - 1);
        let t = match self.rng.below(4) {
            0 | 1 => {
                let b = self.bits_expr(ty, depth - 1);
                let op = *self.rng.pick(&["AND", "OR", "XOR"]);
                format!("{} {op} {}", paren(&a.0), paren(&b.0))
            }
            2 => format!("NOT {}", paren(&a.0)),
            _ => {
                let f = *self.rng.pick(&["SHL", "SHR", "ROL", "ROR"]);
                let n = self.rng.range(0, ty.width() as i64 - 1);
                format!("{f}({}, {n})", a.0)
            }
        };
        (t, full.0, full.1)
    }

    /// INSERT, DELETE, REPLACE (IN2 as long as L, `KNOWN` strings_edges) and MID on `txt` (4..=12
    /// characters before and after) and `s2`, and their comparison
    fn string_edit(&mut self) -> String {
        let ind = self.ind();
        let lit = *self.rng.pick(&["'xy'", "'Q'", "'abc'", "''"]);
        match self.rng.below(5) {
            0 => {
                // LEFT(txt, 6) has 4..=6 characters
                let p = self.rng.range(0, 4);
                format!("{ind}txt := INSERT(LEFT(txt, 6), {lit}, {p});\n")
            }
            1 => {
                // 6..=10 characters, less 1..=2
                let p = self.rng.range(1, 4);
                let l = self.rng.range(1, 2);
                format!("{ind}txt := DELETE(CONCAT(LEFT(txt, 8), 'zz'), {l}, {p});\n")
            }
            2 => {
                let (rep, l) = *self.rng.pick(&[("'R'", 1), ("'RS'", 2), ("'RST'", 3)]);
                let p = self.rng.range(1, 4 - l + 1);
                format!("{ind}txt := REPLACE(txt, {rep}, {l}, {p});\n")
            }
            3 => {
                let l = self.rng.range(1, 4);
                let p = self.rng.range(1, 4 - l + 1);
                let b = self.bool_expr(1);
                format!("{ind}IF {b} THEN\n{ind}  s2 := MID(txt, {l}, {p});\n{ind}ELSE\n{ind}  s2 := CONCAT(s2, {lit});\n{ind}  s2 := RIGHT(s2, 5);\n{ind}END_IF;\n")
            }
            _ => {
                let op = *self.rng.pick(&["<", "<=", "=", "<>", ">", ">="]);
                let dst = *self.rng.pick(&BVARS[3..]);
                if self.rng.chance(50) {
                    format!("{ind}{dst} := txt {op} s2;\n")
                } else {
                    format!("{ind}{dst} := s2 {op} {lit};\n")
                }
            }
        }
    }

    /// TIME + TIME, TIME - TIME, TIME * INT and TIME / INT on durations below 1 s held in whole ms
    /// (matiec's __time_mul/__time_div go through a double: exact there only so), t2 made from t0
    /// (0..=60 ms) and t1 (5..=65 ms) only, so it stays within -0.2 s .. 0.9 s
    fn time_stmt(&mut self) -> String {
        let ind = self.ind();
        let a = *self.rng.pick(&["t0", "t1"]);
        let b = *self.rng.pick(&["t0", "t1"]);
        let ms = *self.rng.pick(EXACT_MS);
        let k = self.rng.range(1, 5);
        match self.rng.below(5) {
            0 => format!("{ind}t2 := {a} * {k} + {b};\n"),
            1 => format!("{ind}t2 := {a} - {b} * {k} + T#{ms}ms;\n"),
            2 => {
                let d = *self.rng.pick(&[2, 4, 5, 8, 10]);
                format!("{ind}t2 := ({a} + {b} + T#{ms}ms) / {d};\n")
            }
            3 => {
                let n = *self.rng.pick(NVARS);
                format!("{ind}t2 := {a} * INT_TO_DINT({n} MOD 4) + T#{ms}ms;\n")
            }
            _ => {
                let dst = *self.rng.pick(&BVARS[3..]);
                let op = *self.rng.pick(&["<", ">=", "=", "<>"]);
                format!("{ind}{dst} := t2 {op} {a} + T#{ms}ms;\n")
            }
        }
    }

    /// `mix_fb` (inputs, then an in-out LINT, then outputs) called informally or formally with `=>`
    fn mix_call(&mut self) -> String {
        let ind = self.ind();
        let inst = *self.rng.pick(&["mx0", "mx1"]);
        let go = self.bool_expr(1);
        let k = self.texpr(Ty::Uint, 1);
        let k = format!("LIMIT(UINT#0, {}, UINT#1000)", k.0);
        let io = *self.rng.pick(&["li0", "li1"]);
        let q = *self.rng.pick(&BVARS[3..]);
        match self.rng.below(3) {
            0 => format!("{ind}{inst}({go}, {k}, {io});\n{ind}{q} := {inst}.q AND {inst}.cnt > 2;\n"),
            1 => format!("{ind}{inst}(en0 := {go}, k := {k}, io := {io}, q => {q}, cnt => ud0);\n"),
            _ => format!("{ind}{inst}(k := {k}, io := {io}, en0 := {go});\n{ind}d2 := LIMIT(-1000, UDINT_TO_DINT({inst}.cnt) + fb0.acc, 1000);\n"),
        }
    }

    /// a FOR over the 2-D array's rows with an inner FOR that may EXIT (only the inner loop)
    fn nested_for(&mut self) -> String {
        let ind = self.ind();
        let from = self.rng.range(0, 3);
        let to = from + self.rng.range(1, 4);
        let c = self.bool_expr(1);
        let e = self.int_expr(1);
        let body = self.loop_body(1);
        format!(
            "{ind}FOR i := {from} TO {to} DO\n{ind}  FOR i2 := -2 TO 1 DO\n{ind}    m2[i2, 1 + i MOD 3] := DINT_TO_INT(LIMIT(-1000, INT_TO_DINT(m2[i2, 1 + i MOD 3]) + ({}), 1000));\n{ind}    IF {c} THEN\n{ind}      EXIT;\n{ind}    END_IF;\n{ind}  END_FOR;\n{body}{ind}END_FOR;\n{ind}i := 0;\n{ind}i2 := 0;\n",
            e.0
        )
    }
}

/// `text` in parentheses unless it is a single name or literal
fn paren(text: &str) -> String {
    if text
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '#' | '[' | ']'))
    {
        text.to_string()
    } else {
        format!("({text})")
    }
}

fn bparen(text: &str) -> String {
    paren(text)
}

#[cfg(test)]
mod tests {
    use super::generate;

    #[test]
    fn the_same_seed_gives_the_same_program() {
        assert_eq!(generate(11), generate(11));
        assert_ne!(generate(11), generate(12));
        assert!(generate(3).starts_with("(* matiec-diff: cycles="));
    }

    /// Forty seeds use every construct of the typed statements at least once.
    #[test]
    fn the_typed_statements_cover_what_the_header_lists() {
        let all: String = (0..40).map(generate).collect();
        for needle in [
            "USINT_TO_",
            "UDINT_TO_",
            "ULINT_TO_",
            "LINT_TO_",
            "BYTE_TO_",
            "DWORD_TO_",
            "LWORD_TO_",
            "LREAL_TO_",
            "_TO_LREAL(",
            "LWORD#16#",
            "ROL(",
            "SQRT(ABS(lr",
            "m2[",
            "lb[",
            "p0 := pts[",
            "] := pts[",
            "INSERT(",
            "DELETE(",
            "REPLACE(",
            "s2 := MID(",
            " := txt ",
            "t2 := (t",
            ") / ",
            "mx0(en0 := ",
            "mx1(k := ",
            "sumto(lim := ",
            "FOR i2 := -2 TO 1 DO",
            "RETURN;",
        ] {
            assert!(all.contains(needle), "no `{needle}` in seeds 0..40");
        }
        // an informal call of the in-out block: three arguments, no `:=`
        assert!(all.lines().any(|l| {
            let l = l.trim();
            (l.starts_with("mx0(") || l.starts_with("mx1(")) && !l.contains(":=")
        }));
    }
}
