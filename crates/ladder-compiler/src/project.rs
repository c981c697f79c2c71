//! The project level: `<project>` -> [`il_frontend::ast::CompilationUnit`].
//!
//! Input: the element tree of a TC6 project (tc6_0201, tc6_0200, or v1.0 `tc6.xsd`, read leniently).
//! Output: one `DataTypes` item for `<dataTypes>`, one `Pou` per `<pou>` (bodies lowered by
//! [`crate::body`]), one `Configuration` per `<configuration>`; diagnostics for what cannot be read.
//! Invariants: POUs keep their interface even when the body cannot be lowered (E3003/E3004), so callers
//! are still checked; vendor data (`addData`, vendor elements) is skipped with one W3002 per file,
//! except a CODESYS CFC chart (read as a POU's or action's body, else E0321: `codesys_cfc`).

use crate::body;
use crate::catalogue;
use crate::context::Ctx;
use crate::decls;
use crate::values;
use crate::xml::Element;
use diagnostics::{code, Diagnostic, XmlContext};
use il_frontend::ast::{
    CompilationUnit, Configuration, Ident, LibraryElement, Literal, LiteralKind, Operand, Pou,
    PouKind, ProgramInstance, Resource, Task, TypeDecl, TypeRef, VarBlock, VarKind,
};
use std::collections::{HashMap, HashSet};

/// Schema version of the file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Version {
    /// `http://www.plcopen.org/xml/tc6_0201` (TC6 XML 2.01), and the default for an unknown namespace
    /// (W3001).
    V201,
    /// `http://www.plcopen.org/xml/tc6_0200` (TC6 XML 2.0).
    V200,
    /// `http://www.plcopen.org/xml/tc6.xsd` (TC6 XML 1.0).
    V1,
}

/// The interface of a POU, as blocks that call it see it.
#[derive(Debug, Clone)]
pub struct PouSig {
    /// `FUNCTION`, `FUNCTION_BLOCK` or `PROGRAM`.
    pub kind: PouKind,
    /// The POU name as written.
    pub name: String,
    /// Inputs, outputs and in-outs with their types, in declaration order.
    pub pins: Vec<(String, VarKind, TypeRef)>,
    /// A FUNCTION's result type.
    pub ret: Option<TypeRef>,
    /// The other variables (`VAR`, `VAR_TEMP`, `VAR_EXTERNAL` ...) with their block kind and type:
    /// not pins, only read to type `inst.x` (an FB instance's internal variable, W1412).
    pub internals: Vec<(String, VarKind, TypeRef)>,
    /// The names of a program's or function block's actions (`<actions>`, CODESYS), as written:
    /// an LD/FBD box of that name calls the action.
    pub actions: Vec<String>,
}

/// Everything a body lowering needs to know about the rest of the project.
#[derive(Default)]
pub struct Index {
    /// Every POU's interface, by upper-case name.
    pub pous: HashMap<String, PouSig>,
    /// Every `<dataType>`, by upper-case name.
    pub types: HashMap<String, TypeDecl>,
    /// Every global variable's type (configurations, resources, vendor global lists), by upper-case name.
    pub globals: HashMap<String, TypeRef>,
    /// The members of each named global variable list (CODESYS GVL), by list, then member name.
    pub global_lists: HashMap<String, HashMap<String, TypeRef>>,
    /// Derived types that nothing in the file defines (upper-case names), each already reported
    /// once (E3009, with every use): a block of such a type is not reported again.
    pub missing_types: HashSet<String>,
    /// The methods of each function block (CODESYS vendor data), by upper-case block name: a call
    /// `M(...)` inside the block runs the block's own method.
    pub method_sigs: HashMap<String, Vec<il_frontend::st::types::MethodSig>>,
    /// The INTERFACEs of CODESYS's vendor data (`crate::xml_oop`), by upper-case name: types the
    /// file defines (their variables are compiled by the ST front end).
    pub interfaces: HashSet<String>,
    /// The ST lowering's view of the fields above ([`crate::st_body::declarations`]), built on first use
    /// and shared by every body: building it per body cost bodies x POUs. The fields are complete before
    /// any body is lowered.
    pub(crate) st_declarations: std::cell::OnceCell<il_frontend::st::Declarations>,
    /// The same with the SFC step and action flag types ([`crate::sfc::st_bridge::declarations`]).
    pub(crate) sfc_declarations: std::cell::OnceCell<il_frontend::st::Declarations>,
}

/// The data types and the POU elements of a project: `<types>`' and those CODESYS keeps in an
/// application's vendor data (the applications' resources, and those of the `<instances>`
/// configurations: CODESYS V3.5 SP17+ writes a device's application so); `single_pou`: `root` is
/// itself the one POU.
fn types_and_pous<'b, 'a>(
    ctx: &mut Ctx,
    root: &'b Element<'a>,
    single_pou: bool,
) -> (Vec<TypeDecl>, Vec<&'b Element<'a>>) {
    let types_el = root.child("types");
    let vendor_resources: Vec<&Element> = application_resources(root)
        .into_iter()
        .chain(instance_resources(root))
        .collect();
    let data_types: Vec<TypeDecl> = types_el
        .and_then(|t| t.child("dataTypes"))
        .into_iter()
        .flat_map(|d| d.children_named("dataType"))
        .chain(
            vendor_resources
                .iter()
                .flat_map(|r| application_data(r, "/datatype", "dataType")),
        )
        .filter_map(|e| decls::data_type(ctx, e))
        .collect();
    // CODESYS V3's UNIONs: in the project's vendor data (and an application's)
    let data_types: Vec<TypeDecl> = data_types
        .into_iter()
        .chain(
            std::iter::once(root)
                .chain(vendor_resources.iter().copied())
                .flat_map(|r| application_data(r, "/plcopenxml/union", "union"))
                .filter_map(|e| decls::union_type(ctx, e))
                .collect::<Vec<_>>(),
        )
        .collect();
    // Interfaces first: bodies call each other in any order.
    let pou_els: Vec<&Element> = types_el
        .and_then(|t| t.child("pous"))
        .into_iter()
        .flat_map(|p| p.children_named("pou"))
        .chain(single_pou.then_some(root))
        .chain(
            vendor_resources
                .iter()
                .flat_map(|r| application_data(r, "/pou", "pou")),
        )
        .collect();
    (data_types, pou_els)
}

/// What the other PLCopen XML files of a project declare: their POUs' interfaces and their data
/// types ([`interfaces`]), known while [`with_other_files`] runs.
#[derive(Debug, Clone, Default)]
pub struct OtherFiles {
    /// The POUs' interfaces.
    pub pous: Vec<PouSig>,
    /// The data types.
    pub types: Vec<TypeDecl>,
    /// The integer constants of the constant global lists (`N`, and `GVL.N` of a named list),
    /// upper case: array bounds of the other files may name them.
    pub constants: HashMap<String, i128>,
    /// The global variables of the text files given with the XML (`.st` global lists), by
    /// upper-case name: a box input or output of an LD/FBD body types them as the body's own.
    pub globals: HashMap<String, TypeRef>,
    /// The members of the named global lists of those files (`Glob.st` holding only `VAR_GLOBAL`
    /// is the list `Glob`), by upper-case list, then member name: `Glob.a` into a box.
    pub global_lists: HashMap<String, HashMap<String, TypeRef>>,
}

thread_local! {
    static OTHER_FILES: std::cell::RefCell<Option<OtherFiles>> = const { std::cell::RefCell::new(None) };
}

/// Runs `f` (the compilation of one XML file of several) with `other` (what the other files
/// declare) known to [`read_project`].
pub fn with_other_files<R>(other: OtherFiles, f: impl FnOnce() -> R) -> R {
    let before = OTHER_FILES.with(|o| o.replace(Some(other)));
    let r = f();
    OTHER_FILES.with(|o| *o.borrow_mut() = before);
    r
}

