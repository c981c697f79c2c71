//! What the ST lowering knows about the program outside the POU being lowered: user data types, POU
//! interfaces (functions, function blocks) and global variables, all as written ([`TypeRef`]s).
//!
//! Input: declarations (from parsed IL units, or from a PLCopen project's interfaces). Output: lookups
//! by case-folded name. Invariants: bodies are never read (a POU can be registered before its body is
//! lowered); later registrations of the same name replace earlier ones.

use crate::ast::{
    CompilationUnit, LibraryElement, Pou, PouKind, TypeDecl, TypeDef, TypeRef, VarKind,
};
use std::collections::HashMap;

/// The interface of a POU as a caller sees it.
#[derive(Debug, Clone)]
pub struct PouInterface {
    /// `FUNCTION` or `FUNCTION_BLOCK` (or `PROGRAM`).
    pub kind: PouKind,
    /// The POU name as written.
    pub name: String,
    /// Every declared variable with its block kind and type, in declaration order (inputs, outputs,
    /// in-outs are the parameters; the others are only used to type `inst.x` reads).
    pub vars: Vec<(String, VarKind, TypeRef)>,
    /// A FUNCTION's result type.
    pub ret: Option<TypeRef>,
    /// The upper-case names of its `VAR_IN_OUT CONSTANT` parameters: they take any value (CODESYS,
    /// TwinCAT), passed through a temporary when it is not a variable.
    pub constant_in_outs: Vec<String>,
}

impl PouInterface {
    /// The interface of a parsed POU (its body is ignored).
    pub fn of(p: &Pou) -> Self {
        PouInterface {
            kind: p.kind,
            name: p.name.name.clone(),
            vars: p
                .var_blocks
                .iter()
                .flat_map(|b| {
                    b.vars
                        .iter()
                        .map(move |v| (v.name.name.clone(), b.kind, v.ty.clone()))
                })
                .collect(),
            ret: p.return_type.clone(),
            constant_in_outs: p
                .var_blocks
                .iter()
                .filter(|b| b.kind == VarKind::InOut && b.constant)
                .flat_map(|b| b.vars.iter().map(|v| v.name.key()))
                .collect(),
        }
    }
    /// The parameters (inputs, outputs, in-outs) in declaration order.
    pub fn params(&self) -> impl Iterator<Item = &(String, VarKind, TypeRef)> {
        self.vars
            .iter()
            .filter(|v| matches!(v.1, VarKind::Input | VarKind::Output | VarKind::InOut))
    }
    /// A variable by name, case-insensitively.
    pub fn var(&self, name: &str) -> Option<&(String, VarKind, TypeRef)> {
        self.vars.iter().find(|v| v.0.eq_ignore_ascii_case(name))
    }
}

/// The program's declarations, keyed by upper-case name.
#[derive(Debug, Clone, Default)]
pub struct Declarations {
    /// `TYPE` declarations by upper-case name.
    pub types: HashMap<String, TypeDecl>,
    /// POU interfaces by upper-case name.
    pub pous: HashMap<String, PouInterface>,
    /// Global variables' declared types by upper-case name.
    pub globals: HashMap<String, TypeRef>,
    /// Named global variable lists (CODESYS GVLs): list, then member, both upper-case.
    pub global_lists: HashMap<String, HashMap<String, TypeRef>>,
    /// The methods of each function block (upper-case block name), callable inside the block
    /// (`M(...)`, `THIS^.M(...)`, see [`super::PouLowering`]).
    pub methods: HashMap<String, Vec<MethodSig>>,
    /// The interfaces variables may have (upper-case name), with the blocks that implement each
    /// ([`super::interface_vars`]).
    pub interfaces: HashMap<String, super::interface_vars::Interface>,
    /// The bases of each derived function block (upper-case names, root first).
    pub bases: HashMap<String, Vec<String>>,
    /// The derived blocks of each block that has some, with their class numbers
    /// ([`super::base_view`]).
    pub derived: super::base_view::Derived,
    /// Whether any declaration holds a `REFERENCE TO` (computed on the first
    /// [`Declarations::has_reference_to`], once the declarations are complete).
    references: std::sync::OnceLock<bool>,
    /// The FUNCTIONs declared without a result type whose body assigns the function's name
    /// (upper case): the body's E0354 ([`super::lower`]'s `void_result`) says what is wrong, so a
    /// call that uses their value reports nothing more.
    pub assigns_missing_result: std::collections::HashSet<String>,
    /// The enumerations declared under `{attribute 'strict'}` (upper case): IEC's strong typing.
    /// The others count as their integer where CODESYS and TwinCAT let them
    /// ([`crate::sema`]'s `loose_enum`; a FOR counter, [`super::lower`]).
    pub strict_enums: std::collections::HashSet<String>,
    /// The files where E0351 (`__NEW` / `__DELETE`) was reported: once per file (`lower::dynamic_memory`).
    pub(super) heap_reported:
        std::sync::Arc<std::sync::Mutex<std::collections::HashSet<crate::FileId>>>,
}

