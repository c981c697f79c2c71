//! Structured Text (IEC 61131-3 ST), compiled through the IL syntax tree.
//!
//! A `.st` file in Siemens SCL is one E0023 before any stage (`scl`), so is an IL file in Siemens STL
//! (`siemens_stl`); a ladder diagram drawn in text, read as IL or ST, is one E1091 (`text_ladder`).
//! Stages: [`lexer`] (logos, case-insensitive keywords, the IL literal decoders) -> [`parser`]
//! (recursive descent with IEC precedence and statement-level error recovery, codes E0100-E0139) ->
//! [`ast`] -> [`lower`] (IL instructions with deferred operators, VAR_TEMP temporaries typed by
//! [`types`], unique labels; codes E3100-E3119) -> the IL tree that IL sema and the C backend read.
//!
//! Input: ST text at a byte base in a file (a PLCopen `<ST>` body, an SFC action or transition).
//! Output: `Vec<IlStmt>` whose instructions carry the spans of the ST constructs they come from, and the
//! VAR_TEMP declarations the POU must get. Invariants: never panics on any input; one bad statement
//! gives one diagnostic and the next statements are still read; the lowering of several snippets into
//! one POU through one [`PouLowering`] gives unique labels and temporaries.

pub mod additional_blocks;
pub mod any_inputs;
pub mod ast;
pub mod base_view;
mod classes;
mod conditional;
mod conflict_markers;
pub mod dropped_results;
pub mod fb_init;
pub mod fb_init_args;
pub mod file;
pub mod generic_blocks;
mod generic_constants;
mod generic_headers;
mod hash_directives;
mod headless_body;
pub mod implicit_enums;
pub mod infer;
pub mod inherit;
pub(crate) mod init_fields;
pub mod interface_vars;
pub mod lexer;
mod list_bounds;
pub mod lone_members;
pub mod lower;
mod method_inits;
mod override_signature;
pub mod parser;
mod pou_inits;
pub mod property;
pub mod qualifiers;
pub mod refs;
mod scl;
pub mod sfc;
mod siemens_stl;
mod stray_text;
mod struct_extends;
mod text_ladder;
pub mod types;
mod using;
mod var_config;
mod var_inst;
pub mod var_stat;
pub mod varlen;

pub use conditional::ProjectDefines;
pub use lower::PouLowering;
pub use pou_inits::{global_variable_names, set_project_globals};
pub use qualifiers::{offered_names, with_other_files_names};
pub use types::{Declarations, PouInterface};

use crate::ast::{IlStmt, Pou, VarBlock, VarKind};
use crate::{FileId, Span};
use diagnostics::Diagnostics;

/// Whether `src` holds a ladder rung drawn in text (ASCII art), which reading it as IL or ST
/// reports as the one E1091 (`text_ladder`); callers that would give another diagnostic for the
/// whole file first let that one speak.
pub fn holds_text_ladder(src: &str) -> bool {
    text_ladder::text_ladder(FileId::default(), src).is_some()
}

/// Parses a statement list (a whole ST body, an SFC action). `base` is the byte offset of `src` in
/// `file`: every span points into that file. Syntax errors are reported; the statements that could be
/// read are returned.
pub fn parse_statements(
    file: FileId,
    src: &str,
    base: usize,
    diags: &mut Diagnostics,
) -> Vec<ast::Stmt> {
    parser::statements(file, src, base, diags)
}

/// [`parse_statements`] of a body or method of `pou`: in a function block that declares no variable
/// `THIS`, edition 3's `THIS.x` is read as `THIS^.x` (the parser's `statements_in`).
pub fn parse_statements_of(
    file: FileId,
    src: &str,
    base: usize,
    pou: &Pou,
    diags: &mut Diagnostics,
) -> Vec<ast::Stmt> {
    let this_declared = pou
        .var_blocks
        .iter()
        .flat_map(|b| b.vars.iter())
        .any(|v| v.name.is("THIS"));
    let this_dot = pou.kind == crate::ast::PouKind::FunctionBlock && !this_declared;
    parser::statements_in(file, src, base, this_dot, this_declared, diags)
}

/// Parses one expression (an SFC transition condition, `:= expr;` forms are not accepted here).
/// `None` (with a diagnostic) when the text is not an expression.
pub fn parse_expression(
    file: FileId,
    src: &str,
    base: usize,
    diags: &mut Diagnostics,
) -> Option<ast::Expr> {
    parser::expression(file, src, base, diags)
}

/// One call does it all for a POU whose body is ST text: parses `src` and lowers it for `pou`.
/// Returns the IL body and, when temporaries were needed, the `VAR_TEMP` block to push onto
/// `pou.var_blocks`. `span` is what the synthesised block points at (the body element).
pub fn compile_body(
    file: FileId,
    src: &str,
    base: usize,
    decls: &Declarations,
    pou: &Pou,
    span: Span,
    diags: &mut Diagnostics,
) -> (Vec<IlStmt>, Option<VarBlock>) {
    let (body, blocks, _) =
        compile_body_with_actions(file, src, base, decls, pou, (&[], &[]), &[], span, diags);
    (body, blocks.into_iter().find(|b| b.kind == VarKind::Temp))
}

