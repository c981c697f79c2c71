//! The compilation pipeline behind `check`, `build` and `run`, and behind the typed API of
//! [`crate::project`].
//!
//! Input: source paths (`.xml` PLCopen projects, `.il` IL, `.st` Structured Text, others by content;
//! `-` standard input) and [`Options`]; every file is taken from [`Session::overlay`] first, and from the
//! file system (and standard input) only when [`Session::disk`] allows it. Output: the source map, the
//! diagnostics, and (when there are no errors) the lowered IL units and the C project.
//! Stages: read (a file that is not text is one E1093, [`crate::binary_input`]; bytes decoded by [`crate::encoding`]: UTF-8, UTF-16, the XML declaration's encoding, else
//! Windows-1252 with note W0305) -> parse (IL, ST) or read + lower ladder (XML) ([`Session::parse`]) -> semantic checks
//! against the PLCopen block prelude and the axes ([`Session::check`]) -> parameter passing (block calls by
//! the chosen strategy) ([`Session::lower_checked`]) -> semantic model of the lowered program -> C
//! ([`Session::generate`]). Invariants: a stage runs only when the ones before it reported no error; no
//! process is started unless [`Options::compile_templates`] asks for the templates' C check.

use crate::axes::AxisConfig;
use diagnostics::{code, Diagnostic, Diagnostics, SourceMap};
use il_frontend::ast::CompilationUnit;
use param_passing::library::Library;
use param_passing::lower::{self, Strategy, TmWindow};
use std::path::{Path, PathBuf};

/// What a project is compiled with, besides its sources. Paths are looked up in [`Session::overlay`]
/// first (so that every one of these files may be given in memory).
#[derive(Debug, Clone)]
pub struct Options {
    /// The target profile (memory model, JSON; `--profile`); `None`: [`c_backend::TargetProfile::default`].
    pub profile: Option<PathBuf>,
    /// How PLCopen block calls are lowered (`--strategy`; paper A's two methods, or per block).
    pub strategy: Strategy,
    /// A folder of user parameter templates (`*.xml`, `--templates`); they replace built-ins of the same
    /// block name.
    pub templates: Option<PathBuf>,
    /// The axis configuration; `None`: `<first input stem>.axes.json` beside the first input, if present.
    pub axes: Option<PathBuf>,
    /// The scan cycle `run` uses (`--cycle-ms`), when given; checked against the configuration's.
    pub cycle_ms: Option<f64>,
    /// The source language of every input (`--lang`); `None`: by extension, else from the content.
    pub lang: Option<Lang>,
    /// Whether each user template's function is compiled alone with the system C compiler (`$CC`) when it
    /// is loaded (the command line does; it starts a process). Without it the templates still get every
    /// other check (schema, body tokens and names).
    pub compile_templates: bool,
    /// User libraries given as source projects (`--lib`): TwinCAT `.plcproj` files (or folders
    /// holding one) whose POUs, types and global lists the inputs use (`Struckig.Otg`).
    pub libraries: Vec<PathBuf>,
}

impl Default for Options {
    /// The command line's defaults: no profile, templates, axes file, cycle or language given; the
    /// parameter-template method; no C compiler started.
    fn default() -> Self {
        Options {
            profile: None,
            strategy: Strategy::Template,
            templates: None,
            axes: None,
            cycle_ms: None,
            lang: None,
            compile_templates: false,
            libraries: Vec::new(),
        }
    }
}

pub use il_frontend::st::file::Lang;

/// The language of an input: `forced`, else by extension (`.il`, `.st`, `.xml`), else from the
/// content. The flag says whether it was detected from the content.
pub fn input_lang(path: &Path, text: &str, forced: Option<Lang>) -> (Lang, bool) {
    if let Some(l) = forced {
        return (l, false);
    }
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("xml") => (Lang::Xml, false),
        Some("il") => (Lang::Il, false),
        Some("st") => (Lang::St, false),
        Some(e) if crate::twincat::OBJECT_EXTENSIONS.contains(&e) => (Lang::Xml, false),
        _ => (il_frontend::st::file::detect(text), true),
    }
}

/// The name diagnostics give standard input (`-` as an input).
pub const STDIN_NAME: &str = "<stdin>";

/// Whether an input path means standard input.
pub fn is_stdin(p: &Path) -> bool {
    p.as_os_str() == "-"
}

/// The motion library's C header, copied into generated projects that use motion blocks.
pub const MOTION_HEADER: &str = include_str!("../../motion-lib/include/motion_lib.h");

/// The scan cycle when neither `--cycle-ms` nor the axis configuration gives one.
pub const DEFAULT_CYCLE_MS: f64 = 10.0;

/// One compilation: the sources read so far, the diagnostics reported so far, and where files come from.
pub struct Session {
    /// Every text read (sources, axes file, templates, generated preludes), by file id.
    pub map: SourceMap,
    /// The diagnostics of every stage run so far, in the order they were reported.
    pub diags: Diagnostics,
    /// File texts by path (sources, the axes file, the profile, templates under [`Options::templates`];
    /// an editor's unsaved buffers): they are read instead of the file system. `-` in it stands for
    /// standard input.
    pub overlay: std::collections::HashMap<PathBuf, String>,
    /// Whether a file that is not in [`Session::overlay`] is read from the file system (and `-` from
    /// standard input). `false`: such a file is an E9001 error ("not given in memory").
    pub disk: bool,
    /// Whether the semantic models record what every name used in a body refers to
    /// ([`il_frontend::sema::Model::names`], for tools; the default). `false`: only what the C
    /// generation reads ([`il_frontend::sema::analyze_for_code`]).
    pub name_table: bool,
    /// The base scan cycle the tasks of the TwinCAT project read last give (ms; the greatest common
    /// divisor of their cycle times), used when neither `--cycle-ms` nor the axes file gives one.
    pub task_cycle_ms: Option<f64>,
    /// The user libraries' source projects (`--lib`, [`Options::libraries`]): read with the inputs,
    /// see [`crate::user_libraries`].
    pub libraries: Vec<PathBuf>,
    /// The files read so far that are TwinCAT 3 objects (`.TcPOU` ...), known to the semantic
    /// analysis ([`il_frontend::sema::TwinCatFiles`]).
    pub twincat_files: Vec<diagnostics::FileId>,
    /// The files read so far that were written for CODESYS or TwinCAT (TwinCAT 3 objects, CODESYS
    /// V2.3 exports and objects, CODESYS's PLCopen XML), known to the semantic analysis
    /// ([`il_frontend::sema::CodesysFiles`]).
    pub codesys_files: Vec<diagnostics::FileId>,
    /// B&R library data types not compiled as they are made of stub blocks
    /// ([`crate::split_blocks::drop_stub_types`]): their uses' E1003 name the stub.
    stub_types: Vec<crate::split_blocks::StubType>,
    /// The actions and METHODs read, and which were linked ([`il_frontend::actions::link`]): those
    /// nothing calls are checked on their own (`Session::check_uncalled`).
    pub linked_actions: il_frontend::actions::Linked,
    /// How many diagnostics reading the files reported ([`Session::parse`]): those after them are
    /// the checks' ([`Session::drop_behind_recovered_errors`]).
    loaded_diags: usize,
}

/// What [`Session::parse`] produced: the user's units and what they are compiled with.
pub struct Parsed {
    /// The user's units, as parsed, in input order.
    pub units: Vec<CompilationUnit>,
    /// The built-in parameter templates and the user's.
    pub library: Library,
    /// The target profile.
    pub profile: c_backend::TargetProfile,
}

/// What [`Session::check`] produced: a program without errors, not yet lowered.
pub struct Checked {
    /// The user's units when they use PLCopen blocks (they are then also in `checked`); empty otherwise.
    user: Vec<CompilationUnit>,
    /// The checked units: the block interfaces and the axes (when blocks are used), then the user's.
    checked: Vec<CompilationUnit>,
    /// The semantic model of `checked`.
    pub model: il_frontend::sema::Model,
    /// The parameter templates.
    pub library: Library,
    /// The target profile.
    pub profile: c_backend::TargetProfile,
    /// Whether the program uses PLCopen blocks.
    pub uses_blocks: bool,
    /// The axis configuration (the default, empty one when there is no file).
    pub axes: AxisConfig,
    /// The scan cycle.
    pub cycle_ms: f64,
}

impl Checked {
    /// The user's units, as parsed.
    pub fn units(&self) -> &[CompilationUnit] {
        if self.uses_blocks {
            &self.user
        } else {
            &self.checked
        }
    }
}

/// What a successful front half produced.
pub struct Lowered {
    /// The user's units as parsed, when block lowering changed them (otherwise they are [`Lowered::units`]:
    /// one copy of the program is kept, whatever its size).
    source_copy: Option<Vec<CompilationUnit>>,
    /// Units to compile: the post-lowering prelude (when blocks are used), then the user's units.
    pub all_units: Vec<CompilationUnit>,
    /// Where the user's units start in `all_units`.
    user_start: usize,
    /// What parameter passing produced: per block type its method and figures, the synthesised
    /// functions, the static-library layouts.
    pub lowering: lower::Lowered,
    /// The parameter templates (built-in and the user's).
    pub library: Library,
    /// The target profile.
    pub profile: c_backend::TargetProfile,
    /// Whether the program uses PLCopen blocks (then the motion runtime is linked).
    pub uses_blocks: bool,
    /// The axis configuration (the default, empty one when there is no file).
    pub axes: AxisConfig,
    /// The scan cycle = the motion engine's cycle.
    pub cycle_ms: f64,
    /// The semantic model of `all_units`: after [`Session::lower`], when nothing was lowered (the
    /// checked program is the compiled one, so it is analysed once); after [`Session::compile`], always
    /// (the model the C was generated from).
    pub model: Option<il_frontend::sema::Model>,
}

impl Lowered {
    /// The user's units after block lowering (without the prelude): what `build --emit il` prints.
    pub fn units(&self) -> &[CompilationUnit] {
        &self.all_units[self.user_start..]
    }
    /// The user's units as parsed, before block lowering.
    pub fn source_units(&self) -> &[CompilationUnit] {
        self.source_copy.as_deref().unwrap_or(self.units())
    }
}

impl Default for Session {
    fn default() -> Self {
        Self::new()
    }
}

impl Session {
    /// An empty session: no sources, no diagnostics.
    pub fn new() -> Self {
        Session {
            map: SourceMap::new(),
            diags: Diagnostics::new(),
            overlay: std::collections::HashMap::new(),
            disk: true,
            name_table: true,
            task_cycle_ms: None,
            libraries: Vec::new(),
            twincat_files: Vec::new(),
            codesys_files: Vec::new(),
            stub_types: Vec::new(),
            linked_actions: Default::default(),
            loaded_diags: 0,
        }
    }

    /// A session that reads nothing but its [`Session::overlay`]: no file system, no standard input.
    pub fn in_memory() -> Self {
        Session {
            disk: false,
            ..Session::new()
        }
    }

