//! OpenPLC Editor v4 project folders as inputs: `ladderc check|build|run DIR`, where `DIR` holds
//! the editor's `project.json` (`"meta": {"type": "plc-project"}`) and its POUs as text files under
//! `pous/` (`pous/programs/main.st`, `pous/function-blocks/Counter.st`, ...).
//!
//! Input: the command line's paths and the [`Session`] (its overlay, and the file system when
//! allowed). Output: the paths with each such folder replaced by its POU files, or by its
//! `project.json` when the POUs are inline there (`crate::openplc_v4_json`; a `project.json` given
//! alone without inline POUs stands for its folder) (sorted, at most
//! [`MAX_FILES`], at most [`MAX_DEPTH`] folders down; a `.ld` among them is read as when given
//! alone (`crate::openplc_v4_ld`), an `.fbd` JSON body is one E1073), and the configuration that `project.json` describes (its tasks,
//! program instances and global variables) written as Structured Text, one [`V4Config`] per folder.
//! Invariants: never panics; nothing from `project.json` reaches the text unless it is a name, a
//! duration, an integer, a direct address or a literal of a closed set of characters (anything
//! else is one E1074 naming the entry, and the entry is left out); data types declared in
//! `project.json` are not read (one W1440 names them); nothing is written.

use crate::pipeline::Session;
use diagnostics::{code, Diagnostic, Diagnostics, Severity};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// At most this many POU files are read from one project folder (a bound against hostile folders).
pub const MAX_FILES: usize = 10_000;

/// How many folders down `pous/` is searched.
pub const MAX_DEPTH: usize = 4;

/// The extensions of the POU files the editor writes (lower case).
const POU_EXTENSIONS: [&str; 5] = ["st", "il", "ld", "fbd", "sfc"];

/// The configuration of one v4 project folder, as Structured Text.
pub struct V4Config {
    /// The name it is shown under (`DIR/project.json [configuration]`).
    pub name: String,
    /// `VAR_GLOBAL ... END_VAR` and `CONFIGURATION ... END_CONFIGURATION`.
    pub text: String,
    /// The `project.json` it is read from.
    pub source: PathBuf,
}

/// Whether `dir` is an OpenPLC Editor v4 project folder: a `project.json` whose `meta.type` is
/// `plc-project` (or `plc-library`).
fn project_json(session: &Session, dir: &Path) -> Option<Value> {
    if !session.disk || !dir.is_dir() || dir.join("plc.xml").is_file() {
        return None;
    }
    let text = session.read_file(&dir.join("project.json")).ok()?;
    let v: Value = serde_json::from_str(&text).ok()?;
    let kind = v.get("meta")?.get("type")?.as_str()?;
    matches!(kind, "plc-project" | "plc-library").then_some(v)
}

/// Whether `p` is an OpenPLC Editor v4 project: its folder or its `project.json`.
pub(crate) fn is_project(session: &Session, p: &Path) -> bool {
    project_json(session, p).is_some() || json_file(session, p).is_some()
}

/// `paths` with each OpenPLC Editor v4 project folder replaced by its POU files; the folders'
/// configurations go to `configs`.
pub fn expand(
    session: &Session,
    paths: &[PathBuf],
    configs: &mut Vec<V4Config>,
    diags: &mut Diagnostics,
) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for p in paths {
        // a project.json given alone: its inline POUs, or (none inline) its folder's POU files
        let (dir, json) = match project_json(session, p) {
            Some(json) => (p.clone(), json),
            None => match json_file(session, p) {
                Some(json) if has_inline_pous(&json) => {
                    out.push(p.clone());
                    push_config(&json, p, configs, diags);
                    continue;
                }
                Some(json) => match p.parent() {
                    Some(dir) if has_pou_files(dir) => (dir.to_path_buf(), json),
                    _ => {
                        out.push(p.clone());
                        continue;
                    }
                },
                None => {
                    out.push(p.clone());
                    continue;
                }
            },
        };
        let p = &dir;
        let mut files = pou_files(&p.join("pous"));
        files.sort();
        // the editor's earlier projects keep their POUs in project.json (`data.pous[].data`)
        if files.is_empty() && has_inline_pous(&json) {
            let file = p.join("project.json");
            out.push(file.clone());
            push_config(&json, &file, configs, diags);
            continue;
        }
        if files.is_empty() {
            diags.push(
                Diagnostic::error(
                    code::E9001,
                    format!("{} is an OpenPLC Editor v4 project with no POU file under pous/", p.display()),
                )
                .with_hint("give the folder that holds project.json and pous/, or the POU files themselves"),
            );
            continue;
        }
        out.extend(files);
        push_config(&json, &p.join("project.json"), configs, diags);
    }
    out
}

