//! Edition 3 inheritance of function blocks (`FUNCTION_BLOCK Child EXTENDS Base IMPLEMENTS I1, I2`,
//! `INTERFACE I ... END_INTERFACE`, `SUPER^`, `FINAL`, `ABSTRACT`), as CODESYS and TwinCAT run it.
//!
//! Input: the pending ST bodies of every file (their [`Oop`] read by [`super::file::parse_text`]) and
//! the parsed units (the blocks' own declarations). Output: the pending bodies to lower, where a
//! derived block is flattened: its variables are its bases' (root first, every section) then its own;
//! its methods and actions are its bases' unless it declares one of the same name (a method with
//! another signature than the base's it would override is E1084 and dropped, the base's kept:
//! `super::override_signature`); its body is its
//! own (the derived block's body replaces the base's, which runs only where `SUPER^()` calls it, as
//! CODESYS and Beckhoff document `SUPER`). `SUPER^.M()` in a text of level `j` of the chain calls the
//! version of `M` visible at level `j - 1` (a hidden method `__S<level>_M`), `SUPER^()` the body of
//! level `j - 1` (a hidden method `__B<level>`; when that body is SFC, a hidden action `__C<level>`
//! the caller replaces by one scan of the base's chart, [`BlockOop::super_charts`]); any other call of a method (`M2()`, `THIS^.M2()`),
//! also inside an inherited method, calls the derived block's version: late binding on the
//! instance's own type, without pointers, since each derived block has its own copy.
//! Invariants: every chain is finite (a cycle is E0331, never followed); texts are rewritten in place
//! with the same length and line breaks, so every span of inherited code is a position in its file;
//! each problem is one located diagnostic (E0330-E0336, E1084).

use super::file::{PendingBody, PendingMethod, PouText};
use super::lexer::{lex, Tok};
use crate::ast::{CompilationUnit, Ident, LibraryElement, PouKind, TypeRef, VarBlock, VarKind};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};
use std::collections::{HashMap, HashSet};
use std::ops::Range;

/// The object-oriented part of a pending body.
#[derive(Debug, Clone)]
pub enum Oop {
    /// A function block's `EXTENDS` / `IMPLEMENTS` / `FINAL` / `ABSTRACT`.
    Block(BlockOop),
    /// An `INTERFACE` (the pending body has no text; it is no POU).
    Interface(InterfaceOop),
}

/// What a function block declares about its place among others.
#[derive(Debug, Clone, Default)]
pub struct BlockOop {
    /// The base after `EXTENDS` (more than one is E0330).
    pub extends: Vec<Ident>,
    /// The interfaces after `IMPLEMENTS`.
    pub implements: Vec<Ident>,
    /// `FUNCTION_BLOCK FINAL`: no block may extend it (E0332).
    pub is_final: bool,
    /// `FUNCTION_BLOCK ABSTRACT`: no variable may be an instance of it (E0333).
    pub is_abstract: bool,
    /// The diagnostics of its methods' declarations, reported when its base is found (a block
    /// whose base is missing is not compiled: E0330 only).
    pub deferred: Vec<Diagnostic>,
    /// After [`flatten`]: the file of each of the body's methods (inherited ones come from their
    /// base's file); empty before, when every method is in the body's file.
    pub method_files: Vec<FileId>,
    /// After [`flatten`]: the bases whose chart (SFC body) `SUPER^()` runs in this block, each as
    /// (the hidden action's name, [`super_chart`], the base's name).
    pub super_charts: Vec<(String, String)>,
}

/// An `INTERFACE name [EXTENDS I0, ...] METHOD ... END_METHOD ... END_INTERFACE`.
#[derive(Debug, Clone)]
pub struct InterfaceOop {
    /// The interface's name.
    pub name: Ident,
    /// The interfaces it extends.
    pub extends: Vec<Ident>,
    /// Its methods: the signatures a block that implements it must have.
    pub methods: Vec<PendingMethod>,
}

/// The identifiers after `EXTENDS` and after `IMPLEMENTS` in `range` of `src`.
fn clause_names(file: FileId, src: &str, range: &Range<usize>) -> (Vec<Ident>, Vec<Ident>) {
    let text = src.get(range.clone()).unwrap_or("");
    let (toks, _) = lex(text);
    let (mut extends, mut implements): (Vec<Ident>, Vec<Ident>) = (Vec::new(), Vec::new());
    let mut into_implements = false;
    let mut after_dot = false;
    for (k, t) in toks.iter().enumerate() {
        let w = text.get(t.range.clone()).unwrap_or("");
        if w.eq_ignore_ascii_case("EXTENDS") {
            into_implements = false;
            // `EXTENDS` with no name after it (the clause ends there, `file`): a base without a
            // name, at the keyword, which `chain_of` reports as missing
            if toks.get(k + 1).is_none_or(|n| {
                n.tok != Tok::Ident
                    || text
                        .get(n.range.clone())
                        .is_some_and(|x| x.eq_ignore_ascii_case("IMPLEMENTS"))
            }) {
                extends.push(Ident::new(
                    "",
                    Span::new(file, range.start + t.range.start, range.start + t.range.end),
                ));
            }
        } else if w.eq_ignore_ascii_case("IMPLEMENTS") {
            into_implements = true;
        } else if t.tok == Tok::Ident {
            let list = if into_implements {
                &mut implements
            } else {
                &mut extends
            };
            match list.last_mut().filter(|_| after_dot) {
                // `TcUnit.FB_TestSuite`: a name qualified by a library's namespace, one name
                Some(last) => {
                    last.name = format!("{}.{w}", last.name);
                    last.span.end = (range.start + t.range.end) as u32;
                }
                None => list.push(Ident::new(
                    w,
                    Span::new(file, range.start + t.range.start, range.start + t.range.end),
                )),
            }
        }
        after_dot = t.tok == Tok::Dot;
    }
    (extends, implements)
}

impl Oop {
    /// The `Oop` of an `INTERFACE` (`p`, read by the scan) with its methods' signatures.
    pub(super) fn interface(
        file: FileId,
        src: &str,
        p: &PouText,
        methods: Vec<PendingMethod>,
    ) -> Oop {
        let extends = p
            .heritage
            .as_ref()
            .map(|h| clause_names(file, src, h).0)
            .unwrap_or_default();
        Oop::Interface(InterfaceOop {
            name: Ident::new(
                &p.name,
                Span::new(file, p.name_range.start, p.name_range.end),
            ),
            extends,
            methods,
        })
    }

    /// The `Oop` of a function block: `None` without `EXTENDS`, `IMPLEMENTS`, `FINAL` or `ABSTRACT`.
    pub(super) fn block(file: FileId, src: &str, p: &PouText) -> Option<Oop> {
        let modifier = p
            .modifier
            .as_ref()
            .and_then(|r| src.get(r.clone()))
            .map(str::to_ascii_uppercase);
        // one word or several (`INTERNAL ABSTRACT`)
        let has = |w: &str| {
            modifier
                .as_deref()
                .is_some_and(|m| m.split_whitespace().any(|x| x == w))
        };
        let is_final = has("FINAL");
        let is_abstract = has("ABSTRACT");
        let (extends, implements) = p
            .heritage
            .as_ref()
            .map(|h| clause_names(file, src, h))
            .unwrap_or_default();
        (is_final || is_abstract || !extends.is_empty() || !implements.is_empty()).then(|| {
            Oop::Block(BlockOop {
                extends,
                implements,
                is_final,
                is_abstract,
                deferred: Vec::new(),
                method_files: Vec::new(),
                super_charts: Vec::new(),
            })
        })
    }
}

