//! User libraries given as source projects: `ladderc run Example.plcproj --lib
//! ../Struckig/Struckig.plcproj`. A TwinCAT project names its libraries
//! (`<PlaceholderReference Include="Struckig">` with `<DefaultResolution>Struckig, * (...)` and
//! `<Namespace>`, or `<LibraryReference Include="Struckig, 1.0 (...)">`); TwinCAT takes them from
//! its installed library repository, which ladderc does not have. Each `--lib` names the library's
//! own project (a `.plcproj`, or a folder holding one): its object files (each `Include` matched
//! regardless of case, by the rule of the application's project) are read with the
//! application's, its POUs, types and global lists become available under the namespace the
//! application's reference gives (`Struckig.Otg`), and unqualified too. The library's own
//! references are resolved the same way among the `--lib` projects.
//!
//! Input: the references of the application's projects and the `--lib` paths. Output: the
//! library object files to read (without their task files: a library runs nothing by itself),
//! the namespaces whose qualifier is dropped, and diagnostics: E1077 for a `--lib` no input
//! project references (without a project, `ladderc run main.st --lib L.plcproj`, its names are
//! available under its default namespace), E1078 for a `--lib` that is no TwinCAT project, E9001
//! for one that cannot be read. Invariants: never panics; each library project is read once,
//! whatever the number of references to it; a library's names join the application's (one
//! namespace in the compiled C: a library POU and an application POU of one name are a
//! duplicate, as with two files).

use crate::pipeline::Session;
use diagnostics::{code, Diagnostic, Diagnostics};
use std::path::{Path, PathBuf};

/// One library reference of a `.plcproj`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Reference {
    /// The library's names that may resolve it, upper case: the placeholder (`Include`) and the
    /// library title of its resolution (`Struckig, * (Stefan Besler)` -> `STRUCKIG`).
    pub names: Vec<String>,
    /// The namespace the referencing project uses (`<Namespace>`, else the library's name).
    pub namespace: String,
    /// `<QualifiedOnly>true</QualifiedOnly>`: TwinCAT takes the library's names only as
    /// `Namespace.Name`. Read, not enforced: ladderc accepts them unqualified too (README).
    pub qualified_only: bool,
}

/// The library references of a `.plcproj`'s text (`PlaceholderReference`, `LibraryReference`).
pub fn references(text: &str) -> Vec<Reference> {
    let arena = ladder_compiler::xml::Arena::new();
    let (root, _) = ladder_compiler::xml::parse(text, &arena);
    let Some(root) = root else {
        return Vec::new();
    };
    // `Include="[Resi4MPM]"`, `<DefaultResolution>[Resi4MPM], * (...)`: a placeholder's name is
    // written in brackets by some TwinCAT versions
    let bare = |s: &str| {
        let s = s.split(',').next().unwrap_or("").trim();
        s.strip_prefix('[')
            .and_then(|t| t.strip_suffix(']'))
            .unwrap_or(s)
            .trim()
            .to_string()
    };
    let title = |s: &str| bare(s).to_ascii_uppercase();
    let mut out = Vec::new();
    for el in root.walk() {
        if !matches!(el.name(), "PlaceholderReference" | "LibraryReference") {
            continue;
        }
        let Some(include) = el.attr("Include") else {
            continue;
        };
        let child = |name: &str| {
            el.walk()
                .find(|c| c.name() == name)
                .map(|c| c.text().trim().to_string())
        };
        let mut names = vec![title(include)];
        if let Some(r) = child("DefaultResolution") {
            let t = title(&r);
            if !names.contains(&t) {
                names.push(t);
            }
        }
        names.retain(|n| !n.is_empty());
        if names.is_empty() {
            continue;
        }
        let namespace = child("Namespace")
            .filter(|n| !n.is_empty())
            .unwrap_or_else(|| bare(include));
        let qualified_only = child("QualifiedOnly").is_some_and(|q| q.eq_ignore_ascii_case("true"));
        out.push(Reference {
            names,
            namespace,
            qualified_only,
        });
    }
    out
}

/// A library project given with `--lib`.
struct LibraryProject {
    /// Its `.plcproj`.
    project: PathBuf,
    /// Its names, upper case: `<Title>`, `<Name>`, the file's stem.
    names: Vec<String>,
    /// `<Title>`, else `<Name>`, else the file's stem, as written.
    title: String,
    /// `<DefaultNamespace>`, else its title.
    default_namespace: String,
    /// Its object files, without task files.
    files: Vec<PathBuf>,
    /// Its own library references.
    references: Vec<Reference>,
}

/// What the `--lib` projects give the compilation.
#[derive(Debug, Default)]
pub struct Resolved {
    /// The library object files to read, library by library in resolution order.
    pub files: Vec<PathBuf>,
    /// The namespaces whose qualifier is dropped (`Struckig.Otg` -> `Otg`), upper case.
    pub namespaces: Vec<String>,
    /// The library files (to tell the application's files from the libraries').
    pub library_files: std::collections::HashSet<PathBuf>,
}

