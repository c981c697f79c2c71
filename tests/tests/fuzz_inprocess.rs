//! Bounded in-process fuzzing of every front end (issue #12, point 6), in the normal test suite.
//!
//! Seeds: the project's own fixtures (IL examples and test programs, ST bodies of the XML fixtures, the
//! PLCopen XML fixtures, the shipped templates, the drive-script fixture and its compiled image). A
//! deterministic xorshift mutator (seeded per front end) flips, inserts, deletes, duplicates and splices
//! bytes, and inserts tokens that front ends care about (brackets, `]]>`, `#`, trigraphs, multi-byte
//! characters). Each input goes through [`ladderc::fuzzing::run`], which asserts that every span is inside
//! its file and on character boundaries and that the rendered diagnostics are bounded; here each input must
//! also finish in under 1 s (3 s in debug builds) and must not panic.
//!
//! Budget: `LADDERC_FUZZ_SECS` seconds per front end (default 10 in release builds, i.e. 60 s in all; 3 in
//! debug builds, where every step is about ten times slower). A failing input is written to
//! `target/fuzz-findings/` and its path is in the failure message.

mod common;

use ladderc::fuzzing::{self, FrontEnd};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use std::time::{Duration, Instant};

fn repo() -> PathBuf {
    common::repo_root()
}

fn files(dirs: &[&str], ext: &str) -> Vec<Vec<u8>> {
    let mut out = Vec::new();
    for d in dirs {
        let Ok(rd) = std::fs::read_dir(repo().join(d)) else {
            continue;
        };
        let mut paths: Vec<PathBuf> = rd.filter_map(|e| e.ok().map(|e| e.path())).collect();
        paths.sort();
        for p in paths {
            if p.extension().is_some_and(|x| x == ext) {
                out.push(std::fs::read(&p).unwrap());
            }
        }
    }
    out
}

const XML_DIRS: &[&str] = &[
    "crates/ladder-compiler/tests/fixtures",
    "tests/tests/fixtures",
    "tests/tests/fixtures/sfc",
    "tests/tests/motion",
];

/// The ST bodies of the XML fixtures (`<ST>` ... CDATA or text ... `</ST>`).
fn st_bodies() -> Vec<Vec<u8>> {
    let mut out = Vec::new();
    for x in files(XML_DIRS, "xml") {
        let x = String::from_utf8_lossy(&x).into_owned();
        let mut rest = x.as_str();
        while let Some(i) = rest.find("<ST>") {
            let after = &rest[i + 4..];
            let Some(j) = after.find("</ST>") else { break };
            let inner = &after[..j];
            let body = match (inner.find("<![CDATA["), inner.rfind("]]>")) {
                (Some(a), Some(b)) if a + 9 <= b => &inner[a + 9..b],
                _ => inner,
            };
            out.push(body.as_bytes().to_vec());
            rest = &after[j..];
        }
    }
    out.push(b"IF b THEN n := n + 1; ELSIF i > 3 THEN q := NOT q; END_IF;\nFOR i := 0 TO 9 DO a[i] := i * 2; END_FOR;\ntm(IN := b, PT := T#1s); q := tm.Q;\nCASE c OF red: n := 1; green, blue: n := 2; END_CASE;".to_vec());
    out
}

fn seeds(fe: FrontEnd) -> Vec<Vec<u8>> {
    let s = match fe {
        FrontEnd::Il => files(
            &[
                "examples/counter",
                "examples/motion",
                "examples/paper-b",
                "tests/tests/motion",
                "crates/il-frontend/tests/samples",
            ],
            "il",
        ),
        FrontEnd::St => st_bodies(),
        FrontEnd::Xml => files(XML_DIRS, "xml"),
        FrontEnd::Template => files(&["templates"], "xml"),
        FrontEnd::DriveScript => files(&["crates/drive-script/tests/scripts"], "ds"),
        FrontEnd::DriveImage => files(&["crates/drive-script/tests/scripts"], "ds")
            .iter()
            .filter_map(|t| {
                let (_, r) = drive_script::compile_str("seed.ds", &String::from_utf8_lossy(t));
                r.ok().map(|c| drive_script::encode(&c.program))
            })
            .collect(),
    };
    assert!(!s.is_empty(), "no seeds for {fe:?}");
    s
}

