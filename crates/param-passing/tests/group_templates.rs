//! PLCopen Part 4 (axes group) blocks in the template library: array parameters in the schema (validation
//! that points into the template), the built-in group templates and their TM figures, and the lowering of
//! array parameters by both methods (element by element into the TM area; one C array in the head).

use diagnostics::{render, Diagnostics, MessageFormat, SourceMap};
use param_passing::library::{self, Library};
use param_passing::lower::{self, il_layout, Method, Strategy, TmWindow};
use param_passing::{prelude, static_lib};

const WINDOW: TmWindow = TmWindow {
    offset: 3840,
    bytes: 256,
    element_addressing: true,
};

/// Every Part 4 block of the motion library's C ABI, with its function.
const GROUP_BLOCKS: &[(&str, &str)] = &[
    ("MC_AddAxisToGroup", "mc_add_axis_to_group"),
    ("MC_RemoveAxisFromGroup", "mc_remove_axis_from_group"),
    ("MC_UngroupAllAxes", "mc_ungroup_all_axes"),
    ("MC_GroupEnable", "mc_group_enable"),
    ("MC_GroupDisable", "mc_group_disable"),
    ("MC_GroupReset", "mc_group_reset"),
    ("MC_GroupStop", "mc_group_stop"),
    ("MC_GroupHalt", "mc_group_halt"),
    ("MC_GroupHome", "mc_group_home"),
    (
        "MC_GroupReadActualPosition",
        "mc_group_read_actual_position",
    ),
    (
        "MC_GroupReadActualVelocity",
        "mc_group_read_actual_velocity",
    ),
    ("MC_GroupReadStatus", "mc_group_read_status"),
    ("MC_MoveLinearAbsolute", "mc_move_linear_absolute"),
    ("MC_MoveLinearRelative", "mc_move_linear_relative"),
    ("MC_MoveCircularAbsolute", "mc_move_circular_absolute"),
    ("MC_MoveCircularRelative", "mc_move_circular_relative"),
    ("MC_MoveDirectAbsolute", "mc_move_direct_absolute"),
];

fn short(map: &SourceMap, diags: Diagnostics) -> String {
    render(map, &diags.into_sorted(), MessageFormat::Short)
}

#[test]
fn every_group_block_of_the_library_has_a_template_that_calls_it() {
    let mut map = SourceMap::new();
    let mut diags = Diagnostics::new();
    let lib = Library::builtin(&mut map, &mut diags);
    assert!(diags.is_empty(), "{}", short(&map, diags));
    let mut table = String::from("block | funcNum | parameters | arrays | TM bytes (IL method)\n");
    for (block, function) in GROUP_BLOCKS {
        let t = lib
            .get(block)
            .unwrap_or_else(|| panic!("no template {block}"));
        assert!(
            library::MOTION_HEADER.contains(&format!("McStatus {function}(")),
            "{function}"
        );
        assert!(t.body.text.contains(&format!("{function}(")), "{block}");
        let g = t
            .param("AxesGroup")
            .expect("every group block takes AxesGroup");
        assert_eq!(g.iec_type, "AXES_GROUP_REF");
        assert!(g.required);
        let l = il_layout(t, &WINDOW).unwrap();
        let arrays: Vec<String> = t
            .params
            .iter()
            .filter_map(|p| p.array.map(|a| format!("{}[{}]", p.name, a.len)))
            .collect();
        table.push_str(&format!(
            "{block} | {} | {} | {} | {}\n",
            t.func_num,
            t.params.len(),
            arrays.join(" "),
            l.total
        ));
        // aligned: every value (every element of an array) at a multiple of its size
        for s in &l.slots {
            let p = t.param(&s.param).unwrap();
            assert_eq!(s.offset % p.class.tm_bytes(), 0, "{block}.{}", s.param);
            assert_eq!(s.bytes, p.tm_bytes());
        }
    }
    // the blocks with BufferMode, TransitionMode and TransitionParameter
    for b in [
        "MC_MoveLinearAbsolute",
        "MC_MoveLinearRelative",
        "MC_MoveCircularAbsolute",
        "MC_MoveCircularRelative",
        "MC_MoveDirectAbsolute",
    ] {
        let t = lib.get(b).unwrap();
        for p in [
            "BufferMode",
            "TransitionMode",
            "TransitionParameter",
            "CoordSystem",
        ] {
            assert!(t.param(p).is_some_and(|p| !p.required), "{b}.{p}");
        }
    }
    insta::assert_snapshot!(table);
}

