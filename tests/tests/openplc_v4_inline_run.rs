//! OpenPLC Editor v4 projects whose POUs are inline in `project.json` (round 25 of issue #13):
//! the editor's 2025 releases kept each POU in `data.pous[].data` (`name`, `variables`,
//! `body: {"language": "st", "value": "..."}` or a Ladder body's rung JSON) before moving them to
//! `pous/*.st|*.ld`. ladderc now reads them as it reads the folder form:
//! - ST POUs (a program calling a function block, its variables by class, a body whose JSON
//!   escapes hold line breaks, a quote and a comment) run from the folder and from `project.json`
//!   given alone, with the task and instance of the file's configuration (before: the folder was an
//!   unlocated E9001 "no POU file under pous/", exit 2; the file was read as ST, one pragma, and
//!   passed `check` and ran empty cycles with exit 0);
//! - a Ladder body (the same rung JSON as `pous/programs/main.ld`) runs (before: as above);
//! - an error of an ST body is located in `project.json` at its place in the JSON string; an FBD
//!   body is one E1073 at the body (before: as above);
//! - a `.json` input that is no v4 project is one located E1074, exit 1, never read as ST
//!   (before: read as ST, exit 0).

mod common;
use common::{check_text, column, in_dir, run_stimulated_files, write_in};

/// A v4 project.json with `pous` (JSON array items) and one 10 ms task running `main`.
fn project(pous: &str) -> String {
    format!(
        r#"{{
  "meta": {{ "name": "inline", "type": "plc-project" }},
  "data": {{
    "dataTypes": [],
    "pous": [
{pous}
    ],
    "configuration": {{
      "resource": {{
        "tasks": [ {{ "id": "0", "name": "task0", "triggering": "Cyclic", "interval": "T#10ms", "priority": 1 }} ],
        "instances": [ {{ "id": "0", "name": "instance0", "task": "task0", "program": "main" }} ],
        "globalVariables": [
          {{ "name": "Limit", "class": "global", "type": {{ "definition": "base-type", "value": "int" }}, "location": "", "initialValue": "3" }}
        ]
      }}
    }}
  }}
}}
"#
    )
}

/// A variable entry as the editor writes it.
fn var(name: &str, class: &str, ty: &str, location: &str, init: &str) -> String {
    format!(
        r#"            {{ "id": "{name}", "name": "{name}", "class": "{class}",
              "type": {{ "definition": "{}", "value": "{ty}" }},
              "location": "{location}", "initialValue": "{init}", "documentation": "", "debug": false }}"#,
        if ty.chars().all(|c| c.is_ascii_lowercase()) {
            "base-type"
        } else {
            "derived"
        }
    )
}

/// A POU entry with an ST body (`body` is the JSON string's text, escapes included).
fn st_pou(kind: &str, name: &str, vars: &[String], body: &str) -> String {
    format!(
        r#"      {{
        "type": "{kind}",
        "data": {{
          "language": "st",
          "name": "{name}",
          "variables": [
{}
          ],
          "body": {{ "language": "st", "value": "{body}" }},
          "documentation": ""
        }}
      }}"#,
        vars.join(",\n")
    )
}

/// The two-POU ST project: `Count` counts the rising edges of its input up to the global
/// `Limit`; `main` calls it with `Pulse` and copies its outputs.
fn st_project() -> String {
    let fb = st_pou(
        "function-block",
        "Count",
        &[
            var("In", "input", "bool", "", ""),
            var("N", "output", "int", "", ""),
            var("Full", "output", "bool", "", ""),
            var("Edge", "local", "R_TRIG", "", ""),
        ],
        r#"\r\n(* counts \"edges\" *)\r\nEdge(CLK := In);\r\nIF Edge.Q AND N < Limit THEN\r\n  N := N + 1; // up\r\nEND_IF;\r\nFull := N >= Limit;\r\n"#,
    );
    let main = st_pou(
        "program",
        "main",
        &[
            var("Pulse", "local", "bool", "%IX0.0", "0"),
            var("Lamp", "local", "bool", "%QX0.0", ""),
            var("Total", "local", "int", "", ""),
            var("Name", "local", "string", "", "'ab'"),
            var("C", "local", "Count", "", ""),
        ],
        r#"C(In := Pulse);\nTotal := C.N;\nLamp := C.Full AND Name = 'a\u0062';\n"#,
    );
    project(&format!("{fb},\n{main}"))
}

