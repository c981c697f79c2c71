//! Debugger acceptance: stops before IF and THEN, nothing runs while stopped, step across an Event and
//! across NextMotionID, write while stopped, the fifth breakpoint is refused; CLI debug transcript.

use drive_script::cli::{debug, DebugArgs, DebugSession};
use drive_script::*;

const SCRIPT: &str = "\
S:: PARAM;
S:: P0 = 100;
S:: MOTION 0;
S:: EVENT 0;
S:: IF MD0 < P0;
S:: THEN MD0 = MD0 + 1 AND MD1 = MD1 + 10;
S:: EVENT 1;
S:: IF MD0 >= 3;
S:: THEN DO_0 = HIGH AND NextMotionID = 1;
S:: MOTION 1;
S:: EVENT 0;
S:: IF TRUE;
S:: THEN MD2 = MD2 + 1;
";

fn interp() -> (Interpreter, SimDrive) {
    let p = compile_str("t.ds", SCRIPT).1.unwrap().program;
    (Interpreter::new(p).unwrap(), SimDrive::new(1))
}

fn at(motion: u16, event: u16, phase: Phase) -> Location {
    Location {
        motion,
        event,
        phase,
    }
}

#[test]
fn stops_before_if_and_nothing_runs_while_stopped() {
    let (mut i, mut d) = interp();
    i.add_breakpoint(at(0, 1, Phase::BeforeIf)).unwrap();
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 1, Phase::BeforeIf))
    );
    assert_eq!(i.memory(0), Some(1), "Event 0 ran before the stop");
    for _ in 0..1000 {
        assert_eq!(
            i.cycle(&mut d),
            CycleResult::Stopped(at(0, 1, Phase::BeforeIf))
        );
        d.tick();
    }
    assert_eq!(i.memory(0), Some(1), "nothing ran during 1000 cycles");
    assert_eq!(i.events_evaluated(), 1);
    // Resuming continues exactly there: Event 1's IF (false), then the pass ends.
    i.resume();
    assert_eq!(i.cycle(&mut d), CycleResult::EndOfPass);
    assert_eq!(i.events_evaluated(), 2);
    // Next pass: Event 0 runs again, then the breakpoint stops again.
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 1, Phase::BeforeIf))
    );
    assert_eq!(i.memory(0), Some(2));
}

#[test]
fn stops_before_then_only_when_the_if_holds_and_resumes_without_reevaluating() {
    let (mut i, mut d) = interp();
    i.add_breakpoint(at(0, 1, Phase::BeforeThen)).unwrap();
    for _ in 0..2 {
        assert_eq!(
            i.cycle(&mut d),
            CycleResult::EndOfPass,
            "MD0 < 3: IF fails, no stop"
        );
    }
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 1, Phase::BeforeThen))
    );
    assert_eq!(i.memory(0), Some(3));
    assert_eq!(d.digital_outputs(), 0, "THEN not run yet");
    // Make the IF false while stopped: the THEN still runs, since the stop is after the IF.
    i.set_memory(0, 0);
    i.resume();
    assert_eq!(i.cycle(&mut d), CycleResult::MotionChanged(1));
    assert_eq!(d.digital_outputs(), 1);
}

#[test]
fn step_goes_if_then_if_across_an_event() {
    let (mut i, mut d) = interp();
    i.add_breakpoint(at(0, 0, Phase::BeforeIf)).unwrap();
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 0, Phase::BeforeIf))
    );
    i.step();
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 0, Phase::BeforeThen))
    );
    assert_eq!(i.memory(0), Some(0), "IF evaluated, THEN not yet");
    i.step();
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 1, Phase::BeforeIf))
    );
    assert_eq!(
        (i.memory(0), i.memory(1)),
        (Some(1), Some(10)),
        "the THEN ran"
    );
    assert!(
        !i.breakpoints().temp_armed(),
        "the temporary entry disarms itself"
    );
    // IF of Event 1 fails: a step goes to the next pass, stopping at the user breakpoint's point.
    i.step();
    assert_eq!(i.cycle(&mut d), CycleResult::EndOfPass);
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 0, Phase::BeforeIf))
    );
}

#[test]
fn step_across_next_motion_id() {
    let (mut i, mut d) = interp();
    i.set_memory(0, 5);
    i.add_breakpoint(at(0, 1, Phase::BeforeThen)).unwrap();
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 1, Phase::BeforeThen))
    );
    i.step();
    assert_eq!(i.cycle(&mut d), CycleResult::MotionChanged(1));
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(1, 0, Phase::BeforeIf))
    );
    assert_eq!(i.memory(2), Some(0));
    i.step();
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(1, 0, Phase::BeforeThen))
    );
    i.resume();
    assert_eq!(i.cycle(&mut d), CycleResult::EndOfPass);
    assert_eq!(i.memory(2), Some(1));
}

#[test]
fn a_write_while_stopped_takes_effect_after_resuming() {
    let (mut i, mut d) = interp();
    i.add_breakpoint(at(0, 0, Phase::BeforeIf)).unwrap();
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 0, Phase::BeforeIf))
    );
    // P0 = 0 makes `MD0 < P0` false: Event 0 must not run after resuming.
    assert!(i.set_param(0, 0));
    i.resume();
    i.cycle(&mut d);
    assert_eq!(i.memory(0), Some(0));
    // MD0 = 7 makes Event 1 hold: its NextMotionID runs in the same slice.
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 0, Phase::BeforeIf))
    );
    i.set_memory(0, 7);
    i.resume();
    assert_eq!(i.cycle(&mut d), CycleResult::MotionChanged(1));
    assert!(!i.set_memory(50, 1), "out-of-range writes are refused");
}

