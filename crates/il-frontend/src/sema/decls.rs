//! Declarations: user data types, POUs and their variables, global variables, configurations.
//!
//! Input: the compilation units. Output: the declaration part of the [`Model`] (types, POU variable
//! tables, globals, configurations) and the list of POU bodies to check. Invariants: every name is
//! registered once (duplicates are reported and the first declaration kept); types are resolved on first
//! use, so declaration order does not matter; an unknown type becomes `Type::Error` after one diagnostic.

use super::model::*;
use super::typing::{literal_fits, literal_type, literal_value, FitError, LitType};
use super::Analyzer;
use crate::ast::{
    self, CompilationUnit, Initializer, LibraryElement, Operand, TypeRef, VarBlock, VarKind,
};
use crate::Span;
use diagnostics::{code, Diagnostic, Severity};
use std::collections::HashMap;

/// Constants visible to an initial value: upper-case name -> (type, value).
pub(crate) type Consts = HashMap<String, (Type, ConstValue)>;

impl Analyzer<'_> {
    /// E1040 for each member of the UNION `name` whose C representation is not the PLC's memory
    /// (a member of another type would read other bytes than CODESYS or TwinCAT read): integers, bit
    /// strings, REAL and LREAL, and arrays and structures of them, share storage as the PLC's do.
    fn check_union_members(&mut self, name: &str, members: &[Variable]) {
        for m in members {
            if self.shares_plc_layout(&m.ty) {
                continue;
            }
            let ty = self.model.type_name(&m.ty);
            self.error(
                code::E1040,
                m.span,
                format!("UNION `{name}`: member `{}` of type {ty} cannot share its storage", m.name),
            )
            .label("ladderc stores this type otherwise than the PLC")
            .hint("a UNION member is an integer, a bit string (BYTE, WORD, DWORD, LWORD), REAL or LREAL, or an array or structure of them; ladderc stores BOOL as 0/1 bytes and TIME, dates and strings in its own layout");
        }
    }

    /// Whether a value of `ty` is stored in C as the PLC stores it (see `check_union_members`).
    fn shares_plc_layout(&self, ty: &Type) -> bool {
        use Elementary as E;
        match ty {
            Type::Elementary(e) => matches!(
                e,
                E::Sint
                    | E::Int
                    | E::Dint
                    | E::Lint
                    | E::Usint
                    | E::Uint
                    | E::Udint
                    | E::Ulint
                    | E::Byte
                    | E::Word
                    | E::Dword
                    | E::Lword
                    | E::Real
                    | E::Lreal
            ),
            Type::Array { element, .. } => self.shares_plc_layout(element),
            Type::Struct(id) => match &self.model.types[id.0 as usize].def {
                UserTypeDef::Struct { fields } => {
                    fields.iter().all(|f| self.shares_plc_layout(&f.ty))
                }
                _ => false,
            },
            _ => false,
        }
    }

    /// Runs the declaration stage; returns the POUs whose bodies are to be checked.
    pub(crate) fn declare<'u>(
        &mut self,
        units: &'u [CompilationUnit],
    ) -> Vec<(PouId, &'u ast::Pou)> {
        let mut pous = Vec::new();
        let mut first_decl: HashMap<String, Span> = HashMap::new();
        // Names first: POUs and types may be used before they are declared.
        for unit in units {
            for item in &unit.items {
                match item {
                    LibraryElement::DataTypes(decls) => {
                        for d in decls {
                            if !self.unique_global_name(&d.name, &mut first_decl) {
                                continue;
                            }
                            self.register_type(d);
                        }
                    }
                    LibraryElement::Pou(p) => {
                        if !self.unique_global_name(&p.name, &mut first_decl) {
                            continue;
                        }
                        if matches!(p.kind, crate::ast::PouKind::FunctionBlock)
                            && StdFb::from_name(&p.name.name).is_some()
                            && !StdFb::is_vendor_name(&p.name.name)
                        {
                            // CODESYS and TwinCAT let a project's block hide the library's; IEC
                            // 61131-3 reserves the standard blocks' names: said, not silent
                            self.warning(
                                code::W1446,
                                p.name.span,
                                format!(
                                    "the FUNCTION_BLOCK `{}` hides the standard function block of that name: every `{}` instance of the project is this block",
                                    p.name.name, p.name.name
                                ),
                            )
                            .label("a standard block's name")
                            .hint(format!("rename the block (for example `My_{}`) to keep the standard one; IEC 61131-3 reserves the names of its standard function blocks", p.name.name));
                        }
                        let id = PouId(self.model.pous.len() as u32);
                        self.pou_names.insert(p.name.key(), id);
                        self.model.pous.push(Pou {
                            name: p.name.name.clone(),
                            span: p.span,
                            kind: p.kind,
                            return_type: None,
                            vars: Vec::new(),
                            externals: Vec::new(),
                            instrs: Vec::new(),
                            var_index: Default::default(),
                            class: p.class,
                            access: p
                                .var_blocks
                                .iter()
                                .filter_map(|b| Some((b, b.access?)))
                                .flat_map(|(b, a)| b.vars.iter().map(move |v| (v.name.key(), a)))
                                .collect(),
                        });
                        pous.push((id, p));
                    }
                    _ => {}
                }
            }
        }
        // `{attribute 'to_string'}` enumerations
        for n in units.iter().flat_map(|u| u.to_string_types.iter()) {
            if let Some(&id) = self.type_names.get(&n.key()) {
                self.model.types[id.0 as usize].to_string = true;
            }
        }
        // `{attribute 'strict'}` enumerations
        for n in units.iter().flat_map(|u| u.strict_types.iter()) {
            if let Some(&id) = self.type_names.get(&n.key()) {
                self.model.types[id.0 as usize].strict = true;
            }
        }
        // Type bodies (structs; aliases are resolved on demand).
        let ids: Vec<TypeId> = (0..self.model.types.len() as u32).map(TypeId).collect();
        for id in ids {
            self.resolve_user_type(id);
        }
        // `Magic : BYTE := C_MAGIC;` in a STRUCT: IEC 61131-3 ed. 3 takes a constant expression
        // (named constants included) as a field's initial value, and CODESYS/TwinCAT take a
        // VAR_GLOBAL CONSTANT declared anywhere in the project
        let field_consts = self.early_global_consts(units);
        for d in struct_declaration_order(units) {
            let ast::TypeDef::Struct { fields } = &d.def else {
                continue;
            };
            let Some(&id) = self.type_names.get(&d.name.key()) else {
                continue;
            };
            if self.model.types[id.0 as usize].span != d.span {
                continue; // a duplicate
            }
            let blocks = [VarBlock {
                access: None,
                name: None,
                kind: VarKind::Local,
                constant: false,
                retain: false,
                vars: self.unlocated_fields(&d.name.name, fields),
                span: d.span,
            }];
            self.declaring_fields = true;
            let vars = self.declare_vars(&blocks, &field_consts, None);
            self.declaring_fields = false;
            if d.union {
                self.check_union_members(&d.name.name, &vars);
            }
            self.model.types[id.0 as usize].def = UserTypeDef::Struct { fields: vars };
        }
        // a structure that holds itself by value has no size: E0343, the field cut
        self.check_struct_cycles();
        // Globals outside configurations.
        // their constants first: an initial value may name a constant of a list read later
        let mut global_consts = Consts::new();
        let free_constants: Vec<&ast::VarDecl> = units
            .iter()
            .flat_map(|u| u.items.iter())
            .filter_map(|item| match item {
                LibraryElement::GlobalVars(b) if b.constant => Some(b.vars.iter()),
                _ => None,
            })
            .flatten()
            .collect();
        self.constants_in_any_order(&free_constants, &mut global_consts, false);
        let mut deferred_inits: Vec<(usize, ast::Initializer)> = Vec::new();
        for unit in units {
            for item in &unit.items {
                if let LibraryElement::GlobalVars(block) = item {
                    // a global instance of the program's own function block initialized by its
                    // variables (`fb : FB_Cell := (Axis := (AxisNo := 1))`): the block's
                    // variables are declared below (after the globals, whose constants they may
                    // use), so its initializer is read then
                    let held: Vec<(Span, ast::Initializer)> = block
                        .vars
                        .iter()
                        .filter(|d| matches!(d.init, Some(ast::Initializer::Struct(..))))
                        .filter(|d| {
                            matches!(&d.ty, TypeRef::Named(n) if self.pou_names.contains_key(&n.key()))
                        })
                        .filter_map(|d| d.init.clone().map(|i| (d.name.span, i)))
                        .collect();
                    let vars = if held.is_empty() {
                        self.declare_vars(std::slice::from_ref(block), &global_consts, None)
                    } else {
                        let mut b = block.clone();
                        for d in &mut b.vars {
                            if held.iter().any(|(at, _)| *at == d.name.span) {
                                d.init = None;
                            }
                        }
                        self.declare_vars(std::slice::from_ref(&b), &global_consts, None)
                    };
                    for v in vars {
                        let mut held_init = held
                            .iter()
                            .find(|(at, _)| *at == v.span)
                            .map(|(_, i)| i.clone());
                        let key = v.name.to_ascii_uppercase();
                        let listed_first = self.free_globals.get(&key).and_then(|&i| {
                            self.model.list_of_global.get(&GlobalRef::Free(i)).copied()
                        });
                        let other_list = match (listed_first, &block.name) {
                            (Some(l), Some(list)) => !self.model.global_lists[l]
                                .name
                                .eq_ignore_ascii_case(&list.name),
                            _ => false,
                        };
                        if other_list {
                            // CODESYS: GVL_A.x and GVL_B.x are two variables, each reached
                            // qualified; an unqualified `x` is ambiguous (E1030)
                            if let Some(list) = &block.name {
                                let at = GlobalRef::Free(self.model.globals.len());
                                self.add_list_member(list, at, &v.name);
                            }
                            if let Some(i) = held_init.take() {
                                deferred_inits.push((self.model.globals.len(), i));
                            }
                            self.model.globals.push(v);
                            continue;
                        }
                        if let Some(&i) = self.free_globals.get(&key) {
                            let first = self.model.globals[i].span;
                            self.error(
                                code::E1002,
                                v.span,
                                format!("global variable `{}` is declared twice", v.name),
                            )
                            .label("declared again here")
                            .also(first, "first declared here")
                            .hint("rename or remove one of the declarations");
                            continue;
                        }
                        if v.constant {
                            if let Some(val) = &v.init {
                                global_consts.insert(key.clone(), (v.ty.clone(), val.clone()));
                            }
                        }
                        if let Some(list) = &block.name {
                            let at = GlobalRef::Free(self.model.globals.len());
                            self.add_list_member(list, at, &v.name);
                        }
                        self.free_globals.insert(key, self.model.globals.len());
                        if let Some(i) = held_init.take() {
                            deferred_inits.push((self.model.globals.len(), i));
                        }
                        self.model.globals.push(v);
                    }
                }
            }
        }
        // Configuration globals (needed by VAR_EXTERNAL).
        let mut configs = Vec::new();
        // (configuration, resource, the variable's name span, its held initial value)
        let mut deferred_config: Vec<(usize, Option<usize>, Span, ast::Initializer)> = Vec::new();
        // the configurations' names so far: IEC 61131-3 (ed. 3, 6.1.2, 6.8.1) names each
        // configuration of a project, and a name is unique in its scope
        let mut config_names: HashMap<String, Span> = HashMap::new();
        // each configuration's constants (with the free globals' ones)
        let mut config_consts: Vec<Consts> = Vec::new();
        for unit in units {
            for item in &unit.items {
                if let LibraryElement::Configuration(c) = item {
                    self.unique_configuration_name(&c.name, &mut config_names);
                    let config = self.model.configurations.len();
                    // a global instance of a block or class initialized by its variables
                    // (`c1 : C := (z := 1)`) is read once the blocks' variables are declared
                    let (held, c_globals) = self.hold_block_inits(&c.globals);
                    deferred_config.extend(held.into_iter().map(|(at, i)| (config, None, at, i)));
                    let globals = self.declare_vars(&c_globals, &global_consts, None);
                    // the configuration's constants, for its resources' initial values too
                    let mut consts = global_consts.clone();
                    let own: Vec<&ast::VarDecl> = c
                        .globals
                        .iter()
                        .filter(|b| b.constant)
                        .flat_map(|b| b.vars.iter())
                        .collect();
                    self.constants_in_any_order(&own, &mut consts, false);
                    self.record_lists(&c.globals, &globals, |index| GlobalRef::Configuration {
                        config,
                        index,
                    });
                    let resources = c
                        .resources
                        .iter()
                        .enumerate()
                        .map(|(resource, r)| {
                            let (held, r_globals) = self.hold_block_inits(&r.globals);
                            deferred_config.extend(
                                held.into_iter()
                                    .map(|(at, i)| (config, Some(resource), at, i)),
                            );
                            let globals = self.declare_vars(&r_globals, &consts, None);
                            self.record_lists(&r.globals, &globals, |index| GlobalRef::Resource {
                                config,
                                resource,
                                index,
                            });
                            Resource {
                                name: r.name.name.clone(),
                                span: r.span,
                                globals,
                                tasks: Vec::new(),
                                programs: Vec::new(),
                            }
                        })
                        .collect();
                    config_consts.push(consts);
                    self.model.configurations.push(Configuration {
                        name: c.name.name.clone(),
                        span: c.span,
                        globals,
                        resources,
                    });
                    configs.push(c);
                }
            }
        }
        // POU variables, each block's before those of the POUs holding its instances: their
        // initial values name the block's inputs (`decl_order`)
        for (id, p) in super::decl_order::pou_declaration_order(&pous) {
            self.declare_pou(id, p, &global_consts);
        }
        // the initializers of global instances of the program's function blocks (see above)
        for (i, init) in deferred_inits {
            let ty = self.model.globals[i].ty.clone();
            let value = self.const_init(&init, &ty, &global_consts);
            self.model.globals[i].init = value;
        }
        for (c, r, at, init) in deferred_config {
            let config = &self.model.configurations[c];
            let globals = match r {
                Some(r) => &config.resources[r].globals,
                None => &config.globals,
            };
            let Some(i) = globals.iter().position(|v| v.span == at) else {
                continue;
            };
            let ty = globals[i].ty.clone();
            let consts = config_consts.get(c).unwrap_or(&global_consts);
            let value = self.const_init(&init, &ty, consts);
            let config = &mut self.model.configurations[c];
            let globals = match r {
                Some(r) => &mut config.resources[r].globals,
                None => &mut config.globals,
            };
            globals[i].init = value;
        }
        // `ADR(x)` in a global's initial value (`fb : FB_M := (pLamp := ADR(GVL.lamp))`)
        self.global_address_initial_values(units);
        // Tasks and program instances.
        for (ci, c) in configs.iter().enumerate() {
            for (ri, r) in c.resources.iter().enumerate() {
                self.declare_resource(ci, ri, r);
            }
        }
        self.configurations_without_programs(&configs);
        pous
    }

    /// W1453 when the CONFIGURATIONs declare no program instance at all (Beremiz writes an empty
    /// `config` with an empty `resource1` into every export): IEC 61131-3 runs only the programs
    /// a resource associates with tasks, so ladderc runs every PROGRAM as without a
    /// configuration, and says so once, at the first configuration.
    fn configurations_without_programs(&mut self, configs: &[&ast::Configuration]) {
        let Some(first) = configs.first() else {
            return;
        };
        if configs
            .iter()
            .any(|c| c.resources.iter().any(|r| !r.programs.is_empty()))
        {
            return;
        }
        let programs: Vec<&str> = self
            .model
            .pous
            .iter()
            .filter(|p| p.kind == crate::ast::PouKind::Program)
            .map(|p| p.name.as_str())
            .collect();
        let what = if configs.len() == 1 {
            format!("configuration `{}` declares", first.name.name)
        } else {
            format!("the {} configurations declare", configs.len())
        };
        let message = match programs.as_slice() {
            [] => format!("{what} no program instance, and there is no PROGRAM: nothing runs"),
            [one] => format!(
                "{what} no program instance: PROGRAM `{one}` runs each cycle as without a configuration"
            ),
            more => format!(
                "{what} no program instance: the {} PROGRAMs run each cycle as without a configuration",
                more.len()
            ),
        };
        self.warning(code::W1453, first.name.span, message)
            .label("no `PROGRAM inst WITH task : P;` in its resources")
            .hint("declare the program instances in a RESOURCE (`PROGRAM Main1 WITH t : Main;`), or leave the empty CONFIGURATION out");
    }

    /// The scalar (elementary, string, enumerated) constants of the project's VAR_GLOBAL CONSTANT
    /// blocks, top-level and of configurations, evaluated silently before the structures are
    /// declared, for the initial values of structure fields (`Magic : BYTE := C_MAGIC;`). A
    /// constant may use one declared after it (`constants_in_any_order`); their errors are
    /// reported when the globals are declared.
    fn early_global_consts(&mut self, units: &[CompilationUnit]) -> Consts {
        let blocks: Vec<&VarBlock> = units
            .iter()
            .flat_map(|u| u.items.iter())
            .flat_map(|item| match item {
                LibraryElement::GlobalVars(b) => vec![b],
                LibraryElement::Configuration(c) => c
                    .globals
                    .iter()
                    .chain(c.resources.iter().flat_map(|r| r.globals.iter()))
                    .collect(),
                _ => Vec::new(),
            })
            .filter(|b| b.constant)
            .collect();
        let mut consts = Consts::new();
        let decls: Vec<&ast::VarDecl> = blocks.iter().flat_map(|b| b.vars.iter()).collect();
        self.constants_in_any_order(&decls, &mut consts, true);
        consts
    }

    /// Adds a global to the named list `list` (a CODESYS GVL), creating the list on first use.
    fn add_list_member(&mut self, list: &ast::Ident, r: GlobalRef, name: &str) {
        let lists = &mut self.model.global_lists;
        let at = match lists
            .iter_mut()
            .position(|l| l.name.eq_ignore_ascii_case(&list.name))
        {
            Some(i) => {
                lists[i].members.push(r);
                i
            }
            None => {
                lists.push(GlobalList {
                    name: list.name.clone(),
                    span: list.span,
                    members: vec![r],
                });
                lists.len() - 1
            }
        };
        self.model.list_of_global.insert(r, at);
        let key = name.to_ascii_uppercase();
        let lists = self.model.lists_of_name.entry(key).or_default();
        if !lists.contains(&at) {
            lists.push(at);
        }
    }

    /// Records the members of the named blocks among `blocks`, declared as `globals` (in order; a
    /// variable that could not be declared is not there, so members are found by name).
    fn record_lists(
        &mut self,
        blocks: &[ast::VarBlock],
        globals: &[Variable],
        at: impl Fn(usize) -> GlobalRef,
    ) {
        for b in blocks {
            let Some(list) = &b.name else { continue };
            for v in &b.vars {
                if let Some(i) = globals.iter().position(|g| g.span == v.name.span) {
                    self.add_list_member(list, at(i), &v.name.name);
                }
            }
        }
    }

    /// Registers a configuration's name; reports a second configuration of that name (E1002):
    /// its instances' variables would be traced and watched under the first one's names.
    fn unique_configuration_name(&mut self, name: &ast::Ident, first: &mut HashMap<String, Span>) {
        if let Some(&prev) = first.get(&name.key()) {
            self.error(
                code::E1002,
                name.span,
                format!("configuration `{}` is declared twice", name.name),
            )
            .label("declared again here")
            .also(prev, "first declared here")
            .hint("each CONFIGURATION of a project needs its own name: rename one (its program instances are then `Name.inst`), or give the files of one project only");
            return;
        }
        first.insert(name.key(), name.span);
    }

    /// Registers a POU or type name; reports a duplicate (returns false).
    fn unique_global_name(&mut self, name: &ast::Ident, first: &mut HashMap<String, Span>) -> bool {
        if let Some(&prev) = first.get(&name.key()) {
            self.declared_twice.insert(name.key());
            self.error(
                code::E1002,
                name.span,
                format!("`{}` is declared twice", name.name),
            )
            .label("declared again here")
            .also(prev, "first declared here")
            .hint("POUs and data types share one namespace; rename one of them");
            return false;
        }
        first.insert(name.key(), name.span);
        true
    }

    fn register_type(&mut self, d: &ast::TypeDecl) {
        let id = TypeId(self.model.types.len() as u32);
        let def = match &d.def {
            ast::TypeDef::Struct { .. } => UserTypeDef::Struct { fields: Vec::new() },
            ast::TypeDef::Enum { values, init } => {
                let (vals, default) = self.enum_values_of(id, values, init.as_ref());
                UserTypeDef::Enum {
                    values: vals,
                    default,
                }
            }
            ast::TypeDef::Alias { .. } => {
                self.pending_aliases.insert(id, d.clone());
                UserTypeDef::Alias {
                    target: Type::Error,
                    init: None,
                }
            }
        };
        self.type_names.insert(d.name.key(), id);
        self.model.types.push(UserType {
            name: d.name.name.clone(),
            span: d.span,
            def,
            union: d.union,
            to_string: false,
            strict: false,
        });
    }

    /// The values of an enumeration (implicit values count on from the previous one) and its default.
    fn enum_values_of(
        &mut self,
        id: TypeId,
        values: &[ast::EnumValue],
        init: Option<&ast::Ident>,
    ) -> (Vec<(String, i128)>, usize) {
        let mut out: Vec<(String, i128)> = Vec::new();
        let mut next = 0i128;
        // the names so far, upper-cased: searching `out` for each value made 100,000 values quadratic
        let mut seen: std::collections::HashSet<String> = std::collections::HashSet::new();
        for v in values {
            if !seen.insert(v.name.name.to_ascii_uppercase()) {
                self.error(
                    code::E1002,
                    v.name.span,
                    format!("enumerated value `{}` is declared twice", v.name.name),
                )
                .label("declared again here")
                .hint("each value of an enumeration needs its own name");
                continue;
            }
            let value = v.value.unwrap_or(next);
            next = value + 1;
            // an enumeration is stored as a DINT (README "Memory model"): a value beyond it
            // would silently become another number in the C
            if i32::try_from(value).is_err() {
                self.error(
                    code::E1017,
                    v.name.span,
                    format!(
                        "enumerated value `{}` = {value} does not fit an enumeration's 32 bits",
                        v.name.name
                    ),
                )
                .label("out of range")
                .hint("ladderc stores an enumeration as a DINT: give its values from -2147483648 to 2147483647");
            }
            self.enum_values
                .entry(v.name.key())
                .or_default()
                .push((id, out.len()));
            out.push((v.name.name.clone(), value));
        }
        let default = match init {
            Some(i) => match out.iter().position(|(n, _)| i.is(n)) {
                Some(p) => p,
                None => {
                    self.error(
                        code::E1025,
                        i.span,
                        format!("`{}` is not a value of this enumeration", i.name),
                    )
                    .label("not one of the listed values")
                    .hint("the initial value must be one of the enumeration's values");
                    0
                }
            },
            None => 0,
        };
        (out, default)
    }

    /// Resolves an alias on first use (reports cycles as unknown types).
    fn resolve_user_type(&mut self, id: TypeId) {
        let Some(d) = self.pending_aliases.remove(&id) else {
            return;
        };
        let ast::TypeDef::Alias { ty, init } = &d.def else {
            return;
        };
        // An alias chain (`t0 : t1; t1 : t2; ...`) is resolved recursively: cap its length.
        if self.resolving.len() >= crate::parser::MAX_TYPE_NESTING {
            // Reported once: every later alias of the same long chain is cut the same way.
            let first = !std::mem::replace(&mut self.alias_chain_reported, true);
            if first {
                self.error(
                    code::E0213,
                    d.name.span,
                    format!(
                        "type `{}` is defined through more than {} named types",
                        d.name.name,
                        crate::parser::MAX_TYPE_NESTING
                    ),
                )
                .label("one alias too many in the chain")
                .hint("define the type directly in terms of an elementary, structured or FB type");
            }
            self.model.types[id.0 as usize].def = UserTypeDef::Alias {
                target: Type::Error,
                init: None,
            };
            return;
        }
        self.resolving.push(id);
        let target = self.resolve_type(ty);
        self.resolving.retain(|r| *r != id);
        let init = init
            .as_ref()
            .and_then(|i| self.const_init(i, &target, &Consts::new()));
        self.model.types[id.0 as usize].def = UserTypeDef::Alias { target, init };
    }

    /// Resolves a type as written.
    pub(crate) fn resolve_type(&mut self, tr: &TypeRef) -> Type {
        match tr {
            TypeRef::Named(n) => self.resolve_named_type(n),
            TypeRef::Ref { target, .. } => match self.resolve_type(target) {
                Type::Error => Type::Error,
                t => Type::Ref(Box::new(t)),
            },
            TypeRef::String { wide, length, span } => {
                if let Some(n) = length.filter(|n| *n > STRING_CAPACITY) {
                    self.warn_string_beyond_capacity(*wide, n, *span);
                }
                Type::String {
                    wide: *wide,
                    len: length.unwrap_or_else(default_string_len),
                }
            }
            TypeRef::Array {
                dims,
                element,
                span,
            } => {
                let element = self.resolve_type(element);
                // Arrays of named array types nest as deep as the chain of names: the same cap as for
                // arrays written out (the parser's E0211), so that no later walk recurses without bound.
                let mut depth = 1;
                let mut t = &element;
                while let Type::Array { element, .. } = t {
                    depth += 1;
                    t = element;
                }
                if depth > crate::parser::MAX_TYPE_NESTING {
                    self.error(
                        code::E0211,
                        *span,
                        format!(
                            "array types nested more than {} deep (counting named array types)",
                            crate::parser::MAX_TYPE_NESTING
                        ),
                    )
                    .label("the element type is itself an array, and so on")
                    .hint("use one array with several dimensions: ARRAY [0..9, 0..9] OF INT");
                    return Type::Error;
                }
                if let Some(d) = dims.iter().find(|d| d.is_variable()) {
                    // (`st::varlen` compiles the allowed ones before sema: what reaches here is
                    // misplaced, or mixes `*` with fixed bounds)
                    let mixed = !dims.iter().all(|d| d.is_variable());
                    self.error(
                        code::E1072,
                        d.span,
                        if mixed {
                            "a variable-length array has `*` in every dimension or in none".to_string()
                        } else {
                            "a variable-length array `ARRAY [*]` is allowed only as a VAR_IN_OUT of a FUNCTION, FUNCTION_BLOCK or METHOD (IEC 61131-3 edition 3, 6.5.3)".to_string()
                        },
                    )
                    .label("variable-length dimension")
                    .hint(if mixed {
                        "write `ARRAY [*, *] OF T` (the caller's bounds in every dimension) or constant bounds in every dimension"
                    } else {
                        "declare it in a VAR_IN_OUT block of a function, function block or method with an ST body, or give it constant bounds (`ARRAY [1..N] OF T`)"
                    });
                    return Type::Error;
                }
                for d in dims {
                    if d.upper < d.lower {
                        self.error(
                            code::E1003,
                            d.span,
                            format!("empty array range {}..{}", d.lower, d.upper),
                        )
                        .label("the upper bound is below the lower bound")
                        .hint("write the bounds as lower..upper");
                    }
                }
                let dims = dims
                    .iter()
                    .map(|d| Dim {
                        lower: d.lower,
                        upper: d.upper,
                    })
                    .collect();
                if element.is_error() {
                    return Type::Error;
                }
                Type::Array {
                    dims,
                    element: Box::new(element),
                }
            }
            TypeRef::Subrange {
                base,
                lower,
                upper,
                span,
            } => match Elementary::from_name(&base.name) {
                Some(e) if e.is_integer() => {
                    let (lo, hi) = e.int_range().unwrap_or((*lower, *upper));
                    if lower > upper || *lower < lo || *upper > hi {
                        self.error(
                            code::E1003,
                            *span,
                            format!("invalid subrange {lower}..{upper} of {}", e.name()),
                        )
                        .label("bounds out of order or outside the base type")
                        .hint(format!("{} holds {lo}..{hi}", e.name()));
                        return Type::Error;
                    }
                    Type::Subrange {
                        base: e,
                        lower: Box::new(*lower),
                        upper: Box::new(*upper),
                    }
                }
                _ => {
                    self.error(
                        code::E1003,
                        base.span,
                        format!("a subrange needs an integer base type, not `{}`", base.name),
                    )
                    .label("not an integer type")
                    .hint("use SINT, INT, DINT, LINT or an unsigned integer type");
                    Type::Error
                }
            },
            TypeRef::Enum { values, span } => {
                let id = TypeId(self.model.types.len() as u32);
                self.enum_counter += 1;
                let (values, default) = self.enum_values_of(id, values, None);
                self.model.types.push(UserType {
                    name: format!("__ENUM_{}", self.enum_counter),
                    span: *span,
                    def: UserTypeDef::Enum { values, default },
                    union: false,
                    to_string: false,
                    strict: false,
                });
                Type::Enum(id)
            }
        }
    }

    /// W1468 at a `STRING(n)`/`WSTRING(n)` declared longer than the 254 characters every string holds
    /// (README, memory model: an `IEC_STRING` of 258 bytes); once per declaration. TwinCAT accepts
    /// `STRING(511)` and more ("TwinCAT does not limit the string length in principle", TwinCAT 3
    /// manual, STRING); IEC 61131-3 ed. 3 leaves the maximum length to the implementation.
    fn warn_string_beyond_capacity(&mut self, wide: bool, declared: u32, span: crate::Span) {
        if self.silent || !self.long_strings_at.insert((span.file, span.start)) {
            return;
        }
        let kw = if wide { "WSTRING" } else { "STRING" };
        self.warning(
            code::W1468,
            span,
            format!(
                "`{kw}({declared})` holds at most {STRING_CAPACITY} characters in ladderc, not {declared}"
            ),
        )
        .label(format!("every {kw} holds {STRING_CAPACITY} characters; longer values are cut"))
        .hint(format!(
            "keep the texts to {STRING_CAPACITY} characters, or split them over several variables (README, memory model)"
        ));
    }

    fn resolve_named_type(&mut self, n: &ast::Ident) -> Type {
        if let Some(e) = Elementary::from_name(&n.name) {
            return Type::Elementary(e);
        }
        if n.is("STRING") || n.is("WSTRING") {
            return Type::String {
                wide: n.is("WSTRING"),
                len: default_string_len(),
            };
        }
        if let Some(&id) = self.type_names.get(&n.key()) {
            if self.resolving.contains(&id) {
                self.error(
                    code::E1003,
                    n.span,
                    format!("type `{}` is defined in terms of itself", n.name),
                )
                .label("refers back to the type being defined")
                .hint("an alias must end at an elementary, structured or FB type");
                return Type::Error;
            }
            if self.pending_aliases.contains_key(&id) {
                self.resolve_user_type(id);
            }
            return match &self.model.types[id.0 as usize].def {
                UserTypeDef::Struct { .. } => Type::Struct(id),
                UserTypeDef::Enum { .. } => Type::Enum(id),
                UserTypeDef::Alias { target, .. } => target.clone(),
            };
        }
        if let Some(e) = pointer_sized(&n.name) {
            return Type::Elementary(e);
        }
        if let Some(&id) = self.pou_names.get(&n.key()) {
            let kind = self.model.pous[id.0 as usize].kind;
            if kind == ast::PouKind::FunctionBlock {
                return Type::Fb(FbType::User(id));
            }
            let what = if kind == ast::PouKind::Program {
                "program"
            } else {
                "function"
            };
            self.error(
                code::E1003,
                n.span,
                format!("`{}` is a {what}, not a type", n.name),
            )
            .label("not a type")
            .hint("variables can have elementary, user-defined or function block types");
            return Type::Error;
        }
        if let Some(fb) = StdFb::from_name(&n.name) {
            // `CTU` of a CODESYS or TwinCAT file is its library's, counting in WORD (a name of
            // edition 3, `CTU_INT`, is IEC's INT counter everywhere)
            let vendor = super::is_codesys_file(n.span.file)
                && ["CTU", "CTD", "CTUD"].iter().any(|c| n.is(c));
            let fb = if vendor { fb.in_vendor_file() } else { fb };
            return Type::Fb(FbType::Standard(fb));
        }
        if n.is("EXCEPTIONCODE") {
            // TwinCAT's `__SYSTEM.ExceptionCode`, the type of `__CATCH(exc)`'s variable (W1427:
            // never written): its 32-bit code
            return Type::Elementary(Elementary::Udint);
        }
        let hint = match vendor_block(&n.name) {
            Some(library) => format!(
                "`{}` is a block of {library}, which ladderc does not provide: declare it as a FUNCTION_BLOCK in the project (or give its library's source with --lib)",
                n.name
            ),
            None => {
                "declare it in a TYPE block or as a FUNCTION_BLOCK, or use an elementary type".into()
            }
        };
        // one E1003 per unknown type, counting its uses (a library block for three instances is
        // one cause)
        if !self.silent {
            let key = n.key();
            if let Some((_, first, others)) =
                self.unknown_types.iter_mut().find(|(k, ..)| *k == key)
            {
                if *first != n.span && !others.contains(&n.span) {
                    others.push(n.span);
                }
                return Type::Error;
            }
            self.unknown_types.push((key, n.span, Vec::new()));
        }
        self.error(code::E1003, n.span, format!("unknown type `{}`", n.name))
            .label("no such type")
            .hint(hint);
        Type::Error
    }

    /// Declares the variables of `blocks` (of a POU of kind `pou`, or of a structure or global list when
    /// `None`); reports duplicates within them and misplaced `R_EDGE`/`F_EDGE` qualifiers.
    pub(crate) fn declare_vars(
        &mut self,
        blocks: &[VarBlock],
        consts: &Consts,
        pou: Option<ast::PouKind>,
    ) -> Vec<Variable> {
        // Sized once: a ladder program can declare tens of thousands of variables in one POU, and
        // regrowing these (a copy of every `Variable` per doubling) showed in its profile.
        let declared: usize = blocks.iter().map(|b| b.vars.len()).sum();
        let mut out: Vec<Variable> = Vec::with_capacity(declared);
        // Names seen so far, as positions in `out`, per global variable list ("" outside named
        // lists): found ignoring case without an upper-cased key per variable.
        let mut seen: HashMap<String, crate::name_index::NameIndex> = HashMap::new();
        let mut consts = consts.clone();
        // a POU's own constants first: an initial value may name one declared below it (`tmr :
        // TON := (PT := DELAY);` above `VAR CONSTANT DELAY : TIME := T#1S;`), as CODESYS and
        // TwinCAT resolve names, not order (their errors, if any, are the same as below: shown once)
        // (and a configuration's or resource's constants likewise, for its globals' initial values)
        let own: Vec<&ast::VarDecl> = blocks
            .iter()
            .filter(|b| b.constant)
            .flat_map(|b| &b.vars)
            .collect();
        if !own.is_empty() {
            self.constants_in_any_order(&own, &mut consts, false);
        }
        for b in blocks {
            // the members of a named global variable list (CODESYS GVL) are seen per list: two
            // lists may both declare `x` (reached as GVL_A.x and GVL_B.x)
            let list_key = match (&b.name, pou) {
                (Some(l), None) => format!("{}.", l.key()),
                _ => String::new(),
            };
            for d in &b.vars {
                let ty = self.resolve_type(&d.ty);
                let init = match &d.init {
                    Some(i) => self.const_init(i, &ty, &consts),
                    None => self.type_default_init(&d.ty),
                };
                let list_seen = match seen.get_mut(&list_key) {
                    Some(l) => l,
                    None => seen.entry(list_key.clone()).or_insert_with(|| {
                        crate::name_index::NameIndex::with_capacity(b.vars.len())
                    }),
                };
                if let Some(prev) = list_seen.find(&d.name.name, |p| out[p].name.as_str()) {
                    let first = out[prev].span;
                    self.error(
                        code::E1002,
                        d.name.span,
                        format!("`{}` is declared twice", d.name.name),
                    )
                    .label("declared again here")
                    .also(first, "first declared here")
                    .hint("each variable of a POU needs its own name (names are case-insensitive)");
                    continue;
                }
                let twincat_word = twincat_configuration_word(&d.name.name, d.name.span.file);
                let accepted = configuration_keyword(&d.name.name)
                    .map(|w| (w, "CODESYS and TwinCAT do"))
                    .or(twincat_word.map(|w| (w, "TwinCAT does")));
                if let Some((word, who)) = accepted {
                    self.warning(
                        code::W1418,
                        d.name.span,
                        format!(
                            "`{}` is a keyword of IEC 61131-3 configurations (`{word}`): accepted as a variable name, as {who}",
                            d.name.name
                        ),
                    )
                    .label("configuration keyword")
                    .hint(format!(
                        "for portable IEC 61131-3 code rename the variable, for example `x{}`",
                        d.name.name
                    ));
                }
                let edge_word = twincat_edge_word(&d.name.name, d.name.span.file);
                if edge_word && !self.declaring_fields {
                    self.warning(
                        code::W1451,
                        d.name.span,
                        format!(
                            "`{}` is an IEC 61131-3 edge qualifier (`x : BOOL R_EDGE;`): accepted as a variable name, as TwinCAT does",
                            d.name.name
                        ),
                    )
                    .label("edge qualifier")
                    .hint(format!(
                        "for portable IEC 61131-3 code rename the variable, for example `fb{}`",
                        d.name.name
                    ));
                }
                // a structure's field named with a keyword, an elementary type or a standard
                // block (`Continue`, `Type`, `byte`, `tp`: B&R's and CODESYS's libraries) is read
                // only after `.` (`s.tp`), where none of them can stand: accepted
                // as are the inputs and outputs of a B&R library block's `.fun` declaration
                // (`Type`, `Configuration`, `string` of B&R's own libraries), read only as
                // `blk(Type := x)` and `blk.Type`
                let keyword_parameter = self
                    .keyword_parameters
                    .contains(&(d.name.span.file, d.name.span.start));
                // a standard block's name in a TwinCAT object (`ton : TON;`): Beckhoff's keywords
                // have no block and its "Shading rules" let a variable be named like a block
                // (Infosys, TwinCAT 3 PLC): accepted, W1456; elsewhere E1031 as the standard says
                let twincat_block = reserved_name(&d.name.name) == Some(STANDARD_BLOCK)
                    && super::is_twincat_file(d.name.span.file);
                if twincat_block && !self.declaring_fields {
                    self.warning(
                        code::W1456,
                        d.name.span,
                        format!(
                            "`{}` is the name of a standard function block, which IEC 61131-3 reserves: accepted as a variable name, as TwinCAT does",
                            d.name.name
                        ),
                    )
                    .label("standard function block's name")
                    .hint(format!(
                        "for portable IEC 61131-3 code rename the variable, for example `fb{}`",
                        d.name.name
                    ));
                }
                if let Some(why) = reserved_name(&d.name.name).filter(|_| {
                    !self.declaring_fields
                        && !keyword_parameter
                        && twincat_word.is_none()
                        && !twincat_block
                        && !edge_word
                }) {
                    // reported once, at the declaration; the variable is kept so that its uses
                    // give no further errors
                    self.error(
                        code::E1031,
                        d.name.span,
                        format!(
                            "`{}` is reserved in IEC 61131-3 ({why}): it cannot name a variable",
                            d.name.name
                        ),
                    )
                    .label("reserved name")
                    .hint(format!(
                        "rename the variable, for example `x{}`",
                        d.name.name
                    ));
                }
                if b.constant {
                    if let Some(v) = &init {
                        consts.insert(d.name.key(), (ty.clone(), v.clone()));
                    }
                }
                if let Some(loc) = &d.location {
                    self.check_bit_location(d, loc, &ty);
                }
                let edge = d
                    .edge
                    .filter(|e| self.edge_allowed(*e, d, b.kind, &ty, pou));
                let position = out.len();
                out.push(Variable {
                    name: d.name.name.clone(),
                    span: d.name.span,
                    kind: b.kind,
                    ty,
                    constant: b.constant,
                    retain: b.retain,
                    location: d.location.as_ref().map(Location::of),
                    init,
                    edge,
                });
                list_seen.insert(&d.name.name, position, |p| out[p].name.as_str());
            }
        }
        // a global list's: once every global is declared (`global_address_initial_values`)
        if pou.is_some() || self.declaring_fields {
            self.address_initial_values(blocks, &mut out, pou);
        }
        out
    }

    /// E1027: a variable located at a single bit (`%QX0.0`, or `%Q0.0` without a size letter) whose
    /// type (or array element type) is not BOOL: the bit cannot hold the value (ZPLC's HIL tests
    /// declare `a AT %Q0.0 : INT`; before, the value was silently cut to one bit).
    /// `%Q*` (not yet located, no size letter: the VAR_CONFIG or the tool places it) takes any type.
    /// The fields of structure `name` without their locations: a placeholder `AT %I*` (TwinCAT's
    /// DUTs, linked by the I/O configuration) makes a plain field of each instance (W0322, once per
    /// type); a fixed address is E1055 (every instance would share it), the field read as plain.
    fn unlocated_fields(&mut self, name: &str, fields: &[ast::VarDecl]) -> Vec<ast::VarDecl> {
        let mut out = fields.to_vec();
        let mut placeholders: Vec<Span> = Vec::new();
        for f in &mut out {
            let Some(loc) = f.location.take() else {
                continue;
            };
            if loc.path.is_empty() {
                placeholders.push(loc.span);
                continue;
            }
            self.error(
                code::E1055,
                loc.span,
                format!(
                    "the field `{}` of `{name}` is at a fixed address: every instance would share it",
                    f.name.name
                ),
            )
            .label("fixed address in a structure type")
            .hint("declare the located variable outside the structure and copy it into the field, or write the placeholder `AT %I*`");
        }
        if let (Some(&first), false) = (placeholders.first(), self.silent) {
            self.diags.push(
                Diagnostic::new(
                    code::W0322,
                    Severity::Note,
                    format!(
                        "{} field(s) of `{name}` declared `AT %I*`/`%Q*`/`%M*`: read as plain fields of each instance",
                        placeholders.len()
                    ),
                )
                .at(first)
                .with_primary_label("placeholder address")
                .with_hint("TwinCAT links such fields in its I/O configuration; set them with --stimulus by their path, read them with --watch"),
            );
        }
        out
    }

    fn check_bit_location(&mut self, d: &ast::VarDecl, loc: &ast::DirectAddress, ty: &Type) {
        if loc.size != ast::AddressSize::Bit || loc.path.is_empty() {
            return;
        }
        let mut t = ty;
        while let Type::Array { element, .. } = t {
            t = element;
        }
        if t.is_error() || matches!(t, Type::Elementary(Elementary::Bool)) {
            return;
        }
        let tn = self.type_name(ty);
        let area = match loc.area {
            ast::Area::Input => "I",
            ast::Area::Output => "Q",
            ast::Area::Memory => "M",
        };
        let path: Vec<String> = loc.path.iter().map(u32::to_string).collect();
        let text = format!("%{area}X{}", path.join("."));
        self.error(
            code::E1027,
            loc.span,
            format!(
                "`{}` has type {tn}, but `{text}` is a single bit: a bit address holds a BOOL",
                d.name.name
            ),
        )
        .label("a bit address")
        .hint("locate the variable at an address of its size (%QB byte, %QW word, %QD double word, %QL long word), or declare it BOOL");
    }

    /// Whether an edge qualifier is where IEC 61131-3 allows it (a BOOL `VAR_INPUT` of a
    /// FUNCTION_BLOCK); reports E1100/E1101 otherwise.
    fn edge_allowed(
        &mut self,
        edge: ast::Edge,
        d: &ast::VarDecl,
        kind: VarKind,
        ty: &Type,
        pou: Option<ast::PouKind>,
    ) -> bool {
        let kw = edge.keyword();
        if pou != Some(ast::PouKind::FunctionBlock) || kind != VarKind::Input {
            let place = match pou {
                Some(ast::PouKind::FunctionBlock) => "this variable block of a function block",
                Some(ast::PouKind::Program) => "a program",
                Some(ast::PouKind::Function) => "a function",
                None => "a structure or a global variable list",
            };
            self.error(
                code::E1100,
                d.span,
                format!("`{kw}` is not allowed in {place}"),
            )
            .label(format!("`{}` is declared {kw} here", d.name.name))
            .hint("edge-triggered declarations are only for VAR_INPUT of a FUNCTION_BLOCK; use an R_TRIG or F_TRIG instance elsewhere");
            return false;
        }
        if !ty.is_error() && !ty.is_bool() {
            let tn = self.type_name(ty);
            self.error(
                code::E1101,
                d.span,
                format!("`{kw}` input `{}` is {tn}, not BOOL", d.name.name),
            )
            .label(format!("this input is {tn}"))
            .hint("only BOOL inputs can be edge-triggered; declare it BOOL or drop the qualifier");
            return false;
        }
        true
    }

    /// The blocks without the structured initial values of their instances of user blocks and
    /// classes (whose variables are not declared yet): those values, keyed by the variable's name
    /// span, and the blocks to declare (the same ones, copied only when one was taken out).
    fn hold_block_inits<'b>(
        &self,
        blocks: &'b [ast::VarBlock],
    ) -> (
        Vec<(Span, ast::Initializer)>,
        std::borrow::Cow<'b, [ast::VarBlock]>,
    ) {
        let is_held = |d: &ast::VarDecl| {
            matches!(d.init, Some(ast::Initializer::Struct(..)))
                && matches!(&d.ty, TypeRef::Named(n) if self.pou_names.contains_key(&n.key()))
        };
        let held: Vec<(Span, ast::Initializer)> = blocks
            .iter()
            .flat_map(|b| b.vars.iter())
            .filter(|d| is_held(d))
            .filter_map(|d| d.init.clone().map(|i| (d.name.span, i)))
            .collect();
        if held.is_empty() {
            return (held, std::borrow::Cow::Borrowed(blocks));
        }
        let mut copy = blocks.to_vec();
        for d in copy.iter_mut().flat_map(|b| b.vars.iter_mut()) {
            if is_held(d) {
                d.init = None;
            }
        }
        (held, std::borrow::Cow::Owned(copy))
    }

    /// The initial value a named alias type gives (`TYPE T : INT := 5`).
    fn type_default_init(&mut self, tr: &TypeRef) -> Option<ConstValue> {
        if let TypeRef::Named(n) = tr {
            if let Some(&id) = self.type_names.get(&n.key()) {
                if let UserTypeDef::Alias { init, .. } = &self.model.types[id.0 as usize].def {
                    return init.clone();
                }
            }
        }
        None
    }

    fn declare_pou(&mut self, id: PouId, p: &ast::Pou, global_consts: &Consts) {
        let return_type = p.return_type.as_ref().map(|t| self.resolve_type(t));
        // (a FUNCTION without result type returns no value: see `Parser::pou`)
        let vars = self.declare_vars(&p.var_blocks, global_consts, Some(p.kind));
        let mut externals = Vec::new();
        for (i, v) in vars.iter().enumerate() {
            if v.kind == VarKind::External {
                if let Some(r) = self.bind_external(v) {
                    externals.push((i, r));
                }
            }
            if p.kind == ast::PouKind::Function && v.is(&p.name.name) {
                self.error(
                    code::E1002,
                    v.span,
                    format!("`{}` is the name of the function's result", v.name),
                )
                .label("declared again here")
                .also(p.name.span, "the function's name is its result variable")
                .hint("rename the variable");
            }
        }
        let pou = &mut self.model.pous[id.0 as usize];
        pou.return_type = return_type;
        pou.set_vars(vars);
        pou.externals = externals;
    }

    /// Finds the global a `VAR_EXTERNAL` refers to and checks the declarations agree.
    fn bind_external(&mut self, v: &Variable) -> Option<GlobalRef> {
        if self.ambiguous_global(&ast::Ident::new(v.name.clone(), v.span)) {
            return None;
        }
        let found = self.find_global(&v.name);
        let Some(r) = found else {
            self.error(code::E1022, v.span, format!("no global variable `{}`", v.name))
                .label("declared VAR_EXTERNAL here")
                .hint("declare it in a VAR_GLOBAL block of the configuration (or outside any configuration)");
            return None;
        };
        let g = self.model.global(r).clone();
        if !v.ty.is_error() && !g.ty.is_error() && g.ty != v.ty {
            let (gt, vt) = (self.type_name(&g.ty), self.type_name(&v.ty));
            self.error(
                code::E1022,
                v.span,
                format!("external `{}` is {vt} but the global is {gt}", v.name),
            )
            .label(format!("declared {vt} here"))
            .also(g.span, format!("global declared {gt} here"))
            .hint("declare the external with the global's type");
        } else if g.constant && !v.constant {
            self.error(
                code::E1022,
                v.span,
                format!("global `{}` is CONSTANT but its external is not", v.name),
            )
            .label("declare this block VAR_EXTERNAL CONSTANT")
            .also(g.span, "constant global declared here")
            .hint("write VAR_EXTERNAL CONSTANT");
        }
        Some(r)
    }

    /// E1030 when `name` is declared by two or more global variable lists (and nothing nearer has
    /// that name): an unqualified use cannot choose. Returns whether it was reported.
    pub(super) fn ambiguous_global(&mut self, name: &ast::Ident) -> bool {
        let lists: Vec<(String, Span)> = self
            .model
            .lists_declaring(&name.name)
            .iter()
            .map(|l| {
                let r = self
                    .model
                    .list_member(l, &name.name)
                    .expect("declared by the list");
                (l.name.clone(), self.model.global(r).span)
            })
            .collect();
        if lists.len() < 2 {
            return false;
        }
        let names: Vec<String> = lists.iter().map(|(l, _)| format!("`{l}`")).collect();
        let mut d = self
            .error(
                code::E1030,
                name.span,
                format!(
                    "`{}` is declared by the global variable lists {} and {}",
                    name.name,
                    names[..names.len() - 1].join(", "),
                    names[names.len() - 1]
                ),
            )
            .label("ambiguous: qualify it with its list");
        for (l, at) in &lists {
            d = d.also(*at, format!("declared in `{l}`"));
        }
        drop(d.hint(format!(
            "write {}.{} (or the other list's name)",
            lists[0].0, name.name
        )));
        true
    }

    /// The global variable of a name: outside any configuration first, then of each configuration and
    /// its resources in source order.
    pub(super) fn find_global(&self, name: &str) -> Option<GlobalRef> {
        let key = name.to_ascii_uppercase();
        if let Some(&i) = self.free_globals.get(&key) {
            return Some(GlobalRef::Free(i));
        }
        for (ci, c) in self.model.configurations.iter().enumerate() {
            if let Some(i) = c.globals.iter().position(|g| g.is(name)) {
                return Some(GlobalRef::Configuration {
                    config: ci,
                    index: i,
                });
            }
            for (ri, r) in c.resources.iter().enumerate() {
                if let Some(i) = r.globals.iter().position(|g| g.is(name)) {
                    return Some(GlobalRef::Resource {
                        config: ci,
                        resource: ri,
                        index: i,
                    });
                }
            }
        }
        None
    }

    fn declare_resource(&mut self, ci: usize, ri: usize, r: &ast::Resource) {
        let mut tasks: Vec<Task> = Vec::new();
        for t in &r.tasks {
            let positive = match &t.interval {
                Some(Operand::Literal(l)) => match l.kind {
                    ast::LiteralKind::Duration(ns) if ns > 0 => Some(ns),
                    _ => None,
                },
                _ => None,
            };
            let interval_ns = match &t.interval {
                Some(Operand::Literal(_)) if positive.is_some() => {
                    positive.and_then(|ns| u64::try_from(ns).ok())
                }
                Some(Operand::Var(_)) | None => None,
                Some(other) => {
                    self.error(
                        code::E1024,
                        other.span(),
                        "a task INTERVAL must be a positive duration",
                    )
                    .label("not a duration")
                    .hint("write INTERVAL := T#10ms");
                    None
                }
            };
            let single = match &t.single {
                Some(Operand::Var(v)) => Some(v.base.name.clone()),
                _ => None,
            };
            tasks.push(Task {
                name: t.name.name.clone(),
                span: t.span,
                interval_ns,
                single,
                priority: t.priority.unwrap_or(0),
            });
        }
        let mut programs = Vec::new();
        for p in &r.programs {
            let task = match &p.task {
                Some(tn) => {
                    match tasks.iter().position(|t| tn.is(&t.name)) {
                        Some(i) => Some(i),
                        None => {
                            self.error(code::E1024, tn.span, format!("no task `{}` in resource `{}`", tn.name, r.name.name))
                            .label("unknown task")
                            .hint("declare the task with TASK name (INTERVAL := ..., PRIORITY := ...)");
                            None
                        }
                    }
                }
                None => None,
            };
            let pou = match self.pou_names.get(&p.type_name.key()) {
                Some(&id) if self.model.pous[id.0 as usize].kind == ast::PouKind::Program => id,
                Some(_) => {
                    self.error(
                        code::E1024,
                        p.type_name.span,
                        format!("`{}` is not a PROGRAM", p.type_name.name),
                    )
                    .label("a function or function block")
                    .hint("only programs are instantiated in a resource");
                    continue;
                }
                None => {
                    self.error(
                        code::E1024,
                        p.type_name.span,
                        format!("unknown program `{}`", p.type_name.name),
                    )
                    .label("no such PROGRAM")
                    .hint("declare it with PROGRAM ... END_PROGRAM");
                    continue;
                }
            };
            let args = self.program_args(ci, ri, pou, &p.args);
            programs.push(ProgramInstance {
                name: p.name.name.clone(),
                span: p.span,
                retain: p.retain,
                task,
                pou,
                args,
            });
        }
        let res = &mut self.model.configurations[ci].resources[ri];
        res.tasks = tasks;
        res.programs = programs;
    }

    /// Binds `PROGRAM inst : P (in := g, out => h)` arguments to globals of the configuration/resource,
    /// direct addresses, or constants.
    fn program_args(
        &mut self,
        ci: usize,
        ri: usize,
        pou: PouId,
        args: &[ast::FormalArg],
    ) -> Vec<ProgramArg> {
        let mut out = Vec::new();
        if args.is_empty() {
            // The usual instance: no copy of the program's interface (tens of thousands of variables in
            // a large generated program).
            return out;
        }
        let prog = self.model.pous[pou.0 as usize].clone();
        for a in args {
            let Some(param) = prog.vars.iter().position(|v| {
                a.name.is(&v.name)
                    && matches!(v.kind, VarKind::Input | VarKind::Output | VarKind::InOut)
            }) else {
                let names: Vec<String> = prog
                    .vars
                    .iter()
                    .filter(|v| matches!(v.kind, VarKind::Input | VarKind::Output | VarKind::InOut))
                    .map(|v| v.name.clone())
                    .collect();
                self.error(
                    code::E1011,
                    a.name.span,
                    format!("program {} has no parameter `{}`", prog.name, a.name.name),
                )
                .label("unknown parameter")
                .hint(format!("parameters of {}: {}", prog.name, names.join(", ")));
                continue;
            };
            let pvar = &prog.vars[param];
            let output = matches!(a.dir, ast::ArgDir::Output { .. });
            if output != (pvar.kind == VarKind::Output) {
                let (what, fix) = if output {
                    ("an input", ":=")
                } else {
                    ("an output", "=>")
                };
                self.error(
                    code::E1013,
                    a.span,
                    format!("`{}` is {what} of program {}", pvar.name, prog.name),
                )
                .label("wrong direction")
                .hint(format!("write {} {fix} ...", pvar.name));
                continue;
            }
            let (value, vty) = match &a.value {
                Operand::Var(v) if v.accessors.is_empty() => {
                    let c = &self.model.configurations[ci];
                    let r = c
                        .globals
                        .iter()
                        .position(|g| v.base.is(&g.name))
                        .map(|index| GlobalRef::Configuration { config: ci, index });
                    let r = r.or_else(|| {
                        c.resources[ri]
                            .globals
                            .iter()
                            .position(|g| v.base.is(&g.name))
                            .map(|index| GlobalRef::Resource {
                                config: ci,
                                resource: ri,
                                index,
                            })
                    });
                    let r = r.or_else(|| {
                        self.free_globals
                            .get(&v.base.key())
                            .map(|&i| GlobalRef::Free(i))
                    });
                    match r {
                        Some(r) => {
                            let ty = self.model.global(r).ty.clone();
                            (ProgramArgValue::Global(r), ty)
                        }
                        None => {
                            self.error(
                                code::E1001,
                                v.span,
                                format!("no global variable `{}`", v.base.name),
                            )
                            .label("not a global of this configuration")
                            .hint(
                                "declare it in the configuration's or resource's VAR_GLOBAL block",
                            );
                            continue;
                        }
                    }
                }
                Operand::Address(ad) => {
                    let l = Location::of(ad);
                    let ty = Type::Elementary(l.elementary());
                    (ProgramArgValue::Address(l), ty)
                }
                other if !output => match self.const_value(other, &pvar.ty, &Consts::new()) {
                    Some(c) => (ProgramArgValue::Const(c), pvar.ty.clone()),
                    None => continue,
                },
                other => {
                    self.error(
                        code::E1026,
                        other.span(),
                        "an output argument needs a global variable or an address",
                    )
                    .label("not writable")
                    .hint("write out => a global variable");
                    continue;
                }
            };
            let ok = if output {
                super::typing::assignable(&pvar.ty, &vty)
            } else {
                super::typing::assignable(&vty, &pvar.ty)
            };
            if !ok {
                let (pt, vt) = (self.type_name(&pvar.ty), self.type_name(&vty));
                self.error(
                    code::E1012,
                    a.value.span(),
                    format!("`{}` of program {} is {pt}, not {vt}", pvar.name, prog.name),
                )
                .label(format!("this is {vt}"))
                .hint("connect a global of the parameter's type");
                continue;
            }
            out.push(ProgramArg {
                param,
                output,
                value,
            });
        }
        out
    }

    /// Evaluates an initial value against the declared type.
    pub(crate) fn const_init(
        &mut self,
        init: &Initializer,
        ty: &Type,
        consts: &Consts,
    ) -> Option<ConstValue> {
        if ty.is_error() {
            return None;
        }
        match init {
            Initializer::Value(op) => self.const_value(op, ty, consts),
            Initializer::Array(elems, span) => {
                let Type::Array { dims, element } = ty else {
                    let t = self.type_name(ty);
                    self.error(
                        code::E1025,
                        *span,
                        format!("an array initializer for a {t}"),
                    )
                    .label("not an array")
                    .hint("give a single value");
                    return None;
                };
                let total: u128 = dims.iter().fold(1u128, |n, d| n.saturating_mul(d.len()));
                let mut out = Vec::new();
                for e in elems {
                    // `[(0)]`, `2(0)`: B&R Automation Studio's zero initializer of a structure
                    // element, its type's initial value, as `(0)` of a whole structure and
                    // `9((0))` are (round 27, before: E1025)
                    let zero = matches!(
                        &e.value,
                        Initializer::Value(Operand::Literal(l))
                            if matches!(l.kind, crate::ast::LiteralKind::Int(0)) && l.type_prefix.is_none()
                    ) && matches!(**element, Type::Struct(_));
                    let null = matches!(&e.value,
                        Initializer::Value(Operand::Var(v)) if v.base.is("NULL") && v.accessors.is_empty());
                    let v = match ((null && matches!(**element, Type::Ref(_))) || zero)
                        .then(|| ConstValue::Struct(Vec::new()))
                        .or_else(|| self.const_init(&e.value, element, consts))
                    {
                        // (`[ADR(a), NULL]`: a reference element that starts as NULL, empty: the
                        // type's default)
                        Some(v) => v,
                        // `[ADR(a), ADR(b)]`: set once every variable is declared, in the
                        // element's place (`address_init`); an empty value is the type's default
                        None if matches!(&e.value, Initializer::Value(Operand::Ref(r)) if r.of.is_some()) => {
                            ConstValue::Struct(Vec::new())
                        }
                        None => return None,
                    };
                    for _ in 0..e.repeat.unwrap_or(1) {
                        if out.len() as u128 >= total {
                            self.error(
                                code::E1025,
                                *span,
                                format!("too many initial values: the array has {total} elements"),
                            )
                            .label("initializer too long")
                            .hint("give at most one value per element");
                            return None;
                        }
                        out.push(v.clone());
                    }
                }
                Some(ConstValue::Array(out))
            }
            Initializer::Struct(fields, span) => {
                let mut out = Vec::new();
                for (name, value) in fields {
                    let field_ty = match ty {
                        Type::Struct(id) => match &self.model.types[id.0 as usize].def {
                            UserTypeDef::Struct { fields } => fields
                                .iter()
                                .find(|f| name.is(&f.name))
                                .map(|f| f.ty.clone()),
                            _ => None,
                        },
                        Type::Fb(FbType::Standard(fb)) => super::stdlib::fb_params(*fb)
                            .iter()
                            .find(|p| name.is(p.name) && p.dir == super::stdlib::Dir::Input)
                            .map(|p| Type::Elementary(p.ty)),
                        Type::Fb(FbType::User(id)) => {
                            let pou = &self.model.pous[id.0 as usize];
                            // a class's PRIVATE or PROTECTED variable is not set from outside
                            // (IEC 61131-3 ed. 3 6.6.5.3; PUBLIC and INTERNAL ones are)
                            let hidden = pou
                                .access
                                .iter()
                                .find(|(n, _)| name.is(n))
                                .map(|&(_, a)| a)
                                .filter(|a| *a != crate::ast::Access::Public);
                            if let Some(a) = hidden {
                                let (pn, kw) = (pou.name.clone(), a.keyword());
                                self.error(
                                    code::E1025,
                                    name.span,
                                    format!(
                                        "`{}` is {kw} to `{pn}`: an initial value sets only its PUBLIC variables",
                                        name.name
                                    ),
                                )
                                .label(format!("a {kw} variable"))
                                .hint(format!("set it in a method of `{pn}`, or declare it in a VAR PUBLIC block"));
                                continue;
                            }
                            pou.vars
                                .iter()
                                .find(|v| {
                                    v.is(&name.name)
                                        && matches!(
                                            v.kind,
                                            VarKind::Input | VarKind::Local | VarKind::Output
                                        )
                                })
                                .map(|v| v.ty.clone())
                        }
                        _ => {
                            let t = self.type_name(ty);
                            self.error(
                                code::E1025,
                                *span,
                                format!("a structure initializer for a {t}"),
                            )
                            .label("not a structure or FB")
                            .hint("give a single value");
                            return None;
                        }
                    };
                    let Some(field_ty) = field_ty else {
                        let t = self.type_name(ty);
                        self.error(
                            code::E1025,
                            name.span,
                            format!("{t} has no field or input `{}`", name.name),
                        )
                        .label("unknown field")
                        .hint("initialize the fields the type declares");
                        continue;
                    };
                    if let Some(v) = self.const_init(value, &field_ty, consts) {
                        out.push((name.name.clone(), v));
                    }
                }
                Some(ConstValue::Struct(out))
            }
        }
    }

    fn const_value(&mut self, op: &Operand, ty: &Type, consts: &Consts) -> Option<ConstValue> {
        let tn = self.type_name(ty);
        if let Some(n) = ty
            .is_integer()
            .then(|| self.loose_enum_number(op, consts))
            .flatten()
        {
            return match ty.elementary().and_then(|e| e.int_range()) {
                Some((lo, hi)) if n < lo || n > hi => {
                    self.error(
                        code::E1017,
                        op.span(),
                        format!("initial value {n} does not fit {tn}"),
                    )
                    .label("out of range")
                    .hint(format!("use a value in the range of {tn} or a wider type"));
                    None
                }
                _ => Some(ConstValue::Int(n)),
            };
        }
        // an integer for an enumeration without {attribute 'strict'}: `loose_enum`
        if let Some(v) = self.integer_initial_value(op, ty, consts) {
            return v;
        }
        match op {
            Operand::Literal(lit) => {
                self.check_single_byte(lit);
                let lt = match literal_type(lit) {
                    Ok(t) => t,
                    Err(e) => {
                        self.error(code::E1017, lit.span, e.message)
                            .label("out of range")
                            .hint(e.hint);
                        return None;
                    }
                };
                let ok = match &lt {
                    LitType::Known(t) => super::typing::assignable(t, ty),
                    LitType::Int(v) => match literal_fits(*v, *v, false, ty) {
                        Ok(()) => true,
                        Err(FitError::Range(v)) => {
                            self.error(
                                code::E1017,
                                lit.span,
                                format!("initial value {v} does not fit {tn}"),
                            )
                            .label("out of range")
                            .hint(format!("use a value in the range of {tn} or a wider type"));
                            return None;
                        }
                        Err(FitError::Kind) => false,
                    },
                    LitType::Real(v) if !super::typing::real_fits(v.abs(), ty) => {
                        self.error(
                            code::E1017,
                            lit.span,
                            format!("initial value {v:E} is beyond the range of {tn}"),
                        )
                        .label("out of range")
                        .hint(format!(
                            "{tn} holds magnitudes up to 3.4028235E38; write a smaller value or use LREAL"
                        ));
                        return None;
                    }
                    LitType::Real(_) => literal_fits(0, 0, true, ty).is_ok(),
                    // `'A'`: a STRING, or (edition 3) a CHAR; `"A"` a WSTRING or a WCHAR
                    LitType::Char(wide) => match ty {
                        Type::String { wide: w, .. } => w == wide,
                        t => {
                            t.elementary()
                                == Some(if *wide {
                                    Elementary::Wchar
                                } else {
                                    Elementary::Char
                                })
                        }
                    },
                };
                if !ok {
                    self.error(
                        code::E1025,
                        lit.span,
                        format!("this initial value is not a {tn}"),
                    )
                    .label(format!("expected {tn}"))
                    .hint("give a literal of the declared type");
                    return None;
                }
                Some(literal_value(lit, ty))
            }
            Operand::EnumValue(e) => {
                let (type_name, value, span) = (&e.type_name, &e.value, &e.span);
                let Type::Enum(id) = ty else {
                    self.error(
                        code::E1025,
                        *span,
                        format!("an enumerated value for a {tn}"),
                    )
                    .label(format!("expected {tn}"))
                    .hint("give a literal of the declared type");
                    return None;
                };
                let ut = &self.model.types[id.0 as usize];
                if !type_name.is(&ut.name) {
                    self.error(
                        code::E1025,
                        *span,
                        format!("`{}` is not of type {tn}", type_name.name),
                    )
                    .label(format!("expected {tn}"))
                    .hint("use a value of the declared enumeration");
                    return None;
                }
                self.enum_index(*id, value)
            }
            Operand::Var(v) if v.accessors.is_empty() => {
                if let Type::Enum(id) = ty {
                    if let Some(c) = self.enum_index_quiet(*id, &v.base.name) {
                        return Some(c);
                    }
                    if !consts.contains_key(&v.base.key()) {
                        return self.enum_index(*id, &v.base);
                    }
                }
                match consts.get(&v.base.key()) {
                    Some((cty, val)) if super::typing::assignable(cty, ty) => Some(val.clone()),
                    Some((cty, _)) => {
                        let ct = self.type_name(cty);
                        self.error(
                            code::E1025,
                            v.span,
                            format!("constant `{}` is {ct}, not {tn}", v.base.name),
                        )
                        .label(format!("expected {tn}"))
                        .hint("use a constant of the declared type");
                        None
                    }
                    None => {
                        self.error(code::E1025, v.span, format!("`{}` is not a constant known here", v.base.name))
                            .label("not a constant")
                            .hint("initial values are literals, enumerated values, or constants (VAR CONSTANT, VAR_GLOBAL CONSTANT) of the POU, its configuration or the global lists");
                        None
                    }
                }
            }
            // `y : REAL := GVL.C1;` (CODESYS, TwinCAT): a constant of a named global list, by
            // its list's name
            Operand::Var(v)
                if !matches!(ty, Type::Enum(_))
                    && self.model.global_list(&v.base.name).is_some()
                    && matches!(&v.accessors[..], [crate::ast::Accessor::Field(m)]
                        if consts.contains_key(&m.key())) =>
            {
                let [crate::ast::Accessor::Field(member)] = &v.accessors[..] else {
                    return None;
                };
                let plain = Operand::Var(ast::VarRef {
                    base: member.clone(),
                    accessors: Default::default(),
                    span: v.span,
                });
                self.const_value(&plain, ty, consts)
            }
            // `p : POINTER TO INT := ADR(a);`, `fbM : FB_M := (pLamp := ADR(lamp))`: set once
            // every variable of the POU is declared, or refused (`address_init`)
            Operand::Ref(r) if r.of.is_some() => None,
            // `E_State.Init` (CODESYS, TwinCAT): a value qualified by its enumeration's name
            Operand::Var(v)
                if matches!(ty, Type::Enum(id)
                    if v.base.is(&self.model.types[id.0 as usize].name)
                        && matches!(&v.accessors[..], [crate::ast::Accessor::Field(_)])) =>
            {
                let (Type::Enum(id), [crate::ast::Accessor::Field(value)]) = (ty, &v.accessors[..])
                else {
                    return None;
                };
                self.enum_index(*id, value)
            }
            other => {
                self.error(
                    code::E1025,
                    other.span(),
                    "an initial value must be a constant",
                )
                .label("not a constant")
                .hint(
                    "initial values are literals, enumerated values, or constants (VAR CONSTANT, VAR_GLOBAL CONSTANT) of the POU, its configuration or the global lists",
                );
                None
            }
        }
    }

    /// The number of the enumerated value `op` names for an integer initial value (`N : INT :=
    /// E_Topic.COUNT_OF;`, `E_Topic#COUNT_OF`, or `COUNT_OF` alone when no constant has that name
    /// and one enumeration only declares it), when its enumeration is declared without
    /// `{attribute 'strict'}` (CODESYS and TwinCAT take it as its number; `super::loose_enum`).
    fn loose_enum_number(&self, op: &Operand, consts: &Consts) -> Option<i128> {
        let (id, value) = match op {
            Operand::EnumValue(e) => (self.model.type_by_name(&e.type_name.name)?, &e.value.name),
            Operand::Var(v) => match &v.accessors[..] {
                [crate::ast::Accessor::Field(value)] => {
                    (self.model.type_by_name(&v.base.name)?, &value.name)
                }
                [] if !consts.contains_key(&v.base.key()) => {
                    match self.enum_values.get(&v.base.key()).map(Vec::as_slice) {
                        Some([(id, _)]) => (*id, &v.base.name),
                        _ => return None,
                    }
                }
                _ => return None,
            },
            _ => return None,
        };
        let ut = self.model.user_type(id);
        match &ut.def {
            UserTypeDef::Enum { values, .. } if !ut.strict => values
                .iter()
                .find(|(n, _)| n.eq_ignore_ascii_case(value))
                .map(|(_, number)| *number),
            _ => None,
        }
    }

    fn enum_index_quiet(&self, id: TypeId, value: &str) -> Option<ConstValue> {
        match &self.model.types[id.0 as usize].def {
            UserTypeDef::Enum { values, .. } => values
                .iter()
                .position(|(n, _)| n.eq_ignore_ascii_case(value))
                .map(|index| ConstValue::Enum { ty: id, index }),
            _ => None,
        }
    }

    fn enum_index(&mut self, id: TypeId, value: &ast::Ident) -> Option<ConstValue> {
        let r = self.enum_index_quiet(id, &value.name);
        if r.is_none() {
            let t = self.model.types[id.0 as usize].name.clone();
            self.error(
                code::E1001,
                value.span,
                format!("`{}` is not a value of {t}", value.name),
            )
            .label("unknown enumerated value")
            .hint(format!("use one of the values declared for {t}"));
        }
        r
    }
}