/// An ST program and an ST function block inline run from the project folder and from
/// `project.json` given alone, with the configuration's task, instance and global: the block
/// counts three edges of Pulse, then Lamp lights. The bodies' JSON escapes (`\r\n`, `\"` in a
/// comment, `\u0062` in a string literal) read as their characters.
#[test]
fn inline_st_pous_run_from_the_folder_and_from_project_json() {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "proj/project.json", &st_project());
    let stimulus = "1,instance0.Pulse,TRUE\n2,instance0.Pulse,FALSE\n3,instance0.Pulse,TRUE\n\
                    4,instance0.Pulse,FALSE\n5,instance0.Pulse,TRUE\n6,instance0.Pulse,FALSE\n\
                    7,instance0.Pulse,TRUE\n";
    for input in ["proj", "proj/project.json"] {
        let (trace, stderr) = run_stimulated_files(
            &[dir.path().join(input)],
            &["--cycle-ms", "10"],
            9,
            stimulus,
            "instance0.Total,instance0.Lamp",
        );
        assert!(
            !stderr.contains("error[") && !stderr.contains("W0302"),
            "{stderr}"
        );
        assert_eq!(
            column(&trace, "instance0.Total"),
            [0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 3.0, 3.0],
            "{input}: {trace}"
        );
        assert_eq!(
            column(&trace, "instance0.Lamp"),
            [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
            "{input}: {trace}"
        );
    }
}

/// A Ladder POU inline (`"body": {"language": "ld", "value": {"name": "main", "rungs": [...]}}`,
/// the JSON of a `.ld` file) runs: Start sets Motor through a rising-edge contact and a set
/// coil, Stop resets it.
#[test]
fn an_inline_ladder_pou_runs() {
    let rail = |id: &str, v: &str, x: i32| {
        format!(
            r#"{{ "id": "{id}", "type": "powerRail", "position": {{ "x": {x}, "y": 30 }}, "data": {{ "variant": "{v}", "variable": {{ "name": "" }} }} }}"#
        )
    };
    let node = |id: &str, ty: &str, v: &str, name: &str, x: i32| {
        format!(
            r#"{{ "id": "{id}", "type": "{ty}", "position": {{ "x": {x}, "y": 38 }}, "data": {{ "variant": "{v}", "variable": {{ "name": "{name}" }} }} }}"#
        )
    };
    let edge =
        |a: &str, b: &str| format!(r#"{{ "id": "{a}-{b}", "source": "{a}", "target": "{b}" }}"#);
    let rung = |k: u32, contact: &str, cv: &str, coil: &str, kv: &str| {
        let (l, c, q, r) = (
            format!("L{k}"),
            format!("C{k}"),
            format!("Q{k}"),
            format!("R{k}"),
        );
        format!(
            "{{ \"id\": \"rung{k}\", \"comment\": \"\",\n  \"nodes\": [\n  {},\n  {},\n  {},\n  {} ],\n  \"edges\": [ {}, {}, {} ] }}",
            rail(&l, "left", 0),
            node(&c, "contact", cv, contact, 60),
            node(&q, "coil", kv, coil, 300),
            rail(&r, "right", 700),
            edge(&l, &c),
            edge(&c, &q),
            edge(&q, &r)
        )
    };
    let vars = [
        var("Start", "local", "bool", "%IX0.0", ""),
        var("Stop", "local", "bool", "%IX0.1", ""),
        var("Motor", "local", "bool", "%QX0.0", ""),
    ]
    .join(",\n");
    let pou = format!(
        r#"      {{
        "type": "program",
        "data": {{
          "language": "ld",
          "name": "main",
          "variables": [
{vars}
          ],
          "body": {{
            "language": "ld",
            "value": {{ "name": "main", "rungs": [
{},
{} ] }}
          }},
          "documentation": ""
        }}
      }}"#,
        rung(1, "Start", "risingEdge", "Motor", "set"),
        rung(2, "Stop", "default", "Motor", "reset")
    );
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "ld/project.json", &project(&pou));
    let (trace, stderr) = run_stimulated_files(
        &[dir.path().join("ld")],
        &["--cycle-ms", "10"],
        6,
        "1,instance0.Start,TRUE\n2,instance0.Start,FALSE\n4,instance0.Stop,TRUE\n5,instance0.Stop,FALSE\n",
        "instance0.Motor",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(
        column(&trace, "instance0.Motor"),
        [0.0, 1.0, 1.0, 1.0, 0.0, 0.0]
    );
}

