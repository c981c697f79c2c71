//! Constructs of the eleventh acceptance run of issue #13 (2026-12-03, branch `lang13`).
//!
//! **The round.** Public repositories no earlier round had tried, checked and run as a new user
//! would (`ladderc check FILE`, then `ladderc run FILE --cycles 50`; snapshots of 2026-12-03):
//! OpenPLC Editor projects (`plc.xml`): 3Matich/Lab-2-OpenPLC, 99sp4rky/waterUltra_ESP_PLC,
//! MatuAcosta/OpenPLC, SaxatileStoner/SFWE511-SemesterProject, angelakmiller/SFWE511 (and its
//! `.st` exports), simongawar/SFWE511, barbarafv/ModbusRedes, kando-123/Data-Flow-Graph,
//! mohsin-riad/PLC-into (7 labs), qUINNCYKID/openPCL, robert-brunner/PLC-Arduino, zibiax/PR009G,
//! Betosteles/CVS-a-XML-para-Proyectos-en-OPENPLC, Matrixas8/Laboratorios-Tecnologias-para-la-
//! automatizacion-Public-2, MauricioCastro16/control-automatizado-openplc, sorfpavel/RPA_semestalka,
//! VanAAO/scada-security-middleware, Vangogh911/alphaTags; OpenPLC v4 / STruC++ ST projects:
//! PiiJar/OpenPLC-Simulator (39 `.st` files, and a `plc.xml` its script generates),
//! thetdy/D64Programmer (`pous/programs/main.st`); hand-written ST: jhunterh/KEVIN; CODESYS-style
//! ST sources and a home-made "PLCopen" file: jomestoy/codesys-opcua-interface.
//!
//! | | units | run | rejected, naming what is missing | wrong |
//! |---|---|---|---|---|
//! | before | 37 (28 XML files, 9 ST files or projects) | 15 | 18 | 4 |
//! | after | 37 | 17 (2 with `--profile crates/c-backend/profiles/openplc.json`) | 20 | 0 |
//!
//! Wrong before: the OpenPLC simulator (891 E2001, one per variable beyond the default 256-byte
//! `%Q`), an OpenPLC v4 program (E0011 at each `x : BOOL AT %QX0.0;`), the water plant whose valve
//! positions at `%QW0..` overwrote its pump bits at `%QX0.x` (38 W1400; OpenPLC keeps them apart), a
//! file cut off at `IF (C1F4MemLoc AN` (a second error about the same word). The rejections name:
//! INT variables at bit addresses (E1027, matiec refuses the files too), a POU without an interface
//! (E1001), a misspelt variable (E1001), unwired coils of an unfinished block (E3005), `Power ON` as
//! a transition (E0107) and a dangling transition (E3128), `1063 M^3` as an initial value (E3011),
//! a pasted table as a body (E0106), `ARRAY[1..MAX_UNITS] OF UNIT_T` as a `<derived>` name (E3013,
//! now naming it), three XML files that are not PLCopen projects (E3002: a CODESYS OPC UA symbol
//! file, a home-made `<plcopenSource>`, a variable list), the C++ blocks of an OpenPLC v4 project and
//! the enumeration it keeps in `project.json` (E1003), EXTENDS (E0303: needs the `extends` work).
//!
//! **Side by side with matiec**: none of the round could be. The XML projects carry no generated
//! ST; matiec refuses the SFWE511 `.st` files (invalid locations) and the OpenPLC v4 simulator
//! (VAR_GLOBAL outside a configuration, named constants in bounds without `-a`), which was written
//! for STruC++.
//!
//! Each test is a minimal reproduction written here, run through `ladderc run` (C compiled with
//! the sanitizers) or `ladderc check`. The repositories' files are not copied here.

mod common;
use common::{check_text, ladderc, rejected_heads, run_stimulated};

