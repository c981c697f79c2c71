//! Scripts driving a motion-lib axis through `MotionLibDrive`: the paper's statement with the jerk-limited
//! profile and the axis limits checked on every cycle, two moves sequenced by `MotionDone`, homing, jog and
//! stop, refused commands and axis errors.

use drive_script::*;
use motion_lib::axis::AxisConfig;
use motion_lib::error::ErrorId;
use motion_lib::fsm::AxisState;
use motion_lib::profile::{Limits, Profile, State};

fn program(text: &str) -> Program {
    let (map, r) = compile_str("t.ds", text);
    match r {
        Ok(c) => c.program,
        Err(d) => panic!("{}", diagnostics::render_human(&map, &d.into_sorted())),
    }
}

/// Equal within 1e-6 pulse (positions are f64 sums of profile segments and the axis origin).
#[track_caller]
fn close(a: f64, b: f64) {
    assert!((a - b).abs() < 1e-6, "{a} != {b}");
}

fn axis(limits: Limits) -> MotionLibDrive {
    let cfg = AxisConfig {
        limits,
        ..AxisConfig::default()
    };
    MotionLibDrive::with_axis(1, cfg).unwrap()
}

/// Set point of the axis after a cycle: (position, velocity, acceleration).
fn set_point(d: &MotionLibDrive) -> (f64, f64, f64) {
    let e = d.engine();
    (
        e.set_position_of(d.axis()).unwrap(),
        e.set_velocity_of(d.axis()).unwrap(),
        e.set_acceleration_of(d.axis()).unwrap(),
    )
}

const PAPER: &str = "\
S:: INIT; S:: Velocity = 100000; S:: Acceleration = 1000000; S:: Deceleration = 1000000;
S:: MOTION 0; S:: EVENT 0; S:: IF MD0 = 0;
S:: THEN DO_0=HIGH AND RelativeTargetPosition=10000 AND MD0 = 1;";

#[test]
fn paper_statement_moves_a_motion_lib_axis_with_its_jerk_limited_profile_within_the_limits() {
    // The axis limits are below the script's settings: the engine must use the axis's limits.
    let lim = Limits {
        vmax: 60_000.0,
        amax: 600_000.0,
        dmax: 500_000.0,
        jmax: 20_000_000.0,
    };
    let mut d = axis(lim);
    let mut i = Interpreter::new(program(PAPER)).unwrap();
    assert_eq!(i.cycle(&mut d), CycleResult::EndOfPass);
    assert_eq!(
        d.digital_outputs() & 1,
        1,
        "DO_0 is HIGH right after the Event"
    );
    assert_eq!(d.motion_state(), MotionState::Moving, "moving at once");
    assert_eq!(d.axis_state(), AxisState::DiscreteMotion);

    let dt = 0.001;
    let tol = 1e-9;
    let (mut prev_p, mut prev_a) = (0.0, 0.0);
    let (mut peak_v, mut peak_a, mut peak_d) = (0.0f64, 0.0f64, 0.0f64);
    let mut moving_cycles = 0;
    for n in 0..1000 {
        i.cycle(&mut d);
        d.tick();
        let (p, v, a) = set_point(&d);
        assert!(v.abs() <= lim.vmax * (1.0 + tol), "cycle {n}: v {v}");
        assert!(a <= lim.amax * (1.0 + tol), "cycle {n}: a {a}");
        assert!(-a <= lim.dmax * (1.0 + tol), "cycle {n}: a {a}");
        assert!(
            (a - prev_a).abs() <= lim.jmax * dt * (1.0 + 1e-6),
            "cycle {n}: jerk {}",
            (a - prev_a) / dt
        );
        // The actual position (what the script reads) moves no faster than vmax.
        assert!((d.position() - prev_p).abs() <= lim.vmax * dt * (1.0 + tol));
        assert!(d.position() >= prev_p - tol, "monotonic");
        assert_eq!(d.position(), p, "the simulated drive follows the set point");
        peak_v = peak_v.max(v);
        peak_a = peak_a.max(a);
        peak_d = peak_d.max(-a);
        if d.motion_state() != MotionState::Standstill {
            moving_cycles += 1;
        }
        prev_p = d.position();
        prev_a = a;
    }
    close(d.position(), 10_000.0);
    assert_eq!(d.actual_position(), 10_000);
    assert_eq!(d.actual_velocity(), 0);
    assert_eq!(d.motion_state(), MotionState::Standstill);
    assert_eq!(i.memory(0), Some(1), "the Event ran once");
    // The limits were reached (the test would not check anything if they were far away).
    assert!(peak_v > 0.99 * lim.vmax, "{peak_v}");
    assert!(peak_a > 0.99 * lim.amax && peak_d > 0.99 * lim.dmax);
    // The move lasts as long as motion-lib's own plan of it.
    let plan = Profile::position(State::default(), 10_000.0, 0.0, &lim).unwrap();
    let planned = (plan.duration() / dt).ceil() as i32;
    assert!(
        (moving_cycles - planned).abs() <= 1,
        "{moving_cycles} cycles, planned {planned}"
    );
}

