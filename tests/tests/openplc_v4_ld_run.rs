//! OpenPLC Editor v4 ladder POUs (round 24 of issue #13): the editor saves a Ladder POU as
//! `pous/programs/main.ld`, its IEC declarations then its rungs as JSON (React Flow nodes
//! `powerRail`, `contact`, `coil`, `block`, `variable`, `parallel`, and the edges between their
//! handles). ladderc now reads the rungs as the editor converts them for its compiler
//! (`ladder-xml.ts`), and the project folder runs end to end (before: one E1073 for the file, so
//! 10 of 10 projects of one repository could not run):
//! - contacts in series (AND), a parallel branch (OR), negated contacts and coils, a falling-edge
//!   contact and a rising-edge coil; `END_VAR` in a rung comment (before: the JSON was looked for
//!   after the last `END_VAR` of the file);
//! - set and reset coils, a rising-edge contact, and a seal-in through a parallel branch, in a
//!   file whose JSON is on one line (the ST that does not fit goes after it);
//! - a TON driven by a contact with its preset and elapsed time at `variable` nodes, a CTU
//!   counting the pulses of a rising-edge contact, MOVE with EN/ENO, GT's result driving a coil;
//! - JSON that is not the editor's (malformed, a name that is not one, an unknown node, a loop):
//!   one located E1064/E1065, exit 1, nothing of the text becomes statements.

mod common;
use common::{check_text, column, repo_root, run_stimulated_files};
use std::path::PathBuf;

fn fixture(name: &str) -> PathBuf {
    repo_root()
        .join("tests/tests/fixtures/openplc_v4_ld")
        .join(name)
}

/// `ladderc run DIR` (10 ms cycles, the project's 10 ms task) with `stimulus` rows.
fn run(project: &str, cycles: u32, stimulus: &str, watch: &str) -> String {
    let (trace, stderr) = run_stimulated_files(
        &[fixture(project)],
        &["--cycle-ms", "10"],
        cycles,
        stimulus,
        watch,
    );
    assert!(!stderr.contains("error["), "{stderr}");
    trace
}

