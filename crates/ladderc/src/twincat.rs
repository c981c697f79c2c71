//! TwinCAT 3 PLC projects: a `.plcproj` file (MSBuild XML) or a folder holding one stands for the
//! object files it lists (`<Compile Include="POUs\MAIN.TcPOU">`), and the tasks of its `.TcTTO` files
//! become the configuration that runs the programs.
//!
//! Input: the command line's paths; the units read from TwinCAT object files and their tasks. Output:
//! the paths of the object files to read, in the project's order; a configuration unit (the tasks,
//! each program instance named like its program) and the base scan cycle (the greatest common divisor
//! of the tasks' cycle times). Invariants: never panics; a path that is no TwinCAT project is kept as
//! it is; without a task file the one PROGRAM runs, else `MAIN`, else one located E0322; a task
//! calling a program no file declares is one E0322 at its name in the task file.

use crate::pipeline::Session;
use diagnostics::{code, Diagnostic, Diagnostics, FileId, Span};
use il_frontend::ast::{CompilationUnit, LibraryElement, PouKind};
use ladder_compiler::twincat::TcTask;
use std::path::{Path, PathBuf};

/// The extensions of the TwinCAT object files ladderc reads (lower case).
pub const OBJECT_EXTENSIONS: [&str; 5] = ["tcpou", "tcdut", "tcgvl", "tcio", "tctto"];

/// Whether `path` names a TwinCAT object file or project file by its extension.
pub fn is_twincat_file(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .is_some_and(|e| OBJECT_EXTENSIONS.contains(&e.as_str()) || e == "plcproj")
}

/// What [`expand`] read of the TwinCAT projects given.
#[derive(Debug, Default)]
pub struct ProjectsRead {
    /// The file name of each project saved as a library.
    pub libraries: Vec<String>,
    /// The names each project may be referenced by (`user_libraries::identity`).
    pub names: Vec<Vec<String>>,
}

/// `paths` with each `.plcproj` file, and each folder holding one (directly or up to three folders
/// down, as a `.tsproj`/`.sln` folder does), replaced by the object files the project lists. The
/// compiler defines of the projects' properties (`<CompilerDefines>`) go to `defines`, their
/// library references to `references` (`None` when no input is a project). A listed file that
/// does not exist is one E1079 at its `<Compile>` element (the project's text is added to the
/// session's sources for it), and its stem goes to `missing`. The file name of each project saved
/// as a library (`is_library_project`) and the names each project may be referenced by go to
/// `projects`.
pub fn expand(
    session: &mut Session,
    paths: &[PathBuf],
    defines: &mut Vec<(String, String)>,
    missing: &mut Vec<String>,
    references: &mut Option<Vec<crate::user_libraries::Reference>>,
    projects: &mut ProjectsRead,
    diags: &mut Diagnostics,
) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for p in paths {
        // a Visual Studio solution (`.sln`) or TwinCAT system project (`.tsproj`) stands for the
        // folder that holds it: its PLC project is looked for there, as for a folder
        // (`Demo.sln` given from its own folder has the empty path as its parent)
        let holder = (has_extension(p, "sln") || has_extension(p, "tsproj"))
            .then(|| match p.parent() {
                Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
                _ => PathBuf::from("."),
            })
            .filter(|d| session.disk && d.is_dir());
        let input = p;
        let p = holder.as_ref().unwrap_or(p);
        let project = if has_extension(p, "plcproj") {
            Some(p.clone())
        } else if session.disk && p.is_dir() && !p.join("plc.xml").is_file() {
            let mut found = Vec::new();
            find_projects(p, 0, &mut found);
            found.sort();
            match found.len() {
                0 => None,
                1 => found.pop(),
                _ => {
                    let list: Vec<String> = found
                        .iter()
                        .map(|f| f.strip_prefix(p).unwrap_or(f).display().to_string())
                        .collect();
                    diags.push(
                        Diagnostic::error(
                            code::E0322,
                            format!(
                                "{} holds {} TwinCAT PLC projects: {}",
                                p.display(),
                                found.len(),
                                list.join(", ")
                            ),
                        )
                        .with_hint("give the .plcproj file of the one to read"),
                    );
                    continue;
                }
            }
        } else {
            None
        };
        match project {
            Some(project) => match session.read_file(&project) {
                Ok(text) => {
                    defines.extend(compiler_defines(&text));
                    if is_library_project(&text) {
                        projects.libraries.push(
                            project
                                .file_name()
                                .map_or_else(String::new, |n| n.to_string_lossy().into_owned()),
                        );
                    }
                    references
                        .get_or_insert_with(Vec::new)
                        .extend(crate::user_libraries::references(&text));
                    projects
                        .names
                        .push(crate::user_libraries::identity(&project, &text).names);
                    let mut project_file = None;
                    for (path, include) in listed_files(&project, &text) {
                        if let Some(found) = listed_file_on_disk(session, &path) {
                            out.push(found);
                            continue;
                        }
                        let file = *project_file.get_or_insert_with(|| {
                            session
                                .map
                                .add_file_owned(project.display().to_string(), text.clone())
                        });
                        diags.push(missing_object(file, &path, include));
                        if let Some(stem) = path.file_stem().and_then(|s| s.to_str()) {
                            missing.push(stem.to_string());
                        }
                    }
                }
                // reading it as an input reports the error
                Err(_) => out.push(project),
            },
            None => {
                // a solution whose PLC project is not there: E1079 at each `PrjFilePath` of its
                // system projects that names no file
                if let Some(dir) = &holder {
                    if missing_plc_projects(session, paths_given(input, dir), dir, diags) {
                        continue;
                    }
                }
                out.push(p.clone())
            }
        }
    }
    out
}