#[test]
fn the_first_cycles_of_a_move_ramp_the_acceleration_at_the_jerk_limit() {
    // Default limits: jerk 1e8 p/s³, so after 1 ms v = j t²/2 = 50 p/s and a = j t = 100000 p/s².
    let mut d = MotionLibDrive::new(1);
    let mut i = Interpreter::new(program(PAPER)).unwrap();
    i.cycle(&mut d);
    d.tick();
    let (_, v, a) = set_point(&d);
    assert!((v - 50.0).abs() < 1e-6, "{v}");
    assert!((a - 100_000.0).abs() < 1e-3, "{a}");
    assert_eq!(d.actual_velocity(), 50);
    assert_eq!(d.actual_current(), 1000, "0.01 mA per p/s²");
}

#[test]
fn a_script_waiting_for_motion_done_sequences_two_moves() {
    let p = program(
        "S:: INIT; S:: Velocity = 50000; S:: Acceleration = 500000; S:: Deceleration = 500000;
         S:: MOTION 0; S:: EVENT 0; S:: IF TRUE; S:: THEN RelativeTargetPosition = 5000 AND NextMotionID = 1;
         S:: MOTION 1; S:: EVENT 0; S:: IF MotionDone;
         S:: THEN MD0 = ActualPosition AND MD3 = ActualVelocity AND AbsoluteTargetPosition = 12000 AND NextMotionID = 2;
         S:: MOTION 2; S:: EVENT 0; S:: IF MotionDone;
         S:: THEN MD1 = ActualPosition AND MD2 = MD2 + 1 AND NextMotionID = 3;
         S:: MOTION 3; S:: EVENT 0; S:: IF 0; S:: THEN Stop;",
    );
    let mut d = MotionLibDrive::new(1);
    let mut i = Interpreter::new(p).unwrap();
    let mut first_done_at = None;
    let mut positions = Vec::new();
    for n in 0..2000 {
        i.cycle(&mut d);
        if first_done_at.is_none() && i.memory(0) != Some(0) {
            first_done_at = Some(n);
            // The second move starts from standstill at the first target.
            close(*positions.last().unwrap(), 5000.0);
            assert_eq!(d.motion_state(), MotionState::Moving);
        }
        d.tick();
        positions.push(d.position());
    }
    assert_eq!(
        i.memory(0),
        Some(5000),
        "first move ended before the second began"
    );
    assert_eq!(i.memory(3), Some(0), "at standstill");
    assert_eq!(i.memory(1), Some(12000));
    assert_eq!(i.memory(2), Some(1));
    assert_eq!(i.location().motion, 3);
    // Without the immediate "moving" report, Motion 1 would see MotionDone in the cycle after the command.
    let first = first_done_at.expect("the first move ended");
    assert!(first > 100, "{first}");
    assert!(positions.windows(2).all(|w| w[0] <= w[1]));
    assert_eq!(d.actual_position(), 12000);
}