/// A method's interface as seen from inside its function block: the call `M(a, b)` or `M(v := a)`
/// stores the arguments into the method's hidden inputs, runs the method there, and reads its
/// outputs and result (`__M_<METHOD>_<VAR>`, `__M_<METHOD>`: [`crate::actions::method_var`]).
#[derive(Debug, Clone)]
pub struct MethodSig {
    /// The method's name as declared.
    pub name: String,
    /// Its VAR_INPUT and VAR_IN_OUT names, in declaration order (positional arguments bind in
    /// this order).
    pub inputs: Vec<String>,
    /// Those of [`Self::inputs`] that are VAR_IN_OUT (bound to the argument, not copied).
    pub in_outs: Vec<String>,
    /// Those of [`Self::in_outs`] declared `VAR_IN_OUT CONSTANT`, with their types: they take any
    /// value (CODESYS), passed through a temporary when it is not a variable.
    pub constant_in_outs: Vec<(String, crate::ast::TypeRef)>,
    /// Its VAR_OUTPUT names.
    pub outputs: Vec<String>,
    /// Whether it returns a value (`METHOD M : INT`).
    pub returns: bool,
    /// Whether its class declares more METHODs of its name (SIMATIC AX overloading, one E1084
    /// at the second): a call that fits a dropped overload, not this one, reports nothing more
    /// (round 31, before: one E1011 per such call).
    pub overloaded: bool,
}

impl MethodSig {
    /// The interface of a method read from an ST file or a CODESYS export.
    pub fn of(m: &super::file::PendingMethod) -> MethodSig {
        let names = |k: &[crate::ast::VarKind]| {
            m.blocks
                .iter()
                .filter(|b| k.contains(&b.kind))
                .flat_map(|b| b.vars.iter().map(|v| v.name.name.clone()))
                .collect()
        };
        MethodSig {
            name: m.name.name.clone(),
            inputs: names(&[crate::ast::VarKind::Input, crate::ast::VarKind::InOut]),
            in_outs: names(&[crate::ast::VarKind::InOut]),
            constant_in_outs: m
                .blocks
                .iter()
                .filter(|b| b.kind == crate::ast::VarKind::InOut && b.constant)
                .flat_map(|b| b.vars.iter().map(|v| (v.name.name.clone(), v.ty.clone())))
                .collect(),
            outputs: names(&[crate::ast::VarKind::Output]),
            returns: m.ret.is_some(),
            overloaded: m.overloaded,
        }
    }
}

impl Declarations {
    /// No declarations.
    pub fn new() -> Self {
        Self::default()
    }

    /// Whether a method's variable of type `ty` is given its initial value again at each call
    /// from a never-written copy (`crate::actions::method_input_default`): a value of an
    /// elementary, string, enumerated or structured type, not a reference, an interface (its
    /// hidden tag and references are set by the call) or a function block instance.
    pub fn resets_per_call(&self, ty: &TypeRef) -> bool {
        match ty {
            TypeRef::Named(n) => {
                let key = n.key();
                !self.interfaces.contains_key(&key)
                    && !self.pous.contains_key(&key)
                    && crate::sema::StdFb::from_name(&n.name).is_none()
                    && !self
                        .types
                        .get(&key)
                        .is_some_and(|t| matches!(&t.def, TypeDef::Alias { ty, .. } if !self.resets_per_call(ty)))
            }
            TypeRef::String { .. } | TypeRef::Subrange { .. } | TypeRef::Enum { .. } => true,
            TypeRef::Array { .. } | TypeRef::Ref { .. } => false,
        }
    }
    /// Whether a method's own VAR or VAR_TEMP of type `ty` starts again at its initial value at
    /// each call, also the second of two calls in one scan (IEC 61131-3 ed. 3, 6.6.1.2: a
    /// method's variables are temporary; CODESYS creates a method's instances again at each call):
    /// what [`Self::resets_per_call`] resets, and arrays of it, and function block instances
    /// (before round 28 these kept the previous call's values when the block called its method
    /// twice in one scan). Not a reference or an interface (set by the method's statements).
    pub fn local_resets_per_call(&self, ty: &TypeRef) -> bool {
        match ty {
            TypeRef::Array { element, .. } => self.local_resets_per_call(element),
            TypeRef::Named(n) => {
                let key = n.key();
                self.pous.contains_key(&key)
                    || crate::sema::StdFb::from_name(&n.name).is_some()
                    || self.resets_per_call(ty)
            }
            _ => self.resets_per_call(ty),
        }
    }

