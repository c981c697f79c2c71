//! Round 34 (sweep 34a, points B3 and B6), TwinCAT 3 projects:
//!
//! - B3: a generic function (SEL) of Tc2_MC2's enumeration constants given to an input of a
//!   built-in motion block, `Direction := SEL(back, MC_Positive_Direction,
//!   MC_Negative_Direction)`: the value has the constants' type (IEC 61131-3 ed. 3, Table 35 "Selection
//!   functions": SEL's result is of the type of IN0 and IN1), as when the same SEL is assigned to an
//!   `MC_Direction` variable. Before: E1012 "Direction of MC_MoveVelocity is USINT, not DINT" (the ST
//!   bodies did not know the library's constants and kept the value in a DINT temporary).
//! - B6: a diagnostic on an operand of an LD/FBD network (`<NWL>` body of a `.TcPOU`) is located at
//!   that operand's element, also for a box's output operand (the ST call writes it after the box's
//!   inputs). Before: E1001 on the box's last input operand's line.

mod common;
use common::{check_files, column, run_traced};

/// Two axes, each moved by MC_MoveVelocity at 10 mm/s with `Direction := SEL(back, MC_Positive_Direction,
/// MC_Negative_Direction)`: X1 with `back` FALSE goes forward (+10 mm/s), X2 with `back` TRUE
/// goes backward (-10 mm/s), every scan. Before: E1012 "Direction of MC_MoveVelocity is USINT, not
/// DINT" and nothing ran.
#[test]
fn sel_of_mc_direction_values_given_to_direction_moves_the_chosen_way() {
    let dir = tempfile::tempdir().unwrap();
    let src = "PROGRAM main
VAR
    power1, power2 : MC_Power;
    move1, move2 : MC_MoveVelocity;
    back1 : BOOL := FALSE;
    back2 : BOOL := TRUE;
END_VAR
power1(Axis := X1, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);
power2(Axis := X2, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);
move1(Axis := X1, Execute := power1.Status, Velocity := 10.0,
      Direction := SEL(back1, MC_Positive_Direction, MC_Negative_Direction));
move2(Axis := X2, Execute := power2.Status, Velocity := 10.0,
      Direction := SEL(back2, MC_Positive_Direction, MC_Negative_Direction));
END_PROGRAM

CONFIGURATION c
RESOURCE r ON PLC
TASK t(INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM p WITH t : main;
END_RESOURCE
END_CONFIGURATION
";
    let axis = |name: &str| {
        format!(
            "{{ \"name\": \"{name}\", \"unit\": \"mm\", \"counts_per_unit\": 1000, \"velocity\": 100, \
             \"acceleration\": 1000, \"deceleration\": 1000, \"jerk\": 0, \"modulo_period\": 0, \
             \"following_error_limit\": 0 }}"
        )
    };
    let st = dir.path().join("dir_sel.st");
    std::fs::write(&st, src).unwrap();
    std::fs::write(
        dir.path().join("dir_sel.axes.json"),
        format!("{{ \"axes\": [ {}, {} ] }}", axis("X1"), axis("X2")),
    )
    .unwrap();
    let (trace, stderr) = run_traced(
        &st,
        20,
        "axis.X1.velocity,axis.X2.velocity,axis.X1.position,axis.X2.position",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    let (v1, v2) = (
        column(&trace, "axis.X1.velocity"),
        column(&trace, "axis.X2.velocity"),
    );
    assert_eq!(v1.len(), 20);
    for k in 0..20 {
        assert_eq!((v1[k], v2[k]), (10.0, -10.0), "cycle {k}");
    }
    let (p1, p2) = (
        column(&trace, "axis.X1.position"),
        column(&trace, "axis.X2.position"),
    );
    assert!(p1[19] > 1.5 && p2[19] < -1.5, "{} {}", p1[19], p2[19]);
}

/// A function block with two BOOL inputs and outputs, as a TwinCAT 3 `.TcPOU`.
const FB_GATE: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4024.12">
  <POU Name="FB_Gate" Id="{3a000000-0000-0000-0000-000000000001}" SpecialFunc="None">
    <Declaration><![CDATA[FUNCTION_BLOCK FB_Gate
VAR_INPUT
	a : BOOL;
	b : BOOL;
END_VAR
VAR_OUTPUT
	both : BOOL;
	either : BOOL;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[both := a AND b;
either := a OR b;]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
"#;

/// One operand of a network archive (`<o>` with its name, type and flags).
fn operand(name: &str, ty: &str, id: u32, indent: &str) -> String {
    format!(
        "{indent}<v n=\"Operand\">\"{name}\"</v>\n{indent}<v n=\"Type\">\"{ty}\"</v>\n{indent}<o n=\"Flags\" t=\"Flags\">\n{indent}  <v n=\"Flags\">0</v>\n{indent}</o>\n{indent}<v n=\"Id\">{id}L</v>\n"
    )
}

/// A PROGRAM `MAIN` in FBD: one network `x := gate(a := first, b := second, either => extra).both`.
fn main_fbd(first: &str, second: &str, extra: &str) -> String {
    let i = "                            ";
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4024.12">
  <POU Name="MAIN" Id="{{3a000000-0000-0000-0000-000000000002}}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
	gate : FB_Gate;
	in1 : BOOL;
	in2 : BOOL;
	x : BOOL;
	y : BOOL;
END_VAR
]]></Declaration>
    <Implementation>
      <NWL>
        <XmlArchive>
          <Data>
            <o xml:space="preserve" t="NWLImplementationObject">
              <v n="NetworkListComment">""</v>
              <v n="DefaultViewMode">"Fbd"</v>
              <l2 n="NetworkList" cet="Network">
                <o>
                  <v n="ILActive">false</v>
                  <v n="FBDValid">false</v>
                  <v n="ILValid">false</v>
                  <l2 n="ILLines" />
                  <v n="Comment">""</v>
                  <v n="Title">""</v>
                  <v n="Label">""</v>
                  <v n="OutCommented">false</v>
                  <l2 n="NetworkItems" cet="BoxTreeAssign">
                    <o>
                      <o n="OutputItems" t="OutputItemList">
                        <l2 n="OutputItems" cet="Operand">
                          <o>
{x}                          </o>
                        </l2>
                      </o>
                      <o n="Flags" t="Flags">
                        <v n="Flags">0</v>
                      </o>
                      <o n="RValue" t="BoxTreeBox">
                        <v n="BoxType">"FB_Gate"</v>
                        <o n="Instance" t="Operand">
{gate}                        </o>
                        <o n="OutputItems" t="OutputItemList">
                          <l2 n="OutputItems" cet="Operand">
                            <n />
                            <o>
{extra}                            </o>
                          </l2>
                        </o>
                        <o n="Flags" t="Flags">
                          <v n="Flags">0</v>
                        </o>
                        <n n="InputFlags" />
                        <l2 n="InputItems" cet="BoxTreeOperand">
                          <o>
                            <o n="Operand" t="Operand">
{first}                            </o>
                            <v n="Id">13L</v>
                          </o>
                          <o>
                            <o n="Operand" t="Operand">
{second}                            </o>
                            <v n="Id">15L</v>
                          </o>
                        </l2>
                        <o n="InputParam" t="ParamList">
                          <l2 n="Names" cet="String">
                            <v>a</v>
                            <v>b</v>
                          </l2>
                          <l2 n="Types" cet="String">
                            <v>BOOL</v>
                            <v>BOOL</v>
                          </l2>
                        </o>
                        <o n="OutputParam" t="ParamList">
                          <l2 n="Names" cet="String">
                            <v>both</v>
                            <v>either</v>
                          </l2>
                          <l2 n="Types" cet="String">
                            <v>BOOL</v>
                            <v>BOOL</v>
                          </l2>
                        </o>
                        <v n="CallType" t="Operator">FunctionBlock</v>
                        <v n="EN">false</v>
                        <v n="ENO">false</v>
                        <n n="STSnippet" />
                        <v n="Id">17L</v>
                      </o>
                      <v n="Id">18L</v>
                    </o>
                  </l2>
                  <l2 n="Connectors" />
                  <v n="Id">19L</v>
                </o>
              </l2>
              <v n="BranchCounter">0</v>
              <v n="ValidIds">true</v>
            </o>
          </Data>
        </XmlArchive>
      </NWL>
    </Implementation>
  </POU>
</TcPlcObject>
"#,
        x = operand("x", "BOOL", 10, i),
        gate = operand("gate", "", 11, "                          "),
        extra = operand(extra, "", 12, "                              "),
        first = operand(first, "BOOL", 14, "                              "),
        second = operand(second, "BOOL", 16, "                              "),
    )
}

/// Whether the short-format diagnostic `line` is located at the `<v n="Operand">` element naming
/// `name` in `text`: `MAIN.TcPOU:LINE:COL` with LINE its line and COL within the element.
fn at_operand(line: &str, text: &str, name: &str) -> bool {
    let needle = format!("<v n=\"Operand\">\"{name}\"</v>");
    let Some((k, l)) = text.lines().enumerate().find(|(_, l)| l.contains(&needle)) else {
        return false;
    };
    let start = l.find(&needle).unwrap_or(0) + 1;
    let prefix = format!("MAIN.TcPOU:{}:", k + 1);
    let col = line
        .strip_prefix(&prefix)
        .and_then(|rest| rest.split(':').next())
        .and_then(|c| c.parse::<usize>().ok());
    col.is_some_and(|c| (start..start + needle.len()).contains(&c))
}

/// An undeclared variable wired to a box's output (TwinCAT's `_REFACTOR_` placeholder left by a
/// refactoring) is one E1001 at that operand's own element. Before: at the line of the box's last
/// input operand (`in2`), 25 lines further down.
#[test]
fn an_undeclared_box_output_operand_is_reported_at_its_own_element() {
    let main = main_fbd("in1", "in2", "_REFACTOR_");
    let (code, lines) = check_files(&[("FB_Gate.TcPOU", FB_GATE), ("MAIN.TcPOU", &main)]);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        at_operand(&lines[0], &main, "_REFACTOR_")
            && lines[0].contains("error[E1001]: undeclared name `_REFACTOR_`"),
        "{lines:?}"
    );
}

