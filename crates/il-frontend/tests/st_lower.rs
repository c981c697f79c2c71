//! ST lowered to IL: the printed IL of each construct (snapshots show the ST and the IL), and the
//! diagnostics of the lowering and of IL sema at the ST spans.

mod st_common;

const DECLS: &str = "TYPE Color : (red, green, blue); END_TYPE
TYPE Pt : STRUCT x : INT; y : REAL; END_STRUCT; END_TYPE
FUNCTION Scale : REAL
VAR_INPUT v : INT; k : REAL; END_VAR
END_FUNCTION
FUNCTION_BLOCK Fb
VAR_INPUT go : BOOL; n : INT; st : INT; END_VAR
VAR_OUTPUT q : BOOL; out : INT; END_VAR
VAR i : INT; a : ARRAY[0..9] OF INT; r : REAL; p : Pt; c : Color; tmr : TON; t : TIME; END_VAR
END_FUNCTION_BLOCK
";

fn lower(st: &str) -> String {
    let (il, diags) = st_common::compile(DECLS, "Fb", st);
    let body = il.split_once("END_VAR\n").map(|(_, b)| b).unwrap_or(&il);
    // Keep the VAR_TEMP block (the temporaries) and the body.
    let temps = il
        .find("VAR_TEMP")
        .map(|k| &il[k..k + il[k..].find("END_VAR").unwrap_or(0)])
        .unwrap_or("");
    let body = body
        .rsplit_once("END_VAR\n")
        .map(|(_, b)| b)
        .unwrap_or(body);
    format!("{st}\n---\n{temps}{body}---\n{diags}")
}

#[test]
fn expressions_use_deferred_operators_and_typed_temporaries() {
    insta::assert_snapshot!(lower(
        "out := n * (n - 2) + a[i + 1] MOD 3;
         r := Scale(n, 2.5) + INT_TO_REAL(n) ** 2.0;
         q := NOT go AND (n > 3 OR i = 0);
         out := LIMIT(MN := 0, IN := n + 1, MX := 100);
         out := -n;
         r := 2.0 ** 3.0;
         p.y := p.y + Scale(k := 1.0, v := p.x);"
    ));
}

#[test]
fn if_elsif_else() {
    insta::assert_snapshot!(lower(
        "IF go THEN out := 1; ELSIF n > 10 THEN out := 2; RETURN; ELSE out := 3; END_IF;"
    ));
}

#[test]
fn case_with_ranges_enums_and_else() {
    insta::assert_snapshot!(lower(
        "CASE n OF 1, 2: out := 10; 3..5: out := 20; ELSE out := 0; END_CASE;
         CASE c OF red: out := 1; Color#blue: out := 2; END_CASE;
         CASE n + 1 OF 7: out := 7; END_CASE;"
    ));
}

#[test]
fn for_loops_with_literal_and_runtime_steps() {
    insta::assert_snapshot!(lower(
        "FOR i := 0 TO 9 DO a[i] := i; END_FOR;
         FOR i := 10 TO 1 BY -3 DO IF i = 4 THEN EXIT; END_IF; END_FOR;
         FOR i := n TO n * 2 BY st DO CONTINUE; END_FOR;"
    ));
}

