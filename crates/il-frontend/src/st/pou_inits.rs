//! Initial values of a POU's own variables computed at run time (CODESYS, TwinCAT): a declaration
//! whose value calls a function or reads a variable declared before it
//! (`_position_random_3 : UDINT := MIN(250000, _number_trajectories / 25);` in Struckig's
//! `RandomTest`), which a declaration's constant expression cannot hold.
//!
//! Input: the text of a POU's declarations (between its name and its body). Output: the ranges of
//! `:= expr` that the declarations' parse leaves out, and the assignments `name := expr;` where they
//! are written in a text of the declarations' length, the rest blanked ([`pou_run_time_inits`]).
//! `super::file::compile_pending` runs them in declaration order, behind a flag, when each
//! instance is initialised (before its FB_init, a hidden `method_inits::INIT_PREFIX` method) and
//! when the POU first runs (an instance that initialisation does not reach); a FUNCTION at each
//! call; a derived block its bases' first ([`super::inherit`]).
//! Invariants: positions do not move; only single-name declarations of VAR, VAR_TEMP (and of
//! VAR_INPUT, VAR_OUTPUT outside a FUNCTION, whose inputs hold their arguments) outside CONSTANT
//! blocks are taken; a value that is a structure or array initialiser, holds a `^` or a `:=`,
//! reads variables only inside `ADR(..)`, `REF(..)`, `SIZEOF(..)`, or is a variable alone given to
//! a variable of a user type (an interface started with an instance) stays the declaration's.

use super::lexer::{lex, Tok, Token};
use super::method_inits::{blank, declarations};
use std::collections::HashSet;
use std::ops::Range;

/// One initial value computed at run time: the variable's name and its `:= expr`, in the text.
pub(super) type Computed = (Range<usize>, Range<usize>);

/// The functions whose arguments are no values read (an address, a size).
const NOT_READ: [&str; 3] = ["ADR", "REF", "SIZEOF"];

/// See the module documentation; `function`: the POU is a FUNCTION. The ranges are `(name, :=
/// expr)` in `text`. `None` when no declaration of `text[region]` has such a value.
pub(super) fn pou_run_time_inits(
    text: &str,
    region: Range<usize>,
    function: bool,
) -> Option<(Vec<Computed>, String)> {
    let decls = text.get(region.clone())?;
    let toks = lex(decls).0;
    let mut inits = blank(decls);
    let mut cut = Vec::new();
    // the variables declared before (upper-case, not constants)
    let mut variables: HashSet<String> = HashSet::new();
    for d in declarations(decls, &toks) {
        let names_end = d.assign.unwrap_or(d.end);
        if !d.constant {
            let colon = (d.start..names_end).find(|&j| toks[j].tok == Tok::Colon);
            for t in toks[d.start..colon.unwrap_or(d.start)]
                .iter()
                .filter(|t| t.tok == Tok::Ident)
            {
                variables.insert(decls[t.range.clone()].to_ascii_uppercase());
            }
        }
        let block_taken = matches!(d.block.as_str(), "VAR" | "VAR_TEMP")
            || (!function && matches!(d.block.as_str(), "VAR_INPUT" | "VAR_OUTPUT"));
        let Some(k) = d.assign else { continue };
        if !block_taken || d.constant || !d.single || toks[d.end].tok != Tok::Semi {
            continue;
        }
        let value = &toks[k + 1..d.end];
        let plain = value
            .first()
            .is_some_and(|t| !matches!(t.tok, Tok::LParen | Tok::LBracket))
            && !value
                .iter()
                .any(|t| matches!(t.tok, Tok::Caret | Tok::Assign));
        // a variable alone given to a variable of a user type (`iDrive : I_DriveBase :=
        // fbDriveNc;`, an interface started with an instance: `super::interface_vars`) stays
        // the declaration's
        let elementary = toks
            .get(d.start + 2)
            .and_then(|t| decls.get(t.range.clone()))
            .is_some_and(|ty| {
                crate::sema::Elementary::from_name(&ty.to_ascii_uppercase()).is_some()
            });
        let alone = value.len() == 1;
        if plain && (elementary || !alone) && run_time(decls, value, &variables) {
            let from = toks[k].range.start;
            let to = toks[d.end - 1].range.end;
            let name = toks[d.start].range.clone();
            cut.push((
                region.start + name.start..region.start + name.end,
                region.start + from..region.start + to,
            ));
            inits.replace_range(name.clone(), &decls[name]);
            let stmt = from..toks[d.end].range.end;
            inits.replace_range(stmt.clone(), &decls[stmt]);
        }
    }
    (!cut.is_empty()).then_some((cut, inits))
}

/// Whether `value` calls a function other than [`NOT_READ`]'s, or reads one of `variables`
/// outside their arguments.
fn run_time(decls: &str, value: &[Token], variables: &HashSet<String>) -> bool {
    let mut inside: Option<usize> = None;
    let mut depth = 0usize;
    for (j, t) in value.iter().enumerate() {
        match t.tok {
            Tok::LParen => depth += 1,
            Tok::RParen => {
                depth = depth.saturating_sub(1);
                if inside.is_some_and(|d| depth < d) {
                    inside = None;
                }
            }
            Tok::Ident if inside.is_none() => {
                let n = decls[t.range.clone()].to_ascii_uppercase();
                let called = value.get(j + 1).is_some_and(|n| n.tok == Tok::LParen);
                let field = j > 0 && value[j - 1].tok == Tok::Dot;
                if called && NOT_READ.contains(&n.as_str()) {
                    inside = Some(depth + 1);
                } else if called || (!field && variables.contains(&n)) {
                    return true;
                }
            }
            _ => {}
        }
    }
    false
}

/// W1433 at `at` (the first such initial value of a POU, `:= expr`), of the variable `name`.
pub(super) fn computed_warning(name: &str, at: crate::Span) -> diagnostics::Diagnostic {
    diagnostics::Diagnostic::warning(
        diagnostics::code::W1433,
        format!("the initial value of `{name}` is computed at run time: IEC 61131-3 takes a constant expression (the POU's other such initial values are not reported)"),
    )
    .at(at)
    .with_primary_label("calls a function or reads a variable")
    .with_hint("compiled as CODESYS and TwinCAT do: assigned in declaration order when the instance is initialised, before FB_init; for another IEC compiler assign it in the body")
}