/// One function block as inheritance sees it.
struct Class {
    name: Ident,
    /// Its own variable blocks, as parsed.
    vars: Vec<VarBlock>,
    /// Its pending body (ST), if any.
    pending: Option<usize>,
    /// Its body is non-empty IL (no pending body): `SUPER^()` cannot run it.
    il_body: bool,
    /// Its body is SFC (a chart, lowered by the caller, not as a method): `SUPER^()` calls a
    /// hidden action the caller replaces by one scan of the chart.
    sfc_body: bool,
    oop: BlockOop,
}

/// The longest chain of bases followed (a longer one is reported as E0331).
const MAX_DEPTH: usize = 100;

/// Flattens the derived function blocks of `pending` into `units` (their variables) and returns the
/// pending bodies to lower (their methods and bodies), and checks `IMPLEMENTS`, `FINAL`, `ABSTRACT`
/// and the initial values of variables of an interface type, and declares each interface's hidden
/// structure ([`super::interface_vars`]). `None` when no pending body has an [`Oop`] (nothing to do).
pub fn flatten(
    units: &mut [CompilationUnit],
    pending: &[PendingBody],
    diags: &mut Diagnostics,
) -> Option<Flat> {
    if !pending.iter().any(|pb| pb.oop.is_some()) {
        return None;
    }
    let mut out: Vec<PendingBody> = pending.to_vec();
    // (a block whose body is SFC too: its EXTENDS, its methods and actions for the blocks that
    // extend it)
    let by_start: HashMap<(FileId, usize), usize> = pending
        .iter()
        .enumerate()
        .map(|(k, pb)| ((pb.file, pb.name_start), k))
        .collect();
    let mut classes: HashMap<String, Class> = HashMap::new();
    let mut other_pous: HashSet<String> = HashSet::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        let LibraryElement::Pou(p) = item else {
            continue;
        };
        if p.kind != PouKind::FunctionBlock {
            other_pous.insert(p.name.key());
            continue;
        }
        let k = by_start
            .get(&(p.name.span.file, p.name.span.start as usize))
            .copied();
        let oop = match k.and_then(|k| pending[k].oop.as_deref()) {
            Some(Oop::Block(b)) => b.clone(),
            _ => BlockOop::default(),
        };
        classes.entry(p.name.key()).or_insert(Class {
            name: p.name.clone(),
            vars: p.var_blocks.clone(),
            pending: k,
            il_body: k.is_none() && !p.body.is_empty(),
            sfc_body: k.is_some_and(|k| pending[k].sfc),
            oop,
        });
    }
    let interfaces: HashMap<String, &InterfaceOop> = pending
        .iter()
        .filter_map(|pb| match pb.oop.as_deref() {
            Some(Oop::Interface(i)) => Some((i.name.key(), i)),
            _ => None,
        })
        .collect();
    unknown_interface_bases(&interfaces, diags);
    // the chain of each derived block, root first; `None` when broken (reported)
    let mut keys: Vec<String> = classes.keys().cloned().collect();
    keys.sort_by_key(|k| {
        let c = &classes[k];
        (c.name.span.file, c.name.span.start)
    });
    let mut chains: HashMap<String, Option<Vec<String>>> = HashMap::new();
    for key in &keys {
        let c = &classes[key];
        if c.oop.extends.is_empty() {
            continue;
        }
        if let Some(extra) = c.oop.extends.get(1) {
            diags.push(
                Diagnostic::error(
                    code::E0330,
                    format!("`{}` extends more than one function block", c.name.name),
                )
                .at(extra.span)
                .with_primary_label("a second base")
                .with_hint("a function block has one base (EXTENDS A); several interfaces go after IMPLEMENTS"),
            );
        }
        chains.insert(
            key.clone(),
            chain_of(key, &classes, &interfaces, &other_pous, diags),
        );
    }
    // a block with a broken chain compiles without its body and methods (its errors are reported),
    // and its methods' instances initialise nothing: the missing base is the one error, not one
    // per instance given FB_init arguments (`super::fb_init`; before round 30, an E0329 "not one
    // ladderc initialises" each: 69 in a TcUnit test library whose FB_TestSuite is not given)
    for key in &keys {
        let Some(chain) = chains.get(key) else {
            continue;
        };
        let c = &classes[key];
        let Some(k) = c.pending else { continue };
        let Some(chain) = chain else {
            let dropped: Vec<Span> = out[k]
                .methods
                .iter()
                .flat_map(|m| m.blocks.iter().map(|b| b.span))
                .collect();
            out[k].text = String::new();
            out[k].methods.clear();
            if !dropped.is_empty() {
                for a in out.iter_mut().flat_map(|pb| pb.fb_init_args.iter_mut()) {
                    a.in_uncompiled_method |= dropped.iter().any(|b| {
                        b.file == a.span.file && b.start <= a.span.start && a.span.end <= b.end
                    });
                }
            }
            continue;
        };
        diags.extend(c.oop.deferred.iter().cloned());
        flatten_one(units, pending, &classes, chain, &mut out[k], diags);
    }
    // IMPLEMENTS: each interface's methods, with the same signature, in the block or its bases
    for key in &keys {
        let c = &classes[key];
        // (a block whose EXTENDS chain is broken lost its methods with its body: its error is
        // the base's, not a missing method of each interface)
        if c.oop.implements.is_empty() || matches!(chains.get(key), Some(None)) {
            continue;
        }
        let methods: Vec<&PendingMethod> = match c.pending {
            Some(k) => out[k].methods.iter().collect(),
            None => Vec::new(),
        };
        // (an interface reached twice, `IMPLEMENTS I_Step, I_Named` where I_Step EXTENDS
        // I_Named, is checked once: one error per missing method)
        let mut seen = HashSet::new();
        for itf in &c.oop.implements {
            check_implements(c, itf, &methods, &interfaces, &mut seen, diags);
        }
    }
    let inits = check_instances(units, &classes, &interfaces, diags);
    // variables of an interface type: each block's interfaces, its bases' included
    let blocks: Vec<(Ident, bool, Vec<Ident>)> = keys
        .iter()
        .map(|key| {
            let c = &classes[key];
            let levels = match chains.get(key) {
                Some(Some(chain)) => chain.clone(),
                Some(None) => Vec::new(),
                None => vec![key.clone()],
            };
            // (a block whose EXTENDS chain is broken keeps its own IMPLEMENTS: it is not
            // compiled, E0330 says why, and its instances given to its interfaces report nothing
            // more, as an ABSTRACT block's)
            let implements = if levels.is_empty() {
                c.oop.implements.clone()
            } else {
                levels
                    .iter()
                    .flat_map(|k| classes[k].oop.implements.iter().cloned())
                    .collect()
            };
            (
                c.name.clone(),
                c.oop.is_abstract || levels.is_empty(),
                implements,
            )
        })
        .collect();
    let table = super::interface_vars::table(units, &blocks, &interfaces);
    // each derived block's bases (upper-case), for E0344
    let bases = chains
        .iter()
        .filter_map(|(k, c)| {
            let c = c.as_ref()?;
            Some((k.clone(), c[..c.len().saturating_sub(1)].to_vec()))
        })
        .collect();
    let derived = declare_classes(units, &classes, &keys, &chains);
    let mut out = out;
    for m in out.iter_mut().flat_map(|b| b.methods.iter_mut()) {
        method_in_outs_by_reference(m, &derived);
    }
    Some(Flat {
        bodies: out,
        interfaces: table,
        inits,
        bases,
        derived,
    })
}

