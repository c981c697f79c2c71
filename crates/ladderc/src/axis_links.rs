//! Which simulated axis each `AXIS_REF` of the program is: TwinCAT's link between a PLC axis
//! variable and an NC axis, read from the axes file.
//!
//! Input: the user's parsed units (before the semantic checks) and the axis configuration.
//! Output: every `AXIS_REF` instance of the program (a global, a program's variable, a field of a
//! function block instance or structure, an array element, at any depth) initialised with the
//! `AxisNo` of the axis it is linked to; the configuration's `declared_by_program` set for the
//! axes whose global the program declares itself; one located E1056 per declaration whose
//! `AXIS_REF`s have no axis, one E1057 per `"link"` that names no `AXIS_REF` of the program.
//! Invariants: two instances are never silently the same axis; only `VAR`, `VAR_GLOBAL` and
//! `VAR_OUTPUT` variables are instances (`VAR_IN_OUT`, `VAR_EXTERNAL`, references and pointers
//! name one, a `VAR_INPUT` is a copy its caller writes; a function block's or program's
//! `VAR_OUTPUT` is storage of the instance that only the block writes, as Beckhoff's XTS sample
//! `Mover` declares `AxisReference : AXIS_REF` "left as output so the link can be made
//! directly"); an instance whose declaration
//! already gives `AxisNo` keeps it, one located `AT` an address takes it from the I/O (as
//! Beremiz's EtherCAT motion does); an `AXIS_REF` whose name no body of the program uses (a field
//! of an HMI structure that only mirrors an axis) is no axis unless a `"link"` names it: it needs
//! no link (no E1056), but a link to it is valid (TwinCAT's System Manager links a declared
//! `AXIS_REF` before any logic reads it), and it then is that axis.
//!
//! The link, as TwinCAT's System Manager keeps it for an NC axis, is one of (in this order):
//! the axis's `"link"` key, the instance path (`GVL_Axes.Axis1`, `Axis1` for a global,
//! `MAIN.fbStation.Axis`, `MAIN.aAxes[2]`); a global `AXIS_REF` named like the axis; a program's
//! `AXIS_REF` named like the axis when no other declaration has its name; and, when
//! the axes file has one axis and the program one `AXIS_REF` instance, those two (there is
//! nothing to choose). Anything else is E1056: a demanding user wants to hear that an axis is
//! missing rather than find two axes of the machine moving as one.

use crate::axes::AxisConfig;
use diagnostics::{code, Diagnostic, Diagnostics};
use il_frontend::ast::{
    Accessor, ArrayInitElement, CallArgs, CompilationUnit, Ident, IlStmt, Initializer, InstrKind,
    LibraryElement, Literal, LiteralKind, Op, Operand, PouKind, TypeDef, TypeRef, VarDecl, VarKind,
    VarRef,
};
use il_frontend::Span;
use std::collections::{HashMap, HashSet};

/// Where the `AXIS_REF`s are inside a declared type.
#[derive(Clone)]
enum Shape {
    /// An `AXIS_REF`.
    Axis,
    /// A function block or structure: its fields that hold `AXIS_REF`s.
    Fields(Vec<(Ident, Shape)>),
    /// An array: its element count (row-major over all dimensions), the first index of each
    /// dimension with its length, and the element.
    Array(Vec<(i128, usize)>, Box<Shape>),
}

/// One `AXIS_REF` instance: its path and how to reach it from the outermost declaration.
struct Leaf {
    path: String,
    steps: Vec<Step>,
    /// A body of the program names it: it needs an axis (E1056 without one). An unused one is an
    /// axis only when a `"link"` names it.
    used: bool,
}

#[derive(Clone)]
enum Step {
    Field(Ident),
    Index(usize),
}

/// The user types that may hold `AXIS_REF`s: function blocks and structures, upper case.
struct Types<'a> {
    fbs: HashMap<String, Vec<&'a VarDecl>>,
}

