//! Round 31's leftovers closed in round 32 (issue #13), end to end:
//! - a TwinCAT library given as an input project beside the application that references it
//!   (`ladderc check App.plcproj Lib.plcproj`, x-PPU's `Resi4MPM`) is known by the namespace of the
//!   reference: `Resi.ParameterSet` is the library's type, as with `--lib` (before: E1032 "give
//!   its source project with --lib, or add its POUs and types to the project" although they were
//!   added, and a false E1084 for each method typed through it);
//! - a derived method whose input is typed through a library that is missing (`Missing.T`, its
//!   E1032 reported) keeps the base's signature `T`: no E1084 (before: two false E1084 in x-PPU);
//!   another type still is E1084;
//! - a FUNCTION without result type whose body assigns its name (a B&R function whose `.fun`
//!   declaration was not given) is one E0354 at the body, not one more per call that uses its
//!   value (MarcoBraun84: 3 errors for one cause).

mod common;
use common::{check_text, column, in_dir, write_in};

/// A TwinCAT object file holding the POU `name` with the declaration `decl`, the ST body `body`
/// and the methods `methods` (declaration, body).
fn tc_pou(name: &str, decl: &str, body: &str, methods: &[(&str, &str, &str)]) -> String {
    let methods: String = methods
        .iter()
        .map(|(m, d, b)| {
            format!(
                "    <Method Name=\"{m}\" Id=\"{{21111111-2222-3333-4444-555555555555}}\">\n      \
<Declaration><![CDATA[{d}]]></Declaration>\n      <Implementation>\n        <ST><![CDATA[{b}]]></ST>\n      \
</Implementation>\n    </Method>\n"
            )
        })
        .collect();
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4024.12\">\n  \
<POU Name=\"{name}\" Id=\"{{11111111-2222-3333-4444-555555555555}}\" SpecialFunc=\"None\">\n    \
<Declaration><![CDATA[{decl}]]></Declaration>\n    <Implementation>\n      <ST><![CDATA[{body}]]></ST>\n    \
</Implementation>\n{methods}  </POU>\n</TcPlcObject>\n"
    )
}

/// A TwinCAT data type object file.
fn tc_dut(name: &str, decl: &str) -> String {
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4024.12\">\n  \
<DUT Name=\"{name}\" Id=\"{{31111111-2222-3333-4444-555555555555}}\">\n    \
<Declaration><![CDATA[{decl}]]></Declaration>\n  </DUT>\n</TcPlcObject>\n"
    )
}

/// A `.plcproj` titled `title`, listing `includes` and referencing the placeholder `lib` (written
/// in brackets, as x-PPU's TwinCAT version does) under the namespace `lib`.
fn plcproj(title: &str, includes: &[&str], lib: Option<&str>) -> String {
    let compile: String = includes
        .iter()
        .map(|i| format!("    <Compile Include=\"{i}\"><SubType>Code</SubType></Compile>\n"))
        .collect();
    let refs = lib.map_or(String::new(), |l| {
        format!(
            "  <ItemGroup>\n    <PlaceholderReference Include=\"[{l}]\">\n      <DefaultResolution>[{l}], * (Me)</DefaultResolution>\n      \
<Namespace>{l}</Namespace>\n    </PlaceholderReference>\n  </ItemGroup>\n"
        )
    });
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Project DefaultTargets=\"Build\" xmlns=\"http://schemas.microsoft.com/developer/msbuild/2003\">\n  \
<PropertyGroup>\n    <Name>{title}_Lib</Name>\n    <Title>{title}</Title>\n  </PropertyGroup>\n  <ItemGroup>\n{compile}  </ItemGroup>\n{refs}</Project>\n"
    )
}

