//! TwinCAT points found in public projects by round 31's sweep (issue #13), end to end:
//! - a `--lib` library project matches its `<Compile Include>` paths regardless of case, as the
//!   application's project does (TwinCAT runs on Windows; before: E9001 and exit 2, then E0330
//!   follow-ons, in OpenCommissioning's OC_Core used as a library);
//! - an output connection `CV => n` follows the rule of the assignment `n := inst.CV` (a WORD
//!   output into a UINT is W1436, as the assignment; before: E1012);
//! - `MEMCPY(p + i - 1, ADR(x) + n - i, 1)`: + and - chain left to right, so the address moved
//!   on by `i - 1` bytes is bounded as `p + (i - 1)` (before: E1035);
//! - an array of a block type declared nowhere, used through a method chain
//!   (`a[1].args.Clear().Add(n)`): the missing type is the one error, E1003 (before: E0349
//!   "is no method" only, the type never named);
//! - a TwinCAT 3 IL body (a network list whose networks are `ILActive`) is one E0325 that names
//!   it as IL (before: "LD/FBD body"), a limit the README lists.

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

/// A TwinCAT object file holding the POU `name` with the declaration `decl` and the ST body `body`.
fn tc_pou(name: &str, decl: &str, body: &str) -> String {
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4024.12\">\n  \
<POU Name=\"{name}\" Id=\"{{11111111-2222-3333-4444-555555555555}}\" SpecialFunc=\"None\">\n    \
<Declaration><![CDATA[{decl}]]></Declaration>\n    <Implementation>\n      <ST><![CDATA[{body}]]></ST>\n    \
</Implementation>\n  </POU>\n</TcPlcObject>\n"
    )
}

/// A `.plcproj` listing `includes` (Windows paths) and referencing the placeholders `libs`.
fn plcproj(name: &str, includes: &[&str], libs: &[&str]) -> String {
    let compile: String = includes
        .iter()
        .map(|i| format!("    <Compile Include=\"{i}\"><SubType>Code</SubType></Compile>\n"))
        .collect();
    let refs: String = libs
        .iter()
        .map(|l| {
            format!(
                "    <PlaceholderReference Include=\"{l}\">\n      <DefaultResolution>{l}, * (Me)</DefaultResolution>\n      \
<Namespace>{l}</Namespace>\n    </PlaceholderReference>\n"
            )
        })
        .collect();
    format!(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Project DefaultTargets=\"Build\" xmlns=\"http://schemas.microsoft.com/developer/msbuild/2003\">\n  \
<PropertyGroup>\n    <Name>{name}</Name>\n    <Title>{name}</Title>\n  </PropertyGroup>\n  <ItemGroup>\n{compile}  </ItemGroup>\n  \
<ItemGroup>\n{refs}  </ItemGroup>\n</Project>\n"
    )
}

/// OpenCommissioning's OC_Core lists `Common\Links\FB_LinkDataLWord.TcPOU` while the file is
/// `FB_LinkDataLWORD.TcPOU`; TwinCAT (on Windows, whose file names ignore case) reads it. Given
/// with `--lib`, the library's Includes are now matched as the application's are: regardless of
/// case (the file renamed in case, and a folder too). The application runs with the library's
/// base and derived blocks: the counter inherited from the base counts one per scan. Before:
/// E9001 "cannot read Lib/POUs/FB_Base.TcPOU", exit 2, and E0330 for the derived block.
#[test]
fn a_library_project_matches_its_includes_regardless_of_case() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write_in(
        d,
        "Lib/Lib.plcproj",
        &plcproj("Lib", &[r"POUs\FB_Base.TcPOU", r"Pous\FB_Child.TcPOU"], &[]),
    );
    write_in(
        d,
        "Lib/POUs/FB_BASE.TcPOU",
        &tc_pou(
            "FB_Base",
            "FUNCTION_BLOCK FB_Base\nVAR_OUTPUT\n\tn : INT;\nEND_VAR\n",
            "n := n + 1;",
        ),
    );
    write_in(
        d,
        "Lib/POUs/FB_Child.TcPOU",
        &tc_pou(
            "FB_Child",
            "FUNCTION_BLOCK FB_Child EXTENDS FB_Base\n",
            "SUPER^();",
        ),
    );
    write_in(
        d,
        "App/App.plcproj",
        &plcproj("App", &[r"POUs\MAIN.TcPOU"], &["Lib"]),
    );
    write_in(
        d,
        "App/POUs/MAIN.TcPOU",
        &tc_pou(
            "MAIN",
            "PROGRAM MAIN\nVAR\n\tc : FB_Child;\n\tk : INT;\nEND_VAR\n",
            "c();\nk := c.n;",
        ),
    );
    let (code, out, err) = in_dir(
        d,
        &[
            "run",
            "App/App.plcproj",
            "--lib",
            "Lib/Lib.plcproj",
            "--cycles",
            "3",
            "--cycle-ms",
            "10",
            "--trace",
            "-",
            "--watch",
            "MAIN.k",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("error["), "{err}");
    assert_eq!(column(&out, "MAIN.k"), [1.0, 2.0, 3.0], "{out}");
}

