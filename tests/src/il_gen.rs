//! Seeded generator of random valid IEC 61131-3 IL projects, for the differential run against matiec.
//!
//! Input: a seed (`u64`). Output: the text of one `.il` file whose first line is
//! `(* matiec-diff: cycles=N seed=S *)`: a TYPE block (a structure), FUNCTIONs (VAR_INPUT, VAR_OUTPUT,
//! VAR), FUNCTION_BLOCKs (VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR with standard blocks), PROGRAMs and a
//! CONFIGURATION whose one task runs them every 10 ms. The bodies use the IL operators (LD/LDN, ST/STN,
//! S/R, AND/OR/XOR and their N and deferred `(` forms, ADD/SUB/MUL/DIV/MOD, the comparisons,
//! JMP/JMPC/JMPCN, RET/RETC, CAL/CALC/CALCN with formal and informal arguments, S1/R1/CLK/IN/PT on
//! instances), the standard blocks (TON, TOF, TP, CTU, CTD, CTUD, R_TRIG, F_TRIG, SR, RS) and
//! functions (conversions, SEL, MUX, MAX, MIN, LIMIT, ABS, SQRT, SHL/SHR/ROL/ROR, NOT, extensible
//! `ADD a, b` / `MUL a, b` / `AND a, b` ... with several inputs), loops made of a backward JMPC/JMPCN
//! counted by the program's `lc`, on BOOL, SINT,
//! INT, DINT, LINT, USINT, UINT, UDINT, BYTE, WORD, DWORD, REAL, LREAL, TIME, arrays and structures.
//! Every program counts its scans (`tick`) and derives its inputs from the count, so edges, timers and
//! counters fire.
//!
//! Invariants: the same seed gives the same text. Nothing is generated whose result the standard leaves
//! open or that the two compilers are known to settle differently (`KNOWN` of `matiec_diff.rs`): every
//! integer and real value is tracked as an interval, an operation that could leave its type is not
//! generated, every stored value is brought back into its variable's range (MOD, or MIN and MAX);
//! divisors are non-zero literals, shift counts are below the width, MUX selectors are within the
//! inputs, timers have a fixed PT > 0, counters are reset (loaded) before CV could pass PV (0), TIME
//! values are only stored and compared, REAL literals are exact in REAL, a jump goes forward except the
//! one closing a loop, which runs 1 to 4 passes of a counter (`lc`) nothing else writes; an extensible
//! call's extra inputs are typed (`KNOWN` lint_compare_literal) and not on REAL (`KNOWN`
//! real_intermediate_precision).

use std::fmt::Write as _;

/// splitmix64: small, seeded, the same everywhere.
pub struct Rng(u64);

impl Rng {
    /// A generator whose sequence is fixed by `seed`.
    pub fn new(seed: u64) -> Self {
        Rng(seed ^ 0x5DEE_CE66_D1CE_4E5B)
    }
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// 0..n (n > 0)
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    /// lo..=hi
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % ((hi - lo + 1) as u64)) as i64
    }
    /// true with `percent` % probability
    pub fn chance(&mut self, percent: usize) -> bool {
        self.below(100) < percent
    }
    pub fn pick<'a, T>(&mut self, s: &'a [T]) -> &'a T {
        &s[self.below(s.len())]
    }
}

/// The elementary types the generator uses.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Ty {
    Bool,
    Sint,
    Int,
    Dint,
    Lint,
    Usint,
    Uint,
    Udint,
    Byte,
    Word,
    Dword,
    Real,
    Lreal,
    Time,
}

use Ty::*;

const INTS: &[Ty] = &[Sint, Int, Dint, Lint, Usint, Uint, Udint];
const BITS: &[Ty] = &[Byte, Word, Dword];
const STORABLE: &[Ty] = &[
    Bool, Bool, Bool, Sint, Int, Int, Dint, Lint, Usint, Uint, Udint, Byte, Word, Dword, Real,
    Lreal,
];

impl Ty {
    fn name(self) -> &'static str {
        match self {
            Bool => "BOOL",
            Sint => "SINT",
            Int => "INT",
            Dint => "DINT",
            Lint => "LINT",
            Usint => "USINT",
            Uint => "UINT",
            Udint => "UDINT",
            Byte => "BYTE",
            Word => "WORD",
            Dword => "DWORD",
            Real => "REAL",
            Lreal => "LREAL",
            Time => "TIME",
        }
    }
    fn is_int(self) -> bool {
        INTS.contains(&self)
    }
    fn is_bits(self) -> bool {
        BITS.contains(&self)
    }
    fn is_real(self) -> bool {
        matches!(self, Real | Lreal)
    }
    fn signed(self) -> bool {
        matches!(self, Sint | Int | Dint | Lint | Real | Lreal)
    }
    fn width(self) -> u32 {
        match self {
            Bool => 1,
            Sint | Usint | Byte => 8,
            Int | Uint | Word => 16,
            Dint | Udint | Dword | Real => 32,
            Lint | Lreal | Time => 64,
        }
    }
    /// the values the type holds (reals: far inside, where every integer is exact)
    fn bounds(self) -> Iv {
        match self {
            Bool => Iv(0.0, 1.0),
            Sint => Iv(-128.0, 127.0),
            Int => Iv(-32768.0, 32767.0),
            Dint => Iv(-2147483648.0, 2147483647.0),
            Lint => Iv(-9.0e18, 9.0e18),
            Usint | Byte => Iv(0.0, 255.0),
            Uint | Word => Iv(0.0, 65535.0),
            Udint | Dword => Iv(0.0, 4294967295.0),
            Real | Lreal => Iv(-1.0e7, 1.0e7),
            Time => Iv(0.0, 0.0),
        }
    }
    /// the range every variable of the type keeps (a stored value is brought back into it)
    fn keep(self) -> Iv {
        match self {
            Sint => Iv(-100.0, 100.0),
            Int => Iv(-1000.0, 1000.0),
            Dint => Iv(-100000.0, 100000.0),
            Lint => Iv(-10000000.0, 10000000.0),
            Usint => Iv(0.0, 200.0),
            Uint => Iv(0.0, 1000.0),
            Udint => Iv(0.0, 100000.0),
            Real | Lreal => Iv(-1000.0, 1000.0),
            _ => self.bounds(),
        }
    }
}

/// A closed interval of values.
#[derive(Clone, Copy, Debug)]
struct Iv(f64, f64);

