//! Property test: random command sequences keep every axis within its limits, cycle to cycle.
//!
//! Input: a seeded generator (xorshift) of sequences: random axis limits and cycle times, single-axis
//! sequences (MC_MoveAbsolute, MC_MoveRelative, MC_MoveAdditive, MC_MoveVelocity, MC_Halt) and 2- or
//! 3-axis group sequences (MC_MoveLinearAbsolute, MC_MoveLinearRelative, MC_GroupHalt), every
//! BufferMode, TransitionModes TMNone / TMCornerDistance / TMMaxCornerDeviation, random Execute
//! patterns (rising edges at random cycles, Execute held or dropped early, re-triggered).
//! Output: assertions on the set-point stream of every cycle: |v| <= vmax, |a| <= max(amax, dmax),
//! |dp| <= vmax dt, |dv| <= max(amax, dmax) dt, |da| <= jmax dt and |d2v| <= jmax dt^2 (all with 1e-9
//! relative slack); PLCopen outputs (Busy, Done, Error, CommandAborted exclusive, Active only while
//! Busy, one Active block per axis or group); every accepted command ends Done, CommandAborted or
//! Error (each sequence ends with an aborting halt that must end Done), none is lost.
//! Invariant: deterministic (fixed seed); `LIMITS_PROPERTY_SEQUENCES` overrides the count.

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::{
    McHalt, McMoveAbsolute, McMoveAdditive, McMoveRelative, McMoveVelocity, McPower,
};
use motion_lib::buffer::{BufferMode, Direction, TransitionMode};
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::group_blocks::{
    McAddAxisToGroup, McGroupEnable, McGroupHalt, McMoveLinearAbsolute, McMoveLinearRelative,
};
use motion_lib::profile::Limits;

fn trace_seq() -> Option<u64> {
    static TRACE: std::sync::OnceLock<Option<u64>> = std::sync::OnceLock::new();
    *TRACE.get_or_init(|| {
        std::env::var("LIMITS_PROPERTY_TRACE")
            .ok()
            .and_then(|s| s.parse().ok())
    })
}

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }
    fn f(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.f()
    }
    fn log(&mut self, a: f64, b: f64) -> f64 {
        (a.ln() + (b.ln() - a.ln()) * self.f()).exp()
    }
    fn n(&mut self, k: u64) -> u64 {
        self.next() % k
    }
    fn chance(&mut self, p: f64) -> bool {
        self.f() < p
    }
}

/// Limits and time scale of one sequence.
struct Scale {
    lim: Limits,
    dt: f64,
    /// Typical move length.
    dist: f64,
}

fn scale(r: &mut Rng) -> Scale {
    let v = r.log(0.01, 1000.0);
    let t = r.log(0.05, 0.5);
    let a = v / t * r.range(0.5, 2.0);
    let jmax = if r.chance(0.2) {
        0.0
    } else {
        a / t * r.range(0.5, 2.0)
    };
    let lim = Limits {
        vmax: v,
        amax: a,
        dmax: a * r.range(0.5, 2.0),
        jmax,
    };
    let dt = t / r.range(4.0, 60.0);
    Scale {
        lim,
        dt,
        dist: v * t * r.range(0.2, 3.0),
    }
}

fn buffer_mode(r: &mut Rng) -> BufferMode {
    BufferMode::from_u8(r.n(6) as u8).unwrap_or_default()
}

/// Block dynamics: around the axis limits (sometimes above: the library caps them).
fn dyn4(r: &mut Rng, l: &Limits) -> (f64, f64, f64, f64) {
    (
        l.vmax * r.range(0.1, 1.5),
        l.amax * r.range(0.2, 1.5),
        l.dmax * r.range(0.2, 1.5),
        if r.chance(0.3) {
            0.0
        } else {
            l.jmax.max(l.amax) * r.range(0.2, 1.5)
        },
    )
}

/// One cycle's set point of one axis.
#[derive(Clone, Copy, Default)]
struct Sp {
    p: f64,
    v: f64,
    a: f64,
}

#[derive(Default)]
struct Stats {
    sequences: u64,
    cycles: u64,
    commands: u64,
    violations: Vec<String>,
}