/// The `.tsproj` files a solution input stands for: the input itself, or those a `.sln` names.
fn paths_given(input: &Path, dir: &Path) -> Vec<PathBuf> {
    if has_extension(input, "tsproj") {
        return vec![input.to_path_buf()];
    }
    let Ok(text) = std::fs::read_to_string(input) else {
        return Vec::new();
    };
    text.split('"')
        .filter(|part| part.to_ascii_lowercase().ends_with(".tsproj"))
        .map(|part| {
            let part = part.replace('\\', "/");
            if dir == Path::new(".") {
                PathBuf::from(part)
            } else {
                dir.join(part)
            }
        })
        .collect()
}

/// Reports (E1079) each PLC project (`<Project ... PrjFilePath="PLC\PLC.plcproj">`) that the
/// system projects `tsprojs` name and that is not in `dir`; whether one was reported.
fn missing_plc_projects(
    session: &mut Session,
    tsprojs: Vec<PathBuf>,
    dir: &Path,
    diags: &mut Diagnostics,
) -> bool {
    let mut reported = false;
    for ts in tsprojs {
        let Ok(text) = std::fs::read_to_string(&ts) else {
            continue;
        };
        let key = "PrjFilePath=\"";
        let mut file = None;
        let mut from = 0;
        while let Some(k) = text[from..].find(key) {
            let start = from + k + key.len();
            let Some(len) = text[start..].find('"') else {
                break;
            };
            from = start + len;
            let listed = &text[start..start + len];
            let path = dir.join(listed.replace('\\', "/"));
            if !has_extension(&path, "plcproj") || path.is_file() {
                continue;
            }
            let file = *file.get_or_insert_with(|| {
                session
                    .map
                    .add_file_owned(ts.display().to_string(), text.clone())
            });
            diags.push(
                Diagnostic::error(
                    code::E1079,
                    format!("the solution lists {listed}, which is not there"),
                )
                .at(Span::new(file, start, start + len))
                .with_primary_label("listed here")
                .with_hint("restore the PLC project (e.g. from version control), or give its .plcproj file"),
            );
            reported = true;
        }
    }
    reported
}

/// Whether a `.plcproj` is a library's project: TwinCAT writes the library's properties
/// (`<Released>`, `<LibraryCategories>`, `<Company>` with `<Title>`) into the projects saved as
/// libraries, and no task (a library's programs run when the code using it calls them).
pub(crate) fn is_library_project(text: &str) -> bool {
    let has = |tag: &str| text.contains(&format!("<{tag}>")) || text.contains(&format!("<{tag} "));
    has("Released") || has("LibraryCategories") || (has("Company") && has("Title"))
}

pub(crate) fn has_extension(p: &Path, ext: &str) -> bool {
    p.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case(ext))
}

