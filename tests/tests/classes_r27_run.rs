//! Round 27 of unseen projects (issue #13): IEC 61131-3 ed. 3 classes and function blocks
//! (6.6.5, 6.6.6), run end to end through `ladderc run`:
//! - a method's VAR_IN_OUT of its own class, or of its base class in a derived class, compiles
//!   and runs: the private methods, protected variables and property accessors of the other
//!   instance are reached through it (IEC and CODESYS give a class access to the PRIVATE members
//!   of every instance of itself); a `REF_TO` of the own class and a method's local VAR of the own
//!   class too (before: E9002, the C used the struct of a class with a base before declaring it,
//!   and a method's local kept a copy of its initial value inside the instance);
//! - a class or block that holds an instance of itself by value, directly or through another
//!   block, a structure or an array, is one E1080 per cycle naming the chain, at `check`, `build`
//!   and `run` alike (before: `check` passed and the C compiler failed, E9002);
//! - `REF(THIS)`, `ADR(THIS)` (THIS: IEC's reference to the own instance, CODESYS's pointer to it)
//!   give the instance's address, as `THIS` and `REF(THIS^)` do (before: E3103);
//! - a class's PUBLIC variable is set in a structured initial value, in a configuration's
//!   VAR_GLOBAL as in a program's VAR (before: E1025 "C has no field or input"); a PRIVATE one is
//!   E1025 naming the specifier;
//! - the access specifiers CODESYS writes for methods, properties and accessors in PLCopen XML
//!   (`<AccessModifiers Private="true" />`) are checked as in text (before: not read, W3002), and
//!   a TwinCAT `.TcPOU`'s `METHOD PRIVATE` is (as before) E1021 from another POU.

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

/// The family of the sweep's repro: `Base` with PRIVATE, PROTECTED and PUBLIC members, a
/// method taking a `Base` in-out, `Derived` (through `Mid`) taking one too. By hand: b.p = 5,
/// b.q = 3; x = Priv() 30 + o.Priv() 30 + Prot() 105 = 165; `d.Use(other := b)` sets b.p to 6
/// and d.p to 9 (its property's PROTECTED setter), then y = Prot() 109 + other.Prot() 106 +
/// other.p 6 + other.Level 6 = 227; z = b.Level = 6; w = d.Level = 9.
#[test]
fn methods_take_instances_of_their_own_class_and_its_base() {
    let src = "CLASS Base
VAR PUBLIC n : INT; END_VAR
VAR PROTECTED p : INT := 5; END_VAR
VAR PRIVATE q : INT := 3; END_VAR
METHOD PRIVATE Priv : INT
    Priv := q * 10;
END_METHOD
METHOD PROTECTED Prot : INT
    Prot := p + 100;
END_METHOD
METHOD PUBLIC Pub : INT
VAR_IN_OUT o : Base; END_VAR
    Pub := Priv() + o.Priv() + THIS.Prot();
END_METHOD
PROPERTY Level : INT
GET
    Level := p;
END_GET
SET PROTECTED
    p := Level;
END_SET
END_PROPERTY
END_CLASS

CLASS Mid EXTENDS Base
END_CLASS

CLASS Derived EXTENDS Mid
METHOD PUBLIC Use : INT
VAR_IN_OUT other : Base; END_VAR
    other.p := other.p + 1;
    Level := 9;
    Use := Prot() + other.Prot() + other.p + other.Level;
END_METHOD
END_CLASS

PROGRAM Main
VAR
    b : Base;
    d : Derived;
    x, y, z, w : INT;
END_VAR
x := b.Pub(o := b);
y := d.Use(other := b);
z := b.Level;
w := d.Level;
END_PROGRAM
";
    let (trace, stderr) = run_text("family.st", src, 1, "Main.x,Main.y,Main.z,Main.w");
    assert_eq!(column(&trace, "Main.x"), [165.0], "{stderr}");
    assert_eq!(column(&trace, "Main.y"), [227.0], "{stderr}");
    assert_eq!(column(&trace, "Main.z"), [6.0], "{stderr}");
    assert_eq!(column(&trace, "Main.w"), [9.0], "{stderr}");
}