/// The POU interfaces and data types of one PLCopen XML file (its diagnostics are left to its own
/// compilation); nothing for a file that is not a PLCopen project.
pub fn interfaces(file: diagnostics::FileId, xml: &str) -> OtherFiles {
    let arena = crate::xml::Arena::new();
    let (Some(parsed), _) = crate::xml::parse(xml, &arena) else {
        return OtherFiles::default();
    };
    let mut scratch = diagnostics::Diagnostics::new();
    let mut ctx = Ctx::new(file, xml, &mut scratch);
    let mut root = &parsed;
    let mut inner = root.children_named("project");
    if let (true, Some(project), None) = (root.name() == "projects", inner.next(), inner.next()) {
        root = project;
    }
    let single_pou = root.name() == "pou" && root.attr("xmlns").is_some_and(is_plcopen_namespace);
    if root.name() != "project" && !single_pou {
        return OtherFiles::default();
    }
    let _version = version(&mut ctx, root);
    vendor_data(&mut ctx, root);
    ctx.constants = decls::collect_constants(root, true, &|_| None);
    let (types, pou_els) = types_and_pous(&mut ctx, root, single_pou);
    let pous = pou_els
        .iter()
        .filter_map(|p| pou_header(&mut ctx, p))
        .map(|h| signature(&h))
        .collect();
    OtherFiles {
        pous,
        types,
        constants: ctx.constants.clone(),
        ..OtherFiles::default()
    }
}

/// Reads the `<project>` root: data types, POUs (bodies lowered to IL) and configurations, in that order; a
/// root that is not `<project>` is E3002 and gives an empty unit.
pub fn read_project(ctx: &mut Ctx, root: &Element) -> CompilationUnit {
    let mut unit = CompilationUnit::default();
    // a file of one POU (RuSTy's and Bachmann's `.cfc`, tools that export one object per file): the
    // project of that POU
    let single_pou = root.name() == "pou" && root.attr("xmlns").is_some_and(is_plcopen_namespace);
    // `<projects version="2.0">` around one `<project>` (a vendor's IDE, beta591414/-CMC-: its own
    // copy of the headers, then the PLCopen project): the project inside
    let mut inner = root.children_named("project");
    if let (true, Some(project), None) = (root.name() == "projects", inner.next(), inner.next()) {
        return read_project(ctx, project);
    }
    if root.name() == "TcPlcObject" {
        // a TwinCAT object file that reaches here is not well-formed (`crate::twincat` reads the
        // others): E3001 said so, and it is no PLCopen project to expect
        return unit;
    }
    if root.name() != "project" && !single_pou {
        // IEC 61131-10's XML exchange format (`<Project xmlns="www.iec.ch/public/TC65SC65BWG7TF10">`,
        // which B&R Automation Studio 6 writes for its LD and FBD): not PLCopen TC6, and not read
        let iec_61131_10 = root
            .attr("xmlns")
            .is_some_and(|n| n.contains("TC65SC65BWG7"));
        if iec_61131_10 {
            let at = ctx.tag(root);
            ctx.diags.push(
                Diagnostic::error(
                    code::E3002,
                    "an IEC 61131-10 XML file (B&R Automation Studio 6 writes its LD and FBD so): ladderc reads PLCopen TC6 XML, not this format",
                )
                .at(at)
                .with_hint("leave the file out (a B&R program's own declarations are then not compiled either, W0022), or give the POU as ST"),
            );
            return unit;
        }
        // TwinCAT 3's old object archive (`<Single ... Method="IArchivable">`, the form early
        // TwinCAT 3 builds saved `.TcPOU`/`.TcTTO` in before `<TcPlcObject>`): a serialized
        // object, neither a TwinCAT source file ladderc reads nor PLCopen XML
        if root.name() == "Single" && root.attr("Method") == Some("IArchivable") {
            let at = ctx.tag(root);
            ctx.diags.push(
                Diagnostic::error(
                    code::E3002,
                    "a TwinCAT object saved in the old `<Single>` archive form (early TwinCAT 3 builds), which ladderc does not read",
                )
                .at(at)
                .with_hint("open the project in a current TwinCAT 3.1 and save it (each object is then written as `<TcPlcObject>`), or export the POUs as PLCopen XML"),
            );
            return unit;
        }
        ctx.error(
            code::E3002,
            ctx.tag(root),
            format!(
                "root element is <{}>, expected a PLCopen <project>",
                root.name()
            ),
        );
        return unit;
    }
    let _version = version(ctx, root);
    vendor_data(ctx, root);
    // integer constants for array bounds: every constant global list of the file, vendor GVLs too,
    // then those of the other files given with it (a per-object export: `ARRAY[1..G.numAxis]` of
    // a list in another file)
    ctx.constants = decls::collect_constants(root, true, &|_| None);
    OTHER_FILES.with(|o| {
        if let Some(other) = o.borrow().as_ref() {
            for (k, v) in &other.constants {
                ctx.constants.entry(k.clone()).or_insert(*v);
            }
        }
    });

    let apps = application_resources(root);
    let (mut data_types, pou_els) = types_and_pous(ctx, root, single_pou);
    let mut headers = Vec::new();
    let mut index = Index::default();
    for d in &data_types {
        index.types.insert(d.name.key(), d.clone());
    }
    // CODESYS exports a function block's METHODs in its vendor data: their hidden variables are
    // part of the block's interface (other POUs read a method's result)
    let mut methods: HashMap<String, Vec<il_frontend::st::file::PendingMethod>> = HashMap::new();
    // POUs that inherit in CODESYS's vendor data and whose body is not ST: not compiled (E0303)
    let mut not_compiled: HashSet<String> = HashSet::new();
    // CODESYS's object orientation in vendor data (`xml_oop`): the interfaces, and in a file that
    // has them or a POU that inherits, each POU of ST text goes to the ST front end as a pending
    // body (flattened, checked and lowered there, as an `.st` file's)
    let resources: Vec<&Element> = application_resources(root)
        .into_iter()
        .chain(instance_resources(root))
        .collect();
    let interface_els = crate::xml_oop::interface_elements(root, &resources);
    let oop_file = !interface_els.is_empty()
        || pou_els
            .iter()
            .any(|p| crate::xml_oop::inheritance_element(p).is_some());
    for el in &interface_els {
        if let Some(pb) = crate::xml_oop::interface(ctx, el) {
            if let Some(il_frontend::st::inherit::Oop::Interface(i)) = pb.oop.as_deref() {
                index.interfaces.insert(i.name.key());
            }
            ctx.pending.push(pb);
        }
    }
    let mut as_text: HashSet<String> = HashSet::new();
    // implicit enumerations of the interfaces (`<type><enum>`) get CODESYS's internal type name, so
    // an ST body types their values by context (`mode := Run` where two enumerations have `Run`)
    let mut enum_namer = il_frontend::st::implicit_enums::PouNamer::new(&data_types);
    for p in &pou_els {
        let header = pou_header(ctx, p).map(|mut h| {
            enum_namer.pou(&mut h);
            // a variable-length in-out (`codesys_vla`) as its hidden address and bound inputs,
            // as the ST front end splits it in text (`il_frontend::st::varlen`): the calls and
            // the body's uses are rewritten when the ST bodies are lowered
            if matches!(h.kind, PouKind::Function | PouKind::FunctionBlock) {
                il_frontend::st::varlen::split_blocks(&mut h.var_blocks);
            }
            h
        });
        let mut ms = match &header {
            Some(h) => xml_methods(ctx, p, h),
            None => Vec::new(),
        };
        if let Some(mut h) = header {
            let inh = crate::xml_oop::inheritance_element(p);
            let pending = if oop_file {
                let oop = inh.map(|i| crate::xml_oop::block_oop(ctx, i));
                crate::xml_oop::pending_body(ctx, p, &h, ms.clone(), oop)
            } else {
                None
            };
            if let (Some(inh), None) = (inh, &pending) {
                // EXTENDS / IMPLEMENTS of a POU whose body is not ST (E0303): not compiled
                xml_inheritance(ctx, inh, &h);
                not_compiled.insert(h.name.key());
                for m in &mut ms {
                    m.text.clear();
                }
            }
            // (a pending body's methods give its block their variables in the ST front end: the
            // block's signature gets them here for the XML bodies that call them)
            let mut with_methods = pending.as_ref().map(|_| h.clone());
            if !ms.is_empty() {
                let target = with_methods.as_mut().unwrap_or(&mut h);
                il_frontend::st::file::add_method_vars(target, &ms, ctx.diags);
                index.method_sigs.insert(
                    h.name.key(),
                    ms.iter()
                        .map(il_frontend::st::types::MethodSig::of)
                        .collect(),
                );
                if pending.is_none() {
                    methods.insert(h.name.key(), ms);
                }
            }
            if let Some(pb) = pending {
                as_text.insert(h.name.key());
                ctx.pending.push(pb);
            }
            let mut sig = signature(with_methods.as_ref().unwrap_or(&h));
            sig.actions = p
                .child("actions")
                .into_iter()
                .flat_map(|a| a.children_named("action"))
                .filter_map(|a| a.attr("name").map(str::trim))
                .filter(|n| crate::values::is_ident(n))
                .map(str::to_string)
                .collect();
            index.pous.insert(h.name.key(), sig);
            headers.push((*p, h));
        }
    }
    for d in enum_namer.finish() {
        index.types.insert(d.name.key(), d.clone());
        data_types.push(d);
    }
    // the POUs and data types of the other XML files given with this one (CODESYS exports one
    // object per file): known to this file's calls and bodies, compiled with their own file
    OTHER_FILES.with(|o| {
        if let Some(other) = o.borrow().as_ref() {
            for sig in &other.pous {
                index
                    .pous
                    .entry(sig.name.to_ascii_uppercase())
                    .or_insert_with(|| sig.clone());
            }
            for d in &other.types {
                index.types.entry(d.name.key()).or_insert_with(|| d.clone());
            }
        }
    });
    let mut configs: Vec<Configuration> = root
        .child("instances")
        .and_then(|i| i.child("configurations"))
        .map(|c| {
            c.children_named("configuration")
                .filter_map(|e| configuration(ctx, e))
                .collect()
        })
        .unwrap_or_default();
    configs.extend(
        apps.iter()
            .filter_map(|r| application_configuration(ctx, r)),
    );
    let free_globals = project_global_lists(ctx, root);
    let blocks = configs
        .iter()
        .flat_map(|c| {
            c.globals
                .iter()
                .chain(c.resources.iter().flat_map(|r| r.globals.iter()))
        })
        .chain(free_globals.iter());
    for b in blocks {
        for v in &b.vars {
            index.globals.insert(v.name.key(), v.ty.clone());
            if let Some(list) = &b.name {
                index
                    .global_lists
                    .entry(list.key())
                    .or_default()
                    .insert(v.name.key(), v.ty.clone());
            }
        }
    }
    // the global variables of the text files given with this one: this file's own come first
    OTHER_FILES.with(|o| {
        if let Some(other) = o.borrow().as_ref() {
            for (k, t) in &other.globals {
                index.globals.entry(k.clone()).or_insert_with(|| t.clone());
            }
            for (list, members) in &other.global_lists {
                let known = index.global_lists.entry(list.clone()).or_default();
                for (k, t) in members {
                    known.entry(k.clone()).or_insert_with(|| t.clone());
                }
            }
        }
    });
    let additional;
    (index.missing_types, additional) = check_types(ctx, &index, &data_types, &headers, &configs);
    // Beremiz's and OpenPLC's additional blocks (`PID`, `INTEGRAL`, ...) the file uses and does not
    // define: their interfaces (ladderc's copy is compiled with the project, see
    // `il_frontend::st::additional_blocks`)
    for pou in il_frontend::st::additional_blocks::declarations() {
        let key = pou.name.key();
        let called = pou
            .var_blocks
            .iter()
            .flat_map(|b| b.vars.iter())
            .any(|v| matches!(&v.ty, TypeRef::Named(n) if additional.contains(&n.key())));
        if additional.contains(&key) || called {
            index.pous.entry(key).or_insert_with(|| signature(pou));
        }
    }

    if !data_types.is_empty() {
        unit.items.push(LibraryElement::DataTypes(data_types));
    }
    for (el, mut pou) in headers {
        if let Some(st) = el.child("body").and_then(|b| b.child("ST")) {
            let blocks = crate::st_body::body_declarations(ctx, st, &pou.name.name);
            pou.var_blocks.extend(blocks);
        }
        if as_text.contains(&pou.name.key()) {
            // its body and methods are lowered by the ST front end (`ctx.pending`)
            unit.items.push(LibraryElement::Pou(pou));
            continue;
        }
        let (stmts, hidden) = if not_compiled.contains(&pou.name.key()) {
            (Vec::new(), Vec::new())
        } else {
            body::lower_pou_body(ctx, &index, el, &pou)
        };
        pou.body = stmts;
        pou.var_blocks.extend(hidden);
        let mut lowered = Vec::new();
        let mut local = diagnostics::Diagnostics::new();
        for m in methods.get(&pou.name.key()).into_iter().flatten() {
            let decls = crate::st_body::declarations(&index);
            let action =
                il_frontend::st::file::lower_method(ctx.file, decls, &mut pou, m, &mut local);
            lowered.extend(action);
        }
        // the block's calls of its own methods (`M(...)`, `THIS^.M(...)`)
        il_frontend::st::file::inline_own_method_calls(&mut pou, &mut lowered, &mut local);
        for d in local {
            ctx.report_in_pou(d, &pou.name.name);
        }
        ctx.actions.extend(lowered);
        unit.items.push(LibraryElement::Pou(pou));
    }
    unit.items
        .extend(free_globals.into_iter().map(LibraryElement::GlobalVars));
    unit.items
        .extend(configs.into_iter().map(LibraryElement::Configuration));
    unit
}

