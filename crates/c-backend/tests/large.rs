//! No size limits: a POU of a million IL lines generates C in time and memory linear in its size.

use c_backend::{Options, TargetProfile};
use diagnostics::{Diagnostics, FileId, Span};
use il_frontend::ast::*;
use std::time::Instant;

fn sp(i: usize) -> Span {
    Span::new(FileId(0), i, i + 1)
}

fn var(name: &str, i: usize) -> Operand {
    Operand::Var(VarRef {
        base: Ident::new(name, sp(i)),
        accessors: Default::default(),
        span: sp(i),
    })
}

fn int(v: i128, i: usize) -> Operand {
    Operand::literal(Literal {
        kind: LiteralKind::Int(v),
        type_prefix: None,
        span: sp(i),
    })
}

fn simple(op: Op, operand: Option<Operand>, i: usize) -> IlStmt {
    IlStmt::Instr(Instruction {
        kind: InstrKind::Simple {
            op,
            negate: false,
            operand,
        },
        span: sp(i),
    })
}

/// `lines` IL lines: LD x / ADD 1 / ST x / LD x / GT 5 / JMPC l<k> / l<k>: ..., all distinct spans.
fn big_program(lines: usize) -> CompilationUnit {
    let mut body = Vec::with_capacity(lines);
    let mut i = 1000;
    let mut k = 0;
    while body.len() < lines {
        i += 10;
        match body.len() % 8 {
            0 => body.push(simple(Op::Ld, Some(var("x", i)), i)),
            1 => body.push(simple(Op::Add, Some(int(1, i + 1)), i)),
            2 => body.push(simple(Op::St, Some(var("x", i)), i)),
            3 => body.push(simple(Op::Ld, Some(var("x", i)), i)),
            4 => body.push(simple(Op::Gt, Some(int(5, i + 1)), i)),
            5 => body.push(IlStmt::Instr(Instruction {
                kind: InstrKind::Jump {
                    cond: Condition::IfTrue,
                    label: Ident::new(format!("l{k}"), sp(i + 1)),
                },
                span: sp(i),
            })),
            6 => {
                body.push(IlStmt::Label(Ident::new(format!("l{k}"), sp(i))));
                k += 1;
            }
            _ => body.push(simple(Op::Ld, Some(var("y", i)), i)),
        }
    }
    let decl = |name: &str, i: usize| VarDecl {
        name: Ident::new(name, sp(i)),
        location: None,
        ty: TypeRef::Named(Ident::new("INT", sp(i + 1))),
        init: None,
        edge: None,
        span: sp(i),
    };
    CompilationUnit {
        items: vec![LibraryElement::Pou(Pou {
            class: false,
            kind: PouKind::Program,
            name: Ident::new("big", sp(1)),
            return_type: None,
            var_blocks: vec![VarBlock {
                access: None,
                name: None,
                kind: VarKind::Local,
                constant: false,
                retain: false,
                vars: vec![decl("x", 10), decl("y", 20)],
                span: sp(5),
            }],
            body,
            span: sp(0),
        })],
        ..Default::default()
    }
}

fn generate_lines(lines: usize) -> (usize, f64, f64) {
    let units = vec![big_program(lines)];
    let mut diags = Diagnostics::new();
    let t0 = Instant::now();
    let model = il_frontend::sema::analyze(&units, &mut diags);
    let sema_s = t0.elapsed().as_secs_f64();
    assert!(!diags.has_errors(), "{:?}", diags.iter().next());
    let t1 = Instant::now();
    let p = c_backend::generate(
        &units,
        &model,
        &TargetProfile::default(),
        &Options::default(),
        &mut diags,
    )
    .expect("generates");
    let gen_s = t1.elapsed().as_secs_f64();
    let c = p.file("program.c").unwrap();
    // every IL line left a trace: 3 stores per 8 lines (2 ST + ... ) - check the labels and stores
    assert!(c.matches("self->v_x = cr_INT;").count() >= lines / 8);
    assert!(c.contains(&format!("L_l{}:;", lines / 8 - 1)));
    (c.len(), sema_s, gen_s)
}

