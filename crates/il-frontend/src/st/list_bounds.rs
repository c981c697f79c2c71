//! Constants of a named global variable list in the bounds of `.st` text (CODESYS objects exported as
//! text): `ARRAY[1..GVL.nJoints]`, `STRING(GVL.N)`, `WSTRING[GVL.N]`, `UINT(0..GVL.N)`, and in the
//! constant expression of an initial value (`C2 : REAL := GVL.C1 / 2.0;`).
//!
//! Input: the file's text and tokens. Output: the text with each list qualifier (`GVL.`) inside an
//! ARRAY's bound brackets, a STRING's length, an integer subrange's bounds or an initial value with
//! an operator blanked, or `None` when there is none. The IEC
//! declaration grammar has no qualified names there; once blanked, the constant is looked up by its
//! name among the integer constants of the file and then of every file given with it (E0022 when
//! none declares it), as TwinCAT objects' bounds are. Invariant: positions unchanged (the qualifier
//! becomes blanks), so every span stays where the user wrote it. That E0022 names the constant as
//! written ([`name_qualifier`]; [`library_qualified_bound`] once the project is read, against the
//! file's own text), and a constant of a library's parameter list (`Lib.Params.n`) is E1032 naming
//! the library.

use super::file::word;
use super::lexer::{Tok, Token};

/// See the module documentation.
pub(super) fn unqualify_list_bounds(src: &str, toks: &[Token]) -> Option<String> {
    let mut blanks = Vec::new();
    let mut k = 0;
    while k + 1 < toks.len() {
        let w = word(src, &toks[k]);
        let opens = if w.eq_ignore_ascii_case("ARRAY") {
            toks[k + 1].tok == Tok::LBracket
        } else if w.eq_ignore_ascii_case("STRING") || w.eq_ignore_ascii_case("WSTRING") {
            matches!(toks[k + 1].tok, Tok::LBracket | Tok::LParen)
        } else {
            // a subrange's bounds: `UINT(0..GVL.N)`
            toks[k + 1].tok == Tok::LParen
                && crate::sema::Elementary::from_name(&w.to_ascii_uppercase())
                    .is_some_and(|e| e.is_integer())
        };
        if !opens {
            k += 1;
            continue;
        }
        // up to the matching bracket (or the end of the text)
        let mut depth = 0usize;
        let mut j = k + 1;
        while j < toks.len() {
            match toks[j].tok {
                Tok::LBracket | Tok::LParen => depth += 1,
                Tok::RBracket | Tok::RParen => {
                    depth -= 1;
                    if depth == 0 {
                        break;
                    }
                }
                Tok::Ident
                    if toks.get(j + 1).is_some_and(|t| t.tok == Tok::Dot)
                        && toks.get(j + 2).is_some_and(|t| t.tok == Tok::Ident) =>
                {
                    blanks.push(toks[j].range.start..toks[j + 1].range.end);
                    j += 1;
                }
                _ => {}
            }
            j += 1;
        }
        k = j + 1;
    }
    initial_value_qualifiers(src, toks, &mut blanks);
    if blanks.is_empty() {
        return None;
    }
    let mut bytes = src.as_bytes().to_vec();
    for r in blanks {
        // (an identifier and a dot: ASCII, so blanking keeps the text UTF-8)
        bytes[r].fill(b' ');
    }
    String::from_utf8(bytes).ok()
}

/// The list qualifiers of the initial values in `VAR` blocks that are constant expressions (an
/// operator `+ - * / MOD` and no `:=` or `[` inside: not a structure or array initializer):
/// `GVL.C1` in `C2 : REAL := GVL.C1 / 2.0;`. A lone `GVL.C1` stays (sema reads it as the list's
/// member), as does a longer path (`GVL.st.x`, `GVL.a[1]`: no constant).
fn initial_value_qualifiers(src: &str, toks: &[Token], blanks: &mut Vec<std::ops::Range<usize>>) {
    let is_kw = |t: &Token, w: &str| super::file::is_word(src, t, w);
    let mut in_vars = false;
    let mut k = 0;
    while k < toks.len() {
        let t = &toks[k];
        let w = word(src, t);
        if matches!(t.tok, Tok::Kw(_) | Tok::Ident)
            && (w.eq_ignore_ascii_case("VAR") || w.to_ascii_uppercase().starts_with("VAR_"))
            && !w.eq_ignore_ascii_case("VAR_CONFIG")
        {
            in_vars = true;
        } else if is_kw(t, "END_VAR") {
            in_vars = false;
        } else if in_vars && t.tok == Tok::Assign {
            let end = (k + 1..toks.len())
                .find(|&j| toks[j].tok == Tok::Semi || is_kw(&toks[j], "END_VAR"))
                .unwrap_or(toks.len());
            let value = &toks[k + 1..end];
            let expression = value.iter().any(|t| {
                matches!(t.tok, Tok::Plus | Tok::Minus | Tok::Star | Tok::Slash) || is_kw(t, "MOD")
            }) && !value
                .iter()
                .any(|t| matches!(t.tok, Tok::Assign | Tok::LBracket));
            if expression {
                for j in 0..value.len() {
                    let qualified = value[j].tok == Tok::Ident
                        && value.get(j + 1).is_some_and(|t| t.tok == Tok::Dot)
                        && value.get(j + 2).is_some_and(|t| t.tok == Tok::Ident)
                        && !value.get(j + 3).is_some_and(|t| {
                            matches!(t.tok, Tok::Dot | Tok::LBracket | Tok::LParen)
                        })
                        && (j == 0 || value[j - 1].tok != Tok::Dot);
                    if qualified {
                        blanks.push(value[j].range.start..value[j + 1].range.end);
                    }
                }
            }
            k = end;
            continue;
        }
        k += 1;
    }
}

