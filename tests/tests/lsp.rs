//! `ladderc lsp` driven by a scripted editor-like client over real JSON-RPC on the binary's standard
//! input and output: open a file with an undeclared name (its diagnostic at the right line), hover a
//! variable (its type), go to definition (its declaration), document symbols, completion of FB members
//! and of a PLCopen block's inputs, fixing the text clears the diagnostic, shutdown and exit end it.

mod common;
mod lsp_client;

use lsp_client::Client;
use serde_json::{json, Value};

const BROKEN: &str = "PROGRAM main\nVAR\n    count : INT;\n    limit : INT := 10;\nEND_VAR\n    LD count\n    ADD 1\n    ST cuont\n    GT limit\nEND_PROGRAM\n";

#[test]
fn an_editor_session() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("counter.il");
    std::fs::write(&path, BROKEN).unwrap();
    let uri = format!("file://{}", path.display());
    let mut c = Client::start(dir.path());

    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": uri, "languageId": "iec-il", "version": 1, "text": BROKEN}}),
    );
    let d = c.diagnostics();
    assert_eq!(d["uri"], json!(uri));
    let list = d["diagnostics"].as_array().unwrap();
    assert_eq!(list.len(), 1, "{d}");
    assert_eq!(list[0]["range"]["start"]["line"], 7, "`ST cuont` is line 8");
    assert_eq!(list[0]["range"]["start"]["character"], 7);
    assert_eq!(list[0]["severity"], 1);
    assert!(list[0]["code"].as_str().unwrap().starts_with('E'), "{d}");
    assert!(
        list[0]["message"].as_str().unwrap().contains("cuont"),
        "{d}"
    );

    // Hover on `count` in `LD count` (line 6, column 8).
    let pos = json!({"textDocument": {"uri": uri}, "position": {"line": 5, "character": 8}});
    let h = c.request("textDocument/hover", pos.clone());
    let md = h["contents"]["value"].as_str().unwrap();
    assert!(md.contains("**count** : `INT`"), "{md}");
    assert!(
        md.contains("VAR of PROGRAM main") && md.contains("line 3"),
        "{md}"
    );

    // Go to definition lands on the declaration `count : INT;` (line 3).
    let def = c.request("textDocument/definition", pos);
    assert_eq!(def["uri"], json!(uri));
    assert_eq!(def["range"]["start"]["line"], 2, "{def}");
    assert_eq!(def["range"]["start"]["character"], 4, "{def}");

    // Document symbols: the program and its variables.
    let syms = c.request(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": uri}}),
    );
    assert_eq!(syms[0]["name"], "main");
    let vars: Vec<&str> = syms[0]["children"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v["name"].as_str().unwrap())
        .collect();
    assert_eq!(vars, ["count", "limit"]);

    // Fixing the text clears the diagnostic.
    let fixed = BROKEN.replace("cuont", "count");
    c.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": uri, "version": 2}, "contentChanges": [{"text": fixed}]}),
    );
    let d = c.diagnostics();
    assert_eq!(d["diagnostics"], json!([]), "{d}");

    // Shutdown and exit end the server with status 0.
    let r = c.request("shutdown", json!(null));
    assert_eq!(r, json!(null));
    c.notify("exit", json!(null));
    let status = c.child.wait().unwrap();
    assert!(status.success(), "{status:?}");
}

/// The labels of a completion answer.
fn labels_of(items: &Value) -> Vec<&str> {
    items
        .as_array()
        .unwrap()
        .iter()
        .map(|i| i["label"].as_str().unwrap())
        .collect()
}

const MOTION: &str = "PROGRAM main\nVAR\n    mv : MC_MoveAbsolute;\n    t : TON;\nEND_VAR\n    CAL mv(\n    LD mv.\nEND_PROGRAM\n";

