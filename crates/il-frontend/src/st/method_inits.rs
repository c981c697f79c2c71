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
//! `THIS^.pRoot`, fisothemes/TwinCat-Dynamic-Collections) are taken (a constant or
//! an array/structure initialiser `[..]`, `(a := 1)` after a type stays a declaration's).

use super::lexer::{lex, Tok};

/// See the module documentation: (declarations, assignments) or `None`.
pub(super) fn split(decls: &str) -> Option<(String, String)> {
    let toks = lex(decls).0;
    let word = |k: usize| decls.get(toks[k].range.clone()).unwrap_or("");
    let mut read = decls.to_string();
    let mut inits = blank(decls);
    let mut found = false;
    let mut in_local = false;
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
                in_local = w == "VAR" || w == "VAR_TEMP";
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
                if single && is_run_time_value(value) && toks[end].tok == Tok::Semi {
                    let from = toks[k].range.start;
                    let to = toks[end - 1].range.end;
                    // the declaration reads without `:= expr`
                    read.replace_range(from..to, &blank(&decls[from..to]));
                    // the assignment: the name, then `:= expr;` where they are
                    let name = toks[s].range.clone();
                    inits.replace_range(name.clone(), &decls[name]);
                    let stmt = from..toks[end].range.end;
                    inits.replace_range(stmt.clone(), &decls[stmt]);
                    found = true;
                }
                k = end;
                continue;
            }
            _ => {}
        }
        k += 1;
    }
    found.then_some((read, inits))
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
