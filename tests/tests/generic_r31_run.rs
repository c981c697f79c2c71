//! Round 31 of issue #13: TwinCAT's and CODESYS's generic constants, and a REAL literal that ends
//! in its point.
//!
//! - `VAR_GENERIC CONSTANT` (Beckhoff Infosys, TC3 PLC "Generic constant variables - VAR_GENERIC
//!   CONSTANT", TwinCAT 3.1.4026; CODESYS online help "VAR_GENERIC CONSTANT"): each instance's
//!   values (`FB_Buf<10>`, `FB_Buf<(2 * GVL.nCount)>`, `FB_Pou<100, 1000>`, `FB_Pou<(nB := 3)>`)
//!   size its own block; an instance without `<...>` takes the initial values. Before: one E1081
//!   per block and per instance (a documented limit), nothing ran.
//! - A value that does not fit (a variable, a value too many, a name the block does not declare,
//!   `<...>` after a block without generic constants): one located E1090 per instance. An error
//!   inside a generic block is said once, however many sizes are built.
//! - `10.` (CODESYS V2.3 exports: `iVoltageOut / 10.;`): the REAL 10.0, with W1459 (IEC 61131-3
//!   requires a digit after the point; CODESYS compiles it). Before: E0104 "missing `;` ... (found
//!   `.`)".

mod common;
use common::{check_files, check_text, column, run_stimulated_files, run_text};

