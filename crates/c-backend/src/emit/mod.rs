//! Assembly of the generated C project: configuration header, type and instance structs, POU functions,
//! globals, the scan entry point and the watchable-variable table.
//!
//! Input: compilation units, the sema model, the target profile, options. Output: the generated files
//! (`ladderc_config.h`, `program.h`, `program.c`, `embedded.c` when embedded functions are supplied).
//! Invariants: struct definitions come in dependency order; every POU's C names derive from [`mangle`];
//! the program is written into one `String` per file, in time linear in the input.

mod access;
mod body;
mod calls;
mod datetime;
mod edges;
mod hier;
mod init;
mod memory;
mod method;
mod overlaps;
mod refs;
mod scan;
mod scope;
mod split;
mod strings;
mod values;

use crate::profile::{AddressUnit, BitNumbering, ByteOrder, TargetProfile};
use crate::{ctypes, mangle, Options};
use body::{jump_targets, Body};
use diagnostics::{code, Diagnostic, Diagnostics, Span};
use il_frontend::ast::{CompilationUnit, LibraryElement, PouKind, VarKind};
use il_frontend::sema::{FbType, Model, PouId, Type, UserTypeDef};
use scope::Scope;
use std::collections::{HashMap, HashSet};
use std::fmt::Write as _;

/// The generator's shared state.
pub struct Gen<'a> {
    pub model: &'a Model,
    pub profile: &'a TargetProfile,
    pub diags: &'a mut Diagnostics,
    /// Embedded functions: upper-case name -> C name.
    pub embedded: HashMap<String, String>,
    /// Free globals: upper-case name -> index in `Model::globals`.
    pub free_globals: rustc_hash::FxHashMap<String, usize>,
    /// (code, span) pairs already reported.
    pub reported: HashSet<(&'static str, Option<Span>)>,
    /// While > 0, diagnostics are suppressed (type probing).
    pub quiet: u32,
    /// The span of the `AT %...` address of each located declaration, by the declaration's name span
    /// and whole span (the model keeps the variable's span only) and whether the address is a `*`
    /// placeholder: a VAR_CONFIG copy of a POU shares its declarations' spans with the original, and
    /// its address is the entry's, while the original keeps its `*`.
    pub address_spans: HashMap<(Span, bool), Span>,
    /// Lazily built name indexes of user POU variables and struct fields (upper-case name -> index),
    /// so that member lookups stay O(1) however many members a type has.
    member_index: std::cell::RefCell<HashMap<(bool, u32), HashMap<String, usize>>>,
    /// Template-method functions (see `method`).
    pub methods: Vec<crate::PouMethod>,
    /// The motion runtime, when the program uses motion blocks.
    pub motion: Option<crate::motion::MotionRuntime>,
    /// The position in `Model::instrs` after the last instruction looked up (bodies are read in
    /// source order, so that is usually where the next one is).
    pub(super) instr_cursor: usize,
    /// Bodies of more instruction units are split into several C functions (see `split`).
    pub(super) part_limit: usize,
    /// Whether the model has an enumerated type: without one no operand name is an enumerated value,
    /// and the per-operand check is skipped.
    pub(super) has_enums: bool,
    /// The slots of hierarchical direct addresses met so far (see `hier`).
    pub(super) hier: hier::Slots,
    /// Flat addresses outside their area (E2001), by the diagnostic's span: the area (0 %I, 1 %Q,
    /// 2 %M), the bytes the address needs and its text (see [`Gen::fold_outside_area`]).
    outside_area: HashMap<Option<Span>, (usize, u64, String)>,
    /// The scratch objects of NULL dereferences (see `refs`): (C type, declaration).
    pub(super) null_refs: Vec<(String, String)>,
    /// The sources' lines, for the sites of run-time errors (see [`Gen::site`]).
    pub(super) lines: &'a crate::SourceLines,
}

impl<'a> Gen<'a> {
    /// The C string literal naming the site of a run-time error (the first one is reported at the
    /// end of the run): `what` (the access, as written), the POU it is in, and its source line
    /// when known (`temps[i] in Main at main.st:12`). The user's text is escaped by
    /// [`mangle::c_string`].
    pub(super) fn site(&self, scope: &Scope, what: &str, span: Span) -> String {
        let pou = scope
            .pou
            .map(|(p, _)| p.name.as_str())
            .unwrap_or("the configuration");
        let text = match self.lines.locate(span) {
            Some(at) => cfmt!("{what} in {pou} at {at}"),
            None => cfmt!("{what} in {pou}"),
        };
        mangle::c_string(text.as_bytes())
    }

