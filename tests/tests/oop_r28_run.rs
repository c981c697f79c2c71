//! Round 28 of unseen projects (issue #13), classes, interfaces and methods, run end to end:
//! - `THIS` (the instance's reference: SIMATIC AX's `REF_TO`, CODESYS's `POINTER TO`) where an
//!   interface the class implements is expected: `Item := THIS;` in a method whose result is the
//!   interface, `visitor.Visit(it := THIS)`, `me := THIS;` (IEC 61131-3 ed. 3, 6.6.6.5; before:
//!   E1006 "cannot store REF_TO Item into IItem" and E1012 at each);
//! - a METHOD's own VAR of a block type (its own class's included), of an array type: they start
//!   again at each call, also at the second of two calls the block makes in one scan (IEC 61131-3
//!   ed. 3, 6.6.1.2, CODESYS; before: they kept the previous call's values, only INT and
//!   structures restarted);
//! - a derived block's METHOD, PROPERTY or ACTION named like a variable of its base, in another
//!   file, apart from case: E1002 at the member (as for a block's own, round 27);
//! - a chain of EXTENDS over several files (`C EXTENDS B`, `B EXTENDS A`, one file each, `.st` or
//!   TwinCAT `.TcPOU`), `_cnt.Up()` of `A`'s instance inside `C`, in every order of the files
//!   (before: E1032 "`_cnt` is neither a variable nor a library" unless `A` was the direct base);
//! - the spellings of methods' variables shown in messages (`Take.oVal` for `__M_TAKE_OVAL`) are
//!   those of the compilation under way (before: a thread kept every earlier compilation's, a
//!   language server's later messages named methods no longer declared).

mod common;
use common::{check_files, column, in_dir, run_text, run_traced_files, write_in};

/// `THIS` given where an interface is expected, as SIMATIC AX writes it (`Self := THIS;` for a
/// method whose result is the interface, `THIS` as an interface input of a call through another
/// interface, `me := THIS;` into a variable): the instance itself, the calls through it run its
/// methods.
#[test]
fn this_is_the_instance_where_an_interface_is_expected() {
    let src = "INTERFACE IItem
    METHOD Value : INT
    END_METHOD
    METHOD Self : IItem
    END_METHOD
END_INTERFACE

INTERFACE IVisitor
    METHOD Visit : INT
        VAR_INPUT
            it : IItem;
        END_VAR
    END_METHOD
END_INTERFACE

CLASS Counter IMPLEMENTS IVisitor
    VAR PUBLIC
        seen : INT;
    END_VAR
    METHOD PUBLIC Visit : INT
        VAR_INPUT
            it : IItem;
        END_VAR
        seen := seen + it.Value();
        Visit := seen;
    END_METHOD
END_CLASS

CLASS Item IMPLEMENTS IItem
    VAR PUBLIC
        v : INT;
        visitor : IVisitor;
        me : IItem;
    END_VAR
    METHOD PUBLIC Value : INT
        Value := v;
    END_METHOD
    METHOD PUBLIC Self : IItem
        Self := THIS;
    END_METHOD
    METHOD PUBLIC Tell : INT
        Tell := visitor.Visit(it := THIS);
    END_METHOD
    METHOD PUBLIC Keep
        me := THIS;
    END_METHOD
END_CLASS

CLASS Special EXTENDS Item
    METHOD PUBLIC Value : INT
        Value := v * 10;
    END_METHOD
END_CLASS

PROGRAM Main
    VAR
        a : Item;
        s : Special;
        c : Counter;
        i : IItem;
        r1, r2, r3, r4 : INT;
    END_VAR
    a.v := 21;
    a.visitor := c;
    i := a.Self();
    r1 := i.Value();
    r2 := a.Tell();
    s.v := 3;
    s.Keep();
    r3 := s.me.Value();
    i := s.Self();
    r4 := i.Value();
END_PROGRAM
";
    let (trace, _) = run_text("this.st", src, 2, "Main.r1,Main.r2,Main.r3,Main.r4");
    assert_eq!(column(&trace, "Main.r1"), [21.0, 21.0]);
    // the counter adds the item's value at each call
    assert_eq!(column(&trace, "Main.r2"), [21.0, 42.0]);
    // a derived class's THIS: its own override runs
    assert_eq!(column(&trace, "Main.r3"), [30.0, 30.0]);
    assert_eq!(column(&trace, "Main.r4"), [30.0, 30.0]);
}