const FB_BUF: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4026.0">
  <POU Name="FB_Buf" Id="{00000000-0000-4000-8000-000000000001}" SpecialFunc="None">
    <Declaration><![CDATA[FUNCTION_BLOCK FB_Buf
VAR_GENERIC CONSTANT
	nLen : UDINT := 4;
END_VAR
VAR_INPUT
	nIn : INT;
END_VAR
VAR_OUTPUT
	nSum : INT;
END_VAR
VAR
	aVal : ARRAY[1..nLen] OF INT;
	i : UDINT;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[nSum := 0;
FOR i := 1 TO nLen DO
	aVal[i] := nIn * UDINT_TO_INT(i);
	nSum := nSum + aVal[i];
END_FOR]]></ST>
    </Implementation>
    <Method Name="Size" Id="{00000000-0000-4000-8000-000000000002}">
      <Declaration><![CDATA[METHOD Size : UDINT
]]></Declaration>
      <Implementation>
        <ST><![CDATA[Size := nLen;]]></ST>
      </Implementation>
    </Method>
  </POU>
</TcPlcObject>
"#;

const GVL: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4026.0">
  <GVL Name="GVL" Id="{00000000-0000-4000-8000-000000000003}">
    <Declaration><![CDATA[{attribute 'qualified_only'}
VAR_GLOBAL CONSTANT
	nCount : UDINT := 3;
END_VAR
]]></Declaration>
  </GVL>
</TcPlcObject>
"#;

const MAIN: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4026.0">
  <POU Name="MAIN" Id="{00000000-0000-4000-8000-000000000004}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
	fbTen : FB_Buf<10>;
	fbSix : FB_Buf<(2 * GVL.nCount)>;
	fbDefault : FB_Buf;
	aPair : ARRAY[1..2] OF FB_Buf<2>;
	nTen, nSix, nDefault, nPair : INT;
	nSizeTen, nSizeSix, nSizeDefault : UDINT;
	nStep : INT;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[nStep := nStep + 1;
fbTen(nIn := nStep);
fbSix(nIn := nStep);
fbDefault(nIn := nStep);
aPair[2](nIn := nStep);
nTen := fbTen.nSum;
nSix := fbSix.nSum;
nDefault := fbDefault.nSum;
nPair := aPair[2].nSum;
nSizeTen := fbTen.Size();
nSizeSix := fbSix.Size();
nSizeDefault := fbDefault.Size();]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
"#;

/// Three instances of a TwinCAT block whose array and loop are sized by its generic constant
/// `nLen` (default 4): `FB_Buf<10>`, `FB_Buf<(2 * GVL.nCount)>` (a global constant, 3) and a plain
/// `FB_Buf`, and an array of `FB_Buf<2>`; each sums `nIn * i` for i in 1..nLen, and its method
/// `Size` returns its own `nLen`. Checked cycle by cycle. Before: three E1081, nothing ran.
#[test]
fn each_instance_is_a_block_of_its_own_size() {
    let dir = tempfile::tempdir().unwrap();
    let mut paths = Vec::new();
    for (name, text) in [
        ("FB_Buf.TcPOU", FB_BUF),
        ("GVL.TcGVL", GVL),
        ("MAIN.TcPOU", MAIN),
    ] {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        paths.push(p);
    }
    let (trace, stderr) = run_stimulated_files(
        &paths,
        &["--cycle-ms", "10"],
        3,
        "",
        "MAIN.nTen,MAIN.nSix,MAIN.nDefault,MAIN.nPair,MAIN.nSizeTen,MAIN.nSizeSix,MAIN.nSizeDefault",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    // sum of n * i for i in 1..N at step n: n * N * (N + 1) / 2
    assert_eq!(column(&trace, "MAIN.nTen"), vec![55.0, 110.0, 165.0]);
    assert_eq!(column(&trace, "MAIN.nSix"), vec![21.0, 42.0, 63.0]);
    assert_eq!(column(&trace, "MAIN.nDefault"), vec![10.0, 20.0, 30.0]);
    assert_eq!(column(&trace, "MAIN.nPair"), vec![3.0, 6.0, 9.0]);
    assert_eq!(column(&trace, "MAIN.nSizeTen"), vec![10.0; 3]);
    assert_eq!(column(&trace, "MAIN.nSizeSix"), vec![6.0; 3]);
    assert_eq!(column(&trace, "MAIN.nSizeDefault"), vec![4.0; 3]);
}

const TWO_CONSTANTS: &str = "FUNCTION_BLOCK FB_Grid
VAR_GENERIC CONSTANT
    nA : INT := 2;
    nB : INT := 2;
END_VAR
VAR_OUTPUT
    nCells : INT;
    nLast : INT;
END_VAR
VAR
    aCells : ARRAY[1..nA, 1..nB] OF INT;
    i, j : INT;
END_VAR
nCells := 0;
FOR i := 1 TO nA DO
    FOR j := 1 TO nB DO
        aCells[i, j] := i * 10 + j;
        nCells := nCells + 1;
    END_FOR
END_FOR
nLast := aCells[nA, nB];
END_FUNCTION_BLOCK

PROGRAM main
VAR
    gBoth : FB_Grid<3, 4>;
    gNamed : FB_Grid<(nB := 5)>;
    gSame : FB_Grid<2, 2>;
    nBoth, nNamed, nSame, lBoth, lNamed : INT;
END_VAR
gBoth();
gNamed();
gSame();
nBoth := gBoth.nCells;
lBoth := gBoth.nLast;
nNamed := gNamed.nCells;
lNamed := gNamed.nLast;
nSame := gSame.nCells;
END_PROGRAM
";

/// Two generic constants in a `.st` file: values in the order of the declarations
/// (`FB_Grid<3, 4>`), by name with the other's initial value (`FB_Grid<(nB := 5)>`), and equal to
/// the initial values (`FB_Grid<2, 2>`, the block itself); a two-dimensional array sized by both.
/// Before: E1081 for the block and each instance.
#[test]
fn values_in_order_and_by_name() {
    let (trace, stderr) = run_text(
        "grid.st",
        TWO_CONSTANTS,
        2,
        "main.nBoth,main.lBoth,main.nNamed,main.lNamed,main.nSame",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "main.nBoth"), vec![12.0; 2]);
    assert_eq!(column(&trace, "main.lBoth"), vec![34.0; 2]);
    assert_eq!(column(&trace, "main.nNamed"), vec![10.0; 2]);
    assert_eq!(column(&trace, "main.lNamed"), vec![25.0; 2]);
    assert_eq!(column(&trace, "main.nSame"), vec![4.0; 2]);
}

/// Values that do not fit: a variable (`<(v)>`), a value too many (`<1, 2>`), a name the block
/// does not declare (`<(M := 3)>`, CODESYS's C0587), `<3>` after a block without generic
/// constants: one E1090 each, at the instance's type, and nothing else (each instance is read as a
/// plain instance). Before: E1081 for each, and E0001 at `<` and `>` of the named value.
#[test]
fn values_that_do_not_fit_are_one_e1090_each() {
    let src = "FUNCTION_BLOCK FB_Buf
VAR_GENERIC CONSTANT
    N : UDINT := 4;
END_VAR
VAR
    data : ARRAY[1..N] OF INT;
END_VAR
data[1] := 1;
END_FUNCTION_BLOCK

FUNCTION_BLOCK FB_Plain
VAR
    q : INT;
END_VAR
q := 1;
END_FUNCTION_BLOCK

PROGRAM main
VAR
    v : UDINT := 3;
    a : FB_Buf<(v)>;
    b : FB_Buf<1, 2>;
    c : FB_Buf<(M := 3)>;
    d : FB_Plain<3>;
END_VAR
a(); b(); c(); d();
END_PROGRAM
";
    let (code, lines) = check_text("misfit.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 4, "{lines:?}");
    let expect = [
        (
            "misfit.st:21:9: error[E1090]",
            "`(v)` is not an integer constant expression",
        ),
        (
            "misfit.st:22:9: error[E1090]",
            "2 values given, `FB_Buf` declares 1",
        ),
        (
            "misfit.st:23:9: error[E1090]",
            "`M` is no generic constant of `FB_Buf`",
        ),
        (
            "misfit.st:24:9: error[E1090]",
            "`FB_Plain` declares no generic constants",
        ),
    ];
    for (line, (head, words)) in lines.iter().zip(expect) {
        assert!(line.starts_with(head) && line.contains(words), "{line}");
    }
}

/// An error inside a generic block (an undeclared name in its body) with three sizes built: one
/// E1001, at the block's own line and column. An instance whose size leaves an array empty
/// (`FB_Buf<0>`): E1003 at the bound in the block.
#[test]
fn an_error_in_a_generic_block_is_said_once() {
    let (code, lines) = check_files(&[
        (
            "FB_Buf.TcPOU",
            &FB_BUF.replace("nSum := nSum + aVal[i];", "nSum := nSum + aVal[i] + zz;"),
        ),
        ("GVL.TcGVL", GVL),
        ("MAIN.TcPOU", MAIN),
    ]);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("FB_Buf.TcPOU:23:27: error[E1001]"),
        "{lines:?}"
    );
    let (code, lines) = check_files(&[
        ("FB_Buf.TcPOU", FB_BUF),
        ("GVL.TcGVL", GVL),
        ("MAIN.TcPOU", &MAIN.replace("FB_Buf<10>", "FB_Buf<0>")),
    ]);
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(
        lines[0].starts_with("FB_Buf.TcPOU:15:15: error[E1003]: empty array range 1..0"),
        "{lines:?}"
    );
}

/// `10.` and `1.` (CODESYS V2.3's REAL literals without a digit after the point): the REALs 10.0
/// and 1.0, one W1459 each at the literal; `1..10` (a range) and `w.1` (a bit) are unchanged.
/// Before: E0104 "missing `;` after the statement (found `.`)" for each.
#[test]
fn a_real_literal_may_end_in_its_point() {
    let src = "PROGRAM main
VAR
    iRaw : INT := 125;
    rVolts : REAL;
    rHalf : REAL;
    w : WORD := 2;
    b : BOOL;
    a : ARRAY[1..10] OF INT;
END_VAR
rVolts := INT_TO_REAL(iRaw) / 10.;
rHalf := 1. / 2.0;
b := w.1;
a[10] := 1;
END_PROGRAM
";
    let (code, lines) = check_text("volts.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].starts_with("volts.st:10:31: warning[W1459]: `10.` has no digit after its point: read as the REAL `10.0`"),
        "{lines:?}"
    );
    assert!(
        lines[1].starts_with("volts.st:11:10: warning[W1459]"),
        "{lines:?}"
    );
    let (trace, _) = run_text("volts.st", src, 2, "main.rVolts,main.rHalf,main.b");
    assert_eq!(column(&trace, "main.rVolts"), vec![12.5; 2]);
    assert_eq!(column(&trace, "main.rHalf"), vec![0.5; 2]);
    assert_eq!(column(&trace, "main.b"), vec![1.0; 2]);
}
