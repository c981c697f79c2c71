//! Gives diagnostics of later stages the PLCopen context (POU, network, localId) of the XML element
//! their span points into.
//!
//! Input: the source map and the diagnostics about to be printed. Output: the same diagnostics, those
//! with a span in a PLCopen XML file and no XML context completed from
//! [`ladder_compiler::locate::Locator`] (semantic errors such as E1001 and E1011 in code lowered from
//! XML). Invariant: a diagnostic that has a context keeps it; each XML file is read once per call, and
//! only when one of its diagnostics needs it.

use diagnostics::{Diagnostic, FileId, SourceMap};
use ladder_compiler::locate::Locator;
use std::borrow::Cow;
use std::collections::HashMap;

/// Whether a source file is a PLCopen XML project (by its name, else by its first characters).
fn is_xml(name: &str, text: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    lower.ends_with(".xml")
        || (!name.starts_with('<') && {
            let t = text.trim_start();
            t.starts_with("<?xml") || t.starts_with("<project")
        })
}

/// See the module header.
pub fn annotate<'a>(map: &SourceMap, diags: &'a [Diagnostic]) -> Cow<'a, [Diagnostic]> {
    let needs = |d: &Diagnostic| {
        d.xml.is_none()
            && d.span.is_some_and(|s| {
                let f = map.get(s.file);
                is_xml(&f.name, &f.text)
            })
    };
    if !diags.iter().any(needs) {
        return Cow::Borrowed(diags);
    }
    let mut locators: HashMap<FileId, Locator> = HashMap::new();
    let out = diags
        .iter()
        .map(|d| {
            if !needs(d) {
                return d.clone();
            }
            let span = d.span.expect("needs a span");
            let loc = locators
                .entry(span.file)
                .or_insert_with(|| Locator::new(&map.get(span.file).text));
            match loc.at(span.start as usize) {
                Some(ctx) => d.clone().with_xml(ctx.clone()),
                None => d.clone(),
            }
        })
        .collect();
    Cow::Owned(out)
}