/// The global variable lists a CODESYS export keeps outside `<instances>`, in the project's vendor
/// data: `addData/data[.../globalvars]/globalVars` (a GVL exported on its own) and
/// `addData/data[.../application]/resource/globalVars` (the lists of an application). They are
/// global to every POU of the file, like a `VAR_GLOBAL` outside a configuration.
fn project_global_lists(ctx: &mut Ctx, root: &Element) -> Vec<VarBlock> {
    let mut lists: Vec<&Element> = Vec::new();
    for data in root
        .children_named("addData")
        .flat_map(|a| a.children_named("data"))
    {
        let name = data.attr("name").unwrap_or("");
        if name.ends_with("/globalvars") {
            lists.extend(data.children_named("globalVars"));
        } else if name.ends_with("/application") {
            lists.extend(
                data.children_named("resource")
                    .flat_map(|r| r.children_named("globalVars")),
            );
        }
    }
    lists
        .into_iter()
        .flat_map(|g| decls::global_lists(ctx, g))
        .collect()
}

/// The `<resource>` of each application a CODESYS or TwinCAT export keeps in the project's vendor
/// data (`addData/data[.../application]/resource`, what "Export PLCopenXML" writes for a whole
/// application): its tasks and program instances, its global variable lists, and in its own
/// vendor data its data types (`.../datatype`) and POUs (`.../pou`).
fn application_resources<'b, 'a>(root: &'b Element<'a>) -> Vec<&'b Element<'a>> {
    root.children_named("addData")
        .flat_map(|a| a.children_named("data"))
        .filter(|d| d.attr("name").is_some_and(|n| n.ends_with("/application")))
        .flat_map(|d| d.children_named("resource"))
        .collect()
}

/// The `<resource>`s of the configurations under `<instances>`. A CODESYS export of a device
/// (V3.5 SP17 and later, WAGO e!COCKPIT) keeps the application's POUs and data types in the
/// vendor data of that resource (`resource/addData/data[.../pou]/pou`), not under `<types>`.
fn instance_resources<'b, 'a>(root: &'b Element<'a>) -> impl Iterator<Item = &'b Element<'a>> {
    root.child("instances")
        .and_then(|i| i.child("configurations"))
        .into_iter()
        .flat_map(|c| c.children_named("configuration"))
        .flat_map(|c| c.children_named("resource"))
}

