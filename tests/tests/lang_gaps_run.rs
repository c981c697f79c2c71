//! Constructs of real projects that were still rejected or mishandled after issue #13's first rounds,
//! each closed end to end through `ladderc run` (traces checked cycle by cycle): partial access to bits
//! and bytes (`x.3`, `x.%X3`, `x.%B1`) in ST, IL, LD and FBD, and the others added below.

mod common;
use common::{check_text, ladderc, rejected_heads, run_traced as run};

use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/lang_gaps")
        .join(name)
}

// ------------------------------------------------------------------ 1. partial access

#[test]
fn partial_access_reads_and_writes_bits_bytes_and_words_in_st_and_il() {
    // w = 16#0005: b0 = w.0 (1), b2 = w.%X2 (1); w.15 := TRUE, then w.0 toggles each cycle:
    // 16#8004, 16#8005, ...; n = -1 with bit 3 cleared is -9; hi = w.%B1 = 16#80; d.%W1 := w puts w
    // in the high word; q AT %QW0: q.1 := w.0 (after the toggle) and q.%X4 := TRUE. IL: flags = 4:
    // seen := flags.2; flags.7 toggles; R flags.%X2 while seen
    let (trace, _) = run(
        &fixture("partial_access.st"),
        3,
        "main.w,main.b0,main.b2,main.n,main.hi,main.d,%QW0,il_side.flags,il_side.seen",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,main.w,main.b0,main.b2,main.n,main.hi,main.d,%QW0,il_side.flags,il_side.seen\n\
         0,0,32772,1,1,-9,128,2147745792,16,128,1\n\
         1,10,32773,0,1,-9,128,2147811328,18,0,0\n\
         2,20,32772,1,1,-9,128,2147745792,16,128,0\n"
    );
}

#[test]
fn partial_access_in_ld_contacts_coils_and_fbd_variables() {
    // LD: flags = 4; flags.5 := flags.2; S out.%X0 on flags.5; R flags.2 on out.0: cycle 0 ends with
    // flags = 16#20, then flags.2 is 0 so flags.5 drops: 0. FBD: bit3 := w.%X3 (w = 8), w.%B1 := 16#A5
    let (trace, _) = run(
        &fixture("partial_access.xml"),
        3,
        "ladder.flags,ladder.out,fbd.w,fbd.bit3",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,ladder.flags,ladder.out,fbd.w,fbd.bit3\n\
         0,0,32,1,42248,1\n\
         1,10,0,1,42248,1\n\
         2,20,0,1,42248,1\n"
    );
}

#[test]
fn partial_access_out_of_range_or_without_bits_is_one_located_e1029_each() {
    let src = "PROGRAM main\nVAR\n w : WORD;\n b : BOOL;\n r : REAL;\n bb : BYTE;\nEND_VAR\n \
               w.16 := TRUE;\n bb := w.%B2;\n r.0 := TRUE;\n b := b.0;\n w.99999999999 := b;\n\
               END_PROGRAM\n";
    let (code, lines) = check_text("bad.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        vec![
            "bad.st:8:4: error[E1029]: `w.16` is out of range: WORD has bits 0 to 15 (hint: WORD has 16 bits, numbered 0 (the least significant) to 15)",
            "bad.st:9:10: error[E1029]: `w.%B2` is out of range: WORD has bytes 0 to 1 (hint: WORD has 16 bits, numbered 0 (the least significant) to 15)",
            "bad.st:10:4: error[E1029]: `r` is REAL, which has no bits to access with `.0` (hint: partial access (`x.3`, `x.%X3`, `x.%B1`) works on integers and BYTE, WORD, DWORD, LWORD)",
            "bad.st:11:9: error[E1029]: `b` is BOOL, which has no bits to access with `.0` (hint: partial access (`x.3`, `x.%X3`, `x.%B1`) works on integers and BYTE, WORD, DWORD, LWORD)",
            "bad.st:12:4: error[E1029]: `w.99999999999` is out of range: WORD has bits 0 to 15 (hint: WORD has 16 bits, numbered 0 (the least significant) to 15)",
        ]
    );
    // the same in IL: one error at the access
    let il = "PROGRAM main\nVAR\n w : WORD;\nEND_VAR\n LD w.%X16\n ST w.0\nEND_PROGRAM\n";
    let (code, lines) = check_text("bad.il", il);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("bad.il:5:7: error[E1029]"),
        "{lines:?}"
    );
}

