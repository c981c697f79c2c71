//! Initial values of a POU's own variables computed at run time (CODESYS, TwinCAT): a declaration
//! whose value calls a function or reads a variable declared before it
//! (`_position_random_3 : UDINT := MIN(250000, _number_trajectories / 25);` in Struckig's
//! `RandomTest`), which a declaration's constant expression cannot hold.
//!
//! Input: the text of a POU's declarations (between its name and its body). Output: the ranges of
//! `:= expr` that the declarations' parse leaves out, and the assignments `name := expr;` where they
//! are written in a text of the declarations' length, the rest blanked ([`pou_run_time_inits`]).
//! `super::file::compile_pending` runs them in declaration order, behind a flag, when each
//! instance is initialised (before its FB_init, a hidden `method_inits::INIT_PREFIX` method; a
//! PROGRAM's instance before the first cycle and its stimulus, `super::fb_init`) and
//! when the POU first runs (an instance that initialisation does not reach); a FUNCTION at each
//! call; a derived block its bases' first ([`super::inherit`]).
//! A variable read is one of the POU declared before it, or a global variable (not CONSTANT) of
//! the project or of the file (`bFirst : BOOL := GVL.aCoils[0];`, `n : INT := gBase + 2;`: the
//! names [`set_project_globals`] makes known, found by [`global_variable_names`]); an address
//! whose index is computed (`p : POINTER TO WORD := ADR(regs[idx]);`) is computed too.
//! Invariants: positions do not move; only single-name declarations of VAR, VAR_TEMP (and of
//! VAR_INPUT, VAR_OUTPUT outside a FUNCTION, whose inputs hold their arguments) outside CONSTANT
//! blocks are taken; a value that is an array initialiser, holds a `^` or a `:=`, reads
//! variables only inside `ADR(..)`, `REF(..)` (a name, or literal indices), `SIZEOF(..)`, or is a
//! variable alone given to a variable of a user type (an interface started with an instance)
//! stays the declaration's. A structure initialiser's fields that are computed so, or are
//! `THIS^` (`fb : FB_X := (a := F(1), b := gCfg, c := 2, p := THIS^)`), become assignments
//! `a := F(1);` in place, which [`prefix_fields`] makes `fb.a := F(1);` once parsed; the other
//! fields stay the declaration's.
//! The global lists outside POUs are read the same way ([`global_run_time_inits`]): a global
//! (not CONSTANT) initialised from another global or by a call is assigned once before the first
//! cycle.

use super::lexer::{lex, Tok, Token};
use super::method_inits::{blank, declarations};
use std::collections::HashSet;
use std::ops::Range;

/// One initial value computed at run time: the variable's name and its `:= expr`, in the text.
pub(super) type Computed = (Range<usize>, Range<usize>);

/// The functions whose arguments are no values read (an address, a size).
const NOT_READ: [&str; 3] = ["ADR", "REF", "SIZEOF"];

thread_local! {
    /// The global variables (not CONSTANT) of the project's files, upper case, set by
    /// [`set_project_globals`] before any file is parsed.
    static PROJECT_GLOBALS: std::cell::RefCell<HashSet<String>> = Default::default();
}

/// Makes `names` (upper case, [`global_variable_names`] of every file of the project) the global
/// variables an initial value may read at run time; returns the names set before, to put back
/// when the project is read.
pub fn set_project_globals(names: HashSet<String>) -> HashSet<String> {
    PROJECT_GLOBALS.with(|g| g.replace(names))
}

/// The names declared in the `VAR_GLOBAL` blocks of `text` that are not CONSTANT (`VAR_GLOBAL
/// CONSTANT`, `VAR_GLOBAL RETAIN CONSTANT`), upper case: a scan of the raw text (an `.st` file or
/// a TwinCAT object's XML), before any file is parsed.
pub fn global_variable_names(text: &str) -> Vec<String> {
    if !text
        .as_bytes()
        .windows(10)
        .any(|w| w.eq_ignore_ascii_case(b"VAR_GLOBAL"))
    {
        return Vec::new();
    }
    let toks = lex(text).0;
    let word = |k: usize| text.get(toks[k].range.clone()).unwrap_or("");
    let mut out = Vec::new();
    for d in declarations(text, &toks) {
        if d.block != "VAR_GLOBAL" {
            continue;
        }
        // the block's qualifiers, after its keyword (`VAR_GLOBAL RETAIN CONSTANT`)
        let mut q = d.start;
        while q > 0
            && toks[q - 1].tok == Tok::Ident
            && !word(q - 1).eq_ignore_ascii_case("VAR_GLOBAL")
        {
            q -= 1;
        }
        let constant = d.constant || (q..d.start).any(|j| word(j).eq_ignore_ascii_case("CONSTANT"));
        if constant {
            continue;
        }
        out.extend(declared_names(text, &toks, &d).map(|n| n.to_ascii_uppercase()));
    }
    out
}

