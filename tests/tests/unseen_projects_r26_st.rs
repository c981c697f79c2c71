//! Round 26 of unseen projects (issue #13), plain-text ST projects (SIMATIC AX, TwinCAT, CODESYS
//! exports, editors' samples), run end to end through `ladderc run`:
//! - a name qualified with a NAMESPACE declared in another file of the project
//!   (`Plant.Util.Twice(21)`, lib.st holding `NAMESPACE Plant.Util ... END_NAMESPACE`) names that
//!   function, and `USING Plant.Util;` of it is no W1421 (before: E1032 "`Plant` is neither a
//!   variable nor a library", with a hint to add POUs that were already there);
//! - FB_init arguments on a function-block field of a STRUCT (`fbLamp : FB_Lamp(sLampName :=
//!   'Kitchen');`, TwinCAT) initialise the field of each instance of the structure, as in a VAR
//!   block (before: E0011 "unexpected `:=`");
//! - an unknown enumeration (`Area#Outputs` of a vendor library not given) is one E1001 at its
//!   first use, counting the others (before: one E1001 per use, 8 for one cause in a SIMATIC AX
//!   project);
//! - description and attribute pragmas (`{ DE:"Heater relay" }`, `{s7.extern=ReadWrite}`) are one
//!   W0301 note per file (before: W0300 "holds code that does not run" at each, 189 in one list);
//!   Beremiz's C code stays W0300;
//! - a `.txt` or extensionless text of ST statements with no POU is read as ST: one E0307 (before:
//!   read as IL, an error a line, 59 for one file); a `.txt` program in ST runs;
//! - a SIMOTION ST unit (`UNIT Name;`, `INTERFACE`, `IMPLEMENTATION`, `ARRAY[..]`) is one E0023 at
//!   its `UNIT` line naming the dialect (before: read as IL lines, then an E0011 at each
//!   `ARRAY[..]`: 53 errors over 6 files).

mod common;
use common::{check_files, check_text, column, in_dir, run_text, write_in};

/// IEC 61131-3 ed. 3 (6.9): a namespace is not tied to a file, and the files given together are
/// one project (SIMATIC AX puts `NAMESPACE Siemens.Ax` in one file and calls its function from
/// another). Qualified and after `USING`, both run.
#[test]
fn a_namespace_of_another_file_names_its_functions() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "lib.st",
        "NAMESPACE Plant.Util
    FUNCTION Twice : INT
        VAR_INPUT
            n : INT;
        END_VAR
        Twice := n * 2;
    END_FUNCTION
END_NAMESPACE
NAMESPACE Tools
    FUNCTION Inc : INT
        VAR_INPUT
            n : INT;
        END_VAR
        Inc := n + 1;
    END_FUNCTION
END_NAMESPACE
",
    );
    write_in(
        dir.path(),
        "main.st",
        "USING Tools;
PROGRAM Main
VAR
    a : INT;
    b : INT;
END_VAR
a := Plant.Util.Twice(21);
b := Inc(a) + Tools.Inc(0);
END_PROGRAM
",
    );
    let (code, out, err) = in_dir(
        dir.path(),
        &[
            "run",
            "lib.st",
            "main.st",
            "--cycles",
            "1",
            "--trace",
            "-",
            "--watch",
            "Main.a,Main.b",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("E1032") && !err.contains("W1421"), "{err}");
    assert_eq!(column(&out, "Main.a"), vec![42.0], "{out}");
    assert_eq!(column(&out, "Main.b"), vec![44.0], "{out}");
}