/// The configuration of the project `json` (read from `file`) into `configs`.
fn push_config(json: &Value, file: &Path, configs: &mut Vec<V4Config>, diags: &mut Diagnostics) {
    let name = format!("{} [configuration]", file.display());
    if let Some(text) = configuration(json, file, diags) {
        configs.push(V4Config {
            name,
            text,
            source: file.to_path_buf(),
        });
    }
}

/// The project of a `.json` file `p` (from the overlay or the file system) that is an OpenPLC
/// Editor v4 `project.json`.
fn json_file(session: &Session, p: &Path) -> Option<Value> {
    if !p
        .extension()
        .is_some_and(|x| x.eq_ignore_ascii_case("json"))
    {
        return None;
    }
    let text = session.read_file(p).ok()?;
    let v: Value = serde_json::from_str(text.strip_prefix('\u{feff}').unwrap_or(&text)).ok()?;
    crate::openplc_v4_json::is_v4_project(&v).then_some(v)
}

/// Whether the project holds POUs in `data.pous`.
fn has_inline_pous(json: &Value) -> bool {
    json.get("data")
        .and_then(|d| d.get("pous"))
        .and_then(Value::as_array)
        .is_some_and(|a| !a.is_empty())
}

/// Whether the folder `dir` has POU files under `pous/`.
fn has_pou_files(dir: &Path) -> bool {
    !pou_files(&dir.join("pous")).is_empty()
}

/// The POU files under `dir` (at most [`MAX_DEPTH`] folders down, at most [`MAX_FILES`]), in name
/// order.
fn pou_files(dir: &Path) -> Vec<PathBuf> {
    crate::folder_walk::files_under(dir, MAX_DEPTH, MAX_FILES, |f| {
        f.extension()
            .and_then(|x| x.to_str())
            .is_some_and(|x| POU_EXTENSIONS.contains(&x.to_ascii_lowercase().as_str()))
    })
}

/// An IEC 61131-3 identifier.
pub(crate) fn is_name(s: &str) -> bool {
    let mut c = s.chars();
    c.next()
        .is_some_and(|f| f.is_ascii_alphabetic() || f == '_')
        && c.all(|x| x.is_ascii_alphanumeric() || x == '_')
}

/// A duration literal (`T#20ms`, `TIME#1s500ms`).
fn is_duration(s: &str) -> bool {
    let up = s.to_ascii_uppercase();
    let body = up
        .strip_prefix("T#")
        .or_else(|| up.strip_prefix("TIME#"))
        .unwrap_or("");
    !body.is_empty()
        && body
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.')
}

/// A direct address (`%IX0.0`, `%QW2`, `%MD10`).
pub(crate) fn is_address(s: &str) -> bool {
    let Some(rest) = s.strip_prefix('%') else {
        return false;
    };
    let mut c = rest.chars();
    matches!(c.next(), Some('I' | 'Q' | 'M' | 'i' | 'q' | 'm'))
        && c.clone().next().is_some()
        && c.all(|x| x.is_ascii_alphanumeric() || x == '.')
}

/// An initial value's text kept as it is: a number, a name, a typed literal, a duration or a
/// quoted string without quotes, comments or statement ends inside.
pub(crate) fn is_literal(s: &str) -> bool {
    let t = s.trim();
    if let Some(inner) = t.strip_prefix('\'').and_then(|x| x.strip_suffix('\'')) {
        return !inner.contains(['\'', '\n', '\r']) && inner.len() <= 254;
    }
    !t.is_empty()
        && t.len() <= 64
        && t.chars()
            .all(|c| c.is_ascii_alphanumeric() || "_#.+-:".contains(c))
        && !t.contains("(*")
}

