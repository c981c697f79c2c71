//! Measures parsing of a generated program: `cargo run --release -p il-frontend --example parse_generated -- LINES POUS`.
#![forbid(unsafe_code)]
fn main() {
    let mut args = std::env::args().skip(1);
    let lines: usize = args
        .next()
        .and_then(|a| a.parse().ok())
        .unwrap_or(1_000_000);
    let pous: usize = args.next().and_then(|a| a.parse().ok()).unwrap_or(1);
    let src = il_frontend::testgen::generate(lines, pous);
    let start = std::time::Instant::now();
    let mut diags = diagnostics::Diagnostics::new();
    let unit = il_frontend::parse(diagnostics::FileId(0), &src, &mut diags);
    println!(
        "{} bytes, {} POUs x {lines} lines: parsed in {:?}, {} diagnostics",
        src.len(),
        unit.items.len(),
        start.elapsed(),
        diags.len()
    );
}
