//! Interpreter behaviour: the paper's statement on the simulated drive, passes and snapshots, slices,
//! integer semantics, timers, jumps and loops, and the full 3-Motion acceptance script.

use drive_script::*;

fn program(text: &str) -> Program {
    let (map, r) = compile_str("t.ds", text);
    match r {
        Ok(c) => c.program,
        Err(d) => panic!("{}", diagnostics::render_human(&map, &d.into_sorted())),
    }
}

fn run(interp: &mut Interpreter, drive: &mut SimDrive, cycles: usize) {
    for _ in 0..cycles {
        interp.cycle(drive);
        drive.tick();
    }
}

#[test]
fn paper_statement_sets_do0_and_moves_plus_10000_pulses() {
    let p = program(
        "S:: INIT; S:: Velocity = 100000; S:: Acceleration = 1000000; S:: Deceleration = 1000000;\n\
         S:: MOTION 0; S:: EVENT 0; S:: IF MD0 = 0;\n\
         S:: THEN DO_0=HIGH AND RelativeTargetPosition=10000 AND MD0 = 1;",
    );
    let mut i = Interpreter::new(p).unwrap();
    let mut d = SimDrive::new(1);
    assert_eq!(i.cycle(&mut d), CycleResult::EndOfPass);
    assert_eq!(
        d.digital_outputs() & 1,
        1,
        "DO_0 is HIGH right after the Event"
    );
    assert_eq!(d.motion_state(), MotionState::Moving);
    run(&mut i, &mut d, 1000);
    assert_eq!(d.actual_position(), 10000);
    assert_eq!(i.memory(0), Some(1), "the Event ran once");
}

#[test]
fn conditions_read_the_snapshot_taken_at_the_start_of_the_pass() {
    // Event 0 starts a move; Event 1 in the same pass still sees the standstill snapshot.
    let p = program(
        "S:: MOTION 0;\n\
         S:: EVENT 0; S:: IF MD0 = 0; S:: THEN VelocityMove = 1000 AND MD0 = 1;\n\
         S:: EVENT 1; S:: IF MotionState = 0; S:: THEN MD1 = MD1 + 1;",
    );
    let mut i = Interpreter::new(p).unwrap();
    let mut d = SimDrive::new(1);
    i.cycle(&mut d);
    assert_eq!(d.motion_state(), MotionState::Moving);
    assert_eq!(i.memory(1), Some(1), "same pass: snapshot says standstill");
    d.tick();
    i.cycle(&mut d);
    assert_eq!(i.memory(1), Some(1), "next pass: snapshot says moving");
    assert_eq!(i.snapshot().motion_state, MotionState::Moving);
}

#[test]
fn a_slice_evaluates_at_most_events_per_cycle_events() {
    let mut text = String::from("S:: INIT; S:: EventsPerCycle = 3; S:: MOTION 0;\n");
    for e in 0..7 {
        text.push_str(&format!(
            "S:: EVENT {e}; S:: IF TRUE; S:: THEN MD{e} = MD{e} + 1;\n"
        ));
    }
    let mut i = Interpreter::new(program(&text)).unwrap();
    let mut d = SimDrive::new(1);
    assert_eq!(i.cycle(&mut d), CycleResult::Budget);
    assert_eq!(i.events_evaluated(), 3);
    assert_eq!(i.memory_words()[..7], [1, 1, 1, 0, 0, 0, 0]);
    assert_eq!(i.cycle(&mut d), CycleResult::Budget);
    assert_eq!(i.cycle(&mut d), CycleResult::EndOfPass);
    assert_eq!(i.memory_words()[..7], [1; 7]);
    assert_eq!(i.location(), Location::START);
}

#[test]
fn an_endless_jump_loop_never_blocks_a_cycle() {
    let p = program("S:: MOTION 0; S:: EVENT 0; S:: IF TRUE; S:: THEN MD0 = MD0 + 1 AND Jump = 0;");
    let mut i = Interpreter::new(p).unwrap();
    let mut d = SimDrive::new(1);
    assert_eq!(i.cycle(&mut d), CycleResult::Budget);
    assert_eq!(i.memory(0), Some(32), "default EventsPerCycle is 32");
}