#[test]
fn relative_move_during_a_move_adds_to_the_running_target() {
    let mut d = MotionLibDrive::new(1);
    d.set_velocity(100_000);
    d.set_acceleration(1_000_000);
    d.set_deceleration(1_000_000);
    d.relative_move(10_000);
    for _ in 0..30 {
        d.tick();
    }
    assert!(d.position() > 100.0 && d.position() < 10_000.0);
    d.relative_move(5_000); // MC_MoveAdditive: target 15000
    assert_eq!(d.motion_state(), MotionState::Moving);
    for _ in 0..1000 {
        d.tick();
    }
    close(d.position(), 15_000.0);
    // At standstill a relative move starts from the actual position (MC_MoveRelative).
    d.relative_move(-20_000);
    for _ in 0..1000 {
        d.tick();
    }
    close(d.position(), -5_000.0);
    // Two relative moves in one THEN: the second adds to the first's target.
    d.relative_move(1000);
    d.relative_move(500);
    for _ in 0..1000 {
        d.tick();
    }
    close(d.position(), -3_500.0);
    d.absolute_move(7);
    for _ in 0..1000 {
        d.tick();
    }
    assert_eq!(d.actual_position(), 7);
}

#[test]
fn homing_runs_to_the_reference_mark_then_the_mark_becomes_position_0() {
    let p = program(
        "S:: INIT; S:: JogVelocity = 20000; S:: Acceleration = 400000; S:: Deceleration = 400000;
         S:: MOTION 0; S:: EVENT 0; S:: IF TRUE;
         S:: THEN MD5 = Homed AND SetPosition = -3000 AND Homing = 1 AND NextMotionID = 1;
         S:: MOTION 1; S:: EVENT 0; S:: IF MotionState = 2; S:: THEN MD2 = MD2 + 1;
         S:: EVENT 1; S:: IF Homed;
         S:: THEN MD0 = ActualPosition AND MD1 = MotionState AND NextMotionID = 2;
         S:: MOTION 2; S:: EVENT 0; S:: IF 0; S:: THEN Stop;",
    );
    let mut d = MotionLibDrive::new(1);
    d.reference_mark = 1000.0;
    let mut i = Interpreter::new(p).unwrap();
    i.cycle(&mut d);
    assert_eq!(d.motion_state(), MotionState::Homing, "homing at once");
    assert!(!d.homed());
    let mut peak = f64::MIN;
    let mut peak_v = 0.0f64;
    for _ in 0..2000 {
        i.cycle(&mut d);
        d.tick();
        peak = peak.max(d.position());
        peak_v = peak_v.max(d.velocity().abs());
    }
    assert_eq!(i.memory(5), Some(0), "not homed before");
    assert!(d.homed());
    assert_eq!(i.memory(0), Some(0), "the reference mark is position 0");
    assert_eq!(i.memory(1), Some(0), "standstill once homed");
    close(peak, 1000.0); // ran from -3000 up to the mark at +1000
    assert!((peak_v - 20_000.0).abs() < 1e-6, "at JogVelocity: {peak_v}");
    // 4000 pulses at 20000 p/s take at least 200 ms, all reported as Homing.
    assert!(i.memory(2).unwrap() >= 200, "{:?}", i.memory(2));
    assert_eq!(d.actual_position(), 0);
}

#[test]
fn homing_method_0_homes_on_the_spot_and_halts_first_when_moving() {
    let mut d = MotionLibDrive::new(1);
    d.set_position(1234);
    assert_eq!(d.actual_position(), 1234, "MC_SetPosition is immediate");
    d.home(0);
    assert_eq!(d.motion_state(), MotionState::Homing);
    d.tick();
    assert!(d.homed());
    assert_eq!(d.actual_position(), 0);
    assert_eq!(d.motion_state(), MotionState::Standstill);

    // While moving: MC_Halt, then MC_Home at the stopping point.
    d.set_velocity(10_000);
    d.velocity_move(10_000);
    for _ in 0..300 {
        d.tick();
    }
    d.home(0);
    assert!(!d.homed());
    assert_eq!(d.motion_state(), MotionState::Homing);
    assert_eq!(d.axis_state(), AxisState::DiscreteMotion, "halting");
    for _ in 0..500 {
        d.tick();
    }
    assert!(d.homed());
    assert_eq!(d.actual_position(), 0);
    assert_eq!(d.motion_state(), MotionState::Standstill);
}

