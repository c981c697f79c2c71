//! OpenPLC Editor projects and plain ST / TwinCAT texts of the seventeenth acceptance run of issue
//! #13 (2026-12-04, branch `round17`).
//!
//! **The round.** Public units no earlier round had tried, checked and run as a new user would
//! (`ladderc run FILES --cycles N --stimulus ...`, or `check`; snapshots of 2026-12-04):
//! - OpenPLC Editor (`tc6_0201`, LD with function blocks): Federico19/Teoria_de_Control, the two
//!   versions of its lab 2 `plc.xml` (commits 0bdc5a7 and b5bf2b2): a proximity sensor (active low)
//!   through NOT into a 500 ms TP and a 10 s / 30 s TOF that drive a relay and a green and a red lamp;
//!   the second version adds three RGB dimmer words at `%QW0..2` blinking from TP chains while the
//!   TOF's elapsed time is inside a window. Beau28713/Waste_Water_VFD_Control (OpenPLC Editor v4, LD
//!   seal-in rungs and two ST function blocks with an enumeration). beta591414/-CMC- (a watering
//!   controller from a vendor's PLCopen editor: `<projects version="2.0">` around a `tc6.xsd`
//!   project, typed blocks `MAX_UDINT`/`MIN_UDINT`, comparison contacts, the vendor's I/O names).
//! - The ST and TwinCAT test files of klauer/blark (a TwinCAT ST parser, `blark/tests/source/*.st`
//!   and `blark/tests/POUs/*.TcPOU`, 21 files): `commas_in_case`, `type_and_fb`,
//!   `var_declarations_var_attrib`, `fb_w_public_access`, `fb_initializer`, `pointer_to_pointer_to`,
//!   `array_initializer`, `and_then_or_else`, `dereference_method`, `object_oriented_dotaccess`,
//!   `array_of_addresses`, `array_of_arrays`, `array_of_objects`, `array_with_integer_initializer`,
//!   `enum_with_function_calls`, `extended_union`, `repeated_declaration`, `stray_comment`,
//!   `FB_Log.TcPOU`, `F_SetStateParams.TcPOU` (pcdshub's lcls-twincat-motion), `global_version.TcPOU`.
//!
//! | | units | run (or check) and behave | rejected, naming what is missing or wrong | ladderc gap |
//! |---|---|---|---|---|
//! | before | 25 (4 PLCopen XML, 18 ST, 3 TcPOU) | 6 | 12 | 7: a header ending with `;` (F_SetStateParams); the `<projects>` wrapper (-CMC-, E3002 at the root); a METHOD after a pragma read as IL (4 files); E0349 for a block type not declared (object_oriented_dotaccess) |
//! | after | 25 | 6 | 15 | 4 left, branch stlang's (below) |
//!
//! Besides the units' own verdicts, constructs they use were gaps, fixed here and run from texts of
//! our own: enumeration values in array bounds (blark's `array_initializer`, `station/`), typed
//! function names on PLCopen blocks (-CMC-'s `MAX_UDINT`, `watering/level.xml`).
//!
//! Measured with main's binary at the start of the round (`before`) and this branch's (`after`), same
//! files, `ladderc check`: `F_SetStateParams.TcPOU` 7 errors before (E0106 at each declaration line:
//! the `VAR_INPUT` block read as statements), 3 after (E1003 naming `ST_BeamParams`,
//! `FB_LinearDeviceStateTable` and `ST_DeviceState`, the types of the library it belongs to);
//! `header_semi/F_InWindow.st` 10 errors before, runs after; `station/` (the enumeration-bounded
//! array of blocks) 3 errors before, runs after; `watering/level.xml` 1 E3002 before, runs after;
//! `rejected/comparison_contact.xml` E3002 at the root before, one E1054 at the contact after;
//! `rejected/selector_names.xml` 2 E1006 before, the same with 2 W1430 saying which variable hid the
//! value after; `object_oriented_dotaccess.st` 3 E0349 before, 1 E1003 (`SomeFunctionBlock`) after.
//! Every other unit gives the same diagnostics before and after.
//!
//! Fixed here:
//! - `FUNCTION F_SetStateParams : BOOL;` (TwinCAT accepts a `;` after a POU's header) read the
//!   declarations as statements: one E0106 per line. The `;` now ends the header of a FUNCTION,
//!   FUNCTION_BLOCK or PROGRAM (`st::file`, `header_semi`).
//! - `ARRAY[RunnerTasks.RUNNER_START+1..RunnerTasks.RUNNER_END-1] OF FB_Runner[...]`: an
//!   enumeration's values bound an array in CODESYS and TwinCAT; ladderc knew integer constants only
//!   (E0022). The values of an enumeration declared before (in the same text, or in another file given
//!   with it, a TwinCAT DUT) now count as integers in array bounds, string lengths and subrange
//!   bounds, numbered as sema numbers them (implicit values count on from the previous one); an
//!   initial value's expression still may not name one (IEC 61131-3 gives enumerations no
//!   arithmetic), and a constant of the same name wins (`const_eval::enum_key`).
//! - `<projects version="2.0">` holding one `<project>` (with its own copy of the headers) is the
//!   project inside; several projects stay E3002.
//! - A block named by a typed function name (`MAX_UDINT`, `EQ_UDINT`, `ADD_INT`, `MUX_INT_DINT`: IEC
//!   61131-3 edition 2, 2.5.1.4) was E3007 "unknown block type" in LD/FBD while ST read it: it is the
//!   function with its generic type fixed, as in ST.
//! - A `<contact typeName="EQ_UDINT">` with `<variable1>` (a vendor's comparison contact, no TC6
//!   element) gave E3008 about its UDINT variable; it is one E1054 naming it, nothing else read of it
//!   (its meaning is the vendor's: a compare block does the same in TC6).
//! - `Position := SEL_MANUAL;` where the block has an input `Sel_Manual : BOOL` (Beau28713's
//!   selector: IEC 61131-3 names ignore case): the variable is read, as matiec reads it (its
//!   "Incompatible data types for ':=' operation" at the same lines, so OpenPLC rejects the project
//!   too), and E1006 follows; W1430 now says that the variable hid the value and names
//!   `SELECTOR_POS#SEL_MANUAL`.
//! - A chain of method calls on an instance whose type is declared nowhere was E0349 "no method" at
//!   each chain; it is the unknown type, E1003 at the declaration, once (`st/lower/call_chain.rs`).
//! - W1400 for outputs of two sizes (`%QW0` over `%QX0.0`) names the OpenPLC profile in its hint.
//!
//! The runs: the OpenPLC sensor timer (reproduced in `proximity_hold.xml`, shorter times) follows
//! its comments: the lamp shows the sensor, a 500 ms pulse starts the off-delay, relay and green lamp
//! hold for the TOF's time after the pulse, the red lamp is their negation. The second version's RGB
//! window (`TIME_TO_INT(TOF1.ET)` between 20 and 30, exclusive, in milliseconds although the student
//! counted seconds) is never met at a 10 or 20 ms scan, so its dimmers stay 0, as in OpenPLC. Its
//! dimmer words at `%QW0..2` share bytes with the lamps at `%QX0.0..3` in ladderc's default memory
//! model (element addressing): W1400 says so, and writing the words clears the lamps; with the
//! OpenPLC profile (`crates/c-backend/profiles/openplc.json`, one image per size as OpenPLC keeps
//! them) they are apart and the lamps behave as in the first version (`proximity_hold_dimmers.xml`).
//! blark's runnable constructs (typed CASE ranges, an enumeration in a block, PUBLIC, a CONSTANT
//! without initial value, FB_init arguments with an initial value, `POINTER TO POINTER TO`, a UNION,
//! `AND_THEN`/`OR_ELSE`) run in `constructs.st`. -CMC-'s level network (the maximum of an analog
//! input and 5000, compared with 5000) runs in `watering/level.xml` with its I/O declared; as
//! published, its comparison contacts are E1054 and its I/O names (`AIO211_AI_CH2`, `DO211_CH3`,
//! the vendor's hardware configuration, not in the file) E1001.
//!
//! The rejections name: types of libraries the files need and do not bring (`ST_LibVersion`,
//! `ST_BeamParams`, `library.TPUDO`: E1003, E1032), an interface not given (`I_SendLog`, E0330),
//! enumerations or constants the fragment does not declare (E0022, E1003), enumeration values
//! computed by calls (E0011: IEC 61131-3 and TwinCAT want constants), a METHOD without its block
//! (E1063), a vendor's comparison contact (E1054), a variable hiding an enumeration value (E1006 with
//! W1430), a block type declared nowhere under a chain of method calls (E1003 at the declaration,
//! once; before, E0349 "no method" at each chain). Left, recorded for the lead: a method file whose `METHOD` follows an `{attribute ...}`
//! pragma (`array_of_arrays.st`, `array_of_objects.st`, `array_with_integer_initializer.st`,
//! `stray_comment.st`) is read as IL (E0011 "after the instruction" and W0001) instead of one E1063:
//! methods in files of their own are branch stlang's; array bounds from `SIZEOF` of TwinCAT's system
//! information (`FB_Log.TcPOU`) are one E0011 at the `(` (located, without naming SIZEOF); a UNION
//! that EXTENDS (`extended_union.st`) is two E0011.
//!
//! matiec side by side (`scripts/matiec-diff.sh`, iec2c 6bb2c33): blark's CASE and enumeration
//! constructs as `tests/fixtures/matiec_diff/r17_case_ranges.st` agree in every value (300 cycles x
//! 7 columns). matiec refuses the typed labels of blark's `CASE character OF BYTE#9..BYTE#10, ...`
//! ("invalid case element(s)": edition 2's grammar has untyped integers there, edition 3 constant
//! expressions) and a BYTE selector (IEC 61131-3: ANY_INT or an enumeration; TwinCAT takes a BYTE):
//! the corpus program writes untyped labels on a USINT, and the typed form runs here
//! (`constructs.st`). No new IL program was found this round.
//!
//! No repository of this round carries a licence that allows copying (Federico19, Beau28713,
//! beta591414: none; blark: GPL-2.0): every fixture under `tests/fixtures/unseen/r17/` is a text of
//! our own reproducing the constructs.