/// A class with a derived class (so its struct is read through the base's) whose method takes
/// an in-out of its own class: `a.Take(from := c)` moves c's amount into a, each scan.
#[test]
fn an_in_out_of_the_own_class_in_a_class_with_a_derived_class() {
    let src = "CLASS Tank
VAR PUBLIC amount : INT; END_VAR
METHOD PUBLIC Take
VAR_IN_OUT from : Tank; END_VAR
    amount := amount + from.amount;
    from.amount := 0;
END_METHOD
END_CLASS
CLASS BigTank EXTENDS Tank
END_CLASS
PROGRAM Main
VAR a, c : Tank; big : BigTank; total : INT; END_VAR
c.amount := c.amount + 4;
a.Take(from := c);
total := a.amount + c.amount;
END_PROGRAM
";
    let (trace, stderr) = run_text("tank.st", src, 3, "Main.a.amount,Main.c.amount,Main.total");
    assert_eq!(
        column(&trace, "Main.a.amount"),
        [4.0, 8.0, 12.0],
        "{stderr}"
    );
    assert_eq!(column(&trace, "Main.c.amount"), [0.0, 0.0, 0.0], "{stderr}");
    assert_eq!(column(&trace, "Main.total"), [4.0, 8.0, 12.0], "{stderr}");
}

/// A derived class's method reads a property and calls a PROTECTED method of a base-class
/// instance given as in-out (CODESYS: PROTECTED is reached from the derived blocks, through any
/// instance).
#[test]
fn a_property_is_read_through_an_in_out_of_the_base_class() {
    let src = "CLASS Sensor
VAR PROTECTED raw : INT := 7; END_VAR
PROPERTY Value : INT
GET
    Value := raw * 2;
END_GET
END_PROPERTY
METHOD PROTECTED Offset : INT
    Offset := 100;
END_METHOD
END_CLASS
CLASS Pair EXTENDS Sensor
METHOD PUBLIC Sum : INT
VAR_IN_OUT other : Sensor; END_VAR
    Sum := Value + other.Value + other.Offset();
END_METHOD
END_CLASS
PROGRAM Main
VAR s : Sensor; p : Pair; x : INT; END_VAR
x := p.Sum(other := s);
END_PROGRAM
";
    let (trace, stderr) = run_text("pair.st", src, 1, "Main.x");
    assert_eq!(column(&trace, "Main.x"), [128.0], "{stderr}");
}

/// A PRIVATE method of another instance of the same class, through an in-out (IEC 61131-3 ed. 3
/// 6.6.5: PRIVATE is per class, not per instance).
#[test]
fn a_private_method_of_another_instance_of_the_same_class() {
    let src = "CLASS Account
VAR PRIVATE balance : INT; END_VAR
METHOD PRIVATE Secret : INT
    Secret := balance;
END_METHOD
METHOD PUBLIC Deposit
VAR_INPUT n : INT; END_VAR
    balance := balance + n;
END_METHOD
METHOD PUBLIC Compare : INT
VAR_IN_OUT other : Account; END_VAR
    Compare := Secret() - other.Secret();
END_METHOD
END_CLASS
CLASS Savings EXTENDS Account
END_CLASS
PROGRAM Main
VAR a, b : Account; d : INT; END_VAR
a.Deposit(n := 10);
b.Deposit(n := 3);
d := a.Compare(other := b);
END_PROGRAM
";
    let (trace, stderr) = run_text("account.st", src, 2, "Main.d");
    assert_eq!(column(&trace, "Main.d"), [7.0, 14.0], "{stderr}");
}

/// A class holding a `REF_TO` of its own class (a linked list) and a method with a local VAR of
/// its own class: neither is an instance inside the instance.
#[test]
fn a_reference_and_a_method_local_of_the_own_class() {
    let src = "CLASS Node
VAR PUBLIC v : INT; next : REF_TO Node; END_VAR
METHOD PUBLIC Total : INT
VAR r : REF_TO Node; scratch : Node; END_VAR
    scratch.v := scratch.v + 1000;
    Total := v;
    r := next;
    WHILE r <> NULL DO
        Total := Total + r^.v;
        r := r^.next;
    END_WHILE
    Total := Total + scratch.v;
END_METHOD
END_CLASS
CLASS Tail EXTENDS Node
END_CLASS
PROGRAM Main
VAR a, b, c : Node; x : INT; END_VAR
a.v := 1; b.v := 20; c.v := 300;
a.next := REF(b); b.next := REF(c);
x := a.Total();
END_PROGRAM
";
    let (trace, stderr) = run_text("list.st", src, 2, "Main.x");
    assert_eq!(column(&trace, "Main.x"), [1321.0, 1321.0], "{stderr}");
}

