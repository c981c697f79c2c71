//! Configurations: tasks with intervals and priorities drive the scan; programs without a task run
//! every cycle.

mod support;
use c_backend::{Options, TargetProfile};
use il_frontend::ast::*;
use support::*;

fn ident(file: diagnostics::FileId, name: &str) -> Ident {
    Ident::new(name, diagnostics::Span::new(file, 0, 0))
}

fn task(file: diagnostics::FileId, name: &str, interval_ms: Option<i128>, priority: u32) -> Task {
    let sp = diagnostics::Span::new(file, 0, 0);
    Task {
        name: ident(file, name),
        interval: interval_ms.map(|ms| {
            Operand::literal(Literal {
                kind: LiteralKind::Duration(ms * 1_000_000),
                type_prefix: None,
                span: sp,
            })
        }),
        single: None,
        priority: Some(priority),
        span: sp,
    }
}

fn instance(
    file: diagnostics::FileId,
    name: &str,
    task: Option<&str>,
    ty: &str,
) -> ProgramInstance {
    ProgramInstance {
        name: ident(file, name),
        retain: false,
        task: task.map(|t| ident(file, t)),
        type_name: ident(file, ty),
        args: Vec::new(),
        span: diagnostics::Span::new(file, 0, 0),
    }
}

fn configuration(
    file: diagnostics::FileId,
    tasks: Vec<Task>,
    programs: Vec<ProgramInstance>,
    globals: Vec<VarBlock>,
) -> LibraryElement {
    let sp = diagnostics::Span::new(file, 0, 0);
    LibraryElement::Configuration(Configuration {
        name: ident(file, "cfg"),
        access: Vec::new(),
        globals,
        resources: vec![Resource {
            name: ident(file, "res"),
            on: Some(ident(file, "PLC")),
            globals: Vec::new(),
            tasks,
            programs,
            span: sp,
        }],
        span: sp,
    })
}

const COUNTER: &str = "PROGRAM counter
VAR
  n : INT;
END_VAR
  LD n
  ADD 1
  ST n
END_PROGRAM
";

#[test]
fn a_task_of_interval_20ms_at_cycle_10ms_runs_every_second_cycle() {
    let (units, model, map) = frontend_with(COUNTER, |u, f| {
        u.items.push(configuration(
            f,
            vec![task(f, "slow", Some(20), 2), task(f, "fast", Some(10), 1)],
            vec![
                instance(f, "a", Some("slow"), "counter"),
                instance(f, "b", Some("fast"), "counter"),
                instance(f, "c", None, "counter"),
            ],
            Vec::new(),
        ))
    });
    let p = generate_with(
        &units,
        &model,
        &map,
        &TargetProfile::default(),
        &Options::default(),
    );
    let b = build_program(p);
    let rows = run(&b, 8, 10.0, "", &["a.n", "b.n", "c.n"]);
    assert_eq!(
        column(&rows, "a.n"),
        ["1", "1", "2", "2", "3", "3", "4", "4"]
    );
    assert_eq!(
        column(&rows, "b.n"),
        ["1", "2", "3", "4", "5", "6", "7", "8"]
    );
    assert_eq!(
        column(&rows, "c.n"),
        ["1", "2", "3", "4", "5", "6", "7", "8"]
    );
    // with a 5 ms cycle the 20 ms task runs every fourth cycle and the 10 ms task every second
    let rows = run(&b, 8, 5.0, "", &["a.n", "b.n"]);
    assert_eq!(
        column(&rows, "a.n"),
        ["1", "1", "1", "1", "2", "2", "2", "2"]
    );
    assert_eq!(
        column(&rows, "b.n"),
        ["1", "1", "2", "2", "3", "3", "4", "4"]
    );
    // with a 30 ms cycle (slower than both tasks) every task runs every cycle
    let rows = run(&b, 3, 30.0, "", &["a.n", "b.n"]);
    assert_eq!(column(&rows, "a.n"), ["1", "2", "3"]);
}