mod common;
use common::{changes, column, run_stimulated_files};
use std::path::{Path, PathBuf};

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/unseen/r17")
        .join(name)
}

/// The OpenPLC sensor, active low: present (FALSE) from cycle 100 to 109.
const SENSOR_PULSE: &str =
    "0,instance0.proximity,1\n100,instance0.proximity,0\n110,instance0.proximity,1\n";

/// Federico19's lab 2: NOT sensor -> TP 500 ms -> TOF (2 s here); lamp, relay and the two lamps.
#[test]
fn openplc_sensor_pulse_and_off_delay_run() {
    let (trace, _) = run_stimulated_files(
        &[fixture("proximity_hold.xml")],
        &[],
        400,
        SENSOR_PULSE,
        "instance0.lamp_ok,instance0.lamp_fault,instance0.lamp_seen,instance0.contactor",
    );
    // the lamp shows the sensor (10 ms scans: cycle k starts at k * 10 ms)
    assert_eq!(
        changes(&trace, "instance0.lamp_seen"),
        [(0, 0.0), (100, 1.0), (110, 0.0)]
    );
    // the pulse (1000..1500 ms) starts the off-delay: held until 1500 + 2000 ms
    assert_eq!(
        changes(&trace, "instance0.lamp_ok"),
        [(0, 0.0), (100, 1.0), (350, 0.0)]
    );
    assert_eq!(
        changes(&trace, "instance0.contactor"),
        changes(&trace, "instance0.lamp_ok")
    );
    assert_eq!(
        changes(&trace, "instance0.lamp_fault"),
        [(0, 1.0), (100, 0.0), (350, 1.0)]
    );
}

