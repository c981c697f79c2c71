//! Camming against the slave's limits: the cam law is a twice continuously differentiable
//! spline (periodic or natural), the slave's set velocity and acceleration carry the law's
//! chain-rule terms, and MC_CamIn is refused with ErrorID 33 when the law (for a master within
//! its axis limits) or the coupling does not fit the slave's limits (README "Camming").
//!
//! Input: hand-made tables; 1 ms cycles; slave limits vmax 100, amax = dmax 1000, jmax 10000.
//! Output: assertions on the spline's derivatives and on every cycle's set point.

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::{McCamIn, McMoveVelocity, McPower};
use motion_lib::buffer::{BufferMode, Direction};
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::error::ErrorId;
use motion_lib::fsm::AxisState;
use motion_lib::profile::Limits;
use motion_lib::sync::CamTable;

const SLAVE: Limits = Limits {
    vmax: 100.0,
    amax: 1000.0,
    dmax: 1000.0,
    jmax: 10000.0,
};

const POINTS: [(f64, f64); 6] = [
    (0.0, 0.0),
    (3.0, 2.0),
    (4.0, 5.0),
    (7.5, 4.0),
    (9.0, 1.0),
    (12.0, 3.0),
];

fn axis(e: &mut Engine, l: Limits) -> usize {
    let a = e
        .add_axis(AxisConfig {
            limits: l,
            ..AxisConfig::default()
        })
        .unwrap();
    McPower {
        enable: true,
        ..Default::default()
    }
    .call(e, a);
    a
}

#[test]
fn the_law_is_twice_continuously_differentiable() {
    let t = CamTable::new(&POINTS).unwrap();
    let eps = 1e-7;
    for periodic in [false, true] {
        // Across every inner point: position, slope and curvature continuous.
        for &(x, y) in &POINTS[1..POINTS.len() - 1] {
            let l = t.eval(x - eps, periodic);
            let r = t.eval(x + eps, periodic);
            assert!(
                (t.eval(x, periodic).0 - y).abs() < 1e-12,
                "through the point"
            );
            assert!((l.1 - r.1).abs() < 1e-5, "slope at {x}: {l:?} {r:?}");
            assert!((l.2 - r.2).abs() < 1e-5, "curvature at {x}: {l:?} {r:?}");
        }
    }
    // Periodic: slope and curvature equal at both ends (the wrap is smooth).
    let a = t.eval(0.0, true);
    let b = t.eval(12.0, true);
    assert!(
        (a.1 - b.1).abs() < 1e-12 && (a.2 - b.2).abs() < 1e-12,
        "{a:?} {b:?}"
    );
    // Single-shot: curvature 0 at the ends and a straight line beyond them.
    let (p1, d1, c1) = t.eval(12.0, false);
    assert!(c1.abs() < 1e-12 && t.eval(0.0, false).2.abs() < 1e-12);
    let (p, d, c) = t.eval(15.0, false);
    assert!((p - (p1 + 3.0 * d1)).abs() < 1e-12 && d == d1 && c == 0.0);
    let (p0, d0, _) = t.eval(0.0, false);
    let (q, e, _) = t.eval(-2.0, false);
    assert!((q - (p0 - 2.0 * d0)).abs() < 1e-12 && e == d0);
}

#[test]
fn the_bounds_cover_the_law_and_are_tight() {
    let t = CamTable::new(&POINTS).unwrap();
    for periodic in [false, true] {
        let b = t.bounds(periodic);
        let (mut m1, mut m2, mut m3) = (0.0f64, 0.0f64, 0.0f64);
        let n = 120_000;
        let h = 12.0 / n as f64;
        let mut last = t.eval(0.0, periodic).2;
        for i in 1..=n {
            let (_, d1, d2) = t.eval(i as f64 * h, periodic);
            m1 = m1.max(d1.abs());
            m2 = m2.max(d2.abs());
            m3 = m3.max(((d2 - last) / h).abs());
            last = d2;
        }
        for (k, (s, bound)) in [m1, m2, m3].iter().zip(b).enumerate() {
            assert!(*s <= bound * (1.0 + 1e-6), "f{} {s} > bound {bound}", k + 1);
            assert!(
                *s >= bound * 0.999,
                "f{} bound {bound} not tight ({s})",
                k + 1
            );
        }
    }
}