/// The keywords [`reserved_name`] refuses.
const KEYWORDS: &[&str] = &[
    "IF",
    "THEN",
    "ELSIF",
    "ELSE",
    "END_IF",
    "CASE",
    "OF",
    "END_CASE",
    "FOR",
    "TO",
    "BY",
    "DO",
    "END_FOR",
    "WHILE",
    "END_WHILE",
    "REPEAT",
    "UNTIL",
    "END_REPEAT",
    "EXIT",
    "CONTINUE",
    "RETURN",
    "AND",
    "OR",
    "XOR",
    "NOT",
    "MOD",
    "TRUE",
    "FALSE",
    "VAR",
    "VAR_INPUT",
    "VAR_OUTPUT",
    "VAR_IN_OUT",
    "VAR_TEMP",
    "VAR_EXTERNAL",
    "VAR_GLOBAL",
    "VAR_ACCESS",
    "VAR_CONFIG",
    "END_VAR",
    "CONSTANT",
    "RETAIN",
    "NON_RETAIN",
    "AT",
    "ARRAY",
    "STRUCT",
    "END_STRUCT",
    "TYPE",
    "END_TYPE",
    "R_EDGE",
    "F_EDGE",
    "PROGRAM",
    "END_PROGRAM",
    "FUNCTION",
    "END_FUNCTION",
    "FUNCTION_BLOCK",
    "END_FUNCTION_BLOCK",
    "CONFIGURATION",
    "END_CONFIGURATION",
    "RESOURCE",
    "END_RESOURCE",
];