/// The elements `<element>` of an application resource's vendor data blocks whose name ends
/// with `suffix`.
fn application_data<'e, 'a>(
    resource: &'e Element<'a>,
    suffix: &'static str,
    element: &'static str,
) -> impl Iterator<Item = &'e Element<'a>> {
    resource
        .children_named("addData")
        .flat_map(|a| a.children_named("data"))
        .filter(move |d| d.attr("name").is_some_and(|n| n.ends_with(suffix)))
        .flat_map(move |d| d.children_named(element))
}

/// An application resource's tasks and program instances, as a configuration of its own (named
/// after the resource; its global variable lists are read by [`project_global_lists`]), or
/// `None` when it has neither.
fn application_configuration(ctx: &mut Ctx, r: &Element) -> Option<Configuration> {
    if r.children_named("task").next().is_none() && r.children_named("pouInstance").next().is_none()
    {
        return None;
    }
    let res = resource_with(ctx, r, false)?;
    Some(Configuration {
        name: res.name.clone(),
        globals: Vec::new(),
        span: res.span,
        resources: vec![res],
        access: Vec::new(),
    })
}

/// Whether `ns` is a PLCopen TC6 namespace (tc6_0201, tc6_0200, tc6.xsd v1.0).
fn is_plcopen_namespace(ns: &str) -> bool {
    ns.contains("plcopen.org/xml/tc6")
}

fn version(ctx: &mut Ctx, root: &Element) -> Version {
    let ns = root.attr("xmlns").unwrap_or_default();
    if ns.contains("tc6_0201") {
        Version::V201
    } else if ns.contains("tc6_0200") {
        Version::V200
    } else if ns.contains("tc6.xsd") || ns.ends_with("/tc6") {
        Version::V1
    } else {
        let span = ctx.attr_span(root, "xmlns");
        let what = if ns.is_empty() {
            "no PLCopen namespace".to_string()
        } else {
            format!("unknown PLCopen namespace `{ns}`")
        };
        ctx.report(
            Diagnostic::warning(code::W3001, format!("{what}; reading it as tc6_0201")).at(span),
        );
        Version::V201
    }
}

/// Whether ladderc reads a vendor data block (`<data name="...">`): the CODESYS/TwinCAT global
/// variable lists, applications (their tasks, data types and POUs), task settings, and the methods
/// and properties of POUs, their EXTENDS / IMPLEMENTS and the project's INTERFACEs
/// (`crate::xml_oop`), the SFC settings of charts.
fn is_read_vendor_data(name: &str) -> bool {
    [
        "/globalvars",
        "/method",
        "/property",
        "/application",
        "/datatype",
        "/pou",
        "/tasksettings",
        // the ST code of a CODESYS EXECUTE box (graph.rs)
        "/stcode",
        // a CODESYS SFC element's attributes: a step's entry, step and exit actions
        // (`sfc::chart::StepAction`); the others repeat what the element says (names, conditions)
        "/sfc/element",
        // a CODESYS chart's SFC settings: its flags (`sfc::flags`: SFCInit and SFCReset run,
        // every other enabled flag is W3402)
        "/sfcsettings",
        // EXTENDS / IMPLEMENTS of a POU, and the project's INTERFACEs (`xml_oop`)
        "/pouinheritance",
        "/plcopenxml/interface",
        // a CODESYS UNION (`decls::union_type`)
        "/plcopenxml/union",
    ]
    .iter()
    .any(|s| name.ends_with(s))
}

/// One W3002 for all `addData` / vendor elements of the file that ladderc does not read (the
/// blocks it reads are searched for further vendor data inside them; an empty `<addData/>`, as
/// CODESYS writes one after each method's interface, holds nothing to ignore).
fn vendor_data(ctx: &mut Ctx, root: &Element) {
    // a CODESYS CFC chart is a body (`codesys_cfc`: read, or E0321 of its own), not ignored vendor
    // data
    let charts = crate::codesys_cfc::unread_charts(ctx, root);
    let mut found: Vec<&Element> = Vec::new();
    let mut ignored_name: Vec<(usize, &str)> = Vec::new();
    // (element, its parent's name)
    let mut stack = vec![(root, "")];
    while let Some((e, parent)) = stack.pop() {
        // the access specifier of a method, a property or an accessor (`xml_member_access`)
        let member_interface = e.name() == "interface"
            && matches!(
                parent,
                "Method" | "Property" | "GetAccessor" | "SetAccessor"
            );
        for c in e.children {
            if c.name() == "addData" {
                let mut ignored = c.children.iter().any(|d| d.name() != "data");
                for d in c.children_named("data") {
                    let name = d.attr("name").unwrap_or("");
                    if d.child("textDeclaration").is_some() {
                        // an interface's declarations as text (`text_declaration`)
                    } else if member_interface && name.ends_with("/accessmodifiers") {
                    } else if crate::codesys_vla::only_its_attributes(d) {
                        // a variable-length in-out's declaration (`codesys_vla`)
                    } else if charts.contains(&d.tag_start()) {
                    } else if is_read_vendor_data(name) {
                        stack.push((d, c.name()));
                    } else {
                        ignored = true;
                        ignored_name.push((c.tag_start(), name));
                    }
                }
                if ignored {
                    found.push(c);
                }
            } else if c.name() == "vendorElement" {
                found.push(c);
            } else {
                stack.push((c, e.name()));
            }
        }
    }
    found.sort_by_key(|e| e.tag_start());
    if let Some(first) = found.first() {
        let mut d = Diagnostic::warning(
            code::W3002,
            format!(
                "vendor data ignored ({} <{}> block{})",
                found.len(),
                first.name(),
                if found.len() == 1 { "" } else { "s" }
            ),
        )
        .at(ctx.tag(first))
        .with_primary_label("tool-specific data, not part of the program");
        ignored_name.sort_by_key(|(at, _)| *at);
        if let Some((_, name)) = ignored_name.iter().find(|(at, _)| *at == first.tag_start()) {
            d = d.with_note(format!("first block: {name}"));
        }
        ctx.report(d);
    }
}

/// A POU with its interface read and its body still empty.
fn pou_header(ctx: &mut Ctx, p: &Element) -> Option<Pou> {
    let span = ctx.tag(p);
    let Some(name) = p
        .attr("name")
        .map(str::trim)
        .filter(|n| values::is_ident(n))
    else {
        ctx.error(code::E3013, span, "POU without a valid `name`");
        return None;
    };
    let name = Ident::new(name, ctx.attr_span(p, "name"));
    let kind = match p.attr("pouType").map(str::trim) {
        Some("program") => PouKind::Program,
        Some("functionBlock") => PouKind::FunctionBlock,
        Some("function") => PouKind::Function,
        other => {
            ctx.error(
                code::E3013,
                ctx.attr_span(p, "pouType"),
                format!(
                    "POU `{}` has pouType `{}`; expected program, functionBlock or function",
                    name.name,
                    other.unwrap_or("")
                ),
            );
            return None;
        }
    };
    let mut var_blocks = Vec::new();
    let mut return_type = None;
    ctx.local_constants = match p.child("interface") {
        Some(iface) => {
            let globals = std::mem::take(&mut ctx.constants);
            let local = decls::collect_constants(iface, false, &|n| {
                globals.get(&n.to_ascii_uppercase()).copied()
            });
            ctx.constants = globals;
            local
        }
        None => Default::default(),
    };
    if let Some(iface) = p.child("interface") {
        read_interface(ctx, iface, &mut return_type, &mut var_blocks);
        if var_blocks.iter().all(|b| b.vars.is_empty()) {
            text_declaration(ctx, iface, &mut return_type, &mut var_blocks);
        }
    }
    ctx.local_constants.clear();
    // A function without `<returnType>` is a function without result (TC6 v2.01: `returnType`
    // has minOccurs=0; IEC 61131-3 ed.3 6.6.2.2: the result type may be left out), read as the
    // same `FUNCTION F` in ST is: it gives its results through VAR_OUTPUT.
    Some(Pou {
        class: false,
        kind,
        name,
        return_type,
        var_blocks,
        body: Vec::new(),
        span,
    })
}