#[test]
fn while_repeat_and_fb_calls() {
    insta::assert_snapshot!(lower(
        "WHILE i < n DO i := i + 1; END_WHILE;
         REPEAT i := i - 1; UNTIL i <= 0 END_REPEAT;
         tmr(IN := go AND n > 0, PT := T#1s, Q => q, ET => t);
         q := tmr.ET > T#500ms;"
    ));
}

#[test]
fn lowering_errors_are_reported_in_st_terms() {
    insta::assert_snapshot!(lower(
        "EXIT;
         out := tmr(IN := go);
         IF n THEN out := 1; END_IF;
         CASE n OF F(1): out := 1; END_CASE;
         FOR r := 0 TO 1 DO out := 1; END_FOR;
         FOR i := 0 TO 1 BY 0 DO out := 1; END_FOR;
         out := LIMIT(0, IN := n, MX := 5);
         out := missing + 1;
         CONTINUE;"
    ));
}

#[test]
fn every_instruction_points_into_the_st_text() {
    use il_frontend::ast::{IlStmt, InstrKind, LibraryElement};
    let mut sm = diagnostics::SourceMap::new();
    let src = "FOR i := 0 TO 9 DO IF i > n THEN EXIT; END_IF; a[i + 1] := i * 2; END_FOR;";
    let file = sm.add("t.st", format!("{DECLS}{src}"));
    let mut diags = diagnostics::Diagnostics::new();
    let unit = il_frontend::parse(file, DECLS, &mut diags);
    let decls = il_frontend::st::Declarations::from_units(std::slice::from_ref(&unit));
    let pou = unit
        .items
        .iter()
        .find_map(|i| match i {
            LibraryElement::Pou(p) if p.name.is("Fb") => Some(p),
            _ => None,
        })
        .unwrap();
    let stmts = il_frontend::st::parse_statements(file, src, DECLS.len(), &mut diags);
    let mut low = il_frontend::st::PouLowering::new(&decls, pou);
    let il = low.statements(&stmts, &mut diags);
    let more = low.statements(&stmts, &mut diags);
    fn spans(code: &[IlStmt], out: &mut Vec<diagnostics::Span>) {
        for s in code {
            if let IlStmt::Instr(i) = s {
                out.push(i.span);
                if let InstrKind::Deferred { body, .. } = &i.kind {
                    spans(body, out);
                }
            }
        }
    }
    let mut all = Vec::new();
    spans(&il, &mut all);
    spans(&more, &mut all);
    assert!(!all.is_empty());
    for s in &all {
        assert!(s.start as usize >= DECLS.len() && s.end as usize <= DECLS.len() + src.len());
    }
    assert!(diags.is_empty());
}

#[test]
fn snippets_lowered_into_one_pou_share_labels_and_temporaries() {
    use il_frontend::ast::LibraryElement;
    let mut sm = diagnostics::SourceMap::new();
    let a = "IF go THEN out := LIMIT(0, n * 2, 9); END_IF;";
    let b = "n > 3 AND MAX(n + 1, 2) < 5";
    let c = "n + 1";
    let file = sm.add("t.st", format!("{DECLS}{a}{b}{c}"));
    let mut diags = diagnostics::Diagnostics::new();
    let unit = il_frontend::parse(file, DECLS, &mut diags);
    let decls = il_frontend::st::Declarations::from_units(std::slice::from_ref(&unit));
    let pou = unit
        .items
        .iter()
        .find_map(|i| match i {
            LibraryElement::Pou(p) if p.name.is("Fb") => Some(p),
            _ => None,
        })
        .unwrap();
    let mut low = il_frontend::st::PouLowering::new(&decls, pou);
    let sa = il_frontend::st::parse_statements(file, a, DECLS.len(), &mut diags);
    let eb = il_frontend::st::parse_expression(file, b, DECLS.len() + a.len(), &mut diags).unwrap();
    let ec =
        il_frontend::st::parse_expression(file, c, DECLS.len() + a.len() + b.len(), &mut diags)
            .unwrap();
    let mut text = il_frontend::print::body(&low.statements(&sa, &mut diags));
    text.push_str("; transition\n");
    text.push_str(&il_frontend::print::body(&low.condition(&eb, &mut diags)));
    text.push_str("; again\n");
    text.push_str(&il_frontend::print::body(&low.statements(&sa, &mut diags)));
    let label = low.fresh_label("SFC", eb.span);
    text.push_str(&format!("; caller's own label: {}\n", label.name));
    assert!(diags.is_empty());
    // A condition that is not BOOL is reported in ST terms.
    let _ = low.condition(&ec, &mut diags);
    let temps = low.finish(pou.span).unwrap();
    for v in &temps.vars {
        let mut t = String::new();
        il_frontend::print::operand(
            &mut t,
            &il_frontend::ast::Operand::Var(il_frontend::ast::VarRef {
                base: v.name.clone(),
                accessors: Default::default(),
                span: v.span,
            }),
        );
        text.push_str(&format!("; temp {t} : {:?}\n", v.ty));
    }
    text.push_str(&st_common::render(&sm, diags));
    insta::assert_snapshot!(text);
}
