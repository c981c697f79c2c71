//! Round 26 of issue #13: what real projects met, fixed outside the helpers' files.
//!
//! - A structure's field named by a keyword (`Type : INT;` in a STRUCT of an `.il` file, read and
//!   written as `r.Type`) is a field, as the ST reader already takes it (B&R's library types name
//!   fields `Type`, `String`) (before: E0008 "missing END_STRUCT" and ten more errors for the one
//!   name).
//! - An address outside the default profile's area that a built-in profile has room for (an
//!   OpenPLC program's `%QW200`) gets E2001 with a hint naming that profile (`--profile openplc`),
//!   and the program runs with it (before: the hint named only `--profile FILE.json`).
//! - A structure's initial value that reaches, inside an element, a structure declared further
//!   below (`x : ARRAY[0..1] OF B := [(t := (s := 1, e := 2)), ...]` with `B`'s field `t : C` and
//!   `C` declared after `B`, B&R's `MpOee.typ`) is read whatever the order of the declarations
//!   (before: E1025 "C has no field `s`" at each field; one level down already worked).
//! - In a TwinCAT `.TcGVL`, an initial value naming a path inside parentheses
//!   (`fb : FB := (p := ADR(GVL_Machine.HWIO.HWOutput.Lamp01))`, houqicheng's marquee) keeps its
//!   qualifiers: only array and string bounds lose a list's name (before: the path was cut to
//!   `Lamp01`, E0305 "no global variable", and the marquee's lamps never lit).

mod common;
use common::{column, in_dir, run_text, write_in};

/// `Type` and `String` as fields of a structure in an IL file: declared, loaded, stored.
#[test]
fn a_keyword_names_a_structure_field_in_il() {
    let src = "TYPE R : STRUCT Type : INT; String : INT; END_STRUCT; END_TYPE\n\
PROGRAM P\n\
VAR r : R; x : INT; y : INT; END_VAR\n\
LD r.Type\n\
ADD 1\n\
ST r.Type\n\
ST x\n\
LD r.String\n\
ADD 10\n\
ST r.String\n\
ST y\n\
END_PROGRAM\n";
    let (trace, stderr) = run_text("keyword_fields.il", src, 3, "P.x,P.y");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "P.x"), vec![1.0, 2.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "P.y"), vec![10.0, 20.0, 30.0], "{trace}");
}

/// `%QW200` does not fit the default profile's 256 bytes of %Q: E2001's hint names the built-in
/// profile that holds it, and with that profile the program runs.
#[test]
fn e2001_names_the_built_in_profile_with_room_for_the_address() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "prog.st",
        "PROGRAM prog\nVAR reg AT %QW200 : INT := 7; END_VAR\nreg := reg + 1;\nEND_PROGRAM\n",
    );
    let (code, _, stderr) = in_dir(dir.path(), &["check", "prog.st"]);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("error[E2001]")
            && stderr.contains("(the built-in `--profile openplc` has room for it)"),
        "{stderr}"
    );
    let (code, stdout, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "prog.st",
            "--profile",
            "openplc",
            "--cycles",
            "2",
            "--watch",
            "prog.reg",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        stdout.lines().nth(2).is_some_and(|l| l.ends_with(",9")),
        "{stdout}"
    );
}

/// The field names of a structure two levels inside an initial value are known whatever the order
/// of the declarations: A's initial value names C's fields through B, C declared last.
#[test]
fn a_nested_initial_value_reaches_a_structure_declared_below() {
    let src = "TYPE\n\
  A : STRUCT\n\
    x : ARRAY[0..1] OF B := [(n := 'a', t := (s := 1, e := 2)), (n := 'b', t := (s := 3, e := 4))];\n\
  END_STRUCT;\n\
  B : STRUCT n : STRING[10]; t : C; END_STRUCT;\n\
  C : STRUCT s : INT; e : INT; END_STRUCT;\n\
END_TYPE\n\
PROGRAM P\n\
VAR a : A; r : INT; q : INT; END_VAR\n\
r := a.x[1].t.e;\n\
q := a.x[0].t.s;\n\
END_PROGRAM\n";
    let (trace, stderr) = run_text("nested_forward.st", src, 1, "P.r,P.q");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "P.r"), vec![4.0], "{trace}");
    assert_eq!(column(&trace, "P.q"), vec![1.0], "{trace}");
}