/// The CTD of a TwinCAT file has Tc2_Standard's interface (PV, CV : WORD). TC3_Lampara writes
/// `CV => ManiobrasPendientes` with a UINT: the output connection stores the output into the
/// variable after the call (IEC 61131-3 ed. 3, 6.6.1.4.2), so it follows the rule of the
/// assignment `nA := fbCount.CV` in the same POU: the WORD counts as the unsigned integer UINT
/// (W1436, once per POU), and both variables hold the counter's value every scan. Before: E1012
/// "output CV of CTD is WORD, cannot be stored into UINT" on the `=>` only.
#[test]
fn an_output_connection_stores_as_the_assignment_does() {
    let src = tc_pou(
        "MAIN",
        "PROGRAM MAIN\nVAR\n    fbCount : CTD;\n    bPulse  : BOOL;\n    bLoad   : BOOL;\n    nA      : UINT;\n    nB      : UINT;\nEND_VAR\n",
        "bLoad := nA = 0 AND NOT bPulse;\nfbCount(CD := bPulse, LOAD := bLoad, PV := 3, CV => nB);\nnA := fbCount.CV;\nbPulse := NOT bPulse;",
    );
    let (code, lines) = check_text("MAIN.TcPOU", &src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("warning[W1436]")
            && lines[0].contains("WORD counted as the unsigned integer UINT"),
        "{lines:?}"
    );
    let (trace, _) = run_text("MAIN.TcPOU", &src, 8, "MAIN.nA,MAIN.nB");
    // cycle 0 loads 3 (CD low); each rising CD (cycles 1, 3, 5, 7) counts down; at 0 the
    // load (cycle 6, CD low) gives 3 again
    let a = column(&trace, "MAIN.nA");
    assert_eq!(a, [3.0, 2.0, 2.0, 1.0, 1.0, 0.0, 3.0, 2.0], "{trace}");
    assert_eq!(column(&trace, "MAIN.nB"), a, "{trace}");
}

