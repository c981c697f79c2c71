//! A generator of large, valid IL programs for performance tests and benchmarks.
//!
//! Input: the number of body lines per POU and the number of POUs. Output: IL source text with `pous`
//! `PROGRAM`s, each declaring its variables and having exactly `lines` body lines that mix boolean logic
//! (`LD`/`AND`/`ORN`/`ST`), arithmetic (`ADD`/`MUL`), comparisons with conditional jumps to labels
//! (`GT`/`JMPC`), multi-line `CAL` of `TON` instances and deferred `AND(`.
//! Invariants: deterministic (same arguments, same text); every name is declared; every jump has its
//! label in the same POU; the text parses without diagnostics.

use std::fmt::Write as _;

/// Deterministic pseudo-random numbers (a 64-bit LCG), so generated programs are reproducible.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self, n: u64) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 33) % n
    }
}

const BOOLS: u64 = 16;
const INTS: u64 = 8;
const TIMERS: u64 = 4;

/// `pous` programs `P0`, `P1`, ... of exactly `lines` body lines each.
pub fn generate(lines: usize, pous: usize) -> String {
    let mut out = String::with_capacity(lines * pous * 14 + pous * 400);
    let mut rng = Lcg(0x1131_2024);
    for p in 0..pous {
        let _ = writeln!(out, "PROGRAM P{p}");
        out.push_str("VAR\n");
        for i in 0..BOOLS {
            let _ = writeln!(out, "    b{i} : BOOL;");
        }
        for i in 0..INTS {
            let _ = writeln!(out, "    n{i} : INT := {i};");
        }
        for i in 0..TIMERS {
            let _ = writeln!(out, "    t{i} : TON;");
        }
        out.push_str("END_VAR\n");
        body(&mut out, lines, &mut rng);
        out.push_str("END_PROGRAM\n");
    }
    out
}

fn body(out: &mut String, lines: usize, rng: &mut Lcg) {
    let mut left = lines;
    let mut label = 0u64;
    while left > 0 {
        let b = |r: &mut Lcg| r.next(BOOLS);
        let n = |r: &mut Lcg| r.next(INTS);
        let pattern = if left >= 6 { rng.next(5) } else { 5 };
        match pattern {
            0 => {
                let _ = write!(
                    out,
                    "    LD b{}\n    AND b{}\n    ORN b{}\n    ST b{}\n",
                    b(rng),
                    b(rng),
                    b(rng),
                    b(rng)
                );
                left -= 4;
            }
            1 => {
                let _ = write!(
                    out,
                    "    LD n{}\n    ADD {}\n    MUL n{}\n    ST n{}\n",
                    n(rng),
                    rng.next(100),
                    n(rng),
                    n(rng)
                );
                left -= 4;
            }
            2 => {
                let _ = write!(
                    out,
                    "    LD n{}\n    GT {}\n    JMPC L{label}\n    LD b{}\n    ST b{}\nL{label}:\n",
                    n(rng),
                    rng.next(50),
                    b(rng),
                    b(rng)
                );
                label += 1;
                left -= 6;
            }
            3 => {
                let _ = write!(
                    out,
                    "    CAL t{}(\n        IN := b{},\n        PT := T#{}ms,\n        Q => b{}\n    )\n",
                    rng.next(TIMERS),
                    b(rng),
                    10 + rng.next(990),
                    b(rng)
                );
                left -= 5;
            }
            4 => {
                let _ = write!(
                    out,
                    "    LD b{}\n    AND( b{}\n        OR b{}\n    )\n    ST b{}\n",
                    b(rng),
                    b(rng),
                    b(rng),
                    b(rng)
                );
                left -= 5;
            }
            _ if left >= 2 => {
                let _ = write!(out, "    LD b{}\n    ST b{}\n", b(rng), b(rng));
                left -= 2;
            }
            _ => {
                out.push_str("    RET\n");
                left -= 1;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_line_count_and_deterministic() {
        let text = generate(100, 3);
        assert_eq!(text, generate(100, 3));
        // Each POU: header, VAR, 28 declarations, END_VAR, 100 body lines, END_PROGRAM.
        assert_eq!(text.lines().count(), 3 * (1 + 1 + 28 + 1 + 100 + 1));
        for lines in [0, 1, 2, 5, 7] {
            assert_eq!(
                generate(lines, 1).lines().count(),
                32 + lines,
                "{lines} lines"
            );
        }
        for kw in ["AND(", "JMPC L", "CAL t", "MUL n", "ORN b", "GT "] {
            assert!(text.contains(kw), "missing {kw}");
        }
    }
}
