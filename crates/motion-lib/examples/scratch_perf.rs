use motion_lib::profile::{Limits, Profile, State};
use rsruckig::prelude::*;
use std::hint::black_box;
use std::time::Instant;
fn rk(
    otg: &mut Ruckig<1, IgnoreErrorHandler>,
    traj: &mut Trajectory<1>,
    s: State,
    pf: f64,
    vf: f64,
    lim: &Limits,
) -> f64 {
    let mut input = InputParameter::new(None);
    input.current_position[0] = s.p;
    input.current_velocity[0] = s.v;
    input.current_acceleration[0] = s.a;
    input.target_position[0] = pf;
    input.target_velocity[0] = vf;
    input.max_velocity[0] = lim.vmax;
    input.max_acceleration[0] = lim.amax;
    input.max_jerk[0] = lim.jmax;
    otg.calculate(black_box(&input), traj).unwrap();
    traj.get_duration()
}
fn best(mut f: impl FnMut() -> f64) -> f64 {
    let mut b = f64::INFINITY;
    for _ in 0..30 {
        let t = Instant::now();
        let mut acc = 0.0;
        for _ in 0..20_000 {
            acc += f();
        }
        black_box(acc);
        b = b.min(t.elapsed().as_nanos() as f64 / 20_000.0);
    }
    b
}
fn main() {
    let lim = Limits {
        vmax: 71.19648842444575,
        amax: 9.488249292368122,
        dmax: 9.488249292368122,
        jmax: 3.750756973755056,
    };
    let start = State {
        p: -2862.4958482247066,
        v: 0.0,
        a: 0.0,
    };
    println!(
        "fast path: {:.1} ns",
        best(|| Profile::position(
            black_box(start),
            black_box(-344.71613673501633),
            black_box(0.0),
            black_box(&lim)
        )
        .unwrap()
        .duration())
    );
    println!(
        "velocity: {:.1} ns",
        best(
            || Profile::velocity(black_box(start), black_box(20.0), black_box(&lim))
                .unwrap()
                .duration()
        )
    );
    println!(
        "100 dependent mul+add: {:.1} ns",
        best(|| {
            let mut x = black_box(1.0f64);
            for _ in 0..100 {
                x = x * 0.999 + 0.001;
            }
            x
        })
    );
    let prof = Profile::position(start, -344.71613673501633, 0.0, &lim).unwrap();
    let d = prof.duration();
    let mut k = 0u32;
    println!(
        "at: {:.1} ns",
        best(|| {
            k = k.wrapping_add(7919);
            prof.at(black_box((k % 1000) as f64 * d / 900.0)).p
        })
    );
    let n = 1_000_000u32;
    let dt = d * 1.2 / n as f64;
    let t0 = Instant::now();
    let mut acc = 0.0;
    for i in 0..n {
        acc += prof.at(black_box(i as f64 * dt)).p;
    }
    println!(
        "at sequential: {:.1} ns {acc}",
        t0.elapsed().as_nanos() as f64 / n as f64
    );
    let s0 = State::default();
    println!(
        "kernel rest: {:.1} ns",
        best(|| Profile::position(
            black_box(s0),
            black_box(10.0),
            black_box(0.0),
            black_box(&lim)
        )
        .unwrap()
        .duration())
    );
    let mut otg = Ruckig::<1, IgnoreErrorHandler>::new(None, 0.001);
    let mut traj = Trajectory::new(None);
    println!(
        "ruckig fast: {:.1} ns",
        best(|| rk(&mut otg, &mut traj, start, -344.71613673501633, 0.0, &lim))
    );
    println!(
        "ruckig kernel rest: {:.1} ns",
        best(|| rk(&mut otg, &mut traj, s0, 10.0, 0.0, &lim))
    );
    let s1 = State {
        p: 0.0,
        v: 20.0,
        a: 3.0,
    };
    println!(
        "ruckig blend: {:.1} ns",
        best(|| rk(&mut otg, &mut traj, s1, 100.0, 10.0, &lim))
    );
    println!(
        "kernel blend: {:.1} ns",
        best(|| Profile::position(
            black_box(s1),
            black_box(100.0),
            black_box(10.0),
            black_box(&lim)
        )
        .unwrap()
        .duration())
    );
}
