//! Edition 3's classes (IEC 61131-3 edition 3, 6.6.5): `CLASS [FINAL | ABSTRACT] Name [EXTENDS
//! Base] [IMPLEMENTS I1, I2] ... END_CLASS`, read as a function block without a body. Each
//! behaviour below, before: one E1076 "a CLASS is not compiled" per class (naming a modifier as
//! the class, `CLASS PUBLIC Lamp` gave "CLASS `PUBLIC`"), its text skipped, its instances E1003.
//! - methods with results, inputs and outputs, called as `inst.M(...)` in statements and
//!   expressions, the variables of a class kept in its instance from scan to scan;
//! - `VAR PUBLIC` variables read and written as `inst.x` from another POU (no W1412);
//! - THIS.M() and SUPER.M() (edition 3's spellings, SIMATIC AX), a class extending a class,
//!   FINAL and access modifiers before the name (`CLASS PUBLIC Lamp`, `CLASS FINAL Pump`);
//! - a class implementing an INTERFACE, called through an interface variable;
//! - instances in a program, in another class and in VAR_GLOBAL; a FUNCTION_BLOCK extending a
//!   class (its PROTECTED variables reached in the block's body);
//! - a PRIVATE or PROTECTED variable (a class's VAR without a specifier is PROTECTED) read or
//!   written from another POU: E1021 (before: W0304, the specifier ignored);
//! - an instance of a class called (`inst();`, `inst(x := 1)`): E1018;
//! - a class's own VAR_INPUT / VAR_OUTPUT / VAR_IN_OUT, and statements of its own: E1076.

mod common;
use common::{check_text, column, run_text};

/// A lamp class with a PUBLIC state, a PRIVATE constant and methods with and without result and
/// inputs: the program switches it each scan and reads its result and PUBLIC variables.
#[test]
fn methods_of_a_class_run_on_its_instance() {
    let src = "CLASS PUBLIC Lamp
VAR PUBLIC
    lit : BOOL;
    n : INT;
END_VAR
VAR PRIVATE
    bonus : INT := 7;
END_VAR
METHOD PUBLIC Switch
    lit := NOT lit;
    n := n + 1;
END_METHOD
METHOD PUBLIC Twice : INT
VAR_INPUT x : INT; END_VAR
    Twice := x * 2 + bonus;
END_METHOD
METHOD PUBLIC Split
VAR_INPUT v : INT; END_VAR
VAR_OUTPUT hi, lo : INT; END_VAR
    hi := v / 10;
    lo := v MOD 10;
END_METHOD
END_CLASS

PROGRAM Main
VAR
    l : Lamp;
    x, h, o : INT;
    b : BOOL;
END_VAR
l.Switch();
x := l.Twice(5) + 1;
l.Split(v := 47, hi => h, lo => o);
b := l.lit;
l.n := l.n + 100;
END_PROGRAM
";
    let (trace, stderr) = run_text("lamp.st", src, 2, "Main.x,Main.h,Main.o,Main.b,Main.l.n");
    assert_eq!(column(&trace, "Main.x"), vec![18.0, 18.0], "{stderr}");
    assert_eq!(column(&trace, "Main.h"), vec![4.0, 4.0]);
    assert_eq!(column(&trace, "Main.o"), vec![7.0, 7.0]);
    assert_eq!(column(&trace, "Main.b"), vec![1.0, 0.0]);
    assert_eq!(column(&trace, "Main.l.n"), vec![101.0, 202.0]);
    assert!(!stderr.contains("W1412"), "{stderr}");
    assert!(!stderr.contains("E1076"), "{stderr}");
}