// ------------------------------------------------------------------ 2. keyword names in XML IL bodies

#[test]
fn keyword_named_variables_in_an_xml_il_body_run_with_one_w1418_at_each_declaration() {
    // `on` and `task` are IL keywords: the body's `LD on`, `ST task` were E0011 at every use, then
    // one E1031 at each declaration; IEC 61131-3 reserves them for configurations only, CODESYS and
    // TwinCAT accept them as names: now the program runs, with one W1418 at each declaration
    // (tests/tests/lang_left_r12.rs has the ST and IL forms)
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture("keyword_names_il.xml"))
        .args(["--cycles", "3", "--watch", "main.on,main.n"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "cycle,time_ms,main.on,main.n\n0,0,1,1\n1,10,2,2\n2,20,3,3\n"
    );
    let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("W1418")).collect();
    assert_eq!(warnings.len(), 2, "{stderr}");
    assert!(
        warnings[0].ends_with("keyword_names_il.xml:10:25: warning[W1418]: `on` is a keyword of IEC 61131-3 configurations (`RESOURCE r ON cpu`): accepted as a variable name, as CODESYS and TwinCAT do [POU `main`] (hint: for portable IEC 61131-3 code rename the variable, for example `xon`)"),
        "{stderr}"
    );
    assert!(
        warnings[1].contains("keyword_names_il.xml:11:25: warning[W1418]: `task` is a keyword"),
        "{stderr}"
    );
}

// ------------------------------------------------------------------ 3. methods called inside their block

#[test]
fn methods_called_inside_their_own_block_run_in_st_files() {
    // Counter's body calls Bump() (count += Twice(step), a method in an expression of a method) and
    // THIS^.Reset() once THIS^.count passes 10 (Reset zeroes count and calls Bump again); main
    // calls c(step := 2) and reads c.Twice(5) + 1 from outside
    let (trace, stderr) = run(
        &fixture("own_methods.st"),
        5,
        "main.c.count,main.c.calls,main.x",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,main.c.count,main.c.calls,main.x\n\
         0,0,4,1,11\n\
         1,10,8,2,11\n\
         2,20,4,3,11\n\
         3,30,8,4,11\n\
         4,40,4,5,11\n"
    );
    // the hidden inputs a call inside the block sets are no inputs the user wrote (no W1411)
    assert!(!stderr.contains("W1411"), "{stderr}");
}

#[test]
fn codesys_methods_call_each_other_and_are_called_from_their_block() {
    // the level rises by Fill(2.0) = 10 a cycle; past 50, Drain() halves it (by Half(), a method
    // called inside a method) before the fill
    let (trace, _) = run(
        &fixture("own_methods.xml"),
        10,
        "PLC_PRG.fbTank.rLevel,PLC_PRG.fbTank.iCalls",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,PLC_PRG.fbTank.rLevel,PLC_PRG.fbTank.iCalls\n\
         0,0,10,1\n1,10,20,2\n2,20,30,3\n3,30,40,4\n4,40,50,5\n\
         5,50,60,6\n6,60,40,7\n7,70,50,8\n8,80,60,9\n9,90,40,10\n"
    );
}