#[test]
fn jog_and_stop_follow_the_inputs() {
    let p = program(
        "S:: INIT; S:: JogVelocity = 20000; S:: Acceleration = 200000; S:: Deceleration = 400000;
         S:: MOTION 0;
         S:: EVENT 0; S:: IF DI_0 = HIGH; S:: THEN Jog = 1;
         S:: EVENT 1; S:: IF DI_1 = HIGH; S:: THEN Jog = -1;
         S:: EVENT 2; S:: IF DI_2 = HIGH; S:: THEN Stop;
         S:: EVENT 3; S:: IF DI_3 = HIGH; S:: THEN Jog = 0;",
    );
    let mut d = MotionLibDrive::new(1);
    let mut i = Interpreter::new(p).unwrap();
    let run = |i: &mut Interpreter, d: &mut MotionLibDrive, inputs: u32, n: usize| {
        d.inputs = inputs;
        let mut peak_dec = 0.0f64;
        for _ in 0..n {
            i.cycle(d);
            d.tick();
            let (_, v, a) = set_point(d);
            if v * a < 0.0 {
                peak_dec = peak_dec.max(a.abs());
            }
        }
        peak_dec
    };
    // Jog + (re-commanded every pass while DI_0 is HIGH).
    run(&mut i, &mut d, 0b0001, 400);
    assert_eq!(d.actual_velocity(), 20_000);
    assert_eq!(d.axis_state(), AxisState::ContinuousMotion);
    assert_eq!(d.motion_state(), MotionState::Moving);
    let p1 = d.position();
    assert!(p1 > 4000.0, "{p1}");
    // Stop (MC_Halt at Deceleration).
    let dec = run(&mut i, &mut d, 0b0100, 300);
    assert!(
        dec <= 400_000.0 * (1.0 + 1e-9) && dec > 0.99 * 400_000.0,
        "{dec}"
    );
    assert_eq!(d.motion_state(), MotionState::Standstill);
    assert_eq!(d.actual_velocity(), 0);
    let p2 = d.position();
    assert!(p2 > p1 && p2 < p1 + 20_000.0 * 0.1);
    // Jog -, then Jog = 0 halts too.
    run(&mut i, &mut d, 0b0010, 400);
    assert_eq!(d.actual_velocity(), -20_000);
    run(&mut i, &mut d, 0b1000, 300);
    assert_eq!(d.motion_state(), MotionState::Standstill);
    assert!(d.position() < p2);
    // Stop at standstill changes nothing.
    let p3 = d.position();
    run(&mut i, &mut d, 0b0100, 10);
    assert_eq!(d.position(), p3);
    assert_eq!(d.motion_state(), MotionState::Standstill);
}

#[test]
fn velocity_move_runs_at_a_signed_velocity_and_zero_halts() {
    let mut d = MotionLibDrive::new(1);
    d.set_acceleration(1_000_000);
    d.set_deceleration(1_000_000);
    d.velocity_move(-30_000);
    assert_eq!(d.motion_state(), MotionState::Moving);
    for _ in 0..200 {
        d.tick();
    }
    assert_eq!(d.actual_velocity(), -30_000);
    // A second command of the same kind while the first is Busy takes the other block instance.
    d.velocity_move(30_000);
    for _ in 0..200 {
        d.tick();
    }
    assert_eq!(d.actual_velocity(), 30_000);
    d.velocity_move(0);
    for _ in 0..200 {
        d.tick();
    }
    assert_eq!(d.actual_velocity(), 0);
    assert_eq!(d.motion_state(), MotionState::Standstill);
}

