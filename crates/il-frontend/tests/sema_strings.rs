//! Sema of the standard string functions: ANY_STRING inputs, integer lengths/positions, result types
//! (LEN/FIND give INT; the others the input string type, as long as the longest input, CONCAT the sum of
//! the lengths, capped at 254), and the diagnostics for misuse.

mod sema_support;
use il_frontend::sema::{Callee, Type};
use sema_support::{analyze_src, check, codes};

fn program(vars: &str, body: &str) -> String {
    format!("PROGRAM P\nVAR\n{vars}END_VAR\n{body}END_PROGRAM\n")
}

#[test]
fn string_functions_type_check_on_strings() {
    let src = program(
        "  s : STRING[10];\n  t : STRING[20];\n  w : WSTRING;\n  n : INT;\n  r : STRING;\n  rw : WSTRING;\n",
        "  LD s\n  LEN\n  ST n\n  LD s\n  LEFT 3\n  ST r\n  LD t\n  RIGHT n\n  ST r\n  LD s\n  MID 2, 1\n  ST r\n  LD s\n  CONCAT t, 'abc', s\n  ST r\n  LD s\n  INSERT t, 2\n  ST r\n  LD s\n  DELETE 1, 2\n  ST r\n  LD s\n  REPLACE 'x', 1, 2\n  ST r\n  LD s\n  FIND 'x'\n  ST n\n  LD w\n  CONCAT \"w\"\n  ST rw\n  LD w\n  FIND \"w\"\n  ST n\n",
    );
    let (_, d) = analyze_src(&src);
    assert!(d.is_empty(), "{d}");
}

#[test]
fn string_results_carry_the_longest_input_length() {
    let src = program(
        "  s : STRING[10];\n  t : STRING[20];\n  r : STRING;\n",
        "  CONCAT(IN1 := s, IN2 := t)\n  ST r\n  LEFT(IN := t, L := 2)\n  ST r\n",
    );
    let (m, d) = analyze_src(&src);
    assert!(d.is_empty(), "{d}");
    // `Pou::instrs` lists the instructions in source order.
    let results: Vec<Type> = m.pous[0]
        .instrs
        .iter()
        .filter_map(|id| match &m.instr_by_id(*id)?.callee {
            Some(Callee::Std { result, .. }) => Some(result.clone()),
            _ => None,
        })
        .collect();
    assert_eq!(
        results,
        [
            Type::String {
                wide: false,
                len: 30
            },
            Type::String {
                wide: false,
                len: 20
            }
        ]
    );
}

#[test]
fn misuse_of_string_functions_is_diagnosed() {
    let src = program(
        "  s : STRING;\n  w : WSTRING;\n  i : INT;\n  x : REAL;\n  r : STRING;\n",
        "  LD i\n  LEN\n  ST i\n  LD s\n  LEFT x\n  ST r\n  LD s\n  CONCAT w\n  ST r\n  LD s\n  MID 1\n  ST r\n  LD s\n  FIND 3\n  ST i\n  LD s\n  LEN\n  ST r\n",
    );
    assert_eq!(
        codes(&src),
        ["E1004", "E1004", "E1005", "E1020", "E1005", "E1006"]
    );
    insta::assert_snapshot!(check(&src));
}
