//! `build --depfile FILE`: the build's dependencies in make syntax.
//!
//! Input: the build's input paths and options, and the files it wrote. Output: one rule
//! `OUTPUT... : INPUT...` (every output depends on every input read: the sources, the axes file, the
//! target profile, every template file of `--templates`), paths as given on the command line, with make's
//! special characters escaped (space, `#`, `$`, `\` before a space, `:` is left as it is).
//! Invariant: the inputs are exactly the files the pipeline reads for these options; built-in templates
//! and the motion library are part of the ladderc executable and are not listed.

use crate::pipeline::{default_axes_path, Options};
use std::path::{Path, PathBuf};

/// The files a build with `paths` and `opts` reads, in a stable order, without duplicates.
pub fn inputs(paths: &[PathBuf], opts: &Options) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = paths
        .iter()
        .filter(|p| p.as_os_str() != "-")
        .cloned()
        .collect();
    match &opts.axes {
        Some(a) => out.push(a.clone()),
        None => {
            if let Some(a) = paths.first().and_then(|p| default_axes_path(p)) {
                if a.is_file() {
                    out.push(a);
                }
            }
        }
    }
    if let Some(p) = &opts.profile {
        out.push(p.clone());
    }
    if let Some(dir) = &opts.templates {
        // the same selection as param_passing::library::Library::add_dir
        let mut t: Vec<PathBuf> = std::fs::read_dir(dir)
            .into_iter()
            .flatten()
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x.eq_ignore_ascii_case("xml")))
            .collect();
        t.sort();
        out.extend(t);
    }
    let mut seen = std::collections::HashSet::new();
    out.retain(|p| seen.insert(p.clone()));
    out
}

/// A path escaped for a make rule.
pub fn escape(p: &Path) -> String {
    let s = p.to_string_lossy();
    let mut out = String::with_capacity(s.len());
    let chars: Vec<char> = s.chars().collect();
    for (i, &c) in chars.iter().enumerate() {
        match c {
            ' ' | '\t' => {
                // backslashes right before a blank are doubled, then the blank is escaped
                let run = chars[..i].iter().rev().take_while(|&&b| b == '\\').count();
                out.extend(std::iter::repeat_n('\\', run));
                out.push('\\');
                out.push(c);
            }
            '#' => out.push_str("\\#"),
            '$' => out.push_str("$$"),
            _ => out.push(c),
        }
    }
    out
}

/// The depfile text: `outputs` depend on `inputs`; each input also gets an empty rule, so that make does
/// not fail when one is deleted (as `gcc -MP` does).
pub fn render(outputs: &[PathBuf], inputs: &[PathBuf]) -> String {
    let mut s = String::new();
    let join = |v: &[PathBuf]| {
        v.iter()
            .map(|p| escape(p))
            .collect::<Vec<_>>()
            .join(" \\\n  ")
    };
    s.push_str(&join(outputs));
    s.push_str(": \\\n  ");
    s.push_str(&join(inputs));
    s.push('\n');
    for i in inputs {
        s.push_str(&format!("\n{}:\n", escape(i)));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn make_special_characters_are_escaped() {
        assert_eq!(escape(Path::new("a b/c#d$e")), "a\\ b/c\\#d$$e");
        assert_eq!(escape(Path::new("x\\ y")), "x\\\\\\ y");
        let text = render(
            &[PathBuf::from("out/program.c")],
            &[PathBuf::from("my prog.il")],
        );
        assert_eq!(text, "out/program.c: \\\n  my\\ prog.il\n\nmy\\ prog.il:\n");
    }
}