/// An error of an inline ST body points at its place in `project.json` (the line of the body,
/// the column of the undeclared name in the JSON string), one error, exit 1; an FBD body is one
/// E1073 at the body, and nothing else of the file is reported.
#[test]
fn errors_of_inline_bodies_are_located_in_project_json() {
    let bad = st_pou(
        "program",
        "main",
        &[var("Lamp", "local", "bool", "%QX0.0", "")],
        r#"Lamp := TRUE;\nLamp := Missing;"#,
    );
    let text = project(&bad);
    let line = text.lines().position(|l| l.contains("Missing")).unwrap() + 1;
    let col = text.lines().nth(line - 1).unwrap().find("Missing").unwrap() + 1;
    let (code, lines) = check_text("project.json", &text);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(&format!("project.json:{line}:{col}: error[E1001]")),
        "{lines:?}"
    );
    let fbd = r#"      {
        "type": "program",
        "data": { "language": "fbd", "name": "main", "variables": [],
          "body": { "language": "fbd", "value": { "name": "main", "rung": { "nodes": [], "edges": [] } } },
          "documentation": "" }
      }"#;
    let text = project(fbd);
    let line = text.lines().position(|l| l.contains("\"rung\"")).unwrap() + 1;
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "fbd/project.json", &text);
    let (code, _, stderr) = in_dir(dir.path(), &["check", "fbd"]);
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(code, Some(1), "{stderr}");
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].starts_with(&format!("fbd/project.json:{line}:"))
            && errors[0].contains("error[E1073]"),
        "{stderr}"
    );
}

/// A `.json` input that is no OpenPLC Editor v4 project (a package.json, malformed JSON) is one
/// E1074 at its start or where the JSON breaks, exit 1 for `check` and `run`: it is never read as
/// ST. Neither is a JSON object given under another name (content detection).
#[test]
fn json_that_is_no_v4_project_is_one_located_error() {
    for (name, text, at) in [
        (
            "package.json",
            "{ \"name\": \"x\", \"version\": \"1.0.0\" }\n",
            "1:1",
        ),
        (
            "broken.json",
            "{\n  \"meta\": { \"type\": \"plc-project\" \n",
            "2:35",
        ),
        ("settings.txt", "{ \"lamp\": \"start\" }\n", "1:1"),
    ] {
        let (code, lines) = check_text(name, text);
        assert_eq!(code, Some(1), "{name}: {lines:?}");
        assert_eq!(lines.len(), 1, "{name}: {lines:?}");
        assert!(
            lines[0].starts_with(&format!("{name}:{at}: error[E1074]")),
            "{name}: {lines:?}"
        );
    }
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "package.json", "{ \"name\": \"x\" }");
    let (code, stdout, stderr) = in_dir(dir.path(), &["run", "package.json", "--cycles", "2"]);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(!stdout.contains("cycle,"), "{stdout}");
}
