//! Round 30: how inputs are named. A Beremiz project folder is the same project whichever way its
//! `plc.xml` is named (`plc.xml`, `./plc.xml`, `DIR/plc.xml`); a Beremiz Python file's STRING
//! variable whose initial value has no quotes is that text, as Beremiz quotes it; an element of a
//! multi-dimensional array is set by `--stimulus` and traced by `--watch` under the name the trace
//! writes for it (`"m.grid[1,0]"`).

mod common;

use common::*;
use std::path::Path;

/// A `plc.xml` of one program `main` (instance `m`) with the ST body `body` and the declarations
/// `vars` (PLCopen `<variable>` elements of its interface).
fn plc_xml(vars: &str, body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="main" pouType="program">
      <interface>
{vars}
      </interface>
      <body><ST><xhtml:p><![CDATA[{body}]]></xhtml:p></ST></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="c"><resource name="r">
    <task name="t" priority="0" interval="T#10ms"><pouInstance name="m" typeName="main"/></task>
  </resource></configuration></configurations></instances>
</project>
"#
    )
}

/// A Beremiz project folder `dir`: `plc.xml`, `beremiz.xml` and a Python file confnode
/// `py_ext_0@py_ext` whose `pyfile.xml` declares `variables` (`<variable .../>` elements).
fn beremiz_project(dir: &Path, plc: &str, variables: &str) {
    write_in(dir, "plc.xml", plc);
    write_in(
        dir,
        "beremiz.xml",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<BeremizRoot URI_location=\"LOCAL://\">\n  <TargetType/>\n</BeremizRoot>\n",
    );
    write_in(
        dir,
        "py_ext_0@py_ext/baseconfnode.xml",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<BaseParams IEC_Channel=\"1\" Name=\"py_ext_0\"/>\n",
    );
    write_in(
        dir,
        "py_ext_0@py_ext/pyfile.xml",
        &format!(
            "<?xml version='1.0' encoding='utf-8'?>\n<PyFile xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">\n  <variables>\n{variables}\n  </variables>\n</PyFile>\n"
        ),
    );
}

/// The values of column `name` of a CSV trace whose header may quote names (RFC 4180).
fn quoted_column(trace: &str, name: &str) -> Vec<String> {
    let mut lines = trace.lines();
    let head = split_csv(lines.next().unwrap());
    let k = head
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {head:?}"));
    lines.map(|l| split_csv(l)[k].clone()).collect()
}

/// A Python file's (py_ext) STRING variables with initial values written without quotes
/// (`initial="localhost"`, `initial="C:\dir\"`) are those texts: Beremiz's generator
/// (`PLCGenerator.ComputeValue`, beremiz/beremiz) adds the quotes to a STRING value that has none,
/// for these configuration globals as for plc.xml's own variables, and a Beremiz build of such a
/// project holds `host : STRING := 'localhost';`. A value already in quotes is read as the literal.
/// Before: E1025 "`localhost` is not a constant known here" and E0320 "... is not a literal", exit 1.
#[test]
fn python_file_string_initial_without_quotes_is_the_text() {
    let dir = tempfile::tempdir().unwrap();
    let plc = plc_xml(
        r#"        <localVars>
          <variable name="n_host"><type><INT/></type></variable>
          <variable name="n_path"><type><INT/></type></variable>
          <variable name="n_quoted"><type><INT/></type></variable>
          <variable name="is_local"><type><BOOL/></type></variable>
        </localVars>
        <externalVars>
          <variable name="host"><type><string/></type></variable>
          <variable name="PATH"><type><string/></type></variable>
          <variable name="quoted"><type><string/></type></variable>
        </externalVars>"#,
        "n_host := LEN(host); n_path := LEN(PATH); n_quoted := LEN(quoted);\n\
         is_local := host = 'localhost';",
    );
    beremiz_project(
        dir.path(),
        &plc,
        r#"    <variable name="host" type="STRING" initial="localhost"/>
    <variable name="PATH" type="STRING" initial="C:\dir\"/>
    <variable name="quoted" type="STRING" initial="'abc'"/>"#,
    );
    let (trace, stderr) = run_traced(dir.path(), 2, "m.n_host,m.n_path,m.n_quoted,m.is_local");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "m.n_host"), [9.0, 9.0], "{trace}");
    assert_eq!(column(&trace, "m.n_path"), [7.0, 7.0], "{trace}");
    assert_eq!(column(&trace, "m.n_quoted"), [3.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "m.is_local"), [1.0, 1.0], "{trace}");
}

