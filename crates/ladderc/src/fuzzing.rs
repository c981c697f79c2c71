//! One fuzzing step per front end, shared by the cargo-fuzz targets (`fuzz/`) and the bounded in-process
//! fuzz test (`tests/fuzz_inprocess.rs`).
//!
//! Input: a front end and arbitrary bytes (text front ends read them as UTF-8, invalid sequences replaced,
//! as an editor would show them). Output: what the step produced ([`Outcome`]). Invariants it asserts (a
//! failed assertion is a finding: the fuzzer stops on the panic): every diagnostic's primary span and label
//! spans lie inside their file and on character boundaries, and the human rendering of the diagnostics is
//! at most [`output_bound`] bytes. No panic may escape a front end; time is measured by the caller.

use diagnostics::{render, Diagnostic, Diagnostics, MessageFormat, SourceMap};

/// The six front ends of the project.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrontEnd {
    /// IL source (`ladderc check x.il`): parse and semantic checks.
    Il,
    /// An ST body of a function block with typed variables: parse, lowering to IL, semantic checks.
    St,
    /// PLCopen TC6 XML (`ladderc check x.xml`): lowering to IL and semantic checks.
    Xml,
    /// A parameter template (`--templates DIR`): schema, body checks, the block declarations it yields.
    Template,
    /// A drive script (`ladderc drive build`): compile, encode the image, run 20 cycles on the simulation.
    DriveScript,
    /// A drive image (`ladderc drive run IMAGE`): decode, then run 20 cycles on the simulation.
    DriveImage,
}

impl FrontEnd {
    /// Every front end, in the order of the fuzz targets.
    pub const ALL: [FrontEnd; 6] = [
        FrontEnd::Il,
        FrontEnd::St,
        FrontEnd::Xml,
        FrontEnd::Template,
        FrontEnd::DriveScript,
        FrontEnd::DriveImage,
    ];
    /// The front end's name (the fuzz target's suffix).
    pub fn name(self) -> &'static str {
        match self {
            FrontEnd::Il => "il",
            FrontEnd::St => "st",
            FrontEnd::Xml => "xml",
            FrontEnd::Template => "template",
            FrontEnd::DriveScript => "drive_script",
            FrontEnd::DriveImage => "drive_image",
        }
    }
}

/// What one step produced.
#[derive(Debug, Default, Clone, Copy)]
pub struct Outcome {
    /// How many diagnostics the input got.
    pub diagnostics: usize,
    /// Bytes of the human rendering of the diagnostics.
    pub rendered_bytes: usize,
}

/// The largest human rendering accepted for an input of `len` bytes: 64 KiB plus 400 bytes per input byte.
pub fn output_bound(len: usize) -> usize {
    64 * 1024 + 400 * len
}

/// How many diagnostics per file a cargo-fuzz target renders in the human format
/// (`LADDERC_FUZZ_MAX_DIAGNOSTICS`, default 5; the product's default is 50). Every diagnostic's spans are
/// still checked; rendering is per diagnostic (each one clipped on its own), so the first few exercise
/// the same code as the first fifty, and the cap's tail line ("N more diagnostics") is reached more often.
/// Rendering was 41 % of an `il` step with the product's default.
pub const FUZZ_MAX_DIAGNOSTICS: usize = 5;

/// Called once by a cargo-fuzz target before its first input: sets the rendering cap of
/// [`FUZZ_MAX_DIAGNOSTICS`] (or `LADDERC_FUZZ_MAX_DIAGNOSTICS`).
pub fn init_target() {
    let n = std::env::var("LADDERC_FUZZ_MAX_DIAGNOSTICS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(FUZZ_MAX_DIAGNOSTICS);
    diagnostics::set_max_per_file(n);
}

/// The declarations an ST body is compiled against (a function block with variables of the common types).
pub const ST_DECLS: &str = "TYPE Color : (red, green, blue); END_TYPE
FUNCTION_BLOCK fuzz
VAR_INPUT i : INT; r : REAL; b : BOOL; s : STRING; t : TIME; END_VAR
VAR_OUTPUT q : BOOL; n : DINT; END_VAR
VAR a : ARRAY [0..9] OF INT; c : Color; tm : TON; ctr : CTU; lr : LREAL; w : WORD; END_VAR
END_FUNCTION_BLOCK
";

/// [`ST_DECLS`] parsed: the unit, its declarations for the ST lowering, and the parser's diagnostics.
struct StPrelude {
    file: diagnostics::FileId,
    unit: il_frontend::ast::CompilationUnit,
    decls: il_frontend::st::Declarations,
    diags: Diagnostics,
}

/// [`ST_DECLS`] parsed once, in the file that [`run`] adds first to its fresh source map.
fn st_prelude() -> &'static StPrelude {
    static PRELUDE: std::sync::OnceLock<StPrelude> = std::sync::OnceLock::new();
    PRELUDE.get_or_init(|| {
        let mut map = SourceMap::new();
        let mut diags = Diagnostics::new();
        let file = map.add("fuzz.st", ST_DECLS);
        let unit = il_frontend::parse(file, ST_DECLS, &mut diags);
        let decls = il_frontend::st::Declarations::from_units(std::slice::from_ref(&unit));
        StPrelude {
            file,
            unit,
            decls,
            diags,
        }
    })
}