impl Iv {
    fn within(self, o: Iv) -> bool {
        self.0 >= o.0 && self.1 <= o.1
    }
    fn hull(a: f64, b: f64, c: f64, d: f64) -> Iv {
        Iv(a.min(b).min(c).min(d), a.max(b).max(c).max(d))
    }
}

/// Something an instruction can name: a variable, an element, a member, an FB output.
#[derive(Clone)]
struct Operand {
    text: String,
    ty: Ty,
    /// may be stored to
    writable: bool,
}

/// A standard FB instance of a POU and what the generator fixed for it.
#[derive(Clone)]
struct StdFb {
    name: String,
    kind: &'static str,
    /// PT (ms) of a timer, PV of a counter
    param: i64,
}

/// A user FUNCTION: its inputs, outputs, result.
#[derive(Clone)]
struct Func {
    name: String,
    inputs: Vec<(String, Ty)>,
    outputs: Vec<(String, Ty)>,
    result: Ty,
}

/// A user FUNCTION_BLOCK: inputs, in-outs, outputs.
#[derive(Clone)]
struct Block {
    name: String,
    inputs: Vec<(String, Ty)>,
    in_outs: Vec<(String, Ty)>,
    outputs: Vec<(String, Ty)>,
}

/// What a body can use.
#[derive(Default)]
struct Scope {
    operands: Vec<Operand>,
    std_fbs: Vec<StdFb>,
    /// user FB instances: (instance, block index)
    user_fbs: Vec<(String, usize)>,
    /// a FUNCTION (no RETC before its result is set, no FB calls)
    in_function: bool,
    /// FB or function: RET/RETC allowed
    may_return: bool,
    /// a PROGRAM, with the loop counter `lc` (DINT) that no other statement writes
    has_loop_counter: bool,
}

/// The generator's state for one project.
struct Gen {
    rng: Rng,
    funcs: Vec<Func>,
    blocks: Vec<Block>,
    labels: usize,
    /// inside the nested list of a deferred operator
    in_parens: bool,
    /// the structure type is declared (`rec_t`: a : INT; b : BOOL; c : REAL)
    has_struct: bool,
}

/// The IL project of `seed`.
pub fn generate(seed: u64) -> String {
    let mut g = Gen {
        rng: Rng::new(seed),
        funcs: Vec::new(),
        blocks: Vec::new(),
        labels: 0,
        in_parens: false,
        has_struct: false,
    };
    g.project(seed)
}

impl Gen {
    fn project(&mut self, seed: u64) -> String {
        let cycles = 40 + 10 * self.rng.below(7);
        let mut out = format!(
            "(* matiec-diff: cycles={cycles} seed={seed}. Generated by ladderc-tests' il_gen (random valid IL). *)\n"
        );
        self.has_struct = self.rng.chance(50);
        if self.has_struct {
            out.push_str(
                "TYPE\n  rec_t : STRUCT\n    a : INT;\n    b : BOOL;\n    c : REAL;\n  END_STRUCT;\nEND_TYPE\n\n",
            );
        }
        for i in 0..self.rng.below(3) {
            out.push_str(&self.function(i));
        }
        for i in 0..self.rng.below(3) {
            out.push_str(&self.block(i));
        }
        let programs = 1 + self.rng.below(2);
        for i in 0..programs {
            out.push_str(&self.program(i));
        }
        out.push_str("CONFIGURATION cfg\n  RESOURCE res ON PLC\n    TASK tsk (INTERVAL := T#10ms, PRIORITY := 0);\n");
        for i in 0..programs {
            let _ = writeln!(out, "    PROGRAM inst{i} WITH tsk : prog{i};");
        }
        out.push_str("  END_RESOURCE\nEND_CONFIGURATION\n");
        out
    }

    fn storable(&mut self) -> Ty {
        *self.rng.pick(STORABLE)
    }

    /// `name : TYPE := init;` with an initial value within the type's range, sometimes
    fn decl(&mut self, name: &str, ty: Ty) -> String {
        if self.rng.chance(30) && ty != Time {
            let v = self.literal(ty);
            format!("    {name} : {} := {v};\n", ty.name())
        } else {
            format!("    {name} : {};\n", ty.name())
        }
    }

    /// a literal of `ty` within its kept range
    fn literal(&mut self, ty: Ty) -> String {
        self.literal_iv(ty).0
    }

    fn literal_iv(&mut self, ty: Ty) -> (String, Iv) {
        match ty {
            Bool => {
                let b = self.rng.chance(50);
                (
                    if b { "TRUE" } else { "FALSE" }.into(),
                    Iv(b as u8 as f64, b as u8 as f64),
                )
            }
            Real | Lreal => {
                let v = *self.rng.pick(&[
                    0.5, 0.25, 1.5, 2.0, 3.0, -1.25, 10.0, 0.125, 100.0, -4.0, 7.75,
                ]);
                (format!("{v:?}"), Iv(v, v))
            }
            Byte | Word | Dword => {
                let max = ty.bounds().1 as u64;
                let v = self.rng.next() & max;
                (format!("16#{v:X}"), Iv(v as f64, v as f64))
            }
            Time => {
                // 10..120 ms: matiec reads T#130ms as 129999999 ns (KNOWN: time_literals)
                let ms = 10 * self.rng.range(1, 12);
                (format!("T#{ms}ms"), Iv(0.0, 0.0))
            }
            _ => {
                let k = ty.keep();
                let small = self.rng.chance(70);
                let (lo, hi) = if small {
                    (k.0.max(-9.0) as i64, k.1.min(9.0) as i64)
                } else {
                    (k.0 as i64, k.1 as i64)
                };
                let v = self.rng.range(lo, hi);
                (format!("{v}"), Iv(v as f64, v as f64))
            }
        }
    }

    fn label(&mut self) -> String {
        self.labels += 1;
        format!("lbl{}", self.labels)
    }