    /// The text of `path`: from the overlay, else from the file system when [`Session::disk`] allows it.
    pub fn read_file(&self, path: &Path) -> std::io::Result<String> {
        if let Some(t) = self.overlay.get(path) {
            return Ok(t.clone());
        }
        if self.disk {
            return std::fs::read_to_string(path);
        }
        Err(not_in_memory())
    }

    /// Adds a decoded file to the source map, with note W0305 at its first byte that is not UTF-8
    /// when it was read as Windows-1252 ([`crate::encoding::Decoded::fallback_at`]).
    pub fn add_decoded(
        &mut self,
        shown: String,
        decoded: crate::encoding::Decoded,
    ) -> diagnostics::FileId {
        let fallback_at = decoded.fallback_at;
        let file = if decoded.encoding == diagnostics::FileEncoding::Utf8 && decoded.byte_base == 0
        {
            self.map.add_file_owned(shown, decoded.text)
        } else {
            self.map
                .add_decoded(shown, decoded.text, decoded.encoding, decoded.byte_base)
        };
        if let Some(at) = fallback_at {
            self.diags.push(
                Diagnostic::new(
                    code::W0305,
                    diagnostics::Severity::Note,
                    "not valid UTF-8 from here on: the file is read as Windows-1252 \
                     (ISO-8859-1 with the CODESYS, TwinCAT and TIA Portal characters)",
                )
                .at(diagnostics::Span::new(file, at, at))
                .with_hint("save the file as UTF-8 to silence this note, or check that the file is not damaged"),
            );
        }
        file
    }

    /// Reads `path` (from the overlay, or from disk when [`Session::disk`]) and decodes it as an
    /// input file is decoded (`crate::encoding`: a declared or Windows-1252 encoding, W0305 at the
    /// first byte that is not UTF-8), into the source map; `None` (E9001 reported) when it cannot.
    pub fn read_decoded(&mut self, path: &Path) -> Option<diagnostics::FileId> {
        let shown = path.display().to_string();
        let decoded = if let Some(t) = self.overlay.get(path) {
            Ok(crate::encoding::Decoded {
                text: t.clone(),
                encoding: diagnostics::FileEncoding::Utf8,
                byte_base: 0,
                fallback_at: None,
            })
        } else if self.disk {
            match std::fs::read(path) {
                Ok(bytes) => crate::encoding::decode(bytes).map_err(|e| {
                    Diagnostic::error(code::E9001, format!("{shown} {}", e.message))
                        .with_hint(e.hint)
                }),
                Err(e) => Err(
                    Diagnostic::error(code::E9001, format!("cannot read {shown}: {e}"))
                        .with_hint("check the path and its permissions"),
                ),
            }
        } else {
            Err(Diagnostic::error(
                code::E9001,
                format!("cannot read {shown}: {}", not_in_memory()),
            ))
        };
        match decoded {
            Ok(d) => Some(self.add_decoded(shown, d)),
            Err(d) => {
                self.diags.push(d);
                None
            }
        }
    }

    /// Whether `path` is in the overlay, or (when [`Session::disk`]) a file on disk.
    pub fn file_exists(&self, path: &Path) -> bool {
        self.overlay.contains_key(path) || (self.disk && path.is_file())
    }

    /// Reads and parses every input (IL, ST or PLCopen XML; `-` is standard input, read once).
    pub fn load(&mut self, paths: &[PathBuf]) -> Vec<CompilationUnit> {
        self.load_as(paths, None)
    }