/// Tokens worth inserting (any front end).
const DICT: &[&[u8]] = &[
    b"(",
    b")",
    b"[",
    b"]",
    b"{",
    b"}",
    b"(*",
    b"*)",
    b"<",
    b">",
    b"/>",
    b"</",
    b"]]>",
    b"<![CDATA[",
    b"&amp;",
    b"&#x20AC;",
    b"\"",
    b"'",
    b"#",
    b"??=",
    b"%:",
    b"<%",
    b"%>",
    b"\\\n",
    b"$",
    b"\xE2\x82\xAC",
    b"\xC3\xA9",
    b"\xF0\x9F\x98\x80",
    b"\n",
    b"\r",
    b"\0",
    b";",
    b":=",
    b"=>",
    b"S::",
    b" IF ",
    b" THEN ",
    b" END_IF",
    b"CAL ",
    b"LD ",
    b"ST ",
    b"JMP ",
    b"FUNCTION_BLOCK ",
    b"END_VAR",
    b"VAR",
    b" := ",
    b"16#FFFF",
    b"T#1s",
    b"ARRAY[0..9] OF INT",
    b"2147483647",
    b"-1",
    b"1e308",
    b"AND ",
    b"OR ",
];

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }
    fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (self.next() % n as u64) as usize
        }
    }
}

const MAX_LEN: usize = 64 * 1024;

fn mutate(rng: &mut Rng, seeds: &[Vec<u8>], input: &mut Vec<u8>) {
    for _ in 0..1 + rng.below(8) {
        let len = input.len();
        match rng.below(8) {
            0 if len > 0 => {
                let i = rng.below(len);
                input[i] ^= 1 << rng.below(8);
            }
            1 => {
                let i = rng.below(len + 1);
                input.insert(i, rng.next() as u8);
            }
            2 if len > 0 => {
                let a = rng.below(len);
                let b = (a + 1 + rng.below(16)).min(len);
                input.drain(a..b);
            }
            3 if len > 0 => {
                let a = rng.below(len);
                let b = (a + 1 + rng.below(64)).min(len);
                let chunk = input[a..b].to_vec();
                let at = rng.below(input.len() + 1);
                input.splice(at..at, chunk);
            }
            4 | 5 => {
                let tok = DICT[rng.below(DICT.len())];
                let at = rng.below(len + 1);
                input.splice(at..at, tok.iter().copied());
            }
            6 if len > 0 => input.truncate(rng.below(len)),
            _ => {
                let other = &seeds[rng.below(seeds.len())];
                if !other.is_empty() {
                    let a = rng.below(other.len());
                    let b = (a + 1 + rng.below(256)).min(other.len());
                    let at = rng.below(len + 1);
                    input.splice(at..at, other[a..b].iter().copied());
                }
            }
        }
    }
    input.truncate(MAX_LEN);
}

fn budget() -> Duration {
    let default = if cfg!(debug_assertions) { 3 } else { 10 };
    let secs = std::env::var("LADDERC_FUZZ_SECS")
        .ok()
        .and_then(|s| s.parse::<u64>().ok())
        .unwrap_or(default);
    Duration::from_secs(secs)
}

fn per_input_limit() -> Duration {
    Duration::from_millis(if cfg!(debug_assertions) { 3000 } else { 1000 })
}

fn save(fe: FrontEnd, n: usize, data: &[u8]) -> PathBuf {
    let dir = repo().join("target/fuzz-findings");
    let _ = std::fs::create_dir_all(&dir);
    let p = dir.join(format!("{}-{n}.bin", fe.name()));
    let _ = std::fs::write(&p, data);
    p
}