    /// A user POU's variable by name (case-insensitive).
    pub fn pou_var(&self, id: PouId, name: &str) -> Option<&'a il_frontend::sema::Variable> {
        let model: &'a Model = self.model;
        let vars = &model.pou(id).vars;
        let i = self.member(true, id.0, vars, name)?;
        vars.get(i)
    }
    /// A user structure's field by name (case-insensitive).
    pub fn struct_field(
        &self,
        id: il_frontend::sema::TypeId,
        name: &str,
    ) -> Option<&'a il_frontend::sema::Variable> {
        let model: &'a Model = self.model;
        let UserTypeDef::Struct { fields } = &model.user_type(id).def else {
            return None;
        };
        let i = self.member(false, id.0, fields, name)?;
        fields.get(i)
    }
    fn member(
        &self,
        pou: bool,
        id: u32,
        vars: &[il_frontend::sema::Variable],
        name: &str,
    ) -> Option<usize> {
        let mut cache = self.member_index.borrow_mut();
        let map = cache.entry((pou, id)).or_insert_with(|| {
            let mut m = HashMap::with_capacity(vars.len());
            for (i, v) in vars.iter().enumerate() {
                m.entry(v.name.to_ascii_uppercase()).or_insert(i);
            }
            m
        });
        map.get(&name.to_ascii_uppercase()).copied()
    }
}

/// Records the address span of every located declaration in the units.
fn collect_address_spans(units: &[CompilationUnit]) -> HashMap<(Span, bool), Span> {
    let mut map = HashMap::new();
    let block = |b: &il_frontend::ast::VarBlock, map: &mut HashMap<(Span, bool), Span>| {
        for d in &b.vars {
            if let Some(a) = &d.location {
                map.insert((d.name.span, a.path.is_empty()), a.span);
                map.insert((d.span, a.path.is_empty()), a.span);
            }
        }
    };
    for u in units {
        for item in &u.items {
            match item {
                LibraryElement::Pou(p) => p.var_blocks.iter().for_each(|b| block(b, &mut map)),
                LibraryElement::GlobalVars(b) => block(b, &mut map),
                LibraryElement::Configuration(c) => {
                    c.globals.iter().for_each(|b| block(b, &mut map));
                    for r in &c.resources {
                        r.globals.iter().for_each(|b| block(b, &mut map));
                    }
                }
                LibraryElement::DataTypes(_) | LibraryElement::Action(_) => {}
            }
        }
    }
    map
}

pub fn generate(
    units: &[CompilationUnit],
    model: &Model,
    profile: &TargetProfile,
    opts: &Options,
    ext: &crate::Extensions,
    diags: &mut Diagnostics,
) -> Vec<(String, String)> {
    let mut g = Gen {
        model,
        profile,
        diags,
        embedded: HashMap::new(),
        free_globals: model
            .globals
            .iter()
            .enumerate()
            .map(|(i, v)| (v.name.to_ascii_uppercase(), i))
            .collect(),
        reported: HashSet::new(),
        quiet: 0,
        instr_cursor: 0,
        part_limit: split::part_limit(),
        has_enums: model
            .types
            .iter()
            .any(|t| matches!(t.def, UserTypeDef::Enum { .. })),
        address_spans: collect_address_spans(units),
        member_index: Default::default(),
        methods: ext.methods.clone(),
        motion: ext.motion.clone(),
        hier: hier::Slots::default(),
        outside_area: HashMap::new(),
        null_refs: Vec::new(),
        lines: &opts.lines,
    };
    g.check_embedded(opts);
    g.check_methods();
    g.check_address_overlaps();

    let mut h = String::new();
    // Room for the whole C text from the start: the text is not regrown (and copied) while it is
    // written. Pages not written are never touched.
    let vars = model.pous.iter().map(|p| p.vars.len()).sum::<usize>() + model.globals.len();
    let mut c = String::with_capacity(
        C_BYTES_PER_INSTR * model.instrs.len() + C_BYTES_PER_VAR * vars + 4096,
    );
    g.header(&mut h);
    g.program_c(units, &mut c);
    g.fold_outside_area();
    // after the program: the hierarchical addresses' slots extend the areas
    let config = config_header_with(profile, g.hier.used);
    let mut files = vec![("ladderc_config.h".to_string(), config)];
    files.push(("program.h".into(), h));
    files.push(("program.c".into(), c));
    if !opts.embedded.is_empty() {
        let mut e = String::from(
            "/* Embedded C functions supplied by the parameter-passing stage. */\n#include \"ladderc_rt.h\"\n\n",
        );
        for f in &opts.embedded {
            e.push_str(&f.c_source);
            if !f.c_source.ends_with('\n') {
                e.push('\n');
            }
        }
        files.push(("embedded.c".into(), e));
    }
    files
}

/// `ladderc_config.h`: the target profile as macros.
pub fn config_header(p: &TargetProfile) -> String {
    config_header_with(p, [0; 3])
}

