//! PMAC motion programs (LINEAR moves with TA/TS/F) from a list of straight jerk-limited moves.
//!
//! Input: a [`CoordSystem`], a list of [`LinearMove`]s, a [`Dialect`] (and optionally a start position and a
//! program number, [`ProgramOptions`]).
//! Output: the program text: `CLOSE` (no buffer left open), on Turbo `DELETE GATHER` (the manual's advice
//! for downloaded program files), the feedrate time unit (`I5190=1000` / `Coord[1].FeedTime=1000`: `F` is
//! in user units per second), axis definitions (`&1 #1->1000X ...`), `OPEN PROG n CLEAR`,
//! `LINEAR ABS FRAX(..)`, one line per move with the `TS`/`TA` (Power: `ts`/`ta`/`td`) and `F` that make the
//! PMAC's own S-curve equal the jerk-limited profile, `DWELL0` after every exact stop, `CLOSE`, and the run
//! command `&1 B1 R`.
//! Invariants: `TS`, `TA`, `TD` are written only when they change (they are modal); on Turbo they are whole
//! milliseconds, rounded up so that no acceleration or jerk grows (Turbo PMAC rounds them to whole ms when
//! it executes them: Software Reference, `TA{data}` and `TS{data}`); on Power they have at most 3 decimals;
//! `F` is the path speed (user units per Isx90 ms, Isx90 = 1000 gives units/s) with at least
//! 3 decimals and as many more (up to 6) as keep the rounding's effect on the move time under 0.5 ms (half the 1 ms move-time tolerance);
//! positions have at most 6 decimals. Zero-length moves are skipped. Invalid input gives E7001/E7002.

use crate::error::PmacError;
use crate::model::{CoordSystem, Dialect, LinearMove, MoveMode, Transition};
use crate::numfmt::{num, rounded};
use crate::scurve::{project, ramp, Ramp, RestToRest};
use std::fmt::Write as _;

/// Options beyond the dialect.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ProgramOptions {
    /// Turbo or Power PMAC.
    pub dialect: Dialect,
    /// Program number; 0 means "the coordinate system's number".
    pub program: u32,
    /// Where the axes are when the program starts (default: all 0). Needed to compute distances and speeds.
    pub start: Option<Vec<f64>>,
}

/// One move as the PMAC will be told to do it (times in seconds).
#[derive(Debug, Clone, PartialEq)]
pub struct PlannedMove {
    /// Absolute end position per axis.
    pub end: Vec<f64>,
    /// Target as written (absolute in ABS mode, increment in INC mode).
    pub written: Vec<f64>,
    /// Absolute or incremental, as written.
    pub mode: MoveMode,
    /// Vector length of the move.
    pub length: f64,
    /// Planned path speed (exact).
    pub speed: f64,
    /// Path speed as written (rounded `F`).
    pub feedrate: f64,
    /// The ramp into this move (from rest or the blend from the previous move).
    pub accel: Ramp,
    /// The ramp out of this move (to rest, or the blend into the next move).
    pub decel: Ramp,
    /// True if the move ends with an exact stop (`DWELL0`).
    pub stops: bool,
}

/// Program text for `cs` and `moves` (start at the origin, program number = coordinate system number).
pub fn write(
    cs: &CoordSystem,
    moves: &[LinearMove],
    dialect: Dialect,
) -> Result<String, PmacError> {
    write_with(
        cs,
        moves,
        &ProgramOptions {
            dialect,
            ..ProgramOptions::default()
        },
    )
}

/// Program text with explicit options.
pub fn write_with(
    cs: &CoordSystem,
    moves: &[LinearMove],
    opts: &ProgramOptions,
) -> Result<String, PmacError> {
    let planned = plan(cs, moves, opts.start.as_deref())?;
    Ok(render(cs, &planned, opts))
}