/// OpenPLC Editor v4 writes the declarations of its per-POU `.st` files (`pous/programs/main.st`)
/// with the location after the type, also before an initial value: `LedBusy : BOOL AT %QX0.0;`,
/// `Count : INT AT %QW1 := 5;`. They are read as `LedBusy AT %QX0.0 : BOOL;`, with one warning
/// W0016 each, and the variables are the process image's: the stimulus sets `%IX0.0`, the trace
/// reads `%QX0.0` and `%QW1`, and `%QW1` starts at its initial value 5. Before: E0011 `expected
/// `;` before `AT`` at each declaration, and nothing ran.
#[test]
fn location_after_the_type_as_openplc_editor_v4_writes_it_runs_with_w0016() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("main.st");
    std::fs::write(
        &f,
        "PROGRAM main\n  VAR\n    Start : BOOL AT %IX0.0 := FALSE;\n    LedBusy : BOOL AT %QX0.0;\n\
         \x20   Count : INT AT %QW1 := 5;\n    Limit : INT := 6;\n  END_VAR\n\
         IF Start THEN\n  Count := Count + 1;\nEND_IF;\nLedBusy := Count > Limit;\nEND_PROGRAM\n",
    )
    .unwrap();
    let (trace, stderr) = run_stimulated(&f, 4, "1,%IX0.0,1\n", "%IX0.0,%QW1,%QX0.0,main.Count");
    assert_eq!(stderr.matches("warning[W0016]").count(), 3, "{stderr}");
    assert!(
        stderr.contains(
            "main.st:5:17: warning[W0016]: the location `AT %QW1` is written after the type: read as if it stood before the `:`"
        ),
        "{stderr}"
    );
    // cycle 0: Start FALSE, Count stays 5; from cycle 1 it counts; LedBusy once Count > 6
    assert_eq!(
        trace,
        "cycle,time_ms,%IX0.0,%QW1,%QX0.0,main.Count\n\
         0,0,0,5,0,5\n1,10,1,6,0,6\n2,20,1,7,1,7\n3,30,1,8,1,8\n"
    );
}

/// The form after the type keeps the rules of the standard one: a location for several names is
/// E0017, an INT at a bit address is E1027, and the standard form is not warned about.
#[test]
fn location_after_the_type_keeps_the_rules_of_located_variables() {
    let heads = rejected_heads(
        "p.st",
        "PROGRAM p\nVAR\n  a, b : BOOL AT %QX0.0;\n  n : INT;\nEND_VAR\nn := n + 1;\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        [
            "p.st:3:6: error[E0017]: one location (`AT`) for several names",
            "p.st:3:15: warning[W0016]: the location `AT %QX0.0` is written after the type: read as if it stood before the `:`",
        ]
    );
    let heads = rejected_heads(
        "w.st",
        "PROGRAM w\nVAR\n  w : INT AT %IX0.1;\nEND_VAR\nw := 1;\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        [
            "w.st:3:11: warning[W0016]: the location `AT %IX0.1` is written after the type: read as if it stood before the `:`",
            "w.st:3:14: error[E1027]: `w` has type INT, but `%IX0.1` is a single bit: a bit address holds a BOOL",
        ]
    );
    let (code, lines) = check_text(
        "q.st",
        "PROGRAM q\nVAR\n  x AT %QX0.0 : BOOL;\nEND_VAR\nx := TRUE;\nEND_PROGRAM\n",
    );
    assert_eq!((code, lines), (Some(0), Vec::<String>::new()));
}

/// A program written for a larger process image than the profile's (OpenPLC has 1,024 words of
/// `%IW` and `%QW`): the first address outside each area, in source order, is one E2001 whose
/// hint names the size it needs, with a note counting the others and naming the size that holds
/// them all. Before: one E2001 per variable (891 for a 39-file OpenPLC simulator). With a profile
/// of that size the same program runs.
#[test]
fn addresses_outside_an_area_are_one_error_per_area() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("far.st");
    std::fs::write(
        &f,
        "PROGRAM main\nVAR\n  near AT %QW2 : INT := 7;\n  seq AT %QW200 : INT;\n\
         \x20 prog AT %QW128 : INT := 1;\n  last AT %QW1023 : INT;\n  cmd AT %IW300 : INT;\n\
         \x20 ack AT %IW301 : INT;\nEND_VAR\nseq := cmd + 1;\nlast := ack;\n%QW130 := 3;\nEND_PROGRAM\n",
    )
    .unwrap();
    let out = ladderc().arg("check").arg(&f).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.matches("error[E2001]").count(), 2, "{stderr}");
    assert!(
        stderr.contains("error[E2001]: address `%QW200` is outside the %Q area (256 bytes in target profile `default`)"),
        "{stderr}"
    );
    assert!(
        stderr.contains("whose `output_bytes` is at least 402")
            && stderr.contains(
                "note: 3 more addresses outside the %Q area are not reported; the farthest, `%QW1023`, needs a target profile whose `output_bytes` is at least 2048"
            ),
        "{stderr}"
    );
    assert!(
        stderr.contains("error[E2001]: address `%IW300` is outside the %I area")
            && stderr.contains(
                "note: 1 more address outside the %I area is not reported: `%IW301`, which needs a target profile whose `input_bytes` is at least 604"
            ),
        "{stderr}"
    );
    // a profile of that size runs it
    let profile = dir.path().join("openplc.json");
    std::fs::write(
        &profile,
        r#"{"name": "openplc", "input_bytes": 2048, "output_bytes": 2048, "memory_bytes": 4096,
            "byte_order": "little", "bit_numbering": "lsb0", "address_unit": "element",
            "tm_offset": 3840, "tm_bytes": 256, "alignment": 1, "data_bytes": 16777216}"#,
    )
    .unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, "cycle,variable,value\n1,%IW300,41\n2,%IW301,9\n").unwrap();
    let out = ladderc()
        .arg("run")
        .arg(&f)
        .arg("--profile")
        .arg(&profile)
        .args(["--cycles", "3", "--stimulus"])
        .arg(&stim)
        .args([
            "--watch",
            "%QW2,%QW128,%QW130,%QW200,%QW1023",
            "--trace",
            "-",
        ])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "cycle,time_ms,%QW2,%QW128,%QW130,%QW200,%QW1023\n\
         0,0,7,1,3,1,0\n1,10,7,1,3,42,0\n2,20,7,1,3,42,9\n"
    );
}