/// The library projects `libs` that the application's `references` (and the libraries' own) name.
/// `has_project`: the inputs hold a TwinCAT project (else no `--lib` is expected to be referenced).
pub fn resolve(
    session: &Session,
    references: &[Reference],
    libs: &[PathBuf],
    has_project: bool,
    diags: &mut Diagnostics,
) -> Resolved {
    let mut projects = Vec::new();
    for lib in libs {
        if let Some(p) = read_library(session, lib, diags) {
            projects.push(p);
        }
    }
    let mut out = Resolved::default();
    let mut used = vec![false; projects.len()];
    let mut pending: Vec<Reference> = references.to_vec();
    let mut namespaces = std::collections::HashSet::new();
    while let Some(r) = pending.pop() {
        let Some(k) = projects
            .iter()
            .position(|p| p.names.iter().any(|n| r.names.contains(n)))
        else {
            // a library ladderc provides, or one not given: its qualifier is handled (or
            // reported, E1032) where it is used
            continue;
        };
        if namespaces.insert(r.namespace.to_ascii_uppercase()) {
            out.namespaces.push(r.namespace.to_ascii_uppercase());
        }
        if !used[k] {
            used[k] = true;
            pending.extend(projects[k].references.iter().cloned());
        }
    }
    for (k, p) in projects.iter().enumerate() {
        if !used[k] {
            if has_project {
                diags.push(
                    Diagnostic::error(
                        code::E1077,
                        format!(
                            "--lib {}: no input project references the library `{}`",
                            p.project.display(),
                            p.title
                        ),
                    )
                    .with_hint(format!(
                        "the projects reference {}; add the library to the project's references (TwinCAT: References, Add library), or give with --lib the library the project references",
                        if references.is_empty() {
                            "no library".to_string()
                        } else {
                            references
                                .iter()
                                .map(|r| r.namespace.clone())
                                .collect::<Vec<_>>()
                                .join(", ")
                        }
                    )),
                );
                continue;
            }
            let ns = p.default_namespace.to_ascii_uppercase();
            if namespaces.insert(ns.clone()) {
                out.namespaces.push(ns);
            }
        }
        for f in &p.files {
            if out.library_files.insert(f.clone()) {
                out.files.push(f.clone());
            }
        }
    }
    out
}

/// Reads the library project at `lib` (a `.plcproj`, or a folder holding one).
fn read_library(session: &Session, lib: &Path, diags: &mut Diagnostics) -> Option<LibraryProject> {
    let project = if crate::twincat::has_extension(lib, "plcproj") {
        lib.to_path_buf()
    } else if session.disk && lib.is_dir() {
        let mut found = Vec::new();
        crate::twincat::find_projects(lib, 0, &mut found);
        found.sort();
        if found.len() != 1 {
            diags.push(
                Diagnostic::error(
                    code::E1078,
                    format!(
                        "--lib {}: the folder holds {} TwinCAT PLC projects, not one",
                        lib.display(),
                        found.len()
                    ),
                )
                .with_hint("give the library's .plcproj file"),
            );
            return None;
        }
        found.pop()?
    } else if session.file_exists(lib) || !session.disk {
        diags.push(
            Diagnostic::error(
                code::E1078,
                format!("--lib {} is no TwinCAT PLC project", lib.display()),
            )
            .with_hint(
                "give the library's .plcproj file (or its folder); other source files are inputs",
            ),
        );
        return None;
    } else {
        lib.to_path_buf()
    };
    let text = match session.read_file(&project) {
        Ok(t) => t,
        Err(e) => {
            diags.push(
                Diagnostic::error(
                    code::E9001,
                    format!("cannot read {}: {e}", project.display()),
                )
                .with_hint("check the path given with --lib and its permissions"),
            );
            return None;
        }
    };
    let Identity {
        names,
        title,
        default_namespace,
    } = identity(&project, &text);
    // an Include is matched as the application's are: regardless of case (Windows file names)
    let files = crate::twincat::listed_files(&project, &text)
        .into_iter()
        .map(|(f, _)| crate::twincat::listed_file_on_disk(session, &f).unwrap_or(f))
        .filter(|f| !crate::twincat::has_extension(f, "tctto"))
        .collect();
    Some(LibraryProject {
        references: references(&text),
        project,
        names,
        title,
        default_namespace,
        files,
    })
}

/// A TwinCAT project's names, as a reference may name it.
pub struct Identity {
    /// Upper case: `<Title>`, `<Name>`, the file's stem.
    pub names: Vec<String>,
    /// `<Title>`, else `<Name>`, else the file's stem, as written.
    pub title: String,
    /// `<DefaultNamespace>`, else its title.
    pub default_namespace: String,
}

