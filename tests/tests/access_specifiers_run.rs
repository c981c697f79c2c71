//! Access specifiers of METHODs and PROPERTYs (IEC 61131-3 edition 3, 6.6.5; CODESYS "Method":
//! PRIVATE only within its own block, PROTECTED also within the blocks derived from it, PUBLIC
//! and INTERNAL from anywhere, the project being one namespace). Each behaviour below, before:
//! the specifier read past and ignored, every call accepted.
//! - a PRIVATE method called from its own class's methods, a PROTECTED one from a class derived
//!   from it two levels down (by its own name and through another instance of the base), a
//!   PUBLIC / INTERNAL one and a property's PUBLIC Get from a program: run, values as computed;
//!   a derived class reads and writes its base's PROTECTED variable through another instance of
//!   the base (before: E1021, the variable's owner being another POU);
//! - `inst.M()` of a PRIVATE or PROTECTED method, `inst.P` of a PRIVATE property and
//!   `inst.P := v` of a property whose SET is PROTECTED, from a program or from a derived class
//!   for a PRIVATE one: one E1021 at the member each (before: accepted);
//! - a derived class calling its base's PRIVATE method by its own name (`M()`, `THIS.M()`,
//!   `SUPER.M()`): one E1021 each, once however many classes inherit the call (before: accepted);
//! - a FUNCTION_BLOCK's PRIVATE method called from its own body and from a program.

mod common;
use common::{check_text, column, run_text};

/// Every accepted access runs: a PRIVATE method and a PRIVATE property inside their class
/// (`Pub = Priv() + THIS.Prot() + Secret` = 30 + 105 + 3), PROTECTED methods, the PROTECTED Set
/// of a property and the base's PROTECTED variable `p` from a class two levels below it (also
/// through its instance `peer` of the base: 109 + 120 + 20 + 9), an INTERNAL method and PUBLIC
/// Get accessors from the program.
#[test]
fn allowed_accesses_to_private_protected_and_internal_members_run() {
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
    Pub := Priv() + THIS.Prot() + Secret;
END_METHOD
METHOD INTERNAL Shared : INT
    Shared := 7;
END_METHOD
PROPERTY PRIVATE Secret : INT
GET
    Secret := q;
END_GET
END_PROPERTY
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
VAR PUBLIC peer : Base; END_VAR
METHOD PUBLIC Use : INT
    peer.p := peer.p + 1;
    Level := 9;
    peer.Level := 20;
    Use := Prot() + peer.Prot() + peer.p + Level;
END_METHOD
END_CLASS

PROGRAM Main
VAR
    b : Base;
    d : Derived;
    x, y, z, w : INT;
END_VAR
x := b.Pub();
y := d.Use();
z := b.Shared() + b.Level;
w := d.Level + d.peer.Level;
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "allowed.st",
        src,
        2,
        "Main.x,Main.y,Main.z,Main.w,Main.d.peer.p",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert!(!stderr.contains("warning["), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), vec![138.0, 138.0]);
    assert_eq!(column(&trace, "Main.y"), vec![258.0, 258.0]);
    assert_eq!(column(&trace, "Main.z"), vec![12.0, 12.0]);
    assert_eq!(column(&trace, "Main.w"), vec![29.0, 29.0]);
    assert_eq!(column(&trace, "Main.d.peer.p"), vec![20.0, 20.0]);
}

