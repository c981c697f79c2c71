//! The scan entry point and the watchable-variable table.
//!
//! Input: the model's configurations (tasks, program instances) or, without a configuration, its
//! PROGRAMs; the AST configurations (program instance arguments, task interval/single operands).
//! Output: `ladderc_program_init`, `ladderc_program_scan` and `ladderc_vars[]` in `program.c`.
//! Invariants: each cycle runs every task whose interval has elapsed on the scan clock (a task due at
//! 0, I, 2I ...; a task slower than the cycle runs on the first cycle at or after its due time), in
//! priority order (lower number first, then declaration order), then the program instances without a
//! task; SINGLE tasks run once per rising edge of their variable; without a configuration, every
//! PROGRAM runs each cycle in source order. A program in no resource that other POUs call (`P();`)
//! has an instance named like it, which only those calls run. Table names: `<instance>.<var>[.<field>|[i]]...`, globals by
//! their own name, located variables alias the process image.

use super::scope::{Place, Scope};
use super::values::area_array;
use super::Gen;
use crate::{ctypes, mangle};
use il_frontend::ast::{AddressSize, ArgDir, CompilationUnit, LibraryElement, PouKind, VarKind};
use il_frontend::sema::{ConstValue, FbType, PouId, Type, UserTypeDef, Variable};
use std::fmt::Write as _;

/// Arrays with more elements than this are left out of the table (they stay usable in the program).
const MAX_WATCHED_ARRAY: u128 = 1024;
/// Upper bound of table entries, so that a huge instance tree cannot make the table unbounded.
const MAX_ENTRIES: usize = 1_000_000;

/// Whether `name` is the hidden program that runs the FB_init methods before the first cycle.
fn is_init_program(name: &str) -> bool {
    name.eq_ignore_ascii_case(il_frontend::st::fb_init::PROGRAM)
}

/// Whether `name` is a B&R Automation Studio program part that is no cyclic program: `_INIT`
/// (run once, before the first cycle) or `_EXIT` (run when the program stops: never in a run).
fn is_br_once_program(name: &str) -> bool {
    name.eq_ignore_ascii_case("_INIT") || name.eq_ignore_ascii_case("_EXIT")
}

/// A program instance to run.
pub(super) struct Instance {
    /// C variable name.
    pub(super) c_name: String,
    /// Table prefix (as written).
    pub(super) watch_name: String,
    pub(super) pou: PouId,
    /// (config, resource, index in resource.programs) for configured instances.
    pub(super) configured: Option<(usize, usize, usize)>,
    /// The own instance of a program that the configuration does not instantiate but other POUs
    /// call or use (`P();`, `P.x`): only those calls run it.
    pub(super) called_only: bool,
}

