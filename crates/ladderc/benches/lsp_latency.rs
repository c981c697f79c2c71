//! `cargo bench -p ladderc --bench lsp_latency`: how long `ladderc lsp` takes to answer on a 10,000-line
//! IL file (issue #15: responses within 100 ms).
//!
//! Input: a generated program (`il_frontend::testgen::generate`, 10,000 body lines in 10 POUs) written to
//! a temporary folder. The server runs in process on `lsp_server::Connection::memory()`; the client
//! side sends real LSP messages. Output: the median and the worst of 9 rounds for: open (the whole check
//! to C, until publishDiagnostics), change, hover, go to definition, document symbols and completion.
//! Invariants: the file has no error; every answer is checked to be non-empty, so a fast wrong answer
//! does not count.
#![forbid(unsafe_code)]

use lsp_server::{Connection, Message, Notification, Request, RequestId};
use serde_json::{json, Value};
use std::time::{Duration, Instant};

fn recv_diagnostics(c: &Connection) -> Value {
    loop {
        match c.receiver.recv_timeout(Duration::from_secs(60)).unwrap() {
            Message::Notification(n) if n.method == "textDocument/publishDiagnostics" => {
                return n.params
            }
            _ => {}
        }
    }
}

fn request(c: &Connection, id: i32, method: &str, params: Value) -> Value {
    c.sender
        .send(Message::Request(Request::new(
            RequestId::from(id),
            method.into(),
            params,
        )))
        .unwrap();
    loop {
        if let Message::Response(r) = c.receiver.recv_timeout(Duration::from_secs(60)).unwrap() {
            if r.id == RequestId::from(id) {
                return r.response_result.unwrap_or(Value::Null);
            }
        }
    }
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let src = il_frontend::testgen::generate(1_000, 10);
    let lines = src.lines().count();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("big.il");
    std::fs::write(&path, &src).unwrap();
    let uri = ladderc::lsp::text::path_to_uri(&path);

    let (server, client) = Connection::memory();
    let t = std::thread::spawn(move || ladderc::lsp::serve(&server));
    request(&client, 0, "initialize", json!({"capabilities": {}}));
    client
        .sender
        .send(Message::Notification(Notification::new(
            "initialized".into(),
            json!({}),
        )))
        .unwrap();

    // A variable use near the end of the file: the last `LD x` of the last POU.
    let (line, col) = src
        .lines()
        .enumerate()
        .filter_map(|(i, l)| {
            l.trim_start()
                .strip_prefix("LD ")
                .map(|rest| (i, l.len() - rest.len()))
        })
        .filter(|(i, _)| *i + 20 < lines)
        .last()
        .expect("an LD instruction");
    let pos = json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": col}});

    let mut rows: Vec<(&str, Vec<f64>)> = [
        "open",
        "change",
        "hover",
        "definition",
        "symbols",
        "completion",
    ]
    .iter()
    .map(|n| (*n, Vec::new()))
    .collect();
    let mut id = 1;
    for round in 0..9 {
        let t0 = Instant::now();
        let method = if round == 0 {
            "textDocument/didOpen"
        } else {
            "textDocument/didChange"
        };
        let params = if round == 0 {
            json!({"textDocument": {"uri": uri, "languageId": "iec-il", "version": 1, "text": src}})
        } else {
            json!({"textDocument": {"uri": uri, "version": round + 1}, "contentChanges": [{"text": src}]})
        };
        client
            .sender
            .send(Message::Notification(Notification::new(
                method.into(),
                params,
            )))
            .unwrap();
        let d = recv_diagnostics(&client);
        let ms = t0.elapsed().as_secs_f64() * 1e3;
        assert_eq!(
            d["diagnostics"],
            json!([]),
            "the generated program has no error"
        );
        rows[if round == 0 { 0 } else { 1 }].1.push(ms);
        for (k, (method, params)) in [
            ("textDocument/hover", pos.clone()),
            ("textDocument/definition", pos.clone()),
            (
                "textDocument/documentSymbol",
                json!({"textDocument": {"uri": uri}}),
            ),
            ("textDocument/completion", pos.clone()),
        ]
        .into_iter()
        .enumerate()
        {
            let t0 = Instant::now();
            let r = request(&client, id, method, params);
            id += 1;
            rows[2 + k].1.push(t0.elapsed().as_secs_f64() * 1e3);
            assert!(!r.is_null() && r != json!([]), "{method} answered nothing");
        }
    }
    request(&client, id, "shutdown", Value::Null);
    client
        .sender
        .send(Message::Notification(Notification::new(
            "exit".into(),
            Value::Null,
        )))
        .unwrap();
    t.join().unwrap().unwrap();

    println!("ladderc lsp on a {lines}-line IL file (release build, in process), 9 rounds");
    println!("{:<12} {:>10} {:>10}", "request", "median ms", "worst ms");
    for (name, v) in rows {
        let worst = v.iter().cloned().fold(0.0, f64::max);
        println!("{name:<12} {:>10.2} {:>10.2}", median(v), worst);
    }
}
