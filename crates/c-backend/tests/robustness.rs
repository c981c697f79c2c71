//! The generator never panics: programs with lines removed either fail analysis or generate C.

use c_backend::{Options, TargetProfile};
use diagnostics::{Diagnostics, SourceMap};

#[test]
fn mutated_programs_never_panic_the_generator() {
    let base = format!(
        "{}\nTYPE\n  pt : STRUCT\n    x : INT := 1;\n  END_STRUCT;\nEND_TYPE\nFUNCTION f : INT\nVAR_INPUT\n  a : INT;\nEND_VAR\n  LD a\n  ADD 1\n  ST f\nEND_FUNCTION\nPROGRAM extra\nVAR\n  p : pt;\n  arr : ARRAY [1..3] OF pt;\n  s : STRING;\n  c : CTU;\nEND_VAR\n  LD p.x\n  f\n  ST arr[2].x\n  LD 'x'\n  ST s\n  CAL c(CU := TRUE, PV := 3)\n  LD c.Q\n  JMPC l1\n  LD 1\nl1:\n  ST %QX0.0\nEND_PROGRAM\n",
        il_frontend::testgen::generate(40, 1)
    );
    let lines: Vec<&str> = base.lines().collect();
    let mut generated = 0;
    let mut rng = 0x2545_f491_4f6c_dd1du64;
    for round in 0..300 {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        let drop1 = (rng % lines.len() as u64) as usize;
        let drop2 = ((rng >> 20) % lines.len() as u64) as usize;
        let src: String = lines
            .iter()
            .enumerate()
            .filter(|(i, _)| *i != drop1 && (round % 2 == 0 || *i != drop2))
            .map(|(_, l)| format!("{l}\n"))
            .collect();
        let mut map = SourceMap::new();
        let file = map.add("m.il", src.clone());
        let mut diags = Diagnostics::new();
        let units = vec![il_frontend::parse(file, &src, &mut diags)];
        let model = il_frontend::sema::analyze(&units, &mut diags);
        if diags.has_errors() {
            // the generator refuses a model with errors
            assert!(c_backend::generate(
                &units,
                &model,
                &TargetProfile::default(),
                &Options::default(),
                &mut diags
            )
            .is_none());
            continue;
        }
        let mut d = Diagnostics::new();
        if c_backend::generate(
            &units,
            &model,
            &TargetProfile::default(),
            &Options::default(),
            &mut d,
        )
        .is_some()
        {
            generated += 1;
        } else {
            assert!(d.has_errors(), "None without an error diagnostic");
        }
        // and even with a model whose errors were dropped, generation returns rather than panics
        let mut fresh = Diagnostics::new();
        let _ = c_backend::generate(
            &units,
            &model,
            &TargetProfile::default(),
            &Options::default(),
            &mut fresh,
        );
    }
    assert!(generated > 50, "only {generated} mutants generated");
}

#[test]
fn models_with_errors_never_panic_the_generator() {
    let srcs = [
        "PROGRAM p\n  LD nope\n  ST also_nope\nEND_PROGRAM\n",
        "PROGRAM p\nVAR\n  x : unknown_type;\nEND_VAR\n  LD x\n  ST x\nEND_PROGRAM\n",
        "PROGRAM p\n  CAL nothing(IN := 1)\n  JMP nowhere\nEND_PROGRAM\n",
        "FUNCTION f : INT\n  LD 1\nEND_FUNCTION\nPROGRAM p\n  f 1, 2, 3\n  ST %QW99999\nEND_PROGRAM\n",
    ];
    for src in srcs {
        let mut map = SourceMap::new();
        let file = map.add("e.il", src.to_string());
        let mut diags = Diagnostics::new();
        let units = vec![il_frontend::parse(file, src, &mut diags)];
        let model = il_frontend::sema::analyze(&units, &mut diags);
        let mut fresh = Diagnostics::new();
        let r = c_backend::generate(
            &units,
            &model,
            &TargetProfile::default(),
            &Options::default(),
            &mut fresh,
        );
        assert!(r.is_none() || !fresh.has_errors());
    }
}
