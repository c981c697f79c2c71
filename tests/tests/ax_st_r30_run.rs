//! Round 30 of unseen projects (issue #13): SIMATIC AX forms in `.st` text.
//! - a task declared by its kind written with its namespace
//!   (`TASK Main : Siemens.Simatic.S71500.Tasks.ProgramCycle;`, as SIMATIC AX's templates write it)
//!   is the same one located E1048 as the short `TASK Main : ProgramCycle;` (before: a bare E0011
//!   "unexpected `:`" that did not say what was wrong).
//! - a class that overloads a method (E1084, the first kept) and implements an interface declaring
//!   another overload of it gets the E1084 only (before: an E0335 interface mismatch as well, that
//!   followed only from ladderc keeping the first overload).
//! - AX Code's documentation-link pragma (`{axcode:docs-v0:@simatic-ax/conversion:TRUNC.md}`) is
//!   the informational note W0301 of a description pragma (before: the warning W0300 "holds code
//!   that does not run", telling the user to rewrite a documentation link in ST).

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

/// The lines of `lines` that are errors.
fn errors(lines: &[String]) -> Vec<&String> {
    lines.iter().filter(|l| l.contains("error[")).collect()
}

/// SIMATIC AX declares a task by its kind, a type of the namespace `Siemens.Simatic.S71500.Tasks`
/// that `USING` imports, and its templates write the kind both bare and with its namespace; IEC
/// 61131-3 (ed. 3, 6.8.2) declares a task by its schedule (`INTERVAL`, `SINGLE`, `PRIORITY`).
/// Both spellings are one E1048 each, at the kind (the qualified one spans the whole name), and
/// the `WITH Main` of the program instances is not reported again. Before: the qualified kind was
/// a bare E0011 "unexpected `:`" (hint "expected `(`"), the short one E1048.
#[test]
fn a_task_kind_written_with_its_namespace_is_the_same_e1048_as_the_short_form() {
    let src = "USING Siemens.Simatic.S71500.Tasks;

CONFIGURATION Cell
    TASK Cyclic : Siemens.Simatic.S71500.Tasks.ProgramCycle;
    PROGRAM Station WITH Cyclic : Counter;
    TASK Boot : Startup;
    PROGRAM Init WITH Boot : Counter;
END_CONFIGURATION

PROGRAM Counter
    VAR n : INT; END_VAR
    n := n + 1;
END_PROGRAM
";
    let (code, lines) = check_text("cell.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 2, "one error per task: {lines:?}");
    assert!(
        errs[0].starts_with(
            "cell.st:4:19: error[E1048]: task `Cyclic` is declared by its kind \
             `Siemens.Simatic.S71500.Tasks.ProgramCycle`, not by a schedule"
        ),
        "{lines:?}"
    );
    assert!(errs[0].contains("INTERVAL := T#10ms"), "{lines:?}");
    assert!(
        errs[1].starts_with(
            "cell.st:6:17: error[E1048]: task `Boot` is declared by its kind `Startup`"
        ),
        "{lines:?}"
    );
    assert!(!lines.iter().any(|l| l.contains("E0011")), "{lines:?}");

    // a name that does not end at `;` is no task kind: the parse error stays where it is
    let src = "CONFIGURATION Cell
    TASK Cyclic : Siemens.Simatic.(x);
    PROGRAM Station WITH Cyclic : Counter;
END_CONFIGURATION

PROGRAM Counter
    VAR n : INT; END_VAR
    n := n + 1;
END_PROGRAM
";
    let (code, lines) = check_text("broken.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(!lines.iter().any(|l| l.contains("E1048")), "{lines:?}");
}

/// IEC 61131-3 ed. 3 (6.6.5, 6.6.6) gives a method a name unique in its class; SIMATIC AX
/// overloads methods by their parameters, which ladderc reports as one E1084 at the second
/// declaration, compiling the first (README, E1084). The interface check does not compare that
/// kept method with the interface's (the interface declares the other overload, as
/// simatic-ax/dynamics' `IDynamicController.Next(value, input)` does): one cause, one error, also
/// when the overloads are in a base class. A method that is not overloaded is still compared.
/// Before: an E0335 "method `Next` of `Ctl` is `Next(value : LREAL) : LREAL`, but interface
/// `ICtl` declares `Next(value : LREAL, input : LREAL) : LREAL`" at the first `Next` besides the
/// E1084.
#[test]
fn an_overloaded_method_is_one_e1084_without_an_interface_mismatch() {
    let itf = "INTERFACE ILimiter
    METHOD Step : LREAL
        VAR_INPUT value : LREAL; limit : LREAL; END_VAR
    END_METHOD
    METHOD Reset
        VAR_INPUT origin : LREAL; END_VAR
    END_METHOD
END_INTERFACE
";
    let src = format!(
        "{itf}
CLASS Limiter IMPLEMENTS ILimiter
    VAR _last : LREAL; END_VAR
    METHOD PUBLIC Step : LREAL
        VAR_INPUT value : LREAL; END_VAR
        Step := MIN(value, _last);
    END_METHOD
    METHOD PUBLIC Step : LREAL
        VAR_INPUT value : LREAL; limit : LREAL; END_VAR
        _last := limit;
        Step := MIN(value, limit);
    END_METHOD
    METHOD PUBLIC Reset
        VAR_INPUT origin : LREAL; END_VAR
        _last := origin;
    END_METHOD
END_CLASS
"
    );
    let (code, lines) = check_text("limiter.st", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0]
            .starts_with("limiter.st:16:19: error[E1084]: `Limiter` declares METHOD `Step` twice"),
        "{lines:?}"
    );

    // the overloads in a base class, the interface on the derived one: the same one error
    let src = format!(
        "{itf}
CLASS BaseLimiter
    VAR _last : LREAL; END_VAR
    METHOD PUBLIC Step : LREAL
        VAR_INPUT value : LREAL; END_VAR
        Step := MIN(value, _last);
    END_METHOD
    METHOD PUBLIC Step : LREAL
        VAR_INPUT value : LREAL; limit : LREAL; END_VAR
        Step := MIN(value, limit);
    END_METHOD
END_CLASS

CLASS Limiter EXTENDS BaseLimiter IMPLEMENTS ILimiter
    METHOD PUBLIC Reset
        VAR_INPUT origin : LREAL; END_VAR
        _last := origin;
    END_METHOD
END_CLASS
"
    );
    let (code, lines) = check_text("derived.st", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 1, "{lines:?}");
    assert!(
        errs[0].starts_with(
            "derived.st:16:19: error[E1084]: `BaseLimiter` declares METHOD `Step` twice"
        ),
        "{lines:?}"
    );

    // a method declared once with another signature than the interface's is still E0335
    let src = format!(
        "{itf}
CLASS Limiter IMPLEMENTS ILimiter
    VAR _last : LREAL; END_VAR
    METHOD PUBLIC Step : LREAL
        VAR_INPUT value : LREAL; END_VAR
        Step := MIN(value, _last);
    END_METHOD
    METHOD PUBLIC Step : LREAL
        VAR_INPUT value : LREAL; limit : LREAL; END_VAR
        Step := MIN(value, limit);
    END_METHOD
    METHOD PUBLIC Reset
        VAR_INPUT origin : INT; END_VAR
        _last := TO_LREAL(origin);
    END_METHOD
END_CLASS
"
    );
    let (code, lines) = check_text("reset.st", &src);
    assert_eq!(code, Some(1), "{lines:?}");
    let errs = errors(&lines);
    assert_eq!(errs.len(), 2, "{lines:?}");
    assert!(errs.iter().any(|l| l.contains("error[E1084]")), "{lines:?}");
    assert!(
        errs.iter()
            .any(|l| l.starts_with("reset.st:20:19: error[E0335]: method `Reset` of `Limiter`")),
        "{lines:?}"
    );
}

/// AX Code links a declaration to its Markdown documentation page with the pragma
/// `{axcode:docs-v0:<package>:<page>.md}` (simatic-ax/conversion, simatic-ax/Generators). IEC
/// 61131-3 ed. 3 (6.2) leaves pragmas to the implementation, and CODESYS's help reads a pragma
/// the compiler cannot interpret as a comment; this one holds no code: it is a description
/// pragma (one key, one value without blanks), the informational W0301 note, one per file as the
/// other description pragmas, and the program runs. Before: the warning W0300 "holds code that
/// does not run" at each pragma, with the hint to write the behaviour in ST.
#[test]
fn an_ax_code_documentation_link_is_a_description_note_and_the_program_runs() {
    let src = "{axcode:docs-v0:@plant/maths:Half.md}
FUNCTION Half : INT
    VAR_INPUT x : INT; END_VAR
    Half := x / 2;
END_FUNCTION

{axcode:docs-v0:@plant/maths:Main.md}
PROGRAM Main
    VAR n : INT := 40; r : INT; END_VAR
    r := Half(n);
    n := n + 2;
END_PROGRAM
";
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "maths.st", src);
    let (code, _, stderr) = in_dir(dir.path(), &["check", "maths.st"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stderr.contains("W0300"), "{stderr}");
    let notes: Vec<&str> = stderr.lines().filter(|l| l.contains("W0301")).collect();
    assert_eq!(notes.len(), 1, "one note per file: {stderr}");
    assert!(
        notes[0].starts_with(
            "maths.st:1:1: note[W0301]: description or attribute pragma \
             `{axcode:docs-v0:@plant/maths:Half.md}` is ignored (and the file's other one)"
        ),
        "{stderr}"
    );

    let (trace, stderr) = run_text("maths.st", src, 3, "Main.r,Main.n");
    assert!(!stderr.contains("W0300"), "{stderr}");
    assert_eq!(column(&trace, "Main.r"), [20.0, 21.0, 22.0], "{trace}");
    assert_eq!(column(&trace, "Main.n"), [42.0, 44.0, 46.0], "{trace}");

    // Beremiz's C code in a pragma is still W0300
    let (_, lines) = check_text(
        "c.st",
        "PROGRAM Main
    VAR n : INT; END_VAR
    {{ printf(\"%d\", 1); }}
    n := n + 1;
END_PROGRAM
",
    );
    assert!(
        lines.iter().any(|l| l.contains("warning[W0300]")),
        "{lines:?}"
    );
}
