//! Object-oriented ST the way TwinCAT and CODESYS libraries write it, the rest (issue #13), run
//! end to end through `ladderc run --sanitize` on files written for these tests
//! (`fixtures/oop_chains/`): calls on a call's result (`stack.Get(i).Pop()`,
//! `list.Item(2).Value := 5;`, `.Next()^.Value`, a method returning an interface), also in
//! conditions, each call once and in source order; property chains; REPEAT ... CONTINUE ... UNTIL
//! with a method call in the condition; FB_init arguments for arrays of instances; `__NEW` /
//! `__DELETE` (E0351); what fisothemes/TwinCat-Dynamic-Collections stopped on (several modifiers,
//! a method's pointer initialised from `THIS^`, a local variable named like a method).
//!
//! Record of public projects (this round): the 46 `.plcproj` of the 25 mirrored TwinCAT
//! repositories, `ladderc check` errors before (main's binary) and after: 1798 -> 1780, compiled
//! 16 -> 16. TcDynCollections 60 -> 41 (E0104 13 -> 0, E0106 5 -> 0, E0100 5 -> 0, E3103 4 -> 0,
//! E0305 7 -> 1, and 14 E0351, one per file that uses `__NEW` / `__DELETE`, newly reported: the
//! library is built on the heap, which ladderc has by design not); SeanyCash/TwinCAT_CNC 94 -> 95
//! (an E1004 for TO_STRING of an enumeration, which main's newer commits accept: not from this
//! branch). None newly compiles: libraries (TcUnit, Tc2_System, `__SYSTEM`), VAR_STAT,
//! variable-length arrays and MEMCPY through pointers stop them.

mod common;
use common::{column, rejected_heads, run_traced};

use std::path::{Path, PathBuf};

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/oop_chains")
        .join(rel)
}

/// `FB_Stack.Get(i)` returns a `REFERENCE TO FB_Item`; every method notes its number (Get 1, Pop
/// 2, Next 3, IsEmpty 4) in `stack.order` and counts itself in `stack.calls`. Items start at 5,
/// 15 (`10 + Get(0).Value`, written through the chain) and 100.
#[test]
fn calls_on_a_methods_result_run_once_each_in_source_order() {
    let (trace, stderr) = run_traced(
        &fixture("chains.st"),
        2,
        "Main.popped,Main.sum,Main.orderAssign,Main.viaPtr,Main.top,Main.orderIf,Main.branch,\
         Main.callsWhile,Main.loops,Main.orderAndThen,Main.stack.items[0].Value,\
         Main.stack.items[1].Value,Main.stack.items[2].Value",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    // `stack.Get(1).Pop()`: 15 -> 14, then the statement `stack.Get(1).Pop();` -> 13
    assert_eq!(column(&trace, "Main.popped"), [14.0, 14.0]);
    // `Get(0).Pop() * 100 + Get(1).Pop()`: 4 * 100 + 12, calls Get Pop Get Pop
    assert_eq!(column(&trace, "Main.sum"), [412.0, 412.0]);
    assert_eq!(column(&trace, "Main.orderAssign"), [1212.0, 1212.0]);
    // `Get(0).Next()^.Next()^.Value` is items[2] (`METHOD Next : POINTER TO FB_Item` with its
    // body right after the result type); `Top` is `Get(2).Value` inside the block
    assert_eq!(column(&trace, "Main.viaPtr"), [100.0, 100.0]);
    assert_eq!(column(&trace, "Main.top"), [100.0, 100.0]);
    // IF Get(0).IsEmpty() (4: no) ELSIF Get(1).Pop() > 0 (11: yes)
    assert_eq!(column(&trace, "Main.orderIf"), [1412.0, 1412.0]);
    // the ELSIF branch; the AND_THEN conditions later are false
    assert_eq!(column(&trace, "Main.branch"), [2.0, 2.0]);
    // WHILE NOT Get(2).IsEmpty(): 4 tests (2 calls each) and 3 bodies (Get, Pop)
    assert_eq!(column(&trace, "Main.callsWhile"), [14.0, 14.0]);
    assert_eq!(column(&trace, "Main.loops"), [3.0, 3.0]);
    // `Get(2).IsEmpty() AND_THEN Get(0).Pop() > 100` (left TRUE: the right runs), then
    // `NOT Get(2).IsEmpty() AND_THEN ...` (left FALSE: the right does not run)
    assert_eq!(column(&trace, "Main.orderAndThen"), [141214.0, 141214.0]);
    assert_eq!(column(&trace, "Main.stack.items[0].Value"), [3.0, 3.0]);
    assert_eq!(column(&trace, "Main.stack.items[1].Value"), [11.0, 11.0]);
    assert_eq!(column(&trace, "Main.stack.items[2].Value"), [0.0, 0.0]);
}

/// `head.Next().Val()`, `head.Next().Next().Val()` through an interface whose method returns the
/// interface, and `a.Next().Next().Val()` from an instance: nodes 1 -> 2 -> 3.
#[test]
fn a_method_returning_an_interface_is_called_on_at_once() {
    let (trace, stderr) = run_traced(&fixture("interface_chain.st"), 1, "Main.x,Main.y,Main.z");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), [2.0]);
    assert_eq!(column(&trace, "Main.y"), [3.0]);
    assert_eq!(column(&trace, "Main.z"), [3.0]);
}