/// A TwinCAT project whose GVL starts a block's pointer input at a lamp three levels inside another
/// (qualified) list: the block writes through it, the lamp lights.
#[test]
fn a_twincat_gvl_initial_value_keeps_its_qualified_path() {
    let dir = tempfile::tempdir().unwrap();
    let obj = |body: &str| {
        format!(
            "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4022.16\">\n{body}\n</TcPlcObject>\n"
        )
    };
    write_in(dir.path(), "GVL_Machine.TcGVL", &obj("<GVL Name=\"GVL_Machine\" Id=\"{00000000-0000-0000-0000-000000000001}\"><Declaration><![CDATA[{attribute 'qualified_only'}\nVAR_GLOBAL\n\tHWIO : ST_IO;\nEND_VAR]]></Declaration></GVL>"));
    write_in(dir.path(), "GVL_General.TcGVL", &obj("<GVL Name=\"GVL_General\" Id=\"{00000000-0000-0000-0000-000000000002}\"><Declaration><![CDATA[VAR_GLOBAL\n\tfbLamp : FB_Lamp := (pLamp := ADR(GVL_Machine.HWIO.HWOutput.Lamp01), n := 2);\nEND_VAR]]></Declaration></GVL>"));
    write_in(dir.path(), "ST_IO.TcDUT", &obj("<DUT Name=\"ST_IO\" Id=\"{00000000-0000-0000-0000-000000000003}\"><Declaration><![CDATA[TYPE ST_IO :\nSTRUCT\n\tHWOutput : ST_Out;\nEND_STRUCT\nEND_TYPE]]></Declaration></DUT>"));
    write_in(dir.path(), "ST_Out.TcDUT", &obj("<DUT Name=\"ST_Out\" Id=\"{00000000-0000-0000-0000-000000000004}\"><Declaration><![CDATA[TYPE ST_Out :\nSTRUCT\n\tLamp01 AT %Q* : BOOL;\nEND_STRUCT\nEND_TYPE]]></Declaration></DUT>"));
    write_in(dir.path(), "FB_Lamp.TcPOU", &obj("<POU Name=\"FB_Lamp\" Id=\"{00000000-0000-0000-0000-000000000005}\" SpecialFunc=\"None\"><Declaration><![CDATA[FUNCTION_BLOCK FB_Lamp\nVAR_INPUT pLamp : POINTER TO BOOL; n : INT; END_VAR\nVAR k : INT; END_VAR]]></Declaration><Implementation><ST><![CDATA[k := k + 1;\nIF pLamp <> 0 AND k >= n THEN pLamp^ := TRUE; END_IF]]></ST></Implementation></POU>"));
    write_in(dir.path(), "MAIN.TcPOU", &obj("<POU Name=\"MAIN\" Id=\"{00000000-0000-0000-0000-000000000006}\" SpecialFunc=\"None\"><Declaration><![CDATA[PROGRAM MAIN\nVAR lit : BOOL; END_VAR]]></Declaration><Implementation><ST><![CDATA[GVL_General.fbLamp();\nlit := GVL_Machine.HWIO.HWOutput.Lamp01;]]></ST></Implementation></POU>"));
    let (code, stdout, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "GVL_Machine.TcGVL",
            "GVL_General.TcGVL",
            "ST_IO.TcDUT",
            "ST_Out.TcDUT",
            "FB_Lamp.TcPOU",
            "MAIN.TcPOU",
            "--cycles",
            "3",
            "--watch",
            "MAIN.lit",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&stdout, "MAIN.lit"), vec![0.0, 1.0, 1.0], "{stdout}");
}
