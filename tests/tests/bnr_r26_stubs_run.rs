//! Round 26 of unseen projects (issue #13), vendor stubs named like ladderc's blocks and outputs in
//! positional calls, run end to end through `ladderc`:
//! - a B&R library's `.fun` stub whose interface differs from the block ladderc provides under
//!   that name (Acp10_MC's `MC_Power` takes `Axis : UDINT`, an address, PLCopen's `Axis :
//!   AXIS_REF` in-out) is the vendor's block, which ladderc does not have: one E1003 per block
//!   type at its first instance, naming the `.fun` file and the difference (before: E1006 "cannot
//!   store UDINT into AXIS_REF" and E1033 "VAR_IN_OUT `Axis` not connected" at every call, 102
//!   errors in one project);
//! - a stub whose interface is ladderc's (`standard.fun`'s TON) keeps ladderc's block standing in:
//!   the program runs (unchanged);
//! - a method whose only parameter is an output, called positionally (`c.Get(x)`, as SIMATIC AX
//!   writes it): the argument binds the output (IEC 61131-3 ed. 3, 6.6.1.4.2: a non-formal call
//!   gives the parameters in the order of the definition) (before: E1011 "C has no input or
//!   output `Get`");
//! - a function block called positionally with one argument too many past its outputs: the
//!   E1020 says an output is given by position only with all the parameters and how to connect it
//!   (before: "C has 0 inputs, 1 given" alone). (Since round 28 a positional call that lists
//!   all of a block's parameters, outputs included, binds the outputs: `functions_r28_run.rs`.)

mod common;

use common::{check_files, check_text, column, in_dir, run_text, write_in};

/// B&R's `MC_Power` (`Axis : UDINT`) declared in a `.fun` stub, two instances called twice each
/// with `Axis := ADR(axis)`: one error, at the first instance, no error at the calls.
#[test]
fn bnr_vendor_stub_unlike_ladderc_block_is_one_error() {
    let fun = "FUNCTION_BLOCK MC_Power\n\tVAR_INPUT\n\t\tAxis : UDINT;\n\t\tEnable : BOOL;\n\tEND_VAR\n\tVAR_OUTPUT\n\t\tStatus : BOOL;\n\t\tBusy : BOOL;\n\t\tError : BOOL;\n\t\tErrorID : UINT;\n\tEND_VAR\n\tVAR\n\t\tInternal : UDINT;\n\tEND_VAR\nEND_FUNCTION_BLOCK\n";
    let main = "PROGRAM main\nVAR\n\taxis : UDINT;\n\tpowerA : MC_Power;\n\tpowerB : MC_Power;\n\ton : BOOL;\nEND_VAR\npowerA(Axis := ADR(axis), Enable := TRUE);\npowerA(Axis := ADR(axis), Enable := TRUE);\npowerB(Axis := ADR(axis), Enable := FALSE);\npowerB(Axis := ADR(axis), Enable := FALSE);\non := powerA.Status;\nEND_PROGRAM\n";
    let (code, lines) = check_files(&[("acp10_mc.fun", fun), ("Main.st", main)]);
    assert_eq!(code, Some(1), "{lines:?}");
    let errors: Vec<&String> = lines.iter().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{lines:?}");
    assert!(
        errors[0].starts_with("Main.st:4:11: error[E1003]: `MC_Power` of acp10_mc.fun (VAR_INPUT Axis : UDINT) is B&R's, not PLCopen's (VAR_IN_OUT Axis : AXIS_REF): not provided"),
        "{lines:?}"
    );
}

/// `standard.fun`'s TON stub (the standard interface): ladderc's TON stands in and times.
#[test]
fn bnr_stub_like_ladderc_block_keeps_it() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "standard.fun",
        "FUNCTION_BLOCK TON\n\tVAR_INPUT\n\t\tIN : BOOL;\n\t\tPT : TIME;\n\tEND_VAR\n\tVAR_OUTPUT\n\t\tQ : BOOL;\n\t\tET : TIME;\n\tEND_VAR\nEND_FUNCTION_BLOCK\n",
    );
    write_in(
        dir.path(),
        "Main.st",
        "PROGRAM main\nVAR\n\tt : TON;\n\tdone : BOOL;\nEND_VAR\nt(IN := TRUE, PT := T#25ms);\ndone := t.Q;\nEND_PROGRAM\n",
    );
    let (code, stdout, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "--lang",
            "st",
            "standard.fun",
            "Main.st",
            "--cycles",
            "5",
            "--cycle-ms",
            "10",
            "--watch",
            "main.done",
            "--trace",
            "-",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    let done = column(&stdout, "main.done");
    assert_eq!(done.first(), Some(&0.0), "{stdout}");
    assert_eq!(done.last(), Some(&1.0), "{stdout}");
}

/// `c.Get(x)` where `Get` declares only `VAR_OUTPUT o`: `x` receives `o`.
#[test]
fn method_output_passed_positionally() {
    let src = "FUNCTION_BLOCK Counter\nVAR\n\tv : INT := 7;\nEND_VAR\nMETHOD PUBLIC Get\nVAR_OUTPUT\n\to : INT;\nEND_VAR\no := v;\nv := v + 1;\nEND_METHOD\nEND_FUNCTION_BLOCK\n\nPROGRAM main\nVAR\n\tc : Counter;\n\tx : INT;\nEND_VAR\nc.Get(x);\nEND_PROGRAM\n";
    let (trace, stderr) = run_text("get.st", src, 2, "main.x");
    assert!(!stderr.contains("error["), "{stderr}");
    assert_eq!(column(&trace, "main.x"), vec![7.0, 8.0], "{trace}");
}

/// A function block given more positional arguments than its inputs and not all its parameters
/// (outputs included): one E1020 that says an output is not passed so.
#[test]
fn fb_output_positional_is_explained() {
    let src = "FUNCTION_BLOCK Five\nVAR_OUTPUT\n\to : INT;\nEND_VAR\no := 5;\nEND_FUNCTION_BLOCK\n\nPROGRAM main\nVAR\n\tf : Five;\n\tx : INT;\nEND_VAR\nf(x, x);\nEND_PROGRAM\n";
    let (code, lines) = check_text("five.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains("error[E1020]: Five has 0 inputs, 2 given: an output of a block is given by position only in a call that lists all its parameters in order")
            && lines[0].contains("`o => x`"),
        "{lines:?}"
    );
}
