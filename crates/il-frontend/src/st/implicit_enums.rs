//! Implicit (inline, anonymous) enumerations get a type name, so that their bare values can be typed
//! by their context like those of a named enumeration.
//!
//! `state : (IDLE, RUN, DONE);` declares an enumeration without a name (IEC 61131-3 ed. 3, 6.4.4.2:
//! an anonymous enumerated data type; CODESYS and TwinCAT call it an implicit enumeration). CODESYS
//! documents that it creates an internal data type for it named `IMPLICIT_ENUM_<POU name>_<variable
//! name>` ("Data Type: Implicit Enumeration", CODESYS online help): this module does the same, before
//! the ST bodies are lowered. The lowering then writes `IDLE` in `state := IDLE;`, `state = IDLE`,
//! a CASE label of `CASE state OF` or an input `fb(mode := IDLE)` as the qualified value
//! `IMPLICIT_ENUM_MAIN_state#IDLE`, as it does for named enumerations, so two blocks (or a block
//! and the block it extends) may both use the value name `IDLE` in their own implicit enumerations.
//!
//! Input: the parsed units and the pending ST bodies (whose methods' variable blocks are not in the
//! units yet). Output: each variable (of a POU, a method, a structure or a global list) whose type is
//! an inline enumeration, or an array of one, now names a new `TYPE` declaration holding those
//! values, added to the unit. Invariants: the names of one declaration list (`a, b : (X, Y);`)
//! share one type (the same text); a name never equals another type's name (a number is appended);
//! a unit without inline enumerations is left as it was.

use super::file::PendingBody;
use crate::ast::{CompilationUnit, Ident, LibraryElement, TypeDecl, TypeDef, TypeRef, VarDecl};
use crate::Span;
use std::collections::{HashMap, HashSet};

/// The prefix CODESYS gives the internal type of an implicit enumeration.
pub const PREFIX: &str = "IMPLICIT_ENUM_";

/// Whether `type_name` is the name this module gave an implicit enumeration.
pub fn is_implicit(type_name: &str) -> bool {
    type_name.len() > PREFIX.len() && type_name[..PREFIX.len()].eq_ignore_ascii_case(PREFIX)
}

/// Names the implicit enumerations of `units` and of the methods of `pending`. Returns the pending
/// bodies with their methods' declarations rewritten, when any method declared one.
pub fn name_all(
    units: &mut [CompilationUnit],
    pending: &[PendingBody],
) -> Option<Vec<PendingBody>> {
    let mut namer = Namer {
        taken: units
            .iter()
            .flat_map(CompilationUnit::type_decls)
            .map(|t| t.name.key())
            .collect(),
        by_span: HashMap::new(),
        new: Vec::new(),
    };
    for unit in units.iter_mut() {
        for item in unit.items.iter_mut() {
            match item {
                LibraryElement::Pou(p) => {
                    let owner = p.name.name.clone();
                    for v in p.var_blocks.iter_mut().flat_map(|b| b.vars.iter_mut()) {
                        namer.var(&owner, v);
                    }
                }
                LibraryElement::DataTypes(ts) => {
                    for t in ts.iter_mut() {
                        if let TypeDef::Struct { fields } = &mut t.def {
                            for f in fields {
                                namer.var(&t.name.name, f);
                            }
                        }
                    }
                }
                LibraryElement::GlobalVars(b) => {
                    let owner = b.name.as_ref().map_or("GLOBAL".into(), |n| n.name.clone());
                    for v in b.vars.iter_mut() {
                        namer.var(&owner, v);
                    }
                }
                LibraryElement::Configuration(_) | LibraryElement::Action(_) => {}
            }
        }
        if !namer.new.is_empty() {
            unit.items
                .insert(0, LibraryElement::DataTypes(std::mem::take(&mut namer.new)));
        }
    }
    // the methods' own declarations (`METHOD M VAR step : (A, B); END_VAR`): their types go into
    // the unit of the block that declares the method
    let mut out: Option<Vec<PendingBody>> = None;
    for (k, pb) in pending.iter().enumerate() {
        let inline = pb
            .methods
            .iter()
            .flat_map(|m| m.blocks.iter().flat_map(|b| b.vars.iter()))
            .any(|v| has_inline(&v.ty));
        if !inline {
            continue;
        }
        let Some(owner) = pb.pou_name(units).map(|n| n.name.clone()) else {
            continue;
        };
        let bodies = out.get_or_insert_with(|| pending.to_vec());
        for m in bodies[k].methods.iter_mut() {
            let owner = format!("{owner}_{}", m.name.name);
            for v in m.blocks.iter_mut().flat_map(|b| b.vars.iter_mut()) {
                namer.var(&owner, v);
            }
        }
        let new = std::mem::take(&mut namer.new);
        let unit = units.iter_mut().find(|u| {
            u.items.iter().any(|i| {
                matches!(i, LibraryElement::Pou(p)
                    if p.name.span.file == pb.file && p.name.span.start as usize == pb.name_start)
            })
        });
        if let Some(u) = unit {
            u.items.insert(0, LibraryElement::DataTypes(new));
        }
    }
    out
}

