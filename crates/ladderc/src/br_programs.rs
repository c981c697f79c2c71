//! B&R Automation Studio programs, one folder each (`Logical/Conveyor/`: `Main.st` with `PROGRAM
//! _INIT`, `_CYCLIC`, `_EXIT`, or `Init.st`, `Cyclic.st`, `Exit.st`; `Variables.var`).
//!
//! Input: the parsed units with their IL bodies (the `.var` files' bare VAR blocks already global
//! lists, W0018) and the source map (the files' paths). Output: for each folder that holds such
//! parts, one PROGRAM named after the folder whose VAR blocks are the folder's `.var` blocks and
//! whose body runs `_INIT`'s statements in its first cycle (behind a hidden flag), then
//! `_CYCLIC`'s; `_EXIT`'s are dropped (a run never stops); one note W0020 per program.
//! Invariants: only `.var` files of the program's own folder become its variables (a project's
//! `Global.var` stays global), and they do so before the parts' statements are compiled
//! ([`own_variables`]), so no program's statements see another program's `.var` names; a folder whose name makes no identifier is named as
//! [`il_frontend::implicit_program_name`] makes one; labels and flags added start with `__`.

use diagnostics::{code, Diagnostic, Diagnostics, Severity, SourceMap};
use il_frontend::ast::{
    CompilationUnit, Condition, Ident, IlStmt, InstrKind, Instruction, LibraryElement, Literal,
    LiteralKind, Op, Operand, Pou, PouKind, TypeRef, VarBlock, VarDecl, VarKind, VarRef,
};
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};

/// The B&R program parts.
const PARTS: [&str; 3] = ["_INIT", "_CYCLIC", "_EXIT"];

/// Whether `file` is a `.var` file (B&R's variable declarations).
fn is_var_file(map: &SourceMap, file: diagnostics::FileId) -> bool {
    Path::new(&map.get(file).name)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("var"))
}

/// Makes each program folder's `.var` blocks the VAR blocks of every program part of the folder
/// (`_INIT`, `_CYCLIC`, `_EXIT`), before the parts' statements are compiled: Automation Studio
/// keeps a program's `Variables.var` to that program (`Private="true"` in its `IEC.prg`), so a
/// name the part uses is its own program's variable whatever another program declares (round 34,
/// before: the `.var` blocks were global until [`join`], and a part's `i := 7` was typed by
/// another program's `i : REAL`, E1006 or not depending on the order of the files). A folder with
/// two parts of one kind keeps its `.var` blocks global (the checks' E1002 names the parts). A
/// variable named like one of the program's actions in another case (`PACK_ML` and the action
/// `Pack_ML`: two names in case-sensitive Automation Studio, one under IEC 61131-3) stays global,
/// as before round 34, so that the action and the variable both keep working.
pub fn own_variables(
    units: &mut [CompilationUnit],
    pending: &[il_frontend::st::file::PendingBody],
    map: &SourceMap,
) {
    let mut folders_of: HashMap<diagnostics::FileId, PathBuf> = HashMap::new();
    let mut dir_of = |file: diagnostics::FileId| -> PathBuf {
        folders_of
            .entry(file)
            .or_insert_with(|| {
                let name = Path::new(&map.get(file).name);
                let path = std::fs::canonicalize(name).unwrap_or_else(|_| name.to_path_buf());
                path.parent().unwrap_or(Path::new("")).to_path_buf()
            })
            .clone()
    };
    // the parts by folder: (unit, item, part)
    let mut folders: BTreeMap<PathBuf, Vec<(usize, usize, usize)>> = BTreeMap::new();
    for (u, unit) in units.iter().enumerate() {
        for (i, item) in unit.items.iter().enumerate() {
            if let LibraryElement::Pou(p) = item {
                if let (PouKind::Program, Some(k)) = (
                    p.kind,
                    PARTS
                        .iter()
                        .position(|n| p.name.name.eq_ignore_ascii_case(n)),
                ) {
                    folders
                        .entry(dir_of(p.name.span.file))
                        .or_default()
                        .push((u, i, k));
                }
            }
        }
    }
    folders.retain(|_, parts| {
        (0..PARTS.len()).all(|k| parts.iter().filter(|p| p.2 == k).count() <= 1)
    });
    if folders.is_empty() {
        return;
    }
    // the actions of each folder's parts (their files are in the folder)
    let mut actions: HashMap<PathBuf, Vec<&Ident>> = HashMap::new();
    for pb in pending {
        let dir = dir_of(pb.file);
        if folders.contains_key(&dir) {
            actions
                .entry(dir)
                .or_default()
                .extend(pb.actions.iter().map(|a| &a.0));
        }
    }
    // the folders' `.var` blocks, taken out of the global lists
    let mut blocks: BTreeMap<PathBuf, Vec<VarBlock>> = BTreeMap::new();
    for unit in units.iter_mut() {
        unit.items.retain_mut(|item| {
            let LibraryElement::GlobalVars(b) = item else {
                return true;
            };
            if !is_var_file(map, b.span.file) {
                return true;
            }
            let dir = dir_of(b.span.file);
            if !folders.contains_key(&dir) {
                return true;
            }
            let case_twin = |v: &VarDecl| {
                actions.get(&dir).is_some_and(|acts| {
                    acts.iter()
                        .any(|a| a.key() == v.name.key() && a.name != v.name.name)
                })
            };
            let (global, own): (Vec<VarDecl>, Vec<VarDecl>) =
                b.vars.iter().cloned().partition(case_twin);
            blocks.entry(dir).or_default().push(VarBlock {
                access: None,
                name: None,
                kind: VarKind::Local,
                vars: own,
                ..b.clone()
            });
            b.vars = global;
            !b.vars.is_empty()
        });
    }
    for (dir, parts) in folders {
        let Some(own) = blocks.get(&dir) else {
            continue;
        };
        for (u, i, _) in parts {
            if let Some(LibraryElement::Pou(p)) = units[u].items.get_mut(i) {
                let mut vars = own.clone();
                vars.append(&mut p.var_blocks);
                p.var_blocks = vars;
            }
        }
    }
}