impl<'a> Types<'a> {
    fn new(units: &'a [CompilationUnit]) -> Self {
        let mut fbs: HashMap<String, Vec<&VarDecl>> = HashMap::new();
        for item in units.iter().flat_map(|u| u.items.iter()) {
            match item {
                LibraryElement::Pou(p) if p.kind == PouKind::FunctionBlock => {
                    let vars = p
                        .var_blocks
                        .iter()
                        .filter(|b| instance_kind(b.kind))
                        .flat_map(|b| b.vars.iter())
                        .collect();
                    fbs.insert(p.name.key(), vars);
                }
                LibraryElement::DataTypes(ts) => {
                    for t in ts {
                        if let TypeDef::Struct { fields } = &t.def {
                            fbs.insert(t.name.key(), fields.iter().collect());
                        }
                    }
                }
                _ => {}
            }
        }
        Types { fbs }
    }

    fn shape(&self, ty: &TypeRef, depth: usize) -> Option<Shape> {
        if depth > 32 {
            return None;
        }
        match ty {
            TypeRef::Named(t) if t.is("AXIS_REF") => Some(Shape::Axis),
            TypeRef::Named(t) => {
                let fields = self.fbs.get(&t.key())?;
                let inner: Vec<(Ident, Shape)> = fields
                    .iter()
                    .filter_map(|v| Some((v.name.clone(), self.shape(&v.ty, depth + 1)?)))
                    .collect();
                (!inner.is_empty()).then_some(Shape::Fields(inner))
            }
            TypeRef::Array { dims, element, .. } => {
                let elem = self.shape(element, depth + 1)?;
                // (bounds as written: any i128, so every step is checked)
                let dims: Vec<(i128, usize)> = dims
                    .iter()
                    .map(|d| {
                        let len = d.upper.checked_sub(d.lower).and_then(|n| n.checked_add(1));
                        (
                            d.lower,
                            len.and_then(|n| usize::try_from(n).ok()).unwrap_or(0),
                        )
                    })
                    .collect();
                let count = dims
                    .iter()
                    .try_fold(1usize, |n, d| n.checked_mul(d.1))
                    .unwrap_or(0);
                (count > 0 && count <= 4096).then(|| Shape::Array(dims, Box::new(elem)))
            }
            _ => None,
        }
    }
}

/// Variables that are instances of their type: `VAR`, `VAR_GLOBAL` and `VAR_OUTPUT` (a
/// function block's or program's output is static storage of its instance, readable from outside
/// (IEC 61131-3 ed. 3, 6.5.2.2) and written only by the block; a `VAR_INPUT` `AXIS_REF` is a copy
/// its caller writes at each call, `VAR_IN_OUT` and `VAR_EXTERNAL` name another variable,
/// `VAR_TEMP` lives for one call).
fn instance_kind(k: VarKind) -> bool {
    matches!(k, VarKind::Local | VarKind::Global | VarKind::Output)
}

/// How many `AXIS_REF`s a shape holds (saturating).
fn count(shape: &Shape) -> usize {
    match shape {
        Shape::Axis => 1,
        Shape::Fields(fs) => fs
            .iter()
            .fold(0usize, |n, (_, s)| n.saturating_add(count(s))),
        Shape::Array(dims, elem) => dims
            .iter()
            .fold(1usize, |n, d| n.saturating_mul(d.1))
            .saturating_mul(count(elem)),
    }
}

/// The most `AXIS_REF`s one declaration may hold (a machine has far fewer axes; a hostile
/// declaration of nested arrays is not enumerated).
const MOST_AXES: usize = 4096;

fn leaves(shape: &Shape, path: &str, steps: &mut Vec<Step>, out: &mut Vec<Leaf>) {
    match shape {
        Shape::Axis => out.push(Leaf {
            path: path.to_string(),
            steps: steps.clone(),
            used: false,
        }),
        Shape::Fields(fs) => {
            for (name, s) in fs {
                steps.push(Step::Field(name.clone()));
                leaves(s, &format!("{path}.{}", name.name), steps, out);
                steps.pop();
            }
        }
        Shape::Array(dims, elem) => {
            let count: usize = dims.iter().map(|d| d.1).product();
            for k in 0..count {
                let mut rest = k;
                let mut idx = Vec::new();
                for (lower, len) in dims.iter().rev() {
                    idx.push(lower.saturating_add((rest % len) as i128));
                    rest /= len;
                }
                idx.reverse();
                let idx: Vec<String> = idx.iter().map(|i| i.to_string()).collect();
                steps.push(Step::Index(k));
                leaves(elem, &format!("{path}[{}]", idx.join(",")), steps, out);
                steps.pop();
            }
        }
    }
}