/// The second version's dimmer words at %QW0/%QW1 beside lamps at %QX0.0..3: W1400 and lamps
/// overwritten in the default memory model, apart with the OpenPLC profile.
#[test]
fn openplc_dimmer_words_share_bytes_unless_openplc_profile() {
    let watch = "instance0.lamp_ok,instance0.lamp_fault,instance0.dimmer_r,instance0.dimmer_g";
    let file = fixture("proximity_hold_dimmers.xml");
    let (trace, stderr) =
        run_stimulated_files(std::slice::from_ref(&file), &[], 400, SENSOR_PULSE, watch);
    assert!(
        stderr.contains("warning[W1400]: `program0.dimmer_r` at %QW0 shares output bits with `program0.lamp_ok` at %QX0.0"),
        "{stderr}"
    );
    assert!(
        stderr.contains(
            "OpenPLC and matiec keep one image per size, where they are apart: `--profile openplc`"
        ),
        "{stderr}"
    );
    // the red dimmer (lamp_fault as 0/1) written as a word after the lamps: bit 0 (lamp_ok) follows
    // it, bit 1 (lamp_fault) is cleared
    assert_eq!(
        changes(&trace, "instance0.lamp_ok"),
        [(0, 1.0), (100, 0.0), (350, 1.0)]
    );
    assert_eq!(changes(&trace, "instance0.lamp_fault"), [(0, 0.0)]);
    // the built-in profile the hint names (a release binary has no source tree beside it)
    let (trace, stderr) =
        run_stimulated_files(&[file], &["--profile", "openplc"], 400, SENSOR_PULSE, watch);
    assert!(!stderr.contains("W1400"), "{stderr}");
    assert_eq!(
        changes(&trace, "instance0.lamp_ok"),
        [(0, 0.0), (100, 1.0), (350, 0.0)]
    );
    assert_eq!(
        changes(&trace, "instance0.lamp_fault"),
        [(0, 1.0), (100, 0.0), (350, 1.0)]
    );
    assert_eq!(
        changes(&trace, "instance0.dimmer_r"),
        [(0, 1.0), (100, 0.0), (350, 1.0)]
    );
    assert_eq!(
        changes(&trace, "instance0.dimmer_g"),
        [(0, 0.0), (100, 1.0), (350, 0.0)]
    );
}