/// E0022 `d` about a constant `X` (``constant expression `X - 1`: `X` names no constant with a
/// value in the files given``) whose list qualifier was blanked: the constant named as written in `src`
/// (`RobotLibParams.TOOL_MAX`), and the list that is not given.
pub(super) fn name_qualifier(d: &mut diagnostics::Diagnostic, src: &str) {
    let Some(span) = d.span else {
        return;
    };
    let Some(end) = ["` names no constant ", "` is not "]
        .iter()
        .find_map(|marker| d.message.find(marker))
    else {
        return;
    };
    let Some(open) = d.message[..end].rfind('`') else {
        return;
    };
    let name = d.message[open + 1..end].to_string();
    if name.contains(['.', '#']) {
        return;
    }
    let (lo, hi) = (span.start as usize, (span.end as usize).min(src.len()));
    let Some(region) = src.get(lo.saturating_sub(128)..hi) else {
        return;
    };
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let dotted = format!(".{name}");
    let found = region.match_indices(&dotted).find_map(|(k, _)| {
        let after = region[k + dotted.len()..].chars().next();
        if after.is_some_and(ident) {
            return None;
        }
        let start = region[..k].rfind(|c: char| !ident(c)).map_or(0, |i| i + 1);
        let list = &region[start..k];
        (!list.is_empty()).then(|| list.to_string())
    });
    let Some(list) = found else {
        return;
    };
    let qualified = format!("{list}.{name}");
    d.message = d.message.replacen(
        &format!("`{name}` names no constant with a value in the files given"),
        &format!("`{qualified}` names no constant with a value in the files given: no global variable list or library parameter list `{list}` given with the file declares `{name}`"),
        1,
    );
    if let Some(expr_open) = d.message.find("constant expression `") {
        let at = expr_open + "constant expression `".len();
        if d.message[at..].starts_with(name.as_str()) {
            d.message.insert_str(at, &format!("{list}."));
        }
    }
}

/// E0022 `d` about a bound's constant, read against the file's text as the user wrote it
/// (`original`: a TwinCAT object's list qualifiers are blanked before the text is parsed, so
/// `name_qualifier` could not see them): the list named as in `name_qualifier`, and a constant
/// qualified by a library's namespace and its parameter list
/// (`ARRAY[1..Tc3_XPlanarStandard.Params_XPlanar.moverCount]`, as TwinCAT names a library's
/// parameters) made the E1032 that the same qualifier gets in a type: the library is not in the
/// project, which is the cause, not the order of the declarations.
pub fn library_qualified_bound(d: &mut diagnostics::Diagnostic, original: &str) {
    if d.code != diagnostics::code::E0022 {
        return;
    }
    name_qualifier(d, original);
    let Some(span) = d.span else {
        return;
    };
    let b = original.as_bytes();
    let ident = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    // the names before the constant, each followed by a dot: `lib.list.` (nearest first)
    let mut names: Vec<std::ops::Range<usize>> = Vec::new();
    let (start, end) = (span.start as usize, span.end as usize);
    let mut at = start;
    while names.len() < 2
        && at >= 2
        && b.get(at - 1) == Some(&b'.')
        && b.get(at - 2).is_some_and(|c| ident(*c))
    {
        let dot = at - 1;
        let mut first = dot;
        while first > 0 && ident(b[first - 1]) {
            first -= 1;
        }
        names.push(first..dot);
        at = first;
    }
    let [list_at, lib_at] = names.as_slice() else {
        return;
    };
    let (Some(list), Some(lib), Some(name)) = (
        original.get(list_at.clone()),
        original.get(lib_at.clone()),
        original.get(start..end),
    ) else {
        return;
    };
    if lib.as_bytes().first().is_some_and(|c| c.is_ascii_digit()) {
        return;
    }
    let hint = format!(
        "`{list}.{name}` is a parameter of the library `{lib}`, whose POUs, types and parameter lists are not in the project: give its source project with --lib, or declare `{name}` in a global constant list of the project"
    );
    let mut e = diagnostics::Diagnostic::error(
        diagnostics::code::E1032,
        format!("`{lib}` in the bound `{lib}.{list}.{name}` is neither a global variable list nor a library ladderc provides"),
    )
    .at(crate::Span::new(span.file, lib_at.start, lib_at.end))
    .with_primary_label("library qualifier")
    .with_hint(hint);
    std::mem::swap(d, &mut e);
}