/// Beckhoff's FB_init: "Any additional variables specified there must be set when declaring a
/// function block instance"; a STRUCT field is such a declaration. Each instance of the structure
/// (one in a program, each element of an array of it) runs FB_init with the field's arguments,
/// positional or named.
#[test]
fn fb_init_arguments_on_a_structure_field_initialise_it() {
    let src = "FUNCTION_BLOCK FB_Lamp
VAR_OUTPUT
    nWatts : INT;
END_VAR
VAR
    sName : STRING;
END_VAR
METHOD FB_init : BOOL
VAR_INPUT
    bInitRetains : BOOL;
    bInCopyCode : BOOL;
    sLampName : STRING;
    nPower : INT;
END_VAR
sName := sLampName;
nWatts := nPower;
END_METHOD
END_FUNCTION_BLOCK

TYPE ST_Room :
STRUCT
    fbLamp : FB_Lamp(sLampName := 'Kitchen', nPower := 40);
    fbSpot : FB_Lamp('Spot', 7);
    nCount : INT;
END_STRUCT
END_TYPE

PROGRAM Main
VAR
    room : ST_Room;
    rooms : ARRAY[1..2] OF ST_Room;
    hall : FB_Lamp(sLampName := 'Hall', nPower := 60);
    total : INT;
    name : STRING;
END_VAR
room.fbLamp();
total := room.fbLamp.nWatts + room.fbSpot.nWatts + rooms[2].fbLamp.nWatts + hall.nWatts;
name := room.fbLamp.sName;
END_PROGRAM
";
    let (trace, stderr) = run_text("room.st", src, 1, "Main.total,Main.name");
    assert!(!stderr.contains("error"), "{stderr}");
    // 40 + 7 + 40 + 60
    assert_eq!(column(&trace, "Main.total"), vec![147.0], "{trace}");
    assert!(trace.contains("\"Kitchen\""), "{trace}");
}