/// The `.plcproj` files in `dir` and its sub-folders, at most three levels down.
pub(crate) fn find_projects(dir: &Path, depth: usize, found: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut subdirs = Vec::new();
    for e in entries.flatten() {
        let path = e.path();
        if path.is_dir() {
            subdirs.push(path);
        } else if has_extension(&path, "plcproj") {
            found.push(path);
        }
    }
    if found.is_empty() && depth < 3 {
        subdirs.sort();
        for d in subdirs {
            find_projects(&d, depth + 1, found);
        }
    }
}

/// The compiler defines of a `.plcproj`'s properties: `<CompilerDefines>A, B:='1'</CompilerDefines>`
/// (TwinCAT's "Compiler defines" field, names separated by commas, each with an optional value),
/// as (name, value) pairs for the conditional pragmas (`{IF defined (A)}`).
fn compiler_defines(text: &str) -> Vec<(String, String)> {
    let arena = ladder_compiler::xml::Arena::new();
    let (root, _) = ladder_compiler::xml::parse(text, &arena);
    let Some(root) = root else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for el in root.walk().filter(|e| e.name() == "CompilerDefines") {
        for item in el.text().split([',', ';']) {
            let (name, value) = match item.split_once(":=").or_else(|| item.split_once('=')) {
                Some((n, v)) => (n.trim(), v.trim().trim_matches('\'')),
                None => (item.trim(), ""),
            };
            if !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
                out.push((name.to_string(), value.to_string()));
            }
        }
    }
    out
}

/// The file a project's `<Compile Include>` path `path` names: the path itself when it exists (or
/// when the session reads no disk), else the one file it names when the case of its letters is
/// ignored: TwinCAT runs on Windows, whose file names ignore case, so a file renamed in case only
/// (Include `FB_LinkDataLWord.TcPOU`, file `FB_LinkDataLWORD.TcPOU`) is still the project's. The
/// one rule for an application's project and a `--lib` library project alike; `None` when no file
/// (or several) match.
pub fn listed_file_on_disk(session: &Session, path: &Path) -> Option<PathBuf> {
    if session.file_exists(path) || !session.disk {
        return Some(path.to_path_buf());
    }
    case_insensitive(path)
}

/// The file `path` names when the case of its letters is ignored (the project's folder first, then
/// each component matched among its folder's entries without regard to case); `None` when none or
/// several match.
fn case_insensitive(path: &Path) -> Option<PathBuf> {
    let mut at = PathBuf::new();
    for part in path.components() {
        let next = at.join(part);
        if next.exists() || !matches!(part, std::path::Component::Normal(_)) {
            at = next;
            continue;
        }
        let want = part.as_os_str().to_str()?;
        let dir = if at.as_os_str().is_empty() {
            Path::new(".")
        } else {
            at.as_path()
        };
        let mut found = std::fs::read_dir(dir)
            .ok()?
            .flatten()
            .map(|e| e.file_name())
            .filter(|n| n.to_str().is_some_and(|n| n.eq_ignore_ascii_case(want)));
        let name = found.next()?;
        if found.next().is_some() {
            return None;
        }
        at = at.join(name);
    }
    at.is_file().then_some(at)
}

/// E1079 at the `Include` attribute (byte range `include` of the project `file`) of `path`.
fn missing_object(file: FileId, path: &Path, include: (usize, usize)) -> Diagnostic {
    Diagnostic::error(
        code::E1079,
        format!(
            "the project lists {}, which is not there",
            path.display()
        ),
    )
    .at(Span::new(file, include.0, include.1))
    .with_primary_label("listed here")
    .with_hint("restore the file (e.g. from version control), or remove its `<Compile>` element from the project; the other files are checked as usual")
}

/// `text` with MSBuild's `%XX` escapes (two hexadecimal digits, a byte) decoded; other text as it
/// is (a `%` not followed by two hexadecimal digits stays).
fn msbuild_unescape(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut k = 0;
    while k < b.len() {
        let hex = |c: u8| (c as char).to_digit(16);
        if b[k] == b'%' && k + 2 < b.len() {
            if let (Some(h), Some(l)) = (hex(b[k + 1]), hex(b[k + 2])) {
                out.push((h * 16 + l) as u8);
                k += 3;
                continue;
            }
        }
        out.push(b[k]);
        k += 1;
    }
    String::from_utf8(out).unwrap_or_else(|_| text.to_string())
}