#[test]
fn own_method_calls_that_cannot_run_are_located_errors() {
    let src = "FUNCTION_BLOCK Fb\nVAR n : INT; END_VAR\n  A();\n  n := Get(1) + Get(2);\n  \
               WHILE Get(3) > 0 DO n := 0; END_WHILE;\n  Nothing(q := 1);\n\
               METHOD A\n  B();\nEND_METHOD\nMETHOD B\n  A();\nEND_METHOD\n\
               METHOD Get : INT\nVAR_INPUT v : INT; END_VAR\n  Get := v;\nEND_METHOD\n\
               METHOD Nothing\nEND_METHOD\nEND_FUNCTION_BLOCK\n\
               PROGRAM main\nVAR f : Fb; END_VAR\n  f();\nEND_PROGRAM\n";
    let (code, lines) = check_text("m.st", src);
    assert_eq!(code, Some(1));
    let codes: Vec<&str> = lines
        .iter()
        .map(|l| l.split_once(": error[").unwrap().0)
        .collect();
    // an unknown parameter; A and B call each other (a call twice in one statement and one in a
    // WHILE condition compile since Struckig's round: `tests/tests/struckig_constructs_run.rs`)
    assert_eq!(
        codes,
        vec!["m.st:6:11", "m.st:8:3", "m.st:11:3"],
        "{lines:?}"
    );
    assert!(lines[0].contains("E1011") && lines[1].contains("E0106"));
}

// ------------------------------------------------------------------ 4. library-qualified names

#[test]
fn names_qualified_with_a_provided_library_run() {
    // go toggles until n (Standard.LIMIT(0, n + 1, 3)) reaches 3, then stays TRUE: the
    // Standard.TON sees IN for 20 ms from cycle 2 and its Q rises in cycle 5, where the
    // Tc2_Standard.R_TRIG counts one edge
    let (trace, _) = run(
        &fixture("library_names.st"),
        6,
        "main.go,main.t.Q,main.n,main.edges",
    );
    assert_eq!(
        trace,
        "cycle,time_ms,main.go,main.t.Q,main.n,main.edges\n\
         0,0,1,0,1,0\n1,10,0,0,2,0\n2,20,1,0,3,0\n3,30,1,0,3,0\n4,40,1,0,3,0\n5,50,1,1,3,1\n"
    );
}

#[test]
fn an_unknown_library_is_one_located_e1032_per_library() {
    let src =
        "PROGRAM main\nVAR\n  pid : OSCAT_BASIC.CTRL_PI;\n  lin : OSCAT_BASIC.F_LIN_TYPE;\n  \
               arr : ARRAY[1..2] OF Lib.Y;\n  x : REAL;\nEND_VAR\n  pid(ACT := x);\n  \
               x := OSCAT_BASIC.F_LIN(x) + pid.Y;\n  x := CAA.Foo(1);\nEND_PROGRAM\n";
    let heads = rejected_heads("lib.st", src);
    assert_eq!(
        heads,
        vec![
            "lib.st:3:9: error[E1032]: `OSCAT_BASIC` is neither a variable nor a library ladderc provides",
            "lib.st:5:24: error[E1032]: `Lib` is neither a variable nor a library ladderc provides",
            "lib.st:10:8: error[E1032]: `CAA` is neither a variable nor a library ladderc provides",
        ]
    );
    // a Util block ladderc does not have is named where it is declared
    let (code, lines) = check_text(
        "util.st",
        "PROGRAM main\nVAR\n  b : Util.BLINK;\nEND_VAR\n  b(ENABLE := TRUE);\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("util.st:3:12: error[E1003]: unknown type `BLINK`"),
        "{lines:?}"
    );
}

// ------------------------------------------------------------------ 6. references and pointers

#[test]
fn reference_and_pointer_declarations_compile_and_run() {
    // REF_TO and POINTER TO compile (issue #13, helper `refs`; before, one E0305 per declaration
    // and the body was not compiled): `x` is 6 after the scan, and `rx^.a` on the NULL `rx` is
    // the run-time report, not an error (`rs` is now `rx`: RS names the standard block, E1031) (`tests/tests/refs_run.rs` has the rest)
    let src = "TYPE S : STRUCT a : INT; END_STRUCT; END_TYPE\nPROGRAM main\nVAR\n  x : INT;\n  \
               r : REF_TO INT;\n  p : POINTER TO INT;\n  rx : REF_TO S;\nEND_VAR\n  r := REF(x);\n  \
               p := ADR(x);\n  r^ := 5;\n  IF r <> NULL THEN x := r^ + 1; END_IF;\n  rx^.a := 3;\n\
               END_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("refs.st");
    std::fs::write(&f, src).unwrap();
    let (trace, stderr) = common::run_traced(&f, 1, "main.x");
    assert_eq!(common::column(&trace, "main.x"), [6.0], "{trace}");
    assert!(
        stderr.contains("runtime: NULL reference dereferenced (first: rx^.a in main"),
        "{stderr}"
    );
}