/// `ladderc_config.h` with `ext` bytes of hierarchical-address slots after the %I, %Q and %M areas:
/// `LADDERC_x_SIZE` is the C array's size, `LADDERC_x_FLAT_SIZE` the profile's (flat addresses).
fn config_header_with(p: &TargetProfile, ext: [u32; 3]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "/* Target profile (memory model), generated by ladderc. */\n#ifndef LADDERC_CONFIG_H\n#define LADDERC_CONFIG_H"
    );
    let areas = [
        ("I", p.area_size(il_frontend::ast::Area::Input)),
        ("Q", p.area_size(il_frontend::ast::Area::Output)),
        ("M", p.area_size(il_frontend::ast::Area::Memory)),
    ];
    for ((a, size), more) in areas.into_iter().zip(ext) {
        let _ = writeln!(
            s,
            "#define LADDERC_{a}_SIZE {}",
            u64::from(size) + u64::from(more)
        );
        if more > 0 {
            let _ = writeln!(s, "#define LADDERC_{a}_FLAT_SIZE {size}");
        }
    }
    let _ = writeln!(s, "#define LADDERC_TM_OFFSET {}", p.tm_offset);
    let _ = writeln!(s, "#define LADDERC_TM_SIZE {}", p.tm_bytes);
    let _ = writeln!(
        s,
        "#define LADDERC_BIG_ENDIAN {}",
        u8::from(p.byte_order == ByteOrder::Big)
    );
    let _ = writeln!(
        s,
        "#define LADDERC_BIT_MSB0 {}",
        u8::from(p.bit_numbering == BitNumbering::Msb0)
    );
    let _ = writeln!(
        s,
        "#define LADDERC_ADDR_BYTE_OFFSET {}",
        u8::from(p.address_unit == AddressUnit::Byte)
    );
    if p.address_unit == AddressUnit::PerSize {
        // %I and %Q: four images (X and B, W, D, L) of a quarter of the flat size each
        let _ = writeln!(s, "#define LADDERC_PER_SIZE_IO 1");
    }
    if p.memory_per_size {
        // %M: four images too, but for the TM window, flat in the first (`TargetProfile::images`)
        let _ = writeln!(s, "#define LADDERC_PER_SIZE_M 1");
    }
    // the nanoseconds of one unit of a number converted to or from TIME (`emit::values`)
    let _ = writeln!(
        s,
        "#define LADDERC_TIME_UNIT_NS INT64_C({})",
        p.time_number_unit.nanoseconds()
    );
    // whether REAL_TO_TIME rounds to whole units (`TimeNumberUnit::rounds_real_to_time`)
    let _ = writeln!(
        s,
        "#define LADDERC_REAL_TO_TIME_WHOLE_UNITS {}",
        u8::from(p.time_number_unit.rounds_real_to_time())
    );
    let _ = writeln!(s, "#define LADDERC_ALIGNMENT {}\n#endif", p.alignment);
    s
}

/// A node of the struct dependency graph.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum Node {
    Struct(u32),
    Pou(u32),
}

impl<'a> Gen<'a> {
    fn check_embedded(&mut self, opts: &Options) {
        for f in &opts.embedded {
            let key = f.name.to_ascii_uppercase();
            if !mangle::is_valid_embedded_name(&f.name) || self.embedded.contains_key(&key) {
                self.diags.push(
                    Diagnostic::error(
                        code::E2007,
                        format!(
                            "invalid embedded C function name `{}` (not a plain C identifier, reserved, or supplied twice)",
                            f.name.escape_default()
                        ),
                    )
                    .with_hint("name embedded functions like MC_MoveAbsolute"),
                );
                continue;
            }
            self.embedded.insert(key, f.name.clone());
        }
    }

    /// The nodes a type's C definition needs complete.
    fn type_deps(&self, ty: &Type, out: &mut Vec<Node>) {
        match ty {
            Type::Array { element, .. } => self.type_deps(element, out),
            Type::Struct(id) => out.push(Node::Struct(id.0)),
            Type::Fb(FbType::User(id)) => out.push(Node::Pou(id.0)),
            _ => {}
        }
    }

    fn node_deps(&self, n: Node) -> Vec<Node> {
        let mut out = Vec::new();
        match n {
            Node::Struct(id) => {
                if let UserTypeDef::Struct { fields } = &self.model.types[id as usize].def {
                    for f in fields {
                        self.type_deps(&f.ty, &mut out);
                    }
                }
            }
            Node::Pou(id) => {
                let p = &self.model.pous[id as usize];
                for v in &p.vars {
                    if v.kind != VarKind::InOut {
                        self.type_deps(&v.ty, &mut out);
                    }
                }
            }
        }
        out
    }