/// The object files a `.plcproj` lists (`<Compile Include="POUs\MAIN.TcPOU">`), relative to its
/// folder, in its order, each with the byte range of its `Include` value in `text`; the other items
/// (visualisations, text lists) are left out, and so is an object excluded from the build
/// (`<ExcludeFromBuild>true</ExcludeFromBuild>`: CODESYS "Properties: Build", the object is not
/// compiled).
pub(crate) fn listed_files(project: &Path, text: &str) -> Vec<(PathBuf, (usize, usize))> {
    let dir = project.parent().unwrap_or(Path::new(""));
    let arena = ladder_compiler::xml::Arena::new();
    let (root, _) = ladder_compiler::xml::parse(text, &arena);
    let Some(root) = root else {
        return vec![(project.to_path_buf(), (0, 0))];
    };
    let mut out = Vec::new();
    for el in root.walk() {
        if el.name() != "Compile" {
            continue;
        }
        let Some((include, range)) = el.attr_and_range("Include") else {
            continue;
        };
        if el
            .child("ExcludeFromBuild")
            .is_some_and(|x| x.text().trim().eq_ignore_ascii_case("true"))
        {
            continue;
        }
        // MSBuild escapes special characters in item paths (`XTS %28Do Not Edit%29\\X.TcPOU`)
        let include = msbuild_unescape(include);
        let rel: PathBuf = include.split(['\\', '/']).collect();
        if is_twincat_file(&rel) && !has_extension(&rel, "plcproj") {
            out.push((dir.join(rel), range));
        }
    }
    out
}

