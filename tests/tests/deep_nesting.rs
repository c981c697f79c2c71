//! Nesting far beyond every cap (issue #12, the recursion audit): 100,000 levels of each construct a user
//! can nest, through the `ladderc` binary. Each run ends with the cap's located diagnostic and exit 1 (or a
//! clean exit 0 where the walk is iterative and needs no cap), never a stack overflow, in a few seconds.
//!
//! Input: generated files in a temporary folder. Output: the exit status and `--message-format short`
//! lines. Invariant: every construct nests 100,000 deep, far beyond its cap (64 to 2,000).

mod common;

use common::ladderc;
use std::path::Path;
use std::process::Output;
use std::time::{Duration, Instant};

const LEVELS: usize = 100_000;

/// Wall time allowed per run: a bound on termination, not a speed figure (speed lives in the benches).
/// A quadratic walk over 100,000 levels takes tens of minutes, so 120 s still catches one, while a debug
/// build on a loaded 2-core machine (41.6 s seen once for the slowest case beside a release build) passes;
/// a release build gets issue #12's 20 s.
const LIMIT: Duration = Duration::from_secs(if cfg!(debug_assertions) { 120 } else { 20 });

/// Runs `ladderc check --message-format short FILE` (or other arguments) in `dir`.
fn check(dir: &Path, args: &[&str]) -> (Output, String) {
    let t = Instant::now();
    let out = ladderc()
        .arg("check")
        .args(["--message-format", "short"])
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap();
    let took = t.elapsed();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(
        matches!(out.status.code(), Some(0..=2)),
        "exit {:?} (a stack overflow is a signal, a panic 101): {}",
        out.status,
        &err[..err.len().min(2000)]
    );
    assert!(took < LIMIT, "took {took:?}");
    assert!(err.len() < 64 * 1024, "{} bytes of diagnostics", err.len());
    (out, err)
}

/// Asserts exit 1 and that `code` is reported in `file`, at a line and column.
fn assert_capped(out: &Output, err: &str, file: &str, code: &str) {
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.lines().any(|l| {
            l.starts_with(&format!("{file}:"))
                && l.contains(&format!("error[{code}]"))
                && l.split(':')
                    .nth(1)
                    .is_some_and(|n| n.parse::<usize>().is_ok())
        }),
        "want a located {code} in {file}:\n{}",
        &err[..err.len().min(2000)]
    );
    assert_eq!(
        err.matches(&format!("[{code}]")).count(),
        1,
        "one report per construct:\n{}",
        &err[..err.len().min(2000)]
    );
}

fn write(dir: &Path, name: &str, text: &str) {
    std::fs::write(dir.join(name), text).unwrap();
}

#[test]
fn array_types_nested_100000_deep_are_e0211() {
    let dir = tempfile::tempdir().unwrap();
    let src = format!(
        "PROGRAM p\nVAR x : {}INT; n : INT; END_VAR\n  LD n\n  ST n\nEND_PROGRAM\n",
        "ARRAY [0..1] OF ".repeat(LEVELS)
    );
    write(dir.path(), "deep.il", &src);
    let (out, err) = check(dir.path(), &["deep.il"]);
    assert_capped(&out, &err, "deep.il", "E0211");
    // The same cap holds in a TYPE block.
    let src = format!(
        "TYPE t : {}INT; END_TYPE\nPROGRAM p\nVAR n : INT; END_VAR\n  LD n\n  ST n\nEND_PROGRAM\n",
        "ARRAY [0..1] OF ".repeat(LEVELS)
    );
    write(dir.path(), "deep_type.il", &src);
    let (out, err) = check(dir.path(), &["deep_type.il"]);
    assert_capped(&out, &err, "deep_type.il", "E0211");
}