    /// Structs and instance structs in dependency order (iterative DFS; cycles are cut).
    fn struct_order(&self) -> Vec<Node> {
        let mut roots: Vec<Node> = (0..self.model.types.len() as u32)
            .filter(|&i| matches!(self.model.types[i as usize].def, UserTypeDef::Struct { .. }))
            .map(Node::Struct)
            .collect();
        roots.extend(
            (0..self.model.pous.len() as u32)
                .filter(|&i| self.model.pous[i as usize].kind != PouKind::Function)
                .map(Node::Pou),
        );
        let mut done = HashSet::new();
        let mut on_stack = HashSet::new();
        let mut order = Vec::new();
        for r in roots {
            if done.contains(&r) {
                continue;
            }
            let mut stack = vec![(r, false)];
            while let Some((n, expanded)) = stack.pop() {
                if expanded {
                    on_stack.remove(&n);
                    if done.insert(n) {
                        order.push(n);
                    }
                    continue;
                }
                if done.contains(&n) || on_stack.contains(&n) {
                    continue;
                }
                on_stack.insert(n);
                stack.push((n, true));
                for d in self.node_deps(n) {
                    if !done.contains(&d) && !on_stack.contains(&d) {
                        stack.push((d, false));
                    }
                }
            }
        }
        order
    }

    /// A struct member declaration for a variable, written as the line `    T v_name[dims];` at the
    /// end of `h` (in place: no `String` per variable); `false`, nothing written, when it has no
    /// storage (located, external) or an unknown type.
    fn member_line(
        &mut self,
        h: &mut String,
        pou_kind: PouKind,
        v: &il_frontend::sema::Variable,
    ) -> bool {
        if v.location.is_some() || v.kind == VarKind::External {
            return false;
        }
        if pou_kind != PouKind::Function && v.kind == VarKind::Temp {
            return false;
        }
        let start = h.len();
        h.push_str("    ");
        if !ctypes::push_base(self.model, &v.ty, h) {
            h.truncate(start);
            self.unsupported(v.span, "a variable of unknown type");
            return false;
        }
        let in_out = v.kind == VarKind::InOut;
        h.push_str(if in_out { " (*v_" } else { " v_" });
        mangle::push_core(h, &v.name);
        if in_out {
            h.push(')');
        }
        ctypes::push_dims(&v.ty, h);
        h.push_str(";\n");
        true
    }

    /// Whether a block's struct may be read through its base's (EXTENDS; `st::base_view`): it
    /// is then defined with the may-alias attribute.
    fn viewed(p: &il_frontend::sema::model::Pou) -> bool {
        p.vars
            .first()
            .is_some_and(|v| v.name.starts_with(il_frontend::st::base_view::CLASS_PREFIX))
    }