/// The type of a global variable entry (`{"definition": "base-type", "value": "INT"}`, an
/// `array` with `data.baseType` and `data.dimensions`), as ST text.
pub(crate) fn type_text(ty: &Value) -> Option<String> {
    let value = ty.get("value").and_then(Value::as_str).unwrap_or("");
    match ty.get("definition").and_then(Value::as_str)? {
        "array" => {
            let data = ty.get("data")?;
            let base = data.get("baseType")?.get("value")?.as_str()?;
            let dims: Vec<String> = data
                .get("dimensions")?
                .as_array()?
                .iter()
                .map(|d| {
                    d.get("dimension")
                        .and_then(Value::as_str)
                        .or_else(|| d.as_str())
                        .map(str::to_string)
                })
                .collect::<Option<_>>()?;
            let dim_ok = |d: &str| {
                d.split_once("..").is_some_and(|(a, b)| {
                    [a.trim(), b.trim()].iter().all(|x| {
                        is_name(x)
                            || x.strip_prefix('-')
                                .unwrap_or(x)
                                .chars()
                                .all(|c| c.is_ascii_digit())
                                && !x.is_empty()
                    })
                })
            };
            (is_name(base) && !dims.is_empty() && dims.iter().all(|d| dim_ok(d)))
                .then(|| format!("ARRAY [{}] OF {base}", dims.join(", ")))
        }
        _ => is_name(value).then(|| value.to_string()),
    }
}

/// The configuration `project.json` (`file`) describes, as ST text; `None` when it describes no
/// program instance (the one PROGRAM of the files then runs, as for any ST file).
fn configuration(json: &Value, file: &Path, diags: &mut Diagnostics) -> Option<String> {
    let data = json.get("data")?;
    let shown = file.display().to_string();
    let empty = Vec::new();
    let list = |v: Option<&Value>| v.and_then(Value::as_array).unwrap_or(&empty).clone();
    let types = list(data.get("dataTypes"));
    if !types.is_empty() {
        let names: Vec<&str> = types
            .iter()
            .filter_map(|t| t.get("name").and_then(Value::as_str))
            .collect();
        diags.push(
            Diagnostic::new(
                code::W1440,
                Severity::Warning,
                format!(
                    "{shown}: the data types it declares are not read ({})",
                    names.join(", ")
                ),
            )
            .with_hint("export the project as PLCopen XML (build/<target>/src/plc.xml) or declare the types in a .st file (TYPE ... END_TYPE)"),
        );
    }
    let mut bad = |what: String| {
        diags.push(
            Diagnostic::error(code::E1074, format!("{shown}: {what} is not read"))
                .with_hint("OpenPLC Editor writes names, durations (T#20ms), addresses (%QX0.0) and literals there: correct the entry in the editor"),
        );
    };
    let resource = data.get("configuration")?.get("resource")?;
    let mut text = String::new();
    let globals = list(
        resource
            .get("globalVariables")
            .or(data.get("globalVariables")),
    );
    let mut decls = Vec::new();
    for g in &globals {
        let name = g.get("name").and_then(Value::as_str).unwrap_or("");
        let ty = g.get("type").and_then(type_text);
        let (true, Some(ty)) = (is_name(name), ty) else {
            bad(format!("global variable `{}`", name.escape_debug()));
            continue;
        };
        let mut d = name.to_string();
        match g.get("location").and_then(Value::as_str).map(str::trim) {
            Some("") | None => {}
            Some(a) if is_address(a) => d.push_str(&format!(" AT {a}")),
            Some(a) => {
                bad(format!("the location `{}` of `{name}`", a.escape_debug()));
                continue;
            }
        }
        d.push_str(&format!(" : {ty}"));
        let init = initial_value(g);
        match init.as_deref().map(str::trim) {
            Some("") | None => {}
            Some(v) if is_literal(v) => d.push_str(&format!(" := {v}")),
            Some(v) => {
                bad(format!(
                    "the initial value `{}` of `{name}`",
                    v.escape_debug()
                ));
                continue;
            }
        }
        decls.push(d);
    }
    if !decls.is_empty() {
        text.push_str("VAR_GLOBAL\n");
        for d in &decls {
            text.push_str(&format!("    {d};\n"));
        }
        text.push_str("END_VAR\n");
    }
    let mut tasks = Vec::new();
    for t in &list(resource.get("tasks")) {
        let name = t.get("name").and_then(Value::as_str).unwrap_or("");
        let interval = t.get("interval").and_then(Value::as_str).unwrap_or("");
        let priority = t.get("priority").and_then(Value::as_i64).unwrap_or(0);
        let cyclic = t
            .get("triggering")
            .and_then(Value::as_str)
            .is_none_or(|k| k.eq_ignore_ascii_case("cyclic"));
        if !is_name(name) || !is_duration(interval) || !cyclic || !(0..=1000).contains(&priority) {
            bad(format!("task `{}`", name.escape_debug()));
            continue;
        }
        tasks.push(format!(
            "        TASK {name}(INTERVAL := {interval}, PRIORITY := {priority});\n"
        ));
    }
    let mut instances = Vec::new();
    for i in &list(resource.get("instances")) {
        let name = i.get("name").and_then(Value::as_str).unwrap_or("");
        let program = i.get("program").and_then(Value::as_str).unwrap_or("");
        let task = i.get("task").and_then(Value::as_str).unwrap_or("");
        if !is_name(name) || !is_name(program) || !(task.is_empty() || is_name(task)) {
            bad(format!("program instance `{}`", name.escape_debug()));
            continue;
        }
        instances.push(if task.is_empty() {
            format!("        PROGRAM {name} : {program};\n")
        } else {
            format!("        PROGRAM {name} WITH {task} : {program};\n")
        });
    }
    if instances.is_empty() {
        return (!text.is_empty()).then_some(text);
    }
    text.push_str("CONFIGURATION Config0\n    RESOURCE Res0 ON PLC\n");
    for t in tasks {
        text.push_str(&t);
    }
    for i in instances {
        text.push_str(&i);
    }
    text.push_str("    END_RESOURCE\nEND_CONFIGURATION\n");
    Some(text)
}