/// Joins each folder's program parts and variables (see the module header).
pub fn join(units: &mut [CompilationUnit], map: &SourceMap, diags: &mut Diagnostics) {
    // each file's absolute folder (`Main.st` given from its own folder is in that folder),
    // looked up once per file
    let mut folders_of: HashMap<diagnostics::FileId, PathBuf> = HashMap::new();
    let mut dir_of = |file: diagnostics::FileId| -> PathBuf {
        folders_of
            .entry(file)
            .or_insert_with(|| {
                let name = Path::new(&map.get(file).name);
                let path = std::fs::canonicalize(name).unwrap_or_else(|_| name.to_path_buf());
                path.parent().unwrap_or(Path::new("")).to_path_buf()
            })
            .clone()
    };
    // the parts by folder: (unit, item, part)
    let mut folders: BTreeMap<PathBuf, Vec<(usize, usize, usize)>> = BTreeMap::new();
    for (u, unit) in units.iter().enumerate() {
        for (i, item) in unit.items.iter().enumerate() {
            if let LibraryElement::Pou(p) = item {
                if let (PouKind::Program, Some(k)) = (
                    p.kind,
                    PARTS
                        .iter()
                        .position(|n| p.name.name.eq_ignore_ascii_case(n)),
                ) {
                    folders
                        .entry(dir_of(p.name.span.file))
                        .or_default()
                        .push((u, i, k));
                }
            }
        }
    }
    let mut removals = Vec::new();
    // each program made: its POU name and its folder (for W1450)
    let mut made: Vec<(String, PathBuf)> = Vec::new();
    // the `.var` files that became a program's variables: their W0018 is withdrawn (W0020 says it)
    let mut own_files = Vec::new();
    let with_parts: Vec<PathBuf> = folders.keys().cloned().collect();
    // the names of the blocks, functions and types (not the program parts): a program folder
    // named like one is a program of another name (see `il_frontend::BR_PROGRAM_SUFFIX`)
    let taken: std::collections::HashSet<String> = units
        .iter()
        .flat_map(|u| u.items.iter())
        .flat_map(|item| match item {
            LibraryElement::Pou(p) if !PARTS.iter().any(|n| p.name.is(n)) => vec![p.name.key()],
            LibraryElement::DataTypes(types) => types.iter().map(|t| t.name.key()).collect(),
            _ => Vec::new(),
        })
        .collect();
    for (dir, parts) in folders {
        // one of each part (two `_CYCLIC` in one folder: the checks' E1002)
        if PARTS
            .iter()
            .enumerate()
            .any(|(k, _)| parts.iter().filter(|p| p.2 == k).count() > 1)
        {
            continue;
        }
        let part = |k: usize| parts.iter().find(|p| p.2 == k).map(|p| (p.0, p.1));
        let Some(host) = part(1).or(part(0)) else {
            continue;
        };
        let folder = dir
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or("BRProgram");
        let shown = il_frontend::implicit_program_name(folder);
        let name = if taken.contains(&shown.to_ascii_uppercase()) {
            format!("{shown}{}", il_frontend::BR_PROGRAM_SUFFIX)
        } else {
            shown.clone()
        };
        made.push((name.clone(), dir.clone()));
        let init = part(0).and_then(|(u, i)| pou_at(units, u, i).cloned());
        let Some(LibraryElement::Pou(p)) = units[host.0].items.get_mut(host.1) else {
            continue;
        };
        let at = p.name.span;
        diags.push(
            Diagnostic::new(
                code::W0020,
                Severity::Note,
                format!("B&R program `{shown}` (its folder): the folder's .var variables, _INIT once, then _CYCLIC each cycle"),
            )
            .at(at)
            .with_hint("as Automation Studio builds a program of a folder; _EXIT does not run (a run has no stop)"),
        );
        p.name = Ident::new(&name, at);
        // the folder's `.var` blocks, made the parts' own by `own_variables`
        own_files.extend(
            p.var_blocks
                .iter()
                .map(|b| b.span.file)
                .filter(|&f| is_var_file(map, f)),
        );
        let cyclic_is_host = part(1).is_some();
        if let Some(init) = init {
            let flag = Ident::new("__BR_INIT_DONE", at);
            p.var_blocks.push(VarBlock::locals(
                vec![VarDecl {
                    name: flag.clone(),
                    location: None,
                    ty: TypeRef::Named(Ident::new("BOOL", at)),
                    init: None,
                    edge: None,
                    span: at,
                }],
                at,
            ));
            if cyclic_is_host {
                // (the folder's `.var` blocks: the host has its own copy)
                p.var_blocks.extend(
                    init.var_blocks
                        .iter()
                        .filter(|b| !is_var_file(map, b.span.file))
                        .cloned(),
                );
            }
            let flag_ref = VarRef {
                base: flag,
                accessors: Default::default(),
                span: at,
            };
            let instr = |kind| IlStmt::Instr(Instruction { kind, span: at });
            let label = Ident::new("__BR_CYCLIC", at);
            let mut body = vec![
                instr(InstrKind::Simple {
                    op: Op::Ld,
                    negate: false,
                    operand: Some(Operand::Var(flag_ref.clone())),
                }),
                instr(InstrKind::Jump {
                    cond: Condition::IfTrue,
                    label: label.clone(),
                }),
                instr(InstrKind::Simple {
                    op: Op::Ld,
                    negate: false,
                    operand: Some(Operand::literal(Literal {
                        kind: LiteralKind::Bool(true),
                        type_prefix: None,
                        span: at,
                    })),
                }),
                instr(InstrKind::Simple {
                    op: Op::St,
                    negate: false,
                    operand: Some(Operand::Var(flag_ref)),
                }),
            ];
            // a RETURN of _INIT ends _INIT, not the first cycle: _CYCLIC still runs after it
            let mut init_body = init.body.clone();
            return_to(&mut init_body, &label);
            body.extend(init_body);
            body.push(IlStmt::Label(label));
            if cyclic_is_host {
                body.append(&mut p.body);
            }
            p.body = body;
            if cyclic_is_host {
                if let Some((u, i)) = part(0) {
                    removals.push((u, i));
                }
            }
        }
        if let Some((u, i)) = part(2) {
            removals.push((u, i));
        }
    }
    removals.sort();
    removals.dedup();
    for (u, i) in removals.into_iter().rev() {
        units[u].items.remove(i);
    }
    diags.retain(|d| d.code != code::W0018 || !d.span.is_some_and(|s| own_files.contains(&s.file)));
    drop_codeless_programs(units, map, &with_parts, &mut dir_of, diags);
    // the `.st` files of each program's folder: its parts and actions
    let mut st_files: Vec<(PathBuf, diagnostics::FileId)> = Vec::new();
    for (id, f) in map.files() {
        let st = Path::new(&f.name)
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("st"));
        if st {
            st_files.push((dir_of(id), id));
        }
    }
    case_shadows(units, map, &made, &st_files, diags);
}

