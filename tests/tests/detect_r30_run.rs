//! Round 30 (issue #13): files that are not what they seem get one diagnostic that says what they
//! are. Siemens STL (`.awl`) read as IL is one E0023 naming STL (before: 9 scattered IL errors on
//! a real MicroWIN export); a binary file (a CODESYS V3 `.project`, an archive, any bytes with NUL)
//! is one E1093 at its start (before: "this file is Siemens SCL" on all 5 real `.project` files); a
//! CODESYS CFC body, exported as an empty `<ST>` plus the chart in vendor data, is one E0321 naming
//! its POU (before: compiled as an empty body, exit 0, only W3002 "vendor data ignored").

mod common;

use common::{check_text, in_dir, run_text};

/// The bytes a CODESYS V3 `.project` starts with (a fixed GUID), as the real files of five public
/// repositories do.
const CODESYS_PROJECT_MAGIC: [u8; 16] = [
    0x23, 0x89, 0xED, 0x33, 0x14, 0xBD, 0x93, 0x4B, 0x8D, 0xA9, 0x5D, 0x91, 0x08, 0xC5, 0x32, 0x35,
];

/// `ladderc check NAME` of `bytes` written to a temporary folder: exit code and standard error.
fn check_bytes(name: &str, bytes: &[u8]) -> (Option<i32>, String) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join(name), bytes).unwrap();
    let (code, _, stderr) = in_dir(dir.path(), &["check", name]);
    (code, stderr)
}

/// The error lines of `stderr` (short format).
fn errors(stderr: &str) -> Vec<&str> {
    stderr.lines().filter(|l| l.contains("error[")).collect()
}

/// A MicroWIN (S7-200) STL export, written for this test: block, title, networks, `A`/`AN`/`O`,
/// `=` and a timer box. IEC 61131-3 ed. 2, 3.2 (Table 52) has no `=` operator and no
/// ORGANIZATION_BLOCK: the file is not IL. Before: note W0302, E0011 at `MAIN:OB1`, W0001, E0001 at
/// each `TITLE=` and `=` line; now one E0023 at the block keyword, naming STL.
#[test]
fn siemens_stl_awl_is_one_error_naming_stl() {
    let src = "ORGANIZATION_BLOCK MAIN:OB1\nTITLE=Pump station\nBEGIN\nNetwork 1 // start\nLD     I0.0\nO      M0.0\nAN     I0.1\n=      M0.0\nNetwork 2\nLD     M0.0\nTON    T37, 50\n=      Q0.0\nEND_ORGANIZATION_BLOCK\n";
    let (code, lines) = check_text("pumps.awl", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("pumps.awl:1:1: error[E0023]: this file is Siemens STL")
            && errors[0].contains("not IEC 61131-3 instruction list"),
        "{lines:?}"
    );
    // nothing else but the note that the file was read as IL by its content
    assert!(lines.iter().all(|l| !l.contains("warning[")), "{lines:?}");
}

/// An STL fragment without its block (networks and `=` only), even named `.il`, is STL too: one
/// E0023 at its first mark, the `Network` heading.
#[test]
fn an_stl_fragment_named_il_is_one_error() {
    let src = "// S7-200 rung\nNetwork 1\nLD     I0.0\nAN     T40\n=      Q0.0\n";
    let (code, lines) = check_text("rung.il", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("rung.il:2:1: error[E0023]: this file is Siemens STL"),
        "{lines:?}"
    );
}

/// An IEC IL file whose one slip looks like STL (`A y` for `AND y`) is not taken for STL: the
/// slip's own error (one mark of one kind is not enough), and valid IL still runs.
#[test]
fn il_with_one_stl_like_slip_keeps_its_own_error() {
    let src = "PROGRAM p\nVAR x : BOOL; y : BOOL; END_VAR\nLD x\nA y\nST y\nEND_PROGRAM\n";
    let (code, lines) = check_text("slip.il", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(lines.iter().all(|l| !l.contains("E0023")), "{lines:?}");
    assert!(
        lines.iter().any(|l| l.starts_with("slip.il:4:1: error[")),
        "{lines:?}"
    );
    let (trace, _) = run_text(
        "ok.il",
        "PROGRAM p\nVAR x : BOOL := TRUE; y : BOOL; END_VAR\nLD x\nAND x\nST y\nEND_PROGRAM\nCONFIGURATION c RESOURCE r ON PLC TASK t(INTERVAL := T#10ms, PRIORITY := 1); PROGRAM m WITH t : p; END_RESOURCE END_CONFIGURATION\n",
        2,
        "m.y",
    );
    assert_eq!(common::column(&trace, "m.y"), vec![1.0, 1.0], "{trace}");
}

/// A binary CODESYS V3 project (its magic bytes, then bytes that hold `#Jy`, which the ST reader
/// once took for SCL's `#local`): one E1093 at 1:1 naming a CODESYS project, with the PLCopen XML
/// export as the hint, exit 1. Before: W0302, W0305 and E0023 "this file is Siemens SCL".
#[test]
fn a_binary_codesys_project_is_named() {
    let mut bytes = CODESYS_PROJECT_MAGIC.to_vec();
    bytes.extend_from_slice(b"#Jy\x01\x02\xfe PROGRAM x \x00\x00\x10");
    let (code, stderr) = check_bytes("Plant.project", &bytes);
    assert_eq!(code, Some(1), "{stderr}");
    let errors = errors(&stderr);
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].starts_with("Plant.project:1:1: error[E1093]: a binary CODESYS V3 project"),
        "{stderr}"
    );
    assert!(errors[0].contains("Export PLCopenXML"), "{stderr}");
    assert!(
        !stderr.contains("SCL") && !stderr.contains("W0302"),
        "{stderr}"
    );
}

