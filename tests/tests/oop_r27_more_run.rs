//! Round 27 of unseen projects (issue #13), object orientation and literals, run end to end:
//! - a METHOD, PROPERTY or ACTION named like a variable of its block or class, apart from case or
//!   not (`METHOD Z` next to `VAR z`): one E1002 at the later declaration, exit 1 (before: compiled,
//!   the name meaning the variable or the member depending on where it was read);
//! - a derived instance passed to a METHOD's `VAR_IN_OUT o : Base` (IEC 61131-3 ed. 3 6.6.5: a
//!   derived instance may be used where its base is expected): it runs, and the method's calls
//!   through `o` run the derived overrides (before: E1012 naming the hidden `__M_TAKE_O`);
//! - no diagnostic shows the hidden name of a method's variable: `Take.oVal`, not `__M_TAKE_OVAL`
//!   (before: E1012 and E1080's chain showed `__M_<M>_<X>`, and E1080 came twice for one input);
//! - a character by its code, `CHAR#16#80`, `CHAR#16#FF`, `WCHAR#16#FFFF` (ed. 3 typed literals:
//!   a CHAR is one byte, a WCHAR two; before: E1017 for every code), `CHAR#16#100` is E1017.

mod common;
use common::{check_text, column, run_text};

/// `METHOD Z` next to `VAR z` (and the same spelling, `METHOD z`; a CLASS's; a PROPERTY `Val` next
/// to `val`; an ACTION `Go` next to `go`): one E1002 at the member, naming both, and nothing else.
#[test]
fn a_member_named_like_a_variable_is_declared_twice() {
    let method = |name: &str, kind: &str, end: &str| {
        format!(
            "{kind} FB_A
VAR
  z : INT := 5;
END_VAR
METHOD PUBLIC {name} : INT
{name} := 42;
END_METHOD
{end}
PROGRAM Main
VAR a : FB_A; r : INT; END_VAR
r := a.{name}();
END_PROGRAM
"
        )
    };
    for (src, name, owner) in [
        (
            method("Z", "FUNCTION_BLOCK", "END_FUNCTION_BLOCK"),
            "Z",
            "FB_A",
        ),
        (
            method("z", "FUNCTION_BLOCK", "END_FUNCTION_BLOCK"),
            "z",
            "FB_A",
        ),
        (method("Z", "CLASS", "END_CLASS"), "Z", "FB_A"),
    ] {
        let (code, lines) = check_text("member.st", &src);
        assert_eq!(code, Some(1), "{lines:?}");
        assert_eq!(lines.len(), 1, "{lines:?}");
        assert!(
            lines[0].starts_with(&format!(
                "member.st:5:15: error[E1002]: `{name}` of `{owner}` is declared twice: as a variable and as a method"
            )),
            "{lines:?}"
        );
    }
    let property = "FUNCTION_BLOCK FB_P
VAR
  val : INT := 5;
END_VAR
PROPERTY Val : INT
GET
Val := 42;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : FB_P; r : INT; END_VAR
r := a.Val;
END_PROGRAM
";
    let (code, lines) = check_text("prop.st", property);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "prop.st:5:10: error[E1002]: `Val` of `FB_P` is declared twice: as a variable and as a property"
        ),
        "{lines:?}"
    );
    let action = "FUNCTION_BLOCK FB_G
VAR
  go : INT := 5;
END_VAR
go := go + 1;
END_FUNCTION_BLOCK
ACTIONS FB_G
ACTION Go:
go := 7;
END_ACTION
END_ACTIONS
PROGRAM Main
VAR a : FB_G; END_VAR
a.Go();
END_PROGRAM
";
    let (code, lines) = check_text("act.st", action);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with(
            "act.st:8:8: error[E1002]: `Go` of `FB_G` is declared twice: as a variable and as an action"
        ),
        "{lines:?}"
    );
}

/// A block that inherits a clashing pair reports it once, at the base's declaration.
#[test]
fn an_inherited_clash_is_reported_once() {
    let src = "FUNCTION_BLOCK FB_Base
VAR
  z : INT;
END_VAR
METHOD Z : INT
Z := 1;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_D EXTENDS FB_Base
END_FUNCTION_BLOCK
PROGRAM Main
VAR d : FB_D; r : INT; END_VAR
r := d.Z();
END_PROGRAM
";
    let (code, lines) = check_text("base.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("base.st:5:8: error[E1002]"),
        "{lines:?}"
    );
}

const FAMILY: &str = "FUNCTION_BLOCK FB_Base
VAR n : INT := 1; END_VAR
METHOD Get : INT
Get := n;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_D EXTENDS FB_Base
METHOD Get : INT
Get := n + 10;
END_METHOD
END_FUNCTION_BLOCK
";