/// A FINAL class extending another: its method calls the base's through `SUPER.Switch()` and its
/// own through `THIS.Switch()` (both run once: the lamp is switched twice, counted twice).
#[test]
fn a_class_extends_a_class_with_this_and_super() {
    let src = "CLASS Lamp
VAR PUBLIC
    lit : BOOL;
    n : INT;
END_VAR
METHOD PUBLIC Switch
    lit := NOT lit;
    n := n + 1;
END_METHOD
END_CLASS

CLASS FINAL Dimmer EXTENDS Lamp
VAR PUBLIC level : INT; END_VAR
METHOD PUBLIC Switch
    SUPER.Switch();
    level := level + 1;
END_METHOD
METHOD PUBLIC Up
    level := level + 10;
    THIS.Switch();
    SUPER.Switch();
END_METHOD
END_CLASS

PROGRAM Main
VAR
    d : Dimmer;
    y : INT;
    b : BOOL;
END_VAR
d.Up();
y := d.level * 100 + d.n;
b := d.lit;
END_PROGRAM
";
    let (trace, stderr) = run_text("dimmer.st", src, 2, "Main.y,Main.b");
    // a scan: level + 10 (Up) + 1 (its own Switch), n + 2 (the base's Switch twice)
    assert_eq!(column(&trace, "Main.y"), vec![1102.0, 2204.0], "{stderr}");
    assert_eq!(column(&trace, "Main.b"), vec![0.0, 0.0]);
}

/// A class implementing an interface, one instance in VAR_GLOBAL called through an interface
/// variable; two instances inside another class; a FUNCTION_BLOCK extending an ABSTRACT class,
/// whose body writes the class's PROTECTED variable and calls its method.
#[test]
fn interfaces_nested_instances_globals_and_a_block_extending_a_class() {
    let src = "INTERFACE ICounter
METHOD Count : INT
VAR_INPUT k : INT; END_VAR
END_METHOD
END_INTERFACE

CLASS Counter IMPLEMENTS ICounter
VAR PUBLIC n : INT; END_VAR
METHOD PUBLIC Count : INT
VAR_INPUT k : INT; END_VAR
    n := n + k;
    Count := n;
END_METHOD
END_CLASS

CLASS Pair
VAR PUBLIC a : Counter; b : Counter; END_VAR
METHOD PUBLIC Both : INT
    Both := a.Count(1) + b.Count(2);
END_METHOD
END_CLASS

CLASS ABSTRACT Shape
VAR PROTECTED corners : INT := 3; END_VAR
METHOD PUBLIC NumCorners : INT
    NumCorners := corners;
END_METHOD
END_CLASS

FUNCTION_BLOCK Square EXTENDS Shape
VAR_INPUT grow : BOOL; END_VAR
VAR_OUTPUT count : INT; END_VAR
IF grow THEN corners := corners + 1; END_IF;
count := NumCorners();
END_FUNCTION_BLOCK

VAR_GLOBAL
    g : Counter;
END_VAR

PROGRAM Main
VAR
    p : Pair;
    i : ICounter;
    sq : Square;
    x, y, z, w : INT;
END_VAR
x := p.Both();
i := g;
y := i.Count(10);
sq(grow := TRUE);
z := sq.count;
w := g.n;
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "shapes.st",
        src,
        2,
        "Main.x,Main.y,Main.z,Main.w,Main.p.b.n",
    );
    assert_eq!(column(&trace, "Main.x"), vec![3.0, 6.0], "{stderr}");
    assert_eq!(column(&trace, "Main.y"), vec![10.0, 20.0]);
    assert_eq!(column(&trace, "Main.z"), vec![4.0, 5.0]);
    assert_eq!(column(&trace, "Main.w"), vec![10.0, 20.0]);
    assert_eq!(column(&trace, "Main.p.b.n"), vec![2.0, 4.0]);
}