/// W1450 at each use, in a B&R program's `.st` files (its parts, its actions), of a name spelled as a global variable of a
/// `.var` file and not as the program's own variable of that name in another case (`MIXING` and
/// `Mixing`): two variables in case-sensitive Automation Studio, one under IEC 61131-3 (6.1.2),
/// which ladderc keeps (the program's own); the warning says the run is not the controller's
/// (round 27, before: silent). Only there: elsewhere a POU that hides a global by a name differing
/// in case is read alike by every IEC tool (CODESYS, TwinCAT and the standard ignore case).
fn case_shadows(
    units: &[CompilationUnit],
    map: &SourceMap,
    made: &[(String, PathBuf)],
    st_files: &[(PathBuf, diagnostics::FileId)],
    diags: &mut Diagnostics,
) {
    use il_frontend::st::lexer::{lex, Tok};
    // the globals of `.var` files: spelling and declaration
    let globals: Vec<&Ident> = units
        .iter()
        .flat_map(|u| u.items.iter())
        .filter_map(|item| match item {
            LibraryElement::GlobalVars(b)
                if Path::new(&map.get(b.span.file).name)
                    .extension()
                    .is_some_and(|e| e.eq_ignore_ascii_case("var")) =>
            {
                Some(b.vars.iter().map(|v| &v.name))
            }
            _ => None,
        })
        .flatten()
        .collect();
    if globals.is_empty() {
        return;
    }
    for (name, dir) in made {
        let Some(p) = units
            .iter()
            .flat_map(|u| u.items.iter())
            .find_map(|item| match item {
                LibraryElement::Pou(p) if p.kind == PouKind::Program && p.name.is(name) => Some(p),
                _ => None,
            })
        else {
            continue;
        };
        // (the global, the program's own variable) differing in case only
        let hidden: Vec<(&Ident, &Ident)> = p
            .var_blocks
            .iter()
            .flat_map(|b| b.vars.iter())
            .filter_map(|v| {
                globals
                    .iter()
                    .find(|g| g.key() == v.name.key() && g.name != v.name.name)
                    .map(|g| (*g, &v.name))
            })
            .collect();
        if hidden.is_empty() {
            continue;
        }
        for &(_, file) in st_files.iter().filter(|(d, _)| d == dir) {
            let src = map.get(file).text.as_str();
            let toks = lex(src).0;
            for (k, t) in toks.iter().enumerate() {
                if t.tok != Tok::Ident || (k > 0 && toks[k - 1].tok == Tok::Dot) {
                    continue;
                }
                let word = &src[t.range.clone()];
                let Some((g, own)) = hidden.iter().find(|(g, _)| g.name == word) else {
                    continue;
                };
                let span = diagnostics::Span {
                    file,
                    start: t.range.start as u32,
                    end: t.range.end as u32,
                };
                diags.push(
                    Diagnostic::new(
                        code::W1450,
                        Severity::Warning,
                        format!(
                            "`{word}` here is the program's own `{}` (IEC 61131-3 ignores case): in case-sensitive B&R Automation Studio it is the global `{}`, another variable",
                            own.name, g.name
                        ),
                    )
                    .at(span)
                    .with_primary_label("spelled as the global")
                    .with_label(own.span, "the program's own variable (IEC 61131-3 ignores case: it hides the global)")
                    .with_label(g.span, "the global variable")
                    .with_hint("rename one of the two (`ladderc explain W1450`): this run differs from the controller's"),
                );
            }
        }
    }
}