    fn function(&mut self, i: usize) -> String {
        let name = format!("fn{i}");
        let result = *self
            .rng
            .pick(&[Int, Dint, Real, Bool, Word, Sint, Uint, Lreal]);
        let mut f = Func {
            name: name.clone(),
            inputs: Vec::new(),
            outputs: Vec::new(),
            result,
        };
        let mut text = format!("FUNCTION {name} : {}\n  VAR_INPUT\n", result.name());
        // the first input has the result's type, so an informal call `LD x` / `fnN y` types well
        // two inputs at least: with a one-input FUNCTION in the project matiec refuses every `S x`
        for k in 0..2 + self.rng.below(2) {
            let ty = if k == 0 { result } else { self.storable() };
            let n = format!("a{k}");
            text.push_str(&format!("    {n} : {};\n", ty.name()));
            f.inputs.push((n, ty));
        }
        text.push_str("  END_VAR\n");
        if self.rng.chance(35) {
            text.push_str("  VAR_OUTPUT\n");
            let ty = self.storable();
            text.push_str(&format!("    q0 : {};\n", ty.name()));
            text.push_str("  END_VAR\n");
            f.outputs.push(("q0".into(), ty));
        }
        let mut sc = Scope {
            in_function: true,
            may_return: true,
            ..Scope::default()
        };
        for (n, ty) in &f.inputs {
            sc.operands.push(Operand {
                text: n.clone(),
                ty: *ty,
                writable: false,
            });
        }
        text.push_str("  VAR\n");
        for k in 0..1 + self.rng.below(3) {
            let ty = self.storable();
            let n = format!("t{k}");
            text.push_str(&self.decl(&n, ty));
            sc.operands.push(Operand {
                text: n,
                ty,
                writable: true,
            });
        }
        text.push_str("  END_VAR\n");
        let mut body = String::new();
        // the result and the outputs are set first, so that every path returns them set
        let e = self.store(&sc, &name, result);
        body.push_str(&e);
        for (n, ty) in f.outputs.clone() {
            body.push_str(&self.store(&sc, &n, ty));
        }
        sc.operands.push(Operand {
            text: name.clone(),
            ty: result,
            writable: true,
        });
        for (n, ty) in &f.outputs {
            sc.operands.push(Operand {
                text: n.clone(),
                ty: *ty,
                writable: true,
            });
        }
        body.push_str(&self.statements(&sc, (2, 5), 0));
        text.push_str(&body);
        text.push_str("END_FUNCTION\n\n");
        self.funcs.push(f);
        text
    }

    /// VAR declarations of standard and user FB instances and of arrays/structures: their text, and
    /// the scope additions
    fn instances(&mut self, sc: &mut Scope, prefix: &str) -> String {
        let mut text = String::new();
        let kinds = [
            "TON", "TOF", "TP", "CTU", "CTD", "CTUD", "R_TRIG", "F_TRIG", "SR", "RS",
        ];
        for k in 0..self.rng.below(4) {
            let kind = *self.rng.pick(&kinds);
            let name = format!("{prefix}{}{k}", kind.to_ascii_lowercase().replace('_', ""));
            let param = match kind {
                "TON" | "TOF" | "TP" => 10 * self.rng.range(2, 12),
                "CTU" | "CTD" | "CTUD" => self.rng.range(2, 6),
                _ => 0,
            };
            let _ = writeln!(text, "    {name} : {kind};");
            if kind.starts_with("CT") {
                // the reset/load inputs, computed before each call
                let _ = writeln!(text, "    {name}_r : BOOL;\n    {name}_l : BOOL;");
            }
            let outs: &[(&str, Ty)] = match kind {
                "TON" | "TOF" | "TP" => &[("Q", Bool), ("ET", Time)],
                "CTU" | "CTD" => &[("Q", Bool), ("CV", Int)],
                "CTUD" => &[("QU", Bool), ("QD", Bool), ("CV", Int)],
                "R_TRIG" | "F_TRIG" => &[("Q", Bool)],
                _ => &[("Q1", Bool)],
            };
            for (o, ty) in outs {
                sc.operands.push(Operand {
                    text: format!("{name}.{o}"),
                    ty: *ty,
                    writable: false,
                });
            }
            sc.std_fbs.push(StdFb { name, kind, param });
        }
        let nblocks = self.blocks.len();
        if nblocks > 0 {
            for k in 0..self.rng.below(3) {
                let b = self.rng.below(nblocks);
                let name = format!("{prefix}u{k}");
                let _ = writeln!(text, "    {name} : {};", self.blocks[b].name);
                for (o, ty) in self.blocks[b].outputs.clone() {
                    sc.operands.push(Operand {
                        text: format!("{name}.{o}"),
                        ty,
                        writable: false,
                    });
                }
                sc.user_fbs.push((name, b));
            }
        }
        if self.rng.chance(40) {
            let ty = *self.rng.pick(&[Int, Dint, Bool, Real, Word, Usint]);
            let _ = writeln!(text, "    arr : ARRAY[0..3] OF {};", ty.name());
            for i in 0..4 {
                sc.operands.push(Operand {
                    text: format!("arr[{i}]"),
                    ty,
                    writable: true,
                });
            }
        }
        if self.has_struct && self.rng.chance(60) {
            let _ = writeln!(text, "    rec : rec_t;");
            for (f, ty) in [("a", Int), ("b", Bool), ("c", Real)] {
                sc.operands.push(Operand {
                    text: format!("rec.{f}"),
                    ty,
                    writable: true,
                });
            }
        }
        text
    }

    fn block(&mut self, i: usize) -> String {
        let name = format!("fb{i}");
        let mut b = Block {
            name: name.clone(),
            inputs: Vec::new(),
            in_outs: Vec::new(),
            outputs: Vec::new(),
        };
        let mut sc = Scope {
            may_return: true,
            ..Scope::default()
        };
        let mut text = format!("FUNCTION_BLOCK {name}\n  VAR_INPUT\n");
        for k in 0..1 + self.rng.below(3) {
            let ty = self.storable();
            let n = format!("i{k}");
            text.push_str(&self.decl(&n, ty));
            sc.operands.push(Operand {
                text: n.clone(),
                ty,
                writable: false,
            });
            b.inputs.push((n, ty));
        }
        text.push_str("  END_VAR\n  VAR_OUTPUT\n");
        for k in 0..1 + self.rng.below(3) {
            let ty = self.storable();
            let n = format!("o{k}");
            text.push_str(&self.decl(&n, ty));
            sc.operands.push(Operand {
                text: n.clone(),
                ty,
                writable: true,
            });
            b.outputs.push((n, ty));
        }
        text.push_str("  END_VAR\n");
        if self.rng.chance(40) {
            let ty = *self.rng.pick(&[Int, Dint, Bool, Real, Udint]);
            text.push_str(&format!(
                "  VAR_IN_OUT\n    io0 : {};\n  END_VAR\n",
                ty.name()
            ));
            sc.operands.push(Operand {
                text: "io0".into(),
                ty,
                writable: true,
            });
            b.in_outs.push(("io0".into(), ty));
        }
        text.push_str("  VAR\n");
        for k in 0..1 + self.rng.below(3) {
            let ty = self.storable();
            let n = format!("m{k}");
            text.push_str(&self.decl(&n, ty));
            sc.operands.push(Operand {
                text: n,
                ty,
                writable: true,
            });
        }
        text.push_str(&self.instances(&mut sc, ""));
        text.push_str("  END_VAR\n");
        text.push_str(&self.statements(&sc, (3, 6), 0));
        text.push_str("END_FUNCTION_BLOCK\n\n");
        self.blocks.push(b);
        text
    }

