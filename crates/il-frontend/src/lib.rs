//! The IL front end: IEC 61131-3 instruction list source in, a typed syntax tree and diagnostics out.
//!
//! Stages: [`lexer`] (logos, one case-insensitive keyword table) -> [`layout`] (significant line ends,
//! repair of unclosed blocks) -> [`parser`] (lalrpop grammar with error recovery) -> [`ast`] -> `sema`
//! (symbols, types, current-result typing, labels). Every node carries a byte [`Span`].
//! [`mod@print`] writes a tree back as IL; [`testgen`] generates large valid programs for tests and benches.
//! [`st`] is the Structured Text front end: ST is parsed and lowered to this IL tree.
//!
//! Input: IL source text (a whole file with [`parse`] / [`parse_named`], or an instruction list alone at a
//! byte offset of its file with [`parse_body`]). Output: an [`ast::CompilationUnit`] (or a `Vec<IlStmt>`),
//! with every problem pushed to the caller's `Diagnostics`; [`sema::analyze`] then resolves the units of
//! one program into a [`sema::model::Model`].
//! Invariants: no input makes these functions panic (a problem is a diagnostic, and the tree read so far is
//! returned); every span points into the file given; the syntax tree holds no resolved information.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod actions;
pub mod ast;
pub mod const_eval;
pub mod il_sizeof;
pub mod layout;
pub mod lexer;
pub mod literal;
pub mod name_index;
pub mod parser;
pub mod print;
pub mod rename;
pub mod sema;
pub mod st;
pub mod testgen;
pub mod type_sizes;

pub use diagnostics::{FileId, Span};

use ast::{CompilationUnit, Ident, IlStmt, LibraryElement, Pou, PouKind, VarKind};
use diagnostics::{code, Diagnostic, Diagnostics, Severity};
use lexer::Tok;
use parser::Parsed;

/// The name of the implicit program that [`parse`] gives to instructions outside any POU.
pub const DEFAULT_IMPLICIT_PROGRAM: &str = "main";

/// Parses one IL source file. Instructions outside any POU become an implicit `PROGRAM main`
/// (warning W0001); use [`parse_named`] to name it after the file.
pub fn parse(file: FileId, src: &str, diags: &mut Diagnostics) -> CompilationUnit {
    parse_named(file, src, DEFAULT_IMPLICIT_PROGRAM, diags)
}

