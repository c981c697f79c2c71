//! PROPERTYs of function blocks (issue #13: CODESYS and TwinCAT projects use them), end to end
//! through `ladderc run`: the Get accessor runs where the property is read (in expressions, IF,
//! ELSIF and WHILE conditions, inside its own block as `P` and `THIS^.P`, from another function
//! block and from the program), the Set accessor where it is written; the same block as an `.st`
//! file, as TwinCAT `.TcPOU` files and as a CODESYS PLCopen XML export gives the same trace; each
//! misuse is one located diagnostic.

mod common;
use common::{check_text, ladderc, rejected_heads, run_traced as run, run_traced_files};

use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/oop_property")
        .join(name)
}

const WATCH: &str = "MAIN.twice,MAIN.band,MAIN.n,MAIN.reads,MAIN.line.total";

/// The trace of `motor.st` (and of its TwinCAT and CODESYS forms), worked out by hand: each cycle
/// the block's body reads Speed (one read) and writes Speed + 7 (the Set clamps to 100); MAIN reads
/// it for `twice`, the first IF (at 63 > 60 in cycle 8 it writes 0), the IF/ELSIF (the ELSIF's read
/// only when the IF's test failed) and each test of the WHILE (n counts 20s below Speed); `reads`
/// is the Get accessor's count; Line's motor steps by 30 (clamped at 100) and `total` is its Speed
/// plus 1000 times its two reads a cycle so far.
const TRACE: &str = "cycle,time_ms,MAIN.twice,MAIN.band,MAIN.n,MAIN.reads,MAIN.line.total\n\
                     0,0,14,1,1,6,2030\n\
                     1,10,28,2,1,13,4060\n\
                     2,20,42,2,2,21,6090\n\
                     3,30,56,2,2,29,8100\n\
                     4,40,70,2,2,37,10100\n\
                     5,50,84,3,3,46,12100\n\
                     6,60,98,3,3,55,14100\n\
                     7,70,112,3,3,64,16100\n\
                     8,80,126,1,0,69,18100\n\
                     9,90,14,1,1,75,20100\n";

#[test]
fn get_and_set_accessors_run_where_the_property_is_read_and_written() {
    let (trace, stderr) = run(&fixture("motor.st"), 10, WATCH);
    assert_eq!(trace, TRACE);
    // the accessors' hidden variables are no internals the user reads (no W1412)
    assert!(!stderr.contains("W1412"), "{stderr}");
}

#[test]
fn the_same_block_as_twincat_files_gives_the_same_trace() {
    let dir = fixture("twincat");
    let files = ["Motor.TcPOU", "Line.TcPOU", "MAIN.TcPOU"].map(|f| dir.join(f));
    let refs: Vec<&Path> = files.iter().map(PathBuf::as_path).collect();
    let (trace, stderr) = run_traced_files(&refs, 10, WATCH);
    assert_eq!(trace, TRACE);
    assert!(!stderr.contains("error"), "{stderr}");
}

#[test]
fn the_same_block_as_a_codesys_export_gives_the_same_trace() {
    let (trace, stderr) = run(&fixture("motor.xml"), 10, WATCH);
    assert_eq!(trace, TRACE);
    assert!(!stderr.contains("E0303"), "{stderr}");
}