/// `x := l.secret` of a `VAR PRIVATE`, `l.hidden := 1` of a class's plain VAR (PROTECTED, as
/// 6.6.5 gives it): one E1021 at each member, exit 1; the same variables inside the class's own
/// methods (also through another instance of the class) compile.
#[test]
fn private_and_protected_variables_are_not_reached_from_outside() {
    let src = "CLASS Lamp
VAR PUBLIC lit : BOOL; END_VAR
VAR PRIVATE secret : INT := 7; END_VAR
VAR hidden : INT; END_VAR
METHOD PUBLIC Copy
VAR_IN_OUT other : Lamp; END_VAR
    other.hidden := secret + hidden;
END_METHOD
END_CLASS

PROGRAM Main
VAR
    l : Lamp;
    x : INT;
END_VAR
x := l.secret;
l.hidden := 1;
x := BOOL_TO_INT(l.lit);
END_PROGRAM
";
    let (code, lines) = check_text("private.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(
        lines,
        vec![
            "private.st:16:8: error[E1021]: `secret` is a PRIVATE variable of class Lamp: not reachable from outside it (hint: read or write it in a method of Lamp (`inst.GetX()`), or declare it in a `VAR PUBLIC` block)".to_string(),
            "private.st:17:3: error[E1021]: `hidden` is a PROTECTED variable of class Lamp: not reachable from outside it (hint: read or write it in a method of Lamp (`inst.GetX()`), or declare it in a `VAR PUBLIC` block)".to_string(),
        ]
    );
}

/// `l();` and `l(x := 1);` of a class instance: one E1018 each, at the instance, naming the class.
#[test]
fn an_instance_of_a_class_is_not_called() {
    let src = "CLASS Lamp
VAR PUBLIC x : INT; END_VAR
METHOD PUBLIC Switch
    x := x + 1;
END_METHOD
END_CLASS

PROGRAM Main
VAR l : Lamp; END_VAR
l();
l(x := 1);
l.Switch();
END_PROGRAM
";
    let (code, lines) = check_text("called.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].starts_with("called.st:10:1: error[E1018]: `l` is an instance of the class Lamp: a class is not called, its methods are"),
        "{lines:?}"
    );
    assert!(
        lines[1].starts_with("called.st:11:1: error[E1018]: "),
        "{lines:?}"
    );
}

/// A class's own VAR_INPUT and statements outside its methods: one E1076 each (at the block's
/// keyword, at the first statement), nothing else.
#[test]
fn a_class_has_no_inputs_and_no_body_of_its_own() {
    let src = "CLASS Lamp
VAR_INPUT lit : BOOL; END_VAR
METHOD PUBLIC Switch
    lit := NOT lit;
END_METHOD
lit := TRUE;
END_CLASS

PROGRAM Main
VAR l : Lamp; END_VAR
l.Switch();
END_PROGRAM
";
    let (code, lines) = check_text("body.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].starts_with("body.st:2:1: error[E1076]: the CLASS `Lamp` declares a VAR_INPUT block: a class has no inputs, outputs or in-outs of its own"),
        "{lines:?}"
    );
    assert!(
        lines[1].starts_with("body.st:6:1: error[E1076]: the CLASS `Lamp` has statements of its own: a class has no body"),
        "{lines:?}"
    );
}

/// A variable named `Class` (a word edition 3 reserves, which older projects use as a name) and
/// a class named after its modifier's position (`CLASS FINAL Pump`) both compile.
#[test]
fn class_stays_a_name_where_a_name_stands() {
    let src = "CLASS FINAL Pump
VAR PUBLIC running : BOOL; END_VAR
METHOD PUBLIC Start
    running := TRUE;
END_METHOD
END_CLASS

PROGRAM Main
VAR
    Class : INT;
    p : Pump;
    r : BOOL;
END_VAR
Class := Class + 1;
p.Start();
r := p.running;
END_PROGRAM
";
    let (trace, stderr) = run_text("named.st", src, 2, "Main.Class,Main.r");
    assert_eq!(column(&trace, "Main.Class"), vec![1.0, 2.0], "{stderr}");
    assert_eq!(column(&trace, "Main.r"), vec![1.0, 1.0]);
}