/// One outermost declaration holding `AXIS_REF`s.
struct Root {
    /// (unit, item, block, var) of the declaration.
    at: (usize, usize, usize, usize),
    name: Ident,
    /// Its paths: the qualified one first, then the short one of a global (`Axis1`).
    prefixes: Vec<String>,
    global: bool,
    leaves: Vec<Leaf>,
}

/// Every name the program's bodies use: variables, fields and pins (upper case).
fn used_names(units: &[CompilationUnit]) -> HashSet<String> {
    fn var(v: &VarRef, out: &mut HashSet<String>) {
        out.insert(v.base.key());
        for a in v.accessors.iter() {
            match a {
                Accessor::Field(f) => {
                    out.insert(f.key());
                }
                Accessor::Index(ops) => ops.iter().for_each(|o| operand(o, out)),
                Accessor::Deref(_) => {}
            }
        }
    }
    fn operand(o: &Operand, out: &mut HashSet<String>) {
        if let Operand::Var(v) = o {
            var(v, out);
        }
    }
    fn args(a: &CallArgs, out: &mut HashSet<String>) {
        match a {
            CallArgs::Formal(list) => list.iter().for_each(|a| operand(&a.value, out)),
            CallArgs::NonFormal(ops) => ops.iter().for_each(|o| operand(o, out)),
            CallArgs::None => {}
        }
    }
    fn body(b: &[IlStmt], out: &mut HashSet<String>) {
        for s in b {
            let IlStmt::Instr(i) = s else { continue };
            match &i.kind {
                // `stHMI_Out.stYRef := Y_Ref`: the target is a copy of an axis, not an axis
                InstrKind::Simple {
                    op: Op::St,
                    operand: Some(Operand::Var(v)),
                    ..
                } => {
                    let mut v = v.clone();
                    let mut rest = v.accessors.to_vec();
                    if matches!(rest.last(), Some(Accessor::Field(_))) {
                        rest.pop();
                        v.accessors = rest.into();
                        var(&v, out);
                    }
                }
                InstrKind::Simple {
                    operand: Some(o), ..
                } => operand(o, out),
                InstrKind::Deferred {
                    operand: o,
                    body: b,
                    ..
                } => {
                    if let Some(o) = o {
                        operand(o, out);
                    }
                    body(b, out);
                }
                InstrKind::Call {
                    instance, args: a, ..
                } => {
                    var(instance, out);
                    args(a, out);
                }
                InstrKind::FunctionCall { args: a, .. } => args(a, out),
                InstrKind::FbInput { instance, .. } => var(instance, out),
                _ => {}
            }
        }
    }
    let mut out = HashSet::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        match item {
            LibraryElement::Pou(p) => body(&p.body, &mut out),
            LibraryElement::Action(a) => body(&a.body, &mut out),
            _ => {}
        }
    }
    out
}

/// The name a leaf is written with last: `MAIN.fbStation.Axis` -> `AXIS`, `MAIN.aAxes[2]` -> `AAXES`.
fn last_name(path: &str) -> String {
    let end = path.find('[').map_or(path, |i| &path[..i]);
    let end = if path.ends_with(']') {
        // an element: the array's name, before its subscript
        &path[..path.rfind('[').unwrap_or(path.len())]
    } else {
        end
    };
    end.rsplit('.').next().unwrap_or(end).to_ascii_uppercase()
}