/// The return type and variable lists of an `<interface>` (of a POU or a CODESYS method).
pub(crate) fn read_interface(
    ctx: &mut Ctx,
    iface: &Element,
    return_type: &mut Option<il_frontend::ast::TypeRef>,
    var_blocks: &mut Vec<VarBlock>,
) {
    for list in iface.children {
        if list.name() == "returnType" {
            *return_type = decls::type_ref(ctx, list);
        } else if let Some(k) = decls::var_kind(list.name()) {
            // (CODESYS's variable-length in-outs are exported among the inputs)
            var_blocks.extend(crate::codesys_vla::split_inputs(decls::var_block(
                ctx, list, k,
            )));
        } else if list.name() == "accessVars" {
            ctx.error(
                code::E3012,
                ctx.tag(list),
                "VAR_ACCESS lists are not supported",
            );
        }
    }
}

/// The declarations of an interface written as text in its vendor data (Bachmann's and RuSTy's
/// `<addData><data><textDeclaration><content>FUNCTION f : DINT VAR_INPUT ... END_VAR</content>`):
/// the header's return type and the `VAR` blocks after it, spans in the XML file.
fn text_declaration(
    ctx: &mut Ctx,
    iface: &Element,
    return_type: &mut Option<il_frontend::ast::TypeRef>,
    var_blocks: &mut Vec<VarBlock>,
) {
    let Some(content) = iface
        .children_named("addData")
        .flat_map(|a| a.children_named("data"))
        .find_map(|d| d.child("textDeclaration"))
        .and_then(|t| t.child("content"))
    else {
        return;
    };
    // one piece of text (plain or CDATA): its offsets are the file's
    let [seg] = content.segments() else {
        return;
    };
    let text = seg.text;
    // the header line (`FUNCTION_BLOCK name`, `FUNCTION name : TYPE`), then the blocks
    let lead = text.len() - text.trim_start().len();
    let header_end = text[lead..].find('\n').map_or(text.len(), |k| lead + k);
    let header = &text[lead..header_end];
    if let Some((_, ty)) = header.split_once(':') {
        let ty = ty.trim().trim_end_matches(';').trim();
        if values::is_ident(ty) && return_type.is_none() {
            let at = seg.start + lead + header.find(ty).unwrap_or(0);
            let span = ctx.span(at, at + ty.len());
            *return_type = Some(
                if ty.eq_ignore_ascii_case("STRING") || ty.eq_ignore_ascii_case("WSTRING") {
                    il_frontend::ast::TypeRef::String {
                        wide: ty.eq_ignore_ascii_case("WSTRING"),
                        length: None,
                        span,
                    }
                } else {
                    il_frontend::ast::TypeRef::Named(Ident::new(ty, span))
                },
            );
        }
    }
    let rest = &text[header_end..];
    if rest.trim().is_empty() {
        return;
    }
    let mut local = diagnostics::Diagnostics::new();
    var_blocks.extend(il_frontend::parse_var_blocks(
        ctx.file,
        rest,
        seg.start + header_end,
        &mut local,
    ));
    for d in local {
        ctx.report(d);
    }
}

/// Reads the interface of a method or property accessor of the POU `p`: its array bounds may name
/// the block's constants or the member's own.
fn read_member_interface(
    ctx: &mut Ctx,
    p: &Element,
    iface: &Element,
    return_type: &mut Option<il_frontend::ast::TypeRef>,
    var_blocks: &mut Vec<VarBlock>,
) {
    let globals = std::mem::take(&mut ctx.constants);
    let lookup = |n: &str| globals.get(&n.to_ascii_uppercase()).copied();
    let mut local = p
        .child("interface")
        .map(|i| decls::collect_constants(i, false, &lookup))
        .unwrap_or_default();
    local.extend(decls::collect_constants(iface, false, &|n| {
        local_or(&local, &globals, n)
    }));
    ctx.constants = globals;
    ctx.local_constants = local;
    read_interface(ctx, iface, return_type, var_blocks);
    ctx.local_constants.clear();
}

/// A constant of the block (`local`), else a global one.
fn local_or(
    local: &HashMap<String, i128>,
    globals: &HashMap<String, i128>,
    n: &str,
) -> Option<i128> {
    let k = n.to_ascii_uppercase();
    local.get(&k).or_else(|| globals.get(&k)).copied()
}

/// CODESYS's inheritance of a POU whose body is not ST (`interface/addData/data[.../pouinheritance]/
/// Inheritance` with `<Extends>` and `<Implements>`, `crate::xml_oop`): one E0303 at the element;
/// the POU's body is not compiled. ladderc flattens inheritance in ST text (`.st`, TwinCAT files,
/// and the ST bodies of PLCopen XML: `il_frontend::st::inherit`), not in graphical bodies.
fn xml_inheritance(ctx: &mut Ctx, inh: &Element, pou: &Pou) {
    ctx.report(
        Diagnostic::error(
            code::E0303,
            format!(
                "`{}` {}: inheritance is compiled for POUs whose body and actions are ST",
                pou.name.name,
                crate::xml_oop::clause(inh)
            ),
        )
        .at(ctx.tag(inh))
        .with_primary_label("object-oriented extension (IEC 61131-3 ed. 3)")
        .with_hint(
            "write the body of this POU in ST, or export it as ST text; its body is not compiled",
        )
        .with_xml(XmlContext {
            pou: Some(pou.name.name.clone()),
            ..Default::default()
        }),
    );
}

/// The METHODs of a POU in CODESYS's vendor data (`addData/data[.../method]/Method`, with an
/// `<interface>` and an ST `<body>`), read for a function block or a program, and its PROPERTYs
/// (`.../property`: `<Property name="P">` with `<interface><returnType>`, and a `<GetAccessor>`
/// and/or `<SetAccessor>` each with its own `<interface>` and ST `<body>`) as the methods of their
/// accessors (`il_frontend::st::property`); a PROGRAM's too (CODESYS V3 lets a program have
/// methods and properties, called inside it or as `PRG.M(x)`); a method or property of a function,
/// or one whose body is not ST, is E0303.
fn xml_methods(ctx: &mut Ctx, p: &Element, pou: &Pou) -> Vec<il_frontend::st::file::PendingMethod> {
    let mut out = Vec::new();
    for data in p
        .children_named("addData")
        .flat_map(|a| a.children_named("data"))
    {
        let kind = data.attr("name").unwrap_or("");
        let (method, items) = if kind.ends_with("/method") {
            (true, data.children_named("Method"))
        } else if kind.ends_with("/property") {
            (false, data.children_named("Property"))
        } else {
            continue;
        };
        for m in items {
            let name = m.attr("name").map(str::trim).unwrap_or("");
            let st = m.child("body").and_then(|b| b.child("ST"));
            let accessors: Vec<&Element> = m
                .children
                .iter()
                .filter(|c| matches!(c.name(), "GetAccessor" | "SetAccessor"))
                .collect();
            let body_st = |a: &Element| a.child("body").and_then(|b| b.child("ST")).is_some();
            // CODESYS V3 gives a PROGRAM methods and properties too, exported in the same vendor
            // data as a function block's (the ST front end compiles them in text: `PRG.M(x)`)
            let why = if !matches!(pou.kind, PouKind::FunctionBlock | PouKind::Program) {
                Some(if method {
                    "methods are compiled for function blocks and programs only".to_string()
                } else {
                    "properties are compiled for function blocks and programs only".to_string()
                })
            } else if !values::is_ident(name) {
                Some(format!(
                    "the {} has no name that is an identifier",
                    if method { "method" } else { "property" }
                ))
            } else if method && st.is_none() {
                Some("the method's body is not ST".to_string())
            } else if !method && accessors.is_empty() {
                Some("the property has no Get or Set accessor".to_string())
            } else if !method && !accessors.iter().all(|a| body_st(a)) {
                Some("an accessor's body is not ST".to_string())
            } else {
                None
            };
            if let Some(why) = why {
                ctx.report(
                    Diagnostic::error(
                        code::E0303,
                        format!(
                            "`{}`: {} `{name}` is not compiled: {why}",
                            pou.name.name,
                            if method { "METHOD" } else { "PROPERTY" }
                        ),
                    )
                    .at(ctx.tag(m))
                    .with_primary_label("object-oriented extension (IEC 61131-3 ed. 3)")
                    .with_hint("write it as a METHOD of a function block with an ST body, or as a FUNCTION")
                    .with_xml(XmlContext {
                        pou: Some(pou.name.name.clone()),
                        ..Default::default()
                    }),
                );
                continue;
            }
            let mut ret = None;
            let mut blocks = Vec::new();
            if !method {
                out.extend(xml_property(ctx, p, m, &pou.name.name, name, &accessors));
                continue;
            }
            if let Some(iface) = m.child("interface") {
                read_member_interface(ctx, p, iface, &mut ret, &mut blocks);
                // a variable-length in-out (`codesys_vla`), split as the block's are
                il_frontend::st::varlen::split_blocks(&mut blocks);
            }
            let ident = Ident::new(name, ctx.attr_span(m, "name"));
            let st = st.expect("checked above");
            let mut t = crate::il_body::embedded_text(st);
            crate::st_body::join_split_operators(&mut t.text, t.base, ctx.xml);
            out.push(il_frontend::st::file::PendingMethod {
                ret: ret.map(|ty| il_frontend::ast::VarDecl::new(ident.clone(), ty, ident.span)),
                name: ident,
                blocks,
                text: t.text,
                base: t.base,
                inst: Vec::new(),
                once: Vec::new(),
                local_inits: Vec::new(),
                overloaded: false,
                access: member_access(m)
                    .map(|a| restricted(ctx, m, &pou.name.name, name, "METHOD", a)),
            });
        }
    }
    out
}

