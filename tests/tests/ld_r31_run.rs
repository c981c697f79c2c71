//! Round 31 (issue #13), the rest of LD/FBD evaluation: a user block's or user function's ENO pin
//! carries the ENO its body leaves (not its EN), and function and block boxes and edge contacts (P/N)
//! run where they stand in the network's evaluation order, as contacts do since round 30 (before:
//! all of them ran before the network's first coil).

mod common;

use common::{column, plcopen_program, run_xml_with_stimulus};

fn col(trace: &str, name: &str) -> Vec<u8> {
    column(trace, name).iter().map(|v| *v as u8).collect()
}

/// A user block that refuses an input above 2: `ENO := FALSE` (its output `Q` still follows `IN`).
const CHECK_FB: &str = r#"<pou name="Check" pouType="functionBlock">
<interface><inputVars><variable name="IN"><type><INT/></type></variable></inputVars>
<outputVars><variable name="Q"><type><INT/></type></variable></outputVars></interface>
<body><ST><xhtml:p><![CDATA[Q := IN;
IF IN > 2 THEN ENO := FALSE; END_IF;]]></xhtml:p></ST></body>
</pou>"#;

/// The same as a user function: `Plus1 := IN + 1`, and `ENO := FALSE` above 2.
const PLUS1_FN: &str = r#"<pou name="Plus1" pouType="function">
<interface><returnType><INT/></returnType><inputVars><variable name="IN"><type><INT/></type></variable></inputVars></interface>
<body><ST><xhtml:p><![CDATA[Plus1 := IN + 1;
IF IN > 2 THEN ENO := FALSE; END_IF;]]></xhtml:p></ST></body>
</pou>"#;

/// One rung: contact `en` into the EN of a box of `block` (`inst` when it is a block), `IN` from
/// the input variable `n`, its ENO into coil `ok`, its output `out` into the output variable `y`.
fn eno_rung(block: &str, instance: bool, out: &str) -> String {
    let inst = if instance {
        r#" instanceName="inst""#
    } else {
        ""
    };
    format!(
        r#"<LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
<contact localId="2" negated="false"><position x="20" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>en</variable></contact>
<inVariable localId="3"><position x="20" y="40"/><connectionPointOut/><expression>n</expression></inVariable>
<block localId="4" typeName="{block}"{inst}><position x="60" y="10"/>
<inputVariables><variable formalParameter="EN"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
<variable formalParameter="IN"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></variable></inputVariables>
<inOutVariables/>
<outputVariables><variable formalParameter="ENO"><connectionPointOut/></variable><variable formalParameter="{out}"><connectionPointOut/></variable></outputVariables>
</block>
<coil localId="5" negated="false"><position x="160" y="10"/><connectionPointIn><connection refLocalId="4" formalParameter="ENO"/></connectionPointIn><connectionPointOut/><variable>ok</variable></coil>
<outVariable localId="6"><position x="160" y="40"/><connectionPointIn><connection refLocalId="4" formalParameter="{out}"/></connectionPointIn><expression>y</expression></outVariable>
<rightPowerRail localId="7"><position x="200" y="0"/><connectionPointIn><connection refLocalId="5"/></connectionPointIn></rightPowerRail>
</LD>"#
    )
}

/// The stimulus of the ENO tests: EN on at cycle 1, `n` 3 (refused) at 3, 1 at 5, EN off at 6.
const ENO_STIMULUS: &str = "1,m.en,TRUE\n3,m.n,3\n5,m.n,1\n6,m.en,FALSE\n";

/// A user block's ENO pin carries the ENO its body leaves: IEC 61131-3 ed. 3 6.6.1.6 (ed. 2 2.5.1.2)
/// makes ENO an output of the block, TRUE when EN is, unless the body sets it FALSE; matiec's FB body
/// sets ENO TRUE and runs the body, and Beremiz's `PLCGenerator.py` reads the pin as `inst.ENO`. The
/// coil `ok` on the pin is FALSE while `n` is 3 (cycles 3-4) and while EN is FALSE (cycle 6).
/// Before: the pin was EN, so `ok` stayed TRUE at cycles 3-4.
#[test]
fn a_user_block_eno_pin_carries_the_eno_its_body_leaves() {
    let text = plcopen_program(
        CHECK_FB,
        &[
            ("en", "BOOL"),
            ("n", "INT"),
            ("ok", "BOOL"),
            ("y", "INT"),
            ("inst", "Check"),
        ],
        &eno_rung("Check", true, "Q"),
    );
    let trace = run_xml_with_stimulus(&text, 7, ENO_STIMULUS, &["m.n", "m.ok", "m.y"]);
    assert_eq!(col(&trace, "m.ok"), [0, 1, 1, 0, 0, 1, 0], "{trace}");
    assert_eq!(col(&trace, "m.y"), [0, 0, 0, 3, 3, 1, 1], "{trace}");
}

