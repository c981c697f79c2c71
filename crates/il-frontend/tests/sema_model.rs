//! The resolved model: per-instruction current-result types, callees and argument bindings, POU
//! variables, configurations.

mod sema_support;
use il_frontend::ast::{self, PouKind, VarKind};
use il_frontend::sema::*;
use sema_support::analyze_src;

/// The info of the instruction that starts at the `n`-th occurrence (0-based) of `text` in `src`.
fn info_at<'m>(model: &'m Model, src: &str, text: &str, n: usize) -> InstrRef<'m> {
    let start = src
        .match_indices(text)
        .nth(n)
        .unwrap_or_else(|| panic!("`{text}` #{n} not in source"))
        .0 as u32;
    model
        .instrs
        .iter()
        .find(|(_, i)| i.span.start == start)
        .map(|(_, i)| i)
        .unwrap_or_else(|| panic!("no instruction at `{text}`"))
}

fn ok(src: &str) -> Model {
    let (m, d) = analyze_src(src);
    assert!(d.is_empty(), "unexpected diagnostics:\n{d}");
    m
}

const INT: Type = Type::INT;

#[test]
fn integer_literal_takes_the_type_of_the_other_operand() {
    let src = "PROGRAM P
VAR
  x : INT;
END_VAR
  LD 5
  ADD x
  ST x
END_PROGRAM
";
    let m = ok(src);
    let ld = info_at(&m, src, "LD 5", 0);
    assert_eq!(ld.cr_before, None);
    assert_eq!(ld.cr_after, Some(INT));
    assert_eq!(ld.operand, Some(INT));
    let add = info_at(&m, src, "ADD x", 0);
    assert_eq!(add.cr_before, Some(INT));
    assert_eq!(add.cr_after, Some(INT));
    assert_eq!(
        add.callee,
        Some(Callee::Std {
            name: "ADD",
            ty: INT,
            result: INT
        })
    );
}

#[test]
fn widening_gives_the_wider_type_and_comparisons_give_bool() {
    let src = "PROGRAM P
VAR
  i : INT;
  d : DINT;
  b : BOOL;
END_VAR
  LD i
  ADD d
  GT 100
  ST b
END_PROGRAM
";
    let m = ok(src);
    let add = info_at(&m, src, "ADD d", 0);
    assert_eq!(add.cr_after, Some(Type::DINT));
    let gt = info_at(&m, src, "GT 100", 0);
    assert_eq!(gt.operand, Some(Type::DINT));
    assert_eq!(gt.cr_after, Some(Type::BOOL));
    assert_eq!(
        gt.callee,
        Some(Callee::Std {
            name: "GT",
            ty: Type::DINT,
            result: Type::BOOL
        })
    );
}

#[test]
fn unconstrained_literals_default_to_dint_and_lreal() {
    let src = "PROGRAM P
VAR
  b : BOOL;
END_VAR
  LD 5
  EQ 3
  ST b
  LD 2.5
  GT 1.0
  ST b
END_PROGRAM
";
    let m = ok(src);
    assert_eq!(info_at(&m, src, "LD 5", 0).cr_after, Some(Type::DINT));
    assert_eq!(info_at(&m, src, "LD 2.5", 0).cr_after, Some(Type::LREAL));
}

#[test]
fn literal_on_one_path_takes_the_type_brought_by_a_jump() {
    // The end of STACK_INT (IEC 61131-3 Annex F): `ZRO_OUT: LD 0` falls through into a label that a jump
    // reaches with an INT.
    let src = "FUNCTION_BLOCK F
VAR_INPUT
  go : BOOL;
END_VAR
VAR_OUTPUT
  OUT : INT;
END_VAR
VAR
  v : INT;
END_VAR
  LD go
  JMPC ZRO_OUT
  LD v
  JMP SET_OUT
ZRO_OUT: LD 0
SET_OUT: ST OUT
END_FUNCTION_BLOCK
";
    let m = ok(src);
    assert_eq!(info_at(&m, src, "LD 0", 0).cr_after, Some(INT));
    assert_eq!(info_at(&m, src, "ST OUT", 0).cr_before, Some(INT));
    // After an unconditional jump the current result is undefined.
    assert_eq!(info_at(&m, src, "JMP SET_OUT", 0).cr_after, None);
}