/// The names a declaration declares (before its `:`).
fn declared_names<'a>(
    decls: &'a str,
    toks: &'a [Token],
    d: &super::method_inits::Declaration,
) -> impl Iterator<Item = &'a str> + 'a {
    let names_end = d.assign.unwrap_or(d.end);
    let colon = (d.start..names_end).find(|&j| toks[j].tok == Tok::Colon);
    let mut at = false;
    toks[d.start..colon.unwrap_or(d.start)]
        .iter()
        .filter(move |t| {
            // `x AT %IX0.0 : BOOL`
            let w = decls.get(t.range.clone()).unwrap_or("");
            at |= w.eq_ignore_ascii_case("AT");
            t.tok == Tok::Ident && !at
        })
        .map(|t| decls.get(t.range.clone()).unwrap_or(""))
}

/// See the module documentation; `function`: the POU is a FUNCTION; `file_globals`: the global
/// variables of the POU's file ([`global_variable_names`]). The ranges are `(name, := expr)` in
/// `text`. `None` when no declaration of `text[region]` has such a value.
pub(super) fn pou_run_time_inits(
    text: &str,
    region: Range<usize>,
    function: bool,
    file_globals: &HashSet<String>,
) -> Option<Found> {
    run_time_inits(text, region, function, false, file_globals)
}

/// What [`pou_run_time_inits`] and [`global_run_time_inits`] find: the ranges (name, what is left
/// out of the declaration), the assignments (a text of the region's length), and the assignments
/// of structured values' fields with their instance ([`prefix_fields`]).
pub(super) struct Found {
    /// The ranges (the variable's name, what is left out of its declaration).
    pub cut: Vec<Computed>,
    /// The assignments, where they are written (a text of the region's length).
    pub inits: String,
    /// The assignments of structured values' fields, with their variable and path
    /// ([`super::init_fields::prefix_fields`]).
    pub prefixed: Vec<(Range<usize>, super::init_fields::InitTarget)>,
    /// The elements whose computed fields have no place (E1069, [`unplaceable_error`]): the
    /// variable's name, the element.
    pub unplaceable: Vec<Computed>,
}

/// The run-time initial values of the global lists (`VAR_GLOBAL`, not CONSTANT) in
/// `text[region]`, a text outside any POU: a global initialised from another global
/// (`rAlpha : REAL := GVL.Pi;`) or by a call (`n : UDINT := TO_UDINT(LIMIT(1, a[2], 16));`), as
/// CODESYS and TwinCAT allow. They run once, in the order of the text (the files in the order
/// given), before the first cycle ([`super::fb_init::PROGRAM`]); until its assignment runs, a
/// global so initialised holds its type's default value.
pub(super) fn global_run_time_inits(
    text: &str,
    region: Range<usize>,
    file_globals: &HashSet<String>,
) -> Option<Found> {
    run_time_inits(text, region, false, true, file_globals)
}