#[test]
fn loop_counts_an_md_word_down_to_zero() {
    // Adds P0 to MD1 five times in one pass.
    let p = program(
        "S:: PARAM; S:: P0 = 7; S:: INIT; S:: MD0 = 5; S:: MOTION 0;\n\
         S:: EVENT 0; S:: IF MD0 > 0; S:: THEN MD1 = MD1 + P0 AND Loop(MD0) = 0;\n\
         S:: EVENT 1; S:: IF TRUE; S:: THEN MD2 = 1;",
    );
    let mut i = Interpreter::new(p).unwrap();
    let mut d = SimDrive::new(1);
    assert_eq!(i.cycle(&mut d), CycleResult::EndOfPass);
    assert_eq!(i.memory(1), Some(35));
    assert_eq!(i.memory(0), Some(0));
    assert_eq!(i.memory(2), Some(1));
}

#[test]
fn integer_semantics_wrap_and_division_by_zero_gives_zero_and_math_error() {
    let p = program(
        "S:: INIT; S:: MD0 = 2147483647; S:: MD1 = -2147483648; S:: MD9 = 0; S:: MOTION 0;\n\
         S:: EVENT 0; S:: IF TRUE;\n\
         S:: THEN MD2 = MD0 + 1 AND MD3 = MD1 - 1 AND MD4 = MD0 * 2 AND MD5 = MD1 / -1 AND MD6 = MD1 % -1 AND MD7 = -7 / 2 AND MD8 = -7 % 2;\n\
         S:: EVENT 1; S:: IF MathError = 0; S:: THEN MD10 = 5 / MD9 AND MD11 = 5 % MD9 AND MD12 = MathError;\n\
         S:: EVENT 2; S:: IF MathError; S:: THEN MathError = 0 AND MD13 = 1;",
    );
    let mut i = Interpreter::new(p).unwrap();
    let mut d = SimDrive::new(1);
    i.cycle(&mut d);
    let m = i.memory_words();
    assert_eq!(m[2], i32::MIN, "MAX + 1 wraps");
    assert_eq!(m[3], i32::MAX, "MIN - 1 wraps");
    assert_eq!(m[4], -2, "MAX * 2 wraps");
    assert_eq!(m[5], i32::MIN, "MIN / -1 wraps");
    assert_eq!(m[6], 0, "MIN % -1 is 0");
    assert_eq!(m[7], -3, "division truncates toward zero");
    assert_eq!(m[8], -1, "remainder has the dividend's sign");
    assert_eq!(m[10], 0);
    assert_eq!(m[11], 0);
    assert_eq!(m[12], 1, "the flag is set by the division by zero");
    assert_eq!(m[13], 1, "MathError is readable in an IF");
    assert!(!i.math_error(), "MathError = 0 clears the flag");
}

#[test]
fn timers_are_done_after_their_time_on_the_drive_clock() {
    let p = program(
        "S:: MOTION 0;\n\
         S:: EVENT 0; S:: IF MD0 = 0; S:: THEN TimerSet_3 = 10 AND MD0 = 1;\n\
         S:: EVENT 1; S:: IF MD0 = 1 AND TimerDone_3; S:: THEN MD0 = 2 AND MD1 = MD2;\n\
         S:: EVENT 2; S:: IF MD0 = 1; S:: THEN MD2 = MD2 + 1;",
    );
    let mut i = Interpreter::new(p).unwrap();
    let mut d = SimDrive::new(1);
    run(&mut i, &mut d, 30);
    assert_eq!(i.memory(0), Some(2));
    // Passes at t = 0..=9 ms see the timer running (t=0 is the setting pass itself).
    assert_eq!(i.memory(1), Some(10));
}