#[test]
fn constant_expressions_of_400000_terms_or_levels_are_one_e0022() {
    // a bound and an initial value as long or as deep as the user writes them: evaluated with a depth
    // cap, and the parsed expression is dropped without recursion (the derived drop overflowed
    // from about 200,000; hence four times LEVELS here)
    let terms = 4 * LEVELS;
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            "sum.st",
            format!(
                "PROGRAM p\nVAR a : ARRAY[0..{}] OF INT; END_VAR\na[0] := 1;\nEND_PROGRAM\n",
                vec!["1"; terms].join("+")
            ),
        ),
        (
            "neg.st",
            format!(
                "PROGRAM p\nVAR a : ARRAY[0..{}1{}] OF INT; END_VAR\na[0] := 1;\nEND_PROGRAM\n",
                "-(".repeat(terms),
                ")".repeat(terms)
            ),
        ),
        (
            "init.il",
            format!(
                "PROGRAM p\nVAR c : LINT := {}; END_VAR\n  LD c\n  ST c\nEND_PROGRAM\n",
                vec!["1"; terms].join("+")
            ),
        ),
    ];
    for (name, src) in cases {
        write(dir.path(), name, &src);
        let (out, err) = check(dir.path(), &[name]);
        assert_capped(&out, &err, name, "E0022");
    }
}

#[test]
fn array_types_at_the_cap_are_accepted() {
    let dir = tempfile::tempdir().unwrap();
    let src = format!(
        "PROGRAM p\nVAR x : {}INT; n : INT; END_VAR\n  LD n\n  ST n\nEND_PROGRAM\n",
        "ARRAY [0..1] OF ".repeat(il_frontend::parser::MAX_TYPE_NESTING)
    );
    write(dir.path(), "at_cap.il", &src);
    let (out, err) = check(dir.path(), &["at_cap.il"]);
    assert!(!err.contains("E0211"), "{err}");
    assert!(matches!(out.status.code(), Some(0 | 1)), "{err}");
}

#[test]
fn initializers_nested_100000_deep_are_e0212() {
    let dir = tempfile::tempdir().unwrap();
    for (name, init) in [
        (
            "brackets.il",
            format!("{}1{}", "[".repeat(LEVELS), "]".repeat(LEVELS)),
        ),
        (
            "repeats.il",
            format!("[{}1{}]", "2([".repeat(LEVELS), "])".repeat(LEVELS)),
        ),
        (
            "structs.il",
            format!("{}1{}", "(a := ".repeat(LEVELS), ")".repeat(LEVELS)),
        ),
    ] {
        let src = format!(
            "PROGRAM p\nVAR x : ARRAY [0..1] OF INT := {init}; n : INT; END_VAR\n  LD n\n  ST n\nEND_PROGRAM\n"
        );
        write(dir.path(), name, &src);
        let (out, err) = check(dir.path(), &[name]);
        assert_capped(&out, &err, name, "E0212");
    }
}

#[test]
fn template_elements_nested_100000_deep_are_e0210() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "main.il",
        "PROGRAM p\nVAR n : INT; END_VAR\n  LD n\n  ST n\nEND_PROGRAM\n",
    );
    std::fs::create_dir(dir.path().join("tpl")).unwrap();
    let text = format!(
        "<?xml version=\"1.0\"?>\n<blockTemplate name=\"ACME_Deep\" funcNum=\"90\">{}{}</blockTemplate>\n",
        "<a>".repeat(LEVELS),
        "</a>".repeat(LEVELS)
    );
    write(&dir.path().join("tpl"), "ACME_Deep.xml", &text);
    let (out, err) = check(dir.path(), &["--templates", "tpl", "main.il"]);
    assert_capped(&out, &err, "tpl/ACME_Deep.xml", "E0210");
}

#[test]
fn st_statements_parentheses_and_operators_nested_100000_deep_are_e0108() {
    let dir = tempfile::tempdir().unwrap();
    for (name, body) in [
        (
            "ifs.st",
            format!(
                "{}n := 1;{}",
                "IF b THEN ".repeat(LEVELS),
                " END_IF;".repeat(LEVELS)
            ),
        ),
        (
            "whiles.st",
            format!(
                "{}n := 1;{}",
                "WHILE b DO ".repeat(LEVELS),
                " END_WHILE;".repeat(LEVELS)
            ),
        ),
        (
            "parens.st",
            format!("n := {}1{};", "(".repeat(LEVELS), ")".repeat(LEVELS)),
        ),
        ("nots.st", format!("b := {}b;", "NOT ".repeat(LEVELS))),
        ("minus.st", format!("n := {}1;", "- ".repeat(LEVELS))),
        (
            "index.st",
            format!("n := {}0{};", "a[".repeat(LEVELS), "]".repeat(LEVELS)),
        ),
        (
            "calls.st",
            format!("n := {}1{};", "ABS(".repeat(LEVELS), ")".repeat(LEVELS)),
        ),
    ] {
        let src = format!(
            "PROGRAM p\nVAR n : INT; b : BOOL; a : ARRAY [0..9] OF INT; END_VAR\n{body}\nEND_PROGRAM\n"
        );
        write(dir.path(), name, &src);
        let (out, err) = check(dir.path(), &[name]);
        assert_capped(&out, &err, name, "E0108");
    }
}