/// `stmts` (an `_INIT` body joined before `_CYCLIC`) with each RETURN a jump to `end`.
fn return_to(stmts: &mut [IlStmt], end: &Ident) {
    for s in stmts {
        if let IlStmt::Instr(i) = s {
            match &mut i.kind {
                InstrKind::Return { cond } => {
                    i.kind = InstrKind::Jump {
                        cond: *cond,
                        label: end.clone(),
                    };
                }
                InstrKind::Deferred { body, .. } => return_to(body, end),
                _ => {}
            }
        }
    }
}

/// The `.var` and `.typ` files of a B&R program folder (it holds `IEC.prg`, or `ANSIC.prg` for a
/// program in C, round 27) none of whose program parts is among the inputs (its code is LD or C,
/// or not given): the program's own declarations
/// (`Private` in IEC.prg), which no other POU may name, so they are not compiled; one note W0022
/// per folder. Before: read as global, two such programs' `Variables.var` were E1002 duplicates.
fn drop_codeless_programs(
    units: &mut [CompilationUnit],
    map: &SourceMap,
    with_parts: &[PathBuf],
    dir_of: &mut impl FnMut(diagnostics::FileId) -> PathBuf,
    diags: &mut Diagnostics,
) {
    let ext = |file: diagnostics::FileId, e: &str| {
        Path::new(&map.get(file).name)
            .extension()
            .is_some_and(|x| x.eq_ignore_ascii_case(e))
    };
    let mut dropped: BTreeMap<PathBuf, diagnostics::Span> = BTreeMap::new();
    let mut program_folder: HashMap<PathBuf, bool> = HashMap::new();
    let mut files = Vec::new();
    for unit in units.iter_mut() {
        unit.items.retain(|item| {
            let (file, span) = match item {
                LibraryElement::GlobalVars(b) if ext(b.span.file, "var") => (b.span.file, b.span),
                LibraryElement::DataTypes(types) => match types.first() {
                    Some(t) if ext(t.name.span.file, "typ") => (t.name.span.file, t.name.span),
                    _ => return true,
                },
                _ => return true,
            };
            let dir = dir_of(file);
            let codeless = !with_parts.contains(&dir)
                && *program_folder
                    .entry(dir.clone())
                    .or_insert_with(|| is_program_folder(&dir));
            if codeless {
                dropped.entry(dir).or_insert(span);
                files.push(file);
            }
            !codeless
        });
    }
    // their W0018 ("read as global variables") is withdrawn: W0022 says what became of them
    diags.retain(|d| d.code != code::W0018 || !d.span.is_some_and(|s| files.contains(&s.file)));
    for (dir, at) in dropped {
        let folder = dir.file_name().and_then(|n| n.to_str()).unwrap_or("?");
        diags.push(
            Diagnostic::new(
                code::W0022,
                Severity::Note,
                format!("B&R program `{folder}`: none of its code is among the inputs, so its own .var and .typ declarations are not compiled"),
            )
            .at(at)
            .with_hint("a program written in LD or C (or another language ladderc does not read) declares them for itself alone; give its .st files to compile it"),
        );
    }
}