/// The access specifier CODESYS writes in a method's, property's or accessor's interface
/// (`<interface><addData><data name=".../accessmodifiers"><AccessModifiers Private="true" />`),
/// as the ST front end reads `METHOD PRIVATE M` in text: `None` when none is written,
/// `Some(None)` for one that restricts nothing (PUBLIC, INTERNAL).
fn written_access(m: &Element) -> Option<Option<il_frontend::ast::Access>> {
    let modifiers = m
        .child("interface")?
        .children_named("addData")
        .flat_map(|a| a.children_named("data"))
        .filter(|d| {
            d.attr("name")
                .is_some_and(|n| n.ends_with("/accessmodifiers"))
        })
        .find_map(|d| d.child("AccessModifiers"))?;
    let set = |a: &str| {
        modifiers
            .attr(a)
            .is_some_and(|v| v.trim().eq_ignore_ascii_case("true"))
    };
    Some(if set("Private") {
        Some(il_frontend::ast::Access::Private)
    } else if set("Protected") {
        Some(il_frontend::ast::Access::Protected)
    } else {
        None
    })
}

/// The restricting access specifier written for `m` (see [`written_access`]).
fn member_access(m: &Element) -> Option<il_frontend::ast::Access> {
    written_access(m).flatten()
}

/// The restriction of member `name` (element `m`) of block `pou`, declared at its name.
fn restricted(
    ctx: &Ctx,
    m: &Element,
    pou: &str,
    name: &str,
    what: &'static str,
    access: il_frontend::ast::Access,
) -> il_frontend::ast::MemberAccess {
    il_frontend::ast::MemberAccess {
        access,
        owner: pou.to_ascii_uppercase(),
        owner_name: pou.to_string(),
        member: name.to_string(),
        at: ctx.attr_span(m, "name"),
        what,
    }
}

/// A PROPERTY of CODESYS's vendor data as the methods of its accessors (see [`xml_methods`]).
fn xml_property(
    ctx: &mut Ctx,
    p: &Element,
    m: &Element,
    pou: &str,
    name: &str,
    accessors: &[&Element],
) -> Vec<il_frontend::st::file::PendingMethod> {
    let ident = Ident::new(name, ctx.attr_span(m, "name"));
    let mut ty = None;
    if let Some(iface) = m.child("interface") {
        read_interface(ctx, iface, &mut ty, &mut Vec::new());
    }
    let Some(ty) = ty else {
        ctx.report(
            Diagnostic::error(
                code::E0303,
                format!("PROPERTY `{name}` has no type (no <returnType> in its <interface>)"),
            )
            .at(ctx.tag(m))
            .with_hint("export the property again from CODESYS: its type is written as its interface's return type")
            .with_xml(XmlContext {
                pou: Some(pou.to_string()),
                ..Default::default()
            }),
        );
        return Vec::new();
    };
    let mut get = None;
    let mut set = None;
    for a in accessors {
        let mut blocks = Vec::new();
        if let Some(iface) = a.child("interface") {
            read_member_interface(ctx, p, iface, &mut None, &mut blocks);
        }
        let Some(st) = a.child("body").and_then(|b| b.child("ST")) else {
            continue;
        };
        let mut t = crate::il_body::embedded_text(st);
        crate::st_body::join_split_operators(&mut t.text, t.base, ctx.xml);
        let slot = if a.name() == "GetAccessor" {
            &mut get
        } else {
            &mut set
        };
        *slot = Some((blocks, t.text, t.base));
    }
    // the accessor's own specifier (`SET PROTECTED`), else the property's
    let own = |kind: &str| {
        accessors
            .iter()
            .find(|a| a.name() == kind)
            .and_then(|a| written_access(a))
            .unwrap_or_else(|| member_access(m))
    };
    let (get_access, set_access) = (own("GetAccessor"), own("SetAccessor"));
    let mut methods = il_frontend::st::property::accessor_methods(&ident, &ty, get, set);
    for pm in &mut methods {
        let is_get = pm
            .name
            .name
            .starts_with(il_frontend::st::property::GET_PREFIX);
        let access = if is_get { get_access } else { set_access };
        pm.access = access.map(|a| restricted(ctx, m, pou, name, "PROPERTY", a));
    }
    methods
}

/// The interface of a POU read from any input (its pins, internals and result), as other PLCopen
/// XML files given with it see it ([`OtherFiles`]).
pub fn signature(p: &Pou) -> PouSig {
    let is_pin = |k: VarKind| matches!(k, VarKind::Input | VarKind::Output | VarKind::InOut);
    // Both lists sized once (a 10,000-rung program has 32,500 internals: growing the list by doubling
    // copied it into fresh pages five times).
    let pin_count: usize = p
        .var_blocks
        .iter()
        .filter(|b| is_pin(b.kind))
        .map(|b| b.vars.len())
        .sum();
    let all: usize = p.var_blocks.iter().map(|b| b.vars.len()).sum();
    let mut pins = Vec::with_capacity(pin_count);
    let mut internals = Vec::with_capacity(all - pin_count);
    for b in &p.var_blocks {
        let list = if is_pin(b.kind) {
            &mut pins
        } else {
            &mut internals
        };
        list.extend(
            b.vars
                .iter()
                .map(|v| (v.name.name.clone(), b.kind, v.ty.clone())),
        );
    }
    PouSig {
        kind: p.kind,
        name: p.name.name.clone(),
        pins,
        ret: p.return_type.clone(),
        internals,
        actions: Vec::new(),
    }
}