// ------------------------------------------------------------------ 5. VAR_CONFIG

/// `ladderc run` of a VAR_CONFIG fixture for 4 cycles with its stimulus, watching the two Lamp outputs,
/// the program's `sw` and `n`: the trace and standard error (asserts exit 0).
fn run_var_config(name: &str) -> (String, String) {
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture(name))
        .args(["--cycles", "4", "--sanitize", "--trace", "-", "--stimulus"])
        .arg(fixture("var_config.stimulus.csv"))
        .args(["--watch", "inst.n,inst.sw,%QX0.1,%QX0.2"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    (String::from_utf8_lossy(&out.stdout).into_owned(), stderr)
}

/// The trace both VAR_CONFIG fixtures give.
const VAR_CONFIG_TRACE: &str = "cycle,time_ms,inst.n,inst.sw,%QX0.1,%QX0.2\n\
     0,0,6,0,0,1\n1,10,7,1,1,1\n2,20,8,1,1,1\n3,30,9,0,0,1\n";

#[test]
fn var_config_locates_placeholders_per_instance_and_sets_initial_values() {
    // two Lamp instances, each `out AT %Q*`, get %QX0.1 and %QX0.2; the program's `sw AT %I*` is
    // %IX0.0 (stimulus: 1 from cycle 1, 0 from cycle 3); `n` starts at 5 instead of 0
    let (trace, _) = run_var_config("var_config.st");
    assert_eq!(trace, VAR_CONFIG_TRACE);
}

#[test]
fn var_config_entries_that_cannot_apply_are_located_e0306() {
    let src = std::fs::read_to_string(fixture("var_config.st"))
        .unwrap()
        .replace(
            "res.inst.n : INT := 5;",
            "res.inst.n AT %QW2 : INT;\n    res.ghost.x : INT := 1;\n    res.inst.l1.nope : BOOL := TRUE;",
        );
    let heads = rejected_heads("vc.st", &src);
    assert_eq!(
        heads,
        vec![
            "vc.st:24:5: error[E0306]: this VAR_CONFIG entry cannot be applied: `n` is not declared AT %Q*",
            "vc.st:25:5: error[E0306]: this VAR_CONFIG entry cannot be applied: `res.ghost` names no program instance",
            "vc.st:26:5: error[E0306]: this VAR_CONFIG entry cannot be applied: `Lamp` has no variable `nope`",
        ]
    );
}

#[test]
fn var_config_of_a_tc6_xml_configuration_locates_placeholders_per_instance() {
    // the same project in PLCopen TC6 XML 2.01: `<configVars>` of the `<configuration>`, paths
    // `res.inst.l1.out`, `cfg.res.inst.l2.out` (the configuration's name in front) and `inst.sw`,
    // an `<initialValue>` for `n`; before, the entries were ignored and each `%Q*` was E2002
    let (trace, _) = run_var_config("var_config.xml");
    assert_eq!(trace, VAR_CONFIG_TRACE);
}

#[test]
fn var_config_placeholders_left_unconfigured_and_bad_xml_entries_are_located() {
    let src = std::fs::read_to_string(fixture("var_config.xml")).unwrap();
    let decl_line = src
        .lines()
        .position(|l| l.contains("address=\"%Q*\""))
        .unwrap()
        + 1;
    // l2's `out AT %Q*` named by no entry: E2002 at the placeholder in Lamp's declaration (the copy
    // made for l1 has the entry's address; before, the error pointed at l1's entry)
    let without_l2: String = src
        .lines()
        .filter(|l| !l.contains("l2.out"))
        .map(|l| format!("{l}\n"))
        .collect();
    let (code, lines) = check_text("vc.xml", &without_l2);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(&format!("vc.xml:{decl_line}:43: error[E2002]: unsupported address `%QX*`: a `*` address must be given a location"))
            && lines[0].contains("[POU `Lamp`]"),
        "{lines:?}"
    );
    // entries that cannot be read or applied: E0306 at their attribute
    let bad = src
        .replace("\"res.inst.n\"", "\"res.ghost.n\"")
        .replace("\"%QX0.2\"", "\"%QX*\"")
        .replace("\"inst.sw\"", "\"inst..sw\"");
    let heads = rejected_heads("vc.xml", &bad);
    assert_eq!(
        heads,
        vec![
            "vc.xml:53:78: error[E0306]: this VAR_CONFIG entry cannot be read: `%QX*` is not a complete direct address (%IX0.0, %QW2, %MD4)",
            "vc.xml:54:48: error[E0306]: this VAR_CONFIG entry cannot be read: `inst..sw` is not an instance path (identifiers joined by dots)",
            "vc.xml:55:48: error[E0306]: this VAR_CONFIG entry cannot be applied: `res.ghost` names no program instance",
        ]
    );
}