/// A `<derived name="ARRAY[1..MAX_UNITS] OF UNIT_T"/>` (a type written out as the name, as a
/// project's script generated it for OpenPLC Editor, whose generator copies the text into the ST
/// it gives matiec) is one E3013 per variable that names the text and says how PLCopen XML writes
/// an array. Before: "<derived> type without a valid `name`", which did not say what was wrong
/// with the name.
#[test]
fn a_type_expression_as_a_derived_name_is_named() {
    let xml = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">\
               <fileHeader companyName=\"\" productName=\"OpenPLC\" productVersion=\"1\" creationDateTime=\"2024-01-01T00:00:00\"/>\
               <contentHeader name=\"p\"><coordinateInfo><fbd><scaling x=\"10\" y=\"10\"/></fbd><ld><scaling x=\"10\" y=\"10\"/></ld>\
               <sfc><scaling x=\"10\" y=\"10\"/></sfc></coordinateInfo></contentHeader><types><dataTypes/><pous>\
               <pou name=\"main\" pouType=\"program\"><interface><localVars>\n\
               <variable name=\"units\"><type><derived name=\"ARRAY[1..MAX_UNITS] OF UNIT_T\"/></type></variable>\n\
               <variable name=\"names\"><type><derived name=\"STRING[20]\"/></type></variable>\n\
               <variable name=\"n\"><type><INT/></type></variable>\n\
               </localVars></interface><body><ST><xhtml:p xmlns:xhtml=\"http://www.w3.org/1999/xhtml\"><![CDATA[n := m + 1;]]></xhtml:p></ST></body></pou>\
               </pous></types><instances><configurations/></instances></project>\n";
    let heads = rejected_heads("plc.xml", xml);
    assert_eq!(
        heads,
        [
            "plc.xml:3:45: error[E3013]: <derived> type name `ARRAY[1..MAX_UNITS] OF UNIT_T` is not a type name [POU `main`]",
            "plc.xml:4:45: error[E3013]: <derived> type name `STRING[20]` is not a type name [POU `main`]",
        ]
    );
    let (_, lines) = check_text("plc.xml", xml);
    assert!(
        lines[0].contains("PLCopen XML writes an array type as <array>"),
        "{lines:?}"
    );
}

/// A file cut off in the middle of an IF condition (`IF (C1F4MemLoc AN`, the last line of a
/// published elevator program): the misspelt operator is one E0100, the IF the end of the text
/// leaves open one E0105. Before, the name was read again as a statement at the end of the text, a
/// third error (E0106 `expected := or ( after AN, found end of text`) about the same word. A name
/// followed by the end of the text with no error before it is still E0106.
#[test]
fn a_file_cut_off_in_a_condition_is_not_reported_twice_at_its_last_word() {
    let heads = rejected_heads(
        "cut.st",
        "PROGRAM p\nVAR a, b, c : BOOL; END_VAR\nIF (a AND b) THEN\n  c := TRUE;\nEND_IF;\nIF (a AN",
    );
    assert_eq!(
        heads,
        [
            "cut.st:6:7: error[E0100]: expected `)`, found name `AN`",
            "cut.st:6:9: error[E0105]: IF is not closed: expected `END_IF`, found the end of the body",
            "cut.st:6:9: warning[W0014]: `p` ends at the end of the file without `END_PROGRAM`: read as if it were there",
        ]
    );
    let heads = rejected_heads(
        "tail.st",
        "PROGRAM p\nVAR a : BOOL; END_VAR\na := TRUE;\nfoo",
    );
    assert_eq!(
        heads[0],
        "tail.st:4:4: error[E0106]: expected `:=` or `(` after `foo`, found the end of the body"
    );
}