/// The same for a user function: the box's ENO pin carries the function's ENO (Beremiz generates
/// `Plus1_4_OUT := Plus1(EN := en, IN := n, ENO => Plus1_4_ENO)` and reads the pin there), and an
/// output variable wired to the result is written only when that ENO is TRUE (Beremiz:
/// `IF Plus1_4_ENO THEN y := Plus1_4_OUT; END_IF`), so `y` keeps 1 while `n` is 3. Before: the pin
/// was EN (`ok` TRUE at cycles 3-4) and `y` took 4.
#[test]
fn a_user_function_eno_pin_carries_the_eno_its_body_leaves() {
    let text = plcopen_program(
        PLUS1_FN,
        &[("en", "BOOL"), ("n", "INT"), ("ok", "BOOL"), ("y", "INT")],
        &eno_rung("Plus1", false, "OUT"),
    );
    let trace = run_xml_with_stimulus(&text, 7, ENO_STIMULUS, &["m.n", "m.ok", "m.y"]);
    assert_eq!(col(&trace, "m.ok"), [0, 1, 1, 0, 0, 1, 0], "{trace}");
    assert_eq!(col(&trace, "m.y"), [0, 1, 1, 1, 1, 2, 2], "{trace}");
}

/// A user block that passes its input on: `Q := IN`.
const PASS_FB: &str = r#"<pou name="Pass" pouType="functionBlock">
<interface><inputVars><variable name="IN"><type><BOOL/></type></variable></inputVars>
<outputVars><variable name="Q"><type><BOOL/></type></variable></outputVars></interface>
<body><ST><xhtml:p><![CDATA[Q := IN;]]></xhtml:p></ST></body>
</pou>"#;

/// One network hanging off a contact on `x`: the top rung writes coil `run`; below it, three rungs
/// read `run`: a contact into the block `p` (`Pass`) whose `Q` drives coil `seen`, a rising-edge
/// contact driving coil `pulse`, and a contact into the EN of a `MOVE` of `n` into `y`.
fn boxes_below_a_coil() -> String {
    let body = r#"<LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
<contact localId="2" negated="false"><position x="20" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>x</variable></contact>
<coil localId="3" negated="false"><position x="200" y="10"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>run</variable></coil>
<contact localId="4" negated="false"><position x="60" y="60"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>run</variable></contact>
<block localId="5" typeName="Pass" instanceName="p"><position x="100" y="60"/>
<inputVariables><variable formalParameter="IN"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></variable></inputVariables>
<inOutVariables/>
<outputVariables><variable formalParameter="Q"><connectionPointOut/></variable></outputVariables>
</block>
<coil localId="6" negated="false"><position x="200" y="60"/><connectionPointIn><connection refLocalId="5" formalParameter="Q"/></connectionPointIn><connectionPointOut/><variable>seen</variable></coil>
<contact localId="7" negated="false" edge="rising"><position x="60" y="160"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>run</variable></contact>
<coil localId="8" negated="false"><position x="200" y="160"/><connectionPointIn><connection refLocalId="7"/></connectionPointIn><connectionPointOut/><variable>pulse</variable></coil>
<contact localId="9" negated="false"><position x="60" y="210"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>run</variable></contact>
<inVariable localId="10"><position x="60" y="240"/><connectionPointOut/><expression>n</expression></inVariable>
<block localId="11" typeName="MOVE"><position x="100" y="210"/>
<inputVariables><variable formalParameter="EN"><connectionPointIn><connection refLocalId="9"/></connectionPointIn></variable>
<variable formalParameter="IN"><connectionPointIn><connection refLocalId="10"/></connectionPointIn></variable></inputVariables>
<inOutVariables/>
<outputVariables><variable formalParameter="ENO"><connectionPointOut/></variable><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
</block>
<outVariable localId="12"><position x="200" y="240"/><connectionPointIn><connection refLocalId="11" formalParameter="OUT"/></connectionPointIn><expression>y</expression></outVariable>
<rightPowerRail localId="13"><position x="240" y="0"/><connectionPointIn><connection refLocalId="3"/><connection refLocalId="6"/><connection refLocalId="8"/></connectionPointIn></rightPowerRail>
</LD>"#;
    plcopen_program(
        PASS_FB,
        &[
            ("x", "BOOL"),
            ("run", "BOOL"),
            ("seen", "BOOL"),
            ("pulse", "BOOL"),
            ("n", "INT"),
            ("y", "INT"),
            ("p", "Pass"),
        ],
        body,
    )
}