    /// [`Session::load`] with every input read in `lang` when it is given.
    pub fn load_as(&mut self, paths: &[PathBuf], lang: Option<Lang>) -> Vec<CompilationUnit> {
        // the spellings of methods' variables in messages: this compilation's only (a language
        // server compiles again and again on one thread)
        il_frontend::actions::forget_spellings();
        // the ST call statements that drop a function's result: this compilation's only
        il_frontend::st::dropped_results::forget();
        let mut units = Vec::new();
        let mut pending = Vec::new();
        let mut var_config = Vec::new();
        let mut stdin_read = false;
        // the integer constants each text file's global lists offer, and the text files whose bounds
        // named a constant they do not declare (index in `units`, file, implicit name, language,
        // diagnostics)
        let mut offered = Vec::new();
        let mut waiting = Vec::new();
        // TwinCAT 3: a .plcproj (or a folder holding one) stands for the object files it lists; the
        // units read from object files, their global lists' names, their tasks
        let mut expand_diags = Diagnostics::new();
        let mut defines = Vec::new();
        let mut twincat_failed: Vec<String> = Vec::new();
        let mut references = None;
        let mut projects_read = crate::twincat::ProjectsRead::default();
        // OpenPLC Editor v4: a folder holding project.json stands for its POU files, and its
        // configuration (tasks, instances, globals) is read as one more ST text below
        let mut v4_configs = Vec::new();
        let mut failed_json: Vec<PathBuf> = Vec::new();
        let paths = crate::openplc_v4::expand(self, paths, &mut v4_configs, &mut expand_diags);
        // SIMATIC AX: a project folder stands for its src/ files; its apax.yml's preprocessor
        // symbols (and those of the apax.yml above a .st input) are defines of `{::ifdef}`
        let paths = crate::apax::expand(self, &paths, &mut defines, &mut expand_diags);
        let paths = crate::twincat::expand(
            self,
            &paths,
            &mut defines,
            &mut twincat_failed,
            &mut references,
            &mut projects_read,
            &mut expand_diags,
        );
        // user libraries given as source projects (`--lib`): their object files first, their
        // namespaces' qualifiers dropped while this function reads
        let libraries = crate::user_libraries::resolve(
            self,
            references.as_deref().unwrap_or_default(),
            &self.libraries,
            references.is_some(),
            &mut expand_diags,
        );
        // a library's PROGRAM named like a POU of the application (the `MAIN` every library made
        // from TwinCAT's project template keeps) is shadowed by it: not read
        let read = |p: &Path| self.read_file(p).ok();
        let lib_files =
            crate::user_libraries::unshadowed(&libraries.files, &paths, |p: &Path| read(p));
        let paths: Vec<PathBuf> = lib_files.into_iter().chain(paths).collect();
        // and the namespaces of the libraries given as input projects beside the application
        let mut namespaces = libraries.namespaces;
        for ns in crate::user_libraries::input_namespaces(
            references.as_deref().unwrap_or_default(),
            &projects_read.names,
        ) {
            if !namespaces.contains(&ns) {
                namespaces.push(ns);
            }
        }
        let _libraries = il_frontend::st::qualifiers::UserLibraries::set(namespaces);
        // the projects' compiler defines, known to the conditional pragmas of every file read
        // below (and read again), until this function returns
        let _defines = il_frontend::st::ProjectDefines::set(defines);
        self.diags.extend(expand_diags);
        let mut twincat_units: Vec<bool> = Vec::new();
        // the files that declare blocks with generic constants (`generic_blocks`)
        let mut generic_texts: Vec<crate::generic_blocks::GenericText> = Vec::new();
        let mut twincat_lists: Vec<(usize, String)> = Vec::new();
        // text files (`.st`, `.txt`) that may be a CODESYS global variable list object
        let mut text_lists: Vec<(usize, String)> = Vec::new();
        let mut twincat_tasks = Vec::new();
        // the programs of every file, known before any is parsed: `PRG.M(x)` in one file calls a
        // method of a program of another (TwinCAT: one POU per file), no library's function
        let mut programs = std::collections::HashSet::new();
        // and the bases their blocks extend: `_abs.M()` names a variable of a base of a base
        let mut bases = std::collections::HashMap::new();
        // and their global variables: a POU's initial value reading one is computed at run time
        let mut globals = std::collections::HashSet::new();
        // and their namespaces: `Plant.Util.Twice(21)` names another file's `NAMESPACE Plant.Util`
        let mut namespaces = std::collections::HashSet::new();
        for p in paths.iter().filter(|p| !is_stdin(p)) {
            let text = match self.overlay.get(p) {
                Some(t) => Some(t.clone()),
                None if self.disk && p.is_file() => std::fs::read(p)
                    .ok()
                    .map(|b| String::from_utf8_lossy(&b).into_owned()),
                None => None,
            };
            if let Some(t) = text {
                programs.extend(il_frontend::st::qualifiers::program_names(&t));
                bases.extend(il_frontend::st::qualifiers::extends_pairs(&t));
                globals.extend(il_frontend::st::global_variable_names(&t));
                namespaces.extend(il_frontend::st::qualifiers::namespace_names(&t));
            }
        }
        let namespaces_before = il_frontend::st::qualifiers::set_project_namespaces(namespaces);
        let programs_before = il_frontend::st::qualifiers::set_project_programs(programs);
        let bases_before = il_frontend::st::qualifiers::set_project_bases(bases);
        let globals_before = il_frontend::st::set_project_globals(globals);
        // several PLCopen XML files (CODESYS exports one object per file), or XML beside text
        // inputs (a TwinCAT project's `.TcDUT` types of an imported PLCopen POU): compiled once
        // all are read, each knowing the POUs and data types of the others. Every input read as
        // PLCopen XML counts, whatever its name: `.xml`, a Beremiz folder, or a file recognised
        // from its content (W0302: RuSTy's `.cfc` charts, a `.plcopen` export)
        let defer_xml = paths.len() > 1;
        let mut deferred_xml: Vec<(usize, diagnostics::FileId, Option<PathBuf>)> = Vec::new();
        for p in &paths {
            // a Beremiz project folder (or its plc.xml): plc.xml, then its confnodes' globals
            let (resolved, beremiz_dir) = crate::beremiz::resolve(self, p);
            let p = &resolved;
            let stdin = is_stdin(p);
            let shown = if stdin {
                STDIN_NAME.to_string()
            } else {
                p.display().to_string()
            };
            // the overlay holds text (an editor's buffer): it is read as it is
            let bytes = if let Some(t) = self.overlay.get(p) {
                Ok(Err(t.clone()))
            } else if stdin && !self.disk {
                Err(not_in_memory())
            } else if stdin {
                if stdin_read {
                    self.diags.push(
                        Diagnostic::error(code::E9001, "`-` (standard input) is given twice")
                            .with_hint("standard input can be read once: give `-` once"),
                    );
                    continue;
                }
                stdin_read = true;
                let mut b = Vec::new();
                std::io::Read::read_to_end(&mut std::io::stdin(), &mut b).map(|_| Ok(b))
            } else if self.disk {
                std::fs::read(p).map(Ok)
            } else {
                Err(not_in_memory())
            };
            // a file that is not text (a binary CODESYS V3 `.project`, an archive): one E1093 at its start
            if let Ok(Ok(b)) = &bytes {
                if let Some(d) = crate::binary_input::not_text(p, b) {
                    let file = self.map.add_file_owned(shown, String::new());
                    self.diags.push(d.at(diagnostics::Span::new(file, 0, 0)));
                    continue;
                }
            }
            // Ok(Ok(bytes)) from a file or standard input, Ok(Err(text)) from the overlay
            let decoded = match bytes {
                Ok(Err(text)) => Ok(crate::encoding::Decoded {
                    text,
                    encoding: diagnostics::FileEncoding::Utf8,
                    byte_base: 0,
                    fallback_at: None,
                }),
                Ok(Ok(bytes)) => crate::encoding::decode(bytes),
                Err(_) if self.disk && p.is_dir() => {
                    // a folder that is no project ladderc reads (beremiz.rs, twincat.rs took those)
                    let v4 = p.join("project.json").is_file();
                    self.diags.push(
                        Diagnostic::error(
                            code::E9001,
                            format!(
                                "{shown} is a folder that holds no project ladderc reads (no plc.xml of Beremiz or OpenPLC, no TwinCAT .plcproj)"
                            ),
                        )
                        .with_hint(if v4 {
                            "an OpenPLC Editor v4 project (project.json): give its generated PLCopen XML (build/<target>/src/plc.xml) or its .st files"
                        } else {
                            "give the source files (.st, .il, .xml), or the folder of a Beremiz, OpenPLC or TwinCAT project"
                        }),
                    );
                    continue;
                }
                Err(e) => {
                    self.diags.push(
                        Diagnostic::error(code::E9001, format!("cannot read {shown}: {e}"))
                            .with_hint("check the path and its permissions"),
                    );
                    continue;
                }
            };
            let decoded = match decoded {
                Ok(d) => d,
                Err(e) => {
                    self.diags.push(
                        Diagnostic::error(code::E9001, format!("{shown} {}", e.message))
                            .with_hint(e.hint),
                    );
                    continue;
                }
            };
            // A UTF-8 byte-order mark is dropped: positions count from the first character after it
            // (JSON's byte offsets add it back: `SourceMap::add_file`).
            let text_after_bom = decoded
                .text
                .strip_prefix('\u{feff}')
                .unwrap_or(&decoded.text);
            // a TwinCAT-encrypted object (`TcEncryptedFile~` then cipher text): one error, unread
            if text_after_bom.starts_with("TcEncryptedFile") {
                let file = self.map.add_file_owned(shown, String::new());
                self.diags.push(
                    Diagnostic::error(
                        code::E1049,
                        "an encrypted TwinCAT file: ladderc cannot read it",
                    )
                    .at(diagnostics::Span::new(file, 0, 0))
                    .with_primary_label("`TcEncryptedFile~` and cipher text")
                    .with_hint("save the project without encryption in TwinCAT (or export its POUs as PLCopen XML) and give ladderc those files"),
                );
                continue;
            }
            let (file_lang, detected) = if stdin {
                (
                    lang.unwrap_or_else(|| il_frontend::st::file::detect(text_after_bom)),
                    lang.is_none(),
                )
            } else {
                input_lang(p, text_after_bom, lang)
            };
            let file = self.add_decoded(shown, decoded);
            // Borrowed from the source map (a field apart from the diagnostics): the text is held once.
            let src = &self.map.get(file).text;
            // an OpenPLC Editor v4 project.json with its POUs inline, read as ST; a `.json` input
            // (or a text that is a JSON object) is never read as ST otherwise
            let json_text = if p
                .extension()
                .is_some_and(|x| x.eq_ignore_ascii_case("json"))
                || (detected && crate::openplc_v4_json::is_json_object(src))
            {
                let shown = &self.map.get(file).name;
                match crate::openplc_v4_json::read(file, src, shown, &mut self.diags) {
                    Some(text) => Some(text),
                    None => {
                        failed_json.push(p.clone());
                        continue;
                    }
                }
            } else {
                None
            };
            let (file_lang, detected) = if json_text.is_some() {
                (Lang::St, false)
            } else {
                (file_lang, detected)
            };
            // a CODESYS V2.3 export (`.EXP`): its sections without code skipped (W1442), its task
            // configuration read as the project's tasks
            let v23_text = if detected && file_lang != Lang::Xml {
                crate::codesys_v23::read(file, src)
            } else {
                None
            };
            let (file_lang, v23_text) = match v23_text {
                Some(export) => {
                    self.diags.extend(export.notes);
                    twincat_tasks.extend(export.tasks.into_iter().map(|t| (file, t)));
                    // the PLC configuration's symbolic names: global variables at their
                    // addresses, a unit of their own (the file's code, if any, follows)
                    if let Some(block) = export.io_globals {
                        units.push(CompilationUnit {
                            items: vec![il_frontend::ast::LibraryElement::GlobalVars(block)],
                            ..CompilationUnit::default()
                        });
                    }
                    if crate::codesys_v23::no_code(&export.text) {
                        continue;
                    }
                    (
                        il_frontend::st::file::detect(&export.text),
                        Some(export.text),
                    )
                }
                None => (file_lang, None),
            };
            // (not for an OpenPLC Editor v4 graphical POU: its E1073 below says what it is, nor
            // for a CODESYS V2.3 export, `.EXP`: a documented input whose language is its own)
            let v23_export =
                v23_text.is_some() || p.extension().is_some_and(|x| x.eq_ignore_ascii_case("exp"));
            if v23_export {
                self.codesys_files.push(file);
            }
            // detected as IL, but no line is an instruction or a declaration (a register list
            // kept as `.txt`): one E1107, not an error a line (`no_program`)
            if detected && !v23_export && file_lang == Lang::Il {
                if let Some(d) = crate::no_program::check(file, src) {
                    self.diags.push(d);
                    continue;
                }
            }
            if detected && !v23_export && openplc_v4_json_body(src).is_none() {
                // an IEC 61131-10 XML file is no PLCopen XML: the note says what the E3002 after
                // it says (ladderc does not read that format)
                let (what, hint) = if file_lang == Lang::Xml && is_iec_61131_10(src) {
                    (
                        "detected from the content as IEC 61131-10 XML, which ladderc does not read"
                            .to_string(),
                        "give the POUs as ST, IL or PLCopen TC6 XML",
                    )
                } else {
                    (
                        format!("read as {} (detected from the content)", file_lang.name()),
                        "name the file .il, .st or .xml, or pass --lang il|st|xml, to choose",
                    )
                };
                self.diags.push(
                    Diagnostic::new(code::W0302, diagnostics::Severity::Note, what)
                        .at(diagnostics::Span::new(file, 0, 0))
                        .with_hint(hint),
                );
            }
            // a CODESYS V2.3 object file (`<pou>`, `<dut>`, `<gvl>` root): its texts as an ST file
            let v2_object = if file_lang == Lang::Xml {
                ladder_compiler::codesys_v2::object_source(file, src)
            } else {
                None
            };
            let v2_text = match v2_object {
                Some(Err(d)) => {
                    self.diags.push(*d);
                    continue;
                }
                Some(Ok(text)) => {
                    self.codesys_files.push(file);
                    Some(text)
                }
                None => None,
            };
            // a TwinCAT 3 object file (`<TcPlcObject>` root): its texts as an ST file, or a task
            let tc_object = if file_lang == Lang::Xml && v2_text.is_none() {
                ladder_compiler::twincat::object_source(file, src)
            } else {
                None
            };
            let tc_text = match tc_object {
                Some(Err(d)) => {
                    self.diags.push(*d);
                    // TwinCAT names the file after its object: a task calling it is not told again
                    if let Some(stem) = p.file_stem().and_then(|s| s.to_str()) {
                        twincat_failed.push(stem.to_string());
                    }
                    continue;
                }
                Some(Ok(ladder_compiler::twincat::TcObject::Task(task))) => {
                    twincat_tasks.push((file, task));
                    continue;
                }
                Some(Ok(ladder_compiler::twincat::TcObject::Source {
                    text,
                    list,
                    notes,
                    moved,
                })) => {
                    // a chart's condition taken from a transition object: shown in the object
                    self.diags.read_moved(file, moved);
                    self.diags.extend(notes);
                    if let Some(list) = list {
                        twincat_lists.push((units.len(), list));
                    }
                    twincat_units.resize(units.len(), false);
                    twincat_units.push(true);
                    self.twincat_files.push(file);
                    self.codesys_files.push(file);
                    Some(text)
                }
                None => None,
            };
            let (file_lang, src) = match (&v2_text, &tc_text) {
                (Some(text), _) | (None, Some(text)) => (Lang::St, text.as_str()),
                (None, None) => (
                    file_lang,
                    json_text
                        .as_deref()
                        .or(v23_text.as_deref())
                        .unwrap_or(src.as_str()),
                ),
            };
            if file_lang == Lang::Xml && is_codesys_xml(src) {
                self.codesys_files.push(file);
            }
            if file_lang == Lang::Xml && defer_xml {
                deferred_xml.push((units.len(), file, beremiz_dir.clone()));
                units.push(il_frontend::ast::CompilationUnit::default());
            } else if file_lang == Lang::Xml {
                let (mut unit, entries, bodies) =
                    ladder_compiler::compile_xml_with_var_config(file, src, &mut self.diags);
                pending.extend(bodies);
                if let Some(dir) = &beremiz_dir {
                    crate::beremiz::add_confnodes(self, dir, &mut unit);
                }
                units.push(unit);
                var_config.extend(entries);
            } else {
                let stem = if stdin {
                    None
                } else {
                    p.file_stem()
                        .and_then(|s| s.to_str())
                        .map(crate::text_lists::object_name)
                };
                let implicit = match stem {
                    Some(stem) if is_iec_identifier(stem) => stem,
                    _ => il_frontend::DEFAULT_IMPLICIT_PROGRAM,
                };
                // OpenPLC Editor v4's `.ld` POU: declarations, then the rungs as JSON, read as ST
                let ld_text = match openplc_v4_json_body(src)
                    .and_then(|at| crate::openplc_v4_ld::read(file, src, at))
                {
                    Some(Ok(text)) => Some(text),
                    Some(Err(d)) => {
                        self.diags.push(*d);
                        continue;
                    }
                    None => None,
                };
                let (file_lang, src) = match &ld_text {
                    Some(text) => (Lang::St, text.as_str()),
                    None => (file_lang, src),
                };
                if let Some(at) = openplc_v4_json_body(src) {
                    // OpenPLC Editor v4's `.fbd` POU: declarations, then the graphics as JSON
                    // (each of its lines would be an error of the text's language)
                    self.diags.push(
                        Diagnostic::error(
                            code::E1073,
                            "an OpenPLC Editor v4 graphical body (JSON after the declarations), which ladderc does not read",
                        )
                        .at(diagnostics::Span::new(file, at, at + 1))
                        .with_primary_label("the JSON body starts here")
                        .with_hint("give the PLCopen XML the editor generates for the project (build/<target>/src/plc.xml), or write the POU in ST"),
                    );
                    continue;
                }
                if file_lang == Lang::St && crate::generic_blocks::declares_generic_constants(src) {
                    generic_texts.push(crate::generic_blocks::GenericText {
                        file,
                        unit: units.len(),
                        text: src.to_string(),
                        implicit: implicit.to_string(),
                    });
                }
                let mut local = Diagnostics::new();
                let (unit, bodies, entries) =
                    il_frontend::st::file::parse_text(file, src, implicit, file_lang, &mut local);
                if v2_text.is_none() && tc_text.is_none() && stem == Some(implicit) {
                    // (the unit is pushed next, in either branch below)
                    text_lists.push((units.len(), implicit.to_string()));
                }
                if local
                    .iter()
                    .any(|d| d.code == code::E0022 || d.code == code::E1032)
                {
                    // a bound may name a constant of a file read later, a qualifier a list or
                    // variable of a file read later: parsed again below
                    offered.push(il_frontend::parser::global_integer_constants(&unit, &local));
                    waiting.push(WaitingFile {
                        unit: units.len(),
                        file,
                        implicit: implicit.to_string(),
                        lang: file_lang,
                        text: v2_text
                            .clone()
                            .or_else(|| tc_text.clone())
                            .or_else(|| v23_text.clone())
                            .or_else(|| ld_text.clone())
                            .or_else(|| json_text.clone()),
                        own: il_frontend::parser::integer_constants(&unit, &local, true),
                        diags: local,
                    });
                    units.push(unit);
                    continue;
                }
                offered.push(il_frontend::parser::global_integer_constants(&unit, &local));
                self.diags.extend(local);
                units.push(unit);
                pending.extend(bodies);
                var_config.extend(entries);
            }
        }
        let lists: Vec<(usize, String)> = text_lists
            .iter()
            .chain(twincat_lists.iter())
            .cloned()
            .collect();
        self.compile_xml_files(
            deferred_xml,
            &lists,
            &mut units,
            &mut var_config,
            &mut pending,
        );
        // the names every file declares, and the global lists named after their files (a text
        // file is a list when it holds nothing else, as `text_lists::name_text_lists` names it)
        let is_list = |k: &usize| {
            units.get(*k).is_some_and(|u| {
                !u.items.is_empty()
                    && u.items
                        .iter()
                        .all(|i| matches!(i, il_frontend::ast::LibraryElement::GlobalVars(_)))
            })
        };
        let names: std::collections::HashSet<String> = units
            .iter()
            .flat_map(il_frontend::st::offered_names)
            .chain(
                text_lists
                    .iter()
                    .filter(|(k, _)| is_list(k))
                    .chain(twincat_lists.iter())
                    .map(|(_, n)| n.to_ascii_uppercase()),
            )
            .collect();
        self.reparse_with_other_files_constants(
            waiting,
            offered,
            names.clone(),
            &mut units,
            &mut pending,
            &mut var_config,
        );
        // a constant no file declares (a library's): one E0022, at its first use
        il_frontend::const_eval::one_error_per_missing_constant(&mut self.diags);
        // a TwinCAT global variable list is named after its object (`GVL.x`)
        for (k, list) in twincat_lists {
            if let Some(unit) = units.get_mut(k) {
                for item in &mut unit.items {
                    if let il_frontend::ast::LibraryElement::GlobalVars(block) = item {
                        block.name = Some(il_frontend::ast::Ident::new(list.clone(), block.span));
                    }
                }
            }
        }
        crate::text_lists::name_text_lists(&mut units, &text_lists);
        // `fb : FB_Buf<10>;`: a block of its own for each set of generic values
        crate::generic_blocks::build(
            self,
            &generic_texts,
            &names,
            &mut units,
            &mut pending,
            &mut twincat_units,
        );
        for c in v4_configs {
            // (the configuration of a project.json whose POUs were not read would name them)
            if failed_json.contains(&c.source) {
                continue;
            }
            let file = self.map.add_file_owned(c.name, c.text);
            let mut local = Diagnostics::new();
            let (unit, bodies, _) = il_frontend::st::file::parse_text(
                file,
                &self.map.get(file).text,
                "configuration",
                Lang::St,
                &mut local,
            );
            self.diags.extend(local);
            units.push(unit);
            pending.extend(bodies);
        }
        self.add_additional_blocks(&mut units, &mut pending);
        if !twincat_units.is_empty() || !twincat_tasks.is_empty() {
            self.task_cycle_ms = crate::twincat::configure(
                self,
                &mut units,
                &twincat_units,
                &twincat_tasks,
                &twincat_failed,
                &projects_read.libraries,
            );
        }
        // VAR_CONFIG once every file is read: a configuration names programs of other files
        il_frontend::st::file::apply_var_config(&mut units, var_config, &mut self.diags);
        // a file of methods without their block (`Block.Method.st`): its block named by its name
        for pb in &mut pending {
            if let Some(lone) = pb.lone.as_mut() {
                lone.name_owner(&self.map.get(pb.file).name);
            }
        }
        // B&R: a program folder's actions file belongs to the folder's program parts
        crate::br_programs::attach_actions(&units, &mut pending, &self.map);
        // B&R: a program folder's `.var` variables are its parts' own, before their bodies compile
        crate::br_programs::own_variables(&mut units, &pending, &self.map);
        // B&R: a `.typ` structure's fields that differ in case only (case-sensitive Automation Studio)
        crate::br_case_fields::keep_first_of_case_twins(&mut units, &self.map, &mut self.diags);
        // B&R: a program's private `.typ` types whose names other declarations take too are its
        // own (alike or not: each program its own copy)
        crate::br_private_types::scope_private_types(&mut units, &self.map);
        // B&R: a block declared in a `.fun` file and implemented in a `.st` one is one block
        let fun_files: Vec<diagnostics::FileId> = self
            .map
            .files()
            .filter(|(_, f)| f.name.to_ascii_lowercase().ends_with(".fun"))
            .map(|(id, _)| id)
            .collect();
        // the interfaces of ladderc's PLCopen blocks, to tell a vendor's stub of the same name
        let templates = if fun_files.is_empty() {
            Library::new()
        } else {
            Library::builtin(&mut diagnostics::SourceMap::new(), &mut Diagnostics::new())
        };
        let provided = |name: &str| {
            use param_passing::template::Direction;
            templates.get(name).map(|t| {
                t.params
                    .iter()
                    .filter_map(|p| {
                        let kind = match p.direction {
                            Direction::Input => il_frontend::ast::VarKind::Input,
                            Direction::Output => il_frontend::ast::VarKind::Output,
                            Direction::InOut => il_frontend::ast::VarKind::InOut,
                            Direction::State => return None,
                        };
                        Some(crate::split_blocks::ProvidedParam {
                            name: p.name.clone(),
                            kind,
                            ty: if p.array.is_some() {
                                "ARRAY".to_string()
                            } else {
                                p.iec_type.clone()
                            },
                            required: p.required,
                        })
                    })
                    .collect()
            })
        };
        let map = &self.map;
        let file_name = |f: diagnostics::FileId| {
            let n = &map.get(f).name;
            n.rsplit(['/', '\\']).next().unwrap_or(n).to_string()
        };
        let stubs = crate::split_blocks::join(
            &mut units,
            &mut pending,
            |f| fun_files.contains(&f),
            provided,
            file_name,
            &mut self.diags,
        );
        // B&R: a library's data types made of its stub blocks are not compiled either
        let folder = |f: diagnostics::FileId| {
            let name = Path::new(&map.get(f).name);
            let path = std::fs::canonicalize(name).unwrap_or_else(|_| name.to_path_buf());
            path.parent().unwrap_or(Path::new("")).to_path_buf()
        };
        let dropped = crate::split_blocks::drop_stub_types(&mut units, &stubs, folder, file_name);
        self.stub_types.extend(dropped);
        // the motion libraries' enumeration constants (`MC_Positive_Direction`), declared for
        // the checks later (`param_passing::prelude`), are USINT in the ST bodies too
        let library_constants: Vec<(&str, &str)> = param_passing::prelude::ENUM_CONSTANTS
            .iter()
            .map(|(name, _)| (*name, "USINT"))
            .collect();
        il_frontend::st::file::compile_pending_with_library(
            &mut units,
            &pending,
            &library_constants,
            &mut self.diags,
        );
        // a file's description and attribute pragmas (`{ DE:"..." }` on each variable): one note
        il_frontend::st::lexer::collapse_metadata_notes(&mut self.diags);
        crate::textual_sfc::lower_textual_sfc(&mut units, &pending, &self.map, &mut self.diags);
        self.linked_actions = il_frontend::actions::link(&mut units, &mut self.diags);
        // B&R: a program folder's _INIT, _CYCLIC, _EXIT and .var files are one program
        crate::br_programs::join(&mut units, &self.map, &mut self.diags);
        il_frontend::st::qualifiers::set_project_programs(programs_before);
        il_frontend::st::qualifiers::set_project_bases(bases_before);
        il_frontend::st::qualifiers::set_project_namespaces(namespaces_before);
        il_frontend::st::set_project_globals(globals_before);
        units
    }

