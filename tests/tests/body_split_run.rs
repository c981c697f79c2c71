//! Long POU bodies are emitted as several C functions (issue #12: `cc -O2` time grows faster than
//! linearly in one function's size). Through `ladderc run`, cycle by cycle, a program of about 900
//! rungs and 3,300 instructions behaves exactly as the same program in one C function
//! (`LADDERC_BODY_PART=0`), cut into parts of about 200 instructions (`LADDERC_BODY_PART=200`) and cut
//! every few instructions (`LADDERC_BODY_PART=5`):
//! jumps forward and backward across parts, a conditional RET, timers, counters, edge triggers, a
//! VAR_TEMP and the current result alive across cuts, a FUNCTION (inputs, output, locals, result) and a
//! FUNCTION_BLOCK with an `R_EDGE` input, `EN`/`ENO` and a VAR_TEMP, all split too. The split C compiles
//! with `-Wall -Wextra -Werror -pedantic`, runs under the sanitizers, and no C function of a large body
//! exceeds a bound.

mod common;

use common::{assert_ok, ladderc, text_column};
use std::fmt::Write as _;
use std::path::Path;

const VARS: usize = 16;

/// A block of `n` rungs (IL) over the program's variables; `tag` keeps its labels unique.
fn rungs(tag: &str, n: usize, out: &mut String) {
    for r in 0..n {
        let (a, b, c) = (r % VARS, (r * 7 + 3) % VARS, r % 8);
        match r % 9 {
            0 => writeln!(out, "    LD in{c}\n    AND y{b}\n    ST y{a}"),
            1 => writeln!(out, "    LD in{c}\n    ANDN y{b}\n    R y{a}"),
            2 => writeln!(
                out,
                "    CAL e{c}(CLK := in{})\n    LD e{c}.Q\n    OR y{b}\n    S y{a}",
                (c + 1) % 8
            ),
            3 => writeln!(
                out,
                "    CAL t{c}(IN := y{b}, PT := T#20ms)\n    LD t{c}.Q\n    ST y{a}"
            ),
            4 => writeln!(
                out,
                "    CAL c{c}(CU := in{c}, R := in{}, PV := 5)\n    LD c{c}.CV\n    ST k{a}",
                (c + 3) % 8
            ),
            5 => writeln!(out, "    LD k{a}\n    ADD {}\n    ST k{b}", r % 7),
            6 => writeln!(out, "    LD k{a}\n    GT 10\n    ST y{b}\n    ST y{a}"),
            7 => writeln!(
                out,
                "    LD y{a}\n    JMPCN {tag}{r}\n    LD k{b}\n    ADD 1\n    ST k{b}\n{tag}{r}:"
            ),
            _ => writeln!(
                out,
                "    LD k{b}\n    ST tmp\n    LD tmp\n    SUB k{a}\n    ST k{a}"
            ),
        }
        .unwrap();
    }
}

/// The program under test: `main` runs block A three times (a backward jump over 300 rungs), skips
/// block B when `in1` (a forward jump over 300 rungs), returns early when `in2`, and calls `Big` and an
/// `EdgeFB` instance, whose bodies are long enough to be split too.
fn program() -> String {
    let mut s = String::new();
    // FUNCTION: acc := 3 * a * lines (two loop rounds), result acc or -acc, output o
    s.push_str(
        "FUNCTION Big : INT\nVAR_INPUT a : INT; b : BOOL; END_VAR\nVAR_OUTPUT o : INT; END_VAR\n\
         VAR i : INT; acc : INT; END_VAR\n    LD b\n    ST ENO\n    LD 0\n    ST acc\n    ST i\nloop:\n",
    );
    for _ in 0..400 {
        s.push_str("    LD acc\n    ADD a\n    ST acc\n");
    }
    s.push_str(
        "    LD i\n    ADD 1\n    ST i\n    LT 3\n    JMPC loop\n    LD ENO\n    JMPCN neg\n    LD acc\n    ST o\n    ST Big\n    RET\n\
         neg:\n    LD 0\n    SUB acc\n    ST Big\nEND_FUNCTION\n\n",
    );
    // FUNCTION_BLOCK: counts rising edges of `go`; `e` is ENO (= go's edge) read back at the end
    s.push_str(
        "FUNCTION_BLOCK EdgeFB\nVAR_INPUT go : BOOL R_EDGE; END_VAR\nVAR_OUTPUT n : INT; e : BOOL; s : INT; END_VAR\n\
         VAR_TEMP t : INT; END_VAR\n    LD go\n    ST ENO\n    LD 0\n    ST t\n    LD go\n    JMPCN done\n    LD n\n    ADD 1\n    ST n\n",
    );
    for _ in 0..400 {
        s.push_str("    LD t\n    ADD 1\n    ST t\n");
    }
    s.push_str("done:\n    LD t\n    ST s\n    LD ENO\n    ST e\nEND_FUNCTION_BLOCK\n\n");
    s.push_str("PROGRAM main\nVAR\n");
    for i in 0..8 {
        writeln!(
            s,
            "    in{i} : BOOL; t{i} : TON; c{i} : CTU; e{i} : R_TRIG;"
        )
        .unwrap();
    }
    for i in 0..VARS {
        writeln!(s, "    y{i} : BOOL; k{i} : INT;").unwrap();
    }
    s.push_str(
        "    loops : INT; total : INT; tmp_seen : INT; res : INT; out : INT; fbi : EdgeFB; fb_n : INT; fb_e : BOOL; fb_s : INT;\nEND_VAR\n\
         VAR_TEMP tmp : INT; END_VAR\n    LD 0\n    ST loops\n    LD k3\n    ST tmp\ntop:\n",
    );
    rungs("a", 300, &mut s);
    s.push_str("    LD loops\n    ADD 1\n    ST loops\n    LT 3\n    JMPC top\n    LD in1\n    JMPC skip\n");
    rungs("b", 300, &mut s);
    s.push_str(
        "skip:\n    LD tmp\n    ST tmp_seen\n    Big(a := 2, b := in0, o => out)\n    ST res\n    CAL fbi(go := in4)\n\
         \x20   LD fbi.n\n    ST fb_n\n    LD fbi.e\n    ST fb_e\n    LD fbi.s\n    ST fb_s\n    LD in2\n    RETC\n",
    );
    rungs("c", 300, &mut s);
    s.push_str("    LD total\n    ADD 1\n    ST total\nEND_PROGRAM\n");
    s
}