/// Gives each block of a family (extended, or extending another) its class variable, first of its
/// variables, and makes each `VAR_IN_OUT x : B` of a block `B` that has derived blocks a
/// `VAR_INPUT x : REFERENCE TO B` (see [`super::base_view`]); returns the derived blocks of each
/// base with their class numbers (a block's number is its place in `keys`, plus one).
fn declare_classes(
    units: &mut [CompilationUnit],
    classes: &HashMap<String, Class>,
    keys: &[String],
    chains: &HashMap<String, Option<Vec<String>>>,
) -> super::base_view::Derived {
    use crate::ast::{Initializer, Operand, VarDecl};
    let id = |k: &str| keys.iter().position(|x| x == k).map_or(0, |p| p as u32 + 1);
    let mut derived: super::base_view::Derived = HashMap::new();
    // each member's chain, root first
    let mut members: HashMap<String, Vec<String>> = HashMap::new();
    for key in keys {
        let Some(Some(chain)) = chains.get(key) else {
            continue;
        };
        for (j, b) in chain[..chain.len() - 1].iter().enumerate() {
            derived
                .entry(b.clone())
                .or_default()
                .push((classes[key].name.clone(), id(key)));
            members
                .entry(b.clone())
                .or_insert_with(|| chain[..=j].to_vec());
        }
        members.insert(key.clone(), chain.clone());
    }
    if members.is_empty() {
        return derived;
    }
    let mut by_reference: HashMap<String, Vec<String>> = HashMap::new();
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        let LibraryElement::Pou(p) = item else {
            continue;
        };
        let key = p.name.key();
        if let (Some(chain), Some(c)) = (members.get(&key), classes.get(&key)) {
            if p.name.span == c.name.span && p.kind == PouKind::FunctionBlock {
                let names: Vec<String> =
                    chain.iter().map(|k| classes[k].name.name.clone()).collect();
                let span = p.name.span;
                let literal = Operand::literal(crate::ast::Literal {
                    kind: crate::ast::LiteralKind::Int(id(&key).into()),
                    type_prefix: None,
                    span,
                });
                let v = VarDecl::new(
                    Ident::new(super::base_view::class_var(&names), span),
                    TypeRef::Named(Ident::new("UINT", span)),
                    span,
                )
                .with_init(Initializer::Value(literal));
                p.var_blocks.insert(0, VarBlock::locals(vec![v], span));
            }
        }
        // VAR_IN_OUT of a base: a REFERENCE TO it, which a derived instance may be passed to
        let (blocks, converted) = in_outs_by_reference(std::mem::take(&mut p.var_blocks), &derived);
        p.var_blocks = blocks;
        if !converted.is_empty() {
            by_reference.insert(key, converted);
        }
    }
    // IL bodies (read already) that call a block with such a parameter pass the instance's
    // address, as the ST lowering does for a `REFERENCE TO` input
    if !by_reference.is_empty() {
        for item in units.iter_mut() {
            for e in item.items.iter_mut() {
                if let LibraryElement::Pou(p) = e {
                    pass_by_reference(p, &by_reference);
                }
            }
        }
    }
    derived
}

/// A METHOD's `VAR_IN_OUT x : B` of a block `B` that has derived blocks: a `VAR_INPUT x :
/// REFERENCE TO B`, as a block's own (see [`declare_classes`]): a derived instance may be passed
/// to it, and the method's calls through it run the derived block's overrides (IEC 61131-3 ed. 3
/// 6.6.5; before round 27: E1012 naming the hidden `__M_<M>_X`).
fn method_in_outs_by_reference(m: &mut PendingMethod, derived: &super::base_view::Derived) {
    m.blocks = in_outs_by_reference(std::mem::take(&mut m.blocks), derived).0;
}

/// `blocks` with each VAR_IN_OUT whose type is a block of `derived` (one that has derived blocks)
/// made a `VAR_INPUT x : REFERENCE TO B` in a block of its own, and the names so converted
/// (upper-case).
fn in_outs_by_reference(
    blocks: Vec<VarBlock>,
    derived: &super::base_view::Derived,
) -> (Vec<VarBlock>, Vec<String>) {
    use crate::ast::{RefKind, VarDecl};
    let is_base =
        |v: &VarDecl| matches!(&v.ty, TypeRef::Named(n) if derived.contains_key(&n.key()));
    let mut converted = Vec::new();
    let mut out = Vec::with_capacity(blocks.len());
    for b in blocks {
        if b.kind != VarKind::InOut || !b.vars.iter().any(is_base) {
            out.push(b);
            continue;
        }
        for v in b.vars.iter().cloned() {
            let mut nb = b.clone();
            if is_base(&v) {
                converted.push(v.name.key());
                let span = v.span;
                nb.kind = VarKind::Input;
                nb.vars = vec![VarDecl {
                    ty: TypeRef::Ref {
                        kind: RefKind::Reference,
                        target: Box::new(v.ty.clone()),
                        span,
                    },
                    ..v
                }];
            } else {
                nb.vars = vec![v];
            }
            out.push(nb);
        }
    }
    (out, converted)
}

/// In the IL body of `p`, `CAL inst(x := v)` where `x` is a converted VAR_IN_OUT of `inst`'s block
/// (`by_reference`: block -> parameters, upper-case): `x := REF(v)`.
fn pass_by_reference(p: &mut crate::ast::Pou, by_reference: &HashMap<String, Vec<String>>) {
    use crate::ast::{CallArgs, IlStmt, InstrKind, Operand};
    let types: HashMap<String, String> = p
        .var_blocks
        .iter()
        .flat_map(|b| b.vars.iter())
        .filter_map(|v| match &v.ty {
            TypeRef::Named(n) => Some((v.name.key(), n.key())),
            _ => None,
        })
        .collect();
    for s in p.body.iter_mut() {
        let IlStmt::Instr(i) = s else { continue };
        let InstrKind::Call { instance, args, .. } = &mut i.kind else {
            continue;
        };
        if !instance.accessors.is_empty() {
            continue;
        }
        let Some(params) = types
            .get(&instance.base.key())
            .and_then(|t| by_reference.get(t))
        else {
            continue;
        };
        let CallArgs::Formal(list) = args else {
            continue;
        };
        for a in list.iter_mut() {
            if !params.contains(&a.name.key()) {
                continue;
            }
            if let Operand::Var(v) = &a.value {
                a.value = Operand::reference(Some(v.clone()), v.span);
            }
        }
    }
}