/// blark's F_SetStateParams.TcPOU: `FUNCTION F : BOOL;` (and the same `;` after a FUNCTION_BLOCK's
/// and a PROGRAM's name) ends the header; before, each declaration line was an E0106.
#[test]
fn header_ending_with_semicolon_runs() {
    let (trace, _) = run_stimulated_files(
        &[fixture("header_semi/F_InWindow.st")],
        &[],
        5,
        "",
        "MAIN.fbAxis.rPosition,MAIN.fbAxis.bInPosition",
    );
    assert_eq!(
        column(&trace, "MAIN.fbAxis.rPosition"),
        [1.0, 2.0, 3.0, 3.0, 3.0]
    );
    assert_eq!(
        column(&trace, "MAIN.fbAxis.bInPosition"),
        [0.0, 0.0, 1.0, 1.0, 1.0]
    );
}

/// blark's array_initializer.st: an array of blocks bounded by enumeration values (declared in
/// another file, a TwinCAT DUT), each element with its own FB_init arguments.
#[test]
fn enumeration_values_bound_an_array_of_blocks() {
    let watch = "MAIN.aStations[1].nParts,MAIN.aStations[2].nParts,MAIN.aStations[3].nParts,\
                 MAIN.aStations[1].sName,MAIN.sLast";
    // the enumeration's file before or after the program's: the same run
    for files in [
        [fixture("station/E_Station.st"), fixture("station/MAIN.st")],
        [fixture("station/MAIN.st"), fixture("station/E_Station.st")],
    ] {
        let (trace, _) = run_stimulated_files(
            &files,
            &[],
            5,
            "1,MAIN.bSensor,1\n2,MAIN.bSensor,0\n3,MAIN.bSensor,1\n",
            watch,
        );
        // indexes 1..3 (FIRST_STATION + 1 .. LAST_STATION - 1); the first two count rising parts
        assert_eq!(
            column(&trace, "MAIN.aStations[1].nParts"),
            [0.0, 1.0, 1.0, 2.0, 2.0]
        );
        assert_eq!(
            column(&trace, "MAIN.aStations[2].nParts"),
            column(&trace, "MAIN.aStations[1].nParts")
        );
        assert_eq!(column(&trace, "MAIN.aStations[3].nParts"), [0.0; 5]);
        let last = trace.lines().last().unwrap();
        assert!(last.ends_with(",\"infeed\",\"outfeed\""), "{trace}");
    }
}