/// IEC 61131-3 reserves `ON`, `WITH` and `TASK` (ed. 3 Annex C) for textual configurations
/// (`RESOURCE r ON cpu`, `PROGRAM p WITH t : P;`, `TASK t (...)`). CODESYS and TwinCAT, which
/// configure tasks in the project tree and have no such text, do not list them among their
/// keywords (CODESYS help "Keywords", Beckhoff Infosys "Keywords"), and real projects name
/// variables `ON`. ladderc reads them unambiguously as names (in a configuration they stand where
/// no variable name can), so they are accepted with warning W1418 instead of E1031. The returned
/// text shows the word's place in a configuration.
pub fn configuration_keyword(name: &str) -> Option<&'static str> {
    [
        ("ON", "RESOURCE r ON cpu"),
        ("WITH", "PROGRAM p WITH t : P"),
        ("TASK", "TASK t (INTERVAL := T#10MS)"),
    ]
    .into_iter()
    .find(|(k, _)| k.eq_ignore_ascii_case(name))
    .map(|(_, place)| place)
}

/// `CONFIGURATION` and `RESOURCE` naming a variable of a TwinCAT 3 object (`Configuration :
/// ST_Config;`, an input of real projects' blocks): TwinCAT configures tasks in the project tree,
/// has no textual configuration, and its list of the keywords that cannot name a variable (Beckhoff
/// Infosys, TwinCAT 3 PLC, "Keywords") has neither, so it is accepted there with W1418 as `ON` is
/// (elsewhere, B&R's sources and IEC 61131-3 text, they stay E1031). The returned text shows the
/// word's place in a configuration.
fn twincat_configuration_word(name: &str, file: diagnostics::FileId) -> Option<&'static str> {
    [
        ("CONFIGURATION", "CONFIGURATION c ... END_CONFIGURATION"),
        ("RESOURCE", "RESOURCE r ON cpu"),
    ]
    .into_iter()
    .find(|(k, _)| k.eq_ignore_ascii_case(name))
    .filter(|_| super::is_twincat_file(file))
    .map(|(_, place)| place)
}

