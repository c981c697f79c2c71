//! One snapshot per semantic check: the source and the diagnostics it gets, rendered for humans.

mod sema_support;
use sema_support::{check, codes};

#[test]
fn clean_program_has_no_diagnostics() {
    let src = "PROGRAM Main
VAR
  a, b : BOOL;
  n : INT;
  t : TON;
END_VAR
  LD a
  ANDN b
  ST t.IN
  LD T#5s
  PT t
  LD t.Q
  ST b
  LD n
  ADD 1
  ST n
END_PROGRAM
";
    assert_eq!(codes(src), Vec::<String>::new(), "{}", check(src));
}

#[test]
fn undeclared_name_is_reported_once_and_silences_follow_on_errors() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  n : INT;
  b : BOOL;
END_VAR
  LD speed
  ADD 1
  ST b
  LD n
  ST spede
END_PROGRAM
"
    ));
}

#[test]
fn duplicate_declarations() {
    insta::assert_snapshot!(check(
        "FUNCTION_BLOCK Motor
VAR_INPUT
  speed : INT;
END_VAR
VAR
  SPEED : REAL;
END_VAR
  LD speed
  ST speed
END_FUNCTION_BLOCK
"
    ));
}

#[test]
fn operator_not_defined_for_type() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  b : BOOL;
  r : REAL;
  i : INT;
END_VAR
  LD b
  ADD 1
  ST i
  LD r
  AND r
  ST r
END_PROGRAM
"
    ));
}

#[test]
fn operand_type_differs_from_current_result() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  i : INT;
  w : WORD;
  r : REAL;
  d : DINT;
END_VAR
  LD i
  ADD w
  ST i
  LD d
  MUL r
  ST r
  LD i
  ADD d
  ST d
END_PROGRAM
"
    ));
}

#[test]
fn store_of_wrong_type() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  i : INT;
  b : BOOL;
  d : DINT;
END_VAR
  LD i
  ST b
  LD d
  ST i
  LD i
  ST d
END_PROGRAM
"
    ));
}

#[test]
fn unreachable_code_does_not_fall_through_into_a_label() {
    // `LD x` is dead (after JMP): the clash at `both` is between the two jumps (BOOL and REAL).
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR x : INT; b : BOOL; r : REAL; END_VAR
  LD b
  JMPC both
  LD r
  JMP both
  LD x
both:
  ST x
END_PROGRAM
"
    ));
}

#[test]
fn type_clash_where_jumps_meet_names_both_jumps() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  go : BOOL;
  n : INT;
  out : BOOL;
END_VAR
  LD go
  JMPC done
  LD n
done:
  ST out
  LD go
  JMPC reload
  LD n
reload:
  LD n
  ST n
END_PROGRAM
"
    ));
}

#[test]
fn undefined_and_duplicate_labels() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  go : BOOL;
END_VAR
  LD go
  JMPC nowhere
again: LD go
again: ST go
END_PROGRAM
"
    ));
}

#[test]
fn call_arguments_are_checked() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  t : TON;
  go : BOOL;
  n : INT;
  done : BOOL;
END_VAR
  CAL t(IN := go, TIME := T#5s)
  CAL t(IN := go, PT := n)
  CAL t(IN := go, Q := done)
  CAL t(PT => n)
  CAL t(IN := go, PT := T#1s, Q => done)
END_PROGRAM
"
    ));
}

#[test]
fn writes_to_constants_and_inputs() {
    insta::assert_snapshot!(check(
        "FUNCTION_BLOCK Fb
VAR_INPUT
  start : BOOL;
END_VAR
VAR CONSTANT
  max : INT := 10;
  locked : BOOL := TRUE;
END_VAR
VAR
  t : TON;
END_VAR
  LD 5
  ST max
  LD FALSE
  ST start
  S start
  LD t.Q
  ST t.Q
  CAL t(IN := FALSE, Q => start)
  R locked
END_FUNCTION_BLOCK
"
    ));
}