#[test]
fn the_fifth_breakpoint_is_refused_and_deleting_frees_a_slot() {
    let (mut i, _) = interp();
    let points = [
        at(0, 0, Phase::BeforeIf),
        at(0, 0, Phase::BeforeThen),
        at(0, 1, Phase::BeforeIf),
        at(0, 1, Phase::BeforeThen),
    ];
    for (n, p) in points.iter().enumerate() {
        assert_eq!(i.add_breakpoint(*p), Ok(n));
    }
    assert_eq!(
        i.add_breakpoint(at(1, 0, Phase::BeforeIf)),
        Err(BreakpointError::Full)
    );
    assert_eq!(
        i.add_breakpoint(at(0, 1, Phase::BeforeIf)),
        Ok(2),
        "same point: same entry"
    );
    i.delete_breakpoint(2).unwrap();
    assert_eq!(i.add_breakpoint(at(1, 0, Phase::BeforeIf)), Ok(2));
    assert_eq!(
        i.add_breakpoint(at(3, 0, Phase::BeforeIf)),
        Err(BreakpointError::NoSuchLocation(at(3, 0, Phase::BeforeIf)))
    );
    assert_eq!(
        i.delete_breakpoint(7),
        Err(BreakpointError::NoSuchBreakpoint(7))
    );
}

#[test]
fn a_disabled_breakpoint_does_not_stop() {
    let (mut i, mut d) = interp();
    let n = i.add_breakpoint(at(0, 0, Phase::BeforeIf)).unwrap();
    i.enable_breakpoint(n, false).unwrap();
    assert_eq!(i.cycle(&mut d), CycleResult::EndOfPass);
    i.enable_breakpoint(n, true).unwrap();
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 0, Phase::BeforeIf))
    );
}

#[test]
fn pause_stops_at_the_next_point() {
    let (mut i, mut d) = interp();
    i.cycle(&mut d);
    i.pause();
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 0, Phase::BeforeIf))
    );
}

#[test]
fn session_print_and_set_registers() {
    let compiled = compile_str("t.ds", SCRIPT).1.unwrap();
    let mut s = DebugSession::new(compiled.program, None).unwrap();
    let mut out = Vec::new();
    for cmd in [
        "set MD3 = -4",
        "print md3",
        "set DI_2 HIGH",
        "print DI_2",
        "set P1 0x10",
        "print P1",
        "set DO_1 = 1",
        "print do_1",
        "print MD50",
        "bogus",
    ] {
        assert!(s.command(cmd, &mut out));
    }
    assert!(!s.command("quit", &mut out));
    let text = String::from_utf8(out).unwrap();
    assert_eq!(
        text,
        "MD3 = -4\nMD3 = -4\nDI_2 = 1\nDI_2 = 1\nP1 = 16\nP1 = 16\nDO_1 = 1\nDO_1 = 1\n\
         error: cannot print `MD50`\nerror: unknown command `bogus` (type `help`)\n"
    );
}

#[test]
fn cli_debug_transcript() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("prog.ds");
    std::fs::write(&path, SCRIPT).unwrap();
    let commands = "\
break 0 1 then
break 0 0
break 0 1
break 1 0 then
break 1 0
list
watch MD0
watch DO_0
run
print where
step
step
print MD0
delete 1
set MD0 = 2
run
print MD0
print md
step
step
print DO_0
delete 0
delete 2
run 50
print MD2
pause
unwatch DO_0
watch
help
quit
print MD0
";
    let mut out = Vec::new();
    let mut err = Vec::new();
    let args = DebugArgs {
        script: path,
        format: diagnostics::MessageFormat::Short,
    };
    let code = debug(&args, &mut commands.as_bytes(), &mut out, &mut err);
    assert_eq!(code, 0);
    assert!(err.is_empty());
    let text = String::from_utf8(out)
        .unwrap()
        .replace(&dir.path().display().to_string(), "DIR");
    insta::assert_snapshot!(text);
}

#[test]
fn inputs_changed_while_stopped_before_a_pass_are_seen_after_resuming() {
    let p = compile_str(
        "t.ds",
        "S:: MOTION 0; S:: EVENT 0; S:: IF DI_4 = HIGH; S:: THEN MD0 = ActualPosition;",
    )
    .1
    .unwrap()
    .program;
    let (mut i, mut d) = (Interpreter::new(p).unwrap(), SimDrive::new(1));
    i.add_breakpoint(at(0, 0, Phase::BeforeIf)).unwrap();
    assert_eq!(
        i.cycle(&mut d),
        CycleResult::Stopped(at(0, 0, Phase::BeforeIf))
    );
    d.set_input(4, true);
    d.set_position(777);
    i.resume();
    assert_eq!(i.cycle(&mut d), CycleResult::EndOfPass);
    assert_eq!(
        i.memory(0),
        Some(777),
        "the pass snapshot is taken when the pass really starts"
    );
}