/// `R_EDGE` and `F_EDGE` naming a variable of a TwinCAT 3 object (`R_Edge : R_TRIG;`, real
/// projects' edge detectors): IEC 61131-3 (ed. 3) reserves them as input qualifiers, but Beckhoff's
/// list of the keywords that cannot name a variable (Infosys, TwinCAT 3 PLC, "Keywords") and its
/// list of names reserved for the future (Compiler Error C0543) have neither, so it is accepted
/// there with W1451 (elsewhere, IEC 61131-3 text, it stays E1031). In a TwinCAT declaration the
/// qualifier stands only after a BOOL input's type, never where a variable's name does.
fn twincat_edge_word(name: &str, file: diagnostics::FileId) -> bool {
    (name.eq_ignore_ascii_case("R_EDGE") || name.eq_ignore_ascii_case("F_EDGE"))
        && super::is_twincat_file(file)
}

/// What [`reserved_name`] says of a standard function block's name.
const STANDARD_BLOCK: &str = "a standard function block";

/// Why `name` cannot name a variable (IEC 61131-3 2nd ed. Annex C, 3rd ed. 6.1.3: keywords, the
/// names of the elementary data types and of the standard function blocks), or `None`. Names the
/// standard also lists but real programs use and matiec, CODESYS and ladderc read unambiguously are
/// accepted: the IL operators (`LD`, `ST`, `S`, `R` ...), the parameter names of the standard
/// blocks (`IN`, `Q`, `PT`, `CU` ...) and the standard function names (`LEN`, `LIMIT` ...).
pub fn reserved_name(name: &str) -> Option<&'static str> {
    // A name that no keyword can equal (case-insensitively) skips the comparisons with each of them
    // (sema checks every declared name: 40,000 for 10,000 generated rungs). `FIRST[c]` has bit `n`
    // set when a keyword of `n` bytes starts with letter `c`; `DIGITS`: whether a keyword holds a
    // digit. Both are computed from the list, so the filter never rules out a keyword.
    const FILTER: ([u64; 26], bool, bool) = {
        let (mut first, mut digits, mut exact) = ([0u64; 26], false, true);
        let mut i = 0;
        while i < KEYWORDS.len() {
            let k = KEYWORDS[i].as_bytes();
            if !k.is_empty() && k.len() < 64 && k[0].is_ascii_alphabetic() {
                first[(k[0].to_ascii_uppercase() - b'A') as usize] |= 1 << k.len();
            } else {
                exact = false;
            }
            let mut j = 0;
            while j < k.len() {
                digits |= k[j].is_ascii_digit();
                j += 1;
            }
            i += 1;
        }
        (first, digits, exact)
    };
    let (first, digits, exact) = FILTER;
    let b = name.as_bytes();
    let may_be_keyword = !exact
        || match b.first() {
            Some(&c) if c.is_ascii_alphabetic() && b.len() < 64 => {
                first[(c.to_ascii_uppercase() - b'A') as usize] & (1 << b.len()) != 0
                    && (digits || !b.iter().any(u8::is_ascii_digit))
            }
            _ => false,
        };
    let is = |k: &&str| k.eq_ignore_ascii_case(name);
    if may_be_keyword && KEYWORDS.iter().any(is) {
        Some("a keyword")
    } else if Elementary::from_name(name).is_some_and(|e| !e.is_long_date() && !e.is_char())
        || ["STRING", "WSTRING", "LTIME"].iter().any(is)
    {
        // (edition 3's LDATE, LTOD, LDT, CHAR, WCHAR are not reserved: edition-2 projects name
        // variables so)
        Some("an elementary data type")
    } else if StdFb::from_name(name).is_some() && !StdFb::is_vendor_name(name) {
        Some(STANDARD_BLOCK)
    } else {
        None
    }
}

