//! Hostile input through the `ladderc` binary (issue #12, points 1-4): depth and length that used to
//! overflow the stack or run quadratic, output that used to grow without bound, multi-byte text that
//! used to be sliced inside a character, and data sizes that used to fail only at link time. Every
//! run must end with exit 0, 1 or 2 (never a panic or a signal) and bounded output.

mod common;

use common::ladderc;
use std::path::Path;
use std::process::Output;

fn write(dir: &Path, name: &str, text: &str) -> std::path::PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn run(args: &[&str], files: &[&Path]) -> Output {
    let out = ladderc().args(args).args(files).output().unwrap();
    assert!(
        matches!(out.status.code(), Some(0..=2)),
        "exit {:?} (a panic is 101, a signal none): {}",
        out.status,
        String::from_utf8_lossy(&out.stderr[..out.stderr.len().min(4000)])
    );
    out
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// An XML project with one PROGRAM `main` (INT a, BOOL b, REAL r) whose body is `body` (an `<ST>`,
/// `<LD>` or `<FBD>` element).
fn project(body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
<fileHeader companyName="x" productName="x" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
<contentHeader name="t"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
<types><dataTypes/><pous>
<pou name="main" pouType="program"><interface><localVars>
<variable name="a"><type><INT/></type></variable>
<variable name="b"><type><BOOL/></type></variable>
<variable name="r"><type><REAL/></type></variable>
</localVars></interface>
<body>{body}</body></pou>
</pous></types></project>
"#
    )
}

fn st(text: &str) -> String {
    project(&format!("<ST><xhtml:p><![CDATA[{text}]]></xhtml:p></ST>"))
}

fn nested_il(levels: usize) -> String {
    let mut s = String::from("PROGRAM p\nVAR a : INT; END_VAR\nLD a\n");
    s.push_str(&"ADD( a\n".repeat(levels));
    s.push_str(&")\n".repeat(levels));
    s.push_str("ST a\nEND_PROGRAM\n");
    s
}

// ------------------------------------------------------------------------------ 1. depth and length

/// One ST program `main` with `x : T` and `a : T := init` whose body is `x := expr;` (line 3).
fn st_assign(ty: &str, init: &str, expr: &str) -> String {
    format!(
        "PROGRAM main\nVAR x : {ty}; a : {ty} := {init}; END_VAR\n  x := {expr};\nEND_PROGRAM\n"
    )
}

/// Where the 1,001st operation starts in `expr`, as the 1-based column of line 3 of [`st_assign`].
fn column_of_operation(expr: &str, op: &str, n: usize) -> usize {
    let (i, _) = expr.match_indices(op).nth(n - 1).unwrap();
    "  x := ".len() + i + 1
}

#[test]
fn an_expression_of_more_than_1000_operations_is_e0109_and_one_of_1000_runs() {
    // cc -O2 is superlinear in one long function: 100,000 mixed DINT operators took over 4 minutes,
    // 90,000 nested ABS calls over 2 (the C itself is linear, one line per operation)
    let dir = tempfile::tempdir().unwrap();
    let ops = ["+", "-", "*", "/", "MOD"];
    let mixed: String = (0..100_000).fold(String::from("a"), |mut s, i| {
        s.push_str(&format!(" {} a", ops[i % 5]));
        s
    });
    let abs = format!("{}a{}", "ABS(".repeat(120), ")".repeat(120));
    // (name, type, initial value, expression, the text before each operation, which of them is the
    // 1,001st operation)
    let cases = [
        (
            "plus",
            "INT",
            "1",
            vec!["a"; 100_000].join(" + "),
            " + ",
            1001,
        ),
        (
            "and",
            "BOOL",
            "TRUE",
            vec!["a"; 100_000].join(" AND "),
            " AND ",
            1001,
        ),
        // every other space precedes an operator
        ("mixed", "DINT", "1", mixed, " ", 2001),
        // 120 calls (within the 128 levels of nesting E0108 allows) and one `+` per term: the
        // 1,001st operation is the 33rd call of the 9th term
        (
            "calls",
            "INT",
            "1",
            vec![abs.as_str(); 600].join(" + "),
            "ABS(",
            8 * 120 + 33,
        ),
    ];
    for (name, ty, init, expr, op, n) in cases {
        let src = write(
            dir.path(),
            &format!("{name}.st"),
            &st_assign(ty, init, &expr),
        );
        let out = run(&["check", "--message-format", "short"], &[&src]);
        assert_eq!(out.status.code(), Some(1), "{name}");
        let err = stderr(&out);
        let col = column_of_operation(&expr, op, n) + usize::from(op.starts_with(' '));
        assert!(
            err.contains(&format!("{name}.st:3:{col}: error[E0109]")),
            "{name}: {err}"
        );
        assert_eq!(err.matches("error[").count(), 1, "{name}: {err}");
    }
    // array indexes count: 600 `v[0]` and 599 `+`, the 1,001st operation is the 501st `[`
    let expr = vec!["v[0]"; 600].join(" + ");
    let src = write(
        dir.path(),
        "index.st",
        &format!("PROGRAM main\nVAR x : INT; v : ARRAY[0..1] OF INT; END_VAR\n  x := {expr};\nEND_PROGRAM\n"),
    );
    let out = run(&["check", "--message-format", "short"], &[&src]);
    let col = column_of_operation(&expr, "[", 501);
    assert!(
        stderr(&out).contains(&format!("index.st:3:{col}: error[E0109]")),
        "{}",
        stderr(&out)
    );
    // at the cap: 1,000 additions build and run (x = 1,001)
    let src = write(
        dir.path(),
        "cap.st",
        &st_assign("INT", "1", &vec!["a"; 1001].join(" + ")),
    );
    let out = run(&["run", "--cycles", "1", "--watch", "main.x"], &[&src]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(String::from_utf8_lossy(&out.stdout).contains("0,0,1001"));
    // an XML <expression> is the same ST expression: the cap holds there too
    let xml = write(
        dir.path(),
        "e.xml",
        &st(&format!("a := {};", vec!["a"; 5000].join(" + "))),
    );
    let out = run(&["check", "--message-format", "short"], &[&xml]);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("error[E0109]"), "{}", stderr(&out));
}