/// [`compile_body`] of a POU that has actions with ST bodies (`(name, text, base)`, CODESYS
/// exports): a call statement `Act();` in the body (or in another action) is lowered as the
/// action's statements, in place. Each action is also lowered on its own (third result, with the
/// diagnostics of that lowering kept in it), for calls from other POUs (`inst.Act();`): see
/// [`crate::actions::link`]. `il_actions` are the POU's actions already lowered to IL (PLCopen XML
/// actions in IL, LD or FBD): a call statement `Act();` of one is a copy of its statements.
/// `chart_steps`: when the POU's body is a chart, its steps, which its actions read as
/// `Step.X`/`Step.T` (of [`sfc::STEP_TYPE`], which `decls` then declares; the caller renames them
/// to the chart's flags).
#[allow(clippy::too_many_arguments)]
pub fn compile_body_with_actions(
    file: FileId,
    src: &str,
    base: usize,
    decls: &Declarations,
    pou: &Pou,
    (actions, chart_steps): (&[(crate::ast::Ident, String, usize)], &[String]),
    il_actions: &[(crate::ast::Ident, Vec<IlStmt>)],
    span: Span,
    diags: &mut Diagnostics,
) -> (Vec<IlStmt>, Vec<VarBlock>, Vec<crate::ast::Action>) {
    let mut local = Diagnostics::new();
    let mut stmts = parse_statements_of(file, src, base, pou, &mut local);
    let mut low = PouLowering::new(decls, pou);
    for step in chart_steps {
        low.declare(
            step,
            crate::ast::TypeRef::Named(crate::ast::Ident::new(sfc::STEP_TYPE, pou.span)),
        );
    }
    let mut parsed: Vec<(crate::ast::Ident, Vec<ast::Stmt>)> = Vec::new();
    if !actions.is_empty() {
        parsed = actions
            .iter()
            .map(|(n, text, b)| {
                (
                    n.clone(),
                    parse_statements_of(n.span.file, text, *b, pou, &mut local),
                )
            })
            .collect();
        // `Advance;` (B&R Automation Studio calls an action so): the action's call, no W1431
        let names: std::collections::HashSet<String> =
            actions.iter().map(|(n, _, _)| n.key()).collect();
        let mut called = Vec::new();
        name_calls(&mut stmts, &names, &mut called);
        for (_, body) in parsed.iter_mut() {
            name_calls(body, &names, &mut called);
        }
        if !called.is_empty() {
            let kept: Vec<_> = local
                .into_vec()
                .into_iter()
                .filter(|d| {
                    !(d.code == diagnostics::code::W1431
                        && d.span.is_some_and(|s| called.contains(&s)))
                })
                .collect();
            local = Diagnostics::new();
            local.extend(kept);
        }
        low.set_actions(parsed.clone());
    }
    diags.extend(local);
    if !il_actions.is_empty() {
        low.set_il_actions(il_actions.to_vec());
    }
    let body = low.statements(&stmts, diags);
    let standalone = parsed
        .iter()
        .map(|(name, stmts)| {
            let mut local = Diagnostics::new();
            let body = low.statements(stmts, &mut local);
            crate::ast::Action {
                pou: pou.name.clone(),
                name: name.clone(),
                body,
                temps: None,
                method_inputs: None,
                method_outputs: Vec::new(),
                method_defaults: Vec::new(),
                diagnostics: local.into_vec(),
                access: None,
            }
        })
        .collect();
    let copies = low.take_literal_copies(span);
    (
        body,
        low.finish(span).into_iter().chain(copies).collect(),
        standalone,
    )
}

/// Makes each statement `Name;` that names one of the POU's actions (`names`, by key) a call
/// `Name();` of it (B&R Automation Studio calls actions so), in `stmts` and the statements nested
/// in them; the spans of those statements' names go to `called`.
fn name_calls(
    stmts: &mut [ast::Stmt],
    names: &std::collections::HashSet<String>,
    called: &mut Vec<Span>,
) {
    use ast::{PlaceBase, StmtKind};
    for s in stmts {
        match &mut s.kind {
            StmtKind::Named(p) if p.accessors.is_empty() => {
                if let PlaceBase::Name(n) = &p.base {
                    if names.contains(&n.key()) {
                        called.push(p.span);
                        s.kind = StmtKind::Call {
                            callee: p.clone(),
                            args: Vec::new(),
                        };
                    }
                }
            }
            StmtKind::If {
                branches,
                else_body,
            } => {
                for b in branches {
                    name_calls(&mut b.body, names, called);
                }
                if let Some(e) = else_body {
                    name_calls(e, names, called);
                }
            }
            StmtKind::Case {
                arms, else_body, ..
            } => {
                for a in arms {
                    name_calls(&mut a.body, names, called);
                }
                if let Some(e) = else_body {
                    name_calls(e, names, called);
                }
            }
            StmtKind::For { body, .. } | StmtKind::While { body, .. } => {
                name_calls(body, names, called)
            }
            StmtKind::Repeat { body, .. } => name_calls(body, names, called),
            _ => {}
        }
    }
}
