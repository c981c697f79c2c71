//! One snapshot per compiler error kind (E6001..E6015), rendered short (file:line:col) and human.

use diagnostics::{render, MessageFormat};
use drive_script::compile_str;

fn diags(text: &str) -> String {
    let (map, r) = compile_str("prog.ds", text);
    let list = r.expect_err("the script must be rejected").into_sorted();
    format!(
        "{}\n{}",
        render(&map, &list, MessageFormat::Short),
        render(&map, &list, MessageFormat::Human)
    )
}

const HEAD: &str = "S:: MOTION 0;\nS:: EVENT 0;\n";

#[test]
fn e6001_missing_statement_start() {
    insta::assert_snapshot!(diags(
        "S:: MOTION 0;\nEVENT 0;\nS:: EVENT 0;\nS:: IF TRUE;\nS:: THEN MD0 = 1;\n"
    ));
}

#[test]
fn e6002_missing_semicolon() {
    insta::assert_snapshot!(diags(
        "S:: MOTION 0;\nS:: EVENT 0;\nS:: IF DI_0 = HIGH\nS:: THEN DO_0 = HIGH;\n"
    ));
}

#[test]
fn e6003_unknown_instruction() {
    insta::assert_snapshot!(diags(&format!(
        "{HEAD}S:: IF TRUE;\nS:: THEN RelativePosition = 10000;\n"
    )));
}

#[test]
fn e6004_parameter_and_memory_index_out_of_range() {
    insta::assert_snapshot!(diags(&format!("{HEAD}S:: IF P16 > 0;\nS:: THEN MD50 = 1;\nS:: EVENT 1;\nS:: IF TRUE;\nS:: THEN DO_16 = HIGH;\n")));
}

#[test]
fn e6005_event_without_if_or_then() {
    insta::assert_snapshot!(diags(
        "S:: MOTION 0;\nS:: EVENT 0;\nS:: THEN MD0 = 1;\nS:: EVENT 1;\nS:: IF TRUE;\nS:: EVENT 2;\nS:: IF TRUE;\nS:: IF TRUE;\nS:: THEN MD0 = 2;\n"
    ));
}

#[test]
fn e6006_next_motion_id_to_a_missing_motion() {
    insta::assert_snapshot!(diags(&format!(
        "{HEAD}S:: IF MotionDone;\nS:: THEN NextMotionID = 3;\n"
    )));
}

#[test]
fn e6007_jump_or_loop_to_a_missing_event() {
    insta::assert_snapshot!(diags(&format!(
        "{HEAD}S:: IF TRUE;\nS:: THEN Jump = 4 AND Loop(MD1) = 1;\n"
    )));
}

#[test]
fn e6008_capacities_exceeded() {
    let mut text = format!(
        "{HEAD}S:: IF DI_0 AND DI_1 AND DI_2 AND DI_3 AND DI_4;\nS:: THEN MD0=1 AND MD1=1 AND MD2=1 AND MD3=1 AND MD4=1 AND MD5=1 AND MD6=1 AND MD7=1 AND MD8=1;\n"
    );
    for m in 1..33 {
        text.push_str(&format!(
            "S:: MOTION {m};\nS:: EVENT 0;\nS:: IF TRUE;\nS:: THEN Stop;\n"
        ));
    }
    let out = diags(&text);
    // The short lines only (the human rendering of 32 Motions adds nothing).
    let short: Vec<&str> = out.lines().filter(|l| l.starts_with("prog.ds:")).collect();
    assert_eq!(short.len(), 3, "one error per capacity, no cascade: {out}");
    insta::assert_snapshot!(short.join("\n"));
}

#[test]
fn e6008_event_pool_capacity() {
    let mut text = String::new();
    for m in 0..2 {
        text.push_str(&format!("S:: MOTION {m};\n"));
        for e in 0..130 {
            text.push_str(&format!("S:: EVENT {e}; S:: IF TRUE; S:: THEN Stop;\n"));
        }
    }
    let out = diags(&text);
    insta::assert_snapshot!(out.lines().next().unwrap());
}

#[test]
fn e6009_or_and_not_in_a_condition() {
    insta::assert_snapshot!(diags(&format!(
        "{HEAD}S:: IF DI_0 = HIGH OR DI_1 = HIGH;\nS:: THEN DO_0 = HIGH;\nS:: EVENT 1;\nS:: IF NOT DI_0;\nS:: THEN DO_0 = LOW;\n"
    )));
}

#[test]
fn e6010_syntax_errors() {
    insta::assert_snapshot!(diags(&format!(
        "{HEAD}S:: IF TRUE;\nS:: THEN MD0 = MD1 + MD2 * 2;\nS:: EVENT 1;\nS:: IF MD0 > ;\nS:: THEN MD0 = 1 MD1 = 2;\nS:: EVENT 2;\nS:: IF @;\nS:: ;\nS:: EVENT 3;\nS:: IF TRUE;\nS:: THEN MD0 = MD1 OR MD2;\nS:: EVENT 4;\nS:: IF TRUE;\nS:: THEN MD0 = NOT MD1;\n"
    )));
}

#[test]
fn e6011_statements_out_of_place() {
    insta::assert_snapshot!(diags(
        "S:: MD0 = 1;\nS:: INIT;\nS:: P0 = 5;\nS:: PARAM;\nS:: IF TRUE;\nS:: MOTION 0;\nS:: Velocity = 5;\nS:: EVENT 0;\nS:: IF TRUE;\nS:: THEN Stop;\n"
    ));
}

#[test]
fn e6012_numbering_out_of_sequence() {
    insta::assert_snapshot!(diags(
        "S:: MOTION 1;\nS:: MOTION 0;\nS:: EVENT 1;\nS:: EVENT 0;\nS:: IF TRUE;\nS:: THEN Stop;\n"
    ));
}

#[test]
fn e6013_wrong_direction() {
    insta::assert_snapshot!(diags(&format!(
        "{HEAD}S:: IF Velocity > 100;\nS:: THEN P0 = 5;\nS:: EVENT 1;\nS:: IF TRUE;\nS:: THEN ActualPosition = 0;\nS:: EVENT 2;\nS:: IF TRUE;\nS:: THEN Loop(P1) = 0;\n"
    )));
}

#[test]
fn e6014_numbers_out_of_range() {
    insta::assert_snapshot!(diags(
        "S:: INIT;\nS:: MD0 = 3000000000;\nS:: EventsPerCycle = 0;\nS:: MOTION 0;\nS:: EVENT 0;\nS:: IF MD0 > 10ms;\nS:: THEN MD1 = 0x1FFFFFFFF;\n"
    ));
}

#[test]
fn e6015_no_motion_or_empty_motion() {
    insta::assert_snapshot!(diags("S:: PARAM;\nS:: P0 = 100;\n"));
    insta::assert_snapshot!(diags(
        "S:: MOTION 0;\nS:: MOTION 1;\nS:: EVENT 0;\nS:: IF TRUE;\nS:: THEN NextMotionID = 0;\n"
    ));
}