    /// Beremiz's and OpenPLC's additional blocks (`PID`, `INTEGRAL`, ...) that `units` use without
    /// declaring them: ladderc's copy read as one more ST file (unit and bodies appended), with one
    /// note W1435 naming them at the first use of the first.
    fn add_additional_blocks(
        &mut self,
        units: &mut Vec<CompilationUnit>,
        pending: &mut Vec<il_frontend::st::file::PendingBody>,
    ) {
        use il_frontend::st::additional_blocks as additional;
        let wanted = additional::wanted(units);
        let names: Vec<&str> = wanted.iter().map(|(n, _)| *n).collect();
        // those the project names, in the order of their first uses
        let mut used: Vec<(&str, diagnostics::Span)> = wanted
            .iter()
            .filter_map(|(n, s)| s.map(|s| (*n, s)))
            .collect();
        used.sort_by_key(|(_, s)| (s.file, s.start));
        let Some(&(_, at)) = used.first() else {
            return;
        };
        let used: Vec<&str> = used.into_iter().map(|(n, _)| n).collect();
        let file = self.map.add_file_owned(
            additional::FILE_NAME.to_string(),
            additional::source_for(&names),
        );
        let mut local = Diagnostics::new();
        let (unit, bodies, _) = il_frontend::st::file::parse_text(
            file,
            &self.map.get(file).text,
            "additional_blocks",
            Lang::St,
            &mut local,
        );
        self.diags.extend(local);
        self.diags.push(
            Diagnostic::new(
                code::W1435,
                diagnostics::Severity::Note,
                format!(
                    "{} {} of the additional function blocks of Beremiz and OpenPLC Editor: ladderc's \
                     built-in copy is compiled with the project",
                    used.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", "),
                    if used.len() == 1 { "is one" } else { "are" }
                ),
            )
            .at(at)
            .with_hint(
                "IEC 61131-3 Annex F's algorithms, a TIME counted in seconds as in those runtimes \
                 (`ladderc explain W1435`); declare a block of the same name to use your own",
            ),
        );
        units.push(unit);
        pending.extend(bodies);
    }

    /// Parses again the text files in `waiting` (their bounds or lengths named constants they do not
    /// declare, E0022) with the integer constants of the other files' `VAR_GLOBAL CONSTANT` lists
    /// known (CODESYS keeps `N_AXES` in `GVL.st`, `ARRAY[1..N_AXES]` in another object's file), until
    /// no new constant is found: at most once per waiting file, so a chain of constants across files
    /// resolves and a cycle stops. The last parse of each file is kept, with its diagnostics. A file
    /// whose qualifier named no library (E1032) is parsed again with `names`, those the project's
    /// files declare, known: `GVL.fbTimer(...)` with the list `GVL` in another file is no library.
    /// Compiles the PLCopen XML files read (`(unit index, file, Beremiz folder)`), each with the POU
    /// interfaces and data types of the others known ([`ladder_compiler::project::with_other_files`]).
    /// `lists` are the text files that may be named global lists (`(unit index, name)`, named later by
    /// `text_lists::name_text_lists` and the TwinCAT objects): their members are known qualified too.
    fn compile_xml_files(
        &mut self,
        files: Vec<(usize, diagnostics::FileId, Option<PathBuf>)>,
        lists: &[(usize, String)],
        units: &mut [il_frontend::ast::CompilationUnit],
        var_config: &mut Vec<il_frontend::st::file::ConfigEntry>,
        pending: &mut Vec<il_frontend::st::file::PendingBody>,
    ) {
        let interfaces: Vec<ladder_compiler::project::OtherFiles> = files
            .iter()
            .map(|(_, f, _)| ladder_compiler::project::interfaces(*f, &self.map.get(*f).text))
            .collect();
        // the text inputs' POUs and data types (`.st`, TwinCAT objects: a TwinCAT project that
        // imported one POU as PLCopen XML keeps its types in `.TcDUT` files)
        let xml_slots: std::collections::HashSet<usize> = files.iter().map(|f| f.0).collect();
        let mut text = ladder_compiler::project::OtherFiles::default();
        for (k, u) in units
            .iter()
            .enumerate()
            .filter(|(k, _)| !xml_slots.contains(k))
        {
            // a file of global lists only, named after the file (or its TwinCAT object)
            let only_lists = !u.items.is_empty()
                && u.items
                    .iter()
                    .all(|i| matches!(i, il_frontend::ast::LibraryElement::GlobalVars(_)));
            let file_list = lists
                .iter()
                .find(|(j, _)| *j == k && only_lists)
                .map(|(_, n)| n.to_ascii_uppercase());
            for b in u.items.iter().flat_map(|i| i.var_blocks()) {
                if !matches!(b.kind, il_frontend::ast::VarKind::Global) {
                    continue;
                }
                let list = b.name.as_ref().map(|n| n.key()).or(file_list.clone());
                for v in &b.vars {
                    text.globals
                        .entry(v.name.key())
                        .or_insert_with(|| v.ty.clone());
                    if let Some(list) = &list {
                        text.global_lists
                            .entry(list.clone())
                            .or_default()
                            .entry(v.name.key())
                            .or_insert_with(|| v.ty.clone());
                    }
                }
            }
            for item in &u.items {
                match item {
                    il_frontend::ast::LibraryElement::Pou(p) => {
                        text.pous.push(ladder_compiler::project::signature(p))
                    }
                    il_frontend::ast::LibraryElement::DataTypes(ts) => {
                        text.types.extend(ts.iter().cloned())
                    }
                    _ => {}
                }
            }
        }
        for (i, (k, file, dir)) in files.into_iter().enumerate() {
            let mut other = ladder_compiler::project::OtherFiles::default();
            other.pous.extend(text.pous.iter().cloned());
            other.types.extend(text.types.iter().cloned());
            other.globals.clone_from(&text.globals);
            other.global_lists.clone_from(&text.global_lists);
            for (_, o) in interfaces.iter().enumerate().filter(|(j, _)| *j != i) {
                other.pous.extend(o.pous.iter().cloned());
                other.types.extend(o.types.iter().cloned());
                for (k, v) in &o.constants {
                    other.constants.entry(k.clone()).or_insert(*v);
                }
            }
            let src = &self.map.get(file).text;
            let diags = &mut self.diags;
            let (mut unit, entries, bodies) =
                ladder_compiler::project::with_other_files(other, || {
                    ladder_compiler::compile_xml_with_var_config(file, src, diags)
                });
            pending.extend(bodies);
            if let Some(dir) = &dir {
                crate::beremiz::add_confnodes(self, dir, &mut unit);
            }
            if let Some(slot) = units.get_mut(k) {
                *slot = unit;
            }
            var_config.extend(entries);
        }
    }

    fn reparse_with_other_files_constants(
        &mut self,
        mut waiting: Vec<WaitingFile>,
        offered: Vec<il_frontend::parser::Constants>,
        names: std::collections::HashSet<String>,
        units: &mut [CompilationUnit],
        pending: &mut Vec<il_frontend::st::file::PendingBody>,
        var_config: &mut Vec<il_frontend::st::file::ConfigEntry>,
    ) {
        if waiting.is_empty() {
            return;
        }
        let mut known: il_frontend::parser::Constants = offered.into_iter().flatten().collect();
        // `SIZEOF(T)` in a bound: the sizes of every file's data types
        known.extend(il_frontend::type_sizes::project_sizes(units.iter()));
        let mut results: Vec<Option<(CompilationUnit, _, _)>> =
            waiting.iter().map(|_| None).collect();
        // (one pass more: a file's own constant may be known once another file's enumeration is,
        // `N : INT := E_Topic.COUNT_OF;` bounding an array declared above it)
        for _ in 0..=waiting.len() {
            let mut found = known.clone();
            let mut own_grew = false;
            for (w, result) in waiting.iter_mut().zip(results.iter_mut()) {
                let src = w.text.as_ref().unwrap_or(&self.map.get(w.file).text);
                let mut local = Diagnostics::new();
                let mut offered = known.clone();
                for (k, v) in &w.own {
                    offered.entry(k.clone()).or_insert(*v);
                }
                let knowing = offered.clone();
                let parsed = il_frontend::parser::with_other_files_constants(offered, || {
                    il_frontend::st::with_other_files_names(names.clone(), || {
                        il_frontend::st::file::parse_text(
                            w.file,
                            src,
                            &w.implicit,
                            w.lang,
                            &mut local,
                        )
                    })
                });
                found.extend(il_frontend::parser::integer_constants_knowing(
                    &parsed.0, &local, false, &knowing,
                ));
                let own = il_frontend::parser::integer_constants_knowing(
                    &parsed.0, &local, true, &knowing,
                );
                own_grew |= own.keys().any(|k| !w.own.contains_key(k));
                w.own.extend(own);
                w.diags = local;
                *result = Some(parsed);
            }
            // the data types of the files parsed again may have sizes now
            let latest: Vec<&CompilationUnit> = units
                .iter()
                .enumerate()
                .map(|(k, u)| {
                    waiting
                        .iter()
                        .zip(&results)
                        .find(|(w, _)| w.unit == k)
                        .and_then(|(_, r)| r.as_ref().map(|r| &r.0))
                        .unwrap_or(u)
                })
                .collect();
            found.extend(il_frontend::type_sizes::project_sizes(
                latest.iter().copied(),
            ));
            let grew = found != known || own_grew;
            known = found;
            if !grew
                || waiting
                    .iter()
                    .all(|w| !w.diags.iter().any(|d| d.code == code::E0022))
            {
                break;
            }
        }
        for (w, parsed) in waiting.into_iter().zip(results) {
            let mut diags = w.diags;
            // a bound's constant named as written in the file (a TwinCAT object's qualifiers are
            // blanked before it is parsed), a library's parameter E1032
            let original = &self.map.get(w.file).text;
            for d in diags.since_mut(0) {
                il_frontend::st::file::library_qualified_bound(d, original);
            }
            // (a library is one E1032, at its first use: in a type or in a bound)
            let library = |d: &Diagnostic| {
                (d.code == code::E1032)
                    .then(|| d.message.split('`').nth(1).map(str::to_ascii_uppercase))
                    .flatten()
            };
            let mut named: std::collections::HashSet<String> =
                self.diags.iter().filter_map(library).collect();
            diags.retain(|d| library(d).is_none_or(|l| named.insert(l)));
            self.diags.extend(diags);
            if let Some((unit, bodies, entries)) = parsed {
                units[w.unit] = unit;
                pending.extend(bodies);
                var_config.extend(entries);
            }
        }
    }

    /// Whether every error reported while reading the files is one whose cause the reader left
    /// behind it, so that the checks may run on the rest: E1032 (an unknown library qualifier,
    /// `Vendor.Connect()`: the qualified names renamed `__...`, which the checks do not report
    /// again), E1085 (a generic POU, not compiled, its calls not reported again), E3016 (a
    /// graphical function block box without a declared instance: the box and what its outputs
    /// feed are left out of the lowered network, the rest of the body is lowered) and E1001 in a
    /// graphical body (an undeclared name at a box's input: the box is left out likewise). Then the
    /// program's other, independent errors (an undeclared name, a missing global list) are
    /// reported in the same run (before: the E1032 or the E3016 alone, the rest on the next run).
    fn only_recovered_parse_errors(&self) -> bool {
        self.diags
            .iter()
            .filter(|d| d.severity == diagnostics::Severity::Error)
            .all(|d| {
                d.code == code::E1032
                    || d.code == code::E1085
                    || d.code == code::E3016
                    || (d.code == code::E1001 && d.xml.is_some())
            })
    }

    /// The checks' errors at a name an E1032 reported, there or at another use of the same
    /// library (`Vendor.Connect()` read as `__ndor_Connect`, an unknown function; `DC_ECP.Dtm425`
    /// as an unknown type), and at a call of a generic POU that E1085 reported (`Pick(1, 2)`, an
    /// unknown function), at a use of a box's instance that E3016 reported as not declared
    /// (`T1.Q` read in another network of the same file, an undeclared name), and the checks'
    /// E1001 of a name that reading a graphical body of the same POU already reported undeclared
    /// (at a box's input): the unknown library, the generic POU, the missing instance or the
    /// undeclared name is their one cause, reported once (the checks run after these errors:
    /// [`Session::only_recovered_parse_errors`]).
    fn drop_behind_recovered_errors(&mut self) {
        // (file, POU, upper-case name) of each E1001 reading the graphical bodies reported
        let mut undeclared = std::collections::HashSet::new();
        for d in self.diags.iter().take(self.loaded_diags) {
            let (Some(s), Some(xml)) = (d.span, d.xml.as_ref()) else {
                continue;
            };
            if d.code != code::E1001 {
                continue;
            }
            if let Some(name) = d.message.split('`').nth(1) {
                let pou = xml.pou.as_deref().unwrap_or("").to_ascii_uppercase();
                undeclared.insert((s.file, pou, name.to_ascii_uppercase()));
            }
        }
        if !undeclared.is_empty() {
            let loaded = self.loaded_diags;
            // the checks' diagnostics have no XML context yet: the POU their span is in
            let mut locators = std::collections::HashMap::new();
            let map = &self.map;
            let mut kept = Diagnostics::new();
            for (k, d) in std::mem::take(&mut self.diags).into_iter().enumerate() {
                let again = k >= loaded
                    && d.code == code::E1001
                    && d.span.is_some_and(|s| {
                        let Some(name) = d.message.split('`').nth(1) else {
                            return false;
                        };
                        let pou = match d.xml.as_ref() {
                            Some(x) => x.pou.clone(),
                            None => locators
                                .entry(s.file)
                                .or_insert_with(|| {
                                    ladder_compiler::locate::Locator::new(&map.get(s.file).text)
                                })
                                .at(s.start as usize)
                                .and_then(|x| x.pou.clone()),
                        };
                        let pou = pou.unwrap_or_default().to_ascii_uppercase();
                        undeclared.contains(&(s.file, pou, name.to_ascii_uppercase()))
                    });
                if !again {
                    kept.push(d);
                }
            }
            self.diags = kept;
        }
        // (upper case) each library E1032 named: the text at its span; each generic POU E1085
        // named: the text at its span up to the `<`; each undeclared instance E3016 named (its
        // span is the `instanceName`), with its file
        let mut libraries = std::collections::HashSet::new();
        let mut generic = std::collections::HashSet::new();
        let mut instances = std::collections::HashSet::new();
        for d in self.diags.iter() {
            let Some(s) = d.span else { continue };
            let text = &self.map.get(s.file).text;
            let Some(at) = text.get(s.start as usize..s.end as usize) else {
                continue;
            };
            if d.code == code::E1032 {
                libraries.insert(at.to_ascii_uppercase());
            } else if d.code == code::E1085 {
                let name = at.split('<').next().unwrap_or(at).trim();
                generic.insert(name.to_ascii_uppercase());
            } else if d.code == code::E3016 && d.message.starts_with("instance `") {
                instances.insert((s.file, at.trim().to_ascii_uppercase()));
            }
        }
        if libraries.is_empty() && generic.is_empty() && instances.is_empty() {
            return;
        }
        let map = &self.map;
        let behind = |s: diagnostics::Span| {
            let text = &map.get(s.file).text;
            let at = text.get(s.start as usize..).unwrap_or("");
            let name_len = at
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(at.len());
            let name = at[..name_len].to_ascii_uppercase();
            (at[name_len..].starts_with('.') && libraries.contains(&name))
                || generic.contains(&name)
                || instances.contains(&(s.file, name))
        };
        let mut kept = Diagnostics::new();
        for d in std::mem::take(&mut self.diags) {
            if d.code == code::E1032
                || d.code == code::E1085
                || d.code == code::E3016
                || d.severity != diagnostics::Severity::Error
                || !d.span.is_some_and(behind)
            {
                kept.push(d);
            }
        }
        self.diags = kept;
    }

    /// The front half: load, check, lower block calls. `None` when errors were reported.
    pub fn lower(&mut self, paths: &[PathBuf], opts: &Options) -> Option<Lowered> {
        let parsed = self.parse(paths, opts)?;
        let checked = self.check(parsed, paths, opts)?;
        self.lower_checked(checked, opts)
    }

    /// The target profile, the parameter templates and the user's units. `None` when errors were
    /// reported.
    pub fn parse(&mut self, paths: &[PathBuf], opts: &Options) -> Option<Parsed> {
        let profile = match &opts.profile {
            Some(p) => self.profile(p)?,
            None => c_backend::TargetProfile::default(),
        };
        // the length of a STRING declared without one: the profile's for the whole compilation (the
        // readers, sema and the C backend read it from the types); every compilation sets it here
        il_frontend::sema::set_default_string_len(profile.default_string_length);
        let mut library = Library::builtin(&mut self.map, &mut self.diags);
        if let Some(dir) = &opts.templates {
            // Checks every user template in full (body tokens and names; its function compiled alone
            // when asked).
            self.user_templates(&mut library, dir, opts.compile_templates);
        }
        self.libraries = opts.libraries.clone();
        // the profile's semantics that the readers need: the unit of TIME as a number (constant
        // expressions of declarations) and the SFC action control (the charts' lowering)
        let unit_before =
            il_frontend::const_eval::set_time_number_unit(profile.time_number_unit.nanoseconds());
        let control_before =
            ladder_compiler::sfc::actions::set_action_control(match profile.sfc_action_control {
                c_backend::SfcActionControl::Iec => {
                    ladder_compiler::sfc::actions::ActionControl::Iec
                }
                c_backend::SfcActionControl::Beremiz => {
                    ladder_compiler::sfc::actions::ActionControl::Beremiz
                }
            });
        let units = self.load_as(paths, opts.lang);
        il_frontend::const_eval::set_time_number_unit(unit_before);
        ladder_compiler::sfc::actions::set_action_control(control_before);
        if let Some(tool) = crate::tool_semantics::tool_of_inputs(self, paths, &units) {
            crate::tool_semantics::warn_unit(&units, &profile, tool, &mut self.diags);
            crate::tool_semantics::warn_final_scan(&units, &profile, tool, &mut self.diags);
        }
        self.loaded_diags = self.diags.len();
        if self.diags.has_errors() && !self.only_recovered_parse_errors() {
            self.unknown_types_behind_bounds(&units, &library);
            return None;
        }
        Some(Parsed {
            units,
            library,
            profile,
        })
    }

    /// The target profile at `path` (E9001 when it cannot be read, E2003 when it is not a valid one).
    /// A bare built-in name (`openplc`, `default`) that names no file is that built-in profile.
    fn profile(&mut self, path: &Path) -> Option<c_backend::TargetProfile> {
        if !(self.overlay.contains_key(path) || (self.disk && path.exists())) {
            if let Some(p) = c_backend::TargetProfile::built_in(path) {
                return Some(p);
            }
        }
        if self.disk && !self.overlay.contains_key(path) {
            return c_backend::TargetProfile::load_or_report(path, &mut self.diags);
        }
        let text = match self.read_file(path) {
            Ok(t) => t,
            Err(e) => {
                self.diags.push(
                    Diagnostic::error(code::E9001, format!("cannot read {}: {e}", path.display()))
                        .with_hint("check the --profile path and its permissions, or name a built-in profile: `default`, `openplc`"),
                );
                return None;
            }
        };
        match c_backend::TargetProfile::from_json(&text) {
            Ok(p) => Some(p),
            Err(e) => {
                self.diags.push(
                    Diagnostic::error(code::E2003, e.to_string())
                        .with_hint("see the memory model section of the c-backend README"),
                );
                None
            }
        }
    }

    /// Adds the user templates of `dir`: the overlay's `dir/*.xml`, and (with [`Session::disk`]) the
    /// folder's files, sorted by path.
    fn user_templates(&mut self, library: &mut Library, dir: &Path, compile_c: bool) {
        let is_xml = |p: &Path| p.extension().is_some_and(|x| x.eq_ignore_ascii_case("xml"));
        let mut in_memory: Vec<PathBuf> = self
            .overlay
            .keys()
            .filter(|p| p.parent() == Some(dir) && is_xml(p))
            .cloned()
            .collect();
        if self.disk && in_memory.is_empty() {
            library.add_dir_with(dir, compile_c, &mut self.map, &mut self.diags);
            return;
        }
        if self.disk {
            if let Ok(entries) = std::fs::read_dir(dir) {
                in_memory.extend(
                    entries
                        .filter_map(|e| e.ok().map(|e| e.path()))
                        .filter(|p| is_xml(p)),
                );
            }
        }
        in_memory.sort();
        in_memory.dedup();
        if in_memory.is_empty() {
            self.diags.push(
                Diagnostic::error(
                    code::E9001,
                    format!(
                        "cannot read the template directory {}: {}",
                        dir.display(),
                        not_in_memory()
                    ),
                )
                .with_hint("give the template files (`DIR/NAME.xml`) in memory, or leave out the templates folder"),
            );
            return;
        }
        let mut files = Vec::new();
        for p in in_memory {
            match self.read_file(&p) {
                Ok(text) => files.push((p.display().to_string(), text)),
                Err(e) => self.diags.push(
                    Diagnostic::error(code::E9001, format!("cannot read {}: {e}", p.display()))
                        .with_hint("template files must be readable UTF-8"),
                ),
            }
        }
        library.add_user_texts(&files, compile_c, &mut self.map, &mut self.diags);
    }

    /// The semantic checks of a parsed program, with the PLCopen block interfaces and the axes file when it
    /// uses blocks. `None` when errors were reported.
    pub fn check(&mut self, parsed: Parsed, paths: &[PathBuf], opts: &Options) -> Option<Checked> {
        let Parsed {
            units: mut user,
            library,
            profile,
        } = parsed;
        let mut axes = self.axis_config(paths, opts.axes.as_deref())?;
        axes.tc2_tables = crate::tc2_blocks::add(&mut user, &mut self.map, &mut self.diags);
        // B&R's EDGEPOS / EDGENEG / EDGE operators
        crate::br_edges::rewrite(&mut user);
        // CODESYS SM3_Basic's AXIS_REF_SM3
        crate::tc2_mc2::sm3_axis_type(&mut user);
        let uses_blocks = uses_library_blocks(&user, &library);
        if uses_blocks {
            crate::axis_links::link(&mut user, &mut axes, &mut self.diags);
            crate::tc2_mc2::read_spellings(&mut user, &library, &mut axes, &mut self.diags);
            // (the METHODs nothing calls, checked on their own in `check_uncalled`)
            crate::tc2_mc2::read_method_spellings(
                &user,
                self.linked_actions.uncalled_methods_mut(),
                &library,
                &mut axes,
                &mut self.diags,
            );
            crate::block_temps::keep(&mut user, &library);
            crate::motion_in_struct::report(&user, &library, &mut self.diags);
        }
        let cycle_ms = match (axes.cycle_ms, opts.cycle_ms) {
            (Some(a), Some(c)) if (a - c).abs() > 1e-9 * a.abs().max(1.0) => {
                self.diags.push(
                    Diagnostic::error(
                        code::E5053,
                        format!(
                            "--cycle-ms {c} differs from the axis configuration's cycle_ms {a}"
                        ),
                    )
                    .with_hint(
                        "leave out --cycle-ms, or make both equal: the engine steps once per scan",
                    ),
                );
                return None;
            }
            (Some(a), _) => a,
            (None, Some(c)) => c,
            (None, None) => self.task_cycle_ms.unwrap_or(DEFAULT_CYCLE_MS),
        };
        // Check the user's program (with the block interfaces and the axes when it uses blocks).
        let mut checked = Vec::new();
        if uses_blocks {
            let axes_il = axes.globals_il();
            let pre = param_passing::prelude::before_lowering(&library);
            let f = self.map.add("<PLCopen blocks>", pre.clone());
            checked.push(il_frontend::parse(f, &pre, &mut self.diags));
            let f = self.map.add("<axis configuration>", axes_il.clone());
            checked.push(il_frontend::parse(f, &axes_il, &mut self.diags));
        }
        // Without blocks the checked program is the compiled one: no copy.
        let user = if uses_blocks {
            checked.extend(user.iter().cloned());
            user
        } else {
            checked.extend(user);
            Vec::new()
        };
        let model = self.analyze(&checked);
        self.check_uncalled(&checked, uses_blocks);
        self.drop_behind_recovered_errors();
        if self.diags.has_errors() {
            if uses_blocks && opts.axes.is_none() && axes.axes.is_empty() && axes.groups.is_empty()
            {
                self.hint_axes_file(paths);
            }
            return None;
        }
        Some(Checked {
            user,
            checked,
            model,
            library,
            profile,
            uses_blocks,
            axes,
            cycle_ms,
        })
    }

    /// The actions and METHODs (property accessors too) that no POU calls, checked as when they
    /// are called (issue #13: `check` runs every check `build` runs; before round 27 their bodies
    /// were never analysed): a second semantic analysis of `units` with them linked into their
    /// POUs ([`il_frontend::actions::with_uncalled`]), whose diagnostics inside their bodies are
    /// kept when not already reported. Nothing of it is compiled.
    fn check_uncalled(&mut self, units: &[CompilationUnit], uses_blocks: bool) {
        let linked = std::mem::take(&mut self.linked_actions);
        let mut local = Diagnostics::new();
        let Some(mut with) = il_frontend::actions::with_uncalled(units, &linked, &mut local) else {
            return;
        };
        if uses_blocks {
            // the AXIS_REF members the METHODs read (`Axis.NcToPlc.ActPos`), as in the bodies
            crate::tc2_mc2::read_axis_members(&mut with, &mut local);
        }
        let spans = il_frontend::actions::uncalled_spans(&linked);
        {
            let _twincat = il_frontend::sema::TwinCatFiles::set(self.twincat_files.iter().copied());
            let _codesys = il_frontend::sema::CodesysFiles::set(self.codesys_files.iter().copied());
            il_frontend::sema::analyze_for_code(&with, &mut local);
        }
        let inside = |d: &Diagnostic| {
            d.span.is_some_and(|s| {
                spans
                    .iter()
                    .any(|a| a.file == s.file && a.start <= s.start && s.end <= a.end)
            })
        };
        let fresh: Vec<Diagnostic> = local
            .into_iter()
            .filter(|d| {
                inside(d)
                    && !self
                        .diags
                        .iter()
                        .any(|e| e.code == d.code && e.span == d.span && e.message == d.message)
            })
            .collect();
        self.diags.extend(fresh);
    }

    /// The semantic analysis of `units` into [`Session::diags`], with or without the name table
    /// ([`Session::name_table`]).
    /// When the only errors of the files are constant expressions without a value (E0022, an
    /// array bound naming a constant of a library or file not given), the types that nothing
    /// declares are reported too (E1003): a file that needs a vendor library names all it lacks in
    /// one run, not the types only once a constant is supplied. Nothing else of the check is
    /// reported (it would follow from the bound).
    fn unknown_types_behind_bounds(&mut self, units: &[CompilationUnit], library: &Library) {
        let only_bounds = self
            .diags
            .iter()
            .filter(|d| d.severity == diagnostics::Severity::Error)
            .all(|d| d.code == code::E0022);
        if !only_bounds || units.is_empty() {
            return;
        }
        let mut found = Diagnostics::new();
        {
            let _twincat = il_frontend::sema::TwinCatFiles::set(self.twincat_files.iter().copied());
            let _codesys = il_frontend::sema::CodesysFiles::set(self.codesys_files.iter().copied());
            il_frontend::sema::analyze_for_code(units, &mut found);
        }
        // (a PLCopen block or an axis is declared by the block library, checked with it later)
        let provided = |name: &str| {
            library.get(name).is_some()
                || name.eq_ignore_ascii_case("AXIS_REF")
                || name.eq_ignore_ascii_case("AXES_GROUP_REF")
        };
        self.diags.extend(found.into_iter().filter(|d| {
            d.code == code::E1003
                && d.message
                    .strip_prefix("unknown type `")
                    .is_some_and(|rest| rest.split('`').next().is_some_and(|name| !provided(name)))
        }));
        // `SIZEOF(ST_Log)` with `ST_Log` holding a field of a type declared nowhere: that type's
        // E1003 is the one error, the E0022 of the size left out (one cause)
        il_frontend::sema::without_sizes_of_unknown(&mut self.diags);
    }

    fn analyze(&mut self, units: &[CompilationUnit]) -> il_frontend::sema::Model {
        let _twincat = il_frontend::sema::TwinCatFiles::set(self.twincat_files.iter().copied());
        let _codesys = il_frontend::sema::CodesysFiles::set(self.codesys_files.iter().copied());
        let model = if self.name_table {
            il_frontend::sema::analyze(units, &mut self.diags)
        } else {
            il_frontend::sema::analyze_for_code(units, &mut self.diags)
        };
        crate::split_blocks::name_stub_types(&self.stub_types, &mut self.diags);
        self.foreign_additional_blocks();
        model
    }

    /// A block that ladderc's additional blocks name (W1435) called with pins they lack: another
    /// library's block of that name (CODESYS Util's `PID(ACTUAL, SET_POINT, ...)`,
    /// `HYSTERESIS(IN, HIGH, LOW)`). Its E1011s (one per pin) become one error at the first.
    fn foreign_additional_blocks(&mut self) {
        use il_frontend::st::additional_blocks::is_additional;
        let noted = |d: &Diagnostic| d.code == code::W1435;
        if !self.diags.iter().any(noted) {
            return;
        }
        // the block named by an E1011 `PID has no parameter `ACTUAL``, and the pin
        let foreign = |d: &Diagnostic| -> Option<(String, String)> {
            if d.code != code::E1011 {
                return None;
            }
            let (block, rest) = d.message.split_once(" has no ")?;
            let pin = rest.split('`').nth(1)?;
            is_additional(block).then(|| (block.to_string(), pin.to_string()))
        };
        let list = std::mem::take(&mut self.diags).into_vec();
        let mut pins: Vec<(String, Vec<String>)> = Vec::new();
        for d in &list {
            if let Some((block, pin)) = foreign(d) {
                match pins.iter_mut().find(|(b, _)| *b == block) {
                    Some((_, p)) if !p.contains(&pin) => p.push(pin),
                    Some(_) => {}
                    None => pins.push((block, vec![pin])),
                }
            }
        }
        let mut done: Vec<String> = Vec::new();
        for d in list {
            let Some((block, _)) = foreign(&d) else {
                self.diags.push(d);
                continue;
            };
            if done.contains(&block) {
                continue;
            }
            let theirs = &pins.iter().find(|(b, _)| *b == block).expect("collected").1;
            let shown: Vec<String> = theirs.iter().map(|p| format!("`{p}`")).collect();
            let ours = d.hint.clone().unwrap_or_default();
            let mut e = Diagnostic::error(
                code::E1011,
                format!(
                    "this `{block}` is another library's (its pins {}): ladderc provides the `{block}` of Beremiz and OpenPLC Editor (IEC 61131-3 Annex F) only",
                    shown.join(", ")
                ),
            )
            .with_primary_label("a pin of another library's block")
            .with_hint(format!(
                "{ours}; a CODESYS Util or vendor `{block}` is not provided: declare the FUNCTION_BLOCK `{block}` in the project (it is then used), or give its library's source with --lib"
            ));
            if let Some(span) = d.span {
                e = e.at(span);
            }
            if let Some(x) = d.xml {
                e = e.with_xml(x);
            }
            self.diags.push(e);
            done.push(block);
        }
    }

    /// Parameter passing: every PLCopen block call lowered by `opts.strategy`. `None` when errors were
    /// reported.
    pub fn lower_checked(&mut self, checked: Checked, opts: &Options) -> Option<Lowered> {
        let Checked {
            user,
            checked,
            model: checked_model,
            library,
            profile,
            uses_blocks,
            axes,
            cycle_ms,
        } = checked;
        let window = TmWindow {
            offset: profile.tm_offset,
            bytes: profile.tm_bytes,
            // %M counts elements also with per-size %I/%Q images
            element_addressing: profile.address_unit != c_backend::AddressUnit::Byte,
        };
        let mut lowering = if uses_blocks {
            lower::lower(&user, &library, opts.strategy, &window, &mut self.diags)
        } else {
            lower::Lowered::default()
        };
        if self.diags.has_errors() {
            return None;
        }
        // The model is valid only for the very units it was computed from (it keys instructions by
        // identity): without block lowering those are `checked`, which is then compiled as it is.
        let user_start = if uses_blocks { 2 } else { 0 };
        let all_units = if uses_blocks {
            let axes_il = axes.globals_il();
            let mut all_units = Vec::new();
            let post = param_passing::prelude::after_lowering(&library);
            let f = self.map.add("<PLCopen block instances>", post.clone());
            all_units.push(il_frontend::parse(f, &post, &mut self.diags));
            let f = self.map.add("<axis configuration>", axes_il.clone());
            all_units.push(il_frontend::parse(f, &axes_il, &mut self.diags));
            all_units.append(&mut lowering.units);
            all_units
        } else {
            checked
        };
        Some(Lowered {
            source_copy: uses_blocks.then_some(user),
            all_units,
            user_start,
            lowering,
            library,
            profile,
            uses_blocks,
            axes,
            cycle_ms,
            model: (!uses_blocks).then_some(checked_model),
        })
    }

    /// A motion program without an axes file: every undeclared name (E1001) may be an axis or group that
    /// the missing file would declare, so its hint says where the file was looked for.
    fn hint_axes_file(&mut self, paths: &[PathBuf]) {
        let looked = paths
            .first()
            .and_then(|p| default_axes_path(p))
            .map(|p| format!("`{}`", p.display()))
            .unwrap_or_else(|| "`<input stem>.axes.json`".into());
        let list = std::mem::take(&mut self.diags).into_vec();
        self.diags.extend(list.into_iter().map(|mut d| {
            if d.code == code::E1001 {
                let axes = format!(
                    "if it is an axis or axes group, declare it in an axes file: none was found \
                     (looked for {looked}); pass `--axes FILE.json` (crates/ladderc/AXES.md)"
                );
                d.hint = Some(match d.hint.take() {
                    Some(h) => format!("{h}; {axes}"),
                    None => axes,
                });
            }
            d
        }));
    }

    /// The axis configuration: `explicit`, else `<stem>.axes.json` beside the first input when it
    /// exists, else the NC axes of the TwinCAT solution the input belongs to ([`crate::nc_axes`]),
    /// else the empty default. `None`: it could not be read or had errors.
    fn axis_config(&mut self, paths: &[PathBuf], explicit: Option<&Path>) -> Option<AxisConfig> {
        let path = match explicit {
            Some(p) => p.to_path_buf(),
            None => match paths
                .first()
                .filter(|p| !is_stdin(p))
                .and_then(|p| default_axes_path(p))
            {
                Some(p) if self.file_exists(&p) => p,
                // a TwinCAT solution's NC axes (`_Config/NC`), else none
                _ => {
                    let before = self.diags.error_count();
                    let plc = crate::nc_axes::plc_project(self, paths);
                    let imported = crate::nc_axes::solution(self, paths)
                        .and_then(|tsproj| crate::nc_axes::import(self, &tsproj, plc.as_deref()));
                    if self.diags.error_count() > before {
                        return None;
                    }
                    return Some(imported.unwrap_or_default());
                }
            },
        };
        let text = match self.read_file(&path) {
            Ok(t) => t,
            Err(e) => {
                self.diags.push(
                    Diagnostic::error(code::E9001, format!("cannot read {}: {e}", path.display()))
                        .with_hint("check the --axes path"),
                );
                return None;
            }
        };
        let text = text.strip_prefix('\u{feff}').unwrap_or(&text).to_string();
        let f = self.map.add(path.display().to_string(), text);
        AxisConfig::parse(&self.map, f, &mut self.diags)
    }

    /// The whole pipeline to a C project.
    pub fn compile(
        &mut self,
        paths: &[PathBuf],
        opts: &Options,
    ) -> Option<(Lowered, c_backend::CProgram)> {
        let mut lowered = self.lower(paths, opts)?;
        let program = self.generate(&mut lowered)?;
        Some((lowered, program))
    }

    /// The C project of a lowered program (its semantic model is taken out of `lowered`). `None` when
    /// errors were reported.
    pub fn generate(&mut self, lowered: &mut Lowered) -> Option<c_backend::CProgram> {
        let model = match lowered.model.take() {
            Some(m) => m,
            None => {
                // The lowered program: its warnings were given on the user's program already; an error
                // here would be a lowering bug, and is reported.
                let mut second = Diagnostics::new();
                let _twincat =
                    il_frontend::sema::TwinCatFiles::set(self.twincat_files.iter().copied());
                let _codesys =
                    il_frontend::sema::CodesysFiles::set(self.codesys_files.iter().copied());
                let m = if self.name_table {
                    il_frontend::sema::analyze(&lowered.all_units, &mut second)
                } else {
                    il_frontend::sema::analyze_for_code(&lowered.all_units, &mut second)
                };
                self.diags.extend(
                    second
                        .into_iter()
                        .filter(|d| d.severity == diagnostics::Severity::Error),
                );
                m
            }
        };
        if self.diags.has_errors() {
            return None;
        }
        let embedded = embedded_functions(lowered);
        let copts = c_backend::Options {
            embedded,
            lines: c_backend::SourceLines::of(&self.map),
        };
        let ext = c_backend::Extensions {
            motion: lowered
                .uses_blocks
                .then(|| lowered.axes.runtime(lowered.cycle_ms, MOTION_HEADER)),
            methods: lowered
                .lowering
                .synthesized
                .iter()
                .map(pou_method)
                .collect(),
        };
        let program = c_backend::generate_with(
            &lowered.all_units,
            &model,
            &lowered.profile,
            &copts,
            &ext,
            &mut self.diags,
        )?;
        lowered.model = Some(model);
        Some(program)
    }
}