/// `u.Take(o := d)` where Take declares `VAR_IN_OUT o : FB_Base` and `d` is an `FB_D`: the method
/// writes `d` itself (`o.n := o.n + k`) and `o.Get()` runs FB_D's override (13, then 15); a base
/// instance runs the base's (2, then 3); a call inside the block with its own derived instance
/// too (11).
#[test]
fn a_derived_instance_is_passed_to_a_methods_in_out_of_its_base() {
    let src = format!(
        "{FAMILY}FUNCTION_BLOCK FB_User
VAR_OUTPUT inner : INT; END_VAR
VAR mine : FB_D; END_VAR
METHOD Take : INT
VAR_IN_OUT o : FB_Base; END_VAR
VAR_INPUT k : INT; END_VAR
o.n := o.n + k;
Take := o.Get();
END_METHOD
inner := Take(o := mine, k := 0);
END_FUNCTION_BLOCK
PROGRAM Main
VAR
  d : FB_D;
  b : FB_Base;
  u : FB_User;
  r, r2, n : INT;
END_VAR
r := u.Take(o := d, k := 2);
r2 := u.Take(o := b, k := 1);
n := d.n;
u();
END_PROGRAM
"
    );
    let (trace, stderr) = run_text("poly.st", &src, 2, "Main.r,Main.r2,Main.n,Main.u.inner");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.r"), [13.0, 15.0], "{trace}");
    assert_eq!(column(&trace, "Main.r2"), [2.0, 3.0], "{trace}");
    assert_eq!(column(&trace, "Main.n"), [3.0, 5.0], "{trace}");
    assert_eq!(column(&trace, "Main.u.inner"), [11.0, 11.0], "{trace}");
}

/// A function block's own `VAR_IN_OUT o : FB_Base` given an `FB_D` dispatches too (it did before:
/// kept working with the methods' conversion).
#[test]
fn a_derived_instance_is_passed_to_a_blocks_in_out_of_its_base() {
    let src = format!(
        "{FAMILY}FUNCTION_BLOCK FB_User
VAR_IN_OUT o : FB_Base; END_VAR
VAR_OUTPUT r : INT; END_VAR
r := o.Get();
END_FUNCTION_BLOCK
PROGRAM Main
VAR d : FB_D; b : FB_Base; u, u2 : FB_User; r, r2 : INT; END_VAR
u(o := d);
r := u.r;
u2(o := b);
r2 := u2.r;
END_PROGRAM
"
    );
    let (trace, stderr) = run_text("poly_fb.st", &src, 1, "Main.r,Main.r2");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.r"), [11.0], "{trace}");
    assert_eq!(column(&trace, "Main.r2"), [1.0], "{trace}");
}

/// A wrong type into a method's in-out is E1012 naming `Take.oVal` as written; a method's input of
/// its own class is one E1080 whose chain reads `Node.Link.nextNode`.
#[test]
fn messages_show_a_methods_variables_as_written() {
    let src = "FUNCTION_BLOCK FB_User
METHOD Take : INT
VAR_IN_OUT oVal : STRING; END_VAR
Take := 1;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR u : FB_User; i : INT; r : INT; END_VAR
r := u.Take(oVal := i);
END_PROGRAM
";
    let (code, lines) = check_text("names.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0]
            .starts_with("names.st:9:21: error[E1012]: Take.oVal of FB_User is STRING, not INT"),
        "{lines:?}"
    );
    let src = "CLASS Node
METHOD PUBLIC Link
VAR_INPUT nextNode : Node; END_VAR
END_METHOD
END_CLASS
PROGRAM Main
VAR n : Node; END_VAR
END_PROGRAM
";
    let (code, lines) = check_text("node.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("error[E1080]: class `Node` contains an instance of itself (through `Node.Link.nextNode`)"),
        "{lines:?}"
    );
    assert!(!lines[0].contains("__M"), "{lines:?}");
}

/// `CHAR#16#80`, `CHAR#16#FF`, `WCHAR#16#FFFF`, `CHAR#65`: characters by their codes, also as an
/// initial value, a constant and a CASE label.
#[test]
fn a_character_is_written_by_its_code() {
    let src = "PROGRAM Main
VAR
  c : CHAR := CHAR#16#80;
  w : WCHAR;
  n, m, k, sel : DINT;
  same : BOOL;
END_VAR
VAR CONSTANT ESC : CHAR := CHAR#16#1B; END_VAR
n := CHAR_TO_DINT(c) + CHAR_TO_DINT(ESC);
CASE c OF
CHAR#16#80: sel := 1;
ELSE sel := 2;
END_CASE
c := CHAR#16#FF;
m := CHAR_TO_DINT(c);
w := WCHAR#16#FFFF;
k := WCHAR_TO_DINT(w);
same := CHAR#65 = CHAR#'A';
END_PROGRAM
";
    let (trace, stderr) = run_text(
        "codes.st",
        src,
        1,
        "Main.n,Main.m,Main.k,Main.sel,Main.same",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.n"), [155.0], "{trace}");
    assert_eq!(column(&trace, "Main.m"), [255.0], "{trace}");
    assert_eq!(column(&trace, "Main.k"), [65535.0], "{trace}");
    assert_eq!(column(&trace, "Main.sel"), [1.0], "{trace}");
    assert_eq!(column(&trace, "Main.same"), [1.0], "{trace}");
}

/// A code beyond the type: `CHAR#16#100` and `WCHAR#16#10000` are each one E1017.
#[test]
fn a_character_code_beyond_its_type_is_refused() {
    let src = "PROGRAM Main
VAR c : CHAR; w : WCHAR; END_VAR
c := CHAR#16#100;
w := WCHAR#16#10000;
END_PROGRAM
";
    let (code, lines) = check_text("big.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].starts_with("big.st:3:6: error[E1017]: character code 256 does not fit CHAR"),
        "{lines:?}"
    );
    assert!(
        lines[1].starts_with("big.st:4:6: error[E1017]: character code 65536 does not fit WCHAR"),
        "{lines:?}"
    );
}
