//! Syntax errors: each snapshot shows the source and the diagnostics together (gleam-style), so a
//! reviewer sees the message, the span and the hint in context.
mod common;

fn show(src: &str) -> String {
    let p = common::parse("test.il", src);
    format!("----- SOURCE\n{src}\n----- DIAGNOSTICS\n{}", p.human())
}

fn prog(body: &str) -> String {
    format!("PROGRAM p\nVAR a, b : BOOL; t : TON; END_VAR\n{body}\nEND_PROGRAM\n")
}

#[test]
fn missing_operand_after_ld() {
    insta::assert_snapshot!(show(&prog("    LD\n    ST b")));
}

#[test]
fn missing_variable_after_st() {
    insta::assert_snapshot!(show(&prog("    LD a\n    ST")));
}

#[test]
fn missing_jump_label() {
    insta::assert_snapshot!(show(&prog("    LD a\n    JMPC")));
}

#[test]
fn not_with_operand() {
    insta::assert_snapshot!(show(&prog("    LD a\n    NOT b")));
}

#[test]
fn ret_with_operand() {
    insta::assert_snapshot!(show(&prog("    RET a")));
}

#[test]
fn cal_without_instance() {
    insta::assert_snapshot!(show(&prog("    CAL")));
}

#[test]
fn fb_input_operator_without_instance() {
    insta::assert_snapshot!(show(&prog("    LD a\n    IN")));
}

#[test]
fn two_operands_on_one_line() {
    insta::assert_snapshot!(show(&prog("    LD a b\n    ST b")));
}

#[test]
fn infix_operator_is_not_il() {
    insta::assert_snapshot!(show(&prog("    LD a\n    = b")));
}

#[test]
fn ld_cannot_be_deferred() {
    insta::assert_snapshot!(show(&prog("    LD( a\n    )\n    ST b")));
}

#[test]
fn missing_end_var() {
    insta::assert_snapshot!(show("PROGRAM p\nVAR a : BOOL;\n    LD a\nEND_PROGRAM\n"));
}

#[test]
fn missing_close_paren_of_deferred_operator() {
    insta::assert_snapshot!(show(&prog("    LD a\n    AND( b\n    OR a\n    ST b")));
}

#[test]
fn missing_end_program_before_next_pou() {
    insta::assert_snapshot!(show(
        "PROGRAM p\n    LD a\nFUNCTION_BLOCK f\nEND_FUNCTION_BLOCK\n"
    ));
}

#[test]
fn mismatched_end_keyword() {
    insta::assert_snapshot!(show("FUNCTION_BLOCK f\n    LD a\nEND_PROGRAM\n"));
}

#[test]
fn semicolon_comment_names_the_construct() {
    insta::assert_snapshot!(show(&prog("    LD a   ; load a\n    ST b")));
}

#[test]
fn lexical_errors() {
    insta::assert_snapshot!(show(&prog(
        "    LD 2#102\n    LD T#5x\n    LD %Z1\n    LD 'it$q'\n    LD D#2001-02-30\n    LD 'open"
    )));
}

#[test]
fn unterminated_comment() {
    insta::assert_snapshot!(show("PROGRAM p\n    LD a (* no end\nEND_PROGRAM\n"));
}

#[test]
fn declarations_after_instructions() {
    insta::assert_snapshot!(show(
        "PROGRAM p\n    LD a\nVAR a : BOOL; END_VAR\nEND_PROGRAM\n"
    ));
}

#[test]
fn function_without_result_type() {
    insta::assert_snapshot!(show("FUNCTION f\n    LD 1\nEND_FUNCTION\n"));
}

#[test]
fn declaration_errors() {
    insta::assert_snapshot!(show(
        "PROGRAM p\nVAR\n    a, b AT %IX0.1 : BOOL;\n    c : INT := ;\n    d : BOOL R_EDGE;\n    e : INT\nEND_VAR\nEND_PROGRAM\n"
    ));
}

#[test]
fn unsupported_var_access_and_task_settings() {
    insta::assert_snapshot!(show(
        "CONFIGURATION c\nVAR_ACCESS x : a.b : INT READ_ONLY; END_VAR\nRESOURCE r ON plc\nTASK t (INTERVAL := T#1s, PRIO := 1, PRIORITY := -1);\nPROGRAM i WITH t : p;\nEND_RESOURCE\nEND_CONFIGURATION\n"
    ));
}

