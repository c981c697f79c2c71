//! Round 27 of unseen projects (issue #13), SIMATIC AX's edition-3 object-oriented ST, run end to
//! end through `ladderc run` / `ladderc check`:
//! - the assignment attempt `r ?= e;` (IEC 61131-3 ed. 3, 6.6.6.7): an interface takes the
//!   instance another interface (or an instance, or a method's interface result) holds when its
//!   class implements it, else NULL; a `REF_TO C` takes it when it is a `C` or derives from it,
//!   else NULL (before: E0101 at the `?`);
//! - a METHOD (or action) that no POU calls is checked as when it is called, also in a library of
//!   classes without a program (before: `check` said clean, exit 0, with an unknown function and an
//!   undeclared variable in it), each error once when it is also called inside its block;
//! - a member inherited from a base declared in another file (`_abs.CountForward()` in a CLASS or
//!   FUNCTION_BLOCK that EXTENDS it) is the base's variable (before: E1032, a library qualifier);
//! - two METHODs of one name in a class (SIMATIC AX's overloading, not IEC) are one E1084 at the
//!   second (before: accepted there, then E1011/E1021/E0106 at the calls);
//! - a method called inside its own class with positional arguments after its inputs binds its
//!   outputs in order (`THIS.Bounds(a, b)`, IEC ed. 3 6.6.1.4.2; before: E1011, while the same
//!   call from outside the class ran);
//! - a nested namespace named relative to an enclosing one (`Types.BeltData` inside `NAMESPACE
//!   Plant.Line` for `NAMESPACE Plant.Line.Types`, IEC ed. 3 6.9; before: E1032).

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

const SHAPES: &str = "INTERFACE IShape
    METHOD Area : INT END_METHOD
END_INTERFACE
INTERFACE INamed
    METHOD Id : INT END_METHOD
END_INTERFACE
CLASS Square IMPLEMENTS IShape, INamed
    VAR PUBLIC side : INT := 3; END_VAR
    METHOD PUBLIC Area : INT
        Area := side * side;
    END_METHOD
    METHOD PUBLIC Id : INT
        Id := 7;
    END_METHOD
END_CLASS
CLASS BigSquare EXTENDS Square
END_CLASS
CLASS Circle IMPLEMENTS IShape
    METHOD PUBLIC Area : INT
        Area := 5;
    END_METHOD
END_CLASS
CLASS Holder
    VAR PUBLIC s : IShape; END_VAR
    METHOD PUBLIC Get : IShape
        Get := s;
    END_METHOD
END_CLASS
";

/// `named ?= shape;` checks the class of the instance `shape` holds when it runs: a Circle (no
/// INamed) leaves `named` NULL, a Square gives a usable `named` whose method runs; an instance
/// and a method returning an interface are attempted from too.
#[test]
fn an_assignment_attempt_to_an_interface_checks_the_instance() {
    let src = format!(
        "{SHAPES}
PROGRAM Main
    VAR
        sq : Square; big : BigSquare; ci : Circle; h : Holder;
        shape : IShape;
        named : INamed;
        circleNull, squareSet, bigSet : BOOL;
        id, viaGet : INT;
    END_VAR
    shape := ci;
    named ?= shape;
    circleNull := named = NULL;
    shape := sq;
    named ?= shape;
    squareSet := named <> NULL;
    IF named <> NULL THEN id := named.Id(); END_IF;
    named ?= big;
    bigSet := named <> NULL;
    named := 0;
    h.s := sq;
    named ?= h.Get();
    IF named <> NULL THEN viaGet := named.Id() + 1; END_IF;
END_PROGRAM
"
    );
    let (trace, stderr) = run_text(
        "attempt.st",
        &src,
        1,
        "Main.circleNull,Main.squareSet,Main.bigSet,Main.id,Main.viaGet",
    );
    assert_eq!(column(&trace, "Main.circleNull"), [1.0], "{stderr}");
    assert_eq!(column(&trace, "Main.squareSet"), [1.0]);
    assert_eq!(column(&trace, "Main.bigSet"), [1.0]);
    assert_eq!(column(&trace, "Main.id"), [7.0]);
    assert_eq!(column(&trace, "Main.viaGet"), [8.0]);
    assert!(!stderr.contains("NULL reference"), "{stderr}");
}