    fn program(&mut self, i: usize) -> String {
        let mut sc = Scope::default();
        let mut text = format!("PROGRAM prog{i}\n  VAR\n    tick : DINT;\n    lc : DINT;\n");
        sc.has_loop_counter = true;
        sc.operands.push(Operand {
            text: "tick".into(),
            ty: Dint,
            writable: false,
        });
        let mut drives = String::from("  LD tick\n  ADD 1\n  ST tick\n");
        // inputs that change with the scan count
        for k in 0..2 + self.rng.below(3) {
            let n = format!("x{k}");
            let _ = writeln!(text, "    {n} : BOOL;");
            let m = self.rng.range(2, 9);
            let t = self.rng.range(1, m - 1);
            let cmp = *self.rng.pick(&["LT", "GE", "EQ", "NE"]);
            let _ = write!(drives, "  LD tick\n  MOD {m}\n  {cmp} {t}\n  ST {n}\n");
            sc.operands.push(Operand {
                text: n,
                ty: Bool,
                writable: false,
            });
        }
        for k in 0..1 + self.rng.below(2) {
            let n = format!("n{k}");
            let ty = *self.rng.pick(&[Int, Dint, Sint, Uint]);
            let _ = writeln!(text, "    {n} : {};", ty.name());
            let m = self.rng.range(3, 40);
            let _ = write!(drives, "  LD tick\n  MOD {m}\n");
            if ty != Dint {
                let _ = writeln!(drives, "  DINT_TO_{}", ty.name());
            }
            let _ = writeln!(drives, "  ST {n}");
            sc.operands.push(Operand {
                text: n,
                ty,
                writable: false,
            });
        }
        for k in 0..3 + self.rng.below(6) {
            let ty = self.storable();
            let n = format!("v{k}");
            text.push_str(&self.decl(&n, ty));
            sc.operands.push(Operand {
                text: n,
                ty,
                writable: true,
            });
        }
        if self.rng.chance(50) {
            let _ = writeln!(text, "    tm : TIME;");
            sc.operands.push(Operand {
                text: "tm".into(),
                ty: Time,
                writable: true,
            });
        }
        text.push_str(&self.instances(&mut sc, ""));
        text.push_str("  END_VAR\n");
        text.push_str(&drives);
        text.push_str(&self.statements(&sc, (6, 10), 0));
        text.push_str("END_PROGRAM\n\n");
        text
    }

    /// `least` to `least + more - 1` statements; `depth` bounds the nesting of forward jumps
    fn statements(&mut self, sc: &Scope, (least, more): (usize, usize), depth: usize) -> String {
        let n = least + self.rng.below(more);
        let mut out = String::new();
        for _ in 0..n {
            out.push_str(&self.statement(sc, depth));
        }
        out
    }

    fn statement(&mut self, sc: &Scope, depth: usize) -> String {
        let can_call = !sc.in_function && (!sc.std_fbs.is_empty() || !sc.user_fbs.is_empty());
        loop {
            match self.rng.below(13) {
                0..=4 => {
                    let targets: Vec<Operand> =
                        sc.operands.iter().filter(|o| o.writable).cloned().collect();
                    if targets.is_empty() {
                        continue;
                    }
                    let t = self.rng.pick(&targets).clone();
                    return self.store(sc, &t.text, t.ty);
                }
                5 | 6 if can_call => {
                    return self.fb_call(sc);
                }
                7 if depth < 2 => {
                    // a forward jump around a few statements
                    let l = self.label();
                    let mut s = String::new();
                    let jmp = self.rng.below(5);
                    if jmp == 0 {
                        let _ = writeln!(s, "  JMP {l}");
                    } else {
                        s.push_str(&self.expr(sc, Bool).0);
                        let op = if jmp.is_multiple_of(2) {
                            "JMPC"
                        } else {
                            "JMPCN"
                        };
                        let _ = writeln!(s, "  {op} {l}");
                    }
                    s.push_str(&self.statements(sc, (1, 3), depth + 1));
                    let _ = writeln!(s, "{l}:");
                    return s;
                }
                11 if depth == 0 && sc.has_loop_counter => {
                    // a backward jump: a loop of 1 to 4 passes counted by `lc`
                    let l = self.label();
                    let n = self.rng.range(1, 4);
                    let mut s = format!("  LD 0\n  ST lc\n{l}:\n");
                    s.push_str(&self.statements(sc, (1, 2), depth + 1));
                    let (test, jump) = if self.rng.chance(50) {
                        ("LT", "JMPC")
                    } else {
                        ("GE", "JMPCN")
                    };
                    let _ = write!(s, "  LD lc\n  ADD 1\n  ST lc\n  {test} {n}\n  {jump} {l}\n");
                    return s;
                }
                8 if sc.may_return && self.rng.chance(30) => {
                    let mut s = self.expr(sc, Bool).0;
                    s.push_str("  RETC\n");
                    return s;
                }
                // matiec refuses many a valid `S x` / `R x` (x a BOOL variable) in a project with
                // user FUNCTIONs ("FB called by 'S' operator does not have a parameter named 'S'")
                9 if self.funcs.is_empty() && !sc.in_function => {
                    // a Boolean variable set or reset (not a function's result: matiec reads
                    // `R fnN` as a call of the function and refuses it)
                    let targets: Vec<Operand> = sc
                        .operands
                        .iter()
                        .filter(|o| o.writable && o.ty == Bool && !o.text.starts_with("fn"))
                        .cloned()
                        .collect();
                    if targets.is_empty() {
                        continue;
                    }
                    let t = self.rng.pick(&targets).clone();
                    let mut s = self.expr(sc, Bool).0;
                    let op = *self.rng.pick(&["S", "R", "STN"]);
                    let _ = writeln!(s, "  {op} {}", t.text);
                    return s;
                }
                10 => {
                    // a TIME stored from a timer or a literal
                    let times: Vec<&Operand> =
                        sc.operands.iter().filter(|o| o.ty == Time).collect();
                    let Some(t) = times.iter().find(|o| o.writable) else {
                        continue;
                    };
                    let src = self.rng.pick(&times).text.clone();
                    return format!("  LD {src}\n  ST {}\n", t.text);
                }
                _ => {}
            }
        }
    }