#[test]
fn il_nested_100000_deep_is_e0200() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(dir.path(), "deep.il", &nested_il(100_000));
    let out = run(&["--message-format", "short", "check"], &[&src]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(err.contains("deep.il:2004:1: error[E0200]"), "{err}");
}

#[test]
fn c_for_deeply_nested_lists_grows_linearly_and_runs() {
    // 1,000 levels (half the limit): before, every level indented its lines 4 more spaces, 20 MB of C
    let dir = tempfile::tempdir().unwrap();
    let il = nested_il(1000).replace("VAR a : INT;", "VAR a : INT := 1;");
    let src = write(dir.path(), "deep.il", &il);
    let out = run(&["build", "-o"], &[&dir.path().join("out"), &src]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let c = std::fs::read_to_string(dir.path().join("out/program.c")).unwrap();
    let widest = c.lines().map(|l| l.len() - l.trim_start().len()).max();
    assert!(
        widest <= Some(16 * 4),
        "indentation stops at 16 levels: {widest:?}"
    );
    assert!(
        c.len() < 100 * il.len(),
        "{} bytes of C for {} of IL",
        c.len(),
        il.len()
    );
    let out = run(&["run", "--cycles", "1", "--watch", "p.a"], &[&src]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    // a := a + (a + (... + a)): 1,001 ones
    let trace = String::from_utf8_lossy(&out.stdout);
    assert!(trace.contains(",1001"), "{trace}");
}

#[test]
fn a_rung_of_3000_contacts_in_series_is_e3200() {
    let mut el = vec![r#"<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>"#.to_string()];
    let n = 3000;
    for i in 0..n {
        el.push(format!(r#"<contact localId="{}" negated="false"><position x="{i}" y="0"/><connectionPointIn><connection refLocalId="{}"/></connectionPointIn><connectionPointOut/><variable>b</variable></contact>"#, i + 2, i + 1));
    }
    el.push(format!(r#"<coil localId="{}" negated="false"><position x="{n}" y="0"/><connectionPointIn><connection refLocalId="{}"/></connectionPointIn><connectionPointOut/><variable>b</variable></coil>"#, n + 2, n + 1));
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "rung.xml",
        &project(&format!("<LD>{}</LD>", el.join("\n"))),
    );
    let out = run(&["--message-format", "short", "check"], &[&src]);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("error[E3200]"), "{}", stderr(&out));
}

#[test]
fn a_lattice_of_contacts_each_fed_by_the_two_before_lowers_in_linear_time_and_runs() {
    // Contact k is fed by contacts k-1 and k-2 (a wired OR): the lowering walked every shared value
    // again from each reader, Fibonacci(k) walks; 60 contacts ran for minutes.
    let n = 300;
    let mut el = vec![r#"<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>"#.to_string()];
    for i in 0..n {
        let mut refs = format!(r#"<connection refLocalId="{}"/>"#, i + 1);
        if i >= 1 {
            refs.push_str(&format!(r#"<connection refLocalId="{i}"/>"#));
        }
        el.push(format!(r#"<contact localId="{}" negated="true"><position x="{i}" y="0"/><connectionPointIn>{refs}</connectionPointIn><connectionPointOut/><variable>b</variable></contact>"#, i + 2));
    }
    el.push(format!(r#"<coil localId="{}" negated="false"><position x="{n}" y="0"/><connectionPointIn><connection refLocalId="{}"/></connectionPointIn><connectionPointOut/><variable>b</variable></coil>"#, n + 2, n + 1));
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "lattice.xml",
        &project(&format!("<LD>{}</LD>", el.join("\n"))),
    );
    // b is FALSE, every negated contact passes power: the coil sets b
    let out = run(&["run", "--cycles", "1", "--watch", "main.b"], &[&src]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let trace = String::from_utf8_lossy(&out.stdout);
    assert!(trace.lines().any(|l| l.ends_with(",1")), "{trace}");
}

#[test]
fn an_fbd_expression_of_indexes_nested_100000_deep_is_a_diagnostic() {
    // `x[x[x[...]]]` in an FBD `<expression>`: the reader of variable accesses recursed per `[` and
    // overflowed the stack at 5,000 levels.
    let n = 100_000;
    let body = format!(
        r#"<FBD><inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>{}1{}</expression></inVariable>
<outVariable localId="2"><position x="1" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><expression>a</expression></outVariable></FBD>"#,
        "a[".repeat(n),
        "]".repeat(n)
    );
    let dir = tempfile::tempdir().unwrap();
    let src = write(dir.path(), "index.xml", &project(&body));
    let out = run(&["--message-format", "short", "check"], &[&src]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(stderr(&out).contains("error[E3011]"), "{}", stderr(&out));
    // the message quotes the expression: clipped to 1,000 characters
    assert!(stderr(&out).len() < 10_000, "{} bytes", stderr(&out).len());
}

#[test]
fn a_loop_of_20000_contacts_is_one_bounded_e3010() {
    // The loop's E3010 labelled every element: 4.8 MB of human output for 20,000 (24 MB for
    // 100,000). A loop of function boxes runs since round 32 (the box evaluated first reads the
    // other's previous result, `tests/tests/fbd_r32_run.rs`): contacts hold no value, so a loop of
    // them stays E3010.
    let n = 20_000;
    let mut el = vec![r#"<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut/></leftPowerRail>"#.to_string()];
    for k in 0..n {
        let src = if k == 0 {
            format!(
                r#"<connection refLocalId="1"/><connection refLocalId="{}"/>"#,
                n + 1
            )
        } else {
            format!(r#"<connection refLocalId="{}"/>"#, k + 1)
        };
        el.push(format!(r#"<contact localId="{}"><position x="0" y="0"/><connectionPointIn>{src}</connectionPointIn><variable>b</variable></contact>"#, k + 2));
    }
    el.push(format!(r#"<coil localId="{}"><position x="1" y="0"/><connectionPointIn><connection refLocalId="{}"/></connectionPointIn><variable>b</variable></coil>"#, n + 2, n + 1));
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "loop.xml",
        &project(&format!("<LD>{}</LD>", el.join("\n"))),
    );
    for format in ["human", "json"] {
        let out = run(&["--message-format", format, "check"], &[&src]);
        assert_eq!(out.status.code(), Some(1), "{format}");
        let err = stderr(&out);
        assert!(
            err.contains("E3010"),
            "{format}: {}",
            &err[..err.len().min(2000)]
        );
        assert!(
            err.contains("at most 64 labels"),
            "{format}: {}",
            &err[..err.len().min(2000)]
        );
        assert!(err.len() < 100_000, "{format}: {} bytes", err.len());
    }
}

#[test]
fn an_sfc_of_30000_steps_in_a_loop_is_lowered_in_linear_time() {
    // Each transition looked at every earlier one for a shared step, and each step at every
    // transition: 50,000 steps took minutes. Now one pass each.
    let n = 30_000;
    let cond = r#"<condition><inline name=""><ST><xhtml:p><![CDATA[b]]></xhtml:p></ST></inline></condition>"#;
    let mut els = vec![
        r#"<step localId="1" name="S0" initialStep="true"><connectionPointOut/></step>"#
            .to_string(),
    ];
    let (mut id, mut prev) = (2, 1);
    for k in 1..n {
        els.push(format!(r#"<transition localId="{id}"><connectionPointIn><connection refLocalId="{prev}"/></connectionPointIn>{cond}</transition>"#));
        els.push(format!(r#"<step localId="{}" name="S{k}"><connectionPointIn><connection refLocalId="{id}"/></connectionPointIn><connectionPointOut/></step>"#, id + 1));
        prev = id + 1;
        id += 2;
    }
    els.push(format!(r#"<transition localId="{id}"><connectionPointIn><connection refLocalId="{prev}"/></connectionPointIn>{cond}</transition>"#));
    els.push(format!(r#"<jumpStep localId="{}" targetName="S0"><connectionPointIn><connection refLocalId="{id}"/></connectionPointIn></jumpStep>"#, id + 1));
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "steps.xml",
        &project(&format!("<SFC>{}</SFC>", els.join("\n"))),
    );
    let out = run(&["--message-format", "short", "check"], &[&src]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
}

#[test]
fn an_enumeration_of_100000_values_is_checked_in_linear_time() {
    // Each value was compared with every earlier one (duplicate check): minutes for 100,000.
    let values: Vec<String> = (0..100_000).map(|k| format!("e{k}")).collect();
    let src = format!(
        "TYPE E : ({}, E5); END_TYPE\nPROGRAM p\nVAR a : INT; x : E; END_VAR\na := 1;\nEND_PROGRAM\n",
        values.join(", ")
    );
    let dir = tempfile::tempdir().unwrap();
    let path = write(dir.path(), "enum.st", &src);
    let out = run(&["--message-format", "short", "check"], &[&path]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("error[E1002]: enumerated value `E5` is declared twice"),
        "{}",
        stderr(&out)
    );
}

// ------------------------------------------------------------------------------ 2. characters

#[test]
fn a_block_type_with_a_multibyte_character_is_a_diagnostic() {
    let body = r#"<FBD><inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>b</expression></inVariable>
<block localId="2" instanceName="t" typeName="T€ON"><position x="1" y="0"/><inputVariables><variable formalParameter="IN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable></inputVariables><inOutVariables/><outputVariables><variable formalParameter="Q"><connectionPointOut/></variable></outputVariables></block></FBD>"#;
    let dir = tempfile::tempdir().unwrap();
    let src = write(dir.path(), "blk.xml", &project(body));
    let out = run(&["check"], &[&src]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
}

/// Checks every span of every JSON diagnostic: inside its file and on character boundaries.
fn assert_spans_on_boundaries(out: &Output, what: &str) {
    for line in String::from_utf8_lossy(&out.stderr).lines() {
        let Ok(v) = serde_json::from_str::<serde_json::Value>(line) else {
            continue;
        };
        let mut spans = vec![(
            v["path"].clone(),
            v["byte_start"].clone(),
            v["byte_end"].clone(),
        )];
        for l in v["labels"].as_array().into_iter().flatten() {
            spans.push((
                l["path"].clone(),
                l["byte_start"].clone(),
                l["byte_end"].clone(),
            ));
        }
        for (path, s, e) in spans {
            let (Some(path), Some(s), Some(e)) = (path.as_str(), s.as_u64(), e.as_u64()) else {
                continue;
            };
            let text = std::fs::read(path).unwrap();
            let text = String::from_utf8_lossy(&text);
            let (s, e) = (s as usize, e as usize);
            assert!(
                s <= e && e <= text.len() && text.is_char_boundary(s) && text.is_char_boundary(e),
                "{what}: span {s}..{e} of {} bytes off a character boundary: {line}",
                text.len()
            );
        }
    }
}

/// Seeds of every text front end, each with multi-byte characters put in at many places.
#[test]
fn every_span_of_every_front_end_lies_on_character_boundaries() {
    let il = "PROGRAM p\nVAR a : INT; s : STRING; END_VAR\nLD a\nADD( 1\nMUL 2\n)\nST a\nLD 'x'\nST s\nJMPC l\nl: LD a\nEND_PROGRAM\n";
    let st_text = "a := (a + 1) * 2; IF b THEN r := r ** 2.0; END_IF; {pragma} (* c *) a := -a;";
    let xml_st = st(st_text);
    let drive = "S:: PARAM;\nS:: P0 = 10000;\nS:: INIT;\nS:: Velocity = 100000;\nS:: MOTION 0;\nS:: EVENT 0;\nS:: IF DI_0 = HIGH AND MotionDone;\nS:: THEN DO_0=HIGH AND RelativeTargetPosition=P0;\n";
    let seeds: [(&str, &str, &[&str]); 4] = [
        ("h.il", il, &["check"]),
        ("h.xml", &xml_st, &["check"]),
        ("h.drive", drive, &["drive", "build", "-o", "/dev/null"]),
        ("h2.xml", &xml_st, &["build", "--emit", "il"]),
    ];
    let dir = tempfile::tempdir().unwrap();
    let mut runs = 0;
    for (name, seed, cmd) in seeds {
        let bounds: Vec<usize> = (0..=seed.len())
            .filter(|&i| seed.is_char_boundary(i))
            .collect();
        for (k, &at) in bounds.iter().enumerate().step_by(bounds.len() / 40 + 1) {
            let ch = ["€", "é", "🗻", "\u{FEFF}", "{€", "(*é", "'€", "%I€"][k % 8];
            let text = format!("{}{ch}{}", &seed[..at], &seed[at..]);
            let src = write(dir.path(), name, &text);
            let mut args = vec!["--message-format", "json"];
            args.extend_from_slice(cmd);
            let out = run(&args, &[&src]);
            assert_spans_on_boundaries(&out, &format!("{name} with {ch:?} at {at}"));
            runs += 1;
        }
    }
    assert!(runs > 100);
}

#[test]
fn json_byte_offsets_count_a_byte_order_mark_of_the_file() {
    // The BOM is dropped from the text (line and column count from the character after it), but
    // `byte_start`/`byte_end` are offsets into the file: they were 3 short.
    let dir = tempfile::tempdir().unwrap();
    let il = "\u{feff}PROGRAM p\nVAR a : INT; END_VAR\nLD zz\nEND_PROGRAM\n";
    let xml = format!("\u{feff}{}", st("a := zz;"));
    for (name, text) in [("bom.il", il.to_string()), ("bom.xml", xml)] {
        let src = write(dir.path(), name, &text);
        let out = run(&["--message-format", "json", "check"], &[&src]);
        let err = stderr(&out);
        let v: serde_json::Value = serde_json::from_str(err.lines().next().unwrap()).unwrap();
        assert_eq!(v["code"], "E1001", "{err}");
        let start = v["byte_start"].as_u64().unwrap() as usize;
        assert_eq!(&text.as_bytes()[start..start + 2], b"zz", "{name}: {err}");
        let line = text
            .lines()
            .nth(v["line"].as_u64().unwrap() as usize - 1)
            .unwrap();
        let col = v["column"].as_u64().unwrap() as usize;
        assert_eq!(line.chars().nth(col - 1), Some('z'), "{name}: {err}");
    }
}

#[test]
fn an_unterminated_pragma_before_a_multibyte_character_ends_on_a_boundary() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(dir.path(), "p.xml", &st("a := 1; {€"));
    let out = run(&["--message-format", "json", "check"], &[&src]);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("\"E0102\""), "{}", stderr(&out));
    assert_spans_on_boundaries(&out, "pragma");
}

/// A pragma whose 40th byte after its `{` falls inside a multibyte character (`{attribute 'x...'`
/// followed by accented letters): its kind is told from whole characters; before, the lexer sliced
/// the text inside the character and panicked (found by mutating the fixtures).
#[test]
fn a_pragma_with_a_multibyte_character_at_its_40th_byte_is_read_whole() {
    let dir = tempfile::tempdir().unwrap();
    let pragma = format!("{{attribute '{}\u{e9}\u{e9}\u{e9}' }}", "x".repeat(26));
    assert!(
        !pragma[1..].is_char_boundary(40),
        "the 40th byte must fall inside a character"
    );
    let text = format!("PROGRAM Main\nVAR n : INT; END_VAR\n{pragma}\nn := n + 1;\nEND_PROGRAM\n");
    let src = write(dir.path(), "p.st", &text);
    let out = run(&["--message-format", "short", "check"], &[&src]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("p.st:3:1: note[W0301]"), "{err}");
}

// ------------------------------------------------------------------------------ 3. bounded output

#[test]
fn many_errors_show_the_first_fifty_per_file_and_count_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "many.il",
        &format!(
            "PROGRAM p\nVAR a : INT; END_VAR\nLD a\n{}END_PROGRAM\n",
            // (5000 names: an undeclared name is reported once per POU)
            (0..5000)
                .map(|k| format!("ST nope{k}\n"))
                .collect::<String>()
        ),
    );
    let out = run(&["check"], &[&src]);
    let err = stderr(&out);
    assert_eq!(err.matches("error[E1001]").count(), 50, "{err}");
    assert!(err.contains("4950 more diagnostics in"), "{err}");
    assert!(err.len() < 40_000, "{} bytes", err.len());

    let out = run(
        &[
            "--message-format",
            "short",
            "--max-diagnostics",
            "3",
            "check",
        ],
        &[&src],
    );
    let err = stderr(&out);
    assert_eq!(err.lines().count(), 4, "{err}");
    let out = run(
        &[
            "--message-format",
            "short",
            "--max-diagnostics",
            "0",
            "check",
        ],
        &[&src],
    );
    assert_eq!(stderr(&out).matches("error[E1001]").count(), 5000);
    let out = run(&["--message-format", "json", "check"], &[&src]);
    let json = stderr(&out);
    assert_eq!(
        json.lines()
            .filter(|l| l.contains("\"kind\":\"diagnostic\""))
            .count(),
        1000,
        "JSON shows the first 1,000 diagnostics per file"
    );
    let summary = json.lines().last().unwrap_or("");
    assert!(
        summary.contains("\"kind\":\"summary\"") && summary.contains("\"errors\":5000"),
        "then the summary record, which counts them all: {summary}"
    );
    let out = run(
        &[
            "--message-format",
            "json",
            "--max-diagnostics",
            "0",
            "check",
        ],
        &[&src],
    );
    assert_eq!(
        stderr(&out)
            .lines()
            .filter(|l| l.contains("\"kind\":\"diagnostic\""))
            .count(),
        5000,
        "--max-diagnostics 0 shows every diagnostic in JSON too"
    );
}

#[test]
fn json_output_of_100000_errors_on_long_lines_stays_bounded() {
    // 100,000 conditional jumps on an INT (E1023 each), every line padded with a wide comment: JSON
    // lines printed every diagnostic, 38 MB for 2.8 MB of IL; the short and human formats cap at 50.
    let dir = tempfile::tempdir().unwrap();
    let n = 100_000;
    let mut il = String::from("PROGRAM p\nVAR a : INT; END_VAR\n");
    for k in 0..n {
        il.push_str(&format!("L{k}: LD a\nJMPC L{} (* ü€ *)\n", (k * 7919) % n));
    }
    il.push_str("END_PROGRAM\n");
    let src = write(dir.path(), "jumps.il", &il);
    for format in ["human", "short", "json"] {
        let out = run(&["--message-format", format, "check"], &[&src]);
        assert_eq!(out.status.code(), Some(1), "{format}");
        let err = stderr(&out);
        assert!(
            err.contains("E1023"),
            "{format}: {}",
            &err[..err.len().min(2000)]
        );
        assert!(
            err.len() < 1_000_000,
            "{format}: {} bytes of diagnostics",
            err.len()
        );
    }
}

#[test]
fn an_operand_list_of_100000_is_e1020_and_one_of_1000_inputs_runs() {
    // `ADD a, a, ...`: the C folds the inputs into one expression nested as deep as the list; 100,000
    // operands took minutes (quadratic) in `check` before the cap.
    let dir = tempfile::tempdir().unwrap();
    let list = |n: usize| {
        format!(
            "PROGRAM p\nVAR a : DINT := 1; END_VAR\nLD a\nADD {}\nST a\nEND_PROGRAM\n",
            vec!["a"; n].join(", ")
        )
    };
    let src = write(dir.path(), "long.il", &list(100_000));
    let out = run(&["--message-format", "short", "check"], &[&src]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("error[E1020]: ADD takes at most 1000 inputs, 100001 given"),
        "{}",
        stderr(&out)
    );
    // at the cap: the current result and 999 operands, 1 + 999 = 1000
    let src = write(dir.path(), "cap.il", &list(999));
    let out = run(&["run", "--cycles", "1", "--watch", "p.a"], &[&src]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(
        String::from_utf8_lossy(&out.stdout).contains(",1000"),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
}

#[test]
fn excerpts_of_long_lines_are_clipped_around_the_label() {
    let dir = tempfile::tempdir().unwrap();
    let long = "(* padding *) ".repeat(70_000); // 1 MB on the line
    let src = write(
        dir.path(),
        "long.il",
        &format!("PROGRAM p\nVAR a : INT; END_VAR\nLD a {long}nope\nST zz\nEND_PROGRAM\n"),
    );
    let out = run(&["check"], &[&src]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(
        err.len() < 4000,
        "{} bytes: {}",
        err.len(),
        &err[..err.len().min(2000)]
    );
    assert!(err.contains("…"), "the cut is marked: {err}");
    assert!(
        err.contains("long.il:3:980006"),
        "real line and column: {err}"
    );
}

#[test]
fn a_2_5_mb_xml_file_with_a_few_diagnostics_prints_a_few_kilobytes() {
    // one 2.5 MB line holding 13 type errors: before, every excerpt printed the whole line
    let body: String = (0..13)
        .map(|i| format!("a := b; (* {} *) ", "x".repeat(190_000 + i)))
        .collect();
    let dir = tempfile::tempdir().unwrap();
    let src = write(dir.path(), "big.xml", &st(&body));
    assert!(std::fs::metadata(&src).unwrap().len() > 2_400_000);
    let out = run(&["check"], &[&src]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(err.matches("error[").count() >= 13, "{err}");
    assert!(err.len() < 13 * 2000, "{} bytes", err.len());
}

#[test]
fn a_drive_script_full_of_errors_prints_a_bounded_report() {
    let dir = tempfile::tempdir().unwrap();
    let line = format!("S:: IF {} = HIGH;\n", "Q".repeat(2000));
    let src = write(dir.path(), "bad.drive", &line.repeat(100)); // 200 KB
    let out = run(&["drive", "build", "-o"], &[&dir.path().join("img"), &src]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(err.len() < 60_000, "{} bytes", err.len());
}

// ------------------------------------------------------------------------------ 4. size limits

#[test]
fn an_array_larger_than_the_data_budget_is_e2100_before_any_c() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "big.il",
        "PROGRAM p\nVAR x : ARRAY[0..2147483647] OF INT; a : INT; END_VAR\nLD a\nST x[1]\nEND_PROGRAM\n",
    );
    let out_dir = dir.path().join("out");
    let out = run(
        &["--message-format", "short", "build", "-o"],
        &[&out_dir, &src],
    );
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(
        err.contains("big.il:2:5: error[E2100]") && err.contains("4294967296 bytes"),
        "{err}"
    );
    assert!(!out_dir.join("program.c").exists());
}

#[test]
fn size_arithmetic_that_overflows_is_e2100() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "over.il",
        "TYPE\n  R : ARRAY[0..1000000] OF LREAL;\n  S : STRUCT a : ARRAY[0..1000000] OF R; END_STRUCT;\nEND_TYPE\n\
         PROGRAM p\nVAR x : ARRAY[0..1000000000] OF S; a : INT; END_VAR\nLD a\nST a\nEND_PROGRAM\n",
    );
    let out = run(
        &["--message-format", "short", "build", "-o"],
        &[&dir.path().join("out"), &src],
    );
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr(&out).contains("over.il:6:5: error[E2100]: variable `x` is too large"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn the_budget_comes_from_the_profile_and_counts_the_program_data_together() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "three.il",
        "PROGRAM p\nVAR x : ARRAY[0..99] OF LREAL; y : ARRAY[0..99] OF LREAL; END_VAR\nLD 1.0\nST x[0]\nEND_PROGRAM\n",
    );
    // 1,600 bytes: fits the default budget, not a 1 KiB one
    let out = run(&["build", "-o"], &[&dir.path().join("ok"), &src]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let profile = c_backend::TargetProfile {
        data_bytes: 1024,
        ..c_backend::TargetProfile::default()
    };
    let pf = write(dir.path(), "small.json", &profile.to_json());
    let out = run(
        &["--message-format", "short", "build", "--profile"],
        &[&pf, Path::new("-o"), &dir.path().join("no"), &src],
    );
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr(&out).contains("error[E2100]: the data of `p` needs 1600 bytes"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn a_repeated_array_initializer_is_one_loop_in_the_c_and_runs() {
    // 70 bytes of ST asked for 2,000,001 initial values: before, one C assignment each (95 MB of C that
    // make did not finish compiling); now a run of equal values is one loop over its row-major positions.
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "arr.st",
        "PROGRAM main
VAR
  big : ARRAY[0..2000000] OF INT := [2000001(7)];
  g : ARRAY[1..3, 0..4] OF DINT := [2, 9(5), 1, 2, 3(-4)];
  s : ARRAY[0..9] OF STRING[4] := [10('ab')];
  x0 : INT; xlast : INT; g10 : DINT; g14 : DINT; g20 : DINT; g24 : DINT; g30 : DINT; g31 : DINT;
  g32 : DINT; g34 : DINT; s9 : STRING[4];
END_VAR
  x0 := big[0]; xlast := big[2000000];
  g10 := g[1,0]; g14 := g[1,4]; g20 := g[2,0]; g24 := g[2,4]; g30 := g[3,0]; g31 := g[3,1];
  g32 := g[3,2]; g34 := g[3,4]; s9 := s[9];
END_PROGRAM
",
    );
    let out = run(&["build", "-o"], &[&dir.path().join("out"), &src]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let c = std::fs::metadata(dir.path().join("out/program.c"))
        .unwrap()
        .len();
    assert!(c < 64 * 1024, "{c} bytes of C");
    let out = run(
        &[
            "run",
            "--cycles",
            "1",
            "--watch",
            "main.x0,main.xlast,main.g10,main.g14,main.g20,main.g24,main.g30,main.g31,main.g32,main.g34,main.s9",
        ],
        &[&src],
    );
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let trace = String::from_utf8_lossy(&out.stdout);
    // row-major: g[1,0] = 2, nine 5s to g[2,4], then 1, 2, -4, -4, -4
    assert!(
        trace
            .lines()
            .any(|l| l == "0,0,7,7,2,5,5,5,1,2,-4,-4,\"ab\""),
        "{trace}"
    );
}

#[test]
fn real_literals_beyond_their_range_are_e1017_not_an_infinity() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "rl.st",
        "PROGRAM main
VAR r : REAL; l : LREAL; END_VAR
  r := REAL#3.5E39;
  l := 1.0E999;
  l := 1.0E300;
  r := REAL#3.0E38;
END_PROGRAM
",
    );
    let out = run(&["check", "--message-format", "short"], &[&src]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(err.contains("rl.st:3:8: error[E1017]"), "{err}");
    assert!(err.contains("rl.st:4:8: error[E1017]"), "{err}");
    assert_eq!(err.matches("error[").count(), 2, "{err}");
}

#[test]
fn untyped_real_literals_beyond_real_are_e1017_in_st_il_and_xml() {
    let dir = tempfile::tempdir().unwrap();
    let st_src = write(
        dir.path(),
        "u.st",
        "PROGRAM main
VAR r : REAL; l : LREAL; q : REAL := -1.0E39; END_VAR
  r := 1.0E300;
  l := 1.0E300;
  r := 3.0E38;
  l := -3.5E38;
END_PROGRAM
",
    );
    let out = run(&["check", "--message-format", "short"], &[&st_src]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(err.contains("u.st:2:38: error[E1017]"), "{err}");
    assert!(err.contains("u.st:3:8: error[E1017]"), "{err}");
    assert_eq!(err.matches("error[").count(), 2, "{err}");

    let il = write(
        dir.path(),
        "u.il",
        "PROGRAM main\nVAR r : REAL; l : LREAL; END_VAR\nLD 1.0E300\nST l\nLD 1.0E300\nST r\nEND_PROGRAM\n",
    );
    let out = run(&["check", "--message-format", "short"], &[&il]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(err.contains("u.il:5:4: error[E1017]"), "{err}");
    assert_eq!(err.matches("error[").count(), 1, "{err}");

    // an FBD <inVariable> expression feeding a REAL
    let fbd = r#"<FBD>
<inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>1.0E300</expression></inVariable>
<outVariable localId="2"><position x="0" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><expression>r</expression></outVariable>
</FBD>"#;
    let xml = write(dir.path(), "u.xml", &project(fbd));
    let out = run(&["check", "--message-format", "short"], &[&xml]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(stderr(&out).contains("error[E1017]"), "{}", stderr(&out));
    let xml = write(dir.path(), "s.xml", &st("r := 1.0E300;"));
    let out = run(&["check", "--message-format", "short"], &[&xml]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(stderr(&out).contains("error[E1017]"), "{}", stderr(&out));

    // in range, the value reaches the trace
    let ok = write(
        dir.path(),
        "ok.st",
        "PROGRAM main\nVAR r : REAL; l : LREAL; END_VAR\n  r := 3.0E38;\n  l := 1.0E300;\nEND_PROGRAM\n",
    );
    let out = run(
        &["run", "--cycles", "1", "--watch", "main.r,main.l"],
        &[&ok],
    );
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let trace = String::from_utf8_lossy(&out.stdout);
    assert!(!trace.to_ascii_lowercase().contains("inf"), "{trace}");
}

#[test]
fn lone_cr_crlf_and_lf_line_ends_each_count_one_line_in_every_format() {
    // line 1 ends in \r, line 2 in \r\n, line 3 in \n, lines 4 and 5 (a comment) in \r: `y` is on line 6
    let text =
        "PROGRAM main\rVAR x : INT; END_VAR\r\n  x := 1;\n  (* c\r *)\r  y := 2;\rEND_PROGRAM\r";
    let dir = tempfile::tempdir().unwrap();
    for name in ["cr.st", "cr.il"] {
        let body = if name.ends_with(".il") {
            text.replace("  x := 1;", "LD 1")
                .replace("  y := 2;", "ST y")
        } else {
            text.to_string()
        };
        let src = write(dir.path(), name, &body);
        let (col, end) = if name.ends_with(".il") {
            (4, 5)
        } else {
            (3, 4)
        };
        let out = run(&["check", "--message-format", "short"], &[&src]);
        assert_eq!(out.status.code(), Some(1));
        let err = stderr(&out);
        assert!(
            err.contains(&format!("{name}:6:{col}: error[E1001]")),
            "{name}: {err}"
        );
        assert_eq!(err.matches("error[").count(), 1, "{name}: {err}");
        let out = run(&["check"], &[&src]);
        let err = stderr(&out);
        assert!(err.contains(&format!("{name}:6:{col}")), "{err}");
        assert!(err.contains("6 │ "), "the excerpt shows line 6: {err}");
        let out = run(&["check", "--message-format", "json"], &[&src]);
        let first: serde_json::Value =
            serde_json::from_str(stderr(&out).lines().next().unwrap()).unwrap();
        assert_eq!(first["line"], 6, "{first}");
        assert_eq!(first["column"], col, "{first}");
        assert_eq!(first["end_line"], 6, "{first}");
        assert_eq!(first["end_column"], end, "{first}");
    }
    // the IL with lone CR line ends is read line by line: it runs
    let il = write(
        dir.path(),
        "run.il",
        "PROGRAM main\rVAR x : INT; END_VAR\r// note\rLD 2 (* a\r b *)\rADD 3\rST x\rEND_PROGRAM\r",
    );
    let out = run(&["run", "--cycles", "1", "--watch", "main.x"], &[&il]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(String::from_utf8_lossy(&out.stdout).contains("0,0,5"));
}

#[test]
fn a_file_of_5000_textual_sfc_charts_is_checked_and_located() {
    // each chart was lowered from a copy of the file padded to its offset, and with the project's
    // declarations rebuilt per chart: charts x file size
    let mut text = String::new();
    let n = 5000;
    for i in 0..n {
        let back = if i == n - 1 { "Bx" } else { "Off" };
        text.push_str(&format!(
            "FUNCTION_BLOCK Blink{i}\n  VAR_OUTPUT q : BOOL; END_VAR\n  INITIAL_STEP Off: END_STEP\n  \
             TRANSITION FROM Off TO On := Off.T >= T#20ms; END_TRANSITION\n  STEP On: q(N); END_STEP\n  \
             TRANSITION FROM On TO {back} := On.T >= T#20ms; END_TRANSITION\nEND_FUNCTION_BLOCK\n"
        ));
    }
    text.push_str(
        "PROGRAM Main\n  VAR b : Blink0; out : BOOL; END_VAR\n  b();\n  out := b.q;\nEND_PROGRAM\n",
    );
    let dir = tempfile::tempdir().unwrap();
    let src = write(dir.path(), "charts.st", &text);
    let out = run(&["check", "--message-format", "short"], &[&src]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    // the last chart's bad step, at its line: 7 lines per chart
    let line = 7 * (n - 1) + 6;
    assert!(
        err.contains(&format!("charts.st:{line}:25: error[E3120]")),
        "{err}"
    );
    assert_eq!(err.matches("error[").count(), 1, "{err}");
    // fixed, the whole file passes
    let fixed = text.replace("TO Bx", "TO Off");
    let src = write(dir.path(), "charts.st", &fixed);
    let out = run(&["check"], &[&src]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
}

#[test]
fn an_input_given_twice_in_one_call_is_e1027() {
    // found by the generator: 20,000 `a := x` in one call were accepted, and the first value won
    let dir = tempfile::tempdir().unwrap();
    let f = "FUNCTION f : INT\nVAR_INPUT a : INT; END_VAR\nf := a;\nEND_FUNCTION\n";
    let src = write(
        dir.path(),
        "d.st",
        &format!("{f}PROGRAM main\nVAR x : INT; t : TON; q : BOOL; n : BOOL; END_VAR\nx := f(a := 1, A := 2);\nt(IN := TRUE, PT := T#1s, in := FALSE, Q => q, Q => n);\nEND_PROGRAM\n"),
    );
    let out = run(&["check", "--message-format", "short"], &[&src]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(err.contains("d.st:7:16: error[E1028]"), "{err}");
    assert!(err.contains("d.st:8:27: error[E1028]"), "{err}");
    // an output may go to two variables
    assert_eq!(err.matches("error[").count(), 2, "{err}");
    let il = write(
        dir.path(),
        "d.il",
        "FUNCTION f : INT\nVAR_INPUT a : INT; END_VAR\nLD a\nST f\nEND_FUNCTION\nPROGRAM main\nVAR x : INT; END_VAR\nf(a := 1, a := 2)\nST x\nEND_PROGRAM\n",
    );
    let out = run(&["check", "--message-format", "short"], &[&il]);
    assert!(
        stderr(&out).contains("d.il:8:11: error[E1028]"),
        "{}",
        stderr(&out)
    );
    // 20,000 of them: one report per repeat, the first 50 shown
    let many = vec!["a := x"; 20_000].join(", ");
    let src = write(
        dir.path(),
        "many.st",
        &format!("{f}PROGRAM main\nVAR x : INT; END_VAR\nx := f({many});\nEND_PROGRAM\n"),
    );
    let out = run(&["check", "--message-format", "short"], &[&src]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert_eq!(err.matches("error[E1028]").count(), 50, "{}", &err[..2000]);
    assert!(out.stderr.len() < 100_000);
}

#[test]
fn distinct_initial_values_of_an_array_are_one_table_in_the_c_and_run() {
    // found by the generator: 100,000 distinct initial values were 100,000 assignments in one INIT
    // function, which cc -O2 did not compile in a minute
    let vals: Vec<i64> = (0..150)
        .map(|i| (i * 37) % 1000 - 500)
        .chain(std::iter::repeat_n(7, 10))
        .chain((0..90).map(|i| (i * 13) % 200))
        .collect();
    let md: Vec<i64> = (0..200).map(|i| (i * 7) % 100).collect();
    let join = |v: &[i64]| {
        v.iter()
            .map(|x| x.to_string())
            .collect::<Vec<_>>()
            .join(",")
    };
    let reals: Vec<String> = (0..70).map(|i| format!("{i}.5")).collect();
    let src = format!(
        "PROGRAM main
VAR v : ARRAY[0..249] OF DINT := [{}]; m : ARRAY[0..1, 0..99] OF INT := [{}];
  r : ARRAY[1..70] OF REAL := [{}]; big : ARRAY[0..19999] OF DINT := [{}];
  s : DINT; w : DINT; q : REAL; i : INT; j : INT; b : DINT; END_VAR
s := 0; w := 0; q := 0.0;
FOR i := 0 TO 249 DO s := s + v[i] * (i + 1); END_FOR;
FOR i := 0 TO 1 DO FOR j := 0 TO 99 DO w := w + m[i, j] * (i * 100 + j + 1); END_FOR; END_FOR;
FOR i := 1 TO 70 DO q := q + r[i]; END_FOR;
b := big[19999] + big[12345];
END_PROGRAM
",
        join(&vals),
        join(&md),
        reals.join(","),
        (0..20_000)
            .map(|i| (i * 3).to_string())
            .collect::<Vec<_>>()
            .join(",")
    );
    let dir = tempfile::tempdir().unwrap();
    let file = write(dir.path(), "tbl.st", &src);
    let out = run(&["build", "-o"], &[&dir.path().join("out"), &file]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let c = std::fs::read_to_string(dir.path().join("out/program.c")).unwrap();
    assert_eq!(
        c.matches("static const IEC_DINT").count(),
        3,
        "v before and after its run, big"
    );
    assert!(
        c.matches("self->v_big[").count() < 5,
        "one copy loop for big"
    );
    let out = run(
        &[
            "run",
            "--cycles",
            "1",
            "--watch",
            "main.s,main.w,main.q,main.b",
        ],
        &[&file],
    );
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let s: i64 = vals
        .iter()
        .enumerate()
        .map(|(i, v)| v * (i as i64 + 1))
        .sum();
    let w: i64 = md.iter().enumerate().map(|(i, v)| v * (i as i64 + 1)).sum();
    let trace = String::from_utf8_lossy(&out.stdout);
    assert!(
        trace.contains(&format!("0,0,{s},{w},2450,{}", 3 * 19999 + 3 * 12345)),
        "{trace}"
    );
}

#[test]
fn a_drive_script_with_lone_cr_line_ends_builds_the_same_image() {
    // before, the first `//` comment ran to the end of the file: "the script has no Motion block"
    let lf = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../crates/drive-script/tests/scripts/three_motions.ds"),
    )
    .unwrap();
    let dir = tempfile::tempdir().unwrap();
    let mut images = Vec::new();
    for (name, text) in [("lf.ds", lf.clone()), ("cr.ds", lf.replace('\n', "\r"))] {
        let src = write(dir.path(), name, &text);
        let img = dir.path().join(format!("{name}.img"));
        let out = ladderc()
            .args(["drive", "build", "-o"])
            .arg(&img)
            .arg(&src)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{name}: {}", stderr(&out));
        images.push(std::fs::read(&img).unwrap());
    }
    assert_eq!(images[0], images[1]);
    // an error after lone-CR lines is located on its line
    let bad = lf
        .replacen("S:: P1 = 3;", "S:: P1 = 3 3;", 1)
        .replace('\n', "\r");
    let src = write(dir.path(), "bad.ds", &bad);
    let out = ladderc()
        .args(["drive", "build", "--message-format", "short", "-o"])
        .arg(dir.path().join("bad.img"))
        .arg(&src)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("bad.ds:5:"), "{}", stderr(&out));
}

#[test]
fn a_field_of_a_direct_address_is_one_e3100_in_every_st_position() {
    // cargo-fuzz `st` (session 21): `%QD2 .F` as an operand made the ST lowering ask for the
    // operand's value and the value's operand in turn, without end (a stack overflow, SIGSEGV).
    let dir = tempfile::tempdir().unwrap();
    for (k, text) in [
        "a := %QD2 .F;",
        "a := -%QD2 .F + 1;",
        "IF %QX0.0 .F THEN a := 1; END_IF;",
        "a := ABS(%QD2 .F);",
    ]
    .into_iter()
    .enumerate()
    {
        let f = write(dir.path(), &format!("addr_field{k}.xml"), &st(text));
        let out = run(&["check", "--message-format", "short"], &[&f]);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(1), "{text}: {err}");
        assert_eq!(err.matches("error[E3100]").count(), 1, "{text}: {err}");
    }
}