/// From a program: a PRIVATE and a PROTECTED method, a PRIVATE property read, a property whose
/// SET is PROTECTED written (its PUBLIC Get read is fine); from a derived class: a PRIVATE method
/// of its base through another instance. One E1021 at each member, naming it, its specifier and
/// its class; exit 1.
#[test]
fn private_and_protected_members_are_not_called_from_outside() {
    let src = "CLASS Base
VAR PRIVATE q : INT := 3; END_VAR
METHOD PRIVATE Priv : INT
    Priv := q;
END_METHOD
METHOD PROTECTED Prot : INT
    Prot := 1;
END_METHOD
PROPERTY PRIVATE Secret : INT
GET
    Secret := q;
END_GET
END_PROPERTY
PROPERTY Level : INT
GET
    Level := q;
END_GET
SET PROTECTED
    q := Level;
END_SET
END_PROPERTY
END_CLASS

CLASS Derived EXTENDS Base
VAR PUBLIC peer : Base; END_VAR
METHOD PUBLIC Use : INT
    Use := peer.Priv() + peer.Prot();
END_METHOD
END_CLASS

PROGRAM Main
VAR
    b : Base;
    d : Derived;
    x : INT;
END_VAR
x := b.Priv();
x := b.Prot();
x := b.Secret;
b.Level := 4;
x := b.Level + d.Use();
END_PROGRAM
";
    let (code, lines) = check_text("denied.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let hint = "(hint: call a PUBLIC method of `Base` that uses it, or declare it PUBLIC)";
    assert_eq!(
        lines,
        vec![
            format!("denied.st:27:17: error[E1021]: METHOD `Priv` is PRIVATE to `Base`: callable only in `Base` itself {hint}"),
            format!("denied.st:37:8: error[E1021]: METHOD `Priv` is PRIVATE to `Base`: callable only in `Base` itself {hint}"),
            format!("denied.st:38:8: error[E1021]: METHOD `Prot` is PROTECTED to `Base`: callable only in `Base` and the blocks extending it {hint}"),
            format!("denied.st:39:8: error[E1021]: the Get accessor of PROPERTY `Secret` is PRIVATE to `Base`: callable only in `Base` itself {hint}"),
            format!("denied.st:40:3: error[E1021]: the Set accessor of PROPERTY `Level` is PROTECTED to `Base`: callable only in `Base` and the blocks extending it {hint}"),
        ]
    );
}

/// A class derived from a class calls the base's PRIVATE method as `Priv()`, `SUPER.Priv()` and
/// `THIS.Priv()`: one E1021 each, once although a third class inherits the method again; the
/// base's own PUBLIC method calling it (inherited by both) is fine.
#[test]
fn a_derived_class_does_not_call_its_bases_private_method() {
    let src = "CLASS Base
VAR PRIVATE q : INT := 3; END_VAR
METHOD PRIVATE Priv : INT
    Priv := q;
END_METHOD
METHOD PUBLIC Open : INT
    Open := Priv();
END_METHOD
END_CLASS

CLASS Derived EXTENDS Base
METHOD PUBLIC Use : INT
    Use := Priv() + SUPER.Priv() + THIS.Priv();
END_METHOD
END_CLASS

CLASS Deeper EXTENDS Derived
END_CLASS

PROGRAM Main
VAR
    d : Deeper;
    x : INT;
END_VAR
x := d.Use() + d.Open();
END_PROGRAM
";
    let (code, lines) = check_text("derived.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let msg = "error[E1021]: METHOD `Priv` is PRIVATE to `Base`: callable only in `Base` itself (hint: a derived block does not call its base's PRIVATE methods: call a PUBLIC or PROTECTED method of `Base` that uses it, or declare it PROTECTED)";
    assert_eq!(
        lines,
        vec![
            format!("derived.st:13:12: {msg}"),
            format!("derived.st:13:27: {msg}"),
            format!("derived.st:13:41: {msg}"),
        ]
    );
}

/// A FUNCTION_BLOCK's PRIVATE method runs from its own body (the count rises by 2 per scan);
/// `fb.Bump()` from the program is one E1021.
#[test]
fn a_function_blocks_private_method_runs_inside_and_is_refused_outside() {
    let ok = "FUNCTION_BLOCK FB_Count
VAR_OUTPUT n : INT; END_VAR
n := n + Bump(2);
METHOD PRIVATE Bump : INT
VAR_INPUT k : INT; END_VAR
    Bump := k;
END_METHOD
END_FUNCTION_BLOCK

PROGRAM Main
VAR c : FB_Count; v : INT; END_VAR
c();
v := c.n;
END_PROGRAM
";
    let (trace, stderr) = run_text("fb_ok.st", ok, 3, "Main.v");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "Main.v"), vec![2.0, 4.0, 6.0]);
    let bad = ok.replace("v := c.n;", "v := c.Bump(5);");
    let (code, lines) = check_text("fb_bad.st", &bad);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        lines,
        vec!["fb_bad.st:13:8: error[E1021]: METHOD `Bump` is PRIVATE to `FB_Count`: callable only in `FB_Count` itself (hint: call a PUBLIC method of `FB_Count` that uses it, or declare it PUBLIC)".to_string()]
    );
}
