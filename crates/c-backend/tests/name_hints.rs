//! The C backend takes each variable's position from sema's resolution of the name (`Model::names`)
//! and checks it against the name; anything else is looked up in the POU's name index. The C must be
//! the same whether sema's resolutions are all there, missing, or point at other variables.

mod support;

use c_backend::{CProgram, Options, TargetProfile};
use il_frontend::sema::{KeyTable, NameRef};

const SRC: &str = "
FUNCTION_BLOCK Latch
VAR_INPUT set : BOOL; reset : BOOL; END_VAR
VAR_OUTPUT q : BOOL; END_VAR
VAR count : INT; END_VAR
    LD set
    OR q
    ANDN reset
    ST q
    LD count
    ADD 1
    ST count
END_FUNCTION_BLOCK

FUNCTION Scale : INT
VAR_INPUT x : INT; k : INT; END_VAR
    LD x
    MUL k
    ST Scale
END_FUNCTION

PROGRAM Main
VAR a0 : BOOL; b0 : BOOL; q0 : BOOL; n0 : INT; l0 : Latch; t0 : TON; END_VAR
    LD a0
    ANDN b0
    ST q0
    CAL l0(set := a0, reset := b0)
    LD l0.q
    ST b0
    LD n0
    Scale 3
    ST n0
    CAL t0(IN := q0, PT := T#10ms)
    LD t0.Q
    ST a0
END_PROGRAM
";

fn c_text(program: &CProgram) -> Vec<(String, String)> {
    let mut files: Vec<(String, String)> = program
        .files
        .iter()
        .map(|(p, t)| (p.clone(), t.clone()))
        .collect();
    files.sort();
    files
}

#[test]
fn c_is_the_same_with_sema_names_present_missing_or_wrong() {
    let (units, model, map) = support::frontend(SRC);
    let profile = TargetProfile::default();
    let opts = Options::default();
    let vars: usize = model
        .names
        .iter()
        .filter(|(_, r)| matches!(r, NameRef::Var(_)))
        .count();
    assert!(vars >= 20, "sema resolved {vars} variable names");
    let reference = c_text(&support::generate_with(
        &units, &model, &map, &profile, &opts,
    ));

    let mut missing = model.clone();
    missing.names = KeyTable::default();
    let without = c_text(&support::generate_with(
        &units, &missing, &map, &profile, &opts,
    ));
    assert_eq!(without, reference, "without sema's names");

    // Every variable resolution moved to the next position: each one fails its name check.
    let mut wrong = model.clone();
    let mut moved = KeyTable::default();
    for (span, r) in model.names.iter() {
        let r = match *r {
            NameRef::Var(i) => NameRef::Var(i + 1),
            other => other,
        };
        moved.insert(*span, r);
    }
    wrong.names = moved;
    let misled = c_text(&support::generate_with(
        &units, &wrong, &map, &profile, &opts,
    ));
    assert_eq!(misled, reference, "with wrong positions");
}