/// Stimulus: input `j` toggles every `j + 1` cycles (offset so that not all start TRUE); `in2` (the early
/// RET) is TRUE in cycles 7-9 and 20.
fn stimulus(cycles: usize) -> String {
    let mut s = String::from("cycle,variable,value\n");
    for k in 0..cycles {
        for j in [0usize, 1, 3, 4, 5, 6, 7] {
            let v = ((k + j) / (j + 1)) % 2;
            writeln!(s, "{k},main.in{j},{v}").unwrap();
        }
        let ret = u8::from((7..=9).contains(&k) || k == 20);
        writeln!(s, "{k},main.in2,{ret}").unwrap();
    }
    s
}

/// `ladderc run` of the program with `LADDERC_BODY_PART` set to `part`, every variable traced; returns
/// the trace.
fn run(dir: &Path, part: &str, sanitize: bool, cycles: usize) -> String {
    let src = dir.join("big.il");
    let stim = dir.join("stim.csv");
    std::fs::write(&src, program()).unwrap();
    std::fs::write(&stim, stimulus(cycles)).unwrap();
    let trace = dir.join(format!("trace_{part}.csv"));
    let mut cmd = ladderc();
    cmd.arg("run")
        .arg(&src)
        .args(["--cycles", &cycles.to_string(), "--stimulus"])
        .arg(&stim)
        .arg("--trace")
        .arg(&trace);
    if sanitize {
        cmd.arg("--sanitize");
    }
    let out = cmd.env("LADDERC_BODY_PART", part).output().unwrap();
    assert_ok(&out);
    std::fs::read_to_string(&trace).unwrap()
}

/// The C of the program with `LADDERC_BODY_PART` set to `part`.
fn c_text(dir: &Path, part: &str) -> String {
    let src = dir.join("big.il");
    std::fs::write(&src, program()).unwrap();
    let out_dir = dir.join(format!("c_{part}"));
    let mut cmd = ladderc();
    cmd.arg("build").arg(&src).arg("-o").arg(&out_dir);
    assert_ok(&cmd.env("LADDERC_BODY_PART", part).output().unwrap());
    std::fs::read_to_string(out_dir.join("program.c")).unwrap()
}