/// An SFC chart whose steps are joined through 50,000 simultaneous convergences before its transition
/// and 50,000 simultaneous divergences after it (100,000 elements, 27 MB at 100,000 each): the chart is walked with explicit stacks, so the
/// chain is no depth at all (a recursive walk overflowed the stack). XML element nesting itself is
/// capped at 256 (`ladder_compiler::xml::MAX_DEPTH`); a chain like this is flat in the file.
#[test]
fn an_sfc_chain_of_100000_divergences_is_walked_without_recursion() {
    let dir = tempfile::tempdir().unwrap();
    let mut els = String::from(
        "<step localId=\"1\" name=\"Init\" initialStep=\"true\"><connectionPointOut/></step>\n",
    );
    let chain = LEVELS / 2;
    let mut prev = 1;
    for i in 0..chain {
        let id = 2 + i;
        els.push_str(&format!("<simultaneousConvergence localId=\"{id}\"><connectionPointIn><connection refLocalId=\"{prev}\"/></connectionPointIn></simultaneousConvergence>\n"));
        prev = id;
    }
    let t = chain + 2;
    els.push_str(&format!("<transition localId=\"{t}\"><connectionPointIn><connection refLocalId=\"{prev}\"/></connectionPointIn><condition><inline name=\"\"><IL><xhtml:p><![CDATA[LD go]]></xhtml:p></IL></inline></condition></transition>\n"));
    prev = t;
    for i in 0..chain {
        let id = t + 1 + i;
        els.push_str(&format!("<simultaneousDivergence localId=\"{id}\"><connectionPointIn><connection refLocalId=\"{prev}\"/></connectionPointIn></simultaneousDivergence>\n"));
        prev = id;
    }
    els.push_str(&format!("<jumpStep localId=\"{}\" targetName=\"Init\"><connectionPointIn><connection refLocalId=\"{prev}\"/></connectionPointIn></jumpStep>\n", prev + 1));
    let xml = format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
<fileHeader companyName="x" productName="x" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
<contentHeader name="t"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
<types><dataTypes/><pous>
<pou name="Seq" pouType="program"><interface><localVars>
<variable name="go"><type><BOOL/></type></variable>
</localVars></interface>
<body><SFC>
{els}</SFC></body></pou>
</pous></types></project>
"#
    );
    write(dir.path(), "chain.xml", &xml);
    let (out, err) = check(dir.path(), &["chain.xml"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        &err[..err.len().min(2000)]
    );
}

#[test]
fn xml_elements_nested_100000_deep_are_capped() {
    let dir = tempfile::tempdir().unwrap();
    let xml = format!(
        "<?xml version=\"1.0\"?>\n<project>{}{}</project>\n",
        "<a>".repeat(LEVELS),
        "</a>".repeat(LEVELS)
    );
    write(dir.path(), "deep.xml", &xml);
    let (out, err) = check(dir.path(), &["deep.xml"]);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("nested deeper than"), "{err}");
}

#[test]
fn alias_chains_of_100000_names_are_e0213() {
    let dir = tempfile::tempdir().unwrap();
    let mut src = String::from("TYPE\n");
    for i in 0..LEVELS {
        src.push_str(&format!("t{i} : t{};\n", i + 1));
    }
    src.push_str(&format!(
        "t{LEVELS} : INT;\nEND_TYPE\nPROGRAM p\nVAR x : t0; END_VAR\n  LD x\n  ST x\nEND_PROGRAM\n"
    ));
    write(dir.path(), "aliases.il", &src);
    let (out, err) = check(dir.path(), &["aliases.il"]);
    assert_capped(&out, &err, "aliases.il", "E0213");
}