/// A class and a block holding themselves by value: one E1080 each at `check`, naming the
/// variable; `build` and `run` say the same and stop before the C compiler.
#[test]
fn a_class_or_block_holding_itself_is_one_error_each() {
    let src = "CLASS Node
VAR PUBLIC v : INT; next : Node; END_VAR
END_CLASS
FUNCTION_BLOCK FbSelf
VAR me : FbSelf; END_VAR
END_FUNCTION_BLOCK
PROGRAM Main
VAR n : Node; f : FbSelf; END_VAR
n.v := 1;
n.next.v := 2;
f();
END_PROGRAM
";
    let (code, lines) = check_text("selfcls.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let want = [
        "selfcls.st:2:21: error[E1080]: class `Node` contains an instance of itself (through `Node.next`)",
        "selfcls.st:5:5: error[E1080]: function block `FbSelf` contains an instance of itself (through `FbSelf.me`)",
    ];
    assert_eq!(lines.len(), want.len(), "{lines:?}");
    for (got, want) in lines.iter().zip(want) {
        assert!(got.starts_with(want), "{lines:?}");
    }
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "selfcls.st", src);
    for args in [
        &["build", "selfcls.st", "-o", "out"][..],
        &["run", "selfcls.st", "--cycles", "1"][..],
    ] {
        let (code, _, stderr) = in_dir(dir.path(), args);
        assert_eq!(code, Some(1), "{args:?}: {stderr}");
        assert_eq!(
            stderr.matches("error[E1080]").count(),
            2,
            "{args:?}: {stderr}"
        );
        assert!(!stderr.contains("E9002"), "{args:?}: {stderr}");
    }
}

/// A cycle through another block, a structure and an array: one E1080 at the variable closing
/// it, naming the chain from the block.
#[test]
fn a_cycle_through_a_block_a_structure_and_an_array_names_the_chain() {
    let src = "TYPE S : STRUCT a : ARRAY[0..1] OF A; END_STRUCT; END_TYPE
FUNCTION_BLOCK A
VAR b : B; k : INT; END_VAR
k := 1;
END_FUNCTION_BLOCK
FUNCTION_BLOCK B
VAR s : S; END_VAR
END_FUNCTION_BLOCK
PROGRAM Main
VAR x : A; END_VAR
x();
END_PROGRAM
";
    let (code, lines) = check_text("chain.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with(
            "chain.st:1:17: error[E1080]: function block `A` contains an instance of itself \
             (through `A.b` -> `B.s` -> `S.a`)"
        ),
        "{lines:?}"
    );
}

/// `REF(THIS)`, `ADR(THIS)`, `REF(THIS^)` and `p := THIS` in methods: the instance's address;
/// `THIS^.z` and `THIS.z` its variable.
#[test]
fn ref_and_adr_of_this_give_the_instance() {
    let src = "CLASS C
VAR PUBLIC z : INT; END_VAR
METHOD PUBLIC Me : REF_TO C
  Me := REF(THIS);
END_METHOD
METHOD PUBLIC Me2 : REF_TO C
  Me2 := REF(THIS^);
END_METHOD
METHOD PUBLIC Me3 : POINTER TO C
  Me3 := ADR(THIS);
END_METHOD
METHOD PUBLIC Me4 : POINTER TO C
VAR p : POINTER TO C; END_VAR
  p := THIS;
  Me4 := p;
END_METHOD
METHOD PUBLIC Sum : INT
  Sum := THIS^.z + THIS.z;
END_METHOD
END_CLASS
PROGRAM Main
VAR c : C; r : REF_TO C; p : POINTER TO C; x, y, w, v, u : INT; END_VAR
c.z := 4; r := c.Me(); x := r^.z;
r := c.Me2(); y := r^.z + 1;
p := c.Me3(); w := p^.z + 2;
p := c.Me4(); v := p^.z + 3;
u := c.Sum();
END_PROGRAM
";
    let (trace, stderr) = run_text("reft.st", src, 1, "Main.x,Main.y,Main.w,Main.v,Main.u");
    assert_eq!(column(&trace, "Main.x"), [4.0], "{stderr}");
    assert_eq!(column(&trace, "Main.y"), [5.0], "{stderr}");
    assert_eq!(column(&trace, "Main.w"), [6.0], "{stderr}");
    assert_eq!(column(&trace, "Main.v"), [7.0], "{stderr}");
    assert_eq!(column(&trace, "Main.u"), [8.0], "{stderr}");
}