#[test]
fn backward_jump_brings_its_type_to_the_label() {
    let src = "PROGRAM P
VAR
  n : INT;
  b : BOOL;
END_VAR
  JMP first
again:
  ST b
  LD n
  ST n
first:
  LD n
  GT 10
  JMPC again
END_PROGRAM
";
    let m = ok(src);
    assert_eq!(info_at(&m, src, "ST b", 0).cr_before, Some(Type::BOOL));
}

#[test]
fn function_call_binds_the_current_result_to_the_first_input() {
    let src = "PROGRAM P
VAR
  g : BOOL;
  a, b : INT;
END_VAR
  LD g
  SEL a, b
  ST a
  LD a
  LIMIT 0, 10
  ST a
  LIMIT(MN := 0, IN := b, MX := 5)
  ST b
END_PROGRAM
";
    let m = ok(src);
    let sel = info_at(&m, src, "SEL a, b", 0);
    assert_eq!(sel.cr_after, Some(INT));
    let params: Vec<(&str, &Type, &ArgSource)> = sel
        .args
        .iter()
        .map(|a| (a.param.as_str(), &a.ty, &a.source))
        .collect();
    assert_eq!(
        params,
        vec![
            ("G", &Type::BOOL, &ArgSource::CurrentResult),
            ("IN0", &INT, &ArgSource::Written(0)),
            ("IN1", &INT, &ArgSource::Written(1)),
        ]
    );
    let lim = info_at(&m, src, "LIMIT 0, 10", 0);
    assert_eq!(lim.args.len(), 3);
    assert!(lim.args.iter().all(|a| a.ty == INT));
    let formal = info_at(&m, src, "LIMIT(MN", 0);
    assert_eq!(formal.cr_after, Some(INT));
    assert_eq!(
        formal
            .args
            .iter()
            .map(|a| a.param.as_str())
            .collect::<Vec<_>>(),
        vec!["MN", "IN", "MX"]
    );
    assert!(formal
        .args
        .iter()
        .all(|a| matches!(a.source, ArgSource::Written(_))));
}

#[test]
fn conversions_bcd_and_time_arithmetic() {
    let src = "FUNCTION WEIGH : WORD
VAR_INPUT
  gross : WORD;
  tare : INT;
  t : TIME;
END_VAR
  LD gross
  BCD_TO_INT
  SUB tare
  INT_TO_BCD
  ST WEIGH
  LD t
  ADD T#1s
  MUL 2
  TIME_TO_DINT
  INT_TO_REAL
END_FUNCTION
";
    let (m, d) = analyze_src(src);
    // INT_TO_REAL of a DINT is the only error.
    assert_eq!(d.matches("error[").count(), 1, "{d}");
    assert!(d.contains("INT_TO_REAL converts from INT, not DINT"), "{d}");
    assert_eq!(
        info_at(&m, src, "BCD_TO_INT", 0).callee,
        Some(Callee::Conversion {
            name: "BCD_TO_INT".into(),
            kind: ConversionKind::FromBcd,
            from: Type::Elementary(Elementary::Word),
            to: INT
        })
    );
    let to_bcd = info_at(&m, src, "INT_TO_BCD", 0);
    assert_eq!(to_bcd.cr_after, Some(Type::Elementary(Elementary::Word)));
    let add = info_at(&m, src, "ADD T#1s", 0);
    assert_eq!(
        add.callee,
        Some(Callee::Std {
            name: "ADD_TIME",
            ty: Type::TIME,
            result: Type::TIME
        })
    );
    assert_eq!(info_at(&m, src, "MUL 2", 0).cr_after, Some(Type::TIME));
    assert_eq!(
        info_at(&m, src, "TIME_TO_DINT", 0).cr_after,
        Some(Type::DINT)
    );
}