/// An enumeration's value is an integer in a bound only, with its declared value (`RUN := 5`, then
/// 6): an initial value's expression naming one stays E0022 (IEC 61131-3 gives enumerations no
/// arithmetic).
#[test]
fn enumeration_values_are_no_numbers_in_initial_values() {
    let types = "TYPE E_Mode : (IDLE, RUN := 5, STOP); END_TYPE\n";
    let (code, lines) = common::check_text(
        "init.st",
        &format!(
            "{types}PROGRAM MAIN\nVAR\n    n : INT := E_Mode.STOP + 1;\nEND_VAR\nEND_PROGRAM\n"
        ),
    );
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("init.st:4:23: error[E0022]: constant expression `E_Mode.STOP + 1`: `E_Mode.STOP` names no constant with a value in the files given"),
        "{lines:?}"
    );
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("bounds.st");
    std::fs::write(
        &file,
        format!(
            "{types}PROGRAM MAIN\nVAR\n    a : ARRAY[E_Mode.RUN..E_Mode.STOP] OF INT;\nEND_VAR\n\
             a[5] := a[5] + 1;\na[6] := a[5] * 10;\nEND_PROGRAM\n"
        ),
    )
    .unwrap();
    let (trace, _) = run_stimulated_files(&[file], &[], 3, "", "MAIN.a[5],MAIN.a[6]");
    assert_eq!(column(&trace, "MAIN.a[5]"), [1.0, 2.0, 3.0]);
    assert_eq!(column(&trace, "MAIN.a[6]"), [10.0, 20.0, 30.0]);
}

/// blark's runnable constructs, in one program of our own.
#[test]
fn blark_constructs_run() {
    let (trace, stderr) = run_stimulated_files(
        &[fixture("constructs.st")],
        &[],
        256,
        "1,MAIN.bTestTwo,1\n2,MAIN.bTestOne,1\n",
        "MAIN.nPrintable,MAIN.fbCabinet.cabinet,MAIN.fbPublic.Error,MAIN.fbSample.nInit,\
         MAIN.fbSample.nInput,MAIN.nThroughTwo,MAIN.nLowByte,MAIN.nBranch",
    );
    assert!(stderr.contains("warning[W0304]"), "{stderr}");
    // characters 9, 10, 13 and 28..126 of 0..255: 102
    assert_eq!(column(&trace, "MAIN.nPrintable")[255], 102.0);
    // green (1) once the count passes 1
    assert_eq!(
        &column(&trace, "MAIN.fbCabinet.cabinet")[..3],
        [0.0, 1.0, 1.0]
    );
    assert_eq!(column(&trace, "MAIN.fbPublic.Error")[0], 1.0);
    assert_eq!(column(&trace, "MAIN.fbSample.nInit")[0], 1.0);
    assert_eq!(column(&trace, "MAIN.fbSample.nInput")[0], 2.0);
    assert_eq!(column(&trace, "MAIN.nThroughTwo")[0], 7.0);
    // 16#1234 little endian: low byte 16#34
    assert_eq!(column(&trace, "MAIN.nLowByte")[0], 52.0);
    assert_eq!(&column(&trace, "MAIN.nBranch")[..3], [3.0, 2.0, 1.0]);
}

/// `ladderc check FILE`: exit 1 and the error lines up to their hints, the folder left out.
fn rejected(file: &Path) -> Vec<String> {
    let (code, stderr) = common::check_stderr(file);
    assert_eq!(code, Some(1), "{stderr}");
    common::diagnostic_heads(stderr.as_bytes(), file.parent().unwrap(), false)
}