/// `REPEAT ... CONTINUE ... UNTIL c.Done(limit := 7)`: the CONTINUE goes on with the UNTIL test,
/// which calls the method (IEC 61131-3 ed. 3, CODESYS): 7 iterations, 7 tests, 3 of them after a
/// CONTINUE; the same with a call chain in the condition (`d.Self().Done(limit := 5)`).
#[test]
fn continue_in_a_repeat_still_runs_the_until_condition_with_its_method_call() {
    let (trace, stderr) = run_traced(
        &fixture("repeat_continue.st"),
        2,
        "Main.c.n,Main.c.tests,Main.odd,Main.skipped,Main.d.n,Main.d.tests",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.c.n"), [7.0, 7.0]);
    assert_eq!(column(&trace, "Main.c.tests"), [7.0, 7.0]);
    assert_eq!(column(&trace, "Main.odd"), [4.0, 4.0]);
    assert_eq!(column(&trace, "Main.skipped"), [3.0, 3.0]);
    assert_eq!(column(&trace, "Main.d.n"), [5.0, 5.0]);
    assert_eq!(column(&trace, "Main.d.tests"), [5.0, 5.0]);
}

/// A call inside an access whose callee is no method (an output), or whose result has nothing to
/// access (`a.M().v` with `METHOD M : INT`), is one E0349 at the call; the rest of the text is
/// still checked.
#[test]
fn a_call_inside_an_access_that_is_no_method_is_one_located_error() {
    let heads = rejected_heads(
        "bad_chain.st",
        "FUNCTION_BLOCK FB_A\nVAR_OUTPUT q : INT; END_VAR\nMETHOD M : INT\nM := 1;\nEND_METHOD\n\
         END_FUNCTION_BLOCK\nPROGRAM Main\nVAR a : FB_A; x : INT; END_VAR\n\
         x := a.q(1).v;\nx := a.M().v;\nx := 1;\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        [
            "bad_chain.st:9:6: error[E0349]: `a.q` is no method: its result cannot be accessed",
            "bad_chain.st:10:6: error[E0349]: `a.M` returns INT: its result has nothing the rest of the access can reach",
        ]
    );
}

