//! Random byte mutations of valid ST never panic the lexer, parser, lowering or IL sema, and every
//! diagnostic span lies inside the text on character boundaries.

mod st_common;

use diagnostics::{Diagnostics, SourceMap};
use il_frontend::ast::LibraryElement;
use il_frontend::st;

const DECLS: &str = "FUNCTION_BLOCK Fb
VAR_INPUT go : BOOL; n : INT; END_VAR
VAR_OUTPUT q : BOOL; out : INT; END_VAR
VAR i : INT; a : ARRAY[0..9] OF INT; r : REAL; tmr : TON; s : STRING; END_VAR
END_FUNCTION_BLOCK
";

const SEED_TEXT: &str = "(* seed *) IF go AND n > 3 THEN out := n * (n - 2) + a[i + 1] MOD 3;
ELSIF n = 0 THEN out := -1; ELSE out := LIMIT(0, n, 10); END_IF;
CASE n OF 1, 2: q := TRUE; 3..5: q := FALSE; ELSE q := go; END_CASE;
FOR i := 9 TO 0 BY -1 DO a[i] := i * i; IF i < 3 THEN EXIT; END_IF; END_FOR;
WHILE i < 10 DO i := i + 1; END_WHILE; REPEAT i := i - 1; UNTIL i <= 0 END_REPEAT;
tmr(IN := go, PT := T#1s500ms, Q => q); r := INT_TO_REAL(n) ** 2.0 / 3.5;
s := 'caf\u{e9} $'x$''; // end
";

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

fn mutate(rng: &mut Rng, src: &[u8]) -> Vec<u8> {
    let mut b = src.to_vec();
    const PIECES: &[&[u8]] = &[
        b"(*", b"*)", b"'", b"\"", b"END_IF", b"IF", b";", b":=", b"(", b")", b"[", b"]", b"..",
        b"#", b"T#", b"16#", b"%IX", b"=>", b"**", b"\xc3", b"\xff", b"{", b"FOR", b"CASE",
    ];
    for _ in 0..1 + rng.below(4) {
        if b.is_empty() {
            break;
        }
        let at = rng.below(b.len());
        match rng.below(4) {
            0 => {
                b.remove(at);
            }
            1 => b[at] = (rng.next() & 0xff) as u8,
            2 => {
                let p = PIECES[rng.below(PIECES.len())];
                b.splice(at..at, p.iter().copied());
            }
            _ => {
                let len = rng.below(12).min(b.len() - at);
                b.drain(at..at + len);
            }
        }
    }
    b
}

fn compile(body: &str) {
    let mut sm = SourceMap::new();
    let text = format!("{DECLS}{body}");
    let file = sm.add("f.st", text.clone());
    let mut diags = Diagnostics::new();
    let mut unit = il_frontend::parse(file, DECLS, &mut diags);
    let decls = st::Declarations::from_units(std::slice::from_ref(&unit));
    for item in &mut unit.items {
        if let LibraryElement::Pou(p) = item {
            let (il, temps) =
                st::compile_body(file, body, DECLS.len(), &decls, p, p.span, &mut diags);
            p.body = il;
            if let Some(t) = temps {
                p.var_blocks.push(t);
            }
        }
    }
    let _ = il_frontend::sema::analyze(std::slice::from_ref(&unit), &mut diags);
    for d in diags.iter() {
        if let Some(s) = d.span {
            let (a, b) = (s.start as usize, s.end as usize);
            assert!(a <= b && b <= text.len(), "span {a}..{b} outside the text");
            assert!(
                text.is_char_boundary(a) && text.is_char_boundary(b),
                "span {a}..{b} cuts a character: {}",
                d.message
            );
        }
    }
    // Rendering must not panic either.
    let _ = st_common::render(&sm, diags);
}

#[test]
fn the_seed_compiles_cleanly() {
    let (_, diags) = st_common::compile(DECLS, "Fb", SEED_TEXT);
    assert_eq!(diags, "");
}

#[test]
fn random_mutations_never_panic() {
    let mut rng = Rng(0x5eed_1234_abcd_0001);
    let n = if cfg!(debug_assertions) { 600 } else { 5000 };
    for _ in 0..n {
        let m = mutate(&mut rng, SEED_TEXT.as_bytes());
        let body = String::from_utf8_lossy(&m).into_owned();
        compile(&body);
    }
}

#[test]
fn deep_nesting_is_reported_not_overflowed() {
    let deep = format!("x := {}1{};", "(".repeat(5000), ")".repeat(5000));
    compile(&deep);
    let ifs = "IF a THEN ".repeat(3000);
    compile(&ifs);
    let nots = format!("x := {}a;", "NOT ".repeat(5000));
    compile(&nots);
}
