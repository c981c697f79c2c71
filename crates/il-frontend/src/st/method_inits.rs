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
//! `THIS^.pRoot`, fisothemes/TwinCat-Dynamic-Collections) or `THIS` are taken, and those of an
//! elementary or pointer type whose value is a (qualified) name (`pCopy : POINTER TO INT :=
//! pHead;`, the block's pointer: Tc3_UnitTest; a constant's name so assigned is the same value)
//! (a literal or an array/structure initialiser `[..]`, `(a := 1)` after a type stays a
//! declaration's).
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
/// assignments, fields without room) or `None`.
pub(super) fn split(decls: &str) -> Option<Split> {
    let toks = lex(decls).0;
    let word_at = |t: &super::lexer::Token| decls.get(t.range.clone()).unwrap_or("");
    let mut read = decls.to_string();
    let mut inits = blank(decls);
    let mut found = false;
    let mut once = Vec::new();
    let mut crowded = Vec::new();
    for d in declarations(decls, &toks) {
        let in_inst = d.block == "VAR_INST";
        let (Some(k), true) = (
            d.assign,
            matches!(d.block.as_str(), "VAR" | "VAR_TEMP") || in_inst,
        ) else {
            continue;
        };
        let (s, end) = (d.start, d.end);
        let single = d.single;
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
        // `(a := 1, b := THIS^.x, c := 2.5)`: several fields, some computed at run time
        if single
            && structured
            && !one_field
            && toks[end].tok == Tok::Semi
            && (is_run_time_value(value) || this)
        {
            let name = toks[s].range.clone();
            match several_fields(decls, value, name.clone(), &mut read, &mut inits) {
                Ok(stmt) => {
                    let semi = toks[end].range.clone();
                    inits.replace_range(semi.clone(), &decls[semi.clone()]);
                    if in_inst {
                        once.push(name.start..stmt.end.max(semi.end));
                    }
                    found = true;
                }
                Err(Some(field)) => {
                    // read without its initial value; one E1075 at the field
                    let from = toks[k].range.start;
                    let to = toks[end - 1].range.end;
                    read.replace_range(from..to, &blank(&decls[from..to]));
                    crowded.push(field);
                    found = true;
                }
                Err(None) => {}
            }
            continue;
        }
        // `pCopy : POINTER TO INT := pHead;`, `n : INT := nCount;`: a variable's value (of the
        // block, a global), read at each call as CODESYS initialises a method's locals; a name
        // given to a variable of a user type (an interface started with an instance) stays the
        // declaration's
        let ty = toks.get(s + 2).map(word_at).unwrap_or("");
        let pointer = ["POINTER", "REFERENCE"]
            .iter()
            .any(|w| ty.eq_ignore_ascii_case(w));
        let elementary = crate::sema::Elementary::from_name(&ty.to_ascii_uppercase()).is_some();
        let read_name = !d.constant
            && (pointer || elementary)
            && value.first().is_some_and(|t| t.tok == Tok::Ident)
            && value.iter().all(|t| matches!(t.tok, Tok::Ident | Tok::Dot))
            && !value.iter().any(|t| {
                t.tok == Tok::Ident
                    && ["NULL", "TRUE", "FALSE"]
                        .iter()
                        .any(|w| word_at(t).eq_ignore_ascii_case(w))
            });
        // an array initialiser (`[N(7)]`: `N` a constant repeat count, no call; `[F(1), 2]`)
        // stays the declaration's, as in a POU's VAR (`super::pou_inits`): ST has no array
        // value to assign
        let array = value.first().is_some_and(|t| t.tok == Tok::LBracket);
        if single
            && !array
            && (!structured || one_field)
            && (is_run_time_value(value) || this || read_name)
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
    }
    found.then_some((read, inits, once, crowded))
}

/// What [`split`] gives: the declarations to parse, the assignments, the ranges of the VAR_INST
/// ones, and the fields of structured initial values with no room for their assignment (E1075).
type Split = (String, String, Vec<Range<usize>>, Vec<Range<usize>>);