const BAD_ARRAYS: &str = r#"<blockTemplate name="MC_BadArrays" funcNum="99">
  <parameters>
    <param name="AxesGroup" abbr="AxG" direction="inout" class="struct" type="AXES_GROUP_REF" required="true"/>
    <param name="Position" abbr="Pos" direction="input" class="array" type="LREAL" length="6"/>
    <param name="Distance" abbr="Dist" direction="input" class="array" element="lreal" type="LREAL" length="six"/>
    <param name="AuxPoint" abbr="Aux" direction="input" class="array" element="lreal" type="LREAL" length="17"/>
    <param name="Axes" abbr="Ax" direction="input" class="array" element="struct" type="AXIS_REF" length="3"/>
    <param name="Velocity" abbr="Vel" direction="input" class="lreal" type="LREAL" length="6"/>
    <param name="EndPoint" abbr="EndP" direction="inout" class="array" element="lreal" type="LREAL" length="6"/>
    <param name="Speeds" abbr="Spd" direction="input" class="array" element="real" type="LREAL" length="6"/>
    <param name="Offsets" abbr="Off" direction="input" class="array" element="lreal" type="LREAL" length="6" low="x"/>
  </parameters>
  <body><![CDATA[ (void)AxG; ]]></body>
</blockTemplate>"#;

#[test]
fn bad_array_declarations_are_reported_inside_the_template() {
    let mut map = SourceMap::new();
    let mut diags = Diagnostics::new();
    let mut lib = Library::new();
    lib.add_text(
        &mut map,
        "templates/MC_BadArrays.xml",
        BAD_ARRAYS,
        &mut diags,
    );
    assert!(lib.get("MC_BadArrays").is_none(), "not loaded");
    let out = short(&map, diags);
    for code in ["E4100", "E4101", "E4102", "E4103", "E4006"] {
        assert!(out.contains(code), "{code}:\n{out}");
    }
    assert!(out
        .lines()
        .all(|l| l.starts_with("templates/MC_BadArrays.xml:")));
    insta::assert_snapshot!(out);
}

/// A user template with an array input and an array output: the body sums and copies the elements.
const ARRAY_DEMO: &str = r#"<blockTemplate name="MC_ArrayDemo" funcNum="77">
  <parameters>
    <param name="AxesGroup" abbr="AxG" direction="inout" class="struct" type="AXES_GROUP_REF" required="true"/>
    <param name="Execute" abbr="Exe" direction="input" class="bool" type="BOOL" required="true"/>
    <param name="Target" abbr="Tgt" direction="input" class="array" element="lreal" type="LREAL" length="3" low="1" required="true"/>
    <param name="Flags" abbr="Flg" direction="input" class="array" element="bool" type="BOOL" length="2" default="TRUE"/>
    <param name="Echo" abbr="Echo" direction="output" class="array" element="lreal" type="LREAL" length="3" low="1"/>
    <param name="Sum" abbr="Sum" direction="output" class="lreal" type="LREAL"/>
  </parameters>
  <local name="i" ctype="uint32_t"/>
  <body><![CDATA[
    Sum = 0.0;
    for (i = 0u; i < 3u; i++) { Echo[i] = Tgt[i]; Sum += Exe && Flg[0] ? Tgt[i] : 0.0; }
    (void)AxG;
  ]]></body>
</blockTemplate>"#;

