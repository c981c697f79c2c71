//! `R_EDGE` / `F_EDGE` declarations: parsed into `VarDecl::edge`, printed back, kept by sema on BOOL
//! inputs of function blocks (`Variable::edge`) and reported anywhere else (E1100) or on a non-BOOL
//! input (E1101).

mod sema_support;
use il_frontend::ast::{Edge, LibraryElement, PouKind};
use sema_support::{analyze_src, check, codes};

const FB: &str = "FUNCTION_BLOCK fb
VAR_INPUT
  a, b : BOOL R_EDGE;
  c : BOOL F_EDGE;
  d : BOOL;
END_VAR
VAR_OUTPUT
  q : BOOL;
END_VAR
  LD a
  OR c
  ST q
END_FUNCTION_BLOCK
";

fn parse(src: &str) -> il_frontend::ast::CompilationUnit {
    let mut diags = diagnostics::Diagnostics::new();
    let u = il_frontend::parse(diagnostics::FileId(0), src, &mut diags);
    assert!(diags.is_empty(), "{diags:?}");
    u
}

#[test]
fn edge_qualifiers_are_parsed_and_printed() {
    let u = parse(FB);
    let LibraryElement::Pou(p) = &u.items[0] else {
        panic!("no POU");
    };
    let edges: Vec<(String, Option<Edge>)> = p.var_blocks[0]
        .vars
        .iter()
        .map(|d| (d.name.name.clone(), d.edge))
        .collect();
    assert_eq!(
        edges,
        [
            ("a".to_string(), Some(Edge::Rising)),
            ("b".to_string(), Some(Edge::Rising)),
            ("c".to_string(), Some(Edge::Falling)),
            ("d".to_string(), None)
        ]
    );
    let printed = il_frontend::print::unit(&u);
    assert!(printed.contains("a : BOOL R_EDGE;"), "{printed}");
    assert!(printed.contains("c : BOOL F_EDGE;"), "{printed}");
    // printing is a fixed point
    assert_eq!(il_frontend::print::unit(&parse(&printed)), printed);
}

#[test]
fn sema_keeps_edges_of_bool_fb_inputs() {
    let (m, d) = analyze_src(FB);
    assert!(d.is_empty(), "{d}");
    let p = m
        .pous
        .iter()
        .find(|p| p.kind == PouKind::FunctionBlock)
        .unwrap();
    let edges: Vec<Option<Edge>> = p.vars.iter().map(|v| v.edge).collect();
    assert_eq!(
        edges,
        [
            Some(Edge::Rising),
            Some(Edge::Rising),
            Some(Edge::Falling),
            None,
            None
        ]
    );
}

#[test]
fn misplaced_or_non_bool_edge_qualifiers_are_errors() {
    let src = "TYPE s : STRUCT x : BOOL R_EDGE; END_STRUCT; END_TYPE
VAR_GLOBAL g : BOOL F_EDGE; END_VAR
FUNCTION_BLOCK fb
VAR_INPUT n : INT R_EDGE; END_VAR
VAR_OUTPUT o : BOOL R_EDGE; END_VAR
VAR m : BOOL F_EDGE; END_VAR
END_FUNCTION_BLOCK
FUNCTION f : BOOL
VAR_INPUT i : BOOL R_EDGE; END_VAR
  LD i
  ST f
END_FUNCTION
PROGRAM p
VAR_INPUT k : BOOL R_EDGE; END_VAR
END_PROGRAM
";
    assert_eq!(
        codes(src),
        ["E1100", "E1100", "E1101", "E1100", "E1100", "E1100", "E1100"]
    );
    insta::assert_snapshot!(check(src));
    // the qualifier is dropped where it is reported
    let (m, _) = analyze_src(src);
    assert!(m
        .pous
        .iter()
        .all(|p| p.vars.iter().all(|v| v.edge.is_none())));
}