/// A master of at most 2 mm/s, 5 mm/s^2, 50 mm/s^3 and a slave of SLAVE: the law fits.
fn coupled(periodic: bool) -> (Engine, usize, usize, McCamIn, CamTable) {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let slave = axis(&mut e, SLAVE);
    let master = axis(
        &mut e,
        Limits {
            vmax: 2.0,
            amax: 5.0,
            dmax: 5.0,
            jmax: 50.0,
        },
    );
    let table = CamTable::new(&POINTS).unwrap();
    let id = e.add_cam_table(table.clone());
    let mut cam = McCamIn {
        execute: true,
        cam_table_id: id,
        periodic,
        master_absolute: true,
        slave_absolute: true,
        master_scaling: 1.0,
        slave_scaling: 2.0,
        ..Default::default()
    };
    cam.call(&mut e, master, slave);
    assert!(cam.busy && !cam.error, "{:?}", cam.error_id);
    (e, master, slave, cam, table)
}

#[test]
fn the_slave_moves_by_the_chain_rule_within_its_limits() {
    for periodic in [true, false] {
        let (mut e, master, slave, mut cam, table) = coupled(periodic);
        // The master accelerates to 2 mm/s and back and forth: its acceleration is not 0
        // for long stretches, so the law's f' a_m term shows.
        let mut mv = McMoveVelocity {
            execute: true,
            velocity: 2.0,
            acceleration: 1.0,
            deceleration: 1.0,
            jerk: 2.0,
            direction: Direction::Positive,
            ..Default::default()
        };
        mv.call(&mut e, master);
        let dt = 0.001;
        let mut prev: Option<(f64, f64)> = None;
        let mut synced = 0;
        let mut with_acc = 0;
        for k in 0..12_000 {
            if k == 6000 {
                mv.execute = false;
                mv.call(&mut e, master);
                mv.velocity = 0.5;
                mv.execute = true;
            }
            mv.call(&mut e, master);
            e.step();
            cam.call(&mut e, master, slave);
            let (v, a) = (
                e.set_velocity_of(slave).unwrap(),
                e.set_acceleration_of(slave).unwrap(),
            );
            assert!(
                v.abs() <= SLAVE.vmax && a.abs() <= SLAVE.amax,
                "{k}: {v} {a}"
            );
            if let Some((pv, pa)) = prev {
                assert!((v - pv).abs() <= SLAVE.amax * dt * (1.0 + 1e-9), "{k}: dv");
                assert!((a - pa).abs() <= SLAVE.jmax * dt * (1.0 + 1e-9), "{k}: da");
            }
            prev = Some((v, a));
            if cam.in_sync {
                synced += 1;
                let (mp, mvel, macc) = (
                    e.set_position_of(master).unwrap(),
                    e.set_velocity_of(master).unwrap(),
                    e.set_acceleration_of(master).unwrap(),
                );
                let x = if periodic { mp.rem_euclid(12.0) } else { mp };
                let (_, d1, d2) = table.eval(x, periodic);
                let ev = 2.0 * d1 * mvel;
                let ea = 2.0 * (d2 * mvel * mvel + d1 * macc);
                assert!((v - ev).abs() < 1e-9, "{k}: v {v} law {ev}");
                assert!((a - ea).abs() < 1e-9, "{k}: a {a} law {ea}");
                if (d1 * macc).abs() > 0.1 {
                    with_acc += 1;
                }
            }
        }
        assert!(synced > 5000, "InSync only {synced} cycles");
        assert!(
            with_acc > 500,
            "the f' a_m term mattered in {with_acc} cycles"
        );
        assert_eq!(e.axis_state(slave).unwrap(), AxisState::SynchronizedMotion);
    }
}

