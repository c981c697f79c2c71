//! `cargo bench -p ladder-compiler`: time to read and lower generated projects (the "10,000 rungs from
//! XML to C in under one second" budget; this is the XML -> IL part).
#![forbid(unsafe_code)]

use diagnostics::{Diagnostics, FileId};
use std::time::Instant;

fn main() {
    // `RUNGS=n` measures one size (for profilers); by default four sizes up to the benchmark's 10,000.
    let sizes: Vec<usize> = match std::env::var("RUNGS").ok().and_then(|v| v.parse().ok()) {
        Some(n) => vec![n],
        None => vec![1_000, 2_000, 5_000, 10_000],
    };
    for rungs in sizes {
        let xml = ladder_compiler::testgen::generate(rungs);
        let t = Instant::now();
        let arena = ladder_compiler::xml::Arena::new();
        let (root, _) = ladder_compiler::xml::parse(&xml, &arena);
        let parse = t.elapsed();
        assert!(root.is_some());
        // Freeing the arena frees the tree.
        drop(arena);
        let mut best = f64::MAX;
        for _ in 0..5 {
            let t = Instant::now();
            let mut diags = Diagnostics::new();
            let unit = ladder_compiler::compile_xml(FileId(0), &xml, &mut diags);
            let dt = t.elapsed().as_secs_f64();
            assert!(!diags.has_errors());
            std::hint::black_box(unit);
            best = best.min(dt);
        }
        println!(
            "{rungs} rungs ({} KiB of XML): xml tree {:.1} ms, xml -> IL tree {:.1} ms (best of 5)",
            xml.len() / 1024,
            parse.as_secs_f64() * 1e3,
            best * 1e3
        );
    }
}