/// Links the program's `AXIS_REF` instances to the axes of `axes` (see the module header).
pub fn link(units: &mut [CompilationUnit], axes: &mut AxisConfig, diags: &mut Diagnostics) {
    let mut roots = Vec::new();
    let used = used_names(units);
    {
        let types = Types::new(units);
        for (u, unit) in units.iter().enumerate() {
            for (i, item) in unit.items.iter().enumerate() {
                let (blocks, prefix, global) = match item {
                    LibraryElement::GlobalVars(b) => (
                        std::slice::from_ref(b),
                        b.name.as_ref().map(|n| n.name.clone()),
                        true,
                    ),
                    LibraryElement::Pou(p) if p.kind == PouKind::Program => {
                        (p.var_blocks.as_slice(), Some(p.name.name.clone()), false)
                    }
                    _ => continue,
                };
                for (b, block) in blocks.iter().enumerate() {
                    if !instance_kind(block.kind) {
                        continue;
                    }
                    for (v, var) in block.vars.iter().enumerate() {
                        // `Axis AT %IW0.0.3.402 : AXIS_REF` (Beremiz's EtherCAT motion): the I/O
                        // gives it its AxisNo
                        if var.location.is_some() {
                            continue;
                        }
                        let Some(shape) = types.shape(&var.ty, 0).filter(|s| count(s) <= MOST_AXES)
                        else {
                            continue;
                        };
                        let mut prefixes = Vec::new();
                        if let Some(p) = &prefix {
                            prefixes.push(format!("{p}.{}", var.name.name));
                        }
                        if global {
                            prefixes.push(var.name.name.clone());
                        }
                        let mut out = Vec::new();
                        leaves(&shape, &prefixes[0], &mut Vec::new(), &mut out);
                        // an `AxisNo` written in the declaration is the user's own link; an
                        // AXIS_REF the program never names needs no axis (a structure's copy of
                        // one), but a `"link"` may still name it
                        out.retain(|l| !gives_axis_no(var.init.as_ref(), &l.steps));
                        for l in out.iter_mut() {
                            l.used = used.contains(&last_name(&l.path));
                        }
                        if !out.is_empty() {
                            roots.push(Root {
                                at: (u, i, b, v),
                                name: var.name.clone(),
                                prefixes,
                                global,
                                leaves: out,
                            });
                        }
                    }
                }
            }
        }
    }
    // every path by which a link may name a leaf: (root, leaf)
    let short = |r: &Root, l: &Leaf| -> Vec<String> {
        r.prefixes
            .iter()
            .map(|p| format!("{p}{}", &l.path[r.prefixes[0].len()..]).to_ascii_uppercase())
            .collect()
    };
    let mut chosen: HashMap<(usize, usize), usize> = HashMap::new();
    let mut taken = vec![false; axes.axes.len()];
    for (k, axis) in axes.axes.iter().enumerate() {
        let Some((link, at)) = &axis.link else {
            continue;
        };
        let want = link.trim().to_ascii_uppercase();
        let found = roots.iter().enumerate().find_map(|(r, root)| {
            root.leaves
                .iter()
                .position(|l| short(root, l).contains(&want))
                .map(|l| (r, l))
        });
        match found {
            Some(key) if !chosen.contains_key(&key) => {
                chosen.insert(key, k);
                taken[k] = true;
            }
            Some(_) => diags.push(
                Diagnostic::error(
                    code::E1057,
                    format!(
                        "axis `{}` links `{link}`, which another axis already links",
                        axis.name
                    ),
                )
                .at(*at)
                .with_hint("each AXIS_REF of the program is one axis of the machine: link it once"),
            ),
            None => diags.push(
                Diagnostic::error(
                    code::E1057,
                    format!(
                        "axis `{}` links `{link}`, which is no AXIS_REF of the program",
                        axis.name
                    ),
                )
                .at(*at)
                .with_hint(
                    "write the instance path of an AXIS_REF: `GVL_Axes.Axis1`, `MAIN.Axis`, \
                     `MAIN.fbStation.Axis`, `MAIN.aAxes[2]` (see `ladderc explain E1057`)",
                ),
            ),
        }
    }
    // a global AXIS_REF named like an axis is that axis (the axes file then declares no global)
    for (r, root) in roots.iter().enumerate() {
        if !root.global
            || root.leaves.len() != 1
            || !root.leaves[0].steps.is_empty()
            || !root.leaves[0].used
        {
            continue;
        }
        let Some(k) = axes
            .axes
            .iter()
            .position(|a| a.name.eq_ignore_ascii_case(&root.name.name))
        else {
            continue;
        };
        axes.axes[k].declared_by_program = true;
        if !taken[k] && !chosen.contains_key(&(r, 0)) {
            chosen.insert((r, 0), k);
            taken[k] = true;
        }
    }
    // a program's own AXIS_REF named like an axis, when no other declaration has that name
    for (r, root) in roots.iter().enumerate() {
        if root.global
            || root.leaves.len() != 1
            || !root.leaves[0].steps.is_empty()
            || !root.leaves[0].used
        {
            continue;
        }
        let alone = roots
            .iter()
            .filter(|o| o.name.key() == root.name.key() && o.leaves.iter().any(|l| l.used))
            .count()
            == 1;
        let Some(k) = axes
            .axes
            .iter()
            .position(|a| a.name.eq_ignore_ascii_case(&root.name.name))
        else {
            continue;
        };
        if alone && !taken[k] && !chosen.contains_key(&(r, 0)) {
            chosen.insert((r, 0), k);
            taken[k] = true;
        }
    }
    // one axis and one AXIS_REF the program uses: those two
    let in_use: Vec<(usize, usize)> = roots
        .iter()
        .enumerate()
        .flat_map(|(r, root)| {
            root.leaves
                .iter()
                .enumerate()
                .filter(|(_, l)| l.used)
                .map(move |(l, _)| (r, l))
        })
        .collect();
    if let [only] = in_use.as_slice() {
        if axes.axes.len() == 1 && chosen.is_empty() && axes.axes[0].link.is_none() {
            chosen.insert(*only, 0);
        }
    }
    let free: Vec<&str> = axes
        .axes
        .iter()
        .zip(&taken)
        .filter(|(_, t)| !**t)
        .map(|(a, _)| a.name.as_str())
        .collect();
    for (r, root) in roots.iter().enumerate() {
        let missing: Vec<&Leaf> = (0..root.leaves.len())
            .filter(|l| root.leaves[*l].used && !chosen.contains_key(&(r, *l)))
            .map(|l| &root.leaves[l])
            .collect();
        if let Some(first) = missing.first() {
            diags.push(e1056(
                &first.path,
                missing.len(),
                &free,
                root.name.span,
                axes,
            ));
        }
    }
    // the initialisers
    for (r, root) in roots.iter().enumerate() {
        let (u, i, b, v) = root.at;
        let decl = match &mut units[u].items[i] {
            LibraryElement::GlobalVars(block) => &mut block.vars[v],
            LibraryElement::Pou(p) => &mut p.var_blocks[b].vars[v],
            _ => continue,
        };
        let shape = {
            // the shape again (the borrow of the units for `Types` has ended)
            root.leaves
                .iter()
                .map(|l| l.steps.clone())
                .collect::<Vec<_>>()
        };
        for (l, steps) in shape.iter().enumerate() {
            if let Some(&k) = chosen.get(&(r, l)) {
                let at = decl.name.span;
                set_axis_no(&mut decl.init, steps, k, at);
            }
        }
    }
}