/// One cause, one error: `Area` used five times in two POUs of two files (also inside the calls
/// of an unknown function, whose E1019 is once per POU) is one E1001 at its first use.
#[test]
fn an_unknown_enumeration_is_one_error() {
    let (code, lines) = check_files(&[
        (
            "a.st",
            "PROGRAM Main
VAR
    b : BYTE;
    i : INT;
END_VAR
PeekArea(Area#Outputs, 10, b);
FOR i := 0 TO 7 DO
    PeekArea(Area#Inputs, i, b);
END_FOR;
IF b = 0 THEN
    b := SEL(Area#Markers = Area#Inputs, b, 1);
END_IF;
END_PROGRAM
",
        ),
        (
            "b.st",
            "FUNCTION_BLOCK FB_Io
VAR
    x : INT;
END_VAR
IF x = Area#Outputs THEN x := 1; END_IF;
END_FUNCTION_BLOCK
",
        ),
    ]);
    assert_eq!(code, Some(1));
    let enums: Vec<&String> = lines.iter().filter(|l| l.contains("E1001")).collect();
    assert_eq!(enums.len(), 1, "{lines:#?}");
    assert!(
        enums[0].starts_with(
            "a.st:6:10: error[E1001]: unknown enumeration `Area` (used 4 more times, not reported)"
        ),
        "{lines:#?}"
    );
    // one use alone: the message as before
    let (_, lines) = check_text(
        "one.st",
        "PROGRAM Main
VAR x : INT; END_VAR
IF x = Mode#Auto THEN x := 1; END_IF;
END_PROGRAM
",
    );
    assert!(
        lines.iter().any(|l| l.ends_with("unknown enumeration `Mode` (hint: declare it in a TYPE block (or give the library that declares it with --lib))")),
        "{lines:#?}"
    );
}

/// IEC 61131-3 ed. 3 (6.2) leaves pragmas to the implementation; a `{ key:"text" }` or
/// `{key=value}` pair describes its declaration (a CODESYS-based editor's description, a SIMATIC AX
/// export attribute): metadata, no code. The program runs as written; the file's pragmas are one
/// note, and a C-code pragma beside them is still W0300.
#[test]
fn description_pragmas_are_one_note_per_file() {
    let src = "VAR_GLOBAL
    SetPoint : REAL := 21.5;\t{ DE:\"Room setpoint\" }
    Hyst : REAL := 0.5;\t{ DE:\"Hysteresis\" }
    {s7.extern=ReadWrite}
    Heater : BOOL;\t{G:'Outputs'}
END_VAR

PROGRAM Main
VAR
    Temp : REAL := 20.0;\t{ DE:\"Measured temperature\" }
END_VAR
{ SetFbVar(OUT, 1); }
IF Temp < SetPoint - Hyst THEN Heater := TRUE; ELSIF Temp > SetPoint + Hyst THEN Heater := FALSE; END_IF;
END_PROGRAM
";
    let (trace, stderr) = run_text("heater.st", src, 1, "Heater");
    assert_eq!(column(&trace, "Heater"), vec![1.0], "{trace}");
    let notes: Vec<&str> = stderr.lines().filter(|l| l.contains("W0301")).collect();
    assert_eq!(notes.len(), 1, "{stderr}");
    assert!(
        notes[0].contains("heater.st:2:30: note[W0301]: description or attribute pragma `{ DE:\"Room setpoint\" }` is ignored (and the file's 4 others)"),
        "{stderr}"
    );
    let code: Vec<&str> = stderr.lines().filter(|l| l.contains("W0300")).collect();
    assert_eq!(code.len(), 1, "{stderr}");
    assert!(code[0].contains("SetFbVar"), "{stderr}");
}

/// IEC 61131-3 7.2 (IL) has no `:=` outside a call, no `;`, no `IF ... THEN ... END_IF`: a text of
/// them is ST. With no POU around them it is one located E0307, in a `.txt` file as in an
/// extensionless one; wrapped in a PROGRAM the `.txt` runs.
#[test]
fn a_text_of_st_statements_is_read_as_st() {
    let body = "IF start THEN
    lamp := TRUE;
END_IF;
count := count + 1;
";
    for name in ["plc_prog.txt", "plc_prog"] {
        let (code, lines) = check_text(name, body);
        assert_eq!(code, Some(1));
        let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
        assert_eq!(errors.len(), 1, "{lines:#?}");
        assert!(
            errors[0].starts_with(&format!(
                "{name}:1:1: error[E0307]: statements outside any POU"
            )),
            "{lines:#?}"
        );
    }
    let program = format!(
        "PROGRAM Main\nVAR start : BOOL := TRUE; lamp : BOOL; count : INT; END_VAR\n{body}END_PROGRAM\n"
    );
    let (trace, _) = run_text("main.txt", &program, 2, "Main.lamp,Main.count");
    assert_eq!(column(&trace, "Main.lamp"), vec![1.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "Main.count"), vec![1.0, 2.0], "{trace}");
}

/// SIMOTION ST is Siemens's motion-controller dialect: a unit with interface and implementation
/// sections and dynamic arrays, not IEC 61131-3. One error per file, at `UNIT`, naming it; a valid
/// file given with it adds none.
#[test]
fn a_simotion_unit_is_one_error_naming_the_dialect() {
    let (code, lines) = check_files(&[
        (
            "mathunit.st",
            "(* utilities *)
UNIT MathUnit;

INTERFACE
    FUNCTION SumArray;
END_INTERFACE

IMPLEMENTATION
    FUNCTION SumArray : LREAL
        VAR_IN_OUT
            data : ARRAY[..] OF LREAL;
        END_VAR
        VAR_TEMP
            i : DINT;
        END_VAR
        SumArray := 0.0;
        FOR i := 0 TO _lastIndexOf(in := data) DO
            SumArray := SumArray + data[i];
        END_FOR;
    END_FUNCTION

    FUNCTION MaxArray : LREAL
        VAR_IN_OUT
            data : ARRAY[..] OF LREAL;
        END_VAR
        MaxArray := data[0];
    END_FUNCTION
END_IMPLEMENTATION
",
        ),
        (
            "main.st",
            "PROGRAM Main
VAR x : INT; END_VAR
x := x + 1;
END_PROGRAM
",
        ),
    ]);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:#?}");
    assert!(
        lines.iter().any(|l| l.starts_with("mathunit.st:2:1: error[E0023]: this file is a SIMOTION ST unit (`UNIT MathUnit`), not IEC 61131-3 Structured Text")),
        "{lines:#?}"
    );
}