    /// instructions that leave a value of `ty` in the current result and store it into `target`
    fn store(&mut self, sc: &Scope, target: &str, ty: Ty) -> String {
        if ty == Time {
            let (l, _) = self.literal_iv(Time);
            return format!("  LD {l}\n  ST {target}\n");
        }
        let (mut s, iv) = self.expr(sc, ty);
        s.push_str(&self.bring_back(ty, iv));
        if ty.is_real() {
            // -0.0 + 0.0 is +0.0: the sign of a zero result (MIN of -0.0 and +0.0, ABS of -0.0) is
            // not fixed alike on both sides (KNOWN: abs_negative_zero)
            s.push_str("  ADD 0.0\n");
        }
        let _ = writeln!(s, "  ST {target}");
        s
    }

    /// instructions that bring a current result in `iv` back into `ty`'s kept range
    fn bring_back(&mut self, ty: Ty, iv: Iv) -> String {
        let k = ty.keep();
        if iv.within(k) {
            return String::new();
        }
        if ty.is_int() && self.rng.chance(60) {
            let m = k.1 as i64 + 1;
            return format!("  MOD {m}\n");
        }
        let (lo, hi) = if ty.is_real() {
            (format!("{:?}", k.0), format!("{:?}", k.1))
        } else if ty == Lint {
            (
                format!("LINT#{}", k.0 as i64),
                format!("LINT#{}", k.1 as i64),
            )
        } else {
            (format!("{}", k.0 as i64), format!("{}", k.1 as i64))
        };
        let mut s = String::new();
        if iv.1 > k.1 {
            let _ = writeln!(s, "  MIN {hi}");
        }
        if iv.0 < k.0 {
            let _ = writeln!(s, "  MAX {lo}");
        }
        s
    }

    /// an operand of `ty` (a variable, or a literal): its text and interval
    fn operand(&mut self, sc: &Scope, ty: Ty) -> (String, Iv) {
        let vars: Vec<&Operand> = sc.operands.iter().filter(|o| o.ty == ty).collect();
        if !vars.is_empty() && self.rng.chance(65) {
            let o = self.rng.pick(&vars);
            (o.text.clone(), ty.keep())
        } else if ty == Lint {
            // typed: matiec passes an untyped literal to its variadic LINT comparisons and MAX/MIN
            // as a C int (KNOWN: lint_compare_literal)
            let (l, iv) = self.literal_iv(ty);
            (format!("LINT#{l}"), iv)
        } else {
            self.literal_iv(ty)
        }
    }

    /// the nested list of a deferred operator `OP( ... )`: an operand and up to two operators (no
    /// function calls and no conversions: matiec finds no first input for them inside parentheses,
    /// which IEC 61131-3 allows); its text after the `(` and its interval
    fn nested(&mut self, sc: &Scope, ty: Ty) -> (String, Iv) {
        let (o, mut iv) = self.typed_operand(sc, ty);
        let mut s = format!("{o}\n");
        self.in_parens = true;
        for _ in 0..self.rng.below(3) {
            if let Some((t, niv)) = self.step(sc, ty, iv) {
                s.push_str(&t);
                iv = niv;
            }
        }
        self.in_parens = false;
        (s, iv)
    }

    /// an operand of `ty` whose literal says its type (`INT#5`): matiec types a function's inputs from
    /// its operands, not from where its result goes
    fn typed_operand(&mut self, sc: &Scope, ty: Ty) -> (String, Iv) {
        let (o, iv) = self.operand(sc, ty);
        let literal = o.starts_with(|c: char| c.is_ascii_digit() || c == '-');
        if literal && ty != Bool && ty != Time {
            return (format!("{}#{o}", ty.name()), iv);
        }
        (o, iv)
    }

    /// instructions whose current result is of `ty`, within `ty`'s bounds: text and interval
    fn expr(&mut self, sc: &Scope, ty: Ty) -> (String, Iv) {
        let (mut s, mut iv) = self.start(sc, ty);
        for _ in 0..self.rng.below(4) {
            if let Some((t, niv)) = self.step(sc, ty, iv) {
                s.push_str(&t);
                iv = niv;
            }
        }
        (s, iv)
    }