/// Checks the set-point stream of one axis (history: the last two cycles).
struct AxisCheck {
    lim: Limits,
    dt: f64,
    hist: Vec<Sp>,
}

impl AxisCheck {
    fn push(&mut self, s: Sp, what: &dyn Fn() -> String, out: &mut Vec<String>) {
        let l = self.lim;
        let dt = self.dt;
        let rel = 1e-9;
        let amax = l.amax.max(l.dmax);
        let mut bad = |cond: bool, msg: &dyn Fn() -> String| {
            if cond && out.len() < 20 {
                out.push(format!("{}: {}", what(), msg()));
            }
        };
        bad(s.v.abs() > l.vmax * (1.0 + rel), &|| {
            format!("|v| {} > vmax {}", s.v, l.vmax)
        });
        bad(s.a.abs() > amax * (1.0 + rel), &|| {
            format!("|a| {} > amax {}", s.a, amax)
        });
        if let Some(p) = self.hist.last().copied() {
            let eps = 1e-12 * (s.p.abs().max(p.p.abs()) + l.vmax * dt);
            bad((s.p - p.p).abs() > l.vmax * dt * (1.0 + rel) + eps, &|| {
                format!("|dp| {} > vmax dt {}", (s.p - p.p).abs(), l.vmax * dt)
            });
            let eps = 1e-12 * l.vmax;
            bad((s.v - p.v).abs() > amax * dt * (1.0 + rel) + eps, &|| {
                format!("|dv| {} > amax dt {}", (s.v - p.v).abs(), amax * dt)
            });
            if l.jmax > 0.0 {
                let eps = 1e-12 * amax;
                bad((s.a - p.a).abs() > l.jmax * dt * (1.0 + rel) + eps, &|| {
                    format!("|da| {} > jmax dt {}", (s.a - p.a).abs(), l.jmax * dt)
                });
                if self.hist.len() >= 2 {
                    let q = self.hist[self.hist.len() - 2];
                    let d2 = s.v - 2.0 * p.v + q.v;
                    bad(
                        d2.abs() > l.jmax * dt * dt * (1.0 + rel) + 1e-12 * l.vmax,
                        &|| format!("|d2v| {} > jmax dt^2 {}", d2.abs(), l.jmax * dt * dt),
                    );
                }
            }
        }
        if self.hist.len() >= 2 {
            self.hist.remove(0);
        }
        self.hist.push(s);
    }
}

/// PLCopen output tracking of one block.
#[derive(Default, Clone, Copy)]
struct OutCheck {
    accepted: u32,
    finished: u32,
    in_cmd: bool,
}

impl OutCheck {
    #[allow(clippy::too_many_arguments)]
    fn see(
        &mut self,
        busy: bool,
        done: bool,
        err: bool,
        aborted: bool,
        active: bool,
        what: &dyn Fn() -> String,
        out: &mut Vec<String>,
    ) {
        let n = [busy, done, err, aborted].iter().filter(|x| **x).count();
        if n > 1 && out.len() < 20 {
            out.push(format!(
                "{}: Busy {busy} Done {done} Error {err} Aborted {aborted}",
                what()
            ));
        }
        if active && !busy && out.len() < 20 {
            out.push(format!("{}: Active without Busy", what()));
        }
        if busy && !self.in_cmd {
            self.in_cmd = true;
            self.accepted += 1;
        }
        if self.in_cmd && (done || err || aborted) {
            self.in_cmd = false;
            self.finished += 1;
        }
    }
}

/// Execute pattern of one block: rising at `start`, held for `hold` cycles, again at `again`.
#[derive(Clone, Copy)]
struct Pattern {
    start: u64,
    hold: u64,
    again: Option<u64>,
}

impl Pattern {
    fn random(r: &mut Rng, span: u64) -> Pattern {
        Pattern {
            start: r.n(span),
            hold: if r.chance(0.5) {
                1 + r.n(3)
            } else {
                1 + r.n(400)
            },
            again: if r.chance(0.2) {
                Some(r.n(span * 2))
            } else {
                None
            },
        }
    }
    fn execute(&self, k: u64) -> bool {
        let on = |s: u64| k >= s && k < s + self.hold;
        on(self.start) || self.again.is_some_and(on)
    }
}