/// The names of the TwinCAT project `project` whose text is `text`.
pub fn identity(project: &Path, text: &str) -> Identity {
    let arena = ladder_compiler::xml::Arena::new();
    let (root, _) = ladder_compiler::xml::parse(text, &arena);
    let property = |name: &str| {
        root.as_ref().and_then(|r| {
            r.walk()
                .find(|e| e.name() == name)
                .map(|e| e.text().trim().to_string())
                .filter(|t| !t.is_empty())
        })
    };
    let stem = project
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("")
        .to_string();
    let title = property("Title")
        .or_else(|| property("Name"))
        .unwrap_or(stem.clone());
    let mut names = Vec::new();
    for n in [Some(title.clone()), property("Name"), Some(stem)]
        .into_iter()
        .flatten()
    {
        let n = n.to_ascii_uppercase();
        if !n.is_empty() && !names.contains(&n) {
            names.push(n);
        }
    }
    let default_namespace = property("DefaultNamespace").unwrap_or(title.clone());
    Identity {
        names,
        title,
        default_namespace,
    }
}

/// The namespaces of `references` that name one of the input projects (`inputs`: each one's
/// [`Identity::names`]): a library given as an input project beside the application that
/// references it (`ladderc check App.plcproj Lib.plcproj`) is read with the application like any
/// input, and its qualifier (`Lib.T`) is dropped as a `--lib` library's is (before round 32: E1032
/// "give its source project with --lib, or add its POUs and types to the project" although they
/// were added), upper case.
pub fn input_namespaces(references: &[Reference], inputs: &[Vec<String>]) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for r in references {
        let ns = r.namespace.to_ascii_uppercase();
        if inputs
            .iter()
            .any(|names| names.iter().any(|n| r.names.contains(n)))
            && !out.contains(&ns)
        {
            out.push(ns);
        }
    }
    out
}

/// The library files `lib_files` without the programs the application's files `app_files` shadow:
/// a library's object file that is one PROGRAM (TwinCAT: one POU per file) named like a POU of the
/// application. TwinCAT keeps a library's POUs in the library's namespace, where the application's
/// own name wins (Beckhoff Infosys, "Library namespace"; CODESYS's shadowing rules search the
/// application before its libraries), and a library runs none of its programs by itself: the
/// `MAIN` that every library made from TwinCAT's "Standard PLC project" template keeps is no
/// duplicate of the application's. `read` gives a file's text.
pub fn unshadowed(
    lib_files: &[PathBuf],
    app_files: &[PathBuf],
    read: impl Fn(&Path) -> Option<String>,
) -> Vec<PathBuf> {
    if lib_files.is_empty() {
        return Vec::new();
    }
    let mut app = std::collections::HashSet::new();
    for f in app_files {
        if let Some(text) = read(f) {
            app.extend(pou_names(&text));
        }
    }
    lib_files
        .iter()
        .filter(|f| {
            let Some(text) = read(f) else {
                return true;
            };
            let programs = il_frontend::st::qualifiers::program_names(&text);
            !(programs.len() == 1 && pou_names(&text).len() == 1 && app.contains(&programs[0]))
        })
        .cloned()
        .collect()
}

/// The names after `PROGRAM`, `FUNCTION_BLOCK`, `FUNCTION`, `INTERFACE` and `TYPE` in `text`, upper
/// case (a word's first letters: enough to tell which POUs and types a file declares).
fn pou_names(text: &str) -> Vec<String> {
    let b = text.as_bytes();
    let word = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if !word(b[i]) || (i > 0 && word(b[i - 1])) {
            i += 1;
            continue;
        }
        let mut j = i;
        while j < b.len() && word(b[j]) {
            j += 1;
        }
        let w = text[i..j].to_ascii_uppercase();
        if ["PROGRAM", "FUNCTION_BLOCK", "FUNCTION", "INTERFACE", "TYPE"].contains(&w.as_str())
            && b.get(j).is_some_and(u8::is_ascii_whitespace)
        {
            let mut k = j;
            while b.get(k).is_some_and(u8::is_ascii_whitespace) {
                k += 1;
            }
            // modifiers (`FUNCTION_BLOCK PUBLIC FB_X`) are skipped
            loop {
                let s = k;
                while k < b.len() && word(b[k]) {
                    k += 1;
                }
                let name = text[s..k].to_ascii_uppercase();
                let modifier = ["PUBLIC", "INTERNAL", "FINAL", "ABSTRACT"].contains(&name.as_str());
                if modifier {
                    while b.get(k).is_some_and(u8::is_ascii_whitespace) {
                        k += 1;
                    }
                    continue;
                }
                if !name.is_empty() {
                    out.push(name);
                }
                break;
            }
            i = k.max(j);
        } else {
            i = j;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn placeholder_and_library_references() {
        let text = r#"<Project><ItemGroup>
            <PlaceholderReference Include="Motion">
              <DefaultResolution>MotionLib, * (Acme)</DefaultResolution>
              <Namespace>Mo</Namespace>
              <QualifiedOnly>true</QualifiedOnly>
            </PlaceholderReference>
            <LibraryReference Include="Util2, 1.0.0.0 (Acme)"><Namespace>Util2</Namespace></LibraryReference>
          </ItemGroup></Project>"#;
        let r = references(text);
        assert_eq!(r.len(), 2);
        assert_eq!(r[0].names, vec!["MOTION", "MOTIONLIB"]);
        assert_eq!(r[0].namespace, "Mo");
        assert!(r[0].qualified_only);
        assert_eq!(r[1].names, vec!["UTIL2"]);
        assert!(!r[1].qualified_only);
    }
}