/// A B&R program folder's actions file (`Actions.st`: `ACTION Name : ... END_ACTION`, no POU):
/// its actions become those of the folder's `_INIT`, `_CYCLIC` and `_EXIT` parts (inlined where
/// they call them, before [`join`] makes one program of the parts); so are those of an actions file
/// in a package the program folder lists in its `IEC.prg` (`<Object Type="Package">`). In a folder
/// with no such part (a library's), the actions become those of the folder's function blocks
/// whose statements call one of them by name (round 26). A file of actions that none of them
/// takes keeps its E1060 (reported by `lone_members::attach`).
pub fn attach_actions(
    units: &[CompilationUnit],
    pending: &mut Vec<il_frontend::st::file::PendingBody>,
    map: &SourceMap,
) {
    let folder = |file: diagnostics::FileId| -> PathBuf {
        let name = Path::new(&map.get(file).name);
        let path = std::fs::canonicalize(name).unwrap_or_else(|_| name.to_path_buf());
        path.parent().unwrap_or(Path::new("")).to_path_buf()
    };
    let mut taken = Vec::new();
    for (a, pb) in pending.iter().enumerate() {
        let actions_file = pb
            .lone
            .as_ref()
            .is_some_and(|l| l.owner.is_none() && pb.methods.is_empty())
            && !pb.actions.is_empty();
        if !actions_file {
            continue;
        }
        // its folder, or the program folder whose package (nested packages too) holds it
        let mut dir = folder(pb.file);
        loop {
            let parts: Vec<usize> = pending
                .iter()
                .enumerate()
                .filter(|(_, q)| {
                    q.lone.is_none()
                        && !q.sfc
                        && q.pou_name(units)
                            .is_some_and(|n| PARTS.iter().any(|p| n.name.eq_ignore_ascii_case(p)))
                        && folder(q.file) == dir
                })
                .map(|(k, _)| k)
                .collect();
            if !parts.is_empty() {
                taken.push((a, parts));
                break;
            }
            match dir.parent() {
                Some(up) if lists_package(up, &dir) => dir = up.to_path_buf(),
                _ => break,
            }
        }
        if taken.last().is_some_and(|(t, _)| *t == a) {
            continue;
        }
        // a library folder's actions file: the actions of the folder's function blocks whose
        // statements call them by name (`ACT_Drive;` in `Valve.st`, as Automation Studio's
        // library lists them with the block's files; IEC 61131-3 ed. 3 6.7.2: an action belongs to
        // a function block and works on its instance's variables); none calling: E1060 stays
        let dir = folder(pb.file);
        let names: Vec<String> = pb
            .actions
            .iter()
            .map(|(n, ..)| n.name.to_ascii_lowercase())
            .collect();
        let blocks: Vec<usize> = pending
            .iter()
            .enumerate()
            .filter(|(_, q)| {
                q.lone.is_none()
                    && !q.sfc
                    && folder(q.file) == dir
                    && is_function_block(units, q)
                    && calls_any(&q.text, &names)
            })
            .map(|(k, _)| k)
            .collect();
        if !blocks.is_empty() {
            taken.push((a, blocks));
        }
    }
    for (a, parts) in taken.iter().rev() {
        let actions = pending[*a].actions.clone();
        for &k in parts {
            pending[k].actions.extend(actions.iter().cloned());
        }
    }
    for (a, _) in taken.into_iter().rev() {
        pending.remove(a);
    }
}

