//! Round 31 of unseen projects (issue #13), SIMATIC AX points, run end to end through
//! `ladderc run` / `ladderc check`:
//! - an assignment attempt from a FUNCTION's result, `r ?= GetItem(x);` (IEC 61131-3 ed. 3,
//!   6.6.6.7: the right side is an expression of an interface or reference type; SIMATIC AX writes
//!   `state ?= AxUnit.Mocking.GetPayload();`) runs as the two-step form (before: E1083); a call
//!   whose result type is unknown (a missing library's) is that call's error alone (before: E1083
//!   and E1032 for one cause);
//! - a task declared by its kind with its parameters as an initial value,
//!   `TASK T : CyclicInterrupt := (CycleTime := T#500ms);` (SIMATIC AX), is E1048 as without
//!   parameters (before: a bare E0011 at the `:`);
//! - W1421 and W0304 no longer say ladderc has no namespaces (it reads the project's namespaces,
//!   README "Namespaces");
//! - after E1084 (two METHODs of one name, SIMATIC AX overloading), a call that fits the dropped
//!   overload reports nothing more (before: one E1011 per call);
//! - a derived class's METHOD that overrides a base method with another signature (SIMATIC AX
//!   overloading across inheritance; IEC 61131-3 ed. 3, 6.6.5.5: an override keeps the signature)
//!   is one E1084 at the derived method, the base's kept (before: accepted silently), and a
//!   `THIS.Init(a)` meant for the base's overload is no E0106 "calls itself".

mod common;
use common::{check_text, column, run_text};

const ITEMS: &str = "INTERFACE IItem
    METHOD Get : INT END_METHOD
END_INTERFACE
INTERFACE IOther
    METHOD Other : INT END_METHOD
END_INTERFACE
CLASS Item IMPLEMENTS IItem
    VAR PUBLIC n : INT := 42; END_VAR
    METHOD PUBLIC Get : INT
        Get := n;
    END_METHOD
END_CLASS
CLASS Spare IMPLEMENTS IItem, IOther
    METHOD PUBLIC Get : INT
        Get := 5;
    END_METHOD
    METHOD PUBLIC Other : INT
        Other := 9;
    END_METHOD
END_CLASS
FUNCTION GetItem : IItem
    VAR_INPUT x : IItem; END_VAR
    GetItem := x;
END_FUNCTION
FUNCTION GetRef : REF_TO Item
    VAR_INPUT x : REF_TO Item; END_VAR
    GetRef := x;
END_FUNCTION
";

/// `r ?= GetItem(p);` with a FUNCTION returning an interface: `r`, a `REF_TO Item`, takes the
/// instance when it is an `Item` (v = 42) and NULL when it is a `Spare` (w = -1); an interface
/// target takes it when the class implements that interface (o = 9 from the `Spare`, `q` NULL
/// for the `Item`); a function returning a `REF_TO` works too (z = 42). Before: E1083 "no
/// variable, instance or method result" at each `?=`.
#[test]
fn assignment_attempt_from_a_function_result_runs() {
    let src = format!(
        "{ITEMS}
PROGRAM Main
    VAR
        it : Item; sp : Spare; p : IItem; r : REF_TO Item; ri : REF_TO Item;
        o2 : IOther; q : IOther; v : INT; w : INT := -1; o : INT; qnull : BOOL; z : INT;
    END_VAR
    p := it;
    r ?= GetItem(p);
    IF r <> NULL THEN v := r^.n; END_IF;
    p := sp;
    r ?= GetItem(p);
    IF r <> NULL THEN w := 1; END_IF;
    o2 ?= GetItem(p);
    o := o2.Other();
    p := it;
    q ?= GetItem(p);
    qnull := q = 0;
    r ?= GetRef(REF(it));
    IF r <> NULL THEN z := r^.n; END_IF;
END_PROGRAM
"
    );
    let (trace, stderr) = run_text(
        "attempt_fn.st",
        &src,
        2,
        "Main.v,Main.w,Main.o,Main.qnull,Main.z",
    );
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "Main.v"), vec![42.0, 42.0], "{trace}");
    assert_eq!(column(&trace, "Main.w"), vec![-1.0, -1.0], "{trace}");
    assert_eq!(column(&trace, "Main.o"), vec![9.0, 9.0], "{trace}");
    assert_eq!(column(&trace, "Main.qnull"), vec![1.0, 1.0], "{trace}");
    assert_eq!(column(&trace, "Main.z"), vec![42.0, 42.0], "{trace}");
}

/// A call of a function no file declares on the right of `?=`: its E1019 alone, located at the
/// name (before: E1083 at the statement as well, two errors for one cause).
#[test]
fn assignment_attempt_from_an_unknown_function_is_its_one_error() {
    let src = format!(
        "{ITEMS}
PROGRAM Main
    VAR r : REF_TO Item; END_VAR
    r ?= FromLibrary(1);
END_PROGRAM
"
    );
    let (code, lines) = check_text("attempt_unknown.st", &src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("attempt_unknown.st:32:10")
            && lines[0].contains("E1019")
            && lines[0].contains("FromLibrary"),
        "{lines:?}"
    );
}