/// The vendor library whose block `name` is, for the blocks real projects use most that ladderc
/// does not provide: CODESYS's Util (TwinCAT's Tc2_Utilities has most of them too) and the
/// real-time clock of Beremiz's and OpenPLC Editor's additional blocks.
fn vendor_block(name: &str) -> Option<&'static str> {
    const UTIL: &[&str] = &[
        "PID_FIXCYCLE",
        "PD",
        "BLINK",
        "LIMITALARM",
        "RAMP_INT",
        "RAMP_REAL",
        "CHARCURVE",
        "LIN_TRAFO",
        "STATISTICS_INT",
        "STATISTICS_REAL",
        "VARIANCE",
        "FREQ_MEASURE",
        "GEN",
        "MANUAL",
    ];
    let u = name.to_ascii_uppercase();
    if UTIL.contains(&u.as_str()) {
        Some("CODESYS's Util library")
    } else {
        None
    }
}

/// The structure declarations of `units` in the order their fields are declared: in source order,
/// except that a structure whose field has an initial value of another structure's type (`START :
/// DAY_DATA := (DAY := 24)`, also an array of it) comes after that structure, which may be declared
/// below it (IEC 61131-3 and CODESYS do not order type declarations; OSCAT's PLCopen export
/// initialises `HOLIDAY : ARRAY[..] OF HOLIDAY_DATA` above HOLIDAY_DATA): its field names are known
/// when the initial value is read; so does every structure such a structure holds by value, at any
/// depth (`x : ARRAY[..] OF B := [(t := (s := 1))]` needs B's field `t : C` and C's fields, C
/// declared below B). A cycle keeps source order (E0343 reports it).
fn struct_declaration_order(units: &[CompilationUnit]) -> Vec<&ast::TypeDecl> {
    let decls: Vec<&ast::TypeDecl> = units
        .iter()
        .flat_map(|u| &u.items)
        .filter_map(|item| match item {
            LibraryElement::DataTypes(decls) => Some(decls),
            _ => None,
        })
        .flatten()
        .filter(|d| matches!(d.def, ast::TypeDef::Struct { .. }))
        .collect();
    let mut index: HashMap<String, usize> = HashMap::new();
    for (i, d) in decls.iter().enumerate() {
        index.entry(d.name.key()).or_insert(i);
    }
    // the structures the fields of `d` hold by value: an initialised field's type is needed with
    // every structure inside it (a nested initial value names their fields), so each structure
    // comes after the ones it holds
    let needs = |d: &ast::TypeDecl| -> Vec<usize> {
        let ast::TypeDef::Struct { fields } = &d.def else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for f in fields {
            let mut ty = &f.ty;
            while let TypeRef::Array { element, .. } = ty {
                ty = element;
            }
            if let TypeRef::Named(n) = ty {
                if let Some(&i) = index.get(&n.key()) {
                    out.push(i);
                }
            }
        }
        out
    };
    // depth first, without recursion (a long chain of types is no deep stack)
    let mut state = vec![0u8; decls.len()]; // 0 new, 1 on the path, 2 placed
    let mut order = Vec::with_capacity(decls.len());
    for start in 0..decls.len() {
        if state[start] != 0 {
            continue;
        }
        state[start] = 1;
        let mut stack: Vec<(usize, Vec<usize>)> = vec![(start, needs(decls[start]))];
        while let Some((at, pending)) = stack.last_mut() {
            let at = *at;
            match pending.pop() {
                Some(next) if state[next] == 0 => {
                    state[next] = 1;
                    let n = needs(decls[next]);
                    stack.push((next, n));
                }
                Some(_) => {}
                None => {
                    state[at] = 2;
                    order.push(decls[at]);
                    stack.pop();
                }
            }
        }
    }
    order
}