/// Whether `body` is the statements of a FUNCTION_BLOCK.
fn is_function_block(units: &[CompilationUnit], body: &il_frontend::st::file::PendingBody) -> bool {
    units.iter().flat_map(|u| u.items.iter()).any(|i| {
        matches!(i, LibraryElement::Pou(p)
            if p.kind == PouKind::FunctionBlock
                && p.name.span.file == body.file
                && p.name.span.start as usize == body.name_start)
    })
}

/// Whether statements `text` name one of `names` (lower case): a call of an action by its name.
fn calls_any(text: &str, names: &[String]) -> bool {
    use il_frontend::st::lexer::{lex, Tok};
    lex(text).0.iter().any(|t| {
        t.tok == Tok::Ident
            && text
                .get(t.range.clone())
                .is_some_and(|w| names.iter().any(|n| w.eq_ignore_ascii_case(n)))
    })
}

/// Whether folder `dir`'s `IEC.prg` (a program) or `.pkg` file (a package) lists its sub-folder
/// `sub` as a package (`<Object Type="Package">Name</Object>`): Automation Studio keeps a
/// program's actions so (round 25, before: E1060 and an E1001 at each call).
fn lists_package(dir: &Path, sub: &Path) -> bool {
    let Some(name) = sub.file_name().and_then(|n| n.to_str()) else {
        return false;
    };
    let Ok(entries) = std::fs::read_dir(dir) else {
        return false;
    };
    entries.flatten().any(|e| {
        let path = e.path();
        let listing = path
            .file_name()
            .and_then(|n| n.to_str())
            .is_some_and(|n| n.eq_ignore_ascii_case("IEC.prg"))
            || path
                .extension()
                .is_some_and(|x| x.eq_ignore_ascii_case("pkg"));
        listing
            && std::fs::read_to_string(&path).is_ok_and(|text| {
                text.split("<Object").skip(1).any(|o| {
                    let Some((attrs, rest)) = o.split_once('>') else {
                        return false;
                    };
                    attrs.contains("Type=\"Package\"")
                        && rest.split('<').next().is_some_and(|n| n.trim() == name)
                })
            })
    })
}

/// Whether `dir` is a B&R program folder: it holds `IEC.prg` (a program in IEC languages) or
/// `ANSIC.prg` (a program in C or C++, round 27: its `.var` files are as private to it).
pub(crate) fn is_program_folder(dir: &Path) -> bool {
    ["IEC.prg", "ANSIC.prg"]
        .iter()
        .any(|n| dir.join(n).is_file())
}

fn pou_at(units: &[CompilationUnit], u: usize, i: usize) -> Option<&Pou> {
    match units.get(u)?.items.get(i)? {
        LibraryElement::Pou(p) => Some(p),
        _ => None,
    }
}