/// Parses one IL source file; instructions and non-global `VAR` blocks outside any POU (as in bare test
/// files) are collected, in order, into one implicit `PROGRAM implicit_name` placed where the first of
/// them appears, with warning W0001. Without instructions, such `VAR` blocks are global variables
/// (note W0018), and with a `VAR_INPUT`, `VAR_OUTPUT` or `VAR_IN_OUT` among them, error E1102.
pub fn parse_named(
    file: FileId,
    src: &str,
    implicit_name: &str,
    diags: &mut Diagnostics,
) -> CompilationUnit {
    let Some(Parsed::Unit(mut top)) = parser::run(file, src, 0, Tok::UnitStart, diags, Vec::new())
    else {
        return CompilationUnit::default();
    };
    // only `VAR` blocks outside the POUs, no instruction (a B&R Automation Studio `.var` file):
    // global variables (W0018), not an implicit program that runs nothing
    if let Some((at, vars, _)) = top.implicit.take_if(|(_, vars, body)| {
        body.is_empty()
            && vars
                .iter()
                .all(|b| b.kind == VarKind::Local && b.name.is_none())
    }) {
        let first = vars.first().map_or(Span::new(file, 0, 0), |b| b.span);
        diags.push(
            Diagnostic::new(
                code::W0018,
                Severity::Note,
                "a VAR block outside any POU: read as global variables",
            )
            .at(Span::new(file, first.start as usize, first.start as usize + 3))
            .with_hint("as B&R Automation Studio's `.var` files declare them; for another IEC compiler write VAR_GLOBAL"),
        );
        let globals = vars.into_iter().map(|mut b| {
            b.kind = VarKind::Global;
            LibraryElement::GlobalVars(b)
        });
        let at = at.min(top.items.len());
        top.items.splice(at..at, globals);
    }
    // a VAR_INPUT, VAR_OUTPUT or VAR_IN_OUT block outside any POU, and no instruction (an ST
    // file's interface written before its `PROGRAM` header): one error at the block, and every
    // block read as global variables so that the POU's uses of them report nothing more (round 33:
    // before, W0001 at the block, an empty implicit program, and an E1001 at each use)
    if let Some((at, vars, _)) = top.implicit.take_if(|(_, vars, body)| {
        body.is_empty()
            && vars.iter().all(|b| {
                b.name.is_none()
                    && matches!(
                        b.kind,
                        VarKind::Local | VarKind::Input | VarKind::Output | VarKind::InOut
                    )
            })
            && vars.iter().any(|b| b.kind != VarKind::Local)
    }) {
        let at = at.min(top.items.len());
        diags.push(interface_outside_pou(file, &vars, &top.items[at..]));
        let globals = vars.into_iter().map(|mut b| {
            b.kind = VarKind::Global;
            LibraryElement::GlobalVars(b)
        });
        top.items.splice(at..at, globals);
    }
    if let Some((at, vars, body)) = top.implicit.take() {
        let implicit_name = &implicit_program_name(implicit_name);
        let first = top.first_bare.unwrap_or(Span::new(file, 0, 0));
        diags.push(parser::implicit_program_warning(first, implicit_name));
        let end = Span::new(file, src.len(), src.len());
        let pou = Pou {
            class: false,
            kind: PouKind::Program,
            name: Ident::new(
                implicit_name,
                Span::new(file, first.start as usize, first.start as usize),
            ),
            return_type: None,
            var_blocks: vars,
            body,
            span: first.to(end),
        };
        top.items
            .insert(at.min(top.items.len()), LibraryElement::Pou(pou));
    }
    il_sizeof::fold_items(&mut top.items);
    CompilationUnit {
        items: top.items,
        ..CompilationUnit::default()
    }
}

/// E1102 at the first interface block (`VAR_INPUT`, `VAR_OUTPUT`, `VAR_IN_OUT`) of `vars`, blocks
/// written outside any POU; `after`: the items that follow them (the POU they belong to, first).
fn interface_outside_pou(
    file: FileId,
    vars: &[ast::VarBlock],
    after: &[LibraryElement],
) -> Diagnostic {
    let keyword = |k: VarKind| match k {
        VarKind::Output => "VAR_OUTPUT",
        VarKind::InOut => "VAR_IN_OUT",
        _ => "VAR_INPUT",
    };
    let block = vars.iter().find(|b| b.kind != VarKind::Local);
    let (keyword, span) = block.map_or(("VAR_INPUT", Span::new(file, 0, 0)), |b| {
        let k = keyword(b.kind);
        (
            k,
            Span::new(file, b.span.start as usize, b.span.start as usize + k.len()),
        )
    });
    let next = after.iter().find_map(|i| match i {
        LibraryElement::Pou(p) => Some(p),
        _ => None,
    });
    let hint = match next {
        Some(p) => format!(
            "move the block after the header `{} {}` (IEC 61131-3 ed. 3, 6.5.1: a POU declares its inputs, outputs and variables between its header and its body)",
            match p.kind {
                PouKind::Program => "PROGRAM",
                PouKind::FunctionBlock => "FUNCTION_BLOCK",
                PouKind::Function => "FUNCTION",
            },
            p.name.name
        ),
        None => "put the block in a POU, after its header (IEC 61131-3 ed. 3, 6.5.1: a POU declares its inputs, outputs and variables between its header and its body); for variables every POU shares write VAR_GLOBAL".to_string(),
    };
    Diagnostic::error(
        code::E1102,
        format!("a {keyword} block outside any POU: it belongs after a POU's header"),
    )
    .at(span)
    .with_primary_label("outside any POU")
    .with_hint(hint)
}