/// The other way round: an output that the assignment may not store either (TON's ET, a TIME,
/// into an INT) stays one E1012 at the `=>`'s variable, as `n := t.ET` is one E1006.
#[test]
fn an_output_connection_the_assignment_refuses_stays_an_error() {
    let src = "PROGRAM main\nVAR\n    t : TON;\n    n : INT;\n    m : INT;\nEND_VAR\n\
t(IN := TRUE, PT := T#1S, ET => n);\nm := t.ET;\nEND_PROGRAM\n";
    let (code, lines) = check_text("app.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errs.len(), 2, "{lines:?}");
    assert!(
        errs[0].contains(
            "app.st:7:33: error[E1012]: output ET of TON is TIME, cannot be stored into INT"
        ),
        "{errs:?}"
    );
    assert!(
        errs[1].contains("app.st:8:") && errs[1].contains("error[E1006]"),
        "{errs:?}"
    );
}

/// OC_Core's `F_Memcpy` swaps bytes with `MEMCPY(destAddr + i - 1, ADR(aBuffer) + n - i, 1)`:
/// `a + b - c` is `(a + b) - c` (+ and - have one precedence and are evaluated from the left,
/// IEC 61131-3 Table 55/71) and TwinCAT counts a pointer byte-wise (Beckhoff Infosys, "Pointer"),
/// so both addresses are the address moved on by a byte offset, bounded as `p + (i - 1)` is. The
/// four bytes come out reversed, through an address (`ADR(dst) + i - 1`) and through a pointer
/// variable (`p + i - 1`). Before: two E1035 "the variable this pointer points into cannot be
/// known" per call.
#[test]
fn memcpy_with_a_chained_byte_offset_copies_from_and_to_that_offset() {
    let src = "FUNCTION F_Swap : UDINT\nVAR_INPUT\n    d : PVOID;\n    n : UDINT;\nEND_VAR\n\
VAR\n    buf : ARRAY[0..3] OF BYTE := [16#11, 16#22, 16#33, 16#44];\n    i : UDINT;\nEND_VAR\n\
FOR i := 1 TO n DO\n    F_Swap := MEMCPY(d + i - 1, ADR(buf) + n - i, 1);\nEND_FOR\nEND_FUNCTION\n\n\
PROGRAM main\nVAR\n    a : ARRAY[0..3] OF BYTE;\n    b : ARRAY[0..3] OF BYTE;\n    i : UDINT;\n\
    a0, a3, b0, b1, b3 : BYTE;\nEND_VAR\n\
F_Swap(d := ADR(a), n := 4);\n\
FOR i := 1 TO 4 DO\n    MEMCPY(ADR(b) + i - 1, ADR(a) + 4 - i, 1);\nEND_FOR\n\
a0 := a[0]; a3 := a[3]; b0 := b[0]; b1 := b[1]; b3 := b[3];\nEND_PROGRAM\n";
    let (trace, err) = run_text("app.st", src, 2, "main.a0,main.a3,main.b0,main.b1,main.b3");
    assert!(!err.contains("error["), "{err}");
    assert_eq!(column(&trace, "main.a0"), [68.0, 68.0], "{trace}"); // 16#44
    assert_eq!(column(&trace, "main.a3"), [17.0, 17.0], "{trace}"); // 16#11
    assert_eq!(column(&trace, "main.b0"), [17.0, 17.0], "{trace}");
    assert_eq!(column(&trace, "main.b1"), [34.0, 34.0], "{trace}");
    assert_eq!(column(&trace, "main.b3"), [68.0, 68.0], "{trace}");
}

/// AAG_Tc3EventLogger's test bench: `Alarm : ARRAY[1..5] OF FB_TcAlarm` (Tc3_EventLogger, not
/// given) with `Alarm[i].ipArguments.Clear().AddUDInt(Cnt)`. The missing block type is the cause:
/// one E1003 naming it at the declaration, nothing for the chain. Before: one E0349 "`al[1].ipArgs.Clear`
/// is no method" and the type never named.
#[test]
fn a_method_chain_on_an_array_of_an_unknown_block_names_the_type() {
    let src = "PROGRAM Main\nVAR\n    al : ARRAY[1..2] OF FB_Missing;\n    n : UDINT;\n    i : INT := 1;\nEND_VAR\n\
al[1].ipArgs.Clear().AddUDInt(n);\nal[i].ipArgs.Clear().AddUDInt(n + 1);\nEND_PROGRAM\n";
    let (code, lines) = check_text("app.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].contains("app.st:3:25: error[E1003]: unknown type `FB_Missing`"),
        "{errs:?}"
    );
}

/// TwinCAT 3 keeps an IL body as a network list whose networks are shown as IL (`ILActive`): a
/// table of operator, operand and parenthesis rows, call arguments over several rows and
/// operands that may be ST expressions (TC3_Lampara's IL blocks). ladderc does not read it (the
/// README lists the limit): one E0325 at the first network, naming the body as IL and saying
/// what to do. Before: the same code, its message calling the body "LD/FBD".
#[test]
fn a_twincat_il_body_is_one_error_naming_it_as_il() {
    let src = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\" ProductVersion=\"3.1.4024.15\">\n\
  <POU Name=\"P_IL\" Id=\"{77777777-7777-7777-7777-777777777777}\" SpecialFunc=\"None\">\n\
    <Declaration><![CDATA[PROGRAM P_IL\nVAR\n    bIn  : BOOL;\n    bOut : BOOL;\nEND_VAR\n]]></Declaration>\n\
    <Implementation>\n      <NWL>\n        <XmlArchive>\n          <Data>\n\
            <o xml:space=\"preserve\" t=\"NWLImplementationObject\">\n\
              <v n=\"DefaultViewMode\">\"Il\"</v>\n\
              <l2 n=\"NetworkList\" cet=\"Network\">\n\
                <o>\n\
                  <v n=\"ILActive\">true</v>\n\
                  <l2 n=\"ILLines\" cet=\"ILStatement\">\n\
                    <o>\n                      <v n=\"Operator\">\"LD\"</v>\n                      <v n=\"Prefix\">\"\"</v>\n\
                      <o n=\"Operand\" t=\"Operand\">\n                        <v n=\"Operand\">\"bIn\"</v>\n                      </o>\n\
                      <v n=\"Postfix\">\"\"</v>\n                    </o>\n\
                  </l2>\n\
                  <l2 n=\"NetworkItems\" />\n\
                </o>\n\
              </l2>\n\
            </o>\n          </Data>\n        </XmlArchive>\n      </NWL>\n    </Implementation>\n  </POU>\n</TcPlcObject>\n";
    let (code, lines) = check_text("P_IL.TcPOU", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].contains("P_IL.TcPOU:17:1: error[E0325]: TwinCAT IL body of `P_IL`, network 1")
            && errs[0].contains("not read")
            && errs[0].contains("write the body in ST"),
        "{errs:?}"
    );
}
