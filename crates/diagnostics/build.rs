//! Generates the code table from `explanations/*.md`: one file per stable code, so that each stage adds
//! its codes by adding files (no shared list to edit). The first line of a file is `# CODE: title`.
#![forbid(unsafe_code)]
use std::fmt::Write as _;
use std::path::Path;

fn main() {
    let dir = Path::new("explanations");
    println!("cargo:rerun-if-changed=explanations");
    let mut entries: Vec<(String, String, String)> = Vec::new();
    for entry in std::fs::read_dir(dir).expect("explanations directory") {
        let path = entry.expect("dir entry").path();
        if path.extension().and_then(|e| e.to_str()) != Some("md") {
            continue;
        }
        println!("cargo:rerun-if-changed={}", path.display());
        let code = path.file_stem().unwrap().to_str().unwrap().to_string();
        assert!(
            code.len() == 5
                && matches!(&code[..1], "E" | "W")
                && code[1..].chars().all(|c| c.is_ascii_digit()),
            "explanation file name must be like E0001.md: {code}"
        );
        let text = std::fs::read_to_string(&path).expect("read explanation");
        let first = text.lines().next().unwrap_or_default();
        let prefix = format!("# {code}: ");
        let title = first
            .strip_prefix(&prefix)
            .unwrap_or_else(|| panic!("{}: first line must be `{prefix}title`", path.display()))
            .trim()
            .to_string();
        let abs = std::fs::canonicalize(&path).unwrap();
        entries.push((code, title, abs.display().to_string()));
    }
    entries.sort();
    let mut out = String::new();
    for (code, _, _) in &entries {
        writeln!(out, "/// See `ladderc explain {code}`.").unwrap();
        writeln!(out, "pub const {code}: Code = Code(\"{code}\");").unwrap();
    }
    writeln!(
        out,
        "/// Every code with its title and explanation text, sorted by code."
    )
    .unwrap();
    writeln!(out, "pub static ALL: &[CodeInfo] = &[").unwrap();
    for (code, title, path) in &entries {
        writeln!(
            out,
            "    CodeInfo {{ code: Code({code:?}), title: {title:?}, explanation: include_str!({path:?}) }},"
        )
        .unwrap();
    }
    writeln!(out, "];").unwrap();
    let out_dir = std::env::var("OUT_DIR").unwrap();
    std::fs::write(Path::new(&out_dir).join("codes.rs"), out).unwrap();
}