#[test]
fn var_config_paths_with_and_without_the_resource_reach_one_instance() {
    // `inst.sw` beside `res.inst.l1.out`: one copy of `main` for the instance (before, the second
    // form made a second copy, the first copy's Lamp addresses were lost, and l1's `%Q*` was E2002)
    let src = std::fs::read_to_string(fixture("var_config.st"))
        .unwrap()
        .replace("res.inst.sw AT", "inst.sw AT");
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("vc.st");
    std::fs::write(&f, &src).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(&f)
        .args(["--cycles", "4", "--sanitize", "--trace", "-", "--stimulus"])
        .arg(fixture("var_config.stimulus.csv"))
        .args(["--watch", "inst.n,inst.sw,%QX0.1,%QX0.2"])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(String::from_utf8_lossy(&out.stdout), VAR_CONFIG_TRACE);
    // a placeholder no entry locates is E2002 at its declaration, not at another instance's entry
    let (code, lines) = check_text(
        "vc.st",
        &src.replace("res.inst.l2.out AT %QX0.2 : BOOL;", ""),
    );
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("vc.st:4:12: error[E2002]"),
        "{lines:?}"
    );
}

#[test]
fn var_config_applies_to_programs_of_other_files() {
    // the configuration in one file, its program and block in another (a project laid out as
    // trust-platform's and RuSTy's examples are): the same trace as the one-file fixture; before,
    // each entry was E0306 "no program `main` in this file"
    let dir = tempfile::tempdir().unwrap();
    let src = std::fs::read_to_string(fixture("var_config.st")).unwrap();
    let at = src.find("CONFIGURATION").unwrap();
    let (pous, config) = (dir.path().join("pous.st"), dir.path().join("config.st"));
    std::fs::write(&pous, &src[..at]).unwrap();
    std::fs::write(&config, &src[at..]).unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(&config)
        .arg(&pous)
        .args(["--cycles", "4", "--sanitize", "--trace", "-", "--stimulus"])
        .arg(fixture("var_config.stimulus.csv"))
        .args(["--watch", "inst.n,inst.sw,%QX0.1,%QX0.2"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "cycle,time_ms,inst.n,inst.sw,%QX0.1,%QX0.2\n\
         0,0,6,0,0,1\n1,10,7,1,1,1\n2,20,8,1,1,1\n3,30,9,0,0,1\n"
    );
    // a program that no file declares is still one located E0306 per entry
    std::fs::write(
        &pous,
        "FUNCTION_BLOCK Lamp\nVAR out AT %Q* : BOOL; END_VAR\nEND_FUNCTION_BLOCK\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&config)
        .arg(&pous)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        stderr
            .matches("error[E0306]: this VAR_CONFIG entry cannot be applied: no program `main` in this project")
            .count(),
        4,
        "{stderr}"
    );
}

#[test]
fn var_config_in_an_il_file_runs() {
    // the IL twin of var_config.st; before, its VAR_CONFIG block was E0019 (skipped)
    let (trace, stderr) = run_var_config("var_config.il");
    assert!(!stderr.contains("E0019"), "{stderr}");
    assert_eq!(trace, VAR_CONFIG_TRACE);
}

#[test]
fn an_interface_method_missing_in_the_block_is_one_located_e0335_without_cascade() {
    // edition 3's INTERFACE (trust-platform's filling line, CODESYS): before, its METHOD and
    // PROPERTY lines were read as IL, one E0011 each plus W0001 "instructions outside any POU";
    // then the interface and the IMPLEMENTS clause were E0303 each; now the interface is read and
    // the block that implements it lacks its method `Open` and its property `IsOpen`, which
    // interfaces declare since their properties are called through interface variables
    // (`tests/tests/oop_interface_run.rs`)
    let src = "INTERFACE IValve\n    METHOD Open : BOOL\n    END_METHOD\n    PROPERTY IsOpen : BOOL\n        GET\n        END_GET\n    END_PROPERTY\nEND_INTERFACE\n\n\
               FUNCTION_BLOCK Valve IMPLEMENTS IValve\nVAR_OUTPUT q : BOOL; END_VAR\n  q := TRUE;\nEND_FUNCTION_BLOCK\n\n\
               PROGRAM main\nVAR v : Valve; END_VAR\n  v();\nEND_PROGRAM\n";
    let heads = rejected_heads("itf.st", src);
    assert_eq!(
        heads,
        vec![
            "itf.st:10:33: error[E0335]: `Valve` IMPLEMENTS `IValve` but has no method `Open`",
            "itf.st:10:33: error[E0335]: `Valve` IMPLEMENTS `IValve` but has no Get accessor for property `IsOpen`",
        ]
    );
}

#[test]
fn st_statements_outside_any_pou_are_one_located_e0307() {
    // a CODESYS body copied out on its own (kedharnath-ry/icss-separator's PLC_PRG.st): before, the
    // .st file's statements were read as IL, one E0011/E0007/E0001 per line and W0001
    let src = "// cycle logic\nIF start THEN\n    n := n + 1;\nEND_IF;\nlamp := n > 3;\n";
    let (code, lines) = check_text("body.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        vec!["body.st:2:1: error[E0307]: statements outside any POU: in a Structured Text file they belong in a PROGRAM, FUNCTION_BLOCK or FUNCTION (hint: wrap them in `PROGRAM body` ... `END_PROGRAM` with their declarations in a VAR block (a CODESYS body exported alone lacks both))"]
    );
    // the same statements in a program, after another POU, run; a stray one after it is E0307
    let prog = format!(
        "FUNCTION_BLOCK Blink\nVAR_OUTPUT q : BOOL; END_VAR\n  q := NOT q;\nEND_FUNCTION_BLOCK\n\
         PROGRAM main\nVAR start : BOOL := TRUE; n : INT; lamp : BOOL; END_VAR\n{src}END_PROGRAM\n"
    );
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("body.st");
    std::fs::write(&f, &prog).unwrap();
    let (trace, _) = run(&f, 5, "main.n,main.lamp");
    assert_eq!(
        trace,
        "cycle,time_ms,main.n,main.lamp\n0,0,1,0\n1,10,2,0\n2,20,3,0\n3,30,4,1\n4,40,5,1\n"
    );
    let (code, lines) = check_text("tail.st", &format!("{prog}x := 1;\n"));
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("tail.st:13:1: error[E0307]"),
        "{lines:?}"
    );
}