fn e1056(path: &str, count: usize, free: &[&str], at: Span, axes: &AxisConfig) -> Diagnostic {
    let more = if count > 1 {
        format!(" (and {} more AXIS_REF of this declaration)", count - 1)
    } else {
        String::new()
    };
    if let Some(solution) = &axes.nc_solution {
        let which = if free.is_empty() {
            "every NC axis is linked already: add an NC axis".to_string()
        } else {
            format!("link one of the NC axes ({}) to it", free.join(", "))
        };
        return Diagnostic::error(
            code::E1056,
            format!("AXIS_REF `{path}`{more} is linked to no NC axis of {solution}"),
        )
        .at(at)
        .with_hint(format!(
            "{which} in TwinCAT (the axis's \"Link To PLC\", saved in the .tsproj's <Mappings> or the PLC's _Config/PLC/*.xti), or \
             give an axes file (--axes FILE.json) with `\"link\": \"{path}\"`"
        ));
    }
    let hint = if axes.axes.is_empty() {
        "declare the machine's axes in an axes file (`<input stem>.axes.json` or --axes FILE, \
         crates/ladderc/AXES.md) and link each AXIS_REF with `\"link\"`, or give the TwinCAT \
         solution's NC configuration (its .tsproj and `_Config/NC`) with the project"
            .to_string()
    } else if free.is_empty() {
        format!(
            "every axis of the axes file is linked already: add an axis with `\"link\": \"{path}\"` \
             (see `ladderc explain E1056`)"
        )
    } else {
        format!(
            "give one of the unlinked axes ({}) `\"link\": \"{path}\"` (see `ladderc explain E1056`)",
            free.join(", ")
        )
    };
    Diagnostic::error(
        code::E1056,
        format!("AXIS_REF `{path}`{more} is linked to no axis of the axes file"),
    )
    .at(at)
    .with_hint(hint)
}