    fn header(&mut self, h: &mut String) {
        h.push_str("/* Generated by ladderc: types, instance structs and prototypes. */\n");
        h.push_str(
            "#ifndef LADDERC_PROGRAM_H\n#define LADDERC_PROGRAM_H\n#include \"ladderc_rt.h\"\n\n",
        );
        let mut base_view_macro = false;
        // every block's and program's struct named before any is defined: a member may point to
        // an instance of a block defined later, or of its own (a method's `VAR_IN_OUT profile :
        // ProfileDesc` inside `ProfileDesc`: Struckig; a class's method taking an instance of its
        // own class or of its base, `VAR_IN_OUT o : Base`, IEC 61131-3 ed. 3 6.6.5)
        let mut forward = false;
        for p in &self.model.pous {
            if p.kind != PouKind::Function {
                let name = self.pou_struct(p);
                let _ = writeln!(h, "typedef struct {name} {name};");
                forward = true;
            }
        }
        if forward {
            h.push('\n');
        }
        for n in self.struct_order() {
            match n {
                Node::Struct(id) => {
                    let t = &self.model.types[id as usize];
                    let UserTypeDef::Struct { fields } = &t.def else {
                        continue;
                    };
                    let name = mangle::user_type(&t.name);
                    // a UNION's members share one storage (CODESYS and TwinCAT; sema admits only
                    // members whose C representation is the PLC's, E1040)
                    let kind = if t.union { "union" } else { "struct" };
                    let _ = writeln!(h, "typedef {kind} {{");
                    let mut any = false;
                    for f in fields.clone() {
                        any |= self.member_line(h, PouKind::FunctionBlock, &f);
                    }
                    if !any {
                        h.push_str("    char unused_;\n");
                    }
                    let _ = writeln!(h, "}} {name};\n");
                }
                Node::Pou(id) => {
                    // Borrowed from the model, not from `self` (no copy of the POU's variables).
                    let model: &'a Model = self.model;
                    let p = &model.pous[id as usize];
                    let name = self.pou_struct(p);
                    // a block of a family (EXTENDS) may be read through its base's struct, whose
                    // members are a prefix of its own (il_frontend::st::base_view): GCC and Clang
                    // must not assume the two struct types never alias
                    let viewed = Self::viewed(p);
                    if viewed && !base_view_macro {
                        base_view_macro = true;
                        h.push_str("#if defined(__GNUC__)\n#define LADDERC_BASE_VIEW __attribute__((__may_alias__))\n#else\n#define LADDERC_BASE_VIEW\n#endif\n\n");
                    }
                    if viewed {
                        // the tag named by the forward typedef, the attribute on the definition
                        let _ = writeln!(h, "struct LADDERC_BASE_VIEW {name} {{");
                    } else {
                        let _ = writeln!(h, "struct {name} {{");
                    }
                    let mut any = false;
                    for v in &p.vars {
                        any |= self.member_line(h, p.kind, v);
                    }
                    for m in edges::hidden_members(p) {
                        let _ = writeln!(h, "    {m}");
                    }
                    if p.kind == PouKind::FunctionBlock && model.fb_eno_read {
                        // the ENO of the instance's last call, as its body left it
                        h.push_str("    IEC_BOOL ENO;\n");
                        any = true;
                    }
                    if !any {
                        h.push_str("    char unused_;\n");
                    }
                    let _ = writeln!(h, "}};");
                    let _ = writeln!(h, "void {name}_INIT({name} *self);");
                    let _ = writeln!(h, "void {name}_BODY({name} *self);\n");
                }
            }
        }
        for i in 0..self.model.pous.len() {
            let model: &'a Model = self.model;
            let p = &model.pous[i];
            if p.kind == PouKind::Function {
                // an array result travels in a struct (C returns no arrays): `F_RET`, and
                // `F_box` that fills one from the function's result variable
                if let Some(rt @ Type::Array { .. }) = &p.return_type {
                    let name = mangle::function(&p.name);
                    if let Some(d) = ctypes::declare(self.model, rt, "a") {
                        let _ = writeln!(
                            h,
                            "typedef struct {{ {d}; }} {name}_RET;\nstatic inline {name}_RET {name}_box(const void *a_) {{ {name}_RET r_; memcpy(&r_.a, a_, sizeof r_.a); return r_; }}"
                        );
                    }
                }
                if let Some(sig) = self.function_signature(p) {
                    let _ = writeln!(h, "{sig};");
                }
            }
        }
        for c in self.embedded.values() {
            let _ = writeln!(h, "void {c}(void);");
        }
        // the instances (defined with the scan) of the programs whose actions other POUs call
        // (they have an action flag, see `il_frontend::actions`): the call runs on the instance;
        // and of those whose variables other POUs use by name (`MAIN.x`)
        for inst in self.instances() {
            let p = self.model.pou(inst.pou);
            let called = p
                .vars
                .iter()
                .any(|v| v.name.starts_with(il_frontend::actions::FLAG_PREFIX))
                || self.model.programs_used_by_name.contains(&inst.pou);
            if !called {
                continue;
            }
            let s = self.pou_struct(p);
            let _ = writeln!(h, "extern {s} {};", inst.c_name);
        }
        h.push_str("\n#endif\n");
    }

    /// The frame members of a split FUNCTION: every variable with storage (outputs and in-outs as
    /// pointers, as passed) and the result variable; the parameters passed by value or pointer are
    /// copied from the parameter of the same name (flag `true`), the rest are initialised in the frame.
    fn function_frame(&self, p: &il_frontend::sema::Pou) -> Vec<(String, String, bool)> {
        let mut members = Vec::new();
        for v in &p.vars {
            if v.location.is_some() {
                continue;
            }
            let name = mangle::var(&v.name);
            let decl = match v.kind {
                VarKind::Output | VarKind::InOut => ctypes::base(self.model, &v.ty)
                    .map(|b| cfmt!("{b} (*{name}){}", ctypes::dims(&v.ty))),
                VarKind::Input | VarKind::Local | VarKind::Temp => {
                    ctypes::declare(self.model, &v.ty, &name)
                }
                _ => None,
            };
            let param = match v.kind {
                VarKind::Input => !matches!(v.ty, Type::Array { .. }),
                VarKind::Output | VarKind::InOut => true,
                _ => false,
            };
            if let Some(d) = decl {
                members.push((d, name, param));
            }
        }
        if let Some(rt) = &p.return_type {
            let name = mangle::var(&p.name);
            if let Some(d) = ctypes::declare(self.model, rt, &name) {
                members.push((d, name, false));
            }
        }
        members.push((
            "IEC_BOOL *ladderc_eno".to_string(),
            "ladderc_eno".to_string(),
            true,
        ));
        members
    }