    /// the first instructions of an expression of `ty`
    fn start(&mut self, sc: &Scope, ty: Ty) -> (String, Iv) {
        for _ in 0..20 {
            match self.rng.below(10) {
                0..=3 => {
                    let vars: Vec<&Operand> = sc.operands.iter().filter(|o| o.ty == ty).collect();
                    if vars.is_empty() {
                        continue;
                    }
                    let o = self.rng.pick(&vars).text.clone();
                    if ty == Bool && self.rng.chance(30) {
                        return (format!("  LDN {o}\n"), ty.keep());
                    }
                    return (format!("  LD {o}\n"), ty.keep());
                }
                4 if ty == Bool => {
                    // a comparison
                    let cty = *self.rng.pick(&[
                        Int, Dint, Sint, Usint, Uint, Real, Lreal, Word, Byte, Lint, Udint, Time,
                        Dword,
                    ]);
                    if cty == Time {
                        let times: Vec<&Operand> =
                            sc.operands.iter().filter(|o| o.ty == Time).collect();
                        if times.is_empty() {
                            continue;
                        }
                        let a = self.rng.pick(&times).text.clone();
                        let (b, _) = self.literal_iv(Time);
                        let op = *self.rng.pick(&["GT", "GE", "EQ", "NE", "LE", "LT"]);
                        return (format!("  LD {a}\n  {op} {b}\n"), Iv(0.0, 1.0));
                    }
                    let (mut s, _) = self.expr(sc, cty);
                    let op = *self.rng.pick(&["GT", "GE", "EQ", "NE", "LE", "LT"]);
                    if self.rng.chance(25) {
                        let (inner, _) = self.nested(sc, cty);
                        let _ = writeln!(s, "  {op}( {inner}  )");
                        return (s, Iv(0.0, 1.0));
                    }
                    let (b, _) = self.operand(sc, cty);
                    let _ = writeln!(s, "  {op} {b}");
                    return (s, Iv(0.0, 1.0));
                }
                4 | 5 if ty != Bool && ty != Time => {
                    // a conversion from another type
                    let from = *self.rng.pick(&[
                        Sint, Int, Dint, Lint, Usint, Uint, Udint, Real, Lreal, Byte, Word, Dword,
                        Bool,
                    ]);
                    if from == ty {
                        continue;
                    }
                    let (mut s, fiv) = self.expr(sc, from);
                    let b = ty.bounds();
                    let iv = if from.is_real() {
                        // REAL to an integer rounds; only within the target's range
                        let r = Iv(fiv.0.round() - 1.0, fiv.1.round() + 1.0);
                        if ty.is_real() {
                            fiv
                        } else if r.within(b) {
                            r
                        } else {
                            continue;
                        }
                    } else if fiv.within(b) {
                        fiv
                    } else if ty.is_real() {
                        continue;
                    } else {
                        // an integer conversion out of range wraps (modulo 2^width) on both sides
                        b
                    };
                    let _ = writeln!(s, "  {}_TO_{}", from.name(), ty.name());
                    return (s, iv);
                }
                6 if ty != Bool && ty != Time => {
                    // SEL G, IN0, IN1 and MUX K, IN0, ...
                    let (a, aiv) = self.typed_operand(sc, ty);
                    let (b, biv) = self.typed_operand(sc, ty);
                    let iv = Iv::hull(aiv.0, aiv.1, biv.0, biv.1);
                    if self.rng.chance(50) {
                        let (g, _) = self.expr(sc, Bool);
                        return (format!("{g}  SEL {a}, {b}\n"), iv);
                    }
                    let (c, civ) = self.typed_operand(sc, ty);
                    let iv = Iv::hull(iv.0, iv.1, civ.0, civ.1);
                    let kty = *self.rng.pick(&[Usint, Uint, Udint, Int]);
                    let (mut k, kiv) = self.expr(sc, kty);
                    // a selector within the inputs: k MOD 3, made non-negative
                    k.push_str("  MOD 3\n");
                    if kiv.0 < 0.0 {
                        k.push_str("  ABS\n");
                    }
                    return (format!("{k}  MUX {a}, {b}, {c}\n"), iv);
                }
                7 if ty != Bool && ty != Time && !ty.is_bits() => {
                    // LIMIT with formal arguments, and MAX/MIN with several inputs
                    let (mut a, mut aiv) = self.typed_operand(sc, ty);
                    let (b, biv) = self.typed_operand(sc, ty);
                    let (mut c, mut civ) = self.typed_operand(sc, ty);
                    if self.rng.chance(50) {
                        if aiv.1 > civ.0 {
                            // MN <= MX: for MN > MX matiec's LIMIT is not the standard's
                            // (KNOWN: limit_mn_above_mx)
                            let k = ty.keep();
                            let lit = |v: f64| {
                                if ty.is_real() {
                                    format!("{}#{v:?}", ty.name())
                                } else {
                                    format!("{}#{}", ty.name(), v as i64)
                                }
                            };
                            (a, aiv) = (lit(k.0), Iv(k.0, k.0));
                            (c, civ) = (lit(k.1), Iv(k.1, k.1));
                        }
                        let iv = Iv(aiv.0.min(civ.0), civ.1.max(aiv.0));
                        return (
                            format!(
                                "  LIMIT(\n    MN := {a},\n    IN := {b},\n    MX := {c}\n  )\n"
                            ),
                            iv,
                        );
                    }
                    let f = *self.rng.pick(&["MAX", "MIN"]);
                    let iv = Iv::hull(aiv.0, aiv.1, biv.0, biv.1);
                    let iv = Iv(iv.0.min(civ.0), iv.1.max(civ.1));
                    return (format!("  LD {a}\n  {f} {b}, {c}\n"), iv);
                }
                8 => {
                    // a user function of this result type, informal or formal
                    let fs: Vec<Func> = self
                        .funcs
                        .iter()
                        .filter(|f| f.result == ty)
                        .cloned()
                        .collect();
                    if fs.is_empty() {
                        continue;
                    }
                    let f = self.rng.pick(&fs).clone();
                    let args: Vec<String> = f
                        .inputs
                        .iter()
                        .map(|(_, t)| self.typed_operand(sc, *t).0)
                        .collect();
                    let mut iv = ty.keep();
                    if ty.is_bits() || ty == Bool {
                        iv = ty.bounds();
                    }
                    if f.outputs.is_empty() && self.rng.chance(50) {
                        let mut s = format!("  LD {}\n  {}", args[0], f.name);
                        if args.len() > 1 {
                            let _ = write!(s, " {}", args[1..].join(", "));
                        }
                        s.push('\n');
                        return (s, iv);
                    }
                    let mut s = format!("  {}(\n", f.name);
                    let mut params: Vec<String> = f
                        .inputs
                        .iter()
                        .zip(&args)
                        .map(|((n, _), a)| format!("    {n} := {a}"))
                        .collect();
                    for (n, t) in &f.outputs {
                        // not an array element: matiec's C for `q0 => arr[2]` names a member
                        // `table2` that its array type lacks
                        let targets: Vec<&Operand> = sc
                            .operands
                            .iter()
                            .filter(|o| o.writable && o.ty == *t && !o.text.contains('['))
                            .collect();
                        if !targets.is_empty() {
                            let o = self.rng.pick(&targets).text.clone();
                            params.push(format!("    {n} => {o}"));
                        }
                    }
                    s.push_str(&params.join(",\n"));
                    s.push_str("\n  )\n");
                    return (s, iv);
                }
                _ => {
                    if ty == Time {
                        let times: Vec<&Operand> =
                            sc.operands.iter().filter(|o| o.ty == Time).collect();
                        if times.is_empty() {
                            return (format!("  LD {}\n", self.literal(Time)), Iv(0.0, 0.0));
                        }
                    }
                    if ty == Bool || ty == Time || self.rng.chance(50) {
                        continue;
                    }
                    let (l, iv) = self.literal_iv(ty);
                    return (format!("  LD {}#{l}\n", ty.name()), iv);
                }
            }
        }
        let (l, iv) = self.literal_iv(ty);
        if ty == Bool || ty == Time {
            return (format!("  LD {l}\n"), iv);
        }
        (format!("  LD {}#{l}\n", ty.name()), iv)
    }