/// `rSq ?= shape;` with `rSq : REF_TO Square`: a BigSquare (derived from Square) gives a
/// reference to it; a Circle gives NULL.
#[test]
fn an_assignment_attempt_to_a_reference_accepts_the_class_and_derived_ones() {
    let src = format!(
        "{SHAPES}
PROGRAM Main
    VAR
        big : BigSquare; ci : Circle;
        shape : IShape;
        rSq : REF_TO Square;
        side : INT;
        circleNull : BOOL;
    END_VAR
    big.side := 4;
    shape := big;
    rSq ?= shape;
    IF rSq <> NULL THEN side := rSq^.side; END_IF;
    shape := ci;
    rSq ?= shape;
    circleNull := rSq = NULL;
END_PROGRAM
"
    );
    let (trace, stderr) = run_text("attempt_ref.st", &src, 1, "Main.side,Main.circleNull");
    assert_eq!(column(&trace, "Main.side"), [4.0], "{stderr}");
    assert_eq!(column(&trace, "Main.circleNull"), [1.0]);
}

/// An attempt to something that is no interface or reference is one located E1083.
#[test]
fn an_assignment_attempt_to_a_number_is_e1083() {
    let src = format!(
        "{SHAPES}
PROGRAM Main
    VAR shape : IShape; n : INT; END_VAR
    n ?= shape;
END_PROGRAM
"
    );
    let (code, lines) = check_text("attempt_bad.st", &src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("attempt_bad.st:32:5") && lines[0].contains("E1083"),
        "{lines:?}"
    );
}

/// A library of one class whose method nothing calls: its unknown function and undeclared
/// variable are the errors a call would give, one each.
#[test]
fn a_method_nothing_calls_is_checked() {
    let src = "CLASS Hasher
    VAR PUBLIC n : INT; END_VAR
    METHOD PUBLIC Run
        VAR_INPUT s : INT; END_VAR
        n := NoSuchFunction(s);
        n := undeclaredVar + 1;
    END_METHOD
END_CLASS
";
    let (code, lines) = check_text("hasher.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].contains("hasher.st:5:14") && lines[0].contains("E1019"),
        "{lines:?}"
    );
    assert!(
        lines[1].contains("hasher.st:6:14") && lines[1].contains("E1001"),
        "{lines:?}"
    );
}

/// A method called inside its own block only (inlined there) and an uncalled one next to it: the
/// called one's error is reported once, the uncalled one's too; a clean uncalled method changes
/// nothing of the run.
#[test]
fn an_uncalled_method_next_to_called_ones() {
    let src = "FUNCTION_BLOCK FB_Count
    VAR_OUTPUT n : INT; END_VAR
    METHOD Inc
        n := n + Missing;
    END_METHOD
    METHOD PUBLIC Spare
        n := n + Absent(1);
    END_METHOD
    Inc();
END_FUNCTION_BLOCK
";
    let (code, lines) = check_text("count.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines
            .iter()
            .any(|l| l.contains("count.st:4:18") && l.contains("E1001")),
        "{lines:?}"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.contains("count.st:7:18") && l.contains("E1019")),
        "{lines:?}"
    );
    let ok = "FUNCTION_BLOCK FB_Count
    VAR_OUTPUT n : INT; END_VAR
    METHOD PUBLIC Spare
        n := n + 100;
    END_METHOD
    n := n + 1;
END_FUNCTION_BLOCK
PROGRAM Main
    VAR c : FB_Count; v : INT; END_VAR
    c();
    v := c.n;
END_PROGRAM
";
    let (trace, stderr) = run_text("count_ok.st", ok, 3, "Main.v");
    assert_eq!(column(&trace, "Main.v"), [1.0, 2.0, 3.0], "{stderr}");
}

/// `_enc.Forward()` in a method of a class extending a base of another file, which declares
/// `_enc` PROTECTED: the base's instance counts (a CLASS, then the same as FUNCTION_BLOCKs).
#[test]
fn a_member_inherited_from_another_file_is_called() {
    for (open, close) in [
        ("CLASS", "END_CLASS"),
        ("FUNCTION_BLOCK", "END_FUNCTION_BLOCK"),
    ] {
        let dir = tempfile::tempdir().unwrap();
        write_in(
            dir.path(),
            "Base.st",
            &format!(
                "{open} Tally
    VAR _v : DINT; END_VAR
    METHOD PUBLIC Forward
        _v := _v + 2;
    END_METHOD
    METHOD PUBLIC Value : DINT
        Value := _v;
    END_METHOD
{close}
{open} Axis
    VAR PROTECTED _enc : Tally; END_VAR
    METHOD PUBLIC Pos : DINT
        Pos := _enc.Value();
    END_METHOD
{close}
"
            ),
        );
        write_in(
            dir.path(),
            "Derived.st",
            &format!(
                "{open} LinearAxis EXTENDS Axis
    METHOD PUBLIC Step
        _enc.Forward();
    END_METHOD
{close}
PROGRAM Main
    VAR a : LinearAxis; p : DINT; END_VAR
    a.Step();
    p := a.Pos();
END_PROGRAM
"
            ),
        );
        let (code, out, err) = in_dir(
            dir.path(),
            &[
                "run",
                "Base.st",
                "Derived.st",
                "--cycles",
                "3",
                "--watch",
                "Main.p",
            ],
        );
        assert_eq!(code, Some(0), "{open}: {err}");
        assert_eq!(column(&out, "Main.p"), [2.0, 4.0, 6.0], "{open}: {err}");
    }
}