#[test]
fn result_computed_and_never_used_is_a_warning() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  a, b, c : INT;
END_VAR
  LD a
  ADD 1
  LD b
  ST c
END_PROGRAM
"
    ));
}

#[test]
fn s_and_r_without_operand() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  go : BOOL;
END_VAR
  LD go
  S
  R go
END_PROGRAM
"
    ));
}

#[test]
fn typed_literal_out_of_range_and_untyped_literal_adapting() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  i : INT;
  b : BOOL;
END_VAR
  LD INT#40000
  ST i
  LD 40000
  ST i
  LD 2
  ST b
  LD 1
  ST b
END_PROGRAM
"
    ));
}

#[test]
fn conditions_must_be_bool() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  n : INT;
END_VAR
  LD n
  JMPC done
  RETC
done:
  LD n
  ST n
END_PROGRAM
"
    ));
}

#[test]
fn unreachable_code_and_missing_current_result() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  x : INT;
END_VAR
  ST x
  JMP done
  LD x
  ST x
done:
  LD x
  ST x
END_PROGRAM
"
    ));
}

#[test]
fn unknown_function_and_wrong_arity() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  x, y : INT;
  g : BOOL;
END_VAR
  LD x
  CLAMP 0, 10
  ST x
  LD g
  SEL x
  ST x
  LD g
  SEL x, y
  ST x
END_PROGRAM
"
    ));
}

#[test]
fn fb_input_operators_and_s_r_on_instances() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  ff : SR;
  c : CTU;
  n : INT;
  go : BOOL;
END_VAR
  LD go
  S1 ff
  R ff
  S ff
  PT c
  LD n
  PV c
  CU c
END_PROGRAM
"
    ));
}

#[test]
fn external_variables_are_bound_to_globals() {
    insta::assert_snapshot!(check(
        "VAR_GLOBAL
  speed : REAL;
END_VAR
PROGRAM Main
VAR_EXTERNAL
  speed : INT;
  missing : BOOL;
END_VAR
  LD speed
  ST speed
END_PROGRAM
"
    ));
}

#[test]
fn unknown_type_gives_one_error() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  t : TIMER;
  b : BOOL;
END_VAR
  LD t.Q
  ST b
  CAL t(IN := b)
END_PROGRAM
"
    ));
}

#[test]
fn deferred_operators_type_their_nested_list() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  a, b, c, x : BOOL;
  i, j : INT;
  r : REAL;
END_VAR
  LD a
  AND( b
  OR c
  )
  ST x
  LD i
  ADD( j
  MUL r
  )
  ST i
  LD a
  OR(
  LD i
  )
  ST x
END_PROGRAM
"
    ));
}

#[test]
fn fb_instances_are_not_values() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  t, u : TON;
  n : INT;
END_VAR
  LD t
  ST u
  LD t
  ST n
  CAL n
  LD n
  IN n
END_PROGRAM
"
    ));
}

#[test]
fn configuration_elements_are_checked() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR_INPUT
  sp : REAL;
END_VAR
VAR_OUTPUT
  q : BOOL;
END_VAR
VAR_EXTERNAL
  lamp : BOOL;
END_VAR
  LD sp
  GT 1.5
  ST q
  ST lamp
END_PROGRAM
FUNCTION_BLOCK NotAProgram
  LD TRUE
  RET
END_FUNCTION_BLOCK
CONFIGURATION Cell
VAR_GLOBAL
  speed : REAL;
  count : INT;
  lamp : BOOL;
END_VAR
RESOURCE Cpu
TASK Fast(INTERVAL := T#10ms, PRIORITY := 1);
TASK Slow(INTERVAL := 5, PRIORITY := 2);
PROGRAM m1 WITH Fast : Main (sp := speed, q => lamp);
PROGRAM m2 WITH Medium : Main (sp := count, q := lamp, zz := speed);
PROGRAM m3 : NotAProgram;
PROGRAM m4 : Nowhere;
END_RESOURCE
END_CONFIGURATION
"
    ));
}