/// blark's fragments that need what they do not bring, or are not valid: each error located.
#[test]
fn blark_fragments_rejected_located() {
    let cases: &[(&str, &[&str])] = &[
        (
            "header_semi_types.st",
            &[
                "header_semi_types.st:6:14: error[E1003]: unknown type `ST_BeamParams`",
                "header_semi_types.st:9:13: error[E1003]: unknown type `FB_DeviceStateTable`",
            ],
        ),
        (
            "vendor_version.st",
            &["vendor_version.st:4:27: error[E1003]: unknown type `ST_LibVersion`"],
        ),
        (
            "library_type.st",
            &["library_type.st:4:34: error[E1032]: `vendorlib` is neither a variable nor a library ladderc provides"],
        ),
        (
            "enum_by_calls.st",
            // (since round 21 a value may be a constant expression: the call is read, and its
            // argument `E_Source.off`, no constant, stops it at the `.`)
            &["enum_by_calls.st:5:37: error[E0011]: unexpected `.`"],
        ),
        (
            "enum_bounds_undeclared.st",
            &[
                "enum_bounds_undeclared.st:5:31: error[E0022]: constant expression `E_Runner.RUNNER_START+1`: `E_Runner.RUNNER_START` names no constant with a value in the files given: no global variable list or library parameter list `E_Runner` given with the file declares `RUNNER_START`",
                "enum_bounds_undeclared.st:5:56: error[E0022]: constant expression `E_Runner.RUNNER_END-1`: `E_Runner.RUNNER_END` names no constant with a value in the files given: no global variable list or library parameter list `E_Runner` given with the file declares `RUNNER_END`",
            ],
        ),
        (
            "method_alone.st",
            &["method_alone.st:3:1: error[E1063]: a METHOD outside any FUNCTION_BLOCK"],
        ),
        (
            "task_info_bounds.st",
            // (SIZEOF in a bound is computed since round 18: the system list's `_TaskInfo` has
            // no size ladderc knows)
            &["task_info_bounds.st:4:27: error[E0022]: constant expression `SIZEOF(                          _TaskInfo)/SIZEOF(PlcTaskSystemInfo)`: the size of `_TaskInfo` is not known (no data type or variable of that name declared before, in this file or another given file)"],
        ),
        (
            "chain_undeclared.st",
            &["chain_undeclared.st:5:16: error[E1003]: unknown type `FB_Recipe`"],
        ),
        (
            "union_extends.st",
            &[
                "union_extends.st:2:14: error[E0011]: unexpected `EXTENDS`",
                "union_extends.st:5:1: error[E0011]: unexpected `END_UNION`",
            ],
        ),
    ];
    for (name, expected) in cases {
        let got = rejected(&fixture(&format!("rejected/{name}")));
        assert_eq!(got, *expected, "{name}");
    }
}

/// beta591414/-CMC-'s watering project (a vendor's editor): a `<projects version="2.0">` wrapper
/// around the TC6 project, and typed function names on blocks (`MAX_UDINT`, `EQ_UDINT`, as ST reads
/// `ADD_INT`). Before: E3002 at the root; after, the project inside runs.
#[test]
fn vendor_wrapper_and_typed_block_names_run() {
    let (trace, _) = run_stimulated_files(
        &[fixture("watering/level.xml")],
        &[],
        6,
        "0,instance0.AI_CH2,1000\n2,instance0.AI_CH2,5000\n4,instance0.AI_CH2,7000\n",
        "instance0.high,instance0.DO_CH3",
    );
    // high := MAX_UDINT(AI_CH2, 5000); DO_CH3 := EQ_UDINT(high, 5000)
    assert_eq!(
        column(&trace, "instance0.high"),
        [5000.0, 5000.0, 5000.0, 5000.0, 7000.0, 7000.0]
    );
    assert_eq!(
        column(&trace, "instance0.DO_CH3"),
        [1.0, 1.0, 1.0, 1.0, 0.0, 0.0]
    );
}