/// CODESYS's `THIS` (a `POINTER TO` the block) into an interface of a FUNCTION_BLOCK, as
/// `THIS^` was already: the same instance.
#[test]
fn a_function_blocks_this_pointer_is_the_instance_for_an_interface() {
    let src = "INTERFACE I_Node
    METHOD Id : INT
    END_METHOD
END_INTERFACE

FUNCTION_BLOCK FB_Node IMPLEMENTS I_Node
    VAR_INPUT
        nId : INT;
    END_VAR
    VAR
        iSelf : I_Node;
    END_VAR
    VAR_OUTPUT
        nSeen : INT;
    END_VAR
    iSelf := THIS;
    nSeen := iSelf.Id();
    METHOD Id : INT
        Id := nId;
    END_METHOD
END_FUNCTION_BLOCK

PROGRAM Main
    VAR
        n : FB_Node;
        r : INT;
    END_VAR
    n(nId := 7);
    r := n.nSeen;
END_PROGRAM
";
    let (trace, _) = run_text("node.st", src, 2, "Main.r");
    assert_eq!(column(&trace, "Main.r"), [7.0, 7.0]);
}

/// A METHOD's own VAR of its own class, of an INT, a structure, an array and a function block
/// type, all changed by the method: every call sees their initial values, also the second of two
/// calls in one scan from outside (`c.M()` twice) and from inside the class (`THIS.M()`, `M()`
/// twice in another method), scan after scan.
#[test]
fn a_methods_variables_start_again_at_each_call() {
    let src = "TYPE Pair : STRUCT a : INT := 1; b : INT := 2; END_STRUCT; END_TYPE

FUNCTION_BLOCK Cnt
VAR_OUTPUT n : INT; END_VAR
n := n + 1;
END_FUNCTION_BLOCK

CLASS C
    VAR PUBLIC
        base : INT := 100;
    END_VAR
    METHOD PUBLIC M : INT
        VAR
            tmp : C;
            k : INT := 3;
            s : Pair;
            arr : ARRAY[1..3] OF INT := [10, 20, 30];
            cnt : Cnt;
            t : TON;
        END_VAR
        M := tmp.base + k + s.a + s.b + arr[2] + cnt.n + TIME_TO_INT(t.PT);
        cnt();
        t.PT := T#1s;
        tmp.base := tmp.base + 1000;
        k := k + 7;
        s.a := s.a + 50;
        arr[2] := arr[2] + 5;
    END_METHOD
    METHOD PUBLIC Twice : INT
        VAR a : INT; END_VAR
        a := THIS.M();
        Twice := a - THIS.M();
    END_METHOD
    METHOD PUBLIC Again : INT
        VAR a : INT; END_VAR
        a := M();
        Again := a - M();
    END_METHOD
END_CLASS

PROGRAM Main
    VAR
        c : C;
        r1, r2, r3, r4 : INT;
    END_VAR
    r1 := c.M();
    r2 := c.M();
    r3 := c.Twice();
    r4 := c.Again();
END_PROGRAM
";
    let (trace, stderr) = run_text("reset.st", src, 3, "Main.r1,Main.r2,Main.r3,Main.r4");
    // 100 + 3 + 1 + 2 + 20 + 0 + 0
    assert_eq!(column(&trace, "Main.r1"), [126.0; 3]);
    assert_eq!(column(&trace, "Main.r2"), [126.0; 3]);
    assert_eq!(column(&trace, "Main.r3"), [0.0; 3]);
    assert_eq!(column(&trace, "Main.r4"), [0.0; 3]);
    // the restart is no copy the user wrote
    assert!(!stderr.contains("W1437"), "{stderr}");
}