#[test]
fn a_property_misused_is_one_located_error_each() {
    let src = "TYPE Pt : STRUCT x : INT; y : INT; END_STRUCT; END_TYPE\n\
               FUNCTION_BLOCK Motor\nVAR rpm : INT; p : Pt; END_VAR\n\
               PROPERTY Speed : INT\nGET Speed := rpm; END_GET\nEND_PROPERTY\n\
               PROPERTY Target : INT\nSET rpm := Target; END_SET\nEND_PROPERTY\n\
               PROPERTY Pos : Pt\nGET Pos := p; END_GET\nSET p := Pos; END_SET\nEND_PROPERTY\n\
               Speed := 3;\nEND_FUNCTION_BLOCK\n\
               FUNCTION_BLOCK Scale\nVAR_IN_OUT value : INT; END_VAR\nVAR_OUTPUT q : INT; END_VAR\n\
               value := value * 2;\nEND_FUNCTION_BLOCK\n\
               PROGRAM main\nVAR m : Motor; s : Scale; x : INT; END_VAR\n\
               m();\nm.Speed := 5;\nx := m.Target + 1;\ns(value := m.Speed);\n\
               s(value := x, q => m.Target);\nm.Pos.x := 4;\nx := m.Pos.y;\n\
               REPEAT x := x + 1; UNTIL m.Speed > x END_REPEAT;\nEND_PROGRAM\n";
    assert_eq!(
        rejected_heads("p.st", src),
        [
            "p.st:14:1: error[E0337]: property `Speed` has no Set accessor: it cannot be written",
            "p.st:24:1: error[E0337]: property `Speed` has no Set accessor: it cannot be written",
            "p.st:25:6: error[E0337]: property `Target` has no Get accessor: it cannot be read",
            "p.st:26:12: error[E0338]: property `Speed` cannot be passed to a VAR_IN_OUT of `s`: \
             a property is code, not a variable",
            "p.st:27:20: error[E0338]: property `Target` cannot be passed to an output of `s`: \
             a property is code, not a variable",
            "p.st:28:1: error[E0338]: a component of property `Pos` cannot be written: the \
             property's value is a copy",
        ]
    );
}

/// A property read in an UNTIL condition (Struckig's tests: `UNTIL otg.State <> ... Busy
/// END_REPEAT`; E0108 before Session 36): its getter runs before each test, also after a CONTINUE.
/// `Step` counts 1, 2, ... and the loop ends at 5 in the first scan (5 rounds, the even counts 2
/// and 4 skipped by CONTINUE, 10 getter calls: one in the body and one in the test per round), at
/// 6 in the second.
#[test]
fn a_property_read_in_an_until_condition_runs_its_getter_before_each_test() {
    let (trace, stderr) = run(&fixture("until.st"), 2, "main.loops,main.skipped,main.gets");
    assert_eq!(
        trace,
        "cycle,time_ms,main.loops,main.skipped,main.gets\n0,0,5,2,10\n1,10,6,3,12\n"
    );
    assert!(!stderr.contains("error["), "{stderr}");
}