    fn pou_struct(&self, p: &il_frontend::sema::Pou) -> String {
        match p.kind {
            PouKind::Program => mangle::program(&p.name),
            _ => mangle::fb(&p.name),
        }
    }

    fn function_signature(&mut self, p: &il_frontend::sema::Pou) -> Option<String> {
        let ret = match &p.return_type {
            Some(t) => match t {
                Type::Array { .. } => cfmt!("{}_RET", mangle::function(&p.name)),
                t => ctypes::base(self.model, t)?,
            },
            None => "void".into(),
        };
        let mut params = Vec::new();
        for v in &p.vars {
            let name = mangle::var(&v.name);
            match v.kind {
                // An array input is passed by value: the caller's array arrives as `name__arg` and is
                // copied into the local `name` when the function starts (see `pou`).
                VarKind::Input if matches!(v.ty, Type::Array { .. }) => params.push(format!(
                    "{} {name}__arg{}",
                    ctypes::base(self.model, &v.ty)?,
                    ctypes::dims(&v.ty)
                )),
                VarKind::Input => {
                    params.push(format!("{} {name}", ctypes::base(self.model, &v.ty)?));
                }
                VarKind::Output | VarKind::InOut => {
                    params.push(format!(
                        "{} (*{name}){}",
                        ctypes::base(self.model, &v.ty)?,
                        ctypes::dims(&v.ty)
                    ));
                }
                _ => {}
            }
        }
        // ENO (IEC 61131-3 Table 18): the caller's flag, TRUE before the call; the body may
        // reset it (`ENO := FALSE`, `R ENO`), the caller stores it where `ENO =>` says
        params.push("IEC_BOOL *ladderc_eno".into());
        Some(format!(
            "{ret} {}({})",
            mangle::function(&p.name),
            params.join(", ")
        ))
    }

    /// The model's POU for the `n`-th AST POU (source order over all units), checked by name.
    fn pou_id(&self, n: usize, name: &str) -> Option<PouId> {
        match self.model.pous.get(n) {
            Some(p) if p.name.eq_ignore_ascii_case(name) => Some(PouId(n as u32)),
            _ => self.model.pou_by_name(name),
        }
    }

    fn program_c(&mut self, units: &[CompilationUnit], c: &mut String) {
        c.push_str("/* Generated by ladderc. */\n#include \"program.h\"\n\n");
        c.push_str("uint8_t ladderc_I[LADDERC_I_SIZE];\nuint8_t ladderc_Q[LADDERC_Q_SIZE];\nuint8_t ladderc_M[LADDERC_M_SIZE];\n\n");
        self.globals_decl(c);
        if let Some(m) = &self.motion {
            c.push_str(&m.declarations());
        }
        // the scratch objects of NULL dereferences go here once the bodies are written
        let scratch_at = c.len();
        self.method_prototypes(c);
        let mut n = 0;
        for u in units {
            for item in &u.items {
                if let LibraryElement::Pou(p) = item {
                    let id = self.pou_id(n, &p.name.name);
                    n += 1;
                    let Some(id) = id else { continue };
                    self.pou(p, id, c);
                }
            }
        }
        self.method_definitions(c);
        self.scan(units, c);
        if !self.null_refs.is_empty() {
            c.insert_str(scratch_at, &self.null_scratch_decls());
        }
    }

    /// Declarations of the global variables (free, configuration, resource).
    fn globals_decl(&mut self, c: &mut String) {
        let mut decl = |g: &mut Self, v: &il_frontend::sema::Variable, name: String| {
            if v.location.is_some() {
                return;
            }
            match ctypes::declare(g.model, &v.ty, &name) {
                Some(d) => {
                    let _ = writeln!(c, "{d};");
                }
                None => g.unsupported(v.span, "a global of unknown type"),
            }
        };
        let model: &'a Model = self.model;
        for r in model.global_refs() {
            let name = self.global_name(r);
            decl(self, model.global(r), name);
        }
        c.push('\n');
    }