#[test]
fn alias_cycles_and_fb_type_names_used_as_instances() {
    insta::assert_snapshot!(check(
        "TYPE
  A : B;
  B : A;
END_TYPE
PROGRAM Main
VAR
  x : A;
END_VAR
  CAL TON
  LD x
  ST x
END_PROGRAM
"
    ));
}

#[test]
fn operand_mistakes_reported_by_the_parser_are_not_reported_again() {
    let src = "PROGRAM Main
VAR
  b : BOOL;
END_VAR
  LD b
  NOT b
  ST b
  ADD
END_PROGRAM
";
    assert_eq!(codes(src), vec!["E0013", "E0012"], "{}", check(src));
}

#[test]
fn operators_without_their_operand_in_a_built_tree() {
    // Trees built by other stages (ladder lowering) do not go through the parser's checks.
    use il_frontend::ast::*;
    use il_frontend::Span;
    let s = |a: usize, b: usize| Span::new(diagnostics::FileId(0), a, b);
    let instr = |op, a, b| {
        IlStmt::Instr(Instruction {
            kind: InstrKind::Simple {
                op,
                negate: false,
                operand: None,
            },
            span: s(a, b),
        })
    };
    let unit = CompilationUnit {
        items: vec![LibraryElement::Pou(Pou {
            class: false,
            kind: PouKind::Program,
            name: Ident::new("P", s(0, 1)),
            return_type: None,
            var_blocks: vec![],
            body: vec![
                instr(Op::Ld, 2, 4),
                instr(Op::Add, 5, 8),
                instr(Op::St, 9, 11),
            ],
            span: s(0, 11),
        })],
        ..Default::default()
    };
    let mut diags = diagnostics::Diagnostics::new();
    il_frontend::sema::analyze(&[unit], &mut diags);
    let got: Vec<(&str, u32)> = diags
        .iter()
        .map(|d| (d.code.0, d.span.unwrap().start))
        .collect();
    assert_eq!(got, vec![("E1020", 2), ("E1020", 5), ("E1020", 9)]);
}

#[test]
fn function_that_never_sets_its_result() {
    insta::assert_snapshot!(check(
        "FUNCTION Twice : INT
VAR_INPUT
  v : INT;
END_VAR
  LD v
  MUL 2
END_FUNCTION
"
    ));
}

#[test]
fn invalid_initial_values() {
    insta::assert_snapshot!(check(
        "TYPE
  Color : (red, green);
END_TYPE
PROGRAM Main
VAR
  b : BOOL := 5;
  a : ARRAY [0..1] OF INT := [1, 2, 3];
  c : Color := blue;
  t : TON := (PT := T#1s, XX := 1);
  n : INT := other;
END_VAR
  LD b
  ST b
END_PROGRAM
"
    ));
}

#[test]
fn stores_into_what_cannot_be_written() {
    insta::assert_snapshot!(check(
        "PROGRAM Main
VAR
  x : BOOL;
END_VAR
  LD x
  ST 5
  ST %IX0.1
  ST %QX0.1
END_PROGRAM
"
    ));
}

/// A user FUNCTION without inputs in operator form takes no current result (matiec reads it so as
/// well); with an operand it is E1020, whose hint says that it has no inputs.
#[test]
fn function_without_inputs_in_operator_form() {
    let decl = "FUNCTION seven : INT\n  LD 7\n  ST seven\nEND_FUNCTION\n";
    let ok = format!(
        "{decl}PROGRAM Main\nVAR\n  x : INT;\nEND_VAR\n  LD x\n  ADD 1\n  seven\n  ST x\nEND_PROGRAM\n"
    );
    assert!(codes(&ok).is_empty(), "{}", check(&ok));
    let bad = format!(
        "{decl}PROGRAM Main\nVAR\n  x : INT;\nEND_VAR\n  LD x\n  seven 5\n  ST x\nEND_PROGRAM\n"
    );
    let (_, diags) = sema_support::analyze_src(&bad);
    assert!(
        diags.contains("E1020") && diags.contains("seven has no inputs: call it without operands"),
        "{diags}"
    );
}