/// An undeclared variable on a box's input (the first of two) is one E1001 at that operand's
/// element, and an undeclared second input at its own (the located reading of the inputs, kept).
#[test]
fn an_undeclared_box_input_operand_is_reported_at_its_own_element() {
    for (first, second) in [("ghost", "in2"), ("in1", "ghost")] {
        let main = main_fbd(first, second, "y");
        let (code, lines) = check_files(&[("FB_Gate.TcPOU", FB_GATE), ("MAIN.TcPOU", &main)]);
        assert_eq!(code, Some(1), "{lines:?}");
        assert_eq!(lines.len(), 1, "{lines:?}");
        assert!(
            at_operand(&lines[0], &main, "ghost")
                && lines[0].contains("error[E1001]: undeclared name `ghost`"),
            "{lines:?}"
        );
    }
}

/// With every operand declared the same network checks clean: a box output operand whose
/// diagnostics are shown at its element is still compiled as the call's output (`either => y`).
#[test]
fn the_box_network_with_its_output_operand_still_checks_clean() {
    let main = main_fbd("in1", "in2", "y");
    let (code, lines) = check_files(&[("FB_Gate.TcPOU", FB_GATE), ("MAIN.TcPOU", &main)]);
    assert_eq!((code, lines.len()), (Some(0), 0), "{lines:?}");
}