#[test]
fn plcopen_block_inputs_in_hover_and_completion() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("m.il");
    std::fs::write(&path, MOTION).unwrap();
    let uri = format!("file://{}", path.display());
    let mut c = Client::start(dir.path());
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": uri, "languageId": "iec-il", "version": 1, "text": MOTION}}),
    );
    let _ = c.diagnostics(); // the unfinished lines are errors: the model still knows the declarations
                             // Hover on the declaration of `mv`: the block's inputs with their types and defaults.
    let h = c.request(
        "textDocument/hover",
        json!({"textDocument": {"uri": uri}, "position": {"line": 2, "character": 5}}),
    );
    let md = h["contents"]["value"].as_str().unwrap();
    assert!(md.contains("`MC_MoveAbsolute`"), "{md}");
    assert!(md.contains("`Position` : `LREAL` (input"), "{md}");
    assert!(md.contains("`Execute` : `BOOL` (input"), "{md}");
    // In `CAL mv(`: the block's inputs as formal arguments.
    let items = c.request(
        "textDocument/completion",
        json!({"textDocument": {"uri": uri}, "position": {"line": 5, "character": 11}}),
    );
    let labels = labels_of(&items);
    assert!(
        labels.contains(&"Position :=") && labels.contains(&"Execute :="),
        "{labels:?}"
    );
    assert!(
        !labels.iter().any(|l| l.starts_with("Done")),
        "outputs are not inputs: {labels:?}"
    );
    // After `mv.`: its inputs and outputs.
    let items = c.request(
        "textDocument/completion",
        json!({"textDocument": {"uri": uri}, "position": {"line": 6, "character": 10}}),
    );
    let labels = labels_of(&items);
    assert!(
        labels.contains(&"Done") && labels.contains(&"Position"),
        "{labels:?}"
    );
    // Elsewhere: the variables in scope.
    let items = c.request(
        "textDocument/completion",
        json!({"textDocument": {"uri": uri}, "position": {"line": 7, "character": 0}}),
    );
    let labels = labels_of(&items);
    assert!(
        labels.contains(&"mv") && labels.contains(&"t"),
        "{labels:?}"
    );
    let _ = c.request("shutdown", json!(null));
    c.notify("exit", json!(null));
    assert!(c.child.wait().unwrap().success());
}

#[test]
fn lone_cr_and_crlf_line_ends_are_lines_as_in_the_cli() {
    // LSP counts `\n`, `\r\n` and a lone `\r` as line ends; so do ladderc's diagnostics
    let text = "PROGRAM main\rVAR\r\n    count : INT;\r    limit : INT := 10;\nEND_VAR\r    LD count\r    ADD 1\r\n    ST cuont\r    GT limit\rEND_PROGRAM\r";
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cr.il");
    std::fs::write(&path, text).unwrap();
    let uri = format!("file://{}", path.display());
    let mut c = Client::start(dir.path());
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": uri, "languageId": "iec-il", "version": 1, "text": text}}),
    );
    let d = c.diagnostics();
    let list = d["diagnostics"].as_array().unwrap();
    assert_eq!(list.len(), 1, "{d}");
    assert_eq!(list[0]["range"]["start"]["line"], 7, "`ST cuont` is line 8");
    assert_eq!(list[0]["range"]["start"]["character"], 7);
    // the command line says the same, 1-based
    let out = common::ladderc()
        .args(["check", "--message-format", "short"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("cr.il:8:8: error["),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // hover and definition across the lone-CR lines
    let pos = json!({"textDocument": {"uri": uri}, "position": {"line": 5, "character": 8}});
    let h = c.request("textDocument/hover", pos.clone());
    let md = h["contents"]["value"].as_str().unwrap();
    assert!(md.contains("**count** : `INT`"), "{md}");
    let def = c.request("textDocument/definition", pos);
    assert_eq!(def["range"]["start"]["line"], 2, "{def}");
    assert_eq!(def["range"]["start"]["character"], 4, "{def}");
    let r = c.request("shutdown", json!(null));
    assert_eq!(r, json!(null));
    c.notify("exit", json!(null));
    assert!(c.child.wait().unwrap().success());
}