    /// one operation on a current result of `ty` in `iv`: its text and the new interval, or None when
    /// the one chosen could leave the type
    fn step(&mut self, sc: &Scope, ty: Ty, iv: Iv) -> Option<(String, Iv)> {
        let b = ty.bounds();
        if ty == Bool {
            let op = *self
                .rng
                .pick(&["AND", "OR", "XOR", "ANDN", "ORN", "XORN", "NOT", "("]);
            if self.in_parens && matches!(op, "NOT" | "(") {
                return None;
            }
            return Some(match op {
                "NOT" => ("  NOT\n".into(), iv),
                "(" => {
                    let op = *self.rng.pick(&["AND", "OR", "XOR", "ANDN", "ORN"]);
                    let (inner, _) = self.nested(sc, Bool);
                    (format!("  {op}( {inner}  )\n"), Iv(0.0, 1.0))
                }
                _ => {
                    let (o, _) = self.operand(sc, Bool);
                    (format!("  {op} {o}\n"), Iv(0.0, 1.0))
                }
            });
        }
        if ty == Time {
            return None;
        }
        if ty.is_bits() {
            let w = ty.width() as i64;
            let k = if self.in_parens { 4 } else { self.rng.below(5) };
            return Some(match k {
                0 => ("  NOT\n".into(), b),
                1 => {
                    let f = *self.rng.pick(&["SHL", "SHR", "ROL", "ROR"]);
                    let n = self.rng.range(0, w - 1);
                    (format!("  {f} {n}\n"), b)
                }
                2 if !self.in_parens => {
                    // an extensible function with two more inputs
                    let op = *self.rng.pick(&["AND", "OR", "XOR"]);
                    let (o1, _) = self.typed_operand(sc, ty);
                    let (o2, _) = self.typed_operand(sc, ty);
                    (format!("  {op} {o1}, {o2}\n"), b)
                }
                _ => {
                    let op = *self.rng.pick(&["AND", "OR", "XOR", "ANDN", "ORN", "XORN"]);
                    let (o, _) = self.operand(sc, ty);
                    (format!("  {op} {o}\n"), b)
                }
            });
        }
        // numbers; inside parentheses no function (MAX, ABS ...): matiec finds no first input there
        let k = self.rng.below(9);
        if self.in_parens && matches!(k, 5..=7) {
            return None;
        }
        match k {
            0..=2 if !self.in_parens && ty != Real && self.rng.chance(25) => {
                // an extensible function with two more inputs (typed literals: an untyped one in a
                // variadic 64-bit call is `KNOWN` lint_compare_literal)
                let op = *self.rng.pick(&["ADD", "MUL"]);
                let (o1, iv1) = self.typed_operand(sc, ty);
                let (o2, iv2) = self.typed_operand(sc, ty);
                let r = arith(op, arith(op, iv, iv1), iv2);
                if !r.within(b) || !arith(op, iv, iv1).within(b) {
                    return None;
                }
                Some((format!("  {op} {o1}, {o2}\n"), r))
            }
            0..=2 => {
                let op = *self.rng.pick(&["ADD", "SUB", "MUL"]);
                let (o, oiv) = self.operand(sc, ty);
                let r = arith(op, iv, oiv);
                if !r.within(b) {
                    return None;
                }
                Some((format!("  {op} {o}\n"), r))
            }
            3 => {
                let d = if ty.is_real() {
                    *self.rng.pick(&[2.0, 4.0, 0.5, -2.0, 8.0])
                } else if ty.signed() {
                    *self.rng.pick(&[2.0, 3.0, 7.0, -2.0, 10.0, -5.0])
                } else {
                    *self.rng.pick(&[2.0, 3.0, 7.0, 10.0])
                };
                let r = if ty.is_real() {
                    Iv::hull(iv.0 / d, iv.1 / d, iv.0 / d, iv.1 / d)
                } else {
                    Iv::hull((iv.0 / d).trunc(), (iv.1 / d).trunc(), 0.0, 0.0)
                };
                let lit = if ty.is_real() {
                    format!("{d:?}")
                } else {
                    format!("{}", d as i64)
                };
                Some((format!("  DIV {lit}\n"), r))
            }
            4 if ty.is_int() => {
                let m = *self.rng.pick(&[2i64, 3, 5, 7, 10, 16, 100]);
                let mf = (m - 1) as f64;
                let r = Iv(
                    if iv.0 < 0.0 { iv.0.max(-mf) } else { 0.0 },
                    if iv.1 > 0.0 { iv.1.min(mf) } else { 0.0 },
                );
                Some((format!("  MOD {m}\n"), r))
            }
            5 => {
                let f = *self.rng.pick(&["MAX", "MIN"]);
                let (o, oiv) = self.operand(sc, ty);
                let r = if f == "MAX" {
                    Iv(iv.0.max(oiv.0), iv.1.max(oiv.1))
                } else {
                    Iv(iv.0.min(oiv.0), iv.1.min(oiv.1))
                };
                Some((format!("  {f} {o}\n"), r))
            }
            6 if ty.signed() => {
                let r = Iv(0.0, iv.0.abs().max(iv.1.abs()));
                if r.1 > b.1 {
                    return None;
                }
                if ty.is_real() {
                    // ABS(-0.0) is -0.0 in matiec (KNOWN: abs_negative_zero): adding 0.0 makes
                    // either +0.0
                    if self.rng.chance(50) {
                        return Some((
                            "  ABS\n  ADD 0.0\n  SQRT\n".into(),
                            Iv(0.0, r.1.sqrt() + 1.0),
                        ));
                    }
                    return Some(("  ABS\n  ADD 0.0\n".into(), r));
                }
                Some(("  ABS\n".into(), r))
            }
            7 => {
                // a deferred operation on a nested list
                let op = *self.rng.pick(&["ADD", "SUB", "MUL"]);
                let (inner, iiv) = self.nested(sc, ty);
                let r = arith(op, iv, iiv);
                if !r.within(b) {
                    return None;
                }
                Some((format!("  {op}( {inner}  )\n"), r))
            }
            _ => None,
        }
    }