#[test]
fn a_property_of_a_program_compiles_and_a_component_is_read() {
    // CODESYS and TwinCAT allow a property below a PROGRAM: compiled as a function block's
    // (`fb_init_run.rs` runs one read and written from another program)
    let src = "PROGRAM other\nVAR x : INT; END_VAR\nPROPERTY P : INT\nGET P := x; END_GET\n\
               END_PROPERTY\nx := x + 1;\nEND_PROGRAM\n";
    let (code, lines) = check_text("o.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    // a read of a structured property's component calls the getter and reads the copy
    let ok = "TYPE Pt : STRUCT x : INT; y : INT; END_STRUCT; END_TYPE\n\
              FUNCTION_BLOCK Fb\nVAR p : Pt; END_VAR\nPROPERTY Pos : Pt\nGET Pos := p; END_GET\n\
              SET p := Pos; END_SET\nEND_PROPERTY\np.y := p.y + 3;\nEND_FUNCTION_BLOCK\n\
              PROGRAM main\nVAR f : Fb; y : INT; q : Pt; END_VAR\nf();\ny := f.Pos.y * 2;\n\
              q := f.Pos; q.x := y; f.Pos := q;\nEND_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("ok.st");
    std::fs::write(&file, ok).unwrap();
    let (trace, _) = run(&file, 3, "main.y,main.f.p.x");
    assert_eq!(
        trace,
        "cycle,time_ms,main.y,main.f.p.x\n0,0,6,6\n1,10,12,12\n2,20,18,18\n"
    );
}

#[test]
fn a_property_is_not_a_variable_to_watch() {
    // `--watch inst.P` names no variable: a property is code (its getter would have to run)
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(fixture("motor.st"))
        .args(["--cycles", "1", "--watch", "MAIN.m.Speed"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("--watch: unknown variable `MAIN.m.Speed`"),
        "{stderr}"
    );
    // and the file itself checks clean
    let (code, lines) = check_text(
        "motor.st",
        &std::fs::read_to_string(fixture("motor.st")).unwrap(),
    );
    assert_eq!(code, Some(0), "{lines:?}");
}

#[test]
fn a_property_that_cannot_be_read_or_compiled_is_one_located_error() {
    // no END_PROPERTY: the text cannot be read
    let heads = rejected_heads(
        "a.st",
        "FUNCTION_BLOCK F\nVAR x : INT; END_VAR\nPROPERTY P : INT\nGET P := x;\nEND_FUNCTION_BLOCK\n",
    );
    assert_eq!(
        heads,
        ["a.st:3:1: error[E0100]: `F`: this PROPERTY cannot be read"]
    );
    // a block whose body is IL: its properties are not compiled
    let heads = rejected_heads(
        "b.st",
        "FUNCTION_BLOCK F\nVAR x : INT; END_VAR\nPROPERTY P : INT\nGET P := 1; END_GET\n\
         END_PROPERTY\nLD x\nST x\nEND_FUNCTION_BLOCK\n",
    );
    assert_eq!(
        heads,
        ["b.st:3:10: error[E0303]: PROPERTY `P` of `F`: the properties of a function block whose \
          body is instruction list are not compiled"]
    );
    // two getters reading each other: named as accessors, not by their hidden names
    let heads = rejected_heads(
        "c.st",
        "FUNCTION_BLOCK F\nPROPERTY P : INT\nGET P := Q; END_GET\nEND_PROPERTY\n\
         PROPERTY Q : INT\nGET Q := P; END_GET\nEND_PROPERTY\nEND_FUNCTION_BLOCK\n\
         PROGRAM main VAR f : F; y : INT; END_VAR y := f.P; END_PROGRAM\n",
    );
    assert_eq!(
        heads,
        [
            "c.st:3:10: error[E0106]: the Get accessor of property `Q` calls itself (directly or \
             through another action)",
            "c.st:6:10: error[E0106]: the Get accessor of property `P` calls itself (directly or \
             through another action)",
        ]
    );
}

#[test]
fn a_block_whose_body_is_only_properties_compiles_them() {
    // TwinCAT writes an empty body for a block that only holds properties; an empty Get still
    // returns the type's initial value
    let src = "FUNCTION_BLOCK F\nVAR x : INT; END_VAR\nPROPERTY Zero : INT\nGET\nEND_GET\n\
               END_PROPERTY\nPROPERTY Next : INT\nGET x := x + 1; Next := x; END_GET\nEND_PROPERTY\n\
               END_FUNCTION_BLOCK\n\
               PROGRAM main VAR f : F; y : INT; z : INT; END_VAR y := f.Next + f.Zero; z := f.Next; END_PROGRAM\n";
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("only.st");
    std::fs::write(&file, src).unwrap();
    let (trace, _) = run(&file, 2, "main.y,main.z");
    assert_eq!(trace, "cycle,time_ms,main.y,main.z\n0,0,1,2\n1,10,3,4\n");
}

#[test]
fn properties_of_instances_in_arrays_and_structures() {
    // each c[i] counts its calls (n) and gets Value + i written: c[3].n = 4, 8, 12; p.b.Value is
    // ten times p.a's count; s = Twice(c[2].Value) + p.b.Value; the CASE reads c[1].Value (2, 4, 6)
    let (trace, _) = run(&fixture("instances.st"), 3, "main.s,main.t,main.c[3].n");
    assert_eq!(
        trace,
        "cycle,time_ms,main.s,main.t,main.c[3].n\n0,0,16,1,4\n1,10,32,2,8\n2,20,48,2,12\n"
    );
}