fn axis_cfg(l: Limits) -> AxisConfig {
    AxisConfig {
        limits: l,
        ..AxisConfig::default()
    }
}

enum Axb {
    Abs(McMoveAbsolute),
    Rel(McMoveRelative),
    Add(McMoveAdditive),
    Vel(McMoveVelocity),
    Halt(McHalt),
}

impl Axb {
    fn call(&mut self, eng: &mut Engine, ax: usize, x: bool) -> (bool, bool, bool, bool, bool) {
        match self {
            Axb::Abs(b) => {
                b.execute = x;
                b.call(eng, ax);
                (b.busy, b.done, b.error, b.command_aborted, b.active)
            }
            Axb::Rel(b) => {
                b.execute = x;
                b.call(eng, ax);
                (b.busy, b.done, b.error, b.command_aborted, b.active)
            }
            Axb::Add(b) => {
                b.execute = x;
                b.call(eng, ax);
                (b.busy, b.done, b.error, b.command_aborted, b.active)
            }
            Axb::Vel(b) => {
                b.execute = x;
                b.call(eng, ax);
                (b.busy, false, b.error, b.command_aborted, b.active)
            }
            Axb::Halt(b) => {
                b.execute = x;
                b.call(eng, ax);
                (b.busy, b.done, b.error, b.command_aborted, b.active)
            }
        }
    }
}

