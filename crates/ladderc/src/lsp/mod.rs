//! `ladderc lsp`: a language server on standard input and output for `.il`, `.st` and PLCopen `.xml`.
//!
//! Input: LSP JSON-RPC messages (lsp-server does the framing). Output: responses and
//! `textDocument/publishDiagnostics` notifications.
//! Features: diagnostics on open and change (the whole `ladderc check` of the buffer, with its axes file and
//! the workspace's `templates/`), hover (a variable's type and declaration, an FB's interface, a PLCopen
//! block's inputs with types and defaults), go to definition, document symbols, completion (variables, FB
//! members after `inst.`, a PLCopen block's inputs in `CAL inst(`), shutdown and exit.
//! Invariants: synchronous (one message at a time: every answer reflects all changes before it); documents
//! are analysed when they change, not per request; nothing is written to disk.

pub mod analysis;
pub mod text;

use analysis::Analysis;
use lsp_server::{Connection, Message, Notification, Request, Response};
use lsp_types::notification::Notification as _;
use lsp_types::request::Request as _;
use lsp_types::{
    CompletionItem, CompletionItemKind, CompletionOptions, Diagnostic as LspDiagnostic,
    DiagnosticSeverity, DocumentSymbol, GotoDefinitionResponse, Hover, HoverContents,
    HoverProviderCapability, Location, MarkupContent, MarkupKind, NumberOrString, OneOf, Position,
    PublishDiagnosticsParams, Range, ServerCapabilities, SymbolKind, TextDocumentSyncCapability,
    TextDocumentSyncKind, Uri,
};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::str::FromStr;

/// The capabilities announced in `initialize`.
pub fn capabilities() -> ServerCapabilities {
    ServerCapabilities {
        text_document_sync: Some(TextDocumentSyncCapability::Kind(TextDocumentSyncKind::FULL)),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        definition_provider: Some(OneOf::Left(true)),
        document_symbol_provider: Some(OneOf::Left(true)),
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some(vec![".".into(), "(".into()]),
            ..Default::default()
        }),
        ..Default::default()
    }
}

/// Runs the server on standard input/output until `exit`. Returns the process exit code (0 after a
/// `shutdown`, 1 when the client went away or broke the protocol).
pub fn run() -> i32 {
    let (connection, io_threads) = Connection::stdio();
    let code = match serve(&connection) {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("ladderc lsp: {e}");
            1
        }
    };
    drop(connection);
    let _ = io_threads.join();
    code
}

/// The server on any connection (standard I/O, or `Connection::memory()` in tests and benchmarks).
pub fn serve(connection: &Connection) -> Result<(), String> {
    let caps = serde_json::to_value(capabilities()).map_err(|e| e.to_string())?;
    let params = connection.initialize(caps).map_err(|e| e.to_string())?;
    let root = workspace_root(&params);
    let mut server = Server {
        root,
        docs: HashMap::new(),
    };
    for msg in &connection.receiver {
        match msg {
            Message::Request(req) => {
                if connection
                    .handle_shutdown(&req)
                    .map_err(|e| e.to_string())?
                {
                    return Ok(());
                }
                let resp = server.request(req);
                connection
                    .sender
                    .send(Message::Response(resp))
                    .map_err(|e| e.to_string())?;
            }
            Message::Notification(n) => {
                if n.method == lsp_types::notification::Exit::METHOD {
                    return Err("exit without shutdown".into());
                }
                if let Some(publish) = server.notification(n) {
                    connection
                        .sender
                        .send(Message::Notification(publish))
                        .map_err(|e| e.to_string())?;
                }
            }
            Message::Response(_) => {}
        }
    }
    Err("the client closed the connection without shutdown".into())
}

fn workspace_root(params: &serde_json::Value) -> Option<PathBuf> {
    let folder = params
        .get("workspaceFolders")
        .and_then(|f| f.get(0))
        .and_then(|f| f.get("uri"))
        .or_else(|| params.get("rootUri"))
        .and_then(|u| u.as_str())?;
    text::uri_to_path(folder)
}