/// The error of a file that is neither in memory nor to be read from the file system.
fn not_in_memory() -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::NotFound,
        "not given in memory (the file system is not read)",
    )
}

/// `<stem>.axes.json` beside `input`.
pub fn default_axes_path(input: &Path) -> Option<PathBuf> {
    let stem = input.file_stem()?.to_str()?;
    Some(input.with_file_name(format!("{stem}.axes.json")))
}

/// A template-method function for the C backend.
fn pou_method(s: &lower::Synthesized) -> c_backend::PouMethod {
    use param_passing::template::TypeClass;
    c_backend::PouMethod {
        name: s.name.clone(),
        pou: s.pou.clone(),
        func_num: s.func_num,
        head: s
            .head
            .iter()
            .map(|h| c_backend::MethodLocal {
                c_type: h.c_type.to_string(),
                local: h.local.clone(),
                boolean: h.class == TypeClass::Bool,
                source: h.source.clone(),
            })
            .collect(),
        locals: s.locals.clone(),
        body: s.body.clone(),
        tail: s
            .tail
            .iter()
            .map(|f| c_backend::MethodFeedback {
                target: f.target.clone(),
                local: f.local.clone(),
                c_type: s
                    .head
                    .iter()
                    .find(|h| h.local == f.local)
                    .map_or("uint8_t", |h| h.c_type)
                    .to_string(),
                boolean: f.class == TypeClass::Bool,
                negated: f.negated,
            })
            .collect(),
        span: s.call_span,
    }
}