#[test]
fn a_refused_command_reports_fault_until_the_next_accepted_one() {
    let mut d = MotionLibDrive::new(1);
    d.set_velocity(0);
    d.relative_move(1000);
    assert_eq!(d.command_error(), Some(ErrorId::InvalidVelocity));
    assert_eq!(d.motion_state(), MotionState::Fault);
    d.tick();
    assert_eq!(d.position(), 0.0, "nothing moved");
    assert_eq!(d.motion_state(), MotionState::Fault);
    d.set_velocity(1000);
    d.relative_move(1000);
    assert_eq!(d.command_error(), None);
    assert_eq!(d.motion_state(), MotionState::Moving);
}

#[test]
fn an_axis_error_is_a_fault_and_stop_acknowledges_it_once_the_axis_stands() {
    let mut d = MotionLibDrive::new(1);
    d.set_velocity(10_000);
    d.velocity_move(10_000);
    for _ in 0..200 {
        d.tick();
    }
    let a = d.axis();
    d.engine_mut()
        .raise_axis_error(a, ErrorId::DriveFault)
        .unwrap();
    d.tick();
    assert_eq!(d.axis_state(), AxisState::ErrorStop);
    assert_eq!(d.motion_state(), MotionState::Fault);
    // Still braking: MC_Reset is refused.
    d.stop();
    assert_eq!(d.command_error(), Some(ErrorId::AxisStillMoving));
    for _ in 0..500 {
        d.tick();
    }
    assert_eq!(d.actual_velocity(), 0);
    assert_eq!(d.motion_state(), MotionState::Fault);
    d.stop();
    assert_eq!(d.command_error(), None);
    assert_eq!(d.axis_state(), AxisState::Standstill);
    assert_eq!(d.motion_state(), MotionState::Standstill);
    d.relative_move(100);
    assert_eq!(d.motion_state(), MotionState::Moving);
}

#[test]
fn the_clock_and_outputs_follow_the_main_loop() {
    let mut d = MotionLibDrive::new(4);
    for _ in 0..5 {
        d.tick();
    }
    assert_eq!(d.now_ms(), 20);
    assert!(
        (d.engine().time() - 0.020).abs() < 1e-12,
        "one engine step per tick"
    );
    d.set_digital_output(3, true);
    d.set_digital_output(40, true); // ignored
    assert_eq!(d.digital_outputs(), 0b1000);
    d.set_input_bit(2, true);
    assert_eq!(d.digital_inputs(), 0b100);
}

#[test]
fn the_three_motion_acceptance_script_runs_on_a_motion_lib_axis() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/scripts/three_motions.ds"
    ))
    .unwrap();
    let mut i = Interpreter::new(program(&text)).unwrap();
    let mut d = MotionLibDrive::new(1);
    let mut max_pos = 0;
    let mut motions_seen = Vec::new();
    let mut dwell_at_first_index = 0;
    for _ in 0..5000 {
        i.cycle(&mut d);
        if i.memory(0) == Some(2) {
            d.set_input_bit(0, true); // start button
        }
        if motions_seen.last() != Some(&i.location().motion) {
            motions_seen.push(i.location().motion);
        }
        d.tick();
        max_pos = max_pos.max(d.actual_position());
        if d.actual_position() == 10_000 && d.actual_velocity() == 0 {
            dwell_at_first_index += 1;
        }
        assert!(d.command_error().is_none(), "{d:?} at {}", i.location());
    }
    assert!(d.homed());
    assert_eq!(motions_seen, vec![0, 1, 2]);
    assert_eq!(max_pos, 30000, "three index moves of P0 = 10000");
    assert!(
        (200..210).contains(&dwell_at_first_index),
        "the P2 = 200 ms dwell starts when the move is done: {dwell_at_first_index}"
    );
    assert_eq!(i.memory(0), Some(30));
    assert_eq!(d.actual_position(), 0);
    assert_eq!(d.digital_outputs(), 0b110);
}

