//! Helpers shared by the integration tests: parsing with a source map, short/human diagnostics,
//! span-free tree comparison, the corpus files.
#![allow(dead_code)]

use diagnostics::{render, Diagnostics, FileId, MessageFormat, SourceMap};
use il_frontend::ast::CompilationUnit;

pub struct Parsed {
    pub map: SourceMap,
    pub file: FileId,
    pub unit: CompilationUnit,
    pub diags: Vec<diagnostics::Diagnostic>,
}

pub fn parse(name: &str, src: &str) -> Parsed {
    let mut map = SourceMap::new();
    let file = map.add(name, src);
    let mut d = Diagnostics::new();
    let stem = name.rsplit('/').next().unwrap_or(name);
    let stem = stem.split('.').next().unwrap_or(stem);
    let unit = il_frontend::parse_named(file, src, stem, &mut d);
    Parsed {
        map,
        file,
        unit,
        diags: d.into_sorted(),
    }
}

impl Parsed {
    pub fn short(&self) -> String {
        render(&self.map, &self.diags, MessageFormat::Short)
    }
    pub fn human(&self) -> String {
        render(&self.map, &self.diags, MessageFormat::Human)
    }
    pub fn errors(&self) -> usize {
        self.diags
            .iter()
            .filter(|d| d.severity == diagnostics::Severity::Error)
            .count()
    }
}

/// The tree as JSON without positions: equal values mean equal trees up to spans.
pub fn shape<T: serde::Serialize>(t: &T) -> serde_json::Value {
    fn strip(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Object(m)
                if m.len() == 3 && m.contains_key("file") && m.contains_key("start") =>
            {
                *v = serde_json::Value::Null;
            }
            serde_json::Value::Object(m) => {
                m.remove("span");
                m.remove("close");
                for (_, x) in m.iter_mut() {
                    strip(x);
                }
            }
            serde_json::Value::Array(a) => a.iter_mut().for_each(strip),
            _ => {}
        }
    }
    let mut v = serde_json::to_value(t).expect("tree serialises");
    strip(&mut v);
    v
}

/// The IL files of the corpus, sorted by name: the bundled ones, and those of `$LADDERC_CORPUS/il` when
/// it is set (see the `test-corpus` crate).
pub fn corpus_il() -> Vec<std::path::PathBuf> {
    test_corpus::list("il", &[".il", ".st"])
}

/// Parse -> print -> parse -> print: the second print equals the first, and the trees are equal.
pub fn assert_round_trip(name: &str, src: &str) -> String {
    let first = parse(name, src);
    let printed = il_frontend::print::unit(&first.unit);
    let second = parse(name, &printed);
    assert_eq!(
        second.errors(),
        0,
        "printed IL of {name} does not parse:\n{}\n{printed}",
        second.short()
    );
    let (a, b) = (
        serde_json::to_string_pretty(&shape(&first.unit)).unwrap(),
        serde_json::to_string_pretty(&shape(&second.unit)).unwrap(),
    );
    if let Some((n, (x, y))) = a
        .lines()
        .zip(b.lines())
        .enumerate()
        .find(|(_, (x, y))| x != y)
    {
        panic!("tree changed for {name} at line {n} of its JSON: {x} != {y}\n{printed}");
    }
    assert_eq!(
        a.lines().count(),
        b.lines().count(),
        "tree changed for {name}"
    );
    let again = il_frontend::print::unit(&second.unit);
    assert_eq!(printed, again, "printing is not a fixed point for {name}");
    printed
}
