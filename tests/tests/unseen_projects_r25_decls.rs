//! Round 25 of unseen projects (issue #13), declarations: what real programs need, run end to end
//! through `ladderc run`:
//! - an initial value that reads a global variable (`bEntryConveyor : BOOL :=
//!   GVL.mb_Input_Coils[0];`, `nStart : INT := gBase + 2;`) is computed at run time, as one that
//!   reads a variable of its POU is: in declaration order when the instance is initialised, from
//!   the global's initial value (before: E1025 "an initial value must be a constant", or E0022);
//! - a pointer whose initial value is an address with a computed index (`motionOnline : POINTER TO
//!   WORD := ADR(registers[indexMotionOnline]);`) starts pointing there (before: E0305, which
//!   called the pointer "a reference"); in a global list too, before the first cycle (round 28;
//!   before: E0305 naming a pointer);
//! - an integer constant set from an enumeration's value (`MAX_TOPICS : INT :=
//!   E_Topics.NUMBER_OF_TOPICS;`, LKinGitHub's PackML and Rohlik) bounds an array, as one set from
//!   a literal does (before: E0022 at the bound).

mod common;
use common::{column, run_text, run_traced_files};

/// CODESYS and TwinCAT take any ST expression as an initial value, "constants, other variables or
/// functions" (CODESYS "Variable Initialization"): a global's element and a global in an
/// expression are read when the program is initialised, from the globals' initial values; the
/// body changing the global later does not change them (they are initial values). W1433 (IEC
/// 61131-3 takes constant expressions) once for the POU.
#[test]
fn an_initial_value_reads_a_global_variable() {
    let src = "VAR_GLOBAL
    gCoils : ARRAY[0..3] OF BOOL := [FALSE, FALSE, TRUE, FALSE];
    gBase : INT := 40;
END_VAR
PROGRAM Main
VAR
    bFirst : BOOL := gCoils[2];
    nStart : INT := gBase + 2;
    nNext : INT := nStart * 2;
END_VAR
gBase := gBase + 1;
END_PROGRAM
";
    let (trace, stderr) = run_text("plant.st", src, 2, "Main.bFirst,Main.nStart,Main.nNext");
    assert_eq!(column(&trace, "Main.bFirst"), [1.0, 1.0]);
    assert_eq!(column(&trace, "Main.nStart"), [42.0, 42.0]);
    assert_eq!(column(&trace, "Main.nNext"), [84.0, 84.0]);
    assert_eq!(stderr.matches("warning[W1433]").count(), 1, "{stderr}");
    assert!(!stderr.contains("error"), "{stderr}");
}

/// A global of a list of another file, read qualified (`GVL.mb_Input_Coils[0]`,
/// huanlamgia/TwinCAT-learning's ModbusData), in a function block's VAR: each instance reads it
/// when it is initialised.
#[test]
fn an_initial_value_reads_a_qualified_global_of_another_file() {
    let dir = tempfile::tempdir().unwrap();
    let gvl = dir.path().join("GVL.st");
    std::fs::write(
        &gvl,
        "VAR_GLOBAL\n    aCoils : ARRAY[0..3] OF BOOL := [TRUE, FALSE, TRUE, FALSE];\n    nOffset : INT := 5;\nEND_VAR\n",
    )
    .unwrap();
    let main = dir.path().join("Main.st");
    std::fs::write(
        &main,
        "FUNCTION_BLOCK FB_Station
VAR_OUTPUT
    bEntry : BOOL := GVL.aCoils[0];
    nPlace : INT := GVL.nOffset * 10 + 1;
END_VAR
END_FUNCTION_BLOCK
PROGRAM Main
VAR
    st : FB_Station;
    bEntry : BOOL;
    nPlace : INT;
END_VAR
st();
bEntry := st.bEntry;
nPlace := st.nPlace;
END_PROGRAM
",
    )
    .unwrap();
    let (trace, stderr) = run_traced_files(&[&gvl, &main], 1, "Main.bEntry,Main.nPlace");
    assert_eq!(column(&trace, "Main.bEntry"), [1.0], "{stderr}");
    assert_eq!(column(&trace, "Main.nPlace"), [51.0], "{stderr}");
    assert!(!stderr.contains("error"), "{stderr}");
}