/// CODESYS's pseudo types `__XINT`, `__UXINT`, `__XWORD` (and TwinCAT's `XINT`, `UXINT`, `XWORD`),
/// a user type of that name aside: pointer-sized integers, LINT, ULINT and LWORD on a 64-bit target
/// (CODESYS help "Data Type: __UXINT, __XINT, __XWORD"; Infosys "Special data types XINT, UXINT,
/// XWORD and PVOID"). ladderc's programs run on 64-bit hosts, so the 64-bit widths.
fn pointer_sized(name: &str) -> Option<Elementary> {
    let upper = name.to_ascii_uppercase();
    match upper.strip_prefix("__").unwrap_or(&upper) {
        "XINT" => Some(Elementary::Lint),
        "UXINT" => Some(Elementary::Ulint),
        "XWORD" => Some(Elementary::Lword),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The keyword filter of [`reserved_name`] never rules out a keyword: the answer is the one of
    /// comparing with every keyword, for every keyword in three spellings and names near them.
    #[test]
    fn reserved_names_are_found_past_the_filter() {
        let slow = |n: &str| KEYWORDS.iter().any(|k| k.eq_ignore_ascii_case(n));
        let mut names: Vec<String> = vec!["".into(), "a0".into(), "_if".into(), "é".into()];
        for k in KEYWORDS {
            let lower = k.to_ascii_lowercase();
            let mixed: String = k
                .chars()
                .enumerate()
                .map(|(i, c)| {
                    if i % 2 == 0 {
                        c.to_ascii_lowercase()
                    } else {
                        c
                    }
                })
                .collect();
            names.extend([
                k.to_string(),
                lower.clone(),
                mixed,
                format!("{k}1"),
                format!("x{lower}"),
            ]);
            names.push(k[..k.len() - 1].to_string());
        }
        for n in &names {
            let got = reserved_name(n) == Some("a keyword");
            assert_eq!(got, slow(n), "{n:?}");
        }
        assert_eq!(reserved_name("End_If"), Some("a keyword"));
        assert_eq!(reserved_name("a0"), None);
    }
}