#[test]
fn named_array_types_100000_deep_are_e0211_or_e0213() {
    let dir = tempfile::tempdir().unwrap();
    // Declared outermost first, the chain is an alias chain (E0213); innermost first, each alias resolves
    // at once and the array nesting grows through the names (E0211).
    let mut forward = String::from("TYPE\n");
    for i in 0..LEVELS {
        forward.push_str(&format!("a{i} : ARRAY [0..1] OF a{};\n", i + 1));
    }
    forward.push_str(&format!("a{LEVELS} : INT;\nEND_TYPE\n"));
    let mut backward = format!("TYPE\na{LEVELS} : INT;\n");
    for i in (0..LEVELS).rev() {
        backward.push_str(&format!("a{i} : ARRAY [0..1] OF a{};\n", i + 1));
    }
    backward.push_str("END_TYPE\n");
    for (name, types, code) in [
        ("forward.il", forward, "E0213"),
        ("backward.il", backward, "E0211"),
    ] {
        let src = format!(
            "{types}PROGRAM p\nVAR x : a0; n : INT; END_VAR\n  LD n\n  ST n\nEND_PROGRAM\n"
        );
        write(dir.path(), name, &src);
        let (out, err) = check(dir.path(), &[name]);
        assert_capped(&out, &err, name, code);
    }
}

#[test]
fn structs_and_fb_instances_contained_100000_deep_are_e0214() {
    let dir = tempfile::tempdir().unwrap();
    let mut structs = String::from("TYPE\n");
    for i in 0..LEVELS {
        structs.push_str(&format!("s{i} : STRUCT a : s{}; END_STRUCT;\n", i + 1));
    }
    structs.push_str(&format!(
        "s{LEVELS} : STRUCT a : INT; END_STRUCT;\nEND_TYPE\nPROGRAM p\nVAR x : s0; n : INT; END_VAR\n  LD n\n  ST n\nEND_PROGRAM\n"
    ));
    write(dir.path(), "structs.il", &structs);
    let (out, err) = check(dir.path(), &["structs.il"]);
    assert_capped(&out, &err, "structs.il", "E0214");
    let mut fbs = String::new();
    for i in 0..LEVELS {
        fbs.push_str(&format!(
            "FUNCTION_BLOCK f{i}\nVAR x : f{}; END_VAR\n  LD 1\nEND_FUNCTION_BLOCK\n",
            i + 1
        ));
    }
    fbs.push_str(&format!(
        "FUNCTION_BLOCK f{LEVELS}\nVAR x : INT; END_VAR\n  LD 1\n  ST x\nEND_FUNCTION_BLOCK\nPROGRAM p\nVAR x : f0; END_VAR\n  LD 1\nEND_PROGRAM\n"
    ));
    write(dir.path(), "fbs.il", &fbs);
    let (out, err) = check(dir.path(), &["fbs.il"]);
    assert_capped(&out, &err, "fbs.il", "E0214");
}

#[test]
fn structs_contained_at_the_cap_are_accepted() {
    let dir = tempfile::tempdir().unwrap();
    // The program holding `x : s0` is the outermost level: n - 1 structs below it.
    let n = il_frontend::sema::nesting::MAX_CONTAINMENT - 1;
    let mut src = String::from("TYPE\n");
    for i in 0..n - 1 {
        src.push_str(&format!("s{i} : STRUCT a : s{}; END_STRUCT;\n", i + 1));
    }
    src.push_str(&format!(
        "s{} : STRUCT a : INT; END_STRUCT;\nEND_TYPE\nPROGRAM p\nVAR x : s0; n : INT; END_VAR\n  LD n\n  ST n\nEND_PROGRAM\n",
        n - 1
    ));
    write(dir.path(), "at_cap.il", &src);
    let (out, err) = check(dir.path(), &["at_cap.il"]);
    assert_eq!(out.status.code(), Some(0), "{err}");
}