/// An INTERFACE that EXTENDS a name that is no interface of the project: one E0330 at the name
/// (TwinCAT's own `__SYSTEM.IQueryInterface`, which every interface may extend, is known).
fn unknown_interface_bases(interfaces: &HashMap<String, &InterfaceOop>, diags: &mut Diagnostics) {
    let mut all: Vec<&&InterfaceOop> = interfaces.values().collect();
    all.sort_by_key(|i| (i.name.span.file, i.name.span.start));
    for i in all {
        for base in &i.extends {
            let key = base.key();
            // (`_SYSTEM.IQueryInterface` with one underscore is found in TwinCAT projects too)
            if interfaces.contains_key(&key) || key.trim_start_matches('_').starts_with("SYSTEM.") {
                continue;
            }
            diags.push(
                Diagnostic::error(
                    code::E0330,
                    format!(
                        "`{}` EXTENDS `{}`, which names no INTERFACE of the project",
                        i.name.name, base.name
                    ),
                )
                .at(base.span)
                .with_primary_label("no such interface")
                .with_hint("name an INTERFACE declared in one of the files given (`.st` INTERFACE ... END_INTERFACE, TwinCAT `.TcIO`), or add the library that declares it"),
            );
        }
    }
}

/// Reports (E1021) each call by its own name (`M()`, `THIS^.M()`, `SUPER^.M()`, also without
/// `^`) in a text of level `level` of a chain of a method a base declares `PRIVATE` (IEC 61131-3
/// ed. 3, 6.6.5; CODESYS "Method": callable only within its own block, not in the blocks
/// derived from it). Inherited code is checked at its own level; each place is reported once.
fn private_calls(
    file: FileId,
    text: &str,
    base: usize,
    level: usize,
    ctx: &Rewrite<'_>,
    diags: &mut Diagnostics,
) {
    let (toks, _) = lex(text);
    let me = ctx.levels[level].name.key();
    for (k, t) in toks.iter().enumerate() {
        if t.tok != Tok::Ident || toks.get(k + 1).is_none_or(|n| n.tok != Tok::LParen) {
            continue;
        }
        // after a `.`: only `THIS.`, `THIS^.`, `SUPER.`, `SUPER^.` (another instance's calls
        // are checked where they are linked, `crate::actions`)
        let mut below = level + 1;
        if k > 0 && toks[k - 1].tok == Tok::Dot {
            let mut q = k - 1;
            if q > 0 && toks[q - 1].tok == Tok::Caret {
                q -= 1;
            }
            let Some(w) = q
                .checked_sub(1)
                .and_then(|q| text.get(toks[q].range.clone()))
            else {
                continue;
            };
            if w.eq_ignore_ascii_case("SUPER") {
                below = level;
            } else if !w.eq_ignore_ascii_case("THIS") {
                continue;
            }
        }
        let Some(name) = text.get(t.range.clone()) else {
            continue;
        };
        let Some(&(_, m, _)) = ctx
            .versions
            .get(&name.to_ascii_uppercase())
            .and_then(|v| v.iter().rev().find(|(l, _, _)| *l < below))
        else {
            continue;
        };
        let Some(a) = m
            .access
            .as_ref()
            .filter(|a| a.access == crate::ast::Access::Private && a.owner != me)
        else {
            continue;
        };
        let span = Span::new(file, base + t.range.start, base + t.range.end);
        if diags
            .iter()
            .any(|d| d.code == code::E1021 && d.span == Some(span))
        {
            continue;
        }
        diags.push(
            Diagnostic::error(
                code::E1021,
                format!(
                    "METHOD `{}` is PRIVATE to `{}`: callable only in `{}` itself",
                    a.member, a.owner_name, a.owner_name
                ),
            )
            .at(span)
            .with_primary_label(format!("PRIVATE {}", a.what))
            .with_label(a.at, "declared PRIVATE here")
            .with_hint(format!(
                "a derived block does not call its base's PRIVATE methods: call a PUBLIC or PROTECTED method of `{}` that uses it, or declare it PROTECTED",
                a.owner_name
            )),
        );
    }
}

/// What [`flatten`] returns: the pending bodies to lower and the interfaces variables may have.
pub struct Flat {
    /// The pending bodies, derived blocks flattened.
    pub bodies: Vec<PendingBody>,
    /// Every interface of the program with the blocks that implement it.
    pub interfaces: Vec<super::interface_vars::Interface>,
    /// The initial values of interface variables (`itf : I_Shape := fbCircle;`), each with the
    /// POU that declares it (the file and start of its name): assigned when the POU first runs.
    pub inits: Vec<super::interface_vars::Init>,
    /// The bases of each derived block (upper-case names, root first).
    pub bases: HashMap<String, Vec<String>>,
    /// The derived blocks of each block that has some, with their class numbers.
    pub derived: super::base_view::Derived,
}

/// The chain of bases of `key`, root first, ending with `key`; `None` (with one diagnostic at the
/// block's EXTENDS) when a base is unknown, not a function block, FINAL, or the chain is a cycle.
fn chain_of(
    key: &str,
    classes: &HashMap<String, Class>,
    interfaces: &HashMap<String, &InterfaceOop>,
    other_pous: &HashSet<String>,
    diags: &mut Diagnostics,
) -> Option<Vec<String>> {
    let mut chain = vec![key.to_string()];
    let mut seen: HashSet<String> = chain.iter().cloned().collect();
    let mut cur = &classes[key];
    while let Some(base) = cur.oop.extends.first() {
        let bkey = base.key();
        let own = cur.name.key() == key;
        let Some(b) = classes.get(&bkey) else {
            if own {
                if base.name.is_empty() {
                    diags.push(
                        Diagnostic::error(
                            code::E0330,
                            format!(
                                "`{}` EXTENDS nothing: the name of the base block is missing after EXTENDS",
                                cur.name.name
                            ),
                        )
                        .at(base.span)
                        .with_primary_label("base block's name missing")
                        .with_hint("write the name of the FUNCTION_BLOCK it extends after EXTENDS, or remove EXTENDS"),
                    );
                    return None;
                }
                let what = if interfaces.contains_key(&bkey) {
                    "is an INTERFACE, which a function block implements (IMPLEMENTS), not extends"
                } else if other_pous.contains(&bkey) {
                    "is a PROGRAM or FUNCTION, not a function block"
                } else {
                    "names no function block of the project"
                };
                diags.push(
                    Diagnostic::error(
                        code::E0330,
                        format!("`{}` EXTENDS `{}`, which {what}", cur.name.name, base.name),
                    )
                    .at(base.span)
                    .with_primary_label("no such base")
                    .with_hint("name a FUNCTION_BLOCK declared in one of the files given (library blocks such as TON cannot be extended here)"),
                );
            }
            return None;
        };
        if seen.contains(&bkey) || chain.len() > MAX_DEPTH {
            let in_cycle = bkey == key || chain.len() > MAX_DEPTH;
            if in_cycle {
                let names: Vec<&str> = chain
                    .iter()
                    .map(|k| classes[k].name.name.as_str())
                    .collect();
                let first = &classes[key];
                diags.push(
                    Diagnostic::error(
                        code::E0331,
                        format!(
                            "`{}` extends itself through its bases: {} -> {}",
                            first.name.name,
                            names.join(" -> "),
                            b.name.name
                        ),
                    )
                    .at(first.oop.extends.first().map_or(first.name.span, |e| e.span))
                    .with_primary_label("the cycle starts here")
                    .with_hint("a chain of EXTENDS must end at a block that extends nothing; remove one EXTENDS of the cycle"),
                );
            }
            return None;
        }
        if b.oop.is_final {
            if own {
                diags.push(
                    Diagnostic::error(
                        code::E0332,
                        format!(
                            "`{}` EXTENDS `{}`, which is FINAL",
                            cur.name.name, b.name.name
                        ),
                    )
                    .at(base.span)
                    .with_primary_label("a FINAL block has no derived blocks")
                    .with_hint(format!(
                        "remove FINAL from `{}` or do not extend it",
                        b.name.name
                    )),
                );
            }
            return None;
        }
        seen.insert(bkey.clone());
        chain.push(bkey);
        cur = b;
    }
    chain.reverse();
    Some(chain)
}