/// The naming of [`name_all`] for PLCopen XML, whose POU interfaces are read one POU at a time: a
/// [`PouNamer`] made beside the project's declared types names the implicit enumerations of each
/// POU's variables (`<type><enum>...</enum></type>`), so their values are typed by context as in an
/// ST file; [`PouNamer::finish`] gives the new declarations.
pub struct PouNamer(Namer);

impl PouNamer {
    /// A namer beside the declared `types` (their names are taken).
    pub fn new(types: &[TypeDecl]) -> Self {
        PouNamer(Namer {
            taken: types.iter().map(|t| t.name.key()).collect(),
            by_span: HashMap::new(),
            new: Vec::new(),
        })
    }

    /// Names the implicit enumerations of `pou`'s variables.
    pub fn pou(&mut self, pou: &mut crate::ast::Pou) {
        let owner = pou.name.name.clone();
        for v in pou.var_blocks.iter_mut().flat_map(|b| b.vars.iter_mut()) {
            self.0.var(&owner, v);
        }
    }

    /// The declarations made, in the order their variables were named.
    pub fn finish(self) -> Vec<TypeDecl> {
        self.0.new
    }
}

fn has_inline(t: &TypeRef) -> bool {
    match t {
        TypeRef::Enum { .. } => true,
        TypeRef::Array { element, .. } => has_inline(element),
        _ => false,
    }
}

struct Namer {
    /// Upper-case type names already declared or given.
    taken: HashSet<String>,
    /// The type given to the inline enumeration written at a span (a declaration list's names
    /// share its text).
    by_span: HashMap<Span, Ident>,
    /// The declarations made for the unit being read.
    new: Vec<TypeDecl>,
}

impl Namer {
    fn var(&mut self, owner: &str, v: &mut VarDecl) {
        let name = format!("{PREFIX}{owner}_{}", v.name.name);
        self.ty(&name, &mut v.ty);
    }

    fn ty(&mut self, name: &str, t: &mut TypeRef) {
        match t {
            TypeRef::Array { element, .. } => self.ty(name, element),
            TypeRef::Enum { values, span } => {
                let span = *span;
                let id = match self.by_span.get(&span) {
                    Some(id) => id.clone(),
                    None => {
                        let mut unique = name.to_string();
                        let mut n = 1;
                        while !self.taken.insert(unique.to_ascii_uppercase()) {
                            n += 1;
                            unique = format!("{name}_{n}");
                        }
                        let id = Ident::new(unique, span);
                        self.new.push(TypeDecl {
                            name: id.clone(),
                            def: TypeDef::Enum {
                                values: values.clone(),
                                init: None,
                            },
                            union: false,
                            span,
                        });
                        self.by_span.insert(span, id.clone());
                        id
                    }
                };
                *t = TypeRef::Named(id);
            }
            _ => {}
        }
    }
}