#[test]
fn a_move_commanded_at_the_end_of_a_braking_ramp_is_deferred_not_refused() {
    // After 201 cycles the paper's move is in its last jerk phase (v ≈ 4278 p/s, a ≈ -925000 p/s²), a
    // state from which motion-lib's profile kernel finds no plan to a target further on (PlanningFailed).
    for (cycles, additive) in [(201, true), (204, false), (150, true)] {
        let mut d = MotionLibDrive::new(1);
        d.set_velocity(100_000);
        d.set_acceleration(1_000_000);
        d.set_deceleration(1_000_000);
        d.relative_move(10_000);
        for _ in 0..cycles {
            d.tick();
        }
        assert_eq!(d.motion_state(), MotionState::Moving);
        if additive {
            d.relative_move(10_000);
        } else {
            d.absolute_move(20_000);
        }
        assert_eq!(d.command_error(), None, "after {cycles} cycles");
        assert_eq!(d.motion_state(), MotionState::Moving);
        let mut standstill_before_end = false;
        for _ in 0..1000 {
            d.tick();
            assert_eq!(d.command_error(), None);
            if d.motion_state() == MotionState::Standstill && d.actual_position() != 20_000 {
                standstill_before_end = true;
            }
        }
        assert!(!standstill_before_end, "MotionDone only at the new target");
        close(d.position(), 20_000.0);
        assert_eq!(d.motion_state(), MotionState::Standstill);
    }
}

#[test]
fn random_commands_with_extreme_arguments_never_panic_and_keep_the_axis_limits() {
    let lim = Limits {
        vmax: 200_000.0,
        amax: 2_000_000.0,
        dmax: 2_000_000.0,
        jmax: 50_000_000.0,
    };
    let values = [
        0,
        1,
        -1,
        7,
        1000,
        -25_000,
        100_000,
        i32::MAX,
        i32::MIN,
        i32::MIN + 1,
    ];
    let mut seed = 0x2545_F491_4F6C_DD1Du64;
    let mut next = |n: usize| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % n as u64) as usize
    };
    let mut d = axis(lim);
    let mut refused = 0;
    let mut seen = [0u32; 4];
    for cycle in 0..4000 {
        if next(4) == 0 {
            let v = values[next(values.len())];
            match next(13) {
                0 => d.set_velocity(v),
                1 => d.set_acceleration(v),
                2 => d.set_deceleration(v),
                3 => d.set_jog_velocity(v),
                4 => d.set_position(v),
                5 => d.velocity_move(v),
                6 => d.relative_move(v),
                7 => d.absolute_move(v),
                8 => d.jog(v),
                9 => d.home(v),
                10 => d.stop(),
                11 => d.set_digital_output((v & 0xFF) as u8, v != 0),
                _ if next(4) == 0 => {
                    let a = d.axis();
                    let _ = d.engine_mut().raise_axis_error(a, ErrorId::DriveFault);
                }
                _ => d.stop(),
            }
            refused += d.command_error().is_some() as u32;
        }
        d.tick();
        let (_, v, a) = set_point(&d);
        assert!(v.abs() <= lim.vmax * (1.0 + 1e-9), "cycle {cycle}: v {v}");
        assert!(a.abs() <= lim.amax * (1.0 + 1e-9), "cycle {cycle}: a {a}");
        let st = d.motion_state();
        seen[st as usize] += 1;
        if d.command_error().is_some() || d.axis_state() == AxisState::ErrorStop {
            assert_eq!(st, MotionState::Fault);
        } else if d.axis_state() != AxisState::Standstill {
            assert_ne!(st, MotionState::Standstill, "cycle {cycle}");
        }
    }
    assert!(refused > 0, "some commands were refused");
    // Every motion state occurred (the sequence exercises moves, homing and faults).
    assert!(seen.iter().all(|&n| n > 0), "{seen:?}");
}
