//! `VAR_CONFIG` blocks of `.st` and `.il` configurations (IEC 61131-3 3rd edition 6.5.6): their
//! entries read from the text, and applied to the parsed units of the whole project (the configuration
//! and its programs may sit in different files) by copying the program and function blocks along each
//! entry's path per instance.
//!
//! Input: the file's text, then every parsed unit. Output: the units with per-instance locations and
//! initial values, and E0306 for an entry that names nothing.

use super::file::*;
use super::lexer::{Tok, Token};
use crate::ast::{CompilationUnit, LibraryElement};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};
use std::ops::Range;

/// One entry of a `VAR_CONFIG` block (IEC 61131-3 3rd edition 6.5.6): the instance path of a
/// variable, the location it gets and its initial value.
#[derive(Debug, Clone)]
pub struct ConfigEntry {
    path: Vec<crate::ast::Ident>,
    location: Option<crate::ast::DirectAddress>,
    init: Option<crate::ast::Initializer>,
    span: Span,
    /// A `VAR_ACCESS` entry instead (given to the configuration whose text holds it).
    access: Option<crate::ast::AccessDecl>,
}

/// One `VAR_ACCESS` entry (IEC 61131-3 2.7.1 / 6.8.2): `name : [res.]prog.{fb.}var : TYPE
/// [READ_WRITE | READ_ONLY]` or `name : [res.]%IX1.1 : TYPE ...` (`entry`: its tokens without the
/// `;`). No direction is READ_ONLY, as the standard says. `Err`: why it cannot be read.
fn access_entry(
    file: FileId,
    src: &str,
    entry: &[&Token],
    span: Span,
) -> Result<crate::ast::AccessDecl, &'static str> {
    use crate::ast::{DirectAddress, Ident};
    let ident = |t: &Token| Ident::new(word(src, t), Span::new(file, t.range.start, t.range.end));
    let expected = "expected `name : resource.program.variable : TYPE READ_WRITE` (or READ_ONLY)";
    let (Some(name), Some(colon)) = (entry.first(), entry.get(1)) else {
        return Err(expected);
    };
    if name.tok != Tok::Ident || colon.tok != Tok::Colon {
        return Err(expected);
    }
    let mut i = 2;
    let mut path = Vec::new();
    let mut subscripts = Vec::new();
    let mut address = None;
    while let Some(t) = entry.get(i) {
        match &t.tok {
            Tok::Ident => {
                path.push(ident(t));
                // `Values[2]`, `Samples[1, 3][2]`: constant subscripts of an element (IEC
                // 61131-3 6.8.2: an access path names a symbolic variable, elements included)
                while entry.get(i + 1).is_some_and(|b| b.tok == Tok::LBracket) {
                    let open = entry[i + 1];
                    let mut values = Vec::new();
                    let mut j = i + 2;
                    loop {
                        let negative = entry.get(j).is_some_and(|m| word(src, m) == "-");
                        if negative {
                            j += 1;
                        }
                        let Some(Tok::Int(v)) = entry.get(j).map(|n| &n.tok) else {
                            return Err("an access path's subscripts are integer literals");
                        };
                        let v = *v;
                        values.push(if negative { -v } else { v });
                        j += 1;
                        match entry.get(j).map(|n| &n.tok) {
                            Some(Tok::Comma) => j += 1,
                            Some(Tok::RBracket) => break,
                            _ => return Err("an access path's subscripts are integer literals"),
                        }
                    }
                    let close = entry[j];
                    subscripts.push((
                        path.len() - 1,
                        values,
                        Span::new(file, open.range.start, close.range.end),
                    ));
                    i = j;
                }
            }
            Tok::Address(area, size, p) if address.is_none() => {
                address = Some(DirectAddress {
                    area: *area,
                    size: *size,
                    path: p.clone(),
                    span: Span::new(file, t.range.start, t.range.end),
                })
            }
            _ => return Err(expected),
        }
        i += 1;
        match entry.get(i).map(|t| &t.tok) {
            Some(Tok::Dot) if address.is_none() => i += 1,
            Some(Tok::Colon) => break,
            _ => return Err(expected),
        }
    }
    if path.is_empty() && address.is_none() {
        return Err(expected);
    }
    if address.is_some() && path.len() > 1 {
        return Err("a direct address is reached as `resource.%IX1.1` or `%IX1.1`");
    }
    let Some(ty) = entry
        .get(i + 1)
        .filter(|t| matches!(t.tok, Tok::Ident | Tok::Kw(_)))
    else {
        return Err("expected the access path's type after `:`");
    };
    let read_only = match entry.get(i + 2) {
        None => true,
        Some(d) if word(src, d).eq_ignore_ascii_case("READ_ONLY") => true,
        Some(d) if word(src, d).eq_ignore_ascii_case("READ_WRITE") => false,
        Some(_) => return Err("the direction is READ_WRITE or READ_ONLY"),
    };
    if entry.len() > i + 3 {
        return Err("unexpected text after the direction");
    }
    Ok(crate::ast::AccessDecl {
        name: ident(name),
        path,
        subscripts,
        address,
        type_name: ident(ty),
        read_only,
        span,
    })
}