/// `TASK Fast : CyclicInterrupt := (CycleTime := T#500ms, EventPriority := USINT#13);`: one
/// E1048 at the kind, as for `TASK Slow : ProgramCycle;` (README, E1048); before: E0011
/// "unexpected `:`" at 3:15. The programs of the configuration are not reported again.
#[test]
fn task_kind_with_parameters_is_e1048() {
    let src = "CONFIGURATION Plc
    TASK Main (INTERVAL := T#10ms, PRIORITY := 1);
    TASK Fast : CyclicInterrupt := (CycleTime := T#500ms, EventPriority := USINT#13);
    TASK Slow : ProgramCycle;
    PROGRAM P1 WITH Main : Counter;
    PROGRAM P2 WITH Fast : Counter;
END_CONFIGURATION
PROGRAM Counter
    VAR x : INT; END_VAR
    x := x + 1;
END_PROGRAM
";
    let (code, lines) = check_text("tasks.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].contains("tasks.st:3:17")
            && lines[0].contains("E1048")
            && lines[0].contains("`Fast` is declared by its kind `CyclicInterrupt`"),
        "{lines:?}"
    );
    assert!(
        lines[1].contains("tasks.st:4:17") && lines[1].contains("E1048"),
        "{lines:?}"
    );
}

/// W1421 for a namespace no file declares, beside a NAMESPACE the file declares and uses: the
/// message says the namespace is not the project's (before: "ladderc has no namespaces", false
/// next to `Plant.Twice(21)`, which runs to 42); W0304's hint no longer says so either.
#[test]
fn namespace_warnings_say_what_is_true() {
    let src = "USING Vendor.Lib;
NAMESPACE Plant
    CLASS PUBLIC Holder
        VAR PUBLIC v : INT; END_VAR
    END_CLASS
    FUNCTION Twice : INT
        VAR_INPUT x : INT; END_VAR
        Twice := 2 * x;
    END_FUNCTION
END_NAMESPACE
PROGRAM Main
    VAR r : INT; END_VAR
    r := Plant.Twice(21);
END_PROGRAM
";
    let (code, lines) = check_text("ns.st", src);
    assert_eq!(code, Some(0));
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].contains("ns.st:1:1")
            && lines[0].contains("W1421")
            && lines[0].contains("no file of the project declares this namespace"),
        "{lines:?}"
    );
    assert!(
        lines[1].contains("ns.st:3:11") && lines[1].contains("W0304"),
        "{lines:?}"
    );
    assert!(
        !lines.iter().any(|l| l.contains("no namespaces")),
        "{lines:?}"
    );
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("ns.st");
    std::fs::write(&f, src).unwrap();
    let out = common::ladderc().arg("check").arg(&f).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("without namespaces"), "{stderr}");
    let (trace, _) = run_text("ns.st", src, 1, "Main.r");
    assert_eq!(column(&trace, "Main.r"), vec![42.0], "{trace}");
}

/// Two METHODs `Flag` in one class (a setter, a getter: SIMATIC AX overloading): one E1084 at
/// the second; the derived class's calls of either (`THIS.Flag(value := TRUE)` fits the first,
/// `THIS.Flag()` as a value the dropped getter) report nothing more (README E1084; before: one
/// E1011 "method `Flag` returns no value" at 16:17, and "has no parameter" for the reverse).
#[test]
fn calls_of_a_dropped_overload_report_nothing_more() {
    let src = "CLASS Base
    VAR PRIVATE _bad : BOOL; END_VAR
    METHOD PUBLIC Flag : BOOL
        Flag := _bad;
    END_METHOD
    METHOD PROTECTED Flag
        VAR_INPUT value : BOOL; END_VAR
        _bad := value;
    END_METHOD
END_CLASS
CLASS User EXTENDS Base
    METHOD PUBLIC Read : BOOL
        THIS.Flag(value := TRUE);
        Read := THIS.Flag();
    END_METHOD
    METHOD PUBLIC Write
        THIS.Flag(value := FALSE);
    END_METHOD
END_CLASS
PROGRAM Main
    VAR u : User; r : BOOL; END_VAR
    r := u.Read();
END_PROGRAM
";
    let (code, lines) = check_text("overloads.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("overloads.st:6:22") && lines[0].contains("E1084"),
        "{lines:?}"
    );
}

