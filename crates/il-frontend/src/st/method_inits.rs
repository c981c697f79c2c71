//! A method's local variable initialised by an expression that calls something (CODESYS, TwinCAT:
//! `blockSize : UDINT := SIZEOF(Block) * SINT_TO_UDINT(dofs);` in stefanbesler/struckig's
//! `Otg.FB_init`), which a declaration's constant expression cannot hold.
//!
//! A method's VAR and VAR_TEMP start from their initial values at each call (CODESYS "Method":
//! they are temporary), so such an initialisation is an assignment run first in the method, in
//! declaration order, where the method's inputs have their values.
//!
//! Input: the text of a method's declarations. Output: that text with each such `:= expr` blanked
//! (read by the IL declaration parser), and a text of the same length holding only the
//! assignments (`blockSize          := SIZEOF(Block) * SINT_TO_UDINT(dofs);`, the name and the
//! expression where they are written, everything else blanked). `None` when there is none.
//! Invariants: positions do not move (the assignments are parsed in place); only single-name
//! declarations of VAR / VAR_TEMP blocks whose initial value holds a call or a `^` (a pointer's
//! `THIS^.pRoot`, fisothemes/TwinCat-Dynamic-Collections) or `THIS` are taken (a constant or
//! an array/structure initialiser `[..]`, `(a := 1)` after a type stays a declaration's).
//!
//! A `VAR_INST` variable (TwinCAT: kept in the instance) is initialised once per instance, not at
//! each call: `pSelf : POINTER TO FB_X := THIS;`, `nSeed : INT := THIS^.nBase * 10;`,
//! `fbView : FB_View := (ipList := THIS^.fbList);` (one field). Its assignment is taken the same
//! way, its range returned apart, and [`run_once`] guards those assignments with a hidden flag
//! [`ONCE_FLAG`] (a VAR_INST of the method). They run when the instance is initialised, before its
//! FB_init, as TwinCAT's declaration initialisation does (a hidden method [`INIT_PREFIX`]`M` that
//! [`super::fb_init`] calls for every instance), and, for an instance that initialisation does not
//! reach, at the method's first call.

use super::lexer::{lex, Tok};
use std::ops::Range;

/// The hidden VAR_INST flag of a method whose VAR_INST initial values are computed at run time.
pub const ONCE_FLAG: &str = "__INST_INIT_DONE";

/// The prefix of the hidden method that computes a method's VAR_INST initial values when an
/// instance is initialised ([`super::file::lower_instance_init`], run by [`super::fb_init`]).
pub const INIT_PREFIX: &str = "__INSTINIT_";