/// FB_init arguments for arrays of instances, as CODESYS declares them: one list per element in
/// index order (`ARRAY[0..2] OF FB_Axis[(nId := 10, fScale := 0.5), (nId := 11), (12, 2.0)]`; the
/// last index fastest in two dimensions), one list for every element (`[(nId := 7)]`), and
/// `ARRAY[1..2] OF FB_Axis(nId := 9, fScale := 3.0)`. Each element's FB_init runs once.
#[test]
fn fb_init_arguments_for_arrays_of_instances_go_to_each_element() {
    let (trace, stderr) = run_traced(
        &fixture("fb_init_array.st"),
        1,
        "Main.axes[0].nId,Main.axes[0].fScale,Main.axes[1].nId,Main.axes[1].fScale,\
         Main.axes[2].nId,Main.axes[2].fScale,Main.gridIds,Main.gridInits,Main.same[1].nId,\
         Main.same[3].nId,Main.same[3].inits,Main.plain[2].nId,Main.plain[2].fScale,Main.sumIds",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.axes[0].nId"), [10.0]);
    assert_eq!(column(&trace, "Main.axes[0].fScale"), [0.5]);
    // FB_init's own default for the input not given
    assert_eq!(column(&trace, "Main.axes[1].nId"), [11.0]);
    assert_eq!(column(&trace, "Main.axes[1].fScale"), [1.0]);
    // positional
    assert_eq!(column(&trace, "Main.axes[2].nId"), [12.0]);
    assert_eq!(column(&trace, "Main.axes[2].fScale"), [2.0]);
    assert_eq!(column(&trace, "Main.gridIds"), [1234.0]);
    assert_eq!(column(&trace, "Main.gridInits"), [4.0]);
    assert_eq!(column(&trace, "Main.same[1].nId"), [7.0]);
    assert_eq!(column(&trace, "Main.same[3].nId"), [7.0]);
    assert_eq!(column(&trace, "Main.same[3].inits"), [1.0]);
    assert_eq!(column(&trace, "Main.plain[2].nId"), [9.0]);
    assert_eq!(column(&trace, "Main.plain[2].fScale"), [3.0]);
    assert_eq!(column(&trace, "Main.sumIds"), [33.0]);
}

/// Several lists whose number is not the array's number of elements are one E0350 at the lists;
/// an argument of a list that FB_init does not take is E0329 at it, as for one instance.
#[test]
fn fb_init_lists_that_do_not_match_the_elements_are_one_located_error() {
    let heads = rejected_heads(
        "bad_lists.st",
        "FUNCTION_BLOCK FB_X\nVAR nId : INT; END_VAR\nMETHOD FB_init : BOOL\n\
         VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; nId : INT; END_VAR\n\
         THIS^.nId := nId;\nEND_METHOD\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR\n  \
         afb : ARRAY[0..2] OF FB_X[(nId := 1), (nId := 2)];\n  \
         bfb : ARRAY[0..1] OF FB_X[(nId := 1), (nOther := 2)];\nEND_VAR\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        [
            "bad_lists.st:10:28: error[E0350]: 2 FB_init argument lists for the 3 elements of `afb`",
            "bad_lists.st:11:42: error[E0329]: argument `nOther`: the FB_init method of `FB_X` has no such input",
        ]
    );
}

