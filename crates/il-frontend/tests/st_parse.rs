//! ST parsing: each construct's syntax tree (source and result in the snapshot), precedence,
//! literals, and syntax errors with recovery (one diagnostic per mistake, later statements kept).

mod st_common;

use diagnostics::{Diagnostics, SourceMap};
use il_frontend::st::{self, ast::*};

/// A compact, span-free rendering of expressions and statements.
fn expr(e: &Expr) -> String {
    match &e.kind {
        ExprKind::Literal(l) => {
            let mut s = String::new();
            il_frontend::print::literal(&mut s, l);
            s
        }
        ExprKind::Place(p) => place(p),
        ExprKind::EnumValue { type_name, value } => format!("{}#{}", type_name.name, value.name),
        ExprKind::Unary { op, operand } => format!("{op:?}({})", expr(operand)),
        ExprKind::Binary { op, left, right } => {
            format!("({} {} {})", expr(left), op.spelling(), expr(right))
        }
        ExprKind::Call { name, args: a } => format!("{}({})", name.name, args(a)),
        ExprKind::Error => "<error>".into(),
    }
}

fn args(a: &[Arg]) -> String {
    a.iter()
        .map(|a| {
            let n = a.name.as_ref().map(|n| n.name.clone()).unwrap_or_default();
            match a.dir {
                ArgDir::Input if a.name.is_some() => format!("{n} := {}", expr(&a.value)),
                ArgDir::Input => expr(&a.value),
                ArgDir::Output { negated } => {
                    format!(
                        "{}{n} => {}",
                        if negated { "NOT " } else { "" },
                        expr(&a.value)
                    )
                }
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

fn place(p: &Place) -> String {
    let mut s = match &p.base {
        PlaceBase::Name(n) => n.name.clone(),
        PlaceBase::Address(_) => "%addr".into(),
    };
    for a in &p.accessors {
        match a {
            Accessor::Field(f) => s.push_str(&format!(".{}", f.name)),
            Accessor::Index(ix) => s.push_str(&format!(
                "[{}]",
                ix.iter().map(expr).collect::<Vec<_>>().join(", ")
            )),
            Accessor::Deref(_) => s.push('^'),
            Accessor::Call { args: a, .. } => s.push_str(&format!("({})", args(a))),
        }
    }
    s
}

fn stmts(out: &mut String, list: &[Stmt], depth: usize) {
    let ind = "  ".repeat(depth);
    for s in list {
        match &s.kind {
            StmtKind::Assign { target, value } => {
                out.push_str(&format!("{ind}{} := {}\n", place(target), expr(value)))
            }
            StmtKind::Call { callee, args: a } => {
                out.push_str(&format!("{ind}call {}({})\n", place(callee), args(a)))
            }
            StmtKind::If {
                branches,
                else_body,
            } => {
                for (k, b) in branches.iter().enumerate() {
                    let kw = if k == 0 { "if" } else { "elsif" };
                    out.push_str(&format!("{ind}{kw} {}\n", expr(&b.cond)));
                    stmts(out, &b.body, depth + 1);
                }
                if let Some(e) = else_body {
                    out.push_str(&format!("{ind}else\n"));
                    stmts(out, e, depth + 1);
                }
            }
            StmtKind::Case {
                selector,
                arms,
                else_body,
            } => {
                out.push_str(&format!("{ind}case {}\n", expr(selector)));
                for a in arms {
                    let labels: Vec<String> = a
                        .labels
                        .iter()
                        .map(|l| match l {
                            CaseLabel::Value(v) => expr(v),
                            CaseLabel::Range(x, y) => format!("{}..{}", expr(x), expr(y)),
                        })
                        .collect();
                    out.push_str(&format!("{ind}  {}:\n", labels.join(", ")));
                    stmts(out, &a.body, depth + 2);
                }
                if let Some(e) = else_body {
                    out.push_str(&format!("{ind}  else:\n"));
                    stmts(out, e, depth + 2);
                }
            }
            StmtKind::For {
                control,
                from,
                to,
                by,
                body,
                ..
            } => {
                out.push_str(&format!(
                    "{ind}for {} := {} to {}{}\n",
                    control.name,
                    expr(from),
                    expr(to),
                    by.as_ref()
                        .map(|b| format!(" by {}", expr(b)))
                        .unwrap_or_default()
                ));
                stmts(out, body, depth + 1);
            }
            StmtKind::While { cond, body } => {
                out.push_str(&format!("{ind}while {}\n", expr(cond)));
                stmts(out, body, depth + 1);
            }
            StmtKind::Repeat { body, until, .. } => {
                out.push_str(&format!("{ind}repeat\n"));
                stmts(out, body, depth + 1);
                out.push_str(&format!("{ind}until {}\n", expr(until)));
            }
            other => out.push_str(&format!("{ind}{other:?}\n")),
        }
    }
}

/// Source, tree and diagnostics, for a snapshot.
fn parse(src: &str) -> String {
    let mut sm = SourceMap::new();
    let file = sm.add("t.st", src);
    let mut diags = Diagnostics::new();
    let list = st::parse_statements(file, src, 0, &mut diags);
    let mut out = format!("{src}\n---\n");
    stmts(&mut out, &list, 0);
    let d = st_common::render(&sm, diags);
    if !d.is_empty() {
        out.push_str("---\n");
        out.push_str(&d);
    }
    out
}

#[test]
fn precedence_follows_iec() {
    insta::assert_snapshot!(parse(
        "a := 1 + 2 * 3 - 4 / 5 MOD 6;\n\
         b := NOT x AND y OR z XOR w & v;\n\
         c := x + 1 > y * 2 = TRUE;\n\
         d := -2 ** 2 + -x;\n\
         e := (1 + 2) * (3 - -4);\n\
         f := a <> b AND c <= d AND e >= f;"
    ));
}

#[test]
fn literals_places_and_calls() {
    insta::assert_snapshot!(parse(
        "t := T#1h2m3.5s; n := 16#FF + 2#1010 + 8#17; r := 1.5E3 + REAL#-2.5;\n\
         s := 'it$'s'; w := \"wide\"; c := Color#red; d := D#2024-01-31; q := %QX0.1;\n\
         a.b[i + 1, 2].c := LIMIT(MN := 0, IN := x, MX := 10) + MAX(a, b, c);\n\
         tmr(IN := go, PT := T#1s, Q => done, NOT Q => notdone, ET =>);\n\
         inst(x, 3);\n\
         F();"
    ));
}

#[test]
fn control_statements() {
    insta::assert_snapshot!(parse(
        "IF a THEN x := 1; ELSIF b THEN x := 2; ELSE x := 3; END_IF;\n\
         CASE sel OF 1, 2: y := 1; 3..5, 7: y := 2; Color#red: y := 3; ELSE y := 0; END_CASE;\n\
         FOR i := 10 TO 1 BY -1 DO IF i = 5 THEN EXIT; END_IF; CONTINUE; END_FOR;\n\
         WHILE k < 10 DO k := k + 1; END_WHILE;\n\
         REPEAT k := k - 1; UNTIL k = 0 END_REPEAT;\n\
         ;;RETURN;"
    ));
}

#[test]
fn comments_pragmas_and_case_insensitive_keywords() {
    insta::assert_snapshot!(parse(
        "(* outer (* nested *) still comment *) if A then // line comment\n\
         {attribute 'hide'} b := TRUE; end_if"
    ));
}

#[test]
fn syntax_errors_recover_at_the_next_statement() {
    insta::assert_snapshot!(parse(
        "x := ;\n\
         y = 2;\n\
         z := 3\n\
         w := 4;\n\
         IF a x := 5; END_IF;\n\
         v := (1 + 2;\n\
         u := 2#102;\n\
         t := a ? b;\n\
         ok := TRUE;"
    ));
}

#[test]
fn unclosed_blocks_and_stray_keywords() {
    insta::assert_snapshot!(parse(
        "END_IF;\nFOR i := 1 TO 3 DO\n  x := i;\nWHILE b DO c := 1; END_WHILE;\nok := 1;"
    ));
}

#[test]
fn unsupported_syntax_is_named() {
    insta::assert_snapshot!(parse("y := p^;\nb := w.3;\nq := tmr.x(1);\nok := 1;"));
}

#[test]
fn one_expression_for_transitions() {
    let mut sm = SourceMap::new();
    let src = "  Level > 10 AND NOT Alarm  ";
    let file = sm.add("t.st", src);
    let mut diags = Diagnostics::new();
    let e = st::parse_expression(file, src, 100, &mut diags).unwrap();
    assert_eq!(expr(&e), "((Level > 10) AND Not(Alarm))");
    assert!(diags.is_empty());
    // The base offset moves every span.
    assert_eq!((e.span.start, e.span.end), (102, 126));
    let mut diags = Diagnostics::new();
    assert!(st::parse_expression(file, "a := b", 0, &mut diags).is_none());
    assert!(st::parse_expression(file, "", 0, &mut diags).is_none());
    assert_eq!(diags.error_count(), 2);
}