/// Does `init` give `AxisNo` for the leaf at `steps`?
fn gives_axis_no(init: Option<&Initializer>, steps: &[Step]) -> bool {
    let Some(init) = init else { return false };
    match (steps.split_first(), init) {
        (None, Initializer::Struct(fs, _)) => fs.iter().any(|(n, _)| n.is("AxisNo")),
        (Some((Step::Field(f), rest)), Initializer::Struct(fs, _)) => fs
            .iter()
            .find(|(n, _)| n.key() == f.key())
            .is_some_and(|(_, i)| gives_axis_no(Some(i), rest)),
        (Some((Step::Index(k), rest)), Initializer::Array(es, _)) => {
            element(es, *k).is_some_and(|i| gives_axis_no(Some(i), rest))
        }
        _ => false,
    }
}

/// The `k`-th element of an array initialiser, repeats expanded.
fn element(es: &[ArrayInitElement], k: usize) -> Option<&Initializer> {
    let mut n = 0usize;
    for e in es {
        let r = e.repeat.unwrap_or(1) as usize;
        if k < n + r {
            return Some(&e.value);
        }
        n += r;
    }
    None
}

/// Adds `AxisNo := k` for the leaf at `steps` to `init`, keeping what the user wrote.
fn set_axis_no(init: &mut Option<Initializer>, steps: &[Step], k: usize, at: Span) {
    match steps.split_first() {
        None => {
            let value = Initializer::Value(Operand::literal(Literal {
                kind: LiteralKind::Int(k as i128),
                type_prefix: None,
                span: at,
            }));
            match init {
                Some(Initializer::Struct(fs, _)) => fs.push((Ident::new("AxisNo", at), value)),
                _ => {
                    *init = Some(Initializer::Struct(
                        vec![(Ident::new("AxisNo", at), value)],
                        at,
                    ))
                }
            }
        }
        Some((Step::Field(f), rest)) => {
            if !matches!(init, Some(Initializer::Struct(..))) {
                *init = Some(Initializer::Struct(Vec::new(), at));
            }
            let Some(Initializer::Struct(fs, _)) = init else {
                return;
            };
            let pos = match fs.iter().position(|(n, _)| n.key() == f.key()) {
                Some(p) => p,
                None => {
                    fs.push((
                        Ident::new(f.name.clone(), at),
                        Initializer::Struct(Vec::new(), at),
                    ));
                    fs.len() - 1
                }
            };
            let mut inner = Some(std::mem::replace(
                &mut fs[pos].1,
                Initializer::Struct(Vec::new(), at),
            ));
            set_axis_no(&mut inner, rest, k, at);
            if let Some(i) = inner {
                fs[pos].1 = i;
            }
        }
        Some((Step::Index(idx), rest)) => {
            // expand repeats so that the element can be given its own value
            let mut flat: Vec<Option<Initializer>> = match init.take() {
                Some(Initializer::Array(es, _)) => es
                    .into_iter()
                    .flat_map(|e| {
                        std::iter::repeat_n(Some(e.value), e.repeat.unwrap_or(1) as usize)
                    })
                    .collect(),
                other => {
                    *init = other;
                    if init.is_some() {
                        return;
                    }
                    Vec::new()
                }
            };
            while flat.len() <= *idx {
                flat.push(None);
            }
            set_axis_no(&mut flat[*idx], rest, k, at);
            let es = flat
                .into_iter()
                .map(|v| ArrayInitElement {
                    repeat: None,
                    value: v.unwrap_or_else(|| Initializer::Struct(Vec::new(), at)),
                })
                .collect();
            *init = Some(Initializer::Array(es, at));
        }
    }
}