#[test]
fn tasks_run_in_priority_order() {
    let src = "PROGRAM first
VAR_EXTERNAL
  log : DINT;
END_VAR
  LD log
  MUL 10
  ADD 1
  ST log
END_PROGRAM
PROGRAM second
VAR_EXTERNAL
  log : DINT;
END_VAR
  LD log
  MUL 10
  ADD 2
  ST log
END_PROGRAM
";
    let (units, model, map) = frontend_with(src, |u, f| {
        let sp = diagnostics::Span::new(f, 0, 0);
        let globals = vec![VarBlock {
            access: None,
            name: None,
            kind: VarKind::Global,
            constant: false,
            retain: false,
            vars: vec![VarDecl {
                name: ident(f, "log"),
                location: None,
                ty: TypeRef::Named(ident(f, "DINT")),
                init: None,
                edge: None,
                span: sp,
            }],
            span: sp,
        }];
        u.items.push(configuration(
            f,
            vec![
                task(f, "t_low", Some(10), 5),
                task(f, "t_high", Some(10), 0),
            ],
            vec![
                instance(f, "p1", Some("t_low"), "first"),
                instance(f, "p2", Some("t_high"), "second"),
            ],
            globals,
        ))
    });
    let p = generate_with(
        &units,
        &model,
        &map,
        &TargetProfile::default(),
        &Options::default(),
    );
    let b = build_program(p);
    let rows = run(&b, 2, 10.0, "", &["log"]);
    // priority 0 (second, +2) before priority 5 (first, +1)
    assert_eq!(column(&rows, "log"), ["21", "2121"]);
}

#[test]
fn without_a_configuration_every_program_runs_each_cycle_in_source_order() {
    let src = "VAR_GLOBAL
  trace : DINT;
END_VAR
PROGRAM zeta
  LD trace
  MUL 10
  ADD 1
  ST trace
END_PROGRAM
PROGRAM alpha
  LD trace
  MUL 10
  ADD 2
  ST trace
END_PROGRAM
";
    let b = build_src(src);
    let rows = run(&b, 2, 10.0, "", &["trace"]);
    assert_eq!(column(&rows, "trace"), ["12", "1212"]);
}

fn global(f: diagnostics::FileId, name: &str, ty: &str, init: Option<i128>) -> VarDecl {
    let sp = diagnostics::Span::new(f, 0, 0);
    VarDecl {
        name: ident(f, name),
        location: None,
        ty: TypeRef::Named(ident(f, ty)),
        init: init.map(|v| {
            Initializer::Value(Operand::literal(Literal {
                kind: LiteralKind::Int(v),
                type_prefix: None,
                span: sp,
            }))
        }),
        edge: None,
        span: sp,
    }
}

fn globals(f: diagnostics::FileId, vars: Vec<VarDecl>) -> Vec<VarBlock> {
    vec![VarBlock {
        access: None,
        name: None,
        kind: VarKind::Global,
        constant: false,
        retain: false,
        vars,
        span: diagnostics::Span::new(f, 0, 0),
    }]
}

fn var_operand(f: diagnostics::FileId, name: &str) -> Operand {
    Operand::Var(VarRef {
        base: ident(f, name),
        accessors: Default::default(),
        span: diagnostics::Span::new(f, 0, 0),
    })
}

#[test]
fn a_single_task_runs_once_per_rising_edge_of_its_variable() {
    let (units, model, map) = frontend_with(COUNTER, |u, f| {
        let mut t = task(f, "on_event", None, 1);
        t.single = Some(var_operand(f, "trig"));
        u.items.push(configuration(
            f,
            vec![t],
            vec![instance(f, "e", Some("on_event"), "counter")],
            globals(f, vec![global(f, "trig", "BOOL", None)]),
        ))
    });
    let p = generate_with(
        &units,
        &model,
        &map,
        &TargetProfile::default(),
        &Options::default(),
    );
    let b = build_program(p);
    let stim = "1,trig,1\n3,trig,0\n4,trig,1\n5,trig,0\n6,trig,1\n";
    let rows = run(&b, 8, 10.0, stim, &["e.n"]);
    assert_eq!(
        column(&rows, "e.n"),
        ["0", "1", "1", "1", "2", "2", "3", "3"]
    );
}