/// The library `Resi` (project `Resi_Lib.plcproj`, title `Resi`): a structure `ParameterSet` and
/// a base block whose method `Exec` takes one; the application `App` references `[Resi]` and
/// derives a block whose `Exec` takes a `Resi.ParameterSet` and counts its `gain` per call.
fn write_library_and_application(d: &std::path::Path) {
    write_in(
        d,
        "Resi/Resi_Lib.plcproj",
        &plcproj(
            "Resi",
            &[r"DUTs\ParameterSet.TcDUT", r"POUs\Base.TcPOU"],
            None,
        ),
    );
    write_in(
        d,
        "Resi/DUTs/ParameterSet.TcDUT",
        &tc_dut(
            "ParameterSet",
            "TYPE ParameterSet :\nSTRUCT\n\tgain : INT := 1;\nEND_STRUCT\nEND_TYPE\n",
        ),
    );
    write_in(
        d,
        "Resi/POUs/Base.TcPOU",
        &tc_pou(
            "Base",
            "FUNCTION_BLOCK Base\nVAR_OUTPUT\n\ttotal : INT;\nEND_VAR\n",
            "",
            &[(
                "Exec",
                "METHOD PROTECTED Exec : BOOL\nVAR_INPUT\n\ti_params : ParameterSet;\nEND_VAR\n",
                "Exec := FALSE;",
            )],
        ),
    );
    write_in(
        d,
        "App/App.plcproj",
        &plcproj(
            "App",
            &[r"POUs\Worker.TcPOU", r"POUs\MAIN.TcPOU"],
            Some("Resi"),
        ),
    );
    write_in(
        d,
        "App/POUs/Worker.TcPOU",
        &tc_pou(
            "Worker",
            "FUNCTION_BLOCK Worker EXTENDS Resi.Base\nVAR\n\tp : Resi.ParameterSet;\nEND_VAR\n",
            "p.gain := 3;\nExec(p);",
            &[(
                "Exec",
                "METHOD PROTECTED Exec : BOOL\nVAR_INPUT\n\ti_params : Resi.ParameterSet;\nEND_VAR\n",
                "total := total + i_params.gain;\nExec := TRUE;",
            )],
        ),
    );
    write_in(
        d,
        "App/POUs/MAIN.TcPOU",
        &tc_pou(
            "MAIN",
            "PROGRAM MAIN\nVAR\n\tw : Worker;\n\tk : INT;\nEND_VAR\n",
            "w();\nk := w.total;",
            &[],
        ),
    );
}

/// x-PPU gives its two library projects beside the application. The library's types and blocks
/// are read with the application and `Resi.` names them, as with `--lib`: the derived method
/// overrides the base's (same signature), and each scan adds the gain 3. Before: E1032 at
/// `Resi` and E1084 "overrides `Base.Exec` with another signature".
#[test]
fn a_library_given_as_an_input_project_is_known_by_its_namespace() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_library_and_application(d);
    for args in [
        &["App/App.plcproj", "Resi/Resi_Lib.plcproj"][..],
        &["App/App.plcproj", "--lib", "Resi/Resi_Lib.plcproj"][..],
    ] {
        let mut all = vec!["run"];
        all.extend_from_slice(args);
        all.extend_from_slice(&[
            "--cycles",
            "3",
            "--cycle-ms",
            "10",
            "--trace",
            "-",
            "--watch",
            "MAIN.k",
        ]);
        let (code, out, err) = in_dir(d, &all);
        assert_eq!(code, Some(0), "{args:?}: {err}");
        assert!(!err.contains("error["), "{args:?}: {err}");
        assert_eq!(column(&out, "MAIN.k"), [3.0, 6.0, 9.0], "{args:?}: {out}");
    }
}

/// Without the library, `Resi.ParameterSet` is one E1032 (the library is missing) and the
/// E0330 of the missing base; no E1084 (there is no base to compare with).
#[test]
fn an_application_without_its_library_names_the_library_once() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_library_and_application(d);
    let (code, _, err) = in_dir(d, &["check", "App/App.plcproj"]);
    assert_eq!(code, Some(1), "{err}");
    let errors: Vec<&str> = err.lines().filter(|l| l.contains("error[")).collect();
    assert!(
        errors
            .iter()
            .any(|l| l.contains("E1032") && l.contains("`Resi`")),
        "{err}"
    );
    assert!(!err.contains("E1084"), "{err}");
}