    /// One POU: init and body functions (FB/program), or the C function (FUNCTION).
    fn pou(&mut self, ast: &il_frontend::ast::Pou, id: PouId, c: &mut String) {
        let model: &'a Model = self.model;
        let p = model.pou(id);
        let mut scope = Scope::for_pou(self.model.pou(id), id);
        let plan = self.plan_parts(&ast.body);
        if plan.is_some() {
            scope.frame();
        }
        let mut targets = HashSet::new();
        jump_targets(&ast.body, &mut targets);
        if p.kind == PouKind::Function {
            let Some(sig) = self.function_signature(p) else {
                return;
            };
            let ret_var = mangle::var(&p.name);
            let ret = match &p.return_type {
                // an array result: its struct made from the result variable (`F_box`)
                Some(Type::Array { .. }) if plan.is_some() => {
                    self.unsupported(p.span, "a FUNCTION returning an array, split into parts");
                    return;
                }
                Some(Type::Array { .. }) => {
                    cfmt!("{}_box(&{ret_var})", mangle::function(&p.name))
                }
                Some(_) => ret_var.clone(),
                None => String::new(),
            };
            let mut b = Body::new(&scope, 1, ret.clone());
            b.targets = targets;
            // locals and the result variable
            let mut pre = String::new();
            // a split body keeps its locals in the frame `fr` only (see `split`)
            let fr = if plan.is_some() { "fr." } else { "" };
            for v in &p.vars {
                if v.kind == VarKind::Input && matches!(v.ty, Type::Array { .. }) {
                    let name = mangle::var(&v.name);
                    if let Some(d) = ctypes::declare(self.model, &v.ty, &name) {
                        if fr.is_empty() {
                            let _ = writeln!(pre, "    {d};");
                        }
                        let _ = writeln!(
                            pre,
                            "    memcpy(&{fr}{name}, {name}__arg, sizeof {fr}{name});"
                        );
                    }
                }
            }
            for v in &p.vars {
                // (in a split body an array input has no local copy: its `__arg` is copied into `fr`)
                let copied = v.kind == VarKind::Input && matches!(v.ty, Type::Array { .. });
                if matches!(v.kind, VarKind::Input | VarKind::Output | VarKind::InOut)
                    && (fr.is_empty() || !copied)
                {
                    let _ = writeln!(pre, "    (void){};", mangle::var(&v.name));
                }
            }
            pre.push_str("    (void)ladderc_eno;\n");
            if let Some(rt) = p.return_type.as_ref().filter(|_| fr.is_empty()) {
                let d = ctypes::declare(self.model, rt, &ret_var).unwrap_or_default();
                let _ = writeln!(pre, "    {d};");
                let _ = writeln!(pre, "    memset(&{ret_var}, 0, sizeof {ret_var});");
            }
            for v in p.vars.iter().filter(|_| fr.is_empty()) {
                if matches!(v.kind, VarKind::Local | VarKind::Temp) && v.location.is_none() {
                    let name = mangle::var(&v.name);
                    if let Some(d) = ctypes::declare(self.model, &v.ty, &name) {
                        let _ = writeln!(pre, "    {d};");
                        let _ = writeln!(pre, "    memset(&{name}, 0, sizeof {name});");
                    }
                }
            }
            let mut init_code = String::new();
            for v in &p.vars {
                if matches!(v.kind, VarKind::Local | VarKind::Temp) && v.location.is_none() {
                    let lv = cfmt!("{fr}{}", mangle::var(&v.name));
                    self.init_value(&mut init_code, 1, &lv, &v.ty, v.init.as_ref(), v.span);
                }
            }
            if let Some(rt) = &p.return_type {
                let lv = cfmt!("{fr}{ret_var}");
                self.init_value(&mut init_code, 1, &lv, rt, None, p.span);
            }
            if let Some(plan) = &plan {
                let frame = split::Frame {
                    name: cfmt!("{}_FRAME", mangle::function(&p.name)),
                    prefix: cfmt!("{}_PART_", mangle::function(&p.name)),
                    self_param: String::new(),
                    self_arg: "",
                    members: self.function_frame(p),
                    leave: if ret.is_empty() {
                        "return;".into()
                    } else {
                        cfmt!("return fr.{ret};")
                    },
                };
                let head = cfmt!("{sig} {{\n");
                let prelude = cfmt!("{pre}{init_code}");
                let reserve = C_BYTES_PER_INSTR.saturating_mul(self.part_limit);
                self.emit_parts(
                    c, &head, &prelude, &scope, b.targets, &ast.body, plan, &frame, reserve,
                );
                return;
            }
            let _ = writeln!(c, "{sig} {{");
            c.push_str(&pre);
            c.push_str(&init_code);
            let at = c.len();
            in_place(c, &mut b, |b| self.stmts(b, &ast.body));
            insert_locals(c, at, &b, &scope, "");
            if ret.is_empty() {
                c.push_str("    return;\n}\n\n");
            } else {
                let _ = writeln!(c, "    return {ret};\n}}\n");
            }
            return;
        }
        let sname = self.pou_struct(p);
        // init
        let _ = writeln!(c, "void {sname}_INIT({sname} *self) {{");
        c.push_str("    memset(self, 0, sizeof *self);\n");
        // `self->v_<name>`, built in one buffer that keeps its room
        let mut lv = String::new();
        for v in &p.vars {
            if matches!(v.kind, VarKind::External | VarKind::InOut | VarKind::Temp) {
                continue;
            }
            if v.location.is_some() {
                // `q AT %QW2 : WORD := 7`: the initial value goes to the process image
                self.init_located(c, v);
                continue;
            }
            lv.clear();
            lv.push_str("self->v_");
            mangle::push_core(&mut lv, &v.name);
            self.init_value(c, 1, &lv, &v.ty, v.init.as_ref(), v.span);
        }
        c.push_str("}\n\n");
        // body
        let mut b = Body::new(&scope, 1, String::new());
        b.targets = targets;
        let mut temps = String::new();
        for v in &p.vars {
            if v.kind == VarKind::Temp && v.location.is_none() {
                let name = mangle::var(&v.name);
                if let Some(d) = ctypes::declare(self.model, &v.ty, &name) {
                    let _ = writeln!(temps, "    {d};");
                    let _ = writeln!(temps, "    memset(&{name}, 0, sizeof {name});");
                }
            }
        }
        let mut temp_init = String::new();
        let fr = if plan.is_some() { "fr." } else { "" };
        for v in &p.vars {
            if v.kind == VarKind::Temp && v.location.is_none() {
                let lv = cfmt!("{fr}{}", mangle::var(&v.name));
                self.init_value(&mut temp_init, 1, &lv, &v.ty, v.init.as_ref(), v.span);
            }
        }
        if let Some(plan) = &plan {
            let members = p
                .vars
                .iter()
                .filter(|v| v.kind == VarKind::Temp && v.location.is_none())
                .filter_map(|v| {
                    let name = mangle::var(&v.name);
                    ctypes::declare(self.model, &v.ty, &name).map(|d| (d, name, false))
                })
                .collect();
            let frame = split::Frame {
                name: cfmt!("{sname}_FRAME"),
                prefix: cfmt!("{sname}_BODY_PART_"),
                self_param: cfmt!("{sname} *self, "),
                self_arg: "self, ",
                members,
                leave: "return;".into(),
            };
            let sig = edges::body_signature(&sname, p);
            let head = cfmt!("{sig} {{\n");
            let reserve = C_BYTES_PER_INSTR.saturating_mul(self.part_limit);
            self.emit_parts(
                c, &head, &temp_init, &scope, b.targets, &ast.body, plan, &frame, reserve,
            );
            c.push_str(&edges::wrapper(&sname, p));
            return;
        }
        let _ = writeln!(c, "{} {{", edges::body_signature(&sname, p));
        c.push_str(&temps);
        c.push_str(&temp_init);
        let at = c.len();
        in_place(c, &mut b, |b| self.stmts(b, &ast.body));
        insert_locals(c, at, &b, &scope, "    (void)self;\n");
        c.push_str("}\n\n");
        c.push_str(&edges::wrapper(&sname, p));
    }
}