#[test]
fn an_expression_as_initial_value_is_located_with_a_declaration_hint() {
    // trust-platform's conformance case `c : INT := b + 1;` in an .st file: before, the hint said
    // "IL has no infix operators: use ... ADD, SUB" (the declarations are read by the IL parser);
    // then the constant expression was evaluated, and `b` named as not being a constant (E0022);
    // since Session 36 it is computed at run time, as CODESYS and TwinCAT do, with W1433
    // (`tests/tests/run_time_inits_run.rs`)
    let src = "PROGRAM Main\nVAR\n    b : INT := 4;\n    c : INT := b + 1;\nEND_VAR\n  b := c;\nEND_PROGRAM\n";
    let (code, lines) = check_text("init.st", src);
    assert_eq!(code, Some(0));
    assert_eq!(
        lines,
        vec!["init.st:4:13: warning[W1433]: the initial value of `c` is computed at run time: IEC 61131-3 takes a constant expression (the POU's other such initial values are not reported) (hint: compiled as CODESYS and TwinCAT do: assigned in declaration order when the instance is initialised, before FB_init; for another IEC compiler assign it in the body)"]
    );
    // a real variable in a bound stays E0022: a bound is no initial value
    let (code, lines) = check_text(
        "bound.st",
        "PROGRAM Main\nVAR\n    b : INT := 4;\n    a : ARRAY[0..b] OF INT;\nEND_VAR\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert!(
        lines
            .iter()
            .any(|l| l.contains("error[E0022]") && l.contains("`b` names no constant")),
        "{lines:?}"
    );
    // in an IL body the operator keeps the IL hint
    let (_, lines) = check_text(
        "op.il",
        "PROGRAM p\nVAR a : INT; END_VAR\n  LD a + 1\n  ST a\nEND_PROGRAM\n",
    );
    assert!(
        lines
            .iter()
            .any(|l| l.contains("error[E0001]") && l.contains("IL has no infix operators")),
        "{lines:?}"
    );
}