/// The static-library functions of the IL method as embedded C for the backend.
fn embedded_functions(l: &Lowered) -> Vec<c_backend::EmbeddedFunction> {
    let mut out = Vec::new();
    if l.lowering.static_functions.is_empty() {
        return out;
    }
    let used: Vec<&str> = l
        .lowering
        .static_functions
        .keys()
        .map(String::as_str)
        .collect();
    let pairs: Vec<_> = used
        .iter()
        .filter_map(|b| {
            l.library
                .get(b)
                .map(|t| (t, &l.lowering.static_functions[*b]))
        })
        .collect();
    let lib = param_passing::static_lib::library_c(pairs, &used);
    for (i, b) in used.iter().enumerate() {
        out.push(c_backend::EmbeddedFunction {
            name: b.to_string(),
            c_source: if i == 0 { lib.clone() } else { String::new() },
        });
    }
    out
}

fn uses_library_blocks(units: &[CompilationUnit], lib: &Library) -> bool {
    use il_frontend::ast::{LibraryElement, TypeRef};
    // A block or type the project declares itself (its own `MC_Power` over its own axis type, as
    // a library written for another runtime has) is the project's: not a use of ladderc's blocks,
    // which would declare the name a second time (E1002 against `<PLCopen blocks>`).
    let own: std::collections::HashSet<String> = units
        .iter()
        .flat_map(|u| u.items.iter())
        .flat_map(|item| match item {
            LibraryElement::Pou(p) => vec![p.name.name.to_ascii_uppercase()],
            LibraryElement::DataTypes(ts) => ts
                .iter()
                .map(|t| t.name.name.to_ascii_uppercase())
                .collect(),
            _ => vec![],
        })
        .collect();
    let library_type = |t: &il_frontend::ast::Ident| {
        !own.contains(&t.name.to_ascii_uppercase())
            && (lib.get(&t.name).is_some() || t.is("AXIS_REF") || t.is("AXES_GROUP_REF"))
    };
    // `fbPower : ARRAY [1..4] OF MC_Power;`, `axes : ARRAY [1..4] OF AXIS_REF;`
    let library = |mut ty: &TypeRef| {
        while let TypeRef::Array { element, .. } = ty {
            ty = element;
        }
        matches!(ty, TypeRef::Named(t) if library_type(t))
    };
    units.iter().flat_map(|u| u.items.iter()).any(|item| {
        item.var_blocks()
            .iter()
            .flat_map(|b| b.vars.iter())
            .any(|v| library(&v.ty))
            // a structure's field (`Axis : AXIS_REF;` of ISIS's ST_AxisControl)
            || matches!(item, LibraryElement::DataTypes(ts) if ts.iter().any(|t| matches!(
                &t.def,
                il_frontend::ast::TypeDef::Struct { fields } if fields.iter().any(|f| library(&f.ty))
            )))
    })
}

