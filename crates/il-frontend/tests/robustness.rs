//! No input makes the parser panic: every cut and every inserted stray character of a rich sample and of
//! the corpus gives diagnostics and a tree, never a crash; mutations that stay valid still round-trip.
mod common;

fn mutations(src: &str, step: usize) -> Vec<String> {
    let mut out = Vec::new();
    let cuts: Vec<usize> = (0..src.len())
        .step_by(step)
        .filter(|&i| src.is_char_boundary(i))
        .collect();
    for &i in &cuts {
        // Drop a few bytes.
        let mut j = (i + 3).min(src.len());
        while !src.is_char_boundary(j) {
            j += 1;
        }
        out.push(format!("{}{}", &src[..i], &src[j..]));
        // Truncate.
        out.push(src[..i].to_string());
        // Insert stray text.
        for junk in ["(", ")", ";", "\n", "'", "(*", ":=", "END_VAR", "AND(", "%"] {
            out.push(format!("{}{junk}{}", &src[..i], &src[i..]));
        }
    }
    out
}

#[test]
fn mutated_rich_sample_never_panics() {
    let src = include_str!("samples/rich.il");
    let mut valid = 0;
    for m in mutations(src, 61) {
        let p = common::parse("m.il", &m);
        // A mutation that is still valid IL must round-trip like any valid input.
        if p.errors() == 0 {
            common::assert_round_trip("m.il", &m);
            valid += 1;
        } else {
            let _ = il_frontend::print::unit(&p.unit);
        }
    }
    assert!(valid > 50, "only {valid} mutations stayed valid");
}

#[test]
fn mutated_corpus_never_panics() {
    for path in common::corpus_il() {
        let src = std::fs::read_to_string(&path).unwrap();
        for m in mutations(&src, 151) {
            let p = common::parse("m.il", &m);
            let _ = il_frontend::print::unit(&p.unit);
        }
    }
}

#[test]
fn arbitrary_bytes_as_text_never_panic() {
    let mut seed = 7u64;
    for _ in 0..300 {
        let text: String = (0..200)
            .map(|_| {
                seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1);
                let pick = b"LD ST AND( ) : := => ; , . [ ] 'x' \"y\" T#1s %IX0.1 VAR END_VAR PROGRAM END_PROGRAM CAL f( \n\n 12 a b (* *)";
                pick[(seed >> 33) as usize % pick.len()] as char
            })
            .collect();
        let p = common::parse("r.il", &text);
        let _ = il_frontend::print::unit(&p.unit);
    }
}