#[test]
fn fifty_thousand_lines_generate_quickly() {
    let (len, sema_s, gen_s) = generate_lines(50_000);
    eprintln!("50k lines: {len} bytes of C, sema {sema_s:.3}s, generate {gen_s:.3}s");
    assert!(len < 50_000 * 200, "output grows linearly");
}

#[test]
#[cfg_attr(debug_assertions, ignore)]
fn a_million_lines_in_one_pou_generate_c() {
    let (len, sema_s, gen_s) = generate_lines(1_000_000);
    eprintln!("1M lines: {len} bytes of C, sema {sema_s:.3}s, generate {gen_s:.3}s");
    assert!(len < 1_000_000 * 200);
}

/// The parser's generator of valid programs: parsed, analysed, generated, compiled strictly and run.
#[test]
fn generated_programs_compile_strictly_and_run() {
    let src = il_frontend::testgen::generate(1000, 3);
    let mut map = diagnostics::SourceMap::new();
    let file = map.add("gen.il", src.clone());
    let mut diags = Diagnostics::new();
    let units = vec![il_frontend::parse(file, &src, &mut diags)];
    let model = il_frontend::sema::analyze(&units, &mut diags);
    assert!(!diags.has_errors());
    let p = c_backend::generate(
        &units,
        &model,
        &TargetProfile::default(),
        &Options::default(),
        &mut diags,
    )
    .expect("generates");
    let dir = tempfile::tempdir().unwrap();
    let opts = c_backend::BuildOptions {
        cc: None,
        extra_flags: [
            "-Wall",
            "-Wextra",
            "-Werror",
            "-O0",
            "-fsanitize=undefined",
            "-fno-sanitize-recover=all",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect(),
    };
    let exe = c_backend::build_with(&p, dir.path(), &opts).expect("builds");
    let out = c_backend::run(
        &exe,
        &c_backend::RunOptions {
            cycles: 50,
            watch: vec!["P0.n0".into(), "P2.b3".into()],
            ..Default::default()
        },
    )
    .unwrap();
    assert!(out.success(), "{}", out.stderr);
    assert!(!out.stderr.contains("runtime error"), "{}", out.stderr);
    assert_eq!(out.stdout.lines().count(), 51);
}

#[test]
fn deeply_nested_deferred_operators_generate_without_recursion() {
    let depth = 1500;
    let mut src = String::from("PROGRAM deep\nVAR\n  a : BOOL;\n  q : BOOL;\nEND_VAR\n  LD a\n");
    for _ in 0..depth {
        src.push_str("  OR( a\n");
    }
    for _ in 0..depth {
        src.push_str("  )\n");
    }
    src.push_str("  ST q\nEND_PROGRAM\n");
    // the front end recurses on nesting: give it a large stack
    let (units, model) = std::thread::Builder::new()
        .stack_size(1 << 30)
        .spawn(move || {
            let mut map = diagnostics::SourceMap::new();
            let file = map.add("deep.il", src.clone());
            let mut diags = Diagnostics::new();
            let units = vec![il_frontend::parse(file, &src, &mut diags)];
            let model = il_frontend::sema::analyze(&units, &mut diags);
            assert!(!diags.has_errors());
            (units, model)
        })
        .unwrap()
        .join()
        .unwrap();
    // the generator walks nested lists with its own stack: a small thread stack is enough
    let c = std::thread::Builder::new()
        .stack_size(256 * 1024)
        .spawn(move || {
            let mut diags = Diagnostics::new();
            let p = c_backend::generate(
                &units,
                &model,
                &TargetProfile::default(),
                &Options::default(),
                &mut diags,
            )
            .expect("generates");
            let c = p.file("program.c").unwrap().to_string();
            std::mem::forget(units); // dropping the deep tree recurses too; not the generator's concern
            std::mem::forget(model);
            c
        })
        .unwrap()
        .join()
        .unwrap();
    assert!(c.contains(&format!("d_{depth} = cr_BOOL;")));
    assert_eq!(c.matches("d_1 = cr_BOOL;").count(), 1);
}
