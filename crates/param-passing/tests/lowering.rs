//! Lowering of block calls by both strategies, checked through the IL front end: the user's program is
//! type-checked against the block prelude, lowered, printed as IL, and the lowered program checks clean.

use diagnostics::{render, Diagnostics, MessageFormat, SourceMap};
use il_frontend::ast::CompilationUnit;
use param_passing::library::Library;
use param_passing::lower::{self, Method, Strategy, TmWindow};
use param_passing::prelude;

const TEMPLATE: &str = r#"<blockTemplate name="MC_Demo" funcNum="7">
  <parameters>
    <param name="Axis" abbr="Ax" direction="inout" class="struct" type="AXIS_REF" required="true"/>
    <param name="Execute" abbr="Ex" direction="input" class="bool" type="BOOL" required="true"/>
    <param name="Position" abbr="Pos" direction="input" class="lreal" type="LREAL" required="true"/>
    <param name="BufferMode" abbr="BM" direction="input" class="byte" type="MC_BUFFER_MODE" default="0"/>
    <param name="Done" abbr="Dn" direction="output" class="bool" type="BOOL"/>
    <param name="ErrorID" abbr="EID" direction="output" class="word" type="WORD"/>
    <param name="State0" abbr="St0" direction="state" class="lword" type="LWORD"/>
  </parameters>
  <body><![CDATA[
    Dn = (uint8_t)(Ex && Pos > 0.0 && Ax == 1u && BM == 0);
    EID = 0;
    St0 = (uint64_t)FuncNum;
  ]]></body>
</blockTemplate>"#;

const PROGRAM: &str = "PROGRAM main
VAR
    ax1 : AXIS_REF := (AxisNo := 1);
    mv : MC_Demo;
    go : BOOL;
    at_target : BOOL;
    err : WORD;
END_VAR
    CAL mv(Axis := ax1, Execute := go, Position := 100.0, Done => at_target, ErrorID => err)
    LD mv.Done
    ST go
END_PROGRAM
";

const WINDOW: TmWindow = TmWindow {
    offset: 3840,
    bytes: 256,
    element_addressing: true,
};

struct Setup {
    map: SourceMap,
    lib: Library,
    units: Vec<CompilationUnit>,
    diags: Diagnostics,
}

fn setup(program: &str) -> Setup {
    let mut map = SourceMap::new();
    let mut diags = Diagnostics::new();
    let mut lib = Library::new();
    lib.add_text(&mut map, "templates/MC_Demo.xml", TEMPLATE, &mut diags);
    let pre = prelude::before_lowering(&lib);
    let pf = map.add("<blocks>", pre.clone());
    let uf = map.add("main.il", program);
    let units = vec![
        il_frontend::parse(pf, &pre, &mut diags),
        il_frontend::parse(uf, program, &mut diags),
    ];
    il_frontend::sema::analyze(&units, &mut diags);
    Setup {
        map,
        lib,
        units,
        diags,
    }
}

fn short(map: &SourceMap, diags: Diagnostics) -> String {
    render(map, &diags.into_sorted(), MessageFormat::Short)
}

/// Lowers, prints the user's unit, and re-checks the lowered program against the struct prelude.
fn lower_and_print(strategy: Strategy) -> (String, lower::Lowered) {
    let mut s = setup(PROGRAM);
    assert!(s.diags.is_empty(), "{}", short(&s.map, s.diags));
    let lowered = lower::lower(&s.units[1..], &s.lib, strategy, &WINDOW, &mut s.diags);
    assert!(s.diags.is_empty(), "{}", short(&s.map, s.diags));
    let il = il_frontend::print::unit(&lowered.units[0]);
    // The lowered program is valid IL against the post-lowering declarations.
    let post = prelude::after_lowering(&s.lib);
    let mut map = SourceMap::new();
    let mut d = Diagnostics::new();
    let pf = map.add("<blocks>", post.clone());
    let lf = map.add("lowered.il", il.clone());
    let units = vec![
        il_frontend::parse(pf, &post, &mut d),
        il_frontend::parse(lf, &il, &mut d),
    ];
    il_frontend::sema::analyze(&units, &mut d);
    let errors: Vec<_> = d
        .iter()
        .filter(|x| x.severity == diagnostics::Severity::Error)
        .cloned()
        .collect();
    assert!(
        errors.is_empty(),
        "{}\n{}",
        il,
        render(&map, &errors, MessageFormat::Short)
    );
    (il, lowered)
}