struct Server {
    root: Option<PathBuf>,
    docs: HashMap<String, Analysis>,
}

/// The LSP range of a byte range, through a line index of its text.
fn range_in(idx: &text::LineIndex, start: usize, end: usize) -> Range {
    let (l0, c0) = idx.position(start);
    let (l1, c1) = idx.position(end);
    Range::new(Position::new(l0, c0), Position::new(l1, c1))
}

fn uri_of(path: &Path) -> Option<Uri> {
    Uri::from_str(&text::path_to_uri(path)).ok()
}

impl Server {
    fn open(&mut self, uri: &str, content: String) -> Option<Notification> {
        let path = text::uri_to_path(uri)?;
        let a = analysis::analyze(&path, &content, self.root.as_deref());
        let idx = text::LineIndex::new(&a.text);
        let diags = a
            .diagnostics
            .iter()
            .map(|(span, d)| {
                let r = match span {
                    Some(s) => range_in(&idx, s.start as usize, s.end as usize),
                    None => Range::default(),
                };
                let mut message = d.message.clone();
                if let Some(h) = &d.hint {
                    message.push_str(&format!("\nhint: {h}"));
                }
                if span.is_none() {
                    if let Some(s) = d.span {
                        let _ = s;
                        message.push_str("\n(reported in another file of the project)");
                    }
                }
                LspDiagnostic {
                    range: r,
                    severity: Some(match d.severity {
                        diagnostics::Severity::Error => DiagnosticSeverity::ERROR,
                        diagnostics::Severity::Warning => DiagnosticSeverity::WARNING,
                        _ => DiagnosticSeverity::INFORMATION,
                    }),
                    code: Some(NumberOrString::String(d.code.0.to_string())),
                    source: Some("ladderc".into()),
                    message,
                    ..Default::default()
                }
            })
            .collect();
        self.docs.insert(uri.to_string(), a);
        let params = PublishDiagnosticsParams {
            uri: Uri::from_str(uri).ok()?,
            diagnostics: diags,
            version: None,
        };
        Some(Notification::new(
            lsp_types::notification::PublishDiagnostics::METHOD.into(),
            params,
        ))
    }

    fn notification(&mut self, n: Notification) -> Option<Notification> {
        use lsp_types::notification::{
            DidChangeTextDocument, DidCloseTextDocument, DidOpenTextDocument,
        };
        match n.method.as_str() {
            DidOpenTextDocument::METHOD => {
                let p: lsp_types::DidOpenTextDocumentParams =
                    serde_json::from_value(n.params).ok()?;
                self.open(p.text_document.uri.as_str(), p.text_document.text)
            }
            DidChangeTextDocument::METHOD => {
                let p: lsp_types::DidChangeTextDocumentParams =
                    serde_json::from_value(n.params).ok()?;
                // Full synchronisation: the last change holds the whole text.
                let text = p.content_changes.into_iter().last()?.text;
                self.open(p.text_document.uri.as_str(), text)
            }
            DidCloseTextDocument::METHOD => {
                let p: lsp_types::DidCloseTextDocumentParams =
                    serde_json::from_value(n.params).ok()?;
                self.docs.remove(p.text_document.uri.as_str());
                Some(Notification::new(
                    lsp_types::notification::PublishDiagnostics::METHOD.into(),
                    PublishDiagnosticsParams {
                        uri: p.text_document.uri,
                        diagnostics: Vec::new(),
                        version: None,
                    },
                ))
            }
            _ => None,
        }
    }

    /// The document and the byte offset of a text-document position.
    fn at(&self, p: &lsp_types::TextDocumentPositionParams) -> Option<(&Analysis, usize)> {
        let a = self.docs.get(p.text_document.uri.as_str())?;
        let off = text::offset(&a.text, p.position.line, p.position.character);
        Some((a, off))
    }