/// Where the JSON body of an OpenPLC Editor v4 graphical POU (`main.ld`: `PROGRAM main VAR ...
/// END_VAR` then `{ "name": ..., "rungs": [...] }`) starts: the `{` of a text that, after an
/// `END_VAR` line, holds only a JSON object with a `"rungs"`, `"nodes"` or `"blocks"` member (the
/// first such place whose JSON is well-formed, as the JSON may hold `END_VAR` in its texts; else the
/// last, so that a body cut short is still one).
fn openplc_v4_json_body(src: &str) -> Option<usize> {
    let upper = src.to_ascii_uppercase();
    let (mut last, mut tries) = (None, 0);
    for (k, _) in upper.match_indices("END_VAR") {
        let end_var = k + "END_VAR".len();
        let rest = &src[end_var..];
        let start = end_var + (rest.len() - rest.trim_start().len());
        if !src[start..].starts_with('{') {
            continue;
        }
        let body = &src[start..crate::openplc_v4_ld::json_end(src, start)];
        // (a ladder body cut short is still one: its reader says where it stops)
        let json = (body.ends_with('}') || body.contains("\"rungs\""))
            && ["\"rungs\"", "\"nodes\"", "\"blocks\""]
                .iter()
                .any(|k| body.contains(k));
        if !json {
            continue;
        }
        // (a few tries: a hostile text may hold many)
        tries += 1;
        if tries <= 8 && serde_json::from_str::<serde::de::IgnoredAny>(body).is_ok() {
            return Some(start);
        }
        last = Some(start);
    }
    last
}