/// `REF(THIS)` in a function block's body and `ADR(THIS)` in a derived block's: the instance.
#[test]
fn ref_of_this_in_block_bodies() {
    let src = "FUNCTION_BLOCK B
VAR_OUTPUT me : REF_TO B; k : INT := 3; END_VAR
me := REF(THIS);
END_FUNCTION_BLOCK
FUNCTION_BLOCK D EXTENDS B
VAR_OUTPUT pd : POINTER TO D; END_VAR
pd := ADR(THIS);
SUPER^();
END_FUNCTION_BLOCK
PROGRAM Main
VAR d : D; x, y : INT; END_VAR
d();
x := d.me^.k;
y := d.pd^.k + 1;
END_PROGRAM
";
    let (trace, stderr) = run_text("refb.st", src, 1, "Main.x,Main.y");
    assert_eq!(column(&trace, "Main.x"), [3.0], "{stderr}");
    assert_eq!(column(&trace, "Main.y"), [4.0], "{stderr}");
}

/// A class's PUBLIC variable in the structured initial value of a configuration's global and of
/// a program's variable.
#[test]
fn a_public_class_variable_is_set_in_an_initial_value() {
    let src = "CLASS C
  VAR PUBLIC z : INT; END_VAR
  METHOD PUBLIC Get : INT
    Get := z;
  END_METHOD
END_CLASS
PROGRAM P
VAR_EXTERNAL c1 : C; END_VAR
VAR c2 : C := (z := 5); r, s : INT; END_VAR
r := c1.Get();
s := c2.Get();
END_PROGRAM
CONFIGURATION K
VAR_GLOBAL c1 : C := (z := 1); END_VAR
RESOURCE R ON PLC
VAR_GLOBAL c3 : C := (z := 9); END_VAR
TASK T(INTERVAL := T#10ms);
PROGRAM I WITH T : P;
END_RESOURCE
END_CONFIGURATION
";
    let (trace, stderr) = run_text("cls2.st", src, 1, "I.r,I.s,c3.z");
    assert_eq!(column(&trace, "I.r"), [1.0], "{stderr}");
    assert_eq!(column(&trace, "I.s"), [5.0], "{stderr}");
    assert_eq!(column(&trace, "c3.z"), [9.0], "{stderr}");
}

/// A PRIVATE class variable in an initial value: E1025 naming the specifier.
#[test]
fn a_private_class_variable_in_an_initial_value_is_an_error() {
    let src = "CLASS C
  VAR PUBLIC z : INT; END_VAR
  VAR PRIVATE h : INT; END_VAR
END_CLASS
PROGRAM P
VAR c2 : C := (z := 5, h := 2); END_VAR
c2.z := 1;
END_PROGRAM
";
    let (code, lines) = check_text("priv.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "priv.st:6:24: error[E1025]: `h` is PRIVATE to `C`: an initial value sets only its PUBLIC variables"
        ),
        "{lines:?}"
    );
}

/// The access specifier of a method in CODESYS's PLCopen XML (`<AccessModifiers Private="true" />`
/// in the vendor data of the method's interface) is checked as `METHOD PRIVATE` in text: a call
/// from another POU is E1021 (before: not read, the call compiled, and W3002 said the block was
/// ignored).
#[test]
fn a_private_method_in_plcopen_xml_is_not_called_from_outside() {
    let fixture = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/real_gaps/xml_methods.xml");
    let src = std::fs::read_to_string(fixture).unwrap();
    let plain = "<Method name=\"M_Home\" ObjectId=\"7e2d9b40-1c3a-4f5e-8a6b-2c4d6e8f0a13\">\n              <interface />";
    assert!(src.contains(plain));
    let private = src.replace(
        plain,
        "<Method name=\"M_Home\" ObjectId=\"7e2d9b40-1c3a-4f5e-8a6b-2c4d6e8f0a13\">\n              <interface><addData><data name=\"http://www.3s-software.com/plcopenxml/accessmodifiers\" handleUnknown=\"implementation\"><AccessModifiers Private=\"true\" /></data></addData></interface>",
    );
    let (code, lines) = check_text("m.xml", &private);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "m.xml:63:10: error[E1021]: METHOD `M_Home` is PRIVATE to `FB_Axis`: callable only in `FB_Axis` itself"
        ),
        "{lines:?}"
    );
    // PUBLIC (and INTERNAL) restrict nothing: the project compiles, without W3002
    let public = private.replace("Private=\"true\"", "Public=\"true\"");
    let (code, lines) = check_text("m.xml", &public);
    assert_eq!(code, Some(0), "{lines:?}");
    assert!(!lines.iter().any(|l| l.contains("W3002")), "{lines:?}");
}