    fn request(&mut self, req: Request) -> Response {
        use lsp_types::request::{Completion, DocumentSymbolRequest, GotoDefinition, HoverRequest};
        let id = req.id.clone();
        let result = match req.method.as_str() {
            HoverRequest::METHOD => serde_json::from_value::<lsp_types::HoverParams>(req.params)
                .ok()
                .and_then(|p| {
                    let (a, off) = self.at(&p.text_document_position_params)?;
                    let md = a.hover(off)?;
                    Some(Hover {
                        contents: HoverContents::Markup(MarkupContent {
                            kind: MarkupKind::Markdown,
                            value: md,
                        }),
                        range: None,
                    })
                })
                .map(|h| serde_json::to_value(h).unwrap_or_default()),
            GotoDefinition::METHOD => {
                serde_json::from_value::<lsp_types::GotoDefinitionParams>(req.params)
                    .ok()
                    .and_then(|p| {
                        let (a, off) = self.at(&p.text_document_position_params)?;
                        let (path, span) = a.definition(off)?;
                        let idx = text::LineIndex::new(a.file_text(span));
                        let r = range_in(&idx, span.start as usize, span.end as usize);
                        Some(GotoDefinitionResponse::Scalar(Location::new(
                            uri_of(&path)?,
                            r,
                        )))
                    })
                    .map(|d| serde_json::to_value(d).unwrap_or_default())
            }
            DocumentSymbolRequest::METHOD => {
                serde_json::from_value::<lsp_types::DocumentSymbolParams>(req.params)
                    .ok()
                    .and_then(|p| {
                        let a = self.docs.get(p.text_document.uri.as_str())?;
                        Some(symbols(a))
                    })
                    .map(|s| serde_json::to_value(s).unwrap_or_default())
            }
            Completion::METHOD => serde_json::from_value::<lsp_types::CompletionParams>(req.params)
                .ok()
                .and_then(|p| {
                    let (a, off) = self.at(&p.text_document_position)?;
                    let items: Vec<CompletionItem> = a
                        .completion(off)
                        .into_iter()
                        .map(|(label, detail)| CompletionItem {
                            label,
                            detail: Some(detail),
                            kind: Some(CompletionItemKind::VARIABLE),
                            ..Default::default()
                        })
                        .collect();
                    Some(items)
                })
                .map(|i| serde_json::to_value(i).unwrap_or_default()),
            _ => {
                return Response::new_err(
                    id,
                    lsp_server::ErrorCode::MethodNotFound as i32,
                    format!("ladderc lsp does not handle {}", req.method),
                )
            }
        };
        Response::new_ok(id, result.unwrap_or(serde_json::Value::Null))
    }
}

#[allow(deprecated)] // DocumentSymbol::deprecated is a required field of the type
fn symbols(a: &Analysis) -> Vec<DocumentSymbol> {
    let idx = text::LineIndex::new(&a.text);
    a.symbols()
        .into_iter()
        .map(|(name, kind, span, vars)| {
            let r = range_in(&idx, span.start as usize, span.end as usize);
            let children = vars
                .into_iter()
                .filter(|v| Some(v.span.file) == Some(span.file))
                .map(|v| {
                    let vr = range_in(&idx, v.span.start as usize, v.span.end as usize);
                    DocumentSymbol {
                        name: v.name.clone(),
                        detail: Some(a.type_name(&v.ty)),
                        kind: SymbolKind::VARIABLE,
                        tags: None,
                        deprecated: None,
                        range: vr,
                        selection_range: vr,
                        children: None,
                    }
                })
                .collect();
            DocumentSymbol {
                name,
                detail: None,
                kind: match kind {
                    il_frontend::ast::PouKind::Program => SymbolKind::MODULE,
                    il_frontend::ast::PouKind::FunctionBlock => SymbolKind::CLASS,
                    il_frontend::ast::PouKind::Function => SymbolKind::FUNCTION,
                },
                tags: None,
                deprecated: None,
                range: r,
                selection_range: Range::new(r.start, r.start),
                children: Some(children),
            }
        })
        .collect()
}