/// See the module documentation: (declarations, assignments, ranges in the text of the VAR_INST
/// assignments) or `None`.
pub(super) fn split(decls: &str) -> Option<(String, String, Vec<Range<usize>>)> {
    let toks = lex(decls).0;
    let word = |k: usize| decls.get(toks[k].range.clone()).unwrap_or("");
    let word_at = |t: &super::lexer::Token| decls.get(t.range.clone()).unwrap_or("");
    let mut read = decls.to_string();
    let mut inits = blank(decls);
    let mut found = false;
    let mut once = Vec::new();
    let mut in_local = false;
    let mut in_inst = false;
    let mut start = None;
    let mut k = 0;
    while k < toks.len() {
        let w = word(k).to_ascii_uppercase();
        match toks[k].tok {
            Tok::Eof => break,
            _ if w == "END_VAR" => {
                in_local = false;
                start = None;
            }
            _ if super::file::is_var_keyword(&w) => {
                in_inst = w == "VAR_INST";
                in_local = w == "VAR" || w == "VAR_TEMP" || in_inst;
                start = Some(k + 1);
            }
            Tok::Semi => start = Some(k + 1),
            Tok::Assign if in_local => {
                let Some(s) = start else {
                    k += 1;
                    continue;
                };
                // `name : TYPE := expr ;`: one name, a colon right after it
                let single = k > s + 2
                    && toks[s].tok == Tok::Ident
                    && toks[s + 1].tok == Tok::Colon
                    && !toks[s + 2..k].iter().any(|t| t.tok == Tok::Assign);
                let end = (k..toks.len())
                    .find(|&j| matches!(toks[j].tok, Tok::Semi | Tok::Eof))
                    .unwrap_or(toks.len() - 1);
                // a call right after `:=` or inside the expression, not an initialiser after the
                // type (`(a := 1, b := 2)` of a structure starts at `:=` + 1 with `(` and holds `:=`)
                let value = &toks[k + 1..end];
                let this = value
                    .iter()
                    .any(|t| t.tok == Tok::Ident && word_at(t).eq_ignore_ascii_case("THIS"));
                let structured = value.first().is_some_and(|t| t.tok == Tok::LParen)
                    && value.iter().any(|t| t.tok == Tok::Assign);
                // `(field := expr)`: one field of a structure or an instance's input, assigned
                // as `name.field := expr;` (several fields are left to the declaration's parse)
                let one_field = structured
                    && value.len() > 4
                    && value[1].tok == Tok::Ident
                    && value[2].tok == Tok::Assign
                    && value.last().is_some_and(|t| t.tok == Tok::RParen)
                    && top_level_commas(&value[1..value.len() - 1]) == 0;
                if single
                    && (!structured || one_field)
                    && (is_run_time_value(value) || this)
                    && toks[end].tok == Tok::Semi
                {
                    let from = toks[k].range.start;
                    let to = toks[end - 1].range.end;
                    // the declaration reads without `:= expr`
                    read.replace_range(from..to, &blank(&decls[from..to]));
                    // the assignment: the name, then `:= expr;` where they are
                    let name = toks[s].range.clone();
                    inits.replace_range(name.clone(), &decls[name.clone()]);
                    let stmt = from..toks[end].range.end;
                    if one_field {
                        // `name   .field := expr ;`: the `(` read as the `.`, the `)` blanked
                        let open = value[0].range.clone();
                        inits.replace_range(open.start..open.start + 1, ".");
                        let inner = value[1].range.start..value[value.len() - 2].range.end;
                        inits.replace_range(inner.clone(), &decls[inner]);
                        let semi = toks[end].range.clone();
                        inits.replace_range(semi.clone(), &decls[semi]);
                    } else {
                        inits.replace_range(stmt.clone(), &decls[stmt.clone()]);
                    }
                    if in_inst {
                        once.push(name.start..stmt.end);
                    }
                    found = true;
                }
                k = end;
                continue;
            }
            _ => {}
        }
        k += 1;
    }
    found.then_some((read, inits, once))
}

/// The commas of `toks` outside parentheses and brackets.
fn top_level_commas(toks: &[super::lexer::Token]) -> usize {
    let mut depth = 0i32;
    let mut n = 0;
    for t in toks {
        match t.tok {
            Tok::LParen | Tok::LBracket => depth += 1,
            Tok::RParen | Tok::RBracket => depth -= 1,
            Tok::Comma if depth == 0 => n += 1,
            _ => {}
        }
    }
    n
}

/// Puts the statements that start in one of `once` (the VAR_INST initial assignments of a method,
/// see the module documentation) in `IF NOT __INST_INIT_DONE THEN ... __INST_INIT_DONE := TRUE;
/// END_IF`, where the first of them was.
pub(super) fn run_once(
    stmts: &mut Vec<super::ast::Stmt>,
    once: &[Range<usize>],
    span: crate::Span,
) {
    use super::ast::{CondBranch, Expr, ExprKind, Place, PlaceBase, Stmt, StmtKind, UnaryOp};
    use crate::ast::{Ident, LiteralKind};
    if once.is_empty() {
        return;
    }
    let starts_in = |s: &Stmt| once.iter().any(|r| r.contains(&(s.span.start as usize)));
    let Some(first) = stmts.iter().position(starts_in) else {
        return;
    };
    let mut body: Vec<Stmt> = Vec::new();
    let mut rest: Vec<Stmt> = Vec::new();
    for (k, s) in std::mem::take(stmts).into_iter().enumerate() {
        if k >= first && starts_in(&s) {
            body.push(s);
        } else {
            rest.push(s);
        }
    }
    let flag = || Place {
        base: PlaceBase::Name(Ident::new(ONCE_FLAG, span)),
        accessors: Vec::new(),
        span,
    };
    body.push(Stmt {
        kind: StmtKind::Assign {
            target: flag(),
            value: Expr::literal(LiteralKind::Bool(true), span),
        },
        span,
    });
    let guard = Stmt {
        kind: StmtKind::If {
            branches: vec![CondBranch {
                cond: Expr {
                    kind: ExprKind::Unary {
                        op: UnaryOp::Not,
                        operand: Box::new(Expr {
                            kind: ExprKind::Place(flag()),
                            span,
                        }),
                    },
                    span,
                },
                body,
                span,
            }],
            else_body: None,
        },
        span,
    };
    rest.insert(first, guard);
    *stmts = rest;
}