/// A TwinCAT `.TcPOU`'s `<Method>` declared `METHOD PRIVATE` is E1021 when called from another
/// POU, as in `.st`.
#[test]
fn a_private_method_in_a_tcpou_is_not_called_from_outside() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "FB_A.TcPOU",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>
<TcPlcObject Version=\"1.1.0.1\">
  <POU Name=\"FB_A\" Id=\"{1}\" SpecialFunc=\"None\">
    <Declaration><![CDATA[FUNCTION_BLOCK FB_A
VAR n : INT := 3; END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[]]></ST>
    </Implementation>
    <Method Name=\"M\" Id=\"{2}\">
      <Declaration><![CDATA[METHOD PRIVATE M : INT
]]></Declaration>
      <Implementation>
        <ST><![CDATA[M := n;]]></ST>
      </Implementation>
    </Method>
  </POU>
</TcPlcObject>
",
    );
    write_in(
        dir.path(),
        "MAIN.TcPOU",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>
<TcPlcObject Version=\"1.1.0.1\">
  <POU Name=\"MAIN\" Id=\"{3}\" SpecialFunc=\"None\">
    <Declaration><![CDATA[PROGRAM MAIN
VAR a : FB_A; x : INT; END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[x := a.M();]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
",
    );
    let (code, _, stderr) = in_dir(dir.path(), &["check", "FB_A.TcPOU", "MAIN.TcPOU"]);
    assert_eq!(code, Some(1), "{stderr}");
    assert_eq!(stderr.matches("error[").count(), 1, "{stderr}");
    assert!(
        stderr.contains("MAIN.TcPOU:8:27: error[E1021]: METHOD `M` is PRIVATE to `FB_A`"),
        "{stderr}"
    );
}

/// A property's specifier in CODESYS's PLCopen XML (PROTECTED), overridden by its Get accessor's
/// own (PUBLIC): from another POU the write is E1021, the read compiles.
#[test]
fn a_protected_property_in_plcopen_xml_with_a_public_getter() {
    let fixture = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/real_gaps/xml_methods.xml");
    let src = std::fs::read_to_string(fixture).unwrap();
    let start = src
        .find("<data name=\"http://www.3s-software.com/plcopenxml/method\" handleUnknown=\"implementation\">\n            <Method name=\"M_Home\"")
        .unwrap();
    let end = start + src[start..].find("</data>").unwrap() + "</data>".len();
    let modifier = |m: &str| {
        format!("<addData><data name=\"http://www.3s-software.com/plcopenxml/accessmodifiers\" handleUnknown=\"implementation\"><AccessModifiers {m}=\"true\" /></data></addData>")
    };
    let property = format!(
        "<data name=\"http://www.3s-software.com/plcopenxml/property\" handleUnknown=\"implementation\">
            <Property name=\"P_Pos\" ObjectId=\"7e2d9b40-1c3a-4f5e-8a6b-2c4d6e8f0a99\">
              <interface><returnType><REAL /></returnType>{}</interface>
              <GetAccessor>
                <interface>{}</interface>
                <body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">P_Pos := rPosition;</xhtml></ST></body>
              </GetAccessor>
              <SetAccessor>
                <body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\">rPosition := P_Pos;</xhtml></ST></body>
              </SetAccessor>
            </Property>
          </data>",
        modifier("Protected"),
        modifier("Public")
    );
    let text = format!("{}{property}{}", &src[..start], &src[end..]).replace(
        "  fbAxis.M_Home();",
        "  fbAxis.P_Pos := 0.0; rLast := fbAxis.P_Pos;",
    );
    let (code, lines) = check_text("p.xml", &text);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "p.xml:68:10: error[E1021]: the Set accessor of PROPERTY `P_Pos` is PROTECTED to `FB_Axis`"
        ),
        "{lines:?}"
    );
}