fn run_time_inits(
    text: &str,
    region: Range<usize>,
    function: bool,
    global_lists: bool,
    file_globals: &HashSet<String>,
) -> Option<Found> {
    let decls = text.get(region.clone())?;
    let toks = lex(decls).0;
    let mut inits = blank(decls);
    let mut cut = Vec::new();
    let mut prefixed = Vec::new();
    let mut unplaceable = Vec::new();
    let all = declarations(decls, &toks);
    // the variables declared before (upper-case, not constants), then the globals that no
    // constant of the POU hides
    let mut variables: HashSet<String> = HashSet::new();
    let constants: HashSet<String> = all
        .iter()
        .filter(|d| d.constant)
        .flat_map(|d| declared_names(decls, &toks, d).map(|n| n.to_ascii_uppercase()))
        .collect();
    let globals: HashSet<String> = PROJECT_GLOBALS.with(|g| {
        g.borrow()
            .iter()
            .chain(file_globals)
            .filter(|n| !constants.contains(*n))
            .cloned()
            .collect()
    });
    for d in all {
        if !d.constant {
            for n in declared_names(decls, &toks, &d) {
                variables.insert(n.to_ascii_uppercase());
            }
        }
        let block_taken = if global_lists {
            // (not CONSTANT: `VAR_GLOBAL RETAIN CONSTANT` too)
            d.block == "VAR_GLOBAL"
                && declared_names(decls, &toks, &d)
                    .all(|n| globals.contains(&n.to_ascii_uppercase()))
        } else {
            matches!(d.block.as_str(), "VAR" | "VAR_TEMP")
                || (!function && matches!(d.block.as_str(), "VAR_INPUT" | "VAR_OUTPUT"))
        };
        // `VAR_INPUT CONSTANT` (CODESYS, TwinCAT: an instance's "parameter", an input set where
        // the instance is declared, CODESYS online help "Command: Edit Parameters"): an input
        let parameter = !global_lists && !function && d.block == "VAR_INPUT";
        let Some(k) = d.assign else { continue };
        if !block_taken || (d.constant && !parameter) || !d.single || toks[d.end].tok != Tok::Semi {
            continue;
        }
        let value = &toks[k + 1..d.end];
        // `fb : FB_X := (a := F(1, 2), b := gCfg, c := 5);`, also nested (`w : FB_W := (View :=
        // (iParent := THIS^));`, `a : ARRAY[0..1] OF ST_R := [(d := F(1)), (d := 2)];`): the
        // fields computed at run time become assignments `fb.a := F(1, 2);`, the others stay the
        // declaration's ([`super::init_fields`])
        let computed = |t: &[Token]| run_time(decls, t, &variables, &globals);
        if let Some(fields) = super::init_fields::computed_fields(decls, value, &computed) {
            let name = toks[d.start].range.clone();
            let label = &decls[name.clone()];
            let whole =
                region.start + toks[k].range.start..region.start + toks[d.end - 1].range.end;
            let var = (region.start + name.start)..(region.start + name.end);
            if !fields.unplaceable.is_empty() {
                // nothing assigned, the value left out: one E1069 at each element
                for &(a, b) in &fields.unplaceable {
                    unplaceable.push((
                        var.clone(),
                        region.start + value[a].range.start..region.start + value[b].range.end,
                    ));
                }
                cut.push((var.clone(), whole));
                continue;
            }
            if fields.all_computed() {
                cut.push((var.clone(), whole));
            } else {
                for r in fields.cuts(value) {
                    cut.push((var.clone(), region.start + r.start..region.start + r.end));
                }
            }
            for f in fields.computed() {
                let field = value[f.first].range.start..value[f.last].range.end;
                let after = value[f.last + 1].range.clone();
                inits.replace_range(field.clone(), &decls[field.clone()]);
                inits.replace_range(after.start..after.start + 1, ";");
                prefixed.push((
                    region.start + field.start..region.start + after.end,
                    (label.to_string(), var.clone(), f.path.clone()),
                ));
            }
            continue;
        }
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
        if plain && (elementary || !alone) && run_time(decls, value, &variables, &globals) {
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
    (!cut.is_empty()).then_some(Found {
        cut,
        inits,
        prefixed,
        unplaceable,
    })
}

/// Whether `value` calls a function other than [`NOT_READ`]'s, or reads one of `variables` or
/// of `globals` (also qualified, `GVL.x`) outside their arguments, or indexes with a name inside
/// `ADR(..)` / `REF(..)` (`ADR(regs[idx])`: an address computed at run time).
fn run_time(
    decls: &str,
    value: &[Token],
    variables: &HashSet<String>,
    globals: &HashSet<String>,
) -> bool {
    // (the depth of the parentheses of a NOT_READ call, whether it takes an address)
    let mut inside: Option<(usize, bool)> = None;
    let mut depth = 0usize;
    let mut brackets = 0usize;
    for (j, t) in value.iter().enumerate() {
        match t.tok {
            Tok::LParen => depth += 1,
            Tok::RParen => {
                depth = depth.saturating_sub(1);
                if inside.is_some_and(|(d, _)| depth < d) {
                    inside = None;
                }
            }
            Tok::LBracket => brackets += 1,
            Tok::RBracket => brackets = brackets.saturating_sub(1),
            Tok::Ident => {
                let n = decls[t.range.clone()].to_ascii_uppercase();
                let called = value.get(j + 1).is_some_and(|n| n.tok == Tok::LParen);
                let field = j > 0 && value[j - 1].tok == Tok::Dot;
                match inside {
                    // `ADR(regs[idx])`, `ADR(regs[N])`: the index is read
                    Some((_, true)) if brackets > 0 => return true,
                    Some(_) => {}
                    None if called && NOT_READ.contains(&n.as_str()) => {
                        inside = Some((depth + 1, n != "SIZEOF"));
                    }
                    None if called
                        || (!field && variables.contains(&n))
                        || globals.contains(&n) =>
                    {
                        return true
                    }
                    None => {}
                }
            }
            _ => {}
        }
    }
    false
}

/// E1069 at `at` (an element of an array initial value, `[.., here, ..]`) of the variable `name`:
/// a field computed at run time in an element whose index ladderc cannot know.
pub(super) fn unplaceable_error(name: &str, at: crate::Span) -> diagnostics::Diagnostic {
    diagnostics::Diagnostic::error(
        diagnostics::code::E1069,
        format!("the initial value of `{name}` computes a field in a repeated array element, or after a repetition counted by a name: ladderc cannot place its assignment"),
    )
    .at(at)
    .with_primary_label("a computed field in this element")
    .with_hint("write the elements one by one with literal repetition counts before it, or assign the field in the body or in FB_init")
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

/// W1433 at `at` (the first such initial value of a file's global lists, `:= expr`), of the
/// global variable `name`.
pub(super) fn computed_global_warning(name: &str, at: crate::Span) -> diagnostics::Diagnostic {
    diagnostics::Diagnostic::warning(
        diagnostics::code::W1433,
        format!("the initial value of the global `{name}` is computed at run time: IEC 61131-3 takes a constant expression (the file's other such initial values are not reported)"),
    )
    .at(at)
    .with_primary_label("calls a function or reads a variable")
    .with_hint("compiled as CODESYS and TwinCAT do: assigned once before the first cycle, in the order of the text; a global read before its own assignment holds its type's default; for another IEC compiler assign it in a program")
}

/// The run-time initial values of the POU declared in `src[declarations]` (file `file`), for its
/// `PendingBody::var_inits`, whatever the language of its body (ST, or a chart: round 31, an SFC
/// block's `n : UINT := nTotal;` was E1025): each `:= expr` taken is blanked in `text` and pushed
/// onto `computed`; W1433 at the first, E1069 for one that cannot be placed.
pub(super) fn pou_var_inits(
    (file, src, declarations): (crate::FileId, &str, Range<usize>),
    text: &mut String,
    function: bool,
    file_globals: &HashSet<String>,
    computed: &mut Vec<Range<usize>>,
    diags: &mut diagnostics::Diagnostics,
) -> Vec<super::file::VarInits> {
    let from = declarations.start;
    if from >= declarations.end {
        return Vec::new();
    }
    let Some(Found {
        cut,
        inits,
        prefixed,
        unplaceable,
    }) = pou_run_time_inits(text, declarations, function, file_globals)
    else {
        return Vec::new();
    };
    for (name, at) in &unplaceable {
        diags.push(unplaceable_error(
            src.get(name.clone()).unwrap_or(""),
            crate::Span::new(file, at.start, at.end),
        ));
    }
    // W1433 once per POU, at the first (of a value computed: not one left out with its E1069)
    let placed =
        |(name, _): &&(Range<usize>, Range<usize>)| !unplaceable.iter().any(|(n, _)| n == name);
    if let Some((name, value)) = cut.iter().find(placed) {
        diags.push(computed_warning(
            src.get(name.clone()).unwrap_or(""),
            crate::Span::new(file, value.start, value.end),
        ));
    }
    for (_, r) in cut {
        computed.push(r.clone());
        super::file::blank(text, r);
    }
    vec![(file, inits, from, prefixed)]
}
