//! User text can never become C: identifiers that are C keywords or runtime names (those IEC 61131-3
//! does not reserve itself: `goto`, `long`, `switch`, `static` ...), and strings holding
//! C syntax, compile and behave as plain data.

mod support;
use support::*;

#[test]
fn c_keywords_and_runtime_names_as_iec_identifiers_compile_safely() {
    let src = "FUNCTION_BLOCK main
VAR_INPUT
  goto : INT;
END_VAR
VAR_OUTPUT
  static : INT;
END_VAR
  LD goto
  ADD 1
  ST static
END_FUNCTION_BLOCK
PROGRAM printf
VAR
  self : main;
  abort : INT;
  ladderc_now : INT;
  int_ : INT;
  long : DINT;
  char : DINT;
  switch : INT := 41;
  _Bool : BOOL;
END_VAR
  CAL self(goto := switch, static => abort)
  LD abort
  ST ladderc_now
  ST int_
  ST long
  LD long
  ADD 1
  ST char
  LD TRUE
  ST _Bool
END_PROGRAM
";
    let b = build_src(src);
    let c = b.program.file("program.c").unwrap();
    assert!(c.contains("FB_main_BODY(&self->v_self)"), "{c}");
    let rows = run(
        &b,
        2,
        10.0,
        "",
        &[
            "printf.abort",
            "printf.ladderc_now",
            "printf.int_",
            "printf._Bool",
            "printf.long",
            "printf.char",
        ],
    );
    assert_eq!(column(&rows, "printf.abort"), ["42", "42"]);
    assert_eq!(column(&rows, "printf.ladderc_now"), ["42", "42"]);
    assert_eq!(column(&rows, "printf._Bool"), ["1", "1"]);
    assert_eq!(column(&rows, "printf.long"), ["42", "42"]);
    assert_eq!(column(&rows, "printf.char"), ["43", "43"]);
}

#[test]
fn strings_holding_c_syntax_stay_strings() {
    let src = "PROGRAM main
VAR
  s : STRING;
  t : STRING := '*/ exit(3); /* \" \\\\ ??/ %s';
  same : BOOL;
END_VAR
  LD '\"*/ system(\"echo INJECTED\"); /*'
  ST s
  LD s
  EQ t
  ST same
END_PROGRAM
";
    let b = build_src(src);
    for (name, text) in &b.program.files {
        if name.starts_with("program") {
            assert!(
                !text.contains("system(\""),
                "{name} holds user text verbatim"
            );
            assert!(!text.contains("exit(3)"), "{name} holds user text verbatim");
        }
    }
    let rows = run(&b, 1, 10.0, "", &["main.s", "main.t", "main.same"]);
    // the trace quotes strings CSV-style (quotes doubled); split on ',' is naive, so rejoin the row
    let raw: Vec<String> = rows[1].clone();
    let line = raw.join(",");
    assert!(
        line.contains("\"\"\"*/ system(\"\"echo INJECTED\"\"); /*\""),
        "{line}"
    );
    assert!(
        line.contains("\"*/ exit(3); /* \"\" \\\\ ??/ %s\""),
        "{line}"
    );
    assert!(line.ends_with(",0"), "{line}");
}