const ARRAY_PROGRAM: &str = "PROGRAM main
VAR
    g : AXES_GROUP_REF := (GroupNo := 0);
    d : MC_ArrayDemo;
    go : BOOL;
    t : ARRAY [1..3] OF LREAL := [1.0, 2.0, 3.0];
    e : ARRAY [1..3] OF LREAL;
    s : LREAL;
END_VAR
    CAL d(AxesGroup := g, Execute := go, Target := t, Echo => e, Sum => s)
END_PROGRAM
";

fn op(o: &il_frontend::ast::Operand) -> String {
    let mut s = String::new();
    il_frontend::print::operand(&mut s, o);
    s
}

struct Setup {
    map: SourceMap,
    lib: Library,
    units: Vec<il_frontend::ast::CompilationUnit>,
    diags: Diagnostics,
}

fn setup(program: &str) -> Setup {
    let mut map = SourceMap::new();
    let mut diags = Diagnostics::new();
    let mut lib = Library::new();
    lib.add_text(
        &mut map,
        "templates/MC_ArrayDemo.xml",
        ARRAY_DEMO,
        &mut diags,
    );
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

/// Lowers the program, prints it, and checks the lowered program against the post-lowering prelude.
fn lower_and_print(strategy: Strategy) -> (String, lower::Lowered) {
    let mut s = setup(ARRAY_PROGRAM);
    assert!(s.diags.is_empty(), "{}", short(&s.map, s.diags));
    let lowered = lower::lower(&s.units[1..], &s.lib, strategy, &WINDOW, &mut s.diags);
    assert!(s.diags.is_empty(), "{}", short(&s.map, s.diags));
    let il = il_frontend::print::unit(&lowered.units[0]);
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
    assert!(!d.has_errors(), "{il}\n{}", short(&map, d));
    (il, lowered)
}

#[test]
fn the_prelude_declares_array_parameters_with_their_bounds_and_defaults() {
    let s = setup(ARRAY_PROGRAM);
    let pre = prelude::before_lowering(&s.lib);
    assert!(
        pre.contains("    Target : ARRAY [1..3] OF LREAL;\n"),
        "{pre}"
    );
    assert!(
        pre.contains("    Flags : ARRAY [0..1] OF BOOL := [TRUE, TRUE];\n"),
        "{pre}"
    );
    assert!(pre.contains("    Echo : ARRAY [1..3] OF LREAL;\n"), "{pre}");
    assert!(pre.contains("    AXES_GROUP_REF : STRUCT GroupNo : UDINT; END_STRUCT;"));
}

#[test]
fn the_il_method_moves_array_elements_into_consecutive_tm_values() {
    let (il, lowered) = lower_and_print(Strategy::Il);
    assert_eq!(lowered.reports[0].method, Method::Il);
    // Target 3 x 8 + Echo 3 x 8 + Sum 8 + AxesGroup 4 + Execute 1 + Flags 2 x 1
    assert_eq!(lowered.reports[0].tm_bytes, 24 + 24 + 8 + 4 + 1 + 2);
    let layout = &lowered.static_functions["MC_ArrayDemo"];
    assert_eq!(layout.slot("Target").unwrap().offset, 0);
    assert_eq!(layout.slot("Echo").unwrap().offset, 24);
    // IEC index low + k is C element k; the unbound Flags come from the instance (its default)
    for (k, idx) in [(0, 1), (1, 2), (2, 3)] {
        assert!(
            il.contains(&format!(
                "    LD t[{idx}]\n    ST TM__MC_ArrayDemo__Target__{k}\n"
            )),
            "{il}"
        );
        assert!(
            il.contains(&format!(
                "    LD TM__MC_ArrayDemo__Echo__{k}\n    ST d.Echo[{idx}]\n"
            )),
            "{il}"
        );
        assert!(
            il.contains(&format!("    LD d.Echo[{idx}]\n    ST e[{idx}]\n")),
            "{il}"
        );
    }
    assert!(il.contains("    LD d.Flags[1]\n    EQ TRUE\n"), "{il}");
    insta::assert_snapshot!(il);
    // the static function holds the arrays as C arrays loaded from and stored to consecutive TM values
    let t = Library::get(&setup(ARRAY_PROGRAM).lib, "MC_ArrayDemo")
        .unwrap()
        .clone();
    let c = static_lib::function_c(&t, layout);
    insta::assert_snapshot!("array_demo_static_function", c);
}

#[test]
fn the_template_method_declares_one_c_array_per_array_parameter() {
    let (il, lowered) = lower_and_print(Strategy::Template);
    assert_eq!(il.matches("FUNC ").count(), 1, "{il}");
    let f = &lowered.synthesized[0];
    let heads: Vec<&str> = f.head.iter().map(|h| h.local.as_str()).collect();
    assert_eq!(
        heads,
        [
            "AxG_1",
            "Exe_1",
            "Tgt_1[0]",
            "Tgt_1[1]",
            "Tgt_1[2]",
            "Flg_1[0]",
            "Flg_1[1]",
            "Echo_1[0]",
            "Echo_1[1]",
            "Echo_1[2]",
            "Sum_1"
        ]
    );
    let sources: Vec<String> = f.head.iter().map(|h| op(&h.source)).collect();
    assert_eq!(sources[2..5], ["t[1]", "t[2]", "t[3]"]);
    assert_eq!(sources[5..7], ["d.Flags[0]", "d.Flags[1]"]);
    let tails: Vec<String> = f
        .tail
        .iter()
        .map(|t| format!("{} = {}", op(&t.target), t.local))
        .collect();
    // the bound input Execute is kept in the instance (round 21: a call that leaves it out keeps
    // it), then the outputs
    assert_eq!(
        tails,
        [
            "d.Execute = Exe_1",
            "d.Echo[1] = Echo_1[0]",
            "d.Echo[2] = Echo_1[1]",
            "d.Echo[3] = Echo_1[2]",
            "e[1] = Echo_1[0]",
            "e[2] = Echo_1[1]",
            "e[3] = Echo_1[2]",
            "d.Sum = Sum_1",
            "s = Sum_1"
        ]
    );
    assert!(
        f.body
            .contains("Echo_1[i] = Tgt_1[i]; Sum_1 += Exe_1 && Flg_1[0]"),
        "{}",
        f.body
    );
}

#[test]
fn a_single_value_bound_to_an_array_is_refused_before_any_code() {
    let program = ARRAY_PROGRAM.replace("Target := t", "Target := 2.5");
    let mut s = setup(&program);
    assert!(s.diags.has_errors(), "the type check refuses it first");
    s.diags = Diagnostics::new(); // the lowering's own legality check is under test
    let lowered = lower::lower(
        &s.units[1..],
        &s.lib,
        Strategy::Template,
        &WINDOW,
        &mut s.diags,
    );
    assert!(lowered.units.is_empty() && lowered.synthesized.is_empty());
    insta::assert_snapshot!(short(&s.map, s.diags));
}

#[test]
fn axis_group_ref_is_another_name_of_axes_group_ref() {
    let program = ARRAY_PROGRAM.replace(
        "g : AXES_GROUP_REF := (GroupNo := 0);",
        "g : AXIS_GROUP_REF := (GroupNo := 2);",
    );
    let mut s = setup(&program);
    assert!(s.diags.is_empty(), "{}", short(&s.map, s.diags));
    let pre = prelude::before_lowering(&s.lib);
    assert!(
        pre.contains("    AXIS_GROUP_REF : AXES_GROUP_REF;\n"),
        "{pre}"
    );
    let lowered = lower::lower(&s.units[1..], &s.lib, Strategy::Il, &WINDOW, &mut s.diags);
    assert!(s.diags.is_empty(), "{}", short(&s.map, s.diags));
    let il = il_frontend::print::unit(&lowered.units[0]);
    assert!(
        il.contains("    LD g.GroupNo\n    ST TM__MC_ArrayDemo__AxesGroup\n"),
        "{il}"
    );
}

#[test]
fn a_required_array_input_may_be_stored_into_the_instance_element_by_element() {
    let program = ARRAY_PROGRAM.replace(
        "    CAL d(AxesGroup := g, Execute := go, Target := t, Echo => e, Sum => s)",
        "    LD 4.0\n    ST d.Target[2]\n    CAL d(AxesGroup := g, Execute := go, Echo => e, Sum => s)",
    );
    let mut s = setup(&program);
    assert!(s.diags.is_empty(), "{}", short(&s.map, s.diags));
    let lowered = lower::lower(
        &s.units[1..],
        &s.lib,
        Strategy::Template,
        &WINDOW,
        &mut s.diags,
    );
    assert!(s.diags.is_empty(), "{}", short(&s.map, s.diags));
    let sources: Vec<String> = lowered.synthesized[0]
        .head
        .iter()
        .filter(|h| h.local.starts_with("Tgt_"))
        .map(|h| op(&h.source))
        .collect();
    assert_eq!(sources, ["d.Target[1]", "d.Target[2]", "d.Target[3]"]);
    // without any store it is still missing
    let program = ARRAY_PROGRAM.replace("Target := t, ", "");
    let mut s = setup(&program);
    lower::lower(&s.units[1..], &s.lib, Strategy::Il, &WINDOW, &mut s.diags);
    let out = short(&s.map, s.diags);
    assert!(
        out.contains("E4023") && out.contains("required input `Target`"),
        "{out}"
    );
}

#[test]
fn array_bounds_outside_dint_are_e4102_not_a_panic() {
    // `low` = i64::MIN panicked in `abs()`; `low` = i32::MAX with 4 elements put the upper bound past DINT.
    for (low, len) in [
        ("-9223372036854775808", 6),
        ("2147483647", 4),
        ("-2147483649", 1),
    ] {
        let text = format!(
            r#"<blockTemplate name="MC_LowDemo" funcNum="99">
  <parameters>
    <param name="AxesGroup" abbr="AxG" direction="inout" class="struct" type="AXES_GROUP_REF" required="true"/>
    <param name="Offsets" abbr="Off" direction="input" class="array" element="lreal" type="LREAL" length="{len}" low="{low}"/>
  </parameters>
  <body><![CDATA[ (void)AxG; ]]></body>
</blockTemplate>"#
        );
        let mut map = SourceMap::new();
        let mut diags = Diagnostics::new();
        let mut lib = Library::new();
        lib.add_text(&mut map, "MC_LowDemo.xml", &text, &mut diags);
        assert!(lib.get("MC_LowDemo").is_none(), "{low}: not loaded");
        let out = short(&map, diags);
        assert!(
            out.contains("MC_LowDemo.xml:4:") && out.contains("E4102"),
            "{low}:\n{out}"
        );
    }
    // the extremes that fit are accepted
    for (low, len) in [("-2147483648", 6), ("2147483642", 6)] {
        let text = format!(
            r#"<blockTemplate name="MC_LowDemo" funcNum="99">
  <parameters>
    <param name="AxesGroup" abbr="AxG" direction="inout" class="struct" type="AXES_GROUP_REF" required="true"/>
    <param name="Offsets" abbr="Off" direction="input" class="array" element="lreal" type="LREAL" length="{len}" low="{low}"/>
  </parameters>
  <body><![CDATA[ (void)AxG; ]]></body>
</blockTemplate>"#
        );
        let mut map = SourceMap::new();
        let mut diags = Diagnostics::new();
        let mut lib = Library::new();
        lib.add_text(&mut map, "MC_LowDemo.xml", &text, &mut diags);
        assert!(
            lib.get("MC_LowDemo").is_some(),
            "{low}: {}",
            short(&map, diags)
        );
    }
}