/// An older CODESYS `.project` is a ZIP archive: the extension names it (E1093, CODESYS project);
/// a ZIP archive of another name is named a ZIP archive.
#[test]
fn a_zip_is_named_by_its_extension() {
    let zip = b"PK\x03\x04\x14\x00\x00\x00\x08\x00project.xml";
    let (code, stderr) = check_bytes("old.project", zip);
    assert_eq!(code, Some(1), "{stderr}");
    assert_eq!(errors(&stderr).len(), 1, "{stderr}");
    assert!(
        stderr.contains("old.project:1:1: error[E1093]: a binary CODESYS V3 project"),
        "{stderr}"
    );
    let (code, stderr) = check_bytes("sources.zip", zip);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("sources.zip:1:1: error[E1093]: a ZIP archive"),
        "{stderr}"
    );
}

/// Any other file with NUL bytes is one E1093 "not a text file" at its start, whatever its name;
/// before, the bytes decided which reader took it (XML E3001, IL E0011, or SCL's E0023).
#[test]
fn any_other_binary_is_not_text() {
    let bytes: Vec<u8> = (0..2048u32)
        .map(|i| (i.wrapping_mul(2_654_435_761) >> 13) as u8)
        .collect();
    assert!(bytes.contains(&0));
    for name in ["blob.bin", "blob.st", "blob.xml"] {
        let (code, stderr) = check_bytes(name, &bytes);
        assert_eq!(code, Some(1), "{name}: {stderr}");
        let errors = errors(&stderr);
        assert_eq!(errors.len(), 1, "{name}: {stderr}");
        assert!(
            errors[0].starts_with(&format!(
                "{name}:1:1: error[E1093]: not a text file (it holds NUL bytes)"
            )),
            "{stderr}"
        );
    }
}

/// UTF-16 text (NUL bytes, but a byte-order mark) is still text: it compiles.
#[test]
fn utf16_text_with_its_mark_is_still_read() {
    let text = "PROGRAM p\nVAR x : INT; END_VAR\nx := x + 1;\nEND_PROGRAM\n";
    let mut bytes = vec![0xFF, 0xFE];
    bytes.extend(text.encode_utf16().flat_map(u16::to_le_bytes));
    let (code, stderr) = check_bytes("wide.st", &bytes);
    assert_eq!(code, Some(0), "{stderr}");
}

/// A CODESYS V3 PLCopen XML export of a POU and a method in CFC: TC6 has no CFC body, so CODESYS
/// writes an empty `<ST>` and the chart in `<addData><data name=".../plcopenxml/cfc">`. The POU's
/// chart is read as FBD since round 31 (`cfc_r31_run.rs`); the method's is one E0321 at its
/// `<CFC>` naming the method (before: exit 0, the bodies compiled empty, only W3002 "vendor data
/// ignored"); the W3002 counts neither.
#[test]
fn a_codesys_cfc_body_is_one_error_naming_its_pou() {
    let cfc = |out: &str| {
        format!(
            r#"<body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml"/></ST>
        <addData><data name="http://www.3s-software.com/plcopenxml/cfc" handleUnknown="implementation">
          <CFC>
            <inVariable localId="0"><position x="8" y="10"/><connectionPointOut><expression/></connectionPointOut><expression>a</expression></inVariable>
            <outVariable localId="1" executionOrderId="0"><position x="20" y="10"/><connectionPointIn><connection refLocalId="0"/></connectionPointIn><expression>{out}</expression></outVariable>
          </CFC>
        </data></addData></body>"#
        )
    };
    let src = format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="" productName="CODESYS" productVersion="CODESYS V3.5 SP20" creationDateTime="2025-01-01T00:00:00"/>
  <contentHeader name="t.project"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Relay" pouType="program">
      <interface><localVars>
        <variable name="a"><type><BOOL/></type><initialValue><simpleValue value="TRUE"/></initialValue></variable>
        <variable name="b"><type><BOOL/></type></variable>
        <variable name="c"><type><BOOL/></type></variable>
      </localVars></interface>
      {}
      <addData><data name="http://www.3s-software.com/plcopenxml/method" handleUnknown="implementation"><Method name="Copy"><interface/>{}</Method></data></addData>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="c"><resource name="r">
    <task name="t" interval="PT0.01S" priority="1"><pouInstance name="m" typeName="Relay"/></task>
  </resource></configuration></configurations></instances>
</project>
"#,
        cfc("b"),
        cfc("c")
    );
    let (code, lines) = check_text("relay.xml", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<_> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with(
            "relay.xml:21:11: error[E0321]: the body of method `Copy` is a CODESYS CFC chart, which ladderc does not read"
        ),
        "{lines:?}"
    );
    assert!(errors[0].contains("[POU `Relay`]"), "{lines:?}");
    assert!(lines.iter().all(|l| !l.contains("W3002")), "{lines:?}");
}