/// The same project's comparison contacts (`typeName="EQ_UDINT"` with `<variable1>`): one E1054 at
/// the contact, no E3008 about its UDINT variable; and Beau28713's selector, whose enumeration values
/// are also the names of its BOOL inputs (names ignore case): E1006 as matiec's "Incompatible data
/// types", each with W1430 saying which name hid the value.
#[test]
fn comparison_contact_and_hidden_enumeration_values_rejected() {
    assert_eq!(
        rejected(&fixture("rejected/comparison_contact.xml")),
        ["comparison_contact.xml:69:13: error[E1054]: contact `high` compares (`typeName=\"EQ_UDINT\"`): a vendor's comparison contact, not PLCopen TC6 [POU `level`, network 2, localId 7]"]
    );
    let file = fixture("rejected/selector_names.xml");
    assert_eq!(
        rejected(&file),
        [
            "selector_names.xml:48:3: error[E1006]: cannot store BOOL into SELECTOR_POS [POU `Selector`]",
            "selector_names.xml:51:3: error[E1006]: cannot store BOOL into SELECTOR_POS [POU `Selector`]",
        ]
    );
    let (_, stderr) = common::check_stderr(&file);
    let notes: Vec<&str> = stderr.lines().filter(|l| l.contains("W1430")).collect();
    assert_eq!(notes.len(), 2, "{stderr}");
    assert!(
        notes[0].contains("selector_names.xml:48:15: warning[W1430]: `SEL_MANUAL` is a variable here, not the value SELECTOR_POS#SEL_MANUAL the assignment expects"),
        "{stderr}"
    );
    // the fix the hint names: the value with its type
    let text = std::fs::read_to_string(&file)
        .unwrap()
        .replace(
            "Position := SEL_MANUAL;",
            "Position := SELECTOR_POS#SEL_MANUAL;",
        )
        .replace(
            "Position := SEL_AUTO;",
            "Position := SELECTOR_POS#SEL_AUTO;",
        );
    let (code, lines) = common::check_text("selector_fixed.xml", &text);
    assert_eq!((code, lines.len()), (Some(0), 0), "{lines:?}");
}

/// blark's object_oriented_dotaccess.st: methods chained on one statement, each returning a
/// reference to its block (runs), and the same on a block whose type is declared nowhere: one
/// E1003 at the declaration (before: E0349 "no method" at each chain, the type not named).
#[test]
fn chained_method_calls_run() {
    let (trace, _) = run_stimulated_files(
        &[fixture("chain/fluent.st")],
        &[],
        2,
        "",
        "MAIN.fbRecipe.nAmount",
    );
    // (0 + 5 + 2) * 10, then (70 + 7) * 10
    assert_eq!(column(&trace, "MAIN.fbRecipe.nAmount"), [70.0, 770.0]);
}

/// `--profile openplc` and `--profile default` are built in (a release binary has no source tree
/// beside it): OpenPLC's one image per size keeps `lamp AT %QX0.0` apart from `state AT %QW0`, the
/// default overlaps them (W1400, whose hint names `--profile openplc`); a bare name that is neither
/// is E9001 naming the built-in ones.
#[test]
fn the_openplc_profile_is_built_in_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("overlap.st");
    std::fs::write(
        &file,
        "PROGRAM p\nVAR\n  lamp AT %QX0.0 : BOOL;\n  state AT %QW0 : UINT;\nEND_VAR\n\
         lamp := TRUE;\nstate := 0;\nEND_PROGRAM\n",
    )
    .unwrap();
    let run = |profile: &[&str]| {
        let out = common::ladderc()
            .current_dir(dir.path())
            .args([
                "--message-format",
                "short",
                "run",
                "overlap.st",
                "--cycles",
                "1",
            ])
            .args(profile)
            .args(["--watch", "p.lamp"])
            .output()
            .unwrap();
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stdout).into_owned(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    let (code, trace, stderr) = run(&["--profile", "openplc"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("W1400"), "{stderr}");
    assert_eq!(column(&trace, "p.lamp"), [1.0]);
    for default in [&[][..], &["--profile", "default"][..]] {
        let (code, trace, stderr) = run(default);
        assert_eq!(code, Some(0), "{stderr}");
        assert!(stderr.contains("warning[W1400]"), "{stderr}");
        assert!(stderr.contains("`--profile openplc`"), "{stderr}");
        assert_eq!(column(&trace, "p.lamp"), [0.0]);
    }
    let (code, _, stderr) = run(&["--profile", "openplcx"]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("error[E9001]") && stderr.contains("`default`, `openplc`"),
        "{stderr}"
    );
}