/// E3009: derived types that nothing defines (one diagnostic per missing type, labels on its uses);
/// returns their upper-case names, and those of the additional blocks of Beremiz and OpenPLC
/// (`PID`, ...) used and not defined, which are no error.
fn check_types(
    ctx: &mut Ctx,
    index: &Index,
    data_types: &[TypeDecl],
    pous: &[(&Element, Pou)],
    configs: &[Configuration],
) -> (HashSet<String>, HashSet<String>) {
    let mut uses: Vec<(String, il_frontend::Span, String)> = Vec::new();
    let additional = std::cell::RefCell::new(HashSet::new());
    let visit = |ty: &TypeRef, owner: &str, uses: &mut Vec<_>| {
        let mut t = ty;
        loop {
            match t {
                TypeRef::Array { element, .. } => t = element,
                // `REFERENCE TO Lib.T`: the library's type is what is missing
                TypeRef::Ref { target, .. } if matches!(&**target, TypeRef::Named(n) if n.name.contains('.')) => {
                    t = target
                }
                _ => break,
            }
        }
        if let TypeRef::Named(n) = t {
            if !catalogue::is_library_type(&n.name)
                && !index.types.contains_key(&n.key())
                && !index.pous.contains_key(&n.key())
                && !index.interfaces.contains(&n.key())
            {
                if il_frontend::st::additional_blocks::is_additional(&n.name) {
                    additional.borrow_mut().insert(n.key());
                } else {
                    uses.push((n.name.clone(), n.span, owner.to_string()));
                }
            }
        }
    };
    for d in data_types {
        match &d.def {
            il_frontend::ast::TypeDef::Alias { ty, .. } => visit(ty, &d.name.name, &mut uses),
            il_frontend::ast::TypeDef::Struct { fields } => {
                for f in fields {
                    visit(&f.ty, &d.name.name, &mut uses)
                }
            }
            il_frontend::ast::TypeDef::Enum { .. } => {}
        }
    }
    let blocks = pous
        .iter()
        .flat_map(|(_, p)| p.var_blocks.iter().map(move |b| (p.name.name.clone(), b)))
        .chain(configs.iter().flat_map(|c| {
            c.globals
                .iter()
                .chain(c.resources.iter().flat_map(|r| r.globals.iter()))
                .map(move |b| (c.name.name.clone(), b))
        }));
    for (owner, b) in blocks {
        for v in &b.vars {
            visit(&v.ty, &owner, &mut uses);
        }
    }
    for (_, p) in pous {
        if let Some(r) = &p.return_type {
            visit(r, &p.name.name, &mut uses);
        }
    }
    let mut order: Vec<String> = Vec::new();
    let mut by_name: HashMap<String, Vec<(il_frontend::Span, String)>> = HashMap::new();
    for (name, span, owner) in uses {
        let key = name.to_ascii_uppercase();
        if !by_name.contains_key(&key) {
            order.push(name.clone());
        }
        by_name.entry(key).or_default().push((span, owner));
    }
    let missing = by_name.keys().cloned().collect();
    for name in order {
        let list = &by_name[&name.to_ascii_uppercase()];
        let (first, owner) = &list[0];
        let mut d = Diagnostic::error(
            code::E3009,
            format!(
                "type `{name}` is not defined in this project ({} use{})",
                list.len(),
                if list.len() == 1 { "" } else { "s" }
            ),
        )
        .at(*first)
        .with_primary_label("unknown type")
        .with_hint(
            "the type probably comes from a library of the editing tool that is not in this file",
        )
        .with_xml(diagnostics::XmlContext {
            pou: Some(owner.clone()),
            ..Default::default()
        });
        for (s, _) in list.iter().skip(1) {
            d = d.with_label(*s, "also used here");
        }
        ctx.report(d);
    }
    (missing, additional.into_inner())
}

fn configuration(ctx: &mut Ctx, c: &Element) -> Option<Configuration> {
    let span = ctx.tag(c);
    let Some(name) = c
        .attr("name")
        .map(str::trim)
        .filter(|n| values::is_ident(n))
    else {
        ctx.error(code::E3013, span, "configuration without a valid `name`");
        return None;
    };
    let globals = c
        .children_named("globalVars")
        .flat_map(|g| decls::global_lists(ctx, g))
        .collect();
    let resources = c
        .children_named("resource")
        .filter_map(|r| resource(ctx, r))
        .collect();
    let access = c
        .children_named("accessVars")
        .flat_map(|l| l.children_named("accessVariable"))
        .filter_map(|v| access_variable(ctx, v))
        .collect();
    for list in c.children_named("configVars") {
        crate::var_config::read(ctx, list, name);
    }
    Some(Configuration {
        name: Ident::new(name, ctx.attr_span(c, "name")),
        globals,
        resources,
        access,
        span,
    })
}

/// `<accessVariable alias="n" instancePathAndName="res.prog.x" direction="readWrite"><type>` of a
/// configuration's `<accessVars>` (tc6_0201 `varListAccess`): the access path `n : res.prog.x : T
/// READ_WRITE` of an ST configuration, READ_ONLY without `direction`. The path's names all point at
/// the attribute. One that cannot be read is E0308.
fn access_variable(ctx: &mut Ctx, v: &Element) -> Option<il_frontend::ast::AccessDecl> {
    let span = ctx.tag(v);
    let bad = |ctx: &mut Ctx, why: &str| {
        ctx.report(
            Diagnostic::error(code::E0308, format!("this access variable cannot be read: {why}"))
                .at(span)
                .with_hint("write alias=\"name\" instancePathAndName=\"resource.program.variable\" direction=\"readWrite\" with a <type>"),
        );
        None
    };
    let alias = v.attr("alias").map(str::trim).unwrap_or("");
    if !values::is_ident(alias) {
        return bad(ctx, "`alias` is not a name");
    }
    let path_text = v.attr("instancePathAndName").map(str::trim).unwrap_or("");
    let pspan = ctx.attr_span(v, "instancePathAndName");
    let (names, address) = match path_text.find('%') {
        Some(k) => {
            let Some(addr) = values::address(&path_text[k..], pspan) else {
                return bad(ctx, "the path's direct address cannot be read");
            };
            (path_text[..k].trim_end_matches('.'), Some(addr))
        }
        None => (path_text, None),
    };
    let path: Vec<Ident> = names
        .split('.')
        .filter(|n| !n.is_empty())
        .map(|n| Ident::new(n.trim(), pspan))
        .collect();
    if path.iter().any(|n| !values::is_ident(&n.name)) || (path.is_empty() && address.is_none()) {
        return bad(
            ctx,
            "`instancePathAndName` is not `resource.program.variable`",
        );
    }
    let ty = v.child("type").and_then(|t| t.children.first());
    let type_name = match ty {
        Some(t) if t.name() == "derived" => t.attr("name").unwrap_or("").trim().to_string(),
        Some(t) => t.name().to_ascii_uppercase(),
        None => String::new(),
    };
    if !values::is_ident(&type_name) {
        return bad(ctx, "its <type> is not an elementary or named type");
    }
    let read_only = match v.attr("direction").map(str::trim) {
        None => true,
        Some(d) if d.eq_ignore_ascii_case("readOnly") => true,
        Some(d) if d.eq_ignore_ascii_case("readWrite") => false,
        Some(_) => return bad(ctx, "`direction` is readWrite or readOnly"),
    };
    Some(il_frontend::ast::AccessDecl {
        name: Ident::new(alias, ctx.attr_span(v, "alias")),
        path,
        subscripts: Vec::new(),
        address,
        type_name: Ident::new(type_name, span),
        read_only,
        span,
    })
}

fn resource(ctx: &mut Ctx, r: &Element) -> Option<Resource> {
    resource_with(ctx, r, true)
}

/// A `<resource>`; its `<globalVars>` only with `globals` (an application resource's lists are
/// read with the project's vendor lists).
fn resource_with(ctx: &mut Ctx, r: &Element, globals: bool) -> Option<Resource> {
    let span = ctx.tag(r);
    let Some(name) = r
        .attr("name")
        .map(str::trim)
        .filter(|n| values::is_ident(n))
    else {
        ctx.error(code::E3013, span, "resource without a valid `name`");
        return None;
    };
    let globals: Vec<VarBlock> = r
        .children_named("globalVars")
        .filter(|_| globals)
        .flat_map(|g| decls::global_lists(ctx, g))
        .collect();
    let mut tasks = Vec::new();
    let mut programs = Vec::new();
    for t in r.children_named("task") {
        let Some(task) = task(ctx, t) else { continue };
        let mut calls = 0;
        let mut library_calls = 0;
        for pi in t.children_named("pouInstance") {
            calls += 1;
            if library_program_call(ctx, pi, Some(&task.name)) {
                library_calls += 1;
            } else if let Some(p) = program_instance(ctx, pi, Some(&task.name)) {
                programs.push(p);
            }
        }
        // a task that runs only library programs (CODESYS's VISU_TASK) is left out with them:
        // it has nothing left to run
        if calls == 0 || library_calls < calls {
            tasks.push(task);
        }
    }
    for pi in r.children_named("pouInstance") {
        if library_program_call(ctx, pi, None) {
            continue;
        }
        if let Some(p) = program_instance(ctx, pi, None) {
            programs.push(p);
        }
    }
    Some(Resource {
        name: Ident::new(name, ctx.attr_span(r, "name")),
        on: None,
        globals,
        tasks,
        programs,
        span,
    })
}