    /// Whether a data type, POU interface or global holds a `REFERENCE TO` (then the ST lowering
    /// looks for the `^` each access leaves out: see `Env::implicit_derefs`). Read once the
    /// declarations are complete: the answer is kept.
    pub fn has_reference_to(&self) -> bool {
        *self.references.get_or_init(|| {
            let holds = super::refs::holds_reference_to;
            self.types.values().any(|t| match &t.def {
                crate::ast::TypeDef::Alias { ty, .. } => holds(ty),
                crate::ast::TypeDef::Struct { fields } => fields.iter().any(|f| holds(&f.ty)),
                crate::ast::TypeDef::Enum { .. } => false,
            }) || self
                .pous
                .values()
                .any(|p| p.vars.iter().any(|v| holds(&v.2)))
                || self.globals.values().any(holds)
                || self.global_lists.values().any(|l| l.values().any(holds))
        })
    }
    /// Every data type, POU interface and global variable of `units`.
    pub fn from_units(units: &[CompilationUnit]) -> Self {
        let mut d = Declarations::new();
        for item in units.iter().flat_map(|u| u.items.iter()) {
            match item {
                LibraryElement::DataTypes(ts) => ts.iter().for_each(|t| d.add_type(t.clone())),
                LibraryElement::Pou(p) => d.add_pou(p),
                LibraryElement::GlobalVars(b) => d.add_global_block(b),
                LibraryElement::Configuration(c) => {
                    let blocks = c
                        .globals
                        .iter()
                        .chain(c.resources.iter().flat_map(|r| r.globals.iter()));
                    for b in blocks {
                        d.add_global_block(b);
                    }
                }
                LibraryElement::Action(_) => {}
            }
        }
        d.strict_enums = units
            .iter()
            .flat_map(|u| u.strict_types.iter().map(|n| n.key()))
            .collect();
        d
    }
    /// Registers a data type (replacing one of the same name).
    pub fn add_type(&mut self, t: TypeDecl) {
        self.types.insert(t.name.key(), t);
    }
    /// Registers a POU's interface (its body is not read).
    pub fn add_pou(&mut self, p: &Pou) {
        self.add_pou_interface(PouInterface::of(p));
    }
    /// Registers an interface built elsewhere (a PLCopen project's `<interface>`).
    pub fn add_pou_interface(&mut self, i: PouInterface) {
        self.pous.insert(i.name.to_ascii_uppercase(), i);
    }
    /// Registers a global variable's type.
    pub fn add_global(&mut self, name: &str, ty: TypeRef) {
        self.globals.insert(name.to_ascii_uppercase(), ty);
    }
    /// A member of the named global variable list `list` (reachable as `list.name`).
    pub fn add_list_member(&mut self, list: &str, name: &str, ty: TypeRef) {
        self.global_lists
            .entry(list.to_ascii_uppercase())
            .or_default()
            .insert(name.to_ascii_uppercase(), ty);
    }
    fn add_global_block(&mut self, b: &crate::ast::VarBlock) {
        for v in &b.vars {
            self.add_global(&v.name.name, v.ty.clone());
            if let Some(list) = &b.name {
                self.add_list_member(&list.name, &v.name.name, v.ty.clone());
            }
        }
    }
    /// A POU's interface by name (case-insensitive).
    pub fn pou(&self, name: &str) -> Option<&PouInterface> {
        self.pous.get(&name.to_ascii_uppercase())
    }
    /// A data type's declaration by name (case-insensitive).
    pub fn type_decl(&self, name: &str) -> Option<&TypeDecl> {
        self.types.get(&name.to_ascii_uppercase())
    }
}