/// Runs one input through `front_end` and checks the invariants (panics on a violation).
pub fn run(front_end: FrontEnd, data: &[u8]) -> Outcome {
    let text = String::from_utf8_lossy(data);
    let mut map = SourceMap::new();
    let mut diags = Diagnostics::new();
    match front_end {
        FrontEnd::Il => {
            let f = map.add("fuzz.il", text.as_ref());
            let unit = il_frontend::parse_named(f, &text, "fuzz", &mut diags);
            let _ = il_frontend::sema::analyze(std::slice::from_ref(&unit), &mut diags);
        }
        FrontEnd::St => {
            use il_frontend::ast::LibraryElement;
            let src = format!("{ST_DECLS}(*ST*)\n{text}");
            let f = map.add("fuzz.st", src);
            // The declarations are the same for every input: parsed once (they were 17 % of a step).
            let prelude = st_prelude();
            assert_eq!(f, prelude.file, "the ST file is the map's first");
            let mut unit = prelude.unit.clone();
            diags.extend(prelude.diags.iter().cloned());
            let decls = &prelude.decls;
            let base = ST_DECLS.len() + "(*ST*)\n".len();
            for item in &mut unit.items {
                if let LibraryElement::Pou(p) = item {
                    let (il, temps) =
                        il_frontend::st::compile_body(f, &text, base, decls, p, p.span, &mut diags);
                    p.body = il;
                    p.var_blocks.extend(temps);
                }
            }
            let _ = il_frontend::sema::analyze(std::slice::from_ref(&unit), &mut diags);
        }
        FrontEnd::Xml => {
            let f = map.add("fuzz.xml", text.as_ref());
            let unit = ladder_compiler::compile_xml(f, &text, &mut diags);
            if !diags.has_errors() {
                let _ = il_frontend::sema::analyze(std::slice::from_ref(&unit), &mut diags);
            }
        }
        FrontEnd::Template => {
            let mut lib = param_passing::library::Library::new();
            if lib
                .add_text(&mut map, "fuzz.xml", &text, &mut diags)
                .is_some()
                && lib.check_bodies(param_passing::library::runtime_symbol_set(), &mut diags)
            {
                // The declarations a loaded template gives the program must parse (never panic).
                let pre = param_passing::prelude::before_lowering(&lib);
                let f = map.add("<PLCopen blocks>", pre.clone());
                let _ = il_frontend::parse(f, &pre, &mut diags);
                let window = param_passing::lower::TmWindow {
                    offset: 3840,
                    bytes: 256,
                    element_addressing: true,
                };
                for t in lib.templates() {
                    if let Ok(layout) = param_passing::lower::il_layout(t, &window) {
                        let _ = param_passing::static_lib::function_c(t, &layout);
                    }
                }
            }
        }
        FrontEnd::DriveScript => {
            let (m, result) = drive_script::compile_str("fuzz.ds", &text);
            map = m;
            match result {
                Ok(c) => {
                    let image = drive_script::encode(&c.program);
                    let back = drive_script::decode(&image).expect("an encoded image decodes");
                    run_image(back);
                }
                Err(d) => diags = d,
            }
        }
        FrontEnd::DriveImage => {
            if let Ok(p) = drive_script::decode(data) {
                run_image(p);
            }
        }
    }
    check_spans(&map, diags.iter());
    let rendered = render(&map, diags.as_slice(), MessageFormat::Human);
    let bound = output_bound(data.len());
    assert!(
        rendered.len() <= bound,
        "{} bytes of diagnostics for {} bytes of input (bound {bound})",
        rendered.len(),
        data.len()
    );
    Outcome {
        diagnostics: diags.len(),
        rendered_bytes: rendered.len(),
    }
}

/// Runs a decoded program for 20 cycles on the simulated drive (a program that the interpreter refuses
/// is fine: it says why).
fn run_image(p: drive_script::Program) {
    if let Ok(mut interp) = drive_script::Interpreter::new(p) {
        let mut drive = drive_script::SimDrive::new(1);
        for _ in 0..20 {
            let _ = interp.cycle(&mut drive);
        }
    }
}

/// Asserts that every span lies inside its file and on character boundaries.
pub fn check_spans<'a>(map: &SourceMap, diags: impl Iterator<Item = &'a Diagnostic>) {
    for d in diags {
        let spans = d
            .span
            .iter()
            .copied()
            .chain(d.labels.iter().map(|l| l.span));
        for s in spans {
            let text = &map.get(s.file).text;
            let (a, b) = (s.start as usize, s.end as usize);
            assert!(
                a <= b && b <= text.len(),
                "{}: span {a}..{b} outside the file ({} bytes): {}",
                d.code,
                text.len(),
                d.message
            );
            assert!(
                text.is_char_boundary(a) && text.is_char_boundary(b),
                "{}: span {a}..{b} not on character boundaries: {}",
                d.code,
                d.message
            );
        }
    }
}