fn campaign(fe: FrontEnd, seed: u64) {
    let seeds = seeds(fe);
    let deadline = Instant::now() + budget();
    let limit = per_input_limit();
    let mut rng = Rng(seed);
    let (mut execs, mut diags, mut slowest) = (0usize, 0usize, Duration::ZERO);
    // Every seed once, unchanged; then mutants until the budget is spent.
    let mut k = 0;
    while k < seeds.len() || Instant::now() < deadline {
        let mut input = seeds[k % seeds.len()].clone();
        if k >= seeds.len() {
            mutate(&mut rng, &seeds, &mut input);
        }
        k += 1;
        let started = Instant::now();
        let result = catch_unwind(AssertUnwindSafe(|| fuzzing::run(fe, &input)));
        let took = started.elapsed();
        execs += 1;
        match result {
            Ok(o) => diags += o.diagnostics,
            Err(e) => {
                let msg = e
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                let p = save(fe, k, &input);
                panic!("{fe:?}: input {} panicked: {msg}", p.display());
            }
        }
        if took > limit {
            let p = save(fe, k, &input);
            panic!(
                "{fe:?}: input {} took {took:?} (limit {limit:?})",
                p.display()
            );
        }
        slowest = slowest.max(took);
    }
    println!(
        "{fe:?}: {execs} inputs from {} seeds, {diags} diagnostics, slowest {slowest:?}",
        seeds.len()
    );
    assert!(execs > seeds.len(), "{fe:?}: no mutant ran");
}

/// Front ends run in a thread with a large stack, as the CLI's main thread has (8 MB there; deep
/// recursion is bounded by the front ends, the margin keeps debug builds' larger frames in).
fn spawn(fe: FrontEnd, seed: u64) {
    std::thread::Builder::new()
        .stack_size(64 << 20)
        .spawn(move || campaign(fe, seed))
        .unwrap()
        .join()
        .unwrap_or_else(|e| std::panic::resume_unwind(e));
}

#[test]
fn fuzz_il() {
    spawn(FrontEnd::Il, 0x1111_2222_3333_4444);
}

#[test]
fn fuzz_st() {
    spawn(FrontEnd::St, 0x5555_6666_7777_8888);
}

#[test]
fn fuzz_xml() {
    spawn(FrontEnd::Xml, 0x9999_aaaa_bbbb_cccc);
}

#[test]
fn fuzz_templates() {
    spawn(FrontEnd::Template, 0xdddd_eeee_ffff_0001);
}

#[test]
fn fuzz_drive_scripts() {
    spawn(FrontEnd::DriveScript, 0x0123_4567_89ab_cdef);
}

#[test]
fn fuzz_drive_images() {
    spawn(FrontEnd::DriveImage, 0xfedc_ba98_7654_3210);
}

#[test]
fn the_invariants_catch_a_span_inside_a_character() {
    // The checker itself: a span that ends inside `€` must be reported.
    let mut map = diagnostics::SourceMap::new();
    let f = map.add("x.il", "a€b");
    let d = diagnostics::Diagnostic::error(diagnostics::code::E4001, "x")
        .at(diagnostics::Span::new(f, 0, 2));
    let r = catch_unwind(AssertUnwindSafe(|| fuzzing::check_spans(&map, [d].iter())));
    assert!(r.is_err());
}

#[test]
fn fuzz_findings_stay_fixed() {
    // cargo-fuzz `template`: a `#` right before a multi-byte character gave an E4201 span that cut it.
    let body = "<blockTemplate name=\"ACME_X\" funcNum=\"1\"><parameters/><body>x #\u{fffd} #</body></blockTemplate>";
    let out = fuzzing::run(FrontEnd::Template, body.as_bytes());
    assert!(out.diagnostics > 0);
    // The committed minimised inputs (fuzz/regressions/<target>/, also seeds of the cargo-fuzz corpora).
    let dir = common::repo_root().join("fuzz/regressions");
    let mut n = 0;
    for (front_end, sub) in [
        (FrontEnd::St, "st"),
        (FrontEnd::Template, "template"),
        (FrontEnd::Xml, "xml"),
    ] {
        for f in std::fs::read_dir(dir.join(sub)).unwrap() {
            let data = std::fs::read(f.unwrap().path()).unwrap();
            let out = fuzzing::run(front_end, &data);
            assert!(out.diagnostics > 0);
            n += 1;
        }
    }
    assert!(n >= 3, "{n} regression inputs");
}