/// The drive-script language has no nesting to recurse over (a value is `a`, `a op b`, `-a` or `~a`;
/// no parentheses; at most 4 conditions and 8 actions per statement): its compiler is flat loops over
/// tokens. 100,000 parentheses, operators or signs are one located E6010 each statement, never deeper.
#[test]
fn drive_scripts_with_100000_parentheses_or_operators_are_e6010() {
    let dir = tempfile::tempdir().unwrap();
    let head = "S:: PARAM;\nS:: INIT;\nS:: MOTION 0;\nS:: EVENT 0;\n";
    for (name, cond) in [
        (
            "parens.ds",
            format!("{}DI_0{}", "(".repeat(LEVELS), ")".repeat(LEVELS)),
        ),
        ("chain.ds", format!("DI_0{}", " + DI_0".repeat(LEVELS))),
        ("signs.ds", format!("{}DI_0", "~".repeat(LEVELS))),
    ] {
        write(
            dir.path(),
            name,
            &format!("{head}S:: IF {cond};\nS:: THEN DO_0=HIGH;\n"),
        );
        let t = Instant::now();
        let out = ladderc()
            .args([
                "drive",
                "build",
                "--message-format",
                "short",
                name,
                "-o",
                "x.img",
            ])
            .current_dir(dir.path())
            .output()
            .unwrap();
        assert!(t.elapsed() < LIMIT, "took {:?}", t.elapsed());
        let err = String::from_utf8_lossy(&out.stderr).into_owned();
        assert_capped(&out, &err, name, "E6010");
    }
}

#[test]
fn il_subscripts_nested_100000_deep_are_one_e0200() {
    // `LD a[a[a[...]]]`: the semantic checks resolve subscripts recursively, and 2,500 levels overflowed
    // the stack (found in session 24 by the perf-il2 helper; the fuzzers never grew an input that deep).
    // The layout pass now skips a `[` past the cap with everything up to its `]`, reported once.
    let dir = tempfile::tempdir().unwrap();
    let deep = format!("{}0{}", "a[".repeat(LEVELS), "]".repeat(LEVELS));
    let cases = [
        (
            "load.il",
            format!("PROGRAM p\nVAR a : ARRAY[0..9] OF INT; x : INT; END_VAR\n  LD {deep}\n  ST x\nEND_PROGRAM\n"),
        ),
        (
            "call.il",
            format!(
                "PROGRAM p\nVAR a : ARRAY[0..9] OF INT; t : TON; END_VAR\n  CAL t(IN := TRUE, PT := T#1s)\n  LD t.Q\n  ST a[{deep}]\nEND_PROGRAM\n"
            ),
        ),
        (
            "body.xml",
            format!(
                r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous>
<pou name="p" pouType="program"><interface><localVars>
<variable name="a"><type><array><dimension lower="0" upper="9"/><baseType><INT/></baseType></array></type></variable>
<variable name="x"><type><INT/></type></variable>
</localVars></interface><body><IL><xhtml xmlns="http://www.w3.org/1999/xhtml">
LD {deep}
ST x
</xhtml></IL></body></pou></pous></types></project>
"#
            ),
        ),
    ];
    for (name, src) in cases {
        write(dir.path(), name, &src);
        let (out, err) = check(dir.path(), &[name]);
        assert_capped(&out, &err, name, "E0200");
        assert!(
            err.contains("subscripts are nested more than 64 deep"),
            "{err}"
        );
    }
}

#[test]
fn il_subscripts_at_the_cap_are_accepted() {
    let dir = tempfile::tempdir().unwrap();
    let n = il_frontend::layout::MAX_SUBSCRIPT_NESTING;
    let at_cap = format!("{}0{}", "a[".repeat(n), "]".repeat(n));
    let src = format!(
        "PROGRAM p\nVAR a : ARRAY[0..9] OF INT; x : INT; END_VAR\n  LD {at_cap}\n  ST x\n  LD a[{at_cap}]\n  ST x\nEND_PROGRAM\n"
    );
    write(dir.path(), "at_cap.il", &src);
    let (out, err) = check(dir.path(), &["at_cap.il"]);
    // 64 levels are accepted; the second load nests 65 and is the one report
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert_eq!(err.matches("[E0200]").count(), 1, "{err}");
    assert!(
        err.contains("at_cap.il:5:"),
        "the report is on line 5, the 65-deep load:\n{err}"
    );
}