/// A v4 variable's initial value as the editor writes it: a string, or `{"simpleValue": {"value": ...}}`.
pub(crate) fn initial_value(variable: &Value) -> Option<String> {
    let v = variable.get("initialValue")?;
    v.as_str().map(str::to_string).or_else(|| {
        v.get("simpleValue")?
            .get("value")?
            .as_str()
            .map(str::to_string)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_safe_text_reaches_the_configuration() {
        let json: Value = serde_json::from_str(
            r#"{"meta":{"name":"p","type":"plc-project"},"data":{"dataTypes":[],"pous":[],
            "configuration":{"resource":{
              "tasks":[{"name":"task0","triggering":"Cyclic","interval":"T#20ms","priority":1},
                       {"name":"bad","triggering":"Cyclic","interval":"T#1ms); x := 1; (","priority":1}],
              "instances":[{"name":"instance0","task":"task0","program":"main"},
                           {"name":"i1; END_RESOURCE","task":"task0","program":"main"}],
              "globalVariables":[
                {"name":"g","type":{"definition":"base-type","value":"INT"},"location":"%QW0","initialValue":"5"},
                {"name":"a","type":{"definition":"array","value":"","data":{"baseType":{"definition":"base-type","value":"BOOL"},"dimensions":[{"dimension":"0..3"}]}},"location":""},
                {"name":"evil","type":{"definition":"base-type","value":"INT"},"location":"","initialValue":"1; END_VAR"}]}}}}"#,
        )
        .unwrap();
        let mut diags = Diagnostics::new();
        let text = configuration(&json, Path::new("p/project.json"), &mut diags).unwrap();
        assert_eq!(
            text,
            "VAR_GLOBAL\n    g AT %QW0 : INT := 5;\n    a : ARRAY [0..3] OF BOOL;\nEND_VAR\n\
             CONFIGURATION Config0\n    RESOURCE Res0 ON PLC\n\
             \x20       TASK task0(INTERVAL := T#20ms, PRIORITY := 1);\n\
             \x20       PROGRAM instance0 WITH task0 : main;\n    END_RESOURCE\nEND_CONFIGURATION\n"
        );
        let errors: Vec<String> = diags.iter().map(|d| d.message.clone()).collect();
        assert_eq!(errors.len(), 3, "{errors:?}");
        assert!(
            errors[0].contains("initial value `1; END_VAR` of `evil`"),
            "{errors:?}"
        );
        assert!(errors[1].contains("task `bad`"), "{errors:?}");
        assert!(
            errors[2].contains("program instance `i1; END_RESOURCE`"),
            "{errors:?}"
        );
    }
}
