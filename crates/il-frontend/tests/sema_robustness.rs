//! No panics on bad input: every body of a set of programs is mutated (instructions removed, operands
//! swapped for names of other kinds, conditions added) and analysed; sema must answer with diagnostics.

mod sema_support;
use sema_support::analyze_src;

const BASE: &str = "TYPE
  Color : (red, green);
END_TYPE
FUNCTION Twice : INT
VAR_INPUT
  v : INT;
END_VAR
  LD v
  MUL 2
  ST Twice
END_FUNCTION
PROGRAM Main
VAR
  a, b : BOOL;
  i, j : INT;
  r : REAL;
  t : TON;
  c : Color;
  arr : ARRAY [0..3] OF INT;
  s : STRING[8];
END_VAR
  LD a
  JMPC skip
  LD i
  ADD( j
  MUL 3
  )
  Twice
  ST arr[i]
skip:
  LD t.Q
  ANDN b
  ST a
  CAL t(IN := a, PT := T#1s)
  LD c
  EQ green
  JMPCN done
  LD r
  SQRT
  ST r
  LD 'x'
  ST s
  LIMIT(MN := 0, IN := i, MX := 9)
  ST j
done:
  RET
END_PROGRAM
";

const OPERANDS: &[&str] = &[
    "a",
    "i",
    "r",
    "t",
    "c",
    "arr",
    "s",
    "green",
    "Twice",
    "5",
    "2.5",
    "T#1s",
    "'str'",
    "INT#7",
    "nowhere",
    "t.Q",
    "arr[r]",
    "%IX0.1",
    "Color#red",
];

#[test]
fn the_unmutated_program_is_clean() {
    let (_, d) = analyze_src(BASE);
    assert_eq!(d, "");
}

#[test]
fn mutated_bodies_never_panic() {
    let lines: Vec<&str> = BASE.lines().collect();
    let body: Vec<usize> = (0..lines.len())
        .filter(|&k| {
            let l = lines[k].trim_start();
            lines[k].starts_with("  ")
                && !l.contains(" : ")
                && !l.starts_with(')')
                && !l.ends_with('(')
                && !l.contains("( ")
        })
        .collect();
    let mut runs = 0;
    for &k in &body {
        // Drop the line.
        let mut v = lines.clone();
        v.remove(k);
        analyze_src(&(v.join("\n") + "\n"));
        runs += 1;
        // Swap the operand.
        let l = lines[k].trim_start();
        if let Some((op, _)) = l.split_once(' ') {
            if !l.contains('(') {
                for o in OPERANDS {
                    let mut v = lines.clone();
                    let new = format!("  {op} {o}");
                    v[k] = &new;
                    analyze_src(&(v.join("\n") + "\n"));
                    runs += 1;
                }
            }
        }
        // Make it a conditional jump target's neighbour: insert an unconditional return before it.
        let mut v = lines.clone();
        v.insert(k, "  RET");
        analyze_src(&(v.join("\n") + "\n"));
        runs += 1;
    }
    assert!(runs > 200, "{runs}");
}