/// The ending of the POU name of a B&R program (named after its folder) whose folder is named like
/// a block or type of the project (a library's `FUNCTION_BLOCK Blink` and the program folder
/// `Logical/Blink/`, as B&R's brdkCert sample has them): Automation Studio never names a program
/// in IEC code, so its name does not enter the namespace of types and blocks; the POU is named
/// `Blink__BR_PROGRAM` and its instance, for tracing, `Blink` ([`program_watch_name`]).
pub const BR_PROGRAM_SUFFIX: &str = "__BR_PROGRAM";

/// The name program `pou` is traced under (`Blink` for `Blink__BR_PROGRAM`, see
/// [`BR_PROGRAM_SUFFIX`]): its own name otherwise.
pub fn program_watch_name(pou: &str) -> &str {
    pou.strip_suffix(BR_PROGRAM_SUFFIX)
        .filter(|n| !n.is_empty())
        .unwrap_or(pou)
}

/// A valid IEC identifier made from a file stem: other characters become `_`, a leading digit gets a `_`
/// prefix (`19_il-test` -> `_19_il_test`).
pub fn implicit_program_name(stem: &str) -> String {
    let mut name: String = stem
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    if name.is_empty() || name.starts_with(|c: char| c.is_ascii_digit()) {
        name.insert(0, '_');
    }
    name
}

/// Parses the `VAR ... END_VAR` blocks `src` holds (nothing else), with spans as if `src` started at
/// byte `base` of the file: Beremiz lets the ST body of a PLCopen XML POU begin with declaration
/// blocks, and matiec reads them as the POU's own.
pub fn parse_var_blocks(
    file: FileId,
    src: &str,
    base: usize,
    diags: &mut Diagnostics,
) -> Vec<ast::VarBlock> {
    const HEAD: &str = "PROGRAM _\n";
    let Some(start) = base.checked_sub(HEAD.len()) else {
        return Vec::new();
    };
    let text = format!("{HEAD}{src}\nEND_PROGRAM\n");
    // `REF_TO` / `POINTER TO` / `REFERENCE TO` (CODESYS vendor texts): see `st::refs`
    let (toks, _) = st::lexer::lex(&text);
    let (blanked, mut refs) = st::refs::RefTypes::blank_keywords_at(file, &text, &toks, start);
    let text = blanked.unwrap_or(text);
    let mut blocks: Vec<ast::VarBlock> =
        match parser::run(file, &text, start, Tok::UnitStart, diags, Vec::new()) {
            Some(Parsed::Unit(top)) => top
                .items
                .into_iter()
                .flat_map(|item| match item {
                    LibraryElement::Pou(p) => p.var_blocks,
                    _ => Vec::new(),
                })
                .collect(),
            _ => Vec::new(),
        };
    refs.apply_to_method(&mut blocks, None);
    refs.report_left(diags);
    blocks
}

/// Parses an instruction list alone (e.g. the text of a PLCopen XML `<IL>` element). `base_offset` is the
/// byte offset of `src` in the file `file`, so that spans point into that file.
pub fn parse_body(
    file: FileId,
    src: &str,
    base_offset: usize,
    diags: &mut Diagnostics,
) -> Vec<IlStmt> {
    parse_body_declared(file, src, base_offset, diags, &[])
}

/// [`parse_body`] of a body whose variables are declared outside its text (a PLCopen XML POU's
/// interface): a keyword among `declared` (`on`, `var`, `task` ...) reads as that variable's name, so
/// that the reserved name is one E1031 at its declaration, as in an `.il` file, not a syntax error at
/// every use.
pub fn parse_body_declared(
    file: FileId,
    src: &str,
    base_offset: usize,
    diags: &mut Diagnostics,
    declared: &[&str],
) -> Vec<IlStmt> {
    let declared = declared.iter().map(|d| d.to_ascii_uppercase()).collect();
    match parser::run(file, src, base_offset, Tok::BodyStart, diags, declared) {
        Some(Parsed::Body(mut body)) => {
            il_sizeof::fold(&mut body);
            body
        }
        _ => Vec::new(),
    }
}