fn single_axis(r: &mut Rng, st: &mut Stats, seq: u64) {
    let sc = scale(r);
    let mut eng = Engine::new(EngineConfig {
        cycle: sc.dt,
        queue_depth: 1 + r.n(4) as usize,
    })
    .unwrap();
    let ax = eng.add_axis(axis_cfg(sc.lim)).unwrap();
    let mut pw = McPower {
        enable: true,
        ..Default::default()
    };
    pw.call(&mut eng, ax);
    let nb = 2 + r.n(5) as usize;
    let mut blocks = Vec::new();
    let span = 20 + r.n(150);
    for _ in 0..nb {
        let (v, a, d, j) = dyn4(r, &sc.lim);
        let bm = buffer_mode(r);
        let dist = sc.dist * r.range(-1.5, 1.5);
        let b = match r.n(6) {
            0 | 1 => Axb::Abs(McMoveAbsolute {
                position: dist,
                velocity: v,
                acceleration: a,
                deceleration: d,
                jerk: j,
                buffer_mode: bm,
                ..Default::default()
            }),
            2 => Axb::Rel(McMoveRelative {
                distance: dist,
                velocity: v,
                acceleration: a,
                deceleration: d,
                jerk: j,
                buffer_mode: bm,
                ..Default::default()
            }),
            3 => Axb::Add(McMoveAdditive {
                distance: dist,
                velocity: v,
                acceleration: a,
                deceleration: d,
                jerk: j,
                buffer_mode: bm,
                ..Default::default()
            }),
            4 => Axb::Vel(McMoveVelocity {
                velocity: v * if r.chance(0.5) { -1.0 } else { 1.0 },
                acceleration: a,
                deceleration: d,
                jerk: j,
                direction: Direction::Positive,
                buffer_mode: bm,
                ..Default::default()
            }),
            _ => Axb::Halt(McHalt {
                deceleration: d,
                jerk: j,
                buffer_mode: bm,
                ..Default::default()
            }),
        };
        blocks.push((b, Pattern::random(r, span), OutCheck::default()));
    }
    if trace_seq() == Some(seq) {
        for (b, pat, _) in &blocks {
            let d = match b {
                Axb::Abs(b) => format!("abs {} v {} {:?}", b.position, b.velocity, b.buffer_mode),
                Axb::Rel(b) => format!("rel {} v {} {:?}", b.distance, b.velocity, b.buffer_mode),
                Axb::Add(b) => format!("add {} v {} {:?}", b.distance, b.velocity, b.buffer_mode),
                Axb::Vel(b) => format!("vel v {} {:?}", b.velocity, b.buffer_mode),
                Axb::Halt(b) => format!("halt {:?}", b.buffer_mode),
            };
            eprintln!(
                "{d} start {} hold {} again {:?}",
                pat.start, pat.hold, pat.again
            );
        }
        eprintln!("limits {:?} dt {}", sc.lim, sc.dt);
    }
    // The closing halt: aborting, Execute held until Done.
    let mut stop = McHalt {
        deceleration: sc.lim.dmax,
        jerk: 0.0,
        buffer_mode: BufferMode::Aborting,
        ..Default::default()
    };
    let stop_at = span * 2 + 200 + r.n(200);
    let mut stop_out = OutCheck::default();
    let mut chk = AxisCheck {
        lim: sc.lim,
        dt: sc.dt,
        hist: Vec::new(),
    };
    let limit = stop_at + 20_000;
    let mut k = 0;
    let what = |k: u64| format!("seq {seq} single axis cycle {k}");
    loop {
        // Blocks called before a rising Execute in the same scan show its effect next scan:
        // count the Active outputs from the last rising edge on.
        let mut actives = 0;
        for (b, pat, oc) in blocks.iter_mut() {
            let x = pat.execute(k);
            let o = b.call(&mut eng, ax, x);
            oc.see(o.0, o.1, o.2, o.3, o.4, &|| what(k), &mut st.violations);
            if x && (k == 0 || !pat.execute(k - 1)) {
                actives = 0;
            }
            actives += o.4 as u32;
        }
        if k == stop_at {
            actives = 0;
        }
        if k >= stop_at {
            stop.execute = true;
            stop.call(&mut eng, ax);
            stop_out.see(
                stop.busy,
                stop.done,
                stop.error,
                stop.command_aborted,
                stop.active,
                &|| what(k),
                &mut st.violations,
            );
            actives += stop.active as u32;
        }
        if actives > 1 && st.violations.len() < 20 {
            st.violations
                .push(format!("{}: {actives} blocks Active", what(k)));
        }
        if (stop.done || stop.error || stop.command_aborted) && blocks.iter().all(|b| !b.2.in_cmd) {
            break;
        }
        if k > limit {
            st.violations
                .push(format!("{}: the closing halt did not end", what(k)));
            break;
        }
        eng.step();
        st.cycles += 1;
        k += 1;
        let s = Sp {
            p: eng.set_position_of(ax).unwrap(),
            v: eng.set_velocity_of(ax).unwrap(),
            a: eng.set_acceleration_of(ax).unwrap(),
        };
        if trace_seq() == Some(seq) {
            eprintln!(
                "{k} {:?} p {} v {} a {}",
                eng.axis_state(ax).unwrap(),
                s.p,
                s.v,
                s.a
            );
        }
        chk.push(s, &|| what(k), &mut st.violations);
    }
    if !stop.done && st.violations.len() < 20 {
        st.violations.push(format!(
            "seq {seq}: the closing halt ended {:?}",
            stop.error_id
        ));
    }
    for (_, _, oc) in &blocks {
        st.commands += oc.accepted as u64;
        if oc.accepted != oc.finished && st.violations.len() < 20 {
            st.violations.push(format!(
                "seq {seq}: {} accepted, {} ended",
                oc.accepted, oc.finished
            ));
        }
    }
    st.commands += 1;
}

enum Grb {
    Abs(McMoveLinearAbsolute),
    Rel(McMoveLinearRelative),
    Halt(McGroupHalt),
}

impl Grb {
    fn call(&mut self, eng: &mut Engine, g: usize, x: bool) -> (bool, bool, bool, bool, bool) {
        match self {
            Grb::Abs(b) => {
                b.execute = x;
                b.call(eng, g);
                (b.busy, b.done, b.error, b.command_aborted, b.active)
            }
            Grb::Rel(b) => {
                b.execute = x;
                b.call(eng, g);
                (b.busy, b.done, b.error, b.command_aborted, b.active)
            }
            Grb::Halt(b) => {
                b.execute = x;
                b.call(eng, g);
                (b.busy, b.done, b.error, b.command_aborted, b.active)
            }
        }
    }
}