#[test]
fn il_method_emits_input_transfer_one_func_and_output_transfer() {
    let (il, lowered) = lower_and_print(Strategy::Il);
    insta::assert_snapshot!(il);
    assert_eq!(lowered.reports[0].method, Method::Il);
    // 8 (LREAL) + 8 (state) + 4 (axis) + 2 (word) + 1 + 1 + 1 (bytes) = 25.
    assert_eq!(lowered.reports[0].tm_bytes, 25);
    assert_eq!(il.matches("FUNC MC_Demo()").count(), 1);
}

#[test]
fn template_method_emits_exactly_one_func_per_call() {
    let (il, lowered) = lower_and_print(Strategy::Template);
    insta::assert_snapshot!(il);
    assert_eq!(lowered.synthesized.len(), 1);
    let f = &lowered.synthesized[0];
    assert_eq!(f.name, "MC_Demo_1");
    assert_eq!(f.func_num, 7);
    assert!(
        f.body
            .contains("Dn_1 = (uint8_t)(Ex_1 && Pos_1 > 0.0 && Ax_1 == 1u && BM_1 == 0);"),
        "{}",
        f.body
    );
    assert!(f.body.contains("St0_1 = (uint64_t)FuncNum;"));
    // The head reads outputs and state back from the instance; the tail writes the bound inputs
    // into the instance (a call that leaves one out keeps it), then outputs and state (and `=>`
    // targets).
    let heads: Vec<&str> = f.head.iter().map(|h| h.local.as_str()).collect();
    assert_eq!(
        heads,
        ["Ax_1", "Ex_1", "Pos_1", "BM_1", "Dn_1", "EID_1", "St0_1"]
    );
    let tails: Vec<&str> = f.tail.iter().map(|t| t.local.as_str()).collect();
    assert_eq!(
        tails,
        ["Ex_1", "Pos_1", "Dn_1", "Dn_1", "EID_1", "EID_1", "St0_1"]
    );
    assert_eq!(lowered.reports[0].il_instructions, 1);
}

#[test]
fn legality_is_checked_before_any_code() {
    let program = "PROGRAM main
VAR ax1 : AXIS_REF; mv : MC_Demo; go : BOOL; END_VAR
    CAL mv(Axis := ax1, Execute := go, Done => TRUE)
    CAL mv(ax1, go, 1.0)
END_PROGRAM
";
    let mut s = setup(program);
    s.diags = Diagnostics::new(); // sema's own view of these calls is not under test here
    let lowered = lower::lower(&s.units[1..], &s.lib, Strategy::Il, &WINDOW, &mut s.diags);
    assert!(lowered.units.is_empty());
    insta::assert_snapshot!(short(&s.map, s.diags));
}

#[test]
fn a_block_that_does_not_fit_the_tm_area_names_the_bytes() {
    let mut s = setup(PROGRAM);
    let small = TmWindow {
        bytes: 16,
        ..WINDOW
    };
    lower::lower(&s.units[1..], &s.lib, Strategy::Il, &small, &mut s.diags);
    insta::assert_snapshot!(short(&s.map, s.diags));
}

#[test]
fn wrong_argument_types_are_reported_by_the_checks_against_the_prelude() {
    let program = "PROGRAM main
VAR ax1 : AXIS_REF; mv : MC_Demo; n : INT; END_VAR
    CAL mv(Axis := ax1, Execute := n, Position := 1.0)
END_PROGRAM
";
    let s = setup(program);
    assert!(s.diags.has_errors());
    insta::assert_snapshot!(short(&s.map, s.diags));
}
