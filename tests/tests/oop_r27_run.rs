//! Round 27 of unseen projects (issue #13), SIMATIC AX's edition-3 object-oriented ST, run end to
//! end through `ladderc run` / `ladderc check`:
//! - the assignment attempt `r ?= e;` (IEC 61131-3 ed. 3, 6.6.6.7): an interface takes the
//!   instance another interface (or an instance, or a method's interface result) holds when its
//!   class implements it, else NULL; a `REF_TO C` takes it when it is a `C` or derives from it,
//!   else NULL (before: E0101 at the `?`).

mod common;
use common::{check_text, column, run_text};

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