/// The configuration that runs a TwinCAT project's programs: from its tasks, else the one PROGRAM
/// or `MAIN`. `units` are all units read; `twincat` says which came from TwinCAT object files;
/// `failed` names the object files that could not be read (a task calling one is not reported again).
/// A task's call of a library program (`VisuElems.Visu_Prg`, TwinCAT's visualisation; `VISU_PRG`
/// of a task `VISU_TASK` where no file declares it, as 3.1.4022 writes it) is left out.
/// Returns the base cycle in ms when tasks give one. Nothing is added when a unit already has a
/// CONFIGURATION. A library's project (`library_projects` names those read) has no task and no
/// program to choose: its programs are compiled, with one note (W1434), and none is configured.
pub fn configure(
    session: &mut Session,
    units: &mut Vec<CompilationUnit>,
    twincat: &[bool],
    tasks: &[(FileId, TcTask)],
    failed: &[String],
    library_projects: &[String],
) -> Option<f64> {
    let has_config = units.iter().any(|u| {
        u.items
            .iter()
            .any(|i| matches!(i, LibraryElement::Configuration(_)))
    });
    if has_config {
        return None;
    }
    // the PROGRAMs of the TwinCAT files (name, span of its name)
    let programs: Vec<(String, Span)> = units
        .iter()
        .zip(twincat.iter().chain(std::iter::repeat(&false)))
        .filter(|(_, &tc)| tc)
        .flat_map(|(u, _)| u.items.iter())
        .filter_map(|i| match i {
            LibraryElement::Pou(p) if p.kind == PouKind::Program => {
                Some((p.name.name.clone(), p.name.span))
            }
            _ => None,
        })
        .collect();
    let all_programs: Vec<String> = units
        .iter()
        .flat_map(|u| u.items.iter())
        .filter_map(|i| match i {
            LibraryElement::Pou(p) if p.kind == PouKind::Program => Some(p.name.key()),
            _ => None,
        })
        .collect();
    let mut lines = Vec::new();
    let mut instances: Vec<String> = Vec::new();
    let mut cycles = Vec::new();
    let tasks: Vec<&(FileId, TcTask)> = tasks
        .iter()
        .filter(|(_, t)| !t.programs.is_empty())
        .collect();
    if tasks.is_empty() {
        if programs.len() < 2 {
            return None;
        }
        let Some((main, _)) = programs
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case("MAIN"))
        else {
            let names: Vec<&str> = programs.iter().map(|(n, _)| n.as_str()).collect();
            if let Some(library) = library_projects.first() {
                session.diags.push(
                    Diagnostic::new(
                        code::W1434,
                        diagnostics::Severity::Note,
                        format!(
                            "`{library}` is a library's project: its {} programs ({}) are compiled, \
                             and no task says which runs",
                            programs.len(),
                            shown_names(&names)
                        ),
                    )
                    .at(programs[0].1)
                    .with_hint(
                        "`check` and `build` need nothing more; `run` calls every program each \
                         cycle in file order: to run one, give a project whose task calls it",
                    ),
                );
                return None;
            }
            session.diags.push(
                Diagnostic::error(
                    code::E0322,
                    format!(
                        "{} TwinCAT programs ({}) and no task file: which one runs is not said",
                        programs.len(),
                        shown_names(&names)
                    ),
                )
                .at(programs[0].1)
                .with_hint(
                    "give the project's task file (.TcTTO) or its .plcproj, or name the program to \
                     run MAIN",
                ),
            );
            return None;
        };
        lines.push("TASK PlcTask(INTERVAL := T#10ms, PRIORITY := 20);".to_string());
        lines.push(format!("PROGRAM {main} WITH PlcTask : {main};"));
    } else {
        for (file, t) in tasks {
            let task_name = safe_name(&t.name).unwrap_or_else(|| "PlcTask".to_string());
            let cycle = t.cycle_us.unwrap_or(10_000);
            let task_line = format!(
                "TASK {task_name}(INTERVAL := T#{cycle}us, PRIORITY := {});",
                t.priority.unwrap_or(20)
            );
            let before = instances.len();
            let mut calls = Vec::new();
            for (name, (s, e)) in &t.programs {
                if name.contains('.') || failed.iter().any(|f| f.eq_ignore_ascii_case(name)) {
                    continue;
                }
                let known =
                    safe_name(name).filter(|n| all_programs.contains(&n.to_ascii_uppercase()));
                // TwinCAT 3.1.4022's visualisation task calls `VISU_PRG`, which the
                // visualisation manager generates (later versions write `VisuElems.Visu_Prg`)
                if known.is_none()
                    && t.name.eq_ignore_ascii_case("VISU_TASK")
                    && name.eq_ignore_ascii_case("VISU_PRG")
                {
                    continue;
                }
                let Some(program) = known else {
                    session.diags.push(
                        Diagnostic::error(
                            code::E0322,
                            format!(
                                "task `{}` calls `{name}`, which no file given declares as a PROGRAM",
                                t.name
                            ),
                        )
                        .at(Span::new(*file, *s, *e))
                        .with_hint("give the program's .TcPOU file too, or the .plcproj that lists it"),
                    );
                    continue;
                };
                if instances.iter().any(|i| i.eq_ignore_ascii_case(&program)) {
                    continue;
                }
                calls.push(format!("PROGRAM {program} WITH {task_name} : {program};"));
                instances.push(program);
            }
            // a task that runs none of the programs read (only a visualisation) is left out
            if instances.len() > before {
                cycles.push(cycle);
                lines.push(task_line);
                lines.extend(calls);
            }
        }
        if instances.is_empty() {
            return None;
        }
    }
    let text = format!(
        "CONFIGURATION TwinCAT\nRESOURCE PLC ON PLC\n{}\nEND_RESOURCE\nEND_CONFIGURATION\n",
        lines.join("\n")
    );
    let file = session.map.add("<TwinCAT tasks>", text);
    let src = session.map.get(file).text.clone();
    let (unit, _, _) = il_frontend::st::file::parse_text(
        file,
        &src,
        "TwinCAT",
        il_frontend::st::file::Lang::St,
        &mut session.diags,
    );
    units.push(unit);
    let gcd = cycles.into_iter().reduce(|a, b| {
        let (mut a, mut b) = (a, b);
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    })?;
    Some(gcd as f64 / 1000.0)
}

/// `name` when it is an IEC identifier (so it can be written into the configuration's text).
/// At most five names, then how many more: `A, B, C, D, E and 28 more`.
fn shown_names(names: &[&str]) -> String {
    match names.len() {
        0..=5 => names.join(", "),
        n => format!("{} and {} more", names[..5].join(", "), n - 5),
    }
}

fn safe_name(name: &str) -> Option<String> {
    let mut chars = name.chars();
    let first = chars.next()?;
    ((first.is_ascii_alphabetic() || first == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_'))
    .then(|| name.to_string())
}