fn task(ctx: &mut Ctx, t: &Element) -> Option<Task> {
    let span = ctx.tag(t);
    let Some(name) = t
        .attr("name")
        .map(str::trim)
        .filter(|n| values::is_ident(n))
    else {
        ctx.error(code::E3013, span, "task without a valid `name`");
        return None;
    };
    let interval = t.attr("interval").and_then(|iv| {
        let s = ctx.attr_span(t, "interval");
        let xsd = iv.trim().trim_start_matches('-');
        if xsd.starts_with('P') {
            // tc6_0200/0201: the attribute is an xsd:duration (CODESYS writes `PT0.05S`)
            return match values::xsd_duration(iv) {
                Ok(ns) => Some(Operand::literal(Literal {
                    kind: LiteralKind::Duration(ns),
                    type_prefix: None,
                    span: s,
                })),
                Err(why) => {
                    ctx.report(
                        Diagnostic::error(
                            code::E3400,
                            format!(
                                "task interval `{}` is not a valid xsd:duration: {why}",
                                iv.trim()
                            ),
                        )
                        .at(s)
                        .with_hint(
                            "write it as PT<seconds>S, e.g. PT0.01S for 10 ms, or PT1H2M3.5S",
                        ),
                    );
                    None
                }
            };
        }
        let parsed = values::literal(iv, s).or_else(|| {
            values::duration(iv).map(|d| Literal {
                kind: LiteralKind::Duration(d),
                type_prefix: None,
                span: s,
            })
        });
        match parsed {
            Some(l) => Some(Operand::literal(l)),
            None => match values::operand(iv, s) {
                Some(op @ Operand::Var(_)) => Some(op),
                _ => {
                    ctx.error(
                        code::E3011,
                        s,
                        format!("task interval `{iv}` is not a duration"),
                    );
                    None
                }
            },
        }
    });
    // CODESYS and TwinCAT keep a cyclic task's period in their task settings too, and TwinCAT
    // writes `interval="PT0S"` beside them: the settings give the period the task runs with.
    let zero = matches!(
        &interval,
        Some(Operand::Literal(l)) if l.kind == LiteralKind::Duration(0)
    );
    let interval = match (&interval, zero) {
        (None, _) | (_, true) => task_settings_interval(ctx, t).or(interval),
        _ => interval,
    };
    let single = t.attr("single").and_then(|sg| {
        let s = ctx.attr_span(t, "single");
        let op = values::operand(sg, s);
        if op.is_none() {
            ctx.error(
                code::E3011,
                s,
                format!("task trigger `{sg}` is not a variable"),
            );
        }
        op
    });
    let priority = t.attr("priority").and_then(|p| p.trim().parse().ok());
    Some(Task {
        name: Ident::new(name, ctx.attr_span(t, "name")),
        interval,
        single,
        priority,
        span,
    })
}

/// The period of a cyclic task from its CODESYS/TwinCAT settings,
/// `addData/data[.../tasksettings]/TaskSettings KindOfTask="Cyclic" Interval="10000"
/// IntervalUnit="us"` (or `Interval="t#10ms"`); `None` for another kind of task, a zero or
/// unreadable period.
fn task_settings_interval(ctx: &mut Ctx, t: &Element) -> Option<Operand> {
    let settings = t
        .children_named("addData")
        .flat_map(|a| a.children_named("data"))
        .filter(|d| d.attr("name").is_some_and(|n| n.ends_with("/tasksettings")))
        .flat_map(|d| d.children_named("TaskSettings"))
        .next()?;
    if !settings
        .attr("KindOfTask")
        .is_some_and(|k| k.trim().eq_ignore_ascii_case("cyclic"))
    {
        return None;
    }
    let text = settings.attr("Interval")?.trim();
    let ns = match text.split_once('#') {
        Some((prefix, rest))
            if ["T", "TIME", "LT", "LTIME"].contains(&prefix.to_ascii_uppercase().as_str()) =>
        {
            values::duration(rest)?
        }
        Some(_) => return None,
        None => {
            let n: f64 = text.parse().ok()?;
            let unit = match settings.attr("IntervalUnit").map(str::trim) {
                Some("ns") => 1.0,
                Some("us") => 1e3,
                Some("s") => 1e9,
                _ => 1e6,
            };
            (n * unit).round() as i128
        }
    };
    (ns > 0).then(|| {
        Operand::literal(Literal {
            kind: LiteralKind::Duration(ns),
            type_prefix: None,
            span: ctx.attr_span(settings, "Interval"),
        })
    })
}

/// Whether `pi` calls a program of a library, which the export does not hold: a library-qualified
/// name (`VisuElems.Visu_Prg`, the visualisation program CODESYS V3 generates and runs in its
/// `VISU_TASK`) with an empty `typeName` (or the same name). It is left out with one W1447 naming
/// it, as the same call in a TwinCAT task file is. A program of the project is never qualified, so
/// an instance named after one (`name="PLC_PRG" typeName=""`) is not such a call.
fn library_program_call(ctx: &mut Ctx, pi: &Element, task: Option<&Ident>) -> bool {
    let Some(name) = pi.attr("name").map(str::trim) else {
        return false;
    };
    let ty = pi
        .attr("typeName")
        .or_else(|| pi.attr("type"))
        .map(str::trim)
        .unwrap_or("");
    let qualified = name.contains('.') && name.split('.').all(values::is_ident);
    if !qualified || !(ty.is_empty() || ty.eq_ignore_ascii_case(name)) {
        return false;
    }
    let library = name.split('.').next().unwrap_or(name);
    let in_task = task.map_or(String::new(), |t| format!(" of task `{}`", t.name));
    ctx.report(
        Diagnostic::warning(
            code::W1447,
            format!("program `{name}`{in_task} is left out: it comes from library `{library}`, not from this file"),
        )
        .at(ctx.attr_span(pi, "name"))
        .with_primary_label("a library's program (CODESYS writes its visualisation's `VisuElems.Visu_Prg` so)")
        .with_hint("nothing to do for a visualisation; a library program the application needs must be given as a POU of the project"),
    );
    true
}

fn program_instance(ctx: &mut Ctx, pi: &Element, task: Option<&Ident>) -> Option<ProgramInstance> {
    let span = ctx.tag(pi);
    let name = pi
        .attr("name")
        .map(str::trim)
        .filter(|n| values::is_ident(n));
    // tc6_0201/0200 say `typeName`; v1.0 says `type`.
    let ty_attr = if pi.attr("typeName").is_some() {
        "typeName"
    } else {
        "type"
    };
    // CODESYS writes `typeName=""`: the instance is named after its program.
    let ty = pi
        .attr(ty_attr)
        .map(str::trim)
        .filter(|n| !n.is_empty())
        .or(name)
        .filter(|n| values::is_ident(n));
    let (Some(name), Some(ty)) = (name, ty) else {
        match (pi.attr("name").map(str::trim), name) {
            // a name that is there but not an identifier: say so, at the name
            (Some(bad), None) if !bad.is_empty() => ctx.error(
                code::E3013,
                ctx.attr_span(pi, "name"),
                format!("program instance name `{bad}` is not an IEC 61131-3 identifier"),
            ),
            _ => ctx.error(
                code::E3013,
                span,
                "program instance needs a `name` and a `typeName`",
            ),
        }
        return None;
    };
    Some(ProgramInstance {
        name: Ident::new(name, ctx.attr_span(pi, "name")),
        retain: false,
        task: task.cloned(),
        type_name: Ident::new(
            ty,
            if pi.attr(ty_attr).is_some_and(|t| !t.trim().is_empty()) {
                ctx.attr_span(pi, ty_attr)
            } else {
                ctx.attr_span(pi, "name")
            },
        ),
        args: Vec::new(),
        span,
    })
}