/// `__NEW` and `__DELETE` (CODESYS, TwinCAT dynamic memory): ladderc has no heap by design, so
/// the first call of a file is one E0351 at it (a library built on the heap uses them everywhere:
/// fisothemes/TwinCat-Dynamic-Collections has 42 in 16 files), and nothing more is reported about
/// the statements holding them, in this POU or the next (the type argument is no
/// undeclared variable, `__DELETE(p);` no unused result); `ladderc run` stops before building.
#[test]
fn new_and_delete_are_one_e0351_per_file_without_a_cascade() {
    let src = "FUNCTION_BLOCK FB_Item\nVAR_OUTPUT v : INT; END_VAR\nEND_FUNCTION_BLOCK\n\
               PROGRAM Main\nVAR\n  p : POINTER TO FB_Item;\n  q : POINTER TO INT;\n  x : INT;\nEND_VAR\n\
               p := __NEW(FB_Item);\nq := __NEW(INT, 10);\nx := p^.v;\n__DELETE(p);\n\
               IF x > 0 THEN\n  __delete(q);\nEND_IF;\nEND_PROGRAM\n\
               PROGRAM Other\nVAR p : POINTER TO FB_Item; END_VAR\nIF p <> 0 THEN\n  __DELETE(p);\nEND_IF;\nEND_PROGRAM\n";
    let heads = rejected_heads("heap.st", src);
    let no_heap = "ladderc has no dynamic memory (no heap) to create or free variables at run time (its other uses in this file are not reported)";
    assert_eq!(
        heads,
        [format!("heap.st:10:6: error[E0351]: `__NEW`: {no_heap}"),]
    );
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("heap.st");
    std::fs::write(&f, src).unwrap();
    let out = common::ladderc()
        .args(["--message-format", "short", "run"])
        .arg(&f)
        .args(["--cycles", "1"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.matches("error[").count(), 1, "{stderr}");
}

/// Several modifiers between `FUNCTION_BLOCK` and the name (`INTERNAL ABSTRACT`, `PUBLIC FINAL`;
/// TwinCAT, fisothemes/TwinCat-Dynamic-Collections): PUBLIC and INTERNAL are W0304, ABSTRACT and
/// FINAL keep their meaning; the blocks run (the override, the base's body through `SUPER^()`).
/// Before, the second word was read as the block's name and the declaration fell apart (E0106).
#[test]
fn several_modifiers_of_a_function_block_are_read() {
    let (trace, stderr) = run_traced(&fixture("modifiers.st"), 2, "Main.a,Main.sq.calls");
    assert!(!stderr.contains("error"), "{stderr}");
    assert!(
        stderr.contains(
            "warning[W0304]: `FUNCTION_BLOCK INTERNAL` of `FB_Shape`: the modifier is ignored"
        ),
        "{stderr}"
    );
    assert_eq!(column(&trace, "Main.a"), [16.0, 16.0]);
    assert_eq!(column(&trace, "Main.sq.calls"), [1.0, 2.0]);
    // ABSTRACT and FINAL after INTERNAL are still checked; `__NEW(POINTER TO INT, 3)`, whose
    // first argument is a type, is the one E0351 (no syntax error at `TO`)
    let heads = rejected_heads(
        "mods.st",
        "FUNCTION_BLOCK INTERNAL ABSTRACT FB_A\nEND_FUNCTION_BLOCK\n\
         FUNCTION_BLOCK INTERNAL FINAL FB_B\nEND_FUNCTION_BLOCK\n\
         FUNCTION_BLOCK FB_C EXTENDS FB_B\nEND_FUNCTION_BLOCK\n\
         PROGRAM Main\nVAR a : FB_A; p : POINTER TO INT; END_VAR\n\
         p := __NEW(POINTER TO INT, 3);\nEND_PROGRAM\n",
    );
    assert_eq!(
        heads,
        [
            "mods.st:1:16: warning[W0304]: `FUNCTION_BLOCK INTERNAL` of `FB_A`: the modifier is ignored",
            "mods.st:3:16: warning[W0304]: `FUNCTION_BLOCK INTERNAL` of `FB_B`: the modifier is ignored",
            "mods.st:5:29: error[E0332]: `FB_C` EXTENDS `FB_B`, which is FINAL",
            "mods.st:8:9: error[E0333]: `a` is an instance of `FB_A`, which is ABSTRACT",
            "mods.st:9:6: error[E0351]: `__NEW`: ladderc has no dynamic memory (no heap) to create or free variables at run time (its other uses in this file are not reported)",
        ]
    );
}

/// Property chains (`PROPERTY Child : REFERENCE TO FB_Tree`, tree a -> b -> c, c.v = 7):
/// `a.Child.Child.Value` reads c's `Value` through two getters; `a.Child.Value := 5;` writes
/// through the reference, running b's `Value` setter (before: E0338, and the property's
/// `REFERENCE TO` type was E0011); `a.Kid().Child.Value + a.Child.Kid().Value` mixes methods and
/// properties in chains; `w := a.Child.Depth();` calls a method on the property's value (b.v +
/// 100; before: E1011). Each use runs the getter once: a's 4 and b's 2 per cycle.
#[test]
fn property_chains_read_and_write_through_reference_properties() {
    let (trace, stderr) = run_traced(
        &fixture("property_chain.st"),
        2,
        "Main.x,Main.y,Main.z,Main.w,Main.a.gets,Main.b.gets,Main.c.gets",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), [7.0, 7.0]);
    assert_eq!(column(&trace, "Main.y"), [5.0, 5.0]);
    assert_eq!(column(&trace, "Main.z"), [14.0, 14.0]);
    assert_eq!(column(&trace, "Main.w"), [105.0, 105.0]);
    assert_eq!(column(&trace, "Main.a.gets"), [4.0, 8.0]);
    assert_eq!(column(&trace, "Main.b.gets"), [2.0, 4.0]);
    assert_eq!(column(&trace, "Main.c.gets"), [0.0, 0.0]);
}