/// The pending body of a class and its file, if it has one.
fn body_of<'p>(c: &Class, pending: &'p [PendingBody]) -> Option<&'p PendingBody> {
    c.pending.map(|k| &pending[k])
}

/// The hidden name of the version of method `m` defined at level `level` of a chain.
fn super_method(level: usize, m: &str) -> String {
    format!("__S{level:02}_{}", m.to_ascii_uppercase())
}

/// The hidden name of the body of level `level` of a chain, run by `SUPER^()`.
/// `__S<level>_`, the start of the hidden name of a method's version at `level` (two digits: a
/// chain is at most [`MAX_DEPTH`] long), as long as `SUPER.` (`SUPER^.` is one byte longer).
fn hidden_prefix(level: usize) -> String {
    format!("__S{level:02}_")
}

fn super_body(level: usize) -> String {
    format!("__B{level:03}")
}

/// The hidden action `SUPER^()` calls when the body of level `level` of a chain is SFC: one scan
/// of that level's chart in the derived block (as long as `SUPER^`).
pub fn super_chart(level: usize) -> String {
    format!("__C{level:03}")
}

/// Flattens one derived block (`chain`, root first, the block last) into `pb` and its POU.
fn flatten_one(
    units: &mut [CompilationUnit],
    pending: &[PendingBody],
    classes: &HashMap<String, Class>,
    chain: &[String],
    pb: &mut PendingBody,
    diags: &mut Diagnostics,
) {
    let levels: Vec<&Class> = chain.iter().map(|k| &classes[k]).collect();
    let n = levels.len() - 1;
    let me = levels[n];
    // variables: the bases' then the block's own; a name declared again is E0334 (a base's
    // VAR_TEMP may be declared again, as CODESYS allows: the block's own replaces it)
    let mut blocks: Vec<VarBlock> = Vec::new();
    let mut declared: HashMap<String, (VarKind, Span, String)> = HashMap::new();
    for (j, c) in levels.iter().enumerate() {
        for b in &c.vars {
            let mut nb = b.clone();
            nb.vars.retain(|v| {
                let key = v.name.key();
                match declared.get(&key) {
                    Some((kind, at, owner)) if *kind != VarKind::Temp => {
                        if j == n {
                            diags.push(
                                Diagnostic::error(
                                    code::E0334,
                                    format!(
                                        "`{}` declares `{}`, which its base `{owner}` declares already",
                                        me.name.name, v.name.name
                                    ),
                                )
                                .at(v.name.span)
                                .with_primary_label("declared again")
                                .with_label(*at, "the base's declaration")
                                .with_hint("a derived block has every variable of its bases: use the base's variable, or rename this one"),
                            );
                        }
                        false
                    }
                    _ => {
                        declared.insert(key, (b.kind, v.name.span, c.name.name.clone()));
                        true
                    }
                }
            });
            blocks.push(nb);
        }
    }
    // a base's VAR_TEMP declared again by a later level: the later declaration is kept
    let mut seen = HashSet::new();
    for b in blocks.iter_mut().rev() {
        b.vars.retain(|v| seen.insert(v.name.key()));
    }
    blocks.retain(|b| !b.vars.is_empty());
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        if let LibraryElement::Pou(p) = item {
            if p.name.span == me.name.span {
                p.var_blocks = blocks.clone();
            }
        }
    }
    // initial values computed at run time: the bases' then the block's own (each level's
    // variables are the derived block's too)
    pb.var_inits = levels
        .iter()
        .filter_map(|c| body_of(c, pending))
        .flat_map(|b| b.var_inits.iter().cloned())
        .collect();
    // methods: the version of each name at each level; the last is the block's
    let mut versions: HashMap<String, Vec<(usize, &PendingMethod, FileId)>> = HashMap::new();
    let mut order: Vec<String> = Vec::new();
    for (j, c) in levels.iter().enumerate() {
        if let Some(b) = body_of(c, pending) {
            for m in &b.methods {
                let key = m.name.key();
                if !versions.contains_key(&key) {
                    order.push(key.clone());
                }
                versions
                    .entry(key)
                    .or_default()
                    .push((j, m, m.name.span.file));
            }
        }
    }
    // a derived version with another signature than the one it overrides: E1084, the base's
    // kept (SIMATIC AX's overloading across inheritance, `super::override_signature`)
    let names: Vec<&Ident> = levels.iter().map(|c| &c.name).collect();
    let overloaded = super::override_signature::keep_base_signatures(&mut versions, &names, diags);
    let mut ctx = Rewrite {
        levels: &levels,
        versions: &versions,
        needed: Vec::new(),
        charts: Vec::new(),
    };
    let mut methods = Vec::new();
    let mut files = Vec::new();
    for key in &order {
        let Some(&(j, m, file)) = versions[key].last() else {
            continue;
        };
        let mut m = m.clone();
        if let Some(access) = overloaded.get(key) {
            m.overloaded = true;
            m.access = access.clone();
        }
        private_calls(file, &m.text, m.base, j, &ctx, diags);
        m.text = ctx.rewrite(file, &m.text, m.base, j, diags);
        methods.push(m);
        files.push(file);
    }
    let own_text = pb.text.clone();
    private_calls(pb.file, &own_text, pb.base, n, &ctx, diags);
    pb.text = ctx.rewrite(pb.file, &own_text, pb.base, n, diags);
    // FB_init: every base's version runs before the block's own, on the same instance (Beckhoff
    // "Behavior with derived function blocks", CODESYS "Method: FB_Init": the base's FB_init is
    // executed implicitly, then the derived block's), see `super::fb_init`
    if let Some(v) = versions.get("FB_INIT") {
        for &(j, _, _) in &v[..v.len().saturating_sub(1)] {
            ctx.needed.push(Hidden::Method(j, "FB_INIT".to_string()));
        }
    }
    // the hidden versions SUPER^ calls, and the versions and bodies they call in turn
    let mut done = HashSet::new();
    while let Some(h) = ctx.needed.pop() {
        if !done.insert(h.clone()) {
            continue;
        }
        match h {
            Hidden::Method(j, key) => {
                let Some(&(_, m, file)) = versions
                    .get(&key)
                    .and_then(|v| v.iter().find(|(l, _, _)| *l == j))
                else {
                    continue;
                };
                let mut m = m.clone();
                m.text = ctx.rewrite(file, &m.text, m.base, j, diags);
                // (the result keeps the method's name: the text assigns it so)
                m.name = Ident::new(super_method(j, &m.name.name), m.name.span);
                methods.push(m);
                files.push(file);
            }
            Hidden::Body(j) => {
                let c = levels[j];
                let (file, text, base) = match body_of(c, pending) {
                    Some(b) => (b.file, b.text.clone(), b.base),
                    None => (c.name.span.file, String::new(), c.name.span.end as usize),
                };
                let text = ctx.rewrite(file, &text, base, j, diags);
                methods.push(PendingMethod {
                    name: Ident::new(super_body(j), c.name.span),
                    ret: None,
                    blocks: Vec::new(),
                    text,
                    base,
                    inst: Vec::new(),
                    once: Vec::new(),
                    local_inits: Vec::new(),
                    overloaded: false,
                    access: None,
                });
                files.push(file);
            }
        }
    }
    // actions: the block's own, then its bases' of other names
    let mut actions = pb.actions.clone();
    for c in levels[..n].iter().rev() {
        if let Some(b) = body_of(c, pending) {
            for a in &b.actions {
                if !actions.iter().any(|x| x.0.key() == a.0.key()) {
                    actions.push(a.clone());
                }
            }
        }
    }
    pb.actions = actions;
    pb.methods = methods;
    if let Some(Oop::Block(b)) = pb.oop.as_deref_mut() {
        b.method_files = files;
        let mut charts = std::mem::take(&mut ctx.charts);
        charts.sort();
        charts.dedup();
        b.super_charts = charts
            .into_iter()
            .map(|j| (super_chart(j), levels[j].name.name.clone()))
            .collect();
    }
}