/// A derived class's `Init(a, b)` over the base's `Init(a)` (SIMATIC AX reads it as an overload;
/// IEC 61131-3 ed. 3, 6.6.5.5: an overriding method keeps the signature of the one it
/// overrides): one E1084 at the derived METHOD's name (21:17) naming `Base.Init`, the base's
/// kept; the program's call with `b`, which fits the dropped one, reports nothing more. Before:
/// exit 0 and no diagnostic, the derived method silently replacing the base's.
#[test]
fn an_override_with_another_signature_is_e1084() {
    let src = "CLASS Base
    VAR PUBLIC id : INT; END_VAR
    METHOD PROTECTED Init
        VAR_INPUT a : INT; END_VAR
        id := a;
    END_METHOD
END_CLASS

CLASS Derived EXTENDS Base
    VAR PUBLIC extra : INT; END_VAR
    METHOD PUBLIC Report : INT
        Report := id;
    END_METHOD
END_CLASS

CLASS Wider EXTENDS Derived
    VAR PUBLIC more : INT; END_VAR
    (* the base's Init with another input: an overload in SIMATIC AX *)

    METHOD PUBLIC Init
        VAR_INPUT a : INT; b : INT := 7; END_VAR
        more := b;
    END_METHOD
END_CLASS

PROGRAM Main
    VAR w : Wider; r : INT; END_VAR
    w.Init(a := 3, b := 4);
    r := w.Report();
END_PROGRAM
";
    let (code, lines) = check_text("override_sig.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    let l = &lines[0];
    assert!(
        l.contains("override_sig.st:20:19") && l.contains("E1084"),
        "{lines:?}"
    );
    assert!(
        l.contains("`Init` of `Wider`") && l.contains("`Base.Init`") && l.contains("signature"),
        "{lines:?}"
    );
}

/// SIMATIC AX's constructor pattern: the derived `Init(a, b)` calls the base's overload with
/// `THIS.Init(a)` (ae-simplified-sorting-machine, `THIS.CONSTRUCTOR(stationID, stationPosLeft)`).
/// With the base's `Init` kept (E1084 at the derived one, 11:19), that call fits it and reports
/// nothing more. Before: no E1084, and E0106 "method `Init` calls itself" at `THIS.Init(a)` with
/// advice about an explicit stack, though nothing recurses.
#[test]
fn a_call_of_the_base_overload_is_no_recursion() {
    let src = "CLASS Base
    VAR PUBLIC id : INT; END_VAR
    METHOD PROTECTED Init
        VAR_INPUT a : INT; END_VAR
        id := a;
    END_METHOD
END_CLASS

CLASS Derived EXTENDS Base
    VAR PUBLIC extra : INT; END_VAR
    METHOD PUBLIC Init
        VAR_INPUT a : INT; b : INT := 7; END_VAR
        THIS.Init(a);
        extra := b;
    END_METHOD
END_CLASS

PROGRAM Main
    VAR d : Derived; END_VAR
    d.Init(a := 3, b := 4);
END_PROGRAM
";
    let (code, lines) = check_text("overload_call.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("overload_call.st:11:19")
            && lines[0].contains("E1084")
            && lines[0].contains("`Base.Init`"),
        "{lines:?}"
    );
    assert!(!lines.iter().any(|l| l.contains("E0106")), "{lines:?}");
}

/// What stays as it was: an override with the base's signature runs late-bound (the base's
/// `Run` calls `Step`, the derived `Step` runs: n = 10 then 20), and a derived method of the name
/// of a base's PRIVATE method, with other inputs, is no override (IEC 61131-3 ed. 3, 6.6.5: a
/// private method is invisible to the derived class) and runs (k = 5).
#[test]
fn same_signature_overrides_and_private_names_still_run() {
    let src = "CLASS Base
    VAR PUBLIC n : INT; k : INT; END_VAR
    METHOD PUBLIC Step
        VAR_INPUT inc : INT; END_VAR
        n := n + inc;
    END_METHOD
    METHOD PUBLIC Run
        Step(inc := 1);
    END_METHOD
    METHOD PRIVATE Helper
        k := 1;
    END_METHOD
END_CLASS

CLASS Derived EXTENDS Base
    METHOD PUBLIC Step
        VAR_INPUT inc : INT; END_VAR
        n := n + 10 * inc;
    END_METHOD
    METHOD PUBLIC Helper
        VAR_INPUT v : INT; END_VAR
        k := v;
    END_METHOD
END_CLASS

PROGRAM Main
    VAR d : Derived; n : INT; k : INT; END_VAR
    d.Run();
    d.Helper(v := 5);
    n := d.n;
    k := d.k;
END_PROGRAM
";
    let (trace, stderr) = run_text("overrides.st", src, 2, "Main.n,Main.k");
    assert_eq!(
        column(&trace, "Main.n"),
        vec![10.0, 20.0],
        "{trace}{stderr}"
    );
    assert_eq!(column(&trace, "Main.k"), vec![5.0, 5.0], "{trace}{stderr}");
}
