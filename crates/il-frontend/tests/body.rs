//! `parse_body` (an instruction list alone, as in a PLCopen XML `<IL>` element) and line handling.
mod common;

use diagnostics::{Diagnostics, FileId, SourceMap};
use il_frontend::ast::*;

#[test]
fn body_spans_point_into_the_containing_file() {
    let xml = "<body><IL>\n  LD start\n  ST motor\n</IL></body>";
    let start = xml.find("<IL>").unwrap() + 4;
    let end = xml.find("</IL>").unwrap();
    let mut map = SourceMap::new();
    let file = map.add("p.xml", xml);
    let mut diags = Diagnostics::new();
    let body = il_frontend::parse_body(file, &xml[start..end], start, &mut diags);
    assert!(diags.is_empty());
    assert_eq!(body.len(), 2);
    let IlStmt::Instr(i) = &body[1] else {
        panic!("expected an instruction")
    };
    assert_eq!(&xml[i.span.range()], "ST motor");
    assert_eq!(map.get(file).line_col(i.span.start as usize), (3, 3));
    insta::assert_snapshot!(il_frontend::print::body(&body), @r"
        LD start
        ST motor
    ");
}

#[test]
fn body_errors_point_into_the_containing_file() {
    let xml = "<IL>LD\nST x</IL>";
    let mut map = SourceMap::new();
    let file = map.add("p.xml", xml);
    let mut diags = Diagnostics::new();
    let body = il_frontend::parse_body(file, &xml[4..xml.len() - 5], 4, &mut diags);
    assert_eq!(body.len(), 1);
    let d = diags.into_vec();
    assert_eq!(d.len(), 1);
    assert_eq!(d[0].code.0, "E0012");
    assert_eq!(&xml[d[0].span.unwrap().range()], "LD");
}

#[test]
fn body_with_pou_keywords_is_an_error_not_a_panic() {
    let mut diags = Diagnostics::new();
    let body = il_frontend::parse_body(FileId(0), "LD a\nEND_PROGRAM\nST b\n", 0, &mut diags);
    assert_eq!(diags.error_count(), 1, "{diags:?}");
    assert_eq!(body.len(), 2);
}

#[test]
fn crlf_tabs_and_bom_are_blanks() {
    let src =
        "\u{feff}PROGRAM p\r\nVAR\tx : BOOL; END_VAR\r\n\tLD x\r\n\r\n\tST x\r\nEND_PROGRAM\r\n";
    let p = common::parse("crlf.il", src);
    assert_eq!(p.short(), "");
    let LibraryElement::Pou(pou) = &p.unit.items[0] else {
        panic!("expected a POU")
    };
    assert_eq!(pou.body.len(), 2);
}

#[test]
fn multi_line_call_arguments_with_comments() {
    let src = "PROGRAM p\n  CAL t( (* timer *)\n    IN := x, // start\n    PT := T#1s\n  )\n  LD t.Q\nEND_PROGRAM\n";
    let p = common::parse("call.il", src);
    assert_eq!(p.short(), "");
    let LibraryElement::Pou(pou) = &p.unit.items[0] else {
        panic!("expected a POU")
    };
    let IlStmt::Instr(Instruction {
        kind: InstrKind::Call {
            args: CallArgs::Formal(args),
            ..
        },
        ..
    }) = &pou.body[0]
    else {
        panic!("expected a call: {:?}", pou.body[0])
    };
    assert_eq!(args.len(), 2);
    assert!(args[1].name.is("pt"));
    assert_eq!(pou.body.len(), 2);
}

#[test]
fn operands_of_every_literal_form() {
    let src = "PROGRAM p\n  LD INT#-5\n  LD %I*\n  LD 'a$27b'\n  LD LDT#1970-01-01-00:00:00\n  LD -1.5\n  LD TRUE\nEND_PROGRAM\n";
    let p = common::parse("lit.il", src);
    assert_eq!(p.short(), "");
    let LibraryElement::Pou(pou) = &p.unit.items[0] else {
        panic!("expected a POU")
    };
    let kinds: Vec<String> = pou
        .body
        .iter()
        .map(|s| match s {
            IlStmt::Instr(Instruction {
                kind:
                    InstrKind::Simple {
                        operand: Some(Operand::Literal(l)),
                        ..
                    },
                ..
            }) => format!(
                "{:?} {:?}",
                l.kind,
                l.type_prefix.as_ref().map(|p| p.name.as_str())
            ),
            IlStmt::Instr(Instruction {
                kind:
                    InstrKind::Simple {
                        operand: Some(Operand::Address(a)),
                        ..
                    },
                ..
            }) => format!("{:?} {:?} {:?}", a.area, a.size, a.path),
            other => format!("{other:?}"),
        })
        .collect();
    assert_eq!(
        kinds,
        vec![
            "Int(-5) Some(\"INT\")",
            "Input Bit []",
            "String { wide: false, value: \"a'b\" } None",
            "DateAndTime(0) Some(\"LDT\")",
            "Real(-1.5) None",
            "Bool(true) None",
        ]
    );
}

#[test]
fn non_ascii_text_is_reported_on_character_boundaries() {
    let src = "PROGRAM p\n    LD ü\n    ST é€\n    LD 'grüße'\nEND_PROGRAM\n";
    let p = common::parse("u.il", src);
    let spans: Vec<&str> = p
        .diags
        .iter()
        .map(|d| &src[d.span.unwrap().range()])
        .collect();
    assert_eq!(spans, vec!["ü", "é", "€"], "{}", p.short());
    // letters beyond ASCII make a name (E1089, round 27); `€` is no letter (E0001)
    let codes: Vec<&str> = p.diags.iter().map(|d| d.code.0).collect();
    assert_eq!(codes, vec!["E1089", "E1089", "E0001"], "{}", p.short());
}

/// A simple, jump or label line (`LD x`, `ADD 5`, `JMPC l`, `l:`, each followed by the line's end,
/// passed from the layout pass to the grammar as one token) gives the tree and the diagnostics its two
/// tokens give (a comment before the line's end keeps them two): for every simple operator word with
/// a name and with an integer, every jump word, a label; spans included, `NOT x` (E0013) too.
#[test]
fn simple_lines_parse_as_their_two_tokens() {
    let parse = |src: &str| {
        let mut diags = Diagnostics::new();
        let body = il_frontend::parse_body(FileId(0), src, 7, &mut diags);
        let diags: Vec<String> = diags
            .iter()
            .map(|d| format!("{} {} {:?} {:?}", d.code, d.message, d.span, d.hint))
            .collect();
        (format!("{body:?}"), diags)
    };
    let same = |line: &str| {
        let one = parse(&format!("LD a\n  {line}\t\n"));
        let two = parse(&format!("LD a\n  {line}\t(* two tokens *)\n"));
        assert_eq!(one, two, "{line}");
        one
    };
    let words = [
        "LD", "ldn", "ST", "STN", "S", "R", "AND", "ANDN", "OR", "ORN", "XOR", "XORN", "NOT",
        "ADD", "SUB", "MUL", "DIV", "MOD", "GT", "GE", "EQ", "NE", "LE", "LT",
    ];
    for w in words {
        let one = same(&format!("{w} x_1"));
        assert_eq!(one.1.is_empty(), w != "NOT", "{w}: {:?}", one.1);
        // `NOT x` keeps the recovered `NOT` without its operand
        assert_eq!(
            one.0.contains("name: \"x_1\""),
            w != "NOT",
            "{w}: {}",
            one.0
        );
        let one = same(&format!("{w} -16"));
        assert_eq!(one.0.contains("Int(-16)"), w != "NOT", "{w}: {}", one.0);
    }
    for w in ["JMP", "jmpc", "JMPCN", "JMPNC"] {
        let one = same(&format!("{w} done"));
        assert!(one.1.is_empty() && one.0.contains("Jump"), "{w}: {one:?}");
    }
    let one = same("done:");
    assert!(
        one.1.is_empty() && one.0.contains("Label(Ident { name: \"done\""),
        "{one:?}"
    );
}
