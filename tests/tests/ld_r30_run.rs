//! Round 30 (issue #13), LD/FBD semantics found on unseen OpenPLC/Beremiz projects: a function-block
//! box whose EN is FALSE leaves its instance's ENO FALSE, a contact reads its variable where it
//! stands in the network (after a coil above it of the same network), and a contact on a variable that
//! is no BOOL gives one error, not a second one at the coil it feeds.

mod common;

use common::{check_text, column, plcopen_program, run_xml_with_stimulus};

/// A user block whose body sets its output: `Q := TRUE`.
const LATCH_FB: &str = r#"<pou name="Latch" pouType="functionBlock">
<interface><outputVars><variable name="Q"><type><BOOL/></type></variable></outputVars></interface>
<body><ST><xhtml:p><![CDATA[Q := TRUE;]]></xhtml:p></ST></body>
</pou>"#;

fn col(trace: &str, name: &str) -> Vec<u8> {
    column(trace, name).iter().map(|v| *v as u8).collect()
}

/// B1 (crebosh/PLC_LD_Projects TrafficLight: the red lamp, fed through a contact on `Flasher1.ENO`,
/// stayed on beside the green one). An LD box of a user block with EN from a contact: while EN is
/// FALSE the block does not run and its ENO is FALSE (IEC 61131-3 ed. 2 2.5.1.2, ed. 3 6.6.1.6; matiec
/// starts every FB body with `if (!EN) { ENO = FALSE; return; }`), so a contact on `inst.ENO` reads
/// FALSE, while the output `Q` keeps its value. Before: `inst.ENO` stayed TRUE from the last call
/// that ran (cycles 4-5 gave `out = 1`, `eno_copy = 1`); the same call in ST was already right.
#[test]
fn an_ld_box_with_en_false_leaves_its_instance_eno_false() {
    let body = r#"<LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
<contact localId="2" negated="false"><position x="20" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>en</variable></contact>
<block localId="3" typeName="Latch" instanceName="inst"><position x="60" y="10"/>
<inputVariables><variable formalParameter="EN"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable></inputVariables>
<inOutVariables/>
<outputVariables><variable formalParameter="ENO"><connectionPointOut/></variable><variable formalParameter="Q"><connectionPointOut/></variable></outputVariables>
</block>
<contact localId="4" negated="false"><position x="120" y="10"/><connectionPointIn><connection refLocalId="3" formalParameter="Q"/></connectionPointIn><connectionPointOut/><variable>inst.ENO</variable></contact>
<coil localId="5" negated="false"><position x="160" y="10"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn><connectionPointOut/><variable>out</variable></coil>
<contact localId="6" negated="false"><position x="20" y="60"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>inst.ENO</variable></contact>
<coil localId="7" negated="false"><position x="160" y="60"/><connectionPointIn><connection refLocalId="6"/></connectionPointIn><connectionPointOut/><variable>eno_copy</variable></coil>
<rightPowerRail localId="8"><position x="200" y="0"/><connectionPointIn><connection refLocalId="5"/><connection refLocalId="7"/></connectionPointIn></rightPowerRail>
</LD>"#;
    let text = plcopen_program(
        LATCH_FB,
        &[
            ("en", "BOOL"),
            ("out", "BOOL"),
            ("eno_copy", "BOOL"),
            ("inst", "Latch"),
        ],
        body,
    );
    let trace = run_xml_with_stimulus(
        &text,
        7,
        "2,m.en,TRUE\n4,m.en,FALSE\n6,m.en,TRUE\n",
        &["m.en", "m.inst.Q", "m.out", "m.eno_copy"],
    );
    assert_eq!(col(&trace, "m.inst.Q"), [0, 0, 1, 1, 1, 1, 1], "{trace}");
    assert_eq!(col(&trace, "m.eno_copy"), [0, 0, 1, 1, 0, 0, 1], "{trace}");
    assert_eq!(col(&trace, "m.out"), [0, 0, 1, 1, 0, 0, 1], "{trace}");
}