#[test]
fn missing_end_at_end_of_file() {
    insta::assert_snapshot!(show(
        "FUNCTION_BLOCK f\nVAR x : BOOL; END_VAR\n    LD x\n    AND( x\n"
    ));
}

/// Ten independent mistakes, one per line: ten diagnostics, one on each of those lines, no cascade.
#[test]
fn ten_independent_errors_are_all_reported_once() {
    let src = prog(
        "    LD\n    LD a\n    JMPC\n    ST b\n    NOT a\n    LD a b\n    CAL\n    LD 2#9\n    ST b\n    = a\n    LD a\n    IN\n    LD( a\n    )\n    XOR a b c\n    LD a ; dialect comment\n    ST b",
    );
    let p = common::parse("ten.il", &src);
    let lines: Vec<usize> = p
        .diags
        .iter()
        .map(|d| p.map.get(p.file).line_col(d.span.unwrap().start as usize).0)
        .collect();
    assert_eq!(
        lines,
        vec![3, 5, 7, 8, 9, 10, 12, 14, 15, 17, 18],
        "{}",
        p.short()
    );
    // The one extra diagnostic is the `;` comment, which is not a syntax error but a named construct.
    assert_eq!(p.diags.iter().filter(|d| d.code.0 != "E0007").count(), 10);
    // The rest of the body still parses.
    let il_frontend::ast::LibraryElement::Pou(pou) = &p.unit.items[0] else {
        panic!("expected a POU")
    };
    assert_eq!(pou.body.len(), 7, "{}", il_frontend::print::unit(&p.unit));
    insta::assert_snapshot!(p.short());
}

#[test]
fn empty_and_comment_only_files_have_no_items() {
    for src in ["", "\n\n", "(* nothing *)\n// here\n"] {
        let p = common::parse("e.il", src);
        assert!(p.unit.items.is_empty(), "{src:?}");
        assert!(p.diags.is_empty(), "{src:?}: {}", p.short());
    }
}

#[test]
fn labels_alone_on_a_line_before_an_instruction_and_before_end() {
    let p = common::parse("l.il", &prog("start: LD a\nmid:\n\n    ST b\nlast:"));
    assert_eq!(p.short(), "");
    insta::assert_snapshot!(il_frontend::print::unit(&p.unit));
}

#[test]
fn keywords_are_case_insensitive_and_names_keep_their_spelling() {
    let p = common::parse(
        "c.il",
        "program Mixed\nvar_input In : bool; R1 : Bool; END_var\n  ld In\n  st R1\n  Jmpc Done\ndone:\nend_program",
    );
    assert_eq!(p.short(), "");
    insta::assert_snapshot!(il_frontend::print::unit(&p.unit));
}

#[test]
fn broken_pou_header_drops_the_pou_but_not_the_next_one() {
    let p = common::parse(
        "h.il",
        "PROGRAM 12\n  LD a\nEND_PROGRAM\nFUNCTION f :\n  LD a\nEND_FUNCTION\nPROGRAM q\n  LD b\nEND_PROGRAM\n",
    );
    insta::assert_snapshot!(format!(
        "{}-----\n{}",
        p.short(),
        il_frontend::print::unit(&p.unit)
    ));
}

#[test]
fn text_after_closing_paren_keeps_the_deferred_instruction() {
    let p = common::parse(
        "d.il",
        &prog("    LD a\n    AND( b\n        OR a\n    ) b\n    ST b"),
    );
    insta::assert_snapshot!(format!(
        "{}-----\n{}",
        p.short(),
        il_frontend::print::unit(&p.unit)
    ));
}

#[test]
fn unmatched_paren_and_stray_end_var() {
    insta::assert_snapshot!(show("END_VAR\nPROGRAM p\n    )\n    ST c\nEND_PROGRAM\n"));
}

#[test]
fn call_argument_errors() {
    insta::assert_snapshot!(show(&prog(
        "    CAL t(IN := )\n    CAL t(IN := a, b)\n    LD t.\n    LD t[1\n    ST b"
    )));
}