/// Writes the program to `out` (e.g. the file of `ladderc run --pmac out.pmc`); write failures are E7005.
pub fn write_to(
    out: &mut dyn std::io::Write,
    cs: &CoordSystem,
    moves: &[LinearMove],
    opts: &ProgramOptions,
) -> Result<(), PmacError> {
    let text = write_with(cs, moves, opts)?;
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| PmacError::transport(format!("cannot write the PMAC program: {e}")))
}

/// Validates and plans every move: distances, path limits, feedrates and ramps.
pub fn plan(
    cs: &CoordSystem,
    moves: &[LinearMove],
    start: Option<&[f64]>,
) -> Result<Vec<PlannedMove>, PmacError> {
    cs.validate()?;
    let n_axes = cs.axes.len();
    let mut pos = match start {
        Some(s) if s.len() != n_axes || s.iter().any(|x| !x.is_finite()) => {
            return Err(PmacError::coord_system(format!(
                "start position needs {n_axes} finite coordinates, got {s:?}"
            )))
        }
        Some(s) => s.to_vec(),
        None => vec![0.0; n_axes],
    };
    // Geometry first: (move, end, delta, length, path speed, unit vector).
    struct Leg<'a> {
        m: &'a LinearMove,
        end: Vec<f64>,
        length: f64,
        speed: f64,
        unit: Vec<f64>,
        rest: RestToRest,
    }
    let mut legs: Vec<Leg> = Vec::new();
    for (i, m) in moves.iter().enumerate() {
        m.validate(i, cs)?;
        let end: Vec<f64> = match m.mode {
            MoveMode::Abs => m.target.clone(),
            MoveMode::Inc => pos.iter().zip(&m.target).map(|(p, d)| p + d).collect(),
        };
        let delta: Vec<f64> = end.iter().zip(&pos).map(|(e, p)| e - p).collect();
        let per_axis = |x: f64| vec![x; n_axes];
        let Some((length, lim)) = project(
            &delta,
            &per_axis(m.velocity),
            &per_axis(m.acceleration),
            &per_axis(m.deceleration),
            &per_axis(m.jerk),
        ) else {
            continue; // zero-length move: nothing to do
        };
        let unit = delta.iter().map(|d| d / length).collect();
        legs.push(Leg {
            m,
            end: end.clone(),
            length,
            speed: lim.velocity,
            unit,
            rest: RestToRest::plan(length, &lim),
        });
        pos = end;
    }
    // Chains of blended moves end at an exact stop (or at the last move).
    let mut out = Vec::with_capacity(legs.len());
    let mut chain_start = 0;
    for idx in 0..legs.len() {
        let last = idx + 1 == legs.len();
        let stops = last || matches!(legs[idx].m.transition, Transition::ExactStop);
        if !stops {
            continue;
        }
        let chain = &legs[chain_start..=idx];
        if chain.len() == 1 {
            let r = chain[0].rest;
            out.push((r.peak_velocity, r.accel, r.decel, true));
        } else {
            // Blended chain: each move at its path speed limit; each transition is the fastest ramp for the
            // largest per-axis speed change within that axis's acceleration and jerk limits.
            let axis_change = |a: Option<&Leg>, b: Option<&Leg>| -> f64 {
                (0..n_axes)
                    .map(|k| {
                        let va = a.map_or(0.0, |l| l.speed * l.unit[k]);
                        let vb = b.map_or(0.0, |l| l.speed * l.unit[k]);
                        (vb - va).abs()
                    })
                    .fold(0.0, f64::max)
            };
            let mut ramps = Vec::with_capacity(chain.len() + 1);
            ramps.push(ramp(
                axis_change(None, Some(&chain[0])),
                chain[0].m.acceleration,
                chain[0].m.jerk,
            ));
            for w in chain.windows(2) {
                ramps.push(ramp(
                    axis_change(Some(&w[0]), Some(&w[1])),
                    w[1].m.acceleration.min(w[0].m.deceleration),
                    w[0].m.jerk.min(w[1].m.jerk),
                ));
            }
            let tail = chain.last().expect("non-empty chain");
            ramps.push(ramp(
                axis_change(Some(tail), None),
                tail.m.deceleration,
                tail.m.jerk,
            ));
            for (k, leg) in chain.iter().enumerate() {
                out.push((leg.speed, ramps[k], ramps[k + 1], k + 1 == chain.len()));
            }
        }
        chain_start = idx + 1;
    }
    Ok(legs
        .iter()
        .zip(out)
        .map(|(leg, (speed, accel, decel, stops))| {
            let written = match leg.m.mode {
                MoveMode::Abs => leg.end.clone(),
                MoveMode::Inc => leg.m.target.clone(),
            };
            PlannedMove {
                end: leg.end.clone(),
                written,
                mode: leg.m.mode,
                length: leg.length,
                speed,
                feedrate: feedrate_text(leg.length, speed).1,
                accel,
                decel,
                stops,
            }
        })
        .collect())
}