/// B1 in FBD: a box with EN from an input variable, and an input variable `inst.ENO` wired to an
/// output variable. Before: `eno_copy` stayed 1 while `en` was FALSE.
#[test]
fn an_fbd_box_with_en_false_leaves_its_instance_eno_false() {
    let body = r#"<FBD>
<inVariable localId="1"><position x="0" y="10"/><connectionPointOut/><expression>en</expression></inVariable>
<block localId="2" typeName="Latch" instanceName="inst"><position x="60" y="10"/>
<inputVariables><variable formalParameter="EN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable></inputVariables>
<inOutVariables/>
<outputVariables><variable formalParameter="ENO"><connectionPointOut/></variable><variable formalParameter="Q"><connectionPointOut/></variable></outputVariables>
</block>
<inVariable localId="3"><position x="0" y="80"/><connectionPointOut/><expression>inst.ENO</expression></inVariable>
<outVariable localId="4"><position x="100" y="80"/><connectionPointIn><connection refLocalId="3"/></connectionPointIn><expression>eno_copy</expression></outVariable>
</FBD>"#;
    let text = plcopen_program(
        LATCH_FB,
        &[("en", "BOOL"), ("eno_copy", "BOOL"), ("inst", "Latch")],
        body,
    );
    let trace = run_xml_with_stimulus(
        &text,
        6,
        "2,m.en,TRUE\n4,m.en,FALSE\n",
        &["m.en", "m.eno_copy"],
    );
    assert_eq!(col(&trace, "m.eno_copy"), [0, 0, 1, 1, 0, 0], "{trace}");
}

/// The toggle of CONTROLLINO's `stairs_light_control`: a contact on `x` feeds `NOT s -> (S) s`, and a
/// contact on `s` below it feeds `(R) s`. `shared`: both rungs hang off one contact on `x` (one
/// network); otherwise each rung has its own contact on `x` (two networks).
fn toggle(shared: bool) -> String {
    let (second_x, lower_from) = if shared {
        (String::new(), 2)
    } else {
        (
            r#"<contact localId="9" negated="false"><position x="20" y="60"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>x</variable></contact>"#
                .to_string(),
            9,
        )
    };
    let body = format!(
        r#"<LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
<contact localId="2" negated="false"><position x="20" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>x</variable></contact>
<contact localId="3" negated="true"><position x="80" y="10"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>s</variable></contact>
<coil localId="4" negated="false" storage="set"><position x="160" y="10"/><connectionPointIn><connection refLocalId="3"/></connectionPointIn><connectionPointOut/><variable>s</variable></coil>
{second_x}
<contact localId="5" negated="false"><position x="80" y="60"/><connectionPointIn><connection refLocalId="{lower_from}"/></connectionPointIn><connectionPointOut/><variable>s</variable></contact>
<coil localId="6" negated="false" storage="reset"><position x="160" y="60"/><connectionPointIn><connection refLocalId="5"/></connectionPointIn><connectionPointOut/><variable>s</variable></coil>
<contact localId="7" negated="false"><position x="80" y="110"/><connectionPointIn><connection refLocalId="{lower_from}"/></connectionPointIn><connectionPointOut/><variable>s</variable></contact>
<coil localId="8" negated="false"><position x="160" y="110"/><connectionPointIn><connection refLocalId="7"/></connectionPointIn><connectionPointOut/><variable>seen</variable></coil>
<rightPowerRail localId="10"><position x="200" y="0"/><connectionPointIn><connection refLocalId="4"/><connection refLocalId="6"/><connection refLocalId="8"/></connectionPointIn></rightPowerRail>
</LD>"#
    );
    plcopen_program("", &[("x", "BOOL"), ("s", "BOOL"), ("seen", "BOOL")], &body)
}

/// B5 (CONTROLLINO-PLC/OpenPLC_examples `stairs_light_control`). IEC 61131-3 evaluates a network's
/// elements in data-flow order (a variable read before a coil writes it is a feedback variable: the
/// value from before), ladderc breaks ties top to bottom, then left to right, and Beremiz/OpenPLC
/// Editor generate one statement per coil in that order (`PLCGenerator.py`, `SortInstances`), each
/// reading its contacts there: the lower rungs read `s` as the set coil above left it, so the press
/// sets and resets `s` in the same scan, and `seen` (below both) reads it reset. The drawing with one
/// shared contact on `x` gives the same trace as the drawing with a contact per rung. Before: with
/// the shared contact every contact read `s` from before the network, so the press toggled `s` on
/// (`s` = 1 from cycle 2) while the separate drawing left it off.
#[test]
fn a_contact_below_a_coil_of_its_network_reads_what_the_coil_wrote() {
    let mut traces = Vec::new();
    for shared in [true, false] {
        let trace = run_xml_with_stimulus(
            &toggle(shared),
            5,
            "2,m.x,TRUE\n3,m.x,FALSE\n",
            &["m.x", "m.s", "m.seen"],
        );
        assert_eq!(
            col(&trace, "m.s"),
            [0, 0, 0, 0, 0],
            "shared {shared}: {trace}"
        );
        assert_eq!(
            col(&trace, "m.seen"),
            [0, 0, 0, 0, 0],
            "shared {shared}: {trace}"
        );
        traces.push(trace);
    }
    assert_eq!(traces[0], traces[1]);
}