fn group(r: &mut Rng, st: &mut Stats, seq: u64) {
    let sc = scale(r);
    let mut eng = Engine::new(EngineConfig {
        cycle: sc.dt,
        queue_depth: 1 + r.n(4) as usize,
    })
    .unwrap();
    let na = 2 + r.n(2) as usize;
    let g = eng.add_group();
    let mut lims = Vec::new();
    let mut axes = Vec::new();
    for i in 0..na {
        // Unequal axis limits.
        let f = r.range(0.3, 1.0);
        let l = Limits {
            vmax: sc.lim.vmax * f,
            amax: sc.lim.amax * r.range(0.3, 1.0),
            dmax: sc.lim.dmax * r.range(0.3, 1.0),
            jmax: sc.lim.jmax * r.range(0.3, 1.0),
        };
        let a = eng.add_axis(axis_cfg(l)).unwrap();
        let mut pw = McPower {
            enable: true,
            ..Default::default()
        };
        pw.call(&mut eng, a);
        let mut add = McAddAxisToGroup {
            execute: true,
            axis: a,
            ident_in_group: i,
            ..Default::default()
        };
        add.call(&mut eng, g);
        assert!(add.done);
        lims.push(l);
        axes.push(a);
    }
    let mut en = McGroupEnable {
        execute: true,
        ..Default::default()
    };
    en.call(&mut eng, g);
    assert!(en.done);
    let nb = 2 + r.n(5) as usize;
    let span = 20 + r.n(150);
    let mut blocks = Vec::new();
    for _ in 0..nb {
        let (v, a, d, j) = dyn4(r, &sc.lim);
        let bm = buffer_mode(r);
        let tm = match r.n(3) {
            0 => TransitionMode::None,
            1 => TransitionMode::CornerDistance,
            _ => TransitionMode::MaxCornerDeviation,
        };
        let tp = sc.dist * r.range(0.0, 0.6);
        let mut pos = [0.0; 16];
        for x in pos.iter_mut().take(na) {
            *x = sc.dist * r.range(-1.5, 1.5);
        }
        if r.chance(0.2) {
            // Collinear with the origin: tangent junctions.
            let s = r.range(0.5, 2.0);
            for (i, x) in pos.iter_mut().take(na).enumerate() {
                *x = sc.dist * s * (i as f64 + 1.0) / na as f64;
            }
        }
        let b = match r.n(5) {
            0..=2 => Grb::Abs(McMoveLinearAbsolute {
                position: pos,
                velocity: v,
                acceleration: a,
                deceleration: d,
                jerk: j,
                buffer_mode: bm,
                transition_mode: tm,
                transition_parameter: tp,
                ..Default::default()
            }),
            3 => Grb::Rel(McMoveLinearRelative {
                distance: pos,
                velocity: v,
                acceleration: a,
                deceleration: d,
                jerk: j,
                buffer_mode: bm,
                transition_mode: tm,
                transition_parameter: tp,
                ..Default::default()
            }),
            _ => Grb::Halt(McGroupHalt {
                deceleration: d,
                jerk: j,
                buffer_mode: bm,
                ..Default::default()
            }),
        };
        blocks.push((b, Pattern::random(r, span), OutCheck::default()));
    }
    if trace_seq() == Some(seq) {
        for (b, pat, _) in &blocks {
            match b {
                Grb::Abs(b) => eprintln!(
                    "abs {:?} v {} {:?} {:?} {} start {} hold {} again {:?}",
                    &b.position[..na],
                    b.velocity,
                    b.buffer_mode,
                    b.transition_mode,
                    b.transition_parameter,
                    pat.start,
                    pat.hold,
                    pat.again
                ),
                Grb::Rel(b) => eprintln!(
                    "rel {:?} v {} {:?} {:?} {} start {} hold {} again {:?}",
                    &b.distance[..na],
                    b.velocity,
                    b.buffer_mode,
                    b.transition_mode,
                    b.transition_parameter,
                    pat.start,
                    pat.hold,
                    pat.again
                ),
                Grb::Halt(b) => eprintln!(
                    "halt {:?} start {} hold {} again {:?}",
                    b.buffer_mode, pat.start, pat.hold, pat.again
                ),
            }
        }
        eprintln!("limits {lims:?} dt {}", sc.dt);
    }
    let mut stop = McGroupHalt {
        deceleration: sc.lim.dmax,
        jerk: 0.0,
        buffer_mode: BufferMode::Aborting,
        ..Default::default()
    };
    let stop_at = span * 2 + 300 + r.n(300);
    let mut stop_out = OutCheck::default();
    let mut chk: Vec<AxisCheck> = lims
        .iter()
        .map(|l| AxisCheck {
            lim: *l,
            dt: sc.dt,
            hist: Vec::new(),
        })
        .collect();
    let limit = stop_at + 40_000;
    let mut k = 0;
    let what = |k: u64| format!("seq {seq} group of {na} cycle {k}");
    loop {
        // Blocks called before a rising Execute in the same scan show its effect next scan:
        // count the Active outputs from the last rising edge on.
        let mut actives = 0;
        for (b, pat, oc) in blocks.iter_mut() {
            let x = pat.execute(k);
            let o = b.call(&mut eng, g, x);
            oc.see(o.0, o.1, o.2, o.3, o.4, &|| what(k), &mut st.violations);
            if x && (k == 0 || !pat.execute(k - 1)) {
                actives = 0;
            }
            actives += o.4 as u32;
        }
        if k == stop_at {
            actives = 0;
        }
        if k >= stop_at {
            stop.execute = true;
            stop.call(&mut eng, g);
            stop_out.see(
                stop.busy,
                stop.done,
                stop.error,
                stop.command_aborted,
                stop.active,
                &|| what(k),
                &mut st.violations,
            );
            actives += stop.active as u32;
        }
        if actives > 1 && st.violations.len() < 20 {
            st.violations
                .push(format!("{}: {actives} blocks Active", what(k)));
        }
        if (stop.done || stop.error || stop.command_aborted) && blocks.iter().all(|b| !b.2.in_cmd) {
            break;
        }
        if k > limit {
            st.violations
                .push(format!("{}: the closing halt did not end", what(k)));
            break;
        }
        eng.step();
        st.cycles += 1;
        k += 1;
        if trace_seq() == Some(seq) {
            let (v, sp) = eng.group_velocity(g).unwrap();
            let o: Vec<String> = blocks
                .iter()
                .map(|b| format!("{}{}", b.2.accepted, if b.2.in_cmd { "*" } else { "" }))
                .collect();
            eprintln!(
                "{k} {:?} p {:?} v {:?} |v| {sp} {o:?}",
                eng.group_state(g).unwrap(),
                &eng.group_position(g).unwrap()[..na],
                &v[..na]
            );
        }
        for (i, a) in axes.iter().enumerate() {
            let s = Sp {
                p: eng.set_position_of(*a).unwrap(),
                v: eng.set_velocity_of(*a).unwrap(),
                a: eng.set_acceleration_of(*a).unwrap(),
            };
            chk[i].push(s, &|| format!("{} axis {i}", what(k)), &mut st.violations);
        }
    }
    if !stop.done && st.violations.len() < 20 {
        st.violations.push(format!(
            "seq {seq}: the closing group halt ended {:?}",
            stop.error_id
        ));
    }
    for (_, _, oc) in &blocks {
        st.commands += oc.accepted as u64;
        if oc.accepted != oc.finished && st.violations.len() < 20 {
            st.violations.push(format!(
                "seq {seq}: {} accepted, {} ended",
                oc.accepted, oc.finished
            ));
        }
    }
    st.commands += 1;
}

#[test]
fn random_sequences_keep_the_limits_and_the_output_rules() {
    let n: u64 = std::env::var("LIMITS_PROPERTY_SEQUENCES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(100_000);
    let mut r = Rng(0x9e37_79b9_7f4a_7c15);
    let mut st = Stats::default();
    let t0 = std::time::Instant::now();
    for seq in 0..n {
        if seq % 2 == 0 {
            single_axis(&mut r, &mut st, seq);
        } else {
            group(&mut r, &mut st, seq);
        }
        st.sequences += 1;
        if st.violations.len() >= 20 {
            break;
        }
    }
    println!(
        "limits property: {} sequences, {} cycles, {} commands, {} violations, {:.1} s",
        st.sequences,
        st.cycles,
        st.commands,
        st.violations.len(),
        t0.elapsed().as_secs_f64()
    );
    assert!(st.violations.is_empty(), "{:#?}", st.violations);
    assert!(st.sequences >= n);
}