/// `ladderc run plc.xml` inside a Beremiz project folder reads the confnodes beside it, as
/// `./plc.xml`, the folder `.` and `DIR/plc.xml` from its parent do (README: Beremiz project
/// folders): the Python file's global `counter` (41) is declared in all four runs, and each traces
/// `m.n` = 42. Before: the bare `plc.xml` (whose parent is the empty path) lost the confnodes: one
/// E1001 "undeclared name `counter`", exit 1.
#[test]
fn bare_plc_xml_in_a_beremiz_folder_reads_its_confnodes() {
    let parent = tempfile::tempdir().unwrap();
    let dir = parent.path().join("proj");
    let plc = plc_xml(
        r#"        <localVars><variable name="n"><type><INT/></type></variable></localVars>
        <externalVars><variable name="counter"><type><INT/></type></variable></externalVars>"#,
        "n := counter + 1;",
    );
    beremiz_project(
        &dir,
        &plc,
        r#"    <variable name="counter" type="INT" initial="41"/>"#,
    );
    let runs = [
        (dir.as_path(), "plc.xml"),
        (dir.as_path(), "./plc.xml"),
        (dir.as_path(), "."),
        (parent.path(), "proj/plc.xml"),
    ];
    for (cwd, input) in runs {
        let (code, trace, stderr) = in_dir(
            cwd,
            &[
                "run", input, "--cycles", "2", "--watch", "m.n", "--trace", "-",
            ],
        );
        assert_eq!(code, Some(0), "{input}: {stderr}");
        assert!(!stderr.contains("error["), "{input}: {stderr}");
        assert_eq!(column(&trace, "m.n"), [42.0, 42.0], "{input}: {trace}");
    }
}

const GRID: &str = "PROGRAM m
VAR
  grid : ARRAY[0..2, 0..1] OF BOOL;
  hit : BOOL;
  count : INT;
END_VAR
hit := grid[1, 0];
IF grid[2, 1] THEN count := count + 1; END_IF;
END_PROGRAM
";

/// An element of a 2-D array is set by `--stimulus` and traced by `--watch` under the names IEC
/// 61131-3 writes (ed. 2, 2.4.1.2: `grid[1,0]`), with or without a blank in the subscript list,
/// and in the quoted form the trace header writes for it (`"m.grid[1,0]"`, RFC 4180), cycle by
/// cycle. Before: both split the name at its comma (`unknown variable `m.grid[1``), and the
/// stimulus reader did not take the quotes off (`unknown variable `"m.grid[1``), exit 2.
#[test]
fn two_d_array_element_is_set_and_watched_by_its_trace_name() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("grid.st");
    std::fs::write(&file, GRID).unwrap();
    let (trace, _) = run_stimulated(
        &file,
        5,
        "1,\"m.grid[1,0]\",TRUE\n2,m.grid[2, 1],TRUE\n3,m.grid[1,0],FALSE\n4,\"m.grid[2,1]\",FALSE\n",
        "m.grid[1,0],m.grid[2, 1],\"m.grid[0,1]\",m.hit,m.count",
    );
    let head = split_csv(trace.lines().next().unwrap());
    assert_eq!(
        head,
        [
            "cycle",
            "time_ms",
            "\"m.grid[1,0]\"",
            "\"m.grid[2,1]\"",
            "\"m.grid[0,1]\"",
            "m.hit",
            "m.count"
        ],
        "{trace}"
    );
    assert_eq!(
        quoted_column(&trace, "\"m.grid[1,0]\""),
        ["0", "1", "1", "0", "0"]
    );
    assert_eq!(
        quoted_column(&trace, "\"m.grid[2,1]\""),
        ["0", "0", "1", "1", "0"]
    );
    assert_eq!(
        quoted_column(&trace, "\"m.grid[0,1]\""),
        ["0", "0", "0", "0", "0"]
    );
    assert_eq!(quoted_column(&trace, "m.hit"), ["0", "1", "1", "0", "0"]);
    assert_eq!(quoted_column(&trace, "m.count"), ["0", "0", "1", "2", "2"]);
}

/// Every name of a full trace's header, given back as the `--watch` list exactly as the header
/// writes it (quotes included), traces the same columns. Before: exit 2 at the first name with a
/// comma.
#[test]
fn full_trace_header_is_a_watch_list() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("grid.st");
    std::fs::write(&file, GRID).unwrap();
    let (full, _) = run_stimulated(&file, 2, "", "");
    let header = full.lines().next().unwrap();
    let names = header.strip_prefix("cycle,time_ms,").unwrap();
    assert!(names.contains("\"m.grid[2,1]\""), "{header}");
    let (watched, _) = run_stimulated(&file, 2, "", names);
    assert_eq!(watched.lines().next(), Some(header));
}

/// A stimulus row whose quoted name is not closed is an error naming the row (`ladderc run`
/// exits 1), not an unknown variable. (New form; before, every quoted name was unknown.)
#[test]
fn stimulus_name_with_an_open_quote_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("grid.st");
    std::fs::write(&file, GRID).unwrap();
    let stim = dir.path().join("stim.csv");
    std::fs::write(&stim, "cycle,variable,value\n1,\"m.grid[1,0],TRUE\n").unwrap();
    let (code, _, stderr) = in_dir(
        dir.path(),
        &["run", "grid.st", "--cycles", "2", "--stimulus", "stim.csv"],
    );
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("stim.csv:2: a quoted name has no closing `\"`"),
        "{stderr}"
    );
}