/// A derived method typed through a library that is not there: the type's E1032 is the error
/// (x-PPU's `i_params : Resi4MPM.ParameterSet` against the base's `ParameterSet`); the
/// signatures are the same but for the qualifier, so no E1084. A method that takes another type
/// (`Missing.Other`, `INT`) still is E1084.
#[test]
fn a_library_qualifier_is_no_other_signature() {
    let src = "\
TYPE ParameterSet : STRUCT gain : INT; END_STRUCT END_TYPE

FUNCTION_BLOCK Base
METHOD Exec : BOOL
VAR_INPUT
    i_params : ParameterSet;
END_VAR
Exec := TRUE;
END_METHOD
METHOD Other : BOOL
VAR_INPUT
    i_params : ParameterSet;
END_VAR
Other := TRUE;
END_METHOD
END_FUNCTION_BLOCK

FUNCTION_BLOCK Derived EXTENDS Base
METHOD Exec : BOOL
VAR_INPUT
    i_params : Missing.ParameterSet;
END_VAR
Exec := FALSE;
END_METHOD
METHOD Other : BOOL
VAR_INPUT
    i_params : Missing.Something;
END_VAR
Other := FALSE;
END_METHOD
END_FUNCTION_BLOCK
";
    let (code, lines) = check_text("qualified_override.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert!(
        errors
            .iter()
            .any(|l| l.contains("E1032") && l.contains("qualified_override.st:21:16")),
        "{errors:?}"
    );
    let e1084: Vec<&&String> = errors.iter().filter(|l| l.contains("E1084")).collect();
    assert_eq!(e1084.len(), 1, "{errors:?}");
    assert!(
        e1084[0].contains("qualified_override.st:25:8") && e1084[0].contains("`Other`"),
        "{errors:?}"
    );
}