impl ConfigEntry {
    /// An entry read elsewhere (a TC6 XML `<configVariable>`): the instance path of the variable
    /// (`res.inst.fb.x` or `inst.x`), the location it gets, its initial value, and where it is written.
    pub fn new(
        path: Vec<crate::ast::Ident>,
        location: Option<crate::ast::DirectAddress>,
        init: Option<crate::ast::Initializer>,
        span: Span,
    ) -> ConfigEntry {
        ConfigEntry {
            path,
            location,
            init,
            span,
            access: None,
        }
    }
}

/// The `VAR_CONFIG ... END_VAR` blocks of a text: their ranges (blanked before the IL parser reads the
/// configuration) and their entries `res.inst.fb.x AT %QX0.1 : BOOL := TRUE;`. An entry that cannot
/// be read is E0306.
pub(super) fn var_config_blocks(
    file: FileId,
    src: &str,
    toks: &[Token],
    diags: &mut Diagnostics,
) -> (Vec<Range<usize>>, Vec<ConfigEntry>) {
    use crate::ast::{DirectAddress, Ident, Initializer, Literal, LiteralKind, Operand};
    let mut ranges = Vec::new();
    let mut entries = Vec::new();
    let mut k = 0;
    while k < toks.len() {
        let access = is_word(src, &toks[k], "VAR_ACCESS");
        if !access && !is_word(src, &toks[k], "VAR_CONFIG") {
            k += 1;
            continue;
        }
        let start = toks[k].range.start;
        k += 1;
        let mut entry: Vec<&Token> = Vec::new();
        while k < toks.len() && !is_word(src, &toks[k], "END_VAR") && toks[k].tok != Tok::Eof {
            if toks[k].tok != Tok::Semi {
                entry.push(&toks[k]);
                k += 1;
                continue;
            }
            k += 1;
            let Some(first) = entry.first() else {
                continue;
            };
            let span = Span::new(file, first.range.start, entry[entry.len() - 1].range.end);
            if access {
                match access_entry(file, src, &entry, span) {
                    Ok(a) => entries.push(ConfigEntry {
                        path: Vec::new(),
                        location: None,
                        init: None,
                        span,
                        access: Some(a),
                    }),
                    Err(why) => diags.push(
                        Diagnostic::error(
                            code::E0308,
                            format!("this VAR_ACCESS entry cannot be read: {why}"),
                        )
                        .at(span)
                        .with_hint("write `name : resource.program.variable : INT READ_WRITE;` inside CONFIGURATION"),
                    ),
                }
                entry.clear();
                continue;
            }
            let bad = |diags: &mut Diagnostics, why: &str| {
                diags.push(
                    Diagnostic::error(code::E0306, format!("this VAR_CONFIG entry cannot be read: {why}"))
                        .at(span)
                        .with_hint("write `resource.instance.variable AT %QX0.1 : BOOL;` or `resource.instance.variable : INT := 5;`"),
                );
            };
            let mut i = 0;
            let mut path = Vec::new();
            while i < entry.len() && entry[i].tok == Tok::Ident {
                path.push(Ident::new(
                    word(src, entry[i]),
                    Span::new(file, entry[i].range.start, entry[i].range.end),
                ));
                i += 1;
                if i < entry.len() && entry[i].tok == Tok::Dot {
                    i += 1;
                } else {
                    break;
                }
            }
            let mut location = None;
            if i < entry.len() && word(src, entry[i]).eq_ignore_ascii_case("AT") {
                if let Some(Tok::Address(area, size, p)) = entry.get(i + 1).map(|t| &t.tok) {
                    let t = entry[i + 1];
                    location = Some(DirectAddress {
                        area: *area,
                        size: *size,
                        path: p.clone(),
                        span: Span::new(file, t.range.start, t.range.end),
                    });
                    i += 2;
                }
            }
            if path.len() < 2 || entry.get(i).map(|t| &t.tok) != Some(&Tok::Colon) {
                bad(diags, "expected `instance.variable [AT %address] : type`");
                entry.clear();
                continue;
            }
            let assign = entry[i..].iter().position(|t| t.tok == Tok::Assign);
            let mut init = None;
            if let Some(a) = assign {
                let rest = &entry[i + a + 1..];
                let (neg, rest) = match rest.first().map(|t| &t.tok) {
                    Some(Tok::Minus) => (true, &rest[1..]),
                    _ => (false, rest),
                };
                let kind = match rest.iter().map(|t| &t.tok).collect::<Vec<_>>().as_slice() {
                    [Tok::Int(v)] => Some(LiteralKind::Int(if neg { -v } else { *v })),
                    [Tok::Real(v)] => Some(LiteralKind::Real(if neg { -v } else { *v })),
                    [Tok::Kw(_)] if !neg && word(src, rest[0]).eq_ignore_ascii_case("TRUE") => {
                        Some(LiteralKind::Bool(true))
                    }
                    [Tok::Kw(_)] if !neg && word(src, rest[0]).eq_ignore_ascii_case("FALSE") => {
                        Some(LiteralKind::Bool(false))
                    }
                    _ => None,
                };
                let Some(kind) = kind else {
                    bad(diags, "the initial value must be a number, TRUE or FALSE");
                    entry.clear();
                    continue;
                };
                let last = entry[entry.len() - 1];
                init = Some(Initializer::Value(Operand::literal(Literal {
                    kind,
                    type_prefix: None,
                    span: Span::new(file, entry[i + a + 1].range.start, last.range.end),
                })));
            }
            entries.push(ConfigEntry {
                path,
                location,
                init,
                span,
                access: None,
            });
            entry.clear();
        }
        let end = toks.get(k).map_or(src.len(), |t| t.range.end);
        ranges.push(start..end);
    }
    (ranges, entries)
}