/// `F` text and value: 3 decimals, more (up to 6) while rounding moves the move time by more than 0.5 ms.
/// `F` is rounded down, never up: a feedrate above the planned speed would take an axis past its velocity
/// limit.
fn feedrate_text(length: f64, speed: f64) -> (String, f64) {
    let exact = length / speed;
    let down = |d: usize| {
        let scale = 10f64.powi(d as i32);
        // A hair of float noise above a representable value must not drop a whole digit.
        let r = ((speed * scale) * (1.0 + 1e-12)).floor() / scale;
        r.min(speed)
    };
    for d in 3..=6 {
        let r = down(d);
        if r > 0.0 && (length / r - exact).abs() <= 0.5e-3 {
            return (num(r, d), rounded(r, d));
        }
    }
    let r = down(6);
    (num(r, 6), rounded(r, 6))
}

fn ms(seconds: f64) -> String {
    num(seconds * 1000.0, 3)
}

/// Whole milliseconds, rounded up (a hair of float noise below a whole number does not round up).
fn whole_ms_up(seconds: f64) -> u64 {
    (seconds * 1000.0 - 1e-6).ceil().max(0.0) as u64
}

/// A Turbo ramp `(TS, TA)` in whole ms: `TS` rounded up, and `TA - TS` rounded up, so that the peak
/// acceleration `v / (TA - TS)` and the jerk `a / TS` never grow; `TA` is at least `2 TS` and at least 1 ms
/// (TA0 TS0 divides by zero on the controller: Software Reference, `TA{data}`).
pub fn turbo_ramp_ms(r: &Ramp) -> (u64, u64) {
    let ts = whole_ms_up(r.ts);
    let rest = whole_ms_up(r.time - r.ts).max(ts);
    (ts, (ts + rest).max(1))
}

/// Keywords of one dialect.
struct Words {
    setup: Vec<String>,
    open: String,
    linear: &'static str,
    abs: &'static str,
    inc: &'static str,
    ta: &'static str,
    ts: &'static str,
    dwell: &'static str,
    close: &'static str,
    run: String,
}

fn words(cs: &CoordSystem, opts: &ProgramOptions) -> Words {
    let prog = if opts.program == 0 {
        cs.number
    } else {
        opts.program
    };
    match opts.dialect {
        Dialect::Turbo => Words {
            setup: vec![
                "CLOSE".to_string(),
                "DELETE GATHER".to_string(),
                crate::pvt::feed_time_setting(cs.number, Dialect::Turbo, 1000.0),
            ],
            open: format!("OPEN PROG {prog} CLEAR"),
            linear: "LINEAR",
            abs: "ABS",
            inc: "INC",
            ta: "TA",
            ts: "TS",
            dwell: "DWELL0",
            close: "CLOSE",
            run: format!("&{} B{prog} R", cs.number),
        },
        Dialect::Power => Words {
            setup: vec![
                "close".to_string(),
                crate::pvt::feed_time_setting(cs.number, Dialect::Power, 1000.0),
            ],
            open: format!("open prog {prog}\nclear"),
            linear: "linear",
            abs: "abs",
            inc: "inc",
            ta: "ta",
            ts: "ts",
            dwell: "dwell0",
            close: "close",
            run: format!("&{} b{prog} r", cs.number),
        },
    }
}