#[test]
fn a_law_too_fast_for_the_slave_is_refused_and_nothing_is_aborted() {
    let mut e = Engine::new(EngineConfig::default()).unwrap();
    let slave = axis(&mut e, SLAVE);
    // 60 mm/s of master: the law's slope (about 3) asks for 180 mm/s of the slave.
    let master = axis(
        &mut e,
        Limits {
            vmax: 60.0,
            amax: 5.0,
            dmax: 5.0,
            jmax: 50.0,
        },
    );
    let id = e.add_cam_table(CamTable::new(&POINTS).unwrap());
    let mut mv = McMoveVelocity {
        execute: true,
        velocity: 10.0,
        acceleration: 100.0,
        deceleration: 100.0,
        jerk: 1000.0,
        ..Default::default()
    };
    mv.call(&mut e, slave);
    for _ in 0..10 {
        e.step();
        mv.call(&mut e, slave);
    }
    let mut cam = McCamIn {
        execute: true,
        cam_table_id: id,
        periodic: true,
        ..Default::default()
    };
    cam.call(&mut e, master, slave);
    assert!(cam.error, "refused");
    assert_eq!(cam.error_id, ErrorId::CamBeyondSlaveLimits);
    assert_eq!(cam.error_id.code(), 33);
    e.step();
    mv.call(&mut e, slave);
    assert!(mv.busy && !mv.command_aborted, "the running move goes on");
    // A master without a jerk limit: the law's jerk is unbounded, refused as well.
    let free = axis(
        &mut e,
        Limits {
            vmax: 1.0,
            amax: 1.0,
            dmax: 1.0,
            jmax: 0.0,
        },
    );
    let mut cam2 = McCamIn {
        execute: true,
        cam_table_id: id,
        periodic: true,
        ..Default::default()
    };
    cam2.call(&mut e, free, slave);
    assert_eq!(cam2.error_id, ErrorId::CamBeyondSlaveLimits);
}

#[test]
fn a_coupling_that_does_not_fit_is_refused_before_and_at_activation() {
    for buffered in [false, true] {
        let mut e = Engine::new(EngineConfig::default()).unwrap();
        let slave = axis(&mut e, SLAVE);
        // The law (slave scaling 2) takes 30 mm/s of the slave's 100: 70 are left to the
        // catch-up, and the slave runs at 90 mm/s relative to a master at rest.
        let table = CamTable::new(&POINTS).unwrap();
        let vm = 30.0 / (2.0 * table.bounds(true)[0]);
        let master = axis(
            &mut e,
            Limits {
                vmax: vm,
                amax: 1.0,
                dmax: 1.0,
                jmax: 1.0,
            },
        );
        let id = e.add_cam_table(table);
        // The same law from standstill is accepted (the refusals below are the coupling's).
        let idle = axis(&mut e, SLAVE);
        let mut ok = McCamIn {
            execute: true,
            cam_table_id: id,
            periodic: true,
            slave_scaling: 2.0,
            ..Default::default()
        };
        ok.call(&mut e, master, idle);
        assert!(ok.busy && !ok.error, "{:?}", ok.error_id);
        let mut mv = McMoveVelocity {
            execute: true,
            velocity: 90.0,
            acceleration: 1000.0,
            deceleration: 1000.0,
            jerk: 10000.0,
            ..Default::default()
        };
        mv.call(&mut e, slave);
        for _ in 0..300 {
            e.step();
            mv.call(&mut e, slave);
        }
        assert!(mv.in_velocity);
        let mut cam = McCamIn {
            execute: true,
            cam_table_id: id,
            periodic: true,
            slave_scaling: 2.0,
            buffer_mode: if buffered {
                BufferMode::Buffered
            } else {
                BufferMode::Aborting
            },
            ..Default::default()
        };
        cam.call(&mut e, master, slave);
        if !buffered {
            assert_eq!(cam.error_id, ErrorId::CamBeyondSlaveLimits);
            e.step();
            mv.call(&mut e, slave);
            assert!(mv.busy && !mv.command_aborted, "nothing aborted");
            continue;
        }
        // Buffered: accepted, refused when it would start (the velocity move reached its
        // velocity); the velocity move goes on, within the limits.
        assert!(cam.busy, "{:?}", cam.error_id);
        let mut prev = e.set_velocity_of(slave).unwrap();
        for _ in 0..2000 {
            e.step();
            mv.call(&mut e, slave);
            cam.call(&mut e, master, slave);
            let v = e.set_velocity_of(slave).unwrap();
            assert!((v - prev).abs() <= SLAVE.dmax * 0.001 * (1.0 + 1e-9));
            assert!(e.set_acceleration_of(slave).unwrap().abs() <= SLAVE.dmax);
            prev = v;
        }
        assert!(cam.error && cam.error_id == ErrorId::CamBeyondSlaveLimits);
        assert_eq!(e.axis_state(slave).unwrap(), AxisState::ContinuousMotion);
        assert!((e.set_velocity_of(slave).unwrap() - 90.0).abs() < 1e-9);
    }
}