/// A structured initial value `value` (`(a := 1, b := THIS^.x, c := 2.5)`, its tokens from `(` to
/// `)`) of the variable whose name is at `name`: the fields computed at run time (a call, a `^`,
/// `THIS`) become assignments `name.b := THIS^.x;` in `inits`, in place (the name where it is
/// written for the first, then in the blank room just before each next one's separator), and are
/// blanked in `read`, which keeps the other fields as the declaration's constant initial value.
/// Returns the range of the assignments; `Err(None)`, both texts unchanged, when a field is not
/// `field := expr` or none is computed at run time; `Err(Some(field))` when there is no room for
/// the name before that field (two computed fields next to each other: `(a := THIS^.x, b :=
/// THIS^.y)`), which the caller reports (E1075).
fn several_fields(
    decls: &str,
    value: &[super::lexer::Token],
    name: Range<usize>,
    read: &mut String,
    inits: &mut String,
) -> Result<Range<usize>, Option<Range<usize>>> {
    let inner = value
        .get(1..value.len().checked_sub(1).ok_or(None)?)
        .ok_or(None)?;
    // the fields, each with the separator before it (`(` or `,`) and after it (`,` or `)`)
    let mut fields: Vec<(usize, usize, usize)> = Vec::new(); // (sep before, first tok, last tok)
    let mut depth = 0i32;
    let mut first = 1;
    for (j, t) in inner.iter().enumerate() {
        match t.tok {
            Tok::LParen | Tok::LBracket => depth += 1,
            Tok::RParen | Tok::RBracket => depth -= 1,
            Tok::Comma if depth == 0 => {
                fields.push((first - 1, first, j));
                first = j + 2;
            }
            _ => {}
        }
    }
    fields.push((first - 1, first, inner.len()));
    // (indexes into `value`: a field's tokens are value[first..=last], separators around them)
    let word_is_this = |t: &super::lexer::Token| {
        t.tok == Tok::Ident
            && decls
                .get(t.range.clone())
                .is_some_and(|w| w.eq_ignore_ascii_case("THIS"))
    };
    let mut run_time = Vec::new();
    for &(sep, a, b) in &fields {
        let toks = value.get(a..=b).ok_or(None)?;
        if toks.len() < 3 || toks[0].tok != Tok::Ident || toks[1].tok != Tok::Assign {
            return Err(None);
        }
        let rest = &toks[2..];
        // `n := SIZEOF(values)`: a constant the declaration's parse computes (`Ctx::address_element`)
        let size_of_name = matches!(
            rest,
            [f, open, arg, close] if f.tok == Tok::Ident
                && decls.get(f.range.clone()).is_some_and(|w| w.eq_ignore_ascii_case("SIZEOF"))
                && open.tok == Tok::LParen
                && arg.tok == Tok::Ident
                && close.tok == Tok::RParen
        );
        if !size_of_name && (is_run_time_value(rest) || rest.iter().any(word_is_this)) {
            run_time.push((sep, a, b));
        }
    }
    if run_time.is_empty() {
        return Err(None);
    }
    let mut new_read = read.clone();
    let mut new_inits = inits.clone();
    let label = &decls[name.clone()];
    let mut last_end = name.end;
    for (n, &(sep, a, b)) in run_time.iter().enumerate() {
        let sep_at = value[sep].range.start;
        if n == 0 {
            new_inits.replace_range(name.clone(), label);
        } else {
            // `name` in the blank room before the separator
            let field = value[a].range.start..value[b].range.end;
            let from = sep_at.checked_sub(label.len()).ok_or(Some(field.clone()))?;
            if from <= last_end {
                return Err(Some(field));
            }
            new_inits.replace_range(from..sep_at, label);
        }
        new_inits.replace_range(sep_at..sep_at + 1, ".");
        let field = value[a].range.start..value[b].range.end;
        new_inits.replace_range(field.clone(), &decls[field.clone()]);
        let after = value[b + 1].range.start;
        new_inits.replace_range(after..after + 1, ";");
        last_end = after + 1;
    }
    // the declaration keeps the other fields; none left: no initial value at all
    if run_time.len() == fields.len() {
        let from = value[0].range.start;
        let to = value[value.len() - 1].range.end;
        // (the `:=` before the value too)
        let assign = decls[..from].rfind(":=").ok_or(None)?;
        new_read.replace_range(assign..to, &blank(&decls[assign..to]));
    } else {
        for (n, &(sep, a, b)) in fields.iter().enumerate() {
            if !run_time.contains(&(sep, a, b)) {
                continue;
            }
            // the field and one comma: its own after it, or (the last) the one before it
            let (from, to) = if b + 1 < value.len() - 1 {
                (value[a].range.start, value[b + 1].range.end)
            } else if n > 0 {
                (value[sep].range.start, value[b].range.end)
            } else {
                (value[a].range.start, value[b].range.end)
            };
            new_read.replace_range(from..to, &blank(&decls[from..to]));
        }
    }
    *read = new_read;
    *inits = new_inits;
    Ok(name.start..last_end)
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

/// One declaration of a variable block (see [`declarations`]).
pub(super) struct Declaration {
    /// The block's keyword, upper-case (`VAR`, `VAR_INST`, `VAR_INPUT` ...).
    pub(super) block: String,
    /// The block is `CONSTANT`.
    pub(super) constant: bool,
    /// The declaration's first token.
    pub(super) start: usize,
    /// Its first `:=`, when it has one.
    pub(super) assign: Option<usize>,
    /// The token that ends it: its `;` (or the end of the text).
    pub(super) end: usize,
    /// It declares one name: `name : TYPE := expr ;`, a colon right after the name.
    pub(super) single: bool,
}

/// The declarations of the variable blocks of `decls` (tokens `toks`), in order: a declaration
/// ends at its `;`, or at the `;` after its `:=` (whose value may hold `:=`, `(a := 1)`).
pub(super) fn declarations(decls: &str, toks: &[super::lexer::Token]) -> Vec<Declaration> {
    let word = |k: usize| decls.get(toks[k].range.clone()).unwrap_or("");
    let mut out = Vec::new();
    let mut block: Option<(String, bool)> = None;
    let mut start = 0;
    let mut k = 0;
    while k < toks.len() {
        let w = word(k).to_ascii_uppercase();
        match toks[k].tok {
            Tok::Eof => break,
            _ if w == "END_VAR" => block = None,
            _ if super::file::is_var_keyword(&w) => {
                // the block's qualifiers (`VAR_INPUT CONSTANT`, `VAR RETAIN`): the first
                // declaration starts after them
                let mut constant = false;
                while k + 1 < toks.len()
                    && ["CONSTANT", "RETAIN", "NON_RETAIN", "PERSISTENT"]
                        .iter()
                        .any(|q| word(k + 1).eq_ignore_ascii_case(q))
                {
                    constant |= word(k + 1).eq_ignore_ascii_case("CONSTANT");
                    k += 1;
                }
                block = Some((w, constant));
                start = k + 1;
            }
            Tok::Semi | Tok::Assign => {
                if let Some((name, constant)) = &block {
                    let assign = (toks[k].tok == Tok::Assign).then_some(k);
                    let end = (k..toks.len())
                        .find(|&j| matches!(toks[j].tok, Tok::Semi | Tok::Eof))
                        .unwrap_or(toks.len() - 1);
                    let single = assign.is_some()
                        && k > start + 2
                        && toks[start].tok == Tok::Ident
                        && toks[start + 1].tok == Tok::Colon
                        && !toks[start + 2..k].iter().any(|t| t.tok == Tok::Assign);
                    out.push(Declaration {
                        block: name.clone(),
                        constant: *constant,
                        start,
                        assign,
                        end,
                        single,
                    });
                    k = end;
                    start = end + 1;
                }
            }
            _ => {}
        }
        k += 1;
    }
    out
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
    for r in inits.iter().flat_map(|(_, _, _, crowded)| crowded) {
        let at = crate::Span::new(file, decls.start + r.start, decls.start + r.end);
        diags.push(
            diagnostics::Diagnostic::error(
                diagnostics::code::E1075,
                "this field's initial value is computed next to another one: ladderc cannot place its assignment",
            )
            .at(at)
            .with_primary_label("computed at run time, right after another computed field")
            .with_hint("put a field with a constant value between the two, or assign this one in FB_init"),
        );
    }
    let (mut blocks, mut inst) = super::file::read_member_var_blocks(
        file,
        inits
            .as_ref()
            .map_or(decl_text, |(read, _, _, _)| read.as_str()),
        decls.start,
        diags,
    );
    let once: Vec<Range<usize>> = inits.as_ref().map_or(Vec::new(), |(_, _, o, _)| {
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
        Some((_, mut t, _, _)) if decls.end <= stmts.start => {
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