#[test]
fn digital_inputs_and_outputs_and_drive_readings() {
    let p = program(
        "S:: MOTION 0;\n\
         S:: EVENT 0; S:: IF DI_2 = HIGH AND DI_3 = LOW; S:: THEN DO_5 = HIGH AND VelocityMove = -2000;\n\
         S:: EVENT 1; S:: IF DO_5; S:: THEN MD0 = ActualVelocity AND MD1 = ActualPosition AND MD2 = ActualCurrent;",
    );
    let mut i = Interpreter::new(p).unwrap();
    let mut d = SimDrive::new(1);
    run(&mut i, &mut d, 5);
    assert_eq!(d.digital_outputs(), 0, "DI_2 is LOW");
    d.set_input(2, true);
    run(&mut i, &mut d, 500);
    assert_eq!(d.digital_outputs(), 1 << 5);
    assert_eq!(i.memory(0), Some(-2000));
    assert!(i.memory(1).unwrap() < -500);
    assert_eq!(i.memory(2), Some(0), "no current at constant velocity");
}

#[test]
fn jog_homing_set_position_absolute_move_and_settings_reach_the_drive() {
    let p = program(
        "S:: INIT; S:: JogVelocity = 3000; S:: MOTION 0;\n\
         S:: EVENT 0; S:: IF MD0 = 0; S:: THEN Jog = 1 AND MD0 = 1;\n\
         S:: EVENT 1; S:: IF MD0 = 1 AND ActualVelocity = 3000; S:: THEN Jog = 0 AND MD0 = 2;\n\
         S:: EVENT 2; S:: IF MD0 = 2 AND MotionDone; S:: THEN SetPosition = 500 AND Homing = 1 AND MD0 = 3;\n\
         S:: EVENT 3; S:: IF MD0 = 3 AND Homed; S:: THEN Velocity = 50000 AND Acceleration = 500000 AND Deceleration = 500000 AND AbsoluteTargetPosition = -4000 AND MD0 = 4;\n\
         S:: EVENT 4; S:: IF MD0 = 4 AND MotionDone AND ActualPosition = -4000; S:: THEN MD0 = 5;",
    );
    let mut i = Interpreter::new(p).unwrap();
    let mut d = SimDrive::new(1);
    let mut states = vec![i.memory(0)];
    for _ in 0..5000 {
        i.cycle(&mut d);
        if states.last() != Some(&i.memory(0)) {
            states.push(i.memory(0));
        }
        d.tick();
    }
    assert_eq!(states, [0, 1, 2, 3, 4, 5].map(Some).to_vec());
    assert!(d.homed());
    assert_eq!(d.actual_position(), -4000);
}

#[test]
fn three_motion_script_indexes_three_times_and_returns_home() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/scripts/three_motions.ds"
    ))
    .unwrap();
    let mut i = Interpreter::new(program(&text)).unwrap();
    let mut d = SimDrive::new(1);
    let mut max_pos = 0;
    let mut motions_seen = Vec::new();
    for _ in 0..5000 {
        if i.cycle(&mut d) == CycleResult::EndOfPass
            && i.location().motion == 0
            && i.memory(0) == Some(2)
        {
            d.set_input(0, true);
        }
        if motions_seen.last() != Some(&i.location().motion) {
            motions_seen.push(i.location().motion);
        }
        d.tick();
        max_pos = max_pos.max(d.actual_position());
    }
    assert_eq!(motions_seen, vec![0, 1, 2]);
    assert_eq!(max_pos, 30000, "three index moves of P0 = 10000");
    assert_eq!(i.memory(0), Some(30));
    assert_eq!(d.actual_position(), 0);
    assert_eq!(
        d.digital_outputs(),
        0b110,
        "DO_0 low after the last index; DO_1 and DO_2 high"
    );
}

#[test]
fn interpreter_rejects_a_program_that_breaks_the_pool_invariants() {
    let mut p = program("S:: MOTION 0; S:: EVENT 0; S:: IF TRUE; S:: THEN MD0 = 1;");
    p.events[0].actions[0].index = 50;
    assert!(Interpreter::new(p.clone())
        .unwrap_err()
        .contains("out of range"));
    p.events[0].actions[0].index = 0;
    p.motions[0].event_count = 2;
    assert!(Interpreter::new(p).is_err());
}