/// `ADR(regs[idx])` with a variable index, and `ADR(registers[indexMotionOnline])` with a
/// constant declared after it (smandyscom/TC3-modules): the pointers start at those elements.
#[test]
fn a_pointer_starts_at_a_computed_address() {
    let src = "PROGRAM Main
VAR
    idx : INT := 2;
    regs : ARRAY[0..3] OF WORD := [10, 11, 12, 13];
    pReg : POINTER TO WORD := ADR(regs[idx]);
    pOnline : POINTER TO WORD := ADR(regs[indexOnline]);
    w, online : WORD;
END_VAR
VAR CONSTANT
    indexOnline : INT := 3;
END_VAR
w := pReg^;
online := pOnline^;
END_PROGRAM
";
    let (trace, stderr) = run_text("regs.st", src, 1, "Main.w,Main.online");
    assert_eq!(column(&trace, "Main.w"), [12.0], "{stderr}");
    assert_eq!(column(&trace, "Main.online"), [13.0], "{stderr}");
    assert!(!stderr.contains("error"), "{stderr}");
}

/// A global list's pointer whose address has a computed index is computed before the first cycle
/// (round 28, `initial_values_r28_run.rs`; before: one E0305, which called it a pointer).
#[test]
fn a_pointer_of_a_global_list_is_computed_before_the_first_cycle() {
    let (trace, stderr) = run_text(
        "gvl.st",
        "VAR_GLOBAL\n    gArr : ARRAY[0..3] OF INT := [4, 5, 6, 7];\n    gI : INT := 1;\n    gP : POINTER TO INT := ADR(gArr[gI]);\nEND_VAR\nPROGRAM Main\nVAR x : INT; END_VAR\nx := gP^;\nEND_PROGRAM\n",
        1,
        "Main.x",
    );
    assert_eq!(column(&trace, "Main.x"), [5.0], "{stderr}");
}

/// `N : INT := E_Topic.COUNT_OF;` (an enumeration without `{attribute 'strict'}`, as its number)
/// bounds `ARRAY[0..N - 1]`; so do a constant of a global list set from a value written
/// `E_Topic#Gamma`, and one set from an enumeration of another file (a TwinCAT DUT) below the
/// array it bounds (LKinGitHub/PackML's `PubSubService`).
#[test]
fn a_constant_set_from_an_enumeration_value_bounds_an_array() {
    let src = "TYPE E_Topic : (Alpha, Beta, Gamma, COUNT_OF); END_TYPE
VAR_GLOBAL CONSTANT
    G : INT := E_Topic#Gamma;
END_VAR
PROGRAM Main
VAR CONSTANT
    N : INT := E_Topic.COUNT_OF;
END_VAR
VAR
    buf : ARRAY[0..N - 1] OF INT;
    small : ARRAY[0..G] OF INT;
    k : INT;
    m : DINT;
END_VAR
buf[N - 1] := 7;
k := buf[2];
small[G] := 4;
m := small[2] + UPPER_BOUND(small, 1);
END_PROGRAM
";
    let (trace, stderr) = run_text("topics.st", src, 1, "Main.k,Main.m");
    assert_eq!(column(&trace, "Main.k"), [7.0], "{stderr}");
    assert_eq!(column(&trace, "Main.m"), [6.0], "{stderr}");
    assert!(!stderr.contains("error"), "{stderr}");

    let dir = tempfile::tempdir().unwrap();
    let main = dir.path().join("PubSub.st");
    std::fs::write(
        &main,
        "PROGRAM PubSub
VAR
    subscribers : ARRAY[1..MAX_TOPICS] OF INT;
    n : DINT;
END_VAR
VAR CONSTANT
    MAX_TOPICS : INT := E_Topics.NUMBER_OF_TOPICS;
END_VAR
n := UPPER_BOUND(subscribers, 1);
END_PROGRAM
",
    )
    .unwrap();
    let dut = dir.path().join("E_Topics.st");
    std::fs::write(
        &dut,
        "TYPE E_Topics :\n(\n    Start := 0,\n    Stop,\n    Reset,\n    NUMBER_OF_TOPICS\n);\nEND_TYPE\n",
    )
    .unwrap();
    let (trace, stderr) = run_traced_files(&[&main, &dut], 1, "PubSub.n");
    assert_eq!(column(&trace, "PubSub.n"), [3.0], "{stderr}");
}