/// Series contacts are AND, a parallel branch (`parallel` open/close) is OR, a negated contact
/// reads the negation, a negated coil writes the negation of its power (NotNotA follows A), a
/// falling-edge contact is TRUE one scan when A falls (and on the first scan, as IEC 61131-3's
/// F_TRIG with A FALSE), a rising-edge coil is TRUE one scan when its power rises. A rung
/// comment holding `END_VAR {"rungs": []}` does not hide where the JSON starts.
#[test]
fn and_or_negated_and_edge_rungs_run() {
    let trace = run(
        "logic",
        6,
        "1,instance0.A,TRUE\n2,instance0.B,TRUE\n3,instance0.A,FALSE\n4,instance0.B,FALSE\n",
        "instance0.Both,instance0.Either,instance0.NotA,instance0.NotNotA,instance0.AFell,instance0.BRose",
    );
    let col = |n: &str| column(&trace, &format!("instance0.{n}"));
    assert_eq!(col("Both"), [0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
    assert_eq!(col("Either"), [0.0, 1.0, 1.0, 1.0, 0.0, 0.0]);
    assert_eq!(col("NotA"), [1.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
    assert_eq!(col("NotNotA"), [0.0, 1.0, 1.0, 0.0, 0.0, 0.0]);
    assert_eq!(col("AFell"), [1.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    assert_eq!(col("BRose"), [0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
}

/// A rising-edge Start sets Motor (set coil), Stop resets it (reset coil, a later rung: with both
/// pressed the reset wins); Run holds itself through a parallel branch until Stop. The JSON is
/// one line: the statements that do not fit in its blanks follow it.
#[test]
fn set_reset_coils_and_a_seal_in_latch() {
    let trace = run(
        "latch",
        8,
        "1,instance0.Start,TRUE\n2,instance0.Start,FALSE\n4,instance0.Stop,TRUE\n\
         5,instance0.Stop,FALSE\n6,instance0.Start,TRUE\n6,instance0.Stop,TRUE\n",
        "instance0.Motor,instance0.Run",
    );
    let latched = [0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0];
    assert_eq!(column(&trace, "instance0.Motor"), latched);
    assert_eq!(column(&trace, "instance0.Run"), latched);
}

/// A TON (instance `Delay`, PT `T#50ms` at a `variable` node) driven by a contact sets Done 50 ms
/// after Go, its ET written to Elapsed; a CTU counts the rising edges of Pulse (PV 3 at a
/// variable node: Full at the third), Clear (a variable at R) resets it; MOVE runs while Load (EN)
/// holds, its ENO drives Moved; GT's result (OUT) drives Over1 (Count > 1).
#[test]
fn a_timer_a_counter_and_functions_with_en() {
    let trace = run(
        "timer_counter",
        10,
        "1,instance0.Go,TRUE\n1,instance0.Pulse,TRUE\n2,instance0.Pulse,FALSE\n\
         3,instance0.Pulse,TRUE\n4,instance0.Pulse,FALSE\n5,instance0.Pulse,TRUE\n\
         5,instance0.Load,TRUE\n6,instance0.Load,FALSE\n8,instance0.Clear,TRUE\n9,instance0.Clear,FALSE\n",
        "instance0.Done,instance0.Elapsed,instance0.Count,instance0.Full,instance0.Snapshot,\
         instance0.Moved,instance0.Over1",
    );
    let col = |n: &str| column(&trace, &format!("instance0.{n}"));
    assert_eq!(
        col("Done"),
        [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]
    );
    assert!(
        trace.lines().nth(7).unwrap().contains(",T#50ms,"),
        "{trace}"
    );
    assert_eq!(
        col("Count"),
        [0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 3.0, 0.0, 0.0]
    );
    assert_eq!(
        col("Full"),
        [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.0, 0.0]
    );
    assert_eq!(
        col("Snapshot"),
        [0.0, 0.0, 0.0, 0.0, 0.0, 3.0, 3.0, 3.0, 3.0, 3.0]
    );
    assert_eq!(
        col("Moved"),
        [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0]
    );
    assert_eq!(
        col("Over1"),
        [0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0]
    );
}

/// The declarations of the hostile files below.
const HEAD: &str = "PROGRAM main\nVAR\n\tDone : bool AT %QX0.0;\n\tT1 : TON;\nEND_VAR\n\n";

/// JSON the editor does not write is one located error, exit 1: malformed JSON at the place the
/// reader stopped (E1064), a pin variable carrying statements at its node (E1065: never compiled),
/// an unknown node type and a loop of edges at the node (E1064), and no second diagnostic.
#[test]
fn hostile_ladder_json_is_one_located_error() {
    let rail = r#"{"id":"L","type":"powerRail","data":{"variant":"left"}}"#;
    let cases = [
        (
            "{\"name\":\"main\",\n\"rungs\":[{\"id\":\"r1\",\"nodes\":[\n{\"id\":\"c\",\"type\":\"contact\"\n".to_string(),
            "main.ld:9:26: error[E1064]: the ladder JSON is not well-formed: EOF while parsing an object",
        ),
        (
            format!(
                "{{\"name\":\"main\",\"rungs\":[{{\"id\":\"r1\",\"nodes\":[{rail},\n\
                 {{\"id\":\"B\",\"type\":\"block\",\"data\":{{\"variant\":{{\"name\":\"TON\",\"type\":\"function-block\"}},\"variable\":{{\"name\":\"T1\"}}}}}},\n\
                 {{\"id\":\"V\",\"type\":\"variable\",\"data\":{{\"variant\":\"input\",\"variable\":{{\"name\":\"T#5s); Done := TRUE; (\"}},\"block\":{{\"id\":\"B\",\"handleId\":\"PT\"}}}}}}],\n\
                 \"edges\":[{{\"source\":\"L\",\"sourceHandle\":\"left-rail\",\"target\":\"B\",\"targetHandle\":\"IN\"}}]}}]}}\n"
            ),
            "main.ld:9:8: error[E1065]: rung 1: `T#5s); Done := TRUE; (` at the block pin `PT` is not a variable or a literal",
        ),
        (
            format!(
                "{{\"name\":\"main\",\"rungs\":[{{\"id\":\"r1\",\"nodes\":[{rail}]}},\n\
                 {{\"id\":\"r2\",\"nodes\":[{rail},\n{{\"id\":\"W\",\"type\":\"wire\"}}],\"edges\":[]}}]}}\n"
            ),
            "main.ld:9:8: error[E1064]: rung 2: a node of type `wire`, which ladderc does not read",
        ),
        (
            "{\"name\":\"main\",\"rungs\":[{\"id\":\"r1\",\"nodes\":[\n\
             {\"id\":\"a\",\"type\":\"contact\",\"data\":{\"variable\":{\"name\":\"Done\"}}},\n\
             {\"id\":\"b\",\"type\":\"coil\",\"data\":{\"variable\":{\"name\":\"Done\"}}}],\n\
             \"edges\":[{\"source\":\"a\",\"target\":\"b\"},{\"source\":\"b\",\"target\":\"a\"}]}]}\n"
                .to_string(),
            "main.ld:8:8: error[E1064]: rung 1: its connections form a loop",
        ),
    ];
    for (json, want) in cases {
        let src = format!("{HEAD}{json}END_PROGRAM\n");
        let (code, lines) = check_text("main.ld", &src);
        assert_eq!(code, Some(1), "{lines:?}");
        let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
        assert_eq!(errors.len(), 1, "{lines:?}");
        assert!(errors[0].starts_with(want), "{lines:?}");
    }
}

/// An error of the program the rungs make (an undeclared contact variable) points at the line of
/// the contact's node in the JSON, not at a line of text ladderc made up.
#[test]
fn a_contact_of_an_undeclared_variable_points_at_its_node() {
    let src = format!(
        "{HEAD}{{\n  \"name\": \"main\",\n  \"rungs\": [\n    {{\n      \"id\": \"r1\",\n      \"nodes\": [\n        \
         {{ \"id\": \"L\", \"type\": \"powerRail\", \"data\": {{ \"variant\": \"left\" }} }},\n        \
         {{ \"id\": \"CONTACT_1\", \"type\": \"contact\",\n          \"data\": {{ \"variant\": \"default\", \"variable\": {{ \"name\": \"Strat\" }} }} }},\n        \
         {{ \"id\": \"COIL_1\", \"type\": \"coil\", \"data\": {{ \"variant\": \"default\", \"variable\": {{ \"name\": \"Done\" }} }} }}\n      ],\n      \
         \"edges\": [\n        {{ \"source\": \"L\", \"target\": \"CONTACT_1\" }},\n        {{ \"source\": \"CONTACT_1\", \"target\": \"COIL_1\" }}\n      ]\n    }}\n  ]\n}}\n"
    );
    let (code, lines) = check_text("main.ld", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    // line 14 holds the contact's id
    assert!(
        errors[0].contains("main.ld:14:") && errors[0].contains("undeclared name `Strat`"),
        "{lines:?}"
    );
}