/// A derived block's METHOD, PROPERTY and ACTION named like variables its base declares in
/// another file (`SPEED` and `speed`, `Level` and `level`, `Mode` and `mode`): one E1002 at each
/// member, exit 1, whichever file comes first.
#[test]
fn a_derived_member_named_like_a_base_variable_is_declared_twice() {
    let base = "FUNCTION_BLOCK Base
VAR
    speed : INT := 5;
    level : INT := 1;
    mode : INT;
END_VAR
END_FUNCTION_BLOCK
";
    let derived = "FUNCTION_BLOCK Derived EXTENDS Base
METHOD PUBLIC SPEED : INT
SPEED := 42;
END_METHOD
PROPERTY Level : INT
GET
Level := 3;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
ACTION Mode:
speed := 1;
END_ACTION
";
    let main = "PROGRAM Main
VAR d : Derived; r : INT; END_VAR
r := d.SPEED();
END_PROGRAM
";
    for files in [
        [
            ("base.st", base),
            ("derived.st", derived),
            ("main.st", main),
        ],
        [
            ("main.st", main),
            ("derived.st", derived),
            ("base.st", base),
        ],
    ] {
        let (code, lines) = check_files(&files);
        assert_eq!(code, Some(1), "{lines:?}");
        assert_eq!(lines.len(), 3, "{lines:?}");
        for (at, name, what) in [
            ("derived.st:2:15", "SPEED", "a method"),
            ("derived.st:5:10", "Level", "a property"),
            ("derived.st:11:8", "Mode", "an action"),
        ] {
            let head = format!(
                "{at}: error[E1002]: `{name}` of `Derived` is declared twice: as a variable and as {what}"
            );
            assert!(
                lines.iter().any(|l| l.starts_with(&head)),
                "{head}\n{lines:?}"
            );
        }
    }
}

const CHAIN_A: &str = "FUNCTION_BLOCK A
VAR
    _cnt : Cnt;
    x : INT := 5;
END_VAR
METHOD PUBLIC Get : INT
Get := x;
END_METHOD
END_FUNCTION_BLOCK

FUNCTION_BLOCK Cnt
VAR_OUTPUT n : INT; END_VAR
METHOD PUBLIC Up
n := n + 1;
END_METHOD
END_FUNCTION_BLOCK
";

const CHAIN_B: &str = "FUNCTION_BLOCK B EXTENDS A
VAR
    y : INT := 7;
END_VAR
END_FUNCTION_BLOCK
";

const CHAIN_C: &str = "FUNCTION_BLOCK C EXTENDS B
VAR_OUTPUT
    total : INT;
END_VAR
_cnt.Up();
total := x + y + _cnt.n + Get();
END_FUNCTION_BLOCK
";

const CHAIN_MAIN: &str = "PROGRAM Main
VAR
    c : C;
    t : INT;
    u : INT;
END_VAR
c();
t := c.total;
u := c.Get() + c.x;
END_PROGRAM
";

/// `C EXTENDS B`, `B EXTENDS A`, one file each: `A`'s instance `_cnt.Up()`, its variable and its
/// method used inside `C` and through a `C` instance; it runs alike in every order of the files.
#[test]
fn a_chain_of_extends_over_files_runs_in_every_order() {
    let files = [
        ("a.st", CHAIN_A),
        ("b.st", CHAIN_B),
        ("c.st", CHAIN_C),
        ("main.st", CHAIN_MAIN),
    ];
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in files {
        write_in(dir.path(), name, text);
    }
    let orders: [[usize; 4]; 6] = [
        [0, 1, 2, 3],
        [2, 1, 0, 3],
        [3, 2, 0, 1],
        [1, 3, 2, 0],
        [2, 0, 3, 1],
        [3, 0, 1, 2],
    ];
    for order in orders {
        let paths: Vec<std::path::PathBuf> =
            order.iter().map(|&k| dir.path().join(files[k].0)).collect();
        let refs: Vec<&std::path::Path> = paths.iter().map(|p| p.as_path()).collect();
        let (trace, _) = run_traced_files(&refs, 2, "Main.t,Main.u");
        // 5 + 7 + n + 5, n counting the scans
        assert_eq!(column(&trace, "Main.t"), [18.0, 19.0], "{order:?}");
        assert_eq!(column(&trace, "Main.u"), [10.0, 10.0], "{order:?}");
    }
}