/// A B&R function's declaration lives in a `.fun` file; without it the body's `Volume := ...`
/// has nothing to assign to: one E0354 there, and the two calls that use the value report
/// nothing more (before: three E0354). A function without result type whose body never assigns
/// its name still gets the E0354 at each call that uses a value (nothing else says it).
#[test]
fn a_function_without_result_type_is_one_error_not_one_per_call() {
    let src = "\
FUNCTION Volume
VAR_INPUT
    h : REAL;
    r : REAL;
END_VAR
Volume := 3.14 * r * r * h;
END_FUNCTION

FUNCTION Log
VAR_INPUT
    x : REAL;
END_VAR
END_FUNCTION

PROGRAM Main
VAR
    v : REAL;
    w : REAL;
END_VAR
v := Volume(2.0, 1.0) * 0.8;
w := Volume(h := 1.0, r := 1.0);
v := Log(w);
END_PROGRAM
";
    let (code, lines) = check_text("volume.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 2, "{errors:?}");
    assert!(
        errors[0].contains("volume.st:6:1")
            && errors[0].contains("E0354")
            && errors[0].contains("declared without a result type"),
        "{errors:?}"
    );
    assert!(
        errors[1].contains("volume.st:22:6")
            && errors[1].contains("E0354")
            && errors[1].contains("`Log` returns no value"),
        "{errors:?}"
    );
}

/// x-PPU's `ObservePicAlpha`: a method hands `INT_TO_LREAL(p^.dist)` to another block's method
/// (hoisted into a temporary), then tests a BOOL property read through the same pointer. The
/// lowering's type cache was keyed by node address alone, and the condition's rewritten node got
/// the address of a node dropped with the previous statement: the condition read as INT, a false
/// E3105 "the IF condition must be BOOL" and the branch compiled as `LD FALSE`. Now each flag
/// value gives its branch, scan by scan.
#[test]
fn a_property_condition_after_a_hoisted_conversion_keeps_its_type() {
    let src = "\
FUNCTION_BLOCK Carrier
VAR
    s3 : BOOL;
    dist : INT := 5;
END_VAR
PROPERTY P3 : BOOL
GET
P3 := s3;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK

FUNCTION_BLOCK State
VAR
    last : LREAL;
END_VAR
METHOD SetNum : BOOL
VAR_INPUT
    i_id : UINT;
    i_value : LREAL;
    i_force : BOOL;
END_VAR
last := i_value;
END_METHOD
END_FUNCTION_BLOCK

FUNCTION_BLOCK Observer
VAR
    m_p : POINTER TO Carrier;
    ok : BOOL;
END_VAR
METHOD Update : BOOL
VAR_IN_OUT
    io : State;
END_VAR
io.SetNum(1, INT_TO_LREAL(m_p^.dist), i_force := TRUE);
IF m_p^.P3 THEN
    ok := TRUE;
ELSE
    ok := FALSE;
END_IF
END_METHOD
END_FUNCTION_BLOCK

PROGRAM Main
VAR
    c : Carrier;
    o : Observer;
    s : State;
    n : INT;
    k : BOOL;
    v : LREAL;
END_VAR
n := n + 1;
c.s3 := (n MOD 2) = 0;
o.m_p := ADR(c);
o.Update(s);
k := o.ok;
v := s.last;
END_PROGRAM
";
    let (out, err) = common::run_text("hoisted.st", src, 4, "Main.k,Main.v");
    assert!(!err.contains("error["), "{err}");
    assert_eq!(column(&out, "Main.k"), [0.0, 1.0, 0.0, 1.0], "{out}");
    assert_eq!(column(&out, "Main.v"), [5.0, 5.0, 5.0, 5.0], "{out}");
}

/// A TwinCAT `<Transition>` object whose body is an FBD network (x-PPU's `TAbort`: one network
/// assigning the transition's name; IEC 61131-3 ed. 3 8.3.3 allows a transition condition in LD
/// or FBD) is read as the ST statement of its network: the chart of `twincat_sfc_run.rs` with
/// `T_Full` drawn as `GE(nLevel, 50) -> T_Full` runs scan by scan as with the ST condition
/// `nLevel >= 50`: in TwinCAT's processing order (actions first, the transition check last, round
/// 34) Fill adds 10 per scan from scan 3, T_Full fires at 50 at the end of scan 7, and in scan 8
/// Fill's exit action counts and Drain takes 20 per scan. Before: E0321 "the transition `T_Full`
/// is not one boolean expression", nothing run.
#[test]
fn a_transition_object_drawn_in_fbd_is_its_network_condition() {
    let fixture = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/twincat_sfc/fbd_transition/MAIN.TcPOU");
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "stim.csv",
        "cycle,variable,value\n2,MAIN.bStart,1\n3,MAIN.bStart,0\n",
    );
    let (code, out, err) = in_dir(
        dir.path(),
        &[
            "run",
            fixture.to_str().unwrap(),
            "--cycles",
            "12",
            "--cycle-ms",
            "10",
            "--stimulus",
            "stim.csv",
            "--trace",
            "-",
            "--watch",
            "MAIN.nLevel,MAIN.nExit",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(
        column(&out, "MAIN.nLevel"),
        // TwinCAT's processing order (round 34): each step's actions from the scan after its
        // transition, one scan later than before (as `twincat_sfc_run.rs`)
        [0.0, 0.0, 0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 30.0, 10.0, -10.0, -10.0],
        "{out}"
    );
    assert_eq!(
        column(&out, "MAIN.nExit"),
        // Fill's exit action in the scan after T_Full (scan 8; before: 7)
        [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
        "{out}"
    );
}

/// Round 32 made a library-qualified enumeration value in a body (`Lib.E.V`) the library's
/// E1032. A dotted `NAMESPACE` name of three parts (SIMATIC AX's `NAMESPACE Simatic.Ax.Comp`) is
/// no such value: the file runs (simatic-ax/lgencomp, where the first build of round 32 gave an
/// E1032 at `Simatic` and a cascade of E0307/E0011 over its five files).
#[test]
fn a_three_part_namespace_name_is_no_library_value() {
    let src = "\
NAMESPACE Simatic.Ax.Comp
    FUNCTION Twice : INT
        VAR_INPUT x : INT; END_VAR
        Twice := x * 2;
    END_FUNCTION
END_NAMESPACE

USING Simatic.Ax.Comp;
PROGRAM Main
    VAR n : INT; END_VAR
    n := Twice(n + 1);
END_PROGRAM
";
    let (out, err) = common::run_text("ns.st", src, 3, "Main.n");
    assert!(!err.contains("error["), "{err}");
    assert_eq!(column(&out, "Main.n"), [2.0, 6.0, 14.0], "{out}");
}
