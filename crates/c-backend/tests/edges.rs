//! Edge-triggered FB inputs (`R_EDGE` / `F_EDGE`) end to end: per-instance memory, the first call with
//! TRUE as a rising edge, the caller's value kept between calls, and the IEC Annex F STACK_INT block
//! (corpus file 17), whose PUSH/POP are `R_EDGE` inputs.

mod support;
use support::*;

const COUNTER_FB: &str = "FUNCTION_BLOCK edges
VAR_INPUT
  up : BOOL R_EDGE;
  down : BOOL F_EDGE;
END_VAR
VAR_OUTPUT
  seen_up : BOOL;
  seen_down : BOOL;
  ups : INT;
  downs : INT;
END_VAR
  LD up
  ST seen_up
  JMPCN no_up
  LD ups
  ADD 1
  ST ups
no_up:
  LD down
  ST seen_down
  JMPCN no_down
  LD downs
  ADD 1
  ST downs
no_down:
END_FUNCTION_BLOCK
";

#[test]
fn r_edge_and_f_edge_inputs_read_true_only_in_the_cycle_of_the_change() {
    let src = format!(
        "{COUNTER_FB}
PROGRAM main
VAR
  a : BOOL;
  b : BOOL;
  e1 : edges;
  e2 : edges;
  u1 : BOOL;
  d1 : BOOL;
END_VAR
  CAL e1(up := a, down := a)
  LD e1.seen_up
  ST u1
  LD e1.seen_down
  ST d1
  CAL e2(up := b, down := b)
END_PROGRAM
"
    );
    let b = build_src(&src);
    // a: TRUE from cycle 0 (first call with TRUE is a rise), FALSE at 3, TRUE at 5..6, FALSE at 7.
    // b: FALSE at first (F_EDGE, like F_TRIG, fires on a first call with FALSE), TRUE at 2, FALSE at 4.
    let stim = "0,main.a,1\n3,main.a,0\n5,main.a,1\n7,main.a,0\n2,main.b,1\n4,main.b,0\n";
    let rows = run(
        &b,
        9,
        10.0,
        stim,
        &[
            "main.u1",
            "main.d1",
            "main.e1.ups",
            "main.e1.downs",
            "main.e2.ups",
            "main.e2.downs",
            "main.e1.up",
        ],
    );
    assert_eq!(
        column(&rows, "main.u1"),
        ["1", "0", "0", "0", "0", "1", "0", "0", "0"]
    );
    assert_eq!(
        column(&rows, "main.d1"),
        ["0", "0", "0", "1", "0", "0", "0", "1", "0"]
    );
    assert_eq!(
        column(&rows, "main.e1.ups"),
        ["1", "1", "1", "1", "1", "2", "2", "2", "2"]
    );
    assert_eq!(
        column(&rows, "main.e1.downs"),
        ["0", "0", "0", "1", "1", "1", "1", "2", "2"]
    );
    // the other instance has its own memory
    assert_eq!(
        column(&rows, "main.e2.ups"),
        ["0", "0", "1", "1", "1", "1", "1", "1", "1"]
    );
    assert_eq!(
        column(&rows, "main.e2.downs"),
        ["1", "1", "1", "1", "2", "2", "2", "2", "2"]
    );
    // the input member keeps the caller's level (not the edge) after the call
    assert_eq!(
        column(&rows, "main.e1.up"),
        ["1", "1", "1", "0", "0", "1", "1", "0", "0"]
    );
}