#[test]
fn fb_calls_input_operators_and_s_r_on_instances() {
    let src = "PROGRAM P
VAR
  t : TON;
  ff : SR;
  go, q : BOOL;
END_VAR
  CAL t(IN := go, PT := T#2s, Q => q)
  LD go
  S1 ff
  R ff
  IN t
  FUNC Helper()
  ST q
END_PROGRAM
";
    let m = ok(src);
    let cal = info_at(&m, src, "CAL t", 0);
    assert_eq!(
        cal.callee,
        Some(Callee::FbInstance {
            fb: FbType::Standard(StdFb::Ton),
            input: None
        })
    );
    let args: Vec<(&str, bool)> = cal
        .args
        .iter()
        .map(|a| (a.param.as_str(), a.output))
        .collect();
    assert_eq!(args, vec![("IN", false), ("PT", false), ("Q", true)]);
    assert_eq!(
        info_at(&m, src, "R ff", 0).callee,
        Some(Callee::FbInstance {
            fb: FbType::Standard(StdFb::Sr),
            input: Some("R".into())
        })
    );
    assert_eq!(
        info_at(&m, src, "S1 ff", 0).callee,
        Some(Callee::FbInstance {
            fb: FbType::Standard(StdFb::Sr),
            input: Some("S1".into())
        })
    );
    let func = info_at(&m, src, "FUNC Helper", 0);
    assert_eq!(
        func.callee,
        Some(Callee::Embedded {
            name: "Helper".into()
        })
    );
    assert_eq!(func.cr_after, Some(Type::BOOL));
}

#[test]
fn user_function_and_user_fb_are_resolved() {
    let src = "FUNCTION Twice : INT
VAR_INPUT
  v : INT;
END_VAR
  LD v
  MUL 2
  ST Twice
END_FUNCTION
FUNCTION_BLOCK Cnt
VAR_INPUT
  up : BOOL;
END_VAR
VAR_OUTPUT
  n : INT;
END_VAR
VAR
  internal : INT;
END_VAR
  LD n
  Twice
  ST n
END_FUNCTION_BLOCK
PROGRAM P
VAR
  c : Cnt;
  k : INT;
END_VAR
  CAL c(up := TRUE, n => k)
  LD c.n
  ST k
END_PROGRAM
";
    let m = ok(src);
    assert_eq!(m.pous.len(), 3);
    assert_eq!(m.pou(PouId(0)).kind, PouKind::Function);
    assert_eq!(m.pou(PouId(0)).return_type, Some(INT));
    let tw = info_at(&m, src, "Twice\n", 1);
    assert_eq!(tw.callee, Some(Callee::UserFunction(PouId(0))));
    assert_eq!(tw.cr_after, Some(INT));
    let prog = m.pou(PouId(2));
    assert_eq!(prog.var("c").unwrap().ty, Type::Fb(FbType::User(PouId(1))));
    let cal = info_at(&m, src, "CAL c", 0);
    assert_eq!(
        cal.callee,
        Some(Callee::FbInstance {
            fb: FbType::User(PouId(1)),
            input: None
        })
    );
}

#[test]
fn variables_keep_kind_type_init_location_and_flags() {
    let src = "TYPE
  Color : (red, green, blue);
  Percent : INT (0..100);
END_TYPE
PROGRAM P
VAR_INPUT
  start : BOOL;
END_VAR
VAR CONSTANT
  limit : INT := 42;
END_VAR
VAR RETAIN
  count : DINT := -7;
  lamp AT %QX0.1 : BOOL;
  buf : ARRAY [0..3] OF INT := [1, 2, 3];
  name : STRING[10] := 'abc';
  col : Color := green;
  pct : Percent;
  t : TON := (PT := T#1s);
END_VAR
  LD start
  ST lamp
END_PROGRAM
";
    let m = ok(src);
    let p = m.pou(PouId(0));
    let names: Vec<(&str, VarKind)> = p.vars.iter().map(|v| (v.name.as_str(), v.kind)).collect();
    assert_eq!(names[0], ("start", VarKind::Input));
    let limit = p.var("LIMIT").unwrap();
    assert!(limit.constant);
    assert_eq!(limit.init, Some(ConstValue::Int(42)));
    let count = p.var("count").unwrap();
    assert!(count.retain);
    assert_eq!(count.init, Some(ConstValue::Int(-7)));
    let lamp = p.var("lamp").unwrap();
    assert_eq!(
        lamp.location,
        Some(Location {
            area: ast::Area::Output,
            size: ast::AddressSize::Bit,
            path: vec![0, 1]
        })
    );
    assert_eq!(
        p.var("buf").unwrap().ty,
        Type::Array {
            dims: vec![Dim { lower: 0, upper: 3 }],
            element: Box::new(INT)
        }
    );
    assert_eq!(
        p.var("buf").unwrap().init,
        Some(ConstValue::Array(vec![
            ConstValue::Int(1),
            ConstValue::Int(2),
            ConstValue::Int(3)
        ]))
    );
    assert_eq!(
        p.var("name").unwrap().ty,
        Type::String {
            wide: false,
            len: 10
        }
    );
    let color = m.type_by_name("color").unwrap();
    assert_eq!(
        p.var("col").unwrap().init,
        Some(ConstValue::Enum {
            ty: color,
            index: 1
        })
    );
    assert_eq!(
        p.var("pct").unwrap().ty,
        Type::Subrange {
            base: Elementary::Int,
            lower: Box::new(0),
            upper: Box::new(100)
        }
    );
    assert_eq!(
        p.var("t").unwrap().init,
        Some(ConstValue::Struct(vec![(
            "PT".into(),
            ConstValue::Duration(1_000_000_000)
        )]))
    );
}

#[test]
fn configuration_tasks_and_program_instances() {
    use il_frontend::Span;
    let s = Span::default;
    let id = |n: &str| ast::Ident::new(n, s());
    let prog = ast::Pou {
        class: false,
        kind: PouKind::Program,
        name: id("Main"),
        return_type: None,
        var_blocks: vec![ast::VarBlock {
            access: None,
            name: None,
            kind: VarKind::External,
            constant: false,
            retain: false,
            vars: vec![ast::VarDecl {
                name: id("speed"),
                location: None,
                ty: ast::TypeRef::Named(id("REAL")),
                init: None,
                edge: None,
                span: s(),
            }],
            span: s(),
        }],
        body: vec![],
        span: s(),
    };
    let config = ast::Configuration {
        name: id("Cell"),
        access: Vec::new(),
        globals: vec![ast::VarBlock {
            access: None,
            name: None,
            kind: VarKind::Global,
            constant: false,
            retain: false,
            vars: vec![ast::VarDecl {
                name: id("speed"),
                location: None,
                ty: ast::TypeRef::Named(id("REAL")),
                init: None,
                edge: None,
                span: s(),
            }],
            span: s(),
        }],
        resources: vec![ast::Resource {
            name: id("Cpu"),
            on: None,
            globals: vec![],
            tasks: vec![ast::Task {
                name: id("Fast"),
                interval: Some(ast::Operand::literal(ast::Literal {
                    kind: ast::LiteralKind::Duration(10_000_000),
                    type_prefix: None,
                    span: s(),
                })),
                single: None,
                priority: Some(1),
                span: s(),
            }],
            programs: vec![ast::ProgramInstance {
                name: id("main1"),
                retain: false,
                task: Some(id("fast")),
                type_name: id("MAIN"),
                args: vec![],
                span: s(),
            }],
            span: s(),
        }],
        span: s(),
    };
    let units = [ast::CompilationUnit {
        items: vec![
            ast::LibraryElement::Pou(prog),
            ast::LibraryElement::Configuration(config),
        ],
        ..Default::default()
    }];
    let mut diags = diagnostics::Diagnostics::new();
    let m = analyze(&units, &mut diags);
    assert!(diags.is_empty(), "{:?}", diags);
    let r = &m.configurations[0].resources[0];
    assert_eq!(r.tasks[0].interval_ns, Some(10_000_000));
    assert_eq!(r.tasks[0].priority, 1);
    assert_eq!(r.programs[0].pou, PouId(0));
    assert_eq!(r.programs[0].task, Some(0));
    assert_eq!(
        m.pou(PouId(0)).externals,
        vec![(
            0,
            GlobalRef::Configuration {
                config: 0,
                index: 0
            }
        )]
    );
}

#[test]
fn several_units_share_one_namespace() {
    let a = "FUNCTION_BLOCK Helper
VAR_OUTPUT
  q : BOOL;
END_VAR
  LD TRUE
  ST q
END_FUNCTION_BLOCK
";
    let b = "PROGRAM P
VAR
  h : Helper;
  x : BOOL;
END_VAR
  CAL h
  LD h.q
  ST x
END_PROGRAM
";
    let mut map = diagnostics::SourceMap::new();
    let fa = map.add("a.il", a);
    let fb = map.add("b.il", b);
    let mut diags = diagnostics::Diagnostics::new();
    let units = [
        sema_support::read(fa, a, &mut diags),
        sema_support::read(fb, b, &mut diags),
    ];
    let m = analyze(&units, &mut diags);
    assert!(diags.is_empty(), "{:?}", diags);
    assert_eq!(
        m.pou(PouId(1)).var("h").unwrap().ty,
        Type::Fb(FbType::User(PouId(0)))
    );
}

#[test]
fn pou_instrs_are_in_source_pre_order() {
    let src = "PROGRAM P
VAR
  a, b, c, x : BOOL;
END_VAR
  LD a
  AND( b
  OR c
  )
  ST x
END_PROGRAM
";
    let m = ok(src);
    let p = m.pou(PouId(0));
    assert_eq!(p.instrs.len(), 4);
    let deferred = info_at(&m, src, "AND(", 0);
    assert_eq!(m.instr_by_id(p.instrs[1]).unwrap(), deferred);
    assert_eq!(deferred.operand, Some(Type::BOOL));
    assert_eq!(
        m.instr_by_id(p.instrs[2]).unwrap(),
        info_at(&m, src, "OR c", 0)
    );
    // The nested list starts with its operand as current result.
    assert_eq!(info_at(&m, src, "OR c", 0).cr_before, Some(Type::BOOL));
}

#[test]
fn names_in_bodies_are_resolved() {
    let src = "TYPE
  Color : (red, green);
END_TYPE
VAR_GLOBAL
  total : INT;
END_VAR
FUNCTION F : Color
VAR_INPUT
  go : BOOL;
END_VAR
  LD go
  ST ENO
  LD total
  ADD 1
  ST total
  LD green
  ST F
END_FUNCTION
";
    let m = ok(src);
    let at = |text: &str, n: usize| {
        let start = src.match_indices(text).nth(n).unwrap().0 as u32;
        *m.names.iter().find(|(s, _)| s.start == start).unwrap().1
    };
    assert_eq!(at("go\n", 0), NameRef::Var(0));
    assert_eq!(at("ENO", 0), NameRef::Eno);
    assert_eq!(at("total\n", 1), NameRef::Global(GlobalRef::Free(0)));
    let color = m.type_by_name("Color").unwrap();
    assert_eq!(
        at("green\n", 0),
        NameRef::EnumValue {
            ty: color,
            index: 1
        }
    );
    assert_eq!(at("F\nEND", 0), NameRef::FunctionResult);
    assert_eq!(m.pou(PouId(0)).return_type, Some(Type::Enum(color)));
}

#[test]
fn program_instance_arguments_are_bound_to_globals_and_addresses() {
    let src = "PROGRAM Main
VAR_INPUT
  sp : REAL;
  n : INT;
END_VAR
VAR_OUTPUT
  q : BOOL;
END_VAR
  LD sp
  GT 1.5
  ST q
END_PROGRAM
CONFIGURATION Cell
VAR_GLOBAL
  speed : REAL;
END_VAR
RESOURCE Cpu
TASK Fast(INTERVAL := T#10ms, PRIORITY := 3);
PROGRAM m1 WITH Fast : Main (sp := speed, n := 7, q => %QX0.1);
END_RESOURCE
END_CONFIGURATION
";
    let m = ok(src);
    let r = &m.configurations[0].resources[0];
    assert_eq!(r.tasks[0].interval_ns, Some(10_000_000));
    assert_eq!(r.tasks[0].priority, 3);
    let p = &r.programs[0];
    assert_eq!((p.pou, p.task), (PouId(0), Some(0)));
    assert_eq!(
        p.args,
        vec![
            ProgramArg {
                param: 0,
                output: false,
                value: ProgramArgValue::Global(GlobalRef::Configuration {
                    config: 0,
                    index: 0
                })
            },
            ProgramArg {
                param: 1,
                output: false,
                value: ProgramArgValue::Const(ConstValue::Int(7))
            },
            ProgramArg {
                param: 2,
                output: true,
                value: ProgramArgValue::Address(Location {
                    area: ast::Area::Output,
                    size: ast::AddressSize::Bit,
                    path: vec![0, 1]
                })
            },
        ]
    );
}

/// The facts of every instruction are kept for the whole compilation (about 80,000 of them in the
/// 100,000-line benchmark): their size is the compiler's peak memory (issue #16's 600 B per line).
/// Instructions with equal facts share one stored copy, so the table holds only a few of them.
#[test]
fn per_instruction_facts_stay_small() {
    use std::mem::size_of;
    assert!(
        size_of::<Type>() <= 32,
        "Type is {} bytes",
        size_of::<Type>()
    );
    let src = il_frontend::testgen::generate(1000, 3);
    let (m, d) = analyze_src(&src);
    assert!(d.is_empty(), "{d}");
    assert!(m.instrs.len() > 1000, "{} instructions", m.instrs.len());
    // Every instruction still has its own span ...
    let spans: std::collections::HashSet<_> = m.instrs.values().map(|i| i.span).collect();
    assert_eq!(spans.len(), m.instrs.len());
    // ... but the facts are stored once per distinct value: the generated program has a few dozen.
    assert!(
        m.instrs.distinct_facts() < 100,
        "{} distinct facts for {} instructions",
        m.instrs.distinct_facts(),
        m.instrs.len()
    );
    // Same facts, same storage: two `ST b<n>` of a BOOL.
    let st: Vec<_> = m
        .instrs
        .values()
        .filter(|i| i.cr_before == Some(Type::BOOL) && i.cr_after == Some(Type::BOOL))
        .filter(|i| i.callee.is_none() && i.args.is_empty() && i.operand == Some(Type::BOOL))
        .take(2)
        .collect();
    assert_eq!(st.len(), 2);
    assert!(std::ptr::eq(st[0].facts, st[1].facts));
    assert_ne!(st[0].span, st[1].span);
}

/// Every operator of a body calls the standard function of its own name, the first time and after
/// (sema looks each operator's function up once).
#[test]
fn each_operator_calls_its_own_standard_function_every_time() {
    let ops = [
        "ADD", "SUB", "MUL", "DIV", "MOD", "GT", "GE", "EQ", "NE", "LE", "LT", "AND", "OR", "XOR",
    ];
    let mut src = String::from("PROGRAM P\nVAR\n  i : INT;\n  w : WORD;\n  b : BOOL;\nEND_VAR\n");
    for round in 0..2 {
        for op in ops {
            let (load, operand) = if matches!(op, "AND" | "OR" | "XOR") {
                ("w", "w")
            } else {
                ("i", "i")
            };
            src.push_str(&format!(
                "  LD {load}\n  {op} {operand} (* {op}{round} *)\n  ST b\n"
            ));
        }
    }
    src.push_str("END_PROGRAM\n");
    let (m, _) = analyze_src(&src);
    for round in 0..2 {
        for op in ops {
            let operand = if matches!(op, "AND" | "OR" | "XOR") {
                "w"
            } else {
                "i"
            };
            let at = src
                .find(&format!("{op} {operand} (* {op}{round} *)"))
                .expect("in the source") as u32;
            let info = m
                .instrs
                .values()
                .find(|i| i.span.start == at)
                .unwrap_or_else(|| panic!("no instruction at {op} #{round}"));
            match &info.callee {
                Some(Callee::Std { name, .. }) => assert_eq!(*name, op, "#{round}"),
                other => panic!("{op} #{round}: {other:?}"),
            }
        }
    }
}

/// The model for code generation (`analyze_for_code`) is the full model but for the name table, which
/// keeps only the uses of a function's name as its result; the diagnostics are the same, W1003 (a
/// function that never sets its result, found through that table) included.
#[test]
fn the_model_for_code_is_the_full_model_without_the_name_table() {
    let src = "FUNCTION Twice : INT
VAR_INPUT
  v : INT;
END_VAR
  LD v
  MUL 2
  ST Twice
END_FUNCTION
FUNCTION Never : INT
VAR_INPUT
  v : INT;
END_VAR
  LD v
END_FUNCTION
PROGRAM P
VAR
  x : INT;
  t : TON;
  b : BOOL;
END_VAR
  LD x
  Twice
  ADD 1
  ST x
  CAL t(IN := b, PT := T#5ms, Q => b)
END_PROGRAM
";
    let mut map = diagnostics::SourceMap::new();
    let file = map.add("test.il", src.to_string());
    let mut parse_diags = diagnostics::Diagnostics::new();
    let units = [il_frontend::parse(file, src, &mut parse_diags)];
    assert!(parse_diags.is_empty());
    let mut full_diags = diagnostics::Diagnostics::new();
    let full = analyze(&units, &mut full_diags);
    let mut code_diags = diagnostics::Diagnostics::new();
    let code = analyze_for_code(&units, &mut code_diags);
    let rendered = |d: diagnostics::Diagnostics| diagnostics::render_human(&map, &d.into_sorted());
    let full_rendered = rendered(full_diags);
    assert!(full_rendered.contains("W1003"), "{full_rendered}");
    assert!(!full_rendered.contains("`Twice` never"), "{full_rendered}");
    assert_eq!(rendered(code_diags), full_rendered);
    let without_names = |m: &Model| {
        let mut m = m.clone();
        m.names = Default::default();
        format!("{m:?}")
    };
    assert_eq!(without_names(&code), without_names(&full));
    assert!(full.names.len() >= 8, "{}", full.names.len());
    let results: Vec<_> = full
        .names
        .iter()
        .filter(|(_, r)| **r == NameRef::FunctionResult)
        .collect();
    assert_eq!(results.len(), 1);
    assert_eq!(code.names.iter().collect::<Vec<_>>(), results);
}