#[test]
fn a_split_body_runs_cycle_by_cycle_as_the_same_body_in_one_function() {
    let dir = tempfile::tempdir().unwrap();
    let cycles = 30;

    // parts of about 200 instructions split every body here; 0 keeps each in one function
    let whole = c_text(dir.path(), "0");
    assert!(
        !whole.contains("_PART_"),
        "LADDERC_BODY_PART=0 splits nothing"
    );
    let split = c_text(dir.path(), "200");
    for f in [
        "P_main_BODY_PART_3(",
        "F_big_PART_2(",
        "FB_edgefb_BODY_PART_2(",
    ] {
        assert!(split.contains(f), "{f} missing: the body was not split");
    }
    // the backward jump to `top`, the forward one to `skip` and Big's loop cross parts
    assert!(split.contains("switch (entry)"), "no jump between parts");
    assert!(split.contains("goto exit_;"), "no jump between parts");

    let reference = run(dir.path(), "0", false, cycles);
    let medium = run(dir.path(), "200", false, cycles);
    let tiny = run(dir.path(), "5", true, cycles);
    let rows = |t: &str| t.lines().map(str::to_string).collect::<Vec<_>>();
    let (r, d, t) = (rows(&reference), rows(&medium), rows(&tiny));
    assert_eq!(r.len(), cycles + 1);
    for k in 0..r.len() {
        assert_eq!(
            r[k], d[k],
            "parts of about 200 instructions, trace line {k}"
        );
        assert_eq!(r[k], t[k], "parts of 5 instructions, trace line {k}");
    }

    // and the values are the expected ones, not only equal
    let in0 = text_column(&reference, "main.in0");
    let in2 = text_column(&reference, "main.in2");
    let in4 = text_column(&reference, "main.in4");
    let res = text_column(&reference, "main.res");
    let out = text_column(&reference, "main.out");
    let loops = text_column(&reference, "main.loops");
    let total = text_column(&reference, "main.total");
    let fb_n = text_column(&reference, "main.fb_n");
    let fb_e = text_column(&reference, "main.fb_e");
    let fb_s = text_column(&reference, "main.fb_s");
    let (mut ends, mut rises, mut last_in4) = (0, 0, false);
    for k in 0..cycles {
        // Big: three rounds of 400 additions of 2; with b FALSE the result is negated and o untouched
        let b = in0[k] == "1";
        assert_eq!(res[k], if b { "2400" } else { "-2400" }, "cycle {k}");
        assert_eq!(out[k], if b { "2400" } else { "0" }, "cycle {k}");
        assert_eq!(loops[k], "3", "cycle {k}: block A runs three times");
        if in2[k] == "0" {
            ends += 1;
        }
        assert_eq!(
            total[k],
            ends.to_string(),
            "cycle {k}: RETC leaves before the end"
        );
        let go = in4[k] == "1";
        let rose = go && !last_in4;
        last_in4 = go;
        if rose {
            rises += 1;
        }
        assert_eq!(fb_n[k], rises.to_string(), "cycle {k}: R_EDGE count");
        assert_eq!(fb_e[k], if rose { "1" } else { "0" }, "cycle {k}: ENO");
        assert_eq!(
            fb_s[k],
            if rose { "400" } else { "0" },
            "cycle {k}: VAR_TEMP"
        );
    }
    assert!(rises >= 3 && ends < cycles && ends > 0);
}

#[test]
fn split_c_compiles_with_all_warnings_as_errors() {
    let dir = tempfile::tempdir().unwrap();
    for part in ["5", "200"] {
        let src = dir.path().join("big.il");
        std::fs::write(&src, program()).unwrap();
        let out_dir = dir.path().join(format!("w{part}"));
        let out = ladderc()
            .arg("build")
            .arg(&src)
            .arg("-o")
            .arg(&out_dir)
            .env("LADDERC_BODY_PART", part)
            .output()
            .unwrap();
        assert_ok(&out);
        let make = std::process::Command::new("make")
            .args(["-s", "CFLAGS=-std=c99 -Wall -Wextra -Werror -pedantic -O0"])
            .current_dir(&out_dir)
            .output()
            .unwrap();
        assert!(
            make.status.success(),
            "part {part}: {}",
            String::from_utf8_lossy(&make.stderr)
        );
    }
}

#[test]
fn no_c_function_of_a_large_body_exceeds_a_bound() {
    // 6,000 rungs (about 22,000 instructions, 25,000 lines of C in one body before the split)
    let dir = tempfile::tempdir().unwrap();
    let mut s = String::from("PROGRAM main\nVAR\n");
    for i in 0..8 {
        writeln!(
            s,
            "    in{i} : BOOL; t{i} : TON; c{i} : CTU; e{i} : R_TRIG;"
        )
        .unwrap();
    }
    for i in 0..VARS {
        writeln!(s, "    y{i} : BOOL; k{i} : INT;").unwrap();
    }
    s.push_str("END_VAR\nVAR_TEMP tmp : INT; END_VAR\n");
    rungs("r", 6000, &mut s);
    s.push_str("END_PROGRAM\n");
    let src = dir.path().join("large.il");
    std::fs::write(&src, s).unwrap();
    let out_dir = dir.path().join("out");
    let out = ladderc()
        .arg("build")
        .arg(&src)
        .arg("-o")
        .arg(&out_dir)
        .env_remove("LADDERC_BODY_PART")
        .output()
        .unwrap();
    assert_ok(&out);
    let c = std::fs::read_to_string(out_dir.join("program.c")).unwrap();
    // function definitions start at column 0 with `{` at the end of the line and end at a `}` line
    let (mut longest, mut functions, mut current) = (0usize, 0usize, None::<usize>);
    for line in c.lines() {
        if line.ends_with('{') && !line.starts_with([' ', '}']) && line.contains('(') {
            current = Some(0);
            functions += 1;
        } else if line == "}" {
            if let Some(n) = current.take() {
                longest = longest.max(n);
            }
        } else if let Some(n) = current.as_mut() {
            *n += 1;
        }
    }
    let total = c.lines().count();
    assert!(total > 20_000, "{total} lines");
    assert!(
        longest <= 2_500,
        "the longest function has {longest} lines (of {total}, {functions} functions)"
    );
    assert!(c.matches("P_main_BODY_PART_").count() >= 2 * 15);
}