/// OpenPLC keeps its digital and analog images apart: `%QX0.1` is a digital output, `%QW0` an
/// analog one, `%QD0` and `%QL0` other registers (matiec gives each located variable its own
/// storage too). A student's water plant (SFWE511) drives pumps at `%QX0.x` and valve positions at
/// `%QW0..%QW7`: with the default profile the valve's value overwrites the pump bits (38 W1400).
/// With `crates/c-backend/profiles/openplc.json` (`"address_unit": "per_size"`) each size has its
/// own image: no W1400, the pump bit follows its input while the valve holds 50, and an address
/// given only in `--watch` (`%QB0`, the byte of `%QX0.0..%QX0.7`) is found in the same image.
#[test]
fn openplc_profile_keeps_digital_and_analog_images_apart() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("plant.st");
    std::fs::write(
        &f,
        "PROGRAM main\nVAR\n  start AT %IX0.0 : BOOL;\n  level AT %IW0 : INT;\n  pump AT %QX0.1 : BOOL;\n\
         \x20 valve AT %QW0 : INT;\n  total AT %QD0 : DINT;\n  big AT %QL0 : LINT;\nEND_VAR\n\
         pump := start;\nvalve := level * 2;\ntotal := total + 1;\nbig := 7;\nEND_PROGRAM\n",
    )
    .unwrap();
    let profile = common::repo_root().join("crates/c-backend/profiles/openplc.json");
    let stim = dir.path().join("stim.csv");
    std::fs::write(
        &stim,
        "cycle,variable,value\n1,%IX0.0,1\n1,%IW0,25\n2,%IX0.0,0\n",
    )
    .unwrap();
    let out = ladderc()
        .args(["--message-format", "short", "run"])
        .arg(&f)
        .arg("--profile")
        .arg(&profile)
        .args(["--cycles", "3", "--sanitize", "--stimulus"])
        .arg(&stim)
        .args([
            "--watch",
            "%IX0.0,%IW0,%QX0.1,%QB0,%QW0,%QD0,%QL0",
            "--trace",
            "-",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("W1400"), "{stderr}");
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "cycle,time_ms,%IX0.0,%IW0,%QX0.1,%QB0,%QW0,%QD0,%QL0\n\
         0,0,0,0,0,0,0,1,7\n1,10,1,25,1,2,50,2,7\n2,20,0,25,0,0,50,3,7\n"
    );
    // the default profile overlaps them, as W1400 says: `valve` (50) is bits of `pump`'s byte
    let (_, stderr) = common::check_stderr(&f);
    assert_eq!(stderr.matches("warning[W1400]").count(), 3, "{stderr}");
}

/// A profile with `"address_unit": "per_size"` keeps each image within its size: `%QW1024` is
/// outside a 2048-byte word image even though the `%Q` array holds four images.
#[test]
fn per_size_images_are_bounded_one_by_one() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("far.st");
    std::fs::write(
        &f,
        "PROGRAM main\nVAR\n  ok AT %QW1023 : INT;\n  far AT %QW1024 : INT;\n  bit AT %QX2047.7 : BOOL;\nEND_VAR\n\
         ok := 1;\nEND_PROGRAM\n",
    )
    .unwrap();
    let profile = common::repo_root().join("crates/c-backend/profiles/openplc.json");
    let out = ladderc()
        .args(["--message-format", "short", "check"])
        .arg(&f)
        .arg("--profile")
        .arg(&profile)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    let heads = common::diagnostic_heads(&out.stderr, dir.path(), true);
    assert_eq!(
        heads,
        ["far.st:4:10: error[E2001]: address `%QW1024` is outside the %Q area (2048 bytes in target profile `openplc`)"]
    );
}