#[test]
fn a_call_without_arguments_sees_the_input_unchanged_and_no_new_edge() {
    let src = format!(
        "{COUNTER_FB}
PROGRAM main
VAR
  a : BOOL;
  set : BOOL;
  e : edges;
END_VAR
  LD set
  JMPCN plain
  CAL e(up := a)
  JMP done
plain:
  CAL e
done:
END_PROGRAM
"
    );
    let b = build_src(&src);
    // cycle 0: up := TRUE (rise); cycles 1-3: plain calls (level stays TRUE, no edge);
    // cycle 4: up := FALSE; cycle 5: plain; cycle 6: up := TRUE (rise)
    let stim = "0,main.set,1\n0,main.a,1\n1,main.set,0\n4,main.set,1\n4,main.a,0\n5,main.set,0\n6,main.set,1\n6,main.a,1\n";
    let rows = run(&b, 7, 10.0, stim, &["main.e.ups", "main.e.seen_up"]);
    assert_eq!(
        column(&rows, "main.e.seen_up"),
        ["1", "0", "0", "0", "0", "0", "1"]
    );
    assert_eq!(
        column(&rows, "main.e.ups"),
        ["1", "1", "1", "1", "1", "1", "2"]
    );
}

#[test]
fn annex_f_stack_int_pushes_and_pops_once_per_edge() {
    let Some(stack) = corpus("il/17_matiec_AnnexF_stack_int_il.st") else {
        return;
    };
    let stack = std::fs::read_to_string(stack).unwrap();
    let src = format!(
        "{stack}
PROGRAM main
VAR
  push : BOOL;
  pop : BOOL;
  reset : BOOL;
  value : INT;
  s : STACK_INT;
  top : INT;
  empty : BOOL;
  oflo : BOOL;
END_VAR
  CAL s(PUSH := push, POP := pop, R1 := reset, IN := value, N := 2)
  LD s.OUT
  ST top
  LD s.EMPTY
  ST empty
  LD s.OFLO
  ST oflo
END_PROGRAM
"
    );
    let b = build_src(&src);
    // reset (N = 2); push 7 and hold PUSH for 3 cycles (one push); push 9; push 11 (overflow: OUT = 0,
    // as Annex F writes it); pop held 2 cycles (one pop: 9); pop (7); pop (empty, OUT = 0).
    let stim = "0,main.reset,1\n1,main.reset,0\n\
                1,main.value,7\n1,main.push,1\n4,main.push,0\n\
                5,main.value,9\n5,main.push,1\n6,main.push,0\n\
                7,main.value,11\n7,main.push,1\n8,main.push,0\n\
                9,main.pop,1\n11,main.pop,0\n12,main.pop,1\n13,main.pop,0\n14,main.pop,1\n";
    let rows = run(&b, 15, 10.0, stim, &["main.top", "main.empty", "main.oflo"]);
    assert_eq!(
        column(&rows, "main.top"),
        ["0", "7", "7", "7", "7", "9", "9", "0", "0", "9", "9", "9", "7", "7", "0"]
    );
    assert_eq!(
        column(&rows, "main.empty"),
        ["1", "0", "0", "0", "0", "0", "0", "0", "0", "0", "0", "0", "0", "0", "1"]
    );
    assert_eq!(
        column(&rows, "main.oflo"),
        ["0", "0", "0", "0", "0", "0", "0", "1", "1", "0", "0", "0", "0", "0", "0"]
    );
}

/// The generated C of an FB with edge-triggered inputs: hidden trigger members, the body proper and
/// the `_BODY` wrapper.
#[test]
fn generated_c_of_edge_inputs() {
    let (units, model, map) = frontend(COUNTER_FB);
    let p = generate_with(
        &units,
        &model,
        &map,
        &Default::default(),
        &Default::default(),
    );
    let h = p.file("program.h").unwrap();
    let c = p.file("program.c").unwrap();
    let start = h.find("struct FB_edges {").unwrap();
    let strct = &h[start..start + h[start..].find("\n};").unwrap() + 3];
    let body = &c[c.find("static void FB_edges_BODY_LEVELS").unwrap()..];
    let wrapper = body.find("void FB_edges_BODY(").unwrap();
    let body = &body[..wrapper + body[wrapper..].find("\n}\n").unwrap() + 3];
    insta::assert_snapshot!(format!("{strct}\n\n{body}"));
}