/// A hidden method [`flatten_one`] must add: a level's version of a method, or a level's body.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
enum Hidden {
    Method(usize, String),
    Body(usize),
}

/// Rewrites `SUPER^.M` and `SUPER^()` in the texts of one chain.
struct Rewrite<'a> {
    levels: &'a [&'a Class],
    versions: &'a HashMap<String, Vec<(usize, &'a PendingMethod, FileId)>>,
    needed: Vec<Hidden>,
    /// The levels whose chart `SUPER^()` runs.
    charts: Vec<usize>,
}

impl Rewrite<'_> {
    /// `text` (at `base` in `file`), written at level `level` of the chain, with `SUPER^.M` written
    /// as the name of the version of `M` visible at `level - 1` (`M` itself when that is the
    /// block's version: blanks before it), `SUPER^.x` of a variable as `x`, `SUPER^()` as the
    /// hidden method of the body of `level - 1`, and `SUPER^` alone (a value) as `THIS^`. Same
    /// length, same line breaks.
    fn rewrite(
        &mut self,
        file: FileId,
        text: &str,
        base: usize,
        level: usize,
        diags: &mut Diagnostics,
    ) -> String {
        let (toks, _) = lex(text);
        let mut out = text.to_string();
        let word = |k: usize| {
            toks.get(k)
                .and_then(|t| text.get(t.range.clone()))
                .unwrap_or("")
        };
        let adjacent = |a: usize, b: usize| matches!((toks.get(a), toks.get(b)), (Some(x), Some(y)) if x.range.end == y.range.start);
        for k in 0..toks.len() {
            if toks[k].tok != Tok::Ident || !word(k).eq_ignore_ascii_case("SUPER") {
                continue;
            }
            // `SUPER.M(...)`, `SUPER.x`: edition 3's spelling (6.6.5, SIMATIC AX) of `SUPER^.M`
            // in a derived block, read so
            let dotted = level > 0
                && toks.get(k + 1).is_some_and(|t| t.tok == Tok::Dot)
                && adjacent(k, k + 1)
                && toks.get(k + 2).is_some_and(|t| t.tok == Tok::Ident)
                && adjacent(k + 1, k + 2);
            if dotted {
                let name = word(k + 2).to_ascii_uppercase();
                let start = toks[k].range.start;
                let visible = self.versions.get(&name).and_then(|v| {
                    let last = v.last()?.0;
                    let at = v.iter().rev().find(|(l, _, _)| *l < level)?.0;
                    Some((at, last))
                });
                match visible {
                    Some((at, last)) if at != last => {
                        self.needed.push(Hidden::Method(at, name.clone()));
                        out.replace_range(start..toks[k + 1].range.end, &hidden_prefix(at));
                    }
                    // the block's own version, or a variable of a base (the block has it)
                    _ => out.replace_range(start..toks[k + 1].range.end, "      "),
                }
                continue;
            }
            if toks.get(k + 1).map(|t| &t.tok) != Some(&Tok::Caret) || !adjacent(k, k + 1) {
                continue;
            }
            let at = Span::new(
                file,
                base + toks[k].range.start,
                base + toks[k + 1].range.end,
            );
            if level == 0 {
                // the root's own SUPER^: E0108 when its text is parsed
                continue;
            }
            let parent = level - 1;
            match toks.get(k + 2).map(|t| &t.tok) {
                Some(Tok::Dot)
                    if adjacent(k + 1, k + 2)
                        && toks.get(k + 3).is_some_and(|t| t.tok == Tok::Ident)
                        && adjacent(k + 2, k + 3) =>
                {
                    let name = word(k + 3).to_ascii_uppercase();
                    let prefix = toks[k].range.start..toks[k + 2].range.end;
                    let visible = self.versions.get(&name).and_then(|v| {
                        let last = v.last()?.0;
                        let at = v.iter().rev().find(|(l, _, _)| *l <= parent)?.0;
                        Some((at, last))
                    });
                    let replacement = match visible {
                        Some((at, last)) if at != last => {
                            self.needed.push(Hidden::Method(at, name.clone()));
                            format!(" {}", hidden_prefix(at))
                        }
                        // the block's own version, or a variable of a base (the block has it)
                        _ => "       ".to_string(),
                    };
                    out.replace_range(prefix, &replacement);
                }
                Some(Tok::LParen) => {
                    let base = self.levels[parent];
                    if base.sfc_body {
                        // a chart: one scan of the base's chart per call, its steps in the
                        // instance (Beckhoff infosys "SUPER": `SUPER^()` runs the base's body);
                        // the call of the hidden action is replaced by that scan when the
                        // charts are lowered (ladderc's `lower_textual_sfc`)
                        out.replace_range(
                            toks[k].range.start..toks[k + 1].range.end,
                            &super_chart(parent),
                        );
                        self.charts.push(parent);
                        continue;
                    }
                    if base.il_body {
                        diags.push(
                            Diagnostic::error(
                                code::E0303,
                                format!(
                                    "SUPER^() runs the body of `{}`, which is instruction list: not supported",
                                    base.name.name
                                ),
                            )
                            .at(at)
                            .with_primary_label("the base's body is IL")
                            .with_hint("write the base's body in Structured Text"),
                        );
                        // the call is left out (blanked up to its `)`, so that positions stay):
                        // one error, no E0108 for the `SUPER^` left behind
                        let mut depth = 0usize;
                        let close = toks[k + 2..].iter().position(|t| {
                            match t.tok {
                                Tok::LParen => depth += 1,
                                Tok::RParen => depth = depth.saturating_sub(1),
                                _ => {}
                            }
                            depth == 0
                        });
                        if let Some(m) = close.map(|m| k + 2 + m) {
                            let range = toks[k].range.start..toks[m].range.end;
                            let blanked: String = out
                                .get(range.clone())
                                .unwrap_or("")
                                .chars()
                                .map(|c| if c == '\n' || c == '\r' { c } else { ' ' })
                                .collect();
                            if blanked.len() == range.len() {
                                out.replace_range(range, &blanked);
                            }
                        }
                        continue;
                    }
                    self.needed.push(Hidden::Body(parent));
                    out.replace_range(
                        toks[k].range.start..toks[k + 1].range.end,
                        &super_body(parent),
                    );
                }
                // `SUPER^` as a value (`itf := SUPER^;`, an argument): the instance itself, seen
                // as its base; an interface call through it dispatches on the instance, as
                // through THIS^ (purushothaman2310/IEC61131-OOPS-TwiCAT)
                _ => out.replace_range(toks[k].range.start..toks[k + 1].range.end, "THIS^ "),
            }
        }
        out
    }
}