#[test]
fn program_instance_arguments_are_copied_in_and_out() {
    let src = "PROGRAM double
VAR_INPUT
  a : INT;
END_VAR
VAR_OUTPUT
  b : INT;
END_VAR
  LD a
  MUL 2
  ST b
END_PROGRAM
";
    let (units, model, map) = frontend_with(src, |u, f| {
        let sp = diagnostics::Span::new(f, 0, 0);
        let mut inst = instance(f, "d", None, "double");
        inst.args = vec![
            FormalArg {
                name: ident(f, "a"),
                dir: ArgDir::Input,
                value: var_operand(f, "src"),
                span: sp,
            },
            FormalArg {
                name: ident(f, "b"),
                dir: ArgDir::Output { negated: false },
                value: var_operand(f, "dst"),
                span: sp,
            },
        ];
        u.items.push(configuration(
            f,
            Vec::new(),
            vec![inst],
            globals(
                f,
                vec![
                    global(f, "src", "INT", Some(5)),
                    global(f, "dst", "INT", None),
                ],
            ),
        ))
    });
    let p = generate_with(
        &units,
        &model,
        &map,
        &TargetProfile::default(),
        &Options::default(),
    );
    let b = build_program(p);
    let rows = run(&b, 3, 10.0, "2,src,-4\n", &["dst", "d.a"]);
    assert_eq!(column(&rows, "dst"), ["10", "10", "-8"]);
    assert_eq!(column(&rows, "d.a"), ["5", "5", "-4"]);
}

#[test]
fn a_configuration_written_in_il_source() {
    let src = "PROGRAM counter
VAR_INPUT
  step : INT;
END_VAR
VAR_OUTPUT
  n : INT;
END_VAR
  LD n
  ADD step
  ST n
END_PROGRAM
CONFIGURATION plant
  VAR_GLOBAL
    total AT %MW10 : INT;
  END_VAR
  RESOURCE cpu ON PLC
    TASK slow (INTERVAL := T#20ms, PRIORITY := 1);
    PROGRAM fast_one : counter (step := 1, n => total);
    PROGRAM slow_one WITH slow : counter (step := 10);
  END_RESOURCE
END_CONFIGURATION
";
    let b = build_src(src);
    let rows = run(
        &b,
        4,
        10.0,
        "",
        &["fast_one.n", "slow_one.n", "total", "%MW10"],
    );
    assert_eq!(column(&rows, "fast_one.n"), ["1", "2", "3", "4"]);
    assert_eq!(column(&rows, "slow_one.n"), ["10", "10", "20", "20"]);
    assert_eq!(column(&rows, "total"), ["1", "2", "3", "4"]);
    assert_eq!(column(&rows, "%MW10"), ["1", "2", "3", "4"]);
}

#[test]
fn a_task_interval_given_by_a_variable_is_read_every_cycle() {
    let src = "PROGRAM counter
VAR
  n : INT;
END_VAR
  LD n
  ADD 1
  ST n
END_PROGRAM
CONFIGURATION plant
  VAR_GLOBAL
    period : TIME := T#30ms;
  END_VAR
  RESOURCE cpu ON PLC
    TASK t (INTERVAL := period, PRIORITY := 1);
    PROGRAM c WITH t : counter;
  END_RESOURCE
END_CONFIGURATION
";
    let b = build_src(src);
    // 30 ms at a 10 ms cycle: cycles 0, 3, 6; from cycle 6 the period is 0 (every cycle)
    let rows = run(&b, 9, 10.0, "6,period,T#0ms\n", &["c.n"]);
    assert_eq!(
        column(&rows, "c.n"),
        ["1", "1", "1", "2", "2", "2", "3", "4", "5"]
    );
}