/// The `&1 #1->1000X #2->1000Y` line.
pub fn axis_definitions(cs: &CoordSystem) -> String {
    let mut s = format!("&{}", cs.number);
    for a in &cs.axes {
        let _ = write!(
            s,
            " #{}->{}{}",
            a.motor,
            num(a.counts_per_unit, 6),
            a.name.to_ascii_uppercase()
        );
    }
    s
}

fn render(cs: &CoordSystem, planned: &[PlannedMove], opts: &ProgramOptions) -> String {
    let w = words(cs, opts);
    let names = cs.axis_names();
    let mut out = String::new();
    for l in &w.setup {
        let _ = writeln!(out, "{l}");
    }
    let _ = writeln!(out, "{}", axis_definitions(cs));
    let _ = writeln!(out, "{}", w.open);
    let first_mode = planned.first().map_or(MoveMode::Abs, |m| m.mode);
    let frax: Vec<String> = names.iter().map(char::to_string).collect();
    let mode_word = |m: MoveMode| if m == MoveMode::Abs { w.abs } else { w.inc };
    let frax_word = if opts.dialect == Dialect::Turbo {
        "FRAX"
    } else {
        "frax"
    };
    let _ = writeln!(
        out,
        "{} {} {}({})",
        w.linear,
        mode_word(first_mode),
        frax_word,
        frax.join(",")
    );
    let mut mode = first_mode;
    // Modal values as written (ms text), so that equal values are not repeated.
    let mut cur_ts = String::new();
    let mut cur_ta = String::new();
    let mut cur_td = String::new();
    for m in planned {
        let mut line: Vec<String> = Vec::new();
        if m.mode != mode {
            line.push(mode_word(m.mode).to_string());
            mode = m.mode;
        }
        let (ts, ta, td) = match opts.dialect {
            // Turbo: the move's TS/TA govern its acceleration; the stop's TS/TA are declared after the move.
            Dialect::Turbo => {
                let (ts, ta) = turbo_ramp_ms(&m.accel);
                (ts.to_string(), ta.to_string(), String::new())
            }
            // Power: one ts for ta and td; a larger ts with the same peak acceleration keeps both within
            // the acceleration and jerk limits (exact when the two ramps have the same ts).
            Dialect::Power => {
                let ts = m.accel.ts.max(m.decel.ts);
                let widen = |r: &Ramp, dv_over_a: f64| {
                    if r.ts == ts {
                        r.time
                    } else {
                        dv_over_a + ts
                    }
                };
                let ta = widen(&m.accel, m.accel.time - m.accel.ts);
                let td = widen(&m.decel, m.decel.time - m.decel.ts);
                (ms(ts), ms(ta), ms(td))
            }
        };
        let mut put = |cur: &mut String, word: &str, val: String| {
            if !val.is_empty() && *cur != val {
                line.push(format!("{word}{val}"));
                *cur = val;
            }
        };
        put(&mut cur_ts, w.ts, ts);
        put(&mut cur_ta, w.ta, ta);
        put(&mut cur_td, "td", td);
        line.push(format!("F{}", feedrate_text(m.length, m.speed).0));
        for (name, x) in names.iter().zip(&m.written) {
            line.push(format!("{name}{}", num(*x, 6)));
        }
        if m.stops {
            if opts.dialect == Dialect::Turbo {
                let mut put = |cur: &mut String, word: &str, val: String| {
                    if *cur != val {
                        line.push(format!("{word}{val}"));
                        *cur = val;
                    }
                };
                let (ts, ta) = turbo_ramp_ms(&m.decel);
                put(&mut cur_ts, w.ts, ts.to_string());
                put(&mut cur_ta, w.ta, ta.to_string());
            }
            line.push(w.dwell.to_string());
        }
        let _ = writeln!(out, "{}", line.join(" "));
    }
    let _ = writeln!(out, "{}", w.close);
    let _ = writeln!(out, "{}", w.run);
    out
}