/// A comparable text of a declared type: its name, or its kind and bounds.
fn type_key(t: &TypeRef) -> String {
    match t {
        TypeRef::Named(i) => i.key(),
        // (also shown in messages: the IEC spelling, `STRING(80)`, `WSTRING`)
        TypeRef::String { wide, length, .. } => {
            let s = if *wide { "WSTRING" } else { "STRING" };
            match length {
                Some(n) => format!("{s}({n})"),
                None => s.to_string(),
            }
        }
        TypeRef::Array { dims, element, .. } => {
            let d: Vec<String> = dims
                .iter()
                .map(|d| format!("{}..{}", d.lower, d.upper))
                .collect();
            format!("ARRAY[{}] OF {}", d.join(","), type_key(element))
        }
        TypeRef::Subrange {
            base, lower, upper, ..
        } => format!("{}({lower}..{upper})", base.key()),
        TypeRef::Enum { values, .. } => {
            let v: Vec<String> = values
                .iter()
                .map(|v| match v.value {
                    Some(n) => format!("{}:={n}", v.name.key()),
                    None => v.name.key(),
                })
                .collect();
            format!("({})", v.join(","))
        }
        TypeRef::Ref { kind, target, .. } => format!("{} {}", kind.keyword(), type_key(target)),
    }
}

/// A method's signature as a text: result type, then each input and output with its type.
pub(super) fn signature(m: &PendingMethod) -> String {
    let mut s = m.ret.as_ref().map_or("-".to_string(), |r| type_key(&r.ty));
    for kind in [VarKind::Input, VarKind::Output, VarKind::InOut] {
        for b in m.blocks.iter().filter(|b| b.kind == kind) {
            for v in &b.vars {
                s.push_str(&format!(" {kind:?}:{}:{}", v.name.key(), type_key(&v.ty)));
            }
        }
    }
    s
}

/// A method's signature for a message: `M(a : INT, VAR_OUTPUT q : BOOL) : BOOL`; a variable-length in-out as written
/// (`a : ARRAY[*] OF LREAL`), not as its hidden inputs (`varlen`), and an ANY input likewise
/// (`In : ANY_NUM`, not `any_inputs`' hidden inputs).
pub(super) fn shown(m: &PendingMethod) -> String {
    let mut ins: Vec<String> = Vec::new();
    for v in m
        .blocks
        .iter()
        .filter(|b| b.kind == VarKind::Input)
        .flat_map(|b| b.vars.iter())
    {
        let up = v.name.name.to_ascii_uppercase();
        let hidden = |suffix: &str| {
            up.rfind(suffix).is_some_and(|k| {
                let d = &up[k + suffix.len()..];
                k > 0 && !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit())
            })
        };
        if hidden(super::varlen::LOWER) || hidden(super::varlen::UPPER) {
            continue;
        }
        // an ANY input as written (`Value : ANY`), not its hidden inputs (`any_inputs`: before
        // round 30, `Value__DISIZE : DINT, Value__TYPECLASS_ANY : INT, Value__PVALUE : ...`)
        match super::any_inputs::written_input(&v.name.name) {
            Some(Some((name, generic))) => {
                ins.push(format!("{name} : {generic}"));
                continue;
            }
            Some(None) => continue,
            None => {}
        }
        match (up.strip_suffix(super::varlen::ADDRESS), &v.ty) {
            (Some(base), TypeRef::Ref { target, .. }) if !base.is_empty() => {
                let rank = m
                    .blocks
                    .iter()
                    .flat_map(|b| b.vars.iter())
                    .filter(|w| {
                        let w = w.name.name.to_ascii_uppercase();
                        w.strip_prefix(base)
                            .and_then(|r| r.strip_prefix(super::varlen::LOWER))
                            .is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
                    })
                    .count()
                    .max(1);
                ins.push(format!(
                    "{} : ARRAY[{}] OF {}",
                    &v.name.name[..base.len()],
                    vec!["*"; rank].join(", "),
                    type_key(target)
                ));
            }
            _ => ins.push(format!("{} : {}", v.name.name, type_key(&v.ty))),
        }
    }
    // the outputs and in-outs too (IEC 61131-3 ed. 3, 6.6.5: they are part of the signature the
    // implementing method repeats), so that two signatures that differ only there read differently
    for (kind, keyword) in [
        (VarKind::Output, "VAR_OUTPUT"),
        (VarKind::InOut, "VAR_IN_OUT"),
    ] {
        for v in m
            .blocks
            .iter()
            .filter(|b| b.kind == kind)
            .flat_map(|b| b.vars.iter())
        {
            ins.push(format!("{keyword} {} : {}", v.name.name, type_key(&v.ty)));
        }
    }
    let ret = m
        .ret
        .as_ref()
        .map_or(String::new(), |r| format!(" : {}", type_key(&r.ty)));
    format!("{}({}){ret}", m.name.name, ins.join(", "))
}