impl Gen<'_> {
    /// The program instances to run: each configured one, or without a configuration the
    /// implicit instance of every PROGRAM.
    pub(super) fn instances(&self) -> Vec<Instance> {
        let mut v = Vec::new();
        if self.model.configurations.is_empty() {
            for (i, p) in self.model.pous.iter().enumerate() {
                if p.kind == PouKind::Program
                    && !is_init_program(&p.name)
                    && !is_br_once_program(&p.name)
                {
                    v.push(Instance {
                        c_name: mangle::implicit_instance(&p.name),
                        watch_name: il_frontend::program_watch_name(&p.name).to_string(),
                        pou: PouId(i as u32),
                        configured: None,
                        called_only: false,
                    });
                }
            }
        } else {
            // an instance name that two configurations (or two resources of one) share is traced
            // qualified by its configuration (`CfgB.P1.n`), its resource (`R2.P1.n`) or both, as
            // IEC 61131-3's access paths name it (ed.3 6.8.2: `resource.program.variable`); a
            // name no other instance has stays as it is (`P1.n`)
            let all: Vec<(usize, usize, &str)> = self
                .model
                .configurations
                .iter()
                .enumerate()
                .flat_map(|(ci, cfg)| {
                    cfg.resources.iter().enumerate().flat_map(move |(ri, r)| {
                        r.programs.iter().map(move |p| (ci, ri, p.name.as_str()))
                    })
                })
                .collect();
            let watch_name = |ci: usize, ri: usize, name: &str| {
                let same = || all.iter().filter(|x| x.2.eq_ignore_ascii_case(name));
                let other_config = same().any(|x| x.0 != ci);
                let other_resource = same().any(|x| x.0 == ci && x.1 != ri);
                let cfg = &self.model.configurations[ci];
                let mut w = String::new();
                if other_config {
                    w.push_str(&cfg.name);
                    w.push('.');
                }
                if other_resource {
                    w.push_str(&cfg.resources[ri].name);
                    w.push('.');
                }
                w.push_str(name);
                w
            };
            for (ci, cfg) in self.model.configurations.iter().enumerate() {
                for (ri, r) in cfg.resources.iter().enumerate() {
                    for (pi, p) in r.programs.iter().enumerate() {
                        v.push(Instance {
                            c_name: mangle::program_instance(ci, ri, &p.name),
                            watch_name: watch_name(ci, ri, &p.name),
                            pou: p.pou,
                            configured: Some((ci, ri, pi)),
                            called_only: false,
                        });
                    }
                }
            }
            // configurations that declare no program instance (the empty `config`/`resource1`
            // Beremiz writes into every export): every PROGRAM runs as without a configuration
            // (W1453 says so, at the configuration)
            let unconfigured = v.is_empty();
            // programs in no resource that other POUs call, use by name or whose actions they call
            for (i, p) in self.model.pous.iter().enumerate() {
                let id = PouId(i as u32);
                let used = self.model.programs_used_by_name.contains(&id)
                    || p.vars
                        .iter()
                        .any(|v| v.name.starts_with(il_frontend::actions::FLAG_PREFIX));
                if p.kind == PouKind::Program
                    && (used || (unconfigured && !is_br_once_program(&p.name)))
                    && !is_init_program(&p.name)
                    && !v.iter().any(|x| x.pou == id)
                {
                    v.push(Instance {
                        c_name: mangle::implicit_instance(&p.name),
                        watch_name: il_frontend::program_watch_name(&p.name).to_string(),
                        pou: id,
                        configured: None,
                        called_only: !unconfigured,
                    });
                }
            }
        }
        v
    }

    pub fn scan(&mut self, units: &[CompilationUnit], c: &mut String) {
        let ast_configs: Vec<&il_frontend::ast::Configuration> = units
            .iter()
            .flat_map(|u| u.items.iter())
            .filter_map(|i| match i {
                LibraryElement::Configuration(c) => Some(c),
                _ => None,
            })
            .collect();
        let instances = self.instances();
        for inst in &instances {
            let s = match self.model.pou(inst.pou).kind {
                PouKind::Program => mangle::program(&self.model.pou(inst.pou).name),
                _ => mangle::fb(&self.model.pou(inst.pou).name),
            };
            let _ = writeln!(c, "{s} {};", inst.c_name);
        }
        // tasks, flattened over configurations and resources
        let mut tasks = Vec::new();
        for (ci, cfg) in self.model.configurations.iter().enumerate() {
            for (ri, r) in cfg.resources.iter().enumerate() {
                for (ti, t) in r.tasks.iter().enumerate() {
                    tasks.push((ci, ri, ti, t.priority));
                }
            }
        }
        tasks.sort_by_key(|t| t.3);
        // program instances of each task, in declaration order
        let mut by_task: std::collections::HashMap<(usize, usize, usize), Vec<usize>> =
            std::collections::HashMap::new();
        for (i, inst) in instances.iter().enumerate() {
            if let Some((ci, ri, pi)) = inst.configured {
                if let Some(ti) = self.model.configurations[ci].resources[ri].programs[pi].task {
                    by_task.entry((ci, ri, ti)).or_default().push(i);
                }
            }
        }
        let n_tasks = tasks.len();
        if n_tasks > 0 {
            let _ = writeln!(
                c,
                "static IEC_TIME ladderc_task_due[{n_tasks}];\nstatic IEC_BOOL ladderc_task_trig[{n_tasks}];"
            );
        }
        // init
        c.push_str("\nvoid ladderc_program_init(void) {\n");
        if self.motion.is_some() {
            c.push_str("    ladderc_motion_init();\n");
        }
        for r in self.model.global_refs() {
            let v = self.model.global(r).clone();
            let name = self.global_name(r);
            self.init_global(c, &v, name);
        }
        for inst in &instances {
            let s = self.instance_struct(inst.pou);
            let _ = writeln!(c, "    {s}_INIT(&{});", inst.c_name);
        }
        // FB_init: the hidden program that runs every instance's, once, before the first cycle
        // (`il_frontend::st::fb_init`)
        if let Some(k) = self
            .model
            .pous
            .iter()
            .position(|p| p.kind == PouKind::Program && is_init_program(&p.name))
        {
            let id = PouId(k as u32);
            let s = self.instance_struct(id);
            let name = mangle::implicit_instance(&self.model.pou(id).name);
            let _ = writeln!(
                c,
                "    {{
        static {s} {name};"
            );
            let _ = writeln!(
                c,
                "        {s}_INIT(&{name});
        {s}_BODY(&{name});
    }}"
            );
        }
        // B&R Automation Studio: `PROGRAM _INIT` runs once, after the instances are initialised
        // and before the first cycle (`_CYCLIC` runs each cycle, `_EXIT` at a stop a run never has)
        if let Some(k) = self.model.pous.iter().position(|p| {
            p.kind == PouKind::Program
                && p.name.eq_ignore_ascii_case("_INIT")
                && self.model.configurations.is_empty()
        }) {
            let id = PouId(k as u32);
            let s = self.instance_struct(id);
            let name = mangle::implicit_instance(&self.model.pou(id).name);
            let _ = writeln!(
                c,
                "    {{
        static {s} {name};
        {s}_INIT(&{name});
        {s}_BODY(&{name});
    }}"
            );
        }
        if n_tasks > 0 {
            c.push_str("    memset(ladderc_task_due, 0, sizeof ladderc_task_due);\n");
            c.push_str("    memset(ladderc_task_trig, 0, sizeof ladderc_task_trig);\n");
        }
        c.push_str("}\n\nvoid ladderc_program_scan(void) {\n");
        for (k, &(ci, ri, ti, _)) in tasks.iter().enumerate() {
            let task = self.model.configurations[ci].resources[ri].tasks[ti].clone();
            let ast_task = ast_configs
                .get(ci)
                .and_then(|c| c.resources.get(ri))
                .and_then(|r| r.tasks.get(ti));
            let scope = Scope::for_config(ci, ri);
            let _ = writeln!(c, "    /* task {k} */\n    {{");
            let single = ast_task.and_then(|t| t.single.as_ref());
            let guard = if let Some(op) = single {
                let v = self
                    .value(&scope, op, &Type::BOOL)
                    .unwrap_or_else(|| "0".into());
                let _ = writeln!(c, "        IEC_BOOL trig = {v};");
                let _ = writeln!(
                    c,
                    "        IEC_BOOL run = (IEC_BOOL)(trig && !ladderc_task_trig[{k}]);"
                );
                let _ = writeln!(c, "        ladderc_task_trig[{k}] = trig;");
                "run".to_string()
            } else {
                let iv = match (task.interval_ns, ast_task.and_then(|t| t.interval.as_ref())) {
                    (Some(ns), _) => {
                        ctypes::int_literal(il_frontend::sema::Elementary::Lint, ns as i128)
                    }
                    (None, Some(op)) => self
                        .value(&scope, op, &Type::TIME)
                        .unwrap_or_else(|| "0".into()),
                    (None, None) => "0".into(),
                };
                let _ = writeln!(c, "        IEC_TIME iv = {iv};");
                let _ = writeln!(
                    c,
                    "        IEC_BOOL run = (IEC_BOOL)(iv <= 0 || ladderc_now >= ladderc_task_due[{k}]);"
                );
                let _ = writeln!(
                    c,
                    "        if (run && iv > 0) ladderc_task_due[{k}] = ladderc_next_due(ladderc_task_due[{k}], ladderc_now, iv);"
                );
                "run".to_string()
            };
            let _ = writeln!(c, "        if ({guard}) {{");
            for &i in by_task.get(&(ci, ri, ti)).map(Vec::as_slice).unwrap_or(&[]) {
                self.run_instance(c, &instances[i], &ast_configs, 3);
            }
            c.push_str("        }\n    }\n");
        }
        for inst in &instances {
            let background = match inst.configured {
                None => !inst.called_only,
                Some((ci, ri, pi)) => self.model.configurations[ci].resources[ri].programs[pi]
                    .task
                    .is_none(),
            };
            if background {
                self.run_instance(c, inst, &ast_configs, 1);
            }
        }
        if self.motion.is_some() {
            c.push_str("    ladderc_motion_step();\n");
        }
        c.push_str("}\n\n");
        self.var_table(c, &instances, &ast_configs);
    }

    fn instance_struct(&self, pou: PouId) -> String {
        let p = self.model.pou(pou);
        match p.kind {
            PouKind::Program => mangle::program(&p.name),
            _ => mangle::fb(&p.name),
        }
    }

    fn init_global(&mut self, c: &mut String, v: &Variable, name: String) {
        if v.location.is_some() {
            self.init_located(c, v);
            return;
        }
        self.init_value(c, 1, &name, &v.ty, v.init.as_ref(), v.span);
    }

    /// A located variable (global or of a POU) starts from the (zeroed) process image; its initial
    /// value, when it has one, is written there.
    pub(super) fn init_located(&mut self, c: &mut String, v: &Variable) {
        if let (Some(ConstValue::Array(elems)), Type::Array { element, .. }) = (&v.init, &v.ty) {
            self.init_located_array(c, v, elems, element);
            return;
        }
        if let Some(init) = &v.init {
            if let Some(e) = v.ty.elementary() {
                if let Some(val) = ctypes::const_elementary(self.model, e, init) {
                    if let Some(Place::Loc { loc, ty, .. }) = self.located_global(v) {
                        let _ = writeln!(
                            c,
                            "    {}",
                            super::values::store_expr(&loc, None, &ty, &val)
                        );
                    }
                }
            }
        }
    }

    /// A located array's initial values (`regs AT %MW10 : ARRAY[0..3] OF INT := [1, 2, 2(0)];`),
    /// row-major as C lays out the elements, each stored at its bytes in the area.
    fn init_located_array(
        &mut self,
        c: &mut String,
        v: &Variable,
        elems: &[ConstValue],
        element: &Type,
    ) {
        let Some(Place::Loc { loc, .. }) = self.located_global(v) else {
            return;
        };
        let (Some(e), Some(size)) = (
            element.elementary(),
            super::values::located_bytes(element, AddressSize::Byte),
        ) else {
            return;
        };
        let total = loc.bytes / size.max(1);
        let each = crate::profile::Located { bytes: size, ..loc };
        for (k, value) in elems.iter().take(total as usize).enumerate() {
            let Some(val) = ctypes::const_elementary(self.model, e, value) else {
                continue;
            };
            let at = cfmt!("{}u", k as u64 * u64::from(size));
            let _ = writeln!(
                c,
                "    {}",
                super::values::store_expr(&each, Some(&at), element, &val)
            );
        }
    }

    fn located_global(&mut self, v: &Variable) -> Option<Place> {
        let loc = v.location.as_ref()?;
        let addr = il_frontend::ast::DirectAddress {
            area: loc.area,
            size: loc.size,
            path: loc.path.clone(),
            span: self
                .address_spans
                .get(&(v.span, loc.path.is_empty()))
                .copied()
                .unwrap_or(v.span),
        };
        let bytes = if v.ty.is_bool() {
            None
        } else {
            super::values::located_bytes(&v.ty, loc.size)
        };
        if bytes.is_none() && !v.ty.is_bool() {
            // no layout in the process image (an array at a bit address, a structure): its uses
            // are E2005 (`Gen::locate_var`)
            return None;
        }
        match self.locate(&addr, bytes) {
            Ok(l) => Some(Place::Loc {
                loc: l,
                ty: v.ty.clone(),
                at: None,
            }),
            Err(d) => {
                self.report_once(*d);
                None
            }
        }
    }

    /// Runs one program instance: argument inputs, body, argument outputs.
    fn run_instance(
        &mut self,
        c: &mut String,
        inst: &Instance,
        ast_configs: &[&il_frontend::ast::Configuration],
        indent: usize,
    ) {
        let pad = "    ".repeat(indent);
        let s = self.instance_struct(inst.pou);
        let args = inst.configured.and_then(|(ci, ri, pi)| {
            ast_configs
                .get(ci)
                .and_then(|c| c.resources.get(ri))
                .and_then(|r| r.programs.get(pi))
                .map(|p| (ci, ri, p.args.clone()))
        });
        if let Some((ci, ri, args)) = &args {
            let scope = Scope::for_config(*ci, *ri);
            for a in args {
                let Some(param) = self.pou_var(inst.pou, &a.name.name) else {
                    self.unsupported(a.span, "an argument that is not a parameter of the program");
                    continue;
                };
                let field = Place::Mem {
                    lv: cfmt!("{}.{}", inst.c_name, mangle::var(&param.name)),
                    ty: param.ty.clone(),
                };
                match a.dir {
                    ArgDir::Input => {
                        if let Some(v) = self.value(&scope, &a.value, &param.ty) {
                            let st = self.store(&field, &v);
                            let _ = writeln!(c, "{pad}{st}");
                        }
                    }
                    ArgDir::Output { .. } => {}
                }
            }
        }
        let _ = writeln!(c, "{pad}{s}_BODY(&{});", inst.c_name);
        if let Some((ci, ri, args)) = &args {
            let scope = Scope::for_config(*ci, *ri);
            for a in args {
                let ArgDir::Output { negated } = a.dir else {
                    continue;
                };
                let Some(param) = self.pou_var(inst.pou, &a.name.name) else {
                    continue;
                };
                let il_frontend::ast::Operand::Var(r) = &a.value else {
                    self.unsupported(
                        a.span,
                        "a program output bound to something other than a variable",
                    );
                    continue;
                };
                let Some(target) = self.place(&scope, r) else {
                    continue;
                };
                let src = cfmt!("{}.{}", inst.c_name, mangle::var(&param.name));
                let src = if negated {
                    super::body::negated(&src, &param.ty)
                } else {
                    src
                };
                let v = super::values::convert(&src, &param.ty, target.ty());
                let st = self.store(&target, &v);
                let _ = writeln!(c, "{pad}{st}");
            }
        }
    }

    fn var_table(
        &mut self,
        c: &mut String,
        instances: &[Instance],
        configs: &[&il_frontend::ast::Configuration],
    ) {
        // Each entry is written into `c` as it is made: no `String` per entry (a 10,000-rung
        // program has 40,000 of them).
        c.push_str("const ladderc_var ladderc_vars[] = {\n");
        let mut out = WatchLines { c, count: 0 };
        // a member of a named global variable list is traced as `List.x`
        // (the model is borrowed through its own reference: no variable or POU is copied)
        let model = self.model;
        for r in model.global_refs() {
            let v = model.global(r);
            let name = self.global_name(r);
            let watch = model.global_qualified_name(r);
            self.watch_var(v, &watch, &name, &mut out);
        }
        // The trace name `instance.var` and the C place `instance_c.v_var` of each variable, built
        // in two buffers that keep their room.
        let (mut name, mut lv) = (String::new(), String::new());
        for inst in instances {
            let pou = model.pou(inst.pou);
            for v in &pou.vars {
                if matches!(v.kind, VarKind::External | VarKind::InOut | VarKind::Temp) {
                    continue;
                }
                name.clear();
                name.push_str(&inst.watch_name);
                name.push('.');
                name.push_str(&v.name);
                lv.clear();
                lv.push_str(&inst.c_name);
                lv.push_str(".v_");
                mangle::push_core(&mut lv, &v.name);
                self.watch_var(v, &name, &lv, &mut out);
            }
        }
        if let Some(m) = &self.motion {
            for e in m.watch_entries() {
                out.line(&e);
            }
        }
        // access paths (VAR_ACCESS), by their access names
        let read_only = self.access_entries(configs, instances, &mut out);
        // each hierarchical address's slot, by its text (`%IX1.0.0`): the host reads and sets it so
        for (text, area, offset, size) in &self.hier.list {
            let tag = match size {
                AddressSize::Bit => "LADDERC_T_BOOL",
                AddressSize::Byte => "LADDERC_T_BYTE",
                AddressSize::Word => "LADDERC_T_WORD",
                AddressSize::DWord => "LADDERC_T_DWORD",
                AddressSize::LWord => "LADDERC_T_LWORD",
            };
            out.line(&cfmt!(
                "{{ {}, {tag}, NULL, {}, {offset}, 0 }}",
                mangle::c_string(text.as_bytes()),
                area_array(*area)
            ));
        }
        let count = out.count;
        if count == 0 {
            c.push_str("    { NULL, LADDERC_T_BOOL, NULL, NULL, 0, 0 }\n");
        }
        let _ = writeln!(c, "}};\nconst size_t ladderc_var_count = {count};");
        // the READ_ONLY access names, which a stimulus may not write
        c.push_str("const char *const ladderc_read_only[] = {");
        for n in &read_only {
            let _ = write!(c, " {},", mangle::c_string(n.as_bytes()));
        }
        let _ = writeln!(
            c,
            " NULL }};\nconst size_t ladderc_read_only_count = {};",
            read_only.len()
        );
    }

    pub(super) fn watch_var(&mut self, v: &Variable, name: &str, lv: &str, out: &mut WatchLines) {
        if v.location.is_some() {
            if let Some(Place::Loc { loc, ty, .. }) = self.located_global(v) {
                if let Type::Array { dims, element } = &ty {
                    self.watch_located_array(name, loc, dims, element, out);
                    return;
                }
                let tag = match ty {
                    Type::Enum(_) => "LADDERC_T_DINT",
                    ref t => match t.elementary() {
                        Some(e) => ctypes::type_tag(e),
                        None => return,
                    },
                };
                out.line(&cfmt!(
                    "{{ {}, {tag}, NULL, {}, {}, {} }}",
                    mangle::c_string(name.as_bytes()),
                    area_array(loc.area),
                    loc.offset,
                    loc.bit.unwrap_or(0)
                ));
            }
            return;
        }
        self.watch_value(name, lv, &v.ty, 0, out);
    }

    /// One watch entry per element of a located array, named as an array's elements are
    /// (`regs[3]`, `grid[0,1]`), each at its bytes in the area (see `Gen::located_index`).
    fn watch_located_array(
        &self,
        name: &str,
        loc: crate::profile::Located,
        dims: &[il_frontend::sema::Dim],
        element: &Type,
        out: &mut WatchLines,
    ) {
        let tag = match element {
            Type::Enum(_) => "LADDERC_T_DINT",
            t => match t.elementary() {
                Some(e) => ctypes::type_tag(e),
                None => return,
            },
        };
        let Some(size) = super::values::located_bytes(element, AddressSize::Byte) else {
            return;
        };
        let total: u128 = dims.iter().map(|d| d.len()).product();
        if total == 0 || total > MAX_WATCHED_ARRAY {
            return;
        }
        for k in 0..total {
            if out.count >= MAX_ENTRIES {
                return;
            }
            let mut rest = k;
            let mut iec = vec![String::new(); dims.len()];
            for (d, dim) in dims.iter().enumerate().rev() {
                iec[d] = (dim.lower + (rest % dim.len()) as i128).to_string();
                rest /= dim.len();
            }
            out.line(&cfmt!(
                "{{ {}, {tag}, NULL, {}, {}, 0 }}",
                mangle::c_string(cfmt!("{name}[{}]", iec.join(",")).as_bytes()),
                area_array(loc.area),
                u128::from(loc.offset) + k * u128::from(size)
            ));
        }
    }

    pub(super) fn watch_value(
        &self,
        name: &str,
        lv: &str,
        ty: &Type,
        depth: usize,
        out: &mut WatchLines,
    ) {
        if out.count >= MAX_ENTRIES || depth > 16 {
            return;
        }
        match ty {
            Type::Enum(_) => out.entry(&[name], "LADDERC_T_DINT", &[lv]),
            Type::Elementary(_) | Type::Subrange { .. } => {
                if let Some(e) = ty.elementary() {
                    out.entry(&[name], ctypes::type_tag(e), &[lv]);
                }
            }
            Type::String { wide: false, .. } => out.entry(&[name], "LADDERC_T_STRING", &[lv]),
            Type::String { wide: true, .. } => out.entry(&[name], "LADDERC_T_WSTRING", &[lv]),
            Type::Struct(id) => {
                if let UserTypeDef::Struct { fields } = &self.model.user_type(*id).def {
                    for f in fields {
                        self.watch_value(
                            &cfmt!("{name}.{}", f.name),
                            &cfmt!("{lv}.{}", mangle::var(&f.name)),
                            &f.ty,
                            depth + 1,
                            out,
                        );
                    }
                }
            }
            Type::Fb(FbType::Standard(f)) => {
                for (p, e, _) in ctypes::std_fb(*f).1 {
                    out.entry(&[name, ".", p], ctypes::type_tag(*e), &[lv, ".", p]);
                }
            }
            Type::Fb(FbType::User(id)) => {
                let pou = self.model.pou(*id);
                for v in &pou.vars {
                    if v.location.is_some()
                        || matches!(v.kind, VarKind::External | VarKind::InOut | VarKind::Temp)
                    {
                        continue;
                    }
                    self.watch_value(
                        &cfmt!("{name}.{}", v.name),
                        &cfmt!("{lv}.{}", mangle::var(&v.name)),
                        &v.ty,
                        depth + 1,
                        out,
                    );
                }
            }
            Type::Array { dims, element } => {
                let total: u128 = dims.iter().map(|d| d.len()).product();
                if total == 0 || total > MAX_WATCHED_ARRAY {
                    return;
                }
                for k in 0..total {
                    let mut rest = k;
                    let mut idx = vec![0u128; dims.len()];
                    for (d, dim) in dims.iter().enumerate().rev() {
                        idx[d] = rest % dim.len();
                        rest /= dim.len();
                    }
                    let iec: Vec<String> = idx
                        .iter()
                        .zip(dims)
                        .map(|(i, d)| (d.lower + *i as i128).to_string())
                        .collect();
                    let c_idx: String = idx.iter().map(|i| cfmt!("[{i}]")).collect();
                    self.watch_value(
                        &cfmt!("{name}[{}]", iec.join(",")),
                        &cfmt!("{lv}{c_idx}"),
                        element,
                        depth + 1,
                        out,
                    );
                }
            }
            _ => {}
        }
    }
}

/// The lines of the watch table (`ladderc_vars[]`), written into the C text as they are made.
pub(super) struct WatchLines<'c> {
    c: &'c mut String,
    /// Entries written so far.
    count: usize,
}

impl WatchLines<'_> {
    /// The entry `{ "name", tag, (void *)&lv, NULL, 0, 0 }` of a value in memory, the name and the
    /// place given in pieces (the name is written as a C string literal).
    fn entry(&mut self, name: &[&str], tag: &str, lv: &[&str]) {
        let c = &mut *self.c;
        c.push_str("    { \"");
        for p in name {
            mangle::push_c_string_body(c, p.as_bytes());
        }
        c.push_str("\", ");
        c.push_str(tag);
        c.push_str(", (void *)&");
        for p in lv {
            c.push_str(p);
        }
        c.push_str(", NULL, 0, 0 },\n");
        self.count += 1;
    }
    /// An entry written whole (`{ ... }`).
    pub(super) fn line(&mut self, e: &str) {
        self.c.push_str("    ");
        self.c.push_str(e);
        self.c.push_str(",\n");
        self.count += 1;
    }
}