fn is_iec_identifier(s: &str) -> bool {
    let mut c = s.chars();
    matches!(c.next(), Some(ch) if ch.is_ascii_alphabetic() || ch == '_')
        && c.all(|ch| ch.is_ascii_alphanumeric() || ch == '_')
        && !s.contains("__")
}

/// The file name for a trace written next to `path` while the program runs (renamed on success).
pub fn staging_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "out".into());
    path.with_file_name(format!(".{name}.partial"))
}

/// A text file whose bounds or lengths named a constant it does not declare (E0022): parsed again
/// once every file's constant lists are known.
struct WaitingFile {
    /// Its place among the units.
    unit: usize,
    file: diagnostics::FileId,
    implicit: String,
    lang: il_frontend::st::file::Lang,
    /// The text parsed when it is not the file's own (a CODESYS V2.3 or TwinCAT object file's
    /// texts, blanks around them).
    text: Option<String>,
    /// The diagnostics of its last parse.
    diags: Diagnostics,
    /// The constants its first parse found in its own POUs' `VAR CONSTANT` blocks (a bound may
    /// name one declared below it), offered to its parses again only.
    own: il_frontend::parser::Constants,
}

/// Whether a PLCopen XML text was exported by CODESYS (its `<fileHeader>` names the product:
/// `productName="CODESYS"`, or the company 3S-Smart Software Solutions): its ST bodies follow
/// CODESYS's meaning where it differs from IEC 61131-3 edition 3's ([`Session::codesys_files`]).
fn is_codesys_xml(src: &str) -> bool {
    let Some(at) = src.find("<fileHeader") else {
        return false;
    };
    let header = &src[at..];
    let header = &header[..header.find('>').unwrap_or(header.len())];
    header.contains("CODESYS") || header.contains("3S-Smart Software Solutions")
}

/// Whether `src` is an IEC 61131-10 XML exchange file (`<Project
/// xmlns="www.iec.ch/public/TC65SC65BWG7TF10">`), which `ladder_compiler::project` refuses (E3002).
fn is_iec_61131_10(src: &str) -> bool {
    let mut end = src.len().min(4096);
    while !src.is_char_boundary(end) {
        end -= 1;
    }
    let head = &src[..end];
    head.contains("<Project") && head.contains("TC65SC65BWG7")
}