/// The feedback side of the same rule: a seal-in contact on `m` before the coil `m` it feeds (and a
/// lower rung sharing it) reads `m` from before the coil, the contact on `m` below the coil what it
/// wrote: `both := m(before) AND m(after)` is TRUE one scan after the start, and FALSE in the scan
/// the stop clears `m` (before round 30: TRUE, the old `m` twice).
#[test]
fn a_seal_in_contact_reads_the_value_from_before_its_coil() {
    let body = r#"<LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
<contact localId="2" negated="false"><position x="20" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>start</variable></contact>
<contact localId="3" negated="false"><position x="20" y="40"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>m</variable></contact>
<contact localId="4" negated="true"><position x="80" y="10"/><connectionPointIn><connection refLocalId="2"/><connection refLocalId="3"/></connectionPointIn><connectionPointOut/><variable>stop</variable></contact>
<coil localId="5" negated="false"><position x="160" y="10"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn><connectionPointOut/><variable>m</variable></coil>
<contact localId="6" negated="false"><position x="80" y="70"/><connectionPointIn><connection refLocalId="3"/></connectionPointIn><connectionPointOut/><variable>m</variable></contact>
<coil localId="7" negated="false"><position x="160" y="70"/><connectionPointIn><connection refLocalId="6"/></connectionPointIn><connectionPointOut/><variable>both</variable></coil>
<rightPowerRail localId="8"><position x="200" y="0"/><connectionPointIn><connection refLocalId="5"/><connection refLocalId="7"/></connectionPointIn></rightPowerRail>
</LD>"#;
    let text = plcopen_program(
        "",
        &[
            ("start", "BOOL"),
            ("stop", "BOOL"),
            ("m", "BOOL"),
            ("both", "BOOL"),
        ],
        body,
    );
    let trace = run_xml_with_stimulus(
        &text,
        6,
        "1,m.start,TRUE\n2,m.start,FALSE\n4,m.stop,TRUE\n5,m.stop,FALSE\n",
        &["m.m", "m.both"],
    );
    assert_eq!(col(&trace, "m.m"), [0, 1, 1, 1, 0, 0], "{trace}");
    assert_eq!(col(&trace, "m.both"), [0, 0, 1, 1, 0, 0], "{trace}");
}

/// B2 (wooyoungkwak/electronjs-api-demo: 6 errors for 2 rungs). A contact on an INT variable is one
/// E3008 at the contact's variable; the coil it feeds gets its power flow (a contact passes BOOL
/// power flow, IEC 61131-3 ed. 2 4.2.3), so no second error. Before: a second E3008 "coil `out`
/// needs BOOL power flow, but is driven by INT" at the coil.
#[test]
fn a_contact_on_an_int_variable_is_one_error_not_two() {
    let body = r#"<LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
<contact localId="2" negated="false"><position x="20" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>n</variable></contact>
<coil localId="3" negated="false"><position x="160" y="10"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>out</variable></coil>
<rightPowerRail localId="4"><position x="200" y="0"/><connectionPointIn><connection refLocalId="3"/></connectionPointIn></rightPowerRail>
</LD>"#;
    let text = plcopen_program("", &[("n", "INT"), ("out", "BOOL")], body);
    let (code, lines) = check_text("plc.xml", &text);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    let line = text
        .lines()
        .position(|l| l.contains("<variable>n</variable>"))
        .unwrap()
        + 1;
    let col = text.lines().nth(line - 1).unwrap().find(">n<").unwrap() + 2;
    assert!(
        errors[0].starts_with(&format!("plc.xml:{line}:{col}: error[E3008]: contact `n`")),
        "{lines:?}"
    );
    assert!(errors[0].contains("type INT, not BOOL"), "{lines:?}");
}