/// A method's `POINTER TO` variable initialised from the instance (`pCurrent : POINTER TO ST_Node
/// := THIS^.pRoot;`, `pSecond : ... := pRoot^.pNext;`) is assigned when the method starts, at each
/// call, as a method's other computed initial values (before: E0305). The list 1 -> 20 -> 300
/// sums to 321; `* 100 + pSecond^.value` adds 20; the second call walks the list again.
#[test]
fn a_methods_pointer_initialised_from_the_instance_is_set_at_each_call() {
    let (trace, stderr) = run_traced(&fixture("pointer_inits.st"), 2, "Main.first,Main.second");
    assert!(
        !stderr.contains("error") && !stderr.contains("warning"),
        "{stderr}"
    );
    assert_eq!(column(&trace, "Main.first"), [32120.0, 32120.0]);
    assert_eq!(column(&trace, "Main.second"), [32120.0, 32120.0]);
    // several names sharing one such initial value are not assigned so: E0305 stays, at the value
    let heads = rejected_heads(
        "shared.st",
        "FUNCTION_BLOCK FB_L\nVAR n : INT; END_VAR\nMETHOD M : INT\n\
         VAR a, b : POINTER TO INT := THIS^.p; END_VAR\nM := 1;\nEND_METHOD\n\
         END_FUNCTION_BLOCK\n",
    );
    assert_eq!(
        heads,
        ["shared.st:4:27: error[E0305]: a pointer cannot have the initial value `THIS^.p`"]
    );
}

/// A method's local variable named like one of its block's methods (`Hash : DINT` in `Resize`
/// beside `THIS^.Hash(key)`, fisothemes/TwinCat-Dynamic-Collections): `THIS^.Hash(...)` calls the
/// method (twice per call of Resize), `Hash` alone is the variable (before: E3103, `Hash` is a
/// variable, not a function). r = (5 * 2) MOD 7; seen = 99 + 1.
#[test]
fn a_method_call_is_not_taken_for_a_local_variable_of_the_same_name() {
    let (trace, stderr) = run_traced(
        &fixture("shadowed_method.st"),
        2,
        "Main.m.r,Main.m.seen,Main.m.hashes",
    );
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.m.r"), [3.0, 3.0]);
    assert_eq!(column(&trace, "Main.m.seen"), [100.0, 100.0]);
    assert_eq!(column(&trace, "Main.m.hashes"), [2.0, 4.0]);
}

/// A chain through a base view (`VAR_IN_OUT b : FB_Base` holding an `FB_Derived`):
/// `b.Get(0).Value := 42;` runs the derived override (`items[1 - i]`), and the `REFERENCE TO`
/// result is bound through the dispatch, so the write reaches `d.items[1]` (before: E1021, also
/// for `t REF= b.Get(0);` without a chain).
#[test]
fn a_chain_through_a_base_view_runs_the_override_and_writes_through() {
    let (trace, stderr) = run_traced(&fixture("base_view_chain.st"), 1, "Main.x,Main.y");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.x"), [42.0]);
    assert_eq!(column(&trace, "Main.y"), [43.0]);
}