/// Checks that block `c` (its methods, inherited ones included) has every method of interface
/// `itf` and of the interfaces it extends, with the same signature; `seen`: the interfaces
/// already checked for the block (not checked again).
fn check_implements(
    c: &Class,
    itf: &Ident,
    methods: &[&PendingMethod],
    interfaces: &HashMap<String, &InterfaceOop>,
    seen: &mut HashSet<String>,
    diags: &mut Diagnostics,
) {
    let mut todo = vec![itf.key()];
    let mut depth = 0;
    while let Some(key) = todo.pop() {
        depth += 1;
        if !seen.insert(key.clone()) || depth > MAX_DEPTH {
            continue;
        }
        let Some(i) = interfaces.get(&key) else {
            if key == itf.key() {
                diags.push(
                    Diagnostic::error(
                        code::E0330,
                        format!(
                            "`{}` IMPLEMENTS `{}`, which names no INTERFACE of the project",
                            c.name.name, itf.name
                        ),
                    )
                    .at(itf.span)
                    .with_primary_label("no such interface")
                    .with_hint("name an INTERFACE declared in one of the files given (`.st` INTERFACE ... END_INTERFACE, TwinCAT `.TcIO`)"),
                );
            }
            continue;
        };
        todo.extend(i.extends.iter().map(Ident::key));
        for m in &i.methods {
            // the interface's method with its variable-length in-outs split as the block's
            // methods are (`varlen`): `a : ARRAY[*] OF T` is then the same on both sides
            let mut split = m.clone();
            let m = if super::varlen::split_blocks(&mut split.blocks) {
                &split
            } else {
                m
            };
            match methods.iter().find(|x| x.name.key() == m.name.key()) {
                // a property the interface declares (its accessor `__GET_P` / `__SET_P`)
                None if super::property::is_accessor(&m.name.name) => {
                    let upper = m.name.name.to_ascii_uppercase();
                    let (kind, prop) = match upper.strip_prefix(super::property::GET_PREFIX) {
                        Some(_) => ("Get", &m.name.name[super::property::GET_PREFIX.len()..]),
                        None => ("Set", &m.name.name[super::property::SET_PREFIX.len()..]),
                    };
                    // the property's name as written: the getter's result, the setter's input
                    let written = m.ret.as_ref().map(|r| r.name.name.as_str()).or_else(|| {
                        let first = m.blocks.first()?.vars.first()?;
                        Some(first.name.name.as_str())
                    });
                    let prop = written.unwrap_or(prop);
                    let what = format!("{kind} accessor for property `{prop}`");
                    diags.push(
                        Diagnostic::error(
                            code::E0335,
                            format!(
                                "`{}` IMPLEMENTS `{}` but has no {what}",
                                c.name.name, i.name.name
                            ),
                        )
                        .at(itf.span)
                        .with_primary_label("property accessor missing")
                        .with_label(m.name.span, "declared by the interface here")
                        .with_hint(format!(
                            "add the PROPERTY with that accessor (GET ... END_GET / SET ... END_SET) to `{}` (or to a block it extends)",
                            c.name.name
                        )),
                    )
                }
                None => diags.push(
                    Diagnostic::error(
                        code::E0335,
                        format!(
                            "`{}` IMPLEMENTS `{}` but has no method `{}`",
                            c.name.name, i.name.name, m.name.name
                        ),
                    )
                    .at(itf.span)
                    .with_primary_label(format!("`{}` missing", shown(m)))
                    .with_label(m.name.span, "declared by the interface here")
                    .with_hint(format!(
                        "add `METHOD {}` to `{}` (or to a block it extends)",
                        shown(m),
                        c.name.name
                    )),
                ),
                // (one overload of several, E1084: the interface may declare another one)
                Some(x) if x.overloaded => {}
                Some(x) if signature(x) != signature(m) => diags.push(
                    Diagnostic::error(
                        code::E0335,
                        format!(
                            "method `{}` of `{}` is `{}`, but interface `{}` declares `{}`",
                            m.name.name,
                            c.name.name,
                            shown(x),
                            i.name.name,
                            shown(m)
                        ),
                    )
                    .at(x.name.span)
                    .with_primary_label("another signature")
                    .with_label(m.name.span, "the interface's method")
                    .with_hint("give the method the interface's result type and the same inputs and outputs, in the same order, with the same types"),
                ),
                Some(_) => {}
            }
        }
    }
}

/// The elements of an array initialiser of an ARRAY OF an interface, at most `len` of them, repeat
/// counts expanded: each an instance (`Some`) or `0`/`NULL` (`None`, unassigned). `None` when an
/// element is anything else, or there are more than `len`.
fn array_of_instances(
    elems: &[crate::ast::ArrayInitElement],
    len: i128,
) -> Option<Vec<Option<&crate::ast::VarRef>>> {
    use crate::ast::{Initializer, LiteralKind, Operand};
    let mut out = Vec::new();
    for e in elems {
        let one = match &e.value {
            Initializer::Value(Operand::Literal(l)) if matches!(l.kind, LiteralKind::Int(0)) => {
                None
            }
            Initializer::Value(Operand::Var(v)) if v.base.is("NULL") => None,
            Initializer::Value(Operand::Var(v)) => Some(v),
            _ => return None,
        };
        for _ in 0..e.repeat.unwrap_or(1) {
            if out.len() as i128 >= len {
                return None;
            }
            out.push(one);
        }
    }
    Some(out)
}

/// Variables whose type is an ABSTRACT block (E0333: not compiled), and the initial values of
/// variables of an interface type: `:= 0` is left out (an interface starts unassigned), `:= inst`
/// (or `:= [inst1, 0, inst2]` for a one-dimensional array) is returned: a POU's assigned when the
/// POU first runs, a VAR_GLOBAL's once before the first cycle (round 29, before: E0336); any
/// other is E0336 (the value is left out).
fn check_instances(
    units: &mut [CompilationUnit],
    classes: &HashMap<String, Class>,
    interfaces: &HashMap<String, &InterfaceOop>,
    diags: &mut Diagnostics,
) -> Vec<super::interface_vars::Init> {
    use crate::ast::{Initializer, Operand};
    fn named(t: &TypeRef) -> Option<&Ident> {
        match t {
            TypeRef::Named(i) => Some(i),
            TypeRef::Array { element, .. } => named(element),
            _ => None,
        }
    }
    let mut inits = Vec::new();
    let mut check = |v: &mut crate::ast::VarDecl, pou: Option<Span>, diags: &mut Diagnostics| {
        let Some(ty) = named(&v.ty) else { return };
        if let Some(c) = classes.get(&ty.key()).filter(|c| c.oop.is_abstract) {
            diags.push(
                Diagnostic::error(
                    code::E0333,
                    format!("`{}` is an instance of `{}`, which is ABSTRACT", v.name.name, c.name.name),
                )
                .at(ty.span)
                .with_primary_label("an ABSTRACT block has no instances")
                .with_hint(format!("declare an instance of a block that EXTENDS `{}` and implements its abstract methods", c.name.name)),
            );
            return;
        }
        let Some(i) = interfaces.get(&ty.key()) else {
            return;
        };
        let Some(init) = v.init.take() else { return };
        match (&init, pou, &v.ty) {
            (Initializer::Value(Operand::Literal(l)), _, _)
                if matches!(l.kind, crate::ast::LiteralKind::Int(0)) => {}
            (Initializer::Value(Operand::Var(value)), pou, TypeRef::Named(_))
                if !value.base.is("NULL") =>
            {
                inits.push(super::interface_vars::Init {
                    pou,
                    var: v.name.clone(),
                    index: None,
                    value: value.clone(),
                });
            }
            (Initializer::Value(Operand::Var(value)), _, _) if value.base.is("NULL") => {}
            // `LampCtrl : ARRAY[0..1] OF I_LampCtrl := [fbLamp1, fbLamp2];` (TwinCAT): element
            // by element, from the first index; `0`/`NULL` elements start unassigned
            (Initializer::Array(elems, _), pou, TypeRef::Array { dims, .. })
                if dims.len() == 1
                    && array_of_instances(elems, dims[0].upper - dims[0].lower + 1).is_some() =>
            {
                let values = array_of_instances(elems, dims[0].upper - dims[0].lower + 1);
                for (k, value) in values.into_iter().flatten().enumerate() {
                    if let Some(value) = value {
                        inits.push(super::interface_vars::Init {
                            pou,
                            var: v.name.clone(),
                            index: Some(dims[0].lower + k as i128),
                            value: value.clone(),
                        });
                    }
                }
            }
            _ => diags.push(
                Diagnostic::error(
                    code::E0336,
                    format!(
                        "`{}` of interface type `{}` has an initial value that is not compiled",
                        v.name.name, i.name.name
                    ),
                )
                .at(v.span)
                .with_primary_label("only `:= 0`, `:= instance` or `:= [instance, 0, ...]`")
                .with_hint(format!(
                    "assign it in the body (`{} := fbInstance;`)",
                    v.name.name
                )),
            ),
        }
    };
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        match item {
            LibraryElement::Pou(p) => {
                let pou = p.name.span;
                for b in p.var_blocks.iter_mut() {
                    for v in b.vars.iter_mut() {
                        check(v, Some(pou), diags);
                    }
                }
            }
            LibraryElement::GlobalVars(b) => {
                for v in b.vars.iter_mut() {
                    check(v, None, diags);
                }
            }
            _ => {}
        }
    }
    inits
}