// ------------------------------------------------------ constant expressions in declarations

#[test]
fn constant_expressions_size_arrays_and_strings_in_st_files() {
    // IEC 61131-3 ed. 3 / CODESYS: N = 4 (VAR_GLOBAL CONSTANT), M = 3 (VAR CONSTANT):
    // a 0..N-1 = 0..3, b 1..2*N = 1..8, c -M..(M + 1) MOD 3, 0..N / 3 = -3..1, 0..1,
    // s STRING[N+1] = 5 characters (the assigned 8 are truncated). Before: E0011 "expected a number"
    let out = ladderc()
        .args(["run"])
        .arg(fixture("const_bounds.st"))
        .args(["--cycles", "1", "--sanitize", "--trace", "-"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "cycle,time_ms,N,Main.M,Main.a[0],Main.a[1],Main.a[2],Main.a[3],Main.b[1],Main.b[2],\
         Main.b[3],Main.b[4],Main.b[5],Main.b[6],Main.b[7],Main.b[8],\"Main.c[-3,0]\",\
         \"Main.c[-3,1]\",\"Main.c[-2,0]\",\"Main.c[-2,1]\",\"Main.c[-1,0]\",\"Main.c[-1,1]\",\
         \"Main.c[0,0]\",\"Main.c[0,1]\",\"Main.c[1,0]\",\"Main.c[1,1]\",Main.s,Main.i\n\
         0,0,4,3,0,10,20,30,0,0,0,0,0,0,0,5,1,0,0,0,0,0,0,0,0,2,\"abcde\",4\n"
    );
}

#[test]
fn constant_expressions_size_arrays_in_il_files() {
    // the same declarations in an IL file: ARRAY[1..N*2] with N = 3 holds 6 elements
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("bounds.il");
    std::fs::write(
        &f,
        "PROGRAM Main\nVAR CONSTANT\n  N : INT := 3;\nEND_VAR\nVAR\n  a : ARRAY[1..N*2] OF INT;\n\
         s : STRING[(N - 1) * 2];\nEND_VAR\n  LD 7\n  ST a[6]\n  LD 'abcdef'\n  ST s\nEND_PROGRAM\n",
    )
    .unwrap();
    let (trace, _) = run(&f, 1, "Main.a[1],Main.a[6],Main.s");
    assert_eq!(
        trace,
        "cycle,time_ms,Main.a[1],Main.a[6],Main.s\n0,0,0,7,\"abcd\"\n"
    );
}

#[test]
fn constant_expressions_that_cannot_be_evaluated_are_one_located_e0022_each() {
    let src = "VAR_GLOBAL CONSTANT\n  N : INT := 4;\n  PI_C : REAL := 3.14;\nEND_VAR\n\
               PROGRAM Main\nVAR\n  k : INT := 3;\n  a : ARRAY[0..k-1] OF INT;\n\
               b : ARRAY[0..N / (N - 4)] OF INT;\n  c : ARRAY[1..N * 1000000000] OF INT;\n\
               s : STRING[N 1];\n  d : ARRAY[0..PI_C] OF INT;\n  e : ARRAY[0..N-1] OF INT;\n\
               END_VAR\n  e[0] := k;\nEND_PROGRAM\n";
    let (code, lines) = check_text("bad.st", src);
    assert_eq!(code, Some(1));
    let hint = "(hint: use integer literals and integer constants (VAR CONSTANT or VAR_GLOBAL CONSTANT with an integer value, declared before in this file, or a VAR_GLOBAL CONSTANT list of another file given with it) with + - * / MOD, parentheses and SIZEOF(T) of a data type)";
    let missing = "(hint: declare the constant in a VAR_GLOBAL CONSTANT list given with the files, or write the number; a library's constant (TwinCAT's, CODESYS's): give the library's source project with --lib)";
    assert_eq!(
        lines,
        vec![
            // (round 32: a name that is no constant of the files given says so, with its own hint)
            format!("bad.st:8:16: error[E0022]: constant expression `k-1`: `k` names no constant with a value in the files given {missing}"),
            format!("bad.st:9:14: error[E0022]: constant expression `N / (N - 4)`: division by zero {hint}"),
            format!("bad.st:10:16: error[E0022]: constant expression `N * 1000000000`: the value overflows {hint}"),
            "bad.st:11:14: error[E0022]: an operator is missing in this constant expression (hint: write + - * / or MOD between the operands)".to_string(),
            format!("bad.st:12:16: error[E0022]: constant expression `PI_C`: `PI_C` is not an integer constant {hint}"),
        ]
    );
}

#[test]
fn constant_expressions_as_initial_values_are_evaluated() {
    // M uses N in the same CONSTANT block; a is sized by M; d: (5 * -3) MOD 4 = -3 (MOD keeps the
    // dividend's sign); e needs LINT. Before: E0001 "unexpected character `*`"
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("init.st");
    std::fs::write(
        &f,
        "VAR_GLOBAL CONSTANT\n  N : INT := 4;\n  M : INT := N * 2 + 1;\nEND_VAR\nPROGRAM Main\nVAR\n\
         a : ARRAY[0..M-1] OF INT := [1, 2, 3(7)];\n  c : INT := N * 2;\n\
         d : DINT := (N + 1) * -3 MOD 4;\n  e : LINT := N * 1000000000000;\n  f : INT := -N;\n\
         END_VAR\nc := c + 1;\nEND_PROGRAM\n",
    )
    .unwrap();
    let (trace, _) = run(&f, 2, "M,Main.a[4],Main.a[8],Main.c,Main.d,Main.e,Main.f");
    assert_eq!(
        trace,
        "cycle,time_ms,M,Main.a[4],Main.a[8],Main.c,Main.d,Main.e,Main.f\n\
         0,0,9,7,0,9,-3,4000000000000,-4\n\
         1,10,9,7,0,10,-3,4000000000000,-4\n"
    );
    // the value is checked against the variable's type like a literal
    let (code, lines) = check_text(
        "range.st",
        "PROGRAM Main\nVAR\n  d : INT := 3 * 20000;\nEND_VAR\nd := d;\nEND_PROGRAM\n",
    );
    assert_eq!(code, Some(1));
    assert_eq!(
        lines,
        vec!["range.st:3:14: error[E1017]: initial value 60000 does not fit INT (hint: use a value in the range of INT or a wider type)"]
    );
}