/// The C text reserved per instruction: IL programs average 58 bytes (`gen_il`: 58.0 for one POU of
/// 1,000,000 lines, 60 for 50 POUs of 2,000).
const C_BYTES_PER_INSTR: usize = 64;

/// The C text reserved per declared variable, on top of [`C_BYTES_PER_INSTR`]: a ladder program's
/// instructions are fewer and longer (generated rungs: 145 bytes of C per instruction, one variable
/// per 1.25 instructions), and its C grows with its variables (the INIT code, the coils, the FB
/// calls): 7.24 MB for 50,000 instructions and 40,001 variables is 64 + 108 per variable. An IL
/// program has few variables, so its reserve hardly changes.
const C_BYTES_PER_VAR: usize = 112;

/// Writes a body's statements straight after the end of `c` (the function's opening lines): `c`'s
/// buffer is lent to the body as its output and taken back afterwards, so a body's C (43 MB for a
/// 1,000,000-line POU) is never held in a second buffer and copied.
fn in_place(c: &mut String, b: &mut Body, write: impl FnOnce(&mut Body)) {
    b.out = std::mem::take(c);
    write(b);
    *c = std::mem::take(&mut b.out);
}

/// Inserts at `at` (before the body, which is only now complete) the current-result locals the body
/// declared, then `tail`.
fn insert_locals(c: &mut String, at: usize, b: &Body, scope: &Scope, tail: &str) {
    let mut locals = String::new();
    write_locals(&mut locals, b, scope);
    locals.push_str(tail);
    c.insert_str(at, &locals);
}

/// Declares the current-result locals (and `EN`/`ENO` when used) at the top of a function.
fn write_locals(c: &mut String, b: &Body, scope: &Scope) {
    for d in b.crs.values() {
        let _ = writeln!(c, "    {d}");
    }
    for n in b.crs.keys() {
        let _ = writeln!(c, "    (void){n};");
    }
    if scope.uses_en.get() {
        c.push_str(
            "    IEC_BOOL v_en = 1;\n    IEC_BOOL v_eno = 1;\n    (void)v_en;\n    (void)v_eno;\n",
        );
    }
}