    /// a call of an FB instance of the scope
    fn fb_call(&mut self, sc: &Scope) -> String {
        let std = !sc.std_fbs.is_empty() && (sc.user_fbs.is_empty() || self.rng.chance(60));
        if !std {
            let (inst, bi) = sc.user_fbs[self.rng.below(sc.user_fbs.len())].clone();
            let b = self.blocks[bi].clone();
            let mut s = String::new();
            let mut params = Vec::new();
            for (n, t) in &b.inputs {
                let (a, _) = self.operand(sc, *t);
                params.push(format!("{n} := {a}"));
            }
            for (n, t) in &b.in_outs {
                let vars: Vec<&Operand> = sc
                    .operands
                    .iter()
                    .filter(|o| o.writable && o.ty == *t && !o.text.contains(['[', '.']))
                    .collect();
                if vars.is_empty() {
                    // an in-out needs a variable; none of this type here: no call
                    return String::new();
                }
                let v = self.rng.pick(&vars).text.clone();
                params.push(format!("{n} := {v}"));
            }
            // an output is not assigned to a variable passed as in-out: matiec copies the in-out
            // back after the outputs (KNOWN: in_out_output_alias)
            let bound: Vec<String> = params[b.inputs.len()..]
                .iter()
                .filter_map(|p| p.split_once(" := ").map(|(_, v)| v.to_string()))
                .collect();
            for (n, t) in &b.outputs {
                let vars: Vec<&Operand> = sc
                    .operands
                    .iter()
                    .filter(|o| o.writable && o.ty == *t && !o.text.contains('['))
                    .filter(|o| !bound.contains(&o.text))
                    .collect();
                if !vars.is_empty() && self.rng.chance(50) {
                    let v = self.rng.pick(&vars).text.clone();
                    params.push(format!("{n} => {v}"));
                }
            }
            let op = self.cal_op(sc, &mut s);
            let _ = writeln!(s, "  {op} {inst}(\n    {}\n  )", params.join(",\n    "));
            return s;
        }
        let f = sc.std_fbs[self.rng.below(sc.std_fbs.len())].clone();
        let n = &f.name;
        let mut s = String::new();
        let b1 = self.operand(sc, Bool).0;
        let b2 = self.operand(sc, Bool).0;
        let operator_form = self.rng.chance(35);
        let params = match f.kind {
            "TON" | "TOF" | "TP" => {
                if operator_form {
                    let _ = write!(s, "  LD T#{}ms\n  PT {n}\n  LD {b1}\n  IN {n}\n", f.param);
                    return s;
                }
                if self.rng.chance(30) {
                    // informal: the inputs in their order
                    let op = self.cal_op(sc, &mut s);
                    let _ = writeln!(s, "  {op} {n}({b1}, T#{}ms)", f.param);
                    return s;
                }
                format!("IN := {b1},\n    PT := T#{}ms", f.param)
            }
            "R_TRIG" | "F_TRIG" => {
                if operator_form {
                    let _ = write!(s, "  LD {b1}\n  CLK {n}\n");
                    return s;
                }
                format!("CLK := {b1}")
            }
            "SR" | "RS" => {
                let (set, reset) = if f.kind == "SR" {
                    ("S1", "R")
                } else {
                    ("S", "R1")
                };
                if operator_form {
                    let _ = write!(s, "  LD {b1}\n  {set} {n}\n  LD {b2}\n  {reset} {n}\n");
                    return s;
                }
                format!("{b1}, {b2}")
            }
            // counters: reset (load) while CV is at PV (at 0), so CV stays within 0..PV, where the
            // standard's counters and matiec's (KNOWN: counter_limits) agree
            "CTU" => {
                let _ = write!(s, "  LD {n}.Q\n  ST {n}_r\n");
                format!("{b1}, {n}_r, {}", f.param)
            }
            "CTD" => {
                let _ = write!(s, "  LD {n}.CV\n  LE 0\n  ST {n}_l\n");
                format!("{b1}, {n}_l, {}", f.param)
            }
            _ => {
                let _ = write!(
                    s,
                    "  LD {n}.CV\n  GE {}\n  ST {n}_r\n  LD {n}.CV\n  LE 0\n  ST {n}_l\n",
                    f.param
                );
                format!("{b1}, {b2}, {n}_r, {n}_l, {}", f.param)
            }
        };
        let op = if f.kind.starts_with("CT") {
            "CAL"
        } else {
            self.cal_op(sc, &mut s)
        };
        if matches!(f.kind, "CTU" | "CTD" | "CTUD" | "SR" | "RS") {
            // informal, the inputs in their order: matiec reads no formal `R :=` or `LD :=` (the
            // names of IL operators) in a CAL, which IEC 61131-3 allows
            let _ = writeln!(s, "  {op} {n}({params})");
        } else {
            let _ = writeln!(s, "  {op} {n}(\n    {params}\n  )");
        }
        s
    }

    /// CAL, or CALC/CALCN after a Boolean expression appended to `s`
    fn cal_op(&mut self, sc: &Scope, s: &mut String) -> &'static str {
        match self.rng.below(4) {
            0 => {
                s.push_str(&self.expr(sc, Bool).0);
                "CALC"
            }
            1 => {
                s.push_str(&self.expr(sc, Bool).0);
                "CALCN"
            }
            _ => "CAL",
        }
    }
}

/// the interval of `a op b`
fn arith(op: &str, a: Iv, b: Iv) -> Iv {
    match op {
        "ADD" => Iv(a.0 + b.0, a.1 + b.1),
        "SUB" => Iv(a.0 - b.1, a.1 - b.0),
        _ => Iv::hull(a.0 * b.0, a.0 * b.1, a.1 * b.0, a.1 * b.1),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_seed_gives_the_same_program() {
        assert_eq!(generate(7), generate(7));
        assert_ne!(generate(7), generate(8));
        assert!(generate(7).starts_with("(* matiec-diff: cycles="));
    }

    /// Forty seeds have a loop closed by a backward conditional jump and extensible calls with
    /// several inputs, arithmetic and bitwise.
    #[test]
    fn loops_and_extensible_calls_are_generated() {
        let all: String = (0..40).map(generate).collect();
        assert!(all.contains("  ST lc\n"));
        let backward = all.lines().any(|l| {
            let l = l.trim();
            (l.starts_with("JMPC ") || l.starts_with("JMPCN "))
                && all.contains(&format!("  ST lc\n{}:", &l[l.find(' ').unwrap() + 1..]))
        });
        assert!(backward);
        for op in ["ADD", "MUL", "AND", "XOR"] {
            assert!(
                all.lines()
                    .any(|l| l.starts_with(&format!("  {op} ")) && l.contains(", ")),
                "no extensible {op}"
            );
        }
    }
}