/// Boxes and edge contacts run where they stand in the network's evaluation order (IEC 61131-3 ed. 2
/// 4.1.3 "Evaluation of networks": an element once all its inputs are evaluated; ladderc breaks ties
/// top to bottom, then left to right; Beremiz's `PLCGenerator.py` writes one statement per element
/// in that order, a block's call where its output is first needed): below the coil `run`, the block
/// `p`, the rising-edge contact and the `MOVE` all see `run` as the coil wrote it, in the scan `x`
/// comes on (cycle 2), as plain contacts there do since round 30. The edge contact gives one pulse
/// per edge (cycle 2 only, though `run` stays TRUE at 3). Before: they all ran before the coil and
/// saw `run` one scan late (`seen` and `y` from cycle 3, `pulse` at cycle 3).
#[test]
fn boxes_and_edge_contacts_below_a_coil_read_what_it_wrote() {
    let trace = run_xml_with_stimulus(
        &boxes_below_a_coil(),
        7,
        "0,m.n,5\n2,m.x,TRUE\n4,m.x,FALSE\n5,m.n,7\n6,m.x,TRUE\n",
        &["m.x", "m.run", "m.seen", "m.pulse", "m.y"],
    );
    assert_eq!(col(&trace, "m.run"), [0, 0, 1, 1, 0, 0, 1], "{trace}");
    assert_eq!(col(&trace, "m.seen"), [0, 0, 1, 1, 0, 0, 1], "{trace}");
    assert_eq!(col(&trace, "m.pulse"), [0, 0, 1, 0, 0, 0, 1], "{trace}");
    assert_eq!(
        column(&trace, "m.y"),
        [0.0, 0.0, 5.0, 5.0, 5.0, 5.0, 7.0],
        "{trace}"
    );
}

/// The feedback side: a block placed before its own output coil still reads the coil's variable from
/// before the coil. `tick AND NOT q` into `p` (`Pass`), `p.Q` into coil `q`: `q` toggles every scan
/// while `tick` is TRUE (as before round 31). Below, sharing the contact on `tick`, a falling-edge
/// contact on `q` (after the coil: it sees what the coil wrote) drives coil `fell`, TRUE in each scan
/// `q` went FALSE (cycles 2 and 4). Before: the edge contact ran before the coil and saw `q` a scan
/// late (`fell` TRUE at cycle 3 only).
#[test]
fn a_box_before_its_own_output_coil_reads_the_value_from_before_the_coil() {
    let body = r#"<LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
<contact localId="2" negated="false"><position x="20" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>tick</variable></contact>
<contact localId="3" negated="true"><position x="60" y="10"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>q</variable></contact>
<block localId="4" typeName="Pass" instanceName="p"><position x="100" y="10"/>
<inputVariables><variable formalParameter="IN"><connectionPointIn><connection refLocalId="3"/></connectionPointIn></variable></inputVariables>
<inOutVariables/>
<outputVariables><variable formalParameter="Q"><connectionPointOut/></variable></outputVariables>
</block>
<coil localId="5" negated="false"><position x="200" y="10"/><connectionPointIn><connection refLocalId="4" formalParameter="Q"/></connectionPointIn><connectionPointOut/><variable>q</variable></coil>
<contact localId="6" negated="false" edge="falling"><position x="60" y="60"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>q</variable></contact>
<coil localId="8" negated="false"><position x="200" y="60"/><connectionPointIn><connection refLocalId="6"/></connectionPointIn><connectionPointOut/><variable>fell</variable></coil>
<rightPowerRail localId="9"><position x="240" y="0"/><connectionPointIn><connection refLocalId="5"/><connection refLocalId="8"/></connectionPointIn></rightPowerRail>
</LD>"#;
    let text = plcopen_program(
        PASS_FB,
        &[
            ("tick", "BOOL"),
            ("q", "BOOL"),
            ("fell", "BOOL"),
            ("p", "Pass"),
        ],
        body,
    );
    let trace = run_xml_with_stimulus(
        &text,
        6,
        "1,m.tick,TRUE\n5,m.tick,FALSE\n",
        &["m.tick", "m.q", "m.fell"],
    );
    assert_eq!(col(&trace, "m.q"), [0, 1, 0, 1, 0, 0], "{trace}");
    assert_eq!(col(&trace, "m.fell"), [0, 0, 1, 0, 1, 0], "{trace}");
}