/// The same chain as TwinCAT objects, one `.TcPOU` each (`_cnt.Up()` of `FB_A`'s instance in
/// `FB_C`), given in the order that names the most derived block first.
#[test]
fn a_chain_of_extends_over_tcpou_files_runs() {
    let tcpou = |name: &str, decl: &str, body: &str| {
        // FB_Cnt's method `Up`, called `_cnt.Up()` in FB_C
        let method = if name == "FB_Cnt" {
            "    <Method Name=\"Up\" Id=\"{2}\">
      <Declaration><![CDATA[METHOD PUBLIC Up
]]></Declaration>
      <Implementation>
        <ST><![CDATA[n := n + 1;]]></ST>
      </Implementation>
    </Method>
"
        } else {
            ""
        };
        format!(
            "<?xml version=\"1.0\" encoding=\"utf-8\"?>
<TcPlcObject Version=\"1.1.0.1\">
  <POU Name=\"{name}\" Id=\"{{1}}\" SpecialFunc=\"None\">
    <Declaration><![CDATA[{decl}]]></Declaration>
    <Implementation>
      <ST><![CDATA[{body}]]></ST>
    </Implementation>
{method}  </POU>
</TcPlcObject>
"
        )
    };
    let objects = [
        (
            "FB_A",
            "FUNCTION_BLOCK FB_A\nVAR\n    _cnt : FB_Cnt;\n    x : INT := 5;\nEND_VAR\n",
            "",
        ),
        (
            "FB_Cnt",
            "FUNCTION_BLOCK FB_Cnt\nVAR_OUTPUT n : INT; END_VAR\n",
            "",
        ),
        (
            "FB_B",
            "FUNCTION_BLOCK FB_B EXTENDS FB_A\nVAR\n    y : INT := 7;\nEND_VAR\n",
            "",
        ),
        (
            "FB_C",
            "FUNCTION_BLOCK FB_C EXTENDS FB_B\nVAR_OUTPUT\n    total : INT;\nEND_VAR\n",
            "_cnt.Up();\ntotal := x + y + _cnt.n;",
        ),
        (
            "MAIN",
            "PROGRAM MAIN\nVAR\n    c : FB_C;\n    t : INT;\nEND_VAR\n",
            "c();\nt := c.total;",
        ),
    ];
    let dir = tempfile::tempdir().unwrap();
    for (name, decl, body) in objects {
        write_in(
            dir.path(),
            &format!("{name}.TcPOU"),
            &tcpou(name, decl, body),
        );
    }
    let (code, out, err) = in_dir(
        dir.path(),
        &[
            "run",
            "FB_C.TcPOU",
            "MAIN.TcPOU",
            "FB_B.TcPOU",
            "FB_Cnt.TcPOU",
            "FB_A.TcPOU",
            "--cycles",
            "2",
            "--watch",
            "MAIN.t",
            "--trace",
            "-",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    // 5 + 7 + n, n counting the scans
    assert_eq!(column(&out, "MAIN.t"), [13.0, 14.0], "{out}");
}

/// Two compilations one after the other on one thread (as a language server runs them): the
/// second's messages do not know the first's methods (before: `__M_TAKE_OVAL` was still shown
/// as the first text's `Take.oVal`).
#[test]
fn the_spellings_of_method_variables_are_per_compilation() {
    use ladderc::{Options, Project};
    let first = "FUNCTION_BLOCK FB_User
METHOD Take : INT
VAR_INPUT oVal : INT; END_VAR
Take := oVal;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR u : FB_User; r : INT; END_VAR
r := u.Take(oVal := 2);
END_PROGRAM
";
    let checked = Project::from_sources([("first.st", first)], Options::default()).check();
    assert!(checked.is_ok());
    assert_eq!(
        il_frontend::actions::shown_names("__M_TAKE_OVAL").as_deref(),
        Some("Take.oVal")
    );
    let second = "PROGRAM Main
VAR r : INT; END_VAR
r := 1;
END_PROGRAM
";
    let checked = Project::from_sources([("second.st", second)], Options::default()).check();
    assert!(checked.is_ok());
    // no method is known now: the hidden name after its prefix
    assert_eq!(
        il_frontend::actions::shown_names("__M_TAKE_OVAL").as_deref(),
        Some("TAKE_OVAL")
    );
}