/// Whether an initial value's tokens compute at run time: a call (`SIZEOF(T) * k`), or a
/// dereference (`THIS^.pRoot`, `pX^.pRight` for a pointer; not `ADR(x)` alone, which a declaration
/// holds).
pub(super) fn is_run_time_value(value: &[super::lexer::Token]) -> bool {
    value
        .windows(2)
        .any(|p| p[0].tok == Tok::Ident && p[1].tok == Tok::LParen)
        || value.iter().any(|t| t.tok == Tok::Caret)
}

/// `text` with every character but line breaks replaced by a space (byte lengths kept: a
/// multi-byte character becomes as many spaces as it has bytes).
pub(super) fn blank(text: &str) -> String {
    text.bytes()
        .map(|b| {
            if b == b'\n' || b == b'\r' {
                b as char
            } else {
                ' '
            }
        })
        .collect()
}

/// A method's or property accessor's declarations and statements, read in place
/// ([`member_text`]).
pub(super) struct MemberText {
    /// Its variable blocks (VAR_INST read as VAR), the run-time initial values left out.
    pub blocks: Vec<crate::ast::VarBlock>,
    /// Its VAR_INST variables (upper-case), [`ONCE_FLAG`] among them when `once` is not empty.
    pub inst: Vec<String>,
    /// The run-time initial assignments where they are written, then the statements.
    pub text: String,
    /// Byte offset of `text` in the file.
    pub base: usize,
    /// The file ranges of the VAR_INST initial assignments ([`run_once`]).
    pub once: Vec<Range<usize>>,
}

/// Reads the declarations `decls` and statements `stmts` (byte ranges of `src`, the file's text) of a
/// method or accessor: the variable blocks without the initial values computed at run time, and the
/// text that assigns them (see the module documentation); the flag of `once` declared at `at`.
pub(super) fn member_text(
    file: crate::FileId,
    src: &str,
    decls: Range<usize>,
    stmts: Range<usize>,
    at: crate::Span,
    diags: &mut diagnostics::Diagnostics,
) -> MemberText {
    use crate::ast::{Ident, TypeRef, VarBlock, VarDecl};
    let decl_text = src.get(decls.clone()).unwrap_or("");
    let inits = split(decl_text);
    let (mut blocks, mut inst) = super::file::read_member_var_blocks(
        file,
        inits
            .as_ref()
            .map_or(decl_text, |(read, _, _)| read.as_str()),
        decls.start,
        diags,
    );
    let once: Vec<Range<usize>> = inits.as_ref().map_or(Vec::new(), |(_, _, o)| {
        o.iter()
            .map(|r| decls.start + r.start..decls.start + r.end)
            .collect()
    });
    if !once.is_empty() {
        // the flag that says the instance's initial values were computed (kept in the instance)
        blocks.push(VarBlock::locals(
            vec![VarDecl::new(
                Ident::new(ONCE_FLAG, at),
                TypeRef::Named(Ident::new("BOOL", at)),
                at,
            )],
            at,
        ));
        inst.push(ONCE_FLAG.to_ascii_uppercase());
    }
    let stmt_text = src.get(stmts.clone()).unwrap_or("");
    let (text, base) = match inits {
        // the assignments where they are written, then the statements (positions kept)
        Some((_, mut t, _)) if decls.end <= stmts.start => {
            t.push_str(&blank(src.get(decls.end..stmts.start).unwrap_or("")));
            t.push_str(stmt_text);
            (t, decls.start)
        }
        _ => (stmt_text.to_string(), stmts.start),
    };
    MemberText {
        blocks,
        inst,
        text,
        base,
        once,
    }
}