/// Applies the `VAR_CONFIG` entries: the program instance's program, and each function block along
/// an entry's path, is copied for that instance (`main__CFG1`, same body), and the copy's variable
/// gets the entry's location (it must be declared `AT %I*` / `%Q*` / `%M*`, of the same area) and
/// initial value. The instances of one program or block that VAR_CONFIG does not name keep the
/// original. An entry whose path names no instance variable is E0306. `units` are every unit of the
/// project: a copy goes into the unit of its original.
pub fn apply_var_config(
    units: &mut [CompilationUnit],
    entries: Vec<ConfigEntry>,
    diags: &mut Diagnostics,
) {
    use crate::ast::{Pou, PouKind, TypeRef};
    if entries.is_empty() {
        return;
    }
    let mut clones: std::collections::HashMap<String, String> = Default::default();
    let mut next = 0;
    // VAR_ACCESS entries: to the configuration whose text holds them
    let (access, entries): (Vec<_>, Vec<_>) = entries.into_iter().partition(|e| e.access.is_some());
    for a in access.into_iter().filter_map(|e| e.access) {
        let inside = units
            .iter_mut()
            .flat_map(|u| u.items.iter_mut())
            .find_map(|i| match i {
                LibraryElement::Configuration(c)
                    if c.span.file == a.span.file
                        && c.span.start <= a.span.start
                        && a.span.end <= c.span.end =>
                {
                    Some(c)
                }
                _ => None,
            });
        match inside {
            Some(c) => c.access.push(a),
            None => diags.push(
                Diagnostic::error(code::E0308, "a VAR_ACCESS block outside a CONFIGURATION")
                    .at(a.span)
                    .with_hint(
                        "access paths are declared inside CONFIGURATION ... END_CONFIGURATION",
                    ),
            ),
        }
    }
    if entries.is_empty() {
        return;
    }
    let find_pou = |units: &[CompilationUnit], name: &str| {
        units.iter().enumerate().find_map(|(u, unit)| {
            unit.items
                .iter()
                .position(|i| matches!(i, LibraryElement::Pou(p) if p.name.is(name)))
                .map(|k| (u, k))
        })
    };
    for e in entries {
        let fail = |diags: &mut Diagnostics, why: String| {
            diags.push(
                Diagnostic::error(code::E0306, format!("this VAR_CONFIG entry cannot be applied: {why}"))
                    .at(e.span)
                    .with_hint("name a resource, a program instance and its variables: `res.inst.fb.x`; the variable must be declared `AT %Q*` (or %I*, %M*) to get a location"),
            );
        };
        // `res.inst.rest` (or `inst.rest`): the program instance
        let mut found = None;
        for (ui, unit) in units.iter().enumerate() {
            for (ii, item) in unit.items.iter().enumerate() {
                let LibraryElement::Configuration(c) = item else {
                    continue;
                };
                for (ri, r) in c.resources.iter().enumerate() {
                    for (pi, p) in r.programs.iter().enumerate() {
                        if e.path.len() > 2 && r.name == e.path[0] && p.name == e.path[1] {
                            found = Some((ui, ii, ri, pi, 2));
                        } else if found.is_none() && p.name == e.path[0] {
                            found = Some((ui, ii, ri, pi, 1));
                        }
                    }
                }
            }
        }
        let Some((ui, ii, ri, pi, skip)) = found else {
            let named: Vec<&str> = e.path.iter().take(2).map(|p| p.name.as_str()).collect();
            fail(
                diags,
                format!("`{}` names no program instance", named.join(".")),
            );
            continue;
        };
        let Some(pou_of) = find_pou(units, &units_program(units, ui, ii, ri, pi)) else {
            let ty = units_program(units, ui, ii, ri, pi);
            fail(diags, format!("no program `{ty}` in this project"));
            continue;
        };
        let LibraryElement::Configuration(c) = &mut units[ui].items[ii] else {
            continue;
        };
        let inst = &mut c.resources[ri].programs[pi];
        // keyed by the program instance, not by how the path names it (`res.inst.x` and
        // `inst.x` reach one instance, so one copy)
        let prefix_key = |n: usize| {
            let mut k = format!("{ui}/{ii}/{ri}/{pi}");
            for p in &e.path[skip..n] {
                k.push('.');
                k.push_str(&p.key());
            }
            k
        };
        let ty = inst.type_name.name.clone();
        let key = prefix_key(skip);
        let mut current = match clones.get(&key) {
            Some(c) => c.clone(),
            None => {
                next += 1;
                let name = format!("{ty}__CFG{next}");
                clones.insert(key, name.clone());
                inst.type_name.name = name.clone();
                let (u, k) = pou_of;
                let LibraryElement::Pou(p) = &units[u].items[k] else {
                    continue;
                };
                let mut copy: Pou = p.clone();
                copy.name.name = name.clone();
                units[u].items.push(LibraryElement::Pou(copy));
                name
            }
        };
        let rest = &e.path[skip..];
        for (depth, v) in rest.iter().enumerate() {
            let Some((u, k)) = find_pou(units, &current) else {
                break;
            };
            let LibraryElement::Pou(p) = &mut units[u].items[k] else {
                break;
            };
            let Some(decl) = p
                .var_blocks
                .iter_mut()
                .flat_map(|b| b.vars.iter_mut())
                .find(|d| d.name == *v)
            else {
                fail(
                    diags,
                    format!(
                        "`{}` has no variable `{}`",
                        p.name.name.split("__CFG").next().unwrap_or(""),
                        v.name
                    ),
                );
                break;
            };
            if depth + 1 == rest.len() {
                if let Some(loc) = &e.location {
                    match &decl.location {
                        Some(d) if d.path.is_empty() && d.area == loc.area => {
                            decl.location = Some(loc.clone());
                        }
                        _ => {
                            fail(
                                diags,
                                format!(
                                    "`{}` is not declared AT {}*",
                                    v.name,
                                    match loc.area {
                                        crate::ast::Area::Input => "%I",
                                        crate::ast::Area::Output => "%Q",
                                        crate::ast::Area::Memory => "%M",
                                    }
                                ),
                            );
                            break;
                        }
                    }
                }
                if e.init.is_some() {
                    decl.init = e.init.clone();
                }
                break;
            }
            let TypeRef::Named(fb) = &decl.ty else {
                fail(diags, format!("`{}` is no function block instance", v.name));
                break;
            };
            let fb_name = fb.name.clone();
            let key = prefix_key(skip + depth + 1);
            let name = match clones.get(&key) {
                Some(c) => c.clone(),
                None => {
                    next += 1;
                    let name = format!("{fb_name}__CFG{next}");
                    clones.insert(key, name.clone());
                    name
                }
            };
            let fb_span = fb.span;
            decl.ty = TypeRef::Named(crate::ast::Ident::new(name.clone(), fb_span));
            if find_pou(units, &name).is_none() {
                let Some((u, k)) = find_pou(units, &fb_name) else {
                    fail(
                        diags,
                        format!("no function block `{fb_name}` in this project"),
                    );
                    break;
                };
                let LibraryElement::Pou(p) = &units[u].items[k] else {
                    break;
                };
                if p.kind != PouKind::FunctionBlock {
                    fail(diags, format!("`{}` is no function block instance", v.name));
                    break;
                }
                let mut copy: Pou = p.clone();
                copy.name.name = name.clone();
                units[u].items.push(LibraryElement::Pou(copy));
            }
            current = name;
        }
    }
    // a program or block all of whose instances now use copies is dropped (its placeholders
    // would have no location)
    let originals: std::collections::HashSet<String> = clones
        .values()
        .filter_map(|c| c.split("__CFG").next())
        .map(str::to_ascii_uppercase)
        .collect();
    loop {
        let before: usize = units.iter().map(|u| u.items.len()).sum();
        let mut used: std::collections::HashSet<String> = Default::default();
        for item in units.iter().flat_map(|u| u.items.iter()) {
            match item {
                LibraryElement::Pou(p) => {
                    for d in p.var_blocks.iter().flat_map(|b| b.vars.iter()) {
                        let mut t = &d.ty;
                        while let TypeRef::Array { element, .. } = t {
                            t = element;
                        }
                        if let TypeRef::Named(n) = t {
                            used.insert(n.key());
                        }
                    }
                }
                LibraryElement::Configuration(c) => {
                    for p in c.resources.iter().flat_map(|r| r.programs.iter()) {
                        used.insert(p.type_name.key());
                    }
                }
                _ => {}
            }
        }
        for unit in units.iter_mut() {
            unit.items.retain(|i| match i {
                LibraryElement::Pou(p) => {
                    !originals.contains(&p.name.key()) || used.contains(&p.name.key())
                }
                _ => true,
            });
        }
        if units.iter().map(|u| u.items.len()).sum::<usize>() == before {
            break;
        }
    }
}

/// The type name of program instance `pi` of resource `ri` of configuration item `ii` of unit `ui`.
fn units_program(units: &[CompilationUnit], ui: usize, ii: usize, ri: usize, pi: usize) -> String {
    match &units[ui].items[ii] {
        LibraryElement::Configuration(c) => c.resources[ri].programs[pi].type_name.name.clone(),
        _ => String::new(),
    }
}