/// SIMATIC AX overloads `SetTD(s)` / `SetTD(s, k)` and `Bad(value)` / `Bad() : BOOL`: one E1084
/// at each second declaration, nothing at the calls (the first is the one compiled).
#[test]
fn a_method_declared_twice_is_one_e1084() {
    let src = "CLASS Sig
    VAR _bad : BOOL; END_VAR
    METHOD PROTECTED Bad
        VAR_INPUT value : BOOL; END_VAR
        _bad := value;
    END_METHOD
    METHOD PUBLIC Bad : BOOL
        Bad := _bad;
    END_METHOD
    METHOD PUBLIC Update
        VAR_INPUT ok : BOOL; END_VAR
        THIS.Bad(value := NOT ok);
    END_METHOD
    METHOD PUBLIC SetTD
        VAR_INPUT s : DINT; END_VAR
    END_METHOD
    METHOD PUBLIC SetTD
        VAR_INPUT s : DINT; k : DINT; END_VAR
    END_METHOD
END_CLASS
PROGRAM Main
    VAR s : Sig; b : BOOL; END_VAR
    s.Update(ok := FALSE);
    b := s.Bad();
    s.SetTD(s := 3, k := 5);
END_PROGRAM
";
    let (code, lines) = check_text("overload.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].contains("overload.st:7:19") && lines[0].contains("E1084"),
        "{lines:?}"
    );
    assert!(
        lines[1].contains("overload.st:17:19") && lines[1].contains("E1084"),
        "{lines:?}"
    );
}

/// `THIS.Bounds(a, b)` and `Scale(3, a)` inside the class: the positional arguments after the
/// inputs receive the outputs in declaration order.
#[test]
fn positional_outputs_of_a_method_called_in_its_own_class() {
    let src = "CLASS K
    VAR PUBLIC r, s : INT; END_VAR
    METHOD PRIVATE Bounds
        VAR_OUTPUT lo : INT; hi : INT; END_VAR
        lo := 1; hi := 9;
    END_METHOD
    METHOD PRIVATE Scale
        VAR_INPUT k : INT; END_VAR
        VAR_OUTPUT y : INT; END_VAR
        y := k * 7;
    END_METHOD
    METHOD PUBLIC Run
        VAR_TEMP a, b : INT; END_VAR
        THIS.Bounds(a, b);
        r := a * 100 + b;
        Scale(3, a);
        s := a;
    END_METHOD
END_CLASS
PROGRAM Main
    VAR k : K; r, s : INT; END_VAR
    k.Run();
    r := k.r;
    s := k.s;
END_PROGRAM
";
    let (trace, stderr) = run_text("bounds.st", src, 1, "Main.r,Main.s");
    assert_eq!(column(&trace, "Main.r"), [109.0], "{stderr}");
    assert_eq!(column(&trace, "Main.s"), [21.0], "{stderr}");
}

/// `Types.Belt` inside `NAMESPACE Plant.Line` names the type of `NAMESPACE Plant.Line.Types`:
/// its initial value is read.
#[test]
fn a_nested_namespace_named_relatively() {
    let src = "NAMESPACE Plant.Line.Types
    TYPE Belt : STRUCT
        speed : REAL := 2.5;
    END_STRUCT;
    END_TYPE
END_NAMESPACE
NAMESPACE Plant.Line
    PROGRAM Main
        VAR d : Types.Belt; s : REAL; END_VAR
        s := d.speed * 2.0;
    END_PROGRAM
END_NAMESPACE
";
    let (trace, stderr) = run_text("belt.st", src, 1, "Main.s");
    assert_eq!(column(&trace, "Main.s"), [5.0], "{stderr}");
}
